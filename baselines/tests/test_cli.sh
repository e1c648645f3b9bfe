#!/usr/bin/env bash
# test_cli.sh BUILD_DIR - the baseline commands keep cfpo's conventions:
# exit codes (0 ok, 1 runtime failure, 2 usage error) and "prog: message"
# errors; -o in every point format, atomic (no file after a failure);
# --trace; one SUMMARY line; the same seed gives the same bytes; dart
# throwing's saturation message. Ends with "N passed, N failed".
set -u
B=${1:?usage: test_cli.sh BUILD_DIR}
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT
pass=0 fail=0
ok() { pass=$((pass + 1)); }
bad() { fail=$((fail + 1)); echo "FAIL: $*" >&2; }

# expect CODE PATTERN CMD...: exit status CODE and stderr matching PATTERN.
expect() {
  local code=$1 pat=$2; shift 2
  "$@" >"$T/out" 2>"$T/err"
  local rc=$?
  if [ $rc -ne "$code" ]; then bad "$* -> exit $rc, want $code ($(head -c 300 "$T/err"))"; return; fi
  if [ -n "$pat" ] && ! grep -qE -- "$pat" "$T/err"; then
    bad "$* -> stderr '$(head -c 300 "$T/err")' lacks /$pat/"; return
  fi
  ok
}

# the baseline commands: scripts/methods.tsv, kinds pd and iter
BENCH_PY="$(cd "$(dirname "$0")/../../scripts" && pwd)/bench.py"
ITER_BIN=" $(python3 "$BENCH_PY" methods --binaries iter) "
for c in $(python3 "$BENCH_PY" methods --binaries pd iter); do
  X="$B/$c"
  # iterative methods: capped, so the format and determinism runs stay short
  cap=(); [[ $ITER_BIN == *" $c "* ]] && cap=(--max-iter 30)
  [ -x "$X" ] || { bad "$X missing"; continue; }
  expect 0 "" "$X" --help
  grep -q "^Usage: $c" "$T/out" && ok || bad "$c --help: no usage line"
  expect 0 "" "$X" -V
  grep -q "^$c " "$T/out" && ok || bad "$c -V: $(cat "$T/out")"
  expect 2 "^$c: the number of points is required|^$c: -n N or --radius R is required" "$X"
  expect 2 "^$c: -n: 'abc' is not a positive whole number" "$X" -n abc
  expect 2 "^$c: -n: '0' is not" "$X" -n 0
  expect 2 "^$c: -n: '-5' is not" "$X" -n -5
  expect 2 "^$c: --seed: 'x1' is not" "$X" -n 100 --seed x1
  expect 2 "^$c: unknown option '--bogus'" "$X" -n 100 --bogus
  expect 2 "^$c: unknown option '-Z'" "$X" -n 100 -Z
  expect 2 "^$c: option '--quiet' takes no value" "$X" -n 100 --quiet=1
  expect 2 "^$c: option '-n' needs a value" "$X" -n
  expect 2 "^$c: unexpected argument 'extra'" "$X" -n 100 extra
  expect 2 "^$c: $T/p.xyz: unknown output format" "$X" -n 100 -o "$T/p.xyz"
  grep -q "$c --help" "$T/err" && ok || bad "$c: no --help hint"
  expect 1 "^$c: .*cannot create" "$X" -n 200 -q -o "$T/no/such/dir/p.txt"
  expect 1 "^$c: .*" "$X" -n 200 -q --trace "$T/no/such/dir/t.tsv"
  # Every format, the same bytes for the same seed, a SUMMARY line.
  for ext in txt npy bin; do
    expect 0 "" "$X" -n 300 -q -s 7 "${cap[@]}" -o "$T/a.$ext" --trace "$T/a.tsv"
    grep -q "^SUMMARY method=" "$T/out" && ok || bad "$c: no SUMMARY line"
    [ "$(grep -c . "$T/out")" = 1 ] && ok || bad "$c: stdout has more than the SUMMARY line"
    [ -s "$T/a.$ext" ] && ok || bad "$c: no $ext output"
    expect 0 "" "$X" -n 300 -q -s 7 "${cap[@]}" -o "$T/b.$ext"
    cmp -s "$T/a.$ext" "$T/b.$ext" && ok || bad "$c: seed 7 twice gives different .$ext bytes"
  done
  expect 0 "" "$X" -n 300 -q -s 7 "${cap[@]}" -o "$T/a.txt"
  n=$(grep -vc '^#' "$T/a.txt")
  npts=$(sed -n 's/.* n=\([0-9]*\) .*/\1/p' "$T/out")
  [ "$n" = "$npts" ] && ok || bad "$c: text file has $n points, SUMMARY says $npts"
  [ "$(stat -c %s "$T/a.bin")" = $((16 * n)) ] && ok || bad "$c: .bin is not 16 n bytes"
  expect 0 "" "$X" -n 300 -q -s 8 "${cap[@]}" -o "$T/c.txt"
  cmp -s "$T/a.txt" "$T/c.txt" && bad "$c: seeds 7 and 8 give the same points" || ok
  head -c 6 "$T/a.npy" | grep -q NUMPY && ok || bad "$c: .npy header"
  [ "$(head -n 1 "$T/a.tsv" | cut -f1)" != "" ] && [ "$(wc -l <"$T/a.tsv")" -ge 2 ] && ok \
    || bad "$c: trace has no rows"
  ls "$T" | grep -q '\.tmp\.' && bad "$c: temporary file left behind" || ok
