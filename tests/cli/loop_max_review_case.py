"""`stability --scene S --max NAME` on what stop 78's review found, each against the whole loop built in numpy/scipy
from the scene's numbers (tests/verify/indep_loop.py: the devices' ZOH in mpmath, E realised entry by entry, the
delay's buffer; its spectral radius scanned on a geometric grid and bisected), no code shared with hapstab:
  * tests/cli/scenes/loop_max_parameter_zero.toml: [parameters] Kx = "0" with Kx inside one wall (three DOFs alike
    only at 0): a certified crossing, within 1e-7 of the reference (was: the split's block without Kx made it "not
    affine", bisection, undecided);
  * tests/cli/scenes/loop_max_one_way_link.toml: a one-way link of 1000: sup g certified, within 1e-7 of the
    reference; with --certificate refused by name (exit 2, the cover search's work limit), no file (was: minutes);
  * a parameter the loop does not read (rnd1_23 of the review, written below): "NOT stable at every value tried",
    exit 1, JSON status "certified" (it said "undecided" beside exit 1), and the reference's rho > 1;
  * tests/cli/scenes/loop_max_pure_masses.toml: two pure masses (a Jordan block at z = 1 at g = 0, "undecided"
    before): sup g certified by the resultant on (0, a] (lti/circle_crossing.hpp), within 1e-7 of the reference, and
    the loop stable at g = 10^-k, k = 1..8, by exact Schur-Cohn on M built in fractions (indep_charpoly.py; in double
    a Jordan block's 1 + O(g) is noise);
  * a hidden mode z = g of the environment (stop 79): sup g = 1, one DOF and two (it said "sup g = 0 [exact]" from
    the mode's instability at the scene's g = 2);
  * tests/cli/scenes/loop_max_walk_to_zero.toml: two mass-dampers under operators b + k/s, walls delayed by z^-2 and a
    coupling (the conservatism campaign's case 2027): M(0) Schur stable, but the walk towards 0 stopped at 0.0038
    after its 400 steps ("undecided", stop 80); sup g certified, stable from 0 (one Lyapunov P for [0, down]), within
    1e-7 of the reference built in numpy from the scene (tests/verify/indep_coupled.py), which is stable at 10^-k,
    k = 2..8.

  loop_max_review_case.py HAPSTAB
exit 0 when every expectation holds, else 1."""
import json
import os
import subprocess
import sys
import tempfile
from fractions import Fraction as Q

import numpy as np

TOP = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")
sys.path.insert(0, os.path.join(TOP, "tests", "verify"))
import indep_charpoly as ICH  # noqa: E402
import indep_coupled as ICP  # noqa: E402
import indep_loop as IL  # noqa: E402
from indep_common import Rational  # noqa: E402

T = Q(1, 1000)


def wall(K, B):
    """K + B (z - 1)/(T z) as a Rational in z."""
    return Rational([K + B / T, -B / T], [1, 0])


def const(k):
    return Rational([k], [1])


def sup_reference(rho, lo, hi):
    """The first p of a geometric grid on [lo, hi] with rho(p) >= 1, bisected to 1e-13 relative against the last
    below; every grid point below it stable."""
    grid = np.geomspace(lo, hi, 400)
    prev = None
    for p in grid:
        if rho(p) >= 1:
            a, b = prev, p
            while (b - a) > 1e-13 * b:
                c = (a + b) / 2
                a, b = (a, c) if rho(c) >= 1 else (c, b)
            return b
        prev = p
    return None


def run(hapstab, args, timeout=120):
    r = subprocess.run([hapstab, "stability"] + args, capture_output=True, text=True, timeout=timeout)
    try:
        j = json.loads(r.stdout)
    except ValueError:
        j = None
    return r.returncode, j, r.stderr


