"""plotdata - `bench.py replot [RESULTS_DIR]` (`make replot`): the figures'
data and the figures of a results folder, and its summary.md, from what the
folder holds (runs.csv, spectra.csv, quality.csv, data/), running nothing
but gnuplot. Default folder: the newest under results/ with a runs.csv.

Writes plotdata/ (the tables the figures draw: convergence-KEY.dat,
runtime.tsv/.dat, speedup.tsv, speedup-cores.dat, speedup-n.dat, ttq-runs.tsv,
ttq-nN.dat, integration.dat and one fig-NAME.vars.gp per figure),
fig-NAME.png for every scripts/fig-NAME.gp (time-to-quality only when the
folder has such runs, integration when it has integration.csv, pcf when
the comparison's analyses hold pcf.txt) and summary.md. Each file is written under a temporary name and renamed.
"""
import math
import os
import re
import shutil
import sys

from . import methods as M
from . import stats as S
from .common import Failure, gnuplot_fig, write

WRITTEN = "# written by scripts/bench.py replot"


class Folder:
    """A results folder's runs.csv (header and rows) and spectra.csv."""
    def __init__(self, R):
        self.R = R
        self.head, self.rows = [], []
        for line in open(f"{R}/runs.csv"):
            line = line.rstrip("\n")
            if line.startswith("#"):
                self.head.append(line)
            elif not line.startswith("run,"):
                self.rows.append(line.split(","))
        self.spectra = [l.rstrip("\n").split(",") for l in open(f"{R}/spectra.csv")][1:]
        plan = next((l[len("# plan: "):] for l in self.head if l.startswith("# plan: ")), "")
        self.plan = plan

    def hdr(self, name):
        for l in self.head:
            m = re.match(r"# .*%s: ([^;]*)" % re.escape(name), l)
            if m:
                return m.group(1)
        return ""

    def planv(self, name):
        m = re.match(r".*%s=([^ ;]*)" % re.escape(name), self.plan)
        return m.group(1) if m else ""


def newest():
    try:
        dirs = sorted(d for d in os.listdir("results") if os.path.isfile(f"results/{d}/runs.csv"))
    except OSError:
        dirs = []
    if not dirs:
        raise Failure("no results folder with a runs.csv under results/ (run make bench first)")
    return f"results/{dirs[-1]}"


def plural(n):
    return "s" if int(n) > 1 else ""


def ranks_note(r):
    return f", {r} ranks" if int(r) > 1 else ""


def blocks(parts):
    """Blocks of lines for gnuplot's `index`, two blank lines apart."""
    return "\n\n".join("".join(l + "\n" for l in b) for b in parts)


def write_text(path, text):
    tmp = f"{path}.tmp.{os.getpid()}"
    with open(tmp, "w") as f:
        f.write(text)
    os.rename(tmp, path)


def columns_vars(F, meth, fig, groups, gpdir, N, SETS):
    lines = [WRITTEN, f"DIR = '{F.R}'; GPDIR = '{gpdir}'; N = {N}; SETS = {SETS}; ZOOM = 0.5; CBMAX = 4",
             "SPAN = %d" % int(2 * math.sqrt(float(N)) + 0.5),
             f"NC = {len(groups)}; array GRP[{len(groups)}]; array LBL[{len(groups)}]"]
    for c, g in enumerate(groups, 1):
        if g.startswith("evolution-it"):
            it = g[len("evolution-it"):]
            lbl = "iteration 0 (start)" if it == "0" else f"iteration {it}"
        elif g == M.group("comparison", "paper", {s[0] for s in F.spectra}) and fig == "evolution":
            its = [S.num(r[10]) for r in F.rows if r[1] == "comparison" and M.key(r[2], r[3]) == "paper"]
            lbl = "converged (mean %s it.)" % ("%d" % int(sum(its) / len(its) + 0.5) if its else "")
        else:
            k = g[len("comparison-"):]
            lbl = meth.label("paper" if k == "cfpo" else k)
        if not os.path.isfile(f"{F.R}/data/analysis/{g}/spectrum.txt"):
            raise Failure(f"{F.R}/data/analysis/{g}/spectrum.txt missing")
        lines.append(f"GRP[{c}] = '{g}'; LBL[{c}] = '{lbl}'")
    write(f"{F.R}/plotdata/fig-{fig}.vars.gp", lines)


