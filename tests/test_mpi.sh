#!/usr/bin/env bash
# test_mpi.sh BUILD_DIR MPIRUN - cfpo under mpirun: output byte-identical to
# the one-process file for any rank count and cut (1 x P, P x 1, uneven
# tiles; the hyperuniform variant too), invariants checked after every migration and halo refresh
# (--check: point count, id checksum, ownership, every halo cell equal to
# its owner's cell), checkpoint and resume on another rank count, a rank
# killed mid-run leaving a usable checkpoint, and errors reported once with
# every rank exiting non-zero; --progressive and --classes on 1-4 ranks
# (the one-process bytes, a resume on another rank count).
set -u
. "$(cd "$(dirname "$0")" && pwd)/mpi_common.sh" "$1" "$2" cfpo-mpi

# The reference: one process, no mpirun, 2 threads.
N=4096
"$CFPO" -n $N -q -t 2 -o ref.npy --trace ref.tsv >ref.out || bad "reference run failed"
"$CFPO" -n $N -q -t 1 --variant simplified -o refs.bin >/dev/null || bad "simplified reference failed"

same() { # same FILE REF WHAT
  if cmp -s "$1" "$2"; then ok; else bad "$3: output differs from the one-process run"; fi
}

# P = 1, 2, 3, 4, 6 with the chosen cut; 1 x P, P x 1 and uneven tiles
# (g = 57 for 4096 points: 57 / 2, 4 and 6 do not divide evenly).
for spec in "1 -" "2 -" "3 -" "4 -" "6 -" "4 1x4" "4 4x1" "6 2x3" "6 3x2" "6 6x1" "3 1x3"; do
  set -- $spec
  p=$1 tiles=()
  [ "$2" != "-" ] && tiles=(--tiles "$2")
  rm -f out.npy
  if run "$p" -n $N -t 1 "${tiles[@]}" -o out.npy --trace out.tsv >run.out 2>run.err; then
    same out.npy ref.npy "P=$p tiles=$2"
    # the statistics are reduced exactly: the trace matches but for timings
    if cmp -s <(cut -f1-6 out.tsv) <(cut -f1-6 ref.tsv); then ok; else bad "P=$p tiles=$2: trace statistics differ"; fi
    grep -q "ranks=$p " run.out && ok || bad "P=$p: summary does not say ranks=$p"
  else
    bad "P=$p tiles=$2: run failed: $(head -3 run.err)"
  fi
done

# Threads inside ranks, and the simplified variant, in raw format.
run 2 -n $N -t 2 -o out.npy >/dev/null 2>run.err && same out.npy ref.npy "2 ranks x 2 threads" || bad "2x2 run failed"
run 3 -n $N -t 1 --variant simplified -o outs.bin >/dev/null 2>run.err && same outs.bin refs.bin "simplified on 3 ranks" ||
  bad "simplified on 3 ranks failed: $(head -3 run.err)"

# The hyperuniform variant: its transport field from every rank's
# fixed-point NUFFT grid, summed exactly (src/solver/nufft.h): the same bytes.
"$CFPO" -n $N -q -t 2 --variant hyperuniform -o refh.npy >/dev/null || bad "hyperuniform reference failed"
for spec in "2 2x1" "3 1x3" "4 2x2 --check"; do
  set -- $spec
  if run "$1" -n $N -t 1 --tiles "$2" ${3:-} --variant hyperuniform -o outh.npy >/dev/null 2>run.err; then
    same outh.npy refh.npy "hyperuniform on $1 ranks, tiles $2 ${3:-}"
  else
    bad "hyperuniform on $1 ranks failed: $(head -3 run.err)"
  fi
done

# Above 65,536 points the hyperuniform variant takes the adaptive schedule
# and its brick colourings (policy.c) before its transport sweeps: 32
# iterations (bricks to 28, transport from 29), the same bytes on 2 and 3
# ranks, with --check on 3.
"$CFPO" -n 70000 -q -t 2 --variant hyperuniform --max-iter 32 -o refhb.npy >/dev/null || bad "hyperuniform 70000 reference failed"
for spec in "2 1x2" "3 3x1 --check"; do
  set -- $spec
  if run "$1" -n 70000 -t 1 --tiles "$2" ${3:-} --variant hyperuniform --max-iter 32 -o outhb.npy >/dev/null 2>run.err; then
    same outhb.npy refhb.npy "hyperuniform, 70000 points, on $1 ranks, tiles $2 ${3:-}"
  else
    bad "hyperuniform, 70000 points, on $1 ranks failed: $(head -3 run.err)"
  fi
done

