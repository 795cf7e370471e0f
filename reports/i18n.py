"""The report's language: one structure and one set of formulas, the prose in English or Russian.

The language of the document being built is held for the duration of a build by
:func:`language` (a context manager; nothing is set outside it).  Prose reaches LaTeX through
:func:`reports.latex.text`, :func:`~reports.latex.prose`, :func:`~reports.latex.mixed` and
:func:`~reports.latex.raw`; each passes its string through :func:`tr`, which returns the Russian
version from :data:`reports.i18n_ru.PHRASES` (whole strings) or :data:`~reports.i18n_ru.PATTERNS`
(templates with numbers or formulas in them) when the language is Russian, and the string itself
otherwise.  New prose is best written with both versions side by side: :func:`say`.

>>> with language("ru"):
...     say("order", "порядок")
'порядок'
>>> say("order", "порядок")
'order'
"""

from __future__ import annotations

import contextvars
import re
from collections.abc import Iterator
from contextlib import contextmanager

__all__ = ["LANGUAGES", "language", "current", "tr", "say"]

#: the languages the report is written in
LANGUAGES = ("en", "ru")

_LANG: contextvars.ContextVar[str] = contextvars.ContextVar(
    "paramres_report_language", default="en"
)


@contextmanager
def language(lang: str) -> Iterator[str]:
    """Build in ``lang`` (one of :data:`LANGUAGES`) inside the ``with`` block."""
    if lang not in LANGUAGES:
        raise ValueError(f"language {lang!r} is not one of {', '.join(LANGUAGES)}")
    token = _LANG.set(lang)
    try:
        yield lang
    finally:
        _LANG.reset(token)


def current() -> str:
    """The language being built (``"en"`` outside :func:`language`)."""
    return _LANG.get()


def say(en: str, ru: str) -> str:
    """The English or the Russian version, whichever language is being built."""
    return ru if _LANG.get() == "ru" else en


def tr(s: str) -> str:
    """``s`` in the language being built: itself in English; in Russian its translation when one
    is known (the whole string, or a template of :data:`reports.i18n_ru.PATTERNS`), else itself."""
    if not s or s.isspace():
        return s
    from .phrasebook import lookup

    hit = lookup(s, _LANG.get())
    if hit is not None:
        return hit
    if _LANG.get() == "en":
        return s
    from .i18n_ru import PATTERNS, PHRASES

    hit = PHRASES.get(s)
    if hit is not None:
        return hit
    core = s.strip()
    hit = PHRASES.get(core)
    if hit is not None:
        return s[: len(s) - len(s.lstrip())] + hit + s[len(s.rstrip()) :]
    for pattern, template in PATTERNS:
        m = re.fullmatch(pattern, core, flags=re.S)
        if m:
            out = template(m) if callable(template) else m.expand(template)
            return s[: len(s) - len(s.lstrip())] + out + s[len(s.rstrip()) :]
    return s
