# plots/user_nyquist.gp -- `hapstab plot nyquist`: the curve G(w) = T H(z) z^-n/(1 - z), z = e^{jwT},
# 0 < w <= pi/T, of the user's H, whose largest real part is the passivity bound b* of paper 001
# (45): the line Re = b* (certified) and the maximiser are marked. Im G grows like T H(1)/(wT) as
# w -> 0 when H(1) != 0; the window is cut (clip_text says below which w).
# Data: DATA/NAME.dat (index 0 the curve: theta w Re Im; index 1 the maximiser) and
# titles, the window and b* as variables hapstab plot sets (gnuplot -e).
if (!exists("figname")) figname = 'nyquist'
name = figname
if (!exists("plotdir")) plotdir = 'plots'
load plotdir.'/common.gp'
f = datadir.'/'.name.'.dat'
set xrange [xmin:xmax]
set yrange [-ymax:ymax]
set clip two
set xzeroaxis ls 8; set yzeroaxis ls 8
# G = T H/(1 - z): H in N/m (force per displacement) times T in s gives N s/m, the unit of b*
set xlabel (tex ? '$\mathrm{Re}\,G$ [N\,s/m]' : 'Re G [N s/m]')
set ylabel (tex ? '$\mathrm{Im}\,G$ [N\,s/m]' : 'Im G [N s/m]')
# the window is cut where Im G grows without bound as w -> 0: said in the title's last line
cut = strlen(clip_omega_text) == 0 ? '' : (tex ? '; the curve leaves the window for $\omega <$ '.clip_omega_text_tex.' rad/s' : "\n(the curve leaves the window for ω < ".clip_omega_text.' rad/s)')
inf = has_bstar ? '' : (tex ? '; $b^* = \infty$ ('.infinite_note_tex.')' : '; b* = inf ('.infinite_note.')')
set title (tex ? '$G = T H(z) z^{-n}/(1-z)$: '.what_tex.inf.cut : "G = T H(z) z⁻ⁿ/(1 − z)\n".what.inf.cut) noenhanced
# the legend below the axes, where it covers neither the curve nor the x label
set key at screen 0.5, screen 0.01 center bottom horizontal samplen 2
set bmargin 6
# Re G = b*: drawn, with its legend entry, when b* is finite; the maximiser is marked when there is
# one (b* can be approached as w -> 0 only: then no point, and no legend entry for it)
if (has_bstar) set arrow 1 from bstar, graph 0 to bstar, graph 1 nohead ls 7
bline = !has_bstar ? '' : (tex ? '$\mathrm{Re}\,G = b^* = $ '.bstar_text_tex : 'Re G = b* = '.bstar_text) \
        .(has_mark ? '' : (tex ? ' (approached as $\omega \to 0$)' : ' (approached as {/Symbol w} → 0)'))
plot f index 0 using 3:4 with lines ls 1 title (tex ? '$G(\omega)$, $0 < \omega \le \pi/T$' : 'G({/Symbol w}), 0 < {/Symbol w} ≤ {/Symbol p}/T'), \
     NaN with lines ls 7 title bline, \
     f index 1 using 1:2 with points pt 7 ps 2 lc rgb '#D55E00' title (has_mark ? (tex ? 'its maximiser $\omega^*$' : 'its maximiser {/Symbol w}*') : '')
