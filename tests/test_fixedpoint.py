"""The paper's fixed-point iteration (eqs. 15, 26, 39, 44): where it works, where it fails, and
that the default solver does not fail there.

References: the certified :func:`verify.solve.boundary`; the closing theorem (past m = 3/5 the two
edge equations of order 3 swap roles, so the paper's 'lower' equation gives the upper edge); the
threshold of :func:`verify.existence.existence` (near it the start theta = 0 lies outside the
shifted interval and the square root of eq. 39 is imaginary).
"""

from __future__ import annotations

import numpy as np
import pytest

from verify.fixedpoint import FixedPointError, failure_map
from verify.grid import boundary_grid
from verify.solve import boundary


@pytest.mark.parametrize(
    "n,m,Q,damping",
    [
        (1, "0.3", None, "exact"),
        (2, "0.5", None, "exact"),
        (1, "0.3", 5, "paper"),
        (2, "0.7", 3, "exact"),
    ],
)
def test_agrees_where_it_converges(n, m, Q, damping):
    fp = boundary(n, m, Q=Q, damping=damping, digits=30, method="fixedpoint")
    ref = boundary(n, m, Q=Q, damping=damping, digits=30)
    assert not fp.certified and fp.radius is None and fp.method == "fixedpoint"
    assert abs(fp.lower - ref.lower) < 1e-28 and abs(fp.upper - ref.upper) < 1e-28


def test_wrong_edge_past_a_closing():
    """Order 3 without friction: 'ok' below m = 3/5, 'other-edge' above (both edges)."""
    ms = np.array([0.3, 0.55, 0.59, 0.61, 0.65, 0.9])
    fm = failure_map([3], ms)
    assert (fm.kinds[0, :, :3] == "ok").all()
    assert (fm.kinds[0, :, 3:] == "other-edge").all()
    fp = boundary(3, "0.65", method="fixedpoint", digits=20)
    ref = boundary(3, "0.65", digits=20)
    assert fp.lower > fp.upper  # the paper's 'lower' is the upper edge here
    assert abs(fp.lower - ref.upper) < 1e-18
    # the default route: lower < upper, each the root of its own equation (grid agrees)
    g = boundary_grid([3], ms)
    for j, m in enumerate(ms):
        b = boundary(3, float(m), digits=20)
        assert b.lower < b.upper or m == 0.6
        assert abs(float(b.lower) - g[0, 0, j]) < 1e-14 * g[0, 0, j]


def test_imaginary_square_root_near_a_threshold():
    """Q = 7, paper model, order 3: at m = 0.26 (just above the threshold 0.2594) the interval
    exists
    but R(0) < 0 (eq. 39 has no real right-hand side at the start)."""
    fm = failure_map([3], np.array([0.26, 0.66, 0.8]), Q=7, damping="paper")
    assert fm.kinds[0, 0, 0] == "imaginary" and fm.kinds[0, 1, 0] == "imaginary"
    assert fm.kinds[0, 0, 1] == "imaginary"
    assert (fm.kinds[0, :, 2] == "ok").all()
    with pytest.raises(FixedPointError) as info:
        boundary(3, "0.26", Q=7, damping="paper", method="fixedpoint")
    assert info.value.kind == "imaginary"
    b = boundary(3, "0.26", Q=7, damping="paper")  # the default route has no such problem
    assert b.exists and b.certified and b.lower < b.upper


def test_map_summary():
    fm = failure_map(range(1, 5), np.linspace(0.05, 0.95, 19))
    counts = fm.counts()
    assert sum(counts.values()) == 4 * 2 * 19 and "spurious" not in counts
    # slow convergence (the map's slope tends to 1 as m -> 1) only at the largest depths
    slow = fm.ms[(fm.kinds == "no-convergence").any(axis=(0, 1))]
    assert (slow > 0.9).all()
    assert fm.first_failure(1, "other-edge") is None  # order 1 never closes
    assert 0.8 < fm.first_failure(4, "other-edge") < 0.86  # order 4 closes at m = 4/5
    assert fm.as_json()["counts"] == counts
