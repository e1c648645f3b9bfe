"""progressive - the progressive part of `make bench` (docs/results/2026-11-28-progressive.md):
every method whose output order is a prefix order, each prefix P_m (the first m points) measured
in its own units Delta(m) by `cfpo-analyze --prefixes` (delta_min, delta_avg, P0 and the shift
variances of every dyadic m from 64, a sample of non-dyadic ones, and the exact worst delta_min
over every m >= 64):

  cfpo      cfpo --progressive (one thread; every core in PROFILE=progressive)
  wse       weighted sample elimination, its progressive order (cfpo-wse --progressive)
  pmj02bn   progressive multi-jittered (0,2) with blue noise (cfpo-pmj02bn)
  sobol     Owen-scrambled Sobol' in natural order (cfpo-sobol)
  ordered   a converged CFPO set (cfpo, threads as above) in greedy farthest-point order (cfpo-fporder)

The default profile runs it at 16,384 points, one seed (PLANS below; tens of seconds); smoke at
2,048; `make bench PROFILE=progressive` alone at 2^20 points into a folder of its own
(results/<date>-<time>-<host>-progressive/), CFPO_PROG_N=N overriding its n (a quicker check).
The figures: delta_min and delta_avg against m for every method (fig-progressive-prefixes.png)
and the first m points of each set at three sizes (fig-progressive-sets.png). progressive.csv
holds one row per run: the SUMMARY's prefix_* keys, the full set's delta and the wall time;
data/progressive/KEY-sS.prefixes.txt the analyser's prefixes.txt, KEY-sS.xy the points drawn.
"""
import os
import shutil
import subprocess
import sys
import time

from .common import Failure, gnuplot_fig, write

# (key, label, command, its arguments besides -n -s -q -o, colour, point type)
METHODS = (("cfpo", "CFPO --progressive", "cfpo", ["--progressive"], "#d62728", 7),
           ("wse", "WSE progressive", "cfpo-wse", ["--progressive"], "#e377c2", 5),
           ("pmj02bn", "PMJ02BN", "cfpo-pmj02bn", [], "#8c6d31", 9),
           ("sobol", "Owen-Sobol'", "cfpo-sobol", [], "#1f77b4", 11),
           ("ordered", "CFPO, greedy FP order", "cfpo", [], "#2ca02c", 13))

# n, seeds, the three prefix sizes drawn, cfpo's threads (0: every core; the
# same bytes on any number)
PLANS = {
    "default": dict(n=16384, seeds=1, draw=(256, 1024, 4096), threads=1),
    "smoke": dict(n=2048, seeds=1, draw=(128, 512, 2048), threads=1),
    "progressive": dict(n=1 << 20, seeds=1, draw=(256, 1024, 4096), threads=0),
}
BASE = 64
FIELDS = ("method", "n", "seed", "wall_seconds", "delta_min", "delta_avg", "prefix_worst_dyadic_dmin",
          "prefix_worst_dyadic_m", "prefix_worst_dyadic_davg", "prefix_worst_any_dmin", "prefix_worst_any_m")


def fields(text, tag="SUMMARY"):
    for line in text.splitlines():
        if line.startswith(tag + " "):
            return dict(kv.split("=", 1) for kv in line.split()[1:] if "=" in kv)
    return {}


def call(argv, what):
    pr = subprocess.run(argv, capture_output=True, text=True, stdin=subprocess.DEVNULL)
    if pr.returncode != 0:
        last = (pr.stderr or "").strip().splitlines()[-1:]
        raise Failure(f"{what} failed: {last[0] if last else 'exit %d' % pr.returncode}")
    return pr.stdout


