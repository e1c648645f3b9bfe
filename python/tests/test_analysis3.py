"""cfpo.analysis on (n, 3) sets: the numbers of cfpo3d-analyze for the same
file (its ANALYZE3D line, its spectrum and g(r) files, to the digits it
prints), with default and non-default options; Steinhardt's Q6 and W6,
the crystal-like fraction, delta and the Voronoi face count of the FCC,
BCC and simple cubic lattices against their known values; the spectrum's
exact sum against the NUFFT; and bad input refused with ValueError."""
import subprocess

import numpy as np
import pytest

import cfpo
from cfpo import analysis


def analyze3d(build, cwd, *args):
    """The ANALYZE3D line of cfpo3d-analyze as a dict of strings."""
    out = subprocess.run([str(build / "cfpo3d-analyze"), *map(str, args)], cwd=cwd, check=True,
                         capture_output=True, text=True).stdout
    line = out.splitlines()[0].split()
    assert line[0] == "ANALYZE3D"
    return dict(f.split("=") for f in line[1:])


def tsv(path):
    return [row.split("\t") for row in path.read_text().splitlines()[1:]]


def lattice(kind, m):
    """The FCC, BCC or simple cubic lattice of m cells a side in [0, 1)^3."""
    basis = {"fcc": [(0, 0, 0), (0.5, 0.5, 0), (0.5, 0, 0.5), (0, 0.5, 0.5)],
             "bcc": [(0, 0, 0), (0.5, 0.5, 0.5)], "sc": [(0, 0, 0)]}[kind]
    cells = np.stack(np.meshgrid(*[np.arange(m)] * 3, indexing="ij"), -1).reshape(-1, 3)
    return np.concatenate([(cells + np.array(b)) / m for b in basis])


@pytest.fixture(scope="module")
def set3():
    """A partly optimised set, a white-noise one, and a jittered FCC lattice
    whose half x < 1/2 is white noise (some crystal-like points, not all)."""
    rng = np.random.default_rng(5)
    half = (lattice("fcc", 5) + rng.normal(0, 0.003, (500, 3))) % 1.0
    half[half[:, 0] < 0.5] = rng.random((int((half[:, 0] < 0.5).sum()), 3)) * [0.5, 1, 1]
    return {"cfpo": cfpo.sample(600, dim=3, seed=4, max_iter=6),
            "white": np.random.default_rng(11).random((500, 3)), "half": half}


@pytest.mark.parametrize("name", ["cfpo", "white", "half"])
def test_matches_command_defaults(build, tmp_path, set3, name):
    pts = set3[name]
    np.save(tmp_path / "p.npy", pts)
    s = analyze3d(build, tmp_path, "--spectrum", "s.tsv", "--pcf", "g.tsv", "--voronoi", "--certify", "p.npy")
    d = analysis.deltas(pts)
    assert d.hist is None and d.nn.shape == (len(pts),)
    assert f"{d.delta_min:.6f}" == s["delta_min"] and f"{d.delta_avg:.6f}" == s["delta_avg"]
    assert np.isclose(d.nn.min() / cfpo._analysis3.delta3(len(pts)), d.delta_min, rtol=1e-12)
    b = analysis.bond_order(pts)
    assert f"{b.q6_global:.6f}" == s["q6_global"] and f"{b.q6_local:.6f}" == s["q6_local"]
    assert str(b.crystal_like) == s["crystal_like"] and f"{b.crystal_fraction:.6f}" == s["crystal_fraction"]
    if name == "half":
        assert 0.2 < b.crystal_fraction < 0.8
    assert f"{b.w6:.6f}" == s["w6"] and f"{b.w6_local:.6f}" == s["w6_local"]
    sp = analysis.spectrum(pts)
    assert isinstance(sp, analysis.Spectrum3) and str(sp.K) == s["kmax"]
    assert sp.power.shape == (2 * sp.K + 1,) * 3
    assert f"{sp.p0:.6g}" == s["p0"] and f"{sp.peak:.6g}" == s["peak"] and str(sp.peak_shell) == s["peak_shell"]
    assert tsv(tmp_path / "s.tsv") == [[str(i), f"{sp.shell[i]:.6g}", str(sp.shell_count[i])]
                                       for i in range(1, sp.K + 1)]
    r, g = analysis.pcf(pts)
    assert f"{g.max():.4f}" == s["pcf_peak"] and f"{r[np.argmax(g)]:.3f}" == s["pcf_peak_r"]
    assert tsv(tmp_path / "g.tsv") == [[f"{x:.4f}", f"{y:.6g}"] for x, y in zip(r, g)]
    v = analysis.structure(pts)
    assert f"{v.faces_mean:.4f}" == s["vor_faces"] and f"{v.faces_sd:.4f}" == s["vor_faces_sd"]
    assert f"{v.volume_var:.6g}" == s["vor_volume_var"]
    assert np.isclose(v.volumes.sum(), 1, rtol=0, atol=1e-9) and v.faces.mean() == pytest.approx(v.faces_mean)
    c = analysis.certify(pts)
    assert ("yes" if c.fpd else "no") == s["fpd_pass"] and str(c.passed) == s["fpd_points"]
    assert f"{c.max_violation:.3g}" == s["fpd_max_violation"]
    assert c.violation.shape == (len(pts),) and c.violation.max() == c.max_violation
    assert np.count_nonzero(c.violation > 1e-9) <= len(pts) - c.passed <= np.count_nonzero(c.violation > -1e-9)


