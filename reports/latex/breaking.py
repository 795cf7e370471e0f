"""Displayed formulas broken over lines: at the top-level ``+`` and ``-`` of a sum
(:func:`math_lines`, :func:`break_source`, :func:`series_terms`), lines filled greedily
(:func:`pack`), and :func:`fit` for a line that may still be too wide."""

from __future__ import annotations

from collections.abc import Sequence

import sympy
from sympy.printing.latex import LatexPrinter

from .config import DEFAULT, Config
from .fragment import Latex
from .maths import math
from .width import visible_width

__all__ = ["math_lines", "pack", "break_source", "series_terms", "fit"]


def _terms(expr: sympy.Expr, config: Config) -> list[Latex]:
    """The terms of a sum, each with its sign, in the printer's order: ``["a", "- b", "+ c"]``."""
    printer = LatexPrinter(dict(config.printer))
    ordered = printer._as_ordered_terms(expr)
    out = []
    for k, term in enumerate(ordered):
        if term.could_extract_minus_sign():
            out.append(Latex("- " + printer.doprint(-term)))
        else:
            out.append(Latex(("+ " if k else "") + printer.doprint(term)))
    return out


def math_lines(expr, config: Config = DEFAULT, width: int | None = None) -> list[Latex]:
    """A formula as one or more lines no wider than ``width`` (``config.max_width``), broken
    before a ``+`` or ``-`` of a top-level sum (on either side of an equation).

    An equation's left side stays on the first line with the ``=``; a line that cannot be broken
    further (a single long product) is kept whole.
    """
    width = config.max_width if width is None else width
    if isinstance(expr, Latex):
        return [expr]
    expr = sympy.sympify(expr)
    whole = math(expr, config)
    if visible_width(whole) <= width:
        return [whole]
    if isinstance(expr, sympy.Equality):
        # a side that fits on a line stays whole; the break before "=" comes first
        lhs, rhs = math(expr.lhs, config), math(expr.rhs, config)
        lhs_parts = [lhs] if visible_width(lhs) <= width else _breakable(expr.lhs, config)
        rhs_parts = [rhs] if visible_width(rhs) + 2 <= width else _breakable(expr.rhs, config)
        pieces = lhs_parts + [Latex("= ") + _strip_plus(rhs_parts[0])] + rhs_parts[1:]
    else:
        pieces = _breakable(expr, config)
    return pack(pieces, width)


def pack(pieces: Sequence[Latex], width: int) -> list[Latex]:
    """Greedy line filling: the pieces joined by spaces, a new line whenever the next piece would
    make the line wider than ``width`` (:func:`visible_width`)."""
    lines: list[Latex] = []
    current = Latex("")
    for piece in pieces:
        candidate = piece if current.empty else current + " " + piece
        if not current.empty and visible_width(candidate) > width:
            lines.append(current)
            current = piece
        else:
            current = candidate
    if not current.empty:
        lines.append(current)
    return lines


def break_source(src: str, width: int) -> list[Latex]:
    """A formula given as LaTeX source, broken into lines no wider than ``width`` (as far as it
    can be): the break points are the ``+`` and ``-`` of a top-level sum, outside every brace and
    ``\\left...\\right`` group, and the first line keeps everything up to the first ``=``.

    >>> [str(x) for x in break_source(r"x = a + \\frac{b + c}{2} - d", 6)]
    ['x = a', '+ \\\\frac{b + c}{2}', '- d']
    """
    if visible_width(src) <= width:
        return [Latex(src)]
    pieces: list[str] = []
    depth = 0
    start = 0
    seen_eq = "=" not in src
    i = 0
    while i < len(src):
        if src.startswith(r"\left", i) and not src[i + 5 : i + 6].isalpha():
            depth += 1
            i += 5
            continue
        if src.startswith(r"\right", i) and not src[i + 6 : i + 7].isalpha():
            depth -= 1
            i += 6
            continue
        ch = src[i]
        if ch == "\\":
            i += 2
            continue
        if ch == "{":
            depth += 1
        elif ch == "}":
            depth -= 1
        elif depth == 0 and ch == "=":
            seen_eq = True
        elif (
            depth == 0
            and seen_eq
            and ch in "+-"
            and i > 0
            and src[i - 1] == " "
            and src[:i].strip()
            and not src[:i].rstrip().endswith(("=", "(", ","))
        ):
            pieces.append(src[start:i].strip())
            start = i
        i += 1
    pieces.append(src[start:].strip())
    return pack([Latex(p) for p in pieces if p], width)


def series_terms(
    expr, var, config: Config = DEFAULT, *, big_o: int | None = None, shown_as=None
) -> list[Latex]:
    """A polynomial in ``var`` as signed terms in ascending powers (``["1", "- 3 m/16", ...]``),
    each coefficient in parentheses when it is a sum; ``big_o`` appends ``+ O(var**big_o)``.
    ``shown_as`` prints another expression in place of ``var`` (e.g. ``1/Q`` for a series in a
    symbol standing for ``1/Q``).

    >>> m = sympy.Symbol("m")
    >>> [str(t) for t in series_terms(sympy.Rational(1, 2) - 3 * m**2 / 16, m, big_o=3)]
    ['\\\\frac{1}{2}', '- \\\\frac{3 m^{2}}{16}', '+ O\\\\left(m^{3}\\\\right)']
    """
    poly = sympy.expand(expr)
    degree = sympy.Poly(poly, var).degree() if poly.has(var) else 0
    out: list[Latex] = []
    for k in range(degree + 1):
        c = poly.coeff(var, k)
        if c == 0:
            continue
        power = (var if shown_as is None else shown_as) ** k
        if isinstance(c, sympy.Add):  # a sum keeps its own signs unless all of them are minus
            neg = all(t.could_extract_minus_sign() for t in c.args)
        else:
            neg = c.could_extract_minus_sign()
        mag = sympy.expand(-c) if neg else c
        if isinstance(mag, sympy.Add) and k > 0:
            body = Latex(r"\left(" + math(mag, config).raw + r"\right) " + math(power, config).raw)
        else:
            body = math(mag * power, config)
        sign = "- " if neg else ("+ " if out else "")
        out.append(Latex(sign) + body)
    if big_o is not None:
        shown = (var if shown_as is None else shown_as) ** big_o
        out.append(Latex(r"+ O\left(" + math(shown, config).raw + r"\right)"))
    return out


def _breakable(expr, config: Config) -> list[Latex]:
    if isinstance(expr, sympy.Add):
        return _terms(expr, config)
    return [math(expr, config)]


def _strip_plus(x: Latex) -> Latex:
    return Latex(x.raw[2:]) if x.raw.startswith("+ ") else x


def fit(line: Latex, config: Config = DEFAULT) -> Latex:
    """``\\fitmath{line}`` if the line is wider than ``config.fit_width`` (TeX then scales it down
    only if it really does not fit), else the line itself."""
    if visible_width(line) > config.fit_width:
        return Latex(r"\fitmath{" + line.raw + "}")
    return line
