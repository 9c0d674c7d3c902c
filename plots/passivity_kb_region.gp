# plots/passivity_kb_region.gp -- (K, B) passivity regions of virtual walls (paper 001, (46), (53),
# Example 4): for device damping b = 1 N s/m and T = 1 ms, the largest stiffness K with b*(K,B,n) < b,
# for delays n = 0..3; backward-difference wall K + B(z-1)/(Tz) (solid) against the Tustin wall
# K + (2B/T)(z-1)/(z+1) (dashed). The passive K form one interval [Kmin, Kmax) (b* is convex in K):
# below the upper curve, and for the delayed Tustin walls above the lower curve of the same style.
# Data: hapstab figure passivity_kb_region (certified b* in golden-section and bisection searches on K).
name = 'passivity_kb_region'
if (!exists("plotdir")) plotdir = 'plots'
load plotdir.'/common.gp'
f = datadir.'/passivity_kb_region.dat'
set xlabel (tex ? 'virtual damping $B$ [N\,s/m]' : 'virtual damping B [N s/m]')
set ylabel (tex ? 'virtual stiffness $K$ [N/m]' : 'virtual stiffness K [N/m]')
set title (tex ? 'Passive $(K,B)$ for $b = 1$\,N\,s/m, $T = 1$\,ms' : 'Passive (K, B) for b = 1 N s/m, T = 1 ms')
set key outside right top
set xrange [0:2]
set logscale y
set yrange [50:10000]
set format y (tex ? '$%g$' : '%g')
plot for [n=0:3] f using 1:(column(3+2*n)) with lines ls (n+1) dt 1 title sprintf(tex ? 'backward diff., $n = %d$' : 'backward difference, n = %d', n), \
     for [n=0:3] f using 1:(column(11+2*n)) with linespoints ls (n+1) dt 2 pt 6 ps 1.2 pi 3 title sprintf(tex ? 'Tustin, $n = %d$' : 'Tustin, n = %d', n), \
     for [n=0:3] f using 1:(column(10+2*n) > 0 ? column(10+2*n) : 1/0) with linespoints ls (n+1) dt 2 pt 4 ps 1.0 pi 3 notitle
