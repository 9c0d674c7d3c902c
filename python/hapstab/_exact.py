"""hapstab._exact -- Python values -> the exact text the library parses (numeric/decimal.hpp).

Numbers are exact: int, fractions.Fraction, decimal.Decimal and numpy integers as they are, a
float (or numpy float) at its EXACT binary value (0.1 -> 3602879701896397/36028797018963968),
a str as the exact decimal or fraction it spells ("0.001", "1e-3", "1/1000"). A transfer
function H(z) is an expression string, a (num, den) pair of coefficient sequences in descending
powers of z (python-control's and MATLAB's convention), or an object with num, den and dt (a
python-control TransferFunction, duck-typed).
"""
from __future__ import annotations

import decimal
import math
import numbers
import re
from fractions import Fraction
from typing import Any, Optional, Sequence, Tuple

from . import _core

# an exact decimal, or a fraction of two (what hapstab's parse_rational reads)
_DECIMAL = r"(?:\d+(?:\.\d*)?|\.\d+)(?:[eE][+-]?\d+)?"
_NUMBER = re.compile(r"\s*[+-]?" + _DECIMAL + r"(?:/" + _DECIMAL + r")?\s*")


def to_fraction(text: str) -> Fraction:
    """The value of a number that `exact` returned ("1e-3/7" too)."""
    num, _, den = text.strip().partition("/")
    return Fraction(num) / Fraction(den) if den else Fraction(num)


def fraction_text(q: Fraction) -> str:
    return str(q.numerator) if q.denominator == 1 else f"{q.numerator}/{q.denominator}"


def exact(x: Any, what: str) -> str:
    """The exact text of the number x; InputError (a ValueError) naming `what` otherwise."""
    if isinstance(x, bool):
        raise _core.InputError(f"{what}: expected a number, got the bool {x}")
    if isinstance(x, str):
        if not _NUMBER.fullmatch(x):
            raise _core.InputError(f"{what}: '{x}' is not an exact number (e.g. 0.001, 1e-3, 1/1000)")
        return x.strip()
    if isinstance(x, numbers.Integral):
        return str(int(x))
    if isinstance(x, numbers.Rational):
        return fraction_text(Fraction(x.numerator, x.denominator))
    if isinstance(x, decimal.Decimal):
        if not x.is_finite():
            raise _core.InputError(f"{what}: {x} is not a finite number")
        return fraction_text(Fraction(x))
    if isinstance(x, numbers.Real):
        f = float(x)
        if not math.isfinite(f):
            raise _core.InputError(f"{what}: {f} is not a finite number")
        return fraction_text(Fraction(f))  # the float's exact binary value
    raise TypeError(f"{what}: expected int, Fraction, float or str, got {type(x).__name__}")


def integer(x: Any, what: str, lo: Optional[int] = None, hi: Optional[int] = None, hint: str = "") -> int:
    """x as an int when it is one (int, numpy integer); InputError naming `what` for a bool, a
    float (even 2.0: nothing is truncated or rounded), a Fraction or a str, and outside [lo, hi]."""
    if isinstance(x, bool) or not isinstance(x, numbers.Integral):
        kind = "the bool" if isinstance(x, bool) else f"the {type(x).__name__}"
        raise _core.InputError(f"{what}: expected an integer, got {kind} {x!r}" + (f"; {hint}" if hint else ""))
    v = int(x)
    if (lo is not None and v < lo) or (hi is not None and v > hi):
        span = f"[{lo}, {hi}]" if hi is not None else f">= {lo}"
        raise _core.InputError(f"{what}: {v} is outside {span}" + (f"; {hint}" if hint else ""))
    return v


def real(x: Any, what: str, positive: bool = True) -> float:
    """x as a finite float (> 0 when `positive`); InputError naming `what` for a bool, a str, NaN,
    an infinity or a value <= 0."""
    if isinstance(x, bool) or not isinstance(x, numbers.Real):
        kind = "the bool" if isinstance(x, bool) else f"the {type(x).__name__}"
        raise _core.InputError(f"{what}: expected a number, got {kind} {x!r}")
    f = float(x)
    if not math.isfinite(f) or (positive and f <= 0):
        raise _core.InputError(f"{what}: {f} is not a finite number" + (" > 0" if positive else ""))
    return f


def _squeeze(seq: Any) -> Any:
    """python-control keeps SISO coefficients as num[0][0]: unwrap single-element nesting."""
    while (not isinstance(seq, (str, bytes)) and hasattr(seq, "__len__") and len(seq) == 1
           and hasattr(seq[0], "__len__") and not isinstance(seq[0], (str, bytes))):
        seq = seq[0]
    return seq


