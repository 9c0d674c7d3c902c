#!/usr/bin/env python3
"""bench/python_binding.py -- hapstab's vectorised Python calls (issue 41) against the C++ calls
they make, in the same run: the wall time of one Python call over N points (median of --repeat
runs, every thread of the machine) beside N times the C++ cost of one point on one thread
(bench_python_binding, Google Benchmark), and the ratio of the two (< 1: the threads more than
pay for the binding; the binding's own cost is the rest). Targets (issue 41; reported, not
asserted -- a benchmark states, the tests check):
    r over 10^6 frequencies (closed form, double)   <= 0.1 s
    certified b* over 10^4 values of K              <= 2 s
    fast b* over 10^5 values of K                   <= 2 s
and the per-call cost of a scalar call (the old binding ran the command in a forked child:
3.3 ms per certified bound of the wall, 4.5 ms per r).

    PYTHONPATH=build/python /usr/bin/python3 bench/python_binding.py [--bench build/bench/bench_python_binding]
        [--repeat 5] [--json FILE]
"""
import argparse
import json
import os
import statistics
import subprocess
import sys
import time

import numpy as np

import hapstab

WALL = "K + B*(z-1)/(T*z)"


def timed(fn, repeat):
    """(median wall seconds, the last result) over `repeat` runs."""
    times, out = [], None
    for _ in range(repeat):
        t0 = time.perf_counter()
        out = fn()
        times.append(time.perf_counter() - t0)
    return statistics.median(times), out


def cpp_costs(bench):
    """Seconds per point of each C++ benchmark (bench_python_binding) on one thread: wall time, as the
    Python calls are timed (on a shared machine both see the same load)."""
    p = subprocess.run([bench, "--benchmark_format=json", "--benchmark_min_time=0.5"], capture_output=True, text=True,
                       check=True)
    scale = {"ns": 1e-9, "us": 1e-6, "ms": 1e-3, "s": 1.0}
    out = {}
    for b in json.loads(p.stdout)["benchmarks"]:
        out[b["name"].split("/")[0].removeprefix("BM_")] = b["real_time"] * scale[b["time_unit"]]
    return out


def main() -> int:
    here = os.path.dirname(os.path.abspath(__file__))
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--bench", default=os.path.join(here, "..", "build", "bench", "bench_python_binding"))
    ap.add_argument("--repeat", type=int, default=5)
    ap.add_argument("--json", help="write the numbers to FILE")
    a = ap.parse_args()
    cpp = cpp_costs(a.bench)
    rows = []

    w = np.linspace(0.5, 3000.0, 10**6)
    s, r = timed(lambda: hapstab.r("1/1000", w), a.repeat)
    assert r.im.shape == w.shape
    rows.append(("r(T, omega) double, 10^6 w", w.size, s, cpp["r_double"], 0.1))

    K = np.linspace(0, 40000, 10**4)
    s, b = timed(lambda: hapstab.bound(WALL, T="1/1000", delay=1, params={"K": K, "B": 5}), a.repeat)
    assert b.failed == 0 and set(b.status_names) <= {"exact", "certified"}
    rows.append(("bound certified, 10^4 K", K.size, s, cpp["bound_cert"], 2.0))

    K5 = np.linspace(0, 40000, 10**5)
    s, f = timed(lambda: hapstab.bound(WALL, T="1/1000", delay=1, params={"K": K5, "B": 5}, method="fast"), a.repeat)
    assert f.failed == 0
    rows.append(("bound fast, 10^5 K", K5.size, s, cpp["bound_fast"], 2.0))

    one = lambda: hapstab.bound(WALL, T="1/1000", params={"K": 1000, "B": 5})  # noqa: E731
    s, _ = timed(lambda: [one() for _ in range(1000)], a.repeat)
    rows.append(("bound scalar call (exact wall), 1 point", 1, s / 1000, None, None))
    s, _ = timed(lambda: [hapstab.r("1/1000", 100) for _ in range(1000)], a.repeat)
    rows.append(("r scalar call (20 digits), 1 point", 1, s / 1000, None, None))

    cpus = len(os.sched_getaffinity(0))
    print(f"hapstab {hapstab.__version__}, {cpus} CPUs, load average {os.getloadavg()[0]:.1f}; "
          f"median of {a.repeat}; C++: bench_python_binding, one thread, wall time")
    print(f"{'call':42} {'points':>8} {'Python [s]':>11} {'C++ N x 1 pt [s]':>17} {'ratio':>7} {'target':>8}  met")
    report = []
    for name, n, s, per, target in rows:
        cxx = None if per is None else n * per
        ratio = None if cxx is None else s / cxx
        met = "" if target is None else ("yes" if s <= target else "NO")
        print(f"{name:42} {n:8d} {s:11.4g} {('' if cxx is None else f'{cxx:.4g}'):>17} "
              f"{('' if ratio is None else f'{ratio:.2f}'):>7} {('' if target is None else f'<= {target:g}'):>8}  {met}")
        report.append({"call": name, "points": n, "python_seconds": s, "cpp_seconds": cxx, "ratio": ratio,
                       "target_seconds": target})
    print(f"C++ per point: parse_tf {cpp['parse'] * 1e6:.2f} us, the expression parsed once and evaluated at one K "
          f"{cpp['parsed_at'] * 1e6:.2f} us, "
          f"fast b* {cpp['bound_fast'] * 1e6:.2f} us, certified b* {cpp['bound_cert'] * 1e6:.1f} us, "
          f"r {cpp['r_double'] * 1e9:.1f} ns")
    if a.json:
        with open(a.json, "w", encoding="utf-8") as f:
            json.dump({"cpus": cpus, "cpp_per_point": cpp, "rows": report}, f, indent=2)
    return 0


if __name__ == "__main__":
    sys.exit(main())
