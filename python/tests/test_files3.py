"""3-D point files from Python: cfpo.save of an (n, 3) set writes the
bytes `cfpo --dim 3 [--box L] -o FILE` writes, in every 3-D format (the
unit torus in .npy, text, CSV and raw; the box of side L in extended XYZ,
LAMMPS data and .gro); cfpo.load(path, dim=3) reads back what --init
reads, the same doubles; bad input (a box that is not positive and
finite, a .gro box past its columns, an unknown or write-only format, a
box for a 2-D set, a file of 2-D points) is refused with one line and
nothing written."""
import subprocess

import numpy as np
import pytest

import cfpo

READ = ["npy", "txt", "csv", "raw"]
RUN = ["--dim", 3, "-n", 200, "--seed", 4, "--max-iter", 3, "-t", 1]


@pytest.fixture(scope="module")
def ref(build, tmp_path_factory):
    """The points of a short 3-D run of the command."""
    d = tmp_path_factory.mktemp("ref3")
    subprocess.run([str(build / "cfpo"), "-q", *map(str, RUN), "-o", "ref.npy"], cwd=d, check=True,
                   capture_output=True)
    return cfpo.load(d / "ref.npy", dim=3)


# the unit torus's formats (a box changes nothing there), and the
# simulation files with a box and with the default side 1
@pytest.mark.parametrize("ext, box", [("npy", None), ("txt", None), ("csv", None), ("raw", None),
                                      ("xyz", 2.5), ("data", 2.5), ("gro", 2.5), ("xyz", None)])
def test_save3_same_bytes_as_command(tmp_path, command, ref, ext, box):
    extra = [] if box is None else ["--box", box]
    command("cfpo", *RUN, *extra, "-o", f"c.{ext}")
    cfpo.save(tmp_path / f"p.{ext}", ref, box=box)
    assert (tmp_path / f"p.{ext}").read_bytes() == (tmp_path / f"c.{ext}").read_bytes()


@pytest.mark.parametrize("ext", READ)
def test_load3_round_trip(tmp_path, ref, ext):
    cfpo.save(tmp_path / f"r.{ext}", ref)
    back = cfpo.load(tmp_path / f"r.{ext}", dim=3)
    assert back.shape == (200, 3) and back.dtype == np.float64
    assert np.array_equal(back, ref)  # text keeps 17 significant digits: the same doubles


def test_box_scales_the_simulation_files(tmp_path, ref):
    cfpo.save(tmp_path / "a.xyz", ref, box=3.0)
    lines = (tmp_path / "a.xyz").read_text().splitlines()
    assert int(lines[0]) == 200
    assert 'Lattice="3' in lines[1]
    first = np.array([float(v) for v in lines[2].split()[1:4]])
    assert np.allclose(first, 3.0 * ref[0], rtol=0, atol=1e-9)


@pytest.mark.parametrize("box, words", [(0.0, "box"), (-1.0, "box"), (float("nan"), "box"),
                                         (float("inf"), "box")])
def test_bad_box_refused(tmp_path, ref, box, words):
    with pytest.raises(ValueError, match=words):
        cfpo.save(tmp_path / "b.xyz", ref, box=box)
    assert not list(tmp_path.glob("b.xyz*"))


def test_gro_box_too_large_refused(tmp_path, ref):
    with pytest.raises(ValueError, match="gro"):
        cfpo.save(tmp_path / "b.gro", ref, box=1e5)
    assert not list(tmp_path.glob("b.gro*"))


def test_formats_refused(tmp_path, ref):
    with pytest.raises(ValueError, match="unknown output format"):
        cfpo.save(tmp_path / "b.pdb", ref)
    cfpo.save(tmp_path / "w.xyz", ref)
    with pytest.raises(ValueError, match="not a 3-D format cfpo reads"):
        cfpo.load(tmp_path / "w.xyz", dim=3)
    with pytest.raises(ValueError, match="only for 3-D"):
        cfpo.save(tmp_path / "b.npy", ref[:, :2], box=2.0)
    assert not list(tmp_path.glob("b.*"))
    with pytest.raises(ValueError, match="dim"):
        cfpo.load(tmp_path / "w.xyz", dim=4)


def test_2d_file_refused_as_3d(tmp_path):
    cfpo.save(tmp_path / "two.npy", np.random.default_rng(1).random((50, 2)))
    with pytest.raises(ValueError):
        cfpo.load(tmp_path / "two.npy", dim=3)
    with pytest.raises(OSError):
        cfpo.load(tmp_path / "missing.npy", dim=3)
