"""Analysis of point sets on the unit torus: the numbers of cfpo-analyze.

Every function takes points as an (n, 2) array in [0, 1)^2. deltas,
spectrum, pcf, structure and certify also take an (n, 3) array in
[0, 1)^3 and then give cfpo3d-analyze's numbers (the 3-D measures,
cfpo._analysis3); bond_order (Q6, W6, crystal-like points) is 3-D only. Any real
numeric dtype and any memory layout is accepted and converted to a
C-contiguous float64 array (one copy only when needed); complex, boolean,
object and string arrays raise TypeError saying how to convert. Wrong
shapes, NaN/inf, points outside [0, 1) and too few points raise ValueError.
The GIL is released during the computation.
"""
import math
from dataclasses import dataclass, field

import numpy as np

from . import _analysis3
from . import _args
from . import _core

CERT_TOL = 1e-3  # analysis/certify.h AN_CERT_TOL
KMAX = 4096      # analysis/power.h AN_KMAX


def _is3(points):
    """True for an (n, 3) set (the 3-D measures); ValueError for (n, d)
    with d other than 2 and 3."""
    try:
        shape = np.shape(points)
    except (ValueError, TypeError):
        return False  # as_points says why
    if len(shape) == 2 and shape[1] not in (2, 3):
        raise ValueError(f"points: expected an (n, 2) or (n, 3) array of points, got shape {shape}")
    return len(shape) == 2 and shape[1] == 3


def _not_in_3d(**given):
    """ValueError when a 2-D-only argument is given for an (n, 3) set."""
    for k, v in given.items():
        if v is not None:
            raise ValueError(f"{k}: does not apply to a 3-D set (n, 3)")


@dataclass
class Deltas:
    """delta_min, delta_avg: the smallest and the mean nearest-neighbour
    distance over Delta(n) = sqrt(2 / (sqrt(3) n)); nn: each point's
    nearest-neighbour distance (not normalised); hist: the counts of
    nn / Delta(n) in 200 bins of 0.01 (cfpo-analyze's nn_hist.txt). For an
    (n, 3) set: over Delta3(n) = (sqrt(2) / n)^(1/3), and hist is None
    (cfpo3d-analyze's delta_min= delta_avg=)."""
    delta_min: float
    delta_avg: float
    nn: np.ndarray = field(repr=False)
    hist: np.ndarray = field(repr=False)


def deltas(points):
    """Nearest-neighbour statistics of a set of at least 2 points (Deltas)."""
    if _is3(points):
        return _analysis3.deltas(points, Deltas)
    a = _args.as_points(points, min_n=2)
    return Deltas(*_core.deltas(a))


@dataclass
class Spectrum:
    """The periodogram and its measures (cfpo-analyze's stats.json).

    power: P(k) for k in [-K, K]^2, power[ky + K, kx + K]; K; ring_count,
    raps (radially averaged power spectrum, raps[0] unused), anisotropy_db:
    per integer ring |k| in 0..K; spike_ratio, spike_k (kx, ky), spike_ring,
    spike_P, spike_ring_mean: the largest P(k) over the mean of its ring;
    raps_peak_ring, raps_peak; effective_nyquist (r_01 / sqrt(n)), r_01,
    r_half; oscillation (with its rings and whether they were clipped by K);
    nufft: (kernel width, grid, beta) or None for the exact sum;
    lattice_ratio, lattice_k, lattice_g, lattice_period: the largest P(k)
    over its ring's mean at the axis frequencies j g / p of a grid of g
    cells (cfpo-analyze --grid; nan when none counts); p0, h_index,
    lowk_alpha: the low-frequency measures (analysis/README.md; details in
    low_frequency); shift_variance: {integrand: (variance, tail)}, the exact
    integration variance under a random toroidal shift and its part from
    beyond the box, for the integrands gauss_0.02 ... disk_0.4."""
    K: int
    power: np.ndarray = field(repr=False)
    ring_count: np.ndarray = field(repr=False)
    raps: np.ndarray = field(repr=False)
    anisotropy_db: np.ndarray = field(repr=False)
    spike_ratio: float = math.nan
    spike_P: float = math.nan
    spike_k: tuple = (0, 0)
    spike_ring: int = 0
    spike_ring_mean: float = math.nan
    raps_peak_ring: int = 0
    raps_peak: float = math.nan
    effective_nyquist: float = math.nan
    r_half: float = math.nan
    r_01: float = math.nan
    oscillation: float = math.nan
    oscillation_rings: tuple = (0, 0)
    oscillation_clipped: bool = False
    nufft: tuple = None
    lattice_ratio: float = math.nan
    lattice_k: tuple = (0, 0)
    lattice_g: int = 0
    lattice_period: int = 0
    p0: float = math.nan
    h_index: float = math.nan
    lowk_alpha: float = math.nan
    low_frequency: dict = field(default_factory=dict, repr=False)
    shift_variance: dict = field(default_factory=dict, repr=False)


