"""`stability --scene S --certificate` beyond 64 DOFs (kind stability-loop-symmetric: the checkers re-derive the split
by identical DOFs from the scene's text, check/stability_loop_symmetric_check.hpp and checks/hapstab_check.py's
split_loop) against the whole loop built here in numpy/scipy from the numbers drawn, never from hapstab or its
checkers.

Scenes: N = 65-100 DOFs in 2-3 classes, interleaved at random (list parameters with N values); per class a mass m
and damping b, an operator (none, a damper, a damper and a spring written as tf "b + k/s": a conserved quantity
per DOF), a wall K + B (z - 1)/(T z); between DOFs of classes a, b the link -u_a v_b; a delay of 0-2 samples; the
environment's gain g drawn at 0.3-3 times a scale so that both verdicts occur. The reference: per DOF m v' = -(b
+ b_o) v - k_o x + u, x' = v (the operator's spring on the position: the conserved quantity set aside), held by
scipy's expm (Van Loan); u_k = -(E x)_(k - n), E(z) = K0 - D1 z^-1 (with c["cv"], a coupling V = cv/z on every
DOF, delay 0: x_e = x + V u, u_k = -(E x_e)_k: docs/scene.md's [coupling]); its spectral radius in double. Required: a
verdict decided at least 1e-6 from rho = 1 by the reference is hapstab's, the certificate's kind
stability-loop-symmetric with the claim's conserved = the number of springs, verified by both checkers (exit 0;
the independent one within its 128 DOFs), and refuted by both with the claim flipped (a stable claim given w = e_1
on one block: w^T P w > 0; a NOT stable one made stable with the other blocks left out: malformed or refuted), and
every hand edit of tests/check/symmetric_loop_case.py's mutants() given its exit code by both.
Within 1e-6 of rho = 1 the case is counted apart.

  indep_symmetric_certificate.py HAPSTAB [--cases N] [--seed S]
exit 0 when every compared case agrees, else 1.
"""
import json
import os
import random
import subprocess
import sys

import numpy as np
import scipy.linalg

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from indep_common import case_files, cases_and_seed, run_cases  # noqa: E402

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "check"))
import symmetric_loop_case as SLC  # noqa: E402

TOP = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")
T = 1e-3
MUTANTS = [0]  # symmetric_loop_case.mutants of each certificate, every one given its exit code by both checkers


def draw(rng, dofs=(65, 100)):
    r = rng.choice([2, 2, 3])
    N = rng.randint(*dofs)
    cls = [a % r for a in range(N)]
    rng.shuffle(cls)
    c = {"N": N, "cls": cls, "n": rng.randint(0, 2), "classes": []}
    for _ in range(r):
        op = rng.choice(["none", "damper", "spring"])
        c["classes"].append({"m": rng.randint(1, 9) / 20, "b": rng.randint(0, 4) / 2, "K": 100 * rng.randint(5, 40),
                             "B": rng.randint(1, 6) / 2, "bo": 0 if op == "none" else rng.randint(1, 4),
                             "ko": 50 * rng.randint(1, 4) if op == "spring" else 0,
                             "u": rng.randint(0, 4) / 2, "v": rng.randint(0, 4) / 2})
    c["g"] = round(rng.uniform(0.3, 3.0) / (1 + c["n"]), 4)
    return c


def values(c, key):
    return [c["classes"][a][key] for a in c["cls"]]


def scene(c):
    lists = "\n".join("%s = [%s]" % (k, ", ".join('"%r"' % x for x in values(c, k))) for k in ("m", "b", "K", "B", "bo", "ko", "u", "v"))
    return """[scene]
T = "1/1000"

[parameters]
%s
g = "%r"

[[device]]
count = %d
name = "d"
m = "m[i]"
b = "b[i]"

[[operator]]
count = %d
name = "h[i]"
dofs = ["d[i]"]
tf = "bo[i] + ko[i]/s"

[environment]
diagonal = "K[i] + B[i]*(z-1)/(T*z)"
off_diagonal = "-u[i]*v[j]"
gain = "g"

[delay]
samples = "%d"
""" % (lists, c["g"], c["N"], c["N"], c["n"]) + ('\n[coupling]\ndiagonal = "%r/z"\n' % c["cv"] if c.get("cv") else "")