def convergence(F, meth, N, SETS):
    """Mean and range over the comparison's traces, per iteration; a set that
    has converged keeps its last value."""
    keys = []
    for k in meth.keys("iter", "cfpo"):  # not the direct samplers: one pass, no curve
        traces = [r[18] for r in F.rows if r[1] == "comparison" and M.key(r[2], r[3]) == k and r[18] != "-"]
        if not traces:
            continue
        keys.append(k)
        sets = []
        for t in traces:
            d = {}
            with open(f"{F.R}/{t}") as f:
                next(f)
                for line in f:
                    c = line.rstrip("\n").split("\t")
                    d[int(S.num(c[0]))] = (S.num(c[1]), S.num(c[2]))
            sets.append((d, max(d) if d else 0))
        top = max(last for _, last in sets)
        out = ["# iteration\tdmin_mean\tdmin_lo\tdmin_hi\tdavg_mean\tdavg_lo\tdavg_hi\tsets_running"]
        for it in range(top + 1):
            a = [d.get(min(it, last), (0.0, 0.0)) for d, last in sets]
            run = sum(1 for _, last in sets if it < last)
            sa = sb = 0.0
            for x, y in a:
                sa += x
                sb += y
            out.append("%d\t%.6f\t%.6f\t%.6f\t%.6f\t%.6f\t%.6f\t%d" % (
                it, sa / len(a), min(x for x, _ in a), max(x for x, _ in a), sb / len(a),
                min(y for _, y in a), max(y for _, y in a), run))
        write(f"{F.R}/plotdata/convergence-{k}.dat", out)
    lines = [WRITTEN, f"DIR = '{F.R}'; N = {N}; SETS = {SETS}",
             f"NM = {len(keys)}; array KEY[{len(keys)}]; array LBL[{len(keys)}]; array COL[{len(keys)}]"]
    for i, k in enumerate(keys, 1):
        lines.append(f"KEY[{i}] = '{k}'; LBL[{i}] = '{meth.label(k)}'; COL[{i}] = '{meth.colour(k)}'")
    write(f"{F.R}/plotdata/fig-convergence.vars.gp", lines)
    return keys


def uncapped(F):
    return [r for r in F.rows if r[1] in ("comparison", "runtime") and r[9] == "-"]


def runtime(F, meth, host):
    """Medians per (method, threads, ranks, n) of every uncapped run."""
    g = {}
    for r in uncapped(F):
        g.setdefault((M.key(r[2], r[3]), r[7], r[8], r[5]), []).append(r)
    tsv = []
    for (k, t, rk, n), rs in sorted(g.items(), key=lambda x: (x[0][0], S.num(x[0][1]), S.num(x[0][2]),
                                                               S.num(x[0][3]))):
        spi = [r[12] for r in rs if r[12] != "-"]
        its = [r[10] for r in rs if r[10] != "-"]
        tsv.append([k, t, rk, n, "%.6g" % S.median([r[11] for r in rs]), "%.6g" % S.median(spi) if spi else "-",
                    "%d" % len(rs), "%g" % S.median(its) if its else "-", "".join(" " + r[0] for r in rs)])
    write(f"{F.R}/plotdata/runtime.tsv", ["\t".join(x) for x in tsv])
    parts, labels = [], []
    for k in meth.keys(*M.KINDS):
        mine = [x for x in tsv if x[0] == k]
        trs = sorted({(x[1], x[2]) for x in mine}, key=lambda tr: (S.num(tr[1]), S.num(tr[0])))
        for t, rk in trs:
            parts.append(["%s\t%s\t%s\t%s\t%s" % (x[3], x[4], -1 if x[5] == "-" else x[5], x[6], x[7])
                          for x in mine if (x[1], x[2]) == (t, rk)])
            l = meth.label(k)
            if meth.kind(k) == "cfpo":
                l += f", {t} thread{plural(t)}"
            l += ranks_note(rk)
            labels.append(f"LBL[%d] = '{l}'; COL[%d] = '{meth.colour(k)}'; PT[%d] = {meth.pt(k)}; "
                          f"DT[%d] = {2 if int(t) > 1 or int(rk) > 1 else 1}; "
                          f"ITER[%d] = {0 if meth.kind(k) in M.ONE_PASS else 1}")
    write_text(f"{F.R}/plotdata/runtime.dat",
               "# one block per method/threads/ranks: n_target median_seconds median_s_per_iter runs median_iterations\n"
               + blocks(parts))
    nb = len(labels)
    write(f"{F.R}/plotdata/fig-runtime.vars.gp", [WRITTEN, f"DIR = '{F.R}'; HOST = '{host}'",
          f"NB = {nb}; array LBL[{nb}]; array COL[{nb}]; array PT[{nb}]; array DT[{nb}]; array ITER[{nb}]"]
          + [l.replace("%d", str(i)) for i, l in enumerate(labels, 1)])
    return tsv


