#!/bin/sh
# cli_average.sh - averaging many files equals the mean of the single-file
# results: the averaged spectrum matrix and RAPS are the means of the three
# single-file ones (to the printed precision), delta_min and delta_avg the
# means of the single values, the NN histogram the sum, the mean spike
# ratio the mean of the single ones; averaging one file
# three times gives that file's result.
. "$(dirname "$0")/common.sh"
cd "$T" || exit 1
for s in 1 2 3; do
  "$B/cfpo" -n 256 --seed $s -t 1 -q -o s$s.txt >/dev/null || bad "cfpo seed $s"
  "$A" -q -K 24 -o one$s s$s.txt >/dev/null || bad "single $s"
done
avg=$("$A" -q -K 24 -o all s1.txt s2.txt s3.txt)
check '[ $? -eq 0 ] && [ "$(field "$avg" sets)" = 3 ]' "average run: $avg"
# spectrum matrix: element by element
check "paste one1/spectrum.txt one2/spectrum.txt one3/spectrum.txt all/spectrum.txt | awk 'NR > 1 {
    w = NF / 4
    for (i = 2; i <= w; i++) { m = (\$i + \$(i + w) + \$(i + 2 * w)) / 3; d = m - \$(i + 3 * w); if (d < 0) d = -d
      if (d > 1e-8 * (m > 1 ? m : 1)) { print NR, i, m, \$(i + 3 * w) > \"/dev/stderr\"; exit 1 } } }'" \
  "averaged spectrum is not the mean of the single spectra"
check "paste one1/raps.txt one2/raps.txt one3/raps.txt all/raps.txt | awk '!/^#/ {
    m = (\$3 + \$8 + \$13) / 3; d = m - \$18; if (d < 0) d = -d; if (d > 1e-9 * (m > 1 ? m : 1)) exit 1 }'" \
  "averaged RAPS is not the mean of the single RAPS"
check "paste one1/nn_hist.txt one2/nn_hist.txt one3/nn_hist.txt all/nn_hist.txt | awk '!/^#/ { if (\$3 + \$7 + \$11 != \$15) exit 1 }'" \
  "averaged histogram is not the sum"
for k in delta_min delta_avg; do
  m=$(for s in 1 2 3; do field "$("$A" -q -K 8 -o x$s$k s$s.txt)" $k; done | awk '{ s += $1 } END { printf "%.9f", s / 3 }')
  a=$(field "$avg" $k)
  check "awk -v a=$a -v m=$m 'BEGIN { d = a - m; if (d < 0) d = -d; exit d > 2e-6 }'" "$k: average $a, mean of singles $m"
done
# the per-set spike ratios: their mean, and each one, are the single runs'
m=$(for s in 1 2 3; do field "$("$A" -q -K 24 -o y$s s$s.txt)" spike_ratio; done | awk '{ s += $1 } END { printf "%.9g", s / 3 }')
a=$(field "$avg" spike_ratio_set_mean)
check "awk -v a=$a -v m=$m 'BEGIN { d = a - m; if (d < 0) d = -d; exit d > 1e-5 * m }'" "spike_ratio_set_mean: average $a, mean of singles $m"
check "[ \"\$(field \"\$avg\" spike_ratio)\" != \"$a\" ]" "spike ratio of the averaged spectrum equals the mean of the per-set ratios"
"$A" -q -K 24 -o same s1.txt s1.txt s1.txt >/dev/null
check "paste one1/raps.txt same/raps.txt | awk '!/^#/ { d = \$3 - \$8; if (d < 0) d = -d; if (d > 1e-9 * (\$3 > 1 ? \$3 : 1)) exit 1 }'" \
  "one file averaged three times differs from itself"
# sets of different n: refused, unless --any-n; then P is still the mean of
# the single spectra and n the sets' mean, rounded
"$B/cfpo" -n 300 --seed 4 -t 1 -q -o s4.txt >/dev/null || bad "cfpo n=300"
"$A" -q -K 24 -o one4 s4.txt >/dev/null || bad "single 4"
"$A" -q -K 24 -o mixed s1.txt s4.txt >/dev/null 2>&1
check '[ $? -eq 1 ]' "sets of different n averaged without --any-n"
mixed=$("$A" -q -K 24 --any-n -o mixed s1.txt s4.txt)
check '[ $? -eq 0 ] && [ "$(field "$mixed" n)" = 278 ] && [ "$(field "$mixed" sets)" = 2 ]' "--any-n run: $mixed"
check "paste one1/spectrum.txt one4/spectrum.txt mixed/spectrum.txt | awk 'NR > 1 {
    w = NF / 3
    for (i = 2; i <= w; i++) { m = (\$i + \$(i + w)) / 2; d = m - \$(i + 2 * w); if (d < 0) d = -d
      if (d > 1e-8 * (m > 1 ? m : 1)) exit 1 } }'" \
  "--any-n: averaged spectrum is not the mean of the single spectra"
finish
