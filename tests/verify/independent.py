#!/usr/bin/python3
"""Random differential campaigns of hapstab's certified paths against references that share no
code and no formula-level shortcut with it (issue 46, "The campaigns that would have caught
these"; docs/verification.md, "Independent campaigns").

  tests/verify/independent.py [--hapstab build/hapstab]
                              [--criterion bound,bound_long,bound_max,stability_max,stability_long,scene_max,scene_coupling,charpoly,symmetry,symmetry16,design16,conservatism,witness,coupling_witness]
                              [--cases N] [--seed S] [--first K] [--case K] [--timeout SEC] [--verbose]

Criteria (each case is drawn from random.Random("SEED:CRITERION:K"), so `--case K` reruns one):
  bound_long     `bound` as below with delays of 50-2000 samples (the long-delay path, issues 43, 48).
  bound          `bound --H H --T T [--delay n] [--frac-delay t_d] [--eta eta]` against paper 001's
                 (45)/(54) evaluated directly in mpmath (indep_passivity.py): the objective sampled
                 densely and refined, its ends taken as limits, a pole at z = -1 decided from the
                 numbers (+inf or -inf).
  bound_max      `bound --H "H0 + K*(H1)" --max K --damping b`: the reference bisects the reference b*(K)
                 (no use of b*'s structure in K), then the Illinois method at 60 digits.
  stability_max  `stability --plant P --H "H0 + K*(H1)" --T T --delay n --max K`: the sampled loop
                 built here (ZOH by mpmath.expm, controller realisations, a shift register for the
                 delay), its spectral radius by mpmath.eig at 50 digits, scanned from K -> 0+
                 (indep_loop.py).
  stability_long `stability --max K` as above with delays of 201-1500 samples (the long-delay path and its
                 gain floor, issue 48): the crossings solved here on a 64-point-per-sample grid of
                 Im K(theta), K = -(z^n + G H0)/(G H1), each bisected; stability below by numpy's
                 eigenvalues, those within 1e-5 of the circle polished by Newton at 40 digits.
  scene_max      `stability --scene S --max g` on random 2-3 DOF scenes whose first device is often
                 open-loop unstable: the same reference on the loop built from the scene's blocks.
                 Any certified supremum with an unstable g in (0, sup) is a miss.
  scene_coupling `stability --scene S --max g` on scenes with a [coupling] V(z) (in parallel with the
                 device, paper 000 (11)) or a gain of degree != 1 in g, so that the closed loop is
                 not affine in g and the bisection on certified verdicts answers (indep_coupled.py:
                 x_e and u solved together per g, M(g) assembled anew, rho at 50 digits). Every
                 certified verdict is checked: stable_at (rho < 1), unstable_at (rho >= 1), exit 1's
                 "NOT stable at every value tried" at each g_ref 2^-k; an affine loop's supremum as
                 in scene_max. Exit 3 is undecided, never agreement (its partial claims are checked).
  charpoly       `stability --scene S` on loops of order 49-64 of pure masses with long delays, where
                 the verdict is Schur-Cohn on lti/realization.cpp's exact charpoly beyond order 48:
                 M built exactly in fractions, det(zI - M) by Hessenberg reduction, Schur-Cohn in
                 fractions (indep_charpoly.py).
  symmetry       `stability --scene S` on scenes of N = 2-32 DOFs in 1-3 classes of identical devices,
                 operators and environment entries (issue 48 item 2: the split by the permutations
                 of identical DOFs): the loop built here (indep_loop) and its spectral radius in
                 double, and hapstab --no-symmetry (the whole matrix) beside it.
  design16       `multidof design --scene S` on symmetry16's scenes, designed on the split of identical
                 DOFs (multidof/design_symmetry.cpp): the designed V in the loop built here (spectral
                 radius in double), a facial infeasibility against E(1) read from the scene in
                 fractions, and --no-symmetry (the whole design) beside it where N <= 6.
  conservatism   `stability --scene S --max g --conservatism` where both regions can be intervals
                 (g the environment's gain, E strictly proper so the loop stays affine beside a
                 coupling with feedthrough, operators b + k/s so M(0) is Schur stable): the exact
                 supremum against the loop reference; Theorem 5's soundness (stable where it
                 concludes and below, its concluding value under the first crossing; a NOT-stable
                 or DC-condition upper end checked); the ratio against the reference's supremum
                 over Theorem 5's bracket. Theorem 5's own supremum has no independent reference
                 (it needs an LMI solver): an infeasible program is counted, not checked.
  witness        `multidof analyze --scene S` on walls K + B(z-1)/(Tz) (a resonance 1e-2..1e-4 from the
                 circle in a quarter), linked walls, contact scenes (backward Euler) and two independent
                 walls, delays 0-24, device levels near Theorem 5's boundary (1e-2, 1e-4, 1e-6 either
                 side) or far from it (indep_witness.py): hapstab's verdict of (16) against the sign of
                 min over theta of lambda_min(He E-hat(e^{j theta}) + Delta_D), E-hat = Tz/(z-1) z^-n E
                 evaluated from the scene's text in mpmath. A printed witness (z, u) is re-evaluated
                 at 50 digits (|z| = 1 exactly, u != 0, phi < 0 strictly); a certified "feasible" with
                 a violation found, or a certified "infeasible" where the condition holds, is a miss.
                 "reference undecided" (|mu| within 1e-25, or a witness with phi = 0 to 40 digits) is
                 counted apart, never as agreement.
  coupling_witness  `multidof analyze --scene S` on the witness criterion's environments (no delay; a
                 wall's spring one sample late, K/z, in 70 %: Re E-hat < 0) with a [coupling] of
                 spring-damper compliances (a constant cross-compliance in 30 % of the multi-DOF
                 ones; the DC condition or V-hat's OSP failing in some), E's gain near Theorem 4's
                 boundary (1e-2, 1e-4, 1e-6 either side) or far from it (indep_coupling.py): hapstab's
                 verdict of Theorem 4 for the scene's own coupling (loop_as_written) against the
                 frequency-domain reference -- mu = min lambda_min([[Delta + He E-hat(z1), He E-hat(z1)],
                 [He E-hat(z1), He V-hat(z2)^-1 + He E-hat(z1)]]) over (z1, z2), sigma = min lambda_min(He
                 V-hat^-1) -- evaluated from the scene's text in mpmath. A printed theorem4_witness
                 (z1, z2, p, u) is re-evaluated at 50 digits (|z| = 1 exactly, [p; V-hat(z2) u] != 0
                 exactly, phi <= 0 on every component); one-DOF components are decided completely,
                 several-DOF ones only when mu < 0 or sigma < 0.

Outcomes per case: agree, MISS (a disagreement: printed with the command line and the
reference value; exit 1), REFERENCE MISSED (hapstab's own maximiser shows a value the reference's
grid did not find: a weakness of the reference, also exit 1), refused (exit 2), undecided
(exit 3), timeout. Refused, undecided and timeouts are never counted as agreement; they are
listed per branch and by the distance from the boundary, and do not fail the run.
Each criterion states per branch the least number of compared cases (a share of --cases); a
run that compares fewer fails ("TOO FEW COMPARED"). --case K checks no minimum.
"""
import argparse
import collections
import json
import math
import os
import pathlib
import random
import subprocess
import sys
import tempfile
import time
from fractions import Fraction as Q

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
ROOT = pathlib.Path(__file__).resolve().parent.parent.parent

import mpmath as mp  # noqa: E402
import numpy as np  # noqa: E402

import indep_charpoly as ICH  # noqa: E402
import indep_coupled as ICP  # noqa: E402
import indep_loop as IL  # noqa: E402
import indep_passivity as IP  # noqa: E402
import indep_roots as IR  # noqa: E402
import indep_witness as IW  # noqa: E402
import indep_coupling as ICW  # noqa: E402
from indep_common import SumTF, dec, run_hapstab, run_hapstab_scene, keep_scene_if_missed, shell_line  # noqa: E402

# relative tolerances, and why:
#  bound: hapstab prints a 30-digit enclosure rounded outward (33 digits); the reference is good to
#  ~45 digits where it converged, and states its own error; 1e-25 leaves 5 digits for both.
TOL_BOUND = mp.mpf(10) ** -25
#  bound_max: the reference K* is bracketed to 1e-24 relative by bisection-type steps on b*(K) at
#  60 digits; hapstab prints 30 digits. 1e-20 leaves room for b*'s error divided by its slope in K.
TOL_KMAX = mp.mpf(10) ** -20
#  stability_max / scene_max: the Illinois bracket of rho(K) = 1 is 1e-26 relative at 50 digits;
#  hapstab is asked for 25 digits. 1e-20 relative. Delays >= 100 are decided in double: 1e-7.
TOL_SUP = mp.mpf(10) ** -20
TOL_SUP_DOUBLE = mp.mpf(10) ** -7


def why_of(err, j):
    """hapstab's own reason for a refusal or an undecided answer (stderr, or the JSON's note)."""
    if err:
        return err.splitlines()[-1]
    if j:
        for k in ("note", "evidence", "why", "method"):
            if j.get(k):
                return str(j[k])
    return ""


def enc(j, key="enclosure"):
    e = j.get(key) if j else None
    if not e:
        return None
    return dec(e[0]), dec(e[1])


# ---------------------------------------------------------------------------------------------
# bound


def case_bound(rng):
    H, T, n, tau, eta, tags = IP.gen_bound(rng)
    return dict(H=H, T=T, n=n, tau=tau, eta=eta, tags=tags, args=IP.bound_args(H, T, n, tau, eta))


def check_bound(c, exe, timeout):
    rc, j, err, dt = run_hapstab(exe, c["args"], timeout)
    nu = Q(c["n"]) + c["tau"]
    ref = IP.bstar(c["H"], c["T"], nu, c["eta"])
    tags = dict(c["tags"])
    if ref["kind"] == "+inf":
        tags["max at"] = "+inf (w -> pi/T)"
    else:
        # label the maximiser; an end within the error of the best is that end
        tags["max at"] = ref["where"]
    tags["end w -> pi/T"] = ref["end_pi"]
    out = dict(tags=tags, rc=rc, seconds=dt, ref=ref, margin=None)
    refs = "+inf" if ref["kind"] == "+inf" else f"{mp.nstr(ref['value'], 35)} (error <= {mp.nstr(ref['err'], 3)}, {ref['where']})"
    out["ref_text"] = refs
    if rc == "timeout":
        out["outcome"] = "timeout"
        return out
    if rc in (2, 3):
        out["outcome"] = "refused" if rc == 2 else "undecided"
        out["why"] = why_of(err, j)
        return out
    if rc != 0 or j is None:
        out["outcome"] = "MISS"
        out["why"] = f"exit {rc}, no JSON: {err[-300:]}"
        return out
    b = str(j.get("bound"))
    hap_inf = b.lstrip("+") in ("inf", "Infinity")
    out["hapstab"] = b
    if ref["kind"] == "+inf":
        out["outcome"] = "agree" if hap_inf else "MISS"
        out["why"] = "" if hap_inf else f"the objective diverges to +inf as w -> pi/T; hapstab says b* = {b}"
        if hap_inf and c.get("certify"):  # since stop 81: +inf certified in the local form at z = -1 at any delay
            CERTIFY["seen"] += 1
            if (CERTIFY["seen"] - 1) % CERTIFY["every"] == 0:
                bound_certificate(c, exe, timeout, out, None, None)
        return out
    if hap_inf:
        out["outcome"] = "MISS"
        out["why"] = f"hapstab says b* = +inf; the reference's objective is bounded (end w -> pi/T: {ref['end_pi']})"
        return out
    lo, hi = enc(j)
    v, e = ref["value"], ref["err"]
    tol = e + TOL_BOUND * max(1, abs(v))
    with mp.workdps(60):
        if v > hi + tol:
            out["outcome"] = "MISS"
            out["why"] = f"the objective reaches {mp.nstr(v, 30)} > hapstab's upper end {mp.nstr(hi, 30)}"
        elif v < lo - tol:
            # the reference's grid may have missed the peak: evaluate at hapstab's maximiser
            w = j.get("omega")
            fw = None
            if w not in (None, "", "null"):
                th = dec(w) * (mp.mpf(c["T"].numerator) / c["T"].denominator)
                ref2 = IP.bstar(c["H"], c["T"], nu, c["eta"], extra_theta=th)
                fw = ref2["value"]
            if fw is not None and fw >= lo - tol:
                out["outcome"] = "REFERENCE MISSED"
                out["why"] = f"the objective at hapstab's maximiser is {mp.nstr(fw, 30)}, above the reference's {mp.nstr(v, 30)}"
            else:
                out["outcome"] = "MISS"
                out["why"] = f"hapstab's lower end {mp.nstr(lo, 30)} exceeds the objective's max {mp.nstr(v, 30)}"
        else:
            out["outcome"] = "agree"
            if c.get("certify"):
                CERTIFY["seen"] += 1
                if (CERTIFY["seen"] - 1) % CERTIFY["every"] == 0:
                    bound_certificate(c, exe, timeout, out, v, tol)
    return out


