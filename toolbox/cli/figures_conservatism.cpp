// cli/figures_conservatism.cpp -- the figure multidof_conservatism (issue 42): how conservative
// Theorem 5 of paper 000 is, in the plane (environment gain g, coupling stiffness kc), on the
// Sec. VI scenes (examples/multidof_case_{i,ii}_{nominal,perturbed}.toml) and the contact scenes
// of multidof/example.hpp (N = 2, 4, 8). Each scene gets the coupling V = V27 / kc: the paper's
// (27) for the 2-DOF scenes, its first block on every device of the contact scenes ([coupling]
// gain = "1/kc": kc scales the coupling's stiffness), and E := g E ([environment] gain = "g").
// For each g on a coarse grid, the largest kc (conservatism/theorem5_max.hpp):
//   exact      the loop as written's stable -> NOT stable change (certified decide_loop verdicts,
//              bisection: the family is not affine in kc, the coupling has a feedthrough);
//   Theorem 5  its boundary (Theorem 4 with that coupling, Assumption 1, hidden modes; certified);
// (Theorem 5 to 1 digit, the exact side to 2: coarse, computed once; a finer Theorem-5 bisection
// lands between Theorem 4's boundary and Lemma 1's DC bound, where at 8 DOF one program's exact
// infeasibility certificate takes minutes -- issue 39's Farkas row reduction)
// and, as a third witness, the simulated loop (exact ZOH, numeric) at sample points of the plane:
// velocities decaying or not (multidof::velocities_decay). Data: multidof_conservatism_<k>.dat
// (g, exact lo/hi, Theorem 5 lo/hi; NaN where a side has no certified end) and
// multidof_conservatism_<k>_sim.dat (g, kc, 1 decays / 0 not); the ratio at g = 1 per scene is
// multidof_conservatism_ratio.dat and the panel titles.
#include <cmath>
#include <fstream>
#include <sstream>

#include "cli/command.hpp"
#include "cli/figure.hpp"
#include "hapstab/conservatism/example.hpp"
#include "hapstab/conservatism/theorem5_max.hpp"
#include "hapstab/multidof/example.hpp"
#include "hapstab/multidof/scene_analysis.hpp"
#include "hapstab/numeric/decimal.hpp"

