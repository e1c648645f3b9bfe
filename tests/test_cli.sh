#!/usr/bin/env bash
# test_cli.sh BUILD_DIR - the cfpo command as a user meets it: exit codes,
# one-line messages, no file left behind on any failure, formats that carry
# the same points, byte-identical output for any thread count, the trace,
# the summary line, progress only on a terminal, clean interruption.
set -u
HERE=$(cd "$(dirname "$0")" && pwd)
B=$(cd "$1" && pwd)
CFPO="$B/cfpo"
T=$(mktemp -d /tmp/cfpo-cli-XXXXXX)
trap 'rm -rf "$T"' EXIT
cd "$T" || exit 1
. "$HERE/cli_expect.sh"

# --- usage errors: exit 2
expect 2 "required" -o x.npy
expect 2 "'abc' is not a positive whole number" -n abc -o x.npy
expect 2 "'12abc'" -n 12abc -o x.npy
expect 2 "'-5'" -n -5 -o x.npy
expect 2 "'0'" -n 0
expect 2 "too small" -n 10 -o x.npy
expect 2 "too small" -n 1 -o x.npy
expect 2 "too small" -n 2
expect 2 "too small" -n 18 --variant simplified
expect 2 "'1e6.5'" -n 1e6.5
expect 2 "--threads" -n 100 --threads 0
expect 2 "--threads" -n 100 --threads two
expect 2 "--tol" -n 100 --tol -1
expect 2 "--tol" -n 100 --tol nan
expect 2 "--tol" -n 100 --tol 0.6
expect 2 "--seed" -n 100 --seed -1
expect 2 "--seed" -n 100 --seed 1x
expect 2 "--max-iter" -n 100 --max-iter -3
expect 2 "--variant" -n 100 --variant fast
expect 2 "--target-min" -n 100 --target-min 2
expect 2 "--target-avg" -n 100 --target-avg abc
expect 2 "--time-limit" -n 100 --time-limit -1
expect 2 "--time-limit" -n 100 --time-limit 0
expect 2 "unknown option '--bogus'" -n 100 --bogus
expect 2 "unknown option '-z'" -n 100 -z
expect 2 "needs a value" -n 100 -o
expect 2 "unknown output format" -n 100 -o points.png
expect 2 "unknown output format" -n 100 -o points
expect 2 "unexpected argument" -n 100 extra
expect 2 "too large for one process" -n 2^33
# --- one number grammar: decimal only, no sign, no spaces, no hex/octal
expect 2 "'0x100'" -n 0x100
expect 2 "' 100'" -n ' 100'
expect 2 "'100 '" -n '100 '
expect 2 "'-2^4'" -n -2^4
expect 2 "'+100'" -n +100
expect 2 "'2^64'" -n 2^64
expect 2 "--seed" -n 100 --seed 0x10
expect 2 "--seed" -n 100 --seed ' 1'
expect 2 "--tol" -n 100 --tol ' 1e-4'
expect 2 "--tol" -n 100 --tol 0x1p-14
expect 2 "--tol" -n 100 --tol 1e-400
"$CFPO" -n 2.5e3 --dry-run 2>&1 | grep -q "n=2500 " && ok || bad "-n 2.5e3 is not 2500"
"$CFPO" -n 2^12 --dry-run 2>&1 | grep -q "n=4096 " && ok || bad "-n 2^12 is not 4096"
# seeds are decimal: 010 is ten (not octal eight), 08 is eight
"$CFPO" -n 100 -q --seed 010 -o s010.bin >/dev/null && "$CFPO" -n 100 -q --seed 10 -o s10.bin >/dev/null &&
  cmp -s s010.bin s10.bin && ok || bad "--seed 010 differs from --seed 10"
"$CFPO" -n 100 -q --seed 08 -o s08.bin >/dev/null && "$CFPO" -n 100 -q --seed 8 -o s8.bin >/dev/null &&
  cmp -s s08.bin s8.bin && ok || bad "--seed 08 differs from --seed 8"
