#!/bin/sh
# cli_errors.sh - bad inputs: every reader error (missing, unknown format,
# empty, garbage, NaN, outside [0,1), truncated or corrupt .npy, wrong .npy
# shape, raw size not a multiple of 16, a folder) and every run-time error
# (sets of different n, a bad file after a good one, an uncreatable output
# folder) exits 1 with exactly one line "cfpo-analyze: ..." naming the file,
# and leaves no output folder and no temporary folder; usage errors exit 2;
# SIGINT and SIGTERM during a run leave nothing behind.
. "$(dirname "$0")/common.sh"
cd "$T" || exit 1

"$B/cfpo" -n 64 -t 1 -q -o good.txt >/dev/null
"$B/cfpo" -n 100 -t 1 -q -o other.txt >/dev/null
"$B/cfpo" -n 64 -t 1 -q -o good.npy >/dev/null
"$B/cfpo" -n 64 -t 1 -q -o good.bin >/dev/null
cp good.txt good.csv
: >empty.txt
printf '0.1 0.2\n0.3 abc\n' >garbage.txt
printf '0.1 0.2\nnan 0.5\n' >nan.txt
printf '0.1 0.2\n1.0 0.5\n' >one.txt
printf '0.1 0.2\n-0.1 0.5\n' >neg.txt
printf '0.1 0.2\n0.5\n' >single.txt
head -c 100 good.npy >trunc.npy
printf 'hello world, not numpy' >magic.npy
head -c 20 good.bin >short.bin
mkdir dir.txt
# a .npy of shape (2, 3)
h="{'descr': '<f8', 'fortran_order': False, 'shape': (2, 3), }"
pad=$((128 - 10 - ${#h} - 1))
{ printf '\223NUMPY\001\000\166\000%s' "$h"; printf "%${pad}s\n" ""; head -c 48 /dev/zero; } >shape.npy

expect() { # expect CODE NAME ARGS...: exit code, message shape, nothing left
  code=$1; name=$2; shift 2
  rm -rf out out.tmp.* 2>/dev/null
  "$A" -q -o out "$@" >stdout.txt 2>stderr.txt
  rc=$?
  if [ "$rc" -ne "$code" ]; then bad "$name: exit $rc, expected $code"; return; fi
  first=$(head -n 1 stderr.txt)
  case "$first" in cfpo-analyze:\ *) ok ;; *) bad "$name: message '$first'" ;; esac
  if [ "$code" -eq 1 ]; then
    check '[ "$(wc -l <stderr.txt)" -eq 1 ]' "$name: not one line: $(cat stderr.txt)"
  fi
  check '[ ! -s stdout.txt ]' "$name: output on stdout"
  check '[ ! -e out ] && [ -z "$(ls -d out.* 2>/dev/null)" ]' "$name: output folder left behind"
}
expect 1 missing nope.txt
expect 1 "unknown extension" good.csv
expect 1 empty empty.txt
expect 1 garbage garbage.txt
expect 1 NaN nan.txt
expect 1 "x = 1" one.txt
expect 1 negative neg.txt
expect 1 "one number" single.txt
expect 1 "truncated npy" trunc.npy
expect 1 "bad magic" magic.npy
expect 1 "npy shape" shape.npy
expect 1 "short raw" short.bin
expect 1 folder dir.txt
expect 1 "different n" good.txt other.txt
expect 1 "good then bad" good.txt nan.txt
expect 1 "good then missing" good.npy good.bin nope.txt
# the message names the file
"$A" -q -o out good.txt nan.txt 2>stderr.txt
check 'grep -q "nan.txt" stderr.txt' "message does not name the bad file"
"$A" -q -o /proc/none/out good.txt 2>stderr.txt
check '[ $? -eq 1 ] && [ "$(wc -l <stderr.txt)" -eq 1 ]' "uncreatable output folder"
expect 2 "no file"
expect 2 "K = 0" -K 0 good.txt
expect 2 "K not a number" -K abc good.txt
expect 2 "K too large" -K 100000 good.txt
expect 2 "bad tolerance" --cert-tol 2 good.txt
expect 2 "negative grid" --grid -3 good.txt
expect 2 "grid not a number" --grid x good.txt
expect 2 "unknown option" --bogus good.txt
expect 2 "^cfpo-analyze: option '--quiet' takes no value" --quiet=1 good.txt
expect 2 "missing value" good.txt -K
# interrupted runs leave nothing (a long exact spectrum, stopped early)
"$B/cfpo" -n 4096 -t 1 -q -o big.npy >/dev/null
for sig in INT TERM; do
  rm -rf out
  "$A" -q --exact -K 1500 -o out big.npy >/dev/null 2>&1 &
  pid=$!
  sleep 1
  kill -s $sig $pid
  wait $pid
  rc=$?
  check '[ $rc -gt 128 ] && [ ! -e out ] && [ -z "$(ls -d out.* 2>/dev/null)" ]' "SIG$sig: exit $rc, left: $(ls -d out* 2>/dev/null)"
done
# the three formats give the same answer
for f in good.txt good.npy good.bin; do "$A" -q -K 16 -o "o_$f" "$f" >/dev/null || bad "reading $f"; done
check 'cmp -s o_good.txt/spectrum.txt o_good.npy/spectrum.txt && cmp -s o_good.txt/spectrum.txt o_good.bin/spectrum.txt' \
  "formats disagree"
finish
