# plots/sweep_map.gp -- the map of a sweep (hapstab sweep plot DIR --x X --y Y --z Z): one cell
# per point, filled with the colour of Z. Solid cells: certified or exact values; hatched cells:
# numeric values (not proven); grey cells: Z infinite (e.g. b* = inf); crossed cells: the point
# failed (its row says why). A cell reaches halfway to each neighbouring value of its axis
# (geometric halfway on a log axis): cells as wide as their gaps; an axis the spec lists
# (values = [0, 1/2, 5, 20]) gets one equal row or column per value, labelled with it (xtics,
# ytics), so 0 and 1/2 stay apart. The colour bar spans the finite values exactly (zmin, zmax).
# Data: DATA/{proven,numeric,infinite,failed}.dat (x y xlo xhi ylo yhi [z]) and grid.dat (x y z, for
# --levels), in a private folder hapstab made. hapstab sets with gnuplot -e: xlabel, ylabel, zlabel,
# title (text, and *_tex for LaTeX), zmin, zmax, xmin..ymax (the cells' outer edges), xlog, ylog,
# has_proven, has_numeric, has_infinite, has_failed (gnuplot refuses an empty data file), and
# optionally levels (level lines over the map: 'auto N' or 'discrete a,b,...') and figname.
name = exists("figname") ? figname : 'sweep_map'
if (!exists("plotdir")) plotdir = 'plots'
load plotdir.'/common.gp'
if (!exists("title")) title = ''; title_tex = ''
set xlabel (tex ? xlabel_tex : xlabel) noenhanced
set ylabel (tex ? ylabel_tex : ylabel) noenhanced
set cblabel (tex ? zlabel_tex : zlabel) noenhanced
if (strlen(title) > 0) set title (tex ? title_tex : title) noenhanced
if (xlog) set logscale x
if (ylog) set logscale y
set xrange [xmin:xmax]
set yrange [ymin:ymax]
set cbrange [zmin:zmax]
set tics out nomirror
# a narrow figure (--size): about one x tic per 2.5 cm (gnuplot's own step ignores label widths)
nice(x) = (e = floor(log10(x)), f = x/10.0**e, (f <= 1 ? 1 : f <= 2 ? 2 : f <= 5 ? 5 : 10) * 10.0**e)
if (exists("size_w_cm") && !xlog && !exists("xtics") && size_w_cm < 14 && xmax > xmin) { set xtics nice((xmax - xmin) / floor(size_w_cm / 2.5)) }
# a listed axis (values = [...]): one equal column or row per value, labelled with it
if (exists("xtics")) { eval 'set xtics '.xtics; set xtics scale 0 }
if (exists("ytics")) { eval 'set ytics '.ytics; set ytics scale 0 }
set grid noxtics noytics
set key at screen 0.5, screen 0.01 center bottom horizontal samplen 1.5 font small
set bmargin 6
set palette defined (0 '#440154', 1 '#3b528b', 2 '#21918c', 3 '#5ec962', 4 '#fde725')  # viridis
set style textbox opaque noborder margins 0.5,0.5
# the level lines, computed by gnuplot's contouring into a table first
if (exists("levels")) {
  set view map; unset surface; set contour base
  eval 'set cntrparam levels '.levels
  set table datadir.'/levels.dat'
  splot datadir.'/grid.dat' using 1:2:3 with lines
  unset table
  unset contour; set surface
}
# the plot command of the non-empty parts; only this script's own text is evaluated
parts = ''
if (has_proven) parts = parts.", datadir.'/proven.dat' using 1:2:3:4:5:6:7 with boxxyerror fs solid 1.0 noborder fc palette title 'certified / exact'"
if (has_numeric) parts = parts.", datadir.'/numeric.dat' using 1:2:3:4:5:6:7 with boxxyerror fs pattern 4 border lc palette fc palette title 'numeric (not proven)'"
if (has_infinite) parts = parts.", datadir.'/infinite.dat' using 1:2:3:4:5:6 with boxxyerror fs solid 1.0 noborder fc rgb '#999999' title 'infinite'"
if (has_failed) parts = parts.", datadir.'/failed.dat' using 1:2:3:4:5:6 with boxxyerror fs pattern 5 border lc rgb '#D55E00' fc rgb '#D55E00' title 'failed'"
if (exists("levels")) parts = parts.", datadir.'/levels.dat' using 1:2 with lines lc rgb '#ffffff' lw 4 notitle, '' using 1:2 with lines lc rgb '#000000' lw 1.5 title 'level lines', '' using 1:2:(sprintf('%g', $3)) every ::2::2 with labels boxed font small textcolor rgb '#000000' notitle"
eval 'plot '.parts[3:]
