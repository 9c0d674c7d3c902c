"""hapstab._sweep -- a sweep from Python: a command over exact parameter axes (docs/sweep.md),
run by the sweep's own workers (cli/sweep_cli.hpp, in a forked child), read back as a
structured numpy array.

    >>> t = hapstab.sweep({"command": "bound",
    ...                    "args": {"H": "K + B*(z-1)/(T*z)", "T": "1/1000", "delay": 1},
    ...                    "axes": {"K": {"from": "0", "to": "40000", "points": 5},
    ...                             "B": {"values": ["0", "5", "20"]}}})
    >>> t["bound"]                  # float64, one row per point in index order
    >>> t.exact["bound"]            # the command's own decimal strings
    >>> t.to_pandas()               # a pandas DataFrame (Debian's python3-pandas)

The spec is a path, TOML text, or a dict of the same shape as the TOML file (given to the
sweep as text: its messages call it "spec"; a float in the dict is written as its shortest
decimal string, 1e-3 -> "0.001", as every Python float is read).
"""
from __future__ import annotations

import csv
import json
import os
import tempfile

import numpy as np
from fractions import Fraction
from typing import Any, Dict, Mapping, Optional

from . import _core


def _toml_value(v: Any, where: str) -> str:
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, int):
        return str(v)
    if isinstance(v, float):  # TOML floats are refused (not exact): the shortest decimal, as every Python float
        from ._exact import exact
        return json.dumps(exact(v, f"spec {where}"))
    if isinstance(v, (str, Fraction)):
        return json.dumps(str(v))  # a TOML basic string: JSON's escapes are TOML's
    if isinstance(v, (list, tuple)):
        return "[" + ", ".join(_toml_value(x, f"{where}[{i}]") for i, x in enumerate(v)) + "]"
    if isinstance(v, Mapping):
        return "{ " + ", ".join(f"{_toml_key(k)} = {_toml_value(x, f'{where}.{k}')}" for k, x in v.items()) + " }"
    raise TypeError(f"spec {where}: cannot write a {type(v).__name__} to TOML")


def _toml_key(k: Any) -> str:
    return json.dumps(str(k))  # quoted keys are always valid TOML


def spec_toml(spec: Mapping[str, Any]) -> str:
    """The TOML text of a spec given as a dict {command, args: {...}, axes: {...}}."""
    unknown = set(spec) - {"command", "args", "axes"}
    if unknown:
        raise _core.InputError(f"spec: unknown key(s) {', '.join(sorted(map(str, unknown)))} "
                               "(expected command, args, axes)")
    lines = [f"command = {_toml_value(spec.get('command', ''), 'command')}"]
    for table in ("args", "axes"):
        lines.append(f"[{table}]")
        for k, v in (spec.get(table) or {}).items():
            lines.append(f"{_toml_key(k)} = {_toml_value(v, f'{table}.{k}')}")
    return "\n".join(lines) + "\n"


def _number(text: str) -> float:
    """A cell as float: decimals, inf, and p/q (exact axis values); ValueError otherwise."""
    if "/" in text:
        return float(Fraction(text))
    return float(text)


def _column(name: str, cells: list, strings: Any) -> Any:
    """index, exit: int64; error: the messages; all true/false: bool; all numbers (empty -> NaN):
    float64; anything else: the strings."""
    import numpy as np
    if name in ("index", "exit"):
        return np.array([int(c) for c in cells], dtype=np.int64)
    if name == "error":
        return strings
    if cells and all(c in ("true", "false") for c in cells):
        return np.array([c == "true" for c in cells], dtype=bool)
    try:
        return np.array([_number(c) if c != "" else np.nan for c in cells], dtype=np.float64)
    except (ValueError, ZeroDivisionError):
        return strings


