"""`stability --scene S --certificate` on multi-DOF scenes (kind stability-loop: the checkers build the
closed-loop matrix from the scene's text themselves, check/stability_loop_check.hpp and
checks/hapstab_check.py's loop_matrix) against the loop built in mpmath from the numbers drawn
(indep_loop.py's scene loop: ZOH by mpmath.expm, the environment realised entry by entry, spectral
radius at 50 digits), never from hapstab or its checkers.

Scenes: indep_loop.gen_scene's 2-3 DOF loops (diagonal walls K + B (z - 1)/(T z), a linking spring
in 40 %, operator dampers or damper-springs, delays 0-2; the first device an ss block in 80 %, open-loop
unstable in 60 %) and, every other case, indep_coupled's with a [coupling] V(z) (spring-dampers,
springs, first-order blocks, a cross term; the reference solves x_e = x + V u, u = -E x_e per g
itself); g placed at 0.2-3 and, in a third, within 1e-4 of the reference's own crossing. In half the
cases operator springs b + k/s are added, some written as tf "b + k/s" or as an ss operator, and the
first device (an ss block) with its own position state: each such integrator is a conserved quantity
the checkers set aside, the reference builds the loop without it, and the certificate must claim
their number (and is refuted with one more or fewer). hapstab's verdict must be the reference's, both checkers must verify
its certificate, and refute it with the claim flipped (w added or dropped); with P's first diagonal
entry negated they refute a stable claim and agree on a NOT stable one (whose claim stays true: the
edited, indefinite P may still prove it).

  indep_loop_certificate.py HAPSTAB [--cases N] [--seed S]
exit 0 when every case agrees, else 1.
"""
import copy
import json
import os
import random
import subprocess
import sys
import tempfile
from fractions import Fraction as Q

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

import mpmath as mp  # noqa: E402

import indep_coupled as IC  # noqa: E402
import indep_loop as IL  # noqa: E402
from indep_common import case_files, cases_and_seed, loop_claim_flipped  # noqa: E402

TOP = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def checkers(exe, f):
    return ([exe, "check", f], ["/usr/bin/python3", os.path.join(TOP, "checks", "hapstab_check.py"), f])


def draw(rng, coupled):
    """A scene of indep_loop.gen_scene (or, coupled, indep_coupled.gen_coupled's, with its [coupling]
    V(z) and g in one of its five places): its first device often an ss block, open-loop unstable."""
    c = IC.gen_coupled(rng) if coupled else IL.gen_scene(rng)
    c["g"] = IL.rq(rng, 0.2, 3)
    if not coupled and rng.random() < 0.5:  # a fractional delay, t_d = (n + frac) T
        c["frac"] = rng.choice([Q(1, 2), Q(1, 4), Q(3, 4), Q(1, 10)])
    c["coupled"] = coupled
    # conserved quantities (check/stability_loop_check.hpp): the same physics written with an extra
    # integrator, each one more state of M at eigenvalue 1 exactly, which the reference never builds:
    # an operator spring b + k/s as tf "b + k/s" or as ss (its deflection integrates v, as x does), and
    # the first device, an ss block, with its own position state; the certificate must claim their number
    c["writes"], c["conserved"] = {}, 0
    if rng.random() < 0.5:
        for i in range(len(c["ops"])):
            if rng.random() < 0.5:
                b = c["ops"][i] if c["ops"][i] is not None else IL.rq(rng, 0.5, 5)
                c["ops"][i] = (b if not isinstance(b, tuple) else b[0], IL.rq(rng, 10, 500))
                c["writes"][i] = rng.choice(["m, b, k", "tf", "ss"])
                c["conserved"] += c["writes"][i] != "m, b, k"
        if c["devices"][0]["kind"] == "ss" and rng.random() < 0.5:
            c["writes"]["device"] = "ss with its position"
            c["conserved"] += 1
    return c


def rewrite(c, text):
    """The scene's text with c["writes"] applied (draw): the same loop, written with integrators."""
    for i, how in c["writes"].items():
        if i == "device":
            d = c["devices"][0]
            old = 'ss = { A = [["%s"]], B = [["%s"]], C = [["1"]], D = [["0"]] }' % (d["A"], d["Bv"])
            new = 'ss = { A = [["%s", "0"], ["1", "0"]], B = [["%s"], ["0"]], C = [["1", "0"]], D = [["0"]] }' % (d["A"], d["Bv"])
        elif how == "m, b, k":
            continue
        else:
            b, k = c["ops"][i]
            old = 'dofs = ["d%d"]\nb = "%s"\nk = "%s"\n' % (i, b, k)
            new = 'dofs = ["d%d"]\n' % i + ('tf = "%s + %s/s"\n' % (b, k) if how == "tf" else
                                           'ss = { A = [["0"]], B = [["1"]], C = [["%s"]], D = [["%s"]] }\n' % (k, b))
        assert text.count(old) == 1, (old, text)
        text = text.replace(old, new)
    return text


