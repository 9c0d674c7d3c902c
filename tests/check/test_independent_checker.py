#!/usr/bin/env python3
"""checks/hapstab_check.py's `wedge` kind on H(z) whose verdicts, margins and gains are known by hand (below),
its `limit-cycle` kind on first-order loops (class LimitCycle), b* = +inf (class BoundInfinite), its
`stability-max` kind on the mass on a virtual wall with delays 0 and 1 (class StabilityMax), its
`passivity-level-mimo` kind on a diagonal G (the least SISO level, by hand) and a coupled 2x2 (mpmath)
(class PassivityLevelMimo), its multi-DOF kinds of the split and of the designed coupling on their examples
(class MultidofSplitAndCoupling), and its
`stability` kind on loops whose characteristic polynomial and verdict
are known by hand (the same cases as tests/check/test_check.cpp's StabilityCheck, which checks the
C++ checker): the zero-order hold of 1/(m s^2) is T^2 (z + 1)/(2 m (z - 1)^2), of 1/s^3 at T = 1
(z^2 + 4 z + 1)/(6 (z - 1)^3) (tables of z-transforms); the verdicts by Jury's conditions.

    python3 tests/check/test_independent_checker.py        (unittest; ctest check_independent_checker)
    HAPSTAB_CHECK_WITHOUT_GMPY2=1 python3 tests/check/...  the same without gmpy2 (ctest check_independent_checker_fractions)

Wedge by hand: H = K/z gives Re H = K cos(theta), Im H = -K sin(theta), so (25) is
K cos + cot(theta/2) K sin + 1 = K (1 + 2 cos(theta)) + 1 (min 1 - K at theta = pi) and (21)
K cos(theta) + 1 (min 1 - K): both hold iff K < 1; (1 + H)^-1 has its pole at -K.
"""
import copy
import json
import math
import os
import sys
import unittest
from fractions import Fraction

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "checks"))
if os.environ.get("HAPSTAB_CHECK_WITHOUT_GMPY2"):  # the checker's rationals in Python's fractions (no gmpy2 installed):
    sys.modules["gmpy2"] = None                    # ctest check_independent_checker_fractions
import hapstab_check as hc  # noqa: E402


def cert(plant, H, delay, stable, charpoly, T="1/1000"):
    return {"certificate": "hapstab", "version": 1, "kind": "stability",
            "model": {"plant": plant, "H": H, "set": {"m": "1", "K": "1000", "B": "2"}, "T": T, "delay": delay},
            "claim": {"status": "exact", "stable": stable}, "evidence": {"charpoly": charpoly}}


WALL = ["-1/1000", "2001/2000", "-3997/2000", "1"]  # z (z-1)^2 + (T^2/2)(z+1)((K + B/T) z - B/T)


class Rationals(unittest.TestCase):
    def test_the_rationals_are_the_ones_this_run_names(self):
        """gmpy2's mpq where it is installed, Python's fractions where it is not (the same values either way)."""
        if os.environ.get("HAPSTAB_CHECK_WITHOUT_GMPY2"):
            self.assertIs(hc.Fraction, Fraction)
        else:
            import gmpy2
            self.assertIs(hc.Fraction, gmpy2.mpq)
        x = hc.exact_value("-6/4", "x")
        self.assertEqual((x, str(x), x.numerator, x.denominator), (Fraction(-3, 2), "-3/2", -3, 2))
        self.assertEqual(hc.printed_number(" +1.5e2", "x"), 150)  # read by fractions: "+" and exponents as Python reads them
        with self.assertRaises(hc.Malformed):
            hc.printed_number("3 / 4", "x")  # mpq would read it; fractions does not


class Stability(unittest.TestCase):
    def test_one_pole_off_zero_by_hand(self):
        # the lag 1/(s + 1) at T = 1, H = K: c = z - E + K (1 - E), E = e^-1, stable iff K < (1 + E)/(1 - E)
        # = 2.16395341... (test_check.cpp's StabilityCheck.OnePoleOffZeroByHand)
        def cert(K, st):
            return {"certificate": "hapstab", "version": 1, "kind": "stability",
                    "model": {"plant": "1/(s + 1)", "H": "K", "set": {"K": K}, "T": "1", "delay": 0},
                    "claim": {"status": "certified", "stable": st}, "evidence": {}}
        for K, st in (("2", True), ("3", False), ("2163953/1000000", True), ("2163954/1000000", False)):
            self.assertEqual(hc.check(cert(K, st))[0], 0, K)
            self.assertEqual(hc.check(cert(K, not st))[0], 1, K)
        c = cert("2", True)
        c["evidence"]["charpoly"] = ["1", "1"]
        self.assertEqual(hc.check(c)[0], 2)
        c = cert("2", True)
        c["model"]["plant"] = "1/(s^3 + s^2 + s + 1)"  # three poles off s = 0
        self.assertEqual(hc.check(c)[0], 2)

    def test_spring_by_hand(self):
        # 1/(s^2 + 1) at T = 1, H = K: c = z^2 - 2 cos(1) z + 1 + K (1 - cos 1)(z + 1), stable iff -1 < K < 0
        # (test_check.cpp's StabilityCheck.SpringByHand); at K = 0 the roots are on the circle: undecided (3)
        def cert(K, st):
            return {"certificate": "hapstab", "version": 1, "kind": "stability",
                    "model": {"plant": "1/(s^2 + 1)", "H": "K", "set": {"K": K}, "T": "1", "delay": 0},
                    "claim": {"status": "certified", "stable": st}, "evidence": {}}
        for K, st in (("-1/2", True), ("1/1000", False), ("-999/1000", True), ("-1001/1000", False), ("-1/1000000", True)):
            self.assertEqual(hc.check(cert(K, st))[0], 0, K)
            self.assertEqual(hc.check(cert(K, not st))[0], 1, K)
        self.assertEqual(hc.check(cert("0", True))[0], 3)
        # a wall -4 cancels the spring 4 of 1/(s^2 + s + 4): c(1) = det(I - Phi) (1 + H(1) P(0)) = 0 exactly
        for ev in ({}, {"argument_principle": True}):
            c = cert("-4", False)
            c["model"]["plant"], c["evidence"] = "1/(s^2 + s + 4)", ev
            self.assertEqual(hc.check(c)[0], 0, ev)
            c["claim"]["stable"] = True
            self.assertEqual(hc.check(c)[0], 1, ev)

    def test_argument_principle_by_hand(self):
        # the delayed integrator 1/s, T = 1, H = K, n = 50: c = z^50 (z - 1) + K, stable iff 0 < K < 2 sin(pi/202)
        # = 0.0311036238407017... (test_check.cpp's StabilityCheck.ArgumentPrincipleByHand)
        def cert(K, st, status="certified"):
            return {"certificate": "hapstab", "version": 1, "kind": "stability",
                    "model": {"plant": "1/s", "H": "K", "set": {"K": K}, "T": "1", "delay": 50},
                    "claim": {"status": status, "stable": st}, "evidence": {"argument_principle": True}}
        for K, st in (("31/1000", True), ("312/10000", False), ("3110362/100000000", True), ("3110363/100000000", False),
                      ("-1/100", False), ("0", False)):
            self.assertEqual(hc.check(cert(K, st))[0], 0, K)
            self.assertEqual(hc.check(cert(K, not st))[0], 1, K)
        self.assertEqual(hc.check(cert("31/1000", True, "exact"))[0], 2)
        c = cert("31/1000", True)
        c["evidence"]["argument_principle"] = False
        self.assertEqual(hc.check(c)[0], 2)
        # poles off s = 0 (E, Phi in intervals): the verdicts of the no-evidence paths (resultant, interval Schur-Cohn)
        verdicts = []
        for plant in ("1/(s + 1)", "1/(s*(s + 1/2))", "1/(s^2 + s + 4)", "1/(s^2 - 1/4)"):
            for K in ("1/100", "1/5", "3/2"):
                w = cert(K, True)
                w["model"]["plant"], w["model"]["delay"] = plant, 12
                other = dict(w, evidence={})
                st = hc.check(other)[0] == 0
                for c in (w, other):
                    c["claim"] = dict(c["claim"], stable=st)
                    self.assertEqual(hc.check(c)[0], 0, (plant, K, c["evidence"]))
                verdicts.append(st)
        self.assertIn(True, verdicts)
        self.assertIn(False, verdicts)

    def test_interval_schur_cohn(self):
        Iv = hc.Iv
        self.assertEqual(hc.schur_cohn_interval([Iv(-1, -1) * Fraction(1, 2), Iv(1)])[0], True)
        self.assertEqual(hc.schur_cohn_interval([Iv(2), Iv(1)])[0], False)
        self.assertIsNone(hc.schur_cohn_interval([Iv(Fraction(9, 10), Fraction(11, 10)), Iv(1)]))  # |p0| = 1 inside

    def test_schur_cohn_known_roots(self):
        F = Fraction
        self.assertTrue(hc.schur_cohn([F(-1, 2), F(1)])[0])
        self.assertFalse(hc.schur_cohn([F(1), F(1)])[0])                # z = -1
        self.assertTrue(hc.schur_cohn([F(1, 2), F(-1), F(1)])[0])        # (1 +- j)/2
        self.assertFalse(hc.schur_cohn([F(1), F(-5, 2), F(1)])[0])       # 1/2 and 2
        self.assertTrue(hc.schur_cohn([F(3)])[0])

    def test_sampled_mass(self):
        # N = 1, k = 2, T = 1: T^2 (z + 1)/2  ->  Nd ascending [1/2, 1/2]
        self.assertEqual(hc.sampled_device([Fraction(1)], 2, Fraction(1)), [Fraction(1, 2), Fraction(1, 2)])
        self.assertEqual(hc.sampled_device([Fraction(1)], 3, Fraction(1)), [Fraction(1, 6), Fraction(4, 6), Fraction(1, 6)])

    def test_mass_on_a_virtual_wall(self):
        self.assertEqual(hc.check(cert("1/(m*s^2)", "K + B*(z-1)/(T*z)", 0, True, WALL))[0], 0)
        self.assertEqual(hc.check(cert("1/(m*s^2)", "K + B*(z-1)/(T*z)", 0, True, ["2/1000", "-2001/1000", "3997/1000", "-2"]))[0], 0)
        code, why = hc.check(cert("1/(m*s^2)", "K + B*(z-1)/(T*z)", 0, False, WALL))
        self.assertEqual(code, 1)
        self.assertIn("every Schur-Cohn step passes", why)
        code, why = hc.check(cert("1/(m*s^2)", "K + B*(z-1)/(T*z)", 0, True, ["-1/1000", "2001/2000", "-3996/2000", "1"]))
        self.assertEqual(code, 1)
        self.assertIn("z^2", why)
        self.assertEqual(hc.check(cert("1/(m*s^2)", "K + B*(z-1)/(T*z)", 1, True, WALL))[0], 1)

    def test_spring_alone_and_operator_mass(self):
        c = ["2001/2000", "-3999/2000", "1"]
        self.assertEqual(hc.check(cert("1/(m*s^2)", "K", 0, False, c))[0], 0)
        self.assertEqual(hc.check(cert("1/(m*s^2)", "K", 0, True, c))[0], 1)
        op = cert("1/(m*s^2)", "K", 0, False, ["4001/4000", "-7999/4000", "1"])
        op["model"]["operator"] = "m*s"
        self.assertEqual(hc.check(op)[0], 0)

    def test_triple_integrator(self):
        self.assertEqual(hc.check(cert("1/s^3", "1", 0, False, ["-5/6", "22/6", "-17/6", "1"], T="1"))[0], 0)

    def test_refuses_what_it_cannot_model(self):
        for plant, H, field in (("1/(m*s^2 + s)", "K", "pole off s = 0"), ("1/m", "K", "not strictly proper"),
                                ("1/(m*s^2)", "K*z^2", "not causal")):
            code, why = hc.check(cert(plant, H, 0, True, WALL))
            self.assertEqual(code, 2, why)
            self.assertIn(field, why)
        c = cert("1/(m*s^2)", "K", 0, True, WALL)
        c2 = copy.deepcopy(c)
        c2["model"]["frac_delay"] = "1/2000"
        self.assertIn("model.frac_delay", hc.check(c2)[1])
        c2 = copy.deepcopy(c)
        c2["claim"]["stable"] = "yes"
        self.assertIn("claim.stable", hc.check(c2)[1])


WALL_SCENE = open(os.path.join(os.path.dirname(os.path.abspath(__file__)), "fixtures", "scene_mass_wall.toml")).read()  # shared with test_check


def scene_cert(scene, stable, sets=None):
    return {"certificate": "hapstab", "version": 1, "kind": "stability", "model": {"scene": scene, "set": sets or {}},
            "claim": {"status": "exact", "stable": stable}, "evidence": {"charpoly": WALL}}


def same_rf(a, b):
    return hc.trim(hc.pmul(a.num, b.den)) == hc.trim(hc.pmul(b.num, a.den))


class CancelledPoles(unittest.TestCase):
    """A pole the expression writes and cancels on or outside the stable region is a hidden mode as written:
    malformed, except for b* (marginal=True) while H as written is marginally stable. marginally_stable is
    checked on products of factors whose roots are known by construction: z -/+ 1, z^2 - 2 c z + 1 (c rational
    in (-1, 1): a pair on the circle), z - r, and (z - r)(z - 1/r) (a pair off the circle, |r| != 1)."""

    def test_marginally_stable_by_construction(self):
        import random
        g = random.Random(80)
        F = Fraction
        kinds = {"one": ([F(-1), F(1)], "circle"), "minus_one": ([F(1), F(1)], "circle"),
                 "pair": (None, "circle"), "inside": (None, "inside"), "outside": (None, "outside"),
                 "reciprocal": (None, "outside")}
        counts = {True: 0, False: 0}
        for _ in range(400):
            d, on_circle, bad = [F(1)], [], False
            for _ in range(g.randint(1, 4)):
                k = g.choice(list(kinds))
                if k in ("one", "minus_one"):
                    f, key = kinds[k][0], k
                elif k == "pair":
                    c = F(g.randint(-9, 9), 10)
                    f, key = [F(1), -2 * c, F(1)], ("pair", c)
                elif k == "inside":
                    r = F(g.randint(-9, 9), 10)
                    f, key = [-r, F(1)], None
                elif k == "outside":
                    r = F(g.choice([-1, 1]) * g.randint(11, 30), 10)
                    f, key, bad = [-r, F(1)], None, True
                else:
                    r = F(g.choice([-1, 1]) * g.randint(1, 9), 10)
                    f, key, bad = hc.pmul([-r, F(1)], [-1 / r, F(1)]), None, True
                if key is not None:
                    bad = bad or key in on_circle  # a repeated root on the circle
                    on_circle.append(key)
                d = hc.pmul(d, f)
            got = hc.marginally_stable(d)[0]
            self.assertEqual(got, not bad, d)
            counts[got] += 1
        self.assertGreaterEqual(min(counts.values()), 100, counts)

    def test_parse_refuses_or_allows(self):
        T = Fraction(1, 1000)
        for text in ("10*(z-2)/(z-2)", "1/(z-1) - 1/(z-1)", "(z+1)/(z-1)*(z-1)", "(z^2-1)/(z+1)"):
            with self.assertRaises(hc.Malformed, msg=text):
                hc.parse_h(text, T, {})
        with self.assertRaises(hc.Malformed):
            hc.parse_h("s/(s*(s+1))", 0, {}, 's')
        self.assertEqual(hc.parse_h("(z-1/2)/(z-1/2)", T, {}).den, [Fraction(1)])
        self.assertEqual(hc.parse_h("B*(z-1)/(T*(z+1))", T, {"B": Fraction(0)}).num, [])  # a zero gain: no modes
        self.assertEqual(len(hc.parse_h("(z-1)*(1 - z^-9)/(1 - z^-1)", T, {}, marginal=True).den), 9)
        for text in ("(z-1)/(z-1)/(z-1)", "10*(z-2)/(z-2)"):
            with self.assertRaises(hc.Malformed, msg=text):
                hc.parse_h(text, T, {}, marginal=True)


