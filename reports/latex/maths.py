"""Mathematics as LaTeX: a sympy expression through one printer (:func:`math`), the report's
notation (:func:`notation`), formulas for running text (:func:`slashed`, :func:`inline`) and
numbers (:func:`number`)."""

from __future__ import annotations

import re

import sympy

from ..i18n import current, tr
from .config import DEFAULT, Config
from .fragment import Latex

__all__ = ["math", "notation", "slashed", "inline", "number"]


def math(expr, config: Config = DEFAULT, **settings) -> Latex:
    """A sympy expression (or anything sympy accepts; :class:`Latex` passes through) as math-mode
    LaTeX, printed with ``config.printer`` updated by ``settings`` (e.g. ``order="lex"``)."""
    if isinstance(expr, Latex):
        return expr
    return Latex(notation(sympy.latex(expr, **{**dict(config.printer), **settings})))


#: sympy orders ``1 + m`` as ``m + 1``; the paper and this report write ``l_0(1 + m)``
_ONE_PLUS_M = re.compile(r"(\\left\(|\\sqrt\{|\{|\()m \+ 1(?=\\right\)|\}|\))")


#: a word set upright inside mathematics (``\\text{at }``, ``\\mathrm{odd}``)
_WORD_IN_MATH = re.compile(r"\\(text|mathrm)\{([^{}$\\]*[A-Za-z]{2}[^{}$\\]*)\}")


def notation(src: str) -> str:
    """The report's notation in sympy's LaTeX: ``1 + m`` (as in ``l_0(1 + m)``), not ``m + 1``;
    words set upright in the formula (``\\text{at }``) in the language being built.

    >>> notation(r"\\left(m + 1\\right)^{2} \\sqrt{m + 1}")
    '\\\\left(1 + m\\\\right)^{2} \\\\sqrt{1 + m}'
    """
    src = _ONE_PLUS_M.sub(lambda mt: mt.group(1) + "1 + m", src)
    if current() != "en":
        src = _WORD_IN_MATH.sub(_word_in_math, src)
    return src


def _word_in_math(mt: re.Match) -> str:
    said = tr(mt.group(2))
    # a translated word is set as text (math fonts have no Cyrillic)
    return f"\\text{{{said}}}" if said != mt.group(2) else mt.group(0)


def slashed(expr, config: Config = DEFAULT, **settings) -> Latex:
    """A formula for running text: fractions written with a slash, ``\\pi n/(6 Q)``, so that a
    line keeps its height (an equation is done side by side)."""
    if isinstance(expr, sympy.Equality):
        return Latex(
            slashed(expr.lhs, config, **settings).raw
            + " = "
            + slashed(expr.rhs, config, **settings).raw
        )
    num, den = sympy.fraction(sympy.sympify(expr))
    if den == 1:
        return math(expr, config, **settings)

    def part(x, strict: bool) -> str:
        src = math(x, config, **settings).raw
        needs = isinstance(x, sympy.Add) or (strict and isinstance(x, sympy.Mul))
        return r"\left(" + src + r"\right)" if needs else src

    return Latex(part(num, False) + "/" + part(den, True))


def inline(body: Latex) -> Latex:
    """In-line math: ``$...$``."""
    return Latex("$" + body.raw + "$")


def number(x, config: Config = DEFAULT, digits: int | None = None) -> Latex:
    """A number for a table or text: integers and rationals exactly, floats with ``digits``
    significant digits in the ``1.5\\cdot 10^{-3}`` style, NaN as an en dash."""
    digits = config.digits if digits is None else digits
    if isinstance(x, bool):
        raise TypeError("a bool is not a number")
    if isinstance(x, int):
        return Latex(f"${x}$")
    try:
        from fractions import Fraction

        if isinstance(x, Fraction):
            return Latex(
                f"${x.numerator}/{x.denominator}$" if x.denominator != 1 else f"${x.numerator}$"
            )
    except ImportError:  # pragma: no cover
        pass
    f = float(x)
    if f != f:
        return Latex("--")
    if f in (float("inf"), float("-inf")):
        return Latex(r"$\infty$" if f > 0 else r"$-\infty$")
    s = f"{f:.{digits}g}"
    mant, _, exp = s.partition("e")
    if exp:
        return Latex(f"${mant}\\cdot 10^{{{int(exp)}}}$")
    return Latex(f"${mant}$")