def default_K(n):
    """cfpo-analyze's default K: ceil(6 sqrt(n)), between 8 and 2048."""
    K = math.ceil(6 * math.sqrt(n))
    return 8 if K < 8 else min(K, 2048)


def spectrum(points, K=None, *, exact=False, width=None, grid=None):
    """Power spectrum P(k) = |sum_j exp(-2 pi i k.x_j)|^2 / n and its measures.

    K: frequencies in [-K, K]^2 (default default_K(n), at most 4096);
    exact: direct summation instead of the NUFFT (O(n K^2)); width: NUFFT
    kernel width 4..16 (default 12); grid: cells a side of the grid whose
    imprint the lattice ratio looks for (default cfpo's grid for n; 0:
    none). Returns a Spectrum with the same numbers as `cfpo-analyze -K K
    FILE` (with `--grid G`) for one set. FFTW's planner is
    guarded, so several threads may call this at once.

    An (n, 3) set gives a Spectrum3 (cfpo._analysis3): the 3-D periodogram
    over [-K, K]^3 (K default ceil(2 n^(1/3)) in 8..64, at most 128), its
    shell averages, P0 and the highest shell, as `cfpo3d-analyze --spectrum
    F --kmax K [--exact]`; width and grid do not apply.
    """
    if _is3(points):
        _not_in_3d(width=width, grid=grid)
        return _analysis3.spectrum(points, K, exact)
    a = _args.as_points(points)
    K = default_K(a.shape[0]) if K is None else _args.whole("K", K, 1, KMAX)
    w = 0 if width is None else _args.whole("width", width, 4, 16)
    g = -1 if grid is None else _args.whole("grid", grid, 0, 1 << 20)
    P, cnt, raps, aniso, spike, peak, hsd, nufft, lat = _core.spectrum(a, K, bool(exact), w, g)
    s_ratio, s_P, kx, ky, s_ring, s_mean = spike
    eff, r_half, r_01, osc, ofrom, oto, clipped = hsd
    lf, sv = _core.lowfreq(P, a.shape[0])
    low = dict(zip(("range", "p0", "p0_count", "h", "intercept", "peak", "peak_ring", "alpha", "rings"), lf))
    return Spectrum(K, P, cnt, raps, aniso, s_ratio, s_P, (kx, ky), s_ring, s_mean, peak[0], peak[1], eff,
                    r_half, r_01, osc, (ofrom, oto), bool(clipped), nufft, lat[0], (lat[1], lat[2]), lat[3],
                    lat[4], lf[1], lf[3], lf[7], low, sv)


@dataclass
class Discrepancy:
    """Five L2 discrepancies, each the square root of its squared formula
    (analysis/README.md; scipy.stats.qmc.discrepancy returns "CD" and "WD"
    squared): wrap-around L2 and diaphony (UTK's normalisation; both
    torus-invariant), L2-star, generalised L2 (Hickernell), centred L2."""
    wrap_l2: float
    diaphony: float
    l2_star: float
    generalized_l2: float
    centred_l2: float


def discrepancy(points):
    """The L2 discrepancies of a set (Discrepancy), exact, O(n log n): the
    numbers cfpo-analyze prints for one set."""
    a = _args.as_points(points)
    return Discrepancy(*_core.discrepancy(a))


