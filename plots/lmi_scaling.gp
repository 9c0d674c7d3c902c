# plots/lmi_scaling.gp -- LMI layer: solve + exact certification time against problem size for
# DSDP, CSDP and the built-in dense IPM, on Theorem 5's LMI structure (paper 000, (16)) with m = 2..32 DOF and an
# environment of n = m/2 + 2 states (bench/lmi.cpp). Points labelled with m. Data:
# bench/chart-lmi DATADIR (runs bench_lmi). CSDP runs in a child process (fork cost ~1 ms
# included); at m = 8 DSDP stops (indefinite Schur matrix) and Solve's CSDP fallback finishes.
# The built-in IPM (Solve's automatic choice up to 64 LMI rows) is ringed where its answer
# did not pass the exact check (then Solve goes on to DSDP).
name = 'lmi_scaling'
if (!exists("plotdir")) plotdir = 'plots'
load plotdir.'/common.gp'
f = datadir.'/lmi_scaling.dat'
set logscale xy
set format y (tex ? '$10^{%T}$' : '10^{%T}')
set format x (tex ? '$10^{%T}$' : '10^{%T}')
set xlabel 'scalar decision variables'
set ylabel 'solve + certify time [ms]'
set key top left Left reverse
set title (tex ? 'LMI scaling: Theorem 5 structure, $m = 2..32$ DOF, $n = m/2 + 2$ states' : 'LMI scaling: Theorem 5 structure, m = 2..32 DOF, n = m/2 + 2 states')
plot f index 0 using 2:4 with linespoints ls 1 title 'DSDP', \
     f index 1 using 2:4 with linespoints ls 2 title 'CSDP', \
     f index 2 using 2:4 with linespoints ls 3 title 'built-in IPM', \
     for [i=0:2] f index i using 2:($5 == 0 ? $4 : 1/0) with points pt 6 ps 2.2 lc rgb '#000000' title (i == 0 ? 'not certified' : ''), \
     f index 0 using 2:4:(sprintf('m=%d', $1)) with labels offset 0,1 notitle, \
     2 with lines ls 8 title '2 ms'
