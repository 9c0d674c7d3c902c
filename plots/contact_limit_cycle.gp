# plots/contact_limit_cycle.gp -- paper 002, Fig. 2 simulated from rest with r = 1: penetration
# theta_k for H = 0.5/((z-0.5)z) at 0.9 k*_wedge (settles at rho = H(1)/(1+H(1)) r) and at
# k = 2.6 above the linear stability limit k = 2 of (1+kH)^{-1}, where the contact loop is
# unstable and the unilateral nonlinearity bounds a limit cycle (certified exactly by
# `hapstab limit-cycle --exact`). theta < 0 means the device has left the wall.
# Data: hapstab figure contact_limit_cycle --out DIR.
name = 'contact_limit_cycle'
if (!exists("plotdir")) plotdir = 'plots'
load plotdir.'/common.gp'
f = datadir.'/contact_limit_cycle.dat'
set xlabel 'sample k'
set ylabel (tex ? 'penetration $\theta_k$ (units of $r$)' : 'penetration {/Symbol q}_k (units of r)')
set title 'Fig. 2 loop from rest: settling vs limit cycle'
set xzeroaxis ls 7
set key at screen 0.5, screen 0.01 center bottom horizontal  # below the x label, not on it
set bmargin 6
plot f using 1:3 with linespoints ls 2 title 'k = 2.6 (limit cycle)', \
     f using 1:2 with linespoints ls 1 title (tex ? '$k = 0.9\,k^*_{\mathrm{wedge}}$' : 'k = 0.9 k*_{wedge}')
