"""hapstab -- passivity and stability of sampled-data haptic systems, from Python.

Each function runs the hapstab command of the same name (the C++ code of the command line,
in-process in a forked child: numbers identical to `hapstab ... --json`, the GIL released,
Ctrl-C stops a long call) and returns a Result whose attributes are the command's JSON keys:

    >>> import hapstab
    >>> b = hapstab.bound("K + B*(z-1)/(T*z)", T="1/1000", params={"K": 1000, "B": 5})
    >>> b.value, b.fraction, b.status
    ('5.5', Fraction(11, 2), 'exact')

H(z) is an expression string, a (num, den) pair of coefficients in descending powers of z
(int, Fraction, str exact; a float at its exact binary value), or a python-control
TransferFunction (any object with num, den, dt). Bad input raises hapstab.InputError (a
ValueError), a certified method that cannot finish hapstab.NumericalError (a RuntimeError).
"""
from __future__ import annotations

import csv
import json
import os
import re
import tempfile
import warnings
from typing import Any, Dict, Mapping, Optional, Sequence

try:
    from . import _core
except ImportError:  # the pure-Python files without the C++ extension next to them: say so
    _here = os.path.dirname(os.path.abspath(__file__))
    if any(name.startswith("_core.") for name in os.listdir(_here)):
        raise  # it is there and does not load: the loader's own message says why
    raise ImportError(f"hapstab: the C++ extension hapstab._core is not built in {_here} (in the build tree: "
                      f"cmake --build build --target hapstab_python; or pip install . from the source tree)") from None
from ._exact import exact, state_space_json, transfer_function
from ._results import Analysis, Bound, Design, PassivityLevel, R, Result, Simulation, Stability, Wedge

__version__: str = _core.__version__
InputError = _core.InputError
NumericalError = _core.NumericalError
InputError.__module__ = NumericalError.__module__ = "hapstab"

__all__ = ["r", "bound", "stability", "wedge", "passivity_level", "simulate", "multidof", "run", "examples_dir",
           "InputError", "NumericalError", "Result", "R", "Bound", "Wedge", "PassivityLevel", "Simulation",
           "Analysis", "Design", "sweep", "Sweep", "Stability"]


def run(*args: str) -> Result:
    """Runs `hapstab args... --json` as given (the escape hatch for options without a keyword)."""
    code, text = _core.run([str(a) for a in args])
    return Result(json.loads(text) if text is not None else {}, code)


_OPTION = re.compile(r"(?<![\w-])--([A-Za-z][A-Za-z0-9-]*)")


def _pythonic(message: str, command: str) -> str:
    """A command's error message in the words of the Python call: the keyword for an option
    (--frac-delay -> frac_delay), params={'K': ...} (or the keyword K=... of simulate and
    multidof) for --set NAME=VALUE."""
    keywords = command in ("simulate", "multidof")  # their parameters are keyword arguments
    unknown = re.search(r"unknown name '([^']+)'", message)
    name = unknown.group(1) if unknown else "NAME"
    message = message.replace("give parameters with --set NAME=VALUE",
                              f"pass {name}=... as a keyword argument" if keywords else f"pass params={{'{name}': ...}}")
    message = re.sub(r"--set[ =]'?([A-Za-z_]\w*)'?", (r"\1" if keywords else r"params['\1']"), message)
    message = message.replace("--set NAME=VALUE", "keyword arguments" if keywords else "params")
    return _OPTION.sub(lambda m: m.group(1).replace("-", "_"), message)


def _json(args: Sequence[str]):
    try:
        code, text = _core.run(list(args))
    except InputError as e:  # the command's message names its options: say it as the call was made
        raise InputError(_pythonic(str(e), args[0])) from None
    if text is None:
        raise RuntimeError(f"hapstab {' '.join(args[:1])} printed no JSON (exit code {code})")
    return json.loads(text), code


def _sets(params: Optional[Mapping[str, Any]]) -> list:
    return [f"--set={name}={exact(v, f'params[{name!r}]')}" for name, v in (params or {}).items()]


def examples_dir() -> str:
    """The folder of hapstab's example scenes (examples/ of the source tree, or share/hapstab/examples)."""
    return _core.examples_dir()


