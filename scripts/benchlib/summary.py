"""summary - summary.md of a results folder: every number computed from
runs.csv, spectra.csv and the figures' tables (plotdata: runtime, speedup,
time-to-quality runs), every table naming the rows of runs.csv (column
`run`) and the groups of spectra.csv it comes from."""
import math

from . import methods as M
from . import stats as S
from .ttq import rank

LEVELS = ("t_avg929", "t_min90", "t_min92", "t_target")


def pm(v, d):
    return "%.*f ± %.*f" % (d, S.mean(v), d, S.sd(v))


def pmsig(v):
    """mean ± sd with three significant digits of the mean."""
    m = S.mean(v)
    d = 2 - int(math.log(m) / math.log(10) + (-0.999999 if m < 1 else 0)) if m > 0 else 3
    d = max(d, 0)
    return "%.*f ± %.*f" % (d, m, d, S.sd(v))


def f3(x):
    return "-" if x in ("-", "", None) else "%.3f" % S.num(x)


def f2(x):
    return "-" if x in ("-", "", None) else "%.2f" % S.num(x)


def tcell(v):
    m = S.median_never(v)
    c = sum(1 for x in v if x != S.NEVER)
    return (S.NEVER if m == S.NEVER else S.secs(m)) + (f" ({c} of {len(v)})" if 0 < c < len(v) else "")


INTRO = """Written by `scripts/bench.py run` (`make bench`), redrawn by `scripts/bench.py replot` (`make replot`).
Every number below is computed from `runs.csv` (one row per run; "rows" name its `run` column)
and `spectra.csv` (one row per averaged spectrum, named by its `group` column, which lists the
runs whose point sets it averages). Machine and build (the header of `runs.csv`):
"""
COMPARISON_NOTE = """δ_min / Δ(n), δ_avg / Δ(n): the smallest and the mean nearest-neighbour distance over the
hexagonal bound Δ(n) = sqrt(2 / (√3 n)), as each run reported them; mean ± sample standard
deviation over the sets (columns `delta_min`, `delta_avg` of the rows). Effective Nyquist
(r_01 / √n, higher: less aliasing) and oscillation (10 × RMS deviation of the RAPS from 1 beyond
its first crossing of 0.98; lower: flatter) are those of the power spectrum averaged over the
sets (spectra.csv, analysis/README.md for the definitions). Spike ratio: the largest P(k) over
the mean of its ring, as the mean of the per-set values (white noise: 10-15) / of the averaged
spectrum (white noise averaged over 10 sets: about 3); a lattice imprint stands far above both.
Iterations and seconds: mean ±
standard deviation; seconds is the tool's sampling time (until converged for the iterative
methods); time / FPO's = mean seconds over FPO's mean seconds, same n and one thread each
(column `threads`); runs with one runs.csv `batch` number started together, each pinned to its own
core (successive seeds of one method, `COMP_TOGETHER` of the profile), so their seconds include a
neighbour's use of the memory system. BS and Bridson produce maximal sets whose size varies a little with the seed
(column `n`); `cfpo-analyze --any-n` averages their spectra (spectra.csv column
`averaged_by`; n of the frequency scale: the sets' mean), the others plain `cfpo-analyze`.
"""
TTQ_NOTE = """Every iterative method, run with `--trace` until δ_min ≥ %s and δ_avg ≥ %s both hold (the
target: the run's `--target-min`/`--target-avg`), it converges (cfpo's rule and tolerance) or its
`--time-limit` passes (column `time_limit` of runs.csv). One-thread runs that are compared started
together, one per core (runs.csv column `batch`); runs on several threads ran alone. Seconds: the
trace's `elapsed` column (wall clock from the start of the run, the start included) at the first
iteration where the level holds; median over the seeds, "never" when the median run did not get
there ("k of m": the seeds that did). Final δ: the last trace row. Certificate pass: the fraction
of the final set's points that are farthest points of the rest (`cfpo-analyze --certify`); spike
ratio: the largest P(k) over its ring's mean for the final set (white noise: 10-15; a lattice
imprint: far more); lattice ratio: the largest P(k) over its ring's mean at the axis frequencies of
cfpo's grid for n (white noise: below 5 in most sets; a trace of the grid: more), all from
`quality.csv`, medians. FPO / this: FPO's median seconds over this
row's at each level, same n (above 1: this row is faster); "≥ x" where FPO's median run did not
get there before it stopped (its time limit): FPO's median seconds to the level or to its stop
over this row's, a lower bound; - where this row never got there.
Per run: `plotdata/ttq-runs.tsv`."""