def speedup(F, meth, host):
    """Median time on 1 thread and 1 rank over the median time of each
    configuration, same method, n and seeds (the seeds that ran both)."""
    cf = meth.keys("cfpo")
    T = {}
    for r in uncapped(F):
        k = M.key(r[2], r[3])
        if k in cf:
            T[(k, r[5], r[7], r[8], r[6])] = (r[11], r[0])
    confs = {x[:4] for x in T}
    sp = []
    for k, n, t, rk in confs:
        pairs = sorted(((T[(k, n, "1", "1", s)], T[x]) for x in T if x[:4] == (k, n, t, rk)
                        for s in [x[4]] if (k, n, "1", "1", s) in T), key=lambda ab: S.num(ab[1][1]))
        if not pairs:
            continue
        ratio = S.median([a[0] for a, _ in pairs]) / S.median([b[0] for _, b in pairs])
        sp.append([k, n, t, rk, "%d" % (int(t) * int(rk)), "%.4f" % ratio,
                   "".join(" " + a[1] for a, _ in pairs) + " |" + "".join(" " + b[1] for _, b in pairs)])
    sp.sort(key=lambda x: (x[0], S.num(x[1]), S.num(x[4]), S.num(x[3])))
    write(f"{F.R}/plotdata/speedup.tsv", ["\t".join(x) for x in sp])
    # against cores: one block per method/n/ranks (the 1-thread, 1-rank row in each)
    # (a method and n with one-thread runs only, as adaptive CFPO's comparison, draws no line)
    multi = {(x[0], x[1]) for x in sp if int(x[4]) > 1}
    ba = sorted({(x[0], x[1], x[3]) for x in sp if (x[0], x[1]) in multi}, key=lambda b: (b[0], S.num(b[1]), S.num(b[2])))
    ba.sort(key=lambda b: b[0], reverse=True)
    parts = []
    for k, n, rk in ba:
        rows = [f"{x[4]}\t{x[5]}\t{x[2]}\t{x[3]}" for x in sp
                if x[0] == k and x[1] == n and (x[3] == rk or (x[3] == "1" and x[2] == "1"))]
        parts.append(sorted(rows, key=lambda l: (S.num(l.split("\t")[0]), l)))
    write_text(f"{F.R}/plotdata/speedup-cores.dat",
               "# speedup against cores used: one block per method/n/ranks: cores speedup threads ranks\n" + blocks(parts))
    bb = sorted({(x[0], x[2], x[3]) for x in sp if int(x[4]) > 1}, key=lambda b: (S.num(b[2]), S.num(b[1])))
    bb.sort(key=lambda b: b[0], reverse=True)
    parts = []
    for k, t, rk in bb:
        rows = [f"{x[1]}\t{x[5]}" for x in sp if x[0] == k and x[2] == t and x[3] == rk]
        parts.append(sorted(rows, key=lambda l: (S.num(l.split("\t")[0]), l)))
    write_text(f"{F.R}/plotdata/speedup-n.dat",
               "# speedup against n: one block per method/threads/ranks (threads x ranks > 1): n speedup\n"
               + blocks(parts))
    maxc = 2
    for x in sp:
        maxc = max(maxc, int(x[4]))
    sizes = sorted({b[1] for b in ba}, key=S.num)
    lines = [WRITTEN, f"DIR = '{F.R}'; HOST = '{host}'", f"MAXC = {maxc}",
             f"NA = {len(ba)}; array LBLA[{len(ba)}]; array COLA[{len(ba)}]; array PTA[{len(ba)}]; array DTA[{len(ba)}]"]
    for i, (k, n, rk) in enumerate(ba, 1):
        j = sizes.index(n) + 1
        lines.append(f"LBLA[{i}] = '{meth.label(k)}, n = {n}{ranks_note(rk)}'; COLA[{i}] = '{meth.colour(k)}'; "
                     f"PTA[{i}] = {4 + j}; DTA[{i}] = {(j - 1) % 5 + 1}")
    lines.append(f"NBB = {len(bb)}; array LBLB[{len(bb)}]; array COLB[{len(bb)}]; array PTB[{len(bb)}]; array DTB[{len(bb)}]")
    for i, (k, t, rk) in enumerate(bb, 1):
        lines.append(f"LBLB[{i}] = '{meth.label(k)}, {t} threads, {rk} rank{plural(rk)}'; COLB[{i}] = '{meth.colour(k)}'; "
                     f"PTB[{i}] = {5 + i % 4}; DTB[{i}] = {2 if int(rk) > 1 else 1}")
    write(f"{F.R}/plotdata/fig-speedup.vars.gp", lines)
    return sp


