"""`stability --scene S` (and its `--certificate`) on loops whose blocks hold modes at z = 1 (s = 0) that the
loop may chain into a Jordan block, against the loop built here in mpmath (50 digits) from the numbers drawn --
never from the scene's text as hapstab reads it, hapstab's output or either checker.

Why: stop 87's review found an `ss` wall hiding a constant force (z = 1 no input reaches, the output sees: an
"injector") beside a sum of positions (z = 1 the input reaches, no output shows: an "integrator"). Each is
semisimple in E's A, but the constant moves the equilibrium and the sum integrates it: z = 1 is a Jordan block of
the loop's period map and the state grows linearly; hapstab said "stable [certified]". indep_hidden_mode.py
missed it: its reference lets any eigenvalue 1 settle. Here the reference looks at the Jordan structure.

The draws (every exact rational, written into the scene as such): one DOF (3/4) or two (a 2 x 2 wall, its DOFs
coupled by -Kc or not), devices force -> velocity: mass-dampers m, b and `ss` devices -- first order; with their
own position state (p' = v, no output shows it: neither kind in the loop); a constant force (gravity: an injector
of the plant); a constant velocity offset (injector); an internal spring (G(0) = 0: the position the loop
integrates differs from the spring's deflection by a constant, an injector of the composed plant); a state that
sums the force (q' = u, unseen: an integrator of the plant; beside the spring the pair chains); own position AND
gravity (the device's A has a Jordan block at s = 0 although the loop settles); a hidden velocity ramp (a true
Jordan block at s = 0: NOT stable); hidden oscillator / growing / damped pairs (s = +-jw, +-w, damped), some
written in a random exact basis. Operators on the first DOF: dampers; m, b, k (a spring: its deflection
integrates the velocity the position does, an injector); `ss` ones with a hidden constant force (injector), a
spring, an unseen integrator of the velocity (neither), a hidden s = 1/2. Walls K + B (z - 1)/(T z) as `tf`, or as
`ss` with hidden parts: injector, integrator, both, neither, hidden modes at 1/2, -1, 3/2 or a rotation pair on
the circle (unreached or unseen), a visible integrator (PI wall) with and without them, a constant feeding the
visible integrator or the visible integrator feeding an unseen sum (chains inside E's A), a hidden Jordan pair at
1; in a random exact basis in 2/5 of the cases. Couplings (6 cases in 10): a compliance 1/kc in parallel with hidden
parts (a constant displacement: injector; a sum of forces: integrator; both; neither; a hidden mode off 1).

The reference: the plant (device states, positions x' = v, operator states; the operator's force -Z_O v on the
device, an operator's mass added to a mass-damper's) discretised under the zero-order hold by Van Loan's exponential
(indep_loop.zoh, 50 digits); the wall xi+ = A_E xi + B_E x_e, the coupling eta+ = A_V eta + B_V u, the force solved
from u = -(C_E xi + D_E x_e), x_e = x + C_V eta + D_V u exactly as the numbers say; X = [plant; xi; eta] and
X+ = M X. With the eigenvalues mu of M (mpmath.eig at 50 digits; at 60, then 80, where its QR iteration does not
converge, rarely -- and where none converges the case is "reference undecided", counted apart) and a = #{|mu - 1| < 1e-12} (a Jordan block of
size k splits by about 1e-50/k at 50 digits, so it stays in that cluster up to k = 4), g = dim null(M - I) = the
number of singular values of M - I below 1e-35 (mpmath.svd_r):
  NOT stable  when a > g (z = 1 not semisimple: a Jordan block, linear growth); else when an eigenvalue outside
              the cluster has |mu| > 1 + 1e-30, or |mu| >= 1 - 1e-40 (on the circle away from 1);
  stable      otherwise (a semisimple z = 1 settles to the constant the conserved quantities select).
The thresholds are checked on every case drawn: the summary prints the largest |mu - 1| counted in the cluster and
the least one outside it, and the largest singular value counted as 0 and the least one above it (seed 1: the
gaps are tens of decades wide). Every case with an eigenvalue at 1 and the rest inside |z| < 1 - 1e-6 is also
simulated: X_n = M^n X_0 from a generic X_0 at n, 2n, 4n steps (n >= 2048, a power of two large enough that the
rest has decayed by 1e-20; M^n by repeated squaring, the same product as n steps): growth is |X_2n - X_n| and
|X_4n - X_2n| both above 1e-6 |X_0| (with the rest decayed, what is left is polynomial in n: linear for a Jordan
block of size 2, the ratio of the two near 2), settling |X_4n - X_2n| < 1e-12 |X_0|; anything else, or growth
where a = g, or settling where a > g, is a REFERENCE INCONSISTENT (counted, fails).

What hapstab promises (docs/stability.md, certificates.md): exit 0 stable, 1 NOT stable, 3 undecided, 2 bad
input or refused. A mode at z = 1 (s = 0) set aside -- a hidden one, or a conserved quantity of the composed plant
-- settles when it is of one kind; injectors beside integrators anywhere in the loop are undecided (exit 3), never
stable (`sim::marginal_parts`). That is this reference's stable-iff-semisimple, made conservative: an undecided
answer is counted apart, never as agreement. One documented difference is avoided rather than followed: hapstab
decides Schur stability of the loop after setting those modes aside, so an eigenvalue 1 of the loop's own
(reached and seen) part -- a wall with no spring, a coupling that integrates the force into its output -- is NOT
stable there, while this reference would call a semisimple one stable. No case draws one: every wall has K > 0,
a PI wall's integrator pushes the DOFs it sums, so the loop moves it off 1, and no coupling shows an integrator.

Required: every decided verdict is the reference's; for a decided case `--certificate` writes one that both
checkers verify and whose claim is the reference's, or refuses by name (exit 2, counted apart). A certificate both
checkers verify for a verdict the reference contradicts is a defect whatever hapstab printed.

  indep_jordan_at_one.py HAPSTAB [--cases N] [--seed S] [--first K] [--progress P] [--keep DIR]
Case k's branches cycle with k (draw()) and its numbers come from random.Random("jordan:S:k"), so --first K
--cases 1 reruns case K; --keep DIR writes the scene of every disagreement there. Exit 0 when no decided case (or certificate) disagrees and the reference is
consistent, else 1. CI slice: --cases 40 --seed 1 (every branch hit, 16 s on the 2-core machine).
"""
import json
import os
import random
import subprocess
import sys
import tempfile
import time
from fractions import Fraction as Q

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

