"""Properties over random depths and orders (hypothesis, fixed derandomised seed).

Independent checks of what the certified solver returns: inside the interval the Floquet route
(:mod:`verify.floquet`, built without the normal form) finds growth, just outside it does not, and
the edges lie on either side of exact tuning only where the theory says so.
"""

from fractions import Fraction

import mpmath
from hypothesis import given, settings
from hypothesis import strategies as st

from verify import boundary
from verify.floquet import growth_factor
from verify.inputs import as_depth

SETTINGS = settings(max_examples=30, deadline=None, derandomize=True)
depths = st.fractions(min_value=Fraction(1, 1000), max_value=Fraction(99, 100))
orders = st.integers(min_value=1, max_value=8)


@SETTINGS
@given(n=orders, m=depths)
def test_unstable_inside_stable_outside(n, m):
    """Growth factor > 1 at the middle of the interval, = 1 (to rounding) just outside both edges
    (no friction: outside, both multipliers lie on the unit circle)."""
    b = boundary(n, m, digits=30)
    lo, hi = b.lower, b.upper
    with mpmath.workdps(40):
        width = hi - lo
        if width < mpmath.mpf(10) ** -20:  # a closing depth: nothing inside
            return
        mid = (lo + hi) / 2
        g_in = growth_factor(m, mid, None, dps=40)
        assert g_in > 1 + width**2 / 100, (n, m, g_in)
        eps = width * mpmath.mpf(10) ** -6
        for T in (lo - eps, hi + eps):
            g_out = growth_factor(m, T, None, dps=40)
            assert abs(g_out - 1) < mpmath.mpf(10) ** -25, (n, m, T, g_out)


@SETTINGS
@given(n=orders, m=depths)
def test_edges_order_and_offsets(n, m):
    """lower <= upper; the offsets T - n T_av/2 are the differences they claim to be."""
    b = boundary(n, m, digits=25)
    assert b.lower <= b.upper
    with mpmath.workdps(40):
        # T_av/T0 from eq. (5), computed here independently of the solver
        mm = mpmath.mpf(m.numerator) / m.denominator
        tav = 2 / (1 / mpmath.sqrt(1 + mm) + 1 / mpmath.sqrt(1 - mm))
        for T, d in ((b.lower, b.delta_lower), (b.upper, b.delta_upper)):
            assert abs((T - n * tav / 2) - d) <= mpmath.mpf(10) ** -22 * max(1, abs(T))


@settings(max_examples=200, deadline=None, derandomize=True)
@given(m=st.fractions(min_value=Fraction(1, 10**15), max_value=1 - Fraction(1, 10**15)))
def test_depth_text_is_exact(m):
    """A depth written as p/q is read back exactly."""
    if 0 < m < 1:
        assert as_depth(f"{m.numerator}/{m.denominator}") == m
