# fig-progressive-sets.gp - the progressive part of the bench: the first DRAW[j]
# points of each method's set (seed 1), a row per method, a column per size.
# Run by scripts/benchlib/progressive.py / bench.py replot:
#   gnuplot -e "VARS='DIR/plotdata/fig-progressive-sets.vars.gp'; OUT='x.png'" scripts/fig-progressive-sets.gp
# Expects DIR, N, NM, arrays KEY[NM], LBL[NM], COL[NM], DRAW[3]; the points in
# DIR/data/progressive/KEY-s1.xy ("x y" lines, the set's first rows).
load VARS
set terminal pngcairo size 1000, (NM * 330 + 60) font "DejaVu Sans,10" noenhanced
set output OUT
set multiplot layout NM, 3 title sprintf("The first m points of each progressive set (n = %d, seed 1)", N) font ",13"
set size ratio -1
set xrange [0:1]
set yrange [0:1]
unset xtics
unset ytics
unset key
do for [i = 1:NM] {
  do for [j = 1:3] {
    set title sprintf("%s, m = %d", LBL[i], DRAW[j])
    plot DIR."/data/progressive/".KEY[i]."-s1.xy" every ::0::(DRAW[j] - 1) using 1:2 with points pt 7 \
         ps (j == 1 ? 0.5 : j == 2 ? 0.3 : 0.15) lc rgb COL[i]
  }
}
unset multiplot
