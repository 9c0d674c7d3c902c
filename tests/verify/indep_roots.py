"""The spectrum of a delayed one-DOF loop without a dense eigenvalue problem (the `stability_long` reference).

The loop matrix M(K) of indep_loop.Loop (plant (Phi, Gam, Cy), controller blocks (A_i, B_i, C_i, D_i) weighted 1
and K, the force delayed n samples) has order n + (its blocks' states). Its eigenvalues are the roots of

    det(zI - M(K)) = z^n A(z) + B_0(z) + K B_1(z),   A = P_d d_0 d_1,   B_i = P_n n_i d_(1-i),

with P_d = det(zI - Phi), P_n = Cy adj(zI - Phi) Gam = det(zI - Phi + Gam Cy) - P_d (the matrix determinant lemma),
d_i = det(zI - A_i) and n_i = C_i adj(zI - A_i) B_i + D_i d_i: the loop's 1 + z^-n G (H_0 + K H_1) = 0 over the
realisations' own denominators, so hidden modes of a realisation stay roots. The characteristic polynomials of
the small blocks come from Faddeev-LeVerrier at 40 digits; the n + deg A roots from Aberth-Ehrlich's simultaneous
iteration in double, started on the circles of the coefficients' Newton polygon (Bini 1996), with p/p' evaluated
as (A + B z^-n)/(n A/z + A' + B' z^-n) where |z| > 1 (z^n never overflows). O(n^2) a sweep against dense QR's
O(n^3): order 1,000 in ~0.1 s against numpy's eigvals ~3-12 s. The result is accepted only when every root is
distinct from the others and its backward error is below 1e-11 of the polynomial's magnitude there; otherwise
None, and the caller solves the dense problem. Checked against numpy.linalg.eigvals of M itself (docs/verification.md,
stop 86)."""
import math

import mpmath as mp
import numpy as np


def charpoly_mp(A):
    """det(zI - A) for a small mpmath matrix, descending coefficients (Faddeev-LeVerrier)."""
    n = A.rows
    c = [mp.mpf(1)]
    Mk = mp.zeros(n, n)
    for k in range(1, n + 1):
        Mk = A * Mk + c[-1] * mp.eye(n)
        c.append(-sum((A * Mk)[i, i] for i in range(n)) / k)
    return np.array(c, dtype=object)


def loop_charpoly_parts(loop):
    """(A, [B_0, B_1]) of det(zI - M(K)) = z^n A + B_0 + K B_1 (the module's formula), mpmath, descending."""
    Pd = charpoly_mp(loop.Phi)
    Pn = np.polysub(charpoly_mp(loop.Phi - loop.Gam * loop.Cy), Pd)
    one = np.array([mp.mpf(1)], dtype=object)
    ds, ns = [], []
    for (A, B, C, D, _) in loop.blocks:
        d = charpoly_mp(A) if A.rows else one
        n = np.polysub(charpoly_mp(A - B * C), d) if A.rows else np.array([mp.mpf(0)], dtype=object)
        ds.append(d)
        ns.append(np.polyadd(n, D[0, 0] * d))
    A = Pd
    for d in ds:
        A = np.polymul(A, d)
    Bs = []
    for i in range(len(ds)):
        t = np.polymul(Pn, ns[i])
        for j in range(len(ds)):
            if j != i:
                t = np.polymul(t, ds[j])
        Bs.append(t)
    return A, Bs


def newton_polygon_start(n, A, B):
    """Starting points for the roots of p = z^n A + B (numpy, descending; B(0) != 0): for each edge of the upper
    convex hull of (k, log|p_k|) from degree k1 to k2, k2 - k1 points on the circle of radius
    (|p_k1|/|p_k2|)^(1/(k2 - k1)), rotated so that no two edges' points line up."""
    logc = {}
    for i, a in enumerate(A[::-1]):
        if a != 0:
            logc[n + i] = math.log(abs(a))
    for i, b in enumerate(B[::-1]):
        if b != 0:
            logc[i] = math.log(abs(b) + (math.exp(logc[i]) if i in logc else 0))
    hull = []
    for k in sorted(logc):
        while len(hull) >= 2:
            (k1, v1), (k2, v2) = hull[-2], hull[-1]
            if (v2 - v1) * (k - k1) > (logc[k] - v1) * (k2 - k1):
                break
            hull.pop()  # the middle point lies on or under the chord
        hull.append((k, logc[k]))
    pts = []
    for (k1, v1), (k2, v2) in zip(hull, hull[1:]):
        m = k2 - k1
        pts.append(math.exp((v1 - v2) / m) * np.exp(1j * (2 * math.pi * np.arange(m) / m + 0.4 + len(pts))))
    return np.concatenate(pts)


