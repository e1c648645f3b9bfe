#!/usr/bin/env bash
# test_checkpoint.sh BUILD_DIR - checkpoints are checked, not trusted: a
# version-3 header with a checksum over header and points (one flipped bit
# anywhere is refused), every header field validated with a one-line error
# naming the file and the field, version-1 and -2 files still read (as runs
# past their near phase), a resume on either side of the switch from the
# near phase to exact solves the same bytes as the run never stopped,
# states no run of cfpo can reach refused before any work, and no
# temporary left behind by a signal that arrives while a checkpoint is
# being written.
set -u
B=$(cd "$1" && pwd)
CFPO="$B/cfpo"
T=$(mktemp -d /tmp/cfpo-ckpt-XXXXXX)
trap 'rm -rf "$T"' EXIT
cd "$T" || exit 1
pass=0 fail=0
ok() { pass=$((pass + 1)); }
bad() { fail=$((fail + 1)); echo "FAIL: $*" >&2; }

# refused FILE PATTERN: --resume FILE exits 1 within 30 s with one line on
# stderr naming the file and matching PATTERN, and writes no output.
refused() {
  local f=$1 pat=$2
  rm -f out.bin
  timeout 30 "$CFPO" -q --max-iter 2 --resume "$f" -o out.bin >o.log 2>e.log
  local rc=$?
  if [ $rc -ne 1 ]; then bad "$f: exit $rc, expected 1 ($(head -c 300 e.log))"; return; fi
  if [ "$(wc -l <e.log)" -ne 1 ]; then bad "$f: $(wc -l <e.log) lines on stderr"; return; fi
  grep -q -- "$f" e.log || { bad "$f: message does not name the file: $(cat e.log)"; return; }
  grep -q -- "$pat" e.log || { bad "$f: message '$(cat e.log)' lacks '$pat'"; return; }
  [ -e out.bin ] && { bad "$f: output written"; return; }
  ls -A | grep -q 'tmp\.' && { bad "$f: temporary left: $(ls -A | grep tmp)"; return; }
  ok
}
# le BYTES VALUE: VALUE (decimal, < 2^63) as BYTES little-endian bytes.
le() {
  local n=$1 v=$2 i s=""
  for ((i = 0; i < n; i++)); do s+=$(printf '\\x%02x' $(((v >> (8 * i)) & 255))); done
  printf "$s"
}
# patch FILE OFFSET BYTES...: overwrite bytes (given as \xHH text) at OFFSET.
patch() { local f=$1 off=$2; shift 2; printf "$*" | dd of="$f" bs=1 seek="$off" conv=notrunc status=none; }
# flip FILE OFFSET: flip the lowest bit of the byte at OFFSET.
flip() {
  local b; b=$(od -An -tu1 -j "$2" -N1 "$1" | tr -d ' ')
  patch "$1" "$2" "$(printf '\\x%02x' $((b ^ 1)))"
}

N=4096
"$CFPO" -q -n $N --max-iter 20 -o ref.bin >/dev/null || bad "reference run"
"$CFPO" -q -n $N --max-iter 10 --checkpoint ck.bin --checkpoint-every 10 >/dev/null || bad "checkpointed run"
[ "$(head -c 8 ck.bin)" = CFPOCKPT ] && [ "$(od -An -tu4 -j8 -N4 ck.bin | tr -d ' ')" = 4 ] &&
  [ "$(od -An -tu4 -j12 -N4 ck.bin | tr -d ' ')" = 80 ] && [ "$(od -An -tx1 -j64 -N16 ck.bin | tr -d ' 0\n')" = "" ] &&
  [ "$(stat -c %s ck.bin)" = $((80 + 16 * N)) ] && ok ||
  bad "checkpoint is not version 4 with no density ($(head -c 16 ck.bin | od -c | head -1))"
