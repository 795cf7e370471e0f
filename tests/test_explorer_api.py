"""The explorer's JSON endpoints over HTTP (no browser): the same certified values as the public
API, bad requests answered with HTTP 400 and one line of JSON, caps, and a fuzz of query strings
(every answer 200 or 400 -- never 500, never a hang).  The command line's refusals of
``paramres explore`` and the static export are here too."""

from __future__ import annotations

import json
import os
import urllib.error
import urllib.request
from urllib.parse import quote, urlencode

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

import paramres
from reports.cli import main
from reports.explorer import api
from reports.explorer.server import Explorer

#: seconds an answer may take before the test calls it a hang (the machine may be loaded)
ANSWER_LIMIT = 60.0


@pytest.fixture(scope="module")
def server():
    app = Explorer(port=0, warm=False).start()
    yield app
    app.stop()


def get(app, path: str) -> tuple[int, dict]:
    try:
        with urllib.request.urlopen(app.url + path.lstrip("/"), timeout=ANSWER_LIMIT) as r:
            return r.status, json.loads(r.read())
    except urllib.error.HTTPError as exc:
        return exc.code, json.loads(exc.read())


def test_multipliers_are_the_public_apis(server):
    status, doc = get(server, "/api/multipliers?T=1.45&m=3/10&digits=30")
    assert status == 200
    ref = paramres.multipliers("1.45", "3/10", digits=30).as_json()
    assert doc["multipliers"] == ref["multipliers"]
    assert doc["max_modulus"] == ref["max_modulus"] == "2.02495401734799458766118694098"
    assert doc["max_modulus_error_bound"] == ref["max_modulus_error_bound"]


def test_boundary_is_the_public_apis(server):
    status, doc = get(server, "/api/boundary?order=1&m=3/10&digits=30")
    assert status == 200
    ref = paramres.boundary(1, "3/10", digits=30).as_json()
    assert (doc["lower"], doc["upper"], doc["error_bound"]) == (
        ref["lower"],
        ref["upper"],
        ref["error_bound"],
    )
    # the closing of the third interval at m = 3/5 (README): both edges equal
    status, doc = get(server, "/api/boundary?order=3&m=3/5&digits=25")
    assert status == 200 and doc["lower"] == doc["upper"]


def test_point_picks_the_interval_that_holds_the_click(server):
    # T = 1.45 lies in the third interval at m = 0.3 ([1.3411..., 1.5447...], /api/boundary)
    status, doc = get(server, "/api/point?T=1.45&m=0.3&digits=20")
    assert status == 200 and doc["order"] == 3
    assert float(doc["boundary"]["lower"]) < 1.45 < float(doc["boundary"]["upper"])
    assert doc["multipliers"]["unstable"] is True
    # the ramp modulation reaches the certified ramp routes
    status, doc = get(server, "/api/point?T=0.5&m=0.3&digits=20&modulation=ramp&switch_time=0.02")
    assert status == 200 and doc["order"] == 1, doc
    ref = paramres.boundary(1, "0.3", digits=20, modulation="ramp", switch_time="0.02")
    assert doc["boundary"]["lower"] == ref.as_json()["lower"]


def test_chart_is_the_growth_map_and_the_grid(server):
    import numpy as np

    from verify.growth import growth_map

    q = "tmin=0.3&tmax=1.2&mmin=0.1&mmax=0.5&nt=10&nm=5&max_order=2"
    status, doc = get(server, f"/api/chart?{q}")
    assert status == 200
    assert len(doc["T"]) == 10 and len(doc["m"]) == 5 and len(doc["growth"]) == 5
    ref = growth_map(np.linspace(0.3, 1.2, 10), np.linspace(0.1, 0.5, 5))
    # the JSON keeps 4 significant digits of the double-precision map
    assert np.allclose(np.array(doc["growth"], dtype=float), ref, rtol=1e-3, atol=1e-12)
    edges = paramres.boundary_grid([1, 2], [float(f"{x:.12g}") for x in np.linspace(0.1, 0.5, 5)])
    assert np.allclose(np.array(doc["lower"], dtype=float), edges[:, 0], rtol=1e-11)
    assert np.allclose(np.array(doc["upper"], dtype=float), edges[:, 1], rtol=1e-11)


