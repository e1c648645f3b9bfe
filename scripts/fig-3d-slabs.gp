# fig-3d-slabs.gp - a slab of each 3-D set of the bench (seed 1): the points
# with z < SLAB (data/d3/KEY-s1.slab, "x y" lines) seen from above, a panel
# per method. Run by scripts/benchlib/d3.py / bench.py replot:
#   gnuplot -e "VARS='DIR/plotdata/fig-3d-slabs.vars.gp'; OUT='x.png'" scripts/fig-3d-slabs.gp
# Expects DIR, N, SLAB, NM, arrays KEY[NM], LBL[NM], COL[NM].
load VARS
NCOL = NM < 4 ? NM : 4
NROW = (NM + NCOL - 1) / NCOL
set terminal pngcairo size (NCOL * 330 + 40), (NROW * 340 + 80) font "DejaVu Sans,11" enhanced
set output OUT
set multiplot layout NROW, NCOL title sprintf("A slab z < %g of each 3-D set, %d points, seed 1", SLAB, N) font ",14"
set size ratio -1
set xrange [0:1]
set yrange [0:1]
unset xtics
unset ytics
unset key
do for [i = 1:NM] {
  set title LBL[i]
  plot DIR."/data/d3/".KEY[i]."-s1.slab" using 1:2 with points pt 7 ps 0.6 lc rgb COL[i]
}
unset multiplot
