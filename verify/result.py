"""The result of a boundary computation: both edges of one interval, with their proof.

:class:`Boundary` is what every solver returns (:mod:`verify.methods`); :func:`proven_text` prints
a number with only the digits its proven radius supports.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field, fields
from fractions import Fraction
from operator import index as _index

import mpmath
from flint import fmpz
from mpmath.libmp import from_man_exp, to_str

from analytic.system import PAPER, System

from .certify import _make_mpf, exact_mpf, to_mpf
from .rounding import _POW10, _pow10, _scaled_bound_text, largest_bound, printed_bound

__all__ = ["Boundary", "from_balls", "proven_text", "fraction_text"]


class _once:
    """A property computed on first use and kept in the instance (``functools.cached_property``
    without its lock, which costs more than the texts it keeps, Python 3.11)."""

    def __init__(self, fn):
        self.fn = fn
        self.name = fn.__name__
        self.__doc__ = fn.__doc__

    def __set_name__(self, owner, name):
        self.name = name

    def __get__(self, obj, owner=None):
        if obj is None:
            return self
        value = self.fn(obj)
        obj.__dict__[self.name] = value
        return value


@dataclass(frozen=True)
class Boundary:
    """The ``order``-th interval of instability at depth ``m``: edges ``lower < upper`` in ``T/T0``.

    ``lower``/``upper`` are mpmath numbers (``None`` if the interval does not exist);
    ``delta_lower``/``delta_upper`` are ``T - n T_av/2`` in units of ``T0`` (``T_av`` of eq. 5, the
    undamped average period); ``radius`` bounds ``|returned - exact|`` for all four numbers
    (``T/T0`` units; ``None`` if not certified); ``lower_enclosure``/``upper_enclosure`` are proven
    ``(low, high)`` bounds of each edge.  ``method`` names the solver, ``regime`` the
    equations used.
    """

    order: int
    m: Fraction
    Q: Fraction | None
    damping: str
    digits: int
    method: str
    exists: bool
    lower: mpmath.mpf | None = None
    upper: mpmath.mpf | None = None
    delta_lower: mpmath.mpf | None = None
    delta_upper: mpmath.mpf | None = None
    radius: mpmath.mpf | None = None
    lower_enclosure: tuple | None = None
    upper_enclosure: tuple | None = None
    certified: bool = False
    regime: str = ""
    notes: tuple = field(default=())
    #: proven radii of ``lower, upper, delta_lower, delta_upper`` (for printing only proven digits)
    radii: tuple | None = field(default=None, repr=False)
    #: the member of the family (:mod:`analytic.system`)
    system: System = PAPER

    @property
    def width(self) -> mpmath.mpf | None:
        """``upper - lower`` (``T/T0``), from the deltas so that tiny widths keep their digits."""
        if not self.exists:
            return None
        with mpmath.workdps(self.digits + 10):
            return self.delta_upper - self.delta_lower

    def _fmt(self, x, k: int | None = None) -> str:
        if x is None:
            return "-"
        if k is not None:
            return self._printed[0][k]
        return proven_text(x, None, self.digits)

    @_once
    def _printed(self) -> tuple:
        """The four printed numbers (lower, upper and the two offsets), formatted once:
        ``(texts, raw)``, the texts (``None`` for a number that does not exist) and the raw items
        ``((D, k), x, radius)`` of their error bound (:func:`verify.rounding.largest_bound`: the
        printed value ``D 10**k``, raw mpf numbers), or ``None`` for ``raw`` where the texts come
        from :func:`_proven`'s general path."""
        values = (self.lower, self.upper, self.delta_lower, self.delta_upper)
        radii = (None,) * 4 if self.radii is None else self.radii
        digits = self.digits
        texts = []
        raw = []
        enough = digits + 1e-9
        for x, r in zip(values, radii, strict=True):
            if x is None:
                texts.append(None)
                continue
            xv = getattr(x, "_mpf_", None)
            rv = getattr(r, "_mpf_", None)
            if xv is None or rv is None or not (xv[1] and rv[1]):
                text, dk = _proven(x, r, digits)
            elif (xv[2] + xv[3] - rv[2] - rv[3] - 2) * _LOG10_2 > enough:
                text, dk = _nstr(xv, digits)  # every digit usable (:func:`_proven`)
            else:
                text, dk = _proven(x, r, digits)
            texts.append(text)
            if dk is None or rv is None:
                raw = None
            elif raw is not None:
                raw.append((dk, xv, rv))
        return tuple(texts), raw

    def error_bound(self) -> str | None:
        """A bound of ``|printed - exact|`` over the four printed numbers (rounding of the print
        included; see :mod:`verify.rounding`), or ``None`` if not certified."""
        return self._error_bound

    @_once
    def _error_bound(self) -> str | None:
        if not (self.certified and self.exists and self.radius is not None):
            return None
        texts, raw = self._printed
        if raw is not None and self.radii is not None:  # in integers, on one scale
            return largest_bound(raw)
        values = (self.lower, self.upper, self.delta_lower, self.delta_upper)
        radii = (self.radius,) * 4 if self.radii is None else self.radii
        return printed_bound(zip(texts, values, radii, strict=True))

    def printed(self) -> tuple:
        """``(lower, upper, delta_lower, delta_upper, error_bound)`` as :meth:`as_json` writes
        them (a row of ``paramres table``), without the rest of the dict."""
        return (*self._printed[0], self._error_bound)

    def as_json(self) -> dict:
        """A JSON-ready dict; numbers as decimal strings with ``digits`` significant digits;
        ``error_bound`` bounds ``|printed - exact|`` for each of them (rounding included),
        ``radius`` is the internal enclosure's (smaller: before rounding)."""
        lower, upper, delta_lower, delta_upper = self._printed[0]
        return {
            "order": self.order,
            **self.system.as_json(),
            "m": None if self.m is None else fraction_text(self.m),
            "Q": None if self.Q is None else fraction_text(self.Q),
            "damping": self.damping if self.Q is not None else "none",
            "digits": self.digits,
            "method": self.method,
            "regime": self.regime,
            "exists": self.exists,
            "lower": lower,
            "upper": upper,
            "delta_lower": delta_lower,
            "delta_upper": delta_upper,
            "radius": self._radius_json,
            "error_bound": self._error_bound,
            "certified": self.certified,
            "notes": list(self.notes),
        }

    @property
    def _radius_json(self) -> str | None:
        return None if self.radius is None else _radius_text(self.radius)

    def __repr__(self) -> str:
        """Every certified digit (the dataclass repr showed mpmath's 15-17)."""
        j = self.as_json()
        return (
            f"Boundary(order={self.order}, m={j['m']}, Q={j['Q']}, damping={j['damping']!r}, "
            f"lower={j['lower']}, upper={j['upper']}, error_bound={j['error_bound']}, "
            f"method={self.method!r})"
        )

    def _repr_html_(self) -> str:
        import html

        return f"<pre>{html.escape(str(self))}</pre>"

    def __str__(self) -> str:
        fr = (
            "no friction"
            if self.Q is None
            else f"Q = {fraction_text(self.Q)} ({self.damping} model)"
        )
        where = f"m = {fraction_text(self.m)}, " if self.m is not None else ""
        head = f"order {self.order}, {where}{fr}"
        if not self.system.is_paper:
            head = f"{self.system.label}: {head}"
        off = "T - n T_av/2" if self.system.is_paper else "T - T_n"
        if not self.exists:
            body = "  no interval of instability"
        else:
            body = (
                f"  lower T/T0 = {self._fmt(self.lower, 0)}   "
                f"({off} = {self._fmt(self.delta_lower, 2)})\n"
                f"  upper T/T0 = {self._fmt(self.upper, 1)}   "
                f"({off} = {self._fmt(self.delta_upper, 3)})"
            )
        bound = self.error_bound()
        if bound == "0":  # the edges are exact rationals printed in full: "< 0" would be false
            proof = "certified: printed = exact"
        elif bound is not None:
            proof = f"certified: |printed - exact| < {bound}"
        else:
            proof = "certified" if self.certified else "not certified"
        tail = f"  [{self.method}; {self.regime}; {proof}]"
        notes = "".join(f"\n  note: {n}" for n in self.notes)
        return f"{head}\n{body}\n{tail}{notes}"


