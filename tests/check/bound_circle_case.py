"""b* = +inf at a simple pole of H on the unit circle inside the band (0 < wT < pi), beyond the exact path's size,
where the long-delay path does not go: `bound` decides it at the pole (passivity/circle_pole.cpp, path at_pole) and
writes the circle form (evidence.pole_on_circle = {q, c_lo, c_hi}; check/bound_check.hpp). Before, every such case
exited 2, "no path takes this case".

The reference shares no code and no formula with either: the poles of D by mpmath.polyroots at 60 digits, and at
each one on the circle inside the band the objective of (45)/(54) as written, f(theta) = Re{T H(e^{j theta})
e^{-j nu theta}/(1 - e^{j theta})}, at theta0 +- 10^-15 and +- 10^-20 in mpmath: s = f(theta0 + d) d tends to the
same nonzero constant from both sides (d of either sign) when the pole's term does not vanish, so f -> +inf on the
side where d s > 0. Where it tends to 0 on both sides (the term vanishes: H = (z - 1)/(z^2 + 1) at an even delay), `bound`
must not claim +inf (it refuses by name beyond the exact path). Each +inf certificate is verified by both checkers
and its hand edits get their exit codes from both (1 refuted, 2 malformed).

  bound_circle_case.py HAPSTAB [--models N] [--seed S]
exit 0 when every expectation holds, else 1 (each failure printed)."""
import argparse
import json
import os
import random
import subprocess
import sys
import tempfile
from fractions import Fraction

import mpmath as mp

from cert_edit import deleted, with_field
from loop_max_case import run_cases

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "verify"))
from indep_common import pmul  # noqa: E402 (the references' polynomial product)

# H's factors on the circle (ascending coefficients; palindromic), their poles inside the band
CIRCLE = [("z^2 + 1 (theta0 = pi/2)", [1, 0, 1]),
          ("z^2 - z + 1 (pi/3)", [1, -1, 1]),
          ("z^2 + z/3 + 1 (an irrational angle, rational cos)", [1, Fraction(1, 3), 1]),
          ("z^4 + 1 (pi/4 and 3 pi/4: cos irrational)", [1, 0, 0, 0, 1]),
          ("z^4 + z^3 + z^2 + z + 1 (2 pi/5 and 4 pi/5)", [1, 1, 1, 1, 1])]


def poly_text(p, var="z"):
    return " + ".join("(%s)*%s^%d" % (Fraction(c), var, k) for k, c in enumerate(p) if c != 0) or "0"


def draw(rng):
    """(label, H text, numerator, denominator, T, n, t_d): a circle factor, times a stable root in half the
    cases, over a random numerator of lower degree; n = 250-5000, a fractional delay in half."""
    name, C = rng.choice(CIRCLE)
    D = [Fraction(c) for c in C]
    if rng.random() < 0.5:
        D = pmul(D, [Fraction(-rng.randint(-8, 8), 10), 1])  # a root in (-0.8, 0.8)
    N = [Fraction(rng.randint(-9, 9), rng.choice([1, 2, 5, 10])) for _ in range(len(D) - 1)]
    if not any(N):
        N[0] = Fraction(1)
    T = Fraction(1, rng.choice([1, 100, 1000]))
    n = rng.randint(250, 5000)
    td = Fraction(rng.randint(1, 9), 10) * T if rng.random() < 0.5 else None
    return name, "(%s)/(%s)" % (poly_text(N), poly_text(D)), N, D, T, n, td


def reference(N, D, T, nu):
    """'+inf' when the objective tends to +inf at a pole on the circle inside the band, 'vanishes' when at every
    such pole f (theta - theta0) tends to 0 on both sides (the leading term vanishes: undecided here), and
    'none' without such a pole."""
    with mp.workdps(60):
        def H(z):
            return mp.polyval([mp.mpf(c.numerator) / c.denominator for c in reversed(N)], z) / \
                mp.polyval([mp.mpf(c.numerator) / c.denominator for c in reversed(D)], z)

        def f(th):
            z = mp.expj(th)
            return mp.re(mp.mpf(T.numerator) / T.denominator * H(z) * mp.expj(-nu * th) / (1 - z))
        out = "none"
        for r in mp.polyroots([mp.mpf(c.numerator) / c.denominator for c in reversed(D)], maxsteps=200, extraprec=200):
            th0 = mp.arg(r)
            if abs(abs(r) - 1) > mp.mpf(10) ** -40 or not mp.mpf(10) ** -30 < th0 < mp.pi - mp.mpf(10) ** -30:
                continue
            s = {d: [f(th0 + side * d) * side * d for side in (1, -1)] for d in (mp.mpf(10) ** -15, mp.mpf(10) ** -20)}
            a, b = s[mp.mpf(10) ** -15], s[mp.mpf(10) ** -20]
            scale = 1 + abs(a[0]) + abs(a[1])
            if max(abs(v) for v in a + b) < mp.mpf(10) ** -12 * scale:
                out = "vanishes" if out == "none" else out
                continue
            # f = s/(theta - theta0) near theta0 with s the same on both sides: +inf on one side, whatever its sign
            if all(abs(x / y - 1) < mp.mpf(10) ** -3 for x, y in zip(a, b)) and abs(b[0] / b[1] - 1) < mp.mpf(10) ** -3:
                return "+inf"
            return "undecided"
        return out


