#!/usr/bin/env bash
# test_density_cli.sh BUILD_DIR - `cfpo --density` and `cfpo-analyze
# --density` as a user meets them: every bad input of the density issue
# (missing, unreadable, truncated or non-grey image; all-zero, negative,
# NaN or infinite values; contrast beyond the limit; an image too large; n
# too small for the support; a resume under another density or none) gives
# one line, a non-zero exit and no file; a good run gives the same bytes
# for any thread count; --init and --resume work under a density; the
# uniform density measures what cfpo-analyze measures without one.
set -u
HERE=$(cd "$(dirname "$0")" && pwd)
B=$(cd "$1" && pwd)
CFPO="$B/cfpo"
AN="$B/cfpo-analyze"
T=$(mktemp -d /tmp/cfpo-dens-XXXXXX)
trap 'rm -rf "$T"' EXIT
cd "$T" || exit 1
mkdir in
. "$HERE/cli_expect.sh"

printf 'P5 4 4 255\n' >in/g.pgm; head -c 16 /dev/zero >>in/g.pgm            # all black: uniform
printf 'P5 4 4 255\n' >in/w.pgm; head -c 16 /dev/zero | tr '\0' '\377' >>in/w.pgm   # all white: zero
printf 'P5 4 4 255\n' >in/t.pgm; head -c 10 /dev/zero >>in/t.pgm            # truncated
printf 'P6 1 1 255\n\0\0\0' >in/c.pgm                                          # colour PPM
printf '\211PNG\r\n\032\nnot really' >in/t.png                                 # truncated PNG
printf 'P5 60000 60000 255\n' >in/big.pgm                                      # too large
printf 'P2 2 1 65535\n1 65535\n' >in/k.pgm                                     # contrast 1:65534 (light = dense)
npy() { # npy NAME V1 V2 V3 V4: a (2, 2) float64 array, values as printf %s floats
  local name=$1; shift
  { printf '\223NUMPY\001\000\166\000'
    printf "%-117s\n" "{'descr': '<f8', 'fortran_order': False, 'shape': (2, 2), }"
    for v in "$@"; do python3 -c "import struct,sys; sys.stdout.buffer.write(struct.pack('<d', float('$v')))"; done
  } >in/$name.npy
}
npy neg 1 2 -1 3; npy nan 1 nan 1 1; npy inf 1 inf 1 1; npy zero 0 0 0 0; npy ok 1 2 3 4

expect 1 "cannot open" -n 1000 --density in/missing.png -o x.npy
mkdir -p in/folder.png
expect 1 "folder.png: read error" -n 1000 --density in/folder.png -o x.npy
expect 1 "unreadable PNG" -n 1000 --density in/t.png -o x.npy
expect 1 "truncated PGM" -n 1000 --density in/t.pgm -o x.npy
expect 1 "not a PGM" -n 1000 --density in/c.pgm -o x.npy
expect 1 "too large" -n 1000 --density in/big.pgm -o x.npy
expect 1 "zero everywhere" -n 1000 --density in/w.pgm -o x.npy
expect 1 "zero everywhere" -n 1000 --density in/zero.npy -o x.npy
expect 1 "non-negative" -n 1000 --density in/neg.npy -o x.npy
expect 1 "non-negative" -n 1000 --density in/nan.npy -o x.npy
expect 1 "non-negative" -n 1000 --density in/inf.npy -o x.npy
expect 1 "contrast 1:6.554e+04.*limit 1:256" -n 1000 --density in/k.pgm:invert -o x.npy
expect 1 "contrast 1:1000 .*limit 1:256" -n 1000 --density ramp:contrast=1000 -o x.npy
expect 1 "not an image" -n 1000 --density swirl -o x.npy
expect 2 "too small for this density" -n 50 --density ramp:contrast=200 -o x.npy
expect 2 "dry-run" -n 1000 --density cos --dry-run
expect 2 "variant" -n 1000 --density cos --variant paper -o x.npy
expect 2 "tiles and --check do not go with --density" -n 1000 --density cos --tiles 1x1 -o x.npy
expect 2 "tiles and --check do not go with --density" -n 1000 --density cos --check -o x.npy

