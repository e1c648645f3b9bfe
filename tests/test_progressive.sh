#!/usr/bin/env bash
# test_progressive.sh BUILD_DIR - `cfpo --progressive` and `--classes K`
# (src/progressive.c, src/main_prog.c):
#  - bad input (--classes 0, a base larger than n, options the path does
#    not take) gives one line, exit 2 and no file;
#  - the prefix order is kept: a run of n/2 points is, byte for byte, the
#    first half of the run of n points (the earlier levels never move once
#    built), and each LEVEL line's prefix measures are those cfpo-analyze
#    --prefixes finds in the file at that prefix;
#  - no prefix's delta_min falls while its level is optimised (the trace,
#    row by row within each level);
#  - the same bytes for 1, 2 and 3 threads, progressive (the default,
#    --level-balance 16, and --level-balance 0, the greedy insertion: not
#    the default's bytes) and with classes (by colouring and
#    --classes-levels);
#  - classes by colouring: no class's delta_min falls over the JOINT
#    lines, the union's never below min(its value, 0.88); the last JOINT
#    line is cfpo-analyze's delta_min of each class's rows and the union;
#  - SUMMARY's worst prefix is the worst LEVEL line, and the trace's last
#    row says the same;
#  - SIGUSR1 mid-run leaves the level's checkpoint, exit 3 and no output,
#    and --resume from it gives the uninterrupted bytes and levels (the
#    default, and --level-balance 0); a resume whose --level-balance
#    differs from the checkpoint's is refused in one line, nothing written;
#  - the joint move (--joint): no prefix's delta_min falls from one JOINT
#    line to the next over the whole run (every sweep of every level's
#    joint move, the levels between them), nor within a level's trace rows
#    (its engine iterations, then its sweeps); the same bytes for 1-3
#    threads and on resume; the LEVEL lines are the file's prefixes and
#    SUMMARY's and the trace's worst prefix the worst of them.
set -u
HERE=$(cd "$(dirname "$0")" && pwd)
B=$(cd "$1" && pwd)
CFPO="$B/cfpo"
AN="$B/cfpo-analyze"
T=$(mktemp -d /tmp/cfpo-prog-XXXXXX)
trap 'rm -rf "$T"' EXIT
cd "$T" || exit 1
. "$HERE/cli_expect.sh"
export OMP_WAIT_POLICY=passive

