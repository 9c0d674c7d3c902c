"""The independent reference of the `witness` criterion (tests/verify/independent.py): paper 000's
Theorem 5 program (16) -- Theorem 4's conditions with the coupling's level Q_V free -- decided in
the frequency domain, from the scene file as written.

Nothing here comes from hapstab. The scene is read with tomllib; each entry of the environment's
transfer-function matrix is evaluated from its text (a restricted expression evaluator: + - * / ^,
integer literals, the scene's parameters, z or s) at a point z of the unit circle in mpmath, s
replaced by (z - 1)/(T z) for a backward-Euler block; the delay is z^-n; E-hat(z) = T z/(z - 1) E(z)
(paper 000 (11)). No realisation, no Hessenberg form, no characteristic polynomial.

The condition (derived here from the paper's definitions, not from hapstab's comments): a point of
(16) gives, at z = e^{j theta} (not a pole) and x = (zI - A)^{-1} B u, v^* M1 v = -Re(u^* X E-hat(z) u)
- u^* Q_E u <= 0 (M1 <= 0 at v = [x; u]: the P terms cancel since |z| = 1), and (14) > 0 gives
Delta_D X - Q_E > 0. So every point of (16) has, for every u != 0,
    phi(theta, u) = Re(u^* X E-hat(e^{j theta}) u) + u^* Delta_D X u > 0,
i.e. lambda_min(He(X E-hat(e^{j theta})) + Delta_D X) > 0 for theta in (0, pi]. X: block diagonal
g_i I (one block per operator) with X E(1) symmetric; for the scenes drawn here E(1) is symmetric
and each independent part of E is connected through E(1), so X = g I on each part and the sign of
phi does not depend on the g's: X = I below (checked on the scene: E(1) symmetric, and every pair of
DOFs that E couples at a random z is coupled through E(1) too, else the reference declines).

The reference's decision is the sign of mu = min over theta of lambda_min(He E-hat + Delta_D): a
sweep in double (numpy) over 32768 frequencies, then golden-section refinement of the 6 best local minima at 40 digits (mpmath.eigh),
and theta = pi, and theta = 1e-18 (the limit theta -> 0+) at 60 digits.
"""
import math
import sys
import tomllib
from fractions import Fraction as Q

import mpmath as mp
import numpy as np

from indep_common import Expr, analyze_case_main, exact, golden, local_extrema, witness_decides

DPS = 40


class Scene:
    """What (16) needs from a scene: T, the environment E(z) entry by entry, the delay, Delta_D."""

    def __init__(self, text):
        d = tomllib.loads(text)
        self.T = exact(d["scene"]["T"])
        self.params = {k: exact(v) for k, v in d.get("parameters", {}).items()}
        self.params["T"] = self.T
        env = d["environment"]
        tf = env["tf"]
        rows = [[tf]] if isinstance(tf, str) else tf
        self.m = len(rows)
        self.domain = env.get("domain", "z")
        if self.domain == "s" and env.get("method") != "backward_euler":
            raise ValueError("the reference reads domain = \"s\" with method = \"backward_euler\" only")
        self.var = "s" if self.domain == "s" else "z"
        self.E = [[Expr(e, self.params) for e in r] for r in rows]
        self.n = int(exact(d.get("delay", {}).get("samples", "0")))
        devs = d["device"]
        osp = d.get("multidof", {}).get("osp")
        # Delta_D: the declared OSP levels, else b of each mass-damper 1/(m s + b) (Re(m j w + b) = b)
        self.delta = [exact(o) for o in osp] if osp else [exact(dv.get("b", "0")) for dv in devs]
        if len(self.delta) != self.m:
            raise ValueError("one device per DOF expected")

    # E-hat(z) = T z/(z - 1) z^-n E(z), entry by entry, in mpmath at the current precision
    def ehat_mp(self, z):
        s = (z - 1) / (self.T.numerator / mp.mpf(self.T.denominator) * z) if self.var == "s" else z
        f = (mp.mpf(self.T.numerator) / self.T.denominator) * z / (z - 1) * z ** (-self.n)
        return mp.matrix([[f * e.mp(self.var, s) for e in r] for r in self.E])

    def ehat_np(self, z):
        T = float(self.T)
        s = (z - 1) / (T * z) if self.var == "s" else z
        f = T * z / (z - 1) * z ** (-self.n)
        out = np.empty((len(z), self.m, self.m), dtype=complex)
        for i, r in enumerate(self.E):
            for j, e in enumerate(r):
                out[:, i, j] = f * np.broadcast_to(e.np(self.var, s), z.shape)
        return out

    def e1(self):
        """E(1) at 40 digits (backward Euler: s = 0)."""
        with mp.workdps(DPS):
            v = mp.mpf(0) if self.var == "s" else mp.mpf(1)
            return mp.matrix([[e.mp(self.var, v) for e in r] for r in self.E])


