"""The result of a boundary computation: both edges of one interval, with their proof.

:class:`Boundary` is what every solver returns (:mod:`verify.methods`); :func:`proven_text` prints
a number with only the digits its proven radius supports.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from fractions import Fraction
from functools import cached_property

import mpmath

from analytic.system import PAPER, System

__all__ = ["Boundary", "proven_text", "fraction_text"]


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
            return self._texts[k]
        return proven_text(x, None, self.digits)

    @cached_property
    def _texts(self) -> tuple:
        """The four printed numbers (lower, upper and the two offsets), formatted once."""
        values = (self.lower, self.upper, self.delta_lower, self.delta_upper)
        return tuple(
            "-"
            if x is None
            else proven_text(x, None if self.radii is None else self.radii[k], self.digits)
            for k, x in enumerate(values)
        )

    def error_bound(self) -> str | None:
        """A bound of ``|printed - exact|`` over the four printed numbers (rounding of the print
        included; see :mod:`verify.rounding`), or ``None`` if not certified."""
        return self._error_bound

    @cached_property
    def _error_bound(self) -> str | None:
        from .rounding import bound_text, printed_error

        if not (self.certified and self.exists and self.radius is not None):
            return None
        values = (self.lower, self.upper, self.delta_lower, self.delta_upper)
        bounds = [
            printed_error(self._fmt(x, k), x, self.radius if self.radii is None else self.radii[k])
            for k, x in enumerate(values)
        ]
        return bound_text(max(b for b in bounds if b is not None))

    def as_json(self) -> dict:
        """A JSON-ready dict; numbers as decimal strings with ``digits`` significant digits;
        ``error_bound`` bounds ``|printed - exact|`` for each of them (rounding included),
        ``radius`` is the internal enclosure's (smaller: before rounding)."""
        fmt = lambda x, k: None if x is None else self._fmt(x, k)  # noqa: E731
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
            "lower": fmt(self.lower, 0),
            "upper": fmt(self.upper, 1),
            "delta_lower": fmt(self.delta_lower, 2),
            "delta_upper": fmt(self.delta_upper, 3),
            "radius": None if self.radius is None else mpmath.nstr(self.radius, 3),
            "error_bound": self.error_bound(),
            "certified": self.certified,
            "notes": list(self.notes),
        }

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
        proof = (
            f"certified: |printed - exact| < {bound}"
            if bound is not None
            else ("certified" if self.certified else "not certified")
        )
        tail = f"  [{self.method}; {self.regime}; {proof}]"
        notes = "".join(f"\n  note: {n}" for n in self.notes)
        return f"{head}\n{body}\n{tail}{notes}"


def proven_text(x: mpmath.mpf, rad, digits: int) -> str:
    """``x`` with at most ``digits`` significant digits, and only as many as the proven radius
    ``rad`` supports (the exact value lies within half a unit of the last digit printed, plus the
    rounding of the print itself).  A value whose enclosure contains zero and is too wide for one
    digit prints as ``"0"`` (e.g. the offset at a closing, which is exactly zero by the closing
    theorem)."""
    if rad is None or rad == 0 or x == 0:
        return mpmath.nstr(x, digits, strip_zeros=False) if x != 0 or rad is None else "0"
    est = _log10_abs(x) - _log10_abs(rad) - _LOG10_2
    usable = math.floor(est)
    if abs(est - round(est)) < 1e-6:  # next to a power of ten: decide it exactly
        with mpmath.workdps(20):
            ratio = abs(x) / (2 * rad)
            usable = int(mpmath.floor(mpmath.log10(ratio))) if ratio >= 1 else 0
    if usable < 1:
        return "0"
    return mpmath.nstr(x, min(digits, usable), strip_zeros=False)


_LOG10_2 = math.log10(2)


def _log10_abs(v) -> float:
    """``log10 |v|`` of a nonzero mpmath number, to about 1e-15 relative (any exponent)."""
    _, man, exp, bc = v._mpf_
    top = man >> (bc - 53) if bc > 53 else man
    return (exp + bc - min(bc, 53) + math.log2(top)) * _LOG10_2


def fraction_text(x) -> str:
    if isinstance(x, Fraction):
        return str(x.numerator) if x.denominator == 1 else f"{x.numerator}/{x.denominator}"
    return str(x)
