"""What the pytest files (and run_notebook.py) share: the command line beside the module
(`hapstab ... --json`, every output validated against its published JSON Schema, docs/schema/),
the exact reading of its decimals, and the code blocks the pages show."""
import importlib.machinery
import importlib.util
import json
import os
import subprocess
from fractions import Fraction

CLI = os.environ.get("HAPSTAB_CLI", "hapstab")
_TOP = os.path.abspath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))


def _schema_checker():
    """scripts/check-json-schema as a module (its validate())."""
    loader = importlib.machinery.SourceFileLoader("check_json_schema",
                                                  os.path.join(_TOP, "scripts", "check-json-schema"))
    spec = importlib.util.spec_from_loader("check_json_schema", loader)
    module = importlib.util.module_from_spec(spec)
    loader.exec_module(module)
    return module


_checker = _schema_checker()


def cli(*args, codes=(0, 1)):
    """`hapstab args... --json`: (exit code, JSON); the exit code must be one of `codes`, and the
    JSON must validate against its schema (docs/json.md)."""
    p = subprocess.run([CLI, *args, "--json"], capture_output=True, text=True, check=False)
    assert p.returncode in codes, p.stderr
    data = json.loads(p.stdout)
    problems = _checker.validate([str(a) for a in args], data)
    assert not problems, "\n".join(problems)
    return p.returncode, data


def block(page, section, language):
    """The first ```LANGUAGE block of PAGE (relative to the top of the tree) under its heading
    `## SECTION` (None: anywhere on the page), as the page shows it."""
    with open(os.path.join(_TOP, page), encoding="utf-8") as f:
        text = f.read()
    if section is not None:
        text = text.split(f"\n## {section}\n", 1)[1].split("\n## ", 1)[0]
    return text.split(f"```{language}\n", 1)[1].split("```", 1)[0]


def F(text):
    """An exact decimal / p/q string as a Fraction."""
    num, _, den = text.partition("/")
    return Fraction(num) / Fraction(den) if den else Fraction(num)
