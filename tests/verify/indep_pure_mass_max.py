"""`stability --scene S --max g` on loops of pure masses (b = 0: at g = 0 each DOF's position and velocity form a Jordan
block at z = 1, whose eigenvalues leave it like sqrt(g); since stop 78 the rational M(g) joins (0, a] exactly by the
resultant of lti/circle_crossing.hpp, certificate evidence no_crossing) against the whole loop built here
(tests/verify/indep_loop.py: the masses' ZOH in mpmath, each E entry realised, the delay's buffer; never hapstab or
its checkers).

Scenes: 2-4 masses (a mass-damper in 15 %: M then holds exponentials and the resultant does not apply), walls
K + B (z - 1)/(T z) with K drawn around B / ((n + 1) T) (0.1-1.5 of it: stable at small g about half the time -- a
delayed wall on a mass needs its damping to beat the stiffness's phase lag), springs linking neighbours in 40 %,
delays 0-3, the gain g on the environment. The reference's supremum: the spectral radius in double on 300 points
geometric in [10^-6, 10^4] of the scene's g, the first point with rho >= 1 bisected against the last below to
1e-13 relative; NOT stable at 10^-6: sup_ref = 0 -- decided exactly for pure masses (Schur-Cohn on the characteristic
polynomial of M built in fractions, indep_charpoly.py): a Jordan block's eigenvalues near g = 0 are 1 + O(g) in
modulus, below double precision's reach.

Required: a certified sup (exit 0) within 1e-6 (relative) of sup_ref, stable at sup 10^-k, k = 1..6 (the
stable interval reaches towards 0), and its certificate (--certificate) verified by both checkers, with
tests/check/loop_max_case.py's hand edits on every K-th (--mutants-every K) each given its exit code by both (the
independent checker's exit 3, beyond its stated size limit, counted apart);
sup = 0 (exit 1) only where the reference is unstable at 10^-6; undecided (exit 3) counted apart, never as an
answer; a certificate refused by name counted apart.

  indep_pure_mass_max.py HAPSTAB [--cases N] [--seed S] [--mutants-every K]
exit 0 when every compared case agrees, else 1."""
import json
import os
import random
import subprocess
import sys
from fractions import Fraction as Q

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import indep_charpoly as ICH  # noqa: E402
import indep_loop as IL  # noqa: E402
from indep_common import Rational, case_files, cases_and_seed, run_cases  # noqa: E402

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "check"))
from loop_max_case import mutants  # noqa: E402

CHECKER = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "checks", "hapstab_check.py")
STATE = {"every": 1, "certified": 0, "verified": 0, "mutants": 0}
T = Q(1, 1000)


def draw(rng):
    N = rng.randint(2, 4)
    n = rng.randint(0, 3)
    devices = [dict(kind="md", m=IL.rq(rng, 0.01, 0.5, den=(100, 200)), b=IL.rq(rng, 0.5, 3, den=(2, 4, 10)) if rng.random() < 0.15 else Q(0)) for _ in range(N)]
    Ks, Bs = [], []
    for _ in range(N):
        B = IL.rq(rng, 1, 8)
        Ks.append(max(Q(1), Q(round(B / ((n + 1) * T) * IL.rq(rng, 0.1, 1.5, den=(10, 20, 100)) * 10), 10)))
        Bs.append(B)
    kc = Q(round(min(Ks) * IL.rq(rng, 0.05, 0.4, den=(20, 100)) * 10), 10) if rng.random() < 0.4 else Q(0)
    E = [[Rational([0], [1]) for _ in range(N)] for _ in range(N)]
    for i in range(N):
        kk = Ks[i] + kc * ((1 if i > 0 else 0) + (1 if i < N - 1 else 0))
        E[i][i] = Rational([kk + Bs[i] / T, -Bs[i] / T], [1, 0])
        for j in (i - 1, i + 1):
            if 0 <= j < N and kc:
                E[i][j] = Rational([-kc], [1])
    rational = all(d["b"] == 0 for d in devices)
    return dict(T=T, devices=devices, ops=[None] * N, E=E, n=n, Knom=1.0,
                tags={"N": N, "delay": n, "links": bool(kc), "M rational": rational})


def stable_at(c, loop, g):
    """The loop's verdict at g: exact where M is rational (pure masses: indep_charpoly's M in fractions, its
    characteristic polynomial by Hessenberg, Schur-Cohn), else rho < 1 in double. Near g = 0 a Jordan block's
    eigenvalues are 1 + O(g) in modulus, below double precision's reach (seed 2 case 151: rho < 1 in double at
    g = 1e-6 where the loop is NOT stable, exactly)."""
    if c["tags"]["M rational"]:
        return ICH.schur_cohn(ICH.hessenberg_charpoly(ICH.exact_M(c, Q(g))))
    return IL.rho_np(loop, float(g)) < 1


