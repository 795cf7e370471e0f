"""Checking and normalising what users pass in: depth, order, quality factor, digits, ranges.

Every public entry point (API and CLI) goes through these, so that a bad value is refused in one
way everywhere: an :class:`InputError` whose message names the value and the allowed range.  The
CLI turns it into ``paramres: error: ...`` and exit status 2.
"""

from __future__ import annotations

import math
import re
from fractions import Fraction

import mpmath

__all__ = [
    "InputError",
    "as_depth",
    "as_order",
    "as_orders",
    "as_quality",
    "as_digits",
    "as_damping",
    "as_range",
    "as_tolerance",
    "as_period",
    "DIGITS_RANGE",
    "MAX_ORDER",
]

#: digits a high-precision result may be asked for (inclusive)
DIGITS_RANGE = (5, 10000)
#: the largest resonance order accepted
MAX_ORDER = 10000


class InputError(ValueError):
    """A value outside what the engine accepts; the message names the value and the range."""


def as_depth(m) -> Fraction | mpmath.mpf:
    """The modulation depth ``0 < m < 1``, kept exact where it can be.

    ``str`` (``"3/5"``, ``"0.3"``, ``"1e-12"``), ``int``, :class:`fractions.Fraction` become a
    ``Fraction`` (exact: ``"0.3"`` is ``3/10``); ``float`` becomes the ``Fraction`` of its binary
    value;
    an mpmath ``mpf`` is kept as it is.
    """
    if isinstance(m, bool):
        raise InputError(f"depth m = {m!r} is not a number; allowed range 0 < m < 1")
    try:
        if isinstance(m, Fraction):
            val = m
        elif isinstance(m, int):
            val = Fraction(m)
        elif isinstance(m, float):
            if not math.isfinite(m):
                raise InputError(f"depth m = {m!r} is not finite; allowed range 0 < m < 1")
            val = Fraction(m)
        elif isinstance(m, mpmath.mpf):
            if not mpmath.isfinite(m):
                raise InputError(f"depth m = {m} is not finite; allowed range 0 < m < 1")
            if not 0 < m < 1:
                raise InputError(f"depth m = {m} is outside the allowed range 0 < m < 1")
            return m
        elif isinstance(m, str):
            text = m.strip()
            if not re.fullmatch(r"[+-]?(\d+(\.\d*)?|\.\d+)([eE][+-]?\d+)?(/\d+)?", text):
                raise InputError(
                    f"depth m = {m!r} is not a number (use e.g. 0.3, 3/5 or 1e-12); allowed range "
                    "0 < m < 1"
                )
            val = Fraction(text)
        else:
            val = Fraction(str(m))
    except (ZeroDivisionError, ValueError) as exc:
        if isinstance(exc, InputError):
            raise
        raise InputError(f"depth m = {m!r} is not a number; allowed range 0 < m < 1") from None
    if not 0 < val < 1:
        raise InputError(f"depth m = {m} is outside the allowed range 0 < m < 1")
    return val


def as_order(n) -> int:
    """A resonance order: an integer ``1 <= n <= MAX_ORDER``."""
    if isinstance(n, bool):
        raise InputError(f"order must be an integer >= 1, got {n!r}")
    try:
        if isinstance(n, str):
            if not re.fullmatch(r"\s*[+-]?\d+\s*", n):
                raise InputError(f"order {n!r} is not an integer; allowed range 1 to {MAX_ORDER}")
            val = int(n)
        elif isinstance(n, float):
            if not (math.isfinite(n) and n == int(n)):
                raise InputError(f"order {n!r} is not an integer; allowed range 1 to {MAX_ORDER}")
            val = int(n)
        else:
            val = int(n)
            if val != n:
                raise InputError(f"order {n!r} is not an integer; allowed range 1 to {MAX_ORDER}")
    except (TypeError, ValueError) as exc:
        if isinstance(exc, InputError):
            raise
        raise InputError(f"order {n!r} is not an integer; allowed range 1 to {MAX_ORDER}") from None
    if not 1 <= val <= MAX_ORDER:
        raise InputError(f"order {val} is outside the allowed range 1 to {MAX_ORDER}")
    return val


def as_orders(spec) -> list[int]:
    """Orders from ``"1-6"``, ``"1,3,5"``, ``"2"``, or an iterable of integers; sorted, unique."""
    if isinstance(spec, str):
        out: set[int] = set()
        if not spec.strip():
            raise InputError("orders: empty list (use e.g. 1-6 or 1,3,5)")
        for part in spec.split(","):
            part = part.strip()
            mt = re.fullmatch(r"(\d+)\s*-\s*(\d+)", part)
            if mt:
                a, b = as_order(mt.group(1)), as_order(mt.group(2))
                if a > b:
                    raise InputError(f"orders: range {part!r} is empty (start > stop)")
                out.update(range(a, b + 1))
            else:
                out.add(as_order(part))
        return sorted(out)
    try:
        items = list(spec)
    except TypeError:
        return [as_order(spec)]
    if not items:
        raise InputError("orders: empty list")
    return sorted({as_order(i) for i in items})