def test_certificate_per_point():
    """FCC passes at every point (violation 0); one point moved: it fails,
    and every point farther than 0.3 from it keeps violation 0 (its own
    lattice hole is the largest empty sphere without it)."""
    q = lattice("fcc", 4)
    c = analysis.certify(q)
    assert c.fpd and np.all(np.abs(c.violation) < 1e-9)
    q[17, 0] = (q[17, 0] + 0.03 * 0.25 / np.sqrt(2)) % 1.0
    c = analysis.certify(q)
    d = np.abs(q - q[17])
    d = np.sqrt((np.minimum(d, 1 - d) ** 2).sum(axis=1))
    assert not c.fpd and c.violation[17] > 1e-3 and c.violation.max() == c.max_violation
    assert np.all(np.abs(c.violation[d > 0.3]) < 1e-9)


def test_matches_command_options(build, tmp_path, set3):
    pts = set3["cfpo"]
    np.savetxt(tmp_path / "p.txt", pts, fmt="%.17g")  # the text reader gives back the same doubles
    s = analyze3d(build, tmp_path, "--neighbours", 14, "--bond", 0.6, "--bonds", 6, "--spectrum", "s.tsv",
                  "--kmax", 10, "--exact", "p.txt")
    b = analysis.bond_order(pts, neighbours=14, bond=0.6, bonds=6)
    assert (b.neighbours, b.bond, b.bonds) == (14, 0.6, 6) == (int(s["neighbours"]), float(s["bond"]),
                                                               int(s["bonds"]))
    assert f"{b.q6_global:.6f}" == s["q6_global"] and str(b.crystal_like) == s["crystal_like"]
    assert f"{b.w6:.6f}" == s["w6"]
    sp = analysis.spectrum(pts, K=10, exact=True)
    assert sp.K == 10 and f"{sp.p0:.6g}" == s["p0"] and f"{sp.peak:.6g}" == s["peak"]
    assert tsv(tmp_path / "s.tsv") == [[str(i), f"{sp.shell[i]:.6g}", str(sp.shell_count[i])] for i in range(1, 11)]


def test_spectrum_exact_and_nufft_agree(set3):
    pts = set3["white"]
    e, f = analysis.spectrum(pts, K=9, exact=True), analysis.spectrum(pts, K=9)
    assert e.shell[0] == pytest.approx(len(pts)) and e.power[9, 9, 9] == pytest.approx(len(pts))
    assert np.allclose(e.power, f.power, rtol=0, atol=1e-6 * len(pts))
    # P(k) = P(-k): the array is symmetric through its centre
    assert np.allclose(e.power, e.power[::-1, ::-1, ::-1], rtol=1e-12, atol=1e-9)
    # a direct sum at one frequency
    k = np.array([2, -3, 1])
    direct = abs(np.exp(-2j * np.pi * pts @ k).sum()) ** 2 / len(pts)
    assert e.power[1 + 9, -3 + 9, 2 + 9] == pytest.approx(direct, rel=1e-9)


