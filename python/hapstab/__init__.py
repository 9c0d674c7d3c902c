"""hapstab -- passivity and stability of sampled-data haptic systems, from Python.

The functions are bindings of hapstab's C++ library (the functions the `hapstab` command line
calls: the same numbers by construction), over its own types (hapstab.tf: an exact transfer
function; hapstab.ss: an exact state space). Every scalar result follows one protocol (value,
lo, hi, lo_exact, hi_exact, status, method, float(), honest comparisons; hapstab._results):

    >>> import hapstab
    >>> b = hapstab.bound("K + B*(z-1)/(T*z)", T="1/1000", params={"K": 1000, "B": 5})
    >>> b.value, b.status, b > 5
    (Fraction(11, 2), 'exact', True)

An array in params (or an omega array for r) makes the call vectorised: one call parses the
expression for every point and runs the points on threads with the GIL released (Ctrl-C stops
it), returning a ResultArray of numpy arrays:

    >>> K = np.linspace(0, 40000, 10001)
    >>> bs = hapstab.bound("K + B*(z-1)/(T*z)", T="1/1000", delay=1, params={"K": K, "B": 5})
    >>> bs.value, bs.lo, bs.hi, bs.status          # float64, float64, float64, str (STATUS)

H(z) is an expression string, a hapstab.TransferFunction, a (num, den) pair of coefficients in
descending powers of z (int, Fraction, str exact; a float as the shortest decimal that rounds to
it, 1e-3 = 1/1000; Fraction(x) for its binary value), or a python-control or scipy.signal system
(read by its attributes: num, den, dt; A, B, C, D, dt for ss=). Bad input raises
hapstab.InputError (a ValueError) naming the argument, a certified method that cannot finish
hapstab.NumericalError (a RuntimeError).
"""
from __future__ import annotations

import os
import re
from typing import Any, Dict, Mapping, Optional, Tuple

try:
    from . import _core
except ImportError:  # the pure-Python files without the C++ extension next to them: say so
    _here = os.path.dirname(os.path.abspath(__file__))
    if any(name.startswith("_core.") for name in os.listdir(_here)):
        raise  # it is there and does not load: the loader's own message says why
    raise ImportError(f"hapstab: the C++ extension hapstab._core is not built in {_here} (in the build tree: "
                      f"cmake --build build --target hapstab_python; or pip install . from the source tree)") from None
from ._exact import (continuous_text, exact, integer, is_state_space, is_system, period_of, real, state_space,
                     system_period, transfer_function)
from ._results import (STATUS, Analysis, Bound, Design, MaxGain, MaxPassiveGain, PassivityLevel, R, Result, ResultArray,
                       Simulation, Stability, UndecidedComparison, Wedge)

__version__: str = _core.__version__
InputError = _core.InputError
NumericalError = _core.NumericalError
InputError.__module__ = NumericalError.__module__ = "hapstab"
TransferFunction = _core.TransferFunction
StateSpace = _core.StateSpace
TransferFunction.__module__ = StateSpace.__module__ = "hapstab"

__all__ = ["tf", "ss", "r", "bound", "stability", "wedge", "passivity_level", "simulate", "multidof", "sweep", "run",
           "examples_dir", "InputError", "NumericalError", "UndecidedComparison", "Result", "ResultArray", "STATUS",
           "TransferFunction", "StateSpace", "R", "Bound", "Wedge", "PassivityLevel", "Stability", "MaxGain",
           "MaxPassiveGain", "Simulation", "Analysis", "Design", "Sweep", "RArray"]

_DELAY_HINT = "delay is a whole number of sample periods n (z^-n); a delay in seconds is frac_delay=... (exact)"


# ---- errors in the words of the call -------------------------------------------------------

_OPTION = re.compile(r"(?<![\w-])--([A-Za-z][A-Za-z0-9-]*)")


def _pythonic(message: str, keywords: bool = False) -> str:
    """A message some library or command code words for the command line, in the words of the
    Python call: an option (--allow-noncausal, --delay) becomes its keyword, --set NAME=VALUE
    params={'NAME': ...} (or the keyword NAME=... of simulate and multidof)."""
    unknown = re.search(r"unknown name '([^']+)'", message)
    name = unknown.group(1) if unknown else "NAME"
    message = message.replace("give parameters with --set NAME=VALUE",
                              f"pass {name}=... as a keyword argument" if keywords else f"pass params={{'{name}': ...}}")
    message = re.sub(r"--set[ =]'?([A-Za-z_]\w*)'?", (r"\1" if keywords else r"params['\1']"), message)
    message = message.replace("--set NAME=VALUE", "keyword arguments" if keywords else "params")
    message = message.replace("--set", "a keyword argument" if keywords else "params")
    message = message.replace("--resume", "resume=True").replace("--allow-noncausal", "allow_noncausal=True")
    return _OPTION.sub(lambda m: m.group(1).replace("-", "_"), message)


