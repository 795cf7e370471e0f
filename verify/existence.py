"""Where an interval of instability exists, with friction: thresholds and gaps in the depth ``m``.

With friction the ``n``-th interval exists at depth ``m`` iff the instability indicator ``D`` (see
:mod:`verify.solve`) is positive somewhere in the order's window, i.e. iff ``g(m) = max D > 0``.
``g`` is negative for small ``m`` (the threshold: friction beats a weak modulation) and, for ``n >=
3``, near every depth where the friction-free interval closes (there ``D0`` has a double zero, so
``D = D0 - (1 - r^2) sinh^2 < 0``: friction swallows the interval); islands may appear elsewhere.

:func:`existence` **proves** the answer on the whole depth axis by branch and bound over closed
depth ranges ``[lo, hi]`` (exact rationals).  On each range ``D`` is bounded in ball arithmetic
for all its depths at once, by the mean-value form in ``m``: ``D(t; M) in D(t; mid) + D_m(t; M)
(M - mid)``, with ``D_m`` from first-order jets (:class:`verify.certify.Jet`) of the parameters
over the ball ``M`` (far tighter than evaluating with ``M`` itself).  A range is

* *exists* (``+1``) when ``D > 0`` at one period ``T`` (the maximiser at the middle, polished in
  ``arb`` near a threshold) for every depth of it, that ``T`` lying in the order's window;
* *none* (``-1``) when ``D < 0`` on the whole window for every depth of it (Taylor's bound around
  the maximiser where ``D'' < 0``, bisection elsewhere; in the trace form also a proof that the
  order's window does not begin before ``D < 0`` for good);
* else bisected, down to the resolution of the digits asked for.

An undecided range between *none* and *exists* that is narrower than that resolution is a
threshold, its enclosure proven on both sides; any other undecided range (or one left past the
budget) is reported as undecided, never guessed.  ``m -> 1`` is covered to ``1 - 2^-K`` within the
resolution.  The former scan (:func:`existence_scan`, float ``g`` on a grid, thresholds proven at
two points each) is kept for comparison; it could miss an island narrower than its spacing.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, fields
from fractions import Fraction
from functools import lru_cache

import mpmath
import numpy as np
from flint import arb, ctx

from analytic.system import PAPER, System

from .certify import CertificationError, bits_for_digits, certified_root, prove_sign, to_mpf
from .derived import backend, regime_roots
from .inputs import (
    EXISTENCE_DIGITS_RANGE,
    InputError,
    as_damping,
    as_digits,
    as_order,
    as_quality,
    as_system,
)
from .params import NEAR_CRITICAL, exact_fraction, form_for, normal_params, trace_params
from .system_params import canonical, trace_atoms

__all__ = [
    "Existence",
    "Threshold",
    "existence",
    "existence_scan",
    "absence_reason",
    "max_indicator",
    "closing_depths",
]


@dataclass(frozen=True)
class Threshold:
    """A depth where the interval appears (``appears=True``, going up in ``m``) or disappears;
    ``value`` has ``digits`` proven digits, ``enclosure = (lo, hi)`` (exact rationals) contains
    the exact depth."""

    value: mpmath.mpf
    enclosure: tuple[Fraction, Fraction]
    appears: bool
    digits: int

    def text(self) -> str:
        from .result import proven_text

        lo, hi = self.enclosure
        return proven_text(self.value, _mpf(hi - lo), self.digits)


@dataclass(frozen=True)
class Existence:
    """The depth ranges ``(a, b)`` in ``(0, 1)`` where the ``order``-th interval exists (``b = 1``:
    open towards ``m -> 1``), the proven thresholds that bound them, and the depth ranges that
    could not be decided (``undecided``, exact rationals ``(lo, hi)``; empty when the whole axis
    is proven).  ``segments`` is the proof: closed depth ranges ``(lo, hi, sign)`` covering the
    axis, ``+1`` exists at every depth, ``-1`` at none, ``0`` undecided (a threshold's enclosure
    or an undecided range)."""

    order: int
    Q: Fraction
    damping: str
    digits: int
    thresholds: tuple[Threshold, ...]
    open_to_one: bool
    undecided: tuple = ()
    segments: tuple = ()
    #: the member of the family (:mod:`analytic.system`); the paper's pendulum by default
    system: System = PAPER

    def _ranges(self) -> list[tuple]:
        """``[(start, end), ...]`` of the ranges where the interval exists, each end a
        :class:`Threshold`, an exact rational (the end of an undecided range) or ``1``."""
        if not self.segments:  # thresholds only (the scan)
            out, start = [], None
            for t in self.thresholds:
                if t.appears:
                    start = t
                else:
                    out.append((start, t))
                    start = None
            if self.open_to_one:
                out.append((start, 1))
            return out
        by_lo = {t.enclosure[0]: t for t in self.thresholds}
        segs = self.segments
        out = []
        for j, (lo, hi, sign) in enumerate(segs):
            if sign != 1:
                continue
            start = by_lo.get(segs[j - 1][0], lo) if j > 0 else lo
            if j + 1 < len(segs):
                end = by_lo.get(segs[j + 1][0], hi)
            else:
                end = 1
            out.append((start, end))
        return out

    @staticmethod
    def _value(e):
        if isinstance(e, Threshold):
            return e.value
        return mpmath.mpf(1) if e == 1 else _mpf(e)

    def _text(self, e, *, up: bool, digits: int | None = None) -> str:
        """The end ``e`` of a range: a threshold's proven digits, else the exact rational rounded
        towards +inf (``up``) or -inf, so that a printed range where the interval exists lies
        inside the proven one (its start rounded up, its end down) and a printed undecided range
        holds the undecided one (its start rounded down, its end up)."""
        if isinstance(e, Threshold):
            return e.text()
        if e == 1:
            return "1"
        return _directed_text(e, self.digits if digits is None else digits, up=up)

    def _inner(self, a, b) -> tuple[str, str]:
        """The texts of a proven range ``a < m < b`` rounded inwards (:meth:`_text`), with as many
        more digits than :attr:`digits` as it takes for the start to print below the end: a range
        narrower than the resolution (next to ``m = 1``, between two gaps) would else print empty
        or reversed (``1 < m < 0.999999999999999``).  A threshold's end keeps its proven digits;
        the other end, where it is a rational, takes the more digits."""
        for extra in range(0, _MORE_DIGITS + 1):
            d = self.digits + extra
            ta, tb = self._text(a, up=True, digits=d), self._text(b, up=False, digits=d)
            if isinstance(a, Threshold) and isinstance(b, Threshold):
                break  # (neither text changes with the digits)
            try:
                if Fraction(ta) < Fraction(tb):
                    break
            except ValueError:  # pragma: no cover - every end prints as a decimal number
                break
        return ta, tb

    @property
    def intervals(self) -> list[tuple]:
        """``[(a, b), ...]`` as mpmath numbers (``b = 1`` when open towards 1)."""
        return [(self._value(a), self._value(b)) for a, b in self._ranges()]

    def interval_texts(self) -> list[list[str]]:
        return [list(self._inner(a, b)) for a, b in self._ranges()]

    def _outer(self, lo: Fraction, hi: Fraction) -> tuple[str, str]:
        """The texts of an undecided range ``lo < m < hi`` rounded outwards (:meth:`_text`),
        with as many more digits than :attr:`digits` as it takes for the rounding to stay
        within the ranges beside it (their far ends): next to ``m = 1``, where the proven ranges
        between gaps are narrower than the resolution, an undecided range rounded at the
        resolution would else print over a whole proven range beside it (``0.999999999999997 <
        m < 1`` over ``0.9999999999999974 < m < 0.9999999999999977``)."""
        segs = self.segments
        j = next((i for i, s in enumerate(segs) if s[0] == lo and s[1] == hi), None)
        below = segs[j - 1][0] if j is not None and j > 0 else None
        above = segs[j + 1][1] if j is not None and j + 1 < len(segs) else None
        for extra in range(0, _MORE_DIGITS + 1):
            d = self.digits + extra
            # (both ends rationals: their texts are decimal numbers)
            ta, tb = self._text(lo, up=False, digits=d), self._text(hi, up=True, digits=d)
            if (below is None or Fraction(ta) > below) and (above is None or Fraction(tb) < above):
                break
        return ta, tb

    def undecided_texts(self) -> list[list[str]]:
        return [list(self._outer(lo, hi)) for lo, hi in self.undecided]

    def where(self, m: Fraction) -> str:
        """Why the interval does or does not exist at the exact depth ``m``: ``"exists"``,
        ``"below the threshold m = ..."``, ``"in the gap ... around the a:b closing ..."``,
        ``"above ..."``, ``"undecided ..."`` (from the proof, :attr:`segments`)."""
        segs = self.segments
        for j, (lo, hi, sign) in enumerate(segs):
            if not lo <= m <= hi:
                continue
            if sign == 1:
                return "exists"
            ranges = self._ranges()
            if sign == 0 and (lo, hi) in self.undecided:
                a, b = self._outer(lo, hi)
                return f"m lies in the range {a} < m < {b} where existence could not be decided"
            if sign == 0:
                return (
                    f"m lies within the enclosure of the threshold near m = "
                    f"{mpmath.nstr(_mpf((lo + hi) / 2), self.digits)}"
                )
            before = [r for r in ranges if self._value(r[1]) <= _mpf(m)]
            after = [r for r in ranges if self._value(r[0]) >= _mpf(m)]
            # the reasons below name the ends of the ranges next to this one as thresholds, or
            # say there is none: not where an undecided range lies between
            below = (
                [segs[j - 1]]
                if j > 0 and (segs[j - 1][0], segs[j - 1][1]) in self.undecided
                else []
            )
            above = (
                [segs[j + 1]]
                if j + 1 < len(segs) and (segs[j + 1][0], segs[j + 1][1]) in self.undecided
                else []
            )
            named = {
                (False, True): above,  # below the threshold
                (False, False): list(self.undecided),  # at no depth
                (True, False): below,  # above the last range
                (True, True): below + above,  # in a gap
            }[(bool(before), bool(after))]
            if named:
                a, b = self._inner(lo, hi)
                und = ", ".join(
                    f"{self._text(u[0], up=False)} < m < {self._text(u[1], up=True)}" for u in named
                )
                return (
                    f"the interval is proven absent for {a} < m < {b}, next to depths where "
                    f"existence could not be decided ({und})"
                )
            if not before and after:
                return f"below the threshold m = {self._text(after[0][0], up=True)}"
            if not before and not after:
                return "the interval exists at no depth 0 < m < 1"
            if not after:
                return (
                    f"above the last range, which ends at m = {self._text(before[-1][1], up=False)}"
                )
            a, b = self._text(before[-1][1], up=False), self._text(after[0][0], up=True)
            closing = _closing_in(self.order, self.Q, self.damping, _mpf(lo), _mpf(hi), self.system)
            around = ""
            if closing is not None:
                mc = closing.m
                around = (
                    f" around the closing T1:T2 = {closing.ratio} (m = {mc.numerator}/"
                    f"{mc.denominator} without friction)"
                )
            return f"in the gap {a} < m < {b}{around}, where friction swallows the interval"
        return "the depth is beyond the range the proof covers"

    def as_json(self) -> dict:
        q = self.Q
        return {
            **self.system.as_json(),
            "order": self.order,
            "Q": str(q.numerator) if q.denominator == 1 else f"{q.numerator}/{q.denominator}",
            "damping": self.damping,
            "digits": self.digits,
            "intervals": self.interval_texts(),
            "thresholds": [
                {
                    "m": t.text(),
                    "appears": t.appears,
                    "enclosure": [
                        _directed_text(t.enclosure[0], self.digits + 3, up=False),
                        _directed_text(t.enclosure[1], self.digits + 3, up=True),
                    ],
                }
                for t in self.thresholds
            ],
            "undecided": self.undecided_texts(),
        }

    def __str__(self) -> str:
        head = f"order {self.order}, Q = {self.as_json()['Q']} ({self.damping} model)"
        if not self.system.is_paper:
            head = f"{self.system.label}: {head}"
        lines = []
        ranges = self.interval_texts()
        if not ranges:
            lines.append(
                f"{head}: the interval exists at no depth 0 < m < 1"
                + (" that could be decided" if self.undecided else "")
            )
        else:
            lines.append(f"{head}: the interval exists for")
            for a, b in ranges:
                lines.append(f"  {a} < m < {b}")
        und = self.undecided_texts()
        for a, b in und[:4]:
            lines.append(f"  undecided: {a} < m < {b}")
        if len(und) > 4:
            lines.append(
                f"  undecided: {len(und) - 4} more ranges within {und[4][0]} < m < {und[-1][1]} "
                "(--json lists them)"
            )
        return "\n".join(lines)

    def _repr_html_(self) -> str:
        """The printed text in a notebook (every certified digit)."""
        from paramres.display import pre_html

        return pre_html(self)


def _closing_in(n: int, Q, damping: str, lo, hi, system: System = PAPER):
    """The frictionless closing (:class:`analytic.closings.Closing`) of order ``n`` whose gap with
    friction lies in ``[lo, hi]`` (``None``: none): without friction and in the paper model at
    its depth, in the exact model at the depth where the damped phases close
    (:func:`_damped_closing`)."""
    for c in _closings_of(n, system):
        if Q is None or damping == "paper":
            mc = float(c.m)
        else:
            mc = _damped_closing(c.a, c.b, Fraction(Q), system)
        if mc is not None and lo <= mc <= hi:
            return c
    return None


def _closings_of(n: int, system: System) -> tuple:
    """The frictionless closings of order ``n`` of ``system``, ordered by depth
    (:func:`analytic.closings.closings`: derived for every member and duty)."""
    from analytic.closings import closings_of_order

    return closings_of_order(n, system)


# ---------------------------------------------------------------------------------------------
# the scan


def closing_depths(n: int, Q: Fraction | None, damping: str, system: System = PAPER) -> list[float]:
    """Depths where the friction-free form of order ``n`` closes (``f(x) = f(y) = 0``), in the
    order of :func:`_closings_of`: both phases turn through whole multiples of ``pi``, ``Omega1 D
    T = a pi``, ``Omega2 (1 - D) T = b pi`` with ``a + b = n`` (:mod:`analytic.closings`).
    Without friction and in the paper model the exact depths of :func:`analytic.closings.closings`
    (the paper's ``(b^2 - a^2)/(b^2 + a^2)``); in the exact model with the damped frequencies,
    where ``a (1 - D) Omega2 = b D Omega1``."""
    found = _closings_of(n, system)
    if Q is None or damping == "paper":
        return [float(c.m) for c in found]
    out = []
    for c in found:
        mc = _damped_closing(c.a, c.b, Fraction(Q), system)
        if mc is not None:
            out.append(mc)
    return out


def _damped_closing(a: int, b: int, Q: Fraction, system: System) -> float | None:
    """The depth where ``a (1 - D) Omega2 = b D Omega1`` with the damped frequencies (float
    bisection; the scaled frequencies of :func:`verify.params.trace_params` are ``nu1 = 2 D
    Omega1/gamma`` and ``nu2 = 2 (1 - D) Omega2/gamma`` for every member, so the condition is
    ``a nu2 = b nu1``).  ``None`` if the phases do not close while both rotate."""
    from analytic.system import phase_regimes

    def rotating(m: Fraction) -> bool:
        return phase_regimes(system, m, Q, "exact") == ("under", "under")

    def h(m: float) -> float:
        tp = trace_params(Fraction(m), Q, backend("math"), system)
        return a * float(tp.nu2) - b * float(tp.nu1)

    # the depths where both phases rotate: an interval from 0 (the laws are monotone in m)
    if not rotating(Fraction(0)):
        return None
    lo, hi = Fraction(0), Fraction(1)
    if not rotating(Fraction(1) - Fraction(1, 2**50)):
        for _ in range(60):
            mid = (lo + hi) / 2
            lo, hi = (mid, hi) if rotating(mid) else (lo, mid)
        hi = lo
    else:
        hi = Fraction(1) - Fraction(1, 2**50)
    flo, fhi = 0.0, float(hi)
    if not fhi > 0:
        return None
    h_lo, h_hi = h(flo), h(fhi)
    if not h_lo * h_hi < 0:
        return None
    for _ in range(80):
        mid = 0.5 * (flo + fhi)
        if (h(mid) < 0) == (h_lo < 0):
            flo = mid
        else:
            fhi = mid
    return 0.5 * (flo + fhi)


def _scan_points(n: int, Q, damping: str) -> np.ndarray:
    pts = [np.logspace(-12, -2, 151), np.linspace(0.01, 0.99, 981), 1 - np.logspace(-2, -9, 121)]
    for mc in closing_depths(n, Q, damping):
        pts.append(
            np.array(
                [
                    mc * (1 + s)
                    for s in (-1e-3, -1e-5, -1e-7, 0, 1e-7, 1e-5, 1e-3)
                    if 0 < mc * (1 + s) < 1
                ]
            )
        )
    ms = np.unique(np.concatenate(pts))
    return ms[(ms > 0) & (ms < 1)]


def max_indicator(n: int, ms, Q: Fraction, damping: str) -> np.ndarray:
    """``max D`` over the window of order ``n`` at each depth (float64; ``> 0``: interval exists).

    Normal form where it applies (vectorised), trace form elsewhere (``-inf`` where the order has
    no window)."""
    from .float_roots import damped_trace, trace_window_ends
    from .grid import damped_normal

    ms = np.atleast_1d(np.asarray(ms, float))
    out = np.full(ms.shape, -np.inf)
    if damping == "paper":
        normal = np.ones(ms.shape, bool)
    else:
        u1 = (4 * float(Q) ** 2 - 1 - ms) / (1 + ms)
        normal = u1 > NEAR_CRITICAL**2
        # exact decision where the float one is in doubt
        for j in np.nonzero(np.abs(u1 - NEAR_CRITICAL**2) < 1e-12)[0]:
            normal[j] = form_for(Fraction(float(ms[j])), Q, damping)[0] == "normal"
    if normal.any():
        P = normal_params(ms[normal], float(Q), damping, backend("numpy"))
        res = damped_normal(np.array([[n]]), P)
        out[normal] = np.asarray(res["dtop"]).ravel()
    for j in np.nonzero(~normal)[0]:
        mj = Fraction(float(ms[j]))
        regimes = form_for(mj, Q, damping)[1] or ("under", "under")
        T = trace_params(mj, Q, backend("math"))
        window = trace_window_ends(n, regimes, T)
        if window is None:
            continue
        out[j] = damped_trace(n, regimes, T, window)["dtop"]
    return out


# ---------------------------------------------------------------------------------------------
# refinement and proof


def _hump(n: int, m: Fraction, Q: Fraction, damping: str, bits: int):
    from .hump import hump_normal, hump_trace

    kind, regimes = form_for(m, Q, damping)
    if kind == "normal":
        return hump_normal(n, m, Q, damping, bits)[0]
    return hump_trace(n, m, Q, regimes)[0]


def _g_ball(n: int, m: Fraction, Q: Fraction, damping: str, bits: int) -> arb | None:
    """``max D`` at depth ``m`` as a ball at about ``bits`` bits (``None``: no window)."""
    h = _hump(n, m, Q, damping, bits)
    if h is None:
        return None
    start = h.top if math.isfinite(h.top) else 0.5 * (h.a + h.b)
    # the maximiser: zero of -D' (increasing through it)
    root = certified_root(
        lambda t: -h.dD(t),
        lambda t: -h.d2D(t),
        start,
        bits=bits // 2 + 16,
        floor=h.floor or 1e-300,
        bracket=(h.a, h.b),
    )
    with ctx.workprec(bits + 32):
        return h.D(root.ball.mid())


def _prove_side(n, m: Fraction, Q, damping, bits, positive: bool) -> bool:
    """Prove ``max D > 0`` (``positive``) or ``max D < 0`` on the window at depth ``m``."""
    from .hump import prove_negative

    h = _hump(n, m, Q, damping, bits)
    if h is None:
        return not positive
    if positive:
        g = _g_ball(n, m, Q, damping, bits)
        return bool(g is not None and g > 0)
    return prove_negative(h, bits)


def _refine(n, Q, damping, m_neg: float, m_pos: float, digits: int) -> Threshold:
    """The depth between ``m_neg`` (no interval) and ``m_pos`` (interval) where ``max D = 0``."""
    bits = bits_for_digits(digits + 3)
    appears = m_pos > m_neg
    # floats: bisection on the sign of g
    lo, hi = m_neg, m_pos
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if mid in (lo, hi):
            break
        if max_indicator(n, [mid], Q, damping)[0] > 0:
            hi = mid
        else:
            lo = mid
    # secant on g in ball arithmetic (midpoints), exact rational depths
    a, b = Fraction(lo), Fraction(hi)
    ga, gb = _g_ball(n, a, Q, damping, bits), _g_ball(n, b, Q, damping, bits)
    tol = Fraction(1, 2 ** (bits + 4)) * b
    for _ in range(100):
        if ga is None or gb is None:  # pragma: no cover - no window on a side (next to a
            # threshold there is one: k > 3 in the over-damped bound); the proofs below decide
            break
        with ctx.workprec(bits + 32):
            gam, gbm = ga.mid(), gb.mid()
            if gbm == gam:
                break
            mb = arb(b.numerator) / b.denominator
            ma = arb(a.numerator) / a.denominator
            mc = (mb - gbm * (mb - ma) / (gbm - gam)).mid()
        c = exact_fraction(to_mpf(mc))
        if not 0 < c < 1:
            break
        a, ga = b, gb
        b, gb = c, _g_ball(n, c, Q, damping, bits)
        if abs(b - a) <= tol:
            break
    mstar = b
    # proof at m* -+ delta
    delta = max(mstar * Fraction(1, 2**bits), Fraction(1, 2 ** (bits + 60)))
    for _ in range(8):
        m_lo, m_hi = mstar - delta, mstar + delta
        below_pos, above_pos = (False, True) if appears else (True, False)
        if (
            0 < m_lo
            and m_hi < 1
            and _prove_side(n, m_lo, Q, damping, bits, below_pos)
            and _prove_side(n, m_hi, Q, damping, bits, above_pos)
        ):
            with mpmath.workprec(bits + 16):
                value = mpmath.mpf(mstar.numerator) / mstar.denominator
            th = Threshold(value, (m_lo, m_hi), bool(appears), digits)
            if th.text() != "0" and _enough(value, m_hi - m_lo, digits):
                return th
        delta *= 4
    raise CertificationError(
        f"could not prove the threshold near m = {float(mstar):.6g} to {digits} digits"
    )


def _enough(value, width: Fraction, digits: int) -> bool:
    with mpmath.workdps(30):
        return _mpf(width) <= abs(value) * mpmath.mpf(10) ** (-digits)


#: the most digits :meth:`Existence._inner` adds to keep a narrow range's ends in order (a range
#: ends at ``1 - 2^-K`` at the least, ``K`` a few bits past the resolution)
_MORE_DIGITS = 40


def _directed_text(x: Fraction, digits: int, *, up: bool) -> str:
    """``x`` rounded to ``digits`` significant digits towards +inf (``up``) or -inf, as decimal
    text: the printed ends of an enclosure still contain what the exact ends contain."""
    if x == 0:
        return "0"
    ax = abs(x)
    e = len(str(ax.numerator)) - len(str(ax.denominator))  # 10**(e-1) <= ax < 10**(e+1)
    if Fraction(10) ** e <= ax:
        pass
    else:
        e -= 1
    scale = digits - 1 - e
    scaled = x * Fraction(10) ** scale
    n = math.ceil(scaled) if up else math.floor(scaled)
    sign, digs = ("-" if n < 0 else ""), str(abs(n))
    if len(digs) > digits:  # rounding carried into a new digit (9.99... -> 10.0)
        e += 1
        scale -= 1
        digs = digs[:-1]
    if -5 <= e < digits:
        if scale > 0:
            digs = digs.rjust(scale + 1, "0")
            text = f"{digs[:-scale]}.{digs[-scale:]}".rstrip("0").rstrip(".")
        else:
            text = digs + "0" * (-scale)
        return sign + text
    mant = f"{digs[0]}.{digs[1:]}".rstrip("0").rstrip(".")
    return f"{sign}{mant}e{e}"


def _mpf(x: Fraction) -> mpmath.mpf:
    """A Fraction as an mpf with enough bits for its digits (rounded to nearest)."""
    with mpmath.workprec(max(64, x.numerator.bit_length(), x.denominator.bit_length()) + 16):
        return mpmath.mpf(x.numerator) / x.denominator


def existence_scan(order, Q, *, damping="exact", digits=15) -> Existence:
    """The former scan (kept for comparison in the benchmark): every threshold it finds is
    proven, but an island narrower than the scan's spacing can be missed.

    Returns an :class:`Existence`: ``.intervals`` (pairs of mpmath numbers, ``b = 1`` when the
    range is open towards ``m -> 1``), ``.thresholds`` (with enclosures), ``.as_json()``.
    """
    n = as_order(order)
    QQ = as_quality(Q)
    if QQ is None:
        raise InputError("existence needs friction: give a quality factor Q > 0")
    model = as_damping(damping)
    d = as_digits(digits)
    Qx = exact_fraction(QQ)
    ms = _scan_points(n, Qx, model)
    g = max_indicator(n, ms, Qx, model)
    # below the scan: no interval as m -> 0 for finite Q; extend down until g < 0
    low = ms[0]
    while g[0] > 0 and low > 1e-280:
        low = low / 1000
        ms = np.concatenate([[low], ms])
        g = np.concatenate([max_indicator(n, [low], Qx, model), g])
    pos = g > 0
    thresholds = []
    for j in range(len(ms) - 1):
        if pos[j] != pos[j + 1]:
            if pos[j + 1]:
                thresholds.append(_refine(n, Qx, model, ms[j], ms[j + 1], d))
            else:
                thresholds.append(_refine(n, Qx, model, ms[j + 1], ms[j], d))
    return Existence(n, Qx, model, d, tuple(thresholds), bool(pos[-1]))


# ---------------------------------------------------------------------------------------------
# the proof: branch and bound over depth ranges

#: the most depth ranges :func:`existence` decides, per bit of the resolution, before it
#: reports the rest as undecided
BUDGET_PER_BIT = 50


def _form_of(m: Fraction, Q: Fraction, damping: str, system: System = PAPER):
    return form_for(m, Q, damping, system)


def _float_stages(
    n: int, boxes, Q: Fraction, damping: str, system: System = PAPER, kinds=None
) -> list:
    """The float stage (maximiser, edges, bracket) at the middle of each range whose equations
    are the normal form, in one vectorised call (``None`` for the others).  The float parameters
    come from the exact middle (right also next to ``m = 1`` and to critical damping).  ``kinds``:
    the equations of each range where known already (:func:`_uniform_form`), else ``None``."""
    from .grid import damped_normal
    from .params import NormalParams

    mids = [(lo + hi) / 2 for lo, hi in boxes]
    out: list = [None] * len(boxes)
    idx, rows = [], []
    for j, x in enumerate(mids):
        kind = kinds[j] if kinds is not None and kinds[j] is not None else None
        if (kind or _form_of(x, Q, damping, system))[0] != "normal":
            continue
        idx.append(j)
        rows.append(normal_params(x, Q, damping, backend("math"), system))
    if not idx:
        return out
    names = [f.name for f in fields(NormalParams)]
    P = NormalParams(*(np.array([float(getattr(r, k)) for r in rows]) for k in names))
    with np.errstate(all="ignore"):
        res = damped_normal(np.array([[n]]), P)
    cols = {k: np.asarray(v, float).ravel() * np.ones(len(idx)) for k, v in res.items()}
    for k, j in enumerate(idx):
        fl = {key: float(val[k]) for key, val in cols.items()}
        fl["bm"] = float(P.bm[k])
        out[j] = fl
    return out


def _decide(
    n: int,
    lo: Fraction,
    hi: Fraction,
    Q: Fraction,
    damping: str,
    bits: int,
    fl,
    system: System,
    form,
) -> int:
    """``+1``: the interval exists at every depth of ``[lo, hi]`` (a point ``T`` with ``D > 0`` in
    the order's window, the same for all of them); ``-1``: at none (``D < 0`` on the whole window
    for all of them); ``0``: not decided on this range.  ``D`` is evaluated with the parameters as
    balls that hold every depth of the range (:func:`verify.solve.depth_ball`); ``fl`` is the
    float stage at the middle (:func:`_float_stages`, or ``None``), only a starting point.
    ``form``: the equations of the whole range (:func:`_uniform_form` of the first range holding
    it)."""
    from .hump import hump_box, hump_trace

    mid = (lo + hi) / 2
    kind, regimes = form
    if kind != "normal":
        touching = _critical_end(lo, hi, Q, damping, regimes, system)
        if touching is not None:  # a half critically damped at or next to an end (verify.bridge)
            from .bridge import decide

            narrow = hi - lo < max(lo, Fraction(1, 2**1000)) / 2**30
            try:
                sign = decide(
                    n,
                    regimes,
                    touching,
                    _box_trace_params(lo, hi, Q, system),
                    4 * _NEGATIVE_PIECES,
                    narrow,
                )
            except (ValueError, ZeroDivisionError, OverflowError, ArithmeticError):
                sign = 0
            if sign:
                return sign
    if kind != "normal" and n == 1 and tuple(regimes) == ("over", "over"):
        # both halves over-damped at every depth of the range (u1 falls and u2 rises with m: the
        # ends and the middle decide it): no interval at any period where kappa <= 6 nu1 nu2
        from .hump import overdamped_no_interval

        with ctx.workprec(64):
            try:
                if overdamped_no_interval(_box_trace_params(lo, hi, Q, system)()):
                    return -1
            except (ValueError, ZeroDivisionError, ArithmeticError):  # pragma: no cover - guard
                pass
    try:
        if kind == "normal":
            h = hump_box(n, lo, hi, Q, damping, float_stage=fl, system=system)
        else:
            h, why = hump_trace(n, mid, Q, regimes, m_box=(lo, hi), system=system)
            if h is None and n == 1 and regimes[1] != "under":
                # both halves over-damped, no sign change of P at the middle: D < 0 is to be
                # proven on all of [0, zend] (beyond it the tail bound)
                T = trace_params(mid, Q, backend("math"), system)
                a = 2 - float(T.nu1) - float(T.nu2)
                if a > 0:
                    zend = max(2 / a, 1.0) * (1 + 1e-6)
                    while abs(float(T.kappa)) * zend * zend * math.exp(-a * zend) >= 0.25:
                        zend *= 1.5
                    h, why = hump_trace(
                        n, mid, Q, regimes, m_box=(lo, hi), window=(1e-9, zend), system=system
                    )
            if h is None:
                # both halves (critically or) over-damped: no rotation, only order 1 can exist;
                # else the phase does not reach the order's window before D < 0 for good
                return -1 if _no_window_on_box(n, lo, hi, Q, regimes, system) else 0
    except (CertificationError, ValueError, ZeroDivisionError, OverflowError, ArithmeticError):
        return 0
    top = h.top
    narrow = hi - lo < max(lo, Fraction(1, 2**1000)) / 2**30
    if narrow and math.isfinite(top):
        start = fl.get("polished", top) if fl is not None else top
        top = _polish_top(h.point or h, start, bits, h.a, h.b)
        if fl is not None:
            fl["polished"] = top
    in_window = kind == "normal" or _in_trace_window(n, lo, hi, Q, regimes, top, system)
    if (narrow or math.isfinite(h.top) and h.dtop > 0) and h.a <= top <= h.b and in_window:
        for prec in (64, 128, 256) if narrow else (64, 128):
            with ctx.workprec(prec):
                val = h.D(_exact_ball(top))
                if not val.is_finite():
                    break
                if val > 0:
                    return 1
                if val < 0 and not narrow:
                    break
    try:
        # the trace form's D near a threshold is flat next to its maximiser, where its balls over
        # a range are wide (kappa grows like (1 - m)^-2): a bisection there takes more pieces,
        # and D' has the larger margin (monotone)
        trace = kind != "normal"
        budget = 4 * _NEGATIVE_PIECES if trace else _NEGATIVE_PIECES
        if _negative_on_box(h, budget=budget, top=top, narrow=narrow, monotone=trace):
            return -1
    except (ValueError, ZeroDivisionError, OverflowError):  # pragma: no cover - guard
        return 0
    return 0


def _critical_end(lo, hi, Q, damping, regimes, system: System = PAPER) -> int | None:
    """The half (``0`` or ``1``) critically damped at an end of the range ``[lo, hi]`` whose inner
    depths have ``regimes`` (none critical), or at a depth outside it within
    :data:`_NEAR_CRITICAL_RANGES` of its widths; else ``None``.  Next to that depth the half's
    ``nu`` is a ball wide for its size, whose ``sin(nu zeta)/nu`` is wide too; the halves' functions
    of :mod:`verify.bridge` stay tight there (its bounds hold over any range with these regimes)."""
    if "critical" in regimes:
        return None
    for x in (lo, hi):
        kind, ends = _form_of(x, Q, damping, system)
        if kind != "normal" and "critical" in ends:
            return ends.index("critical")
    if damping != "exact":
        return None
    for c, half in _critical_depths(Q, system):
        gap = lo - c if c <= lo else c - hi if c >= hi else None
        if gap is not None and gap <= _NEAR_CRITICAL_RANGES * (hi - lo):
            return half
    return None


@lru_cache(maxsize=64)
def _critical_depths(Q: Fraction, system: System = PAPER) -> tuple:
    """``(depth, half)`` of each depth where a half of ``system`` is critically damped (among the
    exact model's regime changes, :func:`_regime_changes`)."""
    out = []
    for c in sorted(_regime_changes(Q, system)):
        kind, ends = _form_of(c, Q, "exact", system)
        if kind != "normal" and "critical" in ends:
            out.append((c, ends.index("critical")))
    return tuple(out)


#: how many of its widths a range may lie from a critical damping and still be decided in the
#: halves' functions (:func:`_critical_end`) before the forms of its regimes
_NEAR_CRITICAL_RANGES = 64


#: the evaluations of each bisection in a range's proof that ``D < 0`` (:func:`_negative_on_box`)
_NEGATIVE_PIECES = 60


def _box_trace_params(lo, hi, Q, system: System = PAPER):
    from .enclosure import AtPrecision
    from .hump import box_prec, depth_ball

    def make():
        Qb = arb(Q.numerator) / Q.denominator
        return trace_params(depth_ball((lo, hi)), Qb, backend("arb"), system)

    return AtPrecision(make, box_prec((lo, hi)))


def _in_trace_window(n, lo, hi, Q, regimes, z, system: System = PAPER) -> bool:
    """``|Phi(z) - n pi| < pi/2`` for every depth of the range (half 2 under-damped), so that a
    point with ``D > 0`` there belongs to order ``n``; with both halves over-damped only order 1
    has a window."""
    from .hump import trace_phase

    if regimes[1] != "under":
        return n == 1
    if not (isinstance(z, arb) or math.isfinite(z)):
        return False
    P = _box_trace_params(lo, hi, Q, system)
    try:
        with ctx.workprec(96):
            ph = trace_phase(regimes, P, _exact_ball(z), (lo, hi), (lo + hi) / 2, Q, system)
            pi = arb.pi()
            return bool(abs(ph - n * pi) < pi / 2)
    except (ValueError, ZeroDivisionError, ArithmeticError):
        return False


def _no_window_on_box(n, lo, hi, Q, regimes, system: System = PAPER) -> bool:
    from .float_roots import trace_window_ends  # noqa: F401  (the float tail bound below is its rule)
    from .hump import prove_no_window

    if regimes[1] != "under":
        return n > 1
    T = trace_params((lo + hi) / 2, Q, backend("math"), system)
    a = 2 - float(T.nu1)
    if not a > 0:
        return False
    z = max(2 / a, 1.0) * (1 + 1e-6)
    while (2 + abs(float(T.kappa)) * z * z) * math.exp(-a * z) >= 0.5:
        z *= 1.25
    # the tail bound needs zeta a > 2 for every depth of the range, and z holds it at the middle
    # with a margin of 1e-6 only: where a's ball is wider, a larger zeta serves as well (the
    # phase, which grows with zeta, must still stay under the order's window there)
    P = _box_trace_params(lo, hi, Q, system)
    for grow in _NO_WINDOW_GROW:
        try:
            if prove_no_window(n, regimes, P, z * grow, (lo, hi), (lo + hi) / 2, Q, system):
                return True
        except (ValueError, ZeroDivisionError, ArithmeticError):
            return False
    return False


#: the factors tried, in turn, on the float tail point of :func:`_no_window_on_box`
_NO_WINDOW_GROW = (1.0, 1.01, 1.1, 1.5)


def _exact_ball(t):
    return t if isinstance(t, arb) else arb(t)


def _polish_top(h, top, bits: int, a: float, b: float):
    """The maximiser of ``D`` refined by Newton's method on ``D'`` (ball midpoints) to about
    ``bits`` bits: near a threshold ``max D`` is tiny and the float maximiser is not good
    enough (any point serves for the proofs; a better one makes them succeed)."""
    from .hump import newton_maximiser

    with ctx.workprec(2 * bits + 40):
        t = newton_maximiser(
            h.dD, h.d2D, _exact_ball(top), 4, arb(2) ** (-2 * bits), arb(2) ** (-4 * bits)
        )
    if not a < t < b:
        return top
    return t


def _negative_on_box(
    h, budget: int, top=None, narrow: bool = False, monotone: bool = False
) -> bool:
    """``D < 0`` on the whole bracket ``[a, b]`` for every depth of the range (the parameters are
    balls): by bisection (:func:`verify.certify.prove_sign`), else by Taylor's bound around the
    float maximiser ``t`` (any point will do; :func:`verify.hump.taylor_negative`, its sides
    first by the sign of ``D'`` with ``monotone``)."""
    from .hump import taylor_negative

    top = h.top if top is None else top
    at_top = (isinstance(top, arb) or math.isfinite(top)) and h.a < top < h.b
    t = top if at_top else 0.5 * (h.a + h.b)
    tf = float(t)
    below = False  # D(t) < 0 proven at some precision
    for prec in (64, 128, 256) if narrow else (64, 128):
        with ctx.workprec(prec):
            tb = _exact_ball(t)
            Dt, D1t = h.D(tb), h.dD(tb)
            if Dt > 0:
                return False
            if not Dt < 0:
                continue
            below = True
            proven = taylor_negative(h, tf, Dt, D1t, 30, prec, budget, monotone, at=tb)
            if proven is not None:
                return proven
    if at_top and not below:
        # not even the value at the maximiser is below zero for every depth of the range (the
        # range straddles a threshold): a bisection of the window, which has to bound D near
        # the maximiser too, at the lowest of these precisions, does not get there either
        return False
    # no usable maximiser: bisection alone
    return prove_sign(h.D, h.dD, h.a, h.b, -1, prec=64, budget=budget)


def _breakpoints(
    n: int, Q: Fraction, damping: str, top: Fraction, system: System = PAPER
) -> list[Fraction]:
    """Where the depth axis is first cut: geometric towards both ends, even in between, at every
    closing (a gap is centred there) and where the equations change (critical damping)."""
    pts = {Fraction(0), top}
    pts.update(Fraction(1, 2**k) for k in range(4, 41))
    pts.update(Fraction(k, 64) for k in range(4, 64))
    k = 7
    while Fraction(1) - Fraction(1, 2**k) < top:
        pts.add(1 - Fraction(1, 2**k))
        k += 1
    for mc in closing_depths(n, Q, damping, system):
        pts.add(Fraction(mc))
    if damping == "exact":
        pts.update(_regime_changes(Q, system))
    return sorted(x for x in pts if 0 <= x <= top)


def _regime_changes(Q: Fraction, system: System) -> set[Fraction]:
    """Depths where the equations change in the exact model: a phase critically damped
    (``omega_i^2 = gamma^2``) and phase 1 at :data:`verify.params.NEAR_CRITICAL` of it, the
    roots of the system's laws (:func:`verify.derived.regime_roots`, solved by sympy, stored as
    their compiled text; the paper's ``4 Q^2 - 1 = +-m``, ...), exact at ``g2 = 1/(4 Q^2)``.  A
    custom system has none: its phases do not depend on ``m``."""
    if not system.uses_depth:
        return set()
    g2, e2 = Fraction(1, 4) / Fraction(Q) ** 2, Fraction(NEAR_CRITICAL) ** 2
    roots = regime_roots(system.name).compiled("exact")(g2, e2)
    if not all(isinstance(root, Fraction | int) for root in roots):  # pragma: no cover - guard
        # the ranges between cuts share their equations only if the cuts are the changes exactly
        raise AssertionError(f"{system.label}: a regime change that is not rational: {roots}")
    return {Fraction(root) for root in roots if 0 < root < 1}


def _segments(n: int, Q: Fraction, damping: str, digits: int, budget: int, system: System = PAPER):
    """The depth axis ``[0, 1 - 2^-K]`` cut into closed ranges, each with its sign
    (:func:`_decide`), adjacent ranges of one sign merged; ``K`` is such that ``2^-K`` is below
    the resolution of ``digits`` digits at ``m = 1``.  Undecided ranges are bisected down to
    that relative resolution, and left undecided past ``budget`` decisions."""
    bits = bits_for_digits(digits + 3)
    top = 1 - Fraction(1, 2 ** (bits + 2))
    cuts = _breakpoints(n, Q, damping, top, system)
    pending = [(cuts[j], cuts[j + 1]) for j in range(len(cuts) - 1)]
    # every depth where the equations change is a cut, so a first range has the equations of
    # its inner depths throughout (:func:`_uniform_form`); its sub-ranges inherit them
    forms = {b: _uniform_form(b, Q, damping, system) for b in pending}
    done: list[tuple] = []
    count = 0
    inherited: dict = {}
    tail_count = 0
    while pending:
        if count >= budget:
            done.extend((lo, hi, 0) for lo, hi in pending)
            break
        # a narrow range takes its parent's float stage (the maximiser is polished in arb)
        fresh = [j for j, b in enumerate(pending) if b not in inherited]
        stages_f = _float_stages(
            n, [pending[j] for j in fresh], Q, damping, system, [forms[pending[j]] for j in fresh]
        )
        stages = [inherited.get(b) for b in pending]
        for j, fl in zip(fresh, stages_f, strict=True):
            stages[j] = fl
        inherited = {}
        nxt = []
        for (lo, hi), fl in zip(pending, stages, strict=True):
            tail = 1 - lo < Fraction(1, 1000)
            if count >= budget or (tail and tail_count >= budget // 3):
                done.append((lo, hi, 0))  # the tail towards m = 1 gets a third of the budget
                continue
            count += 1
            tail_count += tail
            form = forms.pop((lo, hi))
            sign = _decide(n, lo, hi, Q, damping, bits, fl, system, form)
            if sign == 0 and _near_critical_normal(lo, hi, Q, damping, system, form):
                # the normal form degenerates as phase 1 nears critical damping (its terms O(1)
                # where D is O(nu1)); the trace form holds for both halves under-damped as well
                sign = _decide(n, lo, hi, Q, damping, bits, None, system, _UNDER_UNDER)
            splittable = hi - lo > max(lo, Fraction(1, 2**1000)) / 2 ** (bits + 2)
            if sign == 0 and splittable:
                mid = _round_fraction((lo + hi) / 2, lo, hi)
                nxt.extend([(lo, mid), (mid, hi)])
                forms[(lo, mid)] = forms[(mid, hi)] = form
                if fl is not None and hi - lo < max(lo, Fraction(1, 2**1000)) / 2**24:
                    inherited[(lo, mid)] = inherited[(mid, hi)] = fl
            else:
                done.append((lo, hi, sign))
        pending = nxt
    done.sort()
    out: list[list] = []
    for lo, hi, sign in done:
        if out and out[-1][2] == sign and out[-1][1] == lo:
            out[-1][1] = hi
        else:
            out.append([lo, hi, sign])
    return [tuple(x) for x in out], count


#: the trace form with both halves under-damped (:func:`verify.params.form_for`'s choice within
#: :data:`~verify.params.NEAR_CRITICAL` of critical damping)
_UNDER_UNDER = ("trace", ("under", "under"))

#: a range in the normal form is tried in the trace form too where phase 1's ``Omega1/gamma`` is
#: below this at its middle (:func:`_near_critical_normal`)
_NORMAL_NEAR = 4 * NEAR_CRITICAL


def _near_critical_normal(lo, hi, Q, damping: str, system: System, form) -> bool:
    """Whether an undecided range in the normal form (the exact model) lies where phase 1 is near
    critical damping: ``Omega1/gamma < _NORMAL_NEAR`` at its middle (``u1 = (Omega1/gamma)^2`` of
    :func:`verify.system_params.trace_atoms`, before any scaling by the duty).  The trace form
    holds there as well (both halves under-damped at every depth of the range: the normal form is
    chosen only where they are)."""
    if form[0] != "normal" or damping != "exact" or Q is None:
        return False
    u1 = trace_atoms(canonical(system), (lo + hi) / 2, Q, backend("math"))[1]
    return u1 < _NORMAL_NEAR**2


def _uniform_form(box, Q: Fraction, damping: str, system: System):
    """The equations (:func:`verify.params.form_for`) of a first range: those of its inner depths
    (the middle's).  Every depth where the equations change is a cut (:func:`_breakpoints`: the
    regime changes are exact rationals, :func:`_regime_changes`), so the inner depths share them,
    and they hold at the ends as well -- at :data:`~verify.params.NEAR_CRITICAL` both forms are
    valid (the normal form is only less well conditioned), and at a critical damping a half's
    ``nu`` is ``0``, the limit of the inner regime's functions (:mod:`verify.bridge` takes them
    there; :func:`verify.params.trace_params` gives ``nu`` a ball from 0 up)."""
    lo, hi = box
    return _form_of((lo + hi) / 2, Q, damping, system)


def _round_fraction(mid: Fraction, lo: Fraction, hi: Fraction) -> Fraction:
    """A dyadic rational strictly between ``lo`` and ``hi`` near ``mid`` (short numbers)."""
    width = hi - lo
    k = max(0, -(width.numerator.bit_length() - width.denominator.bit_length()) + 3)
    x = Fraction(round(mid * 2**k), 2**k)
    return x if lo < x < hi else mid


def existence(
    order, Q, *, system="pendulum", duty="1/2", damping="exact", digits=15, budget=None
) -> Existence:
    """The depth ranges ``0 < a < m < b <= 1`` where the ``order``-th interval of instability
    exists with friction ``Q`` in the given damping model, proven on the whole depth axis.

    Every range printed and every gap between ranges comes with a proof: the axis is covered by
    closed depth ranges, on each of which the indicator is bounded in ball arithmetic with the
    parameters as balls holding all its depths (branch and bound: a range that cannot be decided
    is bisected).  On a range marked *exists* one period ``T`` is unstable at every depth; on one
    marked *none* ``D < 0`` on the whole window at every depth, so no island, however narrow, is
    missed.  Each end of a range is a threshold whose enclosure is below ``digits`` digits;
    ``m -> 1`` is covered to ``1 - 2^-K`` within that resolution.  What cannot be decided within
    ``budget`` range decisions (or at the resolution, e.g. next to critical damping, where the
    equations change) is reported in ``.undecided``, never guessed.

    ``system`` and ``duty`` choose the member of the family (:mod:`analytic.system`; a
    :class:`~analytic.system.System` passes through): the equations, the closings around which
    the gaps open and the regime changes are derived from its description, and so are the
    parameters of the exact model's trace form over a range of depths
    (:func:`verify.params.trace_params`).  A custom system has no depth and is refused.

    Returns an :class:`Existence`: ``.intervals`` (pairs of mpmath numbers, ``b = 1`` when the
    range is open towards ``m -> 1``), ``.thresholds`` (with enclosures), ``.undecided``,
    ``.as_json()``.
    """
    n = as_order(order)
    sysv = as_system(system, duty)
    if not sysv.uses_depth:
        raise InputError(
            f"existence ranges are over the depth m, and {sysv.label} has none: decide its one "
            "point with boundary(order, system=..., Q=...)"
        )
    QQ = as_quality(Q)
    if QQ is None:
        raise InputError("existence needs friction: give a quality factor Q > 0")
    model = as_damping(damping)
    d = as_digits(digits, EXISTENCE_DIGITS_RANGE)
    Qx = exact_fraction(QQ)
    cap = BUDGET_PER_BIT * bits_for_digits(d + 3) if budget is None else int(budget)
    segs, _count = _segments(n, Qx, model, d, cap, sysv)
    return _assemble(n, Qx, model, d, segs, sysv)


def _assemble(n, Q, model, digits, segs, system: System = PAPER) -> Existence:
    """Thresholds from the undecided ranges that separate the two signs within the resolution;
    every other undecided range is reported as such."""
    # undecided slivers within the resolution of m = 1 belong to the unproven tail towards 1
    near_one = 1 - Fraction(1, 10**digits)
    while len(segs) > 1 and segs[-1][2] == 0 and segs[-1][0] >= near_one:
        segs = segs[:-1]
    thresholds, undecided = [], []
    for j, (lo, hi, sign) in enumerate(segs):
        if sign != 0:
            continue
        left = segs[j - 1][2] if j > 0 else None
        right = segs[j + 1][2] if j + 1 < len(segs) else None
        value = _mpf((lo + hi) / 2)
        if left is not None and right is not None and left * right == -1:
            th = Threshold(value, (lo, hi), right == 1, digits)
            if th.text() != "0" and _enough(value, hi - lo, digits):
                thresholds.append(th)
                continue
        undecided.append((lo, hi))
    pieces = []
    for lo, hi, sign in segs:
        pieces.append((lo, hi, sign))
    return Existence(
        n,
        Q,
        model,
        digits,
        tuple(thresholds),
        bool(segs and segs[-1][2] == 1),
        undecided=tuple(undecided),
        segments=tuple(pieces),
        system=system,
    )


def absence_reason(order, m, Q, *, damping="exact", system=PAPER) -> str:
    """Why the ``order``-th interval does not exist at depth ``m`` with friction ``Q``, from the
    proven existence ranges: below the threshold, in a gap around a closing, above the last
    range, or in a range that could not be decided (see :meth:`Existence.where`)."""
    ex = existence(order, Q, damping=damping, system=system)
    return ex.where(exact_fraction(m))
