"""hapstab._results -- the one result protocol of every hapstab function.

A scalar result is a Result (a number with its enclosure):

    value      fractions.Fraction when the status is exact, else a float midpoint
    lo, hi     the enclosure rounded OUTWARD to floats (lo <= true value <= hi when the status
               is exact or certified; for numeric, the stated error band, not a proof)
    lo_exact, hi_exact   the same ends as exact decimal strings, rounded outward (None where
               the method states no end)
    status     'exact' | 'certified' | 'numeric' | 'upper_bound' | 'undecided' | 'failed'
               ('undecided': the quantity is not proven, value NaN; what is proven is beside it)
    method     how it was computed;  note  caveats
    float(r)   float(value);  r < x, r <= x, r == x, ...  decided by the enclosure, exactly
               (x an int, Fraction, float, exact str, or another Result): a comparison the
               enclosure cannot decide raises UndecidedComparison, saying so. A result that is
               not proven (status numeric, undecided, failed) decides no comparison: it raises
               UndecidedComparison saying so; compare its estimate explicitly (r.value < x)
    f"{r:.3f}", round(r, 3), np.asarray(r), np.isclose(r, x)   the value as a number (a float
               for a format spec and for numpy; round() keeps a Fraction exact); numpy's
               comparison ufuncs (np.less(x, r), np.float64(x) < r) are the honest comparisons
    _repr_html_ / _repr_latex_   for notebooks

A vectorised call (an array in params, or an omega array) returns a ResultArray: value, lo, hi
as float64 arrays of the broadcast shape, status as strings (the names of STATUS, as a scalar
result's), exact (the exact values as strings, None where not exact), lo_exact/hi_exact (the ends
as outward decimals: they decide a comparison the float ends straddle), error (why a point
failed, None where it ran); r[i] (every index given) is point i as a Result, r[1:] / r[mask] /
r[0] of a 2-D array a ResultArray, `for x in r` iterates over the first axis; comparisons
(<, <=, >, >=, ==, !=) are elementwise and decided by the enclosures (raising when an element is
undecided or not proven); np.asarray(r) and to_numpy() are the value array, to_table() the
structured array (parameters, value, lo, hi, status, ...) and to_pandas() a DataFrame of it.
"""
from __future__ import annotations

import html
import math
from fractions import Fraction
from typing import Any, Dict, Optional, Tuple

STATUS = ("exact", "certified", "numeric", "failed")  # a ResultArray's status names (one per point)
_DECIDES = ("exact", "certified", "upper_bound")  # the statuses whose lo/hi are proven: comparisons decide


class UndecidedComparison(ValueError):
    """A comparison whose answer the enclosure of a result does not decide (the number compared
    with lies inside it), or a comparison with a result that is not proven (status numeric,
    undecided or failed: its lo/hi are an estimate or absent). Ask for more digits or a
    certified method, or compare the numbers yourself (r.value < x, r.lo > x)."""


_COMPARISON_UFUNCS = {"less": ("<", ">"), "less_equal": ("<=", ">="), "greater": (">", "<"),
                      "greater_equal": (">=", "<="), "equal": ("==", "=="), "not_equal": ("!=", "!=")}


def _not_proven(name: str, status: str, method: str, note: str, op: str) -> UndecidedComparison:
    """The error of a comparison with a result that is not proven."""
    why = {"numeric": "its lo/hi are an estimated error band, not a proven enclosure",
           "undecided": "it is not proven (what is proven is in its other fields)",
           "failed": "it failed" + (f" ({note})" if note else "")}.get(status, f"its status is {status}")
    return UndecidedComparison(
        f"cannot decide {name} {op} x: the result is {status} ({method}): {why}. hapstab decides comparisons only "
        f"on proven enclosures (status exact or certified): ask for one (method='certified', the default where the "
        f"function has it), or compare the estimate explicitly: r.value {op} x")


def _exact_of(x: Any) -> Any:
    """x as an exact Fraction (or +-inf) for comparisons."""
    from ._exact import exact, to_fraction
    if isinstance(x, Result):
        raise TypeError("internal: Result handled by the caller")
    if isinstance(x, float) and math.isinf(x):
        return x
    if isinstance(x, str) and x.strip() in ("inf", "+inf", "-inf"):
        return float(x)
    return to_fraction(exact(x, "the number compared with"))


def _end(text: Optional[str], f: float) -> Any:
    """An end of an enclosure, exactly: its outward decimal when there is one, else the float (exact)."""
    if text is not None:
        if text in ("inf", "-inf"):
            return float(text)
        from ._exact import to_fraction
        return to_fraction(text)
    if math.isinf(f) or math.isnan(f):
        return f
    return Fraction(f)


def _fmt(x: float) -> str:
    return f"{x:.17g}" if math.isfinite(x) else str(x)


