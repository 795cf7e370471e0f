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

__all__ = ["printed_error", "printed_bound", "largest_bound", "bound_text", "exact"]


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
        xv = getattr(x, "_mpf_", None)
        rv = getattr(radius, "_mpf_", None)
        if xv is None or rv is None:  # not mpmath numbers
            p = Fraction(text[0]) * Fraction(10) ** text[1] if isinstance(text, tuple) else text
            f = abs(Fraction(p) - exact(x)) + exact(radius)
            parts = (f.numerator, f.denominator)
        else:
            D, k = text if type(text) is tuple else _decimal(text)
            parts = _parts(D, k, xv, rv)
        if best is None or parts[0] * best[1] > best[0] * parts[1]:
            best = parts
    return None if best is None else _bound_text(best[0], best[1], 2)


def largest_bound(items) -> str | None:
    """:func:`printed_bound` of raw items ``((D, k), xv, rv)``: the printed value ``D 10**k`` of
    a number whose raw mpf is ``xv``, with the raw mpf ``rv`` of its radius (``None`` for no
    items).  All errors on one scale ``2**-a 10**-b``, so that the largest is that of integers."""
    b = a = 0
    for (_, k), xv, rv in items:
        if k < b:
            b = k
        if xv[2] < a:
            a = xv[2]
        if rv[2] < a:
            a = rv[2]
    scale10 = _POW10.get(-b) or _pow10(-b)
    best = -1
    for (D, k), (xs, xm, xe, _), (_, rm, re, _) in items:
        A = (D if k == b else D * (_POW10.get(k - b) or _pow10(k - b))) << -a
        B = (xm * scale10) << (xe - a)
        num = (abs(A + B) if xs else abs(A - B)) + ((rm * scale10) << (re - a))
        if num > best:
            best = num
    return None if best < 0 else _scaled_bound_text(best, a, b, 2)


def _error_parts(text, x, radius) -> tuple[int, int] | None:
    """``(num, den)`` with ``printed_error(text, x, radius) = num / den`` (not reduced;
    ``den > 0``), or ``None`` unless ``x`` and ``radius`` are mpmath numbers."""
    xv = getattr(x, "_mpf_", None)
    rv = getattr(radius, "_mpf_", None)
    if xv is None or rv is None:  # not mpmath numbers
        return None
    D, k = text if type(text) is tuple else _decimal(text)
    return _parts(D, k, xv, rv)


def _parts(D: int, k: int, xv: tuple, rv: tuple) -> tuple[int, int]:
    """``(num, den)`` with ``num / den = |D 10**k - x| + r`` exactly (not reduced; ``den > 0``),
    for the raw mpf ``xv`` of ``x`` and ``rv`` of ``r``: in integers on one common scale
    ``2**-a 10**-b``."""
    xs, xm, xe, _ = xv
    _, rm, re, _ = rv
    e2 = min(xe, re, 0)
    if k < 0:
        scale10 = _POW10.get(-k) or _pow10(-k)
        A = D << -e2
    else:
        scale10 = 1
        A = D * (_POW10.get(k) or _pow10(k)) << -e2
    B = (xm * scale10) << (xe - e2)
    if xs:
        B = -B
    return abs(A - B) + ((rm * scale10) << (re - e2)), scale10 << -e2


def _decimal(text: str) -> tuple[int, int]:
    """``(D, k)`` with ``value(text) = D 10**k`` exactly, for the decimals the engine prints
    (``"-1.2345e-7"``, ``"0.00123"``, ``"12"``)."""
    mant, _, ex = text.lower().partition("e")
    whole, _, frac = mant.partition(".")
    return _integer(whole + frac), (int(ex) if ex else 0) - len(frac)


#: digits converted by one ``int()`` (below Python's limit on integer string conversion, 4300)
_CHUNK = 4000


def _integer(digits: str) -> int:
    """``int(digits)`` for any length: a print of 10000 digits is beyond the single conversion
    Python allows, so longer texts are read in chunks."""
    if len(digits) <= _CHUNK:
        return int(digits)
    sign = -1 if digits[0] == "-" else 1
    body = digits.lstrip("+-")
    value = 0
    for i in range(0, len(body), _CHUNK):
        chunk = body[i : i + _CHUNK]
        value = value * 10 ** len(chunk) + int(chunk)
    return sign * value


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
    # e: 10**e <= num/den < 10**(e+1).  Start from e <= that one: num/den > 2**(d-1) with d the
    # difference of the bit lengths, and 10**e' <= 2**(d-1) for the e' below; the true e is e'
    # or e' + 1 (num/den < 2**(d+1), and 2 log10(2) < 1)
    e = math.floor((num.bit_length() - den.bit_length() - 1) * _LOG10_2)
    s = digits - 1 - e
    if s >= 0:
        mant = -((-num * (_POW10.get(s) or _pow10(s))) // den)  # ceiling
    else:
        mant = -((-num) // (den * (_POW10.get(-s) or _pow10(-s))))
    # too large by a factor 10 where e was one too small, and 10**digits where the ceiling
    # carried into the next power of ten: ceil(ceil(y) / 10) = ceil(y / 10)
    top = _POW10.get(digits) or _pow10(digits)
    while mant >= top:
        mant = -(-mant // 10)
        e += 1
    head = str(mant)
    return f"{head[0]}.{head[1:]}e{e}" if digits > 1 else f"{head}e{e}"


def _scaled_bound_text(num: int, a: int, b: int, digits: int) -> str:
    """:func:`bound_text` of ``num 2**a 10**b`` (``num >= 0``): :func:`_bound_text` without the
    long division where the bound is a few digits on the scale it was computed on."""
    if num == 0:
        return "0"
    # e <= the exponent of the leading digit, and at most one or two below it: num 2**a 10**b >=
    # 2**(bits-1+a) 10**b (the margin keeps a rounded product off the next integer)
    e = math.floor((num.bit_length() - 1 + a) * _LOG10_2 - 1e-9) + b
    t = b + digits - 1 - e  # the digits' scale: ceil(num 2**a 10**t)
    if t >= 0:
        X = num * (_POW10.get(t) or _pow10(t))
        mant = X << a if a >= 0 else -((-X) >> -a)
    elif a >= 0:
        mant = -((-(num << a)) // (_POW10.get(-t) or _pow10(-t)))
    else:
        mant = -((-num) // ((_POW10.get(-t) or _pow10(-t)) << -a))
    top = _POW10.get(digits) or _pow10(digits)
    while mant >= top:  # e below the leading digit, or the ceiling carried: ceil(ceil(y)/10)
        mant = -(-mant // 10)
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
