#!/usr/bin/env python3
"""Paper 001, Fig. 2 (a)-(e) with matplotlib: the chain of Nyquist-plane maps that turns the
range of a passive operator Z_O(jw) (the closed right half-plane) into the closed unit disk,
(a) Z_O, (b) Z_O + b, (c) R1 = 1/(Z_O + b), (d) r(jw) R1, (e) 2b/(Z_O + b) - 1,
for b = 1 N s/m, T = 1 ms, w = 1000 rad/s. r(jw) = T/(e^{jwT} - 1) (44) comes from hapstab.r,
correctly rounded (real part exact, -T/2). The same figure as `hapstab figure passivity_fig2`.

    PYTHONPATH=build/python MPLBACKEND=Agg python3 examples/python/fig2_nyquist_maps.py --out figs
"""
import numpy as np
import matplotlib.pyplot as plt

import hapstab
from _common import output_folder, save

out = output_folder(__doc__)
b, T, omega = 1.0, "1/1000", 1000
r = hapstab.r(T, omega, digits=17)
rc = complex(r)  # the double nearest each certified part
print(f"r(jw) = {r.decimal[0]} + j {r.decimal[1]}   [re {r.re.status}, im {r.im.status}]")

maps = [("(a) $Z_O(j\\omega)$", lambda Z: Z), ("(b) $Z_O + b$", lambda Z: Z + b),
        ("(c) $R_1 = 1/(Z_O + b)$", lambda Z: 1 / (Z + b)), ("(d) $r(j\\omega) R_1$ [$10^{-3}$]", lambda Z: 1e3 * rc / (Z + b)),
        ("(e) $2b/(Z_O + b) - 1$", lambda Z: 2 * b / (Z + b) - 1)]
fine = b * 2 * np.tan(1.5707 * np.linspace(-1, 1, 801))  # runs to +-infinity for the bounded panels
near = 4 * b * np.linspace(-1, 1, 801)
fig, axes = plt.subplots(2, 3, figsize=(11, 7))
for i, (title, f) in enumerate(maps):
    ax = axes.flat[i]
    y = near if i <= 1 else fine
    x = 4 * b * np.linspace(0, 1, 401) if i <= 1 else b * 2 * np.tan(1.5707 * np.linspace(0, 1, 401))
    ax.plot(*(lambda p: (p.real, p.imag))(f(1j * y)), "k", lw=2, label="Re $Z_O$ = 0 (boundary)")
    for x0 in (0.25 * b, b, 3 * b):
        p = f(x0 + 1j * y)
        ax.plot(p.real, p.imag, "C0", lw=1)
    for y0 in (-b, 0.0, b):
        p = f(x + 1j * y0)
        ax.plot(p.real, p.imag, "C1", lw=1, ls="--")
    if i <= 1:
        ax.set_xlim(-1.5, 5)
        ax.set_ylim(-3.5, 3.5)
    if i == 4:
        ax.add_patch(plt.Circle((0, 0), 1, fill=False, ls=":", color="gray"))
        ax.set_xlim(-1.3, 1.3)
        ax.set_ylim(-1.3, 1.3)
    ax.axhline(0, color="gray", lw=0.5)
    ax.axvline(0, color="gray", lw=0.5)
    ax.set_aspect("equal", adjustable="datalim")
    ax.set_title(title)
    ax.set_xlabel("Re")
    ax.set_ylabel("Im")
axes.flat[5].axis("off")
axes.flat[5].text(0, 0.5, f"b = {b:g} N s/m, T = {T} s, $\\omega$ = {omega} rad/s\n"
                  f"r(j$\\omega$) = {float(r.re):.4g} {float(r.im):+.6g} j\n(hapstab.r, im {r.im.status})\n\n"
                  "black: Re $Z_O$ = 0\nblue: Re $Z_O$ = b/4, b, 3b\norange dashed: Im $Z_O$ = -b, 0, b",
                  va="center")
fig.suptitle("Paper 001, Fig. 2: the Nyquist-plane maps of a passive operator")
fig.tight_layout()
save(fig, out, "python_fig2_nyquist_maps")
