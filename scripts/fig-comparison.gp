# fig-comparison.gp - the paper's figure 6: spectral analysis of every
# method at N points, averaged over SETS sets; point set, power spectrum,
# RAPS and anisotropy per column. Run by scripts/bench.py replot:
#   gnuplot -e "VARS='DIR/plotdata/fig-comparison.vars.gp'; OUT='x.png'" scripts/fig-comparison.gp
load VARS
TITLE = sprintf("Spectral analysis of the methods, %d sets of about %d points each (point sets: seed 1)", SETS, N)
load GPDIR."/fig-columns.gp"
