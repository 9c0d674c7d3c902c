"""`stability --scene S --max g` on 96 held devices in two classes of 48 (tests/cli/scenes/symmetric_held_96.toml):
the supremum by the split of identical DOFs (stability/loop_max_symmetric.hpp). Before the split the whole
closed-loop matrix (384 states) ran for more than 11 minutes; the subprocess here is cut at 120 s (a hang is
a failure, not a timing). Required:
  * exit 0, path "symmetry", three blocks (the fixed space's loop of 2 DOFs, one zero-sum loop per class), the
    supremum the least of the blocks' and its enclosure inside the deciding block's;
  * the reference, the whole loop of 384 states built in numpy/scipy from the scene's numbers
    (tests/check/symmetric_loop_case.py's reference_rho, no code shared with hapstab): spectral radius < 1 at
    12 points geometric in [sup 10^-3, sup (1 - 10^-6)] and > 1 at sup (1 + 10^-6) (a crossing's error in double
    ~ 1e-10 relative here: 10^-6 leaves four decades);
  * --certificate writes kind stability-loop-max-symmetric (check/stability_loop_max_symmetric_check.hpp), its
    claim the printed enclosure around sup, three blocks of which exactly one carries unstable_at, conserved = 96;
    both checkers verify it (exit 0), and each hand edit of max_mutants() gets its exit code from both;
  * --no-symmetry refused by name beyond 64 DOFs (exit 2), and a scene of 8 DOFs in two classes of 4 (a class of
    three or more) split too, its supremum the 96's zero-sum block's (the same one-DOF loop);
  * K inside the environment's tf (tests/cli/scenes/symmetric_three_walls_k.toml, three identical devices, written
    as diagonal / off_diagonal): the supremum against the whole loop in numpy (indep_symmetric_certificate.py's
    reference_rho, the links -K/20 as u v with u = v = sqrt(K/20)), its certificate (a first-order start in each
    block) verified by both checkers with its hand edits, K squared in the diagonal refused by both (malformed:
    not affine); with the links -100 instead, NOT stable for every small K (the fixed space's stiffness K - 200):
    sup K = 0, one block's certificate verified by both, its hand edits too; three devices on walls whose links push
    them apart (+2000): sup g = 0 by the zero-sum block's first-order mirror (NOT stable on (0, eps]: the whole loop's
    rho > 1 in numpy at eps 10^-3, 10^-1 and eps), its certificate verified by both with its hand edits;
  * a coupling V = 1/(20000 z) on every DOF ([coupling], split with E by both checkers): 12 DOFs in two classes,
    sup g against the coupled reference (x_e = x + V u, indep_symmetric_certificate.reference_rho), its certificate
    verified by both; 70 DOFs at g = 1 and 4 (`stability --scene`, kind stability-loop-symmetric beyond 64 DOFs),
    each verdict the reference's and its certificate verified by both.

  symmetric_max_case.py HAPSTAB
exit 0 when every expectation holds, else 1."""
import json
import os
from fractions import Fraction as Q
import subprocess
import sys
import tempfile

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
TOP = os.path.join(HERE, "..", "..")
SCENE = os.path.join(HERE, "scenes", "symmetric_held_96.toml")
INDEPENDENT = os.path.join(TOP, "checks", "hapstab_check.py")
sys.path.insert(0, os.path.join(TOP, "tests", "check"))
from symmetric_loop_case import reference_rho  # noqa: E402
from loop_max_case import outward_mutants  # noqa: E402
sys.path.insert(0, os.path.join(TOP, "tests", "verify"))
import indep_symmetric_certificate as ISC  # noqa: E402
SCENE_K = os.path.join(HERE, "scenes", "symmetric_three_walls_k.toml")


def rho_k(K, link=None):
    """The whole loop of symmetric_three_walls_k.toml at K (links -K/20, or -link), built in numpy/scipy."""
    uv = (K / 20 if link is None else link) ** 0.5
    return ISC.reference_rho({"N": 3, "cls": [0, 0, 0], "n": 0, "g": 1.0, "classes": [
        {"m": 0.5, "b": 1.0, "K": K, "B": 2.0, "bo": 0, "ko": 0, "u": uv, "v": uv}]})


