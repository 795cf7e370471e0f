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

import re
from collections.abc import Iterable, Sequence
from dataclasses import dataclass, field

import sympy
from sympy.printing.latex import LatexPrinter

from .i18n import current, tr

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


@dataclass(frozen=True)
class Latex:
    """A fragment of LaTeX source.  ``+`` concatenates; ``str()`` gives the source."""

    raw: str

    def __str__(self) -> str:
        return self.raw

    def __add__(self, other: Latex | str) -> Latex:
        return Latex(self.raw + _source(other))

    def __radd__(self, other: Latex | str) -> Latex:
        return Latex(_source(other) + self.raw)

    def wrap(self) -> Latex:
        """``{...}``: a group, e.g. an argument."""
        return Latex("{" + self.raw + "}")

    def paren(self) -> Latex:
        """``\\left( ... \\right)``."""
        return Latex(r"\left(" + self.raw + r"\right)")

    def join(self, items: Iterable[Latex | str]) -> Latex:
        """The items with this fragment between them (``str`` items are escaped as text)."""
        return Latex(self.raw.join(_source(i) for i in items))

    @property
    def empty(self) -> bool:
        return not self.raw


def _source(x: Latex | str) -> str:
    """Source of ``x``: a :class:`Latex` as it is, a ``str`` escaped as text."""
    if isinstance(x, Latex):
        return x.raw
    if isinstance(x, str):
        return text(x).raw
    raise TypeError(f"expected Latex or str, got {type(x).__name__}")


@dataclass(frozen=True)
class Config:
    """Everything that decides how the LaTeX looks; frozen, so a run cannot change it midway.

    ``max_width`` is the visible width (in characters, see :func:`visible_width`) of a displayed
    formula line before :func:`math_lines` breaks it; a line wider than ``fit_width`` is wrapped
    in ``\\fitmath``, which lets TeX measure it and scale it to the line if it is too wide;
    ``digits`` the significant digits of a float printed by :func:`number`; ``printer`` the sympy
    ``latex()`` settings.
    """

    documentclass: str = "article"
    class_options: tuple[str, ...] = ("11pt", "a4paper")
    packages: tuple[tuple[str, str], ...] = (
        ("geometry", "margin=2.3cm"),
        ("amsmath", ""),
        ("amssymb", ""),
        ("graphicx", ""),
        ("booktabs", ""),
        ("longtable", ""),
        ("array", ""),
        ("xcolor", ""),
        ("microtype", "expansion=false"),
        ("caption", "font=small,labelfont=bf"),
        ("hyperref", "hidelinks,hypertexnames=false,pdfcreator={paramres},pdfproducer={paramres}"),
    )
    preamble: tuple[str, ...] = (
        # \fitmath{...}: display math scaled down to the line only if TeX finds it too wide
        r"\newsavebox\prfitbox",
        r"\newcommand{\fitmath}[1]{\sbox\prfitbox{$\displaystyle #1$}%",
        r"\ifdim\wd\prfitbox>\dimexpr\linewidth-4em\relax"
        r"\resizebox{\dimexpr\linewidth-4em\relax}{!}{\usebox\prfitbox}%",
        r"\else\usebox\prfitbox\fi}",
        # \fitcell{...}: the same for a formula in a table cell, scaled to the column if needed
        r"\newcommand{\fitcell}[1]{\sbox\prfitbox{$\displaystyle #1$}%",
        r"\ifdim\wd\prfitbox>\linewidth\resizebox{\linewidth}{!}{\usebox\prfitbox}%",
        r"\else\usebox\prfitbox\fi}",
        r"\numberwithin{equation}{section}",
        r"\setlength{\LTcapwidth}{\textwidth}",
        r"\allowdisplaybreaks",
        r"\renewcommand{\topfraction}{0.9}",
        r"\renewcommand{\bottomfraction}{0.8}",
        r"\renewcommand{\textfraction}{0.07}",
        r"\renewcommand{\floatpagefraction}{0.75}",
        r"\emergencystretch=2em",
    )
    max_width: int = 70
    fit_width: int = 60
    digits: int = 6
    printer: tuple[tuple[str, object], ...] = field(
        default=(("mul_symbol", None), ("ln_notation", True), ("fold_short_frac", False))
    )


