"""Byte identity with the commands: every array from Python is the bytes
the command writes to a .npy for the same arguments."""
import json

import numpy as np
import pytest

import cfpo


def same_file(tmp_path, cmd_file, points):
    py_file = tmp_path / ("py-" + cmd_file.name)
    cfpo.save(py_file, points)
    return cmd_file.read_bytes() == py_file.read_bytes()


@pytest.mark.parametrize("args", [
    dict(n=300, seed=5, max_iter=12),
    dict(n=200, seed=2, variant="paper", max_iter=8),
    dict(n=150, seed=9, variant="simplified", tol=0.001),
    dict(n=256, seed=3, target_min=0.8),
    dict(n=120, seed=4, threads=1),
])
def test_sample_same_bytes(tmp_path, command, args):
    opts = {"n": "-n", "seed": "--seed", "variant": "--variant", "max_iter": "--max-iter", "tol": "--tol",
            "target_min": "--target-min", "threads": "--threads"}
    argv = [x for k, v in args.items() for x in (opts[k], v)]
    command("cfpo", *argv, "-o", "c.npy")
    kw = dict(args)
    n = kw.pop("n")
    pts = cfpo.sample(n, **kw)
    assert (tmp_path / "c.npy").read_bytes()[128:] == pts.tobytes()
    assert same_file(tmp_path, tmp_path / "c.npy", pts)


def test_sample_init_same_bytes(tmp_path, command):
    start = cfpo.baselines.dart(200, seed=4)
    cfpo.save(tmp_path / "start.csv", start)
    command("cfpo", "--init", "start.csv", "--max-iter", "6", "-o", "c.npy")
    pts = cfpo.sample(None, init=start, max_iter=6)
    assert same_file(tmp_path, tmp_path / "c.npy", pts)
    assert np.array_equal(cfpo.sample(200, init=start.astype(np.float64, order="F"), max_iter=6), pts)


def read_trace(path):
    rows = [line.split("\t") for line in path.read_text().splitlines()]
    return rows[0], rows[1:]


def test_run_statistics_and_trace_match_command(tmp_path, command):
    out = command("cfpo", "-n", 300, "--seed", 8, "--max-iter", 15, "-o", "c.npy", "--trace", "t.tsv").stdout
    r = cfpo.run(300, seed=8, max_iter=15)
    summary = dict(f.split("=") for f in out.split()[1:])
    assert r.iterations == int(summary["iterations"]) == 15
    assert r.stop == summary["stop"] == "max-iter"
    assert f"{r.delta_min:.6f}" == summary["delta_min"] and f"{r.delta_avg:.6f}" == summary["delta_avg"]
    head, rows = read_trace(tmp_path / "t.tsv")
    assert tuple(head) == cfpo.TRACE_COLUMNS
    assert len(rows) == len(r.trace["iteration"]) == 16
    for i, row in enumerate(rows):
        assert int(row[0]) == r.trace["iteration"][i]
        assert row[1] == f"{r.trace['delta_min'][i]:.9f}" and row[2] == f"{r.trace['delta_avg'][i]:.9f}"
        assert int(row[3]) == r.trace["moved"][i] and int(row[4]) == r.trace["solved"][i]
        assert row[5] == f"{r.trace['max_disp'][i]:.6g}" and row[8] == f"{r.trace['max_move'][i]:.6g}"
        assert int(row[9]) == r.trace["near"][i]
    assert same_file(tmp_path, tmp_path / "c.npy", r.points)


def test_near_phase_then_exact_until_converged():
    r = cfpo.run(300, seed=8)
    near = list(r.trace["near"])
    assert r.converged and r.stop == "converged"
    switch = near.index(0, 1)  # the first iteration of exact solves
    assert switch > 1 and near[0] == 0 and all(near[1:switch]) and not any(near[switch:])


