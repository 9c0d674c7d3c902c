#include "hapstab/conservatism/example.hpp"

#include "hapstab/numeric/error.hpp"

namespace hapstab::conservatism {

namespace {

// (27), decimals as the paper prints them: {A, B, C, D} of each block.
const char* kV27[2][4] = {{"-0.03732", "-3.762", "0.01477", "9.494"}, {"-0.01054", "-6.29", "-0.01639", "9.749"}};

std::string diagonal(int n, int entry, bool paper27) {  // n x n diagonal of (27)'s entry (0 A, 1 B, 2 C, 3 D)
  std::string s = "[";
  for (int i = 0; i < n; ++i) {
    s += i ? ", [" : "[";
    for (int j = 0; j < n; ++j)
      s += std::string(j ? ", " : "") + "\"" + (i == j ? kV27[paper27 ? i % 2 : 0][entry] : "0") + "\"";
    s += "]";
  }
  return s + "]";
}

}  // namespace

std::string with_coupling27(std::string toml, int dofs, bool paper27) {
  auto at = [&](const std::string& what) {
    const size_t k = toml.find(what);
    if (k == std::string::npos) throw InputError("with_coupling27: the scene has no " + what);
    return k;
  };
  toml.insert(at("[parameters]\n") + 13, "g = \"1\"\nkc = \"1000\"\n");
  toml.insert(at("[environment]\n") + 14, "gain = \"g\"\n");
  toml.insert(at("[multidof]\n"), "[coupling]\ngain = \"1/kc\"\nss = { A = " + diagonal(dofs, 0, paper27) + ", B = " +
                                      diagonal(dofs, 1, paper27) + ", C = " + diagonal(dofs, 2, paper27) +
                                      ", D = " + diagonal(dofs, 3, paper27) + " }\n\n");
  if (toml.find("[[input]]") == std::string::npos) toml += "\n[[input]]\ntype = \"impulse\"\ndof = \"d1\"\nmagnitude = \"1/10\"\n";
  return toml;
}

}  // namespace hapstab::conservatism
