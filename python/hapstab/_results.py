"""hapstab._results -- the objects hapstab's functions return.

A Result holds the JSON a command printed: its keys are attributes (result.status), as_dict()
gives a copy of it all, repr shows the main value and its status, and float() works where the
command has one number. exit_code is the command's: 0, or 1 when the property does not hold
(a loop that is not stable is an answer, not an error).
"""
from __future__ import annotations

import copy
from fractions import Fraction
from typing import Any, Dict, Optional, Tuple


class Result:
    """The JSON of one hapstab command, as attributes."""

    _value_key: Optional[str] = None  # the key float() and repr show
    _status_key: str = "status"

    def __init__(self, data: Dict[str, Any], exit_code: int = 0) -> None:
        object.__setattr__(self, "_data", data)
        object.__setattr__(self, "exit_code", exit_code)

    def __getattr__(self, name: str) -> Any:
        try:
            return self._data[name]
        except KeyError:
            raise AttributeError(f"{type(self).__name__} has no attribute '{name}' "
                                 f"(keys: {', '.join(sorted(self._data))})") from None

    def __setattr__(self, name: str, value: Any) -> None:
        raise AttributeError(f"{type(self).__name__} is read-only")

    def __dir__(self):
        return sorted(set(super().__dir__()) | set(self._data))

    def as_dict(self) -> Dict[str, Any]:
        """A deep copy of the command's JSON."""
        return copy.deepcopy(self._data)

    @property
    def value(self) -> Any:
        return self._data.get(self._value_key) if self._value_key else None

    def __float__(self) -> float:
        v = self.value
        if v is None or isinstance(v, bool) or not isinstance(v, (int, float, str)):
            raise TypeError(f"{type(self).__name__} has no single number to convert to float")
        return float(v)  # "inf" -> inf; decimal strings are correctly rounded by float()

    def __repr__(self) -> str:
        return f"hapstab.{type(self).__name__}(value={self.value!r}, status={self._data.get(self._status_key)!r})"


class R(Result):
    """r(jw) of paper 001 (`hapstab r`): re, im as decimal strings, the truncated series beside."""

    @property
    def value(self) -> Tuple[str, str]:
        return (self._data["re"], self._data["im"])

    def __complex__(self) -> complex:
        return complex(float(self._data["re"]), float(self._data["im"]))

    def __float__(self) -> float:
        raise TypeError("r(jw) is complex: use complex(result)")

    def __repr__(self) -> str:
        return f"hapstab.R(re={self._data['re']!r}, im={self._data['im']!r}, status='re exact, im certified')"


class Bound(Result):
    """The passivity bound b* of paper 001 (`hapstab bound`): passive iff b > b*."""

    _value_key = "bound"

    @property
    def value(self) -> str:
        """b* as a decimal string ("inf" when no finite b makes the loop passive)."""
        return self._data["bound"]

    @property
    def fraction(self) -> Optional[Fraction]:
        """b* as a Fraction when it is exact (status 'exact'), else None."""
        e = self._data.get("exact")
        return Fraction(e) if e is not None else None

    @property
    def enclosure(self) -> Tuple[str, str]:
        lo, hi = self._data["enclosure"]
        return (lo, hi)

    def __repr__(self) -> str:
        extra = f", exact={self._data['exact']!r}" if self._data.get("exact") else ""
        return (f"hapstab.Bound(value={self.value!r}, status={self._data['status']!r}{extra}, "
                f"omega={self._data.get('omega')!r})")


class Stability(Result):
    """Schur stability of the sampled haptic loop (`hapstab stability`); with max=NAME the largest
    stable gain: value is `max` (a decimal string, "inf", or "0" when unstable for every small gain)."""

    @property
    def value(self) -> Any:
        return self._data["max"] if "max" in self._data else self._data.get("stable")

    def __bool__(self) -> bool:
        if "max" in self._data:
            return self._data["max"] not in (None, "0")
        return bool(self._data.get("stable"))


class Wedge(Result):
    """The wedge criterion (25) and Tsypkin's condition (21) of paper 002 (`hapstab wedge`)."""

    _value_key = "verdict"

    def __float__(self) -> float:
        raise TypeError("wedge has two margins: float(result.wedge_margin) or float(result.tsypkin_margin)")

    def __bool__(self) -> bool:
        return bool(self._data.get("wedge_holds"))


class PassivityLevel(Result):
    """The OSP/ISP level of paper 000 (`hapstab passivity-level`)."""

    _value_key = "level"


class Analysis(Result):
    """Theorem 5 of paper 000 (`hapstab multidof analyze`)."""

    _value_key = "verdict"

    def __bool__(self) -> bool:
        # as the exit code: Theorem 5 concludes and the loop as written is not proven unstable
        law = self._data.get("loop_as_written") or {}
        return bool(self._data["stability_concluded"]) and law.get("stable") is not False

    def __repr__(self) -> str:
        return (f"hapstab.Analysis(verdict={self._data['verdict']!r}, certified={self._data['certified']!r}, "
                f"stability_concluded={self._data['stability_concluded']!r})")


class Design(Result):
    """Theorem 6 of paper 000 (`hapstab multidof design`): the coupling V = (A_V, B_V, C_V, D_V)."""

    _value_key = "feasible"

    @property
    def V(self):
        """(A_V, B_V, C_V, D_V) as numpy float64 arrays (empty when no V was found)."""
        import numpy as np
        return tuple(np.array(self._data[k], dtype=np.float64) for k in ("A_V", "B_V", "C_V", "D_V"))

    def __bool__(self) -> bool:
        return bool(self._data["feasible"])

    def __repr__(self) -> str:
        return (f"hapstab.Design(feasible={self._data['feasible']!r}, certified={self._data['certified']!r}, "
                f"iterations={self._data['iterations']!r})")


class Simulation(Result):
    """A scene simulated (`hapstab simulate`): the summary's keys as attributes, and the series.

    samples: dict of numpy float64 arrays, 't' of shape (rows,) in s, and per quantity
      'x' [m], 'v' [m/s], 'u' [N], 'fh' [N], 'E_port', 'E_act', 'E_po', 'storage' [J] of shape
      (rows, dofs): column j is DOF j (the CSV's x_j [m] ...).
    fine: the same for the exact intersample grid ('t', 'x', 'v'), or None.
    units: quantity -> unit. out: the folder with the files when simulate(out=...) kept them.
    """

    _value_key = "diverged"

    def __init__(self, data, exit_code, samples, fine, units, out) -> None:
        super().__init__(data, exit_code)
        object.__setattr__(self, "samples", samples)
        object.__setattr__(self, "fine", fine)
        object.__setattr__(self, "units", units)
        object.__setattr__(self, "out", out)

    @property
    def summary(self) -> Dict[str, Any]:
        return self.as_dict()

    def __repr__(self) -> str:
        rows, dofs = self.samples["x"].shape if "x" in self.samples else (0, 0)
        return (f"hapstab.Simulation(diverged={self._data['diverged']!r}, max_velocity={self._data['max_velocity']!r}, "
                f"samples={rows}x{dofs}, status={self._data['status']!r})")

