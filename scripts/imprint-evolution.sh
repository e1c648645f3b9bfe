#!/usr/bin/env bash
# imprint-evolution.sh BUILD N SEED "K1 K2 ..." [CFPO OPTIONS...] - how the
# grid imprint forms over the iterations: for each K, the set after K
# iterations (`cfpo --max-iter K`, the same bytes as the first K iterations
# of any longer run) and its four lattice ratios, P at (0, g), (g, 0),
# (0, 4g/3), (4g/3, 0) over the mean of P on each one's ring
# (scripts/imprint.c, built here into a temporary folder; g as cfpo's
# grid for n at the sizes where its minimum does not apply). K = target
# stands for the run to the issue-44 target (0.925, 0.929). One TSV row a
# K on stdout: K, iterations, delta_min, delta_avg and the four ratios.
# Runs one cfpo at a time with one thread unless the options say more.
# Example: scripts/imprint-evolution.sh build 1048576 1 "1 2 4 8 16 target"
set -euo pipefail
die() { echo "imprint-evolution: $*" >&2; exit 1; }
[ $# -ge 4 ] || die "usage: imprint-evolution.sh BUILD N SEED \"K1 K2 ...\" [CFPO OPTIONS...]"
B=$1 N=$2 SEED=$3 KS=$4
shift 4
[ -x "$B/cfpo" ] || die "$B/cfpo not built (run make)"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cc -O2 -fopenmp -o "$tmp/imprint" "$(dirname "$0")/imprint.c" -lm || die "cannot build scripts/imprint.c"
# cfpo's grid for n (the default variant's, src/engine/grid.c): g = 3 round(sqrt(0.8 n) / 3)
g=$(awk -v n="$N" 'BEGIN { x = sqrt(0.8 * n) / 3; printf "%d", 3 * int(x + 0.5) }')
printf 'K\titerations\tdelta_min\tdelta_avg\t(0,g)\t(g,0)\t(0,4g/3)\t(4g/3,0)\n'
for K in $KS; do
  if [ "$K" = target ]; then stop=(--target-min 0.925 --target-avg 0.929); else stop=(--max-iter "$K"); fi
  sum=$(OMP_WAIT_POLICY=passive "$B/cfpo" -n "$N" --seed "$SEED" -t 1 "${stop[@]}" "$@" -q -o "$tmp/s.npy")
  it=$(sed -n 's/.* iterations=\([0-9]*\).*/\1/p' <<<"$sum")
  dm=$(sed -n 's/.* delta_min=\([0-9.]*\).*/\1/p' <<<"$sum")
  da=$(sed -n 's/.* delta_avg=\([0-9.]*\).*/\1/p' <<<"$sum")
  r=$("$tmp/imprint" "$tmp/s.npy" "$g" | grep -o 'ratio=[0-9.e+-]*' | cut -d= -f2 | tr '\n' '\t')
  printf '%s\t%s\t%s\t%s\t%s\n' "$K" "$it" "$dm" "$da" "${r%$'\t'}"
done
