"""The frictionless grid's path for large grids (at least ``verify.grid._TABLE_MIN`` depths: start
tables per order, every order in one pass over blocks of depths) against the certified boundaries.

Reference: :func:`verify.solve.boundary` at 20 proven digits at the exact depth of each point (a
float means its shortest decimal, as everywhere in the API); it never uses the grid.  The hard
depths (log-spaced with a fixed seed towards both ends, ``m = 1e-12``, ``0.999999`` and the last
double below 1) are embedded among evenly spread filler depths, so that the grid takes the path
of large grids; the filler is long enough for several blocks of work arrays.
"""

from __future__ import annotations

from fractions import Fraction

import numpy as np
import pytest

import verify.grid as grid_module
from verify.grid import ERROR_BOUND, boundary_grid
from verify.solve import boundary

ORDERS = [1, 2, 3, 4, 5, 6, 17, 100]
LAST = float(np.nextafter(1.0, 0.0))
FILLER = (np.arange(2000) + 0.5) / 2000


def _hard(seed: int, count: int) -> np.ndarray:
    rng = np.random.default_rng(seed)
    lo = 10.0 ** rng.uniform(-300, -1, count // 3)
    hi = 1 - 10.0 ** rng.uniform(-16, -1, count // 3)
    mid = rng.uniform(0.01, 0.99, count - 2 * (count // 3))
    return np.concatenate([[1e-12, 0.999999, LAST], lo, mid, np.where(hi < 1, hi, LAST)])


def _large(orders, ms, **kw):
    """``boundary_grid`` at the depths ``ms``, computed in a grid with :data:`FILLER`."""
    assert FILLER.size >= grid_module._TABLE_MIN
    return boundary_grid(orders, np.concatenate([FILLER, ms]), **kw)[..., FILLER.size :]


@pytest.mark.parametrize(
    "kw",
    [{}, {"system": "torsion"}, {"system": "meissner"}, {"duty": "1/3"}],
    ids=["pendulum", "torsion", "meissner", "duty-1/3"],
)
def test_large_grid_matches_certified(kw):
    """Every entry within :data:`ERROR_BOUND` of the certified edge (NaN exactly where there is
    no interval) for orders 1-6, 17 and 100 at hard depths, for each built-in system and a
    duty of 1/3."""
    ms = _hard(20261123, 30)
    g = _large(ORDERS, ms, **kw)
    bad = []
    for i, n in enumerate(ORDERS):
        for j, m in enumerate(ms):
            b = boundary(n, float(m), digits=20, **kw)
            if not b.exists:
                if not np.isnan(g[i, :, j]).all():
                    bad.append((n, m, "an interval the certified route rules out", g[i, :, j]))
                continue
            for k, want in ((0, float(b.lower)), (1, float(b.upper))):
                rel = abs(g[i, k, j] - want) / abs(want)
                if not rel <= ERROR_BOUND:
                    bad.append((n, m, k, g[i, k, j], want, rel))
    assert not bad, "\n".join(map(str, bad[:10]))


def test_a_depth_does_not_depend_on_the_rest_of_the_grid():
    """The start tables depend on the system and the order alone, and every point is iterated
    to convergence on its own: a depth's edges are the same bits in any large grid, with the
    tables computed afresh or taken from the cache, and in any block of the work arrays."""
    ms = _hard(5, 12)
    a = _large([1, 2, 3, 6], ms)
    grid_module._TABLES.clear()
    grid_module._plan.cache_clear()
    shifted = np.concatenate([FILLER[:777], ms, FILLER[777:]])
    b = boundary_grid([6, 3, 2, 1], shifted)[::-1, :, 777 : 777 + ms.size]
    assert np.array_equal(a, b, equal_nan=True)


def test_one_minus_decimals_is_one_minus_the_shortest_decimal():
    """The vectorised ``1 - m`` of float depths near 1 equals ``1 - d`` for ``d`` the shortest
    decimal of ``m`` (``repr``), computed in exact rational arithmetic and rounded once."""
    rng = np.random.default_rng(11)
    short = np.array(
        [
            round(1 - 10.0**e, int(p))
            for e, p in zip(rng.uniform(-15, -1, 3000), rng.integers(1, 17, 3000), strict=True)
        ]
    )
    ms = np.concatenate(
        [
            1 - 10.0 ** rng.uniform(-16.5, -1, 3000),
            short,
            (np.arange(1000) + 0.5) / 1000,
            1 - np.arange(1, 300) * 2.0**-53,
            [LAST, 0.999999, 0.9995, 0.9],
        ]
    )
    ms = ms[(ms > 0.5) & (ms < 1)]
    got = grid_module._one_minus_decimals(ms)
    want = np.array([float(1 - Fraction(repr(float(m)))) for m in ms])
    assert np.array_equal(got, want)
