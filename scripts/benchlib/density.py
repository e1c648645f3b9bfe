"""density - the density part of `make bench`: every method that takes
`--density` (cfpo, and each baseline whose --help names the option) but
those of the profile's dens_skip, on the test densities and the shipped
image (data/astronaut-256.png, see data/README.md), at the profile's dens_n
points, dens_seeds seeds, iterative methods stopped after dens_maxiter
iterations at most; each set analysed by `cfpo-analyze --no-discrepancy
--density SPEC` (analysis/README.md, "Measures under a density"). Writes
density.csv (one row per run: the run's SUMMARY and the analysis' DENSITY
fields) and keeps the image's sets of seed 1 in data/points/ (the stippling
figure's where the profile makes no stippling sets of its own,
stipple.py); read() and section() serve `replot` and summary.md. A folder
written before this part had its name keeps it as adaptive.csv and
data/points/adaptive-image-KEY.txt, read the same way.
"""
import os
import shutil
import subprocess
import sys
import time

from . import stats as S
from .common import Failure, write

HERE = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
IMAGE = os.path.join(HERE, "data", "astronaut-256.png")
# (key, SPEC, label)
DENSITIES = (("cos", "cos:a=0.9", "cos a=0.9 (1:19)"), ("ramp", "ramp:contrast=16", "ramp 1:16"),
             ("balzer", "balzer", "Balzer's field (1:256)"), ("image", IMAGE, "astronaut image (1:255)"))
RUN_FIELDS = ("density", "method", "n", "seed", "seconds", "wall_seconds", "iterations", "stop")
# the DENSITY fields the table shows: (field, heading)
SHOWN = (("density_delta_min", "δ_min (local)"), ("density_delta_avg", "δ_avg (local)"),
         ("count_fidelity_rms", "count fidelity rms"), ("count_fidelity_max", "max"),
         ("capacity_deviation", "capacity deviation"))


def methods(B, meth):
    """(key, label, colour, argv, iterative) of the methods that take
    --density: CFPO (`cfpo --density`, one thread), then every baseline whose
    --help names the option, in methods.tsv's order."""
    out = [("cfpo", "CFPO", meth.colour("adaptive") or "#67000d", [f"{B}/cfpo", "-t", "1"], True)]
    for k in meth.keys("pd", "direct", "iter"):
        words = meth.get(k, "command").split()
        exe = f"{B}/{words[0]}"
        try:
            h = subprocess.run([exe, "--help"], capture_output=True, text=True).stdout
        except OSError:
            continue
        if "--density" in h:
            out.append((k, meth.label(k), meth.colour(k), [exe] + words[1:], meth.kind(k) == "iter"))
    return out


