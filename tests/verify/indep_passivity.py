"""Independent reference for paper 001's passivity bound, (45) with a delay and (54):

    b* = max over w in [0, pi/T] of Re{ T H(e^{jwT}) e^{-jnwT} e^{-jw t_d} / (1 - e^{jwT}) } + eta

evaluated from this definition and nothing else (no polynomial in cos wT, no closed form, no
code of hapstab). With theta = wT and nu = n + t_d/T the objective is
f(theta) = Re{T H(e^{j theta}) e^{-j nu theta} / (1 - e^{j theta})} + eta on [0, pi].

* Interior: f sampled in double on a grid adapted to the delay (64 points per period 2 pi / nu,
  at least 4096), to the poles of H (points at 0, 0.3, 1, 3, ... times 1 - |p| from each pole
  angle, so resonances within 1e-5 of the circle are seen) and to the ends (geometric points
  10^-k, k = 1.5 ... 9, from 0, and k = 1.5 ... 6 from pi); the grid's local maxima are ranked by
  their values in mpmath (30 digits), the best refined by golden section in double,
  then by Newton's method on f' in mpmath at `dps` digits (f', f'' by mpmath.diff), with a
  golden-section fallback in mpmath when Newton leaves its bracket.
* w -> 0: f is even in theta (H has real coefficients), so f(0) is the limit, taken at
  theta = 1e-25 in `dps` (>= 60) digits: the difference is O(1e-50); the error stated is
  |f(1e-25) - f(1e-24)|.
* w -> pi/T: H may have a pole at z = -1. The reference decides the behaviour itself: it
  evaluates c_k = f(pi - 10^-k) 10^-k for k = 3, 6, ..., 24. A finite limit makes c_k -> 0 by
  three orders per step; a pole makes c_k converge to a nonzero constant whose sign is the
  direction of the divergence (+inf or -inf). A finite end value is Richardson-extrapolated,
  2 f(pi - e) - f(pi - 2e) at e = 1e-24 (O(e^2) error; f is not even about pi when nu is not an
  integer), its error stated as the difference from the same at e = 1e-23. These end values are
  computed with 50 more digits (1 + e^{j(pi - e)} cancels near a pole at z = -1).
* Within 1e-4 of pi, where the double grid stops (1e-6 short of pi), f is scanned at pi - 10^-k,
  k = 4 ... 24 in steps of 1/4, in mpmath (a maximum there: a pole at z = -1 beside a delay nu
  within ~1e-6 of a whole number, the end finite or -inf), its local maximum refined by golden section.
* 1 - e^{j theta} is evaluated as -2j sin(theta/2) e^{j theta/2}: computed directly its real
  part, 1 - cos theta, loses its relative accuracy as theta -> 0, and the real part of f (O(1)
  beside an imaginary part O(1/theta)) depends on it.

The reference value is the largest candidate; its error bound is the winning candidate's own.
"""
import cmath
import math
from fractions import Fraction as Q

import mpmath as mp
import numpy as np

from indep_common import Rational, SumTF, fstr, golden_section

GOLD = (math.sqrt(5) - 1) / 2


def one_minus_z_np(th):
    # 1 - e^{j theta} = -2j sin(theta/2) e^{j theta/2}: no cancellation as theta -> 0 (1 - cos
    # theta computed directly loses its relative accuracy there; the real part of f, O(1) beside
    # an imaginary part O(1/theta), depends on it)
    return -2j * np.sin(th / 2) * np.exp(0.5j * th)


