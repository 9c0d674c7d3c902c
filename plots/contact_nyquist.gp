# plots/contact_nyquist.gp -- paper 002, (25) in the Nyquist plane: k*H(e^{j theta}) for
# H = 0.3(z+1)/(z^2-0.5z+0.1) at the certified wedge gain k*_wedge (the curve touches the wedge at
# the critical theta) and at Tsypkin's gain k*_T (touches Re = -1), with the forbidden wedges of
# (25) (apex -1, half-angle pi/2 - theta/2 about the negative real axis) at four frequencies; the
# marked points are k*H at those frequencies and must lie outside their wedge. Here the
# minimum of (25) (theta = 1.772) sits at the apex: k*_wedge = 3 is also the exact linear limit
# of (1+kH)^{-1} (z^2 + 0.4 z + 1 has roots e^{+-j 1.772}).
# Data: hapstab figure contact_nyquist --out DIR.
name = 'contact_nyquist'
if (!exists("plotdir")) plotdir = 'plots'
load plotdir.'/common.gp'
f = datadir.'/contact_nyquist.dat'
set size ratio -1
set clip two
set xrange [-4.5:3.5]; set yrange [-3.2:2.2]
set xzeroaxis ls 8; set yzeroaxis ls 8
set xlabel (tex ? '$\mathrm{Re}\,kH(e^{j\theta})$' : 'Re kH(e^{j{/Symbol q}})')
set ylabel (tex ? '$\mathrm{Im}\,kH(e^{j\theta})$' : 'Im kH(e^{j{/Symbol q}})')
set title (tex ? 'Wedge criterion (25) at $k^*_{\mathrm{wedge}} = 3$' : 'Wedge criterion (25): k*_{wedge} H and the forbidden wedges')
set key outside right top
stats f index 4 using 3 nooutput
thmin = STATS_min
set arrow 1 from -1, graph 0 to -1, graph 1 nohead ls 7
set label 1 (tex ? '$\mathrm{Re} = -1$ (Tsypkin)' : 'Re = -1 (Tsypkin)') at -0.95, -2.9 left font ',16'
wc(i) = i==0 ? '#E69F00' : i==1 ? '#56B4E9' : i==2 ? '#D55E00' : '#CC79A7'
plot for [i=0:3] f index (2+i) using 1:2 with filledcurves closed fs transparent solid 0.18 lc rgb wc(i) \
        title sprintf(tex ? 'wedge, $\theta = %.3f$' : 'wedge, {/Symbol q} = %.3f', i==0 ? pi/6 : i==1 ? pi/3 : i==3 ? 5*pi/6 : thmin) , \
     f index 0 using 1:2 with lines ls 1 lw 3 title (tex ? '$k^*_{\mathrm{wedge}} H$' : 'k*_{wedge} H'), \
     f index 1 using 1:2 with lines ls 3 title (tex ? '$k^*_{\mathrm{T}} H$ (Tsypkin)' : 'k*_{Tsypkin} H'), \
     f index 6 using 1:2 with points pt 7 ps 1.6 lc rgb '#000000' title 'kH at the wedge {/Symbol q}', \
     '+' using (-1):(0) every ::0::0 with points pt 6 ps 2 lc rgb '#000000' title '-1'