class Result:
    """A number with its enclosure, status and method (module docstring)."""

    _symbol = "x"  # its name in LaTeX
    _name = "value"

    def __init__(self, record: Dict[str, Any], **extra: Any) -> None:
        object.__setattr__(self, "_rec", dict(record))
        object.__setattr__(self, "_extra", extra)

    # ---- the protocol ------------------------------------------------------------------------
    @property
    def value(self) -> Any:
        """Fraction when exact, else the float midpoint of the enclosure."""
        v = self._rec.get("value_exact")
        if v is not None and self._rec["status"] == "exact":
            from ._exact import to_fraction
            return to_fraction(v)
        return float(self._rec["mid"])

    @property
    def lo(self) -> float:
        return float(self._rec["lo"])

    @property
    def hi(self) -> float:
        return float(self._rec["hi"])

    @property
    def lo_exact(self) -> Optional[str]:
        return self._rec.get("lo_text")

    @property
    def hi_exact(self) -> Optional[str]:
        return self._rec.get("hi_text")

    @property
    def status(self) -> str:
        return self._rec["status"]

    @property
    def method(self) -> str:
        return self._rec["method"]

    @property
    def note(self) -> str:
        return self._rec.get("note", "")

    def __getattr__(self, name: str) -> Any:
        extra = object.__getattribute__(self, "_extra")
        if name in extra:
            return extra[name]
        raise AttributeError(f"{type(self).__name__} has no attribute '{name}' "
                             f"(it has: value, lo, hi, lo_exact, hi_exact, status, method, note, "
                             f"{', '.join(sorted(extra))})")

    def __setattr__(self, name: str, value: Any) -> None:
        raise AttributeError(f"{type(self).__name__} is read-only")

    def __dir__(self):
        return sorted(set(super().__dir__()) | set(self._extra))

    def as_dict(self) -> Dict[str, Any]:
        """value, lo, hi, lo_exact, hi_exact, status, method, note and the function's own fields."""
        d = {"value": self.value, "lo": self.lo, "hi": self.hi, "lo_exact": self.lo_exact, "hi_exact": self.hi_exact,
             "status": self.status, "method": self.method, "note": self.note}
        d.update(self._extra)
        return d

    def __float__(self) -> float:
        return float(self.value)

    # ---- honest comparisons --------------------------------------------------------------------
    def _bounds(self, op: str = "<") -> Tuple[Any, Any]:
        if self.status not in _DECIDES or math.isnan(self._rec["lo"]) or math.isnan(self._rec["hi"]):
            raise _not_proven(self._name, self.status, self.method, self.note, op)
        return _end(self.lo_exact, self._rec["lo"]), _end(self.hi_exact, self._rec["hi"])

    def _other(self, other: Any) -> Tuple[Any, Any]:
        if isinstance(other, Result):
            return other._bounds()
        x = _exact_of(other)
        return x, x

    def _undecided(self, op: str, other: Any) -> UndecidedComparison:
        return UndecidedComparison(
            f"cannot decide {self._name} {op} {other!r}: the {self.status} enclosure "
            f"[{self.lo_exact or _fmt(self.lo)}, {self.hi_exact or _fmt(self.hi)}] of {self._name} "
            f"does not lie on one side of it (ask for more digits, or compare .lo / .hi)")

    def __lt__(self, other: Any) -> bool:
        lo, hi = self._bounds("<")
        olo, ohi = self._other(other)
        if hi < olo:
            return True
        if lo >= ohi:
            return False
        raise self._undecided("<", other)

    def __le__(self, other: Any) -> bool:
        lo, hi = self._bounds("<=")
        olo, ohi = self._other(other)
        if hi <= olo:
            return True
        if lo > ohi:
            return False
        raise self._undecided("<=", other)

    def __gt__(self, other: Any) -> bool:
        lo, hi = self._bounds(">")
        olo, ohi = self._other(other)
        if lo > ohi:
            return True
        if hi <= olo:
            return False
        raise self._undecided(">", other)

    def __ge__(self, other: Any) -> bool:
        lo, hi = self._bounds(">=")
        olo, ohi = self._other(other)
        if lo >= ohi:
            return True
        if hi < olo:
            return False
        raise self._undecided(">=", other)

    def __eq__(self, other: Any) -> bool:  # type: ignore[override]
        lo, hi = self._bounds("==")
        olo, ohi = self._other(other)
        if hi < olo or lo > ohi:
            return False
        if lo == hi == olo == ohi:
            return True
        raise self._undecided("==", other)

    def __ne__(self, other: Any) -> bool:  # type: ignore[override]
        return not self.__eq__(other)

    __hash__ = None  # type: ignore[assignment]

    # ---- a number for Python and numpy ---------------------------------------------------------
    def __format__(self, spec: str) -> str:
        """f"{r}" is repr(r); f"{r:.3f}" formats float(r) (the value, a display)."""
        return str(self) if not spec else format(float(self), spec)

    def __round__(self, ndigits: Optional[int] = None) -> Any:
        """round(r, n): round(r.value, n) (a Fraction stays exact)."""
        return round(self.value) if ndigits is None else round(self.value, ndigits)

    def __array__(self, dtype: Any = None, copy: Any = None) -> Any:
        """np.asarray(r): a 0-d float64 array of float(r) (np.isclose(r, x), np.array([r1, r2]))."""
        import numpy as np
        return np.asarray(float(self), dtype=dtype)

    def __array_ufunc__(self, ufunc: Any, method: str, *inputs: Any, **kwargs: Any) -> Any:
        """numpy's comparison ufuncs (np.float64(6) > r, np.less(xs, r)) are the honest comparisons
        (elementwise over an array of numbers); any other ufunc sees float(r)."""
        import numpy as np
        ops = _COMPARISON_UFUNCS.get(ufunc.__name__)
        if ops is not None and method == "__call__" and len(inputs) == 2 and not kwargs:
            a, b = inputs
            mine, other, op = (a, b, ops[0]) if a is self else (b, a, ops[1])
            import operator
            fn = {"<": operator.lt, "<=": operator.le, ">": operator.gt, ">=": operator.ge, "==": operator.eq,
                  "!=": operator.ne}[op]
            if isinstance(other, (Result, ResultArray)) or np.ndim(other) == 0:
                if isinstance(other, ResultArray):
                    return NotImplemented
                return np.bool_(fn(mine, other if isinstance(other, Result) else np.asarray(other).item()))
            xs = np.asarray(other)
            return np.vectorize(lambda x: fn(mine, x), otypes=[bool])(xs)
        args = [float(x) if isinstance(x, Result) else x for x in inputs]
        return getattr(ufunc, method)(*args, **kwargs)

    # ---- display -------------------------------------------------------------------------------
    def _value_text(self) -> str:
        v = self.value
        if isinstance(v, Fraction):
            return str(v.numerator) if v.denominator == 1 else f"{v.numerator}/{v.denominator}"
        return _fmt(v)

    def __repr__(self) -> str:
        extra = "".join(f", {k}={v!r}" for k, v in self._repr_extra().items())
        return (f"hapstab.{type(self).__name__}(value={self.value!r}, lo={self.lo!r}, hi={self.hi!r}, "
                f"status={self.status!r}{extra})")

    def _repr_extra(self) -> Dict[str, Any]:
        return {}

    def _enclosure_text(self) -> str:
        return f"[{self.lo_exact or _fmt(self.lo)}, {self.hi_exact or _fmt(self.hi)}]"

    def _repr_html_(self) -> str:
        rows = [("value", self._value_text()), ("enclosure", self._enclosure_text()), ("status", self.status),
                ("method", self.method)]
        rows += [(k, str(v)) for k, v in self._repr_extra().items()]
        if self.note:
            rows.append(("note", self.note))
        body = "".join(f"<tr><th style='text-align:left'>{html.escape(k)}</th><td style='text-align:left'>"
                       f"{html.escape(v)}</td></tr>" for k, v in rows)
        return f"<table><caption>hapstab.{type(self).__name__}</caption>{body}</table>"

    def _repr_latex_(self) -> str:
        v = self.value
        if isinstance(v, Fraction) and v.denominator != 1:
            val = rf"\frac{{{v.numerator}}}{{{v.denominator}}}" if v >= 0 else rf"-\frac{{{-v.numerator}}}{{{v.denominator}}}"
        else:
            val = self._value_text().replace("inf", r"\infty")
        if self.status == "exact":
            return rf"${self._symbol} = {val}$ \quad (exact)"
        lo = (self.lo_exact or _fmt(self.lo)).replace("inf", r"\infty")
        hi = (self.hi_exact or _fmt(self.hi)).replace("inf", r"\infty")
        return rf"${self._symbol} \approx {val} \in [{lo},\ {hi}]$ \quad ({self.status})"


