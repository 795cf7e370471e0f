"""Where an interval of instability exists, with friction: thresholds and gaps in the depth ``m``.

With friction the ``n``-th interval exists at depth ``m`` iff the instability indicator ``D`` (see
:mod:`verify.solve`) is positive somewhere in the order's window, i.e. iff ``g(m) = max D > 0``.
``g`` is negative for small ``m`` (the threshold: friction beats a weak modulation) and, for ``n >=
3``, near every depth where the friction-free interval closes (there ``D0`` has a double zero, so
``D = D0 - (1 - r^2) sinh^2 < 0``: friction swallows the interval).  The ends of the ranges are the
depths where ``max D = 0``, i.e. where ``D`` has a double zero in ``theta``.

:func:`existence` finds them in three stages:

1. **scan**: ``g`` in double precision on a grid of depths (log-spaced towards both ends, plus
   every closing depth of the order, where a gap is centred) -- vectorised;
2. **refine**: each sign change is bracketed by bisection in floats, then located to the requested
   digits by the secant method on ``g`` evaluated in ball arithmetic (``g(m) = D(theta*(m))``
   with the maximiser ``theta*`` from Newton's method on ``D'``);
3. **prove**: at two exact rational depths ``m* -+ delta`` a point with ``D > 0`` is exhibited on
   the side where the interval exists, and ``D < 0`` on the whole window is proven on the other
   (:func:`verify.solve._prove_negative`), so the threshold lies in ``[m* - delta, m* + delta]``.

The scan cannot see a range narrower than its spacing away from the closings; every range that
ends at a closing gap or at a threshold is found.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from fractions import Fraction

import mpmath
import numpy as np
from flint import arb, ctx

from .certify import CertificationError, bits_for_digits, certified_root, to_mpf
from .derived import backend
from .inputs import InputError, as_damping, as_digits, as_order, as_quality
from .params import NEAR_CRITICAL, exact_fraction, form_for, normal_params, trace_params

__all__ = ["Existence", "Threshold", "existence", "max_indicator", "closing_depths"]


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
        from .solve import proven_text

        lo, hi = self.enclosure
        return proven_text(self.value, _mpf(hi - lo), self.digits)


@dataclass(frozen=True)
class Existence:
    """The depth ranges ``(a, b)`` in ``(0, 1)`` where the ``order``-th interval exists (``b = 1``:
    open towards ``m -> 1``), and the proven thresholds that bound them."""

    order: int
    Q: Fraction
    damping: str
    digits: int
    thresholds: tuple[Threshold, ...]
    open_to_one: bool

    @property
    def intervals(self) -> list[tuple]:
        """``[(a, b), ...]`` as mpmath numbers (``b = 1`` when open towards 1)."""
        out, start = [], None
        for t in self.thresholds:
            if t.appears:
                start = t.value
            else:
                out.append((start, t.value))
                start = None
        if self.open_to_one:
            out.append((start, mpmath.mpf(1)))
        return out

    def interval_texts(self) -> list[list[str]]:
        out, start = [], None
        for t in self.thresholds:
            if t.appears:
                start = t.text()
            else:
                out.append([start, t.text()])
        if self.open_to_one:
            out.append([start, "1"])
        return out

    def as_json(self) -> dict:
        q = self.Q
        return {
            "order": self.order,
            "Q": str(q.numerator) if q.denominator == 1 else f"{q.numerator}/{q.denominator}",
            "damping": self.damping,
            "digits": self.digits,
            "intervals": self.interval_texts(),
            "thresholds": [
                {
                    "m": t.text(),
                    "appears": t.appears,
                    "enclosure": [mpmath.nstr(_mpf(e), self.digits + 3) for e in t.enclosure],
                }
                for t in self.thresholds
            ],
        }

    def __str__(self) -> str:
        head = f"order {self.order}, Q = {self.as_json()['Q']} ({self.damping} model)"
        if not self.thresholds and not self.open_to_one:
            return f"{head}: the interval exists at no depth 0 < m < 1"
        lines = [f"{head}: the interval exists for"]
        for a, b in self.interval_texts():
            lines.append(f"  {a} < m < {b}" if b != "1" else f"  {a} < m < 1")
        return "\n".join(lines)


# ---------------------------------------------------------------------------------------------
# the scan


def closing_depths(n: int, Q: Fraction | None, damping: str) -> list[float]:
    """Depths where the friction-free form of order ``n`` closes (``f(x) = f(y) = 0``):
    ``a Omega2 = b Omega1`` with ``a + b = n``, ``1 <= a < b`` -- ``m = (b^2 - a^2)/(b^2 + a^2)``
    without friction and in the paper model; in the exact model with the damped frequencies."""
    out = []
    for a in range(1, n):
        b = n - a
        if a >= b:
            continue
        if Q is None or damping == "paper":
            out.append((b * b - a * a) / (b * b + a * a))
            continue
        q2 = 4 * float(Q) ** 2

        def h(m, a=a, b=b, q2=q2):
            nu1 = math.sqrt(max(q2 - 1 - m, 0.0) / (1 + m))
            nu2 = math.sqrt(max(q2 - 1 + m, 0.0) / (1 - m))
            return a * nu2 - b * nu1

        lo, hi = 0.0, min(1.0, q2 - 1) if q2 < 2 else 1.0
        if not (h(lo) < 0 < h(hi * (1 - 1e-15))):
            continue
        for _ in range(80):
            mid = 0.5 * (lo + hi)
            lo, hi = (mid, hi) if h(mid) < 0 else (lo, mid)
        out.append(0.5 * (lo + hi))
    return out


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
    from .grid import damped_normal, damped_trace, trace_window_ends

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
    from .solve import hump_normal, hump_trace

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
    from .solve import _prove_negative

    h = _hump(n, m, Q, damping, bits)
    if h is None:
        return not positive
    if positive:
        g = _g_ball(n, m, Q, damping, bits)
        return bool(g is not None and g > 0)
    return _prove_negative(h, bits)


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
        if ga is None or gb is None:  # pragma: no cover - both sides have a window here
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


def _mpf(x: Fraction) -> mpmath.mpf:
    """A Fraction as an mpf with enough bits for its digits (rounded to nearest)."""
    with mpmath.workprec(max(64, x.numerator.bit_length(), x.denominator.bit_length()) + 16):
        return mpmath.mpf(x.numerator) / x.denominator


def existence(order, Q, *, damping="exact", digits=15) -> Existence:
    """The depth ranges ``0 < a < m < b <= 1`` where the ``order``-th interval of instability
    exists with friction ``Q`` in the given damping model, each end proven to ``digits`` digits.

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
