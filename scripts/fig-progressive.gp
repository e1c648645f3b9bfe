# fig-progressive.gp - delta_min and delta_avg of every prefix (dyadic and
# sampled non-dyadic) for CFPO --progressive, WSE progressive, a converged
# CFPO set in greedy farthest-point order and Owen-scrambled Sobol'.
# gnuplot -e "D='DIR'; OUT='fig.png'" scripts/fig-progressive.gp, DIR holding
# cp_1.analysis, wse_1.analysis, ord_1.analysis and sobol_1.analysis from
# cfpo-analyze --prefixes (commands: docs/results/2026-11-28-progressive.md).
set terminal pngcairo size 1100,450 font ",10" noenhanced
set output OUT
set multiplot layout 1,2 title "Every prefix m >= 64 of 65,536 points, seed 1, each in its own Delta(m) (dyadic and sampled non-dyadic sizes)"
set logscale x 2
set xlabel "prefix size m"
set key bottom left
set grid
set yrange [0:1]
set ylabel "delta_min / Delta(m)"
p(n) = D."/".n.".analysis/prefixes.txt"
plot p("cp_1") u 1:3 w lp pt 7 ps 0.5 t "CFPO --progressive", \
     p("wse_1") u 1:3 w lp pt 5 ps 0.5 t "WSE progressive", \
     p("ord_1") u 1:3 w lp pt 9 ps 0.5 t "CFPO, greedy FP order", \
     p("sobol_1") u 1:3 w lp pt 11 ps 0.5 t "Owen-Sobol'", \
     0.78 w l dt 2 lc rgb "black" t "target 0.78"
set ylabel "delta_avg / Delta(m)"
plot p("cp_1") u 1:4 w lp pt 7 ps 0.5 t "CFPO --progressive", \
     p("wse_1") u 1:4 w lp pt 5 ps 0.5 t "WSE progressive", \
     p("ord_1") u 1:4 w lp pt 9 ps 0.5 t "CFPO, greedy FP order", \
     p("sobol_1") u 1:4 w lp pt 11 ps 0.5 t "Owen-Sobol'", \
     0.86 w l dt 2 lc rgb "black" t "target 0.86"
unset multiplot
