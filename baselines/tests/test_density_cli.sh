#!/usr/bin/env bash
# test_density_cli.sh BUILD_DIR - the baselines' --density as a user meets
# it: cfpo-dart, cfpo-fpo, cfpo-lfpo and cfpo-bnot under a uniform density
# (cos:a=0) write the bytes they write without one, cfpo-ccvt those of its random
# point set (a lattice has no density); exactly n points; the SUMMARY
# line's deltas are cfpo-analyze --density's; the stop rules work under a
# density (a target stop writes the points of --max-iter at that
# iteration); bad input (a bad SPEC, a missing file, a contrast beyond the
# limit, n too small for the density, --density where a method has none,
# --start grid) gives one line, the exit code of `cfpo --density` for the
# same fault, and no file; --help names the option.
set -u
HERE=$(cd "$(dirname "$0")" && pwd)
B=$(cd "$1" && pwd)
AN="$B/cfpo-analyze"
T=$(mktemp -d /tmp/cfpo-bdens-XXXXXX)
trap 'rm -rf "$T"' EXIT
cd "$T" || exit 1
. "$HERE/../../tests/cli_expect.sh"

printf 'P5 4 4 255\n' >t.pgm; head -c 10 /dev/zero >>t.pgm   # truncated
for c in cfpo-dart cfpo-fpo cfpo-lfpo; do
  CFPO="$B/$c"
  cap=(); [ "$c" != cfpo-dart ] && cap=(--max-iter 15)
  "$CFPO" -q -n 2000 -s 3 "${cap[@]}" -o u.npy >u.sum || bad "$c uniform run"
  "$CFPO" -q -n 2000 -s 3 "${cap[@]}" --density cos:a=0 -o c.npy >c.sum || bad "$c cos:a=0 run"
  cmp -s u.npy c.npy && ok || bad "$c --density cos:a=0 writes other bytes than without a density"
  "$CFPO" -q -n 2000 -s 3 "${cap[@]}" --density ramp:contrast=16 -o r.npy >r.sum || bad "$c ramp run"
  [ "$(stat -c %s r.npy)" -eq $((128 + 2000 * 16)) ] && ok || bad "$c --density: not exactly 2000 points"
  s=$(sed -n 's/^SUMMARY .* delta_min=\([^ ]*\) delta_avg=\([^ ]*\) .*/\1 \2/p' r.sum)
  a=$("$AN" -q -o an --no-discrepancy --no-delaunay --integration 0 --density ramp:contrast=16 r.npy |
      sed -n 's/^DENSITY .*density_delta_min=\([^ ]*\) density_delta_avg=\([^ ]*\) .*/\1 \2/p')
  [ -n "$s" ] && [ "$s" = "$a" ] && ok || bad "$c: SUMMARY deltas '$s', cfpo-analyze --density '$a'"
  grep -q "^DENSITY spec=ramp:contrast=16 hash=" r.sum && ok || bad "$c: no DENSITY line"
  "$CFPO" --help | grep -q -- "--density SPEC" && ok || bad "$c --help lacks --density"
  rm -rf u.npy c.npy r.npy u.sum c.sum r.sum an
  expect 1 "not an image" -n 1000 --density swirl -o x.npy
  expect 1 "cannot open" -n 1000 --density missing.png -o x.npy
  expect 1 "truncated PGM" -n 1000 --density t.pgm -o x.npy
  expect 1 "contrast 1:1000 .*limit 1:256" -n 1000 --density ramp:contrast=1000 -o x.npy
  expect 2 "too small for this density" -n 50 --density ramp:contrast=200 -o x.npy
done

# CCVT: a uniform density gives the random point set's run
CFPO="$B/cfpo-ccvt"
"$CFPO" -q -n 300 --points-per-site 64 --max-iter 15 --point-set random -o u.npy >/dev/null || bad "ccvt random"
"$CFPO" -q -n 300 --points-per-site 64 --max-iter 15 --density cos:a=0 -o c.npy >c.sum || bad "ccvt cos:a=0"
cmp -s u.npy c.npy && ok || bad "ccvt --density cos:a=0 differs from --point-set random"
grep -q "^DENSITY spec=cos:a=0 " c.sum && ok || bad "ccvt: no DENSITY line"
"$CFPO" --help | grep -q -- "--density SPEC" && ok || bad "cfpo-ccvt --help lacks --density"
expect 1 "contrast 1:1000 .*limit 1:256" -n 300 --density ramp:contrast=1000 -o x.npy
rm -f u.npy c.npy c.sum

