#!/usr/bin/env python3
"""Mutation testing of the certificate checkers (issue 47, item 5).

    python3 tests/check/mutate.py --hapstab build/hapstab [--models 300] [--seed 1] [--quiet] [--kinds K1,K2]

Produces certificates of `bound` (random virtual environments, integer delays, eta; reported as
`bound-frac` with a fractional delay t_d = (p/q) T, q = 2..6, sin(pi t_d/T) of both signs, the
Tustin damper's pole at the band's end), `bound-max` (`bound --max K --damping b`: random affine
environments, delays, fractional delays; K_max finite, 0 and +inf), `passivity-level` (SISO G of five
families, ISP and OSP), `passivity-level-mimo` (`passivity-level --ss --kind isp|osp` on random square
state spaces of five families, its own random stream; mutants edit one entry of A, B, C or D, move lo
past the level, hi below it, the witness along and off the circle, delete the stability hypothesis), `r`
(random T, w) and `stability` (random one-DOF loops with every device pole at s = 0: a verdict
stable or NOT stable; its mutants include a producer that built another loop -- the delay + 1, T
doubled -- with that loop's polynomial and verdict, consistently), `stability-max` (`stability --max`
on random one-DOF loops: K_max finite, exact, 0; mutants move lo past the crossing, hi below it,
stable_at and unstable_at, and edit the model) and `wedge` (random H(z) of five
families: the five exact verdicts of paper 002's criteria and assumptions) and `multidof-witness`
(tests/check/mutate_multidof.py: `multidof analyze --certificate` on the witness campaign's random
scenes, where a frequency witness proved (16) infeasible) with `hapstab ... --certificate`, perturbs each in many ways, and runs both checkers
on every mutant: `hapstab check --batch` (check/) and checks/hapstab_check.py (imported; it shares
no code with hapstab). Every mutant carries what must happen:
  accept     the claim is true and its evidence intact (the unmutated certificate; an enclosure
             widened): both must verify;
  refute     the claim is false (b* claimed below the proven lower bound or above the proven upper
             bound, an exact value moved, a printed number that is not the one claimed, a model
             edited so that the claim misses the new model's certified b*): both must refute,
             naming the reason;
  malformed  a field deleted, a field added that no checker reads, a value of the wrong form, a
             sign that makes an input invalid: both must exit 2 naming the field;
  agree      the claim is true or unknown but the evidence was moved (a witness point moved, a
             model edited with no certified verdict on the claim): the two independent checkers
             must give the same verdict.
Ground truth for an edited model is hapstab's own certified enclosure of the edited model at 40
digits (the unmutated claims themselves are verified by both checkers first). Exit 0 when every
expectation holds; prints the counts.
"""
import argparse
import copy
import json
import math
import os
import random
import re
import shutil
import subprocess
import sys
import tempfile
import time
from fractions import Fraction

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "checks"))
import hapstab_check  # noqa: E402  (the independent checker)
import mutate_multidof  # noqa: E402  (the multidof-witness kind)
import mutate_operator  # noqa: E402  (the operator-passivity kind)

OPERATOR_ENTRIES = {}  # id(certificate) -> its operator's entries (mutate_operator.rand_certificate)

TEMPLATES = [
    ("K + B*(z-1)/(T*z)", ["K", "B"]),                        # virtual wall, backward difference (001)
    ("K + B*2*(z-1)/(T*(z+1))", ["K", "B"]),                  # Tustin damper: a pole at z = -1
    ("K*(z - a)/(z^2 - b*z + c)", ["K", "a", "b", "c"]),
    ("(K*z^2 - B)/(z*(z - a))", ["K", "B", "a"]),
    ("K/(z + a)^2 + B*(z-1)/(T*z)", ["K", "B", "a"]),
    ("K*(1 - a)/(z - a) + B*(z^2 - 1)/(T*z^2)", ["K", "B", "a"]),
    ("K", ["K"]),
]


def rand_value(name, rng):
    if name == "K":
        return str(rng.choice([rng.randint(1, 50000), rng.randint(1, 100)]))
    if name == "B":
        return str(rng.randint(0, 40)) if rng.random() < 0.7 else "%d.%d" % (rng.randint(0, 9), rng.randint(0, 99))
    # a, b, c: inside the unit disc (a stable H)
    return "%s0.%02d" % (rng.choice(["", "-"]), rng.randint(0, 80))


def rand_model(rng):
    H, names = rng.choice(TEMPLATES)
    sets = {n: rand_value(n, rng) for n in names}
    if "b" in sets:  # z^2 - b z + c stable: |c| < 1, |b| < 1 + c
        c = Fraction(sets["c"])
        sets["b"] = str(Fraction(rng.randint(-90, 90), 100) * (1 + c))
    T = rng.choice(["1/1000", "1/500", "0.002", "1/100", "1/4000"])
    delay = rng.choice([0, 0, 1, 1, 2, 3, 5])
    eta = rng.choice(["0", "0", "0", "1/10", "2.5"])
    return {"H": H, "set": sets, "T": T, "delay": delay, "eta": eta}


def rand_frac_model(rng):
    """A bound model with a fractional delay t_d = (p/q) T, q in 2..6: sin(pi t_d/T) of both signs,
    the Tustin damper's pole at z = -1 at the band's end (-inf there when the sign is negative, +inf
    -- no certificate -- when positive), ends cos(pi/q) rational (q = 2, 3) and irrational (q >= 4)."""
    m = rand_model(rng)
    if rng.random() < 0.5:
        m["H"], names = TEMPLATES[1] if rng.random() < 0.7 else TEMPLATES[0]
        m["set"] = {n: rand_value(n, rng) for n in names}
    m["delay"] = rng.choice([0, 0, 0, 1, 2])
    q = rng.choice([2, 2, 3, 4, 4, 5, 6])
    p = rng.choice([k for k in range(1, 2 * q) if k % q])
    m["frac_delay"] = frac(Fraction(p, q) * Fraction(m["T"]))
    return m


def bound_args(m, digits):
    a = ["bound", "--H", m["H"], "--T", m["T"], "--delay", str(m["delay"]), "--eta", m["eta"], "--digits", str(digits)]
    if "frac_delay" in m:
        a += ["--frac-delay", m["frac_delay"]]
    for k, v in m["set"].items():
        a += ["--set", "%s=%s" % (k, v)]
    return a


def run(hapstab, args):
    p = subprocess.run([hapstab] + args, capture_output=True, text=True)
    return p.returncode, p.stdout, p.stderr


def certified_enclosure(hapstab, m, cache):
    """hapstab's certified enclosure of b* for model m (40 digits): (lo, hi), "inf", or None."""
    key = json.dumps(m, sort_keys=True)
    if key in cache:
        return cache[key]
    rc, out, _ = run(hapstab, bound_args(m, 40) + ["--json"])
    res = None
    if rc == 0:
        j = json.loads(out)
        if j.get("bound") == "inf":
            res = "inf"
        elif j.get("enclosure_rigorous") and j["status"] in ("exact", "certified"):
            res = (Fraction(j["enclosure"][0]), Fraction(j["enclosure"][1]))
    cache[key] = res
    return res


def claim_interval(cert):
    c = cert["claim"]
    if c["status"] == "exact":
        v = Fraction(c["value"])
        return v, v
    return Fraction(c["lo"]), Fraction(c["hi"])


def frac(x):
    return "%d/%d" % (x.numerator, x.denominator) if x.denominator != 1 else str(x.numerator)


def set_claim(cert, lo, hi):
    """The certificate claiming [lo, hi] (exact when lo == hi was exact), printed fields dropped."""
    c = copy.deepcopy(cert)
    cl = c["claim"]
    for k in ("printed", "printed_lo", "printed_hi"):
        cl.pop(k, None)
    if cl["status"] == "exact" and lo == hi:
        cl["value"] = frac(lo)
    else:
        cl.pop("value", None)
        cl["status"] = "certified"
        cl["lo"], cl["hi"] = frac(lo), frac(hi)
    return c


from cert_edit import deleted, with_field  # noqa: E402


SET_MOVES = (("x 1.001", lambda x: x * Fraction(1001, 1000)), ("+ 1", lambda x: x + 1), ("sign flipped", lambda x: -x))


def model_edits(m, rng, moves=SET_MOVES, fields=("H",)):
    """Model edits the kinds share: each --set value moved by each of `moves` (name, f), and in each
    expression of `fields` one '+' made '-' and one '-' made '+' (chosen at random): (name, model)."""
    edits = []
    for k, v in m["set"].items():
        x = Fraction(v)
        for name, f in moves:
            y = f(x)
            if y != x:
                edits.append(("set %s %s" % (k, name), dict(m, set=dict(m["set"], **{k: frac(y)}))))
    for field in fields:
        h = m[field]
        for a_, b_ in (("+", "-"), ("-", "+")):
            if a_ in h:
                j = [q for q, ch in enumerate(h) if ch == a_][rng.randrange(h.count(a_))]
                edits.append(("%s: a '%s' made '%s'" % (field, a_, b_), dict(m, **{field: h[:j] + b_ + h[j + 1:]})))
    return edits


def model_truth(cert, new_model, hapstab, cache):
    """The expectation for `cert` with its model replaced by new_model."""
    enc = certified_enclosure(hapstab, new_model, cache)
    lo, hi = claim_interval(cert)
    if enc == "inf":
        return "refute"  # a finite claim of an infinite b*
    if enc is None:
        return "agree"
    tlo, thi = enc
    if hi < tlo or lo > thi:
        return "refute"
    return "agree"  # true or undecided: the witness may or may not still reach lo


def bound_mutants(cert, rng, hapstab, cache):
    out = [("unmutated", cert, "accept")]
    lo, hi = claim_interval(cert)
    exact = cert["claim"]["status"] == "exact"
    scale = max(abs(lo), Fraction(1))
    tiny = scale / 10 ** rng.randint(40, 60)
    gap = max(hi - lo, tiny)
    # the claim moved past what the certificate's own evidence proves
    out.append(("hi below the proven lower bound", set_claim(cert, lo - 2 * gap, lo - gap / 2 if not exact else lo - tiny), "refute"))
    out.append(("lo above the proven upper bound", set_claim(cert, hi + gap / 2 if not exact else hi + tiny, hi + 2 * gap), "refute"))
    if exact:
        out.append(("exact value + tiny", set_claim(cert, lo + tiny, lo + tiny), "refute"))
        out.append(("exact value - tiny", set_claim(cert, lo - tiny, lo - tiny), "refute"))
    else:
        out.append(("hi moved inward past lo", set_claim(cert, lo - tiny, lo - tiny / 2), "refute"))
        out.append(("lo moved inward past hi", set_claim(cert, hi + tiny / 2, hi + tiny), "refute"))
        pl = cert["claim"]["printed_lo"]
        moved = pl[:-1] + str((int(pl[-1]) + 1) % 10) if pl[-1].isdigit() else pl + "1"
        out.append(("printed_lo is not the claimed lo", with_field(cert, ["claim", "printed_lo"], moved), "refute"))
    out.append(("enclosure widened", set_claim(cert, lo - tiny, hi + tiny), "accept"))
    out.append(("enclosure widened a lot", set_claim(cert, lo - scale, hi + scale), "accept"))
    out.append(("lo > hi", set_claim(cert, hi + tiny, lo - tiny) if not exact else set_claim(cert, lo + tiny, lo - tiny), "refute"))
    # the witness moved
    c0 = Fraction(cert["evidence"]["witness_c"])
    for name, c1 in (("witness + tiny", c0 + tiny / scale), ("witness - 1/1000", c0 - Fraction(1, 1000)),
                     ("witness negated", -c0), ("witness random", Fraction(rng.randint(-1000, 1000), 1000))):
        out.append((name, with_field(cert, ["evidence", "witness_c"], frac(c1)), "agree"))
    out.append(("witness outside [-1, 1]", with_field(cert, ["evidence", "witness_c"], frac(1 + Fraction(1, rng.randint(2, 1000)))), "refute"))
    # the model edited
    m = cert["model"]
    edits = []
    for k, v in m["set"].items():
        x = Fraction(v)
        for name, y in (("x 1.001", x * Fraction(1001, 1000)), ("+ 1", x + 1), ("sign flipped", -x), ("x 2", 2 * x)):
            if y != x:
                edits.append(("set %s %s" % (k, name), ["set", k], frac(y)))
    if "frac_delay" in m:
        td, T = Fraction(m["frac_delay"]), Fraction(m["T"])
        q = (m["delay"] + td / T).denominator
        edits.append(("frac_delay + T/%d" % q, ["frac_delay"], frac(td + T / q)))
        edits.append(("frac_delay x 2", ["frac_delay"], frac(td * 2)))
        edits.append(("frac_delay + T (one more sample)", ["frac_delay"], frac(td + T)))
        edits.append(("frac_delay 0", ["frac_delay"], "0"))
    else:
        edits.append(("frac_delay T/2 added", ["frac_delay"], frac(Fraction(m["T"]) / 2)))
    edits.append(("T doubled", ["T"], frac(Fraction(m["T"]) * 2)))
    edits.append(("T halved", ["T"], frac(Fraction(m["T"]) / 2)))
    edits.append(("delay + 1", ["delay"], m["delay"] + 1))
    if m["delay"] > 0:
        edits.append(("delay - 1", ["delay"], m["delay"] - 1))
    edits.append(("eta + 1/10", ["eta"], frac(Fraction(m["eta"]) + Fraction(1, 10))))
    if Fraction(m["eta"]) > 0:
        edits.append(("eta = 0", ["eta"], "0"))
    h = m["H"]
    if "+" in h:
        i = [k for k, ch in enumerate(h) if ch == "+"][rng.randrange(h.count("+"))]
        edits.append(("H: a '+' made '-'", ["H"], h[:i] + "-" + h[i + 1:]))
    if "-" in h:
        i = [k for k, ch in enumerate(h) if ch == "-"][rng.randrange(h.count("-"))]
        edits.append(("H: a '-' made '+'", ["H"], h[:i] + "+" + h[i + 1:]))
    for name, path, value in edits:
        nm = copy.deepcopy(m)
        o = nm
        for k in path[:-1]:
            o = o[k]
        o[path[-1]] = value
        # the edited model as the producer takes it (numbers in --set as "p/q" are fine)
        expect = model_truth(cert, nm, hapstab, cache)
        out.append(("model: " + name, with_field(cert, ["model"], nm), expect))
    # malformed: deleted fields, unknown fields, wrong forms, invalid signs
    for path in (["model"], ["claim"], ["evidence"], ["kind"], ["version"], ["model", "H"], ["model", "T"],
                 ["model", "delay"], ["model", "eta"], ["claim", "status"], ["evidence", "witness_c"]):
        out.append(("deleted " + ".".join(path), deleted(cert, path), "malformed"))
    out.append(("deleted claim.value" if exact else "deleted claim.lo", deleted(cert, ["claim", "value" if exact else "lo"]), "malformed"))
    if m["set"]:
        out.append(("deleted model.set", deleted(cert, ["model", "set"]), "malformed"))
    if "frac_delay" in m:
        out += frac_mutants(cert, rng)
    out.append(("added model.t_d", with_field(cert, ["model", "t_d"], "1/2000"), "malformed"))
    out.append(("added claim.omega", with_field(cert, ["claim", "omega"], "1"), "malformed"))
    out.append(("added evidence.omega", with_field(cert, ["evidence", "omega"], "1"), "malformed"))
    out.append(("T as a decimal", with_field(cert, ["model", "T"], "0.001"), "malformed"))
    out.append(("T negated", with_field(cert, ["model", "T"], "-" + m["T"]), "malformed"))
    out.append(("delay negative", with_field(cert, ["model", "delay"], -1), "malformed"))
    out.append(("delay as a string", with_field(cert, ["model", "delay"], str(m["delay"])), "malformed"))
    out.append(("eta negative", with_field(cert, ["model", "eta"], "-1/10"), "malformed"))
    out.append(("status unknown", with_field(cert, ["claim", "status"], "numeric"), "malformed"))
    out.append(("kind unknown", with_field(cert, ["kind"], "bound-inf"), "malformed"))
    out.append(("H unparsable", with_field(cert, ["model", "H"], m["H"] + "*("), "malformed"))
    if "H" in m:  # a pole written and cancelled outside the circle: H as written is unstable (stop 80)
        out.append(("H: a pole at z = 2 written and cancelled", with_field(cert, ["model", "H"], "(" + m["H"] + ")*(z-2)/(z-2)"),
                    "malformed"))
    return out


INF_TEMPLATES = [  # H(z) whose objective is unbounded at a pole on the unit circle (b* = +inf) for some values
    ("K/(z-1) + B*(z-1)/(T*z)", ["K", "B"]),           # a pole at z = 1: +inf iff K > 0 (c -> 1 from below)
    ("K*z/(z^2 + 1) + B*(z-1)/(T*z)", ["K", "B"]),     # poles at +-j (c = 0): +inf from one side, -inf from the other
    ("K + B*2*(z-1)/(T*(z+1))", ["K", "B"]),           # the Tustin wall with t_d = (p/q) T, q = 2, 3: sin(pi tau) > 0
]


def rand_inf_model(rng):
    """A bound model that is often b* = +inf (issue 47: its certificate) and, after a sign flip (K
    negated, t_d + T), often finite -- issue 46 item 1's false +inf."""
    H, names = rng.choice(INF_TEMPLATES)
    sets = {n: rand_value(n, rng) for n in names}
    if "z^2 + 1" in H and rng.random() < 0.5:
        sets["K"] = "-" + sets["K"]
    m = {"H": H, "set": sets, "T": rng.choice(["1/1000", "1/500", "1/100"]), "delay": rng.choice([0, 0, 1, 2, 3]),
         "eta": rng.choice(["0", "0", "1/10"])}
    if "(z+1)" in H:
        q = rng.choice([2, 3, 2, 3, 4, 5, 7])  # q >= 4: the pole at the band's irrational end cos(pi/q)
        m["delay"] = rng.choice([0, 0, 2])
        m["frac_delay"] = frac(Fraction(rng.choice([k for k in range(1, q)]), q) * Fraction(m["T"]))
    elif "z^2 + 1" in H and rng.random() < 0.5:  # the poles at +-j through t_d/T = p/q: c_p = cos(pi/(2q)), irrational
        q = rng.choice([2, 3, 4, 5, 7])
        m["frac_delay"] = frac(Fraction(rng.choice([k for k in range(1, q)]), q) * Fraction(m["T"]))
    return m