def run(bench, p):
    """The runs and analyses; density.csv in bench.work. Nothing when the
    profile has no density part (dens_n None)."""
    n = p.get("dens_n")
    if not n:
        return
    W = bench.work
    ms = [m for m in methods(bench.B, bench.meth) if m[0] not in p.get("dens_skip", [])]
    total = len(DENSITIES) * len(ms) * p["dens_seeds"]
    rows, cols, k = [], list(RUN_FIELDS), 0
    for dk, spec, _ in DENSITIES:
        for key, label, _, argv, iterative in ms:
            for s in range(1, p["dens_seeds"] + 1):
                k += 1
                print(f"bench: density {k} of {total}: {label} on {dk}, n={n} seed={s}", file=sys.stderr, flush=True)
                out = f"{W}/sets/density-{dk}-{key}-s{s}.txt"
                cmd = argv + ["-n", str(n), "-s", str(s), "-q", "--density", spec, "-o", out]
                if iterative:
                    cmd += ["--max-iter", str(p["dens_maxiter"])]
                t1 = time.time()
                pr = subprocess.run(cmd, capture_output=True, text=True, stdin=subprocess.DEVNULL)
                wall = time.time() - t1
                summ = next((l for l in pr.stdout.split("\n") if l.startswith("SUMMARY")), "")
                if pr.returncode != 0 or not summ:
                    first = (pr.stderr.strip().split("\n") or [""])[0]
                    raise Failure(f"density run failed ({' '.join(os.path.basename(c) for c in cmd[:1])} "
                                  f"{' '.join(cmd[1:])}): {first}")
                a = f"{W}/tmp/an-density"
                an = subprocess.run([f"{bench.B}/cfpo-analyze", "-q", "--no-discrepancy", "--density", spec, "-o", a, out],
                                    capture_output=True, text=True)
                dl = next((l for l in an.stdout.split("\n") if l.startswith("DENSITY")), "")
                if an.returncode != 0 or not dl:
                    raise Failure(f"cfpo-analyze --density failed on {out}")
                shutil.rmtree(a)
                f = S.fields(summ)
                row = dict(density=dk, method=key, n=f.get("n", str(n)), seed=str(s), seconds=f.get("seconds", ""),
                           wall_seconds="%.3f" % wall, iterations=f.get("iterations", "-"), stop=f.get("stop", "-"))
                for kk, v in S.fields(dl).items():
                    if kk in ("hash", "spec"):
                        continue
                    row[kk] = v
                    if kk not in cols:
                        cols.append(kk)
                rows.append(row)
                if dk == "image" and s == 1:
                    os.rename(out, f"{W}/data/points/density-image-{key}.txt")
                else:
                    os.remove(out)
    write(f"{W}/density.csv", [",".join(cols)] + [",".join(r.get(c, "") for c in cols) for r in rows])


def read(R):
    """density.csv (adaptive.csv in a folder written before the name) as
    dicts; [] when the folder has neither."""
    path = next((f"{R}/{f}" for f in ("density.csv", "adaptive.csv") if os.path.isfile(f"{R}/{f}")), None)
    if path is None:
        return []
    lines = [l.rstrip("\n").split(",") for l in open(path)]
    return [dict(zip(lines[0], c)) for c in lines[1:]]


def image_sets(R, rows):
    """(key, n, file relative to R) of the image's seed-1 sets the folder
    keeps, in density.csv's order (data/points/density-image-KEY.txt, or
    adaptive-image-KEY.txt in the older folders)."""
    out = []
    for r in rows:
        if r["density"] != "image" or r["seed"] != "1":
            continue
        f = next((f"data/points/{pre}-image-{r['method']}.txt" for pre in ("density", "adaptive")
                  if os.path.isfile(f"{R}/data/points/{pre}-image-{r['method']}.txt")), None)
        if f:
            out.append((r["method"], r["n"], f))
    return out


def section(p, meth, rows):
    """summary.md's density part: medians over the seeds per density and method."""
    if not rows:
        return
    p("## Following a density\n")
    p("Every method that takes `--density` on the test densities and the shipped image (data/README.md),")
    p("n = %s, iterative methods stopped after the profile's iteration cap at most (density.csv; medians over" % rows[0]["n"])
    p("the seeds). The measures are `cfpo-analyze --density` (analysis/README.md): δ in the symmetric")
    p("measure |x_i - x_j| / sqrt(r_i r_j), count fidelity over blocks, capacity deviation where reported.\n")
    p("| density | method | seeds | seconds | iterations | " + " | ".join(h for _, h in SHOWN) + " |")
    p("| --- | --- | --- | --- | --- |" + " --- |" * len(SHOWN))
    for dk, _, dl in DENSITIES:
        for key in dict.fromkeys(r["method"] for r in rows):
            mine = [r for r in rows if r["density"] == dk and r["method"] == key]
            if not mine:
                continue
            med = lambda c: S.median([S.num(r[c]) for r in mine]) if all(r.get(c, "") not in ("", "-") for r in mine) else None
            cells = []
            for c, _ in SHOWN:
                v = med(c)
                cells.append("-" if v is None else "%.4g" % v)
            it = med("iterations")
            p("| %s | %s | %d | %.2f | %s | %s |" % (dl, "CFPO" if key == "cfpo" else meth.label(key), len(mine),
                                                 med("seconds") or 0, "-" if it is None else "%.0f" % it, " | ".join(cells)))
    p("")
