#!/bin/sh
# bench.sh - spectrum timings for the README (not a test): 4,096 points at
# the default K and 1,048,576 points at K = 512, NUFFT (FFTW) path and exact
# path, each run 3 times, medians reported. The exact path at 1M points
# would take minutes: it is timed on the first 16,384 points of the set
# and scaled by n (its cost, n (2K+1)(K+1) complex multiply-adds plus
# n (3K+2) sin/cos, is linear in n); 8,192 points are timed too, to show
# the linearity. Usage: analysis/bench.sh [BUILD_DIR]   (default: build)
set -eu
B=$(cd "${1:-build}" && pwd)
A="$B/cfpo-analyze"
T=$(mktemp -d "${TMPDIR:-/tmp}/cfpo-analysis-bench.XXXXXX")
trap 'rm -rf "$T"' EXIT
cd "$T"
field() { echo "$1" | tr ' ' '\n' | sed -n "s/^$2=//p"; }
median3() { printf '%s\n' "$@" | sort -g | sed -n 2p; }
# run3 LABEL ARGS...: three runs, median spectrum_seconds and seconds
run3() {
  label=$1; shift
  s1=; s2=; s3=; w1=; w2=; w3=
  for i in 1 2 3; do
    out=$("$A" -q -o out "$@")
    eval "s$i=$(field "$out" spectrum_seconds); w$i=$(field "$out" seconds)"
  done
  printf '%-34s spectrum %8.3f s (runs %s %s %s)   whole run %8.3f s\n' "$label" \
    "$(median3 "$s1" "$s2" "$s3")" "$s1" "$s2" "$s3" "$(median3 "$w1" "$w2" "$w3")"
  LAST=$(median3 "$s1" "$s2" "$s3")
}
echo "machine: $(nproc) cores, $(uptime | sed 's/.*load/load/')"
"$B/cfpo" -n 4096 --seed 1 -q -o s4096.npy >/dev/null
run3 "n=4096 K=default nufft" s4096.npy
run3 "n=4096 K=default exact" s4096.npy --exact
"$B/cfpo" -n 1048576 --seed 1 --max-iter 3 -q -o s1m.txt >/dev/null
head -n 16384 s1m.txt >s16k.txt
head -n 8192 s1m.txt >s8k.txt
run3 "n=1048576 K=512 nufft" s1m.txt -K 512
nufft=$LAST
run3 "n=8192 K=512 exact" s8k.txt -K 512 --exact
run3 "n=16384 K=512 exact" s16k.txt -K 512 --exact
exact=$(awk -v t="$LAST" 'BEGIN { printf "%.1f", t * 1048576 / 16384 }')
echo "n=1048576 K=512 exact (estimated, 64 x the 16,384-point time): $exact s"
awk -v a="$exact" -v b="$nufft" 'BEGIN { printf "speed-up of the NUFFT path at 1M points: %.0fx\n", a / b }'
echo "machine after: $(uptime | sed 's/.*load/load/')"