class IntervalArithmetic(unittest.TestCase):
    """hc.Iv (dyadic endpoints, rounded outward to 2^-bits) against Fractions: on random intervals of either
    sign, through zero, exact points, non-dyadic rationals and each of two precisions mixed, every result
    encloses the exact result at every pair of endpoints (the extremes of +, -, *, / are taken there) and at
    a random interior pair, and is at most a few grid steps wider than the exact hull."""

    def test_enclosure(self):
        import random
        rnd = random.Random(75)

        def draw():
            kind = rnd.randrange(5)
            x = Fraction(rnd.randint(-10 ** 6, 10 ** 6), rnd.choice([1, 3, 7, 1 << 20, 10 ** 9 + 7]))
            if kind == 0:
                return x, x
            if kind == 1:  # through zero
                return -abs(x) - Fraction(1, 5), abs(x) + Fraction(1, 9)
            w = Fraction(rnd.randint(0, 10 ** 4), rnd.choice([1, 1 << 30, 10 ** 12]))
            return x, x + w

        saved = hc.Iv.bits
        try:
            for case in range(3000):
                hc.Iv.bits = rnd.choice([60, 128])
                (a, b), (c, d) = draw(), draw()
                X = hc.Iv(a, b)
                hc.Iv.bits = rnd.choice([60, 128])
                Y = hc.Iv(c, d)
                self.assertTrue(X.lo <= a and b <= X.hi and Y.lo <= c and d <= Y.hi)
                t, u = Fraction(rnd.randint(0, 64), 64), Fraction(rnd.randint(0, 64), 64)
                xs, ys = (a, b, a + t * (b - a)), (c, d, c + u * (d - c))
                ops = [(X + Y, lambda p, q: p + q), (X - Y, lambda p, q: p - q), (X * Y, lambda p, q: p * q),
                       (X * c, lambda p, q: p * c), (c * X, lambda p, q: p * c), (c - X, lambda p, q: c - p),
                       (-X, lambda p, q: -p)]
                step = Fraction(1, 2 ** min(60, hc.Iv.bits))
                scale = 1 + max(abs(x) for x in (a, b, c, d)) ** 2
                for R, f in ops:  # the extremes at endpoints: the sampled hull is the exact one
                    vals = [f(p, q) for p in xs for q in ys]
                    self.assertTrue(R.lo <= min(vals) and max(vals) <= R.hi, (case, a, b, c, d))
                    self.assertLessEqual(R.hi - R.lo - (max(vals) - min(vals)), 8 * step * scale, (case, R.lo, R.hi))
                A = X.absolute()
                self.assertTrue(A.lo <= min(abs(p) for p in xs) and max(abs(p) for p in xs) <= A.hi)
                self.assertTrue(A.lo >= 0 if not (a < 0 < b) else A.lo == 0)
                if not (c <= 0 <= d):
                    Q = X / Y
                    self.assertTrue(all(Q.lo <= p / q <= Q.hi for p in xs for q in ys), (case, a, b, c, d))
                else:
                    with self.assertRaises(ZeroDivisionError):
                        X / Y
        finally:
            hc.Iv.bits = saved


    def test_positive_definite(self):
        """hc.semidefinite(., True) (Sylvester by Bareiss on integers) against the leading minors by Fraction
        elimination (written here), on B^T B + c I with c of either sign and 0 (singular PSD at rank-deficient
        B), non-dyadic entries, orders 1-12."""
        import random
        rnd = random.Random(76)

        def det(A):
            A, d = [list(r) for r in A], Fraction(1)
            for k in range(len(A)):
                piv = next((i for i in range(k, len(A)) if A[i][k] != 0), None)
                if piv is None:
                    return Fraction(0)
                if piv != k:
                    A[k], A[piv], d = A[piv], A[k], -d
                d *= A[k][k]
                for i in range(k + 1, len(A)):
                    f = A[i][k] / A[k][k]
                    A[i] = [x - f * y for x, y in zip(A[i], A[k])]
            return d
        seen = set()
        for _ in range(400):
            n, m = rnd.randint(1, 12), rnd.randint(1, 12)
            B = [[Fraction(rnd.randint(-9, 9), rnd.choice([1, 3, 8])) for _ in range(n)] for _ in range(m)]
            c = rnd.choice([Fraction(0), Fraction(rnd.randint(-30, 30), rnd.choice([1, 7, 1024]))])
            A = [[sum(B[k][i] * B[k][j] for k in range(m)) + (c if i == j else 0) for j in range(n)] for i in range(n)]
            want = all(det([row[:k] for row in A[:k]]) > 0 for k in range(1, n + 1))
            self.assertEqual(hc.semidefinite(A, True), want, (A, c))
            seen.add(want)
        self.assertEqual(seen, {True, False})


class Lexer(unittest.TestCase):
    def test_tokens_and_what_is_refused(self):
        """hc.lex (a regular expression since stop 75) on the forms the char-by-char lexer before it gave: an
        exponent only with digits after it, dotted runs as one number; non-ASCII characters, Unicode digits and
        whitespace beyond C's isspace are refused by name, as hapstab's lexer (lti/parse.cpp) refuses them."""
        self.assertEqual(hc.lex("1.5e-3*z^-2 + K_1"), [('num', '1.5e-3'), ('*', '*'), ('name', 'z'), ('^', '^'), ('-', '-'),
                                                     ('num', '2'), ('+', '+'), ('name', 'K_1'), ('end', '')])
        self.assertEqual(hc.lex("1e+ x"), [('num', '1'), ('name', 'e'), ('+', '+'), ('name', 'x'), ('end', '')])
        self.assertEqual(hc.lex("1.2.3e4x\t\n"), [('num', '1.2.3e4'), ('name', 'x'), ('end', '')])
        self.assertEqual(hc.lex(" \x0b\x0c"), [('end', '')])
        for bad in ("1\x1c", "\u00a0 1", "\u0663", "x\u00b2", "1 $ 2", "a,b"):
            with self.assertRaises(hc.Malformed) as e:
                hc.lex(bad)
            self.assertIn("unexpected character", str(e.exception))


class ModelText(unittest.TestCase):
    """A parameter named T, and decimal exponents beyond 6 digits, are refused by name (exit 2), as hapstab check
    refuses them (stop 87's review: model.set.T = 1 made H read T = 1 while the objective used model.T, and a
    certificate with the claim verified; 1e999999999 kept the checker writing out 10^999999999 for hours)."""

    def wall(self):
        path = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "examples", "certificates", "wall-delay1.json")
        with open(path) as f:
            return json.load(f)

    def test_the_example_is_verified(self):
        self.assertEqual(hc.check(self.wall())[0], 0)

    def test_a_parameter_named_T_is_malformed(self):
        c = self.wall()
        c["model"]["set"]["T"] = "1"
        code, why = hc.check(c)[:2]
        self.assertEqual(code, 2, why)
        self.assertIn("model.set.T", why)

    def test_huge_exponents_are_malformed_at_once(self):
        for where in ("printed", "H"):
            c = self.wall()
            if where == "printed":
                c["claim"]["printed"] = "1e999999999"
            else:
                c["model"]["H"] += " + 0*1e999999999"
            code, why = hc.check(c)[:2]
            self.assertEqual(code, 2, (where, why))
            self.assertIn("1e999999999", why)
        self.assertEqual(hc.text_fraction("25e-000001"), Fraction(5, 2))  # six digits or fewer: read as written
        self.assertEqual(hc.text_fraction("1e999999") * 0, 0)


class SceneModel(unittest.TestCase):
    """test_mass_on_a_virtual_wall's loop written as a one-DOF scene (the C++ StabilityCheck.SceneByHand)."""

    def test_by_hand(self):
        one = {"k": "1"}
        self.assertEqual(hc.check(scene_cert(WALL_SCENE, True, one))[0], 0)
        self.assertEqual(hc.check(scene_cert(WALL_SCENE, False, one))[0], 1)
        self.assertEqual(hc.check(scene_cert(WALL_SCENE, True))[0], 1)  # k = 7: another loop
        m = hc.scene_loop_model(scene_cert(WALL_SCENE, True, one)["model"])
        self.assertEqual((m["plant"], m["T"], m["delay"]), ("1/((1)*s^2 + (0)*s)", "1/1000", 0))
        self.assertTrue(same_rf(hc.parse_h(m["H"], Fraction(1, 1000), {}), hc.parse_h("1000 + 2*(z-1)/(T*z)", Fraction(1, 1000), {})))

    def test_tustin_operator_and_delay(self):
        s = WALL_SCENE.replace('tf = "K + B*(z-1)/(T*z)"', 'domain = "s"\nmethod = "tustin"\ntf = "K + B*s"\n[delay]\ntime = "2*T"')
        s += '[[operator]]\ndofs = "arm"\nm = "1/10"\nk = "40"\n'
        m = hc.scene_loop_model(scene_cert(s, True)["model"])
        T = Fraction(1, 1000)
        self.assertTrue(same_rf(hc.parse_h(m["H"], T, {}), hc.parse_h("7000 + 2*(2*(z-1)/(T*(z+1)))", T, {})))
        self.assertTrue(same_rf(hc.parse_h(m["operator"], T, {}, 's'), hc.parse_h("s/10 + 40/s", T, {}, 's')))
        self.assertFalse(same_rf(hc.parse_h(m["H"], T, {}), hc.parse_h("7000 + 2*((z-1)/(T*z))", T, {})))
        self.assertEqual(m["delay"], 2)

    def test_refuses_by_name(self):
        one = {"k": "1"}
        for text, sets, field in ((WALL_SCENE + '[coupling]\ntf = "1"\n', one, "[coupling]"),
                                  (WALL_SCENE + "[contact]\n", one, "[contact]"),
                                  (WALL_SCENE + '[delay]\nsamples = "3/2"\n', one, "not a whole number"),
                                  (WALL_SCENE + '[[device]]\nname = "second"\nm = "1"\n', one, "2 tables"),
                                  (WALL_SCENE, {"kk": "1"}, "model.set.kk"),
                                  (WALL_SCENE.replace('k = "7"', 'k = "K"'), {}, "cycle"),
                                  (WALL_SCENE.replace('m = "1"', 'ss = { A = [["0"]], B = [["1"]], C = [["1"]], D = [["0"]] }'),
                                   one, "device.ss"),
                                  ('[scene]\nT = "1/1000"\n', {}, "[[device]]"),
                                  ("not toml = = 1", one, "not TOML")):
            code, why = hc.check(scene_cert(text, True, sets))
            self.assertEqual(code, 2, why)
            self.assertIn(field, why)


LOOP_SCENE = '[scene]\nT = "1/10"\n[[device]]\nname = "a"\nm = "2"\n[environment]\ntf = "100"\n'


def loop_cert(scene, stable, P, w=None):
    c = {"certificate": "hapstab", "version": 1, "kind": "stability-loop", "model": {"scene": scene, "set": {}},
         "claim": {"status": "certified", "stable": stable}, "evidence": {"P": P}}
    if w is not None:
        c["evidence"]["w"] = w
    return c


class StabilityLoopMax(unittest.TestCase):
    """test_check.cpp's StabilityLoopMaxCheck.ReadingOfTheGain: the parameter must be the whole gain of one
    block, named nowhere else, without a value, the loop without a feedthrough product; P = I proves nothing."""

    def cert(self, gain="g", coupling="1/(1000*z)", name="g", sets=None, tf="100"):
        scene = ('[scene]\nT = "1/100"\n[parameters]\ng = "1"\n[[device]]\nname = "a"\nm = "1"\nb = "2"\n[[operator]]\n'
                 'name = "h"\ndofs = ["a"]\nk = "10"\n[environment]\ngain = "%s"\ntf = "%s"\n[coupling]\ntf = "%s"\n' % (gain, tf, coupling))
        I3 = [["1", "0", "0"], ["0", "1", "0"], ["0", "0", "1"]]
        return {"certificate": "hapstab", "version": 1, "kind": "stability-loop-max",
                "model": {"scene": scene, "set": sets or {}, "name": name},
                "claim": {"status": "certified", "lo": "1", "hi": "2"},
                "evidence": {"cover": [{"to": "1", "P": I3}], "unstable_at": {"at": "2", "P": I3, "w": ["1", "0", "0"]}}}

    def test_reading_of_the_gain(self):
        code, why = hc.check(self.cert())
        self.assertEqual(code, 1, why)
        self.assertIn("w^T P w", why)
        c = self.cert()
        c["evidence"]["unstable_at"]["P"] = [["-1", "0", "0"], ["0", "1", "0"], ["0", "0", "1"]]
        self.assertEqual(hc.check(c)[0], 1)
        for bad in (self.cert(name="q"), self.cert(gain="2*g"), self.cert(coupling="g/(1000*z)"), self.cert(sets={"g": "1"}),
                    self.cert(coupling="1/1000")):
            self.assertEqual(hc.check(bad)[0], 2, hc.check(bad)[1])
        c = self.cert()
        c["evidence"]["unstable_at"]["at"] = "3"
        self.assertEqual(hc.check(c)[0], 2)
        c = self.cert()
        del c["evidence"]["cover"]
        self.assertEqual(hc.check(c)[0], 2)
        code, why = hc.check(self.cert(gain="1", tf="100*g"))  # g inside the wall's tf: read, then refuted
        self.assertEqual(code, 1, why)
        self.assertIn("w^T P w", why)
        for bad in (self.cert(gain="1", tf="100*g*g"), self.cert(tf="100*g"), self.cert(gain="1", tf="100*g", coupling="g/(1000*z)"),
                    self.cert(gain="1", tf="(z-g)*100/(z-1)")):
            self.assertEqual(hc.check(bad)[0], 2, hc.check(bad)[1])
        c = self.cert()  # a first-order start where the spring holds the position at g = 0: beyond the kind
        c["evidence"]["first_order"] = {"to": "1/2", "P0": [["1", "0", "0"], ["0", "1", "0"], ["0", "0", "1"]], "S": []}
        self.assertEqual(hc.check(c)[0], 2)


