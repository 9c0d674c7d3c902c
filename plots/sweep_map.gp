# plots/sweep_map.gp -- the map of a sweep (hapstab sweep plot DIR --x X --y Y --z Z): one square
# per point coloured by Z. Filled squares: certified or exact values; open squares: numeric values
# (not proven); black crosses: Z infinite (e.g. b* = inf); red x: the point failed (its row says why).
# Data: DIR/plot-data/{proven,numeric,infinite,failed}.dat (x y [z]); labels.gp holds the column
# names and the plot command of the non-empty parts (map_plot).
name = 'sweep_map'
if (!exists("plotdir")) plotdir = 'plots'
load plotdir.'/common.gp'
load datadir.'/labels.gp'
set xlabel xname noenhanced
set ylabel yname noenhanced
set cblabel zname noenhanced
set title zname.' over ('.xname.', '.yname.')' noenhanced
set key outside right top
set palette defined (0 '#440154', 1 '#3b528b', 2 '#21918c', 3 '#5ec962', 4 '#fde725')  # viridis
eval map_plot
