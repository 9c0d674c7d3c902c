"""The multidof kinds of tests/check/mutate.py (issue 47), multidof-feasible and multidof-witness:
`multidof analyze --scene S --certificate F` on the witness campaign's random scenes
(tests/verify/indep_witness.py's gen: walls K + B(z - 1)/(Tz) with resonances near the circle,
linked walls, contact scenes in s by backward Euler, two independent parts; delays 0-24; device
levels placed 1e-2..1e-6 from Theorem 5's boundary or far from it) and chains of walls linked by
dampers, kept where a certificate was written ((16) feasible: its exact point; infeasible: a
witness), and their mutants with what must happen (mutate.py's accept / refute / malformed / agree)."""
import copy
import json
import os
import subprocess
import sys
from fractions import Fraction

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "verify"))


def damper_chain(rng):
    """2-3 walls K_i + B_i (z - 1)/(T z) (B_i < 0 in half: E lacks passivity) linked by dampers Bc: E(1)
    = diag(K) couples no operators, X has one free direction per DOF, and an infeasible (16) is
    proven by the several-frequency witness (path_kyp_search.cpp)."""
    N = rng.choice([2, 3])
    p = {"Bc": rng.randint(1, 20)}
    for i in range(N):
        p["K%d" % i] = rng.randint(100, 30000)
        p["B%d" % i] = rng.randint(-8, -1) if rng.random() < 0.5 else rng.randint(0, 10)
    rows = []
    for i in range(N):
        links = (i > 0) + (i < N - 1)
        rows.append(["K%d + (B%d + %d*Bc)*(z-1)/(T*z)" % (i, i, links) if i == j else
                     ("-Bc*(z-1)/(T*z)" if abs(i - j) == 1 else "0") for j in range(N)])
    L = ["[scene]", 'name = "damper chain"', 'T = "1/%d"' % rng.choice([100, 1000, 2000]), "", "[parameters]"]
    L += ['%s = "%d"' % kv for kv in p.items()]
    for i in range(N):
        L += ["", "[[device]]", 'name = "d%d"' % i, 'm = "1/10"', 'b = "%d/100"' % rng.randint(1, 3000),
              "", "[[operator]]", 'name = "h%d"' % i, 'dofs = ["d%d"]' % i, 'b = "1"']
    L += ["", "[environment]", "tf = [" + ",\n      ".join("[" + ", ".join('"%s"' % e for e in r) + "]" for r in rows) + "]"]
    n = rng.choice([0, 0, 1, 2])
    if n:
        L += ["", "[delay]", 'samples = "%d"' % n]
    return "\n".join(L) + "\n"


def perturbed_walls(rng):
    """2-3 walls K_i + B_i (z - 1)/(T z) linked by springs kc, one operator on every DOF (G(m; m): X = g I),
    and multidof.perturb_C swapping the outputs of DOFs 0 and 1 (paper 000 Sec. VI's case i): E'(1) is
    not symmetric, so (16) is infeasible by the facial conditions (the multidof-facial kind), or, with
    equal rows, something else."""
    N = rng.choice([2, 3])
    p = {"kc": rng.randint(1, 5000)}
    for i in range(N):
        p["K%d" % i] = rng.randint(100, 30000)
        p["B%d" % i] = rng.randint(0, 10)
    rows = []
    for i in range(N):
        links = (i > 0) + (i < N - 1)
        rows.append(["K%d + B%d*(z-1)/(T*z) + %d*kc" % (i, i, links) if i == j else ("-kc" if abs(i - j) == 1 else "0")
                     for j in range(N)])
    L = ["[scene]", 'name = "perturbed walls"', 'T = "1/%d"' % rng.choice([100, 1000, 2000]), "", "[parameters]"]
    L += ['%s = "%d"' % kv for kv in p.items()]
    for i in range(N):
        L += ["", "[[device]]", 'name = "d%d"' % i, 'm = "1/10"', 'b = "%d/100"' % rng.randint(1, 3000)]
    L += ["", "[[operator]]", 'name = "h"', "dofs = [" + ", ".join('"d%d"' % i for i in range(N)) + "]",
          "tf = [" + ", ".join("[" + ", ".join('"1"' if i == j else '"0"' for j in range(N)) + "]" for i in range(N)) + "]"]
    L += ["", "[environment]", "tf = [" + ",\n      ".join("[" + ", ".join('"%s"' % e for e in r) + "]" for r in rows) + "]"]
    swap = [["1" if j == (1 - i if i < 2 else i) else "0" for j in range(N)] for i in range(N)]
    L += ["", "[multidof]", "perturb_C = [" + ", ".join("[" + ", ".join('"%s"' % x for x in r) + "]" for r in swap) + "]"]
    n = rng.choice([0, 1, 2])
    if n:
        L += ["", "[delay]", 'samples = "%d"' % n]
    return "\n".join(L) + "\n"


