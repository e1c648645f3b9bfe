#!/usr/bin/env bash
# test_d3_cli.sh BUILD_DIR - the cfpo3d and cfpo3d-analyze commands: bad
# input refused in one line with exit 2 (usage) or 1 (runtime) and no file
# left; the same bytes for 1, 2 and 3 threads; a resume from a checkpoint
# the bytes of the uninterrupted run; --init from the command's own output;
# every output format written, the box scaling of the XYZ and LAMMPS files;
# the stop rules and the SUMMARY line; cfpo3d-analyze on a run's output.
set -u
B=$(cd "$1" && pwd)
CFPO="$B/cfpo3d"
AN="$B/cfpo3d-analyze"
T=$(mktemp -d /tmp/cfpo3d-cli-XXXXXX)
trap 'rm -rf "$T"' EXIT
cd "$T" || exit 1
. "$(dirname "$0")/../cli_expect.sh"

# bad input: usage errors (2)
expect 2 "too small" -n 38 -o a.npy
expect 2 "positive whole number" -n 0 -o a.npy
expect 2 "unknown output format" -n 100 -o a.png
expect 2 "box" -n 100 --box 0 -o a.xyz
expect 2 "box" -n 100 --box nan -o a.xyz
expect 2 "box" -n 100 --box -1 -o a.xyz
expect 2 "tol" -n 100 --tol 0 -o a.npy
expect 2 "threads" -n 100 -t 0 -o a.npy
expect 2 "unrecognized\|unknown" -n 100 --dim 4 -o a.npy
expect 2 "needs a value" -n 100 -o
expect 2 "required" -o a.npy
expect 2 "exclude" -n 100 --init x.npy --resume y.bin
expect 2 "checkpoint-every needs" -n 100 --checkpoint-every 3
expect 2 "target" -n 100 --target-min 0 -o a.npy
expect 2 "flat must be" -n 100 --flat -1 -o a.npy
expect 2 "flat-gain" -n 100 --flat 5 --flat-gain 0 -o a.npy
expect 2 "flat-gain" -n 100 --flat 5 --flat-gain nan -o a.npy
expect 2 "shake must be" -n 100 --shake -1 -o a.npy
expect 2 "shake-amp" -n 100 --shake 1 --shake-amp 0 -o a.npy
expect 2 "schedule from the checkpoint" --resume c.bin --shake 1 -o a.npy
expect 2 "schedule from the checkpoint" --resume c.bin --flat 5 -o a.npy
# runtime failures (1)
expect 1 "cannot open" --init missing.npy -o a.npy
printf '0.1 0.2\n' >bad.txt
expect 1 "expected three numbers" --init bad.txt -o a.npy
rm -f bad.txt
expect 1 "cannot open checkpoint" --resume missing.bin -o a.npy
mkdir folder.npy
expect 1 "read error (is it a folder?)" --init folder.npy -o a.npy
expect 1 "folder.npy: read error" --resume folder.npy -o a.npy
rmdir folder.npy
expect 1 "cannot create" -n 100 -o nofolder/a.npy
{ printf 'CFPO3DCK\x09\x00\x00\x00\x40\x00\x00\x00'; head -c 48 /dev/zero; } >bad.bin
expect 1 "version" --resume bad.bin -o a.npy
rm -f bad.bin

# the same bytes for 1, 2, 3 threads
for t in 1 2 3; do "$CFPO" -q -n 324 --max-iter 6 -t $t -o t$t.npy >s$t.log || bad "run with $t threads"; done
cmp -s t1.npy t2.npy && cmp -s t1.npy t3.npy && ok || bad "threads 1, 2, 3 give different bytes"
grep -q "^SUMMARY method=cfpo3d variant=adaptive n=324 .* iterations=6 .*stop=max-iter" s1.log && ok ||
  bad "SUMMARY line: $(cat s1.log)"
grep -q "^BOX3D side=1 delta_min_box=.* packing_fraction=" s1.log && ok || bad "BOX3D line"

# resume: 3 + 3 iterations, and 4 + 2 (a grid shift at 5)
for k in 3 4; do
  "$CFPO" -q -n 324 --max-iter $k --checkpoint ck$k.bin >/dev/null || bad "checkpointed run"
  "$CFPO" -q --max-iter 6 --resume ck$k.bin -t 3 -o r$k.npy >/dev/null || bad "resume"
  cmp -s r$k.npy t1.npy && ok || bad "resume after $k iterations differs"