def first_points(npy, out, m):
    """The first m points of an n x 2 .npy (float64, C order) as "x y" lines."""
    import struct
    b = open(npy, "rb").read()
    hl = struct.unpack("<H", b[8:10])[0]
    data = b[10 + hl:]
    m = min(m, len(data) // 16)
    write(out, ["%.6f %.6f" % struct.unpack_from("<2d", data, 16 * i) for i in range(m)])


def plan_of(name):
    plan = PLANS.get(name)
    if plan and name == "progressive" and os.environ.get("CFPO_PROG_N"):
        try:
            n = int(os.environ["CFPO_PROG_N"])
        except ValueError:
            raise Failure(f"CFPO_PROG_N='{os.environ['CFPO_PROG_N']}' is not a whole number", 2)
        if n < 4096:
            raise Failure(f"CFPO_PROG_N={n}: at least 4096 (the largest prefix drawn)", 2)
        plan = dict(plan, n=n)
    return plan


def run(bench, p, name=None):
    """The progressive runs into bench.work (progressive.csv,
    data/progressive/); nothing for a profile without a plan here."""
    plan = plan_of(name or bench.name)
    if not plan:
        return
    B, W = bench.B, bench.work
    D = f"{W}/data/progressive"
    os.makedirs(D, exist_ok=True)
    tmp = f"{D}/tmp"
    os.makedirs(tmp, exist_ok=True)
    rows = []
    n = plan["n"]
    for seed in range(1, plan["seeds"] + 1):
        for key, label, cmd, extra, _, _ in METHODS:
            base = f"{D}/{key}-s{seed}"
            npy = f"{tmp}/{key}-s{seed}.npy"
            print(f"bench: progressive {label}, n={n}, seed {seed}", file=sys.stderr, flush=True)
            t1 = time.time()
            argv = [f"{B}/{cmd}", "-n", str(n), "-s", str(seed), "-q"] + extra
            if cmd == "cfpo":
                argv += ["-t", str(plan["threads"] or os.cpu_count() or 1)]
            if key == "ordered":  # the plain set, then its greedy farthest-point order
                call(argv + ["-o", f"{tmp}/plain.npy"], cmd)
                call([f"{B}/cfpo-fporder", "-q", "-o", npy, f"{tmp}/plain.npy"], "cfpo-fporder")
            else:
                call(argv + ["-o", npy], cmd)
            wall = time.time() - t1
            an = fields(call([f"{B}/cfpo-analyze", "--prefixes", "--prefix-base", str(BASE), "--no-discrepancy",
                              "--no-delaunay", "--integration", "0", "-q", "-o", f"{tmp}/an", npy],
                             f"cfpo-analyze --prefixes on {key}"))
            shutil.copyfile(f"{tmp}/an/prefixes.txt", base + ".prefixes.txt")
            rows.append(dict(method=key, n=n, seed=seed, wall_seconds="%.3f" % wall,
                             **{f: an.get(f, "") for f in FIELDS[4:]}))
            if seed == 1:
                first_points(npy, base + ".xy", max(plan["draw"]))
    shutil.rmtree(tmp)
    write(f"{W}/progressive.csv", ["# draw=" + ",".join(map(str, plan["draw"])), ",".join(FIELDS)]
          + [",".join(str(r[f]) for f in FIELDS) for r in rows])


def read(R):
    """(rows, the drawn sizes) of progressive.csv; ([], ()) without one."""
    if not os.path.isfile(f"{R}/progressive.csv"):
        return [], ()
    lines = [l.rstrip("\n") for l in open(f"{R}/progressive.csv")]
    draw = tuple(int(x) for x in lines[0].split("=", 1)[1].split(","))
    cols = lines[1].split(",")
    return [dict(zip(cols, l.split(","))) for l in lines[2:] if l], draw


def prefix_rows(path):
    """The dyadic rows of a prefixes.txt: [(m, delta_min, delta_avg, p0)]."""
    out = []
    for line in open(path):
        c = line.split()
        if line.startswith("#") or len(c) < 5 or c[1] != "dyadic":
            continue
        out.append((int(c[0]), float(c[2]), float(c[3]), c[4]))
    return out


def write_figures(R, written):
    """plotdata/fig-progressive-prefixes.vars.gp and fig-progressive-sets.vars.gp; [] when the
    folder has no progressive runs, else the two figure names."""
    rows, draw = read(R)
    if not rows:
        return []
    have = [m for m in METHODS if any(r["method"] == m[0] for r in rows)]
    head = [written, f"DIR = '{R}'; N = {rows[0]['n']}; NM = {len(have)}",
            f"array KEY[{len(have)}]; array LBL[{len(have)}]; array COL[{len(have)}]; array PT[{len(have)}]",
            f"array DRAW[3]; DRAW[1] = {draw[0]}; DRAW[2] = {draw[1]}; DRAW[3] = {draw[2]}"]
    for i, (key, label, _, _, col, pt) in enumerate(have, 1):
        head.append(f"KEY[{i}] = '{key}'; LBL[{i}] = \"{label}\"; COL[{i}] = '{col}'; PT[{i}] = {pt}")
    os.makedirs(f"{R}/plotdata", exist_ok=True)
    write(f"{R}/plotdata/fig-progressive-prefixes.vars.gp", head)
    write(f"{R}/plotdata/fig-progressive-sets.vars.gp", head)
    return ["progressive-prefixes", "progressive-sets"]


def section(p, R):
    """summary.md's progressive part: every dyadic prefix of seed 1 per method, the worst
    prefixes (medians over seeds), and the figures."""
    rows, draw = read(R)
    if not rows:
        return
    have = [m for m in METHODS if any(r["method"] == m[0] for r in rows)]
    n = rows[0]["n"]
    p("## Progressive sets\n")
    p("Every prefix P_m (the first m points of the file) in its own units Delta(m) = sqrt(2/(sqrt(3) m)),")
    p(f"n = {n} (progressive.csv, data/progressive/; `cfpo-analyze --prefixes --prefix-base {BASE}`).")
    p("delta_min / delta_avg of each dyadic prefix, seed 1:\n")
    p("| m | " + " | ".join(m[1] for m in have) + " |")
    p("| ---: |" + " --- |" * len(have))
    table = {m[0]: {r[0]: r for r in prefix_rows(f"{R}/data/progressive/{m[0]}-s1.prefixes.txt")} for m in have}
    sizes = sorted({s for t in table.values() for s in t})
    for s in sizes:
        p(f"| {s} | " + " | ".join("%.3f / %.3f" % table[m[0]][s][1:3] if s in table[m[0]] else "-"
                                   for m in have) + " |")
    p("")
    p("| method | full set delta_min / delta_avg | worst dyadic prefix delta_min (m) / least dyadic delta_avg | "
      "worst of every m >= %d (m) | seconds (wall) |" % BASE)
    p("| --- | --- | --- | --- | --- |")
    for key, label, _, _, _, _ in have:
        for r in (r for r in rows if r["method"] == key):
            p("| %s (seed %s) | %s / %s | %s (%s) / %s | %s (%s) | %s |" % (
                label, r["seed"], r["delta_min"][:6], r["delta_avg"][:6], r["prefix_worst_dyadic_dmin"][:6],
                r["prefix_worst_dyadic_m"], r["prefix_worst_dyadic_davg"][:6], r["prefix_worst_any_dmin"][:6],
                r["prefix_worst_any_m"], r["wall_seconds"]))
    p("")
    p("![delta_min and delta_avg of every prefix](fig-progressive-prefixes.png)\n")
    p("![the first %s points of each set](fig-progressive-sets.png)\n" % ", ".join(map(str, draw)))


def draw(R):
    for fig in write_figures(R, "# written by scripts/benchlib/progressive.py"):
        gnuplot_fig(R, f"{R}/plotdata", fig)


class _Alone:
    def __init__(self, B, work, name):
        self.B, self.work, self.name = B, work, name


def main(build, name="progressive"):
    """`make bench PROFILE=progressive`: the progressive part alone, in its own folder."""
    import socket
    B = os.path.abspath(build)
    for c in ["cfpo", "cfpo-analyze", "cfpo-fporder"] + [m[2] for m in METHODS]:
        if not os.access(f"{B}/{c}", os.X_OK):
            raise Failure(f"{B}/{c} not built (run make)")
    if not shutil.which("gnuplot"):
        raise Failure("gnuplot not found (run scripts/install-deps.sh)")
    plan = plan_of(name)
    os.environ.setdefault("OMP_WAIT_POLICY", "passive")
    root = os.environ.get("CFPO_RESULTS", "results")
    final = os.path.join(root, time.strftime("%Y%m%d-%H%M%S") + "-" + socket.gethostname().split(".")[0]
                         + "-progressive")
    work = final + f".tmp.{os.getpid()}"
    os.makedirs(work)
    t0 = time.time()
    try:
        run(_Alone(B, work, name), None, name)
        draw(work)
    except BaseException:
        if not os.environ.get("CFPO_BENCH_KEEP"):
            shutil.rmtree(work, ignore_errors=True)
        raise
    out = []
    section(out.append, work)
    load = " ".join(open("/proc/loadavg").read().split()[:3])
    write(f"{work}/summary.md", ["# Progressive benchmark (PROFILE=%s, n = %d)\n" % (name, plan["n"]),
                                 "Host %s, %d cores; load average after: %s; took %.0f s.\n"
                                 % (socket.gethostname(), os.cpu_count() or 1, load, time.time() - t0)] + out)
    os.rename(work, final)
    write_figures(final, "# written by scripts/benchlib/progressive.py")  # the data's folder, renamed
    print(f"bench: progressive results in {final} (summary.md, progressive.csv, fig-progressive-*.png)",
          file=sys.stderr)
