"""Independent reference for the sampled haptic loop's largest stable gain (docs/stability.md,
`stability --max`, one DOF and `--scene` of several DOF): the loop is built here from its blocks
as a linear map per period and its spectral radius computed at 50 digits. Nothing is taken from
hapstab: no characteristic polynomial, no D-decomposition, no code.

The loop, one period: the continuous plant (force -> position; for a scene every device's
force -> velocity block with its position integrator and the operators' dampers) is discretised
exactly under a zero-order hold by the matrix exponential of Van Loan's augmented matrix
[[A, B], [0, 0]] T (mpmath.expm, 50 digits): x+ = Phi x + Gamma F. The positions are sampled,
the controller (each transfer function realised in controllable canonical form) computes its
force from them, and a delay of n samples is a shift register of the computed forces:
F_k = -h_{k-n}. The state [plant; controller; register] gives M(K), and its spectral radius
(mpmath.eig, 50 digits) decides stability.

The supremum sup{K >= 0 : M(K) Schur stable for every K in (0, sup)} is found by a scan from
K -> 0+: rho at K = Knom 1e-9 and 1e-13 (mpmath; unstable at both: sup = 0; in double, for long
delays, at 1e-5 and 1e-7, where a root at 1 - cK is still resolved), then rho in double
(numpy) on a geometric grid of 24 points per decade up to Knom 1e9, each interval whose grid
values come within 1e-3 of 1 also maximised by golden section (a narrow unstable window between
grid points), and the first interval where rho reaches 1 is solved by the Illinois method on
rho(K) - 1 in mpmath to a relative width of 1e-24 (from the interval bisected in double to 1e-9 where its
ends still bracket at 50 digits: `narrowed`). Delays of 100 samples and more are decided in
double (numpy.linalg.eigvals on M of order ~n; a radius within 1e-9 of 1 at a probe is decided at 50
digits, and a radius within the tolerance of 1 counts as a root on the circle; unstable at the smaller
probe only bounds the supremum by it: kind "at_most" -- in double the probes need not lie below the
supremum, so "unstable at both" is "at_most" there too): the
tolerance there is 1e-7 relative, and at
n >= 1000 only hapstab's claim is checked (stable at 8 points of (0, lo), NOT stable just above
hi) to keep the time short.
"""
import math
from fractions import Fraction as Q

import mpmath as mp
import numpy as np

from indep_common import Rational, pmul

DPS = 50


def mpq(q):
    q = Q(q)
    return mp.mpf(q.numerator) / q.denominator


# ---------------------------------------------------------------------------------------------
# Realisations (controllable canonical form), in mpmath matrices


def _pdivmod(a, b):
    """Descending exact polynomials: a = q b + r."""
    a = list(a)
    q = [Q(0)] * max(1, len(a) - len(b) + 1)
    while len(a) >= len(b) and any(a):
        f = a[0] / b[0]
        q[len(q) - (len(a) - len(b)) - 1] = f
        for i in range(len(b)):
            a[i] -= f * b[i]
        a.pop(0)
    while len(a) > 1 and a[0] == 0:
        a.pop(0)
    return q, (a if a else [Q(0)])


def reduce_fraction(num, den):
    """num/den in lowest terms (Euclid's gcd over Q): the transfer function, not its writing. A zero
    numerator is 0/1 -- `0/(T z + T)` is the zero function, with no pole at z = -1 (hapstab reads
    an expression as a rational function; a realisation of the writing would add a mode on the
    circle that nothing drives or shows)."""
    num, den = list(num), list(den)
    while len(num) > 1 and num[0] == 0:
        num.pop(0)
    while len(den) > 1 and den[0] == 0:
        den.pop(0)
    if not any(num):
        return [Q(0)], [Q(1)]
    a, b = list(den), list(num)
    while len(b) > 1 or b[0] != 0:
        if len(b) == 1:  # a nonzero constant: coprime
            return num, den
        _, r = _pdivmod(a, b)
        a, b = b, r
    g = a  # the gcd (degree >= 1 here)
    return _pdivmod(num, g)[0], _pdivmod(den, g)[0]


