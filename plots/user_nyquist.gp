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
set xlabel (tex ? '$\mathrm{Re}\,G$' : 'Re G')
set ylabel (tex ? '$\mathrm{Im}\,G$' : 'Im G')
set title (tex ? '$G = T H(z) z^{-n}/(1-z)$: '.what_tex : 'G = T H(z) z^-n/(1 - z): '.what) noenhanced
if (strlen(clip_text) > 0) set label 2 (tex ? clip_text_tex : clip_text) at graph 0.02, graph 0.04 left noenhanced font ',14'
set key below noenhanced
if (has_bstar) set arrow 1 from bstar, graph 0 to bstar, graph 1 nohead ls 7
plot f index 0 using 3:4 with lines ls 1 title (tex ? '$G(\omega)$, $0 < \omega \le \pi/T$' : 'G(w), 0 < w <= pi/T'), \
     f index 1 using 1:2 with points pt 7 ps 2 lc rgb '#D55E00' \
        title (tex ? '$b^* = $ '.bstar_text_tex : 'b* = '.bstar_text).(tex ? mark_note_tex : mark_note)
