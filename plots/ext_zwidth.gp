# Beyond the papers: the Z-width of a device of damping b = 2 N s/m at T = 1 ms. Data:
# `hapstab figure ext_zwidth`. Left: the walls K + B(z-1)/(Tz) z^-n it renders passively,
# n = 0..3: the region under each curve, its boundary b*(K, B) = b from certified bounds (61
# rays; b* is homogeneous in (K, B)). Middle: the walls the same device with m = 0.1 kg renders
# stably (certified stability limit on each ray: hapstab stability --max). Right: the largest impedance magnitude
# |Z(jw)| = |H(e^{jwT}) e^{-jnwT}|/w (w: omega) over those walls (the upper edge of the Z-width; the lower
# edge is free motion), with the device's own |m jw + b| (m = 0.1 kg) for scale.
name = 'ext_zwidth'
if (!exists("plotdir")) plotdir = 'plots'
load plotdir.'/common.gp'
# One legend for the three panels (the colours are the delays n in each), in the third; the two
# (K, B) panels share the K axis (the B axes differ by a factor 100: passive walls need B < b).
stats datadir.'/ext_zwidth_stable.dat' using 1 nooutput
Kmax = 2000 * ceil(STATS_max / 2000)
set multiplot layout 1,3 title (tex ? 'Z-width of a device with $b = 2$\,N\,s/m, $T = 1$\,ms' : 'Z-width of a device with b = 2 N s/m, T = 1 ms')

set title 'passively rendered walls'
set xlabel (tex ? '$K$ [N/m]' : 'K [N/m]')
set ylabel (tex ? '$B$ [N\,s/m]' : 'B [N s/m]')
set xrange [0:Kmax]
set xtics Kmax/2
set mxtics 2
set yrange [0:*]
unset key
plot for [n=0:3] datadir.'/ext_zwidth_region.dat' index n using 1:2 with lines ls (n+1) notitle
set title (tex ? 'stably rendered walls ($m = 0.1$\,kg)' : 'stably rendered walls (m = 0.1 kg)')
plot for [n=0:3] datadir.'/ext_zwidth_stable.dat' index n using 1:2 with lines ls (n+1) notitle
set title (tex ? 'largest $|Z(j\omega)|$, passive walls' : 'largest |Z(j{/Symbol w})|, passive walls')
set xlabel (tex ? '$\omega$ [rad/s]' : '{/Symbol w} [rad/s]')
set ylabel (tex ? '$|Z(j\omega)|$ [N\,s/m]' : '|Z(j{/Symbol w})| [N s/m]')
set logscale xy
set autoscale x
set yrange [1:1e5]  # room for the legend above the curves
set xtics autofreq
set format x (tex ? '$10^{%L}$' : '10^{%L}')
set format y (tex ? '$10^{%L}$' : '10^{%L}')
set key inside top right Left reverse font ',17' samplen 1.5 spacing 1.0 width -2
plot for [n=0:3] datadir.'/ext_zwidth_magnitude.dat' using 1:(column(n+2)) with lines ls (n+1) title sprintf(tex ? '$n = %d$' : 'n = %d', n), \
     datadir.'/ext_zwidth_magnitude.dat' using 1:6 with lines ls 7 title (tex ? 'device $|m j\omega + b|$' : 'device |m j{/Symbol w} + b|')
unset multiplot