done
# the one run loop's signals: SIGUSR1 (a batch scheduler's warning) with
# --checkpoint ends the run at the next iteration boundary, the checkpoint
# written, no output, exit 3; the resume gives the uninterrupted bytes
"$CFPO" -q -n 20000 -t 1 --checkpoint sig.bin --checkpoint-every 1000 -o sig.npy >/dev/null 2>sig.err &
pid=$!
sleep 2
kill -USR1 $pid
wait $pid
rc=$?
it=$(sed -n 's/.*stopped by a signal at iteration \([0-9]*\);.*/\1/p' sig.err)
[ $rc -eq 3 ] && [ -n "$it" ] && [ -f sig.bin ] && [ ! -e sig.npy ] && ok ||
  bad "SIGUSR1: exit $rc, iteration '$it': $(cat sig.err)"
if [ -n "$it" ]; then
  "$CFPO" -q --max-iter $((it + 1)) --resume sig.bin -t 2 -o sigr.npy >/dev/null
  "$CFPO" -q -n 20000 --max-iter $((it + 1)) -t 2 -o sigu.npy >/dev/null
  cmp -s sigr.npy sigu.npy && ok || bad "resume after SIGUSR1 at $it differs from the uninterrupted run"
fi
rm -f sig.bin sig.err sigr.npy sigu.npy
expect 2 "resume takes" --resume ck3.bin --seed 4 -o a.npy
expect 2 "disagrees" -n 601 --resume ck3.bin -o a.npy
# a flipped byte in the points
cp ck3.bin flip.bin
printf '\x01' | dd of=flip.bin bs=1 seek=100 conv=notrunc status=none
expect 1 "checksum" --resume flip.bin -o a.npy
rm -f flip.bin

# every format, the box scaling; --init from the text output
"$CFPO" -q -n 200 --max-iter 3 --box 2.5 -o o.npy -o o.txt -o o.csv -o o.raw -o o.xyz -o o.data >/dev/null ||
  bad "multi-format run"
[ "$(head -1 o.xyz)" = 200 ] && sed -n 2p o.xyz | grep -q 'Lattice="2.5 0 0 0 2.5 0 0 0 2.5"' && ok || bad "xyz header"
grep -q "^0 2.5 zlo zhi" o.data && grep -q "^200 atoms" o.data && ok || bad "LAMMPS header"
# x in the xyz file is 2.5 x in the text file
paste -d' ' o.txt <(tail -n +3 o.xyz) | awk '{ if ($5 != 2.5 * $1 && ($5 - 2.5 * $1 > 1e-15 || 2.5 * $1 - $5 > 1e-15)) bad++ } END { exit bad > 0 }' &&
  ok || bad "xyz coordinates are not 2.5 times the text file's"
[ "$(ls -A | grep -c tmp)" = 0 ] && ok || bad "temporaries left"
"$CFPO" -q --init o.txt --max-iter 0 -o i.npy >/dev/null && cmp -s i.npy o.npy && ok || bad "--init o.txt --max-iter 0 does not give o.npy"
"$CFPO" -q --init o.csv --max-iter 2 -o i2.npy >/dev/null && ok || bad "--init from CSV"
"$CFPO" -q --init o.raw -n 200 --max-iter 1 -o i3.npy >/dev/null && ok || bad "--init from raw"
expect 2 "disagrees" --init o.npy -n 300 -o a.npy
# a clustered start: 200 points in one cell
awk 'BEGIN { srand(5); for (i = 0; i < 200; i++) printf "%.17g %.17g %.17g\n", 0.01 * rand(), 0.01 * rand(), 0.01 * rand() }' >clus.txt
expect 1 "holds 200 of the given points (at most 64)" --init clus.txt -o a.npy
rm -f clus.txt

# stop rules
"$CFPO" -q -n 324 --target-min 0.85 -o g.npy >g.log && grep -q "stop=target" g.log &&
  awk '/^SUMMARY/ { for (i = 1; i <= NF; i++) if ($i ~ /^delta_min=/) { split($i, a, "="); exit !(a[2] >= 0.85) } }' g.log &&
  ok || bad "--target-min: $(cat g.log)"
"$CFPO" -q -n 324 --time-limit 0.001 >tl.log && grep -q "stop=time" tl.log && ok || bad "--time-limit"
"$CFPO" -q -n 100 --tol 0.4 >cv.log && grep -q "converged=yes.*stop=converged" cv.log && ok || bad "convergence: $(cat cv.log)"
"$CFPO" --dry-run -n 65536 | grep -q "grid=33^3" && ok || bad "--dry-run"

# the flatness rule: with a gain no iteration reaches it stops after
# exactly W iterations (the bytes of --max-iter W); with a gain every early
# iteration passes it runs to the cap
"$CFPO" -q -n 324 -t 1 --flat 4 --flat-gain 1 --shake 0 -o fl.npy >fl.log && grep -q "iterations=4 .*stop=flat" fl.log &&
  "$CFPO" -q -n 324 -t 1 --max-iter 4 -o fl4.npy >/dev/null && cmp -s fl.npy fl4.npy && ok || bad "--flat: $(cat fl.log)"
