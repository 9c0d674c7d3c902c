# Beyond the papers: the Z-width of a device of damping b = 2 N s/m at T = 1 ms. Data:
# `hapstab figure ext_zwidth`. Left: the walls K + B(z-1)/(Tz) z^-n it renders passively,
# n = 0..3: the region under each curve, its boundary b*(K, B) = b from certified bounds (61
# rays; b* is homogeneous in (K, B)). Right: the largest impedance magnitude
# |Z(jw)| = |H(e^{jwT}) e^{-jnwT}|/w over those walls (the upper edge of the Z-width; the lower
# edge is free motion), with the device's own |m jw + b| (m = 0.1 kg) for scale.
name = 'ext_zwidth'
if (!exists("plotdir")) plotdir = 'plots'
load plotdir.'/common.gp'
set multiplot layout 1,2 title (tex ? 'Z-width of a device with $b = 2$\,N\,s/m, $T = 1$\,ms' : 'Z-width of a device with b = 2 N s/m, T = 1 ms')
set title 'passively rendered walls'
set xlabel (tex ? '$K$ [N/m]' : 'K [N/m]')
set ylabel (tex ? '$B$ [N\,s/m]' : 'B [N s/m]')
set xtics 1000
set key top right
plot for [n=0:3] datadir.'/ext_zwidth_region.dat' index n using 1:2 with lines ls (n+1) title sprintf('n = %d', n)
set title 'largest |Z(jw)|'
set xlabel (tex ? '$\omega$ [rad/s]' : 'w [rad/s]')
set ylabel (tex ? '$|Z(j\omega)|$ [N\,s/m]' : '|Z(jw)| [N s/m]')
set logscale xy
set xtics autofreq
set format x (tex ? '$10^{%L}$' : '10^{%L}')
set format y (tex ? '$10^{%L}$' : '10^{%L}')
plot for [n=0:3] datadir.'/ext_zwidth_magnitude.dat' using 1:(column(n+2)) with lines ls (n+1) title sprintf('n = %d', n), \
     datadir.'/ext_zwidth_magnitude.dat' using 1:6 with lines ls 7 title 'device |m jw + b|'
unset multiplot