def realize_discrete(num, den):
    """Proper num/den (descending, exact) -> (A, B, C, D) as mp matrices (order deg den after the
    common factors of num and den are cancelled)."""
    num = [Q(x) for x in num]
    den = [Q(x) for x in den]
    while len(den) > 1 and den[0] == 0:
        den.pop(0)
    while len(num) > 1 and num[0] == 0:
        num.pop(0)
    num, den = reduce_fraction(num, den)
    a0 = den[0]
    den = [x / a0 for x in den]
    num = [x / a0 for x in num]
    r = len(den) - 1
    num = [Q(0)] * (r + 1 - len(num)) + num
    assert len(num) == r + 1, "improper controller"
    D = num[0]
    # strictly proper remainder: num - D den
    rem = [num[i] - D * den[i] for i in range(r + 1)][1:]  # degree r-1, r coefficients
    A = mp.zeros(r, r)
    B = mp.zeros(r, 1)
    C = mp.zeros(1, r)
    if r:
        for i in range(r - 1):
            A[i, i + 1] = 1
        for j in range(r):
            A[r - 1, j] = -mpq(den[r - j])
        B[r - 1, 0] = 1
        for j in range(r):
            C[0, j] = mpq(rem[r - 1 - j])
    return A, B, C, mp.matrix([[mpq(D)]])


def realize_plant(num, den):
    """Strictly proper P(s) = num/den -> (A, B, C) in mp (controllable canonical form)."""
    A, B, C, D = realize_discrete(num, den)
    assert D[0, 0] == 0, "plant must be strictly proper"
    return A, B, C


def zoh(A, B, T):
    """Phi = e^{AT}, Gamma = int_0^T e^{As} ds B by expm of [[A, B], [0, 0]] T (Van Loan)."""
    n, m = A.rows, B.cols
    Mx = mp.zeros(n + m, n + m)
    for i in range(n):
        for j in range(n):
            Mx[i, j] = A[i, j] * T
        for j in range(m):
            Mx[i, n + j] = B[i, j] * T
    E = mp.expm(Mx)
    Phi = mp.zeros(n, n)
    Gam = mp.zeros(n, m)
    for i in range(n):
        for j in range(n):
            Phi[i, j] = E[i, j]
        for j in range(m):
            Gam[i, j] = E[i, n + j]
    return Phi, Gam