"$CFPO" -q -n 324 -t 1 --flat 2 --flat-gain 1e-9 --shake 0 --max-iter 5 >fl2.log && grep -q "iterations=5 .*stop=max-iter" fl2.log &&
  ok || bad "--flat, small gain: $(cat fl2.log)"

# --shake: the same bytes for 1 and 2 threads; the best set is kept, so
# delta_min is at least the unshaken run's (its first round), and the
# SHAKE3D line names the round written (rounds of exactly 3 iterations:
# --flat 3 with a gain no iteration reaches)
for t in 1 2; do "$CFPO" -q -n 324 -t $t --flat 3 --flat-gain 1 --shake 2 -o sh$t.npy >sh$t.log || bad "--shake, $t threads"; done
cmp -s sh1.npy sh2.npy && ok || bad "--shake: threads 1 and 2 give different bytes"
"$CFPO" -q -n 324 -t 1 --max-iter 3 --shake 0 -o sh0.npy >sh0.log
d0=$(awk '/^SUMMARY/ { for (i = 1; i <= NF; i++) if ($i ~ /^delta_min=/) { split($i, a, "="); print a[2] } }' sh0.log)
ds=$(awk '/^SUMMARY/ { for (i = 1; i <= NF; i++) if ($i ~ /^delta_min=/) { split($i, a, "="); print a[2] } }' sh1.log)
grep -q "^SHAKE3D rounds=2 amp=0.15 best_round=[0-2] flat=3 flat_gain=1$" sh1.log && grep -q "iterations=9 .*converged=yes" sh1.log &&
  awk -v a="$ds" -v b="$d0" 'BEGIN { exit !(a >= b) }' && ok || bad "--shake: $(cat sh1.log) against $d0"
if grep -q "best_round=0" sh1.log; then cmp -s sh1.npy sh0.npy && ok || bad "--shake: round 0 kept but not the unshaken bytes"; fi
# --max-iter counts every round: the schedule stops inside round 1
"$CFPO" -q -n 324 -t 1 --flat 3 --flat-gain 1 --shake 2 --max-iter 5 >shm.log &&
  grep -q "iterations=5 .*converged=no .*stop=max-iter" shm.log && grep -q "^SHAKE3D rounds=1 " shm.log && ok ||
  bad "--shake with --max-iter 5: $(cat shm.log)"

# the default schedule (flat window 20, 3 shakes) run whole, and resumed
# from checkpoints inside a round, at the last iteration of round 0 and
# of round 1 (where the round ended), and just after: every resume (on 2
# threads) gives the uninterrupted bytes; the trace's last column is the
# round
"$CFPO" -q -n 324 -t 1 --trace def.tsv -o def.npy >def.log || bad "default run"
grep -q "converged=yes" def.log && grep -q "^SHAKE3D rounds=3 amp=0.15 best_round=[0-3] flat=20 flat_gain=1e-05$" def.log &&
  ok || bad "default run: $(cat def.log)"
r0=$(awk '!/^#/ && $9 == 0' def.tsv | wc -l)
r1=$(awk '!/^#/ && $9 <= 1' def.tsv | wc -l)
for k in 7 $r0 $((r0 + 1)) $((r0 + 9)) $r1 $((r1 + 2)); do
  rm -f dck.bin
  "$CFPO" -q -n 324 -t 1 --max-iter $k --checkpoint dck.bin --checkpoint-every 4 >/dev/null || bad "checkpointed default run to $k"
  "$CFPO" -q --resume dck.bin -t 2 -o dres.npy >/dev/null && cmp -s dres.npy def.npy && ok ||
    bad "the default schedule resumed after $k iterations (rounds end at $r0, $r1) differs"
done
rm -f dck.bin

# the analysis of a run's output
"$AN" t1.npy >an.log && grep -q "^ANALYZE3D n=324 delta_min=.* q6_global=.* crystal_like=" an.log && ok || bad "analyze"
d1=$(awk '/^SUMMARY/ { for (i = 1; i <= NF; i++) if ($i ~ /^delta_min=/) { split($i, a, "="); print a[2] } }' s1.log)
d2=$(awk '{ for (i = 1; i <= NF; i++) if ($i ~ /^delta_min=/) { split($i, a, "="); print a[2] } }' an.log)
[ "$d1" = "$d2" ] && ok || bad "analyze delta_min $d2, run $d1"
# the spike check on the default schedule's set (a clean set: passes)
"$AN" --spike def.npy >sp.log && grep -q " spike=.* spike_noise=.* spike_pass=yes$" sp.log && ok || bad "spike: $(cat sp.log)"
CFPO="$AN"
expect 2 "one input file" 
expect 1 "cannot open" missing.npy

echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]
