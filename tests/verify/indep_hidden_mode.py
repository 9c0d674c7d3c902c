"""`stability --scene S --certificate` on loops whose blocks hide modes (issue 47: the hidden-mode
certificate, check/stability_loop_check.hpp's evidence.hidden) against the loop built here in mpmath
from the numbers drawn, hidden states and all, and its eigenvalues at 50 digits -- never from the
scene's text, hapstab's reading of it, or either checker.

Each case is one DOF: a mass-damper m, b (or an ss device with two more states that its force does not
reach: an oscillator s = +-jw, a growing pair +-w, or a damped pair), a wall E = K + B (z - 1)/(T z), and
in most cases an ss coupling in parallel (paper 000 (11)) with one state h (or a rotation pair on the
circle) that its input does not reach or its output does not show: h = -1, 3/2, -11/10 (not stable),
1/2 (stable), 1 (a semisimple z = 1: it settles). The reference builds the period map X+ = M X on X =
[v, x, device states; eta; xi] (the hold by Van Loan's exponential, the force solved from x_e = x + C_V
eta + D_V u exactly as the numbers say) and calls the loop NOT stable when M has an eigenvalue mu with
|mu| >= 1 - 1e-40 and |mu - 1| > 1e-30 (an eigenvalue 1 settles), stable otherwise.

Required: hapstab's verdict (`stability --scene`) is the reference's (undecided is counted apart, never
as agreement); with --certificate it writes one that both checkers verify -- and where it is a hidden
mode's, its A_h moved by 1/10 is refuted by both -- or refuses by name (exit 2: a stable loop whose
coupling hides a settling z = 1 has no certificate form yet).

  indep_hidden_mode.py HAPSTAB [--cases N] [--seed S]
exit 0 when every decided case agrees, else 1.
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

from indep_common import both_checkers, cases_and_seed  # noqa: E402
from indep_loop import zoh  # noqa: E402

DPS = 50


def s(q):
    q = Q(q)
    return str(q.numerator) if q.denominator == 1 else "%d/%d" % (q.numerator, q.denominator)


def draw(rng):
    c = dict(m=rng.choice(["1/10", "1/2", "1"]), b=rng.choice(["1", "5", "30"]), K=rng.choice(["200", "2000", "20000"]),
             B=rng.choice(["0", "2", "5"]), T=rng.choice(["1/1000", "1/500"]))
    c["device"] = rng.choice(["md", "md", "oscillator", "growing", "damped"])
    c["w2"] = rng.choice(["1", "4", "9"])
    c["coupling"] = rng.choice(["none", "uncontrollable", "unobservable", "uncontrollable", "unobservable"])
    c["h"] = rng.choice(["-1", "3/2", "-11/10", "1/2", "1", "pair"])
    c["kc"] = rng.choice(["500", "2000", "8000"])
    return c


def scene(c):
    L = ["[scene]", 'T = "%s"' % c["T"], "[[device]]", 'name = "d"']
    if c["device"] == "md":
        L += ['m = "%s"' % c["m"], 'b = "%s"' % c["b"]]
    else:
        a21, a22 = {"oscillator": ("-" + c["w2"], "0"), "growing": (c["w2"], "0"), "damped": ("-" + c["w2"], "-1")}[c["device"]]
        L += ['ss = { A = [["-(%s)/(%s)", "0", "0"], ["0", "0", "1"], ["0", "%s", "%s"]], B = [["1/(%s)"], ["0"], ["0"]], '
              'C = [["1", "0", "0"]], D = [["0"]] }' % (c["b"], c["m"], a21, a22, c["m"]), "passive = false"]
    L += ["[environment]", 'tf = "%s + %s*(z-1)/(T*z)"' % (c["K"], c["B"])]
    if c["coupling"] != "none":
        A, B, C = coupling(c)
        q = lambda M: "[" + ", ".join("[" + ", ".join('"%s"' % s(x) for x in row) + "]" for row in M) + "]"  # noqa: E731
        L += ["[coupling]", 'ss = { A = %s, B = %s, C = %s, D = [["1/%s"]] }' % (q(A), q(B), q(C), c["kc"])]
    return "\n".join(L) + "\n"


def coupling(c):
    """The ss coupling's A, B, C (rationals): a state (or pair) its input does not reach, or its output
    does not show, beside a compliance D = 1/kc."""
    A = [[Q(3, 5), Q(-4, 5)], [Q(4, 5), Q(3, 5)]] if c["h"] == "pair" else [[Q(c["h"])]]
    r = len(A)
    if c["coupling"] == "uncontrollable":
        return A, [[Q(0)] for _ in range(r)], [[Q(1, 10000)] * r]
    return A, [[Q(1, 10000)] for _ in range(r)], [[Q(0)] * r]


def reference(c):
    """"NOT stable" or "stable": the eigenvalues of the period map built here, at 50 digits."""
    with mp.workdps(DPS):
        f = lambda q: mp.mpf(Q(q).numerator) / Q(q).denominator  # noqa: E731
        m, b, T = f(c["m"]), f(c["b"]), f(c["T"])
        # plant: [v, x] or [xi_1, xi_2, xi_3, x]; force in, position out
        if c["device"] == "md":
            A = mp.matrix([[-b / m, 0], [1, 0]])
            Bp = mp.matrix([[1 / m], [0]])
        else:
            a21, a22 = {"oscillator": (-f(c["w2"]), 0), "growing": (f(c["w2"]), 0), "damped": (-f(c["w2"]), -1)}[c["device"]]
            A = mp.matrix([[-b / m, 0, 0, 0], [0, 0, 1, 0], [0, a21, a22, 0], [1, 0, 0, 0]])
            Bp = mp.matrix([[1 / m], [0], [0], [0]])
        n = A.rows
        Phi, Gam = zoh(A, Bp, T)
        Kw, Bw = f(c["K"]), f(c["B"])
        k0, k1 = Kw + Bw / T, -Bw / T  # E = k0 + k1 z^-1: force = k0 x_e + k1 xi, xi+ = x_e
        if c["coupling"] != "none":
            Av, Bv, Cv = ([[f(x) for x in row] for row in M] for M in coupling(c))
            Dv = 1 / f(c["kc"])
        else:
            Av, Bv, Cv, Dv = [], [], [[]], 0
        r = len(Av)
        N = n + r + 1
        # u = -(k0 x_e + k1 xi), x_e = x + Cv eta + Dv u  =>  u (1 + k0 Dv) = -(k0 (x + Cv eta) + k1 xi)
        den = 1 + k0 * Dv
        urow = [mp.mpf(0)] * N  # u as a row over X = [plant; eta; xi]
        urow[n - 1] = -k0 / den
        for j in range(r):
            urow[n + j] = -k0 * Cv[0][j] / den
        urow[N - 1] = -k1 / den
        M = mp.zeros(N, N)
        for i in range(n):
            for j in range(n):
                M[i, j] = Phi[i, j]
            for j in range(N):
                M[i, j] += Gam[i, 0] * urow[j]
        for i in range(r):
            for j in range(r):
                M[n + i, n + j] = Av[i][j]
            for j in range(N):
                M[n + i, j] += Bv[i][0] * urow[j]
        # xi+ = x_e = x + Cv eta + Dv u
        M[N - 1, n - 1] += 1
        for j in range(r):
            M[N - 1, n + j] += Cv[0][j]
        for j in range(N):
            M[N - 1, j] += Dv * urow[j]
        ev = mp.eig(M, left=False, right=False)
        bad = [mu for mu in ev if abs(mu) >= 1 - mp.mpf(10) ** -40 and abs(mu - 1) > mp.mpf(10) ** -30]
        return ("NOT stable" if bad else "stable"), max(abs(mu) for mu in ev)


def main(argv):
    exe = argv[1]
    cases, seed = cases_and_seed(argv)
    rng = random.Random("hidden-mode:%d" % seed)
    agree = bad = undecided = 0
    branch = {}
    with tempfile.TemporaryDirectory(prefix="hapstab-hidden-") as tmp:
        sc, cert, mut = (os.path.join(tmp, x) for x in ("s.toml", "c.json", "m.json"))
        for i in range(cases):
            c = draw(rng)
            with open(sc, "w") as fh:
                fh.write(scene(c))
            if os.path.exists(cert):
                os.remove(cert)
            r = subprocess.run([exe, "stability", "--scene", sc], capture_output=True, text=True, timeout=300)
            rc = subprocess.run([exe, "stability", "--scene", sc, "--certificate", cert], capture_output=True, text=True, timeout=300)
            ref, rho = reference(c)
            what = "case %d: device %s, coupling %s %s" % (i, c["device"], c["coupling"], c["h"] if c["coupling"] != "none" else "")
            key = (c["device"] if c["device"] != "md" else "md") + " / " + (c["coupling"] + " " + c["h"] if c["coupling"] != "none" else "no coupling")
            if r.returncode == 3:
                undecided += 1
                print("undecided %s: %s" % (what, (r.stdout + r.stderr).strip()[:160]))
                continue
            got = {0: "stable", 1: "NOT stable"}.get(r.returncode)
            ok, line = got == ref, "hapstab %s (exit %d), reference %s (largest |mu| %s)" % (got, r.returncode, ref, mp.nstr(rho, 12))
            if ok and os.path.exists(cert):
                j = json.load(open(cert))
                if "hidden" in j["evidence"]:
                    h = j["evidence"]["hidden"]
                    j["evidence"]["hidden"]["A_h"][0][0] = s(Q(h["A_h"][0][0]) + Q(1, 10))
                    json.dump(j, open(mut, "w"))
                    good, why = both_checkers(exe, cert, mut, "A_h moved by 1/10")
                    line += "; hidden-mode certificate (%s %s)" % (h["block"], h["kind"])
                    key += " [hidden certificate]"
                else:
                    good = all(subprocess.run(cmd + [cert], capture_output=True).returncode == 0 for cmd in (
                        [exe, "check"], ["/usr/bin/python3", os.path.join(os.path.dirname(os.path.dirname(os.path.dirname(
                            os.path.abspath(__file__)))), "checks", "hapstab_check.py")]))
                    why = "a checker does not verify hapstab's certificate"
                if not good:
                    ok, line = False, line + ": " + why
            elif ok:  # refused by name (exit 2), never a verdict that differs
                ok = rc.returncode == 2
                line += "; no certificate (exit %d: %s)" % (rc.returncode, rc.stderr.strip()[:100])
                key += " [no certificate]"
            branch[key] = branch.get(key, 0) + 1
            agree += ok
            bad += not ok
            print("%s %s: %s" % ("ok  " if ok else "MISS", what, line))
    print("indep_hidden_mode: %d cases, %d agree, %d disagree, %d undecided; %s" % (
        cases, agree, bad, undecided, "; ".join("%s %d" % kv for kv in sorted(branch.items()))))
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
