#!/usr/bin/env bash
# fuzz.sh BUILD_DIR [SECONDS] - runs every libFuzzer harness of BUILD_DIR
# (built by `make fuzz`) for SECONDS each (default 60), FUZZ_JOBS of them
# at a time (a whole number, default the number of cores; a harness is one
# process, so each still has a core for its SECONDS), starting from the
# committed seed corpus fuzz/corpus/NAME (never changed: new inputs go to
# BUILD_DIR/corpus/NAME). Fails on any crash, sanitizer report, leak,
# time-out (an input over 10 s) or out-of-memory; the input that did it is
# kept in BUILD_DIR/artifacts/. Prints one line per harness, in the list's
# order: executions, corpus size, and the slowest input (libFuzzer's whole
# seconds, and milliseconds when the corpus is replayed one by one).
# Tested by tests/test_fuzz_script.sh (with stand-in harnesses).
set -uo pipefail
B=${1:?usage: fuzz.sh BUILD_DIR [SECONDS]}
S=${2:-60}
J=${FUZZ_JOBS:-$(nproc)}
case $J in
  '' | *[!0-9]* | 0*) echo "fuzz: FUZZ_JOBS must be a whole number of at least 1, not '$J'" >&2; exit 2 ;;
esac
ROOT=$(cd "$(dirname "$0")/.." && pwd)
HARNESSES="text csv npy raw ckpt numbers pgm png d3ckpt d3points"
mkdir -p "$B/artifacts"
for h in $HARNESSES; do
  [ -x "$B/fuzz/fuzz_$h" ] || { echo "fuzz: $B/fuzz/fuzz_$h missing (run make fuzz)" >&2; exit 1; }
done

# One harness: its line into $B/fuzz_$h.line, followed by the failure's
# lines when it failed.
one() {
  local h=$1 exe="$B/fuzz/fuzz_$1" log="$B/fuzz_$1.log" rc execs slow slowest
  mkdir -p "$B/corpus/$h"
  "$exe" -max_total_time="$S" -timeout=10 -rss_limit_mb=2048 -max_len=65536 -print_final_stats=1 \
    -artifact_prefix="$B/artifacts/${h}-" "$B/corpus/$h" "$ROOT/fuzz/corpus/$h" >"$log" 2>&1
  rc=$?
  execs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log")
  slow=$(sed -n 's/^stat::slowest_unit_time_sec: *//p' "$log")
  # The slowest input of the corpus, replayed one by one (milliseconds).
  slowest=$(find "$B/corpus/$h" "$ROOT/fuzz/corpus/$h" -type f -print0 | xargs -0 -r "$exe" 2>&1 |
    sed -n 's/^Executed \(.*\) in \([0-9]*\) ms$/\2 \1/p' | sort -n | tail -1)
  {
    echo "FUZZ harness=$h seconds=$S rc=$rc executions=${execs:-?} corpus=$(ls "$B/corpus/$h" | wc -l)" \
      "slowest_unit_s=${slow:-?} slowest_replay_ms=${slowest%% *} slowest_input=${slowest#* }"
    if [ $rc -ne 0 ] || grep -qE "ERROR: (AddressSanitizer|LeakSanitizer|libFuzzer)|runtime error:|SUMMARY: " "$log"; then
      echo "fuzz: $h failed; see $log and $B/artifacts/"
      grep -E "ERROR|runtime error|SUMMARY|Test unit written" "$log" | head -5
    fi
  } >"$B/fuzz_$h.line.tmp" && mv "$B/fuzz_$h.line.tmp" "$B/fuzz_$h.line"
}

for h in $HARNESSES; do
  rm -f "$B/fuzz_$h.line"
  while [ "$(jobs -rp | wc -l)" -ge "$J" ]; do wait -n; done
  one "$h" &
done
wait
status=0
for h in $HARNESSES; do # in the list's order, whatever order they ended in
  if [ ! -f "$B/fuzz_$h.line" ]; then
    echo "fuzz: $h gave no result" >&2
    status=1
    continue
  fi
  sed -n 1p "$B/fuzz_$h.line"
  if [ "$(wc -l <"$B/fuzz_$h.line")" -gt 1 ]; then # a failure: its lines follow
    sed -n '2,$p' "$B/fuzz_$h.line" >&2
    status=1
  fi
done
exit $status
