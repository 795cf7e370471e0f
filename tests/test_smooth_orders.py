"""The sine modulation's certified edges for orders 1-6 (verify.smooth.sine_boundary) against
two independent computations at random depths (seeded, seed 1306):

* an ordinary ODE integration (scipy's DOP853, double precision, of ``(l^2 phi')' + g l phi =
  0`` typed here from the model, not from the sympy forms): the Floquet criterion at the edge
  (odd orders: ``tr M + 2`` changes sign across it; even orders: ``M = I``, the interval is
  closed) and the edge's order (the Floquet solution has ``2n`` zeros in two periods);
* Hill's method (verify.smooth.sine_edges_fourier: the Fourier recurrence, no integration) at
  40 digits, which must fall inside the certified enclosures.
"""

from __future__ import annotations

import math
import random
from fractions import Fraction as F

import mpmath
import numpy as np
import pytest
from scipy.integrate import solve_ivp

from analytic.smooth import sine_closings
from verify.smooth import sine_boundary, sine_edges_fourier

SEED = 1306

#: each depth takes a few seconds per order (six 30-digit boundaries in the module fixture)
pytestmark = pytest.mark.slow


def _depths():
    """One depth per order, m in [0.2, 0.85] (two decimals), from random.Random(SEED)."""
    rng = random.Random(SEED)
    return [(n, F(rng.randint(20, 85), 100)) for n in range(1, 7)]


CASES = _depths()


def _rhs(m: float, T: float):
    g = 4 * math.pi**2

    def f(t, y):
        l = 1 + m * math.sin(2 * math.pi * t / T)
        return [y[1] / (l * l), -g * l * y[0]]

    return f


def _flow(m, T, t0, t1, y0, dense=False):
    return solve_ivp(
        _rhs(m, T), (t0, t1), y0, method="DOP853", rtol=1e-13, atol=1e-15, dense_output=dense
    )


def _monodromy(m: float, T: float) -> np.ndarray:
    cols = [_flow(m, T, 0.0, T, y0).y[:, -1] for y0 in ([1.0, 0.0], [0.0, 1.0])]
    return np.array(cols).T


def _zeros_in_two_periods(m: float, T: float, y0) -> int:
    """Sign changes of phi over [T/4 + T/8, T/4 + T/8 + 2T) of the solution from y0 at T/4."""
    t0 = T / 4
    sol = _flow(m, T, t0, t0 + 2.2 * T, y0, dense=True)
    t = np.linspace(t0 + T / 8, t0 + T / 8 + 2 * T, 20001)
    phi = sol.sol(t)[0]
    return int(np.sum(np.sign(phi[1:]) != np.sign(phi[:-1])))


@pytest.fixture(scope="module")
def certified():
    return {n: sine_boundary(n, m, digits=30) for n, m in CASES}


@pytest.mark.parametrize("n,m", CASES)
def test_thirty_digits(certified, n, m):
    b = certified[n]
    assert b.certified and b.digits == 30
    pairs = zip((b.lower, b.upper), (b.lower_enclosure, b.upper_enclosure), strict=True)
    for T, (lo, hi) in pairs:
        # a bracket of a proven sign change: never a point, and the midpoint inside
        assert lo < T < hi
        assert hi - lo < mpmath.mpf(10) ** -30 * lo


@pytest.mark.parametrize("n,m", CASES)
def test_against_hills_method(certified, n, m):
    """The Fourier route's edges (40 digits, started from the certified midpoints) lie in the
    certified enclosures (widened by 1e-38 for the route's own truncation)."""
    b = certified[n]
    with mpmath.workdps(50):
        got = sine_edges_fourier(n, m, dps=40, start=(b.lower, b.upper))
        slack = mpmath.mpf(10) ** -38
        for T, (lo, hi) in zip(got, (b.lower_enclosure, b.upper_enclosure), strict=True):
            assert lo - slack <= T <= hi + slack, (n, m, T, lo, hi)


@pytest.mark.parametrize("n,m", CASES)
def test_against_ode_floquet_criterion(certified, n, m):
    b = certified[n]
    mf = float(m)
    lo, hi = float(b.lower), float(b.upper)
    I2 = np.eye(2)
    if n % 2 == 0:
        # closed: M = I at the (single) edge; scipy's error at rtol 1e-13 is ~1e-11 here
        assert hi - lo < 1e-25
        assert np.max(np.abs(_monodromy(mf, lo) - I2)) < 1e-9
        # every solution is periodic there: any one has 2n zeros in two periods
        assert _zeros_in_two_periods(mf, lo, [1.0, 0.0]) == 2 * n
        return
    width = hi - lo
    assert width > 0 and b.lower_enclosure[1] < b.upper_enclosure[0]  # proven open
    delta = min(1e-8 * lo, width / 4)
    for T, outside in ((lo, lo - delta), (hi, hi + delta)):
        inside = T + (delta if T == lo else -delta)
        out_tr = np.trace(_monodromy(mf, outside)) + 2
        in_tr = np.trace(_monodromy(mf, inside)) + 2
        assert out_tr > 0 > in_tr, (n, m, T, out_tr, in_tr)
        # the Floquet solution (even or odd about T/4) has 2n zeros in two periods
        M = _monodromy(mf, T)
        assert abs(np.trace(M) + 2) < 1e-8
        counts = {_zeros_in_two_periods(mf, T, y0) for y0 in ([1.0, 0.0], [0.0, 1.0])}
        assert 2 * n in counts, (n, m, T, counts)


def test_closing_theorem_matches_the_edges(certified):
    """The derived statement (analytic.smooth.sine_closings: even orders closed at every depth,
    odd orders never) against the certified edges: even widths 0 within the enclosures, odd
    widths proven positive."""
    th = sine_closings()
    assert th.even_closed and th.odd_open
    for n, _ in CASES:
        b = certified[n]
        disjoint = b.lower_enclosure[1] < b.upper_enclosure[0]
        assert disjoint == (n % 2 == 1)
