"""What the pytest files share: the command line beside the module (`hapstab ... --json`, every
output validated against its published JSON Schema, docs/schema/) and the exact reading of its
decimals."""
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


def F(text):
    """An exact decimal / p/q string as a Fraction."""
    num, _, den = text.partition("/")
    return Fraction(num) / Fraction(den) if den else Fraction(num)
