# plots/common_velocity.gp -- the velocity panels shared by paper 000's Fig. 6 and Fig. 7
# (loaded by multidof_fig6.gp / multidof_fig7.gp, which set name, stem and the panel titles).
# Data: datadir/STEM_none.dat, STEM_designed.dat, STEM_paper27.dat with columns t v_1 ... v_N
# (the closed loop's device velocities after a force impulse on d_a, exact-ZOH simulation).
load plotdir.'/common.gp'
panels = exists("with27") ? 3 : 2
set multiplot layout 1,panels title figtitle
set xlabel 't [s]'
set ylabel 'v [m/s]'
set key top right
set title '(a) no virtual coupling'
plot datadir.'/'.stem.'_none.dat' u 1:2 w l ls 1 t (tex ? '$v_1$ ($d_a$)' : 'v_1 (d_a)'), \
     '' u 1:3 w l ls 2 t (tex ? '$v_2$ ($d_b$)' : 'v_2 (d_b)')
set title '(b) designed V (Theorem 6)'
plot datadir.'/'.stem.'_designed.dat' u 1:2 w l ls 1 t (tex ? '$v_1$' : 'v_1'), \
     '' u 1:3 w l ls 2 t (tex ? '$v_2$' : 'v_2')
if (panels == 3) {
  set title "(b') the paper's V (27)"
  plot datadir.'/'.stem.'_paper27.dat' u 1:2 w l ls 1 t (tex ? '$v_1$' : 'v_1'), \
       '' u 1:3 w l ls 2 t (tex ? '$v_2$' : 'v_2')
}
unset multiplot
