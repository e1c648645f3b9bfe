#!/usr/bin/env bash
# fuzz.sh BUILD_DIR [SECONDS] - runs every libFuzzer harness of BUILD_DIR
# (built by `make fuzz`) for SECONDS each (default 60), one after the
# other, starting from the committed seed corpus fuzz/corpus/NAME (never
# changed: new inputs go to BUILD_DIR/corpus/NAME). Fails on any crash,
# sanitizer report, leak, time-out (an input over 10 s) or out-of-memory;
# the input that did it is kept in BUILD_DIR/artifacts/. Prints one line
# per harness: executions, corpus size, and the slowest input (libFuzzer's
# whole seconds, and milliseconds when the corpus is replayed one by one).
set -uo pipefail
B=${1:?usage: fuzz.sh BUILD_DIR [SECONDS]}
S=${2:-60}
ROOT=$(cd "$(dirname "$0")/.." && pwd)
mkdir -p "$B/artifacts"
status=0
for h in text csv npy raw ckpt numbers pgm png d3ckpt d3points; do
  exe="$B/fuzz/fuzz_$h"
  [ -x "$exe" ] || { echo "fuzz: $exe missing (run make fuzz)" >&2; exit 1; }
  mkdir -p "$B/corpus/$h"
  log="$B/fuzz_$h.log"
  "$exe" -max_total_time="$S" -timeout=10 -rss_limit_mb=2048 -max_len=65536 -print_final_stats=1 \
    -artifact_prefix="$B/artifacts/${h}-" "$B/corpus/$h" "$ROOT/fuzz/corpus/$h" >"$log" 2>&1
  rc=$?
  execs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log")
  slow=$(sed -n 's/^stat::slowest_unit_time_sec: *//p' "$log")
  # The slowest input of the corpus, replayed one by one (milliseconds).
  slowest=$(find "$B/corpus/$h" "$ROOT/fuzz/corpus/$h" -type f -print0 | xargs -0 -r "$exe" 2>&1 |
    sed -n 's/^Executed \(.*\) in \([0-9]*\) ms$/\2 \1/p' | sort -n | tail -1)
  echo "FUZZ harness=$h seconds=$S rc=$rc executions=${execs:-?} corpus=$(ls "$B/corpus/$h" | wc -l)" \
    "slowest_unit_s=${slow:-?} slowest_replay_ms=${slowest%% *} slowest_input=${slowest#* }"
  if [ $rc -ne 0 ] || grep -qE "ERROR: (AddressSanitizer|LeakSanitizer|libFuzzer)|runtime error:|SUMMARY: " "$log"; then
    echo "fuzz: $h failed; see $log and $B/artifacts/" >&2
    grep -E "ERROR|runtime error|SUMMARY|Test unit written" "$log" | head -5 >&2
    status=1
  fi
done
exit $status
