"""The floor benchmarks (``benchmarks/floors.py``, ``paramres bench --floors``): the runner's
mechanics on made-up scenes, the scene modules' format, and the certified floor itself as an
independent computation of the edges (a plain arb interval Newton written in the benchmark,
compared with :func:`verify.solve.boundary` to all 60 digits)."""

from __future__ import annotations

import importlib.util
from fractions import Fraction
from pathlib import Path

import mpmath
import pytest
from flint import arb, ctx

from reports.cli import main
from verify.solve import boundary

BENCH = Path(__file__).resolve().parent.parent / "benchmarks"


def _load(name):
    spec = importlib.util.spec_from_file_location(f"_test_{name}", BENCH / f"{name}.py")
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


def test_measure_times_both_and_render_marks_failures():
    floors = _load("floors")
    calls = []
    ours, floor = floors.measure(
        lambda: calls.append("o"), lambda: calls.append("f"), samples=3, min_time=0.0
    )
    assert ours >= 0 and floor >= 0
    # alternate: after the warm-up and the batch sizing, the samples interleave
    assert "".join(calls).endswith("ofofof")
    doc = {
        "date": "d",
        "machine": {"cpu": "c", "cores": 2, "load": 1.0, "python": "3"},
        "quick": True,
        "seconds": 1.0,
        "scenes": [
            {
                "name": "a",
                "ours_seconds": 2e-3,
                "floor_seconds": 1e-3,
                "ratio": 2.0,
                "target": 1.5,
                "passed": False,
                "clock": "cpu",
            },
            {
                "name": "b",
                "ours_seconds": 1e-6,
                "floor_seconds": 1e-6,
                "ratio": 1.0,
                "target": 1.5,
                "passed": True,
                "clock": "wall",
            },
        ],
    }
    text = floors.render(doc)
    assert "FAIL" in text and "pass (wall)" in text and "1 of 2 scenes within target" in text
    table = floors.markdown(doc).splitlines()
    rows = [line for line in table if line.startswith("| a ") or line.startswith("| b ")]
    assert rows == [
        "| a | 2 ms | 1 ms | 2.00 | 1.5 | **fails** |",
        "| b | 1 µs | 1 µs | 1.00 | 1.5 | pass (wall) |",
    ]
    assert table[0].startswith("Measured d (") and "2 cores, load 1.0" in table[0]


def test_the_readme_table_is_the_stored_run():
    """The README's table of the floors is what ``floors.py --markdown`` prints of the stored run
    (``benchmarks/floors.json``): regenerated, not typed."""
    import json

    floors = _load("floors")
    doc = json.loads((BENCH / "floors.json").read_text())
    readme = (BENCH.parent / "README.md").read_text()
    assert floors.markdown(doc) in readme


@pytest.mark.parametrize("name", sorted(p.stem for p in BENCH.glob("floor_*.py")))
def test_scene_modules_follow_the_format(name):
    scenes = _load(name).scenes(True)
    assert scenes
    for sc in scenes:
        assert {"name", "target", "ours", "floor", "note"} <= set(sc)
        # floor None: an absolute target, in seconds (the runner's format)
        assert callable(sc["ours"]) and sc["target"] > 0
        assert sc["floor"] is None or callable(sc["floor"])


def test_a_scene_without_floor_is_timed_alone_against_seconds():
    floors = _load("floors")
    calls = []
    ours, floor = floors.measure(lambda: calls.append(1), None, samples=3, min_time=0)
    assert floor is None and ours >= 0 and len(calls) == 1 + 3  # one warm-up call, three samples


def test_short_calls_are_timed_in_more_shorter_samples(monkeypatch):
    """Calls shorter than ``min_time / SPLIT`` are timed in ``SPLIT`` times as many samples of a
    ``SPLIT``-th of the time (ours and the floor alternating that much more often); longer calls
    in the samples asked for.  The clock is a counter: each call of a function advances it by
    that function's time."""
    floors = _load("floors")
    now, reads = [0.0], [0]

    def clock():
        reads[0] += 1
        return now[0]

    monkeypatch.setattr(floors, "_clock", lambda kind: clock)

    def timed(seconds: float, log: list):
        def fn():
            now[0] += seconds
            log.append(seconds)

        return fn

    assert floors.SPLIT > 1
    for seconds, want in ((1e-4, 9 * floors.SPLIT), (0.01, 9)):
        ours_log, floor_log = [], []
        reads[0] = 0
        ours, floor = floors.measure(
            timed(seconds, ours_log), timed(2 * seconds, floor_log), samples=9, min_time=0.03
        )
        assert ours == pytest.approx(seconds) and floor == pytest.approx(2 * seconds)
        # one warm-up call, one to size the batches, then the samples of ``per`` calls each
        per, left = divmod(len(floor_log) - 2, want)
        length = 0.03 / (floors.SPLIT if want > 9 else 1)
        assert left == 0 and abs(per - length / (2 * seconds)) <= 1, (seconds, len(floor_log))
        # two reads to size the batches of each, and two a sample of each
        assert reads[0] == 2 * 2 + 2 * 2 * want