PCF_SIGMA = 0.05   # analysis/measures/pcf.h AN_PCF_SIGMA (in Delta(n))
PCF_RMAX = 3.0     # AN_PCF_RMAX
INTEG_M = 1024     # analysis/measures/integration.h AN_INTEG_M
INTEG_SEED = 2022  # AN_INTEG_SEED


def pcf(points, sigma=None, rmax=None, *, dr=None):
    """Pair correlation g(r) on the torus (analysis/README.md): returns (r,
    g), r in units of Delta(n) at b sigma / 5, b = 1..B, up to rmax (and
    below 1/2 - 6 sigma Delta); g with a Gaussian kernel of width sigma
    Delta(n) (default PCF_SIGMA), no window correction, rmax default
    PCF_RMAX. cfpo-analyze's pcf.txt for one set.

    An (n, 3) set: g(r) from pair counts in bins of dr (default 0.02) of
    r / Delta3(n), r the bin centres, up to rmax (default 3, lowered by dr
    until rmax Delta3(n) < 1/2): cfpo3d-analyze --pcf's file; sigma does
    not apply (nor dr in 2-D)."""
    if _is3(points):
        _not_in_3d(sigma=sigma)
        return _analysis3.pcf(points, rmax, dr)
    if dr is not None:
        raise ValueError("dr: applies to 3-D sets (n, 3) only; 2-D g(r) has a kernel of width sigma")
    a = _args.as_points(points, min_n=2)
    s = _args.real("sigma", PCF_SIGMA if sigma is None else sigma, 0.005, 1)
    r = _args.real("rmax", PCF_RMAX if rmax is None else rmax, 0.1, 100)
    g = _core.pcf(a, s, r)
    return (np.arange(1, g.shape[0] + 1) * (s / 5), g)


@dataclass
class Structure:
    """Measures of the periodic Delaunay triangulation (analysis/README.md):
    psi6, the bond-orientational order as psa computes it; voronoi_area_var,
    the variance of the Voronoi cell areas over their squared mean;
    covering_radius and delta_min over Delta(n); mesh_ratio = 2 covering
    radius / delta_min (2 / sqrt(3) on the hexagonal lattice)."""
    psi6: float
    voronoi_area_var: float
    mesh_ratio: float
    covering_radius: float
    delta_min: float


def structure(points):
    """psi6, Voronoi area variance and mesh ratio of a set (Structure), from
    one CGAL periodic Delaunay triangulation: cfpo-analyze's numbers for one
    set. ValueError for duplicate points and sets too few or too clustered
    for a triangulation of the torus.

    An (n, 3) set gives a Structure3 (cfpo._analysis3): faces per Voronoi
    cell and the volume variance from CGAL's periodic 3-D triangulation,
    cfpo3d-analyze --voronoi's numbers."""
    if _is3(points):
        return _analysis3.structure(points)
    a = _args.as_points(points)
    psi6, var, cover, dmin, mesh = _core.delaunay(a)
    D = math.sqrt(2 / (math.sqrt(3) * a.shape[0]))
    return Structure(psi6, var, mesh, cover / D, dmin / D)


@dataclass
class Integration:
    """UTK's integration test with exact ground truth (analysis/README.md):
    the mean squared error over M random Gaussian and M random Heaviside
    integrands on the unit square, and the standard errors of those means."""
    gauss_mse: float
    gauss_se: float
    heaviside_mse: float
    heaviside_se: float


def integration(points, M=INTEG_M, seed=INTEG_SEED):
    """The integration test of a set (Integration): cfpo-analyze's numbers
    (--integration M) for one set; the integrands depend on M and seed only."""
    a = _args.as_points(points)
    m = _args.whole("M", M, 1, 1 << 20)
    s = _args.seed(seed)
    return Integration(*_core.integration(a, m, s))


PREFIX_BASE = 16  # analysis/measures/prefixes.h AN_PREFIX_BASE