def replot(R=None):
    R = R or newest()
    if not os.path.isdir(R):
        raise Failure(f"{R}: no such folder")
    for f in ("runs.csv", "spectra.csv"):
        if not os.path.isfile(f"{R}/{f}"):
            raise Failure(f"{R}/{f} missing (not a folder written by scripts/bench.py)")
    if not shutil.which("gnuplot"):
        raise Failure("gnuplot not found (run scripts/install-deps.sh)")
    R = os.path.abspath(R)
    F = Folder(R)
    gpdir = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    meth = M.Methods()
    SETS, N = F.planv("SETS"), F.planv("COMP_N")
    if not SETS or not N:
        raise Failure(f"{R}/runs.csv: no '# plan:' header line")
    P = f"{R}/plotdata"
    os.makedirs(P, exist_ok=True)
    host = f"{F.hdr('host') or '?'}, {F.hdr('cores') or '?'} cores"
    evo = [s[0] for s in F.spectra if s[1] == "evolution"]
    have = {s[0] for s in F.spectra}
    if evo:  # a profile without evolution runs (seeds, lowk) may have no CFPO comparison either
        columns_vars(F, meth, "evolution", evo + [M.group("comparison", "paper", have)], gpdir, N, SETS)
    columns_vars(F, meth, "comparison", [M.group("comparison", k, have) for k in meth.keys(*M.KINDS)
                                          if M.group("comparison", k, have) in have], gpdir, N, SETS)
    conv_keys = convergence(F, meth, N, SETS)
    rt = runtime(F, meth, host)
    sp = speedup(F, meth, host)
    # a profile without evolution or runtime runs (seeds) draws neither
    # figure (nor the speedup figure); stale copies removed
    figs = [f for f, have in (("evolution", evo), ("comparison", True), ("lowfreq", True), ("convergence", True),
                              ("runtime", rt), ("speedup", any(int(x[4]) > 1 for x in sp))) if have]
    for f in ("evolution", "runtime", "speedup"):
        if f not in figs:
            for g in (f"{R}/fig-{f}.png", f"{P}/fig-{f}.vars.gp"):
                if os.path.exists(g):
                    os.remove(g)
    from . import integration, lowfreq
    lowfreq.write_lowfreq(F, meth, WRITTEN, N)
    integ = integration.read(R)
    # the optional figures: integration (a folder with integration.csv),
    # g(r) (where the averaged analyses hold pcf.txt); stale copies removed
    from . import density, stipple
    dens, stip = density.read(R), stipple.read(R)
    optional = (("integration", bool(integ) and integration.write_figure(R, meth, integ, WRITTEN),
                 ["plotdata/integration.dat"]), ("pcf", lowfreq.write_pcf(F, meth, WRITTEN, N), []),
                ("stipple", stipple.write_figure(R, meth, stip, dens, WRITTEN), []))
    for fig, have, data in optional:
        if have:
            figs.append(fig)
            continue
        for f in [f"fig-{fig}.png", f"plotdata/fig-{fig}.vars.gp"] + data:
            if os.path.exists(f"{R}/{f}"):
                os.remove(f"{R}/{f}")
    from . import d3  # the 3-D part's two figures, where the folder has d3.csv
    figs += d3.write_figures(R, WRITTEN)
    from . import progressive  # the progressive part's two figures, where the folder has progressive.csv
    figs += progressive.write_figures(R, WRITTEN)
    for f in os.listdir(P):
        if f.startswith("ttq-") and f.endswith(".dat"):
            os.remove(f"{P}/{f}")
    from . import ttq
    tmin = tavg = "-"
    runs = []
    if any(r[1] == "ttq" for r in F.rows):
        if not os.path.isfile(f"{R}/quality.csv"):
            raise Failure(f"{R}/quality.csv missing (the folder has time-to-quality runs)")
        tmin, tavg = F.planv("TTQ_TARGET_MIN"), F.planv("TTQ_TARGET_AVG")
        if not tmin or not tavg:
            raise Failure(f"{R}/runs.csv: no TTQ_TARGET_MIN/TTQ_TARGET_AVG in the '# plan:' line")
        runs = ttq.write(F, meth, P, tmin, tavg)
        figs.append("time-to-quality")
    else:
        write(f"{P}/ttq-runs.tsv", ["# no time-to-quality runs in this folder"])
        for f in (f"{R}/fig-time-to-quality.png", f"{P}/fig-time-to-quality.vars.gp"):
            if os.path.exists(f):
                os.remove(f)
    for fig in figs:
        gnuplot_fig(R, P, fig)
    from . import summary
    write_text(f"{R}/summary.md", summary.text(F, meth, conv_keys, rt, sp, runs, tmin, tavg, integ, figs, dens, stip))
    print(f"replot: figures and summary.md in {R}", file=sys.stderr)
