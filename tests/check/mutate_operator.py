"""The operator-passivity kind of tests/check/mutate.py (Assumption 1(b) fails:
check/operator_passivity_check.hpp): random 2x2 operators Z(s) in a small scene (two mass-dampers, a
constant wall), each entry N(s)/(s^2 + d s + e) with small integers (d, e > 0: no pole on the axis)
or a constant; a rational w and a principal minor where He Z(jw)'s minor is negative, found here in
exact complex arithmetic of its own (not the checkers'), so the certificate is true; and its mutants
with what must happen (accept / refute / malformed / agree)."""
from fractions import Fraction as F

from cert_edit import with_field

SCENE = """[scene]
name = "operator"
T = "1/100"

[[device]]
name = "a"
m = "1/10"
b = "1"

[[device]]
name = "b"
m = "1/10"
b = "1"

[[operator]]
name = "Z"
dofs = ["a", "b"]
tf = [[%s, %s], [%s, %s]]

[environment]
tf = [["1000", "0"], ["0", "1000"]]
"""


def poly_text(c):  # descending integer coefficients in s
    n = len(c) - 1
    return " + ".join("(%d)*s^%d" % (a, n - i) if n - i > 1 else "(%d)*s" % a if n - i == 1 else "(%d)" % a
                      for i, a in enumerate(c) if a) or "0"


def rand_entry(rng):
    """(text, num, den) with num, den descending integer lists; den = 1 or s^2 + d s + e, d, e > 0."""
    if rng.random() < 0.3:
        k = rng.randint(-5, 5)
        return '"%d"' % k, [k], [1]
    num = [rng.randint(-4, 4) for _ in range(rng.randint(1, 3))]
    if not any(num):
        num = [1]
    den = [1, rng.randint(1, 6), rng.randint(1, 9)]
    return '"(%s)/(%s)"' % (poly_text(num), poly_text(den)), num, den


def at_jw(c, w):  # descending coefficients at s = jw: (re, im)
    re, im = F(0), F(0)
    for a in c:
        re, im = re * 0 - im * w + a, re * w + im * 0
    return re, im


def cdiv(a, b):
    n = b[0] * b[0] + b[1] * b[1]
    return ((a[0] * b[0] + a[1] * b[1]) / n, (a[1] * b[0] - a[0] * b[1]) / n)


def minor(entries, w, rows):
    """det of He Z(jw) on rows (1 or 2 of them), exactly."""
    Z = [[cdiv(at_jw(n, w), at_jw(d, w)) for (_, n, d) in r] for r in entries]
    H = [[((Z[i][j][0] + Z[j][i][0]) / 2, (Z[i][j][1] - Z[j][i][1]) / 2) for j in rows] for i in rows]
    if len(rows) == 1:
        return H[0][0][0]
    return H[0][0][0] * H[1][1][0] - (H[0][1][0] ** 2 + H[0][1][1] ** 2)


def residue_at_zero_fails(entries):
    """Whether Z's residue at s = 0 shows it not positive real (entries "a + k/s" have residue k, the
    others none): R not symmetric, or not positive semidefinite (2x2: a negative diagonal or det)."""
    R = [[F(e[3]) if len(e) > 3 else F(0) for e in r] for r in entries]
    return R[0][1] != R[1][0] or R[0][0] < 0 or R[1][1] < 0 or R[0][0] * R[1][1] - R[0][1] * R[1][0] < 0


def rand_spring_entry(rng):
    """(text, num, den, k): a + k/s, a damper and a spring (k < 0: pushing away), num/den descending."""
    a, k = rng.randint(0, 4), rng.choice([-5, -2, -1, 1, 2, 5])
    return '"%d + (%d)/s"' % (a, k), [a, k], [1, 0], k


def rand_pole_certificate(rng):
    """A true operator-passivity certificate by the residue at s = 0 ({pole: "0"}), or None: entries
    a + k/s on the diagonal (and off it in a third of the draws), constants elsewhere."""
    for _ in range(20):
        off = rng.random() < 0.33
        entries = [[rand_spring_entry(rng), rand_spring_entry(rng) if off else ('"0"', [0], [1])],
                   [rand_spring_entry(rng) if off else ('"0"', [0], [1]), rand_spring_entry(rng)]]
        if residue_at_zero_fails(entries):
            text = SCENE % tuple(e[0] for r in entries for e in r)
            c = {"certificate": "hapstab", "version": 1, "kind": "operator-passivity", "model": {"scene": text, "set": {}},
                 "claim": {"quantity": "Assumption 1(b) for the scene's operator", "status": "exact", "operator": "Z",
                           "passive": False},
                 "evidence": {"pole": "0"}}
            return c, entries
    return None