class Loop:
    """The sampled loop x+ = Phi x + Gamma F, y = Cy x (positions), controller blocks
    (A_c, B_c, C_c, D_c) of the positions (one block realises H0, one H1: h = h0 + K h1, or for a
    scene one block h = K e), F = -h delayed by n samples. M(K) is assembled per K."""

    def __init__(self, Phi, Gam, Cy, blocks, n):
        self.Phi, self.Gam, self.Cy, self.blocks, self.n = Phi, Gam, Cy, blocks, n
        self.np_ = Phi.rows
        self.m = Gam.cols  # number of forces
        self.nc = sum(b[0].rows for b in blocks)
        self.N = self.np_ + self.nc + n * self.m
        self._np_cache = None

    def M_mp(self, K):
        return self._assemble(mp.mpf(K), mp.zeros, lambda a, b: a * b, mp.mpf,
                              self.Phi, self.Gam, self.Cy, self.blocks)

    def _assemble(self, K, zeros, mul, num, Phi, Gam, Cy, blocks):
        """M(K) from the blocks, in mpmath (M_mp) or in double (M_np): the same assembly."""
        N, npl, m, n = self.N, self.np_, self.m, self.n
        M = zeros(N, N)
        # controller output h = sum_b w_b (C_b xc_b + D_b Cy x), w = 1 for 'fixed', K for 'gain'
        # rows: h as a linear map of the state (1 x N per force)
        H = zeros(m, N)
        off = npl
        for (A, B, C, D, w) in blocks:
            wk = K if w == "K" else num(w)
            r = A.rows if hasattr(A, "rows") else A.shape[0]
            DC = mul(D, Cy)
            for i in range(m):
                for j in range(npl):
                    H[i, j] += wk * DC[i, j]
                for j in range(r):
                    H[i, off + j] += wk * C[i, j]
            BC = mul(B, Cy) if r else None
            for i in range(r):
                for j in range(r):
                    M[off + i, off + j] = A[i, j]
                for j in range(npl):
                    M[off + i, j] = BC[i, j]
            off += r
        # plant rows
        for i in range(npl):
            for j in range(npl):
                M[i, j] = Phi[i, j]
        if n == 0:
            GH = mul(Gam, H)
            for i in range(npl):
                for j in range(N):
                    M[i, j] -= GH[i, j]
        else:
            last = npl + self.nc + (n - 1) * m
            for i in range(npl):
                for k in range(m):
                    M[i, last + k] -= Gam[i, k]
            r0 = npl + self.nc
            for k in range(m):
                for j in range(N):
                    M[r0 + k, j] = H[k, j]
            for s in range(1, n):
                for k in range(m):
                    M[r0 + s * m + k, r0 + (s - 1) * m + k] = 1
        return M

    def _np_parts(self):
        if self._np_cache is None:
            def f(X):
                return np.array(X.tolist(), dtype=float).reshape(X.rows, X.cols)
            blocks = [(f(A), f(B), f(C), f(D), w) for (A, B, C, D, w) in self.blocks]
            args = (lambda r, c: np.zeros((r, c)), lambda a, b: a @ b, float, f(self.Phi), f(self.Gam), f(self.Cy), blocks)
            a = self._assemble(0.0, *args)
            b = self._assemble(1.0, *args) - a
            self._np_cache = (a, b)
        return self._np_cache

    def M_np(self, K):
        # the double matrix at K: assembled from M(0) and M(1) (M is affine in K by its
        # construction here: the controller's gain multiplies its output rows)
        a, b = self._np_parts()
        return a + K * b


def rho_mp(loop, K):
    with mp.workdps(DPS):
        ev = mp.eig(loop.M_mp(K), left=False, right=False)
        return max(abs(e) for e in ev), ev


def rho_np(loop, K):
    return float(np.max(np.abs(np.linalg.eigvals(loop.M_np(K)))))


def crossing_kind(ev):
    e = min(ev, key=lambda x: abs(abs(x) - 1))
    ang = abs(float(mp.arg(e)))
    if ang < 1e-6:
        return "z = 1"
    if abs(ang - math.pi) < 1e-6:
        return "z = -1"
    return "complex"


def illinois(g, a, b, ga, gb, rel):
    """Root of g in [a, b] with ga < 0 <= gb (mp values), to relative width rel."""
    side = 0
    for _ in range(200):
        if b - a <= rel * abs(b):
            break
        c = (a * gb - b * ga) / (gb - ga)
        if not (a < c < b):
            c = (a + b) / 2
        gc = g(c)
        if gc >= 0:
            b, gb = c, gc
            if side == 1:
                ga /= 2
            side = 1
        else:
            a, ga = c, gc
            if side == -1:
                gb /= 2
            side = -1
    return a, b


def narrowed(loop, a, b, ga, gb):
    """The bracket [a, b] of rho(K) - 1 (ga < 0 <= gb at 50 digits) bisected in double to 1e-10 of b, widened by
    1e-9 each side and its signs taken again at 50 digits: the Illinois method then starts 10^-9 wide and needs
    ~3 radii at 50 digits instead of ~12 (since stop 86). Where the narrow ends do not bracket at 50 digits (a
    root that double precision misplaces), [a, b] itself, as before."""
    lo, hi = float(a), float(b)
    while hi - lo > 1e-10 * hi:
        c = (lo + hi) / 2
        if rho_np(loop, c) >= 1:
            hi = c
        else:
            lo = c
    na, nb = max(a, mp.mpf(lo) * (1 - mp.mpf(10) ** -9)), min(b, mp.mpf(hi) * (1 + mp.mpf(10) ** -9))
    gna, gnb = rho_mp(loop, na)[0] - 1, rho_mp(loop, nb)[0] - 1
    return (na, nb, gna, gnb) if gna < 0 <= gnb else (a, b, ga, gb)


