#!/usr/bin/env bash
# test_fuzz_script.sh - scripts/fuzz.sh with stand-in harnesses (shell
# scripts that print libFuzzer's final stats): one line per harness in the
# list's order whatever order they end in; FUZZ_JOBS harnesses at a time
# (harness text waits for harness csv to have started: it passes with 2
# jobs and times out with 1); a harness's sanitizer report fails the run
# and is printed; a missing harness and a bad FUZZ_JOBS are refused in one
# line, running nothing.
set -uo pipefail
ROOT=$(cd "$(dirname "$0")/.." && pwd)
FUZZ="$ROOT/scripts/fuzz.sh"
T=$(mktemp -d /tmp/cfpo-fuzzsh-XXXXXX)
trap 'rm -rf "$T"' EXIT
pass=0 fail=0
ok() { pass=$((pass + 1)); }
bad() { fail=$((fail + 1)); echo "FAIL: $*" >&2; }
LIST="text csv npy raw ckpt numbers pgm png d3ckpt d3points"

# stand-ins in $1/fuzz: each notes its start in $1/started, the later ones
# in the list end first (sleeps), text waits up to 3 s for csv's start
make_build() {
  local b=$1 k=0
  mkdir -p "$b/fuzz"
  for h in $LIST; do
    k=$((k + 1))
    cat >"$b/fuzz/fuzz_$h" <<EOS
#!/usr/bin/env bash
case "\$1" in -max_total_time=*) ;; *) exit 0 ;; esac # a replay of the corpus
echo $h >>"$b/started"
if [ $h = text ]; then
  for _ in \$(seq 30); do grep -qx csv "$b/started" && break; sleep 0.1; done
  grep -qx csv "$b/started" || { echo "==1==ERROR: libFuzzer: timeout"; exit 1; }
fi
sleep 0.$((10 - k))
echo "stat::number_of_executed_units: $k"
echo "stat::slowest_unit_time_sec: 0"
EOS
    chmod +x "$b/fuzz/fuzz_$h"
  done
}

# all pass, two at a time
make_build "$T/a"
FUZZ_JOBS=2 "$FUZZ" "$T/a" 1 >"$T/out" 2>"$T/err"
rc=$?
[ $rc -eq 0 ] && ok || bad "two jobs: exit $rc: $(head -3 "$T/err")"
got=$(sed -n 's/^FUZZ harness=\([a-z0-9]*\) .*/\1/p' "$T/out" | tr '\n' ' ')
[ "$got" = "$LIST " ] && ok || bad "lines out of order or missing: '$got'"
[ "$(wc -l <"$T/out")" -eq 10 ] && ok || bad "$(wc -l <"$T/out") lines on stdout, expected 10"
grep -q "harness=npy seconds=1 rc=0 executions=3 " "$T/out" && ok || bad "npy's line: $(grep npy "$T/out")"
[ ! -s "$T/err" ] && ok || bad "stderr not empty: $(head -2 "$T/err")"

# one at a time: text cannot see csv start, so it fails (proof that two
# ran at once above); its report goes to stderr, every line still printed
make_build "$T/b"
FUZZ_JOBS=1 "$FUZZ" "$T/b" 1 >"$T/out" 2>"$T/err"
rc=$?
[ $rc -eq 1 ] && ok || bad "one job: exit $rc, expected 1"
grep -q "^fuzz: text failed" "$T/err" && grep -q "libFuzzer: timeout" "$T/err" && ok ||
  bad "one job: text's failure not reported: $(cat "$T/err")"
[ "$(wc -l <"$T/out")" -eq 10 ] && ok || bad "one job: $(wc -l <"$T/out") lines, expected 10"
[ "$(head -1 "$T/b/started")" = text ] && [ "$(sed -n 2p "$T/b/started")" = csv ] && ok ||
  bad "one job: not in the list's order: $(tr '\n' ' ' <"$T/b/started")"

# a sanitizer report from one harness, among parallel ones
make_build "$T/c"
printf '#!/usr/bin/env bash\necho "==1==ERROR: AddressSanitizer: heap-buffer-overflow"\necho "SUMMARY: AddressSanitizer: x"\n' \
  >"$T/c/fuzz/fuzz_pgm"
FUZZ_JOBS=4 "$FUZZ" "$T/c" 1 >"$T/out" 2>"$T/err"
rc=$?
[ $rc -eq 1 ] && ok || bad "sanitizer report: exit $rc, expected 1"
grep -q "^fuzz: pgm failed" "$T/err" && grep -q "heap-buffer-overflow" "$T/err" && ok ||
  bad "pgm's report not on stderr: $(cat "$T/err")"
[ "$(grep -c '^fuzz: .* failed' "$T/err")" -eq 1 ] && ok || bad "more than pgm failed: $(cat "$T/err")"
[ "$(wc -l <"$T/out")" -eq 10 ] && ok || bad "sanitizer report: $(wc -l <"$T/out") lines, expected 10"

# refused before anything runs
make_build "$T/d"
rm "$T/d/fuzz/fuzz_png"
"$FUZZ" "$T/d" 1 >"$T/out" 2>"$T/err"
rc=$?
[ $rc -eq 1 ] && [ "$(wc -l <"$T/err")" -eq 1 ] && grep -q "fuzz_png missing" "$T/err" && [ ! -e "$T/d/started" ] && ok ||
  bad "missing harness: exit $rc, '$(cat "$T/err")', started: $(cat "$T/d/started" 2>/dev/null)"
for j in 0 abc -1 1.5 ""; do
  FUZZ_JOBS=$j "$FUZZ" "$T/a" 1 >"$T/out" 2>"$T/err"
  rc=$?
  if [ -z "$j" ]; then # empty: the default, the number of cores
    [ $rc -eq 0 ] && ok || bad "FUZZ_JOBS='': exit $rc: $(head -2 "$T/err")"
    continue
  fi
  [ $rc -eq 2 ] && [ "$(wc -l <"$T/err")" -eq 1 ] && grep -q "FUZZ_JOBS must be" "$T/err" && [ ! -s "$T/out" ] && ok ||
    bad "FUZZ_JOBS='$j': exit $rc, '$(cat "$T/err")'"
done

echo "$pass passed, $fail failed"
[ $fail -eq 0 ]
