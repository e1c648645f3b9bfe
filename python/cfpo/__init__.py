"""cfpo: blue-noise point sets on the unit torus [0, 1)^2.

Parallel Constrained Farthest Point Optimization (CFPO), its analysis
(spectra, distances, an exact FPD certificate) and eight baseline samplers,
from the project's C library. Every array is the same bytes as the
corresponding command writes for the same arguments.

    import cfpo
    pts = cfpo.sample(4096, seed=7)            # (4096, 2) float64
    r = cfpo.run(4096, seed=7, target_min=0.9)  # with statistics and trace
    spec = cfpo.analysis.spectrum(pts)
    cfpo.save("points.csv", pts)

The GIL is released during every long call; Ctrl-C raises
KeyboardInterrupt within one iteration.
"""
from dataclasses import dataclass, field

import numpy as np

from . import _args
from . import _core
from ._progress import ProgressLine

__version__ = _core.version
__all__ = ["sample", "run", "Result", "load", "save", "analysis", "baselines", "__version__"]

STOP_REASONS = ("converged", "target", "time", "max-iter", "caller", "flat", "level-iter")
TRACE_COLUMNS = _core.trace_columns  # the C library's (src/common/tracecols.h)


@dataclass
class Result:
    """The outcome of an iterative run.

    points: (n, 2) float64 array ((n, 3) for dim=3); iterations: iterations
    done; seconds: wall time of the run; delta_min, delta_avg:
    nearest-neighbour distances of the result over Delta(n) (Delta3(n) for
    dim=3); converged: whether the convergence rule held;
    stop: which rule ended the run, one of "converged", "target", "time",
    "max-iter", "caller", "flat" (dim=3's schedule), "level-iter" (the
    progressive schedule's level cap); trace: dict of numpy arrays, one entry a row of the
    command's --trace file (columns TRACE_COLUMNS; a baseline's are its
    command's: the first eight of them, then its own). packing_fraction
    (dim=3 only, else None): the packing fraction of spheres of diameter
    delta_min (pi/6 n d^3 on the unit torus, d = delta_min Delta3(n)): the
    command's BOX3D packing_fraction=, the same at any --box.
    """
    points: np.ndarray
    iterations: int
    seconds: float
    delta_min: float
    delta_avg: float
    converged: bool
    stop: str
    trace: dict = field(repr=False, default_factory=dict)
    packing_fraction: float = None


def _callback(progress, n, max_iter, stops):
    """The per-iteration callable for the C run, and what to close after."""
    if progress is None or progress is False:
        return None, None
    if progress is True:
        line = ProgressLine(n, max_iter, *stops)
        return line, line
    if callable(progress):
        return progress, None
    raise TypeError("progress: expected None, True or a callable(stats) -> bool")


def _density_arg(density, variant):
    """density= as the C layer takes it: a SPEC string, or a 2-D float64 array (row = y)."""
    if variant != "adaptive":
        raise ValueError("variant does not go with density (the density run has one variant)")
    return _args.density(density)


def _dim(dim):
    """dim= as the command's --dim: 2 or 3."""
    if isinstance(dim, bool) or not isinstance(dim, (int, np.integer)):
        raise TypeError("dim: expected 2 or 3")
    if dim not in (2, 3):
        raise ValueError(f"dim: {dim} is not 2 or 3 (the dimension of the torus)")
    return int(dim)


def _call3(want_trace, n, seed, variant, threads, tol, max_iter, target_min, target_avg, time_limit, init,
           progress, density):
    """dim=3: checks the arguments as `cfpo --dim 3` does, then runs the 3-D engine."""
    if variant != "adaptive":
        raise ValueError(f"variant {variant!r} does not apply in 3-D: the 3-D engine has one variant, adaptive")
    if density is not None:
        raise ValueError("density does not apply in 3-D")
    nn = -1 if n is None else _args.points_n(n)
    th = _args.threads(threads)
    t = _args.tol(tol, -1.0)  # -1: the 3-D engine's default
    if t == 0:
        raise ValueError("tol: must be positive in 3-D")
    mi = _args.max_iter(max_iter)
    stops = _args.stop_rules(target_min, target_avg, time_limit)
    start = None if init is None else _args.as_points(init, "init", dim=3)
    cb, line = _callback(progress, nn if nn > 0 else start.shape[0], mi, stops)
    try:
        return _core.run3(nn, _args.seed(seed), th, t, mi, *stops, start, cb, want_trace)
    finally:
        if line is not None:
            line.end()


