"""The baseline samplers, each the same bytes as its command.

dart, bs, bridson: Poisson-disk samplers (cfpo-dart, cfpo-bs,
cfpo-bridson) returning an (m, 2) float64 array (for bs and bridson m is
about n: the maximal set at the radius n gives). fpo, lfpo, ccvt, ccdt,
bnot, lloyd, gbn: iterative methods (cfpo-fpo, cfpo-lfpo, cfpo-ccvt,
cfpo-ccdt, cfpo-bnot, cfpo-lloyd, cfpo-gbn), and white, jitter, sobol, wse, pmj02bn:
direct samplers run the same way (0 iterations), returning a cfpo.Result, with the commands' stop rules
(convergence by tol, target_min, target_avg, time_limit, max_iter), a
progress callable that stops the run by returning True, and each
command's own options as keywords (None: the command's default).

What a method is comes from the C library (METHODS, from
baselines/bl_method.h): its options with their ranges, defaults and
wording, and its trace columns; this module checks the arguments against
that table and adds nothing of its own but one function per method.

The GIL is released while they run; Ctrl-C raises KeyboardInterrupt after
the current iteration (Poisson-disk samplers: at the end of the call).
"""
from . import _args
from . import _core

METHODS = _core.methods()  # {name: {prog, kind, options, columns, rel_radius, density}}


def _values(method, given):
    """The method's option values in its table's order, each checked as
    the command checks it (None or left out: the default)."""
    opts = METHODS[method]["options"]
    unknown = set(given) - {o["py"] for o in opts if o["py"]}
    if unknown:
        raise TypeError(f"{method}: unknown option {sorted(unknown)[0]}")
    return tuple(_args.option(o, given.get(o["py"]) if o["py"] else None) for o in opts)


def _density(density):
    """density= as the C layer takes it (None, a SPEC string, a 2-D array), as cfpo.sample's."""
    if density is None:
        return None
    from . import _density_arg
    return _density_arg(density, "adaptive")


def _poisson(method, n=None, seed=1, density=None, **own):
    nn = -1 if n is None else _args.points_n(n)
    return _core.poisson(method, nn, _args.seed(seed), _values(method, own), _density(density))[0]


def _iterative(method, n, seed=1, tol=None, max_iter=None, target_min=None, target_avg=None, time_limit=None,
               progress=None, density=None, **own):
    from . import Result  # the package's result type
    nn = _args.points_n(n)
    t = _args.tol(tol, _core.default_tol)
    mi = _args.max_iter(max_iter)
    stops = _args.stop_rules(target_min, target_avg, time_limit)
    if progress is not None and not callable(progress):
        raise TypeError("progress: expected None or a callable(stats) -> bool")
    values = _values(method, own)
    pts, it, secs, dmin, davg, conv, stop, tr = _core.iterative(
        method, nn, _args.seed(seed), t, mi, *stops, progress, True, values, _density(density))
    return Result(pts, it, secs, dmin, davg, conv, stop, dict(zip(METHODS[method]["columns"], tr)))


def dart(n, *, seed=1, radius=None, rel_radius=None, max_fails=None, density=None):
    return _poisson("dart", **locals())


def bs(n=None, *, seed=1, radius=None, rel_radius=None):
    return _poisson("bs", **locals())


def bridson(n=None, *, seed=1, radius=None, rel_radius=None, k=None, plain=None):
    return _poisson("bridson", **locals())


def fpo(n, *, seed=1, tol=None, max_iter=None, target_min=None, target_avg=None, time_limit=None, start=None,
        progress=None, density=None):
    return _iterative("fpo", **locals())


def lfpo(n, *, seed=1, tol=None, max_iter=None, target_min=None, target_avg=None, time_limit=None, start=None,
         progress=None, density=None):
    return _iterative("lfpo", **locals())


def ccvt(n, *, seed=1, tol=None, max_iter=None, target_min=None, target_avg=None, time_limit=None,
         points_per_site=None, point_set=None, update=None, assign=None, progress=None, density=None):
    return _iterative("ccvt", **locals())


def ccdt(n, *, seed=1, tol=None, max_iter=None, target_min=None, target_avg=None, time_limit=None, reference=None,
         progress=None):
    return _iterative("ccdt", **locals())


def bnot(n, *, seed=1, tol=None, max_iter=None, target_min=None, target_avg=None, time_limit=None, epsilon=None,
         breaker=None, max_rounds=None, round_iters=None, progress=None, density=None):
    return _iterative("bnot", **locals())


