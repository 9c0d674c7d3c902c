# plots/multidof_scaling.gp -- paper 000, Theorem 5 scaling (data: bench/chart-multidof DATADIR):
# (a) time of the certified Theorem 5 verdict (stability-only mode: Q_E, Q_V eliminated exactly,
# solve + exact re-check) against the total DOF m, median and min-max over the same n random
# environments per point, (b) fraction of those n random
# Fig. 5-type environments (half with per-device force-gain miscalibration) certified stable, with
# its 95% Wilson score interval,
# for one operator on all devices (case-i-like, Gamma = g I) and one operator per device
# (case-ii-like, Gamma block-scalar per device): how much the structure reduces conservatism;
# (c) the whole certified analysis (full mode) of the N-device contact scenes
# (bench/contact_scene.py), log-log against N: before issue 33 (the generic SDP on the built-in
# IPM, recorded with the after series in one run: bench/multidof_contact_before.dat), after (the
# structured KYP path, live), its
# Riccati share, DSDP, and an N^3 reference line; (d) Theorem 6's design of their coupling (one
# first-order SISO block per device), library time: the generic CCL (recorded with the after
# series in one run: bench/multidof_design_before.dat) and the block-wise path (live), N^3 line;
# issue 39's structures, each scene analysed three ways in one run (BM_Structure, full mode,
# library time, CPU seconds of the process): the plan (decomposed into components, the structured KYP/Riccati path, the
# frequency-domain witness; blue) beside the generic SDP on the built-in IPM (orange) and on
# DSDP (yellow), which are run only up to the sizes where they finish in seconds: (e) K objects
# touched by 4 devices each and the one-object contact scenes behind a 1-sample delay
# (infeasible), against the devices N; (f) the one-DOF wall behind a delay of n samples, hard
# (K = 20000: infeasible) and soft (K = 50: feasible), against n, with an n^3 line (the target's
# growth); in both, open symbols from one recorded run of every size, delay 200 included
# (bench/multidof_structure_recorded.dat), where the live run stops at a few seconds' cost.
name = 'multidof_scaling'
wide = 1  # six panels: the PDF and LaTeX versions get a two-column canvas, three rows
tall = 2
if (!exists("plotdir")) plotdir = 'plots'
load plotdir.'/common.gp'
if (!exists("timing")) { timing = ''; timing_tex = '' }
fi = datadir.'/multidof_scaling_case_i.dat'
fii = datadir.'/multidof_scaling_case_ii.dat'
sa = datadir.'/multidof_stages_auto.dat'
sd = datadir.'/multidof_stages_dsdp.dat'
sb = datadir.'/multidof_stages_before.dat'
da = datadir.'/multidof_design_auto.dat'
db = datadir.'/multidof_design_before.dat'
so = datadir.'/multidof_structure_objects.dat'
sh = datadir.'/multidof_structure_hard_wall.dat'
ss = datadir.'/multidof_structure_soft_wall.dat'
si = datadir.'/multidof_structure_infeasible.dat'
sx = datadir.'/multidof_structure_free_x.dat'
sr = datadir.'/multidof_structure_recorded.dat'
set multiplot layout 3,2 title 'Theorems 5 and 6 as the number of devices grows, and the paths by structure'
if (strlen(timing) > 0) { set label 99 (tex ? timing_tex : timing) at screen 0.01, screen 0.02 left font note }
set bmargin 5
stats fi u 9 nooutput
nenv = int(STATS_max)  # environments per point (the bench's samples)
set title sprintf('(a) verdict time, %d random env. per point', nenv) font small
set xlabel (tex ? 'total DOF $m$' : 'total DOF m')
set ylabel 'time [ms]'
set logscale y
set format y (tex ? '$10^{%T}$' : '10^{%T}')
set key top left Left reverse font note spacing 1.0 samplen 1
set bars small
# the median, bars from the fastest to the slowest environment (an infeasible one can be decided
# without an SDP); case ii shifted right by 0.3 so that the bars do not hide each other
plot fi u 2:3:4:5 w yerrorbars ls 1 pt 7 t 'one operator (i): median, min-max', \
     fi u 2:3 w l ls 1 notitle, \
     fii u ($2 + 0.3):3:4:5 w yerrorbars ls 2 pt 5 t 'one per device (ii)', \
     fii u ($2 + 0.3):3 w l ls 2 notitle
