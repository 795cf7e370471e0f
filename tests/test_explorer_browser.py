"""The explorer in a real browser: Debian's Chromium driven headless by Playwright.

One browser per module.  Checked: the page loads without console errors and draws the chart (a
screenshot that is not blank); a click at a known point shows the certified values that
``/api/multipliers`` and ``/api/boundary`` give; moving a control redraws; a preset works; the
animation runs; the generated JavaScript agrees with the Python side (the free-oscillation map
against the matrix exponential of the equation of motion, computed by mpmath; the animation
between samples against the server's samples); the static export draws and moves on its own.

Without Chromium (or the ``playwright`` package) the tests skip and say why, unless
``PARAMRES_REQUIRE_BROWSER=1`` (CI sets it), when they fail.  The screenshot of the page is
written to ``$PARAMRES_SCREENSHOT_DIR`` (default: a temporary directory).
"""

from __future__ import annotations

import functools
import http.server
import json
import os
import threading
import urllib.request
from pathlib import Path

import mpmath
import pytest

CHROMIUM = "/usr/bin/chromium"
ARGS = [
    "--headless",
    "--no-sandbox",
    "--disable-gpu",
    "--disable-quic",
    "--no-first-run",
    "--disable-background-networking",
    "--disable-component-update",
    "--disable-sync",
]
#: milliseconds the page may take for anything (generous: the machine may be loaded)
WAIT = 120_000


def _missing() -> str | None:
    if not os.path.exists(CHROMIUM):
        return f"no Chromium at {CHROMIUM} (Debian: apt-get install chromium)"
    try:
        import playwright.sync_api  # noqa: F401
    except ImportError:
        return "the playwright package is not installed (pip install -e '.[test]')"
    return None


@pytest.fixture(scope="module")
def browser():
    reason = _missing()
    if reason:
        if os.environ.get("PARAMRES_REQUIRE_BROWSER") == "1":
            pytest.fail(f"PARAMRES_REQUIRE_BROWSER=1 but {reason}")
        pytest.skip(reason)
    from playwright.sync_api import sync_playwright

    with sync_playwright() as p:
        b = p.chromium.launch(executable_path=CHROMIUM, args=ARGS)
        yield b
        b.close()


@pytest.fixture(scope="module")
def server():
    """The explorer as a user starts it: a process of its own (``paramres explore``).  A server
    thread in this process would compute while the page's requests are still in flight after a
    test has ended, and mpmath's working precision is process-wide."""
    from reports.explorer import explore

    app = explore(port=0)
    yield app
    app.stop()


@pytest.fixture(scope="module")
def page(browser, server):
    page = browser.new_page(viewport={"width": 1400, "height": 1000})
    page.problems = []
    page.on(
        "console",
        lambda m: page.problems.append(m.text) if m.type in ("error", "warning") else None,
    )
    page.on("pageerror", lambda e: page.problems.append(str(e)))
    page.set_default_timeout(WAIT)
    page.goto(server.url)
    page.wait_for_function("() => window.paramresApp && window.paramresApp.chart && "
                           "window.paramresApp.chart.lower")  # fmt: skip
    yield page
    page.close()


def api(server, path: str) -> dict:
    with urllib.request.urlopen(server.url + path, timeout=WAIT / 1000) as r:
        return json.loads(r.read())


def draws(page) -> int:
    return int(page.get_attribute("[data-testid=chart]", "data-draws"))


def click_at(page, T: float, m: float) -> None:
    """Click the chart where ``(T, m)`` is drawn."""
    x, y = page.evaluate(
        """([T, m]) => {
            const c = document.querySelector('[data-testid=chart]');
            const r = c.getBoundingClientRect();
            const p = window.paramresApp.pixelOf(T, m);
            return [r.left + p[0] * r.width / c.width, r.top + p[1] * r.height / c.height];
        }""",
        [T, m],
    )
    page.mouse.click(x, y)


def test_the_page_loads_and_draws_the_chart(page, tmp_path_factory):
    assert page.problems == []
    # the canvas holds the colour map: many colours, not one
    colours = page.evaluate(
        """() => {
            const c = document.querySelector('[data-testid=chart]');
            const d = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
            const seen = new Set();
            for (let i = 0; i < d.length; i += 4 * 97) seen.add(d[i] + ',' + d[i+1] + ',' + d[i+2]);
            return seen.size;
        }"""
    )
    assert colours > 50
    where = Path(os.environ.get("PARAMRES_SCREENSHOT_DIR") or tmp_path_factory.mktemp("shots"))
    shot = where / "explorer-chart.png"
    page.locator("[data-testid=chart]").screenshot(path=str(shot))
    import matplotlib.image

    pixels = matplotlib.image.imread(str(shot))
    assert pixels.std() > 0.1, "the screenshot of the chart is blank"