def _call(fn, *args: Any, keywords: bool = False, **kwargs: Any) -> Any:
    try:
        return fn(*args, **kwargs)
    except InputError as e:
        raise InputError(_pythonic(str(e), keywords)) from None
    except NumericalError as e:
        raise NumericalError(_pythonic(str(e), keywords)) from None


# ---- parameters: scalars and arrays --------------------------------------------------------

def _is_array(v: Any) -> bool:
    """An array of values: anything np.asarray takes with ndim >= 1 (a list, a tuple, a range, a
    numpy array, a pandas Series or DataFrame column, ...); a 0-d array is one number."""
    import numpy as np
    if isinstance(v, (str, bytes, Mapping)) or v is None:
        return False
    if isinstance(v, (list, tuple, range)):
        return True
    if hasattr(v, "__array__") or hasattr(v, "__len__"):
        return np.ndim(v) >= 1
    return False


def _asarray(v: Any) -> Any:
    import numpy as np
    a = np.asarray(v)
    if a.dtype.kind == "O" and hasattr(v, "dtype") and getattr(v.dtype, "kind", "O") in "fiu":
        a = a.astype(v.dtype)  # a pandas column of a nullable dtype: its numbers
    return a


def _column(name: str, a: Any, what: Optional[str] = None) -> Any:
    """One parameter's values at every point: float64 (the binding reads each as the shortest
    decimal that rounds to it, as a scalar float is read), integers below 2^53 as float64 (exact),
    else the exact texts (Fraction(x) entries for binary values)."""
    import numpy as np
    flat = np.asarray(a).ravel()
    what = what or f"params[{name!r}]"
    if flat.dtype.kind == "b":
        raise InputError(f"{what}: a bool array; expected numbers")
    if flat.dtype.kind == "f":
        bad = ~np.isfinite(flat)
        if bad.any():
            i = int(np.argmax(bad))
            raise InputError(f"{what}[{i}]: {flat[i]} is not a finite number")
        if flat.dtype == np.float64:
            return np.ascontiguousarray(flat)  # the binding reads each as its shortest decimal (core.cpp)
        return [exact(x, f"{what}[{i}]") for i, x in enumerate(flat)]  # float32/16: numpy's own shortest
    if flat.dtype.kind in "iu" and (flat.size == 0 or int(np.abs(flat.astype(object)).max()) < 2**53):
        return flat.astype(np.float64)  # exact: integers below 2^53 are doubles
    return [exact(x.item() if hasattr(x, "item") and not isinstance(x, np.floating) else x, f"{what}[{i}]")
            for i, x in enumerate(flat)]


def _check_names(params: Optional[Mapping[str, Any]], exprs: Any, maximised: Optional[str] = None) -> None:
    """Refuses a name in params that no expression of the call names (a typo is never ignored),
    and the quantity maximised given a value (max=NAME varies it)."""
    if not params or any(text is not None and not isinstance(text, str) for text, _ in exprs):
        return  # no params, or a model given by numbers (params are refused for it by name, later)
    known: set = set()
    for text, variable in exprs:
        if isinstance(text, str):
            known |= set(_core.names_in(text)) - {variable}
    if maximised is not None and str(maximised) in map(str, params):
        v = params[maximised]
        kind = "an array" if _is_array(v) else "a value"
        raise InputError(f"params[{maximised!r}]: {maximised} is the quantity maximised (max={maximised!r}); it takes "
                         f"no {kind} (leave it out of params; arrays go to the other parameters)")
    unknown = [str(k) for k in params if str(k) not in known]
    if unknown:
        names = ", ".join(sorted(known - {"T"})) or "none"
        raise InputError(f"params: unknown name{'s' if len(unknown) > 1 else ''} "
                         f"{', '.join(repr(k) for k in unknown)}: the expressions name {names}")


def _params(params: Optional[Mapping[str, Any]]) -> Tuple[Dict[str, str], list, list, Optional[tuple], Dict[str, Any]]:
    """(fixed exact texts, array names, their columns, broadcast shape or None, the arrays)."""
    import numpy as np
    fixed: Dict[str, str] = {}
    arrays: Dict[str, Any] = {}
    for name, v in (params or {}).items():
        name = str(name)
        if _is_array(v):
            arrays[name] = _asarray(v) if not isinstance(v, np.ndarray) else v
        else:
            fixed[name] = exact(v, f"params[{name!r}]")
    if not arrays:
        return fixed, [], [], None, {}
    try:
        shape = np.broadcast_shapes(*(a.shape for a in arrays.values()))
    except ValueError:
        raise InputError("params: the arrays do not broadcast to one shape: "
                         + ", ".join(f"{k} {a.shape}" for k, a in arrays.items())) from None
    names = list(arrays)
    columns = [_column(k, np.broadcast_to(a, shape)) for k, a in arrays.items()]
    return fixed, names, columns, shape, arrays


def _jobs(jobs: Any) -> int:
    return 0 if jobs is None else integer(jobs, "jobs", 1, 1024)


