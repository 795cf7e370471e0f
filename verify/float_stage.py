"""The float stage of one certified point (scalar floats): the start of every certified edge.

:func:`float_edge` is one undamped edge (safeguarded Halley).

:func:`normal_float_stage` gives what the certified solver starts from -- the undamped-form
bracket ``[a, b]``, the maximiser ``top`` of the indicator ``D`` (with ``dtop = D(top)``) and the
two edges ``lo``, ``hi`` (NaN if ``D(top) <= 0``) -- by the same steps as the vectorised
:func:`verify.grid.damped_normal` (safeguarded Halley on the two edge equations, safeguarded Newton
on ``D'`` and on ``D``), on Python floats: for one point a numpy array of one element costs more
in bookkeeping than the arithmetic.  :func:`float_stage` and :func:`float_edges` are the same on
the parameters as floats, returning a tuple.  Nothing here is proven; the certified solver checks
the bracket and encloses every root itself (:mod:`verify.hump`).
"""

from __future__ import annotations

import math
from functools import cache

from .derived import edge_equation, hoisted, indicator
from .enclosure import sgn_of

__all__ = [
    "float_edge",
    "float_stage",
    "float_edges",
    "normal_float_stage",
    "normal_float_edges",
    "wide_float_edges",
    "bisect_newton",
]


@cache
def _forms(odd: bool):
    parity = -1 if odd else 1  # the multiplier (analytic.stitching.Parity)
    form = indicator(parity)
    return (
        edge_equation(parity).compiled("math", (0, 1, 2)),
        form.compiled("math", (0, 1, 2)),
        form.compiled("math", (1, 2)),
    )


def float_edge(fn, n: int, eps: int, r: float, beta: float) -> float:
    """Scalar safeguarded Halley iteration for one undamped edge (the float stage)."""
    c = n * math.pi / 2
    sgn = sgn_of(n)
    odd = n % 2 == 1
    f0 = math.cos(beta * c) if odd else math.sin(beta * c)
    s = -eps * sgn * r * f0 * (1 if odd else -1)
    th = math.asin(s if -1.0 <= s <= 1.0 else -1.0 if s < -1.0 else 1.0)  # (NaN: 1.0)
    lo, hi = -_HALF_PI, _HALF_PI
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
        # the next step is about K |step|^3, K = 1/(3 |f'|) + (f''/(2 f'))^2 (products in place
        # of powers: cheaper, the same test up to the last bit)
        h = 0.5 * d2 / d1
        a = abs(step)
        if (1.0 / (3.0 * abs(d1)) + h * h) * (a * a * a) <= 2e-16 * abs(tn):
            return tn
        if not lo < tn < hi:
            tn = 0.5 * (lo + hi)
        if hi - lo <= 4e-16 * abs(tn):
            return tn
        th = tn
    return th


@cache
def _hoisted(odd: bool):
    """``(prepare, evaluate)`` of ``(D, D', D'')`` (:func:`verify.derived.hoisted`): ``evaluate(x,
    *prepare(c, r2, u, beta, g))`` gives the very floats of :func:`_forms`' ``d012(x, c, r2, u,
    beta, g)``, with the products of the parameters alone computed once per point instead of at
    each evaluation."""
    return hoisted(indicator(-1 if odd else 1).text("math", (0, 1, 2)), "math")


_HALF_PI = math.pi / 2


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


def _halley_edge(
    f012, lo: float, hi: float, x: float, increasing: bool, first, args: tuple = ()
) -> float:
    """Safeguarded Halley iteration for the root of ``f`` in ``[lo, hi]`` (``f012(x, *args) =
    (f, f', f'')``; ``first`` = its value at the start ``x``), where ``f(lo) < 0 < f(hi)`` if
    ``increasing``, else the reverse; the stopping rule of :func:`float_edge`."""
    f, d1, d2 = first
    isfinite = math.isfinite
    for _ in range(100):
        # the bracket moves by the sign of f (of -f where decreasing); the step needs no sign:
        # (-f)/(-f') and (-f'')/(-f') are f/f' and f''/f' exactly
        if f < 0:
            if increasing:
                lo = x
            else:
                hi = x
        elif f > 0:
            if increasing:
                hi = x
            else:
                lo = x
        else:
            return x
        try:
            step = f / d1
            step = step / (1.0 - 0.5 * step * d2 / d1)
            h = 0.5 * d2 / d1
            K = 1.0 / (3.0 * abs(d1)) + h * h
        except ZeroDivisionError:
            step, K = math.inf, math.inf
        xn = x - step
        s = abs(step)
        if K * (s * s * s) <= 2e-16 * abs(xn) and lo <= xn <= hi and isfinite(xn):
            return xn
        if not lo < xn < hi:
            xn = 0.5 * (lo + hi)
        s = abs(xn)  # max(|xn|, 1e-300) written out (xn is finite here: inside the bracket)
        if hi - lo <= 4e-16 * (s if s >= 1e-300 else 1e-300):
            return xn
        x = xn
        f, d1, d2 = f012(x, *args)
    return x


