"""The baseline samplers, each the same bytes as its command.

dart, bs, bridson: Poisson-disk samplers (cfpo-dart, cfpo-bs,
cfpo-bridson) returning an (m, 2) float64 array (for bs and bridson m is
about n: the maximal set at the radius n gives). fpo, lfpo, ccvt, ccdt,
bnot: iterative methods (cfpo-fpo, cfpo-lfpo, cfpo-ccvt, cfpo-ccdt,
cfpo-bnot) returning a cfpo.Result, with the commands' stop rules
(convergence by tol, target_min, target_avg, time_limit, max_iter), a
progress callable that stops the run by returning True, and each
command's own options as keywords with its defaults (ccvt: point_set,
update, assign; ccdt: reference; bnot: epsilon, breaker, max_rounds,
round_iters).

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


_DEF = _core.baseline_defaults  # the commands' defaults (ccvt_options_init, bnot_rule_init)


def _iterative(method, n, seed, tol, max_iter, target_min, target_avg, time_limit, progress, **own):
    from . import Result  # the package's result type
    nn = _args.points_n(n)
    t = 1e-4 if tol is None else _args.real("tol", tol, 0, _core.tol_max)
    mi = _core.default_max_iter if max_iter is None else _args.whole("max_iter", max_iter, 0, 10**9)
    stops = _args.stop_rules(target_min, target_avg, time_limit)
    if progress is not None and not callable(progress):
        raise TypeError("progress: expected None or a callable(stats) -> bool")
    pts, it, secs, dmin, davg, conv, stop, tr = _core.iterative(
        method, nn, _args.seed(seed), t, mi, *stops, progress, True, **own)
    return Result(pts, it, secs, dmin, davg, conv, stop, dict(zip(_COLUMNS, tr)))


_ITER_DOC = """

    n: number of points (cfpo's minimum applies: tol is relative to cfpo's
    cell side for n); seed; tol (default 1e-4); max_iter (default 10000);
    target_min, target_avg, time_limit: the stop rules of the command;
    progress: a callable receiving each row's statistics (a dict) that
    stops the run by returning True. Returns a cfpo.Result whose points are
    the command's bytes for the same arguments."""


def _fpo(method, n, seed, tol, max_iter, target_min, target_avg, time_limit, start, progress):
    if start not in ("random", "grid"):
        raise ValueError(f"start: '{start}' is not one of random, grid")
    return _iterative(method, n, seed, tol, max_iter, target_min, target_avg, time_limit, progress,
                      local=method == "lfpo", grid=start == "grid")


def fpo(n, *, seed=1, tol=None, max_iter=None, target_min=None, target_avg=None, time_limit=None, start="random",
        progress=None):
    return _fpo("fpo", n, seed, tol, max_iter, target_min, target_avg, time_limit, start, progress)


def lfpo(n, *, seed=1, tol=None, max_iter=None, target_min=None, target_avg=None, time_limit=None, start="random",
         progress=None):
    return _fpo("lfpo", n, seed, tol, max_iter, target_min, target_avg, time_limit, start, progress)


def ccvt(n, *, seed=1, tol=None, max_iter=None, target_min=None, target_avg=None, time_limit=None,
         points_per_site=None, point_set=_DEF["point_set"], update=_DEF["update"], assign=_DEF["assign"],
         progress=None):
    m = 0 if points_per_site is None else _args.whole("points_per_site", points_per_site, 1, 1 << 20)
    return _iterative("ccvt", n, seed, tol, max_iter, target_min, target_avg, time_limit, progress,
                      points_per_site=m, point_set=point_set, update=update, assign=assign)


def ccdt(n, *, seed=1, tol=None, max_iter=None, target_min=None, target_avg=None, time_limit=None, reference=None,
         progress=None):
    k = 0 if reference is None else _args.whole("reference", reference, 1, 10**9)
    return _iterative("ccdt", n, seed, tol, max_iter, target_min, target_avg, time_limit, progress, reference=k)


def bnot(n, *, seed=1, tol=None, max_iter=None, target_min=None, target_avg=None, time_limit=None,
         epsilon=_DEF["epsilon"], breaker=_DEF["breaker"], max_rounds=_DEF["max_rounds"],
         round_iters=_DEF["round_iters"], progress=None):
    return _iterative("bnot", n, seed, tol, max_iter, target_min, target_avg, time_limit, progress,
                      epsilon=_args.real("epsilon", epsilon, 0, 1e3), breaker=_args.flag("breaker", breaker),
                      max_rounds=_args.whole("max_rounds", max_rounds, 1, 10**6),
                      round_iters=_args.whole("round_iters", round_iters, 1, 10**6))


fpo.__doc__ = ("Farthest Point Optimization (Schloemer, Heck, Deussen 2011), global (cfpo-fpo); "
               "start='grid' starts from cfpo's stratified start." + _ITER_DOC)
lfpo.__doc__ = "Local FPO: the removed point's 2-ring only (cfpo-lfpo)." + _ITER_DOC
ccvt.__doc__ = """Capacity-constrained Voronoi tessellation (Balzer et al. 2009) (cfpo-ccvt).

    As Balzer's code by default: every site owns m discrete points on a
    regular lattice, pairs of neighbouring sites swap points while that
    lowers the energy and both sites of a pair that swapped move to their
    centroids at once; converged when a whole pass swaps nothing (tol then
    plays no part). The command's options:
    points_per_site: m (--points-per-site; default 1024 up to n = 16384,
    then 2^24 / n, at least 16).
    point_set: "lattice" (default) or "random" (uniform random points)
    (--point-set).
    update: "pair" (default) or "pass" (every site that swapped moves once
    after the pass; converged also when no site moves tol * L) (--update).
    assign: "nearest" (default: the points, last first, each to the
    nearest site not yet full) or "curve" (runs of m points along a
    Hilbert curve) (--assign).
    None for any of them: its default. A bad choice raises ValueError with the command's wording, a lattice
    that n * m does not allow ValueError.""" + _ITER_DOC
ccdt.__doc__ = """Capacity-constrained Delaunay triangulation (Xu et al. 2011) (cfpo-ccdt).

    By default damped Gauss-Seidel sweeps alternating with re-triangulation,
    run to convergence (tol). reference=K (--reference K, 1..1e9): the
    reference schedule instead, one full-step sweep then re-triangulation
    per iteration, K iterations (converged after the K-th).""" + _ITER_DOC
bnot.__doc__ = """Blue noise through optimal transport (de Goes et al. 2012) (cfpo-bnot).

    By default as its authors' code runs it: a coarse phase until the
    gradient norm |g| <= 2 tau, tau = 0.03 epsilon / n, then line-searched
    steps until |g| <= tau, at most round_iters iterations a round; then the
    regularity breaker perturbs near-perfect hexagonal patches and a new
    round starts, at most max_rounds rounds. The command's options:
    epsilon: the stopping rule's epsilon (--epsilon, default 0.2, in
    [0, 1000]); 0: the run until no site moves tol * L, capacities to 1e-8,
    no breaker (the rule options below then play no part).
    breaker: False stops after the first round (--no-breaker).
    max_rounds: rounds at most (--max-rounds, default 20, 1..1e6).
    round_iters: iterations a round at most (--round-iters, default 20,
    1..1e6).
    With epsilon > 0, tol only decides which sites count as moved in the
    statistics.""" + _ITER_DOC
