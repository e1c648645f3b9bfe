# bench-profiles.sh - the plans of `make bench PROFILE=...` (sourced by
# bench.sh; sets variables, runs nothing).
#
#   SETS          point sets per spectrum (comparison and evolution figures)
#   COMP_N        points per set in the comparison, evolution and convergence
#   COMP_THREADS  threads of CFPO in the comparison (1: every method on one
#                 core, so the seconds compare like for like)
#   EVO_ITERS     iterations at which CFPO is stopped for the evolution figure
#                 (the converged column reuses the comparison's CFPO sets)
#   RT_REPS       seeds per configuration of the runtime experiment
#   RT_THREADS    thread counts of CFPO in the runtime experiment (the
#                 baselines are single-threaded); 1, powers of two, all cores
#   RT_SIZES_<m>  n of the runtime experiment per method m (empty: none);
#                 CFPO also runs on as many MPI ranks as cores (one thread
#                 each) at RT_SIZES_cfpo when mpirun is installed
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
  EVO_ITERS="0 1 2 5 10"
  RT_THREADS=$(bench_threads_list)
  case "$1" in
    smoke)
      SETS=2; COMP_N=1024; RT_REPS=1
      RT_SIZES_cfpo="256 512"; RT_SIZES_simplified="256"
      RT_SIZES_fpo="256"; RT_SIZES_lfpo="256"
      RT_SIZES_dart="4096"; RT_SIZES_bs="4096"; RT_SIZES_bridson="4096"
      ;;
    default)
      SETS=10; COMP_N=4096; RT_REPS=1
      RT_SIZES_cfpo="1024 4096 16384 65536"; RT_SIZES_simplified="1024 4096 16384"
      RT_SIZES_fpo="1024 16384"; RT_SIZES_lfpo="1024 16384"
      RT_SIZES_dart="1024 4096 16384 65536 262144"
      RT_SIZES_bs="1024 4096 16384 65536 262144"
      RT_SIZES_bridson="1024 4096 16384 65536 262144"
      ;;
    paper)
      SETS=10; COMP_N=4096; RT_REPS=1
      RT_SIZES_cfpo="1024 4096 16384 65536 262144 1048576"
      RT_SIZES_simplified="1024 4096 16384 65536 262144"
      RT_SIZES_fpo="1024 4096 16384 65536 262144"; RT_SIZES_lfpo="1024 4096 16384 65536"
      RT_SIZES_dart="1024 4096 16384 65536 262144 1048576"
      RT_SIZES_bs="1024 4096 16384 65536 262144 1048576"
      RT_SIZES_bridson="1024 4096 16384 65536 262144 1048576"
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
    it = a[k] * (n / 1024) ^ b[k]; if (it > cap[k]) it = cap[k]
    if (m != "-" && m + 0 < it) it = m + 0
    s = c[k] * n * it
    if ((k == "cfpo" || k == "simplified") && t > 1) s /= 0.95 * t
    printf "%.3f\n", s + 0.01 }'
}
