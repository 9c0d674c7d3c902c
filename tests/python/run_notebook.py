#!/usr/bin/env python3
"""Executes a notebook (examples/python/tour.ipynb) with Debian's nbclient, in the kernel a reader
makes as the pages say (issue 49: Debian's kernel "python3" runs /usr/bin/python3, which does not
see the venv): README's Python block, run as written with its venv in --out, installs the package
from the build folder --build-dir, and docs/python.md's Jupyter block registers that venv as a
kernel (into --out's JUPYTER_DATA_DIR, not the user's). The notebook runs in that kernel with
the build tree off the path (PYTHONPATH removed), and a last cell checks that hapstab came from
the venv. Then its outputs are checked, not only that it ran: each cell tagged check:NAME must
show the text CHECKS[NAME] expects (regular expressions over its stream and display outputs), a
cell that displays a result must show its HTML and LaTeX forms, the figure cells must show a PNG,
and no cell may raise. The executed notebook is written to --out for a look.

    /usr/bin/python3 tests/python/run_notebook.py examples/python/tour.ipynb --out build/python-notebook --build-dir build
(ctest runs it as python_notebook.)"""
import argparse
import os
import re
import shutil
import subprocess
import sys

import nbformat
from nbclient import NotebookClient
from nbclient.exceptions import CellExecutionError

from clitools import _TOP, block

# what each tagged cell must print (all of them, in its text outputs)
CHECKS = {
    "check:exact": [r"status='exact'", r"value: 11/2 \| passive with device damping 6\? True",
                    r"closed form: virtual wall"],
    "check:undecided": [r"^certified ", r"UndecidedComparison: cannot decide b\* == ", r"b\* > 0\.1 \? (True|False)"],
    "check:vector": [r"^10001 certified bounds in [0-9.]+ s; hapstab\.ResultArray\(Bound, shape=\(10001,\)",
                     r"failed=0", r"largest passive K without delay: 5998\.0 \(closed form",
                     r"largest passive K with one sample of delay: [0-9]+\.[0-9]",
                     r"^max='K' without delay: 6000 exact \| closed form \(46\)$",
                     r"^max='K' with one sample of delay: 4000 exact \| b\* = b at both ends: True$"],
    "check:map": [r"^points: 651 \| passive: [0-9]+ \| stable: [0-9]+ \| passive but not stable at K > 0: 0$",
                  r"^stable at K = 0: 0$"],
    # each verdict names its loop (issue 49): Theorem 5's conclusion is about the loop with a
    # coupling meeting (14), case ii's own loop (no coupling) is NOT stable, so bool(a) is False
    "check:multidof": [r"^Theorem 5 on case ii: \(16\) feasible \| certified: True \| premises: (holds, )*holds$",
                       r"^  concludes stability of the loop with a coupling V meeting Delta_V >= Gamma\^-1 Q_V Gamma\^-1: True$",
                       r"^  Q_V = \[\[",
                       r"^  case ii's loop as written \(coupling: none \(the direct connection\)\): NOT stable \[certified\]$",
                       r"^  bool\(a\), concluded and the loop as written not proven unstable: False$",
                       r"^Theorem 6 on case ii perturbed: V of order [0-9]+ \| verified: True \| ([0-9]+) of \1 checks pass$",
                       r"^  the loop with the designed V: stable \[(certified|exact)\]$",
                       r"^000_two_dof_loop\.toml, its loop as written: stable \[certified\] \| hidden modes: "
                       r"\[\('environment', 'unobservable', True\)\]$",
                       r"^  simulated \([0-9]+, 2\) samples x DOFs; diverged: False"],
    "check:figure": [r"saved tour_bound\.png"],
    "check:table": [r"K\s+value\s+lo\s+hi\s+status"],
}
IMAGES = {"check:map", "check:figure"}  # cells that must display a PNG
RICH = {"check:exact"}                   # cells whose last value is a result: HTML and LaTeX shown


def text_of(cell) -> str:
    parts = []
    for o in cell.get("outputs", []):
        if o.get("output_type") == "stream":
            parts.append(o.get("text", ""))
        elif "data" in o and "text/plain" in o["data"]:
            parts.append(o["data"]["text/plain"])
    return "".join(parts)


def as_in(folder: str, build_dir: str, text: str) -> str:
    """A block's words with its venv in FOLDER and HAPSTAB_BUILD_DIR=BUILD_DIR: the rest as shown."""
    text = re.sub(r"(?<![\w/.-])(?<!-m )venv(?=/|\s|$)", os.path.join(folder, "venv"), text, flags=re.M)
    return text.replace("HAPSTAB_BUILD_DIR=build ", f"HAPSTAB_BUILD_DIR={build_dir} ")