def normal_float_stage(n: int, p) -> dict:
    """``dict(a, b, top, dtop, lo, hi)`` in ``theta`` for order ``n`` and float normal-form
    parameters ``p`` (:class:`verify.params.NormalParams` of floats): :func:`float_stage` as a
    dict."""
    return dict(zip(_KEYS, float_stage(n, *_floats(p)), strict=True))


_KEYS = ("a", "b", "top", "dtop", "lo", "hi")


def _floats(p) -> tuple:
    """``r, r^2, 1 - r^2, beta, g`` of ``p`` as floats."""
    return float(p.r), float(p.r2), float(p.u), float(p.beta), float(p.g)


def float_stage(n: int, r: float, r2: float, u: float, beta: float, g: float) -> tuple:
    """``(a, b, top, dtop, lo, hi)`` in ``theta`` for order ``n`` and the float normal-form
    parameters ``r, r^2, 1 - r^2, beta, g``.

    The steps of :func:`verify.grid.damped_normal` on one point: the maximiser by Newton on
    ``D'`` from where the secant of ``D'`` through the bracket's ends vanishes (to ``1e-12``:
    ``D(top)`` is then below the maximum by about ``D'' 1e-24``), and each edge by Halley's
    method, started where the parabola through the maximiser with the curvature there vanishes
    (or at the bracket's end, where that start falls outside)."""
    odd = n % 2 == 1
    edge, _, d12 = _forms(odd)
    t1 = float_edge(edge, n, 1, r, beta)
    t2 = float_edge(edge, n, -1, r, beta)
    a, b = min(t1, t2), max(t1, t2)
    args = (n * math.pi / 2, r2, u, beta, g)
    prepare, d012 = _hoisted(odd)  # d012(x, *hargs): the floats of _forms' d012(x, *args)
    hargs = prepare(*args)
    at_a = d012(a, *hargs)
    at_b = d012(b, *hargs)
    d1a, d1b = at_a[1], at_b[1]
    if d1a <= 0:
        top, at_top = a, at_a
    elif d1b >= 0:
        top, at_top = b, at_b
    else:
        x0 = a + d1a * (b - a) / (d1a - d1b)
        if not a < x0 < b:
            x0 = 0.5 * (a + b)
        top = bisect_newton(lambda x: d12(x, *args), a, b, x0, False, rtol=1e-12)
        at_top = d012(top, *hargs)
    dtop = at_top[0]
    lo = hi = math.nan
    if dtop > 0:
        curv = at_top[2]
        half = math.sqrt(-2.0 * dtop / curv) if curv < 0 else math.inf
        ends = []
        for end, at_end, x0, inc, (u0, v0) in (
            (a, at_a, top - half, True, (a, top)),
            (b, at_b, top + half, False, (top, b)),
        ):
            if u0 < x0 < v0:
                first = d012(x0, *hargs)
            else:
                x0, first = end, at_end
            ends.append(_halley_edge(d012, u0, v0, x0, inc, first, hargs))
        lo, hi = ends
    return a, b, top, dtop, lo, hi


def normal_float_edges(n: int, p) -> dict:
    """As :func:`normal_float_stage`, cheaper where the interval is not tiny (:func:`float_edges`
    as a dict)."""
    return dict(zip(_KEYS, float_edges(n, *_floats(p)), strict=True))


def float_edges(n: int, r: float, r2: float, u: float, beta: float, g: float) -> tuple:
    """As :func:`float_stage`, cheaper where the interval is not tiny: ``top`` is then the
    middle of the bracket ``[a, b]`` where ``D > 0`` there (``dtop = D(top)``), not the maximiser,
    and each edge is found by Halley's method started at a root of the parabola through that
    point with the slope and curvature there -- or, on a wide bracket (:data:`WIDE`), at the
    bracket's end where Newton's step from there is short (:func:`wide_float_edges`).  Elsewhere
    (``D <= 0`` at the middle, or ``D'' >= 0`` there) it is :func:`float_stage`.  What the
    certified solver needs of ``top`` is a point between the edges where ``D > 0``."""
    return wide_float_edges(n, r, r2, u, beta, g)[:6]


