"""ttq - the time-to-quality runs of a results folder: one record per run
from its trace (columns iteration, delta_min, delta_avg, ..., elapsed = the
8th) and quality.csv: the seconds at which delta_avg >= 0.929, delta_min >=
0.90, delta_min >= 0.92 and the target (delta_min >= TMIN and delta_avg >=
TAVG) first hold (\"never\" when no row does), the final row, the final set's
quality, and whether it is its configuration's median run (by the time to
the target, never counting as infinite, then by the final elapsed). Writes
plotdata/ttq-runs.tsv, plotdata/ttq-nN.dat (one block per configuration:
its median run's trace) and plotdata/fig-time-to-quality.vars.gp.
"""
from . import methods as M
from . import stats as S
from .common import Failure
from .common import write as write_file

TSV_HEAD = ("# run\tkey\tthreads\tn\tseed\ttime_limit\tstop\tt_avg929\tt_min90\tt_min92\tt_target\tfinal_elapsed\t"
            "final_dmin\tfinal_davg\titerations\tcert_pass\tspike_ratio\tspike_k\tmedian_run\tlattice_ratio")
FIELDS = ("run", "key", "threads", "n", "seed", "time_limit", "stop", "t_avg929", "t_min90", "t_min92", "t_target",
          "final_elapsed", "final_dmin", "final_davg", "iterations", "cert_pass", "spike_ratio", "spike_k",
          "median_run", "lattice_ratio")


def rank(k, t):
    """Configuration order in tables and figures; threads break ties."""
    return {"adaptive": 1, "paper": 3, "fpo": 4, "lfpo": 5}.get(k, 6) * 1000 + int(t)


def inf(x):
    return 1e300 if x == S.NEVER else S.num(x)


def trace_rows(path):
    with open(path) as f:
        rows = [l.rstrip("\n").split("\t") for l in f][1:]
    return rows


def label(meth, k, t):
    return f"{meth.label(k)}, {t} thread" + ("s" if int(t) > 1 else "")


def write(F, meth, P, tmin, tavg):
    quality = {}
    for line in open(f"{F.R}/quality.csv"):
        c = line.rstrip("\n").split(",")
        if c[0] != "run":
            quality[c[0]] = c
    runs = []
    for r in F.rows:
        if r[1] != "ttq":
            continue
        x = dict(run=r[0], key=M.key(r[2], r[3]), threads=r[7], n=r[5], seed=r[6], trace=r[18],
                 time_limit=r[19], stop=r[20], iterations=r[10])
        tr = trace_rows(f"{F.R}/{r[18]}")
        if not tr:
            raise Failure(f"{F.R}/{r[18]}: no trace rows")
        lv = dict(t_avg929=S.NEVER, t_min90=S.NEVER, t_min92=S.NEVER, t_target=S.NEVER)
        for c in tr:
            d, a = S.num(c[1]), S.num(c[2])
            for name, ok in (("t_avg929", a >= 0.929), ("t_min90", d >= 0.90), ("t_min92", d >= 0.92),
                             ("t_target", d >= S.num(tmin) and a >= S.num(tavg))):
                if lv[name] == S.NEVER and ok:
                    lv[name] = c[7]
        x.update(lv, final_elapsed=tr[-1][7], final_dmin=tr[-1][1], final_davg=tr[-1][2])
        q = quality.get(r[0])
        x.update(cert_pass=q[4] if q else "-", spike_ratio=q[7] if q else "-", spike_k=q[8] if q else "-",
                 lattice_ratio=q[9] if q and q[9] != "" else "-", median_run="0", rows=tr)
        runs.append(x)
    confs = {}
    for x in runs:
        confs.setdefault((x["n"], x["key"], x["threads"]), []).append(x)
    for members in confs.values():
        o = sorted(members, key=lambda x: (inf(x["t_target"]), S.num(x["final_elapsed"])))
        o[(len(o) + 1) // 2 - 1]["median_run"] = "1"
    write_lines = [TSV_HEAD] + ["\t".join(x[f] for f in FIELDS) for x in runs]
    write_file(f"{P}/ttq-runs.tsv", write_lines)
    # the figure: panels by n, curves by configuration in rank order
    sizes = sorted({x["n"] for x in runs}, key=S.num)
    np_ = len(sizes)
    vars_ = ["# written by scripts/bench.py replot (ttq.py)",
             f"DIR = '{F.R}'; TMIN = {tmin}; TAVG = {tavg}; NP = {np_}",
             "array PN[%d]; array PS[%d]; array PC[%d]" % ((np_ or 1,) * 3)]
    curves = []
    for p, n in enumerate(sizes, 1):
        med = sorted((x for x in runs if x["n"] == n and x["median_run"] == "1"),
                     key=lambda x: rank(x["key"], x["threads"]))
        parts = []
        for x in med:
            parts.append(f"# {label(meth, x['key'], x['threads'])}, seed {x['seed']}, run {x['run']}\n" + "".join(
                "%s\t%s\t%s\n" % (c[7] if S.num(c[7]) > 0 else "0.0001", c[1], c[2]) for c in x["rows"]))
            curves.append((label(meth, x["key"], x["threads"]), meth.colour(x["key"]), 2 if int(x["threads"]) > 1 else 1))
        with open(f"{P}/ttq-n{n}.dat", "w") as f:
            f.write("# one block per configuration (its median run): elapsed_seconds delta_min delta_avg\n"
                    + "\n\n".join(parts))
        vars_.append(f"PN[{p}] = {n}; PS[{p}] = {len(curves) - len(med) + 1}; PC[{p}] = {len(med)}")
    t = len(curves)
    vars_.append("NCUR = %d; array LBL[%d]; array COL[%d]; array DT[%d]" % (t, t or 1, t or 1, t or 1))
    for a, (l, c, d) in enumerate(curves, 1):
        vars_.append(f"LBL[{a}] = '{l}'; COL[{a}] = '{c}'; DT[{a}] = {d}")
    write_file(f"{P}/fig-time-to-quality.vars.gp", vars_)
    return runs