def r(T: Any, omega: Any, digits: int = 20, terms: Optional[int] = None) -> R:
    """r(jw) = T/(e^{jwT} - 1) of paper 001 (44), correctly rounded, and the series (34) truncated."""
    args = ["r", f"--T={exact(T, 'T')}", f"--omega={exact(omega, 'omega')}", f"--digits={int(digits)}", "--json"]
    if terms is not None:
        args.append(f"--terms={int(terms)}")
    return R(*_json(args))


def bound(H: Any, T: Any = None, delay: int = 0, frac_delay: Any = None, eta: Any = 0, digits: int = 30,
          method: str = "certified", params: Optional[Mapping[str, Any]] = None, damping: Any = None,
          grid_points: Optional[int] = None, allow_noncausal: bool = False) -> Bound:
    """The passivity bound b* of paper 001, (45)/(54): the loop is passive iff b > b*.

    T is the sample period (exact; taken from H.dt for a python-control system); delay an
    integer n (z^-n), frac_delay a delay in seconds, eta the operator's shortage of passivity.
    """
    expr, T_text = transfer_function(H, T)
    if T_text is None:
        raise InputError("T is required (the sample period)")
    args = ["bound", f"--H={expr}", f"--T={T_text}", f"--delay={int(delay)}", f"--eta={exact(eta, 'eta')}",
            f"--digits={int(digits)}", f"--method={method}", "--json", *_sets(params)]
    if frac_delay is not None:
        args.append(f"--frac-delay={exact(frac_delay, 'frac_delay')}")
    if damping is not None:
        args.append(f"--damping={exact(damping, 'damping')}")
    if grid_points is not None:
        args.append(f"--grid-points={int(grid_points)}")
    if allow_noncausal:
        args.append("--allow-noncausal")
    return Bound(*_json(args))


def stability(plant: str, H: Any, T: Any = None, delay: int = 0, operator: Optional[str] = None,
              max: Optional[str] = None, digits: int = 20,  # noqa: A002 -- the command's option name
              params: Optional[Mapping[str, Any]] = None) -> Stability:
    """Schur stability of the sampled loop: device plant(s) (force -> position, an expression in s)
    behind a zero-order hold, wall force -z^-n H(z) x(kT), optional operator impedance Z_op(s).
    With max="K" (a gain H is affine in): the largest K with the loop stable on (0, K)."""
    expr, T_text = transfer_function(H, T)
    if T_text is None:
        raise InputError("T is required (the sample period)")
    args = ["stability", f"--plant={plant}", f"--H={expr}", f"--T={T_text}", f"--delay={int(delay)}",
            f"--digits={int(digits)}", "--json", *_sets(params)]
    if operator is not None:
        args.append(f"--operator={operator}")
    if max is not None:
        args.append(f"--max={max}")
    return Stability(*_json(args))


def wedge(H: Any, T: Any = None, digits: int = 20, params: Optional[Mapping[str, Any]] = None) -> Wedge:
    """The wedge criterion (25) and Tsypkin's condition (21) of paper 002 for H(z), over all theta."""
    expr, T_text = transfer_function(H, T)
    args = ["wedge", f"--H={expr}", f"--digits={int(digits)}", "--json", *_sets(params)]
    if T_text is not None:
        args.append(f"--T={T_text}")
    return Wedge(*_json(args))


def passivity_level(H: Any = None, T: Any = None, ss: Optional[Sequence[Any]] = None, kind: str = "osp",
                    backend: Optional[str] = None, lemma: Optional[int] = None, grid: Optional[int] = None,
                    digits: Optional[int] = None, params: Optional[Mapping[str, Any]] = None) -> PassivityLevel:
    """The OSP (kind='osp') or ISP ('isp') level of a discrete LTI system, paper 000 Lemmas 1-2.

    Give H(z) (SISO, with T) or ss=(A, B, C, D) with T (MIMO, square).
    """
    if (H is None) == (ss is None):
        raise InputError("give exactly one of H or ss=(A, B, C, D)")
    args = ["passivity-level", f"--kind={kind}", "--json", *_sets(params)]
    for name, v in (("backend", backend), ("lemma", lemma), ("grid", grid), ("digits", digits)):
        if v is not None:
            args.append(f"--{name}={v}")
    if H is not None:
        expr, T_text = transfer_function(H, T)
        if T_text is None:
            raise InputError("T is required (the sample period)")
        return PassivityLevel(*_json(args + [f"--H={expr}", f"--T={T_text}"]))
    if T is None:
        raise InputError("T is required with ss=(A, B, C, D)")
    if len(ss) != 4:
        raise InputError(f"ss: expected (A, B, C, D), got {len(ss)} items")
    with tempfile.TemporaryDirectory(prefix="hapstab-ss-") as tmp:
        path = os.path.join(tmp, "ss.json")
        with open(path, "w", encoding="utf-8") as f:
            json.dump(state_space_json(*ss, T), f)
        return PassivityLevel(*_json(args + [f"--ss={path}"]))


