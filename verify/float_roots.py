"""Double-precision root finding shared by the grid (:mod:`verify.grid`) and the float stage of
the certified friction solver (:mod:`verify.hump`): the safeguarded Newton iteration on arrays,
the window and the edges of the trace form (exact model, a half critically or over-damped), and
the error bounds the double results are held to.  It imports neither of its users, so that the
grid's fallback to the certified route makes no import cycle.
"""

from __future__ import annotations

import math

import numpy as np

from .derived import term_sizes, trace_indicator, trace_indicator_scaled, trace_window

__all__ = [
    "ERROR_BOUND",
    "NOISE_ULPS",
    "DOUBT",
    "bisect_newton",
    "regime_of",
    "trace_window_ends",
    "damped_trace",
]

_HALF_PI = math.pi / 2

#: the relative error bound of every finite entry of :func:`verify.grid.boundary_grid`
ERROR_BOUND = 1e-14
#: rounding of a form's value, in units of 2^-53 times its term sizes (:func:`verify.grid._noise`)
NOISE_ULPS = 4
#: an edge is escalated when its estimated relative error exceeds this (a quarter of the bound)
DOUBT = ERROR_BOUND / 4


def bisect_newton(f_and_df, lo, hi, x0, increasing, *, iterations=100, rtol=4e-16):
    """Vectorised safeguarded Newton for a root of ``f`` in ``[lo, hi]`` with a sign change
    (``f(lo) < 0 < f(hi)`` if ``increasing`` else the reverse)."""
    x = np.array(x0, float)
    lo, hi = np.array(lo, float), np.array(hi, float)
    sign = np.where(increasing, 1.0, -1.0)
    for _ in range(iterations):
        f, df = f_and_df(x)
        f, df = sign * np.asarray(f, float), sign * np.asarray(df, float)
        lo = np.where(f < 0, x, lo)
        hi = np.where(f > 0, x, hi)
        with np.errstate(divide="ignore", invalid="ignore"):
            step = f / df
        xn = x - step
        scale = np.maximum(np.abs(x), 1e-300)
        small = np.abs(step) <= 0.5 * rtol * scale
        bad = ~((xn > lo) & (xn < hi) | small) | ~np.isfinite(xn)
        xn = np.where(bad, 0.5 * (lo + hi), xn)
        if np.all(small | (f == 0) | (hi - lo <= rtol * scale) | ~np.isfinite(x)):
            x = xn
            break
        x = xn
    return x


def regime_of(u) -> str:
    return "under" if u > 0 else ("critical" if u == 0 else "over")


def trace_window_ends(n: int, regimes, T, *, bits: int = 60, scaled: bool = False):
    """The ``zeta``-window of order ``n`` (floats ``(za, zb)``; ``None`` if the order has none).

    Half 2 under-damped: ``Phi(zeta) = n pi -+ pi/2`` (``Phi`` increases strictly wherever it
    exceeds ``pi/2``: :mod:`verify.solve`), the upper end
    capped where ``(2 + |kappa| zeta^2) exp(-(2 - nu1) zeta) < 1/2`` (``D < 0`` beyond).  Both
    halves critically or over-damped: only ``n = 1``, from the zero of ``P = 2 C1 C2 - kappa S1 S2``
    to a point beyond which ``D < 0`` is guaranteed by ``(2 + |kappa| zeta^2) exp(-(2 - nu1 - nu2)
    zeta) < 1`` (``zeta (2 - nu1 - nu2) > 2``) or, both halves over-damped, by ``max(2, 1 +
    |kappa|/(2 nu1 nu2)) exp(-(2 - nu1 - nu2) zeta) < 1``.

    ``scaled``: the start from ``P exp(-2 zeta)`` (:func:`verify.derived.trace_indicator_scaled`,
    the same signs), for a window past the double range, where ``cosh(2 zeta)`` overflows.
    """
    r1, r2 = regimes
    kappa, nu1, nu2 = float(T.kappa), float(T.nu1), float(T.nu2)
    win = trace_window(r1).compiled("math", (0, 1))
    if r2 == "under":

        def phi(z):
            C1, S1 = win(z, 1.0, kappa, nu1, nu2)
            return nu2 * z + math.atan2(kappa * S1, 2 * nu2 * C1)

        # beyond ztail, D <= (2 + |kappa| zeta^2) exp(nu1 zeta) - exp(2 zeta) < 0 (|C2| <= 1,
        # |S2| <= zeta, C1 <= exp(nu1 zeta), S1 <= zeta exp(nu1 zeta)): the window need not go on
        a = 2 - nu1
        ztail = max(2 / a, 1.0)
        while (2 + abs(kappa) * ztail * ztail) * math.exp(-a * ztail) >= 0.5:
            ztail *= 1.25

        def solve(target):
            lo, hi = 0.0, min((target + math.pi) / nu2, ztail)
            if phi(hi) < target:
                return hi, hi
            for _ in range(bits + 10):
                mid = 0.5 * (lo + hi)
                if phi(mid) < target:
                    lo = mid
                else:
                    hi = mid
            return lo, hi

        za = solve(n * math.pi - _HALF_PI)[0]
        zb = min(solve(n * math.pi + _HALF_PI)[1], ztail)
        if r1 == "under" and nu1 * zb >= _HALF_PI:  # pragma: no cover - Phi may not be monotone
            raise ValueError("half 1 too far from critical damping for the trace-form window")
        return (za, zb) if za < zb else None
    if n != 1 or kappa <= 0:
        return None
    if scaled:
        Pw = trace_indicator_scaled(r1, r2).compiled("math", 3)

        def P(z):  # P exp(-2 zeta): the sign of P
            return Pw(z, 1.0, kappa, nu1, nu2)

    else:
        form = trace_indicator(r1, r2)
        Pf = form.compiled("math", 0)

        def P(z):  # D = sigma P - 2 cosh(2 zeta) with sigma = 1 gives P
            return Pf(z, 1.0, kappa, nu1, nu2) + 2 * math.cosh(2 * z)

    a = 2 - nu1 - nu2
    zend = max(2 / a, 1.0)
    while abs(kappa) * zend * zend * math.exp(-a * zend) >= 0.5:
        zend *= 1.5
    if nu1 > 0 and nu2 > 0:
        # both halves over-damped: 2 C1 C2 + |kappa| S1 S2 = (1 + k) cosh(s zeta) + (1 - k)
        # cosh(d zeta) <= max(2, 1 + k) cosh(s zeta) (k = |kappa|/(2 nu1 nu2), s = nu1 + nu2,
        # d = nu1 - nu2), and 2 cosh(2 zeta) >= exp(a zeta) cosh(s zeta): D < 0 once max(2, 1 + k)
        # exp(-a zeta) < 1 (:func:`verify.hump._prove_window`), here with a factor 2 to spare --
        # far sooner when the damping is strong (a small), where the bound above reaches zeta at
        # which cosh(2 zeta) overflows
        k = abs(kappa) / (2 * nu1 * nu2)
        zend = min(zend, max(math.log(2 * max(2.0, 1 + k)) / a, 1.0))
    if P(zend) >= 0:
        return None
    lo, hi = 0.0, zend
    for _ in range(bits + 10):
        mid = 0.5 * (lo + hi)
        if P(mid) > 0:
            lo = mid
        else:
            hi = mid
    return lo, zend


