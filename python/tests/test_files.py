"""cfpo.load / cfpo.save: every format round-trips exactly, and the bytes
are those the commands write (CSV included)."""
import numpy as np
import pytest

import cfpo


@pytest.mark.parametrize("ext", ["npy", "csv", "txt", "bin", "raw", "f64", "dat", "pts", "xy", "CSV"])
def test_round_trip_exact(tmp_path, ext):
    rng = np.random.default_rng(5)
    p = rng.random((1000, 2))
    p[0] = [0.0, np.nextafter(1.0, 0.0)]
    p[1] = [5e-324, 0.1]
    cfpo.save(tmp_path / f"a.{ext}", p)
    back = cfpo.load(tmp_path / f"a.{ext}")
    assert back.dtype == np.float64 and back.shape == p.shape and np.array_equal(back, p)


def test_csv_layout(tmp_path):
    cfpo.save(tmp_path / "a.csv", np.array([[0.5, 0.25], [0.125, 0.75]]))
    assert (tmp_path / "a.csv").read_text() == "x,y\n0.5,0.25\n0.125,0.75\n"
    (tmp_path / "b.csv").write_text(" x , y \r\n0.25 , 0.5\r\n\n0.75,0.125")
    assert np.array_equal(cfpo.load(tmp_path / "b.csv"), [[0.25, 0.5], [0.75, 0.125]])


def test_npy_readable_by_numpy(tmp_path):
    p = cfpo.baselines.dart(100)
    cfpo.save(tmp_path / "a.npy", p)
    assert np.array_equal(np.load(tmp_path / "a.npy"), p)


@pytest.mark.parametrize("ext", ["csv", "txt", "npy", "bin"])
def test_same_bytes_as_command_output(tmp_path, command, ext):
    command("cfpo", "-n", 100, "--max-iter", 3, "-o", f"c.{ext}")
    p = cfpo.sample(100, max_iter=3)
    cfpo.save(tmp_path / f"p.{ext}", p)
    assert (tmp_path / f"c.{ext}").read_bytes() == (tmp_path / f"p.{ext}").read_bytes()
    assert np.array_equal(cfpo.load(tmp_path / f"c.{ext}"), p)


def test_commands_read_csv(tmp_path, command):
    p = cfpo.baselines.dart(200, seed=9)
    cfpo.save(tmp_path / "s.csv", p)
    cfpo.save(tmp_path / "s.npy", p)
    a = command("cfpo-analyze", "-o", "a", "s.csv").stdout
    b = command("cfpo-analyze", "-o", "b", "s.npy").stdout
    strip = lambda s: [f for f in s.split() if not f.split("=")[0] in ("seconds", "spectrum_seconds",
                                                                          "peak_bytes", "out")]
    assert strip(a) == strip(b)
    bad = command("cfpo", "--init", "missing.csv", check=False)
    assert bad.returncode == 1 and "missing.csv" in bad.stderr