def rho_fractional(c, g):
    """rho of the loop with t_d = (n + frac) T (no coupling), assembled here: over a period the plant
    sees u_(k-n-1) for frac T, then u_(k-n): s+ = Phi_T s + Phi_(T-f) Gamma_f u_(k-n-1) + Gamma_(T-f) u_(k-n)."""
    A, B, Cy = IL.scene_plant(c, with_matrices=True)
    T, f = IL.mpq(c["T"]), IL.mpq(c["frac"]) * IL.mpq(c["T"])
    Pa, Ga = IL.zoh(A, B, T - f)
    Pb, Gb = IL.zoh(A, B, f)
    Ae, Be, Ce, De = IL.realize_matrix(c["E"])
    npl, ne, N, n = A.rows, Ae.rows, B.cols, c["n"]
    L = n + 1
    order = npl + ne + L * N
    M = mp.zeros(order, order)
    H = mp.zeros(N, order)  # the force u_k = -g (C_E xi + D_E Cy s)
    DC = De * Cy
    for i in range(N):
        for j in range(npl):
            H[i, j] = -g * DC[i, j]
        for j in range(ne):
            H[i, npl + j] = -g * Ce[i, j]
    P = Pa * Pb
    G1 = Pa * Gb
    for i in range(npl):
        for j in range(npl):
            M[i, j] = P[i, j]
    for age, G in ((n, Ga), (n + 1, G1)):
        for i in range(npl):
            if age == 0:
                for j in range(order):
                    M[i, j] += sum(G[i, k] * H[k, j] for k in range(N))
            else:
                for k in range(N):
                    M[i, npl + ne + (age - 1) * N + k] = G[i, k]
    BC = Be * Cy
    for i in range(ne):
        for j in range(npl):
            M[npl + i, j] = BC[i, j]
        for j in range(ne):
            M[npl + i, npl + j] = Ae[i, j]
    for k in range(N):
        for j in range(order):
            M[npl + ne + k, j] = H[k, j]
    for b in range(1, L):
        for k in range(N):
            M[npl + ne + b * N + k, npl + ne + (b - 1) * N + k] = 1
    return max(abs(x) for x in mp.eig(M, left=False, right=False))


def rho(c, g):
    with mp.workdps(IL.DPS):
        if c.get("frac"):
            return rho_fractional(c, mp.mpf(g.numerator) / g.denominator)
        loop = IC.CoupledLoop(c) if c["coupled"] else IL.build_loop_scene(c)
        return IL.rho_mp(loop, mp.mpf(g.numerator) / g.denominator)[0]


def scene_text(c):
    """The scene with g = 1 in [parameters] (--set gives c["g"]); a fractional delay as samples."""
    text = rewrite(c, IC.scene_toml(c, 1) if c["coupled"] else IL.scene_toml(c))
    if c.get("frac"):
        text = text.replace('[delay]\nsamples = "%d"\n' % c["n"], "") + '[delay]\nsamples = "%d + %s"\n' % (c["n"], c["frac"])
    return text




def near_crossing(c, rng):
    """g within 1e-4 (relative) of the reference's first crossing above 0.05, on a random side; None
    when there is none below 20."""
    lo, hi = Q(1, 20), None
    r_lo = rho(c, lo)
    for k in range(1, 10):
        g = Q(1, 20) * 2 ** k
        if (rho(c, g) < 1) != (r_lo < 1):
            hi = g
            break
        lo = g
    if hi is None:
        return None
    for _ in range(20):  # bisection to 2^-20 of the bracket: ~1e-6 relative
        mid = (lo + hi) / 2
        if (rho(c, mid) < 1) == (r_lo < 1):
            lo = mid
        else:
            hi = mid
    g = (lo + hi) / 2
    return g * (1 + Q(rng.choice([-1, 1]), 10000))