def pinned_identity(sc):
    """True when X = I may stand for every admissible X (see the module's docstring)."""
    E1 = sc.e1()
    with mp.workdps(DPS):
        z = mp.mpc("0.3", "0.7")
        s = (z - 1) / (mp.mpf(sc.T.numerator) / sc.T.denominator * z) if sc.var == "s" else z
        Ez = [[e.mp(sc.var, s) for e in r] for r in sc.E]
        scale = max(1, max(abs(E1[i, j]) for i in range(sc.m) for j in range(sc.m)))
        tol = mp.mpf(10) ** -30 * scale
        for i in range(sc.m):
            for j in range(sc.m):
                if abs(E1[i, j] - E1[j, i]) > tol:
                    return False, "E(1) is not symmetric"
                if i != j and abs(Ez[i][j]) > tol and abs(E1[i, j]) <= tol:
                    return False, f"E couples DOFs {i} and {j} but E(1) does not (X not pinned)"
    return True, ""


def hform_mp(sc, theta):
    """He(E-hat(e^{j theta})) + Delta_D at the current precision (X = I)."""
    z = mp.expjpi(theta / mp.pi) if theta != mp.pi else mp.mpc(-1, 0)
    Eh = sc.ehat_mp(z)
    m = sc.m
    return mp.matrix([[(Eh[i, j] + mp.conj(Eh[j, i])) / 2 + (mp.mpf(sc.delta[i].numerator) / sc.delta[i].denominator if i == j else 0)
                       for j in range(m)] for i in range(m)])


def lmin_mp(sc, theta):
    H = hform_mp(sc, theta)
    if sc.m == 1:
        return mp.re(H[0, 0]), mp.matrix([[1]])
    E, V = mp.eigh(H)
    k = min(range(sc.m), key=lambda i: mp.re(E[i]))
    return mp.re(E[k]), V[:, k]


def sweep_np(sc, thetas):
    z = np.exp(1j * thetas)
    Eh = sc.ehat_np(z)
    H = (Eh + np.conj(np.transpose(Eh, (0, 2, 1)))) / 2 + np.diag([float(d) for d in sc.delta])[None, :, :]
    return np.linalg.eigvalsh(H)[:, 0]


def grid(K=32768):
    """theta in (0, pi]: K uniform points (a resonance 1e-4 wide is 10 points wide). Below 1e-4 the
    double sweep is cancellation noise (E-hat ~ 1/theta); there the function is even and analytic in
    theta (E(1) symmetric), so its infimum near 0 is the limit theta -> 0+, evaluated at 60 digits."""
    return np.pi * np.arange(1, K + 1) / K


def search(sc, extra=()):
    """min over theta in (0, pi] of lambda_min: dict(mu, theta, where, scale)."""
    th = grid()
    with np.errstate(all="ignore"):
        v = sweep_np(sc, th)
    v = np.where(np.isfinite(v) & (th > 1e-4), v, np.inf)  # near 0: cancellation noise; the limit below
    loc = local_extrema(v)
    best = None
    with mp.workdps(DPS):
        f = lambda t: lmin_mp(sc, t)[0]
        cands = [(mp.pi, f(mp.pi)), (mp.mpf(10) ** -18, None)]
        with mp.workdps(60):
            cands[1] = (mp.mpf(10) ** -18, lmin_mp(sc, mp.mpf(10) ** -18)[0])
        for i in loc:
            a = mp.mpf(th[i - 1]) if i else mp.mpf(th[i]) / 10
            b = mp.mpf(th[i + 1]) if i + 1 < len(th) else mp.pi
            cands.append(golden(f, a, b))
        for t in extra:
            cands.append((mp.mpf(t), f(mp.mpf(t))))
        best = min(cands, key=lambda c: c[1])
        scale = 1 + max(abs(mp.mpf(d.numerator) / d.denominator) for d in sc.delta)
    t = best[0]
    where = "theta = pi" if abs(t - mp.pi) < 1e-9 else ("theta -> 0" if t < 1e-6 else "interior")
    return dict(mu=best[1], theta=t, where=where, scale=scale)


