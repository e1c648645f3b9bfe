# mpi_common.sh - sourced by the tests under mpirun (test_mpi.sh,
# test_dens_mpi.sh) as `. mpi_common.sh BUILD_DIR MPIRUN PREFIX`: B (the
# build), MPIRUN, CFPO, a temporary folder T (removed at exit) made the
# working folder, OpenMPI allowed as root and oversubscribed, the pass /
# fail counters with ok and bad, run P ARGS...: cfpo on P ranks, 120 s at
# most, and expect_err CODE PATTERN P ARGS...: an error reported once for
# the whole job (one "cfpo:" line holding PATTERN), every rank exiting
# CODE, no file left in the folder; watchdog and unwatch bound a job
# started in the background.
B=$(cd "$1" && pwd)
MPIRUN=$2
CFPO="$B/cfpo"
T=$(mktemp -d "/tmp/$3-XXXXXX")
trap 'rm -rf "$T"' EXIT
cd "$T" || exit 1
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
pass=0 fail=0
ok() { pass=$((pass + 1)); }
bad() { fail=$((fail + 1)); echo "FAIL: $*" >&2; }
run() {
  local p=$1; shift
  timeout 120 "$MPIRUN" --oversubscribe -np "$p" "$CFPO" -q "$@"
}
# watchdog PID SECONDS PATTERN: after SECONDS, kill -KILL the job PID
# (mpirun, started with &; its status is then 137) and the processes whose
# command line holds PATTERN, so that a hang fails a check instead of
# running into CTest's limit; unwatch ends it once the job is waited for.
watchdog() {
  ( sleep "$2"; kill -KILL "$1"; pkill -KILL -f -- "$3" ) >/dev/null 2>&1 &
  wd=$!
}
unwatch() {
  pkill -P "$wd" 2>/dev/null
  kill "$wd" 2>/dev/null
  wait "$wd" 2>/dev/null
}
expect_err() {
  local code=$1 pat=$2 p=$3; shift 3
  local before; before=$(ls -A | sort)
  timeout 60 "$MPIRUN" --oversubscribe -np "$p" "$CFPO" "$@" >e.out 2>e.err
  local rc=$?
  local msgs; msgs=$(grep -c '^cfpo:' e.err)
  local after; after=$(ls -A | grep -v -e '^e.out$' -e '^e.err$' | sort)
  if [ $rc -eq 0 ]; then bad "mpirun -np $p cfpo $*: exit 0"
  elif [ "$msgs" -ne 1 ]; then bad "mpirun -np $p cfpo $*: $msgs messages: $(grep '^cfpo:' e.err)"
  elif ! grep -q -- "$pat" e.err; then bad "mpirun -np $p cfpo $*: message lacks '$pat': $(grep '^cfpo:' e.err)"
  elif [ "$after" != "$(echo "$before" | grep -v -e '^e.out$' -e '^e.err$')" ]; then bad "cfpo $*: left files"
  else ok; fi
  # every rank exits with the same code: mpirun reports it
  [ $rc -eq "$code" ] && ok || bad "mpirun -np $p cfpo $*: exit $rc, expected $code"
}
