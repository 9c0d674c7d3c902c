"""An [environment] written as `ss = {A, B, C, D}` in the multi-DOF certificates (check/multidof_model.hpp;
checks/hapstab_check.py's ss_environment): `multidof analyze --scene S --certificate` holds the realisation as
written (model.environment.ss, its gain apart) and both checkers take E = C (xI - A)^-1 B + D exactly.
  - two walls linked by a spring, E = K + B (z - 1)/(T z) per DOF written as a state space (the previous
    positions), and the same E as tf: both (16) feasible, the same claim; both checkers verify each;
  - the same in s (domain = "s", E(s) = C (sI - A)^-1 B + D, backward Euler and Tustin): verified;
  - a spring one sample late, E = K/z (A = 0, B = I, C = K I, D = 0): (16) infeasible, its frequency-domain
    witness (kind multidof-witness) verified;
and each hand edit below gets its exit code from both checkers (2: malformed, named; 1: refuted).

  ss_environment_case.py HAPSTAB
exit 0 when every expectation holds, else 1 (each failure printed)."""
import json
import os
import subprocess
import sys
import tempfile

from cert_edit import deleted, with_field
from loop_max_case import run_cases

SCENE = """[scene]
name = "two devices on linked walls"
T = "0.01"

[[device]]
name = "d_a"
m = "1/10"
b = "1.37"

[[device]]
name = "d_b"
m = "1/10"
b = "1.37"

[[operator]]
name = "H1"
dofs = ["d_a"]
tf = "0.1*(s^2+5*s+10)/(s^2+s+1)"

[[operator]]
name = "H2"
dofs = ["d_b"]
tf = "0.05*(s^2+5*s+10)/(s^2+s+1)"

[environment]
%s

[multidof]
osp = ["1.37", "1.37"]
"""

WALLS_SS = 'ss = { A = [["0", "0"], ["0", "0"]], B = [["1", "0"], ["0", "1"]], C = [["-1/2", "0"], ["0", "-1/2"]], ' \
           'D = [["3/2", "-1/5"], ["-1/5", "2"]] }'
WALLS_TF = 'tf = [["1 + 0.5*(z-1)/z", "-1/5"], ["-1/5", "1.5 + 0.5*(z-1)/z"]]'
LAG_SS = 'ss = { A = [["-10", "0"], ["0", "-20"]], B = [["1", "0"], ["0", "1"]], C = [["5", "1"], ["1", "8"]], ' \
         'D = [["1", "0"], ["0", "1"]] }'
LATE_SS = 'ss = { A = [["0", "0"], ["0", "0"]], B = [["1", "0"], ["0", "1"]], C = [["500", "0"], ["0", "500"]], ' \
          'D = [["0", "0"], ["0", "0"]] }'


def certificate(hapstab, tmp, name, environment):
    scene = os.path.join(tmp, name + ".toml")
    with open(scene, "w") as f:
        f.write(SCENE % environment)
    path = os.path.join(tmp, name + ".json")
    r = subprocess.run([hapstab, "multidof", "analyze", "--scene", scene, "--certificate", path, "--quiet"],
                       capture_output=True, text=True)
    if r.returncode not in (0, 1) or not os.path.exists(path):
        raise SystemExit("FAIL: no certificate for %s (exit %d): %s" % (name, r.returncode, r.stderr.strip()))
    return json.load(open(path))


def edits(cert, infeasible):
    ss = ["model", "environment", "ss"]
    a = cert["model"]["environment"]["ss"]
    if infeasible:  # E = 0 makes phi = u* Delta_D X u > 0: the witness fails
        zero = [["0"] * len(a["C"][0]) for _ in a["C"]]
        return [("unmutated", cert, 0),
                ("C = 0 (E = 0: phi > 0 at the witness)", with_field(cert, ss + ["C"], zero), 1),
                ("ss beside E", with_field(cert, ["model", "environment", "E"], [["0", "0"], ["0", "0"]]), 2)]
    return [("unmutated", cert, 0),
            ("A[0][0] = 1/10 (the realisation of E-hat is not the model's)", with_field(cert, ss + ["A", 0, 0], "1/10"), 1),
            ("D[0][1] = -1/4 (E(1) no longer the point's)", with_field(cert, ss + ["D", 0, 1], "-1/4"), 1),
            ("ss beside E", with_field(cert, ["model", "environment", "E"], [["0", "0"], ["0", "0"]]), 2),
            ("neither ss nor E", deleted(cert, ss), 2),
            ("ss without C", deleted(cert, ss + ["C"]), 2),
            ("ss with a field it does not have", with_field(cert, ss + ["E"], "0"), 2),
            ("B one column short", with_field(cert, ss + ["B"], [row[:1] for row in a["B"]]), 2),
            ("A's entry not a rational", with_field(cert, ss + ["A", 1, 1], "x"), 2),
            ("ss a string", with_field(cert, ss, "A = 0"), 2),
            ("A empty (it crashed hapstab check before the test was added)", with_field(cert, ss + ["A"], []), 2),
            ("D empty", with_field(cert, ss + ["D"], []), 2)]


def main():
    hapstab = sys.argv[1]
    failures, count = 0, 0
    with tempfile.TemporaryDirectory() as tmp:
        walls = certificate(hapstab, tmp, "walls_ss", WALLS_SS)
        twin = certificate(hapstab, tmp, "walls_tf", WALLS_TF)
        same = walls["kind"] == twin["kind"] == "multidof-feasible" and walls["claim"] == twin["claim"] and \
            "ss" in walls["model"]["environment"] and "E" in twin["model"]["environment"]
        print("%s ss and tf: both multidof-feasible, the same claim, each model as written" % ("ok  " if same else "FAIL"))
        failures += not same
        cases = edits(walls, False)
        for method in ("backward_euler", "tustin"):
            c = certificate(hapstab, tmp, "lag_" + method, 'domain = "s"\nmethod = "%s"\n%s' % (method, LAG_SS))
            cases.append(("s-domain ss, " + method, c, 0))
        late = certificate(hapstab, tmp, "late_ss", LATE_SS)
        if late["kind"] != "multidof-witness":
            print("FAIL: the late spring's certificate is %s, not multidof-witness" % late["kind"])
            failures += 1
        cases += [("late spring: " + what, c, want) for what, c, want in edits(late, True)]
        failures += run_cases(hapstab, cases, tmp)
        count = len(cases) + 2
    print("ss_environment_case: %d cases, %d failed" % (count, failures))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
