"""The published JSON Schemas of the command line's --json (docs/schema/, docs/json.md; issue 49):
the checker every CLI call of these tests goes through (clitools.cli) refuses what the schema does
not say -- a renamed key, a float where an exact decimal belongs, a status outside the vocabulary
-- and maps each command line to its schema."""
import copy

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