class Bound(Result):
    """The passivity bound b* of paper 001 (45)/(54): the loop is passive iff b > b*.
    Besides the protocol: omega (the maximiser, rad/s, a decimal str or None), where, decimal
    (b* to the digits asked, a str; 'inf'), infinite, closed_form ({name, equation, formula,
    value, tight} of the catalogue, or None), enclosure_rigorous, damping (with damping=b:
    {b, passive})."""

    _symbol = "b^*"
    _name = "b*"

    def _repr_extra(self) -> Dict[str, Any]:
        extra = {"omega": self._extra.get("omega")}
        if self._extra.get("closed_form"):
            extra["closed_form"] = self._extra["closed_form"]["name"]
        return extra


class PassivityLevel(Result):
    """The OSP (kind 'osp') or ISP ('isp') level of paper 000, Definition 2 / Lemmas 1-2: the
    certified frequency-domain level where it is the level (status exact or certified), else the
    LMI level (numeric; lo is its exactly checked lower bound). Besides the protocol: kind,
    theta, is_level, certified_value, lmi_level, lmi_lower_bound, lmi_method, grid_level."""

    _symbol = r"\nu"
    _name = "the level"

    def _repr_extra(self) -> Dict[str, Any]:
        return {"kind": self._extra.get("kind")}


