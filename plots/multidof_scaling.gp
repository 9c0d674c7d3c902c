# plots/multidof_scaling.gp -- paper 000, Theorem 5 scaling (data from bench/chart-multidof):
# (a) analysis time (incl. exact certificate) against the total DOF m, (b) fraction of random
# Fig. 5-type environments (half with per-device force-gain miscalibration) certified stable,
# for one operator on all devices (case-i-like, Gamma = g I) and one operator per device
# (case-ii-like, Gamma block-scalar per device).
if (!exists("datadir")) datadir = "build/charts"
if (!exists("outfile")) outfile = "multidof_scaling.png"
set terminal pngcairo size 1100,450 font ",11"
set output outfile
set multiplot layout 1,2
set title "(a) Theorem 5 analysis time"
set xlabel "total DOF m"
set ylabel "time [ms]"
set logscale y
set key top left
plot datadir."/multidof_scaling_case_i.dat" u 2:3 w lp pt 7 t "one operator (case i)", \
     datadir."/multidof_scaling_case_ii.dat" u 2:3 w lp pt 5 t "operator per device (case ii)"
unset logscale y
set title "(b) random environments certified stable"
set ylabel "fraction certified"
set yrange [-0.05:1.05]
plot datadir."/multidof_scaling_case_i.dat" u 2:4 w lp pt 7 t "one operator (case i)", \
     datadir."/multidof_scaling_case_ii.dat" u 2:4 w lp pt 5 t "operator per device (case ii)"
unset multiplot
