"""hapstab.multidof -- paper 000: the multi-operator multi-device stability test (Theorem 5)
and the structured coupling design (Theorem 6) of a scene (`hapstab multidof analyze|design`)."""
from __future__ import annotations

from typing import Any, Optional

from . import _SceneFile, _json, _sets
from ._results import Analysis, Design

__all__ = ["analyze", "design"]


def _args(command: str, path: str, backend: Optional[str], overrides: dict) -> list:
    args = ["multidof", command, f"--scene={path}", "--json", *_sets(overrides)]
    if backend is not None:
        args.append(f"--backend={backend}")
    return args


def analyze(scene: Any, *, backend: Optional[str] = None, **overrides: Any) -> Analysis:
    """Theorem 5: the LMIs (16) with an exact certificate, and Assumption 1. bool(result) is
    True when stability is concluded (certified feasible and the assumptions hold) and the
    scene's loop as written (result.loop_as_written) is not proven unstable."""
    with _SceneFile(scene) as path:
        return Analysis(*_json(_args("analyze", path, backend, overrides)))


def design(scene: Any, *, backend: Optional[str] = None, iterations: Optional[int] = None,
           duration: Optional[float] = None, **overrides: Any) -> Design:
    """Theorem 6: a structured coupling V by CCL, independently verified; result.V = (A, B, C, D)."""
    with _SceneFile(scene) as path:
        args = _args("design", path, backend, overrides)
        if iterations is not None:
            args.append(f"--iterations={int(iterations)}")
        if duration is not None:
            args.append(f"--duration={float(duration)!r}")
        return Design(*_json(args))
