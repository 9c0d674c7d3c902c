# Beyond the papers: paper 001's wall H(z) = K + B(z-1)/(Tz) beyond its bound (b = 0.99 b*,
# examples/001_tightness_below.toml, operator tuned to wT = pi) without and with the
# Hannaford-Ryu passivity observer/controller (sim/simulator.hpp). Data: `hapstab figure
# ext_pc_wall`, columns t, x, u applied (after the PC), int f_h v dt, wall force commanded
# (before the PC). All values at the sample instants kT.
# (a) |x(kT)|: the oscillation grows without the PC and decays with it.
# (b) the actuator force: without the PC the wall's force is applied and grows; with it the wall
#     still commands a force (dashed), but at every sample at which it pushes the PC's damper
#     cancels it exactly, so the applied force is 0: what the data holds there is the rounding
#     residue of u - u (~1e-17 N, or exactly 0), which a log axis would draw as noise. The
#     applied force is drawn only where it is not cancelled (|u| > 1e-9 |u_wall|); the label
#     counts the cancelled samples. The PC does not chatter here: it removes the whole wall.
# (c) the human-port energy int f_h v dt, negative when the interface generates energy.
name = 'ext_pc_wall'
if (!exists("plotdir")) plotdir = 'plots'
wide = 1  # three / two panels: the PDF and LaTeX versions get a two-column canvas
load plotdir.'/common.gp'
off = datadir.'/ext_pc_wall_off.dat'
on = datadir.'/ext_pc_wall_on.dat'
cancelled(u, uw) = (uw == uw && uw != 0 && abs(u) <= 1e-9 * abs(uw))
stats on using (cancelled($3, $5) ? 1 : 0) name 'C' nooutput
stats on using (($5 == $5 && $5 != 0) ? 1 : 0) name 'W' nooutput
stats on using (cancelled($3, $5) ? abs($3) : 0) name 'R' nooutput
n_cancel = int(C_sum); n_wall = int(W_sum); n_kept = n_wall - n_cancel
set multiplot layout 1,3 margins 5.5*emx, 1 - 1.1*emx, 9*emy, 1 - 6*emy spacing 7*emx \
  title (tex ? 'Passivity controller on a wall beyond $b^*$ ($b = 0.99\,b^*$, $K = 20$\,kN/m, $B = 5$\,N\,s/m, $T = 1$\,ms)' : 'Passivity controller on a wall beyond b* (b = 0.99 b*, K = 20 kN/m, B = 5 N s/m, T = 1 ms)')
set xlabel (tex ? '$t$ [s]' : 't [s]')
set xrange [0:1]
set xtics 0.25
set key top left font small
set title '(a) position'
set ylabel (tex ? '$|x(kT)|$ [m]' : '|x(kT)| [m]')
set logscale y
set format y (tex ? '$10^{%L}$' : '10^{%L}')
set ytics 100
# the caption line: what (b) cannot draw on a log axis
set label 2 (tex ? sprintf('(b) With the PC the wall still commands a force (dashed: commanded), but at %d of the %d samples where it does, the PC''s damper cancels it: the applied force is $0$ (rounding residue $\le %.0e$\,N).', n_cancel, n_wall, R_max) \
  : sprintf("(b) With the PC the wall still commands a force (dashed: commanded), but at %d of the %d samples where it does, the PC's damper\ncancels it: the applied force is 0 (rounding residue {/Symbol \243} %.0e N). The PC does not chatter here; it removes the wall.", n_cancel, n_wall, R_max)) \
  at screen 0.01, screen 2.7*emy left font note
plot off using 1:(abs($2)) with lines ls 2 title 'without PC', \
     on using 1:(abs($2)) with lines ls 1 title 'with PC'
unset label 2
set title '(b) actuator force'
set ylabel (tex ? '$|u(kT)|$ [N]' : '|u(kT)| [N]')
set yrange [1e-8:1e7]
set key top left font small
plot off using 1:(abs($3)) with lines ls 2 title 'without PC', \
     on using 1:(abs($5)) with lines ls 1 dt 2 title 'with PC (commanded)', \
     on using 1:(cancelled($3, $5) || $3 == 0 ? 1/0 : abs($3)) with points ls 1 pt 7 ps 0.6 \
        title (n_kept > 0 ? 'with PC: applied' : '')
unset logscale y
set format y '%g'
set ytics autofreq
set title '(c) human-port energy'
set ylabel (tex ? '$\int_0^t f_h v\,d\tau$ [J]' : 'energy into the interface [J]')
set key bottom left font small
set yrange [*:1]
plot off using 1:4 with lines ls 2 title 'without PC', \
     on using 1:4 with lines ls 1 title 'with PC', \
     0 with lines ls 8 notitle
unset multiplot