class _FromBalls(Boundary):
    """A :class:`Boundary` built from the four proven balls (:func:`from_balls`): the numbers --
    ``lower, upper, delta_lower, delta_upper`` (the balls' midpoints), ``radii`` (their radii),
    ``radius`` (the largest) and the enclosures (the balls' ends) -- are converted from the balls
    exactly, each on first use, instead of all when the result is built.  Equal to a
    :class:`Boundary` holding the same numbers."""

    @_once
    def lower(self):
        return to_mpf(self._balls[0])

    @_once
    def upper(self):
        return to_mpf(self._balls[1])

    @_once
    def delta_lower(self):
        return to_mpf(self._balls[2])

    @_once
    def delta_upper(self):
        return to_mpf(self._balls[3])

    @_once
    def radii(self):
        return tuple(exact_mpf(x.rad()) for x in self._balls)

    @_once
    def radius(self):
        return max(self.radii)

    @_once
    def lower_enclosure(self):
        return _ends(self.lower, self.radii[0])

    @_once
    def upper_enclosure(self):
        return _ends(self.upper, self.radii[1])

    @_once
    def _raw(self) -> tuple:
        """The raw mpf numbers ``(midpoints, radii)`` of the four balls, read from the balls'
        exact mantissas and exponents (no mpmath numbers built: the printed decimals and their
        bound need only these)."""
        mids = []
        rads = []
        for x in self._balls:
            man, exp = x.mid().man_exp()
            man = int(man)
            if man & 1:  # arb gives the odd mantissa: already mpmath's normal form
                if man > 0:
                    mids.append((0, man, int(exp), man.bit_length()))
                else:
                    mids.append((1, -man, int(exp), (-man).bit_length()))
            else:
                mids.append(from_man_exp(man, int(exp)))
            r = x.rad()
            f = float(r)
            if _TINY < f < _HUGE:  # exact: a radius has a 30-bit mantissa (arb's mag_t)
                man, den = f.as_integer_ratio()  # man odd, den a power of two
                rads.append((0, man, 1 - den.bit_length(), man.bit_length()))
            else:
                man, exp = r.man_exp()
                rads.append(from_man_exp(int(man), int(exp)))
        return tuple(mids), tuple(rads)

    @_once
    def _printed(self) -> tuple:
        """:meth:`Boundary._printed` from the balls' raw numbers (:attr:`_raw`): the same texts
        and bound items; the general path (a zero midpoint or radius) converts the numbers.  A
        row whose four numbers print every digit asked for (the common case) is written by
        :func:`_row_of_balls` straight from the balls, its bound with it."""
        d = self.__dict__
        if "_balls" not in d:  # a copy (``dataclasses.replace``): the numbers are set
            return Boundary._printed.fn(self)
        row = _row_of_balls(d["_balls"], self.digits)
        if row is not None:
            texts, bound = row
            d["_error_bound"] = bound if self.certified else None
            return texts, None
        mids, rads = self._raw
        digits = self.digits
        enough = digits + 1e-9
        texts = []
        raw = []
        for i, (xv, rv) in enumerate(zip(mids, rads, strict=True)):
            if not (xv[1] and rv[1]):
                value = (self.lower, self.upper, self.delta_lower, self.delta_upper)[i]
                text, dk = _proven(value, self.radii[i], digits)
            elif (xv[2] + xv[3] - rv[2] - rv[3] - 2) * _LOG10_2 > enough:
                text, dk = _nstr(xv, digits)  # every digit usable (:func:`_proven`)
            else:
                text, dk = _proven_raw(xv, rv, digits)
            texts.append(text)
            if dk is None:
                raw = None
            elif raw is not None:
                raw.append((dk, xv, rv))
        return tuple(texts), raw

    def printed(self) -> tuple:
        """:meth:`Boundary.printed`; a fresh row is written by :func:`_row_of_balls` straight
        away (the texts and the bound kept, as :attr:`_printed` and :attr:`_error_bound` keep
        them)."""
        d = self.__dict__
        if "_printed" not in d and "_balls" in d:
            row = _row_of_balls(d["_balls"], d["digits"])
            if row is not None:
                texts, bound = row
                d["_printed"] = (texts, None)
                d["_error_bound"] = bound = bound if d["certified"] else None
                return (*texts, bound)
        return (*self._printed[0], self._error_bound)

    @_once
    def _error_bound(self) -> str | None:
        if "_balls" not in self.__dict__:
            return Boundary._error_bound.fn(self)
        if not self.certified:
            return None
        texts, raw = self._printed
        if raw is not None:
            return largest_bound(raw)
        values = (self.lower, self.upper, self.delta_lower, self.delta_upper)
        return printed_bound(zip(texts, values, self.radii, strict=True))

    @property
    def _radius_json(self) -> str:
        if "_balls" not in self.__dict__:
            return Boundary._radius_json.fget(self)
        rv = _raw_max(self._raw[1])
        return _nstr(rv, 3, strip=True)[0] if rv[1] else _radius_text(self.radius)

    def __eq__(self, other):
        if not isinstance(other, Boundary):
            return NotImplemented
        return all(getattr(self, f) == getattr(other, f) for f in _COMPARED)

    __hash__ = Boundary.__hash__


