"""`stability --plant P --H H [--operator b] --certificate` for devices beyond the `stability` kind
(three poles off s = 0 or more: a mass-damper with motor and sensor lags, a second-order mode), whose
certificate is of kind stability-loop with the model as written: the checkers realise the device
G = s P_eff themselves (check/scene_model.hpp's read_scene_loop, checks/hapstab_check.py's
plant_loop_read) and decide their closed-loop matrix by the Stein inertia theorem. The reference
shares none of it: indep_loop.build_loop_1dof realises P itself (force -> position, controllable
canonical form in mpmath), holds it by mpmath.expm, realises H = B (z - 1)/(T z) + K and the delay's
shift register, and takes the spectral radius at 50 digits.

Drawn: m in [0.05, 2], b in [0.5, 5], two or three lags tau s + 1 (tau 1-50 ms), in a quarter a zero
c s + 1 (c < the largest tau, relative degree >= 2 kept), in a fifth a second integrator (P ~ 1/s^2),
in a quarter a spring k in [1, 1000] m instead (no pole at s = 0: the checkers integrate the position
themselves and set that conserved quantity of their own aside, the claim states none);
an operator damper b_o in a third (P_eff = P/(1 + s b_o P), computed here); K log-uniform in
[0.3 m, 10^4 m] (two digits), B 0-2; delays 0-3 samples. hapstab's verdict must be the
reference's, both checkers must verify its certificate and refute it with the claim flipped.

  indep_plant_loop_certificate.py HAPSTAB [--cases N] [--seed S]
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
from indep_common import Rational, cases_and_seed, fstr, loop_claim_flipped, pmul, poly_str  # noqa: E402

TOP = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def draw(rng):
    T = rng.choice([Q(1, 1000), Q(1, 500)])
    m, b = IL.rq(rng, 0.05, 2), IL.rq(rng, 0.5, 5)  # b > 0: the lags and -b/m make three poles off s = 0
    den = [m, b, Q(0)]  # s (m s + b), descending
    lags = [IL.rq(rng, 0.001, 0.05, den=(1000,)) for _ in range(rng.choice([2, 2, 3]))]
    for tau in lags:
        den = pmul(den, [tau, Q(1)])
    tags = {"lags": str(len(lags))}
    u = rng.random()
    if u < 0.2:
        den = pmul(den, [Q(1), Q(0)])
        tags["double integrator"] = True
    elif u < 0.45:  # a spring k: no pole at s = 0 (the checkers' own integrated position, set aside)
        k = IL.rq(rng, 1, 1000) * m
        den = [m, b, k]
        for tau in lags:
            den = pmul(den, [tau, Q(1)])
        tags["spring"] = True
    num = [Q(1)]
    if rng.random() < 0.25:
        zc = IL.rq(rng, 0.001, float(max(lags)), den=(1000,))
        num = [zc + (Q(1, 2000) if zc in lags else 0), Q(1)]  # never cancelling a lag (the stability kind's then)
        tags["zero"] = True
    bo = IL.rq(rng, 0.5, 5) if rng.random() < 0.33 else None
    tags["operator"] = bo is not None
    K = Q(float("%.2g" % (10 ** rng.uniform(-0.5, 4) * float(m)))).limit_denominator(100)  # log-uniform, 2 digits
    B = IL.rq(rng, 0, 2)
    n = rng.randint(0, 3)
    tags["delay"] = str(n)
    return dict(T=T, num=num, den=den, bo=bo, K=max(K, Q(1, 100)), B=B, n=n, tags=tags)


def reference_rho(c):
    """rho of the sampled loop at 50 digits, P_eff = N/(D + s b_o N) realised here."""
    num, den = c["num"], c["den"]
    if c["bo"] is not None:
        sN = num + [Q(0)]
        den = [x + (c["bo"] * sN[i - (len(den) - len(sN))] if i >= len(den) - len(sN) else 0) for i, x in enumerate(den)]
    T = c["T"]
    loop = IL.build_loop_1dof(dict(P=Rational(num, den), H0=Rational([c["B"], -c["B"]], [T, Q(0)]), H1=Rational([Q(1)], [Q(1)]),
                                   T=T, n=c["n"]))
    return IL.rho_mp(loop, mp.mpf(c["K"].numerator) / c["K"].denominator)[0]


def plant_options(c):
    """The drawn device, its operator, T and the delay as `stability` options (indep_plant_max_certificate too)."""
    a = ["--plant", "(%s)/(%s)" % (poly_str(c["num"], "s"), poly_str(c["den"], "s")), "--T", "%s" % c["T"], "--delay", str(c["n"])]
    if c["bo"] is not None:
        a += ["--operator", fstr(c["bo"])]
    return a


def args(c, cert):
    return (["stability"] + plant_options(c) +
            ["--H", "K + B*(z-1)/(T*z)", "--set", "K=%s" % c["K"], "--set", "B=%s" % c["B"], "--json", "--certificate", cert])


def run_case(exe, c, tmp):
    cert, bad = os.path.join(tmp, "c.json"), os.path.join(tmp, "b.json")
    if os.path.exists(cert):
        os.remove(cert)
    r = subprocess.run([exe] + args(c, cert), capture_output=True, text=True, timeout=600)
    with mp.workdps(IL.DPS):
        rr = reference_rho(c)
    what = "K = %s, rho %s" % (c["K"], mp.nstr(rr, 12))
    if abs(1 - rr) < mp.mpf(10) ** -30:
        return None, what + ": on the boundary (skipped)", None
    stable = rr < 1
    if r.returncode == 3 and not os.path.exists(cert):
        return None, what + ": undecided, no certificate", None
    if r.returncode == 2 and "no Stein certificate" in r.stderr:
        return None, what + ": no Stein certificate (refused by name)", None
    if r.returncode not in (0, 1) or not os.path.exists(cert):
        return False, "%s: exit %d: %s" % (what, r.returncode, r.stderr.strip()[:300]), None
    j, cl = json.loads(r.stdout), json.load(open(cert))
    if (j["stable"] != stable or cl["claim"]["stable"] != stable or cl["kind"] != "stability-loop"
            or cl["claim"].get("conserved", 0) != 0):
        return False, "%s: hapstab %s, its certificate %s (%s), the reference %s" % (what, j["stable"], cl["claim"]["stable"],
                                                                                   cl["kind"], stable), None
    with open(bad, "w") as f:
        json.dump(loop_claim_flipped(cl), f)
    checkers = ([exe, "check"], ["/usr/bin/python3", os.path.join(TOP, "checks", "hapstab_check.py")])
    for cmd in checkers:
        v = subprocess.run(cmd + [cert], capture_output=True, text=True, timeout=600)
        if v.returncode != 0:
            return False, "%s: %s exits %d: %s" % (what, os.path.basename(cmd[-1]), v.returncode, (v.stdout + v.stderr).strip()[:300]), None
        v = subprocess.run(cmd + [bad], capture_output=True, text=True, timeout=600)
        if v.returncode != 1:
            return False, "%s: the claim flipped: %s exits %d" % (what, os.path.basename(cmd[-1]), v.returncode), None
    branch = "stable" if stable else "NOT stable"
    return True, "%s: %s (%d states), verified by both, the flipped claim refuted by both" % (what, branch, len(cl["evidence"]["P"])), branch


def main(argv):
    exe = argv[1]
    cases, seed = cases_and_seed(argv)
    rng = random.Random("plant-loop-certificate:%d" % seed)
    good = bad = skipped = 0
    branches = {"stable": 0, "NOT stable": 0}
    tags = {"zero": 0, "double integrator": 0, "spring": 0, "operator": 0, "3 lags": 0, "delay > 0": 0}
    with tempfile.TemporaryDirectory(prefix="hapstab-plant-loop-") as tmp:
        for i in range(cases):
            c = draw(rng)
            ok, line, branch = run_case(exe, c, tmp)
            print("%s case %d (%s): %s" % ({True: "ok  ", False: "MISS", None: "skip"}[ok], i,
                                          ", ".join("%s %s" % kv for kv in c["tags"].items()), line))
            good += ok is True
            bad += ok is False
            skipped += ok is None
            if ok:
                branches[branch] += 1
                for key, hit in (("zero", c["tags"].get("zero")), ("double integrator", c["tags"].get("double integrator")),
                                 ("spring", c["tags"].get("spring")),
                                 ("operator", c["tags"]["operator"]), ("3 lags", c["tags"]["lags"] == "3"),
                                 ("delay > 0", c["n"] > 0)):
                    tags[key] += bool(hit)
    print("indep_plant_loop_certificate: %d cases, %d agree, %d disagree, %d skipped; %s; %s" % (
        cases, good, bad, skipped, ", ".join("'%s' %d" % kv for kv in branches.items()), ", ".join("%s %d" % kv for kv in tags.items())))
    if cases >= 12 and 0 in branches.values():
        print("indep_plant_loop_certificate: TOO FEW COMPARED: a verdict never reached")
        return 1
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
