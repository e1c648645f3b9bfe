#!/usr/bin/env bash
# test_replay.sh BUILD_DIR - every solver route the CPU runs (plain, AVX2,
# AVX-512) on real calls: `cfpo-bench capture` records the inputs of the
# local solves of a run (the adaptive variant's near solves among them,
# replayed as LocalCFPO problems), `cfpo-bench replay` solves each through
# every route and exits non-zero if any call's value or point differs in
# one bit.
# Also: a route asked for with -p runs alone, a bad -p value, a missing
# capture file and a folder are refused with one line.
set -u
B=$(cd "$1" && pwd)
T=$(mktemp -d /tmp/cfpo-replay-XXXXXX)
trap 'rm -rf "$T"' EXIT
cd "$T" || exit 1
pass=0 fail=0
bad() { fail=$((fail + 1)); echo "FAIL: $*" >&2; }
for cfg in "20000 1 1,2,5" "6000 4 3,12"; do
  set -- $cfg
  if ! "$B/cfpo-bench" capture -n "$1" -s "$2" -i "$3" -o calls.bin >c.out 2>c.err; then
    bad "capture n=$1: $(cat c.err)"; continue
  fi
  calls=$(sed -n 's/.* calls=\([0-9]*\).*/\1/p' c.out)
  if ! "$B/cfpo-bench" replay -o calls.bin -k 1 >r.out 2>r.err; then
    bad "replay n=$1: $(cat r.out r.err)"; continue
  fi
  # every captured call replayed, none differing
  grep -q "calls=$calls .*differing_calls=0" r.out && [ "${calls:-0}" -gt 1000 ] && pass=$((pass + 1)) ||
    bad "replay n=$1: $(cat r.out) (captured: $calls)"
  # a route the CPU has, asked for alone: its time, nothing compared
  for p in plain avx2 avx512; do
    "$B/cfpo-bench" replay -o calls.bin -k 1 -p $p >p.out 2>p.err || { bad "-p $p: $(cat p.err)"; continue; }
    if [ "$p" = plain ] || grep -q "$p=yes" p.out; then
      grep -q "${p}_ns_per_call=[1-9]" p.out && pass=$((pass + 1)) || bad "-p $p: no time: $(cat p.out)"
    fi
  done
done
"$B/cfpo-bench" replay -o calls.bin -p sse >o.txt 2>e.txt && bad "-p sse accepted" ||
  { [ "$(wc -l <e.txt)" -eq 1 ] && grep -q "bad solver 'sse'" e.txt && pass=$((pass + 1)) || bad "-p sse: $(cat e.txt)"; }
"$B/cfpo-bench" replay -o no-such.bin >o.txt 2>e.txt && bad "missing capture file accepted" ||
  { [ "$(wc -l <e.txt)" -eq 1 ] && pass=$((pass + 1)) || bad "missing file: $(cat e.txt)"; }
mkdir folder.bin
"$B/cfpo-bench" replay -o folder.bin >o.txt 2>e.txt && bad "a folder accepted as a capture file" ||
  { [ "$(wc -l <e.txt)" -eq 1 ] && grep -q "read error in 'folder.bin'" e.txt && pass=$((pass + 1)) || bad "folder: $(cat e.txt)"; }
echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]
