# plots/lmi_scaling.gp -- LMI layer: solve + exact certification time against problem size for
# DSDP and CSDP, on Theorem 5's LMI structure (paper 000, (16)) with m = 2..32 DOF (environment
# of 2m states: scalar variables m(2m+1) + m(m+1)/2 + 2m, largest block 3m). Points labelled
# with m. Data: bench/chart-lmi OUTDIR (runs bench_lmi). CSDP runs in a child process (fork
# cost ~1 ms included).
name = 'lmi_scaling'
if (!exists("plotdir")) plotdir = 'plots'
load plotdir.'/common.gp'
f = datadir.'/lmi_scaling.dat'
set logscale xy
set format y (tex ? '$10^{%T}$' : '10^{%T}')
set format x (tex ? '$10^{%T}$' : '10^{%T}')
set xlabel 'scalar decision variables'
set ylabel 'solve + certify time [ms]'
set key top left
set title 'LMI scaling: Theorem 5 structure, m = 2..32 DOF'
plot f index 0 using 2:4 with linespoints ls 1 title 'DSDP', \
     f index 1 using 2:4 with linespoints ls 2 title 'CSDP', \
     f index 0 using 2:4:(sprintf('m=%d', $1)) with labels offset 0,1 notitle, \
     2 with lines ls 8 title '2 ms'
