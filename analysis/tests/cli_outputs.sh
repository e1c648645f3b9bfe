#!/bin/sh
# cli_outputs.sh - cfpo-analyze end to end on a CFPO set: the default
# folder name and K, the shapes of every output file, the SUMMARY line,
# the spike ratio recomputed from spectrum.txt and raps.txt,
# --check (NUFFT against exact summation, within 1e-6), --exact giving the
# same RAPS, replacing an earlier output folder but never a foreign one,
# and plot.gp running under gnuplot when gnuplot is installed.
. "$(dirname "$0")/common.sh"
cd "$T" || exit 1

"$B/cfpo" -n 1024 --seed 2 -t 1 -q -o set.npy >/dev/null || bad "cfpo failed"
out=$("$A" set.npy -q)
check '[ $? -eq 0 ]' "cfpo-analyze failed"
check '[ -d set.analysis ]' "default folder set.analysis missing"
for f in spectrum.txt raps.txt nn_hist.txt stats.json plot.gp; do
  check "[ -s set.analysis/$f ]" "$f missing"
done
check 'echo "$out" | grep -q "^SUMMARY method=analyze sets=1 n=1024 K=192 spectrum=nufft "' "summary: $out"
check '[ "$(echo "$out" | wc -l)" -eq 1 ]' "more than one line on stdout"
# spectrum.txt: nonuniform matrix, 2K+2 rows of 2K+2 fields, P(0) = n
check "awk 'NR == 1 && \$1 != 385 { exit 1 } NF != 386 { exit 1 } END { exit NR != 386 }' set.analysis/spectrum.txt" \
  "spectrum.txt is not a 385 x 385 nonuniform matrix"
check "awk '\$1 == 0 && NR > 1 { if (\$(2 + 192) != 1024) exit 1 }' set.analysis/spectrum.txt" "P(0) != n"
# raps.txt: K rows, r/sqrt(n) = r/32, blue noise: RAPS << 1 at low r, peak above 1
check "awk '!/^#/ { c++; if (NF != 5 || \$2 != \$1 / 32) exit 1 } END { exit c != 192 }' set.analysis/raps.txt" \
  "raps.txt rows or columns wrong"
check "awk '!/^#/ && \$1 <= 10 && \$3 > 0.1 { exit 1 }' set.analysis/raps.txt" "low-frequency RAPS not blue"
check 'le 2 "$(field "$out" raps_peak)"' "RAPS peak below 2"
# nn_hist.txt: 200 bins counting every point once
check "awk '!/^#/ { c++; s += \$3 } END { exit !(c == 200 && s == 1024) }' set.analysis/nn_hist.txt" "nn_hist.txt"
if command -v jq >/dev/null 2>&1; then
  check "jq -e '.n == 1024 and .K == 192 and .sets == 1 and .spectrum.method == \"nufft\" and (.delta_min > 0.9)' set.analysis/stats.json >/dev/null" \
    "stats.json content"
else
  check 'grep -q "\"n\": 1024" set.analysis/stats.json' "stats.json content"
