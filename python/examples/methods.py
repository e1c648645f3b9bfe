"""Samples 2,048 points with three methods (CFPO, FPO, dart throwing) and
draws each set and its power spectrum with matplotlib.

    pip install matplotlib
    python python/examples/methods.py [out.png]
"""
import sys

import numpy as np

import cfpo


def main(out="methods.png"):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    n = 2048
    sets = {
        "CFPO (adaptive)": cfpo.sample(n, seed=1),
        "FPO": cfpo.baselines.fpo(n, seed=1).points,
        "dart throwing": cfpo.baselines.dart(n, seed=1),
    }
    fig, axes = plt.subplots(2, len(sets), figsize=(4 * len(sets), 8))
    for col, (name, pts) in enumerate(sets.items()):
        d = cfpo.analysis.deltas(pts)
        spec = cfpo.analysis.spectrum(pts)
        ax = axes[0, col]
        ax.scatter(pts[:, 0], pts[:, 1], s=1, c="k")
        ax.set_aspect("equal")
        ax.set_xlim(0, 1)
        ax.set_ylim(0, 1)
        ax.set_title(f"{name}\ndelta_min {d.delta_min:.3f}  delta_avg {d.delta_avg:.3f}")
        ax = axes[1, col]
        K = spec.K
        ax.imshow(np.clip(spec.power, 0, 4), cmap="gray", origin="lower", extent=(-K, K, -K, K))
        ax.set_title(f"power spectrum (effective Nyquist {spec.effective_nyquist:.2f})")
    fig.tight_layout()
    fig.savefig(out, dpi=100)
    print(f"wrote {out}")


if __name__ == "__main__":
    main(*sys.argv[1:])