def symmetric_scene(rng):
    """A scene of alike DOFs (the symmetry16 campaign's, tests/verify/independent.py: N = 2-32 in 1-3
    classes, delays 0-2): (16) split by multidof/symmetry.hpp, its certificate the lifted point or
    witness, or block by block (multidof-feasible-symmetric) where the lifted order N + m is above 40."""
    import independent
    import indep_loop
    for _ in range(8):  # N >= 12 where a draw allows: a lifted order above 40, the symmetric kind's own
        c = independent.case_symmetry16(rng)
        if len(c["devices"]) >= 12:
            break
    return indep_loop.scene_toml(c)


def produce(hapstab, rng, tmp, i):
    """A certificate of a random scene (every fourth a damper chain, every eighth of alike DOFs), or the
    reason none was written."""
    import indep_witness  # the witness campaign's scene generator (numpy, mpmath: only for this kind)
    text = damper_chain(rng) if i % 4 == 3 else perturbed_walls(rng) if i % 8 == 5 else symmetric_scene(rng) if i % 8 == 1 \
        else indep_witness.gen(rng)["text"]
    scene = os.path.join(tmp, "w%d.toml" % i)
    with open(scene, "w") as f:
        f.write(text)
    path = os.path.join(tmp, "w%d.json" % i)
    # every eighth, and every other scene of alike DOFs: the designed coupling (multidof-coupling[-symmetric])
    command = "design" if i % 8 == 6 or i % 16 == 9 else "analyze"
    try:  # a verdict the structured paths cannot reach falls to the generic SDP: minutes at delay 20+
        p = subprocess.run([hapstab, "multidof", command, "--scene", scene, "--quiet", "--certificate", path],
                           capture_output=True, text=True, timeout=60)
    except subprocess.TimeoutExpired:
        return "over 60 s (the generic SDP)"
    if p.returncode == 2 and "no certificate kind yet" in p.stderr:
        return "decided another way (no kind)"
    if p.returncode == 2 and command == "design" and "no certificate" in p.stderr:
        return "design: no V certified exactly, or beyond Theorem 4's generic program"
    if p.returncode not in (0, 1) or not os.path.exists(path):
        return "exit %d: %s" % (p.returncode, p.stderr.strip().split("error: ", 1)[-1][:60])
    with open(path) as f:
        return json.load(f)


def _set(c, path, value):
    c = copy.deepcopy(c)
    o = c
    for k in path[:-1]:
        o = o[k]
    if value is None:
        del o[path[-1]]
    else:
        o[path[-1]] = value
    return c


def fs(x):
    return str(Fraction(x))


def point_mutants(cert, rng):
    """The several-frequency form's own mutants, then the one-point mutants on its first point."""
    pts = cert["evidence"]["points"]
    m = len(pts[0]["u"])
    out = [("unmutated", cert, "accept")]
    neg = [dict(p, weight=fs(-Fraction(p["weight"]))) if k == 0 else p for k, p in enumerate(pts)]
    out.append(("a weight negated", _set(cert, ["evidence", "points"], neg), "refute"))
    out.append(("every weight 0", _set(cert, ["evidence", "points"], [dict(p, weight="0") for p in pts]), "refute"))
    out.append(("a point's u = 0", _set(cert, ["evidence", "points"],
                                        [dict(p, u=["0"] * m, u_im=["0"] * m) if k == 0 else p for k, p in enumerate(pts)]), "refute"))
    out.append(("a point at z = 1", _set(cert, ["evidence", "points"],
                                         [dict(p, z_re="1", z_im="0") if k == 0 else p for k, p in enumerate(pts)]), "refute"))
    out.append(("points empty", _set(cert, ["evidence", "points"], []), "malformed"))
    out.append(("a weight missing", _set(cert, ["evidence", "points"],
                                         [{a: b for a, b in p.items() if a != "weight"} if k == 0 else p for k, p in enumerate(pts)]),
                "malformed"))
    out.append(("a point with theta", _set(cert, ["evidence", "points"], [dict(pts[0], theta="1")] + pts[1:]), "malformed"))
    out.append(("points beside z_re", _set(cert, ["evidence", "z_re"], "1"), "malformed"))
    out.append(("u_im one short", _set(cert, ["evidence", "points"], [dict(pts[0], u_im=pts[0]["u_im"][:-1])] + pts[1:]), "malformed"))
    out.append(("a point dropped", _set(cert, ["evidence", "points"], pts[1:] or pts), "agree"))
    out.append(("weights x 2 on the first", _set(cert, ["evidence", "points"],
                                                 [dict(p, weight=fs(2 * Fraction(p["weight"]))) if k == 0 else p
                                                  for k, p in enumerate(pts)]), "agree"))
    out.append(("u_im set to u", _set(cert, ["evidence", "points"], [dict(pts[0], u_im=pts[0]["u"])] + pts[1:]), "agree"))
    one = copy.deepcopy(cert)
    p0 = pts[0]
    one["evidence"] = {"z_re": p0["z_re"], "z_im": p0["z_im"], "u": p0["u"], "u_im": p0["u_im"]}
    out += [(n, c, "agree" if e == "accept" else e) for n, c, e in mutants(one, rng)[1:]
            if not n.startswith(("u a decimal", "u one short", "deleted evidence", "added evidence"))]
    return out


