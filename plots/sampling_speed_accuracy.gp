# plots/sampling_speed_accuracy.gp -- r(jw) of paper 001: (left) time per evaluation against the
# componentwise relative error max(|dRe/Re|, |dIm/Im|) (vs a 2x-precision reference) for every closed form (35)-(38), (44)
# and (44)-naive in double/mp50/mp100 (worst over 64 wT in [1e-8, pi]), the series (34) truncated at
# N = 10..10^6 (wT = 1.2345), the Euler-Maclaurin accelerated series and the certified enclosure;
# (right) the accuracy sweep of each double form over wT in [1e-8, pi] in units of eps = 2^-52.
# Data: bench/chart-sampling OUTDIR (runs bench_sampling). Terminal: fmt = png | pdf | svg | tex.
name = 'sampling_speed_accuracy'
if (!exists("plotdir")) plotdir = 'plots'
load plotdir.'/common.gp'
f = datadir.'/sampling_speed_accuracy.dat'
g = datadir.'/sampling_sweep.dat'
set multiplot layout 1,2 title (tex ? '$r(j\omega)$ of paper 001: speed against accuracy' : 'r(j{/Symbol w}) of paper 001: speed against accuracy')
# ---- left: error vs time
set logscale xy
set format x (tex ? '$10^{%T}$' : '10^{%T}')
set format y (tex ? '$10^{%T}$' : '10^{%T}')
set xlabel 'CPU time per evaluation [ns]'
set ylabel 'relative error of r (componentwise)'
set yrange [1e-111:10]
set key bottom right font ',8' spacing 0.9
set title 'forms x scalar, series (34), accelerated'
plot f index 0 using 1:2 with points ls 1 pt 7 ps 1.4 title 'closed forms, double', \
     f index 0 using 1:2:3 with labels font ',7' offset 0,0.7 notitle, \
     f index 1 using 1:2 with points ls 2 pt 5 ps 1.4 title 'closed forms, mp50', \
     f index 2 using 1:2 with points ls 3 pt 9 ps 1.4 title 'closed forms, mp100', \
     f index 3 using 1:2 with linespoints ls 1 pt 6 dt 2 title 'series N=10..1e6, double', \
     f index 4 using 1:2 with linespoints ls 2 pt 4 dt 2 title 'series N=10..1e6, mp50', \
     f index 5 using 1:2 with linespoints ls 3 pt 8 dt 2 title 'series N=10..1e6, mp100', \
     f index 6 using 1:2 with linespoints ls 4 pt 11 title 'accelerated, double', \
     f index 7 using 1:2 with linespoints ls 5 pt 13 title 'accelerated, mp50 (10..40 digits)', \
     f index 8 using 1:2 with linespoints ls 6 pt 3 title 'accelerated, mp100 (30..90 digits)', \
     f index 9 using 1:2 with points ls 7 pt 12 ps 2 title 'certified enclosure (60 digits, width)', \
     1e-30 with lines ls 8 title '30 digits'
# ---- right: accuracy sweep of the double forms
set xlabel (tex ? '$\omega T$ [rad]' : '{/Symbol w}T [rad]')
set ylabel (tex ? 'relative error [$\epsilon = 2^{-52}$]' : 'relative error [eps = 2^{-52}]')
set xrange [1e-8:3.2]
set yrange [1e-2:1e17]
set key top right font ',8'
set title 'double: where each form loses accuracy'
plot g index 0 using 1:3 with lines ls 1 title (tex ? '(35): $1-\cos\omega T$' : '(35): 1 - cos {/Symbol w}T'), \
     g index 1 using 1:3 with lines ls 2 dt 3 title (tex ? '(36): $\cos\omega T-1$' : '(36): cos {/Symbol w}T - 1'), \
     g index 2 using 1:3 with lines ls 3 title '(37): rounded angle', \
     g index 3 using 1:3 with lines ls 4 title '(38): cot = cos/sin', \
     g index 4 using 1:3 with lines ls 6 lw 3 title (tex ? '(44): $-T/2 - j(T/2)/\tan$' : '(44): -T/2 - j(T/2)/tan'), \
     g index 5 using 1:3 with lines ls 5 dt 2 title '(44) naive division', \
     4 with lines ls 7 title (tex ? '$4\epsilon$' : '4 eps')
unset multiplot