done

# Iterative methods: cfpo's trace columns, one row per iteration plus row 0.
for c in cfpo-fpo cfpo-lfpo; do
  X="$B/$c"
  expect 0 "" "$X" -n 300 -q --max-iter 4 --trace "$T/f.tsv"
  [ "$(head -n 1 "$T/f.tsv")" = "$(printf 'iteration\tdelta_min\tdelta_avg\tmoved\tsolved\tmax_disp\tseconds\telapsed')" ] \
    && ok || bad "$c: trace header $(head -n 1 "$T/f.tsv")"
  [ "$(wc -l <"$T/f.tsv")" = 6 ] && ok || bad "$c: trace has $(wc -l <"$T/f.tsv") lines, want 6"
  grep -q "iterations=4 .*converged=no" "$T/out" && ok || bad "$c: summary $(cat "$T/out")"
  expect 2 "^$c: --tol: '0.7' is not a number in \[0, 0.49\]" "$X" -n 300 --tol 0.7
  expect 2 "^$c: --max-iter: 'x' is not" "$X" -n 300 --max-iter x
  expect 2 "^$c: --start: 'foo' is not one of random, grid" "$X" -n 300 --start foo
  expect 2 "^$c: n = 5 is too small" "$X" -n 5
  expect 0 "" "$X" -n 300 -q --max-iter 0
  grep -q "iterations=0 " "$T/out" && ok || bad "$c: --max-iter 0"
done
grep -q "method=lfpo" "$T/out" && ok || bad "cfpo-lfpo does not report method=lfpo"
expect 0 "" "$B/cfpo-fpo" -n 300 -q --local --max-iter 1
grep -q "method=lfpo" "$T/out" && ok || bad "cfpo-fpo --local is not LFPO"
# CCVT's, CCDT's and BNOT's own memory models, not cfpo's.
expect 1 "^cfpo-ccvt: n = 16777216 is too large for memory: ccvt needs about 178\.2 GB" "$B/cfpo-ccvt" -n 2^24
expect 1 "^cfpo-ccdt: n = 1073741824 is too large for memory: ccdt needs about 773\.1 GB" "$B/cfpo-ccdt" -n 2^30
expect 1 "^cfpo-bnot: n = 1073741824 is too large for memory: bnot needs about 1073\.8 GB" "$B/cfpo-bnot" -n 2^30
# FPO's own memory model (about 720 bytes a point), not cfpo's.
expect 1 "^cfpo-fpo: n = 1073741824 is too large for memory: the triangulation needs about 773\.1 GB" "$B/cfpo-fpo" -n 2^30

