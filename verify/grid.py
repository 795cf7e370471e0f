"""Boundaries in double precision for many orders and depths at once (vectorised numpy).

:func:`boundary_grid` solves the same equations as :func:`verify.solve.boundary` -- the per-edge
equations without friction, the normal form (or the trace form) with it -- for every order and
depth in one set of array operations, and returns ``T/T0`` as a float64 array of shape
``(len(orders), 2, len(m))`` (``[:, 0]`` lower edges, ``[:, 1]`` upper edges, NaN where the interval
does not exist).  It is the fast path for plots and tables; :func:`verify.solve.boundary` is the
certified one.  Every finite entry is within a relative :data:`ERROR_BOUND` (1e-14) of the exact
edge, at every depth ``0 < m < 1`` (see :func:`boundary_grid` for where the double computation hands
points to the certified route); ``tests/test_grid.py`` and ``tests/test_grid_hard.py`` check it
against the certified edges on log-spaced samples towards both ends of the depth range.

The solvers here are also the float stage of the certified path (starting values and brackets).

Method (all orders and depths at once):

* no friction: safeguarded Halley iteration on ``theta`` for each edge equation, bracket
  ``(-pi/2, pi/2)`` (window theorem: one simple root each), started at the fixed point of
  ``theta = asin(-k r f(beta c))``; a grid of at least 256 depths starts every edge from a
  cached table of roots per order (2048 depths uniform in ``sqrt(1 - m)``, the cubic through
  the four nearest), and takes the first Halley step of every order at once in work arrays kept
  between calls (:func:`_frictionless_theta`), so that it allocates almost nothing per call;
* friction, normal form, a grid of at least 256 depths away from ``m = 1``: the edges and the
  maximiser of the indicator ``D`` from start tables of their own per ``(system, order, Q,
  damping model)`` (2048 depths uniform in ``sqrt(1 - m)``, the cubic through the four nearest;
  :func:`_table_friction`): one step from there (Householder of order 3 on ``D`` for each edge,
  Halley on ``D'`` for the maximiser), an entry taken where that proves what the bracketed path
  below proves -- both edges converged to zeros of ``D`` inside the window with the edges'
  slopes (``D <= D0 < 0`` there outside the undamped roots: they lie between them), or a
  maximum of ``D`` below minus its rounding bound at a point between the undamped roots (``D0
  > 0`` there);
  next to a threshold (the four nodes do not all have the interval) both edges from the parabola
  (a cubic) through the maximum of ``D`` where that is above its rounding bound
  (:func:`_table_split`);
  where the maximiser is at an end of the undamped interval, no interval by a bound on ``D`` over
  the window (:func:`_no_interval`); next to ``m = 1`` (``1 - beta`` down to
  :data:`TABLE_NEAR_MIN`) the edges where they lie apart; every other entry goes to the bracketed
  path;
* friction, normal form, bracketed: the undamped-form roots (same ``r``, ``beta``) bracket the
  interval (``D <= D0`` and ``D0 < 0`` outside them), in a grid of at least 256 depths from the
  same pass as without friction with start tables per ``(system, order, Q, damping model)``
  (:func:`_damped_brackets`); one compiled call gives ``D``, its first four derivatives and its
  rounding bound (:func:`verify.derived.with_term_sizes`).  From the values at the undamped
  roots, the cubic through ``D'`` and ``D''`` there gives the maximiser of ``D`` and a guess of
  ``D`` there; where the guess is positive, both edges at once (Householder steps of order 3
  safeguarded by bisection, the first from the values at the undamped roots), kept where they
  converge to zeros with the edges' slopes on either side of that split; elsewhere the
  maximiser (Halley steps on ``D'`` where it changes sign) and, where ``D`` is positive there,
  the edges left and right of it.  An edge stops on the error estimate of order 4 of
  its step (:func:`_step`).  Every iteration runs only on the points still moving;
* exact model with a critically or over-damped half: the same on the trace form in
  ``zeta = gamma T/2``, inside the window of the order (see :mod:`verify.solve`);
* near ``m = 1`` (``1 - beta < NEAR_ONE``): Newton steps on the forms for ``m -> 1``
  (:func:`verify.derived.near_one_forms`); the order-1 lower edge, whose ``x = omega_av T/2``
  goes to 0 with ``1 - m``, in ``x`` itself (:func:`verify.derived.order1_forms`); ``1 - m``
  is always computed from the exact depth;
* with friction every entry carries an error estimate (the rounding of the indicator over its
  slope at the edge); next to a threshold or a closing gap, where the edges are a near-double
  root, the few entries that cannot meet the bound are proved in ball arithmetic
  (:func:`_confirm`: the sign of the indicator at the exact depth on both sides of each edge,
  and the secant root between; an edge that misses the bound is moved once to the secant root
  through the two points and tested there) and go to the certified route only where that fails;
* with friction the table path takes both parities in one pass (:class:`_ByParity`: each
  evaluation calls the form of each parity on its part of the points).
"""

from __future__ import annotations

import decimal
import math
import threading
from dataclasses import fields
from fractions import Fraction
from functools import cache, lru_cache

import mpmath
import numpy as np

from .derived import (
    backend,
    edge_equation_linear,
    edge_equation_trig,
    generated_key,
    hoist_powers,
    indicator,
    load_source,
    near_one_forms,
    order1_forms,
    term_sizes,
    with_term_sizes,
)
from .float_roots import (
    DOUBT,
    ERROR_BOUND,
    NOISE_ULPS,
    damped_trace,
    regime_of,
    trace_window_ends,
)
from .float_roots import (
    bisect_newton as _bisect_newton,
)
from .inputs import InputError, as_damping, as_depth, as_orders, as_quality
from .params import (
    NEAR_CRITICAL,
    NormalParams,
    exact_fraction,
    indicator_params,
    normal_params,
    trace_params,
)
from .system_params import trace_atoms

__all__ = [
    "boundary_grid",
    "ERROR_BOUND",
    "normal_edges",
    "undamped_roots",
    "damped_normal",
    "trace_window_ends",
    "damped_trace",
    "regime_of",
]

_HALF_PI = math.pi / 2
_NP = backend("numpy")


def _paper_system():
    from analytic.system import PAPER

    return PAPER


def _parity(n: int) -> str:
    from analytic.stitching import Parity

    return Parity.of(n)