# ---- bad input: one line, exit 2, nothing written
expect 2 "classes" -n 1024 --classes 0 -o x.npy
expect 2 "larger than n" -n 1024 --progressive --base 2048 -o x.npy
expect 2 "too small" -n 1024 --progressive --base 8 -o x.npy
expect 2 "each class needs" -n 100 --classes 20 -o x.npy
expect 2 "--relax does not go with --checkpoint" -n 1024 --progressive --relax 3 --checkpoint ck.bin -o x.npy
expect 2 "does not go with --progressive" -n 1024 --progressive --init x.npy -o y.npy
expect 2 "does not go with --progressive" -n 1024 --progressive --time-limit 5 -o x.npy
expect 2 "does not go with --classes" -n 1024 --classes 4 --check -o x.npy
expect 2 "does not go with --progressive" -n 1024 --progressive --density cos:a=0.5 -o x.npy
expect 2 "hyperuniform does not go" -n 1024 --progressive --variant hyperuniform -o x.npy
expect 2 "--base does not go with --classes" -n 1024 --classes 4 --base 64 -o x.npy
expect 2 "needs --progressive" -n 1024 --base 64 -o x.npy
expect 2 "needs --progressive" -n 1024 --relax 3 -o x.npy
expect 2 "needs --progressive" -n 1024 --joint 3 -o x.npy
expect 2 "must be below sqrt(2)" -n 1024 --progressive --joint 3 --joint-prefix 0.6 --joint-full 0.9 -o x.npy
expect 2 "--joint-last" -n 1024 --progressive --joint-last 0 -o x.npy
expect 2 "--joint-candidates" -n 1024 --progressive --joint 3 --joint-candidates 0 -o x.npy
expect 2 "--joint-solve" -n 1024 --progressive --joint 3 --joint-solve -1 -o x.npy
expect 2 "--joint-avg" -n 1024 --progressive --joint 3 --joint-avg 11 -o x.npy
expect 2 "--joint-soft" -n 1024 --progressive --joint 3 --joint-soft x -o x.npy
expect 2 "--joint-pairs" -n 1024 --progressive --joint 3 --joint-pairs 1001 -o x.npy
expect 2 "--joint-circum" -n 1024 --progressive --joint 3 --joint-circum 25 -o x.npy
expect 2 "needs --progressive" -n 1024 --joint-circum 4 -o x.npy
expect 2 "needs --progressive" -n 1024 --polish 3 -o x.npy
expect 2 "needs --progressive" -n 1024 --level-iter 5 -o x.npy
expect 2 "--level-iter" -n 1024 --progressive --level-iter -2 -o x.npy
expect 2 "--polish does not go with --classes" -n 1024 --classes 4 --polish 3 -o x.npy
expect 2 "--polish-floor" -n 1024 --progressive --polish 3 --polish-floor 1.5 -o x.npy
expect 2 "--polish:" -n 1024 --progressive --polish -1 -o x.npy
expect 2 "--relax does not go with --classes" -n 1024 --classes 4 --relax 2 -o x.npy
expect 2 "--level-iter does not go with --classes" -n 1024 --classes 4 --level-iter 3 -o x.npy
expect 2 "--checkpoint does not go with --classes" -n 1024 --classes 4 --checkpoint ck.bin -o x.npy
expect 2 "needs --classes K" -n 1024 --class-swaps 3 -o x.npy
expect 2 "needs --classes K" -n 1024 --progressive --classes-levels -o x.npy
expect 2 "do not go with --classes-levels" -n 1024 --classes 4 --classes-levels --class-union-floor 0.8 -o x.npy
expect 2 "--class-union-floor" -n 1024 --classes 4 --class-union-floor 2 -o x.npy
expect 2 "--class-reach" -n 1024 --classes 4 --class-reach 0.1 -o x.npy
expect 2 "--class-swaps" -n 1024 --classes 4 --class-swaps 65 -o x.npy
expect 2 "--level-balance needs --progressive" -n 1024 --level-balance 16 -o x.npy
expect 2 "--level-balance needs --progressive" -n 1024 --classes 4 --level-balance 16 -o x.npy
expect 2 "--level-balance: '-1'" -n 1024 --progressive --level-balance -1 -o x.npy
expect 2 "--level-balance needs --progressive (without --classes)" -n 1024 --classes 4 --level-balance 0 -o x.npy
expect 2 "--level-balance needs --progressive (without --classes)" -n 1024 --classes 4 --classes-levels --level-balance 16 -o x.npy
expect 2 "--level-balance-order does not go with --level-balance 0" -n 1024 --progressive --level-balance 0 --level-balance-order -o x.npy
expect 2 "--level-balance-order needs --progressive" -n 1024 --level-balance-order -o x.npy
expect 2 "--level-balance-order needs --progressive" -n 1024 --classes 4 --level-balance-order -o x.npy

run() { "$CFPO" -q "$@"; }
field() { grep -o " $1=[^ ]*" | head -1 | cut -d= -f2; }

# ---- threads: the same bytes
for t in 1 2 3; do
  run -n 2048 -s 4 -t $t --progressive -o p$t.npy >p$t.sum || bad "progressive run, $t threads"
  run -n 1200 -s 2 -t $t --classes 3 -o c$t.npy >c$t.sum || bad "classes run, $t threads"
done
cmp -s p1.npy p2.npy && cmp -s p1.npy p3.npy && ok || bad "--progressive: bytes differ across 1-3 threads"
cmp -s c1.npy c2.npy && cmp -s c1.npy c3.npy && ok || bad "--classes 3: bytes differ across 1-3 threads"
for t in 1 2 3; do
  run -n 2048 -s 4 -t $t --progressive --level-balance 0 -o b$t.npy >b$t.sum || bad "--level-balance 0 run, $t threads"
done
cmp -s b1.npy b2.npy && cmp -s b1.npy b3.npy && ok || bad "--level-balance 0: bytes differ across 1-3 threads"
cmp -s b1.npy p1.npy && bad "--level-balance 0 gave the default's bytes" || ok
run -n 2048 -s 4 -t 2 --progressive --level-balance 16 -o b16.npy >b16.sum || bad "--level-balance 16 run"
cmp -s b16.npy p1.npy && ok || bad "the default is not --level-balance 16"