class CircleCrossing(unittest.TestCase):
    """circle_crossing_free (evidence no_crossing) on the families of tests/lti/test_circle_crossing.cpp, whose
    crossings are known by hand: lambda = 1 - p (on the circle at p = 2), a Jordan block at z = 1 under a damped
    spring (Jury: stable exactly for 0 < p < 4/3), det 1 + p/2 (constant inertia, unstable: the caller proves M(a)
    stable), a rotation p does not move (R = 0 for every p)."""

    def F(self, rows):
        return [[Fraction(x) for x in r] for r in rows]

    def test_hand_families(self):
        self.assertEqual(hc.circle_crossing_free(self.F([[1]]), self.F([[-1]]), Fraction(199, 100)), "")
        self.assertNotEqual(hc.circle_crossing_free(self.F([[1]]), self.F([[-1]]), Fraction(2)), "")
        J, D = self.F([[1, 1], [0, 1]]), self.F([[0, 0], [-1, -2]])
        self.assertEqual(hc.circle_crossing_free(J, D, Fraction(13, 10)), "")
        self.assertNotEqual(hc.circle_crossing_free(J, D, Fraction(3, 2)), "")
        self.assertEqual(hc.circle_crossing_free(J, self.F([[0, 0], [-1, Fraction(-1, 2)]]), Fraction(1)), "")
        self.assertIn("every p", hc.circle_crossing_free(self.F([[0, -1], [1, 0]]), self.F([[0, 0], [0, 0]]), Fraction(1)))

    def test_resultant_and_descartes(self):
        # Res(z - 2, z - 3) = -1; Res(z^2 - 1, z + 1) = 0; (p - 1)(p - 3): a root in (0, 2], none in (0, 1/2]
        self.assertEqual(hc.resultant([-2, 1], [-3, 1]), -1)
        self.assertEqual(hc.resultant([-1, 0, 1], [1, 1]), 0)
        R = [Fraction(3), Fraction(-4), Fraction(1)]
        self.assertIs(hc.no_root_in(R, Fraction(1, 2)), True)
        self.assertIs(hc.no_root_in(R, Fraction(2)), False)
        self.assertIs(hc.no_root_in([Fraction(1), Fraction(0), Fraction(1)], Fraction(10)), True)  # p^2 + 1


class StabilityLoopMaxPlant(unittest.TestCase):
    """test_check.cpp's StabilityLoopMaxCheck.PlantModelReading: K read inside the one-DOF model's H."""

    def cert(self, plant="1/(s^2+2*s)", H="K + 5*(z-1)/(T*z)", sets=None):
        I3 = [["1", "0", "0"], ["0", "1", "0"], ["0", "0", "1"]]
        return {"certificate": "hapstab", "version": 1, "kind": "stability-loop-max",
                "model": {"plant": plant, "H": H, "T": "1/1000", "delay": 0, "set": sets or {}, "name": "K"},
                "claim": {"status": "certified", "lo": "1", "hi": "2"},
                "evidence": {"cover": [{"to": "1", "P": I3}], "unstable_at": {"at": "2", "P": I3, "w": ["1", "0", "0"]}}}

    def test_plant_model_reading(self):
        code, why = hc.check(self.cert())
        self.assertEqual(code, 1, why)
        self.assertIn("w^T P w", why)
        mixed = self.cert()
        mixed["model"]["scene"] = '[scene]\nT = "1/1000"\n'
        for bad in (self.cert(plant="1/(s^2+2*s+0*K)"), self.cert(H="5*(z-1)/(T*z)"), self.cert(H="K*K + 5*(z-1)/(T*z)"),
                    self.cert(sets={"K": "1"}), mixed):
            self.assertEqual(hc.check(bad)[0], 2, hc.check(bad)[1])


class StabilityLoop(unittest.TestCase):
    """The C++ StabilityLoopCheck tests: a mass m = 2 under a spring wall K = 100 at T = 1/10, M =
    [[1, -5], [1/10, 3/4]] by hand (NOT stable: det M = 5/4), and an exact P with P - M^T P M = I."""
    P = [["-1461/800", "29/40"], ["29/40", "-229/2"]]

    def test_hold_beyond_the_limit(self):
        # test_check.cpp's StabilityLoopCheck.HoldBeyondTheLimit: T = 10^118 s, |A T| far beyond 4096
        with open(os.path.join(os.path.dirname(os.path.abspath(__file__)), "fixtures", "beyond_stability_loop_hold.json")) as f:
            code, why = hc.check(hc.json.load(f))
        self.assertEqual(code, 3)
        self.assertIn("the hold e^{AT}", why)

    def test_hidden_mode_of_continuous_blocks_by_hand(self):
        # test_check.cpp's StabilityLoopCheck.HiddenModeOfContinuousBlocksByHand: A_h = [[0, 1], [a, c]] hidden in
        # an ss device: +-2j and +-2 verified, damped refuted, s^2 (a Jordan block at 0) verified; an ss operator's
        # uncontrollable s = 1
        def device(a, c, name="d"):
            scene = ('[scene]\nT = "1/1000"\n[[device]]\nname = "d"\nss = { A = [["-10", "0", "0"], ["0", "0", "1"], '
                     '["0", "%s", "%s"]], B = [["1"], ["0"], ["0"]], C = [["1", "0", "0"]], D = [["0"]] }\npassive = false\n'
                     '[environment]\ntf = "2000"\n' % (a, c))
            return {"certificate": "hapstab", "version": 1, "kind": "stability-loop", "model": {"scene": scene, "set": {}},
                    "claim": {"status": "exact", "stable": False},
                    "evidence": {"hidden": {"block": "device", "name": name, "kind": "uncontrollable",
                                            "basis": [["0", "1", "0"], ["0", "0", "1"]], "A_h": [["0", "1"], [a, c]]}}}
        for a in ("-4", "4"):
            code, why = hc.check(device(a, "0"))
            self.assertEqual(code, 0, why)
            self.assertIn("Hurwitz", why)
        self.assertEqual(hc.check(device("-4", "-1"))[0], 1)
        code, why = hc.check(device("0", "0"))  # s^2: a Jordan block at s = 0 (a hidden ramp): NOT stable since stop 89
        self.assertEqual(code, 0, why)
        self.assertIn("Jordan block", why)
        self.assertEqual(hc.check(device("0", "-1"))[0], 1)  # s (s + 1): s = 0 simple, nothing shown
        self.assertEqual(hc.check(device("-4", "0", "e"))[0], 2)
        c = device("-4", "0")
        del c["evidence"]["hidden"]["name"]
        self.assertEqual(hc.check(c)[0], 2)
        scene = ('[scene]\nT = "1/1000"\n[[device]]\nname = "d"\nm = "1"\nb = "30"\n[[operator]]\nname = "hand"\ndofs = ["d"]\n'
                 'ss = { A = [["-1", "0"], ["0", "1"]], B = [["1"], ["0"]], C = [["1", "1"]], D = [["2"]] }\n[environment]\ntf = "2000"\n')
        op = {"certificate": "hapstab", "version": 1, "kind": "stability-loop", "model": {"scene": scene, "set": {}},
              "claim": {"status": "exact", "stable": False},
              "evidence": {"hidden": {"block": "operator", "name": "hand", "kind": "uncontrollable", "basis": [["0", "1"]], "A_h": [["1"]]}}}
        self.assertEqual(hc.check(op)[0], 0)
        op["evidence"]["hidden"]["A_h"] = [["-1"]]
        self.assertEqual(hc.check(op)[0], 1)

    def test_hidden_mode_by_hand(self):
        # test_check.cpp's StabilityLoopCheck.HiddenModeByHand: a wall with an ss coupling A = diag(1/2, a),
        # B = (1/10000, b)', C = (1, c); b = 0: W = (0, 1) uncontrollable, A_h = a; c = 0: V = (0, 1)' unobservable
        def cert(a, b, c, kind, basis, ah):
            scene = ('[scene]\nT = "1/1000"\n[[device]]\nname = "d"\nm = "1"\nb = "30"\n[environment]\ntf = "100"\n'
                     '[coupling]\nss = { A = [["1/2", "0"], ["0", "%s"]], B = [["1/10000"], ["%s"]], C = [["1", "%s"]], D = [["0"]] }\n'
                     % (a, b, c))
            return {"certificate": "hapstab", "version": 1, "kind": "stability-loop", "model": {"scene": scene, "set": {}},
                    "claim": {"status": "exact", "stable": False},
                    "evidence": {"hidden": {"block": "coupling", "kind": kind, "basis": basis, "A_h": [[ah]]}}}
        row, col = [["0", "1"]], [["0"], ["1"]]
        for a in ("-1", "3/2"):
            code, why = hc.check(cert(a, "0", "1", "uncontrollable", row, a))
            self.assertEqual(code, 0, why)
        self.assertEqual(hc.check(cert("-1", "1", "0", "unobservable", col, "-1"))[0], 0)
        self.assertEqual(hc.check(cert("1", "0", "1", "uncontrollable", row, "1"))[0], 1)
        self.assertEqual(hc.check(cert("1/2", "0", "1", "uncontrollable", row, "1/2"))[0], 1)
        self.assertEqual(hc.check(cert("-1", "0", "1", "uncontrollable", row, "3/2"))[0], 1)
        self.assertEqual(hc.check(cert("-1", "1", "1", "uncontrollable", row, "-1"))[0], 1)
        self.assertEqual(hc.check(cert("-1", "1", "1", "unobservable", col, "-1"))[0], 1)
        self.assertEqual(hc.check(cert("-1", "0", "1", "uncontrollable", [["0", "0"]], "-1"))[0], 1)
        self.assertEqual(hc.check(cert("-1", "0", "1", "uncontrollable", col, "-1"))[0], 2)
        c = cert("-1", "0", "1", "uncontrollable", row, "-1")
        c["claim"]["status"] = "certified"
        self.assertEqual(hc.check(c)[0], 2)
        c = cert("-1", "0", "1", "uncontrollable", row, "-1")
        c["claim"]["stable"] = True
        self.assertEqual(hc.check(c)[0], 2)
        c = cert("-1", "0", "1", "uncontrollable", row, "-1")
        c["evidence"]["hidden"]["block"] = "environment"
        self.assertEqual(hc.check(c)[0], 2)
        c = cert("-1", "0", "1", "uncontrollable", row, "-1")
        c["evidence"]["P"] = [["1"]]
        self.assertEqual(hc.check(c)[0], 2)

    def test_closed_loop_by_hand(self):
        M = hc.loop_matrix(hc.scene_loop_read({"scene": LOOP_SCENE, "set": {}}), 128)
        want = [[Fraction(1), Fraction(-5)], [Fraction(1, 10), Fraction(3, 4)]]
        for i in range(2):
            for j in range(2):
                self.assertTrue(M[i][j].lo <= want[i][j] <= M[i][j].hi)
                self.assertLess(M[i][j].hi - M[i][j].lo, Fraction(1, 10 ** 9))
        D = hc.loop_matrix(hc.scene_loop_read({"scene": LOOP_SCENE + '[delay]\nsamples = 1\n', "set": {}}), 128)
        self.assertEqual(len(D), 3)
        self.assertEqual(D[2][1].lo, -100)
        # the same device as ss (the velocity its state): the same M; as tf = "1/(2*s)" (state 2 v): M in that basis
        for dev, M2 in (('ss = { A = [["0"]], B = [["1/2"]], C = [["1"]], D = [["0"]] }', want),
                        ('tf = "1/(2*s)"', [[Fraction(1), Fraction(-10)], [Fraction(1, 20), Fraction(3, 4)]])):
            Mo = hc.loop_matrix(hc.scene_loop_read({"scene": LOOP_SCENE.replace('m = "2"', dev), "set": {}}), 128)
            for i in range(2):
                for j in range(2):
                    self.assertTrue(Mo[i][j].lo <= M2[i][j] <= Mo[i][j].hi, dev)
        Cp = hc.loop_matrix(hc.scene_loop_read({"scene": LOOP_SCENE + '[coupling]\ntf = "1/100"\n', "set": {}}), 128)
        coupled = [[Fraction(1), Fraction(-5, 2)], [Fraction(1, 10), Fraction(7, 8)]]  # u = -K/(1 + K V) x = -50 x
        for i in range(2):
            for j in range(2):
                self.assertTrue(Cp[i][j].lo <= coupled[i][j] <= Cp[i][j].hi)

    def test_stein_by_hand(self):
        self.assertEqual(hc.check(loop_cert(LOOP_SCENE, False, self.P, ["1", "0"]))[0], 0)
        self.assertEqual(hc.check(loop_cert(LOOP_SCENE, True, self.P))[0], 1)
        damped = LOOP_SCENE.replace('m = "2"', 'm = "2"\nb = "40"')
        self.assertEqual(hc.check(loop_cert(damped, False, self.P, ["1", "0"]))[0], 1)
        for edit, field in (("[contact]\n", "[contact]"), ('[passivity_controller]\ndofs = [0]\n', "[passivity_controller]"),
                            ('[[device]]\nname = "b"\nm = "1"\ncount = 65\n', "65 copies, more than 64")):
            code, why = hc.check(loop_cert(LOOP_SCENE + edit, False, self.P, ["1", "0"]))
            self.assertEqual(code, 2, why)
            self.assertIn(field, why)

    def test_plant_model_by_hand(self):
        # test_check.cpp's StabilityLoopCheck.PlantModelByHand: P = 1/(2 s^2), H = 100 at T = 1/10 as
        # the closed-loop matrix of G = s P = 1/(2 s): [[1, -10], [1/20, 3/4]]
        model = {"plant": "1/(2*s^2)", "H": "100", "set": {}, "T": "1/10", "delay": 0}
        M = hc.loop_matrix(hc.scene_loop_read(model), 128)
        want = [[Fraction(1), Fraction(-10)], [Fraction(1, 20), Fraction(3, 4)]]
        for i in range(2):
            for j in range(2):
                self.assertTrue(M[i][j].lo <= want[i][j] <= M[i][j].hi)
        # no pole at s = 0 (test_check.cpp's trace): P = 1/(s + 1)^3, the position integrated here,
        # this checker's own conserved quantity set aside: 3 states, trace 3 e^-T - K y(T)
        spring = dict(model, plant="1/(s + 1)^3")
        A, B, _ = hc.loop_plant(*hc.scene_loop_read(spring)[2:7])
        L, at = hc.conserved_quantities(A, B)
        self.assertEqual((len(at), hc.own_conserved(spring), hc.own_conserved(model)), (1, 1, 0))
        S = hc.quotient(hc.loop_matrix(hc.scene_loop_read(spring), 128), L, at)
        self.assertEqual(len(S), 3)
        t = 0.1
        trace = 3 * math.exp(-t) - 100 * (1 - math.exp(-t) * (1 + t + t * t / 2))
        self.assertAlmostEqual(float(sum(S[i][i].lo for i in range(3))), trace, places=12)
        self.assertAlmostEqual(float(sum(S[i][i].hi for i in range(3))), trace, places=12)
        for plant, why in (("1/(s + 1)", "relative degree below 2"), ("1/s", "relative degree below 2")):
            with self.assertRaises(hc.Malformed) as e:
                hc.scene_loop_read(dict(model, plant=plant))
            self.assertIn(why, str(e.exception))
        c = loop_cert(LOOP_SCENE, False, self.P, ["1", "0"])
        c["model"] = dict(model, plant="1/(2*s^2)")
        # the hand loop in the basis (2 v, x): P' = S P S, S = diag(1/2, 1), proves it NOT stable the same way
        c["evidence"]["P"] = [["-1461/3200", "29/80"], ["29/80", "-229/2"]]
        code, why = hc.check(c)
        self.assertEqual(code, 0, why)

    def test_conserved_quantities_by_hand(self):
        # test_check.cpp's StabilityLoopCheck.ConservedQuantitiesByHand: an operator spring k = 10 as
        # tf "10/s" or ss (zeta' = v: zeta - x constant), the device as ss with its own position state:
        # one conserved quantity each, and on the quotient the loop written without it
        def plant_M(scene):
            loop = hc.scene_loop_read({"scene": scene, "set": {}})
            L, at = hc.conserved_quantities(*hc.loop_plant(*loop[2:7])[:2])
            return hc.quotient(hc.loop_matrix(loop, 128), L, at), len(at)

        def same(A, B):
            self.assertEqual(len(A), len(B))
            for i in range(len(A)):
                for j in range(len(A)):
                    self.assertTrue(A[i][j].lo <= B[i][j].hi and B[i][j].lo <= A[i][j].hi)

        base, k0 = plant_M(LOOP_SCENE + '[[operator]]\ndofs = ["a"]\nk = "10"\n')
        self.assertEqual(k0, 0)
        for op in ('tf = "10/s"', 'ss = { A = [["0"]], B = [["1"]], C = [["10"]], D = [["0"]] }'):
            M, k = plant_M(LOOP_SCENE + '[[operator]]\ndofs = ["a"]\n' + op + '\n')
            self.assertEqual(k, 1, op)
            same(M, base)
        pos = LOOP_SCENE.replace('m = "2"', 'ss = { A = [["0", "0"], ["1", "0"]], B = [["1/2"], ["0"]], C = [["1", "0"]], D = [["0"]] }')
        M, k = plant_M(pos)
        self.assertEqual(k, 1)
        same(M, plant_M(LOOP_SCENE)[0])
        c = loop_cert(pos, False, self.P, ["1", "0"])
        c["claim"]["conserved"] = 1
        code, why = hc.check(c)
        self.assertEqual(code, 0, why)
        for k in (0, 2):
            c["claim"]["conserved"] = k
            code, why = hc.check(c)
            self.assertEqual(code, 1, why)
            self.assertIn("conserved quantities, but the loop has 1", why)


