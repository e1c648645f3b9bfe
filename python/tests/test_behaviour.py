"""What a Python user expects: the GIL released, Ctrl-C, concurrent calls,
no leak, the stop rules and the progress callback."""
import os
import signal
import subprocess
import sys
import textwrap
import threading
import time

import numpy as np
import pytest

import cfpo


def test_gil_released_during_run():
    """A counter thread keeps counting while a long run holds no GIL."""
    count = [0]
    done = threading.Event()

    def counter():
        while not done.is_set():
            count[0] += 1

    t = threading.Thread(target=counter)
    t.start()
    before = count[0]
    try:
        cfpo.sample(2000, max_iter=40, threads=1)
        cfpo.analysis.certify(cfpo.baselines.dart(2000))
    finally:
        done.set()
        t.join()
    assert count[0] - before > 1000


def test_progress_callback_sees_each_iteration_and_stops():
    seen = []

    def cb(s):
        seen.append(s)
        return s["iteration"] == 5

    r = cfpo.run(400, progress=cb)
    assert r.stop == "caller" and r.iterations == 5 and not r.converged
    assert [s["iteration"] for s in seen] == list(range(6))
    assert seen[-1]["delta_min"] == r.delta_min
    ref = cfpo.run(400, max_iter=5)
    assert np.array_equal(ref.points, r.points)  # the same run up to the stop


@pytest.mark.parametrize("method", ["fpo", "lfpo", "ccvt", "ccdt", "bnot"])
def test_baseline_progress_callback_stops(method):
    f = getattr(cfpo.baselines, method)
    seen = []
    r = f(150, progress=lambda s: seen.append(s["iteration"]) or s["iteration"] == 2)
    assert r.stop == "caller" and r.iterations == 2 and seen == [0, 1, 2]
    assert np.array_equal(r.points, f(150, max_iter=2).points)


def test_progress_callback_exception_propagates():
    def cb(s):
        if s["iteration"] == 2:
            raise ZeroDivisionError("from the callback")
        return False

    with pytest.raises(ZeroDivisionError, match="from the callback"):
        cfpo.run(300, progress=cb)
    with pytest.raises(ZeroDivisionError):
        cfpo.baselines.lfpo(200, progress=lambda s: 1 / 0)


def test_progress_line_on_stderr(capfd):
    cfpo.run(300, max_iter=20, progress=True)
    err = capfd.readouterr().err
    assert "iter " in err and "ETA" in err and err.endswith("\n")


def test_stop_rules():
    # 0.9: above the start's delta_min (0.82-0.84 at 400 points), so the
    # run must iterate, and it stops at the first iteration that reaches it
    r = cfpo.run(400, target_min=0.9)
    assert r.stop == "target" and r.delta_min >= 0.9 and len(r.trace["delta_min"]) >= 2
    assert all(d < 0.9 for d in r.trace["delta_min"][:-1])
    r = cfpo.run(400, max_iter=3)
    assert r.stop == "max-iter" and r.iterations == 3
    r = cfpo.run(300, time_limit=1e-9)
    assert r.stop == "time" and r.iterations == 0
    r = cfpo.run(150, variant="simplified", tol=0.01)
    assert r.stop == "converged" and r.converged
    r = cfpo.baselines.fpo(150, target_avg=0.85)
    assert r.stop == "target" and r.delta_avg >= 0.85
    r = cfpo.baselines.ccdt(150, max_iter=2)
    assert r.stop == "max-iter" and r.iterations == 2
    r = cfpo.baselines.bnot(150, time_limit=1e-9)
    assert r.stop == "time" and r.iterations == 0


