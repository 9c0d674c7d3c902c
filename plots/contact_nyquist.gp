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
# k* from the data (before the axis ranges: stats obeys them): H(1) = 0.6/0.6 = 1, so the curves start at k (theta = 0)
stats f index 0 every ::0::0 using 1 nooutput
kw = STATS_max
stats f index 1 every ::0::0 using 1 nooutput
kt = STATS_max
set size ratio -1
set clip two
set xrange [-4.5:5]; set yrange [-3.2:2.2]  # the wedges' polygons are cut at -4.5, -3.2 and 2.2
set xzeroaxis ls 8; set yzeroaxis ls 8
set xlabel (tex ? '$\mathrm{Re}\,kH(e^{j\theta})$' : 'Re kH(e^{j{/Symbol q}})')
set ylabel (tex ? '$\mathrm{Im}\,kH(e^{j\theta})$' : 'Im kH(e^{j{/Symbol q}})')
set title (tex ? 'Wedge criterion (25) for $H(z) = 0.3(z+1)/(z^2 - 0.5z + 0.1)$' : 'Wedge criterion (25) for H(z) = 0.3(z+1)/(z^2 - 0.5z + 0.1)')
set key inside right top Left reverse font ',17' spacing 1.0 samplen 1.5 width -1
stats f index 4 using 3 nooutput
thmin = STATS_min
set arrow 1 from -1, graph 0 to -1, graph 1 nohead ls 7
set label 1 (tex ? '$\mathrm{Re} = -1$ (Tsypkin)' : 'Re = -1 (Tsypkin)') at -0.95, -2.9 left font ',16'
set label 2 (tex ? '$-1$' : '-1') at -1.12, 0.3 right font ',20' front
# The wedges are nested (the larger theta, the wider): drawn widest first, opaque, each in its
# own light colour, so each band shows; the point k*H(e^{j theta}) of a wedge has its colour.
wc(i) = i==0 ? '#E69F00' : i==1 ? '#56B4E9' : i==2 ? '#D55E00' : '#CC79A7'
wcn(i) = i==0 ? 0xE69F00 : i==1 ? 0x56B4E9 : i==2 ? 0xD55E00 : 0xCC79A7
wt(i) = i==0 ? pi/6 : i==1 ? pi/3 : i==2 ? thmin : 5*pi/6
plot for [i=3:0:-1] f index (2+i) using 1:2 with filledcurves closed fs solid 0.3 border lc rgb wc(i) fc rgb wc(i) \
        title sprintf(tex ? 'wedge at $\theta = %.3f$' : 'wedge at {/Symbol q} = %.3f', wt(i)), \
     f index 0 using 1:2 with lines ls 1 lw 3 title sprintf(tex ? '$k^*_{\mathrm{wedge}} H$ ($k^*_{\mathrm{wedge}} = %.4g$)' : 'k*_{wedge} H  (k*_{wedge} = %.4g)', kw), \
     f index 1 using 1:2 with lines ls 3 title sprintf(tex ? '$k^*_{\mathrm{T}} H$ (Tsypkin, $k^*_{\mathrm{T}} = %.4g$)' : 'k*_{T} H  (Tsypkin, k*_{T} = %.4g)', kt), \
     f index 6 using 1:2:(wcn(int($0))) with points pt 7 ps 2.2 lc rgb variable notitle, \
     f index 6 using 1:2 with points pt 6 ps 2.2 lw 1.5 lc rgb '#000000' title (tex ? '$k^*_{\mathrm{wedge}} H(e^{j\theta})$ at the wedge $\theta$' : 'k*_{wedge} H(e^{j{/Symbol q}}) at the wedge {/Symbol q}'), \
     '+' using (-1):(0) every ::0::0 with points pt 6 ps 4 lw 2.5 lc rgb '#000000' title (tex ? '$-1$ (the apex)' : '-1 (the apex)')
