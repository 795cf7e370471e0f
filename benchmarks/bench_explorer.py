"""The explorer's speed: start, first paint, a click, a redraw (a benchmark, not a test).

    python benchmarks/bench_explorer.py [--repeat R] [--json]

Each repeat starts ``paramres explore --no-browser --port 0`` in a fresh process and drives the
page in headless Chromium (Playwright, ``/usr/bin/chromium``).  Measured:

* **start**: from launching the process to the first answer of ``/`` (the address printed and
  the page served);
* **first paint**: from asking for the page to the chart's colour map on the canvas, and to the
  edges drawn over it;
* **click** (after the server's warm-up): from a click on the chart to the certified multipliers
  and edges shown;
* **redraw** (after the warm-up): from moving a control (the number of orders) to the chart
  drawn again.

The floors (the issue's targets) are written below; each line reports the median time and its
ratio to the floor (< 1 meets it).
"""

from __future__ import annotations

import argparse
import json
import os
import statistics
import subprocess
import sys
import time
import urllib.request
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
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

#: the targets, seconds
FLOORS = {
    "start": 2.0,
    "first paint (colour map)": 2.0,
    "first paint (edges too)": 2.0,
    "click (certified values shown)": 0.3,
    "redraw after a control": 1.0,
    "warm-up done (from start)": None,
}


def one_run(browser) -> dict[str, float]:
    out: dict[str, float] = {}
    t0 = time.perf_counter()
    proc = subprocess.Popen(
        [sys.executable, "-m", "paramres", "explore", "--no-browser", "--port", "0"],
        stdout=subprocess.PIPE,
        stderr=subprocess.DEVNULL,
        text=True,
        cwd=ROOT,
        env={**os.environ, "PYTHONPATH": str(ROOT)},
    )
    try:
        line = proc.stdout.readline()
        url = line.split()[2]
        while True:
            try:
                urllib.request.urlopen(url, timeout=5).read()
                break
            except OSError:
                time.sleep(0.01)
        out["start"] = time.perf_counter() - t0

        page = browser.new_page(viewport={"width": 1400, "height": 1000})
        page.set_default_timeout(120_000)
        t1 = time.perf_counter()
        page.goto(url)
        page.wait_for_function("() => window.paramresApp && window.paramresApp.chart && "
                               "window.paramresApp.chart.growth", polling=5)  # fmt: skip
        out["first paint (colour map)"] = time.perf_counter() - t1
        page.wait_for_function("() => window.paramresApp.chart.lower", polling=5)
        out["first paint (edges too)"] = time.perf_counter() - t1

        # a click, warm: the server has built the engine's forms once (its warm-up)
        while json.loads(urllib.request.urlopen(url + "api/presets").read())["warming"]:
            time.sleep(0.1)
        out["warm-up done (from start)"] = time.perf_counter() - t0
        clicks = []
        for T, m in ((0.5, 0.3), (1.45, 0.3), (1.0, 0.5), (2.0, 0.25)):
            clicks.append(
                page.evaluate(
                    """async ([T, m]) => {
                        const el = document.querySelector('[data-testid=point-status]');
                        el.textContent = '';
                        const t = performance.now();
                        const done = window.paramresApp.examine(String(T), String(m));
                        while (!el.textContent.includes('ms'))
                            await new Promise(r => setTimeout(r, 2));
                        const dt = performance.now() - t;
                        await done;
                        return dt / 1000;
                    }""",
                    [T, m],
                )
            )
        out["click (certified values shown)"] = statistics.median(clicks)

        before = int(page.get_attribute("[data-testid=chart]", "data-draws"))
        t2 = time.perf_counter()
        page.fill("[data-testid=max-order]", "4")
        page.dispatch_event("[data-testid=max-order]", "input")
        page.wait_for_function(
            "n => Number(document.querySelector('[data-testid=chart]').dataset.draws) >= n + 2",
            arg=before,
            polling=5,
        )
        out["redraw after a control"] = time.perf_counter() - t2
        page.close()
    finally:
        proc.terminate()
        proc.wait(10)
    return out


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--json", action="store_true")
    args = ap.parse_args(argv)
    from playwright.sync_api import sync_playwright

    with sync_playwright() as p:
        browser = p.chromium.launch(executable_path=CHROMIUM, args=ARGS)
        runs = [one_run(browser) for _ in range(args.repeat)]
        browser.close()
    rows = {}
    for k, f in FLOORS.items():
        med = statistics.median(r[k] for r in runs)
        rows[k] = {"median_s": med, "floor_s": f, "ratio": None if f is None else med / f}
    if args.json:
        print(json.dumps(rows, indent=2))
    else:
        for k, row in rows.items():
            tail = (
                ""
                if row["floor_s"] is None
                else (f"   floor {row['floor_s'] * 1000:5.0f} ms   ratio {row['ratio']:.2f}")
            )
            print(f"{k:34s} {row['median_s'] * 1000:8.0f} ms{tail}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