def readers_kernel(folder: str, build_dir: str) -> str:
    """The venv of README's Python block with the kernel of docs/python.md's Jupyter block, made in
    FOLDER from the top of the tree as a reader would; returns the kernel's name."""
    shutil.rmtree(os.path.join(folder, "venv"), ignore_errors=True)
    shutil.rmtree(os.path.join(folder, "jupyter"), ignore_errors=True)
    os.environ["JUPYTER_DATA_DIR"] = os.path.join(folder, "jupyter")  # --user installs the kernel here
    for page, section in (("README.md", "Python"), ("docs/python.md", "Jupyter")):
        words = as_in(folder, os.path.abspath(build_dir), block(page, section, "sh"))
        p = subprocess.run(["bash", "-euo", "pipefail", "-c", words], cwd=_TOP, capture_output=True, text=True,
                           check=False)
        if p.returncode != 0:
            sys.exit(f"run_notebook: {page}'s {section} block failed (exit {p.returncode}):\n{words}\n{p.stdout}{p.stderr}")
    return re.search(r"--name (\S+)", block("docs/python.md", "Jupyter", "sh")).group(1)


def main() -> int:
    p = argparse.ArgumentParser(description=__doc__)
    p.add_argument("notebook")
    p.add_argument("--out", required=True, help="folder for the executed notebook and what it writes")
    p.add_argument("--build-dir", required=True, help="the CMake build folder README's block installs from")
    p.add_argument("--timeout", type=int, default=600, help="seconds per cell (a hang guard)")
    a = p.parse_args()
    a.out = os.path.abspath(a.out)
    os.makedirs(a.out, exist_ok=True)
    for name in ("PYTHONPATH", "MPLBACKEND"):  # the venv's package, not the build tree's; figures inline
        os.environ.pop(name, None)
    kernel = readers_kernel(a.out, a.build_dir)
    nb = nbformat.read(a.notebook, as_version=4)
    venv = os.path.join(a.out, "venv", "")
    nb.cells.append(nbformat.v4.new_code_cell("import sys, hapstab\nprint(sys.prefix, hapstab.__file__)"))
    client = NotebookClient(nb, kernel_name=kernel, timeout=a.timeout, resources={"metadata": {"path": a.out}})
    try:
        client.execute()
    except CellExecutionError as e:
        print(f"run_notebook: a cell raised:\n{e}", file=sys.stderr)
        return 1
    finally:
        nbformat.write(nb, os.path.join(a.out, os.path.basename(a.notebook)))
    failures, seen = [], set()
    where = text_of(nb.cells.pop())
    if not where.startswith(venv.rstrip(os.sep) + " " + venv):
        failures.append(f"the kernel {kernel!r} is not the venv's, or its hapstab is not the venv's: {where.strip()}")
    for i, cell in enumerate(nb.cells):
        if cell.cell_type != "code":
            continue
        for o in cell.get("outputs", []):
            if o.get("output_type") == "error":
                failures.append(f"cell {i}: {o.get('ename')}: {o.get('evalue')}")
        for tag in cell.metadata.get("tags", []):
            if not tag.startswith("check:"):
                continue
            seen.add(tag)
            text = text_of(cell)
            for pattern in CHECKS[tag]:
                if not re.search(pattern, text, re.M):
                    failures.append(f"cell {i} ({tag}): no match for {pattern!r} in:\n{text}")
            kinds = {k for o in cell.get("outputs", []) for k in o.get("data", {})}
            if tag in IMAGES and "image/png" not in kinds:
                failures.append(f"cell {i} ({tag}): no PNG shown (outputs: {sorted(kinds)})")
            if tag in RICH and not {"text/html", "text/latex"} <= kinds:
                failures.append(f"cell {i} ({tag}): the result's HTML/LaTeX forms were not shown ({sorted(kinds)})")
    missing = set(CHECKS) - seen
    if missing:
        failures.append(f"the notebook has no cell tagged {sorted(missing)}")
    if not os.path.exists(os.path.join(a.out, "tour_bound.png")):
        failures.append("the figure tour_bound.png was not written")
    for f in failures:
        print("run_notebook: FAILED " + f, file=sys.stderr)
    print(f"run_notebook: {len(seen)} checked cells, {len(failures)} failures ({a.notebook})")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