def test_a_click_shows_the_certified_values_of_the_api(page, server):
    click_at(page, 1.45, 0.3)
    page.wait_for_function(
        "() => document.querySelector('[data-testid=point-status]').textContent.includes('ms')"
    )
    T = page.get_attribute("[data-testid=point]", "data-t")
    m = page.get_attribute("[data-testid=point]", "data-m")
    assert abs(float(T) - 1.45) < 0.01 and abs(float(m) - 0.3) < 0.01
    mu = api(server, f"api/multipliers?T={T}&m={m}&digits=30")
    text = lambda tid: page.inner_text(f"[data-testid={tid}]").strip()  # noqa: E731
    assert text("mu-max") == mu["max_modulus"]
    assert text("growth") == mu["growth_rate"]
    # one bound row for mu1, mu2, |mu|max and ln|mu|max: the largest of their bounds
    bounds = [mu["max_modulus_error_bound"], mu["growth_rate_error_bound"]]
    bounds += [x["error_bound"] for x in mu["multipliers"]]
    assert text("mu-bound").split()[-1] == max(bounds, key=float)
    assert text("mu1") == mu["multipliers"][0]["re"]
    # (1.45, 0.3) lies inside the third interval (/api/boundary: [1.3411..., 1.5447...])
    assert text("order") == "3"
    b = api(server, f"api/boundary?order=3&m={m}&digits=30")
    assert (text("edge-lower"), text("edge-upper")) == (b["lower"], b["upper"])
    assert b["error_bound"] in text("edge-bound")
    assert page.problems == []


def test_the_bound_shown_covers_the_multipliers_at_a_stable_point(page, server):
    """At a stable point ``|mu| = 1`` is known far better than the digits of ``mu1`` and ``mu2``;
    the one bound row under the four numbers must be the largest of their bounds."""
    page.evaluate("() => window.paramresApp.examine('0.7', '0.3')")
    assert page.get_attribute("[data-testid=point]", "data-t") == "0.7"
    mu = api(server, "api/multipliers?T=0.7&m=0.3&digits=30")
    assert not mu["real"]
    bounds = [mu["max_modulus_error_bound"], mu["growth_rate_error_bound"]]
    bounds += [x["error_bound"] for x in mu["multipliers"]]
    worst = max(bounds, key=float)
    assert float(worst) > float(mu["max_modulus_error_bound"])  # the case this test is about
    assert page.inner_text("[data-testid=mu-bound]").strip().split()[-1] == worst
    assert page.problems == []


def test_a_phone_screen_needs_no_sideways_scrolling(browser, server):
    phone = browser.new_page(viewport={"width": 390, "height": 844})
    try:
        phone.set_default_timeout(WAIT)
        phone.goto(server.url)
        phone.wait_for_function("() => window.paramresApp && window.paramresApp.chart")
        width = phone.evaluate("() => document.documentElement.scrollWidth")
        assert width <= 390, f"the page is {width} px wide on a 390 px screen"
    finally:
        phone.close()


def test_moving_a_control_redraws_the_chart(page):
    before = draws(page)
    page.fill("[data-testid=max-order]", "3")
    page.dispatch_event("[data-testid=max-order]", "input")
    page.wait_for_function(
        "n => Number(document.querySelector('[data-testid=chart]').dataset.draws) > n && "
        "window.paramresApp.chart.orders && window.paramresApp.chart.orders.length === 3",
        arg=before,
    )
    before = draws(page)
    page.fill("[data-testid=Q]", "5")
    page.dispatch_event("[data-testid=Q]", "change")
    page.wait_for_function(
        "n => Number(document.querySelector('[data-testid=chart]').dataset.draws) > n + 1 && "
        "window.paramresApp.chart.Q === 5",
        arg=before,
    )
    assert page.problems == []


def test_a_preset_works(page, server):
    page.select_option("[data-testid=preset]", "closing")
    page.wait_for_function(
        "() => document.querySelector('[data-testid=point]').dataset.m === '3/5' && "
        "document.querySelector('[data-testid=point-status]').textContent.includes('ms')"
    )
    assert page.input_value("[data-testid=Q]") == ""
    # the third interval closes at m = 3/5: both certified edges are the same number
    lower = page.inner_text("[data-testid=edge-lower]").strip()
    assert lower == page.inner_text("[data-testid=edge-upper]").strip()
    assert lower == api(server, "api/boundary?order=3&m=3/5&digits=30")["lower"]
    assert page.inner_text("[data-testid=order]").strip() == "3"