def frac_cert(H, T, td, claim, witness, c_lo=None):
    c = {"certificate": "hapstab", "version": 1, "kind": "bound",
         "model": {"H": H, "set": {"K": "2", "B": "2"}, "T": T, "delay": 0, "frac_delay": td, "eta": "0"},
         "claim": claim, "evidence": {"witness_c": witness}}
    if c_lo is not None:
        c["evidence"]["domain_c_lo"] = c_lo
    return c


SQRT2_INSIDE = "70710678118654752441/100000000000000000000"  # sqrt(2)/2 = 0.70710678118654752440084...
SQRT2_BELOW = "70710678118654752440/100000000000000000000"


class FractionalDelay(unittest.TestCase):
    """The cases of test_check.cpp's BoundCheck.FractionalDelay*: H = K, t_d = tau T gives
    f = T K sin((tau + 1/2) wT)/(2 sin(wT/2)); tau = 1/2: T K cos(wT/2), b* = T K = 1 (T = 1/2, K = 2);
    H = -K, tau = 1/4: -T K (4c^2 - 1)/(4c) in c = cos(wT/4), b* = -sqrt(2)/4 at the irrational end;
    the Tustin damper B (z - 1)/(z + 1), T = 1, B = 2, tau = 5/4: tan(wT/2) sin(5wT/4) - cos(5wT/4),
    sup 1.738... (mpmath), -inf at wT = pi and +inf just beyond."""

    def test_half_sample(self):
        exact = {"status": "exact", "value": "1"}
        self.assertEqual(hc.check(frac_cert("K", "1/2", "1/4", exact, "1", "0"))[0], 0)
        self.assertEqual(hc.check(frac_cert("K", "1/2", "1/4", exact, "1"))[0], 0)
        code, why = hc.check(frac_cert("K", "1/2", "1/4", exact, "1/2", "0"))
        self.assertEqual(code, 1)
        self.assertIn("not shown", why)
        code, why = hc.check(frac_cert("K", "1/2", "1/4", {"status": "certified", "lo": "-1/2", "hi": "1"}, "-1/2", "0"))
        self.assertEqual(code, 1)
        self.assertIn("outside the band", why)
        code, why = hc.check(frac_cert("K", "1/2", "1/4", exact, "1", "1/10"))
        self.assertEqual(code, 1)
        self.assertIn("domain_c_lo", why)
        self.assertEqual(hc.check(frac_cert("K", "1/2", "0", exact, "1"))[0], 1)
        self.assertEqual(hc.check(frac_cert("K", "1/2", "-1/4", exact, "1"))[0], 2)

    def test_maximum_at_an_irrational_end(self):
        claim = {"status": "certified", "lo": "-3535533905932737623/10000000000000000000",
                 "hi": "-3535533905932737621/10000000000000000000"}
        self.assertEqual(hc.check(frac_cert("-K", "1/2", "1/8", claim, SQRT2_INSIDE, SQRT2_BELOW)), (0, "b* in [-0.353553390593, -0.353553390593]"))
        self.assertEqual(hc.check(frac_cert("-K", "1/2", "1/8", claim, SQRT2_BELOW, SQRT2_BELOW))[0], 1)
        self.assertEqual(hc.check(frac_cert("-K", "1/2", "1/8", claim, SQRT2_INSIDE, SQRT2_INSIDE))[0], 1)
        self.assertEqual(hc.check(frac_cert("-K", "1/2", "1/8", claim, SQRT2_INSIDE))[0], 1)
        over = {"status": "certified", "lo": "-3535533905932737624/10000000000000000000",
                "hi": "-3535533905932737623/10000000000000000000"}
        self.assertEqual(hc.check(frac_cert("-K", "1/2", "1/8", over, SQRT2_INSIDE, SQRT2_BELOW))[0], 1)

    def test_pole_at_the_end_from_below(self):
        claim = {"status": "certified", "lo": "-1", "hi": "2"}
        self.assertEqual(hc.check(frac_cert("B*(z-1)/(z+1)", "1", "5/4", claim, "1", SQRT2_BELOW))[0], 0)
        claim["hi"] = "3/2"
        code, why = hc.check(frac_cert("B*(z-1)/(z+1)", "1", "5/4", claim, "1", SQRT2_BELOW))
        self.assertEqual(code, 1)
        self.assertIn("fails", why)

    def test_band_tests(self):
        F = Fraction
        self.assertTrue(hc.in_band(F(1), 7) and hc.in_band(F(-1), 1) and not hc.in_band(F(-1), 2))
        self.assertTrue(hc.in_band(F(0), 2) and not hc.in_band(F(-1, 100), 2))
        self.assertTrue(hc.in_band(F(1, 2), 3) and not hc.in_band(F(49, 100), 3))
        self.assertTrue(hc.below_band_end(F(1, 2), 3) and not hc.below_band_end(F(51, 100), 3))
        self.assertTrue(hc.below_band_end(F(-1), 5) and not hc.below_band_end(F(0), 1))
        # far below the end too: cos(pi/10) = 0.951..., cos(pi/5) = 0.809...
        for c in (F(95, 100), F(8, 10), F(0), F(-1, 2), F(-1)):
            self.assertTrue(hc.below_band_end(c, 10), c)
        self.assertFalse(hc.below_band_end(F(96, 100), 10))
        self.assertTrue(hc.in_band(F(96, 100), 10) and not hc.in_band(F(95, 100), 10) and not hc.in_band(F(0), 10))


def max_cert(H, claim, evidence, delay=0):
    return {"certificate": "hapstab", "version": 1, "kind": "bound-max",
            "model": {"H": H, "set": {"B": "1"}, "name": "K", "T": "1/1000", "delay": delay, "eta": "0", "damping": "2"},
            "claim": claim, "evidence": evidence}


def tustin_definition(K, B, nu, th):
    """(45) as written for the Tustin wall K + 2B(z - 1)/(T(z + 1)), T = 1/1000, delay nu, at theta = th, in mpmath
    (1 - z = -2j sin(theta/2) e^{j theta/2}, 1 + z = 2 cos(theta/2) e^{j theta/2}: no cancellation)."""
    import mpmath as mp
    t = mp.mpf(th.numerator) / th.denominator
    half = mp.expj(t / 2)
    omz, opz = -2j * mp.sin(t / 2) * half, 2 * mp.cos(t / 2) * half
    h = K + 2 * B * (-omz) / (mp.mpf(1) / 1000 * opz)
    return mp.re(mp.mpf(1) / 1000 * h * mp.expj(-nu * t) / omz)


class CellsTustinPole(unittest.TestCase):
    """cells_kernel with H's simple pole at z = -1 set apart (integer delays, since stop 81): f of the Tustin wall
    K + 2B(z - 1)/(T(z + 1)) at single points against (45) as written in mpmath at 50 digits (1 - z =
    -2j sin(theta/2) e^{j theta/2}, 1 + z = 2 cos(theta/2) e^{j theta/2}: no cancellation); at pi the limit
    (T/2)(-1)^n (K + 2B/T + rho (n + 1)), rho = -4B/T."""

    def test_against_the_definition(self):
        import mpmath as mp
        T, K, B = Fraction(1, 1000), Fraction(1000), Fraction(5)
        H = hc.parse_h("K + 2*B*(z-1)/(T*(z+1))", T, {"K": K, "B": B}, marginal=True)
        with mp.workdps(50):
            for n in (0, 1, 7, 1000):
                value = hc.cells_kernel(H, T, Fraction(0), Fraction(n))[0]
                for th in (Fraction(1, 10 ** 7), Fraction(3, 10), Fraction(15707, 10000), Fraction(314, 100),
                           Fraction(355, 113) - Fraction(1, 10 ** 6)):
                    want = tustin_definition(1000, 5, n, th)
                    got = value(th)
                    self.assertTrue(got.a - mp.mpf(10) ** -20 <= want <= got.b + mp.mpf(10) ** -20, (n, float(th), got, want))
                at_pi = T / 2 * (K + 2 * B / T - 4 * B / T * (n + 1)) * (1 if n % 2 == 0 else -1)
                near = value(Fraction(355, 113))  # 2.7e-7 beyond pi: the kernel's formula holds there too
                self.assertLess(abs(float(near.mid) - float(at_pi)), 1e-3 * abs(float(at_pi)) + 1e-3, (n, near, at_pi))


class CellsTustinPoleFractional(unittest.TestCase):
    """cells_kernel with H's simple pole at z = -1 and a fractional delay (since stop 82): f of the Tustin wall at
    single points below pi against (45) as written in mpmath at 50 digits; the cell holding pi shown by the tail
    test where rho sin(nu pi) > 0 (f -> -inf there: nu = 1.5, 2.75, 1501.75) and never where it is < 0 (f -> +inf:
    nu = 0.5, 2.25), whatever the bound asked."""

    def test_against_the_definition_and_the_tail(self):
        import mpmath as mp
        T, K, B = Fraction(1, 1000), Fraction(20), Fraction(5)
        H = hc.parse_h("K + 2*B*(z-1)/(T*(z+1))", T, {"K": K, "B": B}, marginal=True)
        with mp.workdps(50):
            for nu in (Fraction(3, 2), Fraction(11, 4), Fraction(6007, 4), Fraction(1, 2), Fraction(9, 4)):
                value, cell_below, _ = hc.cells_kernel(H, T, Fraction(0), nu)
                v = mp.mpf(nu.numerator) / nu.denominator
                for th in (Fraction(1, 10 ** 7), Fraction(3, 10), Fraction(15707, 10000), Fraction(314, 100), Fraction(314159, 100000)):
                    want = tustin_definition(20, 5, v, th)
                    got = value(th)
                    self.assertTrue(got.a - mp.mpf(10) ** -20 <= want <= got.b + mp.mpf(10) ** -20, (float(nu), float(th), got, want))
                minus_inf = mp.sin(mp.pi * v) < 0  # rho = -4B/T < 0: -inf at pi iff sin(nu pi) < 0
                a = Fraction(314159, 100000)  # 2.7e-6 below pi
                shown = cell_below(a, Fraction(355, 113), Fraction(10 ** 6))
                self.assertEqual(shown, minus_inf, (float(nu), shown))
                if minus_inf:  # far below f's values near a: not shown
                    self.assertFalse(cell_below(Fraction(3), Fraction(355, 113), Fraction(-10 ** 9)))