def inf_mutants(cert, rng, hapstab, cache):
    """b* = +inf: the pole c_p and the side the objective tends to +inf from. Every family here has a
    simple pole in c, or the other side outside the band: the side flipped tends to -inf or leaves the
    band (refute)."""
    out = [("unmutated", cert, "accept")]
    ev = cert["evidence"]
    if "pole_at_z" in ev:  # the local form: H's simple pole at z = -1 met by a fractional delay (since stop 81)
        out += [("pole_at_z -> 1", with_field(cert, ["evidence", "pole_at_z"], "1"), "malformed"),
                ("pole_at_z as a number", with_field(cert, ["evidence", "pole_at_z"], -1), "malformed"),
                ("side beside pole_at_z", with_field(cert, ["evidence", "side"], 1), "malformed"),
                ("end_lo beside pole_at_z", with_field(cert, ["evidence", "end_lo"], "0"), "malformed"),
                ("deleted evidence.pole_at_z", deleted(cert, ["evidence", "pole_at_z"]), "malformed"),
                ("status certified", with_field(cert, ["claim", "status"], "certified"), "malformed"),
                ("claim made finite (b* = 0)", with_field(deleted(cert, ["claim", "infinite"]), ["claim", "value"], "0"), "malformed")]
        m = cert["model"]
        T = Fraction(m["T"])
        edits = model_edits(m, rng, SET_MOVES + (("x 2", lambda x: 2 * x),))
        edits += [("frac_delay + T (sin(pi nu) flipped: -inf, issue 46 item 1)", dict(m, frac_delay=frac(Fraction(m["frac_delay"]) + T))),
                  ("frac_delay 0 (nu whole)", dict(m, frac_delay="0")), ("delay + 1", dict(m, delay=m["delay"] + 1)),
                  ("T doubled (t_d/T halved)", dict(m, T=frac(T * 2)))]
        for name, nm in edits:
            enc = certified_enclosure(hapstab, nm, cache)
            out.append(("model: " + name, with_field(cert, ["model"], nm), "agree" if enc == "inf" else "same" if enc is None else "refute"))
        return out
    if "end_lo" in ev:  # the pole at the band's irrational end, isolated in (end_lo, end_hi]
        lo, hi = Fraction(ev["end_lo"]), Fraction(ev["end_hi"])
        ce = (lo + hi) / 2  # within the interval: a point on each side of cos(pi/q) is not known here
        out += [("end_lo -> -1 (other roots of U_{q-1} inside)", with_field(cert, ["evidence", "end_lo"], "-1"), "refute"),
                ("end_hi -> end_lo + (end_hi - end_lo)/10^6", with_field(cert, ["evidence", "end_hi"], frac(lo + (hi - lo) / 10 ** 6)), "agree"),
                ("end_lo above end_hi", with_field(cert, ["evidence", "end_lo"], frac(hi + 1 / Fraction(10 ** 6))), "refute"),
                ("end_lo -> end_hi - (end_hi - end_lo)/10^6", with_field(cert, ["evidence", "end_lo"], frac(hi - (hi - lo) / 10 ** 6)), "agree"),
                ("end_lo a decimal", with_field(cert, ["evidence", "end_lo"], str(float(ce))), "malformed"),
                ("pole_c beside end_lo", with_field(cert, ["evidence", "pole_c"], frac(ce)), "malformed"),
                ("deleted evidence.end_hi", deleted(cert, ["evidence", "end_hi"]), "malformed"),
                ("claim made finite (b* = 0)", with_field(deleted(cert, ["claim", "infinite"]), ["claim", "value"], "0"), "malformed")]
        m = cert["model"]
        T = Fraction(m["T"])
        for name, nm in (("frac_delay + T (sin(pi tau) flipped: -inf, issue 46 item 1)", dict(m, frac_delay=frac(Fraction(m["frac_delay"]) + T))),
                         ("delay + 1", dict(m, delay=m["delay"] + 1))):
            enc = certified_enclosure(hapstab, nm, cache)
            out.append(("model: " + name, with_field(cert, ["model"], nm), "agree" if enc == "inf" else "same" if enc is None else "refute"))
        return out
    if "pole_lo" in ev:  # an irrational pole inside the band, isolated in (pole_lo, pole_hi)
        lo, hi, side = Fraction(ev["pole_lo"]), Fraction(ev["pole_hi"]), ev["side"]
        w = hi - lo
        out += [("side flipped (the objective -> -inf there)", with_field(cert, ["evidence", "side"], -side), "refute"),
                ("the interval moved past the pole", with_field(with_field(cert, ["evidence", "pole_lo"], frac(hi + w / 3)),
                                                                ["evidence", "pole_hi"], frac(hi + w)), "refute"),
                ("pole_hi below pole_lo", with_field(cert, ["evidence", "pole_hi"], frac(lo - w)), "refute"),
                ("pole_lo -> -1 (outside the band, or other poles inside)", with_field(cert, ["evidence", "pole_lo"], "-1"), "refute"),
                ("pole_hi -> 1 (the numerator's roots or other poles, maybe)", with_field(cert, ["evidence", "pole_hi"], "1"), "agree"),
                ("pole_lo a decimal", with_field(cert, ["evidence", "pole_lo"], str(float(lo))), "malformed"),
                ("pole_c beside pole_lo", with_field(cert, ["evidence", "pole_c"], frac((lo + hi) / 2)), "malformed"),
                ("end_lo beside pole_lo", with_field(cert, ["evidence", "end_lo"], frac(lo)), "malformed"),
                ("deleted evidence.pole_hi", deleted(cert, ["evidence", "pole_hi"]), "malformed"),
                ("deleted evidence.side", deleted(cert, ["evidence", "side"]), "malformed"),
                ("claim made finite (b* = 0)", with_field(deleted(cert, ["claim", "infinite"]), ["claim", "value"], "0"), "malformed")]
        m = cert["model"]
        T = Fraction(m["T"])
        for name, nm in (("frac_delay + T", dict(m, frac_delay=frac(Fraction(m["frac_delay"]) + T))), ("delay + 1", dict(m, delay=m["delay"] + 1)),
                         ("K negated", dict(m, set=dict(m["set"], K=frac(-Fraction(m["set"]["K"])))))):
            enc = certified_enclosure(hapstab, nm, cache)
            out.append(("model: " + name, with_field(cert, ["model"], nm), "agree" if enc == "inf" else "same" if enc is None else "refute"))
        return out
    cp, side = Fraction(ev["pole_c"]), ev["side"]
    out.append(("side flipped (the objective -> -inf there, or outside the band)", with_field(cert, ["evidence", "side"], -side), "refute"))
    for name, c1 in (("pole_c + 1/1000", cp + Fraction(1, 1000)), ("pole_c - 10^-30", cp - Fraction(1, 10 ** 30)),
                     ("pole_c random", Fraction(rng.randint(-999, 999), 1000))):
        if c1 != cp:
            out.append((name, with_field(cert, ["evidence", "pole_c"], frac(c1)), "refute"))
    out.append(("pole_c outside [-1, 1]", with_field(cert, ["evidence", "pole_c"], "3/2"), "refute"))
    out.append(("claim made finite (b* = 0)", with_field(deleted(cert, ["claim", "infinite"]), ["claim", "value"], "0"), "malformed"))
    m = cert["model"]
    edits = model_edits(m, rng, SET_MOVES + (("x 2", lambda x: 2 * x),))
    if "frac_delay" in m:
        T = Fraction(m["T"])
        edits.append(("frac_delay + T (sin(pi tau) flipped: -inf, issue 46 item 1)", dict(m, frac_delay=frac(Fraction(m["frac_delay"]) + T))))
        edits.append(("frac_delay 0", dict(m, frac_delay="0")))
    edits.append(("delay + 1", dict(m, delay=m["delay"] + 1)))
    edits.append(("T doubled", dict(m, T=frac(Fraction(m["T"]) * 2))))
    for name, nm in edits:
        enc = certified_enclosure(hapstab, nm, cache)
        expect = "agree" if enc == "inf" else "same" if enc is None else "refute"  # a finite b*: +inf is false
        out.append(("model: " + name, with_field(cert, ["model"], nm), expect))
    for path in (["evidence", "pole_c"], ["evidence", "side"], ["claim", "status"], ["model", "H"], ["evidence"]):
        out.append(("deleted " + ".".join(path), deleted(cert, path), "malformed"))
    out.append(("side 0", with_field(cert, ["evidence", "side"], 0), "malformed"))
    out.append(("side 2", with_field(cert, ["evidence", "side"], 2), "malformed"))
    out.append(("side as a string", with_field(cert, ["evidence", "side"], "+1"), "malformed"))
    out.append(("pole_c a decimal", with_field(cert, ["evidence", "pole_c"], "0.5"), "malformed"))
    out.append(("infinite false", with_field(cert, ["claim", "infinite"], False), "malformed"))
    out.append(("infinite as a string", with_field(cert, ["claim", "infinite"], "true"), "malformed"))
    out.append(("status certified", with_field(cert, ["claim", "status"], "certified"), "malformed"))
    out.append(("a value beside infinite", with_field(cert, ["claim", "value"], "1"), "malformed"))
    out.append(("added evidence.witness_c", with_field(cert, ["evidence", "witness_c"], "1/2"), "malformed"))
    out.append(("T negated", with_field(cert, ["model", "T"], "-" + m["T"]), "malformed"))
    return out


def frac_mutants(cert, rng):
    """What only a fractional delay's certificate has: the band [cos(pi/q), 1] in c = cos(wT/q) and
    its rational lower end evidence.domain_c_lo."""
    out = []
    m, ev = cert["model"], cert["evidence"]
    if "domain_c_lo" in ev:
        c_lo = Fraction(ev["domain_c_lo"])
        above = c_lo + Fraction(1, 10 ** rng.randint(3, 8))  # above cos(pi/q): c_lo is within 10^-40 below it
        out.append(("domain_c_lo above the band's end", with_field(cert, ["evidence", "domain_c_lo"], frac(above)), "refute"))
        out.append(("witness beyond the band's end", with_field(cert, ["evidence", "witness_c"], frac(c_lo - Fraction(1, 10 ** 9))), "refute"))
        out.append(("domain_c_lo lowered", with_field(cert, ["evidence", "domain_c_lo"], frac(c_lo - Fraction(1, 1000))), "agree"))
        out.append(("domain_c_lo deleted (the band [-1, 1])", deleted(cert, ["evidence", "domain_c_lo"]), "agree"))
        out.append(("domain_c_lo a decimal", with_field(cert, ["evidence", "domain_c_lo"], "0.5"), "malformed"))
    out.append(("frac_delay negative", with_field(cert, ["model", "frac_delay"], "-" + m["frac_delay"]), "malformed"))
    out.append(("frac_delay a decimal", with_field(cert, ["model", "frac_delay"], "0.0015"), "malformed"))
    out.append(("frac_delay a number", with_field(cert, ["model", "frac_delay"], 1), "malformed"))
    return out


def r_mutants(cert, rng, hapstab, cache):
    out = [("unmutated", cert, "accept")]
    cl = cert["claim"]
    lo, hi, re = Fraction(cl["im_lo"]), Fraction(cl["im_hi"]), Fraction(cl["re"])
    u = (hi - lo) / 2  # one unit in the last printed place, at least
    mid = Fraction(cl["printed_im"])  # |Im r - mid| <= u/2: correctly rounded

    def claim(l, h, r=re):
        c = with_field(cert, ["claim", "im_lo"], frac(l))
        c = with_field(c, ["claim", "im_hi"], frac(h))
        c["claim"]["re"] = frac(r)
        c["claim"].pop("printed_im", None)
        return c

    tiny = max(abs(mid), Fraction(1)) / 10 ** rng.randint(30, 50)
    out.append(("Im claimed above the value", claim(mid + u, mid + 2 * u), "refute"))
    out.append(("Im claimed below the value", claim(mid - 2 * u, mid - u), "refute"))
    out.append(("Im enclosure widened", claim(lo - tiny, hi + tiny), "accept"))
    out.append(("Re + tiny", claim(lo, hi, re + tiny), "refute"))
    out.append(("Re sign flipped", claim(lo, hi, -re), "refute"))
    out.append(("Im sign flipped", claim(-hi, -lo), "refute"))
    out.append(("lo > hi", claim(hi, lo), "refute"))
    out.append(("printed_im outside", with_field(cert, ["claim", "printed_im"], frac(hi + u)), "refute"))
    T, w = Fraction(cert["model"]["T"]), Fraction(cert["model"]["omega"])
    # an edited model: Im r = -(T/2) cot(wT/2) moves by far more than u (u ~ |Im| 10^-19)
    out.append(("model: omega x 1.001", with_field(cert, ["model", "omega"], frac(w * Fraction(1001, 1000))), "refute"))
    out.append(("model: T x 2", with_field(cert, ["model", "T"], frac(T * 2)), "refute"))
    for path in (["model", "T"], ["model", "omega"], ["claim", "re"], ["claim", "im_lo"], ["claim", "im_hi"], ["claim"], ["model"]):
        out.append(("deleted " + ".".join(path), deleted(cert, path), "malformed"))
    out.append(("omega = 0", with_field(cert, ["model", "omega"], "0"), "malformed"))
    out.append(("added model.delay", with_field(cert, ["model", "delay"], 1), "malformed"))
    return out


MAX_TEMPLATES = [  # (H, the parameter to maximise, the others): affine in it
    ("K + B*(z-1)/(T*z)", "K", ["B"]),
    ("K + B*(z-1)/(T*z)", "B", ["K"]),                       # b* convex, not monotone, in B with a delay
    ("K + B*2*(z-1)/(T*(z+1))", "K", ["B"]),                  # Tustin: a pole at z = -1
    ("K*(z - a)/(z^2 - b*z + c)", "K", ["a", "b", "c"]),
    ("B*(z-1)/(T*z) - K", "K", ["B"]),                        # f1 < 0: K_max = +inf when b*(0) < b
    ("K/(z + a)^2 + B*(z-1)/(T*z)", "B", ["K", "a"]),
]


def rand_max_model(rng):
    H, name, others = rng.choice(MAX_TEMPLATES)
    m = rand_model(rng)
    m["H"], m["name"] = H, name
    m["set"] = {n: rand_value(n, rng) for n in others}
    if name == "B" and "K" in m["set"]:
        m["set"]["K"] = str(rng.randint(1, 3000))
    if "b" in m["set"]:
        m["set"]["b"] = str(Fraction(rng.randint(-90, 90), 100) * (1 + Fraction(m["set"]["c"])))
    m["delay"] = rng.choice([0, 0, 1, 1, 2, 3])
    if H.endswith("- K") and rng.random() < 0.5:  # f1 = -T/2 < 0 without a delay: K_max = +inf when b*(0) < b
        m["delay"] = 0
        m["damping"] = frac(Fraction(m["set"]["B"]) + rng.choice([Fraction(1, 2), Fraction(5)]))
        return m
    if rng.random() < 0.3:
        q = rng.choice([2, 3, 4, 5])
        m["frac_delay"] = frac(Fraction(rng.choice([k for k in range(1, 2 * q) if k % q]), q) * Fraction(m["T"]))
    m["damping"] = rng.choice(["1/2", "1", "3/2", "2", "5", "20"])
    side = random.Random(json.dumps(m, sort_keys=True))  # its own stream: the draws above stay what they were
    if "(z+1)" in H and name == "K" and side.random() < 0.5:
        # the Tustin wall's residue at z = -1 is -4B/T, so for B > 0 an even floor(nu) (sin(nu pi) > 0) sends the
        # objective to +inf at wT = pi: b*(0) = +inf, K_max = 0 (evidence.at_zero_infinite)
        q = side.choice([2, 3, 4, 5])
        m["delay"] = side.choice([0, 2])
        m["frac_delay"] = frac(Fraction(side.randint(1, q - 1), q) * Fraction(m["T"]))
    return m


def max_args(m, digits):
    a = bound_args({k: v for k, v in m.items() if k not in ("name", "damping")}, digits)
    return a + ["--max", m["name"], "--damping", m["damping"]]


def sup_truth(hapstab, args, key, cache):
    """hapstab's supremum (bound --max, stability --max) from `args` + --json, asked at 40 digits:
    (lo, hi) -- the exact value twice when it is one --, "inf", or None (no answer)."""
    if key not in cache:
        rc, out, _ = run(hapstab, args + ["--json"])
        res = None
        if rc in (0, 1):
            j = json.loads(out)
            if j.get("max") == "inf":
                res = "inf"
            elif j.get("max") == "0" and j.get("status") in ("exact", "certified"):
                res = (Fraction(0), Fraction(0))
            elif j.get("exact"):
                res = (Fraction(j["exact"]), Fraction(j["exact"]))
            elif j.get("status") in ("exact", "certified") and j.get("enclosure"):
                res = (Fraction(j["enclosure"][0]), Fraction(j["enclosure"][1]))
        cache[key] = res
    return cache[key]


def max_truth(hapstab, m, cache):
    """hapstab's K_max of the bound-max model m at 40 digits."""
    return sup_truth(hapstab, max_args(m, 40), "max" + json.dumps(m, sort_keys=True), cache)


def max_claim(cert):
    c = cert["claim"]
    if c.get("infinite"):
        return "inf"
    if c["status"] == "exact":
        return Fraction(c["value"]), Fraction(c["value"])
    return Fraction(c["lo"]), Fraction(c["hi"])


def set_max_claim(cert, lo, hi):
    c = copy.deepcopy(cert)
    q = c["claim"]["quantity"]
    c["claim"] = {"quantity": q, "status": "certified", "lo": frac(lo), "hi": frac(hi)}
    return c


def max_mutants(cert, rng, hapstab, cache):
    out = [("unmutated", cert, "accept")]
    ev, m = cert["evidence"], cert["model"]
    claim = max_claim(cert)
    b = Fraction(m["damping"])
    if claim == "inf":
        out.append(("+inf claimed as 1", with_field(with_field(cert, ["claim"], {"status": "exact", "value": "1"}),
                                                  ["evidence", "witness_c"], "1"), "refute"))
    else:
        lo, hi = claim
        scale = max(hi, Fraction(1))
        tiny = scale / 10 ** rng.randint(40, 60)
        gap = max(hi - lo, tiny)
        # K_max = 0 has no b0_hi: a claim above 0 needs it; beside b*(0) = +inf (at_zero_infinite) it is refuted
        need_b0 = "refute" if "b0_hi" in ev or "at_zero_infinite" in ev else "malformed"
        out.append(("claimed above the enclosure", set_max_claim(cert, hi + gap / 2 + tiny, hi + 2 * gap + tiny), need_b0))
        if lo > 0:
            out.append(("claimed below the enclosure", set_max_claim(cert, lo / 2, lo - tiny), "refute"))
            out.append(("lo lowered", set_max_claim(cert, lo / 2, hi), "accept"))
        out.append(("lo negative", set_max_claim(cert, -1 - lo, hi), "refute"))
        out.append(("lo > hi", set_max_claim(cert, hi + tiny, hi), "refute"))
        out.append(("hi raised", set_max_claim(cert, lo, hi + scale / 10), "agree"))
        if cert["claim"]["status"] == "exact":
            out.append(("exact value + tiny", with_field(cert, ["claim", "value"], frac(lo + tiny)), need_b0))
            if lo > 0:
                out.append(("exact value - tiny", with_field(cert, ["claim", "value"], frac(lo - tiny)), "refute"))
        else:
            pl = cert["claim"]["printed_lo"]
            moved = pl[:-1] + str((int(pl[-1]) + 1) % 10) if pl[-1].isdigit() else pl + "1"
            out.append(("printed_lo is not the claimed lo", with_field(cert, ["claim", "printed_lo"], moved), "refute"))
        if "witness_c" in ev:
            c1 = Fraction(ev["witness_c"])
            for name, x in (("witness - 1/1000", c1 - Fraction(1, 1000)), ("witness negated", -c1),
                            ("witness random", Fraction(rng.randint(-1000, 1000), 1000))):
                if -1 <= x <= 1:
                    out.append((name, with_field(cert, ["evidence", "witness_c"], frac(x)), "agree"))
            out.append(("witness outside [-1, 1]", with_field(cert, ["evidence", "witness_c"], frac(-1 - Fraction(1, rng.randint(2, 1000)))), "refute"))
            out.append(("deleted evidence.witness_c", deleted(cert, ["evidence", "witness_c"]), "malformed"))
        inf = with_field(cert, ["claim"], {"status": cert["claim"]["status"], "infinite": True})
        out.append(("claimed +inf", inf, need_b0))
    az = ev.get("at_zero_infinite")
    if az is not None:  # K_max = 0 by b*(0) = +inf: the evidence of `bound`'s +inf form for H(K = 0)
        out.append(("at_zero_infinite not an object", with_field(cert, ["evidence", "at_zero_infinite"], "-1"), "malformed"))
        out.append(("at_zero_infinite emptied", with_field(cert, ["evidence", "at_zero_infinite"], {}), "malformed"))
        out.append(("at_zero_infinite beside a witness", with_field(cert, ["evidence", "witness_c"], "0"), "malformed"))
        if "pole_at_z" in az:
            out.append(("pole_at_z moved to 1", with_field(cert, ["evidence", "at_zero_infinite", "pole_at_z"], "1"), "malformed"))
        if "pole_c" in az:
            pc = Fraction(az["pole_c"])
            out.append(("pole_c moved", with_field(cert, ["evidence", "at_zero_infinite", "pole_c"], frac(pc - Fraction(1, 1000) if pc > 0 else pc + Fraction(1, 1000))), "refute"))
        if "side" in az:
            out.append(("side flipped", with_field(cert, ["evidence", "at_zero_infinite", "side"], -az["side"]), "agree"))
    if "b0_hi" in ev:
        b0 = Fraction(ev["b0_hi"])
        out.append(("b0_hi = b", with_field(cert, ["evidence", "b0_hi"], frac(b)), "refute"))
        out.append(("b0_hi below b*(0)", with_field(cert, ["evidence", "b0_hi"], frac(b0 - max(abs(b0), Fraction(1)) / 1000)), "refute"))
        out.append(("deleted evidence.b0_hi", deleted(cert, ["evidence", "b0_hi"]), "malformed"))
    if "domain_c_lo" in ev:
        c_lo = Fraction(ev["domain_c_lo"])
        out.append(("domain_c_lo above the band's end", with_field(cert, ["evidence", "domain_c_lo"], frac(c_lo + Fraction(1, 10 ** 6))), "refute"))
    # the model edited: expectation from hapstab's own K_max of the edited model
    edits = [("damping x 1.001", dict(m, damping=frac(b * Fraction(1001, 1000)))), ("damping + 1", dict(m, damping=frac(b + 1))),
             ("damping halved", dict(m, damping=frac(b / 2))), ("T doubled", dict(m, T=frac(Fraction(m["T"]) * 2))),
             ("delay + 1", dict(m, delay=m["delay"] + 1)), ("eta + 1/10", dict(m, eta=frac(Fraction(m["eta"]) + Fraction(1, 10))))]
    edits += model_edits(m, rng)
    h = m["H"]
    for name, nm in edits:
        truth = max_truth(hapstab, nm, cache)
        if truth is None:
            expect = "agree"
        elif truth == "inf" or claim == "inf":
            expect = "agree" if truth == claim else "refute"
        else:
            expect = "refute" if claim[1] < truth[0] or claim[0] > truth[1] else "agree"
        out.append(("model: " + name, with_field(cert, ["model"], nm), expect))
    # malformed
    for path in (["model", "name"], ["model", "damping"], ["model", "H"], ["model", "T"], ["claim", "status"], ["model"], ["evidence"]):
        out.append(("deleted " + ".".join(path), deleted(cert, path), "malformed"))
    K = m["name"]
    out.append(("the parameter given a value", with_field(cert, ["model", "set"], dict(m["set"], **{K: "1"})), "malformed"))
    out.append(("H not affine (times the parameter)", with_field(cert, ["model", "H"], "(" + h + ")*" + K), "malformed"))
    out.append(("H not affine (over 1 + the parameter)", with_field(cert, ["model", "H"], "(" + h + ")/(1 + " + K + ")"), "malformed"))
    out.append(("name of no parameter", with_field(cert, ["model", "name"], "Q"), "malformed"))
    out.append(("damping negative", with_field(cert, ["model", "damping"], "-" + m["damping"]), "malformed"))
    out.append(("damping a decimal", with_field(cert, ["model", "damping"], "0.5"), "malformed"))
    out.append(("claim.infinite a string", with_field(cert, ["claim", "infinite"], "yes"), "malformed"))
    out.append(("status numeric", with_field(cert, ["claim", "status"], "numeric"), "malformed"))
    out.append(("added evidence.omega", with_field(cert, ["evidence", "omega"], "1"), "malformed"))
    return out