def sup_reference(loop, Knom, precise=True):
    """dict(kind 'sup'|'zero'|'inf', value, lo, hi, crossing, margin, ...)."""
    Ks, Kn = mp.mpf(Knom) * mp.mpf(10) ** -9, mp.mpf(Knom) * mp.mpf(10) ** -13
    if not precise:  # double: a root at 1 - cK must stay resolvable from 1
        Ks, Kn = mp.mpf(Knom) * mp.mpf(10) ** -5, mp.mpf(Knom) * mp.mpf(10) ** -7
    if precise:
        rs, _ = rho_mp(loop, Ks)
        rn, _ = rho_mp(loop, Kn)
        es = en = mp.mpf(10) ** -40
    else:
        rs, rn = rho_np(loop, float(Ks)), rho_np(loop, float(Kn))
        es = en = 1e-15
        # a root on the circle that K does not move (a Tustin wall's pole at z = -1 cancelled by the
        # sampled mass's zero there) reads 1 +- 1e-13 in double, either side: decide it at 50 digits
        if abs(rs - 1) < 1e-9:
            (rs, _), es = rho_mp(loop, Ks), mp.mpf(10) ** -40
        if abs(rn - 1) < 1e-9:
            (rn, _), en = rho_mp(loop, Kn), mp.mpf(10) ** -40
    if abs(rs - 1) < es and abs(rn - 1) < en:
        # an eigenvalue on the unit circle that K does not move (a controller pole cancelled by a
        # plant zero on the circle, ...): never Schur stable, so the supremum is 0
        return dict(kind="zero", value=mp.mpf(0), rho_small=rs, marginal=True)
    # a radius within the tolerance of 1 is a root on the circle: not Schur stable
    s_unstable, n_unstable = rs >= 1 - es, rn >= 1 - en
    if s_unstable and n_unstable and precise:
        return dict(kind="zero", value=mp.mpf(0), rho_small=rs)
    if s_unstable and n_unstable:  # double (n >= 100): the probes Knom 1e-5, 1e-7 need not be small
        # (case 6378: Knom = 2e6, both probes above the supremum 0.0995): only sup <= Kn is known
        return dict(kind="at_most", value=mp.mpf(Kn), rho_small=rn)
    if n_unstable:  # unstable at the smaller probe, stable at the larger: sup <= Kn (the scan from Ks
        # would only see the window above Ks; a sup in (0, Kn] is not resolved further here)
        return dict(kind="at_most", value=mp.mpf(Kn), rho_small=rn)
    rs = 1 if s_unstable else rs
    start = Kn if rs >= 1 else Ks
    grid = [float(start) * 10 ** (i / 24) for i in range(0, 24 * 18 + 1)]
    rho = [rho_np(loop, k) for k in grid]
    bracket = None
    for i in range(1, len(grid)):
        if rho[i] >= 1:
            bracket = (grid[i - 1], grid[i])
            break
        if i + 1 < len(grid) and rho[i] >= rho[i - 1] and rho[i] >= rho[i + 1] and rho[i] > 1 - 1e-3:
            # a local maximum near 1: look between the grid points for a window above 1
            a, b = grid[i - 1], grid[i + 1]
            for _ in range(60):
                c, d = b - 0.618 * (b - a), a + 0.618 * (b - a)
                if rho_np(loop, c) >= rho_np(loop, d):
                    b = d
                else:
                    a = c
            km = (a + b) / 2
            if rho_np(loop, km) >= 1:
                bracket = (grid[i - 1], km)
                break
    if bracket is None:
        return dict(kind="inf", value=mp.inf, scanned_to=grid[-1])
    a, b = bracket
    if precise:
        with mp.workdps(DPS):
            a, b = mp.mpf(a), mp.mpf(b)
            ga = rho_mp(loop, a)[0] - 1
            gb = rho_mp(loop, b)[0] - 1
            if not (ga < 0 <= gb):
                # the double scan and the 50-digit radius disagree at a grid point: search the
                # bracket in mpmath by bisection on the sign first
                return dict(kind="reference-unsure", value=None, bracket=(a, b), ga=ga, gb=gb)
            a, b, ga, gb = narrowed(loop, a, b, ga, gb)
            lo, hi = illinois(lambda k: rho_mp(loop, k)[0] - 1, a, b, ga, gb, mp.mpf(10) ** -26)
            _, ev = rho_mp(loop, hi)
    else:
        lo, hi = a, b
        for _ in range(60):
            if hi - lo <= 1e-13 * hi:
                break
            c = (lo + hi) / 2
            if rho_np(loop, c) >= 1:
                hi = c
            else:
                lo = c
        ev = np.linalg.eigvals(loop.M_np(hi))
        ev = [mp.mpc(complex(e)) for e in ev]
    margin = None
    half = float(lo) / 2
    margin = 1 - rho_np(loop, half)
    return dict(kind="sup", value=(lo + hi) / 2, lo=lo, hi=hi, crossing=crossing_kind(ev),
                margin=margin)