# CCVT, CCDT and BNOT (bl_cli.c): cfpo's trace columns then their own,
# one row per iteration plus row 0, the stop rules, bad values.
for c in cfpo-ccvt cfpo-ccdt cfpo-bnot; do
  X="$B/$c"
  case $c in
    cfpo-ccvt) extra=$(printf '\tswaps') ;;
    cfpo-ccdt) extra=$(printf '\tsweeps\tstep\tnew_edges\tarea_cv') ;;
    *) extra=$(printf '\tnewton\tcg\tcap_err\tenergy\tgrad_norm\tphase\tround\tregular') ;;
  esac
  expect 0 "" "$X" -n 300 -q --max-iter 4 --trace "$T/f.tsv"
  [ "$(head -n 1 "$T/f.tsv")" = "$(printf 'iteration\tdelta_min\tdelta_avg\tmoved\tsolved\tmax_disp\tseconds\telapsed')$extra" ] \
    && ok || bad "$c: trace header $(head -n 1 "$T/f.tsv")"
  [ "$(wc -l <"$T/f.tsv")" = 6 ] && ok || bad "$c: trace has $(wc -l <"$T/f.tsv") lines, want 6"
  [ "$(awk -F'\t' 'NR > 1 && $1 != NR - 2' "$T/f.tsv" | wc -l)" = 0 ] && ok || bad "$c: trace rows not numbered 0..4"
  grep -q "^SUMMARY method=${c#cfpo-} .*iterations=4 .*converged=no .*stop=max-iter" "$T/out" && ok || bad "$c: summary $(cat "$T/out")"
  expect 0 "" "$X" -n 300 -q --target-min 0.3 --trace "$T/g.tsv"
  last=$(tail -n 1 "$T/g.tsv" | cut -f1)
  grep -q "iterations=$last .*stop=target" "$T/out" && ok || bad "$c: --target-min 0.3: $(cat "$T/out")"
  expect 2 "^$c: --tol: '0.7' is not a number in \[0, 0.49\]" "$X" -n 300 --tol 0.7
  expect 2 "^$c: --max-iter: 'x' is not" "$X" -n 300 --max-iter x
  expect 2 "^$c: --target-min: " "$X" -n 300 --target-min abc
  expect 2 "^$c: n = 5 is too small" "$X" -n 5
  expect 0 "" "$X" -n 300 -q --max-iter 0
  grep -q "iterations=0 " "$T/out" && ok || bad "$c: --max-iter 0"
done
expect 2 "^cfpo-ccvt: --points-per-site: '0' is not a whole number" "$B/cfpo-ccvt" -n 300 --points-per-site 0
expect 2 "^cfpo-ccvt: --points-per-site: 'x' is not" "$B/cfpo-ccvt" -n 300 --points-per-site x
expect 2 "^cfpo-ccdt: unknown option '--points-per-site'" "$B/cfpo-ccdt" -n 300 --points-per-site 8
expect 2 "^cfpo-bnot: unknown option '--points-per-site'" "$B/cfpo-bnot" -n 300 --points-per-site 8
# BNOT run to a move tolerance (--epsilon 0): every row's capacity error
# within 1e-6 (the solver aims at 1e-8), the energy (normalised second
# moment) never rising after row 1.
expect 0 "" "$B/cfpo-bnot" -n 300 -q --epsilon 0 --max-iter 40 --trace "$T/b.tsv"
[ "$(awk -F'\t' 'NR > 1 && $11 + 0 > 1e-6' "$T/b.tsv" | wc -l)" = 0 ] && ok || bad "cfpo-bnot: a trace row with cap_err > 1e-6"
[ "$(awk -F'\t' 'NR > 2 && $12 > e * (1 + 1e-7) { print } { e = $12 }' "$T/b.tsv" | wc -l)" = 0 ] && ok \
  || bad "cfpo-bnot: the energy column rises"
# BNOT's default schedule: at n = 2048 the coarse phase meets the cap of
# 20 iterations (every step's phase column 1) and the run ends there; with
# --no-breaker one round only; the options' errors.
expect 0 "" "$B/cfpo-bnot" -n 2048 -q --trace "$T/b.tsv"
grep -q "iterations=20 .*converged=yes" "$T/out" && ok || bad "cfpo-bnot: the default schedule at n = 2048: $(cat "$T/out")"
[ "$(awk -F'\t' 'NR > 2 && $14 != 1' "$T/b.tsv" | wc -l)" = 0 ] && ok || bad "cfpo-bnot: a capped run left the coarse phase"
expect 0 "" "$B/cfpo-bnot" -n 300 -q --round-iters 500 --no-breaker --trace "$T/b.tsv"
[ "$(awk -F'\t' 'NR > 1 { print $15 }' "$T/b.tsv" | sort -u)" = 1 ] && ok || bad "cfpo-bnot: --no-breaker ran a second round"
expect 2 "^cfpo-bnot: --epsilon: 'x' is not a number" "$B/cfpo-bnot" -n 300 --epsilon x
expect 2 "^cfpo-bnot: --round-iters: '0' is not a whole number" "$B/cfpo-bnot" -n 300 --round-iters 0
expect 2 "^cfpo-bnot: --max-rounds: '-1' is not a whole number" "$B/cfpo-bnot" -n 300 --max-rounds -1
# CCDT's reference schedule: exactly K iterations; CCVT's options.
expect 0 "" "$B/cfpo-ccdt" -n 300 -q --reference 7
grep -q "iterations=7 .*converged=yes" "$T/out" && ok || bad "cfpo-ccdt --reference 7: $(cat "$T/out")"
expect 2 "^cfpo-ccdt: --reference: '0' is not a whole number" "$B/cfpo-ccdt" -n 300 --reference 0
expect 2 "^cfpo-ccvt: --point-set: 'grid' is neither lattice nor random" "$B/cfpo-ccvt" -n 300 --point-set grid
expect 2 "^cfpo-ccvt: --update: 'x' is neither pair nor pass" "$B/cfpo-ccvt" -n 300 --update x
expect 2 "^cfpo-ccvt: --assign: 'x' is neither nearest nor curve" "$B/cfpo-ccvt" -n 300 --assign x
expect 1 "^cfpo-ccvt: n m = 20180 points have no lattice" "$B/cfpo-ccvt" -n 20 --points-per-site 1009
expect 0 "" "$B/cfpo-ccvt" -n 300 -q --points-per-site 8 --point-set random -o "$T/r8.txt"
expect 0 "" "$B/cfpo-ccvt" -n 300 -q --points-per-site 8 -o "$T/m8.txt"
cmp -s "$T/m8.txt" "$T/r8.txt" && bad "cfpo-ccvt: --point-set random has no effect" || ok
expect 0 "" "$B/cfpo-ccvt" -n 300 -q --points-per-site 9 -o "$T/m9.txt"
cmp -s "$T/m8.txt" "$T/m9.txt" && bad "cfpo-ccvt: --points-per-site has no effect" || ok

