// Every printed bound contains its value (issue 40): the JSON of each command that prints bounds is
// walked, and EVERY field naming a bound -- a key lower_bound / upper_bound / *_bound, enclosure /
// *_enclosure, or a two-element array of decimal strings (an enclosure [lo, hi]; the sweep's
// NAME_lo / NAME_hi columns come from these) -- must have a reference: the exact value where it is
// rational, else the library's own enclosure computed in this process (narrower: 40-60 digits).
// A lower end must be <= the reference's lower end, an upper end >= its upper end: outward
// rounding, checked in exact rational arithmetic. A bound field without a reference fails the test
// (so a new one cannot go unchecked). The Python module reads this JSON.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <sstream>

#include "cli/cli_in_process.hpp"
#include "hapstab/contact/wedge.hpp"
#include "hapstab/lmi/passivity_level.hpp"
#include "hapstab/lti/parse.hpp"
#include "hapstab/lti/realization.hpp"
#include "hapstab/numeric/decimal.hpp"
#include "hapstab/numeric/interval.hpp"
#include "hapstab/passivity/bound.hpp"
#include "hapstab/passivity/catalogue.hpp"
#include "hapstab/sampling/series.hpp"
#include "hapstab/stability/sampled_loop.hpp"

using namespace hapstab;
using hapstab_test::run_in_process;  // recorded for cli_json_schema

namespace {

using Ref = Enclosure<rational>;
using Refs = std::map<std::string, Ref>;  // JSON pointer -> what the printed bound must contain

Ref exactly(const rational& q) { return {q, q}; }

bool names_a_bound(const std::string& key) {
  auto ends = [&](const std::string& tail) {
    return key.size() >= tail.size() && key.compare(key.size() - tail.size(), tail.size(), tail) == 0;
  };
  return ends("_bound") || key == "enclosure" || ends("_enclosure");
}
bool is_enclosure_array(const nlohmann::json& v) {
  return v.is_array() && v.size() == 2 && v[0].is_string() && v[1].is_string();
}

// A printed end: a decimal, or "inf"/"-inf".
bool at_most(const std::string& printed, const rational& v) {  // printed <= v
  if (printed == "-inf") return true;
  if (printed == "inf") return false;
  return parse_rational(printed) <= v;
}
bool at_least(const std::string& printed, const rational& v) {  // printed >= v
  if (printed == "inf") return true;
  if (printed == "-inf") return false;
  return parse_rational(printed) >= v;
}

// Walks `j`; every bound field must be in `refs` and contain its reference. Returns the number of
// bound fields checked.
int walk(const nlohmann::json& j, const std::string& path, const Refs& refs, const std::string& what) {
  int checked = 0;
  if (j.is_object()) {
    for (const auto& [k, v] : j.items()) {
      const std::string p = path + "/" + k;
      if (v.is_null()) continue;
      const bool scalar_bound = names_a_bound(k) && v.is_string();
      if (scalar_bound || is_enclosure_array(v)) {
        ++checked;
        const auto r = refs.find(p);
        if (r == refs.end()) {
          ADD_FAILURE() << what << ": the bound field " << p << " = " << v.dump() << " has no reference in this test";
          continue;
        }
        if (is_enclosure_array(v)) {
          EXPECT_TRUE(at_most(v[0].get<std::string>(), r->second.lo))
              << what << " " << p << ": lower end " << v[0] << " is above " << r->second.lo.str();
          EXPECT_TRUE(at_least(v[1].get<std::string>(), r->second.hi))
              << what << " " << p << ": upper end " << v[1] << " is below " << r->second.hi.str();
        } else if (k.find("lower") != std::string::npos) {
          EXPECT_TRUE(at_most(v.get<std::string>(), r->second.lo)) << what << " " << p << " = " << v << " > " << r->second.lo.str();
        } else {
          EXPECT_TRUE(at_least(v.get<std::string>(), r->second.hi)) << what << " " << p << " = " << v << " < " << r->second.hi.str();
        }
        continue;
      }
      checked += walk(v, p, refs, what);
    }
  } else if (j.is_array()) {
    for (size_t i = 0; i < j.size(); ++i) checked += walk(j[i], path + "/" + std::to_string(i), refs, what);
  }
  return checked;
}

// Runs the command in process and walks its JSON; every reference must have been found too.
nlohmann::json check_command(const std::vector<std::string>& args, const Refs& refs) {
  std::string what;
  for (const auto& a : args) what += a + " ";
  const auto run = run_in_process(args);
  EXPECT_EQ(run.code, 0) << what;
  const int checked = walk(run.json, "", refs, what);
  for (const auto& [p, r] : refs) {
    const nlohmann::json::json_pointer ptr(p);
    EXPECT_TRUE(run.json.contains(ptr) && !run.json.at(ptr).is_null()) << what << ": no bound printed at " << p;
  }
  EXPECT_GE(checked, static_cast<int>(refs.size())) << what;
  return run.json;
}

TransferFunction tf_z(const std::string& e, const rational& T) {
  ParseOptions po;
  po.variable = 'z';
  po.T = T;
  return parse_tf(e, po);
}

}  // namespace

