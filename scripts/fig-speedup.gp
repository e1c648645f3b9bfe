# fig-speedup.gp - parallel speedup of CFPO (the paper's figure 9): the
# median time on 1 thread and 1 rank over the median time on the
# configuration, same n and method. Left: against the cores used (threads x
# ranks), one line per method, n and rank count, with the ideal line; right:
# against n, one line per configuration. Data: DIR/plotdata/speedup-cores.dat
# and speedup-n.dat (scripts/bench.py replot).
#   gnuplot -e "VARS='DIR/plotdata/fig-speedup.vars.gp'; OUT='x.png'" scripts/fig-speedup.gp
load VARS
set terminal pngcairo size 1500, 760 font "DejaVu Sans,13" enhanced
set output OUT
set multiplot layout 1, 2 title "Speedup of CFPO over one thread (time until converged; ".HOST.")" font ",16"
set grid lc rgb "#dddddd"
set key outside bottom center maxrows 4 font ",11" width -2 height 1.5
set title "against cores used"
set xlabel "cores used (threads × ranks)"
set ylabel "speedup"
set xrange [0.8:MAXC * 1.05 + 0.2]
set yrange [0:MAXC * 1.1 + 0.2]
set xtics 1
plot x with lines dt 2 lc rgb "#888888" title "ideal", \
     for [i = 1:NA] DIR."/plotdata/speedup-cores.dat" index (i - 1) using 1:2 with linespoints lw 2 pt PTA[i] ps 1.1 dt DTA[i] lc rgb COLA[i] title LBLA[i]
set title "against the number of points"
set xlabel "points n"
set logscale x
set format x "10^{%L}"
set xrange [*:*]; set xtics auto
plot for [i = 1:NBB] DIR."/plotdata/speedup-n.dat" index (i - 1) using 1:2 with linespoints lw 2 pt PTB[i] ps 1.1 dt DTB[i] lc rgb COLB[i] title LBLB[i]
unset multiplot