def test_simulate_is_the_time_domain_run(server):
    status, doc = get(server, "/api/simulate?T=1.45&m=0.3&periods=4&samples=16")
    assert status == 200
    run = paramres.simulate(3, "0.3", T="1.45", periods=4, digits=15, samples=16)
    assert len(doc["segments"]) == 8
    assert doc["segments"][3]["phi"][-1] == pytest.approx(float(run.segments[3].phi[-1]), 1e-9)
    assert doc["growth_per_period"] == pytest.approx(float(run.growth_per_period), 1e-12)
    assert doc["regimes"] == ["under", "under"] and doc["model"] == "none"
    status, doc = get(server, "/api/simulate?T=1.45&m=0.3&periods=4&nonlinear=1")
    assert status == 200 and doc["nonlinear"] is True


def test_simulate_runaway_gets_400_at_once(server):
    # every value within the explorer's caps, yet the jumps at m = 0.99 speed the rotation up
    # without bound: refused by the budget of integration steps, the worker free again at once
    import time

    start = time.monotonic()
    status, doc = get(server, "/api/simulate?T=20&m=0.99&periods=60&samples=200&nonlinear=1")
    assert status == 400 and doc["error"].startswith("the motion grows too fast to follow")
    assert "by period 1 of 60" in doc["error"]
    assert time.monotonic() - start < 10
    status, _ = get(server, "/api/simulate?T=1.45&m=0.3&periods=2&nonlinear=1")
    assert status == 200


@pytest.mark.parametrize(
    ("path", "words"),
    [
        ("/api/boundary?order=1&m=2", "depth m = 2 is outside the allowed range"),
        ("/api/boundary?order=0&m=0.3", "order 0 is outside the allowed range"),
        ("/api/boundary?m=0.3", "order is required"),
        ("/api/boundary?order=1&m=0.3&digits=5000", "outside the explorer's range 5 to 100"),
        # beyond the command line's range too: the message still names the explorer's range
        ("/api/boundary?order=1&m=0.3&digits=100000", "outside the explorer's range 5 to 100"),
        ("/api/boundary?order=1&m=0.3&digits=abc", "the explorer's range is 5 to 100"),
        ("/api/boundary?order=99999&m=0.3", "order 99999 is outside the allowed range 1 to 120"),
        ("/api/multipliers?T=1e400&m=0.3", "outside the explorer's range 0.01 <= T <= 20"),
        ("/api/multipliers?T=abc&m=0.3", "allowed range 0.01 <= T <= 20"),
        ("/api/boundary?order=1&m=0.3&digits=abc", "digits 'abc' is not an integer"),
        ("/api/boundary?order=1&m=0.3&colour=red", "unknown parameter 'colour'"),
        ("/api/boundary?order=1&order=2&m=0.3", "given 2 times"),
        ("/api/multipliers?T=-1&m=0.3", "period T = -1 is outside"),
        ("/api/multipliers?T=1e999999999&m=0.3", "period T = 1e999999999 is outside"),
        ("/api/multipliers?T=1&m=0.3&Q=0", "quality factor Q = 0 is outside"),
        ("/api/multipliers?T=1&m=0.3&damping=wet", "damping model"),
        ("/api/multipliers?T=1&m=0.3&system=rocket", "rocket"),
        ("/api/multipliers?T=1&m=0.3&modulation=triangle", "modulation 'triangle' is not one of"),
        ("/api/chart?nt=100000", "nt 100000 is outside the allowed range 2 to 600"),
        ("/api/chart?max_order=50", "max_order 50 is outside the allowed range 1 to 12"),
        ("/api/chart?tmin=2&tmax=1", "must be smaller than"),
        ("/api/chart?system=custom&omega_sq=1/2,2", "needs a depth axis"),
        ("/api/simulate?T=1&m=0.3&periods=100000", "periods 100000 is outside"),
        ("/api/simulate?T=1&m=0.3&nonlinear=perhaps", "nonlinear 'perhaps' is not one of"),
        ("/api/presets?x=1", "unknown parameter 'x'"),
        ("/api/boundary?%zz", "cannot be read"),
    ],
)
def test_bad_requests_get_400_and_one_line(server, path, words):
    status, doc = get(server, path)
    assert status == 400, (path, doc)
    assert set(doc) == {"error"} and "\n" not in doc["error"], doc
    assert words in doc["error"], (path, doc["error"])
    assert "Traceback" not in doc["error"]


def test_unknown_paths_get_404(server):
    assert get(server, "/api/nothing")[0] == 404
    assert get(server, "/static/../../etc/passwd")[0] == 404
    assert get(server, "/elsewhere")[0] == 404


