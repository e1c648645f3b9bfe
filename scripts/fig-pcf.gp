# fig-pcf.gp - pair correlation g(r) of every method of the comparison whose
# averaged analysis holds a pcf.txt (cfpo-analyze: '#' comment lines, then
# columns r / Delta(n) and g), a panel per method, g = 1 dotted.
# Run by scripts/bench.py replot only when such files exist:
#   gnuplot -e "VARS='DIR/plotdata/fig-pcf.vars.gp'; OUT='x.png'" scripts/fig-pcf.gp
# Expects DIR, N, SETS, NM, arrays GRP[NM], LBL[NM], COL[NM].
load VARS
NCOL = NM < 4 ? NM : 4
NROW = (NM + NCOL - 1) / NCOL
set terminal pngcairo size (NCOL * 380 + 40), (NROW * 300 + 80) font "DejaVu Sans,12" enhanced
set output OUT
set multiplot layout NROW, NCOL title sprintf("Pair correlation g(r), about %d points, averaged over the sets", N) font ",15"
set xlabel "r / Δ(n)" offset 0, 0.5
set ylabel "g(r)" offset 1.5, 0
set grid lc rgb "#dddddd"
unset key
do for [i = 1:NM] {
  set title LBL[i]
  plot DIR."/data/analysis/".GRP[i]."/pcf.txt" using 1:2 with lines lw 2 lc rgb COL[i], \
       1 with lines dt 3 lc rgb "#888888"
}
unset multiplot