DEFAULT = Config()

# --------------------------------------------------------------------------------------- text

_SPECIAL = {
    "\\": r"$\backslash$",
    "{": r"\{",
    "}": r"\}",
    "$": r"\$",
    "&": r"\&",
    "#": r"\#",
    "%": r"\%",
    "_": r"\_",
    "^": r"$^\wedge$",
    "~": r"$\sim$",
    "<": r"$<$",
    ">": r"$>$",
    "|": r"$|$",
}

#: non-ASCII characters that may appear in text, and what they become (pdfLaTeX, OT1 fonts)
_UNICODE = {
    "\u2212": "-",  # minus sign
    "\u2013": "--",
    "\u2014": "---",
    "\u2018": "`",
    "\u2019": "'",
    "\u201c": "``",
    "\u201d": "''",
    "\u2026": r"\ldots{}",
    "\u00a0": "~",
    "\u00d7": r"$\times$",
    "\u00b1": r"$\pm$",
    "\u2213": r"$\mp$",
    "\u2264": r"$\leq$",
    "\u2265": r"$\geq$",
    "\u2260": r"$\neq$",
    "\u2248": r"$\approx$",
    "\u2192": r"$\to$",
    "\u2190": r"$\leftarrow$",
    "\u21d2": r"$\Rightarrow$",
    "\u221a": r"$\surd$",
    "\u221e": r"$\infty$",
    "\u2208": r"$\in$",
    "\u00b2": r"$^2$",
    "\u00b3": r"$^3$",
    "\u2074": r"$^4$",
    "\u00b0": r"$^\circ$",
    "\u00a7": r"\S{}",
    "\u00ab": r"\guillemotleft{}",
    "\u00bb": r"\guillemotright{}",
    "\u00b7": r"$\cdot$",
    "\u03b1": r"$\alpha$",
    "\u03b2": r"$\beta$",
    "\u03b3": r"$\gamma$",
    "\u0393": r"$\Gamma$",
    "\u03b4": r"$\delta$",
    "\u0394": r"$\Delta$",
    "\u03b5": r"$\varepsilon$",
    "\u03b8": r"$\theta$",
    "\u03bb": r"$\lambda$",
    "\u039b": r"$\Lambda$",
    "\u03bc": r"$\mu$",
    "\u03c0": r"$\pi$",
    "\u03c3": r"$\sigma$",
    "\u03c4": r"$\tau$",
    "\u03c6": r"$\varphi$",
    "\u03d5": r"$\phi$",
    "\u03c8": r"$\psi$",
    "\u03c9": r"$\omega$",
    "\u03a9": r"$\Omega$",
}


def text(s: str) -> Latex:
    """Plain text, escaped.  Known non-ASCII characters (Greek letters, dashes, relations) become
    their LaTeX forms; any other non-ASCII character is written as ``[U+XXXX]`` so that the source
    stays ASCII and compiles with any engine.

    >>> str(text("a_1 & b^2 ~ 100%"))
    'a\\\\_1 \\\\& b$^\\\\wedge$2 $\\\\sim$ 100\\\\%'
    >>> str(text("γ ≥ 0"))
    '$\\\\gamma$ $\\\\geq$ 0'
    """
    return Latex(_escape(tr(s)))


#: a double hyphen that starts a command-line option (``--order``): kept as two hyphens
_OPTION = re.compile(r"--(?=[A-Za-z])")
#: a straight quote that opens a quotation (after a space or bracket, or at the start)
_OPENING = re.compile(r"(?:(?<=^)|(?<=[\s(\[]))'(?=\S)")


def _escape(s: str) -> str:
    """The characters of ``s`` as LaTeX text (see :func:`text`), without translation."""
    s = _OPENING.sub("\u2018", _OPTION.sub("\x00", s))
    out = []
    for ch in s:
        if ch == "\x00":
            out.append("-{}-{}")
        elif ch in _SPECIAL:
            out.append(_SPECIAL[ch])
        elif ord(ch) < 128:
            out.append(ch)
        elif ch in _UNICODE:
            out.append(_UNICODE[ch])
        elif "\u0400" <= ch <= "\u04ff" and current() == "ru":  # the Russian report
            out.append(ch)
        else:
            out.append(f"[U+{ord(ch):04X}]")
    return "".join(out)


