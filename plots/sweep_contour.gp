# plots/sweep_contour.gp -- contour lines of a sweep's column Z over (X, Y) (hapstab sweep plot
# --contour). The values at the grid points are the sweep's (certified or numeric, as points.csv
# says); the lines between them are gnuplot's linear interpolation, a picture, not a proof.
# Each line is coloured by its level (the colour bar) and labelled with it.
# Needs a full grid: X the slower axis, Y the faster one (each X block ends with a blank line).
# Data: DATA/grid.dat (x y z, NaN for an infinite or failed value), in a private folder hapstab
# made; hapstab sets xlabel, ylabel, zlabel, title (and *_tex), xfirst, xlast, yfirst, ylast,
# xlog, ylog, zmin, zmax, optionally levels ('auto N' or 'discrete a,b,...'; default auto 10)
# and figname with gnuplot -e.
name = exists("figname") ? figname : 'sweep_contour'
if (!exists("plotdir")) plotdir = 'plots'
load plotdir.'/common.gp'
if (!exists("title")) title = ''; title_tex = ''
set xlabel (tex ? xlabel_tex : xlabel) noenhanced
set ylabel (tex ? ylabel_tex : ylabel) noenhanced
set cblabel (tex ? zlabel_tex : zlabel) noenhanced
if (strlen(title) > 0) set title (tex ? title_tex : title) noenhanced
if (xlog) set logscale x
if (ylog) set logscale y
set xrange [xfirst:xlast]
set yrange [yfirst:ylast]
set cbrange [zmin:zmax]
set view map
set size noratio
unset surface
set contour base
if (exists("levels")) { eval 'set cntrparam levels '.levels } else { set cntrparam levels auto 10 }
set cntrlabel start 2 interval -1 font small
set style textbox opaque noborder margins 1,1
unset key
set tics out nomirror
# a narrow figure (--size): about one x tic per 2.5 cm (gnuplot's own step ignores label widths)
nice(x) = (e = floor(log10(x)), f = x/10.0**e, (f <= 1 ? 1 : f <= 2 ? 2 : f <= 5 ? 5 : 10) * 10.0**e)
if (exists("size_w_cm") && !xlog && size_w_cm < 14 && xlast > xfirst) { set xtics nice((xlast - xfirst) / floor(size_w_cm / 2.5)) }
set grid
# viridis without its last fifth: the yellow end is unreadable as a thin line on white
set palette defined (0 '#440154', 1 '#3b528b', 2 '#21918c', 3 '#5ec962', 3.6 '#b5de2b')
splot datadir.'/grid.dat' using 1:2:3 with lines lw 2.5 palette notitle, \
      '' using 1:2:3 with labels boxed notitle
