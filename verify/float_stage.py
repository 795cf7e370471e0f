"""The float stage of one certified point (scalar floats): the start of every certified edge.

:func:`float_edge` is one undamped edge (safeguarded Halley).

:func:`normal_float_stage` gives what the certified solver starts from -- the undamped-form
bracket ``[a, b]``, the maximiser ``top`` of the indicator ``D`` (with ``dtop = D(top)``) and the
two edges ``lo``, ``hi`` (NaN if ``D(top) <= 0``) -- by the same steps as the vectorised
:func:`verify.grid.damped_normal` (safeguarded Halley on the two edge equations, safeguarded Newton
on ``D'`` and on ``D``), on Python floats: for one point a numpy array of one element costs more
in bookkeeping than the arithmetic.  Nothing here is proven; the certified solver checks the
bracket and encloses every root itself (:mod:`verify.hump`).
"""

from __future__ import annotations

import math
from functools import cache

from .derived import edge_equation, indicator
from .enclosure import sgn_of

__all__ = ["float_edge", "normal_float_stage", "bisect_newton"]


@cache
def _forms(odd: bool):
    parity = -1 if odd else 1  # the multiplier (analytic.stitching.Parity)
    form = indicator(parity)
    return (
        edge_equation(parity).compiled("math", (0, 1, 2)),
        form.compiled("math", (0, 1)),
        form.compiled("math", (1, 2)),
    )


def float_edge(fn, n: int, eps: int, r: float, beta: float) -> float:
    """Scalar safeguarded Halley iteration for one undamped edge (the float stage)."""
    c = n * math.pi / 2
    sgn = sgn_of(n)
    odd = n % 2 == 1
    f0 = math.cos(beta * c) if odd else math.sin(beta * c)
    th = math.asin(max(-1.0, min(1.0, -eps * sgn * r * f0 * (1 if odd else -1))))
    lo, hi = -math.pi / 2, math.pi / 2
    for _ in range(100):
        f, d1, d2 = fn(th, c, sgn, eps, r, beta)
        if f < 0:
            lo = th
        elif f > 0:
            hi = th
        else:
            return th
        step = f / d1
        step = step / (1.0 - 0.5 * step * d2 / d1)
        tn = th - step
        K = 1.0 / (3.0 * abs(d1)) + (0.5 * d2 / d1) ** 2
        if K * abs(step) ** 3 <= 2e-16 * abs(tn):
            return tn
        if not lo < tn < hi:
            tn = 0.5 * (lo + hi)
        if hi - lo <= 4e-16 * abs(tn):
            return tn
        th = tn
    return th


def bisect_newton(
    fd, lo: float, hi: float, x0: float, increasing: bool, *, iterations=100, rtol=4e-16
) -> float:
    """Safeguarded Newton for the root of ``f`` in ``[lo, hi]`` (``fd(x) = (f, f')``), where
    ``f(lo) < 0 < f(hi)`` if ``increasing``, else the reverse."""
    x = float(x0)
    sign = 1.0 if increasing else -1.0
    for _ in range(iterations):
        f, df = fd(x)
        f, df = sign * f, sign * df
        if f < 0:
            lo = x
        elif f > 0:
            hi = x
        try:
            step = f / df
        except ZeroDivisionError:
            step = math.inf
        xn = x - step
        scale = max(abs(x), 1e-300)
        small = abs(step) <= 0.5 * rtol * scale
        if not ((lo < xn < hi) or small) or not math.isfinite(xn):
            xn = 0.5 * (lo + hi)
        if small or f == 0 or hi - lo <= rtol * scale or not math.isfinite(x):
            return xn
        x = xn
    return x


def normal_float_stage(n: int, p) -> dict:
    """``dict(a, b, top, dtop, lo, hi)`` in ``theta`` for order ``n`` and float normal-form
    parameters ``p`` (:class:`verify.params.NormalParams` of floats)."""
    edge, d01, d12 = _forms(n % 2 == 1)
    r, r2, u, beta, g = (float(x) for x in (p.r, p.r2, p.u, p.beta, p.g))
    t1 = float_edge(edge, n, 1, r, beta)
    t2 = float_edge(edge, n, -1, r, beta)
    a, b = min(t1, t2), max(t1, t2)
    args = (n * math.pi / 2, r2, u, beta, g)
    d1a = d12(a, *args)[0]
    d1b = d12(b, *args)[0]
    top = a if d1a <= 0 else b
    if d1a > 0 and d1b < 0:
        top = bisect_newton(lambda x: d12(x, *args), a, b, 0.5 * (a + b), False)
    dtop = d01(top, *args)[0]
    lo = hi = math.nan
    if dtop > 0:
        lo = bisect_newton(lambda x: d01(x, *args), a, top, 0.5 * (a + top), True)
        hi = bisect_newton(lambda x: d01(x, *args), top, b, 0.5 * (top + b), False)
    return {"a": a, "b": b, "top": top, "dtop": dtop, "lo": lo, "hi": hi}