_COMPARED = tuple(f.name for f in fields(Boundary) if f.compare)


try:  # the common case of _row_of_balls, compiled where the package was built with a C compiler
    from ._digits import row as _compiled_row
except ImportError:  # pragma: no cover - a build without one: the Python loop alone
    _compiled_row = None

#: a radius strictly between these is a double exactly (30-bit mantissas, normal doubles) and
#: not an integer (``as_integer_ratio`` gives the odd mantissa over a power of two)
_TINY, _HUGE = 2.0**-990, 1.0


def _row_of_balls(balls, dps: int) -> tuple[tuple, str | None] | None:
    """The four texts of a row and the bound of the printed digits
    (:func:`verify.rounding.largest_bound`) straight from the balls, in one pass: each midpoint's
    mantissa and exponent read once, each radius placed between two powers of two by arb's
    relative accuracy (read in full, a double exactly, only where it is not below one unit of
    the digits), and the digits of :func:`_nstr` (mpmath's ``to_str``: truncated at ``dps + 3``
    digits, rounded half up) taken by one division on the scale of :func:`_digit_scale`.  A
    number whose radius does not support every digit asked for is printed by
    :func:`_proven_raw`.  The bound: each number's error ``|printed - x| + r`` lies within 4.2
    units ``u = 10**-F`` of ``rem u + r`` (``rem``: what the division leaves, the truncated digits
    lying less than 4.2 units below ``|x| 10**F``: :func:`_digit_scale`), and ``r`` is either
    counted or below one unit, so that the largest lies between ``most - 4.2 wide`` and ``most +
    5.2 wide`` (``most`` the largest ``rem u`` with the radii counted, ``wide`` the largest
    ``u``): it is rounded up to two digits in doubles (:func:`_bound_between`), or -- where that
    bracket does not decide the two digits, or out of the doubles' range -- computed in integers
    on one scale from the texts printed (:func:`_exact_bound`).  ``None`` (the general path) for
    a zero midpoint, a radius outside ``(_TINY, _HUGE)`` or huge exponents."""
    scales = _ROW_SCALES.get(dps)
    if scales is None:
        scales = _ROW_SCALES[dps] = {}
    if _compiled_row is not None:  # the same steps, compiled (:mod:`verify._digits`)
        got = _compiled_row(balls, scales, _TEN_TUPLE, _ball_raw, dps)
        if got is not None:
            texts, bound = got
            return texts, (_exact_bound(balls, texts) if bound is None else bound)
    texts = []
    most = wide = 0.0  # the largest error lies within 4.2 wide below most and 5.2 wide above
    exact = False  # the bound in integers
    for x in balls:
        man, exp = x.mid().man_exp()
        man = _index(man)  # FLINT's integers as Python's (int() exactly, without its dispatch)
        exp = _index(exp)
        # arb's relative accuracy: the radius r has 2**(top - acc - 2) <= r < 2**(top - acc - 1)
        # (top = exp + bc; a zero midpoint has none: 1 - 2**63, or 2**63 - 1 with a zero
        # radius), all the digits need to know of r, and the bound where r is below one unit
        # (reading r itself costs twice as much)
        acc = x.rel_accuracy_bits()
        mag = -man if man < 0 else man
        bc = mag.bit_length()
        sc = scales.get(exp + bc)
        if sc is None:
            sc = _digit_scale(dps, exp + bc) or _NO_SCALE
            if len(scales) < 4096:
                scales[exp + bc] = sc
        usable, tiny, unit, shift, p5, fix, thr, u, tens, cut, half, split, piece, nines, fewer = sc
        if usable <= acc < tiny:  # every digit usable, r above _TINY (a zero midpoint: none)
            n = (mag >> (bc - shift) if shift < bc else mag << (shift - bc)) * p5 >> fix
            if n < thr:  # one digit fewer than the scale's most
                cut, half, split, piece, nines = fewer
            D, rem = divmod(n, cut)
            # |printed - x| 10**F (F = fixdps): the printed value is rem units below the
            # truncated digits n, or cut - rem above, and n lies less than 4.2 units below
            # |x| 10**F (:func:`_digit_scale`): the error lies within 4.2 u of rem u + r
            if rem >= half:  # the first digit cut is 5 or more: round half up
                D += 1
                rem = cut - rem
            e = rem * u  # (infinite where 10**-F is beyond the doubles: the integers')
            if acc < unit:  # r not below one unit u: counted exactly (else in the bracket)
                e += float(x.rad())
            if e > most:
                most = e
            if u > wide:
                wide = u
            if D == tens:  # a run of nines carried into the next power of ten
                text = nines
            elif split:  # the first split digits, a point, the rest and an exponent (if any)
                digits = str(D)
                text = f"{digits[:split]}.{digits[split:]}{piece}"
            else:  # "0.00" (if any) and the digits
                text = piece + str(D)
            if man < 0:
                text = "-" + text
        else:  # fewer digits, or no kept scale: :func:`_proven_raw` (its own test first)
            got = _ball_raw(x, man, exp, dps)
            if got is None:
                return None
            text, e = got
            if e is None:
                exact = True
            elif e > most:
                most = e
        texts.append(text)
    texts = tuple(texts)
    return texts, _row_bound(balls, texts, most, wide, exact)


