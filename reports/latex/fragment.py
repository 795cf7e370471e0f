"""The LaTeX value type, :class:`Latex`, and how plain text becomes one: :func:`text` escapes
it (known non-ASCII characters become their LaTeX forms), :func:`raw` takes markup as written,
:func:`ref` a cross-reference."""

from __future__ import annotations

import re
from collections.abc import Iterable
from dataclasses import dataclass

from ..i18n import current, tr

__all__ = ["Latex", "text", "raw", "ref"]


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


def ref(kind: str, label: str) -> Latex:
    """A cross-reference with a non-breaking space: ``ref("Section", "sec:model")``."""
    return Latex(f"{text(kind).raw}~\\ref{{{label}}}")


def raw(s: str) -> Latex:
    """LaTeX source written by the caller (markup, never a result); prose in it is translated
    when the report is built in another language (:func:`reports.i18n.tr`)."""
    return Latex(tr(s))
