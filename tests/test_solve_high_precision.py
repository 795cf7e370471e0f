"""Certified edges at 20000 and 100000 digits, against independent computations.

References:

* 20000 digits: the Floquet route (:func:`verify.floquet.monodromy_matrix`, the monodromy built
  from the segment solutions and the jumps, no sympy, no per-edge equation), its edge condition
  ``tr M = -2`` (odd order), which must change sign across each certified edge widened by a
  relative ``1e-20000`` (evaluated at 20040 digits);
* 100000 digits: the 20000-digit result (its first digits and its enclosure), so the two runs
  must be consistent: the 100000-digit enclosure lies inside the 20000-digit one.
"""

from __future__ import annotations

import mpmath
import pytest

from verify.floquet import monodromy_matrix
from verify.inputs import InputError
from verify.solve import boundary

M = "3/10"


@pytest.fixture(scope="module")
def edges_20000():
    return boundary(3, M, digits=20000)


def test_20000_digits_agree_with_the_floquet_route(edges_20000):
    b = edges_20000
    assert b.radius < mpmath.mpf(10) ** -20000
    with mpmath.workdps(20040):
        eps = mpmath.mpf(10) ** -20000
        for T, enc in ((b.lower, b.lower_enclosure), (b.upper, b.upper_enclosure)):
            # the Floquet route's edge condition tr M + 2 changes sign across T (1 -+ 1e-20000):
            # it has a root there, within the printed digits of the certified edge
            left, right = (trace_plus_two(T * (1 - eps)), trace_plus_two(T * (1 + eps)))
            assert left * right < 0, (mpmath.nstr(left, 5), mpmath.nstr(right, 5))
            assert T * (1 - eps) < enc[0] <= enc[1] < T * (1 + eps)


def trace_plus_two(T):
    """``tr M + 2`` of the Floquet route at ``T/T0 = T`` (at the current mpmath precision)."""
    Mx = monodromy_matrix(M, T)
    return Mx[0, 0] + Mx[1, 1] + 2


def test_100000_digits_contain_the_20000_digit_edges(edges_20000):
    b = boundary(3, M, digits=100000)
    assert b.radius < mpmath.mpf(10) ** -100000
    for k, (x20, x100) in enumerate(((edges_20000.lower, b.lower), (edges_20000.upper, b.upper))):
        with mpmath.workdps(20010):
            assert abs(x100 - x20) <= edges_20000.radius, k
        enc20 = (edges_20000.lower_enclosure, edges_20000.upper_enclosure)[k]
        enc100 = (b.lower_enclosure, b.upper_enclosure)[k]
        with mpmath.workdps(100020):
            assert enc20[0] <= enc100[0] <= enc100[1] <= enc20[1], k
    # the printed digits: the first 20000 of the 100000-digit value are the 20000-digit value's
    # unless that one ends in a run of 9s or 0s (rounding); checked on the text
    t20 = mpmath.nstr(edges_20000.upper, 19990, strip_zeros=False)
    with mpmath.workdps(100010):
        t100 = mpmath.nstr(b.upper, 19990, strip_zeros=False)
    assert t20 == t100


def test_above_the_limit_is_refused_naming_the_range():
    with pytest.raises(InputError, match="100000"):
        boundary(3, M, digits=100001)
