# plots/sweep_map.gp -- the map of a sweep (hapstab sweep plot DIR --x X --y Y --z Z): one cell
# per point, centred on it, filled with the colour of Z. Solid cells: certified or exact values;
# hatched cells: numeric values (not proven); grey cells: Z infinite (e.g. b* = inf); crossed
# cells: the point failed (its row says why). On a grid the cells tile the plane; the cell size
# is the smallest step between consecutive points (grid.dat, in the sweep's order).
# Data: DIR/plot-data/{proven,numeric,infinite,failed,grid}.dat (x y [z]); labels.gp holds the
# column names (and units, xunit/yunit/zunit, when known) and the plot command of the non-empty
# parts (map_plot), which draws boxes of half-widths `cx`, `cy`.
name = 'sweep_map'
if (!exists("plotdir")) plotdir = 'plots'
load plotdir.'/common.gp'
load datadir.'/labels.gp'
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
eval map_plot
