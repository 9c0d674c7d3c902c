// hapstab/check/stability_loop_max_check.cpp -- see stability_loop_max_check.hpp.
#include "hapstab/check/stability_loop_max_check.hpp"

#include <algorithm>
#include <cctype>
#include <functional>
#include <numeric>
#include <optional>
#include <string>
#include <vector>

#include <toml++/toml.h>

#include "hapstab/check/affine.hpp"
#include "hapstab/check/rational_matrix.hpp"
#include "hapstab/check/scene_model.hpp"
#include "hapstab/check/stability_loop_check.hpp"
#include "hapstab/lti/circle_crossing.hpp"
#include "hapstab/numeric/error.hpp"

namespace hapstab::check {

namespace {

using detail::BallRows;
using rational_matrix::Mat;

constexpr size_t kMaxCover = 4096;       // intervals of the cover (each: two Stein tests)
constexpr size_t kMaxLoopOrder = 160;  // M's order (the stability-loop kind takes 1024: one Stein test, not thousands)
constexpr double kMaxCoverWork = 5e7;    // intervals x n^3 (a Stein test ~0.3 ms at order 9: at most ~20 s)

// Every identifier in `text` ([A-Za-z_][A-Za-z0-9_]*).
std::vector<std::string> identifiers(const std::string& text) {
  std::vector<std::string> out;
  for (size_t i = 0; i < text.size();) {
    const auto c = static_cast<unsigned char>(text[i]);
    if (std::isalpha(c) || c == '_') {
      size_t j = i + 1;
      while (j < text.size() && (std::isalnum(static_cast<unsigned char>(text[j])) || text[j] == '_')) ++j;
      out.push_back(text.substr(i, j - i));
      i = j;
    } else {
      ++i;
    }
  }
  return out;
}

}  // namespace

detail::MaxReading detail::read_max_parameter(const std::string& scene, const std::string& p) {
  toml::table root;
  try {
    root = toml::parse(scene);
  } catch (const toml::parse_error& e) {
    throw InputError(std::string("model.scene: not TOML (") + std::string(e.description()) + ")");
  }
  const auto* params = root["parameters"].as_table();
  if (!params || !params->contains(p)) throw InputError("model.name: '" + p + "' is not a parameter of the scene ([parameters])");
  MaxReading r;
  for (const char* b : {"environment", "coupling"})
    if (const auto* t = root[b].as_table())
      if (const auto* g = t->get("gain"); g && g->as_string() && g->as_string()->get() == p) {
        if (!r.block.empty()) throw InputError("model.name: '" + p + "' is the gain of both [environment] and [coupling]");
        r.block = b;
      }
  std::vector<std::string> where;  // every string naming p, the gain and p's own definition aside
  std::function<void(const toml::node&, const std::string&)> scan = [&](const toml::node& n, const std::string& at) {
    if (const auto* t = n.as_table()) {
      for (const auto& [k, v] : *t) {
        const std::string key(k.str());
        // labels and keywords, and the sections the loop's reading ignores, hold no expression of the loop
        if (key == "name" || key == "dofs" || key == "domain" || key == "method") continue;
        if (at.empty() && (key == "input" || key == "initial" || key == "simulate" || key == "reproduce" || key == "multidof")) continue;
        scan(v, at.empty() ? key : at + "." + key);
      }
    } else if (const auto* a = n.as_array()) {
      for (size_t i = 0; i < a->size(); ++i) scan(*a->get(i), at + "[" + std::to_string(i) + "]");
    } else if (const auto* s = n.as_string()) {
      if ((!r.block.empty() && at == r.block + ".gain") || at == "parameters." + p) return;
      for (const auto& id : identifiers(s->get()))
        if (id == p) {
          where.push_back(at);
          break;
        }
    }
  };
  scan(root, "");
  // a tf entry, or a compact scene's diagonal / off_diagonal (the reading writes them out as the tf's entries)
  const auto in_tf = [&](const std::string& b) {
    return std::all_of(where.begin(), where.end(), [&](const std::string& w) {
      return w == b + ".tf" || w.rfind(b + ".tf[", 0) == 0 || w == b + ".diagonal" || w == b + ".off_diagonal";
    });
  };
  if (r.block.empty()) {
    for (const char* b : {"environment", "coupling"})
      if (!where.empty() && in_tf(b)) return {b, true};
    const auto outside = std::find_if(where.begin(), where.end(), [](const std::string& w) {
      return w.rfind("environment.tf", 0) != 0 && w.rfind("coupling.tf", 0) != 0;
    });
    throw InputError("model.name: '" + p + "' is neither the whole gain of [environment] or [coupling] (gain = \"" + p +
                     "\") nor named only in the tf of one of them" +
                     (where.empty() ? std::string() : " (it is named in " + (outside != where.end() ? *outside : where[0] + " and " + where.back()) + ")") +
                     ": beyond this kind (the loop must be affine in it)");
  }
  if (!where.empty())
    throw InputError("model.scene: '" + p + "' is named in " + where[0] + " as well as in " + r.block +
                     ".gain: beyond this kind (only a gain, named nowhere else, makes the loop affine in it)");
  return r;
}

using detail::MaxReading;

std::vector<size_t> detail::affine_column_orders(const nlohmann::json& model, const MaxReading& r, const std::string& p, const SceneLoop& L1,
                                                 long& degree) {
  const bool plant = !model.contains("scene");
  const auto entries = plant ? std::vector<std::vector<std::string>>{{model.at("H").get<std::string>()}}
                             : block_entries(model, r.block, p, L1.dofs());
  const auto& at1 = r.block == "environment" ? L1.E.tf : L1.V->tf;
  ParseOptions po;
  po.variable = 'z';
  po.T = L1.T;
  if (plant) po.parameters = model_parameters(model);  // the other parameters' values (p has none)
  std::vector<size_t> orders;
  for (size_t j = 0; j < entries.size(); ++j) {
    Polynomial<rational> Lj{rational(1)};
    const auto join = [&](const Polynomial<rational>& d) { Lj = divmod(Lj * d, gcd(Lj, d)).first.monic(); };
    for (size_t i = 0; i < entries.size(); ++i) {
      const auto ids = identifiers(entries[i][j]);
      if (std::find(ids.begin(), ids.end(), p) == ids.end()) {
        join(at1[i][j].den());
        continue;
      }
      Affine a;
      try {
        a = prove_affine(entries[i][j], po, p);
      } catch (const InputError& e) {
        throw InputError((plant ? std::string("model.H") : "model.scene: " + r.block + ".tf[" + std::to_string(i) + "][" + std::to_string(j) + "]") +
                         ": " + e.what() + ": beyond this kind");
      }
      degree = std::max(degree, a.D);
      join(a.H0.den());
      join(a.H1.den());
    }
    orders.push_back(static_cast<size_t>(Lj.degree()));
  }
  return orders;
}

namespace {

// sum_j deg L_j (detail::affine_column_orders): the largest order the checker's realisation of the block reaches at any p.
size_t affine_block_order(const nlohmann::json& model, const MaxReading& r, const std::string& p, const detail::SceneLoop& L1, long& degree) {
  const auto orders = detail::affine_column_orders(model, r, p, L1, degree);
  return std::accumulate(orders.begin(), orders.end(), size_t(0));
}

// Affine in p, on the realisations read (header): the gain block's A, B the same and C, D doubled at p = 2,
// the rest equal; p inside the tf: A, B the same at 1, 2 and hi, of the largest order `order` (else beyond),
// C and D at hi on the line through 1 and 2. "" when shown, else what is not.
std::string realisations_not_affine(const MaxReading& r, const std::string& p, const detail::LoopMatrix& m1, const detail::LoopMatrix& m2,
                                    const detail::LoopMatrix* at_hi, size_t order, const rational& hi) {
  const std::string& block = r.block;
  const size_t g = block == "environment" ? 0 : 4;
  if (r.inside)
    for (const auto* m : {&m1, &m2, at_hi ? at_hi : &m1})
      if (m->controller[g].size() != order)
        throw InputError("model.scene: the " + block + "'s realisation at " + p + " = 1, 2 or " + hi.str() + " has order " +
                         std::to_string(m->controller[g].size()) + ", not " + std::to_string(order) +
                         " (a pole cancelled there): beyond this kind");
  for (size_t k = 0; k < 8; ++k) {
    Mat want = m1.controller[k];
    const bool moves = k == g + 2 || k == g + 3;  // C, D of the block
    if (moves && !r.inside)
      for (auto& row : want)
        for (auto& x : row) x *= 2;
    if ((!moves || !r.inside) && m2.controller[k] != want)
      return "the " + block + "'s realisation at " + p + " = 2 is not the one at 1 with " + (r.inside ? "A and B equal" : "C and D doubled") +
             ": the loop is not shown affine in " + p;
    if (at_hi) {
      if (moves)
        for (size_t i = 0; i < want.size(); ++i)
          for (size_t j = 0; j < want[i].size(); ++j) want[i][j] = rational(2 - hi) * m1.controller[k][i][j] + rational(hi - 1) * m2.controller[k][i][j];
      if (at_hi->controller[k] != want)
        return "the " + block + "'s realisation at " + p + " = " + hi.str() + " is not on the line through those at 1 and 2";
    }
  }
  return "";
}


// A one-DOF --plant/--H model: p named in H and in neither the plant nor the operator ("p inside the tf"
// of its one wall). InputError otherwise.
MaxReading read_p_plant(const nlohmann::json& model, const std::string& p) {
  const auto names = [&](const char* key) {
    if (!model.contains(key)) return false;
    if (!model.at(key).is_string()) throw InputError(std::string("model.") + key + ": not a string");
    const auto ids = identifiers(model.at(key).get<std::string>());
    return std::find(ids.begin(), ids.end(), p) != ids.end();
  };
  if (!names("H")) throw InputError("model.H: does not name model.name = " + p);
  for (const char* key : {"plant", "operator"})
    if (names(key)) throw InputError(std::string("model.") + key + ": names " + p + " too: beyond this kind (only H may depend on it)");
  return {"environment", true};
}

Mat symmetric_P(const nlohmann::json& obj, const std::string& where, size_t n, const char* key = "P") {
  const Mat P = detail::exact_matrix(obj, key, where, n);
  if (P.size() != n || P[0].size() != n)
    throw InputError(where + "." + key + ": order " + std::to_string(P.size()) + ", the loop's " + std::to_string(n));
  if (!rational_matrix::symmetric(P)) throw InputError(where + "." + key + ": not symmetric");
  return P;
}

// evidence.first_order.to, exactly (the start of the cover).
rational from0(const nlohmann::json& evidence) { return detail::exact_field(evidence.at("first_order"), "to", "evidence.first_order"); }

// Stable on (0, eps] where M(0) has the eigenvalue 1 on positions that nothing holds (header): rows L with
// L M(0) = L exactly (check/stability_loop_check.hpp's slow_rows), so L M(p) = L + p K, K = L (M(2) -
// M(1)); with P(p) = P0 + L^T S L / p (P0 > 0, S >= 0: P(p) > 0 for p > 0) the Stein matrix is, exactly,
//   Q(p) = P0 - M(p)^T P0 M(p) - (K^T S L + L^T S K) - p K^T S K,
// concave in p; > 0 at 0 and at eps makes it > 0 on [0, eps], so every M(p), 0 < p <= eps, is Schur
// stable (first_order_start); with S of any sign and w^T P(p) w < 0 on (0, eps], none is (first_order_unstable,
// Stein inertia).

// The first-order form's parts {to = eps, P0, S} (and w where `keys` has it), read and shaped (InputError when
// malformed): P0 symmetric of M's order, S symmetric of the slow rows' count k.
struct FirstOrder {
  rational eps;
  Mat P0, S;
};
FirstOrder read_first_order(const nlohmann::json& fo, const std::string& where, std::initializer_list<const char*> keys, const Mat& L, size_t n) {
  if (!fo.is_object()) throw InputError(where + ": not an object");
  detail::only_fields(fo, keys, where);
  if (L.empty()) throw InputError(where + ": the loop has no position that nothing holds at p = 0 (no slow mode to start from)");
  if (L[0].size() != n) throw NumericalError("the slow modes' rows are not of M's order (a checker defect)");
  FirstOrder out{detail::exact_field(fo, "to", where), symmetric_P(fo, where, n, "P0"), detail::exact_matrix(fo, "S", where, L.size())};
  if (out.S.size() != L.size() || out.S[0].size() != L.size() || !rational_matrix::symmetric(out.S))
    throw InputError(where + ".S: not symmetric of order " + std::to_string(L.size()) + " (the slow modes)");
  return out;
}

// P0 > 0 and Q(p) = P0 - M(p)^T P0 M(p) - (K^T S L + L^T S K) - p K^T S K > 0 at p = 0 and eps (balls), K = L (M(2) -
// M(1)): with P0 > 0, v^T Q(p) v is concave in p, so Q > 0 on [0, eps]. "" when shown, else what fails.
std::string first_order_stein(const FirstOrder& f, const detail::LoopMatrix& m1, const detail::LoopMatrix& m2, const Mat& L,
                              const std::string& where) {
  const size_t n = m1.M.size(), k = L.size();
  const Mat& P0 = f.P0;
  const bool pd = detail::positive_definite(P0);
  if (!pd) return where + ".P0 is not shown positive definite";
  // K = L (M(2) - M(1)) and the p-independent part -(K^T S L + L^T S K), in balls
  BallRows K(k, std::vector<flint::Ball>(n, flint::Ball(0L)));
  for (size_t r = 0; r < k; ++r)
    for (size_t j = 0; j < n; ++j)
      for (size_t i = 0; i < n; ++i)
        if (!L[r][i].is_zero()) K[r][j] += flint::Ball(L[r][i]) * (m2.M[i][j] - m1.M[i][j]);
  BallRows SK(k, std::vector<flint::Ball>(n, flint::Ball(0L)));
  for (size_t r = 0; r < k; ++r)
    for (size_t j = 0; j < n; ++j)
      for (size_t t = 0; t < k; ++t) SK[r][j] += flint::Ball(f.S[r][t]) * K[t][j];
  for (const rational& e : {rational(0), f.eps}) {
    const BallRows M = detail::affine_loop_at(m1.M, m2.M, e);
    BallRows PM(n, std::vector<flint::Ball>(n, flint::Ball(0L))), Q = PM;
    for (size_t a = 0; a < n; ++a)
      for (size_t b = 0; b < n; ++b)
        if (!P0[a][b].is_zero())
          for (size_t j = 0; j < n; ++j) PM[a][j] += flint::Ball(P0[a][b]) * M[b][j];
    for (size_t i = 0; i < n; ++i)
      for (size_t j = 0; j < n; ++j) {
        flint::Ball mpm(0L), cross(0L), ksk(0L);
        for (size_t a = 0; a < n; ++a) mpm += M[a][i] * PM[a][j];
        for (size_t r = 0; r < k; ++r) {
          cross += SK[r][j] * flint::Ball(L[r][i]) + SK[r][i] * flint::Ball(L[r][j]);
          ksk += K[r][i] * SK[r][j];
        }
        Q[i][j] = flint::Ball(P0[i][j]) - mpm - cross - flint::Ball(e) * ksk;
      }
    std::string why;
    if (!detail::ball_positive_definite(Q, why))
      return where + " at p = " + e.str() + ": P0 - M^T P0 M - (K^T S L + L^T S K) - p K^T S K " + why;
  }
  return "";
}

}  // namespace

std::string detail::first_order_start(const nlohmann::json& fo, const LoopMatrix& m1, const LoopMatrix& m2, const Mat& L,
                                      const rational& lo, rational& from) {
  const std::string where = "evidence.first_order";
  const FirstOrder f = read_first_order(fo, where, {"to", "P0", "S"}, L, m1.M.size());
  if (f.eps <= 0 || f.eps > lo) throw InputError(where + ".to: not in (0, claim.lo]");
  if (!rational_matrix::positive_definite(f.S, false)) return where + ".S is not positive semidefinite";
  if (std::string why = first_order_stein(f, m1, m2, L, where); !why.empty()) return why;
  from = f.eps;
  return "";
}

std::string detail::first_order_unstable(const nlohmann::json& fo, const LoopMatrix& m1, const LoopMatrix& m2, const Mat& L, const std::string& at,
                                         bool& refuted) {
  const std::string where = at + ".first_order_unstable";
  const size_t n = m1.M.size();
  const FirstOrder f = read_first_order(fo, where, {"to", "P0", "S", "w"}, L, n);
  if (f.eps <= 0) throw InputError(where + ".to: not > 0");
  const Mat w = detail::exact_matrix(nlohmann::json{{"w", nlohmann::json::array({fo.contains("w") ? fo.at("w") : nlohmann::json()})}}, "w", where, n);
  if (w[0].size() != n) throw InputError(where + ".w: not of M's order (" + std::to_string(n) + ")");
  // s = (L w)^T S (L w) < 0 and w^T P0 w + s / eps < 0, exactly: w^T P(p) w = w^T P0 w + s / p <= that for p <= eps
  std::vector<rational> Lw(L.size(), rational(0));
  for (size_t r = 0; r < L.size(); ++r)
    for (size_t i = 0; i < n; ++i) Lw[r] += L[r][i] * w[0][i];
  rational s = 0, q = 0;
  for (size_t r = 0; r < L.size(); ++r)
    for (size_t t = 0; t < L.size(); ++t) s += Lw[r] * f.S[r][t] * Lw[t];
  for (size_t i = 0; i < n; ++i)
    for (size_t j = 0; j < n; ++j) q += w[0][i] * f.P0[i][j] * w[0][j];
  refuted = true;
  if (s >= 0) return where + ": (L w)^T S (L w) = " + detail::decimal(s) + " >= 0";
  if (q + s / f.eps >= 0) return where + ": w^T P0 w + (L w)^T S (L w) / eps = " + detail::decimal(rational(q + s / f.eps)) + " >= 0";
  refuted = false;
  return first_order_stein(f, m1, m2, L, where);
}

void detail::require_loop_max_order(size_t order) {
  if (order > kMaxLoopOrder)
    throw InputError("model: the closed loop has " + std::to_string(order) + " states, beyond this checker's " + std::to_string(kMaxLoopOrder) +
                     " for a supremum (a cover of Stein tests at that order)");
}

detail::BallRows detail::affine_loop_at(const BallRows& M1, const BallRows& M2, const rational& p) {
  const flint::Ball a(rational(2 - p)), b(rational(p - 1));
  BallRows M = M1;
  for (size_t i = 0; i < M.size(); ++i)
    for (size_t j = 0; j < M.size(); ++j) M[i][j] = a * M1[i][j] + b * M2[i][j];
  return M;
}

namespace {

enum class Cover { shown, not_shown, refuted };

// evidence.cover from `from` to lo (header): each interval's P > 0 with Stein at both ends (convex in p), or, P
// linear (P_to; P left out: the last interval's P_to), P and P_to > 0 and the four Bernstein coefficients > 0.
// refuted: a P not positive definite (exact: no retry); not_shown: a Stein or Bernstein test failed in balls
// (another precision may pass); `why` says which. InputError when malformed.
Cover check_cover(const nlohmann::json& cover, const BallRows& M1, const BallRows& M2, rational from, const rational& lo, size_t n,
                  const std::string& p, std::string& why, const std::string& at) {
  Mat last_P_to;  // the last interval's P_to (empty: it had none)
  for (size_t k = 0; k < cover.size(); ++k) {
    const std::string where = at + ".cover[" + std::to_string(k) + "]";
    if (!cover[k].is_object()) throw InputError(where + ": not an object");
    detail::only_fields(cover[k], {"to", "P", "P_to"}, where);
    const rational to = detail::exact_field(cover[k], "to", where);
    // (one interval [lo, lo], M(lo) stable by one P, where no_crossing reaches lo: the check_max_part caller's from = lo)
    if (to < from || (to == from && !(cover.size() == 1 && to == lo && !cover[k].contains("P_to"))))
      throw InputError(where + ".to: not above the interval's start " + from.str());
    if (k + 1 == cover.size() && to != lo) throw InputError(where + ".to: the last interval ends at claim.lo (" + lo.str() + ")");
    const bool linear = cover[k].contains("P_to");  // P at `from`, P_to at `to`, linear between (header)
    const bool inherited = !cover[k].contains("P");
    if (inherited && (!linear || last_P_to.empty()))
      throw InputError(where + ".P: missing (left out only in an interval with P_to after one with P_to: then it is that P_to)");
    const Mat Pk = inherited ? last_P_to : symmetric_P(cover[k], where, n);
    const Mat Pto = linear ? symmetric_P(cover[k], where, n, "P_to") : Mat{};
    last_P_to = Pto;
    for (const Mat* X : {&Pk, &Pto}) {
      if (X->empty() || (X == &Pk && inherited)) continue;  // an inherited P was shown as the last P_to
      const bool pd = detail::positive_definite(*X);
      if (!pd) {
        why = where + (X == &Pk ? ".P" : ".P_to") + " is not shown positive definite";
        return Cover::refuted;
      }
    }
    if (linear) {
      if (!detail::bernstein_stein_holds(Pk, Pto, detail::affine_loop_at(M1, M2, from), detail::affine_loop_at(M1, M2, to), why)) {
        why = where + " on [" + from.str() + ", " + to.str() + "] (P linear): " + why;
        return Cover::not_shown;
      }
    } else {
      for (const rational& e : {from, to})
        if (!detail::stein_holds(Pk, detail::affine_loop_at(M1, M2, e), why)) {
          why = where + " at " + p + " = " + e.str() + ": " + why;
          return Cover::not_shown;
        }
    }
    from = to;
  }
  return Cover::shown;
}

}  // namespace

detail::MaxPart detail::check_max_part(const SceneLoop& L1, const SceneLoop& L2, const MaxReading& r, const std::string& p,
                                       const nlohmann::json& ev,
                                       const ClaimRange& c, long conserved, size_t order, const std::optional<LoopMatrix>& at_hi,
                                       const std::string& at, bool need_unstable) {
  const std::string& block = r.block;
  // the evidence's shape first (malformed before anything is computed)
  const bool has_unstable = ev.contains("unstable_at"), outward = ev.contains("first_order_unstable");
  // no_crossing {to: a} (header): no eigenvalue of the rational M(p) meets the circle on (0, a]; in place of first_order
  // (the cover then starts at min(a, lo)), or, claim.hi = 0, beside unstable_at at a (NOT stable on (0, a])
  std::optional<rational> no_crossing;
  if (ev.contains("no_crossing")) {
    const nlohmann::json& nc = detail::object_field(ev, "no_crossing", at);
    detail::only_fields(nc, {"to"}, at + ".no_crossing");
    no_crossing = detail::exact_field(nc, "to", at + ".no_crossing");
    if (ev.contains("first_order") || outward || *no_crossing <= 0)
      throw InputError(at + ".no_crossing.to: above 0, and not beside first_order or first_order_unstable");
  }
  const rational un_at = no_crossing && c.hi.is_zero() ? *no_crossing : c.hi;  // where unstable_at is
  if (outward && (has_unstable || ev.contains("first_order") || !c.hi.is_zero()))
    throw InputError(at + ".first_order_unstable: with claim.hi = 0 only, in place of unstable_at and first_order (sup = 0 by the "
                          "first-order mirror)");
  if (!has_unstable && !outward && need_unstable)
    throw InputError(at + ".unstable_at: missing (NOT stable at hi bounds sup p; or, sup = 0, first_order_unstable)");
  const nlohmann::json none = nlohmann::json::object();
  const nlohmann::json& un = has_unstable ? detail::object_field(ev, "unstable_at", at) : none;
  detail::only_fields(un, {"at", "P", "w", "slow_quotient"}, at + ".unstable_at");
  const bool slow_quotient = un.contains("slow_quotient");
  if (slow_quotient && (!un.at("slow_quotient").is_boolean() || !un.at("slow_quotient").get<bool>() || !c.hi.is_zero()))
    throw InputError(at + ".unstable_at.slow_quotient: true, with claim.hi = 0 only (sup = 0 beside the slow modes)");
  if (has_unstable && detail::exact_field(un, "at", at + ".unstable_at") != un_at)
    throw InputError(at + ".unstable_at.at: not " + (un_at == c.hi ? "claim.hi (" : "no_crossing.to (") + un_at.str() + ")");
  if (no_crossing && c.hi.is_zero() && (slow_quotient || !has_unstable))
    throw InputError(at + ".no_crossing: with claim.hi = 0, beside unstable_at at no_crossing.to (not on a slow quotient)");
  const nlohmann::json cover = ev.contains("cover") ? ev.at("cover") : nlohmann::json::array();
  if (!cover.is_array() || cover.size() > kMaxCover)
    throw InputError(at + ".cover: not an array of at most " + std::to_string(kMaxCover) + " intervals");
  if (cover.empty() != c.lo.is_zero()) throw InputError(at + ".cover: needed exactly when claim.lo > 0 (it proves (0, lo])");
  MaxPart out;
  for (long bits : {128L, 256L, 512L}) {
    flint::BallPrecision scope(bits);
    const detail::LoopMatrix m1 = detail::loop_matrix(L1, bits), m2 = detail::loop_matrix(L2, bits);
    detail::require_loop_max_order(m1.order);
    out.order = m1.order, out.conserved = m1.conserved, out.bits = bits;
    if (const std::string not_affine = realisations_not_affine(r, p, m1, m2, at_hi ? &*at_hi : nullptr, order, c.hi); !not_affine.empty())
      return {false, not_affine};
    // conserved quantities paired with unseen z = 1 (stability_loop_check.cpp), or a right eigenvector with a part in
    // the plant: the pairing, or the vector, could move with p -- refused
    if ((m1.right_quotient && !m1.embedding.empty()) || (m2.right_quotient && !m2.embedding.empty()))
      throw InputError("model.scene: conserved quantities beside a block's unobservable z = 1 (a quotient by both): beyond this kind");
    if (m1.plant_right || m2.plant_right)
      throw InputError("model.scene: an unseen s = 0 of the plant set aside (a right eigenvector): beyond this kind");
    // p inside the tf (header): the conserved rows come from A, B alone, the same at every p; a block's
    // unobservable z = 1 (right eigenvectors, C r = 0) could move with C(p): refused
    if (r.inside && (m1.right_quotient || m2.right_quotient))
      throw InputError("model.scene: a block's unobservable z = 1 (a quotient by right eigenvectors) with " + p + " inside the " + block +
                       "'s tf: beyond this kind (the right eigenvectors are not shown the same at every " + p + ")");
    if (r.inside && m1.embedding != m2.embedding)
      return {false, "the conserved quantities' rows differ at " + p + " = 1 and 2 (with A and B equal they cannot: a checker defect)"};
    if (m1.feedthrough_loop || m2.feedthrough_loop)
      throw InputError("model.scene: D_E D_V or D_V D_E is not 0 (u and x_e solved through (I + D_E D_V)^-1): the loop is not affine "
                       "in " + p + ", beyond this kind");
    if (m1.conserved != m2.conserved || m1.M.size() != m2.M.size())
      return {false, "the conserved quantities differ at " + p + " = 1 and 2 (a checker defect or a model that is not affine)"};
    if (conserved >= 0 && static_cast<long>(m1.conserved) != conserved)
      return {false, (at == "evidence" ? std::string("claim") : at) + ": " + std::to_string(conserved) + " conserved quantities, but the loop has " +
                         std::to_string(m1.conserved)};
    const size_t n = m1.M.size();
    double tests = 0;  // Stein tests: 2 an interval, 4 Bernstein coefficients of 2.5 products each with P linear
    for (const auto& item : cover) tests += item.is_object() && item.contains("P_to") ? 5 : 1;
    if (tests * static_cast<double>(n * n * n) > kMaxCoverWork)
      throw InputError(at + ".cover: " + std::to_string(cover.size()) + " intervals of order " + std::to_string(n) +
                       ", beyond this checker's work limit (intervals x n^3 <= 5e7, one with P linear counted 5 times)");
    // stable on (0, eps] by the first-order start (header), then [eps, lo] by the cover
    rational from = 0;
    if (ev.contains("first_order")) {
      const std::string fw = detail::first_order_start(ev.at("first_order"), m1, m2, detail::slow_rows(L1, L2, m1), c.lo, from);
      if (!fw.empty()) {
        out.why = fw;
        continue;
      }
    }
    if (no_crossing && bits == 128) {
      if (m1.conserved != 0 || m1.right_quotient || L1.own_conserved != 0)
        throw InputError(at + ".no_crossing: a loop with conserved quantities (M on a quotient): beyond this kind");
      const auto X1 = detail::exact_loop_matrix(L1), X2 = detail::exact_loop_matrix(L2);
      if (!X1 || !X2 || X1->size() != X2->size())
        throw InputError(at + ".no_crossing: M is not rational (a plant component that is not nilpotent: e^{AT} holds "
                              "exponentials): beyond this kind");
      const size_t n = X1->size();
      MatQ M0(static_cast<long>(n), static_cast<long>(n)), Md(static_cast<long>(n), static_cast<long>(n));
      for (size_t i = 0; i < n; ++i)
        for (size_t j = 0; j < n; ++j) {
          M0(long(i), long(j)) = 2 * (*X1)[i][j] - (*X2)[i][j];
          Md(long(i), long(j)) = (*X2)[i][j] - (*X1)[i][j];
        }
      if (static_cast<long>(n) > kCircleCrossingOrder)
        throw InputError(at + ".no_crossing: M of order " + std::to_string(n) + ", beyond this checker's " +
                         std::to_string(kCircleCrossingOrder));
      std::string no;
      try {
        no = no_circle_crossing(M0, Md, *no_crossing);
      } catch (const InputError& e) {
        throw InputError(at + ".no_crossing: " + e.what() + ": beyond this checker");
      }
      if (!no.empty()) return {false, at + ".no_crossing: an eigenvalue may meet the unit circle in (0, " + no_crossing->str() + "]: " + no};
    }
    if (no_crossing) from = std::min(*no_crossing, c.lo);  // to >= lo: the cover is the one point lo
    // NOT stable on (0, eps] by the first-order mirror (header)
    if (outward) {
      bool refuted = false;
      out.why = detail::first_order_unstable(ev.at("first_order_unstable"), m1, m2, detail::slow_rows(L1, L2, m1), at, refuted);
      if (refuted) return {false, out.why};
      if (!out.why.empty()) continue;
    }
    // NOT stable at hi (or, hi = 0, at the limit M(0); slow_quotient: M(0) on ker L, L the slow rows (header))
    if (has_unstable) {
      BallRows Mu = detail::affine_loop_at(m1.M, m2.M, un_at);
      if (slow_quotient) {
        const Mat L = detail::slow_rows(L1, L2, m1);
        if (L.empty()) throw InputError(at + ".unstable_at.slow_quotient: the loop has no slow rows at " + p + " = 0");
        Mu = detail::restricted(Mu, L);
      }
      const size_t nu = Mu.size();
      const Mat Pu = symmetric_P(un, at + ".unstable_at", nu);
      const auto w = detail::exact_matrix(nlohmann::json{{"w", nlohmann::json::array({un.contains("w") ? un.at("w") : nlohmann::json()})}}, "w",
                                          at + ".unstable_at", nu);
      if (w[0].size() != nu) throw InputError(at + ".unstable_at.w: not of P's order");
      rational q = 0;
      for (size_t i = 0; i < nu; ++i)
        for (size_t j = 0; j < nu; ++j) q += w[0][i] * Pu[i][j] * w[0][j];
      if (q >= 0) return {false, at + ".unstable_at: w^T P w = " + detail::decimal(q) + " >= 0"};
      if (!detail::stein_holds(Pu, Mu, out.why)) {
        out.why = "at " + p + " = " + un_at.str() + " (NOT stable): " + out.why;
        continue;
      }
    }
    // stable on [0, lo], or on [eps, lo] after the first-order start (above)
    const Cover shown = check_cover(cover, m1.M, m2.M, from, c.lo, n, p, out.why, at);
    if (shown == Cover::refuted) return {false, out.why};
    if (shown == Cover::not_shown) continue;
    out.verified = true;
    return out;
  }
  return out;
}

nlohmann::json detail::model_at(const nlohmann::json& model, const std::string& p, const rational& value) {
  nlohmann::json m = model;
  m.erase("name");
  if (!m.contains("set")) m["set"] = nlohmann::json::object();
  m["set"][p] = value.str();
  return m;
}

detail::SupModel detail::sup_model(const nlohmann::json& model, const nlohmann::json& claim, const std::string& status) {
  if (!model.contains("name") || !model.at("name").is_string()) throw InputError("model.name: missing or not a string");
  const std::string p = model.at("name").get<std::string>();
  if (model.contains("set") && model.at("set").is_object() && model.at("set").contains(p))
    throw InputError("model.set." + p + ": the parameter maximised has no value");
  const ClaimRange c = claim_range(claim);
  if (c.status != status)
    throw InputError(status == "certified" ? "claim.status: \"certified\" (the loop holds exponentials: enclosures decide)"
                                           : "claim.status: sup = 0 by a hidden mode is \"exact\" (rational evidence, no enclosure)");
  if (!c.refuted && c.lo < 0) throw InputError("claim.lo: negative (sup p >= 0)");
  return {p, c};
}

namespace {

// sup p = 0 by a hidden mode (evidence.hidden, the stability-loop kind's form; header): NOT stable at p = 1 and at
// p = 2 by the same invariant subspace of one ss block. The conditions (C V = 0, A V = V A_h, or W B = 0, W A = A_h W)
// are linear in the block's (A, B, C); read_max_parameter proved that p enters only the environment's or the
// coupling's gain (C, D times p: C V = 0 iff p C V = 0 for p != 0) or a tf entry (not an ss block: no hidden form),
// and no other block. So the subspace, its A_h and the eigenvalue |lambda| >= 1, lambda != 1 (or the Jordan block at
// 1) are the loop's at every p > 0: NOT stable on all of (0, inf), and sup p = 0 (no p0 > 0 qualifies).
Verdict hidden_form(const nlohmann::json& model, const nlohmann::json& claim, const nlohmann::json& evidence) {
  detail::only_fields(evidence, {"hidden"}, "evidence");
  detail::only_fields(claim, {"quantity", "status", "value"}, "claim");
  if (!model.contains("scene") || !model.at("scene").is_string())
    throw InputError("evidence.hidden: a hidden mode of a scene's block (model.scene, a string)");
  const auto [p, c] = detail::sup_model(model, claim, "exact");
  if (c.refuted) return {false, *c.refuted};
  const detail::MaxReading r = detail::read_max_parameter(model.at("scene").get<std::string>(), p);
  std::string shown;
  for (const long v : {1L, 2L}) {
    const Verdict at = detail::hidden_mode_verdict(detail::read_scene_loop(detail::model_at(model, p, rational(v))), evidence.at("hidden"));
    if (!at.verified) return {false, "sup " + p + " = 0 not shown: at " + p + " = " + std::to_string(v) + ", " + at.reason};
    shown = at.reason;
  }
  if (c.lo != 0)
    return {false, "claim: sup " + p + " = " + detail::decimal(c.lo) + ", but the loop is NOT stable for every " + p + " > 0 by a hidden mode (" +
                       shown + "): sup = 0"};
  return {true, "sup " + p + " = 0 [exact]: " + shown + "; at " + p + " = 1 and 2 alike, and for every " + p + " > 0: " + p +
                    " enters only the " + r.block + "'s " + (r.inside ? "tf entries (no ss block's matrices)" : "gain (C, D times " + p + ")") +
                    ", and the hidden subspace's conditions are linear in the block's (A, B, C)"};
}

}  // namespace

Verdict check_stability_loop_max(const nlohmann::json& cert) {
  const auto [model, claim, evidence] = detail::certificate_parts(cert);
  if (model.contains("scene")) detail::only_fields(model, {"scene", "set", "name"}, "model");
  else detail::only_fields(model, {"plant", "H", "operator", "set", "T", "delay", "name"}, "model");
  if (evidence.contains("hidden")) return hidden_form(model, claim, evidence);
  detail::only_fields(claim, {"quantity", "status", "lo", "hi", "printed_lo", "printed_hi", "conserved"}, "claim");
  detail::only_fields(evidence, {"cover", "unstable_at", "first_order", "first_order_unstable", "no_crossing"}, "evidence");
  if (model.contains("scene") ? !model.at("scene").is_string() : !model.contains("plant"))
    throw InputError("model.scene: missing or not a string (or a one-DOF model: plant, H, T, delay)");
  const auto [p, c] = detail::sup_model(model, claim);
  if (c.refuted) return {false, *c.refuted};
  const long conserved = claim.contains("conserved") ? detail::integer_field(claim, "conserved", "claim", 0, 160) : 0;
  const MaxReading r = model.contains("scene") ? detail::read_max_parameter(model.at("scene").get<std::string>(), p) : read_p_plant(model, p);
  const std::string& block = r.block;
  const detail::SceneLoop L1 = detail::read_scene_loop(detail::model_at(model, p, rational(1))), L2 = detail::read_scene_loop(detail::model_at(model, p, rational(2)));
  if (2 * L1.dofs() > kMaxLoopOrder)  // each DOF's v and x: refused before any loop is built in balls
    throw InputError("model: " + std::to_string(L1.dofs()) + " DOFs, a closed loop of at least " + std::to_string(2 * L1.dofs()) +
                     " states, beyond this checker's " + std::to_string(kMaxLoopOrder) + " for a supremum");
  // p inside the block's tf (header): its realisation at 1, 2 and hi of the largest order, sum_j deg L_j
  long degree = 0;
  const size_t order = r.inside ? affine_block_order(model, r, p, L1, degree) : 0;
  std::optional<detail::LoopMatrix> at_hi;
  if (r.inside && c.hi > 0) {
    flint::BallPrecision scope(128);
    at_hi = detail::loop_matrix(detail::read_scene_loop(detail::model_at(model, p, c.hi)), 128);
  }
  const detail::MaxPart part = detail::check_max_part(L1, L2, r, p, evidence, c, conserved, order, at_hi, "evidence");
  if (!part.verified) return {false, "claim: sup " + p + " in [" + detail::decimal(c.lo) + ", " + detail::decimal(c.hi) + "], but " + part.why + " at 512 bits"};
  if (!*part.verified) return {false, part.why};
  const std::string loop = "the closed loop M(" + p + ") (" + std::to_string(part.order) + " states, " + std::to_string(L1.dofs()) +
                           " DOF" + (conserved ? ", on the quotient by " + std::to_string(conserved) + " conserved quantities" : "") +
                           ") = (2 - " + p + ") M(1) + (" + p + " - 1) M(2), affine (" + p +
                           (r.inside ? " inside the " + block + "'s tf, proven affine there (degree bound " + std::to_string(degree) +
                                           "), its realisation of order " + std::to_string(order) + " at 1, 2 and hi"
                                     : " the " + block + "'s gain alone") + ")" +
                           (evidence.contains("first_order") ? "; stable on (0, " + detail::decimal(from0(evidence)) + "] by the first-order start (P0 + L^T S L/" + p +
                                                                    ", concave in " + p + ")"
                            : evidence.contains("no_crossing") && !c.hi.is_zero()
                                ? "; no eigenvalue meets the unit circle on (0, " +
                                      detail::decimal(detail::exact_field(evidence.at("no_crossing"), "to", "evidence.no_crossing")) +
                                      "] (the resultant of det(zI - M) and its reciprocal has no root there)"
                                : std::string());
  const nlohmann::json cover = evidence.contains("cover") ? evidence.at("cover") : nlohmann::json::array();
  if (c.hi.is_zero() && evidence.contains("first_order_unstable"))
    return {true, "sup " + p + " = 0: " + loop + " is NOT stable for every " + p + " in (0, " +
                      detail::decimal(detail::exact_field(evidence.at("first_order_unstable"), "to", "evidence.first_order_unstable")) +
                      "] (the first-order mirror: P0 + L^T S L/" + p + " - M^T (.) M > 0, concave in " + p + ", with w^T (.) w < 0: Stein inertia, " +
                      std::to_string(part.bits) + " bits)"};
  if (c.hi.is_zero() && evidence.contains("no_crossing"))
    return {true, "sup " + p + " = 0: " + loop + " is NOT stable for every " + p + " in (0, " +
                      detail::decimal(detail::exact_field(evidence.at("no_crossing"), "to", "evidence.no_crossing")) +
                      "] (no eigenvalue meets the unit circle there: the resultant of det(zI - M) and its reciprocal has no root; "
                      "at its end an eigenvalue |z| > 1 by Stein inertia, " + std::to_string(part.bits) + " bits)"};
  if (c.hi.is_zero())
    return {true, "sup " + p + " = 0: " + loop + " has at " + p + " -> 0 an eigenvalue |z| > 1 (P - M(0)^T P M(0) > 0, w^T P w < 0: Stein " +
                      "inertia, " + std::to_string(part.bits) + " bits" +
                      (evidence.at("unstable_at").contains("slow_quotient") ? ", on ker L: M(0) there, L its slow rows (L M(0) = L), beside their eigenvalue 1" : "") +
                      "), and so has M(" + p + ") for every small " + p + " > 0"};
  return {true, "sup " + p + " in [" + detail::decimal(c.lo) + ", " + detail::decimal(c.hi) + "]: " + loop + "; stable on [0, " +
                    detail::decimal(c.lo) + "] (0 excluded where the first-order start serves) by " + std::to_string(cover.size()) +
                    " intervals, P > 0 with P - M^T P M > 0 at both ends of each (convex in " + p + "); NOT stable at " +
                    detail::decimal(c.hi) + " (Stein inertia), " + std::to_string(part.bits) + " bits"};
}

}  // namespace hapstab::check