def _ball_raw(x, man: int, exp: int, dps: int) -> tuple[str, float | None] | None:
    """A number of :func:`_row_of_balls` whose radius does not support every digit asked for
    (or has no kept scale), printed by :func:`_proven_raw` (its own test first): its text and
    its error ``|printed - x| + r`` in doubles, or ``None`` for the error where the digits
    printed need the bound in integers; ``None`` (the general path) for a zero midpoint, a radius
    outside ``(_TINY, _HUGE)`` or huge exponents.  ``man 2**exp`` is the midpoint."""
    f = float(x.rad())
    if not (man and _TINY < f < _HUGE):
        return None
    mag = -man if man < 0 else man
    bc = mag.bit_length()
    rm, den = f.as_integer_ratio()  # exact: a radius has a 30-bit mantissa
    text, dk = _proven_raw(
        (man < 0, mag, exp, bc), (0, rm, 1 - den.bit_length(), rm.bit_length()), dps
    )
    if dk is None:  # huge exponents: mpmath's own path
        return None
    if dk[0] or bc > 1000:  # digits printed: their error cancels in doubles
        return text, None
    # "0": the error is |x| + r exactly, in doubles to a relative 1e-15
    return text, _ldexp(float(mag), exp) + f


def _row_bound(balls, texts: tuple, most: float, wide: float, exact: bool) -> str:
    """The bound of a row of :func:`_row_of_balls`: the largest error lies between ``most - 4.2
    wide`` and ``most + 5.2 wide``; the first is then at least ``most / 2`` and off by half a
    unit in its last place at most (within :func:`_bound_between`'s margin).  In integers
    (:func:`_exact_bound`) where that does not decide it, or where ``exact`` asks for it."""
    if exact or most < 8.4 * wide:
        bound = None
    else:
        bound = _bound_between(most - 4.2 * wide, most + 5.2 * wide)
    return _exact_bound(balls, texts) if bound is None else bound


