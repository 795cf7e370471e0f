"""LaTeX as a small value type: the report is assembled from typed pieces, never from loose strings.

A :class:`Latex` holds a fragment of LaTeX source.  Plain text becomes LaTeX only through
:func:`text` (which escapes it), a sympy expression only through :func:`math` (one printer, one set
of settings, held in a frozen :class:`Config`), and the structure of a document -- sections,
paragraphs, displayed equations, tables, figures, lists -- through the functions below, each of
which takes :class:`Latex` or ``str`` (escaped as text) and returns :class:`Latex`.  Nothing depends
on the clock, the machine or dict order, so the same inputs give the same bytes.

>>> str(text("50% of {x}"))
'50\\\\% of \\\\{x\\\\}'
>>> str(inline(math(sympy.Symbol("omega_1") / 2)))
'$\\\\frac{\\\\omega_{1}}{2}$'
"""

from __future__ import annotations

import sympy  # noqa: F401  (the doctests above use it)

from .breaking import break_source, fit, math_lines, pack, series_terms
from .config import DEFAULT, Config
from .document import document
from .fragment import Latex, raw, ref, text
from .maths import inline, math, notation, number, slashed
from .prose import mixed, prose
from .structure import (
    command,
    description,
    environment,
    equation,
    equation_lines,
    figure,
    itemize,
    paragraph,
    section,
    short_caption,
    table,
)
from .width import visible_width

__all__ = [
    "Latex",
    "Config",
    "DEFAULT",
    "text",
    "prose",
    "mixed",
    "raw",
    "ref",
    "math",
    "notation",
    "inline",
    "slashed",
    "short_caption",
    "number",
    "command",
    "environment",
    "section",
    "paragraph",
    "equation",
    "equation_lines",
    "fit",
    "math_lines",
    "pack",
    "break_source",
    "series_terms",
    "table",
    "figure",
    "itemize",
    "description",
    "document",
    "visible_width",
]
