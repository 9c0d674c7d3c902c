# plots/multidof_scaling.gp -- paper 000, Theorem 5 scaling (data: bench/chart-multidof DATADIR):
# (a) time of the certified Theorem 5 verdict (stability-only mode: Q_E, Q_V eliminated exactly,
# solve + exact re-check) against the total DOF m, (b) fraction of random
# Fig. 5-type environments (half with per-device force-gain miscalibration) certified stable,
# for one operator on all devices (case-i-like, Gamma = g I) and one operator per device
# (case-ii-like, Gamma block-scalar per device): how much the structure reduces conservatism;
# (c) the whole certified analysis of the N-device contact scenes (bench/contact_scene.py) per
# stage: realisation, SDP and exact certificate with the built-in IPM, and the DSDP total.
name = 'multidof_scaling'
if (!exists("plotdir")) plotdir = 'plots'
load plotdir.'/common.gp'
fi = datadir.'/multidof_scaling_case_i.dat'
fii = datadir.'/multidof_scaling_case_ii.dat'
sa = datadir.'/multidof_stages_auto.dat'
sd = datadir.'/multidof_stages_dsdp.dat'
set multiplot layout 1,3 title (tex ? 'Theorem 5 as the number of devices grows' : 'Theorem 5 as the number of devices grows')
set title '(a) certified Theorem 5 verdict: time'
set xlabel (tex ? 'total DOF $m$' : 'total DOF m')
set ylabel 'time [ms]'
set logscale y
set format y (tex ? '$10^{%T}$' : '10^{%T}')
set key top left
plot fi u 2:3 w lp ls 1 t 'one operator (case i)', \
     fii u 2:3 w lp ls 2 t 'operator per device (case ii)'
unset logscale y
set format y '%g'
set title '(b) random environments certified stable'
set ylabel 'fraction certified'
set yrange [-0.05:1.05]
set key bottom left
plot fi u 2:4 w lp ls 1 t 'one operator (case i)', \
     fii u 2:4 w lp ls 2 t 'operator per device (case ii)'
unset yrange
set title '(c) contact scenes: certified analysis by stage'
set xlabel (tex ? 'devices $N$' : 'devices N')
set ylabel 'time [s]'
set logscale xy
set format y (tex ? '$10^{%T}$' : '10^{%T}')
set key top left
plot sa u 1:2 w lp ls 3 t 'realisation (IPM run)', \
     sa u 1:3 w lp ls 1 t 'SDP (IPM)', \
     sa u 1:4 w lp ls 4 t 'certificate', \
     sa u 1:($2+$3+$4) w lp ls 2 lw 2 t 'total (IPM)', \
     sd u 1:($2+$3+$4) w lp ls 5 t 'total (DSDP)'
unset multiplot
