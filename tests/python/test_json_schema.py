"""The published JSON Schemas of the command line's --json (docs/schema/, docs/json.md; issue 49):
the checker every CLI call of these tests goes through (clitools.cli) refuses what the schema does
not say -- a renamed key, a float where an exact decimal belongs, a status outside the vocabulary
-- and maps each command line to its schema."""
import copy
from fractions import Fraction

import pytest

from clitools import _checker, cli

WALL = "K + B*(z-1)/(T*z)"


@pytest.mark.parametrize("args, name", [
    (["bound", "--H", WALL], "bound"),
    (["bound", "--H", WALL, "--max", "K", "--damping", "5"], "bound-max"),
    (["stability", "--plant", "1/s^2", "--H", "1"], "stability"),
    (["stability", "--scene", "x.toml"], "stability-scene"),
    (["stability", "--scene", "x.toml", "--max", "K"], "stability-max"),
    (["multidof", "analyze", "--scene", "x.toml"], "multidof-analyze"),
    (["multidof", "design", "--scene", "x.toml"], "multidof-design"),
    (["passivity-level", "--H", "1"], "passivity-level"),
    (["sweep", "spec.toml"], None),
])
def test_each_command_line_has_its_schema(args, name):
    assert _checker.schema_name(args) == name


def test_the_schema_refuses_what_it_does_not_say():
    args = ["bound", "--H", WALL, "--T", "1/1000", "--set", "K=1000", "--set", "B=5"]
    _, j = cli(*args)  # validates (clitools.cli)
    assert _checker.validate(args, j) == []
    renamed = copy.deepcopy(j)
    renamed["lower_bound"] = renamed.pop("enclosure")[0]
    problems = _checker.validate(args, renamed)
    assert any("'enclosure' is a required property" in p for p in problems), problems
    assert any("'lower_bound' was unexpected" in p for p in problems), problems
    as_float = dict(j, bound=5.5)  # an exact value must be a decimal string, never a binary float
    assert any("/bound" in p for p in _checker.validate(args, as_float))
    bad_status = dict(j, status="proven")
    assert any("/status" in p for p in _checker.validate(args, bad_status))
    inverted = dict(j, enclosure=["5.5"])
    assert any("/enclosure" in p for p in _checker.validate(args, inverted))


def test_a_command_without_json_has_no_schema():
    assert _checker.validate(["sweep", "spec.toml"], {})[0].startswith("no schema for `hapstab sweep")


def test_the_docs_validation_recipe_runs_as_shown(tmp_path):
    # docs/json.md "Checking it yourself": the ```sh block, run as shown (hapstab on PATH, a tree
    # with docs/schema/ as the working folder)
    import os
    import re
    import shutil
    import subprocess
    from clitools import CLI, _TOP
    text = open(os.path.join(_TOP, "docs", "json.md"), encoding="utf-8").read()
    block = re.search(r"## Checking it yourself.*?```sh\n(.*?)\n```", text, re.S).group(1)
    (tmp_path / "docs").symlink_to(os.path.join(_TOP, "docs"))
    bindir = tmp_path / "bin"
    bindir.mkdir()
    (bindir / "hapstab").symlink_to(os.path.abspath(CLI) if os.sep in CLI else shutil.which(CLI))
    env = dict(os.environ, PATH=f"{bindir}{os.pathsep}{os.environ['PATH']}")
    p = subprocess.run(["bash", "-euo", "pipefail", "-c", block], cwd=tmp_path, env=env, capture_output=True,
                       text=True, check=False)
    assert p.returncode == 0 and p.stdout.strip() == "valid", (p.stdout, p.stderr)


@pytest.mark.parametrize("args, status", [
    (["passivity-level", "--H", "1 + 1/(z-0.5)", "--T", "0.01"], "exact"),
    (["passivity-level", "--H", "2 + (z+0.3)/(z^2 - 0.5*z + 0.3)", "--T", "0.01", "--kind", "isp"], "certified"),
    (["passivity-level", "--H", "1/(z-0.5)", "--T", "0.01", "--kind", "osp"], "upper_bound"),
])
def test_passivity_level_writes_its_enclosure_under_the_common_name(args, status):
    # issue 49: `enclosure` as bound and stability write it; the old lower_bound/upper_bound are its
    # ends (deprecated); an upper bound alone (OSP <= 0, docs/passivity-levels.md) has no lower end
    from clitools import F
    _, j = cli(*args)
    assert j["status"] == status
    lo, hi = j["enclosure"]
    assert lo == (j["lower_bound"] if j["lower_bound"] is not None else "-inf")
    assert hi == (j["upper_bound"] if j["upper_bound"] is not None else "inf")
    if status == "upper_bound":
        assert (lo, hi) == ("-inf", "-1.5")
    else:
        assert F(lo) <= F(j["exact"] or j["value"]) <= F(hi)


