# fig-stipple.gp - the adaptive part's stippling figure: the shipped image,
# then each method's points under its density (seed 1) as dots, y up (the
# image's top row at y near 1, as cfpo --density reads it).
# Run by scripts/bench.py replot when the folder has adaptive.csv:
#   gnuplot -e "VARS='DIR/plotdata/fig-stipple.vars.gp'; OUT='x.png'" scripts/fig-stipple.gp
# Expects DIR, IMG (a PNG of IW x IH pixels), N, NM, arrays LBL[NM], FILE[NM].
load VARS
NP = NM + 1
NCOL = NP < 4 ? NP : 4
NROW = (NP + NCOL - 1) / NCOL
set terminal pngcairo size (NCOL * 420), (NROW * 440 + 60) font "DejaVu Sans,12" enhanced
set output OUT
set multiplot layout NROW, NCOL title sprintf("Stippling the image, %d points", N) font ",15"
set size ratio -1
set xrange [0:1]; set yrange [0:1]
unset xtics; unset ytics; unset key
set title "the density (dark = dense)"
plot IMG binary filetype=png dx=1./IW dy=1./IH with rgbimage
do for [i = 1:NM] {
  set title LBL[i]
  if (N + 0 > 20000) {
    plot DIR."/".FILE[i] using 1:2 with dots lc rgb "black"
  } else {
    plot DIR."/".FILE[i] using 1:2 with points pt 7 ps 0.25 lc rgb "black"
  }
}
unset multiplot
