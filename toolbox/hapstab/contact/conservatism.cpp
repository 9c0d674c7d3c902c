#include "hapstab/contact/conservatism.hpp"

#include <cmath>

#include "hapstab/contact/limit_cycle.hpp"
#include "hapstab/contact/wedge.hpp"

namespace hapstab::contact {

std::vector<ConservatismCase> default_family() {
  struct Op {
    const char* name;
    rational K, B, M;
    bool none;
  };
  const std::vector<Op> ops{{"none", 0, 0, 0, true},
                            {"soft hand", 100, 2, 0, false},
                            {"medium hand", 500, 5, 0, false},
                            {"stiff hand", 3000, 10, rational(1, 10), false}};
  std::vector<ConservatismCase> out;
  const rational T(1, 1000);
  for (WallKind w : {WallKind::backward_difference, WallKind::tustin})
    for (int d = 0; d <= 2; ++d)
      for (const auto& op : ops) {
        ConservatismCase c;
        c.wall = w;
        c.delay = d;
        c.operator_name = op.name;
        c.name = std::string(w == WallKind::tustin ? "Tustin" : "BD") + " d=" + std::to_string(d) + " " + op.name;
        c.model.m = rational(1, 5);
        c.model.b = rational(1, 2);
        c.model.T = T;
        c.model.O = op.none ? TransferFunction{RationalFunction<rational>(0), Domain::s, 0}
                            : hand_impedance(op.K, op.B, op.M);
        c.model.E = virtual_wall(w, 1, rational(2, 1000), T, d);
        out.push_back(c);
      }
  return out;
}

ConservatismRow evaluate_case(const ConservatismCase& c, long steps) {
  ConservatismRow r;
  r.c = c;
  ModelH mh = model_H(c.model, 30);
  r.H = mh.H;
  ContactAnalysis a = analyze_contact(r.H, 12);
  r.assumptions = a.assumptions.violated;
  r.criteria_evaluated = a.wedge.evaluated();
  r.tsypkin_evaluated = a.tsypkin.evaluated();
  if (a.wedge.evaluated()) {
    r.wedge_inf = a.wedge.gain_infinite;
    if (!r.wedge_inf) r.k_wedge = static_cast<double>(mpfloat<30>(a.wedge.max_gain.value));
  }
  if (a.tsypkin.evaluated()) {
    r.tsypkin_inf = a.tsypkin.gain_infinite;
    if (!r.tsypkin_inf) r.k_tsypkin = static_cast<double>(mpfloat<30>(a.tsypkin.max_gain.value));
  }
  r.k_linear = closed_loop_gain_limit(r.H, 1e9, 1e-6);
  // search range: from well below the smallest certified gain to the linear limit
  double klo = 1e-2, khi = (r.k_linear && *r.k_linear > 0) ? *r.k_linear * 1.5 : 1e7;
  if (r.tsypkin_evaluated && !r.tsypkin_inf) klo = std::min(klo, r.k_tsypkin / 20);
  OnsetResult on = oscillation_onset(r.H, klo, khi, 40, 1e-3, steps);
  r.k_osc = on.k_onset;
  r.period = on.period;
  r.orbit_certified = on.certified;
  if (r.k_osc && r.criteria_evaluated && r.assumptions.empty()) {
    r.wedge_contradicted = r.wedge_inf || r.k_wedge > *r.k_osc * (1 + 1e-3);
    r.tsypkin_contradicted = r.tsypkin_inf || r.k_tsypkin > *r.k_osc * (1 + 1e-3);
  }
  return r;
}

}  // namespace hapstab::contact
