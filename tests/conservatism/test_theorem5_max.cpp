// tests/conservatism/test_theorem5_max.cpp -- Theorem 5's largest parameter and the exact side's
// change of verdict (conservatism/theorem5_max.hpp):
//  - the bisection on a verdict whose boundary is known exactly: the bracket holds it, is as narrow
//    as asked, ends on certified verdicts only, stops at an undecided midpoint, and reports a
//    verdict that never holds;
//  - Sec. VI case ii with (27) / kc (examples/multidof_case_ii_coupling.toml): both ends certified;
//    the conclusion lies below Lemma 1's necessary DC condition X (V(1)/kc - K) > 0, i.e.
//    kc < min_i V_i(1) / K_i with K = T/2 Delta_D^-1 (computed here exactly, independently of the
//    LMIs), and below the exact side's NOT-stable end (Theorem 5 is sound): ratio >= 1;
//  - case i (one operator with the paper's 2x2 H, not passive): Assumption 1 fails, exactly, so
//    Theorem 5 concludes at no value;
//  - refusals by name: no [coupling], a [delay] beside one.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "hapstab/conservatism/theorem5_max.hpp"
#include "hapstab/numeric/decimal.hpp"
#include "hapstab/numeric/error.hpp"

using namespace hapstab;
using conservatism::PointVerdict;

