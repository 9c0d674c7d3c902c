"""hapstab.sweep: the sweep layer from Python (issue 17/18/41): the table is the command's own
(equal to single hapstab.bound calls) as a structured numpy array, specs as dicts, TOML text or
paths, errors naming the key (and no temporary file); Ctrl-C or a kill ends its worker processes too
(issue 49)."""
import json
import math
import os
import signal
import subprocess
import sys
import time
from fractions import Fraction

import numpy as np
import pytest

import hapstab

SPEC = {"command": "bound",
        "args": {"H": "K + B*(z-1)/(T*z)", "T": "1/1000", "delay": 1},
        "axes": {"K": {"from": "0", "to": "3000", "points": 4}, "B": {"values": ["0", "5/2"]}}}


def test_a_dict_spec_gives_one_row_per_point_equal_to_single_bound_calls(tmp_path):
    t = hapstab.sweep(SPEC, out=tmp_path / "out", jobs=2)
    assert len(t) == 8 and t.failed == 0 and t.exit_code == 0
    assert t.path == str(tmp_path / "out") and (tmp_path / "out" / "points.csv").exists()
    assert isinstance(t, np.ndarray) and t.dtype.names is not None and t.shape == (8,)
    assert list(t.exact["index"]) == [str(i) for i in range(8)]
    assert t["bound"].dtype == np.float64
    assert t["status"].dtype == object
    assert t["index"].dtype == np.int64 and list(t["exit"]) == [0] * 8
    assert t["enclosure_rigorous"].dtype == bool and t["enclosure_rigorous"].all()
    assert t.manifest["points"]["ok"] == 8 and len(t.manifest["spec_sha256"]) == 64
    for i in (0, 3, 6):  # the last axis (B) varies fastest
        K, B = t.exact["K"][i], t.exact["B"][i]
        single = hapstab.bound("K + B*(z-1)/(T*z)", T="1/1000", delay=1, params={"K": K, "B": B})
        assert t.exact["bound"][i] == single.decimal
        assert t.exact["enclosure_lo"][i] == single.lo_exact
        assert t["B"][i] == float(Fraction(B))


def test_toml_text_and_a_path_give_the_same_table(tmp_path):
    text = hapstab._sweep.spec_toml(SPEC)
    path = tmp_path / "spec.toml"
    path.write_text(text)
    a = hapstab.sweep(text)
    b = hapstab.sweep(path)
    assert a.path is None
    for name in a.exact:
        assert list(a.exact[name]) == list(b.exact[name])


def test_a_failing_point_is_a_row_not_an_exception():
    spec = {"command": "bound", "args": {"H": "1/(z-c)", "T": "1/1000"}, "axes": {"c": {"values": ["1/2", "2"]}}}
    t = hapstab.sweep(spec)
    assert t.exit_code == 1 and t.failed == 1
    assert t.exact["error"][0] == "" and "unstable" in t.exact["error"][1]
    assert math.isnan(t["bound"][1])


@pytest.mark.parametrize("spec, match", [
    ({"command": "bound", "args": {"H": "K", "T": "1/1000"}, "axes": {"K": {"values": ["1"]}}, "extra": 1}, "extra"),
    ({"command": "bound", "args": {"H": "K", "T": float("nan")}, "axes": {"K": {"values": ["1"]}}},
     "args.T: nan is not a finite number"),  # a finite float is its shortest decimal (0.001: 1/1000)
    ({"command": "bound", "args": {"H": "K", "T": "1/1000"}, "axes": {"K": {"from": "0"}}}, "K"),
    ({"command": "no-such", "args": {}, "axes": {"K": {"values": ["1"]}}}, "no-such"),
])
def test_a_bad_spec_raises_input_error_naming_it(spec, match):
    with pytest.raises(hapstab.InputError, match=match):
        hapstab.sweep(spec)


def test_to_pandas_is_a_dataframe_when_pandas_is_there():
    t = hapstab.sweep(SPEC)
    try:
        import pandas  # noqa: F401
    except ImportError:
        with pytest.raises(ImportError, match="python3-pandas"):
            t.to_pandas()
        return
    df = t.to_pandas()
    assert list(df.columns) == list(t.dtype.names) and len(df) == len(t)
    assert df["bound"].dtype == np.float64 and list(df["bound"]) == list(t["bound"])


# ---- Ctrl-C stops the workers too (issue 49) ---------------------------------------------------

def _proc_stat(pid):
    """(ppid, state, start time) of a live process from /proc/PID/stat, None once it is gone."""
    try:
        with open(f"/proc/{pid}/stat") as f:
            text = f.read()
    except OSError:
        return None
    fields = text[text.rindex(")") + 2:].split()  # after "pid (comm) "
    return int(fields[1]), fields[0], fields[19]


