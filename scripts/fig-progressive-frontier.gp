# fig-progressive-frontier.gp - the trade-off of a progressive set: the
# worst dyadic prefix below the full set (delta_min, each prefix in its own
# Delta(m)) against the full set's delta_min, one point per method or
# setting (medians of 3 seeds), with the issue's targets (0.78, 0.90).
# gnuplot -e "F='frontier.tsv'; OUT='fig.png'" scripts/fig-progressive-frontier.gp
# F: tab-separated rows "label" full_dmin worst_prefix_dmin full_davg
# worst_prefix_davg label_dy_left label_dy_right (+1: the label above the
# point, -1: below; '#' comments), as in
# docs/results/2026-11-29-progressive7-frontier.tsv.
set terminal pngcairo size 1100,480 font ",10" noenhanced
set output OUT
set datafile separator "\t"
set multiplot layout 1,2 title "Progressive sets of 65,536 points: worst prefix 64..n/2 against the full set (medians of 3 seeds)"
set grid
set key off
set xlabel "full set delta_min / Delta(n)"
set ylabel "worst prefix delta_min / Delta(m)"
set xrange [0.6:1.0]
set yrange [0.5:0.85]
set arrow from 0.90, graph 0 to 0.90, graph 1 nohead dt 2 lc rgb "black"
set arrow from graph 0, first 0.78 to graph 1, first 0.78 nohead dt 2 lc rgb "black"
plot F u 2:3 w p pt 7 ps 1.2, F u ($2+0.004):($3+0.012*$6):1 w labels left font ",8"
unset arrow
set xlabel "full set delta_avg / Delta(n)"
set ylabel "worst prefix delta_avg / Delta(m)"
set xrange [0.75:1.0]
set yrange [0.65:0.9]
set arrow from 0.93, graph 0 to 0.93, graph 1 nohead dt 2 lc rgb "black"
set arrow from graph 0, first 0.86 to graph 1, first 0.86 nohead dt 2 lc rgb "black"
plot F u 4:5 w p pt 7 ps 1.2, F u ($4+0.003):($5+0.008*$7):1 w labels left font ",8"
unset multiplot
