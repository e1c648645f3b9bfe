#!/usr/bin/env bash
# bench.sh BUILD_DIR [PROFILE] [--plan] - `make bench`: CFPO against its baselines,
# with the paper's figures (Chen & Gotsman, figures 5-8).
#
# Runs every method of the suite (the list: scripts/methods.tsv) as the plan
# of PROFILE (scripts/bench-profiles.sh: smoke, default, paper) says, then analyses the point sets with cfpo-analyze and
# draws the figures with scripts/replot.sh. Four experiments:
#   evolution   CFPO stopped after EVO_ITERS iterations, SETS seeds
#   comparison  every method, SETS seeds of COMP_N points (traces kept: they
#               are the convergence figure)
#   runtime     every method over n (and CFPO over thread counts)
#   ttq         time to quality: the iterative methods with --trace until a
#               quality target, convergence or a time limit; compared
#               one-thread runs start together, one per core
# Output: $CFPO_RESULTS (default results/)/<date>-<time>-<host>/ with runs.csv
# (one row per run, machine and build in # lines), spectra.csv (one row per
# averaged spectrum, naming its runs), quality.csv (certificate, spike and lattice
# ratio of every ttq run's final set), data/ (traces, seed-1 point sets,
# averaged spectra), plotdata/, fig-*.png and summary.md. The folder is built
# under a temporary name and renamed when complete: a failure or Ctrl-C leaves
# nothing (--plan: print the runs and the estimated time, run nothing;
# CFPO_BENCH_KEEP=1 keeps the temporary folder, for debugging). Progress on stderr: the run, k of N, elapsed, estimated time left.
set -euo pipefail
{ # the whole script is read before it runs: editing it during a run is safe
here=$(cd "$(dirname "$0")" && pwd)
# shellcheck source=bench-profiles.sh
. "$here/bench-profiles.sh"
# shellcheck source=methods.sh
. "$here/methods.sh"

die() { echo "bench: $*" >&2; exit 1; }
B=${1:-build}
PROFILE=${2:-default}
PLAN_ONLY=0
[ "${3:-}" = --plan ] && PLAN_ONLY=1
ROOT=${CFPO_RESULTS:-results}
bench_profile "$PROFILE" || { echo "bench: unknown PROFILE '$PROFILE' (smoke, default, paper)" >&2; exit 2; }
for c in $(methods_binaries) cfpo-analyze; do
  [ -x "$B/$c" ] || die "$B/$c not built (run make)"
done
command -v gnuplot >/dev/null 2>&1 || die "gnuplot not found (run scripts/install-deps.sh)"
B=$(cd "$B" && pwd)
mkdir -p "$ROOT" || die "cannot create $ROOT"
name="$(date +%Y%m%d-%H%M%S)-$(hostname -s)"
final="$ROOT/$name"
[ -e "$final" ] && die "$final already exists"
work="$ROOT/.$name.tmp.$$"
ticker=""
children=()
cleanup() {
  # no errexit in here: killing a run that has just ended fails, and that
  # must not end the cleanup before the folder goes
  set +e
  [ -n "$ticker" ] && kill "$ticker" 2>/dev/null
  local p
  for p in "${children[@]}"; do kill "$p" 2>/dev/null; done
  # the killed runs may still be writing into the folder: let them end
  # (at most 5 s) before it goes
  local k
  for p in "${children[@]}"; do
    for ((k = 0; k < 100; k++)); do kill -0 "$p" 2>/dev/null || break; sleep 0.05; done
  done
  if [ "${CFPO_BENCH_KEEP:-0}" = 1 ] && [ -d "$work" ]; then
    echo "bench: kept $work (CFPO_BENCH_KEEP=1)" >&2
    return
  fi
  # a run that is still ending can add or remove a file while rm walks the
  # folder, and rm then leaves it behind: try again for up to 5 s
  for ((k = 0; k < 50; k++)); do
    rm -rf "$work" 2>/dev/null
    [ -e "$work" ] || break
    sleep 0.1
  done
}
trap cleanup EXIT
trap 'exit 130' INT
trap 'exit 143' TERM HUP
mkdir -p "$work/data/traces" "$work/data/points" "$work/data/analysis" "$work/sets" "$work/tmp"
T0=$(date +%s.%N)

# ---- the plan: one line per run -------------------------------------------
# experiment key n seed threads max_iter estimate output time_limit batch
# (batch: runs with the same number start together; - runs alone)
plan="$work/tmp/plan.tsv"
: >"$plan"
cores=$(nproc)
# add EXP KEY N SEED THREADS MAXITER OUT [BATCH]
add() { printf '%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t-\t%s\n' "$1" "$2" "$3" "$4" "$5" "$6" "$(bench_estimate "$2" "$3" "$5" "$6")" "$7" "${8:--}" >>"$plan"; }
batch=0
for it in $EVO_ITERS; do
  for s in $(seq 1 "$SETS"); do add evolution cfpo "$COMP_N" "$s" "$cores" "$it" "sets/evolution-it$it-s$s.txt"; done
done
COMP_KEYS=$(methods_keys pd iter cfpo)
CFPO_KEYS=" $(methods_keys cfpo) "
PD_KEYS=" $(methods_keys pd) "
is_cfpo() { [[ $CFPO_KEYS == *" $1 "* ]]; }
is_pd() { [[ $PD_KEYS == *" $1 "* ]]; }
# the comparison: one-thread runs of one method in groups of COMP_TOGETHER
# (at most one per core) that start together, each pinned to its own core
together=$COMP_TOGETHER
[ "$together" -gt "$cores" ] && together=$cores
for k in $COMP_KEYS; do
  t=1; is_cfpo "$k" && t=$COMP_THREADS
  slot=0
  for s in $(seq 1 "$SETS"); do
    if [ "$t" -gt 1 ] || [ "$together" -le 1 ]; then add comparison "$k" "$COMP_N" "$s" "$t" - "sets/comparison-$k-s$s.txt"; continue; fi
    [ "$slot" -eq 0 ] && batch=$((batch + 1))
    add comparison "$k" "$COMP_N" "$s" "$t" - "sets/comparison-$k-s$s.txt" "$batch"
    slot=$(((slot + 1) % together))
  done
done
for k in $(methods_keys cfpo) $(methods_keys iter) $(methods_keys pd); do
  var="RT_SIZES_$k"
  for n in ${!var}; do
    threads=1; is_cfpo "$k" && threads=$RT_THREADS
    for t in $threads; do
      # covered by the comparison's runs (same n, threads, seeds)
      ct=1; is_cfpo "$k" && ct=$COMP_THREADS
      [ "$n" = "$COMP_N" ] && [ "$t" = "$ct" ] && [ "$RT_REPS" -le "$SETS" ] && continue
      for s in $(seq 1 "$RT_REPS"); do add runtime "$k" "$n" "$s" "$t" - -; done
    done
  done
done
# CFPO on several ranks (one thread each, as many ranks as cores) at the
# runtime sizes, when mpirun is here: the speedup figure's ranks lines.
MPIRUN=$(command -v mpirun || true)
if [ -n "$MPIRUN" ] && [ "$cores" -ge 2 ]; then
  for n in $RT_SIZES_cfpo; do
    for s in $(seq 1 "$RT_REPS"); do add runtime cfpo-mpi "$n" "$s" 1 - -; done
  done
fi
# Time to quality: per n and seed, the one-thread configurations in groups
# of `cores` that start together (a batch), each pinned to its own core; a
# configuration on several threads is a batch of its own.
add_ttq() { # key n seed threads
  local lim
  lim=$(bench_ttq_limit "$2")
  printf 'ttq\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\n' "$1" "$2" "$3" "$4" "$TTQ_MAXITER" \
    "$(bench_ttq_estimate "$1" "$2" "$4" "$TTQ_MAXITER" "$lim")" "sets/ttq-$1-t$4-n$2-s$3.bin" "$lim" "$batch" >>"$plan"
}
for n in $TTQ_SIZES; do
  for s in $(seq 1 "$TTQ_SEEDS"); do
    slot=0
    cv="TTQ_CONFIGS_$n"
    for c in ${!cv:-$TTQ_CONFIGS}; do
      key=${c%:*}; t=${c#*:}
      if [ "$t" -gt 1 ] || [ "$slot" -eq 0 ] || [ "$slot" -ge "$cores" ]; then batch=$((batch + 1)); slot=0; fi
      if [ "$t" -gt 1 ]; then slot=$cores; else slot=$((slot + 1)); fi
      add_ttq "$key" "$n" "$s" "$t"
    done
  done
done
for n in $TTQ_BIG; do
  for s in $(seq 1 "$TTQ_SEEDS"); do batch=$((batch + 1)); add_ttq adaptive "$n" "$s" 2; done
done
# the CPUs this process may use: one-thread runs of a batch are pinned to
# them in order (when taskset is here)
TASKSET=$(command -v taskset || true)
CPUS=()
if [ -n "$TASKSET" ]; then
  read -r -a CPUS <<<"$("$TASKSET" -cp $$ 2>/dev/null | sed 's/.*: *//' | tr ',' '\n' |
    awk -F- 'NF == 2 { for (c = $1; c <= $2; c++) printf "%d ", c; next } NF == 1 && $1 != "" { printf "%d ", $1 }')"
  [ "${#CPUS[@]}" -ge 1 ] || TASKSET=""
fi
# mpirun refuses root unless told (these machines run as root)
[ "$(id -u)" = 0 ] && export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
NJOBS=$(wc -l <"$plan")
# a batch costs its longest run: the runs in it share the wall clock
EST_TOTAL=$(awk -F'\t' '$10 == "-" { s += $7; next } { if ($7 > b[$10]) b[$10] = $7 } END { for (k in b) s += b[k]; printf "%.3f", s }' "$plan")
if [ "$PLAN_ONLY" = 1 ]; then
  awk -F'\t' '{ printf "%-10s %-10s n=%-8s seed=%-3s threads=%s max_iter=%s estimate=%ss", $1, $2, $3, $4, $5, $6, $7
    if ($9 != "-") printf " time_limit=%ss", $9
    if ($10 != "-") printf " batch=%s", $10
    printf "\n" }' "$plan"
  echo "bench: profile $PROFILE: $NJOBS runs, about $(awk -v s="$EST_TOTAL" 'BEGIN { printf "%d", s / 60 + 0.5 }') min of runs by the rough cost model (a batch counts its longest run; analyses and figures not included)"
  exit 0
