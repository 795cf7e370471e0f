"""Section 8: speed against error (from the benchmarks, when their results are present) and the
time-domain pictures (from :mod:`reports.timeplots`, runs of :func:`verify.simulate`)."""

from __future__ import annotations

import json
import math
from pathlib import Path

from .. import figures
from ..i18n import say, tr
from ..latex import Latex, figure, paragraph, raw, section, table, text
from . import Context, Part

TITLE = "Speed and the time domain"
LABEL = "sec:performance"
#: not cached as a whole: it reads the benchmark's measurements, which are not code
CACHED = False

#: the paper's time-domain figures redrawn here (numbers of :data:`reports.timeplots.PAPER_SCENES`)
SCENES = (1, 4, 7, 9)
#: where the benchmark writes its measurements (relative to the project root)
#: the benchmark's results: in a source tree ``benchmarks/results.json``; an installed wheel carries
#: a copy as ``paramres/data/bench-results.json`` (see setup.py)
_SOURCE_RESULTS = Path(__file__).resolve().parents[2] / "benchmarks" / "results.json"
_PACKAGED_RESULTS = Path(__file__).resolve().parents[2] / "paramres" / "data" / "bench-results.json"
BENCH_RESULTS = _PACKAGED_RESULTS if _PACKAGED_RESULTS.is_file() else _SOURCE_RESULTS


def _time_domain(ctx: Context) -> tuple[list[Latex], list[tuple[str, bytes]]]:
    head = section("Time-domain pictures", "sec:time-domain", level=1)
    from .. import timeplots

    def make():
        out = {}
        for n in SCENES:
            out[f"paper-fig{n}.pdf"] = figures.pdf_bytes(timeplots.paper_figure(n))
        out["saturation.pdf"] = figures.pdf_bytes(timeplots.saturation_figure())
        return out

    from ..i18n import current

    # the figures carry text in the report's language
    key = "time-domain-figures" if current() == "en" else f"time-domain-figures-{current()}"
    files = ctx.cache.get(key, make)
    blocks = [
        head,
        paragraph(
            "The paper's pictures of stationary oscillations, redrawn from simulations that "
            "follow the "
            "pendulum through the jumps half period by half period (exact piecewise propagation "
            "of the "
            "linear model, started on a certified edge from the stationary initial condition of ",
            raw(r"Section~\ref{sec:stitching}"),
            "). The line above each run states its closure error after one (anti)period: the state "
            "returns to where it started to the working precision, which is the time-domain check "
            "that the edge and the initial condition are right.",
        ),
    ]
    for n in SCENES:
        caption = tr(timeplots.PAPER_SCENES[n].caption)
        caption = caption[:1].lower() + caption[1:]
        blocks.append(
            figure(
                f"figures/paper-fig{n}.pdf",
                raw(
                    say(f"The paper's Fig.~{n} redrawn: ", f"Рис.~{n} статьи, перестроенный: ")
                    + caption
                    + say(
                        r". Left: the phase trajectory; right: $\dot\varphi(t)$ and "
                        r"$\varphi(t)$. Blue: the bob-down half of the period (length "
                        r"$l_0(1+m)$); orange: the bob-up half ($l_0(1-m)$); dashed grey: the "
                        r"jumps of the angular velocity; numbers: the ends of the first "
                        r"segments, in order.",
                        r". Слева: фазовая траектория; справа: $\dot\varphi(t)$ и "
                        r"$\varphi(t)$. Синий: полупериод с опущенным грузом (длина "
                        r"$l_0(1+m)$); оранжевый: с поднятым ($l_0(1-m)$); серый пунктир: "
                        r"скачки угловой скорости; цифры: концы первых отрезков по порядку.",
                    )
                ),
                label=f"fig:time-{n}",
            )
        )
    blocks.append(
        figure(
            "figures/saturation.pdf",
            raw(
                say(
                    r"Growth inside the first interval: the linear model grows without bound, the "
                    r"real pendulum's period lengthens with the amplitude, which detunes it "
                    r"(beats); with friction the beats die out to a steady swing.",
                    r"Рост внутри первого интервала: в линейной модели колебания растут "
                    r"неограниченно, у реального маятника период растёт с амплитудой, что выводит "
                    r"его из резонанса (биения); с трением биения затухают до установившихся "
                    r"колебаний.",
                )
            ),
            label="fig:saturation",
        )
    )
    return blocks, sorted(files.items())


