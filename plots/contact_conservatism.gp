# plots/contact_conservatism.gp -- how conservative the criteria of paper 002 are: for each
# virtual wall K(1 + 0.002 D(z)) z^-d (backward difference BD or Tustin, delay d = 0..2) touched
# through a 0.2 kg, 0.5 Ns/m device by an operator (none, soft, medium, stiff hand), the
# certified largest wall stiffness by Tsypkin's condition and by the wedge criterion (25), the
# exact linear stability limit of (1+kH)^{-1}, and the smallest stiffness at which the simulated
# loop (Fig. 5) oscillates. Open symbols: a paper assumption is violated (criterion does not apply);
# Tustin walls with d = 0, 2 make (1+kH)^{-1} unstable at every gain, so they oscillate at any K.
# Data: hapstab figure contact_conservatism --out DIR.
name = 'contact_conservatism'
if (!exists("plotdir")) plotdir = 'plots'
load plotdir.'/common.gp'
if (fmt eq 'png') { set terminal pngcairo size 1800,1100 enhanced font 'DejaVu Sans,20' linewidth 2; set output outdir.'/'.name.'.png' }
f = datadir.'/contact_conservatism.dat'
set logscale y
set format y (tex ? '$10^{%L}$' : '10^{%L}')
set ylabel 'wall stiffness K [N/m]'
set xrange [-0.7:23.7]
set yrange [1e-6:3e6]
set xtics rotate by 60 right font ',14' nomirror noenhanced
set key outside top center horizontal
set bmargin 9
set title 'Largest stiffness: Tsypkin vs wedge (25) vs linear limit vs simulated oscillation onset'
# the "none" cases: the device alone, 1/(m s^2 + b s), puts H's pole at z = 1, so paper 002's
# assumption fails (open symbols); Re H tends to a finite negative limit as w -> 0, and Tsypkin's
# k* (about 1.25 N/m for every wall) is its inverse: a computed value, which the plot says
set label 5 (tex ? 'no hand: $H$ has the device'."'".'s pole at $z = 1$ (assumption violated); Tsypkin'."'".'s $k^* \approx 1.25$ N/m is $-1/\lim_{\omega\to 0} \mathrm{Re}\,H$, computed' \
              : "no hand: H has the device's pole at z = 1 (assumption violated); Tsypkin's k* = 1.25 N/m is -1/(lim Re H as w -> 0), computed") \
    at first -0.4, first 2e-2 left font note
ok(a, v) = (a == 1 && v > 0) ? v : 1/0
bad(a, v) = (a == 0 && v > 0) ? v : 1/0
pos(v) = v > 0 ? v : 1/0
plot f using 1:(pos($5)):xtic(2) with points pt 2 ps 2.2 lc rgb '#000000' title 'linear limit (1+kH)^{-1}', \
     f using 1:(pos($6)) with points pt 7 ps 1.6 lc rgb '#009E73' title 'oscillation onset (simulation)', \
     f using 1:(ok($9, $4)) with points pt 9 ps 2.2 lc rgb '#0072B2' title 'k*_{wedge} (25)', \
     f using 1:(ok($9, $3)) with points pt 5 ps 1.8 lc rgb '#D55E00' title 'k*_{Tsypkin} (21)', \
     f using 1:(bad($9, $4)) with points pt 8 ps 2.2 lc rgb '#0072B2' title 'k*_{wedge}, assumption violated', \
     f using 1:(bad($9, $3)) with points pt 4 ps 1.8 lc rgb '#D55E00' title 'k*_{Tsypkin}, assumption violated'