def test_the_animation_runs(page):
    page.wait_for_function("() => window.paramresApp.run !== null")
    f0 = int(page.get_attribute("[data-testid=pendulum]", "data-frame"))
    t0 = page.get_attribute("[data-testid=pendulum]", "data-t")
    img0 = page.locator("[data-testid=pendulum]").screenshot()
    page.wait_for_function(
        "n => Number(document.querySelector('[data-testid=pendulum]').dataset.frame) > n + 5",
        arg=f0,
    )
    assert page.get_attribute("[data-testid=pendulum]", "data-t") != t0
    page.wait_for_timeout(300)
    assert page.locator("[data-testid=pendulum]").screenshot() != img0


def test_the_generated_propagator_is_the_equation_of_motion(page):
    """The generated free-oscillation map against ``expm(t [[0, 1], [-w^2, -2 g]])`` (mpmath,
    40 digits): the exact solution of ``phi'' + 2 g phi' + w^2 phi = 0`` over a time ``t``;
    under-, critically and over-damped, and without friction.  The paper's model is not the
    equation of motion: it is compared with the same sympy form lambdified by mpmath."""
    cases = [  # (key, t, w, g)
        ("none/under", 0.37, 5.1, 0.0),
        ("exact/under", 0.61, 6.3, 0.45),
        ("exact/critical", 0.52, 1.7, 1.7),
        ("exact/over", 0.44, 1.2, 2.9),
    ]
    page.wait_for_function("() => window.PARAMRES_GEN")
    for key, t, w, g in cases:
        js = page.evaluate(
            """([key, t, w, g]) => {
                const G = window.PARAMRES_GEN;
                const W = key === 'exact/under' ? G.Omega(w, g) : 0;
                const L = key === 'exact/over' ? G.Lambda(w, g) : 0;
                return G.propagator[key](t, w, g, W, L);
            }""",
            [key, t, w, g],
        )
        with mpmath.workdps(40):
            A = mpmath.matrix([[0, 1], [-(mpmath.mpf(w) ** 2), -2 * mpmath.mpf(g)]])
            U = mpmath.expm(A * t)
            ref = [float(U[0, 0]), float(U[0, 1]), float(U[1, 0]), float(U[1, 1])]
        scale = max(abs(x) for x in ref)
        for a, b in zip(js, ref, strict=True):
            assert abs(a - b) <= 1e-13 * scale, (key, js, ref)

    from verify.propagation import _propagator

    f = _propagator("paper", "under", 1, "mpmath")
    t, w, g = 0.61, 6.3, 0.45
    js = page.evaluate(
        "([t, w, g]) => window.PARAMRES_GEN.propagator['paper/under'](t, w, g, 0, 0)", [t, w, g]
    )
    with mpmath.workdps(30):
        ref = [float(e(t, w, g, 0, 0)) for e in f]
    assert all(abs(a - b) <= 1e-14 for a, b in zip(js, ref, strict=True)), (js, ref)

    from fractions import Fraction

    from analytic.system import LAWS

    for name, law in LAWS.items():
        got = page.evaluate(
            "n => { const L = window.PARAMRES_GEN.laws[n]; "
            "return [L.omega1_sq(0.3), L.omega2_sq(0.3), L.jump(0.3)]; }",
            name,
        )
        exact = [float(f(Fraction(3, 10))) for f in (law.omega1_sq, law.omega2_sq, law.jump)]
        assert got == pytest.approx(exact, rel=1e-15), name


def test_the_motion_between_samples_agrees_with_the_server(page, server):
    """The page's state at each sample time of the server's run (the generated propagator from
    the start of the phase) is the server's sample (verify.timedomain, closed-form segments)."""
    worst = page.evaluate(
        """() => {
            const run = window.paramresApp.run;
            let worst = 0, amax = run.amax;
            run.doc.segments.forEach((s) => s.t.forEach((t, k) => {
                const st = window.paramresApp.stateAt(t);
                worst = Math.max(worst, Math.abs(st[0] - s.phi[k]) / amax);
            }));
            return [worst, run.doc.segments.length, run.doc.nonlinear];
        }"""
    )
    assert worst[1] >= 6 and worst[2] is False
    assert worst[0] < 1e-11, worst  # the samples are sent with 15 significant digits


def test_the_page_speaks_russian(page):
    page.click("[data-testid=lang-ru]")
    assert page.inner_text("h1").strip() == "Области параметрического возбуждения"
    page.click("[data-testid=lang-en]")
    assert page.inner_text("h1").strip() == "Regions of parametric excitation"


