# Type stubs of the package hapstab (python/hapstab/__init__.py).
#
# The result protocol (every scalar result is a Result):
#   value        Fraction when status is 'exact', else the float midpoint of the enclosure
#   lo, hi       the enclosure rounded OUTWARD to floats (proven for exact/certified; for
#                numeric the stated error band, not a proof)
#   lo_exact, hi_exact   the same ends as exact decimal strings, rounded outward (or None)
#   status       'exact' | 'certified' | 'numeric' | 'upper_bound' | 'undecided' | 'failed';  method, note
#   float(r)     float(value);  f"{r:.3f}", round(r, 3), np.asarray(r), np.isclose(r, x): the value
#   r < x, r <= x, r > x, r >= x, r == x   decided by the enclosure, exactly (x: int, Fraction,
#                float (its shortest decimal), exact str, or a Result); raises UndecidedComparison
#                when the enclosure does not decide it, and for a result that is not proven
#                (numeric, undecided, failed: compare r.value explicitly)
#   _repr_html_(), _repr_latex_()          notebook display
# A vectorised call (an array in params, or an omega array for r) returns a ResultArray.
import os
from fractions import Fraction
from decimal import Decimal
from typing import Any, Dict, Iterator, List, Mapping, Optional, Sequence, Tuple, Type, Union, overload

import numpy as np
import numpy.typing as npt

from . import multidof as multidof

__version__: str
STATUS: Tuple[str, str, str, str]  # the statuses a ResultArray's points take: exact, certified, numeric, failed

class InputError(ValueError): ...
class NumericalError(RuntimeError): ...
class UndecidedComparison(ValueError): ...

# a number, exact: a float is read as the shortest decimal that rounds to it (Fraction(x): its binary value)
Exact = Union[int, Fraction, float, str, Decimal, np.integer[Any], np.floating[Any]]
# an array: anything np.asarray takes with ndim >= 1 (list, numpy array, pandas Series, ...)
ExactOrArray = Union[Exact, Sequence[Exact], npt.NDArray[Any], Any]
ScalarParams = Mapping[str, Exact]
Number = Union[int, Fraction, float, str, Decimal]  # what a result compares with (np.float64 is a float)
Scene = Union[str, os.PathLike]

class TransferFunction:
    """An exact SISO transfer function (lti/tf.hpp), reduced; build it with tf()."""
    @property
    def num(self) -> List[str]: ...  # descending powers, exact p/q strings
    @property
    def den(self) -> List[str]: ...
    @property
    def T(self) -> Optional[str]: ...
    @property
    def variable(self) -> str: ...

class StateSpace:
    """A discrete state space with exact entries (lti/state_space.hpp); build it with ss()."""
    @property
    def A(self) -> List[List[str]]: ...
    @property
    def B(self) -> List[List[str]]: ...
    @property
    def C(self) -> List[List[str]]: ...
    @property
    def D(self) -> List[List[str]]: ...
    @property
    def T(self) -> str: ...
    @property
    def shape(self) -> Tuple[int, int, int]: ...  # (states, inputs, outputs)

# an expression str, a TransferFunction, (num, den) in descending powers of z, or an object with num, den, dt
TransferFunctionInput = Union[str, TransferFunction, Tuple[Sequence[Exact], Sequence[Exact]], Any]

class Result:
    @property
    def value(self) -> Union[Fraction, float]: ...
    @property
    def lo(self) -> float: ...
    @property
    def hi(self) -> float: ...
    @property
    def lo_exact(self) -> Optional[str]: ...
    @property
    def hi_exact(self) -> Optional[str]: ...
    @property
    def status(self) -> str: ...
    @property
    def method(self) -> str: ...
    @property
    def note(self) -> str: ...
    def as_dict(self) -> Dict[str, Any]: ...
    def __float__(self) -> float: ...
    def __format__(self, spec: str) -> str: ...
    def __round__(self, ndigits: Optional[int] = ...) -> Any: ...
    def __array__(self, dtype: Any = ..., copy: Any = ...) -> npt.NDArray[np.float64]: ...
    def __lt__(self, other: Union[Number, "Result"]) -> bool: ...
    def __le__(self, other: Union[Number, "Result"]) -> bool: ...
    def __gt__(self, other: Union[Number, "Result"]) -> bool: ...
    def __ge__(self, other: Union[Number, "Result"]) -> bool: ...
    def __eq__(self, other: object) -> bool: ...
    def __ne__(self, other: object) -> bool: ...
    def _repr_html_(self) -> str: ...
    def _repr_latex_(self) -> str: ...