# same bytes for any thread count; --init; checkpoint and resume
"$CFPO" -q -n 3000 --density cos:a=0.9 --max-iter 8 -t 1 -o a1.npy >/dev/null || bad "1 thread"
"$CFPO" -q -n 3000 --density cos:a=0.9 --max-iter 8 -t 2 -o a2.npy >/dev/null || bad "2 threads"
"$CFPO" -q -n 3000 --density cos:a=0.9 --max-iter 8 -t 3 -o a3.npy >/dev/null || bad "3 threads"
cmp -s a1.npy a2.npy && cmp -s a1.npy a3.npy && ok || bad "thread counts give other bytes"
"$CFPO" -q -n 3000 --density cos:a=0.9 --max-iter 4 --checkpoint ck.bin --checkpoint-every 4 -o h.npy >/dev/null || bad "checkpoint run"
"$CFPO" -q --density cos:a=0.9 --resume ck.bin --max-iter 8 -o r.npy >/dev/null || bad "resume"
cmp -s a1.npy r.npy && ok || bad "4 + 4 iterations through a checkpoint differ from 8"
expect 1 "another density" --density cos:a=0.8 --resume ck.bin -o x.npy
expect 2 "made with a density" --resume ck.bin -o x.npy
"$CFPO" -q -n 1000 --max-iter 2 --checkpoint u.bin -o u.npy >/dev/null || bad "uniform checkpoint"
expect 1 "made without a density" --density cos --resume u.bin -o x.npy
# the density engine's checkpoint format of 0.1.0 is refused in one line
{ printf 'CFPODENS'; head -c 56 /dev/zero; head -c 48000 /dev/zero; } >old.ck
expect 1 "before its one checkpoint format" --density cos:a=0.9 --resume old.ck -o x.npy
# a flat density is the uniform torus: the bytes of the run without --density
"$CFPO" -q -n 3000 -o flat0.npy >/dev/null || bad "uniform run"
"$CFPO" -q -n 3000 --density in/g.pgm -o flat1.npy >/dev/null || bad "flat density run"
"$CFPO" -q -n 3000 --density cos:a=0 -o flat2.npy >/dev/null || bad "cos:a=0 run"
cmp -s flat0.npy flat1.npy && cmp -s flat0.npy flat2.npy && ok || bad "a flat density gives other bytes than no density"
# ... and its checkpoints name the density: a resume without it is refused
"$CFPO" -q -n 3000 --density in/g.pgm --max-iter 3 --checkpoint fl.ck -o fl.npy >/dev/null || bad "flat checkpoint"
expect 2 "made with a density" --resume fl.ck -o x.npy
"$CFPO" -q --density in/g.pgm --resume fl.ck -o fl2.npy >/dev/null && cmp -s fl2.npy flat0.npy && ok ||
  bad "a flat density's resume does not give the uninterrupted bytes"
rm -f flat0.npy flat1.npy flat2.npy fl.ck fl.npy fl2.npy old.ck
"$CFPO" -q --density cos:a=0.9 --init a1.npy --max-iter 3 -o i.npy >/dev/null && ok || bad "--init with a density"
awk 'BEGIN{for(i=0;i<3000;i++) printf "0.5 %.9f\n", 0.5+i*1e-9}' >clump.txt
expect 1 "too clustered" --density cos:a=0.9 --init clump.txt -o x.npy
rm -f u.npy u.bin h.npy ck.bin clump.txt

# several ranks: tests/test_dens_mpi.sh (label mpi)

# the DENSITY line's levels of cells (dens_levels.h): one on a nearly flat
# density, five on the ramp 1:256 and the image at 16,384 points
for c in "cos:a=0.01 1" "ramp:contrast=256 5" "$HERE/../data/astronaut-256.png 5"; do
  set -- $c
  l=$("$CFPO" -q -n 16384 -t 1 --max-iter 0 --density "$1" -o lv.npy | sed -n 's/^DENSITY .* levels=\([0-9]*\) .*/\1/p')
  [ "$l" = "$2" ] && ok || bad "$(basename "$1"): DENSITY levels='$l', not $2"
done
rm -f lv.npy

# uniform density: the measures equal today's
"$CFPO" -q -n 2000 --max-iter 5 -o uni.npy >/dev/null
s=$("$AN" -q -o an1 uni.npy | sed -n 's/.* delta_min=\([^ ]*\) delta_avg=\([^ ]*\) .*/\1 \2/p')
d=$("$AN" -q -o an2 --density in/g.pgm uni.npy | sed -n 's/^DENSITY .*density_delta_min=\([^ ]*\) density_delta_avg=\([^ ]*\) .*/\1 \2/p')
[ -n "$s" ] && [ "$s" = "$d" ] && ok || bad "uniform density measures '$d', cfpo-analyze '$s'"
[ -s an2/density.txt ] && ok || bad "no density.txt"
if "$AN" -q -o an3 --density in/w.pgm uni.npy >/dev/null 2>err.log; then bad "analyze: zero density accepted"
elif [ -e an3 ] || [ "$(wc -l <err.log)" -ne 1 ]; then bad "analyze: zero density: $(cat err.log)"; else ok; fi

echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]
