# fig-time-to-quality.gp - time to quality: delta_min (top) and delta_avg
# (bottom), relative to Delta(n), against wall-clock seconds since the start
# of the run (the trace's elapsed column), log x; one column of panels per
# n, one curve per method and thread count (its median run over the seeds);
# dashed grey lines: the quality target. Data: DIR/plotdata/ttq-nN.dat
# (scripts/benchlib/ttq.py), one block per curve: elapsed, delta_min, delta_avg.
#   gnuplot -e "VARS='DIR/plotdata/fig-time-to-quality.vars.gp'; OUT='x.png'" scripts/fig-time-to-quality.gp
load VARS
set terminal pngcairo size (NP > 1 ? 760 * NP : 900), 1100 font "DejaVu Sans,13" enhanced
set output OUT
set multiplot layout 2, NP title "Time to quality (median run of each configuration; dashed: the target)" font ",16"
set logscale x
set format x "10^{%L}"
set grid lc rgb "#dddddd"
set key bottom right font ",11"
set xlabel "seconds since the start (log scale)"
do for [p = 1:NP] {
  set title sprintf("n = %d: minimum distance", PN[p])
  set ylabel "δ_{min} / Δ(n)"
  set yrange [0.80:0.935]
  plot for [j = 1:PC[p]] DIR.sprintf("/plotdata/ttq-n%d.dat", PN[p]) index (j - 1) using 1:2 with lines lw 2 \
         dt DT[PS[p] + j - 1] lc rgb COL[PS[p] + j - 1] title LBL[PS[p] + j - 1], \
       TMIN with lines dt 2 lw 1.5 lc rgb "#555555" notitle
}
do for [p = 1:NP] {
  set title sprintf("n = %d: average nearest-neighbour distance", PN[p])
  set ylabel "δ_{avg} / Δ(n)"
  set yrange [0.88:0.94]
  plot for [j = 1:PC[p]] DIR.sprintf("/plotdata/ttq-n%d.dat", PN[p]) index (j - 1) using 1:3 with lines lw 2 \
         dt DT[PS[p] + j - 1] lc rgb COL[PS[p] + j - 1] title LBL[PS[p] + j - 1], \
       TAVG with lines dt 2 lw 1.5 lc rgb "#555555" notitle
}
unset multiplot