# ---------------------------------------------------------------------------------------------
# One DOF: stability --plant P --H H --T T --delay n --max K


def rq(rng, lo, hi, den=(1, 2, 4, 5, 10, 20, 100)):
    d = rng.choice(den)
    return Q(rng.randint(int(math.ceil(lo * d)), int(math.floor(hi * d))), d)


def gen_stability(rng):
    T = rng.choice([Q(1, 1000), Q(1, 500), Q(1, 100), Q(1, 2000)])
    m = rq(rng, 0.05, 2)
    b = rq(rng, 0, 5)
    k = rq(rng, 1, 200)
    pf = rng.choices(["mass-damper", "mass", "spring", "unstable", "negative damping", "lag", "fast device"],
                     weights=[28, 9, 16, 11, 7, 11, 18])[0]
    if pf == "fast device":  # b T / m >= 2: the sampled device is nearly first order, so a gain
        T = Q(1, 100)        # loses stability at z = -1 (without delay)
        m = rq(rng, 0.005, 0.02, den=(1000,))
        b = rq(rng, 3, 8)
        pden = [m, b, 0]
    elif pf == "mass-damper":
        pden = [m, b, 0]
    elif pf == "mass":
        pden = [m, 0, 0]
    elif pf == "spring":
        pden = [m, b, k]
    elif pf == "unstable":
        pden = [m, b, -k]
    elif pf == "negative damping":
        pden = [m, -(b + Q(1, 10)), 0]
    else:
        tau = rq(rng, 0.001, 0.05, den=(1000,))
        pden = pmul([m, b, 0], [tau, 1])
    P = Rational([1], pden)
    B = rq(rng, 0, 5)
    cf = rng.choices(["wall K", "tustin wall K", "damper gain", "overall gain", "negative stiffness",
                      "random H1", "spring only"], weights=[26, 12, 12, 12, 12, 14, 12])[0]
    bd = Rational([B, -B], [T, 0])           # B (z - 1)/(T z)
    one = Rational([1], [1])
    if cf == "wall K":
        H0, H1 = bd, one
    elif cf == "tustin wall K":
        H0, H1 = Rational([2 * B, -2 * B], [T, T]), one
    elif cf == "damper gain":
        H0, H1 = Rational([rq(rng, 1, 100)], [1]), Rational([1, -1], [T, 0])
    elif cf == "overall gain":
        H0 = Rational([0], [1])
        H1 = Rational([1 + B / T, -B / T], [1, 0]) if rng.random() < 0.5 else \
            Rational([1 + B / T, -B / T], [1, -Q(rng.randint(0, 8), 10)])
    elif cf == "negative stiffness":
        H0, H1 = bd, Rational([-1], [1])
        if pf not in ("spring",):
            pden = [m, b, k]
            P = Rational([1], pden)
            pf = "spring"
    elif cf == "spring only":  # H = K: crossings at z = -1 on a mass-damper without delay
        H0, H1 = Rational([0], [1]), one
    else:
        r = Q(rng.randint(20, 90), 100)
        c = Q(rng.randint(-90, 90), 100)
        H0 = bd
        H1 = Rational([rq(rng, -2, 2), rq(rng, -2, 2), 1], [1, -2 * r * c, r * r])
    u = rng.random()
    n = rng.randint(0, 5) if u < 0.94 else (100 if u < 0.98 else 1000)
    if cf == "spring only" and u < 0.94 and rng.random() < 0.6:
        n = 0
    if pf == "fast device" and u < 0.94 and rng.random() < 0.7:
        n = 0
    # a natural gain scale: the stiffness m (2/T)^2 and the damping m 2/T
    Knom = float(m) * 4 / float(T) ** 2 if cf not in ("damper gain",) else float(m) * 2 / float(T)
    if cf == "overall gain":
        Knom = 1.0
    tags = {"plant": pf, "controller": cf, "delay": "0" if n == 0 else ("1-5" if n <= 5 else str(n))}
    return dict(P=P, H0=H0, H1=H1, T=T, n=n, Knom=Knom, tags=tags)


