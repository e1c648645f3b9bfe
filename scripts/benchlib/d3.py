"""d3 - the 3-D part of `make bench` (docs/results/2026-11-28-3d-baselines.md): cfpo3d
against the 3-D baselines (baselines/README.md, "Three dimensions") on the
unit 3-torus, each set measured by cfpo3d-analyze (delta, packing fraction,
Q6, W6, crystal-like fraction, the shell-averaged spectrum and P0, g(r)).

The default profile runs it small (D3 below: about 1,000 points, one seed,
the iterative methods stopped at delta_min 0.90 or a few seconds); `make
bench PROFILE=3d` runs it alone, larger and with 3 seeds, into a folder of
its own (results/<date>-<time>-<host>-3d/). The figures: a slab of each set
(fig-3d-slabs.png), the spectra over shells, g(r), delta_min against time
(time to quality: the traces of cfpo3d and 3-D FPO, the direct methods as
points) and the packing fraction against time (fig-3d.png). d3.csv holds one
row per run: its SUMMARY and ANALYZE3D fields and its wall time.
"""
import os
import subprocess
import sys
import time

from .common import Failure, gnuplot_fig, write

# (key, label, command, its own arguments, iterative, colour)
METHODS = (("cfpo3d", "CFPO 3-D", "cfpo3d", ["-t", "1"], True, "#d62728"),
           ("fpo", "FPO 3-D (CGAL)", "cfpo3d-fpo", [], True, "#1f77b4"),
           ("lloyd", "Lloyd 3-D (CGAL)", "cfpo3d-lloyd", [], True, "#ff7f0e"),
           ("wse", "sample elimination", "cfpo3d-wse", [], False, "#2ca02c"),
           ("dart", "dart throwing", "cfpo3d-dart", [], False, "#9467bd"),
           ("bridson", "Bridson", "cfpo3d-bridson", [], False, "#8c564b"),
           ("jitter", "jittered", "cfpo3d-jitter", [], False, "#7f7f7f"),
           ("white", "white noise", "cfpo3d-white", [], False, "#bcbd22"))

# the plans: n, seeds, what stops the iterative methods
PLANS = {
    "default": dict(n=1000, seeds=1, stop=["--target-min", "0.90", "--time-limit", "8"]),
    "smoke": dict(n=500, seeds=1, stop=["--target-min", "0.85", "--time-limit", "3"]),
    "3d": dict(n=16384, seeds=3, stop=["--target-min", "0.915", "--time-limit", "150"]),
}
FIELDS = ("method", "n", "seed", "seconds", "wall_seconds", "iterations", "stop", "delta_min", "delta_avg",
          "packing_fraction", "q6_global", "crystal_fraction", "w6", "p0", "peak_shell", "pcf_peak")
SLAB = 0.1  # the slab's thickness, in units of the torus side


def fields(text, tag):
    for line in text.splitlines():
        if line.startswith(tag + " "):
            return dict(kv.split("=", 1) for kv in line.split()[1:] if "=" in kv)
    return {}


