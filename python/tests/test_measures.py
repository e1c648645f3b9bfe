"""The measures of analysis/measures/ from Python: the numbers of
cfpo-analyze's stats.json for the same set (low-frequency measures, shift
variances, discrepancies, the prefix measures), and their bad input."""
import json

import numpy as np
import pytest

import cfpo


def g12(v):
    return None if v is None or not np.isfinite(v) else float(f"{v:.12g}")


def test_measures_match_command(tmp_path, command):
    pts = cfpo.sample(500, seed=12, max_iter=30)
    cfpo.save(tmp_path / "p.npy", pts)
    command("cfpo-analyze", "-o", "out", "p.npy")
    js = json.loads((tmp_path / "out" / "stats.json").read_text())
    s = cfpo.analysis.spectrum(pts)
    lf = js["low_frequency"]
    assert g12(s.p0) == lf["P0"] and g12(s.h_index) == lf["H"] and g12(s.lowk_alpha) == lf["alpha"]
    assert s.low_frequency["p0_count"] == lf["P0_count"] and s.low_frequency["peak_ring"] == lf["peak_ring"]
    for name, (var, tail) in s.shift_variance.items():
        assert g12(var) == js["shift_variance"][name]["var"] and g12(tail) == js["shift_variance"][name]["tail"]
    assert len(s.shift_variance) == 6
    d = cfpo.analysis.discrepancy(pts)
    jd = js["discrepancy"]
    assert g12(d.wrap_l2) == jd["wrap_around_l2"] and g12(d.diaphony) == jd["diaphony"]
    assert g12(d.l2_star) == jd["l2_star"] and g12(d.generalized_l2) == jd["generalized_l2"]
    assert g12(d.centred_l2) == jd["centred_l2"]


def test_discrepancy_properties():
    rng = np.random.default_rng(3)
    pts = rng.random((700, 2))
    d = cfpo.analysis.discrepancy(pts)
    shifted = cfpo.analysis.discrepancy(np.mod(pts + [0.25, 0.625], 1.0))
    assert shifted.wrap_l2 == pytest.approx(d.wrap_l2, rel=1e-9)
    assert shifted.diaphony == pytest.approx(d.diaphony, rel=1e-9)
    # white noise: E[WD^2] = (9/4 - 16/9) / n, over 40 sets of 300 points
    wd2 = np.mean([cfpo.analysis.discrepancy(rng.random((300, 2))).wrap_l2 ** 2 for _ in range(40)])
    assert wd2 == pytest.approx((2.25 - 16 / 9) / 300, rel=0.2)
    with pytest.raises(ValueError):
        cfpo.analysis.discrepancy(np.array([[0.5, 1.5]]))


def test_structure_match_command(tmp_path, command):
    pts = cfpo.sample(500, seed=12, max_iter=30)
    cfpo.save(tmp_path / "p.npy", pts)
    command("cfpo-analyze", "-o", "out", "--integration", "64", "p.npy")
    js = json.loads((tmp_path / "out" / "stats.json").read_text())
    st = cfpo.analysis.structure(pts)
    jd = js["delaunay"]
    assert g12(st.psi6) == jd["psi6"] and g12(st.voronoi_area_var) == jd["voronoi_area_var"]
    assert g12(st.mesh_ratio) == jd["mesh_ratio"] and g12(st.covering_radius) == jd["covering_radius"]
    assert st.delta_min == pytest.approx(cfpo.analysis.deltas(pts).delta_min, rel=1e-12)
    r, g = cfpo.analysis.pcf(pts)
    rows = np.loadtxt(tmp_path / "out" / "pcf.txt")
    assert len(r) == len(rows) == 300
    assert np.allclose(rows[:, 0], r, rtol=1e-6) and np.allclose(rows[:, 1], g, rtol=1e-11, atol=1e-300)
    it = cfpo.analysis.integration(pts, M=64)
    ji = js["integration"]
    assert ji["integrands"] == 64
    assert g12(it.gauss_mse) == ji["gauss"]["mse"] and g12(it.heaviside_mse) == ji["heaviside"]["mse"]


def test_structure_properties():
    # a hexagonal lattice (26 x 30, stretched by 0.08% to fit the square)
    i, j = np.meshgrid(np.arange(26), np.arange(30))
    lat = np.column_stack([((i + 0.5 * (j % 2)) / 26).ravel(), (j / 30).ravel()])
    st = cfpo.analysis.structure(lat)
    assert st.psi6 > 0.9999 and abs(st.voronoi_area_var) < 1e-12
    assert st.mesh_ratio == pytest.approx(2 / np.sqrt(3), rel=2e-3)
    rng = np.random.default_rng(4)
    white = rng.random((20000, 2))
    assert cfpo.analysis.structure(white).psi6 == pytest.approx(0.365, abs=0.01)
    r, g = cfpo.analysis.pcf(white)
    assert np.mean(g[(r >= 1) & (r <= 3)]) == pytest.approx(1, abs=0.02)
    iw = cfpo.analysis.integration(rng.random((1024, 2)), M=256)
    ij = cfpo.analysis.integration(cfpo.sample(1024, seed=3, max_iter=30), M=256)
    assert ij.gauss_mse < 0.1 * iw.gauss_mse and ij.heaviside_mse < 0.5 * iw.heaviside_mse
    with pytest.raises(ValueError):
        cfpo.analysis.structure(np.array([[0.1, 0.2], [0.1, 0.2], [0.5, 0.5]]))
    with pytest.raises(ValueError):
        cfpo.analysis.pcf(white, sigma=0)
    with pytest.raises(ValueError):
        cfpo.analysis.integration(white, M=0)


def test_prefixes_match_command(tmp_path, command):
    """cfpo.analysis.prefixes gives the rows of cfpo-analyze --prefixes."""
    pts = cfpo.baselines.wse(300, seed=4, progressive=True).points
    cfpo.save(tmp_path / "p.npy", pts)
    out = command("cfpo-analyze", "--no-discrepancy", "--no-delaunay", "--integration", "0", "--prefixes",
                  "-o", "out", "p.npy")
    rows = [l.split() for l in (tmp_path / "out" / "prefixes.txt").read_text().splitlines() if l[0] != "#"]
    p = cfpo.analysis.prefixes(pts)
    assert [r.m for r in p.rows] == [int(r[0]) for r in rows]
    for r, c in zip(p.rows, rows):
        assert r.kind == c[1] and f"{r.delta_min:.6f}" == c[2] and f"{r.delta_avg:.6f}" == c[3]
        assert f"{r.p0:.6g}" == c[4]
        assert [f"{v:.6g}" for v in r.shiftvar.values()] == c[5:]
    summary = dict(kv.split("=", 1) for kv in out.stdout.split() if "=" in kv)
    assert f"{p.worst_any:.6f}" == summary["prefix_worst_any_dmin"]
    assert str(p.worst_any_m) == summary["prefix_worst_any_m"]
    given = cfpo.analysis.prefixes(pts, sizes=[100, 20])
    assert [r.m for r in given.rows] == [20, 100] and given.rows[0].kind == "given"


def test_prefixes_bad_input():
    pts = np.random.default_rng(5).random((100, 2))
    with pytest.raises(ValueError, match="base"):
        cfpo.analysis.prefixes(pts, base=200)
    with pytest.raises(ValueError):
        cfpo.analysis.prefixes(pts, sizes=[1])
    with pytest.raises(ValueError, match="101"):
        cfpo.analysis.prefixes(pts, sizes=[101])
    with pytest.raises(TypeError):
        cfpo.analysis.prefixes(pts, sizes=[2.5])
