# plots/multidof_fig6.gp -- paper 000, Fig. 6: case i (one 2-DOF operator on both devices,
# nominal environment, examples/multidof_case_i_nominal.toml): velocities after a force impulse
# on d_a (a) without coupling, (b) with the coupling designed by Theorem 6, (b') with the
# paper's (27). Data: hapstab figure multidof_fig6.
name = 'multidof_fig6'
if (!exists("plotdir")) plotdir = 'plots'
stem = name
with27 = 1
figtitle = 'Fig. 6 (paper 000): case i, one operator on both devices, nominal environment'
load plotdir.'/common_velocity.gp'