class Sweep(np.ndarray):
    """A finished sweep: points.csv as a structured numpy array, one row per point (index order).

    t[name]        `index` and `exit` int64; a true/false column bool; a column whose every
                   non-empty cell is a number (decimal, inf, p/q) float64, empty -> NaN; any
                   other column (and `error`) the strings, dtype object
    t.exact[name]  every column's cells as written (strings; the exact axis values, the
                   command's decimals)
    t.manifest     manifest.json (spec SHA-256, version, counts, wall time)
    t.exit_code    0 every point ran, 1 some failed (their `error` cell says why)
    t.path         the output folder (None when it was a temporary one)
    t.failed       the number of failed points;  t.to_pandas()  a DataFrame
    """

    exact: Dict[str, Any]
    manifest: Dict[str, Any]
    exit_code: int
    path: Optional[str]

    @staticmethod
    def read(folder: str, exit_code: int, keep: bool) -> "Sweep":
        with open(os.path.join(folder, "points.csv"), newline="", encoding="utf-8") as f:
            rows = list(csv.reader(f))
        header, body = rows[0], rows[1:]
        exact: Dict[str, Any] = {}
        columns = []
        for k, name in enumerate(header):
            cells = [r[k] for r in body]
            exact[name] = np.array(cells, dtype=object)
            columns.append(_column(name, cells, exact[name]))
        table = np.empty(len(body), dtype=[(n, c.dtype) for n, c in zip(header, columns)])
        for n, c in zip(header, columns):
            table[n] = c
        t = table.view(Sweep)
        t.exact = exact
        with open(os.path.join(folder, "manifest.json"), encoding="utf-8") as f:
            t.manifest = json.load(f)
        t.exit_code = exit_code
        t.path = folder if keep else None
        return t

    def __array_finalize__(self, obj: Any) -> None:
        for name in ("exact", "manifest", "exit_code", "path"):
            setattr(self, name, getattr(obj, name, None))

    @property
    def failed(self) -> int:
        """The points whose command failed (a non-empty `error` cell)."""
        return int(sum(1 for e in (self.exact or {}).get("error", ()) if e))

    def to_pandas(self):
        """The table as a pandas DataFrame (Debian's python3-pandas); the same columns as the array."""
        try:
            import pandas
        except ImportError as e:
            raise ImportError("to_pandas() needs pandas (Debian: python3-pandas); the array itself has the same "
                              "columns") from e
        return pandas.DataFrame({n: np.asarray(self[n]) for n in self.dtype.names})

    def __repr__(self) -> str:
        if self.dtype.names is None or self.exact is None:
            return np.ndarray.__repr__(np.asarray(self))
        return f"hapstab.Sweep(points={len(self)}, failed={self.failed}, columns={list(self.dtype.names)})"


def sweep(spec: Any, out: Optional[str] = None, *, jobs: Optional[int] = None, shard: Optional[str] = None,
          resume: bool = False) -> Sweep:
    """Runs a sweep (docs/sweep.md) and reads its points.csv into a Sweep (a structured array).

    spec: a path, TOML text, or a dict {command, args, axes}. out: the folder to keep
    (points.csv, manifest.json); a temporary one, removed after reading, when None. jobs
    (worker processes), shard ("I/N") and resume as in docs/sweep.md. A bad spec raises
    hapstab.InputError naming the key; failed points are rows with an `error` (exit_code 1)."""
    from . import _call
    from ._exact import integer
    if isinstance(spec, Mapping):
        text: Optional[str] = spec_toml(spec)
    elif isinstance(spec, str) and "\n" in spec:
        text = spec
    elif isinstance(spec, (str, os.PathLike)):
        text = None
    else:
        raise TypeError(f"spec: expected a path, TOML text or a dict, got {type(spec).__name__}")
    if not isinstance(resume, bool):
        raise _core.InputError(f"resume: expected True or False, got {resume!r}")
    n_jobs = 0 if jobs is None else integer(jobs, "jobs", 1, 1024)
    shard_text = "0/1" if shard is None else str(shard)
    with tempfile.TemporaryDirectory(prefix="hapstab-sweep-") as tmp:
        folder = os.fspath(out) if out is not None else os.path.join(tmp, "out")
        code = _call(_core.sweep, text if text is not None else os.fspath(spec), text is not None, folder, n_jobs,
                     shard_text, resume)
        return Sweep.read(folder, code, keep=out is not None)