def feasible_mutants(cert, rng):
    """A multidof-feasible certificate: (16)'s exact point on a realisation of E-hat."""
    ev, model = cert["evidence"], cert["model"]
    m, N = len(ev["X"]), len(ev["A"])
    out = [("unmutated", cert, "accept")]

    def entry(key, i, j, f):
        M = copy.deepcopy(ev[key])
        M[i][j] = fs(f(Fraction(M[i][j])))
        return _set(cert, ["evidence", key], M)
    out.append(("claim infeasible", _set(cert, ["claim", "feasible"], False), "refute"))
    out.append(("Q_V = 0", _set(cert, ["evidence", "Q_V"], [["0"] * m for _ in range(m)]), "refute"))
    out.append(("g_0 = 1/2", entry("X", 0, 0, lambda x: Fraction(1, 2)), "refute"))
    out.append(("D[0][0] + 1", entry("D", 0, 0, lambda x: x + 1), "refute"))
    out.append(("delay + 1", _set(cert, ["model", "delay"], model["delay"] + 1), "refute"))
    if N:
        out.append(("P[0][0] negated", entry("P", 0, 0, lambda x: -x if x else Fraction(-1)), "refute"))
        out.append(("A[0][0] + 1", entry("A", 0, 0, lambda x: x + 1), "refute"))
        out.append(("P not symmetric", entry("P", 0, N - 1, lambda x: x + 1) if N > 1 else entry("P", 0, 0, lambda x: -x - 1), "refute"))
        out.append(("P x 2", _set(cert, ["evidence", "P"], [[fs(2 * Fraction(x)) for x in r] for r in ev["P"]]), "agree"))
        out.append(("A a row short", _set(cert, ["evidence", "A"], ev["A"][:-1]), "malformed"))
    for key in ("A", "B", "C", "D", "P", "X", "Q_E", "Q_V"):
        out.append(("deleted evidence." + key, _set(cert, ["evidence", key], None), "malformed"))
    for path in (["model", "T"], ["model", "environment"], ["model", "devices"], ["model", "operators"], ["claim", "feasible"]):
        out.append(("deleted " + ".".join(path), _set(cert, path, None), "malformed"))
    out.append(("added evidence.u", _set(cert, ["evidence", "u"], ["1"] * m), "malformed"))
    out.append(("status certified", _set(cert, ["claim", "status"], "certified"), "malformed"))
    out.append(("X a decimal", _set(cert, ["evidence", "X"], [["0.5" if (i, j) == (0, 0) else x for j, x in enumerate(r)]
                                                              for i, r in enumerate(ev["X"])]), "malformed"))
    out.append(("T doubled", _set(cert, ["model", "T"], fs(2 * Fraction(model["T"]))), "agree"))
    out.append(("Q_E x 2", _set(cert, ["evidence", "Q_E"], [[fs(2 * Fraction(x)) for x in r] for r in ev["Q_E"]]), "agree"))
    out.append(("X x 2", _set(cert, ["evidence", "X"], [[fs(2 * Fraction(x)) for x in r] for r in ev["X"]]), "agree"))
    big = [dict(d) for d in model["devices"]]
    for d in big:
        d["osp" if "osp" in d else "b"] = fs(Fraction(d.get("osp", d.get("b"))) * 2)
    out.append(("device levels doubled", _set(cert, ["model", "devices"], big), "agree"))
    for name in list(model.get("set", {}))[:2]:
        v = Fraction(model["set"][name])
        out.append(("set.%s x 1.01" % name, _set(cert, ["model", "set", name], fs(v * Fraction(101, 100))), "agree"))
    return out