unset logscale y
set format y '%g'
set title sprintf('(b) fraction certified stable, n = %d per point', nenv) font small
set ylabel 'fraction certified'
set yrange [-0.05:1.05]
set key bottom right Left reverse font note spacing 1.0 samplen 1
plot fi u 2:6:7:8 w yerrorbars ls 1 pt 7 t 'one operator (i), 95% Wilson interval', \
     fi u 2:6 w l ls 1 notitle, \
     fii u ($2 + 0.3):6:7:8 w yerrorbars ls 2 pt 5 t 'one per device (ii)', \
     fii u ($2 + 0.3):6 w l ls 2 notitle
unset yrange
set title '(c) contact scenes, full analysis' font small
set xlabel (tex ? 'devices $N$' : 'devices N')
set ylabel 'time [s]'
set logscale xy
set format y (tex ? '$10^{%T}$' : '10^{%T}')
# every series lies between 3e-3 and 3e2 s; the key above them, in the empty top (the generic SDP's curve
# rises on the right). "recorded": one earlier run (bench/multidof_contact_before.dat, 2026-11-25,
# load ~10) that timed the generic SDP and the KYP path side by side; "this run": live
set yrange [1e-3:1e5]
set key top left Left reverse font note spacing 1.0 samplen 1
# N^3 reference through the structured path's N = 16 point
stats sa u ($1 == 16 ? $2+$3+$4 : NaN) nooutput
t16 = STATS_max
set datafile missing '-'
plot sb u 1:($2+$3+$4) w lp ls 2 t 'generic SDP (recorded run at load 10)', \
     sb u 1:($6+$7+$8) w lp ls 4 t 'KYP path, in that recorded run', \
     sa u 1:($2+$3+$4) w lp ls 1 lw 2 t 'KYP path, this run', \
     sa u 1:3 w lp ls 3 t 'its SDP/Riccati stage, this run', \
     sd u 1:($2+$3+$4) w lp ls 5 t 'DSDP, this run', \
     [16:128] t16 * (x / 16.0)**3 w l ls 7 t (tex ? '$\propto N^3$' : 'N^3')
set title '(d) contact scenes, Theorem 6 design' font small
set xrange [1:200]
set yrange [1e-3:1e3]
set key top left Left reverse font note spacing 1.0 samplen 1
stats da u ($1 == 16 ? $2 : NaN) nooutput
d16 = STATS_max
plot db u 1:2 w lp ls 2 t 'generic CCL (recorded run at load 3)', \
     db u 1:4 w lp ls 4 t 'block-wise, in that recorded run', \
     da u 1:2 w lp ls 1 lw 2 t 'block-wise, this run', \
     [16:128] d16 * (x / 16.0)**3 w l ls 7 t (tex ? '$\propto N^3$' : 'N^3')
