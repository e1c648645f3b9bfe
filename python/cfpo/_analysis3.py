"""The 3-D measures behind cfpo.analysis for (n, 3) sets on the unit
3-torus: the numbers of cfpo3d-analyze (docs/cli.md) from the same C
functions (src/d3/nn3.h, q6.h, measures3_*.h), for one set. Distances are
over Delta3(n) = (sqrt(2) / n)^(1/3), the FCC bound (FCC scores 1).
cfpo.analysis's functions call these when given an (n, 3) array."""
import math
from dataclasses import dataclass, field

import numpy as np

from . import _args
from . import _core

NEIGHBOURS = 12  # cfpo3d-analyze --neighbours
BOND = 0.7       # --bond
BONDS = 8        # --bonds
KMAX3 = 128      # src/d3/measures3_spec.h CFPO3_SPEC_KMAX
PCF3_DR = 0.02   # cfpo3d-analyze --pcf: bins of r / Delta3(n)
PCF3_RMAX = 3.0


def delta3(n):
    """Delta3(n) = (sqrt(2) / n)^(1/3): the nearest-neighbour distance of
    n points on the FCC lattice filling the unit cube."""
    return (math.sqrt(2) / n) ** (1 / 3)


def points(p, min_n=1):
    return _args.as_points(p, min_n=min_n, dim=3)


def deltas(p, deltas_type):
    """delta_min, delta_avg over Delta3(n) and each point's nearest-neighbour
    distance (box units); no histogram (hist None)."""
    a = points(p, 2)
    dmin, davg, nn = _core.deltas3(a)
    return deltas_type(dmin, davg, nn, None)


@dataclass
class BondOrder:
    """Steinhardt's bond order over each point's `neighbours` nearest
    (periodic): q6_global (Q6; FCC 0.5745 with 12, BCC 0.5107 with 14,
    simple cubic 0.3536 with 6), q6_local (the mean of each point's q6),
    crystal_like (points with at least `bonds` neighbours whose normalised
    q6 product exceeds `bond`: ten Wolde, Ruiz-Montero and Frenkel 1996) and
    crystal_fraction; w6, w6_local: the third-order invariant W6 (FCC
    -0.013161, BCC and SC +0.013161). cfpo3d-analyze's q6_global= q6_local=
    crystal_like= crystal_fraction= w6= w6_local=."""
    q6_global: float
    q6_local: float
    crystal_like: int
    crystal_fraction: float
    w6: float
    w6_local: float
    neighbours: int
    bond: float
    bonds: int


def bond_order(p, neighbours=NEIGHBOURS, bond=BOND, bonds=BONDS):
    k = _args.whole("neighbours", neighbours, 1, 64)
    c = _args.real("bond", bond, 0, 1)
    b = _args.whole("bonds", bonds, 0, 64)
    a = points(p)
    if a.shape[0] <= k:
        raise ValueError(f"points: {a.shape[0]} points: more than neighbours = {k} are needed")
    return BondOrder(*_core.bond_order3(a, k, c, b), k, c, b)


@dataclass
class Spectrum3:
    """The 3-D periodogram P(k) = |sum_j exp(-2 pi i k.x_j)|^2 / n for k in
    [-K, K]^3, power[kz + K, ky + K, kx + K]; shell, shell_count: its mean
    and frequency count over each shell |k| in [s - 1/2, s + 1/2), s =
    0..K (shell[0] is P(0) = n); p0 (and p0_count): the mean of P over
    0 < |k| <= 0.2 n^(1/3) (nan when the box does not hold that band);
    peak, peak_shell: the highest shell of 1..K. cfpo3d-analyze --spectrum's
    file and p0= peak= peak_shell= kmax=."""
    K: int
    power: np.ndarray = field(repr=False)
    shell: np.ndarray = field(repr=False)
    shell_count: np.ndarray = field(repr=False)
    p0: float = math.nan
    p0_count: int = 0
    peak: float = math.nan
    peak_shell: int = 0


def spectrum(p, K=None, exact=False):
    a = points(p)
    k = 0 if K is None else _args.whole("K", K, 1, KMAX3)
    P, sh, cnt, p0, c0, peak, peak_shell, k = _core.spectrum3(a, k, _args.flag("exact", exact))
    return Spectrum3(k, P, sh, cnt, p0, c0, peak, peak_shell)


def pcf(p, rmax=None, dr=None):
    """(r, g): g(r) in bins of dr (default 0.02) of r / Delta3(n) from 0 up
    to rmax (default 3, lowered by dr until rmax Delta3(n) < 1/2), r the
    bin centres; pair counts over the Poisson expectation n (n - 1) / 2
    times the shell volume. cfpo3d-analyze --pcf's file."""
    a = points(p, 2)
    r = PCF3_RMAX if rmax is None else _args.real("rmax", rmax, 0.1, 100)
    d = PCF3_DR if dr is None else _args.real("dr", dr, 0.001, 1)
    g = _core.pcf3(a, r, d)
    return ((np.arange(g.shape[0]) + 0.5) * d, g)


@dataclass
class Structure3:
    """The Voronoi cells of a set from CGAL's periodic 3-D Delaunay
    triangulation: faces_mean and faces_sd (faces per cell; zero-area faces
    of co-spherical points not counted), volume_var (the variance of n V,
    V a cell's volume); faces and volumes per point (the volumes sum to 1).
    cfpo3d-analyze --voronoi's vor_faces= vor_faces_sd= vor_volume_var=."""
    faces_mean: float
    faces_sd: float
    volume_var: float
    faces: np.ndarray = field(repr=False)
    volumes: np.ndarray = field(repr=False)


def structure(p):
    a = points(p)
    faces, vol, mf, sf, vv = _core.voronoi3(a)
    return Structure3(mf, sf, vv, faces, vol)


@dataclass
class Certificate3:
    """The 3-D farthest-point certificate (src/d3/measures3_fpd.h): fpd
    when every point passes (none can be moved farther from the rest;
    relative tolerance 1e-9), passed (points that pass), max_violation
    (max over points of (R_i - d_i) / Delta3(n), <= 0 when all pass).
    cfpo3d-analyze --certify's fpd_pass= fpd_points= fpd_max_violation=.
    violation: each point's (R_i - d_i) / Delta3(n) ((n,) float64, in
    the points' order; a point passes when R_i <= d_i (1 + 1e-9), so the
    points with violation > 1e-9 fail)."""
    fpd: bool
    passed: int
    max_violation: float
    violation: np.ndarray = field(repr=False, default=None)


def certify(p):
    a = points(p, 2)
    passed, viol, each = _core.certify3(a)
    return Certificate3(passed == a.shape[0], passed, viol, each)
