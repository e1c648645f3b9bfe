"""Every error a Python caller can make: a clear exception, never a crash."""
import numpy as np
import pytest

import cfpo


@pytest.mark.parametrize("call,exc,msg", [
    (lambda: cfpo.sample(10), ValueError, "n = 10 is too small for CFPO"),
    (lambda: cfpo.sample(0), ValueError, "n: '0' is not a whole number"),
    (lambda: cfpo.sample(1.5), TypeError, "n: expected a whole number"),
    (lambda: cfpo.sample("100"), TypeError, "n: expected a whole number"),
    (lambda: cfpo.sample(), ValueError, "the number of points is required"),
    (lambda: cfpo.sample(100, variant="fast"), ValueError, "variant: 'fast' is not one of adaptive, paper"),
    (lambda: cfpo.sample(100, threads=0), ValueError, "threads: '0' is not a whole number in 1..4096"),
    (lambda: cfpo.sample(100, tol=0.5), ValueError, "tol: '0.5' is not a number in [0, 0.49]"),
    (lambda: cfpo.sample(100, tol=float("nan")), ValueError, "tol"),
    (lambda: cfpo.sample(100, max_iter=-1), ValueError, "max_iter"),
    (lambda: cfpo.sample(100, target_min=0), ValueError, "target_min: '0' is not a number in (0, 1]"),
    (lambda: cfpo.sample(100, target_avg=2), ValueError, "target_avg"),
    (lambda: cfpo.sample(100, time_limit=-1), ValueError, "time_limit"),
    (lambda: cfpo.sample(100, seed=-1), ValueError, "seed"),
    (lambda: cfpo.sample(100, seed=2**64), ValueError, "seed"),
    (lambda: cfpo.sample(100, progress=3), TypeError, "progress"),
    (lambda: cfpo.sample(2**40), ValueError, "too large for one process"),
    (lambda: cfpo.sample(3 * 10**9), MemoryError, "too large for memory"),
    (lambda: cfpo.sample(50, init=np.full((40, 2), 0.5)), ValueError, "the array holds 40 points, n says 50"),
    (lambda: cfpo.baselines.fpo(10), ValueError, "too small"),
    (lambda: cfpo.baselines.ccvt(10), ValueError, "too small"),
    (lambda: cfpo.baselines.fpo(100, start="x"), ValueError, "start: 'x' is not one of random, grid"),
    (lambda: cfpo.baselines.bnot(100, epsilon=-0.1), ValueError, "epsilon: '-0.1' is not a number in [0, 1000]"),
    (lambda: cfpo.baselines.bnot(100, epsilon=float("inf")), ValueError, "epsilon"),
    (lambda: cfpo.baselines.bnot(100, epsilon="0.2"), TypeError, "epsilon: expected a number"),
    (lambda: cfpo.baselines.bnot(100, max_rounds=0), ValueError, "max_rounds: '0' is not a whole number in 1..1000000"),
    (lambda: cfpo.baselines.bnot(100, round_iters=10**6 + 1), ValueError, "round_iters: '1000001' is not a whole"),
    (lambda: cfpo.baselines.bnot(100, round_iters=2.0), TypeError, "round_iters: expected a whole number"),
    (lambda: cfpo.baselines.bnot(100, breaker="no"), TypeError, "breaker: expected True or False"),
    (lambda: cfpo.baselines.bnot(10), ValueError, "too small"),
    (lambda: cfpo.baselines.ccvt(100, point_set="grid"), ValueError, "point_set: 'grid' is neither lattice nor random"),
    (lambda: cfpo.baselines.ccvt(100, update="site"), ValueError, "update: 'site' is neither pair nor pass"),
    (lambda: cfpo.baselines.ccvt(100, assign="random"), ValueError, "assign: 'random' is neither nearest nor curve"),
    (lambda: cfpo.baselines.ccvt(100, assign=1), TypeError, "assign: expected a string, nearest or curve"),
    (lambda: cfpo.baselines.ccvt(101, points_per_site=1), ValueError, "n m = 101 points have no lattice"),
    (lambda: cfpo.baselines.ccvt(100, points_per_site=0), ValueError, "points_per_site: '0' is not a whole number"),
    (lambda: cfpo.baselines.ccdt(100, reference=0), ValueError,
     "reference: '0' is not a whole number in 1..1000000000"),
    (lambda: cfpo.baselines.ccdt(100, reference=True), TypeError, "reference: expected a whole number"),
    (lambda: cfpo.baselines.dart(100, rel_radius=1.9), RuntimeError, "saturated"),
    (lambda: cfpo.baselines.bs(), ValueError, "n or radius is required"),
    (lambda: cfpo.baselines.bs(100, radius=0.3), ValueError, "too large for the unit torus"),
    (lambda: cfpo.baselines.bs(100, radius=0.01, rel_radius=0.5), ValueError, "not both"),
    (lambda: cfpo.analysis.spectrum(np.full((5, 2), 0.5), K=0), ValueError, "K: '0'"),
    (lambda: cfpo.analysis.spectrum(np.full((5, 2), 0.5), width=3), ValueError, "width"),
    (lambda: cfpo.analysis.spectrum(np.full((5, 2), 0.5), grid=-1), ValueError, "grid: '-1'"),
    (lambda: cfpo.analysis.spectrum(np.full((5, 2), 0.5), grid=1.5), TypeError, "grid"),
    (lambda: cfpo.analysis.certify(np.full((5, 2), 0.5), tol=2), ValueError, "tol"),
])
def test_bad_arguments(call, exc, msg):
    with pytest.raises(exc) as e:
        call()
    assert msg in str(e.value)


