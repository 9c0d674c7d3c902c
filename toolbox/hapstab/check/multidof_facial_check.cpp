// hapstab/check/multidof_facial_check.cpp -- see multidof_facial_check.hpp.
#include "hapstab/check/multidof_facial_check.hpp"

#include <string>
#include <vector>

#include "hapstab/check/multidof_model.hpp"
#include "hapstab/numeric/error.hpp"

namespace hapstab::check {

namespace {

using namespace detail;
using namespace multidof_model;

// The rank of the rows (each of `cols` rationals), by Gaussian elimination over Q.
size_t rank_of(std::vector<std::vector<rational>> rows, size_t cols) {
  size_t rank = 0;
  for (size_t c = 0; c < cols && rank < rows.size(); ++c) {
    size_t pivot = rank;
    while (pivot < rows.size() && rows[pivot][c].is_zero()) ++pivot;
    if (pivot == rows.size()) continue;
    std::swap(rows[pivot], rows[rank]);
    for (size_t r = rank + 1; r < rows.size(); ++r) {
      if (rows[r][c].is_zero()) continue;
      const rational f = rows[r][c] / rows[rank][c];
      for (size_t k = c; k < cols; ++k) rows[r][k] -= f * rows[rank][k];
    }
    ++rank;
  }
  return rank;
}

}  // namespace

Verdict check_multidof_facial(const nlohmann::json& cert) {
  const Parts p = certificate_parts(cert);
  if (auto refuted = infeasibility_claim(p, "the facial conditions")) return {false, *refuted};
  only_fields(p.evidence, {}, "evidence");
  const PeriodDelay pd = read_period_delay(p.model);
  const Environment env = read_environment(p.model, pd.T, pd.n);
  const size_t m = env.E.size();
  (void)device_levels(p.model, m);  // the model must be whole, though (a) does not use the levels
  const std::vector<size_t> owner = operator_of(p.model, m);
  const size_t N = p.model.at("operators").size();
  if (env.gain.is_zero()) return {false, "the environment's gain is 0: E-hat = 0, and X E(1) g = 0 is symmetric"};
  const auto E1 = environment_at(env, Cq(1));
  if (!E1)
    throw InputError("model.environment.E: an entry has a pole at z = 1 (E-hat would have a double pole there; this kind "
                     "needs E(1) finite)");
  // g_o(i) E(1)_ij - g_o(j) E(1)_ji = 0 for i < j: one row per pair, N unknowns
  std::vector<std::vector<rational>> rows;
  for (size_t i = 0; i < m; ++i)
    for (size_t j = i + 1; j < m; ++j) {
      std::vector<rational> r(N, rational(0));
      r[owner[i]] += (*E1)[i][j].re;
      r[owner[j]] -= (*E1)[j][i].re;
      bool any = false;
      for (const auto& x : r) any = any || !x.is_zero();
      if (any) rows.push_back(std::move(r));
    }
  const size_t rank = rank_of(rows, N);
  if (rank < N)
    return {false, "the system g_a E(1)_ij = g_b E(1)_ji has rank " + std::to_string(rank) + " < " + std::to_string(N) +
                       " operators: some X = diag(g) != 0 makes X E(1) symmetric, which the facial conditions do not exclude"};
  return {true, "(16) infeasible: no X = diag(g) in G other than 0 makes X E(1) symmetric (the " + std::to_string(rows.size()) +
                    " conditions g_a E(1)_ij = g_b E(1)_ji have rank " + std::to_string(N) + " = the number of operators), so "
                    "phi_X -> -inf as theta -> 0+ for every admissible X, exactly"};
}

}  // namespace hapstab::check
