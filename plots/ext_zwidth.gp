# Beyond the papers: the Z-width of a device of damping b = 2 N s/m at T = 1 ms. Data:
# `hapstab figure ext_zwidth`. Left: the walls K + B(z-1)/(Tz) z^-n it renders passively,
# n = 0..3: the region under each curve, its boundary b*(K, B) = b from certified bounds (61
# rays; b* is homogeneous in (K, B)). Middle: the walls the same device with m = 0.1 kg renders
# stably (certified stability limit on each ray: hapstab stability --max). Right: the largest impedance magnitude
# |Z(jw)| = |H(e^{jwT}) e^{-jnwT}|/w over those walls (the upper edge of the Z-width; the lower
# edge is free motion), with the device's own |m jw + b| (m = 0.1 kg) for scale.
name = 'ext_zwidth'
if (!exists("plotdir")) plotdir = 'plots'
load plotdir.'/common.gp'
set multiplot layout 1,3 title (tex ? 'Z-width of a device with $b = 2$\,N\,s/m, $T = 1$\,ms' : 'Z-width of a device with b = 2 N s/m, T = 1 ms')
set title 'passively rendered walls'
set xlabel (tex ? '$K$ [N/m]' : 'K [N/m]')
set ylabel (tex ? '$B$ [N\,s/m]' : 'B [N s/m]')
set xtics 2000
set key top right
plot for [n=0:3] datadir.'/ext_zwidth_region.dat' index n using 1:2 with lines ls (n+1) title sprintf('n = %d', n)
set title (tex ? 'stably rendered walls ($m = 0.1$\,kg)' : 'stably rendered walls (m = 0.1 kg)')
set xtics 4000
plot for [n=0:3] datadir.'/ext_zwidth_stable.dat' index n using 1:2 with lines ls (n+1) title sprintf('n = %d', n)
set title 'largest |Z(jw)|, passive walls'
set key top right
set xlabel (tex ? '$\omega$ [rad/s]' : 'w [rad/s]')
set ylabel (tex ? '$|Z(j\omega)|$ [N\,s/m]' : '|Z(jw)| [N s/m]')
set logscale xy
set xtics autofreq
set format x (tex ? '$10^{%L}$' : '10^{%L}')
set format y (tex ? '$10^{%L}$' : '10^{%L}')
plot for [n=0:3] datadir.'/ext_zwidth_magnitude.dat' using 1:(column(n+2)) with lines ls (n+1) title sprintf('n = %d', n), \
     datadir.'/ext_zwidth_magnitude.dat' using 1:6 with lines ls 7 title 'device'
unset multiplot
