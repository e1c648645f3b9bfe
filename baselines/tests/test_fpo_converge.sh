#!/usr/bin/env bash
# test_fpo_converge.sh BUILD_DIR - a converged 4096-point global FPO set,
# with cfpo's default tolerance and stopping rule, reaches the published
# quality: delta_min >= 0.92 and delta_avg >= 0.928 (Schloemer et al. report
# about 0.925 and 0.932 at 1024 points). Ends with "N passed, N failed".
set -u
B=${1:?usage: test_fpo_converge.sh BUILD_DIR}
pass=0 fail=0
line=$("$B/cfpo-fpo" -n 4096 -s 1 -q) || { echo "cfpo-fpo failed"; echo "0 passed, 1 failed"; exit 1; }
echo "$line"
get() { sed -n "s/.* $1=\([^ ]*\).*/\1/p" <<<"$line"; }
check() { if awk "BEGIN{exit !($1)}"; then pass=$((pass + 1)); else fail=$((fail + 1)); echo "FAIL: $2" >&2; fi; }
[ "$(get converged)" = yes ] && pass=$((pass + 1)) || { fail=$((fail + 1)); echo "FAIL: not converged" >&2; }
check "$(get delta_min) >= 0.92" "delta_min $(get delta_min) < 0.92"
check "$(get delta_avg) >= 0.928" "delta_avg $(get delta_avg) < 0.928"
echo "$pass passed, $fail failed"
[ $fail -eq 0 ]
