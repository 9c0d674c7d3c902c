"""The independent reference of the `coupling_witness` criterion (tests/verify/independent.py):
paper 000's Theorem 4 for the scene's OWN coupling V, decided in the frequency domain from the
scene file as written, and the exact two-frequency witness hapstab prints when it proves the
program infeasible (`multidof analyze --json`: loop_as_written.theorem4_witness).

Nothing here comes from hapstab. The scene is read with tomllib (indep_witness.Scene: E entry by
entry, the device levels Delta_D); the coupling's transfer-function matrix [coupling] tf is read the
same way and evaluated in mpmath at points of the unit circle. K = (T/2) Delta_D^{-1} (12),
V-hat = (z - 1)/(T z) (V - K) and E-hat = T z/(z - 1) E (11). No realisation of anything.

Theorem 4's conditions in the frequency domain (derived here from the paper's definitions). With
X = Gamma^2 (Gamma in G), a point of the program has, at z1, z2 on the unit circle (not poles):
  (i)   the first LMI of (16) at [x; w], x = (z1 I - A)^-1 B w (its P terms cancel as |z1| = 1):
        w^* Q_E w > -Re(w^* X E-hat(z1) w) for w != 0;
  (ii)  Lemma 1 for V-hat^Gamma at [x; u]: q^* Q_V q <= Re(u^* X q), q = V-hat(z2) u;
  (iii) (14) scaled by Gamma: p^* Delta_D X p + q^* Q_V q - (p + q)^* Q_E (p + q) > 0 for [p; q] != 0;
  (iv)  Q_V > 0 (Delta_V-hat > 0 in (14)).
(i) + (ii) + (iii) at w = p + q: phi(X) = p^* Delta_D X p + Re(u^* X q) + Re(w^* X E-hat(z1) w) > 0 --
what a witness claims violated for every admissible X. The admissible X: X in G (one g_i per
operator; here one operator per device) with X E(1) and X (V(1) - K) symmetric -- E-hat's pole at
z = 1 and V-hat's zero there force it. For the scenes drawn here E(1) and V(1) - K are symmetric
and the DOFs they couple form components that E(z) and V(z) do not couple across: X = g_c I on
each component c, the program splits into one program per component with X = I (homogeneous), and
it is infeasible iff one component's is.

Per component, with q = V-hat(z2) u (V-hat invertible off z2 = 1), Re(u^* q) = q^* S(z2) q,
S = He(V-hat^{-1}), and A(z1) = He(E-hat(z1)):
  phi = [p; q]^* M [p; q],  M(z1, z2) = [[Delta + A, A], [A, S + A]].
  mu    = min over (theta1, theta2) of lambda_min(M)  -- < 0: a two-frequency witness exists;
  sigma = min over theta2 of lambda_min(S)            -- <= 0: (ii) and (iv) cannot both hold.
For one DOF, M is monotone in A and in S (d M/d A = [1 1; 1 1] >= 0, d M/d S = e2 e2^T), so
mu = lambda_min(M(min A, min S)), and the program is feasible iff sigma > 0 and mu > 0 (Q_E = r
just above -min A, Q_V = s just below min S): the reference then decides every verdict. With
several DOF per component, mu < 0 or sigma < 0 proves infeasibility, and otherwise the
reference does not decide (the rank-one two-frequency form is only sufficient): a certified
"infeasible" there is counted apart ("reference cannot decide"), never as agreement.

Sweeps: theta over 8192 (one DOF: 32768) frequencies in double (numpy), the best local minima
refined at 40 digits (golden section; two DOF and more: the 3 least local minima of a 192 x 768
grid of (theta1, theta2) pairs, coordinate-wise, two rounds), theta = pi and the limit theta -> 0
(1e-18 at 60 digits) always.
"""
import math
import re
import sys
import tomllib
from fractions import Fraction as Q

import mpmath as mp
import numpy as np

import indep_witness as IW
from indep_common import Expr, analyze_case_main, golden, local_extrema, witness_decides

DPS = 40


