#!/usr/bin/env python3
"""tests/verify/indep_roots.py (the `stability_long` reference's spectrum) against the loop matrix itself:
det(zI - M) = z^n A + B_0 + K B_1 against numpy.poly(M) for short delays (every plant and controller family of
indep_loop.gen_stability; to 1e-6 of the largest coefficient, np.poly's own rounding), and loop_roots against numpy.linalg.eigvals(M) at delays of 201-400 samples: the
spectral radius within 1e-9 (double precision on both sides; the reference polishes roots near the circle at
40 digits afterwards), each eigenvalue within 1e-7 of a root (a double root at z = 1 splits by ~1e-8 in eigvals).
Also the exact zero roots: B = 0 (the overall gain at K = 0) and z dividing both terms; and
indep_loop.minus_one_every_K (the reference's exact sup 0 for an undamped device under a Tustin wall) against
the roots.

    python3 tests/verify/test_indep_roots.py        (unittest; ctest verify_indep_roots)"""
import os
import random
import sys
import unittest
from fractions import Fraction as Q

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import indep_loop as IL  # noqa: E402
import indep_roots as IR  # noqa: E402
from indep_common import Rational  # noqa: E402


def loop_of(rng, n):
    c = IL.gen_stability(rng)
    c["n"] = n
    return c, IL.build_loop_1dof(c)


def gains(rng, c):
    return [0.0, 1.0, float(c["Knom"]) * rng.uniform(0.01, 3)]


class CharacteristicPolynomial(unittest.TestCase):
    def test_the_formula_is_det_of_the_loop_matrix(self):
        rng = random.Random(11)
        families = set()
        for _ in range(60):
            c, loop = loop_of(rng, rng.randint(1, 8))
            families.add((c["tags"].get("plant"), c["tags"].get("controller")))
            A, (B0, B1) = IR.loop_charpoly_parts(loop)
            for K in gains(rng, c):
                want = np.poly(loop.M_np(K))
                B = np.polyadd(np.array([float(x) for x in B0]), K * np.array([float(x) for x in B1]))
                got = np.polyadd(np.concatenate([[float(x) for x in A], np.zeros(loop.n)]), B)
                self.assertEqual(len(got), len(want))
                # np.poly expands numpy's eigenvalues of M (double; its error grows with ||M||, K up to 1e7):
                # 1e-6 of the largest coefficient still tells a wrong formula (O(1): a sign flipped gives 2)
                self.assertLess(np.max(np.abs(got - want)), 1e-6 * max(1.0, np.max(np.abs(want))), (c["tags"], K))
        self.assertGreaterEqual(len(families), 15)  # the draws reach most plant x controller pairs


class Roots(unittest.TestCase):
    def test_aberth_against_the_dense_eigenvalues(self):
        rng = random.Random(12)
        accepted = 0
        for _ in range(8):
            c, loop = loop_of(rng, rng.randint(201, 400))
            for K in gains(rng, c)[1:]:
                z = IR.loop_roots(loop, K)
                if z is None:  # the caller falls back to the dense problem; rare (counted below)
                    continue
                accepted += 1
                ev = np.linalg.eigvals(loop.M_np(K))
                self.assertEqual(len(z), len(ev))
                self.assertLess(abs(np.abs(z).max() - np.abs(ev).max()), 1e-9, c["tags"])
                self.assertLess(np.abs(ev[:, None] - z[None, :]).min(axis=1).max(), 1e-7, c["tags"])
        self.assertGreaterEqual(accepted, 14)

    def test_exact_zero_roots(self):
        """H0 = 0 (the overall gain) at K = 0: det(zI - M) = z^n A, so n + 1 roots at 0 (the controller's pole at
        0 too) and A's; and a controller K/z beside H0 = 0 with the plant's numerator of degree 0: z divides
        both terms once more."""
        T = Q(1, 1000)
        c = dict(P=Rational([1], [Q(1, 2), Q(3), 0]), H0=Rational([0], [1]), H1=Rational([1 + 5 / T, -5 / T], [1, 0]),
                 T=T, n=250)
        loop = IL.build_loop_1dof(c)
        z = IR.loop_roots(loop, 0.0)
        self.assertEqual(len(z), loop.N)
        self.assertEqual(int(np.sum(z == 0)), 251)
        ev = np.linalg.eigvals(loop.M_np(0.0))
        self.assertLess(abs(np.abs(z).max() - np.abs(ev).max()), 1e-12)
        z1 = IR.loop_roots(loop, 1000.0)
        ev1 = np.linalg.eigvals(loop.M_np(1000.0))
        self.assertLess(abs(np.abs(z1).max() - np.abs(ev1).max()), 1e-9)


class RootAtMinusOne(unittest.TestCase):
    def test_undamped_device_under_a_tustin_wall(self):
        """indep_loop.minus_one_every_K against the roots: an undamped device (mass, spring, negative spring) under
        a Tustin wall has a root at z = -1 at every K; damped, or under a backward-difference wall, it has none."""
        T, n = Q(1, 1000), 230
        tustin = Rational([2 * 5 / T, -2 * 5 / T], [1, 1])
        backward = Rational([5 / T, -5 / T], [1, 0])
        for den, H0, want in (([Q(2, 5), 0, 0], tustin, True), ([Q(8, 5), 0, Q(109, 2)], tustin, True),
                              ([1, 0, -30], tustin, True), ([1, Q(1, 2), 0], tustin, False), ([1, 0, 0], backward, False)):
            c = dict(P=Rational([1], den), H0=H0, H1=Rational([1], [1]), T=T, n=n)
            self.assertIs(IL.minus_one_every_K(c), want, den)
            loop = IL.build_loop_1dof(c)
            for K in (0.001, 1.0, 300.0):
                z = IR.loop_roots(loop, K)
                if z is None:
                    z = np.linalg.eigvals(loop.M_np(K))
                self.assertIs(bool(np.abs(z + 1).min() < 1e-7), want, (den, K))


if __name__ == "__main__":
    unittest.main()