import mpmath as mp  # noqa: E402

from indep_common import cases_and_seed  # noqa: E402
from indep_loop import zoh  # noqa: E402

DPS = 50
TOP = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
CLUSTER, SV_ZERO, OUTSIDE, ON_CIRCLE = "1e-12", "1e-35", "1e-30", "1e-40"

# ---------------------------------------------------------------------------------------------
# exact matrices (lists of lists of Fractions)


def s(q):
    q = Q(q)
    return str(q.numerator) if q.denominator == 1 else "%d/%d" % (q.numerator, q.denominator)


def zeros(r, c):
    return [[Q(0)] * c for _ in range(r)]


def mul(A, B):
    return [[sum((A[i][k] * B[k][j] for k in range(len(B))), Q(0)) for j in range(len(B[0]))] for i in range(len(A))]


def inv(A):
    n = len(A)
    M = [list(A[i]) + [Q(int(i == j)) for j in range(n)] for i in range(n)]
    for c in range(n):
        p = next(r for r in range(c, n) if M[r][c] != 0)
        M[c], M[p] = M[p], M[c]
        f = M[c][c]
        M[c] = [x / f for x in M[c]]
        for r in range(n):
            if r != c and M[r][c] != 0:
                g = M[r][c]
                M[r] = [x - g * y for x, y in zip(M[r], M[c])]
    return [row[n:] for row in M]


def blkdiag(A, B):
    n, m = len(A), len(B)
    out = zeros(n + m, n + m)
    for i in range(n):
        out[i][:n] = A[i]
    for i in range(m):
        out[n + i][n:] = B[i]
    return out


def tm(M):
    """A matrix as a TOML array of strings."""
    return "[" + ", ".join("[" + ", ".join('"%s"' % s(x) for x in row) + "]" for row in M) + "]"


def ss_text(b):
    A, B, C, D = b
    return "ss = { A = %s, B = %s, C = %s, D = %s }" % (tm(A), tm(B), tm(C), tm(D))


def basis_change(rng, b):
    """(A, B, C, D) in a random exact basis: S A S^-1, S B, C S^-1 (S = L U, unit triangular, small integers)."""
    A, B, C, D = b
    n = len(A)
    L, U = zeros(n, n), zeros(n, n)
    for i in range(n):
        L[i][i] = U[i][i] = Q(1)
        for j in range(i):
            L[i][j] = Q(rng.choice([-1, 0, 1, 2]))
            U[j][i] = Q(rng.choice([-1, 0, 1]))
    S = mul(L, U)
    Si = inv(S)
    return mul(mul(S, A), Si), mul(S, B), mul(C, Si), D


# ---------------------------------------------------------------------------------------------
# draws

DEVICES = ["md", "md", "md", "ss first order", "ss own position", "ss gravity", "ss velocity offset", "ss spring",
           "ss force sum", "ss spring + force sum", "ss own position + gravity", "ss hidden ramp", "ss hidden pair"]
OPERATORS = ["none", "none", "damper", "m, b, k spring", "m, b, k spring", "ss hidden constant", "ss spring",
             "ss unseen integrator", "ss hidden s = 1/2"]
WALL_RECIPES = [(), ("inj",), ("int",), ("inj", "int"), ("inj", "int"), ("nei",), ("inj", "nei"), ("off1",),
                ("inj", "off1"), ("int", "off1"), ("pi",), ("pi", "inj"), ("pi", "int"), ("pi", "inj", "int"),
                ("chainA",), ("chainB",), ("jordan",)]
COUPLING_RECIPES = [(), ("inj",), ("int",), ("inj", "int"), ("nei",), ("off1",)]
OFF1 = ["1/2", "-1", "3/2", "pair"]


def dof_vec(rng, N, scale):
    """A row (or column) over the N DOFs: which DOFs, times scale."""
    pat = [1] if N == 1 else rng.choice([[1, 0], [0, 1], [1, 1]])
    return [Q(x) * Q(scale) for x in pat]


