#!/usr/bin/env bash
# test_fpo_stop.sh BUILD_DIR - the stop rules of cfpo-fpo and cfpo-lfpo
# (--target-min, --target-avg, --time-limit; the SUMMARY field stop=):
# a target run stops at the first row of its own trace where every given
# target holds, and its points are those of a run capped at that iteration;
# a target met by the start stops at iteration 0; an unreachable target
# runs to convergence; a time limit stops at the first iteration boundary
# past it (trace elapsed) and soon after in wall-clock time; max-iter and
# converged are named; bad values are usage errors. Ends with "N passed, N
# failed".
set -u
B=${1:?usage: test_fpo_stop.sh BUILD_DIR}
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT
pass=0 fail=0
ok() { pass=$((pass + 1)); }
bad() { fail=$((fail + 1)); echo "FAIL: $*" >&2; }
get() { sed -n "s/.* $1=\([^ ]*\).*/\1/p" <<<"$2"; }

# first_row TRACE DMIN DAVG: the first iteration whose delta_min >= DMIN and
# delta_avg >= DAVG (0 = not given), or "none"
first_row() {
  awk -F'\t' -v a="$2" -v b="$3" 'NR > 1 && $2 >= a && $3 >= b { print $1; found = 1; exit }
    END { if (!found) print "none" }' "$1"
}
last_row() { tail -n 1 "$1" | cut -f1; }

for c in cfpo-fpo cfpo-lfpo; do
  X="$B/$c"
  # targets on both, on one of them
  for tg in "0.90 0.925" "0.88 0" "0 0.928"; do
    set -- $tg
    args=()
    [ "$1" != 0 ] && args+=(--target-min "$1")
    [ "$2" != 0 ] && args+=(--target-avg "$2")
    line=$("$X" -n 1024 -s 3 -q "${args[@]}" --trace "$T/t.tsv" -o "$T/a.bin")
    first=$(first_row "$T/t.tsv" "$1" "$2")
    last=$(last_row "$T/t.tsv")
    if [ "$(get stop "$line")" = target ] && [ "$first" = "$last" ] && [ "$(get iterations "$line")" = "$last" ] \
      && [ "$last" -gt 0 ]; then ok
    else bad "$c ${args[*]}: stop=$(get stop "$line") iterations=$(get iterations "$line"), trace: first row meeting the targets $first, last row $last"; fi
    # the stop rule changes when the run ends, not what it computes
    "$X" -n 1024 -s 3 -q --max-iter "$last" -o "$T/b.bin" >"$T/cap.out"
    if cmp -s "$T/a.bin" "$T/b.bin" && [ "$(get stop "$(cat "$T/cap.out")")" = max-iter ]; then ok
    else bad "$c ${args[*]}: points differ from --max-iter $last, or that run's stop is not max-iter"; fi
  done
  # a target the start already meets: iteration 0
  line=$("$X" -n 1024 -q --target-avg 0.05 --trace "$T/t.tsv")
  [ "$(get stop "$line")" = target ] && [ "$(get iterations "$line")" = 0 ] && [ "$(wc -l <"$T/t.tsv")" = 2 ] && ok \
    || bad "$c: target met at the start: $line"
  # unreachable: converges first
  line=$("$X" -n 512 -q --target-min 0.99 --trace "$T/t.tsv")
  [ "$(get stop "$line")" = converged ] && [ "$(get converged "$line")" = yes ] \
    && [ "$(first_row "$T/t.tsv" 0.99 0)" = none ] && ok || bad "$c: unreachable target: $line"
  line=$("$X" -n 512 -q --max-iter 4)
  [ "$(get stop "$line")" = max-iter ] && [ "$(get iterations "$line")" = 4 ] && ok || bad "$c: max-iter: $line"
  # time limit: --tol 0 never converges at this size within the limit
  lim=0.6
  t1=$(date +%s.%N)
  line=$("$X" -n 4096 -q --tol 0 --time-limit "$lim" --trace "$T/t.tsv")
  t2=$(date +%s.%N)
  verdict=$(awk -F'\t' -v lim="$lim" 'NR > 1 { prev = last; last = $8; step = $7 }
    END { if (last >= lim && prev < lim) print "ok"; else printf "elapsed of the last two rows %s, %s", prev, last }' "$T/t.tsv")
  [ "$(get stop "$line")" = time ] && [ "$verdict" = ok ] && ok || bad "$c: time limit $lim: stop=$(get stop "$line"), $verdict"
  awk -v a="$t1" -v b="$t2" -v lim="$lim" 'BEGIN { exit !(b - a < lim + 3) }' && ok \
    || bad "$c: --time-limit $lim took $(awk -v a="$t1" -v b="$t2" 'BEGIN { print b - a }') s"
  # bad values: usage errors, one line
  for bv in "--target-min 0" "--target-min 1.5" "--target-avg x" "--time-limit -1" "--time-limit"; do
    # shellcheck disable=SC2086
    "$X" -n 256 -q $bv >"$T/out" 2>"$T/err"
    rc=$?
    [ $rc -eq 2 ] && [ "$(wc -l <"$T/err")" = 1 ] && grep -q "^$c: " "$T/err" && ok \
      || bad "$c $bv: exit $rc, stderr '$(head -c 200 "$T/err")'"
  done
done
line=$("$B/cfpo-fpo" -n 512 -q)
[ "$(get stop "$line")" = converged ] && ok || bad "cfpo-fpo default run: $line"
echo "$pass passed, $fail failed"
[ $fail -eq 0 ]
