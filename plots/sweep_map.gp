# plots/sweep_map.gp -- the map of a sweep (hapstab sweep plot DIR --x X --y Y --z Z): one cell
# per point, centred on it, filled with the colour of Z. Solid cells: certified or exact values;
# hatched cells: numeric values (not proven); grey cells: Z infinite (e.g. b* = inf); crossed
# cells: the point failed (its row says why). On a grid the cells tile the plane; the cell size
# is the smallest step between consecutive points (grid.dat, in the sweep's order).
# Data: DATA/{proven,numeric,infinite,failed,grid}.dat (x y [z]), in a private folder hapstab
# made; hapstab sets the column names xname, yname, zname (units xunit, yunit, zunit when known)
# and has_proven, has_numeric, has_infinite, has_failed (1 when that file has points: gnuplot
# refuses an empty data file) with gnuplot -e. Cells are boxes of half-widths `cx`, `cy`.
name = 'sweep_map'
if (!exists("plotdir")) plotdir = 'plots'
load plotdir.'/common.gp'
unit(u) = strlen(u) > 0 ? ' ['.u.']' : ''
if (!exists("xunit")) xunit = ''
if (!exists("yunit")) yunit = ''
if (!exists("zunit")) zunit = ''
set xlabel xname.unit(xunit) noenhanced
set ylabel yname.unit(yunit) noenhanced
set cblabel zname.unit(zunit) noenhanced
set title zname.' over ('.xname.', '.yname.')' noenhanced
# the cell: the smallest non-zero step in x and in y between consecutive points
dx = 1e300; dy = 1e300; px = NaN; py = NaN
stats datadir.'/grid.dat' using (ax = abs($1 - px), (ax > 0 && ax < dx ? dx = ax : 0), ay = abs($2 - py), \
      (ay > 0 && ay < dy ? dy = ay : 0), px = $1, py = $2, $1):2 nooutput
xlo = STATS_min_x; xhi = STATS_max_x; ylo = STATS_min_y; yhi = STATS_max_y
if (dx > 1e299) dx = (xhi > xlo) ? (xhi - xlo) / 10 : 1
if (dy > 1e299) dy = (yhi > ylo) ? (yhi - ylo) / 10 : 1
cx = 0.51 * dx; cy = 0.51 * dy   # the half-widths of a cell: 2% overlap, no hairline seams
set xrange [xlo - dx/2 : xhi + dx/2]
set yrange [ylo - dy/2 : yhi + dy/2]
set tics out nomirror
set grid noxtics noytics
set key at screen 0.5, screen 0.01 center bottom horizontal samplen 1.5
set bmargin 6
set style fill solid 1.0 noborder
set palette defined (0 '#440154', 1 '#3b528b', 2 '#21918c', 3 '#5ec962', 4 '#fde725')  # viridis
# the plot command of the non-empty parts; only this script's own text is evaluated
parts = ''
if (has_proven) parts = parts.", datadir.'/proven.dat' using 1:2:(cx):(cy):3 with boxxyerror fs solid 1.0 noborder fc palette title 'certified / exact'"
if (has_numeric) parts = parts.", datadir.'/numeric.dat' using 1:2:(cx):(cy):3 with boxxyerror fs pattern 4 border lc palette fc palette title 'numeric (not proven)'"
if (has_infinite) parts = parts.", datadir.'/infinite.dat' using 1:2:(cx):(cy) with boxxyerror fs solid 1.0 noborder fc rgb '#999999' title zname.' = inf'"
if (has_failed) parts = parts.", datadir.'/failed.dat' using 1:2:(cx):(cy) with boxxyerror fs pattern 5 border lc rgb '#D55E00' fc rgb '#D55E00' title 'failed'"
eval 'plot '.parts[3:]
