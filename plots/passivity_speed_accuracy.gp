# plots/passivity_speed_accuracy.gp -- speed against accuracy of the passivity bound b* (paper 001,
# (45)): time per case against relative error vs a 100-digit certified reference, for the
# double-double fast path, the certified method at 16/30/100 digits and grid(N), N = 10^2..10^6,
# on five cases (catalogue, order 4, narrow resonances with pole radius 0.9999 and 0.99999).
# Data: bench/chart-passivity OUTDIR (runs bench_passivity). Errors below 1e-40 are drawn at 1e-40.
name = 'passivity_speed_accuracy'
if (!exists("plotdir")) plotdir = 'plots'
load plotdir.'/common.gp'
f = datadir.'/passivity_speed_accuracy.dat'
set logscale xy
set format y (tex ? '$10^{%T}$' : '10^{%T}')
set format x (tex ? '$10^{%T}$' : '10^{%T}')
set xlabel (tex ? 'time per case [$\mu$s]' : 'time per case [{/Symbol m}s]')
set ylabel 'relative error of b*'
set yrange [1e-41:10]
set key outside right top
set title 'Passivity bound: speed vs accuracy (6 cases, pole radius up to 0.99999)'
plot f using (strcol(3) eq 'fast' ? $1 : 1/0):2 with points ls 1 pt 7 ps 1.5 title 'fast (double-double)', \
     f using (strstrt(strcol(3),'certified_16') ? $1 : 1/0):2 with points ls 2 pt 5 ps 1.5 title 'certified, 16 digits', \
     f using (strstrt(strcol(3),'certified_30') ? $1 : 1/0):2 with points ls 3 pt 9 ps 1.5 title 'certified, 30 digits', \
     f using (strstrt(strcol(3),'certified_100') ? $1 : 1/0):2 with points ls 4 pt 11 ps 1.5 title 'certified, 100 digits', \
     f using (strcol(3) eq 'grid' ? 1/0 : strstrt(strcol(3),'grid') ? $1 : 1/0):2 with linespoints ls 5 pt 13 ps 1.2 title 'grid(N), N = 10^2..10^6', \
     1e-13 with lines ls 8 title 'fast-path target 1e-13'
