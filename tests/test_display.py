"""Notebook displays: every public result shows itself in Jupyter (``_repr_html_`` or
``_repr_latex_``) with the same digits as its printed text."""

from __future__ import annotations

import html

import paramres
from analytic.catalogue import catalogue
from analytic.closings import closings
from analytic.reductions import chains


def test_certified_results_show_their_printed_text():
    # the HTML is the printed text itself, so it carries every certified digit
    for result in (
        paramres.multipliers("1.45", "0.3", digits=25),
        paramres.boundary(3, "3/10", digits=40),
    ):
        shown = result._repr_html_()
        assert shown.startswith("<pre>") and html.unescape(shown[5:-6]) == str(result)


def test_existence_shows_its_ranges():
    ex = paramres.existence(3, 3)
    assert html.unescape(ex._repr_html_()[5:-6]) == str(ex)


def test_series_and_closings_and_steps():
    s = paramres.series(2, 4)
    latex = s._repr_latex_()
    assert latex.startswith("$") and latex.endswith("$") and "T_-/T_0" in latex
    c = closings(4)
    table = c._repr_html_()
    assert table.count("<tr>") == 1 + len(c.items) and "3/5" in table  # 2:1 closes at m = 3/5
    assert "$" in c.steps[0]._repr_latex_()
    step = chains()[0].steps[0]
    assert step._repr_latex_().startswith(r"$\displaystyle")


def test_catalogue_rows_escape_their_text():
    row = catalogue()[0]
    shown = row._repr_html_()
    assert "<table>" in shown and html.escape(row.how) in shown