def _descendants(root):
    """{pid: start time} of every live process below `root` (parent links read from /proc)."""
    children = {}
    for name in os.listdir("/proc"):
        if name.isdigit():
            st = _proc_stat(int(name))
            if st is not None:
                children.setdefault(st[0], []).append((int(name), st[2]))
    found, todo = {}, [root]
    while todo:
        for pid, start in children.get(todo.pop(), []):
            found[pid] = start
            todo.append(pid)
    return found


def _alive(pid, start):
    st = _proc_stat(pid)
    return st is not None and st[2] == start and st[1] != "Z"  # same process (not a reused pid), not a zombie


def _wait_for_processes(root, n):
    """The processes below `root` once there are n of them (a hang guard of 60 s)."""
    seen = {}
    for _ in range(600):
        seen.update(_descendants(root))
        if len(seen) >= n:
            break
        time.sleep(0.1)
    assert len(seen) >= n, f"the sweep's processes did not start: {seen}"
    return seen


def _survivors(seen):
    """The processes of `seen` still running after up to 5 s (a SIGKILLed process may still be leaving)."""
    for _ in range(50):
        survivors = [pid for pid, start in seen.items() if _alive(pid, start)]
        if not survivors:
            break
        time.sleep(0.1)
    return survivors


def _clean_up(p, seen):
    """Kills p and whatever of `seen` still runs: a failed test leaves no orphan behind."""
    p.kill()
    for pid, start in seen.items():
        if _alive(pid, start):
            os.kill(pid, signal.SIGKILL)


def _killed_leaves_none(p, n, what, ready=lambda: True):
    """Once `ready()` and p's n descendants run, SIGKILLs p and asserts none of them outlives it."""
    seen = {}
    try:
        assert ready()
        seen = _wait_for_processes(p.pid, n)
        p.kill()
        p.wait(timeout=60)
        survivors = _survivors(seen)
        assert survivors == [], f"{what}: {survivors}"
    finally:
        _clean_up(p, seen)


MILLION_POINTS = ('{"command": "bound", "args": {"H": "K + B*(z-1)/(T*z)", "T": "1/1000", "delay": 1}, '
                  '"axes": {"K": {"from": "0", "to": "40000", "points": 1000000}, "B": {"values": ["5"]}}}')


def test_a_killed_command_line_sweep_takes_its_workers_with_it(tmp_path):
    # `hapstab sweep` SIGKILLed (it cannot clean up): its workers die with it (PR_SET_PDEATHSIG)
    spec = tmp_path / "spec.toml"
    spec.write_text(hapstab._sweep.spec_toml(json.loads(MILLION_POINTS)))
    cli = os.environ.get("HAPSTAB_CLI", "hapstab")
    p = subprocess.Popen([cli, "sweep", str(spec), "--out", str(tmp_path / "out"), "--jobs", "2", "--quiet"],
                         stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, start_new_session=True)
    _killed_leaves_none(p, 2, "workers still running after their sweep was killed")


@pytest.mark.parametrize("to_group", [False, True])
def test_ctrl_c_during_a_sweep_stops_its_worker_processes(to_group):
    # a sweep of a million points on 2 workers (minutes of work); SIGINT to the Python process alone
    # (as Jupyter's interrupt does) or to its process group (a terminal's Ctrl-C): KeyboardInterrupt,
    # and every process the sweep started -- the forked child and its workers -- is gone
    code = ("import hapstab\nprint('started', flush=True)\ntry:\n"
            f"    hapstab.sweep({MILLION_POINTS}, jobs=2)\n"
            "    print('completed')\nexcept KeyboardInterrupt:\n    print('interrupted', flush=True)\n")
    p = subprocess.Popen([sys.executable, "-c", code], stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                         start_new_session=True)
    seen = {}
    try:
        assert p.stdout.readline().strip() == "started"
        seen = _wait_for_processes(p.pid, 3)  # the forked child and its 2 workers
        if to_group:
            os.killpg(p.pid, signal.SIGINT)
        else:
            p.send_signal(signal.SIGINT)
        out, err = p.communicate(timeout=120)
        assert out.split() == ["interrupted"], (out, err)
        survivors = _survivors(seen)
        assert survivors == [], f"processes of the sweep still running after Ctrl-C: {survivors}"
    finally:
        _clean_up(p, seen)


def test_a_killed_interpreter_takes_the_sweep_with_it():
    # the Python process SIGKILLed mid-sweep (a Jupyter kernel restarted): nothing can clean up, so
    # the forked child and its workers die by PR_SET_PDEATHSIG
    code = f"import hapstab\nprint('started', flush=True)\nhapstab.sweep({MILLION_POINTS}, jobs=2)\n"
    p = subprocess.Popen([sys.executable, "-c", code], stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True,
                         start_new_session=True)
    _killed_leaves_none(p, 3, "processes of the sweep still running after the interpreter died",
                        ready=lambda: p.stdout.readline().strip() == "started")