#: a bracket wider than this (in ``theta``) is wide: there ``D`` is far from a parabola (near
#: ``m = 1`` it rises steeply from each end, convex there, to a broad cap), and the float stage
#: evaluates ``D`` at the two ends
WIDE = 1.0


def wide_float_edges(n: int, r: float, r2: float, u: float, beta: float, g: float) -> tuple:
    """:func:`float_edges` and a seventh field, ``convex``: where the bracket is wide
    (:data:`WIDE`), which of its ends have ``D'' >= 0`` in floats -- ``1`` the left, ``2`` the
    right, ``3`` both, ``0`` neither (or a narrow bracket).  There no test of concavity can
    succeed on the whole bracket or on a piece holding such an end (what
    :func:`verify.hump._unimodal` needs to know to start from smaller pieces, and where to test
    ``D'`` first).

    On a wide bracket, ``D`` and its derivatives at the two ends start the edges: an edge whose
    Newton step from the end (``-D/D'`` with ``D < 0 < D'`` at ``a``, ``D'`` of the other sign at
    ``b``) is under an eighth of the half-bracket is started there, where ``D`` is nearly linear
    (a deep modulation puts each edge close to an end); the other at the parabola's root."""
    odd = n % 2 == 1
    edge = _forms(odd)[0]
    t1 = float_edge(edge, n, 1, r, beta)
    t2 = float_edge(edge, n, -1, r, beta)
    a, b = (t1, t2) if t1 < t2 else (t2, t1)
    prepare, d012 = _hoisted(odd)  # d012(x, *args): D, D', D'' (the floats of _forms' d012)
    args = prepare(n * math.pi / 2, r2, u, beta, g)
    mid = 0.5 * (a + b)
    dm, d1, d2 = d012(mid, *args)
    if not (dm > 0 and d2 < 0 and a < mid < b):
        return (*float_stage(n, r, r2, u, beta, g), 0)
    convex = 0
    at_a = at_b = None
    if b - a > WIDE:
        at_a, at_b = d012(a, *args), d012(b, *args)
        convex = (not at_a[2] < 0) + 2 * (not at_b[2] < 0)  # (NaN: convex, the safe side)
        reach = 0.125 * (mid - a)
        fa, da = at_a[0], at_a[1]
        if not (fa < 0 < da and -fa < reach * da):
            at_a = None
        fb, db = at_b[0], at_b[1]
        if not (fb < 0 < -db and -fb < -reach * db):
            at_b = None
    if at_a is None or at_b is None:
        # the parabola dm + d1 t + d2 t^2/2: one root either side of t = 0 (dm > 0 > d2); only
        # where an edge starts from it (on a wide bracket both may start at the bracket's ends)
        disc = math.sqrt(d1 * d1 - 2.0 * d2 * dm)
        q = -0.5 * (d1 + math.copysign(disc, d1))  # the roots q/(d2/2) and dm/q, no cancellation
        if q != 0:
            r0, r1 = q / (0.5 * d2), dm / q
            if r1 < r0:
                r0, r1 = r1, r0
        else:
            r0, r1 = -math.inf, math.inf
    else:
        r0 = r1 = math.nan  # (not used)
    lo = _edge_from(d012, args, a, mid, a, at_a, mid + r0, True)
    hi = _edge_from(d012, args, mid, b, b, at_b, mid + r1, False)
    return a, b, mid, dm, lo, hi, convex


def _edge_from(d012, args: tuple, u: float, v: float, end: float, at_end, x0: float, inc: bool):
    """The edge in ``[u, v]`` by :func:`_halley_edge`: from the bracket's ``end`` where ``D``
    there (``at_end``) was kept as a start, else from the parabola's root ``x0`` (the middle of
    ``[u, v]`` where that falls outside)."""
    if at_end is not None:
        return _halley_edge(d012, u, v, end, inc, at_end, args)
    if not u < x0 < v:
        x0 = 0.5 * (u + v)
    return _halley_edge(d012, u, v, x0, inc, d012(x0, *args), args)
