# Paper 002, experiment 3: an operator pressing on a sampled virtual wall with a bias force.
# Data: `hapstab figure sim_bias_wall` (runs examples/002_bias_wall.toml). The full sampled-data
# model's position between samples (exact ZOH), its samples, and the reduced discrete model of
# paper 002 Fig. 2 (contact/limit_cycle.hpp) on the same instants: the samples agree; the
# reduction drops the motion between them (the penetration peaks and the release instants).
name = 'sim_bias_wall'
if (!exists("plotdir")) plotdir = 'plots'
load plotdir.'/common.gp'
set xlabel (tex ? '$t$ [s]' : 't [s]')
set ylabel (tex ? '$x$ [mm] (wall at $x>0$)' : 'x [mm]  (the wall occupies x > 0)')
set title 'limit cycle at a sampled wall'
set key top right
set autoscale xfix  # the axis ends with the data
plot datadir.'/sim_bias_wall_fine.dat' using 1:($2*1000) with lines ls 1 title 'full model, between samples', \
     datadir.'/sim_bias_wall_samples.dat' using 1:($2*1000) with points ls 1 pt 7 title 'full model at kT', \
     datadir.'/sim_bias_wall_samples.dat' using 1:($3*1000) with points ls 2 pt 6 ps 1.6 title 'reduced model (Fig. 2)', \
     0 with lines ls 7 notitle