// The issue's cases: the ISP level of 1 + 1/(z - 0.5) is exactly 1/3 (min Re G at theta = pi); its
// OSP level min Re 1/G = min Re (z - 1/2)/(z + 1/2) is exactly 1/3 too (at theta = 0). Both were
// printed 0.33333333333333333 at both ends (the upper end below 1/3).
TEST(PrintedBounds, PassivityLevelExactOneThird) {
  const rational third(1, 3);
  for (const std::string kind : {"isp", "osp"}) {
    const auto G = tf_z("1 + 1/(z-0.5)", rational(1, 100));
    auto sys = tf2ss(G).cast<double>();
    sys.T = G.T;
    const auto l = lmi::passivity_level_lmi(sys, kind == "isp" ? lmi::PassivityKind::isp : lmi::PassivityKind::osp, 1);
    ASSERT_TRUE(l.lower_bound.has_value()) << l.note;
    EXPECT_LE(*l.lower_bound, third);
    const auto j = check_command({"passivity-level", "--H", "1 + 1/(z-0.5)", "--T", "0.01", "--kind", kind, "--json"},
                                 {{"/enclosure", exactly(third)},
                                  {"/lower_bound", exactly(third)},
                                  {"/upper_bound", exactly(third)},
                                  {"/certified_frequency/enclosure", exactly(third)},
                                  {"/certified_frequency/lower_bound", exactly(third)},
                                  {"/certified_frequency/upper_bound", exactly(third)},
                                  {"/lmi/lower_bound", exactly(*l.lower_bound)}});
    EXPECT_EQ(j.at("status"), "exact") << kind;
    EXPECT_EQ(j.at("exact"), "1/3") << kind;
    EXPECT_EQ(j.at("certified_frequency").at("exact"), "1/3") << kind;
    EXPECT_NE(j.at("lower_bound"), j.at("upper_bound")) << kind << ": 1/3 has no finite decimal";
  }
}

// A 2 x 2 system whose ISP level is exactly 55/96: R diag(g, 2) R' with g = 1 + (41/64)/(z - 1/2)
// (Re g >= 1 - (41/64)/(3/2) = 55/96 at theta = pi) and the rational rotation R = [3/5 -4/5; 4/5 3/5]
// (He G = R He diag(g, 2) R' has the same eigenvalues). Printed 0.57291666666666667 at both ends
// (above 55/96), status exact.
TEST(PrintedBounds, PassivityLevelExactMimo) {
  const auto file = hapstab_test::temp_path("printed_bounds", "mimo5596.json");
  std::ofstream(file) << R"({"A": [[0.5]], "B": [["3/5", "4/5"]], "C": [["123/320"], ["41/80"]],
                             "D": [["41/25", "-12/25"], ["-12/25", "34/25"]], "T": "1/100"})";
  const rational v(55, 96);
  const auto j = check_command({"passivity-level", "--ss", file.string(), "--kind", "isp", "--json"},
                               {{"/enclosure", exactly(v)},
                                {"/lower_bound", exactly(v)},
                                {"/upper_bound", exactly(v)},
                                {"/certified_frequency/enclosure", exactly(v)},
                                {"/certified_frequency/lower_bound", exactly(v)},
                                {"/certified_frequency/upper_bound", exactly(v)},
                                {"/lmi/lower_bound", exactly(v)}});  // the LMI's lower bound is at most the level
  EXPECT_EQ(j.at("status"), "exact");
  EXPECT_EQ(j.at("exact"), "55/96");
  std::filesystem::remove(file);
}

