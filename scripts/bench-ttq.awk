# bench-ttq.awk - the time-to-quality experiment of a results folder (run by
# replot.sh):
#   awk -F, -v dir=RESULTS -v pdir=PLOTDATA -v tmin=0.925 -v tavg=0.929 \
#       -v methods=methods.tsv -f methods.awk -f bench-ttq.awk RESULTS/runs.csv RESULTS/quality.csv > PLOTDATA/ttq-runs.tsv
# Reads the rows of experiment `ttq` of runs.csv, their traces (columns
# iteration, delta_min, delta_avg, ..., elapsed = column 8) and quality.csv
# (certificate and spike ratio of each final set). Prints one line per run:
# the seconds (trace column elapsed, from the start of the run) at which
# delta_avg >= 0.929, delta_min >= 0.90, delta_min >= 0.92 and the target
# (delta_min >= tmin and delta_avg >= tavg) first hold ("never" when no row
# does), the final row, the quality of the final set, and whether it is its
# configuration's median run (by the time to the target, never counting as
# infinite, then by the final elapsed). Writes the figure's data: for each
# n, PLOTDATA/ttq-nN.dat with one block per configuration (the median run's
# trace: elapsed, delta_min, delta_avg), and PLOTDATA/fig-time-to-quality.vars.gp.
function key(m, v) { return (m == "cfpo") ? v : m }
# configuration order in tables and figures; threads break ties
function rank(k, t) { return (k == "adaptive" ? 1 : k == "paper" ? 3 : k == "fpo" ? 4 : k == "lfpo" ? 5 : 6) * 1000 + t }
# labels and colours from the one list of methods (methods.tsv, through methods.awk)
function label(k, t) { return mlabel(k) ", " t " thread" (t > 1 ? "s" : "") }
function colour(k) { return mcolour(k) }
function inf(x) { return x == "never" ? 1e300 : x + 0 }
FILENAME ~ /runs\.csv$/ {
  if ($0 ~ /^#/ || $1 == "run" || $2 != "ttq") next
  nr++; run[nr] = $1; k[nr] = key($3, $4); th[nr] = $8; n[nr] = $6; seed[nr] = $7; trace[nr] = $19
  lim[nr] = $20; stop[nr] = $21; iters[nr] = $11
  next
}
FILENAME ~ /quality\.csv$/ {
  if ($1 == "run") next
  cp[$1] = $5; sr[$1] = $8; sk[$1] = $9; lr[$1] = $10
  next
}
END {
  print "# run\tkey\tthreads\tn\tseed\ttime_limit\tstop\tt_avg929\tt_min90\tt_min92\tt_target\tfinal_elapsed\tfinal_dmin\tfinal_davg\titerations\tcert_pass\tspike_ratio\tspike_k\tmedian_run\tlattice_ratio"
  for (r = 1; r <= nr; r++) {
    f = dir "/" trace[r]
    ta[r] = t90[r] = t92[r] = tt[r] = "never"; rows = 0
    while ((getline line < f) > 0) {
      if (++rows == 1) continue
      split(line, c, "\t")
      if (ta[r] == "never" && c[3] >= 0.929) ta[r] = c[8]
      if (t90[r] == "never" && c[2] >= 0.90) t90[r] = c[8]
      if (t92[r] == "never" && c[2] >= 0.92) t92[r] = c[8]
      if (tt[r] == "never" && c[2] >= tmin && c[3] >= tavg) tt[r] = c[8]
      fe[r] = c[8]; fd[r] = c[2]; fa[r] = c[3]
    }
    close(f)
    if (rows < 2) { print "bench-ttq: " f ": no trace rows" > "/dev/stderr"; exit 1 }
    cf = n[r] SUBSEP k[r] SUBSEP th[r]
    if (!(cf in cnt)) { nc++; conf[nc] = cf }
    mem[cf, ++cnt[cf]] = r
  }
  # the median run of each configuration
  for (i = 1; i <= nc; i++) {
    cf = conf[i]; m = cnt[cf]
    for (a = 1; a <= m; a++) o[a] = mem[cf, a]
    for (a = 2; a <= m; a++) { x = o[a]; for (b = a - 1; b >= 1 && (inf(tt[o[b]]) > inf(tt[x]) || (inf(tt[o[b]]) == inf(tt[x]) && fe[o[b]] + 0 > fe[x] + 0)); b--) o[b + 1] = o[b]; o[b + 1] = x }
    med[o[int((m + 1) / 2)]] = 1
  }
  for (r = 1; r <= nr; r++)
    printf "%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%d\t%s\n", run[r], k[r], th[r], n[r], seed[r],
      lim[r], stop[r], ta[r], t90[r], t92[r], tt[r], fe[r], fd[r], fa[r], iters[r],
      (run[r] in cp) ? cp[run[r]] : "-", (run[r] in sr) ? sr[run[r]] : "-", (run[r] in sk) ? sk[run[r]] : "-", (r in med),
      (run[r] in lr && lr[run[r]] != "") ? lr[run[r]] : "-"
  # the figure: panels by n, curves by configuration in rank order
  np = 0
  for (r = 1; r <= nr; r++) if (!(n[r] in pidx)) { pidx[n[r]] = 1; pn[++np] = n[r] }
  for (a = 2; a <= np; a++) { x = pn[a]; for (b = a - 1; b >= 1 && pn[b] + 0 > x + 0; b--) pn[b + 1] = pn[b]; pn[b + 1] = x }
  vars = pdir "/fig-time-to-quality.vars.gp"
  printf "# written by scripts/replot.sh (bench-ttq.awk)\nDIR = '%s'; TMIN = %s; TAVG = %s; NP = %d\n", dir, tmin, tavg, np > vars
  printf "array PN[%d]; array PS[%d]; array PC[%d]\n", (np ? np : 1), (np ? np : 1), (np ? np : 1) > vars
  tot = 0
  for (p = 1; p <= np; p++) {
    nm = 0
    for (r = 1; r <= nr; r++) if (n[r] == pn[p] && (r in med)) cm[++nm] = r
    for (a = 2; a <= nm; a++) { x = cm[a]; for (b = a - 1; b >= 1 && rank(k[cm[b]], th[cm[b]]) > rank(k[x], th[x]); b--) cm[b + 1] = cm[b]; cm[b + 1] = x }
    out = pdir "/ttq-n" pn[p] ".dat"
    printf "# one block per configuration (its median run): elapsed_seconds delta_min delta_avg\n" > out
    for (a = 1; a <= nm; a++) {
      r = cm[a]
      if (a > 1) printf "\n\n" > out
      printf "# %s, seed %s, run %s\n", label(k[r], th[r]), seed[r], run[r] > out
      f = dir "/" trace[r]; rows = 0
      while ((getline line < f) > 0) { if (++rows == 1) continue; split(line, c, "\t"); printf "%s\t%s\t%s\n", (c[8] > 0 ? c[8] : 1e-4), c[2], c[3] > out }
      close(f)
      tot++; clbl[tot] = label(k[r], th[r]); ccol[tot] = colour(k[r]); cdt[tot] = (th[r] > 1) ? 2 : 1
    }
    close(out)
    printf "PN[%d] = %s; PS[%d] = %d; PC[%d] = %d\n", p, pn[p], p, tot - nm + 1, p, nm > vars
  }
  printf "NCUR = %d; array LBL[%d]; array COL[%d]; array DT[%d]\n", tot, (tot ? tot : 1), (tot ? tot : 1), (tot ? tot : 1) > vars
  for (a = 1; a <= tot; a++) printf "LBL[%d] = '%s'; COL[%d] = '%s'; DT[%d] = %d\n", a, clbl[a], a, ccol[a], a, cdt[a] > vars
  close(vars)
}
