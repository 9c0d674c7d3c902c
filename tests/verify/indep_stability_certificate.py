"""`stability --certificate` with a mass-damper device (one pole off s = 0: the sampled loop's
coefficients hold e^{-bT/m}, transcendental) or a spring (two poles off s = 0, real or complex: e^{A_c T}) against the loop built in mpmath (indep_loop.py: ZOH
by mpmath.expm, controller realised here, spectral radius at 50 digits; nothing from hapstab): for
each case hapstab's verdict and certificate claim must be the reference's, and both checkers
(`hapstab check`, checks/hapstab_check.py) must verify the certificate. Cases: fixed ones on both
sides of the boundary and within 1e-6 of it, a delay, an operator's mass, an open-loop unstable
device (b < 0), springs (1e-9 from the boundary, undamped, a double pole, an unstable real pole),
then random ones (seeded; a third of them springs).

  indep_stability_certificate.py HAPSTAB [--cases N] [--seed S]
exit 0 when every case agrees, else 1.
"""
import json
import os
import random
import subprocess
import sys
import tempfile
from fractions import Fraction as Q

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

import mpmath as mp  # noqa: E402

import indep_loop as IL  # noqa: E402
from indep_common import Rational, cases_and_seed  # noqa: E402

TOP = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def reference_rho(m, b, op_m, K, B, T, n, k=""):
    """rho of the loop: device 1/((m + op_m) s^2 + b s + k), wall K + B (z - 1)/(T z), z^-n."""
    P = Rational([Q(1)], [Q(m) + Q(op_m or 0), Q(b), Q(k or 0)])
    wall = Rational([Q(K) + Q(B) / Q(T), -Q(B) / Q(T)], [Q(1), Q(0)])
    c = {"P": P, "H0": wall, "H1": Rational([Q(0)], [Q(1)]), "T": Q(T), "n": n}
    loop = IL.build_loop_1dof(c)
    rho, _ = IL.rho_mp(loop, 0)
    return rho


def run_case(exe, m, b, op_m, K, B, T, n, tmp, k=""):
    cert = os.path.join(tmp, "c.json")
    if os.path.exists(cert):
        os.remove(cert)
    args = [exe, "stability", "--plant", "1/(m*s^2 + b*s + k)" if k else "1/(m*s^2 + b*s)", "--set", "m=%s" % m, "--set", "b=%s" % b,
            "--H", "K + B*(z-1)/(T*z)", "--set", "K=%s" % K, "--set", "B=%s" % B, "--T", str(T),
            "--delay", str(n), "--json", "--certificate", cert]
    if op_m:
        args += ["--operator", "%s*s" % op_m]
    if k:
        args += ["--set", "k=%s" % k]
    r = subprocess.run(args, capture_output=True, text=True, timeout=120)
    with mp.workdps(IL.DPS):
        rho = reference_rho(m, b, op_m, K, B, T, n, k)
        ref_stable = rho < 1
        margin = abs(1 - rho)
    what = "m=%s b=%s%s op_m=%s K=%s B=%s T=%s n=%d (rho %s)" % (m, b, " k=%s" % k if k else "", op_m, K, B, T, n, mp.nstr(rho, 12))
    if r.returncode not in (0, 1):
        return False, "%s: exit %d: %s" % (what, r.returncode, r.stderr.strip()[:300])
    j = json.loads(r.stdout)
    if j["stable"] != ref_stable or (r.returncode == 0) != ref_stable:
        return False, "%s: hapstab says stable=%s (exit %d), the reference %s" % (what, j["stable"], r.returncode, ref_stable)
    c = json.load(open(cert))
    if c["claim"]["stable"] != ref_stable:
        return False, "%s: the certificate claims stable=%s" % (what, c["claim"]["stable"])
    for checker in ([exe, "check", cert], ["/usr/bin/python3", os.path.join(TOP, "checks", "hapstab_check.py"), cert]):
        v = subprocess.run(checker, capture_output=True, text=True, timeout=300)
        if v.returncode != 0:
            return False, "%s: %s exits %d: %s" % (what, os.path.basename(checker[1]), v.returncode, (v.stdout + v.stderr).strip()[:300])
    return True, "%s: %s, verified by both (|1 - rho| = %s)" % (what, "stable" if ref_stable else "NOT stable", mp.nstr(margin, 3))


FIXED = [  # (m, b, operator mass, K, B, T, n)
    ("1", "1", "", "850", "2", "1/1000", 3),          # stable, |1 - rho| ~ 8e-6 (docs/commands.md's loop)
    ("1", "1/2", "", "850", "2", "1/1000", 3),        # NOT stable
    ("1", "1", "", "854", "2", "1/1000", 3),          # stable, 0.7 below sup K = 854.714...
    ("1", "1", "", "855", "2", "1/1000", 3),          # NOT stable, 0.3 above it
    ("1/10", "3", "1/20", "2000", "1", "1/1000", 1),  # an operator's mass
    ("1", "-1/10", "", "100", "1", "1/1000", 0),      # an open-loop unstable device (p = 1/10 > 0)
    ("1/2", "5", "", "20000", "5", "1/1000", 5),      # a stiff wall
]
SPRINGS = [  # (m, b, operator mass, K, B, T, n, k): two poles off s = 0, e^{A_c T} transcendental
    ("1", "1", "", "851879606/1000000", "2", "1/1000", 3, "1000"),  # stable, |1 - rho| = 1e-12 (sup K = 851.87960660815...)
    ("1", "1", "", "85188/100", "2", "1/1000", 3, "1000"),          # NOT stable, |1 - rho| = 7e-10
    ("1", "0", "", "500", "2", "1/1000", 1, "10000"),               # undamped: poles +-100j
    ("1", "1", "", "1000", "2", "1/1000", 0, "-100"),               # real poles, one unstable (open loop)
    ("1", "20", "", "300", "1", "1/1000", 2, "100"),                # a double pole at s = -10
    ("1/10", "3", "1/20", "2000", "1", "1/1000", 1, "5000"),        # an operator's mass
]


def main(argv):
    exe = argv[1]
    cases, seed = cases_and_seed(argv)
    rng = random.Random(seed)
    todo = list(FIXED) + list(SPRINGS)
    springs = random.Random("%d:spring" % seed)  # its own draws: the mass-damper cases of a seed stay as they were
    for _ in range(cases):
        todo.append((rng.choice(["1/10", "1/2", "1", "3"]), rng.choice(["1/5", "1", "2", "7/2"]), rng.choice(["", "1/10"]),
                     str(rng.randint(1, 4000)), rng.choice(["0", "1", "2", "5"]), rng.choice(["1/1000", "1/500"]),
                     rng.randint(0, 6), springs.choice(["", "", "100", "1000", "-50", "10000"])))
    bad = 0
    stable = 0
    with tempfile.TemporaryDirectory(prefix="hapstab-stab-cert-") as tmp:
        for case in todo:
            ok, line = run_case(exe, *case[:7], tmp, *case[7:])
            print(("ok   " if ok else "MISS ") + line)
            bad += not ok
            stable += ok and ": stable," in line
    print("indep_stability_certificate: %d cases, %d disagree (%d stable, %d NOT stable among those that agree)" % (
        len(todo), bad, stable, len(todo) - bad - stable))
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
