"""The pieces that turn the engine's output into a document's text: the language of a build,
typeset statements, equation labels, broken long formulas, slashed fractions, short captions."""

from __future__ import annotations

import re

import pytest
import sympy as sp

from reports.i18n import current, language, say, tr
from reports.latex import break_source, notation, short_caption, slashed, text
from reports.phrasebook import lookup
from reports.sections.catalogue import eq_text


def test_language_is_scoped_to_the_build():
    assert current() == "en"
    with language("ru"):
        assert current() == "ru"
        assert say("order", "порядок") == "порядок"
    assert current() == "en" and say("order", "порядок") == "order"
    with pytest.raises(ValueError, match="de"):
        with language("de"):
            pass


def test_translation_falls_back_to_the_english_text():
    with language("ru"):
        assert tr("Summary of results") == "Сводка результатов"
        assert tr("a sentence nobody translated") == "a sentence nobody translated"
        assert tr(r"Figure~\ref{fig:x}") == r"Рис.~\ref{fig:x}"
    assert tr("Summary of results") == "Summary of results"


def test_cyrillic_reaches_the_source_only_in_the_russian_report():
    assert text("Бутиков").raw.isascii()
    with language("ru"):
        assert text("Бутиков").raw == "Бутиков"


def test_options_keep_their_double_hyphen_and_quotes_open():
    assert text("paramres series --order 1 --terms K").raw == (
        "paramres series -{}-{}order 1 -{}-{}terms K"
    )
    assert text("eqs. 2--3").raw == "eqs. 2--3"  # a range stays an en dash
    assert text("the text's 'n > 2' agrees").raw.count("`") == 1


def test_engine_statements_are_typeset():
    en = lookup("T = 3 T_av/2 + Delta T with omega_av T_av = 2 pi; divide by -q - 1.", "en")
    assert en == (
        r"With $T = \tfrac{3}{2} T_{av} + \Delta T$ and $\omega_{av} T_{av} = 2\pi$, divided by "
        r"$-(q + 1)$."
    )
    assert lookup("continuity of the angle at t = 0.", "ru") == "Непрерывность угла при $t = 0$."
    assert lookup("something the phrasebook does not know", "en") is None


@pytest.mark.parametrize(
    "label, shown",
    [
        ("13", "(13)"),
        ("2-3", "(2)--(3)"),
        ("§5", r"\S5"),
        ("15-n3", "(15, $n = 3$)"),
        ("IC-15", "(15, i.c.)"),
        ("39-ref", "(39, reference)"),
        ("19-shift", "(19, centre)"),
    ],
)
def test_equation_labels(label, shown):
    assert eq_text(label).raw == shown


def test_long_formulas_break_at_top_level_signs_only():
    src = r"x = a + \left(b - c\right) - \frac{d + e}{2} + f"
    lines = [line.raw for line in break_source(src, 8)]
    assert lines[0].startswith("x = a")
    assert "".join(lines).replace(" ", "") == src.replace(" ", "")
    # no break inside the bracket or the fraction
    assert all(line.count(r"\left(") == line.count(r"\right)") for line in lines)
    assert all(line.count("{") == line.count("}") for line in lines)


def test_running_text_formulas_keep_the_line_height():
    Q, n = sp.symbols("Q n", positive=True)
    assert slashed(sp.pi * n / (6 * Q)).raw == r"\pi n/\left(6 Q\right)"
    assert slashed(sp.Eq(sp.Symbol("x"), sp.Rational(1, 2))).raw == "x = 1/2"
    assert notation(r"\left(m + 1\right)^{2}") == r"\left(1 + m\right)^{2}"


def test_short_captions_for_the_lists():
    long = "First sentence, which names the figure. " + "More detail follows here. " * 5
    assert short_caption(long) == "First sentence, which names the figure."
    assert short_caption("Short caption.") is None
    # a period inside mathematics or after "Fig" does not end the sentence
    src = r"The paper's Fig.~1 redrawn: $a. b$ stays whole, and so on. " + "x" * 80
    assert short_caption(src) == r"The paper's Fig.~1 redrawn: $a. b$ stays whole, and so on."


def _figure_texts(fig) -> list:
    from matplotlib.text import Text

    return [t for t in fig.findobj(Text) if t.get_visible() and t.get_text().strip()]


