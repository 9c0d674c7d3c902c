# plots/user_bode.gp -- `hapstab plot bode`: |H(e^{jwT}) z^-n| in dB and its unwrapped phase in
# degrees against w (log axis) up to the Nyquist frequency pi/T, with the maximiser w* of the
# passivity bound b* (paper 001 (45)) marked.
# Data: DATA/NAME.dat (w, dB, deg, theta); titles and limits are variables hapstab plot sets (gnuplot -e).
if (!exists("figname")) figname = 'bode'
name = figname
if (!exists("plotdir")) plotdir = 'plots'
load plotdir.'/common.gp'
f = datadir.'/'.name.'.dat'
set logscale x
set xrange [wmin:wmax]
set format x (tex ? '$10^{%T}$' : '10^{%T}')
set multiplot layout 2,1 title (tex ? 'Bode plot of $H z^{-n}$: '.what_tex : "Bode plot of H z⁻ⁿ\n".what) noenhanced
# both panels share one x axis: fixed left and right margins, so the frequencies line up
set lmargin at screen 0.12
set rmargin at screen 0.96
set key off
unset xlabel
set format x ''
set ylabel (tex ? '$|H z^{-n}|$ [dB]' : '|H z^{-n}| [dB]')
if (has_mark) set arrow 1 from omega_star, graph 0 to omega_star, graph 1 nohead ls 7
if (has_mark) set label 1 (tex ? '$\omega^*$ of $b^* = $ '.bstar_text_tex : '{/Symbol w}* of b* = '.bstar_text) at omega_star, graph 0.9 right offset -0.5,0 font ',16'
set yrange [db_min:db_max]
plot f using 1:2 with lines ls 1
unset label 1
set autoscale y
set format x (tex ? '$10^{%T}$' : '10^{%T}')
set xlabel (tex ? '$\omega$ [rad/s] (to $\pi/T$)' : '{/Symbol w} [rad/s] (to {/Symbol p}/T)')
set ylabel 'phase [deg]'
plot f using 1:3 with lines ls 2
unset multiplot