# ---- classes by colouring (the default): over the JOINT lines no class's
# delta_min falls and the union's never below min(its value, 0.88); the
# last JOINT line's classes and union are cfpo-analyze's delta_min of the
# file's row blocks; --classes-levels: the same bytes for 1-3 threads and
# not the colouring's
python3 - <<'PY' && ok || bad "--classes 3: a class fell, or the union below its floor, over the JOINT lines"
import sys
rows = [[float(v) for v in l.split(" delta_min=")[1].split()[0].split(",")] for l in open("c1.sum") if l.startswith("JOINT")]
if len(rows) < 3: sys.exit(1)
for a, b in zip(rows, rows[1:]):
    if any(y < x for x, y in zip(a[:-1], b[:-1])) or b[-1] < min(a[-1], 0.88) - 1e-12: sys.exit(1)
sys.exit(0 if rows[-1][0] > rows[0][0] or rows[-1][1] > rows[0][1] else 1)
PY
python3 - <<'PY' || bad "splitting the classes' rows"
b = open("c1.npy", "rb").read(); h = b.index(b"\n") + 1; n = (len(b) - h) // 16
for c in range(3):
    lo, hi = c * n // 3, (c + 1) * n // 3
    head = "{'descr': '<f8', 'fortran_order': False, 'shape': (%d, 2), }" % (hi - lo)
    head = head + " " * (118 - len(head)) + "\n"
    open("cls%d.npy" % c, "wb").write(b"\x93NUMPY\x01\x00" + bytes([len(head), 0]) + head.encode() + b[h + 16 * lo:h + 16 * hi])
PY
for c in 0 1 2; do "$AN" -q -t 1 cls$c.npy >cls$c.an 2>/dev/null || bad "cfpo-analyze of class $c"; done
"$AN" -q -t 1 c1.npy >clsu.an 2>/dev/null || bad "cfpo-analyze of the union"
python3 - <<'PY' && ok || bad "--classes 3: the last JOINT line is not cfpo-analyze's delta_min of each class and the union"
import sys
last = [l for l in open("c1.sum") if l.startswith("JOINT")][-1]
j = [float(v) for v in last.split(" delta_min=")[1].split()[0].split(",")]
an = [float(open(f).read().split(" delta_min=")[1].split()[0]) for f in ("cls0.an", "cls1.an", "cls2.an", "clsu.an")]
sys.exit(0 if all(abs(a - b) <= 2e-6 for a, b in zip(j, an)) else 1)
PY
for t in 1 2 3; do
  run -n 1200 -s 2 -t $t --classes 3 --classes-levels -o cl$t.npy >cl$t.sum || bad "--classes-levels run, $t threads"
done
cmp -s cl1.npy cl2.npy && cmp -s cl1.npy cl3.npy && ok || bad "--classes-levels: bytes differ across 1-3 threads"
cmp -s cl1.npy c1.npy && bad "--classes-levels gave the colouring's bytes" || ok

# ---- the prefix order: the run of 1024 is the first half of the run of 2048
run -n 1024 -s 4 -t 2 --progressive -o h.npy >h.sum || bad "progressive run of 1024"
python3 - <<'PY' && ok || bad "the 1024-point run is not the first half of the 2048-point run"
import sys
a = open("h.npy", "rb").read(); b = open("p1.npy", "rb").read()
ha = a.index(b"\n") + 1; hb = b.index(b"\n") + 1   # npy headers differ in the shape
sys.exit(0 if a[ha:] == b[hb:hb + len(a) - ha] and len(a) - ha == 1024 * 16 else 1)
PY

# ---- each LEVEL line is the file's prefix, as cfpo-analyze measures it
"$AN" -q --prefixes --prefix-base 64 -t 1 p1.npy >an.sum 2>an.err || bad "cfpo-analyze --prefixes"
python3 - <<'PY' && ok || bad "LEVEL lines differ from cfpo-analyze --prefixes of the file"
import sys
lv = {}
for line in open("p1.sum"):
    if line.startswith("LEVEL"):
        f = dict(kv.split("=") for kv in line.split()[1:])
        lv[int(f["prefix"])] = (float(f["delta_min"]), float(f["delta_avg"]))
an = {}
for line in open("p1.analysis/prefixes.txt"):
    if line.startswith("#"): continue
    w = line.split()
    if w[1] == "dyadic": an[int(w[0])] = (float(w[2]), float(w[3]))