def _bound_between(least: float, most: float) -> str | None:
    """:func:`verify.rounding.bound_text` (two digits, rounded up) of a number known to lie
    between the doubles ``least`` and ``most`` up to their roundings (a relative ``1e-15``: each
    a few products and sums of doubles), or ``None`` where the numbers between them do not all
    round up alike, or lie beyond the doubles' safe range."""
    if not (1e-280 < least and most < 1e280):
        return None
    most *= 1 + 1e-12  # above the number, and below it:
    least *= 1 - 1e-12
    e = _floor(_log10(most))
    t = _TEN_DOUBLES[1 - e]
    q = most * t  # [10, 100) but for the logarithm's rounding
    if q < 10:
        e -= 1
        t = _TEN_DOUBLES[1 - e]
        q = most * t
    elif q >= 100:
        e += 1
        t = _TEN_DOUBLES[1 - e]
        q = most * t
    c = _ceil(q)  # the number times 10**(1-e) is at most c
    if not (c > 10 and least * t > c - 1):  # and above c - 1 (and 10)
        return None
    if c >= 100:  # carried into the next power of ten (in (99, 100])
        return f"1.0e{e + 1}"
    return f"{_TWO_DIGITS[c]}{e}"


#: ``10.0**j`` correctly rounded, for ``|j| <= 300``
_TEN_DOUBLES = {j: (float(10**j) if j >= 0 else 1 / 10**-j) for j in range(-300, 301)}
#: :data:`_TEN_DOUBLES` as a tuple, ``10.0**j`` at ``j + 300`` (:mod:`verify._digits`)
_TEN_TUPLE = tuple(_TEN_DOUBLES[j] for j in range(-300, 301))
#: the head of :func:`_bound_between`'s text by ``c``, the two digits (``"4.7e"`` for 47)
_TWO_DIGITS = {c: f"{c // 10}.{c % 10}e" for c in range(11, 100)}
_floor, _ceil, _log10, _ldexp = math.floor, math.ceil, math.log10, math.ldexp


def _exact_bound(balls, texts) -> str:
    """The bound of :func:`_row_of_balls` in integers: the largest ``|printed - x| + r`` of the
    balls (``x`` a midpoint ``man 2**exp``, ``r`` a radius, a double exactly) and their printed
    texts (the value ``D 10**k`` each text writes), all on one scale ``2**a 10**b``
    (:func:`verify.rounding.largest_bound`), rounded up to two digits."""
    b = a = 0
    items = []
    for x, text in zip(balls, texts, strict=True):
        man, exp = x.mid().man_exp()
        exp = _index(exp)
        rm, den = float(x.rad()).as_integer_ratio()
        re = 1 - den.bit_length()
        # the printed value: the text's digits, the point's place and the exponent (at most
        # some 1400 digits: |x| < 2**3500 and r > 2**-990, :func:`_row_of_balls`)
        number, _, e = text.partition("e")
        head, _, tail = number.partition(".")
        D = int(head + tail)
        k = (int(e) if e else 0) - len(tail)
        items.append((k, D, exp, _index(man), re, rm))
        if k < b:
            b = k
        if exp < a:
            a = exp
        if re < a:
            a = re
    scale10 = _POW10.get(-b) or _pow10(-b)
    best = -1
    for k, D, exp, man, re, rm in items:
        A = (D if k == b else D * (_POW10.get(k - b) or _pow10(k - b))) << -a
        num = abs(A - ((man * scale10) << (exp - a))) + ((rm * scale10) << (re - a))
        if num > best:
            best = num
    return _scaled_bound_text(best, a, b, 2)


