"""The baselines under a density from Python: the same bytes as
`cfpo-dart / cfpo-fpo / cfpo-lfpo / cfpo-ccvt / cfpo-bnot --density SPEC`, a 2-D array
giving the same points as the .npy file holding it, and the commands' bad
input as ValueError."""
import numpy as np
import pytest

import cfpo

B = cfpo.baselines


def summary(out):
    return dict(f.split("=", 1) for f in out.splitlines()[0].split()[1:])


@pytest.mark.parametrize("method,args", [
    ("dart", dict(n=800, seed=3)),
    ("fpo", dict(n=500, seed=2, max_iter=8)),
    ("lfpo", dict(n=500, seed=2, max_iter=8)),
    ("ccvt", dict(n=200, seed=4, max_iter=5, points_per_site=32)),
    ("bnot", dict(n=400, seed=2, max_iter=6)),
])
@pytest.mark.parametrize("spec", ["cos:a=0.9", "ramp:contrast=16"])
def test_same_bytes_as_command(tmp_path, command, method, args, spec):
    opts = {"n": "-n", "seed": "--seed", "max_iter": "--max-iter", "points_per_site": "--points-per-site"}
    argv = [x for k, v in args.items() for x in (opts[k], v)]
    out = command("cfpo-" + method, *argv, "--density", spec, "-o", "c.npy").stdout
    kw = dict(args)
    n = kw.pop("n")
    r = getattr(B, method)(n, density=spec, **kw)
    pts = r if method == "dart" else r.points
    assert (tmp_path / "c.npy").read_bytes()[128:] == np.ascontiguousarray(pts).tobytes()
    if method != "dart":
        s = summary(out)
        assert f"{r.delta_min:.6f}" == s["delta_min"] and f"{r.delta_avg:.6f}" == s["delta_avg"]


def test_array_density_is_the_npy_file(tmp_path, command):
    rho = np.linspace(1.0, 8.0, 64)[None, :] * np.ones((32, 1))
    np.save(tmp_path / "rho.npy", rho)
    command("cfpo-fpo", "-n", 400, "--max-iter", 5, "--density", "rho.npy", "-o", "c.npy")
    r = B.fpo(400, max_iter=5, density=rho)
    assert (tmp_path / "c.npy").read_bytes()[128:] == r.points.tobytes()


def test_uniform_density_is_the_baseline():
    assert np.array_equal(B.dart(600, seed=2, density="cos:a=0"), B.dart(600, seed=2))
    assert np.array_equal(B.fpo(300, max_iter=6, density=np.ones((4, 4))).points, B.fpo(300, max_iter=6).points)
    assert np.array_equal(B.bnot(300, max_iter=6, density="cos:a=0").points, B.bnot(300, max_iter=6).points)
    assert np.array_equal(B.bnot(300, max_iter=4, epsilon=0, density=np.ones((3, 5))).points,
                          B.bnot(300, max_iter=4, epsilon=0).points)


def test_bnot_density_capacities():
    """BNOT under a non-uniform array density: exactly n points, its deltas
    the measure's (cfpo.analysis.density's), the trace's capacity error
    within the run to tol's 1e-8 after every iteration."""
    rho = np.linspace(1.0, 12.0, 48)[None, :] * np.ones((16, 1))
    r = B.bnot(500, seed=3, max_iter=5, epsilon=0, density=rho)
    assert r.points.shape == (500, 2)
    assert max(r.trace["cap_err"]) <= 1e-8
    m = cfpo.analysis.density(r.points, rho)
    assert abs(m.delta_min - r.delta_min) < 1e-12 and abs(m.delta_avg - r.delta_avg) < 1e-12


def test_bad_density():
    with pytest.raises(ValueError, match="contrast 1:1000"):
        B.dart(1000, density="ramp:contrast=1000")
    with pytest.raises(ValueError, match="not an image"):
        B.fpo(1000, density="swirl")
    with pytest.raises(ValueError, match="too small for this density"):
        B.fpo(50, density="ramp:contrast=200")
    with pytest.raises(ValueError, match="start grid"):
        B.fpo(500, density="cos", start="grid")
    with pytest.raises(ValueError, match="not an image"):
        B.bnot(1000, density="swirl")
    with pytest.raises(ValueError, match="contrast 1:1000"):
        B.bnot(1000, density="ramp:contrast=1000")
    with pytest.raises(TypeError):  # no density= where the command has no --density
        B.ccdt(500, density="cos")
    with pytest.raises(TypeError):
        B.bs(500, density="cos")
    assert {k for k, m in B.METHODS.items() if m["density"]} == {"dart", "fpo", "lfpo", "ccvt", "bnot"}
