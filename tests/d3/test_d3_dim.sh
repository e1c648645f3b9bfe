#!/usr/bin/env bash
# test_d3_dim.sh BUILD_DIR - `cfpo --dim 3`, the 3-D engine under the main
# command: the bytes of cfpo3d (the same front end) for either spelling and
# any option order; --dim 2 the 2-D bytes; bad input (a dimension other
# than 2 or 3, n too small for the 3x3x3 grid, a box side of 0, NaN or
# negative, options that do not apply in 3-D, --box in 2-D, a box too wide
# for .gro) refused in one line, exit 2, no file; the --box scaling of
# BOX3D; the .gro file (header, count, coordinates, box line).
set -u
B=$(cd "$1" && pwd)
CFPO="$B/cfpo"
T=$(mktemp -d /tmp/cfpo-dim-XXXXXX)
trap 'rm -rf "$T"' EXIT
cd "$T" || exit 1
. "$(dirname "$0")/../cli_expect.sh"

# bad input
expect 2 "'4' is not 2 or 3" --dim 4 -n 100 -o a.npy
expect 2 "'1' is not 2 or 3" --dim=1 -n 100 -o a.npy
expect 2 "'x' is not 2 or 3" -n 100 --dim x -o a.npy
expect 2 "'--dim' needs a value" -n 100 -o a.npy --dim
expect 2 "too small" --dim 3 -n 38 -o a.npy
expect 2 "box" --dim 3 -n 100 --box 0 -o a.xyz
expect 2 "box" --dim 3 -n 100 --box nan -o a.xyz
expect 2 "box" --dim 3 -n 100 --box -2 -o a.xyz
expect 2 "box" --dim 3 -n 100 --box inf -o a.xyz
expect 2 "below 9999 nm" --dim 3 -n 100 --box 1e4 -o a.gro
expect 2 "--density does not apply in 3-D" --dim 3 -n 100 --density cos:a=0.5 -o a.npy
expect 2 "--tiles does not apply in 3-D" --dim 3 -n 100 --tiles 2x1 -o a.npy
expect 2 "--check does not apply in 3-D" --dim 3 -n 100 --check -o a.npy
expect 2 "--ranks does not apply in 3-D" --dim 3 -n 100 --dry-run --ranks 2
expect 2 "--variant paper does not apply in 3-D" --dim 3 -n 100 --variant paper -o a.npy
expect 2 "--box is for --dim 3" -n 100 --box 2 -o a.npy
expect 2 "--box is for --dim 3" --dim 2 -n 100 --box 2 -o a.npy
expect 2 "unknown output format" --dim 3 -n 100 -o a.png

# the bytes of cfpo3d, for --dim 3 and --dim=3, anywhere on the line
"$B/cfpo3d" -q -n 324 --max-iter 4 -t 2 -o ref.npy >ref.log || bad "cfpo3d run"
"$CFPO" --dim 3 -q -n 324 --max-iter 4 -t 1 -o a.npy >a.log || bad "cfpo --dim 3 run"
"$CFPO" -q -n 324 --dim=3 --max-iter 4 --variant adaptive -o b.npy >/dev/null || bad "cfpo --dim=3 run"
cmp -s ref.npy a.npy && cmp -s ref.npy b.npy && ok || bad "cfpo --dim 3 and cfpo3d give different bytes"
head -c 128 a.npy | grep -q "'shape': (324, 3)" && ok || bad "the .npy is not 324 x 3"
grep -q "^SUMMARY method=cfpo3d variant=adaptive n=324 .*iterations=4 " a.log && ok || bad "SUMMARY: $(cat a.log)"
# --dim 2 is the 2-D command
"$CFPO" -q -n 300 --max-iter 3 -t 1 -o d2.npy >/dev/null && "$CFPO" --dim 2 -q -n 300 --max-iter 3 -t 1 -o d2b.npy >/dev/null &&
  cmp -s d2.npy d2b.npy && ok || bad "--dim 2 differs from no --dim"
"$CFPO" --dim 3 --dry-run -n 65536 | grep -q "^cfpo dry run: n=65536 grid=33^3" && ok || bad "--dim 3 --dry-run"
"$CFPO" --dim 3 --help | grep -q "^usage: cfpo --dim 3 -n N" && ok || bad "--dim 3 --help"

# --box: delta_min_box is side x delta_min x Delta3(n), the packing
# fraction does not depend on the side
"$CFPO" --dim 3 -q -n 324 --max-iter 4 --box 3.5 -o s.gro -o s.txt >s.log || bad "--box 3.5 run"
awk -v n=324 '/^SUMMARY/ { for (i = 1; i <= NF; i++) if ($i ~ /^delta_min=/) { split($i, a, "="); d = a[2] } }
  /^BOX3D/ { for (i = 1; i <= NF; i++) { split($i, a, "="); v[a[1]] = a[2] } }
  END { D = exp(log(sqrt(2) / n) / 3); e = v["delta_min_box"] - 3.5 * d * D; if (e < 0) e = -e;
        f = 3.14159265358979 / 6 * n * (d * D) ^ 3 - v["packing_fraction"]; if (f < 0) f = -f;
        exit !(v["side"] == 3.5 && e < 1e-5 && f < 1e-5) }' s.log && ok || bad "BOX3D: $(grep BOX3D s.log)"
a1=$(sed -n 's/^BOX3D.* packing_fraction=\([^ ]*\).*/\1/p' a.log)
a2=$(sed -n 's/^BOX3D.* packing_fraction=\([^ ]*\).*/\1/p' s.log)
[ -n "$a1" ] && [ "$a1" = "$a2" ] && ok || bad "packing fraction depends on the box: $a1 $a2"
# .gro: title, count, 324 atom lines of 5+5+5+5 columns and 3 x 8, the box line
[ "$(sed -n 2p s.gro)" = 324 ] && [ "$(wc -l <s.gro)" = 327 ] && ok || bad ".gro count or length"
[ "$(tail -1 s.gro)" = "3.500 3.500 3.500" ] && ok || bad ".gro box line: $(tail -1 s.gro)"
sed -n 3p s.gro | grep -q '^    1SPH      X    1 ' && [ "$(sed -n 3p s.gro | awk '{ print length($0) }')" = 44 ] && ok ||
  bad ".gro atom line: $(sed -n 3p s.gro)"
paste -d' ' s.txt <(sed -n '3,326p' s.gro | cut -c21-) | awk '{ for (k = 1; k <= 3; k++) { e = $(k + 3) - 3.5 * $k; if (e < 0) e = -e; if (e > 5.0001e-4) bad++ } }
  END { exit bad > 0 }' && ok || bad ".gro coordinates are not 3.5 times the text file's to 3 decimals"

echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]
