# plots/contact_fig6.gp -- paper 002, Fig. 6: the inequalities (21) and (22) at theta = pi/4 in
# the Nyquist plane of H. Each q = 1..7 is a half-plane bounded by a line through -1 (q = 4 is
# the vertical line, the same as (21), Tsypkin); the arrows point to the side that satisfies it.
# Shaded: the forbidden region where no inequality holds -- the wedge bounded by q = 1 and q = 7.
# Data: hapstab figure contact_fig6 --out DIR.
name = 'contact_fig6'
if (!exists("plotdir")) plotdir = 'plots'
load plotdir.'/common.gp'
f = datadir.'/contact_fig6.dat'
set size ratio -1
set clip two
set xrange [-5:1.5]; set yrange [-3:3]
set xzeroaxis ls 8; set yzeroaxis ls 8
set xlabel (tex ? '$\mathrm{Re}\,H(e^{j\theta})$' : 'Re H(e^{j{/Symbol q}})')
set ylabel (tex ? '$\mathrm{Im}\,H(e^{j\theta})$' : 'Im H(e^{j{/Symbol q}})')
set title (tex ? 'Fig.~6: inequalities (21), (22) at $\theta = \pi/4$' : 'Fig. 6: inequalities (21), (22) at {/Symbol q} = {/Symbol p}/4')
set key outside right top
set style arrow 1 head filled size screen 0.012,20 lc rgb '#000000' lw 1.5
plot f index 8 using 1:2 with filledcurves closed fs solid 0.35 lc rgb '#D55E00' title 'forbidden region', \
     for [q=1:7] f index (q-1) using 1:2 with lines lw (q==1||q==7 ? 3 : 1.5) lc rgb (q==1||q==7 ? '#0072B2' : q==4 ? '#009E73' : '#808080') \
        title (q==4 ? 'q = 4 (and (21))' : q==1 ? 'q = 1' : q==7 ? 'q = 7' : q==2 ? 'q = 2, 3, 5, 6' : ''), \
     f index 7 using 1:2:3:4 with vectors arrowstyle 1 notitle, \
     f index 7 using ($1+1.35*$3):($2+1.35*$4):(sprintf('%d', $5)) with labels font ',16' notitle, \
     '+' using (-1):(0) every ::0::0 with points pt 7 ps 1.5 lc rgb '#000000' title '-1'
