# bench-summary.awk - summary.md of a results folder (run by replot.sh):
#   awk -F, -v convkeys="fpo lfpo ..." -v tmin=0.925 -v tavg=0.929 -v methods=methods.tsv \
#       -f methods.awk -f bench-summary.awk \
#       runs.csv spectra.csv plotdata/runtime.tsv plotdata/speedup.tsv plotdata/ttq-runs.tsv
# Every number is computed here from those files, and every table names the
# rows of runs.csv (column `run`) and spectra.csv (column `group`) it comes
# from; runtime.tsv and speedup.tsv are themselves medians of runs.csv rows
# (replot.sh), ttq-runs.tsv one line per time-to-quality run read from its
# trace and quality.csv (bench-ttq.awk), all listed in the tables.
function key(m, v) { return (m != "cfpo") ? m : (v == "paper" || v == "cfpo") ? "cfpo" : v }
# labels from the one list of methods (methods.tsv, through methods.awk)
function label(k) { return mlabel(k) }
# "3 4 5 9" -> "3-5, 9"
function ranges(s,   a, k, i, j, t, out, st, pv) {
  k = split(s, a, " ")
  for (i = 2; i <= k; i++) { t = a[i] + 0; for (j = i - 1; j >= 1 && a[j] + 0 > t; j--) a[j + 1] = a[j]; a[j + 1] = t }
  out = ""; st = ""
  for (i = 1; i <= k; i++) {
    if (st != "" && a[i] == pv + 1) { pv = a[i]; continue }
    if (st != "") out = out (out == "" ? "" : ", ") st (pv != st ? "-" pv : "")
    st = a[i]; pv = a[i]
  }
  if (st != "") out = out (out == "" ? "" : ", ") st (pv != st ? "-" pv : "")
  return out
}
function mean(s,   a, k, i, t) { k = split(s, a, " "); t = 0; for (i = 1; i <= k; i++) t += a[i]; return k ? t / k : 0 }
function sd(s,   a, k, i, m, t) {
  k = split(s, a, " "); if (k < 2) return 0
  m = mean(s); t = 0; for (i = 1; i <= k; i++) t += (a[i] - m) ^ 2
  return sqrt(t / (k - 1))
}
function secs(x) { return x >= 100 ? sprintf("%.0f", x) : x >= 10 ? sprintf("%.1f", x) : x >= 1 ? sprintf("%.2f", x) : sprintf("%.3g", x) }
function pm(s, d) { return sprintf("%." d "f ± %." d "f", mean(s), sd(s)) }
# mean ± sd with three significant digits of the mean
function pmsig(s,   m, d) { m = mean(s); d = (m > 0) ? 2 - int(log(m) / log(10) + (m < 1 ? -0.999999 : 0)) : 3; if (d < 0) d = 0; return sprintf("%." d "f ± %." d "f", m, sd(s)) }
function f3(x) { return (x == "-" || x == "") ? "-" : sprintf("%.3f", x) }
function f2(x) { return (x == "-" || x == "") ? "-" : sprintf("%.2f", x) }
# median of a list where "never" is infinite: "never" when the median is
function med(s,   a, k, i, j, t, m) {
  k = split(s, a, " "); if (!k) return "-"
  for (i = 1; i <= k; i++) a[i] = (a[i] == "never") ? 1e300 : a[i] + 0
  for (i = 2; i <= k; i++) { t = a[i]; for (j = i - 1; j >= 1 && a[j] > t; j--) a[j + 1] = a[j]; a[j + 1] = t }
  m = (k % 2) ? a[(k + 1) / 2] : (a[k / 2] + a[k / 2 + 1]) / 2
  return m >= 1e299 ? "never" : m
}
function reached(s,   a, k, i, c) { k = split(s, a, " "); c = 0; for (i = 1; i <= k; i++) if (a[i] != "never") c++; return c }
function tcell(s,   m, k, c) { m = med(s); k = split(s, tmp2, " "); c = reached(s)
  return (m == "never" ? "never" : secs(m)) (c < k && c > 0 ? " (" c " of " k ")" : "") }
