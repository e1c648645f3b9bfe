#!/bin/sh
# cli_density.sh - cfpo-analyze --density: the capacity deviation and the
# differential-domain spectrum. With a uniform density the capacity
# deviation is sqrt(voronoi_area_var) (to the printed digits) and the
# spectrum's low-frequency mean is P0's to 2% (over six sets);
# dda_raps.txt has one row a ring 1..K, dda_spectrum.txt is the
# (2K+1)^2 matrix; the numbers do not
# depend on the thread count nor on --no-delaunay (the cells are made for
# the capacities anyway); under a ramp density the peak lies near
# |k| = sqrt(n) and capacities deviate less than areas do. Bad input (the
# option without a value, a missing image, a bad SPEC, every point off the
# support) exits 1 or 2 with one line and leaves no folder.
. "$(dirname "$0")/common.sh"
cd "$T" || exit 1

"$B/cfpo" -n 2000 --max-iter 5 -q -o uni.npy >/dev/null || bad "cfpo uniform"
s=$("$A" -q -o u.an --density cos:a=0 uni.npy)
S=$(echo "$s" | grep '^SUMMARY'); D=$(echo "$s" | grep '^DENSITY')
var=$(field "$S" voronoi_area_var); cap=$(field "$D" capacity_deviation)
check "awk -v v=$var -v c=$cap 'BEGIN { exit !(c > 0 && (sqrt(v) - c)^2 < (2e-6 * c)^2 + 1e-12) }'" \
  "uniform: capacity deviation $cap, sqrt(voronoi_area_var $var)"
# dda_low against P0 over six sets (seeds 1-6; both are then the means'
# values): the window smooths the spectrum, so one set's dda_low differs
# from its P0 by a spread of about 1.4% (sd; -2.2% to +2.0% over seeds
# 1-6), the mean of six sets by about 0.6%
for s in 2 3 4 5 6; do
  "$B/cfpo" -n 2000 --max-iter 5 --seed $s -q -o uni$s.npy >/dev/null || bad "cfpo uniform seed $s"
done
s6=$("$A" -q --no-delaunay -o u6.an --density cos:a=0 uni.npy uni2.npy uni3.npy uni4.npy uni5.npy uni6.npy)
p0=$(field "$(echo "$s6" | grep '^SUMMARY')" p0); low=$(field "$(echo "$s6" | grep '^DENSITY')" dda_low)
check "awk -v a=$p0 -v b=$low 'BEGIN { exit !(a > 0 && (b - a)^2 <= (0.02 * a)^2) }'" \
  "uniform, six sets: dda_low $low, p0 $p0"
K=$(field "$S" K)
rows=$(grep -vc '^#' u.an/dda_raps.txt)
check "[ '$rows' = '$K' ]" "dda_raps.txt: $rows rows, K = $K"
check "[ \"\$(head -n 1 u.an/dda_spectrum.txt | cut -d ' ' -f 1)\" = $((2 * K + 1)) ]" "dda_spectrum.txt header"
check "[ \$(wc -l <u.an/dda_spectrum.txt) -eq $((2 * K + 2)) ]" "dda_spectrum.txt rows"
check "grep -q '^# capacity deviation' u.an/density.txt && grep -q '^# differential-domain spectrum' u.an/density.txt" \
  "density.txt: the new lines"
"$A" -q -t 1 --no-delaunay -o u1.an --density cos:a=0 uni.npy >one.txt || bad "-t 1 --no-delaunay"
check "cmp -s u.an/dda_spectrum.txt u1.an/dda_spectrum.txt && cmp -s u.an/dda_raps.txt u1.an/dda_raps.txt" \
  "1 and 2 threads, with and without --no-delaunay: the spectra differ"
check "[ \"\$(field \"\$(grep ^DENSITY one.txt)\" capacity_deviation)\" = '$cap' ]" "--no-delaunay: no capacity"

"$B/cfpo" -n 2000 --density ramp:contrast=16 --max-iter 20 -q -o ramp.npy >/dev/null || bad "cfpo ramp"
s=$("$A" -q -o r.an --density ramp:contrast=16 ramp.npy)
S=$(echo "$s" | grep '^SUMMARY'); D=$(echo "$s" | grep '^DENSITY')
cap=$(field "$D" capacity_deviation); var=$(field "$S" voronoi_area_var); pf=$(field "$D" dda_peak_freq)
check "awk -v v=$var -v c=$cap 'BEGIN { exit !(c > 0 && c < 0.5 * sqrt(v)) }'" \
  "ramp: capacity deviation $cap not below the areas' $var"
check "awk -v f=$pf -v p=$(field "$D" dda_peak) 'BEGIN { exit !(f > 0.8 && f < 1.3 && p > 1.5) }'" "ramp: peak at $pf"

expect() { # expect CODE NAME ARGS...: exit code, one line, no folder
  code=$1; name=$2; shift 2
  rm -rf out out.tmp.* 2>/dev/null
  "$A" -q -o out "$@" >stdout.txt 2>stderr.txt
  rc=$?
  if [ "$rc" -ne "$code" ]; then bad "$name: exit $rc, expected $code"; return; fi
  if [ "$(wc -l <stderr.txt)" -ne 1 ] || ! grep -q '^cfpo-analyze: ' stderr.txt; then
    bad "$name: message '$(cat stderr.txt)'"; return; fi
  if ls -d out out.tmp.* >/dev/null 2>&1; then bad "$name: a folder was left"; return; fi
  ok
}
expect 2 "--density without a value" uni.npy --density
expect 1 "missing image" --density missing.png uni.npy
expect 1 "bad SPEC" --density cos:a=2 uni.npy
printf 'P2 2 1 255\n0 255\n' >half.pgm # dense x < 1/2, zero density x >= 1/2
awk 'BEGIN { for (i = 0; i < 50; i++) printf "%.6f %.6f\n", 0.55 + 0.008 * i, 0.02 * i }' >off.txt
expect 1 "every point off the support" --density half.pgm off.txt
finish