def max_mutants(c):
    """Hand edits of a stability-loop-max-symmetric certificate c and the exit code both checkers must give each:
    refuted (1) -- the classes merged or a DOF swapped between them (not invariant), a cover P negated, unstable_at's
    w zero, a conserved count moved (claim or block), a block's first-order start dropped; malformed (2) -- a block dropped or given twice, unstable_at
    taken away, a DOF beyond the scene or left out, a cover's last interval not ending at lo, the gain made 2 g
    (not the gain alone; where p is the gain); on a deciding block with first_order_unstable (sup = 0 by the mirror)
    loop_max_case.outward_mutants' edits of it. (tests/verify/indep_symmetric_max.py runs them on its random scenes.)"""
    def edit(f):
        e = json.loads(json.dumps(c))
        f(e)
        return e
    ev = c["evidence"]
    classes, blocks = ev["classes"], ev["blocks"]
    d = next(i for i, b in enumerate(blocks) if "unstable_at" in b or "first_order_unstable" in b)
    out = outward_mutants(c, ["evidence", "blocks", d], c["model"]["name"])[1:] if "first_order_unstable" in blocks[d] else []
    if len(classes) >= 2:
        out += [("the first two classes merged", edit(lambda e: e["evidence"].update(classes=[classes[0] + classes[1]] + classes[2:])), 1),
                ("a DOF swapped between the first two classes", edit(lambda e: e["evidence"].update(
                    classes=[[classes[1][0]] + classes[0][1:], [classes[0][0]] + classes[1][1:]] + classes[2:])), 1)]
    out += [("a DOF index 2^32 + 1", edit(lambda e: e["evidence"]["classes"][0].__setitem__(0, 2 ** 32 + 1)), 2),
            ("a DOF left out of the classes", edit(lambda e: e["evidence"]["classes"][-1].pop() if len(classes[-1]) > 1
                                                   else e["evidence"]["classes"].pop()), 2),
            ]
    if "unstable_at" in blocks[d]:
        out += [("unstable_at's w zero", edit(lambda e: e["evidence"]["blocks"][d]["unstable_at"].update(
                    w=["0"] * len(blocks[d]["unstable_at"]["w"]))), 1),
                ("unstable_at taken away", edit(lambda e: e["evidence"]["blocks"][d].pop("unstable_at")), 2)]
    gain = 'gain = "%s"' % c["model"]["name"]
    if gain in c["model"]["scene"]:  # p the environment's gain (not inside its tf)
        out.append(("the gain made 2 g", edit(lambda e: e["model"].update(scene=c["model"]["scene"].replace(gain, 'gain = "2*%s"' % c["model"]["name"]))), 2))
    if c["claim"]["hi"] == "0":
        return out
    b0 = blocks[0]

    def neg_p(e):
        P = e["evidence"]["blocks"][0]["cover"][0]["P"]
        P[0][0] = str(-Q(P[0][0]))

    def last_to(e):
        e["evidence"]["blocks"][0]["cover"][-1]["to"] = str(Q(c["claim"]["lo"]) * 2)
    out += [("the first block's first cover P[0][0] negated", edit(neg_p), 1),
            ("the claim's conserved moved", edit(lambda e: e["claim"].update(conserved=c["claim"].get("conserved", 0) + 1)), 1),
            ("the first block's conserved moved", edit(lambda e: e["evidence"]["blocks"][0].update(conserved=b0.get("conserved", 0) + 1)), 1),
            ("the first block's cover ending at 2 lo", edit(last_to), 2),
            ("the last block dropped", edit(lambda e: e["evidence"]["blocks"].pop()), 2)]
    fo = next((i for i, b in enumerate(blocks) if "first_order" in b), None)
    if fo is not None:  # M_b(0) has the eigenvalue 1 there: no P holds Stein at 0, so the cover from 0 is not shown
        out.append(("a block's first-order start dropped", edit(lambda e: e["evidence"]["blocks"][fo].pop("first_order")), 1))
    if len(blocks) >= 2:
        out.append(("a block given twice", edit(lambda e: e["evidence"]["blocks"].__setitem__(
            0 if d != 0 else 1, e["evidence"]["blocks"][1 if d != 0 else 2] if len(blocks) > 2 or d != 0 else e["evidence"]["blocks"][0])), 2))
    return out


