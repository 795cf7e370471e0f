"""The paper's own method: fixed-point iteration for ``Delta T`` (eqs. 15, 26, 39, 44), and where
it fails.

The paper writes each edge equation as ``sin(theta) = RHS(theta)`` with ``theta = omega_av Delta
T/2`` and iterates ``theta_{k+1} = asin(RHS(theta_k))`` from ``theta_0 = 0`` (``Delta T = 0``):

* no friction (eqs. 15, 26): ``RHS = s r f(beta (n pi/2 + theta))``; the paper calls ``s = -1`` the
  lower edge and ``s = +1`` the upper, for every order of the parity;
* friction (eqs. 39, 44): ``RHS = s sqrt(R(theta))``, ``R = r^2 f^2 - (1 - r^2) sinh^2(g x)``.

The maps are derived, not typed (:func:`verify.derived.fixed_point_map`).  The iteration is
selectable as ``boundary(..., method="fixedpoint")`` (uncertified; it raises
:class:`FixedPointError` when it does not give an edge) and :func:`failure_map` charts, on a grid
of orders and depths, what it does compared with the certified edges:

``"ok"``
    converged to the edge the paper's sign convention names;
``"other-edge"``
    converged to the *other* edge (the convention is wrong past a closing, where the two edge
    equations swap roles, and wherever ``f(beta x)`` changes sign);
``"spurious"``
    converged to a point that is not an edge (with friction: ``sqrt(R)`` drops the sign of
    ``f``, so ``sin(theta) = -sqrt(R)`` may have solutions that are not edges);
``"no-convergence"``
    no fixed point within the iteration budget (the map's slope exceeds 1 in modulus: it
    oscillates or wanders);
``"imaginary"``
    ``R(theta_k) < 0`` at some iterate although the interval exists (the square root of eqs.
    39, 44 is imaginary: a start at ``theta = 0`` outside a shifted interval);
``"no-interval"``
    the interval does not exist and the iteration fails, as it should;
``"phantom"``
    the interval does not exist but the iteration converges (to a point that is not an edge).

The default solver never does any of this: each edge equation has one root in the window and the
solver stays in the bracket it has proven (``tests/test_fixedpoint.py`` checks it on the same grid).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import mpmath
import numpy as np

from .derived import backend, fixed_point_map
from .inputs import as_damping, as_orders, as_quality
from .methods import register_method

__all__ = [
    "FixedPointError",
    "FixedPointMap",
    "KINDS",
    "iterate",
    "boundary_fixedpoint",
    "failure_map",
]

KINDS = ("ok", "other-edge", "spurious", "no-convergence", "imaginary", "no-interval", "phantom")


class FixedPointError(ArithmeticError):
    """The paper's iteration did not give an edge; ``kind`` says how it failed."""

    def __init__(self, message: str, kind: str):
        super().__init__(message)
        self.kind = kind


def _map_args(n: int, P, damped: bool, s, lib):
    c = n * lib.pi / 2
    if damped:
        return lambda t: (t, c, P.r2, P.u, P.beta, P.g, s)
    return lambda t: (t, c, P.r, P.beta, s)


def iterate(n: int, P, s: int, *, damped: bool, name: str = "numpy", tol=1e-13, max_iter=20000):
    """Run the paper's iteration for order ``n`` with normal-form parameters ``P`` (arrays of the
    back end ``name``), branch ``s``; returns ``(theta, converged, imaginary, iterations)``."""
    from analytic.stitching import Parity

    fn = fixed_point_map(Parity.of(n), damped).compiled(name, 0)
    if name == "numpy":
        lib = np
        shape = np.broadcast(np.asarray(P.r), np.asarray(P.beta)).shape
        th = np.zeros(shape)
        conv = np.zeros(shape, bool)
        imag = np.zeros(shape, bool)
        done_at = np.full(shape, max_iter)
        args = _map_args(n, P, damped, s, lib)
        c = n * np.pi / 2
        with np.errstate(invalid="ignore"):
            for k in range(max_iter):
                new = np.asarray(fn(*args(th)), float)
                bad = ~np.isfinite(new)
                imag |= bad & ~conv
                step = np.abs(new - th)
                # rounding level of the map: a few ulp of theta and of the argument beta (c + theta)
                noise = 4.5e-16 * (2 * np.abs(new) + np.abs(c + new) * np.abs(P.r * P.beta))
                newly = ~conv & ~imag & (step <= np.maximum(tol * np.abs(new), noise))
                done_at[newly] = k + 1
                conv |= newly
                th = np.where(conv | imag, th, new)
                th = np.where(newly, new, th)
                if (conv | imag).all():
                    break
        return th, conv, imag, done_at
    # mpmath, scalars
    args = _map_args(n, P, damped, s, mpmath)
    th = mpmath.mpf(0)
    for k in range(max_iter):
        new = fn(*args(th))
        if isinstance(new, mpmath.mpc) or not mpmath.isfinite(new):
            return th, False, True, k + 1
        if abs(new - th) <= tol * max(abs(new), mpmath.mpf(10) ** (-mpmath.mp.dps * 3)):
            return new, True, False, k + 1
        th = new
    return th, False, False, max_iter