_GREEK = (
    "alpha beta gamma delta epsilon theta lambda mu pi sigma tau phi varphi psi omega "
    "Gamma Delta Theta Lambda Sigma Phi Psi Omega"
).split()
_GREEK_RE = "|".join(sorted(_GREEK, key=len, reverse=True))
#: one formula token of the engine's plain-text notation
_TOKEN = re.compile(
    r"(?P<sqrt>(?<![A-Za-z])sqrt\()"
    r"|(?P<greek>(?<![A-Za-z\\])(?:" + _GREEK_RE + r"))(?:_(?P<gsub>[A-Za-z0-9]+)|(?P<gdig>[0-9]))?"
    r"(?![A-Za-z0-9])"
    r"|(?P<sym>(?<![A-Za-z0-9\\])[A-Za-z])(?:_(?P<sub>[A-Za-z0-9]+|[+-](?![A-Za-z0-9(]))|(?P<dig>[0-9]))"
    r"(?![A-Za-z0-9])"
    r"|(?P<base>(?<![A-Za-z0-9\\])[A-Za-z])?\^(?P<sup>[0-9]+|\([^()]*(?:\([^()]*\)[^()]*)*\)|[A-Za-z])"
    r"|(?P<rel><=|>=|!=|\+-|-\+|->|<|>)"
)
_REL = {
    "<=": r"\le",
    ">=": r"\ge",
    "!=": r"\ne",
    "+-": r"\pm",
    "-+": r"\mp",
    "->": r"\to",
    "<": "<",
    ">": ">",
}
_MATH_SAFE = set("+-/()[].,=<>|:;'! ")


def _balanced(s: str, i: int) -> int:
    """Index just after the ``)`` that closes the ``(`` before ``s[i]`` (or ``len(s)``)."""
    depth = 1
    for j in range(i, len(s)):
        if s[j] == "(":
            depth += 1
        elif s[j] == ")":
            depth -= 1
            if depth == 0:
                return j + 1
    return len(s)


def _mathify(s: str) -> str:
    """A plain formula fragment as math-mode source (the inside of ``$...$``)."""
    out: list[str] = []
    pos = 0
    while True:
        mt = _TOKEN.search(s, pos)
        chunk = s[pos : mt.start()] if mt else s[pos:]
        out.append(_math_chars(chunk))
        if not mt:
            break
        piece, pos = _token_math(s, mt)
        out.append(piece)
    return "".join(out).strip()


def _math_chars(chunk: str) -> str:
    """Plain characters in math mode: letters, digits and safe punctuation kept, ``*`` a thin space,
    ``%&#$~_{}\\`` escaped or dropped."""
    res = []
    for ch in chunk:
        if ch.isalnum() or ch in _MATH_SAFE:
            res.append(ch)
        elif ch == "*":
            res.append(r"\,")
        elif ch in "%&#$":
            res.append("\\" + ch)
        elif ch in _UNICODE:
            res.append(_UNICODE[ch].strip("$"))
    return "".join(res)


def _token_math(s: str, mt: re.Match) -> tuple[str, int]:
    """Math source of the token ``mt`` of ``s`` and the position after it."""
    if mt.group("sqrt"):
        end = _balanced(s, mt.end())
        return r"\sqrt{" + _mathify(s[mt.end() : end - 1]) + "}", end
    if mt.group("greek"):
        sub = mt.group("gsub") or mt.group("gdig")
        return "\\" + mt.group("greek") + (f"_{{{sub}}}" if sub else " "), mt.end()
    if mt.group("sym"):
        sub = mt.group("sub") or mt.group("dig")
        return f"{mt.group('sym')}_{{{sub}}}", mt.end()
    if mt.group("rel"):
        return _REL[mt.group("rel")] + " ", mt.end()
    sup = mt.group("sup")
    sup = sup[1:-1] if sup.startswith("(") else sup
    return (mt.group("base") or "") + "^{" + _mathify(sup) + "}", mt.end()