def check_witness(sc, wz, wu):
    """phi at hapstab's exact point: (ok, phi at 50 digits, why). wz = ["p/q", "p/q"], wu = ["p/q", ...]."""
    za, zb = Q(wz[0]), Q(wz[1])
    u = [Q(x) for x in wu]
    if za * za + zb * zb != 1:
        return False, None, f"z = {za} + {zb} j is not on the unit circle exactly"
    if all(x == 0 for x in u):
        return False, None, "the direction u is 0"
    if za == 1 and zb == 0:
        return False, None, "z = 1 is the pole of E-hat"
    with mp.workdps(50):
        z = mp.mpc(mp.mpf(za.numerator) / za.denominator, mp.mpf(zb.numerator) / zb.denominator)
        Eh = sc.ehat_mp(z)
        uu = [mp.mpf(x.numerator) / x.denominator for x in u]
        m = sc.m
        quad = mp.fsum(uu[i] * Eh[i, j] * uu[j] for i in range(m) for j in range(m))
        dd = mp.fsum(uu[i] ** 2 * mp.mpf(sc.delta[i].numerator) / sc.delta[i].denominator for i in range(m))
        phi = mp.re(quad) + dd
        size = abs(quad) + abs(dd)
    return True, (phi, size), ""


def boundary_scale(sc0):
    """s* = max over theta of lambda_max(-D0^{-1/2} He(E-hat) D0^{-1/2}), D0 = sc0.delta: the device
    levels s * D0 make mu >= 0 exactly from s = s* on (double sweep; its 6 best local maxima, theta = pi
    and theta -> 0 refined at 40 digits: the double sweep is noise within 1e-7 of theta = 0)."""
    th = grid()
    d0 = np.array([float(d) for d in sc0.delta])
    with np.errstate(all="ignore"):
        Eh = sc0.ehat_np(np.exp(1j * th))
        H = -(Eh + np.conj(np.transpose(Eh, (0, 2, 1)))) / 2
        W = H / np.sqrt(d0)[None, :, None] / np.sqrt(d0)[None, None, :]
        lam = np.linalg.eigvalsh(W)[:, -1]
    lam = np.where(np.isfinite(lam) & (th > 1e-4), lam, -np.inf)  # near 0: cancellation noise; the limit below
    with mp.workdps(DPS):
        D0 = [mp.mpf(d.numerator) / d.denominator for d in sc0.delta]

        def negl(t):
            z = mp.expjpi(t / mp.pi) if t != mp.pi else mp.mpc(-1, 0)
            Eh = sc0.ehat_mp(z)
            M = mp.matrix([[-(Eh[a, b] + mp.conj(Eh[b, a])) / 2 / mp.sqrt(D0[a] * D0[b]) for b in range(sc0.m)] for a in range(sc0.m)])
            if sc0.m == 1:
                return -mp.re(M[0, 0])
            return -max(mp.re(x) for x in mp.eigh(M, eigvals_only=True))
        cands = [(mp.pi, negl(mp.pi)), (mp.mpf(10) ** -18, negl(mp.mpf(10) ** -18))]
        for i in local_extrema(-lam):
            a = th[i - 1] if i else th[i] / 10
            b = th[i + 1] if i + 1 < len(th) else math.pi
            cands.append(golden(negl, mp.mpf(a), mp.mpf(b), 50))
        t, v = min(cands, key=lambda c: c[1])
        return float(-v), float(t)


# ---------------------------------------------------------------------------------------------
# the scenes drawn (all numbers exact; every expression uses integer literals and parameters)


def rq(rng, lo, hi, den=(1, 2, 4, 5, 10, 20, 100)):
    d = rng.choice(den)
    return Q(rng.randint(int(math.ceil(lo * d)), int(math.floor(hi * d))), d)