class MaxGain(Result):
    """The largest stable gain of the sampled loop (stability(..., max='K')): sup{K : stable on
    (0, sup)}; 0 when unstable for every small K, inf when stable for every K. Besides the
    protocol: name, outcome, crossing ('z = 1', 'z = -1', 'complex pair'), theta and omega
    (enclosures of the crossing, rad and rad/s), bool(r): a positive supremum exists (raises
    UndecidedComparison when the supremum is not proven: status undecided or failed).

    With scene=...: also path, supremum_proven, stable_on (proven stable there, also when the
    supremum is undecided; open_at_zero: its lower end 0 excluded), change_in (not affine: stable at its lower end, NOT stable at its
    upper end), stable_at, unstable_at, gap, not_affine, verdicts_outcome, states, fixed_modes,
    theorem5, conservatism, conservatism_note, contradiction."""

    _symbol = r"K_{\max}"
    _name = "the largest stable gain"

    def __bool__(self) -> bool:
        if self.status in ("undecided", "failed"):  # never counted as a yes or a no
            raise UndecidedComparison(f"the largest stable gain is {self.status}: {self.note}")
        return self.outcome == "holds" and self.value != 0

    def _repr_extra(self) -> Dict[str, Any]:
        return {"crossing": self._extra.get("crossing")}


class Stability(Result):
    """Schur stability of the sampled loop: the value is the spectral radius of the closed loop
    (its certified enclosure), the verdict is stable (True/False, None when undecided) and
    bool(r) (raises when undecided). Besides the protocol: stable, evidence, verdict_status (the
    verdict's status: exact, certified or undecided), degree, device, precision_bits.

    With scene=...: the scene's loop as written, any number of DOF (stability::decide_loop). The
    value is then the closed-loop matrix's spectral radius in double (status 'numeric'); the
    verdict (stable, verdict_status) is decided by a certificate. Besides: decider (the method
    that decided), dofs, states (order of the closed loop), hidden_modes ([{block, kind,
    discrete, pair, where, re, im, abs, stable}]: every mode a block hides, as written; one
    outside the stability region makes the loop NOT stable whatever the rest does),
    hidden_summary, scene."""

    _symbol = r"\rho"
    _name = "the spectral radius"

    def __bool__(self) -> bool:
        stable = self.stable  # True/False/None, or a ResultArray point's code 1/0/-1
        if stable is None or (not isinstance(stable, bool) and int(stable) < 0):
            raise UndecidedComparison(f"stability undecided: {self._extra.get('evidence') or self.note}")
        return bool(stable)

    def _repr_extra(self) -> Dict[str, Any]:
        return {"stable": self._extra.get("stable")}


class MaxPassiveGain(Result):
    """The passivity boundary as a number (bound(H, max='K', damping=b)): sup{K0 : b > b*(K) for
    0 <= K < K0}, with b*(K_max) = b, or with jump: b*(K_max) <= b (b_at_sup) and b* = +inf above
    (H's pole at z = -1 under a fractional delay); 0 (exact) when not passive at K = 0, inf when passive for
    every K >= 0. Certified (exact where K_max is rational). Besides the protocol: name, outcome
    ('holds' when K_max > 0), infinite, decimal (the digits both ends share), digits_certified,
    damping (exact str), b_at_zero (b*(0), a Bound), omega ((lo, hi) rad/s where b* = b at K_max,
    or None), where, closed_form ({name, equation, formula, value, tight, agrees} of Secs. VI-VII,
    or None), check (with check=True: {holds, bound_at_lo, bound_at_hi}: b* = b within the
    enclosure). bool(r): K_max > 0."""

    _symbol = r"K_{\max}"
    _name = "the largest passive gain"

    def __bool__(self) -> bool:
        return self.outcome == "holds"

    def _repr_extra(self) -> Dict[str, Any]:
        cf = self._extra.get("closed_form")
        return {"name": self._extra.get("name"), "closed_form": cf["name"] if cf else None}


