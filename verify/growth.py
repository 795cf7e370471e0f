"""The growth-rate map: ``log max|mu|`` per modulation period over a grid of ``(T/T0, m)``.

One function, :func:`growth_map`, used by the atlas and the explorer.  It evaluates the period map
of :mod:`verify.floquet` in double precision on the outer product of a vector of periods and a
vector of depths, in blocks of rows so that the memory stays bounded whatever the size of the
grid.  The value is ``log max(|mu1|, |mu2|)``: positive inside an interval of instability (the
amplitude grows by ``e**value`` per period), zero on its edges and outside it without friction,
``-gamma T`` outside it with friction.

    >>> import numpy as np   # at m = 0.3, T = 0.7 T0 is stable, 1.45 T0 inside the first interval
    >>> g = growth_map(np.array([0.7, 1.45]), np.array([0.3]))
    >>> bool(abs(g[0, 0]) < 1e-12), bool(g[0, 1] > 0.1)
    (True, True)

**How it is fast.**  The monodromy of :mod:`verify.floquet` is ``M = J21 U2(t2) J12 U1(t1)``,
``t1 = D T``, ``t2 = (1 - D) T``.  Every half map there has the form ``e**(-gamma t) [[C + g S, S],
[-w S, C - g S]]`` with ``C = cos(Omega t)``, ``S = sin(Omega t)/Omega`` (``Omega = sqrt(w -
gamma**2)`` and ``g = gamma`` in the exact model with an under-damped phase; ``Omega = sqrt(w)``
and ``g = 0`` in the paper's model and without friction).  Multiplying the four matrices out, the
trace is

    tr M = e**(-gamma T) (2 C1 C2 - (k w1 + w2/k - 2 g**2) S1 S2)

and ``det M = e**(-2 gamma T)`` (each half map has determinant ``e**(-2 gamma t)`` --
Liouville's formula, ``C**2 + (w - g**2) S**2 = 1`` -- and ``det J12 J21 = 1``).  The multipliers
are the roots of ``mu**2 - tr M mu + det M``, so with ``h = tr M e**(gamma T) / 2``

    log max|mu| = -gamma T + arccosh(max(|h|, 1)).

Everything but ``C1, S1, C2, S2`` is a number per depth (per row) or per period (per column), so a
point costs four sines and cosines and a few multiplications, done in place on blocks that stay in
the cache.  Rows with an over- or critically damped phase (exact model, ``w <= gamma**2``: only
for ``Q`` below about 1) go through :func:`verify.floquet.growth_factor` itself.  The tests check
the map against that function on grids of every system, duty and damping model.
"""

from __future__ import annotations

import math

import numpy as np

from analytic.system import PAPER

from .floquet import growth_factor
from .inputs import InputError, as_damping, as_system

__all__ = ["growth_map", "CHUNK_POINTS", "TOLERANCE"]

#: points evaluated at once (a few arrays of this many doubles stay in the cache)
CHUNK_POINTS = 1 << 16

#: the map agrees with ``log(verify.floquet.growth_factor(...))`` to ``TOLERANCE * max(1, |g|)``
#: away from the edges; within ``~1e-8`` of an edge both are the square root of a rounding-level
#: discriminant, so there the agreement is ``sqrt(TOLERANCE)`` (see tests/test_growth.py)
TOLERANCE = 1e-12


def _rows(m, system):
    """Per-depth numbers: ``w1, w2`` (``omega_i**2`` with ``omega0 = 2 pi``) and ``k``."""
    two_pi2 = (2 * math.pi) ** 2
    if not system.uses_depth:
        W1, W2, k = (float(v) for v in system.values(None))
        W1, W2, k = (np.full(m.shape, v) for v in (W1, W2, k))
    else:
        W1, W2, k = (np.asarray(v, dtype=float) for v in system.values(m))
        W1, W2, k = np.broadcast_arrays(W1, W2, k)
    return two_pi2 * W1, two_pi2 * W2, k


