"""The baselines as the C library describes them (cfpo.baselines.METHODS):
every method has one wrapper whose keywords are its table's options, the
defaults are the table's, and a run's trace has the command's columns."""
import inspect

import numpy as np
import pytest

import cfpo

B = cfpo.baselines
RUN = {"n", "seed", "tol", "max_iter", "target_min", "target_avg", "time_limit", "progress"}


@pytest.mark.parametrize("name", sorted(B.METHODS))
def test_wrapper_takes_the_tables_options(name):
    m = B.METHODS[name]
    params = set(inspect.signature(getattr(B, name)).parameters)
    own = {o["py"] for o in m["options"] if o["py"]}
    common = RUN if m["kind"] == "iterative" else {"n", "seed"}
    assert params == own | common | ({"density"} if m["density"] else set())
    assert m["prog"] == f"cfpo-{name}"
    for o in m["options"]:
        if o["py"]:
            assert f"{o['py']}:" in getattr(B, name).__doc__


def test_defaults_given_are_the_defaults():
    """Each option given its table default gives the bytes of leaving it out."""
    for name, n in (("dart", 300), ("bridson", 300), ("fpo", 150), ("ccvt", 100), ("bnot", 120)):
        m = B.METHODS[name]
        kw = {}
        for o in m["options"]:
            if not o["py"] or (o["type"] in ("int", "real") and not o["min"] <= o["default"] <= o["max"]):
                continue
            d = o["default"]
            kw[o["py"]] = o["choices"][d] if o["type"] == "choice" else bool(d) if o["type"] == "flag" else d
        extra = {"max_iter": 2} if m["kind"] == "iterative" else {}
        if name == "ccvt":
            extra["points_per_site"] = 64
        a, b = getattr(B, name)(n, **extra), getattr(B, name)(n, **extra, **kw)
        pa, pb = (a, b) if m["kind"] == "poisson" else (a.points, b.points)
        assert kw and np.array_equal(pa, pb), name


def test_trace_has_the_commands_columns(tmp_path, command):
    r = B.ccdt(200, seed=6, max_iter=3)
    command("cfpo-ccdt", "-n", 200, "--seed", 6, "--max-iter", 3, "--trace", "t.tsv", "-q")
    rows = [line.split("\t") for line in (tmp_path / "t.tsv").read_text().splitlines()]
    assert tuple(rows[0]) == B.METHODS["ccdt"]["columns"] == tuple(r.trace)
    assert tuple(r.trace)[:8] == cfpo.TRACE_COLUMNS[:8]
    assert [int(row[10]) for row in rows[1:]] == list(r.trace["new_edges"])
    assert r.trace["new_edges"].dtype == np.int64 and r.trace["step"].dtype == np.float64


def test_bad_option_values_use_the_tables_ranges():
    o = {x["py"]: x for x in B.METHODS["bnot"]["options"]}["max_rounds"]
    with pytest.raises(ValueError, match=f"max_rounds: '{o['max'] + 1}' is not a whole number in 1..{o['max']}"):
        B.bnot(100, max_rounds=o["max"] + 1)
