"""`stability --scene S --max g --certificate` beyond one DOF (kind stability-loop-max,
check/stability_loop_max_check.hpp) against the loop built in mpmath from the numbers drawn
(indep_loop.py's scene loop: ZOH by mpmath.expm, the walls realised entry by entry, the spectral radius
at 50 digits), never from hapstab or its checkers.

Scenes: indep_loop.gen_scene's 2-3 DOF loops with g the environment's gain, every DOF held at g = 0 by
an operator spring b + k/s (written as m, b, k, as tf "b + k/s" or as an ss operator: the latter two are
conserved quantities the certificate must count), so that the loop at g = 0 is Schur stable and a cover
can start there -- except in a fifth of the cases, where one DOF is left free (its position held by
nothing at g = 0: the certificate's first-order start on (0, eps]), and the first device is open-loop
unstable in some (sup g = 0, or a refusal by name where M(0) has an eigenvalue on the circle too). In a quarter,
K is maximised instead, a term of every wall's own expression K + E_ii(z) (gain 1, no conserved quantities:
the certificate's "p inside the tf"), and the reference adds K to the walls it realises; in half of those the
walls at K = 0 are dampers B (z - 1)/(T z) alone (no link spring), so M(0) is marginal where a DOF is free. Required of a certificate (exit 0): both
checkers verify it; the reference's rho < 1 at lo and at lo k/6, k = 1..5, rho > 1 at hi, and its own
first crossing (bisection on rho - 1 at 50 digits) inside [lo, hi] (1e-9 relative); and every mutant of
tests/check/loop_max_case.py (hi halved, lo raised to hi, a P entry negated, the model moved beyond the kind,
...) rejected by both as it must be. sup g = 0 (exit 1): rho > 1 at g = 10^-6 of
the scale. Refusals by name (exit 2) and undecided (exit 3) are counted apart, never as agreement.

  indep_loop_max_certificate.py HAPSTAB [--cases N] [--seed S] [--mutants-every K]
exit 0 when every compared case agrees, else 1.
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
from indep_common import Rational  # noqa: E402

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "check"))
import loop_max_case as LMC  # noqa: E402
import indep_loop_certificate as ILC  # noqa: E402
from indep_common import case_files, cases_and_seed  # noqa: E402


def draw(rng):
    c = IL.gen_scene(rng)
    d0 = c["devices"][0]
    if d0["kind"] == "ss" and not d0["passive"] and rng.random() < 0.7:  # gen_scene draws 60 %: keep a fifth or so
        c["devices"][0] = dict(kind="md", m=d0["m"], b=IL.rq(rng, 0, 5))
        c["tags"]["first device"] = "mass-damper"
    c["g"], c["coupled"], c["writes"], c["conserved"] = Q(1), False, {}, 0
    free = rng.random() < 0.2
    for i in range(len(c["ops"])):
        if free and i == len(c["ops"]) - 1:
            c["ops"][i] = None  # this DOF's position is held by nothing at g = 0
            continue
        b = c["ops"][i] if c["ops"][i] is not None else IL.rq(rng, 0.5, 5)
        c["ops"][i] = (b if not isinstance(b, tuple) else b[0], IL.rq(rng, 10, 500))
        c["writes"][i] = rng.choice(["m, b, k", "m, b, k", "tf", "ss"])
        c["conserved"] += c["writes"][i] != "m, b, k"
    c["tags"]["free DOF"] = free
    # a quarter: K added to every wall's own expression, K + E_ii(z), not a gain (no conserved quantities: the
    # operators written as m, b, k); the reference adds K to the walls it realises
    c["inside"] = rng.random() < 0.25
    c["tags"]["K inside tf"] = c["inside"]
    if c["inside"]:
        c["writes"], c["conserved"] = {}, 0
        if rng.random() < 0.5:  # the walls at K = 0 dampers B (z - 1)/(T z), no link: M(0) marginal, the first-order start
            c["E"] = [[Rational([-e.num[1], e.num[1]], [1, 0]) if i == j else Rational([0], [1]) for j, e in enumerate(row)]
                      for i, row in enumerate(c["E"])]
            c["tags"]["link spring"] = False
            c["tags"]["K inside tf"] = "damper walls"
            if not free and rng.random() < 0.6:  # a DOF held by nothing at K = 0 (the first-order start)
                c["ops"][-1], c["tags"]["free DOF"] = None, True
    return c


def family(c, g):
    """The loop at g: the walls times g, or (K inside the tf) K = g added to every wall E_ii."""
    if not c["inside"]:
        return c, Q(g)
    E = [[e + Rational([Q(g)], [1]) if i == j else e for j, e in enumerate(row)] for i, row in enumerate(c["E"])]
    return dict(c, E=E), Q(1)


def scene(c):
    """ILC.scene_text, with K inside every wall's tf (its gain 1) where c["inside"]."""
    text = ILC.scene_text(c)
    if not c["inside"]:
        return text
    for e in sorted({row[i].expr() for i, row in enumerate(c["E"])}):  # each wall's expression (every occurrence)
        assert '"%s"' % e in text, (e, text)
        text = text.replace('"%s"' % e, '"K + %s"' % e)
    return text.replace('gain = "g"\n', "").replace('g = "1"\n', 'K = "0"\n')