def _call(want_trace, n, seed, variant, threads, tol, max_iter, target_min, target_avg, time_limit, init,
          progress, density=None, dim=2):
    """Checks the arguments as the command does, then runs the C engine."""
    if n is None and init is None:
        raise ValueError("the number of points is required: n")
    if not isinstance(variant, str):
        raise TypeError("variant: expected a string")
    if _dim(dim) == 3:
        return _call3(want_trace, n, seed, variant, threads, tol, max_iter, target_min, target_avg, time_limit,
                      init, progress, density)
    nn = -1 if n is None else _args.points_n(n)
    th = _args.threads(threads)
    t = _args.tol(tol, -1.0)  # -1: the variant's default
    mi = _args.max_iter(max_iter)
    stops = _args.stop_rules(target_min, target_avg, time_limit)
    start = None if init is None else _args.as_points(init, "init")
    dens = None if density is None else _density_arg(density, variant)
    cb, line = _callback(progress, nn if nn > 0 else start.shape[0], mi, stops)
    try:
        return _core.run(nn, _args.seed(seed), variant, th, t, mi, *stops, start, cb, want_trace, dens)
    finally:
        if line is not None:
            line.end()


def run(n=None, *, seed=1, variant="adaptive", threads=None, tol=None, max_iter=None, target_min=None,
        target_avg=None, time_limit=None, init=None, progress=None, density=None, dim=2):
    """Runs CFPO and returns a Result (points, statistics, stop reason, trace).

    n: number of points (at least the command's minimum; may be left out
    with init). seed: 64-bit unsigned. variant: "adaptive" (default),
    "paper" (alias "cfpo"), "simplified" or "hyperuniform" (no
    low-frequency floor; docs/method.md). threads: OpenMP threads; None
    follows OMP_NUM_THREADS, else all cores (the result does not depend on
    it). tol: move tolerance relative to the cell side (default: the
    variant's). max_iter: iteration cap (default 10000). target_min,
    target_avg: stop as soon as every given target holds. time_limit: stop
    at the first iteration boundary past this many seconds. init: (n, 2)
    start points (converted as cfpo.analysis documents) instead of the
    variant's start. progress: True for a progress line with an ETA on
    stderr, or a callable receiving each iteration's statistics as a dict
    (iteration, delta_min, delta_avg, moved, solved, max_disp, seconds,
    elapsed, max_move, near, converged) that stops the run (stop="caller") by
    returning True. density: follow a density, as `cfpo --density SPEC`: a
    SPEC string (an image path, a .npy path, or e.g. "cos:a=0.9") or a 2-D
    array of non-negative values (row j = y); tol is then in local spacings
    (default 1e-4) and delta_min, delta_avg are in the symmetric measure
    (docs/method.md, "Density"). dim: 2 (default) or 3: with 3 the 3-D
    engine of `cfpo --dim 3` on the unit 3-torus (docs/method.md, "Three
    dimensions"): points (n, 3), n at least 39, delta_min and delta_avg over
    Delta3(n) = (sqrt(2)/n)^(1/3), init an (n, 3) array, tol default 1e-4
    (positive), variant only "adaptive", no density; the command's default
    schedule (rounds ended by a flat window of 20 iterations, 3 shakes, the
    best set returned; max_iter counts every round, a target ends it); the
    bytes of `cfpo --dim 3 -n N --seed S ... -o x.npy`.

    The points are the same bytes as `cfpo -n N --seed S ... -o x.npy`
    writes (with density, as `cfpo --density SPEC ...`, the array saved as
    a .npy for SPEC). Raises ValueError/TypeError for bad arguments (the command's
    wording), MemoryError when n does not fit, KeyboardInterrupt on Ctrl-C.
    """
    r = _call(True, n, seed, variant, threads, tol, max_iter, target_min, target_avg, time_limit, init,
              progress, density, dim)
    pts, it, secs, dmin, davg, conv, stop, tr = r
    pf = None
    if pts.shape[1] == 3:  # the command's BOX3D line (src/d3/cli3.c)
        d = dmin * np.cbrt(np.sqrt(2.0) / pts.shape[0])
        pf = float(np.pi / 6.0 * pts.shape[0] * d * d * d)
    return Result(pts, it, secs, dmin, davg, conv, stop, dict(zip(TRACE_COLUMNS, tr)), pf)

