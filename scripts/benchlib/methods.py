"""methods - scripts/methods.tsv, the one list of the methods of the suite.

One row per method in the order of tables and figures: key, label, colour,
gnuplot point type, kind (pd, direct, iter, cfpo), the SUMMARY line's method
and variant, and the command under the build folder with its fixed arguments.
The method key of a runs.csv row (its method and variant) is computed here
and nowhere else; so is the name of a comparison group in a folder written
before the paper variant's key was `paper` (`comparison-cfpo`).
"""
import os

# every kind, in the order the experiments list them
KINDS = ("pd", "direct", "iter", "cfpo")
# the kinds that are not iterative (no convergence curve, no iterations)
ONE_PASS = ("pd", "direct")
TSV = os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "methods.tsv")


class Methods:
    def __init__(self, path=TSV):
        self.rows = {}
        self.order = []
        cols = None
        with open(path) as f:
            for line in f:
                line = line.rstrip("\n")
                if not line or line.startswith("#"):
                    continue
                cells = line.split("\t")
                if cells[0] == "key":
                    cols = cells
                    continue
                if cols is None:
                    raise ValueError(f"{path}: no column line before the rows")
                self.rows[cells[0]] = dict(zip(cols, cells))
                self.order.append(cells[0])
        if not self.order:
            raise ValueError(f"{path}: no methods")

    def keys(self, *kinds):
        """The keys of those kinds (all when none), in the file's order."""
        return [k for k in self.order if not kinds or self.rows[k]["kind"] in kinds]

    def get(self, key, field, default=""):
        return self.rows.get(key, {}).get(field, default)

    def label(self, key):
        return self.get(key, "label", key)

    def colour(self, key):
        return self.get(key, "colour", "#000000")

    def pt(self, key):
        return self.get(key, "pt", "8")

    def kind(self, key):
        return self.get(key, "kind", "")

    def binaries(self, *kinds):
        """The commands' programs, each once, in the file's order."""
        out = []
        for k in self.keys(*kinds):
            b = self.rows[k]["command"].split()[0]
            if b not in out:
                out.append(b)
        return out


def key(method, variant):
    """A runs.csv or integration.csv row's key: cfpo's variant (paper,
    simplified, adaptive, hyperuniform; the variant `cfpo` of the oldest
    folders is the paper's), else the method."""
    if method != "cfpo":
        return method
    return "paper" if variant in ("paper", "cfpo") else variant



def group(prefix, k, have):
    """The name of method k's group (prefix comparison or integration) in a
    folder whose groups are `have`: PREFIX-k, or for the paper variant the
    name of the folders written before it was the key paper
    (PREFIX-cfpo), where only that one is there."""
    g = f"{prefix}-{k}"
    if k == "paper" and g not in have and f"{prefix}-cfpo" in have:
        return f"{prefix}-cfpo"
    return g