@dataclass
class PrefixRow:
    """One prefix P_m (the first m points) in its own units Delta(m):
    kind "dyadic", "sample", "given" or "full"; P0 (NaN below 25 points);
    shiftvar: the exact shift variance of each integrand."""
    m: int
    kind: str
    delta_min: float
    delta_avg: float
    p0: float
    shiftvar: dict


@dataclass
class Prefixes:
    """The prefixes of a set in its order: rows (the rows of
    cfpo-analyze's prefixes.txt) and the exact worst delta_min / Delta(m)
    over every m >= base, reached first at worst_any_m."""
    rows: list
    worst_any: float
    worst_any_m: int


def prefixes(points, base=PREFIX_BASE, sizes=None):
    """The prefix measures of a set in its order (Prefixes): cfpo-analyze
    --prefixes [--prefix-base B] [--prefix-sizes L]. Default sizes: every
    power of two from base to n, 2^k + 1 and round(2^k sqrt 2) between them,
    and n; sizes: a sequence of whole numbers in [2, n] instead."""
    a = _args.as_points(points)
    b = _args.whole("base", base, 2, 1 << 62)
    rows, worst, at = _core.prefixes(a, b, None if sizes is None else [_args.whole("sizes", x, 2, 1 << 62) for x in sizes])
    return Prefixes([PrefixRow(*r) for r in rows], worst, at)


@dataclass
class Certificate:
    """An exact certificate that a set is a Farthest Point Distribution.

    passed: bool per point, it passes the farthest point test (no move of
    it alone increases its distance to the rest by more than the tolerance);
    lct_passed: bool per point, both properties of the Local
    Characterization Theorem hold; violation: each point's farthest point
    violation over Delta(n); target: for each point a farthest point of the
    torus from the others; summary: the certificate of cfpo-analyze
    --certify (fpd, tolerance, delta, covering_radius, fp_pass,
    fp_max_violation, fp_worst, p1_pass, p2_pass, lct_pass,
    p1_max_violation, p2_max_violation)."""
    fpd: bool
    passed: np.ndarray = field(repr=False)
    lct_passed: np.ndarray = field(repr=False)
    violation: np.ndarray = field(repr=False)
    target: np.ndarray = field(repr=False)
    summary: dict = field(default_factory=dict)


def certify(points, tol=None):
    """FPD certificate of a set of at least 2 points (Certificate).

    tol: tolerance relative to Delta(n), in [0, 1] (default CERT_TOL,
    1e-3). The summary holds cfpo-analyze --certify's numbers.

    An (n, 3) set gives a Certificate3 (cfpo._analysis3: fpd, points that
    pass, the largest violation over Delta3(n)), cfpo3d-analyze --certify's
    numbers; its tolerance is fixed (tol does not apply).
    """
    if _is3(points):
        _not_in_3d(tol=tol)
        return _analysis3.certify(points)
    a = _args.as_points(points, min_n=2)
    t = _args.real("tol", CERT_TOL if tol is None else tol, 0, 1)
    flags, viol, target, summary = _core.certify(a, t)
    passed = (flags & 1) != 0
    lct = (flags & 6) == 6
    return Certificate(summary["fpd"], passed, lct, viol, target, summary)


DDA_RADIUS = 8.0  # analysis/dda.h AN_DDA_RADIUS (local spacings)


@dataclass
class DDASpectrum:
    """The differential-domain spectrum of Wei and Wang (2011) with the
    symmetric normalisation (analysis/README.md): pair differences scaled
    by Delta(n) / sqrt(r_i r_j), r = Delta(n) / sqrt(rho) the local
    spacing, summed under a window of radius `radius` local spacings, the
    window's own transform taken off. power[ky + K, kx + K] at the integer
    k of [-K, K]^2 (1 at high frequencies; the periodogram, smoothed, when
    rho = 1); ring_count, raps, anisotropy_db per ring 0..K (raps[0]
    unused); peak, peak_ring, peak_freq (ring / sqrt(n)): the highest ring
    mean; low: the mean over 0 < |k| <= 0.2 sqrt(n); anisotropy_mean_db:
    the mean anisotropy over the rings 0.5..2 sqrt(n); pairs: the pairs
    inside the window. cfpo-analyze's dda_raps.txt, dda_spectrum.txt and
    DENSITY line for one set."""
    K: int
    radius: float
    pairs: float
    power: np.ndarray = field(repr=False)
    ring_count: np.ndarray = field(repr=False)
    raps: np.ndarray = field(repr=False)
    anisotropy_db: np.ndarray = field(repr=False)
    peak: float = math.nan
    peak_ring: int = 0
    peak_freq: float = math.nan
    low: float = math.nan
    anisotropy_mean_db: float = math.nan