class Wedge(Result):
    """The wedge criterion (25) and Tsypkin's condition (21) of paper 002. The value is the wedge
    criterion's margin (min over theta of its left side + 1: it holds iff the margin is > 0);
    bool(r): it holds and the paper's assumptions hold. Besides the protocol: wedge, tsypkin
    ({holds, margin, max_gain (Result, None when infinite), gain_infinite, theta_at_min,
    evidence}), applies, assumptions (violated, in words), H, H1."""

    _symbol = r"m_{\mathrm{wedge}}"
    _name = "the wedge margin"

    def __bool__(self) -> bool:
        return bool(self.wedge["holds"]) and bool(self.applies)

    def __float__(self) -> float:
        return float(self.value)

    def _repr_extra(self) -> Dict[str, Any]:
        return {"wedge_holds": self.wedge["holds"], "tsypkin_holds": self.tsypkin["holds"], "applies": self.applies}


class R:
    """r(jw) = T/(e^{jwT} - 1) of paper 001 (44): re (a Result, exact -T/2) and im (a Result,
    certified: the correctly rounded decimal -+ half a unit in its last place); value the
    complex number, complex(r); lo/hi the corners of the box; the truncated series (34) beside
    when r(..., terms=N) asked for it (series_re, series_im, series_error_bound: decimal strings,
    series_terms N; all None otherwise)."""

    def __init__(self, d: Dict[str, Any], status: str = "certified", method: Optional[str] = None) -> None:
        self.re = Result(d["re"])
        self.im = Result(d["im"])
        object.__setattr__(self.re, "_symbol", r"\mathrm{Re}\,r")
        object.__setattr__(self.im, "_symbol", r"\mathrm{Im}\,r")
        self.series_re, self.series_im = d["series_re"], d["series_im"]
        self.series_terms, self.series_error_bound = d["series_terms"], d["series_error_bound"]
        self.decimal = (d["re_text"], d["im_text"])
        self.status = status
        self.method = method or ("closed form (44): T/(e^{jwT}-1) = -T/2 - j (T/2) cot(wT/2); Re exact, Im from MPFI "
                                 "enclosures")

    @property
    def value(self) -> complex:
        return complex(float(self.re), float(self.im))

    @property
    def lo(self) -> complex:
        return complex(self.re.lo, self.im.lo)

    @property
    def hi(self) -> complex:
        return complex(self.re.hi, self.im.hi)

    def __complex__(self) -> complex:
        return self.value

    def __float__(self) -> float:
        raise TypeError("r(jw) is complex: use complex(r), r.re or r.im")

    def __repr__(self) -> str:
        return f"hapstab.R(re={self.decimal[0]!r}, im={self.decimal[1]!r}, status='re exact, im {self.status}')"

    def _repr_latex_(self) -> str:
        return rf"$r(j\omega) = {self.decimal[0]} {'-' if self.decimal[1].startswith('-') else '+'} " \
               rf"{self.decimal[1].lstrip('-')}\,j$ \quad (Re exact, Im {self.status})"


class Simulation(Result):
    """A scene simulated with the exact-ZOH simulator: the value is the largest |v| at the sample
    instants (numeric), bool(r) is not diverged. Besides the protocol: the summary's fields
    (diverged, trend, energy_generated, limit_cycle, steps_run, ...), and

      samples  dict of numpy float64 arrays: 't' (rows,) in s, and 'x' [m], 'v' [m/s], 'u' [N],
               'fh' [N], 'E_port', 'E_act', 'E_po', 'storage' [J] of shape (rows, dofs)
      fine     the same for the exact intersample grid ('t', 'x', 'v'), or None
      units    quantity -> unit"""

    _symbol = r"\max|v|"
    _name = "max |v|"

    def __bool__(self) -> bool:
        return not self.diverged

    @property
    def summary(self) -> Dict[str, Any]:
        return dict(self._extra["summary_fields"])

    def _repr_extra(self) -> Dict[str, Any]:
        rows, dofs = self.samples["x"].shape if "x" in self.samples else (0, 0)
        return {"diverged": self.diverged, "samples": f"{rows}x{dofs}"}