# --check: invariants after every migration and halo refresh; on a tiny
# grid (n = 100: 9 x 9 cells, tiles of 3 to 5 cells) and on 4096 points.
for spec in "4 100 2x2" "3 100 3x1" "3 100 1x3" "6 4096 3x2"; do
  set -- $spec
  if run "$1" -n "$2" -t 1 --tiles "$3" --check --max-iter 40 -o chk.npy >/dev/null 2>chk.err; then
    if grep -Eq "check: [1-9][0-9]* migrations and [1-9][0-9]* halo refreshes verified" chk.err; then ok
    else bad "--check on $1 ranks n=$2: no verification reported: $(cat chk.err)"; fi
    "$CFPO" -n "$2" -q -t 1 --max-iter 40 -o chk1.npy >/dev/null
    same chk.npy chk1.npy "--check on $1 ranks n=$2 tiles $3"
  else
    bad "--check on $1 ranks n=$2 tiles $3 failed: $(head -3 chk.err)"
  fi
done

# Checkpoint then resume, also on another rank count: the same final bytes.
run 2 -n $N -t 1 --max-iter 60 --checkpoint ck.bin --checkpoint-every 25 -o part.npy >/dev/null 2>ck.err ||
  bad "checkpointed run failed: $(head -3 ck.err)"
[ -f ck.bin ] && ok || bad "no checkpoint written"
ls ck.bin.tmp.* >/dev/null 2>&1 && bad "a temporary checkpoint was left behind" || ok
for p in 1 3 4; do
  rm -f res.npy
  if [ $p = 1 ]; then "$CFPO" -q -t 1 --resume ck.bin -o res.npy >res.out 2>res.err
  else run $p -t 1 --resume ck.bin -o res.npy >res.out 2>res.err; fi
  same res.npy ref.npy "resume (from iteration 50) on $p ranks"
done
# The resumed run's iterations continue the count.
grep -q "iterations=$(grep -o 'iterations=[0-9]*' ref.out | cut -d= -f2) " res.out && ok ||
  bad "resumed run reports $(grep -o 'iterations=[0-9]*' res.out), reference $(grep -o 'iterations=[0-9]*' ref.out)"

# Stop rules on 1 and 3 ranks. Targets: the run stops at the first
# iteration of the reference trace where both hold, with the bytes of a run
# capped there (the same state). Time: it stops past the limit, before
# converging, and says so.
K=$(awk -F'\t' 'NR > 1 && $2 >= 0.9 && $3 >= 0.925 { print $1; exit }' ref.tsv)
if [ -n "$K" ] && [ "$K" -gt 1 ]; then
  "$CFPO" -n $N -q -t 1 --max-iter "$K" -o capped.npy >/dev/null
  for p in 1 3; do
    rm -f tg.npy
    if [ $p = 1 ]; then "$CFPO" -n $N -q -t 1 --target-min 0.9 --target-avg 0.925 -o tg.npy >tg.out 2>tg.err
    else run $p -n $N -t 1 --target-min 0.9 --target-avg 0.925 -o tg.npy >tg.out 2>tg.err; fi
    if grep -q "iterations=$K .*stop=target" tg.out; then ok; else bad "targets on $p ranks: expected stop=target at iteration $K: $(cat tg.out tg.err)"; fi
    same tg.npy capped.npy "targets on $p ranks"
  done
else
  bad "reference trace never reaches delta_min 0.9 and delta_avg 0.925"
fi
for p in 1 3; do
  rm -f tl.tsv
  if [ $p = 1 ]; then "$CFPO" -n 65536 -q -t 1 --time-limit 1 --trace tl.tsv -o tl.npy >tl.out 2>tl.err
  else run $p -n 65536 -t 1 --time-limit 1 --trace tl.tsv -o tl.npy >tl.out 2>tl.err; fi
  last=$(tail -n 1 tl.tsv 2>/dev/null | cut -f8)
  if grep -q "converged=no .*stop=time" tl.out && awk -v e="$last" 'BEGIN { exit !(e >= 1) }'; then ok
  else bad "--time-limit 1 on $p ranks: $(cat tl.out tl.err), last elapsed $last"; fi
done

# A rank killed mid-run: the job ends, the checkpoint under its final name
# is whole, and resuming it gives the uninterrupted result.
"$CFPO" -n 65536 -q -t 1 --max-iter 40 -o big_ref.npy >/dev/null
timeout 120 "$MPIRUN" --oversubscribe -np 2 "$CFPO" -q -n 65536 -t 1 --max-iter 40 --checkpoint kill.bin \
  --checkpoint-every 2 -o big.npy >/dev/null 2>kill.err &
job=$!
for _ in $(seq 600); do [ -f kill.bin ] && break; sleep 0.05; done
sleep 0.3
victim=$(pgrep -f -- "--checkpoint kill.bin" | while read -r p; do
  [ "$(cat /proc/$p/comm 2>/dev/null)" = cfpo ] && echo "$p"; done | tail -1)
