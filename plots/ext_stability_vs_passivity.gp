# plots/ext_stability_vs_passivity.gp -- issue 19: the stability limit of the sampled haptic loop
# against the passivity limit of paper 001 in the (K, B) plane. Device 1/(m s^2 + b s) with
# b = 1 N s/m, T = 1 ms, wall K + B(z-1)/(Tz), delays n = 0..3 (colours). Stable below the solid
# (m = 1 kg), dash-dot (m = 0.01 kg) and dotted (m = 0.001 kg) curves; passive below the dashed
# curve with points (independent of m). The two coincide at B = 0 and part as B grows: B adds to
# the damping for stability (~2(b + B)/((2n+1)T)) and subtracts from it for passivity.
# Data: hapstab figure ext_stability_vs_passivity (stability --max certified; b* certified).
name = 'ext_stability_vs_passivity'
if (!exists("plotdir")) plotdir = 'plots'
load plotdir.'/common.gp'
f = datadir.'/ext_stability_vs_passivity.dat'
set xlabel (tex ? 'virtual damping $B$ [N\,s/m]' : 'virtual damping B [N s/m]')
set ylabel (tex ? 'virtual stiffness $K$ [N/m]' : 'virtual stiffness K [N/m]')
set title (tex ? 'Stable vs passive $(K,B)$, $b = 1$\,N\,s/m, $T = 1$\,ms' : 'Stable vs passive (K, B), b = 1 N s/m, T = 1 ms')
set key outside right top
set xrange [0:2]
set logscale y
set yrange [50:10000]
set format y (tex ? '$%g$' : '%g')
plot for [n=0:3] f using 1:(column(2+4*n)) with lines ls (n+1) dt 1 title sprintf(tex ? 'stable, $n = %d$, $m = 1$' : 'stable, n = %d, m = 1', n), \
     for [n=0:3] f using 1:(column(3+4*n)) with lines ls (n+1) dt 4 lw 1.5 notitle, \
     for [n=0:3] f using 1:(column(4+4*n)) with lines ls (n+1) dt 3 lw 1.5 notitle, \
     for [n=0:3] f using 1:(column(5+4*n)) with linespoints ls (n+1) dt 2 pt 6 pi 2 title sprintf(tex ? 'passive, $n = %d$' : 'passive, n = %d', n), \
     NaN with lines ls 8 dt 4 title (tex ? '$m = 0.01$ (dash-dot)' : 'm = 0.01 (dash-dot)'), \
     NaN with lines ls 8 dt 3 title (tex ? '$m = 0.001$ (dotted)' : 'm = 0.001 (dotted)')