@pytest.mark.parametrize("kind, m, k, q6, w6, faces", [
    ("fcc", 4, 12, 0.5745, -0.013161, 12),
    ("bcc", 5, 14, 0.5107, 0.013161, 14),
    ("sc", 6, 6, 0.3536, 0.013161, 6),
])
def test_lattices(kind, m, k, q6, w6, faces):
    pts = lattice(kind, m)
    b = analysis.bond_order(pts, neighbours=k, bonds=min(k, 8))  # 6 neighbours give at most 6 bonds
    assert abs(b.q6_global - q6) < 1e-3 and abs(b.q6_local - q6) < 1e-3
    assert abs(b.w6 - w6) < 1e-5
    assert b.crystal_like == len(pts) and b.crystal_fraction == 1
    v = analysis.structure(pts)
    assert np.all(v.faces == faces) and v.volume_var < 1e-12
    if kind == "fcc":  # FCC scores 1: Delta3(n) is its spacing
        d = analysis.deltas(pts)
        assert d.delta_min == pytest.approx(1, abs=1e-12) and d.delta_avg == pytest.approx(1, abs=1e-12)


def test_amorphous_set_is_not_crystal_like():
    b = analysis.bond_order(np.random.default_rng(3).random((400, 3)))
    assert b.q6_global < 0.1 and b.crystal_fraction < 0.05


@pytest.mark.parametrize("call, pat", [
    (lambda: analysis.deltas(np.full((50, 4), 0.5)), r"\(n, 2\) or \(n, 3\)"),
    (lambda: analysis.spectrum(np.full((50, 4), 0.5)), r"\(n, 2\) or \(n, 3\)"),
    (lambda: analysis.bond_order(np.full((50, 4), 0.5)), r"\(n, 2\) or \(n, 3\)"),
    (lambda: analysis.deltas(np.where(np.arange(150).reshape(50, 3) == 7, np.nan, 0.5)), "not finite"),
    (lambda: analysis.bond_order(np.where(np.arange(150).reshape(50, 3) == 7, np.inf, 0.5)), "not finite"),
    (lambda: analysis.pcf(np.full((50, 3), 1.0)), "outside"),
    (lambda: analysis.deltas(np.full((1, 3), 0.5)), "at least 2"),
    (lambda: analysis.bond_order(np.random.default_rng(1).random((12, 3))), "more than neighbours = 12"),
    (lambda: analysis.bond_order(np.random.default_rng(1).random((40, 3)), neighbours=65), "neighbours"),
    (lambda: analysis.pcf(np.full((1, 3), 0.5)), "at least 2"),
    (lambda: analysis.pcf(np.random.default_rng(1).random((30, 3)), rmax=0.2, dr=0.5), "no bin of width"),
    (lambda: analysis.spectrum(np.random.default_rng(1).random((30, 3)), K=129), "K"),
    (lambda: analysis.spectrum(np.random.default_rng(1).random((30, 3)), width=8), "width: does not apply"),
    (lambda: analysis.pcf(np.random.default_rng(1).random((30, 3)), sigma=0.1), "sigma: does not apply"),
    (lambda: analysis.certify(np.random.default_rng(1).random((30, 3)), tol=0.01), "tol: does not apply"),
    (lambda: analysis.pcf(np.random.default_rng(1).random((30, 2)), dr=0.1), "dr: applies to 3-D"),
    (lambda: analysis.bond_order(np.random.default_rng(1).random((30, 2))), r"\(n, 3\)"),
    (lambda: analysis.structure(np.full((30, 3), 0.5)), "duplicate points"),
    (lambda: analysis.structure(np.random.default_rng(1).random((5, 3))), "too few or too uneven"),
    (lambda: analysis.certify(np.full((50, 3), 0.5)), "duplicate points"),
    (lambda: analysis.certify(np.random.default_rng(1).random((30, 3))), "too few"),
])
def test_bad_input(call, pat):
    with pytest.raises(ValueError, match=pat):
        call()