def _digits_text(digits: str, exponent: int, dps: int) -> str:
    """The text :func:`_nstr` writes for the digits ``digits`` (no sign) whose first stands for
    ``10**exponent``: fixed point near unit magnitude, else with an exponent."""
    if min(-(dps // 3), -5) < exponent < dps:  # :func:`_scale`'s least exponent in fixed point
        if exponent < 0:
            return ("0." + "0" * (-exponent - 1)) + digits
        if exponent + 1 >= len(digits):  # no digit after the point: none written
            return digits
        return f"{digits[: exponent + 1]}.{digits[exponent + 1 :]}"
    head = f"{digits[:1]}.{digits[1:]}" if len(digits) > 1 else digits
    if exponent > 0:
        return f"{head}e+{exponent}"
    return f"{head}e{exponent}"


def _digit_scale(dps: int, top: int) -> tuple | None:
    """What :func:`_row_of_balls` needs to print a number ``s`` with ``2**(top-1) <= |s| <
    2**top`` as :func:`_nstr` does, as one tuple ``(usable, tiny, unit, shift, p5, fix, thr, u,
    tens, *many, fewer)``.  First the bounds of a ball's relative accuracy ``acc`` (arb's: its
    radius ``r`` has ``2**(top - acc - 2) <= r < 2**(top - acc - 1)``): every digit is usable and
    ``r`` below 1 (``_HUGE``) where ``acc >= usable``, ``r`` is above ``_TINY`` where ``acc <
    tiny``, and below one unit ``u = 10**-F`` where ``acc >= unit``.  Then the truncated digits
    are ``n = (|man| >> (bc - shift)) p5 >> fix`` (:func:`_scale`, ``shift = bitprec``; ``p5 =
    5**F`` and ``fix = fixprec - F``: ``p10 = 10**F = p5 2**F``, so this is :func:`_nstr`'s
    ``(|man| >> (bc - shift)) p10 >> fixprec``, the same integer with a shorter factor), and ``n``
    has ``c`` or ``c - 1`` digits, ``c`` those of ``2**top 10**F``, told apart by ``thr =
    10**(c-1)``; ``u`` is a double, correctly rounded (infinite beyond the doubles' range), and
    ``tens = 10**dps``.  For each count (``many``, in the tuple itself, and ``fewer``, a tuple of
    its own): ``cut``, what the last printed digit stands for (``cut 10**-F``), half of it, how
    the text is written (:func:`_digits_text`: the first ``split`` digits, a point, the rest and
    ``piece``, an exponent or nothing; or, ``split = 0``, ``piece`` -- ``"0.00"`` or nothing --
    and the digits) and the text of a run of nines carried into the next power of ten.  ``None``
    where :func:`_nstr`'s own steps serve: huge exponents, no fixed-point scale, or fewer than
    ``dps + 1`` digits.

    The truncated digits lie less than 4.2 units below ``|s| 10**F``: ``|man| >> (bc - shift)``
    is less than one unit below ``|man| 2**(shift - bc)``, which costs less than ``p10 /
    2**fixprec`` units after the product (``F`` is ``fixprec log10(2)`` rounded to the nearest,
    so ``p10 < 2**fixprec sqrt(10)``, 3.17), and the last shift less than one more."""
    # more than 1400 digits: |x| < 2**3500 and a radius above 2**-990 (_TINY) leave not every
    # digit usable; one digit: no point to place (:func:`_nstr` writes it)
    if dps > 1400 or dps < 2:
        return None
    scale = _scale(dps, top)
    if scale is None:
        return None
    bitprec, fixprec, fixdps, p10, low = scale
    if not fixprec:
        return None
    c = len(str((1 << top) * p10)) if top >= 0 else len(str(p10 >> -top))
    # n >= 2**(top-1) 10**fixdps - 3 >= 10**(c-2) and n < 2**top 10**fixdps < 10**c: c - 1
    # or c digits; the rounding needs at least dps + 1 of them
    if c - 1 <= dps:
        return None
    # a radius below 2**lim (re + rbc <= lim): |x| / (2 rad) > 2**(top - 2 - lim) >= 2 10**dps,
    # every digit usable (and :func:`_proven`'s own test passes)
    lim = top - 3 - math.ceil(dps * _LOG2_10)

    def count(size: int) -> tuple:
        cut = _pow10(size - dps)
        exponent = size - fixdps - 1
        if not low < exponent < dps:  # with an exponent
            split, piece = 1, (f"e+{exponent}" if exponent > 0 else f"e{exponent}")
        elif exponent < 0:  # "0.00" and the digits
            split, piece = 0, "0." + "0" * (-exponent - 1)
        elif exponent + 1 < dps:
            split, piece = exponent + 1, ""
        else:  # every digit before the point: no point written (:func:`_nstr`)
            split, piece = 0, ""
        # the digits rounded up to 10**dps: 10**(dps-1), one place higher
        nines = _digits_text("1" + "0" * (dps - 1), exponent + 1, dps)
        return cut, cut // 2, split, piece, nines

    # r < 2**(top - acc - 1) is below 2**lim (every digit usable) and 1 where acc >= usable, and
    # below 2**-b < 10**-F (b: the bits of 10**F) where acc >= unit; r >= 2**(top - acc - 2) is
    # above 2**-990 where acc < tiny
    usable = top - 1 - min(lim, 0)
    tiny = top + 988
    unit = top - 1 + p10.bit_length()
    # u: 10**-F (F = fixdps) as a double, correctly rounded (infinite beyond the doubles' range:
    # the bound then comes from the integers)
    u = 1 / p10 if fixdps < 280 else math.inf
    p5 = p10 >> fixdps  # 5**F (F <= fixprec)
    head = (usable, tiny, unit, bitprec, p5, fixprec - fixdps, _pow10(c - 1), u, _pow10(dps))
    return head + count(c) + (count(c - 1),)


#: a scale no radius passes (no accuracy ``acc`` with ``0 <= acc < 0``): :func:`_row_of_balls`
#: prints by :func:`_proven_raw`
_NO_SCALE = (0, 0, *(None,) * 13)

#: the scales of :func:`_row_of_balls` by digits, then by ``exponent + bitcount`` (``_NO_SCALE``
#: where :func:`_nstr`'s own steps serve)
_ROW_SCALES: dict[int, dict[int, tuple]] = {}


def _raw_max(rads: tuple) -> tuple:
    """The largest of nonnegative raw mpf numbers (normal form: odd mantissas, or zero)."""
    return max(rads, key=_magnitude)


def _magnitude(r: tuple) -> tuple:
    """A key ordering nonnegative raw mpf numbers by value: ``2**(top-1) <= r < 2**top`` first,
    then the mantissa over ``2**bitcount`` (exactly; an integer for up to 4096 bits -- a radius
    has 30)."""
    if not r[1]:
        return (-math.inf, 0)
    if r[3] <= 4096:
        return (r[2] + r[3], r[1] << (4096 - r[3]))
    return (r[2] + r[3], Fraction(r[1], 1 << (r[3] - 4096)))


def _ends(v, r) -> tuple:
    """``(v - r, v + r)`` exactly."""
    return mpmath.fsub(v, r, exact=True), mpmath.fadd(v, r, exact=True)


def from_balls(
    balls,
    *,
    order,
    m,
    Q,
    damping,
    digits,
    method,
    regime,
    system,
    notes=(),
    certified=True,
) -> Boundary:
    """The result from four proven balls: ``T/T0`` of the lower and the upper edge and their
    offsets.  The numbers are the balls' midpoints (exactly), ``radii`` their radii (exactly) and
    ``radius`` the largest, the enclosures of the edges the balls' ends (exactly: midpoint -+
    radius); each is converted from the balls on first use."""
    obj = _new(_FromBalls)
    _setattr(
        obj,
        "__dict__",
        {
            "order": order,
            "m": m,
            "Q": Q,
            "damping": damping,
            "digits": digits,
            "method": method,
            "exists": True,
            "certified": certified,
            "regime": regime,
            "notes": tuple(notes),
            "system": system,
            "_balls": tuple(balls),
        },
    )
    return obj


_new = object.__new__
_setattr = object.__setattr__


def proven_text(x: mpmath.mpf, rad, digits: int) -> str:
    """``x`` with at most ``digits`` significant digits, and only as many as the proven radius
    ``rad`` supports (the exact value lies within half a unit of the last digit printed, plus the
    rounding of the print itself).  A value whose enclosure contains zero and is too wide for one
    digit prints as ``"0"`` (e.g. the offset at a closing, which is exactly zero by the closing
    theorem)."""
    return _proven(x, rad, digits)[0]


def _proven(x, rad, digits: int) -> tuple[str, tuple[int, int] | None]:
    """:func:`proven_text`, with ``(D, k)``: the printed value ``D 10**k`` exactly (``None``
    where the text comes from the general path below)."""
    xv = getattr(x, "_mpf_", None)
    rv = getattr(rad, "_mpf_", None)
    if xv is not None and rv is not None and xv[1] and rv[1]:
        # the common case, two finite nonzero mpmath numbers: the same estimate and the same
        # text as below, without mpmath's dispatch and comparisons
        return _proven_raw(xv, rv, digits)
    return _proven_slow(x, rad, digits), None


def _proven_raw(xv: tuple, rv: tuple, digits: int) -> tuple[str, tuple[int, int] | None]:
    """:func:`_proven` of the raw mpf numbers of a finite nonzero ``x`` and ``rad``."""
    if (xv[2] + xv[3] - rv[2] - rv[3] - 2) * _LOG10_2 > digits + 1e-9:
        # |x| / (2 rad) > 2**(that exponent) >= 10**digits: every digit asked for is usable
        return _nstr(xv, digits)
    est = (xv[2] - rv[2] - 1 + math.log2(xv[1]) - math.log2(rv[1])) * _LOG10_2
    usable = math.floor(est)
    if abs(est - round(est)) < 1e-6:
        usable = _usable_exactly(_make_mpf(xv), _make_mpf(rv))
    if usable < 1:
        return "0", (0, 0)
    return _nstr(xv, min(digits, usable))


def _proven_slow(x, rad, digits: int) -> str:
    """:func:`proven_text` for any number type, zero and no radius included."""
    if rad is None or rad == 0 or x == 0:
        if x == 0 and rad is not None:
            return "0"
        return _point_dropped(mpmath.nstr(x, digits, strip_zeros=False))
    est = _log10_abs(x) - _log10_abs(rad) - _LOG10_2
    usable = math.floor(est)
    if abs(est - round(est)) < 1e-6:  # next to a power of ten: decide it exactly
        usable = _usable_exactly(x, rad)
    if usable < 1:
        return "0"
    return _point_dropped(mpmath.nstr(x, min(digits, usable), strip_zeros=False))


def _point_dropped(text: str) -> str:
    """mpmath's text without a decimal point that no digit follows (``"2."``, ``"2.e-30"``,
    ``"123."``: ``"2"``, ``"2e-30"``, ``"123"``), as the engine prints every decimal."""
    i = text.find("e")
    if i < 0:
        return text[:-1] if text.endswith(".") else text
    return text[: i - 1] + text[i:] if text[i - 1] == "." else text


_LOG2_10 = math.log(10, 2)


def _nstr(s: tuple, dps: int, strip: bool = False) -> tuple[str, tuple[int, int] | None]:
    """``mpmath.nstr(x, dps, strip_zeros=False)`` of a finite nonzero raw mpf ``s`` (``dps >= 1``):
    the very steps of ``mpmath.libmp.to_str`` (digits truncated at ``dps + 3``, then rounded half
    up; ``strip``: ``strip_zeros=True``), for the case at hand only; with ``(D, k)``, the printed
    value ``D 10**k`` exactly (``None`` for huge exponents, where mpmath's own path writes the
    text).  In integers: the rounded digits are ``n // 10**q`` (plus one when the first digit cut
    is 5 or more) -- no text read back into a number."""
    sign, man, exp, bc = s
    scale = _SCALES.get((dps, exp + bc)) or _scale(dps, exp + bc)
    if scale is None:  # huge exponents: mpmath's own path
        text = to_str(s, dps, strip_zeros=strip)
        return (text if strip else _point_dropped(text)), None
    bitprec, fixprec, fixdps, p10, low = scale
    if fixprec:
        shift = bitprec - bc  # = exp + fixprec
        n = ((man << shift) if shift >= 0 else (man >> -shift)) * p10 >> fixprec
    else:
        n = (man << exp) if exp >= 0 else (man >> -exp)
    digits = _decimal(n)
    size = len(digits)
    exponent = size - fixdps - 1
    if size > dps:
        cut = _POW10.get(size - dps) or _pow10(size - dps)
        if digits[dps] < "5":
            D = n // cut
            digits = digits[:dps]
        else:  # round half up (mpmath's rule, on its truncated digits)
            D = n // cut + 1
            digits = _decimal(D)
            if len(digits) > dps:  # a run of nines carried into the next power of ten
                digits = digits[:dps]
                D //= 10
                exponent += 1
        k = exponent + 1 - dps
    else:
        D = n
        k = exponent + 1 - size
    if sign:
        D = -D
    if low < exponent < dps:  # fixed point near unit magnitude (no zeros to pad: exponent < dps)
        if exponent < 0:
            digits = ("0" * -exponent) + digits
            exponent = 0
        text = f"{digits[: exponent + 1]}.{digits[exponent + 1 :]}"
        exponent = 0
    else:
        text = f"{digits[:1]}.{digits[1:]}"
    if strip:
        text = text.rstrip("0")
        if text[-1] == ".":
            text += "0"
    elif text[-1] == ".":  # no digit after the point (mpmath writes "2." and "2.e-30")
        text = text[:-1]
    if sign:
        text = "-" + text
    if exponent == 0:
        return text, (D, k)
    return (f"{text}e+{exponent}" if exponent > 0 else f"{text}e{exponent}"), (D, k)


def _decimal(n: int) -> str:
    """The decimal digits of the integer ``n`` (``str(n)``, which Python refuses above 4300
    digits; FLINT's conversion for long integers, subquadratic as well)."""
    return str(n) if n.bit_length() < 14000 else fmpz(n).str()


#: ``(bitprec, fixprec, fixdps, 10**fixdps, min_fixed)`` of :func:`_nstr` by
#: ``(dps, exponent + bitcount)``
_SCALES: dict[tuple[int, int], tuple[int, int, int, int, int]] = {}


def _scale(dps: int, top: int) -> tuple[int, int, int, int, int] | None:
    """The fixed-point scale of ``mpmath.libmp.to_digits_exp(s, dps + 3)`` for a number with
    ``2**(top-1) <= |s| < 2**top`` and ``to_str``'s least exponent printed in fixed point, kept
    for the few pairs a table meets (``None`` for huge exponents, beyond ``2**3500``)."""
    if top > 3500 or top < -3500:
        return None
    bitprec = int((dps + 3) * _LOG2_10) + 10
    fixprec = max(bitprec - top, 0)
    fixdps = int(fixprec / _LOG2_10 + 0.5)
    scale = (bitprec, fixprec, fixdps, _pow10(fixdps), min(-(dps // 3), -5))
    if len(_SCALES) < 4096 and fixdps < 2000:
        _SCALES[(dps, top)] = scale
    return scale


def _usable_exactly(x, rad) -> int:
    """``floor(log10(|x| / (2 rad)))`` (at least 0), for ``est`` next to a power of ten."""
    with mpmath.workdps(20):
        ratio = abs(x) / (2 * rad)
        return int(mpmath.floor(mpmath.log10(ratio))) if ratio >= 1 else 0


_LOG10_2 = math.log10(2)


def _log10_abs(v) -> float:
    """``log10 |v|`` of a nonzero mpmath number, to about 1e-15 relative (any exponent)."""
    _, man, exp, bc = v._mpf_
    top = man >> (bc - 53) if bc > 53 else man
    return (exp + bc - min(bc, 53) + math.log2(top)) * _LOG10_2


def _radius_text(r) -> str:
    """``mpmath.nstr(r, 3)``."""
    v = getattr(r, "_mpf_", None)
    return mpmath.nstr(r, 3) if v is None or not v[1] else _nstr(v, 3, strip=True)[0]


def fraction_text(x) -> str:
    if isinstance(x, Fraction):
        return str(x.numerator) if x.denominator == 1 else f"{x.numerator}/{x.denominator}"
    return str(x)