def run(bench, p, name=None):
    """The 3-D runs into bench.work (d3.csv, data/d3/); nothing for a
    profile without a 3-D plan."""
    plan = PLANS.get(name or bench.name)
    if not plan:
        return
    B, W = bench.B, bench.work
    os.makedirs(f"{W}/data/d3", exist_ok=True)
    rows = []
    methods = [m for m in METHODS if os.access(f"{B}/{m[2]}", os.X_OK)]
    for seed in range(1, plan["seeds"] + 1):
        for key, label, cmd, extra, it, _ in methods:
            base = f"{W}/data/d3/{key}-s{seed}"
            argv = [f"{B}/{cmd}", "-n", str(plan["n"]), "-s", str(seed), "-q", "-o", base + ".npy"] + extra
            if it:
                argv += plan["stop"] + ["--trace", base + ".trace"]
            print(f"bench: 3-D {label}, n={plan['n']}, seed {seed}", file=sys.stderr, flush=True)
            t1 = time.time()
            pr = subprocess.run(argv, capture_output=True, text=True, stdin=subprocess.DEVNULL)
            wall = time.time() - t1
            if pr.returncode != 0:
                raise Failure(f"{cmd} failed: {(pr.stderr or '').strip().splitlines()[-1:]}")
            s = fields(pr.stdout, "SUMMARY")
            an = subprocess.run([f"{B}/cfpo3d-analyze", "--spectrum", base + ".spec", "--pcf", base + ".pcf",
                                 base + ".npy"], capture_output=True, text=True)
            if an.returncode != 0:
                raise Failure(f"cfpo3d-analyze failed on {base}.npy: {an.stderr.strip()}")
            a = fields(an.stdout, "ANALYZE3D")
            rows.append(dict(method=key, n=s.get("n"), seed=seed, seconds=s.get("seconds"),
                             wall_seconds="%.3f" % wall, iterations=s.get("iterations"), stop=s.get("stop"),
                             delta_min=a.get("delta_min"), delta_avg=a.get("delta_avg"),
                             packing_fraction=a.get("packing_fraction"), q6_global=a.get("q6_global"),
                             crystal_fraction=a.get("crystal_fraction"), w6=a.get("w6"), p0=a.get("p0"),
                             peak_shell=a.get("peak_shell"), pcf_peak=a.get("pcf_peak")))
            if seed == 1:
                slab(base + ".npy", base + ".slab")
    write(f"{W}/d3.csv", [",".join(FIELDS)] + [",".join(str(r[f]) for f in FIELDS) for r in rows])


def slab(npy, out):
    """The points with z < SLAB of an n x 3 .npy (float64, C order) as "x y" lines."""
    import struct
    b = open(npy, "rb").read()
    hl = struct.unpack("<H", b[8:10])[0]
    data = b[10 + hl:]
    n = len(data) // 24
    lines = []
    for i in range(n):
        x, y, z = struct.unpack_from("<3d", data, 24 * i)
        if z < SLAB:
            lines.append("%.6f %.6f" % (x, y))
    write(out, lines)


def read(R):
    if not os.path.isfile(f"{R}/d3.csv"):
        return []
    lines = [l.rstrip("\n").split(",") for l in open(f"{R}/d3.csv")]
    return [dict(zip(lines[0], l)) for l in lines[1:] if l and l[0]]