@pytest.mark.parametrize("name,args,call", [
    ("cfpo-dart", ["-n", 500, "--seed", 3], lambda: cfpo.baselines.dart(500, seed=3)),
    ("cfpo-dart", ["-n", 300, "--rel-radius", 0.6], lambda: cfpo.baselines.dart(300, rel_radius=0.6)),
    ("cfpo-bs", ["-n", 500, "--seed", 4], lambda: cfpo.baselines.bs(500, seed=4)),
    ("cfpo-bs", ["--radius", 0.05], lambda: cfpo.baselines.bs(radius=0.05)),
    ("cfpo-bridson", ["-n", 500, "--seed", 5], lambda: cfpo.baselines.bridson(500, seed=5)),
    ("cfpo-bridson", ["-n", 400, "-k", 10, "--plain"], lambda: cfpo.baselines.bridson(400, k=10, plain=True)),
])
def test_poisson_baselines_same_bytes(tmp_path, command, name, args, call):
    command(name, *args, "-o", "c.npy")
    assert same_file(tmp_path, tmp_path / "c.npy", call())


@pytest.mark.parametrize("name,args,call", [
    ("cfpo-fpo", ["-n", 200, "--seed", 3, "--max-iter", 4], lambda: cfpo.baselines.fpo(200, seed=3, max_iter=4)),
    ("cfpo-fpo", ["-n", 150, "--start", "grid", "--max-iter", 3],
     lambda: cfpo.baselines.fpo(150, start="grid", max_iter=3)),
    ("cfpo-lfpo", ["-n", 200, "--seed", 2, "--max-iter", 5], lambda: cfpo.baselines.lfpo(200, seed=2, max_iter=5)),
    ("cfpo-lfpo", ["-n", 100, "--target-min", 0.8], lambda: cfpo.baselines.lfpo(100, target_min=0.8)),
    ("cfpo-ccvt", ["-n", 100, "--max-iter", 3, "--points-per-site", 64],
     lambda: cfpo.baselines.ccvt(100, max_iter=3, points_per_site=64)),
    ("cfpo-ccdt", ["-n", 200, "--seed", 6, "--max-iter", 4], lambda: cfpo.baselines.ccdt(200, seed=6, max_iter=4)),
    ("cfpo-bnot", ["-n", 200, "--seed", 7, "--max-iter", 3], lambda: cfpo.baselines.bnot(200, seed=7, max_iter=3)),
])
def test_iterative_baselines_same_bytes(tmp_path, command, name, args, call):
    out = command(name, *args, "-o", "c.npy").stdout
    r = call()
    summary = dict(f.split("=") for f in out.split()[1:])
    assert r.iterations == int(summary["iterations"]) and r.stop == summary["stop"]
    assert same_file(tmp_path, tmp_path / "c.npy", r.points)


B = cfpo.baselines