def sample(n=None, *, seed=1, variant="adaptive", threads=None, tol=None, max_iter=None, target_min=None,
           target_avg=None, time_limit=None, init=None, progress=None, density=None, dim=2, progressive=False,
           classes=None, base=None, level_min=None, relax=None, joint=None, joint_last=None, level_balance=None):
    """CFPO points: run(...).points, an (n, 2) float64 array (dim=3: (n, 3)) that owns its memory.

    The same arguments as cfpo.run; the same bytes as `cfpo ... -o x.npy`
    (dim=3: `cfpo --dim 3 ... -o x.npy`).
    progressive=True: the set of `cfpo --progressive` (every prefix of
    base * 2^k points blue noise, rows in prefix order); classes=K: that of
    `cfpo --classes K` (class c = rows [c n/K, (c+1) n/K)); base, level_min,
    relax, joint, joint_last and level_balance as the command's --base,
    --level-min, --relax, --joint S, --joint-last S (the bounded joint
    move's sweeps) and --level-balance C (each level's new points by
    quadtree quota, cells of about C of the prefix's points; None: the
    default 16; 0: off; progressive only, not with classes), docs/cli.md.
    Both take
    neither init, density nor time_limit (the command refuses them too),
    and only dim=2.
    """
    if progressive or classes is not None:
        if dim != 2:
            raise ValueError("progressive and classes are two-dimensional (dim=2)")
        return progressive_run(n, seed=seed, variant=variant, threads=threads, tol=tol, max_iter=max_iter,
                               target_min=target_min, target_avg=target_avg, progress=progress,
                               classes=classes, base=base, level_min=level_min, relax=relax, joint=joint,
                               joint_last=joint_last, level_balance=level_balance,
                               _refuse=dict(init=init, density=density, time_limit=time_limit))[0]
    if base is not None or level_min is not None or relax is not None or joint is not None or joint_last is not None:
        raise ValueError("base, level_min, relax, joint and joint_last need progressive=True or classes=K")
    if level_balance is not None:
        raise ValueError("level_balance needs progressive=True (without classes)")
    return _call(False, n, seed, variant, threads, tol, max_iter, target_min, target_avg, time_limit, init,
                 progress, density, dim)[0]


def progressive_run(n, *, seed=1, variant="adaptive", threads=None, tol=None, max_iter=None, target_min=None,
                    target_avg=None, progress=None, classes=None, base=None, level_min=None, relax=None, joint=None,
                    joint_last=None, level_balance=None,
                    _refuse=None):
    """Progressive CFPO (`cfpo --progressive`, or `--classes K`): returns
    (points, levels), points (n, 2) in prefix order, the same bytes as the
    command's -o x.npy; levels a list of (prefix, iterations, delta_min,
    delta_avg), each prefix in its own Delta(m) units (docs/cli.md).
    progress: a callable receiving every level's iterations' statistics (a
    True return stops the run with RuntimeError). level_balance: None the
    default leaf size (16), 0 off, C > 0 cells of about C points; not with
    classes."""
    for k, v in (_refuse or {}).items():
        if v is not None:
            raise ValueError(f"{k} does not go with {'classes' if classes is not None else 'progressive'}")
    if n is None:
        raise ValueError("the number of points is required: n")
    nn = _args.points_n(n)
    if not isinstance(variant, str):
        raise TypeError("variant: expected a string")
    K = 0
    if classes is not None:
        if isinstance(classes, bool) or not isinstance(classes, int) or classes < 1:
            raise ValueError(f"classes: '{classes}' is not a whole number >= 1")
        K = classes
    b = 0
    if base is not None:
        if K:
            raise ValueError("base does not go with classes")
        if isinstance(base, bool) or not isinstance(base, int) or base < 1:
            raise ValueError(f"base: '{base}' is not a whole number >= 1")
        b = base
    lm = 0.0 if level_min is None else float(level_min)
    if not 0.0 <= lm <= 1.0:
        raise ValueError(f"level_min: '{level_min}' is not a number in [0, 1]")
    rx = 0 if relax is None else relax
    if isinstance(rx, bool) or not isinstance(rx, int) or rx < 0:
        raise ValueError(f"relax: '{relax}' is not a whole number >= 0")
    js = 0 if joint is None else _args.whole("joint", joint, 0, 1000000)
    jl = 0 if joint_last is None else _args.whole("joint_last", joint_last, 1, 1000000)
    lb = 0  # the default (progressive.h balance)
    if level_balance is not None:
        if K:
            raise ValueError("level_balance needs progressive=True (without classes)")
        v = _args.whole("level_balance", level_balance, 0, 1000000)
        lb = v if v > 0 else -1  # 0: off
    stops = _args.stop_rules(target_min, target_avg, None)
    cb, line = _callback(progress, nn, _args.max_iter(max_iter), stops)
    try:
        r = _core.progressive(nn, _args.seed(seed), variant, _args.threads(threads), _args.tol(tol, -1.0),
                              _args.max_iter(max_iter), stops[0], stops[1], b, K, lm, rx, js, jl, lb, cb)
    finally:
        if line is not None:
            line.end()
    return r[0], r[7]