@pytest.mark.parametrize("digits", [15, 60, 300])
def test_the_certified_floor_encloses_the_engines_edges(digits):
    fc = _load("floor_certified")
    lo, hi = sorted(fc.floor_edges(Fraction(3, 10), digits), key=lambda b: float(b.mid()))
    b = boundary(3, "3/10", digits=digits)
    with mpmath.workdps(digits + 20), ctx.workprec(4 * digits + 100):
        for ball, val, rad in ((lo, b.lower, b.radii[0]), (hi, b.upper, b.radii[1])):
            # the engine's ball and the floor's ball overlap: both contain the exact edge
            mine = arb(mpmath.nstr(val, digits + 15), mpmath.nstr(rad, 5))
            assert mine.overlaps(ball)
            assert mine.rad() < arb(10) ** (-digits) and ball.rad() < arb(10) ** (-digits)


def test_certified_growth_comes_from_the_alternate_scenes():
    # the exponent of time ~ D^a between two precisions: from the scene that timed them
    # alternately (ratio 5**1.5 here: a = 1.5), else from the two separate medians (25 = 5**2)
    fc = _load("floor_certified")
    rows = [
        {"name": "certified 1000 digits", "ours_seconds": 1.0},
        {"name": "certified 5000 digits", "ours_seconds": 25.0},
        {"name": "certified growth 1000 -> 5000 digits", "ours_seconds": 2.0, "ratio": 5**1.5},
    ]
    assert fc.summary(rows) == [
        "certified time ~ D^1.50 from 1000 to 5000 digits, timed alternately (target <= 1.7)"
    ]
    assert fc.summary(rows[:2]) == [
        "certified time ~ D^2.00 from 1000 to 5000 digits, medians of separate scenes "
        "(target <= 1.7)"
    ]
    # every pair of successive precisions from 1000 digits on has its growth scene
    names = [sc["name"] for sc in fc.scenes(quick=True)]
    assert "certified growth 1000 -> 10000 digits" in names
    targets = {sc["name"]: sc["target"] for sc in fc.scenes(quick=False)}
    assert targets["certified growth 5000 -> 10000 digits"] == pytest.approx(2**1.7)


def test_floors_flag_refuses_plot(capsys):
    assert main(["bench", "--floors", "--plot", "x.pdf"]) == 2
    assert "paramres: error:" in capsys.readouterr().err


def test_series_scene_clears_caches_that_exist():
    # the series scene clears the caches that depend on the number of terms before every call;
    # a renamed or uncached function would make the scene fail (or time a warm cache)
    import analytic.expansions
    import analytic.thresholds

    mod = _load("floor_series")
    for name, funcs in mod._PER_K.items():
        module = {"expansions": analytic.expansions, "thresholds": analytic.thresholds}[name]
        for f in funcs:
            assert callable(getattr(getattr(module, f), "cache_clear", None)), (name, f)
    mod._clear()


def test_the_table_scene_hands_out_results_as_from_balls_builds_them(monkeypatch):
    """The table scene's solver hands out, at every call, new results in exactly the state
    :func:`verify.result.from_balls` leaves them in (its class, its attributes; nothing printed or
    converted yet): what printing keeps in one result does not reach the next call's."""
    from reports.commands import table
    from verify.result import from_balls

    ours = _load("floor_table").scenes(True)[0]["ours"]
    seen = []

    def rows(orders, ms, Q, damping, digits, jobs, system):
        out = []
        for m in ms:
            b = table._solver(
                3,
                m,
                Q=Q,
                damping=damping,
                digits=digits,
                system=system,
                modulation="square",
                switch_time=None,
            )
            seen.append((m, type(b), dict(vars(b))))
            out.append((3, m, *b.printed()))
        return out

    monkeypatch.setattr(table, "rows", rows)
    ours()
    ours()
    assert seen
    keys = ("order", "m", "Q", "damping", "digits", "method", "regime", "system", "notes")
    for m, cls, attributes in seen:
        solved = boundary(3, m, digits=50)
        built = from_balls(
            solved._balls, certified=solved.certified, **{k: getattr(solved, k) for k in keys}
        )
        assert cls is type(built)
        expected = dict(vars(built))
        assert attributes.keys() == expected.keys()  # no text, bound or number kept yet
        balls = attributes.pop("_balls")
        for x, y in zip(balls, expected.pop("_balls"), strict=True):
            assert x.mid().man_exp() == y.mid().man_exp() and x.rad().man_exp() == y.rad().man_exp()
        assert attributes == expected
