#!/usr/bin/env bash
# test_d3_mpi.sh BUILD_DIR MPIRUN - `cfpo --dim 3` under mpirun (one brick
# of the grid per rank): the same bytes (output in .npy, extended XYZ and
# LAMMPS, and the trace's statistics) as one process for 2, 3, 4 and 27
# ranks and 1 or 2 threads, across two grid shifts (migrations); the same
# from an --init set whose voids send the measure to the whole set; a
# checkpoint written on 3 ranks equals one process's, and resumes on 1, 2
# and 4 ranks give the uninterrupted bytes; SIGUSR1 to mpirun: exit 3, a
# checkpoint, no output, and a resume on 3 ranks gives the uninterrupted
# bytes; more ranks than the grid's bricks allow: one line, exit 2, no
# file; cfpo3d under mpirun too; --dry-run prints the memory a rank; the
# schedule of shaken rounds on 2 ranks, its checkpoint and a resume on 3.
set -u
HERE=$(cd "$(dirname "$0")/.." && pwd)
. "$HERE/mpi_common.sh" "$1" "$2" cfpo-d3mpi

# n = 1100: a 9^3 grid (3 slabs of 3 cells a side: up to 27 ranks);
# iterations 1 and 5 shift the grid, so points migrate twice
N=1100 IT=5
"$CFPO" -q --dim 3 -n $N --max-iter $IT -t 1 -o ref.npy -o ref.xyz -o ref.lmp --trace ref.tsv >/dev/null ||
  bad "one-process reference failed"
for pt in "2 1" "3 1" "4 1" "2 2" "27 1"; do
  set -- $pt
  rm -f out.npy out.xyz out.lmp out.tsv
  if run "$1" --dim 3 -n $N --max-iter $IT -t "$2" -o out.npy -o out.xyz -o out.lmp --trace out.tsv >run.out 2>run.err; then
    cmp -s out.npy ref.npy && ok || bad "$1 ranks x $2 threads: .npy differs from one process"
    cmp -s out.xyz ref.xyz && cmp -s out.lmp ref.lmp && ok || bad "$1 ranks x $2 threads: .xyz or LAMMPS file differs"
    cmp -s <(cut -d' ' -f1-6 out.tsv) <(cut -d' ' -f1-6 ref.tsv) && ok || bad "$1 ranks: trace statistics differ"
    grep -q "^SUMMARY .* ranks=$1 " run.out && ok || bad "$1 ranks: the summary does not say ranks=$1"
    # the RANKS line: P counts of points that add up to n, and the timers
    pts=$(sed -n 's/^RANKS ranks=[0-9]* bricks=[0-9x]* points=\([0-9,]*\) phases=.*compute_s=.*halo_s=.*/\1/p' run.out)
    [ -n "$pts" ] && [ "$(echo "$pts" | tr , '\n' | awk '{ s += $1; c++ } END { print c, s }')" = "$1 $N" ] && ok ||
      bad "$1 ranks: RANKS line '$(grep RANKS run.out)'"
  else
    bad "$1 ranks x $2 threads: run failed: $(head -3 run.err)"
  fi
done

# the schedule (rounds of exactly 2 iterations: --flat 2 with a gain no
# iteration reaches; 2 shakes): the gathered best set, the shaken set and
# the fresh engine of each round give one process's bytes on 2 ranks; a
# checkpoint inside round 1 (iteration 3) written on 2 ranks is one
# process's, and its resume on 3 ranks gives the uninterrupted bytes
SH="--flat 2 --flat-gain 1 --shake 2"
"$CFPO" -q --dim 3 -n $N $SH -t 1 -o sref.npy >/dev/null || bad "--shake reference failed"
if run 2 --dim 3 -n $N $SH -t 1 -o sout.npy >run.out 2>run.err; then
  cmp -s sout.npy sref.npy && ok || bad "--shake: 2 ranks differ from one process"
else
  bad "--shake on 2 ranks failed: $(head -3 run.err)"
fi
run 2 --dim 3 -n $N $SH --max-iter 3 -t 1 --checkpoint sck.bin >/dev/null 2>sck.err || bad "schedule checkpoint on 2 ranks: $(head -2 sck.err)"
"$CFPO" -q --dim 3 -n $N $SH --max-iter 3 -t 1 --checkpoint sck1.bin >/dev/null
cmp -s sck.bin sck1.bin && ok || bad "the schedule's checkpoint on 2 ranks differs from one process's"
run 3 --dim 3 -t 1 --resume sck.bin -o sres.npy >/dev/null 2>sres.err
cmp -s sres.npy sref.npy && ok || bad "the schedule resumed on 3 ranks: not the uninterrupted bytes ($(head -2 sres.err))"

# --init from a set with a void (1,000 points in half the box, 100 in the
# other half): nearest neighbours beyond a block, so the measure falls back
# to the whole set on every rank
awk 'BEGIN { srand(5); for (i = 0; i < 1100; i++) { x = rand(); x = i < 1000 ? x / 2 : 0.5 + x / 2;
  printf "%.17g %.17g %.17g\n", x, rand(), rand() } }' >void.txt
"$CFPO" -q --dim 3 --init void.txt --max-iter 2 -t 1 -o v1.npy --trace v1.tsv >/dev/null || bad "--init on one process failed"
run 4 --dim 3 --init void.txt --max-iter 2 -t 1 -o v4.npy --trace v4.tsv >/dev/null 2>v.err
cmp -s v1.npy v4.npy && ok || bad "--init on 4 ranks differs from one process ($(head -2 v.err))"
cmp -s <(cut -d' ' -f1-6 v1.tsv) <(cut -d' ' -f1-6 v4.tsv) && ok || bad "--init on 4 ranks: trace statistics differ"