def _options_doc(method):
    """The options' lines of a docstring, from the table."""
    lines = []
    for o in METHODS[method]["options"]:
        if not o["py"]:
            continue
        if o["type"] == "choice":
            what = " or ".join(f'"{w}"' for w in o["choices"]) + f' (default "{o["choices"][o["default"]]}")'
        elif o["type"] == "flag":
            what = f"True or False (default {bool(o['default'])})"
        else:
            lo = "(" if o.get("open_min") else "["
            rng = f"{o['min']}..{o['max']}" if o["type"] == "int" else f"{lo}{o['min']:g}, {o['max']:g}]"
            inside = o["min"] <= o["default"] <= o["max"]
            dflt = (o["default"] if o["type"] == "int" else f"{o['default']:g}") if inside else "the command's"
            what = f"{rng} (default {dflt})"
        cli = f" (--{o['cli']})" if o["cli"] else ""
        lines.append(f"    {o['py']}: {what}{cli}.")
    return "\n".join(lines)


_ITER_DOC = f"""

    n: number of points (cfpo's minimum applies: tol is relative to cfpo's
    cell side for n); seed; tol (default {_core.default_tol:g}); max_iter (default
    {_core.default_max_iter}); target_min, target_avg, time_limit: the stop rules of the
    command; progress: a callable receiving each row's statistics (a dict)
    that stops the run by returning True; density (FPO, LFPO, CCVT, BNOT:
    the command's --density): a SPEC string or a 2-D array (row = y), the
    deltas then in the symmetric measure. Returns a cfpo.Result whose points
    are the command's bytes for the same arguments and whose trace has the
    command's columns."""


def _rel(method):
    return f"{METHODS[method]['rel_radius']:g}"


dart.__doc__ = f"""Dart throwing (Cook 1986): n points at least r apart (cfpo-dart).

    r = rel_radius * Delta(n) (default {_rel("dart")}) or radius itself. Saturation
    (max_fails consecutive rejected darts before n points) raises
    RuntimeError, as the command fails. density: adaptive dart throwing
    (cfpo-dart --density): a SPEC string as `cfpo --density` or a 2-D array
    (row = y); darts drawn proportional to rho, two points in conflict when
    |x_i - x_j| < r / (rho_i rho_j)^(1/4).
{_options_doc("dart")}"""
bs.__doc__ = f"""Boundary sampling (Dunbar & Humphreys 2006): a maximal Poisson-disk set
    (cfpo-bs). r = rel_radius * Delta(n) (default {_rel("bs")}), or radius.
{_options_doc("bs")}"""
bridson.__doc__ = f"""Bridson's sampling (2007), made maximal (cfpo-bridson). k candidates
    per active sample; plain=True: the 2007 algorithm only (not maximal).
    r = rel_radius * Delta(n) (default {_rel("bridson")}), or radius.
{_options_doc("bridson")}"""
fpo.__doc__ = ("Farthest Point Optimization (Schloemer, Heck, Deussen 2011), global (cfpo-fpo); "
               "start='grid' starts from cfpo's stratified start.\n" + _options_doc("fpo") + _ITER_DOC)
lfpo.__doc__ = "Local FPO: the removed point's 2-ring only (cfpo-lfpo).\n" + _options_doc("lfpo") + _ITER_DOC
ccvt.__doc__ = """Capacity-constrained Voronoi tessellation (Balzer et al. 2009) (cfpo-ccvt).

    As Balzer's code by default: every site owns m discrete points on a
    regular lattice, pairs of neighbouring sites swap points while that
    lowers the energy and both sites of a pair that swapped move to their
    centroids at once; converged when a whole pass swaps nothing (tol then
    plays no part). The command's options:
    points_per_site: m (by default 1024 up to n = 16384, then 2^24 / n, at
    least 16).
    point_set: "lattice" or "random" (uniform random points).
    update: "pair" or "pass" (every site that swapped moves once after the
    pass; converged also when no site moves tol * L).
    assign: "nearest" (the points, last first, each to the nearest site not
    yet full) or "curve" (runs of m points along a Hilbert curve).
    A bad choice raises ValueError with the command's wording, a lattice
    that n * m does not allow ValueError.
""" + _options_doc("ccvt") + _ITER_DOC
ccdt.__doc__ = """Capacity-constrained Delaunay triangulation (Xu et al. 2011) (cfpo-ccdt).

    By default damped Gauss-Seidel sweeps alternating with re-triangulation,
    run to convergence (tol). reference=K: the reference schedule instead,
    one full-step sweep then re-triangulation per iteration, K iterations
    (converged after the K-th).
""" + _options_doc("ccdt") + _ITER_DOC
bnot.__doc__ = """Blue noise through optimal transport (de Goes et al. 2012) (cfpo-bnot).

    By default as its authors' code runs it: a coarse phase until the
    gradient norm |g| <= 2 tau, tau = 0.03 epsilon / n, then line-searched
    steps until |g| <= tau, at most round_iters iterations a round; then the
    regularity breaker perturbs near-perfect hexagonal patches and a new
    round starts, at most max_rounds rounds. The command's options:
    epsilon: the stopping rule's epsilon; 0: the run until no site moves
    tol * L, capacities to 1e-8, no breaker (the rule options below then
    play no part). breaker: False stops after the first round. max_rounds:
    rounds at most. round_iters: iterations a round at most.
    With epsilon > 0, tol only decides which sites count as moved in the
    statistics. density: the start drawn from rho, every power cell's
    capacity its mass of rho (1/n each), rho-weighted centroids, rho
    integrated along the power edges in the Newton solve.
""" + _options_doc("bnot") + _ITER_DOC


