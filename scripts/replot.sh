#!/usr/bin/env bash
# replot.sh [RESULTS_DIR] - `make replot`: redraws the figures and summary.md
# of a results folder written by scripts/bench.sh from what it holds
# (runs.csv, spectra.csv, data/), running nothing else. Default: the newest
# folder under results/ that has a runs.csv.
#
# Writes RESULTS_DIR/plotdata/ (the tables the figures draw, derived from
# runs.csv, quality.csv and data/traces), fig-evolution.png,
# fig-comparison.png, fig-convergence.png, fig-runtime.png, fig-speedup.png,
# fig-time-to-quality.png when the folder has time-to-quality runs
# (scripts/fig-*.gp, scripts/bench-ttq.awk) and summary.md
# (scripts/bench-summary.awk). Each file is written under a temporary name
# and renamed, so a failure leaves the earlier version.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
# shellcheck source=methods.sh
. "$here/methods.sh"
die() { echo "replot: $*" >&2; exit 1; }
R=${1:-}
if [ -z "$R" ]; then
  R=$(ls -1d results/*/ 2>/dev/null | sed 's:/$::' | while read -r d; do if [ -f "$d/runs.csv" ]; then echo "$d"; fi; done | sort | tail -n 1)
  [ -n "$R" ] || die "no results folder with a runs.csv under results/ (run make bench first)"
fi
[ -d "$R" ] || die "$R: no such folder"
for f in runs.csv spectra.csv; do [ -f "$R/$f" ] || die "$R/$f missing (not a folder written by scripts/bench.sh)"; done
command -v gnuplot >/dev/null 2>&1 || die "gnuplot not found (run scripts/install-deps.sh)"
R=$(cd "$R" && pwd)
P="$R/plotdata"
mkdir -p "$P"

# header values from runs.csv
hdr() { sed -n "s/^# .*$1: \([^;]*\).*/\1/p" "$R/runs.csv" | head -n 1; }
HOST=$(hdr host)
CORES=$(hdr cores)
plan=$(sed -n 's/^# plan: //p' "$R/runs.csv")
planv() { sed -n "s/.*$1=\([^ ;]*\).*/\1/p" <<<"$plan"; }
SETS=$(planv SETS); N=$(planv COMP_N)
[ -n "$SETS" ] && [ -n "$N" ] || die "$R/runs.csv: no '# plan:' header line"

# method key -> label, colour, point type (the same in every figure), from
# the one list of methods (scripts/methods.tsv)
MKEYS=$(methods_keys pd iter cfpo)
CFPO_KEYS=$(methods_keys cfpo)
mget() { local v; v=$(method_get "$1" "$2"); echo "${v:-$3}"; }
label() { mget "$1" label "$1"; }
colour() { mget "$1" colour "#000000"; }
ptype() { mget "$1" pt 8; }
kind() { mget "$1" kind ""; }

plural() { if [ "$1" -gt 1 ]; then echo s; fi; }
ranks_note() { if [ "$1" -gt 1 ]; then echo ", $1 ranks"; fi; }
# rows of runs.csv as "key,..." (key: method, or the variant for cfpo)
rows() { awk -F, '/^#/ || $1 == "run" { next } { print }' "$R/runs.csv"; }
# cfpo's paper variant (named cfpo before the adaptive variant existed) is
# the key cfpo; its other variants are keys of their own
KEYCOL='function key(m, v) { return (m != "cfpo") ? m : (v == "paper" || v == "cfpo") ? "cfpo" : v }'
MEDIAN='function median(s,   a, k, i, j, t) { k = split(s, a, " "); for (i = 2; i <= k; i++) { t = a[i] + 0; for (j = i - 1; j >= 1 && a[j] + 0 > t; j--) a[j + 1] = a[j]; a[j + 1] = t } return (k % 2) ? a[(k + 1) / 2] : (a[k / 2] + a[k / 2 + 1]) / 2 }'

# ---- evolution and comparison: the groups of spectra.csv ---------------------
trap 'rm -f "$P"/*.tmp.* "$R"/.*.tmp.*' EXIT
cols_vars() { # name groups... -> vars file
  local fig=$1 f="$P/fig-$1.vars.gp" nc=0 g it lbl iters
  shift
  {
    echo "# written by scripts/replot.sh"
    echo "DIR = '$R'; GPDIR = '$here'; N = $N; SETS = $SETS; ZOOM = 0.5; CBMAX = 4"
    echo "SPAN = $(awk -v n="$N" 'BEGIN { printf "%d", 2 * sqrt(n) + 0.5 }')"
    echo "NC = $#; array GRP[$#]; array LBL[$#]"
    for g in "$@"; do
      nc=$((nc + 1))
      case $g in
        evolution-it*) it=${g#evolution-it}; lbl="iteration $it"; [ "$it" = 0 ] && lbl="iteration 0 (start)" ;;
        comparison-cfpo) iters=$(rows | awk -F, "$KEYCOL"' $2 == "comparison" && key($3, $4) == "cfpo" { s += $11; k++ } END { if (k) printf "%d", s / k + 0.5 }')
          lbl="CFPO"; [ "$fig" = evolution ] && lbl="converged (mean ${iters} it.)" ;;
        comparison-*) lbl=$(label "${g#comparison-}") ;;
      esac
      [ -f "$R/data/analysis/$g/spectrum.txt" ] || die "$R/data/analysis/$g/spectrum.txt missing"
      echo "GRP[$nc] = '$g'; LBL[$nc] = '$lbl'"
    done
  } >"$f"
}
evo=()
while read -r g; do evo+=("$g"); done < <(awk -F, '$2 == "evolution" { print $1 }' "$R/spectra.csv")
cols_vars evolution "${evo[@]}" comparison-cfpo
comp=()
for k in $MKEYS; do grep -q "^comparison-$k," "$R/spectra.csv" && comp+=("comparison-$k"); done
cols_vars comparison "${comp[@]}"