def _expression(H: Any, what: str = "H") -> str:
    if not isinstance(H, str):
        raise InputError(f"params: an array in params needs {what} as an expression string (its parameters vary); "
                         f"got {type(H).__name__}")
    return H


# ---- the model types -----------------------------------------------------------------------

def tf(H: Any, T: Any = None, params: Optional[Mapping[str, Any]] = None) -> TransferFunction:
    """An exact transfer function (the library's lti TransferFunction): from an expression in z
    (or s when T is None and it names s), parsed once with `params`; a (num, den) pair in
    descending powers of z; or a python-control TransferFunction (num, den, dt)."""
    if isinstance(H, str):
        _check_names(params, [(H, "z" if T is not None or "z" in _core.names_in(H) else "s")])
    return _call(transfer_function, H, T, params, "H", "")


def ss(A: Any, B: Any, C: Any, D: Any, T: Any) -> StateSpace:
    """An exact discrete state space (A, B, C, D) with period T (entries exact as numbers are)."""
    return _call(state_space, A, B, C, D, T)


def run(*args: str):
    """Runs `hapstab args... --json` as given, the command line itself (the escape hatch for an
    option without a keyword): (exit code, the command's JSON as a dict or None)."""
    import json
    code, text = _core.run([str(a) for a in args])
    return code, (json.loads(text) if text is not None else None)


def examples_dir() -> str:
    """The folder of hapstab's example scenes (examples/ of the source tree, or share/hapstab/examples)."""
    return _core.examples_dir()


# ---- paper 001: r(jw) and b* -----------------------------------------------------------------

class RArray:
    """r(jw) over an array of w: re (float, exact -T/2; re_exact its exact p/q), im (float64, the
    shape of omega), im_lo/im_hi the enclosure of im (outward: proven with method 'certified', the
    stated error band of the double evaluation with 'double'), value the complex128 array,
    status 'certified' or 'numeric', method. np.asarray(r) is value; r[i] (an index for every
    axis) is point i as an R (re exact, im a Result of the array's status), r[1:] / r[mask] an
    RArray, `for x in r` iterates over the first axis."""

    def __init__(self, d: Dict[str, Any], shape: tuple, method: str) -> None:
        import numpy as np
        self.re, self.re_exact = d["re"], d["re_exact"]
        self.im = np.asarray(d["im"]).reshape(shape)
        self.im_lo = np.asarray(d["lo"]).reshape(shape)
        self.im_hi = np.asarray(d["hi"]).reshape(shape)
        self.omega = np.asarray(d["omega"]).reshape(shape) if "omega" in d else None
        self.status = "certified" if method == "certified" else "numeric"
        self._kind = method
        self.method = ("closed form (44), MPFI at 128 bits at each w's exact binary value: Im enclosures rounded outward"
                       if method == "certified" else
                       "closed form (44) in double: Im = -(T/2)/tan(fl(wT)/2), within 1.51 eps plus the rounding of wT "
                       "(sampling/r_forms.hpp); lo/hi state that band, not a proof")

    @property
    def shape(self) -> tuple:
        return self.im.shape

    @property
    def value(self):
        return self.re + 1j * self.im

    @property
    def lo(self):
        return self.re + 1j * self.im_lo

    @property
    def hi(self):
        return self.re + 1j * self.im_hi

    def __array__(self, dtype=None, copy=None):
        import numpy as np
        return np.asarray(self.value, dtype=dtype)

    def __len__(self) -> int:
        return len(self.im)

    def __getitem__(self, index: Any) -> Any:
        import numpy as np
        im, lo, hi = self.im[index], self.im_lo[index], self.im_hi[index]
        if np.ndim(im) == 0:
            from ._exact import to_fraction
            re = to_fraction(self.re_exact)
            re_rec = {"value_exact": self.re_exact, "mid": float(re), "lo": float(self.re), "hi": float(self.re),
                      "lo_text": self.re_exact, "hi_text": self.re_exact, "status": "exact",
                      "method": "Re r = -T/2, exact", "note": ""}
            im_rec = {"value_exact": None, "mid": float(im), "lo": float(lo), "hi": float(hi), "lo_text": None,
                      "hi_text": None, "status": self.status, "method": self.method, "note": ""}
            return R({"re": re_rec, "im": im_rec, "series_re": None, "series_im": None, "series_terms": None,
                      "series_error_bound": None, "re_text": self.re_exact, "im_text": repr(float(im))},
                     status=self.status, method=self.method)
        out = RArray.__new__(RArray)
        out.__dict__.update(self.__dict__)
        out.im, out.im_lo, out.im_hi = im, lo, hi
        return out

    def __iter__(self):
        for i in range(len(self)):
            yield self[i]

    def __repr__(self) -> str:
        return f"hapstab.RArray(shape={self.im.shape}, status={self.status!r})"