def draw_device(rng, kind):
    m, b = Q(rng.choice(["1/10", "1/2", "1"])), Q(rng.choice(["5", "10", "30"]))
    k = Q(rng.choice(["100", "1000"]))
    d = dict(kind=kind, m=m, b=b)
    if kind == "md":
        return d
    a = -b / m
    i = 1 / m
    if kind == "ss first order":
        A, B, C = [[a]], [[i]], [[Q(1)]]
    elif kind == "ss own position":
        A, B, C = [[a, 0], [1, 0]], [[i], [0]], [[1, 0]]
    elif kind == "ss gravity":
        A, B, C = [[a, 1], [0, 0]], [[i], [0]], [[1, 0]]
    elif kind == "ss velocity offset":
        A, B, C = [[a, 0], [0, 0]], [[i], [0]], [[1, Q(rng.choice(["1", "1/100"]))]]
    elif kind == "ss spring":
        A, B, C = [[a, -k / m], [1, 0]], [[i], [0]], [[1, 0]]
    elif kind == "ss force sum":
        A, B, C = [[a, 0], [0, 0]], [[i], [1]], [[1, 0]]
    elif kind == "ss spring + force sum":
        A, B, C = [[a, -k / m, 0], [1, 0, 0], [0, 0, 0]], [[i], [0], [1]], [[1, 0, 0]]
    elif kind == "ss own position + gravity":
        A, B, C = [[a, 1, 0], [0, 0, 0], [1, 0, 0]], [[i], [0], [0]], [[1, 0, 0]]
    elif kind == "ss hidden ramp":
        A, B, C = [[a, 0, 0], [0, 0, 1], [0, 0, 0]], [[i], [0], [0]], [[1, 1, 0]]
    else:  # hidden pair: oscillator s = +-jw, growing +-w, damped
        w2 = Q(rng.choice(["1", "4", "9"]))
        d["pair"] = rng.choice(["oscillator", "growing", "damped"])
        a21, a22 = {"oscillator": (-w2, 0), "growing": (w2, 0), "damped": (-w2, -1)}[d["pair"]]
        A, B = [[a, 0, 0], [0, 0, 1], [0, a21, a22]], [[i], [0], [0]]
        C = [[1, rng.choice([0, Q(1, 10)]), 0]]
    A, B, C = ([[Q(x) for x in row] for row in M] for M in (A, B, C))
    blk = (A, B, C, [[Q(0)]])
    d["basis"] = len(A) > 1 and rng.random() < 0.25
    if d["basis"]:
        blk = basis_change(rng, blk)
    d["ss"] = blk
    return d


def draw_operator(rng, device, kind):
    bo = Q(rng.choice(["0", "2", "5"]))
    o = dict(kind=kind, b=bo, m=Q(0), k=Q(0))
    if kind == "damper":
        o["b"] = Q(rng.choice(["2", "5"]))
    elif kind == "m, b, k spring":
        o["k"] = Q(rng.choice(["50", "500"]))
        if device["kind"] == "md":
            o["m"] = Q(rng.choice(["0", "1/10"]))
    elif kind != "none":
        A, B, C = {"ss hidden constant": ([[0]], [[0]], [[rng.choice([1, 10])]]),
                   "ss spring": ([[0]], [[1]], [[rng.choice([50, 500])]]),
                   "ss unseen integrator": ([[0]], [[1]], [[0]]),
                   "ss hidden s = 1/2": ([[Q(1, 2)]], [[1]], [[0]])}[kind]
        o["ss"] = tuple([[Q(x) for x in row] for row in M] for M in (A, B, C, [[bo]]))
    return o


def wall_part(rng, name, N, gain):
    """One hidden (or visible-integrator) part of an ss wall: (A, B, C) over N DOFs, and its label."""
    beta = lambda: [dof_vec(rng, N, rng.choice(["1", "1/10"]))]  # noqa: E731  B rows (1 x N)
    gam = lambda sc: [[x] for x in dof_vec(rng, N, sc)]  # noqa: E731  C column (N x 1)
    z1, zN = [[Q(0)] * N], [[Q(0)] for _ in range(N)]
    if name == "inj":
        return [[Q(1)]], z1, gam(rng.choice(["1", "50"])), "injector"
    if name == "int":
        return [[Q(1)]], beta(), zN, "integrator"
    if name == "nei":
        return [[Q(1)]], z1, zN, "neither"
    # a visible integrator pushes the DOFs it sums (C = gain B^T): the loop closes around it and moves it off 1
    # (one that sums DOF 0 and pushes DOF 1 of two uncoupled DOFs would stay at 1, a loop mode hapstab's
    # Schur test calls NOT stable by its definition -- not a set-aside mode; not drawn)
    if name == "pi":
        pat = dof_vec(rng, N, 1)
        g = gain / rng.choice([200, 1000])
        return [[Q(1)]], [pat], [[x * g] for x in pat], "visible integrator"
    if name in ("chainA", "chainB", "jordan"):
        A = [[Q(1), Q(1)], [Q(0), Q(1)]] if name != "chainB" else [[Q(1), Q(0)], [Q(1), Q(1)]]
        pat = dof_vec(rng, N, 1)
        b = [pat, [Q(0)] * N]
        g = gain / rng.choice([200, 1000])
        c = [[x * g, Q(0)] for x in pat]
        if name == "chainA":
            return A, b, c, "constant into a visible integrator"
        if name == "chainB":
            return A, b, c, "visible integrator into an unseen sum"
        if rng.random() < 0.5:  # a Jordan pair no input reaches, the output sees
            return A, [[Q(0)] * N, [Q(0)] * N], c, "hidden Jordan pair (unreached)"
        return [[Q(1), Q(0)], [Q(1), Q(1)]], b, [[Q(0), Q(0)] for _ in range(N)], "hidden Jordan pair (unseen)"
    lam = rng.choice(OFF1)
    A = [[Q(3, 5), Q(-4, 5)], [Q(4, 5), Q(3, 5)]] if lam == "pair" else [[Q(lam)]]
    r = len(A)
    if rng.random() < 0.5:
        return A, [[Q(0)] * N for _ in range(r)], [[v] * r for v in dof_vec(rng, N, 1)], "z = %s unreached" % lam
    return A, [dof_vec(rng, N, 1) for _ in range(r)], [[Q(0)] * r for _ in range(N)], "z = %s unseen" % lam


