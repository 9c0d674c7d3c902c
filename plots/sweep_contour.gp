# plots/sweep_contour.gp -- contour lines of a sweep's column Z over (X, Y) (hapstab sweep plot
# --contour). The values at the grid points are the sweep's (certified or numeric, as points.csv
# says); the lines between them are gnuplot's linear interpolation, a picture, not a proof.
# Needs a full grid: X the slower axis, Y the faster one (each X block ends with a blank line).
# Data: DATA/grid.dat (x y z, NaN for an infinite or failed value), in a private folder hapstab
# made; hapstab sets the column names xname, yname, zname with gnuplot -e.
name = 'sweep_contour'
if (!exists("plotdir")) plotdir = 'plots'
load plotdir.'/common.gp'
set xlabel xname noenhanced
set ylabel yname noenhanced
set title zname.' over ('.xname.', '.yname.'): contour lines' noenhanced
set view map
set size noratio
unset surface
set contour base
set cntrparam levels auto 10
set key outside right top
splot datadir.'/grid.dat' using 1:2:3 with lines lw 2 title zname.' ='  # each level: its own line type and key entry
