"""dim=3: cfpo.sample / cfpo.run on the unit 3-torus give the bytes of
`cfpo --dim 3 ... -o x.npy` (and of cfpo3d), for any thread count, from n
or from an (n, 3) start; the run's statistics are the command's; bad
arguments are refused with the command's wording; the command's extended
XYZ and LAMMPS files read back with ASE (when installed) as the points
times the box, with the periodic cell, and its .gro file (nm, 3 decimals)
as the points times the box in Angstrom to 0.005."""
import numpy as np
import pytest

import cfpo


def npy_body(path):
    data = path.read_bytes()
    assert b"'shape': (" in data[:128] and b", 3)" in data[:128]
    return data[128:]


@pytest.mark.parametrize("args", [
    dict(n=324, seed=5, max_iter=5),
    dict(n=200, seed=2, tol=0.001, threads=1),
    dict(n=324, seed=3, target_min=0.8),
])
def test_sample3_same_bytes(tmp_path, command, args):
    opts = {"n": "-n", "seed": "--seed", "max_iter": "--max-iter", "tol": "--tol", "target_min": "--target-min",
            "threads": "--threads"}
    argv = [x for k, v in args.items() for x in (opts[k], v)]
    command("cfpo", "--dim", 3, *argv, "-o", "c.npy")
    kw = dict(args)
    n = kw.pop("n")
    pts = cfpo.sample(n, dim=3, **kw)
    assert pts.shape == (n, 3) and pts.dtype == np.float64 and pts.flags.c_contiguous
    assert npy_body(tmp_path / "c.npy") == pts.tobytes()
    command("cfpo3d", *argv, "-o", "d.npy")
    assert (tmp_path / "d.npy").read_bytes() == (tmp_path / "c.npy").read_bytes()


def test_sample3_threads_and_init(tmp_path, command):
    a = cfpo.sample(324, dim=3, max_iter=4, threads=1)
    b = cfpo.sample(324, dim=3, max_iter=4, threads=3)
    assert np.array_equal(a, b)
    start = np.random.default_rng(7).random((250, 3))
    np.save(tmp_path / "start.npy", start)
    command("cfpo", "--dim", 3, "--init", "start.npy", "--max-iter", 3, "-o", "c.npy")
    pts = cfpo.sample(None, dim=3, init=start, max_iter=3)
    assert npy_body(tmp_path / "c.npy") == pts.tobytes()
    # the start is taken in any layout and real dtype
    assert np.array_equal(cfpo.sample(250, dim=3, init=np.asfortranarray(start), max_iter=3), pts)
    # max_iter=0 gives the start back
    assert np.array_equal(cfpo.sample(None, dim=3, init=start, max_iter=0), start)


def test_run3_statistics_match_command(command):
    out = command("cfpo", "--dim", 3, "-n", 324, "--seed", 8, "--max-iter", 7).stdout
    summary = dict(f.split("=") for f in out.splitlines()[0].split()[1:])
    r = cfpo.run(324, dim=3, seed=8, max_iter=7)
    assert r.points.shape == (324, 3)
    assert r.iterations == int(summary["iterations"]) == 7 and r.stop == summary["stop"] == "max-iter"
    assert f"{r.delta_min:.6f}" == summary["delta_min"] and f"{r.delta_avg:.6f}" == summary["delta_avg"]
    box3d = dict(f.split("=") for f in out.splitlines()[1].split()[1:])
    assert f"{r.packing_fraction:.6f}" == box3d["packing_fraction"]
    assert cfpo.run(324, seed=8, max_iter=2).packing_fraction is None
    assert len(r.trace["iteration"]) == 8 and list(r.trace["iteration"]) == list(range(8))
    # delta_min never falls
    assert np.all(np.diff(r.trace["delta_min"]) >= 0)
    # the caller's callback stops the run
    seen = []
    r2 = cfpo.run(324, dim=3, progress=lambda s: seen.append(s["iteration"]) or s["iteration"] >= 2)
    assert r2.stop == "caller" and r2.iterations == 2 and seen == [0, 1, 2]


@pytest.mark.parametrize("kw, err, pat", [
    (dict(n=100, dim=4), ValueError, "not 2 or 3"),
    (dict(n=100, dim=1), ValueError, "not 2 or 3"),
    (dict(n=100, dim="3"), TypeError, "dim"),
    (dict(n=38, dim=3), ValueError, "too small"),
    (dict(n=100, dim=3, variant="paper"), ValueError, "does not apply in 3-D"),
    (dict(n=100, dim=3, density="cos:a=0.5"), ValueError, "density does not apply in 3-D"),
    (dict(n=100, dim=3, tol=0), ValueError, "tol"),
    (dict(n=None, dim=3, init=np.zeros((100, 2))), ValueError, r"\(n, 3\)"),
    (dict(n=None, dim=3, init=np.full((100, 3), 1.0)), ValueError, "outside"),
    (dict(n=120, dim=3, init=np.zeros((100, 3))), ValueError, "n says 120"),
    (dict(n=None, dim=3), ValueError, "required"),
])
def test_sample3_bad_arguments(kw, err, pat):
    with pytest.raises(err, match=pat):
        cfpo.sample(**kw)


def test_ase_reads_xyz_lammps_and_gro(tmp_path, command):
    ase_io = pytest.importorskip("ase.io")
    box = 2.75
    command("cfpo", "--dim", 3, "-n", 200, "--max-iter", 3, "--box", box, "-o", "p.npy", "-o", "p.xyz",
            "-o", "p.data", "-o", "p.gro")
    pts = np.load(tmp_path / "p.npy")
    for name, kw in (("p.xyz", dict(format="extxyz")), ("p.data", dict(format="lammps-data", atom_style="atomic"))):
        atoms = ase_io.read(tmp_path / name, **kw)
        assert len(atoms) == 200, name
        assert np.allclose(atoms.cell.array, np.diag([box] * 3), rtol=0, atol=1e-12), name
        assert np.allclose(atoms.get_positions(), pts * box, rtol=1e-14, atol=1e-13), name
        if name == "p.xyz":
            assert atoms.pbc.all()
    atoms = ase_io.read(tmp_path / "p.gro")  # GROMACS: nm; ASE: Angstrom
    assert len(atoms) == 200
    assert np.allclose(atoms.cell.array, np.diag([10 * box] * 3), rtol=0, atol=1e-9)
    assert np.abs(atoms.get_positions() - 10 * box * pts).max() <= 0.005 + 1e-9
