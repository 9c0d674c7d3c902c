# Paper 001, experiment 1: tightness of the passivity bound b* = KT/2 + B of the virtual wall
# H(z) = K + B(z-1)/(Tz). Data: `hapstab figure sim_tightness` (runs examples/001_tightness_*.toml
# and random passive operators). Left: velocity with the operator tuned to wT = pi, b = 0.99 b*
# (grows) and 1.01 b* (decays). Right: the energy that entered the interface through the human
# port, int f_h v dt; below b* it becomes negative (the interface generates energy); above b*
# it stays >= 0 for the tuned and for random passive operators.
name = 'sim_tightness'
if (!exists("plotdir")) plotdir = 'plots'
load plotdir.'/common.gp'
set multiplot layout 1,2 title (tex ? 'Tightness of $b^* = KT/2 + B$ (paper 001, (46)): $K = 20$\,kN/m, $B = 5$\,N\,s/m, $T = 1$\,ms' : 'Tightness of b* = KT/2 + B (paper 001, (46)): K = 20 kN/m, B = 5 N s/m, T = 1 ms')
set xlabel (tex ? '$t$ [s]' : 't [s]')
set ylabel (tex ? '$|v|$ [m/s]' : '|v| [m/s]')
set title 'velocity, tuned operator'
set key bottom left
set logscale y
set format y (tex ? '$10^{%L}$' : '10^{%L}')
plot datadir.'/sim_tightness_below.dat' using 1:(abs($2)) with lines ls 2 title 'b = 0.99 b*', \
     datadir.'/sim_tightness_above.dat' using 1:(abs($2)) with lines ls 1 title 'b = 1.01 b*'
unset logscale y
set format y '%g'
set ylabel (tex ? '$\int f_h v\,dt$ [J]' : 'energy into the interface [J]')
set title 'human-port energy'
set key left center Left reverse width -6
stats datadir.'/sim_tightness_random.dat' matrix nooutput
ncol = STATS_size_x
plot datadir.'/sim_tightness_below.dat' using 1:3 with lines ls 2 title 'b = 0.99 b*, tuned', \
     datadir.'/sim_tightness_above.dat' using 1:3 with lines ls 1 title 'b = 1.01 b*, tuned', \
     for [i=2:ncol] datadir.'/sim_tightness_random.dat' using 1:i with lines ls 8 notitle, \
     1/0 with lines ls 8 title 'b = 1.01 b*, random passive'
unset multiplot
