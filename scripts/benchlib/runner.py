"""runner - `bench.py run BUILD PROFILE [--plan]` (`make bench`): CFPO against
its baselines, with the paper's figures (Chen & Gotsman, figures 5-8).

Builds the plan of the profile (profiles.py; the methods: methods.tsv), runs
it (one-thread runs of a batch start together, each pinned to its own CPU;
every other run alone), writes runs.csv, analyses the final sets of the
time-to-quality runs (quality.csv), the integration experiment's sets
(integration.csv, integration.py) and averages the spectra of each group of
sets with cfpo-analyze (spectra.csv, data/analysis/), then draws the figures
and summary.md (plotdata.replot). Everything is built in a temporary folder
renamed when complete: a failure or a signal leaves nothing.
"""
import math
import os
import shutil
import signal
import socket
import subprocess
import sys
import threading
import time

from . import integration as I
from . import methods as M
from .common import Failure, sh, write
from . import profiles as P
from . import stats as S

COLUMNS = ("run,experiment,method,variant,n,n_target,seed,threads,ranks,max_iter,iterations,seconds,"
           "seconds_per_iteration,delta_min,delta_avg,peak_bytes,converged,wall_seconds,trace,time_limit,stop,batch")
COLUMNS_NOTE = ("# columns: seconds = the tool's own sampling time (start included, writing excluded); "
                "seconds_per_iteration = seconds / iterations; peak_bytes = peak resident memory of the process; "
                "n = points produced, n_target = points asked for; max_iter = iteration cap (- none); "
                "wall_seconds = the whole process as timed by this script; time_limit = --time-limit of a ttq run "
                "(- none); stop = the rule that ended the run (SUMMARY stop=); batch = runs with the same number "
                "started together, one per core (- alone)")
# the measures of sampling research (analysis/README.md), appended after the
# 19 columns of the earlier folders, which replot without them
MEASURES = ("p0", "h_index", "lowk_alpha", "disc_wrap_l2", "disc_diaphony", "disc_l2_star", "disc_gen_l2",
            "disc_centred_l2") + I.SHIFTVAR
SPECTRA_COLUMNS = ("group,experiment,method,variant,n,iteration,sets,runs,K,delta_min,delta_avg,raps_peak,"
                   "raps_peak_r,eff_nyquist,oscillation,averaged_by,spike_ratio,spike_k,spike_ratio_set_mean,"
                   + ",".join(MEASURES))
QUALITY_COLUMNS = "run,n,K,certify,cert_pass,cert_max_violation,lct_pass,spike_ratio,spike_k,lattice_ratio,lattice_k"


class Stop(Exception):
    def __init__(self, code):
        super().__init__(code)
        self.code = code


