# plots/multidof_fig7.gp -- paper 000, Fig. 7: case ii (one operator per device, perturbed
# environment, examples/multidof_case_ii_perturbed.toml): velocities after a force impulse on d_a
# (a) without coupling, (b) with the coupling designed by Theorem 6.
# Data: hapstab figure multidof_fig7.
name = 'multidof_fig7'
if (!exists("plotdir")) plotdir = 'plots'
stem = name
figtitle = 'Fig. 7 (paper 000): case ii, an operator per device, perturbed environment'
load plotdir.'/common_velocity.gp'