fi

# ---- progress display ------------------------------------------------------
# state: k N label start-of-run elapsed-at-start left-estimate-at-start
hms() { awk -v s="$1" 'BEGIN { s = int(s + 0.5); if (s >= 3600) printf "%dh%02dm%02ds", s / 3600, (s % 3600) / 60, s % 60; else if (s >= 60) printf "%dm%02ds", s / 60, s % 60; else printf "%ds", s }'; }
now() { date +%s.%N; }
status_line() { # k N label elapsed left
  printf '[%d/%d] %s elapsed, about %s left: %s' "$1" "$2" "$(hms "$4")" "$(hms "$5")" "$3"
}
if [ -t 2 ]; then
  (
    while :; do
      if [ -f "$work/tmp/state" ]; then
        IFS=$'\t' read -r k nj label t0 left <"$work/tmp/state" || true
        if [ -n "${t0:-}" ]; then
          el=$(awk -v a="$(now)" -v b="$T0" 'BEGIN { print a - b }')
          lf=$(awk -v l="$left" -v a="$(now)" -v b="$t0" 'BEGIN { x = l - (a - b); print (x < 0 ? 0 : x) }')
          printf '\r\033[K%s' "$(status_line "$k" "$nj" "$label" "$el" "$lf")" >&2
        fi
      fi
      sleep 1
    done
  ) &
  ticker=$!