def main():
    hapstab = sys.argv[1]
    failures = 0

    def expect(what, ok):
        nonlocal failures
        failures += not ok
        print("%s %s" % ("ok  " if ok else "FAIL", what))

    def run(*args, scene=SCENE):
        return subprocess.run([hapstab, "stability", "--scene", scene, "--max", "g", "--quiet"] + list(args),
                              capture_output=True, text=True, timeout=120)
    r = run("--json")
    expect("96 DOFs: exit %d (want 0)" % r.returncode, r.returncode == 0)
    if r.returncode != 0:
        print(r.stderr[:500])
        return 1
    j = json.loads(r.stdout)
    lo, hi = (float(x) for x in j["sup_enclosure"])
    blocks = j.get("blocks", [])
    d = blocks[j["deciding_block"]] if blocks else {}
    expect("path %s, %d blocks, classes %s" % (j.get("path"), len(blocks), [b.get("class") for b in blocks]),
           j.get("path") == "symmetry" and [b.get("class") for b in blocks] == [None, 0, 1])
    expect("sup in [%r, %r], the least of the blocks' (deciding block %s)" % (lo, hi, j.get("deciding_block")),
           all(float(b["sup_enclosure"][1]) >= hi for b in blocks) and float(d["sup_enclosure"][0]) <= lo + 1e-15 * lo)
    sup = (lo + hi) / 2
    below = [reference_rho(g) for g in sup * np.geomspace(1e-3, 1 - 1e-6, 12)]
    above = reference_rho(sup * (1 + 1e-6))
    expect("the reference: max rho below sup %.9f (< 1), rho at sup (1 + 1e-6) %.9f (> 1)" % (max(below), above),
           max(below) < 1 and above > 1)
    def exits(path):
        return (subprocess.run([hapstab, "check", path], capture_output=True, timeout=300).returncode,
                subprocess.run(["/usr/bin/python3", INDEPENDENT, path], capture_output=True, timeout=300).returncode)
    with tempfile.TemporaryDirectory() as tmp:
        path = os.path.join(tmp, "c.json")
        r = run("--certificate", path)
        cert = json.load(open(path)) if r.returncode == 0 and os.path.exists(path) else {}
        blocks = cert.get("evidence", {}).get("blocks", [])
        expect("--certificate: exit %d, kind %s, %d blocks, %d with unstable_at, conserved %s" % (
            r.returncode, cert.get("kind"), len(blocks), sum("unstable_at" in b for b in blocks), cert.get("claim", {}).get("conserved")),
            cert.get("kind") == "stability-loop-max-symmetric" and len(blocks) == 3 and sum("unstable_at" in b for b in blocks) == 1 and
            cert["claim"].get("conserved") == 96 and float(cert["claim"]["printed_lo"]) <= lo and float(cert["claim"]["printed_hi"]) >= hi)
        if cert:
            expect("both checkers verify it %s" % (exits(path),), exits(path) == (0, 0))
            for what, m, code in max_mutants(cert):
                bad = os.path.join(tmp, "m.json")
                json.dump(m, open(bad, "w"))
                got = exits(bad)
                expect("%s: exits %s (want %d from both)" % (what, got, code), got == (code, code))
        w = run("--no-symmetry")
        expect("--no-symmetry: exit %d, '%s'" % (w.returncode, w.stderr.strip()[:120]), w.returncode == 2 and "64 DOFs" in w.stderr)
        small = os.path.join(tmp, "held_8.toml")
        with open(SCENE) as f:
            open(small, "w").write(f.read().replace("times = 48", "times = 4").replace("count = 96", "count = 8"))
        s = run("--json", scene=small)
        js = json.loads(s.stdout) if s.returncode == 0 else {}
        expect("8 DOFs in two classes of 4: exit %d, path %s, sup %s (the 96's %s)" % (s.returncode, js.get("path"), js.get("max"), j["max"]),
               s.returncode == 0 and js.get("path") == "symmetry" and js.get("max") == j["max"])
    with tempfile.TemporaryDirectory() as tmp:  # K inside the tf
        path = os.path.join(tmp, "k.json")
        r = subprocess.run([hapstab, "stability", "--scene", SCENE_K, "--max", "K", "--quiet", "--json", "--certificate", path],
                           capture_output=True, text=True, timeout=120)
        j = json.loads(r.stdout) if r.returncode == 0 else {}
        cert = json.load(open(path)) if os.path.exists(path) else {}
        if j and cert:
            lo, hi = (float(x) for x in j["sup_enclosure"])
            sup = (lo + hi) / 2
            below = max(rho_k(k) for k in sup * np.geomspace(1e-4, 1 - 1e-6, 12))
            expect("K inside the tf: sup %s, path %s; the reference's max rho below %.9f, at sup (1 + 1e-6) %.9f" % (
                j["max"], j.get("path"), below, rho_k(sup * (1 + 1e-6))), j.get("path") == "symmetry" and below < 1 < rho_k(sup * (1 + 1e-6)))
            expect("K inside the tf: kind %s, a first-order start in every block, both checkers %s" % (cert["kind"], exits(path)),
                   cert["kind"] == "stability-loop-max-symmetric" and all("first_order" in b for b in cert["evidence"]["blocks"]) and
                   exits(path) == (0, 0))
            sq = json.loads(json.dumps(cert))
            sq["model"]["scene"] = sq["model"]["scene"].replace('diagonal = "K + 2', 'diagonal = "K^2/1000 + 2')
            for what, m, code in max_mutants(cert) + [("K squared in the diagonal (not affine)", sq, 2)]:
                bad = os.path.join(tmp, "m.json")
                json.dump(m, open(bad, "w"))
                got = exits(bad)
                expect("K inside the tf, %s: exits %s (want %d from both)" % (what, got, code), got == (code, code))
        else:
            expect("K inside the tf: exit %d, a certificate %s (%s)" % (r.returncode, bool(cert), r.stderr.strip()[:200]), False)
        zero = os.path.join(tmp, "zero.toml")
        open(zero, "w").write(open(SCENE_K).read().replace('off_diagonal = "-K/20"', 'off_diagonal = "-100"'))
        path = os.path.join(tmp, "z.json")
        r = subprocess.run([hapstab, "stability", "--scene", zero, "--max", "K", "--quiet", "--certificate", path],
                           capture_output=True, text=True, timeout=120)
        cert = json.load(open(path)) if os.path.exists(path) else {}
        expect("links -100: exit %d (want 1: sup K = 0), the reference's rho at K = 1e-3, 1 and 100: %s" % (
            r.returncode, ["%.6f" % rho_k(k, 100.0) for k in (1e-3, 1.0, 100.0)]),
            r.returncode == 1 and all(rho_k(k, 100.0) > 1 for k in (1e-3, 1.0, 100.0)))
        if cert:
            expect("sup K = 0: %d block, both checkers %s" % (len(cert["evidence"]["blocks"]), exits(path)),
                   cert["claim"]["hi"] == "0" and len(cert["evidence"]["blocks"]) == 1 and exits(path) == (0, 0))
            for what, m, code in max_mutants(cert):
                bad = os.path.join(tmp, "m.json")
                json.dump(m, open(bad, "w"))
                got = exits(bad)
                expect("sup K = 0, %s: exits %s (want %d from both)" % (what, got, code), got == (code, code))
    with tempfile.TemporaryDirectory() as tmp:  # sup = 0 by a zero-sum block's first-order mirror
        s = 2000 ** 0.5  # links +2000 (u v = -2000): the zero-sum stiffness 1000 - 2000 < 0, the fixed one 5000
        c = {"N": 3, "cls": [0, 0, 0], "n": 0, "g": 1.0, "classes": [{"m": 0.5, "b": 1.0, "K": 1000, "B": 2.0, "bo": 0, "ko": 0, "u": s, "v": -s}]}
        scene, path = os.path.join(tmp, "out.toml"), os.path.join(tmp, "o.json")
        open(scene, "w").write(ISC.scene(c))
        r = run("--json", "--certificate", path, scene=scene)
        j = json.loads(r.stdout) if r.stdout.strip() else {}
        cert = json.load(open(path)) if os.path.exists(path) else {}
        eps = float(j.get("unstable_on", [0, 0])[1])
        rhos = [ISC.reference_rho(dict(c, g=g)) for g in eps * np.array([1e-3, 0.1, 1.0])]
        blocks = cert.get("evidence", {}).get("blocks", [])
        expect("links pushing apart: exit %d (want 1), sup %s, path %s, unstable on (0, %s]; the reference's rho at eps 1e-3, 0.1, 1: %s" % (
            r.returncode, j.get("max"), j.get("path"), eps, ["%.9f" % x for x in rhos]),
            r.returncode == 1 and j.get("max") == "0" and j.get("path") == "symmetry" and eps > 0 and min(rhos) > 1)
        expect("links pushing apart: the certificate's block %s with first_order_unstable, both checkers %s" % (
            [b.get("space") for b in blocks], exits(path) if cert else None),
            len(blocks) == 1 and "first_order_unstable" in blocks[0] and exits(path) == (0, 0))
        if cert:
            for what, m, code in max_mutants(cert):
                bad = os.path.join(tmp, "m.json")
                json.dump(m, open(bad, "w"))
                got = exits(bad)
                expect("links pushing apart, %s: exits %s (want %d from both)" % (what, got, code), got == (code, code))
    with tempfile.TemporaryDirectory() as tmp:  # a coupling, split with E
        for N, what in ((12, "max"), (70, "verdicts")):
            c = {"N": N, "cls": [0, 1] * (N // 2), "n": 0, "g": 1.0, "cv": 1 / 20000, "classes": [
                {"m": 0.1, "b": 1.0, "K": 2000, "B": 2.0, "bo": 0, "ko": 0, "u": 0.5, "v": 1.0},
                {"m": 0.2, "b": 1.0, "K": 3000, "B": 3.0, "bo": 2, "ko": 50, "u": 1.0, "v": 0.5}]}
            scene = os.path.join(tmp, "c%d.toml" % N)
            open(scene, "w").write(ISC.scene(c))
            if what == "max":
                path = os.path.join(tmp, "cm.json")
                r = subprocess.run([hapstab, "stability", "--scene", scene, "--max", "g", "--quiet", "--json", "--digits", "10", "--certificate", path],
                                   capture_output=True, text=True, timeout=120)
                j = json.loads(r.stdout) if r.returncode == 0 else {}
                sup = float(j["sup_enclosure"][0]) if j else 1.0
                rb, ra = ISC.reference_rho(dict(c, g=sup * (1 - 1e-6))), ISC.reference_rho(dict(c, g=sup * (1 + 1e-6)))
                expect("coupled, 12 DOFs: sup g %s (path %s), the reference's rho %.9f below, %.9f above; the certificate %s" % (
                    j.get("max"), j.get("path"), rb, ra, exits(path) if j else None),
                    j.get("path") == "symmetry" and rb < 1 < ra and exits(path) == (0, 0))
                continue
            for g in (1.0, 4.0):
                path = os.path.join(tmp, "cv%d.json" % g)
                r = subprocess.run([hapstab, "stability", "--scene", scene, "--set", "g=%r" % g, "--quiet", "--certificate", path],
                                   capture_output=True, text=True, timeout=120)
                rho = ISC.reference_rho(dict(c, g=g))
                kind = json.load(open(path))["kind"] if os.path.exists(path) else None
                expect("coupled, 70 DOFs, g = %g: exit %d, the reference's rho %.6f; kind %s, the checkers %s" % (
                    g, r.returncode, rho, kind, exits(path) if kind else None),
                    r.returncode == (0 if rho < 1 else 1) and abs(rho - 1) > 1e-6 and kind == "stability-loop-symmetric" and exits(path) == (0, 0))
    print("symmetric_max_case: %d failed" % failures)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
