#!/usr/bin/env bash
# test_plain.sh BUILD_DIR - the engine against the plain engine of
# `cfpo-bench plain` (src/bench_plain.c: one thread, every point solved,
# the cell list sorted again after each phase, no skipping, tiles or halo):
# the paper variant's points after K iterations are the same bytes, for
# several n (squares and not), seeds, thread counts and with and without
# skipping. A difference in the engine's gather, relocation, id order,
# skipping or colour schedule changes some point's bits.
set -u
B=$(cd "$1" && pwd)
T=$(mktemp -d /tmp/cfpo-plain-XXXXXX)
trap 'rm -rf "$T"' EXIT
cd "$T" || exit 1
pass=0 fail=0
bad() { fail=$((fail + 1)); echo "FAIL: $*" >&2; }
for cfg in "1000 1 6" "4096 2 20" "5000 3 12" "20000 4 8"; do
  set -- $cfg
  n=$1 s=$2 k=$3
  if ! "$B/cfpo-bench" plain -n "$n" -s "$s" -k "$k" -o "p.bin" >p.out 2>p.err; then
    bad "plain n=$n: $(cat p.err)"; continue
  fi
  for opt in "-t 1" "-t 2" "-t 3 --no-skip"; do
    if ! "$B/cfpo" -n "$n" --seed "$s" --variant paper --max-iter "$k" $opt -q -o e.bin >e.out 2>e.err; then
      bad "cfpo n=$n $opt: $(cat e.err)"; continue
    fi
    if cmp -s p.bin e.bin; then pass=$((pass + 1)); else bad "n=$n seed=$s $k iterations $opt: engine and plain engine differ"; fi
  done
  # Both report the same statistics of the same set.
  pm=$(sed -n 's/.* delta_min=\([^ ]*\).*/\1/p' p.out) em=$(sed -n 's/.* delta_min=\([^ ]*\).*/\1/p' e.out)
  if [ "$pm" = "$em" ]; then pass=$((pass + 1)); else bad "n=$n: delta_min $pm (plain) against $em (engine)"; fi
done
# A plain run that cannot write its file says why in one line, exits
# non-zero and leaves nothing behind.
before=$(ls -A)
if "$B/cfpo-bench" plain -n 1000 -k 1 -o no-such-dir/x.bin >/dev/null 2>err.txt; then bad "output into a missing folder accepted"
elif [ "$(wc -l <err.txt)" -eq 1 ] && grep -q "cfpo-bench" err.txt && [ "$(ls -A | grep -v '^err.txt$')" = "$(echo "$before" | grep -v '^err.txt$')" ]; then pass=$((pass + 1))
else bad "output into a missing folder: $(cat err.txt)"; fi
echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]
