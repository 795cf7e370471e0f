"""Checking and normalising what users pass in: depth, order, quality factor, digits, ranges.

Every public entry point (API and CLI) goes through these, so that a bad value is refused in one
way everywhere: an :class:`InputError` whose message names the value and the allowed range.  The
CLI turns it into ``paramres: error: ...`` and exit status 2.
"""

from __future__ import annotations

import math
import re
from fractions import Fraction
from functools import lru_cache

import mpmath

__all__ = [
    "InputError",
    "as_number",
    "as_integer",
    "MIN_DEPTH",
    "Q_RANGE",
    "MAX_PERIOD",
    "as_depth",
    "as_order",
    "as_orders",
    "as_quality",
    "as_digits",
    "as_damping",
    "as_range",
    "as_tolerance",
    "as_period",
    "MODULATIONS",
    "as_switch_time",
    "as_modulation",
    "DIGITS_RANGE",
    "BOUNDARY_DIGITS_RANGE",
    "EXISTENCE_DIGITS_RANGE",
    "MAX_ORDER",
]

#: digits a high-precision result may be asked for (inclusive)
DIGITS_RANGE = (5, 10000)
#: digits of a certified boundary (:func:`verify.solve.boundary`; the solver's time grows about
#: as ``D^1.6``: 100000 digits take seconds)
BOUNDARY_DIGITS_RANGE = (5, 100000)
#: digits of a proven threshold (:func:`verify.existence.existence`): its depth ranges are split
#: down to the resolution, and next to ``m = 1`` far below it a range's parameters are no doubles
EXISTENCE_DIGITS_RANGE = (5, 3000)
#: the largest resonance order accepted
MAX_ORDER = 10000
#: the smallest depth accepted (text: ``1e-1000``)
MIN_DEPTH_EXPONENT = 1000
MIN_DEPTH = Fraction(1, 10**MIN_DEPTH_EXPONENT)
#: the range of quality factors accepted (beyond ``Q_RANGE[1]`` friction is far below any
#: printed digit: omit ``Q``)
Q_RANGE = (Fraction(1, 10**6), Fraction(10**30))
#: the longest text of a number accepted, and the largest decimal exponent written in one: both
#: are checked before any arithmetic, so that ``1e999999999`` is refused at once
MAX_NUMBER_TEXT = 2000
MAX_EXPONENT = 10000  # the smallest tolerance, 1e-10000, can be typed

_NUMBER = re.compile(r"[+-]?(\d+(\.\d*)?|\.\d+)([eE]([+-]?\d+))?(/\d+)?")


def as_number(value, *, name: str, allowed: str) -> Fraction:
    """``value`` (text such as ``"0.3"``, ``"3/5"``, ``"1e-12"``; an int, Fraction or float) as an
    exact :class:`~fractions.Fraction`.  A float means its shortest decimal (``0.1`` is ``1/10``,
    as on the command line).  Text longer than :data:`MAX_NUMBER_TEXT` or with an exponent beyond
    :data:`MAX_EXPONENT` is refused before any arithmetic.  ``name`` and ``allowed`` word the
    message of the :class:`InputError` for anything else."""
    kind = type(value)
    if kind is str:  # the common cases first, by exact type (an isinstance check against
        # Fraction, an abstract base class's subclass, costs more than the rest of the check)
        parsed = _parsed(value.strip())
        if parsed is not None:
            return parsed
    elif kind is int:
        return Fraction(value)
    elif kind is Fraction:
        return value
    if isinstance(value, bool):
        raise InputError(f"{name} = {value!r} is not a number; allowed range {allowed}")
    if isinstance(value, Fraction):
        return value
    if isinstance(value, int):
        return Fraction(value)
    if isinstance(value, float):
        if not math.isfinite(value):
            raise InputError(f"{name} = {value!r} is not finite; allowed range {allowed}")
        return Fraction(repr(float(value)))  # np.float64 too
    if not isinstance(value, str):
        raise InputError(f"{name} = {value!r} is not a number; allowed range {allowed}")
    text = value.strip()
    parsed = _parsed(text)
    if parsed is not None:
        return parsed
    shown = text if len(text) <= 60 else text[:40] + "..." + text[-10:]
    if len(text) > MAX_NUMBER_TEXT:
        raise InputError(
            f"{name} = {shown!r} has more than {MAX_NUMBER_TEXT} characters; allowed range "
            f"{allowed}"
        )
    mt = _NUMBER.fullmatch(text)
    if not mt:
        raise InputError(
            f"{name} = {shown!r} is not a number (use e.g. 0.3, 3/5 or 1e-12); allowed range "
            f"{allowed}"
        )
    exponent = mt.group(4)
    if exponent is not None and abs(int(exponent)) > MAX_EXPONENT:
        raise InputError(f"{name} = {shown} is outside the allowed range {allowed}")
    try:
        return _fraction(text)
    except ZeroDivisionError:
        raise InputError(f"{name} = {shown} divides by zero; allowed range {allowed}") from None


