#!/usr/bin/env python3
"""bench.py - the benchmark driver (Python 3 standard library only; the
measures are the C tools' own: cfpo, the baselines, cfpo-analyze, cfpo-bench).

  bench.py run BUILD [PROFILE] [--plan]   make bench: CFPO against its baselines,
                                          the paper's figures; results/<date>-<time>-<host>/
  bench.py replot [RESULTS_DIR]           make replot: figures and summary.md again
  bench.py core BUILD [PROFILE]           make bench-core: sweeps and convergence (core.txt)
  bench.py methods [--binaries] [KIND...] the method list (scripts/methods.tsv) for scripts:
                                          the keys (or the programs) of those kinds
  bench.py methods --get KEY FIELD        one field of a method's row
  bench.py profile PROFILE                a profile's plan as NAME=VALUE lines

PROFILE: smoke, default (the default), paper, seeds, lowk, density or 3d (the 3-D part
alone, benchlib/d3.py; smoke and default run a small 3-D part too) or progressive (the
progressive part alone at 2^20 points, CFPO_PROG_N=N another n, benchlib/progressive.py;
smoke and default run it small). Environment: CFPO_RESULTS
(results root, default results/), CFPO_BENCH_KEEP=1 (keep the temporary
folder of a failed run). The modules: scripts/benchlib/.
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
sys.dont_write_bytecode = True

from benchlib import common, methods, runner  # noqa: E402

USAGE = ("usage: bench.py run BUILD [PROFILE] [--plan] | replot [DIR] | core BUILD [PROFILE] | "
         "methods [--binaries] [KIND...] | methods --get KEY FIELD | profile PROFILE")


def main(argv):
    if not argv or argv[0] in ("-h", "--help"):
        print(__doc__.strip())
        return 0 if argv else 2
    cmd, args = argv[0], argv[1:]
    try:
        if cmd == "run" and len(args) == 2 and args[1] == "3d":  # the 3-D part alone (benchlib/d3.py)
            from benchlib import d3
            try:
                d3.main(args[0], "3d")
            except common.Failure as e:
                print(f"bench: {e}", file=sys.stderr)
                return e.code
            return 0
        if cmd == "run" and len(args) == 2 and args[1] == "progressive":  # alone (benchlib/progressive.py)
            from benchlib import progressive
            try:
                progressive.main(args[0], "progressive")
            except common.Failure as e:
                print(f"bench: {e}", file=sys.stderr)
                return e.code
            return 0
        if cmd == "run" and 1 <= len(args) <= 3 and (len(args) < 3 or args[2] == "--plan"):
            return runner.main(args[0], args[1] if len(args) > 1 else "default", len(args) == 3)
        if cmd == "replot" and len(args) <= 1:
            from benchlib import plotdata
            try:
                plotdata.replot(args[0] if args else None)
            except common.Failure as e:
                print(f"replot: {e}", file=sys.stderr)
                return e.code
            return 0
        if cmd == "core" and 1 <= len(args) <= 2:
            from benchlib import core
            core.main(args[0], args[1] if len(args) > 1 else "default")
            return 0
        if cmd == "profile" and len(args) == 1:
            from benchlib import profiles
            p = profiles.profile(args[0], len(os.sched_getaffinity(0)))
            if p is None:
                raise common.Failure(f"unknown PROFILE '{args[0]}' (smoke, default, paper, seeds, lowk, density)", 2)
            out = {}
            for k, v in p.items():
                if k == "rt_sizes":
                    out.update((f"rt_sizes_{m}", " ".join(map(str, ns))) for m, ns in v.items())
                elif k == "ttq_configs_at":
                    out.update((f"ttq_configs_{n}", " ".join(f"{a}:{b}" for a, b in c)) for n, c in v.items())
                elif k == "ttq_limits":
                    out[k] = " ".join(f"{a}@{n}:{x}" for (a, n), x in v.items())
                elif k == "ttq_configs":
                    out[k] = " ".join(f"{a}:{b}" for a, b in v)
                elif isinstance(v, dict):
                    out[k] = " ".join(f"{a}:{b}" for a, b in v.items())
                elif isinstance(v, (list, tuple)):
                    out[k] = " ".join(map(str, v))
                else:
                    out[k] = "-" if v is None else v
            for k in sorted(out):
                print(f"{k}={out[k]}")
            return 0
        if cmd == "methods":
            m = methods.Methods()
            if args[:1] == ["--get"] and len(args) == 3:
                print(m.get(args[1], args[2]))
            elif args[:1] == ["--binaries"]:
                print(" ".join(m.binaries(*args[1:])))
            else:
                print(" ".join(m.keys(*args)))
            return 0
    except common.Failure as e:
        print(f"bench: {e}", file=sys.stderr)
        return e.code
    print(f"bench: {USAGE}", file=sys.stderr)
    return 2


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