def perturb_mutants(cert, m):
    """multidof.perturb_C added to the model (paper 000 Sec. VI: E' = Pi (E - E(inf)) + E(inf)): the
    identity leaves a model without one as it was; a swap of two DOFs makes another model (either verdict,
    the same exit from both checkers: an E'(1) made asymmetric may leave no X > 0, exit 2 for both); a
    wrong size or a decimal is malformed."""
    eye = [["1" if i == j else "0" for j in range(m)] for i in range(m)]
    had = "perturb_C" in cert["model"]["environment"]  # then the identity is another model
    out = [("perturb_C the identity", _set(cert, ["model", "environment", "perturb_C"], eye), "same" if had else "accept"),
           ("perturb_C one row short", _set(cert, ["model", "environment", "perturb_C"], eye[:-1] if m > 1 else [["1", "0"]]), "malformed"),
           ("perturb_C a decimal", _set(cert, ["model", "environment", "perturb_C"],
                                        [["0.5" if (i, j) == (0, 0) else x for j, x in enumerate(r)] for i, r in enumerate(eye)]),
            "malformed")]
    if m >= 2:
        swap = copy.deepcopy(eye)
        swap[0], swap[1] = swap[1], swap[0]
        out.append(("perturb_C swapping DOFs 0 and 1", _set(cert, ["model", "environment", "perturb_C"], swap), "same"))
    return out


def facial_mutants(cert, m):
    """A multidof-facial certificate: no X = diag(g) != 0 makes X E(1) symmetric (the model alone)."""
    model = cert["model"]
    out = [("unmutated", cert, "accept")]
    out.append(("claim feasible", _set(cert, ["claim", "feasible"], True), "refute"))
    out.append(("gain 0", _set(cert, ["model", "environment", "gain"], "0"), "refute"))
    out.append(("one operator per DOF", _set(cert, ["model", "operators"], [[i] for i in range(m)]), "same"))
    if m >= 2:  # E made symmetric: E(1) symmetric, so X = I qualifies
        E = copy.deepcopy(model["environment"]["E"])
        for i in range(m):
            for j in range(i):
                E[i][j] = E[j][i]
        pc = model["environment"].get("perturb_C")
        sym = _set(cert, ["model", "environment", "E"], E)
        out.append(("E made symmetric", _set(sym, ["model", "environment", "perturb_C"], None) if pc else sym, "refute"))
    for path in (["model", "T"], ["model", "environment"], ["model", "devices"], ["model", "operators"], ["claim", "feasible"],
                 ["claim", "status"], ["model", "environment", "E"]):
        out.append(("deleted " + ".".join(path), _set(cert, path, None), "malformed"))
    out.append(("added evidence.u", _set(cert, ["evidence", "u"], ["1"] * m), "malformed"))
    out.append(("status certified", _set(cert, ["claim", "status"], "certified"), "malformed"))
    out.append(("delay + 1", _set(cert, ["model", "delay"], model["delay"] + 1), "accept"))  # E(1) does not see the delay
    return out


