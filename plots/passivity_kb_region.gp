# plots/passivity_kb_region.gp -- (K, B) passivity regions of virtual walls (paper 001, (46), (53),
# Example 4): for device damping b = 1 N s/m and T = 1 ms, the largest stiffness K with b*(K,B,n) < b,
# for delays n = 0..3 (colour); backward-difference wall K + B(z-1)/(Tz) (solid) against the Tustin
# wall K + (2B/T)(z-1)/(z+1) (dashed). The passive K form one interval [Kmin, Kmax) (b* is convex in
# K): below the upper curve, and for the delayed Tustin walls above the lower dashed curve (shaded).
# Data: hapstab figure passivity_kb_region (a passive K by golden section on certified b*, then both
# edges of the passive interval certified by max_gain, passivity/max_gain.hpp).
name = 'passivity_kb_region'
if (!exists("plotdir")) plotdir = 'plots'
load plotdir.'/common.gp'
f = datadir.'/passivity_kb_region.dat'
set xlabel (tex ? 'virtual damping $B$ [N\,s/m]' : 'virtual damping B [N s/m]')
set ylabel (tex ? 'virtual stiffness $K$ [N/m]' : 'virtual stiffness K [N/m]')
set title (tex ? 'Passive $(K,B)$ for $b = 1$\,N\,s/m, $T = 1$\,ms' : 'Passive (K, B) for b = 1 N s/m, T = 1 ms')
# the tips, before the axes are set (stats obeys their ranges)
do for [n=1:3] {
  stats f using (valid(11+2*n) ? $1 : NaN) nooutput
  Btip = STATS_max
  stats f using (abs($1 - Btip) < 1e-9 ? column(10+2*n) : NaN) nooutput
  Klo = STATS_max > 50 ? STATS_max : 50
  stats f using (abs($1 - Btip) < 1e-9 ? column(11+2*n) : NaN) nooutput
  set arrow (10+n) from Btip, Klo to Btip, STATS_max nohead ls (n+1) dt (12,8) back
}
set xrange [0:2]
set logscale y
set yrange [50:10000]
set format y (tex ? '$%g$' : '%g')
# colour: the delay n; line: the wall (solid backward difference, dashed Tustin). The passive K lie
# below each curve; for the delayed Tustin walls (n >= 1) also above the lower dashed curve. Where
# that lower edge is K = 0 (or below the axis's 50 N/m) it is drawn along the bottom axis, so each
# outline stays closed on the log axis (it was cut there); at the tip the regions are closed by a
# dashed segment at their last B on the grid (step 0.025 N s/m; the true tip lies within one step
# to the right).
set key inside right bottom Left reverse width -2 samplen 3 spacing 1.15
set label 1 'passive: below each curve' at 1.05, 2300 left font ',18'
set label 2 'delayed Tustin: inside the closed dashed outline' at 1.05, 1750 left font ',18'
set label 3 '(its lower edge on the bottom axis: K < 50 N/m, down to 0)' at 1.05, 1380 left font ',15'
plot for [n=0:3] f using 1:(column(3+2*n)) with lines ls (n+1) dt 1 notitle, \
     for [n=0:3] f using 1:(column(11+2*n)) with lines ls (n+1) dt (12,8) notitle, \
     for [n=1:3] f using 1:(column(10+2*n) > 50 ? column(10+2*n) : 50) with lines ls (n+1) dt (12,8) notitle, \
     for [n=0:3] NaN with lines ls (n+1) lw 4 title sprintf(tex ? '$n = %d$' : 'n = %d', n), \
     NaN with lines lc rgb '#000000' lw 2 dt 1 title 'backward difference', \
     NaN with lines lc rgb '#000000' lw 2 dt (12,8) title 'Tustin'