def main():
    hapstab = sys.argv[1]
    failures = 0

    def expect(what, ok):
        nonlocal failures
        failures += not ok
        print("%s %s" % ("ok  " if ok else "FAIL", what))
    scenes = os.path.join(TOP, "tests", "cli", "scenes")

    # 1. Kx = 0 in [parameters]
    md = [dict(kind="md", m=Q(1), b=Q(2)) for _ in range(3)]

    def loop_kx(kx):
        E = [[wall(200 + (kx if i == 0 else 0), Q(1, 2)) if i == j else const(-50) for j in range(3)] for i in range(3)]
        return IL.build_loop_scene(dict(T=T, devices=md, ops=[None] * 3, E=E, n=1))
    ref = sup_reference(lambda kx: IL.rho_np(loop_kx(Q(kx)), 1.0), 1.0, 1e5)
    rc, j, err = run(hapstab, ["--scene", os.path.join(scenes, "loop_max_parameter_zero.toml"), "--max", "Kx", "--json"])
    got = float(j["max"]) if j and j.get("max") else None
    expect("Kx = 0 in the scene: exit 0 (got %s), path %s, sup %s against the reference %.13g" % (rc, j and j.get("path"), got, ref),
           rc == 0 and j.get("path") == "closed_loop_matrix" and j.get("status") == "certified" and abs(got - ref) <= 1e-7 * ref)

    # 2. the one-way link: the answer, and the certificate refused within the work limit
    dev2 = [dict(kind="md", m=Q(1), b=Q(1)), dict(kind="md", m=Q(2), b=Q(3))]
    E2 = [[wall(Q(10), Q(1)), const(1000)], [const(0), wall(Q(10), Q(1))]]
    loop2 = IL.build_loop_scene(dict(T=T, devices=dev2, ops=[None] * 2, E=E2, n=0))
    ref2 = sup_reference(lambda g: IL.rho_np(loop2, g), 1e-3, 1e6)
    path = os.path.join(scenes, "loop_max_one_way_link.toml")
    rc, j, err = run(hapstab, ["--scene", path, "--max", "g", "--json"])
    got = float(j["max"]) if j and j.get("max") else None
    expect("one-way link: exit 0 (got %s), sup %s against the reference %.13g" % (rc, got, ref2),
           rc == 0 and j.get("status") == "certified" and abs(got - ref2) <= 1e-7 * ref2)
    with tempfile.TemporaryDirectory() as tmp:
        cert = os.path.join(tmp, "c.json")
        rc, j, err = run(hapstab, ["--scene", path, "--max", "g", "--certificate", cert, "--quiet"])
        expect("one-way link with --certificate: exit 2 naming the work limit, no file (got %s: %s)" % (rc, err.strip()[-160:]),
               rc == 2 and "work limit" in err and not os.path.exists(cert))

        # 3. a parameter the loop does not read
        text = ('[scene]\nname = "Kx unread"\nT = "1/1000"\n\n[parameters]\nKx = "100"\n\n[[device]]\nname = "d0"\n'
                'ss = { A = [["1/2"]], B = [["1"]], C = [["1"]], D = [["0"]] }\npassive = false\n\n[[device]]\nname = "d1"\n'
                'm = "1/10"\nb = "0"\n\n[environment]\ntf = [["(2000) + (1)*(z-1)/(T*z)", "(-100)"], ["(-100)", "(-100)"]]\n\n'
                '[delay]\nsamples = "2"\n')
        scene = os.path.join(tmp, "unread.toml")
        with open(scene, "w") as f:
            f.write(text)
        dev3 = [dict(kind="ss", A=Q(1, 2), Bv=Q(1), passive=False, m=Q(1)), dict(kind="md", m=Q(1, 10), b=Q(0))]
        E3 = [[wall(Q(2000), Q(1)), const(-100)], [const(-100), const(-100)]]
        r3 = IL.rho_np(IL.build_loop_scene(dict(T=T, devices=dev3, ops=[None] * 2, E=E3, n=2)), 1.0)
        rc, j, err = run(hapstab, ["--scene", scene, "--max", "Kx", "--json"])
        expect("Kx unread: exit 1 (got %s), status %s, path %s; the reference's rho %.6g > 1" % (rc, j and j.get("status"), j and j.get("path"), r3),
               rc == 1 and j.get("status") == "certified" and j.get("path") == "bisection_on_verdicts" and r3 > 1)
    # 4. pure masses
    pm = [dict(kind="md", m=Q(1, 100), b=Q(0)), dict(kind="md", m=Q(1, 50), b=Q(0))]
    E4 = [[wall(Q(2500), Q(5)), const(-500)], [const(-500), wall(Q(3500), Q(8))]]
    loop4 = IL.build_loop_scene(dict(T=T, devices=pm, ops=[None] * 2, E=E4, n=0))
    ref4 = sup_reference(lambda g: IL.rho_np(loop4, g), 1e-3, 1e4)
    # near g = 0 a Jordan block's eigenvalues are 1 + O(g) in modulus, below double precision: decided exactly (M in
    # fractions, Hessenberg, Schur-Cohn: indep_charpoly.py)
    c4 = dict(T=T, devices=pm, ops=[None] * 2, E=E4, n=0)
    small = [ICH.schur_cohn(ICH.hessenberg_charpoly(ICH.exact_M(c4, Q(1, 10 ** k)))) for k in range(1, 9)]
    rc, j, err = run(hapstab, ["--scene", os.path.join(scenes, "loop_max_pure_masses.toml"), "--max", "g", "--json"])
    got = float(j["max"]) if j and j.get("max") else None
    expect("pure masses: exit 0 (got %s), sup %s against the reference %.13g; stable (exactly) at 1e-1..1e-8: %s" % (
        rc, got, ref4, all(small)),
        rc == 0 and j.get("status") == "certified" and abs(got - ref4) <= 1e-7 * ref4 and all(small))
    # 5. a hidden mode the parameter moves (stop 79): the environment's state x1(k + 1) = g x1(k) is fed and read by
    # nothing (uncontrollable and unobservable), so the loop as written has the eigenvalue z = g beside the loop with
    # E = 100 I, which g does not enter: sup g = 1 exactly (by hand; the rest's rho by numpy below). It said
    # "sup g = 0 [exact]" from the unstable hidden mode at the scene's g = 2, on one DOF and on two.
    with tempfile.TemporaryDirectory() as tmp:
        for dofs in (1, 2):
            devs = "".join('[[device]]\nname = "d%d"\nm = "1"\nb = "%d"\n' % (i, 2 + i) for i in range(dofs))
            if dofs == 1:
                env = 'ss = { A = [["g"]], B = [["0"]], C = [["0"]], D = [["100"]] }'
            else:
                env = 'ss = { A = [["g", "0"], ["0", "0"]], B = [["0", "0"], ["1", "0"]], C = [["0", "0"], ["0", "0"]], ' \
                      'D = [["100", "0"], ["0", "100"]] }'
            scene = os.path.join(tmp, "hidden%d.toml" % dofs)
            with open(scene, "w") as f:
                f.write('[scene]\nname = "a hidden mode z = g"\nT = "1/1000"\n[parameters]\ng = "2"\n%s[environment]\n%s\n' % (devs, env))
            rest = IL.build_loop_scene(dict(T=T, devices=[dict(kind="md", m=Q(1), b=Q(2 + i)) for i in range(dofs)],
                                            ops=[None] * dofs, E=[[const(100) if i == j else const(0) for j in range(dofs)]
                                                                  for i in range(dofs)], n=0))
            r5 = IL.rho_np(rest, 1.0)
            rc, j, err = run(hapstab, ["--scene", scene, "--max", "g", "--json"])
            lo, hi = (float(j["enclosure"][0]), float(j["enclosure"][1])) if j and j.get("enclosure") else (None, None)
            expect("a hidden mode z = g, %d DOF: exit 0 (got %s), sup g = 1 inside [%s, %s] (the rest's rho %.6f < 1), not 0 [exact]" % (
                dofs, rc, lo, hi, r5), rc == 0 and j.get("max") != "0" and lo is not None and lo <= 1 <= hi and r5 < 1)
    # 6. the walk towards 0 on a long stable run: the reference is the scene read as indep_coupled builds it
    import random
    c6 = ICP.gen_coupled(random.Random("46:conservatism:2027"), conservatism=True)
    path6 = os.path.join(scenes, "loop_max_walk_to_zero.toml")
    with open(path6) as f:
        same = ICP.scene_toml(c6, "1").split("\n", 1)[1] in f.read()
    loop6 = ICP.CoupledLoop(c6)
    ref6 = sup_reference(lambda g: ICP.rho_np(loop6, g), 1e-8, 10.0)
    small6 = [ICP.rho_np(loop6, 10.0 ** -k) < 1 for k in range(2, 9)]
    rc, j, err = run(hapstab, ["--scene", path6, "--max", "g", "--json"])
    got = float(j["max"]) if j and j.get("max") else None
    expect("walk to 0 (the scene is the campaign's: %s): exit 0 (got %s), stable from 0, sup %s against the reference %.13g; "
           "the reference stable at 1e-2..1e-8: %s" % (same, rc, got, ref6, all(small6)),
           same and rc == 0 and j.get("status") == "certified" and j.get("stable_from") is None and got is not None
           and abs(got - ref6) <= 1e-7 * ref6 and all(small6))
    print("loop_max_review_case: %d failed" % failures)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