if [ -n "$victim" ]; then
  kill -KILL "$victim"
  wait $job
  rc=$?
  [ $rc -ne 0 ] && ok || bad "killing a rank did not end the job with an error"
  [ -f big.npy ] && bad "output written although a rank died" || ok
  if "$CFPO" -q -t 1 --max-iter 40 --resume kill.bin -o big_res.npy >/dev/null 2>res.err; then
    same big_res.npy big_ref.npy "resume after a killed rank"
  else bad "checkpoint left by the killed job is unusable: $(cat res.err)"; fi
else
  wait $job
  bad "could not find a rank to kill (the run ended too soon?)"
fi

# Errors: one message for the whole job, every rank non-zero, no files.
expect_err 2 "unknown option" 3 -n $N --bogus
expect_err 2 "not a positive whole number" 2 -n abc
expect_err 2 "tiles too small" 5 -n 100 -o x.npy
expect_err 2 "use at most 9 ranks" 11 -n 100
expect_err 2 "does not give one tile" 2 -n $N --tiles 3x1
expect_err 2 "cannot cut the 6x6x6 grid" 3 --dim 3 -n 324 -o x.npy
expect_err 2 "text output needs one rank" 2 -n $N -o x.txt
# --progressive and --classes on 1-4 ranks: the one-process bytes (its
# default, --level-balance 16, and --level-balance 0, the classes by
# colouring and by levels, the joint move); the levels too small to cut
# across the ranks (64 points on 3 ranks) are solved by every rank alone.
# A checkpoint of a 2-rank progressive run resumes on 1 and 3 ranks to the
# same bytes.
for args in "--progressive" "--progressive --level-balance 0" "--classes 4" "--classes 4 --classes-levels" \
            "--progressive --joint 2"; do
  "$CFPO" -q -n 2048 -t 1 $args -o refp.npy >/dev/null || bad "$args: reference"
  for p in 1 2 3 4; do
    rm -f outp.npy
    run $p -n 2048 -t 1 $args -o outp.npy >run.out 2>run.err && same outp.npy refp.npy "$args on $p ranks" ||
      bad "$args on $p ranks failed: $(head -2 run.err)"
    [ "$(grep -c '^SUMMARY.* ranks='$p' ' run.out)" = 1 ] && ok || bad "$args on $p ranks: not one SUMMARY saying ranks=$p"
  done
done
"$CFPO" -q -n 8192 -t 1 --progressive -o refp.npy >/dev/null || bad "--progressive reference"
run 2 -n 8192 -t 1 --progressive --checkpoint ckp.bin --checkpoint-every 5 -o outp.npy >/dev/null 2>run.err &&
  same outp.npy refp.npy "--progressive on 2 ranks with checkpoints" || bad "--progressive --checkpoint on 2 ranks failed"
for p in 1 3; do
  rm -f outp.npy
  run $p -n 8192 -t 1 --progressive --resume ckp.bin -o outp.npy >/dev/null 2>run.err &&
    same outp.npy refp.npy "--progressive resumed on $p ranks" || bad "--progressive --resume on $p ranks failed"
done
# SIGUSR1 to mpirun during a 3-rank progressive run (early levels are
# solved by every rank alone): exit 3, one message, no output; the
# checkpoint resumes on 2 ranks to the one-process bytes
"$CFPO" -q -n 65536 -t 1 --progressive -o refp.npy >/dev/null || bad "--progressive reference (65,536)"
rm -f ckp.bin outp.npy
"$MPIRUN" --oversubscribe -np 3 "$CFPO" -q -n 65536 -t 1 --progressive --checkpoint ckp.bin \
  --checkpoint-every 1 -o outp.npy >sig.out 2>sig.err &
job=$! # mpirun itself (it forwards SIGUSR1 to the ranks; `timeout` would die of it)
watchdog $job 120 "--checkpoint ckp.bin"
for w in $(seq 100); do [ -e ckp.bin ] && break; sleep 0.1; done # the ranks are running: signal now
kill -USR1 $job 2>/dev/null
wait $job
rc=$?
unwatch
if [ $rc -eq 137 ]; then bad "--progressive signalled on 3 ranks: still running after 120 s (killed)"
elif [ $rc -eq 3 ]; then
  [ ! -e outp.npy ] && [ "$(grep -c 'stopped by a signal' sig.err)" = 1 ] && ok ||
    bad "--progressive signalled on 3 ranks: output left or not one message: $(grep -c 'stopped by a signal' sig.err)"
else
  echo "note: the 3-rank progressive run ended (exit $rc) before the signal; resuming from its last checkpoint"
fi
rm -f outp.npy
run 2 -n 65536 -t 1 --progressive --resume ckp.bin -o outp.npy >/dev/null 2>run.err &&
  same outp.npy refp.npy "--progressive signalled on 3 ranks, resumed on 2" || bad "--progressive resume on 2 ranks failed: $(head -2 run.err)"