class Bound(Result):
    """b* of paper 001 (45)/(54): passive iff b > b*."""
    omega: Optional[str]          # the maximiser (rad/s), decimal
    where: str
    decimal: str                  # b* to the digits asked ('inf' when no finite b)
    infinite: bool
    closed_form: Optional[Dict[str, Any]]  # {name, equation, formula, value, approx, tight}
    enclosure_rigorous: bool
    damping: Dict[str, Any]       # with damping=b: {b, passive}

class PassivityLevel(Result):
    kind: str
    theta: Optional[float]
    is_level: bool
    certified_value: Optional[str]
    lmi_level: Optional[float]
    lmi_lower_bound: Optional[str]
    lmi_method: str
    grid_level: Optional[float]

class Stability(Result):
    """value: the closed loop's spectral radius; bool(): stable (raises when undecided).
    With scene=...: value the spectral radius in double (status 'numeric'), the verdict
    (stable, verdict_status) certified or exact, decided on the loop as written."""
    stable: Optional[bool]
    evidence: str
    degree: int                   # plant/H/T calls
    device: str
    precision_bits: int
    verdict_status: str           # 'exact' | 'certified' | 'undecided'
    decider: str                  # scene=...: the method that decided
    dofs: int
    states: int
    hidden_modes: List[Dict[str, Any]]  # [{block, kind, discrete, pair, where, re, im, abs, stable}]
    hidden_summary: str
    scene: str
    def __bool__(self) -> bool: ...

class MaxGain(Result):
    """stability(..., max='K'): sup{K : stable on (0, sup)} (0: unstable for small K; inf). Status
    'undecided' (value NaN) where the supremum is not proven; what is then proven is beside it."""
    name: str
    outcome: str                  # 'holds' | 'fails' | 'undecided'
    crossing: Any                 # 'z = 1' | 'z = -1' | 'complex pair'; scene=: {at, crossing, theta, omega, mode}
    theta: Optional[Tuple[float, float]]
    omega: Optional[Tuple[float, float]]
    # stability(scene=..., max=...):
    path: str                     # 'one_dof' | 'closed_loop_matrix' | 'bisection_on_verdicts' | 'hidden_modes'
    supremum_proven: bool
    stable_on: Optional[Tuple[str, str]]     # stable for every value in it (certified)
    open_at_zero: bool            # stable_on excludes 0: M(0) has the eigenvalue 1 (position integrators)
    change_in: Optional[Tuple[str, str]]     # not affine: stable at its lower end, NOT stable at its upper end
    stable_at: Any
    unstable_at: Any
    gap: Optional[float]
    not_affine: Optional[str]
    verdicts_outcome: str         # the bisection's: 'holds' (a certified bracket), 'fails', 'undecided'
    states: int
    fixed_modes: int
    theorem5: Optional[Dict[str, Any]]       # conservatism=True: {bracket, concludes_at, not_at, note, programs, seconds}
    conservatism: Optional[Tuple[str, str]]  # exact / Theorem 5: only where both regions are proven intervals
    conservatism_note: Optional[str]
    contradiction: bool
    def __bool__(self) -> bool: ...  # raises UndecidedComparison when the supremum is not proven

class MaxPassiveGain(Result):
    """bound(H, max='K', damping=b): sup{K0 : b > b*(K) for 0 <= K < K0}; 0 when b <= b*(0), inf
    when passive for every K; certified (exact where rational). bool(): K_max > 0."""
    name: str
    outcome: str                  # 'holds' when K_max > 0
    infinite: bool
    decimal: str
    digits_certified: int
    damping: str                  # b, exact
    b_at_zero: Bound              # b*(0)
    omega: Optional[Tuple[float, float]]  # where b* = b at K_max (rad/s, outward)
    where: str
    jump: bool                    # b*(K_max) <= b and b* = +inf above (H's pole at z = -1, fractional delay)
    b_at_sup: Optional[Bound]     # b*(K_max) when jump
    closed_form: Optional[Dict[str, Any]]  # {name, equation, formula, value, tight, agrees}
    check: Optional[Dict[str, Any]]        # check=True: {holds, bound_at_lo: Bound, bound_at_hi: Bound}
    def __bool__(self) -> bool: ...

