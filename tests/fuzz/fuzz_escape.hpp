// tests/fuzz/fuzz_escape.hpp -- reference readers of the output languages, for the libFuzzer
// targets of report/escape.hpp: each undoes one writer the way the language's own reader would,
// so a target can check escape-then-read == text(input). A mismatch or a forbidden construct
// aborts (libFuzzer reports it as a crash with the input that caused it).
#pragma once

#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>

#include "hapstab/report/escape.hpp"

namespace fuzz {

[[noreturn]] inline void fail(const char* what, std::string_view in, std::string_view out) {
  std::fprintf(stderr, "FUZZ FAILURE: %s\n  input  (%zu bytes): %.*s\n  output (%zu bytes): %.*s\n", what, in.size(),
               int(in.size()), in.data(), out.size(), int(out.size()), out.data());
  std::abort();
}

#define FUZZ_CHECK(cond, what, in, out) \
  do {                                  \
    if (!(cond)) ::fuzz::fail(what, in, out); \
  } while (0)

/// `s` with every tab turned into a space (the writers that cannot hold a tab do this).
inline std::string tabs_to_spaces(std::string s) {
  for (char& c : s)
    if (c == '\t') c = ' ';
  return s;
}

/// Replaces each `from` by `to`, left to right, in one pass over the table (longest first).
template <size_t N>
bool unescape(std::string_view s, const std::pair<const char*, const char*> (&table)[N], std::string& out) {
  out.clear();
  for (size_t i = 0; i < s.size();) {
    bool hit = false;
    for (const auto& [from, to] : table) {
      const std::string_view f(from);
      if (s.substr(i, f.size()) == f) {
        out += to;
        i += f.size();
        hit = true;
        break;
      }
    }
    if (!hit) out += s[i++];
  }
  return true;
}

}  // namespace fuzz