def r(T: Any, omega: Any, digits: int = 20, terms: Optional[int] = None, method: str = "double",
      jobs: Optional[int] = None):
    """r(jw) = T/(e^{jwT} - 1) of paper 001 (44).

    omega a number: an R, correctly rounded to `digits` (re exact, im certified) from the closed
    form alone; terms=N adds the series (34) truncated at |n| <= N beside it (series_re,
    series_im, series_error_bound; None without), as `hapstab r --terms N` prints it. omega an array (float64 at its exact
    binary values): an RArray, method 'double' (numeric, about 10 ns a point) or 'certified'
    (MPFI enclosures, proven)."""
    T_text = exact(T, "T")
    if _is_array(omega):
        import numpy as np
        w = np.asarray(omega)
        if w.dtype.kind not in "fiu":
            raise InputError(f"omega: expected an array of numbers, got dtype {w.dtype}")
        if method not in ("double", "certified"):
            raise InputError(f"method: expected 'double' or 'certified', got {method!r}")
        d = _call(_core.r_many, T_text, np.ascontiguousarray(w.ravel(), dtype=np.float64), method, _jobs(jobs))
        return RArray(d, w.shape, method)
    digits = integer(digits, "digits", 1, 1000)
    terms = None if terms is None else integer(terms, "terms", 0, 100000000)
    return R(_call(_core.r, T_text, exact(omega, "omega"), digits, terms))


def bound(H: Any, T: Any = None, delay: int = 0, frac_delay: Any = None, eta: Any = 0, digits: int = 30,
          method: str = "certified", params: Optional[Mapping[str, Any]] = None, damping: Any = None,
          grid_points: Optional[int] = None, allow_noncausal: bool = False, jobs: Optional[int] = None,
          max: Optional[str] = None, check: bool = False):  # noqa: A002 -- max: the name of the quantity
    """The passivity bound b* of paper 001, (45)/(54): the loop is passive iff b > b*.

    T is the sample period (exact; taken from H.dt for a python-control system); delay an
    integer n >= 0 (z^-n; a bool or a float is refused, never truncated), frac_delay a delay in
    seconds (exact), eta the operator's shortage of passivity, method 'certified' (proven
    enclosure, exact where the maximiser is rational), 'fast' (double, numeric) or 'grid'.
    damping=b adds {b, passive} (passive iff b > b*, decided by the enclosure). An array in
    params gives a ResultArray (H an expression), its points on `jobs` threads (default: every
    CPU).

    max="K" (H an expression affine in K) with damping=b: the passivity boundary as a number, a
    MaxPassiveGain: sup{K0 : b > b*(K) for 0 <= K < K0}, certified (exact where rational), with
    the closed form of Secs. VI-VII that applies; check=True adds b* at the ends of its enclosure
    (b* = b there). Arrays in params (the other parameters) or in damping give a ResultArray."""
    delay = integer(delay, "delay", 0, _core.CRITERION_DELAY, _DELAY_HINT)
    digits = integer(digits, "digits", 10, 280)
    grid_points = 100000 if grid_points is None else integer(grid_points, "grid_points", 2, 100000000)
    if not isinstance(allow_noncausal, bool):
        raise InputError(f"allow_noncausal: expected True or False, got {allow_noncausal!r}")
    if not isinstance(method, str):
        raise InputError(f"method: expected 'certified', 'fast' or 'grid', got {method!r}")
    frac = None if frac_delay is None else exact(frac_delay, "frac_delay")
    eta_text = exact(eta, "eta")
    T_text = period_of(H, T)
    if T_text is None:
        raise InputError("T is required (the sample period)")
    if max is not None:
        return _bound_max(H, T_text, delay, frac, eta_text, digits, method, params, damping, allow_noncausal, jobs,
                          max, check)
    if check is not False:
        raise InputError("check: b* at the ends of the answer's enclosure belongs to max='K' (pass max=...)")
    _check_names(params, [(H, "z")])
    fixed, names, columns, shape, arrays = _params(params)
    if shape is not None:
        if damping is not None:
            raise InputError("damping: with an array in params compare the result instead (bs.lo > b, bs.hi < b)")
        d = _call(_core.bound_many, _expression(H), fixed, names, columns, T_text, delay, frac, eta_text, digits, method,
                  grid_points, allow_noncausal, _jobs(jobs))
        return ResultArray(Bound, d, shape, f"b* ({method})", arrays)
    Htf = _call(transfer_function, H, T_text, fixed, "H", "z", "allow_marginal")  # as `bound` reads H
    d = _call(_core.bound, Htf, T_text, delay, frac, eta_text, digits, method, grid_points, allow_noncausal)
    extra = {k: d[k] for k in ("omega", "where", "decimal", "infinite", "closed_form", "enclosure_rigorous")}
    b = Bound(d, **extra)
    if damping is not None:
        bd = exact(damping, "damping")
        from ._exact import to_fraction
        if to_fraction(bd) <= 0:
            raise InputError(f"damping must be > 0 (got {bd})")
        if b.status not in ("exact", "certified"):
            raise InputError("damping needs a proven b*: use method='certified' (the default)")
        try:
            passive = (not b.infinite) and b < bd
        except UndecidedComparison:
            raise NumericalError(f"damping={bd} lies inside the enclosure of b*; raise digits") from None
        b._extra["damping"] = {"b": bd, "passive": passive}
    return b


