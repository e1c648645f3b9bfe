"""Argument checks shared by the package: the command line's wording for
Python values (ValueError for a bad value, TypeError for a wrong type),
with the ranges the C library gives (cfpo._core), and the conversion of
point arrays."""
import math
import numbers
import os

import numpy as np

from . import _core


def whole(name, v, lo, hi):
    """An int in [lo, hi] (bools refused)."""
    if isinstance(v, bool) or not isinstance(v, numbers.Integral):
        raise TypeError(f"{name}: expected a whole number, got {type(v).__name__}")
    v = int(v)
    if not lo <= v <= hi:
        raise ValueError(f"{name}: '{v}' is not a whole number in {lo}..{hi}")
    return v


def real(name, v, lo, hi, open_lo=False):
    """A finite float in [lo, hi] (or (lo, hi] with open_lo)."""
    if isinstance(v, bool) or not isinstance(v, numbers.Real):
        raise TypeError(f"{name}: expected a number, got {type(v).__name__}")
    v = float(v)
    ok = math.isfinite(v) and (v > lo if open_lo else v >= lo) and v <= hi
    if not ok:
        brace = "(" if open_lo else "["
        raise ValueError(f"{name}: '{v:g}' is not a number in {brace}{lo:g}, {hi:g}]")
    return v


def flag(name, v):
    """True or False (a Python or NumPy bool; anything else refused)."""
    if not isinstance(v, (bool, np.bool_)):
        raise TypeError(f"{name}: expected True or False, got {type(v).__name__}")
    return bool(v)


def choice(name, v, words, bad):
    """The index of v among words; bad: the command's wording of a bad
    value ("is not one of ...", "is neither ... nor ...")."""
    if not isinstance(v, str):
        raise TypeError(f"{name}: expected a string, {', '.join(words[:-1])} or {words[-1]}")
    if v not in words:
        raise ValueError(f"{name}: '{v}' {bad}")
    return words.index(v)


def option(o, v):
    """The value of v for an option of a baseline's table (cfpo._core.methods),
    checked by its type and range; None: the option's default."""
    name = o["py"]
    if v is None:
        return o["default"]
    if o["type"] == "int":
        return whole(name, v, o["min"], o["max"])
    if o["type"] == "real":
        return real(name, v, o["min"], o["max"], open_lo=o["open_min"])
    if o["type"] == "flag":
        return int(flag(name, v))
    return choice(name, v, o["choices"], o["bad"])


def max_iter(v):
    """The iteration cap: None for the default, else a whole number in the
    commands' range."""
    return _core.default_max_iter if v is None else whole("max_iter", v, 0, _core.max_iter_max)


def tol(v, default):
    """A move tolerance in [0, tol_max]; None: default."""
    return default if v is None else real("tol", v, 0, _core.tol_max)


def seed(v):
    """A 64-bit unsigned seed."""
    return whole("seed", v, 0, 2**64 - 1)


def points_n(v):
    """The number of points: a positive whole number."""
    return whole("n", v, 1, 2**63 - 1)


def threads(v):
    """threads=None follows OMP_NUM_THREADS (its first number), else all cores (0)."""
    if v is None:
        env = os.environ.get("OMP_NUM_THREADS", "").split(",")[0].strip()
        return int(env) if env.isdigit() and 1 <= int(env) <= 4096 else 0
    return whole("threads", v, 1, 4096)


def stop_rules(target_min, target_avg, time_limit):
    """The stop rules of src/common/stoprule.c (0 = not set), with its ranges."""
    given = {"target_min": target_min, "target_avg": target_avg, "time_limit": time_limit}
    return tuple(0.0 if v is None else real(k, v, *_core.stop_options[k], open_lo=True) for k, v in given.items())


def as_points(points, name="points", min_n=1, dim=2):
    """points as a C-contiguous float64 (n, dim) array in [0, 1)^dim (dim 2 or 3).

    Any real numeric dtype (integers, float16/32/64, ...) and any memory
    layout (Fortran order, strides, views) is converted (one copy when the
    array is not already C-contiguous float64). Complex, boolean, object and
    string arrays are refused with a TypeError that says how to convert.
    Wrong shapes, NaN/inf, coordinates outside [0, 1) and fewer than min_n
    points raise ValueError.
    """
    try:
        a = np.asarray(points)
    except (ValueError, TypeError) as e:
        raise TypeError(f"{name}: cannot be read as an array of numbers ({e}); pass an (n, {dim}) array, "
                        f"e.g. np.asarray({name}, dtype=np.float64)") from None
    if a.dtype.kind not in "iuf":
        raise TypeError(f"{name}: dtype {a.dtype} is not a real number type; convert with "
                        f"np.asarray({name}, dtype=np.float64)")
    if a.ndim != 2 or a.shape[1] != dim:
        raise ValueError(f"{name}: expected an (n, {dim}) array of points, got shape {a.shape}")
    a = np.ascontiguousarray(a, dtype=np.float64)
    if a.shape[0] < min_n:
        raise ValueError(f"{name}: {a.shape[0]} points; at least {min_n} needed")
    finite = np.isfinite(a)
    if not finite.all():
        i = int(np.argwhere(~finite)[0][0])
        raise ValueError(f"{name}: point {i} is not finite ({', '.join(f'{v:g}' for v in a[i])})")
    inside = (a >= 0) & (a < 1)
    if not inside.all():
        i = int(np.argwhere(~inside)[0][0])
        raise ValueError(f"{name}: point {i} ({', '.join(repr(float(v)) for v in a[i])}) is outside [0,1)^{dim}")
    return a


def density(v):
    """A density as the C layer takes it: a SPEC string (or a path), or a
    2-D float64 array (row = y)."""
    if v is None:
        raise ValueError("density: required: a SPEC string (as cfpo --density SPEC) or a 2-D array")
    if isinstance(v, (str, bytes)) or hasattr(v, "__fspath__"):
        return os.fsdecode(v)
    a = np.ascontiguousarray(v, dtype=np.float64)
    if a.ndim != 2:
        raise ValueError(f"density: expected a SPEC string or a 2-D array, got an array of {a.ndim} dimensions")
    return a
