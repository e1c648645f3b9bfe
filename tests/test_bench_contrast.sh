#!/usr/bin/env bash
# test_bench_contrast.sh BUILD_DIR - `cfpo-bench contrast` (src/bench_contrast.c):
# one line a round on stderr and one RESULT line whose medians,
# quartiles and minima are those of the round lines (recomputed here: the
# median of 3 and 4 rounds, the quartiles by linear interpolation), and
# whose ratio of the best rounds is their quotient; the densities
# and the reference it names, and -t; bad input (an unknown density, n
# too small for the density, -k 0, a stray argument, in this mode and in
# another) gives one line and a non-zero exit. No timing is asserted (benchmarks measure speed, tests do not).
set -u
B=$(cd "$1" && pwd)
T=$(mktemp -d /tmp/cfpo-contrast-XXXXXX)
trap 'rm -rf "$T"' EXIT
cd "$T" || exit 1
pass=0 fail=0
bad() { fail=$((fail + 1)); echo "FAIL: $*" >&2; }
ok() { pass=$((pass + 1)); }
field() { grep -o " $1=[^ ]*" r.out | cut -d= -f2-; }
for k in 3 4; do
  t=$((k - 2)) # one thread (the default), then -t 2
  topt=; [ "$t" -gt 1 ] && topt="-t $t"
  if ! "$B/cfpo-bench" contrast -n 2600 -k "$k" $topt -d ramp:contrast=16 -r cos:a=0.5 >r.out 2>r.err; then
    bad "contrast -k $k: $(head -n 1 r.err)"; continue
  fi
  [ "$(grep -c '^RESULT contrast ' r.out)" = 1 ] && [ "$(wc -l <r.out)" = 1 ] && ok || bad "-k $k: one RESULT line: $(cat r.out)"
  [ "$(grep -c '^cfpo-bench: contrast round [0-9]* of '"$k"': ' r.err)" = "$k" ] && ok || bad "-k $k: $k round lines: $(cat r.err)"
  [ "$(field n) $(field threads) $(field rounds) $(field seeds) $(field iterations)" = "2600 $t $k 3 3-22" ] && ok ||
    bad "-k $k: n, threads, rounds, seeds, iterations: $(cat r.out)"
  [ "$(field density) $(field reference)" = "ramp:contrast=16 cos:a=0.5" ] && ok || bad "-k $k: the specs: $(cat r.out)"
  # the statistics from the round lines: "... X ms against Y ms an iteration, ratio R"
  want=$(awk 'BEGIN { n = 0 } /contrast round/ { a[n] = $7; b[n] = $10; r[n] = $NF; n++ }
    function q(v, p,   i, j, t, at, lo) { for (i = 0; i < n; i++) s[i] = v[i]
      for (i = 1; i < n; i++) for (j = i; j > 0 && s[j - 1] > s[j]; j--) { t = s[j]; s[j] = s[j - 1]; s[j - 1] = t }
      at = p * (n - 1); lo = int(at); return lo + 1 < n ? s[lo] + (at - lo) * (s[lo + 1] - s[lo]) : s[lo] }
    END { printf "%.4f %.4f %.4f %.4f %.4f %.4f %.4f", q(a, 0.5), q(b, 0.5), q(r, 0.25), q(r, 0.5), q(r, 0.75), q(a, 0), q(b, 0) }' r.err)
  got="$(field ms_per_iteration) $(field reference_ms_per_iteration) $(field ratio_q1) $(field ratio) $(field ratio_q3) $(field best_ms_per_iteration) $(field best_reference_ms_per_iteration)"
  # each round line rounds to 4 places: the medians, quartiles and minima agree within 2e-4
  awk -v w="$want" -v g="$got" 'BEGIN { split(w, a); split(g, b); for (i = 1; i <= 7; i++) if (a[i] - b[i] > 2e-4 || b[i] - a[i] > 2e-4) exit 1 }' &&
    ok || bad "-k $k: medians, quartiles and minima $got, from the round lines $want"
  awk -v a="$(field best_ms_per_iteration)" -v b="$(field best_reference_ms_per_iteration)" -v r="$(field ratio_of_best)" \
    'BEGIN { d = a / b - r; exit !(d < 1e-3 && d > -1e-3) }' && ok || bad "-k $k: ratio_of_best is not best over best: $(cat r.out)"
  awk -v q1="$(field ratio_q1)" -v m="$(field ratio)" -v q3="$(field ratio_q3)" 'BEGIN { exit !(q1 > 0 && q1 <= m && m <= q3) }' &&
    ok || bad "-k $k: quartiles out of order: $(cat r.out)"
done
# bad input: one line, a non-zero exit (a stray argument in another mode too)
for args in "contrast -n 4096 -k 1 -d nosuch" "contrast -n 1024 -k 1" "contrast -n 4096 -k 0" "contrast -n 4096 -k 1 stray" \
            "contrast -n 4096 -k 1 -r ramp:contrast=0.5" "sweep -n 1000 -k 1 stray"; do
  if "$B/cfpo-bench" $args >r.out 2>r.err; then bad "$args: accepted"
  elif [ "$(wc -l <r.err)" = 1 ] && grep -q '^cfpo-bench: ' r.err && [ ! -s r.out ]; then ok
  else bad "$args: not one line: $(cat r.err)"; fi
done
echo "$pass passed, $fail failed"
[ "$fail" = 0 ]