def _bound_max(H: Any, T_text: str, delay: int, frac: Optional[str], eta_text: str, digits: int, method: str,
               params: Optional[Mapping[str, Any]], damping: Any, allow_noncausal: bool, jobs: Any, name: Any,
               check: Any):
    """bound(..., max=NAME): passivity::max_gain (`hapstab bound --max NAME --damping b`)."""
    import numpy as np
    if not isinstance(name, str) or not name:
        raise InputError(f"max: expected the name of a parameter of H (a str), got {name!r}")
    if damping is None:
        raise InputError(f"max={name!r} needs damping=b (the device's damping that must exceed b*)")
    if method != "certified":
        raise InputError(f"max={name!r} is certified only: leave out method={method!r}")
    if not isinstance(check, bool):
        raise InputError(f"check: expected True or False, got {check!r}")
    if not isinstance(H, str):
        raise InputError(f"max={name!r}: H must be an expression string in {name} (it is split as H0 + {name} H1), "
                         f"got {type(H).__name__}")
    _check_names(params, [(H, "z")], name)
    fixed, names, columns, shape, arrays = _params(params)
    if _is_array(damping):
        b = np.asarray(damping)
        try:
            shape = np.broadcast_shapes(b.shape, *(a.shape for a in arrays.values()))
        except ValueError:
            raise InputError("damping: the array does not broadcast with the arrays in params: "
                             + ", ".join(f"{k} {a.shape}" for k, a in {"damping": b, **arrays}.items())) from None
        columns = [_column(k, np.broadcast_to(a, shape)) for k, a in arrays.items()]
        damping_arg = _column("damping", np.broadcast_to(b, shape), "damping")
        if not isinstance(damping_arg, list) and (damping_arg <= 0).any():
            i = int(np.argmax(damping_arg <= 0))
            raise InputError(f"damping[{i}] must be > 0 (got {damping_arg[i]!r})")
        arrays = {**arrays, "damping": b}
    else:
        damping_arg = exact(damping, "damping")
    if shape is not None:
        if check:
            raise InputError("check: with arrays the boundary check runs per scalar call (r = bs[i] has lo/hi; "
                             "call bound(..., max=..., check=True) at one point)")
        d = _call(_core.bound_max_many, H, fixed, names, columns, name, damping_arg, T_text, delay, frac, eta_text,
                  digits, allow_noncausal, _jobs(jobs))
        return ResultArray(MaxPassiveGain, d, shape, f"largest passive {name} (passivity::max_gain, certified)", arrays)
    d = _call(_core.bound_max, H, fixed, name, damping_arg, T_text, delay, frac, eta_text, digits, allow_noncausal, check)
    extra = {k: d[k] for k in ("name", "outcome", "infinite", "decimal", "digits_certified", "omega", "where",
                               "closed_form")}
    extra["damping"] = d["damping"]
    extra["b_at_zero"] = Bound(d["b_at_zero"])
    extra["jump"] = d["jump"]
    extra["b_at_sup"] = None if d["b_at_sup"] is None else Bound(d["b_at_sup"])
    c = d["check"]
    extra["check"] = None if c is None else {"holds": c["holds"], "bound_at_lo": Bound(c["bound_at_lo"]),
                                             "bound_at_hi": Bound(c["bound_at_hi"])}
    return MaxPassiveGain(d, **extra)


# ---- paper 002: the wedge criterion ----------------------------------------------------------

def wedge(H: Any, T: Any = None, digits: int = 20, params: Optional[Mapping[str, Any]] = None) -> Wedge:
    """The wedge criterion (25) and Tsypkin's condition (21) of paper 002 for H(z), over all theta
    (T only when the expression names T)."""
    digits = integer(digits, "digits", 1, 60)
    T_text = period_of(H, T) or "1"  # H(z) alone does not depend on T unless the expression names it
    _check_names(params, [(H, "z")])
    Htf = _call(transfer_function, H, T_text, params, "H")
    d = _call(_core.wedge, Htf, digits)
    wedge_c, tsypkin_c = (dict(d[k]) for k in ("wedge", "tsypkin"))
    for c in (wedge_c, tsypkin_c):
        if c["evaluated"]:
            c["margin"] = Result(c["margin"])
            c["max_gain"] = None if c["gain_infinite"] else Result(c["max_gain"])
    if wedge_c["evaluated"]:
        rec = wedge_c["margin"]._rec
    else:
        rec = {"value_exact": None, "mid": float("nan"), "lo": float("nan"), "hi": float("nan"), "lo_text": None,
               "hi_text": None, "status": "failed", "method": "wedge criterion (25)", "note": wedge_c["evidence"]}
    return Wedge(rec, wedge=wedge_c, tsypkin=tsypkin_c, applies=d["applies"], assumptions=d["assumptions"], H=d["H"],
                 H1=d["H1"])


