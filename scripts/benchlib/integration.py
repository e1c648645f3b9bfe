"""integration - the integration experiment of `make bench`: the exact variance
of the estimate of an integral under a random toroidal shift of the set
(cfpo-analyze's shiftvar_*, analysis/README.md, "Integration variance under
a random shift") against n, per method.

The runs are planned by runner.build_plan (their plan entries carry
integ = (key, n)): the comparison's sets at its n, the runtime runs' sets of
one thread at the profile's int_n, and runs of their own (experiment
`integration`) for the seeds missing. analyse() averages each (method, n)
group with `cfpo-analyze --no-discrepancy` (K = ceil(6 sqrt(n)), at most
2048, the tool's default) into integration.csv and deletes the sets it is
done with; write() turns integration.csv into plotdata/integration.dat and
the figure's variables (fig-integration.gp).
"""
import os
import shutil

from . import methods as M
from . import stats as S
from .common import Failure, write

# cfpo-analyze's integrands (periodised Gaussians of width sigma, disks of radius r)
SHIFTVAR = ("shiftvar_gauss_0.02", "shiftvar_gauss_0.05", "shiftvar_gauss_0.15",
            "shiftvar_disk_0.1", "shiftvar_disk_0.25", "shiftvar_disk_0.4")
# and the low-frequency measures of the same analysis (the mean periodogram of
# the sets), delta_min / delta_avg (means over the sets) and the UTK-style MSEs
LOWFREQ = ("p0", "h_index", "lowk_alpha", "delta_min", "delta_avg", "spike_ratio", "utk_gauss_mse",
           "utk_heaviside_mse")
COLUMNS = "group,method,variant,n,n_target,sets,runs,K,averaged_by," + ",".join(SHIFTVAR + LOWFREQ)
# the two the figure draws
SHOWN = (("shiftvar_disk_0.25", "disk, radius 0.25"), ("shiftvar_gauss_0.05", "Gaussian, σ = 0.05"))


def groups(plan, meth):
    """(key, n) of the integration experiment in the order of methods.tsv, then n."""
    seen = {r["integ"] for r in plan if r.get("integ")}
    order = meth.keys(*M.KINDS)
    return sorted(seen, key=lambda g: (order.index(g[0]), g[1]))


def analyse(bench, plan, rows, keep):
    """integration.csv's lines; the sets of a group are deleted once it is
    analysed unless their name is in keep (the comparison's, which the
    spectra take afterwards)."""
    cells = {int(c[0]): c for c in (r.split(",") for r in rows)}
    out = [COLUMNS]
    gs = groups(plan, bench.meth)
    for g, (key, n) in enumerate(gs, 1):
        name = f"integration-{key}-n{n}"
        bench.progress(len(plan), f"integration analysis {g} of {len(gs)}: {key} n={n}", 1, 1, 0)
        mine = [(i + 1, r["out"]) for i, r in enumerate(plan) if r.get("integ") == (key, n)]
        files = [f"{bench.work}/{o}" for _, o in mine]
        for f in files:
            if not os.path.isfile(f):
                raise Failure(f"no point set {f} for {name}")
        sizes = [int(cells[i][4]) for i, _ in mine]
        anyn = len(set(sizes)) > 1
        a = f"{bench.work}/tmp/an-{name}"
        f = bench.analyze(["-q", "--no-discrepancy"] + (["--any-n"] if anyn else []) + ["-o", a] + files, name)
        shutil.rmtree(a)
        for path, (_, o) in zip(files, mine):
            if o not in keep:
                os.remove(path)
        nval = "%.1f" % (sum(sizes) / len(sizes)) if anyn else f.get("n", "")
        out.append(",".join([name, bench.meth.get(key, "method"), bench.meth.get(key, "variant"), nval, str(n),
                             f.get("sets", ""), S.ranges([i for i, _ in mine], ";"), f.get("K", ""),
                             "cfpo-analyze --no-discrepancy" + (" --any-n" if anyn else "")]
                            + [f.get(k, "") for k in SHIFTVAR + LOWFREQ]))
    return out


def read(R):
    """integration.csv of a results folder as dicts; [] when the folder has none."""
    path = f"{R}/integration.csv"
    if not os.path.isfile(path):
        return []
    lines = [l.rstrip("\n").split(",") for l in open(path)]
    head = lines[0]
    return [dict(zip(head, c)) for c in lines[1:]]


def write_figure(R, meth, rows, written):
    """plotdata/integration.dat (one block per method: n, then the SHOWN
    variances) and fig-integration.vars.gp; False when there is nothing to draw."""
    keys = [k for k in meth.keys(*M.KINDS) if any(M.key(r["method"], r["variant"]) == k for r in rows)]
    if not keys:
        return False
    parts = []
    for k in keys:
        mine = sorted((r for r in rows if M.key(r["method"], r["variant"]) == k), key=lambda r: S.num(r["n"]))
        parts.append("".join("%s\t%s\n" % (r["n"], "\t".join(r[v] for v, _ in SHOWN)) for r in mine))
    tmp = f"{R}/plotdata/integration.dat.tmp.{os.getpid()}"
    with open(tmp, "w") as f:
        f.write("# one block per method: n (mean of the sets) " + " ".join(v for v, _ in SHOWN)
                + " (mean over the sets, integration.csv)\n" + "\n\n".join(parts))
    os.rename(tmp, f"{R}/plotdata/integration.dat")
    ns = [S.num(r["n"]) for r in rows]
    lines = [written, f"DIR = '{R}'; NMIN = {min(ns):g}; NMAX = {max(ns):g}",
             "array TTL[%d]; array COLN[%d]" % (len(SHOWN), len(SHOWN))]
    for i, (v, t) in enumerate(SHOWN, 1):
        lines.append(f"TTL[{i}] = '{t}'; COLN[{i}] = {i + 1}")
    lines.append(f"NM = {len(keys)}; array LBL[{len(keys)}]; array COL[{len(keys)}]; array PT[{len(keys)}]")
    for i, k in enumerate(keys, 1):
        lines.append(f"LBL[{i}] = '{meth.label(k)}'; COL[{i}] = '{meth.colour(k)}'; PT[{i}] = {meth.pt(k)}")
    write(f"{R}/plotdata/fig-integration.vars.gp", lines)
    return True