BRANCHES_BOUND = [  # (tag, value, least share of the cases compared with that branch value)
    ("delay", "sin(pi nu) > 0", 0.12), ("delay", "sin(pi nu) < 0", 0.12), ("delay", "integer", 0.12),
    ("pole at z = -1", True, 0.15), ("pole at z = -1", False, 0.15),
    ("max at", "w=0", 0.03), ("max at", "w=pi/T", 0.03), ("max at", "interior", 0.15),
    ("max at", "+inf (w -> pi/T)", 0.03),
    ("end w -> pi/T", "-inf", 0.03),
    ("resonance 1e-5 from the circle", True, 0.08),
]

def case_bound_long(rng):
    """`bound` as above with a delay of 50-2000 samples: the long-delay path (issue 43) with its
    double-interval pruning (issue 48), against the same mpmath reference (its grid is 32 points
    per sample of delay)."""
    H, T, n, tau, eta, tags = IP.gen_bound(rng)
    n = rng.randint(50, 2000)
    if tau != 0:
        tags["delay"] = "sin(pi nu) > 0" if math.sin(math.pi * float(Q(n) + tau)) > 0 else "sin(pi nu) < 0"
    return dict(H=H, T=T, n=n, tau=tau, eta=eta, tags=tags, args=IP.bound_args(H, T, n, tau, eta), certify=True)


CERTIFY = {"every": 1, "seen": 0}  # --certify-every K: bound_long's certificate step on every K-th agreed case


def certify_both(c, exe, timeout, out):
    """The case's command with --certificate, and both checkers' exit codes on what it wrote: (certificate, hapstab
    check's, the independent checker's -- "timeout" past `timeout`), or None with out's `certificate` tag saying why
    none was written (a refusal by name, or the exit code)."""
    top = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
    with tempfile.TemporaryDirectory() as tmp:
        f = os.path.join(tmp, "c.json")
        rc, _, err, _ = run_hapstab(exe, c["args"] + ["--certificate", f], timeout)
        if not os.path.exists(f):
            out["tags"]["certificate"] = "refused by name" if rc == 2 and "--certificate" in err else "none (exit %s)" % rc
            return None
        cert = json.load(open(f))
        ck = subprocess.run([exe, "check", f], capture_output=True, timeout=timeout).returncode
        try:
            py = subprocess.run(["/usr/bin/python3", os.path.join(top, "checks", "hapstab_check.py"), f], capture_output=True,
                                timeout=timeout).returncode
        except subprocess.TimeoutExpired:
            py = "timeout"
        return cert, ck, py


def bound_certificate(c, exe, timeout, out, v, tol):
    """Since stop 79 (bound_long): the same command with --certificate, run through both checkers; beyond the expanded
    form (n + deg H past ~1000) its evidence is the cells' (check/bound_cells.hpp); b* = +inf (v None, since stop 81)
    the local form at z = -1 (pole_at_z). The certificate's claim must hold
    the reference's value (within its error): the cells' claim is the printed enclosure widened, an independent check of
    what both checkers verify. A refuted certificate, or one that does not hold the reference, is a MISS; a refusal by
    name is tagged."""
    got = certify_both(c, exe, timeout, out)
    if got:
        cert, ck, py = got
        form = "cells" if "cells" in cert["evidence"] else "local at z = -1" if "pole_at_z" in cert["evidence"] else "expanded"
        cl = cert["claim"]
        if v is None:  # the reference says +inf: the claim must be it
            lo = hi = None
            holds = cl.get("infinite") is True
        else:
            lo, hi = (dec(cl["value"]), dec(cl["value"])) if "value" in cl else (dec(cl["lo"]), dec(cl["hi"]))
            holds = lo - tol <= v <= hi + tol
        out["tags"]["certificate"] = "%s: %s" % (form, "verified by both" if ck == 0 and py == 0 else
                                                 "verified, beyond the independent checker's limit" if ck == 0 and py == 3 else
                                                 "hapstab check %s, independent %s" % (ck, py))
        if ck != 0 or py not in (0, 3) or not holds:
            out["outcome"] = "MISS"
            out["why"] = "the certificate (%s): hapstab check %s, independent %s, claim %s %s the reference" % (
                form, ck, py, "+inf" if v is None else "[%s, %s]" % (mp.nstr(lo, 20), mp.nstr(hi, 20)),
                "holds" if holds else "does NOT hold")


BRANCHES_BOUND_LONG = [
    ("delay", "sin(pi nu) > 0", 0.1), ("delay", "sin(pi nu) < 0", 0.1), ("delay", "integer", 0.1),
    ("pole at z = -1", True, 0.1), ("pole at z = -1", False, 0.1),
    ("max at", "interior", 0.1), ("resonance 1e-5 from the circle", True, 0.05),
]



# ---------------------------------------------------------------------------------------------
# bound --max K --damping b


def case_bound_max(rng):
    T = rng.choice(IP.TS[:4])
    K0 = IP.rq(rng, 1, 4) / T / 10
    B = IP.rq(rng, 0.1, 5)
    fam0 = rng.choices(["wall", "tustin", "random", "wall+resonance"], weights=[35, 20, 25, 20])[0]
    t0 = []
    if fam0 == "wall":
        t0.append(IP.Rational([B, -B], [T, 0]))
    elif fam0 == "tustin":
        t0.append(IP.Rational([2 * B, -2 * B], [T, T]))
    elif fam0 == "random":
        t0.append(IP.stable_term(rng))
    else:
        t0.append(IP.Rational([B, -B], [T, 0]))
        t0.append(IP.stable_term(rng, resonant=True))
    fam1 = rng.choices(["stiffness", "damping", "tustin damping", "random", "tustin damping removed"], weights=[35, 25, 15, 25, 10])[0]
    if fam1 == "tustin damping removed":
        # H = Tustin wall B - K (its damping taken away): the residue at z = -1, -4(B - K)/T, changes sign
        # at K = B, so with sin(pi nu) < 0 b* is finite below B and +inf above (a jump of b* at the sup)
        fam0, t0 = "tustin", [IP.Rational([2 * B, -2 * B], [T, T])]
        t1 = [IP.Rational([-2, 2], [T, T])]
        knom = 1
    elif fam1 == "stiffness":
        t1 = [IP.Rational([1], [1])]
        knom = K0
    elif fam1 == "damping":
        t1 = [IP.Rational([1, -1], [T, 0])]
        knom = 1
    elif fam1 == "tustin damping":
        t1 = [IP.Rational([2, -2], [T, T])]
        knom = 1
    else:
        t1 = [IP.stable_term(rng)]
        knom = 1
    u = rng.random()
    if fam1 == "tustin damping removed" and u < 0.7:  # sin(pi nu) < 0: nu in (1, 2) or (3, 4)
        tau, n = Q(1) + Q(rng.randint(1, 9), 10), rng.choice([0, 2])
    elif u < 0.45:
        tau = rng.choice(IP.FRACS[:6]) if rng.random() < 0.6 else Q(rng.randint(1, 20), rng.randint(2, 7))
        if tau.denominator == 1:
            tau += Q(1, 2)
        n = 0 if rng.random() < 0.7 else rng.randint(1, 3)
    else:
        tau, n = Q(0), rng.randint(0, 3)
    eta = IP.rq(rng, 0, 1) if rng.random() < 0.2 else Q(0)
    H0, H1 = SumTF(t0), SumTF(t1)
    s = math.sin(math.pi * float(Q(n) + tau))
    tags = {"H0": fam0, "H1": fam1, "delay": "integer" if tau == 0 else ("sin(pi nu) > 0" if s > 0 else "sin(pi nu) < 0"),
            "pole at z = -1": fam0 == "tustin" or fam1.startswith("tustin damping")}
    # the damping b: b*(0) plus a margin (the reference b*(0) decides; +inf: b = 1)
    ref0 = IP.bstar(H0, T, Q(n) + tau, eta, dps=30)
    if ref0["kind"] == "+inf":
        bq = Q(1)
    else:
        v = float(ref0["value"])
        bq = Q(v + abs(v) * rng.uniform(0.05, 2) + rng.uniform(0.01, 1)).limit_denominator(1000)
        if bq <= 0:  # b*(0) < 0: any damping is passive at K = 0; the device's b must be > 0
            bq = Q(rng.randint(1, 100), 100)
    args = ["bound", "--H", f"{H0.expr()} + K*({H1.expr()})", "--T", f"{T.numerator}/{T.denominator}",
            "--max", "K", "--damping", f"{bq.numerator}/{bq.denominator}"]
    if n:
        args += ["--delay", str(n)]
    if tau:
        td = tau * T
        args += ["--frac-delay", f"{td.numerator}/{td.denominator}"]
    if eta:
        args += ["--eta", f"{eta.numerator}/{eta.denominator}"]
    return dict(H0=H0, H1=H1, T=T, n=n, tau=tau, eta=eta, b=bq, knom=knom, tags=tags, args=args)


class KH:
    """H0 + K H1 for the reference (K an exact rational or an mpf): evaluated term by term."""

    def __init__(self, H0, H1, K):
        self.H0, self.H1, self.K = H0, H1, K
        Kf = float(K)
        self.terms = list(H0.terms) + [_Scaled(t, K, Kf) for t in H1.terms]

    def eval_mp(self, z):
        return self.H0.eval_mp(z) + mp.mpf(self.K) * self.H1.eval_mp(z) if not isinstance(self.K, Q) else \
            self.H0.eval_mp(z) + (mp.mpf(self.K.numerator) / self.K.denominator) * self.H1.eval_mp(z)


class _Scaled:
    def __init__(self, t, K, Kf):
        self.t, self.K, self.Kf = t, K, Kf
        self.den = t.den

    def coeffs_float(self):
        num, den = self.t.coeffs_float()
        return [self.Kf * x for x in num], den


def bstar_K(c, K, dps=60, fast=False):
    return IP.bstar(KH(c["H0"], c["H1"], K), c["T"], Q(c["n"]) + c["tau"], c["eta"], dps=dps, fast=fast)


def kmax_reference(c):
    """dict(kind 'zero'|'inf'|'finite', lo, hi, where)."""
    b = mp.mpf(c["b"].numerator) / c["b"].denominator
    r0 = bstar_K(c, Q(0), dps=40)
    if r0["kind"] == "+inf" or r0["value"] >= b:
        return dict(kind="zero", why=f"b*(0) = {mp.nstr(r0['value'], 20)} >= b")
    # scan K from 1e-8 knom upwards (the fast b*: double refinement), 4 points per decade
    knom = float(c["knom"])
    ks = [knom * 10 ** (i / 4) for i in range(-32, 41)]
    prev = 0.0
    hit = None
    for k in ks:
        r = bstar_K(c, mp.mpf(k), dps=30, fast=True)
        if r["kind"] == "+inf" or r["value"] >= b:
            hit = k
            break
        prev = k
    if hit is None:
        return dict(kind="inf", scanned_to=ks[-1])
    if prev == 0.0:
        return dict(kind="zero", why=f"b*(K) >= b already at K = {hit:g}")
    a, bb = mp.mpf(prev), mp.mpf(hit)

    def g(K):
        r = bstar_K(c, K, dps=60)
        return mp.mpf(1) if r["kind"] == "+inf" else r["value"] - b
    def gf(K):
        r = bstar_K(c, K, dps=30, fast=True)
        return mp.mpf(1) if r["kind"] == "+inf" else r["value"] - b
    with mp.workdps(60):
        # bisection to 1e-9 relative on the fast b* (double refinement), then the Illinois
        # method on the 60-digit b* to 1e-24, from a bracket checked at 60 digits
        while bb - a > mp.mpf(10) ** -9 * bb:
            m = (a + bb) / 2
            if gf(m) >= 0:
                bb = m
            else:
                a = m
        # the fast b* may be off by ~1e-7 (near a pole at z = -1 its double grid is noise):
        # widen the bracket until the 60-digit b* straddles b at its ends
        a0, b0 = a, bb
        for w in (mp.mpf(10) ** -8, mp.mpf(10) ** -6, mp.mpf(10) ** -4, mp.mpf(10) ** -2):
            a, bb = a0 * (1 - w), b0 * (1 + w)
            ga, gb = g(a), g(bb)
            if ga < 0 <= gb:
                break
        if not (ga < 0 <= gb):
            return dict(kind="reference-unsure", lo=a, hi=bb, why=f"60-digit b* - b = {mp.nstr(ga, 5)}, {mp.nstr(gb, 5)} at the bracket's ends")
        if gb > 1e10 * abs(ga) or gb == 1:  # a jump (a divergence), not a smooth crossing
            return dict(kind="finite", lo=a, hi=bb, where="jump")
        lo, hi = IL.illinois(g, a, bb, ga, gb, mp.mpf(10) ** -24)
        rr = bstar_K(c, hi, dps=60)
        return dict(kind="finite", lo=lo, hi=hi, where=rr["where"])


