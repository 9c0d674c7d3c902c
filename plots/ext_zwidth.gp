# Beyond the papers: the Z-width of a device of damping b = 2 N s/m at T = 1 ms. Data:
# `hapstab figure ext_zwidth`. Left, on one pair of log axes: the walls K + B(z-1)/(Tz) z^-n it renders passively,
# n = 0..3: the region under each curve, its boundary b*(K, B) = b from certified bounds (61
# rays; b* is homogeneous in (K, B)), and (dashed) the walls the same device with m = 0.1 kg renders
# stably (certified stability limit on each ray: hapstab stability --max). Right: the largest impedance magnitude
# |Z(jw)| = |H(e^{jwT}) e^{-jnwT}|/w (w: omega) over those walls (the upper edge of the Z-width; the lower
# edge is free motion), with the device's own |m jw + b| (m = 0.1 kg) for scale.
name = 'ext_zwidth'
if (!exists("plotdir")) plotdir = 'plots'
load plotdir.'/common.gp'
# The passively and the stably rendered walls on ONE pair of axes (they were two panels whose B
# axes differed by a factor 100, so the regions could not be compared): log-log, since passivity
# needs B < b = 2 N s/m while stability allows B up to about 200; solid = passive, dashed =
# stable, the colours the delays n. Each region lies below and left of its curve.
set multiplot layout 1,2 title (tex ? 'Z-width of a device with $b = 2$\,N\,s/m, $T = 1$\,ms' : 'Z-width of a device with b = 2 N s/m, T = 1 ms')
set title (tex ? 'walls $K + B(z-1)/(Tz)\,z^{-n}$: passive, stable ($m = 0.1$\,kg)' : 'walls K + B(z-1)/(Tz) z^{-n}: passive, stable (m = 0.1 kg)')
set xlabel (tex ? '$K$ [N/m]' : 'K [N/m]')
set ylabel (tex ? '$B$ [N\,s/m]' : 'B [N s/m]')
set logscale xy
set format x (tex ? '$10^{%L}$' : '10^{%L}')
set format y (tex ? '$10^{%L}$' : '10^{%L}')
set xrange [10:1e5]
set yrange [1e-2:1e3]
set key inside bottom left Left reverse font note samplen 2.5 spacing 1.0 maxrows 4 opaque
plot for [n=0:3] datadir.'/ext_zwidth_region.dat' index n using 1:2 with lines ls (n+1) lw 2.5 title sprintf(tex ? 'passive, $n = %d$' : 'passive, n = %d', n), \
     for [n=0:3] datadir.'/ext_zwidth_stable.dat' index n using 1:2 with lines ls (n+1) dt 2 lw 2 title sprintf(tex ? 'stable, $n = %d$' : 'stable, n = %d', n)
set title (tex ? 'largest $|Z(j\omega)|$, passive walls' : 'largest |Z(j{/Symbol w})|, passive walls')
set xlabel (tex ? '$\omega$ [rad/s]' : '{/Symbol w} [rad/s]')
set ylabel (tex ? '$|Z(j\omega)|$ [N\,s/m]' : '|Z(j{/Symbol w})| [N s/m]')
set autoscale x
set yrange [1:1e5]  # room for the legend above the curves
set key inside top right Left reverse font note samplen 1.5 spacing 1.0 maxrows 5
plot for [n=0:3] datadir.'/ext_zwidth_magnitude.dat' using 1:(column(n+2)) with lines ls (n+1) title sprintf(tex ? '$n = %d$' : 'n = %d', n), \
     datadir.'/ext_zwidth_magnitude.dat' using 1:6 with lines ls 7 title (tex ? 'device $|m j\omega + b|$' : 'device |m j{/Symbol w} + b|')
unset multiplot