assert sorted(lv) == [64, 128, 256, 512, 1024, 2048], sorted(lv)
bad = [m for m in lv if abs(lv[m][0] - an[m][0]) > 2e-6 or abs(lv[m][1] - an[m][1]) > 2e-6]
sys.exit(1 if bad else 0)
PY

# ---- SUMMARY's worst prefix = the worst LEVEL line; delta_min never falls within a level
run -n 2048 -s 4 -t 1 --progressive --trace tr.tsv >tr.sum || bad "progressive run with a trace"
cmp -s <(grep -v '^SUMMARY' tr.sum | sed 's/seconds=[^ ]*//') <(grep -v '^SUMMARY' p1.sum | sed 's/seconds=[^ ]*//') && ok \
  || bad "the trace changed the LEVEL lines"
python3 - <<'PY' && ok || bad "a prefix's delta_min fell while its level ran, or the worst prefix is misreported"
import sys
rows = [l.rstrip("\n").split("\t") for l in open("tr.tsv")]
h = rows[0]; rows = rows[1:]
L, P, D, W, WD = (h.index(c) for c in ("level", "prefix", "delta_min", "worst_prefix", "worst_delta_min"))
for a, b in zip(rows, rows[1:]):
    if a[L] == b[L] and float(b[D]) < float(a[D]): sys.exit(1)
levels = [l for l in open("tr.sum") if l.startswith("LEVEL")]
for l in levels:
    f = dict(kv.split("=") for kv in l.split()[1:])
    if float(f["delta_min"]) < float(f["start_delta_min"]): sys.exit(1)
dmins = [(float(dict(kv.split("=") for kv in l.split()[1:])["delta_min"]),
          int(dict(kv.split("=") for kv in l.split()[1:])["prefix"])) for l in levels]
w = min(dmins)
s = dict(kv.split("=") for kv in open("tr.sum").read().split("SUMMARY")[1].split())
if int(s["worst_prefix_min"]) != w[1] or abs(float(s["worst_delta_min"]) - w[0]) > 1e-6: sys.exit(1)
if int(rows[-1][W]) != w[1] or abs(float(rows[-1][WD]) - w[0]) > 1e-6: sys.exit(1)
sys.exit(0)
PY

# ---- --relax: the earlier prefixes are measured again (LEVEL = the file's prefixes)
run -n 1024 -s 1 -t 2 --progressive --relax 3 -o r.npy >r.sum || bad "--relax run"
"$AN" -q --prefixes --prefix-base 64 -t 1 r.npy >/dev/null 2>&1 || bad "cfpo-analyze of the --relax run"
python3 - <<'PY' && ok || bad "--relax: LEVEL lines are not the file's prefixes"
import sys
lv = {int(dict(kv.split("=") for kv in l.split()[1:])["prefix"]): float(dict(kv.split("=") for kv in l.split()[1:])["delta_min"])
      for l in open("r.sum") if l.startswith("LEVEL")}
an = {int(w[0]): float(w[2]) for w in (l.split() for l in open("r.analysis/prefixes.txt") if not l.startswith("#")) if w[1] == "dyadic"}
sys.exit(0 if all(abs(lv[m] - an[m]) <= 2e-6 for m in lv) else 1)
PY

# ---- checkpoints: SIGUSR1 mid-run writes the level's checkpoint, exit 3 and no
# output; --resume gives the uninterrupted bytes (and resumes past level 0)
run -n 16384 -s 2 -t 2 --progressive -o ref.npy >ref.sum || bad "reference run"
# the signal must land past level 0 for the resume to show that it skips
# the finished levels; on a busy machine the run can still be in level 0
# (64 points) when it lands, so the cut is tried again with a longer wait
for wait_s in 0.3 1 2; do
  rm -f ck.bin cut.npy
  "$CFPO" -q -n 16384 -s 2 -t 2 --progressive --checkpoint ck.bin --checkpoint-every 3 -o cut.npy >cut.sum 2>cut.err &
  P=$!
  for i in $(seq 1 400); do [ -f ck.bin ] && break; sleep 0.05; done
  sleep $wait_s
  kill -USR1 $P 2>/dev/null
  wait $P; rc=$?
  grep -q "stopped by a signal at level 0 " cut.err || break
  echo "note: the signal landed in level 0; cutting again with a longer wait"
done
if [ "$rc" -eq 3 ]; then
  [ ! -e cut.npy ] && grep -q "checkpoint ck.bin written" cut.err && ok || bad "a signalled run left output or no message"