def assemble(base, parts):
    A, B, C, D = base
    labels = []
    for (Ah, Bh, Ch, lab) in parts:
        A = blkdiag(A, Ah)
        B = B + Bh
        C = [C[i] + Ch[i] for i in range(len(C))]
        labels.append(lab)
    return (A, B, C, D), labels


def draw(rng, k):
    """Case k: its branches cycle with k -- the wall's recipe k mod 18, the first device's kind k mod 13, and with
    h = k // 18 the operator (k + h) mod 9, the coupling (k + 3 h) mod 10, two DOFs when (k + h) mod 4 = 3: any 18
    consecutive cases hit each, and the shift h pairs every wall with every operator and coupling over 180 cases; the
    rest (numbers, the second device, which DOFs a part acts on, the hidden mode off 1, bases) comes from rng."""
    h = k // 18
    c = dict(T=Q(rng.choice(["1/1000", "1/1000", "1/500"])), N=2 if (k + h) % 4 == 3 else 1)
    N = c["N"]
    c["devices"] = [draw_device(rng, DEVICES[k % len(DEVICES)])] + [draw_device(rng, rng.choice(DEVICES)) for _ in range(N - 1)]
    c["operator"] = draw_operator(rng, c["devices"][0], OPERATORS[(k + h) % len(OPERATORS)])
    K = [Q(rng.choice(["200", "1000", "2000"])) for _ in range(N)]
    Bw = [Q(rng.choice(["0", "2", "5"])) for _ in range(N)]
    Kc = Q(rng.choice(["0", "100"])) if N == 2 else Q(0)
    c.update(K=K, Bw=Bw, Kc=Kc)
    T = c["T"]
    recipe = (WALL_RECIPES + ["tf"])[k % (len(WALL_RECIPES) + 1)]
    c["wall_form"] = "tf" if recipe == "tf" else "ss"
    if c["wall_form"] == "ss":
        # base: D = K + B/T on the diagonal, -Kc off it; one damper state per DOF (xi_j+ = x_e,j, force -B_j/T xi_j)
        D = [[(K[i] + Bw[i] / T) if i == j else -Kc for j in range(N)] for i in range(N)]
        A = zeros(N, N)
        B = [[Q(int(i == j)) for j in range(N)] for i in range(N)]
        C = [[(-Bw[i] / T) if i == j else Q(0) for j in range(N)] for i in range(N)]
        c["wall_recipe"] = recipe
        parts = [wall_part(rng, p, N, K[0]) for p in c["wall_recipe"]]
        blk, c["wall_parts"] = assemble((A, B, C, D), parts)
        c["wall_basis"] = rng.random() < 0.4
        if c["wall_basis"]:
            blk = basis_change(rng, blk)
        c["wall"] = blk
    else:
        c["wall_recipe"], c["wall_parts"], c["wall_basis"] = ("tf",), [], False
    c["coupling_recipe"] = None
    rec = ([None] * 4 + COUPLING_RECIPES)[(k + 3 * h) % (4 + len(COUPLING_RECIPES))]
    if rec is not None:
        kc = Q(rng.choice(["500", "2000", "8000"]))
        parts = []
        for p in rec:
            z1, zN = [[Q(0)] * N], [[Q(0)] for _ in range(N)]
            if p == "inj":
                parts.append(([[Q(1)]], z1, [[x] for x in dof_vec(rng, N, rng.choice(["1/1000", "1/100"]))], "injector"))
            elif p == "int":
                parts.append(([[Q(1)]], [dof_vec(rng, N, rng.choice(["1/1000", "1"]))], zN, "integrator"))
            elif p == "nei":
                parts.append(([[Q(1)]], z1, zN, "neither"))
            else:
                parts.append(wall_part(rng, "off1", N, 1))
        base = ([], [], [[] for _ in range(N)], [[1 / kc if i == j else Q(0) for j in range(N)] for i in range(N)])
        blk, labels = assemble(base, parts)
        if len(blk[0]) > 1 and rng.random() < 0.3:
            blk = basis_change(rng, blk)
        c.update(coupling_recipe=rec, coupling=blk, coupling_parts=labels, kc=kc)
    return c


# ---------------------------------------------------------------------------------------------
# the scene


def scene(c):
    T, N = c["T"], c["N"]
    L = ["[scene]", 'name = "jordan at one"', 'T = "%s"' % s(T)]
    for j, d in enumerate(c["devices"]):
        L += ["", "[[device]]", 'name = "d%d"' % j]
        if d["kind"] == "md":
            L += ['m = "%s"' % s(d["m"]), 'b = "%s"' % s(d["b"])]
        else:
            L += [ss_text(d["ss"]), "passive = false"]
    o = c["operator"]
    if o["kind"] != "none":
        L += ["", "[[operator]]", 'name = "hand"', 'dofs = ["d0"]']
        if "ss" in o:
            L += [ss_text(o["ss"]), "passive = false"]
        else:
            for key in ("m", "b", "k"):
                if o[key] != 0:
                    L.append('%s = "%s"' % (key, s(o[key])))
    L += ["", "[environment]"]
    if c["wall_form"] == "tf":
        def entry(i, j):
            if i != j:
                return s(-c["Kc"])
            return s(c["K"][i]) + (" + %s*(z-1)/(T*z)" % s(c["Bw"][i]) if c["Bw"][i] != 0 else "")
        if N == 1:
            L.append('tf = "%s"' % entry(0, 0))
        else:
            L.append("tf = [" + ", ".join("[" + ", ".join('"%s"' % entry(i, j) for j in range(N)) + "]" for i in range(N)) + "]")
    else:
        L.append(ss_text(c["wall"]))
    if c["coupling_recipe"] is not None:
        L += ["", "[coupling]"]
        if len(c["coupling"][0]) == 0:
            Dv = c["coupling"][3]
            L.append('tf = "%s"' % s(Dv[0][0]) if N == 1 else "tf = " + tm(Dv))
        else:
            L.append(ss_text(c["coupling"]))
    return "\n".join(L) + "\n"