def test_the_screenshot_for_the_readme(page, tmp_path_factory):
    page.select_option("[data-testid=preset]", "fig2")
    page.wait_for_function(
        "() => document.querySelector('[data-testid=point]').dataset.t === '1.45' && "
        "document.querySelector('[data-testid=point-status]').textContent.includes('ms') && "
        "window.paramresApp.chart.lower && window.paramresApp.run"
    )
    page.wait_for_timeout(2500)  # let the pendulum swing a while
    where = Path(os.environ.get("PARAMRES_SCREENSHOT_DIR") or tmp_path_factory.mktemp("shots"))
    page.screenshot(path=str(where / "explorer.png"), full_page=True)
    assert (where / "explorer.png").stat().st_size > 20_000
    assert page.problems == []


def test_the_static_export_draws_and_moves(browser, tmp_path):
    import paramres
    from reports.explorer.export import export

    site = export(tmp_path / "site", presets=["fig2"])
    handler = functools.partial(http.server.SimpleHTTPRequestHandler, directory=str(site))
    handler.log_message = lambda *a: None
    httpd = http.server.ThreadingHTTPServer(("127.0.0.1", 0), handler)
    threading.Thread(target=httpd.serve_forever, daemon=True).start()
    page = browser.new_page(viewport={"width": 1400, "height": 1000})
    problems = []
    page.on("pageerror", lambda e: problems.append(str(e)))
    page.on("console", lambda m: problems.append(m.text) if m.type == "error" else None)
    try:
        page.set_default_timeout(WAIT)
        page.goto(f"http://127.0.0.1:{httpd.server_address[1]}/")
        page.wait_for_function("() => window.paramresApp.chart && window.paramresApp.chart.lower")
        click_at(page, 1.45, 0.3)
        page.wait_for_function("() => window.paramresApp.run !== null")
        T = page.get_attribute("[data-testid=point]", "data-t")
        m = page.get_attribute("[data-testid=point]", "data-m")
        shown = float(page.inner_text("[data-testid=mu-max]"))
        # the page's double-precision monodromy against the certified |mu|max
        ref = float(paramres.multipliers(T, m, digits=20).as_json()["max_modulus"])
        assert shown == pytest.approx(ref, rel=1e-9)
        assert problems == []
    finally:
        page.close()
        httpd.shutdown()
        httpd.server_close()


# ---------------------------------------------------------------- what a failed request leaves
#: the result cells of the readout: none may show a number left over from an earlier input
RESULTS = ["mu1", "mu2", "mu-max", "growth", "mu-bound", "edge-lower", "edge-upper", "edge-bound"]


@pytest.fixture
def fresh(browser, server):
    """A page of its own (a test of this group changes the controls or intercepts requests)."""
    page = browser.new_page(viewport={"width": 1400, "height": 1000})
    page.set_default_timeout(WAIT)
    page.goto(server.url)
    page.wait_for_function("() => window.paramresApp && window.paramresApp.chart && "
                           "window.paramresApp.chart.lower")  # fmt: skip
    page.evaluate("() => window.paramresApp.examine('1.45', '0.3')")
    page.wait_for_function("() => window.paramresApp.run !== null")
    yield page
    page.unroute_all(behavior="ignoreErrors")
    page.close()


#: the results of each panel (not its controls, legend or status line)
SHOWN = {
    "chart-panel": "[data-testid=chart]",
    "readout": "table.values, .verdict",
    "motion": "[data-testid=pendulum], [data-testid=plot-phi], [data-testid=plot-phase]",
}


#: how a panel looks: its state, its note (if shown) and the largest opacity of its results (as
#: drawn: the product of the opacities of the element and its parents)
LOOK = """([tid, results]) => {
            const p = document.querySelector(`[data-testid=${tid}]`);
            const note = p.querySelector('.stale-note');
            const look = note && getComputedStyle(note);
            const shown = note && look.visibility === 'visible' && Number(look.opacity) > 0.9 &&
                note.textContent.trim();
            const faded = [...p.querySelectorAll(results)].map((el) => {
                let o = 1;
                for (let e = el; e; e = e.parentElement) o *= Number(getComputedStyle(e).opacity);
                return o;
            });
            return {state: p.dataset.state || '', note: shown || '', opacity: Math.max(...faded)};
        }"""


def panel(page, testid: str, settle: str | None = None) -> dict:
    """How the panel ``testid`` looks; with ``settle``, once it has taken that state and its
    fading has ended: greyed and labelled ('pending', 'failed'), or plain ('')."""
    if settle is not None:
        page.wait_for_function(
            f"""([tid, results, want]) => {{
                const look = ({LOOK})([tid, results]);
                if (look.state !== want) return false;
                return want ? look.note && look.opacity <= 0.5 : !look.note && look.opacity === 1;
            }}""",
            arg=[testid, SHOWN[testid], settle],
        )
    return page.evaluate(LOOK, [testid, SHOWN[testid]])


