#!/usr/bin/env bash
# test_readme.sh BUILD_DIR [README] - runs every command of the README's
# ```sh blocks, at small n, and fails if one fails. A README edit that adds
# a command is covered at once.
#
# The rules, applied to each command line (comments after '#' dropped,
# lines ending in '\' joined):
#   - `build/` is the build under test (BUILD_DIR);
#   - a point count (-n N, --points N) above 4096 becomes 1024, except in a
#     --dry-run (which allocates no points and needs its n);
#   - `make ...` lines are not run, each with its reason: this test runs
#     inside `make test`, the build is BUILD_DIR, `make bench` takes minutes
#     (test_bench_smoke runs its pipeline), `make python` builds the package
#     (the python test does);
#   - `mpirun` lines run with --oversubscribe, or are skipped with a message
#     where mpirun is not installed; lines needing root (apt, sudo) are
#     skipped.
# All commands run in turn in one temporary folder, so a command may read
# what an earlier one wrote (cfpo-analyze points.npy). Last, the same
# runner is pointed at a small README of its own with a failing command,
# and must fail: the test can fail.
set -u
BUILD=$(cd "${1:?usage: test_readme.sh BUILD_DIR [README]}" && pwd)
SRC=$(cd "$(dirname "$0")/.." && pwd)
README=${2:-$SRC/README.md}
pass=0
fail=0
ok() { pass=$((pass + 1)); echo "ok: $*"; }
bad() { fail=$((fail + 1)); echo "FAIL: $*"; }

export OMP_WAIT_POLICY=PASSIVE OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export OMPI_MCA_rmaps_base_oversubscribe=1

# The commands of the ```sh blocks, one a line.
commands() {
  awk '
    /^```/ { if (inblk) { inblk = 0; next } if ($0 ~ /^```sh[[:space:]]*$/) inblk = 1; next }
    inblk {
      line = $0
      sub(/[[:space:]]+#.*$/, "", line); sub(/^#.*$/, "", line)
      if (line ~ /\\$/) { sub(/\\$/, "", line); acc = acc line " "; next }
      line = acc line; acc = ""
      gsub(/^[[:space:]]+|[[:space:]]+$/, "", line)
      if (line != "") print line
    }' "$1"
}

# A point count written as the commands read it (65536, 2^20, 1e6, 2.5e3).
count_of() {
  awk -v s="$1" 'BEGIN {
    if (s ~ /^[0-9]+\^[0-9]+$/) { split(s, a, "^"); printf "%.0f\n", a[1] ^ a[2]; exit }
    if (s ~ /^[0-9.]+([eE][0-9]+)?$/) { printf "%.0f\n", s + 0; exit }
    print -1 }'
}

# Prints the command to run, or "SKIP reason".
rewrite() {
  local cmd=$1 out="" dry=0 w prev=""
  case "$cmd" in
    "make test"*) echo "SKIP this test runs inside make test"; return ;;
    "make bench"*) echo "SKIP make bench takes minutes; test_bench_smoke runs its pipeline (PROFILE=smoke)"; return ;;
    "make python"*) echo "SKIP make python builds the package; the python test (label python) does"; return ;;
    "make" | "make build"* | "make "*) echo "SKIP the build under test is $BUILD"; return ;;
    sudo* | apt*) echo "SKIP needs root"; return ;;
    source\ *) echo "SKIP changes the shell's environment only"; return ;;
  esac
  case " $cmd " in *" --dry-run "*) dry=1 ;; esac
  read -r -a words <<<"$cmd"
  if [ "${words[0]}" = mpirun ]; then
    command -v mpirun >/dev/null 2>&1 || { echo "SKIP mpirun is not installed"; return; }
    words=(mpirun --oversubscribe "${words[@]:1}")
  fi
  for w in "${words[@]}"; do
    if [ "$dry" = 0 ] && { [ "$prev" = -n ] || [ "$prev" = --points ]; }; then
      local c
      c=$(count_of "$w")
      [ "$c" -gt 4096 ] 2>/dev/null && w=1024
    fi
    case "$w" in build/*) w="$BUILD/${w#build/}" ;; esac
    out="$out $w"
    prev=$w
  done
  echo "${out# }"
}

# Runs every command of README $1 in a fresh folder; returns the failures.
run_readme() {
  local file=$1 tmp n=0 f=0 cmd run
  tmp=$(mktemp -d)
  while IFS= read -r cmd; do
    run=$(rewrite "$cmd")
    case "$run" in SKIP*) echo "skip: $cmd (${run#SKIP })"; continue ;; esac
    n=$((n + 1))
    if (cd "$tmp" && timeout 300 bash -c "$run" </dev/null >"$tmp/.log" 2>&1); then
      echo "  ran: $run"
    else
      echo "  failed: $run"
      sed 's/^/    /' "$tmp/.log" | tail -n 5
      f=$((f + 1))
    fi
  done < <(commands "$file")
  rm -rf "$tmp"
  [ "$n" -gt 0 ] || { echo "  no command found in $file"; f=$((f + 1)); }
  return "$f"
}

echo "== the commands of $README"
if run_readme "$README"; then ok "every command of the README ran"; else bad "a command of the README failed"; fi

# The rules themselves: a large n is cut, and a failing command fails.
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
[ "$(rewrite 'build/cfpo -n 2^20 -o p.npy')" = "$BUILD/cfpo -n 1024 -o p.npy" ] &&
  [ "$(rewrite 'build/cfpo -n 1e10 --dry-run --ranks 4')" = "$BUILD/cfpo -n 1e10 --dry-run --ranks 4" ] &&
  [ "$(rewrite 'build/cfpo --points 4096 -o p.npy')" = "$BUILD/cfpo --points 4096 -o p.npy" ] &&
  case "$(rewrite 'make bench PROFILE=smoke')" in SKIP*) true ;; *) false ;; esac &&
  ok "large n cut to 1024 (not in a dry run), make bench skipped" || bad "the rewrite rules"
printf '# t\n\n```sh\nbuild/cfpo -n 1e6 --max-iter 1 -q -o big.npy   # cut to 1,024\n```\n' >"$scratch/good.md"
if run_readme "$scratch/good.md" >/dev/null; then ok "a README with a good command passes"; else bad "a good command failed"; fi
printf '# t\n\n```sh\nbuild/cfpo -n 4096 \\\n  --tol 7 -o x.npy\n```\n' >"$scratch/broken.md"
if run_readme "$scratch/broken.md" >/dev/null; then bad "a README with a failing command passed"; else ok "a README with a failing command fails"; fi
printf '# t\n\n```c\nint main(void) { return 1; }\n```\n' >"$scratch/none.md"
if run_readme "$scratch/none.md" >/dev/null; then bad "a README without commands passed"; else ok "a README without commands fails"; fi

echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]
