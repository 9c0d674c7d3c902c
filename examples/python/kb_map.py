#!/usr/bin/env python3
"""A (K, B) map of the passivity bound with hapstab.bound: b*(K, B) of the virtual wall
H = K + B(z-1)/(Tz) with a one-sample delay (n = 1, paper 001 (53)) at T = 1 ms, on a grid,
each b* certified (exact here: the status of every cell is checked), all in ONE vectorised call
(params={"K": K[None, :], "B": B[:, None]} broadcast to the grid, the points on threads). The
contour b* = b marks the walls a device with damping b = 1 N s/m renders passively (b > b*).

    PYTHONPATH=build/python MPLBACKEND=Agg python3 examples/python/kb_map.py --out figs
"""
import time

import numpy as np
import matplotlib.pyplot as plt

import hapstab
from _common import output_folder, save

out = output_folder(__doc__)
T, delay, b_device = "1/1000", 1, 1.0
Ks = np.linspace(0, 2000, 11)  # N/m
Bs = np.linspace(0, 1, 11)     # N s/m
t0 = time.perf_counter()
# the grid values are floats: hapstab reads each as the shortest decimal that rounds to it (0.1 is 1/10)
res = hapstab.bound("K + B*(z-1)/(T*z)", T=T, delay=delay, params={"K": Ks[None, :], "B": Bs[:, None]}, digits=17)
seconds = time.perf_counter() - t0
bstar = res.value  # float64, shape (len(Bs), len(Ks))
statuses = set(res.status.ravel())
print(f"{bstar.size} certified bounds in one call, {seconds:.2f} s ({1e3 * seconds / bstar.size:.2f} ms each); "
      f"status: {', '.join(sorted(statuses))}; failed: {res.failed}")
assert statuses <= {"exact", "certified"} and res.failed == 0, (statuses, res.failed)
# passive where b > b*, decided by each enclosure (raises if a cell's enclosure contains b)
passive = res < b_device
print(f"walls this device renders passively: {int(passive.sum())} of {passive.size}")

fig, ax = plt.subplots(figsize=(6.5, 4.5))
cs = ax.contourf(Bs, Ks, bstar.T, levels=20, cmap="viridis")
fig.colorbar(cs, ax=ax, label="b* [N s/m]")
line = ax.contour(Bs, Ks, bstar.T, levels=[b_device], colors="w", linewidths=2)
ax.clabel(line, fmt={b_device: f"b* = b = {b_device:g}"})
ax.set_xlabel("virtual damping B [N s/m]")
ax.set_ylabel("virtual stiffness K [N/m]")
ax.set_title(f"b*(K, B) of K + B(z-1)/(Tz), delay n = {delay}, T = 1 ms\n(passive where b* < b; {bstar.size} points, one call of hapstab.bound)")
save(fig, out, "python_kb_map")
