#!/usr/bin/env python3
"""A multi-DOF analysis of paper 000 from Python: Theorem 5 (hapstab.multidof.analyze) on the
four example scenes of Sec. VI, Theorem 6 (hapstab.multidof.design) on case ii with the
perturbed environment, and the 2-DOF loop simulated (hapstab.simulate: numpy arrays per DOF).

    PYTHONPATH=build/python MPLBACKEND=Agg python3 examples/python/multidof_analysis.py --out figs
"""
import os

import matplotlib.pyplot as plt
import numpy as np

import hapstab
from _common import output_folder, save

out = output_folder(__doc__)
examples = hapstab.examples_dir()
# which loop each verdict is about: Theorem 5 concludes stability of the loop with a coupling V
# whose V-hat^Gamma is Delta_V-OSP, Delta_V >= Gamma^-1 Q_V Gamma^-1; the scene's own loop (Sec. VI's
# scenes write no coupling: the direct connection) is decided separately, as written
print(f"{'scene':28} {'(16)':10} certified  Theorem 5 concludes   the scene's loop as written")
print(f"{'':28} {'':10} {'':10} (with a coupling V)   (no coupling)")
for name in ("multidof_case_i_nominal", "multidof_case_i_perturbed", "multidof_case_ii_nominal",
             "multidof_case_ii_perturbed"):
    a = hapstab.multidof.analyze(os.path.join(examples, name + ".toml"))
    law = a.loop_as_written
    written = {True: "stable", False: "NOT stable", None: "undecided"}[law["stable"]] + f" [{law['status']}]"
    print(f"{name:28} {a.verdict:10} {str(a.certified):10} {str(a.stability_concluded):21} {written}")

d = hapstab.multidof.design(os.path.join(examples, "multidof_case_ii_perturbed.toml"))
A, B, C, D = d.V
print(f"Theorem 6 on case ii (perturbed): feasible {d.feasible}, certified {d.certified}, "
      f"{d.iterations} CCL iterations; D_V =\n{D}")

s = hapstab.simulate(os.path.join(examples, "000_two_dof_loop.toml"))
t, v = s.samples["t"], s.samples["v"]  # v: (rows, DOFs), float64
fig, (ax1, ax2) = plt.subplots(2, 1, figsize=(7, 5), sharex=True)
# the port energy from t = 0- (at rest, 0): the force impulse at t = 0 is work at the human port,
# so each curve starts at 0 and jumps by the impulse's work there (the samples begin after it)
t0 = np.concatenate(([0.0], t))
for j in range(v.shape[1]):
    ax1.plot(t, v[:, j], label=f"DOF {j}")
    ax2.plot(t0, np.concatenate(([0.0], s.samples["E_port"][:, j])), label=f"DOF {j}")
ax1.set_ylabel(f"v [{s.units['v']}]")
ax2.set_ylabel(r"$\int_{0^-}^t f_h v\,dt$ " + f"[{s.units['E_port']}]" + "\n(impulse at t = 0 included)")
ax2.set_xlabel("t [s]")
ax2.set_xlim(-0.05, 3)  # the transient (the jump at t = 0 off the axis line); the run goes on to 10 s, decaying
ax1.legend()
ax1.set_title(f"Paper 000, the 2-DOF loop without coupling: diverged = {s.diverged}, trend {s.trend}")
fig.tight_layout()
save(fig, out, "python_multidof_velocities")