def load(path, dim=2):
    """Reads a point file into an (n, 2) float64 array ((n, 3) with dim=3).

    The format comes from the extension: .txt/.dat/.pts/.xy (text "x y"
    lines, '#' comments), .csv (a header line "x,y", then "x,y" a line),
    .npy (NumPy, float64 or float32), .bin/.raw/.f64 (raw little-endian
    float64 pairs). dim=3 reads what `cfpo --dim 3 --init` reads: .npy
    (n x 3), text "x y z" lines, CSV with the header "x,y,z" and raw
    float64 triples. The reader is the commands' own: it refuses empty,
    truncated or corrupt files, NaN/inf and points outside the unit torus
    (ValueError), and missing or unreadable files (OSError).
    """
    if _dim(dim) == 3:
        if _core.format3_of(str(path)) != 2:
            raise ValueError(f"{path}: not a 3-D format cfpo reads (use .npy, .txt/.dat/.pts, .csv, "
                             ".bin/.raw/.f64)")
        return _core.load3(path)
    return _core.load(path)


def save(path, points, box=None):
    """Writes points ((n, 2) in [0, 1)^2, or (n, 3) in [0, 1)^3) to path,
    format from the extension.

    The file is written under a temporary name and renamed when complete,
    so a failure leaves nothing behind; the bytes are those the commands
    write (`cfpo -o`, `cfpo --dim 3 --box L -o`). 3-D sets also go to the
    files simulation codes read: extended XYZ (.xyz/.extxyz, the periodic
    cell), LAMMPS data (.data/.lmp) and GROMACS .gro, which hold the box of
    side box (default 1; coordinates times box); the other formats hold
    the unit torus. box is for 3-D sets only. Unknown extensions and a box
    that is not positive and finite raise ValueError, unwritable paths
    OSError.
    """
    shape = np.shape(points)
    if len(shape) == 2 and shape[1] == 3:
        a = _args.as_points(points, dim=3)
        b = 1.0 if box is None else _args.real("box", box, 0.0, float("inf"), open_lo=True)
        if _core.format3_of(str(path)) == 0:
            raise ValueError(f"{path}: unknown output format (use .npy, .txt/.dat/.pts, .csv, .bin/.raw/.f64, "
                             ".xyz/.extxyz, .data/.lmp, .gro)")
        _core.save3(path, a, b)
        return
    if box is not None:
        raise ValueError("box: only for 3-D sets ((n, 3) points)")
    a = _args.as_points(points)
    if _core.format_of(str(path)) == "unknown":
        raise ValueError(f"{path}: unknown output format (use {_core.extensions})")
    _core.save(path, a)


from . import analysis  # noqa: E402  (needs the names above)
from . import baselines  # noqa: E402
