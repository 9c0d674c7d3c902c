# Type stubs of hapstab.multidof (python/hapstab/multidof.py).
from typing import Any, Optional

from . import Analysis, Design, Exact, Scene

def analyze(scene: Scene, *, backend: Optional[str] = ..., **overrides: Exact) -> Analysis: ...
def design(scene: Scene, *, backend: Optional[str] = ..., iterations: Optional[int] = ...,
           duration: Optional[float] = ..., **overrides: Exact) -> Design: ...
