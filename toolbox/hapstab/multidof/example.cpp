#include "hapstab/multidof/example.hpp"

#include <sstream>
#include <vector>

#include "hapstab/lti/parse.hpp"
#include "hapstab/numeric/decimal.hpp"

namespace hapstab::multidof::example {

namespace {
rational q(const char* s) { return parse_rational(s, "example constant"); }
}  // namespace

MechanicalEnvironment fig5() {
  MechanicalEnvironment e;
  e.M = q("0.3");
  e.k = 1000;
  e.B = 5;
  e.kc = {rational(800), rational(500)};
  e.Bc = {rational(1), rational(2)};
  return e;
}

rational T() { return q("0.01"); }

StateSpace<rational> environment(bool perturbed) {
  StateSpace<rational> E = mechanical_environment(fig5(), T(), C2dMethod::backward_euler);
  if (perturbed) {
    MatQ Pi(2, 2);
    Pi << 0, 1, 1, 0;
    E.C = Pi * E.C;
  }
  return E;
}

Structure structure(int which_case) {
  const rational d = q("1.37");
  Structure s;
  if (which_case == 1) {
    s.operators = {Operator{"H1 (both hands)", 2, {device("d_a", 1, d), device("d_b", 1, d)}}};
  } else {
    s.operators = {Operator{"H1", 1, {device("d_a", 1, d)}}, Operator{"H2", 1, {device("d_b", 1, d)}}};
  }
  return s;
}

TransferMatrix operator_H(int which_case) {
  ParseOptions po;
  po.variable = 's';
  TransferMatrix H;
  H.domain = Domain::s;
  H.T = 0;
  H.entries = {{parse_tf("0.1*(s^2+5*s+10)/(s^2+s+1)", po), parse_tf(which_case == 1 ? "0.05" : "0", po)},
               {parse_tf(which_case == 1 ? "0.05" : "0", po), parse_tf("0.05*(s^2+5*s+10)/(s^2+s+1)", po)}};
  return H;
}

StateSpace<rational> controller27() {
  StateSpace<rational> V;
  V.T = T();
  V.A = MatQ::Zero(2, 2);
  V.B = MatQ::Zero(2, 2);
  V.C = MatQ::Zero(2, 2);
  V.D = MatQ::Zero(2, 2);
  V.A(0, 0) = q("-0.03732");
  V.A(1, 1) = q("-0.01054");
  V.B(0, 0) = q("-3.762");
  V.B(1, 1) = q("-6.29");
  V.C(0, 0) = q("0.01477");
  V.C(1, 1) = q("-0.01639");
  V.D(0, 0) = q("9.494");
  V.D(1, 1) = q("9.749");
  return V;
}

Problem problem(int which_case, bool perturbed) {
  Problem p;
  p.structure = structure(which_case);
  p.E = environment(perturbed);
  p.coupling.mbar = {1, 1};
  p.coupling.nbar = {1, 1};
  return p;
}


std::string contact_scene(int n, bool active, int objects) {
  if (objects < 1 || objects > n) objects = 1;
  std::ostringstream s;
  s << "[scene]\nname = \"contact scene\"\nT = \"0.01\"\n[parameters]\nM = \"0.3\"\nk = \"1000\"\nB = \"" << (active ? "200" : "5")
    << "\"\n";
  const char* b[] = {"1", "2", "3/2", "5/2"};
  for (int i = 1; i <= n; ++i)
    s << "k" << i << " = \"" << 500 + 100 * ((i - 1) % 4) << "\"\nB" << i << " = \"" << (active ? "-3" : b[(i - 1) % 4]) << "\"\n";
  const char* g[] = {"0.1", "0.05", "0.08", "0.06"};
  for (int i = 1; i <= n; ++i) s << "[[device]]\nname = \"d" << i << "\"\nm = \"1/10\"\nb = \"1.37\"\n";
  for (int i = 1; i <= n; ++i)
    s << "[[operator]]\nname = \"H" << i << "\"\ndofs = [\"d" << i << "\"]\ntf = \"" << g[(i - 1) % 4] << "*(s^2+5*s+10)/(s^2+s+1)\"\n";
  // object o is touched by devices first[o] .. first[o + 1] - 1 (as even a split as n allows)
  std::vector<int> obj(static_cast<size_t>(n + 1));
  for (int i = 1; i <= n; ++i) obj[static_cast<size_t>(i)] = (i - 1) * objects / n;
  std::vector<std::string> den(static_cast<size_t>(objects));
  for (int o = 0; o < objects; ++o) {
    std::string d = "(M*s^2 + (B", ks = "k";
    for (int i = 1; i <= n; ++i)
      if (obj[static_cast<size_t>(i)] == o) d += "+B" + std::to_string(i), ks += "+k" + std::to_string(i);
    den[static_cast<size_t>(o)] = d + ")*s + " + ks + ")";
  }
  s << "[environment]\ndomain = \"s\"\nmethod = \"backward_euler\"\ntf = [";
  for (int i = 1; i <= n; ++i) {
    const std::string ci = "(k" + std::to_string(i) + " + B" + std::to_string(i) + "*s)";
    const std::string& di = den[static_cast<size_t>(obj[static_cast<size_t>(i)])];
    s << (i > 1 ? ", [" : "[");
    for (int j = 1; j <= n; ++j) {
      const std::string cj = "(k" + std::to_string(j) + " + B" + std::to_string(j) + "*s)";
      s << (j > 1 ? ", \"" : "\"");
      if (obj[static_cast<size_t>(i)] != obj[static_cast<size_t>(j)]) s << "0";
      else s << (i == j ? ci + " - " + ci + "^2/" + di : "-" + ci + "*" + cj + "/" + di);
      s << "\"";
    }
    s << "]";
  }
  std::string ones, osp;
  for (int i = 1; i <= n; ++i) ones += (i > 1 ? ", 1" : "1"), osp += (i > 1 ? ", \"1.37\"" : "\"1.37\"");
  s << "]\n[multidof]\nosp = [" << osp << "]\n[multidof.coupling]\nmbar = [" << ones << "]\nnbar = [" << ones << "]\n";
  return s.str();
}

Problem linked_by_dampers(const Problem& pb, const std::vector<std::pair<int, int>>& links, const rational& Bc) {
  const Eigen::Index n = pb.E.states(), m = pb.structure.m(), L = static_cast<Eigen::Index>(links.size());
  Problem out = pb;
  StateSpace<rational>& E = out.E;
  E.A = MatQ::Zero(n + 2 * L, n + 2 * L);
  E.A.topLeftCorner(n, n) = pb.E.A;
  E.B = MatQ::Zero(n + 2 * L, m);
  E.B.topRows(n) = pb.E.B;
  E.C = MatQ::Zero(m, n + 2 * L);
  E.C.leftCols(n) = pb.E.C;
  const rational c = Bc / pb.T();
  for (Eigen::Index l = 0; l < L; ++l) {
    const auto [i, j] = links[static_cast<size_t>(l)];
    // states w = (x_i, x_j) one sample back; force on i: c (x_i - w_i - x_j + w_j), on j the opposite
    E.B(n + 2 * l, i) = 1;
    E.B(n + 2 * l + 1, j) = 1;
    E.C(i, n + 2 * l) -= c;
    E.C(i, n + 2 * l + 1) += c;
    E.C(j, n + 2 * l) += c;
    E.C(j, n + 2 * l + 1) -= c;
    E.D(i, i) += c;
    E.D(j, j) += c;
    E.D(i, j) -= c;
    E.D(j, i) -= c;
  }
  return out;
}

}  // namespace hapstab::multidof::example