# ---------------------------------------------------------------------------------------------
# the reference


def f(q):
    q = Q(q)
    return mp.mpf(q.numerator) / q.denominator


def mpm(M, r=None, c=None):
    r = len(M) if r is None else r
    c = (len(M[0]) if M else 0) if c is None else c
    out = mp.zeros(r, c) if r and c else None
    for i in range(r):
        for j in range(c):
            out[i, j] = f(M[i][j])
    return out


def device_block(d, o):
    """(A, B, C) of the device force -> velocity, an operator's mass added to a mass-damper's."""
    if d["kind"] == "md":
        M = d["m"] + (o["m"] if o else 0)
        return [[-d["b"] / M]], [[1 / M]], [[Q(1)]]
    return d["ss"][:3]


def operator_block(o):
    """(A, B, C, D) of Z_O without its mass (velocity -> force), or None."""
    if o["kind"] == "none":
        return None
    if "ss" in o:
        return o["ss"]
    if o["k"] != 0:  # Z = m s + b + k/s: the deflection q' = v, F = k q + b v
        return [[Q(0)]], [[Q(1)]], [[o["k"]]], [[o["b"]]]
    return [], [], [], [[o["b"]]]


def loop_matrix(c):
    """M (mpmath, 50 digits) on X = [plant: per DOF device states and position, operator states; wall; coupling]."""
    N, T = c["N"], c["T"]
    o = c["operator"]
    devs = [device_block(d, o if j == 0 else None) for j, d in enumerate(c["devices"])]
    ob = operator_block(o)
    offs, n = [], 0
    for (A, _, _) in devs:
        offs.append(n)
        n += len(A) + 1  # states, then the position
    op_off, nop = n, (len(ob[0]) if ob else 0)
    npl = n + nop
    Ap, Bp, Cx = mp.zeros(npl, npl), mp.zeros(npl, N), mp.zeros(N, npl)
    for j, (A, B, C) in enumerate(devs):
        r, x = offs[j], offs[j] + len(A)
        for a in range(len(A)):
            for b in range(len(A)):
                Ap[r + a, r + b] += f(A[a][b])
            Bp[r + a, j] += f(B[a][0])
        for b in range(len(A)):
            Ap[x, r + b] += f(C[0][b])  # x' = v
        Cx[j, x] = 1
    if ob:  # on DOF 0: the device's input gets -(C_o w + D_o v); w' = A_o w + B_o v
        A, B, C = devs[0]
        Ao, Bo, Co, Do = ob
        r = offs[0]
        for a in range(len(A)):
            for b in range(len(A)):
                Ap[r + a, r + b] -= f(B[a][0]) * f(Do[0][0]) * f(C[0][b])
            for b in range(nop):
                Ap[r + a, op_off + b] -= f(B[a][0]) * f(Co[0][b])
        for a in range(nop):
            for b in range(nop):
                Ap[op_off + a, op_off + b] += f(Ao[a][b])
            for b in range(len(A)):
                Ap[op_off + a, r + b] += f(Bo[a][0]) * f(C[0][b])
    Phi, Gam = zoh(Ap, Bp, f(T))
    # the wall and the coupling
    if c["wall_form"] == "tf":
        nz = [j for j in range(N) if c["Bw"][j] != 0]
        AE = zeros(len(nz), len(nz))
        BE = [[Q(int(j == i)) for j in range(N)] for i in nz]
        CE = [[(-c["Bw"][i] / T) if i == j else Q(0) for j in nz] for i in range(N)]
        DE = [[(c["K"][i] + c["Bw"][i] / T) if i == j else -c["Kc"] for j in range(N)] for i in range(N)]
    else:
        AE, BE, CE, DE = c["wall"]
    if c["coupling_recipe"] is not None:
        AV, BV, CV, DV = c["coupling"]
    else:
        AV, BV, CV, DV = [], [], [[] for _ in range(N)], zeros(N, N)
    ne, nv = len(AE), len(AV)
    NT = npl + ne + nv
    DEm, DVm = mpm(DE, N, N), mpm(DV, N, N)
    # u = -(I + D_E D_V)^-1 (C_E xi + D_E (Cx s + C_V eta));  x_e = Cx s + C_V eta + D_V u
    W = mp.inverse(mp.eye(N) + DEm * DVm)
    Y = mp.zeros(N, NT)  # C_E xi + D_E (Cx s + C_V eta) as rows over X
    XE0 = mp.zeros(N, NT)  # Cx s + C_V eta
    for i in range(N):
        for j in range(npl):
            XE0[i, j] = Cx[i, j]
        for j in range(nv):
            XE0[i, npl + ne + j] = f(CV[i][j])
    DX = DEm * XE0
    for i in range(N):
        for j in range(NT):
            Y[i, j] = DX[i, j]
        for j in range(ne):
            Y[i, npl + j] += f(CE[i][j])
    U = -(W * Y)
    XE = XE0 + DVm * U
    M = mp.zeros(NT, NT)
    GU = Gam * U
    for i in range(npl):
        for j in range(npl):
            M[i, j] = Phi[i, j]
        for j in range(NT):
            M[i, j] += GU[i, j]
    for i in range(ne):
        for j in range(ne):
            M[npl + i, npl + j] += f(AE[i][j])
        for j in range(NT):
            M[npl + i, j] += mp.fsum(f(BE[i][k]) * XE[k, j] for k in range(N))
    for i in range(nv):
        for j in range(nv):
            M[npl + ne + i, npl + ne + j] += f(AV[i][j])
        for j in range(NT):
            M[npl + ne + i, j] += mp.fsum(f(BV[i][k]) * U[k, j] for k in range(N))
    return M