def symmetric_mutants(cert, rng):
    """A multidof-feasible-symmetric certificate: the classes, a point per block (the fixed space first)."""
    ev, model = cert["evidence"], cert["model"]
    classes, E = ev["classes"], model["environment"]["E"]
    m = len(E)
    out = [("unmutated", cert, "accept")]
    out.append(("claim infeasible", _set(cert, ["claim", "feasible"], False), "refute"))
    big = [a for a, k in enumerate(classes) if len(k) >= 2]
    i, k = rng.choice(classes[big[0]]) if big else 0, rng.randrange(m)
    edited = copy.deepcopy(E)
    edited[i][k] = "(" + E[i][k] + ") + 1/1000"
    out.append(("E(%d, %d) + 1/1000 (E no longer invariant)" % (i, k), _set(cert, ["model", "environment", "E"], edited), "refute"))
    if len(classes) >= 2:
        a, b = rng.sample(range(len(classes)), 2)
        mixed = copy.deepcopy(classes)
        mixed[a][0], mixed[b][0] = mixed[b][0], mixed[a][0]
        out.append(("classes %d and %d trade a DOF" % (a, b), _set(cert, ["evidence", "classes"], mixed), "same"))
        swapped = copy.deepcopy(classes)
        swapped[a], swapped[b] = swapped[b], swapped[a]
        out.append(("classes %d and %d swapped" % (a, b), _set(cert, ["evidence", "classes"], swapped), "same"))
    levels = [dict(d) for d in model["devices"]]
    if big and len(classes[big[0]]) >= 2:
        d = classes[big[0]][1]  # one device per DOF (alike DOFs are one-DOF devices)
        levels[d]["osp" if "osp" in levels[d] else "b"] = fs(Fraction(levels[d].get("osp", levels[d].get("b"))) + 1)
        out.append(("one level in a class + 1", _set(cert, ["model", "devices"], levels), "refute"))
    fixed = ev["fixed"]
    if fixed["P"]:
        out.append(("fixed P[0][0] negated", _set(cert, ["evidence", "fixed", "P"], [[fs(-Fraction(x)) if (r, c) == (0, 0) else x
                                                                                     for c, x in enumerate(row)] for r, row in enumerate(fixed["P"])]),
                    "refute"))
    out.append(("fixed g_0 = 0", _set(cert, ["evidence", "fixed", "X"], [["0" if (r, c) == (0, 0) else x for c, x in enumerate(row)]
                                                                        for r, row in enumerate(fixed["X"])]), "refute"))
    out.append(("delay + 1", _set(cert, ["model", "delay"], model["delay"] + 1), "refute"))
    if ev["zero_sum"]:
        zs = copy.deepcopy(ev["zero_sum"])
        zs[0]["point"]["Q_V"] = [["0"]]
        out.append(("a zero-sum block's Q_V = 0", _set(cert, ["evidence", "zero_sum"], zs), "refute"))
        zs = copy.deepcopy(ev["zero_sum"])
        zs[0]["point"]["D"] = [[fs(Fraction(zs[0]["point"]["D"][0][0]) + 1)]]
        out.append(("a zero-sum block's D + 1", _set(cert, ["evidence", "zero_sum"], zs), "refute"))
        out.append(("a zero-sum block dropped", _set(cert, ["evidence", "zero_sum"], ev["zero_sum"][1:]), "malformed"))
        zs = copy.deepcopy(ev["zero_sum"])
        zs[0]["class"] = zs[0]["class"] + 1
        out.append(("a zero-sum block's class moved", _set(cert, ["evidence", "zero_sum"], zs), "malformed"))
    for path in (["evidence", "classes"], ["evidence", "fixed"], ["evidence", "zero_sum"], ["model", "operators"], ["claim", "status"]):
        out.append(("deleted " + ".".join(path), _set(cert, path, None), "malformed"))
    out.append(("a DOF in two classes", _set(cert, ["evidence", "classes"], classes + [[0]]), "malformed"))
    out.append(("added evidence.A", _set(cert, ["evidence", "A"], [["0"]]), "malformed"))
    out.append(("perturb_C added", _set(cert, ["model", "environment", "perturb_C"],
                                       [["1" if r == c else "0" for c in range(m)] for r in range(m)]), "malformed"))
    if m >= 2:
        out.append(("operators merged", _set(cert, ["model", "operators"], [list(range(m))]), "malformed"))
    out.append(("gain x 1.01", _set(cert, ["model", "environment", "gain"],
                                   fs(Fraction(101, 100) * Fraction(model["environment"]["gain"]))), "refute"))
    out.append(("T doubled", _set(cert, ["model", "T"], fs(2 * Fraction(model["T"]))), "agree"))
    out.append(("fixed Q_E x 2", _set(cert, ["evidence", "fixed", "Q_E"], [[fs(2 * Fraction(x)) for x in r] for r in fixed["Q_E"]]),
                "agree"))
    return out