# ---- stability of the sampled loop -----------------------------------------------------------

def _text(H: Any, what: str, T_text: Optional[str] = None) -> str:
    """H(z) as an expression: a str, a TransferFunction, or a system object / (num, den) pair
    (exact coefficients, its dt checked against T)."""
    if isinstance(H, str):
        return H
    if isinstance(H, _core.TransferFunction):
        return str(H)
    if is_system(H) or (isinstance(H, (tuple, list)) and len(H) == 2):
        return str(_call(transfer_function, H, T_text, None, what))
    raise TypeError(f"{what}: expected an expression string, a hapstab.TransferFunction, (num, den) or a system "
                    f"object (num, den, dt), got {type(H).__name__}")


def _plant_text(P: Any, what: str = "plant") -> Any:
    """The device P(s) (or the operator's Z_op(s)): an expression in s, or a continuous-time system
    object (num, den; dt 0 or None)."""
    if P is None or isinstance(P, str):
        return P
    if is_system(P):
        return _call(continuous_text, P, what)
    raise TypeError(f"{what}: expected an expression string in s or a continuous-time system object (num, den), got "
                    f"{type(P).__name__}")


def stability(plant: Optional[str] = None, H: Any = None, T: Any = None, delay: int = 0, operator: Optional[str] = None,
              max: Optional[str] = None, digits: int = 20,  # noqa: A002 -- the name of the quantity
              params: Optional[Mapping[str, Any]] = None, jobs: Optional[int] = None, *, scene: Any = None,
              conservatism: bool = False):
    """Schur stability of the sampled loop: device plant(s) (force -> position, an expression in s)
    behind a zero-order hold, wall force -z^-n H(z) x(kT), optional operator impedance Z_op(s).
    A Stability (value: the spectral radius; bool: stable). With max="K" (a gain H is affine
    in): a MaxGain, the largest K with the loop stable on (0, K). An array in params gives a
    ResultArray (stable as int8 1/0/-1 undecided, or the max gains), on threads.

    scene=S (a path or TOML text) instead of plant/H/T/operator/delay: the loop the scene writes,
    any number of DOF, each block's realisation as written (`hapstab stability --scene`:
    stability::decide_loop), params its parameters. A Stability whose value is the closed loop's
    spectral radius in double (status numeric) and whose verdict (stable, verdict_status) is
    certified or exact, with the blocks' hidden modes (hidden_modes). Arrays in params: a
    ResultArray (stable, verdict_status, states, evidence), on threads.

    scene=S with max="NAME": the largest NAME with the loop as written stable, by the library's
    functions `hapstab stability --scene S --max NAME` calls (stability/loop_max.hpp; a one-DOF
    scene stability::max_gain; the bisection on certified verdicts where the loop is not affine in
    NAME): a MaxGain whose value is the supremum where it is proven (status certified or exact),
    else status 'undecided' and value NaN with what is proven beside it (stable_on, change_in);
    with conservatism=True also Theorem 5's largest NAME (theorem5: its bracket, what decided
    each end) and the ratio exact / Theorem 5 (conservatism: (lo, hi) decimal strings, or None). One
    point per call (params scalars); `hapstab.sweep` runs grids."""
    if not isinstance(conservatism, bool):
        raise InputError(f"conservatism: expected True or False, got {conservatism!r}")
    if conservatism and (scene is None or max is None):
        raise InputError("conservatism=True compares Theorem 5 with the loop as written on a scene: it needs scene=... "
                         "and max=...")
    if scene is not None:
        if max is not None:
            return _stability_scene_max(scene, plant, H, T, delay, operator, max, digits, params, conservatism)
        return _stability_scene(scene, plant, H, T, delay, operator, max, params, jobs)
    if plant is None or H is None:
        raise InputError("give plant and H (the device and the wall), or scene=... (a scene's loop as written)")
    delay = integer(delay, "delay", 0, _core.CRITERION_DELAY, _DELAY_HINT)
    digits = integer(digits, "digits", 1, 1000)
    T_text = period_of(H, T)
    if T_text is None:
        raise InputError("T is required (the sample period)")
    if max is not None and not isinstance(max, str):
        raise InputError(f"max: expected the name of a gain (a str), got {max!r}")
    H_text = _text(H, "H", T_text)
    plant, operator = _plant_text(plant), _plant_text(operator, "operator")
    _check_names(params, [(plant, "s"), (H_text, "z"), (operator, "s")], max)
    fixed, names, columns, shape, arrays = _params(params)
    if shape is not None:
        d = _call(_core.stability_many, plant, H_text, operator, T_text, delay, max, digits, fixed, names, columns,
                  _jobs(jobs))
        if max is None:  # value/lo/hi: the spectral radius; stable: 1, 0, -1 undecided
            return ResultArray(Stability, d, shape, "spectral radius of the sampled loop (stability::decide)", arrays)
        return ResultArray(MaxGain, d, shape, f"largest stable {max} (stability::max_gain)", arrays)
    d = _call(_core.stability, plant, H_text, operator, T_text, delay, max, digits, fixed)
    if max is not None:
        rec = d["max"] or {"value_exact": None, "mid": float("nan"), "lo": float("nan"), "hi": float("nan"),
                           "lo_text": None, "hi_text": None, "status": "undecided", "method": "stability::max_gain",
                           "note": d["note"]}
        extra = {k: d.get(k) for k in ("name", "outcome", "crossing", "theta", "omega", "precision_bits")}
        return MaxGain(rec, **extra)
    rec = d["spectral_radius"] or {"value_exact": None, "mid": float("nan"), "lo": float("nan"), "hi": float("nan"),
                                   "lo_text": None, "hi_text": None, "status": d["status"],
                                   "method": "stability::decide", "note": d["evidence"]}
    extra = {k: d[k] for k in ("stable", "evidence", "degree", "device", "precision_bits")}
    extra["verdict_status"] = d["status"]
    return Stability(rec, **extra)