def _sci(x, floor: float = 0.0) -> Latex:
    """``1.2e-05`` as ``1.2 . 10^-5``; at or below ``floor`` (the reference's resolution) as
    ``<= floor``."""
    if x is None:
        return raw("--")
    if float(x) <= floor:
        return raw(f"$\\le 10^{{{round(math.log10(floor))}}}$")
    mant, _, exp = f"{float(x):.1e}".partition("e")
    return raw(f"${mant}\\cdot 10^{{{int(exp)}}}$")


def _speed(ctx: Context) -> tuple[list[Latex], list[tuple[str, bytes]]]:
    """The benchmark's measurements (``benchmarks/results.json``, written by ``paramres bench``):
    the Pareto picture of :mod:`reports.benchplots` and the table of every method."""
    head = section("Speed against error", "sec:speed", level=1)
    if not BENCH_RESULTS.exists():
        return (
            [
                head,
                paragraph(
                    "No benchmark measurements are present in this installation (run",
                    raw(r"\texttt{paramres bench}"),
                    "to produce",
                    raw(r"\texttt{benchmarks/results.json}"),
                    "); the comparison of speed and error appears here once they exist.",
                ),
            ],
            [],
        )
    from .. import benchplots

    data = json.loads(BENCH_RESULTS.read_text(encoding="utf-8"))
    pareto = data.get("pareto", {})
    panels = [
        (title, pareto[key])
        for key, title in (("all", tr("all scenes")), ("small m", "$m \\leq 0.01$"))
        if pareto.get(key)
    ]
    figs = (
        [("speed-pareto.pdf", figures.pdf_bytes(benchplots.pareto_figure(panels)))]
        if panels
        else []
    )
    rows = []
    for item in data.get("methods", []):
        rows.append(
            [
                text(str(item.get("method", ""))),
                text(str(item.get("family", ""))),
                _sci(item.get("seconds")),
                _sci(item.get("error"), benchplots.FLOOR),
                _sci(item.get("error_small_m"), benchplots.FLOOR),
                raw(f"${int(item.get('failures') or 0)}$"),
            ]
        )
    machine = data.get("machine", {})
    where = ", ".join(f"{k} {v}" for k, v in machine.items())
    blocks = [
        head,
        paragraph(
            "Every way the engine offers to compute an edge -- the series, the paper's fixed-point "
            "iteration, double precision per point and on a grid, uncertified mpmath, the "
            "certified "
            "solver, plain root finding on the printed equations and the automatic choice -- "
            "timed on "
            "the same scenes (orders 1 to 6 on a grid of depths, and the hard cases: tiny depth, "
            "depth "
            "near 1, closings, thresholds with friction, order 100) and compared with a certified "
            f"reference of {data.get('reference_digits', '?')} digits",
            raw(r"(Figure~\ref{fig:pareto}, Table~\ref{tab:speed})."),
            text(f"Measured by paramres bench ({where})."),
        ),
    ]
    if figs:
        blocks.append(
            figure(
                "figures/speed-pareto.pdf",
                raw(
                    r"Median CPU time per edge against the largest relative error of $T/T_0$, per "
                    r"method, over all scenes and over the small depths; the methods that no other "
                    r"beats in both are joined (the Pareto front) and labelled."
                ),
                label="fig:pareto",
            )
        )
    if rows:
        blocks.append(
            table(
                [
                    "method",
                    "family",
                    "s per edge",
                    "error (all)",
                    raw(r"error ($m\le 0.01$)"),
                    "failures",
                ],
                rows,
                columns="llrrrr",
                caption="Speed against error of every method (from the benchmark).",
                label="tab:speed",
                long=True,
                size="footnotesize",
                colsep="4pt",  # the Russian method names are the longest
            )
        )
    return blocks, figs


def build(ctx: Context) -> Part:
    speed, f1 = _speed(ctx)
    time_blocks, f2 = _time_domain(ctx)
    body = Latex("\n\n".join(b.raw for b in speed + time_blocks))
    return Part(body, figures=tuple(f1 + f2))
