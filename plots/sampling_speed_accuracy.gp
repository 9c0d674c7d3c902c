# plots/sampling_speed_accuracy.gp -- r(jw) of paper 001: (left) time per evaluation against the
# componentwise relative error max(|dRe/Re|, |dIm/Im|) (vs a 2x-precision reference) for every closed form (35)-(38), (44)
# and (44)-naive in double/mp50/mp100 (worst over 64 wT in [1e-8, pi]), the series (34) truncated at
# N = 10..10^6 (wT = 1.2345), the Euler-Maclaurin accelerated series and the certified enclosure;
# (right) the accuracy sweep of each double form over wT in [1e-8, pi] in units of eps = 2^-52.
# Left: colour = scalar (double, mp50, mp100), marker = closed form; the series and the accelerated
# series are lines (N or the digits grow to the right). Errors below 1e-110 are exact to the plot;
# an infinite or NaN error (r = inf at some wT) sits on the "inf" row above the dashed line.
# Data: bench/chart-sampling OUTDIR (runs bench_sampling); `timing` (machine, load) from
# `hapstab figure`. Terminal: fmt = png | pdf | svg | tex.
name = 'sampling_speed_accuracy'
if (!exists("plotdir")) plotdir = 'plots'
wide = 1  # three / two panels: the PDF and LaTeX versions get a two-column canvas
load plotdir.'/common.gp'
f = datadir.'/sampling_speed_accuracy.dat'
g = datadir.'/sampling_sweep.dat'
if (!exists("timing")) { timing = ''; timing_tex = '' }
# the closed form of a row (column 3) as a marker: (35) (36) (37) (38) (44) (44) naive
form_pt(s) = (s eq 'eq35' ? 4 : s eq 'eq36' ? 8 : s eq 'eq37' ? 10 : s eq 'eq38' ? 12 : s eq 'eq44' ? 6 : 14)
set multiplot title (tex ? '$r(j\omega)$ of paper 001: speed against accuracy' : 'r(j{/Symbol w}) of paper 001: speed against accuracy')
if (strlen(timing) > 0) { set label 99 (tex ? timing_tex : timing) at screen 0.01, screen 0.02 left font note }
# ---- left: error vs time
set lmargin at screen 6*emx
set rmargin at screen 0.47
set tmargin at screen 1 - 6*emy
set bmargin at screen 15*emy
set logscale xy
set format x (tex ? '$10^{%T}$' : '10^{%T}')
set format y (tex ? '$10^{%T}$' : '10^{%T}')
set xrange [1:1e9]
set xtics 100
set xlabel 'CPU time per evaluation [ns]'
set ylabel 'relative error of r (componentwise)'
# finite errors up to 10; above the dashed line the row of infinite errors (r = inf or NaN at some wT)
inf_row = 1e16
set yrange [1e-111:1e21]
set ytics 1e-100, 1e20, 1
if (tex) { set ytics add ('$\infty$' inf_row) } else { set ytics add ('inf' inf_row) }
set arrow 1 from graph 0, first 1e8 to graph 1, first 1e8 nohead dt 2 lc rgb '#808080' front
unset key
set title 'time against error'
fin(v) = ($4 == 0) ? v : 1/0
infv(v) = ($4 == 1) ? inf_row : 1/0
# the closed forms are hollow and nested by size ((35) largest, (44) naive smallest): forms with
# the same time and error stay visible as concentric markers instead of hiding one another
form_ps(s) = (s eq 'eq35' ? 2.6 : s eq 'eq36' ? 2.2 : s eq 'eq37' ? 1.9 : s eq 'eq38' ? 1.6 : s eq 'eq44' ? 1.3 : 1.0)
plot for [i=0:2] f index i using 1:(fin($2)):(form_ps(strcol(3))):(form_pt(strcol(3))) with points ls (i+1) ps variable pt variable lw 2 notitle, \
     for [i=0:2] f index i using 1:(infv($2)):(form_ps(strcol(3))):(form_pt(strcol(3))) with points ls (i+1) ps variable pt variable lw 2 notitle, \
     f index 3 using 1:(fin($2)) with linespoints ls 1 pt 7 ps 0.6 dt 2 notitle, \
     f index 4 using 1:(fin($2)) with linespoints ls 2 pt 7 ps 0.6 dt 2 notitle, \
     f index 5 using 1:(fin($2)) with linespoints ls 3 pt 7 ps 0.6 dt 2 notitle, \
     f index 6 using 1:(fin($2)) with linespoints ls 1 pt 7 ps 1.0 notitle, \
     f index 7 using 1:(fin($2)) with linespoints ls 2 pt 7 ps 1.0 notitle, \
     f index 8 using 1:(fin($2)) with linespoints ls 3 pt 7 ps 1.0 notitle, \
     f index 9 using 1:(fin($2)) with points lc rgb '#000000' pt 3 ps 2.5 lw 2 notitle, \
     1e-30 with lines ls 8 lw 2 notitle
