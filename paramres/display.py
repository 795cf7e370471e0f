"""Notebook displays of the engine's results: the text a result prints, as HTML, and formulas as
LaTeX for Jupyter's ``_repr_latex_``.  Shared by :mod:`analytic` and :mod:`verify` (like
:mod:`paramres.inputs`), so neither imports the other for it.

>>> pre_html("T < 1 & m = 3/10")
'<pre>T &lt; 1 &amp; m = 3/10</pre>'
>>> import sympy
>>> display_math([("T_-", sympy.Rational(1, 2))])
'$\\\\displaystyle \\\\begin{aligned}T_- &= \\\\frac{1}{2}\\\\end{aligned}$'
"""

from __future__ import annotations

import html
from collections.abc import Iterable, Sequence

__all__ = ["pre_html", "display_math", "html_table"]


def pre_html(obj: object) -> str:
    """``str(obj)`` as preformatted HTML: every printed digit, in the notebook as in a terminal."""
    return "<pre>" + html.escape(str(obj)) + "</pre>"


def display_math(lines: Iterable[tuple[str, object]]) -> str:
    """``name = value`` lines, aligned at ``=``, as one display formula; ``name`` is LaTeX, a
    ``value`` that is not already a string goes through sympy's printer."""
    import sympy

    rows = []
    for name, value in lines:
        src = value if isinstance(value, str) else sympy.latex(value)
        rows.append(f"{name} &= {src}")
    return r"$\displaystyle \begin{aligned}" + r" \\ ".join(rows) + r"\end{aligned}$"


def html_table(header: Sequence[str], rows: Iterable[Sequence[object]]) -> str:
    """A small HTML table, every cell escaped (formulas between ``$`` are left to MathJax)."""
    head = "".join(f"<th>{html.escape(str(h))}</th>" for h in header)
    body = "".join(
        "<tr>" + "".join(f"<td>{html.escape(str(c))}</td>" for c in row) + "</tr>" for row in rows
    )
    return f"<table><thead><tr>{head}</tr></thead><tbody>{body}</tbody></table>"
