"""Shared pieces of the independent campaigns (tests/verify/independent.py): exact rational
polynomials and transfer functions written both as hapstab expressions and as coefficient lists
the references evaluate themselves, and the call of the hapstab binary (--json).

Nothing here comes from hapstab's sources: the references evaluate the paper's definitions
directly (indep_passivity.py: paper 001 (45)/(54); indep_loop.py: the sampled loop built as a
state-space map per period).
"""
import ast
import json
import os
import subprocess
import tempfile
import time
from fractions import Fraction as Q

import mpmath as mp
import numpy as np


def fstr(q):
    """An exact rational as hapstab reads it: "3", "(-3/7)"."""
    q = Q(q)
    s = str(q.numerator) if q.denominator == 1 else f"{q.numerator}/{q.denominator}"
    return f"({s})" if q < 0 or q.denominator != 1 else s


def poly_str(c, var):
    """Descending coefficients -> "(a)*z^2 + (b)*z + (c)" (zero terms dropped)."""
    n = len(c) - 1
    terms = []
    for i, a in enumerate(c):
        a = Q(a)
        if a == 0:
            continue
        p = n - i
        mono = "" if p == 0 else (var if p == 1 else f"{var}^{p}")
        if mono == "":
            terms.append(fstr(a))
        elif a == 1:
            terms.append(mono)
        else:
            terms.append(f"{fstr(a)}*{mono}")
    return " + ".join(terms) if terms else "0"


def pmul(a, b):
    out = [Q(0)] * (len(a) + len(b) - 1)
    for i, x in enumerate(a):
        for j, y in enumerate(b):
            out[i + j] += Q(x) * Q(y)
    return out


def padd(a, b):
    n = max(len(a), len(b))
    a = [Q(0)] * (n - len(a)) + [Q(x) for x in a]
    b = [Q(0)] * (n - len(b)) + [Q(x) for x in b]
    out = [x + y for x, y in zip(a, b)]
    while len(out) > 1 and out[0] == 0:
        out.pop(0)
    return out


def pscale(a, k):
    return [Q(k) * Q(x) for x in a]


class Rational:
    """num(var)/den(var) with exact rational descending coefficients."""

    def __init__(self, num, den):
        self.num = [Q(x) for x in num]
        self.den = [Q(x) for x in den]

    def expr(self, var="z"):
        return f"({poly_str(self.num, var)})/({poly_str(self.den, var)})"

    def __add__(self, o):
        return Rational(padd(pmul(self.num, o.den), pmul(o.num, self.den)), pmul(self.den, o.den))

    def scaled(self, k):
        return Rational(pscale(self.num, k), self.den)

    def eval_mp(self, z):
        if not hasattr(self, "_mp"):
            with mp.workdps(150):  # exact enough for every precision the references use
                self._mp = ([mp.mpf(x.numerator) / x.denominator for x in self.num],
                            [mp.mpf(x.numerator) / x.denominator for x in self.den])
        return mp.polyval(self._mp[0], z) / mp.polyval(self._mp[1], z)

    def coeffs_float(self):
        return [float(x) for x in self.num], [float(x) for x in self.den]


class SumTF:
    """A sum of rational terms, each written for hapstab as its own fraction (so the expression
    hapstab parses is the same sum the reference evaluates term by term)."""

    def __init__(self, terms):
        self.terms = list(terms)

    def expr(self, var="z"):
        return " + ".join(t.expr(var) for t in self.terms)

    def eval_mp(self, z):
        return mp.fsum(t.eval_mp(z) for t in self.terms)

    def dens(self):
        return [t.den for t in self.terms]


def cases_and_seed(argv, cases=12, seed=1):
    """--cases N and --seed S of a small campaign script's argv (its defaults otherwise)."""
    if "--cases" in argv:
        cases = int(argv[argv.index("--cases") + 1])
    if "--seed" in argv:
        seed = int(argv[argv.index("--seed") + 1])
    return cases, seed


def case_files(tmp, scene_text):
    """(scene, certificate, mutant) paths in tmp for one case: the scene written, a certificate of the case before
    removed (a producer that writes none must not leave the last one to be checked)."""
    scene, cert, bad = (os.path.join(tmp, x) for x in ("s.toml", "c.json", "b.json"))
    with open(scene, "w") as f:
        f.write(scene_text)
    if os.path.exists(cert):
        os.remove(cert)
    return scene, cert, bad