def readout_numbers(page) -> list[str]:
    return [
        page.inner_text(f"[data-testid={tid}]").strip()
        for tid in RESULTS
        if any(c.isdigit() for c in page.inner_text(f"[data-testid={tid}]"))
    ]


def change(page, testid: str, value: str) -> None:
    page.fill(f"[data-testid={testid}]", value)
    page.dispatch_event(f"[data-testid={testid}]", "change")


def settled(page, *testids: str) -> None:
    """Wait until the status lines of these panels show an answer or an error (not computing)."""
    page.wait_for_function(
        """(ids) => ids.every((id) => {
            const s = document.querySelector(`[data-testid=${id}]`);
            return s.classList.contains('error') || (s.textContent && !s.textContent.includes('…'));
        })""",
        arg=list(testids),
    )


def test_a_refused_point_leaves_no_old_numbers_on_the_page(fresh):
    """Digits 500 (over the cap): /api/point answers 400.  The numbers of the point before must
    not stay beside the error as if they answered the new input."""
    assert readout_numbers(fresh)  # the answer for digits = 30
    change(fresh, "digits", "500")
    fresh.wait_for_function(
        "() => document.querySelector('[data-testid=point-status]').classList.contains('error')"
    )
    assert "digits" in fresh.inner_text("[data-testid=point-status]")
    assert readout_numbers(fresh) == [], "the readout still shows the previous answer"
    look = panel(fresh, "readout", settle="failed")
    assert look["state"] == "failed" and look["note"], look
    # the chart does not depend on the digits: it is the current one
    assert panel(fresh, "chart-panel")["state"] == ""
    # a valid input brings the numbers back and the note goes
    change(fresh, "digits", "30")
    fresh.wait_for_function(
        "() => document.querySelector('[data-testid=point-status]').textContent.includes('ms')"
    )
    assert len(readout_numbers(fresh)) == len(RESULTS)
    look = panel(fresh, "readout", settle="")
    assert look == {"state": "", "note": "", "opacity": 1}, look


def test_a_bad_duty_marks_every_panel(fresh):
    """Duty 'abc': the chart, the point and the run all get 400; the old chart is greyed and
    labelled, the old numbers and the old motion are cleared."""
    change(fresh, "duty", "abc")
    fresh.wait_for_function(
        "() => ['chart-status', 'point-status', 'motion-status'].every((id) => "
        "document.querySelector(`[data-testid=${id}]`).classList.contains('error'))"
    )
    chart = panel(fresh, "chart-panel", settle="failed")
    assert chart["state"] == "failed" and chart["note"] and chart["opacity"] <= 0.5, chart
    assert readout_numbers(fresh) == []
    assert panel(fresh, "readout")["state"] == "failed"
    motion = panel(fresh, "motion", settle="failed")
    assert motion["state"] == "failed" and motion["note"], motion
    assert fresh.evaluate("() => window.paramresApp.run") is None
    change(fresh, "duty", "1/2")
    settled(fresh, "chart-status", "point-status", "motion-status")
    fresh.wait_for_function("() => window.paramresApp.run !== null")
    for tid in ("chart-panel", "readout", "motion"):
        assert panel(fresh, tid, settle="") == {"state": "", "note": "", "opacity": 1}, tid
    assert len(readout_numbers(fresh)) == len(RESULTS)


def test_a_pending_request_greys_and_labels_the_old_results(fresh):
    """While the answer for a new click is on its way, the answer for the old click is greyed
    and labelled; when the answer comes it is shown as it is."""
    held = []
    fresh.route("**/api/point?*", lambda route: held.append(route))
    fresh.route("**/api/simulate?*", lambda route: held.append(route))
    click_at(fresh, 2.5, 0.2)
    fresh.wait_for_function("() => document.querySelector('[data-testid=point]').dataset.t !== "
                            "'1.45'")  # fmt: skip
    for tid in ("readout", "motion"):
        look = panel(fresh, tid, settle="pending")  # the fading starts after a short delay
        assert look["state"] == "pending" and look["note"] and look["opacity"] <= 0.5, (tid, look)
    assert len(held) == 2
    # the status line under the motion does not describe the old run as if it were the new one
    assert "measured" not in fresh.inner_text("[data-testid=motion-status]")
    for route in held:
        route.continue_()
    fresh.unroute_all(behavior="ignoreErrors")
    fresh.wait_for_function(
        "() => document.querySelector('[data-testid=point-status]').textContent.includes('ms')"
    )
    for tid in ("readout", "motion"):
        assert panel(fresh, tid, settle="") == {"state": "", "note": "", "opacity": 1}, tid
    assert fresh.inner_text("[data-testid=order]").strip() == "5"