def produce(hapstab, tmp, H, T, n, td):
    path = os.path.join(tmp, "c.json")
    if os.path.exists(path):
        os.remove(path)
    args = [hapstab, "bound", "--H", H, "--T", str(T), "--delay", str(n), "--json", "--certificate", path]
    if td is not None:
        args += ["--frac-delay", str(td)]
    r = subprocess.run(args, capture_output=True, text=True, timeout=60)
    return r, (json.load(open(path)) if os.path.exists(path) else None)


def edits(c):
    ev = c["evidence"]["pole_on_circle"]
    q = ev["q"]
    lo = Fraction(ev["c_lo"])
    far = "-999/1000" if lo > 0 else "999/1000"  # an interval holding no root of q (near the band's ends)
    return [("unmutated", c, 0),
            ("c_lo and c_hi moved to %s" % far, with_field(with_field(c, ["evidence", "pole_on_circle", "c_lo"], far),
                                                           ["evidence", "pole_on_circle", "c_hi"], far), 1),
            ("c_hi = 1 (the band's end)", with_field(with_field(c, ["evidence", "pole_on_circle", "c_lo"], str(min(lo, Fraction(1, 2)))),
                                                     ["evidence", "pole_on_circle", "c_hi"], "1"), 1),
            ("q times (c - 2) (its Z no factor of D)", with_field(c, ["evidence", "pole_on_circle", "q"],
                                                                  [str(x) for x in pmul([Fraction(v) for v in q], [-2, 1])]), 1),
            ("the status exact", with_field(c, ["claim", "status"], "exact"), 2),
            ("q missing", deleted(c, ["evidence", "pole_on_circle", "q"]), 2),
            ("q a constant", with_field(c, ["evidence", "pole_on_circle", "q"], ["1", "0"]), 2),
            ("pole_at_z beside it", with_field(c, ["evidence", "pole_at_z"], "-1"), 2)]


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("hapstab")
    ap.add_argument("--models", type=int, default=40)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--edits-every", type=int, default=5, help="hand edits on every K-th +inf certificate")
    a = ap.parse_args()
    failures, counts, cases = 0, {}, []
    with tempfile.TemporaryDirectory() as tmp:
        # the term vanishes: (z - 1)/(z^2 + 1) at an even delay, (z + 1)/(z^2 + 1) at an odd one (refused by name);
        # (z - 1)/(z^2 + 1) at an odd delay +inf, and its delay edited by a sample (the term then 0) refuted by both
        fixed = [("(z - 1)/(z^2 + 1), n = 600 (the term vanishes)", "(z-1)/(z^2+1)", [-1, 1], [1, 0, 1], Fraction(1), 600, None),
                 ("(z - 1)/(z^2 + 1), n = 601", "(z-1)/(z^2+1)", [-1, 1], [1, 0, 1], Fraction(1), 601, None),
                 ("(z + 1)/(z^2 + 1), n = 601 (the term vanishes)", "(z+1)/(z^2+1)", [1, 1], [1, 0, 1], Fraction(1, 1000), 601, None)]
        rng = random.Random("%d:bound_circle" % a.seed)
        models = fixed + [draw(rng) for _ in range(a.models)]
        for k, (name, H, N, D, T, n, td) in enumerate(models):
            nu = n + (td / T if td is not None else 0)
            ref = reference([Fraction(x) for x in N], [Fraction(x) for x in D], T, mp.mpf(nu.numerator) / nu.denominator)
            r, c = produce(a.hapstab, tmp, H, T, n, td)
            got = json.loads(r.stdout) if r.returncode == 0 else None
            inf = got is not None and got["bound"] == "inf" and got["status"] == "certified" and got["path"] == "at_pole"
            if ref == "+inf":
                ok = inf and c is not None and "pole_on_circle" in c["evidence"]
            elif ref == "vanishes":
                ok = r.returncode == 2 and "not shown nonzero" in r.stderr
            else:
                ok = False
            key = "%s -> %s" % (ref, "+inf" if inf else "exit %d" % r.returncode)
            counts[key] = counts.get(key, 0) + 1
            if not ok:
                failures += 1
                print("FAIL %s: H = %s, T = %s, n = %d, t_d = %s: reference %s, hapstab exit %d %s" % (
                    name, H, T, n, td, ref, r.returncode, (r.stdout + r.stderr).strip()[:300]))
                continue
            if c is None:
                continue
            want_edits = k < len(fixed) or k % a.edits_every == 0
            cases += [("%s (n = %d): %s" % (name, n, what), e, want) for what, e, want in (edits(c) if want_edits else [("unmutated", c, 0)])]
            if k == 1:
                cases.append(("(z - 1)/(z^2 + 1): the delay a sample more (the term 0)", with_field(c, ["model", "delay"], 602), 1))
        failures += run_cases(a.hapstab, cases, tmp)
    print("bound_circle_case: %d models (%s), %d certificate checks, %d failed" % (
        len(models), ", ".join("%s %d" % kv for kv in sorted(counts.items())), len(cases), failures))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