def reference_sup(c, loop):
    """The first grid point with rho >= 1, bisected (in double); 0 when NOT stable at 1e-6 (stable_at)."""
    grid = np.geomspace(1e-6, 1e4, 300)
    if not stable_at(c, loop, Q(1, 10 ** 6)):
        return 0.0
    prev = grid[0]
    for g in grid[1:]:
        if IL.rho_np(loop, g) >= 1:
            a, b = prev, g
            while b - a > 1e-13 * b:
                c = (a + b) / 2
                a, b = (a, c) if IL.rho_np(loop, c) >= 1 else (c, b)
            return b
        prev = g
    return float("inf")


def both(exe, path):
    return (subprocess.run([exe, "check", path], capture_output=True).returncode,
            subprocess.run(["/usr/bin/python3", CHECKER, path], capture_output=True).returncode)


def run_case(exe, c, tmp):
    text = IL.scene_toml(c)
    scene, cert, bad = case_files(tmp, text)
    loop = IL.build_loop_scene(c)
    ref = reference_sup(c, loop)
    r = subprocess.run([exe, "stability", "--scene", scene, "--max", "g", "--json", "--certificate", cert], capture_output=True, text=True,
                       timeout=300)
    tags = "N %d, delay %d, links %s, %s" % (c["tags"]["N"], c["tags"]["delay"], c["tags"]["links"],
                                             "pure masses" if c["tags"]["M rational"] else "a mass-damper")
    if r.returncode == 2 and "--certificate" in r.stderr:  # the answer without its certificate
        r2 = subprocess.run([exe, "stability", "--scene", scene, "--max", "g", "--json"], capture_output=True, text=True, timeout=300)
        j = json.loads(r2.stdout) if r2.stdout.strip() else {}
        rc, refused = r2.returncode, True
    else:
        j = json.loads(r.stdout) if r.stdout.strip() else {}
        rc, refused = r.returncode, False
    if rc == 3:
        return None, "undecided (sup_ref %.6g; %s)" % (ref, tags), "undecided"
    if rc == 1:
        ok = ref == 0.0
        return ok, "sup = 0, reference %.6g (%s)" % (ref, tags), "sup = 0" if ok else None
    if rc != 0 or not j.get("max"):
        return False, "exit %d: %s" % (rc, (r.stderr or "")[-300:]), None
    sup = float(j["max"])
    if ref in (0.0, float("inf")) or abs(sup - ref) > 1e-6 * ref:
        return False, "sup = %.12g, reference %.12g (%s)" % (sup, ref, tags), None
    small = [stable_at(c, loop, Q(sup) / 10 ** k) for k in range(1, 7)]
    if not all(small):
        return False, "sup = %.12g, but the reference's rho >= 1 below it: %s (%s)" % (sup, small, tags), None
    branch = "certified" + (", (0, a] by the resultant" if j.get("no_crossing_to") else "")
    if refused:
        return True, "sup = %.12g, reference %.12g (%s; certificate refused by name)" % (sup, ref, tags), branch + ", certificate refused"
    STATE["certified"] += 1
    got = both(exe, cert)
    if got == (0, 3):  # beyond the independent checker's stated size limit: counted apart
        return True, "sup = %.12g, reference %.12g (%s; the independent checker's limit)" % (sup, ref, tags), branch + ", independent: beyond its limit"
    if got != (0, 0):
        return False, "sup = %.12g: its certificate hapstab check %d, independent %d" % ((sup,) + got), None
    STATE["verified"] += 1
    with open(cert) as f:
        cj = json.load(f)
    nc = "no_crossing" in cj["evidence"]
    if STATE["certified"] % STATE["every"] == 0:
        for what, m, want in mutants(cj, "g"):
            with open(bad, "w") as f:
                json.dump(m, f)
            e = both(exe, bad)
            if e[0] != e[1] or (e[0] not in (1, 2) if want is None else e[0] != want):
                return False, "mutant '%s': hapstab check %d, independent %d (want %s)" % ((what,) + e + (want,)), None
            STATE["mutants"] += 1
    return True, "sup = %.12g, reference %.12g (%s%s)" % (sup, ref, tags, "; no_crossing" if nc else ""), branch + (
        ", certificate by no_crossing" if nc else "")


def main(argv):
    exe = argv[1]
    cases, seed = cases_and_seed(argv, 6, 1)
    if "--mutants-every" in argv:
        STATE["every"] = int(argv[argv.index("--mutants-every") + 1])
    rng = random.Random("pure-mass-max:%d" % seed)
    counts, bad = run_cases(cases, lambda: draw(rng), lambda c, tmp: run_case(exe, c, tmp), "hapstab-pure-mass-")
    print("indep_pure_mass_max: %d cases, %d disagree; %s; %d certificates verified by both, %d mutants each given its exit code by both" % (
        cases, bad, "; ".join("%s %d" % kv for kv in sorted(counts.items())), STATE["verified"], STATE["mutants"]))
    if cases >= 6 and not any("no_crossing" in k for k in counts):
        print("indep_pure_mass_max: TOO FEW COMPARED: no supremum certified by no_crossing")
        return 1
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