// A level that is not rational: the reference is the certified enclosure at 40 digits.
TEST(PrintedBounds, PassivityLevelCertified) {
  const auto G = tf_z("2 + (z+0.3)/(z^2 - 0.5*z + 0.3)", rational(1, 100));
  const auto c = lmi::passivity_level_certified(G.H, lmi::PassivityKind::isp, 40);
  ASSERT_EQ(c.status, Status::certified) << c.note;
  ASSERT_TRUE(c.enclosure.has_value());
  auto sys = tf2ss(G).cast<double>();
  sys.T = G.T;
  const auto l = lmi::passivity_level_lmi(sys, lmi::PassivityKind::isp, 1);
  Refs refs{{"/enclosure", *c.enclosure},
            {"/lower_bound", *c.enclosure},
            {"/upper_bound", *c.enclosure},
            {"/certified_frequency/enclosure", *c.enclosure},
            {"/certified_frequency/lower_bound", *c.enclosure},
            {"/certified_frequency/upper_bound", *c.enclosure}};
  if (l.lower_bound) refs["/lmi/lower_bound"] = exactly(*l.lower_bound);
  const auto j = check_command({"passivity-level", "--H", "2 + (z+0.3)/(z^2 - 0.5*z + 0.3)", "--T", "0.01", "--kind", "isp", "--json"}, refs);
  EXPECT_TRUE(j.at("exact").is_null());
}

// bound: the wall K + B(z-1)/(Tz) has b* = KT/2 + B exactly (5/6 at K = 1000, B = 1/3, T = 1/1000),
// by every method (the fast path's band and the grid's [max, inf) contain it too); a b* that is not
// rational against its 60-digit enclosure; the Dirichlet constants of (50) against 60 digits.
TEST(PrintedBounds, Bound) {
  const rational v(5, 6);
  for (const std::string method : {"certified", "fast", "grid"}) {
    const auto j = check_command({"bound", "--H", "K + B*(z-1)/(T*z)", "--T", "1/1000", "--set", "K=1000", "--set", "B=1/3",
                                  "--method", method, "--json"},
                                 {{"/enclosure", exactly(v)}});
    if (method == "certified") { EXPECT_EQ(j.at("exact"), "5/6"); }
  }
  passivity::BoundProblem p;
  p.H = tf_z("1/(z^2 - 0.5*z + 0.3)", rational(1, 1000)).H;
  p.T = rational(1, 1000);
  p.delay = 1;
  const auto b = passivity::bound_certified(p, 60);
  ASSERT_TRUE(b.enclosure.has_value());
  check_command({"bound", "--H", "1/(z^2 - 0.5*z + 0.3)", "--T", "1/1000", "--delay", "1", "--json"}, {{"/enclosure", *b.enclosure}});
  passivity::BoundProblem d;
  d.H = tf_z("(z-1)*(1 + z^-1 + z^-2 + z^-3)", rational(1, 1000)).H;
  d.T = rational(1, 1000);
  d.allow_noncausal = true;
  const auto bd = passivity::bound_certified(d, 60);
  check_command({"bound", "--H", "(z-1)*(1 + z^-1 + z^-2 + z^-3)", "--T", "1/1000", "--allow-noncausal", "--json"},
                {{"/enclosure", *bd.enclosure},
                 {"/dirichlet_C", passivity::catalogue::dirichlet_C(60)},
                 {"/dirichlet_D", passivity::catalogue::dirichlet_D(60)}});
}

