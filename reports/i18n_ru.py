"""Russian versions of the report's prose (see :mod:`reports.i18n`), in the paper's own terms:
интервал параметрической неустойчивости, глубина модуляции, добротность, период модуляции.

``PHRASES`` maps an English string, exactly as the report or the engine writes it, to its Russian
version; ``PATTERNS`` are ``(regular expression, replacement)`` pairs for strings that carry numbers
or formulas.  A string with no entry is left in English.
"""

from __future__ import annotations

__all__ = ["PHRASES", "PATTERNS"]

PHRASES: dict[str, str] = {}

PATTERNS: list[tuple[str, object]] = []
