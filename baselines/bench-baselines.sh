#!/usr/bin/env bash
# bench-baselines.sh [BUILD_DIR [OUT_DIR]] - CFPO against its baselines on
# this machine, with one stopping rule for every iterative method (cfpo's:
# a move must gain more than tol * L, converged when no point's net move
# over an iteration reaches tol * L; default tol).
#
#   FPO, LFPO, CFPO -t 1, CFPO -t 2 at n in $SIZES: seconds to converge (the
#   SUMMARY line's seconds: start included, output excluded), iterations,
#   seconds per iteration (mean of the trace's per-iteration seconds), and
#   the ratios FPO/CFPO and LFPO/CFPO (per run and per iteration).
#   DT, BS, Bridson at n in $PD_SIZES: points per second (points placed /
#   SUMMARY seconds) and the ratios to DT.
#
# Every configuration runs $REPS times (default 3); the table gives medians.
# The load average before and after is printed: on a shared 2-core machine,
# quote it with the numbers. Raw rows go to OUT_DIR/baselines-bench.tsv
# (default results/). Environment: REPS, SIZES, PD_SIZES (empty: skip), SEED, and
# METHODS (default "cfpo-t1 cfpo-t2" and the iterative baselines of
# scripts/methods.tsv), PD_METHODS (its Poisson-disk samplers)
# to run a part of the plan.
# bench-baselines.sh --table RAW... prints the table from raw files (e.g.
# several partial runs) without running anything.
# Example (quick): REPS=1 SIZES=4096 PD_SIZES=65536 baselines/bench-baselines.sh build
set -euo pipefail
# the methods: scripts/methods.tsv (kinds iter and pd, read by scripts/bench.py;
# the direct samplers, kind direct, converge to nothing and are left out),
# plus cfpo on 1 and 2 threads
BENCH_PY="$(cd "$(dirname "$0")/../scripts" && pwd)/bench.py"
ITER_KEYS=$(python3 "$BENCH_PY" methods iter)
PD_KEYS=$(python3 "$BENCH_PY" methods pd)

# print_table RAW...: medians and ratios of the rows in the raw files.
print_table() {
awk -F'\t' -v iters="$ITER_KEYS cfpo-t1 cfpo-t2" -v pds="$PD_KEYS" '
function median(key,   k, m, i, j, t, a) {
  m = cnt[key]; if (m == 0) return -1
  for (i = 1; i <= m; i++) a[i] = val[key, i]
  for (i = 2; i <= m; i++) { t = a[i]; for (j = i - 1; j >= 1 && a[j] > t; j--) a[j + 1] = a[j]; a[j + 1] = t }
  return (m % 2) ? a[(m + 1) / 2] : (a[m / 2] + a[m / 2 + 1]) / 2
}
function add(key, v) { cnt[key]++; val[key, cnt[key]] = v }
function ratio(a, b) { return (a > 0 && b > 0) ? sprintf("%10.2fx", a / b) : sprintf("%11s", "-") }
function addsize(list, n,   i, k, A) { k = split(list, A, " "); for (i = 1; i <= k; i++) if (A[i] == n) return list; return list " " n }
function sortsizes(list, out,   k, i, j, t) { k = split(list, out, " "); for (i = 2; i <= k; i++) { t = out[i] + 0; for (j = i - 1; j >= 1 && out[j] + 0 > t; j--) out[j + 1] = out[j]; out[j + 1] = t }; return k }
FNR == 1 { next }
{
  add($1 SUBSEP $2 SUBSEP "s", $4); add($1 SUBSEP $2 SUBSEP "it", $5)
  if ($6 != "-") add($1 SUBSEP $2 SUBSEP "spi", $6)
  add($1 SUBSEP $2 SUBSEP "pts", $7 / $4); add($1 SUBSEP $2 SUBSEP "np", $7)
  add($1 SUBSEP $2 SUBSEP "dmin", $9); add($1 SUBSEP $2 SUBSEP "davg", $10)
  conv[$1 SUBSEP $2] = conv[$1 SUBSEP $2] (conv[$1 SUBSEP $2] == "" ? "" : ",") $8
  if ($5 == "-") pdsizes = addsize(pdsizes, $2); else sizes = addsize(sizes, $2)
}
END {
  nms = split(iters, ms, " ")
  printf "\nIterative methods (medians; the same stopping rule and tolerance):\n"
  printf "%-8s %-8s %5s %10s %6s %11s %9s %9s  %s\n", "n", "method", "runs", "seconds", "iters", "s/iter", "dmin", "davg", "converged"
  ns = sortsizes(sizes, N)
  for (i = 1; i <= ns; i++) for (j = 1; j <= nms; j++) {
    k = ms[j] SUBSEP N[i]
    if (!cnt[k SUBSEP "s"]) continue
    printf "%-8s %-8s %5d %10.3f %6d %11.5f %9.4f %9.4f  %s\n", N[i], ms[j], cnt[k SUBSEP "s"], median(k SUBSEP "s"),
      median(k SUBSEP "it"), median(k SUBSEP "spi"), median(k SUBSEP "dmin"), median(k SUBSEP "davg"), conv[k]
  }
  printf "\nRatios (time of the first / time of the second; > 1: the second is faster):\n"
  printf "%-8s %-22s %11s %11s\n", "n", "ratio", "to converge", "per iter"
  # every baseline against cfpo on 1 and 2 threads, the later baselines
  # against the first, cfpo on 1 against 2 threads
  nb = nms - 2; rl = ""
  for (j = 1; j <= nb; j++) rl = rl " " ms[j] "/cfpo-t1 " ms[j] "/cfpo-t2"
  for (j = 2; j <= nb; j++) rl = rl " " ms[j] "/" ms[1]
  nrs = split(rl " cfpo-t1/cfpo-t2", rs, " ")
  for (i = 1; i <= ns; i++) for (j = 1; j <= nrs; j++) {
    split(rs[j], ab, "/")
    a = ab[1] SUBSEP N[i]; b = ab[2] SUBSEP N[i]
    if (!cnt[a SUBSEP "s"] || !cnt[b SUBSEP "s"]) continue
    printf "%-8s %-22s %s %s\n", N[i], ab[1] " / " ab[2], ratio(median(a SUBSEP "s"), median(b SUBSEP "s")),
      ratio(median(a SUBSEP "spi"), median(b SUBSEP "spi"))
  }
  np = sortsizes(pdsizes, P); npm = split(pds, pm, " ")
  if (np) {
    printf "\nPoisson-disk samplers (medians):\n"
    printf "%-9s %-8s %5s %10s %10s %14s %9s %9s %10s\n", "n", "method", "runs", "points", "seconds", "points/s", "dmin", "davg", "vs " pm[1]
  }
  for (i = 1; i <= np; i++) for (j = 1; j <= npm; j++) {
    k = pm[j] SUBSEP P[i]
    if (!cnt[k SUBSEP "s"]) continue
    pts = median(k SUBSEP "pts"); base = median(pm[1] SUBSEP P[i] SUBSEP "pts")
    printf "%-9s %-8s %5d %10d %10.3f %14.0f %9.4f %9.4f %s\n", P[i], pm[j], cnt[k SUBSEP "s"], median(k SUBSEP "np"),
      median(k SUBSEP "s"), pts, median(k SUBSEP "dmin"), median(k SUBSEP "davg"), ratio(pts, base)
  }
}' "$@"
}

