# fig-stipple.gp - the density part's stippling figure: the shipped image,
# then each method's points under it as black dots on white, side by side
# (top row), and the same crop of each, magnified (bottom row); y up (the
# image's top row at y near 1, as cfpo --density reads it).
# Run by scripts/bench.py replot when the folder has the stippling sets:
#   gnuplot -e "VARS='DIR/plotdata/fig-stipple.vars.gp'; OUT='x.png'" scripts/fig-stipple.gp
# Expects DIR, IMG (a PNG of IW x IH pixels), N, R (the dots' radius in
# units of the torus side), the crop CX0, CX1, CY0, CY1, NM, arrays LBL[NM]
# and FILE[NM]; PW (optional, default 520) a panel's width in pixels.
# The dots are circles of one radius R, chosen (scripts/benchlib/density.py)
# so that their total area n pi R^2 is the image's mean darkness: where
# the points follow rho = 1 - grey/255, the dots' share of a patch is its
# darkness, so the tones read as they would in print (overlaps aside).
load VARS
NC = NM + 1
if (!exists("PW")) PW = 520  # a panel's width in pixels (the plot inside it is square)
GAP = 10            # pixels between panels
TTL = 40            # pixels for a panel's title
TOP = 70            # pixels for the figure's title
RH = PW - GAP + TTL # a row's height
W = NC * PW
H = TOP + 2 * RH
set terminal pngcairo size W, H font "DejaVu Sans,13" enhanced background "white"
set output OUT
set multiplot title sprintf("Stippling the image: %d points, dots of radius %.2g (area = the image's mean darkness)", N, R) font ",17"
unset xtics; unset ytics; unset key
set border lw 0.5 lc rgb "#999999"
set style fill solid 1.0 noborder
do for [row = 0:1] {
  if (row == 0) {
    set xrange [0:1]; set yrange [0:1]
    set object 1 rect from CX0, CY0 to CX1, CY1 front fillstyle empty border lc rgb "#d62728" lw 2
  } else {
    set xrange [CX0:CX1]; set yrange [CY0:CY1]
    unset object 1
  }
  y0 = (1 - row) * RH + GAP / 2.0
  do for [i = 0:NM] {
    set lmargin at screen (1.0 * (i * PW + GAP / 2.0) / W); set rmargin at screen (1.0 * ((i + 1) * PW - GAP / 2.0) / W)
    set bmargin at screen (1.0 * y0 / H); set tmargin at screen (1.0 * (y0 + PW - GAP) / H)
    if (i == 0) {
      set title (row == 0 ? "the density (dark = dense)" : "the crop, magnified") offset 0, -0.3
      plot IMG binary filetype=png dx=1./IW dy=1./IH with rgbimage
    } else {
      set title LBL[i] offset 0, -0.3
      plot DIR."/".FILE[i] using 1:2:(R) with circles lc rgb "black"
    }
  }
}
unset multiplot