@pytest.mark.parametrize("points,exc,msg", [
    (np.zeros((5, 4)), ValueError, "expected an (n, 2) or (n, 3) array of points, got shape (5, 4)"),
    (np.zeros(10), ValueError, "got shape (10,)"),
    (np.zeros((2, 5, 2)), ValueError, "got shape (2, 5, 2)"),
    (np.array([[0.5, np.nan], [0.1, 0.1]]), ValueError, "point 0 is not finite"),
    (np.array([[0.5, 0.5], [0.1, np.inf]]), ValueError, "point 1 is not finite"),
    (np.array([[0.5, 0.5], [1.0, 0.1]]), ValueError, "point 1 (1.0, 0.1) is outside [0,1)^2"),
    (np.array([[-0.1, 0.5], [0.1, 0.1]]), ValueError, "outside"),
    (np.array([[0.5, 0.5]]), ValueError, "1 points; at least 2 needed"),
    (np.zeros((0, 2)), ValueError, "0 points"),
    (np.zeros((4, 2), dtype=complex), TypeError, "np.asarray(points, dtype=np.float64)"),
    (np.zeros((4, 2), dtype=bool), TypeError, "is not a real number type"),
    (np.array([["a", "b"]]), TypeError, "is not a real number type"),
    (np.array([[0.1, None]], dtype=object), TypeError, "is not a real number type"),
    ([[0.1, 0.2], [0.3]], TypeError, "cannot be read as an array of numbers"),
])
def test_bad_point_arrays(points, exc, msg):
    for f in (cfpo.analysis.deltas, cfpo.analysis.certify):
        with pytest.raises(exc) as e:
            f(points)
        assert msg in str(e.value)


def test_any_dtype_and_layout_is_converted():
    p = cfpo.baselines.dart(300, seed=1)
    ref = cfpo.analysis.spectrum(p, 16).power
    for q in (np.asfortranarray(p), np.repeat(p, 2, axis=0)[::2], p.tolist(), p.astype(np.longdouble)):
        assert np.array_equal(cfpo.analysis.spectrum(q, 16).power, ref)
    ints = np.zeros((3, 2), dtype=np.int32)  # integers in [0,1): zeros only
    assert np.array_equal(cfpo.analysis.spectrum(ints, 4).power, cfpo.analysis.spectrum(ints * 0.0, 4).power)
    f32 = p.astype(np.float32)
    assert np.array_equal(cfpo.analysis.spectrum(f32, 16).power,
                          cfpo.analysis.spectrum(f32.astype(np.float64), 16).power)


def test_file_errors(tmp_path):
    with pytest.raises(OSError, match="cannot open"):
        cfpo.load(tmp_path / "missing.npy")
    with pytest.raises(ValueError, match="unknown point file format"):
        cfpo.load(tmp_path / "x.png")
    (tmp_path / "bad.csv").write_text("x,y\n0.5;0.5\n")
    with pytest.raises(ValueError, match="line 2: expected two numbers"):
        cfpo.load(tmp_path / "bad.csv")
    (tmp_path / "t.npy").write_bytes(b"\x93NUMPY\x01\x00" + b"garbage")
    with pytest.raises(ValueError, match="t.npy"):
        cfpo.load(tmp_path / "t.npy")
    with pytest.raises(OSError, match="nodir"):
        cfpo.save(tmp_path / "nodir" / "x.npy", np.full((3, 2), 0.5))
    with pytest.raises(ValueError, match="unknown output format"):
        cfpo.save(tmp_path / "x.jpeg", np.full((3, 2), 0.5))
    with pytest.raises(ValueError, match="outside"):
        cfpo.save(tmp_path / "x.npy", np.full((3, 2), 1.5))
    assert sorted(p.name for p in tmp_path.iterdir()) == ["bad.csv", "t.npy"]  # nothing left behind
