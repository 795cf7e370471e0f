"""Text written in the engine's plain-text notation, with its formula tokens set as math
(:func:`prose`), and text with in-line LaTeX formulas between ``$`` signs (:func:`mixed`)."""

from __future__ import annotations

import re

from ..i18n import tr
from .breaking import break_source, fit
from .config import DEFAULT, Config
from .fragment import _UNICODE, Latex, _escape
from .width import visible_width

__all__ = ["prose", "mixed", "INLINE_FRACTION_WIDTH"]

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


#: a range of equations in prose, ``(10)-(11)``: set with an en dash
_EQ_RANGE = re.compile(r"\((\d+)\)-\((\d+)\)")


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
            out.append(_EQ_RANGE.sub(r"(\1)--(\2)", _prose_only(part).raw))
        elif visible_width(part) > config.fit_width or (
            r"\frac" in part and visible_width(part) > INLINE_FRACTION_WIDTH
        ):
            # the punctuation right after a displayed formula ends the display, not the next line
            stop = re.match(r"[.,;:]", parts[k + 1]) if k + 1 < len(parts) else None
            if stop:
                part += stop.group()
                parts[k + 1] = parts[k + 1][1:].lstrip()
            lines = break_source(part, config.max_width)
            if len(lines) == 1:
                out.append(r"\[" + fit(lines[0], config).raw + r"\]")
            else:
                body = " \\\\\n".join(fit(x, config).raw for x in lines)
                out.append("\n\\begin{multline*}\n" + body + "\n\\end{multline*}\n")
        else:
            out.append("$" + part + "$")
    return Latex("".join(out))
