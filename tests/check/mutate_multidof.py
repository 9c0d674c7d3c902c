"""The multidof-witness kind of tests/check/mutate.py (issue 47): `multidof analyze --scene S
--certificate F` on the witness campaign's random scenes (tests/verify/indep_witness.py's gen: walls
K + B(z - 1)/(Tz) with resonances near the circle, linked walls, contact scenes in s by backward
Euler, two independent parts; delays 0-24; device levels placed 1e-2..1e-6 from Theorem 5's
boundary or far from it), kept where the one-frequency witness decided (16) infeasible, and their
mutants with what must happen (mutate.py's accept / refute / malformed / agree)."""
import copy
import json
import os
import subprocess
import sys
from fractions import Fraction

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "verify"))


def produce(hapstab, rng, tmp, i):
    """A certificate of a random scene, or the reason none was written."""
    import indep_witness  # the witness campaign's scene generator (numpy, mpmath: only for this kind)
    case = indep_witness.gen(rng)
    scene = os.path.join(tmp, "w%d.toml" % i)
    with open(scene, "w") as f:
        f.write(case["text"])
    path = os.path.join(tmp, "w%d.json" % i)
    p = subprocess.run([hapstab, "multidof", "analyze", "--scene", scene, "--quiet", "--certificate", path],
                       capture_output=True, text=True)
    if p.returncode == 2 and "no certificate kind yet" in p.stderr:
        return "feasible or decided another way (no kind)"
    if p.returncode != 1 or not os.path.exists(path):
        return "exit %d: %s" % (p.returncode, p.stderr.strip().split("error: ", 1)[-1][:60])
    with open(path) as f:
        return json.load(f)


def _set(c, path, value):
    c = copy.deepcopy(c)
    o = c
    for k in path[:-1]:
        o = o[k]
    if value is None:
        del o[path[-1]]
    else:
        o[path[-1]] = value
    return c


def fs(x):
    return str(Fraction(x))