def growth(M, rest):
    """'growth' / 'settles' / 'unclear' from X_n, X_2n, X_4n (n a power of two >= 2048 with rest^n < 1e-20)."""
    n, k = 2048, 11
    if rest > 0:
        while rest ** n > mp.mpf(10) ** -20 and k < 30:
            n, k = 2 * n, k + 1
    P = M
    for _ in range(k):
        P = P * P
    X0 = mp.matrix([mp.mpf(1) / (i + 2) + (i % 3) for i in range(M.rows)])
    X1 = P * X0
    X2 = P * X1
    X4 = P * (P * X2)
    d1, d2 = mp.norm(X2 - X1), mp.norm(X4 - X2)
    ref = mp.norm(X0)
    if d2 < mp.mpf(10) ** -12 * ref:
        return "settles", n, d1, d2
    if min(d1, d2) > mp.mpf(10) ** -6 * ref:  # the rest has decayed: what is left is polynomial in n
        return "growth", n, d1, d2
    return "unclear", n, d1, d2


STATS = dict(in_cluster=mp.mpf(0), out_cluster=mp.inf, sv_zero=mp.mpf(0), sv_nonzero=mp.inf)


def reference(c):
    """(verdict, class, details, consistent) from M's eigenvalues, the geometric multiplicity at 1 and the simulation;
    at 50 digits, or 60 and 80 where mpmath's QR does not converge (the same thresholds hold there)."""
    for dps in (DPS, 60, 80):
        try:
            with mp.workdps(dps):
                return reference_at(c)
        except RuntimeError:
            continue
    return "reference undecided", "mpmath's eig or svd does not converge", None, True


def reference_at(c):
    M = loop_matrix(c)
    ev = mp.eig(M, left=False, right=False)
    d1 = [abs(mu - 1) for mu in ev]
    near = [mu for mu, d in zip(ev, d1) if d < mp.mpf(CLUSTER)]
    rest = [mu for mu, d in zip(ev, d1) if d >= mp.mpf(CLUSTER)]
    for d in d1:
        if d < mp.mpf(CLUSTER):
            STATS["in_cluster"] = max(STATS["in_cluster"], d)
        else:
            STATS["out_cluster"] = min(STATS["out_cluster"], d)
    a, g = len(near), 0
    sv = []
    if a:
        S = mp.svd_r(M - mp.eye(M.rows), compute_uv=False)
        sv = sorted(S[i] for i in range(S.rows))
        g = sum(1 for x in sv if x < mp.mpf(SV_ZERO))
        if g:
            STATS["sv_zero"] = max(STATS["sv_zero"], sv[g - 1])
        if g < len(sv):
            STATS["sv_nonzero"] = min(STATS["sv_nonzero"], sv[g])
    rho_rest = max([abs(mu) for mu in rest], default=mp.mpf(0))
    out = [mu for mu in rest if abs(mu) > 1 + mp.mpf(OUTSIDE)]
    circ = [mu for mu in rest if abs(mu) >= 1 - mp.mpf(ON_CIRCLE)]
    if a > g:
        verdict, cls = "NOT stable", "Jordan block at 1"
    elif out:
        verdict, cls = "NOT stable", "|mu| > 1"
    elif circ:
        verdict, cls = "NOT stable", "on the circle off 1"
    else:
        verdict, cls = "stable", ("semisimple 1 (x%d)" % a) if a else "no eigenvalue at 1"
    sim = None
    if a and rho_rest < 1 - mp.mpf(10) ** -6:
        sim = growth(M, rho_rest)
    det = dict(a=a, g=g, rho_rest=rho_rest, states=M.rows, sim=sim, dps=mp.mp.dps,
               near=[mp.nstr(mu, 8) for mu in near],
               sv=[mp.nstr(x, 3) for x in sv[:max(g + 1, a)]],
               big=[mp.nstr(mu, 10) for mu in rest if abs(mu) >= 1 - mp.mpf(ON_CIRCLE)][:6])
    consistent = True
    if sim is not None:
        consistent = (sim[0] == "growth") == (a > g) and sim[0] != "unclear"
    return verdict, cls, det, consistent


