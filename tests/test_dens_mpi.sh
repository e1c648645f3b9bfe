#!/usr/bin/env bash
# test_dens_mpi.sh BUILD_DIR MPIRUN - `cfpo --density` under mpirun: the
# same bytes (output and trace statistics) as one process for P = 2, 3, 4
# ranks and 1 or 2 threads on cos, the ramps 1:16 and 1:256, Balzer's field
# and the shipped image (each on levels of finer cells, dens_levels.h);
# each rank's points within 20% of n / P (the cut balances points);
# checkpoint on one rank count, resume and --init on others, the same
# bytes; a rank count too large for the grid refused once, no file left;
# a run without a trace (the lazy measure) the same bytes and deltas.
set -u
HERE=$(cd "$(dirname "$0")" && pwd)
IMG="$HERE/../data/astronaut-256.png"
. "$HERE/mpi_common.sh" "$1" "$2" cfpo-dmpi

# name, SPEC, n, iterations: the image needs 32,768 points for a grid of
# 9 x 9 cells (up to 9 ranks)
# image and the ramp 1:256 take levels of finer cells (dens_levels.h)
cases=("cos cos:a=0.9 16384 4" "ramp ramp:contrast=16 16384 4" "balzer balzer 16384 4" "img $IMG 32768 3"
       "ramp256 ramp:contrast=256 16384 5")
for cs in "${cases[@]}"; do
  set -- $cs
  name=$1 spec=$2 n=$3 it=$4
  "$CFPO" -q -n "$n" --density "$spec" --max-iter "$it" -t 2 -o "$name.npy" --trace "$name.tsv" >/dev/null ||
    bad "$name: one-process reference failed"
  for pt in "2 1" "3 1" "4 1" "2 2"; do
    set -- $pt
    rm -f out.npy
    if run "$1" -n "$n" --density "$spec" --max-iter "$it" -t "$2" -o out.npy --trace out.tsv >run.out 2>run.err; then
      cmp -s out.npy "$name.npy" && ok || bad "$name on $1 ranks x $2 threads: output differs from one process"
      cmp -s <(cut -f1-6 out.tsv) <(cut -f1-6 "$name.tsv") && ok || bad "$name on $1 ranks: trace statistics differ"
      grep -q "ranks=$1 " run.out && ok || bad "$name on $1 ranks: the summary does not say ranks=$1"
      # every rank's points within 20% of n / P (the test densities; the
      # image too at this n)
      pts=$(grep -o 'RANKS ranks=[0-9]* points=[0-9,]*' run.out | sed 's/.*points=//')
      if [ -n "$pts" ] && echo "$pts" | tr , '\n' |
        awk -v n="$n" -v p="$1" '{ c++; if ($1 < 0.8 * n / p || $1 > 1.2 * n / p) e = 1 } END { exit e || c != p }'; then ok
      else bad "$name on $1 ranks: points per rank '$pts', not within 20% of $n / $1"; fi
    else
      bad "$name on $1 ranks x $2 threads: run failed: $(head -3 run.err)"
    fi
  done
done

# Without a trace the engine measures only at the stop rule's windows and
# where the run stops (cfpo_types.h, lazy_measure): on 3 ranks, 18
# iterations of the ramp 1:256 (measured at 0, 16 and 18), the bytes and
# the summary's deltas of one process with a trace.
keep='s/.*\( iterations=[0-9]*\).*\( delta_min=[^ ]* delta_avg=[^ ]*\).*/\1\2/p'
"$CFPO" -q -n 16384 --density ramp:contrast=256 --max-iter 18 -t 2 -o lz1.npy --trace lz1.tsv >lz1.out ||
  bad "lazy measure: one-process reference failed"
if run 3 -n 16384 --density ramp:contrast=256 --max-iter 18 -t 1 -o lz3.npy >lz3.out 2>run.err; then
  cmp -s lz1.npy lz3.npy && [ -n "$(sed -n "$keep" lz1.out)" ] &&
    [ "$(sed -n "$keep" lz1.out)" = "$(sed -n "$keep" lz3.out)" ] && ok ||
    bad "lazy measure on 3 ranks: $(sed -n "$keep" lz3.out) against one process's $(sed -n "$keep" lz1.out)"
else
  bad "lazy measure on 3 ranks: run failed: $(head -3 run.err)"
fi

# Checkpoint on 2 ranks after 2 of cos's 4 iterations; resume on 3, 4
# and 1: the bytes of the uninterrupted run. The checkpoint's bytes equal
# one process's. --init on 4 ranks against one process.
run 2 -n 16384 --density cos:a=0.9 --max-iter 2 -t 1 --checkpoint ck.bin --checkpoint-every 2 -o h.npy >/dev/null 2>ck.err ||
  bad "checkpointed run on 2 ranks failed: $(head -3 ck.err)"
