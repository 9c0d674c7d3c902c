# plots/passivity_bound_curve.gp -- paper 001, (45): the objective Re{T H(e^{jwT}) z^{-n}/(1 - e^{jwT})}
# against w for the backward-difference wall (n = 0, 1) and the Tustin wall (n = 1), K = 1000 N/m,
# B = 5 N s/m, T = 1 ms, with the certified bound b* and its maximiser marked (the system is
# passive iff b > b*). Data: hapstab figure passivity_bound_curve.
name = 'passivity_bound_curve'
if (!exists("plotdir")) plotdir = 'plots'
load plotdir.'/common.gp'
f = datadir.'/passivity_bound_curve.dat'
m = datadir.'/passivity_bound_curve_marks.dat'
set xlabel (tex ? '$\omega$ [rad/s]' : '{/Symbol w} [rad/s]')
set ylabel (tex ? '$\mathrm{Re}\{T H z^{-n}/(1-z)\}$ [N\,s/m]' : 'Re\{T H z^{-n}/(1-z)\} [N s/m]')
# the axis runs a little past pi/T (dotted line), so the maximisers drawn there are whole
set xrange [0:3141.6 * 1.03]
set yrange [-8:20]
set arrow 1 from 3141.6, graph 0 to 3141.6, graph 1 nohead ls 8
set xtics ('0' 0, '{/Symbol p}/(4T)' 785.4, '{/Symbol p}/(2T)' 1570.8, '3{/Symbol p}/(4T)' 2356.2, '{/Symbol p}/T' 3141.6)
if (tex) set xtics ('0' 0, '$\pi/(4T)$' 785.4, '$\pi/(2T)$' 1570.8, '$3\pi/(4T)$' 2356.2, '$\pi/T$' 3141.6)
set key top left Left reverse width -2
set title (tex ? 'Passivity bound (45): $K = 1000$\,N/m, $B = 5$\,N\,s/m, $T = 1$\,ms' : 'Passivity bound (45): K = 1000 N/m, B = 5 N s/m, T = 1 ms')
plot f index 0 using 1:2 with lines ls 1 title (tex ? 'backward difference, $n = 1$ ($b^* = 5.525$)' : 'backward difference, n = 1 (b* = 5.525)'), \
     f index 1 using 1:2 with lines ls 2 title (tex ? 'backward difference, $n = 0$ ($b^* = 5.5$)' : 'backward difference, n = 0 (b* = 5.5)'), \
     f index 2 using 1:2 with lines ls 3 title (tex ? 'Tustin, $n = 1$ ($b^* = 14.5$)' : 'Tustin, n = 1 (b* = 14.5)'), \
     m using 1:2 with points pt 7 ps 2 lc rgb '#000000' title (tex ? 'certified $b^*$ at its maximiser' : 'certified b* at its maximiser'), \
     m using 1:2:(sprintf('b* = %.6g', $2)) with labels right offset -1,1 notitle
