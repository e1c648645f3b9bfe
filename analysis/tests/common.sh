# common.sh - shared by the cli_*.sh tests: counters, checks, the closing
# "N passed, N failed" line, and a scratch folder removed on exit.
# Sourced with the build folder as $1.
B=${1:?usage: test.sh BUILD_DIR}
B=$(cd "$B" && pwd)
A="$B/cfpo-analyze"
T=$(mktemp -d "${TMPDIR:-/tmp}/cfpo-analysis-test.XXXXXX")
trap 'rm -rf "$T"' EXIT
pass=0
fail=0
ok() { pass=$((pass + 1)); }
bad() { fail=$((fail + 1)); echo "FAIL: $*" >&2; }
check() { if eval "$1"; then ok; else bad "$2"; fi; }
finish() { echo "$pass passed, $fail failed"; [ "$fail" -eq 0 ]; }
# field VALUE of key=VALUE in a SUMMARY line
field() { echo "$1" | tr ' ' '\n' | sed -n "s/^$2=//p"; }
# awk comparison: le A B -> true when A <= B
le() { awk -v a="$1" -v b="$2" 'BEGIN { exit !(a + 0 <= b + 0) }'; }