class BoundMax(unittest.TestCase):
    """The cases of test_check.cpp's BoundMaxCheck: the wall K + B (z - 1)/(T z) without delay has
    b*(K) = K T/2 + B (paper 001 (46)): B = 1, b = 2, T = 1/1000 give K_max = 2000 exactly; H = K with
    one sample of delay b*(K) = 3 K T/2 (Example 4): K_max = 4000/3."""
    WALL = "K + B*(z-1)/(T*z)"
    EV = {"b0_hi": "1", "witness_c": "-1"}

    def code(self, c):
        return hc.check(c)[0]

    def test_wall(self):
        ex = lambda v: {"status": "exact", "value": v}  # noqa: E731
        self.assertEqual(hc.check(max_cert(self.WALL, ex("2000"), self.EV)), (0, "K_max = 2000 (affine in K, degree bound 1)"))
        self.assertEqual(self.code(max_cert(self.WALL, {"status": "certified", "lo": "1999", "hi": "2001"}, self.EV)), 0)
        code, why = hc.check(max_cert(self.WALL, ex("2001"), self.EV))
        self.assertEqual(code, 1)
        self.assertIn("K_max >= ", why)
        code, why = hc.check(max_cert(self.WALL, ex("1999"), self.EV))
        self.assertEqual(code, 1)
        self.assertIn("K_max <= ", why)
        self.assertEqual(self.code(max_cert(self.WALL, ex("2000"), {"b0_hi": "2", "witness_c": "-1"})), 1)
        self.assertEqual(self.code(max_cert(self.WALL, ex("2000"), {"b0_hi": "1/2", "witness_c": "-1"})), 1)
        self.assertEqual(self.code(max_cert(self.WALL, ex("0"), {"witness_c": "-1"})), 1)
        self.assertEqual(self.code(max_cert(self.WALL, {"status": "exact", "infinite": True}, {"b0_hi": "1"})), 1)
        self.assertEqual(self.code(max_cert("B*(z-1)/(T*z) - K", {"status": "exact", "infinite": True}, {"b0_hi": "1"})), 0)

    def test_model(self):
        ex = {"status": "exact", "value": "2000"}
        c = max_cert(self.WALL, ex, self.EV)
        c["model"]["set"]["K"] = "1"
        self.assertEqual(self.code(c), 2)
        for H in ("K*K/1000 + B*(z-1)/(T*z)", "K/(1 + K) + B*(z-1)/(T*z)", "B*(z-1)/(T*z)"):
            code, why = hc.check(max_cert(H, ex, self.EV))
            self.assertEqual(code, 2, H)
            self.assertIn("model.H", why)
        self.assertEqual(self.code(max_cert("(K*K + K)/(K + 1) + B*(z-1)/(T*z)", ex, self.EV)), 0)

    def test_zero_checks_every_evidence(self):
        # H = B + K, t_d = T/2: b*(K) = T (B + K); B = 3000: b*(0) = 3 >= b = 2, K_max = 0 by the witness alone
        c = max_cert("B + K", {"status": "exact", "value": "0"}, {"witness_c": "1", "domain_c_lo": "0"})
        c["model"]["set"]["B"] = "3000"
        c["model"]["frac_delay"] = "1/2000"
        self.assertEqual(self.code(c), 0)
        c["evidence"]["domain_c_lo"] = "1/2"  # beyond the band's end cos(pi/2) = 0
        self.assertEqual(self.code(c), 1)

    def test_delayed_gain(self):
        c = max_cert("K", {"status": "exact", "value": "4000/3"}, {"b0_hi": "0", "witness_c": "1"}, delay=1)
        self.assertEqual(self.code(c), 0)
        c["model"]["delay"] = 0
        self.assertEqual(self.code(c), 1)

    def test_degree_bounds(self):
        deg = lambda text: hc.parse_h(text, Fraction(1), {"K": Fraction(0)}, leaf=lambda k, t, v: hc.Deg(1 if (k, t) == ("name", "K") else 0, 0))  # noqa: E731
        for text, nd in (("K", (1, 0)), ("K*z + 1", (1, 0)), ("1/K", (0, 1)), ("K/(K + z)", (1, 1)), ("K^3", (3, 0)),
                         ("(K + 1)^-2", (0, 2)), ("K + 1/K", (2, 1))):
            d = deg(text)
            self.assertEqual((d.n, d.d), nd, text)


def smax_cert(claim, evidence, delay=0, H="K + B*(z-1)/(T*z)", sets=None):
    return {"certificate": "hapstab", "version": 1, "kind": "stability-max",
            "model": {"plant": "1/(m*s^2)", "H": H, "set": sets or {"m": "1", "B": "2"}, "name": "K", "T": "1/1000", "delay": delay},
            "claim": claim, "evidence": evidence}


class StabilityMax(unittest.TestCase):
    """The cases of test_check.cpp's StabilityMaxCheck: the mass 1/(m s^2) on K + B (z - 1)/(T z),
    m = 1, T = 1/1000, B = 2. Delay 0: c = z (z - 1)^2 + g (z + 1)((K + B/T) z - B/T), g = T^2/(2 m),
    D(K) = K T^4 (4 B m - 2 B^2 T - K T (2 m + B T))^2/(4 m^5) = K (1001 K - 3996000)^2/10^24, and
    the loop is stable iff 0 < K < (2B/T)(2m - BT)/(2m + BT) = 3996000/1001 (Jury). Delay 1: K_max is
    the positive root of K^2 + 6000002 K - 7983992000 (the factor of D), 1330.3699091941487...
    B = 0 (a spring alone): NOT stable for every K > 0, D has no positive root; H = K (z - 1)/(T z):
    a root at z = 1 for every K, D = 0."""
    AT = {"stable_at": "1000"}

    def test_resultant_by_hand(self):
        F = Fraction
        self.assertEqual(hc.reciprocal_resultant([F(-1, 2), F(1)]), F(3, 4))   # c* = 1 - z/2 at 1/2
        self.assertEqual(hc.reciprocal_resultant([F(0), F(0), F(1)]), F(1))     # z^2: c* = 1
        self.assertEqual(hc.reciprocal_resultant([F(-1), F(1)]), F(0))          # z = 1
        z, g = [F(0), F(1)], [F(1, 2000000)]
        c0 = hc.padd(hc.pmul(z, hc.ppow([F(-1), F(1)], 2)), hc.pmul(hc.pmul(g, [F(1), F(1)]), [F(-2000), F(2000)]))
        c1 = hc.pmul(hc.pmul(g, [F(1), F(1)]), z)
        f = [F(-3996000), F(1001)]
        D = hc.resultant_in_K(c0, c1)
        self.assertEqual(D, hc.pscale(hc.pmul(z, hc.pmul(f, f)), F(1, 10 ** 24)))
        self.assertEqual([hc.positive_roots(D, F(3996000, 1001), False), hc.positive_roots(D, F(3996000, 1001), True),
                          hc.positive_roots(D, None, False)], [0, 1, 1])

    def test_wall_without_delay(self):
        ex = lambda v: {"status": "exact", "value": v}  # noqa: E731
        self.assertEqual(hc.check(smax_cert(ex("3996000/1001"), self.AT))[0], 0)
        code, why = hc.check(smax_cert(ex("3996001/1001"), self.AT))
        self.assertEqual(code, 1)
        self.assertIn("root(s) in (0, ", why)
        code, why = hc.check(smax_cert(ex("3995999/1001"), self.AT))
        self.assertEqual(code, 1)
        self.assertIn("is stable", why)
        self.assertEqual(hc.check(smax_cert(ex("3996000/1001"), {"stable_at": "3996000/1001"}))[0], 1)
        code, why = hc.check(smax_cert({"status": "certified", "infinite": True}, self.AT))
        self.assertEqual(code, 1)
        self.assertIn("(0, inf)", why)

    def test_wall_with_one_sample_delay(self):
        cl = lambda lo, hi: {"status": "certified", "lo": lo, "hi": hi}  # noqa: E731
        at = {"stable_at": "1"}
        self.assertEqual(hc.check(smax_cert(cl("1330369/1000", "133037/100"), at, 1))[0], 0)
        self.assertEqual(hc.check(smax_cert(cl("133037/100", "1330371/1000"), at, 1))[0], 1)
        self.assertEqual(hc.check(smax_cert(cl("1330368/1000", "1330369/1000"), at, 1))[0], 1)
        self.assertEqual(hc.check(smax_cert({"status": "exact", "value": "3996000/1001"}, self.AT, 1))[0], 1)

    def test_not_stable_at_small_gains(self):
        zero = {"status": "exact", "value": "0"}
        for delay in (0, 1):
            self.assertEqual(hc.check(smax_cert(zero, {"unstable_at": "1"}, delay, sets={"m": "1", "B": "0"}))[0], 0)
        code, why = hc.check(smax_cert(zero, {"unstable_at": "5"}, 0, "K*(z-1)/(T*z)", {"m": "1"}))
        self.assertEqual(code, 0)
        self.assertIn("D = 0 identically", why)
        self.assertEqual(hc.check(smax_cert(zero, {"unstable_at": "1"}))[0], 1)
        code, why = hc.check(smax_cert(zero, {"unstable_at": "5000"}))
        self.assertEqual(code, 1)
        self.assertIn("root(s) in (0, 5000]", why)

    def test_malformed(self):
        ex = {"status": "exact", "value": "3996000/1001"}
        for c, field in ((smax_cert(ex, self.AT, 0, "K*K + B*(z-1)/(T*z)"), "not affine"),
                         (smax_cert(ex, self.AT, 0, sets={"m": "1", "B": "2", "K": "1"}), "model.set"),
                         (smax_cert(ex, {"stable_at": "1000", "unstable_at": "1"}), "evidence.unstable_at"),
                         (smax_cert(ex, {}), "evidence.stable_at"),
                         (smax_cert(ex, self.AT, 0, "K*z^2"), "not causal")):
            code, why = hc.check(c)
            self.assertEqual(code, 2, why)
            self.assertIn(field, why)
        c = smax_cert(ex, self.AT)
        c["model"]["plant"] = "1/((m + K)*s^2)"
        self.assertEqual(hc.check(c)[0], 2)


def level_cert(H, kind, claim, witness):
    return {"certificate": "hapstab", "version": 1, "kind": "passivity-level",
            "model": {"H": H, "set": {}, "T": "1/1000", "kind": kind}, "claim": claim, "evidence": {"witness_c": witness}}


class PassivityLevel(unittest.TestCase):
    """test_check.cpp's PassivityLevelCheck: G = 1 + 1/(z - 1/2) has phi* = Re G(-1) = 1/3 and
    delta* = Re(1/G)(1) = (3/4)/(9/4) = 1/3 (Re G = 1 + (c - 1/2)/(5/4 - c), Re 1/G = (3/4)/(5/4 + c))."""

    def test_upper_bound_only_by_hand(self):
        # test_check.cpp's PassivityLevelCheck.UpperBoundOnlyByHand: 1/(z - 1/2) has Re(1/G) = c - 1/2,
        # least -3/2 at c = -1; (z + 1)/(z - 1/2) has a zero at -1 and Re(1/G) = 1/4 elsewhere
        def up(hi, printed=None):
            c = {"status": "upper_bound", "hi": hi}
            if printed:
                c["printed_hi"] = printed
            return c
        self.assertEqual(hc.check(level_cert("1/(z-0.5)", "osp", up("-3/2", "-1.5"), "-1"))[0], 0)
        self.assertEqual(hc.check(level_cert("1/(z-0.5)", "osp", up("-3/2", "-1.5"), "1"))[0], 1)
        self.assertEqual(hc.check(level_cert("1/(z-0.5)", "osp", up("-2"), "-1"))[0], 1)
        self.assertEqual(hc.check(level_cert("1/(z-0.5)", "osp", up("-3/2", "-1.4"), "-1"))[0], 1)
        self.assertEqual(hc.check(level_cert("(z+1)/(z-0.5)", "osp", up("1/4"), "-1"))[0], 1)
        self.assertEqual(hc.check(level_cert("(z+1)/(z-0.5)", "osp", up("1/4"), "0"))[0], 0)
        c = level_cert("1/(z-0.5)", "osp", up("-3/2"), "-1")
        c["claim"]["lo"] = "-2"
        self.assertEqual(hc.check(c)[0], 2)

    def test_lower_bound_by_lemma1_by_hand(self):
        # test_check.cpp's PassivityLevelCheck.LowerBoundByLemma1ByHand: G = -1 + 1/(z + 1/2), A = -1/2,
        # B = C = 1, D = -1, P = 1: lo = -4 shown, -3 not; A = -1/3 realises another G; hi = -3 at c0 = 1
        def cert(status, lo, a):
            c = level_cert("-1 + 1/(z + 1/2)", "osp", {"status": status, "lo": lo}, "1")
            c["evidence"] = {"A": [[a]], "B": [["1"]], "C": [["1"]], "D": [["-1"]], "P": [["1"]]}
            if status == "bounds":
                c["claim"]["hi"], c["evidence"]["witness_c"] = "-3", "1"
            return c
        code, why = hc.check(cert("lower_bound", "-4", "-1/2"))
        self.assertEqual(code, 0, why)
        self.assertIn("Lemma 1", why)
        self.assertEqual(hc.check(cert("bounds", "-4", "-1/2"))[0], 0)
        code, why = hc.check(cert("lower_bound", "-3", "-1/2"))
        self.assertEqual(code, 1)
        self.assertIn("(2) < 0 fails", why)
        code, why = hc.check(cert("lower_bound", "-4", "-1/3"))
        self.assertEqual(code, 1)
        self.assertIn("does not realise G", why)
        c = cert("bounds", "-4", "-1/2")
        c["claim"]["hi"] = "-31/10"
        self.assertEqual(hc.check(c)[0], 1)
        c = cert("lower_bound", "-4", "-1/2")
        del c["evidence"]["P"]
        self.assertEqual(hc.check(c)[0], 2)
        c = cert("lower_bound", "-4", "-1/2")
        c["evidence"]["B"] = [["1", "0"]]
        self.assertEqual(hc.check(c)[0], 2)
        c = cert("lower_bound", "-4", "-1/2")
        c["evidence"]["witness_c"] = "1"
        self.assertEqual(hc.check(c)[0], 2)

    def test_first_order(self):
        ex = lambda v: {"status": "exact", "value": v}  # noqa: E731
        G = "1 + 1/(z-0.5)"
        self.assertEqual(hc.check(level_cert(G, "isp", ex("1/3"), "-1")), (0, "phi* = 1/3"))
        self.assertEqual(hc.check(level_cert(G, "osp", ex("1/3"), "1")), (0, "delta* = 1/3"))
        code, why = hc.check(level_cert(G, "isp", ex("1/3"), "1"))
        self.assertEqual(code, 1)
        self.assertIn("not shown", why)
        code, why = hc.check(level_cert(G, "isp", ex("1/2"), "-1"))
        self.assertEqual(code, 1)
        self.assertIn("phi* >= ", why)
        self.assertEqual(hc.check(level_cert(G, "isp", {"status": "certified", "lo": "0", "hi": "1/2"}, "-1/2"))[0], 0)
        # (z + 1)/(z - 0.5) with lo > 0: a zero of G at z = -1 (theta = pi) must be seen there too
        self.assertEqual(hc.check(level_cert("(z + 1)/(z - 0.5)", "osp", ex("1/10"), "1"))[0], 2)
        for H, kind, v in (("1/(z - 2)", "isp", "0"), ("(z + 1)/(z - 0.5)", "osp", "0"), ("1/(z - 0.5)", "osp", "-3/2"),
                           ("z^2/(z - 0.5)", "isp", "0")):
            self.assertEqual(hc.check(level_cert(H, kind, ex(v), "1"))[0], 2, H)


def wedge_cert(H, K, claims):
    keys = ("wedge", "tsypkin", "h_stable", "closed_loop_stable", "dc_gain_nonnegative")
    return {"certificate": "hapstab", "version": 1, "kind": "wedge",
            "model": {"H": H, "set": {"K": K}, "T": "1"},
            "claim": dict({"status": "exact"}, **dict(zip(keys, claims))), "evidence": {}}


