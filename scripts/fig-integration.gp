# fig-integration.gp - integration error against n: the exact variance of the
# estimate (1/n) sum f(x_j + s) of the integral of f under a random toroidal
# shift s (cfpo-analyze's shiftvar_*, analysis/README.md), mean over the sets,
# log-log, one line per method, a panel per integrand (a disk: discontinuous;
# a periodised Gaussian: smooth), with reference slopes n^-1, n^-1.5, n^-2
# and n^-3 (grey, through the first method's value at the smallest n).
# Data: DIR/plotdata/integration.dat (scripts/bench.py replot, from
# integration.csv), one block per method: n, then a column per panel.
#   gnuplot -e "VARS='DIR/plotdata/fig-integration.vars.gp'; OUT='x.png'" scripts/fig-integration.gp
# Expects DIR, NMIN, NMAX, arrays TTL[2], COLN[2], NM, LBL[NM], COL[NM], PT[NM].
load VARS
set terminal pngcairo size 1500, 820 font "DejaVu Sans,13" enhanced
set output OUT
set multiplot layout 1, 2 title "Integration error: variance under a random toroidal shift against n (mean over the sets)" font ",16"
set logscale x 2; set logscale y 10
set format x "2^{%L}"; set format y "10^{%L}"
set xrange [NMIN / 1.3:NMAX * 1.3]
set xlabel "points n"
set ylabel "variance"
set grid lc rgb "#dddddd"
set key outside bottom center maxrows 5 font ",10" width -1
D = DIR."/plotdata/integration.dat"
do for [p = 1:2] {
  c = COLN[p]
  stats D index 0 using 1:c nooutput
  x0 = STATS_min_x; y0 = STATS_max_y
  set title TTL[p]
  plot for [i = 1:NM] D index (i - 1) using 1:c with linespoints lw 2 pt PT[i] ps 1.0 lc rgb COL[i] title LBL[i], \
       y0 * (x / x0) ** -1 with lines dt 2 lc rgb "#666666" title "n^{-1}", \
       y0 * (x / x0) ** -1.5 with lines dt 3 lc rgb "#666666" title "n^{-1.5}", \
       y0 * (x / x0) ** -2 with lines dt 4 lc rgb "#666666" title "n^{-2}", \
       y0 * (x / x0) ** -3 with lines dt 5 lc rgb "#666666" title "n^{-3}"
}
unset multiplot