# (e), (f): '-' marks a size where the generic SDP / DSDP were not run (minutes there). Filled
# symbols and lines: this run (small sizes); open symbols: one recorded run of every size
# (bench/multidof_structure_recorded.dat: kind size planned generic DSDP ...), the same colours.
set title '(e) several objects; infeasible scenes (1-sample delay)' font small
set ylabel 'CPU time [s]'  # the bench's process CPU seconds (every thread): (c), (d) are wall times
set xrange [1.5:100]
set yrange [1e-4:1e5]
# the key names the colours (method) and the symbols (scene) once; the curves carry no titles
set key top left Left reverse font note spacing 1.0 samplen 2 maxrows 7
mark(c) = word(pal, c == 3 ? 1 : c == 4 ? 2 : 5)  # recorded file column -> the method's colour
# X with several free directions: drawn when the bench measured it (a build without that path
# skips it, and its file then holds one row of NaN)
stats [*:*] sx u ((strcol(2) ne "NaN") + 1) nooutput
free_x = STATS_sum > STATS_records ? "sx u (2*$1):2 w lp ls 1 pt 9 dt 3 notitle, sx u (2*$1):3 w lp ls 2 pt 9 dt 3 notitle," : ""
plot NaN w lp ls 1 pt -1 t 'plan (decomposed / witness / X searched)', \
     NaN w lp ls 2 pt -1 t 'generic SDP, built-in IPM', \
     NaN w lp ls 5 pt -1 t 'generic SDP, DSDP', \
     NaN w lp lc rgb '#000000' lw 2 pt 7 t 'K objects x 4 devices (feasible)', \
     NaN w lp lc rgb '#000000' lw 2 pt 5 dt 2 t 'one object, 1-sample delay (infeasible)', \
     NaN w lp lc rgb '#000000' lw 2 pt 9 dt 3 t (free_x eq "" ? 'X with K directions: not in this build' : 'K objects linked: X with K directions'), \
     NaN w p lc rgb '#000000' pt 6 ps 1.3 t 'open: recorded run, every size', \
     so u (4*$1):2 w lp ls 1 pt 7 notitle, so u (4*$1):3 w lp ls 2 pt 7 notitle, so u (4*$1):4 w lp ls 5 pt 7 notitle, \
     si u 1:2 w lp ls 1 pt 5 dt 2 notitle, \
     @free_x \
     for [c=3:5] sr u ($1 == 0 ? 4*$2 : NaN):c w p lc rgb mark(c) pt 6 ps 1.3 notitle, \
     for [c=3:5] sr u ($1 == 3 ? $2 : NaN):c w p lc rgb mark(c) pt 4 ps 1.3 notitle
set title '(f) one-DOF wall behind a delay of n samples' font small
set xlabel (tex ? 'delay $n$ [samples]' : 'delay n [samples]')
set xrange [0.8:300]
stats sr u (($1 == 2 && $2 == 50) ? $3 : NaN) nooutput
w50 = STATS_max
plot NaN w lp ls 1 pt -1 t 'plan (KYP/Riccati / witness)', \
     NaN w lp ls 2 pt -1 t 'generic SDP, built-in IPM', \
     NaN w lp ls 5 pt -1 t 'generic SDP, DSDP', \
     NaN w lp lc rgb '#000000' lw 2 pt 7 t 'soft wall K = 50 (feasible)', \
     NaN w lp lc rgb '#000000' lw 2 pt 5 dt 2 t 'hard wall K = 20000 (infeasible, n >= 2)', \
     NaN w p lc rgb '#000000' pt 6 ps 1.3 t 'open: recorded run, every n', \
     ss u 1:2 w lp ls 1 pt 7 notitle, ss u 1:3 w lp ls 2 pt 7 notitle, ss u 1:4 w lp ls 5 pt 7 notitle, \
     sh u 1:2 w lp ls 1 pt 5 dt 2 notitle, sh u 1:3 w lp ls 2 pt 5 dt 2 notitle, sh u 1:4 w lp ls 5 pt 5 dt 2 notitle, \
     for [c=3:5] sr u ($1 == 2 ? $2 : NaN):c w p lc rgb mark(c) pt 6 ps 1.3 notitle, \
     for [c=3:5] sr u ($1 == 1 ? $2 : NaN):c w p lc rgb mark(c) pt 4 ps 1.3 notitle, \
     [16:300] w50 * (x / 50.0)**3 w l ls 7 t (tex ? '$\propto n^3$ (the target: at most)' : 'n^3 (the target: at most)')
unset multiplot
