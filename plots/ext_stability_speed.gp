# plots/ext_stability_speed.gp -- speed against accuracy of `hapstab stability --max` (issue 19):
# time per call against the requested digits (10..100), for four loops: 1/(s^2 + s) with a spring
# (n = 0), a damper wall B = 2 with n = 3, heavy damping bT/m = 1 (n = 1), and the pure mass 1/s^2
# (exact data). Every result is a certified enclosure at most 10^-digits wide.
# Data: bench/chart-stability OUTDIR (runs bench_stability).
name = 'ext_stability_speed'
if (!exists("plotdir")) plotdir = 'plots'
load plotdir.'/common.gp'
f = datadir.'/ext_stability_speed.dat'
set logscale y
set format y (tex ? '$10^{%T}$' : '10^{%T}')
set xlabel 'requested significant digits'
set ylabel (tex ? 'time per call [$\mu$s]' : 'time per call [{/Symbol m}s]')
set key outside right top
set xrange [0:110]
set title 'stability --max: time against digits (certified enclosures)'
plot f index 0 using 1:2 with linespoints ls 1 title 'spring, n = 0', \
     f index 1 using 1:2 with linespoints ls 2 title 'damper wall, n = 3', \
     f index 2 using 1:2 with linespoints ls 3 title 'bT/m = 1, n = 1', \
     f index 3 using 1:2 with linespoints ls 4 title 'pure mass (exact data)'