def run_case(exe, c, tmp):
    scene, cert, bad = case_files(tmp, scene_text(c))
    r = subprocess.run([exe, "stability", "--scene", scene, "--set", "g=%s" % c["g"], "--json", "--certificate", cert],
                       capture_output=True, text=True, timeout=600)
    rr = rho(c, c["g"])
    what = "g = %s, rho %s" % (c["g"], mp.nstr(rr, 12))
    if abs(1 - rr) < mp.mpf(10) ** -30:
        return None, what + ": on the boundary (skipped)", None
    stable = rr < 1
    if r.returncode == 2 and "no Stein certificate" in r.stderr:
        return None, what + ": no Stein certificate (refused by name): " + r.stderr.strip()[:200], None
    if r.returncode == 3 and "no certificate was written" in r.stderr and not os.path.exists(cert):
        return None, what + ": undecided, no certificate", None
    if r.returncode not in (0, 1):
        return False, "%s: exit %d: %s" % (what, r.returncode, r.stderr.strip()[:300]), None
    j = json.loads(r.stdout)
    cl = json.load(open(cert))
    if j["stable"] != stable or cl["claim"]["stable"] != stable or cl["kind"] != "stability-loop":
        return False, "%s: hapstab %s, its certificate %s (%s), the reference %s" % (
            what, j["stable"], cl["claim"]["stable"], cl["kind"], stable), None
    if cl["claim"].get("conserved", 0) != c["conserved"]:
        return False, "%s: the certificate claims %s conserved quantities, the scene writes %d" % (
            what, cl["claim"].get("conserved", 0), c["conserved"]), None
    mutants = []
    miscounted = copy.deepcopy(cl)  # a conserved quantity more (or, with some, fewer): refuted
    miscounted["claim"]["conserved"] = c["conserved"] + (-1 if c["conserved"] and rng_bit(cl) else 1)
    mutants.append(("conserved miscounted", miscounted))
    mutants.append(("claim flipped", loop_claim_flipped(cl)))
    negated = copy.deepcopy(cl)
    p00 = negated["evidence"]["P"][0][0]
    negated["evidence"]["P"][0][0] = p00[1:] if p00.startswith("-") else "-" + p00
    # P[0][0] negated: for a stable claim P is no longer positive definite (refuted); for NOT stable the
    # claim is true, and the edited P may still prove it (an indefinite P with P - M^T P M > 0): the two
    # checkers must then agree, either way
    mutants.append(("P[0][0] negated", negated))
    for name, m in mutants:
        with open(bad, "w") as f:
            json.dump(m, f)
        codes = []
        for cmd in checkers(exe, bad):
            v = subprocess.run(cmd, capture_output=True, text=True, timeout=600)
            codes.append(v.returncode)
            if v.returncode != 1 and (name != "P[0][0] negated" or stable or v.returncode != 0):
                return False, "%s: %s: %s exits %d: %s" % (what, name, os.path.basename(cmd[1]), v.returncode,
                                                           (v.stdout + v.stderr).strip()[:200]), None
        if codes[0] != codes[1]:
            return False, "%s: %s: the checkers disagree (exits %d and %d)" % (what, name, codes[0], codes[1]), None
    for cmd in checkers(exe, cert):
        v = subprocess.run(cmd, capture_output=True, text=True, timeout=600)
        if v.returncode != 0:
            return False, "%s: %s exits %d: %s" % (what, os.path.basename(cmd[1]), v.returncode, (v.stdout + v.stderr).strip()[:300]), None
    branch = "stable" if stable else "NOT stable"
    return True, "%s: %s (%d states%s), verified by both, its mutants refuted or agreed on" % (
        what, branch, len(cl["evidence"]["P"]) + c["conserved"],
        ", %d conserved: %s" % (c["conserved"], ", ".join(sorted(set(c["writes"].values())))) if c["conserved"] else ""), branch


def rng_bit(cl):
    """A bit of the certificate (P's size), so the choice is reproducible without another stream."""
    return len(cl["evidence"]["P"]) % 2


def main(argv):
    exe = argv[1]
    cases, seed = cases_and_seed(argv)
    rng = random.Random("loop-certificate:%d" % seed)
    bad = good = skipped = near = coupled = blocks = fractional = conserved = 0
    branches = {"stable": 0, "NOT stable": 0}
    with tempfile.TemporaryDirectory(prefix="hapstab-loop-cert-") as tmp:
        for i in range(cases):
            c = draw(rng, i % 2 == 1)
            if i % 3 == 2:
                g = near_crossing(c, rng)
                if g is not None:
                    c["g"], near = g, near + 1
            ok, line, branch = run_case(exe, c, tmp)
            print("%s case %d (%s DOF, delay %s%s): %s" % ({True: "ok  ", False: "MISS", None: "skip"}[ok], i, c["tags"]["DOF"],
                                                           c["n"] + c.get("frac", 0),
                                                           ", coupled, g in " + c["tags"]["g in"] if c["coupled"] else "", line))
            bad += ok is False
            good += ok is True
            skipped += ok is None
            if ok:
                branches[branch] += 1
                coupled += c["coupled"]
                blocks += c["devices"][0]["kind"] == "ss"
                fractional += bool(c.get("frac"))
                conserved += c["conserved"] > 0
    print("indep_loop_certificate: %d cases, %d agree (%d with a coupling, %d with an ss device, %d with a fractional delay, "
          "%d with conserved quantities), %d disagree, %d skipped; %d within 1e-4 of a crossing; %s" % (
              cases, good, coupled, blocks, fractional, conserved, bad, skipped, near, ", ".join("'%s' %d" % kv for kv in branches.items())))
    if cases >= 12 and (0 in branches.values() or coupled == 0 or blocks == 0 or fractional == 0 or conserved == 0):
        print("indep_loop_certificate: TOO FEW COMPARED: a verdict never reached")
        return 1
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