def _stability_scene(scene: Any, plant: Any, H: Any, T: Any, delay: Any, operator: Any, max: Any,  # noqa: A002
                     params: Optional[Mapping[str, Any]], jobs: Any):
    """stability(scene=...): stability::decide_loop on the scene's loop as written."""
    given = [k for k, v in (("plant", plant), ("H", H), ("T", T), ("operator", operator)) if v is not None]
    if delay != 0:
        given.append("delay")
    if given:
        raise InputError(f"scene replaces plant, H, operator, T and delay (the scene holds them); got {', '.join(given)}")
    s = _SceneFile(scene)
    source = s.text if s.text is not None else s.path
    fixed, names, columns, shape, arrays = _params(params)
    if shape is not None:
        d = _call(_core.stability_scene_many, source, s.text is not None, fixed, names, columns, _jobs(jobs))
        return ResultArray(Stability, d, shape, "the scene's loop as written (stability::decide_loop); value: the "
                           "spectral radius in double, verdict: stable/verdict_status", arrays)
    d = _call(_core.stability_scene, source, s.text is not None, fixed)
    radius = d["spectral_radius_numeric"]
    if radius is None:  # not computed: a hidden mode decided the loop
        radius = float("nan")
    rec = {"value_exact": None, "mid": radius, "lo": radius, "hi": radius, "lo_text": None, "hi_text": None,
           "status": "numeric", "method": "spectral radius of the closed-loop matrix in double (" + (d["method"] or
                                                                                                   "not decided") + ")",
           "note": d["evidence"]}
    extra = {k: d[k] for k in ("stable", "evidence", "method", "dofs", "states", "hidden_modes", "hidden_summary",
                               "scene")}
    extra["verdict_status"] = d["status"]
    extra["decider"] = extra.pop("method")
    return Stability(rec, **extra)


def _stability_scene_max(scene: Any, plant: Any, H: Any, T: Any, delay: Any, operator: Any, name: Any, digits: Any,
                         params: Optional[Mapping[str, Any]], conservatism: bool):
    """stability(scene=..., max=NAME[, conservatism=True]): the library's functions the command
    `hapstab stability --scene S --max NAME [--conservatism]` calls (python/bind_stability.cpp:
    stability/loop_max.hpp, or the bisection on certified verdicts where the loop is not affine in
    NAME, conservatism/theorem5_max.hpp)."""
    given = [k for k, v in (("plant", plant), ("H", H), ("T", T), ("operator", operator)) if v is not None]
    if delay != 0:
        given.append("delay")
    if given:
        raise InputError(f"scene replaces plant, H, operator, T and delay (the scene holds them); got {', '.join(given)}")
    if not isinstance(name, str):
        raise InputError(f"max: expected the name of a scene parameter (a str), got {name!r}")
    digits = integer(digits, "digits", 1, 1000)
    fixed, names, columns, shape, arrays = _params(params)
    if shape is not None:
        raise InputError(f"max={name!r} with scene: one point per call (scalar params); hapstab.sweep runs a grid of them "
                         f"(command 'stability', args scene, max, conservatism)")
    s = _SceneFile(scene)
    d = _call(_core.stability_scene_max, s.text if s.text is not None else s.path, s.text is not None, fixed, name,
              digits, conservatism)
    rec = d.pop("record")
    rec["note"] = d.pop("note", rec.get("note", ""))
    return MaxGain(rec, **d)


# ---- paper 000: passivity levels ---------------------------------------------------------------

