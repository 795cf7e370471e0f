"""Error bounds of the decimals the engine prints.

A certified value comes as a ball: a midpoint ``x`` and a radius ``r`` with ``|x - exact| <= r``.
What a user reads is a *rounded* decimal ``p`` of ``x``, so the honest bound of what is printed is
``|p - exact| <= |p - x| + r`` -- the rounding of the print included.  :func:`printed_error`
computes that bound exactly (rational arithmetic) and :func:`bound_text` writes a bound rounded
*up* to two significant digits, so the printed bound is never smaller than the true one.

>>> from fractions import Fraction
>>> import mpmath
>>> x = mpmath.mpf(1) / 3
>>> bound_text(printed_error("0.3333", x, mpmath.mpf(2) ** -60))
'3.4e-5'
"""

from __future__ import annotations

import math
from fractions import Fraction

import mpmath

__all__ = ["printed_error", "printed_bound", "bound_text", "exact"]


def exact(x) -> Fraction:
    """The exact rational value of an mpmath number (or int, Fraction, decimal text)."""
    if isinstance(x, mpmath.mpf):
        sign, man, exp, _ = x._mpf_  # (man_exp drops the sign)
        return (-1 if sign else 1) * Fraction(man) * Fraction(2) ** exp
    return Fraction(x)


def printed_error(text: str | None, x, radius) -> Fraction | None:
    """A bound of ``|value(text) - exact|`` when ``|x - exact| <= radius``; ``None`` when there is
    nothing printed or no radius (an uncertified value)."""
    if text is None or radius is None or x is None:
        return None
    parts = _error_parts(text, x, radius)
    if parts is None:
        return abs(Fraction(text) - exact(x)) + exact(radius)
    return Fraction(*parts)


def printed_bound(items) -> str | None:
    """:func:`bound_text` of the largest :func:`printed_error` over ``(text, x, radius)`` items
    (items without a bound skipped; ``None`` if none has one) -- the same text, in integers
    without reducing fractions.  ``text`` may also be ``(D, k)``, the printed value ``D 10**k``
    (the text already read)."""
    best = None
    for text, x, radius in items:
        if text is None or radius is None or x is None:
            continue
        parts = _error_parts(text, x, radius)
        if parts is None:
            p = Fraction(text[0]) * Fraction(10) ** text[1] if isinstance(text, tuple) else text
            f = abs(Fraction(p) - exact(x)) + exact(radius)
            parts = (f.numerator, f.denominator)
        if best is None or parts[0] * best[1] > best[0] * parts[1]:
            best = parts
    return None if best is None else _bound_text(best[0], best[1], 2)


def _error_parts(text, x, radius) -> tuple[int, int] | None:
    """``(num, den)`` with ``printed_error(text, x, radius) = num / den`` (not reduced;
    ``den > 0``), or ``None`` unless ``x`` and ``radius`` are mpmath numbers."""
    xv = getattr(x, "_mpf_", None)
    rv = getattr(radius, "_mpf_", None)
    if xv is None or rv is None:  # not mpmath numbers
        return None
    # in integers on one common scale 2^-a 10^-b
    D, k = text if type(text) is tuple else _decimal(text)
    xs, xm, xe, _ = xv
    _, rm, re, _ = rv
    X = -xm if xs else xm
    e2 = min(xe, re, 0)
    k10 = min(k, 0)
    scale10 = _pow10(-k10)
    A = D * _pow10(k - k10) << (-e2)
    B = (X << (xe - e2)) * scale10
    C = (rm << (re - e2)) * scale10
    return abs(A - B) + C, scale10 << (-e2)


def _decimal(text: str) -> tuple[int, int]:
    """``(D, k)`` with ``value(text) = D 10**k`` exactly, for the decimals the engine prints
    (``"-1.2345e-7"``, ``"0.00123"``, ``"12"``)."""
    mant, _, ex = text.lower().partition("e")
    whole, _, frac = mant.partition(".")
    return int(whole + frac), (int(ex) if ex else 0) - len(frac)


def bound_text(bound: Fraction | None, digits: int = 2) -> str | None:
    """``bound`` rounded up to ``digits`` significant digits, as ``"3.4e-5"`` (``"0"`` for 0)."""
    if bound is None:
        return None
    bound = Fraction(bound)
    return _bound_text(bound.numerator, bound.denominator, digits)


def _bound_text(num: int, den: int, digits: int) -> str:
    """:func:`bound_text` of ``num / den`` (``num >= 0``, ``den > 0``, not necessarily reduced)."""
    if num == 0:
        return "0"

    def at_least(e: int) -> bool:  # num / den >= 10**e
        return num >= den * _pow10(e) if e >= 0 else num * _pow10(-e) >= den

    # the exponent e with 10**e <= bound < 10**(e+1): estimated from the bit lengths, then fixed
    e = math.floor((num.bit_length() - den.bit_length()) * _LOG10_2)
    while not at_least(e):
        e -= 1
    while at_least(e + 1):
        e += 1
    s = digits - 1 - e
    if s >= 0:
        mant = -((-num * _pow10(s)) // den)  # ceiling
    else:
        mant = -((-num) // (den * _pow10(-s)))
    if mant >= 10**digits:  # rounded up to the next power of ten
        mant //= 10
        e += 1
    head = str(mant)
    return f"{head[0]}.{head[1:]}e{e}" if digits > 1 else f"{head}e{e}"


_LOG10_2 = math.log10(2)
_POW10: dict[int, int] = {}


def _pow10(n: int) -> int:
    """``10**n`` (``n >= 0``), kept for ``n < 2000``: the same few powers recur."""
    p = _POW10.get(n)
    if p is None:
        p = 10**n
        if n < 2000:
            _POW10[n] = p
    return p
