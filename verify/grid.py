"""Boundaries in double precision for many orders and depths at once (vectorised numpy).

:func:`boundary_grid` solves the same equations as :func:`verify.solve.boundary` -- the per-edge
equations without friction, the normal form (or the trace form) with it -- for every order and
depth in one set of array operations, and returns ``T/T0`` as a float64 array of shape
``(len(orders), 2, len(m))`` (``[:, 0]`` lower edges, ``[:, 1]`` upper edges, NaN where the interval
does not exist).  It is the fast path for plots and tables; :func:`verify.solve.boundary` is the
certified one, and ``tests/test_grid.py`` checks the two agree to 1e-14 (relative).

The solvers here are also the float stage of the certified path (starting values and brackets).

Method (all orders and depths at once):

* no friction: safeguarded Halley iteration on ``theta`` for each edge equation, bracket
  ``(-pi/2, pi/2)`` (window theorem: one simple root each), started at the fixed point of
  ``theta = asin(-k r f(beta c))``;
* friction, normal form: the undamped-form roots (same ``r``, ``beta``) bracket the interval
  (``D <= D0`` and ``D0 < 0`` outside them); the maximiser of ``D`` is the root of ``D'`` (Newton
  safeguarded by bisection); the edges are the zeros of ``D`` left and right of it;
* exact model with a critically or over-damped half: the same on the trace form in
  ``zeta = gamma T/2``, inside the window of the order (see :mod:`verify.solve`).
"""

from __future__ import annotations

import math
from dataclasses import fields
from fractions import Fraction

import numpy as np

from .derived import (
    backend,
    edge_equation_linear,
    indicator,
    near_one_forms,
    order1_forms,
    trace_indicator,
    trace_window,
)
from .inputs import as_damping, as_depth, as_orders, as_quality
from .params import NEAR_CRITICAL, NormalParams, normal_params, trace_params

__all__ = [
    "boundary_grid",
    "normal_edges",
    "undamped_roots",
    "damped_normal",
    "trace_window_ends",
    "damped_trace",
    "regime_of",
]

_HALF_PI = math.pi / 2
_NP = backend("numpy")


def _parity(n: int) -> str:
    from analytic.stitching import Parity

    return Parity.of(n)