# Poisson-disk options.
expect 2 "^cfpo-bs: --max-fails applies to cfpo-dart only" "$B/cfpo-bs" -n 100 --max-fails 5
expect 2 "^cfpo-dart: -k applies to cfpo-bridson only" "$B/cfpo-dart" -n 100 -k 5
expect 2 "^cfpo-dart: give --radius or --rel-radius, not both" "$B/cfpo-dart" -n 100 -r 0.01 --rel-radius 0.7
expect 2 "^cfpo-dart: --rel-radius: '-1' is not" "$B/cfpo-dart" -n 100 --rel-radius -1
expect 2 "^cfpo-dart: --radius: '0' is not" "$B/cfpo-dart" -n 100 -r 0
expect 2 "^cfpo-bs: radius 0.3 is too large" "$B/cfpo-bs" -r 0.3
expect 2 "^cfpo-dart: radius 1e-06 is too small" "$B/cfpo-dart" -n 100 -r 1e-6
expect 0 "" "$B/cfpo-bs" -r 0.02 -q
grep -q "method=bs" "$T/out" && ok || bad "cfpo-bs -r without -n"
expect 0 "" "$B/cfpo-bridson" -n 500 -q --plain -k 5
# Saturation: past the jamming limit; clear message, exit 1, no output file.
expect 1 "^cfpo-dart: saturated: placed [0-9]+ of 2000 points at radius r = [0-9.e-]+ \(0\.9000 Delta\(n\)\); 100000 consecutive darts were rejected" \
  "$B/cfpo-dart" -n 2000 --rel-radius 0.9 --max-fails 100000 -q -o "$T/sat.txt"
[ -e "$T/sat.txt" ] && bad "saturated run left an output file" || ok
# DT places exactly n points.
expect 0 "" "$B/cfpo-dart" -n 1234 -q -o "$T/d.txt"
[ "$(grep -vc '^#' "$T/d.txt")" = 1234 ] && ok || bad "cfpo-dart -n 1234 wrote $(grep -vc '^#' "$T/d.txt") points"

# PMJ02BN: its options, SUMMARY names, and bad input (one line, no file).
P="$B/cfpo-pmj02bn"
expect 2 "^cfpo-pmj02bn: --candidates: '0' is not a whole number" "$P" -n 300 --candidates 0 -o "$T/pm0.npy"
[ -e "$T/pm0.npy" ] && bad "cfpo-pmj02bn --candidates 0 left an output file" || ok
expect 2 "^cfpo-pmj02bn: -n: 'x' is not" "$P" -n x
for o in "" "--candidates 1" "--global" "--candidates 1 --global"; do
  expect 0 "" "$P" -n 1000 -q -s 3 $o -o "$T/pm.npy"
  want=pmj02bn; [[ $o == *"--candidates 1"* ]] && want=pmj02; [[ $o == *global* ]] && want=$want-global
  grep -q "^SUMMARY method=$want " "$T/out" && ok || bad "cfpo-pmj02bn $o: $(cat "$T/out")"
done
expect 0 "" "$P" -n 1000 -q -s 3 -o "$T/pm1.txt"
expect 0 "" "$P" -n 1000 -q -s 3 --candidates 1 -o "$T/pm2.txt"
cmp -s "$T/pm1.txt" "$T/pm2.txt" && bad "cfpo-pmj02bn: --candidates 1 changes nothing" || ok

echo "$pass passed, $fail failed"
[ $fail -eq 0 ]
