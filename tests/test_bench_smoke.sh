#!/usr/bin/env bash
# test_bench_smoke.sh BUILD_DIR - `make bench PROFILE=smoke` end to end
# (scripts/bench.py run, scripts/bench.py replot) into a temporary results root:
# the folder and nothing else appears; runs.csv has the documented header and
# columns, one well-formed row per planned run, every method and experiment;
# the evolution snapshots are the states their traces say; the time-to-
# quality runs are the planned configurations, batched one per core (and
# the comparison's one-thread runs of a method two by two on 2 cores), each
# stopped by the rule its own trace shows, with a quality.csv row each;
# `--plan` lists exactly the runs made; every figure is a PNG (signature and
# header checked); summary.md shows every figure and numbers that recompute
# from runs.csv and the traces; replot redraws everything from the folder
# alone (and a folder without time-to-quality runs); errors give one line,
# a non-zero exit and leave nothing.
set -uo pipefail
B=$(cd "${1:-build}" && pwd)
SRC=$(cd "$(dirname "$0")/.." && pwd)
T=$(mktemp -d "${TMPDIR:-/tmp}/cfpo-bench-test.XXXXXX")
trap 'rm -rf "$T"' EXIT
pass=0; fail=0
ok() { pass=$((pass + 1)); }
bad() { fail=$((fail + 1)); echo "FAIL: $*"; }
check() { local what=$1; shift; if "$@"; then ok; else bad "$what"; fi; }
# check WHAT holds 'A && B ...': the whole list decides (not A alone)
holds() { eval "$1"; }
cd "$SRC" || exit 1
# the methods (scripts/methods.tsv): SUMMARY method names as regular
# expressions, all / Poisson-disk (no trace) / the rest (through an
# iterative command line: the direct samplers' one pass has its trace row
# too), and the comparison's keys as runs.csv shows them (cfpo's variant
# for cfpo's rows: the key of each CFPO variant is its variant's name)
BENCH="python3 scripts/bench.py"
methods_keys() { $BENCH methods "$@"; }
method_get() { $BENCH methods --get "$1" "$2"; }
mre() { local k; for k in $(methods_keys "$@"); do method_get "$k" method; done | sort -u | paste -sd'|'; }
M_ALL=$(mre); M_PD=$(mre pd); M_IT=$(mre direct iter cfpo)
COMP_SEEN=$(for k in $(methods_keys pd direct iter cfpo); do m=$(method_get "$k" method); [ "$m" = cfpo ] && m=$(method_get "$k" variant); echo "$m"; done | sort -u | tr '\n' ' ')
N_COMP=$(methods_keys pd direct iter cfpo | wc -w)
# one key a method: each key is its runs.csv rows' key (the paper variant's: paper)
check "methods.tsv: every key is its method or its variant (keys: $(methods_keys | tr '\n' ' '))" \
  [ "$(methods_keys | tr ' ' '\n' | sort | tr '\n' ' ')" = "$COMP_SEEN" ]

# ---- the smoke run ----------------------------------------------------------
export CFPO_RESULTS="$T/res"
if ! $BENCH run "$B" smoke >"$T/out" 2>"$T/err"; then
  echo "FAIL: bench.py run smoke exited non-zero:"; tail -n 5 "$T/err"; echo "0 passed, 1 failed"; exit 1
fi
ok
n_dirs=$(find "$T/res" -mindepth 1 -maxdepth 1 | wc -l)
check "exactly one folder under the results root (found $n_dirs)" [ "$n_dirs" -eq 1 ]
R=$(find "$T/res" -mindepth 1 -maxdepth 1 -type d | head -n 1)
check "folder named <date>-<time>-<host>" grep -Eq '/[0-9]{8}-[0-9]{6}-[^/]+$' <<<"$R"
check "progress lines on stderr ([k/N] ... elapsed ... left)" grep -Eq '^bench: \[[0-9]+/[0-9]+\] .* elapsed, about .* left: ' "$T/err"

# ---- runs.csv -------------------------------------------------------------------
csv="$R/runs.csv"
cols="run,experiment,method,variant,n,n_target,seed,threads,ranks,max_iter,iterations,seconds,seconds_per_iteration,delta_min,delta_avg,peak_bytes,converged,wall_seconds,trace,time_limit,stop,batch"
check "runs.csv column line" [ "$(grep -v '^#' "$csv" | head -n 1)" = "$cols" ]
for h in 'cpu: ' 'cores: ' 'compiler: ' 'C flags: ' 'git commit: ' 'FFTW ' 'CGAL ' 'OpenMPI ' 'gnuplot ' 'load average before' 'load average after'; do
  check "runs.csv header names '$h'" grep -q "^# .*$h" "$csv"
