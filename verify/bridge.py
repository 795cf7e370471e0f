"""Existence over a range of depths that ends at a critical damping (the exact model's trace form).

At a depth where a half is critically damped its ``nu`` is 0, and over any range of depths that
ends there the trace form's ``S = sin(nu zeta)/nu`` (or ``sinh(nu zeta)/nu``) is a ball without
bounds: :mod:`verify.existence` split such a range down to its resolution and left a sliver of
about ``2e-15`` undecided at ``m = 1 - 4 Q^2`` (half 2) or ``m = 4 Q^2 - 1`` (half 1).

Here the indicator is the one form of :func:`verify.derived.trace_indicator_halves`, whose
arguments are the values of the halves' functions ``C``, ``S`` themselves (their derivatives in
``zeta`` are ``C' = -u S``, ``S' = C``, proven for every regime as the form is derived).  The
values are taken in a way that stays finite where ``nu`` holds 0 (:func:`half_values`: ``S = zeta
sinc(nu zeta)``), with the parameters as balls holding every depth of the range, its critical end
included.  The phase that numbers the orders is :func:`verify.hump.phase_of` of those values.

Inside the range the halves keep the regimes of its inner depths, and at the critical end the
touching half has no rotation (``C = 1``, ``S = zeta``), the limit of both: the bounds below hold
at every depth of the closed range.
"""

from __future__ import annotations

import math

from flint import acb, arb, ctx

from .certify import prove_sign
from .derived import HALF_SQUARE, trace_indicator_halves
from .hump import newton_maximiser, phase_of, tail_negative

__all__ = ["half_values", "decide"]


def half_values(regime: str, nu, z) -> tuple:
    """``(C, S)`` of a half in ``regime`` (:func:`verify.derived.half_period_forms`: ``cos(nu
    zeta)``, ``sin(nu zeta)/nu``; ``cosh``, ``sinh(nu zeta)/nu``; ``1``, ``zeta``) at ``zeta = z``,
    as balls that stay finite where the ball ``nu`` holds 0: ``S = zeta sinc(nu zeta)``, and over-
    damped ``zeta sinh(x)/x`` with ``x = nu zeta``.  The four functions are even in ``x``;
    ``cosh(x)`` and ``sinh(x)/x`` increase with ``|x|``, ``cos(x)`` and ``sinc(x)`` decrease for
    ``|x| <= 3`` (``< pi``): there their values at the ends of ``|x|``'s range bound them, so a
    ball ``x`` near 0 of width ``r`` gives them to ``O(r^2)``, not to ``O(r)`` as the functions
    of a ball do (:func:`verify.params.trace_params` gives ``nu`` from 0 up: not centred on 0)."""
    if regime == "critical":
        return arb(1), z
    x = nu * z
    lo, hi = x.abs_lower(), x.abs_upper()
    if regime == "under":
        if not hi <= 3:
            return x.cos(), z * x.sinc()
        return lo.cos().union(hi.cos()), z * lo.sinc().union(hi.sinc())
    return lo.cosh().union(hi.cosh()), z * _sinhc(lo).union(_sinhc(hi))


def _sinhc(t):
    """``sinh(t)/t`` at a point ``t >= 0`` (1 at 0)."""
    return acb(0, t).sinc().real


#: the factors tried, in turn, on the float point of the tail bound
_TAIL_GROW = (1.0, 1.1, 1.5, 2.0)
#: points of the float search for the maximiser of ``D`` on ``[0, ztail]``
_GRID = 96
#: the relative margins tried on the window of half 2's phase (half 1 critical at or next to the
#: range)
_WIDEN = (1e-3, 0.02, 0.1)