fi
progress() { # k label est_done actual_done est_left
  local el left
  el=$(awk -v a="$(now)" -v b="$T0" 'BEGIN { print a - b }')
  left=$(awk -v ed="$3" -v ad="$4" -v el="$5" 'BEGIN { r = (ed > 0.5 && ad > 0) ? ad / ed : 1; printf "%.1f", r * el }')
  if [ -n "$ticker" ]; then
    printf '%s\t%s\t%s\t%s\t%s\n' "$1" "$NJOBS" "$2" "$(now)" "$left" >"$work/tmp/state.new"
    mv "$work/tmp/state.new" "$work/tmp/state"
  else
    echo "bench: $(status_line "$1" "$NJOBS" "$2" "$el" "$left")" >&2
  fi
}

# ---- machine and build: the header of runs.csv ------------------------------
pkgver() { dpkg-query -W -f '${Version}' "$1" 2>/dev/null || echo unknown; }
flags=$(sed -n 's/^C_FLAGS = //p' "$B/CMakeFiles/cfpo_core.dir/flags.make" 2>/dev/null | head -n 1)
cxxflags=$(sed -n 's/^CXX_FLAGS = //p' "$B/baselines/CMakeFiles/cfpo_cgal.dir/flags.make" 2>/dev/null | head -n 1)
commit=$(git -C "$here/.." rev-parse --short HEAD 2>/dev/null || echo none)
git -C "$here/.." diff --quiet HEAD 2>/dev/null || commit="$commit (uncommitted changes)"
csv="$work/runs.csv"
{
  echo "# cfpo method comparison (scripts/bench.sh), profile $PROFILE, started $(date -u +%FT%TZ)"
  echo "# host: $(hostname -s); cpu: $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2- | sed 's/^ //'); cores: $cores; memory: $(free -g | awk '/Mem:/ { print $2 }') GiB"
  echo "# compiler: $(cc --version | head -n 1); C flags: ${flags:-unknown}; C++ flags (FPO, LFPO): ${cxxflags:-unknown}; build type: $(sed -n 's/^CMAKE_BUILD_TYPE:STRING=//p' "$B/CMakeCache.txt")"
  echo "# git commit: $commit"
  echo "# libraries: FFTW $(pkgver libfftw3-dev); CGAL $(pkgver libcgal-dev); OpenMPI $(pkgver libopenmpi-dev); GMP $(pkgver libgmp-dev); gnuplot $(gnuplot --version | cut -d' ' -f2-)"
  echo "# environment: $( (env | grep -E '^(OMP|GOMP)_' || echo 'no OMP_ or GOMP_ variables') | sort | tr '\n' ' ' | sed 's/ $//')"
  echo "# plan: SETS=$SETS COMP_N=$COMP_N COMP_THREADS=$COMP_THREADS COMP_TOGETHER=$together EVO_ITERS=$EVO_ITERS RT_REPS=$RT_REPS RT_THREADS=$RT_THREADS TTQ_SIZES=$(echo $TTQ_SIZES $TTQ_BIG | tr ' ' ,) TTQ_SEEDS=$TTQ_SEEDS TTQ_MAXITER=$TTQ_MAXITER TTQ_TARGET_MIN=$TTQ_TARGET_MIN TTQ_TARGET_AVG=$TTQ_TARGET_AVG TTQ_CONFIGS=$(echo $TTQ_CONFIGS | tr ' ' ,)$(for n in $TTQ_SIZES; do v=TTQ_CONFIGS_$n; [ -n "${!v:-}" ] && printf ' TTQ_CONFIGS_%s=%s' "$n" "$(echo ${!v} | tr ' ' ,)"; done) TASKSET=$([ -n "$TASKSET" ] && echo yes || echo no); $NJOBS runs"
  echo "# load average before: $(cut -d' ' -f1-3 /proc/loadavg)"
  echo "# columns: seconds = the tool's own sampling time (start included, writing excluded); seconds_per_iteration = seconds / iterations; peak_bytes = peak resident memory of the process; n = points produced, n_target = points asked for; max_iter = iteration cap (- none); wall_seconds = the whole process as timed by this script; time_limit = --time-limit of a ttq run (- none); stop = the rule that ended the run (SUMMARY stop=); batch = runs with the same number started together, one per core (- alone)"
  echo "run,experiment,method,variant,n,n_target,seed,threads,ranks,max_iter,iterations,seconds,seconds_per_iteration,delta_min,delta_avg,peak_bytes,converged,wall_seconds,trace,time_limit,stop,batch"
} >"$csv"