class Wedge(unittest.TestCase):
    def test_one_sample_delay(self):
        self.assertEqual(hc.check(wedge_cert("K/z", "1/2", (True, True, True, True, True)))[0], 0)
        self.assertEqual(hc.check(wedge_cert("K/z", "1", (False, False, True, False, True)))[0], 0)   # = 0 at theta = pi
        self.assertEqual(hc.check(wedge_cert("K/z", "2", (False, False, True, False, True)))[0], 0)
        code, why = hc.check(wedge_cert("K/z", "1", (True, False, True, False, True)))
        self.assertEqual(code, 1)
        self.assertIn("claim.wedge", why)
        # K = -1/2: (25) is |K| (1 + cos) + K cos + 1 = 3/2, (21) 1 - cos/2: both hold; H(1) < 0
        self.assertEqual(hc.check(wedge_cert("K/z", "-1/2", (True, True, True, True, False)))[0], 0)

    def test_constant(self):
        self.assertEqual(hc.check(wedge_cert("K", "3", (True, True, True, True, True)))[0], 0)
        self.assertEqual(hc.check(wedge_cert("K", "-1", (False, False, True, False, False)))[0], 0)

    def test_max_positive(self):
        F = Fraction
        self.assertIsNotNone(hc.max_positive([F(0), F(1)], [F(0), F(-1)], F(-1), F(1)))  # |c| = 0 at c = 0
        self.assertIsNone(hc.max_positive([F(1), F(1)], [F(1), F(-1)], F(-1), F(1)))      # 1 + |c|
        self.assertIsNotNone(hc.max_positive([F(-1, 4), F(0), F(1)], [F(-1, 4), F(0), F(1)], F(-1), F(1)))

    def test_max_nonnegative(self):
        # max >= 0: an end where both vanish stands for no cell (the wedge gains' first campaign)
        F = Fraction
        v = [F(-1), F(-1)]  # -(1 + c)
        self.assertIsNotNone(hc.max_positive(v, v, F(-1), F(1), strict=False))
        self.assertIsNone(hc.max_positive([F(1), F(1)], [F(1), F(1)], F(-1), F(1), strict=False))
        self.assertIsNone(hc.max_positive([F(0), F(0), F(1)], [F(0), F(0), F(-1)], F(-1), F(1), strict=False))
        self.assertIsNotNone(hc.max_positive([F(0), F(1)], [F(-1, 2), F(-1)], F(-1), F(1), strict=False))

    def test_refuses_a_pole_on_the_circle(self):
        code, why = hc.check(wedge_cert("K/(z - 1)", "1", (True, True, True, True, True)))
        self.assertEqual(code, 2)
        self.assertIn("unit circle", why)


def mimo_cert(A, B, C, D, claim, evidence=None):
    return {"certificate": "hapstab", "version": 1, "kind": "passivity-level-mimo",
            "model": {"A": A, "B": B, "C": C, "D": D, "T": "1/100", "kind": "isp"},
            "claim": claim, "evidence": evidence or {}}


# G = diag(g1, g2), g1 = (z + 1/2)/(z - 1/2) (Re g1 = (3/4)/(5/4 - c), min 1/3 at theta = pi),
# g2 = 1 + (3/4) z^-2 (Re g2 = 1 + (3/4) cos 2 theta, min 1/4 at theta = pi/2): phi* = 1/4 exactly
# (the cases of tests/check/test_check.cpp's PassivityLevelMimoCheck, for the C++ checker).
DIAG = ([["1/2", "0", "0"], ["0", "0", "0"], ["0", "1", "0"]], [["1", "0"], ["0", "1"], ["0", "0"]],
        [["1", "0", "0"], ["0", "0", "3/4"]], [["1", "0"], ["0", "1"]])
# coupled 2x2; mpmath at 60 digits: phi* = 0.13457867356938227191106546829846... at theta = 2.0700732099837...
COUPLED = ([["0", "1/2"], ["-1/2", "0"]], [["1", "0"], ["1/3", "1"]], [["1", "0"], ["1/4", "1"]], [["2", "1/3"], ["-1/5", "3/2"]])
COUPLED_WITNESS = {  # t = tan(theta/2) to 30 digits
    "witness_c": "-28706733526243037880659009817130398777347852942453452692249/59956733526243037880659009817130398777347852942453452692249",
    "witness_s": "52637755892421837435168465889250000000000000000000000000000/59956733526243037880659009817130398777347852942453452692249"}


def exact_claim(v):
    return {"status": "exact", "value": v}


def range_claim(lo, hi):
    return {"status": "certified", "lo": lo, "hi": hi}


class PassivityLevelMimo(unittest.TestCase):
    def test_diagonal_is_the_least_siso_level(self):
        self.assertEqual(hc.check(mimo_cert(*DIAG, exact_claim("1/4")))[0], 0)
        for wrong in ("1/3", "2500000000000000000000000000001/10000000000000000000000000000000",
                      "2499999999999999999999999999999/10000000000000000000000000000000"):
            self.assertEqual(hc.check(mimo_cert(*DIAG, exact_claim(wrong)))[0], 1, wrong)
        self.assertEqual(hc.check(mimo_cert(*DIAG, range_claim("0", "1/4"), {"witness_c": "0", "witness_s": "1"}))[0], 0)
        self.assertEqual(hc.check(mimo_cert(*DIAG, range_claim("-1", "3/10"), {"witness_c": "-21/221", "witness_s": "220/221"}))[0], 0)
        code, why = hc.check(mimo_cert(*DIAG, range_claim("0", "1/2"), {"witness_c": "1", "witness_s": "0"}))
        self.assertEqual(code, 1)
        self.assertIn("not shown", why)
        code, why = hc.check(mimo_cert(*DIAG, range_claim("0", "1/2"), {"witness_c": "1/2", "witness_s": "1/2"}))
        self.assertEqual(code, 1)
        self.assertIn("not on the unit circle", why)
        # the first channel alone: the SISO level 1/3, also the `passivity-level` kind's value for g1
        one = ([["1/2"]], [["1"]], [["1"]], [["1"]])
        self.assertEqual(hc.check(mimo_cert(*one, exact_claim("1/3")))[0], 0)
        self.assertEqual(hc.check(mimo_cert(*one, exact_claim("1/4")))[0], 1)

    def test_coupled_against_mpmath(self):
        lo, hi = "134578673569382271911/1000000000000000000000", "134578673569382271912/1000000000000000000000"
        self.assertEqual(hc.check(mimo_cert(*COUPLED, range_claim(lo, hi), COUPLED_WITNESS))[0], 0)
        code, why = hc.check(mimo_cert(*COUPLED, range_claim(hi, "134578673569382271913/1000000000000000000000"), COUPLED_WITNESS))
        self.assertEqual(code, 1)
        self.assertIn("phi* >= ", why)
        code, why = hc.check(mimo_cert(*COUPLED, range_claim("0", "134578673569382271910/1000000000000000000000"), COUPLED_WITNESS))
        self.assertEqual(code, 1)
        self.assertIn("not shown", why)
        self.assertEqual(hc.check(mimo_cert(*COUPLED, exact_claim(lo)))[0], 1)

    def test_constant_eigenvalue(self):
        m = ([["1/2"]], [["1", "0"]], [["1"], ["0"]], [["1", "0"], ["0", "1/5"]])  # He G has the eigenvalue 1/5 everywhere
        code, why = hc.check(mimo_cert(*m, exact_claim("1/5")))
        self.assertEqual(code, 1)
        self.assertIn("not decided", why)
        self.assertEqual(hc.check(mimo_cert(*m, range_claim("199999/1000000", "1/5"), {"witness_c": "1", "witness_s": "0"}))[0], 0)

    def test_upper_bound_only_by_hand(self):
        # test_check.cpp's PassivityLevelMimoCheck.UpperBoundOnlyByHand: G = diag(1/(z - 1/2), 1/(z - 1/5)
        # + d22); at z0 = -1 with d22 = -1, 1/G = diag(-3/2, -6/11): delta* <= -3/2, not <= -8/5; with
        # d22 = 5/6 det G(-1) = 0 (the witness proves nothing); ISP: He G(-1) = diag(-2/3, -11/6)
        def cert(d22, hi, w, kind="osp", printed=None):
            c = mimo_cert([["1/2", "0"], ["0", "1/5"]], [["1", "0"], ["0", "1"]], [["1", "0"], ["0", "1"]],
                          [["0", "0"], ["0", d22]], {"status": "upper_bound", "hi": hi}, {"witness_c": w[0], "witness_s": w[1]})
            c["model"]["kind"] = kind
            if printed:
                c["claim"]["printed_hi"] = printed
            return c
        code, why = hc.check(cert("-1", "-3/2", ("-1", "0"), printed="-1.5"))
        self.assertEqual(code, 0, why)
        self.assertIn("upper bound only", why)
        self.assertEqual(hc.check(cert("-1", "-8/5", ("-1", "0")))[0], 1)
        self.assertEqual(hc.check(cert("-1", "-3/2", ("1", "0")))[0], 1)
        self.assertEqual(hc.check(cert("-1", "-3/2", ("-1", "0"), printed="-1.4"))[0], 1)
        self.assertEqual(hc.check(cert("-1", "-3/2", ("-1", "1/2")))[0], 1)
        code, why = hc.check(cert("5/6", "-100", ("-1", "0")))
        self.assertEqual(code, 1)
        self.assertIn("det G = 0 at the witness", why)
        self.assertEqual(hc.check(cert("-1", "-11/6", ("-1", "0"), kind="isp"))[0], 0)
        self.assertEqual(hc.check(cert("-1", "-2", ("-1", "0"), kind="isp"))[0], 1)
        c = cert("-1", "-3/2", ("-1", "0"))
        c["claim"]["lo"] = "-2"
        self.assertEqual(hc.check(c)[0], 2)
        c = cert("-1", "-3/2", ("-1", "0"))
        c["evidence"] = {}
        self.assertEqual(hc.check(c)[0], 2)

    def test_lower_bound_by_lemma1_by_hand(self):
        # test_check.cpp's PassivityLevelMimoCheck.LowerBoundByLemma1ByHand: G = -1 + 1/(z + 1/2), P = 1:
        # OSP -F = [[19/4, -3], [-3, 2]] > 0 at lo = -4, not at -3; ISP likewise; hi = -3 at z0 = 1
        def cert(kind, claim, ev):
            c = mimo_cert([["-1/2"]], [["1"]], [["1"]], [["-1"]], claim, ev)
            c["model"]["kind"] = kind
            return c
        P1 = {"P": [["1"]]}
        code, why = hc.check(cert("osp", {"status": "lower_bound", "lo": "-4"}, P1))
        self.assertEqual(code, 0, why)
        self.assertIn("Lemma 1", why)
        code, why = hc.check(cert("osp", {"status": "lower_bound", "lo": "-3"}, P1))
        self.assertEqual(code, 1)
        self.assertIn("(2) < 0 fails", why)
        self.assertEqual(hc.check(cert("osp", {"status": "lower_bound", "lo": "-4"}, {"P": [["-1"]]}))[0], 1)
        self.assertEqual(hc.check(cert("osp", {"status": "lower_bound", "lo": "-4"}, {"P": [["0"]]}))[0], 1)
        self.assertEqual(hc.check(cert("isp", {"status": "lower_bound", "lo": "-4"}, P1))[0], 0)
        self.assertEqual(hc.check(cert("isp", {"status": "lower_bound", "lo": "-3"}, P1))[0], 1)
        both = {"status": "bounds", "lo": "-4", "hi": "-3", "printed_lo": "-4", "printed_hi": "-3.0"}
        ev = {"witness_c": "1", "witness_s": "0", "P": [["1"]]}
        self.assertEqual(hc.check(cert("osp", both, ev))[0], 0)
        self.assertEqual(hc.check(cert("osp", dict(both, hi="-31/10", printed_hi="-3.1"), ev))[0], 1)
        self.assertEqual(hc.check(cert("osp", {"status": "bounds", "lo": "-2", "hi": "-3"}, ev))[0], 1)
        self.assertEqual(hc.check(cert("osp", {"status": "lower_bound", "lo": "-4"}, ev))[0], 2)
        self.assertEqual(hc.check(cert("osp", {"status": "lower_bound", "lo": "-4"}, {}))[0], 2)
        self.assertEqual(hc.check(cert("osp", {"status": "lower_bound", "lo": "-4"}, {"P": [["1", "0"]]}))[0], 2)

    def test_osp_by_hand_and_against_mpmath(self):
        # the C++ checker's cases (test_check.cpp, OspByHandAndAgainstMpmath): delta* of DIAG = 1/3 at
        # theta = 0 by hand; of COUPLED 0.204061059135553914835147667520313... (mpmath, 60 digits)
        def osp(c):
            c["model"]["kind"] = "osp"
            return c
        self.assertEqual(hc.check(osp(mimo_cert(*DIAG, exact_claim("1/3"))))[0], 0)
        for wrong in ("1/4", "4/7"):
            self.assertEqual(hc.check(osp(mimo_cert(*DIAG, exact_claim(wrong))))[0], 1, wrong)
        self.assertEqual(hc.check(osp(mimo_cert(*DIAG, range_claim("1/4", "1/3"), {"witness_c": "1", "witness_s": "0"})))[0], 0)
        code, why = hc.check(osp(mimo_cert(*DIAG, range_claim("1/4", "1/3"), {"witness_c": "-1", "witness_s": "0"})))
        self.assertEqual(code, 1)
        self.assertIn("delta* <= ", why)
        code, why = hc.check(osp(mimo_cert(*DIAG, range_claim("-1", "1/3"), {"witness_c": "1", "witness_s": "0"})))
        self.assertEqual(code, 1)
        self.assertIn("lo > 0", why)
        w = {"witness_c": "-208191918127890245872492649742460031681211876814435161/708191918127890245872492649742460031681211876814435161",
             "witness_s": "676898750277979347572454619000000000000000000000000000/708191918127890245872492649742460031681211876814435161"}
        lo, hi = "204061059135553914835/1000000000000000000000", "204061059135553914836/1000000000000000000000"
        self.assertEqual(hc.check(osp(mimo_cert(*COUPLED, range_claim(lo, hi), w)))[0], 0)
        code, why = hc.check(osp(mimo_cert(*COUPLED, range_claim(hi, "204061059135553914837/1000000000000000000000"), w)))
        self.assertEqual(code, 1)
        self.assertIn("delta* >= ", why)
        self.assertEqual(hc.check(osp(mimo_cert(*COUPLED, range_claim("1/10", "204061059135553914834/1000000000000000000000"), w)))[0], 1)
        # a zero of G at z = -1 (1 + 1/z), or at z = +-j (1 + z^-2): refused by name
        minus1 = ([["1/2", "0"], ["0", "0"]], [["1", "0"], ["0", "1"]], [["1", "0"], ["0", "1"]], [["1", "0"], ["0", "1"]])
        code, why = hc.check(osp(mimo_cert(*minus1, range_claim("1/10", "1/3"), {"witness_c": "1", "witness_s": "0"})))
        self.assertEqual(code, 2)
        self.assertIn("z = -1", why)
        pmj = (DIAG[0], DIAG[1], [["1", "0", "0"], ["0", "0", "1"]], DIAG[3])
        code, why = hc.check(osp(mimo_cert(*pmj, range_claim("1/10", "1/3"), {"witness_c": "1", "witness_s": "0"})))
        self.assertEqual(code, 2)
        self.assertIn("vanishes on the unit circle", why)

    def test_malformed(self):
        ok = mimo_cert(*DIAG, range_claim("0", "1/4"), {"witness_c": "0", "witness_s": "1"})
        for path, value, field in ((("model", "kind"), "ips", "model.kind"), (("model", "T"), "0", "model.T"),
                                   (("model", "H"), "1/z", "model.H"), (("evidence", "witness_v"), "1", "evidence.witness_v"),
                                   (("model", "D"), [["1", "0", "0"], ["0", "1", "0"]], "model.D"),
                                   (("model", "C"), [["1", "0", "0"]], "model.C")):
            c = copy.deepcopy(ok)
            c[path[0]][path[1]] = value
            code, why = hc.check(c)
            self.assertEqual(code, 2, (path, why))
            self.assertIn(field, why)
        c = copy.deepcopy(ok)
        c["model"]["A"][0][0] = "3/2"
        self.assertEqual(hc.check(c)[0], 2)
        self.assertEqual(hc.check(mimo_cert(*DIAG, exact_claim("1/4"), {"witness_c": "0", "witness_s": "1"}))[0], 2)
        c = copy.deepcopy(ok)
        del c["evidence"]["witness_s"]
        self.assertEqual(hc.check(c)[0], 2)