def free_position_every_K(c):
    """z = 1 is an eigenvalue of M(K) for every K, decided exactly: the device integrates its
    velocity (P(s) = num/den with den(0) = 0) and neither H0 nor H1 pushes back at DC (H0(1) =
    H1(1) = 0, finite): a constant position with zero force is an equilibrium for every K (an
    eigenvalue 1 that no K moves), so the loop is never Schur stable and the supremum is 0.
    Double precision cannot see this on the long-delay loops (order ~n): a root at 1 comes out
    as 1 +- 1e-13, on either side."""
    if c["P"].den[-1] != 0:
        return False
    for H in (c["H0"], c["H1"]):
        num, den = reduce_fraction([Q(x) for x in H.num], [Q(x) for x in H.den])
        if sum(den) == 0 or sum(num) != 0:
            return False
    return True


def minus_one_every_K(c):
    """z = -1 is an eigenvalue of M(K) for every K, decided exactly: the device is P = c/(m s^2 + k) without
    damping (a mass, k = 0, or an undamped spring of either sign), whose zero-order hold vanishes at z = -1
    ((1 - z^-1) Z{P/s} = c (1 - cos wT)(z + 1)/(k (z^2 - 2 cos(wT) z + 1)), w^2 = k/m; c T^2 (z + 1)/(2 m (z - 1)^2)
    at k = 0; cosh for k < 0), and H0 or H1 has a pole there (a Tustin wall): det(zI - M) = z^n P_d d_0 d_1 +
    P_n (n_0 d_1 + K n_1 d_0) (indep_roots.py) is 0 at z = -1 for every K, so the loop is never Schur stable and
    the supremum is 0. Double precision reads that root as 1 +- 1e-13, and the roots of det(zI - M) as exactly
    1: the reference could not say before (stops 67-86)."""
    num, den = reduce_fraction([Q(x) for x in c["P"].num], [Q(x) for x in c["P"].den])
    if len(num) != 1 or len(den) != 3 or den[1] != 0:
        return False
    for H in (c["H0"], c["H1"]):
        hn, hd = reduce_fraction([Q(x) for x in H.num], [Q(x) for x in H.den])
        if any(hn) and sum(x * (-1) ** (len(hd) - 1 - i) for i, x in enumerate(hd)) == 0:
            return True
    return False