LOWFREQ_NOTE = """The measures of sampling research ([analysis/README.md](../../analysis/README.md#measures-of-sampling-research-measures),
"Measures of sampling research"), from the analysis that averages the sets of each method (spectra.csv,
the columns of the same names; discrepancies and variances: the mean of the per-set values), n as above:

- **P0** (`p0`): the mean of P(k) over 0 < |k| ≤ 0.2 √n, the low-frequency floor (white noise 1).
- **H** (`h_index`): the hyperuniformity index, the intercept at k = 0 of the least-squares line
  through the RAPS of the rings up to 0.2 √n over the RAPS at its first peak (effectively
  hyperuniform: H ≤ 1e-3; negative for a k² spectrum such as jittered's).
- **α** (`lowk_alpha`): the least-squares slope of log RAPS against log |k| over the same rings
  (0: a flat floor; 2: a k² spectrum).
- **wrap-around L2, diaphony, L2-star, generalised L2, centred L2** (`disc_*`): the L2
  discrepancies, each the square root of its squared form (Hickernell 1998; Zinterhof 1976;
  Warnock 1972); the first two torus-invariant.
- **Var disk r, Var Gauss σ** (`shiftvar_*`): the exact variance of the estimate
  (1/n) Σ f(x_j + s) of the integral of f under a uniformly random toroidal shift s,
  (1/n) Σ_{k ≠ 0} |f̂(k)|² P(k), for f the indicator of a disk of radius r and the periodised
  Gaussian of width σ.
"""
INTEGRATION_NOTE = """The exact variance under a random toroidal shift (the last columns above) at each n of the
integration experiment (integration.csv, one row per method and n: the analysis of its sets with
`cfpo-analyze --no-discrepancy`, the mean of the per-set variances; the sets: the comparison's at
its n, one-thread runtime runs, and runs of experiment `integration` for the seeds missing).
Slope: the least-squares slope of log variance against log n over the rows of the method
(white noise: -1; a flat low-frequency floor keeps it near -1; the disk's discontinuity bounds a
blue-noise set's at about -1.5)."""


def slope(xs, ys):
    """Least-squares slope of log y against log x ('-' for fewer than 2 points or y <= 0)."""
    pts = [(math.log(x), math.log(y)) for x, y in zip(xs, ys) if x > 0 and y > 0]
    if len(pts) < 2 or len({x for x, _ in pts}) < 2:
        return "-"
    mx = sum(x for x, _ in pts) / len(pts)
    my = sum(y for _, y in pts) / len(pts)
    return "%.2f" % (sum((x - mx) * (y - my) for x, y in pts) / sum((x - mx) ** 2 for x, _ in pts))


def g3(x):
    return "-" if x in ("-", "", None) or x.lower() == "nan" else "%.3g" % S.num(x)


def lowfreq_section(p, F, meth, N):
    from .lowfreq import TABLE, table_rows
    rows = table_rows(F, meth)
    if not rows:
        return
    p("## Low-frequency spectrum, discrepancies and integration variance at n = %s\n" % N)
    p("| method | " + " | ".join(h for _, h in TABLE) + " | spectra.csv group |")
    p("| --- |" + " --- |" * (len(TABLE) + 1))
    for k, g, v in rows:
        p("| %s | %s | `%s` |" % (meth.label(k), " | ".join(g3(v[c]) for c, _ in TABLE), g))
    p("")
    p(LOWFREQ_NOTE)
    p("![low-frequency RAPS](fig-lowfreq.png)\n")