@dataclass
class DensityMeasures:
    """How a set follows a density (cfpo-analyze --density SPEC, one set;
    analysis/README.md): delta_min, delta_avg in the symmetric measure
    |x_i - x_j| / sqrt(r_i r_j); hist: counts of each point's smallest
    measure in 100 bins of 0.02 (density.txt); count_fidelity_rms/max over
    blocks (count_fidelity16_*: the blocks expecting 16 or more points),
    blocks a side; off_support: points where rho = 0;
    capacity_deviation: std / mean of the capacities, each point's exact
    integral of rho (mean 1) over its Voronoi cell (capacities; None and
    nan when the set has no Delaunay triangulation of the torus);
    capacity_sum_error: |sum of capacities - 1|; dda: DDASpectrum."""
    delta_min: float
    delta_avg: float
    hist: np.ndarray = field(repr=False)
    count_fidelity_rms: float = math.nan
    count_fidelity_max: float = math.nan
    count_fidelity16_rms: float = math.nan
    count_fidelity16_max: float = math.nan
    blocks: int = 0
    off_support: float = 0.0
    capacity_deviation: float = math.nan
    capacities: np.ndarray = field(default=None, repr=False)
    capacity_sum_error: float = math.nan
    dda: DDASpectrum = None


def density(points, density, K=None):
    """The measures of a set of at least 2 points under a density
    (DensityMeasures): cfpo-analyze --density SPEC's numbers for one set.

    density: a SPEC string as cfpo --density takes it, or a 2-D array of
    non-negative values (row = y); K: the differential-domain spectrum's
    frequencies [-K, K]^2 (default default_K(n), at most 4096). ValueError
    with the command's wording for a bad density, or when no point lies
    where the density is above 0; MemoryError when out of memory.
    """
    a = _args.as_points(points, min_n=2)
    K = default_K(a.shape[0]) if K is None else _args.whole("K", K, 1, KMAX)
    d = _args.density(density)
    r = _core.density_measures(a, d, K)
    dda = DDASpectrum(r["K"], r["radius"], r["pairs"], r["power"], r["ring_count"], r["raps"],
                      r["anisotropy_db"], r["peak"], r["peak_ring"], r["peak_freq"], r["low"],
                      r["anisotropy_mean_db"])
    return DensityMeasures(r["delta_min"], r["delta_avg"], r["hist"].astype(np.int64), r["count_fidelity_rms"],
                           r["count_fidelity_max"], r["count_fidelity16_rms"], r["count_fidelity16_max"],
                           r["blocks"], r["off_support"], r["capacity_deviation"], r["capacities"],
                           r["capacity_sum_error"], dda)


Spectrum3 = _analysis3.Spectrum3
Structure3 = _analysis3.Structure3
Certificate3 = _analysis3.Certificate3
BondOrder = _analysis3.BondOrder


def bond_order(points, neighbours=_analysis3.NEIGHBOURS, bond=_analysis3.BOND, bonds=_analysis3.BONDS):
    """Steinhardt's Q6 and W6 and the crystal-like points of an (n, 3) set
    (BondOrder), over each point's `neighbours` nearest (1..64, default 12;
    n must exceed it); a point is crystal-like with at least `bonds` (0..64,
    default 8) neighbours whose normalised q6 product exceeds `bond` (in
    [0, 1], default 0.7): cfpo3d-analyze --neighbours K --bond C --bonds B."""
    if not _is3(points):
        raise ValueError("points: bond_order takes a 3-D set, an (n, 3) array")
    return _analysis3.bond_order(points, neighbours, bond, bonds)
