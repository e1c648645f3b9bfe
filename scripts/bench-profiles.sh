# bench-profiles.sh - the plans of `make bench PROFILE=...` (sourced by
# bench.sh; sets variables, runs nothing).
#
#   SETS          point sets per spectrum (comparison and evolution figures)
#   COMP_N        points per set in the comparison, evolution and convergence
#   COMP_THREADS  threads of CFPO in the comparison (1: every method on one
#                 core, so the seconds compare like for like)
#   COMP_TOGETHER one-thread comparison runs of one method (successive
#                 seeds) that start together, each pinned to its own core
#                 (at most the cores; 1: every run alone, the seconds free of
#                 a neighbour's use of the memory system)
#   EVO_ITERS     iterations at which CFPO is stopped for the evolution figure
#                 (the converged column reuses the comparison's CFPO sets)
#   RT_REPS       seeds per configuration of the runtime experiment
#   RT_THREADS    thread counts of CFPO in the runtime experiment (the
#                 baselines are single-threaded); 1, powers of two, all cores
#   RT_SIZES_<m>  n of the runtime experiment per method m (empty: none);
#                 CFPO also runs on as many MPI ranks as cores (one thread
#                 each) at RT_SIZES_cfpo when mpirun is installed
#   TTQ_SIZES     n of the time-to-quality experiment: every iterative
#                 method (TTQ_CONFIGS) runs with --trace until the quality
#                 target TTQ_TARGET_MIN / TTQ_TARGET_AVG holds, it converges,
#                 or its time limit (bench_ttq_limit) passes
#   TTQ_BIG       n at which only CFPO (default variant, 2 threads) runs
#                 that experiment (empty: none)
#   TTQ_SEEDS     seeds per configuration of that experiment
#   TTQ_MAXITER   iteration cap of its runs (- none)
#   TTQ_CONFIGS   its configurations, KEY:THREADS (adaptive = cfpo's default
#                 variant, paper = cfpo --variant paper); the one-thread runs
#                 of one n and seed start together, one per core, pinned
#                 (taskset), in groups of as many as there are cores, in this
#                 order; a run on several threads runs alone
#   TTQ_CONFIGS_<n>  the configurations at n when they differ (unset: TTQ_CONFIGS)
#
# The runtime figure uses every uncapped run (comparison and runtime
# experiments), so the runtime plan leaves out n = COMP_N on COMP_THREADS.

bench_threads_list() {
  local c t=1 list=""
  c=$(nproc)
  while [ "$t" -lt "$c" ]; do list="$list $t"; t=$((t * 2)); done
  echo "${list# } $c" | sed 's/^ //'
}

bench_profile() {
  # OpenMP threads sleep at barriers instead of spinning (unless the caller
  # set OMP_WAIT_POLICY): with spinning, any other busy process on a 2-core
  # machine makes a 2-thread CFPO run 10-100x slower (9 barriers per
  # iteration, each waiting for a descheduled thread); see README.md
  export OMP_WAIT_POLICY=${OMP_WAIT_POLICY:-passive}
  COMP_THREADS=1
  COMP_TOGETHER=$(nproc)
  EVO_ITERS="0 1 2 5 10"
  RT_THREADS=$(bench_threads_list)
  TTQ_TARGET_MIN=0.925; TTQ_TARGET_AVG=0.929
  TTQ_CONFIGS="adaptive:1 fpo:1 paper:1 lfpo:1 adaptive:2"
  TTQ_SIZES="4096 65536"; TTQ_BIG=""; TTQ_SEEDS=3; TTQ_MAXITER=-
  case "$1" in
    smoke)
      SETS=2; COMP_N=1024; RT_REPS=1
      RT_SIZES_cfpo="256 512"; RT_SIZES_simplified="256"
      RT_SIZES_fpo="256"; RT_SIZES_lfpo="256"; RT_SIZES_ccvt="256"; RT_SIZES_ccdt="256"
      RT_SIZES_bnot="256"
      RT_SIZES_dart="4096"; RT_SIZES_bs="4096"; RT_SIZES_bridson="4096"
      TTQ_SIZES="1024"; TTQ_SEEDS=1; TTQ_MAXITER=80
      ;;
    default)
      SETS=10; COMP_N=4096; RT_REPS=1
      RT_SIZES_cfpo="1024 4096 16384"; RT_SIZES_simplified="1024 4096"
      RT_SIZES_fpo="1024 16384"; RT_SIZES_lfpo="1024"
      RT_SIZES_ccvt="1024"; RT_SIZES_ccdt="1024"
      RT_SIZES_bnot="1024 4096 16384"
      # at 65,536 points only the experiment the CFPO schedule is tuned
      # on: adaptive CFPO on one and two threads against FPO (CFPO-paper
      # and LFPO there: PROFILE=paper)
      TTQ_CONFIGS_65536="adaptive:1 fpo:1 adaptive:2"
      RT_SIZES_dart="1024 4096 16384 65536 262144"
      RT_SIZES_bs="1024 4096 16384 65536 262144"
      RT_SIZES_bridson="1024 4096 16384 65536 262144"
      ;;
    paper)
      SETS=10; COMP_N=4096; RT_REPS=1
      COMP_TOGETHER=1
      RT_SIZES_cfpo="1024 4096 16384 65536 262144 1048576"
      RT_SIZES_simplified="1024 4096 16384 65536 262144"
      RT_SIZES_fpo="1024 4096 16384 65536 262144"; RT_SIZES_lfpo="1024 4096 16384 65536"
      RT_SIZES_ccvt="1024 4096 16384 65536"; RT_SIZES_ccdt="1024 4096 16384 65536"
      RT_SIZES_bnot="1024 4096 16384"
      RT_SIZES_dart="1024 4096 16384 65536 262144 1048576"
      RT_SIZES_bs="1024 4096 16384 65536 262144 1048576"
      RT_SIZES_bridson="1024 4096 16384 65536 262144 1048576"
      TTQ_BIG="1048576"
      ;;
    *) return 1 ;;
  esac
}

