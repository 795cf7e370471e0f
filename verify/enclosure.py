"""From proven balls of the unknown to the result: parameters at the working precision, the
accuracy each unknown needs, and :func:`edges_result`, which turns the two enclosed roots into a
:class:`verify.result.Boundary` (``T/T0`` and the offsets as balls, every radius proven; from
such balls, however found, :func:`verify.result.from_balls`)."""

from __future__ import annotations

import math
from functools import lru_cache

from flint import arb, ctx

from .certify import CertificationError, pow2
from .result import Boundary, from_balls

__all__ = [
    "AtPrecision",
    "GUARD",
    "sgn_of",
    "theta_scale",
    "theta_floor",
    "edges_result",
    "no_interval",
]


#: the bits above the working precision at which :class:`AtPrecision` evaluates its numbers
GUARD = 12


class AtPrecision:
    """Numbers recomputed for every working precision (``flint.ctx.prec``), cached.

    With ``rounded=True`` the value (an ``arb`` or a dataclass of them) is computed once at the
    highest precision asked for so far, and a lower precision takes it rounded from there (a ball
    rounded outward still holds the exact value): one evaluation instead of one per precision."""

    def __init__(self, make, min_prec: int = 0, rounded: bool = False):
        self._make = make
        self._cache: dict[int, object] = {}
        self._min = min_prec  # e.g. what a depth range needs to keep 1 - m
        self._rounded = rounded
        self._top = -1  # the highest precision computed (rounded=True)

    def __call__(self):
        prec = ctx.prec
        val = self._cache.get(prec)
        if val is None:
            ctx.prec = max(prec, self._min) + GUARD
            try:
                if prec < self._top:
                    val = _round(self._cache[self._top])
                else:
                    val = self._make()
                    if self._rounded:
                        self._top = prec
            finally:
                ctx.prec = prec
            self._cache[prec] = val
        return val


def _round(v):
    """``v`` (an ``arb``, a tuple or a dataclass of numbers) rounded to the working precision."""
    if type(v) is arb:
        return +v
    if type(v) is tuple:
        return tuple(_round(x) for x in v)
    return type(v)(**{k: (+x if type(x) is arb else x) for k, x in vars(v).items()})


_HALF = arb(0.5)


def sgn_of(n: int) -> int:
    """``sin(n pi/2)`` for odd ``n``, ``cos(n pi/2)`` for even ``n`` (exact)."""
    return (1 if n % 4 == 1 else -1) if n % 2 else (1 if n % 4 == 0 else -1)


def theta_scale(theta: float, n: int, bits: int):
    """What ``theta`` must be accurate relative to: itself (for the offset ``delta``) and
    ``x = n pi/2 + theta`` (for ``T``; small for the lower edge of order 1 as ``m -> 1``)."""
    s = min(abs(theta), abs(n * math.pi / 2 + theta))
    if s > n * 1e-59:  # above theta_floor(bits, n) <= 3 n 2**-201 (no ball compared)
        return s
    return max(s, theta_floor(bits, n))


@lru_cache(maxsize=256)
def theta_floor(bits: int, n: int):
    """Absolute scale for a ``theta`` that may be exactly zero (closings): ``2**-max(2 bits,
    200)`` of about ``n pi/2`` (``3n/2``, exactly), an exact ``arb`` (a float would underflow to
    zero above about 160 digits, and the enclosure of a zero ``theta`` would never be small enough
    relative to nothing); above it ``theta`` (and the offset ``delta``) is given to full relative
    accuracy."""
    return arb((3 * n, -max(2 * bits, 200) - 1))


def edges_result(
    req,
    method,
    th_lo,
    th_hi,
    P,
    bits,
    regime,
    prec,
    notes=(),
    theta=True,
    certified=True,
    ys=None,
) -> Boundary:
    """Turn two ``theta`` (or ``zeta``) balls into the result: ``T/T0`` and offsets as balls,
    midpoints returned, radius the largest proven error.  ``ys`` (balls of ``y = theta + pi/2``
    for the two edges, near ``m = 1``; ``None`` to use ``theta``) give ``T`` from ``x = y + (n -
    1) pi/2`` and the offset from ``theta = y - pi/2``, each without cancellation."""
    n = req.order
    old = ctx.prec
    ctx.prec = prec
    try:
        p = P()
        if theta and ys is not None:
            pi = arb.pi()
            half = arb(n) * _HALF  # exact, and no arb-with-int operation
            Ts = [(y + (n - 1) * pi / 2) / (pi * p.w) for y in ys]
            ds = [(y - pi / 2) / (pi * p.w) + half * p.dinv for y in ys]
        elif theta:
            pi = arb.pi()
            half = arb(n) * _HALF  # exact, and no arb-with-int operation
            pw = pi * p.w
            Ts = [(half + th / pi) / p.w for th in (th_lo, th_hi)]
            ds = [th / pw for th in (th_lo, th_hi)]
            if not p.dinv.is_zero():  # 1/w - 1/w0 (the exact model with friction)
                ds = [d + half * p.dinv for d in ds]
        else:
            pi = arb.pi()
            Ts = [2 * p.Q * z / pi for z in (th_lo, th_hi)]
            ds = [T - arb(n) / (2 * p.w0) for T in Ts]
        tol = pow2(-bits)
        for T in Ts:
            if not T.rad() <= T.abs_lower() * tol:  # pragma: no cover - guard
                raise CertificationError(f"enclosure of T too wide: {T}")
    finally:
        ctx.prec = old
    return from_balls(
        Ts + ds,
        order=n,
        m=req.m,
        Q=req.Q,
        damping=req.damping,
        digits=req.digits,
        method=method,
        regime=regime,
        system=req.system,
        notes=notes,
        certified=certified,
    )


def no_interval(req, method, regime, notes=(), certified=True) -> Boundary:
    return Boundary(
        order=req.order,
        m=req.m,
        Q=req.Q,
        damping=req.damping,
        digits=req.digits,
        method=method,
        exists=False,
        certified=certified,
        regime=regime,
        notes=tuple(notes),
        system=req.system,
    )
