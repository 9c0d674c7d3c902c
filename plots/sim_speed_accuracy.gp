# Steps per second against the error of the sampled-data simulation (bench/sim.cpp through
# bench/chart-sim), on paper 002's bias wall with its hand (examples/002_bias_wall.toml: device
# m = 0.05 kg, b = 1 N s/m; hand 0.2 kg, 2 N s/m, 500 N/m; wall K = 20 kN/m, B = 0.1 N s/m with
# contact; bias 2 N; T = 1 ms), 2000 periods: exact ZOH (error = rounding only), RK4 with n
# substeps per period (n at each point), and adaptive Odeint (Dormand-Prince 5(4)) at relative
# tolerance 10^-k and absolute 10^-k-6 (k at each point; the state is x ~ 1e-4 m). Error: max_k |x_k - x_ref,k| / max |x_ref| against the exact-ZOH
# recursion in 50-digit arithmetic. Data: sim_speed_accuracy.dat with columns  method
# steps_per_s  max_rel_error  benchmark  label (n=.. / k=.., '-' for none); `timing` (machine, load) from `hapstab figure`.
name = 'sim_speed_accuracy'
if (!exists("plotdir")) plotdir = 'plots'
load plotdir.'/common.gp'
if (!exists("timing")) { timing = ''; timing_tex = '' }
f = datadir.'/sim_speed_accuracy.dat'
set logscale xy
set format x (tex ? '$10^{%L}$' : '10^{%L}')
set format y (tex ? '$10^{%L}$' : '10^{%L}')
set xrange [1e-13:1]
set yrange [1e5:1e9]
set xlabel (tex ? 'max relative error of $x(kT)$ (vs. 50-digit exact ZOH)' : 'max relative error of x(kT) (vs. 50-digit exact ZOH)')
set ylabel 'sample periods per second (one core)'
set title (tex ? 'Simulator speed against accuracy: paper 002''s bias wall with hand and contact, 2000 periods' : "Simulator speed against accuracy: paper 002's bias wall with hand and contact, 2000 periods")
set key top right Left reverse
set bmargin 5
if (strlen(timing) > 0) { set label 99 (tex ? timing_tex : timing) at screen 0.01, screen 0.02 left font note }
lbl(c) = (strcol(c) eq '-' ? '' : strcol(c))
plot f using (strcol(1) eq 'zoh' ? $3 : 1/0):2 with points ls 1 pt 7 ps 2.5 title 'exact ZOH (rounding only)', \
     '' using (strcol(1) eq 'rk4' ? $3 : 1/0):2 with linespoints ls 2 ps 1.6 title 'RK4, n substeps per period', \
     '' using (strcol(1) eq 'rk4' ? $3 : 1/0):2:(lbl(5)) with labels offset 0,-1.2 font note textcolor rgb word(pal, 2) notitle, \
     '' using (strcol(1) eq 'odeint' ? $3 : 1/0):2 with linespoints ls 3 ps 1.6 title (tex ? 'adaptive Odeint (DP5), rel. tolerance $10^{-k}$, abs. $10^{-k-6}$' : 'adaptive Odeint (DP5), rel. tolerance 10^{-k}, abs. 10^{-k-6}'), \
     '' using (strcol(1) eq 'odeint' ? $3 : 1/0):2:(lbl(5)) with labels offset 0,1.2 font note textcolor rgb word(pal, 3) notitle