# checkpoint on 3 ranks after 3 iterations; resume on 1, 2 and 4 ranks
run 3 --dim 3 -n $N --max-iter 3 -t 1 --checkpoint ck.bin >/dev/null 2>ck.err || bad "checkpointed run on 3 ranks: $(head -2 ck.err)"
"$CFPO" -q --dim 3 -n $N --max-iter 3 -t 1 --checkpoint ck1.bin >/dev/null
cmp -s ck.bin ck1.bin && ok || bad "the checkpoint written on 3 ranks differs from one process's"
ls ck.bin.tmp* >/dev/null 2>&1 && bad "a temporary checkpoint was left behind" || ok
for p in 1 2 4; do
  rm -f res.npy
  if [ $p = 1 ]; then "$CFPO" -q --dim 3 -t 1 --resume ck.bin --max-iter $IT -o res.npy >/dev/null 2>res.err
  else run $p --dim 3 -t 1 --resume ck.bin --max-iter $IT -o res.npy >/dev/null 2>res.err; fi
  cmp -s res.npy ref.npy && ok || bad "resume on $p ranks: not the uninterrupted bytes ($(head -2 res.err))"
done

# SIGUSR1 to mpirun (forwarded to the ranks): every rank stops at the same
# iteration boundary, one checkpoint, exit 3, no output. A tolerance no
# move falls below keeps the run going until the signal (the default run
# of N points can converge within the wait; so can the default schedule's
# flat rule, which --flat 0 --shake 0 turns off)
"$MPIRUN" --oversubscribe -np 2 "$CFPO" -q --dim 3 -n $N -t 1 --tol 1e-12 --flat 0 --shake 0 --checkpoint sig.ck --checkpoint-every 1000 \
  -o sig.npy >sig.out 2>sig.err &
pid=$!
sleep 3
kill -USR1 $pid
wait $pid
rc=$?
it=$(sed -n 's/.*stopped by a signal at iteration \([0-9]*\);.*/\1/p' sig.err | head -1)
[ $rc -eq 3 ] && [ -n "$it" ] && [ -f sig.ck ] && [ ! -e sig.npy ] && [ "$(grep -c '^cfpo:' sig.err)" = 1 ] && ok ||
  bad "SIGUSR1 under mpirun: exit $rc, iteration '$it', checkpoint $(ls sig.ck 2>&1): $(grep cfpo: sig.err | head -2)"
if [ -n "$it" ]; then
  run 3 --dim 3 -t 1 --resume sig.ck --max-iter $((it + 1)) -o sigr.npy >/dev/null 2>&1
  "$CFPO" -q --dim 3 -t 2 -n $N --tol 1e-12 --flat 0 --shake 0 --max-iter $((it + 1)) -o sigu.npy >/dev/null
  cmp -s sigr.npy sigu.npy && ok || bad "resume of the signalled run on 3 ranks: not the uninterrupted bytes"
fi

# too many ranks for the grid: 100 points make a 3^3 grid (one brick), and
# 5 ranks cannot cut a 9^3 grid (5 > 3 slabs a side and prime)
rm -f e.out e.err res.npy ref.* v1.* v4.* ck* sig* sigr.npy sigu.npy out.* run.* void.txt v.err
expect_err 2 "cannot cut the 3x3x3 grid" 2 --dim 3 -n 100 -o bad.npy
expect_err 2 "cannot cut the 9x9x9 grid" 5 --dim 3 -n $N -o bad.npy

# the cfpo3d command under mpirun: the same bytes
"$CFPO" -q --dim 3 -n $N --max-iter 2 -t 1 -o c1.npy >/dev/null
timeout 120 "$MPIRUN" --oversubscribe -np 2 "$B/cfpo3d" -q -n $N --max-iter 2 -t 1 -o c2.npy >c2.out 2>&1
cmp -s c1.npy c2.npy && grep -q "ranks=2 " c2.out && ok || bad "cfpo3d on 2 ranks: $(head -2 c2.out)"

# --dry-run under mpirun: the memory a rank for the ranks it runs on (every
# rank holds n-long arrays, so a rank of two holds no less than one
# process), and the process's own bytes
field() { sed -n "s/.* $1=\([0-9.]*\).*/\1/p" "$2"; }
"$CFPO" --dim 3 --dry-run -n 65536 >d1.out 2>&1
run 2 --dim 3 --dry-run -n 65536 >d2.out 2>&1
if grep -q " ranks=1 " d1.out && grep -q " ranks=2 " d2.out && [ "$(grep -c "dry run" d2.out)" = 1 ]; then
  awk -v a="$(field bytes_per_point d1.out)" -v b="$(field bytes_per_point_rank d1.out)" \
      -v c="$(field bytes_per_point_rank d2.out)" -v r="$(field rank_bytes d2.out)" -v p="$(field process_bytes d2.out)" \
      'BEGIN { exit !(a > 0 && a == b && c >= a && p > 0 && r > c * 65536) }' && ok ||
    bad "--dry-run memory a rank: $(cat d1.out d2.out)"
else
  bad "--dry-run under mpirun: $(cat d1.out d2.out)"
fi

echo "$pass passed, $fail failed"
[ $fail -eq 0 ]