# The same state as a version-3 file (64-byte header), from which the older
# versions below are made: read as before.
python3 - ck.bin ck3.bin <<'PY'
import struct, sys, zlib
d = open(sys.argv[1], 'rb').read()
h = bytearray(d[:64]); struct.pack_into('<II', h, 8, 3, 64); struct.pack_into('<I', h, 60, 0)
struct.pack_into('<I', h, 60, zlib.crc32(bytes(h) + d[80:]) & 0xffffffff)
open(sys.argv[2], 'wb').write(bytes(h) + d[80:])
PY
"$CFPO" -q --max-iter 20 --resume ck3.bin -o res3.bin >/dev/null && cmp -s res3.bin ref.bin && ok ||
  bad "resume from a version-3 checkpoint differs from the uninterrupted run"
[ "$(od -An -tu4 -j56 -N4 ck.bin | tr -d ' ')" = 1 ] && ok || bad "a checkpoint in the near phase has near != 1"
"$CFPO" -q --max-iter 20 --resume ck.bin -o res.bin >/dev/null && cmp -s res.bin ref.bin && ok ||
  bad "resume from a version-4 checkpoint differs from the uninterrupted run"
# The schedule steps by iteration (two-cell near solves before 7, strong
# over-relaxation from 4 and before 20): checkpoints just before each step
# resume to the uninterrupted run's bytes.
"$CFPO" -q -n $N --max-iter 22 -o ref22.bin >/dev/null || bad "reference run to 22"
for k in 3 6 19; do
  "$CFPO" -q -n $N --max-iter $k --checkpoint st$k.ck --checkpoint-every $k >/dev/null || bad "checkpoint at $k"
  "$CFPO" -q --max-iter 22 --resume st$k.ck -o str$k.bin >/dev/null && cmp -s str$k.bin ref22.bin && ok ||
    bad "resume from iteration $k differs from the uninterrupted run"
done

# rehead IN OUT VERSION NEAR: IN with another version and near field, its
# checksum made right again.
rehead() {
  python3 - "$@" <<'PY'
import struct, sys, zlib
d = bytearray(open(sys.argv[1], 'rb').read())
struct.pack_into('<I', d, 8, int(sys.argv[3]))
struct.pack_into('<I', d, 56, int(sys.argv[4]))
struct.pack_into('<I', d, 60, 0)
struct.pack_into('<I', d, 60, zlib.crc32(bytes(d)) & 0xffffffff)
open(sys.argv[2], 'wb').write(d)
PY
}
# Version 2 (and 1, below) came from runs that solved exactly throughout:
# they resume as near = 0, the same bytes as a version-3 file saying so.
rehead ck3.bin exact.ck 3 0
rehead ck3.bin old2.ck 2 0
"$CFPO" -q --max-iter 20 --resume exact.ck -o res0.bin >/dev/null || bad "resume from near = 0"
cmp -s res0.bin res.bin && bad "near = 0 resumed as the near phase" || ok
"$CFPO" -q --max-iter 20 --resume old2.ck -o res2.bin >/dev/null 2>e.log && cmp -s res2.bin res0.bin && ok ||
  bad "version-2 checkpoint not read as near = 0: $(cat e.log)"
rehead ck3.bin res2.ck 2 1;                      refused res2.ck "reserved"
rehead ck3.bin near7.ck 3 7;                     refused near7.ck "near = 7"

# One flipped bit anywhere is refused: a point, the seed, the iteration,
# the checksum itself.
for off in $((64 + 16 * 100 + 3)) $((64 + 16 * N - 1)) 24 48 60; do
  cp ck.bin flip$off.ck; flip flip$off.ck $off
  refused flip$off.ck "checkpoint"
done
grep -q checksum e.log && ok || bad "a flipped bit is not reported as a checksum mismatch: $(cat e.log)"

