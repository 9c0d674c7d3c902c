"""Independent reference for `stability --scene S --max g` on scenes with a `[coupling]` V(z) and
on scenes whose closed loop is not affine in g (issue 46, "The campaigns that would have caught
these"; criterion scene_coupling of tests/verify/independent.py).

The loop, one period, built here from the scene's blocks as docs/scene.md defines them (paper 000
(11)): the devices (velocity state and position integrator per DOF, operators' dampers) sampled
under a ZOH by Van Loan's matrix exponential at 50 digits (indep_loop.scene_plant); the environment
E and the coupling V realised entry by entry (controllable canonical form); the coupling in
parallel with the device: x_e = x + g_V (C_V s_V + D_V u), u = -g_E (C_E s_E + D_E x_e), with
g_E, g_V the blocks' `gain` expressions evaluated at g. The two equations are solved together for
[x_e; u] as one 2N x 2N linear system per value of g (mpmath.lu_solve at 50 digits, numpy in
double) -- no elimination formula, no composed controller. s_E' = A_E s_E + B_E x_e,
s_V' = A_V s_V + B_V u, the device force u delayed by a shift register of n samples (V sees the
computed force, the devices the delayed one). M(g) is assembled anew at every g (it is not affine
in g when D_E D_V != 0 or a gain is not of degree 1), and its spectral radius by mpmath.eig at 50
digits decides stability.

Nothing here comes from hapstab: no characteristic polynomial, no D-decomposition, no code.
"""
import math
from fractions import Fraction as Q

import mpmath as mp
import numpy as np

import indep_loop as IL
from indep_common import Rational

DPS = 50

# The gain expressions: (hapstab's text, the value as a function of g (Fraction or mpf), whether
# of degree 1 in g). One spec is the source of both, so the scene and the reference cannot differ.
GAINS = {
    "g": ("g", lambda g: g, True),
    "1/g": ("1/g", lambda g: 1 / g, False),
    "g(1+g)/2": ("g*(1 + g)/2", lambda g: g * (1 + g) / 2, False),
    "1": (None, lambda g: 1, True),
}