def stability_args(c, digits=25):
    h = f"{c['H0'].expr()} + K*({c['H1'].expr()})"
    a = ["stability", "--plant", c["P"].expr("s"), "--H", h, "--T", f"{c['T'].numerator}/{c['T'].denominator}",
         "--delay", str(c["n"]), "--max", "K", "--digits", str(digits)]
    return a


def build_loop_1dof(c):
    with mp.workdps(DPS):
        A, B, C = realize_plant(c["P"].num, c["P"].den)
        Phi, Gam = zoh(A, B, mpq(c["T"]))
        blocks = []
        for H, w in ((c["H0"], 1), (c["H1"], "K")):
            Ac, Bc, Cc, Dc = realize_discrete(H.num, H.den)
            blocks.append((Ac, Bc, Cc, Dc, w))
        return Loop(Phi, Gam, C, blocks, c["n"])


# ---------------------------------------------------------------------------------------------
# Scenes of several DOF: stability --scene S --max g


def gen_scene(rng):
    T = Q(1, 1000)
    N = 2 if rng.random() < 0.8 else 3
    devices = []
    first = rng.choices(["unstable ss", "stable ss", "mass-damper"], weights=[60, 20, 20])[0]
    for i in range(N):
        m = rq(rng, 0.05, 1)
        if i == 0 and first == "unstable ss":
            a = rq(rng, 0.5, 30)
            devices.append(dict(kind="ss", A=a / m * m, Bv=1 / m, passive=False, m=m))
        elif i == 0 and first == "stable ss":
            a = -rq(rng, 0.5, 30)
            devices.append(dict(kind="ss", A=a, Bv=1 / m, passive=True, m=m))
        else:
            devices.append(dict(kind="md", m=m, b=rq(rng, 0, 5)))
    ops = [rq(rng, 0.5, 5) if rng.random() < 0.5 else None for _ in range(N)]
    # environment: diagonal walls (K + B (z-1)/(T z)), a spring between neighbours in 40%
    Ks = [rq(rng, 100, 3000) for _ in range(N)]
    Bs = [rq(rng, 0, 8) for _ in range(N)]
    if rng.random() < 0.25:  # issue 46 item 2's environment on every DOF
        Ks = [Q(1000)] * N
        Bs = [Q(5)] * N
    kc = rq(rng, 50, 2000) if rng.random() < 0.4 else Q(0)
    E = [[None] * N for _ in range(N)]
    for i in range(N):
        for j in range(N):
            if i == j:
                kk = Ks[i] + kc * ((1 if i > 0 else 0) + (1 if i < N - 1 else 0))
                E[i][j] = Rational([kk + Bs[i] / T, -Bs[i] / T], [1, 0])
            elif abs(i - j) == 1 and kc:
                E[i][j] = Rational([-kc], [1])
            else:
                E[i][j] = Rational([0], [1])
    n = 0 if rng.random() < 0.7 else rng.randint(1, 2)
    tags = {"first device": first, "DOF": str(N), "delay": str(n), "link spring": bool(kc)}
    return dict(T=T, devices=devices, ops=ops, E=E, n=n, tags=tags, Knom=1.0)


def scene_toml(c):
    T = c["T"]
    L = ["# generated by tests/verify/independent.py (criterion scene_max)", "[scene]",
         'name = "independent campaign scene"', f'T = "{T.numerator}/{T.denominator}"', ""]
    for i, d in enumerate(c["devices"]):
        L.append("[[device]]")
        L.append(f'name = "d{i}"')
        if d["kind"] == "ss":
            A, Bv = d["A"], d["Bv"]
            L.append(f'ss = {{ A = [["{A}"]], B = [["{Bv}"]], C = [["1"]], D = [["0"]] }}')
            if not d["passive"]:
                L.append("passive = false")
        else:
            L.append(f'm = "{d["m"]}"')
            L.append(f'b = "{d["b"]}"')
        L.append("")
    for i, bo in enumerate(c["ops"]):
        if bo is None:
            continue
        if isinstance(bo, tuple):
            L += ["[[operator]]", f'name = "h{i}"', f'dofs = ["d{i}"]', f'b = "{bo[0]}"', f'k = "{bo[1]}"', ""]
            continue
        L += ["[[operator]]", f'name = "h{i}"', f'dofs = ["d{i}"]', f'b = "{bo}"', ""]
    rows = []
    for r in c["E"]:
        rows.append("[" + ", ".join('"' + e.expr() + '"' for e in r) + "]")
    L += ["[environment]", "tf = [" + ", ".join(rows) + "]", 'gain = "g"', ""]
    L += ["[parameters]", 'g = "1"', ""]
    if c["n"]:
        L += ["[delay]", f'samples = "{c["n"]}"', ""]
    return "\n".join(L) + "\n"