def as_quality(Q) -> Fraction | mpmath.mpf | None:
    """The quality factor ``Q > 0`` (``None`` or ``"none"``/``"inf"``: no friction)."""
    if Q is None:
        return None
    if isinstance(Q, str) and Q.strip().lower() in ("none", "inf", "infinity"):
        return None
    if isinstance(Q, bool):
        raise InputError(f"quality factor Q must be a number > 0, got {Q!r}")
    try:
        if isinstance(Q, mpmath.mpf):
            val = Q
            ok = mpmath.isfinite(Q)
        elif isinstance(Q, float):
            ok = math.isfinite(Q)
            val = Fraction(Q) if ok else Q
        elif isinstance(Q, str):
            text = Q.strip()
            if not re.fullmatch(r"[+-]?(\d+(\.\d*)?|\.\d+)([eE][+-]?\d+)?(/\d+)?", text):
                raise InputError(f"quality factor Q = {Q!r} is not a number; allowed range Q > 0")
            val, ok = Fraction(text), True
        else:
            val, ok = Fraction(Q), True
    except (TypeError, ValueError, ZeroDivisionError) as exc:
        if isinstance(exc, InputError):
            raise
        raise InputError(f"quality factor Q = {Q!r} is not a number; allowed range Q > 0") from None
    if not ok:
        raise InputError(
            f"quality factor Q = {Q!r} must be finite (omit it for no friction); allowed range Q "
            "> 0"
        )
    if not val > 0:
        raise InputError(f"quality factor Q = {Q} is outside the allowed range Q > 0")
    return val


def as_digits(d) -> int:
    """Decimal digits for a high-precision result, ``DIGITS_RANGE[0] <= d <= DIGITS_RANGE[1]``."""
    lo, hi = DIGITS_RANGE
    try:
        if isinstance(d, bool):
            raise TypeError
        if isinstance(d, str):
            if not re.fullmatch(r"\s*\d+\s*", d):
                raise TypeError
            val = int(d)
        else:
            val = int(d)
            if val != d:
                raise TypeError
    except (TypeError, ValueError):
        raise InputError(f"digits {d!r} is not an integer; allowed range {lo} to {hi}") from None
    if not lo <= val <= hi:
        raise InputError(f"digits {val} is outside the allowed range {lo} to {hi}")
    return val


def as_damping(model) -> str:
    """``"exact"`` or ``"paper"``."""
    if not isinstance(model, str) or model.strip().lower() not in ("exact", "paper"):
        raise InputError(f"damping model {model!r} is not one of: exact, paper")
    return model.strip().lower()


_TOL_LOW = mpmath.mpf(10) ** (-DIGITS_RANGE[1])
_TOL_HIGH = mpmath.mpf("0.1")


def as_tolerance(tol) -> mpmath.mpf:
    """A relative tolerance ``10**-DIGITS_RANGE[1] <= tol <= 0.1``."""
    lo_text = f"1e-{DIGITS_RANGE[1]}"
    try:
        val = mpmath.mpf(tol.strip() if isinstance(tol, str) else tol)
    except (TypeError, ValueError):
        raise InputError(
            f"tolerance {tol!r} is not a number; allowed range {lo_text} to 0.1"
        ) from None
    if not mpmath.isfinite(val) or not (_TOL_LOW <= val <= _TOL_HIGH):
        raise InputError(f"tolerance {tol} is outside the allowed range {lo_text} to 0.1")
    return val


def as_range(
    spec: str, *, name: str = "m", low=Fraction(0), high=Fraction(1), max_points: int = 1_000_000
) -> list[Fraction]:
    """Values from ``"START:STOP:STEP"`` (``STOP`` included when hit exactly), all in ``(low,
    high)``.

    Exact (``Fraction``) arithmetic, so ``0.1:0.9:0.1`` has exactly nine points.
    """
    parts = spec.split(":") if isinstance(spec, str) else []
    if len(parts) != 3:
        raise InputError(f"{name} range {spec!r} is not START:STOP:STEP (e.g. 0.05:0.95:0.05)")
    try:
        start, stop, step = (Fraction(p.strip()) for p in parts)
    except (ValueError, ZeroDivisionError):
        raise InputError(f"{name} range {spec!r} has a part that is not a number") from None
    if step <= 0:
        raise InputError(f"{name} range {spec!r}: STEP must be > 0")
    if stop < start:
        raise InputError(f"{name} range {spec!r}: STOP must be >= START")
    if not (low < start and stop < high):
        raise InputError(f"{name} range {spec!r} leaves the allowed range {low} < {name} < {high}")
    count = int((stop - start) / step) + 1
    if count > max_points:
        raise InputError(f"{name} range {spec!r} has {count} points; at most {max_points} allowed")
    return [start + k * step for k in range(count)]


#: the largest modulation period accepted, in units of T0
MAX_PERIOD = 10**6


def as_period(T, *, name: str = "period T/T0") -> Fraction | mpmath.mpf:
    """A modulation period in units of ``T0``, ``0 < T <= MAX_PERIOD``, kept exact where it can be
    (the same conversions as :func:`as_depth`)."""
    if isinstance(T, bool):
        raise InputError(f"{name} must be a number > 0, got {T!r}")
    try:
        if isinstance(T, mpmath.mpf):
            if not mpmath.isfinite(T):
                raise InputError(f"{name} must be finite, got {T}")
            val = T
        elif isinstance(T, float):
            if not math.isfinite(T):
                raise InputError(f"{name} must be finite, got {T!r}")
            val = Fraction(T)
        elif isinstance(T, str):
            text = T.strip()
            if not re.fullmatch(r"[+-]?(\d+(\.\d*)?|\.\d+)([eE][+-]?\d+)?(/\d+)?", text):
                raise InputError(
                    f"{name} = {T!r} is not a number; allowed range 0 < T <= {MAX_PERIOD}"
                )
            val = Fraction(text)
        else:
            val = Fraction(T)
    except (TypeError, ValueError, ZeroDivisionError) as exc:
        if isinstance(exc, InputError):
            raise
        raise InputError(
            f"{name} = {T!r} is not a number; allowed range 0 < T <= {MAX_PERIOD}"
        ) from None
    if not 0 < val <= MAX_PERIOD:
        raise InputError(f"{name} = {T} is outside the allowed range 0 < T <= {MAX_PERIOD}")
    return val