def with_margins(c, wm, wg, tm, tg, wc, tc):
    c = copy.deepcopy(c)
    c["claim"].update({"wedge_margin": wm, "wedge_gain": wg, "tsypkin_margin": tm, "tsypkin_gain": tg})
    c["evidence"] = {k: v for k, v in (("wedge_witness_c", wc), ("tsypkin_witness_c", tc)) if v is not None}
    return c


def rng(lo, hi, printed=None):
    return dict({"lo": lo, "hi": hi}, **({"printed": printed} if printed else {}))


class WedgeMargins(unittest.TestCase):
    """H = K/z (the Wedge cases): K = 1/2: (25)'s left side 1/2 + cos(theta), margin (min + 1) 1/2 at
    theta = pi, k* = 2; (21)'s cos(theta)/2, margin 1/2, k* = 2. K = -1/2: (25)'s left side 1/2 everywhere
    (margin 3/2, k* = +inf), (21)'s -cos(theta)/2, margin 1/2 at theta = 0, k* = 2 (tests/check/test_check.cpp
    WedgeCheck.MarginsAndGainsByHand, for the C++ checker)."""

    def test_by_hand(self):
        half = wedge_cert("K/z", "1/2", (True, True, True, True, True))
        self.assertEqual(hc.check(with_margins(half, rng("1/2", "1/2", "0.5"), rng("2", "2", "2"), rng("1/2", "1/2"), rng("2", "2"), "-1", "-1"))[0], 0)
        code, why = hc.check(with_margins(half, rng("51/100", "52/100"), rng("2", "2"), rng("1/2", "1/2"), rng("2", "2"), "-1", "-1"))
        self.assertEqual(code, 1)
        self.assertIn("wedge_margin", why)
        code, why = hc.check(with_margins(half, rng("1/2", "1/2", "0.6"), rng("2", "2"), rng("1/2", "1/2"), rng("2", "2"), "-1", "-1"))
        self.assertEqual(code, 1)
        self.assertIn("printed", why)
        self.assertEqual(hc.check(with_margins(half, rng("1/2", "1/2"), {"infinite": True}, rng("1/2", "1/2"), rng("2", "2"), "-1", "-1"))[0], 1)
        self.assertEqual(hc.check(with_margins(half, rng("49/100", "51/100"), rng("2", "2"), rng("1/2", "1/2"), rng("2", "2"), "-1/2", "-1"))[0], 1)
        neg = wedge_cert("K/z", "-1/2", (True, True, True, True, False))
        self.assertEqual(hc.check(with_margins(neg, rng("3/2", "3/2", "1.5"), {"infinite": True}, rng("1/2", "1/2", "0.5"), rng("2", "2", "2"), "0", "1"))[0], 0)
        self.assertEqual(hc.check(with_margins(neg, rng("3/2", "3/2"), rng("1", "100"), rng("1/2", "1/2"), rng("2", "2"), "0", "1"))[0], 1)
        self.assertEqual(hc.check(with_margins(half, rng("1/2", "1/2"), rng("2", "2"), rng("1/2", "1/2"), rng("2", "2"), None, "-1"))[0], 2)
        self.assertEqual(hc.check(with_margins(half, rng("1/2", "1/2"), rng("0", "2"), rng("1/2", "1/2"), rng("2", "2"), "-1", "-1"))[0], 2)


def inf_cert(H, K, delay, pole, side, td=None, B=None):
    c = {"certificate": "hapstab", "version": 1, "kind": "bound",
         "model": {"H": H, "set": {"K": K}, "T": "1/1000", "delay": delay, "eta": "0"},
         "claim": {"status": "exact", "infinite": True}, "evidence": {"pole_c": pole, "side": side}}
    if td:
        c["model"]["frac_delay"] = td
    if B:
        c["model"]["set"]["B"] = B
    return c


class BoundInfinite(unittest.TestCase):
    """b* = +inf by hand: H = K z/(z^2 + 1) is K/(2c) on the circle and Re 1/(1 - z) = 1/2, so
    f = T K/(4c) (n = 0), T K (1 + 2c)/(4c) (n = 1): +inf as c -> 0 from above for K > 0, -inf from below;
    H = K/(z - 1): f = T K c/(2(1 - c)), +inf as c -> 1 from below for K > 0; the Tustin wall with
    t_d = T/2 (+inf at c = cos(wT/2) = 0 from above) and 3T/2 (-inf there: issue 46 item 1)."""

    def test_by_hand(self):
        for n in (0, 1):
            self.assertEqual(hc.check(inf_cert("K*z/(z^2 + 1)", "3", n, "0", 1))[0], 0)
            code, why = hc.check(inf_cert("K*z/(z^2 + 1)", "3", n, "0", -1))
            self.assertEqual(code, 1)
            self.assertIn("-inf", why)
            self.assertEqual(hc.check(inf_cert("K*z/(z^2 + 1)", "-3", n, "0", -1))[0], 0)
            self.assertEqual(hc.check(inf_cert("K*z/(z^2 + 1)", "-3", n, "0", 1))[0], 1)
        self.assertEqual(hc.check(inf_cert("K/(z - 1)", "2", 0, "1", -1))[0], 0)
        self.assertEqual(hc.check(inf_cert("K/(z - 1)", "-2", 0, "1", -1))[0], 1)
        self.assertEqual(hc.check(inf_cert("K/(z - 1)", "2", 0, "1", 1))[0], 1)
        self.assertEqual(hc.check(inf_cert("K/(z - 1)", "2", 0, "1/2", -1))[0], 1)
        self.assertEqual(hc.check(inf_cert("K/(z - 1)", "2", 0, "1", 0))[0], 2)
        tustin = "K + B*2*(z-1)/(T*(z+1))"
        self.assertEqual(hc.check(inf_cert(tustin, "20", 0, "0", 1, "1/2000", "5"))[0], 0)
        code, why = hc.check(inf_cert(tustin, "20", 0, "0", 1, "3/2000", "5"))
        self.assertEqual(code, 1)
        self.assertIn("-inf", why)
        self.assertEqual(hc.check(inf_cert(tustin, "20", 0, "0", -1, "1/2000", "5"))[0], 1)

    def test_at_the_irrational_band_end(self):
        # test_check.cpp's BoundCheck.InfiniteAtTheIrrationalBandEnd: K/(z + 1), T = 1, t_d = T/4: near
        # wT = pi the objective is ~ K cos(3 pi/4)/(2 sin theta), +inf for K = -1, -inf for K = 1
        def cert(K, lo, hi):
            return {"certificate": "hapstab", "version": 1, "kind": "bound",
                    "model": {"H": "K/(z+1)", "set": {"K": K}, "T": "1", "delay": 0, "frac_delay": "1/4", "eta": "0"},
                    "claim": {"status": "exact", "infinite": True}, "evidence": {"end_lo": lo, "end_hi": hi}}
        self.assertEqual(hc.check(cert("-1", "7/10", "71/100"))[0], 0)
        code, why = hc.check(cert("1", "7/10", "71/100"))
        self.assertEqual(code, 1)
        self.assertIn("-inf", why)
        self.assertEqual(hc.check(cert("-1", "-1/10", "71/100"))[0], 1)
        self.assertEqual(hc.check(cert("-1", "7/10", "705/1000"))[0], 1)
        c = cert("-1", "7/10", "71/100")
        c["evidence"]["pole_c"] = "1"
        self.assertEqual(hc.check(c)[0], 2)

    def test_local_form_at_minus_one(self):
        # test_check.cpp's BoundCheck.InfiniteAtMinusOneLocalForm: K/(z + 1), T = 1, nu = 1500 + 1/4: +inf iff K < 0;
        # one sample more flips the sign; a whole nu or no pole at -1 refuted; another z or a field beside it malformed
        def cert(H, K, n, td):
            model = {"H": H, "set": {"K": K}, "T": "1", "delay": n, "eta": "0"}
            if td:
                model["frac_delay"] = td
            return {"certificate": "hapstab", "version": 1, "kind": "bound", "model": model,
                    "claim": {"status": "exact", "infinite": True}, "evidence": {"pole_at_z": "-1"}}
        self.assertEqual(hc.check(cert("K/(z+1)", "-1", 1500, "1/4"))[0], 0)
        code, why = hc.check(cert("K/(z+1)", "1", 1500, "1/4"))
        self.assertEqual(code, 1)
        self.assertIn("-inf", why)
        self.assertEqual(hc.check(cert("K/(z+1)", "1", 1501, "1/4"))[0], 0)
        self.assertEqual(hc.check(cert("K/(z+1)", "-1", 1501, "1/4"))[0], 1)
        self.assertEqual(hc.check(cert("K/(z+1)", "-1", 1500, None))[0], 1)
        self.assertEqual(hc.check(cert("K/(z+1)", "-1", 1500, "1"))[0], 1)
        self.assertEqual(hc.check(cert("K/(z-1/2)", "-1", 1500, "1/4"))[0], 1)
        c = cert("K/(z+1)", "-1", 1500, "1/4")
        c["evidence"]["pole_at_z"] = "1"
        self.assertEqual(hc.check(c)[0], 2)
        c = cert("K/(z+1)", "-1", 1500, "1/4")
        c["evidence"]["side"] = 1
        self.assertEqual(hc.check(c)[0], 2)

    def test_at_an_irrational_pole_inside_the_band(self):
        # test_check.cpp's BoundCheck.InfiniteAtAnIrrationalPoleInsideTheBand: K/(z^2 + 1), T = 1, t_d = T/3:
        # f = K sin(11 theta/6)/(4 cos theta sin(theta/2)) -> +K inf as theta -> pi/2 from below, i.e. from
        # c = cos(theta/3) > sqrt(3)/2 (side +1) for K = 1
        def cert(K, lo, hi, side):
            return {"certificate": "hapstab", "version": 1, "kind": "bound",
                    "model": {"H": "K/(z^2+1)", "set": {"K": K}, "T": "1", "delay": 0, "frac_delay": "1/3", "eta": "0"},
                    "claim": {"status": "exact", "infinite": True},
                    "evidence": {"pole_lo": lo, "pole_hi": hi, "side": side}}
        self.assertEqual(hc.check(cert("1", "433/500", "867/1000", 1))[0], 0)
        code, why = hc.check(cert("1", "433/500", "867/1000", -1))
        self.assertEqual(code, 1)
        self.assertIn("-inf", why)
        self.assertEqual(hc.check(cert("-1", "433/500", "867/1000", -1))[0], 0)
        self.assertEqual(hc.check(cert("-1", "433/500", "867/1000", 1))[0], 1)
        code, why = hc.check(cert("1", "867/1000", "9/10", 1))
        self.assertEqual(code, 1)
        self.assertIn("does not isolate", why)
        code, why = hc.check(cert("1", "4/5", "867/1000", 1))
        self.assertEqual(code, 1)
        self.assertIn("numerator", why)
        self.assertEqual(hc.check(cert("1", "-1/10", "867/1000", 1))[0], 1)
        c = cert("1", "433/500", "867/1000", 1)
        c["evidence"]["pole_c"] = "0"
        self.assertEqual(hc.check(c)[0], 2)


OPERATOR_SCENE = """[scene]
name = "H1"
T = "1/100"

[[device]]
name = "a"
m = "1/10"
b = "137/100"

[[device]]
name = "b"
m = "1/10"
b = "137/100"

[[operator]]
name = "H1"
dofs = ["a", "b"]
tf = [["0.1*(s^2+5*s+10)/(s^2+s+1)", "0.05"], ["0.05", "0.05*(s^2+5*s+10)/(s^2+s+1)"]]

[[operator]]
name = "spring"
dofs = ["a"]
tf = "1/(s^2 + 1)"

[environment]
tf = [["1000", "0"], ["0", "1000"]]
"""