@lru_cache(maxsize=1024)
def _parsed(text: str) -> Fraction | None:
    """The exact value of a well-formed number text (as :func:`as_number` checks it), or
    ``None`` for anything :func:`as_number` must refuse (it then words the message)."""
    if len(text) > MAX_NUMBER_TEXT:
        return None
    mt = _NUMBER.fullmatch(text)
    if not mt:
        return None
    exponent = mt.group(4)
    if exponent is not None and abs(int(exponent)) > MAX_EXPONENT:
        return None
    try:
        return _fraction(text)
    except ZeroDivisionError:
        return None


def _fraction(text: str) -> Fraction:
    """The value of a text :data:`_NUMBER` matches: ``Fraction`` itself reads a decimal or an
    integer ratio, not a decimal over an integer (``0.3/2``, ``1e-1/3``), so the two parts are
    read apart."""
    num, slash, den = text.partition("/")
    if not slash:
        return Fraction(num)
    return Fraction(num) / int(den)


class InputError(ValueError):
    """A value outside what the engine accepts; the message names the value and the range."""


def as_depth(m) -> Fraction | mpmath.mpf:
    """The modulation depth ``MIN_DEPTH <= m < 1``, kept exact where it can be.

    ``str`` (``"3/5"``, ``"0.3"``, ``"1e-12"``), ``int``, :class:`fractions.Fraction` become a
    ``Fraction`` (exact: ``"0.3"`` is ``3/10``); a ``float`` means its shortest decimal (``0.3`` is
    ``3/10``, as on the command line); an mpmath ``mpf`` is kept as it is (its binary value).
    """
    allowed = f"0 < m < 1 (m >= 1e-{MIN_DEPTH_EXPONENT})"
    if isinstance(m, mpmath.mpf):
        if not mpmath.isfinite(m):
            raise InputError(f"depth m = {m} is not finite; allowed range {allowed}")
        if not MIN_DEPTH <= _mpf_fraction(m) < 1:
            raise InputError(f"depth m = {m} is outside the allowed range {allowed}")
        return m
    val = as_number(m, name="depth m", allowed=allowed)
    if not _depth_ok(val.numerator, val.denominator):
        raise InputError(f"depth m = {_show(m)} is outside the allowed range {allowed}")
    return val


def _depth_ok(p: int, q: int) -> bool:
    """``MIN_DEPTH <= p/q < 1`` (``q > 0``), in integers (a comparison of Fractions costs more
    than a certified edge's proof at 15 digits)."""
    return 0 < p < q and p * _MIN_DEPTH_PQ[1] >= q * _MIN_DEPTH_PQ[0]


_MIN_DEPTH_PQ = (MIN_DEPTH.numerator, MIN_DEPTH.denominator)
_Q_RANGE_PQ = tuple((x.numerator, x.denominator) for x in Q_RANGE)


def _show(value) -> str:
    text = str(value).strip()
    return text if len(text) <= 60 else text[:40] + "..." + text[-10:]


def _mpf_fraction(x) -> Fraction:
    """The exact value of a finite mpmath number (``man_exp`` drops the sign: use the word)."""
    sign, man, exp, _ = x._mpf_
    return (-1 if sign else 1) * Fraction(man) * Fraction(2) ** exp


def as_integer(value, *, name: str, low: int, high: int) -> int:
    """An integer ``low <= value <= high`` given as text (``"12"``), an int, or an integral float;
    text of more than 30 characters is refused before conversion."""
    if type(value) is int and low <= value <= high:  # the common case, checked at once
        return value
    allowed = f"{low} to {high}"
    if isinstance(value, bool):
        raise InputError(f"{name} {value!r} is not an integer; allowed range {allowed}")
    if isinstance(value, str):
        text = value.strip()
        if len(text) > 30 and re.fullmatch(r"[+-]?\d+", text):
            raise InputError(f"{name} {_show(text)} is outside the allowed range {allowed}")
        if not re.fullmatch(r"[+-]?\d{1,30}", text):
            raise InputError(f"{name} {_show(value)!r} is not an integer; allowed range {allowed}")
        val = int(text)
    elif isinstance(value, float):
        if not (math.isfinite(value) and value == int(value)):
            raise InputError(f"{name} {value!r} is not an integer; allowed range {allowed}")
        val = int(value)
    else:
        try:
            val = int(value)
            ok = val == value
        except (TypeError, ValueError, OverflowError):
            ok = False
        if not ok:
            raise InputError(f"{name} {_show(value)!r} is not an integer; allowed range {allowed}")
    if not low <= val <= high:
        raise InputError(f"{name} {_show(val)} is outside the allowed range {allowed}")
    return val


