"""cfpo.sample(n, progressive=True) and classes=K: the bytes of
`cfpo --progressive` / `cfpo --classes K` (-o x.npy), the same for any
thread count, and the command's refusals as ValueError."""
import numpy as np
import pytest

import cfpo


def test_progressive_bytes_of_the_command(command, tmp_path):
    command("cfpo", "-n", 1500, "-s", 3, "-t", 1, "--progressive", "-o", "p.npy")
    want = np.load(tmp_path / "p.npy")
    got = cfpo.sample(1500, seed=3, threads=2, progressive=True)
    assert got.shape == (1500, 2)
    assert got.tobytes() == want.tobytes()


def test_level_balance_bytes_of_the_command(command, tmp_path):
    """the default (--level-balance 16), level_balance=0 (off: the old
    greedy insertion) and another leaf size: each the command's bytes, and
    the three sets differ"""
    got = {}
    for name, args, kw in (("d", (), {}), ("o", ("--level-balance", 0), dict(level_balance=0)),
                           ("e", ("--level-balance", 16), dict(level_balance=16)),
                           ("c", ("--level-balance", 32), dict(level_balance=32))):
        command("cfpo", "-n", 1500, "-s", 3, "-t", 1, "--progressive", *args, "-o", f"{name}.npy")
        got[name] = cfpo.sample(1500, seed=3, threads=2, progressive=True, **kw).tobytes()
        assert got[name] == np.load(tmp_path / f"{name}.npy").tobytes(), name
    assert got["d"] == got["e"]
    assert got["d"] != got["o"] and got["d"] != got["c"] and got["o"] != got["c"]


def test_progressive_options_bytes(command, tmp_path):
    command("cfpo", "-n", 1000, "-s", 2, "--progressive", "--base", 100, "--level-min", 0.8, "--relax", 2,
            "-o", "q.npy")
    want = np.load(tmp_path / "q.npy")
    got = cfpo.sample(1000, seed=2, progressive=True, base=100, level_min=0.8, relax=2)
    assert got.tobytes() == want.tobytes()


def test_joint_bytes_of_the_command(command, tmp_path):
    """the bounded joint move (--joint S, --joint-last S) from Python: the
    command's bytes, for progressive levels and for classes, and it moves
    the points (not the set without it)"""
    command("cfpo", "-n", 1000, "-s", 4, "--progressive", "--level-min", 0.8, "--joint", 3, "--joint-last", 5,
            "-o", "j.npy")
    got = cfpo.sample(1000, seed=4, progressive=True, level_min=0.8, joint=3, joint_last=5)
    assert got.tobytes() == np.load(tmp_path / "j.npy").tobytes()
    assert got.tobytes() != cfpo.sample(1000, seed=4, progressive=True, level_min=0.8).tobytes()
    command("cfpo", "-n", 800, "-s", 2, "--classes", 4, "--joint", 2, "-o", "k.npy")
    got = cfpo.sample(800, seed=2, classes=4, joint=2)
    assert got.tobytes() == np.load(tmp_path / "k.npy").tobytes()


def test_classes_bytes_of_the_command(command, tmp_path):
    command("cfpo", "-n", 1200, "-s", 5, "--classes", 3, "-o", "c.npy")
    want = np.load(tmp_path / "c.npy")
    got = cfpo.sample(1200, seed=5, classes=3)
    assert got.tobytes() == want.tobytes()


def test_levels_are_the_prefixes():
    pts, levels = cfpo.progressive_run(1024, seed=1)
    assert [m for m, *_ in levels] == [64, 128, 256, 512, 1024]
    for m, _it, dmin, davg in levels:
        d = cfpo.analysis.deltas(pts[:m])
        assert d.delta_min == pytest.approx(dmin, abs=1e-9)
        # the engine sums distances in units of Delta / 2^24 (6e-8 each)
        assert d.delta_avg == pytest.approx(davg, abs=1e-7)


@pytest.mark.parametrize("kw, msg", [
    (dict(classes=0), "classes"),
    (dict(progressive=True, base=5000), "larger than n"),
    (dict(progressive=True, time_limit=5.0), "time_limit does not go"),
    (dict(progressive=True, init=np.zeros((1024, 2))), "init does not go"),
    (dict(classes=4, base=64), "base does not go with classes"),
    (dict(base=64), "need progressive"),
    (dict(joint=3), "need progressive"),
    (dict(progressive=True, joint=-1), "joint"),
    (dict(progressive=True, joint_last=0), "joint_last"),
    (dict(progressive=True, variant="hyperuniform"), "hyperuniform"),
    (dict(progressive=True, level_balance=-1), "level_balance"),
    (dict(classes=4, level_balance=16), "level_balance needs progressive"),
    (dict(classes=4, level_balance=0), "level_balance needs progressive"),
    (dict(level_balance=16), "level_balance needs progressive"),
])
def test_refused(kw, msg):
    with pytest.raises(ValueError, match=msg):
        cfpo.sample(1024, **kw)