rm -f s010.bin s10.bin s08.bin s8.bin
"$CFPO" -n 100 -q --tol 1e-320 --max-iter 2 >/dev/null 2>tol.log && ok || bad "--tol 1e-320 refused: $(cat tol.log)"
rm -f tol.log
# --- runtime failures: exit 1
expect 1 "No such file or directory" -n 100 -o nodir/x.npy
mkdir adir.npy
expect 1 "is a directory" -n 100 -o adir.npy
expect 1 "is a directory" -n 100 --trace adir.npy
rmdir adir.npy
expect 1 "too large for memory" -n 2^31

# --- the run's files: distinct, named, creatable before the work, all or nothing
expect 2 "^cfpo: -o: the file name is empty" -n 100 -o ''
expect 2 "^cfpo: --trace: the file name is empty" -n 100 --trace ''
expect 2 "^cfpo: -o f.tsv and --trace f.tsv are the same file" -n 100 --trace f.tsv -o f.tsv
expect 2 "^cfpo: -o c.bin and --checkpoint ./c.bin are the same file" -n 100 --checkpoint ./c.bin -o c.bin
mkdir sub && ln -s sub alias
expect 2 "are the same file" -n 100 --trace sub/t.tsv -o p.npy --checkpoint alias/t.tsv
rm -r alias sub
expect 2 "^cfpo: option '--no-skip' takes no value" -n 100 --no-skip=1
expect 1 "^cfpo: nodir/ck.bin: cannot create file" -n 100 --checkpoint nodir/ck.bin --max-iter 0
# a trace that cannot be written whole (file size limit; 400 rows, about 30 KB) replaces no output
echo old >keep.npy
(trap '' XFSZ; ulimit -f 8; "$CFPO" -n 300 -q --tol 1e-12 --max-iter 400 -o keep.npy --trace big.tsv) >/dev/null 2>xf.err
rc=$?
[ $rc -eq 1 ] && grep -q "big.tsv: write failed" xf.err && ok || bad "trace over the size limit: exit $rc, $(cat xf.err)"
[ "$(cat keep.npy)" = old ] && ok || bad "a failed trace replaced the output"
[ -z "$(ls -A | grep -e '\.tmp\.' -e '^big.tsv$')" ] && ok || bad "temporaries left: $(ls -A)"
rm -f keep.npy xf.err

# --- --init FILE: a start from another sampler's points
"$B/cfpo-dart" -n 1500 -q -o d.txt >/dev/null || bad "cfpo-dart failed"
expect 2 "^cfpo: --init d.txt: the file holds 1500 points, -n says 1000" --init d.txt -n 1000
expect 2 "^cfpo: --init does not go with --resume" --init d.txt --resume x.bin
expect 1 "^cfpo: --init nofile.npy: " --init nofile.npy
awk 'BEGIN { for (i = 0; i < 100; i++) printf "0.%04d 0.0005\n", 5 + i; for (i = 0; i < 400; i++) printf "%.6f %.6f\n", (i % 20 + 0.5) / 20, (int(i / 20) + 0.5) / 20 }' >clump.txt
expect 1 "^cfpo: cell (0, 0) of the .* grid holds more than 64 points" --init clump.txt -o clumped.npy
"$CFPO" --init d.txt -q -t 1 -o i1.npy --trace i1.tsv >i1.out 2>&1 && ok || bad "--init run failed: $(cat i1.out)"
"$CFPO" --init d.txt -q -t 2 -o i2.npy >/dev/null 2>&1 && cmp -s i1.npy i2.npy && ok || bad "--init: 1 and 2 threads differ"
grep -q " n=1500 " i1.out && ok || bad "--init: n does not come from the file: $(cat i1.out)"
# the start is the file's set (delta_min of iteration 0 is the dart set's, not
# cfpo's start), and delta_min never falls below it
d0=$(awk 'NR == 2 { print $2 }' i1.tsv)
awk -v d0="$d0" 'NR > 1 && $2 < d0 { bad = 1 } END { exit bad }' i1.tsv && ok || bad "--init: delta_min fell below the start's"
awk -v d0="$d0" 'BEGIN { exit !(d0 > 0.7 && d0 < 0.8) }' && ok || bad "--init: iteration 0 is not the dart set (delta_min $d0)"
rm -f d.txt clump.txt i1.npy i2.npy i1.tsv i1.out

