"""hapstab.multidof -- paper 000: the multi-operator multi-device stability test (Theorem 5)
and the structured coupling design (Theorem 6) of a scene.

Both run the library's composition of these (scene -> problem, the LMIs (16) with an exact
certificate, Assumption 1, the loop as written; the CCL design and its verification) as
`hapstab multidof analyze|design` composes it, in a forked child: a long SDP cannot be
interrupted from inside, so Ctrl-C kills the child (python/bind_scene.cpp says why this path
is not yet a direct binding)."""
from __future__ import annotations

import json
import os
from typing import Any, Optional

from . import InputError, _call, _core, _SceneFile
from ._exact import exact, integer, real
from ._results import Analysis, Design

__all__ = ["analyze", "design"]


def _run(command: str, scene: Any, backend: Optional[str], overrides: dict, extra: list) -> dict:
    s = _SceneFile(scene)
    if backend is not None and backend not in ("auto", "dsdp", "csdp", "ipm"):
        raise InputError(f"backend: expected 'auto', 'dsdp', 'csdp' or 'ipm', got {backend!r}")
    if s.text is not None:  # the command reads files: the text goes to a private folder of the child's
        import tempfile
        with tempfile.TemporaryDirectory(prefix="hapstab-scene-") as tmp:
            path = os.path.join(tmp, "scene.toml")
            with open(path, "w", encoding="utf-8") as f:
                f.write(s.text)
            return _args_run(command, path, backend, overrides, extra, "scene")
    return _args_run(command, s.path, backend, overrides, extra, None)


def _args_run(command: str, path: str, backend: Optional[str], overrides: dict, extra: list,
              text_name: Optional[str]) -> tuple:
    args = ["multidof", command, f"--scene={path}", "--json"]
    args += [f"--set={k}={exact(v, str(k))}" for k, v in overrides.items()]
    if backend is not None:
        args.append(f"--backend={backend}")
    args += extra
    try:
        code, text = _call(_core.run, args, keywords=True)
    except InputError as e:
        message = str(e)
        if text_name is not None:  # the scene was text: no file name of ours in the message
            message = message.replace(path, text_name)
        raise InputError(message) from None
    return code, json.loads(text)


def _record(value: float, certified: bool, method: str, note: str = "") -> dict:
    return {"value_exact": None, "mid": value, "lo": value, "hi": value, "lo_text": None, "hi_text": None,
            "status": "certified" if certified else "numeric", "method": method, "note": note}


def analyze(scene: Any, *, backend: Optional[str] = None, **overrides: Any) -> Analysis:
    """Theorem 5: the LMIs (16) with an exact certificate, and Assumption 1. bool(result) is
    True when stability is concluded (certified feasible and the assumptions hold) and the
    scene's loop as written (result.loop_as_written) is not proven unstable."""
    code, j = _run("analyze", scene, backend, overrides, [])
    margin = j.get("margin")
    rec = _record(float("nan") if margin is None else float(margin), bool(j.get("certified")),
                  "Theorem 5: LMIs (16), facial reduction, exact certificate of the rounded point",
                  j.get("certificate", ""))
    return Analysis(rec, exit_code=code, **j)


def design(scene: Any, *, backend: Optional[str] = None, iterations: Optional[int] = None,
           duration: Optional[float] = None, **overrides: Any) -> Design:
    """Theorem 6: a structured coupling V by CCL, independently verified; result.V = (A, B, C, D)."""
    extra = []
    if iterations is not None:
        extra.append(f"--iterations={integer(iterations, 'iterations', 1, 10000)}")
    if duration is not None:
        extra.append(f"--duration={real(duration, 'duration')!r}")
    code, j = _run("design", scene, backend, overrides, extra)
    gap = j.get("trace_gap")
    rec = _record(float("nan") if gap is None else float(gap), False, "Theorem 6: cone complementarity linearisation",
                  j.get("message", ""))
    return Design(rec, exit_code=code, **j)