def loop_claim_flipped(cl):
    """A stability-loop certificate with its claim flipped: w added (a unit vector) to a stable
    claim, w removed from a NOT stable one; both checkers must refute it."""
    flipped = json.loads(json.dumps(cl))
    stable = cl["claim"]["stable"]
    flipped["claim"]["stable"] = not stable
    if stable:
        flipped["evidence"]["w"] = ["1"] + ["0"] * (len(cl["evidence"]["P"]) - 1)
    else:
        del flipped["evidence"]["w"]
    return flipped


def both_checkers(exe, good, bad, bad_what):
    """(True, "") when both checkers verify the certificate file `good` (exit 0) and refute `bad`
    (exit 1), else (False, which did not and what)."""
    top = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
    for cmd in ([exe, "check"], ["/usr/bin/python3", os.path.join(top, "checks", "hapstab_check.py")]):
        if subprocess.run(cmd + [good], capture_output=True).returncode != 0:
            return False, "%s does not verify it" % os.path.basename(cmd[-1])
        if subprocess.run(cmd + [bad], capture_output=True).returncode != 1:
            return False, "%s does not refute %s" % (os.path.basename(cmd[-1]), bad_what)
    return True, ""


def run_hapstab(exe, args, timeout):
    """Runs `hapstab ARGS --json`; returns (rc, parsed JSON or None, stderr text, seconds)."""
    t0 = time.monotonic()
    try:
        p = subprocess.run([exe] + args + ["--json"], capture_output=True, text=True, timeout=timeout)
    except subprocess.TimeoutExpired:
        return "timeout", None, f"no answer within {timeout} s", time.monotonic() - t0
    dt = time.monotonic() - t0
    j = None
    try:
        j = json.loads(p.stdout) if p.stdout.strip() else None
    except json.JSONDecodeError:
        j = None
    return p.returncode, j, p.stderr.strip(), dt


def run_hapstab_scene(exe, text, prefix, extra_args, timeout):
    """Writes the scene TEXT to a temporary file and runs `hapstab stability --scene FILE
    EXTRA_ARGS --json` on it; returns (rc, JSON or None, stderr text, seconds, the arguments run,
    the file). keep_scene_if_missed removes the file unless the case is a miss."""
    with tempfile.NamedTemporaryFile("w", suffix=".toml", delete=False, prefix=prefix) as f:
        f.write(text)
    args = ["stability", "--scene", f.name] + list(extra_args)
    return run_hapstab(exe, args, timeout) + (args, f.name)


def keep_scene_if_missed(out, path, *certificates):
    """A missed case keeps its scene file (named in its `why`) and its certificates to be run again;
    others remove them."""
    if out["outcome"] in ("MISS", "REFERENCE MISSED"):
        out["why"] = out.get("why", "") + f" (scene kept: {path})"
    else:
        for f in (path,) + certificates:
            if os.path.exists(f):
                os.unlink(f)


def shell_line(exe, args):
    def q(a):
        return a if all(c.isalnum() or c in "-_./=:" for c in a) else "'" + a.replace("'", "'\\''") + "'"
    return " ".join(q(a) for a in [exe] + args)


def dec(s):
    """A decimal string from hapstab's JSON as an mpf (inf kept)."""
    if s is None:
        return None
    s = str(s).strip()
    if s in ("inf", "+inf", "Infinity"):
        return mp.inf
    if s in ("-inf", "-Infinity"):
        return -mp.inf
    with mp.workdps(120):  # every digit hapstab printed
        return mp.mpf(s)


def golden_section(f, a, b, it=60, tol=None):
    """Golden-section search for a minimum of f on [a, b] in mpmath: `it` steps, or fewer once the
    bracket is narrower than tol (relative to 1 + |a|). Returns the final bracket (a, c, d, b) and
    f at c and d."""
    g = (mp.sqrt(5) - 1) / 2
    c, d = b - g * (b - a), a + g * (b - a)
    fc, fd = f(c), f(d)
    for _ in range(it):
        if tol is not None and b - a < tol * (1 + abs(a)):
            break
        if fc < fd:
            b, d, fd = d, c, fc
            c = b - g * (b - a)
            fc = f(c)
        else:
            a, c, fc = c, d, fd
            d = a + g * (b - a)
            fd = f(d)
    return a, c, d, b, fc, fd


def golden(f, a, b, it=60):
    """golden_section's better end: (argmin, min)."""
    _, c, d, _, fc, fd = golden_section(f, a, b, it)
    return (c, fc) if fc < fd else (d, fd)


def local_extrema(v, k=6):
    """Indices of the k least local minima of the array v."""
    n = len(v)
    loc = [i for i in range(n) if v[i] <= (v[i - 1] if i else np.inf) and v[i] <= (v[i + 1] if i + 1 < n else np.inf)]
    return sorted(loc, key=lambda i: v[i])[:k]