def growth_map(tau, m, Q=None, damping="exact", *, system=PAPER, duty=None, chunk=CHUNK_POINTS):
    """``log max|mu|`` on the grid ``tau`` x ``m``: an array of shape ``(len(m), len(tau))``.

    ``tau`` and ``m`` are 1-d sequences of floats (periods ``T/T0 > 0``, depths ``0 < m < 1``);
    ``Q`` is ``None`` (no friction) or a float ``> 0``; ``damping`` is ``"exact"`` or ``"paper"``.
    ``system`` and ``duty`` pick a member of the family (:mod:`analytic.system`); a custom system
    has no depth (``m`` then only sets the number of rows).
    """
    tau = np.atleast_1d(np.asarray(tau, dtype=float))
    m = np.atleast_1d(np.asarray(m, dtype=float))
    if tau.ndim != 1 or m.ndim != 1:
        raise InputError("growth_map takes 1-d arrays of periods and depths")
    if isinstance(chunk, bool) or not isinstance(chunk, int) or chunk < 1:
        raise InputError(f"chunk must be a positive integer, got {chunk!r}")
    if not np.all(np.isfinite(tau)) or not np.all(tau > 0):
        raise InputError("period T/T0 must be finite and > 0")
    sysv = as_system(system, "1/2" if duty is None else duty)
    if sysv.uses_depth and (not np.all(np.isfinite(m)) or not np.all((m > 0) & (m < 1))):
        raise InputError("depth m must be finite and in the allowed range 0 < m < 1")
    model = as_damping(damping)
    if Q is not None:
        Q = float(Q)
        if not math.isfinite(Q) or Q <= 0:
            raise InputError("quality factor Q must be finite and > 0 (None for no friction)")
    gamma = 0.0 if Q is None else math.pi / Q
    D = float(sysv.duty)
    t1, t2 = D * tau, tau - D * tau  # per column
    w1, w2, k = _rows(m, sysv)
    exact = Q is not None and model == "exact"
    g2 = gamma * gamma if exact else 0.0
    z1, z2 = w1 - g2, w2 - g2
    fast = (z1 > 0) & (z2 > 0)
    O1, O2 = np.sqrt(np.where(fast, z1, 1.0)), np.sqrt(np.where(fast, z2, 1.0))
    # h = C1 C2 - R s1 s2 with s_i = sin(Omega_i t_i): R = (k w1 + w2/k - 2 g^2) / (2 O1 O2)
    R = (k * w1 + w2 / k - 2 * g2) / (2 * O1 * O2)
    loss = gamma * tau  # per column: -log of the damping over one period
    out = np.empty((m.size, tau.size))
    rows = max(1, chunk // max(1, tau.size))
    shape = (rows, tau.size)
    buf = [np.empty(shape) for _ in range(4)]
    for start in range(0, m.size, rows):
        stop = min(m.size, start + rows)
        n = stop - start
        x1, x2, a, b = (v[:n] for v in buf)
        np.multiply(O1[start:stop, None], t1[None, :], out=x1)
        np.multiply(O2[start:stop, None], t2[None, :], out=x2)
        np.cos(x1, out=a)
        np.cos(x2, out=b)
        np.multiply(a, b, out=a)  # C1 C2
        np.sin(x1, out=x1)
        np.sin(x2, out=x2)
        np.multiply(x1, x2, out=x1)
        np.multiply(x1, R[start:stop, None], out=x1)  # R s1 s2
        np.subtract(a, x1, out=a)  # h
        np.abs(a, out=a)
        np.maximum(a, 1.0, out=a)
        dest = out[start:stop]
        np.arccosh(a, out=dest)
        if gamma:
            np.subtract(dest, loss[None, :], out=dest)
    slow = np.flatnonzero(~fast)
    if slow.size:  # over- or critically damped phases: the general route, row by row
        with np.errstate(divide="ignore"):
            for i in slow:
                g = growth_factor(
                    m[i] if sysv.uses_depth else 0.5, tau, Q, model, backend="numpy", system=sysv
                )
                out[i] = np.log(g)
    return out