def bound_max_certificate(c, exe, timeout, out, ref):
    """Since stop 90: on every agreed case (every K-th with --certify-every K) the same command with --certificate, run
    through both checkers. The claim must hold the reference: 0 where it finds b*(0) >= b (every form: the witness,
    the integrator, b*(0) = +inf by bound's evidence at K = 0), +inf where it never reaches b, else an enclosure that
    meets its bracket (1e-20 relative; exactly at a jump). A refuted certificate, or a claim the reference contradicts,
    is a MISS; a refusal by name is tagged (`certificate`), never counted as verified."""
    CERTIFY["seen"] += 1
    if (CERTIFY["seen"] - 1) % CERTIFY["every"] != 0:
        return
    got = certify_both(c, exe, timeout, out)
    if got:
        cert, ck, py = got
        ev = cert["evidence"]
        form = next((name for key, name in (("at_zero_infinite", "b*(0) = +inf"), ("integrator", "integrator"), ("jump_at_z", "jump"),
                                            ("cells_at_0", "cells"), ("witness_theta", "cells"), ("witness_c", "witness"))
                     if key in ev), "b*(0) < b, f1 <= 0" if cert["claim"].get("infinite") else "other")
        out["tags"]["certificate form"] = form
        cl = cert["claim"]
        if cl.get("infinite") is True:
            holds = ref["kind"] == "inf"
            text = "+inf"
        else:
            lo, hi = (dec(cl["value"]), dec(cl["value"])) if "value" in cl else (dec(cl["lo"]), dec(cl["hi"]))
            text = "[%s, %s]" % (mp.nstr(lo, 20), mp.nstr(hi, 20))
            if ref["kind"] == "zero":
                holds = hi == 0
            elif ref["kind"] == "finite":
                slack = 0 if ref["where"] == "jump" else TOL_KMAX
                holds = lo <= ref["hi"] * (1 + slack) and hi >= ref["lo"] * (1 - slack)
            else:
                holds = False
        out["tags"]["certificate"] = ("verified by both" if ck == 0 and py == 0 else
                                      "verified, beyond the independent checker's limit" if ck == 0 and py == 3 else
                                      "hapstab check %s, independent %s" % (ck, py))
        if ck != 0 or py not in (0, 3) or not holds:
            out["outcome"] = "MISS"
            out["why"] = "the certificate (%s): hapstab check %s, independent %s, claim %s %s the reference (K_max %s)" % (
                form, ck, py, text, "holds" if holds else "does NOT hold", ref["kind"])


def check_bound_max(c, exe, timeout):
    rc, j, err, dt = run_hapstab(exe, c["args"], timeout)
    ref = kmax_reference(c)
    tags = dict(c["tags"])
    tags["K_max"] = ref["kind"]
    if ref["kind"] == "finite":
        tags["b* = b at"] = ref["where"]
    out = dict(tags=tags, rc=rc, seconds=dt, margin=None)
    if ref["kind"] == "finite":
        out["ref_text"] = f"K_max in [{mp.nstr(ref['lo'], 30)}, {mp.nstr(ref['hi'], 30)}]"
    else:
        out["ref_text"] = f"K_max {ref['kind']} ({ref.get('why', '')})"
    if rc == "timeout":
        out["outcome"] = "timeout"
        return out
    if rc in (2, 3):
        out["outcome"] = "refused" if rc == 2 else "undecided"
        out["why"] = why_of(err, j)
        return out
    if j is None or rc not in (0, 1):
        out["outcome"] = "MISS"
        out["why"] = f"exit {rc}, no JSON: {err[-300:]}"
        return out
    mx = str(j.get("max"))
    out["hapstab"] = mx
    if ref["kind"] == "reference-unsure":
        out["outcome"] = "REFERENCE MISSED"
        out["why"] = ref["why"]
        return out
    if ref["kind"] == "zero":
        ok = mx in ("0",) or (dec(mx) == 0 if mx not in ("None", "inf") else False)
        out["outcome"] = "agree" if ok else "MISS"
        out["why"] = "" if ok else f"the reference finds b*(K) >= b for every K > 0 ({ref.get('why')}); hapstab says {mx}"
        if ok:
            bound_max_certificate(c, exe, timeout, out, ref)
        return out
    if ref["kind"] == "inf":
        ok = mx.lstrip("+") == "inf"
        out["outcome"] = "agree" if ok else "MISS"
        out["why"] = "" if ok else f"the reference finds b*(K) < b up to K = {ref['scanned_to']:g}; hapstab says {mx}"
        if ok:
            bound_max_certificate(c, exe, timeout, out, ref)
        return out
    if mx.lstrip("+") == "inf" or j.get("enclosure") is None:
        out["outcome"] = "MISS"
        out["why"] = f"hapstab says {mx}; the reference crosses b at K in [{mp.nstr(ref['lo'], 20)}, {mp.nstr(ref['hi'], 20)}]"
        return out
    lo, hi = enc(j)
    tl = ref["lo"] * (1 - TOL_KMAX)
    th = ref["hi"] * (1 + TOL_KMAX)
    if ref["where"] == "jump":
        tl, th = ref["lo"], ref["hi"]
    if hi < tl or lo > th:
        out["outcome"] = "MISS"
        out["why"] = f"hapstab's enclosure [{mp.nstr(lo, 25)}, {mp.nstr(hi, 25)}] misses the reference's"
    elif ref["where"] == "jump" and not j.get("jump"):
        # b* diverges just above the sup (H's pole at z = -1 changing side): "b* = b at the sup" would be false
        out["outcome"] = "MISS"
        out["why"] = "the reference's b* jumps to +inf at the sup; hapstab does not say so (jump: false)"
    else:
        out["outcome"] = "agree"
        bound_max_certificate(c, exe, timeout, out, ref)
    return out


BRANCHES_BOUND_MAX = [
    ("delay", "integer", 0.2), ("delay", "sin(pi nu) > 0", 0.06), ("delay", "sin(pi nu) < 0", 0.06),
    ("K_max", "finite", 0.4), ("K_max", "zero", 0.01),
    ("pole at z = -1", True, 0.1),
    ("b* = b at", "interior", 0.05), ("b* = b at", "jump", 0.02),
    ("certificate", "verified by both", 0.3),  # since stop 90 (at --certify-every 1)
]


# ---------------------------------------------------------------------------------------------
# stability --max (one DOF) and --scene --max (several DOF)


def case_stability(rng):
    c = IL.gen_stability(rng)
    c["args"] = IL.stability_args(c)
    return c


def compare_sup(out, ref, j, rc, tol, name):
    """Shared verdict logic of stability_max and scene_max."""
    mx = str(j.get("max")) if j else "None"
    out["hapstab"] = mx
    if ref["kind"] == "zero":
        ok = rc == 1 and mx == "0"
        out["outcome"] = "agree" if ok else "MISS"
        if not ok:
            out["why"] = f"the loop is unstable for small {name} (rho = {mp.nstr(ref['rho_small'], 20)} at {name} -> 0+); hapstab: exit {rc}, max {mx}"
        return out
    if ref["kind"] == "inf":
        ok = rc == 0 and mx.lstrip("+") == "inf"
        out["outcome"] = "agree" if ok else "MISS"
        if not ok:
            out["why"] = f"no crossing up to {name} = {ref['scanned_to']:g}; hapstab: exit {rc}, max {mx}"
        return out
    if ref["kind"] == "at_most":  # unstable at the smaller probe K = value: sup <= value
        ok = (rc == 1 and mx == "0") or (rc == 0 and j is not None and j.get("enclosure") is not None
                                         and enc(j)[1] <= ref["value"] * (1 + tol))
        out["outcome"] = "agree" if ok else "MISS"
        if not ok:
            out["why"] = (f"the loop is NOT stable at {name} = {mp.nstr(ref['value'], 6)} (rho = "
                          f"{mp.nstr(ref['rho_small'], 12)}), so sup <= it; hapstab: exit {rc}, max {mx}")
        return out
    if ref["kind"] != "sup":
        out["outcome"] = "REFERENCE MISSED"
        out["why"] = f"the reference could not place its crossing: {ref}"
        return out
    if rc == 1 and mx == "0":
        out["outcome"] = "MISS"
        out["why"] = f"hapstab says unstable for small {name}; the reference is stable on (0, {mp.nstr(ref['lo'], 20)})"
        return out
    if rc != 0 or j.get("enclosure") is None:
        out["outcome"] = "MISS"
        out["why"] = f"hapstab: exit {rc}, max {mx}; the reference's sup is {mp.nstr(ref['value'], 25)}"
        return out
    lo, hi = enc(j)
    if hi < ref["lo"] * (1 - tol) or lo > ref["hi"] * (1 + tol):
        out["outcome"] = "MISS"
        out["why"] = (f"hapstab's enclosure [{mp.nstr(lo, 25)}, {mp.nstr(hi, 25)}] misses the reference's "
                      f"[{mp.nstr(ref['lo'], 25)}, {mp.nstr(ref['hi'], 25)}]")
        if lo > ref["hi"] * (1 + tol):
            out["why"] += f": the loop is NOT stable at {name} = {mp.nstr(ref['hi'], 25)} inside hapstab's (0, sup)"
        return out
    out["outcome"] = "agree"
    crossing = (j.get("crossing") or {}).get("at")
    if crossing and ref.get("crossing") and crossing.replace("complex pair", "complex") != ref["crossing"]:
        out["note"] = f"crossing: hapstab {crossing}, reference {ref['crossing']}"
    return out


def check_claim_double(loop, j, rc, knom):
    """n >= 1000: only hapstab's claim is checked, in double (the full reference would take minutes)."""
    if rc == 0 and j and j.get("enclosure"):
        lo, hi = enc(j)
        for f in (1e-6, 1e-4, 0.01, 0.1, 0.25, 0.5, 0.9, 1 - 1e-6):
            if IL.rho_np(loop, float(lo) * f) >= 1:
                return dict(kind="claim", ok=False, why=f"rho >= 1 at K = {float(lo) * f:g} inside (0, lo)")
        if IL.rho_np(loop, float(hi) * (1 + 1e-6)) < 1:
            return dict(kind="claim", ok=False, why=f"rho < 1 just above hi = {float(hi):g}")
        return dict(kind="claim", ok=True)
    if rc == 1 and j and str(j.get("max")) == "0":
        for f in (1e-6, 1e-4, 1e-2):
            if IL.rho_np(loop, float(knom) * f) < 1:
                return dict(kind="claim", ok=False, why=f"hapstab: unstable for small K, but rho < 1 at K = {float(knom) * f:g}")
        return dict(kind="claim", ok=True)
    return None


def tag_reference(ref, tags, out, name):
    """The reference's supremum (or its kind) into the case's tags and its printed text."""
    if ref["kind"] == "sup":
        tags["crossing"] = ref["crossing"]
        out["margin"] = ref["margin"]
        out["ref_text"] = f"sup {name} in [{mp.nstr(ref['lo'], 30)}, {mp.nstr(ref['hi'], 30)}] ({ref['crossing']})"
    else:
        tags["crossing"] = ref["kind"]
        out["ref_text"] = f"sup {name}: {ref['kind']}"


def check_stability(c, exe, timeout):
    rc, j, err, dt = run_hapstab(exe, c["args"], timeout)
    loop = IL.build_loop_1dof(c)
    tags = dict(c["tags"])
    out = dict(tags=tags, rc=rc, seconds=dt, margin=None)
    free = IL.free_position_every_K(c)
    if free:
        tags["z = 1 for every K (exact)"] = True
    if c["n"] >= 1000:
        cl = check_claim_double(loop, j, rc, c["Knom"])
        if free and rc == 1 and j and str(j.get("max")) == "0":
            cl = dict(kind="claim", ok=True)
        tags["stable at small K"] = "n/a (n >= 1000: claim checked)"
        if rc == "timeout" or rc in (2, 3):
            out["outcome"] = {"timeout": "timeout", 2: "refused", 3: "undecided"}[rc]
            out["why"] = why_of(err, j)
            out["ref_text"] = "not computed (n >= 1000)"
            return out
        out["ref_text"] = "hapstab's claim checked in double at 8 points below lo and just above hi"
        if cl is None:
            out["outcome"] = "unchecked"
            out["why"] = f"exit {rc}, max {j.get('max') if j else None}"
            return out
        out["outcome"] = "agree" if cl["ok"] else "MISS"
        out["why"] = cl.get("why", "")
        tags["crossing"] = (j.get("crossing") or {}).get("at", "?")
        return out
    precise = c["n"] < 100
    if free:  # decided exactly (free_position_every_K); the scan in double cannot see it at n >= 100
        ref = dict(kind="zero", value=mp.mpf(0), rho_small=mp.mpf(1), marginal=True)
    else:
        ref = IL.sup_reference(loop, c["Knom"], precise=precise)
    tags["stable at small K"] = ref["kind"] in ("sup", "inf")
    tag_reference(ref, tags, out, "K")
    if rc == "timeout":
        out["outcome"] = "timeout"
        return out
    if rc in (2, 3):
        out["outcome"] = "refused" if rc == 2 else "undecided"
        out["why"] = why_of(err, j)
        return out
    if j is None:
        out["outcome"] = "MISS"
        out["why"] = f"exit {rc}, no JSON: {err[-300:]}"
        return out
    return compare_sup(out, ref, j, rc, TOL_SUP if precise else TOL_SUP_DOUBLE, "K")


