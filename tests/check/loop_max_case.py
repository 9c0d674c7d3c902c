"""A `stability-loop-max` certificate (check/stability_loop_max_check.hpp) end to end: hapstab writes it
for `stability --scene S --max NAME`, both checkers verify it, and each hand edit below gets the exit
code it must from both (1 refuted: the evidence does not prove the edited claim; 2 malformed: the model
is beyond the kind). The ctests certificate_loop_max* run it on tests/cli/scenes/loop_max_held_devices.toml (the
environment's gain), integrator_devices_2dof.toml (the first-order start), loop_max_wall_stiffness.toml (the
parameter inside the wall's tf), loop_max_free_wall_stiffness.toml (both), loop_max_wall_stiffness_conserved.toml (inside
the tf beside a conserved quantity), loop_max_pure_masses.toml (no_crossing: pure masses, M rational) and
loop_max_zero_outward.toml (sup = 0 by the first-order mirror).

  loop_max_case.py HAPSTAB SCENE NAME
  loop_max_case.py HAPSTAB plant NAME --plant P --H H --T T [--delay n]   (the one-DOF loop, a device pole off s = 0)
exit 0 when every expectation holds, else 1 (each failure printed)."""
import json
import os
import subprocess
import sys
import tempfile
from fractions import Fraction

from cert_edit import deleted, with_field

TOP = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def exits(hapstab, cert, tmp):
    path = os.path.join(tmp, "m.json")
    with open(path, "w") as f:
        json.dump(cert, f)
    return (subprocess.run([hapstab, "check", path], capture_output=True).returncode,
            subprocess.run(["/usr/bin/python3", os.path.join(TOP, "checks", "hapstab_check.py"), path], capture_output=True).returncode)


def agrees(got, want):
    """Both checkers' exits (hapstab check, independent) as wanted: `want` from both, or (None) rejected --
    refuted or malformed -- the same by both."""
    return got[0] == got[1] and (got[0] in (1, 2) if want is None else got[0] == want)


def run_cases(hapstab, cases, tmp):
    """Each (what, certificate, wanted exit) through both checkers, a line each; the number that failed."""
    failures = 0
    for what, c, want in cases:
        got = exits(hapstab, c, tmp)
        ok = agrees(got, want)
        failures += not ok
        print("%s %s: hapstab check %d, independent %d (want %s)" % ("ok  " if ok else "FAIL", what, got[0], got[1],
                                                                       "1 or 2" if want is None else want))
    return failures


def outward_mutants(cert, at, name):
    """Hand edits of sup = 0 by the first-order mirror (evidence.first_order_unstable {to, P0, S, w} at the path `at`:
    ["evidence"], or a stability-loop-max-symmetric block's): refuted (1) -- w zero or S negated ((L w)^T S (L w) >= 0),
    eps 10^6 times as large (w^T P(eps) w or Q(eps) fails), P0[0][0] negated (P0 not positive definite); malformed (2) --
    the mirror dropped, given beside unstable_at, eps 0, w one entry short, a cover added, hi raised to 1."""
    fo = cert
    for key in at + ["first_order_unstable"]:
        fo = fo[key]
    where = at + ["first_order_unstable"]
    p0 = fo["P0"][0][0]
    return [("unmutated", cert, 0),
            ("the mirror's w zero", with_field(cert, where + ["w"], ["0"] * len(fo["w"])), 1),
            ("the mirror's S negated", with_field(cert, where + ["S"], [[str(-Fraction(v)) for v in row] for row in fo["S"]]), 1),
            ("the mirror's eps 10^6 times as large", with_field(cert, where + ["to"], str(Fraction(fo["to"]) * 10 ** 6)), 1),
            ("the mirror's P0[0][0] negated", with_field(cert, where + ["P0", 0, 0], p0[1:] if p0.startswith("-") else "-" + p0), 1),
            ("the mirror dropped", deleted(cert, where), 2),
            ("the mirror beside an unstable_at", with_field(cert, at + ["unstable_at"], {"at": "0", "P": fo["P0"], "w": fo["w"]}), 2),
            ("the mirror's eps 0", with_field(cert, where + ["to"], "0"), 2),
            ("the mirror's w one entry short", with_field(cert, where + ["w"], fo["w"][:-1]), 2),
            ("a cover of [0, 1] added", with_field(cert, at + ["cover"], [{"to": "1", "P": fo["P0"]}]), 2),
            ("the parameter given a value", with_field(cert, ["model", "set"], {name: "1"}), 2)]


