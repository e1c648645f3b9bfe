# fig-convergence.gp - the paper's figure 7: delta_min and delta_avg (relative
# to Delta(n)) against iterations for the iterative methods, mean of the sets
# (line) with the range over the sets (band). A set that has converged keeps
# its last value. Data: DIR/plotdata/convergence-KEY.dat (scripts/bench.py replot), columns
# iteration, delta_min mean/min/max, delta_avg mean/min/max, sets running.
#   gnuplot -e "VARS='DIR/plotdata/fig-convergence.vars.gp'; OUT='x.png'" scripts/fig-convergence.gp
load VARS
set terminal pngcairo size 1500, 620 font "DejaVu Sans,13" enhanced
set output OUT
set multiplot layout 1, 2 title sprintf("Convergence, %d sets of %d points (line: mean over the sets; band: range)", SETS, N) font ",16"
set logscale x
set xrange [1:*]
set xlabel "iteration (log scale)"
set grid lc rgb "#dddddd"
set key bottom right font ",12"
set style fill transparent solid 0.18 noborder
set title "minimum distance"
set ylabel "δ_{min} / Δ(n)"
set yrange [0.45:0.95]
plot for [i = 1:NM] DIR."/plotdata/convergence-".KEY[i].".dat" using 1:3:4 with filledcurves lc rgb COL[i] notitle, \
     for [i = 1:NM] DIR."/plotdata/convergence-".KEY[i].".dat" using 1:2 with lines lw 2 lc rgb COL[i] title LBL[i]
set title "average nearest-neighbour distance"
set ylabel "δ_{avg} / Δ(n)"
set yrange [0.8:0.95]
plot for [i = 1:NM] DIR."/plotdata/convergence-".KEY[i].".dat" using 1:6:7 with filledcurves lc rgb COL[i] notitle, \
     for [i = 1:NM] DIR."/plotdata/convergence-".KEY[i].".dat" using 1:5 with lines lw 2 lc rgb COL[i] title LBL[i]
unset multiplot