def integration_section(p, meth, integ):
    from .integration import SHOWN
    p("## Integration error against n\n")
    p(INTEGRATION_NOTE + "\n")
    p("| method | n | sets | runs.csv rows | " + " | ".join("Var " + t for _, t in SHOWN) + " | integration.csv group |")
    p("| --- | --- | --- | --- |" + " --- |" * len(SHOWN) + " --- |")
    slopes = []
    for k in meth.keys(*M.KINDS):
        mine = sorted((r for r in integ if M.key(r["method"], r["variant"]) == k), key=lambda r: S.num(r["n"]))
        if not mine:
            continue
        for r in mine:
            p("| %s | %s | %s | %s | %s | `%s` |" % (meth.label(k), r["n"], r["sets"], r["runs"].replace(";", ", "),
                                                  " | ".join(g3(r[v]) for v, _ in SHOWN), r["group"]))
        slopes.append((k, [slope([S.num(r["n"]) for r in mine], [S.num(r[v]) for r in mine]) for v, _ in SHOWN]))
    p("")
    p("| method | " + " | ".join("slope, " + t for _, t in SHOWN) + " |")
    p("| --- |" + " --- |" * len(SHOWN))
    for k, sl in slopes:
        p("| %s | %s |" % (meth.label(k), " | ".join(sl)))
    p("")
    p("![integration](fig-integration.png)\n")
    lowfreq_by_n(p, meth, integ)


LOWFREQ_BY_N = (("delta_min", "δ_min", "%.4f"), ("delta_avg", "δ_avg", "%.4f"), ("p0", "P0", None),
                ("h_index", "H", None), ("lowk_alpha", "α", "%.2f"), ("spike_ratio", "spike ratio", "%.1f"),
                ("utk_gauss_mse", "UTK Gaussian MSE", None), ("utk_heaviside_mse", "UTK Heaviside MSE", None))


def lowfreq_by_n(p, meth, integ):
    """The low-frequency measures of each (method, n) of integration.csv; nothing
    for a folder written before integration.csv had them."""
    rows = [r for r in integ if r.get("p0") not in (None, "")]
    if not rows:
        return
    p("## Low-frequency measures per method and n\n")
    p("One `cfpo-analyze --no-discrepancy` of each (method, n) group's sets (integration.csv): P0, H and α")
    p("of their mean periodogram, δ_min / δ_avg and the UTK-style MSEs means over the sets.\n")
    p("| method | n | sets | " + " | ".join(h for _, h, _ in LOWFREQ_BY_N) + " |")
    p("| --- | --- | --- |" + " --- |" * len(LOWFREQ_BY_N))
    for k in meth.keys(*M.KINDS):
        for r in sorted((r for r in rows if M.key(r["method"], r["variant"]) == k), key=lambda r: S.num(r["n"])):
            cells = [g3(r[c]) if f is None or r[c] in ("", "-") else f % S.num(r[c]) for c, _, f in LOWFREQ_BY_N]
            p("| %s | %s | %s | %s |" % (meth.label(k), r["n"], r["sets"], " | ".join(cells)))
    p("")