# Each method's own options (issue 24): the command's bytes, iterations and
# stop reason; and the option changes the result (so the identity shows
# that Python passes it on, not that both sides ignore it).
@pytest.mark.parametrize("name,args,call,plain", [
    ("cfpo-bnot", ["-n", 200, "--seed", 7, "--epsilon", 0, "--max-iter", 3],
     lambda: B.bnot(200, seed=7, epsilon=0, max_iter=3), lambda: B.bnot(200, seed=7, max_iter=3)),
    # epsilon 1 at n = 200, seed 3: 30 iterations in 7 rounds, the breaker
    # finding regular sites after the first; the default (0.2) ends in its
    # first round's coarse phase.
    ("cfpo-bnot", ["-n", 200, "--seed", 3, "--epsilon", 1],
     lambda: B.bnot(200, seed=3, epsilon=1), lambda: B.bnot(200, seed=3)),
    ("cfpo-bnot", ["-n", 200, "--seed", 3, "--epsilon", 1, "--no-breaker"],
     lambda: B.bnot(200, seed=3, epsilon=1, breaker=False), lambda: B.bnot(200, seed=3, epsilon=1)),
    ("cfpo-bnot", ["-n", 200, "--seed", 3, "--epsilon", 1, "--max-rounds", 2],
     lambda: B.bnot(200, seed=3, epsilon=1, max_rounds=2), lambda: B.bnot(200, seed=3, epsilon=1)),
    ("cfpo-bnot", ["-n", 200, "--seed", 3, "--epsilon", 1, "--round-iters", 4],
     lambda: B.bnot(200, seed=3, epsilon=1, round_iters=4), lambda: B.bnot(200, seed=3, epsilon=1)),
    ("cfpo-ccvt", ["-n", 100, "--max-iter", 3, "--points-per-site", 64, "--point-set", "random"],
     lambda: B.ccvt(100, max_iter=3, points_per_site=64, point_set="random"),
     lambda: B.ccvt(100, max_iter=3, points_per_site=64)),
    ("cfpo-ccvt", ["-n", 100, "--max-iter", 3, "--points-per-site", 64, "--update", "pass"],
     lambda: B.ccvt(100, max_iter=3, points_per_site=64, update="pass"),
     lambda: B.ccvt(100, max_iter=3, points_per_site=64)),
    ("cfpo-ccvt", ["-n", 100, "--max-iter", 3, "--points-per-site", 64, "--assign", "curve"],
     lambda: B.ccvt(100, max_iter=3, points_per_site=64, assign="curve"),
     lambda: B.ccvt(100, max_iter=3, points_per_site=64)),
    ("cfpo-ccdt", ["-n", 200, "--seed", 6, "--reference", 3],
     lambda: B.ccdt(200, seed=6, reference=3), lambda: B.ccdt(200, seed=6, max_iter=3)),
    ("cfpo-wse", ["-n", 300, "--seed", 4, "--progressive"],
     lambda: B.wse(300, seed=4, progressive=True), lambda: B.wse(300, seed=4)),
    ("cfpo-wse", ["-n", 300, "--seed", 4, "--ratio", 3, "--alpha", 6, "--no-weight-limit"],
     lambda: B.wse(300, seed=4, ratio=3, alpha=6, weight_limit=False), lambda: B.wse(300, seed=4)),
    ("cfpo-pmj02bn", ["-n", 300, "--seed", 4, "--candidates", 1],
     lambda: B.pmj02bn(300, seed=4, candidates=1), lambda: B.pmj02bn(300, seed=4)),
    ("cfpo-pmj02bn", ["-n", 300, "--seed", 4, "--global"],
     lambda: B.pmj02bn(300, seed=4, global_candidates=True), lambda: B.pmj02bn(300, seed=4)),
])
def test_baseline_options_same_bytes(tmp_path, command, name, args, call, plain):
    out = command(name, *args, "-o", "c.npy").stdout
    r = call()
    summary = dict(f.split("=") for f in out.split()[1:])
    assert r.iterations == int(summary["iterations"]) and r.stop == summary["stop"]
    assert same_file(tmp_path, tmp_path / "c.npy", r.points)
    assert not np.array_equal(r.points, plain().points)


def test_baseline_defaults_are_the_commands(tmp_path, command):
    """The defaults given explicitly are the defaults: the same bytes as
    the command run with none of its own options."""
    command("cfpo-bnot", "-n", 200, "--seed", 5, "--round-iters", 3, "-o", "b.npy")
    r = B.bnot(200, seed=5, epsilon=0.2, breaker=True, max_rounds=20, round_iters=3)
    assert same_file(tmp_path, tmp_path / "b.npy", r.points)
    command("cfpo-ccvt", "-n", 100, "--points-per-site", 64, "--max-iter", 2, "-o", "v.npy")
    r = B.ccvt(100, points_per_site=64, max_iter=2, point_set="lattice", update="pair", assign="nearest")
    assert same_file(tmp_path, tmp_path / "v.npy", r.points)


def stats_json(command, tmp_path, points, *extra):
    cfpo.save(tmp_path / "p.npy", points)
    command("cfpo-analyze", *extra, "-o", "out", "p.npy")
    return json.loads((tmp_path / "out" / "stats.json").read_text())


def g12(v):
    return None if v is None or not np.isfinite(v) else float(f"{v:.12g}")