namespace hapstab::cli {
namespace {

namespace fs = std::filesystem;

struct Panel {
  std::string title, text;
  int n;
};

std::vector<Panel> panels() {
  auto file = [](const char* f) {
    std::ifstream in(examples_dir() / f);
    std::stringstream s;
    s << in.rdbuf();
    std::string t = s.str();
    const size_t r = t.find("\n[reproduce]");  // what reproduce checks: not part of this study
    return r == std::string::npos ? t : t.substr(0, r + 1);
  };
  std::vector<Panel> p{{"case i, nominal E", conservatism::with_coupling27(file("multidof_case_i_nominal.toml"), 2, true), 2},
                       {"case i, perturbed E", conservatism::with_coupling27(file("multidof_case_i_perturbed.toml"), 2, true), 2},
                       {"case ii, nominal E", conservatism::with_coupling27(file("multidof_case_ii_nominal.toml"), 2, true), 2},
                       {"case ii, perturbed E", conservatism::with_coupling27(file("multidof_case_ii_perturbed.toml"), 2, true), 2}};
  for (int N : {2, 4, 8})
    p.push_back({"contact, N = " + std::to_string(N), conservatism::with_coupling27(multidof::example::contact_scene(N), N, false), N});
  return p;
}

double num(const std::optional<conservatism::PointVerdict>& v) { return v ? to_real<double>(v->at) : std::nan(""); }

void write(const fs::path& dir) {
  const std::vector<Panel> ps = panels();
  auto ratios = open_data_file(dir / "multidof_conservatism_ratio.dat");
  ratios << "# panel  exact/Theorem5 lo hi at g = 1 (NaN: no certified bracket)  'title'\n";
  for (size_t k = 0; k < ps.size(); ++k) {
    const Panel& P = ps[k];
    const bool small = P.n <= 2;
    const std::vector<rational> gs = small ? std::vector<rational>{rational(1, 10), rational(1), rational(10)}
                                           : std::vector<rational>{rational(1), rational(10)};
    auto scene_at = [&](const rational& g, const rational& kc) {
      return scene::parse_scene(P.text, P.title, {{"g", g}, {"kc", kc}});
    };
    auto o = open_data_file(dir / ("multidof_conservatism_" + std::to_string(k) + ".dat"));
    o << "# " << P.title << ": largest coupling stiffness kc (V = V27/kc) against the environment gain g (E := g E)\n"
      << "# g  exact_lo exact_hi (certified verdicts: stable at lo, NOT stable at hi; hi NaN: stable at every kc tried up to "
         "lo = 64000)  theorem5_lo theorem5_hi (concludes at lo, not at hi; NaN: no certified end)\n";
    std::optional<Enclosure<rational>> r1;
    for (const rational& g : gs) {
      const auto ex = conservatism::exact_max_by_verdicts(
          [&](const rational& kc) { return multidof::problem_from_scene(scene_at(g, kc)).loop; }, rational(1000), "kc", 2, 6);
      const auto t5 = conservatism::theorem5_max([&](const rational& kc) { return scene_at(g, kc); }, rational(1000), "kc", 1, 6);
      o << to_real<double>(g) << " " << num(ex.lo) << " " << num(ex.hi) << " " << num(t5.lo) << " " << num(t5.hi) << "\n";
      if (g == 1 && ex.lo && ex.hi) r1 = conservatism::ratio(ex.bracket(), t5);
    }
    ratios << k << " " << (r1 ? to_real<double>(r1->lo) : std::nan("")) << " " << (r1 ? to_real<double>(r1->hi) : std::nan(""))
           << " '" << P.title << "'\n";
    // the simulator's witness: velocities after the scene's force impulse, 10 s
    auto s = open_data_file(dir / ("multidof_conservatism_" + std::to_string(k) + "_sim.dat"));
    s << "# g kc decays(1)/not(0): the loop simulated 10 s (exact ZOH, numeric), " << P.title << "\n";
    const std::vector<rational> kcs = small ? std::vector<rational>{rational(300), rational(2000), rational(6000), rational(20000), rational(60000)}
                                            : std::vector<rational>{rational(1000), rational(6000), rational(40000)};
    for (const rational& g : gs)
      for (const rational& kc : kcs) {
        const auto sp = multidof::problem_from_scene(scene_at(g, kc));
        const auto run = multidof::simulate_with_coupling(sp, &*sp.loop.coupling, 10.0);
        s << to_real<double>(g) << " " << to_real<double>(kc) << " "
          << (multidof::velocities_decay(run, to_real<double>(sp.problem.T())).decays ? 1 : 0) << "\n";
      }
  }
}

/// Panel titles title0 .. title6 and their second lines sub0 .. sub6 (the ratio at g = 1).
GnuplotVars titles(const fs::path& dir) {
  GnuplotVars v;
  std::ifstream in(dir / "multidof_conservatism_ratio.dat");
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream l(line);
    int k;
    std::string lo, hi;  // "nan" when there is no certified bracket
    l >> k >> lo >> hi;
    std::string title;
    std::getline(l, title);
    title = title.substr(title.find('\'') + 1);
    title = title.substr(0, title.rfind('\''));
    char r[96];
    if (lo == "nan" || hi == "nan") std::snprintf(r, sizeof r, "Theorem 5 concludes nowhere");
    else std::snprintf(r, sizeof r, "boundaries exact/Thm 5: %.3g-%.3g", std::stod(lo), std::stod(hi));
    v.text.emplace_back("title" + std::to_string(k), title);
    v.text.emplace_back("sub" + std::to_string(k), r);
  }
  return v;
}

const RegisterFigure fig({"multidof_conservatism", "000",
                          "How conservative Theorem 5 is: the largest coupling stiffness for which the loop is stable "
                          "(certified verdicts) and for which Theorem 5 concludes, against the environment gain, on the "
                          "Sec. VI and contact scenes, with simulated verdicts",
                          &write, &titles});

}  // namespace
}  // namespace hapstab::cli