def _schemas():
    import glob
    import json
    import os
    from clitools import _TOP
    return {os.path.basename(p)[:-len(".schema.json")]: json.load(open(p, encoding="utf-8"))
            for p in sorted(glob.glob(os.path.join(_TOP, "docs", "schema", "*.schema.json")))}


def _properties(node, where=""):
    """(where, key, schema) of every property of a schema, nested objects and array items included."""
    if isinstance(node, dict):
        for key, sub in node.get("properties", {}).items():
            yield f"{where}/{key}", key, sub
        for key, sub in node.items():
            yield from _properties(sub, f"{where}/{key}" if key not in ("properties", "items", "oneOf") else where)
    elif isinstance(node, list):
        for sub in node:
            yield from _properties(sub, where)


def _refs(schema):
    """The common definitions a property's schema refers to (through oneOf too)."""
    found = {schema.get("$ref", "")} | {s.get("$ref", "") for s in schema.get("oneOf", [])}
    return {r.split("/")[-1] for r in found if r.startswith("common.schema.json#/$defs/")}


def test_the_same_things_go_by_the_same_names_in_every_schema():
    # issue 49: a status is a word of the shared vocabulary wherever a key says status; a path, the
    # digits asked for and the digits proven each have one definition (common.schema.json) that
    # every command's schema refers to; no schema spells them its own way
    shared = {"status": "status", "path": "path", "digits": "digits", "digits_certified": "digits_certified",
              "status_detail": "status_detail"}
    seen = set()
    for name, schema in _schemas().items():
        if name == "common":
            continue
        for where, key, sub in _properties(schema):
            if sub.get("deprecated"):
                continue
            want = shared.get(key) or ("status" if key.endswith("_status") else
                                       "digits_certified" if key.endswith("_digits_certified") else None)
            if want == "digits_certified" and key != want:
                continue  # a prefixed value's (wedge.margin_digits_certified): an integer, described as such
            if want:
                assert want in _refs(sub), f"{name}.schema.json {where}: not the common {want} ({sub})"
                seen.add((key, name))
            assert not (key.endswith("_digits") or key == "max_digits"), \
                f"{name}.schema.json {where}: digits go by digits / digits_certified (docs/json.md)"
    for key, commands in {"digits_certified": ("r", "bound-max", "stability-max"), "status_detail": ("r",),
                          "path": ("bound", "bound-max", "stability", "stability-max", "stability-scene",
                                   "multidof-analyze", "multidof-design")}.items():
        for c in commands:
            assert (key, c) in seen, (key, c)


def test_every_old_name_is_marked_deprecated_and_listed_in_the_docs_table():
    import os
    import re
    from clitools import _TOP
    text = open(os.path.join(_TOP, "docs", "json.md"), encoding="utf-8").read()
    table = re.search(r"## Old names kept for one release\n(.*?)\n## ", text, re.S).group(1)
    listed = set(re.findall(r"`(?:[a-z_]+\.)?([a-z_]+)`", "\n".join(
        row.split("|")[2] for row in table.splitlines() if row.startswith("| `"))))
    deprecated = {key for name, schema in _schemas().items() for _, key, sub in _properties(schema)
                  if sub.get("deprecated")}
    assert deprecated == listed, (deprecated, listed)
    assert "Names that still differ" not in text


def test_r_writes_its_status_as_a_word_and_the_sentence_beside_it():
    _, j = cli("r", "--T", "1/1000", "--omega", "100", "--digits", "25")
    assert (j["status"], j["series_status"]) == ("certified", "certified")
    assert j["status_detail"].startswith("re exact (-T/2), im certified")
    assert "series_error_bound" in j["series_status_detail"]
    assert (j["digits"], j["digits_certified"]) == (25, 25)


def test_bound_max_writes_its_crossing_frequency_as_omega_enclosure():
    # bound's omega is a decimal (the maximiser); an enclosure takes the shared suffix
    _, j = cli("bound", "--H", WALL, "--T", "1/1000", "--set", "B=2", "--damping", "5", "--delay", "1", "--max", "K")
    lo, hi = (float(x) for x in j["omega_enclosure"])
    assert 0 < lo <= hi and j["omega"] == j["omega_enclosure"]


