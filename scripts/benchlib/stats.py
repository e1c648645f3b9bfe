"""stats - the arithmetic and number formats the tables share: medians
(\"never\" counting as infinite), means, sample standard deviations, run
id ranges, and awk-compatible number printing (results folders written by
the earlier shell driver replot to the same bytes)."""
import math

NEVER = "never"


def num(s):
    """A field as awk reads it in a numeric context: its leading number, else 0."""
    if isinstance(s, (int, float)):
        return float(s)
    try:
        return float(s)
    except (TypeError, ValueError):
        import re
        m = re.match(r"\s*[-+]?(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?", s or "")
        return float(m.group(0)) if m else 0.0


def median(values):
    """Median of numbers; values may be strings (read as numbers)."""
    a = sorted(num(v) for v in values)
    k = len(a)
    if not k:
        return None
    return a[(k - 1) // 2] if k % 2 else (a[k // 2 - 1] + a[k // 2]) / 2


def median_never(values):
    """Median where \"never\" is infinite: \"never\" when the median is; \"-\" for none."""
    if not values:
        return "-"
    a = [1e300 if v == NEVER else num(v) for v in values]
    m = median(a)
    return NEVER if m >= 1e299 else m


def mean(values):
    a = [num(v) for v in values]
    return sum(a) / len(a) if a else 0.0


def sd(values):
    a = [num(v) for v in values]
    if len(a) < 2:
        return 0.0
    m = mean(a)
    return math.sqrt(sum((x - m) ** 2 for x in a) / (len(a) - 1))


def ranges(ids, sep=", "):
    """[3, 4, 5, 9] -> \"3-5, 9\" (sorted numerically)."""
    a = sorted(int(num(i)) for i in ids)
    out = []
    i = 0
    while i < len(a):
        j = i
        while j + 1 < len(a) and a[j + 1] == a[j] + 1:
            j += 1
        out.append(str(a[i]) if j == i else f"{a[i]}-{a[j]}")
        i = j + 1
    return sep.join(out)


def g6(x):
    """A number as awk prints it with %s or print (CONVFMT %.6g; integers whole)."""
    if isinstance(x, str):
        return x
    if x == int(x) and abs(x) < 1e16:
        return str(int(x))
    return "%.6g" % x


def secs(x):
    x = num(x)
    if x >= 100:
        return "%.0f" % x
    if x >= 10:
        return "%.1f" % x
    if x >= 1:
        return "%.2f" % x
    return "%.3g" % x


def hms(s):
    s = int(s + 0.5)
    if s >= 3600:
        return "%dh%02dm%02ds" % (s // 3600, (s % 3600) // 60, s % 60)
    if s >= 60:
        return "%dm%02ds" % (s // 60, s % 60)
    return "%ds" % s


def fields(line):
    """key=value words of a SUMMARY line."""
    out = {}
    for w in line.split():
        if "=" in w:
            k, v = w.split("=", 1)
            out[k] = v
    return out