def qs(q):
    q = Q(q)
    return f"{q.numerator}" if q.denominator == 1 else f"{q.numerator}/{q.denominator}"


def env_wall(rng, T, p, i=""):
    """K + B (z - 1)/(T z) (+ a resonance near the circle): (expression, tags)."""
    p[f"K{i}"] = rq(rng, 0.1, 40) / T
    p[f"B{i}"] = rq(rng, -2, 10) if rng.random() < 0.25 else rq(rng, 0, 10)
    e = f"K{i} + B{i}*(z-1)/(T*z)"
    res = rng.random() < 0.25
    if res:  # c (z - 1) z/(z^2 - a1 z + a0), poles at radius r = 1 - eps
        eps = Q(1, rng.choice([100, 1000, 10000]))
        r = 1 - eps
        cph = Q(rng.randint(-95, 95), 100)
        p[f"a1{i}"], p[f"a0{i}"] = 2 * r * cph, r * r
        p[f"c{i}"] = rq(rng, -2, 2) * eps * p[f"K{i}"] * T
        e += f" + c{i}*(z-1)*z/(z^2 - a1{i}*z + a0{i})"
    return e, res


def draw_env(rng, fam, T, p):
    """The environment's tf (a string or rows of strings) and its tags."""
    if fam == "wall":
        e, res = env_wall(rng, T, p)
        return e, {"resonance near the circle": res}
    if fam == "two parts":
        e0, r0 = env_wall(rng, T, p, "a")
        e1, r1 = env_wall(rng, T, p, "b")
        return [[e0, "0"], ["0", e1]], {"resonance near the circle": r0 or r1}
    N = rng.choice([2, 2, 3, 3, 4]) if fam == "contact" else rng.choice([2, 3])
    if fam == "linked walls":
        walls = [env_wall(rng, T, p, str(i))[0] for i in range(N)]
        p["kc"] = rq(rng, 0.05, 20) / T
        rows = []
        for i in range(N):
            nb = (1 if i > 0 else 0) + (1 if i < N - 1 else 0)
            rows.append([f"{walls[i]} + {nb}*kc" if i == j else ("(-1)*kc" if abs(i - j) == 1 else "0") for j in range(N)])
        return rows, {"resonance near the circle": False}
    # contact: one virtual mass M (ground k, B) touched through k_i + B_i s (bench/contact_scene.py)
    p["M"], p["k"], p["B"] = rq(rng, 0.05, 2), rq(rng, 10, 3000), rq(rng, 0, 10)
    for i in range(N):
        p[f"k{i}"], p[f"B{i}"] = rq(rng, 50, 3000), rq(rng, -1, 5) if rng.random() < 0.2 else rq(rng, 0, 5)
    den = "(M*s^2 + (B" + "".join(f" + B{i}" for i in range(N)) + ")*s + k" + "".join(f" + k{i}" for i in range(N)) + ")"
    rows = [[f"k{i} + B{i}*s - (k{i} + B{i}*s)^2/{den}" if i == j else f"(-1)*(k{i} + B{i}*s)*(k{j} + B{j}*s)/{den}"
             for j in range(N)] for i in range(N)]
    return rows, {"resonance near the circle": False}


def env_text(tf, fam):
    if isinstance(tf, str):
        return f'[environment]\ntf = "{tf}"\n'
    rows = ",\n      ".join("[" + ", ".join(f'"{e}"' for e in r) + "]" for r in tf)
    dom = 'domain = "s"\nmethod = "backward_euler"\n' if fam == "contact" else ""
    return f"[environment]\n{dom}tf = [{rows}]\n"