class Wedge(Result):
    """value: the wedge criterion's margin; bool(): it holds and the assumptions hold."""
    wedge: Dict[str, Any]         # {evaluated, holds, evidence, margin: Result, max_gain: Result | None, gain_infinite, theta_at_min}
    tsypkin: Dict[str, Any]
    applies: bool
    assumptions: List[str]
    H: str
    H1: Optional[str]
    def __bool__(self) -> bool: ...

class R:
    """r(jw): re (Result, exact), im (Result, certified), value complex, lo/hi the box."""
    re: Result
    im: Result
    series_re: Optional[str]  # None unless r(..., terms=N) asked for the series (34)
    series_im: Optional[str]
    series_terms: Optional[int]
    series_error_bound: Optional[str]
    decimal: Tuple[str, str]
    status: str
    method: str
    @property
    def value(self) -> complex: ...
    @property
    def lo(self) -> complex: ...
    @property
    def hi(self) -> complex: ...
    def __complex__(self) -> complex: ...

class RArray:
    """r(jw) over an omega array."""
    re: float
    re_exact: str
    im: npt.NDArray[np.float64]
    im_lo: npt.NDArray[np.float64]
    im_hi: npt.NDArray[np.float64]
    status: str
    method: str
    @property
    def value(self) -> npt.NDArray[np.complex128]: ...
    @property
    def lo(self) -> npt.NDArray[np.complex128]: ...
    @property
    def hi(self) -> npt.NDArray[np.complex128]: ...
    def __len__(self) -> int: ...
    def __getitem__(self, index: Any) -> Any: ...   # R at a full index, RArray otherwise
    def __iter__(self) -> Iterator[Any]: ...
    def __array__(self, dtype: Any = ..., copy: Any = ...) -> npt.NDArray[np.complex128]: ...

class ResultArray:
    """A vectorised call: value, lo, hi (float64, the broadcast shape of params), status (str, as
    a scalar result's), exact (object: str or None), lo_exact/hi_exact (object: the ends as outward
    decimals, which decide a comparison the float ends straddle), error (object: str or None),
    params, method; b* adds omega, stability adds stable (int8: 1, 0, -1 undecided); bound(max=) adds
    omega, b_at_zero; stability(scene=) adds verdict_status (str: exact, certified, undecided),
    states, evidence. r[i] (an index per axis) a Result, r[1:] a ResultArray; iteration over the
    first axis; comparisons elementwise and honest; to_numpy() the values, to_table() the table."""
    shape: Tuple[int, ...]
    method: str
    params: Dict[str, npt.NDArray[Any]]
    value: npt.NDArray[np.float64]
    lo: npt.NDArray[np.float64]
    hi: npt.NDArray[np.float64]
    status: npt.NDArray[np.str_]
    exact: npt.NDArray[np.object_]
    lo_exact: npt.NDArray[np.object_]
    hi_exact: npt.NDArray[np.object_]
    error: npt.NDArray[np.object_]
    @property
    def failed(self) -> int: ...
    @property
    def ndim(self) -> int: ...
    @property
    def size(self) -> int: ...
    def __len__(self) -> int: ...
    def __getitem__(self, index: Any) -> Any: ...   # a Result at a full index, a ResultArray otherwise
    def __iter__(self) -> Iterator[Any]: ...
    def __array__(self, dtype: Any = ..., copy: Any = ...) -> npt.NDArray[np.float64]: ...
    def __eq__(self, other: object) -> npt.NDArray[np.bool_]: ...  # type: ignore[override]
    def __ne__(self, other: object) -> npt.NDArray[np.bool_]: ...  # type: ignore[override]
    def __lt__(self, other: Any) -> npt.NDArray[np.bool_]: ...
    def __le__(self, other: Any) -> npt.NDArray[np.bool_]: ...
    def __gt__(self, other: Any) -> npt.NDArray[np.bool_]: ...
    def __ge__(self, other: Any) -> npt.NDArray[np.bool_]: ...
    def to_numpy(self) -> npt.NDArray[np.float64]: ...
    def to_table(self) -> npt.NDArray[np.void]: ...
    def to_pandas(self) -> Any: ...

class Simulation(Result):
    """value: max |v| at the samples (numeric); bool(): not diverged."""
    samples: Dict[str, npt.NDArray[np.float64]]
    fine: Optional[Dict[str, npt.NDArray[np.float64]]]
    units: Dict[str, str]
    diverged: bool
    trend: str
    max_velocity: float
    energy_generated: float
    limit_cycle: Optional[Dict[str, Any]]
    steps_run: int
    @property
    def summary(self) -> Dict[str, Any]: ...
    def __bool__(self) -> bool: ...

