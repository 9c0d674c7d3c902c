# plots/sweep_line.gp -- a sweep's column Z over one axis X (hapstab sweep plot DIR --x X --z Z,
# no --y): one line per combination of the spec's other axes, in the Okabe-Ito colours. Filled
# markers: certified or exact values; open markers: numeric (not proven); triangles at the top:
# Z infinite; crosses at the bottom: the point failed. A line joins the finite values only.
# Data: DATA/line.dat (x z kind, kind 0 proven, 1 numeric, 2 infinite, 3 failed; one gnuplot
# index per line), in a private folder hapstab made; hapstab sets xlabel, ylabel, title (and
# *_tex), ngroups and group1, group2, ... (the lines' names, "B = 1/2"), zmin, zmax, xlog,
# has_numeric, has_infinite, has_failed and optionally figname with gnuplot -e.
name = exists("figname") ? figname : 'sweep_line'
if (!exists("plotdir")) plotdir = 'plots'
load plotdir.'/common.gp'
if (!exists("title")) title = ''; title_tex = ''
set xlabel (tex ? xlabel_tex : xlabel) noenhanced
set ylabel (tex ? ylabel_tex : ylabel) noenhanced
if (strlen(title) > 0) set title (tex ? title_tex : title) noenhanced
if (xlog) set logscale x
set autoscale xfix
set offsets graph 0.02, graph 0.02, 0, 0  # the end markers whole
# room above for the infinite markers and below for the failed ones
pad = 0.06 * (zmax - zmin); ytop = zmax + pad; ybot = zmin - pad
set yrange [zmin - 2*pad : zmax + 2*pad]
set tics out nomirror
# a narrow figure (--size): about one x tic per 2.5 cm (gnuplot's own step ignores label widths)
nice(x) = (e = floor(log10(x)), f = x/10.0**e, (f <= 1 ? 1 : f <= 2 ? 2 : f <= 5 ? 5 : 10) * 10.0**e)
if (exists("size_w_cm") && !xlog && size_w_cm < 14 && xlast > xfirst) { set xtics nice((xlast - xfirst) / floor(size_w_cm / 2.5)) }
set key above horizontal samplen 2 font small noenhanced
f = datadir.'/line.dat'
gname(g) = tex ? value('group'.g.'_tex') : value('group'.g)
gtitle(g) = gname(g)  # one line of a one-axis sweep: no key entry (the y label names it)
if (ngroups == 1 && strlen(group1) == 0 && !has_numeric && !has_infinite && !has_failed) unset key
fin(k, v) = (k <= 1) ? v : 1/0
parts = "for [g=1:ngroups] f index (g-1) using 1:(fin($3, $2)) with lines ls g title gtitle(g)"
parts = parts.", for [g=1:ngroups] f index (g-1) using 1:($3 == 0 ? $2 : 1/0) with points ls g pt 7 ps 1.2 notitle"
parts = parts.", for [g=1:ngroups] f index (g-1) using 1:($3 == 1 ? $2 : 1/0) with points ls g pt 6 ps 1.2 notitle"
parts = parts.", for [g=1:ngroups] f index (g-1) using 1:($3 == 2 ? ytop : 1/0) with points ls g pt 9 ps 1.5 notitle"
parts = parts.", for [g=1:ngroups] f index (g-1) using 1:($3 == 3 ? ybot : 1/0) with points lc rgb '#D55E00' pt 2 ps 1.5 notitle"
if (has_numeric) parts = parts.", keyentry with points lc rgb '#000000' pt 6 title 'numeric (not proven)'"
if (has_infinite) parts = parts.", keyentry with points lc rgb '#000000' pt 9 title 'infinite'"
if (has_failed) parts = parts.", keyentry with points lc rgb '#D55E00' pt 2 title 'failed'"
eval 'plot '.parts