def mutants(cert, name):
    """(what, edited certificate, the exit code both checkers must give, None: rejected) for a stability-loop-max
    certificate of a supremum (claim.hi > 0, a cover): the claim moved where the evidence cannot prove
    it (refuted) and the model moved beyond the kind (malformed)."""
    claim = cert["claim"]
    if Fraction(claim["hi"]) == 0 and "first_order_unstable" in cert["evidence"]:
        return outward_mutants(cert, ["evidence"], name)
    if Fraction(claim["hi"]) == 0:  # sup = 0: Stein inertia at M(0) (on ker L beside slow modes)
        un = cert["evidence"]["unstable_at"]
        P00 = un["P"][0][0]
        out = [("unmutated", cert, 0),
               ("w zero (w^T P w = 0)", with_field(cert, ["evidence", "unstable_at", "w"], ["0"] * len(un["w"])), 1),
               ("P's first entry negated", with_field(cert, ["evidence", "unstable_at", "P", 0, 0], P00[1:] if P00.startswith("-") else "-" + P00), None),
               ("a cover of [0, 1] added", with_field(cert, ["evidence", "cover"], [{"to": "1", "P": un["P"]}]), 2),
               ("the parameter given a value", with_field(cert, ["model", "set"], {name: "1"}), 2),
               ("the unstable point dropped", deleted(cert, ["evidence", "unstable_at"]), 2)]
        if un.get("slow_quotient"):
            out += [("the slow quotient dropped (M(0) whole: P of the wrong order)", deleted(cert, ["evidence", "unstable_at", "slow_quotient"]), 2),
                    ("slow_quotient false", with_field(cert, ["evidence", "unstable_at", "slow_quotient"], False), 2)]
        return out
    cover = cert["evidence"]["cover"]
    text = cert["model"].get("scene")

    def claim_hi(v):
        c = with_field(deleted(cert, ["claim", "printed_hi"]), ["claim", "hi"], v)
        return with_field(c, ["evidence", "unstable_at", "at"], v)

    def claim_lo(v):
        c = with_field(deleted(cert, ["claim", "printed_lo"]), ["claim", "lo"], v)
        return with_field(c, ["evidence", "cover", len(cover) - 1, "to"], v)
    P00 = cover[0]["P"][0][0]
    neg = P00[1:] if P00.startswith("-") else "-" + P00
    env = 'gain = "%s"' % name
    out = [("unmutated", cert, 0),
           ("hi lowered below the crossing (hi/2: the loop is stable there)", claim_hi(str(Fraction(claim["hi"]) / 2)), 1),
           ("lo written as an expression", claim_lo("2*%s" % claim["hi"]), 2),
           ("lo raised to hi (NOT stable there)", claim_lo(claim["hi"]), 1),
           ("lo above hi", claim_lo(str(2 * Fraction(claim["hi"]))), 1),
           ("the first interval's P00 negated", with_field(cert, ["evidence", "cover", 0, "P", 0, 0], neg), 1),
           ("conserved quantities miscounted", with_field(cert, ["claim", "conserved"], claim.get("conserved", 0) + 1), 1),
           ("the parameter given a value", with_field(cert, ["model", "set"], {name: "1"}), 2),
           ("the cover dropped", deleted(cert, ["evidence", "cover"]), 2),
           ("the unstable point dropped", deleted(cert, ["evidence", "unstable_at"]), 2)]
    linear = [k for k, piece in enumerate(cover) if "P_to" in piece]
    if linear:  # an interval with P linear (the Bernstein test): its ends' P's edited
        k = linear[-1]  # the one nearest the crossing
        piece = cover[k]
        Pk = piece["P"] if "P" in piece else cover[k - 1]["P_to"]  # left out: the last interval's P_to
        T00 = piece["P_to"][0][0]
        out += [("a linear interval's P_to[0][0] negated", with_field(cert, ["evidence", "cover", k, "P_to", 0, 0],
                                                                      T00[1:] if T00.startswith("-") else "-" + T00), 1),
                ("a linear interval's P and P_to swapped", with_field(with_field(cert, ["evidence", "cover", k, "P"], piece["P_to"]),
                                                                     ["evidence", "cover", k, "P_to"], Pk), None),
                ("a linear interval's P_to dropped (one P over it)", deleted(cert, ["evidence", "cover", k, "P_to"]), None),
                ("a linear interval's P_to of the wrong order", with_field(cert, ["evidence", "cover", k, "P_to"], [row[:-1] for row in piece["P_to"][:-1]]), 2),
                ("the first linear interval's P left out (no P_to before it)", deleted(cert, ["evidence", "cover", linear[0], "P"]), 2)]
        if "P" not in piece:  # its P is the last interval's P_to: that one edited edits both
            P00 = Pk[0][0]
            out.append(("the P_to that the next interval inherits, [0][0] negated", with_field(
                cert, ["evidence", "cover", k - 1, "P_to", 0, 0], P00[1:] if P00.startswith("-") else "-" + P00), 1))
    if text is None:  # the one-DOF --plant/--H model: p in H only
        model = cert["model"]
        H, P = model["H"], model["plant"]
        out += [("the parameter named in the plant too", with_field(cert, ["model", "plant"], "(%s)*(1 + 0*%s)" % (P, name)), 2),
                ("H squared in the parameter (not affine)", with_field(cert, ["model", "H"], "%s*%s/1000 + (%s)" % (name, name, H)), 2),
                ("a pole of H that cancels at %s = 1" % name, with_field(cert, ["model", "H"], "(z-%s)/(z-1) - 1 + (%s)" % (name, H)), 2),
                ("H without the parameter", with_field(cert, ["model", "H"], H.replace(name, "1")), 2),
                ("the device's mass doubled", with_field(cert, ["model", "plant"], "(%s)/2" % P), None),
                ("the delay one sample longer", with_field(cert, ["model", "delay"], model["delay"] + 1), None)]
        text = ""
    elif env in text:
        out.append(("the gain not the parameter alone", with_field(cert, ["model", "scene"], text.replace(env, 'gain = "2*%s"' % name)), 2))
    else:  # the parameter inside the wall's tf (proven affine there; the realisation of the largest order)
        assert "[environment]" in text
        term = '"%s + ' % name
        at = text.index("tf = ", text.index("[environment]"))
        line = text[at:text.index("\n", at) + 1]
        N = text.count("[[device]]")
        D = "[" + ", ".join("[" + ", ".join('"%s"' % (name if i == j else "0") for j in range(N)) + "]" for i in range(N)) + "]"
        ss = 'ss = { A = [["0"]], B = [[%s]], C = [%s], D = %s }\n' % (", ".join(['"0"'] * N), ", ".join(['["0"]'] * N), D)
        out += [("the parameter squared in an entry (not affine)", with_field(cert, ["model", "scene"], text.replace(term, '"%s*%s/1000 + ' % (name, name), 1)), 2),
                ("the parameter the gain as well", with_field(cert, ["model", "scene"], text.replace("[environment]", "[environment]\n" + env)), 2),
                ("an entry whose pole cancels at %s = 1" % name,
                 with_field(cert, ["model", "scene"], text.replace(term, '"(z-%s)/(z-1) - 1 + %s + ' % (name, name), 1)), 2),
                ("the parameter in an ss wall", with_field(cert, ["model", "scene"], text.replace(line, ss)), 2)]
        if claim.get("conserved") and "[delay]" in text and "[coupling]" not in text:  # conserved rows beside it (since stop 78)
            V = 'ss = { A = [["1"]], B = [[%s]], C = [%s], D = [%s] }\n\n' % (
                ", ".join(['"1"'] + ['"0"'] * (N - 1)), ", ".join(['["0"]'] * N), ", ".join(["[" + ", ".join(['"0"'] * N) + "]"] * N))
            out += [("the conserved quantities not claimed", deleted(cert, ["claim", "conserved"]), 1),
                    ("an ss coupling with an unobservable z = 1 beside it (a quotient by right eigenvectors)",
                     with_field(cert, ["model", "scene"], text.replace("[delay]", "[coupling]\n" + V + "[delay]")), 2)]
    if 'B = "5"' in text:
        out.append(("the gain named in another expression too", with_field(cert, ["model", "scene"], text.replace('B = "5"', 'B = "5*%s/%s"' % (name, name))), 2))
    fo = cert["evidence"].get("first_order")
    if fo:  # the first-order start on (0, eps] (a position that nothing holds at p = 0)
        p0 = fo["P0"][0][0]
        s0 = fo["S"][0][0]
        out += [("the first-order start dropped (the cover then starts at 0, where M(0) is marginal)", deleted(cert, ["evidence", "first_order"]), 1),
                ("P0's first entry negated", with_field(cert, ["evidence", "first_order", "P0", 0, 0], p0[1:] if p0.startswith("-") else "-" + p0), 1),
                ("S negated (not positive semidefinite)", with_field(cert, ["evidence", "first_order", "S", 0, 0], s0[1:] if s0.startswith("-") else "-" + s0), 1),
                ("S zero (P0 alone: M(0) is marginal)", with_field(cert, ["evidence", "first_order", "S"], [["0"] * len(fo["S"])] * len(fo["S"])), 1),
                ("eps beyond lo", with_field(cert, ["evidence", "first_order", "to"], str(2 * Fraction(claim["hi"]))), 2)]
        if env in text:
            out.append(("the first-order start with the coupling's gain", with_field(cert, ["model", "scene"], text.replace(env, "").replace("[coupling]", "[coupling]\n" + env)), None))
    nc = cert["evidence"].get("no_crossing")
    if nc:  # stable on (0, a]: no eigenvalue of the rational M(p) meets the circle there (since stop 78)
        out += [("no_crossing dropped (the cover then starts at 0, where M(0) has a Jordan block at z = 1)", deleted(cert, ["evidence", "no_crossing"]), 1),
                ("the cover's one P negated", with_field(cert, ["evidence", "cover", len(cover) - 1, "P"],
                                                          [[str(-Fraction(v)) for v in row] for row in cover[-1]["P"]]), 1) if "P" in cover[-1] else
                ("the cover kept", cert, 0),
                ("no_crossing.to 0", with_field(cert, ["evidence", "no_crossing", "to"], "0"), 2),
                ("no_crossing beside a first_order", with_field(cert, ["evidence", "first_order"], {"to": nc["to"], "P0": [], "S": []}), 2),
                ("no_crossing with a field more", with_field(cert, ["evidence", "no_crossing", "from"], "0"), 2),
                ("a device damped (M not rational: beyond no_crossing)", with_field(cert, ["model", "scene"], text.replace('b = "0"', 'b = "1"', 1)), 2)]
        # the claim moved past the crossing, no_crossing.to with it: the resultant has its root in (0, to] (refuted there,
        # before any cover is read)
        h = Fraction(claim["hi"])
        c = with_field(with_field(deleted(deleted(cert, ["claim", "printed_lo"]), ["claim", "printed_hi"]), ["claim", "lo"], str(2 * h)), ["claim", "hi"], str(3 * h))
        c = with_field(with_field(c, ["evidence", "cover", len(cover) - 1, "to"], str(2 * h)), ["evidence", "unstable_at", "at"], str(3 * h))
        out.append(("no_crossing.to past the crossing (claim and cover moved with it)", with_field(c, ["evidence", "no_crossing", "to"], str(3 * h / 2)), 1))
    if len(cover) > 1:
        # refuted where the first P fails at its new end, else malformed (the next interval then empty): rejected
        out.append(("an interval's end moved past the next one's", with_field(cert, ["evidence", "cover", 0, "to"], cover[1]["to"]), None))
    return out


def main():
    hapstab, scene, name = sys.argv[1:4]
    args = ["--scene", scene] if scene.endswith(".toml") else sys.argv[4:]  # else: a one-DOF --plant/--H loop's options
    with tempfile.TemporaryDirectory() as tmp:
        path = os.path.join(tmp, "c.json")
        r = subprocess.run([hapstab, "stability"] + args + ["--max", name, "--certificate", path, "--quiet"],
                           capture_output=True, text=True)
        if r.returncode not in (0, 1) or not os.path.exists(path):  # 1: sup = 0 (NOT stable for every small value)
            print("FAIL: the producer wrote no certificate (exit %d): %s" % (r.returncode, r.stderr.strip()))
            return 1
        with open(path) as f:
            cert = json.load(f)
        cases = mutants(cert, name)
        failures = run_cases(hapstab, cases, tmp)
        print("loop_max_case: %d cases, %d failed" % (len(cases), failures))
        return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