function spk(g) { return (g in sg) && sspm[g] != "" ? sprintf("%.1f / %.1f", sspm[g], sspk[g]) : "-" }
function ttqlabel(k) { return mlabel(k) }
function ttqrank(k, t) { return (k == "adaptive" ? 1 : k == "paper" ? 3 : k == "fpo" ? 4 : k == "lfpo" ? 5 : 6) * 1000 + t }
function nice_n(n) { return n >= 1048576 && n % 1048576 == 0 ? n / 1048576 "M" : n >= 1024 && n % 1024 == 0 ? n / 1024 "k" : n }

FILENAME ~ /runs\.csv$/ {
  if ($0 ~ /^# /) { hdr[++nh] = substr($0, 3); if ($0 ~ /^# host: /) { host = $0; sub(/^# host: /, "", host); sub(/;.*/, "", host) }
    if ($0 ~ /profile /) { prof = $0; sub(/.*profile /, "", prof); sub(/,.*/, "", prof) }
    if ($0 ~ /^# plan: /) { plan = $0 } ; next }
  if ($1 == "run") next
  k = key($3, $4)
  if ($2 == "comparison") {
    if (!(k in cn)) order[++no] = k
    cn[k]++; cid[k] = cid[k] " " $1; cdmin[k] = cdmin[k] " " $14; cdavg[k] = cdavg[k] " " $15
    csec[k] = csec[k] " " $12; cthr[k] = $8; cN[k] = cN[k] " " $5; cmem[k] = cmem[k] " " $16
    if ($11 != "-") cit[k] = cit[k] " " $11
    if ($17 == "yes") cconv[k]++
  }
  if ($2 == "evolution") { ev = $10; if (!(ev in en)) eorder[++neo] = ev; en[ev]++; eid[ev] = eid[ev] " " $1; edmin[ev] = edmin[ev] " " $14; edavg[ev] = edavg[ev] " " $15 }
  nrows++
  next
}
FILENAME ~ /spectra\.csv$/ {
  if ($1 == "group") next
  sg[$1] = 1; seff[$1] = $14; sosc[$1] = $15; speak[$1] = $12; sruns[$1] = $8; sby[$1] = $16; ssets[$1] = $7
  sspk[$1] = ($17 == "-") ? "" : $17; sspm[$1] = ($19 == "-") ? "" : $19
  next
}
FILENAME ~ /ttq-runs\.tsv$/ {
  if ($0 ~ /^#/) next
  split($0, a, "\t")
  c = a[4] SUBSEP a[2] SUBSEP a[3]
  if (!(c in qn)) { nq++; qconf[nq] = c; if (!(a[4] in qsz)) { qsz[a[4]] = 1; nqs++; qsizes[nqs] = a[4] } }
  qn[c]++; qid[c] = qid[c] " " a[1]; qlim[a[4]] = a[6]; qst[c, a[7]]++
  qta[c] = qta[c] " " a[8]; q90[c] = q90[c] " " a[9]; q92[c] = q92[c] " " a[10]; qtt[c] = qtt[c] " " a[11]
  qfd[c] = qfd[c] " " a[13]; qfa[c] = qfa[c] " " a[14]
  if (a[16] != "-") qcp[c] = qcp[c] " " a[16]
  if (a[17] != "-") qsr[c] = qsr[c] " " a[17]
  if (a[20] != "" && a[20] != "-") qlr[c] = qlr[c] " " a[20]
  next
}
FILENAME ~ /runtime\.tsv$/ {
  split($0, a, "\t")
  nrt++; rt[nrt] = $0
  next
}
FILENAME ~ /speedup\.tsv$/ {
  split($0, a, "\t")
  nsp++; sp[nsp] = $0
  next
}
END {
  N = 0; split(cN["cfpo"], tmp, " "); N = tmp[1]
  printf "# Method comparison on %s (profile %s)\n\n", host, prof
  print "Written by `scripts/bench.sh` (`make bench`), redrawn by `scripts/replot.sh` (`make replot`)."
  print "Every number below is computed from `runs.csv` (one row per run; \"rows\" name its `run` column)"
  print "and `spectra.csv` (one row per averaged spectrum, named by its `group` column, which lists the"
  print "runs whose point sets it averages). Machine and build (the header of `runs.csv`):"
  print ""
  print "```"
  for (i = 1; i <= nh; i++) if (hdr[i] !~ /^columns:/) print hdr[i]
  print "```"
  print ""
  # ---- comparison
  fpo = ("fpo" in cn) ? mean(csec["fpo"]) : 0
  printf "## Quality and cost at n = %s, %d sets per method\n\n", N, cn["cfpo"]
  print "| method | runs.csv rows | δ_min / Δ(n) | δ_avg / Δ(n) | eff. Nyquist | oscillation | spike ratio (sets / average) | iterations | converged | seconds | time / FPO's | threads | peak MB | spectra.csv group |"
  print "| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |"
  for (i = 1; i <= no; i++) {
    k = order[i]; g = "comparison-" k
    it = (k in cit) ? sprintf("%.0f ± %.0f", mean(cit[k]), sd(cit[k])) : "-"
    cv = (k in cit) ? sprintf("%d of %d", cconv[k], cn[k]) : "-"
    ratio = fpo > 0 ? sprintf("%.3f", mean(csec[k]) / fpo) : "-"
    printf "| %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %.1f | `%s` |\n", label(k), ranges(cid[k]), pm(cdmin[k], 4), pm(cdavg[k], 4),
      (g in sg) ? f3(seff[g]) : "-", (g in sg) ? f2(sosc[g]) : "-", spk(g), it, cv, pmsig(csec[k]), ratio, cthr[k], mean(cmem[k]) / 1048576, g
  }
  print ""
  print "δ_min / Δ(n), δ_avg / Δ(n): the smallest and the mean nearest-neighbour distance over the"
  print "hexagonal bound Δ(n) = sqrt(2 / (√3 n)), as each run reported them; mean ± sample standard"
  print "deviation over the sets (columns `delta_min`, `delta_avg` of the rows). Effective Nyquist"
  print "(r_01 / √n, higher: less aliasing) and oscillation (10 × RMS deviation of the RAPS from 1 beyond"
  print "its first crossing of 0.98; lower: flatter) are those of the power spectrum averaged over the"
  print "sets (spectra.csv, analysis/README.md for the definitions). Spike ratio: the largest P(k) over"
  print "the mean of its ring, as the mean of the per-set values (white noise: 10-15) / of the averaged"
  print "spectrum (white noise averaged over 10 sets: about 3); a lattice imprint stands far above both."
  print "Iterations and seconds: mean ±"
  print "standard deviation; seconds is the tool's sampling time (until converged for the iterative"
  print "methods); time / FPO's = mean seconds over FPO's mean seconds, same n and one thread each"
  print "(column `threads`); runs with one runs.csv `batch` number started together, each pinned to its own"
  print "core (successive seeds of one method, `COMP_TOGETHER` of the profile), so their seconds include a"
  print "neighbour's use of the memory system. BS and Bridson produce maximal sets whose size varies a little with the seed"
  print "(column `n`); their spectra are averaged by `scripts/bench-average.awk` (spectra.csv column"
  print "`averaged_by`), the others by `cfpo-analyze` itself."
  print ""
  print "![comparison](fig-comparison.png)"
  print ""
  print "![convergence](fig-convergence.png)"
  print ""
  nk = split(convkeys, ck, " ")
  if (nk) {
    printf "Convergence: the traces of rows"
    for (i = 1; i <= nk; i++) printf "%s %s (%s)", (i > 1 ? ";" : ""), ranges(cid[ck[i]]), label(ck[i])
    print "; plotted as `plotdata/convergence-*.dat`."
    print ""
  }
  # ---- evolution
  if (neo) {
    print "## Evolution of CFPO"
    print ""
    print "| iteration | runs.csv rows | δ_min / Δ(n) | δ_avg / Δ(n) | eff. Nyquist | oscillation | spike ratio (sets / average) | spectra.csv group |"
    print "| --- | --- | --- | --- | --- | --- | --- | --- |"
    for (i = 1; i <= neo; i++) {
      ev = eorder[i]; g = "evolution-it" ev
      printf "| %s | %s | %s | %s | %s | %s | %s | `%s` |\n", ev, ranges(eid[ev]), pm(edmin[ev], 4), pm(edavg[ev], 4), (g in sg) ? f3(seff[g]) : "-", (g in sg) ? f2(sosc[g]) : "-", spk(g), g
    }
    if ("cfpo" in cn) printf "| converged | %s | %s | %s | %s | %s | %s | `comparison-cfpo` |\n", ranges(cid["cfpo"]), pm(cdmin["cfpo"], 4), pm(cdavg["cfpo"], 4), f3(seff["comparison-cfpo"]), f2(sosc["comparison-cfpo"]), spk("comparison-cfpo")
    print ""
    print "![evolution](fig-evolution.png)"
    print ""
  }
  # ---- runtime
  print "## Runtime"
  print ""
  print "Median over seeds of every uncapped run (experiments `comparison` and `runtime`), per method,"
  print "threads, ranks and n (`plotdata/runtime.tsv`)."
  print ""
  print "| method | threads | ranks | n | runs | seconds (median) | seconds per iteration | iterations | runs.csv rows |"
  print "| --- | --- | --- | --- | --- | --- | --- | --- | --- |"
  nkeys = split(mkeys("pd iter cfpo"), korder, " ")
  for (j = 1; j <= nkeys; j++) for (i = 1; i <= nrt; i++) {
    split(rt[i], a, "\t")
    if (a[1] != korder[j]) continue
    printf "| %s | %s | %s | %s | %s | %s | %s | %s | %s |\n", label(a[1]), a[2], a[3], a[4], a[7], secs(a[5]), (a[6] == "-" ? "-" : sprintf("%.3g", a[6])), a[8], ranges(a[9])
  }
  print ""
  print "![runtime](fig-runtime.png)"
  print ""
  print "## Speedup"
  print ""
  print "Median time on 1 thread and 1 rank over the median time of the configuration, same method, n"
  print "and seeds (`plotdata/speedup.tsv`; on 2 cores this is 1 against 2 threads)."
  print ""
  print "| method | n | threads | ranks | speedup | runs.csv rows (1 thread \\| this configuration) |"
  print "| --- | --- | --- | --- | --- | --- |"
  for (i = 1; i <= nsp; i++) {
    split(sp[i], a, "\t")
    if (a[5] == 1) continue
    split(a[7], b, "|")
    printf "| %s | %s | %s | %s | %.2f | %s \\| %s |\n", label(a[1]), a[2], a[3], a[4], a[6], ranges(b[1]), ranges(b[2])
  }
  print ""
  print "![speedup](fig-speedup.png)"
  if (nq) ttq_section()
}
# ---- time to quality: one table per n
function ttq_section(   i, j, c, a, n, k, t, lv, f, fc, cc, r, st, x) {
  print ""
  print "## Time to quality"
  print ""
  printf "Every iterative method, run with `--trace` until δ_min ≥ %s and δ_avg ≥ %s both hold (the\n", tmin, tavg
  print "target: the run's `--target-min`/`--target-avg`), it converges (cfpo's rule and tolerance) or its"
  print "`--time-limit` passes (column `time_limit` of runs.csv). One-thread runs that are compared started"
  print "together, one per core (runs.csv column `batch`); runs on several threads ran alone. Seconds: the"
  print "trace's `elapsed` column (wall clock from the start of the run, the start included) at the first"
  print "iteration where the level holds; median over the seeds, \"never\" when the median run did not get"
  print "there (\"k of m\": the seeds that did). Final δ: the last trace row. Certificate pass: the fraction"
  print "of the final set's points that are farthest points of the rest (`cfpo-analyze --certify`); spike"
  print "ratio: the largest P(k) over its ring's mean for the final set (white noise: 10-15; a lattice"
  print "imprint: far more); lattice ratio: the largest P(k) over its ring's mean at the axis frequencies of"
  print "cfpo's grid for n (white noise: below 5 in most sets; a trace of the grid: more), all from"
  print "`quality.csv`, medians. FPO / this: FPO's median seconds over this"
  print "row's at each level, same n (above 1: this row is faster); - where either never got there."
  print "Per run: `plotdata/ttq-runs.tsv`."
  # configurations in order
  for (i = 2; i <= nq; i++) { c = qconf[i]; split(c, a, SUBSEP); x = a[1] * 1e6 + ttqrank(a[2], a[3])
    for (j = i - 1; j >= 1; j--) { split(qconf[j], b, SUBSEP); if (b[1] * 1e6 + ttqrank(b[2], b[3]) <= x) break; qconf[j + 1] = qconf[j] }
    qconf[j + 1] = c }
  for (i = 2; i <= nqs; i++) { x = qsizes[i]; for (j = i - 1; j >= 1 && qsizes[j] + 0 > x + 0; j--) qsizes[j + 1] = qsizes[j]; qsizes[j + 1] = x }
  split("ta 90 92 tt", lv, " ")
  for (j = 1; j <= nqs; j++) {
    n = qsizes[j]
    print ""
    printf "### n = %s (time limit %s s)\n\n", n, qlim[n]
    printf "| method | threads | runs.csv rows | δ_avg ≥ 0.929 (s) | δ_min ≥ 0.90 (s) | δ_min ≥ 0.92 (s) | target (s) | stopped by | final δ_min | final δ_avg | certificate pass | spike ratio | lattice ratio | FPO / this: δ_avg ≥ 0.929 | δ_min ≥ 0.90 | δ_min ≥ 0.92 | target |\n"
    print "| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |"
    f = n SUBSEP "fpo" SUBSEP 1
    for (i = 1; i <= nq; i++) {
      c = qconf[i]; split(c, a, SUBSEP)
      if (a[1] != n) continue
      k = a[2]; t = a[3]
      st = ""; split("target converged time max-iter", stn, " ")
      for (r = 1; r <= 4; r++) if ((c, stn[r]) in qst) st = st (st == "" ? "" : ", ") stn[r] " " qst[c, stn[r]]
      printf "| %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s", ttqlabel(k), t, ranges(qid[c]), tcell(qta[c]), tcell(q90[c]),
        tcell(q92[c]), tcell(qtt[c]), st, sprintf("%.4f", med(qfd[c])), sprintf("%.4f", med(qfa[c])),
        (c in qcp) ? sprintf("%.4f", med(qcp[c])) : "-", (c in qsr) ? sprintf("%.1f", med(qsr[c])) : "-",
        (c in qlr) ? sprintf("%.1f", med(qlr[c])) : "-"
      for (r = 1; r <= 4; r++) {
        fc = (f in qn) ? med(r == 1 ? qta[f] : r == 2 ? q90[f] : r == 3 ? q92[f] : qtt[f]) : "never"
        cc = med(r == 1 ? qta[c] : r == 2 ? q90[c] : r == 3 ? q92[c] : qtt[c])
        printf " | %s", (k != "adaptive" && k != "paper") || fc == "never" || cc == "never" || cc + 0 <= 0 ? "-" : sprintf("%.2f", fc / cc)
      }
      printf " |\n"
    }
  }
  print ""
  print "![time to quality](fig-time-to-quality.png)"
}