def aberth_roots(n, A, B, iters=500):
    """Every root of p = z^n A + B (A, B numpy descending, B(0) != 0) by Aberth-Ehrlich, or None (see the
    module's docstring)."""
    A, B = np.asarray(A, dtype=complex), np.asarray(B, dtype=complex)
    dA, dB = np.polyder(A) if len(A) > 1 else np.array([0j]), np.polyder(B) if len(B) > 1 else np.array([0j])
    z = newton_polygon_start(n, A, B)
    active = np.ones(len(z), dtype=bool)

    def newton_ratio(z):  # p/p', divided through by z^n where |z| > 1
        a, da, b, db = np.polyval(A, z), np.polyval(dA, z), np.polyval(B, z), np.polyval(dB, z)
        big = np.abs(z) > 1
        with np.errstate(all="ignore"):
            u = np.where(big, z, 1) ** -n
            zn = np.where(big, 0, z ** n)
            return np.where(big, (a + b * u) / (n * a / z + da + db * u), (zn * a + b) / (n * zn / z * a + zn * da + db))
    last = np.zeros(0)
    for _ in range(iters):
        idx = np.nonzero(active)[0]
        if not len(idx):
            break
        w = newton_ratio(z[idx])
        diff = z[idx, None] - z[None, :]
        diff[np.arange(len(idx)), idx] = np.inf
        with np.errstate(all="ignore"):
            step = w / (1 - w * (1 / diff).sum(axis=1))
        if not np.all(np.isfinite(step)):
            return None
        z[idx] -= step
        last = np.abs(step) / np.maximum(np.abs(z[idx]), 1e-300)
        active[idx] = last > 1e-13
    else:  # a root stalled at rounding's level (a near-double root converges linearly): accepted only that close
        if last.max() > 1e-9:
            return None
    gap = np.abs(z[:, None] - z[None, :])
    np.fill_diagonal(gap, np.inf)
    if gap.min() < 1e-9 * max(1.0, np.abs(z).max()):
        return None
    r = np.abs(z)
    with np.errstate(all="ignore"):
        over = np.exp(-n * np.log(r))  # |z|^-n, used where |z| > 1
        under = np.exp(n * np.log(r))
        resid = np.where(r > 1, np.abs(np.polyval(A, z) + np.polyval(B, z) * z ** -n),
                         np.abs(z ** n * np.polyval(A, z) + np.polyval(B, z)))
        mag = np.where(r > 1, np.polyval(np.abs(A), r) + np.polyval(np.abs(B), r) * over,
                       under * np.polyval(np.abs(A), r) + np.polyval(np.abs(B), r))
    return z if np.all(resid <= 1e-11 * mag) else None


def loop_roots(loop, K):
    """The eigenvalues of M(K) (numpy complex), or None where Aberth is not accepted. z = 0 is taken out exactly as
    often as z divides both terms (B = 0: n plus A's own roots at 0)."""
    with mp.workdps(40):
        A, (B0, B1) = loop_charpoly_parts(loop)
        B = np.polyadd(B0, mp.mpf(K) * B1)
    n, A, B = loop.n, [float(x) for x in A], [float(x) for x in B]
    while B and B[0] == 0:
        B.pop(0)
    while len(A) > 1 and A[-1] == 0:  # A = z A~: z^n A = z^(n + 1) A~
        A.pop()
        n += 1
    if not B:
        return np.concatenate([np.roots(A), np.zeros(n)])
    zeros = 0
    while B[-1] == 0 and n > 0:  # z divides both terms
        B.pop()
        n, zeros = n - 1, zeros + 1
    z = aberth_roots(n, np.array(A), np.array(B))
    return None if z is None else np.concatenate([z, np.zeros(zeros)])
