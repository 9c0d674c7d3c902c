# plots/multidof_fig67.gp -- paper 000 Fig. 6 (case i) and Fig. 7 (case ii): velocity vector
# response to a force impulse on device d_a, (a) without coupling, (b) with a stabilising
# coupling (the designed V of Theorem 6, and the paper's (27)). Data:
#   hapstab multidof figure --scene examples/multidof_case_i_nominal.toml --out DIR
#   hapstab multidof figure --scene examples/multidof_case_ii_perturbed.toml --out DIR
# then: gnuplot -e "datadir='DIR'; stem='multidof_case_i_nominal'" plots/multidof_fig67.gp
if (!exists("datadir")) datadir = "."
if (!exists("stem")) stem = "multidof_case_i_nominal"
if (!exists("outfile")) outfile = datadir."/".stem."_velocity.png"
set terminal pngcairo size 1200,420 font ",11"
set output outfile
set multiplot layout 1,3
set xlabel "t [s]"
set ylabel "v [m/s]"
set key top right
set title "(a) no coupling"
plot datadir."/".stem."_none.dat" u 1:2 w l t "v_1", "" u 1:3 w l t "v_2"
set title "(b) designed V (Theorem 6)"
plot datadir."/".stem."_designed.dat" u 1:2 w l t "v_1", "" u 1:3 w l t "v_2"
set title "(b') paper's V (27)"
plot datadir."/".stem."_paper27.dat" u 1:2 w l t "v_1", "" u 1:3 w l t "v_2"
unset multiplot