def white(n, *, seed=1, tol=None, max_iter=None, target_min=None, target_avg=None, time_limit=None, progress=None):
    return _iterative("white", **locals())


def jitter(n, *, seed=1, tol=None, max_iter=None, target_min=None, target_avg=None, time_limit=None,
           progress=None):
    return _iterative("jitter", **locals())


def sobol(n, *, seed=1, tol=None, max_iter=None, target_min=None, target_avg=None, time_limit=None, plain=None,
          progress=None):
    return _iterative("sobol", **locals())


def lloyd(n, *, seed=1, tol=None, max_iter=None, target_min=None, target_avg=None, time_limit=None, iterations=None,
          progress=None):
    return _iterative("lloyd", **locals())


def gbn(n, *, seed=1, tol=None, max_iter=None, target_min=None, target_avg=None, time_limit=None, sigma=None,
        step=None, iterations=None, cutoff=None, threads=None, progress=None):
    return _iterative("gbn", **locals())


def wse(n, *, seed=1, tol=None, max_iter=None, target_min=None, target_avg=None, time_limit=None, progressive=None,
        ratio=None, alpha=None, weight_limit=None, progress=None):
    return _iterative("wse", **locals())


def pmj02bn(n, *, seed=1, tol=None, max_iter=None, target_min=None, target_avg=None, time_limit=None,
            candidates=None, global_candidates=None, progress=None):
    return _iterative("pmj02bn", **locals())


white.__doc__ = ("White noise: n independent uniform points (cfpo-white); direct (0 iterations).\n"
                 + _options_doc("white") + _ITER_DOC)
jitter.__doc__ = ("Jittered sampling: one uniform point in each of n strata, round(sqrt(n)) rows of\n"
                  "    floor or ceil of n / rows equal cells (cfpo-jitter); direct (0 iterations).\n"
                  + _options_doc("jitter") + _ITER_DOC)
sobol.__doc__ = ("Owen-scrambled Sobol': the first n points of the 2-D Sobol' sequence under nested\n"
                 "    uniform scrambling (cfpo-sobol); plain=True: unscrambled. Direct (0 iterations).\n"
                 + _options_doc("sobol") + _ITER_DOC)
wse.__doc__ = ("Weighted sample elimination (Yuksel 2015) on the periodic unit square (cfpo-wse):\n"
               "    ratio * n white-noise candidates eliminated to n; progressive=True: the order in\n"
               "    which every prefix n / 2^k is the set left at that stage. Direct (0 iterations).\n"
               + _options_doc("wse") + _ITER_DOC)
pmj02bn.__doc__ = ("Progressive multi-jittered (0,2) sequence with blue noise (Christensen, Kensler,\n"
                   "    Kilpatrick 2018) on the unit square (cfpo-pmj02bn): every prefix of 2^k points a\n"
                   "    (0,k,2)-net, rows in sequence order; candidates=1: pmj02. Direct (0 iterations).\n"
                   + _options_doc("pmj02bn") + _ITER_DOC)
lloyd.__doc__ = ("Lloyd's algorithm towards a centroidal Voronoi tessellation on the torus\n"
                 "    (cfpo-lloyd); converged when no site moves tol * L, or after iterations (100).\n" + _options_doc("lloyd") + _ITER_DOC)
gbn.__doc__ = ("Gaussian blue noise (Ahmed, Ren, Wonka 2022) as the authors' toroidal code runs it\n"
               "    (cfpo-gbn): sigma 1, step 0.25, 1000 iterations by default.\n" + _options_doc("gbn") + _ITER_DOC)