# bench_estimate KEY N THREADS MAXITER: rough seconds of one run, for the
# progress display's time-left estimate only (the display rescales it by the
# measured/estimated ratio of the runs finished so far). From single runs on
# this 2-core machine: iterations to converge ~ a (n/1024)^b (capped), and
# seconds per point and iteration on one core.
bench_estimate() {
  awk -v k="$1" -v n="$2" -v t="$3" -v m="$4" 'BEGIN {
    if (k == "cfpo-mpi") { k = "cfpo"; t = 2 }
    if (k == "dart") { print 8e-6 * n + 0.01; exit }
    if (k == "bs") { print 1.5e-6 * n + 0.01; exit }
    if (k == "bridson") { print 5e-6 * n + 0.01; exit }
    a["cfpo"] = 230; b["cfpo"] = 0.5; cap["cfpo"] = 1250; c["cfpo"] = 1.1e-6
    a["simplified"] = 654; b["simplified"] = 0.35; cap["simplified"] = 1550; c["simplified"] = 0.75e-6
    a["fpo"] = 166; b["fpo"] = 0.33; cap["fpo"] = 5000; c["fpo"] = 2.5e-6
    a["lfpo"] = 239; b["lfpo"] = 0.55; cap["lfpo"] = 5000; c["lfpo"] = 2.5e-6
    a["ccvt"] = 330; b["ccvt"] = 0; cap["ccvt"] = 5000; c["ccvt"] = 1.5e-5
    a["ccdt"] = 120; b["ccdt"] = 0.1; cap["ccdt"] = 5000; c["ccdt"] = 1.5e-5
    a["bnot"] = 20; b["bnot"] = 0; cap["bnot"] = 20; c["bnot"] = 1.05e-5
    it = a[k] * (n / 1024) ^ b[k]; if (it > cap[k]) it = cap[k]
    if (m != "-" && m + 0 < it) it = m + 0
    s = c[k] * n * it
    if ((k == "cfpo" || k == "simplified") && t > 1) s /= 0.95 * t
    printf "%.3f\n", s + 0.01 }'
}

# bench_ttq_limit N: the time limit (seconds) of a time-to-quality run with
# n points. FPO needs about 65 s at 65,536 points to reach the target on
# this machine; LFPO several times that (it stops at the limit).
bench_ttq_limit() {
  awk -v n="$1" 'BEGIN { print (n <= 1024) ? 10 : (n <= 4096) ? 30 : (n <= 65536) ? 150 : 900 }'
}

# bench_ttq_estimate KEY N THREADS MAXITER LIMIT: rough seconds of one
# time-to-quality run: until the target holds or the run converges, at most
# LIMIT (or MAXITER iterations). Single runs on this 2-core machine: adaptive
# CFPO reaches the target in 72 iterations at 4,096 points (0.71 s on one
# thread) and converges just short of it at 16,384 (339 iterations, 7.7 s on
# two), so at most about 350 iterations at 2.2e-6 s per point and iteration
# on one thread; paper CFPO converges before the target (cfpo model of
# bench_estimate); FPO reaches the target in 0.78 s at 4,096 points and
# about 65 s at 65,536, LFPO in 4.75 s at 4,096 (both 2.2-2.5e-6 s per point
# and iteration).
bench_ttq_estimate() {
  local conv
  if [ "$1" = paper ]; then conv=$(bench_estimate cfpo "$2" "$3" "$4"); else conv=0; fi
  awk -v k="$1" -v n="$2" -v t="$3" -v m="$4" -v lim="$5" -v conv="$conv" 'BEGIN {
    r = n / 4096
    if (k == "adaptive") { it = 72 * r ^ 1.1; if (it > 350) it = 350; if (m != "-" && m + 0 < it) it = m + 0
      s = 2.2e-6 * n * it; if (t > 1) s /= 0.95 * t }
    else if (k == "paper") s = conv
    else { s = (k == "fpo") ? 0.78 * r ^ 1.6 : 4.75 * r ^ 1.64
      if (m != "-" && 2.5e-6 * n * m < s) s = 2.5e-6 * n * m }
    if (s > lim + 0) s = lim + 0
    printf "%.3f\n", s + 0.01 }'
}