def boundary_fixedpoint(req):
    """``boundary(..., method="fixedpoint")``: the paper's iteration at ``digits`` digits in mpmath,
    with the paper's labels (``s = -1`` lower, ``s = +1`` upper).  Not certified."""
    from .params import halves, normal_params
    from .result import Boundary

    if req.Q is not None and not halves(req.m, req.Q, req.damping).normal:
        raise FixedPointError("the paper's iteration needs both halves under-damped", "imaginary")
    damped = req.Q is not None
    with mpmath.workdps(req.digits + 15):
        P = normal_params(req.m, req.Q, req.damping, backend("mpmath"))
        out = []
        for s in (-1, 1):
            th, conv, imag, k = iterate(
                req.order,
                P,
                s,
                damped=damped,
                name="mpmath",
                tol=mpmath.mpf(10) ** (-(req.digits + 8)),
            )
            if not conv:
                kind = "imaginary" if imag else "no-convergence"
                raise FixedPointError(
                    f"the paper's iteration for the {'lower' if s < 0 else 'upper'} edge of order "
                    f"{req.order} at m = {float(req.m):.6g}: {kind} after {k} steps",
                    kind,
                )
            out.append(th)
        n = req.order
        T = [(mpmath.mpf(n) / 2 + t / mpmath.pi) / P.w for t in out]
        d = [t / (mpmath.pi * P.w) + mpmath.mpf(n) / 2 * P.dinv for t in out]
    return Boundary(
        order=n,
        m=req.m,
        Q=req.Q,
        damping=req.damping,
        digits=req.digits,
        method="fixedpoint",
        exists=True,
        lower=T[0],
        upper=T[1],
        delta_lower=d[0],
        delta_upper=d[1],
        radius=None,
        certified=False,
        regime="paper's fixed-point iteration (eqs. 15, 26, 39, 44)",
        notes=("labels as in the paper: s = -1 gives 'lower', s = +1 'upper'",),
    )


@dataclass(frozen=True)
class FixedPointMap:
    """``kinds[i, e, j]``: what the iteration does for ``orders[i]``, edge ``e`` (0: the paper's
    lower, ``s = -1``; 1: upper) at depth ``ms[j]``; ``iterations`` likewise."""

    orders: tuple
    ms: np.ndarray
    Q: object
    damping: str
    kinds: np.ndarray
    iterations: np.ndarray

    def counts(self) -> dict:
        vals, cnt = np.unique(self.kinds, return_counts=True)
        return {str(v): int(c) for v, c in zip(vals, cnt, strict=True)}

    def first_failure(self, order: int, kind: str):
        """The smallest depth at which ``order`` shows ``kind`` on either edge (``None``: never)."""
        i = self.orders.index(order)
        hit = np.nonzero((self.kinds[i] == kind).any(axis=0))[0]
        return None if hit.size == 0 else float(self.ms[hit[0]])

    def as_json(self) -> dict:
        return {
            "orders": list(self.orders),
            "m": [float(x) for x in self.ms],
            "Q": None if self.Q is None else float(self.Q),
            "damping": self.damping,
            "kinds": self.kinds.tolist(),
            "counts": self.counts(),
        }


def failure_map(orders, ms, *, Q=None, damping="exact", max_iter=5000) -> FixedPointMap:
    """Classify the paper's iteration on the grid ``orders x ms`` against the edges of
    :func:`verify.grid.boundary_grid` (see the module text for the kinds)."""
    from .grid import boundary_grid
    from .params import normal_params

    orders = tuple(as_orders(orders)) if isinstance(orders, str) else tuple(int(o) for o in orders)
    ms = np.asarray(ms, float)
    QQ = as_quality(Q)
    model = as_damping(damping)
    damped = QQ is not None
    ref = boundary_grid(orders, ms, Q=Q, damping=model)
    Qf = None if QQ is None else float(QQ)
    P = normal_params(ms, Qf, model, backend("numpy"))
    kinds = np.empty((len(orders), 2, ms.size), dtype=object)
    iters = np.zeros((len(orders), 2, ms.size), int)
    for i, n in enumerate(orders):
        exists = np.isfinite(ref[i, 0])
        width = np.where(exists, ref[i, 1] - ref[i, 0], 0.0)
        for e, s in enumerate((-1, 1)):
            th, conv, imag, k = iterate(n, P, s, damped=damped, max_iter=max_iter)
            T = (n / 2 + th / math.pi) / P.w
            tol = 1e-9 * np.maximum(np.abs(T), 1e-300) + 1e-6 * np.abs(width)
            same = np.abs(T - ref[i, e]) <= tol
            other = np.abs(T - ref[i, 1 - e]) <= tol
            kind = np.where(
                exists,
                np.where(
                    conv,
                    np.where(same, "ok", np.where(other, "other-edge", "spurious")),
                    np.where(imag, "imaginary", "no-convergence"),
                ),
                np.where(conv, "phantom", "no-interval"),
            )
            kinds[i, e] = kind
            iters[i, e] = k
    return FixedPointMap(orders, ms, QQ, model, kinds, iters)


register_method("fixedpoint")(boundary_fixedpoint)
