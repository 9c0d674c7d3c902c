"""A stability-loop-symmetric certificate (beyond the 64 DOFs of a whole loop's): `stability --scene S --certificate`
on tests/cli/scenes/symmetric_held_96.toml (96 held devices in two classes of 48, an operator spring each: 96
conserved quantities), stable at g = 1 and NOT stable at g = 2. Required:
  * the kind, its blocks (fixed, and one zero-sum block per class; NOT stable: one block) and conserved = 96;
  * both checkers verify each certificate (exit 0);
  * the reference, built here from the scene's numbers with numpy and scipy and sharing no code with either
    checker or hapstab (the whole loop of 384 states: per DOF m v' = -(b + 2) v - kh x + u, x' = v, held by
    scipy's expm; u_k = -(E x)_(k-1), E(z) = K0 - (Bc/T) z^-1 on the diagonal), has spectral radius < 1 at
    g = 1 and > 1 at g = 2 (each at least 1e-6 from 1);
  * each hand edit of mutants() gets its exit code from both checkers.

  symmetric_loop_case.py HAPSTAB
exit 0 when every expectation holds, else 1 (each failure printed)."""
import json
import os
import subprocess
import sys
import tempfile
from fractions import Fraction as Q

import numpy as np
import scipy.linalg

HERE = os.path.dirname(os.path.abspath(__file__))
TOP = os.path.join(HERE, "..", "..")
SCENE = os.path.join(TOP, "tests", "cli", "scenes", "symmetric_held_96.toml")
INDEPENDENT = os.path.join(TOP, "checks", "hapstab_check.py")


def reference_rho(g):
    """The spectral radius of the 96-DOF loop written in symmetric_held_96.toml, built from its numbers."""
    N, T, kh = 96, 1e-3, 50.0
    m = [0.1 if i % 2 == 0 else 0.2 for i in range(N)]
    kc = [2000.0 if i % 2 == 0 else 3000.0 for i in range(N)]
    Bc = [2.0 if i % 2 == 0 else 3.0 for i in range(N)]
    A, B = np.zeros((2 * N, 2 * N)), np.zeros((2 * N, N))
    for i in range(N):  # state (v_i, x_i); the device's b = 1 and the operator's damper 2, its spring kh on x
        A[2 * i, 2 * i], A[2 * i, 2 * i + 1], A[2 * i + 1, 2 * i] = -(1 + 2) / m[i], -kh / m[i], 1
        B[2 * i, i] = 1 / m[i]
    V = scipy.linalg.expm(np.block([[A, B], [np.zeros((N, 2 * N)), np.zeros((N, N))]]) * T)
    Phi, Gam = V[:2 * N, :2 * N], V[:2 * N, 2 * N:]
    C = np.zeros((N, 2 * N))
    for i in range(N):
        C[i, 2 * i + 1] = 1
    K0 = np.array([[g * (kc[i] + Bc[i] / T) if i == j else -g * (kc[i] + kc[j]) / 2000 for j in range(N)] for i in range(N)])
    D1 = np.diag([g * Bc[i] / T for i in range(N)])
    # X = [s; x_(k-1); w_(k-1)], w = E x: s+ = Phi s - Gam w_(k-1); x_k = C s; w_k = K0 C s - D1 x_(k-1)
    Z = np.zeros
    M = np.block([[Phi, Z((2 * N, N)), -Gam], [C, Z((N, N)), Z((N, N))], [K0 @ C, -D1, Z((N, N))]])
    return max(abs(np.linalg.eigvals(M)))


