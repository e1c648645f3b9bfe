# bench-average.awk - averages power spectra written by cfpo-analyze
# (spectrum.txt, gnuplot nonuniform matrix, all with the same K) and derives
# from the average what cfpo-analyze derives from its own: RAPS, anisotropy,
# effective Nyquist frequency, oscillation and spike ratio, with
# analysis/README.md's definitions (rings i(i-1) < |k|^2 <= i(i+1); unbiased
# ring variance; C(r) at every |k|^2 <= K^2; oscillation over rings nu_osc ..
# nu_osc + 5 sqrt(n); spike: the largest P / ring mean over the half plane
# ky > 0 or (ky = 0, kx > 0), rings of >= 16 frequencies, first in (ky, kx)
# order on ties).
#
# Why it exists: cfpo-analyze averages only sets of equal n, and the maximal
# Poisson-disk samplers (BS, Bridson) give a slightly different n per seed.
# bench.sh also runs it on cfpo-analyze's own averages and compares the
# numbers, so this code is checked on every run.
#
# mawk -v out=DIR -v n=N -v crop=C [-v croponly=1] -f bench-average.awk SPECTRUM...
#   croponly=1: one file, only DIR/spectrum.txt is written (cropped).
#   N: the n for r / sqrt(n) (the mean n of the sets); C: half-width of the
#   cropped spectrum written for the figures (|kx|, |ky| <= C).
# Writes DIR/spectrum.txt (average, cropped), DIR/raps.txt (r, r/sqrt(n),
# raps, anisotropy_db, count) and prints one line of key=value on stdout.
function ring(q,   i) {
  i = int(sqrt(q) + 0.5)
  while (i * (i + 1) < q) i++
  while (i > 0 && i * (i - 1) >= q) i--
  return i
}
# the cropped average for the figures (5 significant digits)
function write_crop(   c, f, kx, ky) {
  c = (crop > K || crop <= 0) ? K : crop
  f = out "/spectrum.txt"
  printf "%d", 2 * c + 1 > f
  for (kx = -c; kx <= c; kx++) printf " %d", kx > f
  printf "\n" > f
  for (ky = -c; ky <= c; ky++) {
    printf "%d", ky > f
    for (kx = -c; kx <= c; kx++) printf " %.5g", P[ky, kx] > f
    printf "\n" > f
  }
  close(f)
}
FNR == 1 {
  files++
  if (files == 1) { K = ($2 < 0 ? -$2 : $2); W = 2 * K + 1 }
  else if ($1 != W) { print "bench-average: " FILENAME ": K differs from the first file" > "/dev/stderr"; exit 1 }
  next
}
croponly && ($1 > crop || $1 < -crop) { next }
{
  ky = $1
  for (j = 2; j <= NF; j++) P[ky, j - 2 - K] += $j
}
END {
  if (files == 0 || K == 0) { print "bench-average: no spectrum read" > "/dev/stderr"; exit 1 }
  if (croponly) { for (k in P) P[k] /= files; write_crop(); exit 0 }
  for (ky = -K; ky <= K; ky++) for (kx = -K; kx <= K; kx++) P[ky, kx] /= files
  # rings: sums, then squared deviations (two passes, as rings.c)
  R2 = K * K
  for (ky = -K; ky <= K; ky++) for (kx = -K; kx <= K; kx++) {
    q = kx * kx + ky * ky
    if (q == 0) continue
    i = ring(q)
    if (i <= K) { cnt[i]++; sum[i] += P[ky, kx] }
    if (q <= R2) { csum[q] += P[ky, kx]; ccnt[q]++ }
  }
  for (i = 1; i <= K; i++) mean[i] = cnt[i] ? sum[i] / cnt[i] : 0
  for (ky = -K; ky <= K; ky++) for (kx = -K; kx <= K; kx++) {
    q = kx * kx + ky * ky
    if (q == 0) continue
    i = ring(q)
    if (i <= K) { d = P[ky, kx] - mean[i]; dev[i] += d * d }
  }
  sn = sqrt(n)
  f = out "/raps.txt"
  printf "# radially averaged power spectrum and anisotropy of the average of %d spectra (bench-average.awk); n=%s K=%d\n", files, n, K > f
  printf "# r\tr/sqrt(n)\traps\tanisotropy_db\tcount\n" > f
  peak = 1
  for (i = 1; i <= K; i++) {
    if (cnt[i] >= 2 && mean[i] > 0) a = sprintf("%.9g", 10 * log(dev[i] / (cnt[i] - 1) / (mean[i] * mean[i])) / log(10))
    else a = "NaN"
    printf "%d\t%.9g\t%.9g\t%s\t%d\n", i, i / sn, mean[i], a, cnt[i] > f
    if (mean[i] > mean[peak]) peak = i
  }
  close(f)
  # effective Nyquist (hsd.c)
  acc = 0; num = 0; last01 = -1; half = -1
  for (q = 1; q <= R2; q++) {
    if (!ccnt[q]) continue
    acc += csum[q]; num += ccnt[q]; C = acc / num
    if (C < 0.1) last01 = q
    if (q >= n / 4 && C > 0.5) { half = q; break }
  }
  eff = (half < 0) ? "-" : sprintf("%.6f", (last01 < 0 ? 0 : sqrt(last01)) / sn)
  # oscillation (hsd.c)
  from = 0
  for (i = 1; i <= K && !from; i++) if (mean[i] >= 0.98) from = i
  if (!from) osc = "-"
  else {
    lim = from + 5 * sn; to = (lim >= K) ? K : int(lim)
    acc = 0; w = 0
    for (i = from; i <= to; i++) { d = mean[i] - 1; acc += cnt[i] * d * d; w += cnt[i] }
    osc = sprintf("%.6f", 10 * sqrt(acc / w))
  }
  # spike ratio (rings.c)
  best = -1; spike = "-"; sk = "-"
  for (ky = 0; ky <= K; ky++) for (kx = -K; kx <= K; kx++) {
    if (!(ky > 0 || kx > 0)) continue
    i = ring(kx * kx + ky * ky)
    if (i > K || cnt[i] < 16 || !(mean[i] > 0)) continue
    q = P[ky, kx] / mean[i]
    if (q > best) { best = q; spike = sprintf("%.6g", q); sk = kx "," ky }
  }
  write_crop()
  printf "sets=%d K=%d raps_peak=%.6f raps_peak_r=%.6f eff_nyquist=%s oscillation=%s spike_ratio=%s spike_k=%s\n", files, K, mean[peak], peak / sn, eff, osc, spike, sk
}
