# plots/ext_stability_speed.gp -- speed against accuracy of `hapstab stability --max` (issue 19):
# time per call against the requested digits (10..100), for four loops: 1/(s^2 + s) with a spring
# (n = 0), a damper wall B = 2 with n = 3, heavy damping bT/m = 1 (n = 1), and the pure mass 1/s^2
# (exact data). Every result is a certified enclosure at most 10^-digits wide.
# Data: bench/chart-stability OUTDIR (runs bench_stability); `timing` (machine, load) from
# `hapstab figure`.
name = 'ext_stability_speed'
if (!exists("plotdir")) plotdir = 'plots'
load plotdir.'/common.gp'
f = datadir.'/ext_stability_speed.dat'
if (!exists("timing")) { timing = ''; timing_tex = '' }
set logscale y
set format y (tex ? '$%g$' : '%g')
set ytics (20, 50, 100, 200, 500, 1000, 2000, 5000)
set xlabel 'requested significant digits of the limit'
set ylabel (tex ? 'time per call [$\mu$s]' : 'time per call [{/Symbol m}s]')
set key top left Left reverse font small
set xrange [0:110]
set xtics 10
set yrange [20:5000]
set bmargin 5
set title 'stability --max: time to a certified enclosure of the gain limit, against its digits'
if (strlen(timing) > 0) { set label 99 (tex ? timing_tex : timing) at screen 0.01, screen 0.02 left font note }
plot f index 0 using 1:2 with linespoints ls 1 title (tex ? '$1/(s^2+s)$, spring, $n = 0$' : '1/(s^2 + s), spring, n = 0'), \
     f index 1 using 1:2 with linespoints ls 2 title (tex ? 'damper wall $B = 2$, $n = 3$' : 'damper wall B = 2, n = 3'), \
     f index 2 using 1:2 with linespoints ls 3 title (tex ? 'heavy damping $bT/m = 1$, $n = 1$' : 'heavy damping bT/m = 1, n = 1'), \
     f index 3 using 1:2 with linespoints ls 4 title (tex ? 'pure mass $1/s^2$ (exact data)' : 'pure mass 1/s^2 (exact data)')