def prose(s: str) -> Latex:
    """Text written in the engine's plain-text notation, with its formula tokens set as math:
    Greek names (``omega_av``, ``gamma``, ``Delta``, ``omega1``), subscripted letters (``A_2``,
    ``T_av``, ``T0``, ``F_+``), powers (``^2``, ``^(a+b)``), ``sqrt(...)`` and the relations ``<=``,
    ``>=``, ``+-``, ``-+``, ``->``; everything else is escaped as by :func:`text`.

    >>> str(prose("omega_av T/2 = n pi, (1-m)^2"))
    '$\\\\omega_{av}$ T/2 = n $\\\\pi$, (1-m)$^{2}$'
    >>> str(prose("T = a T1 = a sqrt(2/(a^2 + b^2)) T0, 1 <= a"))
    'T = a $T_{1}$ = a $\\\\sqrt{2/(a^{2} + b^{2})}$ $T_{0}$, 1 $\\\\le$ a'
    """
    s = tr(s)
    if "$" in s:  # a translation may carry its formulas in LaTeX already
        return mixed(s)
    return _prose_only(s)


def _prose_only(s: str) -> Latex:
    """:func:`prose` without translation."""
    s = re.sub(r"(?<=\S)\*(?=\S)", "\u00b7", s.replace("**", "^"))
    out: list[str] = []
    pos = 0
    for mt in _TOKEN.finditer(s):
        if mt.start() < pos:
            continue
        out.append(_escape(s[pos : mt.start()]))
        piece, pos = _token_math(s, mt)
        out.append("$" + piece.strip() + "$")
    out.append(_escape(s[pos:]))
    return Latex("".join(out))


#: a formula with a fraction wider than this (characters, :func:`visible_width`) is displayed, not
#: set in the line, where it would push the lines apart
INLINE_FRACTION_WIDTH = 24


def mixed(s: str, config: Config = DEFAULT) -> Latex:
    """Text with in-line formulas already in LaTeX between ``$`` signs (as the engine's
    explanations are written): the formulas pass through, the text between them goes through
    :func:`prose`.  A formula wider than ``config.fit_width`` is set as a display (through
    :func:`fit`), since in-line math cannot break inside brackets.  An unpaired ``$`` is escaped.

    >>> str(mixed("printed $q^2$ where omega_1 gives $q$"))
    'printed $q^2$ where $\\\\omega_{1}$ gives $q$'
    """
    s = tr(s)
    parts = s.split("$")
    if len(parts) % 2 == 0:  # unpaired: treat the last "$" as text
        tail = parts.pop()
        parts[-1] = parts[-1] + "$" + tail
    out = []
    for k, part in enumerate(parts):
        if k % 2 == 0:
            out.append(_prose_only(part).raw)
        elif visible_width(part) > config.fit_width or (
            r"\frac" in part and visible_width(part) > INLINE_FRACTION_WIDTH
        ):
            lines = break_source(part, config.max_width)
            if len(lines) == 1:
                out.append(r"\[" + fit(lines[0], config).raw + r"\]")
            else:
                body = " \\\\\n".join(fit(x, config).raw for x in lines)
                out.append("\n\\begin{multline*}\n" + body + "\n\\end{multline*}\n")
        else:
            out.append("$" + part + "$")
    return Latex("".join(out))


def ref(kind: str, label: str) -> Latex:
    """A cross-reference with a non-breaking space: ``ref("Section", "sec:model")``."""
    return Latex(f"{text(kind).raw}~\\ref{{{label}}}")


def raw(s: str) -> Latex:
    """LaTeX source written by the caller (markup, never a result); prose in it is translated
    when the report is built in another language (:func:`reports.i18n.tr`)."""
    return Latex(tr(s))


# --------------------------------------------------------------------------------------- math


