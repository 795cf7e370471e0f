"""How wide typeset math is, roughly, in characters: :func:`visible_width`, used to decide where
to break a displayed formula and when to scale it."""

from __future__ import annotations

import re

from .fragment import Latex

__all__ = ["visible_width"]

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
