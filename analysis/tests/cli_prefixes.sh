#!/bin/sh
# cli_prefixes.sh - cfpo-analyze --prefixes: prefixes.txt (one row per size
# of the plan, or the given sizes), the prefix_* SUMMARY keys ('-' without
# the option), bad option values (exit 2 with one line, nothing written), and
# cfpo-fporder: the same points, a worst prefix better than the file order's,
# its bad values.
. "$(dirname "$0")/common.sh"
cd "$T" || exit 1

"$B/cfpo" -n 300 -t 1 -q -s 5 -o x.txt >/dev/null
s=$("$A" -q --no-discrepancy --no-delaunay --integration 0 --prefixes -o a x.txt)
check '[ -f a/prefixes.txt ]' "prefixes.txt written"
rows=$(grep -vc '^#' a/prefixes.txt)
# 16 17 23 32 33 45 64 65 91 128 129 181 256, then 300 itself
check '[ "$rows" -eq 14 ]' "14 rows for n = 300 from 16 (got $rows)"
check '[ "$(field "$s" prefix_base)" = 16 ]' "prefix_base"
m=$(field "$s" prefix_worst_any_m)
check '[ "$m" -ge 16 ] && [ "$m" -le 300 ]' "prefix_worst_any_m in range ($m)"
full=$(awk '$1 == 300 { print $3 }' a/prefixes.txt)
dmin=$(field "$s" delta_min)
check 'awk -v a="$full" -v b="$dmin" "BEGIN { exit !((a - b) ^ 2 < 1e-10) }"' "the full row is the set's delta_min ($full, $dmin)"
wa=$(field "$s" prefix_worst_any_dmin)
wd=$(field "$s" prefix_worst_dyadic_dmin)
check 'le "$wa" "$wd"' "the worst of all prefixes is at most the worst dyadic ($wa, $wd)"

s=$("$A" -q --no-discrepancy --no-delaunay --integration 0 --prefixes --prefix-sizes 50,20,300 -o b x.txt)
check '[ "$(grep -v "^#" b/prefixes.txt | awk "{ printf \"%s \", \$1 }")" = "20 50 300 " ]' "given sizes"
check '[ "$(field "$s" prefix_worst_dyadic_dmin)" = - ]' "no dyadic rows with given sizes"

# m = 344: the Gaussian variance's theta tail reaches the underflow there (its
# K alone decides it); the tail loop once ran on forever
"$B/cfpo" -n 400 -t 1 -q -s 5 -o y.txt >/dev/null
timeout 60 "$A" -q --no-discrepancy --no-delaunay --integration 0 --prefixes --prefix-sizes 344 -o f y.txt >/dev/null
rc=$?
check '[ "$rc" -eq 0 ] && [ "$(grep -v "^#" f/prefixes.txt | awk "{ print \$1 }")" = 344 ]' "prefix of 344 points ends (exit $rc)"

s=$("$A" -q --no-discrepancy --no-delaunay --integration 0 -o c x.txt)
check '[ ! -f c/prefixes.txt ] && [ "$(field "$s" prefix_worst_any_dmin)" = - ]' "nothing without --prefixes"

expect2() { # expect2 NAME ARGS...: exit 2, one line, no folder
  name=$1; shift
  rm -rf out
  "$A" -q -o out "$@" >stdout.txt 2>stderr.txt
  rc=$?
  check '[ "$rc" -eq 2 ]' "$name: exit $rc"
  check '[ "$(wc -l <stderr.txt)" -eq 1 ] && grep -q "^cfpo-analyze: " stderr.txt' "$name: one line"
  check '[ ! -e out ] && [ ! -s stdout.txt ]' "$name: nothing written"
}
expect2 "base 1" --prefixes --prefix-base 1 x.txt
expect2 "base abc" --prefixes --prefix-base abc x.txt
expect2 "size 0" --prefixes --prefix-sizes 0,5 x.txt
expect2 "size list" --prefixes --prefix-sizes 5,,x x.txt
expect2 "sizes without --prefixes" --prefix-sizes 5 x.txt
expect2 "base without --prefixes" --prefix-base 16 x.txt
expect2 "two files" --prefixes x.txt x.txt
# a base or size above n: a run-time error (exit 1), one line, no folder
rm -rf out
"$A" -q -o out --prefixes --prefix-base 512 x.txt >stdout.txt 2>stderr.txt
rc=$?
check '[ "$rc" -eq 1 ] && [ "$(wc -l <stderr.txt)" -eq 1 ] && [ ! -e out ]' "base above n: exit $rc"

# cfpo-fporder: the same points, in an order whose prefixes beat the file's own
"$B/cfpo-fporder" -o fp.txt x.txt >/dev/null
check '[ "$(sort x.txt | md5sum)" = "$(sort fp.txt | md5sum)" ]' "fporder keeps the points"
s2=$("$A" -q --no-discrepancy --no-delaunay --integration 0 --prefixes -o d fp.txt)
s1=$("$A" -q --no-discrepancy --no-delaunay --integration 0 --prefixes -o e x.txt)
wo=$(field "$s1" prefix_worst_any_dmin)
wf=$(field "$s2" prefix_worst_any_dmin)
check '! le "$wf" "$wo"' "greedy order's worst prefix $wf beats the file order's $wo"
rm -f out.txt
"$B/cfpo-fporder" --first 300 -o out.txt x.txt >stdout.txt 2>stderr.txt
rc=$?
check '[ "$rc" -eq 1 ] && [ "$(wc -l <stderr.txt)" -eq 1 ] && [ ! -e out.txt ]' "fporder --first n: exit $rc, one line, no file"
"$B/cfpo-fporder" --first x -o out.txt x.txt >stdout.txt 2>stderr.txt
rc=$?
check '[ "$rc" -eq 2 ] && [ "$(wc -l <stderr.txt)" -eq 1 ] && [ ! -e out.txt ]' "fporder --first x: exit $rc, one line, no file"
finish