def ref_text(verdict, cls, det):
    if det is None:
        return "%s (%s)" % (verdict, cls)
    t = "%s (%s; %d states, %d digits; a = %d, g = %d at z = 1" % (verdict, cls, det["states"], det["dps"], det["a"], det["g"])
    if det["a"]:
        t += ", eigenvalues there %s, singular values of M - I %s" % (det["near"], det["sv"])
    t += "; rest |mu| <= %s" % mp.nstr(det["rho_rest"], 10)
    if det["big"]:
        t += ", on or outside the circle: %s" % det["big"]
    if det["sim"]:
        kind, n, d1, d2 = det["sim"]
        t += "; simulated: %s (|X_2n - X_n| = %s, |X_4n - X_2n| = %s, n = %d, |X_0| = %s)" % (
            kind, mp.nstr(d1, 4), mp.nstr(d2, 4), n, mp.nstr(mp.norm(mp.matrix([mp.mpf(1) / (i + 2) + (i % 3) for i in range(
                det["states"])])), 4))
    return t + ")"


# ---------------------------------------------------------------------------------------------
# the campaign


def marginal_tag(c):
    """What the draw put at z = 1 / s = 0 by construction: chains inside a block, or injectors / integrators."""
    chains = {"constant into a visible integrator", "visible integrator into an unseen sum", "hidden Jordan pair (unreached)",
              "hidden Jordan pair (unseen)"}
    labels = list(c["wall_parts"]) + list(c.get("coupling_parts") or [])
    kinds = [d["kind"] for d in c["devices"]]
    if any(lab in chains for lab in labels) or any(k in ("ss own position + gravity", "ss hidden ramp") for k in kinds):
        return "chain inside a block's A"
    inj = "injector" in labels or c["operator"]["kind"] in ("m, b, k spring", "ss hidden constant", "ss spring") or any(
        k in ("ss gravity", "ss velocity offset", "ss spring", "ss spring + force sum") for k in kinds)
    integ = "integrator" in labels or any(k in ("ss force sum", "ss spring + force sum") for k in kinds)
    return {(False, False): "none", (True, False): "injectors only", (False, True): "integrators only",
            (True, True): "injectors and integrators"}[(inj, integ)]


def tags(c):
    t = {"DOFs": str(c["N"]), "operator": c["operator"]["kind"], "wall": "+".join(c["wall_recipe"]) or "ss plain",
         "coupling": "none" if c["coupling_recipe"] is None else ("+".join(c["coupling_recipe"]) or "compliance"),
         "at z = 1 (drawn)": marginal_tag(c)}
    for d in c["devices"]:
        t["device " + d["kind"]] = d.get("pair", "yes")
    for lab in c["wall_parts"]:
        t["wall part " + lab] = "yes"
    for lab in c.get("coupling_parts") or []:
        t["coupling part " + lab] = "yes"
    return t


def run(exe, args, cmd=None):
    """The completed process, or None after 300 s (a binary that cannot run raises: run campaigns on a copy of it)."""
    try:
        return subprocess.run((cmd or [exe]) + args, capture_output=True, text=True, timeout=300)
    except subprocess.TimeoutExpired:
        return None


def check_certificate(exe, cert):
    """(verified by both?, which refutes)."""
    for cmd in ([exe, "check"], ["/usr/bin/python3", os.path.join(TOP, "checks", "hapstab_check.py")]):
        p = run(exe, [cert], cmd)
        if p is None or p.returncode != 0:
            return False, "%s %s: %s" % (os.path.basename(cmd[-1]), "exit %d" % p.returncode if p else "timeout",
                                          (p.stdout + p.stderr).strip()[:200] if p else "")
    return True, ""


def summary(counts, per_tag, refcls, times, done, final):
    head = "==" if final else "-- progress"
    n = len(times)
    print("%s indep_jordan_at_one: %d cases, %.1f s (%.2f s per case, slowest %.2f s)" % (
        head, n, sum(times), sum(times) / max(1, n), max(times, default=0)))
    print("   outcomes: " + ", ".join("%s %d" % kv for kv in sorted(counts.items())))
    print("   reference: " + ", ".join("%s %d" % kv for kv in sorted(refcls.items())))
    with mp.workdps(10):
        print("   thresholds: |mu - 1| in the cluster <= %s, outside >= %s (cut %s); singular values of M - I counted 0 <= %s,"
              " others >= %s (cut %s)" % (mp.nstr(STATS["in_cluster"], 3), mp.nstr(STATS["out_cluster"], 3), CLUSTER,
                                          mp.nstr(STATS["sv_zero"], 3), mp.nstr(STATS["sv_nonzero"], 3), SV_ZERO))
    print("   per branch: agree / undecided / refused / DISAGREE   (certificates: verified / refused)")
    for (tag, val), cnt in sorted(per_tag.items()):
        print("     %-28s %-40s %3d / %3d / %3d / %3d   (%d / %d)" % (
            tag, val, cnt["agree"], cnt["undecided"], cnt["refused"], cnt["DISAGREE"], cnt["cert verified"],
            cnt["cert refused"]))
    if final:
        want = [("DOFs", "2"), ("coupling", "none")] + [("device " + k, None) for k in set(DEVICES)] + \
               [("operator", k) for k in set(OPERATORS)] + [("wall", "+".join(r)) for r in WALL_RECIPES if r] + \
               [("wall", "tf"), ("wall", "ss plain")] + [("coupling", "+".join(r) or "compliance") for r in COUPLING_RECIPES] + \
               [("at z = 1 (drawn)", v) for v in ("none", "injectors only", "integrators only", "injectors and integrators",
                                                  "chain inside a block's A")]
        miss = [f"{t} = {v}" for t, v in want if not any(t == a and v in (None, b) for a, b in per_tag)]
        print("   branches not hit: " + (", ".join(miss) if miss else "none"))
    sys.stdout.flush()


