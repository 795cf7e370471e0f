"""The report's sections, one module each, in reading order.

Every section module defines ``TITLE``, ``LABEL`` and ``build(ctx) -> Part``: the section's LaTeX
body (without its heading) and the figures it draws, computed from the engine's objects.  Optional:
``CACHED = False`` for a section that is cheap to build (it is not stored in the cache), and
``NEW_PAGE = True`` for one that starts on a new page.  A new chapter is one more module here and
one more name in :data:`SECTIONS`; prose in both languages is written with
:func:`reports.i18n.say`.  A section
whose engine parts are not present in this installation says so in the report instead of guessing
(:func:`missing`).
"""

from __future__ import annotations

import importlib
import sys
from collections.abc import Callable
from dataclasses import dataclass, field

from analytic.cache import Cache

from ..latex import DEFAULT, Config, Latex

__all__ = [
    "Part",
    "Context",
    "SECTIONS",
    "SECOND_PROCESS",
    "SECOND_SHARES",
    "AFTER_SECOND",
    "LONGEST_FIRST",
    "load",
    "shared",
]

#: section modules, in the order they appear
SECTIONS = (
    "introduction",
    "summary",
    "model",
    "stitching",
    "catalogue",
    "expansions",
    "closings",
    "family",
    "switching",
    "diagrams",
    "accuracy",
    "performance",
    "certification",
    "conclusions",
)


#: sections a cold build hands to a second process (:func:`reports.report.assemble` with
#: ``jobs=2``), in this order, the shared results (:func:`shared`) that process returns with
#: them, and the sections that need those results and are therefore built after it is done.  The
#: catalogue's derivations share the slow reductions (:mod:`analytic.reductions`) with the
#: stitching section, the threshold series (:mod:`analytic.thresholds`) with the expansions and
#: the closings (:func:`analytic.closings.closings`) with the closings section, so those go with
#: the catalogue, after it; the other sections need none of them.  A section waiting for the
#: second process may define ``prepare(ctx)``: what it shares with that process's sections,
#: computed there before the shared list (the summary: the closings and the leading thresholds).
SECOND_PROCESS = ("catalogue", "stitching", "expansions", "closings")
SECOND_SHARES = ("catalogue-rows", "closings-theorem", "threshold-leading")
AFTER_SECOND = ("summary", "conclusions")

#: the other sections of a cold build, the longest first (CPU seconds of a cold build: the
#: switching section 5 to 7, the speed section about 5, the diagrams 3.5, the family 2 to 3,
#: the rest 1.5 or less).  Both processes take the next one from this list when they are free --
#: the first from the start, the second after its own sections -- so the slow sections are
#: spread over both processes whatever the second process's own sections cost.  A section not
#: named here comes after these, in reading order.
LONGEST_FIRST = (
    "switching",
    "performance",
    "diagrams",
    "family",
    "accuracy",
    "model",
    "closings",
)


@dataclass(frozen=True)
class Part:
    """What a section contributes: its body and its figures ``(file name, PDF bytes)``."""

    body: Latex
    figures: tuple[tuple[str, bytes], ...] = ()


@dataclass
class Context:
    """What every section gets: the LaTeX configuration, the cache for expensive work, and a
    logger for progress messages (to stderr)."""

    config: Config = DEFAULT
    cache: Cache = field(default_factory=lambda: Cache(None))
    log: Callable[[str], None] = field(default=lambda msg: print(msg, file=sys.stderr, flush=True))
    #: results computed once per build and shared between sections (see :func:`shared`)
    memo: dict = field(default_factory=dict)


def shared(ctx: Context, name: str, make: Callable[[], object]):
    """``make()`` computed once per build (and through the cache across builds), for results that
    more than one section shows, e.g. the summary up front and the section with the details."""
    if name not in ctx.memo:
        ctx.memo[name] = ctx.cache.get(name, make)
    return ctx.memo[name]


def load(name: str):
    """The section module ``name``."""
    return importlib.import_module(f"{__name__}.{name}")