class Analysis(Result):
    """Theorem 5 of paper 000 (multidof.analyze, multidof::analyze_scene): the value is the LMI
    margin, status certified when (16)'s verdict was proven exactly. bool(r): stability concluded
    and the scene's loop as written not proven unstable (ok). Besides the protocol: feasible,
    certified, verdict ('feasible', 'infeasible', 'undecided'), certificate, stability_concluded,
    premises_hold, premise_failure ('' or the first premise that does not hold), assumptions
    ([{name, holds, outcome, certified, detail}]: Assumption 1, then the blocks' hidden modes),
    loop_as_written ({stable, coupling, method, status, why, states, spectral_radius_numeric,
    theorem4_witness}), hidden_modes, gamma, x, q_v, delta_v_required (numpy arrays), margin,
    facial_reduction, solver, path, witness and weighted_witness (the exact witnesses of (16)'s
    infeasibility as `multidof analyze --json` prints them, rationals as "p/q" strings, or None;
    docs/json.md), symmetry (None, or {group, classes, blocks}: (16) split by the permutations of
    identical DOFs, docs/multidof.md), least_dissipative ({q_v, norm, delta_v, gamma,
    point_certified, minimality} or None), scene, T, dofs, delay, delay_text, seconds."""

    _symbol = r"\mathrm{margin}"
    _name = "the LMI margin"

    # the loop Theorem 5's conclusion is about: not the scene's loop, which may write no coupling
    CONCLUDED_FOR = "the loop with any coupling V whose V-hat^Gamma is Delta_V-OSP, Delta_V >= Gamma^-1 Q_V Gamma^-1"

    def __bool__(self) -> bool:
        return bool(self._extra["ok"])

    def _repr_extra(self) -> Dict[str, Any]:
        # which loop each verdict is about (issue 49): Theorem 5's conclusion, and the scene's loop as written
        concluded = self._extra.get("stability_concluded")
        return {"verdict": self._extra.get("verdict"),
                "theorem5": f"stable: {self.CONCLUDED_FOR}" if concluded else f"no conclusion: {self._why_not()}",
                "loop_as_written": _loop_text(self._extra.get("loop_as_written")),
                "ok": bool(self)}

    def _why_not(self) -> str:
        if self._extra.get("verdict") != "feasible" or not self._extra.get("certified"):
            return f"the LMIs (16) are {self._extra.get('verdict')} ({'certified' if self._extra.get('certified') else 'not certified'})"
        return self._extra.get("premise_failure") or "a premise does not hold"


class Design(Result):
    """Theorem 6 of paper 000 (multidof.design, multidof::design_scene): the value is the CCL
    trace gap (numeric); bool(r): a coupling V was found and verified and every premise holds
    (ok). V = (A_V, B_V, C_V, D_V) as numpy arrays, V_exact the exact hapstab.StateSpace (None
    without a V). Besides the protocol: feasible, certified, converged, iterations, trace_gap,
    trace_history, convex_infeasible, convex_certified, gamma, q_v, delta_v, verification
    ([{name, verdict, certified, status, detail}]: the independent checks, the loop with V
    decided, the simulation), loop_with_v, simulation ({decays, text}), warning, message,
    assumptions, premise_failure, hidden_modes, facial_reduction, scene, T, dofs, delay."""

    _symbol = r"\mathrm{gap}"
    _name = "the trace gap"

    @property
    def V(self):
        return tuple(self._extra[k] for k in ("A_V", "B_V", "C_V", "D_V"))

    def __bool__(self) -> bool:
        return bool(self._extra["ok"])

    def _repr_extra(self) -> Dict[str, Any]:
        return {"feasible": self._extra.get("feasible"), "certified": self._extra.get("certified"),
                "loop_with_v": _loop_text(self._extra.get("loop_with_v")), "ok": bool(self)}


def _loop_text(loop: Optional[Dict[str, Any]]) -> Optional[str]:
    """A decided loop in a line: "NOT stable [certified], coupling: none (the direct connection)"."""
    if not loop:
        return None
    verdict = {True: "stable", False: "NOT stable", None: "undecided"}[loop.get("stable")]
    return f"{verdict} [{loop.get('status')}], coupling: {loop.get('coupling')}"


_VERDICT = ("exact", "certified", "numeric", "undecided")  # a stability array's verdict_status (code 3: undecided)
_CORE = ("value", "lo", "hi", "status", "exact", "lo_exact", "hi_exact", "error")


