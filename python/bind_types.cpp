// python/bind_types.cpp -- the library's model types in Python: hapstab.TransferFunction (lti/
// tf.hpp: exact SISO H(z) or P(s)) and hapstab.StateSpace (lti/state_space.hpp, exact entries).
// Built once, passed to any function: hapstab.tf("K + B*(z-1)/(T*z)", T="1/1000", params=...)
// parses the expression once.
#include "cli/tf_options.hpp"
#include "hapstab/lti/state_space.hpp"
#include "hapstab/numeric/decimal.hpp"
#include "hapstab/numeric/error.hpp"
#include "python/binding.hpp"

namespace hapstab::python {
namespace {

std::vector<std::string> descending(const Polynomial<rational>& p) {
  std::vector<std::string> out;
  for (int k = p.degree(); k >= 0; --k) out.push_back(p.coeff(k).str());
  if (out.empty()) out.push_back("0");
  return out;
}

std::vector<rational> exact_list(const std::vector<std::string>& texts, const std::string& what) {
  std::vector<rational> v;
  for (size_t i = 0; i < texts.size(); ++i) v.push_back(exact_arg(texts[i], what + "[" + std::to_string(i) + "]"));
  return v;
}

Mat<rational> exact_matrix(const std::vector<std::vector<std::string>>& rows, const std::string& what) {
  const size_t cols = rows.empty() ? 0 : rows.front().size();
  Mat<rational> M(Eigen::Index(rows.size()), Eigen::Index(cols));
  for (size_t i = 0; i < rows.size(); ++i) {
    if (rows[i].size() != cols)
      throw InputError(what + ": row " + std::to_string(i) + " has " + std::to_string(rows[i].size()) + " entries, row 0 has " +
                       std::to_string(cols));
    for (size_t j = 0; j < cols; ++j)
      M(Eigen::Index(i), Eigen::Index(j)) = exact_arg(rows[i][j], what + "[" + std::to_string(i) + "][" + std::to_string(j) + "]");
  }
  return M;
}

// "refuse" (every use but b*) or "allow_marginal" (b*, as `bound` reads H): lti/parse.hpp HiddenPoles.
HiddenPoles hidden_policy(const std::string& name) {
  if (name == "refuse") return HiddenPoles::refuse;
  if (name == "allow_marginal") return HiddenPoles::allow_marginal;
  throw std::logic_error("hidden_poles: '" + name + "' (expected refuse or allow_marginal)");
}

std::vector<std::vector<std::string>> texts(const Mat<rational>& M) {
  std::vector<std::vector<std::string>> out(size_t(M.rows()));
  for (Eigen::Index i = 0; i < M.rows(); ++i)
    for (Eigen::Index j = 0; j < M.cols(); ++j) out[size_t(i)].push_back(M(i, j).str());
  return out;
}

}  // namespace

void register_types(py::module_& m) {
  py::class_<TransferFunction>(m, "TransferFunction",
                               "An exact SISO transfer function H(z) (discrete, sample period T) or P(s) (continuous), "
                               "reduced: lti/tf.hpp. Build it with hapstab.tf().")
      .def_property_readonly("num", [](const TransferFunction& t) { return descending(t.num()); },
                             "numerator coefficients, descending powers, exact (p/q strings)")
      .def_property_readonly("den", [](const TransferFunction& t) { return descending(t.den()); },
                             "denominator coefficients, descending powers, exact (monic)")
      .def_property_readonly("T", [](const TransferFunction& t) { return t.is_discrete() ? py::object(py::str(t.T.str())) : py::object(py::none()); },
                             "the sample period (exact p/q string), None for P(s)")
      .def_property_readonly("variable", [](const TransferFunction& t) { return std::string(t.variable()); })
      .def("__str__", &TransferFunction::to_string)
      .def("__repr__", [](const TransferFunction& t) {
        return "hapstab.TransferFunction(" + t.to_string() + (t.is_discrete() ? ", T=" + t.T.str() : std::string()) + ")";
      });

  m.def(
      "tf_from_expression",
      [](const std::string& text, const std::optional<std::string>& T, const std::map<std::string, std::string>& params,
         const std::string& variable, const std::string& what, const std::string& hidden_poles) {
        std::map<std::string, rational> p;
        for (const auto& [k, v] : params) p[k] = exact_arg(v, "params['" + k + "']");
        const rational period = T ? exact_arg(*T, "T") : rational(0);
        if (T && period <= 0) throw InputError("T: the sample period must be > 0, got " + *T);
        ParseOptions po = parse_options(variable.empty() ? 0 : variable[0], period, std::move(p), hidden_policy(hidden_poles));
        try {
          return parse_tf(text, po);
        } catch (const InputError& e) {
          throw InputError(what + ": " + e.what());
        }
      },
      py::arg("text"), py::arg("T"), py::arg("params"), py::arg("variable"), py::arg("what"), py::arg("hidden_poles") = "refuse",
      "Parses an exact expression (lti/parse.hpp) into a TransferFunction.");
  m.def(
      "tf_from_coefficients",
      [](const std::vector<std::string>& num, const std::vector<std::string>& den, const std::string& T,
         const std::string& what, const std::string& hidden_poles) {
        const rational period = exact_arg(T, "T");
        if (period <= 0) throw InputError("T: the sample period must be > 0, got " + T);
        return cli::tf_from_coefficients(exact_list(num, what + " numerator"), exact_list(den, what + " denominator"),
                                         period, what + " numerator", what + " denominator", hidden_policy(hidden_poles));
      },
      py::arg("num"), py::arg("den"), py::arg("T"), py::arg("what"), py::arg("hidden_poles") = "refuse",
      "H(z) = num(z)/den(z) from exact coefficients in descending powers of z.");

  py::class_<StateSpace<rational>>(m, "StateSpace",
                                   "A discrete state space (A, B, C, D) with exact entries and period T: lti/state_space.hpp.")
      .def(py::init([](const std::vector<std::vector<std::string>>& A, const std::vector<std::vector<std::string>>& B,
                       const std::vector<std::vector<std::string>>& C, const std::vector<std::vector<std::string>>& D,
                       const std::string& T) {
             StateSpace<rational> s{exact_matrix(A, "ss A"), exact_matrix(B, "ss B"), exact_matrix(C, "ss C"),
                                    exact_matrix(D, "ss D"), exact_arg(T, "T")};
             if (s.T <= 0) throw InputError("T: the sample period must be > 0, got " + T);
             s.validate("ss");
             return s;
           }),
           py::arg("A"), py::arg("B"), py::arg("C"), py::arg("D"), py::arg("T"))
      .def_property_readonly("A", [](const StateSpace<rational>& s) { return texts(s.A); })
      .def_property_readonly("B", [](const StateSpace<rational>& s) { return texts(s.B); })
      .def_property_readonly("C", [](const StateSpace<rational>& s) { return texts(s.C); })
      .def_property_readonly("D", [](const StateSpace<rational>& s) { return texts(s.D); })
      .def_property_readonly("T", [](const StateSpace<rational>& s) { return s.T.str(); })
      .def_property_readonly("shape", [](const StateSpace<rational>& s) {
        return py::make_tuple(s.states(), s.inputs(), s.outputs());
      }, "(states, inputs, outputs)")
      .def("__repr__", [](const StateSpace<rational>& s) {
        return "hapstab.StateSpace(states=" + std::to_string(s.states()) + ", inputs=" + std::to_string(s.inputs()) +
               ", outputs=" + std::to_string(s.outputs()) + ", T=" + s.T.str() + ")";
      });
}

}  // namespace hapstab::python
