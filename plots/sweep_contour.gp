# plots/sweep_contour.gp -- contour lines of a sweep's column Z over (X, Y) (hapstab sweep plot
# --contour). The values at the grid points are the sweep's (certified or numeric, as points.csv
# says); the lines between them are gnuplot's linear interpolation, a picture, not a proof.
# Each line is coloured by its level (the colour bar) and labelled with it.
# Needs a full grid: X the slower axis, Y the faster one (each X block ends with a blank line).
# Data: DATA/grid.dat (x y z, NaN for an infinite or failed value), in a private folder hapstab
# made; hapstab sets the column names xname, yname, zname with gnuplot -e.
name = 'sweep_contour'
if (!exists("plotdir")) plotdir = 'plots'
load plotdir.'/common.gp'
unit(u) = strlen(u) > 0 ? ' ['.u.']' : ''
if (!exists("xunit")) xunit = ''
if (!exists("yunit")) yunit = ''
if (!exists("zunit")) zunit = ''
set xlabel xname.unit(xunit) noenhanced
set ylabel yname.unit(yunit) noenhanced
set cblabel zname.unit(zunit) noenhanced
set title zname.' over ('.xname.', '.yname.'): contour lines' noenhanced
stats datadir.'/grid.dat' using 1:2 nooutput
set xrange [STATS_min_x:STATS_max_x]
set yrange [STATS_min_y:STATS_max_y]
set view map
set size noratio
unset surface
set contour base
set cntrparam levels auto 10
set cntrlabel start 8 interval -1 font ',16'
set style textbox opaque noborder margins 1,1
unset key
set tics out nomirror
set grid
# viridis without its last fifth: the yellow end is unreadable as a thin line on white
set palette defined (0 '#440154', 1 '#3b528b', 2 '#21918c', 3 '#5ec962', 3.6 '#b5de2b')
splot datadir.'/grid.dat' using 1:2:3 with lines lw 2.5 palette notitle, \
      '' using 1:2:3 with labels boxed notitle