class CScene(IW.Scene):
    """The witness campaign's scene plus its [coupling] V(z) (tf, in z or backward-Euler s)."""

    def __init__(self, text):
        super().__init__(text)
        d = tomllib.loads(text)
        cp = d["coupling"]
        if "tf" not in cp:
            raise ValueError("the reference reads [coupling] tf only")
        tf = cp["tf"]
        rows = [[tf]] if isinstance(tf, str) else tf
        if len(rows) != self.m or any(len(r) != self.m for r in rows):
            raise ValueError("[coupling] is not m x m")
        self.vdomain = cp.get("domain", "z")
        if self.vdomain == "s" and cp.get("method") != "backward_euler":
            raise ValueError("the reference reads a coupling in s with backward_euler only")
        self.vvar = "s" if self.vdomain == "s" else "z"
        self.V = [[Expr(e, self.params) for e in r] for r in rows]
        if self.n:
            raise ValueError("Theorem 4 with the scene's coupling is not run with a [delay]")

    def _tmp(self):
        return mp.mpf(self.T.numerator) / self.T.denominator

    def vhat_mp(self, z):
        """V-hat(z) = (z - 1)/(T z) (V(z) - K), K = T/(2 delta_i) on the diagonal."""
        T = self._tmp()
        s = (z - 1) / (T * z) if self.vvar == "s" else z
        f = (z - 1) / (T * z)
        m = self.m
        return mp.matrix([[f * (self.V[i][j].mp(self.vvar, s) - (T / 2 / mp_q(self.delta[i]) if i == j else 0))
                           for j in range(m)] for i in range(m)])

    def v_at_one(self):
        with mp.workdps(DPS):
            v = mp.mpf(0) if self.vvar == "s" else mp.mpf(1)
            T = self._tmp()
            return mp.matrix([[self.V[i][j].mp(self.vvar, v) - (T / 2 / mp_q(self.delta[i]) if i == j else 0)
                               for j in range(self.m)] for i in range(self.m)])

    def vhat_np(self, z):
        T = float(self.T)
        s = (z - 1) / (T * z) if self.vvar == "s" else z
        f = (z - 1) / (T * z)
        out = np.empty((len(z), self.m, self.m), dtype=complex)
        for i, r in enumerate(self.V):
            for j, e in enumerate(r):
                k = T / 2 / float(self.delta[i]) if i == j else 0.0
                out[:, i, j] = f * (np.broadcast_to(e.np(self.vvar, s), z.shape) - k)
        return out


def mp_q(q):
    return mp.mpf(q.numerator) / q.denominator


def _circle(t):
    return mp.expjpi(t / mp.pi) if t != mp.pi else mp.mpc(-1, 0)


def components(sc):
    """The DOFs' components (X = g_c I on each), or (None, why) when the reference declines."""
    E1, V1 = sc.e1(), sc.v_at_one()
    m = sc.m
    with mp.workdps(DPS):
        tol = mp.mpf(10) ** -30 * (1 + max(abs(x) for x in list(E1) + list(V1)))
        for i in range(m):
            for j in range(m):
                if abs(E1[i, j] - E1[j, i]) > tol or abs(V1[i, j] - V1[j, i]) > tol:
                    return None, "E(1) or V(1) - K is not symmetric"
        parent = list(range(m))

        def find(a):
            while parent[a] != a:
                a = parent[a]
            return a
        for i in range(m):
            for j in range(m):
                if i != j and (abs(E1[i, j]) > tol or abs(V1[i, j]) > tol):
                    parent[find(i)] = find(j)
        comps = {}
        for i in range(m):
            comps.setdefault(find(i), []).append(i)
        comps = sorted(comps.values())
        z = mp.mpc("0.3", "0.7")
        Eh, Vh = sc.ehat_mp(z), sc.vhat_mp(z)
        where = {i: k for k, c in enumerate(comps) for i in c}
        for i in range(m):
            for j in range(m):
                if where[i] != where[j] and (abs(Eh[i, j]) > tol or abs(Vh[i, j]) > tol):
                    return None, f"E or V couples DOFs {i} and {j} but E(1), V(1) - K do not (X not pinned)"
    return comps, ""


