"""cfpo.analysis.density: the numbers of `cfpo-analyze --density SPEC` for
one set (its DENSITY line, dda_raps.txt and density.txt), for a SPEC
string and for an array (the command reading it from a .npy); the
capacities sum to 1 and, with rho = 1, their deviation is the Voronoi
area variance's square root; bad input raises with the command's wording."""
import math

import numpy as np
import pytest

import cfpo


def density_line(out):
    line = next(l for l in out.splitlines() if l.startswith("DENSITY "))
    return dict(kv.split("=", 1) for kv in line.split()[1:])


def rows(path):
    return np.array([[float(v) for v in l.split()] for l in path.read_text().splitlines() if not l.startswith("#")])


@pytest.mark.parametrize("spec", ["ramp:contrast=16,res=256", "array"])
def test_same_numbers(tmp_path, command, spec):
    if spec == "array":
        y, x = np.mgrid[0:30, 0:40]
        arg = 1.0 + (x / 39.0) * 5 + (y > 12)
        np.save(tmp_path / "rho.npy", arg)
        spec = "rho.npy"
    else:
        arg = spec
    pts = cfpo.sample(1500, density=arg, max_iter=8, seed=2)
    cfpo.save(str(tmp_path / "p.npy"), pts)
    out = command("cfpo-analyze", "--density", spec, "-o", "p.an", "p.npy").stdout
    D = density_line(out)
    m = cfpo.analysis.density(pts, arg)
    for key, have in [("density_delta_min", m.delta_min), ("density_delta_avg", m.delta_avg),
                      ("count_fidelity_rms", m.count_fidelity_rms), ("count_fidelity16_max", m.count_fidelity16_max),
                      ("capacity_deviation", m.capacity_deviation), ("dda_peak", m.dda.peak),
                      ("dda_peak_freq", m.dda.peak_freq), ("dda_low", m.dda.low),
                      ("dda_aniso_db", m.dda.anisotropy_mean_db)]:
        assert math.isclose(float(D[key]), have, rel_tol=1e-5, abs_tol=1e-5), (key, D[key], have)
    assert int(D["blocks"]) == m.blocks
    r = rows(tmp_path / "p.an" / "dda_raps.txt")
    assert r.shape[0] == m.dda.K == cfpo.analysis.default_K(1500)
    np.testing.assert_allclose(r[:, 2], m.dda.raps[1:], rtol=1e-8, atol=1e-9)
    np.testing.assert_array_equal(r[:, 4], m.dda.ring_count[1:])
    h = rows(tmp_path / "p.an" / "density.txt")
    np.testing.assert_allclose(h[:, 1], m.hist / m.hist.sum(), rtol=1e-5, atol=1e-7)
    assert m.capacities.shape == (1500,) and abs(m.capacities.sum() - 1) < 1e-12
    assert m.dda.power.shape == (2 * m.dda.K + 1,) * 2 and m.dda.radius == cfpo.analysis.DDA_RADIUS
    assert 0.8 < m.dda.peak_freq < 1.3 and m.dda.peak > 1.5 and abs(m.dda.low) < 0.1


def test_uniform_reduces():
    pts = cfpo.sample(2000, max_iter=10, seed=4)
    m = cfpo.analysis.density(pts, np.ones((3, 3)), K=120)
    s = cfpo.analysis.structure(pts)
    assert math.isclose(m.capacity_deviation, math.sqrt(s.voronoi_area_var), rel_tol=1e-9)
    sp = cfpo.analysis.spectrum(pts, K=120)
    assert math.isclose(m.dda.low, sp.p0, rel_tol=0.05)
    d = cfpo.analysis.deltas(pts)
    assert math.isclose(m.delta_min, d.delta_min, rel_tol=1e-12)


@pytest.mark.parametrize("rho, err, words", [
    (None, ValueError, "required"),
    (np.ones(5), ValueError, "2-D"),
    (np.zeros((4, 4)), ValueError, "zero everywhere"),
    ("swirl", ValueError, "not an image"),
    ("missing.png", ValueError, "cannot open"),
])
def test_bad_density(rho, err, words):
    with pytest.raises(err, match=words):
        cfpo.analysis.density(np.random.default_rng(1).random((100, 2)), rho)


def test_bad_points_and_K():
    with pytest.raises(ValueError):
        cfpo.analysis.density(np.array([[0.5, 0.5]]), "cos")
    with pytest.raises(ValueError, match="K"):
        cfpo.analysis.density(np.random.default_rng(1).random((100, 2)), "cos", K=0)
    rho = np.zeros((1, 2))
    rho[0, 0] = 1  # x < 1/2 only
    off = np.column_stack([np.linspace(0.55, 0.95, 50), np.linspace(0, 0.98, 50)])
    with pytest.raises(ValueError, match="no point"):
        cfpo.analysis.density(off, rho)
