# plots/passivity_fig3.gp -- paper 001, Fig. 3: an operator with a shortage of passivity eta = 0.3 N s/m
# (Re Z_O(jw) >= -eta, Sec. VII), drawn through the maps of Fig. 2, which turn its range into the
# closed unit disk once b is replaced by b - eta: (a) Z_O, (b) Z_O + b, (c) R1 = 1/(Z_O + b),
# (d) r(jw) R1 with r = T/(e^{jwT} - 1) (44), (e) 2(b - eta)/(Z_O + b) - 1. Data: hapstab figure
# passivity_fig3. Panels (a)/(b) share one scale, (e) is the unit disk; (c) keeps a margin so the
# boundary circle, which touches Re = 0, is not clipped.
# Curves: the region boundary (Re Z_O = -eta), images of the lines Re Z_O + eta = b/4, b, 3b and Im Z_O = -b, 0, b.
name = 'passivity_fig3'
if (!exists("plotdir")) plotdir = 'plots'
if (!exists("datafile")) datafile = 'passivity_fig3.dat'
load plotdir.'/common.gp'
f = datadir.'/'.datafile
unset key
set multiplot layout 2,3 title (tex ? 'Operator with shortage $\eta = 0.3$\,N\,s/m (Fig.~3): $\mathrm{Re}\,Z_O \ge -\eta$, $b = 1$\,N\,s/m' : 'Fig. 3: operator with shortage {/Symbol h} = 0.3 N s/m (Re Z_O {/Symbol \263} -{/Symbol h}), b = 1 N s/m')
set size ratio -1
set xzeroaxis ls 8
set yzeroaxis ls 8
ttl(i) = i==0 ? '(a) Z_O: Re {/Symbol \263} -{/Symbol h}' : i==1 ? '(b) Z_O + b' : i==2 ? '(c) R_1 = 1/(Z_O + b)' : i==3 ? '(d) r(j{/Symbol w}) R_1' : '(e) 2(b-{/Symbol h})/(Z_O+b) - 1'
tttl(i) = i==0 ? '(a) $Z_O$: $\mathrm{Re} \ge -\eta$' : i==1 ? '(b) $Z_O + b$' : i==2 ? '(c) $R_1 = 1/(Z_O+b)$' : i==3 ? '(d) $r(j\omega) R_1$' : '(e) $2(b-\eta)/(Z_O+b) - 1$'
unitx(i) = i<=1 ? 'Re [N s/m]' : i==2 ? 'Re [m/(N s)]' : i==3 ? 'Re [10^{-3} m/N]' : 'Re'
unity(i) = i<=1 ? 'Im [N s/m]' : i==2 ? 'Im [m/(N s)]' : i==3 ? 'Im [10^{-3} m/N]' : 'Im'
sc(i) = i==3 ? 1e3 : 1
do for [i=0:4] {
  set title (tex ? tttl(i) : ttl(i))
  set xlabel unitx(i)
  set ylabel unity(i)
  set xtics autofreq; set ytics autofreq
  if (i <= 1) { set xrange [-1.5:5]; set yrange [-3.5:3.5] }
  if (i == 2) { set xrange [-0.25:1.6]; set yrange [-0.9:0.9]; set xtics 0.5; set ytics 0.5 }
  if (i == 3) { set autoscale xy; set xtics 0.5; set ytics 0.5 }
  if (i == 4) { set xrange [-1.3:1.3]; set yrange [-1.3:1.3] }
  # the operator's range (Re Z_O >= -eta), shaded as in the paper's Fig. 3
  unset object 1
  if (i <= 1) { set object 1 rect from (i == 0 ? -0.3 : 0.7), graph 0 to graph 1, graph 1 fc rgb word(pal, 1) fs transparent solid 0.12 noborder behind }
  s = sc(i)
  plot f index i using ($1*s):($3==1 ? $2*s : 1/0) with lines ls 2 lw 1, \
       f index i using ($1*s):($3==2 ? $2*s : 1/0) with lines ls 3 lw 1, \
       f index i using ($1*s):($3==0 ? $2*s : 1/0) with lines ls 1 lw 3
}
# legend panel
set title ''
unset object 1
unset border; unset tics; unset xlabel; unset ylabel; unset grid; unset xzeroaxis; unset yzeroaxis
set key center center box
set xrange [0:1]; set yrange [0:1]
plot 2 ls 1 lw 3 title (tex ? 'boundary $\mathrm{Re}\,Z_O = -\eta$' : 'boundary Re Z_O = -{/Symbol h}'), \
     NaN with boxes fc rgb word(pal, 1) fs transparent solid 0.12 noborder title (tex ? 'range of $Z_O$ (a), (b)' : 'range of Z_O in (a), (b)'), \
     2 ls 2 lw 1 title (tex ? '$\mathrm{Re}\,Z_O + \eta = b/4,\ b,\ 3b$' : 'Re Z_O + {/Symbol h} = b/4, b, 3b'), \
     2 ls 3 lw 1 title (tex ? '$\mathrm{Im}\,Z_O = -b,\ 0,\ b$' : 'Im Z_O = -b, 0, b')
unset multiplot