class Part:
    """One component: A(theta) = He E-hat, S(theta) = He V-hat^-1, Delta, at any precision."""

    def __init__(self, sc, dofs):
        self.sc, self.d, self.k = sc, dofs, len(dofs)

    def _sub(self, M):
        return mp.matrix([[M[i, j] for j in self.d] for i in self.d])

    def A(self, t):
        Eh = self._sub(self.sc.ehat_mp(_circle(t)))
        return (Eh + Eh.H) / 2

    def S(self, t):
        Vi = mp.inverse(self._sub(self.sc.vhat_mp(_circle(t))))
        return (Vi + Vi.H) / 2

    def M(self, A, S):
        k = self.k
        M = mp.matrix(2 * k, 2 * k)
        for i in range(k):
            for j in range(k):
                a = A[i, j]
                M[i, j] = a + (mp_q(self.sc.delta[self.d[i]]) if i == j else 0)
                M[i, k + j] = M[k + i, j] = a
                M[k + i, k + j] = S[i, j] + a
        return M

    def A_np(self, th):
        Eh = self.sc.ehat_np(np.exp(1j * th))[:, self.d][:, :, self.d]
        return (Eh + np.conj(np.transpose(Eh, (0, 2, 1)))) / 2

    def S_np(self, th):
        Vi = np.linalg.inv(self.sc.vhat_np(np.exp(1j * th))[:, self.d][:, :, self.d])
        return (Vi + np.conj(np.transpose(Vi, (0, 2, 1)))) / 2

    def M_np(self, A, S, kappa=1.0):
        """M for every pair: A (n1 x k x k), S (n2 x k x k) -> (n1 x n2 x 2k x 2k)."""
        k = self.k
        n1, n2 = len(A), len(S)
        D = np.diag([float(self.sc.delta[i]) for i in self.d])
        M = np.zeros((n1, n2, 2 * k, 2 * k), dtype=complex)
        a = kappa * A[:, None, :, :]
        M[:, :, :k, :k] = a + D
        M[:, :, :k, k:] = a
        M[:, :, k:, :k] = a
        M[:, :, k:, k:] = a + S[None, :, :, :]
        return M


def lmin(H):
    if H.rows == 1:
        return mp.re(H[0, 0])
    return min(mp.re(x) for x in mp.eigh(H, eigvals_only=True))


def min_1d(f_np, f_mp, K):
    """min over theta in (0, pi] of f (a matrix's least eigenvalue): dict(v, theta, where)."""
    th = np.pi * np.arange(1, K + 1) / K
    with np.errstate(all="ignore"):
        v = np.linalg.eigvalsh(f_np(th))[:, 0]
    v = np.where(np.isfinite(v) & (th > 1e-4), v, np.inf)  # near 0: cancellation noise; the limit below
    with mp.workdps(DPS):
        f = lambda t: lmin(f_mp(t))
        cands = [(mp.pi, f(mp.pi))]
        with mp.workdps(60):
            cands.append((mp.mpf(10) ** -18, lmin(f_mp(mp.mpf(10) ** -18))))
        for i in local_extrema(v):
            a = mp.mpf(th[i - 1]) if i else mp.mpf(th[i]) / 10
            b = mp.mpf(th[i + 1]) if i + 1 < len(th) else mp.pi
            cands.append(golden(f, a, b))
        t, val = min(cands, key=lambda c: c[1])
    return dict(v=val, theta=t, where=where_of(t))


def where_of(t):
    t = abs(t)
    return "theta = pi" if abs(t - mp.pi) < 1e-9 else ("theta -> 0" if t < 1e-6 else "interior")


def part_mu_1dof(P):
    """One DOF: mu = lambda_min(M(min A, min S)), sigma = min S (monotonicity, module docstring)."""
    a = min_1d(lambda th: P.A_np(th), P.A, 32768)
    s = min_1d(lambda th: P.S_np(th), P.S, 32768)
    with mp.workdps(DPS):
        mu = lmin(P.M(mp.matrix([[a["v"]]]), mp.matrix([[s["v"]]])))
    return dict(mu=mu, sigma=s["v"], where1=a["where"], where2=s["where"])


def grid2(K1=256, K2=512):
    t1 = np.pi * np.arange(1, K1 + 1) / K1
    t2 = np.pi * np.arange(-K2 + 1, K2 + 1) / K2
    t2 = t2[np.abs(t2) > 1e-12]
    return t1, t2


