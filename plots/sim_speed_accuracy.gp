# Steps per second against the error of the sampled-data simulation (bench/sim.cpp through
# bench/chart-sim): exact ZOH (error = rounding only), RK4 with n substeps per period, and
# adaptive Odeint (Dormand-Prince) at several tolerances. Data: sim_speed_accuracy.dat with
# columns  method  steps_per_s  max_rel_error.
name = 'sim_speed_accuracy'
if (!exists("plotdir")) plotdir = 'plots'
load plotdir.'/common.gp'
set logscale xy
set format x '10^{%L}'
set format y '10^{%L}'
if (tex) { set format x '$10^{%L}$'; set format y '$10^{%L}$' }
set xlabel 'max relative error (vs. 50-digit reference)'
set ylabel 'sample periods per second'
set title '1-DOF wall with contact: speed against accuracy'
set key bottom left
plot datadir.'/sim_speed_accuracy.dat' using (strcol(1) eq 'zoh' ? $3 : 1/0):2 with points ls 1 pt 7 ps 2 title 'exact ZOH', \
     '' using (strcol(1) eq 'rk4' ? $3 : 1/0):2 with linespoints ls 2 title 'RK4, n substeps', \
     '' using (strcol(1) eq 'odeint' ? $3 : 1/0):2 with linespoints ls 3 title 'adaptive Odeint (DP5)'