def test_the_page_and_its_scripts_are_served_from_the_package(server):
    for path, kind in [
        ("", "text/html"),
        ("static/app.js", "javascript"),
        ("static/style.css", "text/css"),
        ("static/generated.js", "javascript"),
    ]:
        with urllib.request.urlopen(server.url + path, timeout=ANSWER_LIMIT) as r:
            assert r.status == 200 and kind in r.headers["Content-Type"]
            body = r.read().decode()
        # offline: nothing is fetched from elsewhere
        assert "http://" not in body.replace(server.url, "") and "https://" not in body


def test_a_computation_past_the_time_cap_gets_503(monkeypatch):
    import threading

    release = threading.Event()

    def slow(query):  # stands for a computation that takes too long
        release.wait(30)
        return {}

    monkeypatch.setitem(api.ENDPOINTS, "boundary", slow)
    monkeypatch.setitem(api.ENDPOINTS, "simulate", slow)
    app = Explorer(port=0, timeout=0.2, warm=False).start()
    try:
        status, doc = get(app, "/api/boundary?order=1&m=0.3")
        assert status == 503 and "took longer than 0.2 s" in doc["error"]
        assert doc["error"].endswith("ask for fewer digits")
        release.set()  # the worker is free again
        release.clear()
        status, doc = get(app, "/api/simulate?T=1&m=0.3")
        assert status == 503 and doc["error"].endswith("ask for fewer periods or fewer samples")
    finally:
        release.set()
        app.stop()


# ------------------------------------------------------------------------------------------------
# fuzz: garbage and random query strings

names = st.sampled_from(
    ["order", "m", "T", "Q", "digits", "damping", "system", "duty", "omega_sq", "jump",
     "modulation", "switch_time", "nt", "nm", "max_order", "periods", "nonlinear", "samples",
     "amplitude", "tmin", "tmax", "mmin", "mmax", "parts", "zzz", ""]
)  # fmt: skip
values = st.one_of(
    st.sampled_from(
        ["0.3", "3/5", "1", "0", "-1", "1e-12", "1e999999", "nan", "inf", "none", "exact",
         "paper", "ramp", "square", "custom", "torsion", "1/0", "", "½", "1" * 3000, "12", "5",
         "600", "601", "growth", "edges", "1,2", "0.02"]
    ),
    st.text(max_size=8),
)  # fmt: skip
pairs = st.lists(st.tuples(names, values), max_size=6)


@settings(
    max_examples=int(os.environ.get("PARAMRES_FUZZ_EXAMPLES", "150")),
    deadline=None,
    derandomize=True,
    suppress_health_check=[HealthCheck.too_slow, HealthCheck.function_scoped_fixture],
)
@given(
    endpoint=st.sampled_from(sorted(api.ENDPOINTS) + ["nothing"]),
    query=st.one_of(pairs.map(urlencode), st.text(max_size=40).map(lambda s: quote(s, safe="=&%"))),
)
def test_fuzzed_queries_get_200_or_400(server, endpoint, query):
    status, doc = get(server, f"/api/{endpoint}?{query}")
    if endpoint == "nothing":
        assert status == 404
        return
    assert status in (200, 400), (endpoint, query, status, doc)
    if status == 400:
        assert set(doc) == {"error"} and doc["error"] and "\n" not in doc["error"]


# ------------------------------------------------------------------------------------------------
# the command line


@pytest.mark.parametrize(
    ("argv", "words"),
    [
        (["explore", "--port", "70000"], "port 70000 is outside the allowed range 0 to 65535"),
        (["explore", "--port", "http"], "port 'http' is not an integer"),
        (["explore", "--host", "a b"], "host 'a b' is not a host name"),
    ],
)
def test_explore_refuses_bad_options(capsys, argv, words):
    assert main(argv) == 2
    err = capsys.readouterr().err
    assert err.startswith("paramres: error: ") and words in err and len(err.splitlines()) == 1


def test_explore_refuses_an_export_into_a_file(tmp_path, capsys):
    target = tmp_path / "afile"
    target.write_text("x")
    assert main(["explore", "--export", str(target)]) == 2
    assert "not an empty directory" in capsys.readouterr().err
    assert target.read_text() == "x"


def test_explore_refuses_an_export_where_nothing_can_be_made(capsys):
    # /proc passes os.access for root, but no directory can be made there: one line, no traceback
    assert main(["explore", "--export", "/proc/paramres-export"]) == 2
    err = capsys.readouterr().err
    assert err.startswith("paramres: error: --export /proc/paramres-export: cannot write in /proc")
    assert len(err.splitlines()) == 1