def coupling_mutants(cert, rng):
    """A multidof-coupling certificate: (16)'s point and V-hat's storage P_V for the model's coupling V."""
    ev, model = cert["evidence"], cert["model"]
    V = model["coupling"]
    m, n = len(ev["X"]), len(ev["P_V"])
    out = [("unmutated", cert, "accept")]

    def scaled(key, f, where="evidence"):
        M = (ev if where == "evidence" else V)[key]
        return [[fs(f(i, j, Fraction(x))) for j, x in enumerate(r)] for i, r in enumerate(M)]
    out.append(("claim false", _set(cert, ["claim", "theorem4"], False), "refute"))
    out.append(("P_V[0][0] negated", _set(cert, ["evidence", "P_V"], scaled("P_V", lambda i, j, x: -x if (i, j) == (0, 0) else x)),
                "refute"))
    if n > 1:
        out.append(("P_V not symmetric", _set(cert, ["evidence", "P_V"], scaled("P_V", lambda i, j, x: x + 1 if (i, j) == (0, n - 1) else x)),
                    "refute"))
    out.append(("delay + 1", _set(cert, ["model", "delay"], model["delay"] + 1), "refute"))
    out.append(("g_0 = 1/2", _set(cert, ["evidence", "X"], scaled("X", lambda i, j, x: Fraction(1, 2) if (i, j) == (0, 0) else x)), "refute"))
    out.append(("D_V x 2", _set(cert, ["model", "coupling", "D"], scaled("D", lambda i, j, x: 2 * x, "V")), "agree"))
    out.append(("D_V x 1/4", _set(cert, ["model", "coupling", "D"], scaled("D", lambda i, j, x: x / 4, "V")), "agree"))
    out.append(("D_V negated", _set(cert, ["model", "coupling", "D"], scaled("D", lambda i, j, x: -x, "V")), "agree"))
    out.append(("P_V x 2", _set(cert, ["evidence", "P_V"], scaled("P_V", lambda i, j, x: 2 * x)), "agree"))
    out.append(("Q_V x 2", _set(cert, ["evidence", "Q_V"], scaled("Q_V", lambda i, j, x: 2 * x)), "agree"))
    big = [dict(d) for d in model["devices"]]
    for d in big:
        d["osp" if "osp" in d else "b"] = fs(Fraction(d.get("osp", d.get("b"))) * 2)
    out.append(("device levels doubled (K halved)", _set(cert, ["model", "devices"], big), "agree"))
    for path in (["evidence", "P_V"], ["model", "coupling"], ["model", "coupling", "D"], ["claim", "theorem4"], ["evidence", "X"]):
        out.append(("deleted " + ".".join(path), _set(cert, path, None), "malformed"))
    out.append(("coupling.B a row short", _set(cert, ["model", "coupling", "B"], V["B"][:-1] if V["B"] else [["0"] * m]), "malformed"))
    out.append(("P_V a row short", _set(cert, ["evidence", "P_V"], ev["P_V"][:-1]), "malformed"))
    out.append(("added evidence.u", _set(cert, ["evidence", "u"], ["1"] * m), "malformed"))
    out.append(("status certified", _set(cert, ["claim", "status"], "certified"), "malformed"))
    out.append(("D_V a decimal", _set(cert, ["model", "coupling", "D"], [["0.5" if (i, j) == (0, 0) else x for j, x in enumerate(r)]
                                                                       for i, r in enumerate(V["D"])]), "malformed"))
    zero = [dict(d) for d in model["devices"]]
    zero[0]["osp" if "osp" in zero[0] else "b"] = "0"
    out.append(("a device level 0 (K undefined)", _set(cert, ["model", "devices"], zero), "same"))
    return out


def coupling_symmetric_mutants(cert, rng):
    """A multidof-coupling-symmetric certificate: the split's points at the whole's invariant diagonal
    (g, q_E, q_V per class) and one V block with its storage per DOF."""
    ev, model = cert["evidence"], cert["model"]
    r, m = len(ev["classes"]), len(model["coupling_blocks"])
    out = [("unmutated", cert, "accept")]

    def per_class(key, k, f):
        v = list(ev[key])
        v[k] = fs(f(Fraction(v[k])))
        return _set(cert, ["evidence", key], v)
    k = rng.randrange(r)
    out.append(("claim false", _set(cert, ["claim", "theorem4"], False), "refute"))
    out.append(("g[%d] x 2" % k, per_class("g", k, lambda x: 2 * x), "refute"))
    out.append(("q_V[%d] x 3" % k, per_class("q_V", k, lambda x: 3 * x), "refute"))
    out.append(("q_E[%d] + 1" % k, per_class("q_E", k, lambda x: x + 1), "refute"))
    out.append(("g[%d] = 1/2" % k, per_class("g", k, lambda x: Fraction(1, 2)), "refute"))
    i = rng.randrange(m)
    pv = copy.deepcopy(ev["P_V"])
    pv[i][0][0] = fs(-Fraction(pv[i][0][0]))
    out.append(("P_V[%d][0][0] negated" % i, _set(cert, ["evidence", "P_V"], pv), "refute"))
    vb = copy.deepcopy(model["coupling_blocks"])
    vb[i]["D"] = [[fs(2 * Fraction(vb[i]["D"][0][0]))]]
    out.append(("V block %d's D x 2" % i, _set(cert, ["model", "coupling_blocks"], vb), "agree"))
    out.append(("delay + 1", _set(cert, ["model", "delay"], model["delay"] + 1), "refute"))
    out.append(("a V block dropped", _set(cert, ["model", "coupling_blocks"], model["coupling_blocks"][1:]), "malformed"))
    out.append(("a P_V dropped", _set(cert, ["evidence", "P_V"], ev["P_V"][1:]), "malformed"))
    for path in (["evidence", "g"], ["evidence", "q_V"], ["evidence", "fixed"], ["model", "coupling_blocks"], ["claim", "status"]):
        out.append(("deleted " + ".".join(path), _set(cert, path, None), "malformed"))
    out.append(("g one value short", _set(cert, ["evidence", "g"], ev["g"][:-1]), "malformed"))
    out.append(("added evidence.X", _set(cert, ["evidence", "X"], [["1"]]), "malformed"))
    E = copy.deepcopy(model["environment"]["E"])
    a = next((c for c in ev["classes"] if len(c) >= 2), ev["classes"][0])
    E[a[0]][0] = "(" + E[a[0]][0] + ") + 1/1000"
    out.append(("E(%d, 0) + 1/1000" % a[0], _set(cert, ["model", "environment", "E"], E), "refute" if len(a) >= 2 else "agree"))
    return out