if [ "${1:-}" = "--table" ]; then
  shift
  print_table "$@"
  exit 0
fi
B=${1:-build}
OUT=${2:-results}
REPS=${REPS:-3}
SIZES=${SIZES-"4096 16384 65536"}
PD_SIZES=${PD_SIZES-"65536 1048576"}
SEED=${SEED:-1}
METHODS=${METHODS:-"cfpo-t1 cfpo-t2 $ITER_KEYS"}
PD_METHODS=${PD_METHODS:-"$PD_KEYS"}
for c in cfpo $(python3 "$BENCH_PY" methods --binaries iter pd); do
  [ -x "$B/$c" ] || { echo "bench-baselines: $B/$c not found (build first)" >&2; exit 1; }
done
mkdir -p "$OUT"
RAW="$OUT/baselines-bench.tsv"
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
printf 'method\tn\trep\tseconds\titerations\ts_per_iter\tpoints\tconverged\tdelta_min\tdelta_avg\n' >"$RAW"

field() { sed -n "s/.* $1=\([^ ]*\).*/\1/p" <<<"$2"; }

# run NAME N REP CMD...: one run; appends a raw row.
run() {
  local name=$1 n=$2 rep=$3; shift 3
  local line
  line=$("$@" -q --trace "$TMP/trace.tsv" | grep '^SUMMARY') || { echo "bench-baselines: $name n=$n failed" >&2; exit 1; }
  local it spi
  it=$(field iterations "$line")
  if [ "$it" = "-" ]; then spi="-"; else
    spi=$(awk -F'\t' 'NR > 2 { s += $7; k++ } END { if (k) printf "%.6g", s / k; else print "-" }' "$TMP/trace.tsv")
  fi
  printf '%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\n' "$name" "$n" "$rep" "$(field seconds "$line")" "$it" "$spi" \
    "$(field n "$line")" "$(field converged "$line")" "$(field delta_min "$line")" "$(field delta_avg "$line")" >>"$RAW"
  printf '  %-12s n=%-8s rep %s: %ss, %s iterations, %s s/iter\n' "$name" "$n" "$rep" \
    "$(field seconds "$line")" "$it" "$spi" >&2
}

echo "# bench-baselines on $(hostname), $(nproc) cores, $(date -u +%FT%TZ)"
echo "# load before: $(cut -d' ' -f1-3 /proc/loadavg)"
# cmd_for METHOD N: the command line of one method.
cmd_for() {
  case $1 in
    cfpo-t1) echo "$B/cfpo -n $2 -s $SEED -t 1" ;;
    cfpo-t2) echo "$B/cfpo -n $2 -s $SEED -t 2" ;;
    *) local c
       c=$(python3 "$BENCH_PY" methods --get "$1" command)
       [ -n "$c" ] || { echo "bench-baselines: unknown method $1" >&2; exit 2; }
       echo "$B/$c -n $2 -s $SEED" ;;
  esac
}
for n in $SIZES; do
  for rep in $(seq 1 "$REPS"); do
    for m in $METHODS; do
      # shellcheck disable=SC2046
      run "$m" "$n" "$rep" $(cmd_for "$m" "$n")
    done
  done
done
for n in $PD_SIZES; do
  for rep in $(seq 1 "$REPS"); do
    for m in $PD_METHODS; do
      # shellcheck disable=SC2046
      run "$m" "$n" "$rep" $(cmd_for "$m" "$n")
    done
  done
done
echo "# load after: $(cut -d' ' -f1-3 /proc/loadavg)"

print_table "$RAW"
echo "# raw rows: $RAW"