elif [ "$rc" -eq 0 ]; then
  echo "note: the run ended before the signal; resuming from its last level's checkpoint"
else
  bad "signalled run: exit $rc ($(cat cut.err))"
fi
run -n 16384 -s 2 -t 1 --progressive --resume ck.bin -o res.npy >res.sum || bad "--resume"
cmp -s ref.npy res.npy && ok || bad "--resume: not the uninterrupted bytes"
grep -q "^LEVEL level=0 prefix=64 iterations=- " res.sum && ok || bad "--resume started at level 0"
python3 - <<'PY' && ok || bad "--resume: the finished levels' measures differ from the uninterrupted run's"
import sys
def lv(f): return {l.split()[2]: (l.split()[6], l.split()[7]) for l in open(f) if l.startswith("LEVEL")}
sys.exit(0 if lv("ref.sum") == lv("res.sum") else 1)
PY
expect 2 "needs the run's -n" --progressive --resume ck.bin -o x.npy
expect 1 "checkpoint is for another run" -n 16384 -s 3 --progressive --resume ck.bin -o x.npy
expect 1 "no level of this run has that size" -n 16000 --base 100 -s 2 --progressive --resume ck.bin -o x.npy
# the checkpoint's balance setting (its level seed says it): the run of 2,048
# points leaves its last level's checkpoint, which is level 5 of the run of
# 4,096; resumed there, the default and --level-balance 0 each give their
# uninterrupted bytes; a resume with another setting is refused, nothing written
for lb in 16 0; do
  run -n 2048 -s 3 -t 1 --progressive --level-balance $lb --checkpoint ckh$lb.bin -o h$lb.npy >/dev/null \
    || bad "--level-balance $lb: the checkpointed run of 2048"
  run -n 4096 -s 3 -t 1 --progressive --level-balance $lb -o f$lb.npy >/dev/null || bad "--level-balance $lb: 4096"
  run -n 4096 -s 3 -t 2 --progressive --level-balance $lb --resume ckh$lb.bin -o r$lb.npy >r$lb.sum \
    || bad "--level-balance $lb: --resume at level 5"
  cmp -s f$lb.npy r$lb.npy && ok || bad "--level-balance $lb: --resume at level 5 is not the uninterrupted bytes"
  grep -q "^LEVEL level=5 prefix=2048 iterations=24 " r$lb.sum && grep -q "^LEVEL level=4 prefix=1024 iterations=- " r$lb.sum \
    && ok || bad "--level-balance $lb: the resume did not start at level 5"
done
cmp -s f16.npy f0.npy && bad "--level-balance 0 and the default gave the same bytes at 4096" || ok
expect 1 "written with --level-balance 0, this run has --level-balance 16;" -n 4096 -s 3 --progressive --resume ckh0.bin -o x.npy
expect 1 "written with --level-balance 16, this run has --level-balance 0;" -n 4096 -s 3 --progressive --level-balance 0 \
  --resume ckh16.bin -o x.npy
expect 1 "written with --level-balance 16, this run has --level-balance 32;" -n 4096 -s 3 --progressive --level-balance 32 \
  --resume ckh16.bin -o x.npy
# a checkpoint of an earlier version's default, whose levels are in the
# greedy order (tests/data/prog-greedy-256.bin: `cfpo -n 256 -s 3 -t 1
# --progressive --checkpoint` before the paced order), refused in one line
expect 1 "by an earlier version, whose greedy order of the levels this one no longer makes; start the run again" \
  -n 512 -s 3 --progressive --resume "$HERE/data/prog-greedy-256.bin" -o x.npy
expect 1 "by an earlier version" -n 512 -s 3 --progressive --level-balance 0 --resume "$HERE/data/prog-greedy-256.bin" \
  -o x.npy
# a checkpoint of the paced order's default (every level paced, before the
# small levels were herded: tests/data/prog-paced-256.bin, `cfpo -n 256 -s 3
# -t 1 --progressive --checkpoint` at 129a90e), refused in one line
expect 1 "by an earlier version, whose paced order of the levels this one no longer makes; start the run again" \
  -n 512 -s 3 --progressive --resume "$HERE/data/prog-paced-256.bin" -o x.npy
expect 1 "by an earlier version, whose paced order" -n 512 -s 3 --progressive --level-balance-order \
  --resume "$HERE/data/prog-paced-256.bin" -o x.npy