@pytest.mark.parametrize("how", ["timeout", "network"])
def test_a_chart_that_does_not_come_is_marked(fresh, how):
    """The server's time cap (503) or no answer at all: the chart drawn before is greyed and
    labelled, not left as if it were the new one."""

    def refuse(route):
        if how == "network":
            return route.abort()
        body = json.dumps({"error": "the computation took longer than 30 s; try fewer orders"})
        route.fulfill(status=503, content_type="application/json", body=body)

    fresh.route("**/api/chart?*", refuse)
    change(fresh, "Q", "7")
    fresh.wait_for_function(
        "() => document.querySelector('[data-testid=chart-status]').classList.contains('error')"
    )
    chart = panel(fresh, "chart-panel", settle="failed")
    assert chart["state"] == "failed" and chart["note"] and chart["opacity"] <= 0.5, chart
    fresh.unroute_all(behavior="ignoreErrors")
    change(fresh, "Q", "8")
    fresh.wait_for_function("() => window.paramresApp.chart.Q === 8 && "
                            "window.paramresApp.chart.lower")  # fmt: skip
    settled(fresh, "chart-status")
    assert panel(fresh, "chart-panel", settle="") == {"state": "", "note": "", "opacity": 1}


# ---------------------------------------------------------------- the chart's lettering
#: records every text drawn on the chart canvas: its box and its font size in CSS pixels
RECORD_TEXT = """
(() => {
  const fill = CanvasRenderingContext2D.prototype.fillText;
  window.chartTexts = [];
  CanvasRenderingContext2D.prototype.fillText = function (text, x, y, ...rest) {
    const c = this.canvas;
    if (c.id === 'chart' && c.clientWidth) {
      const k = c.clientWidth / c.width;  // canvas pixels -> CSS pixels
      const M = this.getTransform();
      const m = this.measureText(text);
      const corners = [[x - m.actualBoundingBoxLeft, y - m.actualBoundingBoxAscent],
        [x + m.actualBoundingBoxRight, y - m.actualBoundingBoxAscent],
        [x - m.actualBoundingBoxLeft, y + m.actualBoundingBoxDescent],
        [x + m.actualBoundingBoxRight, y + m.actualBoundingBoxDescent]]
        .map(([a, b]) => M.transformPoint(new DOMPoint(a, b)));
      const xs = corners.map((p) => p.x * k), ys = corners.map((p) => p.y * k);
      const px = Number((/([0-9.]+)px/.exec(this.font) || [0, 0])[1]);
      window.chartTexts.push({
        text: String(text), draw: Number(c.dataset.draws || 0),
        size: px * Math.hypot(M.a, M.b) * k,
        box: [Math.min(...xs), Math.min(...ys), Math.max(...xs), Math.max(...ys)],
        width: c.clientWidth, height: c.clientHeight,
      });
    }
    return fill.call(this, text, x, y, ...rest);
  };
})();
"""


@pytest.mark.parametrize(
    "viewport, scale",
    [({"width": 1400, "height": 1000}, 1), ({"width": 390, "height": 844}, 3)],
    ids=["desktop", "phone"],
)
def test_the_chart_lettering_is_readable_and_does_not_overlap(browser, server, viewport, scale):
    """Every label of the chart (ticks, axis names, orders) at least 11 CSS pixels high as a
    font, inside the canvas, and no two overlapping: on a desktop and on a phone (390 x 844 CSS
    pixels, 3 device pixels each), where the chart is drawn narrower than its 760 pixels."""
    context = browser.new_context(viewport=viewport, device_scale_factor=scale)
    page = context.new_page()
    try:
        page.add_init_script(RECORD_TEXT)
        page.set_default_timeout(WAIT)
        page.goto(server.url)
        page.wait_for_function("() => window.paramresApp && window.paramresApp.chart && "
                               "window.paramresApp.chart.lower")  # fmt: skip
        page.wait_for_timeout(300)
        texts = page.evaluate("() => window.chartTexts")
        last = max(t["draw"] for t in texts)
        texts = [t for t in texts if t["draw"] == last]
        labels = {t["text"] for t in texts}
        assert {"0.5", "3.0", "0.1", "0.9", "T / T₀", "1", "6"} <= labels, labels
        small = [(t["text"], round(t["size"], 1)) for t in texts if t["size"] < 11]
        assert not small, f"labels smaller than 11 CSS px: {small}"
        for t in texts:
            x0, y0, x1, y1 = t["box"]
            assert x0 >= -0.5 and y0 >= -0.5, t
            assert x1 <= t["width"] + 0.5 and y1 <= t["height"] + 0.5, t
        for i, a in enumerate(texts):
            for b in texts[i + 1 :]:
                apart = (
                    a["box"][2] <= b["box"][0] + 0.5
                    or b["box"][2] <= a["box"][0] + 0.5
                    or a["box"][3] <= b["box"][1] + 0.5
                    or b["box"][3] <= a["box"][1] + 0.5
                )
                assert apart, (a, b)
    finally:
        context.close()


