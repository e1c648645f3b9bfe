#!/bin/sh
# cli_measures.sh - the measures of analysis/measures/ in cfpo-analyze: every
# key in the SUMMARY line (between check_maxdiff and peak_bytes, out= last)
# and in stats.json, CFPO values on the right side of white noise's,
# averaging two sets (discrepancies: the mean of the sets' values; shift
# variances and P0: the values of the averaged spectrum, i.e. the means),
# --no-discrepancy leaving everything else byte-identical; the pair
# correlation, Delaunay measures and integration test (CFPO more ordered
# than white noise, pcf.txt averaged, their options).
. "$(dirname "$0")/../../tests/common.sh"
cd "$T" || exit 1

"$B/cfpo" -n 1024 --seed 2 -t 1 -q -o a.txt >/dev/null || bad "cfpo failed"
"$B/cfpo" -n 1024 --seed 3 -t 1 -q -o b.txt >/dev/null || bad "cfpo failed"
awk 'BEGIN { srand(5); for (i = 0; i < 1024; i++) printf "%.17g %.17g\n", rand(), rand() }' >w.txt

keys="p0 h_index lowk_alpha disc_wrap_l2 disc_diaphony disc_l2_star disc_gen_l2 disc_centred_l2
shiftvar_gauss_0.02 shiftvar_gauss_0.05 shiftvar_gauss_0.15 shiftvar_disk_0.1 shiftvar_disk_0.25 shiftvar_disk_0.4
psi6 voronoi_area_var mesh_ratio covering_radius utk_gauss_mse utk_heaviside_mse"
sa=$("$A" -q -t 1 -o a a.txt) || bad "cfpo-analyze a.txt failed"
sw=$("$A" -q -t 1 -o w w.txt) || bad "cfpo-analyze w.txt failed"
for k in $keys; do
  check "field \"\$sa\" $k | grep -Eq '^-?[0-9.]+(e[-+][0-9]+)?\$'" "$k missing or not a number: $sa"
done
check 'echo "$sa" | grep -q " check_maxdiff=- p0=.* shiftvar_disk_0.4=[^ ]* psi6=.* utk_heaviside_mse=[^ ]* prefix_base=- .* prefix_worst_any_m=- peak_bytes=[0-9]* out=a$"' \
  "key order: $sa"
# CFPO against white noise: less low-frequency power, smaller discrepancies
# and integration variances
check 'le "$(field "$sa" p0)" 0.05 && le 0.7 "$(field "$sw" p0)"' "p0: cfpo $(field "$sa" p0), white $(field "$sw" p0)"
# (the centred L2 discrepancy of one 1,024-point CFPO set spreads with the
# seed: 0.0026-0.0053 over seeds 2-6, before and after 2026-11-28's grid
# walk, against white noise's 0.0130 here: it is asked to be 2x below, the
# others 3x)
for k in disc_wrap_l2 disc_centred_l2 shiftvar_gauss_0.05 shiftvar_disk_0.25; do
  f=3
  [ $k = disc_centred_l2 ] && f=2
  check 'awk -v a="$(field "$sa" $k)" -v w="$(field "$sw" $k)" -v f=$f "BEGIN { exit !(f * a < w) }"' \
    "$k: cfpo $(field "$sa" $k) not $f times below white noise's $(field "$sw" $k)"
done
# The L2-star discrepancy against white noise's exact expectation,
# E[D^2] = (2^-2 - 3^-2) / n (D = 0.0116 at 1,024 points), not one white
# set: D of one set, white or CFPO, spreads widely (this white set 0.0086;
# CFPO seeds 2-13 0.0018-0.0046). The root mean square of four CFPO sets
# (seeds 2-5) is asked to be 3 times below the expectation's root.
"$B/cfpo" -n 1024 --seed 4 -t 1 -q -o c.txt >/dev/null || bad "cfpo failed"
"$B/cfpo" -n 1024 --seed 5 -t 1 -q -o d.txt >/dev/null || bad "cfpo failed"
ms=0
for f in a b c d; do
  if [ $f = a ]; then s1=$sa; else s1=$("$A" -q -t 1 --integration 0 --no-delaunay -o l$f $f.txt) || bad "cfpo-analyze $f.txt failed"; fi
  d=$(field "$s1" disc_l2_star)
  ms=$(awk -v m="$ms" -v d="$d" 'BEGIN { printf "%.10g", m + d * d / 4 }')
done
check 'awk -v m="$ms" "BEGIN { exit !(9 * m < (1 / 4 - 1 / 9) / 1024) }"' \
  "disc_l2_star: root mean square of four CFPO sets $(awk -v m="$ms" 'BEGIN { print sqrt(m) }') not 3 times below white noise's $(awk 'BEGIN { print sqrt((1 / 4 - 1 / 9) / 1024) }')"
