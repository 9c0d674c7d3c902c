# Type stubs of the package hapstab (python/hapstab/__init__.py).
import os
from fractions import Fraction
from typing import Any, Dict, Mapping, Optional, Sequence, Tuple, Union

import numpy as np
import numpy.typing as npt

from . import multidof as multidof

__version__: str

class InputError(ValueError): ...
class NumericalError(RuntimeError): ...

Exact = Union[int, Fraction, float, str]
# an expression str, (num, den) in descending powers of z, or an object with num, den, dt
TransferFunctionInput = Any
Scene = Union[str, os.PathLike]

class Result:
    exit_code: int
    def __getattr__(self, name: str) -> Any: ...
    def as_dict(self) -> Dict[str, Any]: ...
    @property
    def value(self) -> Any: ...
    def __float__(self) -> float: ...

class R(Result):
    re: str
    im: str
    @property
    def value(self) -> Tuple[str, str]: ...
    def __complex__(self) -> complex: ...

class Bound(Result):
    status: str
    omega: Optional[str]
    method: str
    @property
    def value(self) -> str: ...
    @property
    def fraction(self) -> Optional[Fraction]: ...
    @property
    def enclosure(self) -> Tuple[str, str]: ...

class Stability(Result):
    status: str
    @property
    def value(self) -> Any: ...
    def __bool__(self) -> bool: ...

class Wedge(Result):
    verdict: str
    wedge_holds: bool
    tsypkin_holds: bool
    def __bool__(self) -> bool: ...

class PassivityLevel(Result):
    level: Optional[float]
    kind: str

class Analysis(Result):
    feasible: bool
    certified: bool
    stability_concluded: bool
    verdict: str
    def __bool__(self) -> bool: ...

class Design(Result):
    feasible: bool
    certified: bool
    @property
    def V(self) -> Tuple[npt.NDArray[np.float64], ...]: ...
    def __bool__(self) -> bool: ...

class Simulation(Result):
    samples: Dict[str, npt.NDArray[np.float64]]
    fine: Optional[Dict[str, npt.NDArray[np.float64]]]
    units: Dict[str, str]
    out: Optional[str]
    diverged: bool
    @property
    def summary(self) -> Dict[str, Any]: ...

def run(*args: str) -> Result: ...
def examples_dir() -> str: ...
def r(T: Exact, omega: Exact, digits: int = ..., terms: Optional[int] = ...) -> R: ...
def bound(H: TransferFunctionInput, T: Optional[Exact] = ..., delay: int = ..., frac_delay: Optional[Exact] = ...,
          eta: Exact = ..., digits: int = ..., method: str = ..., params: Optional[Mapping[str, Exact]] = ...,
          damping: Optional[Exact] = ..., grid_points: Optional[int] = ..., allow_noncausal: bool = ...) -> Bound: ...
def stability(plant: str, H: TransferFunctionInput, T: Optional[Exact] = ..., delay: int = ...,
              operator: Optional[str] = ..., max: Optional[str] = ..., digits: int = ...,
              params: Optional[Mapping[str, Exact]] = ...) -> Stability: ...
def wedge(H: TransferFunctionInput, T: Optional[Exact] = ..., digits: int = ...,
          params: Optional[Mapping[str, Exact]] = ...) -> Wedge: ...
def passivity_level(H: Optional[TransferFunctionInput] = ..., T: Optional[Exact] = ...,
                    ss: Optional[Sequence[Any]] = ..., kind: str = ..., backend: Optional[str] = ...,
                    lemma: Optional[int] = ..., grid: Optional[int] = ..., digits: Optional[int] = ...,
                    params: Optional[Mapping[str, Exact]] = ...) -> PassivityLevel: ...
def simulate(scene: Scene, *, out: Optional[Union[str, os.PathLike]] = ..., force: bool = ...,
             max_output: Optional[float] = ..., **overrides: Exact) -> Simulation: ...
def read_series(path: str) -> Tuple[Dict[str, npt.NDArray[np.float64]], Dict[str, str]]: ...

class Sweep:
    columns: Dict[str, npt.NDArray[Any]]
    exact: Dict[str, npt.NDArray[np.object_]]
    manifest: Dict[str, Any]
    exit_code: int
    path: Optional[str]
    def __len__(self) -> int: ...
    @property
    def failed(self) -> int: ...
    def as_dict(self) -> Dict[str, npt.NDArray[Any]]: ...
    def frame(self) -> Any: ...

def sweep(spec: Union[str, os.PathLike, Mapping[str, Any]], out: Optional[Union[str, os.PathLike]] = ..., *,
          jobs: Optional[int] = ..., shard: Optional[str] = ..., resume: bool = ...) -> Sweep: ...