def scene_plant(c, with_matrices=False):
    """The scene's devices (and operators' dampers) sampled under a ZOH: (Phi, Gamma, Cy) at 50
    digits, the state per DOF [velocity, position], Cy the sampled positions (with_matrices: the
    continuous (A, B, Cy) instead)."""
    with mp.workdps(DPS):
        N = len(c["devices"])
        # continuous plant: per DOF the device's velocity state(s) and its position
        blocksA = []
        for i, d in enumerate(c["devices"]):
            if d["kind"] == "ss":
                a, bv = mpq(d["A"]), mpq(d["Bv"])
            else:
                a, bv = -mpq(d["b"]) / mpq(d["m"]), 1 / mpq(d["m"])
            bo = c["ops"][i]
            ko = 0
            if isinstance(bo, tuple):  # operator b_o + k_o/s: its spring deflection is the position
                bo, ko = bo            # (the conserved difference of the two integrals set aside)
            if bo is not None:  # operator damper: force -b_o v on the device
                a = a - bv * mpq(bo)
            blocksA.append((a, bv, -bv * mpq(ko)))
        n = 2 * N
        A = mp.zeros(n, n)
        B = mp.zeros(n, N)
        Cy = mp.zeros(N, n)
        for i, (a, bv, ax) in enumerate(blocksA):
            A[2 * i, 2 * i] = a          # velocity state (C = 1: v = state)
            A[2 * i, 2 * i + 1] = ax     # an operator's spring on the position
            A[2 * i + 1, 2 * i] = 1       # position' = velocity
            B[2 * i, i] = bv
            Cy[i, 2 * i + 1] = 1
        if with_matrices:
            return A, B, Cy
        Phi, Gam = zoh(A, B, mpq(c["T"]))
        return Phi, Gam, Cy


def realize_matrix(E):
    """An N x N matrix of Rational entries realised entry by entry (controllable canonical form
    each, the entries' states stacked): (A, B, C, D) as mp matrices, input and output N."""
    with mp.workdps(DPS):
        N = len(E)
        off = 0
        ents = []
        for i in range(N):
            for j in range(N):
                Ae, Be, Ce, De = realize_discrete(E[i][j].num, E[i][j].den)
                ents.append((i, j, Ae, Be, Ce, De))
        r = sum(e[2].rows for e in ents)
        Ac = mp.zeros(r, r)
        Bc = mp.zeros(r, N)
        Cc = mp.zeros(N, r)
        Dc = mp.zeros(N, N)
        for (i, j, Ae, Be, Ce, De) in ents:
            k = Ae.rows
            for p in range(k):
                for q in range(k):
                    Ac[off + p, off + q] = Ae[p, q]
                Bc[off + p, j] = Be[p, 0]
                Cc[i, off + p] = Ce[0, p]
            Dc[i, j] += De[0, 0]
            off += k
        return Ac, Bc, Cc, Dc


def build_loop_scene(c):
    Phi, Gam, Cy = scene_plant(c)
    Ac, Bc, Cc, Dc = realize_matrix(c["E"])
    return Loop(Phi, Gam, Cy, [(Ac, Bc, Cc, Dc, "K")], c["n"])