fi
# spike ratio: the summary's value and k are the largest P(k) / ring mean
# over rings of >= 16 frequencies as spectrum.txt and raps.txt give them
sr=$(field "$out" spike_ratio); sk=$(field "$out" spike_k)
check 'le 3 "$sr" && le "$sr" 40' "spike_ratio $sr of a CFPO set outside [3, 40]"
check '[ "$(field "$out" spike_ratio_set_mean)" = "$sr" ]' "one set: spike_ratio_set_mean differs from spike_ratio"
want=$(awk 'FNR == 1 { f++ } f == 1 && !/^#/ { m[$1] = $3; c[$1] = $5; next }
  f == 2 && FNR == 1 { for (i = 2; i <= NF; i++) kx[i] = $i; next }
  f == 2 { ky = $1; for (i = 2; i <= NF; i++) { x = kx[i]; if (!(ky > 0 || (ky == 0 && x > 0))) continue
      q = x * x + ky * ky; r = int(sqrt(q) + 0.5); if (!(r in m) || c[r] < 16) continue
      v = $i / m[r]; if (v > best) { best = v; bk = x "," ky } } }
  END { printf "%s %s", best, bk }' set.analysis/raps.txt set.analysis/spectrum.txt)
check 'awk -v a="$sr" -v b="${want%% *}" "BEGIN { d = a - b; exit !(d < 1e-5 * b && d > -1e-5 * b) }" && [ "$sk" = "${want#* }" ]' \
  "summary spike_ratio=$sr spike_k=$sk, from the files: $want"
if command -v jq >/dev/null 2>&1; then
  check "jq -e '(.spike_per_set | length) == 1 and .spike.min_ring_count == 16 and (.spike_per_set[0].ratio - .spike.ratio | fabs) < 1e-9' set.analysis/stats.json >/dev/null" \
    "stats.json spike fields"
fi
# --check: NUFFT against exact summation
out=$("$A" set.npy -q -K 96 --check -o chk)
d=$(field "$out" check_maxdiff)
check 'le "$d" 1e-6' "check_maxdiff $d above 1e-6"
# --exact gives the same RAPS
"$A" set.npy -q -K 96 --exact -o ex >/dev/null
check "paste chk/raps.txt ex/raps.txt | awk '!/^#/ { d = \$3 - \$8; if (d < 0) d = -d; if (d > 1e-6 * (\$8 > 1 ? \$8 : 1)) exit 1 }'" \
  "--exact RAPS differs from the NUFFT RAPS"
# an earlier output folder is replaced, with no leftovers
out=$("$A" set.npy -q -K 32)
check '[ $? -eq 0 ] && [ "$(field "$out" K)" = 32 ]' "rerun into an existing output folder failed"
check '[ -z "$(ls -d set.analysis.* 2>/dev/null)" ]' "temporary folders left behind"
# a full disk (here a file size limit, SIGXFSZ ignored so the write fails
# with EFBIG): one line naming the output folder, not its temporary, exit 1,
# nothing left behind
(trap '' XFSZ; ulimit -f 1; exec "$A" set.npy -q -o full.analysis) >/dev/null 2>err.txt
rc=$?
check '[ $rc -eq 1 ] && [ "$(wc -l <err.txt)" -eq 1 ]' "disk full: exit $rc, $(cat err.txt)"
check 'grep -q "full.analysis/" err.txt && ! grep -q "\.tmp\." err.txt' "disk-full message names the temporary: $(cat err.txt)"
check '[ -z "$(ls -d full.analysis* 2>/dev/null)" ]' "disk full left $(ls -d full.analysis* 2>/dev/null)"
# the lattice ratio: cfpo's grid for n = 1024 (g = 27, period 3: the axis
# frequencies 9, 18, ..., 54), a value of P over its ring's mean that
# spectrum.txt and raps.txt give back; --grid 0 turns it off
lr=$(field "$out" lattice_ratio); lk=$(field "$out" lattice_k)
check 'echo "$lk" | grep -Eq "^(0,(9|18|27|36|45|54)|(9|18|27|36|45|54),0)$"' "lattice_k $lk not an axis frequency of g = 27"
lw=$(awk -v k="$lk" 'BEGIN { split(k, a, ","); kx = a[1]; ky = a[2]; f = kx + ky }
  FNR == 1 { fi++ } fi == 1 && !/^#/ && $1 == f { m = $3; next }
  fi == 2 && FNR == 1 { for (i = 2; i <= NF; i++) if ($i == kx) col = i; next }
  fi == 2 && $1 == ky { p = $col } END { printf "%.4g", p / m }' set.analysis/raps.txt set.analysis/spectrum.txt)
check "awk -v a=$lr -v b=$lw 'BEGIN { d = a - b; if (d < 0) d = -d; exit d > 1e-3 * b }'" "lattice_ratio $lr, recomputed $lw"
out0=$("$A" set.npy -q --grid 0 -o g0)
check 'echo "$out0" | grep -q " lattice_ratio=- lattice_k=- "' "--grid 0: $out0"
# a foreign folder is never replaced
mkdir mine && touch mine/notes
"$A" set.npy -q -o mine >/dev/null 2>err.txt
check '[ $? -eq 1 ] && [ -f mine/notes ] && [ "$(wc -l <err.txt)" -eq 1 ]' "a foreign folder was touched"
if command -v gnuplot >/dev/null 2>&1; then
  (cd set.analysis && gnuplot plot.gp >/dev/null 2>&1)
  check '[ -s set.analysis/spectrum.png ] && [ -s set.analysis/raps.png ]' "gnuplot plot.gp failed"
  "$A" set.npy -q >/dev/null
  check '[ $? -eq 0 ] && [ ! -e set.analysis/spectrum.png ]' "folder with pictures not replaced"
fi
finish