for j in '"low_frequency": {"range": 6.4, "P0": ' '"P0_count": ' '"rings": \[1, 6\]' '"discrepancy": {"rooted": true' \
         '"per_set": {"wrap_around_l2": \[' '"shift_variance": {"tail": ' '"disk_0.25": {"radius": 0.25, "var": '; do
  check "grep -q '$j' a/stats.json" "stats.json lacks $j"
done

# two sets: discrepancies are the mean of the single values; P0 and the
# shift variances come from the averaged spectrum, which is their mean
sb=$("$A" -q -t 1 -o b b.txt) || bad "cfpo-analyze b.txt failed"
sab=$("$A" -q -t 1 -o ab a.txt b.txt) || bad "cfpo-analyze a.txt b.txt failed"
for k in $keys; do
  [ "$k" = h_index ] || [ "$k" = lowk_alpha ] && continue
  check 'awk -v a="$(field "$sa" $k)" -v b="$(field "$sb" $k)" -v m="$(field "$sab" $k)" \
    "BEGIN { d = m - (a + b) / 2; if (d < 0) d = -d; exit !(d <= 1e-5 * m) }"' \
    "$k of two sets $(field "$sab" $k) is not the mean of $(field "$sa" $k) and $(field "$sb" $k)"
done
check 'grep -q "\"per_set\": {\"wrap_around_l2\": \[[^],]*, [^],]*\]" ab/stats.json' "per_set has not two values"

# --no-discrepancy: the discrepancies are '-' and null, the rest unchanged
sn=$("$A" -q -t 1 --no-discrepancy -o n a.txt) || bad "--no-discrepancy failed"
for k in disc_wrap_l2 disc_diaphony disc_l2_star disc_gen_l2 disc_centred_l2; do
  check '[ "$(field "$sn" $k)" = - ]' "--no-discrepancy: $k=$(field "$sn" $k)"
done
check 'grep -q "\"discrepancy\": null" n/stats.json' "--no-discrepancy: discrepancy not null"
for k in p0 h_index lowk_alpha shiftvar_disk_0.1 raps_peak delta_avg; do
  check '[ "$(field "$sn" $k)" = "$(field "$sa" $k)" ]' "--no-discrepancy changed $k"
done
for f in spectrum.txt raps.txt nn_hist.txt plot.gp; do check "cmp -s a/$f n/$f" "--no-discrepancy changed $f"; done
# structure and integration: CFPO on the ordered side of white noise; pcf.txt
# is the mean of the sets' g; the options' bad values are usage errors
gt() { awk -v a="$1" -v b="$2" 'BEGIN { exit !(a > b) }'; }
check 'gt "$(field "$sa" psi6)" "$(field "$sw" psi6)"' "psi6: cfpo $(field "$sa" psi6), white $(field "$sw" psi6)"
check 'gt "$(field "$sw" voronoi_area_var)" "$(field "$sa" voronoi_area_var)"' "voronoi_area_var: cfpo not below white"
check 'gt "$(field "$sw" mesh_ratio)" "$(field "$sa" mesh_ratio)"' "mesh_ratio: cfpo not below white"
check 'gt "$(field "$sw" utk_gauss_mse)" "$(field "$sa" utk_gauss_mse)"' "utk_gauss_mse: cfpo not below white"
check 'gt "$(field "$sw" utk_heaviside_mse)" "$(field "$sa" utk_heaviside_mse)"' "utk_heaviside_mse: cfpo not below white"
check 'awk "NR > 3 && \$1 < 0.5 && \$2 != 0 { bad = 1 } END { exit bad }" a/pcf.txt' "cfpo: g != 0 below 0.5 Delta"
check 'paste a/pcf.txt b/pcf.txt ab/pcf.txt | awk "NR > 3 { d = \$6 - (\$2 + \$4) / 2; if (d < 0) d = -d; if (d > 1e-9 * (\$6 + 1)) bad = 1 } END { exit bad }"' \
  "pcf.txt of two sets is not the mean"
check '[ $(grep -vc "^#" a/pcf.txt) -eq 300 ]' "pcf.txt has not 300 rows"
"$A" -q -t 1 --pcf-sigma 0.1 --pcf-rmax 2 --integration 0 --no-delaunay -o o a.txt >/dev/null || bad "options failed"
check '[ $(grep -vc "^#" o/pcf.txt) -eq 100 ] && grep -q "\"integration\": null" o/stats.json && grep -q "\"delaunay\": null" o/stats.json' \
  "--pcf-sigma/--pcf-rmax/--integration 0/--no-delaunay not followed"
for o in "--pcf-sigma 0" "--pcf-sigma x" "--pcf-rmax 0.01" "--pcf-rmax 1e9" "--integration -1" "--integration 1.5"; do
  "$A" -q $o -o bad a.txt >/dev/null 2>&1
  check '[ $? -eq 2 ] && [ ! -e bad ]' "$o is not a usage error"
done
"$A" -q --no-discrepancy=1 a.txt >/dev/null 2>&1
check '[ $? -eq 2 ]' "--no-discrepancy=1 is not a usage error"
finish