def decide(n: int, regimes, touching: int, P, budget: int, narrow: bool) -> int:
    """``+1`` (the interval of order ``n`` exists at every depth of the range), ``-1`` (at none)
    or ``0`` (not decided) for a range of depths at or next to a critical damping of half
    ``touching + 1`` (``0`` or ``1``; the bounds below hold for any range of these regimes, the
    critical depth in it or not); ``regimes`` are those of its inner depths, ``P()`` the
    trace parameters as balls holding every depth (:class:`verify.enclosure.AtPrecision`);
    ``budget`` evaluations for the bisection, ``narrow`` for a range within the resolution (the
    value at the maximiser tried at higher precisions).

    - **Half 2 not under-damped inside** (with half 1 over-damped: ``Q < 1/2``): no half rotates
      at any depth of the range, so only order 1 can exist.  Its window lies in ``[0, zt]``,
      beyond which ``D < 0`` (:func:`verify.hump.tail_negative`).
    - **Half 2 under-damped inside, and critical at or next to the range:** its phase ``Phi(zt) <
      n pi - pi/2`` shows that no order ``n >= 2`` reaches its window before ``zt`` (``Phi``
      increases wherever it exceeds ``pi/2``).  Order 1's window lies in ``[0, zt]``; a point
      ``zeta`` with ``D > 0`` belongs to it where ``kappa S1 > 0``, ``C1 > 0``, ``zeta kappa S1 >
      2 C1`` and ``nu2 zeta < pi``: then ``atan2(kappa S1, 2 nu2 C1) = pi/2 - atan(2 nu2
      C1/(kappa S1)) >= pi/2 - 2 nu2 C1/(kappa S1)``, so ``Phi - pi/2 >= nu2 (zeta - 2 C1/(kappa
      S1)) > 0`` for ``nu2 > 0``, and ``Phi <= nu2 zeta + pi/2 < 3 pi/2`` (at the critical depth
      itself only order 1 exists).
    - **Half 1 critical at or next to the range, half 2 under-damped:** the order's window ``[za,
      zb]`` is proven by the phase at its ends, as :func:`verify.hump.hump_trace` proves it.

    ``-1`` where ``D < 0`` on the window (bisection), ``+1`` where ``D > 0`` at the float
    maximiser within it."""
    r1, r2 = regimes
    sigma = -1 if n % 2 else 1
    signs = HALF_SQUARE[r1], HALF_SQUARE[r2]
    forms = [trace_indicator_halves().compiled("arb", k) for k in (0, 1, 2)]

    def values(z):
        p = P()
        C1, S1 = half_values(r1, p.nu1, z)
        C2, S2 = half_values(r2, p.nu2, z)
        return (z, sigma, p.kappa, C1, S1, C2, S2, signs[0] * p.nu1**2, signs[1] * p.nu2**2)

    def phase(z):
        return _phase(r1, P(), z)

    funcs = [lambda z, F=F: F(*values(_ball(z))) for F in forms]
    with ctx.workprec(96):
        p = P()
        kf, n1, n2 = (float(v.mid()) for v in (p.kappa, p.nu1, p.nu2))
    # D's bound beyond zt: |C_i| <= B_i, |S_i| <= zeta B_i, with B_i = 1 under-damped and
    # cosh(nu_i zeta) <= exp(nu_i zeta) else (:func:`verify.hump.tail_negative`)
    over = [r != "under" for r in regimes]
    zt = _tail_point(n1 * over[0] + n2 * over[1], kf)
    if zt is None:
        return 0

    def tail_at(z) -> bool:
        with ctx.workprec(96):
            p = P()
            a = 2 - p.nu1 * over[0] - p.nu2 * over[1]
            return tail_negative(p.kappa, a, arb(z))

    zt = next((zt * g for g in _TAIL_GROW if tail_at(zt * g)), None)
    if zt is None:
        return 0
    pi = arb.pi()
    if r2 != "under" or touching == 1:
        if r2 != "under" and r1 == "under":  # (not met by the paper's pendulum: u1 < u2)
            return 0
        if n > 1:
            if r2 != "under":
                return -1
            with ctx.workprec(96):
                return -1 if phase(arb(zt)) < n * pi - pi / 2 else 0
        a, b = 0.0, zt
    else:
        window = _phase_window(n, phase, zt)
        if window is None:
            with ctx.workprec(96):
                return -1 if phase(arb(zt)) < n * pi - pi / 2 else 0
        a, b = window
    top = _float_top(funcs, a, b)
    if top is not None:
        for prec in (64, 128, 256) if narrow else (64, 128):
            with ctx.workprec(prec):
                t = arb(top)
                if funcs[0](t) > 0 and _in_window(n, regimes, touching, P, phase, t):
                    return 1
    for prec in (64, 128):
        if prove_sign(funcs[0], funcs[1], a, b, -1, prec=prec, budget=budget):
            return -1
    return 0


