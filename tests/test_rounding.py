"""Honest bounds: the error printed beside a certified number bounds the number *as printed*
(rounding included), not the internal ball.  References: the exact value of the closing
T = 2 sqrt(2/5) (the closing theorem at m = 3/5, order 3; ``paramres crossings``) and mpmath at
200 digits for order 1 at m = 3/10."""

from __future__ import annotations

from fractions import Fraction

import mpmath
import pytest

from verify.rounding import bound_text, exact, printed_error
from verify.solve import boundary


def test_bound_text_rounds_up():
    assert bound_text(Fraction(34, 10**6)) == "3.4e-5"
    assert bound_text(Fraction(341, 10**7)) == "3.5e-5"
    assert bound_text(Fraction(999, 10**4)) == "1.0e-1"
    assert bound_text(Fraction(1, 3)) == "3.4e-1"
    assert bound_text(Fraction(0)) == "0"
    for b in (Fraction(1, 7), Fraction(10**40 + 1, 10**80), Fraction(5, 10**103)):
        assert Fraction(bound_text(b)) >= b


def test_exact_keeps_the_sign():
    assert exact(mpmath.mpf("-0.5")) == Fraction(-1, 2)


@pytest.mark.parametrize("digits", [10, 20, 40])
def test_printed_bound_covers_the_printed_digits(digits):
    b = boundary(3, "3/5", digits=digits)
    printed = Fraction(b.as_json()["lower"])
    with mpmath.workdps(200):
        reference = 2 * mpmath.sqrt(mpmath.mpf(2) / 5)  # the closing period, exactly 2 sqrt(2/5)
        err = abs(mpmath.mpf(printed.numerator) / printed.denominator - reference)
        bound = Fraction(b.error_bound())
        assert err <= mpmath.mpf(bound.numerator) / bound.denominator
    # and it is the bound of what is printed: no smaller than the rounding of the last digit
    # can make it (the old text printed the internal radius, 5.0e-103 under 40 digits)
    assert bound > Fraction(1, 10 ** (digits + 3))
    assert bound < Fraction(1, 10 ** (digits - 2))
    assert f"|printed - exact| < {b.error_bound()}" in str(b)


def test_printed_error_formula():
    x = mpmath.mpf(1) / 3
    assert printed_error("0.3333", x, 0) == abs(Fraction("0.3333") - exact(x))
    assert printed_error(None, x, 0) is None and printed_error("1", x, None) is None


def test_repr_shows_every_certified_digit():
    b = boundary(3, "0.3", digits=50)
    text = repr(b)
    assert b.as_json()["lower"] in text and b.as_json()["upper"] in text
    assert len(b.as_json()["lower"].replace(".", "").lstrip("0")) == 50
    assert "<pre>" in b._repr_html_()
