"""hapstab._exact -- Python values -> the exact text the library parses (numeric/decimal.hpp).

Numbers are exact: int, fractions.Fraction, decimal.Decimal and numpy integers as they are, a
str as the exact decimal or fraction it spells ("0.001", "1e-3", "1/1000"), and a float (or
numpy float, or a 0-d array) as the SHORTEST decimal that rounds to it -- its repr: 1e-3 is
1/1000, 0.1 is 1/10, as written in the source. Its exact binary value is fractions.Fraction(x)
(0.1 -> 3602879701896397/36028797018963968). A transfer function H(z) is an expression string, a
(num, den) pair of coefficient sequences in descending powers of z (python-control's, SciPy's and
MATLAB's convention), or a system object read by its attributes: num, den, dt (python-control's
TransferFunction, scipy.signal's TransferFunction/lti/dlti; zeros-poles-gain through its to_tf()),
and A, B, C, D, dt for a state space (python-control's StateSpace, scipy.signal's StateSpace).
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


def _float_text(x: Any) -> str:
    """The shortest decimal that rounds to the float x (repr; numpy's own for a numpy float, so a
    float32 0.1 is 0.1 too)."""
    text = str(x) if type(x).__module__ == "numpy" else repr(float(x))
    return text if _NUMBER.fullmatch(text) else repr(float(x))


def exact(x: Any, what: str) -> str:
    """The exact text of the number x; InputError (a ValueError) naming `what` otherwise."""
    if getattr(x, "ndim", None) == 0 and hasattr(x, "item") and not isinstance(x, numbers.Number):
        x = x[()]  # a 0-d array: its element (a numpy scalar, which keeps its own precision)
    if isinstance(x, bool) or type(x).__name__ == "bool_":
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
        return _float_text(x)  # the shortest decimal that rounds to it (Fraction(x): the binary value)
    if getattr(x, "ndim", 0) >= 1 or isinstance(x, (list, tuple)):
        raise _core.InputError(f"{what}: expected one number, got an array ({type(x).__name__})")
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


def _is_seq(x: Any) -> bool:
    """A sequence of values (not a str, not a 0-d array)."""
    return not isinstance(x, (str, bytes)) and hasattr(x, "__len__") and getattr(x, "ndim", 1) != 0


def _squeeze(seq: Any) -> Any:
    """python-control keeps SISO coefficients as num[0][0]: unwrap single-element nesting."""
    while _is_seq(seq) and len(seq) == 1 and _is_seq(seq[0]):
        seq = seq[0]
    return seq


def _continuous(dt: Any) -> bool:
    """python-control: dt = 0 continuous, True discrete with no period, > 0 the period; SciPy:
    dt None continuous."""
    return dt is None or dt is False or (not isinstance(dt, bool) and dt == 0)


def system_period(obj: Any, T_text: Optional[str], what: str) -> Optional[str]:
    """The exact period of a discrete system object (its dt, checked against T when both are given)."""
    dt = getattr(obj, "dt", None)
    if _continuous(dt):
        raise _core.InputError(f"{what}: a continuous-time system (dt = {dt!r}); hapstab needs it discrete, in z "
                               f"(discretise it first, or give its expression)")
    if isinstance(dt, bool):  # dt = True: 'discrete, period unspecified' (python-control)
        if T_text is None:
            raise _core.InputError(f"{what}.dt = True leaves the sample period open: pass T")
        return T_text
    dt_text = exact(dt, f"{what}.dt")
    if T_text is not None and to_fraction(T_text) != to_fraction(dt_text):
        raise _core.InputError(f"{what}.dt = {dt!r} ({dt_text}) does not match T = {T_text}")
    return T_text if T_text is not None else dt_text


def is_system(H: Any) -> bool:
    """An object read by its attributes: num/den (or to_tf), or A/B/C/D."""
    return not isinstance(H, (str, tuple, list)) and (
        (hasattr(H, "num") and hasattr(H, "den")) or hasattr(H, "to_tf") or is_state_space(H))


def is_state_space(H: Any) -> bool:
    return not isinstance(H, (str, tuple, list)) and all(hasattr(H, k) for k in ("A", "B", "C", "D"))


def _numden(H: Any, what: str) -> Tuple[Any, Any]:
    if not (hasattr(H, "num") and hasattr(H, "den")) and hasattr(H, "to_tf"):
        H = H.to_tf()  # scipy.signal's ZerosPolesGain (its to_tf: a TransferFunction)
    if not (hasattr(H, "num") and hasattr(H, "den")):
        raise _core.InputError(f"{what}: a state-space system here needs a transfer function (num, den); "
                               f"pass its transfer function")
    return H.num, H.den


def _coefficients(H: Any, T_text: Optional[str], what: str) -> Tuple[Any, Any, Optional[str]]:
    """(num, den, T) of H given as a (num, den) pair or an object with num, den, dt."""
    if is_system(H):
        T_text = system_period(H, T_text, what)
        num, den = _numden(H, what)
        return num, den, T_text
    if isinstance(H, (tuple, list)) and len(H) == 2:
        return H[0], H[1], T_text
    raise TypeError(f"{what}: expected an expression str, a (num, den) pair, a hapstab.TransferFunction or an object "
                    f"with num, den, dt; got {type(H).__name__}")


def continuous_text(P: Any, what: str) -> str:
    """A continuous-time system object (num, den in descending powers of s; dt 0 or None) as an
    exact expression in s (the plant of `stability`)."""
    dt = getattr(P, "dt", None)
    if not _continuous(dt):
        raise _core.InputError(f"{what}: a discrete-time system (dt = {dt!r}); {what} is continuous, P(s)")
    num, den = _numden(P, what)

    def poly(cs: Any, part: str) -> str:
        texts = coefficient_texts(cs, f"{what} {part}")
        n = len(texts) - 1
        return " + ".join(f"({c})*s^{n - k}" for k, c in enumerate(texts))

    return f"({poly(num, 'numerator')})/({poly(den, 'denominator')})"


def coefficient_texts(coefficients: Any, what: str) -> list:
    """The exact texts of c0, c1, ... (descending powers of z)."""
    seq = _squeeze(coefficients)
    if not _is_seq(seq):
        seq = [seq]
    cs = list(seq)
    if not cs:
        raise _core.InputError(f"{what}: an empty coefficient list")
    out = []
    for k, c in enumerate(cs):
        if _is_seq(c):
            raise _core.InputError(f"{what}: coefficient {k} is a sequence; hapstab takes SISO transfer functions")
        out.append(exact(c, f"{what}[{k}]"))
    return out


def transfer_function(H: Any, T: Any, params: Optional[dict] = None, what: str = "H", variable: str = "z",
                      hidden_poles: str = "refuse"):
    """H as a hapstab.TransferFunction (the library's lti TransferFunction): from an expression
    (parsed once, with `params` exact), a (num, den) pair, an object with num, den, dt, or a
    TransferFunction already built (its T must match). A pole the expression (or num/den) writes and
    cancels on or outside the stable region is refused, or with hidden_poles="allow_marginal" (b*, as
    `bound` reads H) while H as written stays marginally stable (lti/parse.hpp HiddenPoles)."""
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
        return _core.tf_from_expression(H, T_text, texts, variable, what, hidden_poles)
    num, den, T_text = _coefficients(H, T_text, what)
    if params:
        raise _core.InputError(f"params: {what} is given by its coefficients (numbers); params name parameters of an "
                               "expression")
    if T_text is None:
        raise _core.InputError("T is required (the sample period)")
    return _core.tf_from_coefficients(coefficient_texts(num, f"{what} numerator"),
                                      coefficient_texts(den, f"{what} denominator"), T_text, what, hidden_poles)


def period_of(H: Any, T: Any) -> Optional[str]:
    """The exact sample period of a call: T, or H's own (a TransferFunction's T, a system's dt)."""
    if T is not None:
        return exact(T, "T")
    if isinstance(H, _core.TransferFunction):
        return H.T
    if is_system(H):
        return system_period(H, None, "H")
    return None


def state_space(A: Any, B: Any, C: Any, D: Any, T: Any):
    """A hapstab.StateSpace (exact entries: ints, Fractions, exact strings, floats as their shortest decimal)."""
    def matrix(M: Any, name: str) -> list:
        if hasattr(M, "__array__") and not isinstance(M, str):  # numpy, pandas, numpy.matrix
            import numpy as np
            M = np.asarray(M)
            M = [[M[i, j] for j in range(M.shape[1])] for i in range(M.shape[0])] if M.ndim == 2 else list(M)
        rows = [M] if not hasattr(M, "__len__") or isinstance(M, str) else list(M)
        out = []
        for i, row in enumerate(rows):
            row = [row] if not hasattr(row, "__len__") or isinstance(row, str) else list(row)
            out.append([exact(x, f"ss {name}[{i}][{j}]") for j, x in enumerate(row)])
        return out

    return _core.StateSpace(matrix(A, "A"), matrix(B, "B"), matrix(C, "C"), matrix(D, "D"), exact(T, "T"))