expect 1 "this run has --level-balance 16 --level-balance-order;" -n 4096 -s 3 --progressive --level-balance-order \
  --resume ckh16.bin -o x.npy
expect 1 "written with --level-balance 16, this run has --level-balance 0;" -n 16384 -s 2 --progressive --level-balance 0 \
  --resume ck.bin -o x.npy

# ---- the joint move: threads, the prefixes never fall, LEVEL = file, worst prefix
for t in 1 2 3; do
  run -n 2048 -s 4 -t $t --progressive --joint 4 --level-min 0.8 -o j$t.npy >j$t.sum || bad "--joint run, $t threads"
done
cmp -s j1.npy j2.npy && cmp -s j1.npy j3.npy && ok || bad "--joint: bytes differ across 1-3 threads"
cmp -s j1.npy p1.npy && bad "--joint changed nothing" || ok
run -n 2048 -s 4 -t 1 --progressive --joint 4 --level-min 0.8 --trace jt.tsv -o jt.npy >jt.sum || bad "--joint with a trace"
cmp -s jt.npy j1.npy && ok || bad "--joint: the trace changed the bytes"
"$AN" -q --prefixes --prefix-base 64 -t 1 j1.npy >/dev/null 2>&1 || bad "cfpo-analyze of the --joint run"
python3 - <<'PY' && ok || bad "--joint: a prefix fell, or LEVEL / SUMMARY / trace misreport the prefixes"
import sys
kv = lambda l: dict(x.split("=", 1) for x in l.split()[1:])
J = [kv(l) for l in open("jt.sum") if l.startswith("JOINT")]
assert len(J) >= 10, len(J)
best = {}
for j in J:  # every prefix's delta_min, in run order, never falls
    for k, v in enumerate(float(x) for x in j["delta_min"].split(",")):
        if k in best and v < best[k]: sys.exit("prefix %d fell at level %s sweep %s" % (k, j["level"], j["sweep"]))
        best[k] = v
rows = [l.rstrip("\n").split("\t") for l in open("jt.tsv")]
h = rows[0]; rows = rows[1:]
L, D, W, WD = (h.index(c) for c in ("level", "delta_min", "worst_prefix", "worst_delta_min"))
for a, b in zip(rows, rows[1:]):
    if a[L] == b[L] and float(b[D]) < float(a[D]): sys.exit("trace: delta_min fell within level %s" % a[L])
lv = {int(kv(l)["prefix"]): (float(kv(l)["delta_min"]), float(kv(l)["delta_avg"])) for l in open("jt.sum") if l.startswith("LEVEL")}
an = {int(w[0]): (float(w[2]), float(w[3])) for w in (l.split() for l in open("j1.analysis/prefixes.txt") if not l.startswith("#")) if w[1] == "dyadic"}
if any(abs(lv[m][0] - an[m][0]) > 2e-6 or abs(lv[m][1] - an[m][1]) > 2e-6 for m in lv): sys.exit("LEVEL != file")
last = [float(x) for x in J[-1]["delta_min"].split(",")]
if any(abs(a - lv[m][0]) > 2e-6 for a, m in zip(last, sorted(lv))): sys.exit("last JOINT line != LEVEL lines")
w = min((v[0], m) for m, v in lv.items())
s = kv("SUMMARY" + open("jt.sum").read().split("SUMMARY")[1])
if int(s["worst_prefix_min"]) != w[1] or abs(float(s["worst_delta_min"]) - w[0]) > 1e-6: sys.exit("SUMMARY worst")
if int(rows[-1][W]) != w[1] or abs(float(rows[-1][WD]) - w[0]) > 1e-6: sys.exit("trace worst")
PY
# resume with the joint move: SIGUSR1 mid-run, then --resume gives the same bytes
run -n 8192 -s 2 -t 2 --progressive --joint 3 -o jref.npy >jref.sum || bad "--joint reference run"
"$CFPO" -q -n 8192 -s 2 -t 2 --progressive --joint 3 --checkpoint jck.bin --checkpoint-every 3 -o jcut.npy >jcut.sum 2>jcut.err &
P=$!
for i in $(seq 1 400); do [ -f jck.bin ] && break; sleep 0.05; done
sleep 0.2
kill -USR1 $P 2>/dev/null
wait $P; rc=$?
[ "$rc" -eq 3 ] || [ "$rc" -eq 0 ] || bad "--joint signalled run: exit $rc ($(cat jcut.err))"
[ "$rc" -eq 0 ] && echo "note: the --joint run ended before the signal; resuming from its last level's checkpoint"
run -n 8192 -s 2 -t 1 --progressive --joint 3 --resume jck.bin -o jres.npy >jres.sum || bad "--joint --resume"
cmp -s jref.npy jres.npy && ok || bad "--joint --resume: not the uninterrupted bytes"

