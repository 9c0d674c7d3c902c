"""One named multi-DOF scene through `stability --scene S --max g` against scene_max's reference
(indep_loop.py: the loop built here from the scene's blocks -- ZOH by mpmath.expm, the environment
realised entry by entry -- its spectral radius at 50 digits, the crossing by the Illinois method),
for scenes that record a defect of the certified crossing (tests/cli/scenes/). The scene file must
be exactly the text indep_loop.scene_toml writes for the case's model, so that both read one model.

  indep_scene_case.py HAPSTAB NAME SCENE
exit 0 when hapstab's certified supremum agrees with the reference (and its crossing is the one the
case names), else 1.
"""
import os
import sys
from fractions import Fraction as Q

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

import mpmath as mp  # noqa: E402

import indep_loop as IL  # noqa: E402
from indep_common import Rational, run_hapstab  # noqa: E402
from independent import TOL_SUP, compare_sup  # noqa: E402


def const(k):
    return Rational([Q(k)], [1])


T = Q(1, 1000)
CASES = {
    # issue 46: light devices (m/b = T/10, T/10) on a stiff coupled wall; the loop loses stability by
    # a real eigenvalue leaving through z = -1. decide_loop's Stein certificate is too ill-conditioned
    # near the crossing, and `--max g` answered "undecided: decide_loop could not confirm stability just
    # below the crossing" although its walk had certified [0, crossing).
    "zminus1_light_devices_2dof": (dict(
        T=T, devices=[dict(kind="md", m=Q(1, 10000), b=Q(1)), dict(kind="md", m=Q(1, 5000), b=Q(2))],
        ops=[(Q(1), Q(50)), (Q(1), Q(80))], E=[[const(2500), const(-500)], [const(-500), const(3500)]],
        n=0, tags={}, Knom=1.0), "z = -1"),
    # issue 46: mass-damper devices without an operator spring (each integrates its position: M(0) has
    # the eigenvalue 1 twice) under a coupled wall scaled by g. The walk towards 0 stopped at ~1e-6 of
    # the crossing: "sup g: undecided"; the first-order cover at g = 0 proves (0, eps].
    "integrator_devices_2dof": (dict(
        T=T, devices=[dict(kind="md", m=Q(1, 100), b=Q(1)), dict(kind="md", m=Q(1, 50), b=Q(2))],
        ops=[None, None], E=[[const(2500), const(-500)], [const(-500), const(3500)]],
        n=0, tags={}, Knom=1.0), "complex pair"),
    # issue 46 (scene_max seed 58 case 100): an open-loop unstable device beside a mass-damper
    # (integrating its position), a diagonal wall scaled by g. Near g = 64.5 two eigenvalues of M(g)
    # meet (a double real eigenvalue): Gershgorin in an eigenbasis fails there, and the Stein step
    # failed on the environment's ~10^4 entries beside the devices' ~10^-3 -- the walk towards 0
    # stopped at g = 64.5, a third of the supremum, "sup g: undecided". Balanced by powers of two
    # (loop_max.cpp, balance_by_powers_of_two), the same ball is certified.
    "double_eigenvalue_unstable_device_2dof": (dict(
        T=T, devices=[dict(kind="ss", A=Q(17, 10), Bv=Q(10, 9), passive=False), dict(kind="md", m=Q(1), b=Q(51, 25))],
        ops=[Q(29, 10), Q(3)],
        E=[[Rational([Q(44231, 5), Q(-8000)], [1, 0]), const(0)], [const(0), Rational([Q(5528), Q(-4950)], [1, 0])]],
        n=0, tags={}, Knom=1.0), "complex pair"),
    # issue 46 (scene_max seed 58 case 54): mass-dampers (position integrators: M(0) has the eigenvalue 1
    # twice) with operator dampers under a diagonal wall scaled by g, one sample of delay. The delay
    # register's defective eigenvalue 0 made the first-order cover's eigenbasis ill-conditioned (its
    # eps ~ 1e-16, below where the walk towards 0 reaches): "sup g: undecided" until the cover took an
    # orthonormal basis of range(M(0) - I) turned by Schur vectors, with a per-row (Perron) scaling.
    "delayed_integrator_devices_2dof": (dict(
        T=T, devices=[dict(kind="md", m=Q(1), b=Q(1, 2)), dict(kind="md", m=Q(19, 100), b=Q(9, 2))],
        ops=[Q(5, 2), Q(49, 10)],
        E=[[Rational([Q(10061), Q(-7200)], [1, 0]), const(0)], [const(0), Rational([Q(34083, 5), Q(-6500)], [1, 0])]],
        n=1, tags={}, Knom=1.0), "complex pair"),
}
REFERENCE_CROSSING = {"complex pair": "complex"}  # the reference's name for hapstab's


def main(argv):
    exe, name, path = argv[1], argv[2], argv[3]
    mp.mp.dps = 60  # as independent.py's main: comparisons of 20-digit enclosures
    c, crossing = CASES[name]
    text = open(path).read()
    body = text[text.index("\n[scene]") + 1:]  # the file's own comment above it explains the case
    if body != IL.scene_toml(c)[IL.scene_toml(c).index("[scene]"):]:
        print(f"{path}: not the text indep_loop.scene_toml writes for case {name}")
        return 1
    rc, j, err, _ = run_hapstab(exe, ["stability", "--scene", path, "--max", "g", "--digits", "20"], 120)
    ref = IL.sup_reference(IL.build_loop_scene(c), c["Knom"])
    out = compare_sup(dict(tags={}), ref, j, rc, TOL_SUP, "g")
    at = ((j or {}).get("crossing") or {}).get("at")
    print(f"{name}: {out['outcome']}; hapstab: exit {rc}, max {(j or {}).get('max')} at {at}; reference: "
          f"{ref.get('kind')} {ref.get('value')} ({ref.get('crossing')}) {out.get('why', '')}")
    if rc != 0 or (j or {}).get("status") != "certified":
        print(f"  expected a certified supremum (exit 0): {(j or {}).get('note', err)[:400]}")
        return 1
    return 0 if out["outcome"] == "agree" and at == crossing and ref.get("crossing") == REFERENCE_CROSSING.get(crossing, crossing) else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv))
