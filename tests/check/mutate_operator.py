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


def residue_fails(entries, w2):
    """Whether Z's residue at its axis pole s = j w0 (w0^2 = w2; w0 irrational too) shows it not positive real:
    every entry carries its residue e[3] = (re, y) there, Im R = y/w0 (0 for a constant); R (2x2) not Hermitian,
    or not positive semidefinite (a negative diagonal or determinant, |R_12|^2 = re^2 + y^2/w2). Decided here
    from the draw, not by the checkers' code."""
    R = [[e[3] if len(e) > 3 else (F(0), F(0)) for e in r] for r in entries]
    hermitian = R[0][0][1] == 0 and R[1][1][1] == 0 and R[0][1] == (R[1][0][0], -R[1][0][1])
    if not hermitian:
        return True
    im2 = R[0][1][1] ** 2 / w2 if w2 else F(0)
    return R[0][0][0] < 0 or R[1][1][0] < 0 or R[0][0][0] * R[1][1][0] - (R[0][1][0] ** 2 + im2) < 0


def rand_pole_entry(rng, w2, imaginary=False):
    """(text, num, den, residue) with the pole s = j w0, w0^2 = w2: w2 = 0 a + k/s (residue k); w2 > 0 a + k s/(s^2
    + w2) (residue k/2, real) or, `imaginary`, c/(s^2 + w2) (residue c/(2 j w0) = -j c/(2 w0): y = -c/2)."""
    a, k = rng.randint(0, 4), rng.choice([-5, -2, -1, 1, 2, 5])
    if w2 == 0:
        return '"%d + (%d)/s"' % (a, k), None, None, (F(k), F(0))
    if imaginary:
        return '"(%d)/(s^2 + %s)"' % (k, w2), None, None, (F(0), -F(k) / 2)
    return '"%d + (%d)*s/(s^2 + %s)"' % (a, k, w2), None, None, (F(k, 2), F(0))


def a_and_k(entry):
    """(a, k) of a drawn pole entry's text '"a + (k)*s/(s^2 + w2)"'."""
    t = entry[0].strip('"')
    return int(t.split(" ")[0]), int(t.split("(")[1].split(")")[0])


def ss_scene(w2, entries):
    """SCENE with Z = diag(a1 + k1 s/(s^2 + w2), a2 + k2 s/(s^2 + w2)) written as ss (two oscillators)."""
    (a1, k1), (a2, k2) = a_and_k(entries[0][0]), a_and_k(entries[1][1])
    w2 = str(w2)
    return SCENE.split("tf = [[")[0] + (
        'ss = { A = [["0", "1", "0", "0"], ["-%s", "0", "0", "0"], ["0", "0", "0", "1"], ["0", "0", "-%s", "0"]], '
        'B = [["0", "0"], ["1", "0"], ["0", "0"], ["0", "1"]], C = [["0", "%d", "0", "0"], ["0", "0", "0", "%d"]], '
        'D = [["%d", "0"], ["0", "%d"]] }\n\n[environment]\ntf = [["1000", "0"], ["0", "1000"]]\n') % (w2, w2, k1, k2, a1, a2)


def rand_pole_certificate(rng):
    """A true operator-passivity certificate by the residue at the axis pole s = j w0 ({pole: "w0"}, w0
    = 0 in half the draws, else 1, 2 or 3/2; or {pole_squared: "w2"}, w0 = sqrt(2) or sqrt(3), irrational),
    or None: poles on the diagonal, and off it in a third of the draws (w0 > 0: real residues, or an
    imaginary pair c/(s^2 + w2) that is Hermitian only when the two c are opposite), constants elsewhere. In
    a fifth of the w0 > 0 draws a diagonal Z written as ss."""
    zero = ('"0"', [0], [1])
    for _ in range(40):
        w0 = rng.choice([F(0), F(0), F(0), F(1), F(2), F(3, 2), None, None])
        w2 = rng.choice([F(2), F(3)]) if w0 is None else w0 * w0
        off = rng.random() < 0.33
        imag = w2 != 0 and rng.random() < 0.5
        if imag:
            c = rng.choice([-3, -1, 1, 3])
            lo = rand_pole_entry(rng, w2, True)
            if rng.random() < 0.6:  # opposite c: Hermitian
                lo = ('"(%d)/(s^2 + %s)"' % (-c, w2), None, None, (F(0), F(c) / 2))
            hi = ('"(%d)/(s^2 + %s)"' % (c, w2), None, None, (F(0), -F(c) / 2))
        else:
            hi = rand_pole_entry(rng, w2) if off else zero
            lo = rand_pole_entry(rng, w2) if off else zero
        entries = [[rand_pole_entry(rng, w2), hi], [lo, rand_pole_entry(rng, w2)]]
        if not residue_fails(entries, w2):
            continue
        text = SCENE % tuple(e[0] for r in entries for e in r)
        if w2 != 0 and not off and not imag and rng.random() < 0.2:  # the same diagonal Z written as ss
            text = ss_scene(w2, entries)
        c = {"certificate": "hapstab", "version": 1, "kind": "operator-passivity", "model": {"scene": text, "set": {}},
             "claim": {"quantity": "Assumption 1(b) for the scene's operator", "status": "exact", "operator": "Z",
                       "passive": False},
             "evidence": {"pole": str(w0)} if w0 is not None else {"pole_squared": str(w2)}}
        return c, entries
    return None


def pole_mutants(cert, entries, rng):
    """The residue form's mutants: each pole entry's residue negated in the scene (tf: this module's own
    residue decides; ss: its C), a double pole written into entry (1, 1) (accept), the pole moved off
    (refute: no pole there), negative or a witness beside it (malformed)."""
    out = [("unmutated", cert, "accept")]
    text = cert["model"]["scene"]
    key = "pole" if "pole" in cert["evidence"] else "pole_squared"
    w2 = F(cert["evidence"][key]) ** (2 if key == "pole" else 1)
    ss = "ss = {" in text
    for i in range(2):
        for j in range(2):
            e = entries[i][j]
            if len(e) <= 3:
                continue
            flipped = [list(r) for r in entries]
            flipped[i][j] = e[:3] + ((-e[3][0], -e[3][1]),)
            if w2 == 0:
                new_text = '"%s + (%d)/s"' % (e[0].strip('"').split(" ")[0], -int(e[3][0]))
            else:
                k = int(e[0].split("(")[1].split(")")[0])
                new_text = e[0].replace("(%d)" % k, "(%d)" % -k, 1)
            flipped[i][j] = (new_text,) + flipped[i][j][1:]
            if ss and i != j:
                continue
            mutated = ss_scene(w2, flipped) if ss else SCENE % tuple(x[0] for r in flipped for x in r)
            out.append(("residue (%d,%d) negated" % (i + 1, j + 1), with_field(cert, ["model", "scene"], mutated),
                        "accept" if residue_fails(flipped, w2) else "refute"))
    if not ss:
        double = [list(r) for r in entries]
        double[0][0] = ('"1/s^2"', [1], [1, 0, 0]) if w2 == 0 else ('"1/(s^2 + %s)^2"' % w2, None, None)
        out.append(("entry (1,1) a double pole", with_field(cert, ["model", "scene"], SCENE % tuple(x[0] for r in double for x in r)),
                    "accept"))
    moved = str(F(cert["evidence"][key]) + F(1, 3))  # no pole at the moved w0 (or w0^2)
    out += [("pole moved off", with_field(cert, ["evidence", key], moved), "refute"),
            ("pole negative", with_field(cert, ["evidence", key], "-1"), "malformed"),
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
    if "pole" in cert["evidence"] or "pole_squared" in cert["evidence"]:
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