# Version-1 files (no checksum): still read, same result; fields validated.
v1() { # v1 FILE N VARIANT TOL_BITS_HEX ITER CONVERGED [RESERVED]: header + ck.bin's points
  { printf CFPOCKP1; le 8 "$2"; le 8 1; le 8 "$3"
    printf "$4"; le 8 "$5"; le 8 "$6"; le 8 "${7:-0}"; tail -c +65 ck3.bin; } >"$1"
}
TOL=$(od -An -tx1 -j40 -N8 ck.bin | tr -d ' \n' | sed 's/../\\x&/g') # this run's tol, as bytes
v1 good.v1 $N 2 "$TOL" 10 0
"$CFPO" -q --max-iter 20 --resume good.v1 -o res1.bin >/dev/null 2>e.log && cmp -s res1.bin res0.bin && ok ||
  bad "version-1 checkpoint not read as before: $(cat e.log)"
v1 var.v1 $N $((2 + (1 << 32))) "$TOL" 10 0;  refused var.v1 "variant"
v1 conv.v1 $N 2 "$TOL" 10 7;                   refused conv.v1 "converged"
v1 tol.v1 $N 2 "$(printf '\\xa9\\x13\\xd0\\x44\\xd8\\xf0\\xdf\\x3f')" 10 0; refused tol.v1 "tol" # 0.4999
v1 iter.v1 $N 2 "$TOL" $((1 << 40)) 0;         refused iter.v1 "iteration"
v1 res.v1 $N 2 "$TOL" 10 0 1;                  refused res.v1 "reserved"
v1 small.v1 5 2 "$TOL" 10 0;                   refused small.v1 "n = 5"
v1 big.v1 $((N + 1)) 2 "$TOL" 10 0;            refused big.v1 "truncated"
v1 long.v1 $((N - 1)) 2 "$TOL" 10 0;           refused long.v1 "trailing"
# Version 4 fields: a version this cfpo does not know, converged = 7; the
# density schedule's state without a density.
cp ck.bin ver.ck; patch ver.ck 8 '\x05';        refused ver.ck "version 5"
cp ck.bin conv.ck; patch conv.ck 36 '\x07';     refused conv.ck "converged"
cp ck.bin nconv.ck; patch nconv.ck 36 '\x01';   refused nconv.ck "near = 1 with converged"
cp ck.bin nvar.ck; patch nvar.ck 32 '\x00';     refused nvar.ck "near = 1 with a variant"
cp ck.bin var.ck; patch var.ck 32 '\x02\x00\x00\x01'; refused var.ck "variant"
cp ck.bin dref.ck; patch dref.ck 72 '\x00\x00\x00\x00\x00\x00\xe0\x3f'; refused dref.ck "davg_ref"
printf 'CFPOCKPT' >short.ck;                    refused short.ck "not a cfpo checkpoint"

# A state no run can reach: 2000 points on one spot (a run never brings
# points closer than its start's minimum distance). Refused at once, not
# after minutes of solving one crowded cell.
{ for i in $(seq 2000); do tail -c +$((64 + 16 * 7 + 1)) ck3.bin | head -c 16; done; tail -c +$((64 + 16 * 2000 + 1)) ck3.bin; } >pts.raw
{ printf CFPOCKP1; le 8 $N; le 8 1; le 8 2; printf "$TOL"; le 8 10; le 8 0; le 8 0; cat pts.raw; } >crowd.v1
refused crowd.v1 "puts 20[0-9][0-9] points in cell"
# Two points on one spot, nothing crowded: the distance itself is refused.
{ tail -c +$((64 + 16 * 7 + 1)) ck3.bin | head -c 16; tail -c +$((64 + 16 + 1)) ck3.bin; } >pts2.raw
{ printf CFPOCKP1; le 8 $N; le 8 1; le 8 2; printf "$TOL"; le 8 10; le 8 0; le 8 0; cat pts2.raw; } >twin.v1
refused twin.v1 "closer than"
# A clump spaced wider than the start's minimum distance but far fuller
# than any run makes: 306 points in a square of half a cell side (n = 4096:
# a 57 x 57 grid), so one cell holds at least 76 whatever the grid's shift.
python3 - ck3.bin clump.v1 <<'PY'
import struct, sys
d = open(sys.argv[1], 'rb').read()
N, L = 4096, 1 / 57
pts = [struct.unpack_from('<dd', d, 64 + 16 * i) for i in range(N)]
sp = L / 2 / 18
lat = [(0.5 + sp * (i + 0.5), 0.5 + sp * (j + 0.5)) for i in range(18) for j in range(17)]
rest = [p for p in pts if not (0.49 < p[0] < 0.51 + L / 2 and 0.49 < p[1] < 0.51 + L / 2)]
hdr = b'CFPOCKP1' + struct.pack('<QQQdQQQ', N, 1, 2, 0.0, 10, 0, 0)
open(sys.argv[2], 'wb').write(hdr + b''.join(struct.pack('<dd', *p) for p in lat + rest[:N - len(lat)]))
PY
refused clump.v1 "more than 64 is refused"

