"""The repeated-block forms of a scene (docs/scene.md, "Repeated blocks": list parameters, count, diagonal /
off_diagonal / blocks) in both checkers' reading (check/scene_model.hpp, checks/hapstab_check.py's
scene_copies / scene_lists / scene_diagonal): `stability --scene COMPACT --certificate` and the same scene
written out (WRITTEN) must give the same claim and evidence, both checkers must verify it, and each hand
edit below of the compact scene must get its exit code from both (2: malformed, named; None: rejected).

  compact_scene_case.py HAPSTAB COMPACT WRITTEN
exit 0 when every expectation holds, else 1 (each failure printed)."""
import json
import os
import subprocess
import sys
import tempfile

from cert_edit import with_field
from loop_max_case import run_cases


def edits(cert):
    text = cert["model"]["scene"]

    def scene(old, new):
        assert old in text, old
        return with_field(cert, ["model", "scene"], text.replace(old, new, 1))
    return [("unmutated", cert, 0),
            ("a list indexed past its end (kc[5] of 4 values)", scene('diagonal = "kc[i]', 'diagonal = "kc[5]'), 2),
            ("a list named without an index", scene('b = "sum(Bc)/14"', 'b = "Bc/14"'), 2),
            ("count = 0", scene("count = 4\nname = \"d\"", "count = 0\nname = \"d\""), 2),
            ("count = 65 (beyond the checkers' 64)", scene("count = 4\nname = \"d\"", "count = 65\nname = \"d\""), 2),
            ("blocks = 3 (does not divide 4 DOFs)", scene("blocks = 2", "blocks = 3"), 2),
            ("off_diagonal without diagonal", scene('diagonal = "kc[i] + Bc[i]*(z-1)/(T*z)"\n', ""), 2),
            ("a counted table without a name", scene("count = 4\nname = \"d\"\n", "count = 4\n"), 2),
            ("--set on a list parameter", with_field(cert, ["model", "set"], {"kc": "1"}), 2),
            ("a list that names itself (a cycle)",
             with_field(cert, ["model", "scene"], text.replace('kh = "50"', 'kh = "50"\nq = ["q[1]"]').replace('k = "kh"', 'k = "kh + q[1]"')), 2),
            ("lists that double 60 times (beyond 1 MB)", with_field(cert, ["model", "scene"], text.replace(
                'kh = "50"', 'kh = "50"\n' + "".join('a%d = ["a%d[1] + a%d[1]"]\n' % (i, i + 1, i + 1) for i in range(60)) + 'a60 = ["1"]').replace(
                'k = "kh"', 'k = "kh + a0[1]"')), 2),
            ("the walls' dampers negated (the loop NOT stable: the claim false)", scene('Bc = ["2", "3", "4", "5"]', 'Bc = ["-20", "-30", "-40", "-50"]'), None)]


def main():
    hapstab, compact, written = sys.argv[1:4]
    failures = 0
    with tempfile.TemporaryDirectory() as tmp:
        certs = []
        for scene in (compact, written):
            path = os.path.join(tmp, os.path.basename(scene) + ".json")
            r = subprocess.run([hapstab, "stability", "--scene", scene, "--certificate", path, "--quiet"], capture_output=True, text=True)
            if r.returncode not in (0, 1) or not os.path.exists(path):
                print("FAIL: no certificate for %s (exit %d): %s" % (scene, r.returncode, r.stderr.strip()))
                return 1
            certs.append(json.load(open(path)))
        same = certs[0]["claim"] == certs[1]["claim"] and certs[0]["evidence"] == certs[1]["evidence"]
        print("%s the compact and the written-out scene give the same claim and evidence" % ("ok  " if same else "FAIL"))
        failures += not same
        cases = edits(certs[0])
        failures += run_cases(hapstab, cases, tmp)
    print("compact_scene_case: %d cases, %d failed" % (len(cases) + 1, failures))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