BRANCHES_STABILITY = [
    ("stable at small K", True, 0.3), ("stable at small K", False, 0.05),
    ("crossing", "z = 1", 0.02), ("crossing", "z = -1", 0.02), ("crossing", "complex", 0.2),
    ("delay", "0", 0.08), ("delay", "1-5", 0.4),
]


# ---------------------------------------------------------------------------------------------
# stability --max with a long delay: the crossing search of stability/long_delay.cpp (its gain
# floor prunes the band away from the crossover, issue 48)


def case_stability_long(rng):
    """`stability --max K` as above with a delay of 201-1500 samples (the long-delay path, degree >
    200). The reference solves 1 + z^-n G(z) (H0 + K H1)(z) = 0 on the circle for real K itself:
    G = C (zI - Phi)^-1 Gamma from the loop's own ZOH (mpmath expm), Im of
    K(theta) = -(z^n + G H0)/(G H1) on a grid of 64 points per sample of delay, each sign change
    refined by bisection, the smallest positive K among them and at z = +-1; stability below it
    by the loop matrix's eigenvalues (the roots of det(zI - M) by Aberth, indep_roots.py, or numpy's
    dense eigenvalues; those near the circle polished, rho_polished) at K*/1000 and at K* (1 - 1e-6)."""
    c = IL.gen_stability(rng)
    c["n"] = rng.randint(201, 1500)
    c["tags"]["delay"] = "201-1500"
    c["args"] = IL.stability_args(c)
    return c


def long_crossing_reference(c, loop):
    """The smallest positive crossing gain on the unit circle (see case_stability_long), or None
    when there is none; the kind of the crossing."""
    import numpy as np
    Phi = np.array(loop.Phi.tolist(), dtype=float)
    Gam = np.array(loop.Gam.tolist(), dtype=float)
    Cy = np.array(loop.Cy.tolist(), dtype=float)
    n = c["n"]

    def polyval(p, z):
        return np.polyval(np.array([float(x) for x in p]), z)

    def kval(theta):
        z = np.exp(1j * np.atleast_1d(theta))
        A = z[:, None, None] * np.eye(Phi.shape[0])[None] - Phi[None]
        try:
            X = np.linalg.solve(A, np.broadcast_to(Gam, (len(z),) + Gam.shape))
        except np.linalg.LinAlgError:  # z rounded onto an open-loop pole on the circle: 1e-12 rad aside
            z = z * np.exp(1e-12j)
            A = z[:, None, None] * np.eye(Phi.shape[0])[None] - Phi[None]
            X = np.linalg.solve(A, np.broadcast_to(Gam, (len(z),) + Gam.shape))
        G = (Cy[None] @ X)[:, 0, 0]
        h0 = polyval(c["H0"].num, z) / polyval(c["H0"].den, z)
        h1 = polyval(c["H1"].num, z) / polyval(c["H1"].den, z)
        return -(z ** n + G * h0) / (G * h1)

    th = np.linspace(0, math.pi, 64 * (n + 10) + 1)[1:-1]
    w = kval(th)
    im = w.imag
    cands = []
    idx = np.nonzero(np.sign(im[:-1]) * np.sign(im[1:]) < 0)[0]
    if len(idx):  # every sign change of Im K(theta) bisected at once, 60 halvings
        a, b, fa = th[idx], th[idx + 1], im[idx]
        for _ in range(60):
            mid = 0.5 * (a + b)
            fm = kval(mid).imag
            left = (fm < 0) == (fa < 0)
            a, fa, b = np.where(left, mid, a), np.where(left, fm, fa), np.where(left, b, mid)
        cands += [(k, "complex") for k in kval(0.5 * (a + b)).real if k > 0]
    for t, kind in ((1e-12, "z = 1"), (math.pi - 1e-12, "z = -1")):
        k = kval(t)[0]  # K -> 0 there is an open-loop pole on the circle, not a crossing at K > 0
        if np.isfinite(k.real) and k.real > 1e-9 * c["Knom"] and abs(k.imag) < 1e-6 * abs(k.real):
            cands.append((k.real, kind))
    return min(cands) if cands else None


def rho_polished(c, loop, K):
    """The spectral radius of the loop matrix at K: its eigenvalues as the roots of det(zI - M) (indep_roots.py:
    Aberth's iteration, numpy's dense eigenvalues where it is not accepted), those within 1e-5 of the
    circle polished by Newton at 40 digits on z^n + G(z) (H0 + K H1)(z) = 0 (G = Cy (zI - Phi)^-1
    Gamma from the reference's own ZOH): double precision alone misjudges a root 1e-8 inside the
    circle (the delayed double integrator's slowly decaying pair)."""
    import numpy as np
    ev = IR.loop_roots(loop, float(K))  # the roots of det(zI - M), Aberth in O(n^2) (indep_roots.py)
    if ev is None:  # not accepted there: the dense problem
        ev = np.linalg.eigvals(loop.M_np(float(K)))
    rho = 0.0
    with mp.workdps(40):
        Kq = mp.mpf(K)

        def chi(z):
            G = (loop.Cy * mp.lu_solve(z * mp.eye(loop.Phi.rows) - loop.Phi, loop.Gam))[0, 0]
            return z ** c["n"] + G * (c["H0"].eval_mp(z) + Kq * c["H1"].eval_mp(z))
        for e in ev:
            r = abs(complex(e))
            if abs(r - 1) < 1e-5:
                z = mp.mpc(complex(e))
                for _ in range(60):
                    f = chi(z)
                    h = mp.mpf(10) ** -20 * (1 + abs(z))
                    step = f / ((chi(z + h) - f) / h)
                    z -= step
                    if abs(step) < mp.mpf(10) ** -30:
                        break
                if abs(chi(z)) < mp.mpf(10) ** -25 and abs(z - complex(e)) < 1e-6:
                    r = abs(z)  # at 40 digits: rho - 1 resolved below double's 1e-16 (crossing_by_radius bisects on it)
            rho = max(rho, r)
    return rho


def crossing_by_radius(c, loop, lo, hi):
    """The first K in [lo, hi] where the polished radius reaches 1, given rho(lo) < 1 <= rho(hi): a geometric scan
    of 48 points per decade, then bisection to 1e-12 of K; None where the scan sees none. For a crossing that the
    grid of K(theta) misses (at an angle below its spacing, 1/64 of a sample: a fast device near z = 1), as the
    check at K* (1 - 1e-6) shows (since stop 86; before, "a crossing below the grid's", not compared)."""
    steps = max(2, int(48 * math.log10(hi / lo)))
    a = lo
    for i in range(1, steps + 1):
        b = lo * (hi / lo) ** (i / steps)
        if rho_polished(c, loop, b) >= 1:
            break
        a = b
    else:
        return None
    while b - a > 1e-12 * b:
        m = (a + b) / 2
        a, b = (a, m) if rho_polished(c, loop, m) >= 1 else (m, b)
    return (a + b) / 2


def check_stability_long(c, exe, timeout):
    rc, j, err, dt = run_hapstab(exe, c["args"], timeout)
    loop = IL.build_loop_1dof(c)
    tags = dict(c["tags"])
    out = dict(tags=tags, rc=rc, seconds=dt, margin=None)
    if IL.free_position_every_K(c):
        tags["z = 1 for every K (exact)"] = True
        ref = dict(kind="zero")
    elif IL.minus_one_every_K(c):
        tags["z = -1 for every K (exact)"] = True
        ref = dict(kind="zero")
    else:
        cross = long_crossing_reference(c, loop)
        probe = (cross[0] if cross else c["Knom"]) / 1000
        rho0 = rho_polished(c, loop, probe)
        if abs(1 - rho0) < 1e-12:
            ref = dict(kind="unsure", why=f"rho = {rho0!r} at K = {probe!r}, too near the circle to say")
        elif rho0 > 1:
            ref = dict(kind="zero")
        elif cross is None:
            ref = dict(kind="inf")
        else:
            ref = dict(kind="sup", value=cross[0], crossing=cross[1])
            if rho_polished(c, loop, cross[0] * (1 - 1e-6)) >= 1:
                k = crossing_by_radius(c, loop, probe, cross[0] * (1 - 1e-6))
                ref = dict(kind="sup", value=k, crossing="below the grid (radius)") if k else \
                    dict(kind="unsure", why=f"rho >= 1 at K* (1 - 1e-6), K* = {cross[0]!r}: a crossing below the grid's")
    tags["stable at small K"] = ref["kind"] in ("sup", "inf")
    tags["crossing"] = ref.get("crossing", ref["kind"])
    out["ref_text"] = f"sup K = {ref['value']!r} ({ref['crossing']})" if ref["kind"] == "sup" else f"sup K: {ref['kind']}"
    if rc == "timeout" or rc in (2, 3):
        out["outcome"] = {"timeout": "timeout", 2: "refused", 3: "undecided"}[rc]
        out["why"] = why_of(err, j)
        return out
    mx = str(j.get("max")) if j else "None"
    out["hapstab"] = mx
    if ref["kind"] == "unsure":
        out["outcome"], out["why"] = "REFERENCE MISSED", ref["why"]
    elif ref["kind"] == "zero":
        out["outcome"] = "agree" if rc == 1 and mx == "0" else "MISS"
        out["why"] = "" if out["outcome"] == "agree" else f"unstable at small K by the reference; hapstab: exit {rc}, max {mx}"
    elif ref["kind"] == "inf":
        out["outcome"] = "agree" if rc == 0 and mx.lstrip("+") == "inf" else "MISS"
        out["why"] = "" if out["outcome"] == "agree" else f"no crossing on the reference's grid; hapstab: exit {rc}, max {mx}"
    elif rc != 0 or not j.get("enclosure"):
        out["outcome"], out["why"] = "MISS", f"the reference's sup is {ref['value']!r}; hapstab: exit {rc}, max {mx}"
    else:
        lo, hi = enc(j)
        K = mp.mpf(ref["value"])
        if lo > K * (1 + TOL_LONG):
            out["outcome"] = "MISS"
            out["why"] = f"hapstab's [{mp.nstr(lo, 20)}, {mp.nstr(hi, 20)}] lies above the reference's crossing {ref['value']!r}: a crossing missed"
        elif hi < K * (1 - TOL_LONG):
            out["outcome"] = "REFERENCE MISSED"
            out["why"] = f"hapstab's [{mp.nstr(lo, 20)}, {mp.nstr(hi, 20)}] lies below the reference's {ref['value']!r} (a crossing between its grid points?)"
        else:
            out["outcome"] = "agree"
    return out


TOL_LONG = 1e-9  # the reference's crossing, bisected in double to 2^-60 of an arc: ~1e-12 relative


BRANCHES_STABILITY_LONG = [
    ("stable at small K", True, 0.3), ("stable at small K", False, 0.05), ("crossing", "complex", 0.2),
]


def case_scene(rng):
    c = IL.gen_scene(rng)
    return c


def check_scene(c, exe, timeout):
    rc, j, err, dt, args, path = run_hapstab_scene(exe, IL.scene_toml(c), "indep_scene_", ["--max", "g", "--digits", "25"], timeout)
    loop = IL.build_loop_scene(c)
    ref = IL.sup_reference(loop, c["Knom"])
    tags = dict(c["tags"])
    tags["stable at small g"] = ref["kind"] in ("sup", "inf")
    out = dict(tags=tags, rc=rc, seconds=dt, margin=None, scene=IL.scene_toml(c), args=args)
    tag_reference(ref, tags, out, "g")
    # the states hapstab's closed-loop matrix has, beside the reference's (informative)
    if rc == "timeout":
        out["outcome"] = "timeout"
    elif rc in (2, 3):
        out["outcome"] = "refused" if rc == 2 else "undecided"
        out["why"] = why_of(err, j)
        if rc == 3 and j and j.get("stable_on") and ref["kind"] in ("zero", "sup"):
            # "stable on [a, b]": every g there must be stable for the reference
            a, b = enc(j, "stable_on")
            out["tags"]["exit 3 with stable_on"] = True
            # what hapstab proves there (the interval) is compared: a checked, passed claim counts
            out["outcome"] = "agree"
            for f in (0, 0.25, 0.5, 0.75, 1):
                g = a + (b - a) * f
                if g > 0 and IL.rho_mp(loop, g)[0] >= 1:
                    out["outcome"] = "MISS"
                    out["why"] = f"hapstab proves stable on [{a}, {b}], but rho >= 1 at g = {mp.nstr(g, 20)}"
                    if f == 1 and IL.rho_mp(loop, g * (1 - mp.mpf(10) ** -14))[0] < 1:
                        out["why"] += (" (the printed upper end lies above the crossing: the interval"
                                       " proven stable is rounded outward where it must be rounded inward)")
                    break
    elif j is None:
        out["outcome"] = "MISS"
        out["why"] = f"exit {rc}, no JSON: {err[-300:]}"
    else:
        compare_sup(out, ref, j, rc, TOL_SUP, "g")
    keep_scene_if_missed(out, path)
    return out


