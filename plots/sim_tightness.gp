# Paper 001, experiment 1: tightness of the passivity bound b* = KT/2 + B of the virtual wall
# H(z) = K + B(z-1)/(Tz). Data: `hapstab figure sim_tightness` (runs examples/001_tightness_*.toml
# and random passive operators). Left: velocity with the operator tuned to wT = pi, b = 0.99 b*
# (grows) and 1.01 b* (decays). Right: the energy that entered the interface through the human
# port, int f_h v dt, from t = 0- (at rest, 0): the force impulse at t = 0 is work done at that
# port, the jump at t = 0 (0.25 mJ); below b* the energy becomes negative (the interface generates
# energy); above b* it stays >= 0 for the tuned and for random passive operators.
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
# the impulse at t = 0 sets v = 5 m/s; the next sample, on the Nyquist-frequency oscillation's
# node, is 1e-4 m/s: from t = 2T on the samples show the envelope, so the first two are left out
set label 1 (tex ? 'from $t = 2T$ (impulse at $t = 0$)' : 'from t = 2T (impulse at t = 0)') at graph 0.03, graph 0.95 left font ',16'
plot datadir.'/sim_tightness_below.dat' using 1:($1 >= 0.0015 ? abs($2) : NaN) with lines ls 2 title 'b = 0.99 b*', \
     datadir.'/sim_tightness_above.dat' using 1:($1 >= 0.0015 ? abs($2) : NaN) with lines ls 1 title 'b = 1.01 b*'
unset label 1
unset logscale y
# energy in mJ on a scale where the passive runs (b = 1.01 b*: the tuned operator and 24 random
# passive ones) are visible; below b* the energy leaves the window downwards (value at the end noted)
stats datadir.'/sim_tightness_below.dat' using 3 nooutput
emin = STATS_min
stats datadir.'/sim_tightness_random.dat' matrix nooutput
ncol = STATS_size_x
set format y '%g'
set ylabel (tex ? '$\int_{0^-}^t f_h v\,dt$ [mJ]' : 'energy in, {/Symbol \362}_{0-}^t f_h v dt [mJ]')
# the impulse's work at the port: the jump at t = 0
stats datadir.'/sim_tightness_above.dat' every ::1::1 using 3 nooutput
e_impulse = STATS_max * 1000
set label 3 sprintf(tex ? 'impulse: $+%.2f$\,mJ' : 'impulse: +%.2f mJ', e_impulse) at first 0.02, first e_impulse * 1.12 left font ',15'
set yrange [-0.15:0.75]
set xrange [-0.025:1]  # the jump at t = 0 off the axis line
set title 'human-port energy'
set key top right Left reverse width -3 font ',18' spacing 1.0
set label 2 sprintf(tex ? 'down to $%.1f$\,J at $t = 1$\,s' : 'down to %.1f J at t = 1 s', emin) at graph 0.56, graph 0.125 left font ',15' textcolor rgb word(pal, 2)
plot for [i=2:ncol] datadir.'/sim_tightness_random.dat' using 1:(column(i)*1000) with lines lc rgb '#9a9a9a' lw 1 notitle, \
     1/0 with lines lc rgb '#9a9a9a' lw 1 title 'b = 1.01 b*, 24 random passive', \
     datadir.'/sim_tightness_above.dat' using 1:($3*1000) with lines ls 1 title 'b = 1.01 b*, tuned', \
     datadir.'/sim_tightness_below.dat' using 1:($3*1000) with lines ls 2 title 'b = 0.99 b*, tuned', \
     0 with lines ls 7 lw 1 notitle
unset multiplot