def _coefficients(H: Any, T_text: Optional[str], what: str) -> Tuple[Any, Any, Optional[str]]:
    """(num, den, T) of H given as a (num, den) pair or an object with num, den, dt."""
    if hasattr(H, "num") and hasattr(H, "den"):
        dt = getattr(H, "dt", None)
        if dt is None or dt is False or (not isinstance(dt, bool) and dt == 0):
            raise _core.InputError(f"{what}: a continuous-time system (dt = {dt!r}); hapstab needs H(z), discrete")
        if not isinstance(dt, bool):  # dt = True: 'discrete, period unspecified' (python-control)
            if T_text is None:
                T_text = exact(dt, f"{what}.dt")
            elif float(dt) != float(to_fraction(T_text)):
                raise _core.InputError(f"{what}.dt = {dt!r} does not match T = {T_text}")
        elif T_text is None:
            raise _core.InputError(f"{what}.dt = True leaves the sample period open: pass T")
        return H.num, H.den, T_text
    if isinstance(H, (tuple, list)) and len(H) == 2:
        return H[0], H[1], T_text
    raise TypeError(f"{what}: expected an expression str, a (num, den) pair, a hapstab.TransferFunction or an object "
                    f"with num, den, dt; got {type(H).__name__}")


def coefficient_texts(coefficients: Any, what: str) -> list:
    """The exact texts of c0, c1, ... (descending powers of z)."""
    seq = _squeeze(coefficients)
    if isinstance(seq, (str, bytes)) or not hasattr(seq, "__iter__"):
        seq = [seq]
    cs = list(seq)
    if not cs:
        raise _core.InputError(f"{what}: an empty coefficient list")
    out = []
    for k, c in enumerate(cs):
        if hasattr(c, "__len__") and not isinstance(c, str):
            raise _core.InputError(f"{what}: coefficient {k} is a sequence; hapstab takes SISO transfer functions")
        out.append(exact(c, f"{what}[{k}]"))
    return out


def transfer_function(H: Any, T: Any, params: Optional[dict] = None, what: str = "H", variable: str = "z"):
    """H as a hapstab.TransferFunction (the library's lti TransferFunction): from an expression
    (parsed once, with `params` exact), a (num, den) pair, an object with num, den, dt, or a
    TransferFunction already built (its T must match)."""
    T_text = None if T is None else exact(T, "T")
    if isinstance(H, _core.TransferFunction):
        if params:
            raise _core.InputError(f"params: {what} is a TransferFunction already (its parameters have values); "
                                   "pass the expression to vary them")
        if T_text is not None and H.T is not None and to_fraction(H.T) != to_fraction(T_text):
            raise _core.InputError(f"{what} was built with T = {H.T}, not T = {T_text}")
        return H
    if isinstance(H, str):
        texts = {str(k): exact(v, f"params[{k!r}]") for k, v in (params or {}).items()}
        return _core.tf_from_expression(H, T_text, texts, variable, what)
    num, den, T_text = _coefficients(H, T_text, what)
    if params:
        raise _core.InputError(f"params: {what} is given by its coefficients (numbers); params name parameters of an "
                               "expression")
    if T_text is None:
        raise _core.InputError("T is required (the sample period)")
    return _core.tf_from_coefficients(coefficient_texts(num, f"{what} numerator"),
                                      coefficient_texts(den, f"{what} denominator"), T_text, what)


def period_of(H: Any, T: Any) -> Optional[str]:
    """The exact sample period of a call: T, or H's own (a TransferFunction's T, a system's dt)."""
    if T is not None:
        return exact(T, "T")
    if isinstance(H, _core.TransferFunction):
        return H.T
    if not isinstance(H, str) and (hasattr(H, "num") and hasattr(H, "dt")):
        return _coefficients(H, None, "H")[2]
    return None


def state_space(A: Any, B: Any, C: Any, D: Any, T: Any):
    """A hapstab.StateSpace (exact entries: ints, Fractions, exact strings, floats at their binary value)."""
    def matrix(M: Any, name: str) -> list:
        if hasattr(M, "tolist"):
            M = M.tolist()
        rows = [M] if not hasattr(M, "__len__") or isinstance(M, str) else list(M)
        out = []
        for i, row in enumerate(rows):
            row = [row] if not hasattr(row, "__len__") or isinstance(row, str) else list(row)
            out.append([exact(x, f"ss {name}[{i}][{j}]") for j, x in enumerate(row)])
        return out

    return _core.StateSpace(matrix(A, "A"), matrix(B, "B"), matrix(C, "C"), matrix(D, "D"), exact(T, "T"))