# ---- the level cap: 24 iterations by default, --level-iter N, 0: each level to convergence
run -n 2048 -s 4 -t 1 --progressive --level-iter 0 -o li0.npy >li0.sum || bad "--level-iter 0"
run -n 2048 -s 4 -t 1 --progressive --level-iter 24 -o li24.npy >li24.sum || bad "--level-iter 24"
cmp -s li24.npy p1.npy && ok || bad "the default is not --level-iter 24"
grep '^SUMMARY' li24.sum | grep ' converged=yes ' | grep -q ' stop=level-iter ' && ok || bad "the level cap's end: $(grep ^SUMMARY li24.sum)"
run -n 2048 -s 4 -t 1 --progressive --max-iter 5 -o lim5.npy >lim5.sum || bad "--progressive --max-iter 5"
grep '^SUMMARY' lim5.sum | grep ' converged=no ' | grep -q ' stop=max-iter ' && ok || bad "--max-iter below the cap: $(grep ^SUMMARY lim5.sum)"
python3 - <<'PY' && ok || bad "--level-iter: a level ran past its cap, or the uncapped levels did not run longer"
import sys
it = lambda f: [int(l.split()[3].split("=")[1]) for l in open(f) if l.startswith("LEVEL")]
a, b = it("li0.sum"), it("li24.sum")
if max(b) > 24 or max(a) <= 24: sys.exit("%s %s" % (a, b))
PY

# ---- the polish: threads, each prefix at or above min(its start, the floor), the full set never falls, resume
for t in 1 2 3; do
  run -n 2048 -s 4 -t $t --progressive --joint 4 --level-min 0.8 --polish 6 --polish-floor 0.74 -o q$t.npy >q$t.sum \
    || bad "--polish run, $t threads"
done
cmp -s q1.npy q2.npy && cmp -s q1.npy q3.npy && ok || bad "--polish: bytes differ across 1-3 threads"
"$AN" -q --prefixes --prefix-base 64 -t 1 q1.npy >/dev/null 2>&1 || bad "cfpo-analyze of the --polish run"
python3 - <<'PY' && ok || bad "--polish: a prefix fell below its floor, the full set fell, or LEVEL != file"
import sys
kv = lambda l: dict(x.split("=", 1) for x in l.split()[1:])
P = [kv(l) for l in open("q1.sum") if l.startswith("POLISH")]
assert len(P) >= 2 and P[0]["sweep"] == "0", len(P)
start = [float(x) for x in P[0]["delta_min"].split(",")]
for p in P:
    d = [float(x) for x in p["delta_min"].split(",")]
    if any(v < min(a, 0.74) - 1e-9 for v, a in zip(d[:-1], start[:-1])): sys.exit("a prefix below its floor")
    if d[-1] < start[-1] - 1e-12: sys.exit("the full set fell")
    start[-1] = d[-1]
lv = {int(kv(l)["prefix"]): float(kv(l)["delta_min"]) for l in open("q1.sum") if l.startswith("LEVEL")}
an = {int(w[0]): float(w[2]) for w in (l.split() for l in open("q1.analysis/prefixes.txt") if not l.startswith("#")) if w[1] == "dyadic"}
if any(abs(lv[m] - an[m]) > 2e-6 for m in lv): sys.exit("LEVEL != file")
PY
run -n 2048 -s 4 -t 2 --progressive --joint 4 --level-min 0.8 --polish 6 --polish-floor 0.74 --checkpoint qck.bin \
  -o qc.npy >qc.sum || bad "--polish with --checkpoint"
run -n 2048 -s 4 -t 1 --progressive --joint 4 --level-min 0.8 --polish 6 --polish-floor 0.74 --resume qck.bin \
  -o qr.npy >qr.sum || bad "--polish --resume"
cmp -s q1.npy qc.npy && cmp -s q1.npy qr.npy && ok || bad "--polish: --checkpoint or --resume changed the bytes"

echo "test_progressive: $pass passed, $fail failed"
[ "$fail" -eq 0 ]