def mutants(cert, rng):
    """[(name, certificate, expectation)] of one multidof-witness certificate."""
    out = [("unmutated", cert, "accept")]
    ev, model = cert["evidence"], cert["model"]
    m = len(ev["u"])
    zr, zi = Fraction(ev["z_re"]), Fraction(ev["z_im"])
    # refute: the claim or the evidence made false on its face
    out.append(("u = 0", _set(cert, ["evidence", "u"], ["0"] * m), "refute"))
    out.append(("z = 1", _set(_set(cert, ["evidence", "z_re"], "1"), ["evidence", "z_im"], "0"), "refute"))
    out.append(("z off the circle", _set(cert, ["evidence", "z_re"], fs(zr * Fraction(1000001, 1000000))), "refute"))
    out.append(("z conjugated off the circle", _set(cert, ["evidence", "z_im"], fs(zi + Fraction(1, 10 ** 12))), "refute"))
    out.append(("claim feasible", _set(cert, ["claim", "feasible"], True), "refute"))
    big = [dict(d) for d in model["devices"]]
    for d in big:
        d["osp" if "osp" in d else "b"] = fs(Fraction(d.get("osp", d.get("b"))) + 10 ** 15)
    out.append(("device levels raised by 1e15", _set(cert, ["model", "devices"], big), "refute"))
    # malformed: a field deleted or added, a value of the wrong form
    for path in (["model", "T"], ["model", "delay"], ["model", "environment"], ["model", "devices"], ["model", "operators"],
                 ["model", "environment", "E"], ["model", "environment", "gain"], ["model", "environment", "domain"],
                 ["evidence", "u"], ["evidence", "z_re"], ["claim", "feasible"], ["claim", "status"]):
        out.append(("deleted " + ".".join(path), _set(cert, path, None), "malformed"))
    out.append(("added model.frac_delay", _set(cert, ["model", "frac_delay"], "1/2000"), "malformed"))
    out.append(("added evidence.theta", _set(cert, ["evidence", "theta"], "1"), "malformed"))
    out.append(("status certified", _set(cert, ["claim", "status"], "certified"), "malformed"))
    out.append(("T negative", _set(cert, ["model", "T"], "-" + model["T"]), "malformed"))
    out.append(("delay negative", _set(cert, ["model", "delay"], -1), "malformed"))
    out.append(("u a decimal", _set(cert, ["evidence", "u"], ["0.5"] + ev["u"][1:]), "malformed"))
    out.append(("u one short", _set(cert, ["evidence", "u"], ev["u"][:-1]), "malformed"))
    out.append(("method zoh", _set(cert, ["model", "environment", "method"], "zoh"), "malformed"))
    out.append(("domain w", _set(cert, ["model", "environment", "domain"], "w"), "malformed"))
    out.append(("a device one DOF more", _set(cert, ["model", "devices"],
                                              [dict(model["devices"][0], dofs=model["devices"][0]["dofs"] + 1)] + model["devices"][1:]),
                "malformed"))
    out.append(("a DOF in two operators", _set(cert, ["model", "operators"], model["operators"] + [[0]]), "malformed"))
    out.append(("an entry unparsable", _set(cert, ["model", "environment", "E"],
                                            [[e + " *" if (i, j) == (0, 0) else e for j, e in enumerate(r)]
                                             for i, r in enumerate(model["environment"]["E"])]), "malformed"))
    if m >= 2:  # E(1) no longer symmetric: outside the kind
        E = copy.deepcopy(model["environment"]["E"])
        E[0][1] = "(" + E[0][1] + ") + 1"
        out.append(("E(1) not symmetric", _set(cert, ["model", "environment", "E"], E), "malformed"))
        merged = [[i for i in range(m)]]
        out.append(("operators merged", _set(cert, ["model", "operators"], merged), "agree"))
        split = [[i] for i in range(m)]
        out.append(("operators split", _set(cert, ["model", "operators"], split), "agree"))
    # agree: the model or the evidence moved, the claim unknown: the two checkers must agree
    out.append(("delay + 1", _set(cert, ["model", "delay"], model["delay"] + 1), "agree"))
    out.append(("T doubled", _set(cert, ["model", "T"], fs(2 * Fraction(model["T"]))), "agree"))
    out.append(("gain negated", _set(cert, ["model", "environment", "gain"], fs(-Fraction(model["environment"]["gain"]))), "agree"))
    out.append(("gain x 1.01", _set(cert, ["model", "environment", "gain"], fs(Fraction(101, 100) * Fraction(model["environment"]["gain"]))), "agree"))
    k = rng.randrange(m)
    u = list(ev["u"])
    u[k] = fs(-Fraction(u[k]) if Fraction(u[k]) != 0 else 1)
    out.append(("u[%d] flipped" % k, _set(cert, ["evidence", "u"], u), "agree"))
    out.append(("z conjugated", _set(cert, ["evidence", "z_im"], fs(-zi)), "agree"))
    # another rational point of the circle: t = tan(theta/2) moved by 1e-3 relative
    t = zi / (1 + zr) if zr != -1 else None
    if t is not None and t != 0:
        t2 = t * Fraction(1001, 1000)
        out.append(("z moved along the circle", _set(_set(cert, ["evidence", "z_re"], fs((1 - t2 * t2) / (1 + t2 * t2))),
                                                    ["evidence", "z_im"], fs(2 * t2 / (1 + t2 * t2))), "agree"))
    for name in list(model.get("set", {}))[:3]:
        v = Fraction(model["set"][name])
        out.append(("set.%s x 1.01" % name, _set(cert, ["model", "set", name], fs(v * Fraction(101, 100))), "agree"))
    return out


def branches(certs):
    ws = [c for k, c in certs if k == "multidof-witness"]
    if not ws:
        return ""
    return ("  multidof-witness branches: DOF 1 %d, 2-4 %d; s-domain %d; delay 0 %d, 1 %d, >= 2 %d; z = -1 %d; "
            "several operator groups %d; a declared osp %d" % (
                sum(1 for c in ws if len(c["evidence"]["u"]) == 1), sum(1 for c in ws if len(c["evidence"]["u"]) > 1),
                sum(1 for c in ws if c["model"]["environment"]["domain"] == "s"),
                sum(1 for c in ws if c["model"]["delay"] == 0), sum(1 for c in ws if c["model"]["delay"] == 1),
                sum(1 for c in ws if c["model"]["delay"] >= 2), sum(1 for c in ws if c["evidence"]["z_re"] == "-1"),
                sum(1 for c in ws if len(c["model"]["operators"]) > 1 and "0" in c["model"]["environment"]["E"][0]),
                sum(1 for c in ws if any("osp" in d for d in c["model"]["devices"]))))