# ---- convergence: mean and range over the comparison's traces ---------------
conv_keys=""
for k in $(methods_keys iter cfpo); do
  traces=$(rows | awk -F, -v k="$k" "$KEYCOL"' $2 == "comparison" && key($3, $4) == k && $19 != "-" { print $19 }')
  [ -n "$traces" ] || continue
  conv_keys="$conv_keys $k"
  # shellcheck disable=SC2086
  (cd "$R" && awk -F'\t' '
    FNR == 1 { f++; next }
    { it = $1 + 0; dmin[f, it] = $2; davg[f, it] = $3; if (it > last[f]) last[f] = it; if (it > M) M = it }
    END {
      print "# iteration\tdmin_mean\tdmin_lo\tdmin_hi\tdavg_mean\tdavg_lo\tdavg_hi\tsets_running"
      for (it = 0; it <= M; it++) {
        sa = sb = 0; la = lb = 1e9; ha = hb = -1e9; run = 0
        for (i = 1; i <= f; i++) {
          j = (it <= last[i]) ? it : last[i]; if (it < last[i]) run++
          a = dmin[i, j]; b = davg[i, j]; sa += a; sb += b
          if (a < la) la = a; if (a > ha) ha = a; if (b < lb) lb = b; if (b > hb) hb = b
        }
        printf "%d\t%.6f\t%.6f\t%.6f\t%.6f\t%.6f\t%.6f\t%d\n", it, sa / f, la, ha, sb / f, lb, hb, run
      }
    }' $traces) >"$P/convergence-$k.dat.tmp.$$"
  mv "$P/convergence-$k.dat.tmp.$$" "$P/convergence-$k.dat"
done
{
  echo "# written by scripts/replot.sh"
  echo "DIR = '$R'; N = $N; SETS = $SETS"
  set -- $conv_keys
  echo "NM = $#; array KEY[$#]; array LBL[$#]; array COL[$#]"
  i=0; for k in $conv_keys; do i=$((i + 1)); echo "KEY[$i] = '$k'; LBL[$i] = '$(label "$k")'; COL[$i] = '$(colour "$k")'"; done
} >"$P/fig-convergence.vars.gp"

# ---- runtime: medians per (method, threads, ranks, n) -------------------------
# every uncapped run of the comparison and runtime experiments
rows | awk -F, "$KEYCOL $MEDIAN"'
  ($2 == "comparison" || $2 == "runtime") && $10 == "-" {
    g = key($3, $4) SUBSEP $8 SUBSEP $9 SUBSEP $6
    s[g] = s[g] " " $12; if ($13 != "-") p[g] = p[g] " " $13; if ($11 != "-") it[g] = it[g] " " $11
    c[g]++; ids[g] = ids[g] " " $1
  }
  END { for (g in c) { split(g, a, SUBSEP)
    printf "%s\t%s\t%s\t%s\t%.6g\t%s\t%d\t%s\t%s\n", a[1], a[2], a[3], a[4], median(s[g]),
      (p[g] == "" ? "-" : sprintf("%.6g", median(p[g]))), c[g], (it[g] == "" ? "-" : sprintf("%g", median(it[g]))), ids[g] } }' \
  | sort -t$'\t' -k1,1 -k2,2n -k3,3n -k4,4n >"$P/runtime.tsv.tmp.$$"
mv "$P/runtime.tsv.tmp.$$" "$P/runtime.tsv"
# blocks for gnuplot, methods in the figure order
{
  echo "# one block per method/threads/ranks: n_target median_seconds median_s_per_iter runs median_iterations"
  nb=0
  for k in $MKEYS; do
    for tr in $(awk -F'\t' -v k="$k" '$1 == k { print $2 "/" $3 }' "$P/runtime.tsv" | sort -t/ -k2,2n -k1,1n -u); do
      [ $nb -gt 0 ] && printf '\n\n'
      nb=$((nb + 1))
      awk -F'\t' -v k="$k" -v tr="$tr" '$1 == k && $2 "/" $3 == tr { printf "%s\t%s\t%s\t%s\t%s\n", $4, $5, ($6 == "-" ? -1 : $6), $7, $8 }' "$P/runtime.tsv"
    done
  done
} >"$P/runtime.dat.tmp.$$"
mv "$P/runtime.dat.tmp.$$" "$P/runtime.dat"
{
  echo "# written by scripts/replot.sh"
  echo "DIR = '$R'; HOST = '${HOST:-?}, ${CORES:-?} cores'"
  blocks=$(for k in $MKEYS; do awk -F'\t' -v k="$k" '$1 == k { print $1 "/" $2 "/" $3 }' "$P/runtime.tsv" | sort -t/ -k3,3n -k2,2n -u; done)
  nb=$(echo "$blocks" | grep -c . || true)
  echo "NB = $nb; array LBL[$nb]; array COL[$nb]; array PT[$nb]; array DT[$nb]; array ITER[$nb]"
  i=0
  for b in $blocks; do
    i=$((i + 1)); IFS=/ read -r k t r <<<"$b"
    l=$(label "$k"); [ "$(kind "$k")" = cfpo ] && l="$l, $t thread$(plural "$t")"
    l="$l$(ranks_note "$r")"
    it=1; [ "$(kind "$k")" = pd ] && it=0
    echo "LBL[$i] = '$l'; COL[$i] = '$(colour "$k")'; PT[$i] = $(ptype "$k"); DT[$i] = $(( (t > 1 || r > 1) ? 2 : 1 )); ITER[$i] = $it"
  done
} >"$P/fig-runtime.vars.gp"

# ---- speedup: time on 1 thread, 1 rank / time on (threads, ranks) ------------
# same method, n and seeds: the ratio of the medians over the seeds that ran
# both configurations (uncapped comparison and runtime runs)
rows | awk -F, -v ck=" $CFPO_KEYS " "$KEYCOL $MEDIAN"'
  ($2 == "comparison" || $2 == "runtime") && $10 == "-" && index(ck, " " key($3, $4) " ") {
    k = key($3, $4); T[k, $6, $8, $9, $7] = $12; id[k, $6, $8, $9, $7] = $1; conf[k SUBSEP $6 SUBSEP $8 SUBSEP $9] = 1
  }
  END {
    for (c in conf) { split(c, a, SUBSEP); k = a[1]; n = a[2]; t = a[3]; r = a[4]
      sb = ""; sc = ""; ib = ""; ic = ""
      for (g in T) { split(g, b, SUBSEP); if (b[1] != k || b[2] != n || b[3] != t || b[4] != r) continue
        s = b[5]; if (!((k, n, 1, 1, s) in T)) continue
        sb = sb " " T[k, n, 1, 1, s]; sc = sc " " T[g]; ib = ib " " id[k, n, 1, 1, s]; ic = ic " " id[g] }
      if (sc == "") continue
      printf "%s\t%s\t%s\t%s\t%d\t%.4f\t%s |%s\n", k, n, t, r, t * r, median(sb) / median(sc), ib, ic } }' \
  | sort -t$'\t' -k1,1 -k2,2n -k5,5n -k4,4n >"$P/speedup.tsv.tmp.$$"
mv "$P/speedup.tsv.tmp.$$" "$P/speedup.tsv"
{
  echo "# speedup against cores used: one block per method/n/ranks: cores speedup threads ranks"
  first=1
  for b in $(awk -F'\t' '{ print $1 "/" $2 "/" $4 }' "$P/speedup.tsv" | sort -t/ -k1,1r -k2,2n -k3,3n -u); do
    IFS=/ read -r k n r <<<"$b"
    [ $first -eq 0 ] && printf '\n\n'; first=0
    awk -F'\t' -v k="$k" -v n="$n" -v r="$r" '$1 == k && $2 == n && ($4 == r || ($4 == 1 && $3 == 1)) { printf "%s\t%s\t%s\t%s\n", $5, $6, $3, $4 }' "$P/speedup.tsv" | sort -n
  done
} >"$P/speedup-cores.dat.tmp.$$"
mv "$P/speedup-cores.dat.tmp.$$" "$P/speedup-cores.dat"
{
  echo "# speedup against n: one block per method/threads/ranks (threads x ranks > 1): n speedup"
  first=1
  for b in $(awk -F'\t' '$5 > 1 { print $1 "/" $3 "/" $4 }' "$P/speedup.tsv" | sort -t/ -k1,1r -k3,3n -k2,2n -u); do
    IFS=/ read -r k t r <<<"$b"
    [ $first -eq 0 ] && printf '\n\n'; first=0
    awk -F'\t' -v k="$k" -v t="$t" -v r="$r" '$1 == k && $3 == t && $4 == r { printf "%s\t%s\n", $2, $6 }' "$P/speedup.tsv" | sort -n
  done
} >"$P/speedup-n.dat.tmp.$$"
mv "$P/speedup-n.dat.tmp.$$" "$P/speedup-n.dat"
{
  echo "# written by scripts/replot.sh"
  echo "DIR = '$R'; HOST = '${HOST:-?}, ${CORES:-?} cores'"
  echo "MAXC = $(awk -F'\t' 'BEGIN { m = 2 } $5 > m { m = $5 } END { print m }' "$P/speedup.tsv")"
  ba=$(awk -F'\t' '{ print $1 "/" $2 "/" $4 }' "$P/speedup.tsv" | sort -t/ -k1,1r -k2,2n -k3,3n -u)
  na=$(echo "$ba" | grep -c . || true)
  echo "NA = $na; array LBLA[$na]; array COLA[$na]; array PTA[$na]; array DTA[$na]"
  i=0; nsz=$(echo "$ba" | cut -d/ -f2 | sort -un | wc -l)
  for b in $ba; do
    i=$((i + 1)); IFS=/ read -r k n r <<<"$b"
    j=$(echo "$ba" | cut -d/ -f2 | sort -un | grep -nx "$n" | cut -d: -f1)
    echo "LBLA[$i] = '$(label "$k"), n = $n$(ranks_note "$r")'; COLA[$i] = '$(colour "$k")'; PTA[$i] = $((4 + j)); DTA[$i] = $(( (j - 1) % 5 + 1 ))"
  done
  bb=$(awk -F'\t' '$5 > 1 { print $1 "/" $3 "/" $4 }' "$P/speedup.tsv" | sort -t/ -k1,1r -k3,3n -k2,2n -u)
  nbb=$(echo "$bb" | grep -c . || true)
  echo "NBB = $nbb; array LBLB[$nbb]; array COLB[$nbb]; array PTB[$nbb]; array DTB[$nbb]"
  i=0
  for b in $bb; do
    i=$((i + 1)); IFS=/ read -r k t r <<<"$b"
    echo "LBLB[$i] = '$(label "$k"), $t threads, $r rank$(plural "$r")'; COLB[$i] = '$(colour "$k")'; PTB[$i] = $((5 + i % 4)); DTB[$i] = $(( r > 1 ? 2 : 1 ))"
  done
  : "$nsz"
} >"$P/fig-speedup.vars.gp"

# ---- time to quality: per run, from its trace and quality.csv ------------------
FIGS="evolution comparison convergence runtime speedup"
rm -f "$P"/ttq-*.dat
if rows | awk -F, '$2 == "ttq" { f = 1 } END { exit !f }'; then
  [ -f "$R/quality.csv" ] || die "$R/quality.csv missing (the folder has time-to-quality runs)"
  tmin=$(planv TTQ_TARGET_MIN); tavg=$(planv TTQ_TARGET_AVG)
  [ -n "$tmin" ] && [ -n "$tavg" ] || die "$R/runs.csv: no TTQ_TARGET_MIN/TTQ_TARGET_AVG in the '# plan:' line"
  awk -F, -v dir="$R" -v pdir="$P" -v tmin="$tmin" -v tavg="$tavg" -v methods="$METHODS_TSV" \
    -f "$here/methods.awk" -f "$here/bench-ttq.awk" "$R/runs.csv" "$R/quality.csv" \
    >"$P/ttq-runs.tsv.tmp.$$" || die "reading the time-to-quality traces failed"
  mv "$P/ttq-runs.tsv.tmp.$$" "$P/ttq-runs.tsv"
  FIGS="$FIGS time-to-quality"
else
  tmin=-; tavg=-
  echo "# no time-to-quality runs in this folder" >"$P/ttq-runs.tsv"
  rm -f "$R/fig-time-to-quality.png" "$P/fig-time-to-quality.vars.gp"
fi

# ---- figures -------------------------------------------------------------------
for fig in $FIGS; do
  out="$R/.fig-$fig.png.tmp.$$"
  gnuplot -e "VARS='$P/fig-$fig.vars.gp'; OUT='$out'" "$here/fig-$fig.gp" 2>"$P/gnuplot-$fig.log" \
    || die "gnuplot failed on scripts/fig-$fig.gp: $(grep -m1 -v '^$' "$P/gnuplot-$fig.log")"
  [ -s "$out" ] || die "scripts/fig-$fig.gp wrote no image"
  mv "$out" "$R/fig-$fig.png"
done

# ---- summary.md --------------------------------------------------------------------
awk -F, -v convkeys="$conv_keys" -v tmin="$tmin" -v tavg="$tavg" -v methods="$METHODS_TSV" \
  -f "$here/methods.awk" -f "$here/bench-summary.awk" "$R/runs.csv" "$R/spectra.csv" \
  "$P/runtime.tsv" "$P/speedup.tsv" "$P/ttq-runs.tsv" \
  >"$R/.summary.md.tmp.$$" || die "writing summary.md failed"
mv "$R/.summary.md.tmp.$$" "$R/summary.md"
echo "replot: figures and summary.md in $R" >&2
