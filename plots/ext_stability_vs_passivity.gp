# plots/ext_stability_vs_passivity.gp -- issue 19: the stability limit of the sampled haptic loop
# against the passivity limit of paper 001 in the (K, B) plane. Device 1/(m s^2 + b s) with
# b = 1 N s/m, T = 1 ms, wall K + B(z-1)/(Tz), delays n = 0..3 (colours). Stable below the solid
# (m = 1 kg), dash-dot (m = 0.01 kg) and dotted (m = 0.001 kg) curves; passive below the dashed
# curve with points (independent of m). The key names the line kinds (black) and the delays
# (colours) once each. The two coincide at B = 0 and part as B grows: B adds to
# the damping for stability (~2(b + B)/((2n+1)T)) and subtracts from it for passivity.
# Data: hapstab figure ext_stability_vs_passivity (stability --max certified; b* certified).
name = 'ext_stability_vs_passivity'
if (!exists("plotdir")) plotdir = 'plots'
load plotdir.'/common.gp'
f = datadir.'/ext_stability_vs_passivity.dat'
set xlabel (tex ? 'virtual damping $B$ [N\,s/m]' : 'virtual damping B [N s/m]')
set ylabel (tex ? 'virtual stiffness $K$ [N/m]' : 'virtual stiffness K [N/m]')
set title (tex ? 'Stable against passive walls $K + B(z-1)/(Tz)\,z^{-n}$: device $1/(ms^2 + bs)$, $b = 1$\,N\,s/m, $T = 1$\,ms' : 'Stable against passive walls K + B(z-1)/(Tz) z^{-n}: device 1/(ms^2 + bs), b = 1 N s/m, T = 1 ms')
# colour = delay n, line kind = which limit (the walls below a curve are stable / passive)
set key top left Left reverse font small spacing 1.0 maxrows 4 width -1
set xrange [0:2]
set logscale y
set yrange [50:30000]
set format y (tex ? '$%g$' : '%g')
set ytics (50, 100, 200, 500, 1000, 2000, 5000, 10000, 20000)
plot for [n=0:3] f using 1:(column(2+4*n)) with lines ls (n+1) dt 1 notitle, \
     for [n=0:3] f using 1:(column(3+4*n)) with lines ls (n+1) dt 4 lw 1.5 notitle, \
     for [n=0:3] f using 1:(column(4+4*n)) with lines ls (n+1) dt 3 lw 1.5 notitle, \
     for [n=0:3] f using 1:(column(5+4*n)) with linespoints ls (n+1) dt 2 pt 6 pi 2 notitle, \
     NaN with lines lc rgb '#000000' lw 2 dt 1 title (tex ? 'stable, $m = 1$\,kg' : 'stable, m = 1 kg'), \
     NaN with lines lc rgb '#000000' lw 1.5 dt 4 title (tex ? 'stable, $m = 0.01$\,kg' : 'stable, m = 0.01 kg'), \
     NaN with lines lc rgb '#000000' lw 1.5 dt 3 title (tex ? 'stable, $m = 0.001$\,kg' : 'stable, m = 0.001 kg'), \
     NaN with linespoints lc rgb '#000000' lw 2 dt 2 pt 6 title 'passive (any m)', \
     for [n=0:3] NaN with lines lt (n+1) lw 8 title sprintf(tex ? 'delay $n = %d$' : 'delay n = %d', n)