LEVEL_TEMPLATES = [  # SISO G(z), Schur stable for the values drawn
    ("1 + K/(z - a)", ["K", "a"]),
    ("(z - a)/(z - b)", ["a", "b"]),
    ("K*(z^2 + p*z + r)/(z^2 - b*z + c)", ["K", "p", "r", "b", "c"]),
    ("K + B*(z-1)/(T*z)", ["K", "B"]),
    ("(K*z + 1)/(z*(z - a))", ["K", "a"]),
    ("1/(z - a) - K", ["K", "a"]),  # OSP <= 0 with D = -K: Lemma 1's lower bound (lower_bound, bounds)
]


def rand_level(rng):
    H, names = rng.choice(LEVEL_TEMPLATES)
    sets = {}
    for n in names:
        if n in ("K", "B"):
            sets[n] = rng.choice([str(rng.randint(1, 20)), "%d/%d" % (rng.randint(1, 20), rng.randint(2, 40))])
        else:
            sets[n] = "%s0.%02d" % (rng.choice(["", "-"]), rng.randint(0, 95))
    if "c" in sets:
        sets["b"] = frac(Fraction(rng.randint(-90, 90), 100) * (1 + Fraction(sets["c"])))
    return {"H": H, "set": sets, "T": rng.choice(["1/1000", "1/100"]), "kind": rng.choice(["isp", "osp"])}


def level_args(m, digits=17):
    a = ["passivity-level", "--H", m["H"], "--T", m["T"], "--kind", m["kind"], "--digits", str(digits)]
    for k, v in m["set"].items():
        a += ["--set", "%s=%s" % (k, v)]
    return a


def level_produce(hapstab, m, cache, tmp, digits=17):
    return produce(hapstab, level_args(m, digits), "level%d" % digits + json.dumps(m, sort_keys=True), "l-edit.json", cache, tmp)


def claim_ends(cl):
    """A level claim's ends: (value, value) when it is exact, (-inf, hi) for an upper bound only, (lo, inf)
    for a lower bound only, else (lo, hi)."""
    if cl["status"] == "upper_bound":
        return (-math.inf, Fraction(cl["hi"]))
    if cl["status"] in ("lower_bound", "bounds"):
        return (Fraction(cl["lo"]), Fraction(cl["hi"]) if "hi" in cl else math.inf)
    return (Fraction(cl["value"]),) * 2 if cl["status"] == "exact" else (Fraction(cl["lo"]), Fraction(cl["hi"]))


def numden_mutants(cert, rng):
    """H written as its coefficients (model.num, model.den: `--num/--den`, a .mat's num and den) in
    place of the expression and its parameters: the same H, so the certificate is accepted as before;
    H beside them is malformed; one coefficient moved by a thousandth: the two checkers agree."""
    m = cert["model"]
    T = Fraction(m["T"])
    G = hapstab_check.parse_h(m["H"], T, {k: Fraction(v) for k, v in m.get("set", {}).items()})
    nm = {k: v for k, v in m.items() if k not in ("H", "set")}
    nm["num"], nm["den"] = [frac(x) for x in reversed(G.num or [Fraction(0)])], [frac(x) for x in reversed(G.den)]
    out = [("model as num/den", with_field(cert, ["model"], nm), "accept"),
           ("num/den beside H", with_field(cert, ["model"], dict(nm, H=m["H"])), "malformed")]
    moved = copy.deepcopy(nm)
    i = rng.randrange(len(moved["num"]))
    moved["num"][i] = frac(Fraction(moved["num"][i]) * Fraction(1001, 1000) + Fraction(1, 10 ** 6))
    out.append(("num/den: a coefficient moved", with_field(cert, ["model"], moved), "agree"))
    return out


def upper_bound_mutants(cert, rng):
    """passivity-level with status upper_bound (an OSP value <= 0: the level <= hi only): hi lowered
    below the frequency minimum (refute), raised (accept), its printed decimal or the witness moved, a
    lower end added (malformed)."""
    hi = Fraction(cert["claim"]["hi"])
    step = max(abs(hi), Fraction(1)) / 100
    c0 = Fraction(cert["evidence"]["witness_c"])
    out = [("unmutated", cert, "accept"),
           ("hi lowered", with_field(deleted(cert, ["claim", "printed_hi"]), ["claim", "hi"], frac(hi - step)), "refute"),
           ("hi raised", with_field(deleted(cert, ["claim", "printed_hi"]), ["claim", "hi"], frac(hi + step)), "accept"),
           ("printed_hi is not the claimed hi", with_field(cert, ["claim", "printed_hi"], cert["claim"]["printed_hi"] + "1"), "refute"),
           ("witness outside [-1, 1]", with_field(cert, ["evidence", "witness_c"], frac(1 + Fraction(1, rng.randint(2, 1000)))), "refute"),
           ("a lower end added", with_field(cert, ["claim", "lo"], frac(hi - 1)), "malformed"),
           ("status certified without lo", with_field(cert, ["claim", "status"], "certified"), "malformed"),
           ("deleted evidence.witness_c", deleted(cert, ["evidence", "witness_c"]), "malformed")]
    for name, x in (("witness - 1/1000", c0 - Fraction(1, 1000)), ("witness random", Fraction(rng.randint(-1000, 1000), 1000))):
        if -1 <= x <= 1:
            out.append((name, with_field(cert, ["evidence", "witness_c"], frac(x)), "agree"))
    return out


def level_frame(cert, rng):
    """What the level kinds' mutants start from: the claim's ends lo, hi (both the value when it is
    exact), their scale max(|lo|, 1), a step `tiny` 40-60 digits below it, the enclosure's width
    `gap` (at least tiny), and claim(l, h): the certificate with its claim replaced by [l, h]."""
    cl = cert["claim"]
    lo, hi = claim_ends(cl)
    scale = max(abs(lo), Fraction(1))
    tiny = scale / 10 ** rng.randint(40, 60)

    def claim(l, h):
        c = copy.deepcopy(cert)
        c["claim"] = {"quantity": cl["quantity"], "status": "certified", "lo": frac(l), "hi": frac(h)}
        return c
    return lo, hi, scale, tiny, max(hi - lo, tiny), claim


def level_mutants(cert, rng, hapstab, cache, tmp):
    if cert["claim"]["status"] == "upper_bound":
        return upper_bound_mutants(cert, rng)
    if cert["claim"]["status"] in ("lower_bound", "bounds"):
        return level_lemma1_mutants(cert, rng)
    out = [("unmutated", cert, "accept")]
    cl, m = cert["claim"], cert["model"]
    lo, hi, scale, tiny, gap, claim = level_frame(cert, rng)
    osp = m["kind"] == "osp"
    out.append(("claimed above the level", claim(hi + gap / 2 + tiny, hi + 2 * gap + tiny), "refute"))
    below_lo = lo - 2 * gap - tiny
    out.append(("claimed below the level", claim(below_lo, lo - gap / 2 - tiny),
                "refute" if not osp or below_lo > 0 else "malformed"))
    out.append(("lo lowered", claim(lo - min(tiny, lo / 2) if osp else lo - scale, hi), "accept"))
    out.append(("hi raised", claim(lo, hi + scale), "accept"))
    out.append(("lo > hi", claim(hi + tiny, hi), "refute"))
    if cl["status"] == "exact":
        out.append(("exact value + tiny", with_field(cert, ["claim", "value"], frac(lo + tiny)), "refute"))
        out.append(("exact value - tiny", with_field(cert, ["claim", "value"], frac(lo - tiny)), "refute"))
    else:
        pl = cl["printed_lo"]
        out.append(("printed_lo is not the claimed lo", with_field(cert, ["claim", "printed_lo"], pl + "1"), "refute"))
    c0 = Fraction(cert["evidence"]["witness_c"])
    for name, x in (("witness - 1/1000", c0 - Fraction(1, 1000)), ("witness negated", -c0),
                    ("witness random", Fraction(rng.randint(-1000, 1000), 1000))):
        if -1 <= x <= 1:
            out.append((name, with_field(cert, ["evidence", "witness_c"], frac(x)), "agree"))
    out.append(("witness outside [-1, 1]", with_field(cert, ["evidence", "witness_c"], frac(1 + Fraction(1, rng.randint(2, 1000)))), "refute"))
    # the model edited: hapstab's own certificate of the edited model decides
    moves = (("x 1.001", lambda x: x * Fraction(1001, 1000)), ("+ 1/10", lambda x: x + Fraction(1, 10)), ("sign flipped", lambda x: -x))
    edits = [("kind swapped", dict(m, kind="isp" if osp else "osp"))] + model_edits(m, rng, moves)
    h = m["H"]
    for name, nm in edits:
        other = level_produce(hapstab, nm, cache, tmp, 30)
        if isinstance(other, dict):
            olo, ohi = claim_ends(other["claim"])
            expect = "refute" if hi < olo or lo > ohi else "agree"
            if nm["kind"] == "osp" and lo <= 0:  # this claim, read as an OSP level, is no level at all
                expect = "malformed"
        else:
            expect = "same"  # no certificate of the edited model: both checkers give one exit, whichever
        out.append(("model: " + name, with_field(cert, ["model"], nm), expect))
    for path in (["model"], ["claim"], ["evidence"], ["model", "H"], ["model", "T"], ["model", "kind"], ["claim", "status"],
                 ["evidence", "witness_c"]):
        out.append(("deleted " + ".".join(path), deleted(cert, path), "malformed"))
    out.append(("kind unknown", with_field(cert, ["model", "kind"], "io"), "malformed"))
    out.append(("G unstable", with_field(cert, ["model", "H"], "(" + h + ")/(z - 2)"), "malformed"))
    out.append(("G not causal", with_field(cert, ["model", "H"], "z^2*(" + h + ")"), "malformed"))
    G = hapstab_check.parse_h(h, Fraction(m["T"]), {k: Fraction(v) for k, v in m["set"].items()})
    cancels = hapstab_check.peval(G.num, Fraction(-1)) == 0  # h's zero at -1 takes the pole away
    out.append(("G with a pole on the circle", with_field(cert, ["model", "H"], "(" + h + ")/(z + 1)"), "same" if cancels else "malformed"))
    out.append(("T a decimal", with_field(cert, ["model", "T"], "0.001"), "malformed"))
    out.append(("status numeric", with_field(cert, ["claim", "status"], "numeric"), "malformed"))
    out.append(("added model.delay", with_field(cert, ["model", "delay"], 1), "malformed"))
    if osp:
        out.append(("OSP claim <= 0", claim(-scale, -scale / 2), "malformed"))
        out.append(("G with a zero on the circle", with_field(cert, ["model", "H"], "(" + h + ")*(z + 1)/z"), "malformed"))
    return out


MIMO_FAMILIES = {}  # family: certificates produced