"$CFPO" -q -n 16384 --density cos:a=0.9 --max-iter 2 -t 1 --checkpoint ck1.bin -o h1.npy >/dev/null
cmp -s ck.bin ck1.bin && ok || bad "the checkpoint written on 2 ranks differs from one process's"
ls ck.bin.tmp* >/dev/null 2>&1 && bad "a temporary checkpoint was left behind" || ok
for p in 1 3 4; do
  rm -f res.npy
  if [ $p = 1 ]; then "$CFPO" -q -t 1 --density cos:a=0.9 --resume ck.bin --max-iter 4 -o res.npy >/dev/null 2>res.err
  else run $p -t 1 --density cos:a=0.9 --resume ck.bin --max-iter 4 -o res.npy >/dev/null 2>res.err; fi
  cmp -s res.npy cos.npy && ok || bad "resume on $p ranks: not the uninterrupted bytes ($(head -2 res.err))"
done
# (cos's points under Balzer's field: some nearest neighbours in the measure
# lie beyond a rank's halo, so the measure falls back to the whole set)
"$CFPO" -q -t 1 --density balzer --init cos.npy --max-iter 2 -o i1.npy --trace i1.tsv >/dev/null
run 4 -t 2 --density balzer --init cos.npy --max-iter 2 -o i4.npy --trace i4.tsv >/dev/null 2>i.err
cmp -s <(cut -f1-6 i1.tsv) <(cut -f1-6 i4.tsv) && ok || bad "--init on 4 ranks: trace statistics differ"
cmp -s i1.npy i4.npy && ok || bad "--init on 4 ranks differs from one process ($(head -2 i.err))"
# the one output writer: .npy and raw through MPI-IO (above); text needs
# one rank, as without a density
expect_err 2 "text output needs one rank" 2 -n 16384 --density cos:a=0.9 --max-iter 4 -t 1 -o out.txt

# A batch scheduler's SIGUSR1 to mpirun (forwarded to the ranks): every
# rank stops at the same iteration boundary, the checkpoint is written, the
# job exits 3 with no output; a resume on 3 ranks gives the uninterrupted
# bytes (a one-process run to the same iteration). 262,144 points: the run
# to its own stop takes about 13 s on two cores, so the signal after 3 s
# finds it running (65,536 points ended in 3.2 s, before the signal).
"$MPIRUN" --oversubscribe -np 2 "$CFPO" -q -n 262144 -t 1 --density cos:a=0.9 --checkpoint sig.ck \
  --checkpoint-every 1000 -o sig.npy >sig.out 2>sig.err &
pid=$!
watchdog $pid 120 "--checkpoint sig.ck"
sleep 3
kill -USR1 $pid
wait $pid
rc=$?
unwatch
[ $rc -eq 137 ] && bad "SIGUSR1 under mpirun: still running after 120 s (killed)"
it=$(sed -n 's/.*stopped by a signal at iteration \([0-9]*\);.*/\1/p' sig.err | head -1)
[ $rc -eq 3 ] && [ -n "$it" ] && [ -f sig.ck ] && [ ! -e sig.npy ] && ok ||
  bad "SIGUSR1 under mpirun: exit $rc, iteration '$it', checkpoint $(ls sig.ck 2>&1): $(grep cfpo: sig.err | head -2)"
if [ -n "$it" ]; then
  run 3 -t 1 --density cos:a=0.9 --resume sig.ck --max-iter $((it + 2)) -o sigr.npy >/dev/null 2>&1
  "$CFPO" -q -t 2 -n 262144 --density cos:a=0.9 --max-iter $((it + 2)) -o sigu.npy >/dev/null
  cmp -s sigr.npy sigu.npy && ok || bad "resume on 3 ranks after SIGUSR1 at $it: not the uninterrupted bytes"
fi
rm -f sig.*  sigr.npy sigu.npy

# Errors: one message for the whole job, every rank exits 2 (or 1), no file.
# 8,192 points on the image: a grid of 3 x 3 cells, one rank at most;
# 16,384 on cos: 30 x 30 cells, 100 ranks at most
expect_err 2 "grid has 3 x 3 cells, enough for at most 1 rank (this run has 2)" 2 -n 8192 --density "$IMG" -o x.npy
expect_err 1 "made with another density" 2 --density cos:a=0.8 --resume ck.bin -o x.npy
expect_err 2 "made with a density" 3 --resume ck.bin -o x.npy

echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]
