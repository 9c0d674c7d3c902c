// python/binding.hpp -- what the binding files of hapstab._core share: exact arguments, the
// result record every function returns (value, outward-rounded lo/hi as floats and as exact
// decimal strings, status, method), parameter columns of the vectorised calls, and the loop
// that runs their points on threads with the GIL released and Ctrl-C polled.
//
// The binding calls the library's own functions (the same ones the command line calls): no
// command line, no JSON. Its inputs are exact texts that the Python layer wrote (_exact.py:
// "1/1000", a float's shortest decimal) or numpy float64 arrays (each entry its shortest decimal;
// r's omega grid at its binary values); its errors are the library's InputError/NumericalError,
// worded for Python by the names passed in (ParseOptions::parameter_hint, LoopNames).
#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cstdint>
#include <functional>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "hapstab/lti/parse.hpp"
#include "hapstab/numeric/result.hpp"
#include "hapstab/numeric/scalar.hpp"
#include "hapstab/scene/scene.hpp"
#include "hapstab/sim/hidden_modes.hpp"

namespace hapstab::python {

namespace py = pybind11;

/// Status codes of the arrays the vectorised calls return (hapstab.STATUS names them).
enum StatusCode : int8_t { code_exact = 0, code_certified = 1, code_numeric = 2, code_failed = 3 };
StatusCode status_code(Status s);

/// The exact value of `text` (what _exact.exact wrote); InputError naming `what` otherwise.
rational exact_arg(const std::string& text, const std::string& what);
std::optional<rational> exact_arg(const std::optional<std::string>& text, const std::string& what);

/// The shortest decimal that rounds to the double x (Python's repr: 1e-3 is 1/1000), exactly: how
/// a float is read (python/hapstab/_exact.py; fractions.Fraction(x) gives the binary value).
rational shortest_decimal(double x);

/// How Python code names parameters and the period in the parser's messages.
ParseOptions parse_options(char variable, const rational& T, std::map<std::string, rational> params,
                           HiddenPoles hidden_poles = HiddenPoles::refuse);

/// The result record: {"value_exact": "p/q" | None, "mid": float, "lo": float, "hi": float,
/// "lo_text": str, "hi_text": str, "status": str, "method": str, "note": str}. lo/hi are the
/// enclosure rounded outward to doubles; lo_text/hi_text to `digits` significant decimal
/// digits, outward (exact decimals that still enclose). Without an enclosure (a numeric value
/// with no stated error): lo = hi = mid, texts of mid, and the status says numeric.
/// JSON the library builds for the command line (multidof/witness_json.hpp), as Python objects
/// (dict, list, str, float, bool, None), so that both print the same object.
inline py::object from_json(const nlohmann::json& j) { return py::module_::import("json").attr("loads")(j.dump()); }

py::dict record(const Certified<rational>& c, int digits);
/// The record of an infinite value (b* = inf, a gain stable for every K): value, lo, hi all +inf.
py::dict record_infinite(Status status, const std::string& method, const std::string& note);
py::dict record(const std::optional<Enclosure<rational>>& e, const rational& mid, Status status, const std::string& method,
                const std::string& note, int digits);

/// The parameter columns of a vectorised call: names, and per point the exact values.
struct Columns {
  std::vector<std::string> names;
  std::vector<std::vector<rational>> values;  ///< values[k][i]: parameter k at point i
  size_t points = 0;
  /// From Python: names, and per name a numpy float64 array (each entry read as the shortest
  /// decimal that rounds to it, as Python reads a float) or a list of exact texts; all of the
  /// same length (the Python layer broadcast them).
  static Columns from_python(const std::vector<std::string>& names, const py::list& columns);
  /// `fixed` with point i's values added.
  std::map<std::string, rational> at(const std::map<std::string, rational>& fixed, size_t i) const;
};

/// The expression `expr` (named `what` in messages) parsed once for the columns' parameters, the
/// fixed ones given: lti/parse.hpp's ParsedExpression, the parser's messages in Python's words.
ParsedExpression parsed(const std::string& expr, const std::string& what, char variable, const rational& T,
                        const std::map<std::string, rational>& fixed, const Columns& cols,
                        HiddenPoles hidden_poles = HiddenPoles::refuse);

/// Refuses (InputError naming `what`) an expression that names anything but the variable, T and
/// the parameters given (fixed or columns): a mistake of the whole call, raised before its points
/// run, not a failure of each point.
void check_names(const std::string& expr, const std::string& what, char variable,
                 const std::map<std::string, rational>& fixed, const Columns& cols);

/// Runs fn(i) for i < n on `jobs` threads (0: every CPU available) with the GIL released,
/// polling Ctrl-C: a KeyboardInterrupt stops the run after the points in progress and is raised.
void run_points(size_t n, unsigned jobs, const std::function<void(uint64_t)>& fn);

/// A failed point's message (InputError, NumericalError, anything else as "internal error: ...").
std::string point_error(const std::exception& e);

/// Runs `work` on a worker thread with the GIL released, polling Ctrl-C every 20 ms. On Ctrl-C
/// the work is asked to stop (numeric/interrupt.hpp: it stops at its next interruption point)
/// and KeyboardInterrupt is raised once it has; an exception of `work` is raised here.
void run_interruptible(const std::function<void()>& work);

/// A scene from Python: a path, or TOML text (named "scene" in messages) with is_text; the
/// overrides are exact texts of scene parameters.
scene::Scene scene_arg(const std::string& scene, bool is_text, const std::map<std::string, std::string>& overrides);

/// Every hidden mode of a loop's blocks as written (sim/hidden_modes.hpp): a list of
/// {block, kind, discrete, pair, where, re, im, abs ((lo, hi) floats, outward), stable}.
py::list hidden_modes(const sim::LoopHiddenModes& h);

/// The columns every vectorised call returns, one entry per point: value, lo, hi (NaN until the
/// point runs), status (failed until it runs), exact (the exact value where the status is exact),
/// lo_exact/hi_exact (the ends as outward decimals, where the floats may not decide a comparison)
/// and error (why the point failed). dict() hands them to Python as numpy arrays.
struct PointColumns {
  explicit PointColumns(size_t n);
  std::vector<double> value, lo, hi;
  std::vector<int8_t> status;
  std::vector<std::optional<std::string>> exact, lo_exact, hi_exact, error;
  /// Point i's enclosure [a, b] (outward to floats and to `digits` decimals) and its midpoint.
  void enclose(size_t i, const rational& a, const rational& b, int digits);
  py::dict dict() const;  ///< {"value", "lo", "hi", "status", "exact", "lo_exact", "hi_exact", "error"}
};

/// A float64 numpy array of n entries, and one of int8.
py::array_t<double> doubles(const std::vector<double>& v);
py::array_t<int8_t> codes(const std::vector<int8_t>& v);
/// An object array of str (None for an empty optional).
py::array strings(const std::vector<std::optional<std::string>>& v);

void register_types(py::module_& m);
void register_passivity(py::module_& m);
void register_stability(py::module_& m);
void register_scene(py::module_& m);
void register_multidof(py::module_& m);

}  // namespace hapstab::python
