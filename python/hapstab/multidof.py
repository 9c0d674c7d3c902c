"""hapstab.multidof -- paper 000: the multi-operator multi-device stability test (Theorem 5)
and the structured coupling design (Theorem 6) of a scene.

Both are bindings of the library's one entry point (multidof/scene_analysis.hpp: analyze_scene,
design_scene, the study `hapstab multidof analyze|design` prints): the scene as paper 000's
problem, the LMIs (16) with an exact certificate, Assumption 1 and the blocks' hidden modes, the
loop as written decided; the CCL design, its independent verification, the loop with the
designed V decided and simulated. They run on a worker thread with the GIL released; Ctrl-C
stops them at the next LMI solve, Riccati point or simulation block and raises
KeyboardInterrupt."""
from __future__ import annotations

from typing import Any, Optional

from . import InputError, _call, _core, _SceneFile
from ._exact import exact, integer, real
from ._results import Analysis, Design

__all__ = ["analyze", "design"]


def _scene(scene: Any, backend: Optional[str], overrides: dict) -> tuple:
    s = _SceneFile(scene)
    if backend is None:
        backend = "auto"
    if backend not in ("auto", "dsdp", "csdp", "ipm"):
        raise InputError(f"backend: expected 'auto', 'dsdp', 'csdp' or 'ipm', got {backend!r}")
    texts = {str(k): exact(v, str(k)) for k, v in overrides.items()}
    return (s.text if s.text is not None else s.path), s.text is not None, texts, backend


def analyze(scene: Any, *, backend: Optional[str] = None, **overrides: Any) -> Analysis:
    """Theorem 5 on a scene (a path, or TOML text; scene parameters as keywords, exact).

    An Analysis: value the LMIs' margin (numeric; status 'certified' when (16)'s verdict is
    proven exactly), bool(result) True when stability is concluded (certified feasible and every
    premise holds) and the scene's loop as written is not proven unstable. Fields: feasible,
    certified, verdict, certificate, stability_concluded, premises_hold, premise_failure,
    assumptions, loop_as_written, hidden_modes, gamma, x, q_v, delta_v_required (numpy),
    least_dissipative, delay, delay_text, seconds, ..."""
    source, is_text, texts, backend = _scene(scene, backend, overrides)
    d = _call(_core.multidof_analyze, source, is_text, texts, backend, keywords=True)
    rec = {"value_exact": None, "mid": float(d["margin"]), "lo": float(d["margin"]), "hi": float(d["margin"]),
           "lo_text": None, "hi_text": None, "status": "certified" if d["certified"] else "numeric",
           "method": "Theorem 5: LMIs (16), facial reduction, exact certificate of the rounded point",
           "note": d["certificate"]}
    return Analysis(rec, **d)


def design(scene: Any, *, backend: Optional[str] = None, iterations: Optional[int] = None,
           duration: Optional[float] = None, **overrides: Any) -> Design:
    """Theorem 6 on a scene: a structured coupling V by CCL (at most `iterations`, default 40),
    independently verified, the loop with V decided as written and simulated for `duration`
    seconds (default 10; a numeric cross-check that can warn, never decide).

    A Design: value the CCL trace gap (numeric), bool(result) True when a V passed every check,
    every premise holds; V = (A, B, C, D) numpy arrays, V_exact the exact hapstab.StateSpace.
    A simulation or closed-loop decision that contradicts a certificate raises NumericalError
    (`hapstab multidof design` exits 3)."""
    iterations = 40 if iterations is None else integer(iterations, "iterations", 1, 10000)
    duration = 10.0 if duration is None else real(duration, "duration")  # <= 1e6: design_scene checks
    source, is_text, texts, backend = _scene(scene, backend, overrides)
    d = _call(_core.multidof_design, source, is_text, texts, backend, iterations, duration, keywords=True)
    rec = {"value_exact": None, "mid": float(d["trace_gap"]), "lo": float(d["trace_gap"]), "hi": float(d["trace_gap"]),
           "lo_text": None, "hi_text": None, "status": "numeric", "method": "Theorem 6: cone complementarity linearisation",
           "note": d["message"]}
    return Design(rec, **d)
