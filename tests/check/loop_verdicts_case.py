"""A `stability-loop-verdicts` certificate (check/stability_loop_verdicts_check.hpp) end to end: hapstab writes it for
`stability --scene S --max NAME` where the loop is not affine in NAME (the bisection on verdicts), both checkers
verify it, and each hand edit below gets the exit code it must from both (1 refuted: a verdict's evidence does not
prove it; 2 malformed: a part that is not about the model claimed). The ctest certificate_loop_verdicts runs it on
examples/multidof_case_ii_coupling.toml with kc (the coupling's stiffness, gain 1/kc: stable at lo, NOT stable at
hi) and examples/000_two_dof_loop.toml with k (stable at every value tried: no upper end, exit 3, every verdict
written).

  loop_verdicts_case.py HAPSTAB SCENE NAME EXIT
exit 0 when every expectation holds, else 1 (each failure printed)."""
import json
import os
import subprocess
import sys
import tempfile

from cert_edit import deleted, with_field
from loop_max_case import run_cases


def swapped_values(cert, name):
    """The first two verdicts' values exchanged in the claim and in their parts' models (each part keeps its P)."""
    a, b = (v["at"] for v in cert["claim"]["verdicts"][:2])
    c = with_field(cert, ["claim", "verdicts", 0, "at"], b)
    c = with_field(c, ["claim", "verdicts", 1, "at"], a)
    c = with_field(c, ["evidence", "verdicts", 0, "model", "set", name], b)
    return with_field(c, ["evidence", "verdicts", 1, "model", "set", name], a)


def moved(cert, i, name, value):
    """Verdict i claimed at `value`, its part's model moved with it (its P kept)."""
    c = with_field(cert, ["claim", "verdicts", i, "at"], value)
    return with_field(c, ["evidence", "verdicts", i, "model", "set", name], value)


def mutants(cert, name):
    verdicts = cert["claim"]["verdicts"]
    part = cert["evidence"]["verdicts"][0]
    P00 = part["evidence"]["P"][0][0]
    out = [("unmutated", cert, 0),
           ("the first part's P[0][0] negated", with_field(cert, ["evidence", "verdicts", 0, "evidence", "P", 0, 0],
                                                           P00[1:] if P00.startswith("-") else "-" + P00), None),
           ("a verdict flipped in the claim only", with_field(cert, ["claim", "verdicts", 0, "stable"], not verdicts[0]["stable"]), 2),
           ("a verdict's value moved in the claim only", with_field(cert, ["claim", "verdicts", 0, "at"], verdicts[0]["at"] + "1"), 2),
           ("a part's scene edited (a number doubled)", with_field(cert, ["evidence", "verdicts", 0, "model", "scene"],
                                                                   part["model"]["scene"].replace("\nT = \"", "\nT = \"2*", 1)), 2),
           ("the parameter given a value", with_field(cert, ["model", "set", name], "1"), 2),
           ("a part's kind another", with_field(cert, ["evidence", "verdicts", 0, "kind"], "stability-loop-max"), 2),
           ("a part dropped (evidence only)", deleted(cert, ["evidence", "verdicts", 0]), 2),
           ("a value twice", with_field(with_field(cert, ["claim", "verdicts", 1, "at"], verdicts[0]["at"]),
                                        ["evidence", "verdicts", 1, "model", "set", name], verdicts[0]["at"]), 2),
           ("no verdicts", with_field(with_field(cert, ["claim", "verdicts"], []), ["evidence", "verdicts"], []), 2),
           ("a verdict and its part dropped (a weaker claim)", deleted(deleted(cert, ["claim", "verdicts", 0]), ["evidence", "verdicts", 0]), 0)]
    if len(verdicts) >= 2 and verdicts[0]["stable"] != verdicts[1]["stable"]:
        out += [("the two values exchanged (each P kept)", swapped_values(cert, name), 1),
                ("the stable verdict moved just above the NOT stable value (its P kept)",
                 moved(cert, 0, name, "%s/1" % (int(verdicts[1]["at"]) + 1) if verdicts[1]["at"].isdigit() else verdicts[1]["at"]), 1)]
    else:  # every verdict alike: one moved far out
        out.append(("a stable verdict's value times 1000 (its P kept)", moved(cert, 0, name, verdicts[-1]["at"] + "000"), None))
    return out


def main():
    hapstab, scene, name, want = sys.argv[1], sys.argv[2], sys.argv[3], int(sys.argv[4])
    with tempfile.TemporaryDirectory() as tmp:
        path = os.path.join(tmp, "c.json")
        r = subprocess.run([hapstab, "stability", "--scene", scene, "--max", name, "--digits", "4", "--certificate", path, "--quiet"],
                           capture_output=True, text=True)
        if r.returncode != want or not os.path.exists(path):
            print("FAIL: exit %d (want %d), certificate %s: %s" % (r.returncode, want, os.path.exists(path), r.stderr.strip()))
            return 1
        with open(path) as f:
            cert = json.load(f)
        cases = mutants(cert, name)
        failures = run_cases(hapstab, cases, tmp)
        print("loop_verdicts_case: %d cases, %d failed" % (len(cases), failures))
        return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
