"""The growth-rate map: ``log max|mu|`` per modulation period over a grid of ``(T/T0, m)``.

One function, :func:`growth_map`, used by the atlas and the explorer.  It evaluates the period map
of :mod:`verify.floquet` (numpy backend, double precision) on the outer product of a vector of
periods and a vector of depths, in chunks of rows so that the memory stays bounded whatever the
size of the grid.  The value is ``log max(|mu1|, |mu2|)``: positive inside an interval of
instability (the amplitude grows by ``e**value`` per period), zero on its edges and outside it
without friction, ``-gamma T`` outside it with friction.

    >>> import numpy as np   # at m = 0.3, T = 0.7 T0 is stable, 1.45 T0 inside the first interval
    >>> g = growth_map(np.array([0.7, 1.45]), np.array([0.3]))
    >>> bool(abs(g[0, 0]) < 1e-12), bool(g[0, 1] > 0.1)
    (True, True)
"""

from __future__ import annotations

import numpy as np

from analytic.system import PAPER

from .floquet import growth_factor
from .inputs import InputError

__all__ = ["growth_map", "CHUNK_POINTS"]

#: points evaluated at once (about 60 bytes of temporaries each)
CHUNK_POINTS = 1 << 18


def growth_map(tau, m, Q=None, damping="exact", *, system=PAPER, duty=None, chunk=CHUNK_POINTS):
    """``log max|mu|`` on the grid ``tau`` x ``m``: an array of shape ``(len(m), len(tau))``.

    ``tau`` and ``m`` are 1-d sequences of floats (periods ``T/T0 > 0``, depths ``0 < m < 1``);
    ``Q`` is ``None`` (no friction) or a float ``> 0``; ``damping`` is ``"exact"`` or ``"paper"``.
    """
    tau = np.atleast_1d(np.asarray(tau, dtype=float))
    m = np.atleast_1d(np.asarray(m, dtype=float))
    if tau.ndim != 1 or m.ndim != 1:
        raise InputError("growth_map takes 1-d arrays of periods and depths")
    if not isinstance(chunk, int) or chunk < 1:
        raise InputError(f"chunk must be a positive integer, got {chunk!r}")
    out = np.empty((m.size, tau.size))
    rows = max(1, chunk // max(1, tau.size))
    for start in range(0, m.size, rows):
        block = m[start : start + rows, None]
        g = growth_factor(
            block, tau[None, :], Q, damping, backend="numpy", system=system, duty=duty
        )
        with np.errstate(divide="ignore"):
            out[start : start + rows] = np.log(g)
    return out
