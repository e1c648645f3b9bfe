"""square-hierarchy.py - a nested square lattice in prefix order, for
`cfpo-analyze --prefixes` (docs/tried.md, "Progressive sets: the square
lattice's doubling").

Level 0 is the 8 x 8 grid; each level adds the centres of the squares of
the lattice so far, so the union is the lattice turned by 45 degrees with
its spacing divided by sqrt(2), and every dyadic prefix from 64 points on
is a square lattice. Optionally the whole set is moved by a smooth field
(rms A torus units, every Fourier mode with |kx|, |ky| <= K but (0, 0),
Gaussian amplitudes) to break the lattice's peaks.

    python3 scripts/square-hierarchy.py N OUT.npy [A K SEED]
"""
import sys

import numpy as np


def grid(s, ox, oy):
    k = round(1 / s)
    i = np.arange(k)
    x, y = np.meshgrid(ox + i * s, oy + i * s, indexing="ij")
    return np.column_stack([x.ravel(), y.ravel()])


def nested(n):
    s = 1.0 / 8
    o = 0.5 * s
    levels = [grid(s, o, o)]
    m, turned = 64, False
    while m < n:
        if not turned:
            levels.append(grid(s, o + s / 2, o + s / 2))
        else:
            levels.append(np.vstack([grid(s, o + s / 2, o), grid(s, o, o + s / 2)]))
            s /= 2
        turned = not turned
        m *= 2
    return np.vstack(levels)[:n]


def warped(x, amp, kmax, seed):
    rng = np.random.default_rng(seed)
    u = np.zeros_like(x)
    for kx in range(-kmax, kmax + 1):
        for ky in range(-kmax, kmax + 1):
            if kx == 0 and ky == 0:
                continue
            for d in range(2):
                a, ph = rng.normal(), rng.uniform(0, 2 * np.pi)
                u[:, d] += a * np.cos(2 * np.pi * (kx * x[:, 0] + ky * x[:, 1]) + ph)
    return x + u * (amp / np.sqrt(np.mean(u**2)))


def main(argv):
    if len(argv) not in (3, 6):
        sys.exit("usage: square-hierarchy.py N OUT.npy [A K SEED]")
    n = int(argv[1])
    if n < 64 or n & (n - 1):
        sys.exit("square-hierarchy.py: N must be a power of two of at least 64")
    x = nested(n)
    if len(argv) == 6:
        x = warped(x, float(argv[3]), int(argv[4]), int(argv[5]))
    np.save(argv[2], np.mod(x, 1.0))


if __name__ == "__main__":
    main(sys.argv)
