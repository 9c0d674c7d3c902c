# plots/lmi_scaling.gp -- LMI layer on Theorem 5's LMI structure (paper 000, (16)) with m = 2..32
# DOF and an environment of n = m/2 + 2 states (bench/lmi.cpp), DSDP, CSDP and the built-in dense
# IPM in the same run. Data: bench/chart-lmi DATADIR (runs bench_lmi).
# (a) solve + exact certification time against the number of scalar variables. Ringed: the
#     answer did not pass the exact check; squares: DSDP stopped in trouble and Solve's CSDP
#     fallback finished (the time is both runs). CSDP runs in a child process (fork ~1 ms).
# (b) the accuracy reached: the certification margin, i.e. the smallest eigenvalue of the strict
#     LMIs at the solution in original coordinates (what the exact LDL^T check had to spare),
#     labelled with the bits of the dyadic rounding that passed. The m = 8 instance is the
#     tight one (margin ~4e-3 for every solver).
name = 'lmi_scaling'
if (!exists("plotdir")) plotdir = 'plots'
load plotdir.'/common.gp'
f = datadir.'/lmi_scaling.dat'
set multiplot layout 1,2 title (tex ? 'LMI layer: Theorem 5 structure, $m = 2..32$ DOF, $n = m/2 + 2$ states' : 'LMI layer: Theorem 5 structure, m = 2..32 DOF, n = m/2 + 2 states')
set logscale xy
set format y (tex ? '$10^{%T}$' : '10^{%T}')
set format x (tex ? '$10^{%T}$' : '10^{%T}')
set xlabel 'scalar decision variables'
set title '(a) solve + certify time'
set ylabel 'time [ms]'
set key top left Left reverse
plot f index 0 using 2:4 with linespoints ls 1 title 'DSDP', \
     f index 1 using 2:4 with linespoints ls 2 title 'CSDP', \
     f index 2 using 2:4 with linespoints ls 3 title 'built-in IPM', \
     for [i=0:2] f index i using 2:($5 == 0 ? $4 : 1/0) with points pt 6 ps 2.2 lc rgb '#000000' title (i == 0 ? 'not certified' : ''), \
     f index 0 using 2:($7 == 1 ? $4 : 1/0) with points pt 4 ps 2.2 lc rgb '#0072B2' title 'DSDP -> CSDP fallback', \
     f index 0 using 2:4:(sprintf('m=%d', $1)) with labels offset 0,1 notitle, \
     2 with lines ls 8 title '2 ms'
set title '(b) certification margin reached'
set ylabel 'min eigenvalue, strict LMIs'
set yrange [1e-3:100]
set key top right
plot f index 0 using 2:($5 == 1 ? $6 : 1/0) with linespoints ls 1 title 'DSDP', \
     f index 1 using 2:($5 == 1 ? $6 : 1/0) with linespoints ls 2 title 'CSDP', \
     f index 2 using 2:($5 == 1 ? $6 : 1/0) with linespoints ls 3 title 'built-in IPM', \
     f index 1 using 2:($5 == 1 ? $6 : 1/0):(sprintf('%d bits', $8)) with labels offset 0,-1 notitle
unset multiplot
