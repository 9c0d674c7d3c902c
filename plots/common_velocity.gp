# plots/common_velocity.gp -- the velocity panels shared by paper 000's Fig. 6 and Fig. 7
# (loaded by multidof_fig6.gp / multidof_fig7.gp, which set name, stem and the panel titles).
# Data: datadir/STEM_none.dat, STEM_designed.dat, STEM_paper27.dat with columns t v_1 ... v_N
# (the closed loop's device velocities after a force impulse on d_a, exact-ZOH simulation).
# Every panel has the same legend and time axis (starting a little before the impulse at t = 0,
# so the jump is not drawn on the axis); the coupled panels (b), (b') share one velocity axis;
# (a), which diverges without coupling, is drawn in units of 10^k m/s so its ticks are plain numbers.
load plotdir.'/common.gp'
panels = exists("with27") ? 3 : 2
none = datadir.'/'.stem.'_none.dat'
designed = datadir.'/'.stem.'_designed.dat'
paper27 = datadir.'/'.stem.'_paper27.dat'
# the ranges, before any axis range is set (stats obeys them)
stats none using 1:(abs($2) > abs($3) ? abs($2) : abs($3)) nooutput
tmax = STATS_max_x
amax = STATS_max_y
ea = amax >= 1000 ? floor(log10(amax)) : 0
sa = 10.0**ea
stats designed using 2:3 nooutput
lo = STATS_min_x < STATS_min_y ? STATS_min_x : STATS_min_y
hi = STATS_max_x > STATS_max_y ? STATS_max_x : STATS_max_y
if (panels == 3) {
  stats paper27 using 2:3 nooutput
  lo = STATS_min_x < lo ? STATS_min_x : lo
  lo = STATS_min_y < lo ? STATS_min_y : lo
  hi = STATS_max_x > hi ? STATS_max_x : hi
  hi = STATS_max_y > hi ? STATS_max_y : hi
}
pad = 0.06 * (hi - lo)
set multiplot layout 1,panels title figtitle
set xlabel (tex ? '$t$ [s]' : 't [s]')
set xrange [-0.03 * tmax : tmax]
set key top left samplen 1.5  # (a) grows at the end; (b), (b') start at the top left
v1 = tex ? '$v_1$ ($d_a$)' : 'v_1 (d_a)'
v2 = tex ? '$v_2$ ($d_b$)' : 'v_2 (d_b)'
set title '(a) no virtual coupling'
set ylabel (ea == 0 ? (tex ? '$v$ [m/s]' : 'v [m/s]') : sprintf(tex ? '$v$ [$10^{%d}$ m/s]' : 'v [10^{%d} m/s]', ea))
plot none u 1:($2/sa) w l ls 1 t v1, '' u 1:($3/sa) w l ls 2 t v2
set ylabel (tex ? '$v$ [m/s]' : 'v [m/s]')
set key top right
set yrange [lo - pad : hi + pad]
set title '(b) designed V (Theorem 6)'
plot designed u 1:2 w l ls 1 t v1, '' u 1:3 w l ls 2 t v2
if (panels == 3) {
  set title "(b') the paper's V (27)"
  plot paper27 u 1:2 w l ls 1 t v1, '' u 1:3 w l ls 2 t v2
}
unset multiplot
