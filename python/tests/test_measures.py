"""The measures of analysis/measures/ from Python: the numbers of
cfpo-analyze's stats.json for the same set (low-frequency measures, shift
variances, discrepancies), and their bad input."""
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