def passivity_level(H: Any = None, T: Any = None, ss: Any = None, kind: str = "osp", backend: Optional[str] = None,
                    lemma: Optional[int] = None, grid: Optional[int] = None, digits: Optional[int] = None,
                    params: Optional[Mapping[str, Any]] = None, jobs: Optional[int] = None):
    """The OSP (kind='osp') or ISP ('isp') level of a discrete LTI system, paper 000 Lemmas 1-2.

    Give H(z) (SISO, with T) or ss=(A, B, C, D) (or a hapstab.StateSpace) with T (MIMO, square).
    An array in params (H an expression) gives a ResultArray, on threads (the SDP solves one at a
    time: the solvers are not thread-safe)."""
    if (H is None) == (ss is None):
        raise InputError("give exactly one of H or ss=(A, B, C, D)")
    if kind not in ("osp", "isp"):
        raise InputError(f"kind: expected 'osp' or 'isp', got {kind!r}")
    backend = "auto" if backend is None else backend
    if backend not in ("auto", "dsdp", "csdp", "ipm"):
        raise InputError(f"backend: expected 'auto', 'dsdp', 'csdp' or 'ipm', got {backend!r}")
    lemma = 1 if lemma is None else integer(lemma, "lemma", 1, 2)
    grid = 4096 if grid is None else integer(grid, "grid", 16, 10000000)
    digits = 17 if digits is None else integer(digits, "digits", 10, 100)
    if ss is not None:
        if params:
            raise InputError("params: ss=(A, B, C, D) holds numbers; params name parameters of an expression H")
        if isinstance(ss, _core.StateSpace):
            model = ss
        elif is_state_space(ss):  # python-control's or scipy.signal's StateSpace: A, B, C, D, dt
            T_ss = _call(system_period, ss, None if T is None else exact(T, "T"), "ss")
            model = _call(state_space, ss.A, ss.B, ss.C, ss.D, T_ss)
        else:
            if T is None:
                raise InputError("T is required with ss=(A, B, C, D)")
            if not isinstance(ss, (tuple, list)) or len(ss) != 4:
                raise InputError(f"ss: expected (A, B, C, D), a hapstab.StateSpace or a state-space object (A, B, C, D, "
                                 f"dt), got {type(ss).__name__}")
            model = _call(state_space, *ss, T)
        d = _call(_core.passivity_level_ss, model, kind, backend, lemma, grid, digits)
    else:
        T_text = period_of(H, T)
        if T_text is None:
            raise InputError("T is required (the sample period)")
        _check_names(params, [(H, "z")])
        fixed, names, columns, shape, arrays = _params(params)
        if shape is not None:
            d = _call(_core.passivity_level_many, _expression(H), T_text, fixed, names, columns, kind, backend, lemma,
                      grid, digits, _jobs(jobs))
            return ResultArray(PassivityLevel, d, shape, f"{kind} level (lmi::passivity_levels)", arrays)
        d = _call(_core.passivity_level, _call(transfer_function, H, T_text, fixed, "H"), kind, backend, lemma, grid,
                  digits)
    extra = {k: d[k] for k in ("kind", "theta", "is_level", "certified_value", "lmi_level", "lmi_lower_bound",
                               "lmi_method", "grid_level")}
    return PassivityLevel(d["level"], **extra)


# ---- scenes -------------------------------------------------------------------------------------

class _SceneFile:
    """A scene given as a path, or as TOML text (given to the library as text, named 'scene')."""

    def __init__(self, scene: Any) -> None:
        if isinstance(scene, str) and "\n" in scene:
            self.text, self.path = scene, None
        elif isinstance(scene, (str, os.PathLike)):
            self.text, self.path = None, os.fspath(scene)
        else:
            raise TypeError(f"scene: expected a path or TOML text, got {type(scene).__name__}")


_UNITS = {"t": "s", "x": "m", "v": "m/s", "u": "N", "fh": "N", "E_port": "J", "E_act": "J", "E_po": "J", "storage": "J"}


def simulate(scene: Any, *, force: bool = False, max_output: Optional[float] = None, **overrides: Any) -> Simulation:
    """Simulates a scene (a path, or TOML text) with the exact-ZOH simulator (the library's, as
    `hapstab simulate`); the series come back as numpy arrays (Simulation.samples, .fine).

    overrides are scene parameters (exact). max_output (MB, default 200) caps the arrays the run
    would hold (force=True lifts it). Ctrl-C stops the run within about 1/100 of it."""
    s = _SceneFile(scene)
    if not isinstance(force, bool):
        raise InputError(f"force: expected True or False, got {force!r}")
    cap = 200.0 if max_output is None else real(max_output, "max_output")
    texts = {str(k): exact(v, str(k)) for k, v in overrides.items()}
    d = _call(_core.simulate, s.text if s.text is not None else s.path, s.text is not None, texts, cap, force,
              keywords=True)
    summary = d["summary"]
    rec = {"value_exact": None, "mid": summary["max_velocity"], "lo": summary["max_velocity"],
           "hi": summary["max_velocity"], "lo_text": None, "hi_text": None, "status": "numeric",
           "method": summary["method"], "note": ""}
    return Simulation(rec, samples=d["samples"], fine=d["fine"], units=dict(_UNITS), summary_fields=summary, **summary)


from . import multidof  # noqa: E402  (uses _SceneFile, _call above)
from ._sweep import Sweep, sweep  # noqa: E402
