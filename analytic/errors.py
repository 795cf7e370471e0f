"""The one error type for bad input, and exact parsing of user numbers, shared by every package.

:mod:`analytic` and :mod:`verify` both check what users pass in; this module is the neutral place
both may import (``analytic`` never imports ``verify``).  The command line turns an
:class:`InputError` into ``paramres: error: ...`` and exit status 2.
"""

from __future__ import annotations

import math
import re
from fractions import Fraction

__all__ = ["InputError", "parse_rational", "NUMBER"]

#: a decimal or a fraction, as users type them: ``0.3``, ``3/5``, ``1e-12``
NUMBER = re.compile(r"[+-]?(\d+(\.\d*)?|\.\d+)([eE][+-]?\d+)?(/\d+)?")

#: decimal exponents beyond this are refused before any arithmetic (a huge exponent would make
#: the exact rational itself astronomically large)
MAX_EXPONENT = 4000


class InputError(ValueError):
    """A value outside what the engine accepts; the message names the value and the range."""


def parse_rational(value, what: str, allowed: str) -> Fraction:
    """``value`` (str, int, Fraction, float) as an exact Fraction; a float means its shortest
    decimal (``0.3`` is ``3/10``), as on the command line."""
    if isinstance(value, bool):
        raise InputError(f"{what} = {value!r} is not a number; allowed range {allowed}")
    if isinstance(value, Fraction):
        return value
    if isinstance(value, int):
        return Fraction(value)
    if isinstance(value, float):
        if not math.isfinite(value):
            raise InputError(f"{what} = {value!r} is not finite; allowed range {allowed}")
        return Fraction(repr(value))
    text = str(value).strip()
    mt = NUMBER.fullmatch(text)
    if not mt:
        raise InputError(
            f"{what} = {value!r} is not a number (use e.g. 0.3, 3/5 or 1e-12); "
            f"allowed range {allowed}"
        )
    exp = mt.group(3)
    if exp and abs(int(exp[1:])) > MAX_EXPONENT:
        raise InputError(f"{what} = {value!r} has an exponent too large; allowed range {allowed}")
    try:
        return Fraction(text)
    except ZeroDivisionError:
        raise InputError(f"{what} = {value!r} divides by zero; allowed range {allowed}") from None