def part_mu_2d(P, kappa=1.0, K1=192, K2=384):
    """lambda_min(M) over a (theta1, theta2) grid in double: (values n1 x n2, t1, t2)."""
    t1, t2 = grid2(K1, K2)
    with np.errstate(all="ignore"):
        A, S = P.A_np(t1), P.S_np(t2)
        v = np.linalg.eigvalsh(P.M_np(A, S, kappa))[:, :, 0]
    return np.where(np.isfinite(v), v, np.inf), t1, t2


def part_mu_mdof(P):
    """Several DOF: mu over (theta1, theta2) -- the double grid, its 3 least local minima refined
    at 40 digits coordinate-wise, the rows theta1 = pi, theta1 -> 0 and columns theta2 = pi,
    theta2 -> 0 taken at 40/60 digits on the grid's other coordinate's best."""
    v, t1, t2 = part_mu_2d(P)
    s = min_1d(lambda th: P.S_np(th), P.S, 8192)
    n1, n2 = v.shape
    pad = np.pad(v, 1, constant_values=np.inf)
    is_min = np.ones_like(v, dtype=bool)
    for a in (0, 1, 2):
        for b in (0, 1, 2):
            is_min &= v <= pad[a:a + n1, b:b + n2]
    loc = sorted((v[i, j], i, j) for i, j in zip(*np.nonzero(is_min & np.isfinite(v))))
    with mp.workdps(DPS):
        cacheA, cacheS = {}, {}

        def f(a, b):
            if a not in cacheA:
                cacheA[a] = P.A(a)
            if b not in cacheS:
                cacheS[b] = P.S(b)
            return lmin(P.M(cacheA[a], cacheS[b]))
        best = None
        for _, i, j in loc[:3]:
            a, b = mp.mpf(t1[i]), mp.mpf(t2[j])
            h1, h2 = mp.pi / n1, mp.pi / (n2 // 2)
            for _round in range(2):
                a, _ = golden(lambda x: f(x, b), max(a - h1, mp.mpf(10) ** -12), min(a + h1, mp.pi), 20)
                b, val = golden(lambda y: f(a, y), b - h2, min(b + h2, mp.pi), 20)
                h1, h2 = h1 / 8, h2 / 8
            if best is None or val < best[2]:
                best = (a, b, val)
        a, b, _ = best
        ends = [(mp.pi, b), (a, mp.pi)]
        for a2, b2 in ends:
            val = f(a2, b2)
            if val < best[2]:
                best = (a2, b2, val)
        with mp.workdps(60):
            e = mp.mpf(10) ** -18
            for a2, b2 in ((e, best[1]), (best[0], e), (best[0], -e)):
                val = lmin(P.M(P.A(a2), P.S(b2)))
                if val < best[2]:
                    best = (a2, b2, val)
    return dict(mu=best[2], sigma=s["v"], where1=where_of(best[0]), where2=where_of(best[1]))


def reference(sc):
    """dict(comps, parts: [dict(mu, sigma, ...)], scale) or dict(declined=why)."""
    comps, why = components(sc)
    if comps is None:
        return dict(declined=why)
    parts = []
    for c in comps:
        P = Part(sc, c)
        r = part_mu_1dof(P) if len(c) == 1 else part_mu_mdof(P)
        r["dofs"] = c
        parts.append(r)
    scale = 1 + max(abs(mp_q(d)) for d in sc.delta)
    return dict(comps=comps, parts=parts, scale=scale)


def classify(ref):
    """'holds' (feasible: one-DOF components only), 'violated (witness)', 'violated (V-hat not OSP)',
    'no witness' (several DOF: not decided), 'undecided' (within the tolerance)."""
    tol = mp.mpf(10) ** -25 * ref["scale"]
    if any(p["mu"] < -tol for p in ref["parts"]):
        return "violated (witness)"
    if any(p["sigma"] < -tol for p in ref["parts"]):
        return "violated (V-hat not OSP)"
    if any(abs(p["mu"]) <= tol or abs(p["sigma"]) <= tol for p in ref["parts"]):
        return "undecided"
    return "holds" if all(len(p["dofs"]) == 1 for p in ref["parts"]) else "no witness"


# ---------------------------------------------------------------------------------------------
# hapstab's witness, re-evaluated


class GQ:
    """An exact complex rational a + b j (Fractions): the witness's direction V-hat(z2) u exactly."""

    def __init__(self, a, b=0):
        self.a, self.b = Q(a), Q(b)

    def _o(self, o):
        return o if isinstance(o, GQ) else GQ(o)

    def __add__(self, o):
        o = self._o(o)
        return GQ(self.a + o.a, self.b + o.b)
    __radd__ = __add__

    def __sub__(self, o):
        o = self._o(o)
        return GQ(self.a - o.a, self.b - o.b)

    def __rsub__(self, o):
        return self._o(o) - self

    def __mul__(self, o):
        o = self._o(o)
        return GQ(self.a * o.a - self.b * o.b, self.a * o.b + self.b * o.a)
    __rmul__ = __mul__

    def __truediv__(self, o):
        o = self._o(o)
        n = o.a * o.a + o.b * o.b
        if n == 0:
            raise ZeroDivisionError("a pole at the witness's point")
        return self * GQ(o.a / n, -o.b / n)

    def __rtruediv__(self, o):
        return self._o(o) / self

    def __neg__(self):
        return GQ(-self.a, -self.b)

    def __pos__(self):
        return self

    def __pow__(self, k):
        if not isinstance(k, (int, GQ)):
            raise ValueError("power")
        if isinstance(k, GQ):
            if k.b != 0 or k.a.denominator != 1:
                raise ValueError("non-integer power")
            k = int(k.a)
        r = GQ(1)
        b = self if k >= 0 else GQ(1) / self
        for _ in range(abs(k)):
            r = r * b
        return r

    def iszero(self):
        return self.a == 0 and self.b == 0


def vhat_exact(sc, z, u):
    """V-hat(z) u exactly (Fractions; z = GQ on the circle)."""
    T = sc.T
    s = (z - 1) / (z * T) if sc.vvar == "s" else z
    f = (z - 1) / (z * T)
    out = []
    for i in range(sc.m):
        acc = GQ(0)
        for j in range(sc.m):
            v = eval(sc.V[i][j].code, {"__builtins__": {}}, sc.V[i][j]._env(lambda q: GQ(q), sc.vvar, s))
            if i == j:
                v = v - T / (2 * sc.delta[i])
            acc = acc + f * v * u[j]
        out.append(acc)
    return out


def check_witness(sc, ref, w):
    """hapstab's printed theorem4_witness against the scene: (None or the failure, phi values at 50
    digits per reference component, |terms|). 'boundary' when a phi is 0 to 40 digits."""
    z1 = (Q(w["z1"][0]), Q(w["z1"][1]))
    z2 = (Q(w["z2"][0]), Q(w["z2"][1]))
    for name, (a, b) in (("z1", z1), ("z2", z2)):
        if a * a + b * b != 1:
            return f"{name} = {a} + {b} j is not on the unit circle exactly", None
    if z1 == (1, 0):
        return "z1 = 1 is the pole of E-hat", None
    if z2 == (1, 0):
        return "z2 = 1: V-hat(1) = 0, every term vanishes", None
    p = [GQ(a, b) for a, b in zip(w["p"]["re"], w["p"]["im"])]
    u = [GQ(a, b) for a, b in zip(w["u"]["re"], w["u"]["im"])]
    if len(p) != sc.m or len(u) != sc.m:
        return "p or u does not have one entry per DOF", None
    try:
        q = vhat_exact(sc, GQ(*z2), u)
    except ZeroDivisionError:
        return "z2 is a pole of V", None
    if all(x.iszero() for x in p) and all(x.iszero() for x in q):
        return "the direction [p; V-hat(z2) u] is 0 exactly: it proves nothing", None
    with mp.workdps(50):
        c = lambda g: mp.mpc(mp_q(g.a), mp_q(g.b))
        pm, um, qm = [c(x) for x in p], [c(x) for x in u], [c(x) for x in q]
        Eh = sc.ehat_mp(mp.mpc(mp_q(z1[0]), mp_q(z1[1])))
        wm = [pm[i] + qm[i] for i in range(sc.m)]
        e = [mp.fsum(Eh[i, j] * wm[j] for j in range(sc.m)) for i in range(sc.m)]
        vals = []
        for comp in ref["comps"]:  # X_c = the indicator of the component: every admissible X is sum g_c X_c
            t1 = mp.fsum(mp_q(sc.delta[i]) * abs(pm[i]) ** 2 for i in comp)
            t2 = mp.re(mp.fsum(mp.conj(um[i]) * qm[i] for i in comp))
            t3 = mp.re(mp.fsum(mp.conj(wm[i]) * e[i] for i in comp))
            vals.append((t1 + t2 + t3, abs(t1) + abs(t2) + abs(t3)))
    for phi, size in vals:
        if phi > mp.mpf(10) ** -40 * size:
            return f"phi = {mp.nstr(phi, 30)} > 0 on a component at hapstab's witness", vals
    if all(abs(phi) <= mp.mpf(10) ** -40 * size for phi, size in vals):
        return "boundary", vals
    return None, vals


# ---------------------------------------------------------------------------------------------
# the scenes drawn: indep_witness's environments (no delay) with a coupling and a gain kap on E


def coupling_entry(rng, T, p, i, delta):
    """V_ii = 1/(kc + bc s), s = (z - 1)/(T z) (a spring-damper compliance: stable). kc = rho 2 delta/T,
    so that V(1) - K = (1/rho - 1) T/(2 delta) > 0 for rho < 1 (rho > 1 in a tenth: the DC condition
    fails); bc = beta (delta - kc T/2): at z = -1, Re 1/V-hat = (kc T/2 + bc)/(1 - (kc T/2 + bc)/delta)
    is positive only for beta < 1 (beta > 1 in a sixth: V-hat is not OSP there)."""
    rho = IW.rq(rng, 1.05, 2, (20, 100)) if rng.random() < 0.1 else IW.rq(rng, 0.05, 0.95, (20, 100))
    beta = IW.rq(rng, 1.02, 2, (50, 100)) if rng.random() < 0.16 else IW.rq(rng, 0.02, 0.98, (50, 100))
    p[f"kc{i}"] = rho * 2 * delta / T
    p[f"bc{i}"] = beta * delta * abs(1 - rho)
    return f"1/(kc{i} + bc{i}*(z-1)/(T*z))", rho > 1


def gen(rng):
    fam = rng.choices(["wall", "linked walls", "two parts", "contact"], weights=[45, 22, 15, 18])[0]
    T = rng.choice([Q(1, 1000), Q(1, 500), Q(1, 2000), Q(1, 100)])
    p = {}
    tf, tags = IW.draw_env(rng, "contact" if fam == "contact" else fam, T, p)
    delayed = fam != "contact" and rng.random() < 0.7
    if delayed:  # the wall's spring computed one sample late, K z^-1, written in E itself (Re E-hat < 0)
        sub = lambda e: re.sub(r"\bK(\w*) \+ B", r"K\1/z + B", e)
        tf = sub(tf) if isinstance(tf, str) else [[sub(e) for e in r] for r in tf]
    tags["spring one sample late"] = delayed
    if fam == "contact" and len(tf) > 3:  # the reference's 2-D sweep: at most 3 DOF
        tf = [r[:3] for r in tf[:3]]
    m = 1 if isinstance(tf, str) else len(tf)
    devs = [dict(kind="md", b=IW.rq(rng, 0.2, 5), m=IW.rq(rng, 0.05, 1), hb=IW.rq(rng, 0.5, 5)) for _ in range(m)]
    rows, dc_fails = [], False
    for i in range(m):
        e, f = coupling_entry(rng, T, p, i, devs[i]["b"])
        dc_fails |= f
        rows.append(e)
    cross = m > 1 and fam != "two parts" and rng.random() < 0.3
    if cross:  # a symmetric constant cross-compliance between neighbours (V(1) - K stays symmetric)
        p["cv"] = IW.rq(rng, -1, 1) * T / (4 * max(d["b"] for d in devs))
    V = [[rows[i] if i == j else ("cv" if cross and abs(i - j) == 1 else "0") for j in range(m)] for i in range(m)]
    tags.update({"family": fam, "DOF": str(m), "DC condition fails": dc_fails, "cross-coupled V": cross})
    kap_text = "kap"
    tf_k = f"{kap_text}*({tf})" if isinstance(tf, str) else [[f"{kap_text}*({e})" if e != "0" else "0" for e in r] for r in tf]
    p["kap"] = Q(1)
    sc0 = CScene(scene_text(T, p, tf_k, fam, devs, V))
    kap, dist = pick_gain(rng, sc0)
    p["kap"] = kap
    tags["gain"] = dist
    tags["near the boundary"] = dist.startswith("1e-")
    return dict(text=scene_text(T, p, tf_k, fam, devs, V), tags=tags)


def scene_text(T, p, tf, fam, devs, V):
    t = IW.scene_text(T, p, tf, fam, 0, devs)
    rows = ",\n      ".join("[" + ", ".join(f'"{e}"' for e in r) + "]" for r in V)
    return t.replace("# generated by tests/verify/independent.py (criterion witness)",
                     "# generated by tests/verify/independent.py (criterion coupling_witness)") + f"\n[coupling]\ntf = [{rows}]\n"


def boundary_gain(sc):
    """kap* where Theorem 4's frequency form first fails as E's gain grows from 0 (double; one DOF
    in closed form from the monotonicity above), or None (sigma <= 0, or no crossing up to 1e6)."""
    comps, _ = components(sc)
    if comps is None:
        return None
    best = None
    for c in comps:
        P = Part(sc, c)
        th = np.pi * np.arange(1, 8193) / 8192
        with np.errstate(all="ignore"):
            S = P.S_np(th)
            sig = np.nanmin(np.linalg.eigvalsh(S)[:, 0])
        if not sig > 0:
            return None
        if len(c) == 1:
            with np.errstate(all="ignore"):
                a = np.nanmin(P.A_np(th)[:, 0, 0].real / float(sc.params["kap"]))
                s = np.nanmin(S[:, 0, 0].real)
            d = float(sc.delta[c[0]])
            k = -d * s / (a * (d + s)) if a < 0 else math.inf
        else:
            t1, t2 = grid2(96, 192)
            with np.errstate(all="ignore"):
                A1, S2 = P.A_np(t1) / float(sc.params["kap"]), P.S_np(t2)

            def mu(kap):
                with np.errstate(all="ignore"):
                    v = np.linalg.eigvalsh(P.M_np(A1, S2, kap))[:, :, 0]
                return np.min(np.where(np.isfinite(v), v, np.inf))
            lo, hi = 0.0, 1.0
            while mu(hi) > 0 and hi < 1e6:
                lo, hi = hi, hi * 4
            if hi >= 1e6:
                continue
            for _ in range(30):
                mid = 0.5 * (lo + hi)
                lo, hi = (mid, hi) if mu(mid) > 0 else (lo, mid)
            k = hi
        best = k if best is None else min(best, k)
    return best if best is not None and math.isfinite(best) else None


def pick_gain(rng, sc0):
    k = boundary_gain(sc0)
    if k is None:
        return IW.rq(rng, 0.05, 3, (20, 100)), "no boundary in the gain"
    u = rng.random()
    if u < 0.45:
        e = rng.choice([2, 4, 6])
        sg = rng.choice([-1, 1])
        return Q(round(k * (1 + sg * 10.0 ** -e) * 10 ** 14), 10 ** 14), f"1e-{e} {'below' if sg < 0 else 'above'} the boundary"
    x = k * (rng.uniform(0.2, 0.9) if u < 0.72 else rng.uniform(1.1, 3))
    return Q(x).limit_denominator(10 ** 6) or Q(1, 10 ** 6), "far " + ("below" if x < k else "above")


# ---------------------------------------------------------------------------------------------
# hapstab's answer against the reference


def hapstab_answer(j):
    """What `multidof analyze --json` says of Theorem 4 with the scene's coupling."""
    law = j.get("loop_as_written") or {}
    why = law.get("why") or ""
    if law.get("method") == "Theorem 4 with the scene's coupling" and law.get("stable") is True:
        return "feasible"
    if "needs Assumption 1" in why:
        return "not run (Assumption 1)"
    if "certified by a frequency-domain witness" in why:
        return "infeasible (witness)"
    if "certified by an exact Farkas certificate" in why:
        return "infeasible (Farkas or facial)"
    if "Theorem 4 with the scene's coupling does not conclude" in why:
        return "not certified"
    return "not run"


def decide(c, sc, j, rc):
    tags = dict(c["tags"])
    out = dict(tags=tags, rc=rc, margin=None)
    h = hapstab_answer(j)
    tags["hapstab"] = h
    law = j.get("loop_as_written") or {}
    out["hapstab"] = f"{h}: {(law.get('why') or '')[:200]}"
    ref = reference(sc)
    if "declined" in ref:
        out.update(outcome="reference undecided", why="the reference declines: " + ref["declined"])
        return out
    cls = classify(ref)
    tags["reference"] = cls
    mus = min(p["mu"] for p in ref["parts"])
    sig = min(p["sigma"] for p in ref["parts"])
    out["margin"] = float(min(abs(mus), abs(sig)) / ref["scale"])
    worst = min(ref["parts"], key=lambda p: p["mu"])
    tags["reference minimiser"] = f"{worst['where1']} / {worst['where2']}"
    out["ref_text"] = f"mu = {mp.nstr(mus, 20)}, sigma = {mp.nstr(sig, 20)} ({cls})"
    if h.startswith("not run"):
        out.update(outcome="unchecked", why=f"Theorem 4 with the coupling was not run: {law.get('why', '')[:200]}")
        return out
    if h == "not certified":
        out.update(outcome="undecided", why=(law.get("why") or "")[:200])
        return out
    w = law.get("theorem4_witness")
    if h == "infeasible (witness)":
        if w is None:
            out.update(outcome="MISS", why="the verdict says witness, but --json has no theorem4_witness")
            return out
        bad, vals = check_witness(sc, ref, w)
        tags["witness verified"] = bad is None
        if vals:
            out["ref_text"] += "; phi at hapstab's witness per component = " + ", ".join(mp.nstr(v[0], 15) for v in vals)
            z1, z2 = (Q(w["z1"][0]), Q(w["z1"][1])), (Q(w["z2"][0]), Q(w["z2"][1]))
            tags["witness z1"] = "-1" if z1 == (-1, 0) else "interior"
            tags["witness z2"] = "-1" if z2 == (-1, 0) else "interior"
            tags["witness p = 0"] = all(Q(x) == 0 for x in w["p"]["re"] + w["p"]["im"])
            tags["witness u = 0 (environment side)"] = all(Q(x) == 0 for x in w["u"]["re"] + w["u"]["im"])
        if witness_decides(out, bad):
            return out
    elif w is not None:
        out.update(outcome="MISS", why=f"a theorem4_witness printed with the verdict {h}")
        return out
    if cls == "undecided":
        out.update(outcome="reference undecided", why="mu or sigma within the reference's tolerance")
    elif h == "feasible":
        ok = cls in ("holds", "no witness")
        out["outcome"] = "agree" if ok else "MISS"
        if not ok:
            out["why"] = f"hapstab: Theorem 4 holds for the coupling, certified; the reference: {out['ref_text']}"
    elif cls.startswith("violated"):
        out["outcome"] = "agree"
        if h == "infeasible (witness)" and cls != "violated (witness)":
            out.update(outcome="REFERENCE MISSED", why="hapstab's witness holds at 50 digits; the reference found mu >= 0")
    elif h == "infeasible (witness)":
        out.update(outcome="REFERENCE MISSED", why="hapstab's witness holds at 50 digits; the reference found no violation")
    elif cls == "holds":
        out.update(outcome="MISS", why=f"hapstab: {h}, certified; the reference (one DOF per component, complete) finds "
                                       f"the program feasible: {out['ref_text']}")
    else:
        out.update(outcome="reference undecided", why="several DOF, no two-frequency witness: the reference does not "
                                                      "decide a certified infeasibility")
    return out


SCENE = CScene  # what independent.py's check_analyze reads a case's text with

if __name__ == "__main__":  # HAPSTAB SCENE [feasible | witness]: one scene through `multidof analyze` and this reference
    sys.exit(analyze_case_main(sys.argv, SCENE, decide))