def text(F, meth, conv_keys, rt, sp, runs, tmin, tavg, integ=(), figs=(), dens=(), stip=()):
    out = []
    p = out.append
    host = prof = ""
    hdr = []
    for l in F.head:
        if not l.startswith("# "):
            continue
        hdr.append(l[2:])
        if l.startswith("# host: "):
            host = l[len("# host: "):].split(";")[0]
        if "profile " in l:
            prof = l.split("profile ")[-1].split(",")[0]
    comp, evo = {}, {}
    for r in F.rows:
        if r[1] == "comparison":
            comp.setdefault(M.key(r[2], r[3]), []).append(r)
        if r[1] == "evolution":
            evo.setdefault(r[9], []).append(r)
    spec = {s[0]: s for s in F.spectra}
    paper = M.group("comparison", "paper", spec)

    def spk(g):
        s = spec.get(g)
        if not s or s[18] in ("-", ""):
            return "-"
        return "%.1f / %.1f" % (S.num(s[18]), S.num("" if s[16] == "-" else s[16]))

    N = comp["paper"][0][4] if "paper" in comp else next((rs[0][4] for rs in comp.values()), "")
    p(f"# Method comparison on {host} (profile {prof})\n")
    p(INTRO)
    p("```")
    out.extend(h for h in hdr if not h.startswith("columns:"))
    p("```\n")
    fpo = S.mean([r[11] for r in comp["fpo"]]) if "fpo" in comp else 0
    nsets = len(comp.get("paper", next(iter(comp.values()), [])))
    fewer = ", ".join("%s %d" % (meth.label(k), len(rs)) for k, rs in comp.items() if len(rs) != nsets)
    p("## Quality and cost at n = %s, %d sets per method%s\n" % (N, nsets, f" (fewer: {fewer})" if fewer else ""))
    p("| method | runs.csv rows | δ_min / Δ(n) | δ_avg / Δ(n) | eff. Nyquist | oscillation | spike ratio (sets / average) "
      "| iterations | converged | seconds | time / FPO's | threads | peak MB | spectra.csv group |")
    p("| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |")
    for k, rs in comp.items():
        g = M.group("comparison", k, spec)
        its = [r[10] for r in rs if r[10] != "-"]
        it = "%.0f ± %.0f" % (S.mean(its), S.sd(its)) if its else "-"
        cv = "%d of %d" % (sum(1 for r in rs if r[16] == "yes"), len(rs)) if its else "-"
        ratio = "%.3f" % (S.mean([r[11] for r in rs]) / fpo) if fpo > 0 else "-"
        s = spec.get(g)
        p("| %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %.1f | `%s` |" % (
            meth.label(k), S.ranges([r[0] for r in rs]), pm([r[13] for r in rs], 4), pm([r[14] for r in rs], 4),
            f3(s[13]) if s else "-", f2(s[14]) if s else "-", spk(g), it, cv, pmsig([r[11] for r in rs]), ratio,
            rs[-1][7], S.mean([r[15] for r in rs]) / 1048576, g))
    p("")
    p(COMPARISON_NOTE)
    p("![comparison](fig-comparison.png)\n")
    lowfreq_section(p, F, meth, N)
    if "pcf" in figs:
        p("Pair correlation g(r) of the comparison's averaged analyses (`data/analysis/*/pcf.txt`):\n")
        p("![pair correlation](fig-pcf.png)\n")
    p("![convergence](fig-convergence.png)\n")
    if conv_keys:
        p("Convergence: the traces of rows" + ";".join(
            " %s (%s)" % (S.ranges([r[0] for r in comp.get(k, [])]), meth.label(k)) for k in conv_keys)
          + "; plotted as `plotdata/convergence-*.dat`.\n")
    if evo:
        p("## Evolution of CFPO\n")
        p("| iteration | runs.csv rows | δ_min / Δ(n) | δ_avg / Δ(n) | eff. Nyquist | oscillation | spike ratio (sets / average) "
          "| spectra.csv group |")
        p("| --- | --- | --- | --- | --- | --- | --- | --- |")
        for ev, rs in evo.items():
            g = "evolution-it" + ev
            s = spec.get(g)
            p("| %s | %s | %s | %s | %s | %s | %s | `%s` |" % (
                ev, S.ranges([r[0] for r in rs]), pm([r[13] for r in rs], 4), pm([r[14] for r in rs], 4),
                f3(s[13]) if s else "-", f2(s[14]) if s else "-", spk(g), g))
        if "paper" in comp:
            rs, s = comp["paper"], spec.get(paper)
            p("| converged | %s | %s | %s | %s | %s | %s | `%s` |" % (
                S.ranges([r[0] for r in rs]), pm([r[13] for r in rs], 4), pm([r[14] for r in rs], 4),
                f3(s[13] if s else ""), f2(s[14] if s else ""), spk(paper), paper))
        p("")
        p("![evolution](fig-evolution.png)\n")
    p("## Runtime\n")
    p("Median over seeds of every uncapped run (experiments `comparison` and `runtime`), per method,")
    p("threads, ranks and n (`plotdata/runtime.tsv`).\n")
    p("| method | threads | ranks | n | runs | seconds (median) | seconds per iteration | iterations | runs.csv rows |")
    p("| --- | --- | --- | --- | --- | --- | --- | --- | --- |")
    for k in meth.keys(*M.KINDS):
        for a in rt:
            if a[0] == k:
                p("| %s | %s | %s | %s | %s | %s | %s | %s | %s |" % (
                    meth.label(k), a[1], a[2], a[3], a[6], S.secs(a[4]), "-" if a[5] == "-" else "%.3g" % S.num(a[5]),
                    a[7], S.ranges(a[8].split())))
    p("")
    p("![runtime](fig-runtime.png)\n")
    if "speedup" in figs:
        speedup_section(p, meth, sp)
    if integ:
        p("")
        integration_section(p, meth, integ)
    if runs:
        ttq_section(p, meth, runs, tmin, tavg)
    if dens:
        from .density import section
        section(p, meth, dens)
    if "stipple" in figs:
        from .stipple import section
        section(p, stip)
    if "3d" in figs:
        from .d3 import section
        section(p, F.R)
    if "progressive-prefixes" in figs:
        from .progressive import section
        section(p, F.R)
    return "\n".join(out) + "\n"