# BNOT: a uniform density gives the bytes without one (the authors'
# schedule and the run to tol); under the ramp exactly n points, the
# SUMMARY deltas cfpo-analyze --density's; the bad SPECs as above
CFPO="$B/cfpo-bnot"
for e in "" "--epsilon 0 --max-iter 6"; do
  "$CFPO" -q -n 1000 -s 3 $e -o u.npy >/dev/null || bad "bnot $e uniform"
  "$CFPO" -q -n 1000 -s 3 $e --density cos:a=0 -o c.npy >c.sum || bad "bnot $e cos:a=0"
  cmp -s u.npy c.npy && ok || bad "bnot $e --density cos:a=0 writes other bytes than without a density"
done
"$CFPO" -q -n 1000 -s 3 --density ramp:contrast=16 -o r.npy >r.sum || bad "bnot ramp run"
[ "$(stat -c %s r.npy)" -eq $((128 + 1000 * 16)) ] && ok || bad "bnot --density: not exactly 1000 points"
s=$(sed -n 's/^SUMMARY .* delta_min=\([^ ]*\) delta_avg=\([^ ]*\) .*/\1 \2/p' r.sum)
a=$("$AN" -q -o an --no-discrepancy --no-delaunay --integration 0 --density ramp:contrast=16 r.npy |
    sed -n 's/^DENSITY .*density_delta_min=\([^ ]*\) density_delta_avg=\([^ ]*\) .*/\1 \2/p')
[ -n "$s" ] && [ "$s" = "$a" ] && ok || bad "bnot: SUMMARY deltas '$s', cfpo-analyze --density '$a'"
grep -q "^DENSITY spec=ramp:contrast=16 hash=" r.sum && ok || bad "bnot: no DENSITY line"
"$CFPO" --help | grep -q -- "--density SPEC" && ok || bad "cfpo-bnot --help lacks --density"
rm -rf u.npy c.npy r.npy c.sum r.sum an
expect 1 "not an image" -n 1000 --density swirl -o x.npy
expect 1 "cannot open" -n 1000 --density missing.png -o x.npy
expect 1 "truncated PGM" -n 1000 --density t.pgm -o x.npy
expect 1 "contrast 1:1000 .*limit 1:256" -n 1000 --density ramp:contrast=1000 -o x.npy
expect 2 "too small for this density" -n 50 --density ramp:contrast=200 -o x.npy

# the stop rules under a density: a target stop at iteration K writes the
# points of --max-iter K
CFPO="$B/cfpo-fpo"
"$CFPO" -q -n 1500 --density cos:a=0.9 --target-min 0.8 --target-avg 0.88 -o t.npy >t.sum || bad "target run"
K=$(sed -n 's/^SUMMARY .* iterations=\([0-9]*\) .*/\1/p' t.sum)
grep -q "stop=target" t.sum && ok || bad "fpo --density: no target stop ($(cat t.sum))"
"$CFPO" -q -n 1500 --density cos:a=0.9 --max-iter "$K" -o k.npy >/dev/null || bad "max-iter run"
cmp -s t.npy k.npy && ok || bad "fpo --density: the target stop at $K differs from --max-iter $K"
rm -f t.npy k.npy t.sum
expect 2 "start grid does not go with --density" -n 1000 --density cos --start grid -o x.npy
for c in cfpo-bs cfpo-bridson; do
  CFPO="$B/$c"; expect 2 "applies to cfpo-dart only" -n 1000 --density cos -o x.npy
done
for c in cfpo-ccdt; do
  CFPO="$B/$c"; expect 2 "is not offered by $c" -n 1000 --density cos -o x.npy
done

echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]