def test_keyboard_interrupt_mid_run(tmp_path):
    """SIGINT to a child process in a long run: KeyboardInterrupt, promptly,
    and the interpreter goes on."""
    script = textwrap.dedent("""
        import sys, time, cfpo
        print("start", flush=True)
        t = time.time()
        try:
            cfpo.sample(200000, threads=1, tol=0)
            print("finished", flush=True)
        except KeyboardInterrupt:
            print("interrupted %.3f" % (time.time() - t), flush=True)
        print("usable", cfpo.sample(64, max_iter=2).shape, flush=True)
    """)
    p = subprocess.Popen([sys.executable, "-c", script], stdout=subprocess.PIPE, text=True)
    assert p.stdout.readline().strip() == "start"
    time.sleep(3.0)
    sent = time.time()
    p.send_signal(signal.SIGINT)
    out, _ = p.communicate(timeout=120)
    lines = out.split("\n")
    assert lines[0].startswith("interrupted"), out
    assert time.time() - sent < 60
    assert "usable (64, 2)" in out and p.returncode == 0


def test_concurrent_calls_agree():
    """Two threads sampling and analysing at once get what one thread gets."""
    ref_pts = cfpo.sample(500, seed=3, max_iter=20)
    ref_spec = cfpo.analysis.spectrum(ref_pts, 40).power
    out, errors = [None] * 4, []

    def work(i):
        try:
            p = cfpo.sample(500, seed=3, max_iter=20)
            out[i] = (p, cfpo.analysis.spectrum(p, 40).power)
        except Exception as e:  # noqa: BLE001 (reported below)
            errors.append(e)

    threads = [threading.Thread(target=work, args=(i,)) for i in range(4)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert not errors
    for p, s in out:
        assert np.array_equal(p, ref_pts) and np.array_equal(s, ref_spec)


def rss_kb():
    with open(f"/proc/{os.getpid()}/status") as f:
        for line in f:
            if line.startswith("VmRSS:"):
                return int(line.split()[1])
    return 0


def test_no_leak_over_1000_calls():
    def calls():
        p = cfpo.sample(64, max_iter=2, threads=1)
        cfpo.analysis.deltas(p)
        cfpo.baselines.dart(64)
        cfpo.load(path)

    path = "/tmp/cfpo-leak-%d.npy" % os.getpid()
    cfpo.save(path, cfpo.baselines.dart(64))
    try:
        for _ in range(200):
            calls()
        before = rss_kb()
        for _ in range(1000):
            calls()
        grown = rss_kb() - before
    finally:
        os.unlink(path)
    assert grown < 4096, f"RSS grew by {grown} kB over 1000 calls"


def test_returned_arrays_own_their_memory():
    p = cfpo.sample(64, max_iter=1)
    assert p.flags["OWNDATA"] and p.flags["C_CONTIGUOUS"] and p.dtype == np.float64
    d = cfpo.baselines.dart(64)
    assert d.base is not None and not isinstance(d.base, np.ndarray)  # the C buffer, no copy
    del d


def test_threads_none_follows_omp_num_threads(monkeypatch):
    from cfpo import _args
    monkeypatch.setenv("OMP_NUM_THREADS", "3")
    assert _args.threads(None) == 3
    monkeypatch.setenv("OMP_NUM_THREADS", "1,2")
    assert _args.threads(None) == 1
    monkeypatch.delenv("OMP_NUM_THREADS")
    assert _args.threads(None) == 0  # all cores, as the command
    # The run uses that many threads: OMP_NUM_THREADS set in the process
    # after the start (OpenMP itself read 1 at start-up) still counts.
    script = textwrap.dedent("""
        import os, cfpo
        tasks = []
        def seen(s):
            tasks.append(len(os.listdir("/proc/self/task")))
            return False
        cfpo.sample(2000, max_iter=3, progress=seen)
        os.environ["OMP_NUM_THREADS"] = "3"
        before = len(tasks)
        cfpo.sample(2000, max_iter=3, progress=seen)
        print(max(tasks[:before]), max(tasks[before:]))
    """)
    env = dict(os.environ, OMP_NUM_THREADS="1")
    out = subprocess.run([sys.executable, "-c", script], env=env, capture_output=True, text=True, check=True)
    one, three = map(int, out.stdout.split())
    assert (one, three) == (1, 3), out.stdout  # the interpreter's thread, then two OpenMP workers beside it
    # Any thread count gives the same points.
    monkeypatch.setenv("OMP_NUM_THREADS", "1")
    a = cfpo.sample(300, max_iter=10)
    assert np.array_equal(a, cfpo.sample(300, max_iter=10, threads=2))