class Objective:
    def __init__(self, H, T, nu, eta, dps=60):
        self.H, self.T, self.nu, self.eta, self.dps = H, Q(T), Q(nu), Q(eta), dps
        self.Tf, self.nuf, self.etaf = float(self.T), float(self.nu), float(self.eta)
        self.fl = [t.coeffs_float() for t in H.terms]

    # double precision, vectorised (the grid)
    def f_np(self, th):
        z = np.exp(1j * th)
        h = np.zeros_like(z)
        for num, den in self.fl:
            h = h + np.polyval(num, z) / np.polyval(den, z)
        g = self.Tf * h * np.exp(-1j * self.nuf * th) / one_minus_z_np(th)
        return g.real + self.etaf

    def f_d(self, th):
        z = cmath.exp(1j * th)
        h = 0
        for num, den in self.fl:
            pn = 0j
            for c in num:
                pn = pn * z + c
            pd = 0j
            for c in den:
                pd = pd * z + c
            h += pn / pd
        return (self.Tf * h * cmath.exp(-1j * self.nuf * th) / (-2j * math.sin(th / 2) * cmath.exp(0.5j * th))).real + self.etaf

    # mpmath at the working precision
    def f_mp(self, th):
        th = mp.mpf(th)
        z = mp.expj(th)
        nu = mp.mpf(self.nu.numerator) / self.nu.denominator
        T = mp.mpf(self.T.numerator) / self.T.denominator
        g = T * self.H.eval_mp(z) * mp.expj(-nu * th) / (-2j * mp.sin(th / 2) * mp.expj(th / 2))
        return mp.re(g) + mp.mpf(self.eta.numerator) / self.eta.denominator

    def poles(self):
        out = []
        for _, den in self.fl:
            if len(den) > 1:
                out.extend(np.roots(den))
        return out


def end_zero(obj):
    with mp.workdps(obj.dps):
        a = obj.f_mp(mp.mpf(10) ** -25)
        b = obj.f_mp(mp.mpf(10) ** -24)
        return a, abs(a - b)


def end_pi(obj):
    """('finite', value, err) or ('+inf'|'-inf', None, None), decided from the numbers.
    50 more digits: near a pole at z = -1, 1 + e^{j(pi - e)} loses its real part to cancellation."""
    with mp.workdps(obj.dps + 50):
        pi = mp.pi
        cs = []
        for k in range(3, 25, 3):
            e = mp.mpf(10) ** -k
            cs.append(obj.f_mp(pi - e) * e)
        scale = abs(cs[0]) * 1000 + 1  # |f(pi - 1e-3)| + 1
        c1, c2 = cs[-2], cs[-1]
        if abs(c2) > mp.mpf(10) ** -12 * scale and abs(c2 / c1 - 1) < mp.mpf(10) ** -3:
            return ("+inf" if c2 > 0 else "-inf"), None, None

        def rich(e):
            return 2 * obj.f_mp(pi - e) - obj.f_mp(pi - 2 * e)
        v = rich(mp.mpf(10) ** -24)
        v2 = rich(mp.mpf(10) ** -23)
        return "finite", v, abs(v - v2)


