#include "hapstab/lti/state_space_json.hpp"

#include <cmath>

#include <nlohmann/json.hpp>

#include "hapstab/numeric/decimal.hpp"
#include "hapstab/numeric/error.hpp"
#include "hapstab/numeric/limits.hpp"

namespace hapstab {

namespace {

rational entry(const nlohmann::json& v, const std::string& where) {
  if (v.is_number()) {
    const double x = v.get<double>();
    if (!std::isfinite(x)) throw InputError(where + ": an entry is not finite (a number beyond the range of double)");
    return exact_rational(x);
  }
  if (v.is_string()) return parse_rational(v.get<std::string>(), where);
  throw InputError(where + ": expected a number or a string with an exact number");
}

Mat<rational> matrix(const nlohmann::json& j, const std::string& key, const std::string& file) {
  const std::string where = file + ": \"" + key + "\"";
  if (!j.contains(key)) throw InputError(where + " is missing");
  const auto& m = j.at(key);
  if (!m.is_array()) throw InputError(where + " must be an array of rows");
  if (m.empty()) return Mat<rational>(0, 0);
  const size_t rows = m.size();
  if (!m[0].is_array()) throw InputError(where + " must be an array of rows");
  const size_t cols = m[0].size();
  const auto limit = static_cast<size_t>(limits::state_space_dim);
  if (rows > limit || cols > limit)
    throw InputError(where + " is " + std::to_string(rows) + "x" + std::to_string(cols) + ", more than the limit of " +
                     std::to_string(limit) + " rows or columns");
  Mat<rational> M(rows, cols);
  for (size_t i = 0; i < rows; ++i) {
    if (!m[i].is_array() || m[i].size() != cols)
      throw InputError(where + ": row " + std::to_string(i + 1) + " does not have " + std::to_string(cols) + " entries");
    for (size_t c = 0; c < cols; ++c)
      M(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(c)) =
          entry(m[i][c], where + "[" + std::to_string(i + 1) + "][" + std::to_string(c + 1) + "]");
  }
  return M;
}

}  // namespace

StateSpace<rational> state_space_from_json_exact(std::string_view text, const std::string& where) {
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(text);
  } catch (const std::exception& e) {
    throw InputError(where + ": not valid JSON (" + e.what() + ")");
  }
  if (!j.is_object()) throw InputError(where + ": expected a JSON object with A, B, C, D, T");
  StateSpace<rational> s;
  s.A = matrix(j, "A", where);
  s.B = matrix(j, "B", where);
  s.C = matrix(j, "C", where);
  s.D = matrix(j, "D", where);
  if (!j.contains("T")) throw InputError(where + ": \"T\" (sample period) is missing");
  const auto& t = j.at("T");
  if (t.is_string()) s.T = parse_rational(t.get<std::string>(), where + ": \"T\"");
  else if (t.is_number()) s.T = exact_rational(t.get<double>());
  else throw InputError(where + ": \"T\" must be a number or a string with an exact number");
  if (!(s.T > 0)) throw InputError(where + ": \"T\" must be > 0 (a discrete-time system)");
  s.validate(where);
  return s;
}

StateSpace<double> state_space_from_json(std::string_view text, const std::string& where) {
  const StateSpace<rational> q = state_space_from_json_exact(text, where);
  auto rounded = [](const Mat<rational>& M) {
    return Mat<double>(M.unaryExpr([](const rational& x) { return to_real<double>(x); }));
  };
  StateSpace<double> s{rounded(q.A), rounded(q.B), rounded(q.C), rounded(q.D), q.T};
  for (const auto* M : {&s.A, &s.B, &s.C, &s.D})
    if (!M->allFinite()) throw InputError(where + ": an entry is not finite (a number beyond the range of double)");
  return s;
}

}  // namespace hapstab
