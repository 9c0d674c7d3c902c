# plots/contact_speed_accuracy.gp -- cost against accuracy of the wedge criterion (25): the
# certified check (exact verdict + margin enclosure at 6, 15, 30 digits) beside N-point double
# grids (N = 1e2..1e5), for H of order 2 to 6. Error: relative error of min_theta w(theta)
# against the 40-digit certified value (floor 1e-40 = exact to the plotted precision). A grid
# can only overestimate the minimum and never proves the verdict.
# Data: bench/chart-contact OUTDIR (from bench_contact's JSON).
name = 'contact_speed_accuracy'
if (!exists("plotdir")) plotdir = 'plots'
load plotdir.'/common.gp'
f = datadir.'/contact_speed_accuracy.dat'
set logscale xy
set format x (tex ? '$10^{%L}$' : '10^{%L}')
set format y (tex ? '$10^{%L}$' : '10^{%L}')
set xlabel (tex ? 'CPU time per check [$\mu$s]' : 'CPU time per check [{/Symbol m}s]')
set ylabel 'relative error of the minimum margin'
set yrange [1e-42:10]
set key outside right top
set title 'Wedge criterion: certified (exact root isolation + MPFI) vs grid'
plot for [i=0:4] f index i using 1:2 with linespoints ls (i+1) pt 7 title sprintf('certified, order %d', i+2), \
     for [i=5:9] f index i using 1:2 with linespoints ls (i-4) dt 2 pt 6 title sprintf('grid, order %d', i-3)