def test_export_writes_a_static_copy(tmp_path):
    from reports.explorer.export import export

    out = export(tmp_path / "site", presets=["fig2"])
    page = (out / "index.html").read_text()
    assert "window.PARAMRES_STATIC = true" in page
    for name in ("static/app.js", "static/style.css", "static/generated.js", "data/fig2.json"):
        assert (out / name).is_file(), name
    doc = json.loads((out / "data" / "fig2.json").read_text())
    assert len(doc["growth"]) == len(doc["m"]) and doc["orders"] == [1, 2, 3, 4, 5, 6]
    presets = json.loads((out / "data" / "presets.json").read_text())["presets"]
    assert [p["id"] for p in presets] == ["fig2"]


def test_explore_in_python_returns_the_running_server(capsys):
    app = paramres.explore(port=0)
    try:
        assert app.url.startswith("http://127.0.0.1:")
        assert app.url in capsys.readouterr().out
        status, doc = get(app, "/api/presets")
        assert status == 200 and {p["id"] for p in doc["presets"]} >= {"fig2", "fig8", "closing"}
    finally:
        app.stop()


def test_explore_in_a_notebook_returns_an_iframe(monkeypatch):
    """With IPython running, ``paramres.explore()`` returns an ``IFrame`` of the page (a stand-in
    IPython module here: the test does not need IPython installed)."""
    import sys
    import types

    class IFrame:
        def __init__(self, src, width, height):
            self.src, self.width, self.height = src, width, height

    ipython = types.ModuleType("IPython")
    ipython.get_ipython = lambda: object()
    display = types.ModuleType("IPython.display")
    display.IFrame = IFrame
    monkeypatch.setitem(sys.modules, "IPython", ipython)
    monkeypatch.setitem(sys.modules, "IPython.display", display)
    frame = paramres.explore(port=0)
    try:
        assert isinstance(frame, IFrame) and frame.src == frame.explorer.url
        assert get(frame.explorer, "/api/presets")[0] == 200
    finally:
        frame.explorer.stop()


def test_the_command_serves_until_stopped(tmp_path):
    """``paramres explore --no-browser --port 0`` prints its address and serves the page."""
    import subprocess
    import sys

    proc = subprocess.Popen(
        [sys.executable, "-m", "paramres", "explore", "--no-browser", "--port", "0"],
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
        env={**os.environ, "PARAMRES_CACHE_DIR": str(tmp_path)},
    )
    try:
        line = proc.stdout.readline()
        assert line.startswith("paramres explorer: http://127.0.0.1:"), line
        url = line.split()[2]
        with urllib.request.urlopen(url, timeout=ANSWER_LIMIT) as r:
            assert r.status == 200 and b'data-testid="chart"' in r.read()
    finally:
        proc.terminate()
        proc.wait(30)
    assert "Traceback" not in proc.stderr.read()


def test_the_threshold_preset_is_above_the_threshold_and_inside_the_interval():
    """The "threshold" preset says: order 1 with Q = 5, m just above pi/(6Q) (the leading
    threshold, eq. 38).  Its depth is above pi/(6Q) and above the proven threshold of its own
    damping model (``verify.existence``, branch and bound), and its period lies inside the certified
    interval of order 1 there (``boundary``), so the clicked point is unstable."""
    from fractions import Fraction

    import mpmath

    (pre,) = [p for p in api.PRESETS if p["id"] == "threshold"]
    Qv, model = Fraction(pre["chart"]["Q"]), pre["chart"]["damping"]
    m, T = Fraction(pre["point"]["m"]), Fraction(pre["point"]["T"])
    assert Qv == 5 and pre["chart"]["system"] == "pendulum"
    ex = paramres.existence(1, Qv, damping=model, digits=15)
    first = next(t for t in ex.thresholds if t.appears)
    assert not ex.undecided and first.enclosure[1] < m  # exact rationals
    with mpmath.workdps(30):  # the margins are above 1e-3: 30 digits decide them
        mm = mpmath.mpf(m.numerator) / m.denominator
        assert mm > mpmath.pi / (6 * Qv)
        assert [iv for iv in ex.intervals if iv[0] < mm <= iv[1]]  # m in a proven range
    b = paramres.boundary(1, m, Q=Qv, damping=model, digits=15)
    Tm = mpmath.mpf(T.numerator) / T.denominator  # 1/2, exact
    assert b.exists and b.lower_enclosure[1] < Tm < b.upper_enclosure[0]
