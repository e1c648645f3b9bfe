#!/bin/sh
# cli_imprint.sh - the report's imprint line: cfpo-analyze prints one plain
# line after SUMMARY when the spike ratio is above the noise level
# ln(M / 2) + 4 (M = (2K + 1)^2 frequencies), and nothing otherwise:
# - white noise (cfpo-white, three seeds) and a converged CFPO set: no line;
# - 64 rows of 64 points (x uniform, y jittered by half a row): the line,
#   at k (0, 64), naming the grid's frequency given --grid 64, not with
#   --grid 0;
# - the line carries no key=value pair, so SUMMARY parsers ignore it.
. "$(dirname "$0")/common.sh"
cd "$T" || exit 1
imprint() { echo "$1" | grep '^imprint: ' ; }

for s in 1 2 3; do
  "$B/cfpo-white" -n 16384 --seed "$s" -q -o "w$s.npy" >/dev/null || bad "cfpo-white seed $s failed"
  out=$("$A" -q --no-discrepancy --integration 0 --no-delaunay -o "w$s.an" "w$s.npy") || bad "analysis of white noise $s failed"
  check '[ -z "$(imprint "$out")" ]' "white noise seed $s: $(imprint "$out") (spike_ratio $(field "$out" spike_ratio))"
  check '[ "$(echo "$out" | wc -l)" -eq 1 ]' "white noise seed $s: more than the SUMMARY line"
done

"$B/cfpo" -n 4096 --seed 1 -q -o c.npy >/dev/null || bad "cfpo failed"
out=$("$A" -q --no-discrepancy --integration 0 --no-delaunay -o c.an c.npy) || bad "analysis of the CFPO set failed"
check '[ -z "$(imprint "$out")" ]' "converged CFPO set: $(imprint "$out")"

# rows: P(0, 64) is about n sinc(pi / 2)^2 = 0.4 n, its ring's mean about 1
awk 'BEGIN { srand(7); for (j = 0; j < 64; j++) for (i = 0; i < 64; i++)
  printf "%.12f %.12f\n", rand(), (j + 0.5 + 0.5 * (rand() - 0.5)) / 64 }' > lat.txt
out=$("$A" -q --no-discrepancy --integration 0 --no-delaunay --grid 64 -o lat.an lat.txt) || bad "analysis of the rows failed"
line=$(imprint "$out")
check '[ -n "$line" ]' "rows: no imprint line (spike_ratio $(field "$out" spike_ratio))"
check 'echo "$line" | grep -q "at k (0, 64)"' "rows: line not at (0, 64): $line"
check 'echo "$line" | grep -q "grid"' "rows with --grid 64: the line does not name the grid: $line"
check '[ "$(echo "$out" | wc -l)" -eq 2 ] && echo "$out" | head -n 1 | grep -q "^SUMMARY "' "rows: not SUMMARY then one line: $out"
check '! echo "$line" | grep -q "="' "the imprint line has a key=value pair: $line"
out=$("$A" -q --no-discrepancy --integration 0 --no-delaunay --grid 0 -o lat0.an lat.txt)
check 'imprint "$out" | grep -vq "grid"' "rows with --grid 0: the line names a grid: $(imprint "$out")"
finish