def _sgn(n) -> np.ndarray:
    """``sin(n pi/2)`` for odd ``n``, ``cos(n pi/2)`` for even ``n``: exact ``+-1``, which is
    ``(-1)**(n // 2)`` in both cases."""
    n = np.asarray(n)
    return 1.0 - 2.0 * ((n // 2) % 2)


#: Halley steps of the fast path before a point is handed to the safeguarded iteration
_FAST_STEPS = 8


#: Halley steps for starting values (:func:`undamped_roots` with ``rough``)
_ROUGH_STEPS = 4


def _full(a, shape) -> np.ndarray:
    """``a`` broadcast to ``shape`` as a new C-contiguous float64 array (broadcasting assignment:
    cheaper than ``np.broadcast_to(...).copy()`` on the arrays of a grid)."""
    out = np.empty(shape)
    out[...] = a
    return out


def _sin_cos(a):
    """``sin(a)``, ``cos(a)`` from one tangent of the half angle (``h = tan(a/2)``: ``2h/(1+h^2)``,
    ``(1-h)(1+h)/(1+h^2)``), each to a few ulp of 1: one transcendental call instead of two."""
    h = np.tan(0.5 * a)
    inv = 1.0 / (1.0 + h * h)
    return 2.0 * h * inv, (1.0 - h) * (1.0 + h) * inv


def undamped_roots(n, r, beta, eps, *, start=None, iterations: int = 80, rough=None):
    """The root in ``(-pi/2, pi/2)`` of the edge equation ``eps`` (``+-1``) for order(s) ``n``;
    ``n``, ``r``, ``beta``, ``eps`` are broadcast together (orders of both parities may be mixed).

    Started at ``asin(-k r f(beta c))`` (the first fixed-point iterate) improved by one Newton
    step on the equation with ``f(beta (c + theta))`` linearised in ``theta``, or at ``start``
    (starting values broadcast with the rest, e.g. from :func:`_table_start`); then Halley steps
    on :func:`verify.derived.edge_equation_trig` (its four sines computed once per step), the
    arrays compacted to the points still moving once half of them have stopped.  A point stops
    when Halley's error estimate ``K step^3`` is below ``2^-57`` (an absolute angle next to ``c =
    n pi/2``; the order-1 edge whose ``x = pi/2 + theta`` is small is solved in ``x`` by the
    caller).  Points that leave the window or do not stop within :data:`_FAST_STEPS` steps are
    solved again by the safeguarded iteration (:func:`_safeguarded`: the bracket starts as the
    window and shrinks with every sign seen).  Returns float64 ``theta`` of the broadcast
    shape.

    ``rough``: starting values only (e.g. the nodes of :func:`_table_start`): a point stops once
    its Halley step is below ``rough``, and a point that has not stopped after
    :data:`_ROUGH_STEPS` steps keeps its last iterate (inside the window).
    """
    _lin, coef = edge_equation_linear()
    n = np.asarray(n)
    c, sgn, odd = n * _HALF_PI, _sgn(n), (n % 2).astype(float)  # on the small array of orders
    r, beta, eps = np.asarray(r, float), np.asarray(beta, float), np.asarray(eps, float)
    shape = np.broadcast(c, r, beta, eps).shape
    # the coefficients on the unbroadcast arrays (orders x signs, depths), then one full array
    A, B = coef.compiled("numpy", (0, 1))(sgn, eps, odd, r)

    def full(a):
        if np.shape(a) == shape:
            return np.ascontiguousarray(a, float).ravel()
        out = np.empty(shape)  # (assignment broadcasts in C; np.broadcast_to is slower)
        out[...] = a
        return out.ravel()

    if start is None:
        c, sgn, odd, r, eps = (full(a) for a in (c, sgn, odd, r, eps))
        beta = full(beta)
        # start: theta0 = asin(-k f(beta c)) (first fixed-point iterate), then one Newton step on
        # the equation with f(beta (c + theta)) linearised in theta (no new transcendentals)
        sb, cb = _sin_cos(beta * c)
        isodd = odd == 1
        f0 = np.where(isodd, cb, sb)
        f1 = np.where(isodd, -sb, cb)
        k = eps * sgn * r * np.where(isodd, 1.0, -1.0)
        s0 = np.clip(-k * f0, -1.0, 1.0)
        th = np.arcsin(s0)
        kb = k * f1 * beta
        with np.errstate(divide="ignore", invalid="ignore"):
            th1 = th - kb * th / (np.sqrt((1 - s0) * (1 + s0)) + kb)
        th = np.where(np.isfinite(th1) & (np.abs(th1) < _HALF_PI), th1, th)
        start, bc = th, beta * c
        th = th.copy()
    else:
        bc = full(beta * c)
        beta = full(beta)
        start = np.minimum(np.maximum(full(start), -1.57), 1.57)  # inside the window
        th = start.copy()
    A, B = full(A), full(B)
    trig = edge_equation_trig().compiled("numpy", (0, 1, 2))
    # Halley steps, the arrays compacted to the points still moving once half of them stopped
    idx = np.arange(th.size)
    t, bb, AA, BB = th, beta, A, B
    done = np.zeros(th.size, bool)
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        steps = _FAST_STEPS if rough is None else _ROUGH_STEPS
        for it in range(steps):
            st, ct = np.sin(t), np.cos(t)  # to half an ulp: the last step's residual is the error
            y = bc + bb * t
            sy, cy = np.sin(y), np.cos(y)
            f, d1, d2 = trig(st, ct, sy, cy, bb, AA, BB)
            step = f / d1
            h = 0.5 * d2 / d1
            step /= 1.0 - step * h
            t_old, t = t, t - step
            # a step out of the window goes half way from where it was to the window's end
            out = np.abs(t) >= _HALF_PI
            if out.any():
                t = np.where(out, 0.5 * (t_old + np.copysign(_HALF_PI, t)), t)
            a = np.abs(step)
            # Halley's error after the step is about K step^3, K = F3/(6 F1) - (F2/(2 F1))^2
            # with |F3| <= 1 + r beta^3 <= 2: below 2^-57 (theta is an absolute angle next to
            # c = n pi/2 >= pi/2; the order-1 edge where x = pi/2 + theta is small is solved in x
            # by the caller)
            # by the caller); K >= 1/(3 |F1|) >= 1/6, so this stops no step above 3.5e-6
            if rough is None:
                stop = (1.0 / (3.0 * np.abs(d1)) + h * h) * (a * a * a) <= 7e-18
            else:
                stop = a <= rough
            if out.any():
                stop &= ~out
            last = it == steps - 1
            nstop = np.count_nonzero(stop)
            if not last and nstop * 2 < stop.size:
                continue
            th[idx] = t
            done[idx[stop]] = True
            if last or nstop == stop.size:
                break
            keep = ~stop
            idx, t, bc, bb, AA, BB = (v[keep] for v in (idx, t, bc, bb, AA, BB))
    if rough is None and not done.all():
        redo = np.nonzero(~done)[0]
        th[redo] = _safeguarded(
            start[redo],
            c.ravel()[redo] if c.size == th.size else full(c)[redo],
            beta[redo],
            A[redo],
            B[redo],
            iterations=iterations,
        )
    return th.reshape(shape)


def _safeguarded(th, c, beta, A, B, *, iterations: int = 80):
    """Safeguarded Halley iteration on :func:`verify.derived.edge_equation_linear` from ``th``:
    the bracket starts as the window ``(-pi/2, pi/2)`` and shrinks with every sign seen; only the
    points not yet converged are iterated further."""
    lin, _coef = edge_equation_linear()
    fn = lin.compiled("numpy", (0, 1, 2))
    th = np.array(th, float, copy=True)
    lo = np.full(th.shape, -_HALF_PI)
    hi = np.full(th.shape, _HALF_PI)
    idx = np.arange(th.size)
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
    return th


def normal_edges(n, P, eps_pair=(1, -1)):
    """Both undamped edge roots ``(theta_eps=+1, theta_eps=-1)`` for parameters ``P``
    (arrays broadcast with ``n``)."""
    eps = np.array(eps_pair, float).reshape((len(eps_pair),) + (1,) * max(np.ndim(n), np.ndim(P.r)))
    n, r, beta = np.asarray(n), np.asarray(P.r), np.asarray(P.beta)
    start = None
    if beta.ndim == 1 and r.shape == beta.shape and beta.size >= _TABLE_MIN and n.ndim == 2:
        start = _table_start(n, r, beta, eps)
    both = undamped_roots(n[None], r[None], beta[None], eps, start=start)
    return tuple(both)


#: grids with at least this many depths start from a table of roots at a few of their own depths
_TABLE_MIN = 256
_TABLE_NODES = 97


def _table_start(n, r, beta, eps):
    """Starting values for the roots at every depth: the roots at :data:`_TABLE_NODES` of the
    depths (spread evenly over the sorted ``beta``), interpolated by the cubic through the four
    nearest nodes (each root is an analytic function of the depth with the window theorem's one
    simple root, so the start is right to ``O(h^4)``, about 1e-8, and one Halley step finishes
    it; where it is not, the iteration goes on for those points)."""
    order = np.argsort(beta, kind="stable")
    # distinct positions (beta.size >= _TABLE_NODES), then distinct depths
    k = min(_TABLE_NODES, beta.size)
    pick = order[np.rint(np.arange(k) * ((beta.size - 1) / (k - 1))).astype(int)]
    xb = beta[pick]
    keep = xb[1:] > xb[:-1]
    if not keep.all():
        keep = np.concatenate([[True], keep])
        pick, xb = pick[keep], xb[keep]
    # (len(eps), orders, nodes), to about 1e-12 (a Halley step of 1e-4 leaves ~K 1e-12)
    nodes = undamped_roots(n[None], r[pick][None], xb[None], eps, rough=1e-4)
    flat = nodes.reshape(-1, xb.size)
    return _cubic(xb, flat, beta).reshape(nodes.shape[:-1] + (beta.size,))


def _cubic(xb, rows, x):
    """The rows ``rows`` (``(k, len(xb))``, values at the sorted nodes ``xb``) interpolated at
    ``x`` by the cubic (Lagrange) through the four nodes nearest each point (linearly where
    there are fewer than four nodes): shape ``(k, len(x))``."""
    if xb.size < 4:
        return np.stack([np.interp(x, xb, row) for row in rows])
    j = np.minimum(np.maximum(np.searchsorted(xb, x) - 2, 0), xb.size - 4)
    # the denominators of the Lagrange weights, per interval of nodes (on the small table)
    q = [xb[i : xb.size - 3 + i] for i in range(4)]
    den = [
        (q[i] - q[(i + 1) % 4]) * (q[i] - q[(i + 2) % 4]) * (q[i] - q[(i + 3) % 4])
        for i in range(4)
    ]
    d = [x - q[i][j] for i in range(4)]
    d01, d23 = d[0] * d[1], d[2] * d[3]
    w = (d[1] * d23, d[0] * d23, d01 * d[3], d01 * d[2])
    out = (w[0] / den[0][j]) * np.take(rows, j, axis=1)
    for i in range(1, 4):
        out += (w[i] / den[i][j]) * np.take(rows, j + i, axis=1)
    return out


# ---------------------------------------------------------------------------------------------
# the frictionless grid: start tables per order, one vectorised pass over all orders

#: the start tables hold the roots at this many depths, uniform in ``rho = sqrt(1 - m)`` (for
#: orders up to about 10 the cubic through them is then right to ~1e-8 or better, away from the
#: order-1 edge with ``x -> 0``)
START_NODES = 2048


#: the start tables computed so far, ``(system, n, friction) -> (2, K)`` (``friction``: None or
#: ``(Q, damping)``, :func:`_damped_brackets`; read-only; cleared when it holds
#: :data:`_TABLES_MAX`)
_TABLES: dict = {}
_TABLES_MAX = 512


def _start_tables(system, orders, friction=None) -> list:
    """For each order ``n`` of ``orders``: the roots ``theta`` of both edge equations (rows ``eps
    = +1, -1``) at the depths ``m = 1 - rho^2``, ``rho = (k + 1/2)/K`` (``K =``
    :data:`START_NODES`), shape ``(2, K)``, read-only.  Starting values only
    (:func:`_frictionless_theta` iterates every point to convergence from them), so a table is a
    function of ``system`` and ``n`` alone, computed once (the orders not yet seen in one
    vectorised solve, to 1e-12): it cannot change a result.  ``rho`` makes the roots smooth up
    to ``m = 1``, where the parameters go like ``sqrt(1 - m)``.

    ``friction = (Q, damping)``: the same roots for the parameters of the damped normal form
    (the brackets of the grid with friction, :func:`_fill_normal`), a table per ``(system, n,
    Q, damping)``; where those parameters are not defined (a half not underdamped) the node
    holds the frictionless root (a start like any other)."""
    found = {n: _TABLES.get((system, n, friction)) for n in set(orders)}
    missing = sorted(n for n, tab in found.items() if tab is None)
    if missing:
        rho = (np.arange(START_NODES) + 0.5) / START_NODES
        om = rho * rho
        if friction is not None:
            with np.errstate(all="ignore"):
                P = normal_params(1 - om, friction[0], friction[1], _NP, system, om=om)
            r, beta = (np.asarray(v, float) * np.ones(om.shape) for v in (P.r, P.beta))
            ok = np.isfinite(r) & np.isfinite(beta) & (r >= 0) & (beta > 0)
            r, beta = r[ok], beta[ok]
        else:
            P = normal_params(1 - om, None, "exact", _NP, system, om=om)
            r, beta = np.asarray(P.r, float), np.asarray(P.beta, float)
        n = np.array(missing).reshape(1, -1, 1)
        eps = np.array([1.0, -1.0]).reshape(2, 1, 1)
        roots = undamped_roots(n, r.reshape(1, 1, -1), beta.reshape(1, 1, -1), eps, rough=1e-12)
        if friction is not None:
            plain = np.stack(_start_tables(system, missing), axis=1)
            plain = np.array(plain, float)
            plain[..., ok] = roots
            roots = plain
        if len(_TABLES) + len(missing) > _TABLES_MAX:
            _TABLES.clear()
        for k, order in enumerate(missing):
            tab = np.array(roots[:, k], float)
            tab.flags.writeable = False
            found[order] = _TABLES[(system, order, friction)] = tab
    return [found[n] for n in orders]


class _Plan:
    """What :func:`_frictionless_theta` needs of ``orders`` besides the depths: the rows (one per
    order and sign ``eps``, the odd orders first), ``c = n pi/2`` and the coefficients per unit
    ``r`` of :func:`verify.derived.edge_equation_linear` per row, and the stacked start tables."""

    def __init__(self, system, orders: tuple, friction=None):
        _lin, coef = edge_equation_linear()
        no = len(orders)
        rows = [(e, i) for e in range(2) for i in range(no)]  # (sign eps = 1 - 2 e, order i)
        rows.sort(key=lambda ei: orders[ei[1]] % 2 == 0)  # odd orders first (stable)
        self.rows = len(rows)
        self.odd = sum(1 for _e, i in rows if orders[i] % 2)
        n = np.array([orders[i] for _e, i in rows])
        eps = np.array([1.0 - 2.0 * e for e, _i in rows])
        self.c = (n * _HALF_PI)[:, None]
        odd = (n % 2).astype(float)
        coefs = coef.compiled("numpy", (0, 1))
        a, b = (np.asarray(v, float) * np.ones(n.shape) for v in coefs(_sgn(n), eps, odd, 1.0))
        a2, b2 = (np.asarray(v, float) * np.ones(n.shape) for v in coefs(_sgn(n), eps, odd, 2.0))
        # the structure the kernel relies on (derivation guard): linear in r, cos(y) alone in the
        # odd rows, sin(y) alone in the even ones
        k = self.odd
        if not (
            np.array_equal(a2, 2 * a)
            and np.array_equal(b2, 2 * b)
            and not b[:k].any()
            and not a[k:].any()
            and np.all(np.abs(a[:k]) == 1)
            and np.all(np.abs(b[k:]) == 1)
        ):  # pragma: no cover - derivation guard
            raise AssertionError("edge equation coefficients not of the form the grid assumes")
        self.a, self.b = a[:, None], b[:, None]
        # per unit r: the coefficient of f(y) (cos y in odd rows, sin y in even ones) in F, and
        # that of the other function of y in F'/beta
        self.kf, self.kg = (a + b)[:, None], (b - a)[:, None]
        _check_kernel(self)
        self.order = np.array([i for _e, i in rows])
        self.sign = np.array([e for e, _i in rows])
        # the rows of the order-1 edge that goes to x = pi/2 + theta -> 0 (solved in x after,
        # without friction; with friction that root brackets the lower edge: solved here)
        self.x_rows = [
            k for k, (e, i) in enumerate(rows) if orders[i] == 1 and e == 0 and friction is None
        ]
        tables = _start_tables(system, orders, friction)
        self.table = np.stack([tables[i][e] for e, i in rows])


def _check_kernel(plan) -> None:
    """Derivation guard: ``F, F', F''`` as :func:`_frictionless_block` computes them (``sin
    theta + kf r f(y)``, ``cos theta + kg r beta g(y)``, ``-(sin theta + beta^2 kf r f(y))``)
    equal :func:`verify.derived.edge_equation_trig` at a few points of every row."""
    trig = edge_equation_trig().compiled("numpy", (0, 1, 2))
    R, k = plan.kf.shape[0], plan.odd
    grid = np.linspace(0.1, 1.4, 12).reshape(4, 1, 3)
    t, y, beta, r = (
        np.broadcast_to(grid[i][:, np.roll(np.arange(3), i)], (R, 3)) for i in range(4)
    )
    st, ct, sy, cy = np.sin(t), np.cos(t), np.sin(y), np.cos(y)
    f = np.concatenate([cy[:k], sy[k:]])
    g = np.concatenate([sy[:k], cy[k:]])
    want = trig(st, ct, sy, cy, beta, plan.a * r, plan.b * r)
    ours = (st + plan.kf * r * f, ct + plan.kg * r * beta * g, -(st + beta**2 * plan.kf * r * f))
    for w, o in zip(want, ours, strict=True):
        if not np.allclose(w, o, rtol=1e-13, atol=1e-13):  # pragma: no cover - derivation guard
            raise AssertionError("the grid's edge equation differs from the derived one")


@lru_cache(maxsize=16)
def _plan(system, orders: tuple, friction=None) -> _Plan:
    return _Plan(system, orders, friction)


class _Workspace(threading.local):
    """The work arrays of :func:`_frictionless_theta`, kept between calls (one set per thread):
    a fresh array costs a page fault per 4 KiB on every call, about as much as the arithmetic on
    it.  At most :data:`_WORK_EDGES` edges each (or 64 depths of every row)."""

    def __init__(self):
        self.floats: list = []
        self.flags = np.empty(0, bool)

    def arrays(self, count: int, shape: tuple):
        size = shape[0] * shape[1]
        if len(self.floats) < count or self.floats[0].size < size:
            size_all = max(size, self.floats[0].size if self.floats else 0)
            self.floats = [np.empty(size_all) for _ in range(max(count, len(self.floats)))]
            self.flags = np.empty(size_all, bool)
        views = [b[:size].reshape(shape) for b in self.floats[:count]]
        return views, self.flags[:size].reshape(shape)


_WORK = _Workspace()

#: :func:`_frictionless_theta` works on blocks of depths of at most this many edges
_WORK_EDGES = 1 << 14


def _start_values(table, rho, out, tmp, axis: int = 1) -> None:
    """``out`` (``(rows, len(rho))``) = the rows of ``table`` (values at the nodes of
    :func:`_start_tables`) interpolated at ``rho`` by the cubic through the four nearest nodes.
    ``axis=0``: ``table`` holds the nodes along its rows (``(K, columns)``, one gather per node
    fetches every column) and ``out`` is ``(len(rho), columns)``; the same numbers."""
    K = table.shape[axis]
    u = rho * K - 0.5  # the position in units of the node spacing
    j = np.floor(u)
    np.clip(j - 1, 0, K - 4, out=j)
    v = u - j
    v1, v2, v3 = v - 1, v - 2, v - 3
    v01, v23 = v * v1, v2 * v3
    j = j.astype(np.intp)
    # the Lagrange weights of the nodes j .. j+3 (uniform spacing)
    np.take(table, j, axis=axis, out=out, mode="clip")  # (j is in range: no checks)
    w = v1 * v23 * (-1 / 6)
    out *= w if axis else w[:, None]
    for i, w in ((1, v * v23 * 0.5), (2, v01 * v3 * -0.5), (3, v01 * v2 * (1 / 6))):
        np.take(table, j + i, axis=axis, out=tmp, mode="clip")
        tmp *= w if axis else w[:, None]
        out += tmp


def _frictionless_theta(orders, P, rho, system, theta, friction=None) -> None:
    """Both undamped edge roots of every order at every depth: ``theta[i, 0]`` the root of the
    edge equation ``eps = +1`` of ``orders[i]``, ``theta[i, 1]`` that of ``eps = -1`` (``theta``:
    ``(len(orders), 2, N)``, filled here), for the parameters ``P`` (arrays of ``N`` depths),
    ``rho = sqrt(1 - m)``.  The same equations and convergence test as :func:`undamped_roots`,
    all orders in one pass, in blocks of :data:`_WORK_EDGES` edges in kept work arrays.

    Started from the cached tables of :func:`_start_tables` (right to about 1e-8 for the orders
    of a plot, so that one Halley step finishes most points).  That first step, on every point,
    computes to full accuracy only the sines that enter the equation itself (``sin theta`` and
    ``f(y)``: ``cos y`` in the rows of odd orders, ``sin y`` in the even ones); ``cos theta`` and
    the other function of ``y``, which enter only the derivative, come from the Pythagorean
    identity, and the convergence test adds what their error costs the step.  The points that
    have not converged go on with every sine computed, compacted, and to the safeguarded
    iteration (:func:`_safeguarded`) if they still have not."""
    plan = _plan(system, tuple(orders), friction)
    width = max(64, _WORK_EDGES // plan.rows)
    N = rho.size
    beta_all = np.ascontiguousarray(P.beta, float)
    r_all = np.ascontiguousarray(P.r, float)
    for j0 in range(0, N, width):
        j1 = min(N, j0 + width)
        block = _frictionless_block(plan, rho[j0:j1], beta_all[j0:j1], r_all[j0:j1])
        theta[plan.order, plan.sign, j0:j1] = block


def _frictionless_block(plan, rho, beta, r):
    """:func:`_frictionless_theta` on one block of depths: ``theta`` of the rows of ``plan`` (a
    work array, valid until the next call)."""
    N, k = rho.size, plan.odd
    (th, start, kf, kg, bc, st, y, fy, gy, ct, tmp, q), stop = _WORK.arrays(12, (plan.rows, N))
    _start_values(plan.table, rho, th, tmp)
    np.clip(th, -1.57, 1.57, out=th)  # inside the window
    np.copyto(start, th)
    np.multiply(plan.kf, r, out=kf)  # the coefficient of f(y) in F
    np.multiply(plan.kg, r * beta, out=kg)  # the coefficient of the other function in F'
    np.multiply(plan.c, beta, out=bc)
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        np.sin(th, out=st)
        np.multiply(th, beta, out=y)
        y += bc
        np.cos(y[:k], out=fy[:k])
        np.sin(y[k:], out=fy[k:])
        # cos theta >= 0 in the window; the other function of y with the sign of its quadrant:
        # sin y >= 0 where floor(y/pi) is even, cos y >= 0 where floor(y/pi + 1/2) is (y >= 0)
        np.subtract(1.0, st, out=ct)
        np.add(1.0, st, out=tmp)
        ct *= tmp
        np.sqrt(ct, out=ct)
        np.multiply(y, 1 / math.pi, out=q)
        q[k:] += 0.5
        np.floor(q, out=q)
        np.multiply(q, 0.5, out=tmp)
        np.floor(tmp, out=tmp)
        tmp *= 2.0
        q -= tmp
        np.subtract(0.5, q, out=q)  # > 0 where the function is >= 0
        np.subtract(1.0, fy, out=gy)
        np.add(1.0, fy, out=tmp)
        gy *= tmp
        np.sqrt(gy, out=gy)
        np.copysign(gy, q, out=gy)
        # F, F', F'' (the form of verify.derived.edge_equation_trig, checked by _Plan)
        np.multiply(kf, fy, out=kf)  # A cos y + B sin y
        np.multiply(kg, gy, out=kg)  # beta (B cos y - A sin y)
        np.add(st, kf, out=fy)  # F
        kg += ct  # F'
        kf *= beta * beta
        kf += st  # -F''
        # Halley: step = (F/F') / (1 - (F/F') F''/(2 F'))
        fy /= kg  # F/F'
        kf /= kg
        kf *= -0.5  # h = F''/(2 F')
        np.multiply(fy, kf, out=tmp)
        np.subtract(1.0, tmp, out=tmp)
        fy /= tmp  # the step
        np.subtract(th, fy, out=y)  # the new iterate
        # Halley's error K step^3 (as in undamped_roots), and what the identity costs: the
        # square of each partner is right to 2.2e-16 (that of f to half an ulp), so the partner
        # p to 2.2e-16 (1/p + p), F' to 4.4e-16 (1/min(cos theta, |p|) + 1) (r, beta <= 1), and
        # the step to that over |F'|, relative: below 7e-18 where 128 |step| <= min |F'|
        np.abs(fy, out=fy)  # |step|
        np.abs(kg, out=kg)  # |F'|
        np.abs(gy, out=gy)
        np.minimum(gy, ct, out=gy)
        gy *= kg
        np.multiply(fy, 128.0, out=tmp)
        np.less_equal(tmp, gy, out=stop)
        np.multiply(kg, 3.0, out=tmp)
        np.reciprocal(tmp, out=tmp)
        kf *= kf
        tmp += kf  # K
        np.multiply(fy, fy, out=gy)
        gy *= fy
        gy *= tmp
        stop &= gy <= 7e-18
        for row in plan.x_rows:  # done where _fill_frictionless solves it again in x from here
            stop[row] |= y[row] < 0.5 * ORDER1_X - _HALF_PI
        np.abs(y, out=tmp)
        out = tmp >= _HALF_PI
        if out.any():  # a step out of the window goes half way to the window's end
            y[out] = 0.5 * (th[out] + np.copysign(_HALF_PI, y[out]))
            stop &= ~out
    flat = y.ravel()
    idx = np.flatnonzero(~stop)
    if idx.size:
        _finish(plan, flat, idx, start.ravel()[idx], N, beta, r)
    return y


def _finish(plan, flat, idx, start, N: int, beta, r) -> None:
    """The points ``idx`` of a block (``flat``: its iterates, rows of ``plan`` times ``N``
    depths) that the first step did not finish: Halley steps with every sine computed, the
    points dropped as they converge, and the safeguarded iteration from ``start`` for those that
    do not within :data:`_FAST_STEPS` steps."""
    trig = edge_equation_trig().compiled("numpy", (0, 1, 2))
    row, col = np.divmod(idx, N)
    bb, rr = beta[col], r[col]
    A, B = plan.a[row, 0] * rr, plan.b[row, 0] * rr
    cc = plan.c[row, 0]
    bc = cc * bb
    pos = np.arange(idx.size)
    t = flat[idx]
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        for _ in range(_FAST_STEPS - 1):
            b = bb[pos]
            y = bc[pos] + b * t
            f, d1, d2 = trig(np.sin(t), np.cos(t), np.sin(y), np.cos(y), b, A[pos], B[pos])
            step = f / d1
            h = 0.5 * d2 / d1
            step /= 1.0 - step * h
            tn = t - step
            a = np.abs(step)
            ok = (1.0 / (3.0 * np.abs(d1)) + h * h) * (a * a * a) <= 7e-18
            out = np.abs(tn) >= _HALF_PI
            if out.any():
                tn = np.where(out, 0.5 * (t + np.copysign(_HALF_PI, tn)), tn)
                ok &= ~out
            flat[idx[pos]] = tn
            pos, t = pos[~ok], tn[~ok]
            if not pos.size:
                return
    flat[idx[pos]] = _safeguarded(start[pos], cc[pos], bb[pos], A[pos], B[pos])


def _bisect_newton_compact(
    fn,
    args,
    lo,
    hi,
    x0,
    increasing: bool,
    *,
    scale=None,
    halley=False,
    rtol=4e-16,
    iterations=100,
    first=None,
):
    """Safeguarded Newton (``halley=True``: Halley, ``fn`` also giving ``f''``) for ``fn(x, *args)
    -> (f, df[, d2f])`` on arrays, one root per point in ``[lo, hi]`` with a sign change
    (``f(lo) < 0 < f(hi)`` if ``increasing`` else the reverse; ``increasing`` may be an array of
    ``+-1``, per point): everything broadcast to one shape,
    the bracket shrunk with every sign seen, a step that leaves it replaced by bisection, and each
    point dropped from the iteration once it has converged, so that the few slow points do not keep
    the whole array iterating.  A point has converged when its last step or its bracket is below
    ``rtol`` of ``scale`` (the size that sets the relative error: ``c + theta``, where ``T`` is
    proportional to it; ``|x|`` when ``scale`` is None), or when ``f`` is exactly 0.  ``first``:
    ``fn(x0, *args)`` flattened, if the caller has it already."""
    shape = np.broadcast(np.asarray(x0), np.asarray(lo), np.asarray(hi), *args).shape
    if isinstance(increasing, bool):
        increasing = 1.0 if increasing else -1.0
    if scale is None:
        scale = np.abs(np.asarray(x0, float))
    flat = [_full(a, shape).ravel() for a in (x0, lo, hi, scale, increasing, *args)]
    x, lo, hi, sc, sgn = flat[0].copy(), flat[1].copy(), flat[2].copy(), flat[3], flat[4]
    args = flat[5:]
    tol = rtol * np.maximum(np.abs(sc), 1e-300)
    out = x.copy()
    idx = np.arange(x.size)
    sub, tl, sign = args, tol, sgn
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        for it in range(iterations):
            vals = first if it == 0 and first is not None else fn(x, *sub)
            f, df = sign * np.asarray(vals[0], float), sign * np.asarray(vals[1], float)
            lo = np.where(f < 0, x, lo)
            hi = np.where(f > 0, x, hi)
            step = f / df
            if halley:
                step = step / (1.0 - 0.5 * step * (sign * np.asarray(vals[2], float)) / df)
            xn = x - step
            small = np.abs(step) <= 0.5 * tl
            bad = ~((xn > lo) & (xn < hi) | small) | ~np.isfinite(xn)
            xn = np.where(bad, 0.5 * (lo + hi), xn)
            out[idx] = xn
            stop = small | (f == 0) | (hi - lo <= tl) | ~np.isfinite(x)
            if stop.all():
                break
            if stop.any():
                keep = ~stop
                idx, xn, lo, hi, tl = idx[keep], xn[keep], lo[keep], hi[keep], tl[keep]
                sign = sign[keep]
                sub = tuple(a[idx] for a in args)
            x = xn
    return out.reshape(shape)


def damped_normal(n, P, edges=None):
    """Friction, normal form: ``dict(a, b, top, dtop, lo, hi)`` of float64 ``theta`` arrays (one
    parity): the undamped-form bracket ``[a, b]``, the maximiser ``top`` of ``D`` with ``dtop =
    D(top)``, and the edges (NaN where the interval does not exist).  ``edges``: the undamped
    roots ``normal_edges(n, P)`` if the caller has them already.  (:func:`_damped_normal` also
    gives the error estimates of the grid.)"""
    res = _damped_normal(n, P, edges)
    return {k: res[k] for k in ("a", "b", "top", "dtop", "lo", "hi")}


@cache
def _indicator_all(parity: int, sizes: bool = True):
    """``(D, D', D'', D''', D'''', sum |t_i|, sum |dt_i/dtheta|)`` of the indicator of ``parity``
    in one compiled numpy call (:func:`verify.derived.with_term_sizes`: six transcendental
    calls); ``sizes=False``: ``(D, D', D'', D''')`` only."""
    if not sizes:
        return with_term_sizes(indicator(parity)).compiled("numpy", (0, 1, 2, 3))
    return with_term_sizes(indicator(parity), 4).compiled("numpy", (0, 1, 2, 3, 4, 5, 6))


@cache
def _indicator_powers(parity: int):
    """:func:`_indicator_all` with the powers ``beta**k`` and ``g**k`` (``k >= 3``) of the
    parameters taken as arguments (:func:`verify.derived.hoist_powers`): ``(fn, powers)``, ``fn``
    called as ``fn(theta, c, r2, u, beta, g, *[v**k for (v, k) in powers])`` gives the same bits
    as :func:`_indicator_all` (the table path computes the powers once per depth)."""
    from .forms_generated import SOURCES

    form, orders = with_term_sizes(indicator(parity), 4), (0, 1, 2, 3, 4, 5, 6)
    text = SOURCES.get(generated_key(form.key, "numpy", orders))
    if text is None:  # pragma: no cover - the stored texts cover this form
        text = form.real.source("numpy", orders)
    text, powers = hoist_powers(text, ("beta", "g"))
    return load_source(text, "numpy", orders), powers


#: the maximiser of ``D`` is taken once its Halley step (on ``D'``) is below this (absolute, in
#: ``theta``); its value ``D(top)`` is then the Taylor polynomial of degree 3 of ``D`` at the last
#: iterate, which leaves an error of about ``D'''' step^4/24 <= 1e-21 D''''`` (far below the
#: rounding of ``D``) and a maximiser off by about ``step^3``, whose ``D`` is below the maximum by
#: some ``D'' 1e-30``
_TOP_STEP = 1e-5

#: an edge is taken once Halley's estimate of its error, ``K step^3`` with ``K = |D'''|/(6 |D'|)
#: + (D''/(2 D'))^2``, is below this times ``max(c + theta, 1)`` (and its step below
#: :data:`_EDGE_STEP`, where that estimate holds)
_EDGE_RTOL = 2e-16
_EDGE_STEP = 1e-4


def _damped_normal(n, P, edges=None, *, split=False, pair=True):
    """:func:`damped_normal` with the grid's error estimates: also ``undecided`` (the sign of
    ``D`` at the maximiser is within the rounding bound of ``D``) and ``lo_doubt``, ``hi_doubt``
    (the edge's estimated relative error -- the rounding bound of ``D`` over its slope at the
    edge, as :func:`_root_doubt` -- exceeds :data:`DOUBT`).

    Every evaluation gives ``D``, its first three derivatives and the rounding bound from one
    set of transcendental calls (:func:`_indicator_all`).  The maximiser: Halley steps on ``D'``
    from the root of the cubic that interpolates ``D'`` and ``D''`` at the ends of the undamped
    bracket (``D'`` decreasing through it), safeguarded by bisection (:func:`_maximiser`).  The
    edges: Halley steps on ``D`` from the undamped roots (the first from the values there,
    computed already), each in the bracket between its undamped root and the maximiser, stopped
    by Halley's error estimate (:func:`_edges`).  Each iteration runs only on the points still
    moving.

    ``split=True`` (the grid): ``top`` is only a point where ``D`` exceeds twice its rounding
    bound where the interval exists (it splits the edges' brackets and proves the existence),
    the maximiser itself only where no such point has been met; ``dtop`` is ``D`` there."""
    n = np.asarray(n)
    parity = int(_parity(int(n.flat[0])))
    ev = _indicator_all(parity)
    t1, t2 = normal_edges(n, P) if edges is None else edges
    a, b = np.minimum(t1, t2), np.maximum(t1, t2)
    c = n * _HALF_PI
    params = (c, P.r2, P.u, P.beta, P.g)
    shape = np.broadcast(a, b, *params).shape
    a, b = _full(a, shape).ravel(), _full(b, shape).ravel()
    args = tuple(_full(v, shape).ravel() for v in params)
    cc = args[0]
    far = _full(np.asarray(P.bm) >= NEAR_ONE, shape).ravel() if split else None
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        # both ends in one call (with the sizes, for a maximiser at an end)
        k = a.size
        both = ev(np.concatenate([a, b]), *(np.concatenate([v, v]) for v in args))
        at_a, at_b = tuple(v[:k] for v in both), tuple(v[k:] for v in both)
        d1a, d1b = at_a[1], at_b[1]
        left = d1a <= 0
        top = np.where(left, a, b)
        dtop = np.where(left, at_a[0], at_b[0])
        tot = np.where(left, at_a[5], at_b[5])
        tsl = np.where(left, at_a[6], at_b[6])
        within = (d1a > 0) & (d1b < 0)
        inside = np.nonzero(within)[0]
        lo = np.full(a.size, np.nan)
        hi = np.full(a.size, np.nan)
        lo_doubt = np.zeros(a.size, bool)
        hi_doubt = np.zeros(a.size, bool)
        solved = np.zeros(a.size, bool)
        x0 = guess = None
        if inside.size:
            ends = (a[inside], b[inside], d1a[inside], d1b[inside])
            x0, guess = _hermite_root(*ends, at_a[2][inside], at_b[2][inside], at_a[0][inside])
        if inside.size and split and pair:
            # where the cubic predicts D > 0 at its maximiser, the edges at once, in the
            # brackets split there; kept where both converge to simple zeros with the slopes of
            # the edges (D increasing through the lower, decreasing through the upper) on either
            # side of the split -- D is then positive between them (one zero each side of the
            # maximiser), and the interval exists; an edge whose error is not bounded is
            # escalated as on the other path
            # (not next to m = 1, where the standard form loses the digits that decide it)
            guess = np.where(far[inside], guess, -1.0)
            sel = inside[guess > 0]
            if sel.size:
                split_at = x0[guess > 0]
                got = _edge_pair(ev, args, a, b, split_at, at_a, at_b, sel, iterations=8)
                ok = got[4] & (got[0] < split_at) & (split_at < got[1])
                ok &= got[1] - got[0] > 1e-8 * np.maximum(np.abs(cc[sel] + got[1]), 1.0)
                sel = sel[ok]
                lo[sel], hi[sel] = got[0][ok], got[1][ok]
                lo_doubt[sel], hi_doubt[sel] = got[2][ok], got[3][ok]
                top[sel] = split_at[ok]
                dtop[sel] = np.inf  # (D > 0 between the edges: not its maximum)
                solved[sel] = True
                keep = ~solved[inside]
                inside, x0 = inside[keep], x0[keep]
        if inside.size:
            sub = tuple(v[inside] for v in args)
            ends = (a[inside], b[inside], d1a[inside], d1b[inside])
            got = _maximiser(ev, sub, *ends, x0, split=split)
            top[inside], dtop[inside], tot[inside], tsl[inside] = got
        noise = NOISE_ULPS * 2.0**-53 * (np.abs(tot) + np.abs(cc + top) * np.abs(tsl))
        undecided = np.abs(dtop) <= noise
        sel = np.nonzero((dtop > 0) & ~solved)[0]
        if sel.size:
            got = _edge_pair(ev, args, a, b, top[sel], at_a, at_b, sel)
            lo[sel], hi[sel], lo_doubt[sel], hi_doubt[sel] = got[:4]
    out = {"a": a, "b": b, "top": top, "dtop": dtop, "lo": lo, "hi": hi}
    out.update(undecided=undecided, lo_doubt=lo_doubt, hi_doubt=hi_doubt)
    return {key: v.reshape(shape) for key, v in out.items()}


def _hermite_root(a, b, ya, yb, sa, sb, da=None):
    """A start for the zero of ``D'`` in ``[a, b]``: the zero of the cubic with the values ``ya >
    0 > yb`` and slopes ``sa``, ``sb`` of ``D'`` at the ends (four Newton steps from the secant
    root, kept in the bracket; the secant root where they fail).  With ``da = D(a)`` also the
    value of ``D`` there that the cubic predicts (``D(a)`` plus its integral from ``a``): a guess,
    which the caller checks."""
    h = b - a
    p0, p1, m0, m1 = ya, yb, sa * h, sb * h
    # the cubic in t = (x - a)/h: p0 + m0 t + c2 t^2 + c3 t^3
    c2 = 3 * (p1 - p0) - 2 * m0 - m1
    c3 = 2 * (p0 - p1) + m0 + m1
    t0 = ya / (ya - yb)
    t = t0
    for _ in range(4):
        f = p0 + t * (m0 + t * (c2 + t * c3))
        df = m0 + t * (2 * c2 + 3 * t * c3)
        t = np.minimum(np.maximum(t - f / df, 0.0), 1.0)
    t = np.where(np.isfinite(t) & (t > 0) & (t < 1), t, t0)
    if da is None:
        return a + t * h
    return a + t * h, da + h * t * (p0 + t * (m0 / 2 + t * (c2 / 3 + t * c3 / 4)))


def _maximiser(ev, args, a, b, d1a, d1b, x0, *, split=False, iterations: int = 100):
    """The maximiser of ``D`` in ``[a, b]`` where ``D'(a) > 0 > D'(b)``, from ``x0``: ``(top,
    D(top), sum |t_i|, sum |dt_i/dtheta|)`` (the sizes at the last iterate).
    Halley steps on ``D'``, a step out of the bracket replaced by bisection, each point dropped
    once its step is below :data:`_TOP_STEP` (which says why that is enough).  ``split=True``: a
    point is also dropped once ``D`` exceeds twice its rounding bound there (that point is
    returned).
    ``split=False`` (the float stage of the proofs, :mod:`verify.existence`, which start from the
    maximiser itself): each point is iterated until its step is below ``1e-12`` of ``max(c +
    (a + b)/2, 1)``, and ``D`` and the sizes are evaluated at the maximiser found."""
    x = np.where((x0 > a) & (x0 < b), x0, 0.5 * (a + b))
    tl = _TOP_STEP if split else 0.5e-12 * np.maximum(args[0] + 0.5 * (a + b), 1.0)
    lo, hi = a.copy(), b.copy()
    top, dtop = x.copy(), np.full(x.size, -np.inf)
    tot, tsl = np.zeros(x.size), np.zeros(x.size)
    idx = np.arange(x.size)
    sub = args
    for it in range(iterations):
        D, D1, D2, D3, _D4, T0, T1 = ev(x, *sub)
        lo = np.where(D1 > 0, x, lo)
        hi = np.where(D1 < 0, x, hi)
        s = D1 / D2
        s = s / (1.0 - 0.5 * s * D3 / D2)  # (0 where D' = 0, NaN -> bisection where D'' = 0)
        xn = x - s
        done = np.abs(s) <= tl
        if it >= 2:  # (a bracket this narrow takes more than two steps)
            narrow = hi - lo <= 1e-12 * np.maximum(np.abs(x), 1.0)
            if narrow.any():  # bisection has closed in on it: the step to the midpoint
                s = np.where(narrow & ~done, x - 0.5 * (lo + hi), s)
                done |= narrow & (np.abs(s) <= tl)
        if split:
            noise = NOISE_ULPS * 2.0**-53 * (np.abs(T0) + np.abs(sub[0] + x) * np.abs(T1))
            high = (D > 2 * noise) & ~done
            if high.any():
                s = np.where(high, 0.0, s)
                done |= high
        last = it == iterations - 1
        if done.any() or last:
            j = np.nonzero(done)[0] if not last else np.arange(x.size)
            sj = s[j]
            top[idx[j]] = x[j] - sj
            dtop[idx[j]] = D[j] - sj * (D1[j] - sj * (0.5 * D2[j] - sj * D3[j] / 6.0))
            tot[idx[j]], tsl[idx[j]] = T0[j], T1[j]
        if done.all() or last:
            break
        xn = np.where((xn > lo) & (xn < hi), xn, 0.5 * (lo + hi))
        keep = ~done
        idx, x, lo, hi = idx[keep], xn[keep], lo[keep], hi[keep]
        if not split:
            tl = tl[keep]
        sub = tuple(v[keep] for v in sub)
    if not split:
        D, _D1, _D2, _D3, _D4, tot, tsl = ev(top, *args)
        dtop = np.asarray(D, float)
    return top, dtop, tot, tsl


def _edge_pair(ev, args, a, b, top, at_a, at_b, sel, iterations: int = 100):
    """Both edges of the points ``sel`` in one iteration (:func:`_edges`): the lower in ``[a,
    top]`` from ``a``, the upper in ``[top, b]`` from ``b``, the first step of each from the
    values ``at_a``, ``at_b`` there (no new evaluation): ``(lower, upper, lower doubt, upper
    doubt, good)``, ``good``: both converged to zeros with the edges' slopes."""
    k = sel.size
    sub = tuple(np.concatenate([v[sel], v[sel]]) for v in args)
    aa, bb = a[sel], b[sel]
    x1 = np.concatenate(
        [e[sel] - _step(*(v[sel] for v in at[:4]))[0] for e, at in ((a, at_a), (b, at_b))]
    )
    brl, brh = np.concatenate([aa, top]), np.concatenate([top, bb])
    x1 = np.where((x1 > brl) & (x1 < brh), x1, 0.5 * (brl + brh))
    sign = np.concatenate([np.ones(k), -np.ones(k)])
    scale = np.maximum(sub[0] + np.concatenate([aa, bb]), 1.0)
    root, unsure, good = _edges(ev, sub, brl, brh, x1, sign, scale, iterations=iterations)
    return root[:k], root[k:], unsure[:k], unsure[k:], good[:k] & good[k:]


def _step(D, D1, D2, D3, D4=None):
    """Householder's step of order 3 for a zero of ``D`` (convergence of order 4; the third
    derivative comes with every evaluation anyway) and an estimate of the error it leaves:
    ``(step, err)``.  With ``D4`` (the fourth derivative): ``K step^4``, ``K = |c2|^3 + 2 |c2 c3|
    + |c4|``, ``c_k = D^(k)/(k! D')`` (the error after the step is ``(c2^3 - 2 c2 c3 + c4) e^4``
    to leading order, ``e`` the error before it, which the step equals to a relative ``O(e^3)``);
    without it, Halley's ``K step^3`` with ``K = |c3| + c2^2`` (what a step of order 2 would
    leave; an upper estimate)."""
    h = 0.5 * D2 / D1
    q = D / D1
    c3 = D3 / (6.0 * D1)
    s = q * (1.0 - q * h) / (1.0 - q * (2.0 * h - q * c3))  # (NaN where D' = 0)
    a = np.abs(s)
    if D4 is None:
        return s, (np.abs(c3) + h * h) * (a * a * a)
    ah = np.abs(h)
    a2 = a * a
    return s, (ah * (ah * ah + 2.0 * np.abs(c3)) + np.abs(D4 / (24.0 * D1))) * (a2 * a2)


def _edges(ev, args, lo, hi, x, sign, scale, *, iterations: int = 100):
    """The zeros of ``D`` in ``[lo, hi]`` (``sign D`` negative at ``lo``, positive at ``hi``),
    from ``x``: ``(roots, doubt)``.  Steps of :func:`_step`, a step out of the bracket replaced by
    bisection; a point stops once the error estimate is below :data:`_EDGE_RTOL` times ``scale``
    (and its step below :data:`_EDGE_STEP`), or its bracket is that narrow.  ``doubt``: the
    rounding bound of ``D`` over its slope at the root exceeds :data:`DOUBT` relative to ``c +
    root`` (as :func:`_root_doubt`; the slope at the last iterate corrected by ``D''`` times the
    step).  Also ``good``: the point stopped by the error estimate (not by the bracket or the
    count), at a zero where ``sign D`` increases."""
    root = x.copy()
    doubt = np.zeros(x.size, bool)
    good = np.zeros(x.size, bool)
    idx = np.arange(x.size)
    sub, sg, sc = args, sign, scale
    for it in range(iterations):
        D, D1, D2, D3, D4, T0, T1 = ev(x, *sub)
        f = sg * D
        lo = np.where(f < 0, x, lo)
        hi = np.where(f > 0, x, hi)
        s, err = _step(D, D1, D2, D3, D4)
        done = (err <= _EDGE_RTOL * sc) & (np.abs(s) <= _EDGE_STEP)
        converged = done.copy()
        if it >= 2:  # (a bracket this narrow takes more than two steps)
            narrow = (hi - lo <= 2 * _EDGE_RTOL * sc) & ~done
            if narrow.any():  # bisection has closed in on it: the step to the midpoint
                s = np.where(narrow, x - 0.5 * (lo + hi), s)
                done |= narrow
        last = it == iterations - 1
        if done.any() or last:
            j = np.nonzero(done)[0] if not last else np.arange(x.size)
            sj = s[j]
            r = x[j] - sj
            slope = np.abs(D1[j] - D2[j] * sj)
            at = np.abs(sub[0][j] + r)
            noise = NOISE_ULPS * 2.0**-53 * (np.abs(T0[j]) + at * np.abs(T1[j]))
            root[idx[j]] = r
            doubt[idx[j]] = ~(noise / (slope * at) <= DOUBT)
            good[idx[j]] = converged[j] & (sg[j] * (D1[j] - D2[j] * sj) > 0)
        if done.all() or last:
            break
        xn = x - s
        xn = np.where((xn > lo) & (xn < hi), xn, 0.5 * (lo + hi))
        keep = ~done
        idx, x, lo, hi, sg, sc = idx[keep], xn[keep], lo[keep], hi[keep], sg[keep], sc[keep]
        sub = tuple(v[keep] for v in sub)
    return root, doubt, good


# ---------------------------------------------------------------------------------------------
# the grid with friction: start tables of the edges themselves

#: the fast path with friction takes at most this many steps per edge or maximiser (a point that
#: has not converged by then goes to the bracketed path; from the tables, one step converges
#: nearly everywhere)
_TABLE_STEPS = 1


def _edge_tables(system, orders, friction) -> list:
    """For each order ``n`` of ``orders``: the friction edges and the maximiser of ``D`` at the
    depths of :func:`_start_tables` (``m = 1 - rho^2``), rows ``(lower, upper, top)`` (``theta``),
    shape ``(3, K)``, read-only: ``lower``, ``upper`` NaN where the interval does not exist,
    ``top`` the maximiser of ``D`` (NaN where it is one of the ends of the undamped interval,
    and at every node where the normal form does not apply; next to a threshold the nodes where
    the interval exists give the maximiser a start where the edges have none).  Starting values
    only (:func:`_table_friction` proves every point it takes from them and hands the rest to the
    bracketed path), computed once per ``(system, n, Q, damping)`` by :func:`_damped_normal` at
    the nodes: they cannot change a result."""
    key = lambda n: (system, n, friction, "edges")  # noqa: E731
    found = {n: _TABLES.get(key(n)) for n in set(orders)}
    missing = sorted(n for n, tab in found.items() if tab is None)
    if missing:
        rho = (np.arange(START_NODES) + 0.5) / START_NODES
        om = rho * rho
        with np.errstate(all="ignore"):
            P = normal_params(1 - om, friction[0], friction[1], _NP, system, om=om)
            P = NormalParams(
                *(np.asarray(getattr(P, f.name), float) * np.ones(om.shape) for f in fields(P))
            )
        ok = np.isfinite(P.r) & np.isfinite(P.beta) & (P.r >= 0) & (P.beta > 0)
        ok &= np.isfinite(P.g) & np.isfinite(P.u)
        sub = NormalParams(*(getattr(P, f.name)[ok] for f in fields(P)))
        tabs = {n: np.full((3, START_NODES), np.nan) for n in missing}
        for parity in (1, 0):
            ns = [n for n in missing if n % 2 == parity]
            if not ns or not ok.any():
                continue
            res = _damped_normal(np.array(ns)[:, None], sub, split=False)
            for k, n in enumerate(ns):
                lo, hi, top = res["lo"][k], res["hi"][k], res["top"][k]
                both = np.isfinite(lo) & np.isfinite(hi)
                # (a maximiser at an end of the undamped interval: none inside, no start)
                inner = (top > res["a"][k]) & (top < res["b"][k])
                tabs[n][0, ok] = np.where(both, lo, np.nan)
                tabs[n][1, ok] = np.where(both, hi, np.nan)
                tabs[n][2, ok] = np.where(inner, top, np.nan)
        if len(_TABLES) + len(missing) > _TABLES_MAX:
            _TABLES.clear()
        for n in missing:
            tab = tabs[n]
            tab.flags.writeable = False
            found[n] = _TABLES[key(n)] = tab
    return [found[n] for n in orders]


#: the table path of the grid with friction takes the depths with ``1 - beta`` from here up
#: (below it the standard form loses more than six digits to ``1 - beta``)
TABLE_NEAR_MIN = 1e-6
#: next to ``m = 1`` (``1 - beta <`` :data:`NEAR_ONE`) the table path takes an interval only where
#: its edges lie this far apart (relative): the standard form there loses ``log10(1/(1 - beta))``
#: digits, and ``D`` between such edges is far above that loss, so the interval exists
_NEAR_GAP = 1e-3


def _table_friction(orders, P, rho, system, friction, cols) -> dict:
    """The grid with friction from the start tables of its edges (:func:`_edge_tables`), for the
    depths ``cols`` (each with ``1 - beta >=`` :data:`NEAR_ONE`): arrays ``(len(orders), N)`` as
    :func:`_damped_normal` gives them (``lo``, ``hi``, ``top``, ``dtop``, ``undecided``,
    ``lo_doubt``, ``hi_doubt``) and ``done``, the entries taken here; the others go to the
    bracketed path.

    Where the four nodes nearest a depth all have the interval: steps of :func:`_step` on ``D``
    from the cubic through the nodes' edges, an entry taken where both edges converge (the
    estimate of order 4) to zeros inside the window ``|theta| < pi/2`` with ``D`` increasing
    through the lower and decreasing through the upper, the lower below the upper.  Inside the
    window ``D <= D0 < 0`` outside the undamped roots, so these are zeros of ``D`` between them,
    and with one zero of ``D`` each side of its maximiser there (the structure the bracketed path
    relies on) they are the edges and the interval exists.  Where the four nodes all lack it:
    Halley steps on ``D'`` from the cubic through the nodes' maximisers, an entry taken (no
    interval) where they converge (step below :data:`_TOP_STEP`) to a maximum ``D'' < 0`` with
    ``D`` below minus its rounding bound there and the undamped indicator ``D0`` (``D`` with
    ``u = g = 0``) above ``1e-12`` (so the point lies between the undamped roots, where ``D`` has
    its one maximum): ``D < 0`` on the whole window.

    Both parities in one pass (:class:`_FrictionPlan`): the rows of the odd orders first, every
    set of points in that order, and each evaluation calls the form of each parity on its part
    (:class:`_ByParity`); the first step of the edges and of the maximisers from one evaluation
    (the maximisers one slice of it); the results gathered in that order of the rows with masks,
    and put in the caller's order once at the end."""
    no, N = len(orders), rho.size
    keys = ("lo", "hi", "top", "dtop", "undecided", "lo_doubt", "hi_doubt", "done")
    nc = cols.size
    full = nc == N  # (then cols is every column, in order)

    def blank(key):
        return np.full((no, N), np.nan) if key in keys[:4] else np.zeros((no, N), bool)

    if nc == 0:
        return {key: blank(key) for key in keys}
    plan = _friction_plan(system, orders, friction)
    R1, crow, oddrow = plan.n_odd, plan.c, plan.odd
    start = np.empty((nc, 3 * no))
    _start_values(plan.table, rho if full else rho[cols], start, np.empty_like(start), axis=0)
    st = np.ascontiguousarray(start.T).reshape(no, 3, nc)  # rows in the plan's order
    lo0, hi0, top0 = st[:, 0], st[:, 1], st[:, 2]
    if full:
        params = (P.r2, P.u, P.beta, P.g)
        near = np.asarray(P.bm) < NEAR_ONE
    else:
        params = (P.r2[cols], P.u[cols], P.beta[cols], P.g[cols])
        near = np.asarray(P.bm)[cols] < NEAR_ONE
    ev, powers = _indicator_both()
    named = dict(zip(("r2", "u", "beta", "g"), params, strict=True))
    pars = np.array(params + tuple(named[v] ** k for v, k in powers))  # (once per depth)
    nrows = len(pars) + 2  # the arguments of ev: c, the parameters and powers, the parity mask

    def gather(rc, at):
        """The arguments of ev (one row each) at the entries ``(rc, at)`` (plan's rows)."""
        args = np.empty((nrows, at.size))
        args[0] = crow[rc]
        np.take(pars, at, axis=1, out=args[1:-1], mode="clip")
        args[-1] = oddrow[rc]
        return args

    # results in the plan's order of the rows
    # (each kind of result one array, put in the caller's order of the rows at once)
    floats, flags = np.full((4, no, nc), np.nan), np.zeros((3, no, nc), bool)
    LO, HI, TOP, DTOP = floats
    LOD, HID, DONE = flags
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        pair = np.isfinite(lo0) & np.isfinite(hi0) & (lo0 < hi0)
        tmask = np.isfinite(top0) & ~pair & ~near
        pr, pc = np.nonzero(pair)  # (row-major: the odd orders' entries first)
        tr, tc = np.nonzero(tmask)
        k, kt = pr.size, tr.size
        k1 = int(np.searchsorted(pr, R1))
        k0 = k - k1
        E = 2 * k1 + kt  # where the edges of the even orders start
        tsl = slice(2 * k1, E)  # the maximisers
        moving = None
        high = np.zeros(0, bool)
        if k + kt:
            # one evaluation for the first step of both edges where the four nodes have the
            # interval and of the maximiser where they all lack it: the points [lower, upper,
            # maximiser] of the odd orders, then [maximiser, lower, upper] of the even (each
            # parity one slice of the call, the maximisers one slice of the result: no copies)
            lo_p, hi_p, top_t = lo0[pair], hi0[pair], top0[tmask]
            cat = np.concatenate
            x_all = cat([lo_p[:k1], hi_p[:k1], top_t, lo_p[k1:], hi_p[k1:]])
            args_all = gather(
                cat([pr[:k1], pr[:k1], tr, pr[k1:], pr[k1:]]),
                cat([pc[:k1], pc[:k1], tc, pc[k1:], pc[k1:]]),
            )
            first = ev(x_all, *args_all)
        if k:
            # the edges (sign 0: the maximisers' points, not taken)
            sign = np.ones(x_all.size)
            sign[k1 : 2 * k1] = -1.0
            sign[tsl] = 0.0
            sign[E + k0 :] = -1.0
            root, doubt, good, (moving, xm) = _table_edges(
                ev, args_all, x_all, sign, first=first, left=True
            )
        if kt:
            tsub = args_all[:, tsl]
            top, dtop, ok, high, (curv, third) = _table_top(
                ev, tsub, x_all[tsl], first=tuple(f[tsl] for f in first)
            )
            TOP[tmask] = np.where(ok, top, np.nan)
            DTOP[tmask] = np.where(ok, dtop, np.nan)
            DONE[tmask] = ok
        if high.any() or (moving is not None and moving.size):
            # an interval whose edges the tables did not give (split at the maximiser), and the
            # edges that one step did not converge: more steps, in the same calls
            hsub = tsub[:, high] if kt else args_all[:, :0]
            hx = (top[high], dtop[high], curv[high]) if kt else (np.zeros(0),) * 3
            h3 = third[high] if kt else None
            extra = None if moving is None else (args_all[:, moving], xm, sign[moving])
            lo, hi, lo_d, hi_d, ok, more = _table_split(ev, hsub, *hx, extra=extra, third=h3)
            if moving is not None:
                root[moving], doubt[moving], good[moving] = more
            if ok.any():
                at = np.flatnonzero(tmask)[high][ok]
                LO.flat[at], HI.flat[at] = lo[ok], hi[ok]
                LOD.flat[at], HID.flat[at] = lo_d[ok], hi_d[ok]
                TOP.flat[at] = hx[0][ok]
                DTOP.flat[at] = np.inf
                DONE.flat[at] = True
        if k:
            # the edges in the entries' order (that of the mask): [odd orders, even orders]
            lp = np.concatenate([np.arange(k1), np.arange(E, E + k0)])
            hp = np.concatenate([np.arange(k1, 2 * k1), np.arange(E + k0, E + 2 * k0)])
            lo, hi = root[lp], root[hp]
            ok = good[lp] & good[hp] & (lo < hi)
            gap = np.maximum(np.abs(crow[pr] + hi), 1.0)
            ok &= hi - lo > np.where(near[pc], _NEAR_GAP, 1e-8) * gap
            LO[pair], HI[pair] = np.where(ok, lo, np.nan), np.where(ok, hi, np.nan)
            LOD[pair], HID[pair] = doubt[lp] & ok, doubt[hp] & ok
            TOP[pair] = np.where(ok, 0.5 * (lo + hi), np.nan)  # (D > 0 between the edges)
            DTOP[pair] = np.where(ok, np.inf, np.nan)
            DONE[pair] = ok
        # the entries left (mostly a maximiser at an end of the undamped interval, at small
        # depths): no interval wherever the bound of :func:`_no_interval` proves it
        ri, ci = np.nonzero(~DONE & ~near)
        if ri.size:
            ok = _no_interval(oddrow[ri], crow[ri], *np.take(pars[:4], ci, axis=1))
            DONE[ri[ok], ci[ok]] = True
    inv = plan.inverse
    floats, flags = floats[:, inv], flags[:, inv]
    got = dict(zip(("lo", "hi", "top", "dtop"), floats, strict=True))
    got.update(zip(("lo_doubt", "hi_doubt", "done"), flags, strict=True))
    out = {}
    for key in keys:
        if full and key in got:
            out[key] = got[key]
            continue
        out[key] = blank(key)
        if key in got:
            out[key][:, cols] = got[key]
    return out


#: the plans of :func:`_table_friction`, ``(system, orders, friction) -> _FrictionPlan``
#: (cleared when it holds :data:`_TABLES_MAX`)
_FRICTION_PLANS: dict = {}


class _FrictionPlan:
    """What :func:`_table_friction` needs of ``orders`` besides the depths: the order of its rows
    (``rows``, the odd orders first, each parity in the caller's order; ``inverse`` puts them
    back), ``c = n pi/2`` and the parity of each row in that order, the number of odd rows, and
    the start tables (:func:`_edge_tables`) of every row in that order stacked node by node,
    ``(K, 3 len(orders))`` (columns: lower edge, upper edge, maximiser of each row), so that
    one gather per node of the cubic fetches every row (:func:`_start_values` with ``axis=0``)."""

    __slots__ = ("rows", "inverse", "c", "odd", "n_odd", "table")

    def __init__(self, system, orders, friction):
        orders = np.asarray(orders)
        self.rows = np.argsort(orders % 2 == 0, kind="stable")
        self.inverse = np.argsort(self.rows)
        self.c = orders[self.rows] * _HALF_PI
        self.odd = orders[self.rows] % 2 == 1
        self.n_odd = int(np.count_nonzero(self.odd))
        tables = _edge_tables(system, orders.tolist(), friction)
        table = np.concatenate([tables[i] for i in self.rows]).T.copy()
        table.flags.writeable = False
        self.table = table


def _friction_plan(system, orders, friction) -> _FrictionPlan:
    key = (system, tuple(int(n) for n in orders), friction)
    plan = _FRICTION_PLANS.get(key)
    if plan is None:
        if len(_FRICTION_PLANS) >= _TABLES_MAX:
            _FRICTION_PLANS.clear()
        plan = _FRICTION_PLANS[key] = _FrictionPlan(system, orders, friction)
    return plan


def _parity_call(fn_odd, fn_even, odd, x, args):
    """``fn_odd(x, *args)`` at the points where ``odd`` and ``fn_even(x, *args)`` at the others
    (arrays of one length), as one result (a tuple of arrays where the functions give tuples):
    on two slices where the odd points come first (the order the table path keeps), else on
    the gathered points."""
    k = int(np.count_nonzero(odd))
    if k == odd.size:
        return fn_odd(x, *args)
    if k == 0:
        return fn_even(x, *args)
    if not odd[k:].any():
        a = fn_odd(x[:k], *(v[:k] for v in args))
        b = fn_even(x[k:], *(v[k:] for v in args))
        if isinstance(a, tuple):
            return tuple(np.concatenate((p, q)) for p, q in zip(a, b, strict=True))
        return np.concatenate((a, b))
    even = ~odd
    a = fn_odd(x[odd], *(v[odd] for v in args))
    b = fn_even(x[even], *(v[even] for v in args))

    def put(p, q):
        r = np.empty(x.shape, np.result_type(p, q))
        r[odd], r[even] = p, q
        return r

    if isinstance(a, tuple):
        return tuple(put(p, q) for p, q in zip(a, b, strict=True))
    return put(a, b)


class _ByParity:
    """A compiled form of each parity as one callable: ``f(x, *args, odd)`` evaluates the form of
    the odd orders where the bool array ``odd`` is true and that of the even orders elsewhere
    (:func:`_parity_call`).  The mask rides last among the arguments, so that the iterations
    that carry their arguments along (compacting every one with the same mask) carry it too."""

    __slots__ = ("odd_fn", "even_fn")

    def __init__(self, odd_fn, even_fn):
        self.odd_fn, self.even_fn = odd_fn, even_fn

    def __call__(self, x, *args):
        odd = args[-1]  # (a row of a 2-D array of arguments holds it as 0.0 and 1.0)
        return _parity_call(
            self.odd_fn, self.even_fn, odd if odd.dtype == bool else odd != 0, x, args[:-1]
        )


@cache
def _indicator_both():
    """:func:`_indicator_powers` of both parities as one :class:`_ByParity` (called as ``fn(theta,
    c, r2, u, beta, g, *powers, odd)``) and the powers, which the two stored forms share."""
    odd_fn, p_odd = _indicator_powers(int(_parity(1)))
    even_fn, p_even = _indicator_powers(int(_parity(2)))
    if p_odd != p_even:  # pragma: no cover - the stored forms hoist the same powers
        raise RuntimeError(f"the indicators hoist different powers: {p_odd} and {p_even}")
    return _ByParity(odd_fn, even_fn), p_odd


@cache
def _plain_both():
    """The indicator ``D`` of both parities, value only, as one :class:`_ByParity`."""
    return _ByParity(
        indicator(int(_parity(1))).compiled("numpy", 0),
        indicator(int(_parity(2))).compiled("numpy", 0),
    )


#: :func:`_no_interval` bounds ``D`` on this many pieces of the range where it can be positive,
#: where one piece is not enough (next to a threshold)
_NO_INTERVAL_PIECES = 32


def _no_interval(parity, c, r2, u, beta, g):
    """Where ``D < 0`` on the whole window, proved by a bound (no interval there; the entry's
    edges NaN, its maximum not needed).  The normal form is ``D = r2 f(beta x)^2 - u sinh(g
    x)^2 - sin(theta)^2``, ``x = c + theta``, ``f`` a sine or cosine
    (:class:`verify.params.NormalParams`).  Where ``D >= 0``, ``sin(theta)^2 <= r2 f(beta x)^2``,
    so ``|theta| <= s_0 = asin(sqrt(r2))`` in the window.  On ``[-s, s]``, ``x >= c - s`` and ``D
    <= P - u sinh(g (c - s))^2`` (``sinh^2`` grows with ``x > 0``), ``P`` the largest ``r2 f(beta
    x)^2`` there (:func:`_f2_peak`): an entry is taken where that is negative with a margin (the
    sinh term above ``2 P``, far above the rounding of either side).  Elsewhere ``|theta| <= s_1
    = asin(sqrt(P))`` where ``D >= 0``, and ``[-s_1, s_1]`` is cut into
    :data:`_NO_INTERVAL_PIECES` pieces, on each of which ``D`` is at most ``P_i - u sinh(g
    x_i)^2 - sin(t_i)^2`` (``P_i`` as ``P``, ``x_i`` the piece's left end, ``t_i`` its ``theta``
    nearest 0): an entry is taken where every piece's bound is below minus ``1e-10`` times the
    sizes of its terms.  The terms are the indicator's own (the compiled form at ``theta = 0``
    with ``u = 0`` or ``r2 = 0``, and with ``r2 = u = 0`` for ``sin^2``); ``s_0``, ``s_1`` are
    rounded up (by more than the rounding of ``c -+ s``).  ``parity``: that of every entry (an
    int, as :func:`verify.derived.indicator` takes it), or a bool array, true for the entries of
    odd orders."""
    if np.ndim(parity) == 0:
        form, odd = indicator(parity).compiled("numpy", 0), None
    else:
        form, odd = _plain_both(), np.asarray(parity, bool)
    with np.errstate(invalid="ignore", over="ignore", divide="ignore"):
        pad = 1e-15 * c
        s = np.arcsin(np.sqrt(np.clip(r2, 0.0, 1.0))) * (1.0 + 1e-12) + pad
        peak, damp = _f2_peak(form, c - s, c + s, r2, u, beta, g, odd=odd)
        taken = (c - s > 0) & (r2 >= 0) & (2.0 * peak < damp)
        rest = np.nonzero(~taken & (peak < r2) & (r2 >= 0))[0]
        if rest.size == 0:
            return taken
        N = _NO_INTERVAL_PIECES
        k = rest.size
        cc, rr, uu, bb, gg = (v[rest] for v in (c, r2, u, beta, g))
        s = np.arcsin(np.sqrt(np.clip(peak[rest], 0.0, 1.0))) * (1.0 + 1e-12) + pad[rest]
        e = s[:, None] * (np.arange(N + 1) * (2.0 / N) - 1.0)  # the pieces' ends in theta
        e[:, 0], e[:, N] = -s, s
        X = cc[:, None] + e  # ... in x (each end shared by its two pieces)
        rep = tuple(np.repeat(v, N) for v in (rr, uu, bb, gg))
        a, b = e[:, :-1].ravel(), e[:, 1:].ravel()
        near = np.where(a * b <= 0, 0.0, np.minimum(np.abs(a), np.abs(b)))
        ends = (X[:, :-1].ravel(), X[:, 1:].ravel())
        oddN = None if odd is None else np.repeat(odd[rest], N)
        P, S, sin2 = _f2_peak(form, *ends, *rep, theta=near, odd=oddN)
        bound = P - S - sin2
        ok = (X[:, :-1].ravel() > 0) & (bound < -1e-10 * (P + S + sin2 + rep[0]))
        taken[rest] = ok.reshape(k, N).all(axis=1)
    return taken


def _f2_peak(form, x1, x2, r2, u, beta, g, *, theta=None, odd=None):
    """``(P, S)``: an upper bound ``P`` of ``r2 f(beta x)^2`` on ``[x1, x2]`` and ``S = u sinh(g
    x1)^2`` (:func:`_no_interval`; ``form`` the compiled indicator, ``r2 f(beta x)^2 - u sinh(g
    x)^2`` at ``theta = 0``, taken with ``u = 0`` or ``r2 = 0``): ``f^2`` is monotone between the
    multiples of ``pi/2`` of ``beta x``, so its largest value is at an end or at the one multiple
    inside (``r2`` where there are more); the multiples are counted on the range widened by a
    relative 1e-12 and the bound raised by what ``f^2`` can change over that.  ``theta``: also
    ``sin(theta)^2`` there (the form with ``r2 = u = 0``), in the same call: ``(P, S, sin^2)``.
    ``odd``: ``form`` is :func:`_plain_both`, and this is its mask of the odd orders."""
    k = x1.size
    q = 2.0 / math.pi
    y1, y2 = beta * x1 * q, beta * x2 * q  # the ends in units of pi/2
    j1, j2 = np.floor(y1 * (1 - 1e-12)), np.floor(y2 * (1 + 1e-12))
    mid = j2 / (q * beta)  # the multiple of pi/2 inside (where there is one)
    blocks = 4 if theta is None else 5
    # the evaluations point by point (row j: those of point j): with the points' parities
    # sorted, each parity is one slice of the call
    th, x, rr = np.zeros((k, blocks)), np.empty((k, blocks)), np.zeros((k, blocks))
    x[:, 0], x[:, 1], x[:, 2], x[:, 3:] = x1, x2, mid, x1[:, None]  # (no stack: its overhead)
    rr[:, :3] = r2[:, None]
    uu = np.zeros((k, blocks))
    uu[:, 3] = u
    if theta is not None:
        th[:, 4] = theta
    bb, gg = np.repeat(beta, blocks), np.repeat(g, blocks)
    args = (th.ravel(), x.ravel(), rr.ravel(), uu.ravel(), bb, gg)
    got = form(*args) if odd is None else form(*args, np.repeat(odd, blocks))
    got = np.asarray(got, float).reshape(k, blocks)
    ends = np.maximum(got[:, 0], got[:, 1])
    ends = np.where(j2 == j1, ends, np.maximum(ends, got[:, 2]))
    peak = np.where((j2 - j1 <= 1) & (beta > 0), ends + 1e-9 * r2 * (1 + y2), r2)
    if theta is None:
        return peak, -got[:, 3]
    return peak, -got[:, 3], -got[:, 4]


def _table_edges(ev, args, x, sign, steps: int = _TABLE_STEPS, *, first=None, left=False):
    """Zeros of ``D`` from ``x`` near them (:func:`_table_friction`): at most ``steps`` (default
    :data:`_TABLE_STEPS`) steps of :func:`_step`, each point dropped once the estimate of order 4
    of its error is below :data:`_EDGE_RTOL` times ``max(c + theta, 1)`` (its step below
    :data:`_EDGE_STEP`): ``(roots, doubt, good)`` as :func:`_edges` (``good``: converged inside
    the window, with ``sign D`` increasing through the zero).  ``first``: the evaluation at ``x``
    (``ev(x, *args)``, done already); ``left=True``: also the indices of the points still moving
    after the last step and their next iterates.  ``args``: a 2-D array, one row per argument
    (compacted as one).  A point of ``sign`` 0 is evaluated with the others but not iterated
    (its results are not used)."""
    root = np.full(x.size, np.nan)
    doubt = np.zeros(x.size, bool)
    good = np.zeros(x.size, bool)
    idx = np.arange(x.size)
    sub, sg = args, sign
    sc = _EDGE_RTOL * np.maximum(args[0] + x, 1.0)
    for it in range(steps):
        D, D1, D2, D3, D4, T0, T1 = ev(x, *sub) if it or first is None else first
        s, err = _step(D, D1, D2, D3, D4)
        done = (err <= sc) & (np.abs(s) <= _EDGE_STEP)
        j = np.nonzero(done)[0]
        if it == 0 and 2 * j.size > x.size:  # most points at once: no gathers (the same values)
            r = x - s
            slope = D1 - D2 * s
            at = np.abs(sub[0] + r)
            noise = NOISE_ULPS * 2.0**-53 * (np.abs(T0) + at * np.abs(T1))
            root = np.where(done, r, np.nan)
            doubt = ~(noise / (np.abs(slope) * at) <= DOUBT) & done
            good = (sg * slope > 0) & (np.abs(r) < _HALF_PI) & done
        elif j.size:
            sj = s[j]
            r = x[j] - sj
            slope = D1[j] - D2[j] * sj
            at = np.abs(sub[0][j] + r)
            noise = NOISE_ULPS * 2.0**-53 * (np.abs(T0[j]) + at * np.abs(T1[j]))
            root[idx[j]] = r
            doubt[idx[j]] = ~(noise / (np.abs(slope) * at) <= DOUBT)
            good[idx[j]] = (sg[j] * slope > 0) & (np.abs(r) < _HALF_PI)
        keep = ~done & np.isfinite(s) & (sg != 0)
        if not keep.any():
            rest = (idx[:0], x[:0])
            break
        idx, x, sg, sc = idx[keep], (x - s)[keep], sg[keep], sc[keep]
        sub = sub[:, keep]
    else:
        rest = (idx, x)
    return (root, doubt, good, rest) if left else (root, doubt, good)


def _table_top(ev, args, x, *, first=None):
    """The maximiser of ``D`` from ``x`` near it (:func:`_table_friction`): at most
    :data:`_TABLE_STEPS` Halley steps on ``D'``, a point dropped once its step is below
    :data:`_TOP_STEP` (``D`` there from its Taylor polynomial, as :func:`_maximiser`):
    ``(top, D(top), ok, high, (D''(top), D'''(top)))``, ``ok`` where that is a maximum
    (``D'' < 0``) inside the window, ``D`` below minus its rounding bound and the undamped
    indicator above ``1e-12``;
    ``high`` where it is a maximum inside the window with ``D`` above its rounding bound (the
    interval exists: :func:`_table_split` finds its edges).  ``first``: the evaluation at ``x``,
    done already.  ``ev`` is :func:`_indicator_both`, ``args`` a 2-D array, one row per argument
    (the last the mask of the odd orders)."""
    x0 = x
    top = np.full(x.size, np.nan)
    dtop = np.full(x.size, np.nan)
    curv = np.full(x.size, np.nan)
    third = np.full(x.size, np.nan)
    ok = np.zeros(x.size, bool)
    high = np.zeros(x.size, bool)
    idx = np.arange(x.size)
    sub = args
    for it in range(_TABLE_STEPS):
        D, D1, D2, D3, _D4, T0, T1 = ev(x, *sub) if it or first is None else first
        s = D1 / D2
        s = s / (1.0 - 0.5 * s * D3 / D2)
        done = np.abs(s) <= _TOP_STEP
        j = np.nonzero(done)[0]
        if it == 0 and 2 * j.size > x.size:  # most points at once: no gathers (the same values)
            t = x - s
            d = D - s * (D1 - s * (0.5 * D2 - s * D3 / 6.0))
            at = np.abs(sub[0] + x)
            noise = NOISE_ULPS * 2.0**-53 * (np.abs(T0) + at * np.abs(T1))
            top, dtop = np.where(done, t, np.nan), np.where(done, d, np.nan)
            curv, third = np.where(done, D2 - s * D3, np.nan), np.where(done, D3, np.nan)
            inner = (D2 < 0) & (np.abs(t) < _HALF_PI) & done
            ok = inner & (d < -noise)
            high = inner & (d > noise)
        elif j.size:
            sj = s[j]
            t = x[j] - sj
            d = D[j] - sj * (D1[j] - sj * (0.5 * D2[j] - sj * D3[j] / 6.0))
            at = np.abs(sub[0][j] + x[j])
            noise = NOISE_ULPS * 2.0**-53 * (np.abs(T0[j]) + at * np.abs(T1[j]))
            top[idx[j]], dtop[idx[j]] = t, d
            curv[idx[j]] = D2[j] - sj * D3[j]
            third[idx[j]] = D3[j]
            inner = (D2[j] < 0) & (np.abs(t) < _HALF_PI)
            ok[idx[j]] = inner & (d < -noise)
            high[idx[j]] = inner & (d > noise)
        keep = ~done & np.isfinite(s)
        if not keep.any():
            break
        idx, x = idx[keep], (x - s)[keep]
        sub = sub[:, keep]
    sel = np.nonzero(ok)[0]
    if 2 * sel.size > x0.size:  # the undamped indicator there: D with u = g = 0 (the same
        # derived form), at every point at once where most are taken (no gathers; NaN elsewhere)
        zero = np.zeros(x0.size)
        d0 = _plain_both()(top, args[0], args[1], zero, args[3], zero, args[-1])
        ok &= np.asarray(d0, float) > 1e-12
    elif sel.size:
        c, r2, _u, beta, _g = args[:5, sel]
        zero = np.zeros(sel.size)
        d0 = _plain_both()(top[sel], c, r2, zero, beta, zero, args[-1, sel])
        ok[sel] = np.asarray(d0, float) > 1e-12
    return top, dtop, ok, high, (curv, third)


#: the steps :func:`_table_split` takes at most from its starts (next to a threshold the edges are
#: a near-double root; each step runs on the few points still moving)
_SPLIT_STEPS = 6


def _table_split(ev, args, top, dtop, curv, extra=None, third=None):
    """Both edges of the entries whose maximum of ``D`` is above its rounding bound at ``top``
    (:func:`_table_top`: the start tables had no edges at all four nodes, next to a threshold):
    from ``top -+ sqrt(2 D(top)/|D''(top)|)`` (the parabola through the maximum; with ``third``,
    ``D'''(top)``, two Newton steps on the cubic from there), at most
    :data:`_SPLIT_STEPS` steps of :func:`_step` (:func:`_table_edges`): ``(lower, upper, lower
    doubt, upper doubt, good)``, ``good`` where both converged inside the window with the edges'
    slopes on either side of ``top`` (as the pair path of :func:`_table_friction` takes them).
    ``args`` (and the ``args`` of ``extra``): 2-D, one row per argument of ``ev``.
    ``extra = (args, x, sign)``: more zeros to iterate in the same calls (the table path's edges
    that its first step did not converge), returned last as ``(roots, doubt, good)``."""
    k = top.size
    half = np.sqrt(2.0 * dtop / -curv)
    h = np.concatenate([-half, half])
    if third is not None:  # two Newton steps on the cubic through the maximum
        d, c2, c3 = (np.concatenate([v, v]) for v in (dtop, 0.5 * curv, third / 6.0))
        for _ in range(2):
            hn = h - (d + h * h * (c2 + h * c3)) / (h * (2.0 * c2 + 3.0 * h * c3))
            h = np.where(np.isfinite(hn) & (hn * h > 0), hn, h)
    x0 = [top + h[:k], top + h[k:]]
    sub = [args, args]
    sign = [np.ones(k), -np.ones(k)]
    if extra is not None:
        x0.append(extra[1])
        sub.append(extra[0])
        sign.append(extra[2])
    sub = np.concatenate(sub, axis=1)
    root, doubt, good = _table_edges(
        ev, sub, np.concatenate(x0), np.concatenate(sign), steps=_SPLIT_STEPS
    )
    lo, hi = root[:k], root[k : 2 * k]
    ok = good[:k] & good[k : 2 * k] & (lo < top) & (top < hi)
    ok &= hi - lo > 1e-8 * np.maximum(np.abs(args[0] + hi), 1.0)
    more = (root[2 * k :], doubt[2 * k :], good[2 * k :])
    return lo, hi, doubt[:k], doubt[k : 2 * k], ok, more


# ---------------------------------------------------------------------------------------------
# the grid


def _halves_exact(m, Q: Fraction):
    """Regime names per depth for the exact model (exact rational decision on the exact depths)."""
    return [regime_of(4 * Q * Q - 1 - x) for x in m], [regime_of(4 * Q * Q - 1 + x) for x in m]


#: the regime names by the codes of :func:`_halves` (``-1``, ``0``, ``+1``), shifted by one
_REGIMES = ("over", "critical", "under")


def _halves(dep, cols, Q: Fraction):
    """:func:`_halves_exact` for the depths ``cols`` of ``dep`` as int8 arrays of codes (``+1``
    under-, ``0`` critically, ``-1`` over-damped; the name is ``_REGIMES[code + 1]``), decided in
    floats where ``4 Q^2 - 1 -+ m`` is far from 0 (its float value is within a few ulp of ``4 Q^2
    + 1`` of the exact one: ``4 Q^2 - 1`` and ``m`` are each rounded once) and from the exact
    depth elsewhere."""
    q = 4 * Q * Q - 1
    qf, ms = float(q), dep.m[cols]
    margin = 1e-12 * (abs(qf) + 2.0)
    codes = []
    for sign in (-1, 1):
        u = qf + sign * ms
        out = np.where(u > 0, 1, -1).astype(np.int8)
        for j in np.nonzero(np.abs(u) <= margin)[0]:
            out[j] = _REGIMES.index(regime_of(q + sign * dep.exact(int(cols[j])))) - 1
        codes.append(out)
    return codes[0], codes[1]


#: the double path serves depths with ``1 - m`` at least this (the last double below 1 has
#: ``1 - m = 2**-53``) and ``m`` at least the smallest normal double; exact depths outside are
#: computed by the certified route
OM_MIN = 2.0**-53
M_MIN = 2.0**-1022


#: below this ``1 - m`` a float depth's ``1 - m`` is taken from its shortest decimal (above it the
#: binary and decimal ``1 - m`` differ by less than a relative 1e-15)
DECIMAL_OM = 0.11


def _one_minus_decimal(x: float) -> float:
    """``1 - d`` rounded once to a double, ``d`` the shortest decimal of ``x`` (``0 < x < 1``)."""
    text = repr(x)
    whole, _, frac = text.partition(".")
    if whole != "0" or not frac.isdigit():  # an exponent form (not for x near 1): exact decimals
        with decimal.localcontext() as dc:
            dc.prec = 60
            return float(decimal.Decimal(1) - decimal.Decimal(text))
    scale = 10 ** len(frac)
    return (scale - int(frac)) / scale


#: the decimal places :func:`_one_minus_decimals` tries (``10^15 < 2^53``: every integer below is a
#: double)
_PLACES = np.arange(1, 16, dtype=float)[:, None]
_SCALES = 10.0**_PLACES


def _decimal_fraction(x: float) -> Fraction:
    """The shortest decimal of ``x`` (``0 < x < 1``) as a Fraction: ``Fraction(repr(x))``, from
    the digits of a plain ``0.ddd`` form without the parser (the exponent form through it)."""
    text = repr(x)
    if text[:2] == "0." and text[2:].isdigit():
        return Fraction(int(text[2:]), 10 ** (len(text) - 2))
    return Fraction(text)


def _one_minus_decimals(x) -> np.ndarray:
    """:func:`_one_minus_decimal` of every element of ``x`` (doubles ``1/2 <= x < 1``), vectorised:
    the shortest decimal of ``x`` with at most 15 places is ``d = 1 - E/10^L`` for the least
    ``L`` at which ``E = rint((1 - x) 10^L)`` (``1 - x`` is exact) gives ``fl(d) = x`` (both
    integers are exact doubles, so ``fl(d)`` and ``1 - d = E/10^L`` are each rounded once); the
    nearest ``L``-place decimal to ``x`` is the one ``repr`` takes.  Depths whose shortest decimal
    is longer go through :func:`_one_minus_decimal`."""
    x = np.asarray(x, float)
    E = np.rint((1.0 - x) * _SCALES)
    hit = (_SCALES - E) / _SCALES == x
    first = np.argmax(hit, axis=0)
    cols = np.arange(x.size)
    out = E[first, cols] / _SCALES[first, 0]
    miss = ~hit[first, cols]
    for j in np.nonzero(miss)[0]:
        out[j] = _one_minus_decimal(float(x[j]))
    return out


class _Depths:
    """The depths of a grid: ``m`` and ``om = 1 - m`` as float64 arrays, ``om`` computed from the
    exact depth (``1 - float(m)`` loses every digit of ``1 - m`` that ``float(m)`` rounded off,
    and near ``m = 1`` the edges depend on ``1 - m`` to the last digit); ``exact(j)`` is the
    exact depth as a Fraction (the shortest decimal for float input); ``double`` marks the depths
    the double path serves (:data:`OM_MIN`, :data:`M_MIN`)."""

    def __init__(self, m):
        arr = np.atleast_1d(np.asarray(m, dtype=object if _is_exactish(m) else float))
        if arr.dtype == object:
            self._exact = [exact_fraction(as_depth(x)) for x in arr.ravel()]
            self.m = np.array([float(x) for x in self._exact], float)
            self.om = np.array([float(1 - x) for x in self._exact], float)
        else:
            self.m = np.ascontiguousarray(arr, float).ravel()
            bad = ~((self.m > 0) & (self.m < 1))
            if bad.any():
                as_depth(float(self.m[np.argmax(bad)]))  # raises the standard error
            self._exact = None
            # a float depth means its shortest decimal (as everywhere in the API): 1 - m from the
            # decimal, corrected where the decimal and the binary value differ enough to matter
            # (1 - m_binary is exact for m >= 1/2 by Sterbenz; relative 2^-53 below)
            self.om = 1 - self.m
            near = np.nonzero(self.om < DECIMAL_OM)[0]
            if near.size:
                # 1 - decimal(x) exactly, rounded once (:func:`_one_minus_decimal`)
                self.om[near] = _one_minus_decimals(self.m[near])
        self.size = self.m.size
        self.double = (self.om >= OM_MIN) & (self.m >= M_MIN)

    def exact(self, j: int) -> Fraction:
        """The exact depth: the shortest decimal of a float input, as in the rest of the API."""
        return _decimal_fraction(float(self.m[j])) if self._exact is None else self._exact[j]

    def exact_all(self, idx) -> list:
        return [self.exact(int(j)) for j in idx]


def boundary_grid(orders, m, *, Q=None, damping="exact", system="pendulum", duty=None):
    """Lower and upper boundaries ``T/T0`` for every order in ``orders`` and depth in ``m``.

    Returns a float64 array of shape ``(len(orders), 2, len(m))``: ``[i, 0, j]`` the lower and
    ``[i, 1, j]`` the upper edge of order ``orders[i]`` at depth ``m[j]``; NaN where the interval
    does not exist.  ``orders`` keeps the caller's order (duplicates allowed).  ``m`` is a float
    array (each depth is the shortest decimal of its float, as everywhere in the API) or a
    sequence of exact depths (str such as ``"0.99999999999"``, ``Fraction``, ``int``, mpmath
    ``mpf``; each depth is that exact value: ``1 - m`` is computed from it exactly, never from
    ``float(m)``).

    **Accuracy.**  Every finite entry is within a relative :data:`ERROR_BOUND` (1e-14) of the
    exact edge at the exact depth, and an entry is NaN exactly where the interval does not exist:
    for every order, without friction and in both damping models, at every depth ``0 < m < 1``.
    The double path serves ``1 - m >= 2**-53`` (every double depth) and ``m >= 2**-1022``; exact
    depths outside, and the points next to a threshold or a closing gap where the double
    computation cannot decide the edges to that bound (a double root of the indicator), are
    proved in ball arithmetic (:func:`_confirm`) or, where that fails, computed by the
    certified route (:func:`verify.solve.boundary`).  ``tests/test_grid.py`` and
    ``tests/test_grid_hard.py`` check the claim against the certified edges on log-spaced samples
    (``1 - m`` down to ``2**-53``, ``m`` down to 1e-300, orders 1-6 and up to 100).  The order-1
    lower edge, which goes to 0 like ``1 - m``, is solved in ``x = omega_av T/2`` itself
    (:func:`verify.derived.order1_forms`) so that it keeps its relative accuracy.

    **Other members of the family** (``system``, ``duty``; :mod:`analytic.system`): the same
    double path with the generated parameters (:mod:`verify.system_params`) without friction and
    in the paper model, for ``1 - m >=`` :data:`FAMILY_OM_MIN`; every other entry (the exact
    model with friction, depths closer to 1, and the entries the double path cannot bound) comes
    from the certified route, so the accuracy claim is the same.  ``tests/test_family.py`` checks
    it on random samples.
    """
    from .inputs import as_system

    sysv = as_system(system, "1/2" if duty is None else duty)
    if not sysv.uses_depth:
        raise InputError(f"a custom system has no depth: there is no grid over m ({sysv.label})")
    orders = [int(o) for o in (orders if not isinstance(orders, int | str) else as_orders(orders))]
    as_orders(orders)  # validates
    scalar = np.ndim(m) == 0
    dep = _Depths(m)
    Qx = as_quality(Q)
    damping = as_damping(damping)
    out = np.full((len(orders), 2, dep.size), np.nan)
    doubt = np.zeros((len(orders), dep.size), bool)
    chunk = max(256, CHUNK_EDGES // (2 * len(orders)))  # depths per block: bounded memory
    if sysv.is_paper:
        served = dep.double
        for cols in _blocks(np.nonzero(served)[0], chunk):
            part, part_doubt = _double_grid(orders, dep, cols, Qx, damping)
            out[:, :, cols] = part
            doubt[:, cols] = part_doubt
        doubt[:, ~served] = True
    else:
        served = dep.double & (dep.om >= FAMILY_OM_MIN)
        if Qx is not None and damping == "exact":
            served[:] = False
        Qf = None if Qx is None else float(Qx)
        for cols in _blocks(np.nonzero(served)[0], chunk):
            P = normal_params(dep.m[cols], Qf, damping, _NP, sysv, om=dep.om[cols])
            part = np.full((len(orders), 2, cols.size), np.nan)
            doubt[:, cols] = _fill_normal(
                part,
                orders,
                dep.m[cols],
                P,
                damped=Qx is not None,
                system=sysv,
                om=dep.om[cols],
                friction=None if Qf is None else (Qf, damping),
            )
            out[:, :, cols] = part
        doubt[:, ~served] = True
    todo = list(zip(*np.nonzero(doubt), strict=True))
    if Qx is not None and todo:  # the proof in ball arithmetic, all entries at one precision
        mine = [(i, j) for i, j in todo if served[j]]
        got = _confirm_many(
            [(orders[i], dep.exact(j), out[i, :, j]) for i, j in mine],
            Qx,
            damping,
            sysv,
            refine=True,
        )
        for (i, j), edges in zip(mine, got, strict=True):
            if edges is not None:
                out[i, :, j] = edges
                doubt[i, j] = False
        todo = list(zip(*np.nonzero(doubt), strict=True))
    for i, j in todo:
        out[i, :, j] = _certified_point(
            orders[i], dep.exact(j), Qx, damping, sysv, outside=not served[j]
        )
    return out[..., 0] if scalar else out


#: other members of the family: depths closer to 1 than this go to the certified route
FAMILY_OM_MIN = 1e-9

#: the grid is computed in blocks of depths of about this many edges each (the working arrays
#: of a block take some hundred bytes per edge; the result itself 16 bytes per depth and order)
CHUNK_EDGES = 1 << 18


def _blocks(cols, size: int):
    """``cols`` in consecutive pieces of at most ``size``."""
    for start in range(0, cols.size, size):
        yield cols[start : start + size]


#: working precision (bits) of :func:`_confirm`
CONFIRM_BITS = 128
#: :func:`_confirm` proves each edge within this relative distance of the exact one (a proof,
#: not an estimate: it needs no margin below the bound other than for the checks' own rounding,
#: which ball arithmetic includes)
CONFIRM_REL = 0.8 * ERROR_BOUND


def _confirmed(n: int, m: Fraction, Q, damping: str, system, edges) -> bool:
    """Whether :func:`_confirm` proves the double edges ``edges = (lower, upper)`` (``T/T0``) of a
    friction entry within a relative :data:`CONFIRM_REL` of the exact edges."""
    return _confirm(n, m, Q, damping, system, edges) is not None


def _confirm(n: int, m: Fraction, Q, damping: str, system, edges, *, refine: bool = False):
    """The edges ``(lower, upper)`` (``T/T0``, doubles) of a friction entry whose double edges
    ``edges`` the error estimate could not bound, where a proof in ball arithmetic puts them
    within a relative :data:`CONFIRM_REL` of the exact edges; else ``None``.  The proof: the
    indicator ``D`` of the normal form, with the parameters enclosed at the exact depth, is
    negative at ``lower (1 - d)`` and positive at ``lower (1 + d)``, and positive at ``upper (1 -
    d)`` and negative at ``upper (1 + d)`` (``d =`` :data:`CONFIRM_REL`, ``theta = pi (T w -
    n/2)``).  So each edge has a zero of ``D`` within the bound, and the interval exists; that
    these zeros are the edges is the structure the double path relies on everywhere (one zero of
    ``D`` each side of its maximiser, inside the undamped interval).  Each edge returned is the
    secant root of ``D`` through those two points (at the working precision, rounded once; ``D``
    is smooth and its zero simple there, so it lands within about an ulp of the exact edge where
    the double edge, set by the rounding of ``D`` near a double root, may be off by up to the
    bound), kept inside the proved bracket.
    ``refine=True``: an edge whose bracket fails the test (a double edge off by more than the
    bound, as the rounding of ``D`` next to a double root can leave it) is moved once to the
    secant root through the two points and tested again with the same proof around that point.
    ``None`` (the entry then goes to the certified route) where a sign is not decided, the
    entry is NaN, or the normal form does not apply (a half critically or over-damped)."""
    return _confirm_many([(n, m, edges)], Q, damping, system, refine=refine)[0]


def _confirm_many(entries, Q, damping: str, system, *, refine: bool = False) -> list:
    """:func:`_confirm` of every ``(n, m, edges)`` of ``entries`` (one working precision and its
    constants for all): a list of the results."""
    arb, ctx = _flint()
    Qf = Q if isinstance(Q, Fraction) else Fraction(Q)
    with ctx.workprec(CONFIRM_BITS):
        half_pi = arb.pi() / 2
        d = arb(CONFIRM_REL)  # the double, exactly
        consts = (half_pi, 2 * half_pi, ((-1, 1 - d), (1, 1 + d)))
        return [_confirm_at(n, m, Qf, damping, system, e, refine, consts) for n, m, e in entries]


def _confirm_at(n, m, Qf, damping, system, edges, refine, consts):
    """:func:`_confirm` at the working precision, with its constants ``consts``."""
    lo, hi = float(edges[0]), float(edges[1])
    if not (math.isfinite(lo) and math.isfinite(hi) and lo < hi):
        return None
    m = m if isinstance(m, Fraction) else Fraction(m)
    a, b, p, q = Qf.numerator, Qf.denominator, m.numerator, m.denominator
    if damping == "exact" and not (4 * a * a - b * b) * q > p * b * b:  # 4 Q^2 - 1 - m > 0
        return None
    arb = _flint()[0]
    form = _arb_indicator(n % 2)
    out = []
    half_pi, pi, scales = consts
    r2, u, beta, g, w = indicator_params(m, Qf, damping, _ARB, system)
    n2 = arb(n) / 2
    args = (n * half_pi, r2, u, beta, g)
    for T, first in ((lo, -1), (hi, 1)):
        for again in (refine, False):
            ends = []
            ok = True
            aT = arb(T)
            for side, scale in scales:
                Tx = aT * scale
                v = form(pi * (Tx * w - n2), *args)
                want = first * side  # lower: -, +; upper: +, -
                if not (v < 0 if want > 0 else v > 0):
                    if not again:
                        return None
                    ok = False
                ends.append((Tx.mid(), v.mid()))
            (t1, v1), (t2, v2) = ends  # D is close to linear in T across the bracket
            root = float(t1 - v1 * (t2 - t1) / (v2 - v1))
            if ok:
                out.append(root if float(t1) <= root <= float(t2) else T)
                break
            if not (math.isfinite(root) and root > 0):
                return None
            T = root  # (the secant root through the two points: the bracket again there)
    return (out[0], out[1]) if out[0] < out[1] else None


@cache
def _flint():
    """``(arb, ctx)`` of python-flint (imported on first use)."""
    from flint import arb, ctx

    return arb, ctx


@cache
def _arb_indicator(odd: int):
    """The indicator ``D`` of the parity of the orders ``n`` with ``n % 2 == odd``, compiled for
    ``arb`` (:func:`_confirm`)."""
    return indicator(int(_parity(2 - odd))).compiled("arb", 0)


_ARB = backend("arb")


def _certified_point(
    n: int, m: Fraction, Q, damping: str, system=None, outside: bool = True
) -> tuple[float, float]:
    """Both edges from the certified route (NaN if the interval does not exist), at enough digits
    for a double: 20, more where the route asks for more; for a depth outside the double grid
    (``outside``) or one whose error the double grid cannot bound (the refusal says which)."""
    from .certified import boundary
    from .certify import CertificationError

    err = None
    for digits in (20, 40, 80, 160):
        try:
            kw = {} if system is None else {"system": system}
            b = boundary(n, m, Q=Q, damping=damping, digits=digits, **kw)
        except CertificationError as exc:
            err = exc
            continue
        return (float(b.lower), float(b.upper)) if b.exists else (math.nan, math.nan)
    where = (
        "outside the double grid (1 - m >= 2**-53, m >= 2**-1022)"
        if outside
        else "the double grid cannot bound its error there"
    )
    raise InputError(
        f"depth m = {m} (1 - m = {float(1 - m):.3g}, order {n}): {where}, and the certified "
        f"route could not enclose it ({err})"
    )


def _double_grid(orders, dep: _Depths, cols, Qx, damping):
    """The double path for the depths ``cols``: edges ``(len(orders), 2, len(cols))`` and a mask
    ``(len(orders), len(cols))`` of the entries whose error it cannot bound by
    :data:`ERROR_BOUND`."""
    ms, om = dep.m[cols], dep.om[cols]
    out = np.full((len(orders), 2, ms.size), np.nan)
    doubt = np.zeros((len(orders), ms.size), bool)
    if Qx is None or damping == "paper":
        Qf = None if Qx is None else float(Qx)
        P = normal_params(ms, Qf, damping, _NP, om=om)
        fr = None if Qx is None else (Qf, damping)
        doubt[:] = _fill_normal(out, orders, ms, P, damped=Qx is not None, om=om, friction=fr)
        return out, doubt
    Qexact = Fraction(Qx) if not isinstance(Qx, Fraction) else Qx
    h1, h2 = _halves(dep, cols, Qexact)
    # (Omega1/gamma)^2, the derived trace form's u1 (verify.params.trace_params): phase 1 near
    # critical damping takes the trace form
    u1 = trace_atoms(_paper_system(), ms, float(Qexact), _NP)[1]
    normal = (h1 == 1) & (u1 >= NEAR_CRITICAL**2)
    fr = (float(Qexact), "exact")
    if normal.all():  # (every depth: no subset to gather and put back)
        P = normal_params(ms, float(Qexact), "exact", _NP, om=om)
        P = _exact_near_critical(P, ms, lambda k: dep.exact(int(cols[k])), Qexact)
        doubt[:] = _fill_normal(out, orders, ms, P, damped=True, om=om, friction=fr)
        return out, doubt
    if normal.any():
        idx = np.nonzero(normal)[0]
        sub = ms[idx]
        P = normal_params(sub, float(Qexact), "exact", _NP, om=om[idx])
        P = _exact_near_critical(P, sub, lambda k: dep.exact(int(cols[idx[k]])), Qexact)
        part = np.full((len(orders), 2, sub.size), np.nan)
        doubt[:, idx] = _fill_normal(part, orders, sub, P, damped=True, om=om[idx], friction=fr)
        out[:, :, idx] = part
    for j in np.nonzero(~normal)[0]:
        T = trace_params(dep.exact(int(cols[j])), Qexact, backend("math"))
        regimes = (_REGIMES[h1[j] + 1], _REGIMES[h2[j] + 1])
        for i, n in enumerate(orders):
            try:
                window = trace_window_ends(n, regimes, T)
                if window is None:
                    continue
                res = damped_trace(n, regimes, T, window)
            except OverflowError:  # past the double range: the certified route decides
                doubt[i, j] = True
                continue
            scale = 2 * float(Qexact) / math.pi
            out[i, 0, j] = res["lo"] * scale
            out[i, 1, j] = res["hi"] * scale
            doubt[i, j] = res.get("doubt", False)
    return out, doubt


def _exact_near_critical(P, ms, exact, Q: Fraction):
    """Recompute the parameters of depths next to critical damping of half 1 (``4 Q^2 - 1 - m``
    tiny, where its float value has few correct digits) from the exact depths (``exact(k)``: the
    exact depth of ``ms[k]``)."""
    near = np.nonzero(np.abs(4 * float(Q) ** 2 - 1 - ms) < 1e-8)[0]
    if near.size == 0:
        return P
    cols = {f.name: np.array(getattr(P, f.name), float, copy=True) for f in fields(NormalParams)}
    for j in near:
        pm = normal_params(exact(int(j)), Q, "exact", backend("math"))
        for k in cols:
            cols[k][j] = float(getattr(pm, k))
    return NormalParams(**cols)


def _is_exactish(m) -> bool:
    if isinstance(m, str | Fraction | mpmath.mpf):
        return True
    if isinstance(m, list | tuple) or (isinstance(m, np.ndarray) and m.dtype == object):
        items = np.ravel(np.asarray(m, object))
        return any(isinstance(x, str | Fraction | mpmath.mpf) for x in items)
    return False


def _order1_lower(P, cols, x_hi, eps=None, *, x_theta=None, doubt=False):
    """The order-1 edge whose ``x = pi/2 + theta`` goes to 0 as ``m -> 1`` (``T -> 0``), solved
    in ``x`` itself on the forms of :func:`verify.derived.order1_forms` for the columns ``cols``:
    there ``theta`` is within rounding of ``-pi/2`` and carries no digit of ``x``.

    ``eps = 1``: the undamped edge equation ``E(x)``, with ``E(0) = v > 0`` and one simple root in
    ``(0, x_hi)``, ``x_hi = pi`` (the window theorem); ``eps = None``: the friction indicator
    ``D(x)``, with ``D(0) = -u < 0`` and ``x_hi = pi/2 + top`` (``D(top) > 0``; ``D <= D0 < 0``
    left of the undamped root, so its one zero in ``(0, x_hi)`` is the lower edge).  Newton,
    started where the Taylor polynomial ``F(0) + F''(0) x^2/2`` of the form vanishes (both forms
    are even in ``x``; the start is right to a relative ``O(x^2)``); where it leaves the bracket,
    safeguarded Newton on the bracket.  ``x_theta``: ``pi/2 + theta`` from the solver in
    ``theta`` (absolute error ~1e-16), the start where it is not tiny.
    ``doubt=True`` also returns the mask of roots whose error :func:`_root_doubt` cannot bound."""
    edge, ind = order1_forms()
    bm = P.bm[cols]
    if eps is not None:
        form = edge
        args = (P.u[cols] / (1 + P.r[cols]), P.beta[cols], bm)
    else:
        form = ind
        args = (P.r2[cols], P.u[cols], P.beta[cols], bm, P.g[cols])
    f01 = form.compiled("numpy", (0, 1))
    x_hi = np.asarray(x_hi, float) * np.ones(bm.shape)
    # x_theta is right to an absolute 1e-16: the better start unless x is tiny
    taylor = np.ones(bm.shape, bool) if x_theta is None else ~(np.asarray(x_theta) > 1e-4)
    x0 = np.array(x_theta if x_theta is not None else x_hi, float, copy=True)
    if taylor.any():
        sub = tuple(a[taylor] for a in args)
        f0, f2 = form.compiled("numpy", (0, 2))(np.zeros(sub[0].shape), *sub)
        with np.errstate(invalid="ignore", divide="ignore"):
            x0[taylor] = np.sqrt(-2 * np.asarray(f0, float) / np.asarray(f2, float))
    x = np.where(np.isfinite(x0) & (x0 > 0) & (x0 < x_hi), x0, 0.5 * x_hi)
    # Newton from there (the points not yet converged only); a point that leaves the bracket or
    # does not converge is solved again by the safeguarded iteration
    idx = np.arange(x.size)
    slope = np.empty(x.size) if doubt else None
    for it in range(12):
        f, d = f01(x if it == 0 else x[idx], *(args if it == 0 else (a[idx] for a in args)))
        d = np.asarray(d, float)
        if doubt:
            slope[idx] = d  # (at the last iterate: a step of at most 8e-16 x from the root)
        with np.errstate(invalid="ignore", divide="ignore"):
            step = np.asarray(f, float) / d
        x[idx] -= step
        idx = idx[~(np.abs(step) <= 8e-16 * np.abs(x[idx]))]
        if not idx.size:
            break
    bad = ~(np.isfinite(x) & (x > 0) & (x < x_hi))
    bad[idx] = True
    if bad.any():
        sub = tuple(a[bad] for a in args)
        x[bad] = _bisect_newton(
            lambda z: f01(z, *sub), 0 * x_hi[bad], x_hi[bad], 0.5 * x_hi[bad], eps is None
        )
        if doubt:
            slope[bad] = np.asarray(form.compiled("numpy", 1)(x[bad], *sub), float)
    if doubt:
        return x, _root_doubt(form, x, args, x, slope=slope)
    return x


#: the order-1 lower edge is solved in ``x`` (:func:`_order1_lower`) where ``x`` is below this,
#: without and with friction (an absolute error of ``theta`` is a relative error of ``x`` amplified
#: by ``1/x``; with friction the indicator's error estimate asks for the wider range)
ORDER1_X = 1.0
ORDER1_X_DAMPED = 1.0

#: below this ``1 - beta`` (``m > 0.975``) the grid polishes with the forms for ``m -> 1``
NEAR_ONE = 0.2


def _polish_near_one(theta, n, P, form, slope: bool = False):
    """Newton steps on a :func:`verify.derived.near_one_forms` form for the depths with
    ``1 - beta < NEAR_ONE`` (where the standard forms lose ``log10(1/bm)`` digits to
    cancellation); ``theta`` has rows of orders ``n``.  ``slope=True``: also the form's
    derivative of the last step at those depths (``(rows, depths)``, for :func:`_root_doubt`)."""
    cols = np.nonzero(P.bm < NEAR_ONE)[0]
    if cols.size == 0:
        return (theta, None) if slope else theta
    theta = np.array(theta, float, copy=True)
    c = (np.asarray(n, float) * _HALF_PI).reshape(-1, 1)
    fn = form.compiled("numpy", (0, 1))
    t = theta[:, cols]
    if form is near_one_forms()[2]:  # the indicator, in (theta, c, u, bm, g)
        args = (c, P.u[cols], P.bm[cols], P.g[cols])
    else:
        args = (c, P.r[cols], P.u[cols] / (1 + P.r[cols]), P.bm[cols])
    for _ in range(2):  # the start is right to ~1e-16/bm: two Newton steps reach rounding
        f, d = fn(t, *args)
        with np.errstate(invalid="ignore", divide="ignore"):
            step = np.asarray(f, float) / np.asarray(d, float)
        t = t - np.where(np.isfinite(step), step, 0.0)
    theta[:, cols] = t
    return (theta, np.asarray(d, float) * np.ones(t.shape)) if slope else theta


def _fill_normal(
    out, orders, ms, P, damped: bool, *, system=None, om=None, friction=None
) -> np.ndarray:
    """Fill ``out`` (orders x 2 x depths) from the normal form; returns the mask (orders x
    depths) of entries whose error is not bounded by :data:`ERROR_BOUND` (to be escalated).
    ``system`` (default the paper's) and ``om = 1 - m``: for the start tables of the frictionless
    grid (:func:`_frictionless_theta`, grids of at least :data:`_TABLE_MIN` depths); with
    friction also ``friction = (Q, damping)``, the key of the start tables of the undamped roots
    that bracket the edges (:func:`_damped_brackets`)."""
    orders_arr = np.array(orders)
    doubt = np.zeros((len(orders), ms.size), bool)
    P = NormalParams(
        *(np.asarray(getattr(P, f.name), float) * np.ones(ms.shape) for f in fields(NormalParams))
    )
    if not damped and om is not None and ms.size >= _TABLE_MIN:
        _fill_frictionless(out, orders_arr, P, om, system or _paper_system())
        return doubt
    if not damped:
        n = orders_arr[:, None]
        t1, t2 = normal_edges(n, P)
        near = near_one_forms()
        t1 = _polish_near_one(t1, orders_arr, P, near[0])
        t2 = _polish_near_one(t2, orders_arr, P, near[1])
        T1 = (n / 2.0 + t1 / math.pi) / P.w
        T2 = (n / 2.0 + t2 / math.pi) / P.w
        for i in np.nonzero(orders_arr == 1)[0]:  # the eps = +1 root is the one with x -> 0
            cols = np.nonzero((_HALF_PI + t1[i] < ORDER1_X) | (P.bm < NEAR_ONE))[0]
            if cols.size:
                x = _order1_lower(P, cols, math.pi, 1, x_theta=_HALF_PI + t1[i, cols])
                T1[i, cols] = x / (math.pi * P.w[cols])
        out[:, 0, :] = np.minimum(T1, T2)
        out[:, 1, :] = np.maximum(T1, T2)
        return doubt
    fast = None
    if om is not None and friction is not None and ms.size >= _TABLE_MIN:
        # the edges from their own start tables where that proves them (the depths away from
        # m = 1); the bracketed path for the rest, its brackets at those depths alone
        sysv = system or _paper_system()
        far = np.nonzero(P.bm >= TABLE_NEAR_MIN)[0]
        fast = _table_friction(orders_arr, P, np.sqrt(om), sysv, friction, far)
        need = np.nonzero(~fast["done"].all(axis=0))[0]
        Pn = NormalParams(*(getattr(P, f.name)[need] for f in fields(NormalParams)))
        if need.size:
            t1, t2 = _damped_brackets(orders_arr, Pn, om[need], sysv, friction)
    else:
        t1, t2 = normal_edges(orders_arr[:, None], P)  # the undamped roots of all orders at once
    no = len(orders)
    if fast is None:
        res = {}
    else:
        res = fast
    for parity in (1, 0):
        rows = np.nonzero(orders_arr % 2 == parity)[0]
        if rows.size == 0:
            continue
        if fast is None:
            got = _damped_normal(
                orders_arr[rows][:, None], P, edges=(t1[rows], t2[rows]), split=True
            )
            for k in _RESULT_KEYS:
                if k not in res:
                    res[k] = np.empty((no, ms.size), got[k].dtype)
                res[k][rows] = got[k]
        else:
            ri, ci = np.nonzero(~fast["done"][rows][:, need])
            if ri.size:  # the entries left, one by one (orders and depths flattened)
                Ps = NormalParams(*(getattr(Pn, f.name)[ci] for f in fields(NormalParams)))
                ends = (t1[rows][ri, ci], t2[rows][ri, ci])
                got = _damped_normal(orders_arr[rows][ri], Ps, ends, split=True, pair=False)
                for k in _RESULT_KEYS:
                    res[k][rows[ri], need[ci]] = got[k]
    # every order and both edges at once from here
    n = orders_arr[:, None]
    both, slope = _polish_near_one(
        np.concatenate([res["lo"], res["hi"]]),
        np.concatenate([orders_arr] * 2),
        P,
        near_one_forms()[2],
        slope=True,
    )
    lo, hi = both[:no], both[no:]
    base = n / 2.0
    out[:, 0, :] = (base + lo / math.pi) / P.w
    out[:, 1, :] = (base + hi / math.pi) / P.w
    top_doubt, lo_doubt, hi_doubt = _normal_doubt(n, P, res, lo, hi, slope)
    for i in np.nonzero(orders_arr == 1)[0]:
        near = (_HALF_PI + lo[i] < ORDER1_X_DAMPED) | (P.bm < NEAR_ONE)
        cols = np.nonzero(np.isfinite(lo[i]) & near)[0]
        if cols.size:
            x, unsure = _order1_lower(
                P,
                cols,
                _HALF_PI + res["top"][i, cols],
                x_theta=_HALF_PI + lo[i, cols],
                doubt=True,
            )
            out[i, 0, cols] = x / (math.pi * P.w[cols])
            lo_doubt[i, cols] = unsure
    doubt[:] = top_doubt | lo_doubt | hi_doubt
    return doubt


#: what :func:`_fill_normal` takes of :func:`_damped_normal`
_RESULT_KEYS = ("lo", "hi", "top", "dtop", "undecided", "lo_doubt", "hi_doubt")


def _damped_brackets(orders, P, om, system, friction):
    """The undamped roots ``(theta_eps=+1, theta_eps=-1)`` (each ``(len(orders), N)``) for the
    parameters ``P`` of the damped normal form, as :func:`normal_edges` gives them: from
    :func:`_frictionless_theta` with the start tables of ``friction = (Q, damping)`` (a function
    of the key alone), every root to convergence in ``theta`` (next to ``m = 1`` the friction
    path takes the lower edge of order 1 from its solve in ``x``, :func:`_order1_lower`, and the
    root with ``x = pi/2 + theta -> 0`` only brackets it)."""
    theta = np.empty((len(orders), 2, om.size))
    _frictionless_theta(orders.tolist(), P, np.sqrt(om), system, theta, friction)
    return theta[:, 0], theta[:, 1]


def _fill_frictionless(out, n, P, om, system) -> None:
    """:func:`_fill_normal` without friction for a grid of at least :data:`_TABLE_MIN` depths:
    the roots of every order and sign from :func:`_frictionless_theta` straight into ``out``,
    the depths near 1 polished (:func:`_polish_roots`), the order-1 edge with ``x -> 0``
    solved in ``x`` (:func:`_order1_lower`), then ``T/T0`` and the lower and upper edge, in
    place."""
    _frictionless_theta(n.tolist(), P, np.sqrt(om), system, out)
    near = np.nonzero(P.bm < NEAR_ONE)[0]
    if near.size:
        _polish_roots(out, n, P, near)
    xs = []
    for i in np.nonzero(n == 1)[0]:  # the eps = +1 root is the one with x -> 0
        x = _HALF_PI + out[i, 0]
        cols = np.nonzero((x < ORDER1_X) | (P.bm < NEAR_ONE))[0]
        if cols.size:
            xs.append((i, cols, _order1_lower(P, cols, math.pi, 1, x_theta=x[cols])))
    # T/T0 = (n/2 + theta/pi)/w, the operations of _fill_normal in place
    out /= math.pi
    out += (n / 2.0)[:, None, None]
    out /= P.w
    for i, cols, x in xs:
        out[i, 0, cols] = x / (math.pi * P.w[cols])
    lower = np.minimum(out[:, 0], out[:, 1])
    np.maximum(out[:, 0], out[:, 1], out=out[:, 1])
    out[:, 0] = lower


def _polish_roots(theta, n, P, cols) -> None:
    """:func:`_polish_near_one` for both signs of :func:`_fill_frictionless` (``theta``: orders x
    signs x depths), Newton steps on the forms for ``m -> 1`` at the depths ``cols`` alone, in
    place.  The roots come right to ~1e-16/bm; Newton's error after a step ``s`` is ``C s^2``
    with ``C = |F''/(2 F')|``, which grows like ``1/bm``: below 1e-20 where ``|s| <= 1e-12``
    and ``bm >= 1e-4``, and a second step is taken at the other depths (as
    :func:`_polish_near_one` takes everywhere)."""
    r = P.r[cols]
    args = ((n * _HALF_PI)[:, None], r, P.u[cols] / (1 + r), P.bm[cols])
    small = args[3] < 1e-4
    with np.errstate(invalid="ignore", divide="ignore"):
        for e, form in enumerate(near_one_forms()[:2]):
            fn = form.compiled("numpy", (0, 1))
            t = theta[:, e, cols]
            f, d = fn(t, *args)
            step = np.asarray(f, float) / np.asarray(d, float)
            step = np.where(np.isfinite(step), step, 0.0)
            t -= step
            again = np.nonzero(small | (np.abs(step) > 1e-12).any(axis=0))[0]
            if again.size:
                sub = (args[0], *(a[again] for a in args[1:]))
                f, d = fn(t[:, again], *sub)
                step = np.asarray(f, float) / np.asarray(d, float)
                t[:, again] -= np.where(np.isfinite(step), step, 0.0)
            theta[:, e, cols] = t


def _noise(form, v, args, scale):
    """A bound on the rounding error of ``form`` at ``v``: :data:`NOISE_ULPS` ulp of its term
    sizes, the angles (of size ``scale``) with errors of a few ulp
    (:func:`verify.derived.term_sizes`)."""
    sizes = term_sizes(form).compiled("numpy", (0, 1))
    total, slope = sizes(v, *args)
    return NOISE_ULPS * 2.0**-53 * (np.abs(total) + np.abs(scale) * np.abs(slope))


def _root_doubt(form, root, args, scale, slope=None):
    """Whether a root ``root`` of ``form`` may be off by more than :data:`DOUBT` relative to
    ``scale`` (where ``T`` is proportional to ``scale``): the rounding error of the form over its
    slope at the root (``slope``: that slope where the caller has it, e.g. from the last Newton
    step, a rounding away from the root)."""
    with np.errstate(invalid="ignore", divide="ignore"):
        if slope is None:
            slope = form.compiled("numpy", 1)(root, *args)
        slope = np.abs(np.asarray(slope, float))
        err = _noise(form, root, args, scale) / (slope * np.abs(scale))
        return np.isfinite(root) & ~(err <= DOUBT)


def _normal_doubt(n, P, res, lo, hi, slope=None):
    """Masks of the entries of the normal-form friction path that must be escalated: ``(top,
    lower, upper)``: the sign of ``D`` at its maximiser within rounding (existence undecided),
    and each edge whose estimated error exceeds :data:`DOUBT` (near a threshold or a closing gap,
    where the edges are a near-double root).  :func:`_damped_normal` gave them for the standard
    form; the depths polished on the form for ``m -> 1`` (``1 - beta <`` :data:`NEAR_ONE`) are
    judged here on that form (``slope``: its derivative at those depths from the last step of
    :func:`_polish_near_one`, rows lower edges then upper)."""
    undecided, edges = res["undecided"], [res["lo_doubt"].copy(), res["hi_doubt"].copy()]
    cols = np.nonzero(np.asarray(P.bm) < NEAR_ONE)[0]
    if cols.size == 0:
        return undecided, edges[0], edges[1]
    # next to m = 1 the standard form's parameters lose the digits that decide the sign of D at
    # its maximiser (order 1 at m = 1 - 9.4e-11 read D = -1.6e-15 where the interval exists):
    # there no interval is taken from the double path; the proof decides it
    undecided = np.array(undecided, bool, copy=True)
    undecided[..., cols] |= ~np.isfinite(_full(lo, undecided.shape)[..., cols])
    c = n * _HALF_PI
    params = (c, P.u[cols], P.bm[cols], P.g[cols])
    shape = np.broadcast_shapes(lo[:, cols].shape, *(np.shape(v) for v in params))
    args = tuple(_full(v, shape) for v in params)
    nearf = near_one_forms()[2]
    with np.errstate(invalid="ignore", over="ignore"):  # both edges in one call
        t = np.concatenate([_full(lo[:, cols], shape), _full(hi[:, cols], shape)])
        args = tuple(np.concatenate([a, a]) for a in args)
        sel = np.isfinite(t)
        part = np.zeros(t.shape, bool)
        if sel.any():
            sub = tuple(a[sel] for a in args)
            d = None if slope is None else _full(slope, t.shape)[sel]
            part[sel] = _root_doubt(nearf, t[sel], sub, sub[0] + t[sel], slope=d)
        k = shape[0]
        edges[0][:, cols], edges[1][:, cols] = part[:k], part[k:]
    return undecided, edges[0], edges[1]