field() { sed -n "s/.* $1=\([^ ]*\).*/\1/p" <<<"$2"; }

load1=$(cut -d' ' -f1 /proc/loadavg)
if awk -v l="$load1" 'BEGIN { exit !(l > 0.5) }'; then
  echo "bench: note: load average $load1 before the start; other work on this machine disturbs the timings" >&2
fi

# ---- the runs ----------------------------------------------------------------
# Plan lines in order; the lines of one batch start together and are waited
# for together, every other line runs alone.
mapfile -t PLAN <"$plan"
# each key's command, kind, SUMMARY method and variant (scripts/methods.tsv)
declare -A MCMD MKIND MMETHOD MVARIANT
for k in $(methods_keys); do
  MCMD[$k]=$(method_get "$k" command); MKIND[$k]=$(method_get "$k" kind)
  MMETHOD[$k]=$(method_get "$k" method); MVARIANT[$k]=$(method_get "$k" variant)
done
declare -a R_LABEL R_PID R_T1 R_T2 R_RC
# launch I SLOT: starts plan line I (0-based; run I+1) in the background,
# the one-thread runs of a batch pinned to the SLOT-th allowed CPU
launch() {
  local i=$1 slot=$2 exp key n seed t maxit est out lim bat id cmd
  IFS=$'\t' read -r exp key n seed t maxit est out lim bat <<<"${PLAN[$i]}"
  id=$(printf '%04d' $((i + 1)))
  cmd=()
  if [ "$bat" != - ] && [ "$t" = 1 ] && [ -n "$TASKSET" ]; then
    cmd=("$TASKSET" -c "${CPUS[$((slot % ${#CPUS[@]}))]}")
  fi
  if [ "$key" = cfpo-mpi ]; then
    cmd+=("$MPIRUN" --oversubscribe -np "$cores" "$B/cfpo" --variant paper -t "$t")
  else
    local words
    read -r -a words <<<"${MCMD[$key]}"
    cmd+=("$B/${words[0]}" "${words[@]:1}")
    case ${MKIND[$key]} in cfpo|ttq) cmd+=(-t "$t") ;; esac
  fi
  cmd+=(-n "$n" -s "$seed" -q)
  [ "$maxit" != - ] && cmd+=(--max-iter "$maxit")
  [ "$exp" = ttq ] && cmd+=(--target-min "$TTQ_TARGET_MIN" --target-avg "$TTQ_TARGET_AVG" --time-limit "$lim")
  is_pd "$key" || cmd+=(--trace "$work/data/traces/run-$id.tsv")
  [ "$out" != - ] && cmd+=(-o "$work/$out")
  R_T1[i]=$(now)
  "${cmd[@]}" </dev/null >"$work/tmp/run-$id.out" 2>"$work/tmp/run-$id.err" &
  R_PID[i]=$!
  children+=("$!")
}
# finish_all FROM TO: waits for plan lines FROM..TO-1, each end time taken
# when that run ends (polling, so a short run of a batch is not charged the
# longest one's time)
finish_all() {
  local i left rc
  left=$(($2 - $1))
  while [ "$left" -gt 0 ]; do
    for ((i = $1; i < $2; i++)); do
      [ -n "${R_T2[i]:-}" ] && continue
      if [ $(($2 - $1)) -eq 1 ] || ! kill -0 "${R_PID[i]}" 2>/dev/null; then
        rc=0
        wait "${R_PID[i]}" || rc=$?
        R_T2[i]=$(now)
        R_RC[i]=$rc
        left=$((left - 1))
      fi
    done
    [ "$left" -gt 0 ] && sleep 0.05
  done
  children=()
}
# record I: the row of runs.csv of plan line I; dies when the run failed
record() {
  local i=$1 exp key n seed t maxit est out lim bat id line it secs spi wall trace=-
  IFS=$'\t' read -r exp key n seed t maxit est out lim bat <<<"${PLAN[$i]}"
  id=$(printf '%04d' $((i + 1)))
  line=$(grep '^SUMMARY' "$work/tmp/run-$id.out" || true)
  if [ "${R_RC[i]}" -ne 0 ] || [ -z "$line" ]; then
    [ -n "$ticker" ] && printf '\n' >&2
    die "run $((i + 1)) (${R_LABEL[i]}) failed (exit ${R_RC[i]}): $(tail -n 1 "$work/tmp/run-$id.err")"
  fi
  is_pd "$key" || trace="data/traces/run-$id.tsv"
  it=$(field iterations "$line"); secs=$(field seconds "$line")
  spi=$(awk -v s="$secs" -v i="$it" 'BEGIN { if (i == "-" || i + 0 == 0) print "-"; else printf "%.6g", s / i }')
  wall=$(awk -v a="${R_T2[i]}" -v b="${R_T1[i]}" 'BEGIN { printf "%.3f", a - b }')
  printf '%d,%s,%s,%s,%s,%s,%s,%s,%s,%s,%s,%s,%s,%s,%s,%s,%s,%s,%s,%s,%s,%s\n' $((i + 1)) "$exp" "$(field method "$line")" \
    "$(field variant "$line")" "$(field n "$line")" "$n" "$seed" "$(field threads "$line")" "$(field ranks "$line")" \
    "$maxit" "$it" "$secs" "$spi" "$(field delta_min "$line")" "$(field delta_avg "$line")" \
    "$(field peak_bytes "$line")" "$(field converged "$line")" "$wall" "$trace" "$lim" "$(field stop "$line")" "$bat" >>"$csv"
  [ "$exp" = ttq ] && printf '%d\t%s\n' $((i + 1)) "$out" >>"$work/tmp/ttq-sets.tsv"
  rm -f "$work/tmp/run-$id.out" "$work/tmp/run-$id.err"
}
: >"$work/tmp/ttq-sets.tsv"
est_done=0
act_done=0
i=0
while [ "$i" -lt "$NJOBS" ]; do
  IFS=$'\t' read -r exp key n seed t maxit est out lim bat <<<"${PLAN[$i]}"
  j=$((i + 1))
  if [ "$bat" != - ]; then
    while [ "$j" -lt "$NJOBS" ] && [ "$(cut -f10 <<<"${PLAN[$j]}")" = "$bat" ]; do j=$((j + 1)); done
  fi
  label=""; best=0
  for ((m = i; m < j; m++)); do
    IFS=$'\t' read -r exp key n seed t maxit est out lim bat <<<"${PLAN[$m]}"
    R_LABEL[m]="$exp $key n=$n seed=$seed threads=$t"
    [ "$key" = cfpo-mpi ] && R_LABEL[m]="${R_LABEL[m]} ranks=$cores"
    [ "$maxit" != - ] && R_LABEL[m]="${R_LABEL[m]} max-iter=$maxit"
    [ "$lim" != - ] && R_LABEL[m]="${R_LABEL[m]} limit=${lim}s"
    label="$label${label:+ + }${R_LABEL[m]}"
    best=$(awk -v a="$best" -v b="$est" 'BEGIN { print (b > a) ? b : a }')
  done
  [ $((j - i)) -gt 1 ] && label="together: $label"
  progress $((i + 1)) "$label" "$est_done" "$act_done" \
    "$(awk -v tot="$EST_TOTAL" -v d="$est_done" 'BEGIN { print tot - d }')"
  for ((m = i; m < j; m++)); do launch "$m" $((m - i)); done
  finish_all "$i" "$j"
  wall=0
  for ((m = i; m < j; m++)); do
    record "$m"
    wall=$(awk -v a="$wall" -v b="${R_T2[m]}" -v c="${R_T1[m]}" 'BEGIN { print (b - c > a) ? b - c : a }')
  done
  est_done=$(awk -v a="$est_done" -v b="$best" 'BEGIN { print a + b }')
  act_done=$(awk -v a="$act_done" -v b="$wall" 'BEGIN { print a + b }')
  i=$j