def mutants(c):
    """Hand edits of a stability-loop-symmetric certificate c and the exit code both checkers must give each:
    refuted (1) -- a P entry negated, a conserved count moved, the classes merged or a DOF swapped between
    them (not invariant, the classes being unlike), w zero; malformed (2) -- a block dropped or given twice, a
    DOF left out of the classes or beyond the scene, a zero-sum block of a class that is not there, conserved on a NOT stable claim.
    (tests/verify/indep_symmetric_certificate.py runs them on its random scenes.)"""
    def edit(f):
        e = json.loads(json.dumps(c))
        f(e)
        return e

    def neg_p(e):
        P = e["evidence"]["blocks"][0]["P"]
        P[0][0] = str(-Q(P[0][0]))
    ev = c["evidence"]
    classes, blocks = ev["classes"], ev["blocks"]
    out = []
    if len(classes) >= 2:
        out += [("the first two classes merged", edit(lambda e: e["evidence"].update(classes=[classes[0] + classes[1]] + classes[2:])), 1),
                ("a DOF swapped between the first two classes", edit(lambda e: e["evidence"].update(
                    classes=[[classes[1][0]] + classes[0][1:], [classes[0][0]] + classes[1][1:]] + classes[2:])), 1)]
    out.append(("a DOF index 2^32 + 1 (read as 1 if narrowed unchecked)", edit(lambda e: e["evidence"]["classes"][0].__setitem__(0, 2 ** 32 + 1)), 2))
    out.append(("a DOF left out of the classes", edit(lambda e: e["evidence"]["classes"][-1].pop() if len(classes[-1]) > 1
                                                      else e["evidence"]["classes"].pop()), 2))
    if not c["claim"]["stable"]:
        return out + [("NOT stable: w zero", edit(lambda e: e["evidence"]["blocks"][0].update(w=["0"] * len(blocks[0]["w"]))), 1),
                      ("NOT stable: conserved on the claim", edit(lambda e: e["claim"].update(conserved=0)), 2)]
    out += [("stable: P[0][0] of the first block negated", edit(neg_p), 1),
            ("stable: the claim's conserved moved", edit(lambda e: e["claim"].update(conserved=c["claim"].get("conserved", 0) + 1)), 1),
            ("stable: the first block's conserved moved", edit(lambda e: e["evidence"]["blocks"][0].update(
                conserved=blocks[0].get("conserved", 0) + 1)), 1),
            ("stable: the last block dropped", edit(lambda e: e["evidence"]["blocks"].pop()), 2)]
    if len(blocks) >= 2:
        out += [("stable: a block given twice", edit(lambda e: e["evidence"]["blocks"].__setitem__(-1, e["evidence"]["blocks"][-2])), 2),
                ("stable: a zero-sum block of a class that is not there", edit(lambda e: e["evidence"]["blocks"][-1].update({"class": len(classes)})), 2)]
    return out


def main():
    hapstab = sys.argv[1]
    failures = 0

    def expect(what, ok):
        nonlocal failures
        failures += not ok
        print("%s %s" % ("ok  " if ok else "FAIL", what))

    def exits(path):
        return (subprocess.run([hapstab, "check", path], capture_output=True).returncode,
                subprocess.run(["/usr/bin/python3", INDEPENDENT, path], capture_output=True).returncode)
    with tempfile.TemporaryDirectory() as tmp:
        certs = {}
        for g, stable in (("1", True), ("2", False)):
            path = os.path.join(tmp, "g%s.json" % g)
            r = subprocess.run([hapstab, "stability", "--scene", SCENE, "--set", "g=" + g, "--certificate", path, "--quiet"],
                               capture_output=True, text=True)
            if r.returncode != (0 if stable else 1) or not os.path.exists(path):
                expect("g = %s: a certificate (exit %d: %s)" % (g, r.returncode, r.stderr.strip()[:200]), False)
                continue
            c = json.load(open(path))
            spaces = [(b["space"], b.get("class")) for b in c["evidence"]["blocks"]]
            want = [("fixed", None), ("zero-sum", 0), ("zero-sum", 1)] if stable else None
            expect("g = %s: kind stability-loop-symmetric, claim stable %s, blocks %s, conserved %s" % (
                g, c["claim"]["stable"], spaces, c["claim"].get("conserved")),
                c["kind"] == "stability-loop-symmetric" and c["claim"]["stable"] == stable and
                (spaces == want and c["claim"].get("conserved") == 96 if stable else len(spaces) == 1 and "conserved" not in c["claim"]))
            expect("g = %s: both checkers verify it %s" % (g, exits(path)), exits(path) == (0, 0))
            rho = reference_rho(float(g))
            expect("g = %s: the reference's spectral radius %.9f is %s 1" % (g, rho, "<" if stable else ">"),
                   rho < 1 - 1e-6 if stable else rho > 1 + 1e-6)
            certs[stable] = c
        if len(certs) < 2:
            return 1

        cases = mutants(certs[True]) + mutants(certs[False])
        for what, m, code in cases:
            path = os.path.join(tmp, "m.json")
            json.dump(m, open(path, "w"))
            got = exits(path)
            expect("%s: exits %s (want %d from both)" % (what, got, code), got == (code, code))
    print("symmetric_loop_case: %d failed" % failures)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
