# plots/lmi_scaling.gp -- LMI layer on Theorem 5's LMI structure (paper 000, (16)) with m = 2..32
# DOF and an environment of n = m/2 + 2 states (bench/lmi.cpp), DSDP, CSDP and the built-in dense
# IPM in the same run. Data: bench/chart-lmi DATADIR (runs bench_lmi); `timing` (the machine and
# its load during the run) comes from `hapstab figure` (cli/figure.hpp, bench_timing_vars).
# (a) solve + exact certification time against the number of scalar variables (m on the top
#     axis), with the solvers' key as in (b). Ringed: the answer did not pass the exact check; squares: DSDP stopped in trouble and
#     Solve's CSDP fallback finished (the time is both runs); diamonds: the solver did not report
#     success, the exact check passed anyway. CSDP runs in a child process (fork ~1 ms). The
#     dotted line is issue 5's target, 2 ms at Theorem 5's own size (43 variables, 10x10 blocks).
# (b) the accuracy reached: the certification margin, i.e. the smallest eigenvalue of the strict
#     LMIs at the solution in original coordinates (what the exact LDL^T check had to spare). The
#     bits of the dyadic rounding that passed are named once when they are the same everywhere,
#     else written at each point. The m = 8 instance is the tight one (margin ~4e-3 for every solver).
# Marker kinds with no point in the data get no key entry.
name = 'lmi_scaling'
if (!exists("plotdir")) plotdir = 'plots'
wide = 1  # three / two panels: the PDF and LaTeX versions get a two-column canvas
load plotdir.'/common.gp'
if (!exists("timing")) { timing = ''; timing_tex = '' }
f = datadir.'/lmi_scaling.dat'
# which special cases occur, over all three solvers (block i = solver i)
n_uncert = 0; n_fallback = 0; n_status = 0
do for [i=0:2] {
  stats f index i using ($5 == 0 ? 1 : 0) name 'S' nooutput; n_uncert = n_uncert + int(S_sum)
  stats f index i using ($5 == 1 && $9 == 0 ? 1 : 0) name 'S' nooutput; n_status = n_status + int(S_sum)
}
stats f index 0 using ($7 == 1 ? 1 : 0) name 'S' nooutput; n_fallback = int(S_sum)
bits_min = 1e9; bits_max = -1
do for [i=0:2] {
  stats f index i using ($5 == 1 ? $8 : 1/0) name 'B' nooutput
  if (B_records > 0) { bits_min = (B_min < bits_min ? B_min : bits_min); bits_max = (B_max > bits_max ? B_max : bits_max) }
}
same_bits = (bits_max >= 0 && bits_min == bits_max)
set multiplot layout 1,2 margins 7.5*emx, 1 - 2*emx, 7.5*emy, 1 - 9*emy spacing 7.5*emx \
  title (tex ? 'LMI layer: Theorem 5 structure, $m = 2..32$ DOF, $n = m/2 + 2$ states; one core per solve' : 'LMI layer: Theorem 5 structure, m = 2..32 DOF, n = m/2 + 2 states; one core per solve')
set logscale xy
set format y (tex ? '$10^{%T}$' : '10^{%T}')
set format x (tex ? '$10^{%T}$' : '10^{%T}')
set xrange [8:1200]
set xlabel 'scalar decision variables'
# the top axis names m at each problem's size
set logscale x2
set x2range [8:1200]
set x2tics scale 0.5 out nomirror
set xtics nomirror
set x2label 'm (DOF)' offset 0,-0.5
set title '(a) solve + certify time'
set ylabel 'time [ms]'
# from a decade at least a factor 2 below the fastest solve (an idle machine's built-in IPM takes
# under 1 ms at m = 2: a fixed bottom of 1 ms cut it off) to 1e6 ms
tmin = 1e9
do for [i=0:2] { stats f index i using 4 name 'T' nooutput; tmin = (T_min < tmin ? T_min : tmin) }
ybot = 10**floor(log10(tmin) - 0.3)  # at least a factor 2 below the fastest: no marker on the edge
set yrange [(ybot < 1 ? ybot : 1):1e6]
# the key top left, above every curve (short texts: it must end before 200 variables)
set key top left Left reverse font note spacing 1.0 samplen 1.5
if (strlen(timing) > 0) { set label 99 (tex ? timing_tex : timing) at screen 0.01, screen 0.02 left font note }
plot f index 0 using 2:4:x2tic(sprintf('%d', $1)) with linespoints ls 1 pt 6 ps 2.4 title 'DSDP', \
     f index 1 using 2:4 with linespoints ls 2 pt 5 ps 1.5 title 'CSDP', \
     f index 2 using 2:4 with linespoints ls 3 pt 9 ps 1.0 title 'built-in IPM', \
     for [i=0:2] f index i using 2:($5 == 0 ? $4 : 1/0) with points pt 6 ps 2.6 lw 2 lc rgb '#000000' \
        title (i == 0 && n_uncert > 0 ? 'not certified' : ''), \
     for [i=0:2] f index i using 2:($5 == 1 && $9 == 0 ? $4 : 1/0) with points pt 12 ps 2.6 lw 2 lc rgb '#000000' \
        title (i == 0 && n_status > 0 ? 'solver failed, exact check passed' : ''), \
     f index 0 using 2:($7 == 1 ? $4 : 1/0) with points pt 4 ps 2.6 lw 2 lc rgb word(pal, 1) \
        title (n_fallback > 0 ? 'DSDP, then CSDP (both timed)' : ''), \
     2 with lines ls 8 lw 2 title 'target 2 ms (43 variables)'
unset label 99
set title '(b) certification margin'.(same_bits ? sprintf(' (all %d-bit rounding)', bits_min) : '')
set ylabel (tex ? '$\lambda_{\min}$ of the strict LMIs' : '{/Symbol l}_{min} of the strict LMIs')
set yrange [1e-3:100]
set key top right Left reverse font small
plot f index 0 using 2:($5 == 1 ? $6 : 1/0):x2tic(sprintf('%d', $1)) with linespoints ls 1 pt 6 ps 2.4 title 'DSDP', \
     f index 1 using 2:($5 == 1 ? $6 : 1/0) with linespoints ls 2 pt 5 ps 1.5 title 'CSDP', \
     f index 2 using 2:($5 == 1 ? $6 : 1/0) with linespoints ls 3 pt 9 ps 1.0 title 'built-in IPM', \
     f index 1 using 2:($5 == 1 && !same_bits ? $6 : 1/0):(sprintf('%d bits', $8)) with labels offset 0,-1.2 notitle
unset multiplot
