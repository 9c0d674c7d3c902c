#!/usr/bin/env python3
"""An independent checker of hapstab certificates (issue 47): it shares no code with hapstab.

    python3 checks/hapstab_check.py CERT.json        "verified" (exit 0), "refuted: <why>" (exit 1),
                                                     "malformed: <field>" (exit 2),
                                                     "not checked: <why>" (exit 3, beyond the size limit)
    python3 checks/hapstab_check.py --batch FILE     one certificate per line, one JSON verdict per line
    python3 checks/hapstab_check.py --files CERT...  one JSON verdict per file, with the seconds its
                                                     check took (hapstab reproduce runs it so)

Exact rationals are gmpy2's mpq (GMP, Debian's python3-gmpy2, under the name Fraction below: the same
arithmetic as Python's fractions, 2-3 times faster; Python's fractions where gmpy2 is not installed; text is
always read by Python's fractions, so what is accepted as a number does not depend on it); its own intervals
with dyadic endpoints (class Iv: integers over 2^e, rounded outward) for the hold's e^(A h) and the Stein
tests of loops; mpmath's interval arithmetic (iv) only for the enclosure of cot in `r` and of c(e^(j pi t))
on arcs in `stability`'s argument principle. It reads the model as written (the expression of H(z) with its
own parser, below) and derives every quantity by a route other than hapstab's (docs/certificates.md).

Kinds and theorems:

bound  b* = sup_{0<=w<=pi/T} Re{T H(z) z^-n e^{-j w t_d}/(1-z)} + eta, z = e^{jwT} (paper 001,
       (45)/(54)), t_d = model.frac_delay (0 when absent).
       Route: tau = n + t_d/T = P/q, phi = wT/q in [0, pi/q], w = e^{j phi}, so z = w^q and the delay
       is w^-P; t = tan(phi/2), w = (1+jt)/(1-jt). With Nw(w) = N(w^q), Dw(w) = D(w^q) w^P and
       d = max(deg Nw, deg Dw): Nw = Nt(t)/(1-jt)^d, Dw = Dt(t)/(1-jt)^d, and
       T/(1 - w^q) = T (1-jt)^q/((1-jt)^q - (1+jt)^q) = (jT/2)(1-jt)^q/Sq(t), Sq = Im (1+jt)^q, so
           f = -(T/2) Im{Nt conj(Dt) (1-jt)^q} / (|Dt|^2 Sq(t)) + eta
       (q = 1: (T/2)[Gr - Gi/t]/|Dt|^2 with G = Nt conj(Dt)). f is even in t (f(-phi) = f(phi)):
       numerator and Sq are odd, so dividing both by t gives E(u)/F(u) in u = t^2 >= 0
       (F = |Dt|^2 Sq/t > 0 on the band: Sq/t = (1+u)^(q/2) sin(q phi/2)/t); with
       u = (1-c)/(1+c), c = cos(phi), and m = max(deg E, deg F):
           f(c) = (T/2) E^(c)/F^(c) + eta,  E^(c) = sum e_i (1-c)^i (1+c)^(m-i), F^ likewise,
       on the band c in [cos(pi/q), 1] (F^ >= 0 there). Claim b* in [lo, hi] (or = v):
         upper  P = (hi - eta) F^ - (T/2) E^ >= 0 on [c_lo, 1], c_lo = evidence.domain_c_lo (-1 when
                absent) shown <= cos(pi/q) by some R_k(u(c_lo)) <= 0, k <= q, R_k(u) = Re (1+jt)^k =
                (1+u)^(k/2) cos(k phi/2), all > 0 iff phi < pi/q; or P (1+c)^k R_q(u(c)) >= 0 there (> 0
                inside the band: the test across an irrational end where f -> -inf). Nonnegativity:
                the distinct roots of P in [c_lo, 1] isolated by bisection with Sturm counts of P's
                square-free part, P > 0 at both ends of every isolating interval and >= 0 at the ends
                (P keeps its sign between roots);
         lower  the witness c0 in the band (R_k(u0) > 0 for k < q and R_q(u0) >= 0; c0 = -1 only for
                q = 1) with f(c0) >= lo, exactly, f evaluated on E^/F^ reduced by their gcd (at a
                removable point the value is f's limit, which the sup reaches).
       b* = +inf: the forms above at a pole, or without expanding the delay: at z = -1 (pole_at_z,
       bound_infinite_at_minus_one) or at a simple pole inside the band (pole_on_circle, status certified,
       bound_infinite_on_circle: f = Im(k)/(theta - theta0) + O(1), Im(k) shown nonzero in intervals).
r      r(jw) = T/(e^{jwT}-1) = -T/2 - j (T/2) cot(wT/2) (paper 001, (44)): Re r = -T/2 exactly;
       Im r in [im_lo, im_hi] by mpmath interval cot at 128, 256, ... 65536 bits.
stability  the one-DOF sampled loop (device P(s), operator Z_op(s), ZOH, force = -z^-n H(z) x):
       P_eff = P/(1 + s Z_op P) = N(s)/s^k (every pole at s = 0, else not modelled here: exit 2);
       its zero-order hold from the pulse response (sampled_device); the characteristic
       polynomial c = z^n L (z-1)^k + A Nd (H = A/L); evidence.charpoly must be a multiple of it;
       the verdict by the Schur-Cohn recursion in exact fractions (schur_cohn).

       model.scene (stability --scene, a one-DOF scene's TOML text, with model.set its --set values): the
       loop read from the scene here (scene_loop_model, tomllib): [[device]] m, b -> P = 1/(m s^2 + b s),
       tf G -> G/s; [[operator]] m, b, k -> Z_op = m s + b + k/s, tf Z with mass [mo] -> Z + mo s;
       [environment] tf in z, or in s with backward_euler s = (z-1)/(T z) or tustin 2(z-1)/(T(z+1)),
       times gain -> H; [delay] time/T or samples, a whole number; each parameter replaced by its
       definition in parentheses. Anything else (two DOF, count, ss, [coupling], [contact], ...): exit 2.

stability-max  K_max = sup{K0 > 0 : the loop above stable for every K in (0, K0)}, H = H0 + K H1
       (prove_affine): the family c(z; K) = z^n L (z-1)^k + (A0 L/L0 + K A1 L/L1) Nd = c0 + K c1
       (L = lcm(L0, L1), deg c1 < deg c0 = d). D(K) = Res_{d,d}(c, c*), c* = z^d c(1/z), vanishes
       iff c has a pair of roots b, 1/b -- every root on the circle is one -- so on an interval
       without a root of D the loop is stable at every K or at none. Stable at stable_at in (0, lo)
       and D root-free on (0, lo): K_max >= lo; the loop at hi NOT stable: K_max <= hi; NOT stable
       at unstable_at = e and D root-free on (0, e] (or D = 0): K_max = 0; +inf: stable_at and D
       root-free on (0, inf). D by Sylvester determinants (Bareiss, integers) at K = -d .. d and
       Lagrange interpolation; its roots by Sturm sequences (positive_roots).

wedge  paper 002's wedge criterion (25) Re H + cot(theta/2)|Im H| + 1 > 0 and Tsypkin's (21)
       Re H + 1 > 0 on theta in [0, pi], and the assumptions H stable, (1+H)^-1 stable, H(1) >= 0.
       Route: u = tan^2(theta/2) in [0, inf) (wedge_polys): Re H = Gr/F, Im H cot(theta/2) = Jt/F,
       so (25) is max(Gr + Jt + F, Gr - Jt + F) > 0 on [0, inf) and H(-1) + 1 > 0 (theta = pi);
       [0, inf) is [0, B] with B a Cauchy bound of every root (max_positive: Sturm isolation).
       Assumptions by schur_cohn on D and D + N, H(1) exactly.
passivity-level-mimo  phi* = min over theta of lambda_min(He G(e^{j theta})), G = C(zI - A)^-1 B + D square,
       A Schur stable (schur_cohn on det(zI - A), by Faddeev-LeVerrier). Route: Q(u) (mimo_level_poly),
       u = tan^2(theta/2), interpolated from exact determinants of He G - lo I at circle points; phi* >= lo
       iff He G - lo I > 0 at one point of every arc between the roots of Q(t^2) in t >= 0 (and theta = pi)
       (Sylvester: leading minors); phi* <= hi if He G - hi I is not > 0 at the witness; an exact v by
       phi* >= v and a root on the circle (mimo_lower). OSP (model.kind "osp"): the same with the pencil
       He G - nu G^H G for He G - nu I (delta* = min lambda_min(He G^-1)), given det G != 0 on the circle
       (mimo_regular_on_circle: |det G|^2 interpolated likewise, no root for t in [0, inf), G(-1) regular)
       and lo > 0.
limit-cycle  a periodic orbit of paper 002's loop (4), y = -k H(z) x, x = max(y, -rho): H = N/D reduced
       (D monic, degree n), the difference equation D(z) y = -k N(z) x run P steps from the window
       evidence.y = (y_0..y_{n-1}) (lc_next: the unique solution of each step, 1 + k H(inf) > 0); the window
       must repeat (a P-periodic solution), P must be the least period (no P/p-periodicity, p | P prime),
       the amplitude (max - min)/2, its printed decimal (half a unit), the samples with y < -rho exact;
       attracting iff the product J of the steps' companion Jacobians is Schur stable (Faddeev-LeVerrier,
       schur_cohn), claimed only when no sample lies on y = -rho.
multidof-witness  paper 000's Theorem 5 program (16) infeasible for the scene's environment as written
       (E(z) entries, in z or in s by backward Euler/Tustin, its gain, the delay z^-n, the devices' levels
       Delta_D, the operators): every point of (16) has phi_X(z, u) = Re(u^T X E-hat(z) u) + u^T Delta_D X u
       > 0, E-hat = T z/(z-1) z^-n g E (11); the admissible X have X E(1) symmetric (else phi -> -inf at
       theta -> 0+), one multiplier per group of operators coupled through E(1), the ratios within a group
       g_b / g_a = E(1)_ij / E(1)_ji (i in a, j in b) found along the pairs (none admissible: refused). Route: the
       s-entries parsed with s the rational function of z itself, evaluated at the rational z of the
       evidence in Gaussian rationals; phi per group <= 0, one < 0. Several weighted points (evidence.points,
       the several-frequency witness where X has several free directions): sum_j w_j phi per group.
multidof-facial  paper 000's (16) infeasible because no X = diag(g) != 0 (one g per operator) makes X E(1)
       symmetric (then phi -> -inf at theta -> 0+ for every admissible X): the linear system
       g_a E(1)_ij = g_b E(1)_ji (i < j) has full column rank, by its own elimination in fractions; E(1)
       from the model's entries (perturb_C applied), the gain != 0. No evidence.
multidof-feasible  paper 000's (16) feasible: the evidence's realisation (A, B, C, D) equals the model's
       E-hat = T z/(z-1) z^-n g E(z) at N + n + d + 2 integer points (so identically), and the point (P, X,
       Q_E, Q_V) passes P > 0, M1 <= 0, (14) > 0, Q_V > 0, X = diag(g) with g >= 1 per operator, by
       symmetric elimination in fractions.
multidof-feasible-symmetric  the same claim for a scene of alike DOFs, one point per block of its split
       (paper 000's (16) under the permutations within `classes`): one-DOF operators, the OSP level equal
       within each class, and E invariant (E(i, i) = E(a0, a0); E(i, k) = E(a0, a1) or E(a0, c0)) are
       checked on all m^2 entries as reduced rational functions; the blocks' E are formed here,
       E_f(a, c) = sum_{j in class c} E(a0, j) and e_a = E(a0, a0) - E(a0, a1), and each block's point
       passes multidof-feasible's test with g > 0 (the lift scales it to g >= 1: multidof/symmetry.hpp).
multidof-coupling  paper 000's Theorem 4 for the model's coupling V (A, B, C, D): (16) at the evidence's point as
       multidof-feasible, and Lemma 1 for V-hat (17) (built here from V and K = (T/2) Delta_D^-1) at its X and
       Q_V: P_V > 0 and F <= 0 by symmetric elimination in fractions.
multidof-coupling-symmetric  the same for a V of one block per DOF designed on the split: (16) by the split as
       multidof-feasible-symmetric, each block's X, Q_E, Q_V a positive multiple of the image of the whole's
       invariant diagonal (g, q_E, q_V), g >= 1, q_V > 0; Lemma 1 for each DOF's V-hat_i at (g, q_V) of its class.
Size limit: stability-loop-symmetric: 128 DOFs (hapstab check: 256); multidof-feasible: N + m <= 80 (multidof-coupling: also nV + m <= 80; each block's, for -symmetric, with m <= 512 DOFs in all); multidof-witness: m <= 64 DOFs; limit-cycle: P n <= 40000; passivity-level-mimo: m n <= 24 (inputs x states); stability: a characteristic polynomial of degree <= 400 (<= 10000 by the argument principle); stability-max: degree <= 40; stability-loop: M's order <= 100 (hapstab check: 1024); stability-loop-max: intervals x n^3 <= 10^6
(its 81 Sylvester determinants of order 80 take ~17 s there); bound models of degree
max(q deg N, q deg D + P, q) <= 64 (max(deg N, deg D + n) for an integer delay; exact Sturm
sequences in Python's fractions grow fast: degree 41 takes 1.3 s, degree 101 two minutes); beyond
it exit 3.
"""
import json
import re
import sys
import time
from fractions import Fraction as TextFraction
try:
    from gmpy2 import mpq as Fraction  # Python's fractions on GMP (Debian's python3-gmpy2)
except ImportError:  # the same values, 2-3 times slower
    Fraction = TextFraction
import math
from math import comb, gcd



def text_fraction(txt):
    """The number a decimal text writes, exactly; an exponent of more than 6 digits is refused (ValueError), as
    hapstab's reader refuses it: 10^999999999 is a typo, and writing it out would take this checker hours."""
    m = re.search(r"[eE][+-]?([0-9]+)$", txt.strip())
    if m and len(m.group(1).lstrip("0")) > 6:
        raise ValueError("exponent beyond 6 digits")
    return Fraction(TextFraction(txt))


MAX_DEGREE = 64
# b* = +inf at the band's irrational end (bound_infinite_at_end): gcds and Sturm counts on one short
# interval, no full-band sequence: 1-2 s at degree 199 (reproduce's q = 100), so a higher limit
MAX_END_DEGREE = 200
if hasattr(sys, "set_int_max_str_digits"):
    sys.set_int_max_str_digits(0)  # exact numbers of any length (Python 3.11 limits str -> int to 4300 digits)


class Malformed(Exception):
    pass


class TooLarge(Exception):
    pass


# ---------------------------------------------------------------- polynomials (ascending lists)
def trim(p):
    p = list(p)
    while p and p[-1] == 0:
        p.pop()
    return p


def padd(a, b):
    n = max(len(a), len(b))
    return trim([(a[i] if i < len(a) else 0) + (b[i] if i < len(b) else 0) for i in range(n)])


def pneg(a):
    return [-x for x in a]


def psub(a, b):
    return padd(a, pneg(b))


def integers(a):
    """(A, L): a = A / L with A integers and L > 0 the lcm of a's denominators."""
    L = 1
    for x in a:  # ints and Fractions both have numerator and denominator
        if L % x.denominator:
            L = L * x.denominator // gcd(L, x.denominator)
    return [x.numerator * (L // x.denominator) for x in a], L


def pmul(a, b):
    """a b, convolved in integers over the common denominators (a Fraction per product is ~10x slower)."""
    if not a or not b:
        return []
    (A, la), (B, lb) = integers(a), integers(b)
    out = [0] * (len(A) + len(B) - 1)
    for i, x in enumerate(A):
        if x == 0:
            continue
        for j, y in enumerate(B):
            out[i + j] += x * y
    d = la * lb
    return trim([Fraction(c, d) for c in out])


def pscale(a, k):
    return trim([x * k for x in a])


def pdivmod(a, b):
    a = list(a)
    if not b:
        raise ZeroDivisionError
    q = [Fraction(0)] * max(len(a) - len(b) + 1, 0)
    while len(a) >= len(b) and a:
        k = Fraction(a[-1]) / b[-1]
        s = len(a) - len(b)
        q[s] = k
        for i, y in enumerate(b):
            a[s + i] -= k * y
        a.pop()
        a = trim(a)
    return trim(q), a


def pgcd(a, b):
    a, b = trim(a), trim(b)
    while b:
        a, b = b, pdivmod(a, b)[1]
    if not a:
        return a
    return [x / a[-1] for x in a]


def pderiv(a):
    return trim([i * a[i] for i in range(1, len(a))])


def peval(a, x):
    v = Fraction(0)
    for c in reversed(a):
        v = v * x + c
    return v


def ppow(a, n):
    r = [Fraction(1)]
    for _ in range(n):
        r = pmul(r, a)
    return r


# ---------------------------------------------------------------- rational functions in z
class RF:
    def __init__(self, num, den=None):
        self.num = trim(num)
        self.den = trim(den) if den is not None else [Fraction(1)]
        if not self.den:
            raise ZeroDivisionError
        self.reduce()

    def reduce(self):
        if not self.num:
            self.den = [Fraction(1)]
            return
        g = pgcd(self.num, self.den)
        if len(g) > 1:
            self.num = pdivmod(self.num, g)[0]
            self.den = pdivmod(self.den, g)[0]
        lead = self.den[-1]
        self.num = [x / lead for x in self.num]
        self.den = [x / lead for x in self.den]

    def __add__(self, o):
        return RF(padd(pmul(self.num, o.den), pmul(o.num, self.den)), pmul(self.den, o.den))

    def __sub__(self, o):
        return RF(psub(pmul(self.num, o.den), pmul(o.num, self.den)), pmul(self.den, o.den))

    def __mul__(self, o):
        return RF(pmul(self.num, o.num), pmul(self.den, o.den))

    def __truediv__(self, o):
        if not o.num:
            raise Malformed("model.H: division by zero")
        return RF(pmul(self.num, o.den), pmul(self.den, o.num))

    def __neg__(self):
        return RF(pneg(self.num), self.den)

    def degree(self):
        return max(len(self.num), len(self.den)) - 1

    def __eq__(self, o):  # reduced, the denominator monic: equal as functions iff equal here
        return isinstance(o, RF) and self.num == o.num and self.den == o.den
    __hash__ = None


# ---------------------------------------------------------------- the expression of H(z), as written
LEX = re.compile(r"[ \t\n\r\x0b\x0c]*(?:([0-9.]+(?:[eE][+-]?[0-9]+)?)|([A-Za-z_][A-Za-z0-9_]*)|([-+*/^()])|(\Z))")


def lex(text):
    """Tokens of an expression: numbers (digits and dots, an exponent e[+-]digits), names (ASCII letters, digits,
    _), the characters + - * / ^ ( ); ASCII whitespace between (C's isspace, as hapstab's lexer); anything else
    is malformed."""
    toks, i = [], 0
    while True:
        m = LEX.match(text, i)
        if m is None:
            j = i + len(text[i:]) - len(text[i:].lstrip(" \t\n\r\x0b\x0c"))
            raise Malformed("model.H: unexpected character %r" % text[j])
        num, name, op, end = m.groups()
        if end is not None:
            break
        toks.append(('num', num) if num is not None else ('name', name) if name is not None else (op, op))
        i = m.end()
    toks.append(('end', ''))
    return toks


class ScenePlant(str):
    """The plant text "(G)/s" scene_loop_model writes for a device given by its velocity G(s): the s it
    cancels when G(0) = 0 is this checker's own integrator (the position offset, a conserved quantity, as
    hapstab's scene loop reads the device), not the scene's text. A certificate's JSON never holds one."""


def parse_h(text, T, params, var='z', field='model.H', leaf=None, marginal=False):
    """H(var) of the expression: + - * / ^ (integer exponents), unary +/-, parentheses, numbers,
    the variable var (z or s), T and the parameters; -z^2 is -(z^2); a^b^c is refused.
    `leaf(kind, text, value)` builds the leaves in another algebra (Deg: degree bounds). A pole the
    expression writes and an operation cancels on or outside the stable region is malformed (realised as
    written, a hidden mode), unless `marginal` (b*: the frequency response) and H as written is marginally
    stable."""
    try:
        return _parse(text, T, params, var, leaf or rf_leaf, marginal, isinstance(text, ScenePlant))
    except Malformed as e:
        raise Malformed(str(e).replace("model.H", field, 1))


def rf_leaf(kind, txt, value):
    """A leaf of the expression as a rational function: a number, the variable, a parameter, T."""
    return RF([Fraction(0), Fraction(1)]) if kind == 'var' else RF([value])


class Deg:
    """Upper bounds (n, d) of the degrees of the numerator and the denominator of an expression as
    a rational function of one parameter K over Q(z): K is (1, 0), anything else (0, 0);
    p1/q1 + p2/q2 = (p1 q2 + p2 q1)/(q1 q2), and so on."""
    num = [1]  # never refused as a divisor here (the parses at values of K are)

    def __init__(self, n, d):
        self.n, self.d = n, d

    def __add__(self, o):
        return Deg(max(self.n + o.d, o.n + self.d), self.d + o.d)

    __sub__ = __add__

    def __mul__(self, o):
        return Deg(self.n + o.n, self.d + o.d)

    def __truediv__(self, o):
        return Deg(self.n + o.d, self.d + o.n)

    def __neg__(self):
        return self

    def degree(self):
        return 0


def cancelled_pole(op, a, b, r):
    """The factor an operation cancels from the denominators the expression writes: the written one
    (a.den b.den for *, a.den b.num for /, lcm(a.den, b.den) for + and -) over the result's; [1] when
    nothing is cancelled or a product or quotient is 0 (a zero gain removes its branch)."""
    if op in '*/' and not r.num:
        return [Fraction(1)]
    right = b.num if op == '/' else b.den
    if len(r.den) == len(a.den) + len(right) - 1:
        return [Fraction(1)]  # the result's denominator is the written one
    if op in '+-':
        if a.den == b.den:
            return pdivmod(a.den, r.den)[0]
        g = pgcd(a.den, b.den)
        written = pdivmod(pmul(a.den, b.den), g)[0]
    else:
        written = pmul(a.den, right)
    removed, rest = pdivmod(written, r.den)
    assert not trim(rest), "the result's denominator divides the written one"
    return removed


def marginally_stable(d):
    """(True, why) when every root of d (ascending, non-zero) has |z| <= 1 and those with |z| = 1 are simple:
    g = gcd(d, z^n d(1/z)) holds the roots on the circle and the pairs (r, 1/r); the rest, d/g, must pass
    Schur-Cohn; g must be square-free with every root on the circle: without its factors z - 1 and z + 1, g is
    z^k P(z + 1/z) (P(w) = g_k + sum_j g_(k+j) D_j(w), D_j the Dickson polynomials z^j + z^-j) and P must have
    k distinct real roots in (-2, 2) (Sturm)."""
    d = trim(d)
    g = pgcd(d, d[::-1])
    if len(g) > 1 and not schur_cohn(pdivmod(d, g)[0])[0] or len(g) <= 1 and not schur_cohn(d)[0]:
        return False, "a root outside the unit circle"
    if len(g) <= 1:
        return True, "every root inside"
    if len(pgcd(g, pderiv(g))) > 1:
        return False, "a repeated root on the unit circle (or a repeated pair r, 1/r)"
    for r in (Fraction(1), Fraction(-1)):
        if peval(g, r) == 0:
            g = pdivmod(g, [-r, Fraction(1)])[0]
    if len(g) == 1:
        return True, "simple roots on the unit circle"
    k = (len(g) - 1) // 2
    if (len(g) - 1) % 2 or g != g[::-1]:
        return False, "a pair of roots r, 1/r off the unit circle"
    P, Dm, Dj = [g[k]], [Fraction(2)], [Fraction(0), Fraction(1)]  # D_0 = 2, D_1 = w
    for j in range(1, k + 1):
        P = padd(P, pscale(Dj, g[k + j]))
        Dm, Dj = Dj, psub(pmul([Fraction(0), Fraction(1)], Dj), Dm)
    seq = sturm_seq(P)
    if variations(seq, Fraction(-2)) - variations(seq, Fraction(2)) != k:
        return False, "a pair of roots r, 1/r off the unit circle"
    return True, "simple roots on the unit circle"


def _parse(text, T, params, var, leaf, marginal=False, integrator=False):
    toks = lex(text)
    pos = [0]
    hidden = [[Fraction(1)]]  # the product of the factors cancelled with a root on or outside the stable region

    def combine(op, a, b):
        r = a + b if op == '+' else a - b if op == '-' else a * b if op == '*' else a / b
        if leaf is rf_leaf:  # a pole written and cancelled stays a hidden mode, realised as written
            removed = cancelled_pole(op, a, b, r)
            if len(trim(removed)) > 1 and not (schur_cohn(removed) if var == 'z' else hurwitz(removed))[0]:
                hidden[0] = pmul(hidden[0], removed)
                if len(hidden[0]) - 1 > MAX_DEGREE:  # H as written beyond the degree limit: refused
                    raise TooLarge("model.H: the poles it cancels on or outside the stable region pass degree %d: "
                                   "realised as written, hidden modes" % MAX_DEGREE)
        return r

    def peek():
        return toks[pos[0]][0]

    def take():
        t = toks[pos[0]]
        pos[0] += 1
        return t

    def expr(depth):
        r = term(depth)
        while peek() in '+-' and peek() != 'end':
            op = take()[0]
            r = combine(op, r, term(depth))
        return r

    def term(depth):
        r = unary(depth)
        while peek() in ('*', '/'):
            op = take()[0]
            r = combine(op, r, unary(depth))
        return r

    def unary(depth):
        neg = False
        while peek() in ('+', '-'):
            neg ^= take()[0] == '-'
        r = power(depth)
        return -r if neg else r

    def power(depth):
        base = primary(depth)
        if peek() != '^':
            return base
        take()
        paren = False
        if peek() == '(':
            paren = True
            take()
        sign = 1
        if peek() in ('+', '-'):
            sign = -1 if take()[0] == '-' else 1
        kind, txt = take()
        if kind != 'num' or not txt.isdigit() or len(txt) > 4:
            raise Malformed("model.H: expected an integer exponent after '^'")
        k = sign * int(txt)
        if paren and take()[0] != ')':
            raise Malformed("model.H: expected ')' to close the exponent")
        if peek() == '^':
            raise Malformed("model.H: a^b^c is ambiguous")
        if abs(k) * max(base.degree(), 0) > MAX_DEGREE:
            raise TooLarge("model.H: a power of degree above %d" % MAX_DEGREE)
        if k < 0:
            if not base.num:
                raise Malformed("model.H: division by zero")
            base = leaf('num', '1', Fraction(1)) / base
            k = -k
        r = leaf('num', '1', Fraction(1))
        for _ in range(k):
            r = r * base
        return r

    def primary(depth):
        kind, txt = take()
        if kind == 'num':
            try:
                return leaf('num', txt, text_fraction(txt))
            except (ValueError, ZeroDivisionError):
                raise Malformed("model.H: malformed number %r" % txt)
        if kind == 'name':
            if txt == var:
                return leaf('var', txt, None)
            if txt == 'T':  # the sample period, never a parameter (parameters() refuses model.set.T)
                return leaf('name', txt, T)
            if txt in params:
                return leaf('name', txt, params[txt])
            raise Malformed("model.H: unknown name %r" % txt)
        if kind == '(':
            if depth > 200:
                raise Malformed("model.H: parentheses nested too deep")
            r = expr(depth + 1)
            if take()[0] != ')':
                raise Malformed("model.H: expected ')'")
            return r
        raise Malformed("model.H: expected a number, a name or '('")

    h = expr(0)
    if peek() != 'end':
        raise Malformed("model.H: unexpected %r" % toks[pos[0]][1])
    allowed = (marginal and var == 'z' and marginally_stable(pmul(h.den, hidden[0]))[0] or
               integrator and var == 's' and len(hidden[0]) == 2 and hidden[0][0] == 0)  # the factor s, once
    if len(hidden[0]) > 1 and not allowed:
        raise Malformed("model.H: an operation cancels a pole the expression writes on or outside the stable region "
                        "(%s): realised as written it is a hidden mode" % ('|z| >= 1' if var == 'z' else 'Re s >= 0'))
    return h


# ---------------------------------------------------------------- certificate fields
def exact(obj, key, where):
    if not isinstance(obj, dict) or key not in obj:
        raise Malformed("%s.%s: missing" % (where, key))
    return exact_value(obj[key], "%s.%s" % (where, key))


def exact_value(v, what):
    if not isinstance(v, str):
        raise Malformed("%s: expected a string \"p/q\"" % what)
    s = v[1:] if v.startswith('-') else v
    parts = s.split('/')
    if len(parts) > 2 or not all(p.isascii() and p.isdigit() for p in parts):
        raise Malformed("%s: %r is not \"p/q\" or \"p\" (integers)" % (what, v[:60]))
    if len(parts) == 2 and int(parts[1]) == 0:
        raise Malformed("%s: divides by zero" % what)
    return Fraction(TextFraction(v))


def obj_field(c, key):
    if not isinstance(c, dict) or key not in c:
        raise Malformed("%s: missing" % key)
    if not isinstance(c[key], dict):
        raise Malformed("%s: not an object" % key)
    return c[key]


def only(obj, known, where):
    for k in obj:
        if k not in known:
            raise Malformed("%s.%s: a field this checker does not know (it would not be checked)" % (where, k))


def period(model):
    """model.T, the sample period, > 0."""
    T = exact(model, "T", "model")
    if T <= 0:
        raise Malformed("model.T: must be > 0")
    return T


def parameters(model):
    """model.set as {NAME: Fraction}."""
    sets = model.get("set", {})
    if not isinstance(sets, dict):
        raise Malformed("model.set: not an object")
    if "T" in sets:
        raise Malformed("model.set.T: T is the sample period (model.T), not a parameter")
    return {k: exact_value(v, "model.set." + k) for k, v in sets.items()}


def delay_of(model):
    """model.delay, an integer n in [0, 100000]."""
    n = model.get("delay")
    if not isinstance(n, int) or isinstance(n, bool) or n < 0 or n > 100000:
        raise Malformed("model.delay: missing, not an integer or outside [0, 100000]")
    return n


def coefficients(model, key):
    """model.num or model.den: "p/q" strings in descending powers of z, at most 201."""
    a = model.get(key)
    if not isinstance(a, list) or not a:
        raise Malformed("model.%s: missing or not a non-empty array of \"p/q\" (descending powers of z)" % key)
    if len(a) > 201:
        raise Malformed("model.%s: more than 201 coefficients" % key)
    return [exact_value(x, "model.%s[%d]" % (key, i)) for i, x in enumerate(a)]


def model_h(model, marginal=False):
    """(H, T): H(z) as written, with the sample period model.T > 0: model.H parsed with the
    parameters model.set, or its coefficients model.num and model.den (descending powers of z;
    `--num/--den`, a .mat's num and den), with no H and no set beside them."""
    T = period(model)
    if "num" in model or "den" in model:
        if "H" in model:
            raise Malformed("model: H and num/den both given (one model, written one way)")
        if "set" in model:
            raise Malformed("model.set: num/den hold numbers, not parameters")
        num, den = coefficients(model, "num"), coefficients(model, "den")
        if den[0] == 0:
            raise Malformed("model.den: the leading coefficient is 0")
        H = RF(num[::-1], den[::-1])
        lost = pdivmod(trim(den[::-1]), H.den)[0] if H.num else [Fraction(1)]
        if len(trim(lost)) > 1 and not schur_cohn(lost)[0] and not (marginal and marginally_stable(den[::-1])[0]):
            raise Malformed("model.num/den: they share a factor with a root on or outside the unit circle: realised "
                            "as written, a hidden mode")
        return H, T
    if not isinstance(model.get("H"), str):
        raise Malformed("model.H: missing or not a string (or num and den, its coefficients)")
    try:
        return parse_h(model["H"], T, parameters(model), marginal=marginal), T
    except ZeroDivisionError:
        raise Malformed("model.H: division by zero")


def printed_number(v, what):
    if not isinstance(v, str):
        raise Malformed("%s: not a string" % what)
    try:
        return text_fraction(v.strip())
    except (ValueError, ZeroDivisionError):
        raise Malformed("%s: %r is not a number" % (what, v))


def parts(c):
    """(model, claim, evidence) of a certificate whose top-level fields are the known ones."""
    only(c, ("certificate", "version", "kind", "model", "claim", "evidence", "produced_by"), "certificate")
    return obj_field(c, "model"), obj_field(c, "claim"), obj_field(c, "evidence")


def claim_range(claim, may_be_infinite=False):
    """(status, lo, hi, infinite, refuted): "exact" with value, or "certified" with lo, hi, or (where
    allowed) "infinite": true alone; the printed decimals must be the claimed numbers. Malformed when
    malformed; refuted (a reason, else None) when false on its face."""
    status = claim.get("status")
    if status not in ("exact", "certified"):
        raise Malformed("claim.status: missing or neither \"exact\" nor \"certified\"")
    infinite = claim.get("infinite", False) if may_be_infinite else False
    if not isinstance(infinite, bool):
        raise Malformed("claim.infinite: not true/false")
    if infinite:
        if any(k in claim for k in ("value", "lo", "hi", "printed", "printed_lo", "printed_hi")):
            raise Malformed("claim.infinite: true beside a finite value")
        return status, None, None, True, None
    if status == "exact":
        lo = hi = exact(claim, "value", "claim")
    else:
        lo, hi = exact(claim, "lo", "claim"), exact(claim, "hi", "claim")
        if lo > hi:
            return status, lo, hi, False, "claim: lo > hi"
    for key in ("printed_lo", "printed_hi", "printed"):
        if key in claim and printed_number(claim[key], "claim." + key) != (hi if key == "printed_hi" else lo):
            return status, lo, hi, False, "claim.%s = %s is not the claimed number" % (key, claim[key])
    return status, lo, hi, False, None


# ---------------------------------------------------------------- P >= 0 on [a, b]
def sturm_seq(p):
    seq = [p, pderiv(p)]
    while seq[-1] and len(seq[-1]) > 1:
        r = pdivmod(seq[-2], seq[-1])[1]
        if not r:
            break
        lead = abs(r[-1])
        seq.append([-x / lead for x in r])
    return seq


def variations(seq, x):
    signs = [s for s in (peval(q, x) for q in seq if q) if s != 0]
    return sum(1 for u, v in zip(signs, signs[1:]) if (u > 0) != (v > 0))


def nonneg_on(p, a, b):
    """None when p >= 0 on [a, b], else the reason."""
    if not p:
        return None
    for e in (a, b):
        if peval(p, e) < 0:
            return "negative at c = %s" % e
    sq = pdivmod(p, pgcd(p, pderiv(p)))[0] if len(p) > 2 else p  # square-free part
    if len(sq) <= 1:
        return None if p[-1] > 0 else "a negative constant"
    seq = sturm_seq(sq)

    def count(lo, hi):  # distinct roots in (lo, hi]
        return variations(seq, lo) - variations(seq, hi)

    # isolate the roots in (a, b) by bisection; check p > 0 at every non-root end point met
    stack = [(a, b)]
    while stack:
        lo, hi = stack.pop()
        n = count(lo, hi) - (1 if peval(sq, hi) == 0 else 0)  # roots in (lo, hi)
        for e in (lo, hi):
            v = peval(p, e)
            if v < 0:
                return "negative at c = %s" % e
        if n == 0:
            # no root inside: p keeps the sign it has at a non-root end
            for e in (lo, hi):
                v = peval(p, e)
                if v != 0:
                    break
            else:
                mid = (lo + hi) / 2
                if peval(p, mid) < 0:
                    return "negative at c = %s" % mid
            continue
        if n == 1 and peval(sq, lo) != 0 and peval(sq, hi) != 0 and peval(p, lo) > 0 and peval(p, hi) > 0:
            continue  # one root, p > 0 on both sides: p >= 0 on [lo, hi]
        if hi - lo < Fraction(1, 2 ** 4000):
            return "root isolation did not finish"
        mid = (lo + hi) / 2
        stack.append((lo, mid))
        stack.append((mid, hi))
    return None


# ---------------------------------------------------------------- bound
def spread(p, q):
    """p(w^q): the coefficients of p at the multiples of q."""
    out = [Fraction(0)] * ((len(p) - 1) * q + 1) if p else []
    for k, a in enumerate(p):
        out[k * q] = a
    return trim(out)


def objective_c(H, T, P, q, limit=MAX_DEGREE):
    """(E^, F^) with f(c) = (T/2) E^(c)/F^(c), c = cos(wT/q), by the tan route (module docstring);
    TooLarge above the degree `limit`."""
    Nw = spread(H.num, q)
    Dw = [Fraction(0)] * P + spread(H.den, q)  # D(w^q) w^P: the delay e^{-j tau wT} = w^-P
    d = max(len(Nw), len(Dw)) - 1
    if max(d, q) > limit:
        raise TooLarge("degree %d of H(w^q) w^-P (q = %d) is above this checker's limit %d" % (max(d, q), q, limit))

    # complex polynomials in t as (re, im) lists; 1 + jt and 1 - jt
    def cmul(x, y):
        return (psub(pmul(x[0], y[0]), pmul(x[1], y[1])), padd(pmul(x[0], y[1]), pmul(x[1], y[0])))
    plus = ([Fraction(1)], [Fraction(0), Fraction(1)])
    minus = ([Fraction(1)], [Fraction(0), Fraction(-1)])
    pw_plus, pw_minus = [([Fraction(1)], [])], [([Fraction(1)], [])]
    for _ in range(max(d, q)):
        pw_plus.append(cmul(pw_plus[-1], plus))
        pw_minus.append(cmul(pw_minus[-1], minus))

    def tilde(coeffs):
        re, im = [], []
        for k, a in enumerate(coeffs):
            if a == 0:
                continue
            x = cmul(pw_plus[k], pw_minus[d - k])
            re, im = padd(re, pscale(x[0], a)), padd(im, pscale(x[1], a))
        return re, im

    Nr, Ni = tilde(Nw)
    Dr, Di = tilde(Dw)
    G = (padd(pmul(Nr, Dr), pmul(Ni, Di)), psub(pmul(Ni, Dr), pmul(Nr, Di)))  # Nt conj(Dt)
    Gq = cmul(G, pw_minus[q])  # times (1 - jt)^q
    num = pneg(Gq[1])          # -Im(G (1 - jt)^q)
    Sq = pw_plus[q][1]         # Im (1 + jt)^q
    F = pmul(padd(pmul(Dr, Dr), pmul(Di, Di)), Sq)
    for p in (num, F):
        if any(p[i] != 0 for i in range(0, len(p), 2)):
            raise AssertionError("not odd in t")
    Eu, Fu = num[1::2], F[1::2]  # divided by t, in u = t^2
    m = max(len(Eu), len(Fu)) - 1
    pm = [[(-1) ** k * comb(i, k) for k in range(i + 1)] for i in range(m + 1)]  # (1 - u)^i
    pp = [[comb(i, k) for k in range(i + 1)] for i in range(m + 1)]              # (1 + u)^i

    def hat(p):
        out = []
        for i, a in enumerate(p):
            if a != 0:
                out = padd(out, pscale(pmul(pm[i], pp[m - i]), a))
        return out

    return hat(Eu), hat(Fu)


def re_power(k):
    """R_k(u) = Re (1 + jt)^k as a polynomial in u = t^2: sum_i C(k, 2i) (-u)^i."""
    out = []
    for i in range(0, k // 2 + 1):
        out.append(Fraction(comb(k, 2 * i)) * (-1) ** i)
    return trim(out)


def in_band(c0, q):
    """c0 = cos(phi0) with phi0 in [0, pi/q]: t = tan(phi0/2), R_k = Re (1 + jt)^k =
    (1 + t^2)^(k/2) cos(k phi0/2) is > 0 for k < q and >= 0 for k = q iff phi0 <= pi/q (if
    phi0 > pi/q, the first k with k phi0/2 > pi/2 has k phi0/2 in (pi/2, pi): cos < 0)."""
    if c0 < -1 or c0 > 1:
        return False
    if c0 == -1:
        return q == 1  # phi0 = pi
    u = (1 - c0) / (1 + c0)
    return all(peval(re_power(k), u) > 0 for k in range(1, q)) and peval(re_power(q), u) >= 0


def below_band_end(c_lo, q):
    """c_lo <= cos(pi/q), decided exactly: c_lo = -1, or R_k(u) <= 0 for some k = 1 .. q at
    u = tan^2(phi/2) of c_lo (phi/2 < pi/(2q) iff cos(k phi/2) > 0 for every k <= q: else the
    first k with k phi/2 >= pi/2 has k phi/2 in [pi/2, pi), cos <= 0)."""
    if c_lo == -1:
        return True
    if c_lo < -1 or c_lo > 1:
        return False
    u = (1 - c_lo) / (1 + c_lo)
    return any(peval(re_power(k), u) <= 0 for k in range(1, q + 1))


def end_multiplier(q):
    """(1 + c)^k R_q((1 - c)/(1 + c)), k = deg R_q: > 0 on (cos(pi/q), 1] (c > -1, R_q > 0 for
    phi < pi/q), a simple root at cos(pi/q)."""
    R = re_power(q)
    k = len(R) - 1
    out = []
    for i, a in enumerate(R):
        out = padd(out, pscale(pmul(ppow([Fraction(1), Fraction(-1)], i), ppow([Fraction(1), Fraction(1)], k - i)), a))
    return out


def short(x):
    s = str(x)
    return s if len(s) <= 60 else s[:57] + "..."


def check_bound(c):
    model, claim, evidence = parts(c)
    only(model, ("H", "set", "num", "den", "T", "delay", "frac_delay", "eta"), "model")
    only(claim, ("quantity", "status", "value", "lo", "hi", "printed", "printed_lo", "printed_hi", "infinite"), "claim")
    cells = "infinite" not in claim and "cells" in evidence
    integrator = "infinite" in claim and "integrator" in evidence  # H's pole at z = 1, nothing expanded
    if integrator:
        only(evidence, ("integrator",), "evidence")
    elif cells:
        only(evidence, ("cells", "witness_theta"), "evidence")
    elif "infinite" not in claim:
        only(evidence, ("witness_c", "domain_c_lo"), "evidence")
    # b* = +inf: bound_infinite_any checks the size where its form expands the delay
    H, T, eta, P, q = bound_model(model, expanded=not (cells or "infinite" in claim))
    status, lo, hi, infinite, refuted = claim_range(claim, may_be_infinite=True)
    if refuted:
        return False, refuted
    if "infinite" in claim and not infinite:
        raise Malformed("claim.infinite: false (a finite claim has no such field)")
    if integrator:
        return bound_integrator(H, status, evidence)
    if not infinite and peval(H.den, Fraction(1)) == 0:
        return False, ("b* finite fails: H has an uncancelled pole at z = 1 (an integrator), where b* = +inf whatever "
                       "the residue's sign (docs/commands.md)")
    if infinite:
        return bound_infinite_any(H, T, P, q, status, evidence, "evidence")
    if cells:
        return bound_cells(H, T, eta, Fraction(P, q), lo, hi, evidence)
    c0 = exact(evidence, "witness_c", "evidence")
    c_lo = exact(evidence, "domain_c_lo", "evidence") if "domain_c_lo" in evidence else Fraction(-1)
    E, F = objective_c(H, T, P, q)
    A = pscale(E, T / 2)
    why = upper_bound(A, F, hi - eta, c_lo, q)
    if why:
        return False, "b* <= %s (%.12g) fails: %s" % (hi, float(hi), why)
    why = lower_bound(A, F, lo - eta, c0, q)
    if why:
        return False, "b* >= %s (%.12g) not shown: %s" % (short(lo), float(lo), why)
    return True, ("b* = %s" % lo) if status == "exact" else "b* in [%.12g, %.12g]" % (float(lo), float(hi))


def bound_infinite_any(H, T, P, q, status, evidence, where):
    """b* = +inf by any form but the integrator's: the local form at z = -1 (pole_at_z) and the circle form
    (pole_on_circle), nothing expanded; or a pole of the objective in c (pole_c, side / pole_lo, pole_hi, side /
    end_lo, end_hi), the delay expanded (size limited as bound_model's). The claim's status is the form's:
    "certified" for the circle form (shown in intervals), "exact" otherwise. `where` names the evidence."""
    if "pole_at_z" in evidence:
        only(evidence, ("pole_at_z",), where)
        if status != "exact":
            raise Malformed("claim.status: b* = +inf at z = -1 is claimed \"exact\"")
        return bound_infinite_at_minus_one(H, P, q, evidence)
    if "pole_on_circle" in evidence:
        only(evidence, ("pole_on_circle",), where)
        if status != "certified":
            raise Malformed("claim.status: b* = +inf at a pole on the circle is claimed \"certified\" (shown in intervals)")
        return bound_infinite_on_circle(H, T, Fraction(P, q), evidence)
    only(evidence, ("pole_c", "side", "end_lo", "end_hi", "pole_lo", "pole_hi"), where)
    if P > 10 ** 6 or q > 10 ** 6:
        raise TooLarge("t_d/T has a numerator or denominator above 10^6")
    return bound_infinite(H, T, P, q, status, evidence)


def bound_integrator(H, status, evidence):
    """b* = +inf by H's simple uncancelled pole at z = 1 (H in lowest terms: N(1) != 0), whatever the sign of
    its residue r = N(1)/D'(1). The definition `bound` states (docs/commands.md), this checker's reading of it:
    near w = 0, 1 - z ~ -j wT and H ~ r/(j wT), so T H/(1 - z) ~ T r/(wT)^2 -> +inf for r > 0; for r < 0 (45)
    alone is finite, but (45) is sufficient only for H stable, and with a passive spring operator k_o/s the
    low-frequency loop m s^3 + b s^2 + k_o s + r/T has a negative constant term, so a root s > 0, for every b."""
    if status != "exact":
        raise Malformed("claim.status: b* = +inf is claimed \"exact\"")
    if evidence.get("integrator") is not True:
        raise Malformed("evidence.integrator: must be true (H's uncancelled pole at z = 1)")
    one = Fraction(1)
    if peval(H.den, one) != 0:
        return False, "b* = +inf not shown: z = 1 is not a pole of H"
    d1 = peval(pderiv(H.den), one)
    if d1 == 0:
        return False, "b* = +inf not shown: the pole of H at z = 1 is not simple"
    return True, "b* = +inf: H's simple pole at z = 1 (an integrator, r = %s)" % short(peval(H.num, one) / d1)


def bound_infinite_at_minus_one(H, P, q, evidence):
    """b* = +inf as wT -> pi from H's simple pole at z = -1 met by the delay nu = P/q (not an integer).
    This checker's own derivation: with z = e^{j theta}, H = G + r/(z + 1), r = N(-1)/D'(-1), G has no pole
    at -1, so Re{T G(z) e^{-j nu theta}/(1 - z)} stays bounded as theta -> pi (1 - z -> 2). The rest is
    T r Re{e^{-j nu theta}/(1 - z^2)}, and 1 - z^2 = z (z^-1 - z) = -2j sin(theta) z, so it equals
    T r Re{j e^{-j (nu + 1) theta}}/(2 sin theta) = T r sin((nu + 1) theta)/(2 sin theta). As theta -> pi
    from below, sin theta -> 0+ and sin((nu + 1) theta) -> sin(nu pi + pi) = -sin(nu pi), nonzero for nu
    not an integer: the objective -> +inf iff r sin(nu pi) < 0. For nu = P/q, P >= 0, sin(nu pi) has the
    sign (-1)^(P // q) (nu pi lies strictly between (P // q) pi and (P // q + 1) pi)."""
    if evidence.get("pole_at_z") != "-1":
        raise Malformed("evidence.pole_at_z: only \"-1\" is taken")
    if q == 1:
        return False, "b* = +inf not shown: the delay %d is a whole number of samples (sin(nu pi) = 0)" % P
    N, D = H.num, H.den
    m1 = Fraction(-1)
    if peval(D, m1) != 0:
        return False, "b* = +inf not shown: z = -1 is not a pole of H"
    d1 = peval(pderiv(D), m1)
    if d1 == 0:
        return False, "b* = +inf not shown: the pole of H at z = -1 is not simple"
    r = peval(N, m1) / d1
    if r == 0:
        return False, "b* = +inf not shown: N(-1) = 0"
    sin_sign = 1 if (P // q) % 2 == 0 else -1
    if (1 if r > 0 else -1) * sin_sign > 0:
        return False, "b* = +inf not shown: r sin(nu pi) > 0 (r = %s, nu = %d/%d): the objective tends to -inf at wT = pi" % (short(r), P, q)
    return True, "b* = +inf: H's simple pole at z = -1 (r = %s) and sin(nu pi) of the other sign (nu = %d/%d)" % (short(r), P, q)


def bound_infinite_on_circle(H, T, nu, evidence):
    """b* = +inf at a simple pole z0 = e^{j theta0} of H inside the band, 0 < theta0 < pi (evidence.pole_on_circle =
    {q, c_lo, c_hi}, the delay never expanded). The pole: c0 = cos(theta0) is a root of q in [c_lo, c_hi] inside
    (-1, 1) (q changes sign there, or vanishes at c_lo = c_hi), and Z(z) = z^m q((z + 1/z)/2), expanded here by the
    binomial theorem, divides D; on |z| = 1, (z + 1/z)/2 = Re z, so Z(z0) = z0^m q(c0) = 0 at z0 = c0 + j sqrt(1 - c0^2),
    and D(z0) = 0. Near z0, H = R/(z - z0) + (bounded), R = N(z0)/D'(z0) (D'(z0) != 0: simple), and
    e^{j theta} - z0 = j z0 (theta - theta0)(1 + O(theta - theta0)), so with g(theta) = T e^{-j nu theta}/(1 - e^{j theta})
    (smooth at theta0 != 0), f = Re{g H} = Re{g(theta0) R/(j z0 (theta - theta0))} + O(1) = Im(k)/(theta - theta0) + O(1),
    k = T R e^{-j nu theta0}/((1 - z0) z0). Im(k) != 0, shown in mpmath intervals over all of [c_lo, c_hi], sends f to
    +inf on one side of theta0."""
    from mpmath import iv
    e = evidence["pole_on_circle"]
    if not isinstance(e, dict):
        raise Malformed("evidence.pole_on_circle: must be an object {q, c_lo, c_hi}")
    only(e, ("q", "c_lo", "c_hi"), "evidence.pole_on_circle")
    qs = e.get("q")
    if not isinstance(qs, list) or not 2 <= len(qs) <= 1001:
        raise Malformed("evidence.pole_on_circle.q: must be a list of 2 to 1001 \"p/q\" strings (ascending powers of c)")
    qp = trim([exact_value(v, "evidence.pole_on_circle.q[%d]" % i) for i, v in enumerate(qs)])
    if len(qp) < 2:
        raise Malformed("evidence.pole_on_circle.q: a constant has no root")
    lo, hi = exact(e, "c_lo", "evidence.pole_on_circle"), exact(e, "c_hi", "evidence.pole_on_circle")
    fails = "b* = +inf not shown: "
    if not -1 < lo <= hi < 1:
        return False, fails + "[c_lo, c_hi] is not inside (-1, 1) (the band's inside)"
    if (peval(qp, lo) != 0) if lo == hi else (peval(qp, lo) * peval(qp, hi) >= 0):
        return False, fails + "q has no root shown in [c_lo, c_hi] (no sign change, no zero)"
    m = len(qp) - 1
    Z = [Fraction(0)] * (2 * m + 1)
    for k, qk in enumerate(qp):
        for i in range(k + 1):
            Z[m + k - 2 * i] += qk * comb(k, i) / 2 ** k
    if pdivmod(H.den, trim(Z))[1]:
        return False, fails + "z^m q((z + 1/z)/2) does not divide D (no pole of H shown on the circle)"
    iv.prec = 256

    def I(x):
        return iv.mpf(x.numerator) / x.denominator

    def mul(a, b):
        return a[0] * b[0] - a[1] * b[1], a[0] * b[1] + a[1] * b[0]

    def div(a, b):
        d = b[0] * b[0] + b[1] * b[1]
        return (a[0] * b[0] + a[1] * b[1]) / d, (a[1] * b[0] - a[0] * b[1]) / d

    def at(p, z):
        v = (iv.mpf(0), iv.mpf(0))
        for a in reversed(p):
            v = mul(v, z)
            v = (v[0] + I(Fraction(a)), v[1])
        return v
    c0 = iv.mpf([I(lo).a, I(hi).b])
    s0 = iv.sqrt(1 - c0 * c0)
    z0 = (c0, s0)
    d1 = at(pderiv(H.den), z0)
    if not (d1[0] * d1[0] + d1[1] * d1[1]).a > 0:
        return False, fails + "D'(z0) may be 0 (the pole is not shown simple)"
    x = I(nu) * iv.atan2(s0, c0)
    k = div(mul(at(H.num, z0), (iv.cos(x), -iv.sin(x))), d1)
    k = div(k, mul((1 - c0, -s0), z0))
    im = I(T) * k[1]
    if not (im.a > 0 or im.b < 0):
        return False, fails + "Im(k) of the pole's term is not shown nonzero"
    return True, "b* = +inf: H's simple pole at cos(theta0) in [%s, %s], Im(k) %s 0 (+inf as theta -> theta0 from %s)" % (
        short(lo), short(hi), ">" if im.a > 0 else "<", "above" if im.a > 0 else "below")


def bound_infinite(H, T, P, q, status, evidence):
    """b* = +inf: the objective (T/2) E/F tends to +inf as c -> pole_c from `side` inside the band.
    E/F reduced to Er/Fr, Fr = (c - c_p)^m R with R(c_p) != 0: near c_p the objective is
    (T/2) Er(c_p) / ((c - c_p)^m R(c_p)) to first order, so its sign on the side s is
    sign Er(c_p) * s^m * sign R(c_p), and it grows without bound there."""
    if status != "exact":
        raise Malformed("claim.status: b* = +inf is claimed \"exact\"")
    if "end_lo" in evidence or "end_hi" in evidence:
        if "pole_c" in evidence or "side" in evidence:
            raise Malformed("evidence: end_lo/end_hi beside pole_c/side (one pole)")
        return bound_infinite_at_end(H, T, P, q, exact(evidence, "end_lo", "evidence"), exact(evidence, "end_hi", "evidence"))
    side = evidence.get("side")
    if side not in (1, -1) or isinstance(side, bool):
        raise Malformed("evidence.side: missing or not +1 or -1")
    if "pole_lo" in evidence or "pole_hi" in evidence:
        if "pole_c" in evidence:
            raise Malformed("evidence: pole_lo/pole_hi beside pole_c (one pole)")
        return bound_infinite_inside(H, T, P, q, exact(evidence, "pole_lo", "evidence"), exact(evidence, "pole_hi", "evidence"), side)
    cp = exact(evidence, "pole_c", "evidence")
    if not in_band(cp, q):
        return False, "b* = +inf not shown: evidence.pole_c = %s is outside the band [cos(pi/%d), 1]" % (short(cp), q)
    if side == 1 and cp == 1:
        return False, "b* = +inf not shown: side +1 at c_p = 1 leaves the band"
    if side == -1 and (cp == -1 or peval(re_power(q), (1 - cp) / (1 + cp)) <= 0):
        return False, "b* = +inf not shown: side -1 at the band's end c_p = cos(pi/%d) leaves the band" % q
    E, F = objective_c(H, T, P, q)
    g = pgcd(E, F)
    Er, R = (pdivmod(E, g)[0], pdivmod(F, g)[0]) if g else (E, F)
    if peval(R, cp) != 0:
        return False, "b* = +inf not shown: evidence.pole_c = %s is not a pole of the objective" % short(cp)
    m = 0
    while peval(R, cp) == 0:
        R = pdivmod(R, [-cp, Fraction(1)])[0]
        m += 1
    sign = (1 if peval(Er, cp) > 0 else -1) * (1 if peval(R, cp) > 0 else -1) * (side if m % 2 else 1)
    if sign < 0:
        return False, "b* = +inf not shown: the objective tends to -inf as c -> %s from %s (a pole of order %d)" % (
            short(cp), "above" if side > 0 else "below", m)
    return True, "b* = +inf: the objective tends to +inf as c -> %s from %s" % (short(cp), "above" if side > 0 else "below")


def cheb_u(k):
    """U_k, the Chebyshev polynomial of the second kind: U_k(cos phi) = sin((k + 1) phi)/sin phi."""
    prev, cur = [Fraction(1)], [Fraction(0), Fraction(2)]
    if k == 0:
        return prev
    for _ in range(k - 1):
        prev, cur = cur, psub(pmul([Fraction(0), Fraction(2)], cur), prev)
    return cur


def bound_infinite_inside(H, T, P, q, s, b, side):
    """b* = +inf at a pole inside the band that (s, b) isolates (an irrational one: a pole of H on the
    circle seen through t_d/T = p/q): s < b both in the band; the reduced denominator R has exactly one
    root in (s, b) and none at s or b, the reduced numerator Er none in [s, b]; so Er/R keeps one sign on
    each side of the pole within (s, b) and its modulus grows without bound towards it: +inf from above
    iff Er(b) R(b) > 0, from below iff Er(s) R(s) > 0."""
    if not s < b:
        return False, "b* = +inf not shown: not pole_lo < pole_hi"
    if not in_band(s, q) or not in_band(b, q):
        return False, "b* = +inf not shown: pole_lo or pole_hi is outside the band [cos(pi/%d), 1]" % q
    E, F = objective_c(H, T, P, q)
    g = pgcd(E, F)
    Er, R = (pdivmod(E, g)[0], pdivmod(F, g)[0]) if g else (E, F)
    if len(R) < 2 or peval(R, s) == 0 or peval(R, b) == 0 or roots_in(R, s, b) != 1:
        return False, "b* = +inf not shown: (pole_lo, pole_hi) does not isolate one pole of the objective"
    if peval(Er, s) == 0 or peval(Er, b) == 0 or (len(Er) > 1 and roots_in(Er, s, b) != 0):
        return False, "b* = +inf not shown: the reduced numerator has a root in [pole_lo, pole_hi]"
    at = b if side == 1 else s
    if (peval(Er, at) > 0) != (peval(R, at) > 0):
        return False, "b* = +inf not shown: the objective tends to -inf as c -> the pole from %s" % ("above" if side == 1 else "below")
    return True, "b* = +inf: the objective tends to +inf as c -> its pole in (%s, %s) from %s" % (
        short(s), short(b), "above" if side == 1 else "below")


def bound_infinite_at_end(H, T, P, q, s, b):
    """b* = +inf at the band's irrational end c_e = cos(pi/q) (z = -1 with a fractional delay), on the
    interval (s, b]: U_{q-1}, whose roots are cos(k pi/q), has one root in (s, 1) and one in (s, b),
    so c_e (its largest) is its only root in (s, 1); gcd(R, U_{q-1}) (R the reduced denominator) has a
    root in (s, 1), so R(c_e) = 0; R has no other root in (s, b], Er none; so Er/R has the sign of
    Er(b) R(b) on (c_e, b] and grows without bound as c -> c_e from above."""
    if q < 2:
        return False, "b* = +inf not shown: the band's end is c = -1 (an integer delay): give pole_c"
    if not (-1 <= s < b <= 1):
        return False, "b* = +inf not shown: not -1 <= end_lo < end_hi <= 1"
    U = cheb_u(q - 1)
    if peval(U, s) == 0 or peval(U, b) == 0 or roots_in(U, s, Fraction(1)) != 1 or roots_in(U, s, b) != 1:
        return False, "b* = +inf not shown: (end_lo, end_hi] does not isolate cos(pi/%d)" % q
    E, F = objective_c(H, T, P, q, MAX_END_DEGREE)
    g = pgcd(E, F)
    Er, R = (pdivmod(E, g)[0], pdivmod(F, g)[0]) if g else (E, F)
    G = pgcd(R, U)
    if len(G) < 2 or roots_in(G, s, Fraction(1)) < 1:
        return False, "b* = +inf not shown: cos(pi/%d) is not a pole of the objective" % q
    if peval(R, s) == 0 or peval(R, b) == 0 or roots_in(R, s, b) != 1:
        return False, "b* = +inf not shown: the reduced denominator has another root in (end_lo, end_hi], or one at its ends"
    if peval(Er, s) == 0 or peval(Er, b) == 0 or roots_in(Er, s, b) != 0:
        return False, "b* = +inf not shown: the reduced numerator has a root in [end_lo, end_hi]"
    if (peval(Er, b) > 0) != (peval(R, b) > 0):
        return False, "b* = +inf not shown: the objective tends to -inf as c -> cos(pi/%d) from above" % q
    return True, "b* = +inf: the objective tends to +inf as c -> cos(pi/%d) from above (wT -> pi)" % q


MAX_BOUND_CELLS = 20000  # each cell two interval evaluations in mpmath (~1 ms each)


def on_circle(p):
    """p(z) at z = e^{j theta} as a(c) + j s b(c), c = cos theta, s = sin theta: z^k = T_k(c) + j s U_{k-1}(c)."""
    a, b = [], []
    t_prev, t_k = [Fraction(1)], [Fraction(0), Fraction(1)]  # T_0, T_1
    u_prev, u_k = [], [Fraction(1)]  # U_{-1} = 0, U_0
    for k, coeff in enumerate(p):
        tk = [Fraction(1)] if k == 0 else t_k
        uk = [] if k == 0 else u_k
        a, b = padd(a, pscale(tk, coeff)), padd(b, pscale(uk, coeff))
        if k >= 1:  # T_{k+1} = 2c T_k - T_{k-1}, U_k = 2c U_{k-1} - U_{k-2}
            t_prev, t_k = t_k, psub(pmul([Fraction(0), Fraction(2)], t_k), t_prev)
            u_prev, u_k = u_k, psub(pmul([Fraction(0), Fraction(2)], u_k), u_prev)
    return a, b


def cells_kernel(H, T, eta, nu):
    """f(theta) = eta + (T/2) [A(c) cos(nu theta) + E(c) S(theta)] / B(c), S = sin(nu theta) cot(theta/2), with
    N conj(D) = X + j s Y on the circle, A = X - (1 + c) Y, E = X + (1 - c) Y, B = |D|^2 (derived here from
    T/(1 - z) = (T/2)(1 + j cot(theta/2)), s cot(theta/2) = 1 + c, s sin(nu theta) = (1 - c) S), in mpmath
    intervals: (value(theta), cell_below(a, b, hi)). cell_below shows f(m) + f'([a, b]) [-r, r] < hi (mean value
    theorem; or its halves, up to 6 times), S = 2 nu cos(theta/2) sinc(nu theta)/sinc(theta/2) and f' written
    out by hand below, each polynomial shifted exactly to the cell's centre in c."""
    from mpmath import iv
    iv.prec = 192
    # H's simple pole at z = -1 with an integer delay n (the Tustin wall delayed): H = G + rho/(z + 1), G without it,
    # and the pole's part T Re{rho e^{-j n theta}/(1 - z^2)} = T rho sin((n + 1) theta)/(2 sin theta) (1 - z^2 =
    # -2j sin(theta) z, as in bound_infinite_at_minus_one): f gains (T/2) rho K(theta), K = sin(m theta)/sin(theta),
    # m = n + 1, finite on [0, pi] (m sinc(m theta)/sinc(theta) near 0, (-1)^(m+1) m sinc(m phi)/sinc(phi) in
    # phi = pi - theta near pi). A fractional delay (frac): the same part with the real m = nu + 1, finite below pi
    # (its sinc form near 0, sin(m theta)/sin(theta) elsewhere); near pi sin(m theta) -> sin(nu pi + pi) = -sin(nu pi)
    # != 0 over sin(theta) -> 0+, so rho K -> +inf (b* = +inf, no cell bounds it) or -inf. The cell holding pi,
    # [a, b] with pi/2 < a < pi < b, is shown by tail_below: with rho sin(m theta) <= w < 0 on [a, pi] and
    # 0 < sin(theta) <= sin(a) there, rho K <= w/sin(a); the rest of f by its value at a and its derivative.
    rho, m, frac = Fraction(0), 0, False
    if peval(H.den, Fraction(-1)) == 0 and peval(pderiv(H.den), Fraction(-1)) != 0:
        rho = peval(H.num, Fraction(-1)) / peval(pderiv(H.den), Fraction(-1))
        if nu.denominator == 1:
            m = nu.numerator + 1
        else:
            frac = True
        H = H - RF([rho], [Fraction(1), Fraction(1)])
    N, D = H.num, H.den
    na, nb = on_circle(N)
    da, db = on_circle(D)
    one_m_c2 = [Fraction(1), Fraction(0), Fraction(-1)]
    X = padd(pmul(na, da), pmul(one_m_c2, pmul(nb, db)))
    Y = psub(pmul(nb, da), pmul(na, db))
    A = psub(X, pmul([Fraction(1), Fraction(1)], Y))
    E = padd(X, pmul([Fraction(1), Fraction(-1)], Y))
    B = padd(pmul(da, da), pmul(one_m_c2, pmul(db, db)))

    def q(x):
        return iv.mpf(x.numerator) / x.denominator

    def deriv(p):
        return [k * p[k] for k in range(1, len(p))]
    exact_polys = (A, E, B, deriv(A), deriv(E), deriv(B))
    polys = [[q(x) for x in p] for p in exact_polys]

    def shifted(cm):  # each polynomial in t = c - cm (exact Taylor shift): the centred form over a cell, whose
        out = []      # enclosure follows p's variation there, not its coefficients' size (a resonance near the circle)
        for p in exact_polys:
            b = list(p)
            for i in range(len(b)):
                for j in range(len(b) - 2, i - 1, -1):
                    b[j] += cm * b[j + 1]
            out.append([q(x) for x in b])
        return out
    vnu, half, vT, veta = q(nu), iv.mpf(1) / 2, q(T), q(eta)

    def horner(p, c):
        r = iv.mpf(0)
        for x in reversed(p):
            r = r * c + x
        return r

    fact = [1]
    for k in range(1, 34):
        fact.append(fact[-1] * k)

    f_coeff = [iv.mpf((-1) ** k) / fact[2 * k + 1] for k in range(16)]  # sinc's series, and sinc'(y)/y's
    d_coeff = [None] + [iv.mpf((-1) ** k * 2 * k) / fact[2 * k + 1] for k in range(1, 16)]
    remainder = iv.mpf([-1, 1]) * (iv.mpf(1) / fact[33] * 34)  # |remainders| <= |y|^32 / 33!, 32 |y|^31 / 33!, |y| <= 1

    def sinc2(x):  # sinc(x), sinc'(x) for an interval x >= 0: series to x^30 with its remainder below 1, else direct
        def series(y):
            y2, f, d = y * y, iv.mpf(0), iv.mpf(0)
            for k in reversed(range(16)):
                f = f * y2 + f_coeff[k]
            for k in reversed(range(1, 16)):
                d = d * y2 + d_coeff[k]
            return f + remainder, d * y + remainder

        def direct(y):
            sy, cy = iv.sin(y), iv.cos(y)
            return sy / y, (cy - sy / y) / y
        if x.b <= 1:
            return series(x)
        if x.a >= 1:
            return direct(x)
        (f1, d1), (f2, d2) = series(iv.mpf([x.a, 1])), direct(iv.mpf([1, x.b]))
        return iv.mpf([min(f1.a, f2.a), max(f1.b, f2.b)]), iv.mpf([min(d1.a, d2.a), max(d1.b, d2.b)])

    def sinc_any(x):  # sinc2 for an interval of either sign (sinc even, sinc' odd)
        if x.a >= 0:
            return sinc2(x)
        if x.b <= 0:
            f, d = sinc2(-x)
            return f, -d
        f, d = sinc2(iv.mpf([0, max(-x.a, x.b)]))
        w = max(abs(d.a), abs(d.b))
        return f, iv.mpf([-w, w])

    vm, vrho = (q(nu + 1) if frac else iv.mpf(m)), q(rho)

    def pole_k(th):  # K(theta) = sin(m theta)/sin(theta) and K'(theta), over the interval th
        if th.b <= 1.5:
            g1, g1d = sinc_any(vm * th)
            g2, g2d = sinc_any(th)
            return vm * g1 / g2, vm * (vm * g1d * g2 - g1 * g2d) / (g2 * g2)
        phi = iv.pi - th
        if not frac and phi.b <= 1.5:
            sign = 1 if m % 2 == 1 else -1  # (-1)^(m + 1)
            h1, h1d = sinc_any(vm * phi)
            h2, h2d = sinc_any(phi)
            return sign * vm * h1 / h2, -sign * vm * (vm * h1d * h2 - h1 * h2d) / (h2 * h2)
        sm, cm, s1, c1 = iv.sin(vm * th), iv.cos(vm * th), iv.sin(th), iv.cos(th)
        return sm / s1, (vm * cm * s1 - sm * c1) / (s1 * s1)

    def f_and_df(th, centred=None, pole=True):
        c, s = iv.cos(th), iv.sin(th)
        ps, t = (polys, c) if centred is None else (centred[0], c - q(centred[1]))
        u = th * half
        cu, su = iv.cos(u), iv.sin(u)
        cn, sn = iv.cos(vnu * th), iv.sin(vnu * th)
        g1, g1d = sinc2(vnu * th)
        g2, g2d = sinc2(u)
        g = g1 / g2
        S = 2 * vnu * cu * g
        dg = (vnu * g1d * g2 - half * g1 * g2d) / (g2 * g2)
        dS = 2 * vnu * (cu * dg - half * su * g)
        a, e, b, da_, de_, db_ = (horner(p, t) for p in ps)
        R = a * cn + e * S
        dR = -s * da_ * cn - vnu * a * sn - s * de_ * S + e * dS
        f = veta + vT * half * R / b
        df = vT * half * (dR * b + R * s * db_) / (b * b)
        if pole and (m or frac):
            k, dk = pole_k(th)
            f, df = f + vT * half * vrho * k, df + vT * half * vrho * dk
        return f, df

    def value(theta):
        return f_and_df(q(theta))[0]

    def tail_below(a, hi):  # the cell holding pi, frac only (above)
        if (q(a) > iv.pi / 2) is not True:
            return False
        th = iv.mpf([q(a).a, iv.pi.b])
        rest = f_and_df(q(a), pole=False)[0] + f_and_df(th, pole=False)[1] * iv.mpf([0, (iv.pi - q(a)).b])
        w = (vrho * iv.sin(vm * th)).b
        if not w < 0:
            return False
        return (rest + vT * half * (iv.mpf(w) / iv.sin(q(a)).b) < q(hi)) is True

    def cell_below(a, b, hi, depth=0):
        if frac and (q(a) < iv.pi) is not False and (q(b) > iv.pi) is not False:  # the cell may hold pi
            if (q(a) < iv.pi) is not True or (q(b) > iv.pi) is not True:
                return False
            return tail_below(a, hi) or (depth < 6 and cell_below(a, (a + b) / 2, hi, depth + 1) and
                                         cell_below((a + b) / 2, b, hi, depth + 1))
        m, r = (a + b) / 2, (b - a) / 2
        fm = value(m)
        cm = Fraction(math.cos(float(m)))  # a rational near cos(m), the centre of c over the cell
        dcell = f_and_df(iv.mpf([q(a).a, q(b).b]), (shifted(cm), cm))[1]
        if (fm + dcell * iv.mpf([-1, 1]) * q(r) < q(hi)) is True:
            return True
        return depth < 6 and cell_below(a, m, hi, depth + 1) and cell_below(m, b, hi, depth + 1)
    return value, cell_below, q


def read_cells(evidence, key):
    ends = evidence.get(key)
    if not isinstance(ends, list) or not ends:
        raise Malformed("evidence.%s: must be a non-empty array of \"p/q\" strings" % key)
    if len(ends) > MAX_BOUND_CELLS:
        raise TooLarge("evidence.%s: %d cells, above this checker's limit of %d" % (key, len(ends), MAX_BOUND_CELLS))
    return [exact_value(x, "evidence.%s[%d]" % (key, i)) for i, x in enumerate(ends)]


def cells_below_fail(kernel, ends, hi):
    """None when the cells (their right ends, from 0; the last beyond pi) show f < hi on [0, pi]; else why."""
    from mpmath import iv
    _, cell_below, q = kernel
    if (iv.pi < q(ends[-1])) is not True:
        return "the cells end at or below pi (they must cover [0, pi])"
    for i, (a, b) in enumerate(zip([Fraction(0)] + ends, ends)):  # the order first: it costs nothing
        if not a < b:
            return "cell %d's end %s is not above the one before" % (i + 1, short(b))
    a = Fraction(0)
    for i, b in enumerate(ends):
        if not cell_below(a, b, hi):
            return "f < %.12g not shown on cell %d [%.12g, %.12g]" % (float(hi), i + 1, float(a), float(b))
        a = b
    return None


def witness_fail(kernel, theta0, lo):
    """None when theta0 lies in [0, pi] and f(theta0) > lo is shown; else why."""
    from mpmath import iv
    value, _, q = kernel
    if theta0 < 0 or (q(theta0) < iv.pi) is not True:
        return "evidence.witness_theta = %s is not in [0, pi]" % short(theta0)
    if (q(lo) < value(theta0)) is not True:
        return "f(theta0) > %.12g not shown at theta0 = %.12g" % (float(lo), float(theta0))
    return None


def bound_cells(H, T, eta, nu, lo, hi, evidence):
    """b* in [lo, hi] by cells, the delay never expanded (hapstab's check/bound_cells.hpp states the theorem):
    f < hi on each cell and f(witness_theta) > lo (cells_kernel)."""
    kernel = cells_kernel(H, T, eta, nu)
    ends = read_cells(evidence, "cells")
    theta0 = exact(evidence, "witness_theta", "evidence")
    why = witness_fail(kernel, theta0, lo)  # one value: before the cells' thousands
    if why:
        return False, "b* >= %.12g not shown: %s" % (float(lo), why)
    why = cells_below_fail(kernel, ends, hi)
    if why:
        return False, "b* <= %.12g not shown: %s" % (float(hi), why)
    return True, "b* in [%.12g, %.12g] (%d cells, the delay never expanded)" % (float(lo), float(hi), len(ends))


def bound_max_cells(H0, H1, T, eta, nu, b, K, claim_range_, evidence, D):
    """K_max by cells (hapstab's check/bound_max_check.hpp): lo > 0 by b0_hi < b, f at K = 0 below b0 on
    cells_at_0 and f at K = lo below b on cells_at_lo; K_max <= hi by f at K = hi above b at witness_theta;
    K_max = +inf has no cells' form."""
    status, lo, hi, infinite = claim_range_
    if infinite:
        raise Malformed("claim.infinite: K_max = +inf has no cells' form (evidence.witness_theta)")
    upper = "jump_at_z" if "jump_at_z" in evidence else "witness_theta"  # b* = +inf above hi (bound_max_jump)
    only(evidence, ("b0_hi", "cells_at_0", "cells_at_lo", upper) if lo > 0 else (upper,), "evidence")

    def at(k):
        return cells_kernel(H0 + RF([k]) * H1, T, eta, nu)
    if lo > 0:
        b0 = exact(evidence, "b0_hi", "evidence")
        if b0 >= b:
            return False, "evidence.b0_hi = %s is not < b: K_max > 0 not shown" % short(b0)
        why = cells_below_fail(at(Fraction(0)), read_cells(evidence, "cells_at_0"), b0)
        if why:
            return False, "b*(%s = 0) < b0_hi not shown: %s" % (K, why)
        why = cells_below_fail(at(lo), read_cells(evidence, "cells_at_lo"), b)
        if why:
            return False, "%s_max >= %.12g fails: b*(%s = lo) < b not shown: %s" % (K, float(lo), K, why)
    if upper == "jump_at_z":
        why = bound_max_jump(H0, H1, nu.numerator, nu.denominator, hi, evidence)
    else:
        why = witness_fail(at(hi), exact(evidence, "witness_theta", "evidence"), b)
    if why:
        return False, "%s_max <= %.12g not shown: b*(%s = hi) > b: %s" % (K, float(hi), K, why)
    return True, "%s_max %s (cells, the delay never expanded; affine in %s, degree bound %d)" % (
        K, ("= %s" % lo) if status == "exact" else "in [%.12g, %.12g]" % (float(lo), float(hi)), K, D)


def bound_model(model, expanded=True):
    """H, T, eta, P, q of a bound model (tau = n + t_d/T = P/q); `expanded`: the limit of the form that expands
    the delay."""
    H, T = model_h(model, marginal=True)  # as `bound` reads it
    n = delay_of(model)
    td = exact(model, "frac_delay", "model") if "frac_delay" in model else Fraction(0)
    if td < 0:
        raise Malformed("model.frac_delay: must be >= 0")
    eta = exact(model, "eta", "model")
    if eta < 0:
        raise Malformed("model.eta: must be >= 0")
    tau = n + td / T
    if expanded and (tau.denominator > 10 ** 6 or tau.numerator > 10 ** 6):
        raise TooLarge("t_d/T has a numerator or denominator above 10^6")
    return H, T, eta, tau.numerator, tau.denominator


def upper_bound(A, F, bound, c_lo, q):
    """None when A/F <= bound on the band [cos(pi/q), 1] (F >= 0 there), shown on [c_lo, 1] (c_lo
    shown <= cos(pi/q)): P = bound F - A >= 0 there, or P (1 + c)^k R_q >= 0 across an irrational
    end where A/F -> -inf (end_multiplier > 0 inside the band). Else the reason."""
    if not below_band_end(c_lo, q):
        return "evidence.domain_c_lo = %s is not <= cos(pi/%d): [c_lo, 1] misses part of the band" % (short(c_lo), q)
    P = psub(pscale(F, bound), A)
    why = nonneg_on(P, c_lo, Fraction(1))
    if why and q > 1 and nonneg_on(pmul(P, end_multiplier(q)), c_lo, Fraction(1)) is None:
        return None
    return "bound F(c) - (T/2) E(c) on [%s, 1] is %s" % (short(c_lo), why) if why else None


def lower_bound(A, F, target, c0, q):
    """None when the objective A/F (its value or limit) at the witness c0 in the band is >= target."""
    if c0 < -1 or c0 > 1:
        return "evidence.witness_c = %s is outside [-1, 1]" % c0
    if not in_band(c0, q):
        return "evidence.witness_c = %s is outside the band [cos(pi/%d), 1] (w > pi/T)" % (short(c0), q)
    g = pgcd(A, F)  # reduced: at a removable point the value is f's limit, which the sup reaches
    Ar, Fr = (pdivmod(A, g)[0], pdivmod(F, g)[0]) if g else (A, F)
    f0 = peval(Fr, c0)
    if f0 == 0:
        return "evidence.witness_c = %s is a pole of the objective (a pole of H on the unit circle)" % c0
    v = peval(Ar, c0) / f0
    if v < target:
        return "the objective at the witness c0 = %s is %.12g short of it" % (short(c0), float(target - v))
    return None


# ---------------------------------------------------------------- bound-max
def prove_affine(text, T, params, K, marginal=False):
    """(H0, H1, D) with H = H0 + K H1 for every K, proven: the numerator of H - H0 - K H1 has degree
    <= D = max(n, d + 1) in K ((n, d) the Deg bounds of the expression) and vanishes at D + 1 values
    of K where the parse is defined (a rational function of K evaluated exactly there)."""
    dg = parse_h(text, T, dict(params, **{K: Fraction(0)}), leaf=lambda kind, txt, v: Deg(1 if (kind, txt) == ('name', K) else 0, 0))
    D = max(dg.n, dg.d + 1)
    if D > 64:
        raise Malformed("model.H: its degree in %s is bounded only by %d (above 64): not proven affine" % (K, D))

    def at(k):
        return parse_h(text, T, dict(params, **{K: k}), marginal=marginal)
    try:
        H0 = at(Fraction(0))
        H1 = at(Fraction(1)) - H0
    except ZeroDivisionError:
        raise Malformed("model.H: division by zero at %s = 0 or 1" % K)
    if not H1.num:
        raise Malformed("model.H: does not depend on model.name = %s" % K)
    proven, tried, j = 2, 0, 1
    while proven < D + 1:
        j += 1
        k = Fraction(2 * j + 1, 3) * (-1) ** j  # distinct, never 0 or 1
        try:
            h = at(k)
        except (Malformed, ZeroDivisionError):  # divides by zero at k: at most d such values
            tried += 1
            if tried > D + dg.d + 2:
                raise Malformed("model.H: undefined at too many values of %s" % K)
            continue
        e = H0 + RF([k]) * H1
        if h.num != e.num or h.den != e.den:
            raise Malformed("model.H: not affine in %s (H(%s) != H(0) + %s (H(1) - H(0)))" % (K, k, k))
        proven += 1
    return H0, H1, D


def parameter_name(model):
    """model.name, the parameter maximised: a string, given no value in model.set."""
    K = model.get("name")
    if not isinstance(K, str) or not K:
        raise Malformed("model.name: missing or not a string")
    if isinstance(model.get("set", {}), dict) and K in model.get("set", {}):
        raise Malformed("model.set: gives the parameter model.name = %s a value" % K)
    return K


def bound_max_jump(H0, H1, P, q, hi, evidence):
    """b*(K) = +inf for every K > hi (evidence.jump_at_z = "-1"), or why not. Near z = -1, H0 + K H1 =
    G(K) + r(K)/(z + 1) with G(K) regular there and r(K) = r0 + K r1, ri = Ni(-1)/Di'(-1) (0 where Hi has
    no pole at -1; a repeated pole is not taken). By bound_infinite_at_minus_one's derivation the objective
    tends to +inf as wT -> pi iff r(K) sin(nu pi) < 0, nu = P/q not whole. With s = (-1)^(P // q), the sign
    of sin(nu pi): r1 s < 0 and r(hi) s <= 0 give r(K) s < 0 for every K > hi."""
    if evidence.get("jump_at_z") != "-1":
        raise Malformed("evidence.jump_at_z: only \"-1\" is taken")
    if q == 1:
        return "the delay %d is a whole number of samples (sin(nu pi) = 0): no jump at wT = pi" % P
    m1 = Fraction(-1)
    r = []
    for name, part in (("H0", H0), ("H1", H1)):
        if peval(part.den, m1) != 0:
            r.append(Fraction(0))
            continue
        d1 = peval(pderiv(part.den), m1)
        if d1 == 0:
            return "%s has a repeated pole at z = -1" % name
        r.append(peval(part.num, m1) / d1)
    s = 1 if (P // q) % 2 == 0 else -1
    if r[1] * s >= 0:
        return "r1 sin(nu pi) < 0 fails (r1 = %s, nu = %d/%d)" % (short(r[1]), P, q)
    if (r[0] + hi * r[1]) * s > 0:
        return "r(hi) sin(nu pi) <= 0 fails (r(hi) = %s): the objective tends to -inf just above hi" % short(r[0] + hi * r[1])
    return None


def check_bound_max(c):
    """K_max = sup{K0 >= 0 : b*(K) < b on [0, K0)} for H = H0 + K H1 (proven affine), b* convex in
    K (a sup of affine functions): K_max >= lo > 0 if b*(0) <= b0 < b and b*(lo) <= b; K_max <= hi if
    b*(hi) >= b (a witness); K_max = +inf if b*(0) <= b0 < b and f1 <= 0 on the band."""
    model, claim, evidence = parts(c)
    only(model, ("H", "set", "name", "T", "delay", "frac_delay", "eta", "damping"), "model")
    only(claim, ("quantity", "status", "infinite", "value", "lo", "hi", "printed", "printed_lo", "printed_hi"), "claim")
    cells = "witness_theta" in evidence or "cells_at_0" in evidence  # the long-delay form (bound_max_cells)
    integrator = "integrator" in evidence  # K_max = 0 by H's pole at z = 1 (the pole0/pole1 test below)
    at_zero = "at_zero_infinite" in evidence  # K_max = 0 by b*(0) = +inf (a bound certificate's evidence for H0)
    if integrator:
        only(evidence, ("integrator",), "evidence")
    elif at_zero:
        only(evidence, ("at_zero_infinite",), "evidence")
    elif not cells:
        jump = "jump_at_z" in evidence  # b* = +inf above hi (bound_max_jump), in place of witness_c
        only(evidence, ("jump_at_z" if jump else "witness_c", "b0_hi", "domain_c_lo"), "evidence")
    K = parameter_name(model)
    sets = model.get("set", {})
    # the delay model and the parameters, read as for bound (H parsed at K = 0 there)
    m0 = dict(model, set=dict(sets, **{K: "0"}) if isinstance(sets, dict) else sets)
    m0.pop("name")
    m0.pop("damping", None)
    _, T, eta, P, q = bound_model(m0, expanded=not (cells or integrator or at_zero))
    b = exact(model, "damping", "model")
    if b <= 0:
        raise Malformed("model.damping: must be > 0")
    try:
        H0, H1, D = prove_affine(model["H"], T, parameters(model), K, marginal=True)  # as `bound --max` reads it
    except ZeroDivisionError:
        raise Malformed("model.H: division by zero")
    status, lo, hi, infinite, refuted = claim_range(claim, True)
    if refuted:
        return False, refuted
    if infinite and "jump_at_z" in evidence:
        raise Malformed("evidence.jump_at_z: K_max = +inf has no upper end")
    if not infinite and lo < 0:
        return False, "claim: lo < 0 (K_max >= 0 by its definition)"
    one = Fraction(1)
    pole0, pole1 = peval(H0.den, one) == 0, peval(H1.den, one) == 0
    if pole0 or pole1:  # b*(0) = +inf, or b*(K) = +inf for every K > 0 (H0 + K H1 keeps H1's pole): K_max = 0
        why = ("H(%s = 0) has a pole at z = 1 (an integrator): b*(0) = +inf" % K) if pole0 else \
            ("the part of H in %s has a pole at z = 1 that H(%s = 0) lacks (an integrator): b* = +inf for every %s > 0" % (K, K, K))
        if infinite or lo > 0:
            return False, "%s_max = 0, not the claim: %s (docs/commands.md)" % (K, why)
        if integrator:
            if evidence.get("integrator") is not True:
                raise Malformed("evidence.integrator: must be true (a pole of H at z = 1)")
            if peval(pderiv((H0 if pole0 else H1).den), one) == 0:
                return False, "%s_max = 0 not shown: the pole at z = 1 is not simple" % K
            return True, "%s_max = 0: %s" % (K, why)
    elif integrator:
        return False, "evidence.integrator: neither H0 nor H1 has a pole at z = 1"
    if at_zero:
        # b*(0) = +inf >= b: no K0 > 0 has b*(K) < b on [0, K0), so K_max = 0
        inner = evidence["at_zero_infinite"]
        if not isinstance(inner, dict):
            raise Malformed("evidence.at_zero_infinite: must be an object (a bound certificate's evidence of b* = +inf)")
        if infinite or lo != 0 or hi != 0:
            return False, "%s_max = 0, not the claim: evidence.at_zero_infinite states b*(%s = 0) = +inf (>= b)" % (K, K)
        ok, why = bound_infinite_any(H0, T, P, q, status, inner, "evidence.at_zero_infinite")
        if not ok:
            return False, "%s_max = 0 not shown: b*(%s = 0) = +inf fails: %s" % (K, K, why)
        return True, "%s_max = 0: b*(%s = 0) = +inf >= b; %s (affine in %s, degree bound %d)" % (K, K, why, K, D)
    if cells:
        return bound_max_cells(H0, H1, T, eta, Fraction(P, q), b, K, (status, lo, hi, infinite), evidence, D)
    c_lo = exact(evidence, "domain_c_lo", "evidence") if "domain_c_lo" in evidence else Fraction(-1)
    if not below_band_end(c_lo, q):  # checked whenever given, also where no bound reads it (K_max = 0)
        return False, "evidence.domain_c_lo = %s is not <= cos(pi/%d)" % (short(c_lo), q)

    def objective(k):  # (T/2) E^ and F^ of H0 + k H1
        E, F = objective_c(H0 + RF([k]) * H1, T, P, q)
        return pscale(E, T / 2), F
    if infinite or lo > 0:
        b0 = exact(evidence, "b0_hi", "evidence")
        if b0 >= b:
            return False, "evidence.b0_hi = %s is not < b: K_max > 0 not shown" % short(b0)
        why = upper_bound(*objective(Fraction(0)), b0 - eta, c_lo, q)
        if why:
            return False, "b*(%s = 0) <= b0_hi = %.12g fails: %s" % (K, float(b0), why)
    if infinite:
        E1, F1 = objective_c(H1, T, P, q)
        why = upper_bound(pscale(E1, T / 2), F1, Fraction(0), c_lo, q)
        if why:
            return False, "%s_max = +inf fails: f1 <= 0 (the objective of dH/d%s) not shown: %s" % (K, K, why)
        return True, "%s_max = +inf (b*(0) < b, f1 <= 0; affine in %s, degree bound %d)" % (K, K, D)
    if lo > 0:
        why = upper_bound(*objective(lo), b - eta, c_lo, q)
        if why:
            return False, "%s_max >= %.12g fails: b*(%s = lo) <= b not shown: %s" % (K, float(lo), K, why)
    if "jump_at_z" in evidence:
        why = bound_max_jump(H0, H1, P, q, hi, evidence)
        if why:
            return False, "%s_max <= %.12g not shown: b*(%s) = +inf above hi: %s" % (K, float(hi), K, why)
    else:
        why = lower_bound(*objective(hi), b - eta, exact(evidence, "witness_c", "evidence"), q)
    if why:
        return False, "%s_max <= %.12g not shown: b*(%s = hi) >= b: %s" % (K, float(hi), K, why)
    return True, "%s_max %s (affine in %s, degree bound %d)" % (
        K, ("= %s" % lo) if status == "exact" else "in [%.12g, %.12g]" % (float(lo), float(hi)), K, D)


# ---------------------------------------------------------------- passivity-level
def re_over_circle(P, Q):
    """(E^, F^) with Re{P/Q}(e^{j theta}) = E^(c)/F^(c), c = cos(theta), F^ = (1+c)^d |Qt|^2 = 2^d |Q|^2:
    t = tan(theta/2), z = (1+jt)/(1-jt), Pt = P(z)(1-jt)^d, Qt likewise (d = max(deg P, deg Q)),
    Re{P/Q} = Re(Pt conj(Qt))/|Qt|^2, both even in t (real coefficients), so polynomials in
    u = t^2 = (1-c)/(1+c), multiplied out by (1+c)^m."""
    d = max(len(P), len(Q)) - 1

    def cmul(x, y):
        return (psub(pmul(x[0], y[0]), pmul(x[1], y[1])), padd(pmul(x[0], y[1]), pmul(x[1], y[0])))
    plus, minus = ([Fraction(1)], [Fraction(0), Fraction(1)]), ([Fraction(1)], [Fraction(0), Fraction(-1)])
    pw_plus, pw_minus = [([Fraction(1)], [])], [([Fraction(1)], [])]
    for _ in range(d):
        pw_plus.append(cmul(pw_plus[-1], plus))
        pw_minus.append(cmul(pw_minus[-1], minus))

    def tilde(coeffs):
        re, im = [], []
        for k, a in enumerate(coeffs):
            if a != 0:
                x = cmul(pw_plus[k], pw_minus[d - k])
                re, im = padd(re, pscale(x[0], a)), padd(im, pscale(x[1], a))
        return re, im
    Pr, Pi = tilde(P)
    Qr, Qi = tilde(Q)
    E = padd(pmul(Pr, Qr), pmul(Pi, Qi))
    F = padd(pmul(Qr, Qr), pmul(Qi, Qi))
    if any(x != 0 for x in E[1::2] + F[1::2]):
        raise AssertionError("parity in t")
    Eu, Fu = E[0::2], F[0::2]
    # m = d, not the degrees found: (1+c)^d (1+u)^d = 2^d, so F^ = 2^d |Q(e^{j theta})|^2 exactly, also
    # at c = -1 (theta = pi), where a root of Q at z = -1 lowers the degree of F in u (the campaign
    # found a zero of G at z = -1 missed with the smaller m)
    m = d

    def hat(q):
        out = []
        for i, a in enumerate(q):
            if a != 0:
                out = padd(out, pscale(pmul(ppow([Fraction(1), Fraction(-1)], i), ppow([Fraction(1), Fraction(1)], m - i)), a))
        return out
    return hat(Eu), hat(Fu)


def upper_bound_claim(claim):
    """A claim of status "upper_bound" (a level <= hi only): {quantity, status, hi[, printed_hi]}, the
    printed decimal the number claimed: (hi, why it is refuted or None)."""
    only(claim, ("quantity", "status", "hi", "printed_hi"), "claim")
    hi = exact(claim, "hi", "claim")
    if "printed_hi" in claim and printed_number(claim["printed_hi"], "claim.printed_hi") != hi:
        return hi, "claim.printed_hi = %s is not the claimed %s" % (claim["printed_hi"], short(hi))
    return hi, None


def lower_bound_claim(claim):
    """A claim of status "lower_bound" ({lo[, printed_lo]}: a level >= lo only) or "bounds" (the same and
    {hi[, printed_hi]}), each printed decimal the number claimed: (lo, hi or None, why it is refuted or None)."""
    bounds = claim.get("status") == "bounds"
    only(claim, ("quantity", "status", "lo", "printed_lo") + (("hi", "printed_hi") if bounds else ()), "claim")
    lo = exact(claim, "lo", "claim")
    hi = exact(claim, "hi", "claim") if bounds else None
    why = None
    for key, x in (("printed_lo", lo), ("printed_hi", hi)):
        if key in claim and printed_number(claim[key], "claim." + key) != x and why is None:
            why = "claim.%s = %s is not the claimed %s" % (key, claim[key], short(x))
    if bounds and lo > hi and why is None:
        why = "claim: lo = %s > hi = %s" % (short(lo), short(hi))
    return lo, hi, why


def check_passivity_level(c):
    """phi* = min Re G (isp) or delta* = min Re(1/G) (osp) over theta in [0, pi], G Schur stable
    (OSP: no zero of G on the circle, delta* > 0): level >= lo iff E^ - lo F^ >= 0 on [-1, 1];
    level <= hi if E^(c0) - hi F^(c0) <= 0 at the witness c0 (F^ > 0 on [-1, 1]). A claim of status
    "upper_bound" (an OSP value <= 0, a zero of G on the circle: not the level) is the witness part
    alone, with F^(c0) > 0."""
    model, claim, evidence = parts(c)
    only(model, ("H", "set", "num", "den", "T", "kind"), "model")
    only(claim, ("quantity", "status", "value", "lo", "hi", "printed", "printed_lo", "printed_hi"), "claim")
    lemma1 = claim.get("status") in ("lower_bound", "bounds")
    if not lemma1:
        only(evidence, ("witness_c",), "evidence")
    kind = model.get("kind")
    if kind not in ("isp", "osp"):
        raise Malformed("model.kind: missing or neither \"isp\" nor \"osp\"")
    G, T = model_h(model)
    if not G.num:
        raise Malformed("model.H: G = 0")
    if len(G.num) > len(G.den):
        raise Malformed("model.H: G is not causal")
    if len(G.den) - 1 > MAX_DEGREE:
        raise TooLarge("degree %d of G above this checker's limit %d" % (len(G.den) - 1, MAX_DEGREE))
    ok, why = schur_cohn(G.den)
    if not ok:
        raise Malformed("model.H: G is not Schur stable (%s)" % why)
    osp = kind == "osp"
    E, F = re_over_circle(G.den, G.num) if osp else re_over_circle(G.num, G.den)
    one = Fraction(1)
    name = "delta*" if osp else "phi*"
    def upper_fails(hi, c0):
        if c0 < -1 or c0 > 1:
            return "evidence.witness_c = %s is outside [-1, 1]" % short(c0)
        if peval(F, c0) == 0:
            return "evidence.witness_c: %s = 0 there (no bound from it)" % ("G" if osp else "1/G")
        w0 = peval(E, c0) / peval(F, c0)
        if w0 > hi:
            return "%s <= %s (%.12g) not shown: the value at the witness c0 = %s is %.12g > hi" % (name, short(hi), float(hi), short(c0), float(w0))
        return None
    if claim.get("status") == "upper_bound":  # the level <= hi only (an OSP value <= 0, a zero of G on the circle)
        hi, refuted = upper_bound_claim(claim)
        if refuted:
            return False, refuted
        c0 = exact(evidence, "witness_c", "evidence")
        why = upper_fails(hi, c0)
        if why:
            return False, why
        return True, "%s <= %.12g (an upper bound only: the value %.12g at c0 = %s)" % (
            name, float(hi), float(peval(E, c0) / peval(F, c0)), short(c0))
    if lemma1:  # level >= lo by Lemma 1 at P for the realisation (A, B, C, D) in the evidence; hi as above
        lo, hi, refuted = lower_bound_claim(claim)
        only(evidence, ("A", "B", "C", "D", "P") + (("witness_c",) if hi is not None else ()), "evidence")
        A, B, C, D, P = (mimo_matrix(evidence, k) for k in ("A", "B", "C", "D", "P"))
        n = len(A)
        if n == 0 or any(len(r) != n for r in A) or len(B) != n or any(len(r) != 1 for r in B) or len(C) != 1 or \
                len(C[0]) != n or len(D) != 1 or len(D[0]) != 1 or len(P) != n or any(len(r) != n for r in P):
            raise Malformed("evidence: A n x n (n >= 1), B n x 1, C 1 x n, D 1 x 1, P n x n expected")
        c0 = exact(evidence, "witness_c", "evidence") if hi is not None else None
        if refuted:
            return False, refuted
        # G_r = D + C (tI - A)^-1 B equals G at n + deg(den) + 1 points where both are defined: then the
        # polynomial N d - p D of degree <= n + deg(den) vanishes there, so it is 0 (G_r = G)
        need, t, equal = n + len(G.den), 1, 0
        while equal < need:
            t += 1
            tq = Fraction(t)
            if peval(G.den, tq) == 0:
                continue
            X = solve_shifted(A, B, tq)
            if X is None:
                continue
            gr = D[0][0] + sum(C[0][i] * X[i][0] for i in range(n))
            g = peval(G.num, tq) / peval(G.den, tq)
            if gr != g:
                return False, "evidence: (A, B, C, D) does not realise G as written (at z = %d: %s, G = %s)" % (t, short(gr), short(g))
            equal += 1
        why = lemma1_level_fails(A, B, C, D, P, lo, osp)
        if why:
            return False, "%s >= %s (%.12g) not shown: %s" % (name, short(lo), float(lo), why)
        shown = "%s >= %.12g (Lemma 1 at P for the realisation written, equal to G at %d points)" % (name, float(lo), need)
        if hi is not None:
            why = upper_fails(hi, c0)
            if why:
                return False, why
            shown += "; %s <= %.12g at c0 = %s" % (name, float(hi), short(c0))
        return True, shown
    status, lo, hi, _, refuted = claim_range(claim)
    if refuted:
        return False, refuted
    if osp:
        if max_positive(F, F, -one, one):
            raise Malformed("model.H: G has a zero on the unit circle: delta* is not Lemma 1's level")
        if lo <= 0:
            raise Malformed("claim: an OSP value <= 0 is an upper bound of Lemma 1's level only")
    why = nonneg_on(psub(E, pscale(F, lo)), -one, one)
    if why:
        return False, "%s >= %s (%.12g) fails: E(c) - lo F(c) is %s" % (name, short(lo), float(lo), why)
    c0 = exact(evidence, "witness_c", "evidence")
    if c0 < -1 or c0 > 1:
        return False, "evidence.witness_c = %s is outside [-1, 1]" % short(c0)
    w0 = peval(E, c0) / peval(F, c0)
    if w0 > hi:
        return False, "%s <= %s (%.12g) not shown: the value at the witness c0 = %s is %.12g > hi" % (
            name, short(hi), float(hi), short(c0), float(w0))
    return True, "%s %s" % (name, ("= %s" % lo) if status == "exact" else "in [%.12g, %.12g]" % (float(lo), float(hi)))


# ---------------------------------------------------------------- passivity-level-mimo
MAX_MIMO_DEGREE = 24  # m n: the degree of the interpolated polynomial in u = tan^2(theta/2) (below)


def cq(x):
    return (Fraction(x), Fraction(0))


def cq_add(a, b):
    return (a[0] + b[0], a[1] + b[1])


def cq_sub(a, b):
    return (a[0] - b[0], a[1] - b[1])


def cq_mul(a, b):
    return (a[0] * b[0] - a[1] * b[1], a[0] * b[1] + a[1] * b[0])


def cq_div(a, b):
    n = b[0] * b[0] + b[1] * b[1]
    return ((a[0] * b[0] + a[1] * b[1]) / n, (a[1] * b[0] - a[0] * b[1]) / n)


def cq_det(M):
    """Determinant of a square matrix of Gaussian rationals (elimination with row exchanges)."""
    M = [list(r) for r in M]
    n, d = len(M), cq(1)
    for k in range(n):
        p = next((r for r in range(k, n) if M[r][k] != (0, 0)), None)
        if p is None:
            return cq(0)
        if p != k:
            M[k], M[p] = M[p], M[k]
            d = (-d[0], -d[1])
        d = cq_mul(d, M[k][k])
        for r in range(k + 1, n):
            if M[r][k] != (0, 0):
                f = cq_div(M[r][k], M[k][k])
                M[r] = [cq_sub(M[r][j], cq_mul(f, M[k][j])) for j in range(n)]
    return d


def mimo_matrix(model, key):
    rows = model.get(key)
    where = "model." + key
    if not isinstance(rows, list) or any(not isinstance(r, list) for r in rows):
        raise Malformed("%s: missing or not an array of rows" % where)
    if len(rows) > 64 or any(len(r) > 64 for r in rows):
        raise TooLarge("%s: more than 64 rows or columns" % where)
    M = [[exact_value(v, "%s[%d][%d]" % (where, i, j)) for j, v in enumerate(r)] for i, r in enumerate(rows)]
    if M and any(len(r) != len(M[0]) for r in M):
        raise Malformed("%s: rows of different lengths" % where)
    return M


def faddeev_leverrier(A):
    """det(zI - A), ascending coefficients: M_k = A M_{k-1} + c_{n-k+1} I, c_{n-k} = -tr(A M_k)/k."""
    n = len(A)
    coeffs = [Fraction(0)] * n + [Fraction(1)]
    Mk = [[Fraction(0)] * n for _ in range(n)]
    for k in range(1, n + 1):
        AM = [[sum(A[i][l] * Mk[l][j] for l in range(n)) for j in range(n)] for i in range(n)]
        Mk = [[AM[i][j] + (coeffs[n - k + 1] if i == j else 0) for j in range(n)] for i in range(n)]
        coeffs[n - k] = -sum(sum(A[i][l] * Mk[l][i] for l in range(n)) for i in range(n)) / k
    return coeffs


def mimo_G(sys, z):
    """G(z) = C (zI - A)^-1 B + D at a Gaussian rational z, by Gauss-Jordan elimination."""
    A, B, C, D = sys[:4]
    n, m = len(A), len(D)
    M = [[cq_sub(z if i == j else cq(0), cq(A[i][j])) for j in range(n)] + [cq(B[i][j]) for j in range(m)] for i in range(n)]
    for k in range(n):
        p = next(r for r in range(k, n) if M[r][k] != (0, 0))
        M[k], M[p] = M[p], M[k]
        piv = M[k][k]
        M[k] = [cq_div(x, piv) for x in M[k]]
        for r in range(n):
            if r != k and M[r][k] != (0, 0):
                f = M[r][k]
                M[r] = [cq_sub(M[r][j], cq_mul(f, M[k][j])) for j in range(n + m)]
    X = [row[n:] for row in M]
    return [[cq_add(cq(D[i][j]), reduce_sum(cq_mul(cq(C[i][l]), X[l][j]) for l in range(n))) for j in range(m)] for i in range(m)]


def reduce_sum(it):
    s = cq(0)
    for x in it:
        s = cq_add(s, x)
    return s


def he_minus(sys, z, nu):
    """He G(z) - nu I (ISP), or He G(z) - nu G(z)^H G(z) when sys carries "osp" (its fifth item)."""
    G = mimo_G(sys, z)
    m = len(G)
    H = [[((G[i][j][0] + G[j][i][0]) / 2 - (nu if i == j and not sys[4] else 0), (G[i][j][1] - G[j][i][1]) / 2)
          for j in range(m)] for i in range(m)]
    if sys[4]:  # (G^H G)_ij = sum_k conj(G_ki) G_kj
        for i in range(m):
            for j in range(m):
                g = reduce_sum(cq_mul((G[k][i][0], -G[k][i][1]), G[k][j]) for k in range(m))
                H[i][j] = cq_sub(H[i][j], (nu * g[0], nu * g[1]))
    return H


def circle_z(t):
    """z = (1 + jt)/(1 - jt) = ((1 - t^2) + 2jt)/(1 + t^2): theta = 2 atan t."""
    w = 1 + t * t
    return ((1 - t * t) / w, 2 * t / w)


def positive_definite(H):
    """Sylvester's criterion: every leading principal minor of the Hermitian H is > 0."""
    for k in range(1, len(H) + 1):
        d = cq_det([row[:k] for row in H[:k]])
        if d[1] != 0:
            raise AssertionError("a Hermitian minor is not real")
        if d[0] <= 0:
            return False
    return True


def integer_poly(p):
    """p times a positive rational so that its coefficients are coprime integers."""
    L = 1
    for a in p:
        L = L * a.denominator // gcd(L, a.denominator)
    ints = [int(a * L) for a in p]
    g = 0
    for a in ints:
        g = gcd(g, a)
    return [a // g for a in ints] if g else ints


def sign_at(p, x):
    """The sign of the integer polynomial p (non-empty) at the rational x = u/v, v > 0: the sign of
    v^d p(u/v) = sum p_k u^k v^(d - k), by Horner's rule h <- h u + p_k v^(d - k)."""
    u, v = x.numerator, x.denominator
    d = len(p) - 1
    h, vk = p[d], 1
    for k in range(d - 1, -1, -1):
        vk *= v
        h = h * u + p[k] * vk
    return (h > 0) - (h < 0)


def mimo_level_poly(sys, d, nu, det_g=False):
    """Q(u), u = t^2 = tan^2(theta/2), with Q(u(theta)) = (1 + u)^(mn) 2^m |d(z)|^(2m) det(He G(z) - nu I) on
    z = e^{j theta}. P(c) = 2^m |d|^(2m) det(He G - nu I) is a polynomial of degree <= mn in c = cos theta:
    it is det of d(z) d(1/z) (G(z) + G(1/z)^T - 2 nu I) on the circle, a Laurent polynomial in z of exponents
    -mn..mn invariant under z -> 1/z; with c = (1 - u)/(1 + u), (1 + u)^(mn) P(c) = sum p_i (1 - u)^i
    (1 + u)^(mn - i) has degree <= mn in u. Interpolated (Lagrange) at u = 0, 1, 4, ..., (mn)^2, each value
    computed on the circle point z(t) exactly (Gaussian rationals). OSP: He G - nu G^H G instead
    (d(z) d(1/z) G(1/z)^T G(z) is a Laurent polynomial matrix of exponents -n..n too: the same degree).
    det_g: (1 + u)^(mn) |d|^(2m) |det G(z)|^2 instead (|det(d G)|^2, degree <= mn in c likewise)."""
    m, n = len(sys[3]), len(sys[0])
    N = m * n
    xs, ys = [], []
    for k in range(N + 1):
        t = Fraction(k)
        z = circle_z(t)
        dz = (Fraction(0), Fraction(0))
        for a in reversed(d):
            dz = cq_add(cq_mul(dz, z), cq(a))
        if det_g:
            g = cq_det(mimo_G(sys, z))
            v = g[0] ** 2 + g[1] ** 2
        else:
            v = 2 ** m * cq_det(he_minus(sys, z, nu))[0]
        xs.append(t * t)
        ys.append((1 + t * t) ** N * (dz[0] ** 2 + dz[1] ** 2) ** m * v)
    Q = []
    for i in range(N + 1):  # Lagrange
        li, den = [Fraction(1)], Fraction(1)
        for j in range(N + 1):
            if j != i:
                li = pmul(li, [-xs[j], Fraction(1)])
                den *= xs[i] - xs[j]
        Q = padd(Q, pscale(li, ys[i] / den))
    return trim(Q)


def mimo_lower(sys, d, lo):
    """(None or why He G - lo I >= 0 fails on the circle, whether det(He G - lo I) has a root there, samples).
    In t = tan(theta/2) in [0, inf) (theta = pi at t = inf): the roots of R(t) = Q(t^2) are isolated by
    bisection with Sturm counts on [eps, B] (B a Cauchy bound; eps below every positive root when t = 0 is
    one); every isolating interval's ends, t = 0 (when not a root) and B sample every arc between roots."""
    Q = mimo_level_poly(sys, d, lo)
    if not Q:
        return "det(He G - lo I) is 0 at every theta: not decided", False, 0
    R = [Fraction(0)] * (2 * len(Q) - 1)
    R[0::2] = Q
    R = trim(R)
    root0 = peval(R, Fraction(0)) == 0
    Rr = R
    while len(Rr) > 1 and Rr[0] == 0:
        Rr = Rr[1:]
    Rr = sqfree(Rr)
    B = 1 + max((abs(a / Rr[-1]) for a in Rr[:-1]), default=Fraction(0))
    eps = Fraction(0)
    if root0:
        eps = abs(Rr[0]) / (abs(Rr[0]) + max(abs(a) for a in Rr)) / 2  # |root| > |a_0|/(|a_0| + max|a_i|)
    points, roots = {B}, 0
    if not root0:
        points.add(Fraction(0))
    else:
        points.add(eps)
    # Rr square-free: one Sturm sequence for every count, each member scaled to integer coefficients
    # (a positive factor: the same signs), evaluated homogeneously in integers at x = p/q
    seq = [integer_poly(q) for q in sturm_seq(Rr)] if len(Rr) > 1 else []

    def sign_variations(x):
        signs = [v for v in (sign_at(q, x) for q in seq if q) if v != 0]
        return sum(1 for u, v in zip(signs, signs[1:]) if u != v)
    stack = [(eps, B)] if len(Rr) > 1 else []
    while stack:
        a, b = stack.pop()
        k = sign_variations(a) - sign_variations(b)  # distinct roots in (a, b), neither end a root
        if k == 0:
            continue
        if k == 1:
            roots += 1
            points.update((a, b))
            continue
        mid = (a + b) / 2
        while peval(Rr, mid) == 0:
            mid = (mid + b) / 2
        stack += [(a, mid), (mid, b)]
    at_pi = cq_det(he_minus(sys, cq(-1), lo))[0] == 0
    touches = roots > 0 or root0 or at_pi
    for t in sorted(points):
        if not positive_definite(he_minus(sys, circle_z(t), lo)):
            return ("He G - lo I is not positive definite at t = tan(theta/2) = %s, where det != 0" % short(t)), touches, len(points)
    return None, touches, len(points)


def mimo_regular_on_circle(sys, d):
    """None when det G(e^{j theta}) != 0 for every theta, else why not: Q(u) of mimo_level_poly(det_g)
    has no root u = t^2, t in [0, inf) (Q(0) != 0, Sturm on (0, B], B a Cauchy bound), and det G(-1) != 0
    (theta = pi, t = inf)."""
    if cq_det(mimo_G(sys, cq(-1))) == (0, 0):
        return "det G(-1) = 0 (a zero of G at z = -1)"
    Q = mimo_level_poly(sys, d, 0, det_g=True)
    if not Q:
        return "det G is 0 at every theta"
    if peval(Q, Fraction(0)) == 0:
        return "det G(1) = 0 (a zero of G at z = 1)"
    Qs = sqfree(Q)
    if len(Qs) > 1:
        B = 1 + max(abs(a / Qs[-1]) for a in Qs[:-1])
        seq = [integer_poly(q) for q in sturm_seq(Qs)]

        def variations(x):
            signs = [v for v in (sign_at(q, x) for q in seq if q) if v != 0]
            return sum(1 for u, v in zip(signs, signs[1:]) if u != v)
        if variations(Fraction(0)) - variations(B) != 0:
            return "det G vanishes on the unit circle (|det G|^2 has a root in u = tan^2(theta/2) > 0, Sturm)"
    return None


def check_passivity_level_mimo(c):
    """phi* = min over theta of lambda_min(He G(e^{j theta})), G = C(zI - A)^-1 B + D square, A Schur stable:
    phi* >= lo iff He G - lo I > 0 at one point of every arc between the roots of its determinant (times
    |d|^(2m)) on the circle; phi* <= hi if He G - hi I is not > 0 at the witness (c0, s0), c0^2 + s0^2 = 1;
    an exact claim v: phi* >= v so, and det(He G - v I) = 0 somewhere on the circle. OSP: delta* the same
    with He G - nu G^H G (a congruence of He G^-1 - nu I where G is regular: det G != 0 on the circle is
    checked first), and lo > 0. A claim of status "upper_bound" (an OSP value <= 0) is the witness
    part alone, with det G(z0) != 0 for OSP (then for every nu > hi the pencil is not >= 0 at z0).
    Status "lower_bound" (or "bounds": with such an upper bound beside it): the level >= lo if P = P' > 0
    and paper 000's (2) < 0 at the level lo with evidence.P (Lemma 1's "if": (1) holds with V = x'Px)."""
    model, claim, evidence = parts(c)
    only(model, ("A", "B", "C", "D", "T", "kind"), "model")
    only(claim, ("quantity", "status", "value", "lo", "hi", "printed", "printed_lo", "printed_hi"), "claim")
    if model.get("kind") not in ("isp", "osp"):
        raise Malformed("model.kind: missing or not \"isp\" or \"osp\"")
    osp = model["kind"] == "osp"
    period(model)
    A, B, C, D = (mimo_matrix(model, k) for k in ("A", "B", "C", "D"))
    n, m = len(A), (len(B[0]) if B else 0)
    if n == 0 or any(len(r) != n for r in A):
        raise Malformed("model.A: empty or not square")
    if len(B) != n or m == 0:
        raise Malformed("model.B: not n x m with m >= 1")
    if len(C) != m or any(len(r) != n for r in C):
        raise Malformed("model.C: not m x n (G square)")
    if len(D) != m or any(len(r) != m for r in D):
        raise Malformed("model.D: not m x m")
    if m * n > MAX_MIMO_DEGREE:
        raise TooLarge("m n = %d above this checker's limit %d" % (m * n, MAX_MIMO_DEGREE))
    d = faddeev_leverrier(A)
    ok, why = schur_cohn(d)
    if not ok:
        raise Malformed("model.A: not Schur stable (%s)" % why)
    sys_ = (A, B, C, D, osp)
    lvl = "delta*" if osp else "phi*"
    status = claim.get("status")
    if status in ("upper_bound", "lower_bound", "bounds"):
        # the level <= hi (an OSP value <= 0): the witness; the level >= lo: Lemma 1 at the storage P
        if status == "upper_bound":
            lo, (hi, refuted) = None, upper_bound_claim(claim)
        else:
            lo, hi, refuted = lower_bound_claim(claim)
        only(evidence, (("witness_c", "witness_s") if hi is not None else ()) + (("P",) if lo is not None else ()), "evidence")
        if hi is not None:
            c0, s0 = exact(evidence, "witness_c", "evidence"), exact(evidence, "witness_s", "evidence")
        if lo is not None:
            P = mimo_matrix(evidence, "P")
            if len(P) != n or any(len(r) != n for r in P):
                raise Malformed("evidence.P: not %d x %d (the states)" % (n, n))
        if refuted:
            return False, refuted
        shown = []
        if lo is not None:
            why = lemma1_level_fails(A, B, C, D, P, lo, osp)
            if why:
                return False, "%s >= %s (%.12g) not shown: %s" % (lvl, short(lo), float(lo), why)
            shown.append("%s >= %.12g (Lemma 1 at P: P > 0, (2) < 0)" % (lvl, float(lo)))
        if hi is not None:
            if c0 * c0 + s0 * s0 != 1:
                return False, "evidence: the witness (%s, %s) is not on the unit circle" % (short(c0), short(s0))
            if osp and cq_det(mimo_G(sys_, (c0, s0))) == (0, 0):
                return False, "evidence: det G = 0 at the witness (no bound from it)"
            if positive_definite(he_minus(sys_, (c0, s0), hi)):
                return False, "%s <= %s (%.12g) not shown: the pencil at hi is positive definite at the witness" % (lvl, short(hi), float(hi))
            shown.append("%s <= %.12g (the pencil at hi not > 0 at the witness%s)" % (lvl, float(hi), ", G regular there" if osp else ""))
        return True, "%s (%dx%d%s)" % ("; ".join(shown), m, m, ", an upper bound only" if lo is None else "")
    if osp:  # G regular on the circle: He G - nu G^H G = G^H (He G^-1 - nu I) G there
        why = mimo_regular_on_circle(sys_, d)
        if why:
            raise Malformed("model: %s: the OSP pencil's minimum is not the level there" % why)
    status, lo, hi, _, refuted = claim_range(claim)
    if status == "exact":
        only(evidence, (), "evidence")
    else:
        only(evidence, ("witness_c", "witness_s"), "evidence")
    if refuted:
        return False, refuted
    if status != "exact":
        c0, s0 = exact(evidence, "witness_c", "evidence"), exact(evidence, "witness_s", "evidence")
    if osp and lo <= 0:
        return False, "delta* >= %s: an OSP claim needs lo > 0 (a value <= 0 is not Lemma 1's level)" % short(lo)
    why, touches, samples = mimo_lower(sys_, d, lo)
    if why:
        return False, "%s >= %s (%.12g) fails: %s" % (lvl, short(lo), float(lo), why)
    if status == "exact":
        if not touches:
            return False, "%s <= %s not shown: the pencil at v is regular on the whole circle (%s > v)" % (lvl, short(lo), lvl)
        return True, "%s = %s (%dx%d, %d states; %d samples)" % (lvl, lo, m, m, n, samples)
    if c0 * c0 + s0 * s0 != 1:
        return False, "evidence: the witness (%s, %s) is not on the unit circle" % (short(c0), short(s0))
    if positive_definite(he_minus(sys_, (c0, s0), hi)):
        return False, "%s <= %s (%.12g) not shown: the pencil at hi is positive definite at the witness" % (lvl, short(hi), float(hi))
    return True, "%s in [%.12g, %.12g] (%dx%d, %d states; %d samples)" % (lvl, float(lo), float(hi), m, m, n, samples)


# ---------------------------------------------------------------- r
def check_r(c):
    only(c, ("certificate", "version", "kind", "model", "claim", "evidence", "produced_by"), "certificate")
    model, claim = obj_field(c, "model"), obj_field(c, "claim")
    only(model, ("T", "omega"), "model")
    only(claim, ("quantity", "re", "im_lo", "im_hi", "printed_im"), "claim")
    if "evidence" in c:
        only(obj_field(c, "evidence"), (), "evidence")
    T, w = exact(model, "T", "model"), exact(model, "omega", "model")
    if T <= 0:
        raise Malformed("model.T: must be > 0")
    if w == 0:
        raise Malformed("model.omega: w = 0 is a pole of r")
    re, lo, hi = exact(claim, "re", "claim"), exact(claim, "im_lo", "claim"), exact(claim, "im_hi", "claim")
    if re != -T / 2:
        return False, "claim.re = %s is not -T/2 = %s" % (re, -T / 2)
    if lo > hi:
        return False, "claim: im_lo > im_hi"
    if "printed_im" in claim:
        q = printed_number(claim["printed_im"], "claim.printed_im")
        if q < lo or q > hi:
            return False, "claim.printed_im is outside [im_lo, im_hi]"
    from mpmath import iv
    old = iv.prec
    try:
        bits = 128
        while bits <= 65536:
            iv.prec = bits
            x = iv.mpf(w.numerator) * iv.mpf(T.numerator) / (iv.mpf(w.denominator) * iv.mpf(T.denominator) * 2)
            y = -iv.cot(x) * iv.mpf(T.numerator) / (2 * iv.mpf(T.denominator))
            a, b = (exact_mpf(e) for e in y._mpi_)
            if a is not None and b is not None:
                if lo <= a and b <= hi:
                    return True, "Re r = -T/2, Im r in [%.12g, %.12g] (mpmath iv, %d bits)" % (float(lo), float(hi), bits)
                if b < lo or a > hi:
                    return False, "Im r = -(T/2) cot(wT/2) is outside [im_lo, im_hi] (mpmath iv at %d bits)" % bits
            bits *= 2
    finally:
        iv.prec = old
    return False, "Im r in [im_lo, im_hi] not shown at 65536 bits"


def exact_mpf(t):
    """The exact rational of an mpmath mpf tuple (sign, mantissa, exponent, bits), None when it is
    not finite (inf and nan have mantissa 0 and a non-zero exponent)."""
    sign, man, exp, _ = t
    if man == 0 and exp != 0:  # inf, nan
        return None
    v = Fraction(man) * (Fraction(2) ** exp)
    return -v if sign else v


# ---------------------------------------------------------------- stability
MAX_STABILITY_DEGREE = 400


def sampled_device(N, k, T):
    """Nd with P_d(z) = Nd(z)/(z-1)^k, the zero-order hold of N(s)/s^k (deg N < k), from the
    pulse response: y(l) = sum_m b_m (lT)^m/m! (the step response; b_m the coefficient of s^(k-m)
    in N), h_l = y(l) - y(l-1) for l >= 1, h_0 = y(0) = 0, P_d = sum_l h_l z^-l; with w = 1/z,
    g(w) = (1-w)^k sum_l h_l w^l is a polynomial of degree <= k (the k-th differences of a
    polynomial of degree k-1 in l vanish; checked) and Nd(z) = z^k g(1/z)."""
    def y(l):
        v, fact = Fraction(0), 1
        for m in range(1, k + 1):
            fact *= m
            v += N[k - m] * (l * T) ** m / fact if k - m < len(N) else 0
        return v
    L = 2 * k + 3
    h = [Fraction(0)] + [y(l) - y(l - 1) for l in range(1, L)]
    binom = ppow([Fraction(1), Fraction(-1)], k)  # (1 - w)^k
    g = [sum((binom[j] * h[i - j] for j in range(len(binom)) if 0 <= i - j < L), Fraction(0)) for i in range(L)]
    if any(x != 0 for x in g[k + 1:]):
        raise AssertionError("the sampled device is not Nd/(z-1)^k")
    return trim([g[k - i] for i in range(k + 1)])


def schur_cohn(p):
    """(True, why) when every root of p (ascending, non-zero) is in |z| < 1, else (False, the step
    that fails): |p_0| < |p_d| and the Schur transform (p_d p - p_0 p*)/z stable (Schur, Cohn)."""
    a = trim(p)
    while len(a) > 1:
        d = len(a) - 1
        if abs(a[0]) >= abs(a[-1]):
            return False, "Schur-Cohn at degree %d: |p_0| >= |p_d| (a root on or outside the unit circle)" % d
        q = [a[-1] * a[i + 1] - a[0] * a[d - 1 - i] for i in range(d)]
        a = [x / q[-1] for x in q]
    return True, "every Schur-Cohn step passes"


def effective_device(model):
    """(T, n, params, P_eff) of a one-DOF loop's model as written: P_eff = P/(1 + s Zop P), the plant
    with its operator (model.H is read by the caller)."""
    for key in ("plant", "H"):
        if not isinstance(model.get(key), str):
            raise Malformed("model.%s: missing or not a string" % key)
    if "operator" in model and not isinstance(model["operator"], str):
        raise Malformed("model.operator: not a string")
    T, n, params = period(model), delay_of(model), parameters(model)
    try:
        dev = parse_h(model["plant"], T, params, 's', 'model.plant')
        if "operator" in model:
            Z = parse_h(model["operator"], T, params, 's', 'model.operator')
            one = RF([Fraction(1)]) + RF([Fraction(0), Fraction(1)]) * Z * dev
            if not one.num:
                raise Malformed("model.operator: 1 + s Z_op P is zero")
            whole = padd(pmul(dev.den, Z.den), pmul([Fraction(0), Fraction(1)], pmul(Z.num, dev.num)))
            dev = dev / one
            # the device's and the operator's modes are the roots of Dp Dz + s Nz Np; one the reduction cancels
            # stays a mode of the loop as written: in Re s >= 0 it is malformed (but one s: the operator spring's
            # deflection beside the position it integrates, a conserved quantity)
            lost, rem = pdivmod(whole, dev.den)
            lost = trim(lost)
            if len(lost) > 1 and lost[0] == 0:
                lost = lost[1:]
            if len(lost) > 1 and not hurwitz(lost)[0]:
                raise Malformed("model.operator: P/(1 + s Z_op P) cancels a mode of the device and the operator with "
                                "Re s >= 0: realised as written it is a hidden mode the wall does not move")
    except ZeroDivisionError:
        raise Malformed("model: division by zero")
    if not dev.num:
        raise Malformed("model.plant: zero (the device does not move)")
    return T, n, params, dev


def loop_device(model, one_pole=False):
    """(T, n, params, k, Nd) of a one-DOF loop's model as written (model.H is read by the caller):
    P_eff = P/(1 + s Zop P) = N/s^k (every pole at s = 0, else not modelled here: malformed) and its
    zero-order hold Nd/(z-1)^k (sampled_device). With one_pole, P_eff = N/(s^k (s - p)) with one
    simple rational pole p != 0 is taken too: then Nd is the tuple (p, r, Ndp) of pole_device."""
    T, n, params, dev = effective_device(model)
    k = len(dev.den) - 1
    if len(dev.num) > k:
        raise Malformed("model.plant: the device is not strictly proper")
    N = [x / dev.den[-1] for x in dev.num]
    if any(x != 0 for x in dev.den[:k]):
        k0 = next(i for i, x in enumerate(dev.den) if x != 0)  # den = s^k0 q(s), q(0) != 0
        if not one_pole or k - k0 > 2:
            raise Malformed("model.plant: the device has a pole off s = 0: this checker handles devices with every pole "
                            "at s = 0%s only" % (" or one or two poles off it (a mass-damper, a spring)" if one_pole else ""))
        if k - k0 == 1:
            return T, n, params, k0, pole_device(N, k0, -dev.den[k0] / dev.den[k0 + 1], T)
        return T, n, params, k0, spring_device(N, k0, [x / dev.den[-1] for x in dev.den[k0:]], T)
    return T, n, params, k, sampled_device(N, k, T)


def pole_device(N, k, p, T):
    """(p, r, Ndp) of P_eff = N/(s^k (s - p)): P_eff/s = Q/s^(k+1) + r/(s - p), r = N(p)/p^(k+1), so the
    step response sampled is y(l) = sum_m q_(k-m) (lT)^m/m! + r (E^l - 1) (E = e^(pT); the constants
    cancel, y(0) = 0) and its differences give P_d = Ndp/(z-1)^k + r (E - 1)/(z - E), Ndp the hold of
    Q/s^k (sampled_device)."""
    r = peval(N, p) / p ** (k + 1)
    Q, rem = pdivmod(padd(N, [Fraction(0)] * (k + 1) + [-r]), [-p, Fraction(1)])
    if trim(rem):
        raise AssertionError("N - r s^(k+1) is not divisible by s - p")
    return p, r, sampled_device(Q, k, T)


def spring_device(N, k, q, T):
    """('spring', A_c, R, Ndp) of P_eff = N/(s^k q(s)), q = s^2 + a1 s + a0 monic, a0 != 0 (two poles
    off s = 0, real or complex). Partial fractions over Q: P_eff/s = Q/s^(k+1) + R/q, R = R0 + R1 s =
    N s^-(k+1) mod q (s^-1 = -(s + a1)/a0 mod q), Q = (N - R s^(k+1))/q (exact division, checked).
    R/q = C (sI - A_c)^-1 B with A_c = [[0, 1], [-a0, -a1]], B = [0; 1], C = [R0, R1], so the step
    response y(lT) = (the hold of Q/s^k's part) + C Phi^l B - C B, Phi = e^(A_c T) (y(0) = 0:
    Q_k + R1 = 0, checked), and the hold of R/q is (z - 1) C (zI - Phi)^-1 B - C B = Nq/Delta, Delta =
    det(zI - Phi), Nq = (R0 phi12 - R1 + R1 phi22) z - R0 phi12 + R1 phi11 - R1 det(Phi)."""
    a0, a1 = q[0], q[1]
    if a0 == 0 or len(q) != 3 or q[2] != 1:
        raise AssertionError("q is not monic of degree 2 with q(0) != 0")
    sinv = [-a1 / a0, -1 / a0]  # s^-1 mod q

    def mod_q(p):
        return pdivmod(p, q)[1] if len(trim(p)) > 2 else trim(p)
    R = mod_q(N)
    for _ in range(k + 1):
        R = mod_q(pmul(R, sinv))
    R = (R + [Fraction(0), Fraction(0)])[:2]
    Q, rem = pdivmod(padd(N, pscale([Fraction(0)] * (k + 1) + R, -1)), q)
    if trim(rem):
        raise AssertionError("N - R s^(k+1) is not divisible by q")
    Qk = Q[k] if k < len(Q) else Fraction(0)
    if Qk + R[1] != 0:
        raise AssertionError("the step response is not 0 at t = 0")
    return "spring", [[Fraction(0), Fraction(1)], [-a0, -a1]], R, sampled_device(Q, k, T)


class Iv:
    """A closed interval [lo, hi] = [a, b] / 2^e with integers a <= b. Dyadic endpoints make each operation a few
    integer operations (a Fraction costs a gcd on every one). Results are rounded outward to the grid 2^-bits
    (Iv.bits; sums of points on one grid are exact), so each operation encloses the exact result for every pair
    of points of its operands, and lo, hi are the endpoints as Fractions."""
    bits = 128
    __slots__ = ('a', 'b', 'e')

    def __init__(self, lo, hi=None):
        e = Iv.bits
        if type(lo) is int and hi is None:
            self.a = self.b = lo << e
        else:
            lo = Fraction(lo)
            hi = lo if hi is None else Fraction(hi)
            self.a = (lo.numerator << e) // lo.denominator  # floor
            self.b = -((-hi.numerator << e) // hi.denominator)  # ceiling
        self.e = e

    @staticmethod
    def grid(a, b, e):
        """[a, b] / 2^e, rounded outward to 2^-bits where e is finer."""
        r = object.__new__(Iv)
        s = e - Iv.bits
        if s > 0:
            a, b, e = a >> s, -((-b) >> s), Iv.bits  # >> is a floor on Python's integers of either sign
        r.a, r.b, r.e = a, b, e
        return r

    @property
    def lo(self):
        return Fraction(self.a, 1 << self.e)

    @property
    def hi(self):
        return Fraction(self.b, 1 << self.e)

    def __add__(self, o):
        if not isinstance(o, Iv):
            o = Iv(o)
        s = self.e - o.e
        if s == 0:
            return Iv.grid(self.a + o.a, self.b + o.b, self.e)
        if s > 0:
            return Iv.grid(self.a + (o.a << s), self.b + (o.b << s), self.e)
        return Iv.grid((self.a << -s) + o.a, (self.b << -s) + o.b, o.e)
    __radd__ = __add__

    def __neg__(self):
        return Iv.grid(-self.b, -self.a, self.e)

    def __sub__(self, o):
        return self + (-(o if isinstance(o, Iv) else Iv(o)))

    def __rsub__(self, o):
        return Iv(o) - self

    def __mul__(self, o):
        if not isinstance(o, Iv):  # times an exact rational p/q: two products, one floor and one ceiling
            c = o if type(o) in (int, Fraction) else Fraction(o)
            p, q = c.numerator, c.denominator
            lo, hi = (self.a * p, self.b * p) if p >= 0 else (self.b * p, self.a * p)
            return Iv.grid(lo // q, -((-hi) // q), self.e)
        e = self.e + o.e
        if o.a == o.b:  # an exact dyadic
            c = o.a
            return Iv.grid(self.a * c, self.b * c, e) if c >= 0 else Iv.grid(self.b * c, self.a * c, e)
        ps = (self.a * o.a, self.a * o.b, self.b * o.a, self.b * o.b)
        return Iv.grid(min(ps), max(ps), e)
    __rmul__ = __mul__

    def __truediv__(self, o):
        if o.a <= 0 <= o.b:
            raise ZeroDivisionError("interval divisor holds 0")
        one = 1 << (o.e + Iv.bits)  # 1/[a, b] 2^e = [2^e/b, 2^e/a], on the grid 2^-bits, for either sign
        return self * Iv.grid(one // o.b, -((-one) // o.a), Iv.bits)

    def absolute(self):
        if self.a >= 0:
            return self
        if self.b <= 0:
            return -self
        return Iv.grid(0, max(-self.a, self.b), self.e)


def iv_matmul(X, Y):
    """X Y for matrices whose entries are Iv or exact numbers (made Iv): each entry's sum of products taken on
    the integers of the endpoints (all at one exponent: the lower ends of the products summed, and the upper),
    rounded outward once. Encloses X Y for every pair of matrices in X and Y."""
    def ints(Z):
        Z = [[z if isinstance(z, Iv) else Iv(z) for z in row] for row in Z]
        e = max((z.e for row in Z for z in row), default=0)
        return [[(z.a << (e - z.e), z.b << (e - z.e)) for z in row] for row in Z], e
    (Xi, ex), (Yi, ey) = ints(X), ints(Y)
    cols = list(zip(*Yi))
    out = []
    for row in Xi:
        terms = [(k, a, b) for k, (a, b) in enumerate(row) if a or b]
        r = []
        for col in cols:
            lo = hi = 0
            for k, a, b in terms:
                c, d = col[k]
                if a == b:
                    p, q = a * c, a * d
                    if a < 0:
                        p, q = q, p
                elif c == d:
                    p, q = a * c, b * c
                    if c < 0:
                        p, q = q, p
                else:
                    ps = (a * c, a * d, b * c, b * d)
                    p, q = min(ps), max(ps)
                lo += p
                hi += q
            r.append(Iv.grid(lo, hi, ex + ey))
        out.append(r)
    return out


def expm_interval(A, t, bits):
    """e^(A t) (A 2x2 rational, t > 0) enclosed entrywise: M = A t/2^s with ||M||_inf <= 1/2, its
    Taylor sum to N terms in exact Fractions plus the remainder bound ||M||^N/N! * 2 (geometric,
    ||M|| <= 1/2) on every entry, then s squarings in interval arithmetic."""
    Iv.bits = bits
    M = [[x * t for x in row] for row in A]
    s = 0
    norm = max(abs(r[0]) + abs(r[1]) for r in M)
    while norm > Fraction(1, 2) * 2 ** s:
        s += 1
    M = [[x / 2 ** s for x in row] for row in M]
    norm = norm / 2 ** s

    def mm(X, Y):
        return [[X[i][0] * Y[0][j] + X[i][1] * Y[1][j] for j in range(2)] for i in range(2)]
    S = [[Fraction(1), Fraction(0)], [Fraction(0), Fraction(1)]]
    term, j, bound = S, 0, Fraction(1)
    while True:
        j += 1
        term = [[x / j for x in row] for row in mm(term, M)]
        bound = bound * norm / j
        S = [[S[a][b] + term[a][b] for b in range(2)] for a in range(2)]
        if bound * 2 < Fraction(1, 2 ** (bits + 8)):
            break
    rem = bound * norm / (j + 1) * 2
    P = [[Iv(x - rem, x + rem) for x in row] for row in S]
    for _ in range(s):
        P = mm(P, P)
    return P


def ipoly_mul(a, b):
    """a b for polynomials whose coefficients are Iv or Fraction (ascending)."""
    out = [Iv(0)] * (len(a) + len(b) - 1)
    for i, x in enumerate(a):
        for j, y in enumerate(b):
            out[i + j] = out[i + j] + x * y
    return out


def ipoly_add(a, b):
    n = max(len(a), len(b))
    return [(a[i] if i < len(a) else Iv(0)) + (b[i] if i < len(b) else Iv(0)) for i in range(n)]


def spring_charpoly(n, k, spring, A, L, T, bits):
    """c(z) = z^n L (z - 1)^k Delta + A (Ndp Delta + (z - 1)^k Nq) (spring_device), in intervals."""
    _, Ac, R, Ndp = spring
    Phi = expm_interval(Ac, T, bits)
    det = Phi[0][0] * Phi[1][1] - Phi[0][1] * Phi[1][0]
    Delta = [det, -(Phi[0][0] + Phi[1][1]), Iv(1)]
    Nq = [R[1] * Phi[0][0] - R[0] * Phi[0][1] - R[1] * det, R[0] * Phi[0][1] - R[1] + R[1] * Phi[1][1]]
    Dk = ppow([Fraction(-1), Fraction(1)], k)
    c = ipoly_mul(pmul([Fraction(0)] * n + L, Dk), Delta)
    return ipoly_add(c, ipoly_mul(A, ipoly_add(ipoly_mul(Ndp, Delta), ipoly_mul(Dk, Nq)))), Phi


def schur_cohn_interval(p):
    """schur_cohn for every polynomial whose coefficients lie in the intervals p (ascending; the
    leading one must exclude 0): (True/False, why) when each step's comparison |p_0| < |p_d| is
    decided over the whole box, None when one is not."""
    a = list(p)
    while len(a) > 1:
        d = len(a) - 1
        a0, ad = a[0].absolute(), a[-1].absolute()
        if a0.lo >= ad.hi:
            return False, "interval Schur-Cohn at degree %d: |p_0| >= |p_d| for every polynomial in the enclosure" % d
        if not a0.hi < ad.lo:
            return None
        q = [a[-1] * a[i + 1] - a[0] * a[d - 1 - i] for i in range(d)]
        if q[-1].lo <= 0:  # p_d^2 - p_0^2 > 0, but its enclosure is too wide to show it
            return None
        a = [x / q[-1] for x in q]
    return True, "every Schur-Cohn step passes for every polynomial in the enclosure"


def exp_interval(x, bits):
    """[lo, hi], Fractions with denominators 2^bits, holding e^x (x rational): y = x/2^s with
    |y| <= 1/2, its Taylor sum to N terms with the remainder |y|^(N+1)/(N+1)! * 2 (a geometric bound
    for |y| <= 1/2), rounded outward, then squared s times (every value > 0: monotone)."""
    s = 0
    while abs(x) > Fraction(1, 2) * 2 ** s:
        s += 1
    y = x / 2 ** s
    unit = Fraction(1, 2 ** bits)
    term, total, k = Fraction(1), Fraction(0), 0
    while True:
        total += term
        k += 1
        term = term * y / k
        if abs(term) * 2 < unit:
            break
    lo, hi = total - 2 * abs(term) - unit, total + 2 * abs(term) + unit

    def down(v):
        return Fraction((v.numerator * 2 ** bits) // v.denominator, 2 ** bits)

    def up(v):
        return Fraction(-((-v.numerator * 2 ** bits) // v.denominator), 2 ** bits)
    lo, hi = down(lo), up(hi)
    for _ in range(s):
        lo, hi = down(lo * lo), up(hi * hi)
    if lo <= 0:
        raise AssertionError("exp enclosure not positive")
    return lo, hi


def pshift(p, a):
    """p(x + a), by Horner's rule on polynomials."""
    q = []
    for c in reversed(p):
        q = padd(pmul(q, [a, Fraction(1)]), [c])
    return trim(q)


def loop_poly(n, k, Nd, A, L):
    """c = z^n L (z-1)^k + A Nd: the characteristic polynomial with the wall H = A/L."""
    return padd(pmul([Fraction(0)] * n + L, ppow([Fraction(-1), Fraction(1)], k)), pmul(A, Nd))


def loop_wall(model, T, params, n):
    """model.H, the wall H(z) as written, with z^-n H causal."""
    try:
        H = parse_h(model["H"], T, params, 'z', 'model.H')
    except ZeroDivisionError:
        raise Malformed("model: division by zero")
    if len(H.num) > len(H.den) + n:
        raise Malformed("model.H: z^-n H(z) is not causal")
    return H


MAX_WINDING_DEGREE = 10000  # about 4 (d + 16) arcs at ~0.6 ms each in mpmath's intervals: ~25 s


def winding_count(n, LD, AN):
    """The roots of c(z) = z^n LD(z) + AN(z) (real coefficients, deg AN < n + deg LD) inside |z| < 1,
    z^n never expanded: the argument principle on the upper half circle z = e^(j pi t), t in [0, 1],
    given c(1), c(-1) != 0 (the caller checks them exactly). [0, 1] is cut into arcs, each halved until
    c's rectangle over it (mpmath iv, 128 bits) excludes 0; the rectangle then lies in one of the open
    half-planes Re > 0, Im > 0, Re < 0, Im < 0 (h = 0, 1, 2, 3 quarter turns), where arg c is within a
    quarter turn of h pi/2. Adjacent arcs share a point: their half-planes are never opposite, and the
    unwrapped arg moves by +1, -1 or 0 quarter turns from one to the next (integers only). The ends
    are real, in Re half-planes: roots inside = (quarter turns)/2 (c(conj z) = conj c(z)). None when an
    arc narrower than 2^-100 is not decided (a root on or too near the circle)."""
    from mpmath import iv
    old = iv.prec
    iv.prec = 128
    try:
        def point(q):
            return iv.mpf(q.numerator) / iv.mpf(q.denominator)

        LDi = [point(a) if isinstance(a, Fraction) else a for a in LD]  # Fractions or mpmath intervals
        ANi = [point(a) if isinstance(a, Fraction) else a for a in AN]

        def horner(p, zr, zi):
            vr, vi = iv.mpf(0), iv.mpf(0)
            for a in reversed(p):
                vr, vi = vr * zr - vi * zi + a, vr * zi + vi * zr
            return vr, vi

        def rectangle(a, b):
            t = iv.mpf([point(a).a, point(b).b])
            zr, zi = iv.cos(iv.pi * t), iv.sin(iv.pi * t)
            nr, ni = iv.cos(iv.pi * n * t), iv.sin(iv.pi * n * t)
            lr, li = horner(LDi, zr, zi)
            ar, ai = horner(ANi, zr, zi)
            return nr * lr - ni * li + ar, nr * li + ni * lr + ai
        arcs0 = 4 * (n + len(LD) - 1 + 16)
        todo = [(Fraction(i - 1, arcs0), Fraction(i, arcs0)) for i in range(arcs0, 0, -1)]
        turns, first, last, count = 0, None, None, 0
        while todo:
            a, b = todo.pop()
            re, im = rectangle(a, b)
            h = 0 if re.a > 0 else 1 if im.a > 0 else 2 if re.b < 0 else 3 if im.b < 0 else None
            if h is None:
                if b - a < Fraction(1, 2 ** 100):
                    return None
                m = (a + b) / 2
                todo += [(m, b), (a, m)]
                continue
            count += 1
            if first is None:
                first = h
            else:
                step = (h - last) % 4
                if step == 2:
                    raise AssertionError("opposite half-planes on adjacent arcs")
                turns += {0: 0, 1: 1, 3: -1}[step]
            last = h
        if first % 2 or last % 2 or turns % 2:
            raise AssertionError("the ends of the half circle are not in Re half-planes")
        return turns // 2, count
    finally:
        iv.prec = old


def winding_parts(n, k, Nd, A, L, T, bits):
    """c(z) = z^n P1(z) + P0(z), z^n kept apart: Fractions with every device pole at s = 0 (P1 = L (z-1)^k,
    P0 = A Nd); mpmath intervals with a mass-damper (P1 = L (z-1)^k (z - E), P0 = A (Ndp (z - E) +
    r (E - 1)(z-1)^k), E = e^(pT) by exp_interval) or a spring (P1 = L (z-1)^k Delta, P0 = A (Ndp Delta +
    (z-1)^k Nq), Phi by expm_interval: spring_charpoly's formulas)."""
    from mpmath import iv
    Dk = ppow([Fraction(-1), Fraction(1)], k)
    LD = trim(pmul(L, Dk))
    if not isinstance(Nd, tuple):
        return LD, trim(pmul(A, Nd))
    iv.prec = bits

    def box(lo, hi):
        return iv.mpf([(iv.mpf(lo.numerator) / lo.denominator).a, (iv.mpf(hi.numerator) / hi.denominator).b])

    def mul(a, b):
        out = [iv.mpf(0)] * (len(a) + len(b) - 1)
        for i, x in enumerate(a):
            for j, y in enumerate(b):
                out[i + j] = out[i + j] + x * y
        return out

    def add(a, b):
        return [(a[i] if i < len(a) else 0) + (b[i] if i < len(b) else 0) for i in range(max(len(a), len(b)))]

    def fr(p):
        return [box(x, x) for x in p]
    if Nd[0] == "spring":
        _, Ac, R, Ndp = Nd
        Phi = [[box(x.lo, x.hi) for x in row] for row in expm_interval(Ac, T, bits)]
        det = Phi[0][0] * Phi[1][1] - Phi[0][1] * Phi[1][0]
        Delta = [det, -(Phi[0][0] + Phi[1][1]), iv.mpf(1)]
        r0, r1 = box(R[0], R[0]), box(R[1], R[1])
        Nq = [r1 * Phi[0][0] - r0 * Phi[0][1] - r1 * det, r0 * Phi[0][1] - r1 + r1 * Phi[1][1]]
        return mul(fr(LD), Delta), mul(fr(A), add(mul(fr(Ndp), Delta), mul(fr(Dk), Nq)))
    p, r, Ndp = Nd
    lo, hi = exp_interval(p * T, bits)
    E = box(lo, hi)
    zE = [-E, iv.mpf(1)]
    return mul(fr(LD), zE), mul(fr(A), add(mul(fr(Ndp), zE), [x * (box(r, r) * (E - 1)) for x in fr(Dk)]))


def check_stability_winding(model, claim, T, n, params, k, Nd):
    """evidence.argument_principle: c = z^n P1 + P0 (winding_parts: every device pole at s = 0, a
    mass-damper or a spring) with z^n never expanded (winding_count); stable iff every one of its
    n + deg P1 roots is inside. c(+-1) != 0 exactly with every pole at s = 0 (= 0: a root on the circle),
    in intervals otherwise (128 to 4096 bits)."""
    from mpmath import iv
    if claim["status"] != "certified":
        raise Malformed("claim.status: decided by the argument principle, the verdict is \"certified\"")
    H = loop_wall(model, T, params, n)
    degree = n + len(H.den) - 1 + k + (0 if not isinstance(Nd, tuple) else 2 if Nd[0] == "spring" else 1)
    if degree > MAX_WINDING_DEGREE:
        raise TooLarge("the characteristic polynomial has degree %d, above this checker's limit %d for the argument principle" % (
            degree, MAX_WINDING_DEGREE))
    if isinstance(Nd, tuple) and dc_zero(k, Nd, H.num, H.den):
        why = "c(1) = 0 exactly (1 - e^(pT) or det(I - Phi) times a rational factor that is 0): a root on the unit circle"
        if claim["stable"]:
            return False, "claim: stable, but " + why
        return True, "NOT stable (degree %d, delay %d never expanded; %s)" % (degree, n, why)
    old = iv.prec
    try:
        for bits in (128, 256, 512, 1024, 2048, 4096):
            LD, AN = winding_parts(n, k, Nd, H.num, H.den, T, bits)
            if len(LD) - 1 + n != degree or len(AN) - 1 >= degree:
                raise AssertionError("the parts of c do not have the degrees of c")
            if not isinstance(Nd, tuple):
                break
            ends = [(1 if e == 1 else (-1) ** n) * sum(x * e ** i for i, x in enumerate(LD)) + sum(x * e ** i for i, x in enumerate(AN))
                    for e in (1, -1)]
            if all(not (v.a <= 0 <= v.b) for v in ends):
                break
        else:
            raise TooLarge("the loop is too close to its boundary: c(1) or c(-1) not separated from 0 at 4096 bits")
    finally:
        iv.prec = old
    c1 = cm1 = 1
    if not isinstance(Nd, tuple):
        c1 = peval(LD, Fraction(1)) + peval(AN, Fraction(1))
        cm1 = (-1) ** n * peval(LD, Fraction(-1)) + peval(AN, Fraction(-1))
    if c1 == 0 or cm1 == 0:
        ok, why = False, "c(%d) = 0: a root on the unit circle" % (1 if c1 == 0 else -1)
    else:
        r = winding_count(n, LD, AN)
        if r is None:
            raise TooLarge("the loop is too close to its boundary: an arc of width 2^-100 not separated from 0")
        inside, arcs = r
        ok = inside == degree
        why = "argument principle on the upper half circle (%d arcs): %d of the %d roots inside" % (arcs, inside, degree)
    if ok != claim["stable"]:
        return False, "claim: %s, but %s" % ("stable" if claim["stable"] else "NOT stable", why)
    return True, "%s (degree %d, delay %d never expanded; %s)" % ("stable" if ok else "NOT stable", degree, n, why)


SCENE_LOOP = ("scene", "parameters", "device", "operator", "environment", "delay")
SCENE_IGNORED = ("input", "initial", "simulate", "reproduce", "multidof")  # not in the loop's stability


def scene_beyond(where, what):
    raise Malformed("model.scene: %s: %s (beyond this checker; docs/certificates.md lists what it reads of a scene)" % (
        where, what))


def scene_text(v, where):
    """An exact number as TOML writes it: a string (a number or an expression) or an integer."""
    if isinstance(v, bool) or not isinstance(v, (str, int)):
        raise Malformed("model.scene: %s: expected a string or an integer" % where)
    return v if isinstance(v, str) else str(v)


def scene_constant(text, T, where):
    """The value of a constant expression (T known when T is not None)."""
    if T is None and any(k == 'name' and t == 'T' for k, t in lex(text)):
        raise Malformed("model.scene: %s: names T" % where)
    try:
        h = parse_h(text, T, {}, 's', 'model.scene: ' + where)
    except ZeroDivisionError:
        raise Malformed("model.scene: %s: division by zero" % where)
    if len(h.num) > 1 or len(h.den) > 1:
        raise Malformed("model.scene: %s: not a number" % where)
    return h.num[0] / h.den[0] if h.num else Fraction(0)


def scene_lists(text, lists, where, memo=None, chain=frozenset()):
    """NAME[k] -> "(v_k)" and sum(NAME) -> "((v_1) + ... + (v_n))" for the list parameters (docs/scene.md,
    "Repeated blocks"; check/scene_model.cpp's Parameters::expand), each value expanded once (memo); a list
    named otherwise, or naming itself, is malformed; more than 1 MB is beyond."""
    if not lists:
        return text
    memo = {} if memo is None else memo

    def value(name, k):  # k = 0: the sum
        if (name, k) not in memo:
            if name in chain:
                raise Malformed("model.scene: parameters.%s: depends on itself (a cycle)" % name)
            vs = lists[name] if k == 0 else [lists[name][k - 1]]
            e = " + ".join("(" + scene_lists(v, lists, "parameters." + name, memo, chain | {name}) + ")" for v in vs)
            if len(e) > 1 << 20:
                scene_beyond("parameters." + name, "its values expand to more than 1 MB")
            memo[(name, k)] = e
        return "(" + memo[(name, k)] + ")"

    def total(m):
        return value(m.group(1), 0) if m.group(1) in lists else m.group(0)

    def indexed(m):
        name, index = m.group(1), m.group(2)
        if name not in lists:
            return m.group(0)
        if not (index.isdigit() and len(index) <= 6 and 1 <= int(index) <= len(lists[name])):
            raise Malformed("model.scene: %s: '%s[%s]': the list parameter %s has %d values, %s[1] .. %s[%d] (or sum(%s))" % (
                where, name, index, name, len(lists[name]), name, name, len(lists[name]), name))
        return value(name, int(index))
    text = re.sub(r"(?<![\w.])sum\(\s*([A-Za-z_]\w*)\s*\)", total, text)
    text = re.sub(r"(?<![\w.])([A-Za-z_]\w*)\[([^\]]*)\]", indexed, text)
    if len(text) > 1 << 20:
        scene_beyond(where, "its parameters expand to more than 1 MB")
    for name in re.findall(r"(?<![\w.])[A-Za-z_]\w*", text):
        if name in lists:
            raise Malformed("model.scene: %s: '%s' is a list parameter: write %s[k] or sum(%s)" % (where, name, name, name))
    return text


def scene_copies(root, max_dofs=64):
    """[[device]] and [[operator]] tables with count = n written out as hapstab's reader does (n copies in
    place, named NAME[k] or the name's own [i] pattern, "[i]" -> "[k]" in every string); at most max_dofs."""
    def indexed(v, k):
        if isinstance(v, str):
            return v.replace("[i]", "[%d]" % k)
        if isinstance(v, list):
            return [indexed(x, k) for x in v]
        if isinstance(v, dict):
            return {a: indexed(b, k) for a, b in v.items()}
        return v
    for key in ("device", "operator"):
        tables = root.get(key)
        if not isinstance(tables, list):
            continue
        out = []
        for i, t in enumerate(tables):
            if not isinstance(t, dict) or "count" not in t:
                out.append(t)
                continue
            where = "%s[%d]" % (key, i + 1)
            n = t["count"]
            if not isinstance(n, int) or isinstance(n, bool) or n < 1:
                raise Malformed("model.scene: %s.count: a whole number of copies >= 1" % where)
            if n > max_dofs:
                scene_beyond(where + ".count", "%d copies, more than %d" % (n, max_dofs))
            if not isinstance(t.get("name"), str):
                raise Malformed("model.scene: %s.name: a table with count needs a name: its copies are NAME[1] .. NAME[count]" % where)
            pattern = t["name"] if "[i]" in t["name"] else t["name"] + "[i]"
            for k in range(1, n + 1):
                copy = {a: indexed(b, k) for a, b in t.items() if a not in ("count", "name")}
                copy["name"] = pattern.replace("[i]", "[%d]" % k)
                out.append(copy)
        root[key] = out


def scene_list_values(v, where):
    """A list parameter's values: [v1, ..., vn] or {repeat = [v1, ..., vp], times = n}; 1 .. 4096 of them."""
    times = 1
    if isinstance(v, dict):
        scene_keys(v, ("repeat", "times"), where)
        times = v.get("times")
        v = v.get("repeat")
        if not isinstance(times, int) or isinstance(times, bool) or not 1 <= times <= 4096:
            raise Malformed("model.scene: %s: a repeated list needs repeat = [values] and times = n (1 .. 4096)" % where)
    if not isinstance(v, list) or not v or len(v) * times > 4096:
        raise Malformed("model.scene: %s: a list of 1 .. 4096 values" % where)
    return [scene_text(x, "%s[%d]" % (where, i + 1)) for i, x in enumerate(v)] * times


def scene_expand(text, defs, free, where, memo, chain, lists=None):
    """text with every parameter (but free) replaced by "(its definition)", recursively; the tokens
    are lex's (numbers with an exponent, names, single characters); list parameters first (scene_lists)."""
    text = scene_lists(text, lists, where, memo)
    out, size = [], 0
    for kind, tok in lex(text)[:-1]:
        if kind == 'name' and tok in defs and tok != free:
            if tok not in memo:
                if tok in chain:
                    raise Malformed("model.scene: parameters.%s: depends on itself (a cycle)" % tok)
                if len(chain) >= 200:
                    scene_beyond("parameters." + tok, "defined through more than 200 others in a chain")
                e = scene_expand(defs[tok], defs, free, "parameters." + tok, memo, chain | {tok}, lists)
                if any(k == 'name' and t in ('s', 'z') for k, t in lex(e)):
                    raise Malformed("model.scene: parameters.%s: names s or z (a parameter is a number)" % tok)
                memo[tok] = e
            out.append("(" + memo[tok] + ")")
        else:
            out.append(tok)
        size += len(out[-1]) + 1
        if size > 1 << 20:
            scene_beyond(where, "its parameters expand to more than 1 MB")
    return " ".join(out)


def scene_one(root, key, required):
    if key not in root:
        if required:
            raise Malformed("model.scene: [[%s]]: missing" % key)
        return None
    tables = root[key]
    if not isinstance(tables, list):
        raise Malformed("model.scene: %s: expected an array of tables [[%s]]" % (key, key))
    if len(tables) != 1:
        scene_beyond("[[%s]]" % key, "%d tables (one DOF: one device, one operator)" % len(tables))
    if not isinstance(tables[0], dict):
        raise Malformed("model.scene: [[%s]]: not a table" % key)
    return tables[0]


def scene_keys(t, known, where):
    for k in t:
        if k not in known:
            scene_beyond("%s.%s" % (where, k), "a key this checker does not model")


def scene_siso(v, where):
    """One transfer function: a string or a 1 x 1 matrix of strings."""
    if isinstance(v, list) and len(v) == 1 and isinstance(v[0], list) and len(v[0]) == 1:
        v = v[0][0]
    if not isinstance(v, str):
        scene_beyond(where, "not one transfer function (a matrix: more than one DOF)")
    return v


def scene_read(model, free, coupling=False, max_dofs=64):
    """(root, T, expand, field) of model.scene: the TOML (only the loop's sections and the ignored ones),
    T, and the parameters substituted (model.set replacing definitions; model.name, with free, stays a
    name): expand(text, where) substitutes them in text, field(table, key, where, default) in a key's
    value. Every parameter is expanded once: a cycle is malformed, used or not."""
    import tomllib
    if not isinstance(model.get("scene"), str):
        raise Malformed("model.scene: missing or not a string (the scene's TOML text)")
    if len(model["scene"]) > 1 << 20:
        scene_beyond("the scene", "more than 1 MB")
    try:
        root = tomllib.loads(model["scene"])
    except (tomllib.TOMLDecodeError, RecursionError) as e:
        raise Malformed("model.scene: not TOML: %s" % e)
    for key in root:
        if key not in SCENE_LOOP and key not in SCENE_IGNORED and not (coupling and key == "coupling"):
            scene_beyond("[%s]" % key, "a section this checker does not model")
    if isinstance(root.get("multidof"), dict) and "perturb_C" in root["multidof"]:  # it changes E (multidof commands only)
        scene_beyond("multidof.perturb_C", "Sec. VI's perturbed environment, which stability does not model")
    head = root.get("scene")
    if not isinstance(head, dict) or "T" not in head:
        raise Malformed("model.scene: [scene].T: missing (the sample period)")
    scene_keys(head, ("name", "description", "T"), "scene")
    T = scene_constant(scene_text(head["T"], "scene.T"), None, "scene.T")
    if T <= 0:
        raise Malformed("model.scene: scene.T: must be > 0")
    scene_copies(root, max_dofs)
    defs, lists = {}, {}
    params = root.get("parameters", {})
    if not isinstance(params, dict):
        raise Malformed("model.scene: [parameters]: not a table")
    for name, v in params.items():
        if name in ("T", "s", "z"):
            scene_beyond("parameters." + name, "a parameter named T, s or z")
        if isinstance(v, (list, dict)):
            lists[name] = scene_list_values(v, "parameters." + name)
            continue
        defs[name] = scene_text(v, "parameters." + name)
    K = model.get("name") if free and isinstance(model.get("name"), str) else None
    for name, v in parameters(model).items():
        if name in lists:
            raise Malformed("model.set.%s: a list parameter (its values are the scene's)" % name)
        if name not in defs:
            raise Malformed("model.set.%s: not a parameter of the scene" % name)
        if name == K:
            raise Malformed("model.set: gives the parameter model.name = %s a value" % K)
        defs[name] = str(v)
    memo = {}

    def expand(text, where):
        return scene_expand(text, defs, K, where, memo, frozenset(), lists)

    def field(t, key, where, default):
        return expand(scene_text(t[key], where + "." + key), where + "." + key) if key in t else default

    for name in defs:
        if name != K:
            expand(name, "parameters." + name)
    return root, T, expand, field


def scene_wall_entry(env, text, expand):
    """One entry of [environment] as an expression in z: its parameters substituted, s replaced by
    backward Euler's or Tustin's z-expression where domain = "s"."""
    for key in ("domain", "method"):
        if key in env and not isinstance(env[key], str):
            raise Malformed("model.scene: environment.%s: not a string" % key)
    E = expand(text, "environment.tf")
    domain = env.get("domain", "z")
    if domain == "s":
        sub = {"backward_euler": "(z-1)/(T*z)", "tustin": "2*(z-1)/(T*(z+1))"}.get(env.get("method"))
        if sub is None:
            raise Malformed("model.scene: environment.method: an s-domain environment needs \"backward_euler\" or \"tustin\"")
        return " ".join("(" + sub + ")" if k == 'name' and t == 's' else t for k, t in lex(E)[:-1])
    if domain != "z":
        raise Malformed("model.scene: environment.domain: \"z\" or \"s\"")
    if "method" in env:
        raise Malformed("model.scene: environment.method: only with domain = \"s\"")
    return E


def scene_delay(root, T, field, limit=100000, whole=True):
    """[delay] in samples, in [0, limit] (a whole number when `whole`); 0 without the section."""
    if "delay" not in root:
        return 0
    delay = root["delay"]
    if not isinstance(delay, dict):
        raise Malformed("model.scene: [delay]: not a table")
    scene_keys(delay, ("time", "samples"), "delay")
    if len(delay) != 1:
        raise Malformed("model.scene: [delay]: give exactly one of time, samples")
    key = next(iter(delay))
    d = scene_constant(field(delay, key, "delay", "0"), T, "delay." + key)
    d = d / T if key == "time" else d
    if d < 0:
        raise Malformed("model.scene: delay.%s: must be >= 0" % key)
    if whole and d.denominator != 1:
        scene_beyond("delay." + key, "a delay of %s samples, not a whole number" % d)
    if d > limit:
        scene_beyond("delay." + key, "more than %d samples" % limit)
    return int(d) if whole else d


def scene_loop_model(model, free=False):
    """model itself without model.scene; else {plant, H[, operator], set: {}, T, delay[, name]}: the
    one-DOF loop of the scene (the stability kind's docstring above), read here from its TOML."""
    if not isinstance(model, dict) or "scene" not in model:
        return model
    only(model, ("scene", "set", "name") if free else ("scene", "set"), "model")
    root, T, expand, field = scene_read(model, free)
    out = {"T": str(T), "set": {}}
    if free and "name" in model:
        out["name"] = model["name"]
    dev = scene_one(root, "device", True)
    scene_keys(dev, ("name", "m", "b", "tf", "passive"), "device")
    if "tf" in dev:
        if "m" in dev or "b" in dev:
            raise Malformed("model.scene: device: give either m, b or tf, not both")
        out["plant"] = ScenePlant("(" + expand(scene_siso(dev["tf"], "device.tf"), "device.tf") + ")/s")
    else:
        if "m" not in dev:
            raise Malformed("model.scene: device.m: missing (the device mass)")
        m, b = field(dev, "m", "device", "0"), field(dev, "b", "device", "0")
        if scene_constant(m, T, "device.m") <= 0:
            raise Malformed("model.scene: device.m: must be > 0")
        if scene_constant(b, T, "device.b") < 0:
            raise Malformed("model.scene: device.b: must be >= 0")
        out["plant"] = "1/((%s)*s^2 + (%s)*s)" % (m, b)
    op = scene_one(root, "operator", False)
    if op is not None:
        scene_keys(op, ("name", "dofs", "m", "b", "k", "tf", "mass", "passive"), "operator")
        if "dofs" in op:
            d = op["dofs"]
            d = d[0] if isinstance(d, list) and len(d) == 1 else d
            if not ((isinstance(d, int) and not isinstance(d, bool) and d == 0) or
                    (isinstance(d, str) and isinstance(dev.get("name"), str) and d == dev["name"])):
                raise Malformed("model.scene: operator.dofs: not the scene's one DOF")
        if "tf" in op:
            if any(k in op for k in ("m", "b", "k")):
                raise Malformed("model.scene: operator: give either m, b, k or tf, not both")
            Z = "(" + expand(scene_siso(op["tf"], "operator.tf"), "operator.tf") + ")"
            if "mass" in op:
                if not isinstance(op["mass"], list) or len(op["mass"]) != 1:
                    raise Malformed("model.scene: operator.mass: expected a list of one mass")
                Z += " + (" + expand(scene_text(op["mass"][0], "operator.mass[1]"), "operator.mass[1]") + ")*s"
            out["operator"] = Z
        else:
            if "mass" in op:
                raise Malformed("model.scene: operator.mass: only with tf")
            out["operator"] = "(%s)*s + (%s) + (%s)/s" % (field(op, "m", "operator", "0"), field(op, "b", "operator", "0"),
                                                        field(op, "k", "operator", "0"))
    env = root.get("environment")
    if not isinstance(env, dict):
        raise Malformed("model.scene: [environment]: missing (the loop has no controller)")
    scene_keys(env, ("tf", "domain", "method", "gain"), "environment")
    if "tf" not in env:
        raise Malformed("model.scene: environment.tf: missing")
    E = scene_wall_entry(env, scene_siso(env["tf"], "environment.tf"), expand)
    out["H"] = "(%s)*(%s)" % (field(env, "gain", "environment", "1"), E)
    out["delay"] = scene_delay(root, T, field)
    return out


MAX_LOOP_ORDER = 100  # stability-loop: M's order (Bareiss on Q_mid - r I: ~20 s at order 98)


def scene_dof(v, names, where):
    if isinstance(v, int) and not isinstance(v, bool) and 0 <= v < len(names):
        return v
    if isinstance(v, str) and v in names:
        return names.index(v)
    raise Malformed("model.scene: %s: not a DOF number or the name of a device" % where)


def scene_text_matrix(v, n, where):
    """An n x n matrix of expressions (a string when n = 1)."""
    if isinstance(v, str):
        if n != 1:
            scene_beyond(where, "one transfer function for %d DOF (write the matrix)" % n)
        return [[v]]
    if not isinstance(v, list) or len(v) != n or any(not isinstance(r, list) or len(r) != n for r in v):
        raise Malformed("model.scene: %s: expected a %d x %d matrix of strings" % (where, n, n))
    if any(not isinstance(e, str) for r in v for e in r):
        raise Malformed("model.scene: %s: an entry that is not a string" % where)
    return v


def scene_rf(text, T, var, where):
    try:
        return parse_h(text, T, {}, var, "model.scene: " + where)
    except ZeroDivisionError:
        raise Malformed("model.scene: %s: division by zero" % where)


def plant_loop_read(model):
    """stability-loop's reading of a one-DOF `stability --plant P --H H [--operator Z]` model as written
    ({plant, H, operator, set, T, delay}): one device block G = s P_eff, P_eff = P/(1 + s Z P), of
    relative degree >= 2; the wall H(z); n whole samples. Without a pole of P_eff at s = 0 the
    integrated position carries one conserved quantity of this checker's own (own_conserved)."""
    only(model, ("plant", "H", "operator", "set", "T", "delay"), "model")
    T, n, params, P = effective_device(model)
    s = RF([Fraction(0), Fraction(1)])
    try:
        H = parse_h(model["H"], T, params, 'z', 'model.H')
    except ZeroDivisionError:
        raise Malformed("model.H: division by zero")
    G = s * P
    if len(G.num) >= len(G.den):
        raise Malformed("model.plant: a device of relative degree below 2 (beyond this checker)")
    if len(H.num) > len(H.den):
        raise Malformed("model.H: an improper H(z) (beyond this checker)")
    devices = [{"first": 0, "dofs": 1, "block": ("tf", 1, [[G]])}]
    zero = [Fraction(0)]
    return T, Fraction(n), devices, zero, list(zero), list(zero), [], ("tf", [[H]]), None


def own_conserved(model):
    """Conserved quantities this checker's realisation adds, not the model: a --plant P_eff without a
    pole at s = 0, realised as G = s P_eff with its position integrated (G(0) = 0, so x - K xi is
    constant, K A_G = C_G, K B_G = 0); the quotient by it sets x = K xi, P_eff's output: the loop as
    written. 0 for a scene."""
    if "scene" in model or "plant" not in model:
        return 0
    return 1 if effective_device(model)[3].den[0] != 0 else 0


def scene_loop_read(model, max_dofs=64):
    """stability-loop's reading of model.scene: (T, delay, mass, damping, stiffness, operators, E) with
    per DOF the device's m, b plus its m, b, k operators; the tf and ss operators [(ports, Z)], Z
    ("tf", proper RFs in s) or ("ss", (A, B, C, D) as written); E N x N in z (discretised, times gain).
    A model without a scene is the one-DOF --plant/--H loop (plant_loop_read)."""
    if "scene" not in model and "plant" in model:
        return plant_loop_read(model)
    only(model, ("scene", "set"), "model")
    root, T, expand, field = scene_read(model, False, coupling=True, max_dofs=max_dofs)
    devs = root.get("device")
    if not isinstance(devs, list) or not devs or any(not isinstance(d, dict) for d in devs):
        raise Malformed("model.scene: [[device]]: missing or not tables")
    names, mass, damp, stiff, devices = [], [], [], [], []
    for i, d in enumerate(devs):
        key = "device[%d]" % (i + 1)
        scene_keys(d, ("name", "m", "b", "tf", "ss", "passive"), key)
        dev = {"first": len(mass), "dofs": 1, "block": None, "name": d.get("name")}
        if "tf" in d or "ss" in d:
            if "m" in d or "b" in d:
                raise Malformed("model.scene: %s: give either m, b or tf/ss, not both" % key)
            dev["block"] = scene_device_block(d, key, T, expand)
            dev["dofs"] = dev["block"][1]
            mass += [Fraction(0)] * dev["dofs"]
            damp += [Fraction(0)] * dev["dofs"]
        else:
            if "m" not in d:
                raise Malformed("model.scene: %s.m: missing (the device mass)" % key)
            mass.append(scene_constant(field(d, "m", key, "0"), T, key + ".m"))
            damp.append(scene_constant(field(d, "b", key, "0"), T, key + ".b"))
            if mass[-1] <= 0 or damp[-1] < 0:
                raise Malformed("model.scene: %s: m must be > 0 and b >= 0" % key)
        stiff += [Fraction(0)] * dev["dofs"]
        name = d.get("name") if isinstance(d.get("name"), str) else ""
        names += [name if dev["dofs"] == 1 else ""] * dev["dofs"]  # a block of several DOFs: by number
        devices.append(dev)
    if len(names) > max_dofs:
        scene_beyond("[[device]]", "%d DOFs, more than %d" % (len(names), max_dofs))
    ops = []
    tables = root.get("operator", [])
    if not isinstance(tables, list) or any(not isinstance(o, dict) for o in tables):
        raise Malformed("model.scene: [[operator]]: not tables")
    for i, o in enumerate(tables):
        key = "operator[%d]" % (i + 1)
        scene_keys(o, ("name", "dofs", "m", "b", "k", "tf", "ss", "mass", "passive"), key)
        dofs = o.get("dofs")
        ports = [] if dofs is None else [scene_dof(x, names, key + ".dofs") for x in (dofs if isinstance(dofs, list) else [dofs])]
        if "tf" not in o and "ss" not in o:
            if "mass" in o:
                raise Malformed("model.scene: %s.mass: only with tf or ss" % key)
            ports = ports or [0]
            if len(ports) != 1:
                raise Malformed("model.scene: %s.dofs: m, b, k act on one DOF" % key)
            j = ports[0]
            mass[j] += scene_constant(field(o, "m", key, "0"), T, key + ".m")
            damp[j] += scene_constant(field(o, "b", key, "0"), T, key + ".b")
            stiff[j] += scene_constant(field(o, "k", key, "0"), T, key + ".k")
            continue
        if any(k in o for k in ("m", "b", "k")):
            raise Malformed("model.scene: %s: give either m, b, k or tf/ss, not both" % key)
        if "tf" in o and "ss" in o:
            raise Malformed("model.scene: %s: give exactly one of tf, ss" % key)
        if "ss" in o:  # the impedance's realisation as written: ("ss", (A, B, C, D)), q from D
            ss = scene_ss_table(o["ss"], key)
            q = len(ss["D"]) if isinstance(ss.get("D"), list) else len(ports)
            ports = ports or list(range(min(q, len(names))))
            if q == 0 or len(ports) != q:
                raise Malformed("model.scene: %s.ss: D is not a square matrix over the operator's DOFs" % key)
            n = scene_ss_order(ss)
            Z = ("ss", tuple(scene_ss_matrix(ss, k, r, cl, key, T, expand) for k, r, cl in
                             (("A", n, n), ("B", n, q), ("C", q, n), ("D", q, q))))
        else:
            q = 1 if isinstance(o["tf"], str) else len(o["tf"]) if isinstance(o["tf"], list) else 0
            ports = ports or list(range(min(q, len(names))))
            if q == 0 or len(ports) != q:
                raise Malformed("model.scene: %s.tf: not a square matrix over the operator's DOFs" % key)
            Z = []
            for row in scene_text_matrix(o["tf"], q, key + ".tf"):
                Z.append([])
                for e in row:
                    f = scene_rf(expand(e, key + ".tf"), T, 's', key + ".tf")
                    if len(f.num) > len(f.den):
                        raise Malformed("model.scene: %s.tf: an improper entry (write a mass by m or mass)" % key)
                    Z[-1].append(f)
            Z = ("tf", Z)
        if "mass" in o:
            if not isinstance(o["mass"], list) or len(o["mass"]) != q:
                raise Malformed("model.scene: %s.mass: expected a mass per DOF of the operator" % key)
            for a, x in enumerate(o["mass"]):
                mass[ports[a]] += scene_constant(expand(scene_text(x, key + ".mass"), key + ".mass"), T, key + ".mass")
        ops.append((ports, Z))
    env = root.get("environment")
    if not isinstance(env, dict):
        raise Malformed("model.scene: [environment]: missing (the loop has no controller)")
    E = scene_discrete(env, "environment", len(names), T, expand, field)
    V = None
    if "coupling" in root:
        if not isinstance(root["coupling"], dict):
            raise Malformed("model.scene: [coupling]: not a table")
        V = scene_discrete(root["coupling"], "coupling", len(names), T, expand, field)
    return T, scene_delay(root, T, field, limit=1000, whole=False), devices, mass, damp, stiff, ops, E, V


def scene_device_block(d, key, T, expand):
    """A device given by ss = { A, B, C, D } (D = 0) or tf (a string or a square matrix), in s,
    strictly proper: ("ss", dofs, (A, B, C)) or ("tf", dofs, G)."""
    if "tf" in d and "ss" in d:
        raise Malformed("model.scene: %s: give exactly one of tf, ss" % key)
    if "tf" in d:
        tf = d["tf"]
        q = 1 if isinstance(tf, str) else len(tf) if isinstance(tf, list) else 0
        if q == 0:
            raise Malformed("model.scene: %s.tf: expected a string or a square matrix of strings" % key)
        G = []
        for row in scene_text_matrix(tf, q, key + ".tf"):
            G.append([])
            for e in row:
                f = scene_rf(expand(e, key + ".tf"), T, 's', key + ".tf")
                if f.num and len(f.num) >= len(f.den):
                    raise Malformed("model.scene: %s.tf: not strictly proper (a device has no feedthrough)" % key)
                G[-1].append(f)
        return "tf", q, G
    ss = d["ss"]
    if not isinstance(ss, dict) or any(k not in ("A", "B", "C", "D") for k in ss):
        raise Malformed("model.scene: %s.ss: expected a table { A = ..., B = ..., C = ..., D = ... }" % key)
    n = len(ss["A"]) if isinstance(ss.get("A"), list) else 0
    q = len(ss["D"]) if isinstance(ss.get("D"), list) else 0
    if n == 0 or q == 0:
        raise Malformed("model.scene: %s.ss: a device needs states and at least one DOF" % key)
    A = scene_ss_matrix(ss, "A", n, n, key, T, expand)
    B = scene_ss_matrix(ss, "B", n, q, key, T, expand)
    C = scene_ss_matrix(ss, "C", q, n, key, T, expand)
    if any(x != 0 for r in scene_ss_matrix(ss, "D", q, q, key, T, expand) for x in r):
        raise Malformed("model.scene: %s.ss.D: not 0 (a device has no feedthrough)" % key)
    return "ss", q, (A, B, C)


def scene_ss_matrix(ss, key, rows, cols, where, T, expand):
    at = "%s.ss.%s" % (where, key)
    a = ss.get(key)
    if not isinstance(a, list):
        raise Malformed("model.scene: %s: missing or not a matrix" % at)
    if rows == 0 or cols == 0:
        if not (a == [] or a == [[]] or (cols == 0 and len(a) == rows and all(r == [] for r in a))):
            raise Malformed("model.scene: %s: not of size %d x %d" % (at, rows, cols))
        return [[Fraction(0)] * cols for _ in range(rows)]
    if len(a) != rows or any(not isinstance(r, list) or len(r) != cols for r in a):
        raise Malformed("model.scene: %s: not of size %d x %d" % (at, rows, cols))
    return [[scene_constant(expand(scene_text(x, at), at), T, at) for x in r] for r in a]


def scene_ss_table(ss, where):
    """ss = { A, B, C, D }: a table of those keys only."""
    if not isinstance(ss, dict) or any(k not in ("A", "B", "C", "D") for k in ss):
        raise Malformed("model.scene: %s.ss: expected a table { A = ..., B = ..., C = ..., D = ... }" % where)
    return ss


def scene_ss_order(ss):
    """The order n of ss.A (0 when written [] or [[]])."""
    A = ss.get("A")
    return len(A) if isinstance(A, list) and A != [[]] else 0


def scene_discrete(t, where, N, T, expand, field):
    """[environment] or [coupling]: ("tf", N x N RFs in z, times gain) or ("ss", (A, B, C, D) with C, D times gain);
    the tf matrix written as diagonal / off_diagonal [/ blocks] too (scene_diagonal)."""
    scene_keys(t, ("tf", "ss", "diagonal", "off_diagonal", "blocks", "domain", "method", "gain"), where)
    if "diagonal" in t and ("tf" in t or "ss" in t):
        raise Malformed("model.scene: %s: give one of tf, ss, diagonal" % where)
    if "diagonal" not in t and ("off_diagonal" in t or "blocks" in t):
        raise Malformed("model.scene: %s: off_diagonal and blocks need diagonal" % where)
    if "diagonal" not in t and ("tf" in t) == ("ss" in t):
        raise Malformed("model.scene: %s: give exactly one of tf, ss" % where)
    gain_text = field(t, "gain", where, "1")
    if "ss" in t:
        if "domain" in t or "method" in t:
            scene_beyond(where + ".domain", "an ss block in s")
        ss = scene_ss_table(t["ss"], where)
        n = scene_ss_order(ss)
        g = scene_constant(gain_text, T, where + ".gain")
        Am = scene_ss_matrix(ss, "A", n, n, where, T, expand)
        Bm = scene_ss_matrix(ss, "B", n, N, where, T, expand)
        Cm = [[g * x for x in r] for r in scene_ss_matrix(ss, "C", N, n, where, T, expand)]
        Dm = [[g * x for x in r] for r in scene_ss_matrix(ss, "D", N, N, where, T, expand)]
        return "ss", (Am, Bm, Cm, Dm)
    gain = scene_rf(gain_text, T, 'z', where + ".gain")
    E, read = [], {}  # each distinct text (as expanded) read once: identical DOFs repeat their entries
    for row in scene_diagonal(t, where, N) if "diagonal" in t else scene_text_matrix(t["tf"], N, where + ".tf"):
        E.append([])
        for e in row:
            text = scene_wall_entry(t, e, expand)
            if text not in read:
                f = scene_rf(text, T, 'z', where + ".tf") * gain
                if len(f.num) > len(f.den):
                    raise Malformed("model.scene: %s.tf: an improper entry in z" % where)
                read[text] = f
            E[-1].append(read[text])
    return "tf", E


def scene_diagonal(t, where, N):
    """diagonal / off_diagonal [/ blocks] as the N x N entries' text (docs/scene.md, "Repeated blocks"): (i, i)
    the diagonal with [i] its row's number, (i, j) the off-diagonal with [i] the row's and [j] the column's
    (from 1), 0 between blocks of N/K DOFs."""
    d, off = t["diagonal"], t.get("off_diagonal", "0")
    if not isinstance(d, str) or not isinstance(off, str):
        raise Malformed("model.scene: %s.diagonal, off_diagonal: not strings" % where)
    K = t.get("blocks", 1)
    if not isinstance(K, int) or isinstance(K, bool) or K < 1 or N % K:
        raise Malformed("model.scene: %s.blocks: a whole number K >= 1 that divides the %d DOFs" % (where, N))
    size = N // K
    return [[d.replace("[i]", "[%d]" % (i + 1)) if i == j else
             off.replace("[i]", "[%d]" % (i + 1)).replace("[j]", "[%d]" % (j + 1)) if i // size == j // size else "0"
             for j in range(N)] for i in range(N)]


def column_lcms(G):
    """The monic lcm of each column's denominators."""
    cols = []
    for j in range(len(G[0])):
        d = [Fraction(1)]
        for row in G:
            g = pgcd(d, row[j].den)
            d = pdivmod(pmul(d, row[j].den), g)[0]
            d = [x / d[-1] for x in d]
        cols.append(d)
    return cols


def realise_columns(G, over=None):
    """(A, B, C, D) of the p x q matrix G (proper RFs): column j over the monic lcm d_j of its
    denominators (or over[j], a monic multiple of it) in controllable companion form (x_t' = x_(t+1),
    x_(r-1)' = -sum a_t x_t + u_j), C the strictly proper numerators over d_j, D the direct part."""
    p, q = len(G), len(G[0])
    cols = column_lcms(G) if over is None else over
    n = sum(len(d) - 1 for d in cols)
    A = [[Fraction(0)] * n for _ in range(n)]
    B = [[Fraction(0)] * q for _ in range(n)]
    C = [[Fraction(0)] * n for _ in range(p)]
    D = [[Fraction(0)] * q for _ in range(p)]
    off = 0
    for j, d in enumerate(cols):
        r = len(d) - 1
        for t in range(r - 1):
            A[off + t][off + t + 1] = Fraction(1)
        for t in range(r):
            A[off + r - 1][off + t] = -d[t]
        if r:
            B[off + r - 1][j] = Fraction(1)
        for i in range(p):
            f, rem = pdivmod(d, G[i][j].den)
            if rem:
                raise AssertionError("a denominator does not divide its column's lcm")
            num = pmul(G[i][j].num, f)
            D[i][j] = num[r] if len(num) > r else Fraction(0)
            num = psub(num, [D[i][j] * x for x in d])
            for t in range(r):
                C[i][off + t] = num[t] if t < len(num) else Fraction(0)
        off += r
    return A, B, C, D


def loop_plant(devices, mass, damp, stiff, ops):
    """(A, B, pos) of stability-loop's continuous plant (C++ check/stability_loop_check.cpp): the
    devices' states (a mass-damper: its velocity, 1/(m s + b) with its operators' m and b), then the
    positions x (from index pos), then the tf and ss operators' states; forces f = u - Dv v - K x - Cz zeta."""
    N = len(mass)
    devs = []
    for d in devices:
        if d["block"] is None:
            j = d["first"]
            devs.append(([[-damp[j] / mass[j]]], [[1 / mass[j]]], [[Fraction(1)]]))
        else:
            if any(mass[j] != 0 for j in range(d["first"], d["first"] + d["dofs"])):
                scene_beyond("[[operator]]", "an operator's mass on a device given by tf or ss")
            kind, q, data = d["block"]
            devs.append(data if kind == "ss" else realise_columns(data)[:3])
    nd = sum(len(R[0]) for R in devs)
    reals = [Z[1] if Z[0] == "ss" else realise_columns(Z[1]) for _, Z in ops]
    nz = sum(len(R[0]) for R in reals)
    ns = nd + N + nz
    Ad = [[Fraction(0)] * nd for _ in range(nd)]
    Bd = [[Fraction(0)] * N for _ in range(nd)]
    Cd = [[Fraction(0)] * nd for _ in range(N)]
    off = 0
    for d, (Ar, Br, Cr) in zip(devices, devs):
        n = len(Ar)
        for i in range(n):
            for t in range(n):
                Ad[off + i][off + t] = Ar[i][t]
            for c in range(d["dofs"]):
                Bd[off + i][d["first"] + c] = Br[i][c]
        for r in range(d["dofs"]):
            for t in range(n):
                Cd[d["first"] + r][off + t] = Cr[r][t]
        off += n
    Dv = [[Fraction(0)] * N for _ in range(N)]
    for d in devices:
        if d["block"] is not None:
            for j in range(d["first"], d["first"] + d["dofs"]):
                Dv[j][j] += damp[j]
    Cz = [[Fraction(0)] * nz for _ in range(N)]
    Bz = [[Fraction(0)] * N for _ in range(nz)]
    Az = [[Fraction(0)] * nz for _ in range(nz)]
    off = 0
    for (ports, _), (Ao, Bo, Co, Do) in zip(ops, reals):
        n = len(Ao)
        for a, pa in enumerate(ports):
            for t in range(n):
                Cz[pa][off + t] += Co[a][t]
            for c, pc in enumerate(ports):
                Dv[pa][pc] += Do[a][c]
        for t in range(n):
            for t2 in range(n):
                Az[off + t][off + t2] = Ao[t][t2]
            for c, pc in enumerate(ports):
                Bz[off + t][pc] += Bo[t][c]
        off += n
    BDC = mmul(Bd, mmul(Dv, Cd)) if nd else []
    BCz = mmul(Bd, Cz) if nd and nz else [[Fraction(0)] * nz for _ in range(nd)]
    BzC = mmul(Bz, Cd) if nz else []
    A = [[Fraction(0)] * ns for _ in range(ns)]
    B = [[Fraction(0)] * N for _ in range(ns)]
    for i in range(nd):
        for t in range(nd):
            A[i][t] = Ad[i][t] - BDC[i][t]
        for j in range(N):
            A[i][nd + j] = -Bd[i][j] * stiff[j]
            B[i][j] = Bd[i][j]
        for t in range(nz):
            A[i][nd + N + t] = -BCz[i][t]
    for j in range(N):
        for t in range(nd):
            A[nd + j][t] = Cd[j][t]
    for i in range(nz):
        for t in range(nd):
            A[nd + N + i][t] = BzC[i][t]
        for t in range(nz):
            A[nd + N + i][nd + N + t] = Az[i][t]
    return A, B, nd


def expm_interval_n(A, t, bits):
    """e^(A t) for a square rational A, enclosed entrywise: M = A t/2^s with ||M||_inf <= 1/2, its Taylor
    sum in intervals plus the remainder ||M||^N/N! * 2 on every entry, then s squarings."""
    Iv.bits = bits
    n = len(A)
    norm = max((sum(abs(x) for x in row) for row in A), default=Fraction(0)) * t
    s = 0
    while norm > Fraction(1, 2) * 2 ** s:
        s += 1
    M = [[Iv(x * t / 2 ** s, x * t / 2 ** s) for x in row] for row in A]
    norm = norm / 2 ** s
    S = [[Iv(1 if i == j else 0) for j in range(n)] for i in range(n)]
    term, j, bound = [row[:] for row in S], 0, Fraction(1)
    while True:
        j += 1
        term = [[x * Fraction(1, j) for x in row] for row in iv_matmul(term, M)]
        bound = bound * norm / j
        S = [[S[i][l] + term[i][l] for l in range(n)] for i in range(n)]
        if bound * 2 < Fraction(1, 2 ** (bits + 8)):
            break
    rem = bound * norm / (j + 1) * 2
    P = [[x + Iv(-rem, rem) for x in row] for row in S]
    for _ in range(s):
        P = iv_matmul(P, P)
    return P


def frac_inverse(M):
    """M^-1 by Gauss-Jordan in Fractions; Malformed when singular (det(I + D_E D_V) = 0)."""
    n = len(M)
    M = [list(r) + [Fraction(1 if i == j else 0) for j in range(n)] for i, r in enumerate(M)]
    for c in range(n):
        r = next((i for i in range(c, n) if M[i][c] != 0), None)
        if r is None:
            raise Malformed("model.scene: det(I + D_E D_V) = 0: the coupling's algebraic loop has no solution")
        M[c], M[r] = M[r], M[c]
        p = M[c][c]
        M[c] = [x / p for x in M[c]]
        for i in range(n):
            if i != c and M[i][c] != 0:
                f = M[i][c]
                M[i] = [x - f * y for x, y in zip(M[i], M[c])]
    return [r[n:] for r in M]


def balanced_norm(A):
    """The largest row sum of D^-1 A D, D = diag(2^k_i) by Parlett-Reinsch balancing (radix 2, exactly)."""
    A = [list(r) for r in A]
    n = len(A)
    for _ in range(60):
        changed = False
        for i in range(n):
            c = sum(abs(A[j][i]) for j in range(n) if j != i)
            r = sum(abs(A[i][j]) for j in range(n) if j != i)
            if c == 0 or r == 0:
                continue
            total, f = c + r, Fraction(1)
            while c < r / 2:
                c, f = c * 4, f * 2
            while c >= r * 2:
                c, f = c / 4, f / 2
            if (c + r) / f < Fraction(95, 100) * total:
                changed = True
                for j in range(n):
                    A[i][j] /= f
                    A[j][i] *= f
        if not changed:
            break
    return max((sum(abs(x) for x in row) for row in A), default=Fraction(0))


def loop_matrix(loop, bits, slow=False, exact=False):
    """stability-loop's M (C++ check/stability_loop_check.hpp) in intervals at `bits`: the plant held,
    the controller x_e = x + V u, u = -E x_e solved exactly (u = F [s; xi; eta], x_e = X [s; xi; eta]),
    the delay's buffer. `slow`: the same exactly (Fractions) with each hold e^{Ah} -> I, Gamma_h -> h B,
    what l^T M is for every l whose plant part has l_p^T A = 0 (slow_rows). `exact`: M exactly (Fractions)
    where [[A, B], [0, 0]] is nilpotent (pure masses: exp of it h a finite sum), else None."""
    T, d, devices, mass, damp, stiff, ops, Eb, Vb = loop
    A, Bu, pos = loop_plant(devices, mass, damp, stiff, ops)
    N, ns = len(mass), len(A)
    # the hold's exponent: |A T| beyond 2^12 makes e^{AT} span more than ~6000 binary orders (check/stability_loop_check.cpp),
    # measured on A balanced (companion forms' row sums are far above their rates)
    if not slow and balanced_norm(A) * T > 4096:
        raise TooLarge("model: the hold e^{AT} has |A T| (A balanced, its largest row sum) more than 4096: beyond this checker")
    n, f = int(d), (d - int(d)) * T  # t_d = n T + f
    aug = [A[i] + Bu[i] for i in range(ns)] + [[Fraction(0)] * (ns + N) for _ in range(N)]

    cv = (lambda x: Fraction(x)) if slow or exact else Iv
    if exact:  # aug nilpotent: aug^size = 0
        P = aug
        for _ in range(len(aug) - 1):
            P = mmul(P, aug)
        if any(x != 0 for r in P for x in r):
            return None

    def hold(h):  # (Phi_h, Gamma_h) from exp([A B; 0 0] h); slow: (I, h B); exact: the finite sum of (aug h)^k / k!
        if slow:
            return [[Fraction(1 if i == j else 0) for j in range(ns)] for i in range(ns)], [[h * x for x in r] for r in Bu]
        if exact:
            size = len(aug)
            X = [[Fraction(1 if i == j else 0) for j in range(size)] for i in range(size)]
            term = [r[:] for r in X]
            for k in range(1, size):
                term = [[x * h / k for x in r] for r in mmul(term, aug)]
                X = [[x + y for x, y in zip(rx, ry)] for rx, ry in zip(X, term)]
            return [r[:ns] for r in X[:ns]], [r[ns:] for r in X[:ns]]
        X = expm_interval_n(aug, h, bits)
        return [r[:ns] for r in X[:ns]], [r[ns:] for r in X[:ns]]

    def imul(P, Q):
        return [[sum((P[i][k] * Q[k][j] for k in range(len(Q))), cv(0)) for j in range(len(Q[0]))] for i in range(len(P))]
    # over a period the plant sees u_(k-n-1) on [kT, kT + f) and u_(k-n) after:
    # s+ = Phi_T s + Phi_(T-f) Gamma_f u_(k-n-1) + Gamma_(T-f) u_(k-n)
    if f == 0:
        Phi, G0 = hold(T)
        G1 = None
    else:
        Pa, G0 = hold(T - f)
        Pb, Gb = hold(f)
        Phi, G1 = imul(Pa, Pb), imul(Pa, Gb)
    buffers = n + (1 if f else 0)
    AE, BE, CE, DE = Eb[1] if Eb[0] == "ss" else realise_columns(Eb[1])
    if Vb is None:
        AV, BV, CV, DV = [], [], [[] for _ in range(N)], [[Fraction(0)] * N for _ in range(N)]
    else:
        AV, BV, CV, DV = Vb[1] if Vb[0] == "ss" else realise_columns(Vb[1])
    nE, nV = len(AE), len(AV)
    nc = ns + nE + nV
    order = nc + buffers * N
    if order > MAX_LOOP_ORDER:
        raise TooLarge("the closed loop has %d states, above this checker's limit %d" % (order, MAX_LOOP_ORDER))
    W = frac_inverse([[Fraction(1 if i == j else 0) + sum(DE[i][k] * DV[k][j] for k in range(N)) for j in range(N)] for i in range(N)])
    F = [[Fraction(0)] * nc for _ in range(N)]
    X = [[Fraction(0)] * nc for _ in range(N)]
    for i in range(N):
        for j in range(N):
            for k in range(N):
                F[i][pos + k] -= W[i][j] * DE[j][k]
            for t in range(nE):
                F[i][ns + t] -= W[i][j] * CE[j][t]
            for t in range(nV):
                F[i][ns + nE + t] -= W[i][j] * sum(DE[j][k] * CV[k][t] for k in range(N))
        X[i][pos + i] += 1
        for t in range(nV):
            X[i][ns + nE + t] += CV[i][t]
    X = [[X[i][j] + sum(DV[i][k] * F[k][j] for k in range(N)) for j in range(nc)] for i in range(N)]
    Z = cv(0)
    M = [[Z] * order for _ in range(order)]
    for i in range(ns):
        for j in range(ns):
            M[i][j] = Phi[i][j]

    def drive(G, age):  # u_(k-age) on s: age 0 is u_k = F [s; xi; eta], age a >= 1 the buffer's block a
        for i in range(ns):
            if age == 0:
                for j in range(nc):
                    M[i][j] = M[i][j] + sum((G[i][k] * F[k][j] for k in range(N) if F[k][j]), cv(0))
            else:
                for j in range(N):
                    M[i][nc + (age - 1) * N + j] = G[i][j]
    drive(G0, n)
    if f:
        drive(G1, n + 1)
    if buffers:
        for i in range(N):
            for j in range(nc):
                M[nc + i][j] = cv(F[i][j])
        for b in range(1, buffers):
            for i in range(N):
                M[nc + b * N + i][nc + (b - 1) * N + i] = cv(1)
    for i in range(nE):
        for j in range(nc):
            M[ns + i][j] = cv(sum(BE[i][k] * X[k][j] for k in range(N)) + (AE[i][j - ns] if ns <= j < ns + nE else 0))
    for i in range(nV):
        for j in range(nc):
            M[ns + nE + i][j] = cv(sum(BV[i][k] * F[k][j] for k in range(N)) + (AV[i][j - ns - nE] if j >= ns + nE else 0))
    return M


def echelon(K):
    """K (rows) in reduced row echelon form, exactly, in place: the pivot columns."""
    pivots, row = [], 0
    for c in range(len(K[0]) if K else 0):
        if row == len(K):
            break
        r = next((i for i in range(row, len(K)) if K[i][c] != 0), None)
        if r is None:
            continue
        K[row], K[r] = K[r], K[row]
        p = K[row][c]
        K[row] = [x / p for x in K[row]]
        for i in range(len(K)):
            if i != row and K[i][c] != 0:
                f = K[i][c]
                K[i] = [x - f * y for x, y in zip(K[i], K[row])]
        pivots.append(c)
        row += 1
    return pivots


def conserved_quantities(A, B):
    """A basis of {l : l^T [A B] = 0} (exact), each l_i = 1 at its own index c_i and 0 at the others':
    ([l_1, ..., l_k], [c_1, ..., c_k]) from the reduced echelon form of [A B]^T."""
    ns, N = len(A), (len(B[0]) if B else 0)
    return null_basis([[A[i][j] for i in range(ns)] for j in range(ns)] + [[B[i][j] for i in range(ns)] for j in range(N)], ns)


def null_basis(K, ns):
    """A basis of {v : K v = 0} (K with ns columns, exact; K is reduced in place), each v_i = 1 at its own free
    column c_i and 0 at the others': ([v_1, ..., v_k], [c_1, ..., c_k])."""
    pivots = echelon(K)
    L, at = [], []
    for f in (c for c in range(ns) if c not in pivots):
        l = [Fraction(0)] * ns
        l[f] = Fraction(1)
        for r, pc in enumerate(pivots):
            l[pc] = -K[r][f]
        L.append(l)
        at.append(f)
    return L, at


def right_quotient(M, R):
    """M on the quotient by right eigenvectors r_j (M r_j = r_j; rows of R), in reduced echelon form first (r_j 1
    at its own c_j, 0 at the others'): the induced map on the other coordinates is M[a][b] - sum_j r_j[a] M[c_j][b]."""
    R = [list(r) for r in R]
    n = len(M)
    at = echelon(R)
    if len(at) != len(R):
        raise AssertionError("the right eigenvectors are dependent (a checker defect)")
    kept = [i for i in range(n) if i not in at]
    return [[M[a][b] - sum((Iv(R[j][a]) * M[c][b] for j, c in enumerate(at) if R[j][a]), Iv(0)) for b in kept] for a in kept]


def quotient(M, L, at):
    """M on the quotient by the conserved quantities: x_c = -L[:, kept] x_kept, so M11 = M[kept, kept]
    - M[kept, c] L[:, kept] (L zero beyond the plant's states)."""
    if not at:
        return M
    ns = len(L[0])
    kept = [i for i in range(len(M)) if i not in at]
    return [[M[a][b] - sum((M[a][c] * Iv(L[i][b]) for i, c in enumerate(at) if b < ns and L[i][b]), Iv(0)) for b in kept]
            for a in kept]


def hurwitz(p):
    """(True, why) when every root of p (ascending) has Re s < 0: the Cayley map z = (1 + s)/(1 - s) takes Re s < 0
    onto |z| < 1; p(1) = 0 is a root at s = 1; else q(z) = sum p_k (z - 1)^k (z + 1)^(d - k), of degree d, has the
    images of p's roots: Schur-Cohn on q."""
    p = trim(p)
    if peval(p, Fraction(1)) == 0:
        return False, "a root at s = 1"
    d = len(p) - 1
    q = [Fraction(0)]
    for k, a in enumerate(p):
        term = [Fraction(a)]
        for _ in range(k):
            term = pmul(term, [Fraction(-1), Fraction(1)])
        for _ in range(d - k):
            term = pmul(term, [Fraction(1), Fraction(1)])
        q = padd(q, term)
    return schur_cohn(q)


def hidden_mode_verdict(loop, h, model):
    """evidence.hidden {block, [name,] kind, basis, A_h} of a block written as ss: an environment or coupling (C, D
    times gain, as read; discrete), a device or an operator by name (continuous). Unobservable: C V = 0, A V = V
    A_h (V = basis, n x r); uncontrollable: W B = 0, W A = A_h W (W = basis, r x n); the basis of full rank (its
    Gram matrix > 0). Discrete: charpoly(A_h) = (z - 1)^k q, q(1) != 0, q not Schur stable; continuous:
    charpoly(A_h) = s^k q, q(0) != 0, q not Hurwitz (a root lambda != 0, Re lambda >= 0: e^{lambda T} has |.| >= 1
    and is not 1, as lambda T = 2 pi j m is impossible for an algebraic lambda and a rational T). The span is
    invariant in the loop's M whatever the rest of the loop is (the block's output does not show it, or its input
    does not reach it), so M has an eigenvalue != 1 with |z| >= 1: NOT stable, and not by a conserved quantity.
    Or (since stop 89) q is stable but the marginal eigenvalue is not semisimple in A_h: a Jordan block of M at 1."""
    if not isinstance(h, dict):
        raise Malformed("evidence.hidden: not an object")
    block, kind = h.get("block"), h.get("kind")
    named = block in ("device", "operator")
    only(h, ("block", "name", "kind", "basis", "A_h") if named else ("block", "kind", "basis", "A_h"), "evidence.hidden")
    if block not in ("environment", "coupling", "device", "operator"):
        raise Malformed("evidence.hidden.block: \"environment\", \"coupling\", \"device\" or \"operator\"")
    if kind not in ("unobservable", "uncontrollable"):
        raise Malformed("evidence.hidden.kind: \"unobservable\" or \"uncontrollable\"")
    if named:
        name = h.get("name")
        if not isinstance(name, str):
            raise Malformed("evidence.hidden.name: missing or not a string")
        if block == "device":
            found = [dv["block"][2] for dv in loop[2] if dv.get("block") and dv["block"][0] == "ss" and dv.get("name") == name]
        else:
            root = scene_read(model, False, coupling=True)[0]
            names = [o.get("name") for o in root.get("operator", []) if "tf" in o or "ss" in o]
            found = [Z[1][:3] for (ports, Z), nm in zip(loop[6], names) if Z[0] == "ss" and nm == name]
        if len(found) != 1:
            raise Malformed("evidence.hidden.name: %s %s named %r given by ss in the scene" % ("no" if not found else "more than one", block, name))
        A, B, C = found[0]
    else:
        d = loop[7] if block == "environment" else loop[8]
        if d is None:
            raise Malformed("evidence.hidden.block: the scene has no [coupling]")
        if d[0] != "ss":
            raise Malformed("evidence.hidden.block: the %s is written as tf: a hidden mode is certified of an ss block as written" % block)
        A, B, C, _ = d[1]
    n = len(A)
    Ah = h.get("A_h")
    r = len(Ah) if isinstance(Ah, list) else 0
    if n == 0 or r == 0 or r > MAX_LOOP_ORDER or n > MAX_LOOP_ORDER:
        raise Malformed("evidence.hidden: the block has no state, A_h is empty, or beyond this checker's order %d" % MAX_LOOP_ORDER)
    Ah = frac_matrix(h, "A_h", r, r, "evidence.hidden")
    unobs = kind == "unobservable"
    Vb = frac_matrix(h, "basis", n, r, "evidence.hidden") if unobs else frac_matrix(h, "basis", r, n, "evidence.hidden")
    zero = mmul(C, Vb) if unobs else mmul(Vb, B)
    if any(x != 0 for row in zero for x in row):
        return False, "evidence.hidden: %s" % ("C basis != 0 (the output shows it)" if unobs else "basis B != 0 (the input reaches it)")
    if (mmul(A, Vb) != mmul(Vb, Ah)) if unobs else (mmul(Vb, A) != mmul(Ah, Vb)):
        return False, "evidence.hidden: the basis does not span an invariant subspace with A_h"
    if not semidefinite(mmul(mT(Vb), Vb) if unobs else mmul(Vb, mT(Vb)), True):
        return False, "evidence.hidden.basis: not of full rank %d" % r
    q = faddeev_leverrier(Ah)
    marginal = Fraction(0) if named else Fraction(1)  # the eigenvalue that may settle
    k1 = 0
    while len(trim(q)) > 1 and peval(q, marginal) == 0:
        q = pdivmod(q, [-marginal, Fraction(1)])[0]
        k1 += 1
    ok, why = hurwitz(q) if named else schur_cohn(q)
    if ok:
        # the marginal eigenvalue itself not semisimple in A_h (geometric multiplicity r - rank(A_h - marginal I)
        # below k1): A_h, or e^{A_h T}, is the loop's M on that invariant subspace (or on the quotient by it), so M
        # has a Jordan block at z = 1 and the loop grows polynomially: NOT stable too
        shifted = [[x - (marginal if i == j else 0) for j, x in enumerate(row)] for i, row in enumerate(Ah)]
        geometric = r - len(echelon(shifted))
        if k1 > 0 and geometric < k1:
            return True, ("NOT stable [exact]: the %s hides an %s subspace of dimension %d, invariant in the loop; A_h has %s of "
                          "algebraic multiplicity %d and geometric %d (a Jordan block: M's %s is not semisimple)") % (
                block + (" %r" % h["name"] if named else ""), kind, r, "s = 0" if named else "z = 1", k1, geometric,
                "z = 1 = e^{0 T}" if named else "z = 1")
        return False, "evidence.hidden: every eigenvalue of A_h other than %s is %s, and it is semisimple: nothing shown" % (
            "s = 0" if named else "z = 1", "in Re s < 0" if named else "inside the unit circle")
    return True, "NOT stable [exact]: the %s hides an %s subspace of dimension %d, invariant in the loop; charpoly(A_h) = %s^%d q, q not %s (%s)" % (
        block + (" %r" % h["name"] if named else ""), kind, r, "s" if named else "(z - 1)", k1, "Hurwitz" if named else "Schur stable", why)


def loop_quotient(model):
    """The loop of the model (scene_loop_read) and what stability_loop_check.hpp sets aside: the plant's
    conserved quantities L (at their indices `at`), the wall's and the coupling's uncontrollable z = 1
    (left eigenvectors of M, eigenvalue 1) and their unobservable z = 1 outside those (`right`), the
    checker's own count `own`, and the blocks' realisations [(A, B, C, D) of E, of V]."""
    return loop_quotient_of(scene_loop_read(model), own_conserved(model))


def loop_quotient_of(loop, own=0):
    """loop_quotient of a loop read already (`own`: the checker's own conserved quantities)."""
    A, B, pos = loop_plant(*loop[2:7])
    L, at = conserved_quantities(A, B)
    if len(at) < own:
        raise AssertionError("the integrated position carries no conserved quantity (a checker defect)")
    ns = len(A)
    # the plant's unseen s = 0: A r = 0 with no position in it (the output y = x is blind to r), so M r = r
    Ex = [[Fraction(1 if i == pos + j else 0) for j in range(len(B[0]))] for i in range(ns)]
    right = [(0, r) for r in conserved_quantities(mT(A), Ex)[0]]
    blocks = [loop[7][1] if loop[7][0] == "ss" else realise_columns(loop[7][1])]
    if loop[8] is not None:
        blocks.append(loop[8][1] if loop[8][0] == "ss" else realise_columns(loop[8][1]))
    nc = ns + sum(len(b[0]) for b in blocks)
    L = [l + [Fraction(0)] * (nc - ns) for l in L]
    offset = ns
    for Ab, Bb, Cb, _ in blocks:
        if Ab:
            AmI = [[x - (1 if i == j else 0) for j, x in enumerate(r)] for i, r in enumerate(Ab)]
            Ld, atd = conserved_quantities(AmI, Bb)
            for l, c in zip(Ld, atd):
                L.append([Fraction(0)] * offset + l + [Fraction(0)] * (nc - offset - len(l)))
                at.append(offset + c)
            # and its unobservable z = 1: (A - I) r = 0, C r = 0 (right eigenvectors of M; a fully hidden mode is both,
            # paired with itself below)
            cols = [[Cb[i][j] for i in range(len(Cb))] for j in range(len(Ab))]
            Rd, _ = conserved_quantities(mT(AmI), cols)
            right += [(offset, r) for r in Rd]
        offset += len(Ab)
    if right and at:
        # Left eigenvectors at z = 1 (L) beside right ones: G = L R^T pairs them. If l^T r = 0 for a left l and a right
        # r that nothing else pairs (k - rank G left ones and m - rank G right ones unpaired), the constant l could
        # move the equilibrium that the sum r integrates (a Jordan block at z = 1), which the quotient by both would
        # hide: refused. Otherwise: R^n = span(R_paired) + ker L, M = I on the first, and ker L modulo the unpaired
        # right ones (N^T R, G N = 0: inside ker L) is what the Stein test decides.
        R = [[Fraction(0)] * off + list(r) + [Fraction(0)] * (nc - off - len(r)) for off, r in right]
        G = [[sum((l[t] * r[t] for t in range(nc) if l[t] and r[t]), Fraction(0)) for r in R] for l in L]
        N = null_basis(G, len(R))[0]
        paired = len(R) - len(N)
        if paired < len(L) and N:
            raise Malformed("model: %d conserved quantities (left eigenvectors at z = 1) beside %d unseen z = 1 (right "
                            "eigenvectors), neither paired with the other (l^T r = 0): whether the constant reaches the sum "
                            "(a Jordan block at z = 1) is not decided by this kind" % (len(L) - paired, len(N)))
        right = [(0, [sum((n[j] * R[j][t] for j in range(len(R)) if n[j]), Fraction(0)) for t in range(nc)]) for n in N]
    return loop, L, at, right, own, blocks


def loop_quotient_matrix(loop, L, at, right, bits):
    """M in intervals at `bits`, on the quotient by the conserved quantities (loop_quotient)."""
    M = quotient(loop_matrix(loop, bits), L, at)
    if right:  # on the quotient's coordinates (those not in `at`), then by the right eigenvectors
        full = len(M) + len(at)
        R = []
        for off, r in right:
            v = [Fraction(0)] * full
            v[off:off + len(r)] = r
            R.append([x for i, x in enumerate(v) if i not in at])
        M = right_quotient(M, R)
    return M


def stein_shown(P, M):
    """Q = P - M^T P M > 0 for every M in the intervals (iv_positive_definite)."""
    n = len(P)
    MtPM = iv_matmul(list(zip(*M)), iv_matmul(P, M))
    return iv_positive_definite([[Iv(P[i][j]) - MtPM[i][j] for j in range(n)] for i in range(n)])


def bernstein_stein_shown(Pa, Pb, Ma, Mb):
    """P(t) = (1 - t) Pa + t Pb, M(t) = (1 - t) Ma + t Mb on [0, 1]: S(t) = P(t) - M(t)^T P(t) M(t) is a cubic,
    sum_s C_s B_s(t) in the Bernstein basis (B_s >= 0, summing to 1), C_s = ((3 - s) Pa + s Pb)/3 - (3 choose
    s)^-1 sum_{i + j + k = s} X_i^T P_j X_k (X_0 = Ma, X_1 = Mb, P_0 = Pa, P_1 = Pb): every C_s > 0 (intervals)
    gives S(t) > 0 on [0, 1]. Derived here from the expansion of the product of three affine factors; the
    pairs X_1^T P_j X_0 and X_0^T P_j X_1 are transposes of each other (P_j symmetric)."""
    n = len(Pa)
    R = range(n)

    def px(P, X):  # P X, P exact
        return iv_matmul(P, X)

    def xt(X, Y):  # X^T Y
        return iv_matmul(list(zip(*X)), Y)
    PaMa, PaMb, PbMa, PbMb = px(Pa, Ma), px(Pa, Mb), px(Pb, Ma), px(Pb, Mb)
    Y, Z = xt(Mb, PaMa), xt(Ma, PbMb)  # X1' P0 X0 and X0' P1 X1 (their transposes: X0' P0 X1, X1' P1 X0)
    A, B = xt(Ma, PbMa), xt(Mb, PaMb)  # X0' P1 X0, X1' P0 X1
    sums = (xt(Ma, PaMa),                                          # s = 0: X0' P0 X0
            [[Y[a][b] + Y[b][a] + A[a][b] for b in R] for a in R],  # s = 1
            [[Z[a][b] + Z[b][a] + B[a][b] for b in R] for a in R],  # s = 2
            xt(Mb, PbMb))                                          # s = 3: X1' P1 X1
    for s, T in enumerate(sums):
        w = Fraction(1, 1 if s in (0, 3) else 3)
        C = [[Iv(Fraction(3 - s, 3) * Pa[a][b] + Fraction(s, 3) * Pb[a][b]) - T[a][b] * w for b in R] for a in R]
        if not iv_positive_definite(C):
            return False
    return True


def iv_positive_definite(Q):
    """Every symmetric matrix in the intervals Q is positive definite: D Q_mid D minus the scaled radii's
    largest row sum times I, > 0 by exact elimination (D = diag(2^-k_i), 2^k_i ~ sqrt(Q_mid_ii): a congruence)."""
    n = len(Q)
    mid = [[(x.lo + x.hi) / 2 for x in row] for row in Q]
    d = [Fraction(1, 2 ** k) if k >= 0 else Fraction(2 ** -k)
         for k in (((x.numerator.bit_length() - x.denominator.bit_length()) // 2 if x > 0 else 0)
                   for x in (mid[i][i] for i in range(n)))]
    r = max(sum(d[i] * d[j] * ((Q[i][j].hi - Q[i][j].lo) / 2 + abs(mid[i][j] - (mid[i][j] + mid[j][i]) / 2)) for j in range(n))
            for i in range(n))
    S = [[d[i] * d[j] * (mid[i][j] + mid[j][i]) / 2 - (r if i == j else 0) for j in range(n)] for i in range(n)]
    return semidefinite(S, True)


def symmetric_evidence(obj, where, n):
    """obj.P as a symmetric n x n matrix of Fractions (Malformed otherwise)."""
    Pl = obj.get("P")
    m = len(Pl) if isinstance(Pl, list) else 0
    if m > MAX_LOOP_ORDER:
        raise TooLarge("%s.P of order %d, above this checker's limit %d" % (where, m, MAX_LOOP_ORDER))
    if n is not None and m != n:
        raise Malformed("%s.P: order %d, the loop's %d" % (where, m, n))
    P = frac_matrix(obj, "P", m, m, where)
    if any(P[i][j] != P[j][i] for i in range(m) for j in range(i)):
        raise Malformed("%s.P: not symmetric" % where)
    return P


def check_stability_loop(c):
    """stability-loop: the Stein inertia theorem on the closed loop M built here from the model
    (check/stability_loop_check.hpp): Q = P - M^T P M > 0 for every M in the intervals (stein_shown),
    and P > 0 (stable) or w^T P w < 0 (NOT stable)."""
    model, claim, evidence = parts(c)
    only(claim, ("quantity", "status", "stable", "conserved"), "claim")
    if "hidden" in evidence:  # NOT stable by a hidden mode of an ss environment or coupling, exactly
        only(evidence, ("hidden",), "evidence")
        only(claim, ("quantity", "status", "stable"), "claim")
        if claim.get("status") != "exact":
            raise Malformed("claim.status: a hidden mode's verdict is \"exact\"")
        if claim.get("stable") is not False:
            raise Malformed("claim.stable: a hidden mode shows NOT stable (false) only")
        return hidden_mode_verdict(scene_loop_read(model), evidence["hidden"], model)
    only(evidence, ("P", "w"), "evidence")
    k = claim.get("conserved", 0)
    if not isinstance(k, int) or isinstance(k, bool) or k < 0:
        raise Malformed("claim.conserved: not an integer >= 0")
    if claim.get("status") != "certified":
        raise Malformed("claim.status: missing or not \"certified\"")
    if not isinstance(claim.get("stable"), bool):
        raise Malformed("claim.stable: missing or not true/false")
    return stein_verdict(loop_quotient(model), evidence, claim["stable"], k, "evidence")


def stein_verdict(quotient, evidence, stable, k, where):
    """check_stability_loop's test on a loop (loop_quotient's tuple) from evidence {P[, w]} (named `where`):
    its k conserved quantities, Q = P - M^T P M > 0 in intervals, P > 0 or w^T P w < 0."""
    loop, L, at, right, own, _ = quotient
    if len(at) + len(right) - own != k:
        return False, ("claim: %d conserved quantities, but the loop has %d (l^T [A B] = 0 of the plant, l^T [A - I, B] = 0 "
                       "of the wall or coupling, exactly: each an eigenvalue 1 of M)" % (k, len(at) + len(right) - own))
    P = symmetric_evidence(evidence, where, None)
    n = len(P)
    if stable == ("w" in evidence):
        raise Malformed(where + (".w: only for NOT stable" if stable else ".w: missing (NOT stable needs w with w^T P w < 0)"))
    if stable:
        if not semidefinite(P, True):
            return False, "claim: stable, but %s.P is not positive definite" % where
        sign = "P > 0"
    else:
        w = frac_matrix({"w": [evidence["w"]]}, "w", 1, n)[0]
        q = sum(w[i] * P[i][j] * w[j] for i in range(n) for j in range(n))
        if q >= 0:
            return False, "claim: NOT stable, but w^T P w = %s >= 0" % short(q)
        sign = "w^T P w < 0"
    for bits in (128, 256, 512):
        M = loop_quotient_matrix(loop, L, at, right, bits)
        if len(M) != n:
            raise Malformed("%s.P: order %d, the loop's %d%s" % (where, n, len(M), " (on the quotient by its conserved quantities)" if at else ""))
        if stein_shown(P, M):
            return True, "%s (closed loop of %d states built from the model%s%s, intervals at %d bits; P - M^T P M > 0 and %s)" % (
                "stable" if stable else "NOT stable", n + len(at), ", on the quotient by its conserved quantities (k = %d)" % k if k else "",
                ", the position integrated here set to P's output (its own conserved quantity: the model as written)" if own else "",
                bits, sign)
    return False, "claim: %s, but P - M^T P M is not shown positive definite at 512 bits" % ("stable" if stable else "NOT stable")


MAX_LOOP_SYMMETRIC_DOFS = 256  # stability-loop-symmetric: DOFs of the kind (hapstab check's limit too)
MAX_LOOP_SYMMETRIC_READ = 128  # and this checker's: E's N^2 entries expanded and compared, ~N^3 (19 s at 128, 143 s at 256)


def split_loop(loop, classes):
    """stability-loop-symmetric's split (C++ check/stability_loop_symmetric_check.hpp) of a scene loop by the
    partition `classes` (0-based DOFs): (fixed loop, [zero-sum loop or None per class], sizes), or a string
    naming the first difference when the loop is not invariant under the classes' permutations. The fixed loop:
    one DOF per class (its first DOF's device and operators) under E_F[a][a] = E(f_a, f_a) + (k_a - 1) E(f_a,
    s_a), E_F[a][b] = k_b E(f_a, f_b); class a's zero-sum loop: f_a under E(f_a, f_a) - E(f_a, s_a); a coupling V
    (tf) split the same way; each column over the whole's column lcm (the loop's states are the whole's,
    restricted)."""
    T, d, devices, mass, damp, stiff, ops, E, V = loop
    if E[0] != "tf":
        scene_beyond("environment.ss", "beyond stability-loop-symmetric (the split compares E's entries, a tf)")
    if V is not None and V[0] != "tf":
        scene_beyond("coupling.ss", "beyond stability-loop-symmetric (the split compares V's entries, a tf)")
    if any(dev["dofs"] != 1 for dev in devices) or any(len(ports) != 1 for ports, _ in ops):
        scene_beyond("[[device]] / [[operator]]", "a block on several DOFs: beyond stability-loop-symmetric (one DOF each)")
    N = len(mass)
    if not isinstance(classes, list) or any(not isinstance(c, list) or not c for c in classes):
        raise Malformed("evidence.classes: a list of non-empty lists of DOF indices (0-based)")
    class_of = [None] * N
    for a, c in enumerate(classes):
        for i in c:
            if not isinstance(i, int) or isinstance(i, bool) or not 0 <= i < N:
                raise Malformed("evidence.classes: %r is not one of the scene's DOFs 0 .. %d" % (i, N - 1))
            if class_of[i] is not None:
                raise Malformed("evidence.classes: DOF %d in two classes" % i)
            class_of[i] = a
    if None in class_of:
        raise Malformed("evidence.classes: not every DOF is in a class (a partition of the DOFs)")

    def dof(i):  # device i is DOF i (one DOF each); its operators in order
        return (mass[i], damp[i], stiff[i], devices[i]["block"], [Z for ports, Z in ops if ports[0] == i])
    f = [c[0] for c in classes]
    s = [c[1] if len(c) > 1 else None for c in classes]
    for a, c in enumerate(classes):
        for i in c:
            if dof(i) != dof(f[a]):
                return "DOF %d is not identical to DOF %d of its class (device or operators)" % (i, f[a])
    for G, name, what in ((E[1], "E", "environment"),) + (((V[1], "V", "coupling"),) if V is not None else ()):
        for i in range(N):
            for j in range(N):
                a, b = class_of[i], class_of[j]
                ri, rj = f[a], (f[a] if i == j else s[a] if a == b else f[b])
                if G[i][j] != G[ri][rj]:
                    return "the %s is not invariant under the classes: %s[%d][%d] != %s[%d][%d]" % (what, name, i + 1, j + 1, name, ri + 1, rj + 1)
    r = len(classes)

    def split(G):  # [fixed space's (tf, over)] + [class a's zero-sum (tf, over) or None]
        over = [column_lcms([[G[f[a]][f[b]]] for a in range(r)] + ([[G[f[b]][s[b]]]] if s[b] is not None else []))[0] for b in range(r)]
        GF = [[(G[f[a]][f[a]] + RF([Fraction(len(classes[a]) - 1)]) * G[f[a]][s[a]] if s[a] is not None else G[f[a]][f[a]])
               if a == b else RF([Fraction(len(classes[b]))]) * G[f[a]][f[b]] for b in range(r)] for a in range(r)]
        return [(GF, over)] + [([[G[f[a]][f[a]] - G[f[a]][s[a]]]], [over[a]]) if s[a] is not None else None for a in range(r)]
    Es = split(E[1])
    Vs = split(V[1]) if V is not None else None

    def block(reps, k):
        bops = [([reps.index(ports[0])], Z) for ports, Z in ops if ports[0] in reps]
        bdevs = [dict(devices[i], first=a) for a, i in enumerate(reps)]
        return (T, d, bdevs, [mass[i] for i in reps], [damp[i] for i in reps], [stiff[i] for i in reps], bops,
                ("ss", realise_columns(*Es[k])), ("ss", realise_columns(*Vs[k])) if Vs is not None else None)
    zero_sum = [block([f[a]], a + 1) if s[a] is not None else None for a in range(r)]
    return block(f, 0), zero_sum, [len(c) for c in classes]


def block_slot(blk, zero_sum, sizes, seen, where):
    """A split's block {space: "fixed" | "zero-sum", class, conserved} (C++ detail::block_slot): (slot -- None for
    the fixed space, else its class --, multiplicity, conserved), the slot added to `seen`; Malformed when a
    field is wrong, a class of one DOF is named or a block is given twice."""
    if blk.get("space") == "fixed":
        if "class" in blk:
            raise Malformed(where + ".class: only for a zero-sum block")
        slot, copies = None, 1
    elif blk.get("space") == "zero-sum":
        a = blk.get("class")
        if not isinstance(a, int) or isinstance(a, bool) or not 0 <= a < len(sizes):
            raise Malformed(where + ".class: not a class index")
        if zero_sum[a] is None:
            raise Malformed(where + ".class: class %d has one DOF (no zero-sum space)" % a)
        slot, copies = a, sizes[a] - 1
    else:
        raise Malformed(where + ".space: missing or not \"fixed\" / \"zero-sum\"")
    if slot in seen:
        raise Malformed(where + ": a block given twice")
    seen.add(slot)
    kb = blk.get("conserved", 0)
    if not isinstance(kb, int) or isinstance(kb, bool) or kb < 0:
        raise Malformed(where + ".conserved: not an integer >= 0")
    return slot, copies, kb


def check_stability_loop_verdicts(c):
    """stability-loop-verdicts (C++ check/stability_loop_verdicts_check.hpp): the certified verdicts of the scene's
    loop at values of one parameter (the bisection on verdicts, where the loop is not affine in it): one whole
    stability-loop (or stability-loop-symmetric) certificate per claimed value, whose model is exactly the scene
    with that value set and whose claim.stable is the one claimed, each checked by its own kind's checker here."""
    model, claim, evidence = parts(c)
    only(model, ("scene", "set", "name"), "model")
    only(claim, ("quantity", "status", "verdicts"), "claim")
    only(evidence, ("verdicts",), "evidence")
    if not isinstance(model.get("scene"), str):
        raise Malformed("model.scene: missing or not a string")
    name = model.get("name")
    if not isinstance(name, str) or not name:
        raise Malformed("model.name: missing or not a parameter's name")
    if not isinstance(model.get("set"), dict):
        raise Malformed("model.set: missing or not an object")
    if name in model["set"]:
        raise Malformed("model.set: gives %s a value (the parameter whose verdicts are claimed)" % name)
    if claim.get("status") != "certified":
        raise Malformed("claim.status: missing or not \"certified\"")
    verdicts = claim.get("verdicts")
    if not isinstance(verdicts, list) or not 1 <= len(verdicts) <= 64:
        raise Malformed("claim.verdicts: not an array of 1..64 verdicts")
    proofs = evidence.get("verdicts")
    if not isinstance(proofs, list) or len(proofs) != len(verdicts):
        raise Malformed("evidence.verdicts: not an array of one certificate per claimed verdict")
    seen, stable = set(), 0
    for i, (v, part) in enumerate(zip(verdicts, proofs)):
        at, ev = "claim.verdicts[%d]" % i, "evidence.verdicts[%d]" % i
        if not isinstance(v, dict):
            raise Malformed(at + ": not an object {at, stable}")
        only(v, ("at", "stable"), at)
        value = exact(v, "at", at)
        if value in seen:
            raise Malformed(at + ".at: %s twice" % value)
        seen.add(value)
        if not isinstance(v.get("stable"), bool):
            raise Malformed(at + ".stable: missing or not true/false")
        if not isinstance(part, dict) or not isinstance(part.get("kind"), str):
            raise Malformed(ev + ": not a certificate object with a kind")
        kind = part["kind"]
        if kind not in ("stability-loop", "stability-loop-symmetric"):
            raise Malformed(ev + ".kind: %r, not stability-loop or stability-loop-symmetric" % kind)
        if part.get("certificate") != "hapstab" or part.get("version") != 1 or isinstance(part.get("version"), bool):
            raise Malformed(ev + ": not a hapstab certificate of version 1")
        want_set = dict(model["set"])
        want_set[name] = v["at"]
        if part.get("model") != {"scene": model["scene"], "set": want_set}:
            raise Malformed(ev + ".model: not the scene as written with its set and %s = %s (each verdict must be about the "
                            "model of this certificate)" % (name, v["at"]))
        if not isinstance(part.get("claim"), dict) or part["claim"].get("stable") is not v["stable"]:
            raise Malformed(ev + ".claim.stable: not the verdict claimed at %s = %s" % (name, value))
        try:
            ok, why = (check_stability_loop if kind == "stability-loop" else check_stability_loop_symmetric)(part)
        except Malformed as e:
            raise Malformed(ev + ": " + str(e))
        if not ok:
            return False, "%s (%s = %s): %s" % (ev, name, value, why)
        stable += v["stable"]
    return True, ("%d verdicts of the scene's loop along %s (%d stable, %d NOT stable), each a stability-loop certificate "
                  "verified on the scene with %s set" % (len(verdicts), name, stable, len(verdicts) - stable, name))


def check_stability_loop_symmetric(c):
    """stability-loop-symmetric (C++ check/stability_loop_symmetric_check.hpp): the scene's loop split by the
    permutations of identical DOFs (evidence.classes; the invariance checked here on the scene as written), each
    small loop's Stein evidence verified as stability-loop's (stein_verdict): stable, every block and the
    conserved quantities k_F + sum_a (k_a - 1) k_a'; NOT stable, one block."""
    model, claim, evidence = parts(c)
    only(claim, ("quantity", "status", "stable", "conserved"), "claim")
    only(evidence, ("classes", "blocks"), "evidence")
    if claim.get("status") != "certified":
        raise Malformed("claim.status: missing or not \"certified\"")
    if not isinstance(claim.get("stable"), bool):
        raise Malformed("claim.stable: missing or not true/false")
    stable = claim["stable"]
    if not stable and "conserved" in claim:
        raise Malformed("claim.conserved: only with stable (NOT stable is shown by one block)")
    k = claim.get("conserved", 0)
    if not isinstance(k, int) or isinstance(k, bool) or k < 0:
        raise Malformed("claim.conserved: not an integer >= 0")
    if "scene" not in model:
        raise Malformed("model.scene: missing (this kind splits a scene's DOFs)")
    devices = scene_read(model, False, coupling=True, max_dofs=MAX_LOOP_SYMMETRIC_DOFS)[0].get("device")
    n = len(devices) if isinstance(devices, list) else 0  # one DOF each, or refused below
    if n > MAX_LOOP_SYMMETRIC_READ:
        raise TooLarge("model.scene: %d devices, above this checker's limit %d for stability-loop-symmetric (reading E's N^2 "
                       "entries costs ~N^3: 19 s at 128)" % (n, MAX_LOOP_SYMMETRIC_READ))
    split = split_loop(scene_loop_read(model, MAX_LOOP_SYMMETRIC_DOFS), evidence.get("classes"))
    if isinstance(split, str):
        return False, "evidence.classes: " + split
    fixed, zero_sum, sizes = split
    blocks = evidence.get("blocks")
    needed = 1 + sum(1 for z in zero_sum if z is not None)
    if not isinstance(blocks, list) or len(blocks) != (needed if stable else 1):
        raise Malformed("evidence.blocks: %s" % ("stable needs every block: the fixed space and each class of two DOFs or more, %d" % needed
                                                if stable else "NOT stable is shown by one block"))
    seen, total, said = set(), 0, []
    for b, blk in enumerate(blocks):
        where = "evidence.blocks[%d]" % (b + 1)
        if not isinstance(blk, dict):
            raise Malformed(where + ": not an object")
        only(blk, ("space", "class", "conserved", "P", "w"), where)
        slot, copies, kb = block_slot(blk, zero_sum, sizes, seen, where)
        loop = fixed if slot is None else zero_sum[slot]
        ok, why = stein_verdict(loop_quotient_of(loop), blk, stable, kb, where)
        if not ok:
            return False, "%s (%s): %s" % (where, blk["space"], why)
        total += copies * kb
        said.append("%s%s: %s" % (blk["space"], "" if slot is None else " of class %d (x%d)" % (slot, copies), why))
    if stable and total != k:
        return False, "claim: %d conserved quantities, but the blocks have %d (k_F + sum_a (k_a - 1) k_a')" % (k, total)
    return True, "%s by the split of %d DOFs into %d classes of identical DOFs (invariance checked exactly on the scene as written): %s" % (
        "stable" if stable else "NOT stable", sum(sizes), len(sizes), "; ".join(said))


MAX_LOOP_COVER = 4096  # stability-loop-max: intervals of the cover (two Stein tests each)
MAX_LOOP_COVER_WORK = 1000000  # and intervals x n^3 (~1.3 s at 193 tests of order 8: ~13 s at the limit)


def gain_block(scene, p):
    """stability-loop-max's reading of p (check/stability_loop_max_check.hpp): (block, inside) -- block
    "environment" or "coupling" whose gain is exactly p, p a parameter named in no other string of the
    scene (labels and keywords -- name, dofs, domain, method -- and the ignored sections aside); or
    (inside) p named only in the tf entries of one of them, its gain not p."""
    import tomllib
    try:
        root = tomllib.loads(scene)
    except (tomllib.TOMLDecodeError, RecursionError) as e:
        raise Malformed("model.scene: not TOML: %s" % e)
    if not isinstance(root.get("parameters"), dict) or p not in root["parameters"]:
        raise Malformed("model.name: %r is not a parameter of the scene ([parameters])" % p)
    blocks = [b for b in ("environment", "coupling") if isinstance(root.get(b), dict) and root[b].get("gain") == p]
    if len(blocks) > 1:
        raise Malformed("model.name: %r is the gain of both [environment] and [coupling]" % p)
    found = []

    def scan(node, at):
        if isinstance(node, dict):
            for k, v in node.items():
                if k in ("name", "dofs", "domain", "method") or (not at and k in ("input", "initial", "simulate", "reproduce", "multidof")):
                    continue
                scan(v, k if not at else at + "." + k)
        elif isinstance(node, list):
            for i, v in enumerate(node):
                scan(v, "%s[%d]" % (at, i))
        elif isinstance(node, str) and at not in ([blocks[0] + ".gain"] if blocks else []) + ["parameters." + p]:
            if p in re.findall(r"[A-Za-z_][A-Za-z0-9_]*", node):
                found.append(at)
    scan(root, "")
    if not blocks:
        for b in ("environment", "coupling"):
            if found and all(w == b + ".tf" or w.startswith(b + ".tf[") or w in (b + ".diagonal", b + ".off_diagonal") for w in found):
                return b, True
        raise Malformed("model.name: %r is neither the whole gain of [environment] or [coupling] nor named only in the tf of one of "
                        "them: beyond this kind" % p)
    if found:
        raise Malformed("model.scene: %r is named in %s as well as in %s.gain: beyond this kind (only a gain, named nowhere "
                        "else, makes the loop affine in it)" % (p, found[0], blocks[0]))
    return blocks[0], False


def affine_block_order(model, block, p, N):
    """(sum_j deg L_j, the largest degree bound) of affine_column_orders: the largest order the realisation reaches
    at any p."""
    orders, degree = affine_column_orders(model, block, p, N)
    return sum(orders), degree


def affine_column_orders(model, block, p, N):
    """p inside the block's tf (check/stability_loop_max_check.hpp): each entry naming p proven affine in it
    (prove_affine: H = H0 + p H1); ([deg L_j per column j], the largest degree bound), L_j the monic lcm over
    column j of den H0 and den H1 -- the largest order that column's realisation reaches at any p."""
    root, T, expand, field = scene_read(model, True, coupling=True)
    t = root.get(block)
    if not isinstance(t, dict) or ("tf" not in t and "diagonal" not in t):
        scene_beyond(block + ".ss", "the parameter inside an ss block (only a tf entry is proven affine)")
    gain_text = field(t, "gain", block, "1")
    E = [["(%s)*(%s)" % (gain_text, scene_wall_entry(t, e, expand)) for e in row]
         for row in (scene_diagonal(t, block, N) if "diagonal" in t else scene_text_matrix(t["tf"], N, block + ".tf"))]
    orders, degree = [], 0
    for j in range(N):
        L = [Fraction(1)]
        for i in range(N):
            if p in re.findall(r"[A-Za-z_][A-Za-z0-9_]*", E[i][j]):
                try:
                    H0, H1, D = prove_affine(E[i][j], T, {}, p)
                except Malformed as e:
                    raise Malformed("model.scene: %s.tf[%d][%d]: %s: beyond this kind" % (block, i, j, e))
                dens, degree = (H0.den, H1.den), max(degree, D)
            else:
                dens = (scene_rf(E[i][j], T, 'z', block + ".tf").den,)
            for d in dens:
                g = pgcd(L, d)
                L = pdivmod(pmul(L, d), g)[0]
                L = [x / L[-1] for x in L]
        orders.append(len(L) - 1)
    return orders, degree


def plant_reading(model, p):
    """stability-loop-max of a one-DOF --plant/--H model: p named in H, in neither the plant nor the operator
    (p inside the tf of its one wall): ("environment", True)."""
    def names(key):
        if key not in model:
            return False
        if not isinstance(model[key], str):
            raise Malformed("model.%s: not a string" % key)
        return p in re.findall(r"[A-Za-z_][A-Za-z0-9_]*", model[key])
    if not names("H"):
        raise Malformed("model.H: does not name model.name = %s" % p)
    for key in ("plant", "operator"):
        if names(key):
            raise Malformed("model.%s: names %s too: beyond this kind (only H may depend on it)" % (key, p))
    return "environment", True


def plant_wall_order(model, p):
    """affine_block_order of the one-DOF wall H: (deg of the lcm of den H0, den H1, the degree bound)."""
    T, _, params, _ = effective_device(model)
    try:
        H0, H1, D = prove_affine(model["H"], T, params, p)
    except ZeroDivisionError:
        raise Malformed("model.H: division by zero: beyond this kind")
    g = pgcd(H0.den, H1.den)
    return len(pdivmod(pmul(H0.den, H1.den), g)[0]) - 1, D


def newton_interpolate(xs, ys):
    """The polynomial (ascending) of degree < len(xs) through (xs[i], ys[i]), exactly: Newton's divided differences."""
    n = len(xs)
    d = [Fraction(y) for y in ys]
    for j in range(1, n):
        for i in range(n - 1, j - 1, -1):
            d[i] = (d[i] - d[i - 1]) / (xs[i] - xs[i - j])
    p = [d[n - 1]]
    for i in range(n - 2, -1, -1):
        p = padd(pmul(p, [-Fraction(xs[i]), Fraction(1)]), [d[i]])
    return trim(p)


def resultant(f, g):
    """Res(f, g) = lc(f)^deg g lc(g)^deg f prod (alpha_i - beta_j) (f, g ascending, f != 0), exactly, by Euclid's
    recursion: Res(f, g) = (-1)^(deg f deg g) lc(g)^(deg f - deg r) Res(g, r), r = f mod g (derived from
    Res(g, f) = lc(g)^deg f prod over g's roots beta of f(beta) and f(beta) = r(beta)); Res(f, c) = c^deg f."""
    f, g = trim(f), trim(g)
    if not g:
        return Fraction(0)
    n, m = len(f) - 1, len(g) - 1
    if m == 0:
        return g[0] ** n
    r = pdivmod(f, g)[1]
    if not r:
        return Fraction(0)
    return (-1) ** (n * m) * g[-1] ** (n - (len(r) - 1)) * resultant(g, r)


def no_root_in(R, a):
    """True when R (R(0) != 0) has no real root in (0, a]; False when it has one; None when not decided. Descartes'
    rule of signs on Q(t) = (1 + t)^d R((u + v t)/(1 + t)), whose positive roots are R's roots in (u, v): no sign
    variation, no root; one, exactly one; more, (u, v) halved (Vincent), at most 60 times deep. In integers: R scaled
    by its common denominator, and Q L^d = sum_k r_k A^k B^(d - k) with A = L (u + v t), B = L (1 + t) (Horner)."""
    if peval(R, a) == 0:
        return False
    r, _ = integers(R)
    d = len(r) - 1

    def mul(x, y):
        out = [0] * (len(x) + len(y) - 1)
        for i, xi in enumerate(x):
            if xi:
                for j, yj in enumerate(y):
                    out[i + j] += xi * yj
        return out
    stack = [(Fraction(0), Fraction(a), 0)]
    while stack:
        u, v, depth = stack.pop()
        L = u.denominator * v.denominator
        A, B = [u.numerator * (L // u.denominator), v.numerator * (L // v.denominator)], [L, L]
        Q, Bp = [r[d]], [1]
        for j in range(d - 1, -1, -1):
            Bp = mul(Bp, B)
            Q = mul(Q, A)
            for i, x in enumerate(Bp):
                Q[i] += r[j] * x
        signs = [x > 0 for x in Q if x != 0]
        var = sum(1 for x, y in zip(signs, signs[1:]) if x != y)
        if var == 0:
            continue
        if var == 1:
            return False
        w = (u + v) / 2
        if depth >= 60 or peval(R, w) == 0:
            return None if depth >= 60 else False
        stack += [(u, w, depth + 1), (w, v, depth + 1)]
    return True


def circle_crossing_free(M0, M1, a):
    """"" when no p in (0, a] gives M0 + p M1 an eigenvalue on the unit circle (C++ lti/circle_crossing.hpp, derived here
    again): c(z, p) = det(zI - M(p)) is monic in z, so R(p) = Res_z(c, z^n c(1/z)) = prod over c's roots mu of mu^n
    c(1/mu) vanishes where a root lies on the circle (1/mu = conj mu a root too); deg_p c <= r = rank M1 (the matrix
    determinant lemma), deg R <= 2 n r (the Sylvester matrix): c from r + 1 characteristic polynomials, R from 2 n r + 1
    resultants, both interpolated exactly; no root of R / p^m in (0, a] (no_root_in): the roots stay off the circle on
    (0, a] (continuity). Else why not."""
    n = len(M0)
    K = [row[:] for row in M1]
    r = len(echelon(K)) if K else 0
    D = 2 * n * r
    if n > 64 or D > 2048:
        raise TooLarge("evidence.no_crossing: M of order %d, 2 n rank(M1) = %d: above this checker's limits 64 and 2048" % (n, D))
    cs = [faddeev_leverrier([[M0[i][j] + k * M1[i][j] for j in range(n)] for i in range(n)]) for k in range(r + 1)]
    ck = [newton_interpolate(list(range(r + 1)), [c[k] for c in cs]) for k in range(n + 1)]
    values = []
    for i in range(D + 1):
        c = [peval(q, Fraction(i)) for q in ck]
        values.append(resultant(c, c[::-1]))
    R = newton_interpolate(list(range(D + 1)), values)
    if not R:
        return "R vanishes for every p (eigenvalues mu, 1/mu at every p): nothing shown"
    m = 0
    while R[m] == 0:
        m += 1
    R = R[m:]  # (a double root -- a complex pair on the circle -- leaves Descartes undecided there: not shown, never shown)
    free = no_root_in(R, a)
    if free is True:
        return ""
    return "R(p) / p^%d (degree %d) has a real root in (0, %s]%s" % (m, len(R) - 1, short(a), "" if free is False else " or was not decided")


def slow_rows(l1, l2, Lq, at, right):
    """The rows r of the loop's slow modes at p = 0 (check/stability_loop_max_check.hpp), on the coordinates
    of the quotient by the conserved rows Lq (at their indices `at`, loop_quotient): l^T E for a basis l of
    {l : l^T (M~(0) - I) = 0, l_p^T A = 0}, M~(0) = 2 M~(1) - M~(2) the slow matrices (loop_matrix's slow=True)
    of the loops read at p = 1 and 2, E the quotient's embedding (x = E y: x_kept = y, x_c = -L[:, kept] y),
    in reduced echelon form. With l_p^T A = 0, l^T M(p) = l^T M~(p) exactly, so r^T M(0) = r^T."""
    if right:
        raise Malformed("evidence.first_order: a loop on a quotient by a block's unobservable z = 1 (right eigenvectors): beyond this kind")
    S1, S2 = loop_matrix(l1, 0, slow=True), loop_matrix(l2, 0, slow=True)
    A = loop_plant(*l1[2:7])[0]
    n, ns = len(S1), len(A)
    M0mI = [[2 * S1[i][j] - S2[i][j] - (1 if i == j else 0) for j in range(n)] for i in range(n)]
    Ap = [list(A[i]) if i < ns else [Fraction(0)] * ns for i in range(n)]
    L = conserved_quantities(M0mI, Ap)[0]
    if L and at:  # on the quotient: r = l^T E
        kept = [i for i in range(n) if i not in at]
        L = [[l[kb] - sum(l[c] * q[kb] for q, c in zip(Lq, at) if kb < len(q)) for kb in kept] for l in L]
    if L:
        L = L[:len(echelon(L))]  # reduced echelon form; the conserved rows' own images (0) dropped
    return L


def read_first_order(fo, where, keys, loops, quotient, n):
    """The first-order form's parts {to = eps, P0, S} (and w where `keys` has it): (eps, P0, S, L), L the slow rows;
    Malformed when malformed."""
    if not isinstance(fo, dict):
        raise Malformed(where + ": not an object")
    only(fo, keys, where)
    L = slow_rows(*loops, *quotient)
    if not L:
        raise Malformed(where + ": the loop has no position that nothing holds at p = 0")
    eps = exact(fo, "to", where)
    k = len(L)
    P0 = symmetric_evidence({"P": fo.get("P0")}, where, n)
    S = frac_matrix(fo, "S", k, k, where)
    if any(S[i][j] != S[j][i] for i in range(k) for j in range(i)):
        raise Malformed(where + ".S: not symmetric")
    return eps, P0, S, L


def first_order_stein(eps, P0, S, L, M1, M2, where):
    """P0 > 0 and Q(p) = P0 - M^T P0 M - (K^T S L + L^T S K) - p K^T S K > 0 at 0 and eps, K = L (M(2) - M(1)):
    concave in p (P0 > 0), so > 0 on [0, eps]. "" when shown, else what fails."""
    n, k = len(M1), len(L)
    if not semidefinite(P0, True):
        return where + ".P0 is not positive definite"
    K = [[sum((Iv(L[r][i]) * (M2[i][j] - M1[i][j]) for i in range(n) if L[r][i]), Iv(0)) for j in range(n)] for r in range(k)]
    SK = [[sum((Iv(S[r][t]) * K[t][j] for t in range(k) if S[r][t]), Iv(0)) for j in range(n)] for r in range(k)]
    for e in (Fraction(0), eps):
        u, v = Iv(2 - e), Iv(e - 1)
        M = [[u * M1[i][j] + v * M2[i][j] for j in range(n)] for i in range(n)]
        MtPM = iv_matmul(list(zip(*M)), iv_matmul(P0, M))
        Q = [[Iv(P0[i][j]) - MtPM[i][j]
              - sum((SK[r][j] * Iv(L[r][i]) + SK[r][i] * Iv(L[r][j]) + Iv(e) * K[r][i] * SK[r][j] for r in range(k)), Iv(0))
              for j in range(n)] for i in range(n)]
        if not iv_positive_definite(Q):
            return "%s at p = %s: P0 - M^T P0 M - (K^T S L + L^T S K) - p K^T S K not shown positive definite" % (where, short(e))
    return ""


def first_order_start(fo, loops, quotient, M1, M2, lo):
    """(eps, "") when evidence.first_order {to = eps, P0, S} shows every M(p), 0 < p <= eps, Schur stable:
    with L the slow rows (L M(0) = L exactly), K = L (M(2) - M(1)) and P(p) = P0 + L^T S L / p, the Stein
    matrix is Q(p) = P0 - M^T P0 M - (K^T S L + L^T S K) - p K^T S K, concave in p, > 0 at 0 and eps
    (check/stability_loop_max_check.hpp); (None, what fails) otherwise."""
    where = "evidence.first_order"
    eps, P0, S, L = read_first_order(fo, where, ("to", "P0", "S"), loops, quotient, len(M1))
    if not 0 < eps <= lo:
        raise Malformed(where + ".to: not in (0, claim.lo]")
    if not semidefinite(S, False):
        return None, where + ".S is not positive semidefinite"
    fails = first_order_stein(eps, P0, S, L, M1, M2, where)
    return (None, fails) if fails else (eps, "")


def first_order_unstable(fo, loops, quotient, M1, M2, where):
    """The mirror, evidence.first_order_unstable {to = eps, P0, S, w}: with s = (L w)^T S (L w) < 0 and w^T P0 w + s / eps
    < 0 (exactly), w^T P(p) w < 0 for every p in (0, eps], and Q(p) = P(p) - M^T P(p) M > 0 there (as the start's, S of
    any sign): M(p) not Schur stable and no eigenvalue on the circle (Stein inertia), so NOT stable on (0, eps].
    (True, "") shown; (False, why) refuted (an exact test); (None, why) a ball test failed."""
    where += ".first_order_unstable"
    n = len(M1)
    eps, P0, S, L = read_first_order(fo, where, ("to", "P0", "S", "w"), loops, quotient, n)
    if eps <= 0:
        raise Malformed(where + ".to: not > 0")
    w = frac_matrix({"w": [fo.get("w")]}, "w", 1, n, where)[0]
    Lw = [sum(l[i] * w[i] for i in range(n)) for l in L]
    s = sum(Lw[r] * S[r][t] * Lw[t] for r in range(len(L)) for t in range(len(L)))
    if s >= 0:
        return False, where + ": (L w)^T S (L w) >= 0"
    if sum(w[i] * P0[i][j] * w[j] for i in range(n) for j in range(n)) + s / eps >= 0:
        return False, where + ": w^T P0 w + (L w)^T S (L w) / eps >= 0"
    fails = first_order_stein(eps, P0, S, L, M1, M2, where)
    return (None, fails) if fails else (True, "")


def sup_model(model, claim, status="certified"):
    """A supremum kind's maximised parameter (model.name, given no value in model.set) and its claim (status
    "certified", or `status`; lo >= 0): (p, set, lo, hi, refuted) -- refuted when the printed ends are not lo and hi."""
    p = model.get("name")
    if not isinstance(p, str):
        raise Malformed("model.name: missing or not a string")
    sets = model.get("set", {})
    if not isinstance(sets, dict):
        raise Malformed("model.set: not an object")
    if p in sets:
        raise Malformed("model.set.%s: the parameter maximised has no value" % p)
    if claim.get("status") != status:
        raise Malformed("claim.status: missing or not \"certified\" (the loop holds exponentials: enclosures decide)" if status == "certified"
                        else "claim.status: sup = 0 by a hidden mode is \"exact\" (rational evidence)")
    _, lo, hi, _, refuted = claim_range(claim)
    if not refuted and lo < 0:
        raise Malformed("claim.lo: negative (sup p >= 0)")
    return p, sets, lo, hi, refuted


def stability_loop_max_hidden(model, claim, evidence):
    """sup p = 0 by a hidden mode for every p (evidence.hidden, the stability-loop kind's form; claim exact, value 0).
    hidden_mode_verdict shows the loop NOT stable at p = 1 and at p = 2 by one invariant subspace of an ss block. Its
    conditions (C V = 0, A V = V A_h; or W B = 0, W A = A_h W) are linear in the block's (A, B, C), and gain_block
    proves p enters only the environment's or the coupling's gain (C, D times p: C V = 0 iff p C V = 0, p != 0) or
    its tf entries (no ss block), and nothing else. So the subspace is the loop's at every p > 0: NOT stable on
    (0, inf), and sup p = 0."""
    only(evidence, ("hidden",), "evidence")
    only(claim, ("quantity", "status", "value"), "claim")
    if not isinstance(model.get("scene"), str):
        raise Malformed("evidence.hidden: a hidden mode of a scene's block (model.scene, a string)")
    p, sets, lo, _, refuted = sup_model(model, claim, "exact")
    if refuted:
        return False, refuted
    block, inside = gain_block(model["scene"], p)
    why = ""
    for v in (1, 2):
        m = dict({k: x for k, x in model.items() if k != "name"}, set=dict(sets))
        m["set"][p] = str(v)
        ok, why = hidden_mode_verdict(scene_loop_read(m), evidence["hidden"], m)
        if not ok:
            return False, "sup %s = 0 not shown: at %s = %d, %s" % (p, p, v, why)
    if lo != 0:
        return False, "claim: sup %s = %s, but the loop is NOT stable for every %s > 0 by a hidden mode (%s): sup = 0" % (p, short(lo), p, why)
    return True, "sup %s = 0: %s; at %s = 1 and 2 alike, and at every %s > 0 (%s enters only the %s's %s)" % (
        p, why, p, p, p, block, "tf entries" if inside else "gain")


def check_stability_loop_max(c):
    """stability-loop-max (check/stability_loop_max_check.hpp): p the gain of one block alone (the realisations
    at p = 1 and 2: A, B equal, C, D doubled), or inside one block's tf (each entry proven affine, the
    realisation of the largest order at 1, 2 and hi, C, D at hi on the line), or in a one-DOF model's H, so
    the loop's M(p) = (2 - p) M(1) + (p - 1) M(2) (D_E D_V = D_V D_E = 0); on each cover interval [a, b] one
    P > 0 with P - M^T P M > 0 at both ends (convex in p: stable on all of it), or P at a and P_to at b, linear
    between (P left out: the last interval's P_to), with the four Bernstein coefficients of the cubic
    P(t) - M(t)^T P(t) M(t) positive definite (bernstein_stein_shown); and at claim.hi P, w with w^T P w < 0:
    NOT stable (Stein inertia); hi = 0: M(0) with an eigenvalue outside the circle, so M(p) for every small p > 0."""
    model, claim, evidence = parts(c)
    plant = "scene" not in model  # the one-DOF --plant/--H loop (scene_loop_read)
    only(model, ("plant", "H", "operator", "set", "T", "delay", "name") if plant else ("scene", "set", "name"), "model")
    if "hidden" in evidence:
        return stability_loop_max_hidden(model, claim, evidence)
    only(claim, ("quantity", "status", "lo", "hi", "printed_lo", "printed_hi", "conserved"), "claim")
    only(evidence, ("cover", "unstable_at", "first_order", "first_order_unstable", "no_crossing"), "evidence")
    if not isinstance(model.get("plant" if plant else "scene"), str):
        raise Malformed("model.scene (or model.plant): missing or not a string")
    p, sets, lo, hi, refuted = sup_model(model, claim)
    if refuted:
        return False, refuted
    k = claim.get("conserved", 0)
    if not isinstance(k, int) or isinstance(k, bool) or k < 0:
        raise Malformed("claim.conserved: not an integer >= 0")
    block, inside = plant_reading(model, p) if plant else gain_block(model["scene"], p)
    at_p = []
    for v in (1, 2) if not inside or hi == 0 else (1, 2, hi):
        m = dict({k: x for k, x in model.items() if k != "name"}, set=dict(sets))
        m["set"][p] = str(v)
        at_p.append(loop_quotient(m))
    if inside:  # the realisation at 1, 2 (and hi) of the largest order; C, D at hi on the line through 1 and 2
        order, degree = affine_block_order(model, block, p, len(at_p[0][0][3])) if not plant else plant_wall_order(model, p)
        if any(len(q[5][0 if block == "environment" else 1][0]) != order for q in at_p):
            raise Malformed("model.scene: the %s's realisation at %s = 1, 2 or %s is not of order %d (a pole cancelled there): beyond "
                            "this kind" % (block, p, short(hi), order))
    ok, why, n, bits = loop_max_part(at_p, evidence, lo, hi, k, p, block, inside, "evidence")
    if not ok:
        return False, why if ok is False else "claim: sup %s in [%s, %s], but %s at 512 bits" % (p, short(lo), short(hi), why)
    if hi == 0 and "first_order_unstable" in evidence:
        return True, "sup %s = 0: M(%s) = (2 - %s) M(1) + (%s - 1) M(2) (%d states) is NOT stable for every %s in (0, %s] (the first-order mirror, %d bits)" % (
            p, p, p, p, n, p, short(exact(evidence["first_order_unstable"], "to", "evidence.first_order_unstable")), bits)
    if hi == 0 and "no_crossing" in evidence:
        return True, ("sup %s = 0: M(%s) = (2 - %s) M(1) + (%s - 1) M(2) (%d states) is NOT stable for every %s in (0, %s] (no eigenvalue on "
                      "the unit circle there: the resultant; an eigenvalue |z| > 1 at its end, Stein inertia, %d bits)" % (
                          p, p, p, p, n, p, short(exact(evidence["no_crossing"], "to", "evidence.no_crossing")), bits))
    if hi == 0:
        return True, "sup %s = 0: M(%s) = (2 - %s) M(1) + (%s - 1) M(2) (%d states) has at %s -> 0 an eigenvalue |z| > 1 (Stein inertia, %d bits%s)" % (
            p, p, p, p, n, p, bits, ", on ker L beside the slow modes" if "slow_quotient" in evidence["unstable_at"] else "")
    how = "inside the %s's tf, proven affine there" % block if inside else "the %s's gain alone" % block
    return True, "sup %s in [%s, %s]: M(%s) affine (%d states, %s); stable on [0, %s] by %d intervals (one P > 0 per interval, P - M^T P M > 0 at both ends: convex in %s); NOT stable at %s (Stein inertia), %d bits" % (
        p, short(lo), short(hi), p, n, how, short(lo), len(evidence.get("cover", [])), p, short(hi), bits)


def loop_max_part(at_p, evidence, lo, hi, k, p, block, inside, where, need_unstable=True):
    """One loop's supremum evidence ({cover, first_order, unstable_at} of `evidence`, named `where`) on the loop
    read at p = 1, 2 (and hi: p inside the tf), at_p their loop_quotient's (C++ check_max_part): (True, "", n, bits)
    shown; (False, why, ...) refuted; (None, why, ...) not shown at 512 bits. unstable_at may be absent only where
    need_unstable is False (a block of stability-loop-max-symmetric that another block bounds)."""
    has_un, outward = "unstable_at" in evidence, "first_order_unstable" in evidence
    un = evidence.get("unstable_at", {})
    if outward and (has_un or "first_order" in evidence or hi != 0):
        raise Malformed(where + ".first_order_unstable: with claim.hi = 0 only, in place of unstable_at and first_order (sup = 0 "
                        "by the first-order mirror)")
    if (not has_un and not outward and need_unstable) or not isinstance(un, dict):
        raise Malformed(where + ".unstable_at: missing or not an object (NOT stable at hi bounds sup p; or, sup = 0, first_order_unstable)")
    only(un, ("at", "P", "w", "slow_quotient"), where + ".unstable_at")
    # no_crossing {to: a}: no eigenvalue of the rational M(p) on the circle on (0, a]; in place of first_order (the
    # cover then starts at min(a, lo)), or, claim.hi = 0, beside unstable_at at a (NOT stable on (0, a])
    nc_to = None
    if "no_crossing" in evidence:
        nc = evidence["no_crossing"]
        if not isinstance(nc, dict):
            raise Malformed(where + ".no_crossing: not an object")
        only(nc, ("to",), where + ".no_crossing")
        nc_to = exact(nc, "to", where + ".no_crossing")
        if "first_order" in evidence or outward or nc_to <= 0:
            raise Malformed(where + ".no_crossing.to: above 0, and not beside first_order or first_order_unstable")
    un_at = nc_to if nc_to is not None and hi == 0 else hi
    if has_un and exact(un, "at", where + ".unstable_at") != un_at:
        raise Malformed(where + ".unstable_at.at: not %s" % ("claim.hi" if un_at == hi else "no_crossing.to"))
    on_ker = "slow_quotient" in un  # sup = 0 beside slow modes: M(0) on ker L, L M(0) = L (the C++ header)
    if nc_to is not None and hi == 0 and (on_ker or not has_un):
        raise Malformed(where + ".no_crossing: with claim.hi = 0, beside unstable_at at no_crossing.to (not on a slow quotient)")
    if on_ker and (un["slow_quotient"] is not True or hi != 0):
        raise Malformed(where + ".unstable_at.slow_quotient: true, with claim.hi = 0 only (sup = 0 beside the slow modes)")
    cover = evidence.get("cover", [])
    if not isinstance(cover, list) or len(cover) > MAX_LOOP_COVER:
        raise Malformed(where + ".cover: not an array of at most %d intervals" % MAX_LOOP_COVER)
    if (not cover) != (lo == 0):
        raise Malformed(where + ".cover: needed exactly when claim.lo > 0 (it proves (0, lo])")
    (l1, L1, a1, r1, own1, b1), (l2, L2, a2, r2, own2, b2) = at_p[:2]
    g = 0 if block == "environment" else 1
    for i, (x, y) in enumerate(zip(b1, b2)):
        if i != g:
            want = x
        elif inside:
            want = (x[0], x[1], y[2], y[3])
        else:
            want = (x[0], x[1], [[2 * v for v in row] for row in x[2]], [[2 * v for v in row] for row in x[3]])
        if tuple(y) != tuple(want):
            return False, "the %s's realisation at %s = 2 is not the one at 1 with %s: not shown affine" % (
                block, p, "A and B equal" if inside else "C and D doubled"), 0, 0
        if len(at_p) > 2:
            if i == g:
                want = (x[0], x[1]) + tuple([[(2 - hi) * u + (hi - 1) * v for u, v in zip(ru, rv)] for ru, rv in zip(x[k], y[k])] for k in (2, 3))
            if tuple(at_p[2][5][i]) != tuple(want):
                return False, "the %s's realisation at %s = %s is not on the line through those at 1 and 2" % (block, p, short(hi)), 0, 0
    for bl in (b1, b2):
        if len(bl) > 1:
            DE, DV = bl[0][3], bl[1][3]
            if any(v != 0 for row in mmul(DE, DV) for v in row) or any(v != 0 for row in mmul(DV, DE) for v in row):
                raise Malformed("model.scene: D_E D_V or D_V D_E is not 0: the loop is not affine in %s, beyond this kind" % p)
    if (a1 and r1) or (a2 and r2):  # conserved quantities paired with unseen z = 1: the pairing could move with p
        raise Malformed("model.scene: conserved quantities beside a block's unobservable z = 1 (a quotient by both): beyond this kind")
    ns1 = len(loop_plant(*l1[2:7])[0])  # a right eigenvector with a part in the plant could move with a plant parameter
    if any(x != 0 for off, r in r1 + r2 if off < ns1 for x in r[:ns1 - off]):
        raise Malformed("model.scene: an unseen s = 0 of the plant set aside (a right eigenvector): beyond this kind")
    count = len(a1) + len(r1) - own1
    # p inside the tf: the conserved rows come from A, B alone (the plant's l^T [A B] = 0, a block's uncontrollable
    # z = 1), the same at every p; a block's unobservable z = 1 (C r = 0) could move with C(p): refused
    if inside and (r1 or r2):
        raise Malformed("model.scene: a block's unobservable z = 1 (a quotient by right eigenvectors) with %s inside the %s's tf"
                        ": beyond this kind (the right eigenvectors are not shown the same at every %s)" % (p, block, p))
    if inside and (L1 != L2 or a1 != a2):
        return False, "the conserved quantities' rows differ at %s = 1 and 2 (with A and B equal they cannot)" % p, 0, 0
    if count != len(a2) + len(r2) - own2:
        return False, "the conserved quantities differ at %s = 1 and 2" % p, 0, 0
    if count != k:
        return False, "%s: %d conserved quantities, but the loop has %d" % ("claim" if where == "evidence" else where, k, count), 0, 0
    if nc_to is not None:
        if count or r1 or own1:
            raise Malformed(where + ".no_crossing: a loop with conserved quantities (M on a quotient): beyond this kind")
        X1, X2 = loop_matrix(l1, 0, exact=True), loop_matrix(l2, 0, exact=True)
        if X1 is None or X2 is None or len(X1) != len(X2):
            raise Malformed(where + ".no_crossing: M is not rational (a plant that is not nilpotent: e^{AT} holds exponentials): "
                            "beyond this kind")
        no = circle_crossing_free([[2 * x - y for x, y in zip(r1_, r2_)] for r1_, r2_ in zip(X1, X2)],
                                  [[y - x for x, y in zip(r1_, r2_)] for r1_, r2_ in zip(X1, X2)], nc_to)
        if no:
            return False, "%s.no_crossing: an eigenvalue may meet the unit circle in (0, %s]: %s" % (where, short(nc_to), no), 0, 0
    why = ""
    for bits in (128, 256, 512):
        M1, M2 = loop_quotient_matrix(l1, L1, a1, r1, bits), loop_quotient_matrix(l2, L2, a2, r2, bits)
        n = len(M1)
        # one with P linear counted 3 times: measured 2.5 (stop 85: a cover of 323 intervals, 99 linear, 5.2 s; one of
        # 230, 193 linear, 5.7 s; order 10)
        tests = sum(3 if isinstance(c, dict) and "P_to" in c else 1 for c in cover)
        if tests * n ** 3 > MAX_LOOP_COVER_WORK:
            raise TooLarge("evidence.cover: %d intervals of order %d, above this checker's limit (intervals x n^3 <= %d, one with "
                           "P linear counted 3 times)" % (len(cover), n, MAX_LOOP_COVER_WORK))

        def M_at(x):
            u, v = Iv(2 - x), Iv(x - 1)
            return [[u * M1[i][j] + v * M2[i][j] for j in range(n)] for i in range(n)]
        start, ok = (min(nc_to, lo) if nc_to is not None else Fraction(0)), True  # to >= lo: the cover is the one point lo
        if "first_order" in evidence:
            eps, fails = first_order_start(evidence["first_order"], (l1, l2), (L1, a1, r1), M1, M2, lo)
            if fails:
                why = fails
                continue
            start = eps
        if outward:  # NOT stable on (0, eps]: the first-order mirror
            shown, fails = first_order_unstable(evidence["first_order_unstable"], (l1, l2), (L1, a1, r1), M1, M2, where)
            if shown is False:
                return False, fails, n, bits
            if shown is None:
                why = fails
                continue
        if has_un:  # NOT stable at hi (Stein inertia; sup = 0 by no_crossing: at its end)
            Mu = M_at(un_at)
            if on_ker:
                S = slow_rows(l1, l2, L1, a1, r1)
                if not S:
                    raise Malformed(where + ".unstable_at.slow_quotient: the loop has no slow rows at %s = 0" % p)
                K = [list(r) for r in S]
                Mu = quotient(Mu, S, echelon(K))  # S in reduced echelon form: x_pivot = -S[:, kept] y
            nu = len(Mu)
            Pu = symmetric_evidence(un, where + ".unstable_at", nu)
            w = frac_matrix({"w": [un.get("w")]}, "w", 1, nu, where + ".unstable_at")[0]
            if sum(w[i] * Pu[i][j] * w[j] for i in range(nu) for j in range(nu)) >= 0:
                return False, where + ".unstable_at: w^T P w >= 0", n, bits
            if not stein_shown(Pu, Mu):
                why = "at %s = %s (NOT stable): P - M^T P M not shown positive definite" % (p, short(hi))
                continue
        last_P_to = None  # the last interval's P_to (None: it had none)
        for i, piece in enumerate(cover):
            at = "%s.cover[%d]" % (where, i)
            if not isinstance(piece, dict):
                raise Malformed(at + ": not an object")
            only(piece, ("to", "P", "P_to"), at)
            to = exact(piece, "to", at)
            if to < start or (to == start and not (len(cover) == 1 and to == lo and "P_to" not in piece)):
                raise Malformed(at + ".to: not above the interval's start")
            if i + 1 == len(cover) and to != lo:
                raise Malformed(at + ".to: the last interval ends at claim.lo")
            if "P" not in piece:  # left out: the last interval's P_to (a chain of linear intervals names each node once)
                if "P_to" not in piece or last_P_to is None:
                    raise Malformed(at + ".P: missing (left out only in an interval with P_to after one with P_to)")
                P = last_P_to
            else:
                P = symmetric_evidence(piece, at, n)
                if not semidefinite(P, True):
                    return False, at + ".P is not positive definite", n, bits
            last_P_to = None
            if "P_to" in piece:  # P at start, P_to at to, linear between: the Bernstein test
                Pto = last_P_to = symmetric_evidence({"P": piece["P_to"]}, at + "(P_to)", n)
                if not semidefinite(Pto, True):
                    return False, at + ".P_to is not positive definite", n, bits
                if not bernstein_stein_shown(P, Pto, M_at(start), M_at(to)):
                    why, ok = "%s on [%s, %s] (P linear): a Bernstein coefficient of P(t) - M(t)^T P(t) M(t) not shown positive " \
                        "definite" % (at, short(start), short(to)), False
                    break
            else:
                for e in (start, to):
                    if not stein_shown(P, M_at(e)):
                        why, ok = "%s at %s = %s: P - M^T P M not shown positive definite" % (at, p, short(e)), False
                        break
            if not ok:
                break
            start = to
        if not ok:
            continue
        return True, "", n, bits
    return None, why, 0, 0


def check_stability_loop_max_symmetric(c):
    """stability-loop-max-symmetric (C++ check/stability_loop_max_symmetric_check.hpp): p the whole gain of
    [environment] (gain_block), so E(p) = p E(1); the loops read at p = 1 and 2 split by evidence.classes
    (split_loop: the invariance checked on each), each block's supremum evidence checked as stability-loop-max's
    (loop_max_part, the gain test on the block's realisations); every block stable on [0, lo] and one NOT stable at
    hi (hi = 0: one block, its M(0) with an eigenvalue outside the circle); the conserved quantities k_F + sum_a
    (k_a - 1) k_a'."""
    model, claim, evidence = parts(c)
    only(model, ("scene", "set", "name"), "model")
    only(claim, ("quantity", "status", "lo", "hi", "printed_lo", "printed_hi", "conserved"), "claim")
    only(evidence, ("classes", "blocks"), "evidence")
    if not isinstance(model.get("scene"), str):
        raise Malformed("model.scene: missing or not a string")
    p, sets, lo, hi, refuted = sup_model(model, claim)
    if refuted:
        return False, refuted
    if hi == 0 and "conserved" in claim:
        raise Malformed("claim.conserved: only with hi > 0 (sup = 0 is shown by one block)")
    k = claim.get("conserved", 0)
    if not isinstance(k, int) or isinstance(k, bool) or k < 0:
        raise Malformed("claim.conserved: not an integer >= 0")
    block, inside = gain_block(model["scene"], p)
    if block != "environment":
        raise Malformed("model.name: %r is the gain of [coupling]: beyond stability-loop-max-symmetric (the split compares the "
                        "environment only)" % p)
    splits = []
    for v in (1, 2) if not inside or hi == 0 else (1, 2, hi):
        m = dict({key: x for key, x in model.items() if key != "name"}, set=dict(sets))
        m["set"][p] = str(v)
        devices = scene_read(m, False, coupling=True, max_dofs=MAX_LOOP_SYMMETRIC_DOFS)[0].get("device")
        if isinstance(devices, list) and len(devices) > MAX_LOOP_SYMMETRIC_READ:
            raise TooLarge("model.scene: %d devices, above this checker's limit %d for stability-loop-max-symmetric" % (
                len(devices), MAX_LOOP_SYMMETRIC_READ))
        split = split_loop(scene_loop_read(m, MAX_LOOP_SYMMETRIC_DOFS), evidence.get("classes"))
        if isinstance(split, str):
            return False, "evidence.classes: at %s = %s, %s" % (p, short(Fraction(v)), split)
        splits.append(split)
    (fixed1, zero1, sizes), (fixed2, zero2, _) = splits[:2]
    classes = evidence["classes"]
    column, degree = affine_column_orders(model, "environment", p, sum(sizes)) if inside else (None, 0)
    blocks = evidence.get("blocks")
    needed = 1 + sum(1 for z in zero1 if z is not None)
    if not isinstance(blocks, list) or len(blocks) != (1 if hi == 0 else needed):
        raise Malformed("evidence.blocks: %s" % ("sup = 0 is shown by one block" if hi == 0 else
                                                "every block is needed: the fixed space and each class of two DOFs or more, %d" % needed))
    seen, total, unstable, said = set(), 0, 0, []
    for b, blk in enumerate(blocks):
        where = "evidence.blocks[%d]" % (b + 1)
        if not isinstance(blk, dict):
            raise Malformed(where + ": not an object")
        only(blk, ("space", "class", "conserved", "cover", "first_order", "unstable_at", "first_order_unstable", "no_crossing"), where)
        slot, copies, kb = block_slot(blk, zero1, sizes, seen, where)
        loops = [sp[0] if slot is None else sp[1][slot] for sp in splits]
        at_p = [loop_quotient_of(loop) for loop in loops]
        if inside:  # the block's realisation at 1, 2 (and hi) of its largest order: its columns', the whole's columns f_b
            order = sum(column[c[0]] for a, c in enumerate(classes) if slot is None or slot == a)
            if any(len(q[5][0][0]) != order for q in at_p):
                raise Malformed("%s: the block's realisation at %s = 1, 2 or %s is not of order %d (a pole cancelled there): beyond "
                                "this kind" % (where, p, short(hi), order))
        unstable += "unstable_at" in blk or "first_order_unstable" in blk
        ok, why, n, bits = loop_max_part(at_p, blk, lo, hi, kb, p, "environment", inside, where, need_unstable=False)
        if ok is None:
            return False, "claim: sup %s in [%s, %s], but %s (%s): %s at 512 bits" % (p, short(lo), short(hi), where, blk["space"], why)
        if not ok:
            return False, "%s (%s): %s" % (where, blk["space"], why)
        total += copies * kb
        said.append("%s%s: %d states, %d intervals%s (%d bits)" % (blk["space"], "" if slot is None else " of class %d (x%d)" % (slot, copies),
                                                                   n, len(blk.get("cover", [])), ", NOT stable at hi" if "unstable_at" in blk else
                                                                   ", NOT stable on (0, eps] (first-order mirror)" if "first_order_unstable" in blk else "", bits))
    if unstable != 1:
        raise Malformed("evidence.blocks: %d with unstable_at or first_order_unstable; exactly one block bounds sup from above" % unstable)
    if hi != 0 and total != k:
        return False, "claim: %d conserved quantities, but the blocks have %d (k_F + sum_a (k_a - 1) k_a')" % (k, total)
    head = "by the split of %d DOFs into %d classes of identical DOFs (invariance checked exactly at %s = 1 and 2; %s %s)" % (
        sum(sizes), len(sizes), p, p, "inside the environment's tf, each entry proven affine (degree bound %d)" % degree if inside
        else "the environment's gain alone")
    if hi == 0:
        return True, "sup %s = 0 %s: %s" % (p, head, "; ".join(said))
    return True, "sup %s in [%s, %s] %s: every block stable on [0, %s], one NOT stable at %s: %s" % (
        p, short(lo), short(hi), head, short(lo), short(hi), "; ".join(said))


def lagrange(xs, ys):
    """The polynomial of degree < len(xs) through (xs[k], ys[k]), ascending coefficients."""
    out = []
    for i, xi in enumerate(xs):
        basis, den = [Fraction(1)], Fraction(1)
        for j, xj in enumerate(xs):
            if j != i:
                basis = pmul(basis, [-xj, Fraction(1)])
                den *= xi - xj
        out = padd(out, pscale(basis, ys[i] / den))
    return out


def ss_transfer(A, B, C, D):
    """Z(s) = C (sI - A)^-1 B + D entry by entry as RFs: chi = det(sI - A) (Faddeev-LeVerrier) and
    chi (Z - D) = C adj(sI - A) B, of degree < n, interpolated at n integers where chi != 0."""
    n, m = len(A), len(D)
    chi = faddeev_leverrier(A)
    pts, vals = [], [[[] for _ in range(m)] for _ in range(m)]
    k = 0
    while len(pts) < n:
        s, k = Fraction(k), k + 1
        c = peval(chi, s)
        if c == 0:
            continue
        X = solve_shifted(A, B, s)
        pts.append(s)
        for i in range(m):
            for j in range(m):
                vals[i][j].append(c * sum(C[i][l] * X[l][j] for l in range(n)))
    return [[RF(padd(pscale(chi, D[i][j]), lagrange(pts, vals[i][j]) if n else []), chi) for j in range(m)] for i in range(m)]


def residue_fails(Z, q, at):
    """What shows Z not positive real at its axis pole s = j w0, w0 = sqrt(q) >= 0 (q rational), or "": each
    entry in lowest terms, the pole's order the multiplicity of f = s (q = 0) or s^2 + q in its denominator
    (>= 2 fails); for a simple pole R_ij = n(j w0)/d'(j w0) = X + j w0 Y, X and Y rational from the even and
    odd parts at -q; R not Hermitian, or [[X, -Y], [Y, X/q]] (congruent to [[X, -w0 Y], [w0 Y, X]]) not
    positive semidefinite, fails (check/operator_passivity_check.hpp)."""
    m = len(Z)
    f = [Fraction(0), Fraction(1)] if q == 0 else [q, Fraction(0), Fraction(1)]

    def parts(p):  # (E_p(-q), O_p(-q)): p(j w0) = E + j w0 O
        even = sum((p[k] * (-q) ** (k // 2) for k in range(0, len(p), 2)), Fraction(0))
        odd = sum((p[k] * (-q) ** (k // 2) for k in range(1, len(p), 2)), Fraction(0))
        return even, odd
    X = [[Fraction(0)] * m for _ in range(m)]
    Y = [[Fraction(0)] * m for _ in range(m)]
    for i in range(m):
        for j in range(m):
            n, d = trim(Z[i][j].num), trim(Z[i][j].den)
            g = pgcd(n, d) if n else [Fraction(1)]
            if len(g) > 1:
                n, d = pdivmod(n, g)[0], pdivmod(d, g)[0]
            order, e = 0, d
            while len(e) >= len(f):
                quo, rem = pdivmod(e, f)
                if trim(rem):
                    break
                e, order = quo, order + 1
            if order >= 2:
                return "entry (%d, %d) has a pole of order %d at %s" % (i + 1, j + 1, order, at)
            if order == 1:
                a, b = parts(n)
                c, e2 = parts(pderiv(d))
                den = c * c + q * e2 * e2
                X[i][j], Y[i][j] = (a * c + q * b * e2) / den, (b * c - a * e2) / den
    if any(X[i][j] != X[j][i] or (q != 0 and Y[i][j] != -Y[j][i]) for i in range(m) for j in range(i + 1)):
        return "its residue at %s is not Hermitian" % at
    E = X if q == 0 else ([X[i] + [-y for y in Y[i]] for i in range(m)] + [Y[i] + [x / q for x in X[i]] for i in range(m)])
    if not semidefinite(E, False):
        return "its residue at %s is not positive semidefinite" % at
    return ""


def check_operator_passivity(c):
    """Assumption 1(b) of paper 000 fails for the scene's operator claim.operator (a tf matrix in s): a
    positive real Z has He Z(jw) >= 0 at every real w that is not a pole, so the principal minor of He
    Z(jw) on evidence.minor (0-based rows) being < 0 at evidence.w, exactly in Q(j), with no entry's
    denominator 0 there, shows Z is not passive (check/operator_passivity_check.hpp). Or evidence.pole = w0
    (rational, >= 0) or pole_squared = w0^2 (> 0, w0 irrational too): Z's residue at its axis pole s = j w0 not
    Hermitian PSD, or a multiple pole there
    (residue_fails; an ss operator's entries formed exactly by ss_transfer)."""
    model, claim, evidence = parts(c)
    only(claim, ("quantity", "status", "operator", "passive"), "claim")
    at_pole = "pole" in evidence or "pole_squared" in evidence
    only(evidence, (("pole",) if "pole" in evidence else ("pole_squared",)) if at_pole else ("w", "minor"), "evidence")
    if claim.get("status") != "exact":
        raise Malformed("claim.status: missing or not \"exact\"")
    if not isinstance(claim.get("passive"), bool):
        raise Malformed("claim.passive: missing or not true/false")
    if claim["passive"]:
        raise Malformed("claim.passive: true has no certificate form here (only false, with a witness)")
    name = claim.get("operator")
    if not isinstance(name, str):
        raise Malformed("claim.operator: missing or not a string")
    ops = scene_loop_read(model)[6]
    root = scene_read(model, False, coupling=True)[0]
    named = [o.get("name") for o in root.get("operator", []) if "tf" in o or "ss" in o]
    at = [i for i, n in enumerate(named) if n == name]
    if len(at) != 1:
        raise Malformed("claim.operator: %s operator given by tf or ss named %r in the scene" % ("no" if not at else "more than one", name))
    Z = ops[at[0]][1]
    is_ss = Z[0] != "tf"
    Z = Z[1]
    q = len(Z[3]) if is_ss else len(Z)
    if at_pole:  # a positive real Z has only simple poles on the axis, with Hermitian PSD residues
        if "pole" in evidence:
            w0 = exact(evidence, "pole", "evidence")
            if w0 < 0:
                raise Malformed("evidence.pole: w0 >= 0 (the pole s = j w0; its conjugate's residue is the conjugate)")
            q, at = w0 * w0, "s = 0" if w0 == 0 else "s = j%s" % short(w0)
        else:  # w0 = sqrt(q), irrational ones too
            q = exact(evidence, "pole_squared", "evidence")
            if q <= 0:
                raise Malformed("evidence.pole_squared: w0^2 > 0 (the pole s = j sqrt(w0^2); s = 0 is pole = 0)")
            at = "s = j sqrt(%s)" % short(q)
        why = residue_fails(ss_transfer(*Z) if is_ss else Z, q, at)
        if why:
            return True, "operator %r is not passive: %s (Assumption 1(b) fails)" % (name, why)
        return False, "operator %r not passive not shown: at most a simple pole at %s with a Hermitian PSD residue" % (name, at)
    w = exact(evidence, "w", "evidence")
    rows = evidence.get("minor")
    if not isinstance(rows, list) or not rows or any(not isinstance(r, int) or isinstance(r, bool) or not 0 <= r < q for r in rows):
        raise Malformed("evidence.minor: not a non-empty array of integers in [0, %d)" % q)
    if any(rows[k] >= rows[k + 1] for k in range(len(rows) - 1)):
        raise Malformed("evidence.minor: rows not increasing")

    def at_jw(p):
        v = cq(0)
        for a in reversed(p):
            v = cq_add(cq_mul(v, (Fraction(0), w)), cq(a))
        return v
    Zj = [[None] * q for _ in range(q)]
    if is_ss:  # C (jwI - A)^-1 B + D as written, by elimination over Q(j)
        A, B, C, D = Z
        n = len(A)
        M = [[(-A[i][k], w if i == k else Fraction(0)) for k in range(n)] + [cq(B[i][j]) for j in range(q)] for i in range(n)]
        for k in range(n):
            p = next((r for r in range(k, n) if M[r][k] != (0, 0)), None)
            if p is None:
                return False, "Z(s) of %r (ss) has jwI - A singular at w = %s" % (name, short(w))
            M[k], M[p] = M[p], M[k]
            for i in range(n):
                if i != k and M[i][k] != (0, 0):
                    f = cq_div(M[i][k], M[k][k])
                    M[i] = [cq_sub(a, cq_mul(f, b)) for a, b in zip(M[i], M[k])]
        X = [[cq_div(M[k][n + j], M[k][k]) for j in range(q)] for k in range(n)]
        for i in range(q):
            for j in range(q):
                v = cq(D[i][j])
                for k in range(n):
                    v = cq_add(v, cq_mul(cq(C[i][k]), X[k][j]))
                Zj[i][j] = v
    for i in range(q):
        for j in range(q):
            if is_ss:
                continue
            d = at_jw(Z[i][j].den)
            if d == (0, 0):
                return False, "Z(s) of %r has a pole at s = jw, w = %s" % (name, short(w))
            Zj[i][j] = cq_div(at_jw(Z[i][j].num), d)
    H = [[((Zj[a][b][0] + Zj[b][a][0]) / 2, (Zj[a][b][1] - Zj[b][a][1]) / 2) for b in rows] for a in rows]
    m = cq_det(H)
    if m[1] != 0:
        raise AssertionError("a Hermitian minor is not real")
    which = ",".join(str(r + 1) for r in rows)
    if m[0] >= 0:
        return False, "operator %r not passive not shown: the principal minor {%s} of He Z(jw) at w = %s is %.12g >= 0" % (
            name, which, short(w), float(m[0]))
    return True, "operator %r is not passive: the principal minor {%s} of He Z(jw) at w = %s is %.12g < 0 (Assumption 1(b) fails)" % (
        name, which, short(w), float(m[0]))


def check_stability(c):
    model, claim, evidence = parts(c)
    model = scene_loop_model(model)
    only(model, ("plant", "H", "operator", "set", "T", "delay"), "model")
    only(claim, ("quantity", "status", "stable"), "claim")
    only(evidence, ("charpoly", "argument_principle"), "evidence")
    if "argument_principle" in evidence and evidence["argument_principle"] is not True:
        raise Malformed("evidence.argument_principle: not true")
    if "argument_principle" in evidence and "charpoly" in evidence:
        raise Malformed("evidence: both charpoly and argument_principle")
    T, n, params, k, Nd = loop_device(model, one_pole=True)
    if claim.get("status") not in ("exact", "certified"):
        raise Malformed("claim.status: missing or neither \"exact\" nor \"certified\"")
    if not isinstance(claim.get("stable"), bool):
        raise Malformed("claim.stable: missing or not true/false")
    if "argument_principle" in evidence:
        return check_stability_winding(model, claim, T, n, params, k, Nd)
    if isinstance(Nd, tuple) and Nd[0] == "spring":
        return check_stability_spring(model, claim, evidence, T, n, params, k, Nd)
    if isinstance(Nd, tuple):
        return check_stability_pole(model, claim, evidence, T, n, params, k, Nd)
    given = evidence.get("charpoly")
    if not isinstance(given, list) or not given:
        raise Malformed("evidence.charpoly: missing or not a non-empty list")
    given = trim([exact_value(v, "evidence.charpoly[%d]" % i) for i, v in enumerate(given)])
    H = loop_wall(model, T, params, n)
    degree = len(H.den) - 1 + n + k
    if degree > MAX_STABILITY_DEGREE:
        raise TooLarge("the characteristic polynomial has degree %d, above this checker's limit %d" % (degree, MAX_STABILITY_DEGREE))
    cpoly = loop_poly(n, k, Nd, H.num, H.den)
    if len(given) != len(cpoly):
        return False, "evidence.charpoly has degree %d, the loop as written %d" % (len(given) - 1, len(cpoly) - 1)
    ratio = given[-1] / cpoly[-1]
    for i, (g, x) in enumerate(zip(given, cpoly)):
        if g != ratio * x:
            return False, "evidence.charpoly is not the characteristic polynomial of the loop as written (z^%d: %s, expected %s)" % (
                i, short(g), short(ratio * x))
    ok, why = schur_cohn(cpoly)
    if ok != claim["stable"]:
        return False, "claim: %s, but %s" % ("stable" if claim["stable"] else "NOT stable", why)
    return True, "%s (degree %d; %s)" % ("stable" if ok else "NOT stable", len(cpoly) - 1, why)


def dc_zero(k, Nd, A, L):
    """With a device pole off s = 0 (Nd a pole_device or spring_device tuple): c(1) = 0 exactly? c(1)
    = F g, F = 1 - E or det(I - Phi) (no e^(pT) is 1, so F != 0) and g rational: k = 0, g = L(1) + A(1)
    (Ndp(1) - rho) with rho = r or R1 (N_q(1) = -R1 Delta(1)); k >= 1, g = A(1) Ndp(1)."""
    one = Fraction(1)
    Ndp, rho = (Nd[3], Nd[2][1]) if Nd[0] == "spring" else (Nd[2], Nd[1])
    if k > 0:
        return peval(A, one) * peval(Ndp, one) == 0
    return peval(L, one) + peval(A, one) * (peval(Ndp, one) - rho) == 0


def check_stability_spring(model, claim, evidence, T, n, params, k, spring):
    """A device with two poles off s = 0 (spring_device): Phi = e^(A_c T) is enclosed (expm_interval),
    c(z) in interval coefficients (spring_charpoly), and Schur-Cohn decided over the whole box
    (schur_cohn_interval), at 128 to 4096 bits until every step is decided: the verdict then holds
    for the true Phi, which the box holds."""
    if "charpoly" in evidence:
        raise Malformed("evidence.charpoly: the device has poles off s = 0: its coefficients are not rational")
    if claim["status"] != "certified":
        raise Malformed("claim.status: with device poles off s = 0 the verdict is \"certified\"")
    H = loop_wall(model, T, params, n)
    degree = len(H.den) + 1 + n + k
    if degree > MAX_STABILITY_MAX_DEGREE:
        raise TooLarge("the characteristic polynomial has degree %d, above this checker's limit %d with device poles off s = 0" % (
            degree, MAX_STABILITY_MAX_DEGREE))
    if dc_zero(k, spring, H.num, H.den):
        ok, why = False, "c(1) = 0 exactly (det(I - Phi) times a rational factor that is 0): a root on the unit circle"
        if ok != claim["stable"]:
            return False, "claim: stable, but " + why
        return True, "NOT stable (two device poles off s = 0; %s)" % why
    for bits in (128, 256, 512, 1024, 2048, 4096):
        c, Phi = spring_charpoly(n, k, spring, H.num, H.den, T, bits)
        if c[-1].lo <= 0 <= c[-1].hi:
            raise AssertionError("the leading coefficient's enclosure holds 0")
        decided = schur_cohn_interval(c)
        if decided is not None:
            break
    else:
        raise TooLarge("the loop is too close to its boundary: Schur-Cohn undecided on e^(A T)'s enclosure at 4096 bits")
    ok, why = decided
    why = "Phi = e^(A T) enclosed at %d bits (trace in [%.12g, %.12g]); %s" % (
        bits, float((Phi[0][0] + Phi[1][1]).lo), float((Phi[0][0] + Phi[1][1]).hi), why)
    if ok != claim["stable"]:
        return False, "claim: %s, but %s" % ("stable" if claim["stable"] else "NOT stable", why)
    return True, "%s (degree %d, two device poles off s = 0; %s)" % ("stable" if ok else "NOT stable", len(c) - 1, why)


def check_stability_pole(model, claim, evidence, T, n, params, k, pole):
    """A device with one pole p off s = 0: c(z; E) = z^n L (z-1)^k (z - E) + A (Ndp (z - E) + r (E - 1)(z-1)^k)
    = c0 + E c1, E = e^(pT) transcendental. D(E) = Res(c, c*) (resultant_in_K) has no root in an
    enclosure [lo, hi] of E (exp_interval, narrowed until so): no c(.; E) there has a root on the
    circle, the degree does not move (deg c1 < deg c0), so Schur-Cohn at E = lo decides for the true E.
    D = 0 identically: c and c* share a root for every E: NOT stable."""
    if "charpoly" in evidence:
        raise Malformed("evidence.charpoly: the device has a pole off s = 0: its coefficients are not rational")
    if claim["status"] != "certified":
        raise Malformed("claim.status: with a device pole off s = 0 the verdict is \"certified\"")
    p, r, Ndp = pole
    H = loop_wall(model, T, params, n)
    degree = len(H.den) + n + k
    if degree > MAX_STABILITY_MAX_DEGREE:
        raise TooLarge("the characteristic polynomial has degree %d, above this checker's limit %d with a device pole off s = 0" % (
            degree, MAX_STABILITY_MAX_DEGREE))
    A, L = H.num, H.den
    Dk = ppow([Fraction(-1), Fraction(1)], k)
    zLD = pmul([Fraction(0)] * n + L, Dk)
    rD = pscale(Dk, r)
    c0 = padd(pmul([Fraction(0), Fraction(1)], zLD), pmul(A, padd(pmul([Fraction(0), Fraction(1)], Ndp), pscale(rD, -1))))
    c1 = padd(pmul(A, padd(rD, pscale(Ndp, -1))), pscale(zLD, -1))
    c0, c1 = trim(c0), trim(c1)
    if len(c1) >= len(c0):
        raise Malformed("model: the E-part of c has degree >= that of c0")
    D = trim(resultant_in_K(c0, c1))
    if not D:
        ok, why = False, "c and c* share a root for every E (D = 0)"
    else:
        for bits in (128, 256, 512, 1024, 2048, 4096):
            lo, hi = exp_interval(p * T, bits)
            if peval(D, lo) != 0 and peval(D, hi) != 0 and positive_roots(pshift(D, lo), hi - lo, True) == 0:
                break
        else:
            raise TooLarge("the loop is too close to its boundary: e^(pT)'s enclosure at 4096 bits holds a root of D(E)")
        ok, why = schur_cohn(padd(c0, pscale(c1, lo)))
        why = "E = e^(%s) in [%.12g, %.12g], D(E) root-free there; %s" % (short(p * T), float(lo), float(hi), why)
    if ok != claim["stable"]:
        return False, "claim: %s, but %s" % ("stable" if claim["stable"] else "NOT stable", why)
    return True, "%s (degree %d, device pole %s; %s)" % ("stable" if ok else "NOT stable", len(c0) - 1, short(p), why)


# ---------------------------------------------------------------- stability-max
MAX_STABILITY_MAX_DEGREE = 40


def det_int(M):
    """The determinant of a square integer matrix (Bareiss' fraction-free elimination: every
    division exact)."""
    M = [list(r) for r in M]
    n, sign, prev = len(M), 1, 1
    for i in range(n - 1):
        piv = next((r for r in range(i, n) if M[r][i] != 0), None)
        if piv is None:
            return 0
        if piv != i:
            M[i], M[piv] = M[piv], M[i]
            sign = -sign
        for r in range(i + 1, n):
            for j in range(i + 1, n):
                M[r][j] = (M[r][j] * M[i][i] - M[r][i] * M[i][j]) // prev
        prev = M[i][i]
    return sign * M[n - 1][n - 1]


def reciprocal_resultant(c):
    """Res_{d,d}(c, c*), c* = z^d c(1/z), c of exact degree d: the Sylvester determinant of order 2d
    (d rows of c, d rows of c*, coefficients descending) = lc(c)^d prod_{c(a)=0} c*(a); computed on
    L c with integer coefficients (L the common denominator), divided by L^(2d)."""
    d = len(c) - 1
    L = 1
    for x in c:
        L = L * x.denominator // gcd(L, x.denominator)
    ci = [int(x * L) for x in c]
    desc = ci[::-1]  # c*'s descending coefficients are c's ascending ones
    rows = [[0] * i + desc + [0] * (d - 1 - i) for i in range(d)]
    rows += [[0] * i + ci + [0] * (d - 1 - i) for i in range(d)]
    return Fraction(det_int(rows), L ** (2 * d))


def resultant_in_K(c0, c1):
    """D(K) = Res_{d,d}(c0 + K c1, its reciprocal), of degree <= 2d in K (every Sylvester entry is
    affine in K): Lagrange interpolation of its values at K = -d .. d."""
    d = len(c0) - 1
    xs = [Fraction(i) for i in range(-d, d + 1)]
    D = []
    for xi in xs:
        v = reciprocal_resultant(padd(c0, pscale(c1, xi)))
        if v == 0:
            continue
        basis, den = [Fraction(1)], Fraction(1)
        for xj in xs:
            if xj != xi:
                basis = pmul(basis, [-xj, Fraction(1)])
                den *= xi - xj
        D = padd(D, pscale(basis, v / den))
    return D


def positive_roots(p, b, closed):
    """The number of distinct roots of p != 0 in (0, b), or (0, b] when closed; b None: (0, inf).
    Its roots at 0 and b divided out; Descartes' rule of signs when it shows none, else Sturm's
    theorem on the square-free part."""
    q = trim(p)
    while len(q) > 1 and q[0] == 0:
        q = q[1:]  # divided by K: the root at 0
    count = 0
    while b is not None and len(q) > 1 and peval(q, b) == 0:
        count = 1 if closed else 0
        q = pdivmod(q, [-b, Fraction(1)])[0]
    if len(q) < 2:
        return count
    # Descartes first (cheap): no sign variation in the coefficients of q(x) (roots in (0, inf)) or of
    # (1 + y)^n q(b/(1 + y)) (roots in (0, b), as y > 0) proves there is none
    n = len(q) - 1
    R = q if b is None else [sum(q[i] * b ** i * comb(n - i, j) for i in range(n - j + 1)) for j in range(n + 1)]
    signs = [x > 0 for x in R if x != 0]
    if all(u == v for u, v in zip(signs, signs[1:])):
        return count
    q = sqfree(q)  # Sturm counts the distinct roots of a square-free polynomial
    seq = sturm_seq(q)
    if b is None:
        signs = [x[-1] for x in seq if x]
        at_b = sum(1 for u, v in zip(signs, signs[1:]) if (u > 0) != (v > 0))
    else:
        at_b = variations(seq, b)
    return count + variations(seq, Fraction(0)) - at_b


def stability_family(model):
    """(K, T, n, k, Nd, H0, H1, Dbound, L, c0, c1): H = H0 + K H1 proven affine; with L = lcm of
    H0's and H1's denominators, c(z; K) = z^n L (z-1)^k + (A0 L/L0 + K A1 L/L1) Nd = c0 + K c1."""
    model = scene_loop_model(model, free=True)
    only(model, ("plant", "H", "operator", "set", "name", "T", "delay"), "model")
    K = parameter_name(model)
    T, n, params, k, Nd = loop_device(model)
    try:
        H0, H1, Dbound = prove_affine(model["H"], T, params, K)
    except ZeroDivisionError:
        raise Malformed("model.H: division by zero")
    for name, H in (("H0", H0), ("H1", H1)):
        if len(H.num) > len(H.den) + n:
            raise Malformed("model.H: z^-n %s(z) is not causal" % name)
    L = pmul(H0.den, pdivmod(H1.den, pgcd(H0.den, H1.den))[0])
    if len(L) - 1 + n + k > MAX_STABILITY_MAX_DEGREE:
        raise TooLarge("the characteristic polynomial has degree %d, above this checker's limit %d for stability-max" % (
            len(L) - 1 + n + k, MAX_STABILITY_MAX_DEGREE))
    c0 = loop_poly(n, k, Nd, pmul(H0.num, pdivmod(L, H0.den)[0]), L)
    c1 = pmul(pmul(H1.num, pdivmod(L, H1.den)[0]), Nd)
    if len(c1) >= len(c0):
        raise Malformed("model: c1 has degree >= that of c0 (the leading coefficient would move with %s)" % K)
    return K, T, n, k, Nd, H0, H1, Dbound, L, c0, c1


def check_stability_max(c):
    """K_max = sup{K0 > 0 : stable on (0, K0)} for the one-DOF loop with H = H0 + K H1: on an interval
    of K where D(K) = Res_z(c, c*) has no root, c(.; K) is stable at every K or at none (a root
    leaves the disc through the circle, where c and c* share it). K_max >= lo > 0: stable at
    stable_at in (0, lo), D root-free on (0, lo); K_max <= hi > 0: the loop at hi NOT stable;
    K_max = 0: NOT stable at unstable_at = e > 0 and D root-free on (0, e] (or D = 0); +inf: stable
    at stable_at > 0, D root-free on (0, inf)."""
    model, claim, evidence = parts(c)
    only(claim, ("quantity", "status", "infinite", "value", "lo", "hi", "printed", "printed_lo", "printed_hi"), "claim")
    only(evidence, ("stable_at", "unstable_at"), "evidence")
    K, T, n, k, Nd, H0, H1, Dbound, L, c0, c1 = stability_family(model)
    status, lo, hi, infinite, refuted = claim_range(claim, True)
    if refuted:
        return False, refuted
    if not infinite and lo < 0:
        return False, "claim: lo < 0 (K_max >= 0 by its definition)"
    zero = not infinite and hi == 0
    for key, wanted in (("stable_at", infinite or lo > 0), ("unstable_at", zero)):
        if key in evidence and not wanted:
            raise Malformed("evidence.%s: not read for this claim" % key)
    D = resultant_in_K(c0, c1)
    shown = []
    if infinite or lo > 0:
        K0 = exact(evidence, "stable_at", "evidence")
        if K0 <= 0 or (not infinite and K0 >= lo):
            return False, "evidence.stable_at = %s is not in (0, %s)" % (short(K0), "inf" if infinite else short(lo))
        ok, why = schur_cohn(padd(c0, pscale(c1, K0)))
        if not ok:
            return False, "%s_max >= lo fails: NOT stable at %s = %s: %s" % (K, K, short(K0), why)
        if not D:
            return False, "%s_max >= lo not shown: D = Res_z(c, c*) vanishes for every %s" % (K, K)
        m = positive_roots(D, None if infinite else lo, False)
        if m:
            return False, "%s_max >= lo not shown: D(%s) = Res_z(c, c*) has %d root(s) in (0, %s)" % (
                K, K, m, "inf" if infinite else "%.12g" % float(lo))
        shown.append("stable at %s = %s, D root-free on (0, %s)" % (K, short(K0), "inf" if infinite else "lo"))
    if infinite:
        return True, "%s_max = +inf (%s; degree %d in z)" % (K, shown[0], len(c0) - 1)
    if not zero:
        Hh = H0 + RF([hi]) * H1
        ok, why = schur_cohn(loop_poly(n, k, Nd, Hh.num, Hh.den))
        if ok:
            return False, "%s_max <= %.12g not shown: the loop at %s = hi is stable (%s)" % (K, float(hi), K, why)
        shown.append("NOT stable at %s = hi" % K)
    else:
        e = exact(evidence, "unstable_at", "evidence")
        if e <= 0:
            return False, "evidence.unstable_at = %s is not > 0" % short(e)
        ok, why = schur_cohn(padd(c0, pscale(c1, e)))
        if ok:
            return False, "%s_max = 0 not shown: c(z; %s = %s) is stable" % (K, K, short(e))
        if D:
            m = positive_roots(D, e, True)
            if m:
                return False, "%s_max = 0 not shown: D(%s) = Res_z(c, c*) has %d root(s) in (0, %s]" % (K, K, m, short(e))
        shown.append("NOT stable at %s = %s, %s" % (K, short(e), "D root-free on (0, e]" if D else "D = 0 identically"))
    return True, "%s_max %s (%s; degree %d in z)" % (
        K, ("= %s" % lo) if status == "exact" else "in [%.12g, %.12g]" % (float(lo), float(hi)), "; ".join(shown), len(c0) - 1)


# ---------------------------------------------------------------- wedge
def sqfree(p):
    return pdivmod(p, pgcd(p, pderiv(p)))[0] if len(p) > 2 else p


def roots_in(p, lo, hi, seq=None):
    """The number of distinct roots of p in (lo, hi) when p(lo), p(hi) != 0 (Sturm); seq: p's
    Sturm sequence of its square-free part, when the caller counts on many intervals."""
    if len(p) < 2:
        return 0
    seq = seq or sturm_seq(sqfree(p))
    return variations(seq, lo) - variations(seq, hi)


def max_positive(p1, p2, a, b, strict=True):
    """None when max(p1, p2) > 0 at every point of [a, b], else where not. The distinct roots of
    p1 p2 in (a, b) are isolated by bisection (Sturm); p1, p2 keep their signs between them, so
    the isolating intervals' ends test every cell; at a root, gcd(p1, p2) vanishing there means
    both are 0, else one is 0 and the other has the sign it has at the interval's end. strict=False:
    max(p1, p2) >= 0 (at a root one of them is 0, so only the open cells are tested, each at a point
    inside it: an end of [a, b] that is a root stands for no cell)."""
    def fails(x):
        v1, v2 = peval(p1, x), peval(p2, x)
        if (v1 > 0 or v2 > 0) if strict else (v1 >= 0 or v2 >= 0):
            return None
        return ("not > 0 at u = %s" if strict else "< 0 at u = %s") % short(x)
    for x in (a, b):
        if fails(x):
            return fails(x)
    if not strict and (not p1 or not p2):
        return None  # max(0, p) >= 0
    R = sqfree(p2 if not p1 else p1 if not p2 else pmul(p1, p2))
    for e in (a, b):
        while len(R) > 1 and peval(R, e) == 0:
            R = pdivmod(R, [-e, Fraction(1)])[0]
    if len(R) < 2:
        return None if strict else fails((a + b) / 2)  # one sign on (a, b): an end that is a root stands for none
    g = pgcd(p1, p2) if p1 and p2 else []
    seq_R = sturm_seq(R)  # R is square-free: one sequence for every interval of the bisection
    stack = [(a, b)]
    while stack:
        lo, hi = stack.pop()
        for x in (lo, hi):
            if fails(x):
                return fails(x)
        n = roots_in(R, lo, hi, seq_R)
        # non-strict: an end that is a root of p1 p2 passes by itself and stands for no cell, so
        # every cell is sampled inside it (a piece without roots at its midpoint)
        if n == 0:
            if not strict and fails((lo + hi) / 2):
                return fails((lo + hi) / 2)
            continue
        if n == 1 and not strict and peval(p1, lo) * peval(p2, lo) != 0 and peval(p1, hi) * peval(p2, hi) != 0:
            continue
        if n == 1 and strict:
            where = "a root in (%.12g, %.12g)" % (float(lo), float(hi))
            if not p1 or not p2:
                return "max = 0 at " + where
            if len(g) > 1 and roots_in(g, lo, hi) == 1:
                return "both are 0 at " + where
            other = p2 if roots_in(p1, lo, hi) == 1 else p1
            if peval(other, lo) < 0:
                return "one is 0 and the other < 0 at " + where
            continue
        mid = (lo + hi) / 2
        while peval(R, mid) == 0:
            mid = (mid + hi) / 2
        stack += [(lo, mid), (mid, hi)]
    return None


def wedge_polys(H):
    """(Gr, Jt, F) in u = tan^2(theta/2): with t = tan(theta/2), z = (1+jt)/(1-jt), d = deg D,
    N~ = N(z)(1-jt)^d, D~ likewise, G = N~ conj(D~) = Gr + j Gi: Re H = Gr/F, Im H/t = Jt/F with
    Jt = Gi/t, F = |D~|^2 (Gr, F even and Gi odd in t: polynomials in u = t^2)."""
    d = len(H.den) - 1
    def cmul(x, y):
        return (psub(pmul(x[0], y[0]), pmul(x[1], y[1])), padd(pmul(x[0], y[1]), pmul(x[1], y[0])))
    plus, minus = ([Fraction(1)], [Fraction(0), Fraction(1)]), ([Fraction(1)], [Fraction(0), Fraction(-1)])
    def tilde(coeffs):
        re, im = [], []
        for k, a in enumerate(coeffs):
            x = ([Fraction(1)], [])
            for _ in range(k):
                x = cmul(x, plus)
            for _ in range(d - k):
                x = cmul(x, minus)
            re, im = padd(re, pscale(x[0], a)), padd(im, pscale(x[1], a))
        return re, im
    Nr, Ni = tilde(H.num)
    Dr, Di = tilde(H.den)
    Gr = padd(pmul(Nr, Dr), pmul(Ni, Di))
    Gi = psub(pmul(Ni, Dr), pmul(Nr, Di))
    F = padd(pmul(Dr, Dr), pmul(Di, Di))
    if any(x != 0 for x in Gr[1::2] + F[1::2] + Gi[0::2]):
        raise AssertionError("parity in t")
    return Gr[0::2], Gi[1::2], F[0::2]


def cauchy_bound(polys):
    b = Fraction(1)
    for p in polys:
        if len(p) > 1:
            b = max(b, 1 + max(abs(x) for x in p[:-1]) / abs(p[-1]))
    return b


def check_wedge(c):
    model, claim, evidence = parts(c)
    only(evidence, ("wedge_witness_c", "tsypkin_witness_c"), "evidence")
    only(model, ("H", "set", "num", "den", "T"), "model")
    only(claim, ("quantity", "status", "wedge", "tsypkin", "h_stable", "closed_loop_stable", "dc_gain_nonnegative",
                 "wedge_margin", "tsypkin_margin", "wedge_gain", "tsypkin_gain"), "claim")
    if claim.get("status") != "exact":
        raise Malformed("claim.status: missing or not \"exact\"")
    H, T = model_h(model)
    if len(H.num) > len(H.den):
        raise Malformed("model.H: not causal (deg num > deg den)")
    N, D = H.num, H.den
    if not N:
        N = []
    Gr, Jt, F = wedge_polys(H)
    bound = cauchy_bound([F, padd(Gr, F), padd(padd(Gr, Jt), F), psub(padd(Gr, F), Jt)])
    zero = Fraction(0)
    if max_positive(F, F, zero, bound) or peval(D, Fraction(-1)) == 0:
        raise Malformed("model.H: H has a pole on the unit circle: the criteria are not evaluated")
    h_m1 = peval(N, Fraction(-1)) / peval(D, Fraction(-1))  # theta = pi (u = inf): J = 0 there
    facts = []
    why = max_positive(padd(padd(Gr, Jt), F), padd(psub(Gr, Jt), F), zero, bound)
    if why is None and h_m1 + 1 <= 0:
        why = "H(-1) + 1 <= 0 at theta = pi"
    facts.append(("wedge", why is None, "(25) " + ("holds" if why is None else "fails: " + why)))
    why = max_positive(padd(Gr, F), padd(Gr, F), zero, bound)
    if why is None and h_m1 + 1 <= 0:
        why = "H(-1) + 1 <= 0 at theta = pi"
    facts.append(("tsypkin", why is None, "(21) " + ("holds" if why is None else "fails: " + why)))
    ok, why = schur_cohn(D)
    facts.append(("h_stable", ok, "H stable: " + why))
    cl = padd(D, N)
    ok, why = schur_cohn(cl) if cl else (False, "D + N = 0")
    facts.append(("closed_loop_stable", ok, "(1 + H)^-1 stable: " + why))
    d1 = peval(D, Fraction(1))
    dc = d1 != 0 and peval(N, Fraction(1)) / d1 >= 0
    facts.append(("dc_gain_nonnegative", dc, "H(1) infinite" if d1 == 0 else "H(1) = %s" % short(peval(N, Fraction(1)) / d1)))
    for key, truth, why in facts:
        v = claim.get(key)
        if not isinstance(v, bool):
            raise Malformed("claim.%s: missing or not true/false" % key)
        if v != truth:
            return False, "claim.%s = %s, but %s" % (key, "true" if v else "false", why)
    shown = "; ".join(w for _, _, w in facts)
    for key, p1, p2 in (("wedge", padd(Gr, Jt), psub(Gr, Jt)), ("tsypkin", Gr, Gr)):
        why = wedge_margins(claim, evidence, key, p1, p2, F, h_m1)
        if why:
            return False, why
    return True, shown


def margin_between(p1, p2, F, h_m1, lo, hi, c0):
    """None when mu = min over theta in [0, pi] of max(p1, p2)/F + 1 (u = tan^2(theta/2) in [0, inf),
    and H(-1) + 1 at theta = pi) is >= lo (max(p1 + (1 - lo) F, p2 + (1 - lo) F) >= 0 on [0, inf),
    non-strict, and H(-1) + 1 >= lo) and, when hi is given, <= hi at the witness c0 = cos(theta0);
    else what failed."""
    if lo is not None:
        q1, q2 = padd(p1, pscale(F, 1 - lo)), padd(p2, pscale(F, 1 - lo))
        why = max_positive(q1, q2, Fraction(0), cauchy_bound([q1, q2]), strict=False)
        if why is None and h_m1 + 1 < lo:
            why = "H(-1) + 1 < lo at theta = pi"
        if why:
            return "min >= %.12g fails: %s" % (float(lo), why)
    if hi is None:
        return None
    if c0 < -1 or c0 > 1:
        return "the witness c0 = %s is outside [-1, 1]" % short(c0)
    if c0 == -1:
        v = h_m1 + 1
    else:
        u = (1 - c0) / (1 + c0)
        v = max(peval(p1, u), peval(p2, u)) / peval(F, u) + 1
    if v > hi:
        return "min <= %.12g not shown: the left side + 1 at the witness c0 = %s is %.12g" % (float(hi), short(c0), float(v))
    return None


def margin_bounds(claim, field, gain):
    """(lo, hi, infinite, refuted) of claim.<field>: {lo, hi, printed} (printed: both ends round to it)
    or, for a gain, {infinite: true}."""
    o = claim.get(field)
    if not isinstance(o, dict):
        raise Malformed("claim.%s: not an object" % field)
    if gain and "infinite" in o:
        only(o, ("infinite",), "claim." + field)
        if o["infinite"] is not True:
            raise Malformed("claim.%s.infinite: not true" % field)
        return None, None, True, None
    only(o, ("lo", "hi", "printed"), "claim." + field)
    lo, hi = exact(o, "lo", "claim." + field), exact(o, "hi", "claim." + field)
    if gain and lo <= 0:
        raise Malformed("claim.%s.lo: a gain k* is > 0" % field)
    if lo > hi:
        return lo, hi, False, "claim.%s: lo > hi" % field
    if "printed" in o:
        t = o["printed"]
        a, b = (half_unit_close(t, lo), half_unit_close(t, hi)) if isinstance(t, str) else (None, None)
        if a is None or b is None:
            raise Malformed("claim.%s.printed: not a decimal" % field)
        if not (a and b):
            return lo, hi, False, "claim.%s.printed = %s is not what both ends round to" % (field, t)
    return lo, hi, False, None


def wedge_margins(claim, evidence, key, p1, p2, F, h_m1):
    """claim.<key>_margin in [lo, hi] and claim.<key>_gain: k* = 1/(1 - mu) (k H meets the criterion
    iff k (mu - 1) + 1 > 0 at every theta), so k* >= lo iff mu >= 1 - 1/lo, k* <= hi iff
    mu <= 1 - 1/hi, +inf iff mu >= 1. None when every claim present holds."""
    wkey = key + "_witness_c"
    c0 = exact(evidence, wkey, "evidence") if wkey in evidence else None
    def witness():
        if c0 is None:
            raise Malformed("evidence.%s: missing" % wkey)
        return c0
    readers = 0
    if key + "_margin" in claim:
        lo, hi, _, refuted = margin_bounds(claim, key + "_margin", False)
        if refuted:
            return refuted
        readers += 1
        why = margin_between(p1, p2, F, h_m1, lo, hi, witness())
        if why:
            return "claim.%s_margin: %s" % (key, why)
    if key + "_gain" in claim:
        lo, hi, infinite, refuted = margin_bounds(claim, key + "_gain", True)
        if refuted:
            return refuted
        if infinite:
            why = margin_between(p1, p2, F, h_m1, Fraction(1), None, None)
        else:
            readers += 1
            why = margin_between(p1, p2, F, h_m1, 1 - 1 / lo, 1 - 1 / hi, witness())
        if why:
            return "claim.%s_gain: %s" % (key, why)
    if c0 is not None and not readers:
        raise Malformed("evidence.%s: no claim reads it" % wkey)
    return None


# ---------------------------------------------------------------- limit-cycle
MAX_LC_STEPS = 40000  # P n: the recursion's exact fractions grow with P (beyond: exit 3)


def lure_loop(model):
    """(N, D, k, rho, beta, n) of paper 002's loop (4) y = -k H x, x = max(y, -rho): H = N/D reduced,
    D monic of degree n >= 1, N padded to n + 1 coefficients, beta = k n_n = k H(inf), 1 + beta > 0."""
    only(model, ("H", "set", "num", "den", "T", "gain", "rho"), "model")
    H, _ = model_h(model)
    if len(H.num) > len(H.den):
        raise Malformed("model.H: not causal (deg num > deg den)")
    n = len(H.den) - 1
    if n < 1:
        raise Malformed("model.H: H is a constant: the loop has no state")
    k, rho = exact(model, "gain", "model"), exact(model, "rho", "model")
    if k < 0:
        raise Malformed("model.gain: must be >= 0")
    if rho <= 0:
        raise Malformed("model.rho: must be > 0")
    N = list(H.num) + [Fraction(0)] * (n + 1 - len(H.num))
    beta = k * N[n]
    if 1 + beta <= 0:
        raise Malformed("model: 1 + k H(inf) <= 0: the algebraic loop has no unique solution")
    return N, list(H.den), k, rho, beta, n


def lc_next(loop, w):
    """The output after the window w (n outputs): D(z) y = -k N(z) x solved for the new y, which is
    a/(1 + beta) in contact (>= -rho) and a + beta rho out of it (< -rho): exactly one holds."""
    N, D, k, rho, beta, n = loop
    a = -sum(D[i] * w[i] + k * N[i] * max(w[i], -rho) for i in range(n))
    y = a / (1 + beta)
    return y if y >= -rho else a + beta * rho


def half_unit_close(text, x):
    """|text - x| <= half a unit in the last digit of the decimal `text`; None when not a decimal."""
    m = re.fullmatch(r"-?([0-9]+)(?:\.([0-9]+))?(?:[eE]([+-]?[0-9]{1,4}))?", text)
    if not m:
        return None
    unit = Fraction(10) ** (int(m.group(3) or 0) - len(m.group(2) or ""))
    return 2 * abs(Fraction(TextFraction(text)) - x) <= unit


def lc_monodromy(loop, y, P):
    """J = C_{P-1} ... C_0, C_j the Jacobian of the window map at step j (a companion matrix whose
    last row is -(D_i + k N_i chi_{j+i})/(1 + beta chi_{j+n}), chi = [y > -rho])."""
    N, D, k, rho, beta, n = loop
    J = [[Fraction(int(i == j)) for j in range(n)] for i in range(n)]
    for j in range(P):
        last = [-(D[i] + (k * N[i] if y[j + i] > -rho else 0)) / (1 + (beta if y[j + n] > -rho else 0)) for i in range(n)]
        J = J[1:] + [[sum(last[i] * J[i][c] for i in range(n)) for c in range(n)]]
    return J


def check_limit_cycle(c):
    model, claim, evidence = parts(c)
    only(evidence, ("y",), "evidence")
    only(claim, ("quantity", "status", "period", "amplitude", "printed_amplitude", "free_steps", "attracting"), "claim")
    if claim.get("status") != "exact":
        raise Malformed("claim.status: missing or not \"exact\"")
    loop = lure_loop(model)
    n, rho = loop[5], loop[3]
    P, free_claimed = claim.get("period"), claim.get("free_steps")
    for key, v, lo in (("period", P, 1), ("free_steps", free_claimed, 0)):
        if not isinstance(v, int) or isinstance(v, bool) or v < lo or v > 100000:
            raise Malformed("claim.%s: missing, not an integer or outside [%d, 100000]" % (key, lo))
    amplitude = exact(claim, "amplitude", "claim")
    printed = claim.get("printed_amplitude")
    if not isinstance(printed, str) or half_unit_close(printed, amplitude) is None:
        raise Malformed("claim.printed_amplitude: missing or not a decimal")
    attracting = claim.get("attracting")
    if "attracting" in claim and not isinstance(attracting, bool):
        raise Malformed("claim.attracting: not true/false")
    ys = evidence.get("y")
    if not isinstance(ys, list) or len(ys) != n:
        raise Malformed("evidence.y: missing, not an array or not n = %d outputs (the order of H)" % n)
    y = [exact_value(v, "evidence.y[%d]" % i) for i, v in enumerate(ys)]
    if P * n > MAX_LC_STEPS:
        raise TooLarge("period x order = %d above this checker's limit %d" % (P * n, MAX_LC_STEPS))
    for j in range(P):
        y.append(lc_next(loop, y[j:j + n]))
    for i in range(n):
        if y[P + i] != y[i]:
            return False, "the state does not repeat: y_%d != y_%d (the recursion of (4) from evidence.y)" % (P + i, i)
    m, p = P, 2
    while m > 1:
        if m % p == 0:
            while m % p == 0:
                m //= p
            d = P // p
            if all(y[i + d] == y[i] for i in range(P - d)):
                return False, "claim.period = %d is not the least period: y repeats after %d" % (P, d)
        p += 1
    orbit = y[:P]
    amp = (max(orbit) - min(orbit)) / 2
    if amp != amplitude:
        return False, "claim.amplitude is not (max - min)/2 of y over the orbit, %s" % short(amp)
    if not half_unit_close(printed, amp):
        return False, "claim.printed_amplitude = %s is not the amplitude rounded" % printed
    free = sum(1 for v in orbit if v < -rho)
    if free != free_claimed:
        return False, "claim.free_steps = %d, but %d samples per period have y < -rho" % (free_claimed, free)
    why = "periodic orbit of least period %d, amplitude %s, %d samples out of contact" % (P, short(amp), free)
    if attracting is not None:
        if any(v == -rho for v in orbit):
            raise Malformed("claim.attracting: a sample lies on y = -rho (the map is only piecewise affine there)")
        ok, sc = schur_cohn(faddeev_leverrier(lc_monodromy(loop, y, P)))
        if ok != attracting:
            return False, "claim.attracting = %s, but the monodromy matrix: %s" % ("true" if attracting else "false", sc)
        why += "; %s (monodromy: %s)" % ("attracting" if ok else "not attracting", sc)
    return True, why


# ---------------------------------------------------------------- multidof-witness
MAX_WITNESS_DOFS = 64  # m: m^2 entries parsed and evaluated exactly in fractions


def env_entries(model, T, params, max_dofs=None):
    """E(z) as written, each entry a rational function of z: an s-domain entry parsed with s itself
    the rational function (z - 1)/(T z) (backward Euler) or 2(z - 1)/(T (z + 1)) (Tustin), so the
    substitution is done symbolically here (hapstab's checker evaluates N(s)/D(s) homogeneously)."""
    env = model.get("environment")
    if not isinstance(env, dict):
        raise Malformed("model.environment: missing or not an object")
    only(env, ("domain", "method", "gain", "E", "ss", "perturb_C"), "model.environment")
    domain = env.get("domain")
    if domain not in ("z", "s"):
        raise Malformed("model.environment.domain: must be \"z\" or \"s\"")
    if domain == "s":
        method = env.get("method")
        if method == "backward_euler":
            sub = RF([Fraction(-1), Fraction(1)], [Fraction(0), T])
        elif method == "tustin":
            sub = RF([Fraction(-2), Fraction(2)], [T, T])
        else:
            raise Malformed("model.environment.method: must be \"backward_euler\" or \"tustin\" with domain \"s\"")
        leaf = lambda kind, txt, value: sub if kind == 'var' else RF([value])
    else:
        if "method" in env:
            raise Malformed("model.environment.method: only with domain \"s\"")
        leaf = None
    g = exact(env, "gain", "model.environment")
    if ("E" in env) == ("ss" in env):
        raise Malformed("model.environment: exactly one of E (the entries as written) and ss (the realisation as written)")
    limit = max_dofs or MAX_WITNESS_DOFS
    if "ss" in env:
        out = ss_environment(env["ss"], sub if domain == "s" else None, limit)
        return perturbed(env, out), g
    E = env.get("E")
    if not isinstance(E, list) or not E or len(E) > limit:
        if isinstance(E, list) and len(E) > limit:
            raise TooLarge("model.environment.E: %d DOFs, above this checker's limit of %d" % (len(E), limit))
        raise Malformed("model.environment.E: must be an m x m array of strings")
    m = len(E)
    parsed = {}  # a compact scene written out repeats a few entries m^2 times
    out = []
    for i, row in enumerate(E):
        if not isinstance(row, list) or len(row) != m:
            raise Malformed("model.environment.E[%d]: a row of %d strings" % (i, m))
        out.append([])
        for j, e in enumerate(row):
            where = "model.environment.E[%d][%d]" % (i, j)
            if not isinstance(e, str):
                raise Malformed(where + ": not a string")
            try:
                if e not in parsed:
                    if leaf is not None:  # the poles it cancels, in s (the substitution's own z^k or (z + 1)^k aside)
                        parse_h(e, T, params, var=domain, field=where)
                    parsed[e] = parse_h(e, T, params, var=domain, field=where, leaf=leaf)
                out[-1].append(parsed[e])
            except ZeroDivisionError:
                raise Malformed(where + ": division by zero")
    return perturbed(env, out), g


MAX_SS_ENVIRONMENT_STATES = 64  # Faddeev-LeVerrier and n solves in fractions


def ss_environment(ss, s_of_z, limit):
    """E = C (xI - A)^-1 B + D of model.environment.ss {A, B, C, D} as written (N >= 1 states, m x m), entry by
    entry as rational functions of z: ss_transfer's in x, and for domain "s" (s_of_z the method's s as a
    rational function of z) each entry's numerator and denominator evaluated at s(z) by Horner."""
    if not isinstance(ss, dict):
        raise Malformed("model.environment.ss: must be an object {A, B, C, D}")
    only(ss, ("A", "B", "C", "D"), "model.environment.ss")
    A = ss.get("A")
    D = ss.get("D")
    if not isinstance(A, list) or not A or not isinstance(D, list) or not D:
        raise Malformed("model.environment.ss: A and D must be non-empty matrices")
    N, m = len(A), len(D)
    if N > MAX_SS_ENVIRONMENT_STATES or m > limit:
        raise TooLarge("model.environment.ss: %d states and %d DOFs, above this checker's limits %d and %d"
                       % (N, m, MAX_SS_ENVIRONMENT_STATES, limit))
    where = "model.environment.ss"
    A, B, C, D = (frac_matrix(ss, k, r, c, where) for k, r, c in (("A", N, N), ("B", N, m), ("C", m, N), ("D", m, m)))
    E = ss_transfer(A, B, C, D)
    if s_of_z is None:
        return E

    def at_sub(p):
        r = RF([])
        for c in reversed(p):
            r = r * s_of_z + RF([c])
        return r
    return [[at_sub(h.num) / at_sub(h.den) for h in row] for row in E]


def perturbed(env, out):
    """E' = Pi (E - E(inf)) + E(inf) with model.environment.perturb_C = Pi, else E."""
    m = len(out)
    if "perturb_C" in env:  # paper 000 Sec. VI: C_E := Pi C_E, D_E unchanged, so E' = Pi (E - D) + D, D = E(inf)
        Pi = env["perturb_C"]
        if not isinstance(Pi, list) or len(Pi) != m or any(not isinstance(r, list) or len(r) != m for r in Pi):
            raise Malformed("model.environment.perturb_C: must be %d x %d \"p/q\" strings" % (m, m))
        Pi = [[exact_value(x, "model.environment.perturb_C[%d][%d]" % (i, j)) for j, x in enumerate(r)] for i, r in enumerate(Pi)]
        D = []
        for i in range(m):
            D.append([])
            for j in range(m):
                h = out[i][j]  # as a rational function of z: its limit at z = inf
                if len(h.num) > len(h.den):
                    raise Malformed("model.environment.E[%d][%d]: not proper (E(inf) is needed by perturb_C)" % (i, j))
                D[-1].append(h.num[-1] / h.den[-1] if h.num and len(h.num) == len(h.den) else Fraction(0))
        out = [[sum((RF([Pi[i][k]]) * (out[k][j] - RF([D[k][j]])) for k in range(m) if Pi[i][k] != 0), RF([D[i][j]]))
                for j in range(m)] for i in range(m)]
    return out


def rf_at(h, z):
    """h(z) for a Gaussian rational z, or None at a pole."""
    def horner(p):
        r = cq(0)
        for c in reversed(p):
            r = cq_add(cq_mul(r, z), cq(c))
        return r
    d = horner(h.den)
    if d == (0, 0):
        return None
    return cq_div(horner(h.num), d)


def witness_levels(model, m):
    devs = model.get("devices")
    if not isinstance(devs, list) or not devs:
        raise Malformed("model.devices: missing or not a non-empty array")
    delta = []
    for d, dev in enumerate(devs):
        where = "model.devices[%d]" % d
        if not isinstance(dev, dict):
            raise Malformed(where + ": not an object")
        only(dev, ("dofs", "m", "b", "osp"), where)
        k = dev.get("dofs")
        if not isinstance(k, int) or isinstance(k, bool) or k < 1:
            raise Malformed(where + ".dofs: missing or not a positive integer")
        if "osp" in dev:
            if "m" in dev or "b" in dev:
                raise Malformed(where + ": osp beside m, b")
            level = exact(dev, "osp", where)
        else:
            if k != 1:
                raise Malformed(where + ": a mass-damper has one DOF")
            if exact(dev, "m", where) <= 0:
                raise Malformed(where + ".m: must be > 0")
            level = exact(dev, "b", where)  # Re(1/G(jw)) = Re(m jw + b) = b
        delta += [level] * k
        if len(delta) > m:
            break
    if len(delta) != m:
        raise Malformed("model.devices: their DOFs do not add up to E's %d" % m)
    return delta


def operator_owner(model, m):
    """The operator of every DOF (each DOF in exactly one of model.operators)."""
    ops = model.get("operators")
    if not isinstance(ops, list) or not ops:
        raise Malformed("model.operators: missing or not a non-empty array")
    owner = [None] * m
    for o, dofs in enumerate(ops):
        if not isinstance(dofs, list) or not dofs:
            raise Malformed("model.operators[%d]: a non-empty array of DOF indices" % o)
        for v in dofs:
            if not isinstance(v, int) or isinstance(v, bool) or not 0 <= v < m or owner[v] is not None:
                raise Malformed("model.operators[%d]: %r is not a free DOF index in [0, %d)" % (o, v, m))
            owner[v] = o
    if None in owner:
        raise Malformed("model.operators: DOF %d has no operator" % owner.index(None))
    return owner


MAX_FEASIBLE_ORDER = 80  # N + m: exact elimination in fractions on matrices of that order (~11 s at 74)


def frac_matrix(ev, key, rows, cols, where="evidence"):
    M = ev.get(key)
    if not isinstance(M, list) or len(M) != rows or any(not isinstance(r, list) or len(r) != cols for r in M):
        raise Malformed("%s.%s: must be %d x %d \"p/q\" strings" % (where, key, rows, cols))
    return [[exact_value(x, "%s.%s[%d][%d]" % (where, key, i, j)) for j, x in enumerate(r)] for i, r in enumerate(M)]


def semidefinite(M, strict):
    """Positive (semi)definite by symmetric elimination: no negative pivot; a zero pivot has a zero row
    (and is refused when strict). Strict: Sylvester's criterion, every leading principal minor > 0, the
    minors by Bareiss's fraction-free elimination on M scaled to integers (step k's pivot is the k-th leading
    minor times den^k, each division exact by Sylvester's identity), no gcd on the way."""
    if strict:
        den = 1
        for row in M:
            for x in row:
                d = Fraction(x).denominator
                den = den * d // gcd(den, d)
        A = [[Fraction(x).numerator * (den // Fraction(x).denominator) for x in row] for row in M]
        n, prev = len(A), 1
        for k in range(n):
            p, Ak = A[k][k], A[k]
            if p <= 0:
                return False
            for i in range(k + 1, n):
                Ai, f = A[i], A[i][k]
                for j in range(k + 1, n):
                    Ai[j] = (p * Ai[j] - f * Ak[j]) // prev
            prev = p
        return True
    M = [list(r) for r in M]
    n = len(M)
    for k in range(n):
        p = M[k][k]
        if p < 0 or (strict and p == 0):
            return False
        if p == 0:
            if any(M[k][j] != 0 for j in range(k + 1, n)):
                return False
            continue
        for i in range(k + 1, n):
            if M[i][k] != 0:
                f = M[i][k] / p
                for j in range(k + 1, n):
                    M[i][j] -= f * M[k][j]
    return True


def mmul(A, B):
    return [[sum((a * B[l][j] for l, a in enumerate(row) if a), Fraction(0)) for j in range(len(B[0]) if B else 0)] for row in A]


def mT(A):
    return [list(r) for r in zip(*A)] if A else []


def msum(A, B, s=1):
    return [[a + s * b for a, b in zip(ra, rb)] for ra, rb in zip(A, B)]


def solve_shifted(A, B, z):
    """(zI - A)^-1 B in fractions, or None when singular."""
    n, m = len(A), len(B[0]) if B else 0
    M = [[(z if i == j else 0) - A[i][j] for j in range(n)] + list(B[i]) for i in range(n)]
    for k in range(n):
        p = next((r for r in range(k, n) if M[r][k] != 0), None)
        if p is None:
            return None
        M[k], M[p] = M[p], M[k]
        for i in range(n):
            if i != k and M[i][k] != 0:
                f = M[i][k] / M[k][k]
                M[i] = [a - f * b for a, b in zip(M[i], M[k])]
    return [[M[i][n + j] / M[i][i] for j in range(m)] for i in range(n)]


def feasible_point(E, g, T, n, delta, owner, ev, where, g_at_least_one):
    """(True, how many points compared) when the point `ev` (A, B, C, D, P, X, Q_E, Q_V, named `where`)
    holds: (A, B, C, D) realises E-hat = T z/(z-1) z^-n g E(z) of the m x m rational functions E (equal at
    N + n + d + 2 integer points: the cross-multiplied difference has degree <= N + n + d + 1), P > 0,
    M1 <= 0, (14) > 0, Q_V > 0, X = diag(g), one g per operator, g >= 1 (g > 0 for a block of the split);
    else (False, what fails)."""
    m = len(E)
    if not isinstance(ev, dict):
        raise Malformed(where + ": missing or not an object")
    only(ev, ("A", "B", "C", "D", "P", "X", "Q_E", "Q_V"), where)
    Araw = ev.get("A")
    if not isinstance(Araw, list):
        raise Malformed(where + ".A: missing or not a matrix")
    N = len(Araw)
    if N + m > MAX_FEASIBLE_ORDER:
        raise TooLarge("%s.A: order %d with m = %d, above this checker's limit N + m <= %d" % (where, N, m, MAX_FEASIBLE_ORDER))
    mat = lambda k, r, cols: frac_matrix(ev, k, r, cols, where)
    A, B, C, D = mat("A", N, N), mat("B", N, m), mat("C", m, N), mat("D", m, m)
    P, X, QE, QV = mat("P", N, N), mat("X", m, m), mat("Q_E", m, m), mat("Q_V", m, m)
    d = max(h.degree() for row in E for h in row)
    need, agreed, z = N + n + d + 2, 0, 1
    while agreed < need and z < 2 + 4 * need + 64:
        z += 1
        Y = solve_shifted(A, B, Fraction(z))
        if Y is None:
            continue
        G = msum(mmul(C, Y), D) if N else D
        factor = T * g * Fraction(z) / (z - 1) / Fraction(z) ** n
        vals = [[rf_at(h, cq(z)) for h in row] for row in E]
        if any(v is None for row in vals for v in row):
            continue
        for i in range(m):
            for j in range(m):
                if G[i][j] != factor * vals[i][j][0]:
                    return False, "(A, B, C, D) does not realise the model's E-hat: entry (%d, %d) differs at z = %d" % (i, j, z)
        agreed += 1
    if agreed < need:
        return False, "too few points to compare the realisation with the model"
    for i in range(m):
        for j in range(m):
            if i != j and X[i][j] != 0:
                return False, "X is not diagonal"
            if owner[i] == owner[j] and X[i][i] != X[j][j]:
                return False, "X is not g I on an operator's DOFs"
        if g_at_least_one and X[i][i] < 1:
            return False, "g < 1 ((9))"
        if X[i][i] <= 0:
            return False, "g <= 0"
    if any(M[i][j] != M[j][i] for M in (P, QE, QV) for i in range(len(M)) for j in range(i)):
        return False, "P, Q_E or Q_V not symmetric"
    if not semidefinite(P, True):
        return False, "P > 0 fails"
    AtP = mmul(mT(A), P) if N else []
    M11 = msum(mmul(AtP, A), P, -1) if N else []
    M12 = msum(mmul(AtP, B), mmul(mT(C), X), Fraction(-1, 2)) if N else []
    XD = mmul(X, D)
    BtPB = mmul(mmul(mT(B), P), B) if N else [[Fraction(0)] * m for _ in range(m)]
    M22 = msum(msum(BtPB, QE, -1), msum(XD, mT(XD)), Fraction(-1, 2))
    neg = [[-(M11[i][j] if j < N else M12[i][j - N]) for j in range(N + m)] for i in range(N)]
    neg += [[-(M12[j][i] if j < N else M22[i][j - N]) for j in range(N + m)] for i in range(m)]
    if not semidefinite(neg, False):
        return False, "(16)'s first LMI M1 <= 0 fails"
    S = [[(delta[i] * X[i][i] if i == j else 0) - QE[i][j] for j in range(m)] + [-QE[i][j] for j in range(m)] for i in range(m)]
    S += [[-QE[i][j] for j in range(m)] + [QV[i][j] - QE[i][j] for j in range(m)] for i in range(m)]
    if not semidefinite(S, True):
        return False, "(14) > 0 fails"
    if not semidefinite(QV, True):
        return False, "Q_V > 0 fails"
    return True, agreed


MULTIDOF_MODEL = ("T", "delay", "environment", "set", "devices", "operators")


def feasible_claim(c, evidence_keys, key="feasible", model_keys=MULTIDOF_MODEL):
    """(model, evidence) of a multi-DOF certificate whose claim is {status "exact", KEY: true} (its fields
    known), or None when KEY is false (which a point cannot prove: (16) infeasible, V missing Theorem 4)."""
    model, claim, ev = parts(c)
    only(model, model_keys, "model")
    only(claim, ("status", key), "claim")
    only(ev, evidence_keys, "evidence")
    if claim.get("status") != "exact":
        raise Malformed("claim.status: must be \"exact\"")
    if not isinstance(claim.get(key), bool):
        raise Malformed("claim.%s: missing or not true/false" % key)
    return (model, ev) if claim[key] else None


def check_multidof_feasible(c):
    """Paper 000's (16) feasible at the evidence's point on its realisation of the model's E-hat (feasible_point)."""
    got = feasible_claim(c, ("A", "B", "C", "D", "P", "X", "Q_E", "Q_V"))
    if got is None:
        return False, "the claim is that (16) is infeasible; a point proves only feasibility"
    model, ev = got
    Araw, Draw = ev.get("A"), ev.get("D")
    if isinstance(Araw, list) and isinstance(Draw, list) and len(Araw) + len(Draw) > MAX_FEASIBLE_ORDER:  # before the model is parsed
        raise TooLarge("evidence.A: order %d with m = %d (D's rows), above this checker's limit N + m <= %d" % (
            len(Araw), len(Draw), MAX_FEASIBLE_ORDER))
    T, n = period(model), delay_of(model)
    E, g = env_entries(model, T, parameters(model))
    m = len(E)
    ok, why = feasible_point(E, g, T, n, witness_levels(model, m), operator_owner(model, m), ev, "evidence", True)
    if not ok:
        return False, why
    return True, "(16) feasible: the realisation is the model's E-hat, P > 0, M1 <= 0, (14) > 0, Q_V > 0, X in G"


def lemma1_matrix(A, B, C, D, P, X, Q):
    """Paper 000's (2) with the supply y'Xu - y'Qy: [[A'PA - P + C'QC, A'PB - C'X/2 + C'QD], [., B'PB - (XD + D'X')/2
    + D'QD]], the quadratic form of x+'Px+ - x'Px - (y'Xu + u'X'y)/2 + y'Qy at [x; u]."""
    N, m = len(A), len(D)
    AtP, CtQ = mmul(mT(A), P), mmul(mT(C), Q)
    F11 = msum(msum(mmul(AtP, A), P, -1), mmul(CtQ, C))
    F12 = msum(msum(mmul(AtP, B), mmul(mT(C), X), Fraction(-1, 2)), mmul(CtQ, D))
    XD = mmul(X, D)
    F22 = msum(msum(mmul(mmul(mT(B), P), B), msum(XD, mT(XD)), Fraction(-1, 2)), mmul(mmul(mT(D), Q), D))
    F = [[F11[i][j] if j < N else F12[i][j - N] for j in range(N + m)] for i in range(N)]
    return F + [[F12[j][i] if j < N else F22[i][j - N] for j in range(N + m)] for i in range(m)]


def lemma1_level_fails(A, B, C, D, P, lo, osp):
    """None when P = P' > 0 and paper 000's (2) < 0 at Delta = lo I (OSP) or Phi = lo I (ISP) with this P (Lemma 1's
    "if": then (1) holds with V = x'Px, so the level is >= lo); else what fails."""
    n, m = len(A), len(D)
    if any(P[i][j] != P[j][i] for i in range(n) for j in range(i)):
        return "evidence.P is not symmetric"
    if not semidefinite(P, True):
        return "P > 0 fails"
    ident = [[Fraction(int(i == j)) for j in range(m)] for i in range(m)]
    Q = [[lo * x for x in r] for r in ident] if osp else [[Fraction(0)] * m for _ in range(m)]
    neg = [[-x for x in row] for row in lemma1_matrix(A, B, C, D, P, ident, Q)]
    if not osp:
        for i in range(m):
            neg[n + i][n + i] -= lo  # + Phi = lo I in (2)'s lower right block
    if not semidefinite(neg, True):
        return "(2) < 0 fails at the level lo with this P"
    return None


def vhat_lemma1(AV, BV, CV, DV, delta, T, X, QV, PV):
    """None when Lemma 1 holds for V-hat (17) (Gamma = I, K = (T/2) diag(delta)^-1) built from V at X, Q_V with the
    storage PV: PV > 0 and F <= 0; else what fails."""
    nv, m = len(AV), len(DV)
    if any(d <= 0 for d in delta):
        raise Malformed("model.devices: a level <= 0: K = (T/2) Delta_D^-1 (12) is not defined")
    K = [[T / (2 * delta[i]) if i == j else Fraction(0) for j in range(m)] for i in range(m)]
    N = nv + m
    A = [list(AV[i]) + [-BV[i][j] / T for j in range(m)] for i in range(nv)] + [[Fraction(0)] * N for _ in range(m)]
    B = [[BV[i][j] / T for j in range(m)] for i in range(nv)] + [[Fraction(int(i == j)) for j in range(m)] for i in range(m)]
    C = [list(CV[i]) + [(K[i][j] - DV[i][j]) / T for j in range(m)] for i in range(m)]
    D = [[(DV[i][j] - K[i][j]) / T for j in range(m)] for i in range(m)]
    if any(PV[i][j] != PV[j][i] for i in range(N) for j in range(i)):
        return "P_V is not symmetric"
    if not semidefinite(PV, True):
        return "P_V > 0 fails"
    neg = [[-x for x in row] for row in lemma1_matrix(A, B, C, D, PV, X, QV)]
    if not semidefinite(neg, False):
        return "Lemma 1 for V-hat at X and Q_V: F <= 0 fails"
    return None


def check_multidof_coupling(c):
    """Paper 000's Theorem 4 for the model's coupling V, through Theorem 5: (16) at the evidence's point
    (feasible_point), and Lemma 1 for V-hat (17) (Gamma = I, K = (T/2) Delta_D^-1 (12)) at its X and Q_V:
    P_V > 0 and F = [[A'PA - P + C'QC, A'PB - C'X/2 + C'QD], [., B'PB - (XD + D'X)/2 + D'QD]] <= 0."""
    got = feasible_claim(c, ("A", "B", "C", "D", "P", "X", "Q_E", "Q_V", "P_V"), "theorem4", MULTIDOF_MODEL + ("coupling",))
    if got is None:
        return False, "the claim is that V misses Theorem 4's conditions; a point proves only that it meets them"
    model, ev = got
    V = model.get("coupling")
    if not isinstance(V, dict):
        raise Malformed("model.coupling: missing or not an object")
    only(V, ("A", "B", "C", "D"), "model.coupling")
    Araw = V.get("A")
    if not isinstance(Araw, list):
        raise Malformed("model.coupling.A: missing or not a matrix")
    nv = len(Araw)
    T, n = period(model), delay_of(model)
    E, g = env_entries(model, T, parameters(model))
    m = len(E)
    if nv + m > MAX_FEASIBLE_ORDER:
        raise TooLarge("model.coupling.A: V-hat's order %d above this checker's limit %d" % (nv + m, MAX_FEASIBLE_ORDER))
    AV, BV, CV, DV = (frac_matrix(V, k, r, cl, "model.coupling") for k, r, cl in (("A", nv, nv), ("B", nv, m), ("C", m, nv), ("D", m, m)))
    delta, owner = witness_levels(model, m), operator_owner(model, m)
    ok, why = feasible_point(E, g, T, n, delta, owner, {k: v for k, v in ev.items() if k != "P_V"}, "evidence", True)
    if not ok:
        return False, "(16) at the evidence's point: " + why
    X, QV = frac_matrix(ev, "X", m, m), frac_matrix(ev, "Q_V", m, m)
    PV = frac_matrix(ev, "P_V", nv + m, nv + m)
    why = vhat_lemma1(AV, BV, CV, DV, delta, T, X, QV, PV)
    if why:
        return False, why
    return True, "V meets Theorem 4's conditions: (16) at the point, V-hat Gamma^-1 Q_V Gamma^-1-OSP by Lemma 1"


MAX_SYMMETRIC_DOFS = 512  # m: the invariance is m^2 comparisons of parsed entries (a few distinct ones)


def split_16(model, ev, invariant=None):
    """(ok, why, blocks) of (16) by the split of alike DOFs (multidof-feasible-symmetric above) on the model and
    the evidence's classes, fixed and zero_sum; with invariant = (g, q_E, q_V) per class, each block's X, Q_E, Q_V
    must moreover be one positive multiple of the whole's image (k_c times on the fixed space)."""
    T, n = period(model), delay_of(model)
    if "perturb_C" in (model.get("environment") or {}):
        raise Malformed("model.environment.perturb_C: outside this kind (the split needs E itself invariant)")
    E, g = env_entries(model, T, parameters(model), MAX_SYMMETRIC_DOFS)
    m = len(E)
    delta, owner = witness_levels(model, m), operator_owner(model, m)
    if len(set(owner)) != m:  # (h1)
        raise Malformed("model.operators: an operator has two DOFs or more; this kind needs one-DOF operators")
    classes = split_classes(ev, m)
    r = len(classes)
    if invariant is not None and any(len(v) != r for v in invariant):
        raise Malformed("evidence.g, q_E, q_V: one value per class (%d)" % r)
    cls = {i: a for a, k in enumerate(classes) for i in k}
    for a, k in enumerate(classes):  # (h2)
        if any(delta[i] != delta[k[0]] for i in k):
            return False, "class %d is not of alike DOFs: the OSP levels differ" % a, 0
    for i in range(m):  # (h3)
        for k in range(m):
            a, b = classes[cls[i]], classes[cls[k]]
            ri, rk = a[0], (a[0] if i == k else a[1] if cls[i] == cls[k] else b[0])
            if (E[i][k].num, E[i][k].den) != (E[ri][rk].num, E[ri][rk].den):
                return False, "E is not invariant under the permutations within the classes: E(%d, %d) is not E(%d, %d)" % (i, k, ri, rk), 0

    def image_fails(pt, where, image):
        """pt's X, Q_E, Q_V one positive multiple of the diagonal image [X, Q_E, Q_V][i]."""
        if image is None:
            return None
        mb = len(image[0])
        mats = [frac_matrix(pt, k, mb, mb, where) for k in ("X", "Q_E", "Q_V")]
        tau = mats[0][0][0] / image[0][0]
        ok = tau > 0 and all(mats[q][i][j] == (tau * image[q][i] if i == j else 0) for q in range(3) for i in range(mb) for j in range(mb))
        return None if ok else "its X, Q_E, Q_V are not one positive multiple of the image of the whole's (g, q_E, q_V)"
    fixed = [[rf_sum(E[classes[a][0]][j] for j in classes[c]) for c in range(r)] for a in range(r)]
    pf = ev.get("fixed")
    if not isinstance(pf, dict):
        raise Malformed("evidence.fixed: missing or not an object")
    img = None if invariant is None else [[len(classes[a]) * v[a] for a in range(r)] for v in invariant]
    why = image_fails(pf, "evidence.fixed", img)
    ok, why = (False, why) if why else feasible_point(fixed, g, T, n, [delta[k[0]] for k in classes], list(range(r)), pf, "evidence.fixed", False)
    if not ok:
        return False, "the fixed space's block: " + why, 0
    zs = ev.get("zero_sum")
    big = [a for a in range(r) if len(classes[a]) >= 2]
    if not isinstance(zs, list) or len(zs) != len(big):
        raise Malformed("evidence.zero_sum: must be one block per class of two DOFs or more (%d)" % len(big))
    for k, (a, b) in enumerate(zip(big, zs)):
        where = "evidence.zero_sum[%d]" % k
        if not isinstance(b, dict):
            raise Malformed(where + ": not an object")
        only(b, ("class", "point"), where)
        if b.get("class") != a or isinstance(b.get("class"), bool):
            raise Malformed(where + ".class: must be %d (the classes of two DOFs or more, in order)" % a)
        a0, a1 = classes[a][0], classes[a][1]
        pt = b.get("point")
        if not isinstance(pt, dict):
            raise Malformed(where + ".point: missing or not an object")
        why = image_fails(pt, where + ".point", None if invariant is None else [[v[a]] for v in invariant])
        ok, why = (False, why) if why else feasible_point([[E[a0][a0] - E[a0][a1]]], g, T, n, [delta[a0]], [0], pt, where + ".point", False)
        if not ok:
            return False, "class %d's zero-sum block: %s" % (a, why), 0
    return True, "", 1 + len(big)


def split_classes(ev, m):
    classes = ev.get("classes")
    if not isinstance(classes, list) or not classes or any(not isinstance(k, list) or not k for k in classes):
        raise Malformed("evidence.classes: must be a non-empty array of non-empty arrays of DOF indices")
    flat = [i for k in classes for i in k]
    if any(not isinstance(i, int) or isinstance(i, bool) for i in flat) or sorted(flat) != list(range(m)):
        raise Malformed("evidence.classes: must hold every DOF 0..%d exactly once" % (m - 1))
    return classes


def check_multidof_feasible_symmetric(c):
    """Paper 000's (16) feasible by the split of alike DOFs (multidof-feasible-symmetric, above)."""
    got = feasible_claim(c, ("classes", "fixed", "zero_sum"))
    if got is None:
        return False, "the claim is that (16) is infeasible; points prove only feasibility"
    model, ev = got
    ok, why, blocks = split_16(model, ev)
    if not ok:
        return False, why
    return True, "(16) feasible by the split of alike DOFs (E invariant), each of %d blocks' points verified with g > 0, lifted to g >= 1" % blocks


def check_multidof_coupling_symmetric(c):
    """Paper 000's Theorem 4 for a decentralised V on the split of alike DOFs: (16) by split_16 at the whole's
    invariant diagonal (g, q_E, q_V), g >= 1, q_V > 0; Lemma 1 for each DOF's V-hat_i at (g, q_V) of its class."""
    got = feasible_claim(c, ("classes", "g", "q_E", "q_V", "fixed", "zero_sum", "P_V"), "theorem4",
                         MULTIDOF_MODEL + ("coupling_blocks",))
    if got is None:
        return False, "the claim is that V misses Theorem 4's conditions; points prove only that it meets them"
    model, ev = got
    inv = []
    for key in ("g", "q_E", "q_V"):
        v = ev.get(key)
        if not isinstance(v, list):
            raise Malformed("evidence.%s: must be one \"p/q\" per class" % key)
        inv.append([exact_value(x, "evidence.%s[%d]" % (key, i)) for i, x in enumerate(v)])
    if any(x < 1 for x in inv[0]):
        return False, "g < 1 ((9))"
    if any(x <= 0 for x in inv[2]):
        return False, "q_V <= 0 (Q_V > 0)"
    ok, why, blocks = split_16(model, ev, inv)
    if not ok:
        return False, "(16) by the split: " + why
    T = period(model)
    env = model["environment"]
    E_dofs = len(env["E"] if "E" in env else env["ss"]["D"])  # split_16 read it whole
    classes = split_classes(ev, E_dofs)
    cls = {i: a for a, k in enumerate(classes) for i in k}
    delta = witness_levels(model, E_dofs)
    Vb, PVs = model.get("coupling_blocks"), ev.get("P_V")
    if not isinstance(Vb, list) or len(Vb) != E_dofs:
        raise Malformed("model.coupling_blocks: must be one {A, B, C, D} per DOF (%d)" % E_dofs)
    if not isinstance(PVs, list) or len(PVs) != E_dofs:
        raise Malformed("evidence.P_V: must be one storage per DOF block (%d)" % E_dofs)
    for i, b in enumerate(Vb):
        where = "model.coupling_blocks[%d]" % i
        if not isinstance(b, dict) or not isinstance(b.get("A"), list):
            raise Malformed(where + ": must be {A, B, C, D}")
        only(b, ("A", "B", "C", "D"), where)
        nv = len(b["A"])
        if nv + 1 > MAX_FEASIBLE_ORDER:
            raise TooLarge(where + ": V-hat's order above this checker's limit")
        AV, BV, CV, DV = (frac_matrix(b, k, r, cl, where) for k, r, cl in (("A", nv, nv), ("B", nv, 1), ("C", 1, nv), ("D", 1, 1)))
        PV = frac_matrix({"P_V": PVs[i]}, "P_V", nv + 1, nv + 1, "evidence.P_V[%d]" % i)
        a = cls[i]
        why = vhat_lemma1(AV, BV, CV, DV, [delta[i]], T, [[inv[0][a]]], [[inv[2][a]]], PV)
        if why:
            return False, "DOF %d's block of V: %s" % (i, why)
    return True, ("V meets Theorem 4's conditions: (16) by the split (%d blocks, at the whole's invariant diagonal) and "
                  "Lemma 1 for V-hat block by block (%d blocks of V)" % (blocks, E_dofs))


def rf_sum(terms):
    terms = list(terms)
    out = terms[0]
    for t in terms[1:]:
        out = out + t
    return out


def infeasibility_parts(c, by):
    """(model, evidence, T, n, E, g) of a multi-DOF certificate claiming (16) infeasible, exactly; or
    the refutation when it claims (16) feasible (`by` proves only infeasibility)."""
    model, claim, ev = parts(c)
    only(model, ("T", "delay", "environment", "set", "devices", "operators"), "model")
    only(claim, ("status", "feasible"), "claim")
    if claim.get("status") != "exact":
        raise Malformed("claim.status: must be \"exact\"")
    if not isinstance(claim.get("feasible"), bool):
        raise Malformed("claim.feasible: missing or not true/false")
    if claim["feasible"]:
        return None, "the claim is that (16) is feasible; %s proves only infeasibility" % by
    T, n = period(model), delay_of(model)
    E, g = env_entries(model, T, parameters(model))
    return (model, ev, T, n, E, g), None


def check_multidof_facial(c):
    """Paper 000's (16) infeasible by the facial conditions: every admissible X has X E(1) symmetric
    (the witness kind's (a)); when g_a E(1)_ij = g_b E(1)_ji for all i < j has only g = 0, no X does."""
    got, refuted = infeasibility_parts(c, "the facial conditions")
    if refuted:
        return False, refuted
    model, ev, T, n, E, g = got
    only(ev, (), "evidence")
    m = len(E)
    witness_levels(model, m)
    owner = operator_owner(model, m)
    N = len(model["operators"])
    if g == 0:
        return False, "the environment's gain is 0: X E(1) g = 0 is symmetric"
    E1 = [[rf_at(h, cq(1)) for h in row] for row in E]
    if any(v is None for row in E1 for v in row):
        raise Malformed("model.environment.E: an entry has a pole at z = 1 (E(1) must be finite)")
    rows = []
    for i in range(m):
        for j in range(i + 1, m):
            r = [Fraction(0)] * N
            r[owner[i]] += E1[i][j][0]
            r[owner[j]] -= E1[j][i][0]
            if any(r):
                rows.append(r)
    rank = 0
    for col in range(N):
        piv = next((k for k in range(rank, len(rows)) if rows[k][col] != 0), None)
        if piv is None:
            continue
        rows[rank], rows[piv] = rows[piv], rows[rank]
        for k in range(rank + 1, len(rows)):
            f = rows[k][col] / rows[rank][col]
            rows[k] = [a - f * b for a, b in zip(rows[k], rows[rank])]
        rank += 1
    if rank < N:
        return False, "some X = diag(g) != 0 makes X E(1) symmetric (rank %d < %d operators)" % (rank, N)
    return True, "(16) infeasible: no X = diag(g) != 0 makes X E(1) symmetric (rank %d)" % rank


def check_multidof_witness(c):
    """Paper 000's (16) infeasible for every admissible X: phi_X(z, u) = Re(u^T X E-hat(z) u) + u^T
    Delta_D X u > 0 at every point of (16) (M1 <= 0 at [x; u], x = (zI - A)^-1 B u, and Delta_D X - Q_E
    > 0 by (14)); X E(1) must be symmetric (else phi -> -inf as theta -> 0+, E-hat ~ (T/2)(1 - j
    cot(theta/2)) E(1)), which fixes the ratios g_b / g_a = E(1)_ij / E(1)_ji on operators E(1) couples; the
    evidence holds when phi_c <= 0 on every such group and < 0 on one (phi_X = sum g_c phi_c < 0)."""
    got, refuted = infeasibility_parts(c, "a witness")
    if refuted:
        return False, refuted
    model, ev, T, n, E, g = got
    m = len(E)
    delta = witness_levels(model, m)
    ops = model.get("operators")
    owner = operator_owner(model, m)
    one = cq(1)
    E1 = [[rf_at(h, one) for h in row] for row in E]
    for i in range(m):
        for j in range(m):
            if E1[i][j] is None:
                raise Malformed("model.environment.E[%d][%d]: a pole at z = 1 (E(1) must be finite)" % (i, j))
    # the admissible X: g_a E(1)_ij = g_b E(1)_ji (i in operator a, j in b), so g_b = g_a E(1)_ij / E(1)_ji
    # along every pair not both 0: one direction per connected group (ratio[o] relative to its first
    # operator group[o]); a 0 against a non-0, opposite signs or a cycle's disagreement leave no X > 0
    ratio, group = [None] * len(ops), [None] * len(ops)
    for s0 in range(len(ops)):
        if ratio[s0] is not None:
            continue
        ratio[s0], group[s0], stack = Fraction(1), s0, [s0]
        while stack:
            o = stack.pop()
            for i in range(m):
                if owner[i] != o:
                    continue
                for j in range(m):
                    a, b = E1[i][j], E1[j][i]
                    if a[1] != 0 or b[1] != 0:
                        raise Malformed("model.environment.E: E(1) is not real (%d, %d)" % (i, j))
                    a, b = a[0], b[0]
                    if a == 0 and b == 0:
                        continue
                    r = ratio[o] * a / b if a != 0 and b != 0 else None
                    o2 = owner[j]
                    if r is None or r <= 0 or (ratio[o2] is not None and ratio[o2] != r):
                        raise Malformed("model.environment.E: no X > 0 makes X E(1) symmetric (%d, %d): the facial "
                                        "conditions decide, outside this kind" % (i, j))
                    if ratio[o2] is None:
                        ratio[o2], group[o2] = r, s0
                        stack.append(o2)

    def find(a):
        return group[a]
    if "points" in ev:  # the several-frequency witness: S_g = sum_j w_j phi_g(z_j, u_j)
        only(ev, ("points",), "evidence")
        pts = ev["points"]
        if not isinstance(pts, list) or not pts or len(pts) > 4096:
            raise Malformed("evidence.points: 1 to 4096 points")
    else:
        only(ev, ("z_re", "z_im", "u", "u_im"), "evidence")
        pts = [dict(ev, weight="1")]
    phi = {}
    for k, pt in enumerate(pts):
        where = "evidence.points[%d]" % k if "points" in ev else "evidence"
        if not isinstance(pt, dict):
            raise Malformed(where + ": not an object")
        only(pt, ("z_re", "z_im", "u", "u_im", "weight"), where)
        z = (exact(pt, "z_re", where), exact(pt, "z_im", where))
        w = exact(pt, "weight", where)
        ur, ui = pt.get("u"), pt.get("u_im", ["0"] * m)
        if not isinstance(ur, list) or len(ur) != m or not isinstance(ui, list) or len(ui) != m:
            raise Malformed(where + ".u: must be %d \"p/q\" strings (u_im too)" % m)
        u = [(exact_value(x, where + ".u[%d]" % i), exact_value(y, where + ".u_im[%d]" % i)) for i, (x, y) in enumerate(zip(ur, ui))]
        if z[0] * z[0] + z[1] * z[1] != 1:
            return False, "z is not on the unit circle"
        if z == (1, 0):
            return False, "z = 1 is E-hat's pole"
        if all(x == (0, 0) for x in u):
            return False, "u = 0"
        if w < 0:
            return False, "a negative weight"
        zc, zn, k2 = (z[0], -z[1]), cq(1), n
        while k2:  # conj(z)^n = z^-n on the circle
            if k2 & 1:
                zn = cq_mul(zn, zc)
            zc = cq_mul(zc, zc)
            k2 >>= 1
        f = cq_mul(cq_mul(cq(T * g), cq_div(z, cq_sub(z, cq(1)))), zn)
        for i in range(m):
            acc = cq(0)
            for j in range(m):
                if u[j] == (0, 0):
                    continue
                v = rf_at(E[i][j], z)
                if v is None:
                    return False, "z is a pole of E[%d][%d]" % (i, j)
                acc = cq_add(acc, cq_mul(v, u[j]))
            r = find(owner[i])
            ubar = (u[i][0], -u[i][1])
            term = cq_mul(ubar, cq_mul(f, acc))[0] + delta[i] * (u[i][0] ** 2 + u[i][1] ** 2)
            phi[r] = phi.get(r, Fraction(0)) + w * ratio[owner[i]] * term
    if any(v > 0 for v in phi.values()):
        return False, "phi > 0 on a group of operators: the witness does not hold for every admissible X"
    if all(v == 0 for v in phi.values()):
        return False, "phi = 0 on every group: no strict witness"
    return True, "(16) infeasible: phi <= 0 on %d group(s) of operators, < 0 on one" % len(phi)


# ---------------------------------------------------------------- driver
def check(c):
    """(exit code, reason): 0 verified, 1 refuted, 2 malformed, 3 not checked (too large)."""
    try:
        if not isinstance(c, dict):
            raise Malformed("certificate: not a JSON object")
        if c.get("certificate") != "hapstab":
            raise Malformed("certificate: missing or not \"hapstab\"")
        if c.get("version") != 1 or isinstance(c.get("version"), bool):
            raise Malformed("version: missing or not 1")
        checkers = {"bound": check_bound, "bound-max": check_bound_max, "limit-cycle": check_limit_cycle,
                    "multidof-feasible": check_multidof_feasible, "multidof-witness": check_multidof_witness,
                    "multidof-feasible-symmetric": check_multidof_feasible_symmetric,
                    "multidof-coupling": check_multidof_coupling,
                    "multidof-coupling-symmetric": check_multidof_coupling_symmetric,
                    "multidof-facial": check_multidof_facial,
                    "operator-passivity": check_operator_passivity,
                    "passivity-level": check_passivity_level,
                    "passivity-level-mimo": check_passivity_level_mimo,
                    "r": check_r, "stability": check_stability, "stability-max": check_stability_max,
                    "stability-loop": check_stability_loop, "stability-loop-max": check_stability_loop_max,
                    "stability-loop-symmetric": check_stability_loop_symmetric,
                    "stability-loop-max-symmetric": check_stability_loop_max_symmetric,
                    "stability-loop-verdicts": check_stability_loop_verdicts, "wedge": check_wedge}
        kind = c.get("kind")
        if not isinstance(kind, str) or kind not in checkers:
            raise Malformed("kind: %r has no checker (known: %s)" % (kind, ", ".join(sorted(checkers))))
        ok, why = checkers[kind](c)
        return (0 if ok else 1), why
    except Malformed as e:
        return 2, str(e)
    except TooLarge as e:
        return 3, str(e)
    except RecursionError:
        return 2, "model.H: nested too deep"
    except (ZeroDivisionError, ValueError, TypeError, AssertionError) as e:  # never "verified"
        return 3, "internal error of the checker: %r" % (e,)


def check_file(name):
    """(exit code, reason) of the certificate in the file `name`."""
    try:
        with open(name) as f:
            c = json.load(f)
    except (OSError, ValueError) as e:
        return 2, str(e)
    return check(c)


def main(argv):
    if len(argv) >= 3 and argv[1] == "--files":
        worst = 0
        for name in argv[2:]:
            t0 = time.perf_counter()
            code, why = check_file(name)
            worst = max(worst, code)
            verdict = ["verified", "refuted", "malformed", "not checked"][code]
            print(json.dumps({"file": name, "verdict": verdict, "exit": code, "reason": why,
                              "seconds": round(time.perf_counter() - t0, 6)}), flush=True)
        return worst
    if len(argv) == 3 and argv[1] == "--batch":
        worst = 0
        with open(argv[2]) as f:
            for lineno, line in enumerate(f, 1):
                if not line.strip():
                    continue
                try:
                    c = json.loads(line)
                except ValueError as e:
                    code, why = 2, "not JSON (%s)" % e
                else:
                    code, why = check(c)
                worst = max(worst, code)
                verdict = ["verified", "refuted", "malformed", "not checked"][code]
                print(json.dumps({"line": lineno, "verdict": verdict, "exit": code, "reason": why}), flush=True)
        return worst
    if len(argv) != 2:
        print("usage: hapstab_check.py CERT.json | --batch FILE | --files CERT...", file=sys.stderr)
        return 2
    code, why = check_file(argv[1])
    print(["verified", "refuted: " + why, "malformed: " + why, "not checked: " + why][code])
    return code


if __name__ == "__main__":
    sys.exit(main(sys.argv))
