"""The vectorised double-precision grid against the certified boundaries.

Reference: :func:`verify.solve.boundary` at 20 proven digits for each point (a fixed-seed random
sample log-spaced towards m -> 0 and m -> 1, as in SciPy's mpmath tests); the grid must agree to a
relative 1e-14 everywhere, and be NaN exactly where the certified route says the interval does not
exist.
"""

from __future__ import annotations

import numpy as np
import pytest

from verify.existence import existence
from verify.grid import boundary_grid
from verify.inputs import InputError
from verify.solve import boundary

RTOL = 1e-14


def _sample(seed, count):
    rng = np.random.default_rng(seed)
    lo = 10.0 ** rng.uniform(-12, -1, count // 3)
    mid = rng.uniform(0.05, 0.95, count // 3)
    hi = 1 - 10.0 ** rng.uniform(-9, -1.3, count - 2 * (count // 3))
    return np.concatenate([lo, mid, hi])


def _check(orders, ms, Q=None, damping="exact"):
    g = boundary_grid(orders, ms, Q=Q, damping=damping)
    assert g.shape == (len(orders), 2, len(ms))
    bad = []
    for i, n in enumerate(orders):
        for j, m in enumerate(ms):
            # at the same depth: a float given to the API (grid or certified route) means its
            # shortest decimal
            b = boundary(n, float(m), Q=Q, damping=damping, digits=20)
            if not b.exists:
                if not np.isnan(g[i, :, j]).all():
                    bad.append(
                        (n, m, "grid has an interval the certified route rules out", g[i, :, j])
                    )
                continue
            for k, want in ((0, float(b.lower)), (1, float(b.upper))):
                got = g[i, k, j]
                if not abs(got - want) <= RTOL * abs(want):
                    bad.append((n, m, k, got, want, abs(got - want) / abs(want)))
    assert not bad, "\n".join(map(str, bad[:10]))


def test_undamped_random_points():
    _check([1, 2, 3, 4, 5, 6], _sample(1, 45))


def test_undamped_high_orders():
    _check([17, 40, 100], _sample(2, 15))


@pytest.mark.parametrize("damping", ["paper", "exact"])
def test_damped(damping):
    ms = np.concatenate([np.linspace(0.05, 0.95, 13), [0.999, 0.9999]])
    _check([1, 2, 3, 5], ms, Q=5, damping=damping)


def test_exact_model_low_Q_trace_form():
    """Q = 0.7: half 1 near critical (trace form) or over-damped for large m."""
    ms = np.array([0.5, 0.9, 0.95, 0.96, 0.97, 0.99])
    _check([1, 2], ms, Q=0.7, damping="exact")


def test_closings_and_tiny_widths():
    ms = np.array([3 / 5, 4 / 5, 5 / 13, 15 / 17, 1e-12, 1e-8])
    _check([3, 4, 5, 6], ms)


def test_order_and_shape_conventions():
    ms = np.array([0.2, 0.4])
    g = boundary_grid([3, 1, 3], ms)
    assert np.array_equal(g[0], g[2]) and g[1, 0, 0] < g[0, 0, 0]
    assert (g[:, 0] < g[:, 1]).all()
    one = boundary_grid([1, 2], 0.3)
    assert one.shape == (2, 2)
    exact = boundary_grid([1], ["3/10"])
    assert exact[0, 0, 0] == one[0, 0]


def test_bad_input():
    for args, kw in (
        (([0], [0.3]), {}),
        (([1], [1.0]), {}),
        (([1], [np.nan]), {}),
        (([1], [0.3]), {"Q": -1}),
        (([1], [0.3]), {"damping": "x"}),
    ):
        with pytest.raises(InputError):
            boundary_grid(*args, **kw)


def test_figures_2_and_8_can_be_drawn():
    """Fig. 2: orders 1-6 without friction over 0 < m < 1, every edge finite and ordered.
    Fig. 8: paper model, Q = 3, 5, 7: the NaN pattern of order 3 at Q = 7 is the island of
    :func:`verify.existence.existence` (gone between ~0.486 and ~0.654)."""
    ms = np.linspace(0.001, 0.999, 999)
    fig2 = boundary_grid(range(1, 7), ms)
    assert np.isfinite(fig2).all() and (fig2[:, 0] <= fig2[:, 1]).all()
    ex = existence(3, 7, damping="paper")
    (a1, b1), (a2, _) = ex.intervals
    for Q in (3, 5, 7):
        fig8 = boundary_grid(range(1, 7), ms, Q=Q, damping="paper")
        assert np.isfinite(fig8[0, 0, -1])
        if Q == 7:
            has = np.isfinite(fig8[2, 0])
            inside = ((ms > float(a1)) & (ms < float(b1))) | (ms > float(a2))
            margin = (
                (np.abs(ms - float(a1)) < 2e-3)
                | (np.abs(ms - float(b1)) < 2e-3)
                | (np.abs(ms - float(a2)) < 2e-3)
            )
            assert np.array_equal(has[~margin], inside[~margin])


@pytest.mark.parametrize("Q", [None, 7])
def test_large_grid_near_one_matches_certified(Q):
    """A grid of at least 256 depths starts from interpolated roots at some of its own depths
    (:func:`verify.grid._table_start`), which may overshoot the window next to ``m = 1``; the
    entries there must still be the edges.  Reference: the certified route at 20 digits on the
    depths closest to 1 (every interval of orders 1-3), the rest of the grid as filler."""
    near = 1 - np.logspace(-12, -1, 40)
    ms = np.concatenate([(np.arange(1000) + 0.5) / 1000, near])
    g = boundary_grid([1, 2, 3], ms, Q=Q)
    for i, n in enumerate((1, 2, 3)):
        for j in range(1000, ms.size):
            b = boundary(n, float(ms[j]), Q=Q, digits=20)
            assert b.exists, (n, ms[j])
            for k, want in ((0, b.lower), (1, b.upper)):
                assert abs(g[i, k, j] - float(want)) <= RTOL * abs(float(want)), (n, ms[j], k)
