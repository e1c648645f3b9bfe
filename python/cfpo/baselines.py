"""The baseline samplers, each the same bytes as its command.

dart, bs, bridson: Poisson-disk samplers (cfpo-dart, cfpo-bs,
cfpo-bridson) returning an (m, 2) float64 array (for bs and bridson m is
about n: the maximal set at the radius n gives). fpo, lfpo, ccvt, ccdt,
bnot: iterative methods (cfpo-fpo, cfpo-lfpo, cfpo-ccvt, cfpo-ccdt,
cfpo-bnot) returning a cfpo.Result, with the commands' stop rules
(convergence by tol, target_min, target_avg, time_limit, max_iter) and a
progress callable that stops the run by returning True.

The GIL is released while they run; Ctrl-C raises KeyboardInterrupt after
the current iteration (Poisson-disk samplers: at the end of the call).
"""
from . import _args
from . import _core

_DART, _BS, _BRIDSON = 0, 1, 2
_COLUMNS = ("iteration", "delta_min", "delta_avg", "moved", "solved", "max_disp", "seconds", "elapsed")


def _poisson(kind, n, seed, radius, rel_radius, max_fails=1000000, k=30, plain=False):
    nn = -1 if n is None else _args.points_n(n)
    r = -1.0 if radius is None else _args.real("radius", radius, 0, 1, open_lo=True)
    rel = -1.0 if rel_radius is None else _args.real("rel_radius", rel_radius, 0, 2, open_lo=True)
    mf = _args.whole("max_fails", max_fails, 1, 2**63 - 1)
    kk = _args.whole("k", k, 1, 1000000)
    return _core.poisson(kind, nn, _args.seed(seed), r, rel, mf, kk, bool(plain))[0]


def dart(n, *, seed=1, radius=None, rel_radius=None, max_fails=1000000):
    """Dart throwing (Cook 1986): n points at least r apart (cfpo-dart).

    r = rel_radius * Delta(n) (default 0.75) or radius itself. Saturation
    (max_fails consecutive rejected darts before n points) raises
    RuntimeError, as the command fails.
    """
    return _poisson(_DART, n, seed, radius, rel_radius, max_fails=max_fails)


def bs(n=None, *, seed=1, radius=None, rel_radius=None):
    """Boundary sampling (Dunbar & Humphreys 2006): a maximal Poisson-disk set
    (cfpo-bs). r = rel_radius * Delta(n) (default 0.8495), or radius."""
    return _poisson(_BS, n, seed, radius, rel_radius)


def bridson(n=None, *, seed=1, radius=None, rel_radius=None, k=30, plain=False):
    """Bridson's sampling (2007), made maximal (cfpo-bridson). k candidates
    per active sample; plain=True: the 2007 algorithm only (not maximal).
    r = rel_radius * Delta(n) (default 0.7755), or radius."""
    return _poisson(_BRIDSON, n, seed, radius, rel_radius, k=k, plain=plain)


def _iterative(method, n, seed, tol, max_iter, target_min, target_avg, time_limit, progress, local=False,
               start="random", m=None):
    from . import Result  # the package's result type
    nn = _args.points_n(n)
    t = 1e-4 if tol is None else _args.real("tol", tol, 0, _core.tol_max)
    mi = _core.default_max_iter if max_iter is None else _args.whole("max_iter", max_iter, 0, 10**9)
    stops = _args.stop_rules(target_min, target_avg, time_limit)
    if start not in ("random", "grid"):
        raise ValueError(f"start: '{start}' is not one of random, grid")
    mm = 0 if m is None else _args.whole("points_per_site", m, 1, 1 << 20)
    if progress is not None and not callable(progress):
        raise TypeError("progress: expected None or a callable(stats) -> bool")
    pts, it, secs, dmin, davg, conv, stop, tr = _core.iterative(
        method, nn, _args.seed(seed), t, mi, *stops, bool(local), start == "grid", mm, progress, True)
    return Result(pts, it, secs, dmin, davg, conv, stop, dict(zip(_COLUMNS, tr)))


_ITER_DOC = """

    n: number of points (cfpo's minimum applies: tol is relative to cfpo's
    cell side for n); seed; tol (default 1e-4); max_iter (default 10000);
    target_min, target_avg, time_limit: the stop rules of the command;
    progress: a callable receiving each row's statistics (a dict) that
    stops the run by returning True. Returns a cfpo.Result whose points are
    the command's bytes for the same arguments."""


def fpo(n, *, seed=1, tol=None, max_iter=None, target_min=None, target_avg=None, time_limit=None, start="random",
        progress=None):
    return _iterative("fpo", n, seed, tol, max_iter, target_min, target_avg, time_limit, progress, False, start)


def lfpo(n, *, seed=1, tol=None, max_iter=None, target_min=None, target_avg=None, time_limit=None, start="random",
         progress=None):
    return _iterative("lfpo", n, seed, tol, max_iter, target_min, target_avg, time_limit, progress, True, start)


def ccvt(n, *, seed=1, tol=None, max_iter=None, target_min=None, target_avg=None, time_limit=None,
         points_per_site=None, progress=None):
    return _iterative("ccvt", n, seed, tol, max_iter, target_min, target_avg, time_limit, progress,
                      m=points_per_site)


def ccdt(n, *, seed=1, tol=None, max_iter=None, target_min=None, target_avg=None, time_limit=None, progress=None):
    return _iterative("ccdt", n, seed, tol, max_iter, target_min, target_avg, time_limit, progress)


def bnot(n, *, seed=1, tol=None, max_iter=None, target_min=None, target_avg=None, time_limit=None, progress=None):
    return _iterative("bnot", n, seed, tol, max_iter, target_min, target_avg, time_limit, progress)


fpo.__doc__ = ("Farthest Point Optimization (Schloemer, Heck, Deussen 2011), global (cfpo-fpo); "
               "start='grid' starts from cfpo's stratified start." + _ITER_DOC)
lfpo.__doc__ = "Local FPO: the removed point's 2-ring only (cfpo-lfpo)." + _ITER_DOC
ccvt.__doc__ = ("Capacity-constrained Voronoi tessellation (Balzer et al. 2009) (cfpo-ccvt); "
                "points_per_site: the command's --points-per-site." + _ITER_DOC)
ccdt.__doc__ = "Capacity-constrained Delaunay triangulation (Xu et al. 2011) (cfpo-ccdt)." + _ITER_DOC
bnot.__doc__ = "Blue noise through optimal transport (de Goes et al. 2012) (cfpo-bnot)." + _ITER_DOC