# ---------------------------------------------------------------- the plan
def build_plan(p, meth, cores, mpirun):
    plan = []

    def add(exp, key, n, seed, threads, maxiter, out, limit=None, batch=None, est=None, integ=None):
        if est is None:
            est = P.estimate(key, n, threads, maxiter)
        plan.append(dict(exp=exp, key=key, n=n, seed=seed, threads=threads, maxiter=maxiter,
                         est=est, out=out, limit=limit, batch=batch, integ=integ))

    batch = 0
    for it in p["evo_iters"]:
        for s in range(1, p["sets"] + 1):
            add("evolution", "paper", p["comp_n"], s, cores, it, f"sets/evolution-it{it}-s{s}.txt")
    together = p["comp_together"]
    for k in meth.keys(*M.KINDS):
        t = p["comp_threads"] if meth.kind(k) == "cfpo" else 1
        integ = (k, p["comp_n"]) if p["comp_n"] in P.int_sizes(p, k) else None
        slot = 0
        for s in range(1, P.comp_sets(p, k) + 1):
            out = f"sets/comparison-{k}-s{s}.txt"
            if t > 1 or together <= 1:
                add("comparison", k, p["comp_n"], s, t, None, out, integ=integ)
                continue
            if slot == 0:
                batch += 1
            add("comparison", k, p["comp_n"], s, t, None, out, batch=batch, integ=integ)
            slot = (slot + 1) % together
    kept = set()  # (key, n, seed) of the runtime runs whose sets the integration experiment takes
    for k in meth.keys("cfpo") + meth.keys("iter") + meth.keys("direct") + meth.keys("pd"):
        cf = meth.kind(k) == "cfpo"
        for n in p["rt_sizes"].get(k, []):
            for t in (p["rt_threads"] if cf else [1]):
                ct = p["comp_threads"] if cf else 1
                if n == p["comp_n"] and t == ct and P.comp_sets(p, k) >= p["rt_reps"]:
                    continue  # the comparison's runs (same n, threads, seeds)
                for s in range(1, p["rt_reps"] + 1):
                    if t == 1 and n != p["comp_n"] and n in P.int_sizes(p, k) and s <= P.int_seeds(p, n):
                        kept.add((k, n, s))
                        add("runtime", k, n, s, t, None, f"sets/runtime-{k}-n{n}-s{s}.txt", integ=(k, n))
                    else:
                        add("runtime", k, n, s, t, None, None)
    if mpirun and cores >= 2:
        for n in p["rt_sizes"].get("paper", []):
            for s in range(1, p["rt_reps"] + 1):
                add("runtime", "paper-mpi", n, s, 1, None, None)
    for k in meth.keys(*M.KINDS):  # the integration experiment's own runs
        for n in P.int_sizes(p, k):
            if n == p["comp_n"]:
                continue
            slot = 0
            for s in range(1, P.int_seeds(p, n) + 1):
                if (k, n, s) in kept:
                    continue
                out = f"sets/integration-{k}-n{n}-s{s}.txt"
                if together <= 1:
                    add("integration", k, n, s, 1, None, out, integ=(k, n))
                    continue
                if slot == 0:
                    batch += 1
                add("integration", k, n, s, 1, None, out, batch=batch, integ=(k, n))
                slot = (slot + 1) % together

    def add_ttq(key, n, seed, t, b):
        lim = P.ttq_limit(p, key, n)
        add("ttq", key, n, seed, t, p["ttq_maxiter"], f"sets/ttq-{key}-t{t}-n{n}-s{seed}.bin", lim, b,
            P.ttq_estimate(key, n, t, p["ttq_maxiter"], lim))

    for n in p["ttq_sizes"]:
        for s in range(1, p["ttq_seeds"] + 1):
            slot = 0
            for key, t in P.ttq_configs(p, n):
                if t > 1 or slot == 0 or slot >= cores:
                    batch += 1
                    slot = 0
                slot = cores if t > 1 else slot + 1
                add_ttq(key, n, s, t, batch)
    for n in p["ttq_big"]:
        for s in range(1, p["ttq_seeds"] + 1):
            batch += 1
            add_ttq("adaptive", n, s, 2, batch)
    return plan


def groups_of(plan):
    """The plan as a list of index ranges: a batch's runs, or one run alone."""
    out, i = [], 0
    while i < len(plan):
        j = i + 1
        if plan[i]["batch"] is not None:
            while j < len(plan) and plan[j]["batch"] == plan[i]["batch"]:
                j += 1
        out.append((i, j))
        i = j
    return out


def plan_total(plan):
    """Seconds by the cost model: a batch counts its longest run."""
    return sum(max(plan[m]["est"] for m in range(i, j)) for i, j in groups_of(plan))


def dash(x):
    return "-" if x is None else str(x)


def print_plan(plan, name):
    for r in plan:
        line = "%-10s %-10s n=%-8s seed=%-3s threads=%s max_iter=%s estimate=%ss" % (
            r["exp"], r["key"], r["n"], r["seed"], r["threads"], dash(r["maxiter"]), "%.3f" % r["est"])
        if r["limit"] is not None:
            line += " time_limit=%ss" % r["limit"]
        if r["batch"] is not None:
            line += " batch=%s" % r["batch"]
        print(line)
    print("bench: profile %s: %d runs, about %d min of runs by the rough cost model (a batch counts its "
          "longest run; analyses and figures not included)" % (name, len(plan), int(plan_total(plan) / 60 + 0.5)))


