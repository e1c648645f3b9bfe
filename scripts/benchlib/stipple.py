"""stipple - the stippling figure of `make bench`: the shipped image
(data/astronaut-256.png, see data/README.md) followed at the profile's
stipple_n points (seed 1) by CFPO, adaptive dart throwing, density FPO and
BNOT, each run as STIPPLE says (the profile's stipple_cap, where set, caps
the iterative ones lower), their points drawn as black dots side by side
with a magnified crop of each (scripts/fig-stipple.gp).

Writes stipple.csv (one row per method: the run's SUMMARY fields, its wall
time and its arguments) and data/points/stipple-KEY.txt. A folder without
them (a profile without stipple_n, or written before) draws the figure
from the density part's image sets instead (density.image_sets), as
before. write_figure() and section() serve `replot` and summary.md.
"""
import os
import struct
import subprocess
import sys
import time
import zlib

from . import density as D
from . import stats as S
from .common import Failure, write

# The methods of the figure, in its order, each with the arguments its
# command gets besides -n, -s, -q, --density and -o. CFPO runs to its own
# stop (the density schedule, docs/method.md "Density"; before it had one
# it was capped at 150 iterations: 0.894 / 0.943 on the image at 20,000
# points, locally normalised). Density FPO is capped at 50
# iterations: on the same image and n it has 0.844 / 0.9250 there and
# 0.847 / 0.9252 after 100, at twice the time. BNOT runs its authors'
# schedule, which ends by itself (20 iterations there).
STIPPLE = (("cfpo", "CFPO", []),  # to its own stop (the density schedule)
           ("dart", "adaptive dart throwing", []),
           ("fpo", "density FPO", ["--max-iter", "50"]),
           ("bnot", "BNOT", []))
# the crop, in units of the torus side (y up): the face
CROP = (0.27, 0.57, 0.59, 0.89)
FIELDS = ("method", "n", "seed", "seconds", "wall_seconds", "iterations", "stop", "args")