def speedup_section(p, meth, sp):
    p("## Speedup\n")
    p("Median time on 1 thread and 1 rank over the median time of the configuration, same method, n")
    p("and seeds (`plotdata/speedup.tsv`; on 2 cores this is 1 against 2 threads).\n")
    p("| method | n | threads | ranks | speedup | runs.csv rows (1 thread \\| this configuration) |")
    p("| --- | --- | --- | --- | --- | --- |")
    for a in sp:
        if a[4] == "1":
            continue
        b = a[6].split("|")
        p("| %s | %s | %s | %s | %.2f | %s \\| %s |" % (meth.label(a[0]), a[1], a[2], a[3], S.num(a[5]),
                                                        S.ranges(b[0].split()), S.ranges(b[1].split())))
    p("")
    p("![speedup](fig-speedup.png)")


def ttq_section(p, meth, runs, tmin, tavg):
    p("")
    p("## Time to quality")
    p("")
    p(TTQ_NOTE % (tmin, tavg))
    confs = {}
    for x in runs:
        confs.setdefault((x["n"], x["key"], x["threads"]), []).append(x)
    order = sorted(confs, key=lambda c: S.num(c[0]) * 1e6 + rank(c[1], c[2]))
    for n in sorted({c[0] for c in confs}, key=S.num):
        p("")
        p("### n = %s (time limit %s s)\n" % (n, [x for x in runs if x["n"] == n][-1]["time_limit"]))
        p("| method | threads | runs.csv rows | δ_avg ≥ 0.929 (s) | δ_min ≥ 0.90 (s) | δ_min ≥ 0.92 (s) | target (s) | stopped by "
          "| final δ_min | final δ_avg | certificate pass | spike ratio | lattice ratio | FPO / this: δ_avg ≥ 0.929 "
          "| δ_min ≥ 0.90 | δ_min ≥ 0.92 | target |")
        p("| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |")
        fpo = confs.get((n, "fpo", "1"))
        for c in order:
            if c[0] != n:
                continue
            xs, k = confs[c], c[1]
            st = ", ".join("%s %d" % (s, sum(1 for x in xs if x["stop"] == s))
                           for s in ("target", "converged", "time", "max-iter") if any(x["stop"] == s for x in xs))
            cp = [x["cert_pass"] for x in xs if x["cert_pass"] != "-"]
            sr = [x["spike_ratio"] for x in xs if x["spike_ratio"] != "-"]
            lr = [x["lattice_ratio"] for x in xs if x["lattice_ratio"] not in ("", "-")]
            cells = [meth.label(k), c[2], S.ranges([x["run"] for x in xs])] + [tcell([x[l] for x in xs]) for l in LEVELS]
            cells += [st, "%.4f" % S.median([x["final_dmin"] for x in xs]), "%.4f" % S.median([x["final_davg"] for x in xs]),
                      "%.4f" % S.median(cp) if cp else "-", "%.1f" % S.median(sr) if sr else "-",
                      "%.1f" % S.median(lr) if lr else "-"]
            for l in LEVELS:
                cc = S.median_never([x[l] for x in xs])
                fc = S.median_never([x[l] for x in fpo]) if fpo else S.NEVER
                if k not in ("adaptive", "paper") or cc == S.NEVER or cc <= 0:
                    cells.append("-")
                elif fc != S.NEVER:
                    cells.append("%.2f" % (fc / cc))
                elif fpo and all(x["stop"] == "time" or x[l] != S.NEVER for x in fpo):
                    # FPO stopped by its time limit before the level: the seconds
                    # it ran (or reached the level in) bound its time from below
                    lo = S.median([x[l] if x[l] != S.NEVER else x["final_elapsed"] for x in fpo])
                    cells.append("≥ %.2f" % (lo / cc))
                else:
                    cells.append("-")
            p("| " + " | ".join(cells) + " |")
    p("")
    p("![time to quality](fig-time-to-quality.png)")
