# fig-3d.gp - the 3-D part of the bench in four panels: the power spectrum
# averaged over shells |k| = s (seed 1, data/d3/KEY-s1.spec: shell, power),
# g(r) (data/d3/KEY-s1.pcf: r / Delta3(n), g), delta_min against time (time
# to quality: the traces of cfpo3d, whose rows hold each iteration's own
# seconds in column 7, and of 3-D FPO and Lloyd, elapsed seconds in column 2; the
# direct methods as points, plotdata/d3-direct.dat; below delta 0.6 or
# 1 ms off the panel) and the packing
# fraction (pi/6) sqrt(2) delta_min^3 against time.
#   gnuplot -e "VARS='DIR/plotdata/fig-3d.vars.gp'; OUT='x.png'" scripts/fig-3d.gp
# Expects DIR, N, NM, arrays KEY[NM], LBL[NM], COL[NM], IT[NM].
load VARS
set terminal pngcairo size 1300, 1000 font "DejaVu Sans,11" enhanced
set output OUT
set multiplot layout 2, 2 title sprintf("Three dimensions, %d points (seed 1)", N) font ",14"
set grid lc rgb "#dddddd"
set key top left font ",9"
phi(d) = pi / 6 * sqrt(2) * d**3
set title "power spectrum over shells"
set xlabel "shell |k|"
set ylabel "P(|k|)"
set logscale y
plot for [i = 1:NM] DIR."/data/d3/".KEY[i]."-s1.spec" using 1:2 every ::1 with lines lw 2 lc rgb COL[i] title LBL[i], \
     1 with lines dt 3 lc rgb "#888888" notitle
unset logscale y
set title "pair correlation"
set xlabel "r / Δ_3(n)"
set ylabel "g(r)"
set key top right
plot for [i = 1:NM] DIR."/data/d3/".KEY[i]."-s1.pcf" using 1:2 every ::1 with lines lw 2 lc rgb COL[i] title LBL[i], \
     1 with lines dt 3 lc rgb "#888888" notitle
set title "time to quality"
set xlabel "seconds (one thread; loaded machines vary)"
set ylabel "δ_{min}"
set logscale x
set format x "%g"
set xrange [1e-3:*]
set yrange [0.6:1]
set key bottom right
D = DIR."/plotdata/d3-direct.dat"
plot for [i = 1:NM] (KEY[i] eq "cfpo3d" ? DIR."/data/d3/cfpo3d-s1.trace" : "/dev/null") \
       using (c = (column(1) == 1 ? 0 : c) + $7, c):2 with linespoints pt 7 ps 0.5 lw 2 lc rgb COL[i] title LBL[i], \
     for [i = 1:NM] (IT[i] && KEY[i] ne "cfpo3d" ? DIR."/data/d3/".KEY[i]."-s1.trace" : "/dev/null") \
       using ($2 > 0 ? $2 : NaN):3 every ::1 with linespoints pt 7 ps 0.5 lw 2 lc rgb COL[i] title LBL[i], \
     for [i = 1:NM] (IT[i] ? "/dev/null" : D) using (strcol(3) eq KEY[i] ? $1 : NaN):2 with points pt 5 ps 1.5 lc rgb COL[i] title LBL[i]
set title "packing fraction of spheres of diameter δ_{min} Δ_3(n)"
set ylabel "packing fraction"
set yrange [0.2:0.76]
set key top left
plot for [i = 1:NM] (KEY[i] eq "cfpo3d" ? DIR."/data/d3/cfpo3d-s1.trace" : "/dev/null") \
       using (c = (column(1) == 1 ? 0 : c) + $7, c):(phi($2)) with linespoints pt 7 ps 0.5 lw 2 lc rgb COL[i] title LBL[i], \
     for [i = 1:NM] (IT[i] && KEY[i] ne "cfpo3d" ? DIR."/data/d3/".KEY[i]."-s1.trace" : "/dev/null") \
       using ($2 > 0 ? $2 : NaN):(phi($3)) every ::1 with linespoints pt 7 ps 0.5 lw 2 lc rgb COL[i] title LBL[i], \
     for [i = 1:NM] (IT[i] ? "/dev/null" : D) using (strcol(3) eq KEY[i] ? $1 : NaN):(phi($2)) with points pt 5 ps 1.5 lc rgb COL[i] title LBL[i], \
     pi / sqrt(18) with lines dt 2 lc rgb "#444444" title "FCC 0.7405", \
     0.384 with lines dt 3 lc rgb "#444444" title "RSA saturation 0.384"
unset multiplot