def reference_rho(c):
    N, n, g = c["N"], c["n"], c["g"]
    m, b, K, B, bo, ko, u, v = (values(c, k) for k in ("m", "b", "K", "B", "bo", "ko", "u", "v"))
    A, Bm = np.zeros((2 * N, 2 * N)), np.zeros((2 * N, N))
    for i in range(N):
        A[2 * i, 2 * i], A[2 * i, 2 * i + 1], A[2 * i + 1, 2 * i] = -(b[i] + bo[i]) / m[i], -ko[i] / m[i], 1
        Bm[2 * i, i] = 1 / m[i]
    V = scipy.linalg.expm(np.block([[A, Bm], [np.zeros((N, 3 * N))]]) * T)
    Phi, Gam = V[:2 * N, :2 * N], V[:2 * N, 2 * N:]
    C = np.zeros((N, 2 * N))
    C[np.arange(N), 2 * np.arange(N) + 1] = 1
    K0 = np.array([[g * (K[i] + B[i] / T) if i == j else -g * u[i] * v[j] for j in range(N)] for i in range(N)])
    D1 = np.diag([g * B[i] / T for i in range(N)])
    if c.get("cv"):  # a coupling V = cv/z (delay 0): x_e = x + V u, u_k = -(E x_e)_k; state [s; q = x_e,(k-1); r = u_(k-1)]
        assert n == 0, "the coupled reference has no delay"
        cv = c["cv"]
        # x_e,k = C s + cv r, u_k = -(K0 x_e,k - D1 q) = -K0 C s - cv K0 r + D1 q
        U = np.hstack([-K0 @ C, D1, -cv * K0])
        M = np.zeros((4 * N, 4 * N))
        M[:2 * N, :2 * N] = Phi
        M[:2 * N] += Gam @ U
        M[2 * N:3 * N, :2 * N], M[2 * N:3 * N, 3 * N:] = C, cv * np.eye(N)
        M[3 * N:] = U
        return max(abs(np.linalg.eigvals(M)))
    # state [s; q = x_(k-1); w_(k-1) .. w_(k-n)], w = E x = K0 C s - D1 q, u_k = -w_(k-n)
    S = 2 * N + N + n * N
    M = np.zeros((S, S))
    W = np.hstack([K0 @ C, -D1])  # w_k from [s; q]
    M[2 * N:3 * N, :2 * N] = C
    if n == 0:
        M[:2 * N, :3 * N] = np.hstack([Phi, np.zeros((2 * N, N))]) - Gam @ W
    else:
        M[:2 * N, :2 * N] = Phi
        M[:2 * N, 3 * N + (n - 1) * N:3 * N + n * N] = -Gam
        M[3 * N:4 * N, :3 * N] = W
        for k in range(1, n):
            M[3 * N + k * N:3 * N + (k + 1) * N, 3 * N + (k - 1) * N:3 * N + k * N] = np.eye(N)
    return max(abs(np.linalg.eigvals(M)))


def run_case(exe, c, tmp):
    path, cert, bad = case_files(tmp, scene(c))
    rho = reference_rho(c)
    r = subprocess.run([exe, "stability", "--scene", path, "--certificate", cert, "--quiet"], capture_output=True, text=True, timeout=600)
    if abs(rho - 1) < 1e-6:
        return None, "the reference's rho %.12f within 1e-6 of 1" % rho, "near"
    if r.returncode == 3:  # undecided: no certificate, never counted as either verdict
        return None, "undecided (rho %.9f): %s" % (rho, r.stderr.strip()[:200]), "undecided"
    if r.returncode not in (0, 1):
        return False, "exit %d (rho %.9f): %s" % (r.returncode, rho, r.stderr.strip()[:300]), None
    stable = r.returncode == 0
    if stable != (rho < 1):
        return False, "hapstab says %s, the reference's rho is %.12f" % ("stable" if stable else "NOT stable", rho), None
    cl = json.load(open(cert))
    springs = sum(1 for a in c["cls"] if c["classes"][a]["ko"])
    if cl["kind"] != "stability-loop-symmetric" or (stable and cl["claim"].get("conserved", 0) != springs):
        return False, "kind %s, conserved %s (the scene writes %d springs)" % (cl["kind"], cl["claim"].get("conserved"), springs), None

    def exits(p):
        return tuple(subprocess.run(cmd, capture_output=True, timeout=600).returncode
                     for cmd in ([exe, "check", p], ["/usr/bin/python3", os.path.join(TOP, "checks", "hapstab_check.py"), p]))
    got = exits(cert)
    if got not in ((0, 0), (0, 3)):
        return False, "the checkers exit %s on the certificate" % (got,), None
    flipped = json.loads(json.dumps(cl))
    if stable:
        flipped["claim"]["stable"] = False
        flipped["claim"].pop("conserved", None)
        blk = flipped["evidence"]["blocks"][0]
        flipped["evidence"]["blocks"] = [dict(blk, w=["1"] + ["0"] * (len(blk["P"]) - 1))]
    else:
        flipped["claim"]["stable"] = True
        flipped["evidence"]["blocks"][0].pop("w")
    with open(bad, "w") as f:
        json.dump(flipped, f)
    gf = exits(bad)
    if gf[0] not in (1, 2) or gf[1] not in (1, 2, 3) or (gf[1] != 3 and gf[0] != gf[1]):
        return False, "the claim flipped: the checkers exit %s" % (gf,), None
    for what, m, code in SLC.mutants(cl):
        with open(bad, "w") as f:
            json.dump(m, f)
        gm = exits(bad)
        if gm not in ((code, code), (code, 3)):
            return False, "%s: the checkers exit %s (want %d)" % (what, gm, code), None
        MUTANTS[0] += 1
    return True, "%s (rho %.9f; %d DOFs in %d classes, %d springs, delay %d), verified by %s, its flip and mutants rejected" % (
        "stable" if stable else "NOT stable", rho, c["N"], len(c["classes"]), springs, c["n"],
        "both" if got == (0, 0) else "hapstab check"), "stable" if stable else "NOT stable"


def main(argv):
    exe = argv[1]
    cases, seed = cases_and_seed(argv, 6, 1)
    rng = random.Random("symmetric-certificate:%d" % seed)
    counts, bad = run_cases(cases, lambda: draw(rng), lambda c, tmp: run_case(exe, c, tmp), "hapstab-sym-cert-")
    print("indep_symmetric_certificate: %d cases, %d disagree; %s; mutants %d, each given its exit code by both checkers" % (
        cases, bad, "; ".join("%s %d" % kv for kv in sorted(counts.items())), MUTANTS[0]))
    if cases >= 6 and (counts.get("stable", 0) == 0 or counts.get("NOT stable", 0) == 0):
        print("indep_symmetric_certificate: TOO FEW COMPARED: a verdict never reached")
        return 1
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