def scene_text(T, p, tf, fam, n, devices):
    L = ["# generated by tests/verify/independent.py (criterion witness)", "[scene]",
         f'name = "witness campaign: {fam}"', f'T = "{qs(T)}"', "", "[parameters]"]
    L += [f'{k} = "{qs(v)}"' for k, v in p.items()]
    L.append("")
    for i, d in enumerate(devices):
        L += ["[[device]]", f'name = "d{i}"']
        if d["kind"] == "md":
            L += [f'm = "{qs(d["m"])}"', f'b = "{qs(d["b"])}"']
        else:  # 1/(m s + b + k/s): a device with a spring, resonant when b is small; OSP level b
            L += [f'tf = "s/(({qs(d["m"])})*s^2 + ({qs(d["b"])})*s + {qs(d["k"])})"']
        L += ["", "[[operator]]", f'name = "h{i}"', f'dofs = ["d{i}"]', f'b = "{qs(d["hb"])}"', ""]
    L.append(env_text(tf, fam))
    if n:
        L += ["[delay]", f'samples = "{n}"', ""]
    if any(d["kind"] == "tf" for d in devices):
        L += ["[multidof]", "osp = [" + ", ".join(f'"{qs(d.get("osp", d["b"]))}"' for d in devices) + "]", ""]
    return "\n".join(L)


def pick_level(rng, s_star):
    """A device-level scale s: near the boundary s* (1e-2, 1e-4, 1e-6 either side), or far from it."""
    u = rng.random()
    if s_star <= 0:
        return Q(rng.randint(50, 2000), 100), "s* <= 0 (feasible for every level)"
    if u < 0.45:
        k = rng.choice([2, 4, 6])
        sg = rng.choice([-1, 1])
        x = s_star * (1 + sg * 10.0 ** -k)
        return Q(round(x * 10 ** 14), 10 ** 14), f"1e-{k} {'below' if sg < 0 else 'above'} the boundary"
    x = s_star * (rng.uniform(0.2, 0.9) if u < 0.72 else rng.uniform(1.1, 3))
    return Q(x).limit_denominator(1000) or Q(1, 1000), "far " + ("below" if x < s_star else "above")


def gen(rng):
    fam = rng.choices(["wall", "contact", "linked walls", "two parts"], weights=[45, 25, 18, 12])[0]
    T = rng.choice([Q(1, 1000), Q(1, 500), Q(1, 2000), Q(1, 100)])
    p = {}
    tf, tags = draw_env(rng, fam, T, p)
    u = rng.random()
    n = 0 if u < 0.1 else (1 if u < 0.45 else (rng.randint(2, 5) if u < 0.8 else rng.randint(6, 24)))
    m = 1 if isinstance(tf, str) else len(tf)
    beta = [Q(1)] + [rq(rng, 0.5, 3) for _ in range(m - 1)]
    devs = [dict(kind="md", b=beta[i], m=rq(rng, 0.05, 1), hb=rq(rng, 0.5, 5)) for i in range(m)]
    sc0 = Scene(scene_text(T, p, tf, fam, n, devs))
    parts = [[0], [1]] if fam == "two parts" else [list(range(m))]
    tags.update({"family": fam, "delay": "0" if n == 0 else ("1" if n == 1 else ("2-5" if n <= 5 else "6-24")),
                 "DOF": str(m)})
    dist = []
    for part in parts:
        s_star, _ = boundary_scale(_sub(sc0, part))
        s, d = pick_level(rng, s_star)
        dist.append(d)
        for i in part:
            devs[i]["b"] = s * beta[i]
    tags["near the boundary"] = any(d.startswith("1e-") for d in dist)
    tags["level"] = dist[0] if len(dist) == 1 else " / ".join(sorted(set(x.split(" the")[0] for x in dist)))
    if rng.random() < 0.12:  # a resonant device s/(m s^2 + b s + k), its level b declared
        i = rng.randrange(m)
        devs[i].update(kind="tf", k=rq(rng, 10, 5000), osp=devs[i]["b"])
        tags["resonant device"] = True
    return dict(text=scene_text(T, p, tf, fam, n, devs), tags=tags)


def _sub(sc, part):
    """The scene restricted to the DOFs `part` (an independent part of E)."""
    import copy
    s = copy.copy(sc)
    s.E = [[sc.E[i][j] for j in part] for i in part]
    s.delta = [sc.delta[i] for i in part]
    s.m = len(part)
    return s


# ---------------------------------------------------------------------------------------------
# hapstab's answer against the reference