class Analysis(Result):
    """multidof.analyze: Theorem 5 on a scene (multidof::analyze_scene). value: the LMI margin;
    bool(): ok (stability concluded and the loop as written not proven unstable)."""
    ok: bool
    feasible: bool
    certified: bool
    stability_concluded: bool
    premises_hold: bool
    premise_failure: str          # '' or the first premise that does not hold
    verdict: str                  # 'feasible' | 'infeasible' | 'undecided'
    certificate: str
    margin: float
    gamma: List[float]
    x: List[float]
    q_v: npt.NDArray[np.float64]
    delta_v_required: npt.NDArray[np.float64]
    facial_reduction: str
    solver: str
    assumptions: List[Dict[str, Any]]      # [{name, holds, outcome, certified, detail}]
    loop_as_written: Dict[str, Any]        # {stable, coupling, method, status, why, states, spectral_radius_numeric,
                                           #  theorem4_witness: Theorem 4's two-frequency witness (dict) or None}
    path: Optional[str]                    # the planner's path that decided (None: none did)
    witness: Optional[Dict[str, Any]]      # (16) infeasible by one frequency: {theta, z, u, phi, phi_negative, form}
    weighted_witness: Optional[Dict[str, Any]]  # ... by several: {points, directions, sums, sums_numeric, sums_nonpositive, form}
    hidden_modes: List[Dict[str, Any]]
    least_dissipative: Optional[Dict[str, Any]]
    scene: str
    T: str
    dofs: int
    delay: int
    delay_text: Optional[str]
    seconds: Dict[str, float]
    def __bool__(self) -> bool: ...

class Design(Result):
    """multidof.design: Theorem 6 on a scene (multidof::design_scene). value: the CCL trace gap;
    bool(): ok (a verified V, every premise holding). A contradiction raises NumericalError."""
    ok: bool
    feasible: bool
    certified: bool
    premise_failure: str
    converged: bool
    iterations: int
    trace_gap: float
    trace_history: List[float]
    convex_infeasible: bool
    convex_certified: bool
    A_V: npt.NDArray[np.float64]
    B_V: npt.NDArray[np.float64]
    C_V: npt.NDArray[np.float64]
    D_V: npt.NDArray[np.float64]
    V_exact: Optional[StateSpace]
    gamma: List[float]
    q_v: npt.NDArray[np.float64]
    delta_v: npt.NDArray[np.float64]
    verification: List[Dict[str, Any]]     # [{name, verdict, certified, status, detail, witness}]
    loop_with_v: Optional[Dict[str, Any]]
    simulation: Optional[Dict[str, Any]]   # {decays, text}
    warning: Optional[str]
    message: str
    assumptions: List[Dict[str, Any]]
    hidden_modes: List[Dict[str, Any]]
    facial_reduction: str
    scene: str
    T: str
    dofs: int
    delay: int
    delay_text: Optional[str]
    @property
    def V(self) -> Tuple[npt.NDArray[np.float64], ...]: ...
    def __bool__(self) -> bool: ...

def tf(H: TransferFunctionInput, T: Optional[Exact] = ..., params: Optional[Mapping[str, Exact]] = ...) -> TransferFunction: ...
def ss(A: Any, B: Any, C: Any, D: Any, T: Exact) -> StateSpace: ...
def run(*args: str) -> Tuple[int, Optional[Dict[str, Any]]]: ...
def examples_dir() -> str: ...
@overload
def r(T: Exact, omega: Exact, digits: int = ..., terms: Optional[int] = ..., method: str = ...,  # type: ignore[misc]
      jobs: Optional[int] = ...) -> R: ...
@overload
def r(T: Exact, omega: Union[Sequence[Exact], npt.NDArray[Any], Any], digits: int = ..., terms: Optional[int] = ...,
      method: str = ..., jobs: Optional[int] = ...) -> RArray: ...
# scalar params (or none): one result; arrays in params (or in damping): a ResultArray
@overload
def bound(H: TransferFunctionInput, T: Optional[Exact] = ..., delay: int = ..., frac_delay: Optional[Exact] = ...,  # type: ignore[misc]
          eta: Exact = ..., digits: int = ..., method: str = ..., params: Optional[ScalarParams] = ...,
          damping: Optional[Exact] = ..., grid_points: Optional[int] = ..., allow_noncausal: bool = ...,
          jobs: Optional[int] = ..., max: None = ..., check: bool = ...) -> Bound: ...