def rho(c, g):
    return ILC.rho(*family(c, g))


def crossing(rho_at, lo, hi):
    """The reference's first crossing in [lo, hi]: bisection on rho - 1 (rho(lo) < 1 <= rho(hi)) to 1e-12."""
    a, b = Q(lo), Q(hi)
    for _ in range(60):
        if (b - a) <= b * Q(1, 10 ** 12):
            break
        m = (a + b) / 2
        if rho_at(m) < 1:
            a = m
        else:
            b = m
    return a, b


MUTANTS = [0]  # mutants of the certificates (tests/check/loop_max_case.py's), every one rejected as it must be
MUTATE = {"every": 1, "case": 0}  # --mutants-every K: the mutants of every K-th case only (the reference on all)


def mutants_every(argv):
    """--mutants-every K (default 1): the mutants take most of a case's time (each through both checkers); a
    campaign for the reference's counts runs them on every K-th case."""
    if "--mutants-every" in argv:
        MUTATE["every"] = int(argv[argv.index("--mutants-every") + 1])
        if MUTATE["every"] < 1:
            raise SystemExit("--mutants-every: a whole number >= 1")


def checkers_exit(exe, path):
    return tuple(subprocess.run(cmd, capture_output=True, timeout=900).returncode for cmd in ILC.checkers(exe, path))


def judge(exe, cl, verdicts, rho_at, name, bad):
    """A stability-loop-max certificate's claim against the reference rho_at(value) (50 digits), shared with
    indep_plant_max_certificate.py: (True, what, None) for a sup = 0 that rho > 1 at 10^-6 confirms; (True, "",
    (a, b)) for [lo, hi] with rho < 1 at lo k/6, k = 1..6, rho > 1 at hi, the reference's crossing [a, b] in [lo,
    hi] (1e-9 relative) and every mutant of loop_max_case rejected by both checkers as it must be (one beyond
    the independent checker's stated limit, exit 3, is not checked there); (False, what, None) otherwise."""
    lo, hi = Q(cl["claim"]["lo"]), Q(cl["claim"]["hi"])
    if hi == 0:
        r0 = rho_at(Q(1, 10 ** 6))
        if not r0 > 1:
            return False, "sup %s = 0 certified, but the reference's rho at %s = 1e-6 is %s" % (name, name, mp.nstr(r0, 15)), None
        return True, "sup %s = 0 (rho(1e-6) = %s), verified by both" % (name, mp.nstr(r0, 12)), None
    for g in [lo * k / 6 for k in range(1, 7)]:
        rg = rho_at(g)
        if not rg < 1:
            return False, "stable on (0, %s] certified, but the reference's rho at %s is %s" % (float(lo), float(g), mp.nstr(rg, 15)), None
    rh = rho_at(hi)
    if not rh > 1:
        return False, "NOT stable at %s certified, but the reference's rho there is %s" % (float(hi), mp.nstr(rh, 15)), None
    a, b = crossing(rho_at, lo, hi)
    tol = hi * Q(1, 10 ** 9)
    if b < lo - tol or a > hi + tol:
        return False, "the reference's crossing [%s, %s] is outside [%s, %s]" % (float(a), float(b), float(lo), float(hi)), None
    for what, m, want in (LMC.mutants(cl, name)[1:] if MUTATE["case"] % MUTATE["every"] == 0 else []):
        with open(bad, "w") as f:
            json.dump(m, f)
        got = checkers_exit(exe, bad)
        if got[1] == 3:
            got = (got[0], got[0])
        if not LMC.agrees(got, want):
            return False, "%s: the checkers exit %s (want %s)" % (what, got, "1 or 2" if want is None else want), None
        MUTANTS[0] += 1
    return True, "", (a, b)