# ---- scenes --------------------------------------------------------------------------------

class _SceneFile:
    """A scene given as a path, or as TOML text (written to a temporary scene.toml)."""

    def __init__(self, scene: Any) -> None:
        self._tmp = None
        if isinstance(scene, str) and "\n" in scene:
            self._tmp = tempfile.TemporaryDirectory(prefix="hapstab-scene-")
            self.path = os.path.join(self._tmp.name, "scene.toml")
            with open(self.path, "w", encoding="utf-8") as f:
                f.write(scene)
        elif isinstance(scene, (str, os.PathLike)):
            self.path = os.fspath(scene)
        else:
            raise TypeError(f"scene: expected a path or TOML text, got {type(scene).__name__}")

    def __enter__(self) -> str:
        return self.path

    def __exit__(self, *exc) -> None:
        if self._tmp is not None:
            self._tmp.cleanup()


_COLUMN = re.compile(r"(?P<name>[A-Za-z_]+)_(?P<dof>\d+) \[(?P<unit>[^\]]*)\]")


def read_series(path: str) -> tuple:
    """A simulate CSV (one header row `t [s],x_0 [m],...`) -> ({'t': (rows,), 'x': (rows, dofs), ...}, units)."""
    import numpy as np
    with open(path, newline="", encoding="utf-8") as f:
        header = next(csv.reader(f))
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # "input contained no data" for a run that recorded nothing
        data = np.loadtxt(path, delimiter=",", skiprows=1, ndmin=2, dtype=np.float64)
    if data.size == 0:
        data = np.empty((0, len(header)), dtype=np.float64)
    columns: Dict[str, list] = {}
    units = {"t": "s"}
    for k, name in enumerate(header[1:], start=1):
        m = _COLUMN.fullmatch(name)
        if not m:
            raise RuntimeError(f"{path}: unexpected column '{name}'")
        columns.setdefault(m["name"], []).append(k)
        units[m["name"]] = m["unit"]
    series = {"t": np.ascontiguousarray(data[:, 0])}
    for name, ks in columns.items():
        series[name] = np.ascontiguousarray(data[:, ks])
    return series, units


def simulate(scene: Any, *, out: Optional[str] = None, force: bool = False, max_output: Optional[float] = None,
             **overrides: Any) -> Simulation:
    """Simulates a scene (a path, or TOML text) with the exact-ZOH simulator: `hapstab simulate`.

    overrides are scene parameters (`--set NAME=VALUE`, exact). The files (CSV, plot.gp,
    summary.json) go to `out` when given (kept), else to a temporary folder (removed).
    """
    with _SceneFile(scene) as path, tempfile.TemporaryDirectory(prefix="hapstab-sim-") as tmp:
        folder = os.fspath(out) if out is not None else tmp
        args = ["simulate", f"--scene={path}", f"--out={folder}", "--json", "--quiet", *_sets(overrides)]
        if force:
            args.append("--force")
        if max_output is not None:
            args.append(f"--max-output={float(max_output)!r}")
        data, code = _json(args)
        samples, units = read_series(os.path.join(folder, "samples.csv"))
        fine_path = os.path.join(folder, "fine.csv")
        fine = read_series(fine_path)[0] if os.path.exists(fine_path) else None
        return Simulation(data, code, samples, fine, units, folder if out is not None else None)


from . import multidof  # noqa: E402  (uses _SceneFile, _json, _sets above)
from ._sweep import Sweep, sweep  # noqa: E402