def main(argv):
    exe = argv[1]
    cases, seed = cases_and_seed(argv, cases=40)
    first = int(argv[argv.index("--first") + 1]) if "--first" in argv else 0
    progress = int(argv[argv.index("--progress") + 1]) if "--progress" in argv else 0
    keep = argv[argv.index("--keep") + 1] if "--keep" in argv else None
    if keep:
        os.makedirs(keep, exist_ok=True)
    counts, refcls, times = {}, {}, []
    per_tag = {}
    bad = 0
    with tempfile.TemporaryDirectory(prefix="hapstab-jordan-") as tmp:
        sc, cert = os.path.join(tmp, "s.toml"), os.path.join(tmp, "c.json")
        for k in range(first, first + cases):
            t0 = time.monotonic()
            c = draw(random.Random("jordan:%d:%d" % (seed, k)), k)
            text = scene(c)
            with open(sc, "w") as fh:
                fh.write(text)
            if os.path.exists(cert):
                os.remove(cert)
            verdict, cls, det, consistent = reference(c)
            refcls[cls] = refcls.get(cls, 0) + 1
            r = run(exe, ["stability", "--scene", sc])
            rc = r.returncode if r else "timeout"
            got = {0: "stable", 1: "NOT stable"}.get(rc)
            out = (r.stdout + r.stderr).strip() if r else "no answer within 300 s"
            certnote, outcome = "", None
            if not consistent:
                outcome = "REFERENCE INCONSISTENT"
            elif det is None:
                outcome = "reference undecided"
            elif rc == 3:
                outcome = "undecided"
            elif got is None:
                outcome = "refused"
            elif got != verdict:
                outcome = "DISAGREE"
            else:
                outcome = "agree"
            cert_state = None
            if got is not None and det is not None:
                p = run(exe, ["stability", "--scene", sc, "--certificate", cert])
                if p is not None and p.returncode in (0, 1) and os.path.exists(cert):
                    ok, why = check_certificate(exe, cert)
                    claim = json.load(open(cert))["claim"].get("stable")
                    claimed = "stable" if claim else "NOT stable"
                    if ok and claimed != verdict:
                        outcome, certnote = "DISAGREE", "; a certificate both checkers verify claims %s" % claimed
                    elif not ok:
                        outcome, certnote = "DISAGREE", "; hapstab's certificate is not verified: " + why
                    else:
                        cert_state, certnote = "cert verified", "; certificate verified by both (%s)" % json.load(open(cert))["kind"]
                elif p is not None and p.returncode in (2, 3) and not os.path.exists(cert):
                    cert_state, certnote = "cert refused", "; certificate refused (exit %d): %s" % (
                        p.returncode, p.stderr.strip()[:120])
                else:
                    outcome, certnote = "DISAGREE", "; --certificate exit %s without a certificate" % (
                        p.returncode if p else "timeout")
            counts[outcome] = counts.get(outcome, 0) + 1
            if outcome in ("undecided", "refused"):
                key = "%s, reference %s" % (outcome, cls)
                counts[key] = counts.get(key, 0) + 1
            for tv in tags(c).items():
                cnt = per_tag.setdefault(tv, dict(agree=0, undecided=0, refused=0, DISAGREE=0, **{
                    "REFERENCE INCONSISTENT": 0, "reference undecided": 0, "cert verified": 0, "cert refused": 0}))
                cnt[outcome] += 1
                if cert_state:
                    cnt[cert_state] += 1
            times.append(time.monotonic() - t0)
            what = "case %d: %d DOF, devices %s, operator %s, wall %s, coupling %s" % (
                k, c["N"], "/".join(d["kind"] for d in c["devices"]), c["operator"]["kind"], "+".join(c["wall_parts"]) or
                c["wall_form"], "none" if c["coupling_recipe"] is None else ("+".join(c["coupling_parts"]) or "compliance"))
            first_line = out.splitlines()[0] if out else ""
            if outcome in ("DISAGREE", "REFERENCE INCONSISTENT"):
                bad += 1
                print("%s %s" % (outcome, what))
                print("  hapstab (exit %s): %s%s" % (rc, out[:1500].replace("\n", "\n    "), certnote))
                print("  reference: " + ref_text(verdict, cls, det))
                print("  scene:\n    " + text.replace("\n", "\n    "))
                print("  rerun: %s %s --seed %d --first %d --cases 1" % (sys.argv[0], exe, seed, k))
                if keep:
                    with open(os.path.join(keep, "seed%d_case%d.toml" % (seed, k)), "w") as fh:
                        fh.write("# indep_jordan_at_one seed %d case %d: hapstab %s (exit %s), reference %s\n" % (
                            seed, k, got, rc, ref_text(verdict, cls, det)) + text)
            else:
                print("%-9s %s: hapstab %s; reference %s (%s)%s" % (
                    "ok" if outcome == "agree" else outcome, what, first_line[:90] if outcome != "agree" else got, verdict,
                    cls, certnote[:100]))
            sys.stdout.flush()
            if progress and (k - first + 1) % progress == 0 and k + 1 < first + cases:
                summary(counts, per_tag, refcls, times, k - first + 1, False)
    summary(counts, per_tag, refcls, times, cases, True)
    return 1 if bad else 0


if __name__ == "__main__":
    if len(sys.argv) < 2 or not os.access(sys.argv[1], os.X_OK):
        print(__doc__)
        sys.exit(2)
    sys.exit(main(sys.argv))
