#!/bin/sh
# cli_certify.sh - the FPD certificate from the command line.
# A converged CFPO set (build/cfpo -n 1024): near-pass (>= 99% of the points
# pass, violations under 0.1 Delta(n)) and both tests agree point for point.
# An exact pass is not expected: a CFPO fixed point is only the farthest
# point of its neighbours within the constraint square (cell grown by
# L - Delta(n)), and a few points (about 0.3%) could gain a few percent of
# Delta(n) just outside it (README.md). A converged FPO set (build/cfpo-fpo,
# when the baselines are built) passes exactly. A jittered copy and a
# dart-throwing set (generated here) fail.
. "$(dirname "$0")/common.sh"
cd "$T" || exit 1
"$B/cfpo" -n 1024 --seed 3 -t 1 -q -o cfpo.txt >/dev/null || bad "cfpo failed"
out=$("$A" -q -K 16 --certify cfpo.txt)
echo "cfpo:   $out"
p=$(field "$out" cert_pass); v=$(field "$out" cert_max_violation); l=$(field "$out" lct_pass)
check 'le 0.99 "$p"' "CFPO set: pass fraction $p"
check 'le "$v" 0.1' "CFPO set: max violation $v"
check '[ "$p" = "$l" ]' "CFPO set: the two tests disagree ($p vs $l)"
if [ -x "$B/cfpo-fpo" ]; then
  "$B/cfpo-fpo" -n 1024 --seed 3 -q -o fpo.txt >/dev/null || bad "cfpo-fpo failed"
  out=$("$A" -q -K 16 --certify -o fpo fpo.txt)
  echo "fpo:    $out"
  check '[ "$(field "$out" certify)" = pass ]' "FPO set does not pass"
else
  echo "(no $B/cfpo-fpo: FPO part skipped)"
fi
# jittered copy: every coordinate moved by up to 0.05 Delta(n)
awk -v a="$(awk 'BEGIN { print 0.1 * sqrt(2 / (sqrt(3) * 1024)) }')" 'BEGIN { srand(7) } !/^#/ {
  x = $1 + a * (rand() - 0.5); y = $2 + a * (rand() - 0.5)
  x -= int(x); if (x < 0) x += 1; y -= int(y); if (y < 0) y += 1
  if (x >= 1) x = 0; if (y >= 1) y = 0; printf "%.17g %.17g\n", x, y }' cfpo.txt >jitter.txt
out=$("$A" -q -K 16 --certify -o jitter jitter.txt)
echo "jitter: $out"
check '[ "$(field "$out" certify)" = fail ] && le "$(field "$out" cert_pass)" 0.5' "jittered set: $out"
# dart throwing: random points kept if no earlier point is within r
awk 'BEGIN { srand(11); r = 0.75 * sqrt(2 / (sqrt(3) * 300)); m = 0
  for (t = 0; t < 6000; t++) { x = rand(); y = rand(); okp = 1
    for (j = 0; j < m && okp; j++) { dx = x - X[j]; dy = y - Y[j]
      dx -= int(dx + (dx < 0 ? -0.5 : 0.5)); dy -= int(dy + (dy < 0 ? -0.5 : 0.5))
      if (dx * dx + dy * dy < r * r) okp = 0 }
    if (okp) { X[m] = x; Y[m] = y; m++ } }
  for (j = 0; j < m; j++) printf "%.17g %.17g\n", X[j], Y[j] }' >dart.txt
out=$("$A" -q -K 16 --certify -o dart dart.txt)
echo "dart:   $out"
check '[ "$(field "$out" certify)" = fail ] && le "$(field "$out" cert_pass)" 0.5' "dart set: $out"
finish
