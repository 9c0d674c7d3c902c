# plots/contact_speed_accuracy.gp -- cost against accuracy of the wedge criterion (25): the
# certified check (exact verdict + margin enclosure at 6, 15, 30 digits: one marker each) beside
# N-point double grids (N = 1e2..1e5, dashed, N growing to the right), for H of order 2 to 6
# (colour). Error: relative error of min_theta w(theta) against the 40-digit certified value;
# errors below 1e-40 (the certified margins agree with it to 40+ digits) are drawn on the
# "<= 1e-40" row below the axis break. A grid can only overestimate the minimum and never proves
# the verdict. The dotted vertical line is issue 33's target: the certified margin at order 6 in
# at most 1 ms. Data: bench/chart-contact OUTDIR (from bench_contact's JSON); `timing` (machine,
# load) from `hapstab figure`.
name = 'contact_speed_accuracy'
if (!exists("plotdir")) plotdir = 'plots'
load plotdir.'/common.gp'
if (!exists("timing")) { timing = ''; timing_tex = '' }
f = datadir.'/contact_speed_accuracy.dat'
floor_row = 1e-22     # where errors <= 1e-40 are drawn
ey(e) = (e <= 1e-39 ? floor_row : e)
set logscale xy
set format x (tex ? '$10^{%T}$' : '10^{%T}')
set xrange [1:3e4]
set yrange [3e-23:30]
set ytics ("10^{0}" 1, "10^{-5}" 1e-5, "10^{-10}" 1e-10, "10^{-15}" 1e-15, "{/Symbol \243}10^{-40}" floor_row)
if (tex) { set ytics ('$10^{0}$' 1, '$10^{-5}$' 1e-5, '$10^{-10}$' 1e-10, '$10^{-15}$' 1e-15, '$\le 10^{-40}$' floor_row) }
set mytics 5
# the axis break between the 1e-20 decade and the floor row: a gap in the frame, marked //
set object 1 rect from graph -0.01, first 2.5e-22 to graph 1.01, first 4e-21 fc rgb '#ffffff' fs solid noborder front
set label 1 '//' at graph 0, first 1e-21 center front
set label 2 '//' at graph 1, first 1e-21 center front
set arrow 3 from 1000, graph 0 to 1000, graph 1 nohead ls 8 lw 2 back
set xlabel (tex ? 'CPU time per check [$\mu$s]' : 'CPU time per check [{/Symbol m}s]')
set ylabel 'relative error of the minimum margin'
set rmargin at screen 1 - 25*emx
set bmargin 5
set key at screen 0.99, graph 1 Left reverse font small spacing 1.05
set title 'Wedge criterion (25): certified (exact root isolation + MPFI) against grids'
if (strlen(timing) > 0) { set label 99 (tex ? timing_tex : timing) at screen 0.01, screen 0.02 left font note }
plot for [i=0:4] f index i using 1:($3 == 6 ? ey($2) : 1/0) with points lt (i+1) pt 4 ps 3.0 lw 2 notitle, \
     for [i=0:4] f index i using 1:($3 == 15 ? ey($2) : 1/0) with points lt (i+1) pt 8 ps 2.3 lw 2 notitle, \
     for [i=0:4] f index i using 1:($3 == 30 ? ey($2) : 1/0) with points lt (i+1) pt 7 ps 1.2 notitle, \
     for [i=5:9] f index i using 1:(ey($2)) with linespoints lt (i-4) dt 2 pt 7 ps 0.8 notitle, \
     NaN with points lc rgb '#000000' pt 4 ps 3.0 lw 2 title 'certified, 6 digits', \
     NaN with points lc rgb '#000000' pt 8 ps 2.3 lw 2 title 'certified, 15 digits', \
     NaN with points lc rgb '#000000' pt 7 ps 1.2 title 'certified, 30 digits', \
     NaN with linespoints lc rgb '#000000' dt 2 pt 7 ps 0.8 title 'grid, N = 10^2..10^5', \
     NaN with lines ls 8 lw 2 title 'target: 1 ms (order 6)', \
     for [i=0:4] NaN with lines lt (i+1) lw 8 title sprintf('H of order %d', i+2)