def _sgn(n) -> np.ndarray:
    """``sin(n pi/2)`` for odd ``n``, ``cos(n pi/2)`` for even ``n``: exact ``+-1``, which is
    ``(-1)**(n // 2)`` in both cases."""
    n = np.asarray(n)
    return 1.0 - 2.0 * ((n // 2) % 2)


def undamped_roots(n, r, beta, eps, *, iterations: int = 80):
    """The root in ``(-pi/2, pi/2)`` of the edge equation ``eps`` (``+-1``) for order(s) ``n``;
    ``n``, ``r``, ``beta``, ``eps`` are broadcast together (orders of both parities may be mixed).

    Safeguarded Halley iteration (the bracket starts as the window and shrinks with every sign
    seen), started at ``asin(-k r f(beta c))``, the first fixed-point iterate; only the points not
    yet converged are iterated further.  Returns float64 ``theta`` of the broadcast shape.
    """
    lin, coef = edge_equation_linear()
    fn = lin.compiled("numpy", (0, 1, 2))
    n = np.asarray(n)
    c, sgn, odd = n * _HALF_PI, _sgn(n), (n % 2).astype(float)  # on the small array of orders
    c, sgn, odd, r, beta, eps = np.broadcast_arrays(
        c, sgn, odd, np.asarray(r, float), np.asarray(beta, float), np.asarray(eps, float)
    )
    shape = c.shape
    c, sgn, odd, r, beta, eps = (
        np.ascontiguousarray(a).ravel() for a in (c, sgn, odd, r, beta, eps)
    )
    # start: theta0 = asin(-k f(beta c)) (first fixed-point iterate), then one Newton step on the
    # equation with f(beta (c + theta)) linearised in theta (no new transcendental functions)
    sb, cb = np.sin(beta * c), np.cos(beta * c)
    f0 = np.where(odd == 1, cb, sb)
    f1 = np.where(odd == 1, -sb, cb)
    k = eps * sgn * r * np.where(odd == 1, 1.0, -1.0)
    s0 = np.clip(-k * f0, -1.0, 1.0)
    th = np.arcsin(s0)
    with np.errstate(divide="ignore", invalid="ignore"):
        th1 = th - k * f1 * beta * th / (np.sqrt((1 - s0) * (1 + s0)) + k * f1 * beta)
    th = np.where(np.isfinite(th1) & (np.abs(th1) < _HALF_PI), th1, th)
    lo = np.full(th.shape, -_HALF_PI)
    hi = np.full(th.shape, _HALF_PI)
    idx = np.arange(th.size)
    A, B = (
        np.asarray(v, float) * np.ones(th.shape)
        for v in coef.compiled("numpy", (0, 1))(sgn, eps, odd, r)
    )
    args = (c, beta, A, B)
    sub = args
    for _ in range(iterations):
        t, ll, hh = th[idx], lo[idx], hi[idx]
        f, d1, d2 = fn(t, *sub)
        ll = np.where(f < 0, t, ll)
        hh = np.where(f > 0, t, hh)
        step = f / d1
        step = step / (1.0 - 0.5 * step * d2 / d1)  # Halley
        tn = t - step
        # Halley's error after the step is about K step^3, K = F3/(6 F1) - (F2/(2 F1))^2 with
        # |F3| <= 1 + r beta^3 <= 2: accept tn when that is below rounding
        K = 1.0 / (3.0 * np.abs(d1)) + (0.5 * d2 / d1) ** 2
        small = K * np.abs(step) ** 3 <= 2e-16 * np.abs(tn)
        bad = ~((tn > ll) & (tn < hh) | small) | ~np.isfinite(tn)
        if bad.any():
            tn = np.where(bad, 0.5 * (ll + hh), tn)
        th[idx], lo[idx], hi[idx] = tn, ll, hh
        # the residual is at the level of rounding: 2 ulp of sin(theta) and of the argument of f
        noise = 4.5e-16 * (
            2 * np.abs(t) + np.abs(sub[0] + t) * sub[1] * (np.abs(sub[2]) + np.abs(sub[3]))
        )
        keep = ~(small | (np.abs(f) <= noise) | (hh - ll <= 8e-16 * np.abs(t)))
        if not keep.any():
            break
        if not keep.all():
            idx = idx[keep]
            sub = tuple(a[idx] for a in args)
    return th.reshape(shape)


def normal_edges(n, P, eps_pair=(1, -1)):
    """Both undamped edge roots ``(theta_eps=+1, theta_eps=-1)`` for parameters ``P``
    (arrays broadcast with ``n``)."""
    eps = np.array(eps_pair, float).reshape((len(eps_pair),) + (1,) * max(np.ndim(n), np.ndim(P.r)))
    both = undamped_roots(np.asarray(n)[None], np.asarray(P.r)[None], np.asarray(P.beta)[None], eps)
    return tuple(both)


def _bisect_newton(f_and_df, lo, hi, x0, increasing, *, iterations=100, rtol=4e-16):
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


def damped_normal(n, P):
    """Friction, normal form: ``dict(a, b, top, lo, hi)`` of float64 ``theta`` arrays (one parity):
    the undamped-form bracket ``[a, b]``, the maximiser ``top`` of ``D`` and the edges (NaN where
    the interval does not exist)."""
    n = np.asarray(n)
    parity = _parity(int(n.flat[0]))
    form = indicator(parity)
    dd = form.compiled("numpy", (1, 2))
    d01 = form.compiled("numpy", (0, 1))
    t1, t2 = normal_edges(n, P)
    a, b = np.minimum(t1, t2), np.maximum(t1, t2)
    c = n * _HALF_PI
    args = (c, P.r2, P.u, P.beta, P.g)
    shape = np.broadcast(a, *args).shape
    a, b = np.broadcast_to(a, shape), np.broadcast_to(b, shape)
    # maximiser: zero of D' (decreasing through it)
    d1a = np.asarray(dd(a, *args)[0], float) * np.ones(shape)
    d1b = np.asarray(dd(b, *args)[0], float) * np.ones(shape)
    inside = (d1a > 0) & (d1b < 0)
    top = np.where(d1a <= 0, a, b)
    if inside.any():
        x0 = 0.5 * (a + b)
        root = _bisect_newton(lambda x: dd(x, *args), a, b, x0, False)
        top = np.where(inside, root, top)
    dtop = np.asarray(d01(top, *args)[0], float) * np.ones(shape)
    exists = dtop > 0
    lo = np.full(shape, np.nan)
    hi = np.full(shape, np.nan)
    if exists.any():
        e_lo = _bisect_newton(lambda x: d01(x, *args), a, top, 0.5 * (a + top), True)
        e_hi = _bisect_newton(lambda x: d01(x, *args), top, b, 0.5 * (top + b), False)
        lo = np.where(exists, e_lo, np.nan)
        hi = np.where(exists, e_hi, np.nan)
    return {"a": a, "b": b, "top": top, "dtop": dtop, "lo": lo, "hi": hi}


# ---------------------------------------------------------------------------------------------
# trace form (exact model, a half critically or over-damped)


def regime_of(u) -> str:
    return "under" if u > 0 else ("critical" if u == 0 else "over")


def trace_window_ends(n: int, regimes, T, *, bits: int = 60):
    """The ``zeta``-window of order ``n`` (floats ``(za, zb)``; ``None`` if the order has none).

    Half 2 under-damped: ``Phi(zeta) = n pi -+ pi/2`` (``Phi`` increases strictly), the upper end
    capped where ``(2 + |kappa| zeta^2) exp(-(2 - nu1) zeta) < 1/2`` (``D < 0`` beyond).  Both
    halves critically or over-damped: only ``n = 1``, from the zero of ``P = 2 C1 C2 - kappa S1 S2``
    to a point beyond which ``D < 0`` is guaranteed by ``|kappa| zeta^2 exp(-(2 - nu1 - nu2) zeta) <
    1``.
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
    form = trace_indicator(r1, r2)
    Pf = form.compiled("math", 0)

    def P(z):  # D = sigma P - 2 cosh(2 zeta) with sigma = 1 gives P
        return Pf(z, 1.0, kappa, nu1, nu2) + 2 * math.cosh(2 * z)

    a = 2 - nu1 - nu2
    zend = max(2 / a, 1.0)
    while abs(kappa) * zend * zend * math.exp(-a * zend) >= 0.5:
        zend *= 1.5
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


def damped_trace(n: int, regimes, T, window):
    """Friction, trace form, one order and depth: ``dict(a, b, top, dtop, lo, hi)`` in ``zeta``."""
    sigma = -1.0 if n % 2 else 1.0
    form = trace_indicator(*regimes)
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
        top = float(_bisect_newton(lambda x: fd(x), lo, hi, zs[k], False))
    else:
        top = float(zs[k])
    dtop = d01(top, *args)[0]
    out.update(top=top, dtop=dtop)
    if dtop <= 0:
        return out

    def f01(x):
        return np.array(d01(float(x), *args))

    out["lo"] = float(_bisect_newton(f01, za, top, 0.5 * (za + top), True))
    out["hi"] = float(_bisect_newton(f01, top, zb, 0.5 * (top + zb), False))
    return out


# ---------------------------------------------------------------------------------------------
# the grid


def _halves_float(m: np.ndarray, Q: Fraction):
    """Regime names per depth for the exact model (exact rational decision)."""
    u1 = np.array([4 * Q * Q - 1 - Fraction(float(x)) for x in m], dtype=object)
    u2 = np.array([4 * Q * Q - 1 + Fraction(float(x)) for x in m], dtype=object)
    return [regime_of(a) for a in u1], [regime_of(b) for b in u2]


def boundary_grid(orders, m, *, Q=None, damping="exact") -> np.ndarray:
    """Lower and upper boundaries ``T/T0`` for every order in ``orders`` and depth in ``m``.

    Returns a float64 array of shape ``(len(orders), 2, len(m))``: ``[i, 0, j]`` the lower and
    ``[i, 1, j]`` the upper edge of order ``orders[i]`` at depth ``m[j]``; NaN where the interval
    does not exist.  ``orders`` keeps the caller's order (duplicates allowed); ``m`` is any array
    of depths in ``(0, 1)`` (floats, or exact values converted to the nearest float).  Relative
    error at most 1e-14 against the certified :func:`verify.solve.boundary`.
    """
    orders = [int(o) for o in (orders if not isinstance(orders, int | str) else as_orders(orders))]
    as_orders(orders)  # validates
    scalar = np.ndim(m) == 0
    ms = np.atleast_1d(np.asarray(m, dtype=object if _is_exactish(m) else float))
    if ms.dtype == object:
        ms = np.array([float(as_depth(x)) for x in ms], float)
    else:
        ms = ms.astype(float)
        bad = ~((ms > 0) & (ms < 1))
        if bad.any():
            as_depth(float(ms[np.argmax(bad)]))  # raises the standard error
    Qx = as_quality(Q)
    damping = as_damping(damping)
    out = np.full((len(orders), 2, ms.size), np.nan)
    if Qx is None or damping == "paper":
        Qf = None if Qx is None else float(Qx)
        P = normal_params(ms, Qf, damping, _NP)
        _fill_normal(out, orders, ms, P, damped=Qx is not None)
        return out[..., 0] if scalar else out
    Qexact = Fraction(Qx) if not isinstance(Qx, Fraction) else Qx
    h1, h2 = _halves_float(ms, Qexact)
    u1 = (4 * float(Qexact) ** 2 - 1 - ms) / (1 + ms)
    normal = np.array([a == "under" for a in h1]) & (u1 >= NEAR_CRITICAL**2)
    if normal.any():
        sub = ms[normal]
        P = _exact_near_critical(normal_params(sub, float(Qexact), "exact", _NP), sub, Qexact)
        part = np.full((len(orders), 2, sub.size), np.nan)
        _fill_normal(part, orders, sub, P, damped=True)
        out[:, :, normal] = part
    for j in np.nonzero(~normal)[0]:
        mj = Fraction(float(ms[j]))
        T = trace_params(mj, Qexact, backend("math"))
        for i, n in enumerate(orders):
            window = trace_window_ends(n, (h1[j], h2[j]), T)
            if window is None:
                continue
            res = damped_trace(n, (h1[j], h2[j]), T, window)
            scale = 2 * float(Qexact) / math.pi
            out[i, 0, j] = res["lo"] * scale
            out[i, 1, j] = res["hi"] * scale
    return out[..., 0] if scalar else out


def _exact_near_critical(P, ms, Q: Fraction):
    """Recompute the parameters of depths next to critical damping of half 1 (``4 Q^2 - 1 - m``
    tiny, where its float value has few correct digits) from exact rationals."""
    near = np.nonzero(np.abs(4 * float(Q) ** 2 - 1 - ms) < 1e-8)[0]
    if near.size == 0:
        return P
    cols = {f.name: np.array(getattr(P, f.name), float, copy=True) for f in fields(NormalParams)}
    for j in near:
        pm = normal_params(Fraction(float(ms[j])), Q, "exact", backend("math"))
        for k in cols:
            cols[k][j] = float(getattr(pm, k))
    return NormalParams(**cols)


def _is_exactish(m) -> bool:
    if isinstance(m, str | Fraction):
        return True
    if isinstance(m, list | tuple):
        return any(isinstance(x, str | Fraction) for x in m)
    return False


def _polish_order1(x0, P, cols, eps=None):
    """Newton on the order-1 forms in ``x = pi/2 + theta`` (:func:`verify.derived.order1_forms`)
    for the columns ``cols``: keeps the relative accuracy of small ``x`` (``T -> 0`` as ``m -> 1``).
    ``eps`` picks the undamped edge equation; ``None`` the friction indicator."""
    edge, ind = order1_forms()
    x = np.array(x0, float)
    bm = P.bm[cols]
    if eps is not None:
        fn = edge.compiled("numpy", (0, 1))
        v = P.u[cols] / (1 + P.r[cols])
        args = (v, P.beta[cols], bm)
    else:
        fn = ind.compiled("numpy", (0, 1))
        args = (P.r2[cols], P.u[cols], P.beta[cols], bm, P.g[cols])
    for _ in range(8):
        f, d = fn(x, *args)
        step = np.asarray(f, float) / np.asarray(d, float)
        x = x - step
        if np.all(np.abs(step) <= 4e-16 * np.abs(x)):
            break
    return x


#: below this ``1 - beta`` (``m > 0.995``) the grid polishes with the forms for ``m -> 1``
NEAR_ONE = 0.05


def _polish_near_one(theta, n, P, form):
    """Newton steps on a :func:`verify.derived.near_one_forms` form for the depths with
    ``1 - beta < NEAR_ONE`` (where the standard forms lose ``log10(1/bm)`` digits to
    cancellation); ``theta`` has rows of orders ``n``."""
    cols = np.nonzero(P.bm < NEAR_ONE)[0]
    if cols.size == 0:
        return theta
    theta = np.array(theta, float, copy=True)
    c = (np.asarray(n, float) * _HALF_PI).reshape(-1, 1)
    fn = form.compiled("numpy", (0, 1))
    t = theta[:, cols]
    if len(form.args) == 5 and form.args[2].name == "u":
        args = (c, P.u[cols], P.bm[cols], P.g[cols])
    else:
        args = (c, P.r[cols], P.u[cols] / (1 + P.r[cols]), P.bm[cols])
    for _ in range(2):  # the start is right to ~1e-16/bm: two Newton steps reach rounding
        f, d = fn(t, *args)
        with np.errstate(invalid="ignore", divide="ignore"):
            step = np.asarray(f, float) / np.asarray(d, float)
        t = t - np.where(np.isfinite(step), step, 0.0)
    theta[:, cols] = t
    return theta


def _fill_normal(out, orders, ms, P, damped: bool):
    orders_arr = np.array(orders)
    P = NormalParams(
        *(np.asarray(getattr(P, f.name), float) * np.ones(ms.shape) for f in fields(NormalParams))
    )
    if not damped:
        n = orders_arr[:, None]
        t1, t2 = normal_edges(n, P)
        near = near_one_forms()
        t1 = _polish_near_one(t1, orders_arr, P, near[0])
        t2 = _polish_near_one(t2, orders_arr, P, near[1])
        T1 = (n / 2.0 + t1 / math.pi) / P.w
        T2 = (n / 2.0 + t2 / math.pi) / P.w
        for i in np.nonzero(orders_arr == 1)[0]:  # the eps = +1 root is the one with x -> 0
            x0 = _HALF_PI + t1[i]
            cols = np.nonzero(x0 < 0.5)[0]
            if cols.size:
                T1[i, cols] = _polish_order1(x0[cols], P, cols, 1) / (math.pi * P.w[cols])
        out[:, 0, :] = np.minimum(T1, T2)
        out[:, 1, :] = np.maximum(T1, T2)
        return
    for parity in (1, 0):
        rows = np.nonzero(orders_arr % 2 == parity)[0]
        if rows.size == 0:
            continue
        n = orders_arr[rows][:, None]
        res = damped_normal(n, P)
        near = near_one_forms()[2]
        lo = _polish_near_one(res["lo"], orders_arr[rows], P, near)
        hi = _polish_near_one(res["hi"], orders_arr[rows], P, near)
        base = n / 2.0
        out[rows, 0, :] = (base + lo / math.pi) / P.w
        out[rows, 1, :] = (base + hi / math.pi) / P.w
        for k, i in enumerate(rows):
            if orders_arr[i] != 1:
                continue
            x0 = _HALF_PI + lo[k]
            cols = np.nonzero(np.isfinite(x0) & (x0 < 0.5))[0]
            if cols.size:
                out[i, 0, cols] = _polish_order1(x0[cols], P, cols) / (math.pi * P.w[cols])
