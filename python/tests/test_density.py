"""density=: the same bytes as `cfpo --density SPEC`, for a SPEC string and
for an array (the command reading it from a .npy); bad densities raise
ValueError with the command's wording."""
import numpy as np
import pytest

import cfpo


@pytest.mark.parametrize("spec", ["cos:a=0.9", "ramp:contrast=16,res=256"])
def test_spec_same_bytes(tmp_path, command, spec):
    command("cfpo", "-n", 1500, "--density", spec, "--max-iter", 6, "--seed", 3, "-o", "c.npy")
    pts = cfpo.sample(1500, density=spec, max_iter=6, seed=3)
    assert (tmp_path / "c.npy").read_bytes()[128:] == pts.tobytes()


def test_array_same_bytes(tmp_path, command):
    y, x = np.mgrid[0:40, 0:50]
    rho = 1.0 + (x / 49.0) * 7 + (y > 20)
    np.save(tmp_path / "rho.npy", rho)
    command("cfpo", "-n", 1200, "--density", "rho.npy", "--max-iter", 5, "-o", "c.npy")
    r = cfpo.run(1200, density=rho, max_iter=5)
    assert (tmp_path / "c.npy").read_bytes()[128:] == r.points.tobytes()
    assert r.iterations == 5 and len(r.trace["iteration"]) == 6


@pytest.mark.parametrize("rho, words", [
    (np.zeros((4, 4)), "zero everywhere"),
    (np.array([[1.0, -1.0]]), "non-negative"),
    (np.array([[1.0, np.nan]]), "non-negative"),
    (np.array([[1.0, 1000.0]]), "beyond the limit"),
    ("swirl", "not an image"),
])
def test_bad_density(rho, words):
    with pytest.raises(ValueError, match=words):
        cfpo.sample(1000, density=rho, max_iter=1)


def test_bad_shape_and_variant():
    with pytest.raises(ValueError, match="2-D"):
        cfpo.sample(1000, density=np.ones(5))
    with pytest.raises(ValueError, match="variant"):
        cfpo.sample(1000, density="cos", variant="paper")


@pytest.mark.parametrize("spec, max_iter", [("ramp:contrast=64,res=256", 21), ("cos:a=0.9", None)])
def test_lazy_measure_same_run(spec, max_iter):
    """sample() asks for no trace, so the density engine measures only at the
    stop rule's windows and the end; run() (with its trace) measures every
    iteration: the same points, and to the run's own stop the same
    iterations (docs/method.md, "Density", item 3)."""
    r = cfpo.run(1024, density=spec, max_iter=max_iter, seed=5, threads=2)
    seen = []
    lazy = cfpo.sample(1024, density=spec, max_iter=max_iter, seed=5, threads=2)
    assert lazy.tobytes() == r.points.tobytes()
    cb = cfpo.run(1024, density=spec, max_iter=max_iter, seed=5, threads=2,
                  progress=lambda s: seen.append(s["iteration"]) and False)
    assert cb.points.tobytes() == r.points.tobytes()
    assert (cb.delta_min, cb.delta_avg, cb.iterations) == (r.delta_min, r.delta_avg, r.iterations)
    assert seen == list(range(r.iterations + 1))
