# plots/ext_long_delay.gp -- delays of teleoperation scale (issue 43): where the methods fail.
# (a) b* of paper 001 (45) against the delay n (log axes) for a stiff wall K = 1000, B = 5 and a
# soft one K = 10, B = 5 (T = 1 ms): certified (the exact path while it is cheap, the long-delay
# path beyond), double grids of 10^4 and 10^6 points, and Sec. VI's closed forms: (46) at n = 0
# and (53) at n = 1 (exact), (53)'s conservative (2n+1)KT/2 + B above and the value at w = 0,
# (2n+1)KT/2 - B, below. (b) The grids' relative error against the certified b*: it grows once a
# grid under-samples the e^{-j n wT} of the delay (spacing pi/N against the period 2 pi/n).
# (c) sup K of stability --max (device 1/(s^2 + s), wall K + 0.5(z-1)/(Tz)): certified, the grids
# (max_gain_grid) and the small-T law 2(b + B)/((2n+1) T). (d) The grids' relative error.
# Data: ext_long_delay_bound.dat, ext_long_delay_kmax.dat (toolbox/cli/figures_delay.cpp).
name = 'ext_long_delay'
wide = 1
tall = 1
if (!exists("plotdir")) plotdir = 'plots'
load plotdir.'/common.gp'
fb = datadir.'/ext_long_delay_bound.dat'
fk = datadir.'/ext_long_delay_kmax.dat'
err(x, r) = (abs(x - r) / abs(r) < 1e-17 ? 1e-17 : abs(x - r) / abs(r))
set multiplot layout 2,2 title 'Delays of teleoperation scale: certified b* and sup K against double grids'
set bmargin 5
set logscale xy
set format x (tex ? '$10^{%T}$' : '10^{%T}')
set format y (tex ? '$10^{%T}$' : '10^{%T}')
set xrange [0.7:14000]
set xlabel (tex ? 'delay $n$ [samples]' : 'delay n [samples]')
set title (tex ? '(a) $b^*$, (45): walls $K = 1000$ and $K = 10$, $B = 5$' : '(a) b*, (45): walls K = 1000 and K = 10, B = 5') font small
set ylabel (tex ? '$b^*$ [N s/m]' : 'b* [N s/m]')
set key top left Left reverse font note spacing 0.9
plot fb index 0 u 1:2 w l ls 1 t 'certified, K = 1000', \
     fb index 0 u 1:3 w p ls 2 pt 6 t 'grid 1e4', \
     fb index 0 u 1:4 w p ls 3 pt 4 t 'grid 1e6', \
     fb index 0 u 1:5 w l lc rgb '#888888' dt 2 t '(53) upper (2n+1)KT/2 + B', \
     fb index 0 u 1:($6 > 0 ? $6 : 1/0) w l lc rgb '#888888' dt 3 t 'value at w = 0', \
     fb index 1 u ($1 > 0 ? $1 : 1/0):2 w p ls 4 pt 7 ps 1.5 t '(53), n = 1 (exact)', \
     fb index 0 u 1:8 w l ls 5 t 'certified, K = 10', \
     fb index 0 u 1:9 w p ls 2 pt 6 notitle, \
     fb index 0 u 1:10 w p ls 3 pt 4 notitle
set title '(b) b*: relative error of the grids' font small
set ylabel 'relative error'
set yrange [1e-17:10]
set key top left Left reverse font note spacing 0.9
plot fb index 0 u 1:(err($3, $2)) w lp ls 2 pt 6 t 'grid 1e4, K = 1000', \
     fb index 0 u 1:(err($4, $2)) w lp ls 3 pt 4 t 'grid 1e6, K = 1000', \
     fb index 0 u 1:(err($9, $8)) w lp ls 2 pt 7 dt 2 t 'grid 1e4, K = 10', \
     fb index 0 u 1:(err($10, $8)) w lp ls 3 pt 5 dt 2 t 'grid 1e6, K = 10'
unset yrange
set title (tex ? '(c) sup $K$, stability --max: $1/(s^2 + s)$, $B = 0.5$' : '(c) sup K, stability --max: 1/(s^2 + s), B = 0.5') font small
set ylabel 'sup K [N/m]'
set key bottom left Left reverse font note spacing 0.9
plot fk u 1:2 w l ls 1 t 'certified', \
     fk u 1:3 w p ls 2 pt 6 t 'grid 1e4', \
     fk u 1:4 w p ls 3 pt 4 t 'grid 1e6', \
     fk u 1:5 w l lc rgb '#888888' dt 2 t 'small-T law 2(b + B)/((2n+1)T)'
set title '(d) sup K: relative error of the grids and of the law' font small
set ylabel 'relative error'
set yrange [1e-17:10]
set key top left Left reverse font note spacing 0.9
plot fk u 1:(err($3, $2)) w lp ls 2 pt 6 t 'grid 1e4', \
     fk u 1:(err($4, $2)) w lp ls 3 pt 4 t 'grid 1e6', \
     fk u 1:(err($5, $2)) w lp lc rgb '#888888' dt 2 pt 1 t 'small-T law'
unset multiplot