# ---------------------------------------------------------------- the engine's notes, the language
def point_settled(page, T: str) -> None:
    """Wait until the readout shows the answer for a point at ``T`` (or an error)."""
    page.wait_for_function(
        """(T) => {
            const w = document.querySelector('[data-testid=point]');
            const s = document.querySelector('[data-testid=point-status]');
            return w.dataset.t === T && !s.textContent.includes('…') && s.textContent !== '';
        }""",
        arg=T,
    )


def notes_shown(page, testid: str) -> list[str]:
    """The notes of a result as the page shows them (label and text), none if hidden."""
    return page.evaluate(
        """(tid) => {
            const box = document.querySelector(`[data-testid=${tid}]`);
            if (box.hidden || !box.offsetHeight) return [];
            return [...box.querySelectorAll('p')].map((p) => [
                p.querySelector('.label').textContent, p.querySelector('[lang=en]').textContent]);
        }""",
        testid,
    )


def test_the_engine_notes_are_shown_under_the_values_they_explain(fresh, server):
    """A stable point without friction: the engine says ln|mu|max = 0 exactly; at a closing
    (Meissner, m = 24/25, T = 5: M = I) the digits are fewer than asked and a note says why; with
    ramps both the multipliers and the edges carry notes.  Each note is shown under its panel's
    values, as the engine wrote it, with a label in the page's language; a point without notes
    leaves none behind."""
    cases = [
        ({"system": "pendulum"}, "0.7", "0.3"),
        ({"system": "meissner"}, "5", "24/25"),
        ({"system": "pendulum", "modulation": "ramp"}, "1.45", "0.3"),
    ]
    for controls, T, m in cases:
        for tid, value in controls.items():
            fresh.select_option(f"[data-testid={tid}]", value)
            fresh.dispatch_event(f"[data-testid={tid}]", "change")
        fresh.wait_for_timeout(300)
        settled(fresh, "chart-status")
        fresh.evaluate("([T, m]) => window.paramresApp.examine(T, m)", [T, m])
        point_settled(fresh, T)
        q = f"T={T}&m={m}&system={controls['system']}"
        if "modulation" in controls:
            q += "&modulation=ramp&switch_time=0.02"
        doc = api(server, "/api/point?" + q.replace("/", "%2F"))
        want_mu, want_edge = doc["multipliers"]["notes"], doc["boundary"]["notes"]
        assert want_mu, (T, m)  # each case has notes to show
        assert notes_shown(fresh, "mu-notes") == [["note:", n] for n in want_mu], (T, m)
        assert notes_shown(fresh, "edge-notes") == [["note:", n] for n in want_edge], (T, m)
        if T == "5":  # the closing: the note on the digits printed
            assert any("fewer digits" in n for _, n in notes_shown(fresh, "mu-notes"))
    assert notes_shown(fresh, "edge-notes")  # the ramp's edges have theirs
    # in Russian the label is translated, the engine's words are not
    fresh.click("[data-testid=lang-ru]")
    shown = notes_shown(fresh, "mu-notes")
    assert shown and all(label == "примечание:" and "ramp" in text for label, text in shown)
    fresh.click("[data-testid=lang-en]")
    # a point without notes clears those of the point before
    fresh.select_option("[data-testid=modulation]", "square")
    fresh.dispatch_event("[data-testid=modulation]", "change")
    fresh.wait_for_timeout(300)
    settled(fresh, "chart-status")
    fresh.evaluate("() => window.paramresApp.examine('2.5', '0.2')")
    point_settled(fresh, "2.5")
    assert notes_shown(fresh, "mu-notes") == [] and notes_shown(fresh, "edge-notes") == []
    # a failed request clears them too
    fresh.evaluate("() => window.paramresApp.examine('0.7', '0.3')")
    point_settled(fresh, "0.7")
    assert notes_shown(fresh, "mu-notes")
    change(fresh, "digits", "500")
    fresh.wait_for_function(
        "() => document.querySelector('[data-testid=point-status]').classList.contains('error')"
    )
    assert notes_shown(fresh, "mu-notes") == []