# SIGUSR1 to one rank alone while the ranks work alone on the first
# level (64 points; 10,000 iterations there, about half a second): every
# rank stops at the same iteration (a rank that stopped by itself left the
# others waiting for it at the next level: a hang), exit 3, one message
# naming level 0, no output.
rm -f ckp1.bin outp.npy
"$MPIRUN" --oversubscribe -np 3 "$CFPO" -q -n 65536 -t 1 --progressive --level-iter 10000 --level-min 0.99 \
  --tol 1e-300 --checkpoint ckp1.bin --checkpoint-every 1000 -o outp.npy >sig.out 2>sig.err &
job=$!
watchdog $job 60 "--checkpoint ckp1.bin"
for w in $(seq 300); do [ -e ckp1.bin ] && break; sleep 0.02; done # iteration 1,000 of level 0
victim=$(pgrep -f -- "--checkpoint ckp1.bin" | while read -r p; do
  [ "$(cat /proc/$p/comm 2>/dev/null)" = cfpo ] && echo "$p"; done | sed -n 2p)
[ -n "$victim" ] && kill -USR1 "$victim"
wait $job
rc=$?
unwatch
if [ -z "$victim" ]; then bad "one rank signalled: no rank found to signal"
elif [ $rc -eq 137 ]; then bad "one rank signalled in the ranks' lone level: the job hung (killed after 60 s)"
elif [ $rc -ne 3 ]; then bad "one rank signalled in the ranks' lone level: exit $rc, not 3: $(head -3 sig.err)"
else
  [ ! -e outp.npy ] && [ "$(grep -c 'stopped by a signal at level 0 ' sig.err)" = 1 ] && [ -s ckp1.bin ] && ok ||
    bad "one rank signalled: output left, no checkpoint or not one message naming level 0: $(head -3 sig.err)"
fi
expect_err 2 "the checkpoint is for" 2 --resume ck.bin --seed 9
head -c 1000 ck.bin >trunc.bin
expect_err 1 "truncated" 2 --resume trunc.bin -o y.npy
expect_err 1 "cannot open" 2 --resume missing.bin
mkdir ro && chmod 555 ro
if [ "$(id -u)" = 0 ]; then : # root writes anywhere; use a missing folder instead
  expect_err 1 "cannot create" 2 -n $N -o nodir/x.npy
else
  expect_err 1 "cannot create" 2 -n $N -o ro/x.npy
fi

# --dry-run: arithmetic only, for any P.
if "$CFPO" -n 1e10 --dry-run --ranks 1024 >dry.out 2>dry.err; then
  grep -q "px=32 py=32" dry.out && ok || bad "dry run for 1024 ranks is not a 32x32 cut: $(cat dry.out)"
  bpr=$(grep -o 'bytes_per_rank=[0-9]*' dry.out | cut -d= -f2)
  ppr=$(grep -o 'points_per_rank=[0-9]*' dry.out | cut -d= -f2)
  awk -v b="$bpr" -v p="$ppr" 'BEGIN { exit !(p > 9.0e6 && p < 1.1e7 && b / p > 40 && b / p < 80) }' && ok ||
    bad "dry run: $ppr points and $bpr bytes per rank for 1e10 on 1024 ranks"
else
  bad "dry run failed: $(cat dry.err)"
fi

# --dry-run counts the hyperuniform variant's transport grids: the memory it
# adds over the adaptive variant's model is the extra a real run measures
# (peak resident sizes of both variants through the first transport sweep).
val() { grep -o " $1=[0-9]*" "$2" | cut -d= -f2; }
for v in adaptive hyperuniform; do
  "$CFPO" -n 262144 --variant $v --dry-run >dry-$v.out 2>&1 || bad "dry run of $v failed"
  "$CFPO" -n 262144 --variant $v --max-iter 42 -q -t 2 -o mem-$v.npy >mem-$v.out 2>&1 || bad "run of $v failed"
done
awk -v dm="$(( $(val bytes_per_rank dry-hyperuniform.out) - $(val bytes_per_rank dry-adaptive.out) ))" \
    -v dp="$(( $(val peak_bytes mem-hyperuniform.out) - $(val peak_bytes mem-adaptive.out) ))" \
    'BEGIN { exit !(dm > 0.8 * dp && dm < 1.25 * dp) }' && ok ||
  bad "dry run: the hyperuniform variant's extra memory is modelled as $(( $(val bytes_per_rank dry-hyperuniform.out) - $(val bytes_per_rank dry-adaptive.out) )) bytes, measured $(( $(val peak_bytes mem-hyperuniform.out) - $(val peak_bytes mem-adaptive.out) ))"

echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]