def as_order(n) -> int:
    """A resonance order: an integer ``1 <= n <= MAX_ORDER``."""
    return as_integer(n, name="order", low=1, high=MAX_ORDER)


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
    """The quality factor, ``Q_RANGE[0] <= Q <= Q_RANGE[1]`` (``None`` or ``"none"``/``"inf"``:
    no friction), exact like :func:`as_depth` (an mpmath ``mpf`` is kept)."""
    if Q is None:
        return None
    kind = type(Q)
    if kind is int:  # the common cases first, by exact type (as as_number); else as below
        got = _INT_QUALITY.get(Q)  # (a Fraction is immutable: the one made before will do)
        if got is not None:
            return got
        if _quality_ok(Q, 1):
            got = Fraction(Q)
            if len(_INT_QUALITY) < 256:
                _INT_QUALITY[Q] = got
            return got
    elif kind is Fraction and _quality_ok(Q.numerator, Q.denominator):
        return Q
    if isinstance(Q, str) and Q.strip().lower() in ("none", "inf", "infinity"):
        return None
    lo, hi = Q_RANGE
    allowed = "1e-6 <= Q <= 1e30 (omit Q for no friction)"
    if isinstance(Q, mpmath.mpf):
        if not mpmath.isfinite(Q):
            raise InputError(f"quality factor Q = {Q} must be finite; allowed range {allowed}")
        if not lo <= _mpf_fraction(Q) <= hi:
            raise InputError(f"quality factor Q = {Q} is outside the allowed range {allowed}")
        return Q
    val = as_number(Q, name="quality factor Q", allowed=allowed)
    if not _quality_ok(val.numerator, val.denominator):
        raise InputError(f"quality factor Q = {_show(Q)} is outside the allowed range {allowed}")
    return val


#: the integer quality factors met so far (in range), as Fractions (making one costs more than the
#: lookup)
_INT_QUALITY: dict[int, Fraction] = {}


def _quality_ok(p: int, q: int) -> bool:
    """``Q_RANGE[0] <= p/q <= Q_RANGE[1]`` (``q > 0``), in integers (as :func:`_depth_ok`)."""
    (lp, lq), (hp, hq) = _Q_RANGE_PQ
    return p * lq >= q * lp and p * hq <= q * hp


def as_digits(d, allowed: tuple[int, int] = DIGITS_RANGE) -> int:
    """Decimal digits for a high-precision result, ``allowed[0] <= d <= allowed[1]``
    (:data:`DIGITS_RANGE` unless the caller allows more, as the certified boundary does with
    :data:`BOUNDARY_DIGITS_RANGE`)."""
    return as_integer(d, name="digits", low=allowed[0], high=allowed[1])


def as_damping(model) -> str:
    """``"exact"`` or ``"paper"``."""
    if type(model) is str and (model == "exact" or model == "paper"):  # the common case
        return model
    if not isinstance(model, str) or model.strip().lower() not in ("exact", "paper"):
        raise InputError(f"damping model {_show(repr(model))} is not one of: exact, paper")
    return model.strip().lower()


_TOL_LOW = Fraction(1, 10 ** DIGITS_RANGE[1])
_TOL_HIGH = Fraction(1, 10)