class OperatorPassivity(unittest.TestCase):
    """test_check.cpp's OperatorPassivityCheck.PaperH1ByHand: He H1(jw) = [[0.1 r, 0.05], [0.05, 0.05 r]],
    r = Re g(jw); det = 0.005 r^2 - 0.0025, r(3) = 37/73 (< 0), r(0) = 10 (0.4975); 1/(s^2 + 1) has a
    pole at w = 1."""

    def cert(self, op, w, minor, passive=False):
        return {"certificate": "hapstab", "version": 1, "kind": "operator-passivity",
                "model": {"scene": OPERATOR_SCENE, "set": {}},
                "claim": {"status": "exact", "operator": op, "passive": passive}, "evidence": {"w": w, "minor": minor}}

    def test_paper_h1_by_hand(self):
        code, why = hc.check(self.cert("H1", "3", [0, 1]))
        self.assertEqual(code, 0, why)
        code, why = hc.check(self.cert("H1", "0", [0, 1]))
        self.assertEqual(code, 1)
        self.assertIn("0.4975", why)
        self.assertEqual(hc.check(self.cert("H1", "3", [0]))[0], 1)
        self.assertEqual(hc.check(self.cert("H1", "-717/256", [0, 1]))[0], 0)
        code, why = hc.check(self.cert("spring", "1", [0]))
        self.assertEqual(code, 1)
        self.assertIn("pole", why)
        for bad in (self.cert("H2", "3", [0, 1]), self.cert("H1", "3", [1, 0]), self.cert("H1", "3", [0, 2]),
                    self.cert("H1", "3", [0, 1], passive=True)):
            self.assertEqual(hc.check(bad)[0], 2)


    def test_state_space_operator_by_hand(self):
        # test_check.cpp's OperatorPassivityCheck.StateSpaceOperatorByHand: Z = 1 - 3/(s + 1) as ss, Re Z(j0) = -2,
        # Re Z(2j) = 2/5, Re Z(j/2) = -7/5; a hidden integrator (A = 0, C = 0) is singular at w = 0
        def cert(a, c, w, ev=None):
            scene = ('[scene]\nT = "1/100"\n[[device]]\nname = "a"\nm = "1/10"\nb = "1"\n[[operator]]\nname = "Z"\n'
                     'dofs = ["a"]\nss = { A = [["%s"]], B = [["1"]], C = [["%s"]], D = [["1"]] }\n[environment]\ntf = "1000"\n' % (a, c))
            return {"certificate": "hapstab", "version": 1, "kind": "operator-passivity", "model": {"scene": scene, "set": {}},
                    "claim": {"status": "exact", "operator": "Z", "passive": False}, "evidence": ev or {"w": w, "minor": [0]}}
        code, why = hc.check(cert("-1", "-3", "0"))
        self.assertEqual(code, 0, why)
        self.assertEqual(hc.check(cert("-1", "-3", "2"))[0], 1)
        self.assertEqual(hc.check(cert("-1", "-3", "1/2"))[0], 0)
        code, why = hc.check(cert("0", "0", "0"))
        self.assertEqual(code, 1)
        self.assertIn("singular", why)
        # the residue form on Z's entries formed exactly: 1 - 3/(s + 1) and Z = 1 (C = 0) have no pole at 0;
        # A = 0, C = -3 is 1 - 3/s (residue -3); C = 3 a spring
        self.assertEqual(hc.check(cert("-1", "-3", "0", {"pole": "0"}))[0], 1)
        self.assertEqual(hc.check(cert("0", "0", "0", {"pole": "0"}))[0], 1)
        code, why = hc.check(cert("0", "-3", "0", {"pole": "0"}))
        self.assertEqual(code, 0, why)
        self.assertEqual(hc.check(cert("0", "3", "0", {"pole": "0"}))[0], 1)

    def test_residue_at_zero_by_hand(self):
        # test_check.cpp's OperatorPassivityCheck.ResidueAtZeroByHand: 2 - 10/s (residue -10), 1/s^2, an
        # asymmetric or indefinite residue are not passive; 2 + 10/s and (s + 1)/(s^2 + s) = 1/s are refuted
        def cert(tf):
            scene = ('[scene]\nT = "1/100"\n[[device]]\nname = "a"\nm = "1/10"\nb = "1"\n[[device]]\nname = "b"\nm = "1/10"\n'
                     'b = "1"\n[[operator]]\nname = "Z"\ndofs = ["a", "b"]\ntf = %s\n[environment]\ntf = [["1000", "0"], ["0", "1000"]]\n' % tf)
            return {"certificate": "hapstab", "version": 1, "kind": "operator-passivity", "model": {"scene": scene, "set": {}},
                    "claim": {"status": "exact", "operator": "Z", "passive": False}, "evidence": {"pole": "0"}}
        code, why = hc.check(cert('[["2 - 10/s", "0"], ["0", "1"]]'))
        self.assertEqual(code, 0, why)
        self.assertEqual(hc.check(cert('[["2 + 10/s", "0"], ["0", "1"]]'))[0], 1)
        code, why = hc.check(cert('[["1/s^2", "0"], ["0", "1"]]'))
        self.assertEqual(code, 0, why)
        self.assertIn("order 2", why)
        self.assertEqual(hc.check(cert('[["1/s", "2/s"], ["0", "1/s"]]'))[0], 0)
        self.assertEqual(hc.check(cert('[["1/s", "2/s"], ["2/s", "1/s"]]'))[0], 0)
        self.assertEqual(hc.check(cert('[["(s + 1)/(s^2 + s)", "0"], ["0", "1/s"]]'))[0], 1)
        c = cert('[["2 - 10/s", "0"], ["0", "1"]]')
        c["evidence"]["pole"] = "1"  # no pole at s = j
        self.assertEqual(hc.check(c)[0], 1)
        c["evidence"]["pole"] = "-1"
        self.assertEqual(hc.check(c)[0], 2)
        c = cert('[["2 - 10/s", "0"], ["0", "1"]]')
        c["evidence"]["w"] = "1"
        self.assertEqual(hc.check(c)[0], 2)

    def test_residue_on_the_axis_by_hand(self):
        # test_check.cpp's OperatorPassivityCheck.ResidueOnTheAxisByHand: 2 - 10 s/(s^2 + 4) (residue -5 at 2j),
        # a double pole, and at s = j a Hermitian PSD residue (refuted), a non-Hermitian one, an indefinite one
        def cert(tf, w0, key="pole"):
            scene = ('[scene]\nT = "1/100"\n[[device]]\nname = "a"\nm = "1/10"\nb = "1"\n[[device]]\nname = "b"\nm = "1/10"\n'
                     'b = "1"\n[[operator]]\nname = "Z"\ndofs = ["a", "b"]\ntf = %s\n[environment]\ntf = [["1000", "0"], ["0", "1000"]]\n' % tf)
            return hc.check({"certificate": "hapstab", "version": 1, "kind": "operator-passivity", "model": {"scene": scene, "set": {}},
                             "claim": {"status": "exact", "operator": "Z", "passive": False}, "evidence": {key: w0}})
        code, why = cert('[["2 - 10*s/(s^2 + 4)", "0"], ["0", "1"]]', "2")
        self.assertEqual(code, 0, why)
        self.assertIn("s = j2", why)
        self.assertEqual(cert('[["2 - 10*s/(s^2 + 4)", "0"], ["0", "1"]]', "1")[0], 1)
        self.assertEqual(cert('[["2 + 10*s/(s^2 + 4)", "0"], ["0", "1"]]', "2")[0], 1)
        code, why = cert('[["1/(s^2 + 4)^2", "0"], ["0", "1"]]', "2")
        self.assertEqual(code, 0, why)
        self.assertIn("order 2", why)
        self.assertEqual(cert('[["s/(s^2 + 1)", "1/(s^2 + 1)"], ["-1/(s^2 + 1)", "s/(s^2 + 1)"]]', "1")[0], 1)
        code, why = cert('[["s/(s^2 + 1)", "1/(s^2 + 1)"], ["1/(s^2 + 1)", "s/(s^2 + 1)"]]', "1")
        self.assertEqual(code, 0, why)
        self.assertIn("not Hermitian", why)
        code, why = cert('[["s/(s^2 + 1)", "2/(s^2 + 1)"], ["-2/(s^2 + 1)", "s/(s^2 + 1)"]]', "1")
        self.assertEqual(code, 0, why)
        self.assertIn("not positive semidefinite", why)
        # w0 = sqrt(2) ({pole_squared: 2}): R = -5 (verified), 5 (refuted), -j (3/4) sqrt(2) (not Hermitian); 0, -2 malformed
        code, why = cert('[["2 - 10*s/(s^2 + 2)", "0"], ["0", "1"]]', "2", "pole_squared")
        self.assertEqual(code, 0, why)
        self.assertIn("s = j sqrt(2)", why)
        self.assertEqual(cert('[["2 + 10*s/(s^2 + 2)", "0"], ["0", "1"]]', "2", "pole_squared")[0], 1)
        code, why = cert('[["3/(s^2 + 2)", "0"], ["0", "1"]]', "2", "pole_squared")
        self.assertEqual(code, 0, why)
        self.assertIn("not Hermitian", why)
        for q in ("0", "-2"):
            self.assertEqual(cert('[["3/(s^2 + 2)", "0"], ["0", "1"]]', q, "pole_squared")[0], 2)


class BoundNumDen(unittest.TestCase):
    """H given by its coefficients (--num/--den, a .mat's num and den) is the same H (test_check.cpp's
    BoundCheck.NumDenIsTheSameH): H = 4 with one sample of delay at T = 1/2, b* = 3 T K/2 = 3; den
    [1, 0] is 4/z, a second sample: b* = (2n + 1) T K/2 = 5."""

    def test_by_hand(self):
        c = {"certificate": "hapstab", "version": 1, "kind": "bound",
             "model": {"num": ["4"], "den": ["1"], "T": "1/2", "delay": 1, "eta": "0"},
             "claim": {"status": "exact", "value": "3"}, "evidence": {"witness_c": "1"}}
        self.assertEqual(hc.check(c)[0], 0)
        d = copy.deepcopy(c)
        d["model"]["den"] = ["1", "0"]
        self.assertEqual(hc.check(d)[0], 1)
        d["claim"]["value"] = "5"
        self.assertEqual(hc.check(d)[0], 0)
        for edit, field in ((lambda m: m.update(H="4"), "model"), (lambda m: m.update(set={"K": "4"}), "model.set"),
                            (lambda m: m.update(den=["0", "1"]), "model.den"), (lambda m: m.update(num=[]), "model.num"),
                            (lambda m: m.update(num=[0.5]), "model.num[0]"), (lambda m: m.update(num=["0.5"]), "model.num[0]"),
                            (lambda m: m.pop("den"), "model.den")):
            d = copy.deepcopy(c)
            edit(d["model"])
            code, why = hc.check(d)
            self.assertEqual(code, 2, field)
            self.assertIn(field, why)


def lc_cert(gain, rho, period, amp, printed, free, y, attracting=None, H="1/z"):
    c = {"certificate": "hapstab", "version": 1, "kind": "limit-cycle",
         "model": {"H": H, "set": {}, "T": "1", "gain": gain, "rho": rho},
         "claim": {"status": "exact", "period": period, "amplitude": amp, "printed_amplitude": printed, "free_steps": free},
         "evidence": {"y": y}}
    if attracting is not None:
        c["claim"]["attracting"] = attracting
    return c


class LimitCycle(unittest.TestCase):
    """H = 1/z: y_{j+1} = -k max(y_j, -rho). k = 2, rho = 1: 2 -> -4 -> 2, period 2, amplitude 3, one
    sample out of contact, J = (-2)(0) = 0 (attracting); k = 1: 1/2 -> -1/2 -> 1/2, J = 1 (not attracting);
    from 1 the orbit touches y = -rho (attraction beyond the checker). The cases of test_check.cpp's
    LimitCycleCheck.FirstOrderByHand."""

    def test_by_hand(self):
        self.assertEqual(hc.check(lc_cert("2", "1", 2, "3", "3", 1, ["2"], True))[0], 0)
        self.assertEqual(hc.check(lc_cert("2", "1", 2, "3", "3", 1, ["-4"], True))[0], 0)
        self.assertEqual(hc.check(lc_cert("2", "2", 2, "6", "6.0", 1, ["4"], True))[0], 0)
        for c, why in ((lc_cert("2", "1", 1, "3", "3", 1, ["2"]), "does not repeat"),
                       (lc_cert("2", "1", 4, "3", "3", 1, ["2"]), "least period"),
                       (lc_cert("2", "1", 2, "4", "4", 1, ["2"]), "amplitude"),
                       (lc_cert("2", "1", 2, "3", "3.6", 1, ["2"]), "printed_amplitude"),
                       (lc_cert("2", "1", 2, "3", "3", 0, ["2"]), "free_steps"),
                       (lc_cert("2", "1", 2, "3", "3", 1, ["2"], False), "attracting"),
                       (lc_cert("2", "2", 2, "3", "3", 1, ["2"]), "does not repeat"),
                       (lc_cert("1", "1", 2, "1/2", "0.5", 0, ["1/2"], True), "attracting")):
            code, reason = hc.check(c)
            self.assertEqual(code, 1, reason)
            self.assertIn(why, reason)
        self.assertEqual(hc.check(lc_cert("1", "1", 2, "1/2", "0.5", 0, ["1/2"], False))[0], 0)
        self.assertEqual(hc.check(lc_cert("1", "1", 2, "1", "1", 0, ["1"]))[0], 0)
        self.assertEqual(hc.check(lc_cert("1", "1", 2, "1", "1", 0, ["1"], True))[0], 2)  # a sample on y = -rho
        self.assertEqual(hc.check(lc_cert("2", "1", 2, "3", "3", 1, ["2", "-4"]))[0], 2)
        self.assertEqual(hc.check(lc_cert("2", "1", 2, "3", "3", 1, ["2"], H="2"))[0], 2)
        self.assertEqual(hc.check(lc_cert("-2", "1", 2, "3", "3", 1, ["2"]))[0], 2)
        self.assertEqual(hc.check(lc_cert("1", "1", 2, "3", "3", 1, ["2"], H="-2 + 1/z"))[0], 2)


EXAMPLES = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "examples", "certificates")


def example(name):
    import json
    with open(os.path.join(EXAMPLES, name)) as f:
        return json.load(f)


class MultidofSplitAndCoupling(unittest.TestCase):
    """The kinds of stop 67 on their examples: multidof-feasible-symmetric (16 identical contacts in 4
    classes) and multidof-coupling (paper 000's case ii designed), each verified as written and refuted
    or refused where one hypothesis of its theorem is broken."""

    def test_symmetric_example_verifies(self):
        self.assertEqual(hc.check(example("multidof-feasible-symmetric-contact16.json"))[0], 0)

    def test_a_dof_traded_between_classes_breaks_the_invariance(self):
        c = example("multidof-feasible-symmetric-contact16.json")
        cl = c["evidence"]["classes"]
        cl[0][1], cl[1][1] = cl[1][1], cl[0][1]
        code, why = hc.check(c)[:2]
        self.assertEqual(code, 1, why)
        self.assertIn("not invariant", why)

    def test_a_level_moved_within_a_class(self):
        c = example("multidof-feasible-symmetric-contact16.json")
        dof = c["evidence"]["classes"][2][1]
        c["model"]["devices"][dof]["b"] = "2"
        code, why = hc.check(c)[:2]
        self.assertEqual(code, 1, why)
        self.assertIn("not of alike DOFs", why)

    def test_two_dof_operator_is_outside_the_kind(self):
        c = example("multidof-feasible-symmetric-contact16.json")
        ops = c["model"]["operators"]
        c["model"]["operators"] = [ops[0] + ops[1]] + ops[2:]
        self.assertEqual(hc.check(c)[0], 2)

    def test_coupling_example_verifies_and_its_feedthrough_matters(self):
        c = example("multidof-coupling-case-ii.json")
        self.assertEqual(hc.check(c)[0], 0)
        D = c["model"]["coupling"]["D"]
        c["model"]["coupling"]["D"] = [[str(2 * Fraction(x)) for x in r] for r in D]
        code, why = hc.check(c)[:2]
        self.assertEqual(code, 1, why)
        self.assertIn("Lemma 1", why)

    def test_coupling_level_zero_leaves_k_undefined(self):
        c = example("multidof-coupling-case-ii.json")
        c["model"]["devices"][0]["osp"] = "0"
        self.assertIn(hc.check(c)[0], (1, 2))  # (14) fails first, or K = (T/2) Delta_D^-1 is undefined



class MultidofFeasibleSize(unittest.TestCase):
    def test_beyond_the_limit_is_said_before_the_model_is_read(self):
        # a 1.5 MB certificate of 48 DOFs spent 8 s parsing its 2,304 environment entries before
        # the size limit said "not checked": the limit is now read off A and D first (exit 3),
        # whatever the model holds (here a model that would not even parse)
        N, m = 80, 2
        c = {"certificate": "hapstab", "version": 1, "kind": "multidof-feasible",
             "model": {"T": "1/100", "environment": {"tf": [["(", "0"], ["0", "1"]]}},
             "claim": {"status": "exact", "feasible": True},
             "evidence": {"A": [["0"] * N for _ in range(N)], "D": [["0"] * m for _ in range(m)]}}
        code, why = hc.check(c)[:2]
        self.assertEqual(code, 3, why)
        self.assertIn("N + m <= 80", why)


if __name__ == "__main__":
    unittest.main()