def med(xs):
    xs = sorted(float(x) for x in xs if x not in ("", "-", "None", "nan"))
    if not xs:
        return float("nan")
    k = len(xs)
    return xs[k // 2] if k % 2 else (xs[k // 2 - 1] + xs[k // 2]) / 2


def write_figures(R, written):
    """plotdata/fig-3d-slabs.vars.gp and fig-3d.vars.gp; [] when the folder
    has no 3-D runs, else the two figure names."""
    rows = read(R)
    if not rows:
        return []
    have = [m for m in METHODS if any(r["method"] == m[0] for r in rows)]
    n = rows[0]["n"]
    # the direct methods' points in the time figures: (median seconds, median delta_min)
    pts = []
    for key, label, _, _, it, col in have:
        rs = [r for r in rows if r["method"] == key]
        pts.append("%s %s %s" % (med(r["seconds"] for r in rs), med(r["delta_min"] for r in rs), key))
    write(f"{R}/plotdata/d3-direct.dat", ["# seconds delta_min method"] + pts)
    head = [written, f"DIR = '{R}'; N = {n}; SLAB = {SLAB}", f"NM = {len(have)}; array KEY[{len(have)}]; "
            f"array LBL[{len(have)}]; array COL[{len(have)}]; array IT[{len(have)}]"]
    for i, (key, label, _, _, it, col) in enumerate(have, 1):
        head.append(f"KEY[{i}] = '{key}'; LBL[{i}] = '{label}'; COL[{i}] = '{col}'; IT[{i}] = {1 if it else 0}")
    write(f"{R}/plotdata/fig-3d-slabs.vars.gp", head)
    write(f"{R}/plotdata/fig-3d.vars.gp", head)
    return ["3d-slabs", "3d"]


def section(p, R):
    """summary.md's 3-D part: medians over seeds per method, and the figures."""
    rows = read(R)
    if not rows:
        return
    p("## Three dimensions\n")
    p("cfpo3d against the 3-D baselines at n = %s (d3.csv; medians over %d seed(s); cfpo3d and 3-D FPO stopped"
      % (rows[0]["n"], len({r['seed'] for r in rows})))
    p("by the profile's target or time limit, see `stop`). delta over Delta3(n) = (sqrt(2)/n)^(1/3); packing")
    p("fraction of spheres of diameter delta_min; Q6, W6 and the crystal-like fraction over 12 neighbours;")
    p("P0 the mean power over 0 < |k| <= 0.2 n^(1/3).\n")
    p("| method | delta_min | delta_avg | packing | Q6 | W6 | crystal-like | P0 | seconds | iterations | stop |")
    p("| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |")
    for key, label, _, _, it, _ in METHODS:
        rs = [r for r in rows if r["method"] == key]
        if not rs:
            continue
        m = lambda f: med(r[f] for r in rs)  # noqa: E731
        p("| %s | %.4f | %.4f | %.4f | %.4f | %.5f | %.4f | %.3g | %.3g | %s | %s |" % (
            label, m("delta_min"), m("delta_avg"), m("packing_fraction"), m("q6_global"), m("w6"),
            m("crystal_fraction"), m("p0"), m("seconds"), rs[0]["iterations"], rs[0]["stop"]))
    p("")
    p("![3-D slabs](fig-3d-slabs.png)\n")
    p("![3-D spectra, g(r), time to quality](fig-3d.png)\n")


def draw(R):
    """The figures with gnuplot (for the standalone 3d profile)."""
    os.makedirs(f"{R}/plotdata", exist_ok=True)
    for fig in write_figures(R, "# written by scripts/benchlib/d3.py"):
        gnuplot_fig(R, f"{R}/plotdata", fig)


class _Alone:
    def __init__(self, B, work):
        self.B, self.work, self.name = B, work, "3d"


def main(build, name="3d"):
    """`make bench PROFILE=3d`: the 3-D part alone, in its own folder."""
    import shutil
    import socket
    B = os.path.abspath(build)
    for c in ["cfpo3d", "cfpo3d-analyze"] + [m[2] for m in METHODS if m[0] not in ("fpo", "lloyd")]:
        if not os.access(f"{B}/{c}", os.X_OK):
            raise Failure(f"{B}/{c} not built (run make)")
    if not shutil.which("gnuplot"):
        raise Failure("gnuplot not found (run scripts/install-deps.sh)")
    os.environ.setdefault("OMP_WAIT_POLICY", "passive")
    root = os.environ.get("CFPO_RESULTS", "results")
    final = os.path.join(root, time.strftime("%Y%m%d-%H%M%S") + "-" + socket.gethostname().split(".")[0] + "-3d")
    work = final + f".tmp.{os.getpid()}"
    os.makedirs(work)
    t0 = time.time()
    run(_Alone(B, work), None, name)
    draw(work)
    out = []
    section(out.append, work)
    load = " ".join(open("/proc/loadavg").read().split()[:3])
    write(f"{work}/summary.md", ["# 3-D benchmark (PROFILE=%s)\n" % name,
                                 "Host %s, %d cores; load average after: %s; took %.0f s.\n"
                                 % (socket.gethostname(), os.cpu_count() or 1, load, time.time() - t0)] + out)
    os.rename(work, final)
    print(f"bench: 3-D results in {final} (summary.md, d3.csv, fig-3d*.png)", file=sys.stderr)