done
planned=$(sed -n 's/^# plan: .*; \([0-9]*\) runs$/\1/p' "$csv")
rows=$(grep -v '^#' "$csv" | tail -n +2 | wc -l)
check "one row per planned run ($rows rows, $planned planned)" [ -n "$planned" ] && [ "$rows" -eq "$planned" ] && [ "$rows" -gt 0 ]
bad_rows=$(grep -v '^#' "$csv" | tail -n +2 | awk -F, -v mall="^($M_ALL)\$" -v mpd="^($M_PD)\$" -v mit="^($M_IT)\$" '
  function num(x) { return x ~ /^[0-9]+(\.[0-9]*)?([eE][-+]?[0-9]+)?$/ }
  function int_(x) { return x ~ /^[0-9]+$/ }
  { e = "" }
  NF != 22 { e = e " fields=" NF }
  $1 != NR { e = e " run" }
  $2 !~ /^(evolution|comparison|runtime|integration|ttq)$/ { e = e " experiment" }
  $3 !~ mall { e = e " method" }
  ($3 == "cfpo") != ($4 ~ /^(paper|adaptive|simplified|hyperuniform)$/) || ($3 != "cfpo" && $4 != "-") { e = e " variant" }
  ($2 == "evolution" || $2 == "runtime") && $4 == "adaptive" { e = e " variant (evolution and runtime run the paper variant)" }
  !int_($5) || !int_($6) || !int_($7) || !int_($8) || !int_($9) || ($9 != 1 && !($3 == "cfpo" && $8 == 1 && $2 == "runtime")) { e = e " n/seed/threads/ranks" }
  $10 != "-" && !int_($10) { e = e " max_iter" }
  !num($12) || !num($16) || $16 == 0 || !num($18) { e = e " seconds/peak/wall" }
  !num($14) || !num($15) || $14 > 1.2 || $15 > 1.2 || $14 > $15 + 1e-9 { e = e " delta" }
  $3 ~ mpd && ($11 != "-" || $13 != "-" || $17 != "-" || $19 != "-" || $21 != "-") { e = e " non-iterative" }
  $3 ~ mit && (!int_($11) || $17 !~ /^(yes|no)$/ || $19 == "-") { e = e " iterative" }
  $3 ~ mit && $11 > 0 && ($13 - $12 / $11 > 1e-5 * $13 + 1e-9 || $12 / $11 - $13 > 1e-5 * $13 + 1e-9) { e = e " s/iter" }
  $3 ~ mit && $21 !~ /^(converged|target|time|max-iter)$/ { e = e " stop" }
  ($21 == "converged") != ($17 == "yes") || ($21 == "max-iter" && $11 != $10) { e = e " stop/converged/cap" }
  $2 != "ttq" && ($20 != "-" || $21 == "target" || $21 == "time") { e = e " ttq fields outside ttq" }
  $2 != "ttq" && $2 != "comparison" && $2 != "integration" && $22 != "-" { e = e " batch outside ttq, comparison and integration" }
  $22 != "-" && !int_($22) { e = e " batch" }
  $2 == "ttq" && (!num($20) || !int_($22) || $3 ~ mpd) { e = e " ttq fields" }
  $10 != "-" && $2 != "ttq" && ($11 != $10 || $17 != "no") { e = e " capped" }
  ($2 == "comparison" || $2 == "integration") && $3 ~ mit && $17 != "yes" { e = e " not converged" }
  e != "" { print $1 ":" e }')
check "every row well formed${bad_rows:+ (bad: $bad_rows)}" [ -z "$bad_rows" ]
keys=$(grep -v '^#' "$csv" | awk -F, '$2 == "comparison" { print ($3 == "cfpo" ? $4 : $3) }' | sort -u | tr '\n' ' ')
check "comparison has all $N_COMP methods of scripts/methods.tsv (found: $keys; want: $COMP_SEEN)" [ "$keys" = "$COMP_SEEN" ]
for e in evolution comparison runtime integration ttq; do check "experiment $e present" grep -q "^[0-9]*,$e," "$csv"; done
# the comparison's sets per method: the profile's sets, fewer where comp_sets says
SETS_P=$($BENCH profile smoke | sed -n 's/^sets=//p'); COMP_SETS=$($BENCH profile smoke | sed -n 's/^comp_sets=//p')
badcs=$(grep -v '^#' "$csv" | awk -F, -v sets="$SETS_P" -v cs="$COMP_SETS" '
  BEGIN { n = split(cs, a, " "); for (i = 1; i <= n; i++) { split(a[i], b, ":"); want[b[1]] = b[2] } }
  $2 == "comparison" { c[$3 == "cfpo" ? $4 : $3]++ }
  END { for (k in c) if (c[k] != ((k in want) ? want[k] : sets)) printf "%s:%d ", k, c[k] }')
check "comparison: $SETS_P sets a method, as comp_sets ($COMP_SETS) says for the others${badcs:+ (bad: $badcs)}" [ -z "$badcs" ] && [ -n "$COMP_SETS" ]
# every iterative baseline of the list (CCVT, CCDT and BNOT among them) in the
# comparison, runtime and convergence experiments and in summary.md
for k in $(methods_keys iter); do
  m=$(method_get "$k" method); l=$(method_get "$k" label)
  check "$l in the comparison and runtime experiments" \
    [ "$(grep -v '^#' "$csv" | awk -F, -v m="$m" '$3 == m && ($2 == "comparison" || $2 == "runtime") { print $2 }' | sort -u | wc -l)" -eq 2 ]
  check "$l in the convergence figure's data" grep -q "'$k'" "$R/plotdata/fig-convergence.vars.gp"
  check "$l in the runtime figure's data" grep -q "LBL\[[0-9]*\] = '$l'" "$R/plotdata/fig-runtime.vars.gp"
  check "summary.md: a $l row in the comparison table" grep -q "^| $l | " "$R/summary.md"
done
for g in comparison-ccvt comparison-ccdt comparison-bnot; do check "spectra.csv has the group $g" grep -q "^$g," "$R/spectra.csv"; done
threads=$(grep -v '^#' "$csv" | awk -F, '$2 == "runtime" && $3 == "cfpo" { print $8 }' | sort -un | tr '\n' ' ')
want=$($BENCH profile smoke | sed -n 's/^rt_threads=//p' | tr ' ' '\n' | sort -un | tr '\n' ' ')
check "runtime has CFPO on $want threads (found: $threads)" [ "$threads" = "$want" ]
if command -v mpirun >/dev/null && [ "$(nproc)" -ge 2 ]; then
  # CFPO on several ranks: present, and the same set as on one rank (the
  # same iterations and statistics at each n and seed)
  mpi=$(grep -v '^#' "$csv" | awk -F, '$2 == "runtime" && $3 == "cfpo" && $9 > 1' | wc -l)
  check "runtime has CFPO on several ranks ($mpi rows)" [ "$mpi" -gt 0 ]
  diffr=$(grep -v '^#' "$csv" | tail -n +2 | awk -F, '$2 != "ttq" && $3 == "cfpo" && $4 == "paper" && $10 == "-" {
      k = $6 "/" $7; v = $11 "/" $14 "/" $15
      if ($9 == 1) one[k] = v; else many[k] = v }
    END { for (k in many) if (!(k in one) || one[k] != many[k]) printf "%s ", k }')
  check "CFPO on several ranks gives the one-rank result${diffr:+ (differs: $diffr)}" [ -z "$diffr" ]
fi
for f in $(grep -v '^#' "$csv" | tail -n +2 | cut -d, -f19 | grep -v '^-$'); do
  [ -s "$R/$f" ] || { bad "trace $f missing"; break; }
done
ok

# the evolution snapshot after K iterations is the state of row K of the
# comparison run's trace (same seed; the output is thread-independent)
mism=$(grep -v '^#' "$csv" | awk -F, -v R="$R" '
  $2 == "comparison" && $3 == "cfpo" && $4 == "paper" { tr[$7] = $19 }
  $2 == "evolution" { ev[NR] = $0 }
  END { for (i in ev) { split(ev[i], a, ","); f = R "/" tr[a[7]]; d = ""
    while ((getline line < f) > 0) { split(line, b, "\t"); if (b[1] == a[10]) d = b[2] }
    close(f)
    if (d == "" && a[10] == 0) continue
    if (d == "" || d - a[14] > 1e-6 || a[14] - d > 1e-6) print a[1] } }')
check "evolution rows match the comparison traces${mism:+ (rows: $mism)}" [ -z "$mism" ]

# ---- time to quality ---------------------------------------------------------------
prof() { $BENCH profile smoke | sed -n "s/^$1=//p"; }
ttq_sizes=$(prof ttq_sizes); ttq_seeds=$(prof ttq_seeds); ttq_configs=$(prof ttq_configs)
tmin=$(prof ttq_target_min); tavg=$(prof ttq_target_avg)
want_ttq=$(for n in $ttq_sizes; do for s in $(seq 1 "$ttq_seeds"); do for c in $ttq_configs; do echo "$n/$s/${c%:*}/${c#*:}"; done; done; done | sort | tr '\n' ' ')
got_ttq=$(grep -v '^#' "$csv" | awk -F, '$2 == "ttq" { print $6 "/" $7 "/" ($3 == "cfpo" ? $4 : $3) "/" $8 }' | sort | tr '\n' ' ')
check "ttq runs are the planned configurations (want: $want_ttq; got: $got_ttq)" [ "$want_ttq" = "$got_ttq" ]
# batches: one n and seed each; several runs only when all have one thread,
# at most one per core; adaptive CFPO on one thread shares its batch with FPO
badb=$(grep -v '^#' "$csv" | awk -F, -v cores="$(nproc)" '$2 == "ttq" {
    b = $22; c[b]++; k = $6 "/" $7; if ((b in key) && key[b] != k) bad[b] = 1; key[b] = k; if ($8 > 1) multi[b] = 1
    m = ($3 == "cfpo" ? $4 : $3) $8; if (m == "adaptive1") ad[b] = 1; if (m == "fpo1") fp[b] = 1 }
  END { for (b in c) if (bad[b] || c[b] > cores || ((b in multi) && c[b] > 1)) printf "%s ", b
        if (cores >= 2) for (b in ad) if (!(b in fp)) printf "%s(cfpo without fpo) ", b }')
check "ttq batches well formed${badb:+ (bad: $badb)}" [ -z "$badb" ]
# comparison batches (COMP_TOGETHER): one method and one thread each, at
# most one run per core, every one-thread run in one when there are 2 cores
badc=$(grep -v '^#' "$csv" | awk -F, -v cores="$(nproc)" '$2 == "comparison" {
    b = $22; if (b == "-") { if (cores >= 2 && $8 == 1) printf "%s(alone) ", $1; next }
    m = $3 "/" $4; c[b]++; if ((b in key) && key[b] != m) bad[b] = 1; key[b] = m; if ($8 > 1) bad[b] = 1 }
  END { for (b in c) if (bad[b] || c[b] > cores) printf "%s ", b }')
check "comparison batches well formed${badc:+ (bad: $badc)}" [ -z "$badc" ]
# each run stopped by the rule its own trace shows
badt=$(grep -v '^#' "$csv" | awk -F, -v R="$R" -v a="$tmin" -v b="$tavg" '$2 == "ttq" {
    f = R "/" $19; first = ""; last = ""; lel = ""; rows = 0
    while ((getline line < f) > 0) { if (++rows == 1) continue; split(line, t, "\t"); last = t[1]; lel = t[8]
      if (first == "" && t[2] >= a && t[3] >= b) first = t[1] }
    close(f)
    ok = (last == $11)
    if ($21 == "target") ok = ok && first == last
    else if ($21 == "converged") ok = ok && (first == "" || first == last)
    else ok = ok && first == ""
    if ($21 == "time") ok = ok && lel >= $20
    if (!ok) printf "%s(stop=%s first=%s last=%s) ", $1, $21, first, last }')
check "ttq runs stop where their traces say${badt:+ (bad: $badt)}" [ -z "$badt" ]
check "a ttq run reaches the target in smoke" grep -Eq '^[0-9]+,ttq,.*,target,[0-9]+$' "$csv"
q="$R/quality.csv"
check "quality.csv header" [ "$(head -n 1 "$q")" = "run,n,K,certify,cert_pass,cert_max_violation,lct_pass,spike_ratio,spike_k,lattice_ratio,lattice_k" ]
badq=$(awk -F, 'FNR == NR { if ($2 == "ttq") { want[$1] = $5 } next }
  FNR > 1 { if (!($1 in want) || $2 != want[$1] || NF != 11 || $4 !~ /^(pass|fail)$/ || !($5 >= 0 && $5 <= 1) || !($7 >= 0 && $7 <= 1) ||
      !($8 > 1 && $8 < 1000) || $9 !~ /^-?[0-9]+;-?[0-9]+$/ ||
      !($10 == "-" && $11 == "-" || $10 >= 0 && $10 <= $8 && $11 ~ /^(0;[0-9]+|[0-9]+;0)$/)) printf "%s ", $1; seen[$1]++ }
  END { for (r in want) if (seen[r] != 1) printf "missing:%s ", r }' <(grep -v '^#' "$csv") "$q")
check "quality.csv: one well-formed row per ttq run${badq:+ (bad: $badq)}" [ -z "$badq" ]
# summary.md: a table per n, a row per configuration, and the FPO row's
# time to delta_avg >= 0.929 and the adaptive CFPO ratio recomputed from
# the traces (one seed in smoke, so the medians are the runs' own values)
for n in $ttq_sizes; do
  check "summary.md: time-to-quality table for n = $n" grep -q "^### n = $n (time limit [0-9.]* s)" "$R/summary.md"
  rows_n=$(awk -v n="$n" '/^### n = / { on = ($4 == n) } /^## / { on = 0 } on && /^\| (CFPO|FPO|LFPO)/' "$R/summary.md")
  check "summary.md: $(echo "$ttq_configs" | wc -w) rows of 17 cells for n = $n" \
    [ "$(grep -c . <<<"$rows_n")" -eq "$(echo "$ttq_configs" | wc -w)" ] && [ -z "$(awk -F' [|] ' 'NF != 17' <<<"$rows_n")" ]
  t_of() { grep -v '^#' "$csv" | awk -F, -v R="$R" -v n="$n" -v k="$1" '$2 == "ttq" && $6 == n && $7 == 1 && ($3 == "cfpo" ? $4 : $3) == k && $8 == 1 {
      f = R "/" $19; while ((getline line < f) > 0) { split(line, t, "\t"); if (t[1] ~ /^[0-9]+$/ && t[3] >= 0.929) { print t[8]; exit } } }'; }
  tf=$(t_of fpo); tc=$(t_of adaptive)
  fcell=$(awk -v x="$tf" 'BEGIN { if (x == "") print "never"; else if (x >= 100) printf "%.0f", x; else if (x >= 10) printf "%.1f", x; else if (x >= 1) printf "%.2f", x; else printf "%.3g", x }')
  # FPO short of the level: "-", or "≥ x" (x: FPO's seconds at its stop over CFPO's) when its time limit stopped it
  fstop=$(grep -v '^#' "$csv" | awk -F, -v R="$R" -v n="$n" '$2 == "ttq" && $6 == n && $3 == "fpo" { f = R "/" $19; while ((getline line < f) > 0) { split(line, t, "\t"); e = t[8] } print $21 "," e; exit }')
  rcell=$(awk -v f="$tf" -v c="$tc" -v s="${fstop%,*}" -v e="${fstop#*,}" 'BEGIN { if (c == "") print "-"; else if (f != "") printf "%.2f", f / c; else if (s == "time") printf "≥ %.2f", e / c; else print "-" }')
  check "summary.md: FPO reaches delta_avg 0.929 at $fcell s (trace)" grep -q "^| FPO | 1 | [0-9]* | $fcell |" <<<"$rows_n"
  check "summary.md: CFPO (adaptive) 1 thread, FPO / this at delta_avg 0.929 = $rcell" \
    awk -F' [|] ' -v r="$rcell" '$1 == "| CFPO (adaptive)" && $2 == 1 { found = 1; if ($14 != r) exit 1 } END { exit !found }' <<<"$rows_n"
  crun=$(grep -v '^#' "$csv" | awk -F, -v n="$n" '$2 == "ttq" && $6 == n && $7 == 1 && $3 == "cfpo" && $4 == "adaptive" && $8 == 1 { print $1; exit }')
  lcell=$(awk -F, -v r="$crun" '$1 == r { if ($10 == "-") print "-"; else printf "%.1f", $10 }' "$q")
  check "summary.md: CFPO (adaptive) 1 thread, lattice ratio $lcell (quality.csv, run $crun)" \
    awk -F' [|] ' -v l="$lcell" '$1 == "| CFPO (adaptive)" && $2 == 1 { found = 1; if ($13 != l || l == "") exit 1 } END { exit !found }' <<<"$rows_n"
done
# the plan lists exactly these runs, the ttq ones with their limit and batch
$BENCH run "$B" smoke --plan >"$T/plan" 2>&1
check "--plan lists one line per run made ($(grep -c '^[a-z]' "$T/plan") lines for $rows runs)" \
  [ "$(grep -Ec '^(evolution|comparison|runtime|integration|ttq) ' "$T/plan")" -eq "$rows" ]
check "--plan: ttq runs with time_limit and batch" \
  [ "$(grep -Ec '^ttq .* time_limit=[0-9.]+s batch=[0-9]+$' "$T/plan")" -eq "$(echo $want_ttq | wc -w)" ]
check "--plan: the total" grep -Eq "^bench: profile smoke: $rows runs, about [0-9]+ min" "$T/plan"

# ---- spectra.csv ------------------------------------------------------------------
groups=$(tail -n +2 "$R/spectra.csv" | cut -d, -f1 | tr '\n' ' ')
ng=$(tail -n +2 "$R/spectra.csv" | wc -l)
n_evo=$(prof evo_iters | wc -w)
check "spectra.csv: $n_evo evolution + $N_COMP comparison groups (found $ng: $groups)" [ "$ng" -eq $((n_evo + N_COMP)) ]
for g in $groups; do
  check "analysis of $g (spectrum, raps)" [ -s "$R/data/analysis/$g/spectrum.txt" ] && [ -s "$R/data/analysis/$g/raps.txt" ]
  check "seed-1 point set of $g" [ -s "$R/data/points/$g.txt" ]
done
SPEC_NEW="p0,h_index,lowk_alpha,disc_wrap_l2,disc_diaphony,disc_l2_star,disc_gen_l2,disc_centred_l2,shiftvar_gauss_0.02,shiftvar_gauss_0.05,shiftvar_gauss_0.15,shiftvar_disk_0.1,shiftvar_disk_0.25,shiftvar_disk_0.4"
check "spectra.csv: 33 columns, spike ratio (average and per-set mean) and its k, then the measures of sampling research" \
  awk -F, -v new="$SPEC_NEW" 'NR == 1 { n = split(new, c, ","); for (i = 1; i <= n; i++) if ($(19 + i) != c[i]) exit 1
      exit !($17 == "spike_ratio" && $18 == "spike_k" && $19 == "spike_ratio_set_mean" && NF == 33) }
    NF != 33 || !($17 > 1 && $17 < 1000) || $18 !~ /^-?[0-9]+;-?[0-9]+$/ || !($19 > 1 && $19 < 1000) { exit 1 }' "$R/spectra.csv"
# the new columns of the converged sets: numbers in their ranges (P0 of white
# noise about 1, of the blue-noise sets far below; discrepancies in (0, 1);
# variances positive, white noise's the largest)
badm=$(awk -F, 'NR > 1 && $2 == "comparison" {
    for (i = 20; i <= 33; i++) if ($i !~ /^-?[0-9.]+(e[-+]?[0-9]+)?$/) { printf "%s(col %d) ", $1, i; next }
    for (i = 23; i <= 27; i++) if (!($i > 0 && $i < 1)) printf "%s(disc %d) ", $1, i
    for (i = 28; i <= 33; i++) if (!($i > 0)) printf "%s(var %d) ", $1, i
    if ($3 == "white") { if (!($20 > 0.7 && $20 < 1.4)) printf "white(p0 %s) ", $20; wv = $32 } else if ($32 > mv) mv = $32
    if ($3 == "bnot" && !($20 < 0.01)) printf "bnot(p0 %s) ", $20 }
  END { if (!(wv > mv)) printf "white noise variance %s not the largest (%s) ", wv, mv }' "$R/spectra.csv")
check "spectra.csv: the measures in their ranges${badm:+ (bad: $badm)}" [ -z "$badm" ]
check "BS and Bridson averaged by cfpo-analyze --any-n, same-n groups by plain cfpo-analyze" \
  awk -F, 'NR > 1 && (($3 == "bs" || $3 == "bridson") != ($16 == "cfpo-analyze --any-n") || $16 !~ /^cfpo-analyze/) { exit 1 }' "$R/spectra.csv"
# the BS and Bridson rows: n is the mean of their runs' n (runs.csv column n)
badn=$(awk -F, 'FNR == NR { if ($2 == "comparison") { s[$3] += $5; c[$3]++ } next }
  FNR > 1 && ($3 == "bs" || $3 == "bridson") { m = sprintf("%.1f", s[$3] / c[$3]); if ($5 != m) printf "%s(%s, runs %s) ", $1, $5, m }' \
  <(grep -v '^#' "$csv") "$R/spectra.csv")
check "spectra.csv: n of BS and Bridson is their runs' mean${badn:+ (bad: $badn)}" [ -z "$badn" ]

# ---- integration.csv: one row per method of the comparison and n of the profile --------
ic="$R/integration.csv"
check "integration.csv header" [ "$(head -n 1 "$ic")" = "group,method,variant,n,n_target,sets,runs,K,averaged_by,shiftvar_gauss_0.02,shiftvar_gauss_0.05,shiftvar_gauss_0.15,shiftvar_disk_0.1,shiftvar_disk_0.25,shiftvar_disk_0.4,p0,h_index,lowk_alpha,delta_min,delta_avg,spike_ratio,utk_gauss_mse,utk_heaviside_mse" ]
want_int=$(for k in $(methods_keys pd direct iter cfpo); do for n in $(prof int_n); do echo "integration-$k-n$n"; done; done | sort | tr '\n' ' ')
got_int=$(tail -n +2 "$ic" | cut -d, -f1 | sort | tr '\n' ' ')
check "integration.csv: a row per method and n (want: $want_int; got: $got_int)" [ "$want_int" = "$got_int" ]
# each row: its runs (ranges a;b-c) are the runs.csv rows of that method and
# n_target whose sets the experiment took (comparison at its n, the
# integration runs, one-thread runtime runs), as many as sets; variances > 0
# and white noise's the largest at each n
badi=$(awk -F, 'FNR == NR { if ($1 ~ /^[0-9]+$/) { k = ($3 == "cfpo") ? $4 : $3; key[$1] = k "/" $6; ex[$1] = $2; th[$1] = $8 } next }
  FNR > 1 { g = $1; sub(/^integration-/, "", g); sub(/-n[0-9]+$/, "", g); m = split($7, parts, ";"); c = 0
    for (i = 1; i <= m; i++) { split(parts[i], ab, "-"); hi = (ab[2] == "" ? ab[1] : ab[2])
      for (r = ab[1]; r <= hi; r++) { c++; if (key[r] != g "/" $5 || !(ex[r] == "comparison" || ex[r] == "integration" || (ex[r] == "runtime" && th[r] == 1))) printf "%s(run %d) ", $1, r } }
    if (c != $6) printf "%s(%d runs, %s sets) ", $1, c, $6
    for (i = 10; i <= 15; i++) if (!($i > 0)) printf "%s(col %d) ", $1, i
    if (g == "white") wv[$5] = $14; else if ($14 > mv[$5]) mv[$5] = $14 }
  END { for (n in wv) if (!(wv[n] > mv[n])) printf "white noise not the largest at %s ", n }' <(grep -v '^#' "$csv") "$ic")
check "integration.csv: rows cite their runs, positive variances${badi:+ (bad: $badi)}" [ -z "$badi" ]
# the integration experiment made only the sets the others did not: no
# (method, n, seed) twice among the sets it took
dup=$(grep -v '^#' "$csv" | awk -F, '$2 == "integration" { k = ($3 == "cfpo" ? $4 : $3) "/" $6 "/" $7; i[k] = 1 }
  $2 == "runtime" && $8 == 1 && $9 == 1 { k = ($3 == "cfpo" ? $4 : $3) "/" $6 "/" $7; r[k] = 1 }
  END { for (k in i) if (k in r) printf "%s ", k }')
check "integration runs only where no runtime run of one thread made the set${dup:+ (twice: $dup)}" [ -z "$dup" ]
# summary.md: the figure data are integration.csv's (disk r = 0.25 of the last row)
last=$(tail -n 1 "$ic" | awk -F, '{ printf "%s\t%s\t%s", $4, $14, $11 }')
check "plotdata/integration.dat holds integration.csv's last row ($last)" grep -qF "$last" "$R/plotdata/integration.dat"

# summary.md's low-frequency table per method and n: a row per integration.csv
# row, its P0 (column 6) that row's p0, every P0 > 0
lown=$(awk '/^## Low-frequency measures per method and n/ { on = 1; next } on && /^## / { on = 0 } on && /^\| / && !/^\| (method|---)/' "$R/summary.md")
check "summary.md: a low-frequency row per integration.csv row ($(grep -c . <<<"$lown") of $(($(wc -l <"$ic") - 1)))" \
  [ "$(grep -c . <<<"$lown")" -eq "$(($(wc -l <"$ic") - 1))" ]
badp=$(awk -F, 'FNR == NR { if (FNR > 1) { if (!($16 > 0)) print "p0 " $1; want[sprintf("%.3g", $16)]++ } next }
  { split($0, c, " [|] "); if (!(c[6] in want) || want[c[6]] == 0) print "row " c[1] " " c[3] " P0 " c[6]; else want[c[6]]-- }' "$ic" - <<<"$lown")
check "summary.md: the P0 of each (method, n) is integration.csv's${badp:+ (bad: $badp)}" [ -z "$badp" ]

# ---- the profile seeds (planned only): no evolution, runtime or ttq runs; the
# comparison at 65,536 points with the profile's sets per method (fewer for
# the slow ones, none for some); the integration experiment's 10 seeds of
# every method at 4,096
$BENCH run "$B" seeds --plan >"$T/plan-seeds" 2>&1
check "seeds plan: no evolution, runtime or ttq runs" [ "$(grep -Ec '^(evolution|runtime|ttq) ' "$T/plan-seeds")" -eq 0 ]
sp() { $BENCH profile seeds | sed -n "s/^$1=//p"; }
bads=$(cs=$(sp comp_sets); for k in $(methods_keys pd direct iter cfpo); do c=$(grep -Ec "^comparison $k +n=65536 " "$T/plan-seeds")
  w=$(tr ' ' '\n' <<<"$cs" | sed -n "s/^$k://p"); w=${w:-$(sp sets)}; [ "$c" -eq "$w" ] || printf '%s(%s, want %s) ' "$k" "$c" "$w"
  i=$(grep -Ec "^integration $k +n=4096 " "$T/plan-seeds"); [ "$i" -eq 10 ] || printf '%s(4096: %s) ' "$k" "$i"; done)
check "seeds plan: comparison sets at 65,536 and 10 integration seeds at 4,096 per method${bads:+ (bad: $bads)}" [ -z "$bads" ]

# ---- the profile lowk (planned only): adaptive CFPO, the hyperuniform variant, FPO
# and BNOT only, the integration experiment from 2^10 to 2^20 (FPO and BNOT to 2^16)
$BENCH run "$B" lowk --plan >"$T/plan-lowk" 2>&1
others=$(grep -E '^(comparison|integration|evolution|runtime|ttq) ' "$T/plan-lowk" | awk '{ print $2 }' | sort -u | tr '\n' ' ')
check "lowk plan: only FPO, BNOT, adaptive and hyperuniform CFPO (got: $others)" [ "$others" = "adaptive bnot fpo hyperuniform " ]
check "lowk plan: the two CFPO variants to 2^20, FPO and BNOT to 2^16" \
  holds '[ "$(grep -Ec "^integration (adaptive|hyperuniform) +n=1048576 " "$T/plan-lowk")" -eq 6 ] && ! grep -Eq "^integration (fpo|bnot) +n=(262144|1048576) " "$T/plan-lowk"'

# ---- the profile density (planned only): the density part alone at 65,536
# points, 3 seeds, CFPO, DT and density FPO (LFPO, CCVT and BNOT left out);
# of the other experiments only the comparison's one set of adaptive CFPO
$BENCH run "$B" density --plan >"$T/plan-density" 2>&1
dp() { $BENCH profile density | sed -n "s/^$1=//p"; }
check "density plan: one comparison run of adaptive CFPO, nothing else ($(grep -Ec '^(comparison|integration|evolution|runtime|ttq) ' "$T/plan-density") runs)" \
  holds '[ "$(grep -Ec "^(comparison|integration|evolution|runtime|ttq) " "$T/plan-density")" -eq 1 ] && grep -Eq "^comparison adaptive +n=1024 " "$T/plan-density"'
check "density profile: the density part at 65,536 points, 3 seeds, without LFPO, CCVT and BNOT (got n=$(dp dens_n) seeds=$(dp dens_seeds) skip=$(dp dens_skip))" \
  [ "$(dp dens_n) $(dp dens_seeds) $(tr ' ' '\n' <<<"$(dp dens_skip)" | sort | tr '\n' ' ')" = "65536 3 bnot ccvt lfpo " ]

# ---- the low-frequency table: every number recomputes from spectra.csv --------------
lowtab=$(awk '/^## Low-frequency spectrum/ { on = 1; next } on && /^## / { on = 0 } on && /^\| / && !/^\| (method|---)/' "$R/summary.md")
check "summary.md: a low-frequency table row per method ($(grep -c . <<<"$lowtab") of $N_COMP)" [ "$(grep -c . <<<"$lowtab")" -eq "$N_COMP" ]
badl=$(awk -F, 'FNR == NR { if (FNR > 1 && $2 == "comparison") { s = ""
      split("20 21 22 23 24 25 26 27 31 32 33 28 29 30", c, " ")
      for (i = 1; i <= 14; i++) s = s " | " (($(c[i]) == "" || $(c[i]) == "-" || tolower($(c[i])) == "nan") ? "-" : sprintf("%.3g", $(c[i])))
      want[$1] = s " | `" $1 "` |" } next }
    { g = $0; sub(/.*`comparison-/, "comparison-", g); sub(/`.*/, "", g); row = $0; sub(/^\| [^|]* /, "", row)
      if (!(g in want) || row != substr(want[g], 2)) print g; seen[g] = 1 }
    END { for (g in want) if (!(g in seen)) print "missing " g }' "$R/spectra.csv" - <<<"$lowtab")
check "summary.md: the low-frequency table recomputes from spectra.csv${badl:+ (bad: $badl)}" [ -z "$badl" ]
check "summary.md: the low-frequency table defines its measures and links analysis/README.md" \
  grep -q '(../../analysis/README.md#measures-of-sampling-research-measures)' "$R/summary.md"
for d in '\*\*P0\*\*' '\*\*H\*\*' '\*\*α\*\*' '\*\*wrap-around L2' '\*\*Var disk r'; do
  check "summary.md defines $d" grep -q "^- $d" "$R/summary.md"
done
check "summary.md: CFPO (adaptive) beside CFPO in the comparison table" \
  grep -q "^| CFPO (adaptive) | [0-9]" "$R/summary.md"
check "summary.md: CFPO (hyperuniform) in the comparison and low-frequency tables" \
  [ "$(grep -c "^| CFPO (hyperuniform) | " "$R/summary.md")" -ge 2 ]

# ---- figures ----------------------------------------------------------------------
png_ok() { # PNG signature, then an IHDR chunk with a non-zero width and height
  [ -s "$1" ] || return 1
  [ "$(head -c 8 "$1" | od -An -tx1 | tr -d ' \n')" = 89504e470d0a1a0a ] || return 1
  [ "$(head -c 16 "$1" | tail -c 4)" = IHDR ] || return 1
  local w h
  w=$(head -c 20 "$1" | tail -c 4 | od -An -tu1 | awk '{ print $1 * 16777216 + $2 * 65536 + $3 * 256 + $4 }')
  h=$(head -c 24 "$1" | tail -c 4 | od -An -tu1 | awk '{ print $1 * 16777216 + $2 * 65536 + $3 * 256 + $4 }')
  [ "$w" -ge 400 ] && [ "$h" -ge 300 ] && [ "$(stat -c %s "$1")" -gt 10000 ]
}
FIGS="evolution comparison lowfreq convergence runtime speedup integration time-to-quality stipple 3d-slabs 3d progressive-prefixes progressive-sets"
for f in $FIGS; do
  check "fig-$f.png is a PNG image" png_ok "$R/fig-$f.png"
  check "summary.md shows fig-$f.png" grep -q "](fig-$f.png)" "$R/summary.md"
  check "scripts/fig-$f.gp exists" [ -f scripts/fig-$f.gp ]
done
# the 3-D part (scripts/benchlib/d3.py): one d3.csv row per 3-D command built, each
# with its analysis (delta, packing fraction, P0), and the table in summary.md
n3=$(ls "$B"/cfpo3d "$B"/cfpo3d-white "$B"/cfpo3d-jitter "$B"/cfpo3d-dart "$B"/cfpo3d-bridson "$B"/cfpo3d-wse "$B"/cfpo3d-fpo "$B"/cfpo3d-lloyd 2>/dev/null | wc -l)
check "d3.csv: one row per 3-D method ($n3), each measured" \
  holds '[ "$(tail -n +2 "$R/d3.csv" | wc -l)" -eq "$n3" ] && ! tail -n +2 "$R/d3.csv" | grep -q ",None,\|,,"'
check "summary.md: the 3-D table" grep -q "^| sample elimination | 0\.6" "$R/summary.md"
# the progressive part (scripts/benchlib/progressive.py): one row per method, each
# measured; every method's prefixes and drawn points; its tables in summary.md
check "progressive.csv: five rows, each measured" \
  holds '[ "$(tail -n +3 "$R/progressive.csv" | wc -l)" -eq 5 ] && ! tail -n +3 "$R/progressive.csv" | grep -q ",,"'
for k in cfpo wse pmj02bn sobol ordered; do
  check "progressive: $k's prefixes and points" \
    holds '[ "$(grep -c " dyadic " "$R/data/progressive/$k-s1.prefixes.txt")" -ge 5 ] && [ "$(wc -l <"$R/data/progressive/$k-s1.xy")" -eq 2048 ]'
done
check "summary.md: the progressive tables" \
  holds 'grep -q "^## Progressive sets" "$R/summary.md" && grep -q "^| PMJ02BN (seed 1) | 0\.[0-9]" "$R/summary.md"'
# cfpo-analyze writes pcf.txt: the g(r) figure, a panel per comparison group
npcf=$(find "$R/data/analysis" -path '*/comparison-*/pcf.txt' | wc -l)
check "the comparison's analyses hold pcf.txt" [ "$npcf" -ge 2 ]
check "no other PNG than the figures, fig-pcf.png among them" [ "$(find "$R" -name '*.png' | wc -l)" -eq 14 ] && png_ok "$R/fig-pcf.png"
check "fig-pcf: one panel per comparison group with pcf.txt" [ "$(grep -c "^GRP\[" "$R/plotdata/fig-pcf.vars.gp")" -eq "$npcf" ]
check "the low-frequency panel draws every method of the comparison" \
  [ "$(grep -c "^GRP\[[0-9]*\] = 'comparison-" "$R/plotdata/fig-lowfreq.vars.gp")" -eq "$N_COMP" ]

# ---- the density part: every method taking --density on the four densities --------
ac="$R/density.csv"
dm=cfpo
for k in $(methods_keys pd direct iter); do
  b=$($BENCH methods --get "$k" command | cut -d' ' -f1)
  "$B/$b" --help 2>/dev/null | grep -q -- --density && ! grep -qw "$k" <<<"$(prof dens_skip)" && dm="$dm $k"
done
want=$(($(wc -w <<<"$dm") * 4 * $(prof dens_seeds)))
check "density.csv: a row per density and method taking --density ($dm: $want)" [ "$(($(wc -l <"$ac") - 1))" -eq "$want" ]
bada=$(awk -F, 'NR == 1 { for (i = 1; i <= NF; i++) c[$i] = i; next }
  { dm = $c["density_delta_min"]; da = $c["density_delta_avg"]
    if (!(dm > 0 && dm <= da && da < 1.5)) printf "%s/%s(delta %s %s) ", $1, $2, dm, da
    if ($2 == "cfpo" && $3 != '"$(prof dens_n)"') printf "%s/cfpo(n %s) ", $1, $3
    if (!($c["count_fidelity_rms"] >= 0)) printf "%s/%s(fidelity) ", $1, $2 }' "$ac")
check "density.csv: local delta in (0, 1.5), exact n for CFPO, fidelity reported${bada:+ (bad: $bada)}" [ -z "$bada" ]
badp=$(for k in $dm; do f="$R/data/points/density-image-$k.txt"; n=$(awk -F, -v k="$k" '$1 == "image" && $2 == k && $4 == 1 { print $3 }' "$ac")
  [ -f "$f" ] && [ "$(grep -vc '^#' "$f")" = "$n" ] || printf '%s ' "$k"; done)
check "the density part keeps the image's seed-1 sets: one per method, n points each${badp:+ (bad: $badp)}" [ -z "$badp" ]
# the stippling figure's own runs: CFPO, DT, FPO and BNOT (those of them that
# take --density) at stipple_n, each set of exactly that n (CFPO's and the
# iterative ones') and drawn; the iterative ones capped at stipple_cap
sc="$R/stipple.csv"
sm=$(for k in cfpo dart fpo bnot; do grep -qw "$k" <<<"$dm $(prof dens_skip)" && echo "$k"; done | tr '\n' ' ')
check "stipple.csv: a row per method of the figure ($sm)" [ "$(tail -n +2 "$sc" | cut -d, -f1 | tr '\n' ' ')" = "$sm" ]
bads=$(tail -n +2 "$sc" | while IFS=, read -r k n s sec wall it stop args; do f="$R/data/points/stipple-$k.txt"
  [ -f "$f" ] && [ "$(grep -vc '^#' "$f")" = "$n" ] && [ "$s" = 1 ] || printf '%s(set) ' "$k"
  { [ "$k" = dart ] || [ "$n" = "$(prof stipple_n)" ]; } || printf '%s(n %s) ' "$k" "$n"
  { [ "$it" = - ] || [ "$it" -le "$(prof stipple_cap)" ]; } || printf '%s(iterations %s) ' "$k" "$it"
  grep -qF "FILE[" "$R/plotdata/fig-stipple.vars.gp" && grep -qF "'data/points/stipple-$k.txt'" "$R/plotdata/fig-stipple.vars.gp" || printf '%s(not drawn) ' "$k"; done)
check "stippling sets: n points each, seed 1, capped, drawn${bads:+ (bad: $bads)}" [ -z "$bads" ]
# the dots' radius: their total area n pi R^2 is the image's mean darkness (in (0, 1))
check "stippling dots: n pi R^2 in (0, 1)" awk -v n="$(prof stipple_n)" '/^DIR = / { for (i = 1; i <= NF; i++) if ($i == "R") r = $(i + 2); sub(/;$/, "", r) }
  END { a = n * 3.14159265 * r * r; exit !(a > 0 && a < 1) }' "$R/plotdata/fig-stipple.vars.gp"
check "summary.md: the density table, a row per density and method" \
  [ "$(awk '/^## Following a density/ { on = 1; next } on && /^## / { on = 0 } on && /^\| / && !/^\| (density|---)/' "$R/summary.md" | wc -l)" -eq "$(($(wc -w <<<"$dm") * 4))" ]

# ---- summary.md: numbers recompute from runs.csv ------------------------------------
for k in paper fpo; do
  row=$(grep -v '^#' "$csv" | awk -F, -v k="$k" '$2 == "comparison" && ($3 == "cfpo" ? $4 : $3) == k { s += $14; c++; id = id (id == "" ? "" : " ") $1 }
    END { printf "%.4f|%s", s / c, id }')
  mean=${row%%|*}
  ids=${row#*|}
  first=${ids%% *}; last=${ids##* }
  lbl=$(method_get "$k" label)
  check "summary.md: $lbl row cites runs $first-$last and delta_min mean $mean" \
    grep -q "^| $lbl | $first-$last | $mean ± " "$R/summary.md"
done

# ---- replot: from the folder alone ----------------------------------------------------
sum_before=$(md5sum "$csv" "$R/spectra.csv" "$R/integration.csv")
cp "$R/summary.md" "$T/summary.before"
rm -f "$R"/fig-*.png "$R/summary.md"
rm -rf "$R/plotdata"
if $BENCH replot "$R" >"$T/rout" 2>"$T/rerr"; then ok; else bad "bench.py replot failed: $(tail -n 1 "$T/rerr")"; fi
for f in $FIGS; do check "replot redrew fig-$f.png" png_ok "$R/fig-$f.png"; done
check "replot rewrote the same summary.md" cmp -s "$R/summary.md" "$T/summary.before"
check "replot left runs.csv, spectra.csv and integration.csv alone" [ "$(md5sum "$csv" "$R/spectra.csv" "$R/integration.csv")" = "$sum_before" ]
# a folder without time-to-quality runs (written before they existed)
old="$T/old"; cp -r "$R" "$old"
awk -F, '/^#/ || $2 != "ttq"' "$R/runs.csv" >"$old/runs.csv"; rm -f "$old/quality.csv" "$old/fig-time-to-quality.png"
if $BENCH replot "$old" >/dev/null 2>"$T/rerr2"; then ok; else bad "replot of a folder without ttq runs: $(tail -n 1 "$T/rerr2")"; fi
check "no ttq runs: no time-to-quality figure or section" holds '[ ! -e "$old/fig-time-to-quality.png" ] && ! grep -q "Time to quality" "$old/summary.md"'
check "no ttq runs: the integration figure still drawn" png_ok "$old/fig-integration.png"
rm -rf "$old"
# a folder written before the measures: spectra.csv of 19 columns, no integration.csv
old="$T/old2"; cp -r "$R" "$old"
cut -d, -f1-19 "$R/spectra.csv" >"$old/spectra.csv"; rm -f "$old/integration.csv"
if $BENCH replot "$old" >/dev/null 2>"$T/rerr3"; then ok; else bad "replot of a folder before the measures: $(tail -n 1 "$T/rerr3")"; fi
check "before the measures: no integration figure, no low-frequency table" \
  holds '[ ! -e "$old/fig-integration.png" ] && ! grep -q "^## Low-frequency" "$old/summary.md" && ! grep -q "^## Integration" "$old/summary.md"'
check "before the measures: the low-frequency panel still drawn (raps.txt)" png_ok "$old/fig-lowfreq.png"
# pair correlation: a pcf.txt in an averaged analysis gives the g(r) figure;
# without one, it goes (silently)
rm -f "$old"/data/analysis/*/pcf.txt
printf '# pair correlation, test data\n# r/Delta g\n0.1 0\n0.5 0\n0.9 1.8\n1.2 1.1\n2.0 1.0\n3.0 1.0\n' >"$old/data/analysis/comparison-paper/pcf.txt"
cp "$old/data/analysis/comparison-paper/pcf.txt" "$old/data/analysis/comparison-fpo/pcf.txt"
if $BENCH replot "$old" >/dev/null 2>"$T/rerr4"; then ok; else bad "replot with pcf.txt: $(tail -n 1 "$T/rerr4")"; fi
check "pcf.txt present: fig-pcf.png a PNG, shown in summary.md, one panel per such method" \
  holds 'png_ok "$old/fig-pcf.png" && grep -q "](fig-pcf.png)" "$old/summary.md" && [ "$(grep -c "^GRP\[" "$old/plotdata/fig-pcf.vars.gp")" -eq 2 ]'
rm -f "$old"/data/analysis/*/pcf.txt
if $BENCH replot "$old" >/dev/null 2>"$T/rerr5"; then ok; else bad "replot after pcf.txt went: $(tail -n 1 "$T/rerr5")"; fi
check "pcf.txt gone: no g(r) figure, no mention" holds '[ ! -e "$old/fig-pcf.png" ] && ! grep -q "fig-pcf" "$old/summary.md"'
rm -rf "$old"
# a folder written before the paper variant's key was `paper` and before the
# density part and the stippling runs had names of their own: the group
# comparison-cfpo, adaptive.csv and data/points/adaptive-image-KEY.txt, no
# stipple.csv; replot reads it as before
old="$T/old3"; cp -r "$R" "$old"
sed -i 's/^comparison-paper,/comparison-cfpo,/' "$old/spectra.csv"
mv "$old/data/analysis/comparison-paper" "$old/data/analysis/comparison-cfpo"
mv "$old/data/points/comparison-paper.txt" "$old/data/points/comparison-cfpo.txt"
mv "$old/density.csv" "$old/adaptive.csv"
for f in "$old"/data/points/density-image-*.txt; do mv "$f" "${f/density-image-/adaptive-image-}"; done
rm -f "$old/stipple.csv" "$old"/data/points/stipple-*.txt
if $BENCH replot "$old" >/dev/null 2>"$T/rerr6"; then ok; else bad "replot of a folder with the old names: $(tail -n 1 "$T/rerr6")"; fi
check "old names: the paper variant's row cites comparison-cfpo, the density table and the stippling figure are there" \
  holds 'grep -q "^| CFPO (paper) | .*\`comparison-cfpo\` |" "$old/summary.md" && grep -q "^## Following a density" "$old/summary.md" && png_ok "$old/fig-stipple.png" && grep -qF "adaptive-image-cfpo.txt" "$old/plotdata/fig-stipple.vars.gp" && png_ok "$old/fig-evolution.png"'
rm -rf "$old"
(cd "$T/res/.." && mkdir -p results && cp -r "$R" results/ && python3 "$SRC/scripts/bench.py" replot >/dev/null 2>&1)
check "replot without an argument takes the newest folder under results/" [ -s "$T/results/$(basename "$R")/fig-speedup.png" ]

# ---- errors: one line, non-zero, nothing left --------------------------------------------
one_line_err() { # expected-rc cmd...: exit status and one "prog: ..." line
  local want=$1; shift
  "$@" >"$T/e.out" 2>"$T/e.err"; local rc=$?
  [ "$rc" -eq "$want" ] && [ "$(wc -l <"$T/e.err")" -eq 1 ] && grep -Eq '^(bench|replot): ' "$T/e.err"
}
export CFPO_RESULTS="$T/res2"
check "unknown profile: exit 2, one line" one_line_err 2 $BENCH run "$B" huge
check "missing build: exit 1, one line" one_line_err 1 $BENCH run "$T/nobuild" smoke
check "bad sub-command: exit 2, one line" one_line_err 2 $BENCH bogus
check "failed runs leave no folder" [ ! -e "$T/res2" ] || [ -z "$(ls -A "$T/res2")" ]
mkdir -p "$T/notres"
check "replot of a folder without runs.csv: exit 1, one line" one_line_err 1 $BENCH replot "$T/notres"
# SIGTERM in the middle of the runs: neither the folder nor its temporary
$BENCH run "$B" smoke >/dev/null 2>&1 &
pid=$!
for _ in $(seq 1 50); do [ -n "$(ls -A "$T/res2" 2>/dev/null)" ] && break; sleep 0.1; done
sleep 1
kill -TERM "$pid" 2>/dev/null
wait "$pid"; rc=$?
check "SIGTERM: non-zero exit (got $rc)" [ "$rc" -ne 0 ]
check "SIGTERM: nothing left under the results root" [ -z "$(ls -A "$T/res2" 2>/dev/null)" ]
sleep 0.3
check "SIGTERM: no run left behind" [ -z "$(pgrep -f "$T/res2" || true)" ]

echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]