def hapstab_answer(j, rc):
    """'feasible', 'infeasible (witness)', 'infeasible (<path>)' or 'not certified'."""
    if not j.get("certified"):
        return "not certified"
    if j.get("feasible"):
        return "feasible"
    path = j.get("path") or ""
    if j.get("witness") is not None or path == "frequency-domain witness":
        return "infeasible (witness)"
    if path == "decomposed" and "frequency-domain witness" in (j.get("certificate") or ""):
        return "infeasible (witness)"
    return f"infeasible ({path})"


def verify_witness(sc, w, out):
    """hapstab's printed witness re-evaluated at 50 digits: None (verified), or the failure text;
    'boundary' when phi is within 1e-40 of 0 (relative): neither verified nor refuted."""
    if w is None:
        return "the path says witness, but --json has no witness (z, u)"
    ok, val, why = check_witness(sc, w["z"], w["u"])
    if not ok:
        return why
    phi, size = val
    out["witness_phi"] = phi
    za, zb = Q(w["z"][0]), Q(w["z"][1])
    out["tags"]["witness at"] = "theta = pi" if (za, zb) == (-1, 0) else ("theta < 1e-3" if abs(zb) < Q(1, 1000) and za > 0 else "interior")
    out["ref_text"] = f"phi at hapstab's (z, u) = {mp.nstr(phi, 25)} (|terms| {mp.nstr(size, 5)}); " + out.get("ref_text", "")
    if phi > mp.mpf(10) ** -40 * size:
        return f"phi = {mp.nstr(phi, 30)} > 0 at hapstab's witness z = {w['z']}, u = {w['u']} (hapstab printed phi = {w['phi']})"
    if phi >= -mp.mpf(10) ** -40 * size:
        return "boundary"
    rel = abs(float(phi) - w["phi"]) / max(abs(float(phi)), 1e-300)
    if rel > 1e-6:
        out["note"] = f"hapstab's phi {w['phi']} against {mp.nstr(phi, 17)} (X_1 scaled?)"
    return None


def decide(c, sc, j, rc):
    """The case's outcome (dict) from hapstab's JSON and the reference."""
    tags = dict(c["tags"])
    out = dict(tags=tags, rc=rc, margin=None)
    ok, why = pinned_identity(sc)
    if not ok:
        out.update(outcome="reference undecided", why="the reference declines: " + why)
        return out
    ref = search(sc)
    tol = mp.mpf(10) ** -25 * ref["scale"]
    mu = ref["mu"]
    out["margin"] = float(mu / ref["scale"])
    tags["reference minimiser"] = ref["where"]
    tags["reference"] = "violated" if mu < -tol else ("holds" if mu > tol else "undecided")
    out["ref_text"] = f"min lambda_min = {mp.nstr(mu, 25)} at theta = {mp.nstr(ref['theta'], 15)} ({ref['where']})"
    h = hapstab_answer(j, rc)
    tags["hapstab"] = h
    out["hapstab"] = f"{h}: {(j.get('certificate') or '')[:160]}"
    if h == "not certified":
        out.update(outcome="undecided", why=(j.get("verdict") or "") + ": " + (j.get("certificate") or "")[:160])
        return out
    if h == "infeasible (witness)":
        bad = verify_witness(sc, j.get("witness"), out)
        tags["witness verified"] = bad is None
        if witness_decides(out, bad):
            return out
    if tags["reference"] == "undecided":
        out.update(outcome="reference undecided", why=f"mu = {mp.nstr(mu, 5)} within the reference's tolerance")
    elif h == "feasible":
        out["outcome"] = "agree" if tags["reference"] == "holds" else "MISS"
        if out["outcome"] == "MISS":
            out["why"] = f"hapstab: (16) feasible, certified; the reference finds phi < 0: {out['ref_text']}"
    elif tags["reference"] == "violated":
        out["outcome"] = "agree"
    elif h == "infeasible (witness)":
        out.update(outcome="REFERENCE MISSED", why="hapstab's witness holds at 50 digits, the reference's search found no violation")
    else:
        out.update(outcome="MISS", why=f"hapstab: {h}, certified; the reference's frequency condition holds: {out['ref_text']}")
    return out


SCENE = Scene  # what independent.py's check_analyze reads a case's text with

if __name__ == "__main__":  # HAPSTAB SCENE [feasible | witness]: one scene through `multidof analyze` and this reference
    sys.exit(analyze_case_main(sys.argv, SCENE, decide))
