#!/usr/bin/env bash
# compare-sets.sh BUILD OUT LABEL FILES [LABEL FILES ...] - groups of point
# sets side by side: each group (a label and a quoted glob of point files
# with the same n, e.g. our sets and a reference implementation's) is
# averaged by cfpo-analyze into OUT/<k>.analysis; the script prints one
# table row per group (sets, n, mean and spread of delta_min and
# delta_avg per set, RAPS peak of the averaged spectrum, mean per-set
# spike ratio) and writes OUT/raps.png, the groups' averaged RAPS overlaid
# against |k| / sqrt(n), and OUT/table.md. FILES may instead name one
# analysis folder that cfpo-analyze wrote for such a group (stats.json and
# raps.txt, e.g. a `make bench` results folder's data/analysis/<group>):
# it is used as it is.
# Example: scripts/compare-sets.sh build cmp ours "sets/ours-*.txt" reference "/tmp/ref/*.txt"
set -euo pipefail
die() { echo "compare-sets: $*" >&2; exit 1; }
[ $# -ge 4 ] && [ $(( ($# - 2) % 2 )) = 0 ] || die "usage: compare-sets.sh BUILD OUT LABEL FILES [LABEL FILES ...]"
B=$1 OUT=$2
shift 2
[ -x "$B/cfpo-analyze" ] || die "$B/cfpo-analyze not built (run make)"
command -v gnuplot >/dev/null 2>&1 || die "gnuplot not found (run scripts/install-deps.sh)"
mkdir -p "$OUT"
labels=() k=0
printf '| group | sets | n | delta_min (mean, min-max) | delta_avg (mean, min-max) | RAPS peak | spike ratio per set (mean) |\n|---|---|---|---|---|---|---|\n' >"$OUT/table.md"
while [ $# -gt 0 ]; do
  k=$((k + 1)); label=$1
  # shellcheck disable=SC2206
  files=($2)
  shift 2
  [ -e "${files[0]}" ] || die "$label: no file matches '${files[*]}'"
  if [ "${#files[@]}" -eq 1 ] && [ -d "${files[0]}" ]; then
    [ -f "${files[0]}/stats.json" ] && [ -f "${files[0]}/raps.txt" ] ||
      die "$label: ${files[0]} is not an analysis folder (stats.json, raps.txt)"
    rm -rf "$OUT/$k.analysis"
    cp -R "${files[0]}" "$OUT/$k.analysis" || die "$label: cannot copy ${files[0]}"
  else
    "$B/cfpo-analyze" -q -o "$OUT/$k.analysis" "${files[@]}" >/dev/null || die "$label: cfpo-analyze failed"
  fi
  awk -v label="$label" '
    function arr(s, a,   t) { t = s; sub(/.*\[/, "", t); sub(/\].*/, "", t); return split(t, a, /, */) }
    /"n":/ { n = $2; sub(/,/, "", n) }
    /"sets":/ { sets = $2; sub(/,/, "", sets) }
    /"delta_min_per_set"/ { m = arr($0, dm) }
    /"delta_avg_per_set"/ { arr($0, da) }
    /"raps_peak"/ { p = $0; sub(/.*"raps": /, "", p); sub(/}.*/, "", p) }
    /"spike_ratio_set_mean"/ { sr = $2; sub(/,/, "", sr) }
    END {
      lo1 = hi1 = dm[1]; lo2 = hi2 = da[1]; s1 = s2 = 0
      for (i = 1; i <= m; i++) { s1 += dm[i]; s2 += da[i]
        if (dm[i] < lo1) lo1 = dm[i]; if (dm[i] > hi1) hi1 = dm[i]
        if (da[i] < lo2) lo2 = da[i]; if (da[i] > hi2) hi2 = da[i] }
      printf "| %s | %d | %d | %.4f (%.3f-%.3f) | %.4f (%.3f-%.3f) | %.2f | %.1f |\n", label, sets, n, s1 / m, lo1, hi1, s2 / m, lo2, hi2, p, sr
    }' "$OUT/$k.analysis/stats.json" >>"$OUT/table.md"
  labels+=("$label")
done
cat "$OUT/table.md"
plot=""
for ((i = 1; i <= k; i++)); do
  plot="$plot${plot:+, }'$OUT/$i.analysis/raps.txt' using 2:3 with lines lw 2 title '${labels[$((i - 1))]//\'/}'"
done
gnuplot <<EOF || die "gnuplot failed"
set terminal pngcairo size 900,520 font "DejaVu Sans,12" enhanced
set output "$OUT/raps.png"
set title "radially averaged power spectrum (mean of the sets of each group)"
set xlabel "frequency |k| / sqrt(n)"
set ylabel "RAPS"
set xrange [0:4]
set yrange [0:*]
set grid
set key top right
plot $plot
EOF
echo "compare-sets: $OUT/raps.png, $OUT/table.md"
