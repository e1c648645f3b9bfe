# fig-evolution.gp - the paper's figure 5: CFPO on N points stopped after 0,
# 1, 2, 5, 10 iterations and converged; point set, averaged power spectrum,
# RAPS and anisotropy per column. Run by scripts/bench.py replot:
#   gnuplot -e "VARS='DIR/plotdata/fig-evolution.vars.gp'; OUT='x.png'" scripts/fig-evolution.gp
load VARS
TITLE = sprintf("Evolution of CFPO on %d points (%d sets; point sets: seed 1)", N, SETS)
load GPDIR."/fig-columns.gp"