def case_symmetry(rng):
    """`stability --scene S` on random scenes of N = 2-32 DOFs in 1-3 classes of identical devices
    (a mass-damper, or a first-order ss device, stable or open-loop unstable), operators (none, a
    damper, a damper and spring) and environment entries: E(i, i) = K_a + B_a (z - 1)/(T z),
    E(i, j) = -k_ab or -k_ab (z - p_ab)/z by the classes of i and j (issue 48 item 2). hapstab splits
    the loop by the permutations within the classes (stability/symmetry.hpp); the reference builds
    the whole loop itself (indep_loop: ZOH in mpmath, E realised entry by entry) and takes its
    spectral radius in double; hapstab --no-symmetry decides the whole matrix beside it."""
    T = Q(1, 1000)
    N = rng.choice([2, 3, 4, 5, 6, 8, 12, 16, 24, 32])
    r = min(N, rng.choice([1, 2, 2, 3]))
    cls = list(range(r)) + [rng.randrange(r) for _ in range(N - r)]
    rng.shuffle(cls)
    kinds = [rng.choices(["md", "unstable ss", "stable ss"], weights=[60, 25, 15])[0] for _ in range(r)]
    devs, opc, K, B = [], [], [], []
    for a in range(r):
        m = IL.rq(rng, 0.05, 1)
        if kinds[a] == "md":
            devs.append(dict(kind="md", m=m, b=IL.rq(rng, 0, 5)))
        else:
            sgn = 1 if kinds[a] == "unstable ss" else -1
            devs.append(dict(kind="ss", A=sgn * IL.rq(rng, 0.5, 20), Bv=1 / m, passive=sgn < 0, m=m))
        opc.append(rng.choice([None, IL.rq(rng, 0.5, 5), (IL.rq(rng, 0.5, 5), IL.rq(rng, 10, 200))]))
        K.append(IL.rq(rng, 100, 3000) / max(1, N // 4))
        B.append(IL.rq(rng, 0, 8))
    off = [[None] * r for _ in range(r)]
    for a in range(r):
        for b in range(r):
            k = IL.rq(rng, 0, 400) / N if rng.random() < 0.7 else Q(0)
            off[a][b] = IL.Rational([-k], [1]) if rng.random() < 0.6 else IL.Rational([-k, k * Q(rng.randint(-5, 5), 10)], [1, 0])
    E = [[IL.Rational([K[cls[i]] + B[cls[i]] / T, -B[cls[i]] / T], [1, 0]) if i == j else off[cls[i]][cls[j]]
          for j in range(N)] for i in range(N)]
    n = 0 if rng.random() < 0.7 else rng.randint(1, 2)
    sizes = sorted((cls.count(a) for a in range(r)), reverse=True)
    tags = {"N": "2-4" if N <= 4 else "5-12" if N <= 12 else "16-32", "classes": str(r),
            "a class of one": 1 in sizes, "first class": kinds[cls[0]], "delay": str(n)}
    return dict(T=T, devices=[devs[cls[i]] for i in range(N)], ops=[opc[cls[i]] for i in range(N)], E=E, n=n,
                tags=tags, Knom=1.0)


def check_symmetry(c, exe, timeout):
    text = IL.scene_toml(c)
    rc, j, err, dt, args, path = run_hapstab_scene(exe, text, "indep_symmetry_", [], timeout)
    rcw, jw, errw, dtw = run_hapstab(exe, args + ["--no-symmetry"], timeout)
    loop = IL.build_loop_scene(c)
    rho = IL.rho_np(loop, 1.0)
    tags = dict(c["tags"])
    tags["hapstab path"] = (j or {}).get("path") or "none"
    out = dict(tags=tags, rc=rc, seconds=dt, margin=abs(1 - rho), scene=text, args=args)
    out["ref_text"] = f"rho = {rho!r} (the loop built here, double); hapstab --no-symmetry: exit {rcw}, {(jw or {}).get('method')}"
    near = abs(1 - rho) < 1e-9
    tags["reference"] = "within 1e-9 of 1" if near else ("stable" if rho < 1 else "NOT stable")
    v, vw = (j or {}).get("stable"), (jw or {}).get("stable")
    if rc == "timeout":
        out["outcome"] = "timeout"
    elif v is not None and vw is not None and v != vw:
        out.update(outcome="MISS", why=f"with the symmetry {v}, the whole matrix {vw}")
    elif rc in (2, 3) or v is None:
        out.update(outcome="refused" if rc == 2 else "undecided", why=why_of(err, j))
    elif near:  # not compared: only the whole matrix, which shares code with the split, could say
        out.update(outcome="reference too near the circle", why=f"rho = {rho!r}; hapstab --no-symmetry agrees")
    elif v != (rho < 1):
        out.update(outcome="MISS", why=f"hapstab: {'stable' if v else 'NOT stable'} ({j.get('method')}); rho = {rho!r}")
    else:
        out["outcome"] = "agree"
    keep_scene_if_missed(out, path)
    return out


BRANCHES_SYMMETRY = [  # compared verdicts
    ("hapstab path", "symmetry", 0.6), ("reference", "stable", 0.15), ("reference", "NOT stable", 0.15),
    ("N", "16-32", 0.1), ("classes", "3", 0.1), ("a class of one", True, 0.05), ("first class", "unstable ss", 0.1),
]


def case_symmetry16(rng):
    """`multidof analyze --scene S` (Theorem 5's (16)) on `symmetry`'s scenes made Theorem 5's:
    every device a mass-damper with b > 0 (OSP: Assumption 1(a)) and an operator on every DOF, the
    classes as drawn there (issue 48 item 2: (16) split by multidof/symmetry.hpp)."""
    c = case_symmetry(rng)
    fresh, ops = {}, {}
    devices = []
    for d, o in zip(c["devices"], c["ops"]):
        if id(d) not in fresh:  # one new device (and operator) per class: the classes stay alike
            fresh[id(d)] = dict(kind="md", m=d["m"], b=d["b"] if d["kind"] == "md" and d["b"] > 0 else IL.rq(rng, 0.5, 5))
            ops[id(d)] = o if o is not None else IL.rq(rng, 0.5, 5)
        devices.append(fresh[id(d)])
    c["ops"] = [ops[id(d)] for d in c["devices"]]
    c["devices"] = devices
    c["tags"]["first class"] = "mass-damper"
    return c


def check_symmetry16(c, exe, timeout):
    text = IL.scene_toml(c)
    with tempfile.NamedTemporaryFile("w", suffix=".toml", delete=False, prefix="indep_symmetry16_") as f:
        f.write(text)
    cert = f.name[:-5] + ".json"
    args = ["multidof", "analyze", "--scene", f.name, "--quiet"]
    rc, j, err, dt = run_hapstab(exe, args, timeout)
    rcw, jw, errw, dtw = run_hapstab(exe, args + ["--no-symmetry"], timeout)
    cert_err = ""
    if (j or {}).get("path") == "symmetry":  # its certificate: the lifted point or witness (else another kind, or none yet)
        cert_err = run_hapstab(exe, args + ["--certificate", cert], timeout)[2]
    tags = dict(c["tags"])
    tags["hapstab path"] = "symmetry" if (j or {}).get("path") == "symmetry" else "whole"
    out = dict(tags=tags, rc=rc, seconds=dt, margin=None, scene=text, args=args)
    v, vw = (j or {}).get("verdict"), (jw or {}).get("verdict")
    cw = bool((jw or {}).get("certified"))
    tags["whole program"] = f"{vw} ({'certified' if cw else 'numeric'})"
    out["ref_text"] = f"--no-symmetry: exit {rcw}, {tags['whole program']}"
    if rc == "timeout" or rcw == "timeout":
        out["outcome"] = "timeout"
    elif j is None or jw is None:
        out.update(outcome="refused" if rc == 2 else "MISS", why=why_of(err, j) or f"exit {rc}")
    elif tags["hapstab path"] == "whole":
        same = v == vw and j.get("certified") == jw.get("certified")
        out.update(outcome="agree" if same else "MISS",
                   why="" if same else f"not split: {v} ({j.get('certified')}), --no-symmetry {vw} ({cw})")
    elif v not in ("feasible", "infeasible") or not j.get("certified"):
        out.update(outcome="MISS", why=f"the split decided {v} (certified {j.get('certified')}): it decides only certified verdicts")
    elif cw and vw != v:
        out.update(outcome="MISS", why=f"the split: {v}, the whole program certified {vw}")
    elif not os.path.exists(cert) and "the checker does not take this model" in cert_err:
        tags["independent checker"] = "no certificate: the kind's stated limit"  # (a non-symmetric E(1) before stop 66)
        out["outcome"] = "agree"
    elif not os.path.exists(cert):
        out.update(outcome="MISS", why=f"a certified {v} verdict without its certificate: {cert_err[-300:]}")
    else:  # the lifted point or witness, checked by both checkers (neither knows of the split)
        blocks = [b for b in j["symmetry"]["blocks"] if b["verdict"] == "infeasible"]
        tags["split verdict"] = v if v == "feasible" else v + (" (fixed space)" if blocks and blocks[-1]["name"].startswith("the fixed")
                                                              else " (a class's zero-sum space)")
        ck = subprocess.run([exe, "check", cert], capture_output=True, text=True)
        py = subprocess.run([sys.executable, str(ROOT / "checks" / "hapstab_check.py"), cert], capture_output=True, text=True)
        with open(cert) as fc:
            tags["certificate"] = json.load(fc)["kind"]  # the lifted point, or block by block beyond order 40
        tags["independent checker"] = {0: "verified", 3: "beyond its size limit"}.get(py.returncode, "refuted")
        if ck.returncode != 0 or py.returncode not in (0, 3):
            out.update(outcome="MISS", why=f"the lifted point: hapstab check exit {ck.returncode} ({ck.stdout.strip()[:200]}); "
                                           f"the independent checker exit {py.returncode} ({py.stdout.strip()[:200]})")
        else:
            out["outcome"] = "agree"
    keep_scene_if_missed(out, f.name, cert)
    return out


BRANCHES_SYMMETRY16 = [  # compared cases
    ("hapstab path", "symmetry", 0.25), ("split verdict", "feasible", 0.1), ("split verdict", "infeasible (fixed space)", 0.02), ("independent checker", "verified", 0.15), ("N", "16-32", 0.05),
    ("classes", "3", 0.1), ("a class of one", True, 0.05), ("delay", "1", 0.05),
    ("certificate", "multidof-feasible-symmetric", 0.01),
]


def case_design16(rng):
    """`multidof design --scene S` (Theorem 6) on `symmetry16`'s scenes: designed on the split by
    the permutations of identical DOFs (multidof/design_symmetry.cpp, issue 48 item 2)."""
    return case_symmetry16(rng)


def coupled_loop_rho(c, V):
    """The spectral radius (double) of the scene's loop with the coupling V = (A, B, C, D) (numpy),
    built here from the scene (indep_loop's ZOH plant and E realised entry by entry): the force on
    the devices is F = z^-n E (x - V F) (the environment sees the positions less V's output, V is
    fed the applied force); the devices get -F (indep_loop.Loop's sign: F = -h)."""
    Phi, Gam, Cy = (np.array(X.tolist(), dtype=float) for X in IL.scene_plant(c))
    Ae, Be, Ce, De = (np.array(X.tolist(), dtype=float).reshape(X.rows, X.cols) for X in IL.realize_matrix(c["E"]))
    Av, Bv, Cv, Dv = V
    N, ne, nv, n = De.shape[0], Ae.shape[0], Av.shape[0], c["n"]
    Z = np.zeros
    if n == 0:  # F = W (Ce xe + De y - De Cv xv), W = (I + De Dv)^-1
        W = np.linalg.inv(np.eye(N) + De @ Dv)
        A = np.block([[Ae - Be @ Dv @ W @ Ce, -Be @ Cv + Be @ Dv @ W @ De @ Cv], [Bv @ W @ Ce, Av - Bv @ W @ De @ Cv]])
        B = np.vstack([Be - Be @ Dv @ W @ De, Bv @ W @ De])
        C = np.hstack([W @ Ce, -W @ De @ Cv])
        D = W @ De
    else:  # state [xe; s_1 .. s_n; xv], F = s_n, the environment's input y - Cv xv - Dv s_n
        k = ne + n * N + nv
        A = Z((k, k))
        B = Z((k, N))
        last = ne + (n - 1) * N
        A[:ne, :ne] = Ae
        A[:ne, ne + n * N:] = -Be @ Cv
        A[:ne, last:last + N] += -Be @ Dv
        B[:ne] = Be
        A[ne:ne + N, :ne] = Ce
        A[ne:ne + N, ne + n * N:] = -De @ Cv
        A[ne:ne + N, last:last + N] += -De @ Dv
        B[ne:ne + N] = De
        for s_ in range(1, n):
            A[ne + s_ * N:ne + (s_ + 1) * N, ne + (s_ - 1) * N:ne + s_ * N] = np.eye(N)
        A[ne + n * N:, ne + n * N:] = Av
        A[ne + n * N:, last:last + N] = Bv
        C = Z((N, k))
        C[:, last:last + N] = np.eye(N)
        D = Z((N, N))
    M = np.block([[Phi - Gam @ D @ Cy, -Gam @ C], [B @ Cy, A]])
    return float(np.max(np.abs(np.linalg.eigvals(M))))


def positive_x_symmetrising(E):
    """Whether some g > 0 makes diag(g) E(1) symmetric (g_i E1_ij = g_j E1_ji for all i, j), E(1)
    exact from the entries (Fractions), by ratios along a spanning forest: the facial condition of
    Theorem 5's (16) read from the scene here, knowing nothing of hapstab's split."""
    N = len(E)
    E1 = [[sum(e.num) / sum(e.den) for e in row] for row in E]
    ratio = [None] * N  # g_i = ratio[i] * g_root(i), on each connected part
    root = list(range(N))
    for s0 in range(N):
        if ratio[s0] is not None:
            continue
        ratio[s0], stack = Q(1), [s0]
        while stack:
            i = stack.pop()
            for j in range(N):
                a, b = E1[i][j], E1[j][i]
                if i == j or (a == 0 and b == 0):
                    continue
                if a == 0 or b == 0 or a * b < 0:  # one side zero, or g_i / g_j = b / a < 0
                    return False
                r = ratio[i] * a / b  # g_j = g_i a / b
                if ratio[j] is None:
                    ratio[j], root[j] = r, s0
                    stack.append(j)
                elif ratio[j] != r:
                    return False
    return True


def check_design16(c, exe, timeout):
    text = IL.scene_toml(c)
    with tempfile.NamedTemporaryFile("w", suffix=".toml", delete=False, prefix="indep_design16_") as f:
        f.write(text)
    args = ["multidof", "design", "--scene", f.name, "--quiet", "--duration", "0.01"]
    rc, j, err, dt = run_hapstab(exe, args, timeout)
    # the whole design beside it where it is quick (its generic CCL grows like N^6: design.hpp)
    N = len(c["devices"])
    rcw, jw = run_hapstab(exe, args + ["--no-symmetry"], timeout)[:2] if N <= 6 else ("not run (N > 6)", None)
    split = ((j or {}).get("path") or "").startswith("symmetry")
    tags = dict(c["tags"])
    tags["hapstab path"] = "symmetry" if split else ((j or {}).get("path") or "none")
    tags["split verdict"] = "none"
    out = dict(tags=tags, rc=rc, seconds=dt, margin=None, scene=text, args=args)
    concl = lambda x: ("V verified" if x.get("stability_concluded") else
                       "convex part infeasible" if x.get("convex_certified") else "no conclusion")
    tags["whole design"] = concl(jw) if jw else f"exit {rcw}"
    out["ref_text"] = f"--no-symmetry: exit {rcw}, {tags['whole design']}"
    if rc == "timeout" or rcw == "timeout":
        out.update(outcome="timeout", why="the split" if rc == "timeout" else "--no-symmetry")
    elif j is None:
        out.update(outcome="refused" if rc == 2 else "MISS", why=why_of(err, j) or f"exit {rc}")
    elif not split and jw is None:
        out.update(outcome="not compared", why=f"not split ({(j.get('plan') or [{}])[0].get('why', '')[:200]}), N > 6")
    elif not split:
        same = jw is not None and concl(j) == concl(jw)
        out.update(outcome="agree" if same else "MISS",
                   why="" if same else f"not split: {concl(j)}, --no-symmetry {tags['whole design']}")
    elif j.get("path") == "symmetry of identical DOFs (facial conditions)":  # (19) infeasible, exactly
        tags["split verdict"] = "convex part infeasible"
        if not j.get("convex_certified"):
            out.update(outcome="MISS", why=f"the split's facial conditions without a certified infeasible verdict: {j.get('verdict')}")
        elif positive_x_symmetrising(c["E"]):
            out.update(outcome="MISS", why="the split says no X > 0 makes X E(1) symmetric; the scene's E(1) admits one")
        elif jw is not None and jw.get("stability_concluded"):
            out.update(outcome="MISS", why="the split proves (19) infeasible, the whole design verified a V")
        else:
            out["outcome"] = "agree"
    elif j.get("path") == "symmetry of identical DOFs (Theorem 5's (16))":  # (19) infeasible as (16) is
        tags["split verdict"] = "(16) infeasible"
        cert = f.name[:-5] + ".json"
        args16 = ["multidof", "analyze", "--scene", f.name, "--quiet"]
        ran = run_hapstab(exe, args16, timeout)
        cert_err = run_hapstab(exe, args16 + ["--certificate", cert], timeout)[2]
        ck = subprocess.run([exe, "check", cert], capture_output=True, text=True) if os.path.exists(cert) else None
        py = subprocess.run([sys.executable, str(ROOT / "checks" / "hapstab_check.py"), cert], capture_output=True,
                            text=True) if os.path.exists(cert) else None
        if not j.get("convex_certified") or (ran[1] or {}).get("verdict") != "infeasible":
            out.update(outcome="MISS", why=f"design: {j.get('verdict')}; analyze: {(ran[1] or {}).get('verdict')}")
        elif ck is None and "the checker does not take this model" in cert_err:
            tags["independent checker"] = "no certificate: the kind's stated limit"
            out["outcome"] = "agree"
        elif ck is None:
            out.update(outcome="MISS", why=f"a certified infeasible (16) without its certificate: {cert_err[-300:]}")
        elif ck.returncode != 0 or (py is not None and py.returncode not in (0, 3)):
            out.update(outcome="MISS", why=f"the analysis's certificate: hapstab check exit {ck.returncode}, independent {py.returncode}")
        elif jw is not None and jw.get("stability_concluded"):
            out.update(outcome="MISS", why="the split proves (16) infeasible, the whole design verified a V")
        else:
            tags["independent checker"] = {0: "verified", 3: "beyond its size limit"}.get(py.returncode, "refuted")
            out["outcome"] = "agree"
    elif not (j.get("stability_concluded") and j.get("certified")):
        out.update(outcome="MISS", why=f"the split decided without a certified, verified V: {j.get('verdict')}")
    elif jw is not None and jw.get("convex_certified"):
        out.update(outcome="MISS", why="the split verified a V, the whole design proves its convex part infeasible")
    else:  # the designed V in the loop built here, which knows nothing of the split
        tags["split verdict"] = "V verified"
        nv, N = len(j["B_V"]), len(j["D_V"])  # V's doubles are its exact dyadic entries (design.hpp)
        V = tuple(np.array(j[k], dtype=float).reshape(r, cl)
                  for k, r, cl in (("A_V", nv, nv), ("B_V", nv, N), ("C_V", N, nv), ("D_V", N, N)))
        rho = coupled_loop_rho(c, V)
        out["margin"] = abs(1 - rho)
        out["ref_text"] += f"; the loop with the designed V built here: rho = {rho!r}"
        tags["reference"] = "within 1e-9 of 1" if abs(1 - rho) < 1e-9 else ("stable" if rho < 1 else "NOT stable")
        # its certificate (multidof-coupling: Theorem 4's program on the whole for that V), both checkers
        cert = f.name[:-5] + ".coupling.json"
        rcc, _, errc, _ = run_hapstab(exe, args + ["--certificate", cert], timeout)
        ck = subprocess.run([exe, "check", cert], capture_output=True, text=True) if os.path.exists(cert) else None
        py = subprocess.run([sys.executable, str(ROOT / "checks" / "hapstab_check.py"), cert], capture_output=True,
                            text=True) if os.path.exists(cert) else None
        tags["certificate"] = ("refused by name" if rcc == 2 and "no certificate" in errc else
                               "timeout" if rcc == "timeout" else f"none (exit {rcc})") if ck is None \
            else "verified by both" if ck.returncode == 0 and py.returncode == 0 \
            else "verified (beyond the independent checker's size)" if ck.returncode == 0 and py.returncode == 3 else "REFUTED"
        if abs(1 - rho) < 1e-9:
            out.update(outcome="reference too near the circle", why=f"rho = {rho!r}")
        elif rho >= 1:
            out.update(outcome="MISS", why=f"a verified V, but the loop with it built here has rho = {rho!r}")
        elif tags["certificate"] == "timeout":
            out.update(outcome="timeout", why="the designed V's certificate (Theorem 4's program on the whole)")
        elif tags["certificate"] == "REFUTED" or tags["certificate"].startswith("none"):
            out.update(outcome="MISS", why=f"the designed V's certificate: {tags['certificate']} "
                                           f"(hapstab check {ck and ck.stdout.strip()[:150]}; {errc[-200:]})")
        else:
            out["outcome"] = "agree"
    keep_scene_if_missed(out, f.name, f.name[:-5] + ".json", f.name[:-5] + ".coupling.json")
    return out


BRANCHES_DESIGN16 = [  # compared cases
    ("hapstab path", "symmetry", 0.3), ("reference", "stable", 0.2), ("split verdict", "convex part infeasible", 0.05), ("N", "16-32", 0.05), ("classes", "3", 0.1),
    ("a class of one", True, 0.05), ("delay", "1", 0.05), ("certificate", "verified by both", 0.05),
]


BRANCHES_SCENE = [  # compared cases: a supremum, or an exit 3's "stable on [a, b]" (checked at 5 points of it)
    ("stable at small g", True, 0.2), ("stable at small g", False, 0.05),
    ("first device", "unstable ss", 0.1), ("crossing", "complex", 0.05), ("delay", "0", 0.3),
]


# ---------------------------------------------------------------------------------------------
# stability --scene S --max g with a [coupling], or g not of degree 1 (bisection on verdicts)


def short_decimal(x, digits=2):
    """x > 0 rounded to `digits` significant digits, as a plain decimal string (no exponent)."""
    e = math.floor(math.log10(x)) - (digits - 1)
    mant = round(x / 10 ** e)
    q = Q(mant) * (Q(10) ** e)
    s = f"{q.numerator}" if q.denominator == 1 else None
    if s is None:  # q = mant / 10^-e exactly: write it with -e decimals
        k = -e
        whole, frac = divmod(mant, 10 ** k)
        s = f"{whole}.{str(frac).rjust(k, '0')}"
    return s


def case_scene_coupling(rng):
    c = ICP.gen_coupled(rng)
    loop = ICP.CoupledLoop(c)
    stable_small, cross = ICP.first_crossing_double(loop)
    c["loop"] = loop
    c["cross"] = cross
    # the scene's value of g (where the bisection starts): near the double-precision boundary in
    # 80% (within a factor 16 either side), else 1
    if cross is not None and rng.random() < 0.8:
        c["gref"] = short_decimal(cross * 2 ** rng.uniform(-4, 4))
    else:
        c["gref"] = "1"
    c["Knom"] = 1.0
    return c


def check_claim_points(loop, pts, want_stable):
    """rho at 50 digits at each point; the first point where the claim fails, or None."""
    for g in pts:
        r = IL.rho_mp(loop, g)[0]
        if (r < 1) != want_stable:
            return g, r
    return None


def verdicts_certificate(exe, path, c, timeout, tags):
    """Since stop 78 the bisection's answer writes kind stability-loop-verdicts: the same command with --certificate,
    the certificate through both checkers (the verdicts themselves are compared with the loop built here above).
    A refusal by name is counted apart; a refuted or malformed certificate, or a claimed value that is not among the
    answer's, is a miss (returned as its reason)."""
    cert = path[:-5] + ".verdicts.json"
    r = run_hapstab(exe, ["stability", "--scene", path, "--max", "g", "--digits", "25", "--certificate", cert], timeout)
    if not os.path.exists(cert):
        # exit 3 without one: the answer undecided (stable at lo, the next value undecided), which has none
        tags["verdicts certificate"] = {2: "refused by name", 3: "none (undecided)"}.get(r[0], "not written (exit %s)" % r[0])
        return None if r[0] in (2, 3) else "no certificate of the bisection's verdicts (exit %s): %s" % (r[0], r[2][-200:])
    codes = [subprocess.run(cmd + [cert], capture_output=True, text=True).returncode
             for cmd in ([exe, "check"], [sys.executable, str(ROOT / "checks" / "hapstab_check.py")])]
    os.unlink(cert)
    if codes != [0, 0]:
        return "the bisection's verdicts certificate: hapstab check exit %d, independent %d" % tuple(codes)
    tags["verdicts certificate"] = "verified by both"
    return None


def check_scene_coupling(c, exe, timeout):
    text = ICP.scene_toml(c, c["gref"])
    rc, j, err, dt, args, path = run_hapstab_scene(exe, text, "indep_coupled_", ["--max", "g", "--digits", "25"], timeout)
    loop = c["loop"]
    tags = dict(c["tags"])
    gref = dec(c["gref"])
    out = dict(tags=tags, rc=rc, seconds=dt, scene=text, args=args)
    # distance from the boundary: |1 - rho| at the scene's value of g, the first value decided
    r0 = IL.rho_np(loop, float(gref))
    out["margin"] = 1 - r0
    # the values the bisection can try are g_ref 2^k, |k| <= 10: a boundary outside them cannot be found
    cr = c.get("cross")
    inside = cr is not None and float(gref) / 1024 <= cr <= float(gref) * 1024
    tags["boundary within g_ref 2^-10..2^10"] = inside
    if not inside:
        out["margin"] = None
    tags["stable at the scene's g"] = r0 < 1
    hpath = j.get("path") if j else None
    tags["path"] = hpath or ("none" if rc not in ("timeout", 2) else str(rc))
    out["ref_text"] = f"rho = {r0:.12g} at the scene's g = {c['gref']}"
    if rc == "timeout":
        out["outcome"] = "timeout"
    elif rc == 2:
        out["outcome"] = "refused"
        out["why"] = why_of(err, j)
    elif j is None:
        out["outcome"] = "MISS"
        out["why"] = f"exit {rc}, no JSON: {err[-300:]}"
    elif hpath == "bisection_on_verdicts":
        # the claims: a certified "stable" at stable_at, a certified "NOT stable" at unstable_at;
        # exit 1: NOT stable at every value tried (g_ref 2^-k, k = 0..10); nothing between them
        sa, ua = j.get("stable_at"), j.get("unstable_at")
        bad = []
        if sa:
            f_ = check_claim_points(loop, [dec(sa["at"])], True)
            if f_:
                bad.append(f"hapstab: stable at g = {sa['at']} [{sa.get('status')}], but rho = {mp.nstr(f_[1], 20)}")
        if ua:
            f_ = check_claim_points(loop, [dec(ua["at"])], False)
            if f_:
                bad.append(f"hapstab: NOT stable at g = {ua['at']} [{ua.get('status')}], but rho = {mp.nstr(f_[1], 20)}")
        if rc == 1:
            f_ = check_claim_points(loop, [gref / 2 ** k for k in range(11)], False)
            if f_:
                bad.append(f"hapstab: NOT stable at every value tried (g_ref 2^-k), but rho = {mp.nstr(f_[1], 20)} at g = {mp.nstr(f_[0], 20)}")
        if rc == 0 and not (sa and ua):
            bad.append("exit 0 without a certified bracket (stable_at and unstable_at)")
        if rc in (0, 1) or (rc == 3 and sa):
            cert_bad = verdicts_certificate(exe, path, c, timeout, tags)
            if cert_bad:
                bad.append(cert_bad)
        if rc == 0 and sa and ua:
            tags["bisection"] = "bracket"
        elif rc == 1:
            tags["bisection"] = "NOT stable at every value tried"
        else:
            tags["bisection"] = "exit 3, stable_at only" if sa else f"exit {rc}, no verdict claim"
        if bad:
            out["outcome"] = "MISS"
            out["why"] = "; ".join(bad)
        elif rc in (0, 1):
            out["outcome"] = "agree"
        elif rc == 3:
            out["outcome"] = "undecided"
            out["why"] = why_of(err, j)[:200] + (" (its claim stable_at checked: holds)" if sa else "")
        else:
            out["outcome"] = "MISS"
            out["why"] = f"exit {rc}"
    else:
        # the certified crossing of an affine loop (closed_loop_matrix): a proven supremum, or
        # exit 3 with an interval proven stable (checked at five points), or sup 0 with exit 1
        ref = IL.sup_reference(loop, c["Knom"])
        tag_reference(ref, tags, out, "g")
        tags["stable at small g"] = ref["kind"] in ("sup", "inf")
        if rc == 3:
            out["outcome"] = "undecided"
            out["why"] = why_of(err, j)[:200]
            if j.get("stable_on"):
                a, b = enc(j, "stable_on")
                f_ = check_claim_points(loop, [x for x in (a + (b - a) * t for t in (0, 0.25, 0.5, 0.75, 1)) if x > 0], True)
                if f_:
                    out["outcome"] = "MISS"
                    out["why"] = f"hapstab proves stable on [{a}, {b}], but rho = {mp.nstr(f_[1], 20)} >= 1 at g = {mp.nstr(f_[0], 20)}"
                else:
                    out["why"] += " (its claim stable_on checked at 5 points: holds)"
        else:
            compare_sup(out, ref, j, rc, TOL_SUP, "g")
    keep_scene_if_missed(out, path)
    return out


BRANCHES_SCENE_COUPLING = [  # compared: a verdict bracket, exit 1's NOT-stable values, or a supremum
    ("path", "bisection_on_verdicts", 0.3), ("path", "closed_loop_matrix", 0.05),
    ("bisection", "bracket", 0.15), ("bisection", "NOT stable at every value tried", 0.02),
    ("g in", "env g, V with feedthrough", 0.1), ("g in", "coupling 1/g", 0.08), ("g in", "coupling g", 0.02),
    ("g in", "env g(1+g)/2", 0.05), ("g in", "env g, V strictly proper", 0.03),
    ("first device", "unstable ss", 0.1), ("delay", "1", 0.03), ("coupling", "feedthrough, cross term", 0.02),
]


# ---------------------------------------------------------------------------------------------
# stability --scene S on loops of order 49..64 (the exact charpoly beyond order 48)


def case_charpoly(rng):
    c = ICH.gen_charpoly(rng)
    k, kind = ICH.crossing_gain(c)
    u = rng.random()
    if k is None:
        g = short_decimal(10 ** rng.uniform(-2, 1))
        c["tags"]["gain"] = "no crossing in [1e-3, 1e5]"
    elif u < 0.3:  # within 1e-6 relative of the double-precision crossing: 8 digits
        g = short_decimal(k * (1 + rng.uniform(-1e-6, 1e-6)), digits=8)
        c["tags"]["gain"] = "1e-6 from the crossing"
    else:
        g = short_decimal(k * 2 ** rng.uniform(-4, 2))
        c["tags"]["gain"] = "1/16 to 4 times the crossing"
    c["g"] = g
    c["whole_matrix"] = rng.random() < 0.5  # drawn last: the cases before this draw are unchanged
    return c


def check_charpoly(c, exe, timeout):
    text = ICH.scene_toml(c, c["g"])
    # identical DOFs are split by their symmetry (stability/symmetry.hpp) unless --no-symmetry: half
    # of those cases keep the whole matrix, so both paths meet the reference
    whole = c["tags"]["DOFs"] == "random" or c.get("whole_matrix", False)
    rc, j, err, dt, args, path = run_hapstab_scene(exe, text, "indep_charpoly_", ["--no-symmetry"] if whole else [], timeout)
    tags = dict(c["tags"])
    out = dict(tags=tags, rc=rc, seconds=dt, scene=text, args=args)
    t0 = time.monotonic()
    M = ICH.exact_M(c, Q(c["g"]))
    p = ICH.hessenberg_charpoly(M)
    st = ICH.schur_cohn(p)
    rho = ICH.rho_double(M)
    out["ref_seconds"] = time.monotonic() - t0
    out["margin"] = 1 - rho
    tags["reference"] = "stable" if st else "NOT stable"
    out["ref_text"] = (f"{'stable' if st else 'NOT stable'} (Schur-Cohn on det(zI - M) of degree {len(p) - 1}, in fractions); "
                       f"rho = {rho:.15g} in double")
    states = j.get("states") if j else None
    method = (j.get("method") or "") if j else ""
    exact_cp = "Schur-Cohn on det(zI - M)" in method
    tags["hapstab path"] = ("exact charpoly, order > 48" if exact_cp and states and states > 48 else
                            "exact charpoly, order <= 48" if exact_cp else
                            "symmetry" if j and j.get("path") == "symmetry" else (method or "none"))
    if abs(1 - rho) > 1e-8 and (rho < 1) != st:
        out["outcome"] = "REFERENCE MISSED"
        out["why"] = f"the reference disagrees with itself: exact {'stable' if st else 'NOT stable'}, rho = {rho!r} in double"
    elif rc == "timeout":
        out["outcome"] = "timeout"
    elif rc == 2:
        out["outcome"] = "refused"
        out["why"] = why_of(err, j)
    elif j is None or rc not in (0, 1, 3):
        out["outcome"] = "MISS"
        out["why"] = f"exit {rc}, no JSON: {err[-300:]}"
    elif j.get("stable") is None:
        out["outcome"] = "undecided"
        out["why"] = why_of(err, j)[:200]
    else:
        hs = bool(j["stable"])
        out["hapstab"] = f"{'stable' if hs else 'NOT stable'} [{j.get('status')}], {states} states, {method}"
        if hs == st and rc == (0 if hs else 1):
            out["outcome"] = "agree"
        else:
            out["outcome"] = "MISS"
            out["why"] = f"hapstab: {out['hapstab']} (exit {rc}); the reference: {out['ref_text']}"
    keep_scene_if_missed(out, path)
    return out


BRANCHES_CHARPOLY = [  # compared verdicts
    ("hapstab path", "exact charpoly, order > 48", 0.35), ("hapstab path", "exact charpoly, order <= 48", 0.1),
    ("hapstab path", "symmetry", 0.1),
    ("reference", "stable", 0.15), ("reference", "NOT stable", 0.15),
    ("DOFs", "identical, uncoupled", 0.2), ("DOFs", "identical, linked", 0.05), ("DOFs", "random", 0.2),
    ("gain", "1e-6 from the crossing", 0.15), ("DOF", "3", 0.1),
]


# ---------------------------------------------------------------------------------------------
# stability --scene S --max g --conservatism: exact / Theorem 5, where both are suprema of intervals


def case_conservatism(rng):
    c = ICP.gen_coupled(rng, conservatism=True)
    c["loop"] = ICP.CoupledLoop(c)
    c["Knom"] = 1.0
    return c


def dc_condition_fails(c):
    """Lemma 1's DC condition, independently: (V(1) - K)_jj <= 0 for some j, K_jj = T/(2 Delta_j),
    Delta_j = b_j (a mass-damper 1/(m s + b) is OSP with level b). V(1) from the scene's entries."""
    T = c["T"]
    for j, d in enumerate(c["devices"]):
        e = c["V"][j][j]
        v1 = sum(e.num) / sum(e.den)
        if v1 - T / (2 * Q(d["b"])) <= 0:
            return True
    return False


def check_conservatism(c, exe, timeout):
    text = ICP.scene_toml(c, "1")
    rc, j, err, dt, args, path = run_hapstab_scene(exe, text, "indep_conservatism_", ["--max", "g", "--conservatism", "--digits", "3"], timeout)
    loop = c["loop"]
    tags = dict(c["tags"])
    out = dict(tags=tags, rc=rc, seconds=dt, scene=text, args=args, margin=None)
    ref = IL.sup_reference(loop, c["Knom"])
    tag_reference(ref, tags, out, "g")
    if rc == "timeout":
        out["outcome"] = "timeout"
    elif rc == 2:
        out["outcome"] = "refused"
        out["why"] = why_of(err, j)
    elif j is None:
        out["outcome"] = "MISS"
        out["why"] = f"exit {rc}, no JSON: {err[-300:]}"
    else:
        bad = []
        # 1. the exact side, as scene_max (a supremum, or exit 3 with an interval proven stable)
        if j.get("supremum_proven"):
            sub = dict(tags={}, margin=None)
            compare_sup(sub, ref, j, 0 if j.get("max") not in (None, "0") else 1, TOL_SUP, "g")
            tags["exact side"] = "supremum"
            if sub["outcome"] != "agree":
                bad.append("exact side: " + sub.get("why", sub["outcome"]))
        else:
            tags["exact side"] = "sup 0" if j.get("max") == "0" else "undecided"
            if j.get("max") == "0" and ref["kind"] in ("sup", "inf"):
                bad.append(f"exact side: sup 0, but the reference is stable at small g ({ref['kind']})")
            if j.get("stable_on"):
                a, b = enc(j, "stable_on")
                f_ = check_claim_points(loop, [x for x in (a + (b - a) * t for t in (0, 0.25, 0.5, 0.75, 1)) if x > 0], True)
                if f_:
                    bad.append(f"exact side: stable on [{a}, {b}] claimed, but rho = {mp.nstr(f_[1], 20)} at g = {mp.nstr(f_[0], 20)}")
        # 2. Theorem 5 is sound: where it concludes, the loop is stable, and (g being the environment's
        #    gain, its region an interval (0, sup]) so is every smaller g: concludes_at <= the exact sup
        t5 = j.get("theorem5") or {}
        ca, na = t5.get("concludes_at"), t5.get("not_at")
        tags["Theorem 5"] = "bracket" if t5.get("bracket") else ("concludes, no upper end" if ca else "no conclusion")
        if ca:
            g5 = dec(ca["at"])
            f_ = check_claim_points(loop, [g5 * t for t in (1, 0.5, 0.1, 0.01)], True)
            if f_:
                bad.append(f"Theorem 5 concludes at g = {ca['at']}, but rho = {mp.nstr(f_[1], 20)} >= 1 at g = {mp.nstr(f_[0], 20)}")
            if ref["kind"] == "sup" and g5 > ref["hi"] * (1 + TOL_SUP):
                bad.append(f"Theorem 5 concludes at g = {ca['at']}, above the reference's first crossing {mp.nstr(ref['hi'], 20)}")
        if na:
            why5 = na.get("why", "")
            if "NOT stable" in why5:
                f_ = check_claim_points(loop, [dec(na["at"])], False)
                if f_:
                    bad.append(f"Theorem 5: the loop is NOT stable at g = {na['at']} claimed, but rho = {mp.nstr(f_[1], 20)}")
                tags["Theorem 5's upper end"] = "loop NOT stable (checked)"
            elif "DC condition" in why5:
                if not dc_condition_fails(c):
                    bad.append(f"Theorem 5: Lemma 1's DC condition claimed to fail at g = {na['at']}, but (V(1) - K)_jj > 0 for every j")
                tags["Theorem 5's upper end"] = "DC condition (checked)"
            else:
                tags["Theorem 5's upper end"] = "program infeasible (not referenced: no independent LMI solver)"
        # 3. the ratio: printed only where both sides are suprema of intervals; it must hold
        #    exact_sup / [t5 lo, t5 hi], the exact sup the reference's
        r = j.get("conservatism")
        tags["ratio"] = r is not None
        if r is not None:
            if not (j.get("supremum_proven") and t5.get("bracket")):
                bad.append("a ratio printed without both suprema proven")
            elif ref["kind"] == "sup":
                rl, rh = dec(r[0]), dec(r[1])
                t5l, t5h = enc(t5, "bracket")
                need_lo, need_hi = ref["lo"] / t5h, ref["hi"] / t5l
                if rl > need_lo * (1 + TOL_SUP) or rh < need_hi * (1 - TOL_SUP):
                    bad.append(f"ratio [{r[0]}, {r[1]}] does not hold the reference's sup / Theorem 5's bracket, "
                               f"[{mp.nstr(need_lo, 12)}, {mp.nstr(need_hi, 12)}]")
        if bad:
            out["outcome"] = "MISS"
            out["why"] = "; ".join(bad)
        elif j.get("supremum_proven") or tags.get("ratio"):
            out["outcome"] = "agree"
        elif rc == 3:
            out["outcome"] = "undecided"
            out["why"] = (j.get("note") or "")[:200]
        else:
            out["outcome"] = "agree"  # sup 0 with exit 1, checked above
        if ref["kind"] == "sup":
            out["margin"] = 1 - IL.rho_np(loop, float(ref["lo"]) / 2)
    keep_scene_if_missed(out, path)
    return out


BRANCHES_CONSERVATISM = [
    ("exact side", "supremum", 0.5), ("Theorem 5", "bracket", 0.05), ("ratio", True, 0.05),
]


# ---------------------------------------------------------------------------------------------
# multidof analyze --scene S: (16) infeasible by the frequency-domain witness, or feasible


def case_witness(rng):
    c = IW.gen(rng)
    return c


def check_analyze(c, exe, timeout, prefix, ref):
    """`multidof analyze --scene S --json` on the case's scene text and the reference module `ref`'s
    decide (indep_witness, indep_coupling): the case's outcome."""
    import tempfile
    with tempfile.NamedTemporaryFile("w", suffix=".toml", delete=False, prefix=prefix) as f:
        f.write(c["text"])
    args = ["multidof", "analyze", "--scene", f.name]
    rc, j, err, dt = run_hapstab(exe, args, timeout)
    out = dict(tags=dict(c["tags"]), rc=rc, seconds=dt, margin=None, scene=c["text"], args=args)
    if rc == "timeout":
        out["outcome"] = "timeout"
    elif rc == 2:
        out.update(outcome="refused", why=why_of(err, j))
    elif j is None or rc not in (0, 1, 3):
        out.update(outcome="MISS", why=f"exit {rc}, no JSON: {err[-300:]}")
    else:
        r = ref.decide(c, ref.SCENE(c["text"]), j, rc)
        r.update(seconds=dt, scene=c["text"], args=args)
        out = r
    keep_scene_if_missed(out, f.name)
    return out


def check_witness(c, exe, timeout):
    return check_analyze(c, exe, timeout, "indep_witness_", IW)


BRANCHES_WITNESS = [  # compared: hapstab's certified verdict of (16) against the reference's
    ("hapstab", "infeasible (witness)", 0.15), ("hapstab", "feasible", 0.2), ("witness verified", True, 0.15),
    ("witness at", "theta = pi", 0.01), ("witness at", "theta < 1e-3", 0.01), ("witness at", "interior", 0.03),
    ("reference minimiser", "theta = pi", 0.02), ("reference minimiser", "theta -> 0", 0.02),
    ("reference minimiser", "interior", 0.1), ("near the boundary", True, 0.1),
    ("family", "contact", 0.08), ("family", "two parts", 0.03), ("resonance near the circle", True, 0.03),
]


# ---------------------------------------------------------------------------------------------
# multidof analyze --scene S with a [coupling]: Theorem 4 for the scene's own coupling


def case_coupling_witness(rng):
    return ICW.gen(rng)


def check_coupling_witness(c, exe, timeout):
    return check_analyze(c, exe, timeout, "indep_coupling_", ICW)


BRANCHES_COUPLING_WITNESS = [  # compared: hapstab's certified verdict of Theorem 4 for the coupling
    ("hapstab", "feasible", 0.15), ("hapstab", "infeasible (witness)", 0.02), ("witness verified", True, 0.02),
    ("reference", "holds", 0.1), ("reference", "violated (witness)", 0.15), ("near the boundary", True, 0.05),
    ("DC condition fails", True, 0.02), ("cross-coupled V", True, 0.02), ("family", "contact", 0.05),
    ("family", "two parts", 0.05), ("family", "linked walls", 0.05),
]


CRITERIA = {
    "bound": (case_bound, check_bound, BRANCHES_BOUND),
    "bound_long": (case_bound_long, check_bound, BRANCHES_BOUND_LONG),
    "bound_max": (case_bound_max, check_bound_max, BRANCHES_BOUND_MAX),
    "stability_max": (case_stability, check_stability, BRANCHES_STABILITY),
    "stability_long": (case_stability_long, check_stability_long, BRANCHES_STABILITY_LONG),
    "scene_max": (case_scene, check_scene, BRANCHES_SCENE),
    "scene_coupling": (case_scene_coupling, check_scene_coupling, BRANCHES_SCENE_COUPLING),
    "charpoly": (case_charpoly, check_charpoly, BRANCHES_CHARPOLY),
    "symmetry": (case_symmetry, check_symmetry, BRANCHES_SYMMETRY),
    "symmetry16": (case_symmetry16, check_symmetry16, BRANCHES_SYMMETRY16),
    "design16": (case_design16, check_design16, BRANCHES_DESIGN16),
    "conservatism": (case_conservatism, check_conservatism, BRANCHES_CONSERVATISM),
    "witness": (case_witness, check_witness, BRANCHES_WITNESS),
    "coupling_witness": (case_coupling_witness, check_coupling_witness, BRANCHES_COUPLING_WITNESS),
}


MARGIN_TEXT = {  # what each criterion's distance from the boundary is (the default: 1 - rho at sup/2)
    "bound": "none: b* has no boundary",
    "bound_long": "none: b* has no boundary",
    "bound_max": "none",
    "scene_coupling": "|1 - rho| at the scene's value of g, the first value decided; n/a: no boundary within g_ref 2^-10..2^10 (double scan)",
    "charpoly": "1 - rho of M in double",
    "witness": "the reference's min over theta of lambda_min(He E-hat + Delta_D), relative to 1 + max Delta_D",
    "coupling_witness": "min(|mu|, |sigma|) of the reference, relative to 1 + max Delta_D",
}


def margin_bucket(m):
    if m is None:
        return "n/a"
    m = abs(m)
    for lim, name in ((1e-2, ">= 1e-2"), (1e-4, "1e-4..1e-2"), (1e-6, "1e-6..1e-4")):
        if m >= lim:
            return name
    return "< 1e-6"


def print_summary(crit, a, first, done, dt, slowest, counts, per_branch, undec_margin, partial=False):
    """The criterion's counts so far: at its end, and every --progress cases (a run cut short keeps them)."""
    n = len(done)
    head = "-- progress" if partial else "=="
    print(f"{head} {crit}: {n} cases (seed {a.seed}, first {first}), {dt:.1f} s, slowest case {slowest[1]} ({slowest[0]:.1f} s)")
    print("   outcomes: " + ", ".join(f"{o} {v}" for o, v in sorted(counts.items())))
    print("   per branch (compared = agree + miss; undecided/refused/timeout apart):")
    for (tag, val), cnt in sorted(per_branch.items(), key=lambda kv: (kv[0][0], str(kv[0][1]))):
        rest = ", ".join(f"{o} {v}" for o, v in sorted(cnt.items()) if o != "compared")
        print(f"     {tag} = {val}: compared {cnt['compared']} ({rest})")
    if undec_margin:
        print(f"   not decided by hapstab, by the reference's distance from the boundary ({MARGIN_TEXT.get(crit, '1 - rho at sup/2')}):")
        for (o, bk), v in sorted(undec_margin.items()):
            print(f"     {o}, {bk}: {v}")
    sys.stdout.flush()


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--hapstab", default="build/hapstab")
    ap.add_argument("--criterion", default="bound,bound_max,stability_max,scene_max,scene_coupling,charpoly,conservatism,witness,"
                                          "coupling_witness")
    ap.add_argument("--cases", type=int, default=100)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--first", type=int, default=0)
    ap.add_argument("--case", type=int, default=None)
    ap.add_argument("--timeout", type=float, default=60)
    ap.add_argument("--verbose", action="store_true")
    ap.add_argument("--certify-every", type=int, default=1,
                    help="bound, bound_long, bound_max: write and check the certificate of every K-th agreed case (the CI slice of bound_long: 5)")
    ap.add_argument("--max-seconds", type=float, default=None,
                    help="stop a criterion after this long and summarise the cases run (minimums scale to them)")
    ap.add_argument("--progress", type=int, default=1000,
                    help="print the counts so far every this many cases (0: only at the end)")
    a = ap.parse_args()
    CERTIFY["every"] = max(1, a.certify_every)
    mp.mp.dps = 60  # comparisons of 30-digit enclosures; the references set their own precision
    if not os.access(a.hapstab, os.X_OK):
        print(f"independent.py: --hapstab {a.hapstab}: not an executable", file=sys.stderr)
        return 2
    failed = False
    for crit in a.criterion.split(","):
        if crit not in CRITERIA:
            print(f"independent.py: unknown criterion '{crit}' (known: {', '.join(CRITERIA)})", file=sys.stderr)
            return 2
        gen, check, branches = CRITERIA[crit]
        ks = [a.case] if a.case is not None else range(a.first, a.first + a.cases)
        counts = collections.Counter()
        per_branch = collections.defaultdict(collections.Counter)
        undec_margin = collections.Counter()
        misses = []
        t0 = time.monotonic()
        slowest = (0, None)
        done = []
        for k in ks:
            if a.max_seconds is not None and time.monotonic() - t0 > a.max_seconds:
                print(f"   --max-seconds {a.max_seconds:g}: stopped after {len(done)} cases")
                break
            done.append(k)
            rng = random.Random(f"{a.seed}:{crit}:{k}")
            c = gen(rng)
            tc = time.monotonic()
            r = check(c, a.hapstab, a.timeout)
            el = time.monotonic() - tc
            if el > slowest[0]:
                slowest = (el, k)
            o = r["outcome"]
            counts[o] += 1
            compared = o in ("agree", "MISS", "REFERENCE MISSED")
            for tag, val in r["tags"].items():
                per_branch[(tag, val)][o] += 1
                if compared:
                    per_branch[(tag, val)]["compared"] += 1
            if o in ("undecided", "refused", "timeout", "reference undecided"):
                undec_margin[(o, margin_bucket(r.get("margin")))] += 1
            args = r.get("args", c.get("args"))
            line = shell_line(a.hapstab, args) if args else ""
            if o in ("MISS", "REFERENCE MISSED") or a.verbose or a.case is not None:
                print(f"[{crit} case {k}] {o}: {r.get('why', '')}")
                print(f"  command: {line}")
                print(f"  reference: {r.get('ref_text')}; hapstab: {r.get('hapstab')} (exit {r['rc']}, {r['seconds']:.2f} s)")
                print(f"  branches: {r['tags']}")
                if r.get("scene"):
                    print("  scene:\n    " + r["scene"].replace("\n", "\n    "))
                print(f"  rerun: tests/verify/independent.py --hapstab {a.hapstab} --criterion {crit} --seed {a.seed} --case {k}")
                sys.stdout.flush()
            elif o in ("undecided", "refused", "timeout", "unchecked", "reference undecided"):
                print(f"[{crit} case {k}] {o} (exit {r['rc']}): {r.get('why', '')[:200]}")
                print(f"  command: {line}")
                sys.stdout.flush()
            if o in ("MISS", "REFERENCE MISSED"):
                misses.append(k)
            if a.progress > 0 and len(done) % a.progress == 0 and len(done) < len(ks):
                print_summary(crit, a, ks[0], done, time.monotonic() - t0, slowest, counts, per_branch, undec_margin,
                              partial=True)
        dt = time.monotonic() - t0
        n = len(done)
        print_summary(crit, a, ks[0], done, dt, slowest, counts, per_branch, undec_margin)
        if a.case is None:
            for tag, val, share in branches:
                need = int(share * n)
                have = per_branch[(tag, val)]["compared"]
                flag = "" if have >= need else "   TOO FEW COMPARED"
                print(f"   minimum: {tag} = {val}: {have} compared, minimum {need}{flag}")
                if have < need:
                    failed = True
        if misses:
            failed = True
            print(f"   MISSES in cases {misses}")
        sys.stdout.flush()
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
