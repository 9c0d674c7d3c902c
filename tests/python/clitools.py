"""What the pytest files share: the command line beside the module (`hapstab ... --json`) and the
exact reading of its decimals."""
import json
import os
import subprocess
from fractions import Fraction

CLI = os.environ.get("HAPSTAB_CLI", "hapstab")


def cli(*args, codes=(0, 1)):
    """`hapstab args... --json`: (exit code, JSON); the exit code must be one of `codes`."""
    p = subprocess.run([CLI, *args, "--json"], capture_output=True, text=True, check=False)
    assert p.returncode in codes, p.stderr
    return p.returncode, json.loads(p.stdout)


def F(text):
    """An exact decimal / p/q string as a Fraction."""
    num, _, den = text.partition("/")
    return Fraction(num) / Fraction(den) if den else Fraction(num)