def darkness(path):
    """The mean of 1 - grey/255 over the pixels of an 8-bit greyscale PNG
    (colour type 0, not interlaced: the shipped image); None for any other
    PNG. This is the mean of the density cfpo --density reads from it."""
    with open(path, "rb") as f:
        b = f.read()
    if b[:8] != b"\x89PNG\r\n\x1a\n":
        return None
    i, idat, w, h = 8, b"", 0, 0
    while i + 8 <= len(b):
        ln, typ = struct.unpack(">I4s", b[i:i + 8])
        data = b[i + 8:i + 8 + ln]
        if typ == b"IHDR":
            w, h, depth, ctype, _, _, lace = struct.unpack(">IIBBBBB", data)
            if depth != 8 or ctype != 0 or lace != 0:
                return None
        elif typ == b"IDAT":
            idat += data
        i += 12 + ln
    raw = zlib.decompress(idat)
    prev, total = bytearray(w), 0
    for r in range(h):  # undo the five PNG row filters
        ft, row = raw[r * (w + 1)], bytearray(raw[r * (w + 1) + 1:(r + 1) * (w + 1)])
        for x in range(w):
            a, up, c = row[x - 1] if x else 0, prev[x], prev[x - 1] if x else 0
            if ft == 1:
                row[x] = (row[x] + a) & 255
            elif ft == 2:
                row[x] = (row[x] + up) & 255
            elif ft == 3:
                row[x] = (row[x] + (a + up) // 2) & 255
            elif ft == 4:
                p = a + up - c
                pa, pb, pc = abs(p - a), abs(p - up), abs(p - c)
                row[x] = (row[x] + (a if pa <= pb and pa <= pc else up if pb <= pc else c)) & 255
        total += sum(row)
        prev = row
    return 1 - total / (255.0 * w * h)


def plan(B, meth, p):
    """(key, label, argv) of the figure's runs: the STIPPLE methods that are
    built and take --density (density.methods), the profile's stipple_cap
    replacing a larger --max-iter of an iterative one."""
    have = {m[0]: m for m in D.methods(B, meth)}
    out = []
    cap = p.get("stipple_cap")
    for key, label, args in STIPPLE:
        if key not in have:
            continue
        args = list(args)
        if cap is not None and have[key][4]:
            if "--max-iter" in args:
                j = args.index("--max-iter") + 1
                args[j] = str(min(int(args[j]), cap))
            else:
                args += ["--max-iter", str(cap)]
        out.append((key, label, have[key][3] + args))
    return out


def run(bench, p):
    """The runs, as many at a time as there are cores (each on one thread);
    stipple.csv and data/points/stipple-KEY.txt in bench.work. Nothing when
    the profile has no stipple_n."""
    n = p.get("stipple_n")
    if not n:
        return
    W = bench.work
    runs = plan(bench.B, bench.meth, p)
    slots = max(1, len(os.sched_getaffinity(0)) if hasattr(os, "sched_getaffinity") else os.cpu_count() or 1)
    # the longest first (BNOT, then the capped iterative ones), so that the
    # cores finish together
    first = ("bnot", "cfpo", "fpo")
    todo = sorted(enumerate(runs), key=lambda x: first.index(x[1][0]) if x[1][0] in first else len(first))
    going, done = [], {}
    while todo or going:
        while todo and len(going) < slots:
            i, (key, label, argv) = todo.pop(0)
            print(f"bench: stippling {i + 1} of {len(runs)}: {label}, n={n}", file=sys.stderr, flush=True)
            cmd = argv + ["-n", str(n), "-s", "1", "-q", "--density", D.IMAGE, "-o", f"{W}/data/points/stipple-{key}.txt"]
            out, err = open(f"{W}/tmp/stipple-{key}.out", "w+"), open(f"{W}/tmp/stipple-{key}.err", "w+")
            pr = subprocess.Popen(cmd, stdout=out, stderr=err, stdin=subprocess.DEVNULL)
            bench.children.append(pr)
            going.append((i, cmd, pr, out, err, time.time()))
        time.sleep(0.05)
        for g in [g for g in going if g[2].poll() is not None]:
            i, cmd, pr, out, err, t1 = g
            going.remove(g)
            bench.children.remove(pr)
            out.seek(0)
            err.seek(0)
            summ = next((l for l in out.read().split("\n") if l.startswith("SUMMARY")), "")
            first = (err.read().strip().split("\n") or [""])[0]
            out.close()
            err.close()
            if pr.returncode != 0 or not summ:
                raise Failure(f"stippling run failed ({os.path.basename(cmd[0])} {' '.join(cmd[1:])}): {first}")
            done[i] = (summ, time.time() - t1)
    rows = [",".join(FIELDS)]
    for i, (key, _, argv) in enumerate(runs):
        f = S.fields(done[i][0])
        rows.append(",".join([key, f.get("n", str(n)), "1", f.get("seconds", ""), "%.3f" % done[i][1],
                              f.get("iterations", "-"), f.get("stop", "-"), " ".join(argv[1:])]))
    write(f"{W}/stipple.csv", rows)


def read(R):
    path = f"{R}/stipple.csv"
    if not os.path.isfile(path):
        return []
    lines = [l.rstrip("\n").split(",") for l in open(path)]
    return [dict(zip(lines[0], c)) for c in lines[1:]]


def write_figure(R, meth, rows, dens_rows, written):
    """fig-stipple.vars.gp: the image, then each method's points, the dots'
    radius and the crop; the stippling sets (rows, stipple.csv) where the
    folder has them, else the density part's image sets (dens_rows, its
    density.csv). False when the folder holds neither."""
    labels = {k: lbl for k, lbl, _ in STIPPLE}
    sets = []
    for r in rows:
        f = f"data/points/stipple-{r['method']}.txt"
        if os.path.isfile(f"{R}/{f}"):
            it = r["iterations"]
            lbl = labels.get(r["method"], meth.label(r["method"]))
            sets.append((lbl if it in ("", "-") else f"{lbl}, {it} iterations", r["n"], f))
    if not sets:
        sets = [("CFPO" if k == "cfpo" else meth.label(k), n, f) for k, n, f in D.image_sets(R, dens_rows)]
    if not sets:
        return False
    n = int(sets[0][1])
    with open(D.IMAGE, "rb") as f:
        head = f.read(24)
    iw, ih = int.from_bytes(head[16:20], "big"), int.from_bytes(head[20:24], "big")
    dark = darkness(D.IMAGE)
    # n dots of radius r cover n pi r^2: the image's mean darkness (0.5 for
    # an image this reader does not decode)
    r = ((0.5 if dark is None else dark) / (n * 3.141592653589793)) ** 0.5
    x0, x1, y0, y1 = CROP
    lines = [written, f"DIR = '{R}'; IMG = '{D.IMAGE}'; IW = {iw}; IH = {ih}; N = {n}; R = {r:.6g}",
             f"CX0 = {x0}; CX1 = {x1}; CY0 = {y0}; CY1 = {y1}",
             f"NM = {len(sets)}; array LBL[{len(sets)}]; array FILE[{len(sets)}]"]
    for i, (lbl, _, f) in enumerate(sets, 1):
        lines.append(f"LBL[{i}] = '{lbl}'; FILE[{i}] = '{f}'")
    write(f"{R}/plotdata/fig-stipple.vars.gp", lines)
    return True


def section(p, rows):
    """summary.md's stippling part: the figure and, where the folder has its
    own runs, what each took."""
    p("## Stippling\n")
    if rows:
        p("The shipped image (data/README.md) at n = %s, seed 1 (stipple.csv): each method's points as black"
          % rows[0]["n"])
        p("dots of one radius, their total area the image's mean darkness, and a magnified crop.\n")
        p("| method | arguments | iterations | stopped by | seconds | wall seconds |")
        p("| --- | --- | --- | --- | --- | --- |")
        labels = {k: lbl for k, lbl, _ in STIPPLE}
        for r in rows:
            p("| %s | `%s` | %s | %s | %s | %s |" % (labels.get(r["method"], r["method"]), r["args"] or "-",
                                                  r["iterations"], r["stop"], S.secs(r["seconds"]),
                                                  S.secs(r["wall_seconds"])))
        p("")
    else:
        p("The image's seed-1 sets of the density part, as black dots, and a magnified crop.\n")
    p("![stippling](fig-stipple.png)\n")