# --- help and version
"$CFPO" --help >h.txt 2>&1 && grep -q "^Usage: cfpo" h.txt && grep -q -- "--trace" h.txt && ok || bad "--help"
"$CFPO" --version | grep -q "^cfpo [0-9]" && ok || bad "--version"

# --- success: formats, summary, trace
"$CFPO" -n 1000 --seed 7 -o p.bin --trace t.tsv >s.txt 2>e.txt && ok || bad "plain run failed: $(cat e.txt)"
[ ! -s e.txt ] && ok || bad "stderr not empty when not a terminal: $(cat e.txt)"
[ "$(wc -l <s.txt)" -eq 1 ] && grep -Eq '^SUMMARY method=cfpo variant=adaptive n=1000 seed=7 threads=[0-9]+ ranks=1 iterations=[0-9]+ seconds=[0-9.]+ delta_min=0\.9[0-9]+ delta_avg=0\.9[0-9]+ converged=yes peak_bytes=[0-9]+ bytes_per_point=[0-9.]+ stop=converged$' s.txt && ok || bad "summary line: $(cat s.txt)"
[ "$(stat -c %s p.bin)" -eq 16000 ] && ok || bad "p.bin has $(stat -c %s p.bin) bytes"
iters=$(sed -n 's/.* iterations=\([0-9]*\).*/\1/p' s.txt)
[ "$(head -1 t.tsv)" = "$(printf 'iteration\tdelta_min\tdelta_avg\tmoved\tsolved\tmax_disp\tseconds\telapsed\tmax_move\tnear')" ] && ok || bad "trace header: $(head -1 t.tsv)"
[ "$(($(wc -l <t.tsv) - 2))" -eq "$iters" ] && ok || bad "trace has $(wc -l <t.tsv) lines for $iters iterations"
"$CFPO" -n 1000 --seed 7 -o p.npy -q >/dev/null && ok || bad "npy run"
cmp -s <(tail -c 16000 p.npy) p.bin && [ "$(stat -c %s p.npy)" -eq 16128 ] && ok || bad ".npy data differs from .bin"
"$CFPO" -n 1000 --seed 7 -o p.txt -q >/dev/null && ok || bad "txt run"
python3 - p.txt p.bin <<'PY' && ok || bad ".txt values differ from .bin"
import struct, sys
txt = [float(v) for line in open(sys.argv[1]) for v in line.split()]
raw = open(sys.argv[2], 'rb').read()
binv = list(struct.unpack('<%dd' % (len(raw) // 8), raw))
sys.exit(0 if txt == binv else 1)
PY
ls -A | grep -q 'tmp\.' && bad "temporary files left: $(ls -A)" || ok

# --- determinism across thread counts and skipping, seeds differ
for t in 1 2 3 4; do "$CFPO" -n 3000 --seed 9 -t $t -q -o d$t.bin >/dev/null || bad "-t $t failed"; done
"$CFPO" -n 3000 --seed 9 -t 2 --no-skip -q -o dn.bin >/dev/null
cmp -s d1.bin d2.bin && cmp -s d1.bin d3.bin && cmp -s d1.bin d4.bin && ok || bad "thread counts give different bytes"
cmp -s d1.bin dn.bin && ok || bad "--no-skip gives different bytes"
# --- the AVX-512 or AVX2 solver (the widest the CPU has) and the narrower
# ones (CFPO_SOLVER=avx2, CFPO_SOLVER=plain) give the same bytes, every
# variant, 1 and 2 threads
routes="plain"
if [ "$(uname -m)" = x86_64 ] && grep -qw avx2 /proc/cpuinfo; then
  routes="plain avx2"
  if grep -qw avx512f /proc/cpuinfo && grep -qw avx512dq /proc/cpuinfo && grep -qw bmi2 /proc/cpuinfo; then
    "$CFPO" --version | grep -q "(LocalCFPO: avx512)" && ok || bad "AVX-512 CPU, but --version says: $("$CFPO" --version)"
  else
    "$CFPO" --version | grep -q "(LocalCFPO: avx2)" && ok || bad "AVX2 CPU, but --version says: $("$CFPO" --version)"
  fi
  CFPO_SOLVER=avx2 "$CFPO" --version | grep -q "(LocalCFPO: avx2)" && ok || bad "CFPO_SOLVER=avx2 not taken: $(CFPO_SOLVER=avx2 "$CFPO" --version)"
fi
# avx512 and auto allow every route: the default's choice
for r in avx512 auto; do
  [ "$(CFPO_SOLVER=$r "$CFPO" --version)" = "$("$CFPO" --version)" ] && ok || bad "CFPO_SOLVER=$r: $(CFPO_SOLVER=$r "$CFPO" --version)"
done
CFPO_SOLVER=plain "$CFPO" --version | grep -q "(LocalCFPO: plain)" && ok || bad "CFPO_SOLVER=plain not taken: $(CFPO_SOLVER=plain "$CFPO" --version)"
for v in adaptive paper simplified; do
  for t in 1 2; do
    "$CFPO" -n 3000 --seed 9 --variant $v -t $t -q -o r$v$t.bin >/dev/null
    for r in $routes; do
      CFPO_SOLVER=$r "$CFPO" -n 3000 --seed 9 --variant $v -t $t -q -o p$v$t$r.bin >/dev/null
      cmp -s r$v$t.bin p$v$t$r.bin && ok || bad "$v, $t threads: the $r solver gives other bytes"
    done
  done
done
# the density solve follows the same choice (src/density/dens_solve.c)
for t in 1 2; do
  "$CFPO" -n 3000 --seed 9 -t $t --max-iter 12 --density cos:a=0.9,kx=1,ky=0 -q -o rd$t.bin >/dev/null 2>&1
  for r in $routes; do
    CFPO_SOLVER=$r "$CFPO" -n 3000 --seed 9 -t $t --max-iter 12 --density cos:a=0.9,kx=1,ky=0 -q -o pd$t$r.bin >/dev/null 2>&1
    cmp -s rd$t.bin pd$t$r.bin && ok || bad "density, $t threads: the $r solver gives other bytes"
  done
done
CFPO_SOLVER=fast expect 2 "CFPO_SOLVER: bad value 'fast'" -n 100 -o x.npy
"$CFPO" -n 3000 --seed 10 -q -o e.bin >/dev/null
cmp -s d1.bin e.bin && bad "seeds 9 and 10 give the same bytes" || ok
"$CFPO" -n 3000 --seed 9 --variant simplified -q -o sv.bin >/dev/null && ! cmp -s d1.bin sv.bin && ok || bad "simplified variant"

# --- --max-iter caps the run and says converged=no
"$CFPO" -n 3000 --max-iter 3 -q >m.txt && grep -q "iterations=3 .*converged=no" m.txt && ok || bad "--max-iter 3: $(cat m.txt)"

# --- progress on a terminal
if command -v script >/dev/null 2>&1; then
  script -qec "$CFPO -n 3000 -o tty.bin" /dev/null >tty.log 2>&1
  grep -q "iter [0-9]* *delta_min" tty.log && grep -q "ETA" tty.log && ok || bad "no progress line on a terminal"
  script -qec "$CFPO -n 3000 -q" /dev/null >ttyq.log 2>&1
  grep -q "delta_min 0" ttyq.log && bad "--quiet still shows progress" || ok
fi

# --- interruption leaves the old file intact and no temporary file
printf 'keep' >big.npy
"$CFPO" -n 3000000 -t 2 -q -o big.npy >/dev/null 2>&1 &
pid=$!
sleep 1.5
kill -INT $pid
wait $pid
rc=$?
[ $rc -ne 0 ] && [ "$(cat big.npy)" = keep ] && ok || bad "interrupt: rc $rc, big.npy now $(stat -c %s big.npy) bytes"
ls -A | grep -q 'tmp\.' && bad "interrupt left temporary files: $(ls -A | grep tmp)" || ok

echo "$pass passed, $fail failed"
[ $fail -eq 0 ]