@pytest.mark.parametrize("args, path", [
    (["bound", "--H", WALL, "--T", "1/1000", "--set", "B=2", "--damping", "5", "--max", "K", "--digits", "40"], "exact"),
    (["bound", "--H", WALL, "--T", "1/1000", "--set", "B=2", "--damping", "5", "--max", "K", "--delay", "300"],
     "long_delay"),
    (["stability", "--plant", "1/(m*s^2 + b*s)", "--H", WALL, "--T", "1/1000", "--delay", "1", "--set", "m=1",
      "--set", "b=5", "--set", "B=2", "--max", "K", "--digits", "25"], "polynomial"),
])
def test_max_writes_the_digits_asked_and_the_digits_proven_under_the_shared_names(args, path):
    # issue 49: digits (asked) and digits_certified (of the printed max, proven); max_digits is the old
    # name of digits_certified, kept for one release (deprecated in the schema)
    from clitools import F
    _, j = cli(*args)
    asked = int(args[args.index("--digits") + 1]) if "--digits" in args else 30
    assert j["digits"] == asked and j["path"] == path
    assert j["digits_certified"] == j["max_digits"] and 0 < j["digits_certified"] <= asked
    # what digits_certified promises: max and both ends of the proven enclosure agree to that many digits
    lo, hi, m = F(j["enclosure"][0]), F(j["enclosure"][1]), F(j["max"])
    ulp = Fraction(10) ** (len(str(int(m))) - j["digits_certified"])  # a unit in the last certified place (m >= 1)
    assert m >= 1 and hi - lo <= ulp and abs(m - lo) <= ulp and abs(m - hi) <= ulp, (j["enclosure"], j["max"])


def test_stability_scene_writes_the_path_that_decided():
    from clitools import _TOP
    import os
    for scene, path in (("000_two_dof_loop.toml", "closed_loop_matrix"), ("001_tightness_below.toml", "polynomial")):
        _, j = cli("stability", "--scene", os.path.join(_TOP, "examples", scene))
        assert j["path"] == path, (scene, j["path"], j["method"])


def test_wedge_and_passivity_level_keep_their_old_names_beside_the_shared_ones():
    from clitools import F
    _, w = cli("wedge", "--H", "0.5*(z+1)/(z^2-0.5*z)", "--digits", "12")
    for part in ("wedge", "tsypkin"):
        for v in ("margin", "max_gain"):
            assert w[part][f"{v}_digits_certified"] == w[part][f"{v}_digits"] == 12
    _, p = cli("passivity-level", "--H", "1 + 1/(z-0.5)", "--T", "0.01", "--kind", "osp")
    c = p["certified_frequency"]
    assert c["enclosure"] == [c["lower_bound"], c["upper_bound"]]
    assert F(c["enclosure"][0]) <= F(c["exact"]) <= F(c["enclosure"][1])


def test_the_cli_tests_records_are_validated_and_an_invalid_one_fails(tmp_path, capsys):
    # ctest cli_json_schema: the --json runs the C++ CLI tests record (tests/cli/cli_run.hpp), read
    # back by check-json-schema --dumped: shell words or an argv, stdout text or an in-process document
    import json
    args = ["bound", "--H", WALL, "--T", "1/1000", "--set", "K=1000", "--set", "B=5"]
    _, good = cli(*args)
    assert _checker.check_dumped(str(tmp_path)) == 1  # nothing recorded: the tests did not run with the variable
    (tmp_path / "1.json").write_text(json.dumps({"test": "T.good", "command": f"bound --H '{WALL}' --T 1/1000 --json",
                                                 "exit": 0, "stdout": json.dumps(good, indent=2)}))
    (tmp_path / "2.json").write_text(json.dumps({"test": "T.error", "command": "bound --H 1/(z-2 --json", "exit": 2,
                                                 "stdout": "hapstab: error: --H: ..."}))
    assert _checker.check_dumped(str(tmp_path)) == 0
    assert "2 --json runs recorded" in capsys.readouterr().out
    (tmp_path / "4.json").write_text(json.dumps({"test": "T.bad", "argv": args + ["--json"], "exit": 0,
                                                 "json": dict(good, status="proven")}))
    assert _checker.check_dumped(str(tmp_path)) == 1
    assert "T.bad: `hapstab bound" in capsys.readouterr().out