// stability: the spectral radius of the closed loop and, with --max, the largest stable gain and
// the crossing's angle and frequency, against the library's enclosures at 40 digits.
TEST(PrintedBounds, Stability) {
  const rational T(1, 1000), m(1, 2), b(1, 10), B(2);
  stability::Loop loop = stability::mass_damper_wall(m, b, B, T, 1);
  const stability::MaxGain mg = stability::max_gain(loop, 40, "K");
  ASSERT_EQ(mg.outcome, Outcome::holds) << mg.note;
  ASSERT_TRUE(mg.theta.has_value());
  const Ref omega{mg.theta->lo / T, mg.theta->hi / T};
  const std::vector<std::string> common = {"stability", "--plant", "1/(m*s^2 + b*s)", "--H", "K + B*(z-1)/(T*z)", "--T", "1/1000",
                                           "--delay", "1", "--set", "m=1/2", "--set", "b=1/10", "--set", "B=2"};
  auto args = common;
  for (const char* a : {"--max", "K", "--json"}) args.push_back(a);
  check_command(args, {{"/enclosure", mg.enclosure}, {"/crossing/theta", *mg.theta}, {"/crossing/omega", omega}});
  // at K = 1000: the loop as `stability` decides it
  stability::Loop at = loop;
  at.H = tf_z("1000 + 2*(z-1)/(T*z)", T);
  at.H_gain.reset();
  const auto r = stability::decide(at);
  ASSERT_TRUE(r.spectral_radius.has_value());
  args = common;
  for (const char* a : {"--set", "K=1000", "--json"}) args.push_back(a);
  check_command(args, {{"/spectral_radius", *r.spectral_radius}});
}

// wedge: the margins of the wedge criterion and of Tsypkin's, against analyze_contact at 40 digits
// (the CLI prints them at --digits + 5 = 25).
TEST(PrintedBounds, Wedge) {
  const auto H = tf_z("0.5*(z+1)/(z^2-0.5*z)", rational(1, 1000));
  const auto a = contact::analyze_contact(H, 40);
  ASSERT_TRUE(a.wedge.margin.enclosure && a.tsypkin.margin.enclosure);
  check_command({"wedge", "--H", "0.5*(z+1)/(z^2-0.5*z)", "--json"},
                {{"/wedge/margin_enclosure", *a.wedge.margin.enclosure}, {"/tsypkin/margin_enclosure", *a.tsypkin.margin.enclosure}});
}

// r: the series' error bound is an upper bound of |r - r_N|: at least the 60-digit enclosure's upper end.
TEST(PrintedBounds, RSeriesErrorBound) {
  const rational T(1, 1000), w(2000);
  const interval<60> e = sampling::r_series_error_bound(scalar_cast<interval<60>>(T), scalar_cast<interval<60>>(w * T), 1000);
  check_command({"r", "--T", "1/1000", "--omega", "2000", "--json"}, {{"/series_error_bound", Ref{lower_rational(e), upper_rational(e)}}});
}

// sweep: points.csv's NAME_lo / NAME_hi columns are the command's enclosure: for the wall at
// K = 1000, 3000 (B = 1/3) they contain KT/2 + B = 5/6, 11/6.
TEST(PrintedBounds, SweepColumns) {
  const auto dir = hapstab_test::temp_path("printed_bounds", "sweep");
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "spec.toml") << "command = \"bound\"\n[args]\nH = \"K + B*(z-1)/(T*z)\"\nT = \"1/1000\"\n"
                                      "[axes]\nK = { values = [\"1000\", \"3000\"] }\nB = { values = [\"1/3\"] }\n";
  const auto run = hapstab_test::run_cli("sweep " + (dir / "spec.toml").string() + " --out " + (dir / "out").string() +
                                         " --jobs 1 --quiet");
  ASSERT_EQ(run.code, 0) << run.out;
  std::ifstream in(dir / "out" / "points.csv");
  std::string header, line;
  std::getline(in, header);
  auto column = [&](const std::string& row, const std::string& name) {
    std::vector<std::string> h, c;
    std::stringstream hs(header), rs(row);
    for (std::string x; std::getline(hs, x, ',');) h.push_back(x);
    for (std::string x; std::getline(rs, x, ',');) c.push_back(x);
    for (size_t i = 0; i < h.size(); ++i)
      if (h[i] == name) return c.at(i);
    ADD_FAILURE() << "no column " << name << " in " << header;
    return std::string("0");
  };
  int rows = 0;
  for (const rational& v : {rational(5, 6), rational(11, 6)}) {
    ASSERT_TRUE(std::getline(in, line));
    EXPECT_TRUE(at_most(column(line, "enclosure_lo"), v)) << line;
    EXPECT_TRUE(at_least(column(line, "enclosure_hi"), v)) << line;
    ++rows;
  }
  EXPECT_EQ(rows, 2);
  std::filesystem::remove_all(dir);
}
