# fig-progressive-prefixes.gp - the progressive part of the bench: delta_min and
# delta_avg of every prefix P_m (dyadic m as points, the sampled non-dyadic
# ones on the lines between) of every method's set, seed 1, each in its own
# units Delta(m). Run by scripts/benchlib/progressive.py / bench.py replot:
#   gnuplot -e "VARS='DIR/plotdata/fig-progressive-prefixes.vars.gp'; OUT='x.png'" scripts/fig-progressive-prefixes.gp
# Expects DIR, N, NM, arrays KEY[NM], LBL[NM], COL[NM], PT[NM].
load VARS
set terminal pngcairo size 1200,480 font "DejaVu Sans,10" noenhanced
set output OUT
set multiplot layout 1,2 title sprintf("Every prefix m >= 64 of %d points, seed 1, each in its own Delta(m)", N)
set logscale x 2
set format x "%.0f"
set xlabel "prefix size m"
set key font ",9" box opaque
set grid
set yrange [0:1]
f(i) = DIR."/data/progressive/".KEY[i]."-s1.prefixes.txt"
dy(k, v) = k eq "dyadic" ? v : NaN
set ylabel "delta_min / Delta(m)"
set key at graph 0.99, 0.52 right top
plot for [i = 1:NM] f(i) using 1:3 with lines lw 1.5 lc rgb COL[i] notitle, \
     for [i = 1:NM] f(i) using 1:(dy(strcol(2), $3)) with points pt PT[i] ps 0.8 lc rgb COL[i] title LBL[i], \
     0.78 with lines dt 2 lc rgb "black" title "issue 41's goal 0.78"
set ylabel "delta_avg / Delta(m)"
set key at graph 0.99, 0.03 right bottom
plot for [i = 1:NM] f(i) using 1:4 with lines lw 1.5 lc rgb COL[i] notitle, \
     for [i = 1:NM] f(i) using 1:(dy(strcol(2), $4)) with points pt PT[i] ps 0.8 lc rgb COL[i] title LBL[i], \
     0.86 with lines dt 2 lc rgb "black" title "issue 41's goal 0.86"
unset multiplot