def math(expr, config: Config = DEFAULT, **settings) -> Latex:
    """A sympy expression (or anything sympy accepts; :class:`Latex` passes through) as math-mode
    LaTeX, printed with ``config.printer`` updated by ``settings`` (e.g. ``order="lex"``)."""
    if isinstance(expr, Latex):
        return expr
    return Latex(notation(sympy.latex(expr, **{**dict(config.printer), **settings})))


#: sympy orders ``1 + m`` as ``m + 1``; the paper and this report write ``l_0(1 + m)``
_ONE_PLUS_M = re.compile(r"(\\left\(|\\sqrt\{|\{|\()m \+ 1(?=\\right\)|\}|\))")


def notation(src: str) -> str:
    """The report's notation in sympy's LaTeX: ``1 + m`` (as in ``l_0(1 + m)``), not ``m + 1``.

    >>> notation(r"\\left(m + 1\\right)^{2} \\sqrt{m + 1}")
    '\\\\left(1 + m\\\\right)^{2} \\\\sqrt{1 + m}'
    """
    return _ONE_PLUS_M.sub(lambda mt: mt.group(1) + "1 + m", src)


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


_CMD = re.compile(r"\\[A-Za-z]+\*?|\\.")
_INVISIBLE = {
    r"\left",
    r"\right",
    r"\mathopen",
    r"\mathclose",
    r"\displaystyle",
    r"\limits",
    r"\,",
    r"\;",
    r"\!",
    r"\ ",
}


def visible_width(src: Latex | str) -> int:
    """A rough width of typeset math, in characters: each command counts as one character (or
    none for sizing commands), braces count nothing, and a fraction counts the wider of numerator
    and denominator.  Used only to decide where to break a displayed formula."""
    s = src.raw if isinstance(src, Latex) else src

    def width(s: str) -> int:
        total = 0
        i = 0
        while i < len(s):
            if s.startswith(r"\frac", i) or s.startswith(r"\dfrac", i):
                i = s.index("frac", i) + 4
                a, i = _group(s, i)
                b, i = _group(s, i)
                total += max(width(a), width(b)) + 1
                continue
            m = _CMD.match(s, i)
            if m:
                total += 0 if m.group(0) in _INVISIBLE else 1
                i = m.end()
                continue
            if s[i] in "{} ":
                i += 1
                continue
            total += 1
            i += 1
        return total

    return width(s)


def _group(s: str, i: int) -> tuple[str, int]:
    """The brace group starting at ``s[i]`` (skipping spaces) and the index after it."""
    while i < len(s) and s[i] == " ":
        i += 1
    if i >= len(s) or s[i] != "{":
        return (s[i : i + 1], i + 1)
    depth = 0
    for j in range(i, len(s)):
        if s[j] == "{" and (j == 0 or s[j - 1] != "\\"):
            depth += 1
        elif s[j] == "}" and s[j - 1] != "\\":
            depth -= 1
            if depth == 0:
                return s[i + 1 : j], j + 1
    return s[i + 1 :], len(s)


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


# ---------------------------------------------------------------------------------- structure


def command(name: str, *args: Latex | str, optional: Latex | str | None = None) -> Latex:
    """``\\name[optional]{arg}...`` (``str`` arguments are escaped as text)."""
    opt = "" if optional is None else "[" + _source(optional) + "]"
    return Latex("\\" + name + opt + "".join("{" + _source(a) + "}" for a in args))


def environment(
    name: str, body: Latex | str, *args: Latex | str, optional: str | None = None
) -> Latex:
    """``\\begin{name}...body...\\end{name}`` on lines of their own."""
    head = "\\begin{" + name + "}" + (f"[{optional}]" if optional else "")
    head += "".join("{" + _source(a) + "}" for a in args)
    return Latex(f"{head}\n{_source(body).rstrip()}\n\\end{{{name}}}")


def section(title: Latex | str, label: str | None = None, level: int = 0) -> Latex:
    """``\\section`` (level 0), ``\\subsection`` (1) or ``\\subsubsection`` (2), with a label."""
    name = ("section", "subsection", "subsubsection")[level]
    out = command(name, title)
    if label:
        out = out + command("label", raw(label))
    return out