# Across the switch from the near phase to exact solves (S, the first
# trace row with near = 0; the switch comes at the end of iteration S - 1,
# whose near sweep moved nothing): checkpoints at S - 2 and S - 1 (near =
# 1, then 0) resume to the bytes of the uninterrupted run.
"$CFPO" -q -n $N --max-iter 2000 --trace sw.tsv >/dev/null || bad "run to convergence"
S=$(awk -F'\t' 'NR > 2 && $10 == 0 { print $1; exit }' sw.tsv)
if [ -n "$S" ] && [ "$S" -gt 2 ]; then
  "$CFPO" -q -n $N --max-iter $((S + 3)) -o sw.bin >/dev/null || bad "run past the switch"
  for k in $((S - 2)) $((S - 1)); do
    "$CFPO" -q -n $N --max-iter $k --checkpoint sw$k.ck --checkpoint-every $k >/dev/null || bad "checkpoint at $k"
    [ "$(od -An -tu4 -j56 -N4 sw$k.ck | tr -d ' ')" = $((k < S - 1)) ] && ok || bad "checkpoint at $k: near field wrong"
    "$CFPO" -q --max-iter $((S + 3)) --resume sw$k.ck -o swr$k.bin >/dev/null && cmp -s swr$k.bin sw.bin && ok ||
      bad "resume from iteration $k (switch at $S) differs from the uninterrupted run"
  done
else
  bad "no switch to exact solves in the trace (S='$S')"
fi

# SIGTERM (a batch scheduler's warning) while a checkpoint is written: the
# first fsync (the first checkpoint's commit) raises it. With --checkpoint
# the run finishes that checkpoint, writes one more at the next iteration
# boundary and exits 3 with no output and no temporary; --resume then gives
# the uninterrupted run's bytes. Without --checkpoint the signal ends the
# run (143) while its output is committed, and nothing is left.
if [ -f "$B/tests/libsigterm_fsync.so" ]; then
  LD_PRELOAD="$B/tests/libsigterm_fsync.so" "$CFPO" -q -n $N --max-iter 5 --checkpoint sig.ck \
    --checkpoint-every 1 -o sig.bin >/dev/null 2>sig.err
  rc=$?
  [ $rc -eq 3 ] && ok || bad "SIGTERM during a checkpoint: exit $rc, expected 3 ($(cat sig.err))"
  grep -q "stopped by a signal at iteration [0-9]*; checkpoint sig.ck written" sig.err && ok ||
    bad "SIGTERM: the message does not say where the run stopped: $(cat sig.err)"
  ls -A | grep '^sig\.' | grep -qv -e '^sig\.ck$' -e '^sig\.err$' && bad "SIGTERM left: $(ls -A | grep '^sig\.')" || ok
  "$CFPO" -q -n $N --max-iter 5 -o ref5.bin >/dev/null || bad "reference run to 5"
  "$CFPO" -q --max-iter 5 --resume sig.ck -o sigr.bin >/dev/null && cmp -s sigr.bin ref5.bin && ok ||
    bad "resume after SIGTERM: not the uninterrupted bytes"
  LD_PRELOAD="$B/tests/libsigterm_fsync.so" "$CFPO" -q -n $N --max-iter 2 -o sig2.bin >/dev/null 2>&1
  rc=$?
  [ $rc -eq 143 ] && ok || bad "SIGTERM during the output's commit: exit $rc, expected 143"
  ls -A | grep -q '^sig2\.' && bad "SIGTERM during the output's commit left: $(ls -A | grep '^sig2\.')" || ok