def as_tolerance(tol) -> mpmath.mpf:
    """A relative tolerance ``10**-DIGITS_RANGE[1] <= tol <= 0.1`` (as an mpmath number)."""
    allowed = f"1e-{DIGITS_RANGE[1]} to 0.1"
    if isinstance(tol, mpmath.mpf):
        if not mpmath.isfinite(tol) or not _TOL_LOW <= _mpf_fraction(tol) <= _TOL_HIGH:
            raise InputError(f"tolerance {tol} is outside the allowed range {allowed}")
        return tol
    val = as_number(tol, name="tolerance", allowed=allowed)
    if not _TOL_LOW <= val <= _TOL_HIGH:
        raise InputError(f"tolerance {_show(tol)} is outside the allowed range {allowed}")
    with mpmath.workprec(64):
        return mpmath.mpf(val.numerator) / val.denominator


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
    allowed = f"START:STOP:STEP with {low} < START <= STOP < {high}, STEP > 0"
    start, stop, step = (
        as_number(p, name=f"{name} range {_show(spec)!r}: {part}", allowed=allowed)
        for p, part in zip(parts, ("START", "STOP", "STEP"), strict=True)
    )
    if step <= 0:
        raise InputError(f"{name} range {spec!r}: STEP must be > 0")
    if stop < start:
        raise InputError(f"{name} range {spec!r}: STOP must be >= START")
    if name == "m" and start < MIN_DEPTH:
        raise InputError(
            f"m range {_show(spec)!r} leaves the allowed range 0 < m < 1 "
            f"(m >= 1e-{MIN_DEPTH_EXPONENT})"
        )
    if not (low < start and stop < high):
        raise InputError(f"{name} range {spec!r} leaves the allowed range {low} < {name} < {high}")
    if (stop - start) > step * max_points:
        raise InputError(
            f"{name} range {_show(spec)!r} has more than {max_points} points; at most "
            f"{max_points} allowed"
        )
    count = int((stop - start) / step) + 1
    return [start + k * step for k in range(count)]


#: the largest modulation period accepted, in units of T0
MAX_PERIOD = 10**6


def as_period(T, *, name: str = "period T/T0") -> Fraction | mpmath.mpf:
    """A modulation period in units of ``T0``, ``0 < T <= MAX_PERIOD``, kept exact where it can be
    (the same conversions as :func:`as_depth`)."""
    allowed = f"0 < T <= {MAX_PERIOD}"
    if isinstance(T, mpmath.mpf):
        if not mpmath.isfinite(T):
            raise InputError(f"{name} must be finite, got {T}")
        if not 0 < T <= MAX_PERIOD:
            raise InputError(f"{name} = {T} is outside the allowed range {allowed}")
        return T
    val = as_number(T, name=name, allowed=allowed)
    if not 0 < val <= MAX_PERIOD:
        raise InputError(f"{name} = {_show(T)} is outside the allowed range {allowed}")
    return val


#: the modulations of the length: the paper's jump, linear ramps, a sine
MODULATIONS = ("square", "ramp", "sine")


def as_switch_time(S) -> Fraction:
    """A switching time ``S >= 0`` (units ``T0``) as an exact Fraction (text, int, Fraction,
    float as its shortest decimal, or an mpmath number at its binary value)."""
    allowed = "0 <= S <= the shorter phase min(D, 1-D) T (units of T0)"
    if isinstance(S, mpmath.mpf):
        if not mpmath.isfinite(S):
            raise InputError(f"switching time S = {S} is not finite; allowed range {allowed}")
        v = _mpf_fraction(S)
    else:
        v = as_number(S, name="switching time S", allowed=allowed)
    if v < 0:
        raise InputError(f"switching time S = {_show(S)} is negative; allowed range {allowed}")
    return v


def as_modulation(modulation, switch_time=None, system=None) -> tuple[str, Fraction | None]:
    """``(kind, S)``: the modulation (one of :data:`MODULATIONS`) and, for ``ramp``, the
    switching time ``S`` (``None`` otherwise).  Refused: an unknown kind, a switching time
    without ``ramp``, ``ramp`` without one, ``ramp`` or ``sine`` for a system other than the
    pendulum (a ``System`` or its name), ``sine`` with a duty other than ``1/2``."""
    if type(modulation) is str and modulation == "square" and switch_time is None:
        return "square", None  # the default: nothing below applies to it
    kind = modulation.strip().lower() if isinstance(modulation, str) else None
    if kind not in MODULATIONS:
        raise InputError(
            f"modulation {_show(repr(modulation))} is not one of: {', '.join(MODULATIONS)}"
        )
    if kind != "ramp" and switch_time is not None:
        raise InputError(
            f"a switching time S = {_show(switch_time)} needs the ramp modulation "
            f"(--modulation ramp); the {kind} modulation has none"
        )
    if kind == "ramp" and switch_time is None:
        raise InputError("the ramp modulation needs a switching time S >= 0 (--switch-time S)")
    name = getattr(system, "name", system)
    if kind != "square" and name is not None and name != "pendulum":
        raise InputError(
            f"the {kind} modulation is implemented for the pendulum only, not for system {name!r}"
        )
    duty = getattr(system, "duty", None)
    if kind == "sine" and duty is not None and duty != Fraction(1, 2):
        raise InputError(
            f"the sine modulation has equal halves: duty D = {duty} is not allowed (only D = 1/2)"
        )
    return kind, (as_switch_time(switch_time) if kind == "ramp" else None)