def test_the_notes_of_a_run_are_shown(fresh):
    """A run whose answer carries notes shows them under the motion (the label translated)."""

    def with_note(route):
        response = route.fetch()
        doc = response.json()
        doc["notes"] = ["a note on the run"]
        route.fulfill(response=response, json=doc)

    fresh.route("**/api/simulate?*", with_note)
    fresh.evaluate("() => window.paramresApp.examine('2.5', '0.2')")
    fresh.wait_for_function("() => window.paramresApp.run && window.paramresApp.run.doc.notes")
    assert notes_shown(fresh, "motion-notes") == [["note:", "a note on the run"]]
    fresh.click("[data-testid=lang-ru]")
    assert notes_shown(fresh, "motion-notes") == [["примечание:", "a note on the run"]]
    fresh.click("[data-testid=lang-en]")


def test_the_status_lines_follow_the_language(fresh):
    """The status lines under the chart, the readout and the motion are said again in Russian
    when the language changes, those of a finished answer and 'computing…' alike."""
    point_settled(fresh, "1.45")
    settled(fresh, "chart-status", "motion-status")
    fresh.click("[data-testid=lang-ru]")
    chart = fresh.inner_text("[data-testid=chart-status]")
    point = fresh.inner_text("[data-testid=point-status]")
    motion = fresh.inner_text("[data-testid=motion-status]")
    assert chart.startswith("диаграмма построена · маятник"), chart
    assert "шаровая арифметика" in point and "ball" not in point and " мс" in point, point
    assert "периодов" in motion and "measured" not in motion, motion
    assert fresh.inner_text("[data-testid=point]").startswith("T/T0 = 1.45")
    assert fresh.get_attribute("[data-testid=Q]", "placeholder") == "нет"
    fresh.click("[data-testid=lang-en]")
    assert "ball arithmetic" in fresh.inner_text("[data-testid=point-status]")
    # a request on its way: 'computing…' in one language, then in the other
    held = []
    fresh.route("**/api/point?*", lambda route: held.append(route))
    fresh.evaluate("() => { window.paramresApp.examine('2.5', '0.2'); }")
    fresh.wait_for_function("() => document.querySelector('[data-testid=point]').dataset.t === "
                            "'2.5'")  # fmt: skip
    assert fresh.inner_text("[data-testid=point-status]") == "computing…"
    fresh.click("[data-testid=lang-ru]")
    assert fresh.inner_text("[data-testid=point-status]") == "вычисляю…"
    fresh.click("[data-testid=lang-en]")
    for route in held:
        route.continue_()


def test_the_first_words_of_the_page_are_the_scripts(browser, server):
    """Every text the script writes in English (data-i18n) is the text the page has before the
    script runs: no label changes under the reader's eyes (the legend said 'certified-grade
    edges' until the script wrote 'edges')."""
    texts = "() => [...document.querySelectorAll('[data-i18n]')].map((e) => [e.dataset.i18n, " \
            "e.textContent.trim()])"  # fmt: skip
    bare = browser.new_context(java_script_enabled=False)
    live = browser.new_page()
    try:
        page = bare.new_page()
        page.goto(server.url)
        before = [
            [el.get_attribute("data-i18n"), el.text_content().strip()]
            for el in page.query_selector_all("[data-i18n]")
        ]
        live.set_default_timeout(WAIT)
        live.goto(server.url)
        live.wait_for_function("() => window.paramresApp && window.paramresApp.chart")
        after = live.evaluate(texts)
        assert len(before) == len(after) > 20
        assert [a for a, b in zip(before, after, strict=True) if a != b] == []
    finally:
        bare.close()
        live.close()


def test_a_failed_readout_lays_its_note_over_nothing(fresh):
    """A failed readout (digits over the cap): its note takes a line of its own, above the cleared
    rows; it covers no row, heading or verdict of the readout."""
    change(fresh, "digits", "500")
    fresh.wait_for_function(
        "() => document.querySelector('[data-testid=point-status]').classList.contains('error')"
    )
    panel(fresh, "readout", settle="failed")
    overlaps = fresh.evaluate(
        """() => {
            const r = document.querySelector('[data-testid=readout]');
            const box = r.querySelector('.stale-note').getBoundingClientRect();
            return [...r.querySelectorAll('tr, h2, .verdict, .where, .status')].filter((el) => {
                const b = el.getBoundingClientRect();
                return b.height && box.left < b.right && b.left < box.right &&
                    box.top < b.bottom && b.top < box.bottom;
            }).map((el) => el.textContent.trim());
        }"""
    )
    assert overlaps == []
