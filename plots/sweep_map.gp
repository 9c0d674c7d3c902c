# plots/sweep_map.gp -- the map of a sweep (hapstab sweep plot DIR --x X --y Y --z Z): one square
# per point coloured by Z. Filled squares: certified or exact values; open squares: numeric values
# (not proven); black crosses: Z infinite (e.g. b* = inf); red x: the point failed (its row says why).
# Data: DATA/{proven,numeric,infinite,failed}.dat (x y [z]), in a private folder hapstab made;
# hapstab sets the column names xname, yname, zname and has_proven, has_numeric, has_infinite,
# has_failed (1 when that file has points: gnuplot refuses an empty data file) with gnuplot -e.
name = 'sweep_map'
if (!exists("plotdir")) plotdir = 'plots'
load plotdir.'/common.gp'
set xlabel xname noenhanced
set ylabel yname noenhanced
set cblabel zname noenhanced
set title zname.' over ('.xname.', '.yname.')' noenhanced
set key outside right top
set palette defined (0 '#440154', 1 '#3b528b', 2 '#21918c', 3 '#5ec962', 4 '#fde725')  # viridis
# the plot command of the non-empty parts; only this script's own text is evaluated
parts = ''
if (has_proven) parts = parts.", datadir.'/proven.dat' using 1:2:3 with points pt 5 ps 1.2 lc palette title 'certified / exact'"
if (has_numeric) parts = parts.", datadir.'/numeric.dat' using 1:2:3 with points pt 4 ps 1.2 lc palette title 'numeric (not proven)'"
if (has_infinite) parts = parts.", datadir.'/infinite.dat' using 1:2 with points pt 2 ps 1.2 lc rgb 'black' title zname.' = inf'"
if (has_failed) parts = parts.", datadir.'/failed.dat' using 1:2 with points pt 1 ps 1.5 lc rgb 'red' title 'failed'"
eval 'plot '.parts[3:]
