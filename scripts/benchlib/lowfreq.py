"""lowfreq - the figures' data of the comparison's measures of sampling
research (analysis/README.md): the low-frequency RAPS panel
(fig-lowfreq.gp: the averaged RAPS of every method for |k| < 1.2 sqrt(n),
log y) and the pair correlation g(r) (fig-pcf.gp: a panel per method, drawn
only where the averaged analyses hold a pcf.txt), and the rows of the
low-frequency table of summary.md, read from spectra.csv.
"""
import os

from . import methods as M
from .common import write

# spectra.csv columns of the low-frequency table, after the 19 of the
# earlier folders: (column, heading)
TABLE = (("p0", "P0"), ("h_index", "H"), ("lowk_alpha", "α"), ("disc_wrap_l2", "wrap-around L2"),
         ("disc_diaphony", "diaphony"), ("disc_l2_star", "L2-star"), ("disc_gen_l2", "generalised L2"),
         ("disc_centred_l2", "centred L2"), ("shiftvar_disk_0.1", "Var disk r=0.1"),
         ("shiftvar_disk_0.25", "Var disk r=0.25"), ("shiftvar_disk_0.4", "Var disk r=0.4"),
         ("shiftvar_gauss_0.02", "Var Gauss σ=0.02"), ("shiftvar_gauss_0.05", "Var Gauss σ=0.05"),
         ("shiftvar_gauss_0.15", "Var Gauss σ=0.15"))


def comparison_groups(F, meth):
    """(key, group) of the comparison's averaged analyses, in the order of methods.tsv."""
    have = {s[0] for s in F.spectra}
    return [(k, M.group("comparison", k, have)) for k in meth.keys(*M.KINDS) if M.group("comparison", k, have) in have]


def table_rows(F, meth):
    """(key, group, {column: text}) for the low-frequency table; [] for a
    folder whose spectra.csv lacks the columns (written before them)."""
    head = [l.rstrip("\n").split(",") for l in open(f"{F.R}/spectra.csv")][0]
    if any(c not in head for c, _ in TABLE):
        return []
    idx = {c: head.index(c) for c, _ in TABLE}
    spec = {s[0]: s for s in F.spectra}
    return [(k, g, {c: spec[g][i] for c, i in idx.items()}) for k, g in comparison_groups(F, meth)]


def write_lowfreq(F, meth, written, N):
    gs = comparison_groups(F, meth)
    lines = [written, f"DIR = '{F.R}'; N = {N}; SETS = {F.planv('SETS')}",
             f"NM = {len(gs)}; array GRP[{len(gs)}]; array LBL[{len(gs)}]; array COL[{len(gs)}]; array DT[{len(gs)}]"]
    for i, (k, g) in enumerate(gs, 1):
        # the Poisson-disk and direct samplers dashed, the optimisers solid
        lines.append(f"GRP[{i}] = '{g}'; LBL[{i}] = '{meth.label(k)}'; COL[{i}] = '{meth.colour(k)}'; "
                     f"DT[{i}] = {2 if meth.kind(k) in M.ONE_PASS else 1}")
    write(f"{F.R}/plotdata/fig-lowfreq.vars.gp", lines)


def write_pcf(F, meth, written, N):
    """fig-pcf.vars.gp when some comparison group has data/analysis/GROUP/pcf.txt;
    False (and nothing written) when none has."""
    gs = [(k, g) for k, g in comparison_groups(F, meth) if os.path.isfile(f"{F.R}/data/analysis/{g}/pcf.txt")]
    if not gs:
        return False
    lines = [written, f"DIR = '{F.R}'; N = {N}; SETS = {F.planv('SETS')}",
             f"NM = {len(gs)}; array GRP[{len(gs)}]; array LBL[{len(gs)}]; array COL[{len(gs)}]"]
    for i, (k, g) in enumerate(gs, 1):
        lines.append(f"GRP[{i}] = '{g}'; LBL[{i}] = '{meth.label(k)}'; COL[{i}] = '{meth.colour(k)}'")
    write(f"{F.R}/plotdata/fig-pcf.vars.gp", lines)
    return True