#: one point per method of ``paramres bench`` (the names as reports/benchmark.py gives them)
SPEED_POINTS = [
    {"method": "series K=1", "family": "series", "seconds": 1e-6, "error": 1e-2, "front": True},
    {"method": "series K=2", "family": "series", "seconds": 2e-6, "error": 1e-4, "front": True},
    {"method": "fixed point (paper)", "family": "fixed point", "seconds": 1e-4, "error": 1e-9},
    {"method": "double, per point", "family": "double", "seconds": 1e-5, "error": 1e-15},
    {"method": "numpy grid", "family": "grid", "seconds": 3e-6, "error": 1e-15, "front": True},
    {"method": "mpmath 30, uncertified", "family": "mpmath", "seconds": 4e-4, "error": 1e-29},
    {
        "method": "certified 30",
        "family": "certified",
        "seconds": 1e-4,
        "error": 1e-30,
        "front": True,
    },
    {
        "method": "certified 50",
        "family": "certified",
        "seconds": 2e-4,
        "error": 1e-50,
        "front": True,
    },
    {"method": "findroot 30 (printed eq.)", "family": "findroot", "seconds": 1e-3, "error": 1e-29},
    {"method": "auto, tol=1e-8", "family": "auto", "seconds": 5e-5, "error": 1e-11},
]


def test_the_russian_speed_figure_has_no_english_words():
    # panel titles, legend and the labels of the Pareto front: only the names of libraries and
    # functions (mpmath, numpy, findroot) stay as they are
    from reports.benchplots import pareto_figure

    with language("ru"):
        fig = pareto_figure([(tr("all scenes"), SPEED_POINTS), ("$m \\leq 0.01$", SPEED_POINTS)])
    shown = " ".join(t.get_text() for t in _figure_texts(fig))
    words = set(re.findall(r"[A-Za-z]{4,}", re.sub(r"\$[^$]*\$", " ", shown)))
    assert words <= {"mpmath", "numpy", "findroot"}, words
    assert "гарантированный" in shown and "ряд, K=1" in shown


@pytest.mark.parametrize("lang", ["en", "ru"])
def test_time_figure_titles_end_inside_the_figure(lang):
    # the paper's Fig. 9 has the longest titles (an edge, friction and its model); in Russian
    # they need a third line, which must not push the first title out at the top either
    from reports.timeplots import paper_figure

    with language(lang):
        fig = paper_figure(9)
    renderer = fig.canvas.get_renderer()
    titles = [t for t in _figure_texts(fig) if t.get_text().startswith("$n = ")]
    assert titles
    for t in titles:
        box = t.get_window_extent(renderer)
        assert box.x1 <= fig.bbox.x1 and box.y1 <= fig.bbox.y1, (t.get_text(), box)
    if lang == "ru":
        assert "рад" in " ".join(t.get_text() for t in _figure_texts(fig))


@pytest.mark.parametrize("lang", ["en", "ru"])
def test_front_labels_touch_no_marker(lang):
    # the report's speed figure from the stored benchmark: a label of the Pareto front (e.g.
    # "series K=1" at a cluster of series points) overlaps no point of its family
    import json

    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.lines import Line2D
    from matplotlib.text import Annotation

    from reports.benchplots import pareto_figure
    from reports.sections.performance import BENCH_RESULTS

    pareto = json.loads(BENCH_RESULTS.read_text(encoding="utf-8"))["pareto"]
    with language(lang):
        fig = pareto_figure([(tr("all scenes"), pareto["all"]), ("m", pareto["small m"])])
    renderer = FigureCanvasAgg(fig).get_renderer()
    fig.draw(renderer)
    checked = 0
    for ax in fig.axes:
        marks = [m for m in ax.get_lines() if isinstance(m, Line2D) and m.get_marker() != "None"]
        for t in ax.texts:
            if isinstance(t, Annotation) and t.get_fontsize() == 6 and t.get_color() == "0.2":
                # the run's first point: the front marker at the label's height
                x, y = t.xy
                first = next(
                    m for m in marks if m.get_markeredgecolor() == "black" and m.get_ydata()[0] == y
                )
                box = t.get_window_extent(renderer)
                for m in marks:
                    if m.get_color() == first.get_color():
                        assert not box.overlaps(m.get_window_extent(renderer)), t.get_text()
                checked += 1
    assert checked >= 4


def test_errata_cells_leave_a_definition_to_the_entry_with_the_series_it_serves():
    """An erratum's cell elides a series too long for it (``\\dots``); the definition of the
    series' variable goes with it, a definition that a shown formula uses stays."""
    from reports.sections.summary import _lines

    series = " + ".join(rf"\frac{{{k} s^{{{k}}}}}{{{k + 1} \pi}} m^{{{k}}}" for k in range(1, 40))
    src = rf"T = 1,\quad s = \sqrt{{1 - m^{{2}}}},\quad T_{{-}} = {series}"
    lines = _lines(src)
    assert lines == [r"\fitcell{T = 1}", r"\dots"], lines
    lines = _lines(r"s = \sqrt{1 - m^{2}},\quad T = 1 + s m")
    assert lines == [r"\fitcell{s = \sqrt{1 - m^{2}}}", r"\fitcell{T = 1 + s m}"], lines
    assert _lines(r"m = \frac{3}{5}") == [r"\fitcell{m = \frac{3}{5}}"]
