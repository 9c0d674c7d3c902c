# plots/user_wedge.gp -- `hapstab plot nyquist --wedge`: k* H(e^{j theta}), 0 <= theta <= pi, of the
# user's H at its wedge gain k* = k*_wedge, with the forbidden wedges of the wedge criterion (25) of
# paper 002 (apex -1, half-angle pi/2 - theta/2 about the negative real axis) at theta = pi/6, pi/3,
# 5 pi/6 and at the critical theta of (25); the marked points are k* H at those theta and lie outside
# their wedge (on its edge at the critical theta), as in contact_nyquist. `curve` (a gnuplot -e value) is
# 'k*H', or 'H' when k*_wedge is infinite or not evaluated (the curve is then H itself).
# Data: DATA/NAME_wedge.dat; titles, names and limits are variables hapstab plot sets (gnuplot -e).
if (!exists("figname")) figname = 'nyquist'
name = figname.'_wedge'
if (!exists("plotdir")) plotdir = 'plots'
load plotdir.'/common.gp'
f = datadir.'/'.name.'.dat'
set size ratio -1
set clip two
set xrange [xmin:xmax]; set yrange [ymin:ymax]
set xzeroaxis ls 8; set yzeroaxis ls 8
curve_tex_math = (curve eq 'k*H') ? 'k^*H' : 'H'
set xlabel (tex ? '$\mathrm{Re}\,'.curve_tex_math.'(e^{j\theta})$' : 'Re '.curve.'(e^{j{/Symbol q}})')
set ylabel (tex ? '$\mathrm{Im}\,'.curve_tex_math.'(e^{j\theta})$' : 'Im '.curve.'(e^{j{/Symbol q}})')
set title (tex ? what_tex.'; '.verdict_tex : what.'; '.verdict) noenhanced
set key outside right top
wc(i) = i==0 ? '#E69F00' : i==1 ? '#56B4E9' : i==2 ? '#D55E00' : '#CC79A7'
wt(i) = i==0 ? pi/6 : i==1 ? pi/3 : i==2 ? theta_crit : 5*pi/6
plot for [i=0:3] f index (1+i) using 1:2 with filledcurves closed fs transparent solid 0.18 lc rgb wc(i) \
        title sprintf(tex ? 'wedge, $\theta = %.3f$' : 'wedge, {/Symbol q} = %.3f', wt(i)), \
     f index 0 using 1:2 with lines ls 1 lw 3 title (tex ? '$'.curve_tex_math.'$' : curve), \
     f index 5 using 1:2 with points pt 7 ps 1.6 lc rgb '#000000' title (tex ? '$'.curve_tex_math.'$ at the wedge $\theta$' : curve.' at the wedge {/Symbol q}'), \
     '+' using (-1):(0) every ::0::0 with points pt 6 ps 2 lc rgb '#000000' title '-1'