def pole_mutants(cert, entries, rng):
    """The residue form's mutants: each spring's sign flipped in the scene (this module's own residue
    decides), a double pole written into entry (1, 1) (accept), the pole moved or a witness beside it
    (malformed)."""
    out = [("unmutated", cert, "accept")]
    text = cert["model"]["scene"]
    for i in range(2):
        for j in range(2):
            e = entries[i][j]
            if len(e) > 3:
                flipped = [list(r) for r in entries]
                flipped[i][j] = ('"%d + (%d)/s"' % (e[1][0], -e[3]), [e[1][0], -e[3]], [1, 0], -e[3])
                out.append(("spring (%d,%d) sign flipped" % (i + 1, j + 1),
                            with_field(cert, ["model", "scene"], SCENE % tuple(x[0] for r in flipped for x in r)),
                            "accept" if residue_at_zero_fails(flipped) else "refute"))
    double = [list(r) for r in entries]
    double[0][0] = ('"1/s^2"', [1], [1, 0, 0])
    out += [("entry (1,1) a double pole at 0", with_field(cert, ["model", "scene"], SCENE % tuple(x[0] for r in double for x in r)),
             "accept"),
            ("pole 1", with_field(cert, ["evidence", "pole"], "1"), "malformed"),
            ("a witness w beside the pole", with_field(cert, ["evidence", "w"], "1"), "malformed"),
            ("passive true", with_field(cert, ["claim", "passive"], True), "malformed"),
            ("the scene's operator renamed", with_field(cert, ["model", "scene"], text.replace('name = "Z"', 'name = "Y"')), "malformed")]
    return out


def rand_certificate(rng):
    """A true operator-passivity certificate (a negative minor found on a grid of w; in a fifth of the
    draws the residue at s = 0, rand_pole_certificate), or None."""
    if rng.random() < 0.2:
        return rand_pole_certificate(rng)
    for _ in range(20):
        entries = [[rand_entry(rng), rand_entry(rng)], [rand_entry(rng), rand_entry(rng)]]
        for w in [F(k, 4) for k in range(-20, 21)]:
            for rows in ([0, 1], [0], [1]):
                if minor(entries, w, rows) < 0:
                    text = SCENE % tuple(e[0] for r in entries for e in r)
                    c = {"certificate": "hapstab", "version": 1, "kind": "operator-passivity",
                         "model": {"scene": text, "set": {}},
                         "claim": {"quantity": "Assumption 1(b) for the scene's operator", "status": "exact",
                                   "operator": "Z", "passive": False},
                         "evidence": {"w": str(w), "minor": rows}}
                    return c, entries
    return None


def mutants(cert, entries, rng):
    if "pole" in cert["evidence"]:
        return pole_mutants(cert, entries, rng)
    w, rows = F(cert["evidence"]["w"]), cert["evidence"]["minor"]
    out = [("unmutated", cert, "accept")]
    for name, w2 in (("w + 1/1000", w + F(1, 1000)), ("w random", F(rng.randint(-400, 400), 100)), ("w 0", F(0))):
        if w2 != w:
            out.append((name, with_field(cert, ["evidence", "w"], str(w2)), "accept" if minor(entries, w2, rows) < 0 else "refute"))
    for rows2 in ([0, 1], [0], [1]):
        if rows2 != rows:
            out.append(("minor " + str(rows2), with_field(cert, ["evidence", "minor"], rows2),
                        "accept" if minor(entries, w, rows2) < 0 else "refute"))
    # an entry's denominator made s^2 + w^2: a pole at jw (nothing proven there; the refusal names it)
    if w != 0:
        text = cert["model"]["scene"].replace("tf = [[", "tf = [[\"1/(s^2 + %s)\", " % (w * w), 1)
        first = text.index("\"1/(s^2")
        rest = text.index(", ", text.index("\", ", first) + 3)  # drop the old first entry
        text = text[:text.index("\", ", first) + 3] + text[rest + 2:]
        out.append(("entry (1,1) with a pole at jw", with_field(cert, ["model", "scene"], text), "refute"))
    out += [("operator renamed", with_field(cert, ["claim", "operator"], "Z2"), "malformed"),
            ("passive true", with_field(cert, ["claim", "passive"], True), "malformed"),
            ("status certified", with_field(cert, ["claim", "status"], "certified"), "malformed"),
            ("w a decimal", with_field(cert, ["evidence", "w"], "0.5"), "malformed"),
            ("minor not increasing", with_field(cert, ["evidence", "minor"], [1, 0]), "malformed"),
            ("minor beyond the operator", with_field(cert, ["evidence", "minor"], [0, 2]), "malformed"),
            ("minor empty", with_field(cert, ["evidence", "minor"], []), "malformed"),
            ("evidence.w deleted", {**cert, "evidence": {"minor": rows}}, "malformed"),
            ("a field added to the claim", with_field(cert, ["claim", "omega"], "1"), "malformed"),
            # Z = diag(1 + 1/(s + 1), 1) as ss: He Z(jw) >= I, every minor > 0
            ("the scene's operator a passive ss", with_field(cert, ["model", "scene"], cert["model"]["scene"].split("tf = [[")[0] +
                                                              'ss = { A = [["-1"]], B = [["1", "0"]], C = [["1"], ["0"]], D = [["1", "0"], ["0", "1"]] }\n\n[environment]\ntf = [["1000", "0"], ["0", "1000"]]\n'),
             "refute"),
            # Z = diag(1 - 3/(s + 1), 1) as ss: Re Z11(jw) = 1 - 3/(1 + w^2), negative for w^2 < 2
            ("the scene's operator a non-passive ss", with_field(cert, ["model", "scene"], cert["model"]["scene"].split("tf = [[")[0] +
                                                                  'ss = { A = [["-1"]], B = [["1", "0"]], C = [["-3"], ["0"]], D = [["1", "0"], ["0", "1"]] }\n\n[environment]\ntf = [["1000", "0"], ["0", "1000"]]\n'),
             "accept" if w * w < 2 and rows in ([0], [0, 1]) else "refute")]
    return out
