"""b* = +inf at a pole of H on the unit circle seen through a fractional delay (`bound --frac-delay
--certificate`, evidence pole_lo/pole_hi or pole_c and the side; check/bound_objective.hpp), against
paper 001's objective evaluated in mpmath at 50 digits, which shares no code with hapstab:
f(theta) = Re{T H(e^{j theta}) e^{-j theta tau}/(1 - e^{j theta})}, tau = n + p/q.

Drawn: H = K N(z)/((z^2 - 2 c z + 1) L(z)), c = cos theta_p a random rational in (-1, 1) (the pole
pair e^{+-j theta_p} on the circle), N of degree 0-2 with small integers, L = 1 or a stable real pole
z - a; K of either sign; T 1/1000 or 1/100; n = 0-2 whole samples and p/q, q = 2-7 (c_p =
cos(theta_p/q) irrational for most draws, rational for some); in 15 %, K/(z^2 + 1) behind tau = 1/2 or
5/2, where the real part cancels the pole (f = T K sin(theta (3/2 + tau))/(4 cos theta sin(theta/2))
is bounded at pi/2: b* finite, no +inf may be claimed). The reference: |f| at theta_p -+ 10^-12
and 10^-24 (it grows ~10^12-fold at a pole the real part keeps, stays bounded where it cancels), +inf
from the side where f grows positive. hapstab must print b* = +inf [exact] exactly when the
reference does, its certificate's side must be the reference's (c = cos(theta/q) above c_p is theta
below theta_p), both checkers must verify it and refute it with the side flipped.

  indep_bound_inf_inside.py HAPSTAB [--cases N] [--seed S]
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

from indep_common import both_checkers, cases_and_seed, fstr, pmul, poly_str  # noqa: E402

def bare(q):
    """A rational as an option value: "3", "-3/7" (no parentheses)."""
    return str(q.numerator) if q.denominator == 1 else "%d/%d" % (q.numerator, q.denominator)


def draw(rng):
    T = rng.choice([Q(1, 1000), Q(1, 100)])
    c = Q(rng.randint(-95, 95), 100)
    den = [Q(1), -2 * c, Q(1)]
    if rng.random() < 0.4:
        den = pmul(den, [Q(1), -Q(rng.randint(-8, 8), 10)])
    num = [Q(rng.randint(-3, 3)) for _ in range(rng.randint(1, 3))]
    if all(x == 0 for x in num):
        num = [Q(1)]
    while len(num) > 1 and num[0] == 0:
        num = num[1:]
    K = Q(rng.choice([-1, 1]) * rng.randint(1, 20), rng.choice([1, 2, 10]))
    q = rng.randint(2, 7)
    p = rng.randint(1, q - 1)
    if rng.random() < 0.15:  # K/(z^2 + 1) behind tau = 1/2 + 2k: f = T K sin(theta (3/2 + tau))/(4 cos theta sin(theta/2)) stays bounded
        return dict(T=T, c=Q(0), num=[Q(1)], den=[Q(1), Q(0), Q(1)], K=K, n=rng.choice([0, 2]), p=1, q=2)
    return dict(T=T, c=c, num=num, den=den, K=K, n=rng.randint(0, 2), p=p, q=q)


def reference(case):
    """(+inf?, side) from mpmath: side +1 when f -> +inf as theta rises to theta_p (c = cos(theta/q)
    falls to c_p from above), -1 from above theta_p; None when the real part keeps f bounded."""
    T, tau = mp.mpf(case["T"].numerator) / case["T"].denominator, case["n"] + mp.mpf(case["p"]) / case["q"]
    K = mp.mpf(case["K"].numerator) / case["K"].denominator

    def H(z):
        return K * mp.polyval([mp.mpf(x.numerator) / x.denominator for x in case["num"]], z) / \
            mp.polyval([mp.mpf(x.numerator) / x.denominator for x in case["den"]], z)

    def f(th):
        z = mp.expj(th)
        return mp.re(T * H(z) * mp.expj(-th * tau) / (1 - z))
    thp = mp.acos(mp.mpf(case["c"].numerator) / case["c"].denominator)
    below = [f(thp - d) for d in (mp.mpf(10) ** -12, mp.mpf(10) ** -24)]
    above = [f(thp + d) for d in (mp.mpf(10) ** -12, mp.mpf(10) ** -24)]
    grows = lambda v: abs(v[1]) > 1e9 * max(abs(v[0]), mp.mpf(10) ** -30)  # noqa: E731
    if not grows(below) and not grows(above):
        return None
    if grows(below) and below[1] > 0:
        return 1
    if grows(above) and above[1] > 0:
        return -1
    return 0  # -inf on both sides: not +inf at this pole


def main(argv):
    exe = argv[1]
    cases, seed = cases_and_seed(argv)
    rng = random.Random("bound-inf-inside:%d" % seed)
    agree = bad = 0
    branch = {"+inf side +1": 0, "+inf side -1": 0, "bounded": 0, "pole_lo (irrational)": 0, "pole_c (rational)": 0}
    with tempfile.TemporaryDirectory(prefix="hapstab-inf-inside-") as tmp:
        cert, flipped = os.path.join(tmp, "c.json"), os.path.join(tmp, "f.json")
        for i in range(cases):
            case = draw(rng)
            H = "K*(%s)/(%s)" % (poly_str(case["num"], "z"), poly_str(case["den"], "z"))
            td = Q(case["p"], case["q"]) * case["T"]
            args = [exe, "bound", "--H", H, "--set", "K=%s" % bare(case["K"]), "--T", bare(case["T"]), "--delay", str(case["n"]),
                    "--frac-delay", bare(td), "--json", "--certificate", cert]
            if os.path.exists(cert):
                os.remove(cert)
            r = subprocess.run(args, capture_output=True, text=True, timeout=300)
            with mp.workdps(50):
                ref = reference(case)
            what = "case %d: %s, T %s, n %d, t_d %s" % (i, H.replace("K", fstr(case["K"])), case["T"], case["n"], td)
            ok, line = True, ""
            inf = r.returncode in (0, 1) and json.loads(r.stdout).get("bound") == "inf"
            if ref in (1, -1):
                if not inf or not os.path.exists(cert):
                    ok, line = False, "the reference has +inf (side %d), hapstab exit %d: %s" % (ref, r.returncode, (r.stdout + r.stderr)[:200])
                else:
                    c = json.load(open(cert))
                    ev = c["evidence"]
                    if ev.get("side") != ref:
                        ok, line = False, "the certificate's side %s, the reference's %d (%s)" % (ev.get("side"), ref, ev)
                    else:
                        c["evidence"]["side"] = -ref
                        json.dump(c, open(flipped, "w"))
                        ok, line = both_checkers(exe, cert, flipped, "the side flipped")
                        if ok:
                            branch["+inf side %+d" % ref] += 1
                            branch["pole_lo (irrational)" if "pole_lo" in ev else "pole_c (rational)"] += 1
                            line = "+inf from side %+d (%s), verified by both, flipped refuted by both" % (ref, ",".join(sorted(ev)))
            elif ref is None:
                if inf:
                    ok, line = False, "the reference keeps f bounded at the pole, hapstab prints +inf"
                else:
                    branch["bounded"] += 1
                    line = "bounded at the pole (the real part cancels), hapstab finite"
            else:
                line = "-inf on both sides (not compared)"
            agree += ok
            bad += not ok
            print("%s %s: %s" % ("ok  " if ok else "MISS", what, line))
    print("indep_bound_inf_inside: %d cases, %d agree, %d disagree; %s" % (cases, agree, bad, ", ".join("%s %d" % kv for kv in branch.items())))
    if cases >= 12 and 0 in (branch["+inf side +1"], branch["+inf side -1"], branch["pole_lo (irrational)"], branch["bounded"]):
        print("indep_bound_inf_inside: TOO FEW COMPARED: a branch never reached")
        return 1
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
