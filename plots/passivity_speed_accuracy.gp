# plots/passivity_speed_accuracy.gp -- speed against accuracy of the passivity bound b* (paper 001,
# (45)): CPU time per case against the relative error vs a 100-digit certified reference, for the
# double-double fast path, the certified method at 16/30/100 digits and grid(N), N = 10^2..10^6,
# on six cases (bench/passivity.cpp: a delayed wall, an IIR filter, order 4, narrow resonances with
# pole radius 0.9999 and 0.99999, order 6 with a delay of 2). Colour = case, marker = method.
# Errors below 1e-40 (the certified values agree with the reference to 40+ digits) are drawn on
# the "<= 1e-40" row below the axis break. Data: bench/chart-passivity OUTDIR (runs
# bench_passivity), columns  time[us] rel_err method case case_index; `timing` (machine, load)
# from `hapstab figure`.
name = 'passivity_speed_accuracy'
if (!exists("plotdir")) plotdir = 'plots'
load plotdir.'/common.gp'
if (!exists("timing")) { timing = ''; timing_tex = '' }
f = datadir.'/passivity_speed_accuracy.dat'
floor_row = 1e-22     # where errors <= 1e-40 are drawn
ey(e) = (e <= 1e-39 ? floor_row : e)
is(m) = (strcol(3) eq m)
casename(i) = (i == 0 ? 'wall K + B(z-1)/(Tz), n = 1' : i == 1 ? 'IIR (1-z)/(z-0.9)' : i == 2 ? 'order 4' : \
               i == 3 ? 'resonance, |p| = 0.9999' : i == 4 ? 'order 4, |p| = 0.99999, n = 1' : 'order 6, |p| = 0.9999, n = 2')
set logscale xy
set format x (tex ? '$10^{%T}$' : '10^{%T}')
set xrange [1:1e7]
set yrange [3e-23:30]
set ytics ("10^{0}" 1, "10^{-5}" 1e-5, "10^{-10}" 1e-10, "10^{-15}" 1e-15, "{/Symbol \243}10^{-40}" floor_row)
if (tex) { set ytics ('$10^{0}$' 1, '$10^{-5}$' 1e-5, '$10^{-10}$' 1e-10, '$10^{-15}$' 1e-15, '$\le 10^{-40}$' floor_row) }
set mytics 5
# the axis break between the 1e-20 decade and the floor row: a gap in the frame, marked //
set object 1 rect from graph -0.01, first 2.5e-22 to graph 1.01, first 4e-21 fc rgb '#ffffff' fs solid noborder front
set label 1 '//' at graph 0, first 1e-21 center front
set label 2 '//' at graph 1, first 1e-21 center front
set xlabel (tex ? 'CPU time per case [$\mu$s]' : 'CPU time per case [{/Symbol m}s]')
set ylabel 'relative error of b*'
set key at screen 0.99, graph 1 Left reverse font small spacing 1.05
set rmargin at screen 1 - 27*emx
set bmargin 5
set title (tex ? 'Passivity bound $b^*$: speed against accuracy, 6 cases (pole radius up to 0.99999)' : 'Passivity bound b*: speed against accuracy, 6 cases (pole radius up to 0.99999)')
if (strlen(timing) > 0) { set label 99 (tex ? timing_tex : timing) at screen 0.01, screen 0.02 left font note }
set pointintervalbox 0
plot f using 1:(is('grid_100') || strstrt(strcol(3), 'grid_') ? ey($2) : 1/0):($5 + 1) with linespoints lc variable lw 1.5 pt 7 ps 0.7 notitle, \
     f using 1:(is('fast') ? ey($2) : 1/0):($5 + 1) with points lc variable pt 7 ps 2.2 notitle, \
     f using 1:(is('certified_16') ? ey($2) : 1/0):($5 + 1) with points lc variable pt 4 ps 3.2 lw 2 notitle, \
     f using 1:(is('certified_30') ? ey($2) : 1/0):($5 + 1) with points lc variable pt 8 ps 2.4 lw 2 notitle, \
     f using 1:(is('certified_100') ? ey($2) : 1/0):($5 + 1) with points lc variable pt 12 ps 1.6 lw 2 notitle, \
     1e-13 with lines ls 8 lw 2 notitle, \
     NaN with points lc rgb '#000000' pt 7 ps 2.2 title 'fast (double-double)', \
     NaN with points lc rgb '#000000' pt 4 ps 3.2 lw 2 title 'certified, 16 digits', \
     NaN with points lc rgb '#000000' pt 8 ps 2.4 lw 2 title 'certified, 30 digits', \
     NaN with points lc rgb '#000000' pt 12 ps 1.6 lw 2 title 'certified, 100 digits', \
     NaN with linespoints lc rgb '#000000' lw 1.5 pt 7 ps 0.7 title 'grid(N), N = 10^2..10^6', \
     NaN with lines ls 8 lw 2 title 'fast-path target 10^{-13}', \
     for [i=0:5] NaN with lines lt (i + 1) lw 8 title casename(i)