# ------------------------------------------------------------ the driver
class Bench:
    def __init__(self, build, name, root):
        self.B, self.name, self.root = build, name, root
        self.meth = M.Methods()
        self.here = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
        self.children = []
        self.work = None
        self.ticker = None
        self.state = None
        self.t0 = time.time()

    # -- progress
    def progress(self, k, label, est_done, act_done, est_left):
        el = time.time() - self.t0
        r = act_done / est_done if est_done > 0.5 and act_done > 0 else 1
        left = r * est_left
        if self.ticker:
            self.state = (k, label, time.time(), left)
        else:
            print("bench: " + self.status_line(k, label, el, left), file=sys.stderr, flush=True)

    def status_line(self, k, label, el, left):
        return "[%d/%d] %s elapsed, about %s left: %s" % (k, len(self.plan), S.hms(el), S.hms(left), label)

    def tick(self):
        while not self.ticker_stop.wait(1):
            if self.state:
                k, label, t0, left = self.state
                line = self.status_line(k, label, time.time() - self.t0, max(0, left - (time.time() - t0)))
                sys.stderr.write("\r\033[K" + line)
                sys.stderr.flush()

    def end_ticker(self):
        if self.ticker:
            self.ticker_stop.set()
            self.ticker.join()
            self.ticker = None
            sys.stderr.write("\r\033[K")

    # -- the header of runs.csv
    def header(self, p, cores, pinning):
        B = self.B

        def pkgver(pkg):
            return sh(f"dpkg-query -W -f '${{Version}}' {pkg} 2>/dev/null") or "unknown"

        def flags(path, var):
            try:
                for line in open(path):
                    if line.startswith(var + " = "):
                        return line[len(var) + 3:].rstrip("\n")
            except OSError:
                pass
            return "unknown"
        repo = os.path.dirname(self.here)
        commit = sh(f"git -C '{repo}' rev-parse --short HEAD 2>/dev/null") or "none"
        if subprocess.run(["git", "-C", repo, "diff", "--quiet", "HEAD"], capture_output=True).returncode != 0:
            commit += " (uncommitted changes)"
        cpu = "unknown"
        for line in open("/proc/cpuinfo"):
            if line.startswith("model name"):
                cpu = line.split(":", 1)[1].strip()
                break
        btype = ""
        for line in open(os.path.join(B, "CMakeCache.txt")):
            if line.startswith("CMAKE_BUILD_TYPE:STRING="):
                btype = line.split("=", 1)[1].rstrip("\n")
        env = sorted(f"{k}={v}" for k, v in os.environ.items() if k.startswith(("OMP_", "GOMP_")))
        cfgs = ",".join(f"{k}:{t}" for k, t in p["ttq_configs"])
        extra = "".join(" TTQ_CONFIGS_%d=%s" % (n, ",".join(f"{k}:{t}" for k, t in c))
                        for n, c in p["ttq_configs_at"].items() if n in p["ttq_sizes"])
        lims = ",".join(f"{k}@{n}:{s}" for (k, n), s in p["ttq_limits"].items())
        return [
            f"# cfpo method comparison (scripts/bench.py), profile {self.name}, started "
            + time.strftime("%Y-%m-%dT%H:%M:%SZ", time.gmtime()),
            "# host: %s; cpu: %s; cores: %d; memory: %s GiB" % (
                socket.gethostname().split(".")[0], cpu, cores, sh("free -g | awk '/Mem:/ { print $2 }'")),
            "# compiler: %s; C flags: %s; C++ flags (FPO, LFPO): %s; build type: %s" % (
                sh("cc --version"), flags(os.path.join(B, "CMakeFiles/cfpo_core.dir/flags.make"), "C_FLAGS"),
                flags(os.path.join(B, "baselines/CMakeFiles/cfpo_cgal.dir/flags.make"), "CXX_FLAGS"), btype),
            f"# git commit: {commit}",
            "# libraries: FFTW %s; CGAL %s; OpenMPI %s; GMP %s; gnuplot %s" % (
                pkgver("libfftw3-dev"), pkgver("libcgal-dev"), pkgver("libopenmpi-dev"), pkgver("libgmp-dev"),
                sh("gnuplot --version").split(" ", 1)[-1]),
            "# environment: " + (" ".join(env) if env else "no OMP_ or GOMP_ variables"),
            "# plan: SETS=%d COMP_N=%d COMP_THREADS=%d COMP_TOGETHER=%d EVO_ITERS=%s RT_REPS=%d RT_THREADS=%s "
            "TTQ_SIZES=%s TTQ_SEEDS=%d TTQ_MAXITER=%s TTQ_TARGET_MIN=%s TTQ_TARGET_AVG=%s TTQ_CONFIGS=%s%s%s "
            "TASKSET=%s; %d runs" % (
                p["sets"], p["comp_n"], p["comp_threads"], p["comp_together"], " ".join(map(str, p["evo_iters"])),
                p["rt_reps"], " ".join(map(str, p["rt_threads"])),
                ",".join(map(str, p["ttq_sizes"] + p["ttq_big"])), p["ttq_seeds"], dash(p["ttq_maxiter"]),
                p["ttq_target_min"], p["ttq_target_avg"], cfgs, extra, (" TTQ_LIMITS=" + lims) if lims else "",
                "yes" if pinning else "no", len(self.plan)),
            "# load average before: " + " ".join(open("/proc/loadavg").read().split()[:3]),
        ]

    # -- one run
    def command(self, r, i, cores, mpirun):
        B, key = self.B, r["key"]
        if key == "paper-mpi":
            cmd = [mpirun, "--oversubscribe", "-np", str(cores), f"{B}/cfpo", "--variant", "paper", "-t", str(r["threads"])]
        else:
            words = self.meth.get(key, "command").split()
            cmd = [f"{B}/{words[0]}"] + words[1:]
            if self.meth.kind(key) == "cfpo":
                cmd += ["-t", str(r["threads"])]
        cmd += ["-n", str(r["n"]), "-s", str(r["seed"]), "-q"]
        if r["maxiter"] is not None:
            cmd += ["--max-iter", str(r["maxiter"])]
        if r["exp"] == "ttq":
            cmd += ["--target-min", self.p["ttq_target_min"], "--target-avg", self.p["ttq_target_avg"],
                    "--time-limit", str(r["limit"])]
        if self.meth.kind(key) != "pd":
            cmd += ["--trace", f"{self.work}/data/traces/run-{i + 1:04d}.tsv"]
        if r["out"]:
            cmd += ["-o", f"{self.work}/{r['out']}"]
        return cmd

    def run_group(self, lo, hi, cores, mpirun, cpus):
        procs = []
        for m in range(lo, hi):
            r = self.plan[m]
            cpu = None
            if r["batch"] is not None and r["threads"] == 1 and cpus:
                cpu = cpus[(m - lo) % len(cpus)]
            tmp = f"{self.work}/tmp/run-{m + 1:04d}"
            out, err = open(tmp + ".out", "w"), open(tmp + ".err", "w")
            t1 = time.time()
            pr = subprocess.Popen(self.command(r, m, cores, mpirun), stdin=subprocess.DEVNULL, stdout=out,
                                  stderr=err)
            if cpu is not None:  # pinned at once, before its work starts (as taskset -c would)
                try:
                    os.sched_setaffinity(pr.pid, {cpu})
                except OSError:
                    pass
            out.close()
            err.close()
            self.children.append(pr)
            procs.append([pr, t1, None])
        # each end time taken when that run ends, so a short run of a batch
        # is not charged the longest one's time
        while any(x[2] is None for x in procs):
            for x in procs:
                if x[2] is None and x[0].poll() is not None:
                    x[2] = time.time()
            if any(x[2] is None for x in procs):
                if len(procs) == 1:
                    procs[0][0].wait()
                else:
                    time.sleep(0.05)
        self.children = []
        return procs

    def record(self, m, pr, t1, t2, label):
        r = self.plan[m]
        tmp = f"{self.work}/tmp/run-{m + 1:04d}"
        line = next((l for l in open(tmp + ".out") if l.startswith("SUMMARY")), "")
        if pr.returncode != 0 or not line:
            errs = open(tmp + ".err").read().rstrip("\n").split("\n")
            self.end_ticker()
            raise Failure(f"run {m + 1} ({label}) failed (exit {pr.returncode}): {errs[-1]}")
        f = S.fields(line)
        trace = "-" if self.meth.kind(r["key"]) == "pd" else f"data/traces/run-{m + 1:04d}.tsv"
        it, secs = f.get("iterations", ""), f.get("seconds", "")
        spi = "-" if it == "-" or S.num(it) == 0 else "%.6g" % (S.num(secs) / S.num(it))
        row = [str(m + 1), r["exp"], f.get("method", ""), f.get("variant", ""), f.get("n", ""), str(r["n"]),
               str(r["seed"]), f.get("threads", ""), f.get("ranks", ""), dash(r["maxiter"]), it, secs, spi,
               f.get("delta_min", ""), f.get("delta_avg", ""), f.get("peak_bytes", ""), f.get("converged", ""),
               "%.3f" % (t2 - t1), trace, dash(r["limit"]), f.get("stop", ""), dash(r["batch"])]
        os.remove(tmp + ".out")
        os.remove(tmp + ".err")
        return ",".join(row)

    def label(self, r, cores):
        s = f"{r['exp']} {r['key']} n={r['n']} seed={r['seed']} threads={r['threads']}"
        if r["key"] == "paper-mpi":
            s += f" ranks={cores}"
        if r["maxiter"] is not None:
            s += f" max-iter={r['maxiter']}"
        if r["limit"] is not None:
            s += f" limit={r['limit']}s"
        return s

    def analyze(self, args, what):
        pr = subprocess.run([f"{self.B}/cfpo-analyze"] + args, capture_output=True, text=True)
        line = next((l for l in pr.stdout.split("\n") if l.startswith("SUMMARY")), "")
        if pr.returncode != 0 or not line:
            raise Failure(f"cfpo-analyze failed on {what}")
        return S.fields(line)

    # -- everything
    def main(self, plan_only):
        p = P.profile(self.name, os.cpu_count() or 1)
        if p is None:
            raise Failure(f"unknown PROFILE '{self.name}' (smoke, default, paper, seeds, lowk, density)", 2)
        cores = len(os.sched_getaffinity(0)) if hasattr(os, "sched_getaffinity") else os.cpu_count()
        p = P.profile(self.name, cores)
        self.p = p
        P.omp_env()
        for c in self.meth.binaries() + ["cfpo-analyze"]:
            if not os.access(f"{self.B}/{c}", os.X_OK):
                raise Failure(f"{self.B}/{c} not built (run make; the baselines on CGAL need CGAL, see CMake's output)")
        mpirun = shutil.which("mpirun")
        self.plan = build_plan(p, self.meth, cores, mpirun)
        if plan_only:
            print_plan(self.plan, self.name)
            return
        if not shutil.which("gnuplot"):
            raise Failure("gnuplot not found (run scripts/install-deps.sh)")
        self.B = os.path.abspath(self.B)
        try:
            os.makedirs(self.root, exist_ok=True)
        except OSError:
            raise Failure(f"cannot create {self.root}")
        name = time.strftime("%Y%m%d-%H%M%S") + "-" + socket.gethostname().split(".")[0]
        final = os.path.join(self.root, name)
        if os.path.exists(final):
            raise Failure(f"{final} already exists")
        self.work = os.path.join(self.root, f".{name}.tmp.{os.getpid()}")
        for d in ("data/traces", "data/points", "data/analysis", "sets", "tmp"):
            os.makedirs(os.path.join(self.work, d))
        cpus = sorted(os.sched_getaffinity(0)) if hasattr(os, "sched_getaffinity") else []
        if os.geteuid() == 0:  # mpirun refuses root unless told
            os.environ.update(OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
        if sys.stderr.isatty():
            self.ticker_stop = threading.Event()
            self.ticker = threading.Thread(target=self.tick, daemon=True)
            self.ticker.start()
        head = self.header(p, cores, bool(cpus))
        load1 = float(open("/proc/loadavg").read().split()[0])
        if load1 > 0.5:
            print(f"bench: note: load average {load1:g} before the start; other work on this machine "
                  "disturbs the timings", file=sys.stderr)
        rows, ttq_sets = [], []
        total = plan_total(self.plan)
        est_done = act_done = 0.0
        for lo, hi in groups_of(self.plan):
            labels = [self.label(self.plan[m], cores) for m in range(lo, hi)]
            best = max(self.plan[m]["est"] for m in range(lo, hi))
            label = " + ".join(labels)
            if hi - lo > 1:
                label = "together: " + label
            self.progress(lo + 1, label, est_done, act_done, total - est_done)
            procs = self.run_group(lo, hi, cores, mpirun, cpus)
            wall = 0.0
            for m, (pr, t1, t2) in zip(range(lo, hi), procs):
                rows.append(self.record(m, pr, t1, t2, labels[m - lo]))
                wall = max(wall, t2 - t1)
                if self.plan[m]["exp"] == "ttq":
                    ttq_sets.append((m + 1, self.plan[m]["out"]))
            est_done += best
            act_done += wall
        N = len(self.plan)
        from . import density, stipple
        density.run(self, p)
        stipple.run(self, p)
        from . import d3  # the 3-D part (small in smoke and default)
        d3.run(self, p)
        from . import progressive  # the progressive part (small in smoke and default)
        progressive.run(self, p)
        quality = [QUALITY_COLUMNS]
        for q, (run, out) in enumerate(ttq_sets, 1):
            self.progress(N, f"final-set analysis {q} of {len(ttq_sets)} (run {run})", 1, 1, 0)
            f = self.analyze(["-q", "--certify", "-o", f"{self.work}/tmp/an-q", f"{self.work}/{out}"], f"{out} (run {run})")
            quality.append(",".join([str(run)] + [f.get(k, "") for k in ("n", "K", "certify", "cert_pass",
                           "cert_max_violation", "lct_pass", "spike_ratio")] + [f.get("spike_k", "").replace(",", ";"),
                           f.get("lattice_ratio", ""), f.get("lattice_k", "").replace(",", ";")]))
            shutil.rmtree(f"{self.work}/tmp/an-q")
            os.remove(f"{self.work}/{out}")
        write(f"{self.work}/quality.csv", quality)
        keep = {r["out"] for r in self.plan if r["exp"] == "comparison"}
        write(f"{self.work}/integration.csv", I.analyse(self, self.plan, rows, keep))
        spectra = self.spectra(p, rows)
        write(f"{self.work}/spectra.csv", spectra)
        shutil.rmtree(f"{self.work}/sets")
        took = time.time() - self.t0
        after = "# load average after: %s; runs and analyses took %s" % (
            " ".join(open("/proc/loadavg").read().split()[:3]), S.hms(took))
        write(f"{self.work}/runs.csv", head + [COLUMNS_NOTE, after, COLUMNS] + rows)
        self.end_ticker()
        print(f"bench: {N} runs done in {S.hms(took)}; drawing the figures", file=sys.stderr)
        from . import plotdata
        plotdata.replot(self.work)
        shutil.rmtree(f"{self.work}/tmp")
        try:
            os.rename(self.work, final)
        except OSError:
            raise Failure(f"cannot rename {self.work} to {final}")
        self.work = None
        print(f"bench: results in {final} (summary.md, runs.csv, fig-*.png); took "
              f"{S.hms(time.time() - self.t0)}", file=sys.stderr)

    def spectra(self, p, rows):
        """One averaged analysis per group of sets (cfpo-analyze; --any-n for
        the maximal Poisson-disk sets, whose n varies with the seed)."""
        n = p["comp_n"]
        crop = int(3 * math.sqrt(n) + 0.999)
        K = math.ceil(6 * math.sqrt(n))
        groups = [(f"evolution-it{it}", "evolution", "paper", str(it)) for it in p["evo_iters"]]
        groups += [(f"comparison-{k}", "comparison", k, "-") for k in self.meth.keys(*M.KINDS)
                   if P.comp_sets(p, k) > 0]  # a profile may leave a method out of the comparison (seeds)
        cells = [r.split(",") for r in rows]
        out = [SPECTRA_COLUMNS]
        for g, (grp, exp, key, it) in enumerate(groups, 1):
            self.progress(len(self.plan), f"analysis {g} of {len(groups)}: {grp}", 1, 1, 0)
            files = sorted((f for f in os.listdir(f"{self.work}/sets") if f.startswith(grp + "-s")),
                           key=lambda f: f)
            if not files:
                raise Failure(f"no point sets for {grp}")
            files = [f"{self.work}/sets/{f}" for f in files]
            ids = S.ranges([c[0] for c in cells if c[1] == exp and M.key(c[2], c[3]) == key and c[9] == it], ";")
            sizes = [sum(1 for l in open(f) if not l.startswith("#")) for f in files]
            a = f"{self.work}/tmp/an-{grp}"
            dst = f"{self.work}/data/analysis/{grp}"
            os.makedirs(dst)
            anyn = len(set(sizes)) > 1
            f = self.analyze(["-q", "-K", str(K)] + (["--any-n"] if anyn else []) + ["-o", a] + files, grp)
            for name in ("raps.txt", "stats.json", "pcf.txt"):
                if name != "pcf.txt" or os.path.isfile(f"{a}/{name}"):  # pcf.txt: where the tool writes one
                    shutil.copy(f"{a}/{name}", dst)
            crop_spectrum(f"{a}/spectrum.txt", f"{dst}/spectrum.txt", crop)
            shutil.rmtree(a)
            nval = "%.1f" % (sum(sizes) / len(sizes)) if anyn else f.get("n", "")
            out.append(",".join([grp, exp, self.meth.get(key, "method"), self.meth.get(key, "variant"), nval, it,
                                 f.get("sets", ""), ids] + [f.get(k, "") for k in (
                                     "K", "delta_min", "delta_avg", "raps_peak", "raps_peak_r", "eff_nyquist",
                                     "oscillation")] + ["cfpo-analyze --any-n" if anyn else "cfpo-analyze",
                                 f.get("spike_ratio", ""), f.get("spike_k", "").replace(",", ";"),
                                 f.get("spike_ratio_set_mean", "")] + [f.get(k, "") for k in MEASURES]))
            os.rename(f"{self.work}/sets/{grp}-s1.txt", f"{self.work}/data/points/{grp}.txt")
        return out

    def cleanup(self):
        self.end_ticker()
        for pr in self.children:
            try:
                pr.terminate()
            except OSError:
                pass
        for pr in self.children:  # let the killed runs end (at most 5 s) before the folder goes
            try:
                pr.wait(5)
            except subprocess.TimeoutExpired:
                pr.kill()
        if self.work and os.path.isdir(self.work):
            if os.environ.get("CFPO_BENCH_KEEP") == "1":
                print(f"bench: kept {self.work} (CFPO_BENCH_KEEP=1)", file=sys.stderr)
                return
            for _ in range(50):
                shutil.rmtree(self.work, ignore_errors=True)
                if not os.path.exists(self.work):
                    break
                time.sleep(0.1)


def crop_spectrum(src, dst, crop):
    """The figures' copy of an averaged spectrum: |kx|, |ky| <= crop, 5 digits."""
    with open(src) as f:
        head = f.readline().split()
        K = abs(int(head[1]))
        c = K if crop > K or crop <= 0 else crop
        lines = ["%d" % (2 * c + 1) + "".join(" %d" % kx for kx in range(-c, c + 1))]
        for line in f:
            v = line.split()
            ky = int(v[0])
            if -c <= ky <= c:
                vals = v[1 + K - c:1 + K + c + 1]
                lines.append("%d" % ky + "".join(" %.5g" % float(x) for x in vals))
    write(dst, lines)


def main(build, name, plan_only):
    bench = Bench(build, name, os.environ.get("CFPO_RESULTS", "results"))

    def on_signal(sig, frame):
        raise Stop(130 if sig == signal.SIGINT else 143)
    for s in (signal.SIGINT, signal.SIGTERM, signal.SIGHUP):
        signal.signal(s, on_signal)
    try:
        bench.main(plan_only)
        return 0
    except Failure as e:
        bench.cleanup()
        print(f"bench: {e}", file=sys.stderr)
        return e.code
    except Stop as e:
        bench.cleanup()
        return e.code
    except BaseException:
        bench.cleanup()
        raise