else
  bad "tests/libsigterm_fsync.so not built"
fi

# SIGUSR1 from outside mid-run, as a scheduler sends it: the same (exit 3,
# a checkpoint, no output; the resume gives the uninterrupted bytes). The
# run is long (no limit, 2^16 points); the signal comes after 1 s. A
# kill -9 during a run leaves no file beside the output (nothing is opened
# before the end).
"$CFPO" -q -n 65536 -t 1 --checkpoint usr.ck --checkpoint-every 1000 -o usr.bin >/dev/null 2>usr.err &
pid=$!
sleep 1
kill -USR1 $pid
wait $pid
rc=$?
[ $rc -eq 3 ] && [ -f usr.ck ] && [ ! -e usr.bin ] && ok ||
  bad "SIGUSR1: exit $rc (expected 3), checkpoint $(ls usr.ck 2>&1), output $(ls usr.bin 2>&1): $(cat usr.err)"
it=$(sed -n 's/.*at iteration \([0-9]*\);.*/\1/p' usr.err)
if [ -n "$it" ]; then
  "$CFPO" -q -n 65536 -t 1 --max-iter $((it + 2)) -o usr-ref.bin >/dev/null || bad "reference run"
  "$CFPO" -q -t 2 --max-iter $((it + 2)) --resume usr.ck -o usr-res.bin >/dev/null && cmp -s usr-res.bin usr-ref.bin && ok ||
    bad "resume after SIGUSR1 at iteration $it: not the uninterrupted bytes"
else
  bad "SIGUSR1: no iteration in the message: $(cat usr.err)"
fi
"$CFPO" -q -n 65536 -t 1 --trace k9.tsv -o k9.bin >/dev/null 2>&1 &
pid=$!
sleep 1
kill -9 $pid
wait $pid 2>/dev/null
ls -A | grep -q '^k9\.' && bad "kill -9 during a run left: $(ls -A | grep '^k9\.')" || ok
rm -f usr.* usr-* k9.* sig*.* ref5.bin

# The hyperuniform variant's schedule steps by iteration too (its stage from
# 29: transport sweeps, near sweeps at 41, 46, ..., 71; the end at 75): a resume before the
# stage, inside its first transport block and just before a near sweep of
# it ends in the uninterrupted run's bytes.
"$CFPO" -q -n $N -t 2 --variant hyperuniform -o hu.bin >/dev/null || bad "hyperuniform run"
for k in 28 33 40; do
  "$CFPO" -q -n $N -t 2 --variant hyperuniform --max-iter $k --checkpoint hu$k.ck --checkpoint-every $k \
    >/dev/null || bad "hyperuniform run to $k"
  "$CFPO" -q -t 1 --resume hu$k.ck -o hu$k.bin >/dev/null && cmp -s hu$k.bin hu.bin && ok ||
    bad "hyperuniform: resume from iteration $k differs from the uninterrupted run"
done
# Its last checkpoint (converged, after the near sweeps of its stage) reads back.
"$CFPO" -q -n $N -t 2 --variant hyperuniform --checkpoint hu75.ck --checkpoint-every 75 >/dev/null ||
  bad "hyperuniform run to its end"
"$CFPO" -q -t 1 --resume hu75.ck -o hu75.bin >/dev/null && cmp -s hu75.bin hu.bin && ok ||
  bad "hyperuniform: its converged checkpoint does not resume to its points"

echo "$pass passed, $fail failed"
[ $fail -eq 0 ]
