#!/usr/bin/env bash
# test_d3_analyze_cli.sh BUILD - cfpo3d-analyze's 3-D measures on the command
# line: --spectrum and --pcf write their TSV files (K shells, the g(r) bins)
# and add their fields; the NUFFT's P0 equals --exact's; on an FCC lattice
# (a text file written here) --voronoi gives 12 faces and no volume spread,
# --certify passes every point and W6 is -0.013161; bad values are refused
# in one line with exit 2 and no file written.
set -u
B=$1
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT
fail=0
bad() { echo "FAIL: $*"; fail=1; }
AN="$B/cfpo3d-analyze"
"$B/cfpo3d-wse" -n 1500 -s 4 -q -o "$T/w.npy" >/dev/null || bad "wse"
out=$("$AN" --spectrum "$T/s.tsv" --pcf "$T/g.tsv" --kmax 14 "$T/w.npy") || bad "analyze exits non-zero"
echo "$out" | grep -q " p0=.* peak_shell=.* kmax=14 spike=.* spike_noise=.* spike_pass=[a-z]* pcf_peak=" || bad "fields: $out"
[ "$(tail -n +2 "$T/s.tsv" | wc -l)" -eq 14 ] || bad "14 shells"
[ "$(tail -n +2 "$T/g.tsv" | wc -l)" -eq 150 ] || bad "150 g(r) bins"
ex=$("$AN" --spectrum "$T/s2.tsv" --kmax 14 --exact "$T/w.npy")
p0a=$(echo "$out" | sed 's/.* p0=\([^ ]*\).*/\1/'); p0b=$(echo "$ex" | sed 's/.* p0=\([^ ]*\).*/\1/')
awk -v a="$p0a" -v b="$p0b" 'BEGIN { d = a - b; if (d < 0) d = -d; exit !(d < 1e-5 * (b > 1 ? b : 1)) }' || bad "P0 $p0a (NUFFT) vs $p0b (exact)"
# FCC, 4 x 4 x 4 cells, shifted off the box's faces
python3 - "$T/fcc.txt" <<'PY'
import sys
o = [(0, 0, 0), (.5, .5, 0), (.5, 0, .5), (0, .5, .5)]
with open(sys.argv[1], "w") as f:
    for z in range(4):
        for y in range(4):
            for x in range(4):
                for a, b, c in o:
                    f.write("%.17g %.17g %.17g\n" % ((x + a + .25) / 4, (y + b + .25) / 4, (z + c + .25) / 4))
PY
if out=$("$AN" --voronoi --certify "$T/fcc.txt" 2>"$T/e"); then
  echo "$out" | grep -q " w6=-0.01316" || bad "FCC W6: $out"
  echo "$out" | grep -q " vor_faces=12.0000 vor_faces_sd=0.0000 vor_volume_var=[0-9.e-]* " || bad "FCC Voronoi: $out"
  awk -v v="$(echo "$out" | sed 's/.* vor_volume_var=\([^ ]*\).*/\1/')" 'BEGIN { exit !(v < 1e-12) }' || bad "FCC volumes: $out"
  echo "$out" | grep -q " fpd_pass=yes fpd_points=256 " || bad "FCC certificate: $out"
elif grep -q "needs a build with CGAL" "$T/e"; then
  echo "no CGAL: --voronoi and --certify refused"
else
  bad "FCC: $(cat "$T/e")"
fi
for args in "--kmax 0" "--kmax 500" "--spectrum" "--bogus"; do
  "$AN" $args "$T/w.npy" >/dev/null 2>"$T/e"; rc=$?
  [ $rc -eq 2 ] && [ "$(wc -l <"$T/e")" -eq 1 ] || bad "$args: rc $rc, $(cat "$T/e")"
done
"$AN" --spectrum "$T/no/such/dir/s.tsv" "$T/w.npy" >/dev/null 2>"$T/e"; [ $? -eq 1 ] && [ ! -e "$T/no" ] || bad "unwritable spectrum file"
[ $fail -eq 0 ] && echo "all passed"
exit $fail
