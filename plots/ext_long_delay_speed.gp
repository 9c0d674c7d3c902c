# plots/ext_long_delay_speed.gp -- delays of teleoperation scale (issue 43): time and accuracy
# against the delay n, one Google Benchmark run (bench/delay.cpp). (a) b* of (45) for the wall
# 10 + 5(z-1)/(Tz): the exact path (its polynomial has degree n + 1: ~n^4), the long-delay path
# (certified, 30 digits: ~n), its double twin (fast) and grids of 10^4 and 10^6 points; (b) their
# relative error against a 45-digit certified reference (1e-17 and below: exact to double or
# better); (c), (d) the same for sup K (device 1/(s^2 + s), wall K + 0.5(z-1)/(Tz)): polynomial path,
# long-delay path (certified, 20 digits), grids (max_gain_grid).
# Data: bench/chart-delay OUTDIR (runs bench_delay); `timing` (machine, load) from `hapstab figure`.
name = 'ext_long_delay_speed'
wide = 1
tall = 1
if (!exists("plotdir")) plotdir = 'plots'
load plotdir.'/common.gp'
if (!exists("timing")) { timing = ''; timing_tex = '' }
f = datadir.'/ext_long_delay_speed.dat'
clip(x) = (x < 1e-17 ? 1e-17 : x)
set multiplot layout 2,2 title 'Long delays: time and accuracy of each path against the delay'
if (strlen(timing) > 0) { set label 99 (tex ? timing_tex : timing) at screen 0.01, screen 0.01 left font note }
set bmargin 5
set logscale xy
set format x (tex ? '$10^{%T}$' : '10^{%T}')
set format y (tex ? '$10^{%T}$' : '10^{%T}')
set xrange [0.7:14000]
set xlabel (tex ? 'delay $n$ [samples]' : 'delay n [samples]')
set title '(a) b*: time per case' font small
set ylabel 'time [ms]'
set yrange [1e-2:1e5]
set key top left Left reverse font note spacing 0.9
plot f index 0 u 1:2 w lp ls 1 t 'exact path', \
     f index 1 u 1:2 w lp ls 2 t 'long-delay path (certified)', \
     f index 2 u 1:2 w lp ls 3 t 'fast (double)', \
     f index 3 u 1:2 w lp ls 4 t 'grid 1e4', \
     f index 4 u 1:2 w lp ls 5 t 'grid 1e6'
unset yrange
set title '(b) b*: relative error' font small
set ylabel 'relative error'
set yrange [1e-18:10]
set key top left Left reverse font note spacing 0.9
plot f index 0 u 1:(clip($3)) w lp ls 1 t 'exact path', \
     f index 1 u 1:(clip($3)) w lp ls 2 t 'long-delay path', \
     f index 2 u 1:(clip($3)) w lp ls 3 t 'fast', \
     f index 3 u 1:(clip($3)) w lp ls 4 t 'grid 1e4', \
     f index 4 u 1:(clip($3)) w lp ls 5 t 'grid 1e6'
unset yrange
set title '(c) sup K: time per case' font small
set ylabel 'time [ms]'
set yrange [1e-1:1e5]
set key top left Left reverse font note spacing 0.9
plot f index 5 u 1:2 w lp ls 1 t 'polynomial path', \
     f index 6 u 1:2 w lp ls 2 t 'long-delay path (certified)', \
     f index 7 u 1:2 w lp ls 4 t 'grid 1e4', \
     f index 8 u 1:2 w lp ls 5 t 'grid 1e6'
unset yrange
set title '(d) sup K: relative error' font small
set ylabel 'relative error'
set yrange [1e-18:10]
set key top left Left reverse font note spacing 0.9
plot f index 5 u 1:(clip($3)) w lp ls 1 t 'polynomial path', \
     f index 6 u 1:(clip($3)) w lp ls 2 t 'long-delay path', \
     f index 7 u 1:(clip($3)) w lp ls 4 t 'grid 1e4', \
     f index 8 u 1:(clip($3)) w lp ls 5 t 'grid 1e6'
unset multiplot
