"""A pole an expression writes and an operation cancels (stop 80): hapstab's parser (lti/parse.hpp,
through the Python binding) against the independent checker's (checks/hapstab_check.py: its own
lexer, rational functions, per-operation test, Schur-Cohn, Hurwitz and marginal-stability test), on
random expressions built to cancel on purpose. They share no code. Each expression is refused by
both or by neither; where both accept, the reduced H is the same. The truth of each case is also
known by construction (the factor cancelled and where its root lies), and checked.

Run: PYTHONPATH=build/python /usr/bin/python3 -m pytest tests/python/test_cancellations.py
(ctest runs it in python_tests: 1500 cases, seed 80; HAPSTAB_CANCEL_CASES=N HAPSTAB_CANCEL_SEED=S for
a longer campaign, the counts per branch printed with -s)."""
import os
import random
import sys
from fractions import Fraction

import hapstab
from hapstab import _core

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "checks"))
import hapstab_check as hc  # noqa: E402

T = Fraction(1, 1000)
# roots of factors: inside the circle, on it, outside; in s: left, on the axis, right
Z_ROOTS = {"inside": ["1/2", "-3/10", "9/10", "0"], "circle": ["1", "-1"], "outside": ["2", "-3/2", "11/10"]}
S_ROOTS = {"inside": ["-1", "-5/2", "-1/10"], "circle": ["0"], "outside": ["1", "3/10"]}


def factor(var, root):
    return "(%s - (%s))" % (var, root) if root != "0" else var


def case(g, var):
    """(text, where the cancelled root lies or None, what the construction is): one of the shapes below,
    around a random stable filler F."""
    roots = Z_ROOTS if var == "z" else S_ROOTS
    where = g.choice(["inside", "circle", "outside", None])
    f = factor(var, g.choice(roots[where or "inside"]))
    a, b = g.choice(roots["inside"]), g.choice(roots["inside"])
    filler = "(%d*%s + %d)/(%s)" % (g.randint(1, 9), var, g.randint(-5, 5), factor(var, a))
    other = factor(var, b)
    shapes = [
        ("%d*%s/%s" % (g.randint(1, 5), f, f), "f/f"),
        ("(%s)*%s/(%s*%s)" % (filler, f, f, other), "F f/(f g)"),
        ("1/%s - 1/%s + %s" % (f, f, filler), "1/f - 1/f"),
        ("(%s + %s)/%s*%s" % (var, g.randint(1, 4), f, f), "(x + c)/f * f"),
        ("(%s)*(%s*%s)^-1*%s" % (filler, f, other, f), "F (f g)^-1 f"),
    ]
    if where is None:  # nothing cancelled: a plain filler, or a zero gain times a pole on the circle
        shapes = [(filler, "F"), ("0*%s/%s + %s" % (other, factor(var, g.choice(roots["circle"])), filler), "0 * g/c + F"),
                  ("%s/(%s*%s)" % (filler, f, other), "F/(f g)")]
    text, shape = g.choice(shapes)
    return text, where, shape


def hapstab_parse(text, var):
    try:
        return _core.tf_from_expression(text, str(T) if var == "z" else None, {}, var, "H")
    except hapstab.InputError as e:
        assert "cancels" in str(e), (text, str(e))
        return None


def checker_parse(text, var):
    try:
        return hc.parse_h(text, T if var == "z" else Fraction(0), {}, var)
    except hc.Malformed as e:
        assert "cancels a pole" in str(e), (text, str(e))
        return None


def test_both_parsers_refuse_the_same_cancellations():
    g = random.Random(int(os.environ.get("HAPSTAB_CANCEL_SEED", "80")))
    cases = int(os.environ.get("HAPSTAB_CANCEL_CASES", "1500"))
    counts = {}
    for k in range(cases):
        var = "z" if k % 3 else "s"
        text, where, shape = case(g, var)
        mine, theirs = hapstab_parse(text, var), checker_parse(text, var)
        refused = where in ("circle", "outside")
        assert (mine is None) == refused, (text, where)
        assert (theirs is None) == refused, (text, where)
        if mine is not None:  # the same reduced H (numerator and monic denominator, ascending)
            num = [Fraction(c) for c in reversed(mine.num)]
            den = [Fraction(c) for c in reversed(mine.den)]
            lead = den[-1]
            assert [c / lead for c in num] == theirs.num and [c / lead for c in den] == theirs.den, text
        key = (var, where, shape)
        counts[key] = counts.get(key, 0) + 1
    # every branch: each variable, each place of the cancelled root (and none), each shape
    for var in "zs":
        for where in ("inside", "circle", "outside", None):
            assert sum(n for (v, w, _), n in counts.items() if v == var and w == where) >= 60, (var, where, counts)
    assert len(counts) >= 35, counts
    print("\n%d cases, per (variable, cancelled root, shape): %s" % (cases, sorted(counts.items(), key=str)))


def test_bound_takes_a_simple_cancelled_pole_on_the_circle_as_the_command_line_does():
    moving_sum = "(z-1)*(1 - z^-9)/(1 - z^-1)"  # the moving sum in closed form: z = 1 cancelled, simple
    b = hapstab.bound(moving_sum, T="1/1000", allow_noncausal=True)
    assert b.status == "certified" and abs(b.value - 0.00136818827762279085) < 1e-15
    many = hapstab.bound("(z-1)*(K - z^-9)/(1 - z^-1)", T="1/1000", params={"K": [1, 1]}, allow_noncausal=True)
    assert list(many.status) == ["certified", "certified"]
    for call in (lambda: hapstab.bound("10*(z-2)/(z-2)", T="1/1000"),  # outside: H as written is unstable
                 lambda: hapstab.bound("(z-1)/(z-1)^2*(z-1)", T="1/1000"),  # a repeated pole on the circle
                 lambda: hapstab.stability(plant="1/(m*s^2+b*s)", H=moving_sum + "/z^9", T="1/1000",
                                           params={"m": 1, "b": 1})):  # a loop keeps the hidden mode
        try:
            call()
            raise AssertionError("accepted")
        except hapstab.InputError as e:
            assert "cancels" in str(e), str(e)