unset label 99
unset arrow 1
# ---- right: accuracy sweep of the double forms
unset key
set lmargin at screen 0.58 + 4*emx
set rmargin at screen 1 - 1.1*emx
set xlabel (tex ? '$\omega T$ [rad]' : '{/Symbol w}T [rad]')
set ylabel (tex ? 'relative error [$\epsilon = 2^{-52}$]' : 'relative error [eps = 2^{-52}]')
set xrange [1e-8:3.2]
set xtics 100
set yrange [1e-2:1e26]
set ytics 1e-4, 1e4
unset key
set key inside top right Left reverse font note spacing 1.0 samplen 1.5
set title 'double forms against {/Symbol w}T'
plot g index 0 using 1:3 with lines ls 1 title (tex ? '(35): $1-\cos\omega T$' : '(35): 1 - cos {/Symbol w}T'), \
     g index 1 using 1:3 with lines ls 2 dt 3 title (tex ? '(36): $\cos\omega T-1$' : '(36): cos {/Symbol w}T - 1'), \
     g index 2 using 1:3 with lines ls 3 title '(37): rounded angle', \
     g index 3 using 1:3 with lines ls 4 title '(38): cot = cos/sin', \
     g index 4 using 1:3 with lines ls 6 lw 3 title (tex ? '(44): $-T/2 - j(T/2)/\tan$' : '(44): -T/2 - j(T/2)/tan'), \
     g index 5 using 1:3 with lines ls 5 dt 2 title '(44) naive division', \
     4 with lines ls 7 title (tex ? '$4\epsilon$' : '4 eps')
# ---- the left panel's key, below both panels in columns (a plot of its own spanning the width:
# a key is laid out within its plot's width, and in the panel it took 35-40% of the figure)
set lmargin at screen 0.02
set rmargin at screen 0.98
set tmargin at screen 9*emy
set bmargin at screen 2*emy
unset border; unset tics; unset xlabel; unset ylabel; unset title; unset logscale; unset grid; unset arrow
unset label 99
set xrange [0:1]; set yrange [0:1]
set key at screen 0.5, screen 9*emy center top horizontal maxcols 5 Left reverse font note spacing 1.0 samplen 1.5 width 1
plot NaN with lines ls 1 lw 8 title 'double', \
     NaN with lines ls 2 lw 8 title 'mp50', \
     NaN with lines ls 3 lw 8 title 'mp100', \
     NaN with points lc rgb '#000000' pt 4 ps 2.6 lw 2 title '(35)', \
     NaN with points lc rgb '#000000' pt 8 ps 2.2 lw 2 title '(36)', \
     NaN with points lc rgb '#000000' pt 10 ps 1.9 lw 2 title '(37)', \
     NaN with points lc rgb '#000000' pt 12 ps 1.6 lw 2 title '(38)', \
     NaN with points lc rgb '#000000' pt 6 ps 1.3 lw 2 title '(44)', \
     NaN with points lc rgb '#000000' pt 14 ps 1.0 lw 2 title '(44) naive', \
     NaN with linespoints lc rgb '#000000' dt 2 pt 7 ps 0.6 title (tex ? 'series (34), $N = 10..10^6$' : 'series (34), N = 10..10^6'), \
     NaN with linespoints lc rgb '#000000' pt 7 ps 1.0 title 'accelerated series', \
     NaN with points lc rgb '#000000' pt 3 ps 2.5 lw 2 title 'certified (60 digits, width)', \
     NaN with lines ls 8 lw 2 title '30 digits'
unset multiplot
