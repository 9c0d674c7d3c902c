"""hapstab._sweep -- `hapstab sweep` from Python: a command over exact parameter axes
(docs/sweep.md), run by the command's own workers, read back as numpy arrays.

    >>> t = hapstab.sweep({"command": "bound",
    ...                    "args": {"H": "K + B*(z-1)/(T*z)", "T": "1/1000", "delay": 1},
    ...                    "axes": {"K": {"from": "0", "to": "40000", "points": 5},
    ...                             "B": {"values": ["0", "5", "20"]}}})
    >>> t.columns["bound"]          # float64, one row per point in index order
    >>> t.exact["bound"]            # the command's own decimal strings
    >>> t.frame()                   # a pandas DataFrame, when pandas is importable

The spec is a path, TOML text, or a dict of the same shape as the TOML file.
"""
from __future__ import annotations

import csv
import json
import os
import tempfile
from fractions import Fraction
from typing import Any, Dict, Mapping, Optional

from . import _core


def _toml_value(v: Any, where: str) -> str:
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, int):
        return str(v)
    if isinstance(v, float):  # hapstab refuses TOML floats (not exact): say how to give it
        raise _core.InputError(f"spec {where}: {v!r} is a float; give it as a string ('0.001' or '1/1000'), exactly")
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


class Sweep:
    """A finished sweep: points.csv as columns (one entry per point, index order).

    columns[name]  `index` and `exit` int64; a true/false column bool; a column whose every
                   non-empty cell is a number (decimal, inf, p/q) float64, empty -> NaN; any
                   other column (and `error`) the strings, dtype object
    exact[name]    every column's cells as written (strings; the exact axis values, the
                   command's decimals)
    manifest       manifest.json (spec SHA-256, version, counts, wall time)
    exit_code      0 every point ran, 1 some failed (their `error` cell says why)
    path           the output folder (None when it was a temporary one)
    """

    def __init__(self, folder: str, exit_code: int, keep: bool) -> None:
        import numpy as np
        with open(os.path.join(folder, "points.csv"), newline="", encoding="utf-8") as f:
            rows = list(csv.reader(f))
        header, body = rows[0], rows[1:]
        self.exact: Dict[str, Any] = {}
        self.columns: Dict[str, Any] = {}
        for k, name in enumerate(header):
            cells = [r[k] for r in body]
            self.exact[name] = np.array(cells, dtype=object)
            self.columns[name] = _column(name, cells, self.exact[name])
        with open(os.path.join(folder, "manifest.json"), encoding="utf-8") as f:
            self.manifest: Dict[str, Any] = json.load(f)
        self.exit_code = exit_code
        self.path: Optional[str] = folder if keep else None

    def __len__(self) -> int:
        return len(self.exact.get("index", ()))

    @property
    def failed(self) -> int:
        """The points whose command failed (a non-empty `error` cell)."""
        return int(sum(1 for e in self.exact.get("error", ()) if e))

    def as_dict(self) -> Dict[str, Any]:
        """{column: numpy array} (the `columns`)."""
        return dict(self.columns)

    def frame(self):
        """The table as a pandas DataFrame (numeric columns as float64); needs pandas."""
        try:
            import pandas
        except ImportError as e:
            raise ImportError("Sweep.frame() needs pandas; .columns has the same data as numpy arrays") from e
        return pandas.DataFrame(self.columns)

    def __repr__(self) -> str:
        return f"hapstab.Sweep(points={len(self)}, failed={self.failed}, columns={list(self.columns)})"


def sweep(spec: Any, out: Optional[str] = None, *, jobs: Optional[int] = None, shard: Optional[str] = None,
          resume: bool = False) -> Sweep:
    """Runs `hapstab sweep SPEC --out DIR` (docs/sweep.md) and reads its points.csv.

    spec: a path, TOML text, or a dict {command, args, axes}. out: the folder to keep
    (points.csv, manifest.json); a temporary one, removed after reading, when None. jobs,
    shard ("I/N") and resume as on the command line. A bad spec raises hapstab.InputError
    naming the key; failed points are rows with an `error` (exit_code 1), not exceptions.
    """
    with tempfile.TemporaryDirectory(prefix="hapstab-sweep-") as tmp:
        if isinstance(spec, Mapping):
            text = spec_toml(spec)
        elif isinstance(spec, str) and "\n" in spec:
            text = spec
        elif isinstance(spec, (str, os.PathLike)):
            text = None
        else:
            raise TypeError(f"spec: expected a path, TOML text or a dict, got {type(spec).__name__}")
        path = os.fspath(spec) if text is None else os.path.join(tmp, "spec.toml")
        if text is not None:
            with open(path, "w", encoding="utf-8") as f:
                f.write(text)
        folder = os.fspath(out) if out is not None else os.path.join(tmp, "out")
        args = ["sweep", path, f"--out={folder}", "--quiet"]
        if jobs is not None:
            args.append(f"--jobs={int(jobs)}")
        if shard is not None:
            args.append(f"--shard={shard}")
        if resume:
            args.append("--resume")
        code, _ = _core.run(args)
        if code not in (0, 1):
            raise RuntimeError(f"hapstab sweep ended with exit code {code} (a worker died; "
                               "run again with out= and resume=True to keep the finished points)")
        return Sweep(folder, code, keep=out is not None)