def mutants(cert, rng):
    """[(name, certificate, expectation)] of one multidof-feasible(-symmetric), -facial or -witness certificate."""
    if cert["kind"] == "multidof-feasible-symmetric":
        return symmetric_mutants(cert, rng)
    if cert["kind"] == "multidof-coupling":
        return coupling_mutants(cert, rng)
    if cert["kind"] == "multidof-coupling-symmetric":
        return coupling_symmetric_mutants(cert, rng)
    if cert["kind"] == "multidof-facial":
        return facial_mutants(cert, len(cert["model"]["environment"]["E"])) + \
            perturb_mutants(cert, len(cert["model"]["environment"]["E"]))[1:]
    if cert["kind"] == "multidof-feasible":
        return feasible_mutants(cert, rng) + perturb_mutants(cert, len(cert["evidence"]["X"]))
    if "points" in cert["evidence"]:
        return point_mutants(cert, rng)
    ev, model = cert["evidence"], cert["model"]
    m = len(ev["u"])
    out = [("unmutated", cert, "accept")] + perturb_mutants(cert, m)
    zr, zi = Fraction(ev["z_re"]), Fraction(ev["z_im"])
    # refute: the claim or the evidence made false on its face
    zero = _set(cert, ["evidence", "u"], ["0"] * m)
    if "u_im" in ev:
        zero = _set(zero, ["evidence", "u_im"], ["0"] * m)
    out.append(("u = 0", zero, "refute"))
    out.append(("z = 1", _set(_set(cert, ["evidence", "z_re"], "1"), ["evidence", "z_im"], "0"), "refute"))
    out.append(("z off the circle", _set(cert, ["evidence", "z_re"], fs(zr * Fraction(1000001, 1000000))), "refute"))
    out.append(("z conjugated off the circle", _set(cert, ["evidence", "z_im"], fs(zi + Fraction(1, 10 ** 12))), "refute"))
    out.append(("claim feasible", _set(cert, ["claim", "feasible"], True), "refute"))
    big = [dict(d) for d in model["devices"]]
    for d in big:
        d["osp" if "osp" in d else "b"] = fs(Fraction(d.get("osp", d.get("b"))) + 10 ** 15)
    out.append(("device levels raised by 1e15", _set(cert, ["model", "devices"], big), "refute"))
    # malformed: a field deleted or added, a value of the wrong form
    for path in (["model", "T"], ["model", "delay"], ["model", "environment"], ["model", "devices"], ["model", "operators"],
                 ["model", "environment", "E"], ["model", "environment", "gain"], ["model", "environment", "domain"],
                 ["evidence", "u"], ["evidence", "z_re"], ["claim", "feasible"], ["claim", "status"]):
        out.append(("deleted " + ".".join(path), _set(cert, path, None), "malformed"))
    out.append(("added model.frac_delay", _set(cert, ["model", "frac_delay"], "1/2000"), "malformed"))
    out.append(("added evidence.theta", _set(cert, ["evidence", "theta"], "1"), "malformed"))
    out.append(("status certified", _set(cert, ["claim", "status"], "certified"), "malformed"))
    out.append(("T negative", _set(cert, ["model", "T"], "-" + model["T"]), "malformed"))
    out.append(("delay negative", _set(cert, ["model", "delay"], -1), "malformed"))
    out.append(("u a decimal", _set(cert, ["evidence", "u"], ["0.5"] + ev["u"][1:]), "malformed"))
    out.append(("u one short", _set(cert, ["evidence", "u"], ev["u"][:-1]), "malformed"))
    out.append(("method zoh", _set(cert, ["model", "environment", "method"], "zoh"), "malformed"))
    out.append(("domain w", _set(cert, ["model", "environment", "domain"], "w"), "malformed"))
    out.append(("a device one DOF more", _set(cert, ["model", "devices"],
                                              [dict(model["devices"][0], dofs=model["devices"][0]["dofs"] + 1)] + model["devices"][1:]),
                "malformed"))
    out.append(("a DOF in two operators", _set(cert, ["model", "operators"], model["operators"] + [[0]]), "malformed"))
    out.append(("an entry unparsable", _set(cert, ["model", "environment", "E"],
                                            [[e + " *" if (i, j) == (0, 0) else e for j, e in enumerate(r)]
                                             for i, r in enumerate(model["environment"]["E"])]), "malformed"))
    if m >= 2:  # E(1) no longer symmetric: another model (the ratio g_1/g_0 moves, or no X > 0 is left: exit 2)
        E = copy.deepcopy(model["environment"]["E"])
        E[0][1] = "(" + E[0][1] + ") + 1"
        out.append(("E(1) not symmetric", _set(cert, ["model", "environment", "E"], E), "same"))
        merged = [[i for i in range(m)]]
        out.append(("operators merged", _set(cert, ["model", "operators"], merged), "same"))  # may leave no X > 0: exit 2 for both
        split = [[i] for i in range(m)]
        out.append(("operators split", _set(cert, ["model", "operators"], split), "agree"))
    # agree: the model or the evidence moved, the claim unknown: the two checkers must agree
    out.append(("delay + 1", _set(cert, ["model", "delay"], model["delay"] + 1), "agree"))
    out.append(("T doubled", _set(cert, ["model", "T"], fs(2 * Fraction(model["T"]))), "agree"))
    out.append(("gain negated", _set(cert, ["model", "environment", "gain"], fs(-Fraction(model["environment"]["gain"]))), "agree"))
    out.append(("gain x 1.01", _set(cert, ["model", "environment", "gain"], fs(Fraction(101, 100) * Fraction(model["environment"]["gain"]))), "agree"))
    k = rng.randrange(m)
    u = list(ev["u"])
    u[k] = fs(-Fraction(u[k]) if Fraction(u[k]) != 0 else 1)
    out.append(("u[%d] flipped" % k, _set(cert, ["evidence", "u"], u), "agree"))
    out.append(("z conjugated", _set(cert, ["evidence", "z_im"], fs(-zi)), "agree"))
    # another rational point of the circle: t = tan(theta/2) moved by 1e-3 relative
    t = zi / (1 + zr) if zr != -1 else None
    if t is not None and t != 0:
        t2 = t * Fraction(1001, 1000)
        out.append(("z moved along the circle", _set(_set(cert, ["evidence", "z_re"], fs((1 - t2 * t2) / (1 + t2 * t2))),
                                                    ["evidence", "z_im"], fs(2 * t2 / (1 + t2 * t2))), "agree"))
    for name in list(model.get("set", {}))[:3]:
        v = Fraction(model["set"][name])
        same = "perturb_C" in model["environment"]  # E'(1) may leave no X > 0: exit 2, for both
        out.append(("set.%s x 1.01" % name, _set(cert, ["model", "set", name], fs(v * Fraction(101, 100))), "same" if same else "agree"))
    return out