def test_analysis_numbers_match_command(tmp_path, command):
    pts = cfpo.sample(400, seed=11, max_iter=30)
    js = stats_json(command, tmp_path, pts, "--certify")
    d = cfpo.analysis.deltas(pts)
    assert g12(d.delta_min) == js["delta_min"] and g12(d.delta_avg) == js["delta_avg"]
    s = cfpo.analysis.spectrum(pts)
    assert s.K == js["K"]
    assert g12(s.effective_nyquist) == js["effective_nyquist"]
    assert g12(s.oscillation) == js["oscillation"]
    assert list(s.oscillation_rings) == js["oscillation_rings"]
    assert g12(s.spike_ratio) == js["spike"]["ratio"]
    assert [*s.spike_k] == [js["spike"]["kx"], js["spike"]["ky"]]
    assert g12(s.lattice_ratio) == js["lattice"]["ratio"] and s.lattice_g == js["lattice"]["g"] == 18
    assert [*s.lattice_k] == [js["lattice"]["kx"], js["lattice"]["ky"]]
    s30 = cfpo.analysis.spectrum(pts, grid=30)
    js30 = stats_json(command, tmp_path, pts, "--grid", "30")
    assert g12(s30.lattice_ratio) == js30["lattice"]["ratio"] and s30.lattice_period == js30["lattice"]["period"] == 3
    assert np.isnan(cfpo.analysis.spectrum(pts, grid=0).lattice_ratio)
    assert s.raps_peak_ring == js["raps_peak"]["ring"] and g12(s.raps_peak) == js["raps_peak"]["raps"]
    assert g12(s.r_01) == js["effective_nyquist_detail"]["r_01"]
    c = cfpo.analysis.certify(pts)
    jc = js["certificate"]
    assert c.fpd == jc["fpd"]
    assert g12(c.summary["covering_radius"]) == jc["covering_radius"]
    assert g12(c.passed.sum() / len(pts)) == jc["farthest_point"]["pass_fraction"]
    assert g12(c.lct_passed.sum() / len(pts)) == jc["local_characterization"]["pass_fraction"]
    assert g12(c.summary["fp_max_violation"]) == jc["farthest_point"]["max_violation"]
    assert c.summary["fp_worst"] == jc["farthest_point"]["worst_point"]
    assert c.violation.argmax() == c.summary["fp_worst"]


def rows_of(path):
    return [line.split() for line in path.read_text().splitlines() if line and not line.startswith("#")]


def num(fmt, v):
    return fmt % v if np.isfinite(v) else "NaN"


def test_spectrum_raps_and_histogram_files_match(tmp_path, command):
    """raps.txt, nn_hist.txt and spectrum.txt of cfpo-analyze, written from
    Python's arrays with the command's formats: the same text."""
    pts = cfpo.baselines.dart(300, seed=2)
    stats_json(command, tmp_path, pts, "-K", 20)
    s = cfpo.analysis.spectrum(pts, 20)
    raps = rows_of(tmp_path / "out" / "raps.txt")
    assert [int(r[0]) for r in raps] == list(range(1, 21))
    for row in raps:
        i = int(row[0])
        assert row[2:] == [num("%.12g", s.raps[i]), num("%.9g", s.anisotropy_db[i]), str(s.ring_count[i])]
    d = cfpo.analysis.deltas(pts)
    hist = rows_of(tmp_path / "out" / "nn_hist.txt")
    assert [int(r[2]) for r in hist] == d.hist.tolist() and d.hist.sum() == 300
    spec = rows_of(tmp_path / "out" / "spectrum.txt")
    assert [int(v) for v in spec[0][1:]] == list(range(-20, 21))
    P = np.array([[float(v) for v in row[1:]] for row in spec[1:]])
    assert P.shape == s.power.shape == (41, 41)
    assert np.allclose(P, s.power, rtol=6e-9, atol=0)  # the file holds 9 significant digits
    # The exact sum agrees with the NUFFT as the command's --check measures.
    e = cfpo.analysis.spectrum(pts, 20, exact=True)
    assert np.max(np.abs(e.power - s.power) / np.maximum(e.power, 1)) < 1e-6