done

# ---- quality of the ttq runs' final sets: certificate, spike and lattice ratio
qcsv="$work/quality.csv"
echo "run,n,K,certify,cert_pass,cert_max_violation,lct_pass,spike_ratio,spike_k,lattice_ratio,lattice_k" >"$qcsv"
nq=$(wc -l <"$work/tmp/ttq-sets.tsv")
q=0
while IFS=$'\t' read -r run out; do
  q=$((q + 1))
  progress "$NJOBS" "final-set analysis $q of $nq (run $run)" 1 1 0
  sum=$("$B/cfpo-analyze" -q --certify -o "$work/tmp/an-q" "$work/$out") || die "cfpo-analyze --certify failed on $out (run $run)"
  printf '%s,%s,%s,%s,%s,%s,%s,%s,%s,%s,%s\n' "$run" "$(field n "$sum")" "$(field K "$sum")" "$(field certify "$sum")" \
    "$(field cert_pass "$sum")" "$(field cert_max_violation "$sum")" "$(field lct_pass "$sum")" \
    "$(field spike_ratio "$sum")" "$(field spike_k "$sum" | tr , ';')" \
    "$(field lattice_ratio "$sum")" "$(field lattice_k "$sum" | tr , ';')" >>"$qcsv"
  rm -rf "$work/tmp/an-q" "${work:?}/$out"
