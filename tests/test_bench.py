"""The benchmark's machinery on tiny scenes: structure, errors against the reference, the Pareto
front.  No assertion is about time (the machine is shared): only that times are measured.

References: the certified edges of :func:`verify.solve.boundary` at 60 digits (what the benchmark
itself compares with), recomputed here independently for the error checks; the printed equations
are those of :mod:`analytic.printed` (eqs. 13, 25, 36).
"""

from __future__ import annotations

import json
import math
from fractions import Fraction

import mpmath
import pytest

from reports import benchmark as bench
from verify.solve import boundary

SCENE = bench.Scene(3, Fraction(3, 10))
CLOSING = bench.Scene(3, Fraction(3, 5), group="closing")
FRICTION = bench.Scene(1, Fraction(55, 1000), Fraction(10), "paper", group="threshold")

NAMES = (
    "series K=1",
    "series K=4",
    "fixed point (paper)",
    "double, per point",
    "numpy grid",
    "mpmath 30, uncertified",
    "certified 15",
    "certified 50",
    "findroot 15 (printed eq.)",
    "auto, tol=1e-8",
)


def pick(*names):
    return [m for m in bench.methods() if m.name in names]


@pytest.fixture(scope="module")
def result():
    return bench.run(
        scene_list=[SCENE, CLOSING, FRICTION],
        method_list=pick(*NAMES),
        runs=1,
        grid_depths=20,
        table=False,
    )


def rel(a, b):
    with mpmath.workdps(70):
        return float(abs(mpmath.mpf(a) - b) / abs(b))


def test_every_pair_is_measured_or_explained(result):
    assert len(result.measurements) == len(NAMES) * 3
    for x in result.measurements:
        if x.failure is None:
            assert x.cpu is not None and x.cpu > 0 and x.wall > 0 and x.calls >= 1
            assert x.error is not None and x.error >= bench.ERROR_FLOOR
        else:
            assert x.error is None
    # every method applies to these scenes: the friction scene is in the paper's model (its
    # printed eq. 36 and the normal form) and its series near the threshold are derived
    assert all(x.failure is None for x in result.measurements), [
        (x.method, x.scene.name, x.failure) for x in result.measurements if x.failure
    ]


def test_errors_against_the_reference(result):
    ref = boundary(3, Fraction(3, 10), digits=60)
    x = result.find("certified 50", SCENE)
    assert x.error < 1e-50
    assert result.find("certified 15", SCENE).error < 1e-15
    assert result.find("double, per point", SCENE).error < 1e-14
    assert result.find("numpy grid", SCENE).error < 1e-14
    assert result.find("findroot 15 (printed eq.)", SCENE).error < 1e-13
    assert result.find("auto, tol=1e-8", SCENE).error <= 1e-8
    # series K=1 (eq. 19's linear term): error of the size of the next term, ~m^2
    s1 = result.find("series K=1", SCENE).error
    assert 1e-3 < s1 < 0.2
    # recompute one error independently: the series value against the reference
    from verify.auto import series_value

    lo, hi = series_value(3, 1, 0.3)
    assert math.isclose(s1, max(rel(lo, ref.lower), rel(hi, ref.upper)), rel_tol=1e-6)


def test_the_paper_iteration_is_compared_with_its_own_labels(result):
    """Below the closing m = 3/5 of order 3 the paper's convention (s = -1 'lower') is right; at
    the closing both edges coincide; past it the two edge equations swap roles and the paper's
    'lower' edge is the upper one: an error of the relative width (docs/theory.md, closings)."""
    assert result.find("fixed point (paper)", SCENE).error < 1e-12
    assert result.find("fixed point (paper)", CLOSING).error < 1e-12
    past = bench.Scene(3, Fraction(7, 10))
    res = bench.run(
        scene_list=[past],
        method_list=pick("fixed point (paper)"),
        runs=1,
        grid_depths=10,
        table=False,
    )
    ref = boundary(3, Fraction(7, 10), digits=30)
    width = float((ref.upper - ref.lower) / ref.lower)
    assert math.isclose(res.find("fixed point (paper)", past).error, width, rel_tol=1e-9)


def test_auto_records_its_choice(result):
    x = result.find("auto, tol=1e-8", SCENE)
    assert x.chosen == "double"
    assert result.find("auto, tol=1e-8", FRICTION).chosen.startswith("certified")


def test_friction_scene(result):
    assert result.find("certified 15", FRICTION).error < 1e-15
    assert result.find("numpy grid", FRICTION).error < 1e-12
    # eq. 36 (paper model, with friction) solved by findroot gives the edges
    assert result.find("findroot 15 (printed eq.)", FRICTION).error < 1e-12
    assert result.find("mpmath 30, uncertified", FRICTION).error < 1e-25


def test_summary_pareto_and_json(result):
    rows = result.summary()
    assert [r["method"] for r in rows] == list(NAMES)
    for r in rows:
        assert set(r) >= {"method", "family", "digits", "seconds", "error", "failures"}
    for key in ("all", "small m"):
        pts = bench.pareto(result, key)
        secs = [p["seconds"] for p in pts]
        assert secs == sorted(secs)
        best = math.inf
        for p in pts:  # on the front exactly when no faster point has a smaller error
            assert p["front"] == (p["error"] < best)
            best = min(best, p["error"])
    doc = result.as_json()
    text = json.dumps(doc)
    back = json.loads(text)
    assert back["machine"]["cores"] >= 1 and back["date"]
    assert {t["name"].split(",")[0] for t in back["targets"]} >= {"numpy grid"}
    assert len(back["measurements"]) == len(result.measurements)
    assert "CPU/edge" in result.table() and "closing" in result.hard_table()
    assert "numpy grid, 6 orders" in result.targets_text()


def test_scenes_cover_the_hard_cases():
    groups = {s.group for s in bench.scenes()}
    assert groups == {"standard", "tiny m", "m near 1", "closing", "threshold", "high order"}
    quick = bench.scenes(quick=True)
    assert {s.group for s in quick} == groups and len(quick) < len(bench.scenes())
    for s in bench.scenes():
        assert boundary(s.order, s.m, Q=s.Q, damping=s.damping, digits=15).exists, s.name


def test_median_time_counts_runs():
    calls = []
    wall, cpu, n = bench.median_time(lambda: calls.append(1), runs=3, budget=1.0, first=1e-6)
    assert n == len(calls) and n >= 3 and wall >= 0 and cpu >= 0


def test_auto_against_certified_interleaved():
    """The ratios are measured (positive, finite) for one point per tolerance and for the two
    tables, and record which methods the automatic choice used (series at small depths)."""
    rows = bench.auto_ratios(quick=True)
    assert len(rows) == len(bench.TOLERANCES) + len(bench.TABLE_DEPTHS)
    for r in rows:
        assert 0 < r["ratio"] < math.inf and r["auto_seconds_per_edge"] > 0
        assert sum(r["methods"].values()) >= 1
    small = rows[-1]
    assert "0.001-0.019" in small["name"]
    assert set(small["methods"]) == {"series K=" + k for k in "12345678"} & set(small["methods"])
    assert any(k.startswith("series") for k in small["methods"])
