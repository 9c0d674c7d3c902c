"""hapstab._exact -- Python values -> the exact text hapstab's command line reads.

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


def _squeeze(seq: Any) -> Any:
    """python-control keeps SISO coefficients as num[0][0]: unwrap single-element nesting."""
    while (not isinstance(seq, (str, bytes)) and hasattr(seq, "__len__") and len(seq) == 1
           and hasattr(seq[0], "__len__") and not isinstance(seq[0], (str, bytes))):
        seq = seq[0]
    return seq


def polynomial(coefficients: Any, what: str) -> str:
    """c0 z^n + c1 z^(n-1) + ... + cn as an exact expression (descending powers of z)."""
    seq = _squeeze(coefficients)
    if isinstance(seq, (str, bytes)) or not hasattr(seq, "__iter__"):
        seq = [seq]
    cs = list(seq)
    if not cs:
        raise _core.InputError(f"{what}: an empty coefficient list")
    terms = []
    n = len(cs) - 1
    for k, c in enumerate(cs):
        if hasattr(c, "__len__") and not isinstance(c, str):
            raise _core.InputError(f"{what}: coefficient {k} is a sequence; hapstab takes SISO transfer functions")
        text = exact(c, f"{what}[{k}]")
        power = n - k
        terms.append(f"({text})" + ("" if power == 0 else "*z" if power == 1 else f"*z^{power}"))
    return "(" + " + ".join(terms) + ")"


def transfer_function(H: Any, T: Any, what: str = "H") -> Tuple[str, Optional[str]]:
    """(expression, exact T or None) for H given as a str, a (num, den) pair or a num/den/dt object."""
    T_text = None if T is None else exact(T, "T")
    if isinstance(H, str):
        return H, T_text
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
        num, den = H.num, H.den
    elif isinstance(H, (tuple, list)) and len(H) == 2:
        num, den = H
    else:
        raise TypeError(f"{what}: expected an expression str, a (num, den) pair or an object with num, den, dt; "
                        f"got {type(H).__name__}")
    return f"{polynomial(num, what + ' numerator')}/{polynomial(den, what + ' denominator')}", T_text


def state_space_json(A: Any, B: Any, C: Any, D: Any, T: Any) -> dict:
    """The JSON of `passivity-level --ss` (lti/state_space_json.hpp) for matrices A, B, C, D."""
    def entry(x: Any, where: str) -> Any:
        if isinstance(x, numbers.Integral) and not isinstance(x, bool):
            return int(x)
        return exact(x, where)

    def matrix(M: Any, name: str) -> list:
        rows = [M] if not hasattr(M, "__len__") else list(M)
        out = []
        for i, row in enumerate(rows):
            row = [row] if not hasattr(row, "__len__") or isinstance(row, str) else list(row)
            out.append([entry(x, f"ss {name}[{i}][{j}]") for j, x in enumerate(row)])
        return out

    return {"A": matrix(A, "A"), "B": matrix(B, "B"), "C": matrix(C, "C"), "D": matrix(D, "D"),
            "T": exact(T, "T")}