done <"$work/tmp/ttq-sets.tsv"

# ---- spectra: one averaged analysis per group of sets ------------------------
# group experiment key iteration: the runs whose output is sets/<group>-s*.txt
groups="$work/tmp/groups.tsv"
: >"$groups"
for it in $EVO_ITERS; do printf 'evolution-it%s\tevolution\tcfpo\t%s\n' "$it" "$it" >>"$groups"; done
for key in $COMP_KEYS; do printf 'comparison-%s\tcomparison\t%s\t-\n' "$key" "$key" >>"$groups"; done
crop=$(awk -v n="$COMP_N" 'BEGIN { printf "%d", 3 * sqrt(n) + 0.999 }')
K=$(awk -v n="$COMP_N" 'BEGIN { k = 6 * sqrt(n); printf "%d", (k == int(k)) ? k : int(k) + 1 }')
AVG="$here/bench-average.awk"
AWK=$(command -v mawk || command -v awk)  # mawk: Debian's default awk, the fastest here
scsv="$work/spectra.csv"
echo "group,experiment,method,variant,n,iteration,sets,runs,K,delta_min,delta_avg,raps_peak,raps_peak_r,eff_nyquist,oscillation,averaged_by,spike_ratio,spike_k,spike_ratio_set_mean" >"$scsv"
# ranges 3 4 5 9 -> 3-5;9
ranges() { tr ' ' '\n' | sort -n | awk 'NF { if (p != "" && $1 == p + 1) { p = $1; next } if (s != "") printf "%s%s;", s, (p != s ? "-" p : ""); s = $1; p = $1 } END { if (s != "") printf "%s%s", s, (p != s ? "-" p : "") }'; }
checked=0
ng=$(wc -l <"$groups")
g=0
while IFS=$'\t' read -r grp exp key it; do
  g=$((g + 1))
  progress "$NJOBS" "analysis $g of $ng: $grp" 1 1 0
  files=("$work"/sets/"$grp"-s*.txt)
  [ -f "${files[0]}" ] || die "no point sets for $grp"
  # the runs of this group, from runs.csv: experiment, key and cap
  ids=$(awk -F, -v e="$exp" -v k="$key" -v m="$( [ "$it" = - ] && echo - || echo "$it")" '
    /^#/ || $1 == "run" { next }
    { kk = ($3 != "cfpo") ? $3 : ($4 == "paper" || $4 == "cfpo") ? "cfpo" : $4 }
    $2 == e && kk == k && $10 == m { printf "%s ", $1 }' "$csv" | ranges)
  dst="$work/data/analysis/$grp"
  mkdir -p "$dst"
  nvals=$(for f in "${files[@]}"; do grep -vc '^#' "$f"; done | sort -u | wc -l)
  variant=${MVARIANT[$key]}; mname=${MMETHOD[$key]}
  if [ "$nvals" -eq 1 ]; then
    a="$work/tmp/an-$grp"
    sum=$("$B/cfpo-analyze" -q -K "$K" -o "$a" "${files[@]}") || die "cfpo-analyze failed on $grp"
    cp "$a/raps.txt" "$a/stats.json" "$dst/"
    "$AWK" -v out="$dst" -v n="$(field n "$sum")" -v crop="$crop" -v croponly=1 -f "$AVG" "$a/spectrum.txt" \
      || die "cropping the spectrum of $grp failed"
    if [ "$checked" -eq 0 ] && [ "$exp" = comparison ]; then
      # check bench-average.awk against cfpo-analyze on this group
      chk=$("$AWK" -v out="$work/tmp" -v n="$(field n "$sum")" -v crop=1 -f "$AVG" "$a/spectrum.txt")
      for m in eff_nyquist oscillation raps_peak spike_ratio; do
        awk -v a="$(field "$m" " $sum")" -v b="$(field "$m" " $chk")" 'BEGIN { d = a - b; t = 1e-5 * (b > 1 ? b : 1); exit !(d < t && d > -t) }' \
          || die "bench-average.awk disagrees with cfpo-analyze on $grp: $m $(field "$m" " $sum") vs $(field "$m" " $chk")"
      done
      checked=1
    fi
    rm -rf "$a"
    printf '%s,%s,%s,%s,%s,%s,%s,%s,%s,%s,%s,%s,%s,%s,%s,cfpo-analyze,%s,%s,%s\n' "$grp" "$exp" "$mname" "$variant" \
      "$(field n "$sum")" "$it" "$(field sets "$sum")" "$ids" "$(field K "$sum")" "$(field delta_min "$sum")" \
      "$(field delta_avg "$sum")" "$(field raps_peak "$sum")" "$(field raps_peak_r "$sum")" \
      "$(field eff_nyquist "$sum")" "$(field oscillation "$sum")" "$(field spike_ratio "$sum")" \
      "$(field spike_k "$sum" | tr , ';')" "$(field spike_ratio_set_mean "$sum")" >>"$scsv"
  else
    # sets of different n (maximal Poisson-disk sets): one analysis per set at
    # a common K, averaged by bench-average.awk
    specs=()
    for f in "${files[@]}"; do
      a="$work/tmp/an-$grp-$(basename "$f" .txt)"
      "$B/cfpo-analyze" -q -K "$K" -o "$a" "$f" >"$a.sum" || die "cfpo-analyze failed on $f"
      specs+=("$a/spectrum.txt")
    done
    nmean=$(cat "$work"/tmp/an-"$grp"-*.sum | sed -n 's/.* n=\([0-9]*\).*/\1/p' | awk '{ s += $1; k++ } END { printf "%.1f", s / k }')
    dmin=$(cat "$work"/tmp/an-"$grp"-*.sum | sed -n 's/.* delta_min=\([^ ]*\).*/\1/p' | awk '{ s += $1; k++ } END { printf "%.6f", s / k }')
    davg=$(cat "$work"/tmp/an-"$grp"-*.sum | sed -n 's/.* delta_avg=\([^ ]*\).*/\1/p' | awk '{ s += $1; k++ } END { printf "%.6f", s / k }')
    spm=$(cat "$work"/tmp/an-"$grp"-*.sum | sed -n 's/.* spike_ratio=\([^ ]*\).*/\1/p' | awk '{ s += $1; k++ } END { printf "%.6g", s / k }')
    sum=$("$AWK" -v out="$dst" -v n="$nmean" -v crop="$crop" -f "$AVG" "${specs[@]}") || die "averaging the spectra of $grp failed"
    rm -rf "$work"/tmp/an-"$grp"-*
    printf '%s,%s,%s,%s,%s,%s,%s,%s,%s,%s,%s,%s,%s,%s,%s,bench-average.awk,%s,%s,%s\n' "$grp" "$exp" "$mname" "$variant" \
      "$nmean" "$it" "$(field sets " $sum")" "$ids" "$(field K " $sum")" "$dmin" "$davg" "$(field raps_peak " $sum")" \
      "$(field raps_peak_r " $sum")" "$(field eff_nyquist " $sum")" "$(field oscillation " $sum")" \
      "$(field spike_ratio " $sum")" "$(field spike_k " $sum" | tr , ';')" "$spm" >>"$scsv"
  fi
  mv "$work/sets/$grp-s1.txt" "$work/data/points/$grp.txt"
done <"$groups"
rm -rf "$work/sets"

T1=$(now)
{
  echo "# load average after: $(cut -d' ' -f1-3 /proc/loadavg); runs and analyses took $(hms "$(awk -v a="$T1" -v b="$T0" 'BEGIN { print a - b }')")"
} >>"$work/runs.csv.tail"
# the header gets the duration: insert before the column line
awk -v tail="$(cat "$work/runs.csv.tail")" '/^run,/ && !done { print tail; done = 1 } { print }' "$csv" >"$csv.new"
mv "$csv.new" "$csv"
rm -f "$work/runs.csv.tail"

[ -n "$ticker" ] && { kill "$ticker" 2>/dev/null; ticker=""; printf '\r\033[K' >&2; }
echo "bench: $NJOBS runs done in $(hms "$(awk -v a="$T1" -v b="$T0" 'BEGIN { print a - b }')"); drawing the figures" >&2
"$here/replot.sh" "$work" || die "drawing the figures failed"
rm -rf "$work/tmp"
mv "$work" "$final" || die "cannot rename $work to $final"
echo "bench: results in $final (summary.md, runs.csv, fig-*.png); took $(hms "$(awk -v a="$(now)" -v b="$T0" 'BEGIN { print a - b }')")" >&2
exit 0
}