def gen_coupled(rng, conservatism=False):
    """A scene of 2-3 DOF (indep_loop.gen_scene's devices, operators, walls and springs) with a
    [coupling] and the parameter g in one of five places. conservatism: Theorem 5's setting
    (mass-dampers with b > 0, no delay, g the environment's gain, V strictly proper: the loop is
    affine in g, so both sides are suprema of intervals)."""
    c = IL.gen_scene(rng)
    T, N = c["T"], len(c["devices"])
    place = rng.choices(["env g, V with feedthrough", "coupling 1/g", "coupling g", "env g(1+g)/2",
                         "env g, V strictly proper"], weights=[35, 25, 10, 15, 15])[0]
    if conservatism:
        place = "env g, V strictly proper"
        c["n"] = 0
        c["tags"]["delay"] = "0"
        c["devices"] = [dict(kind="md", m=d["m"], b=IL.rq(rng, 0.5, 5)) for d in c["devices"]]
        c["tags"]["first device"] = "mass-damper"
        # an operator b + k/s on every DOF (Theorem 5 needs one per DOF; its spring makes M(0) Schur
        # stable, so the walk of the certified crossing can reach 0)
        c["ops"] = [(IL.rq(rng, 0.5, 5), IL.rq(rng, 10, 500)) for _ in c["devices"]]
    # V per DOF: the admittance of a coupling spring kc in parallel with a damper bc, kc in
    # [0.2, 5] times the DOF's wall stiffness (paper 000's virtual coupling), or a pure spring
    V = [[Rational([0], [1]) for _ in range(N)] for _ in range(N)]
    kinds = []
    for i in range(N):
        Kw = c["E"][i][i].num[0] + c["E"][i][i].num[1]  # the wall's K (numerator K + B/T, -B/T)
        kc = IL.rq(rng, 0.2, 5) * max(Kw, Q(100))
        kc = Q(round(kc))
        bc = IL.rq(rng, 0, 5)
        kind = rng.choices(["spring-damper", "spring", "first order"], weights=[55, 20, 25])[0]
        if place == "env g, V strictly proper":
            kind = "lagged spring-damper"
            if conservatism:  # Lemma 1's DC condition wants V(1) = 1/kc > T/(2 Delta), Delta = b
                kc = Q(round(IL.rq(rng, 0.05, 0.9, den=(20, 100)) * 2 * c["devices"][i]["b"] / T))
                kind = "spring-damper"  # with feedthrough: E is made strictly proper below
        if kind == "spring-damper":    # T z / ((kc T + bc) z - bc): feedthrough T/(kc T + bc)
            V[i][i] = Rational([T, 0], [kc * T + bc, -bc])
        elif kind == "spring":         # 1/kc
            V[i][i] = Rational([1], [kc])
        elif kind == "first order":    # d + e/(z - a), a in (-0.9, 0.9)
            a = IL.rq(rng, -0.9, 0.9, den=(10, 20))
            d = 1 / kc
            e = IL.rq(rng, -1, 1) / kc
            V[i][i] = Rational([d, e - d * a], [1, -a])
        else:                          # T / ((kc T + bc) z - bc): strictly proper
            V[i][i] = Rational([T], [kc * T + bc, -bc])
        kinds.append(kind)
    offdiag = N >= 2 and rng.random() < 0.15 and place != "env g, V strictly proper"
    if offdiag:  # a small symmetric cross term in D_V
        e = Q(1, round(IL.rq(rng, 2, 20) * max(c["E"][0][0].num[0], Q(100))))
        V[0][1] = Rational([e], [1])
        V[1][0] = Rational([e], [1])
    if conservatism:  # E z^-1: D_E = 0, so x_e = x + V u, u = -g E x_e stays affine in g
        c["E"] = [[Rational(e.num, e.den + [Q(0)]) for e in row] for row in c["E"]]
    gE, gV = {"env g, V with feedthrough": ("g", "1"), "coupling 1/g": ("1", "1/g"), "coupling g": ("1", "g"),
              "env g(1+g)/2": ("g(1+g)/2", "1"), "env g, V strictly proper": ("g", "1")}[place]
    c["V"] = V
    c["gE"], c["gV"] = gE, gV
    c["tags"] = dict(c["tags"])
    c["tags"]["g in"] = "env g, E strictly proper" if conservatism else place
    c["tags"]["coupling"] = "feedthrough, E strictly proper" if conservatism else "strictly proper" if place == "env g, V strictly proper" else (
        "feedthrough, cross term" if offdiag else "feedthrough")
    return c


def scene_toml(c, gref):
    """indep_loop.scene_toml's scene with the gains moved as c says, [coupling] added and g = gref."""
    text = IL.scene_toml(c)
    gtext = GAINS[c["gE"]][0]
    text = text.replace('gain = "g"\n', f'gain = "{gtext}"\n' if gtext else "")
    text = text.replace('g = "1"\n', f'g = "{gref}"\n')
    rows = ["[" + ", ".join('"' + e.expr() + '"' for e in r) + "]" for r in c["V"]]
    L = ["[coupling]", "tf = [" + ", ".join(rows) + "]"]
    if GAINS[c["gV"]][0]:
        L.append(f'gain = "{GAINS[c["gV"]][0]}"')
    return text + "\n".join(L) + "\n"


def _np(Mx):
    return np.array(Mx.tolist(), dtype=float) if Mx.rows and Mx.cols else np.zeros((Mx.rows, Mx.cols))