class Expr:
    """One scene expression, compiled once: evaluated with mpmath (exact constants) or numpy."""
    OK = (ast.Expression, ast.BinOp, ast.UnaryOp, ast.Add, ast.Sub, ast.Mult, ast.Div, ast.Pow,
          ast.USub, ast.UAdd, ast.Name, ast.Load, ast.Constant)

    def __init__(self, text, params):
        tree = ast.parse(text.replace("^", "**"), mode="eval")
        consts = []
        for node in ast.walk(tree):
            if not isinstance(node, self.OK):
                raise ValueError(f"expression {text!r}: {type(node).__name__} not understood")
            if isinstance(node, ast.Constant) and not isinstance(node.value, int):
                raise ValueError(f"expression {text!r}: non-integer literal {node.value!r}")

        class Lit(ast.NodeTransformer):
            def visit_Constant(self, node):
                consts.append(node.value)
                return ast.copy_location(ast.Name(id=f"_k{len(consts) - 1}", ctx=ast.Load()), node)
        tree = ast.fix_missing_locations(Lit().visit(tree))
        self.code = compile(tree, "<scene>", "eval")
        self.consts = consts
        self.params = params
        self.text = text

    def _env(self, conv, var, val):
        env = {f"_k{i}": conv(Q(c)) for i, c in enumerate(self.consts)}
        env.update({k: conv(v) for k, v in self.params.items()})
        env[var] = val
        return env

    def mp(self, var, val):
        return eval(self.code, {"__builtins__": {}}, self._env(lambda q: mp.mpf(q.numerator) / q.denominator, var, val))

    def np(self, var, val):
        return eval(self.code, {"__builtins__": {}}, self._env(float, var, val))


def exact(x):
    if isinstance(x, int):
        return Q(x)
    if isinstance(x, str):
        return Q(x.strip())
    raise ValueError(f"not an exact number: {x!r}")


def analyze_case_main(argv, scene_cls, decide, expect=(("feasible", "feasible"), ("witness", "infeasible (witness)"))):
    """HAPSTAB SCENE [EXPECT]: one scene file through `multidof analyze --json` and a reference's
    decide (indep_witness.py, indep_coupling.py); exit 0 when they agree (and hapstab's answer is
    expect[EXPECT], e.g. feasible | witness), else 1."""
    exe, path = argv[1], argv[2]
    text = open(path).read()
    p = subprocess.run([exe, "multidof", "analyze", "--scene", path, "--json"], capture_output=True, text=True, timeout=300)
    j = json.loads(p.stdout)
    out = decide(dict(tags={}), scene_cls(text), j, p.returncode)
    print(f"{path}: {out['outcome']}; hapstab: {out.get('hapstab', '')[:200]}")
    print(f"  reference: {out.get('ref_text')}" + (f"; {out['why']}" if out.get("why") else ""))
    want = dict(expect).get(argv[3]) if len(argv) > 3 else None
    if want and out["tags"].get("hapstab") != want:
        print(f"  expected hapstab's answer {want}")
        return 1
    return 0 if out["outcome"] == "agree" else 1


def witness_decides(out, bad):
    """hapstab's printed witness re-evaluated (bad: None when it holds, "boundary" when phi = 0 to 40
    digits, else why it fails) into the case's outcome: True when that decides the case."""
    if bad == "boundary":
        out.update(outcome="reference undecided", why="hapstab's witness has phi = 0 to 40 digits")
        return True
    if bad:
        out.update(outcome="MISS", why="hapstab's certified witness does not hold: " + bad)
        return True
    return False


def run_cases(cases, draw, run_one, prefix):
    """A small campaign's loop: `cases` cases, each drawn (draw()), run in a temporary folder (run_one(c, tmp) ->
    (ok, what, branch): True agrees, False disagrees, None is counted apart), printed as ok / MISS / skip, and
    counted by branch (a disagreement as "disagree", a timeout as "timeout"). Returns (counts, disagreements)."""
    counts, bad = {}, 0
    with tempfile.TemporaryDirectory(prefix=prefix) as tmp:
        for k in range(cases):
            c = draw()
            try:
                ok, what, branch = run_one(c, tmp)
            except subprocess.TimeoutExpired:
                ok, what, branch = None, "timeout", "timeout"
            print("%s case %d: %s" % ({True: "ok  ", False: "MISS", None: "skip"}[ok], k, what), flush=True)
            bad += ok is False
            counts[branch or "disagree"] = counts.get(branch or "disagree", 0) + 1
    return counts, bad