namespace {

std::string example(const std::string& f) {
  std::ifstream in(std::string(HAPSTAB_SOURCE_DIR) + "/examples/" + f);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

conservatism::SceneAt at_kc(const std::string& text) {
  return [text](const rational& kc) { return scene::parse_scene(text, "case ii + (27)/kc", {{"kc", kc}}); };
}

PointVerdict exact_verdict(bool yes) {
  PointVerdict v;
  v.yes = yes;
  v.status = Status::exact;
  return v;
}

}  // namespace

TEST(BisectVerdicts, BracketsAKnownBoundaryOnCertifiedEnds) {
  const rational boundary(22, 7);  // yes below 22/7, no from it on
  for (const rational ref : {rational(1, 1000), rational(3), rational(1000)}) {
    const auto b = conservatism::bisect_verdicts([&](const rational& p) { return exact_verdict(p < boundary); }, ref, 9, 20);
    ASSERT_TRUE(b.lo && b.hi) << b.note;
    EXPECT_TRUE(b.lo->proven() && *b.lo->yes);
    EXPECT_TRUE(b.hi->proven() && !*b.hi->yes);
    EXPECT_LT(b.lo->at, boundary);
    EXPECT_GE(b.hi->at, boundary);
    EXPECT_LE(b.hi->at - b.lo->at, pow10(-9) * b.lo->at) << "reference " << ref.str();
  }
  // 10 doublings from 1/1000 end at 1.024 < 22/7: said so, no upper end invented
  const auto short_search = conservatism::bisect_verdicts([&](const rational& p) { return exact_verdict(p < boundary); },
                                                          rational(1, 1000), 9, 10);
  EXPECT_FALSE(short_search.hi.has_value());
  EXPECT_NE(short_search.note.find("no upper end"), std::string::npos) << short_search.note;
}

TEST(BisectVerdicts, AnUndecidedMidpointIsNeverAnEnd) {
  // certified yes below 1, certified no above 2, undecided between: the bracket stays [<= 1, >= 2]
  const auto b = conservatism::bisect_verdicts(
      [](const rational& p) {
        if (p <= 1) return exact_verdict(true);
        if (p >= 2) return exact_verdict(false);
        PointVerdict v;  // undecided (a numeric-only verdict is one too)
        v.yes = false;
        v.status = Status::numeric;
        return v;
      },
      rational(1, 2), 6);
  ASSERT_TRUE(b.lo && b.hi);
  EXPECT_LE(b.lo->at, 1);
  EXPECT_GE(b.hi->at, 2);
  EXPECT_NE(b.note.find("undecided"), std::string::npos) << b.note;
}

TEST(BisectVerdicts, NoYesAnywhereIsReportedAndBadInputRefused) {
  const auto b = conservatism::bisect_verdicts([](const rational&) { return exact_verdict(false); }, rational(1), 6);
  EXPECT_EQ(b.outcome, Outcome::fails);
  EXPECT_FALSE(b.lo.has_value());
  EXPECT_EQ(b.steps.size(), 11u);  // the reference and 10 halvings
  EXPECT_THROW(conservatism::bisect_verdicts([](const rational&) { return exact_verdict(true); }, rational(0), 6), InputError);
  EXPECT_THROW(conservatism::bisect_verdicts([](const rational&) { return exact_verdict(true); }, rational(1), 13), InputError);
}

TEST(Theorem5Max, CaseIiWithCoupling27IsBelowLemma1sDcBoundAndTheExactBoundary) {
  const std::string text = example("multidof_case_ii_coupling.toml");
  const auto t5 = conservatism::theorem5_max(at_kc(text), rational(1000), "kc", 2);
  ASSERT_TRUE(t5.lo && t5.hi) << t5.note;
  EXPECT_TRUE(t5.lo->proven() && *t5.lo->yes) << t5.lo->why;
  EXPECT_TRUE(t5.hi->proven() && !*t5.hi->yes) << t5.hi->why;
  EXPECT_EQ(t5.lo->status, Status::exact);
  // Lemma 1 (analysis.hpp): X (V(1)/kc - K) symmetric positive definite, X diagonal > 0, so
  // V_i(1)/kc > K_i for each device: kc < V_i(1) 2 Delta_i / T. V_i(1) = D + C B / (1 - A).
  const rational T(1, 100), delta(137, 100);
  auto V1 = [](const char* a, const char* b, const char* c, const char* d) {
    return parse_rational(d) + parse_rational(c) * parse_rational(b) / (1 - parse_rational(a));
  };
  const rational kc_dc = std::min(V1("-0.03732", "-3.762", "0.01477", "9.494"), V1("-0.01054", "-6.29", "-0.01639", "9.749")) *
                         2 * delta / T;
  EXPECT_LE(t5.lo->at, kc_dc) << "Theorem 5 concluded where Lemma 1's necessary condition fails";
  // Not asserted: which condition binds. With Theorem 4's program proven infeasible by its
  // frequency-domain witness, the boundary lies just below Lemma 1's DC bound (2550-2570 against
  // 2586.7); before the witness, the DC condition was the first certified "does not conclude".
  const auto ex = conservatism::exact_max_by_verdicts([&](const rational& kc) { return at_kc(text)(kc).loop; }, rational(1000),
                                                      "kc", 2);
  ASSERT_TRUE(ex.lo && ex.hi) << ex.note;
  EXPECT_LE(t5.lo->at, ex.hi->at) << "Theorem 5 concluded where the loop is proven NOT stable";
  const auto r = conservatism::ratio(ex.bracket(), t5);
  ASSERT_TRUE(r.has_value());
  EXPECT_GE(r->hi, 1);
  EXPECT_LE(r->lo, r->hi);
}

TEST(Theorem5Max, CaseIConcludesNowhereBecauseAssumption1Fails) {
  std::string text = example("multidof_case_ii_coupling.toml");
  const size_t a = text.find("[[operator]]"), b = text.find("[environment]");
  ASSERT_NE(a, std::string::npos);
  text.replace(a, b - a,
               "[[operator]]\nname = \"H1\"\ndofs = [\"d_a\", \"d_b\"]\n"
               "tf = [[\"0.1*(s^2+5*s+10)/(s^2+s+1)\", \"0.05\"], [\"0.05\", \"0.05*(s^2+5*s+10)/(s^2+s+1)\"]]\n\n");
  const auto v = conservatism::theorem5_at(at_kc(text)(rational(1000)));
  ASSERT_TRUE(v.proven());
  EXPECT_FALSE(*v.yes);
  EXPECT_EQ(v.status, Status::exact);
  EXPECT_NE(v.why.find("Assumption 1"), std::string::npos) << v.why;
  const auto t5 = conservatism::theorem5_max(at_kc(text), rational(1000), "kc", 3);
  EXPECT_EQ(t5.outcome, Outcome::fails);
  EXPECT_NE(t5.note.find("concludes at none"), std::string::npos) << t5.note;
}

TEST(Theorem5Max, RefusesWhatItDoesNotCompare) {
  const std::string nominal = example("multidof_case_ii_nominal.toml");  // no [coupling]
  try {
    conservatism::theorem5_at(scene::parse_scene(nominal, "nominal"));
    FAIL() << "accepted a scene without [coupling]";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("[coupling]"), std::string::npos) << e.what();
  }
  const std::string delayed = example("multidof_case_ii_coupling.toml") + "\n[delay]\nsamples = \"1\"\n";
  try {
    conservatism::theorem5_at(scene::parse_scene(delayed, "delayed"));
    FAIL() << "accepted a [delay] beside a [coupling]";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("[delay]"), std::string::npos) << e.what();
  }
}
