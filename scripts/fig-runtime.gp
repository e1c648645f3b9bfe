# fig-runtime.gp - the paper's figure 8: runtime against n, log-log, one line
# per method, thread count and rank count (median over seeds). Left: seconds
# until the result (iterative methods: until converged); right: seconds per
# iteration. Data: DIR/plotdata/runtime.dat (scripts/bench.py replot), one block per line:
# n_target, median seconds, median seconds per iteration, runs, median
# iterations.
#   gnuplot -e "VARS='DIR/plotdata/fig-runtime.vars.gp'; OUT='x.png'" scripts/fig-runtime.gp
load VARS
set terminal pngcairo size 1500, 780 font "DejaVu Sans,13" enhanced
set output OUT
set multiplot layout 1, 2 title "Runtime against the number of points (median over seeds; ".HOST.")" font ",16"
set logscale xy
set format x "10^{%L}"; set format y "10^{%L}"
set xlabel "points n"
set grid lc rgb "#dddddd"
set key outside bottom center maxrows 4 font ",11" width -2 height 1.5
set title "time to the result (iterative methods: until converged)"
set ylabel "seconds"
plot for [i = 1:NB] DIR."/plotdata/runtime.dat" index (i - 1) using 1:2 with linespoints lw 2 pt PT[i] ps 1.1 dt DT[i] lc rgb COL[i] title LBL[i]
set title "time per iteration (iterative methods)"
set ylabel "seconds per iteration"
plot for [i = 1:NB] DIR."/plotdata/runtime.dat" index (i - 1) using 1:(column(3) > 0 ? column(3) : NaN) with linespoints lw 2 pt PT[i] ps 1.1 dt DT[i] lc rgb COL[i] title (ITER[i] ? LBL[i] : "")
unset multiplot