class ResultArray:
    """The results of a vectorised call (module docstring): value, lo, hi (float64), status (str:
    'exact', 'certified', 'numeric', 'failed', as a scalar result's), exact (object: str or None),
    error (object: str or None), method, params (the inputs, broadcast), and the function's own
    columns (omega for b*)."""

    def __init__(self, kind: type, columns: Dict[str, Any], shape: Tuple[int, ...], method: str,
                 params: Dict[str, Any]) -> None:
        import numpy as np
        cols = {k: (np.asarray(v).reshape(shape) if hasattr(v, "__len__") else v) for k, v in columns.items()}
        # one status type everywhere: the names, as a scalar result's status and a sweep's column
        cols["status"] = np.array(STATUS)[cols["status"]]
        if "verdict_status" in cols:
            cols["verdict_status"] = np.array(_VERDICT)[cols["verdict_status"]]
        self._set(kind, cols, tuple(shape), method, {k: np.broadcast_to(np.asarray(v), shape) for k, v in params.items()})

    def _set(self, kind: type, columns: Dict[str, Any], shape: Tuple[int, ...], method: str,
             params: Dict[str, Any]) -> None:
        self._kind = kind
        self.shape = shape
        self.method = method
        self.params = params
        self._columns = columns
        for k, v in columns.items():
            setattr(self, k, v)

    @property
    def ndim(self) -> int:
        return len(self.shape)

    @property
    def size(self) -> int:
        import numpy as np
        return int(np.prod(self.shape, dtype=np.int64))

    @property
    def failed(self) -> int:
        """The points that did not run (their error says why)."""
        import numpy as np
        return int(np.count_nonzero(self.error != None))  # noqa: E711 -- elementwise, in numpy

    def __len__(self) -> int:
        return self.shape[0] if self.shape else 1

    def __array__(self, dtype: Any = None, copy: Any = None) -> Any:
        import numpy as np
        return np.asarray(self.value, dtype=dtype)

    def to_numpy(self) -> Any:
        """The values, a float64 array of the broadcast shape (a copy; what np.asarray(r) gives)."""
        import numpy as np
        return np.array(self.value, dtype=np.float64)

    # ---- indexing and iteration ------------------------------------------------------------------
    def _point(self, i: Tuple[int, ...]) -> Result:
        flat = {k: (v[i] if hasattr(v, "shape") and v.shape == self.shape else v) for k, v in self._columns.items()}
        rec = {"value_exact": flat.get("exact"), "mid": float(flat["value"]), "lo": float(flat["lo"]),
               "hi": float(flat["hi"]), "lo_text": flat.get("lo_exact"), "hi_text": flat.get("hi_exact"),
               "status": str(flat["status"]), "method": self.method, "note": flat.get("error") or ""}
        extra = {k: flat[k] for k in self._columns if k not in _CORE}
        if "verdict_status" in extra:
            extra["verdict_status"] = str(extra["verdict_status"])
        extra.update({name: v[i] for name, v in self.params.items()})
        return self._kind(rec, **extra)

    def __getitem__(self, index: Any) -> Any:
        """r[i] (an index for every axis): point i as a scalar Result; any other index (a slice,
        a mask, an index array, one index of a 2-D array): the ResultArray of those points."""
        import numpy as np
        where = np.arange(self.size).reshape(self.shape)[index]
        if np.ndim(where) == 0:
            return self._point(np.unravel_index(int(where), self.shape))
        out = ResultArray.__new__(ResultArray)
        out._set(self._kind, {k: (v[index] if hasattr(v, "shape") and v.shape == self.shape else v)
                              for k, v in self._columns.items()},
                 where.shape, self.method, {k: v[index] for k, v in self.params.items()})
        return out

    def __iter__(self) -> Any:
        """Over the first axis: Results of a 1-D array, ResultArrays of the rows of a 2-D one."""
        for i in range(len(self)):
            yield self[i]

    # ---- elementwise comparisons, decided by the enclosures ------------------------------------
    def _compare(self, op: str, other: Any) -> Any:
        import numpy as np
        if isinstance(other, (Result, ResultArray)):
            raise TypeError("compare a ResultArray with numbers (or a numpy array of numbers)")
        y = np.broadcast_to(np.asarray(other, dtype=np.float64), self.shape)
        lo, hi = self.lo, self.hi
        bad = ~np.isin(self.status, _DECIDES)
        if op == "<":
            yes, no = hi < y, lo >= y
        elif op == "<=":
            yes, no = hi <= y, lo > y
        elif op == ">":
            yes, no = lo > y, hi <= y
        elif op == ">=":
            yes, no = lo >= y, hi < y
        else:  # == (and != its negation): equal only where the enclosure is the point y itself
            yes, no = (lo == y) & (hi == y), (hi < y) | (lo > y)
        yes, no = np.array(yes), np.array(no)
        undecided = ~(yes | no) & ~bad
        # where the float ends straddle x (an end not a double, next to x), the exact ends decide
        ends = self._columns.get("lo_exact"), self._columns.get("hi_exact")
        for i in map(tuple, np.argwhere(undecided)):
            if ends[0] is None or ends[0][i] is None or not np.isfinite(y[i]):
                continue
            a, b, x = _end(ends[0][i], lo[i]), _end(ends[1][i], hi[i]), Fraction(float(y[i]))
            yes_i = {"<": b < x, "<=": b <= x, ">": a > x, ">=": a >= x, "==": a == b == x}[op]
            no_i = {"<": a >= x, "<=": a > x, ">": b <= x, ">=": b < x, "==": b < x or a > x}[op]
            if yes_i or no_i:
                yes[i], undecided[i] = yes_i, False
        if bad.any():
            first = tuple(np.argwhere(bad)[0])
            status = str(self.status[first])
            err = _not_proven(f"r[{', '.join(map(str, first))}]", status, self.method,
                              str(self.error[first] or ""), op)
            raise UndecidedComparison(f"{int(bad.sum())} of {bad.size} points are not proven (the first at index "
                                      f"{tuple(int(i) for i in first)}"
                                      + (": the point failed" if status == "failed" else "") + "); " + str(err))
        if undecided.any():
            n = int(undecided.sum())
            first = tuple(np.argwhere(undecided)[0])
            raise UndecidedComparison(
                f"cannot decide {op} {other if np.ndim(other) == 0 else '(array)'} at {n} of {undecided.size} points "
                f"(the first at index {tuple(int(i) for i in first)}: "
                f"enclosure [{_fmt(float(lo[first]))}, {_fmt(float(hi[first]))}]"
                + "); the decided ones: (r.lo > x) | (r.hi <= x) ...")
        return yes

    def __lt__(self, other: Any) -> Any:
        return self._compare("<", other)

    def __le__(self, other: Any) -> Any:
        return self._compare("<=", other)

    def __gt__(self, other: Any) -> Any:
        return self._compare(">", other)

    def __ge__(self, other: Any) -> Any:
        return self._compare(">=", other)

    def __eq__(self, other: Any) -> Any:  # type: ignore[override]
        return self._compare("==", other)

    def __ne__(self, other: Any) -> Any:  # type: ignore[override]
        return ~self._compare("==", other)

    __hash__ = None  # type: ignore[assignment]

    def __array_ufunc__(self, ufunc: Any, method: str, *inputs: Any, **kwargs: Any) -> Any:
        """numpy's comparison ufuncs (np.float64(5) < r, np.less(x, r)) are the elementwise honest
        comparisons; any other ufunc (np.log10(r), np.maximum(r, 0)) sees the value array."""
        ops = _COMPARISON_UFUNCS.get(ufunc.__name__)
        if ops is not None and method == "__call__" and len(inputs) == 2 and not kwargs:
            a, b = inputs
            if a is self and not isinstance(b, (Result, ResultArray)):
                return self._compare(ops[0], b) if ops[0] != "!=" else ~self._compare("==", b)
            if b is self and not isinstance(a, (Result, ResultArray)):
                return self._compare(ops[1], a) if ops[1] != "!=" else ~self._compare("==", a)
            raise TypeError("compare a ResultArray with numbers (or a numpy array of numbers)")
        args = [x.value if isinstance(x, ResultArray) else float(x) if isinstance(x, Result) else x for x in inputs]
        return getattr(ufunc, method)(*args, **kwargs)

    # ---- tables --------------------------------------------------------------------------------
    def to_table(self) -> Any:
        """A structured numpy array of the points: one field per parameter, then value, lo, hi,
        status (str), the function's own columns, exact and error (objects)."""
        import numpy as np
        names = list(self.params) + [k for k in self._columns]
        arrays = [np.broadcast_to(np.asarray(v), self.shape) for v in self.params.values()] + \
                 [np.broadcast_to(np.asarray(v), self.shape) for v in self._columns.values()]
        dtype = [(n, a.dtype) for n, a in zip(names, arrays)]
        out = np.empty(self.shape, dtype=dtype)
        for n, a in zip(names, arrays):
            out[n] = a
        return out

    def to_pandas(self) -> Any:
        """The points as a pandas DataFrame (one row per point, the columns of to_table(); status
        as strings, as a sweep's; Debian's python3-pandas)."""
        try:
            import pandas
        except ImportError as e:
            raise ImportError("to_pandas() needs pandas (Debian: python3-pandas); to_table() has the same table") from e
        table = self.to_table().ravel()
        return pandas.DataFrame({n: table[n] for n in table.dtype.names})

    def _counts(self) -> Dict[str, int]:
        import numpy as np
        return {str(c): int(n) for c, n in zip(*np.unique(self.status, return_counts=True))}

    def __repr__(self) -> str:
        return (f"hapstab.ResultArray({self._kind.__name__}, shape={self.shape}, status={self._counts()}, "
                f"failed={self.failed}, method={self.method!r})")

    def _repr_html_(self) -> str:
        rows = self.to_table().ravel()
        head = list(rows.dtype.names)
        show = rows[:10]
        cells = "".join("<tr>" + "".join(f"<td>{html.escape(str(r[n]))}</td>" for n in head) + "</tr>" for r in show)
        more = f"<p>... {rows.size - 10} more points</p>" if rows.size > 10 else ""
        return (f"<p>hapstab.ResultArray of {self._kind.__name__}, shape {self.shape}, status {self._counts()}</p><table>"
                + "<tr>" + "".join(f"<th>{html.escape(n)}</th>" for n in head) + "</tr>" + cells + "</table>" + more)
