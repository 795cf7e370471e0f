"""Two independent routes to the same boundaries: the determinant / normal-form route of
:mod:`verify.solve` (equations derived by :mod:`analytic`) and the Floquet route of
:mod:`verify.floquet` (monodromy built directly from segment solutions and jump matrices).

At random points (fixed seed): (1) on each certified edge ``det(M - (-1)^n I) = 0`` to within 1e-30
(relative to the size of ``M``) at 60 digits -- ``(-1)^n`` is a multiplier (without friction it is a
double one, so the determinant, not the multiplier, is the well-conditioned test); (2) a period is
inside an interval of :func:`verify.grid.boundary_grid` exactly when the Floquet growth per period
exceeds 1.
"""

from __future__ import annotations

import random
from fractions import Fraction

import mpmath
import numpy as np
import pytest

from verify.floquet import floquet_multipliers, growth_factor, monodromy_matrix
from verify.grid import boundary_grid
from verify.solve import boundary

CASES = [
    (None, "exact"),
    (Fraction(3), "paper"),
    (Fraction(7), "exact"),
    (Fraction(5), "paper"),
    (Fraction(3, 2), "exact"),
    (Fraction(7, 10), "exact"),
]


def _random_points(seed, count):
    rng = random.Random(seed)
    for _ in range(count):
        n = rng.randint(1, 8)
        m = Fraction(rng.uniform(0.02, 0.98)).limit_denominator(10**6)
        Q, damping = rng.choice(CASES)
        yield n, m, Q, damping


@pytest.mark.parametrize("seed", [1, 2, 3])
def test_edges_are_floquet_boundaries(seed):
    checked = 0
    for n, m, Q, damping in _random_points(seed, 16):
        b = boundary(n, m, Q=Q, damping=damping, digits=40)
        if not b.exists:
            continue
        sigma = -1 if n % 2 else 1
        for T in (b.lower, b.upper):
            M = monodromy_matrix(m, T, Q, damping, dps=60)
            with mpmath.workdps(60):
                det = (M[0, 0] - sigma) * (M[1, 1] - sigma) - M[0, 1] * M[1, 0]
                size = 1 + max(abs(x) for x in M) ** 2
                assert abs(det) < mpmath.mpf(10) ** -30 * size, (n, m, Q, damping, T, det)
            mu = floquet_multipliers(m, T, Q, damping, dps=60)
            assert min(abs(x - sigma) for x in mu) < 1e-15
        checked += 1
    assert checked >= 3


@pytest.mark.parametrize("Q,damping", CASES)
def test_inside_iff_floquet_growth(Q, damping):
    rng = np.random.default_rng(7)
    ms = rng.uniform(0.03, 0.97, 60)
    taus = rng.uniform(0.05, 3.5, 60)
    orders = list(range(1, 41))
    g = boundary_grid(orders, ms, Q=None if Q is None else float(Q), damping=damping)
    grow = growth_factor(ms, taus, None if Q is None else float(Q), damping, backend="numpy")
    for j in range(ms.size):
        lo, hi = g[:, 0, j], g[:, 1, j]
        with np.errstate(invalid="ignore"):
            inside = np.any((taus[j] > lo) & (taus[j] < hi))
            dist = np.abs(np.concatenate([lo, hi]) - taus[j])
            near = bool(np.any(dist[np.isfinite(dist)] < 1e-7))
        if near:
            continue
        threshold = 1 + 1e-9
        assert inside == (grow[j] > threshold), (ms[j], taus[j], grow[j], lo, hi)
