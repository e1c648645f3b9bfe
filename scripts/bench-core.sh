#!/usr/bin/env bash
# bench-core.sh BUILD_DIR [PROFILE] - the core CFPO benchmark (`make bench-core`).
# Prints the figures the core issue asks for, each measured by
# build/cfpo-bench, and writes them to results/<date>-<host>/core.txt.
# PROFILE: default (65,536 and 1,048,576 points) or smoke (small, seconds).
set -euo pipefail
B=${1:-build}
PROFILE=${2:-default}
BENCH="$B/cfpo-bench"
[ -x "$BENCH" ] || { echo "bench-core.sh: $BENCH not built (run make)" >&2; exit 1; }
out="results/$(date +%Y%m%d-%H%M%S)-$(hostname -s)"
mkdir -p "$out"
log="$out/core.txt"
cores=$(nproc)
case "$PROFILE" in
  smoke) sizes="4096 16384"; k=3 ;;
  default|paper) sizes="65536 1048576"; k=5 ;;
  *) echo "bench-core.sh: unknown PROFILE '$PROFILE' (default, smoke, paper)" >&2; exit 2 ;;
esac
steps=$(( $(echo $sizes | wc -w) * 3 ))
step=0
t_start=$(date +%s)
run() {
  step=$((step + 1))
  local el=$(( $(date +%s) - t_start ))
  printf '[%d/%d, %ds] cfpo-bench %s\n' "$step" "$steps" "$el" "$*" >&2
  "$BENCH" "$@" | tee -a "$log"
}
{
  echo "# CFPO core benchmark, profile $PROFILE"
  echo "# machine: $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2- | sed 's/^ //'), $cores cores, $(free -g | awk '/Mem:/{print $2}') GiB"
  echo "# compiler: $(cc --version | head -n 1); commit $(git rev-parse --short HEAD 2>/dev/null || echo none)"
  echo "# load before: $(cut -d' ' -f1-3 /proc/loadavg)"
} | tee "$log"
for n in $sizes; do
  run sweep -n "$n" -t 1 -k "$k"
  [ "$cores" -ge 2 ] && run sweep -n "$n" -t 2 -k "$k"
  run converge -n "$n" -t "$cores"
done
echo "# load after: $(cut -d' ' -f1-3 /proc/loadavg)" | tee -a "$log"
# The comparison against the targets of the core issue, from the lines above.
awk '
  /^RESULT sweep/ { for (i = 3; i <= NF; i++) { split($i, kv, "="); f[kv[1]] = kv[2] }
    key = f["n"] "/" f["threads"]; sweep[key] = f["seconds_per_sweep"]; upd[key] = f["us_per_update"] }
  /^RESULT converge/ { for (i = 3; i <= NF; i++) { split($i, kv, "="); g[kv[1]] = kv[2] }
    conv[g["n"]] = g["seconds"]; bpp[g["n"]] = g["bytes_per_point"] }
  END {
    print "# versus the targets"
    for (k in upd) if (k ~ /\/1$/) { split(k, a, "/"); printf "us per point-update (one local solve), 1 thread, n=%s: %.3f (target <= 0.8)\n", a[1], upd[k] }
    for (k in sweep) if (k ~ /\/2$/) { split(k, a, "/"); one = sweep[a[1] "/1"];
      printf "speedup 2 threads vs 1, n=%s: %.2fx (target >= 1.9)\n", a[1], one / sweep[k];
      if (a[1] == 1048576) printf "full sweep of 1M points on 2 threads: %.3f s (target <= 0.42)\n", sweep[k] }
    for (n in conv) { printf "seconds to converge, n=%s: %s%s\n", n, conv[n], n == 1048576 ? " (target <= 60)" : "";
      printf "peak bytes per point, n=%s: %s (target <= 64)\n", n, bpp[n] }
  }' "$log" | tee -a "$log"
echo "bench-core.sh: results in $log" >&2
