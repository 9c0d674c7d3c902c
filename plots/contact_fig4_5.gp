# plots/contact_fig4_5.gp -- paper 002, Figs. 4 and 5: the shifted unilateral nonlinearity
# x = xi(y + rho) - rho = max(y, -rho) for rho = 0.5, 1, 2 (Fig. 4), and the region of the
# (y, x) plane it covers as rho runs over (0, inf) (Fig. 5, shaded): the sector between x = 0
# and x = y for y < 0 together with the line x = y for y >= 0.
# Data: hapstab figure contact_fig4_5 --out DIR.
name = 'contact_fig4_5'
if (!exists("plotdir")) plotdir = 'plots'
load plotdir.'/common.gp'
f = datadir.'/contact_fig4_5.dat'
set multiplot layout 1,2
set size ratio -1
set xrange [-3:3]; set yrange [-3:3]
set xzeroaxis ls 8; set yzeroaxis ls 8
set xlabel (tex ? '$y_k$' : 'y_k')
set ylabel (tex ? '$x_k = \xi(y_k+\rho)-\rho$' : 'x_k = {/Symbol x}(y_k+{/Symbol r}) - {/Symbol r}')
set title (tex ? 'Fig.~4: shifted unilateral nonlinearity' : 'Fig. 4: shifted unilateral nonlinearity')
set key top left
plot f index 0 using 1:2 with lines ls 2 title (tex ? '$\rho = 0.5$' : '{/Symbol r} = 0.5'), \
     f index 0 using 1:3 with lines ls 1 title (tex ? '$\rho = 1$' : '{/Symbol r} = 1'), \
     f index 0 using 1:4 with lines ls 3 title (tex ? '$\rho = 2$' : '{/Symbol r} = 2')
set title (tex ? 'Fig.~5: region covered for $0 < \rho < \infty$' : 'Fig. 5: region covered for 0 < {/Symbol r} < {/Symbol \245}')
set ylabel (tex ? '$x_k$' : 'x_k')
plot f index 1 using 1:2 with filledcurves closed fs transparent solid 0.35 lc rgb '#0072B2' title 'sector (y < 0)', \
     f index 0 using 1:($1 >= 0 ? $1 : 1/0) with lines ls 1 lw 3 title 'x = y (y >= 0)', \
     f index 0 using 1:1 with lines ls 7 notitle
unset multiplot
