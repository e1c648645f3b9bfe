# fig-lowfreq.gp - the low-frequency end of the comparison's spectra: the RAPS
# averaged over the sets of each method against |k| / sqrt(n) for
# |k| < 1.2 sqrt(n), log y, one curve per method (the Poisson-disk and direct
# samplers dashed). The grey band is the range of P0 (0 < |k| <= 0.2 sqrt(n),
# analysis/README.md): a flat floor there (FPO-type sets) makes the
# integration error fall as 1/n, a falling one (BNOT) faster. Run by
# scripts/bench.py replot:
#   gnuplot -e "VARS='DIR/plotdata/fig-lowfreq.vars.gp'; OUT='x.png'" scripts/fig-lowfreq.gp
# Expects DIR, N, SETS, NM, arrays GRP[NM] (groups under DIR/data/analysis),
# LBL[NM], COL[NM], DT[NM].
load VARS
set terminal pngcairo size 1300, 820 font "DejaVu Sans,13" enhanced
set output OUT
set title sprintf("Low-frequency power: RAPS for |k| < 1.2 √n, about %d points, mean of the sets of each method", N) font ",15"
set logscale y
set format y "10^{%L}"
set xrange [0:1.2]; set yrange [1e-6:10]
set xlabel "frequency |k| / √n"
set ylabel "RAPS P(|k|) (log)"
set grid lc rgb "#dddddd"
set key outside right center font ",11" spacing 1.1
set object 1 rect from 0, graph 0 to 0.2, graph 1 fc rgb "#eeeeee" fs solid 1.0 noborder behind
set label 1 "P0 range" at 0.1, graph 0.96 center font ",10" textcolor rgb "#666666"
plot for [i = 1:NM] DIR."/data/analysis/".GRP[i]."/raps.txt" using 2:($3 > 0 ? $3 : NaN) with lines lw 2 dt DT[i] lc rgb COL[i] title LBL[i], \
     1 with lines dt 3 lc rgb "#888888" title "white noise (1)"