def branches(certs):
    fs_ = [c for k, c in certs if k == "multidof-feasible"]
    ws = [c for k, c in certs if k == "multidof-witness"]
    head = ""
    if fs_:
        head = ("  multidof-feasible branches: DOF 1 %d, 2-4 %d; s-domain %d; delay 0 %d, >= 1 %d; E-hat states <= 10 %d, 11-40 %d, > 40 %d" % (
            sum(1 for c in fs_ if len(c["evidence"]["X"]) == 1), sum(1 for c in fs_ if len(c["evidence"]["X"]) > 1),
            sum(1 for c in fs_ if c["model"]["environment"]["domain"] == "s"),
            sum(1 for c in fs_ if c["model"]["delay"] == 0), sum(1 for c in fs_ if c["model"]["delay"] > 0),
            sum(1 for c in fs_ if len(c["evidence"]["A"]) <= 10), sum(1 for c in fs_ if 10 < len(c["evidence"]["A"]) <= 40),
            sum(1 for c in fs_ if len(c["evidence"]["A"]) > 40)))
    if not ws:
        return head
    return head + ("\n" if head else "") + ("  multidof-witness branches: DOF 1 %d, 2-4 %d; s-domain %d; delay 0 %d, 1 %d, >= 2 %d; z = -1 %d; "
            "several operator groups %d; a declared osp %d; several weighted points %d" % (
                sum(1 for c in ws if len(c["model"]["environment"]["E"]) == 1),
                sum(1 for c in ws if len(c["model"]["environment"]["E"]) > 1),
                sum(1 for c in ws if c["model"]["environment"]["domain"] == "s"),
                sum(1 for c in ws if c["model"]["delay"] == 0), sum(1 for c in ws if c["model"]["delay"] == 1),
                sum(1 for c in ws if c["model"]["delay"] >= 2), sum(1 for c in ws if c["evidence"].get("z_re") == "-1"),
                sum(1 for c in ws if len(c["model"]["operators"]) > 1 and "0" in c["model"]["environment"]["E"][0]),
                sum(1 for c in ws if any("osp" in d for d in c["model"]["devices"])),
                sum(1 for c in ws if "points" in c["evidence"])))
