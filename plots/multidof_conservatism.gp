# plots/multidof_conservatism.gp -- how conservative Theorem 5 of paper 000 is (issue 42): in the
# plane (environment gain g: E := g E; coupling stiffness kc: V = V27 / kc, (27) of Sec. VI), the
# largest kc for which the loop as written is stable (certified decide_loop verdicts: stable at
# the lower end, NOT stable at the upper; the family is not affine in kc, so this is a change of
# verdict, not a proven supremum) and the largest for which Theorem 5 concludes (Theorem 4 with
# that coupling, Assumption 1, hidden modes; certified ends), on the four Sec. VI scenes and the
# contact scenes N = 2, 4, 8 (g = 1, 10 there: their cost); a triangle: stable at every kc tried (up
# to 64000). Points: the loop simulated 10 s after a force impulse (numeric): circle = velocities
# decay, cross = they do not. Panel titles: the ratio of the boundaries (not of suprema: neither
# region is proven an interval in kc) exact / Theorem 5 at g = 1. Data: hapstab figure multidof_conservatism --out DIR.
name = 'multidof_conservatism'
if (!exists("plotdir")) plotdir = 'plots'
wide = 1
tall = 1
load plotdir.'/common.gp'
if (!exists("title0")) { title0 = 'case i nominal'; title1 = 'case i perturbed'; title2 = 'case ii nominal'; \
  title3 = 'case ii perturbed'; title4 = 'contact N = 2'; title5 = 'contact N = 4'; title6 = 'contact N = 8' }
if (!exists("sub0")) { sub0 = ''; sub1 = ''; sub2 = ''; sub3 = ''; sub4 = ''; sub5 = ''; sub6 = '' }
nan(v) = (v == v) ? v : 1/0
set logscale xy
set xrange [0.05:20]
set yrange [300:1e5]
set format y (tex ? '$10^{%L}$' : '10^{%L}')
set format x (tex ? '$10^{%L}$' : '10^{%L}')
set xtics font small
set ytics font small
unset key
set multiplot layout 2,4 title (tex ? 'Largest coupling stiffness $k_c$ ($V = V_{27}/k_c$): exact vs Theorem 5 (ratio of the boundaries at g = 1)' \
                                    : 'Largest coupling stiffness k_c (V = V_{27}/k_c): exact vs Theorem 5 (ratio of the boundaries at g = 1)')
do for [k=0:6] {
  f = datadir.'/'.name.'_'.k.'.dat'
  s = datadir.'/'.name.'_'.k.'_sim.dat'
  t = value('title'.k)."\n".value('sub'.k)
  set title t font small noenhanced
  set xlabel (k >= 4 ? (tex ? 'environment gain $g$' : 'environment gain g') : '') font small
  set ylabel ((k % 4) == 0 ? (tex ? '$k_c$ [1]' : 'k_c') : '') font small
  plot f using 1:(nan($2)) with filledcurves x1 fc rgb '#cde8d8' notitle, \
       f using 1:(nan($4)) with filledcurves x1 fc rgb '#9cc7e6' notitle, \
       f using 1:(nan($2)) with linespoints ls 3 pt 7 ps 1.2 notitle, \
       f using 1:(valid(3) ? 1/0 : $2) with points pt 9 ps 2.4 lc rgb '#009E73' notitle, \
       f using 1:(nan($4)) with linespoints ls 2 dt 2 pt 5 ps 1.2 notitle, \
       s using 1:($3 == 1 ? $2 : 1/0) with points pt 6 ps 1.4 lc rgb '#000000' notitle, \
       s using 1:($3 == 0 ? $2 : 1/0) with points pt 2 ps 1.6 lc rgb '#CC79A7' notitle
}
# the eighth slot: the key
unset title; unset xlabel; unset ylabel; unset tics; unset border; unset grid
set lmargin 1; set rmargin 1
set key left center reverse Left box opaque font small spacing 1.3 samplen 1.2
unset logscale; set xrange [0:1]; set yrange [0:1]
plot 0.5 with dots lc rgb '#ffffff' notitle, \
     keyentry with boxes fs solid fc rgb '#cde8d8' title 'stable (certified)', \
     keyentry with boxes fs solid fc rgb '#9cc7e6' title 'Thm 5 concludes', \
     keyentry with linespoints ls 3 pt 7 title 'exact boundary', \
     keyentry with points pt 9 ps 2.2 lc rgb '#009E73' title 'stable to 64000', \
     keyentry with linespoints ls 2 dt 2 pt 5 title 'Thm 5 boundary', \
     keyentry with points pt 6 ps 1.4 lc rgb '#000000' title 'sim. 10 s: decays', \
     keyentry with points pt 2 ps 1.6 lc rgb '#CC79A7' title 'sim.: not decayed'
unset multiplot
