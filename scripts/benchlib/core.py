"""core - `bench.py core BUILD PROFILE` (`make bench-core`): the core CFPO
benchmark, each figure measured by BUILD/cfpo-bench (sweeps on 1 and 2
threads and a run to convergence per n), printed and written to
results/<date>-<time>-<host>/core.txt with the comparison against the core
targets. PROFILE: default (65,536 and 1,048,576 points; paper: the same) or
smoke (4,096 and 16,384, seconds)."""
import os
import socket
import subprocess
import sys
import time

from .common import Failure, sh
from .stats import fields


def main(build, name):
    bench = f"{build}/cfpo-bench"
    if not os.access(bench, os.X_OK):
        raise Failure(f"{bench} not built (run make)")
    if name == "smoke":
        sizes, k = [4096, 16384], 3
    elif name in ("default", "paper"):
        sizes, k = [65536, 1048576], 5
    else:
        raise Failure(f"unknown PROFILE '{name}' (default, smoke, paper)", 2)
    out = "results/%s-%s" % (time.strftime("%Y%m%d-%H%M%S"), socket.gethostname().split(".")[0])
    os.makedirs(out, exist_ok=True)
    cores = os.cpu_count() or 1
    log = open(f"{out}/core.txt", "w")

    def emit(line):
        print(line)
        log.write(line + "\n")
        log.flush()
    cpu = next((l.split(":", 1)[1].strip() for l in open("/proc/cpuinfo") if l.startswith("model name")), "unknown")
    emit(f"# CFPO core benchmark, profile {name}")
    emit("# machine: %s, %d cores, %s GiB" % (cpu, cores, sh("free -g | awk '/Mem:/{print $2}'")))
    emit("# compiler: %s; commit %s" % (sh("cc --version"), sh("git rev-parse --short HEAD 2>/dev/null") or "none"))
    emit("# load before: " + " ".join(open("/proc/loadavg").read().split()[:3]))
    plan = []
    for n in sizes:
        plan.append(["sweep", "-n", str(n), "-t", "1", "-k", str(k)])
        if cores >= 2:
            plan.append(["sweep", "-n", str(n), "-t", "2", "-k", str(k)])
        plan.append(["converge", "-n", str(n), "-t", str(cores)])
    t0 = time.time()
    results = []
    for i, args in enumerate(plan, 1):
        print("[%d/%d, %ds] cfpo-bench %s" % (i, len(plan), int(time.time() - t0), " ".join(args)), file=sys.stderr)
        pr = subprocess.run([bench] + args, capture_output=True, text=True)
        for line in pr.stdout.rstrip("\n").split("\n"):
            if line:
                emit(line)
                if line.startswith("RESULT "):
                    results.append((line.split()[1], fields(line)))
        if pr.returncode != 0:
            raise Failure(f"cfpo-bench {' '.join(args)} failed (exit {pr.returncode})")
    emit("# load after: " + " ".join(open("/proc/loadavg").read().split()[:3]))
    sweep, conv = {}, {}
    for kind, f in results:
        if kind == "sweep":
            sweep[(f["n"], f["threads"])] = f
        elif kind == "converge":
            conv[f["n"]] = f
    emit("# versus the targets")
    for (n, t), f in sweep.items():
        if t == "1":
            emit("us per point-update (one local solve), 1 thread, n=%s: %.3f (target <= 0.8)" % (n, float(f["us_per_update"])))
    for (n, t), f in sweep.items():
        if t == "2" and (n, "1") in sweep:
            one = float(sweep[(n, "1")]["seconds_per_sweep"])
            emit("speedup 2 threads vs 1, n=%s: %.2fx (target >= 1.9)" % (n, one / float(f["seconds_per_sweep"])))
            if n == "1048576":
                emit("full sweep of 1M points on 2 threads: %.3f s (target <= 0.42)" % float(f["seconds_per_sweep"]))
    for n, f in conv.items():
        emit("seconds to converge, n=%s: %s%s" % (n, f["seconds"], " (target <= 60)" if n == "1048576" else ""))
        emit("peak bytes per point, n=%s: %s (target <= 64)" % (n, f["bytes_per_point"]))
    log.close()
    print(f"bench: core results in {out}/core.txt", file=sys.stderr)