class CoupledLoop:
    """M(g) of the loop with its coupling, assembled anew at each g (see the module's docstring)."""

    def __init__(self, c):
        self.c = c
        with mp.workdps(DPS):
            self.Phi, self.Gam, self.Cy = IL.scene_plant(c)
            self.E = IL.realize_matrix(c["E"])
            self.V = IL.realize_matrix(c["V"])
        self.N = len(c["devices"])
        self.n = c["n"]
        self.np_ = self.Phi.rows
        self.re = self.E[0].rows
        self.rv = self.V[0].rows
        self.order = self.np_ + self.re + self.rv + self.n * self.N
        self.fE = GAINS[c["gE"]][1]
        self.fV = GAINS[c["gV"]][1]
        self._f = None

    def _floats(self):
        if self._f is None:
            self._f = dict(Phi=_np(self.Phi), Gam=_np(self.Gam), Cy=_np(self.Cy),
                           E=[_np(x) for x in self.E], V=[_np(x) for x in self.V])
        return self._f

    def _assemble(self, g, xp):
        """xp: 'mp' (mpmath matrices at the current precision) or 'np' (double)."""
        N, npl, re, rv, n = self.N, self.np_, self.re, self.rv, self.n
        if xp == "np":
            f = self._floats()
            Phi, Gam, Cy = f["Phi"], f["Gam"], f["Cy"]
            (Ae, Be, Ce, De), (Av, Bv, Cv, Dv) = f["E"], f["V"]
            a, b = float(self.fE(g)), float(self.fV(g))
            Z = lambda r, k: np.zeros((r, k))  # noqa: E731
        else:
            Phi, Gam, Cy = self.Phi, self.Gam, self.Cy
            (Ae, Be, Ce, De), (Av, Bv, Cv, Dv) = self.E, self.V
            g = mp.mpf(g)
            a, b = mp.mpf(self.fE(g)), mp.mpf(self.fV(g))
            Z = mp.zeros
        Ns = self.order
        ox, oe, ov, orr = 0, npl, npl + re, npl + re + rv
        # S [x_e; u] = R s, s the state [x; s_E; s_V; register]
        S = Z(2 * N, 2 * N)
        R = Z(2 * N, Ns)
        for i in range(N):
            S[i, i] = 1
            S[N + i, N + i] = 1
            for j in range(N):
                S[i, N + j] = -b * Dv[i, j]
                S[N + i, j] = a * De[i, j]
            for j in range(npl):
                R[i, ox + j] = Cy[i, j]
            for j in range(rv):
                R[i, ov + j] = b * Cv[i, j]
            for j in range(re):
                R[N + i, oe + j] = -a * Ce[i, j]
        if xp == "np":
            XU = np.linalg.solve(S, R)
            M = np.zeros((Ns, Ns))
        else:
            XU = mp.inverse(S) * R
            M = mp.zeros(Ns, Ns)
        # the device force: u now (n = 0) or the register's last entry
        for i in range(npl):
            for j in range(npl):
                M[i, ox + j] += Phi[i, j]
            for k in range(N):
                if n == 0:
                    for j in range(Ns):
                        M[i, j] += Gam[i, k] * XU[N + k, j]
                else:
                    M[i, orr + (n - 1) * N + k] += Gam[i, k]
        for p in range(re):
            for q in range(re):
                M[oe + p, oe + q] += Ae[p, q]
            for k in range(N):
                if Be[p, k] != 0:
                    for j in range(Ns):
                        M[oe + p, j] += Be[p, k] * XU[k, j]
        for p in range(rv):
            for q in range(rv):
                M[ov + p, ov + q] += Av[p, q]
            for k in range(N):
                if Bv[p, k] != 0:
                    for j in range(Ns):
                        M[ov + p, j] += Bv[p, k] * XU[N + k, j]
        if n:
            for k in range(N):
                for j in range(Ns):
                    M[orr + k, j] = XU[N + k, j]
            for s in range(1, n):
                for k in range(N):
                    M[orr + s * N + k, orr + (s - 1) * N + k] = 1
        return M

    def M_mp(self, g):
        with mp.workdps(DPS):
            return self._assemble(g, "mp")

    def M_np(self, g):
        return self._assemble(g, "np")


def rho_mp(loop, g):
    return IL.rho_mp(loop, g)


def rho_np(loop, g):
    return IL.rho_np(loop, g)


def first_crossing_double(loop, lo=1e-6, hi=1e6):
    """The first g in [lo, hi] (geometric grid, 12 per decade) where rho >= 1 in double, with whether
    the loop is stable at lo; for placing the scene's value of g near the boundary."""
    k = lo
    stable_lo = rho_np(loop, lo) < 1
    steps = int(round(12 * math.log10(hi / lo)))
    for i in range(steps + 1):
        k = lo * 10 ** (i / 12)
        if (rho_np(loop, k) < 1) != stable_lo:
            return stable_lo, k
    return stable_lo, None
