# plots/passivity_speed_accuracy.gp -- speed against accuracy of the passivity bound b* (paper 001,
# (45)): CPU time per case against the relative error vs a 100-digit certified reference, for the
# double-double fast path, the certified method at 16/30/100 digits and grid(N), N = 10^2..10^6,
# on six cases (bench/passivity.cpp: a delayed wall, an IIR filter, order 4, narrow resonances with
# pole radius 0.9999 and 0.99999, order 6 with a delay of 2). Colour = case, marker = method.
# Errors below 1e-40 (the certified values agree with the reference to 40+ digits) are drawn below
# the axis break on a lane per certified precision (16, 30, 100 digits). Data: bench/chart-passivity OUTDIR (runs
# bench_passivity), columns  time[us] rel_err method case case_index; `timing` (machine, load)
# from `hapstab figure`.
name = 'passivity_speed_accuracy'
if (!exists("plotdir")) plotdir = 'plots'
load plotdir.'/common.gp'
if (!exists("timing")) { timing = ''; timing_tex = '' }
f = datadir.'/passivity_speed_accuracy.dat'
# errors <= 1e-40 below the axis break, one lane per certified precision (16, 30, 100 digits: the
# three methods take about the same time on a case, and on one row their markers hid each other)
lane16 = 3e-22; lane30 = 1e-23; lane100 = 3e-25
ey(e, lane) = (e <= 1e-39 ? lane : e)
is(m) = (strcol(3) eq m)
casename(i) = (i == 0 ? 'wall K + B(z-1)/(Tz), n = 1' : i == 1 ? 'IIR (1-z)/(z-0.9)' : i == 2 ? 'order 4' : \
               i == 3 ? 'resonance, |p| = 0.9999' : i == 4 ? 'order 4, |p| = 0.99999, n = 1' : 'order 6, |p| = 0.9999, n = 2')
set multiplot
if (strlen(timing) > 0) { set label 99 (tex ? timing_tex : timing) at screen 0.01, screen 0.02 left font note }
set logscale xy
set format x (tex ? '$10^{%T}$' : '10^{%T}')
set xrange [1:1e7]
set yrange [1e-25:30]
set ytics ("10^{0}" 1, "10^{-5}" 1e-5, "10^{-10}" 1e-10, "10^{-15}" 1e-15, \
           "{/Symbol \243}10^{-40}: 16 digits" lane16, "30 digits" lane30, "100 digits" lane100) font small
if (tex) { set ytics ('$10^{0}$' 1, '$10^{-5}$' 1e-5, '$10^{-10}$' 1e-10, '$10^{-15}$' 1e-15, \
                      '$\le 10^{-40}$: 16 digits' lane16, '30 digits' lane30, '100 digits' lane100) }
set mytics 5
# the axis break between the 1e-20 decade and the lanes: a gap in the frame, marked //
set object 1 rect from graph -0.01, first 2e-21 to graph 1.01, first 6e-21 fc rgb '#ffffff' fs solid noborder front
set label 1 '//' at graph 0, first 3.5e-21 center front
set label 2 '//' at graph 1, first 3.5e-21 center front
set xlabel (tex ? 'CPU time per case [$\mu$s]' : 'CPU time per case [{/Symbol m}s]')
set ylabel 'relative error of b*'
set lmargin at screen 19*emx
set rmargin at screen 1 - 2*emx
set tmargin at screen 1 - 5*emy
set bmargin at screen 16*emy
set title (tex ? 'Passivity bound $b^*$: speed against accuracy, 6 cases (pole radius up to 0.99999)' : 'Passivity bound b*: speed against accuracy, 6 cases (pole radius up to 0.99999)')
set pointintervalbox 0
unset key
plot f using 1:(strstrt(strcol(3), 'grid_') ? ey($2, 0) : 1/0):($5 + 1) with linespoints lc variable lw 1.5 pt 7 ps 0.7 notitle, \
     f using 1:(is('fast') ? ey($2, 0) : 1/0):($5 + 1) with points lc variable pt 7 ps 2.2 notitle, \
     f using 1:(is('certified_16') ? ey($2, lane16) : 1/0):($5 + 1) with points lc variable pt 4 ps 2.4 lw 2 notitle, \
     f using 1:(is('certified_30') ? ey($2, lane30) : 1/0):($5 + 1) with points lc variable pt 8 ps 2.4 lw 2 notitle, \
     f using 1:(is('certified_100') ? ey($2, lane100) : 1/0):($5 + 1) with points lc variable pt 12 ps 2.4 lw 2 notitle, \
     1e-13 with lines ls 8 lw 2 notitle
# ---- the key below the plot, in columns (a plot of its own spanning the width: outside on the
# right it took 35-40% of the figure)
unset object 1; unset label 1; unset label 2; unset label 99
set lmargin at screen 0.02
set rmargin at screen 0.98
set tmargin at screen 11*emy
set bmargin at screen 2.5*emy
unset border; unset tics; unset xlabel; unset ylabel; unset title; unset logscale; unset grid
set xrange [0:1]; set yrange [0:1]
set key at screen 0.5, screen 11*emy center top horizontal maxcols 4 Left reverse font small spacing 1.0 samplen 1.5 width 1
plot NaN with points lc rgb '#000000' pt 7 ps 2.2 title 'fast (double-double)', \
     NaN with points lc rgb '#000000' pt 4 ps 2.4 lw 2 title 'certified, 16 digits', \
     NaN with points lc rgb '#000000' pt 8 ps 2.4 lw 2 title 'certified, 30 digits', \
     NaN with points lc rgb '#000000' pt 12 ps 2.4 lw 2 title 'certified, 100 digits', \
     NaN with linespoints lc rgb '#000000' lw 1.5 pt 7 ps 0.7 title 'grid(N), N = 10^2..10^6', \
     NaN with lines ls 8 lw 2 title 'fast-path target 10^{-13}', \
     for [i=0:5] NaN with lines lt (i + 1) lw 8 title casename(i)
unset multiplot
