# bench/sweep_throughput.gp -- hapstab sweep's throughput on the 1000 x 1000 (K, B) map of the
# delayed backward-difference wall: points per second on N nodes of 2 cores, extrapolated from the
# per-shard CPU time of a 50 x 50 run (shards share nothing) plus the one-process merge, certified
# (30 digits) and fast; the markers are the throughputs measured with --jobs 1 and 2 on one machine
# (at N = 1/2 and 1 node). The merge bounds the speed-up at many nodes.
# Data: bench/sweep-overhead --datadir DIR (DIR/sweep_throughput.dat). Not in plots/: no figure of
# hapstab reproduce (it needs the benchmark run); draw it with
#   gnuplot -e "plotdir='plots'; datadir='DIR'; outdir='DIR'; fmt='png'" bench/sweep_throughput.gp
name = 'sweep_throughput'
if (!exists("plotdir")) plotdir = 'plots'
load plotdir.'/common.gp'
f = datadir.'/sweep_throughput.dat'
set xlabel 'nodes (2 cores each)'
set ylabel 'points per second'
set title 'hapstab sweep: 10^6-point (K, B) map, extrapolated from per-shard CPU time' noenhanced
set logscale xy
set xrange [0.35:200]
set format y '%g'
set key left top
plot f index 0 using 1:2 with linespoints ls 1 title 'certified, extrapolated', \
     f index 0 using 1:3 with linespoints ls 2 title 'fast, extrapolated', \
     f index 1 using 1:2 with points ls 1 pt 6 ps 2 title 'certified, measured (--jobs 1, 2)', \
     f index 1 using 1:3 with points ls 2 pt 4 ps 2 title 'fast, measured (--jobs 1, 2)'