def damped_trace(n: int, regimes, T, window, *, scaled: bool = False):
    """Friction, trace form, one order and depth: ``dict(a, b, top, dtop, lo, hi, doubt)`` in
    ``zeta``; ``doubt``: the sign of ``D`` at the maximiser is within rounding, or an edge's
    estimated relative error exceeds :data:`DOUBT` (as :func:`_normal_doubt`).

    ``scaled``: all of it in ``D exp(-2 zeta)``, its derivatives and its rounding bound
    (:func:`verify.derived.trace_indicator_scaled`), for a window past the double range: the
    same zeros and signs; ``top`` is its maximiser (``D > 0`` there where the interval exists, all
    that the certified stage needs of it) and ``dtop`` its value."""
    sigma = -1.0 if n % 2 else 1.0
    form = trace_indicator_scaled(*regimes) if scaled else trace_indicator(*regimes)
    d01 = form.compiled("math", (0, 1))
    d12 = form.compiled("math", (1, 2))
    args = (sigma, float(T.kappa), float(T.nu1), float(T.nu2))
    za, zb = window
    out = {"a": za, "b": zb, "top": math.nan, "dtop": -math.inf, "lo": math.nan, "hi": math.nan}
    # maximiser: scan then Newton on D' (the window holds at most a few oscillations of nothing)
    zs = np.linspace(za, zb, 65)
    vals = [d01(z, *args)[0] for z in zs]
    k = int(np.argmax(vals))
    lo, hi = zs[max(k - 1, 0)], zs[min(k + 1, len(zs) - 1)]

    def fd(x):
        return np.array(d12(float(x), *args))

    d1lo, d1hi = d12(lo, *args)[0], d12(hi, *args)[0]
    if d1lo > 0 > d1hi:
        top = float(bisect_newton(lambda x: fd(x), lo, hi, zs[k], False))
    else:
        top = float(zs[k])
    dtop = d01(top, *args)[0]
    # the sizes of the terms of D (or D exp(-2 zeta)), without overflow where scaled
    sizes = form.compiled("math", (4, 5)) if scaled else term_sizes(form).compiled("math", (0, 1))

    def noise(z):  # as :func:`_noise`, the angles of size zeta
        total, slope = sizes(z, *args)
        return NOISE_ULPS * 2.0**-53 * (abs(total) + z * abs(slope))

    out.update(top=top, dtop=dtop, doubt=abs(dtop) <= noise(top))
    if dtop <= 0:
        return out

    def f01(x):
        return np.array(d01(float(x), *args))

    out["lo"] = float(bisect_newton(f01, za, top, 0.5 * (za + top), True))
    out["hi"] = float(bisect_newton(f01, top, zb, 0.5 * (top + zb), False))
    for z in (out["lo"], out["hi"]):
        slope = abs(d01(z, *args)[1])
        if not noise(z) <= DOUBT * slope * z:
            out["doubt"] = True
    return out
