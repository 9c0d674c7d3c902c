# Beyond the papers: paper 001's wall H(z) = K + B(z-1)/(Tz) beyond its bound (b = 0.99 b*,
# examples/001_tightness_below.toml, operator tuned to wT = pi) without and with the
# Hannaford-Ryu passivity observer/controller (sim/simulator.hpp). Data: `hapstab figure
# ext_pc_wall`. Left: |x| (the oscillation grows without the PC, decays with it). Middle: the
# actuator force, the PC's damper chatter included. Right: the human-port energy int f_h v dt,
# negative when the interface generates energy.
name = 'ext_pc_wall'
if (!exists("plotdir")) plotdir = 'plots'
load plotdir.'/common.gp'
set multiplot layout 1,3 title (tex ? 'Passivity controller on a wall beyond $b^*$ ($b = 0.99\,b^*$, $K = 20$\,kN/m, $B = 5$\,N\,s/m, $T = 1$\,ms)' : 'Passivity controller on a wall beyond b* (b = 0.99 b*, K = 20 kN/m, B = 5 N s/m, T = 1 ms)')
set xlabel (tex ? '$t$ [s]' : 't [s]')
set key top left
set title 'position'
set ylabel (tex ? '$|x|$ [m]' : '|x| [m]')
set logscale y
set format y (tex ? '$10^{%L}$' : '10^{%L}')
plot datadir.'/ext_pc_wall_off.dat' using 1:(abs($2)) with lines ls 2 title 'without PC', \
     datadir.'/ext_pc_wall_on.dat' using 1:(abs($2)) with lines ls 1 title 'with PC'
set title 'actuator force'
set ylabel (tex ? '$|u|$ [N]' : '|u| [N]')
plot datadir.'/ext_pc_wall_off.dat' using 1:(abs($3)) with lines ls 2 title 'without PC', \
     datadir.'/ext_pc_wall_on.dat' using 1:(abs($3)) with lines ls 1 title 'with PC'
unset logscale y
set format y '%g'
set title 'human-port energy'
set ylabel (tex ? '$\int f_h v\,dt$ [J]' : 'energy into the interface [J]')
set key bottom left
set yrange [-2:1]
plot datadir.'/ext_pc_wall_off.dat' using 1:4 with lines ls 2 title 'without PC', \
     datadir.'/ext_pc_wall_on.dat' using 1:4 with lines ls 1 title 'with PC'
unset multiplot