def near_pi(obj):
    """A maximum within 1e-4 of pi, which the double grid cannot place (it stops 1e-6 short of pi):
    f at pi - 10^-k, k = 4 ... 24 in steps of 1/4, in mpmath with 50 more digits (as end_pi);
    a local maximum among them is refined by golden section in e = pi - theta. Returns
    (theta, value, error) or None (the largest value at an end of the scan: the end candidates
    and the grid hold it)."""
    with mp.workdps(obj.dps + 50):
        es = [mp.mpf(10) ** (-mp.mpf(k) / 4) for k in range(16, 97)]
        fs = [obj.f_mp(mp.pi - e) for e in es]
        i = max(range(len(fs)), key=lambda k: fs[k])
        if i == 0 or i == len(fs) - 1:
            return None
        lo, hi = es[i + 1], es[i - 1]
        a, _, _, b, _, _ = golden_section(lambda e: -obj.f_mp(mp.pi - e), lo, hi, 400,
                                          mp.mpf(10) ** -(obj.dps // 2 + 2) * lo)
        e = (a + b) / 2
        v = obj.f_mp(mp.pi - e)
        err = abs(obj.f_mp(mp.pi - a) - v) + abs(obj.f_mp(mp.pi - b) - v) \
            + mp.mpf(10) ** -(obj.dps - 12) * (1 + abs(v))
        return mp.pi - e, v, err


def grid(obj):
    N = max(4096, int(64 * float(obj.nu) / 2) + 1)
    th = [np.linspace(0, np.pi, N + 1)[1:-1]]
    ks = np.arange(1.5, 9.01, 0.25)
    th.append(10.0 ** -ks)
    # near pi at most 1e-6: a pole of H at z = -1 makes the double objective there a difference
    # of terms ~1/(pi - theta) (the end itself is taken in mpmath, end_pi)
    th.append(np.pi - 10.0 ** -ks[ks <= 6])
    offs = np.array([0, 0.3, 1, 3, 10, 30, 100, 300])
    for p in obj.poles():
        r = abs(p)
        if r < 0.8:
            continue
        phi = abs(cmath.phase(p))
        d = max(1 - r, 1e-9)
        th.append(phi + d * offs)
        th.append(phi - d * offs)
    t = np.concatenate(th)
    # nothing within 1e-6 of pi: near a pole at z = -1 the double objective is noise there (the
    # end is end_pi's, in mpmath)
    t = t[(t > 0) & (t < np.pi - 1e-6)]
    t = np.unique(t)
    with np.errstate(all="ignore"):
        f = obj.f_np(t)
    ok = np.isfinite(f)
    return t[ok], f[ok]


def golden_d(obj, a, b, iters=80):
    c = b - GOLD * (b - a)
    d = a + GOLD * (b - a)
    fc, fd = obj.f_d(c), obj.f_d(d)
    for _ in range(iters):
        if b - a < 1e-13 * max(1.0, abs(a)):
            break
        if fc >= fd:
            b, d, fd = d, c, fc
            c = b - GOLD * (b - a)
            fc = obj.f_d(c)
        else:
            a, c, fc = c, d, fd
            d = a + GOLD * (b - a)
            fd = obj.f_d(d)
    x = (a + b) / 2
    return x, obj.f_d(x)


def refine_mp(obj, th0, a, b):
    """Newton on f' from th0 inside [a, b] (mpmath); golden section in mpmath if Newton fails.
    Returns (theta, value, error bound)."""
    with mp.workdps(obj.dps):
        a, b = mp.mpf(a), mp.mpf(b)
        th = mp.mpf(th0)
        f = obj.f_mp
        ok = False
        step = None
        for _ in range(12):
            d1 = mp.diff(f, th, 1)
            d2 = mp.diff(f, th, 2)
            if not d2 < 0:
                break
            step = -d1 / d2
            tn = th + step
            if not (a <= tn <= b):
                break
            th = tn
            if abs(step) < mp.mpf(10) ** -(obj.dps // 2 + 4) * (1 + abs(th)):
                ok = True
                break
        if ok:
            v = f(th)
            d1 = mp.diff(f, th, 1)
            err = abs(d1 * step) + mp.mpf(10) ** -(obj.dps - 12) * (1 + abs(v))
            return th, v, err
        # golden section for the maximum (the least of -f), in mpmath
        a, _, _, b, _, _ = golden_section(lambda x: -f(x), a, b, 400, mp.mpf(10) ** -(obj.dps // 2 + 2))
        x = (a + b) / 2
        v = f(x)
        err = abs(f(a) - v) + abs(f(b) - v) + mp.mpf(10) ** -(obj.dps - 12) * (1 + abs(v))
        return x, v, err


def bstar(H, T, nu, eta=0, dps=60, extra_theta=None, fast=False):
    """The reference b*: dict(kind 'finite'|'+inf', value, err, where, theta, end_pi).
    fast: the grid's maxima refined in double only (about 1e-12 relative; used to scan and
    bracket, never to compare)."""
    obj = Objective(H, T, nu, eta, dps)
    kpi, vpi, epi = end_pi(obj)
    if kpi == "+inf":
        return dict(kind="+inf", value=mp.inf, err=0, where="w->pi/T", theta=mp.pi, end_pi=kpi)
    v0, e0 = end_zero(obj)
    cands = [("w=0", mp.mpf(0), v0, e0)]
    if kpi == "finite":
        cands.append(("w=pi/T", mp.pi, vpi, epi))
    t, f = grid(obj)
    if len(t) > 2:
        inner = np.where((f[1:-1] >= f[:-2]) & (f[1:-1] >= f[2:]))[0] + 1
        if len(inner) <= 400 and not fast:
            # rank the grid's local maxima by their value in mpmath (30 digits), not in double:
            # near a pole the double values can be far off and crowd out the true peaks
            with mp.workdps(30):
                fm = np.array([float(obj.f_mp(mp.mpf(float(t[i])))) for i in inner])
            f = f.copy()
            f[inner] = fm
        order = inner[np.argsort(-f[inner])]
        best = f[order[0]] if len(order) else -np.inf
        spread = (np.max(f) - np.min(f)) if len(f) else 0
        # at most 40 (a constant objective, e.g. H = c/(z + 1) without delay, makes every grid
        # point a local maximum)
        pick = [i for i in order[:8]] + [i for i in order[8:40] if f[i] >= best - 1e-3 * spread]
        dref = []
        for i in pick:
            x, v = golden_d(obj, t[i - 1], t[i + 1])
            if not fast:
                with mp.workdps(30):  # ranked by the value in mpmath (see above)
                    v = float(obj.f_mp(mp.mpf(x)))
            dref.append((v, x, t[i - 1], t[i + 1]))
        dref.sort(key=lambda r: -r[0])
        top = dref[0][0] if dref else -np.inf
        for k, (v, x, a, b) in enumerate(dref):
            if fast:
                if k < 1:
                    cands.append(("interior", mp.mpf(x), mp.mpf(v), mp.mpf(1e-12) * (1 + abs(v))))
                continue
            if k < 3 or v >= top - 1e-9 * (abs(top) + 1):
                th, vm, em = refine_mp(obj, x, a, b)
                cands.append(("interior", th, vm, em))
    if kpi != "+inf":  # on the -inf side too: a maximum within 1e-6 of pi before the fall (nu = n + 1e-12)
        np_ = near_pi(obj)
        if np_ is not None:
            cands.append(("interior", np_[0], np_[1], np_[2]))
    if extra_theta is not None:
        with mp.workdps(dps):
            th = mp.mpf(extra_theta)
            if 0 < th < mp.pi:
                cands.append(("interior", th, obj.f_mp(th), mp.mpf(10) ** -(dps - 12)))
    w = max(cands, key=lambda c: c[2])
    for c in cands:  # an end within the errors of the best is where the maximum is
        if c[0] != "interior" and c[2] >= w[2] - (w[3] + c[3] + mp.mpf(10) ** -28 * (1 + abs(w[2]))):
            w = (c[0], c[1], w[2], max(w[3], c[3])) if c[2] < w[2] else c
            break
    return dict(kind="finite", value=w[2], err=w[3], where=w[0], theta=w[1], end_pi=kpi, obj=obj)


# ---------------------------------------------------------------------------------------------
# Generators


def rq(rng, lo, hi, den=(1, 2, 3, 4, 5, 8, 10, 16, 20, 25, 100)):
    d = rng.choice(den)
    return Q(rng.randint(int(math.ceil(lo * d)), int(math.floor(hi * d))), d)


def rand_cos(rng):
    return Q(rng.randint(-95, 95), 100)


def stable_term(rng, resonant=False):
    """A stable rational term with exact coefficients; resonant: a pair at radius 1 - 1e-5."""
    kind = rng.random()
    if resonant:
        r = Q(99999, 100000)
        c = rand_cos(rng)
        den = [1, -2 * r * c, r * r]
        num = [rq(rng, -2, 2), rq(rng, -2, 2)]
        if num == [0, 0]:
            num = [Q(1), Q(0)]
        return Rational(pmul_s(num, Q(1, rng.choice([100, 1000, 10000]))), den)
    # a numerator drawn all zero is made 1 (no draw more: every other case stays as it was); a zero
    # term made bound_max's H1 = 0, which hapstab rightly refuses ("does not depend on K")
    if kind < 0.4:
        p = rq(rng, -0.95, 0.95)
        num = [rq(rng, -3, 3), rq(rng, -3, 3)]
        return Rational(num if any(num) else [Q(1), Q(0)], [1, -p])
    r = Q(rng.randint(30, 98), 100)
    c = rand_cos(rng)
    den = [1, -2 * r * c, r * r]
    num = [rq(rng, -3, 3), rq(rng, -3, 3), rq(rng, -3, 3)]
    return Rational(num if any(num) else [Q(1), Q(0), Q(0)], den)


def pmul_s(a, k):
    return [Q(x) * k for x in a]


FRACS = [Q(1, 2), Q(3, 2), Q(4, 3), Q(5, 3), Q(5, 4), Q(7, 4), Q(101, 2)]
TS = [Q(1, 1000), Q(1, 500), Q(1, 2000), Q(1, 100), Q(1)]


def wall(T, K, B):
    # K + B (z - 1)/(T z)
    return Rational([K * T + B, -B], [T, 0])


def tustin(T, K, B):
    # K + 2 B (z - 1)/(T (z + 1))
    return Rational([K * T + 2 * B, K * T - 2 * B], [T, T])


def gen_bound(rng):
    """A random instance of (45)/(54): (H, T, n, td_over_T, eta, tags)."""
    T = rng.choice(TS)
    fam = rng.choices(["wall", "tustin", "tustin+", "pole-1", "random", "resonant"],
                      weights=[16, 20, 14, 14, 20, 16])[0]
    K = rq(rng, 1, 4) * Q(1, T) * rng.choice([1, 10, 100]) / 100
    B = rq(rng, 0.1, 5)
    terms = []
    res = False
    if fam == "wall":
        terms.append(wall(T, K, B))
    elif fam == "tustin":
        terms.append(tustin(T, K, B))
    elif fam == "tustin+":
        terms.append(tustin(T, K, B))
        res = rng.random() < 0.5
        terms.append(stable_term(rng, resonant=res))
    elif fam == "pole-1":
        c = rq(rng, -3, 3) or Q(1)
        terms.append(Rational([c], [1, 1]))
        if rng.random() < 0.6:
            res = rng.random() < 0.3
            terms.append(stable_term(rng, resonant=res))
    elif fam == "random":
        for _ in range(rng.randint(1, 2)):
            terms.append(stable_term(rng))
    else:
        res = True
        terms.append(stable_term(rng, resonant=True))
        if rng.random() < 0.5:
            terms.append(stable_term(rng))
    # delay
    u = rng.random()
    if u < 0.65:
        if rng.random() < 0.6:
            tau = rng.choice(FRACS)
        else:
            while True:
                q = rng.randint(2, 7)
                p = rng.randint(1, 6 * q)
                tau = Q(p, q)
                if tau.denominator > 1:
                    break
        n = 0 if rng.random() < 0.6 else rng.randint(1, 5)
    else:
        tau = Q(0)
        n = rng.randint(0, 6) if rng.random() < 0.93 else rng.randint(10, 60)
    eta = rq(rng, 0, 2) if rng.random() < 0.2 else Q(0)
    H = SumTF(terms)
    s = math.sin(math.pi * float(Q(n) + tau))
    tags = {"family": fam}
    if tau == 0:
        tags["delay"] = "integer"
    else:
        tags["delay"] = "sin(pi nu) > 0" if s > 0 else "sin(pi nu) < 0"
    tags["pole at z = -1"] = fam in ("tustin", "tustin+", "pole-1")
    tags["resonance 1e-5 from the circle"] = res
    return H, T, n, tau, eta, tags


def bound_args(H, T, n, tau, eta):
    a = ["bound", "--H", H.expr(), "--T", fstr(T).strip("()")]
    if n:
        a += ["--delay", str(n)]
    if tau:
        td = tau * T
        a += ["--frac-delay", f"{td.numerator}/{td.denominator}"]
    if eta:
        a += ["--eta", f"{eta.numerator}/{eta.denominator}"]
    return a
