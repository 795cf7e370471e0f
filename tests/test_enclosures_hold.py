"""Every certified edge lies in its own enclosure, and the enclosure is as tight as the radius.

The enclosures are the proven ``(low, high)`` bounds of each edge (:class:`verify.result.Boundary`);
they are the balls' exact ends (:func:`verify.result.from_balls`), never the midpoint plus
or minus the radius rounded to the ambient mpmath precision (which, at 53 bits, collapsed a
30-digit enclosure to one point beside the edge)."""

from fractions import Fraction

import mpmath
import pytest

from verify.certified import boundary
from verify.ramp import ramp_boundary
from verify.smooth import sine_boundary

M = Fraction(1, 10)

CASES = {
    "square wave": lambda: boundary(1, M, digits=30),
    "sine": lambda: sine_boundary(1, M, digits=30),
    "ramp": lambda: ramp_boundary(1, M, Fraction(1, 100), digits=30).boundary,
}


@pytest.mark.parametrize("name", sorted(CASES))
def test_edge_lies_in_its_enclosure(name):
    b = CASES[name]()
    assert b.certified and b.exists
    for value, (lo, hi) in ((b.lower, b.lower_enclosure), (b.upper, b.upper_enclosure)):
        # exact differences: no rounding to the mpmath context
        assert mpmath.fsub(lo, value, exact=True) <= 0 <= mpmath.fsub(hi, value, exact=True)
        assert 0 < mpmath.fsub(hi, lo, exact=True) <= 2 * b.radius