def _phase(r1: str, p, z):
    """:func:`verify.hump.phase_of` at ``zeta = z`` from half 1's values (:func:`half_values`) in
    regime ``r1``, for every depth the balls ``p`` hold (an under-damped half 1 needs ``nu1 zeta <
    pi`` there, else :class:`ValueError`)."""
    C1, S1 = half_values(r1, p.nu1, z)
    return phase_of(z, p.kappa, p.nu2, C1, S1, p.nu1 if r1 == "under" else None)


def _ball(z):
    return z if isinstance(z, arb) else arb(z)


def _tail_point(b: float, kappa: float) -> float | None:
    """A float ``zeta`` past which ``(2 + |kappa| zeta^2) exp(-(2 - b) zeta)`` stays below 1/4
    (``a zeta > 2``), or ``None`` where ``a = 2 - b`` is not positive."""
    a = 2 - b
    if not a > 0:
        return None
    z = max(2 / a, 1.0) * (1 + 1e-6)
    while (2 + abs(kappa) * z * z) * math.exp(-a * z) >= 0.25:
        z *= 1.25
    return z


def _phase_window(n, phase, zt) -> tuple | None:
    """The window of order ``n`` in ``zeta`` (half 2 under-damped): ``[za, zb]`` with ``Phi(za)``
    between ``(n - 1) pi - pi/2`` and ``n pi - pi/2`` (or ``za = 0`` for order 1) and ``Phi(zb)``
    past ``n pi + pi/2`` (or ``zb = zt``, beyond which ``D < 0``), at every depth of the range;
    ``None`` where ``Phi`` stays below ``n pi - pi/2`` up to ``zt`` (floats, at the parameters'
    midpoints) or where the ends are not proven."""
    pi = math.pi

    def f(z):
        with ctx.workprec(64):
            return float(phase(arb(z)).mid())

    lo_t, hi_t = n * pi - pi / 2, n * pi + pi / 2
    if f(zt) < lo_t:
        return None
    za = 0.0 if n == 1 else _bisect(f, lo_t, 0.0, zt)
    zb = zt if f(zt) <= hi_t else _bisect(f, hi_t, za, zt)
    P = arb.pi()
    for widen in _WIDEN:
        wa, wb = za * (1 - widen), min(zb * (1 + widen), zt)
        with ctx.workprec(96):
            low = wa == 0 or bool(
                phase(arb(wa)) < n * P - P / 2 and phase(arb(wa)) > (n - 1) * P - P / 2
            )
            high = wb == zt or bool(
                phase(arb(wb)) > n * P + P / 2 and phase(arb(wb)) < (n + 1) * P + P / 2
            )
        if low and high:
            return wa, wb
    return None


def _bisect(f, target: float, a: float, b: float) -> float:
    """A float where ``f`` crosses ``target`` in ``[a, b]`` (``f(a) < target <= f(b)``)."""
    for _ in range(80):
        c = 0.5 * (a + b)
        if f(c) < target:
            a = c
        else:
            b = c
    return 0.5 * (a + b)


def _float_top(funcs, a: float, b: float) -> float | None:
    """The maximiser of ``D`` on ``[a, b]``: the best of a grid of midpoints, refined by Newton's
    method on ``D'`` (any point serves the proof; a better one makes it succeed)."""
    best, top = -math.inf, None
    with ctx.workprec(64):
        for k in range(1, _GRID):
            z = a + (b - a) * k / _GRID
            v = float(funcs[0](arb(z)).mid())
            if v > best:
                best, top = v, z
        if top is None:
            return None
        t = newton_maximiser(funcs[1], funcs[2], arb(top), 30, arb(2) ** -50)
    tf = float(t)
    return tf if a < tf < b else top


def _in_window(n, regimes, touching, P, phase, t) -> bool:
    """Whether the point ``t`` belongs to the window of order ``n`` at every depth of the range
    (:func:`decide`)."""
    r1, r2 = regimes
    if r2 != "under":
        return n == 1  # no half rotates
    pi = arb.pi()
    if touching == 1:  # half 2 critical at or next to the range: order 1 by the bound of decide
        if n != 1:
            return False
        p = P()
        C1, S1 = half_values(r1, p.nu1, t)
        kS = p.kappa * S1
        return bool(kS > 0 and C1 > 0 and t * kS > 2 * C1 and p.nu2 * t < pi)
    return bool(abs(phase(t) - n * pi) < pi / 2)