@overload
def bound(H: TransferFunctionInput, T: Optional[Exact] = ..., delay: int = ..., frac_delay: Optional[Exact] = ...,  # type: ignore[misc]
          eta: Exact = ..., digits: int = ..., method: str = ..., params: Optional[ScalarParams] = ...,
          damping: Exact = ..., grid_points: Optional[int] = ..., allow_noncausal: bool = ...,
          jobs: Optional[int] = ..., *, max: str, check: bool = ...) -> MaxPassiveGain: ...
@overload
def bound(H: TransferFunctionInput, T: Optional[Exact] = ..., delay: int = ..., frac_delay: Optional[Exact] = ...,
          eta: Exact = ..., digits: int = ..., method: str = ..., params: Optional[Mapping[str, ExactOrArray]] = ...,
          damping: Optional[ExactOrArray] = ..., grid_points: Optional[int] = ..., allow_noncausal: bool = ...,
          jobs: Optional[int] = ..., max: Optional[str] = ..., check: bool = ...) -> ResultArray: ...
@overload
def stability(plant: Optional[Any] = ..., H: Optional[TransferFunctionInput] = ..., T: Optional[Exact] = ...,  # type: ignore[misc]
              delay: int = ..., operator: Optional[Any] = ..., max: None = ..., digits: int = ...,
              params: Optional[ScalarParams] = ..., jobs: Optional[int] = ..., *,
              scene: Optional[Scene] = ..., conservatism: bool = ...) -> Stability: ...
@overload
def stability(plant: Optional[Any] = ..., H: Optional[TransferFunctionInput] = ..., T: Optional[Exact] = ...,  # type: ignore[misc]
              delay: int = ..., operator: Optional[Any] = ..., *, max: str, digits: int = ...,
              params: Optional[ScalarParams] = ..., jobs: Optional[int] = ...,
              scene: Optional[Scene] = ..., conservatism: bool = ...) -> MaxGain: ...
@overload
def stability(plant: Optional[Any] = ..., H: Optional[TransferFunctionInput] = ..., T: Optional[Exact] = ...,
              delay: int = ..., operator: Optional[Any] = ..., max: Optional[str] = ..., digits: int = ...,
              params: Optional[Mapping[str, ExactOrArray]] = ..., jobs: Optional[int] = ..., *,
              scene: Optional[Scene] = ..., conservatism: bool = ...) -> ResultArray: ...
def wedge(H: TransferFunctionInput, T: Optional[Exact] = ..., digits: int = ...,
          params: Optional[Mapping[str, Exact]] = ...) -> Wedge: ...
@overload
def passivity_level(H: Optional[TransferFunctionInput] = ..., T: Optional[Exact] = ...,  # type: ignore[misc]
                    ss: Optional[Union[StateSpace, Sequence[Any], Any]] = ..., kind: str = ...,
                    backend: Optional[str] = ..., lemma: Optional[int] = ..., grid: Optional[int] = ...,
                    digits: Optional[int] = ..., params: Optional[ScalarParams] = ...,
                    jobs: Optional[int] = ...) -> PassivityLevel: ...
@overload
def passivity_level(H: Optional[TransferFunctionInput] = ..., T: Optional[Exact] = ...,
                    ss: Optional[Union[StateSpace, Sequence[Any], Any]] = ..., kind: str = ...,
                    backend: Optional[str] = ..., lemma: Optional[int] = ..., grid: Optional[int] = ...,
                    digits: Optional[int] = ..., params: Optional[Mapping[str, ExactOrArray]] = ...,
                    jobs: Optional[int] = ...) -> ResultArray: ...
def simulate(scene: Scene, *, force: bool = ..., max_output: Optional[float] = ..., **overrides: Exact) -> Simulation: ...

class Sweep(np.ndarray):
    """A structured array, one row per point: t['bound'] float64, t['index'] int64, ..."""
    exact: Dict[str, npt.NDArray[np.object_]]
    manifest: Dict[str, Any]
    exit_code: int
    path: Optional[str]
    @property
    def failed(self) -> int: ...
    def to_pandas(self) -> Any: ...

def sweep(spec: Union[str, os.PathLike, Mapping[str, Any]], out: Optional[Union[str, os.PathLike]] = ..., *,
          jobs: Optional[int] = ..., shard: Optional[str] = ..., resume: bool = ...) -> Sweep: ...