def paragraph(*parts: Latex | str) -> Latex:
    """Running text: the parts joined by single spaces (``str`` parts escaped as text), except
    before a part that starts with closing punctuation and after one that ends with ``(``.

    >>> str(paragraph("the period", inline(raw("T")), ", the depth (", inline(raw("m")), ")."))
    'the period $T$, the depth ($m$).'
    """
    out = ""
    for p in parts:
        src = _source(p)
        if not src:
            continue
        if (
            out
            and not out.endswith(("(", " ", "\n", "~"))
            and not src.startswith((".", ",", ";", ":", ")", "'", "!", "?", "-"))
        ):
            out += " "
        out += src
    return Latex(out)


def equation(
    body,
    *,
    tag: str | None = None,
    label: str | None = None,
    numbered: bool = True,
    config: Config = DEFAULT,
) -> Latex:
    """A displayed formula.  ``body`` is a sympy expression/equation or :class:`Latex`; a formula
    wider than ``config.max_width`` is broken over lines (``multline``).  ``tag`` prints the given
    number instead of the automatic one (used for the paper's equation numbers)."""
    lines = math_lines(body, config)
    return equation_lines(lines, tag=tag, label=label, numbered=numbered, config=config)


def fit(line: Latex, config: Config = DEFAULT) -> Latex:
    """``\\fitmath{line}`` if the line is wider than ``config.fit_width`` (TeX then scales it down
    only if it really does not fit), else the line itself."""
    if visible_width(line) > config.fit_width:
        return Latex(r"\fitmath{" + line.raw + "}")
    return line


def equation_lines(
    lines: Sequence[Latex],
    *,
    tag: str | None = None,
    label: str | None = None,
    numbered: bool = True,
    config: Config = DEFAULT,
) -> Latex:
    """Displayed math from ready lines: ``equation`` for one line, ``multline`` for more; each
    line goes through :func:`fit`."""
    lines = [fit(line, config) for line in lines]
    marks = ""
    if tag is not None:
        marks += command("tag", raw(tag)).raw
    if label:
        marks += command("label", raw(label)).raw
    star = "" if (numbered or tag is not None) else "*"
    if len(lines) == 1:
        return environment("equation" + star, Latex(lines[0].raw + marks))
    body = " \\\\\n".join(line.raw for line in lines) + marks
    return environment("multline" + star, Latex(body))


def table(
    header: Sequence[Latex | str],
    rows: Sequence[Sequence[Latex | str]],
    *,
    columns: str | None = None,
    caption: Latex | str | None = None,
    label: str | None = None,
    long: bool = False,
    size: str | None = None,
    colsep: str | None = None,
) -> Latex:
    """A booktabs table.  ``columns`` is the column spec (default: left, then right-aligned);
    ``long=True`` makes a ``longtable`` that may break across pages (caption on top, the header
    repeated on every page); ``size`` a font size (``"small"``) and ``colsep`` the space between
    columns (``"3pt"``), both local to the table."""
    ncol = len(header)
    for r in rows:
        if len(r) != ncol:
            raise ValueError(f"row has {len(r)} cells, header has {ncol}")
    columns = columns or ("l" + "r" * (ncol - 1))
    head = " & ".join(_source(h) for h in header) + r" \\"
    body = "\n".join(" & ".join(_source(c) for c in r) + r" \\" for r in rows)
    cap = _caption(caption) if caption is not None else ""
    lab = command("label", raw(label)).raw if label else ""
    switches = [f"\\{size}"] if size else []
    if colsep:
        switches.append(f"\\setlength{{\\tabcolsep}}{{{colsep}}}")
    if long:
        top = (cap + lab + r" \\" + "\n") if cap else ""
        content = (
            f"{top}\\toprule\n{head}\n\\midrule\n\\endfirsthead\n"
            f"\\toprule\n{head}\n\\midrule\n\\endhead\n"
            f"\\bottomrule\n\\endlastfoot\n{body}"
        )
        inner = environment("longtable", Latex(content), raw(columns))
        if not switches:
            return inner
        return Latex("{" + "\n".join(switches) + "\n" + inner.raw + "\n}")
    tab = environment(
        "tabular", Latex(f"\\toprule\n{head}\n\\midrule\n{body}\n\\bottomrule"), raw(columns)
    )
    inner = (
        "\n".join(["\\centering", *switches]) + "\n" + (cap + lab + "\n" if cap else "") + tab.raw
    )
    return environment("table", Latex(inner), optional="htbp")