def mutants_said():
    return "its mutants refuted" if MUTATE["case"] % MUTATE["every"] == 0 else "mutants not run (--mutants-every %d)" % MUTATE["every"]


def run_case(exe, c, tmp):
    path, cert, bad = case_files(tmp, scene(c))
    name = "K" if c["inside"] else "g"
    r = subprocess.run([exe, "stability", "--scene", path, "--max", name, "--digits", "12", "--json", "--quiet", "--certificate", cert],
                       capture_output=True, text=True, timeout=900)
    if r.returncode == 2:
        why = r.stderr.strip()
        kind = ("marginal at g = 0" if "marginally stable" in why or "M(0)" in why else
                "no Stein P" if "no Stein" in why else "not affine" if "affine" in why else "other")
        return None, "refused by name (%s): %s" % (kind, why[:200]), "refused: " + kind
    if r.returncode == 3:
        return None, "undecided: " + r.stderr.strip()[:200], "undecided"
    if r.returncode not in (0, 1) or not os.path.exists(cert):
        return False, "exit %d without a certificate: %s" % (r.returncode, r.stderr.strip()[:300]), None
    cl = json.load(open(cert))
    verdicts = checkers_exit(exe, cert)
    if verdicts not in ((0, 0), (0, 3)):  # 3: beyond the independent checker's stated limit (not checked)
        return False, "a checker does not verify the certificate: exits %s" % (verdicts,), None
    if cl["claim"].get("conserved", 0) != c["conserved"]:
        return False, "the certificate claims %s conserved quantities, the scene writes %d" % (cl["claim"].get("conserved", 0), c["conserved"]), None
    ok, what, ab = judge(exe, cl, verdicts, lambda g: rho(c, g), name, bad)
    if ok is not True or ab is None:
        return ok, what, "sup = 0" if ok else None
    (a, b), lo, hi = ab, Q(cl["claim"]["lo"]), Q(cl["claim"]["hi"])
    n = len(cl["evidence"]["unstable_at"]["P"])
    return True, "sup %s in [%.12g, %.12g] (reference crossing %.12g; %d intervals, order %d%s), verified by %s, %s" % (
        name, float(lo), float(hi), float((a + b) / 2), len(cl["evidence"]["cover"]), n,
        ", %d conserved" % c["conserved"] if c["conserved"] else "", "both" if verdicts == (0, 0) else "hapstab check (beyond the independent one's limit)",
        mutants_said()), \
        "certified sup" + ("" if verdicts == (0, 0) else ", independent beyond its limit")


def main(argv):
    cases, seed = cases_and_seed(argv, 100, 1)
    mutants_every(argv)
    rng = random.Random("%d:indep_loop_max_certificate" % seed)
    counts, bad = {}, 0
    with tempfile.TemporaryDirectory() as tmp:
        for k in range(cases):
            c = draw(rng)
            MUTATE["case"] = k
            try:
                ok, what, branch = run_case(argv[1], c, tmp)
            except subprocess.TimeoutExpired:
                ok, what, branch = None, "timeout", "timeout"
            tag = "ok  " if ok else "MISS" if ok is False else "skip"
            print("%s case %d (%s): %s" % (tag, k, ", ".join("%s %s" % kv for kv in c["tags"].items()), what), flush=True)
            bad += ok is False
            key = branch or "disagree"
            if branch and c["tags"]["free DOF"]:
                key += " (a free DOF)"
            if branch and c["inside"]:
                key += " (K inside the tf)"
            counts[key] = counts.get(key, 0) + 1
    print("indep_loop_max_certificate: %d cases, %d disagree; %s; mutants of the certificates %d, each rejected as it must be" % (
        cases, bad, "; ".join("%s %d" % kv for kv in sorted(counts.items())), MUTANTS[0]))
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
