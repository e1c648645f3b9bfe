"""progress=True: one line on stderr rewritten in place, with an ETA, in
the style of the command's progress line (src/main.c)."""
import math
import sys
import time


class ProgressLine:
    """A callback for cfpo.run: prints iteration, deltas, moves and an ETA.

    ETA: with quality targets, from the rise of delta_min / delta_avg over
    the last 8 iterations; without, from the geometric decay of the number
    of moves over the last 8 iterations; capped by max_iter and the time
    limit."""

    def __init__(self, n, max_iter, target_min=0.0, target_avg=0.0, time_limit=0.0, stream=None):
        self.n, self.max_iter = n, max_iter
        self.tmin, self.tavg, self.tlim = target_min, target_avg, time_limit
        self.stream = stream or sys.stderr
        self.hist = []
        self.last = 0.0
        self.shown = False

    def _eta(self, s):
        self.hist.append((s["moved"] + 0.5, s["delta_min"], s["delta_avg"]))
        if len(self.hist) < 9:
            return None
        now, old = self.hist[-1], self.hist[-9]
        left_it = self.max_iter - s["iteration"]
        if self.tmin > 0 or self.tavg > 0:
            left = 0.0
            for target, i in ((self.tmin, 1), (self.tavg, 2)):
                if target > 0 and now[i] < target:
                    rise = (now[i] - old[i]) / 8
                    left = max(left, (target - now[i]) / rise if rise > 0 else math.inf)
            left = min(left, left_it)
        else:
            ratio = now[0] / old[0]
            left = left_it
            if ratio < 0.999:
                left = min(left, math.log(now[0]) / -(math.log(ratio) / 8))
        eta = left * s["seconds"]
        if self.tlim > 0:
            eta = min(eta, max(0.0, self.tlim - s["elapsed"]))
        return eta

    def __call__(self, s):
        eta = self._eta(s)
        t = time.monotonic()
        if t - self.last < 0.1 and s["iteration"] > 0:
            return False
        self.last = t
        rate = self.n / s["seconds"] / 1e6 if s["seconds"] > 0 else 0.0
        etas = "?" if eta is None or not math.isfinite(eta) else f"~{eta:.0f}s"
        self.stream.write(f"\riter {s['iteration']}  delta_min {s['delta_min']:.4f}  "
                          f"delta_avg {s['delta_avg']:.4f}  moved {s['moved']}  {rate:.2f} Mpts/s  "
                          f"elapsed {s['elapsed']:.1f}s  ETA {etas}\033[K")
        self.stream.flush()
        self.shown = True
        return False

    def end(self):
        if self.shown:
            self.stream.write("\n")
            self.stream.flush()