def short_caption(src: str, limit: int = 90) -> str | None:
    """The first sentence of a caption (LaTeX source) for the lists of figures and tables, or
    ``None`` when the caption is short enough to be listed whole."""
    if len(src) <= limit:
        return None
    depth = 0
    in_math = False
    for i, ch in enumerate(src):
        if ch == "$" and (i == 0 or src[i - 1] != "\\"):
            in_math = not in_math
        elif ch == "{":
            depth += 1
        elif ch == "}":
            depth -= 1
        elif (
            ch == "."
            and not in_math
            and depth == 0
            and src[i + 1 : i + 2] == " "
            and not src[max(0, i - 4) : i].endswith(("Fig", "eq", "eqs", "Eq", "e.g", "i.e"))
        ):
            return src[: i + 1]
    return None


def _caption(caption: Latex | str) -> str:
    src = _source(caption)
    short = short_caption(src)
    return r"\caption" + ("" if short is None else "[{" + short + "}]") + "{" + src + "}"


def figure(
    path: str, caption: Latex | str, *, label: str | None = None, width: str = r"\textwidth"
) -> Latex:
    """A floating figure with one graphic (``path`` relative to the .tex file)."""
    body = (
        "\\centering\n" + command("includegraphics", raw(path), optional=raw(f"width={width}")).raw
    )
    body += "\n" + _caption(caption)
    if label:
        body += command("label", raw(label)).raw
    return environment("figure", Latex(body), optional="htbp")


def itemize(items: Iterable[Latex | str]) -> Latex:
    """A bulleted list."""
    return environment("itemize", Latex("\n".join("\\item " + _source(i) for i in items)))


def description(items: Iterable[tuple[Latex | str, Latex | str]]) -> Latex:
    """A list of (term, explanation) pairs."""
    return environment(
        "description", Latex("\n".join(f"\\item[{_source(k)}] {_source(v)}" for k, v in items))
    )


def document(
    body: Sequence[Latex],
    *,
    title: Latex | str,
    author: Latex | str = "",
    date: Latex | str = "",
    banner: str | None = None,
    abstract: Latex | str | None = None,
    config: Config = DEFAULT,
    packages: Sequence[tuple[str, str]] = (),
    preamble: Sequence[Latex | str] = (),
    contents: Sequence[Latex] = (Latex(r"\tableofcontents"),),
    back: Sequence[Latex] = (),
) -> Latex:
    """A complete document: optional ``% banner`` line, ``packages`` (loaded first, e.g. the font
    encoding and language), the packages and preamble of ``config``, then ``preamble`` (LaTeX
    source), the title block, the abstract, ``contents`` (table of contents, lists), the body
    blocks separated by blank lines, and the ``back`` matter (bibliography)."""
    head = []
    if banner:
        head.append("% " + banner)
    head.append(
        command(
            "documentclass", raw(config.documentclass), optional=raw(",".join(config.class_options))
        ).raw
    )
    for name, opts in (*packages, *config.packages):
        head.append(Latex("\\usepackage" + (f"[{opts}]" if opts else "") + "{" + name + "}").raw)
    head.extend(config.preamble)
    head.extend(_source(x) if isinstance(x, Latex) else x for x in preamble)
    head.append(command("title", title).raw)
    head.append(command("author", author).raw)
    head.append(command("date", date).raw)
    blocks = [r"\maketitle"]
    if abstract is not None:
        blocks.append(environment("abstract", abstract).raw)
    blocks.extend(b.raw for b in contents)
    blocks.extend(b.raw for b in body)
    blocks.extend(b.raw for b in back)
    content = "\n\n".join(blocks)
    return Latex("\n".join(head) + "\n\n" + environment("document", Latex(content)).raw + "\n")
