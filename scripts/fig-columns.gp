# fig-columns.gp - the layout shared by fig-evolution.gp and fig-comparison.gp
# (the paper's figures 5 and 6): one column per point set, three rows:
#   1. the seed-1 point set (a detail of the torus, [0, ZOOM]^2)
#   2. the power spectrum P(k) averaged over the sets, greyscale, |k| <= SPAN
#   3. RAPS (red, left axis) and anisotropy (blue, right axis, dB) against
#      frequency |k| / sqrt(n)
# Expects (from the including script and the vars file written by scripts/bench.py replot):
#   OUT, TITLE, NC, DIR (results folder), N (points), SPAN (half-width of the
#   spectrum shown, in k), CBMAX, ZOOM, SETS, arrays GRP[NC] (group names
#   under DIR/data/analysis and DIR/data/points) and LBL[NC] (column titles).
CW = 330.0; PW = 256.0; X0 = 150.0; XR = 90.0
Wpx = X0 + NC * CW + XR
Hpx = 1010.0
set terminal pngcairo size Wpx, Hpx font "DejaVu Sans,13" enhanced
set output OUT
sx(px) = px / Wpx
sy(px) = 1.0 - px / Hpx
left(c) = X0 + (c - 1) * CW + 40

set multiplot title TITLE font "DejaVu Sans,17"
# row labels
set label 1 "point set\n(detail [0, ".sprintf("%g", ZOOM)."]^2)" at screen sx(12), sy(95 + PW / 2) left font ",13"
set label 2 sprintf("power spectrum\n(mean of %d sets)\nk_x, k_y: cycles\nper unit length", SETS) at screen sx(12), sy(410 + PW / 2) left font ",13"
set label 3 sprintf("radial mean\n(RAPS, red)\nand anisotropy\n(dB, blue),\nmean of %d sets", SETS) at screen sx(12), sy(735 + 100) left font ",13"

do for [c = 1:NC] {
  x0 = left(c)
  # 1. points
  set lmargin at screen sx(x0); set rmargin at screen sx(x0 + PW)
  set tmargin at screen sy(95); set bmargin at screen sy(95 + PW)
  set title LBL[c] font ",14"
  unset key
  set xrange [0:ZOOM]; set yrange [0:ZOOM]
  set xtics ZOOM / 2 format "%g" font ",10" offset 0, 0.3; set ytics ZOOM / 2 format "%g" font ",10" offset 0.5, 0
  unset xlabel; unset ylabel
  plot DIR."/data/points/".GRP[c].".txt" using 1:2 with points pt 7 ps 0.32 lc rgb "black"
  unset title; unset label 1; unset label 2; unset label 3
  # 2. spectrum
  set tmargin at screen sy(410); set bmargin at screen sy(410 + PW)
  set xrange [-SPAN:SPAN]; set yrange [-SPAN:SPAN]
  set xtics SPAN format "%g" font ",10"; set ytics SPAN format "%g" font ",10"
  set palette gray
  set cbrange [0:CBMAX]
  if (c == NC) {
    set colorbox user origin screen sx(x0 + PW + 8), sy(410 + PW) size screen sx(12), (PW / Hpx)
    set cbtics 1 font ",10"
    set cblabel "P(k)" font ",11" offset -0.5, 0
  } else { unset colorbox }
  plot DIR."/data/analysis/".GRP[c]."/spectrum.txt" nonuniform matrix with image
  # 3. RAPS and anisotropy
  set tmargin at screen sy(735); set bmargin at screen sy(735 + 200)
  set xrange [0:4]; set xtics 1 format "%g" font ",10"
  set yrange [0:5]; set ytics 1 format "%g" font ",10" textcolor rgb "#c00000" nomirror
  set y2range [-20:10]; set y2tics 10 format "%g" font ",10" textcolor rgb "#0040c0"
  set xlabel "frequency |k| / √n" font ",11" offset 0, 0.5
  if (c == 1) { set ylabel "RAPS P(|k|)" font ",11" textcolor rgb "#c00000" offset 1.5, 0 } else { unset ylabel }
  if (c == NC) { set y2label "anisotropy (dB)" font ",11" textcolor rgb "#0040c0" offset -1.5, 0 } else { unset y2label }
  set grid xtics lc rgb "#dddddd"
  plot DIR."/data/analysis/".GRP[c]."/raps.txt" using 2:3 with lines lw 1.5 lc rgb "#c00000", \
       "" using 2:4 axes x1y2 with lines lw 1 lc rgb "#0040c0", \
       1 with lines dt 2 lc rgb "#888888"
  unset grid; unset xlabel; unset ylabel; unset y2label; unset y2tics
  set ytics mirror textcolor rgb "black"
}
unset multiplot