def rand_mimo(rng):
    """A random square MIMO state space (m = 2 or 3 inputs, n = 1..4 states, m n <= 12), A Schur stable by
    construction (every row's absolute sum < 1, or a rotation-like block of radius < 1), of five families:
    dense, diagonal (decoupled: the level is the least SISO level), triangular A, D = 0 (strictly proper),
    a lightly damped pair (a resonance: the minimiser inside (0, pi)) and a dense one with D's diagonal
    negative (an OSP value <= 0 beside Lemma 1's level: the lower_bound and bounds claims)."""
    fam = rng.choice(["dense", "diagonal", "triangular", "strictly proper", "resonance", "negative D"])
    m = rng.choice([2, 2, 3])
    n = rng.randint(1, 12 // m if fam != "resonance" else 4)
    if fam == "resonance":
        n = max(n, 2)

    def q(lim, den=(2, 3, 4, 5, 7, 10)):
        d = rng.choice(den)
        return Fraction(rng.randint(-lim * d, lim * d), d)
    A = [[Fraction(0)] * n for _ in range(n)]
    for i in range(n):
        if fam in ("diagonal", "triangular"):
            A[i][i] = Fraction(rng.randint(-8, 8), 10)
        if fam in ("dense", "strictly proper"):
            row = [Fraction(rng.randint(-4, 4), 10 * n) for _ in range(n)]
            A[i] = row
        if fam == "triangular":
            for j in range(i + 1, n):
                A[i][j] = Fraction(rng.randint(-3, 3), 4)
    if fam == "resonance":
        # poles r e^{+-j phi} with (cos phi, sin phi) a rational point of the circle
        r, (c, sq) = Fraction(rng.randint(80, 95), 100), rng.choice([(Fraction(3, 5), Fraction(4, 5)), (Fraction(4, 5), Fraction(3, 5)),
                                                                     (Fraction(0), Fraction(1)), (Fraction(-3, 5), Fraction(4, 5))])
        A[0][0], A[0][1], A[1][0], A[1][1] = r * c, -r * sq, r * sq, r * c
        for i in range(2, n):
            A[i][i] = Fraction(rng.randint(-5, 5), 10)
    B = [[q(1) for _ in range(m)] for _ in range(n)]
    C = [[q(1) for _ in range(n)] for _ in range(m)]
    if fam == "diagonal":  # m blocks of one input each: states split among them
        for i in range(n):
            for j in range(m):
                B[i][j] = B[i][j] if i % m == j else Fraction(0)
                C[j][i] = C[j][i] if i % m == j else Fraction(0)
    D = [[q(2) if i == j else (q(1) if fam != "diagonal" else Fraction(0)) for j in range(m)] for i in range(m)]
    if fam == "strictly proper":
        D = [[Fraction(0)] * m for _ in range(m)]
    for i in range(m):
        D[i][i] += rng.choice([0, 1, 3, 5]) if fam != "negative D" else -Fraction(rng.randint(4, 12), 4) - abs(D[i][i])
    fm = lambda M: [[frac(x) for x in r] for r in M]  # noqa: E731
    return {"A": fm(A), "B": fm(B), "C": fm(C), "D": fm(D), "T": rng.choice(["1/1000", "1/100"]), "family": fam,
            "kind": rng.choice(["isp", "osp"])}


def mimo_produce(hapstab, m, cache, tmp, digits=17):
    """hapstab's passivity-level-mimo certificate of the state space m (its kind, ISP or OSP), or the exit
    code when it writes none."""
    ss = {k: m[k] for k in ("A", "B", "C", "D", "T")}
    kind = m.get("kind", "isp")
    path = os.path.join(tmp, "ss.json")
    with open(path, "w") as f:
        json.dump(ss, f)
    return produce(hapstab, ["passivity-level", "--ss", path, "--kind", kind, "--digits", str(digits)],
                   "mimo%s%d" % (kind, digits) + json.dumps(ss, sort_keys=True), "mimo-edit.json", cache, tmp)


def mimo_entry_edits(m, rng):
    """One entry of A, B, C or D (chosen at random) x 1.001, + 1/10, negated: (name, model)."""
    edits = []
    for key in ("A", "B", "C", "D"):
        M = m[key]
        i, j = rng.randrange(len(M)), rng.randrange(len(M[0]))
        x = Fraction(M[i][j])
        for name, y in (("x 1.001", x * Fraction(1001, 1000)), ("+ 1/10", x + Fraction(1, 10)), ("negated", -x)):
            if y != x:
                N = [list(r) for r in M]
                N[i][j] = frac(y)
                edits.append(("%s[%d][%d] %s" % (key, i, j, name), dict(m, **{key: N})))
    return edits


def mimo_upper_bound_mutants(cert, rng):
    """passivity-level-mimo with status upper_bound (an OSP value <= 0: the level <= hi only, the
    witness alone): hi lowered (refute) or raised (accept), its printed decimal or the witness moved,
    the witness off the circle, a lower end added; at a real witness z0 = +-1, D edited so that G(z0)'s
    first column is 0 (det G(z0) = 0: the pencil singular there for every nu, nothing proven: refute)."""
    hi = Fraction(cert["claim"]["hi"])
    step = max(abs(hi), Fraction(1)) / 100
    c0, s0 = Fraction(cert["evidence"]["witness_c"]), Fraction(cert["evidence"]["witness_s"])
    out = [("unmutated", cert, "accept"),
           ("hi lowered", with_field(deleted(cert, ["claim", "printed_hi"]), ["claim", "hi"], frac(hi - step)), "refute"),
           ("hi raised", with_field(deleted(cert, ["claim", "printed_hi"]), ["claim", "hi"], frac(hi + step)), "accept"),
           ("printed_hi is not the claimed hi", with_field(cert, ["claim", "printed_hi"], cert["claim"]["printed_hi"] + "1"), "refute"),
           ("witness off the circle (s0 + 1/1000)", with_field(cert, ["evidence", "witness_s"], frac(s0 + Fraction(1, 1000))), "refute"),
           ("a lower end added", with_field(cert, ["claim", "lo"], frac(hi - 1)), "malformed"),
           ("status certified without lo", with_field(cert, ["claim", "status"], "certified"), "malformed"),
           ("deleted evidence.witness_s", deleted(cert, ["evidence", "witness_s"]), "malformed")]
    t0 = s0 / (1 + c0) if c0 != -1 else Fraction(10 ** 6)
    for name, t in (("witness t + 1/1000", t0 + Fraction(1, 1000)), ("witness random", Fraction(rng.randint(0, 3000), 1000))):
        w = 1 + t * t
        mut = with_field(cert, ["evidence", "witness_c"], frac((1 - t * t) / w))
        out.append((name, with_field(mut, ["evidence", "witness_s"], frac(2 * t / w)), "agree"))
    if s0 == 0 and cert["model"]["kind"] == "osp":
        m = cert["model"]
        A, B, C, D = ([[Fraction(x) for x in r] for r in m[k]] for k in ("A", "B", "C", "D"))
        G = hapstab_check.mimo_G((A, B, C, D, True), (c0, Fraction(0)))
        D2 = [list(r) for r in m["D"]]
        for i in range(len(D2)):
            D2[i][0] = frac(D[i][0] - G[i][0][0])
        out.append(("D edited: det G(z0) = 0 at the witness", with_field(cert, ["model", "D"], D2), "refute"))
    return out


def lemma1_mutants(cert, rng, upper_mutants, witness_keys):
    """passivity-level(-mimo) with status lower_bound or bounds (the LMI's level printed: lo by Lemma 1 at
    the storage P, hi the frequency value <= 0 at its witness): lo lowered (accept: (2) is non-decreasing
    in the level), lo raised a tenth of its scale (refute: the LMI's lo is within ~1e-5 of Lemma 1's
    supremum) or past hi, its printed decimal, P negated, not symmetric, scaled, of the wrong shape or
    gone; the bounds' hi and witness by `upper_mutants` (the kind's upper-bound-only mutants) on the
    certificate without lo and P."""
    cl = cert["claim"]
    lo = Fraction(cl["lo"])
    scale = max(abs(lo), Fraction(1))
    P = cert["evidence"]["P"]
    n = len(P)
    without_printed = deleted(cert, ["claim", "printed_lo"])
    out = [("unmutated", cert, "accept"),
           ("lo lowered", with_field(without_printed, ["claim", "lo"], frac(lo - scale)), "accept"),
           ("lo raised by a tenth of its scale", with_field(without_printed, ["claim", "lo"], frac(lo + scale / 10)), "refute"),
           ("printed_lo is not the claimed lo", with_field(cert, ["claim", "printed_lo"], cl["printed_lo"] + "1"), "refute"),
           ("P[0][0] negated", with_field(cert, ["evidence", "P", 0, 0], frac(-Fraction(P[0][0]))), "refute"),
           ("P x 10^6", with_field(cert, ["evidence", "P"], [[frac(Fraction(x) * 10 ** 6) for x in r] for r in P]), "agree"),
           ("P[0][0] + 1/1000", with_field(cert, ["evidence", "P", 0, 0], frac(Fraction(P[0][0]) + Fraction(1, 1000))), "agree"),
           ("P a row too few", with_field(cert, ["evidence", "P"], P[:-1] if n > 1 else [[]]), "malformed"),
           ("P an entry a decimal", with_field(cert, ["evidence", "P", 0, 0], "0.5"), "malformed"),
           ("deleted evidence.P", deleted(cert, ["evidence", "P"]), "malformed")]
    if n > 1:
        out.append(("P not symmetric", with_field(cert, ["evidence", "P", 0, 1], frac(Fraction(P[0][1]) + 1)), "refute"))
    if cl["status"] == "bounds":
        hi = Fraction(cl["hi"])
        out.append(("lo past hi", with_field(without_printed, ["claim", "lo"], frac(hi + scale / 10)), "refute"))
        out.append(("status lower_bound beside hi", with_field(cert, ["claim", "status"], "lower_bound"), "malformed"))
        out.append(("status upper_bound beside lo", with_field(cert, ["claim", "status"], "upper_bound"), "malformed"))
        upper = deleted(deleted(with_field(cert, ["claim", "status"], "upper_bound"), ["claim", "lo"]), ["claim", "printed_lo"])
        upper["evidence"] = {k: v for k, v in upper["evidence"].items() if k in witness_keys}
        out += [(name, c, e) for name, c, e in upper_mutants(upper, rng) if name not in ("unmutated", "a lower end added")]
    else:
        out.append(("a witness added", with_field(cert, ["evidence", witness_keys[0]], "1"), "malformed"))
        out.append(("status bounds without hi", with_field(cert, ["claim", "status"], "bounds"), "malformed"))
    return out


def level_lemma1_mutants(cert, rng):
    """The SISO kind's Lemma 1 claims: lemma1_mutants, and the realisation (A, B, C, D) in the evidence
    edited (it no longer realises G as written: refuted before any LMI), or of the wrong shape."""
    ev = cert["evidence"]
    a00 = Fraction(ev["A"][0][0])
    out = lemma1_mutants(cert, rng, upper_bound_mutants, ("witness_c",))
    out += [("evidence.A[0][0] + 1/10", with_field(cert, ["evidence", "A", 0, 0], frac(a00 + Fraction(1, 10))), "refute"),
            ("evidence.D + 1", with_field(cert, ["evidence", "D", 0, 0], frac(Fraction(ev["D"][0][0]) + 1)), "refute"),
            ("evidence.B with two inputs", with_field(cert, ["evidence", "B"], [r + ["0"] for r in ev["B"]]), "malformed"),
            ("deleted evidence.A", deleted(cert, ["evidence", "A"]), "malformed"),
            ("model.H + 1/10 (the realisation is of the H written before)",
             with_field(cert, ["model", "H"], "(" + cert["model"]["H"] + ") + 1/10"), "refute")]
    return out


def mimo_mutants(cert, rng, hapstab, cache, tmp):
    cl, m = cert["claim"], cert["model"]
    if cl["status"] == "upper_bound":
        return mimo_upper_bound_mutants(cert, rng) + mimo_model_mutants(cert, rng, hapstab, cache, tmp, *claim_ends(cl))
    if cl["status"] in ("lower_bound", "bounds"):
        return (lemma1_mutants(cert, rng, mimo_upper_bound_mutants, ("witness_c", "witness_s")) +
                mimo_model_mutants(cert, rng, hapstab, cache, tmp, *claim_ends(cl)))
    out = [("unmutated", cert, "accept")]
    exact_claim = cl["status"] == "exact"
    lo, hi, scale, tiny, gap, claim = level_frame(cert, rng)
    out.append(("lo > hi", claim(hi + tiny, hi), "refute"))
    if exact_claim:
        out.append(("exact value + tiny", with_field(cert, ["claim", "value"], frac(lo + tiny)), "refute"))
        out.append(("exact value - tiny", with_field(cert, ["claim", "value"], frac(lo - tiny)), "refute"))
        out.append(("exact value - 1/1000", with_field(cert, ["claim", "value"], frac(lo - Fraction(1, 1000))), "refute"))
        out.append(("exact made certified without a witness", claim(lo - scale, hi), "malformed"))
        out.append(("added evidence.witness_c", with_field(cert, ["evidence", "witness_c"], "1"), "malformed"))
    else:
        out.append(("lo raised past the level", claim(hi + gap / 2 + tiny, hi + 2 * gap + tiny), "refute"))
        out.append(("lo raised to hi + tiny", claim(hi + tiny, hi + 2 * tiny), "refute"))
        out.append(("hi lowered below the level", claim(lo - 2 * gap - tiny, lo - gap / 2 - tiny), "refute"))
        osp = m["kind"] == "osp"  # an OSP claim holds only with lo > 0 (a value <= 0 is not the level)
        out.append(("lo lowered", claim(lo / 2 if osp and lo - scale <= 0 else lo - scale, hi), "accept"))
        if osp:
            out.append(("OSP lo lowered to <= 0", claim(min(-scale, lo - scale), hi), "refute"))
        out.append(("hi raised", claim(lo, hi + scale), "accept"))
        out.append(("printed_lo is not the claimed lo", with_field(cert, ["claim", "printed_lo"], cl["printed_lo"] + "1"), "refute"))
        out.append(("printed_hi is not the claimed hi", with_field(cert, ["claim", "printed_hi"], cl["printed_hi"] + "1"), "refute"))
        c0, s0 = Fraction(cert["evidence"]["witness_c"]), Fraction(cert["evidence"]["witness_s"])
        t0 = s0 / (1 + c0) if c0 != -1 else Fraction(10 ** 6)
        for name, t in (("witness t + 1/1000", t0 + Fraction(1, 1000)), ("witness t x (1 + 10^-40)", t0 * (1 + Fraction(1, 10 ** 40))),
                        ("witness random", Fraction(rng.randint(0, 3000), 1000))):
            w = 1 + t * t
            mut = with_field(cert, ["evidence", "witness_c"], frac((1 - t * t) / w))
            out.append((name, with_field(mut, ["evidence", "witness_s"], frac(2 * t / w)), "agree"))
        out.append(("witness at theta = 0", with_field(with_field(cert, ["evidence", "witness_c"], "1"), ["evidence", "witness_s"], "0"), "agree"))
        out.append(("witness off the circle (s0 + 1/1000)", with_field(cert, ["evidence", "witness_s"], frac(s0 + Fraction(1, 1000))), "refute"))
        out.append(("witness off the circle (c0 = 2)", with_field(cert, ["evidence", "witness_c"], "2"), "refute"))
        for key in ("witness_c", "witness_s"):
            out.append(("deleted evidence." + key, deleted(cert, ["evidence", key]), "malformed"))
        out.append(("witness a decimal", with_field(cert, ["evidence", "witness_c"], "0.5"), "malformed"))
        out.append(("added evidence.witness_v", with_field(cert, ["evidence", "witness_v"], ["1", "0"]), "malformed"))
    return out + mimo_model_mutants(cert, rng, hapstab, cache, tmp, lo, hi)


def mimo_expect(lo, hi, other):
    """The expectation for the claim [lo, hi] on a model whose own certificate is `other`: false (disjoint
    from other's claim) is refuted; where other bounds the level only from above or by Lemma 1 (an OSP
    value <= 0, maybe with a zero of G on the circle, which makes the checkers refuse a range claim's model: exit 2)
    it is rejected, 1 or 2, the same by both; else the two checkers agree."""
    olo, ohi = claim_ends(other["claim"])
    if hi < olo or lo > ohi:
        return "rejected" if other["claim"]["status"] in ("upper_bound", "lower_bound", "bounds") and lo > -math.inf else "refute"
    return "agree"


def mimo_model_mutants(cert, rng, hapstab, cache, tmp, lo, hi):
    """The model edited (an entry of A, B, C, D; the other kind; shapes, fields), whatever the claim
    (lo = -inf for an upper bound only): hapstab's own certificate of the edited model decides."""
    m, out = cert["model"], []
    # one entry of A, B, C or D edited: hapstab's own certificate of the edited model decides
    for name, nm in mimo_entry_edits(m, rng):
        other = mimo_produce(hapstab, nm, cache, tmp, 30)
        if isinstance(other, dict):
            expect = mimo_expect(lo, hi, other)
        else:
            expect = "same"  # no certificate of the edited model (unstable A, ...): both checkers give one exit
        out.append(("model: " + name, with_field(cert, ["model"], nm), expect))
    for path in (["model"], ["claim"], ["evidence"], ["model", "A"], ["model", "B"], ["model", "C"], ["model", "D"], ["model", "T"],
                 ["model", "kind"], ["claim", "status"]):
        out.append(("deleted " + ".".join(path), deleted(cert, path), "malformed"))
    n, k = len(m["A"]), len(m["D"])
    unstable = [[frac(Fraction(x) + (2 if i == j else 0)) for j, x in enumerate(r)] for i, r in enumerate(m["A"])]
    out.append(("A + 2I (not Schur stable: the hypothesis)", with_field(cert, ["model", "A"], unstable), "malformed"))
    # the other level's kind: hapstab's own certificate of that kind decides (or both checkers give one exit)
    other_kind = "isp" if m["kind"] == "osp" else "osp"
    other = mimo_produce(hapstab, dict(m, kind=other_kind), cache, tmp, 30)
    if isinstance(other, dict):
        expect = mimo_expect(lo, hi, other)
    else:
        expect = "same"
    out.append(("kind " + other_kind, with_field(cert, ["model", "kind"], other_kind), expect))
    out.append(("kind unknown", with_field(cert, ["model", "kind"], "io"), "malformed"))
    out.append(("G not square (a row of C and D dropped)", with_field(with_field(cert, ["model", "C"], m["C"][:-1]), ["model", "D"],
                                                                      m["D"][:-1]), "malformed"))
    out.append(("D not m x m", with_field(cert, ["model", "D"], [r[:-1] for r in m["D"]]), "malformed"))
    out.append(("B with a row too few", with_field(cert, ["model", "B"], m["B"][:-1] if n > 1 else []), "malformed"))
    out.append(("A not square", with_field(cert, ["model", "A"], [r + ["0"] for r in m["A"]]), "malformed"))
    out.append(("an entry a decimal", with_field(cert, ["model", "D", 0, 0], "0.5"), "malformed"))
    out.append(("an entry a JSON number", with_field(cert, ["model", "D", k - 1, k - 1], 1), "malformed"))
    out.append(("T a decimal", with_field(cert, ["model", "T"], "0.001"), "malformed"))
    out.append(("T negative", with_field(cert, ["model", "T"], "-1/100"), "malformed"))
    out.append(("status numeric", with_field(cert, ["claim", "status"], "numeric"), "malformed"))
    out.append(("added model.H", with_field(cert, ["model", "H"], "1/(z - 1/2)"), "malformed"))
    out.append(("added model.delay", with_field(cert, ["model", "delay"], 1), "malformed"))
    out.append(("kind made passivity-level (SISO)", with_field(cert, ["kind"], "passivity-level"), "malformed"))
    return out


STABILITY_TEMPLATES = [  # (plant, operator or None, H, names): every device pole at s = 0 (exact data)
    ("1/(m*s^2)", None, "K + B*(z-1)/(T*z)", ["m", "K", "B"]),            # mass on a virtual wall (001)
    ("1/(m*s^2)", None, "K + B*2*(z-1)/(T*(z+1))", ["m", "K", "B"]),      # Tustin damper
    ("1/(m*s^2)", None, "K*(z - a)/(z - b)", ["m", "K", "a", "b"]),      # lead/lag wall
    ("1/(m*s^2)", "c*s", "K + B*(z-1)/(T*z)", ["m", "c", "K", "B"]),      # an operator's mass
    ("(1 + c*s)/(m*s^3)", None, "K + B*(z-1)/(T*z)", ["m", "c", "K", "B"]),  # an integrating device
]
# a mass-damper (one pole off s = 0, b of either sign: e^{-bT/m} transcendental; stability only), a spring (two)
POLE_TEMPLATES = [
    ("1/(m*s^2 + b*s)", None, "K + B*(z-1)/(T*z)", ["m", "b", "K", "B"]),
    ("1/(m*s^2 + b*s)", "c*s", "K + B*(z-1)/(T*z)", ["m", "b", "c", "K", "B"]),
    ("1/(m*s^2 + b*s + k)", None, "K + B*(z-1)/(T*z)", ["m", "b", "k", "K", "B"]),  # a spring: two poles off s = 0
]


def rand_stability(rng, templates=STABILITY_TEMPLATES):
    plant, op, H, names = rng.choice(templates)
    sets = {}
    for n in names:
        if n == "m":
            sets[n] = rng.choice(["1", "1/2", "3", "0.05"])
        elif n == "c":
            sets[n] = rng.choice(["1/10", "1", "0.002"])
        elif n == "K":
            sets[n] = str(rng.choice([rng.randint(1, 3000), rng.randint(1, 60000)]))
        elif n == "B":
            sets[n] = str(rng.randint(0, 30))
        elif n == "k":
            sets[n] = rng.choice(["100", "1000", "-50", "10000"])
        else:
            sets[n] = "%s0.%02d" % (rng.choice(["", "-"]), rng.randint(0, 95))
    m = {"plant": plant, "H": H, "set": sets, "T": rng.choice(["1/1000", "1/500", "1/4000"]),
         "delay": rng.choice([0, 0, 1, 1, 2, 3])}
    if op:
        m["operator"] = op
    return m


def stability_args(m):
    a = ["stability", "--plant", m["plant"], "--H", m["H"], "--T", m["T"], "--delay", str(m["delay"])]
    if "operator" in m:
        a += ["--operator", m["operator"]]
    for k, v in m["set"].items():
        a += ["--set", "%s=%s" % (k, v)]
    return a


def produce(hapstab, args, key, name, cache, tmp):
    """hapstab's certificate for the command `args` (cached under `key`), or the exit code when it
    writes none."""
    if key not in cache:
        path = os.path.join(tmp, name)
        if os.path.exists(path):
            os.remove(path)
        rc, _, _ = run(hapstab, args + ["--certificate", path])
        if rc in (0, 1) and os.path.exists(path):
            with open(path) as f:
                cache[key] = json.load(f)
        else:
            cache[key] = rc
    return cache[key]


def stability_produce(hapstab, m, cache, tmp):
    """hapstab's certificate of model m (dict), or the exit code when it writes none."""
    return produce(hapstab, stability_args(m), json.dumps(m, sort_keys=True), "s-edit.json", cache, tmp)


def proportional(a, b):
    a = [Fraction(x) for x in a]
    b = [Fraction(x) for x in b]
    while a and a[-1] == 0:
        a.pop()
    while b and b[-1] == 0:
        b.pop()
    if len(a) != len(b) or not a:
        return False
    r = a[-1] / b[-1]
    return all(x == r * y for x, y in zip(a, b))


def wrong_loop(cert, coeffs, name):
    """The certificate with evidence.charpoly = coeffs (another loop's) and the claim its verdict:
    a producer that built the wrong loop, consistently."""
    c = with_field(cert, ["evidence", "charpoly"], [frac(x) for x in coeffs])
    ok, _ = hapstab_check.schur_cohn([Fraction(x) for x in coeffs])
    c["claim"]["stable"] = ok
    return ("wrong loop: " + name, c, "refute")


def loop_edits(m, rng):
    """The edits of a one-DOF loop's model (stability, stability-max): --set values, T halved, the
    delay +- 1, a sign in H or the plant, the operator removed."""
    edits = model_edits(m, rng, fields=("H", "plant"))
    edits += [("T halved", dict(m, T=frac(Fraction(m["T"]) / 2))), ("delay + 1", dict(m, delay=m["delay"] + 1))]
    if m["delay"] > 0:
        edits.append(("delay - 1", dict(m, delay=m["delay"] - 1)))
    if "operator" in m:
        # with the operator's own parameters (c of c*s): a --set that names nothing is refused by the producer
        used = m["plant"] + " " + m["H"]
        sets = {k: v for k, v in m.get("set", {}).items() if re.search(r"\b%s\b" % re.escape(k), used)}
        edits.append(("operator removed", dict({k: v for k, v in m.items() if k != "operator"}, set=sets)))
    return edits


def pole_stability_mutants(cert, rng, hapstab, cache, tmp):
    """A `stability` certificate of a mass-damper or a spring (no evidence: the checkers derive c(z; E)
    and enclose E = e^{pT}, or e^{A_c T}, themselves): the claim flipped, the status, a charpoly added, the model edited (the
    producer's certificate of the edited model decides), fields deleted, malformed models."""
    out = [("unmutated", cert, "accept")]
    st = cert["claim"]["stable"]
    out.append(("claim.stable flipped", with_field(cert, ["claim", "stable"], not st), "refute"))
    out.append(("status certified -> exact", with_field(cert, ["claim", "status"], "exact"), "malformed"))
    out.append(("added evidence.charpoly", with_field(cert, ["evidence", "charpoly"], ["1", "1"]), "malformed"))
    m = cert["model"]
    for name, nm in loop_edits(m, rng):
        other = stability_produce(hapstab, nm, cache, tmp)
        if isinstance(other, dict):
            expect = "malformed" if "charpoly" in other["evidence"] else ("accept" if other["claim"]["stable"] == st else "refute")
        else:
            expect = "malformed" if other == 2 else "agree"
        out.append(("model: " + name, with_field(cert, ["model"], nm), expect))
    for path in (["model"], ["claim"], ["kind"], ["model", "plant"], ["model", "H"], ["model", "T"], ["model", "delay"],
                 ["claim", "stable"], ["claim", "status"]):
        out.append(("deleted " + ".".join(path), deleted(cert, path), "malformed"))
    out.append(("added model.frac_delay", with_field(cert, ["model", "frac_delay"], "1/2000"), "malformed"))
    return out + loop_malformed(cert)


def stability_mutants(cert, rng, hapstab, cache, tmp):
    if "charpoly" not in cert["evidence"]:
        return pole_stability_mutants(cert, rng, hapstab, cache, tmp)
    out = [("unmutated", cert, "accept")]
    cp = [Fraction(x) for x in cert["evidence"]["charpoly"]]
    st = cert["claim"]["stable"]
    out.append(("claim.stable flipped", with_field(cert, ["claim", "stable"], not st), "refute"))
    out.append(("status exact -> certified", with_field(cert, ["claim", "status"], "certified"), "accept"))
    k = Fraction(rng.choice([-3, 2, 7]), rng.choice([1, 5, 11]))
    out.append(("charpoly scaled", with_field(cert, ["evidence", "charpoly"], [frac(k * x) for x in cp]), "accept"))
    out.append(("charpoly with a trailing 0", with_field(cert, ["evidence", "charpoly"], [frac(x) for x in cp] + ["0"]), "accept"))
    i = rng.randrange(len(cp))
    for name, f in (("+ 1", lambda x: x + 1), ("x (1 + 10^-30)", lambda x: x * (1 + Fraction(1, 10 ** 30))),
                    ("negated", lambda x: -x)):
        moved = list(cp)
        moved[i] = f(cp[i])
        if moved[i] != cp[i]:
            out.append(("charpoly[%d] %s" % (i, name), with_field(cert, ["evidence", "charpoly"], [frac(x) for x in moved]), "refute"))
    out.append(("charpoly: leading term dropped", with_field(cert, ["evidence", "charpoly"], [frac(x) for x in cp[:-1]]), "refute"))
    if cp != cp[::-1] and cp != [-x for x in cp[::-1]]:
        out.append(("charpoly reversed", with_field(cert, ["evidence", "charpoly"], [frac(x) for x in cp[::-1]]), "refute"))
    # a producer that built the wrong loop, with the verdict of that loop (consistent evidence)
    m = cert["model"]
    for name, edit in (("delay + 1", {"delay": m["delay"] + 1}), ("T doubled", {"T": frac(Fraction(m["T"]) * 2)})):
        other = stability_produce(hapstab, dict(m, **edit), cache, tmp)
        if isinstance(other, dict):
            out.append(wrong_loop(cert, [Fraction(x) for x in other["evidence"]["charpoly"]], name))
    # the model edited: expectation from the producer's certificate of the edited model
    for name, nm in loop_edits(m, rng):
        other = stability_produce(hapstab, nm, cache, tmp)
        if isinstance(other, dict) and "charpoly" not in other["evidence"]:
            expect = "malformed"  # the edit put a device pole off s = 0 (b 0 -> b): a charpoly there is malformed
        elif isinstance(other, dict):
            same = proportional(other["evidence"]["charpoly"], cp)
            expect = "refute" if not same or other["claim"]["stable"] != st else "accept"
        else:
            expect = "malformed" if other == 2 else "agree"
        out.append(("model: " + name, with_field(cert, ["model"], nm), expect))
    # malformed
    for path in (["model"], ["claim"], ["evidence"], ["kind"], ["model", "plant"], ["model", "H"], ["model", "T"],
                 ["model", "delay"], ["claim", "stable"], ["claim", "status"], ["evidence", "charpoly"]):
        out.append(("deleted " + ".".join(path), deleted(cert, path), "malformed"))
    out.append(("added model.frac_delay", with_field(cert, ["model", "frac_delay"], "1/2000"), "malformed"))
    out.append(("added evidence.roots_inside", with_field(cert, ["evidence", "roots_inside"], 1), "malformed"))
    out.append(("claim.stable as a string", with_field(cert, ["claim", "stable"], "true"), "malformed"))
    out.append(("status numeric", with_field(cert, ["claim", "status"], "numeric"), "malformed"))
    out.append(("charpoly entry a decimal", with_field(cert, ["evidence", "charpoly"], ["0.5"] + cert["evidence"]["charpoly"][1:]), "malformed"))
    out.append(("charpoly empty", with_field(cert, ["evidence", "charpoly"], []), "malformed"))
    # a pole written and cancelled: realised as written, a hidden mode of the loop (stop 80)
    out.append(("H: a pole at z = 1 written and cancelled", with_field(cert, ["model", "H"], "(" + m["H"] + ")*(z-1)/(z-1)"),
                "malformed"))
    out.append(("plant: a pole at s = 1 written and cancelled",
                with_field(cert, ["model", "plant"], "(" + m["plant"] + ")*(s-1)/(s-1)"), "malformed"))
    return out + loop_malformed(cert) + winding_mutants(cert, rng, hapstab, cache, tmp)


def winding_mutants(cert, rng, hapstab, cache, tmp):
    """The same loop decided by the argument principle (evidence.argument_principle, what the producer
    writes beyond degree 2000; the checkers take it at any degree): made from the charpoly certificate,
    accepted as it is and mutated -- the claim flipped, the status exact, the flag false or beside a
    charpoly, a delay +- 1 or a set value edited (expected by the producer's verdict of that model)."""
    w = with_field(with_field(deleted(cert, ["evidence", "charpoly"]), ["evidence", "argument_principle"], True),
                   ["claim", "status"], "certified")
    st = w["claim"]["stable"]
    out = [("argument principle: unmutated", w, "accept"),
           ("argument principle: claim.stable flipped", with_field(w, ["claim", "stable"], not st), "refute"),
           ("argument principle: status exact", with_field(w, ["claim", "status"], "exact"), "malformed"),
           ("argument principle: false", with_field(w, ["evidence", "argument_principle"], False), "malformed"),
           ("argument principle: beside a charpoly", with_field(w, ["evidence", "charpoly"], cert["evidence"]["charpoly"]), "malformed")]
    for name, nm in loop_edits(w["model"], rng)[:4]:
        other = stability_produce(hapstab, nm, cache, tmp)
        if isinstance(other, dict):
            expect = "malformed" if "charpoly" not in other["evidence"] else ("accept" if other["claim"]["stable"] == st else "refute")
        else:
            expect = "malformed" if other == 2 else "agree"
        out.append(("argument principle: model: " + name, with_field(w, ["model"], nm), expect))
    return out


def loop_malformed(cert):
    """Malformed models of a one-DOF loop (stability, stability-max): T negated, a negative delay, a
    plant that does not parse, has three poles off s = 0, is in z or is not strictly proper."""
    m = cert["model"]
    out = [("T negated", with_field(cert, ["model", "T"], "-" + m["T"]), "malformed"),
           ("delay negative", with_field(cert, ["model", "delay"], -1), "malformed"),
           ("plant unparsable", with_field(cert, ["model", "plant"], m["plant"] + "*("), "malformed"),
           ("plant with three poles off s = 0", with_field(cert, ["model", "plant"], "1/(m*s^3 + s^2 + s + 1)"), "malformed"),
           ("plant in z", with_field(cert, ["model", "plant"], "1/(z - 1)"), "malformed")]
    if "operator" not in m or cert["kind"] == "stability-max":  # P/(1 + c s^2 P) is strictly proper whatever P is: 1/m there is a spring
        out.append(("plant not strictly proper", with_field(cert, ["model", "plant"], "1/m"), "malformed"))
    return out


# The device G = s P (force -> velocity) of each plant P the stability templates write, in lowest terms: written
# as (P)*s it would cancel P's pole at s = 0, which the scene's parser refuses as a hidden mode (b = 0 included).
DEVICE_OF_PLANT = {"1/(m*s^2)": "1/(m*s)", "1/(m*s^2 + b*s)": "1/(m*s + b)", "(1 + c*s)/(m*s^3)": "(1 + c*s)/(m*s^2)",
                   "1/(m*s^2 + b*s + k)": "s/(m*s^2 + b*s + k)"}


def scene_of(m):
    """The one-DOF scene of a `stability` model (plant P, H, operator c*s, set, T, delay) for `stability
    --scene`: the device G = s P (force -> velocity, passive = false: no claim checked; DEVICE_OF_PLANT), the
    operator's c*s as tf "0" with mass [c], the wall H in z, the delay in samples. None when m is not of that
    form (a plant the templates do not write, e.g. a mutant's edited plant)."""
    plain = ("plant", "H", "T", "delay", "set")
    if not isinstance(m, dict) or any(k not in m for k in plain) or set(m) - set(plain) - {"operator"}:
        return None
    if not all(isinstance(m[k], str) for k in ("plant", "H", "T")) or not isinstance(m["set"], dict):
        return None
    if not isinstance(m["delay"], int) or isinstance(m["delay"], bool) or not all(isinstance(v, str) for v in m["set"].values()):
        return None
    op = m.get("operator")
    if op is not None and (not isinstance(op, str) or not op.endswith("*s")):
        return None
    device = DEVICE_OF_PLANT.get(m["plant"])
    if device is None:
        return None
    q = lambda t: json.dumps(t)  # a TOML basic string (JSON's escapes are TOML's)
    L = ["[scene]", "T = " + q(m["T"])]
    if m["set"]:
        L += ["[parameters]"] + ["%s = %s" % (k, q(v)) for k, v in sorted(m["set"].items())]
    L += ["[[device]]", 'name = "arm"', "tf = " + q(device), "passive = false"]
    if op is not None:
        L += ["[[operator]]", 'dofs = "arm"', 'tf = "0"', "mass = [%s]" % q(op[:-2])]
    L += ["[environment]", "tf = " + q(m["H"])]
    if m["delay"]:
        L += ["[delay]", 'samples = "%d"' % m["delay"]]
    return "\n".join(L) + "\n"


def scene_mutants(cert, rng, hapstab, cache, tmp, problems):
    """A `stability` certificate as `stability --scene` writes it (the model the scene's text, which
    the checkers read themselves, check/scene_model.hpp): the producer's own scene certificate must
    hold the plain one's claim and evidence; every mutant of the plain certificate whose model is a
    plain loop, with the scene of that model in its place, keeps its expectation (the same loop);
    and the scene's own malformations: sections and keys beyond the reading, a second device, a
    fractional delay, a parameter cycle, model.set naming no parameter. A producer that writes no
    scene certificate, or another claim or evidence, is a problem (appended to `problems`)."""
    base = scene_of(cert["model"])
    if base is None:
        return []
    path = os.path.join(tmp, "scene.toml")
    with open(path, "w") as f:
        f.write(base)
    produced = produce(hapstab, ["stability", "--scene", path], "scene:" + base, "s-scene.json", cache, tmp)
    if not isinstance(produced, dict):
        problems.append("stability --scene wrote no certificate (exit %s) for the scene of %s" % (produced, json.dumps(cert["model"])))
        return []
    out = [("scene: unmutated (stability --scene)", produced, "accept")]
    if produced["claim"] != cert["claim"] or produced["evidence"] != cert["evidence"]:
        problems.append("stability --scene's claim or evidence differ from --plant/--H's for %s" % json.dumps(cert["model"]))
    for name, c, expect in stability_mutants(cert, rng, hapstab, cache, tmp):
        text = scene_of(c.get("model"))
        if text is not None:
            out.append(("scene: " + name, dict(c, model={"scene": text, "set": {}}), expect))
    edits = [("[coupling] added", base + '[coupling]\ntf = "1/1000"\n'), ("[contact] added", base + "[contact]\n"),
             ("a second device", base + '[[device]]\nname = "second"\nm = "1"\n'),
             ("device.ss beside tf", base.replace('passive = false', 'passive = false\nss = { A = [["0"]] }')),
             ("a fractional delay", base + '[delay]\nsamples = "1/2"\n' if "[delay]" not in base else
              base.replace('samples = "', 'samples = "1/2 + ')),
             ("a parameter cycle", base.replace("[[device]]", '[parameters]\ncyc = "cyc"\n[[device]]') if "[parameters]" not in base
              else base.replace("[parameters]", '[parameters]\ncyc = "cyc"')),
             ("not TOML", base + "= =\n"), ("[environment] removed", base.split("[environment]")[0])]
    for name, text in edits:
        out.append(("scene: " + name, dict(produced, model={"scene": text, "set": {}}), "malformed"))
    out.append(("scene: model.set names no parameter", with_field(produced, ["model", "set"], {"nosuch": "1"}), "malformed"))
    out.append(("scene: deleted model.scene", deleted(produced, ["model", "scene"]), "malformed"))
    out.append(("scene: model.plant beside model.scene", with_field(produced, ["model", "plant"], "1/s^2"), "malformed"))
    return out


STABILITY_MAX_TEMPLATES = [  # (plant, operator or None, H, the parameter maximised, the others)
    ("1/(m*s^2)", None, "K + B*(z-1)/(T*z)", "K", ["m", "B"]),             # the stiffness of a wall (001)
    ("1/(m*s^2)", None, "K + B*(z-1)/(T*z)", "B", ["m", "K"]),             # its damper
    ("1/(m*s^2)", None, "K + B*2*(z-1)/(T*(z+1))", "K", ["m", "B"]),       # Tustin damper: a pole at z = -1
    ("1/(m*s^2)", None, "K*(z - a)/(z - b)", "K", ["m", "a", "b"]),       # a lead/lag wall's gain
    ("1/(m*s^2)", "c*s", "K + B*(z-1)/(T*z)", "K", ["m", "c", "B"]),       # an operator's mass
    ("(1 + c*s)/(m*s^3)", None, "K + B*(z-1)/(T*z)", "K", ["m", "c", "B"]),  # an integrating device
    ("1/(m*s^2)", None, "K*(z-1)/(T*z) + B", "K", ["m", "B"]),             # K a damper gain: a root at z = 1 for every K
    ("1/(m*s^2)", None, "C - K + B*(z-1)/(T*z)", "K", ["m", "C", "B"]),   # a stiffness C softened by K: exact at z = 1
    ("1/(m*s^2)", None, "C - K + B*(z-1)/(T*z)", "K", ["m", "C", "B"]),
]


def rand_stability_max(rng):
    plant, op, H, name, others = rng.choice(STABILITY_MAX_TEMPLATES)
    m = rand_stability(rng)  # T, delay and the draws of m, c, a, b
    sets = {}
    for n in others:
        if n == "B":  # mostly a damper that the loop needs; sometimes none or a negative one (K_max = 0)
            sets[n] = str(rng.choice([rng.randint(1, 30)] * 6 + [0, -rng.randint(1, 5)]))
        elif n in ("K", "C"):
            sets[n] = str(rng.randint(1, 3000))
        elif n in m["set"]:
            sets[n] = m["set"][n]
        else:
            sets[n] = {"m": rng.choice(["1", "1/2", "3"]), "c": rng.choice(["1/10", "1", "0.002"])}.get(
                n, "%s0.%02d" % (rng.choice(["", "-"]), rng.randint(0, 95)))
    out = {"plant": plant, "H": H, "set": sets, "name": name, "T": m["T"], "delay": m["delay"]}
    if op:
        out["operator"] = op
    return out


def stability_max_args(m, digits):
    return stability_args({k: v for k, v in m.items() if k != "name"}) + ["--max", m["name"], "--digits", str(digits)]


def stability_max_produce(hapstab, m, cache, tmp, digits=20):
    return produce(hapstab, stability_max_args(m, digits), "smax%d" % digits + json.dumps(m, sort_keys=True), "sm-edit.json", cache, tmp)


def stability_max_truth(hapstab, m, cache):
    """hapstab's K_max of the stability-max model m at 40 digits."""
    return sup_truth(hapstab, stability_max_args(m, 40), "smax-truth" + json.dumps(m, sort_keys=True), cache)


def stability_max_mutants(cert, rng, hapstab, cache, tmp):
    out = [("unmutated", cert, "accept")]
    m, ev = cert["model"], cert["evidence"]
    claim = max_claim(cert)
    q = cert["claim"]["quantity"]

    def claimed(lo, hi, evidence):
        return dict(copy.deepcopy(cert), claim={"quantity": q, "status": "certified", "lo": frac(lo), "hi": frac(hi)}, evidence=evidence)
    if claim == "inf":
        out.append(("+inf claimed as 1", claimed(1, 1, {"stable_at": "1/2"}), "refute"))
    elif claim[1] == 0:  # K_max = 0: unstable on (0, e], D root-free there
        e = Fraction(ev["unstable_at"])
        out.append(("K_max = 0 claimed as [e, 2e]", claimed(e, 2 * e, {"stable_at": frac(e / 2)}), "refute"))
        out.append(("K_max = 0 claimed +inf", with_field(with_field(cert, ["claim"], {"quantity": q, "status": "exact", "infinite": True}),
                                                         ["evidence"], {"stable_at": frac(e)}), "refute"))
        out.append(("unstable_at = 0", with_field(cert, ["evidence", "unstable_at"], "0"), "refute"))
        out.append(("unstable_at negative", with_field(cert, ["evidence", "unstable_at"], frac(-e)), "refute"))
        out.append(("unstable_at halved", with_field(cert, ["evidence", "unstable_at"], frac(e / 2)), "accept"))
        out.append(("unstable_at x 10^6 (past D's roots?)", with_field(cert, ["evidence", "unstable_at"], frac(e * 10 ** 6)), "agree"))
        out.append(("deleted evidence.unstable_at", deleted(cert, ["evidence", "unstable_at"]), "malformed"))
        out.append(("added evidence.stable_at", with_field(cert, ["evidence", "stable_at"], frac(e)), "malformed"))
    else:
        lo, hi = claim
        K0 = Fraction(ev["stable_at"])
        tiny = max(hi, Fraction(1)) / 10 ** rng.randint(40, 60)
        gap = max(hi - lo, tiny)
        mid = (K0 + lo) / 2
        out.append(("lo raised past the crossing", claimed(hi + gap / 2 + tiny, hi + 2 * gap + tiny, ev), "refute"))
        out.append(("claim and stable_at moved above the crossing", claimed(2 * hi + 1, 3 * hi + 2, {"stable_at": frac(hi * 3 / 2 + 1)}), "refute"))
        out.append(("hi lowered below the crossing", claimed(mid, lo - tiny, ev), "refute"))
        out.append(("hi lowered to stable_at's level", claimed(K0 / 2, K0, {"stable_at": frac(K0 / 3)}), "refute"))
        out.append(("lo lowered (still above stable_at)", claimed(mid, hi, ev), "accept"))
        out.append(("stable_at moved inside (0, lo)", with_field(cert, ["evidence", "stable_at"], frac(lo * Fraction(rng.randint(1, 99), 100))), "accept"))
        out.append(("stable_at = lo", with_field(cert, ["evidence", "stable_at"], frac(lo)), "refute"))
        out.append(("stable_at = 0", with_field(cert, ["evidence", "stable_at"], "0"), "refute"))
        out.append(("stable_at negative", with_field(cert, ["evidence", "stable_at"], frac(-K0)), "refute"))
        out.append(("stable_at above lo", with_field(cert, ["evidence", "stable_at"], frac(hi + gap)), "refute"))
        out.append(("lo > hi", claimed(hi + tiny, hi, ev), "refute"))
        out.append(("lo negative", claimed(-1 - lo, hi, ev), "refute"))
        out.append(("hi raised", claimed(lo, hi + max(hi, Fraction(1)) / 10, ev), "agree"))
        out.append(("claimed +inf", with_field(with_field(cert, ["claim"], {"quantity": q, "status": "certified", "infinite": True}),
                                               ["evidence"], ev), "refute"))
        out.append(("claimed 0", with_field(with_field(cert, ["claim"], {"quantity": q, "status": "exact", "value": "0"}),
                                            ["evidence"], {"unstable_at": frac(K0)}), "refute"))
        if cert["claim"]["status"] == "exact":
            out.append(("exact value + tiny", with_field(cert, ["claim", "value"], frac(lo + tiny)), "refute"))
            out.append(("exact value - tiny", with_field(cert, ["claim", "value"], frac(lo - tiny)), "refute"))
        else:
            pl = cert["claim"]["printed_lo"]
            moved = pl[:-1] + str((int(pl[-1]) + 1) % 10) if pl[-1].isdigit() else pl + "1"
            out.append(("printed_lo is not the claimed lo", with_field(cert, ["claim", "printed_lo"], moved), "refute"))
        out.append(("deleted evidence.stable_at", deleted(cert, ["evidence", "stable_at"]), "malformed"))
        out.append(("added evidence.unstable_at", with_field(cert, ["evidence", "unstable_at"], frac(hi)), "malformed"))
        out.append(("stable_at a decimal", with_field(cert, ["evidence", "stable_at"], "0.5"), "malformed"))
    # the model edited: hapstab's own K_max of the edited model (40 digits) decides
    edits = loop_edits(m, rng) + [("T doubled", dict(m, T=frac(Fraction(m["T"]) * 2)))]
    others = [k for k in m["set"] if k != "m"]
    if others:
        edits.append(("name: another parameter maximised", dict(m, name=rng.choice(others), set=dict(m["set"], **{m["name"]: "1"}))))
    for name, nm in edits:
        if "name" in nm and nm["name"] in nm["set"]:  # the new parameter has no value: the old one gets 1
            nm = dict(nm, set={k: v for k, v in nm["set"].items() if k != nm["name"]})
        truth = stability_max_truth(hapstab, nm, cache)
        if truth is None:
            expect = "same"  # no answer for the edited model (or it is refused): both checkers give one exit
        elif truth == "inf" or claim == "inf":
            expect = "agree" if truth == claim else "refute"
        else:
            expect = "refute" if claim[1] < truth[0] or claim[0] > truth[1] else "agree"
        out.append(("model: " + name, with_field(cert, ["model"], nm), expect))
    # malformed
    for path in (["model"], ["claim"], ["evidence"], ["kind"], ["model", "plant"], ["model", "H"], ["model", "name"], ["model", "T"],
                 ["model", "delay"], ["claim", "status"]):
        out.append(("deleted " + ".".join(path), deleted(cert, path), "malformed"))
    K, h = m["name"], m["H"]
    out.append(("the parameter given a value", with_field(cert, ["model", "set"], dict(m["set"], **{K: "1"})), "malformed"))
    out.append(("H not affine (times the parameter)", with_field(cert, ["model", "H"], "(" + h + ")*" + K), "malformed"))
    out.append(("H not affine (over 1 + the parameter)", with_field(cert, ["model", "H"], "(" + h + ")/(1 + " + K + ")"), "malformed"))
    out.append(("the parameter in the plant", with_field(cert, ["model", "plant"], "1/((m + %s)*s^2)" % K), "malformed"))
    out.append(("name of no parameter", with_field(cert, ["model", "name"], "Q"), "malformed"))
    out.append(("added model.frac_delay", with_field(cert, ["model", "frac_delay"], "1/2000"), "malformed"))
    out.append(("added evidence.charpoly", with_field(cert, ["evidence", "charpoly"], ["1"]), "malformed"))
    out.append(("claim.infinite a string", with_field(cert, ["claim", "infinite"], "yes"), "malformed"))
    out.append(("status numeric", with_field(cert, ["claim", "status"], "numeric"), "malformed"))
    return out + loop_malformed(cert)


WEDGE_TEMPLATES = [  # H(z) of paper 002's examples and of virtual walls
    ("K + B*(z-1)/(T*z)", ["K", "B"]),
    ("K*(z + 1)/(z^2 - a*z)", ["K", "a"]),
    ("K*(z - a)/(z - b)", ["K", "a", "b"]),
    ("K*(1 - a)/(z - a)", ["K", "a"]),
    ("K/(z^2 - b*z + c)", ["K", "b", "c"]),
]


def rand_wedge(rng):
    H, names = rng.choice(WEDGE_TEMPLATES)
    sets = {}
    for n in names:
        if n == "K":
            sets[n] = rng.choice([str(rng.randint(1, 20)), "%d/%d" % (rng.randint(1, 20), rng.randint(2, 40))])
        elif n == "B":
            sets[n] = str(rng.randint(0, 30))
        elif n == "k":
            sets[n] = rng.choice(["100", "1000", "-50", "10000"])
        else:
            sets[n] = "%s0.%02d" % (rng.choice(["", "-"]), rng.randint(0, 95))
    if "c" in sets:  # z^2 - b z + c stable
        c = Fraction(sets["c"])
        sets["b"] = frac(Fraction(rng.randint(-90, 90), 100) * (1 + c))
    return {"H": H, "set": sets, "T": rng.choice(["1/1000", "1/100", "1"])}


def wedge_args(m):
    a = ["wedge", "--H", m["H"], "--T", m["T"]]
    for k, v in m["set"].items():
        a += ["--set", "%s=%s" % (k, v)]
    return a


def wedge_produce(hapstab, m, cache, tmp):
    """hapstab's wedge certificate of model m, or the exit code when it writes none."""
    return produce(hapstab, wedge_args(m), "wedge" + json.dumps(m, sort_keys=True), "w-edit.json", cache, tmp)


WEDGE_CLAIMS = ("wedge", "tsypkin", "h_stable", "closed_loop_stable", "dc_gain_nonnegative")


WEDGE_RANGES = ("wedge_margin", "tsypkin_margin", "wedge_gain", "tsypkin_gain")


def margin_disjoint(a, b):
    """Two claimed ranges ({lo, hi} or {infinite}) that cannot both hold."""
    if a is None or b is None:
        return False
    if "infinite" in a or "infinite" in b:
        return ("infinite" in a) != ("infinite" in b)
    return Fraction(a["hi"]) < Fraction(b["lo"]) or Fraction(b["hi"]) < Fraction(a["lo"])


def wedge_margin_mutants(cert, rng):
    """The margins and gains k* of both criteria: each range moved past the value, printed digits
    moved, the witness moved or removed, an infinite gain made finite and back."""
    out = []
    cl, ev = cert["claim"], cert["evidence"]
    for key in ("wedge", "tsypkin"):
        w = key + "_witness_c"
        for field in (key + "_margin", key + "_gain"):
            r = cl.get(field)
            if r is None:
                continue
            if "infinite" in r:
                out.append((field + " +inf made [1, 2]", with_field(cert, ["claim", field], {"lo": "1", "hi": "2"}), "malformed" if w not in ev else "refute"))
                out.append((field + ".infinite false", with_field(cert, ["claim", field], {"infinite": False}), "malformed"))
                continue
            lo, hi = Fraction(r["lo"]), Fraction(r["hi"])
            d = max(hi - lo, abs(hi) / 10 ** 20, Fraction(1, 10 ** 40))
            def ranged(l, h, printed=False):
                o = {"lo": frac(l), "hi": frac(h)}
                if printed and "printed" in r:
                    o["printed"] = r["printed"]
                return with_field(cert, ["claim", field], o)
            gain = field.endswith("_gain")
            if not gain or lo - 2 * d > 0:
                out.append((field + " below the value", ranged(lo - 2 * d, lo - d), "refute"))
            out.append((field + " above the value", ranged(hi + d, hi + 2 * d), "refute"))
            out.append((field + " lo > hi", ranged(hi + d, lo - d) if not gain or lo - d > 0 else ranged(hi + d, lo), "refute"))
            out.append((field + " widened (printed dropped)", ranged(lo - d if not gain else lo / 2, hi + d), "accept"))
            if "printed" in r:  # an end 10 units of the printed last digit away: it no longer rounds to it
                out.append((field + " widened, printed kept", ranged(lo, hi + 10 * last_unit(r["printed"]), True), "refute"))
            out.append(("made +inf" if gain else field + " made a gain", with_field(cert, ["claim", field], {"infinite": True}),
                        "refute" if gain else "malformed"))
            if "printed" in r:
                out.append((field + " printed moved", with_field(cert, ["claim", field, "printed"], bump_last_digit(r["printed"])), "refute"))
                out.append((field + " printed not a number", with_field(cert, ["claim", field, "printed"], "0.1.2"), "malformed"))
            if gain:
                out.append((field + " lo = 0", ranged(Fraction(0), hi), "malformed"))
            out.append((field + " added x", with_field(cert, ["claim", field, "x"], "1"), "malformed"))
            out.append((field + " lo a decimal", with_field(cert, ["claim", field, "lo"], "0.5"), "malformed"))
        if w in ev:
            c0 = Fraction(ev[w])
            out.append((w + " outside [-1, 1]", with_field(cert, ["evidence", w], "2"), "refute"))
            for name, c1 in (("+ 1/1000", c0 + Fraction(1, 1000)), ("negated", -c0), ("random", Fraction(rng.randint(-1000, 1000), 1000))):
                if -1 <= c1 <= 1 and c1 != c0:
                    out.append((w + " " + name, with_field(cert, ["evidence", w], frac(c1)), "agree"))
            out.append(("deleted evidence." + w, deleted(cert, ["evidence", w]), "malformed"))
            out.append((w + " a decimal", with_field(cert, ["evidence", w], "0.5"), "malformed"))
            rest = deleted(cert, ["claim", key + "_margin"]) if key + "_margin" in cl else cert
            finite_gain = key + "_gain" in cl and "infinite" not in cl[key + "_gain"]
            out.append(("deleted claim." + key + "_margin", rest, "accept" if finite_gain else "malformed"))
    return out


def wedge_mutants(cert, rng, hapstab, cache, tmp):
    out = [("unmutated", cert, "accept")]
    for key in WEDGE_CLAIMS:
        out.append(("claim.%s flipped" % key, with_field(cert, ["claim", key], not cert["claim"][key]), "refute"))
    m = cert["model"]
    edits = model_edits(m, rng, SET_MOVES + (("x 2", lambda x: 2 * x),))
    edits.append(("T x 10", dict(m, T=frac(Fraction(m["T"]) * 10))))
    h = m["H"]
    for name, nm in edits:
        other = wedge_produce(hapstab, nm, cache, tmp)
        if isinstance(other, dict):
            same = all(other["claim"][k] == cert["claim"][k] for k in WEDGE_CLAIMS)
            disjoint = any(margin_disjoint(cert["claim"].get(k), other["claim"].get(k)) for k in WEDGE_RANGES)
            expect = "refute" if not same or disjoint else "accept" if other["claim"] == cert["claim"] and other["evidence"] == cert["evidence"] else "agree"
        else:
            expect = "malformed" if other == 2 else "agree"
        out.append(("model: " + name, with_field(cert, ["model"], nm), expect))
    out += wedge_margin_mutants(cert, rng)
    for path in (["model"], ["claim"], ["evidence"], ["kind"], ["model", "H"], ["model", "T"], ["claim", "status"]) + tuple(
            ["claim", k] for k in WEDGE_CLAIMS):
        out.append(("deleted " + ".".join(path), deleted(cert, path), "malformed"))
    out.append(("added model.delay", with_field(cert, ["model", "delay"], 1), "malformed"))
    out.append(("added evidence.witness_c", with_field(cert, ["evidence", "witness_c"], "0"), "malformed"))
    out.append(("added claim.margin", with_field(cert, ["claim", "margin"], "0"), "malformed"))
    out.append(("claim.wedge as a string", with_field(cert, ["claim", "wedge"], "true"), "malformed"))
    out.append(("status certified", with_field(cert, ["claim", "status"], "certified"), "malformed"))
    out.append(("T negated", with_field(cert, ["model", "T"], "-" + m["T"]), "malformed"))
    out.append(("H unparsable", with_field(cert, ["model", "H"], h + "*("), "malformed"))
    out.append(("H not causal", with_field(cert, ["model", "H"], "z^2 + " + h), "malformed"))
    out.append(("H with a pole on the circle", with_field(cert, ["model", "H"], "(" + h + ")/(z - 1)"), "malformed"))
    return out


LC_TEMPLATES = [  # (H, the values drawn): loops of paper 002 (4) that oscillate for gains above the wedge's k*
    ("(z + 1)/(z^2 - a*z)", "a"),        # paper 002's example, its k* = 1.11 at a = 0.5
    ("1/(z^2 - b*z + c)", "bc"),          # a lightly damped resonance
    ("(z + d)/(z^2 - b*z + c)", "bcd"),
    ("1/((z - a)*(z^2 - b*z + c))", "abc"),
]


def rand_limit_cycle(rng):
    """A limit-cycle model: H of LC_TEMPLATES, a gain k in [0.6, 4], rho 1 or random."""
    H, names = rng.choice(LC_TEMPLATES)
    sets = {}
    for n in sorted(names, key=lambda x: x != "c"):  # c first: b is drawn against it
        if n == "c":
            sets[n] = frac(Fraction(rng.randint(30, 95), 100))
        elif n == "b":
            c = Fraction(sets["c"])
            sets[n] = frac(Fraction(rng.randint(-95, 95), 100) * (1 + c))
        else:
            sets[n] = frac(Fraction(rng.randint(-80, 80), 100))
    gain = frac(Fraction(rng.randint(60, 400), 100))
    rho = rng.choice(["1", "1", frac(Fraction(rng.randint(1, 50), rng.randint(1, 20)))])
    return {"H": H, "set": sets, "T": "1", "gain": gain, "rho": rho}


def lc_args(m):
    a = ["limit-cycle", "--H", m["H"], "--gain", m["gain"], "--rho", m["rho"], "--steps", "20000", "--exact"]
    for k, v in m["set"].items():
        a += ["--set", "%s=%s" % (k, v)]
    return a


def lc_produce(hapstab, m, cache, tmp):
    """hapstab's limit-cycle certificate of model m, or the exit code when it writes none."""
    return produce(hapstab, lc_args(m), "lc" + json.dumps(m, sort_keys=True), "lc-edit.json", cache, tmp)


def decimal20(x):
    """x to 20 significant digits, rounded to nearest (as a plain or scientific decimal)."""
    if x == 0:
        return "0"
    e = len(str(abs(x.numerator) // abs(x.denominator))) - 1 if abs(x) >= 1 else -len(str(abs(x.denominator) // abs(x.numerator)))
    while abs(x) >= Fraction(10) ** (e + 1):
        e += 1
    while abs(x) < Fraction(10) ** e:
        e -= 1
    m = round(x / Fraction(10) ** (e - 19))
    return "%se%d" % (str(m), e - 19)


def last_unit(t):
    """The unit of the last mantissa digit of the decimal t ("1.25e-3": 10^-5)."""
    mant, _, exp = t.lower().partition("e")
    return Fraction(10) ** (int(exp or 0) - len(mant.partition(".")[2]))


def bump_last_digit(t):
    """The decimal t with its last mantissa digit moved by 5 (so it is 5 units off)."""
    mant = t.split("e")[0].split("E")[0]
    i = len(mant) - 1
    return t[:i] + str((int(t[i]) + 5) % 10) + t[i + 1:]


def same_lure_loop(m, nm):
    """Whether the edited model nm is the same loop (4) as m (H reduced, k, rho: the independent checker's reading)."""
    try:
        return hapstab_check.lure_loop(m) == hapstab_check.lure_loop(nm)
    except Exception:  # a model the checker cannot read is not the same loop
        return False


def lc_mutants(cert, rng, hapstab, cache, tmp):
    out = [("unmutated", cert, "accept")]
    cl, ev, m = cert["claim"], cert["evidence"], cert["model"]
    P, amp, y = cl["period"], Fraction(cl["amplitude"]), [Fraction(v) for v in ev["y"]]
    loop = hapstab_check.lure_loop(m)  # only to draw the next sample of the orbit (a phase shift)
    y_next = hapstab_check.lc_next(loop, y)
    out.append(("state moved one sample along the orbit", with_field(cert, ["evidence", "y"], [frac(v) for v in y[1:] + [y_next]]), "accept"))
    scaled = with_field(cert, ["model"], dict(m, rho=frac(2 * Fraction(m["rho"]))))
    scaled["evidence"]["y"] = [frac(2 * v) for v in y]
    scaled["claim"]["amplitude"] = frac(2 * amp)
    scaled["claim"]["printed_amplitude"] = decimal20(2 * amp)
    out.append(("rho, the state and the amplitude doubled (4) is homogeneous", scaled, "accept"))
    out.append(("rho doubled alone", with_field(cert, ["model", "rho"], frac(2 * Fraction(m["rho"]))), "refute"))
    if "attracting" in cl:
        out.append(("attracting flipped", with_field(cert, ["claim", "attracting"], not cl["attracting"]), "refute"))
        out.append(("attracting deleted (no claim)", deleted(cert, ["claim", "attracting"]), "accept"))
        out.append(("attracting as a string", with_field(cert, ["claim", "attracting"], "true"), "malformed"))
    for name, p in (("period + 1", P + 1), ("period - 1", P - 1), ("period x 2 (not the least)", 2 * P)):
        if p >= 1:
            out.append((name, with_field(cert, ["claim", "period"], p), "refute"))
    tiny = max(abs(amp), Fraction(1)) / 10 ** rng.randint(30, 60)
    out.append(("amplitude + tiny", with_field(cert, ["claim", "amplitude"], frac(amp + tiny)), "refute"))
    out.append(("amplitude x 2", with_field(cert, ["claim", "amplitude"], frac(2 * amp)), "refute"))
    out.append(("amplitude as max |y|", with_field(cert, ["claim", "amplitude"], frac(max(abs(v) for v in y) + (0 if max(abs(v) for v in y) != amp else 1))), "refute"))
    out.append(("printed amplitude moved", with_field(cert, ["claim", "printed_amplitude"], bump_last_digit(cl["printed_amplitude"])), "refute"))
    out.append(("free_steps + 1", with_field(cert, ["claim", "free_steps"], cl["free_steps"] + 1), "refute"))
    if cl["free_steps"] > 0:
        out.append(("free_steps - 1", with_field(cert, ["claim", "free_steps"], cl["free_steps"] - 1), "refute"))
    i = rng.randrange(len(y))
    for name, v in (("+ tiny", y[i] + tiny), ("x 1.001", y[i] * Fraction(1001, 1000) if y[i] else Fraction(1, 1000)), ("negated", -y[i] if y[i] else Fraction(1))):
        out.append(("y[%d] %s" % (i, name), with_field(cert, ["evidence", "y"], [frac(v) if j == i else ev["y"][j] for j in range(len(y))]), "refute"))
    for name, nm in model_edits(m, rng, SET_MOVES) + [("gain x 1.001", dict(m, gain=frac(Fraction(m["gain"]) * Fraction(1001, 1000))))]:
        # the old orbit's state run on another loop does not repeat (the recursion's coefficients
        # changed); a model the producer refuses (exit 2: ill-posed, not causal) is malformed
        key = "lc-valid" + json.dumps(nm, sort_keys=True)
        if key not in cache:
            cache[key] = run(hapstab, [x for x in lc_args(nm) if x != "--exact"])[0]
        expect = "malformed" if cache[key] == 2 else "refute"
        if expect == "refute" and same_lure_loop(m, nm):
            expect = "accept"  # the edit did not change the loop: a sign flipped on a term whose parameter is 0
        out.append(("model: " + name, with_field(cert, ["model"], nm), expect))
    for path in (["model"], ["claim"], ["evidence"], ["kind"], ["model", "H"], ["model", "T"], ["model", "gain"], ["model", "rho"],
                 ["claim", "status"], ["claim", "period"], ["claim", "amplitude"], ["claim", "printed_amplitude"],
                 ["claim", "free_steps"], ["evidence", "y"]):
        out.append(("deleted " + ".".join(path), deleted(cert, path), "malformed"))
    out.append(("added model.delay", with_field(cert, ["model", "delay"], 1), "malformed"))
    out.append(("added evidence.x0", with_field(cert, ["evidence", "x0"], ["0"]), "malformed"))
    out.append(("y one sample long", with_field(cert, ["evidence", "y"], ev["y"] + ["0"]), "malformed"))
    out.append(("y a decimal", with_field(cert, ["evidence", "y"], ["0.5"] + ev["y"][1:]), "malformed"))
    out.append(("amplitude a decimal", with_field(cert, ["claim", "amplitude"], "1.5"), "malformed"))
    out.append(("printed amplitude not a number", with_field(cert, ["claim", "printed_amplitude"], "about 1"), "malformed"))
    out.append(("period 0", with_field(cert, ["claim", "period"], 0), "malformed"))
    out.append(("period a string", with_field(cert, ["claim", "period"], str(P)), "malformed"))
    out.append(("status certified", with_field(cert, ["claim", "status"], "certified"), "malformed"))
    out.append(("gain negative", with_field(cert, ["model", "gain"], "-" + m["gain"]), "malformed"))
    out.append(("rho 0", with_field(cert, ["model", "rho"], "0"), "malformed"))
    out.append(("H a constant", with_field(cert, ["model", "H"], "2"), "malformed"))
    out.append(("H not causal", with_field(cert, ["model", "H"], "z^3 + " + m["H"]), "malformed"))
    out.append(("H unparsable", with_field(cert, ["model", "H"], m["H"] + "*("), "malformed"))
    out.append(("1 + k H(inf) <= 0", with_field(cert, ["model", "H"], "-1 + 0*(" + m["H"] + ")"), "malformed"))
    return out


def rand_loop_scene(rng):
    """A random multi-DOF scene the stability-loop kind reads: 2-3 DOFs (mass-dampers, or 1/(m s + b) as
    tf or ss, open-loop unstable with b = -1), operators (b, or
    m, b, k, on one DOF; a tf impedance coupling two DOFs in a fifth), diagonal walls K + B(z-1)/(Tz)
    with a linking spring in 40 %, in z or s (backward Euler, Tustin), a gain g, a coupling (tf or ss) in
    30 %, a delay of 0-2 samples, fractions of one too. Conserved quantities: an operator spring written
    as tf "b + k/s" or as ss, and an ss device with its own position state."""
    N = rng.choice([2, 2, 3])
    T = rng.choice(["1/1000", "1/500"])
    L = ["[scene]", 'T = "%s"' % T, "[parameters]", 'g = "%s"' % rng.choice(["1/2", "1", "2", "5"]),
         'kc = "%d"' % (rng.randint(50, 2000) if rng.random() < 0.4 else 0)]
    blocks = set()
    for i in range(N):
        m, b = rng.choice(["1/10", "1/2", "1"]), rng.choice(["0", "1/2", "2", "-1"])
        form = rng.choice(["md", "md", "tf", "ss"]) if b != "-1" else rng.choice(["tf", "ss"])  # b < 0: open-loop unstable
        L += ["[[device]]", 'name = "d%d"' % i]
        if form == "md":
            L += ['m = "%s"' % m, 'b = "%s"' % b]
        elif form == "tf":
            L += ['tf = "1/(%s*s + %s)"' % (m, b), "passive = false"]
        elif rng.random() < 0.1:  # an undamped oscillator (s = +-j w) or a growing pair (+-w) the device hides
            w2 = rng.choice(["-4", "-9", "4"])
            L += ["# hidden device oscillator %s" % w2,
                  'ss = { A = [["-(%s)/(%s)", "0", "0"], ["0", "0", "1"], ["0", "%s", "0"]], B = [["1/(%s)"], ["0"], ["0"]], '
                  'C = [["1", "0", "0"]], D = [["0"]] }' % (b, m, w2, m), "passive = false"]
        elif rng.random() < 0.7:
            L += ['ss = { A = [["-(%s)/(%s)"]], B = [["1/(%s)"]], C = [["1"]], D = [["0"]] }' % (b, m, m), "passive = false"]
        else:  # with its own position state, which no output shows: a conserved quantity
            L += ['ss = { A = [["-(%s)/(%s)", "0"], ["1", "0"]], B = [["1/(%s)"], ["0"]], C = [["1", "0"]], D = [["0"]] }' % (b, m, m),
                  "passive = false"]
        if form != "md":
            blocks.add(i)
    for i in range(N):
        if rng.random() < 0.5:
            bo, ko = rng.choice(["1", "3"]), rng.choice([50, 500])
            spring = rng.random() < 0.5
            form = rng.choice(["m, b, k", "m, b, k", "tf", "ss"]) if spring else "m, b, k"
            L += ["[[operator]]", 'dofs = "d%d"' % i]
            if form == "tf":  # the spring in the operator's own state: a conserved quantity
                L += ['tf = "%s + %d/s"' % (bo, ko)]
            elif form == "ss":
                L += ['ss = { A = [["0"]], B = [["1"]], C = [["%d"]], D = [["%s"]] }' % (ko, bo)]
            else:
                L += ['b = "%s"' % bo]
                if spring:
                    L += ['k = "%d"' % ko] + ([] if i in blocks else ['m = "1/20"'])
    if rng.random() < 0.2:
        L += ["[[operator]]", 'dofs = ["d0", "d1"]', 'tf = [["2*(s + 3)/(s + 1)", "1/2"], ["1/2", "1"]]'] + (
            [] if blocks & {0, 1} else ['mass = ["1/50", "0"]'])
    Ks = [rng.randint(100, 3000) for _ in range(N)]
    Bs = [rng.choice([0, 1, 4]) for _ in range(N)]
    domain = rng.choice(["z", "backward_euler", "tustin"])
    rows = []
    for i in range(N):
        row = []
        for j in range(N):
            if i == j:
                links = (1 if i > 0 else 0) + (1 if i < N - 1 else 0)
                e = "%d + %d*kc + %d*s" % (Ks[i], links, Bs[i]) if domain != "z" else "%d + %d*kc + %d*(z-1)/(T*z)" % (Ks[i], links, Bs[i])
            elif abs(i - j) == 1:
                e = "-kc"
            else:
                e = "0"
            row.append('"%s"' % e)
        rows.append("[" + ", ".join(row) + "]")
    L.append("[environment]")
    if domain != "z":
        L += ['domain = "s"', 'method = "%s"' % domain]
    L += ["tf = [" + ", ".join(rows) + "]", 'gain = "g"']
    if rng.random() < 0.3:  # a coupling in parallel with the devices: spring-dampers' admittances, tf or ss
        kcs = [rng.choice([500, 2000, 8000]) for _ in range(N)]
        if rng.random() < 0.5:
            rows = [["\"T*z/((%d*T + 2)*z - 2)\"" % kcs[i] if i == j else '"0"' for j in range(N)] for i in range(N)]
            L += ["[coupling]", "tf = [" + ", ".join("[" + ", ".join(r) + "]" for r in rows) + "]"]
        else:  # a static compliance, as ss with no state
            L += ["[coupling]", "ss = { A = [], B = [], C = [], D = [%s] }" % ", ".join(
                "[" + ", ".join('"1/%d"' % kcs[i] if i == j else '"0"' for j in range(N)) + "]" for i in range(N))]
    elif rng.random() < 0.25:  # an ss coupling that hides a mode (NOT stable by it when |z| >= 1, z != 1: evidence.hidden)
        kc = rng.choice([500, 2000, 8000])
        h = rng.choice(["-1", "3/2", "-11/10", "1/2", "1", "pair"])
        Ah = [["3/5", "-4/5"], ["4/5", "3/5"]] if h == "pair" else [[h]]  # the pair: e^{+-j theta} on the circle
        r = len(Ah)
        unobs = rng.random() < 0.5
        Bm = [[("%d/%d" % (rng.randint(1, 3), 10 ** 4)) if unobs else "0" for _ in range(N)] for _ in range(r)]
        Cm = [["0" if unobs else "%d/%d" % (rng.randint(1, 3), 10 ** 4) for _ in range(r)] for _ in range(N)]
        Dm = [['"1/%d"' % kc if i == j else '"0"' for j in range(N)] for i in range(N)]
        q = lambda M: "[" + ", ".join("[" + ", ".join('"%s"' % x for x in row) + "]" for row in M) + "]"  # noqa: E731
        L += ["# hidden: %s %s" % ("unobservable" if unobs else "uncontrollable", h), "[coupling]",
              "ss = { A = %s, B = %s, C = %s, D = [%s] }" % (q(Ah), q(Bm), q(Cm), ", ".join("[" + ", ".join(r_) + "]" for r_ in Dm))]
    n = rng.choice(["0", "0", "1", "2", "1/2", "3/4", "3/2"])
    if n != "0":
        L += ["[delay]", 'samples = "%s"' % n]
    return "\n".join(L) + "\n"


def loop_produce(hapstab, scene, cache, tmp):
    """`stability --scene`'s certificate of the scene text (cached), or the exit code when it writes none."""
    path = os.path.join(tmp, "loop.toml")
    with open(path, "w") as f:
        f.write(scene)
    return produce(hapstab, ["stability", "--scene", path], "loop:" + scene, "l-edit.json", cache, tmp)


def hidden_loop_mutants(cert, rng):
    """stability-loop NOT stable by a hidden mode (evidence.hidden): A_h moved (refute: the subspace is not
    invariant with it), the basis scaled (accept) or zero (refute), the other kind or block, the claim's
    status or verdict (malformed), P beside it (malformed), the hidden mode moved inside the circle in the
    scene (refute), the wall's gain changed (accept: the coupling's hidden mode does not see it)."""
    h = cert["evidence"]["hidden"]
    Ah = [[Fraction(x) for x in r] for r in h["A_h"]]
    basis = [[Fraction(x) for x in r] for r in h["basis"]]
    scene = cert["model"]["scene"]
    moved = [[frac(x) for x in r] for r in Ah]
    moved[0][0] = frac(Ah[0][0] + Fraction(1, 10))
    out = [("unmutated", cert, "accept"),
           ("A_h[0][0] + 1/10", with_field(cert, ["evidence", "hidden", "A_h"], moved), "refute"),
           ("basis x 3", with_field(cert, ["evidence", "hidden", "basis"], [[frac(3 * x) for x in r] for r in basis]), "accept"),
           ("basis zero", with_field(cert, ["evidence", "hidden", "basis"], [["0"] * len(r) for r in basis]), "refute"),
           ("the other kind", with_field(cert, ["evidence", "hidden", "kind"],
                                         "unobservable" if h["kind"] == "uncontrollable" else "uncontrollable"), "rejected"),
           ("block environment (written as tf)", with_field(cert, ["evidence", "hidden", "block"], "environment"), "malformed"),
           ("block unknown", with_field(cert, ["evidence", "hidden", "block"], "plant"), "malformed"),
           ("status certified", with_field(cert, ["claim", "status"], "certified"), "malformed"),
           ("claim stable", with_field(cert, ["claim", "stable"], True), "malformed"),
           ("claim conserved 0 beside it", with_field(cert, ["claim", "conserved"], 0), "malformed"),
           ("P beside it", with_field(cert, ["evidence", "P"], [["1"]]), "malformed"),
           ("deleted evidence.hidden.A_h", deleted(cert, ["evidence", "hidden", "A_h"]), "malformed"),
           ("A_h a decimal", with_field(cert, ["evidence", "hidden", "A_h", 0, 0], "0.5"), "malformed"),
           ("scene: the wall's gain x 4", with_field(cert, ["model", "scene"], scene.replace('g = "', 'g = "4*', 1)), "accept")]
    if h["block"] == "device":  # the oscillator damped in the scene: A_h no longer describes it
        for w2 in ("-4", "-9", "4"):
            if '["0", "%s", "0"]]' % w2 in scene:
                out.append(("scene: the hidden oscillator damped", with_field(cert, ["model", "scene"], scene.replace(
                    '["0", "%s", "0"]]' % w2, '["0", "%s", "-1"]]' % w2, 1)), "refute"))
                break
        out.append(("the device renamed in the evidence", with_field(cert, ["evidence", "hidden", "name"], "nobody"), "malformed"))
    for old, new in (('[["-1"]]', '[["-1/2"]]'), ('[["3/2"]]', '[["2/3"]]'), ('[["-11/10"]]', '[["-9/10"]]'),
                     ('[["3/5", "-4/5"], ["4/5", "3/5"]]', '[["3/10", "-2/5"], ["2/5", "3/10"]]')):
        if "ss = { A = " + old in scene:
            out.append(("scene: the hidden mode moved inside", with_field(cert, ["model", "scene"], scene.replace("ss = { A = " + old, "ss = { A = " + new, 1)),
                        "refute"))
    return out


def loop_mutants(cert, rng, hapstab, cache, tmp):
    """stability-loop: the claim flipped, its count of conserved quantities changed, P scaled (accept for a positive factor), P asymmetric or cut
    (malformed), an entry of P moved (agree: a nearby P may still prove it), w scaled or zero, the scene
    edited (the edited scene's own certificate decides: another verdict refutes, the same one is
    agree, another order is malformed), sections and fields the checkers do not read."""
    if "hidden" in cert["evidence"]:
        return hidden_loop_mutants(cert, rng)
    out = [("unmutated", cert, "accept")]
    ev, st = cert["evidence"], cert["claim"]["stable"]
    P = [[Fraction(x) for x in r] for r in ev["P"]]
    n = len(P)
    flipped = with_field(cert, ["claim", "stable"], not st)
    if st:
        flipped["evidence"]["w"] = ["1"] + ["0"] * (n - 1)
    else:
        del flipped["evidence"]["w"]
    out.append(("claim flipped", flipped, "refute"))
    kc = cert["claim"].get("conserved", 0)
    out.append(("conserved + 1", with_field(cert, ["claim", "conserved"], kc + 1), "refute"))
    if kc:
        out.append(("conserved dropped", deleted(cert, ["claim", "conserved"]), "refute"))
    out.append(("conserved a string", with_field(cert, ["claim", "conserved"], str(kc)), "malformed"))
    out.append(("conserved negative", with_field(cert, ["claim", "conserved"], -1), "malformed"))
    k = Fraction(rng.choice([2, 3, 7]), rng.choice([1, 5, 11]))
    out.append(("P scaled by %s" % k, with_field(cert, ["evidence", "P"], [[frac(k * x) for x in r] for r in P]), "accept"))
    out.append(("P negated", with_field(cert, ["evidence", "P"], [[frac(-x) for x in r] for r in P]), "refute"))
    i, j = rng.randrange(n), rng.randrange(n)
    if i != j:
        asym = [[frac(x) for x in r] for r in P]
        asym[i][j] = frac(P[i][j] + 1)
        out.append(("P[%d][%d] alone moved (asymmetric)" % (i, j), with_field(cert, ["evidence", "P"], asym), "malformed"))
    moved = [[frac(x) for x in r] for r in P]
    moved[i][j] = moved[j][i] = frac(P[i][j] * Fraction(1001, 1000) + Fraction(1, 10 ** 6))
    out.append(("P[%d][%d] and P[%d][%d] moved" % (i, j, j, i), with_field(cert, ["evidence", "P"], moved), "agree"))
    out.append(("P's last row and column cut", with_field(cert, ["evidence", "P"], [[frac(x) for x in r[:-1]] for r in P[:-1]]), "malformed"))
    if not st:
        w = [Fraction(x) for x in ev["w"]]
        out.append(("w doubled", with_field(cert, ["evidence", "w"], [frac(2 * x) for x in w]), "accept"))
        out.append(("w zero", with_field(cert, ["evidence", "w"], ["0"] * n), "refute"))
        out.append(("w one entry short", with_field(cert, ["evidence", "w"], ev["w"][:-1]), "malformed"))
    scene = cert["model"]["scene"]
    half = (scene + '[delay]\nsamples = "1/2"\n') if "[delay]" not in scene else scene.replace('samples = "', 'samples = "1/2 + ', 1)
    edits = [("a delay of half a sample more", half), ("g x 4", scene.replace('g = "', 'g = "4*', 1)), ("g / 4", scene.replace('g = "', 'g = "(1/4)*', 1)),
             ("T halved", scene.replace('T = "', 'T = "(1/2)*', 1)), ("the first mass x 4", scene.replace('m = "', 'm = "4*', 1)),
             ("the first damping + 5", scene.replace('b = "', 'b = "5 + ', 1))]
    for name, text in edits:
        if text == scene:
            continue
        other = loop_produce(hapstab, text, cache, tmp)
        if isinstance(other, dict):
            expect = "malformed" if len(other["evidence"]["P"]) != n else ("agree" if other["claim"]["stable"] == st else "refute")
        else:  # no verdict to compare with (undecided, no Stein P): the checkers agree, whatever they say
            expect = "same"
        out.append(("scene: " + name, with_field(cert, ["model", "scene"], text), expect))
    out.append(("scene: a [contact]", with_field(cert, ["model", "scene"], scene + "[contact]\n"), "malformed"))
    out.append(("scene: [multidof] perturb_C", with_field(cert, ["model", "scene"], scene + '[multidof]\nperturb_C = [["0", "1"], ["1", "0"]]\n'), "malformed"))
    out.append(("scene: an ss device", with_field(cert, ["model", "scene"],
                                                   scene.replace('[[device]]\nname = "d0"', '[[device]]\nname = "d0"\nss = { A = [["0"]] }', 1)), "malformed"))
    for path in (["model", "scene"], ["evidence", "P"], ["claim", "stable"], ["claim", "status"]):
        out.append(("deleted " + ".".join(path), deleted(cert, path), "malformed"))
    out.append(("status exact", with_field(cert, ["claim", "status"], "exact"), "malformed"))
    out.append(("added evidence.charpoly", with_field(cert, ["evidence", "charpoly"], ["1", "1"]), "malformed"))
    out.append(("added model.plant", with_field(cert, ["model", "plant"], "1/s^2"), "malformed"))
    return out


def rand_r(rng):
    T = rng.choice(["1/1000", "1/100", "3/7", "0.002", "1"])
    w = "%s%d/%d" % (rng.choice(["", "-"]), rng.randint(1, 10 ** 6), rng.randint(1, 10 ** 3))
    return T, w


KINDS = ("bound", "r", "bound-max", "passivity-level", "passivity-level-mimo", "stability", "stability-max", "wedge",
         "bound-inf", "limit-cycle", "multidof-witness", "stability-loop", "operator-passivity")  # multidof-witness: multidof-feasible beside it


def bound_produce(hapstab, m, digits, path, label, certs, skipped):
    """`bound`'s certificate of model m appended to certs as bound, bound-frac or bound-inf (b* =
    +inf), or the producer's refusal counted in skipped under `label`."""
    rc, _, err = run(hapstab, bound_args(m, digits) + ["--certificate", path])
    if rc != 0:
        why = label + ": " + err.strip().split("error: ", 1)[-1].split(" (")[0][:70]
        skipped[why] = skipped.get(why, 0) + 1
        return
    with open(path) as f:
        cert = json.load(f)
    certs.append(("bound-inf" if cert["claim"].get("infinite") else "bound" if "frac_delay" not in m else "bound-frac", cert))


def produce_certificates(a, kinds, rng, srng, tmp, cache, scache, mrng, irng, lrng):
    """The certificates of random models of each kind asked for, [(kind, certificate)], and the
    producer runs that wrote none {why: count}. rng draws every kind but stability-max (srng),
    passivity-level-mimo (mrng), bound-inf (irng) and limit-cycle (lrng); stability-loop has its own."""
    certs = []  # (kind, certificate)
    lrng2 = random.Random(a.seed * 1000 + 52)
    skipped = {}
    for i in range(a.models if "bound" in kinds else 0):
        m = rand_frac_model(rng) if i % 2 else rand_model(rng)
        path = os.path.join(tmp, "b%d.json" % i)
        bound_produce(a.hapstab, m, rng.choice([10, 15, 20, 30]), path, "bound-frac" if "frac_delay" in m else "bound", certs, skipped)
    for i in range(max(a.models // 4, 2) if "r" in kinds else 0):
        T, w = rand_r(rng)
        path = os.path.join(tmp, "r%d.json" % i)
        rc, out, err = run(a.hapstab, ["r", "--T", T, "--omega", w, "--terms", "10", "--certificate", path])
        if rc != 0:
            skipped["r: " + err.strip()[:60]] = skipped.get("r: " + err.strip()[:60], 0) + 1
            continue
        with open(path) as f:
            certs.append(("r", json.load(f)))
    for i in range(max(a.models // 2, 2) if "bound-max" in kinds else 0):
        m = rand_max_model(rng)
        path = os.path.join(tmp, "m%d.json" % i)
        rc, out, err = run(a.hapstab, max_args(m, rng.choice([10, 15, 20, 30])) + ["--certificate", path])
        if rc not in (0, 1) or not os.path.exists(path):
            why = "bound-max: " + err.strip().split("error: ", 1)[-1].split(" (")[0][:70]
            skipped[why] = skipped.get(why, 0) + 1
            if rc not in (1, 2):  # not a refusal: show the model
                print("bound-max producer exit %d on %s: %s" % (rc, json.dumps(m), err.strip()[:200]))
            continue
        with open(path) as f:
            certs.append(("bound-max", json.load(f)))
    for i in range(max(a.models // 2, 2) if "passivity-level" in kinds else 0):
        cert = level_produce(a.hapstab, rand_level(rng), scache, tmp, rng.choice([10, 17, 30]))
        if not isinstance(cert, dict):
            skipped["passivity-level: exit %s" % cert] = skipped.get("passivity-level: exit %s" % cert, 0) + 1
            continue
        certs.append(("passivity-level", cert))
    for i in range(max(a.models // 2, 2) if "passivity-level-mimo" in kinds else 0):
        m = rand_mimo(mrng)
        cert = mimo_produce(a.hapstab, m, scache, tmp, mrng.choice([10, 17, 30]))
        if not isinstance(cert, dict):
            skipped["passivity-level-mimo: exit %s" % cert] = skipped.get("passivity-level-mimo: exit %s" % cert, 0) + 1
            continue
        MIMO_FAMILIES[m["family"]] = MIMO_FAMILIES.get(m["family"], 0) + 1
        certs.append(("passivity-level-mimo", cert))
    for i in range(max(a.models // 2, 2) if "stability-max" in kinds else 0):
        m = rand_stability_max(srng)
        cert = stability_max_produce(a.hapstab, m, scache, tmp, srng.choice([10, 20, 30]))
        if not isinstance(cert, dict):
            skipped["stability-max: exit %s" % cert] = skipped.get("stability-max: exit %s" % cert, 0) + 1
            continue
        certs.append(("stability-max", cert))
    def collect(kind, count, make):
        """count certificates of `kind` from make() (a certificate, or the exit code of a producer run
        that wrote none: counted in skipped)."""
        for _ in range(count if kind in kinds else 0):
            cert = make()
            if isinstance(cert, dict):
                certs.append((kind, cert))
            else:
                skipped["%s: exit %s" % (kind, cert)] = skipped.get("%s: exit %s" % (kind, cert), 0) + 1
    collect("stability", max(a.models // 2, 2),
            lambda: stability_produce(a.hapstab, rand_stability(rng, STABILITY_TEMPLATES + POLE_TEMPLATES), scache, tmp))
    collect("stability-loop", max(a.models // 4, 2), lambda: loop_produce(a.hapstab, rand_loop_scene(lrng2), scache, tmp))
    collect("wedge", max(a.models // 2, 2), lambda: wedge_produce(a.hapstab, rand_wedge(rng), scache, tmp))
    orng = random.Random(a.seed * 1000 + 53)  # operator-passivity's own stream: certificates built here, true by construction
    for _ in range(max(a.models // 4, 2) if "operator-passivity" in kinds else 0):
        made = mutate_operator.rand_certificate(orng)
        if made:
            OPERATOR_ENTRIES[id(made[0])] = made[1]
            certs.append(("operator-passivity", made[0]))
    for i in range(max(a.models // 2, 2) if "bound-inf" in kinds else 0):
        m = rand_inf_model(irng)
        path = os.path.join(tmp, "i%d.json" % i)
        bound_produce(a.hapstab, m, 20, path, "bound-inf", certs, skipped)
    for i in range(max(a.models // 2, 2) if "limit-cycle" in kinds else 0):
        for _ in range(6):  # most random loops decay or diverge: up to six draws for one proven orbit
            cert = lc_produce(a.hapstab, rand_limit_cycle(lrng), scache, tmp)
            if isinstance(cert, dict):
                break
        if not isinstance(cert, dict):
            skipped["limit-cycle: exit %s" % cert] = skipped.get("limit-cycle: exit %s" % cert, 0) + 1
            continue
        certs.append(("limit-cycle", cert))
    wrng = random.Random(a.seed * 1000 + 51)  # multidof-witness's own stream
    for i in range(max(a.models // 2, 2) if "multidof-witness" in kinds else 0):
        cert = mutate_multidof.produce(a.hapstab, wrng, tmp, i)
        if not isinstance(cert, dict):
            skipped["multidof-witness: " + cert] = skipped.get("multidof-witness: " + cert, 0) + 1
            continue
        certs.append((cert["kind"], cert))
    return certs, skipped


def print_new_branches(certs):
    """The branches of the limit-cycle and bound-inf checkers the campaign reached."""
    lcs = [c for k, c in certs if k == "limit-cycle"]
    if lcs:
        periods = sorted(c["claim"]["period"] for c in lcs)
        print("  limit-cycle branches: attracting %d, not attracting %d, undecided (a sample on y = -rho) %d; order %s; "
              "periods %d..%d (median %d); with free samples %d; rho != 1 %d" % (
                  sum(1 for c in lcs if c["claim"].get("attracting") is True), sum(1 for c in lcs if c["claim"].get("attracting") is False),
                  sum(1 for c in lcs if "attracting" not in c["claim"]), sorted({len(c["evidence"]["y"]) for c in lcs}),
                  periods[0], periods[-1], periods[len(periods) // 2], sum(1 for c in lcs if c["claim"]["free_steps"] > 0),
                  sum(1 for c in lcs if c["model"]["rho"] != "1")))
    infs = [c for k, c in certs if k == "bound-inf"]
    if infs:
        at = [c for c in infs if "pole_c" in c["evidence"]]
        print("  bound-inf branches: integer delay %d, fractional %d; side +1 %d, -1 %d; pole at c = 1 %d, 0 %d, other %d, "
              "at the irrational band end %d, irrational inside the band %d, the local form at z = -1 %d" % (
                  sum(1 for c in infs if "frac_delay" not in c["model"]), sum(1 for c in infs if "frac_delay" in c["model"]),
                  sum(1 for c in at if c["evidence"]["side"] == 1), sum(1 for c in at if c["evidence"]["side"] == -1),
                  sum(1 for c in at if c["evidence"]["pole_c"] == "1"), sum(1 for c in at if c["evidence"]["pole_c"] == "0"),
                  sum(1 for c in at if c["evidence"]["pole_c"] not in ("0", "1")), sum(1 for c in infs if "end_lo" in c["evidence"]),
                  sum(1 for c in infs if "pole_lo" in c["evidence"]), sum(1 for c in infs if "pole_at_z" in c["evidence"])))
    if mutate_multidof.branches(certs):
        print(mutate_multidof.branches(certs))
    wedges = [c for k, c in certs if k == "wedge"]
    if wedges:
        print("  wedge branches: k* +inf %d, finite %d, numeric (not claimed) %d (of both criteria)" % (
            sum(1 for c in wedges for k in ("wedge_gain", "tsypkin_gain") if "infinite" in c["claim"].get(k, {})),
            sum(1 for c in wedges for k in ("wedge_gain", "tsypkin_gain") if "lo" in c["claim"].get(k, {})),
            sum(1 for c in wedges for k in ("wedge_gain", "tsypkin_gain") if k not in c["claim"])))


def print_branches(certs, mutants, cpp):
    """The branches of the checkers the campaign reached (fractional delays, bound-max, stability-max)."""
    print_new_branches(certs)
    frac_certs = [c for k, c in certs if k == "bound-frac"]
    if frac_certs:  # the branches of a fractional delay that the campaign reached
        qs = [(c["model"]["delay"] + Fraction(c["model"]["frac_delay"]) / Fraction(c["model"]["T"])).denominator for c in frac_certs]
        crossing = sum(1 for (k, nm, _, _), cj in zip(mutants, cpp) if k == "bound-frac" and nm == "unmutated" and "times U_" in cj["reason"])
        print("  bound-frac branches: band end rational (q = 2, 3) %d, irrational (q >= 4) %d; H with a pole at z = -1 %d; "
              "upper bound shown across the end (P U_{q-1}) %d" % (
                  sum(1 for q in qs if q <= 3), sum(1 for q in qs if q >= 4),
                  sum(1 for c in frac_certs if "(z+1)" in c["model"]["H"]), crossing))
    max_certs = [c for k, c in certs if k == "bound-max"]
    if max_certs:
        cl = [max_claim(c) for c in max_certs]
        print("  bound-max branches: K_max finite > 0 %d (exact %d), 0 %d (by b*(0) = +inf %d), +inf %d; with a fractional delay %d, a delay %d" % (
            sum(1 for x in cl if x != "inf" and x[1] > 0), sum(1 for c, x in zip(max_certs, cl) if x != "inf" and x[1] > 0 and c["claim"]["status"] == "exact"),
            sum(1 for x in cl if x != "inf" and x[1] == 0), sum(1 for c in max_certs if "at_zero_infinite" in c["evidence"]),
            sum(1 for x in cl if x == "inf"),
            sum(1 for c in max_certs if "frac_delay" in c["model"]), sum(1 for c in max_certs if c["model"]["delay"] > 0)))
    stab = [c for (k, nm, c, _) in mutants if k == "stability" and nm == "unmutated"]
    if stab:
        spring = [c for c in stab if "charpoly" not in c["evidence"] and "+ k)" in c["model"]["plant"]]
        print("  stability branches: every pole at s = 0 %d, a mass-damper (e^{pT}) %d, a spring (e^{A_c T}) %d; "
              "stable %d, NOT stable %d" % (
            sum(1 for c in stab if "charpoly" in c["evidence"]), sum(1 for c in stab if "charpoly" not in c["evidence"]) - len(spring),
            len(spring),
            sum(1 for c in stab if c["claim"]["stable"]), sum(1 for c in stab if not c["claim"]["stable"])))
    loops = [c for (k, nm, c, _) in mutants if k == "stability-loop" and nm == "unmutated"]
    if loops:
        sc = [c["model"]["scene"] for c in loops]
        print("  stability-loop branches: stable %d, NOT stable %d; 3 DOF %d, a delay %d, a tf operator %d, the wall in s %d; "
              "a coupling %d; a tf or ss device %d; a fractional delay %d; conserved quantities %d; states %d-%d" % (
                                sum(1 for c in loops if c["claim"]["stable"]), sum(1 for c in loops if not c["claim"]["stable"]),
                                sum(1 for t in sc if 'name = "d2"' in t), sum(1 for t in sc if "[delay]" in t),
                                sum(1 for t in sc if 'dofs = ["d0", "d1"]' in t), sum(1 for t in sc if 'domain = "s"' in t),
                                sum(1 for t in sc if "[coupling]" in t), sum(1 for t in sc if "passive = false" in t),
                                sum(1 for t in sc if re.search(r'samples = "\d*/', t)),
                                sum(1 for c in loops if c["claim"].get("conserved", 0) > 0),
                                min((len(c["evidence"]["P"]) for c in loops if "P" in c["evidence"]), default=0),
                                max((len(c["evidence"]["P"]) for c in loops if "P" in c["evidence"]), default=0)))
        hid = [c["evidence"]["hidden"] for c in loops if "hidden" in c["evidence"]]
        print("  stability-loop by a hidden mode (exact): %d; of a device %d; uncontrollable %d, unobservable %d; on the circle %d (a pair %d)" % (
            len(hid), sum(1 for h in hid if h["block"] == "device"), sum(1 for h in hid if h["kind"] == "uncontrollable"),
            sum(1 for h in hid if h["kind"] == "unobservable"),
            sum(1 for c in loops if "hidden" in c["evidence"] and re.search(r"# hidden: \w+ (-1|pair)\n", c["model"]["scene"])),
            sum(1 for h in hid if len(h["A_h"]) == 2)))
    ops = [c for (k, nm, c, _) in mutants if k == "operator-passivity" and nm == "unmutated"]
    if ops:
        poles = [c for c in ops if "pole" in c["evidence"] or "pole_squared" in c["evidence"]]
        print("  operator-passivity branches: a negative minor %d, the residue at s = 0 %d, at s = j w0 != 0 %d (w0 irrational %d, "
              "an ss operator %d, an imaginary residue %d)" % (
                  sum(1 for c in ops if "minor" in c["evidence"]), sum(1 for c in poles if c["evidence"].get("pole") == "0"),
                  sum(1 for c in poles if c["evidence"].get("pole") != "0"), sum(1 for c in poles if "pole_squared" in c["evidence"]),
                  sum(1 for c in poles if "ss = {" in c["model"]["scene"]),
                  sum(1 for c in poles if re.search(r'"\(-?\d+\)/\(s\^2', c["model"]["scene"]))))
    lvl = [c for (k, nm, c, _) in mutants if k == "passivity-level" and nm == "unmutated"]
    if lvl:
        print("  passivity-level branches: ISP %d, OSP %d; exact %d, certified %d, an upper bound only %d, Lemma 1's lower "
              "bound %d (with hi %d)" % (
                  sum(1 for c in lvl if c["model"]["kind"] == "isp"), sum(1 for c in lvl if c["model"]["kind"] == "osp"),
                  *(sum(1 for c in lvl if c["claim"]["status"] == st) for st in ("exact", "certified", "upper_bound")),
                  sum(1 for c in lvl if c["claim"]["status"] in ("lower_bound", "bounds")),
                  sum(1 for c in lvl if c["claim"]["status"] == "bounds")))
    mimo = [(c, cj["reason"]) for (k, nm, c, _), cj in zip(mutants, cpp) if k == "passivity-level-mimo" and nm == "unmutated"]
    if mimo:
        print("  passivity-level-mimo branches: ISP %d, OSP %d; exact %d, certified %d, an upper bound only %d, Lemma 1's "
              "lower bound %d (with hi %d); level <= 0 %d; 3x3 %d; families %s" % (
                  sum(1 for c, _ in mimo if c["model"]["kind"] == "isp"), sum(1 for c, _ in mimo if c["model"]["kind"] == "osp"),
                  *(sum(1 for c, _ in mimo if c["claim"]["status"] == st) for st in ("exact", "certified", "upper_bound")),
                  sum(1 for c, _ in mimo if c["claim"]["status"] in ("lower_bound", "bounds")),
                  sum(1 for c, _ in mimo if c["claim"]["status"] == "bounds"),
                  sum(1 for c, _ in mimo if Fraction(c["claim"].get("value", c["claim"].get("lo", c["claim"].get("hi")))) <= 0),
                  sum(1 for c, _ in mimo if len(c["model"]["D"]) == 3), json.dumps(MIMO_FAMILIES, sort_keys=True)))
    smax = [(c, cj["reason"]) for (k, nm, c, _), cj in zip(mutants, cpp) if k == "stability-max" and nm == "unmutated"]
    if smax:
        cl = [max_claim(c) for c, _ in smax]
        print("  stability-max branches: K_max finite > 0 %d (exact %d), 0 %d (D = 0 identically %d), +inf %d; with a delay %d, "
              "an operator %d" % (
                  sum(1 for x in cl if x != "inf" and x[1] > 0), sum(1 for (c, _), x in zip(smax, cl) if x != "inf" and x[1] > 0 and
                                                                    c["claim"]["status"] == "exact"),
                  sum(1 for x in cl if x != "inf" and x[1] == 0), sum(1 for _, r in smax if "D = 0 identically" in r),
                  sum(1 for x in cl if x == "inf"), sum(1 for c, _ in smax if c["model"]["delay"] > 0),
                  sum(1 for c, _ in smax if "operator" in c["model"])))


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--hapstab", required=True)
    ap.add_argument("--models", type=int, default=300, help="bound models (and as many r cases / 4)")
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--quiet", action="store_true")
    ap.add_argument("--kinds", default=",".join(KINDS), help="the kinds to produce, comma-separated (default: all)")
    a = ap.parse_args()
    kinds = set(a.kinds.split(","))
    unknown = kinds - set(KINDS)
    if unknown:
        ap.error("--kinds: unknown %s (known: %s)" % (", ".join(sorted(unknown)), ", ".join(KINDS)))
    rng = random.Random(a.seed)
    cache = {}
    tmp = tempfile.mkdtemp(prefix="hapstab-mutate-")
    scache = {}
    srng = random.Random(a.seed * 1000 + 47)  # its own stream: the other kinds draw what they drew before it was added
    t0 = time.time()
    mrng = random.Random(a.seed * 1000 + 48)  # passivity-level-mimo's own stream, likewise
    irng = random.Random(a.seed * 1000 + 49)  # bound-inf's own stream
    lrng = random.Random(a.seed * 1000 + 50)  # limit-cycle's own stream
    certs, skipped = produce_certificates(a, kinds, rng, srng, tmp, cache, scache, mrng, irng, lrng)
    produced = time.time() - t0
    mutants = []
    problems = []  # producer runs that break what the mutants rely on
    scrng = random.Random(a.seed * 1000 + 51)  # the scene mutants' own stream
    nrng = random.Random(a.seed * 1000 + 52)  # num/den's
    stability_seen = 0
    for kind, cert in certs:
        stability_seen += kind == "stability"
        if kind == "stability" and stability_seen % 4 == 1:  # a quarter (the first) also as `stability --scene` writes it
            for name, c, expect in scene_mutants(cert, scrng, a.hapstab, scache, tmp, problems):
                mutants.append(("stability (scene)", name, c, expect))
        if kind == "stability":
            ms = stability_mutants(cert, rng, a.hapstab, scache, tmp)
        elif kind == "stability-max":
            ms = stability_max_mutants(cert, srng, a.hapstab, scache, tmp)
        elif kind == "bound-max":
            ms = max_mutants(cert, rng, a.hapstab, cache)
        elif kind == "passivity-level":
            ms = level_mutants(cert, rng, a.hapstab, scache, tmp)
        elif kind == "wedge":
            ms = wedge_mutants(cert, rng, a.hapstab, scache, tmp)
        elif kind == "passivity-level-mimo":
            ms = mimo_mutants(cert, mrng, a.hapstab, scache, tmp)
        elif kind == "bound-inf":
            ms = inf_mutants(cert, irng, a.hapstab, cache)
        elif kind == "limit-cycle":
            ms = lc_mutants(cert, lrng, a.hapstab, scache, tmp)
        elif kind == "stability-loop":
            ms = loop_mutants(cert, scrng, a.hapstab, scache, tmp)
        elif kind.startswith("multidof-"):
            ms = mutate_multidof.mutants(cert, lrng)
        elif kind == "operator-passivity":
            ms = mutate_operator.mutants(cert, OPERATOR_ENTRIES[id(cert)], nrng)
        else:
            ms = (bound_mutants if kind.startswith("bound") else r_mutants)(cert, rng, a.hapstab, cache)
        if kind in ("bound", "bound-inf", "wedge", "limit-cycle", "passivity-level") and "H" in cert["model"]:
            ms = list(ms) + numden_mutants(cert, nrng)
        for name, c, expect in ms:
            mutants.append((kind, name, c, expect))
    # the C++ checker: one process over all mutants
    batch = os.path.join(tmp, "mutants.jsonl")
    with open(batch, "w") as f:
        for _, _, c, _ in mutants:
            f.write(json.dumps(c) + "\n")
    t1 = time.time()
    p = subprocess.run([a.hapstab, "check", "--batch", batch], capture_output=True, text=True)
    cpp_seconds = time.time() - t1
    cpp = [json.loads(line) for line in p.stdout.splitlines()]
    if len(cpp) != len(mutants):
        print("hapstab check --batch answered %d of %d lines: %s" % (len(cpp), len(mutants), p.stderr[-500:]))
        return 1
    t2 = time.time()
    py = [hapstab_check.check(c) for _, _, c, _ in mutants]
    py_seconds = time.time() - t2
    counts, failures = {}, list(problems)
    want_code = {"accept": 0, "refute": 1, "malformed": 2}
    for (kind, name, c, expect), cj, (pcode, preason) in zip(mutants, cpp, py):
        ccode, creason = cj["exit"], cj["reason"]
        key = (kind, expect)
        counts[key] = counts.get(key, 0) + 1
        ok = True
        if pcode == 3:
            counts[("py not checked", kind)] = counts.get(("py not checked", kind), 0) + 1
            ok = expect in ("agree", "same") or (ccode in (1, 2) if expect == "rejected" else ccode == want_code[expect])
        elif expect == "agree":
            ok = ccode == pcode and ccode in (0, 1)
        elif expect == "same":
            ok = ccode == pcode
        elif expect == "rejected":
            ok = ccode == pcode and ccode in (1, 2)
        else:
            ok = ccode == want_code[expect] and pcode == want_code[expect]
        if ok and expect in ("refute", "malformed", "rejected") and (not creason or not preason):
            ok = False  # a rejection names what failed
        if not ok:
            failures.append("%s / %s: expected %s, hapstab check %d (%s), independent %d (%s)" % (
                kind, name, expect, ccode, creason[:160], pcode, preason[:160]))
    shutil.rmtree(tmp, ignore_errors=True)
    n = len(mutants)
    accepted_false = sum(1 for (k, nm, c, e), cj, (pc, _) in zip(mutants, cpp, py)
                         if e in ("refute", "malformed", "rejected") and (cj["exit"] == 0 or pc == 0))
    kinds = sorted({k for k, _ in certs})
    scenes = sum(1 for _, nm, _, _ in mutants if nm == "scene: unmutated (stability --scene)")
    print("certificates: %d (%s)%s; producer runs skipped: %s" % (
        len(certs), ", ".join("%d %s" % (sum(1 for k, _ in certs if k == kd), kd) for kd in kinds),
        ", and %d of the stability ones as stability --scene writes them" % scenes if scenes else "", skipped or "none"))
    kinds = sorted({k for k, _, _, _ in mutants})
    for kd in kinds:
        per = [(e, cj["exit"], pc) for (k, _, _, e), cj, (pc, _) in zip(mutants, cpp, py) if k == kd]
        print("  %s: %d mutants (accept %d, refute %d, malformed %d, agree %d), false or malformed accepted %d" % (
            kd, len(per), *(sum(1 for e, _, _ in per if e in x) for x in (("accept",), ("refute", "rejected"), ("malformed",), ("agree", "same"))),
            sum(1 for e, ce, pe in per if e in ("refute", "malformed", "rejected") and (ce == 0 or pe == 0))))
    print("mutants: %d; expected accept %d, refute %d, malformed %d, agree %d" % (
        n, sum(v for (k, e), v in counts.items() if e == "accept"), sum(v for (k, e), v in counts.items() if e in ("refute", "rejected")),
        sum(v for (k, e), v in counts.items() if e == "malformed"), sum(v for (k, e), v in counts.items() if e in ("agree", "same"))))
    for key in sorted(k for k in counts if k[0] == "py not checked"):
        print("independent checker: not checked (size limit): %d %s" % (counts[key], key[1]))
    print_branches(certs, mutants, cpp)
    print("false or malformed claims accepted: %d" % accepted_false)
    print("time: production %.1f s, hapstab check %.1f s, independent checker %.1f s" % (produced, cpp_seconds, py_seconds))
    if failures:
        print("FAILURES: %d" % len(failures))
        for f in failures[:40]:
            print("  " + f)
        return 1
    if not a.quiet:
        print("every expectation holds")
    return 0


if __name__ == "__main__":
    sys.exit(main())
