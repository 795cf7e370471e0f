"""The fast formatting of proven decimals (:func:`verify.result.proven_text`, the error bound of a
:class:`verify.result.Boundary`, :func:`verify.rounding.printed_bound`) writes exactly the text
of the general formulation kept here as the reference: ``mpmath.nstr`` on the estimate of usable
digits, and the bound of the print in :class:`fractions.Fraction` arithmetic, rounded up.  Random
cases at many precisions and exponents, with ties (a digit 5 after the last printed), runs of
nines (the rounding carries into a new power of ten) and ratios value/radius next to powers of
ten (where the digit count is decided exactly)."""

from __future__ import annotations

import dataclasses
import math
import random
import sys
from fractions import Fraction

import mpmath
import pytest
from mpmath.libmp import from_man_exp

from verify.result import proven_text
from verify.rounding import bound_text, printed_bound, printed_error
from verify.solve import boundary

_LOG10_2 = math.log10(2)


def _log10_abs(v) -> float:
    _, man, exp, bc = v._mpf_
    top = man >> (bc - 53) if bc > 53 else man
    return (exp + bc - min(bc, 53) + math.log2(top)) * _LOG10_2


def reference_text(x, rad, digits: int) -> str:
    """The formatting as first written (mpmath's comparisons and ``nstr``)."""
    if rad is None or rad == 0 or x == 0:
        return mpmath.nstr(x, digits, strip_zeros=False) if x != 0 or rad is None else "0"
    est = _log10_abs(x) - _log10_abs(rad) - _LOG10_2
    usable = math.floor(est)
    if abs(est - round(est)) < 1e-6:
        with mpmath.workdps(20):
            ratio = abs(x) / (2 * rad)
            usable = int(mpmath.floor(mpmath.log10(ratio))) if ratio >= 1 else 0
    if usable < 1:
        return "0"
    return mpmath.nstr(x, min(digits, usable), strip_zeros=False)


def reference_bound(bound: Fraction, digits: int = 2) -> str:
    """The bound rounded up, in Fraction arithmetic, as first written."""
    if bound == 0:
        return "0"
    limit = sys.get_int_max_str_digits()
    sys.set_int_max_str_digits(0)  # tiny radii: integers of many thousand digits
    try:
        e = len(str(bound.numerator)) - len(str(bound.denominator))
    finally:
        sys.set_int_max_str_digits(limit)
    while Fraction(10) ** e > bound:
        e -= 1
    while Fraction(10) ** (e + 1) <= bound:
        e += 1
    scale = Fraction(10) ** (digits - 1 - e)
    mant = -((-bound * scale.numerator) // scale.denominator)
    if mant >= 10**digits:
        mant //= 10
        e += 1
    head = str(mant)
    return f"{head[0]}.{head[1:]}e{e}" if digits > 1 else f"{head}e{e}"


def reference_error(text: str, x, radius) -> Fraction:
    sign, man, exp, _ = x._mpf_
    xs = (-1 if sign else 1) * Fraction(man) * Fraction(2) ** exp
    _, rm, re, _ = radius._mpf_
    return abs(Fraction(text) - xs) + Fraction(rm) * Fraction(2) ** re


def _mpf(man: int, exp: int) -> mpmath.mpf:
    """The exact number ``man 2**exp`` (no rounding to the working precision)."""
    v = mpmath.mpf(0)
    v._mpf_ = from_man_exp(man, exp)
    return v


def _cases(seed: int, n: int):
    rng = random.Random(seed)
    for _ in range(n):
        bits = rng.choice([53, 120, 200, 400, 1200])
        kind = rng.random()
        if kind < 0.15:  # runs of nines, powers of ten and ties in decimal
            d = rng.randint(1, 70)
            man = rng.choice([10**d - 1, 10**d, 10**d + 1, 5 * 10**d, 5 * 10**d - 1, 25 * 10**d])
            exp = rng.randint(-300, 50)
        else:
            man = rng.getrandbits(bits) | 1
            exp = rng.randint(-bits - 300, 300) if kind < 0.97 else rng.randint(-12000, 12000)
        # (exponents beyond +-3500 bits take mpmath's own path; within the reference's reach)
        x = _mpf(-man if rng.random() < 0.5 else man, exp)
        if rng.random() < 0.15:  # |x| / (2 rad) next to a power of ten
            p = rng.randint(0, 60)
            with mpmath.workdps(80):
                r = abs(x) / (2 * mpmath.mpf(10) ** p)
                r = r * (1 + mpmath.mpf(rng.choice([-1, 0, 1])) * mpmath.mpf(2) ** -70)
            rad = _mpf(*_man_exp(r))
        else:
            rbits = rng.choice([10, 30, 53, 64])
            rad = _mpf(rng.getrandbits(rbits) | 1, exp + bc_of(man) - rbits - rng.randint(0, 260))
        yield x, rad, rng.choice([1, 2, 3, 5, 15, 20, 50, 100, rng.randint(1, 120)])


def bc_of(man: int) -> int:
    return man.bit_length()


def _man_exp(v):
    sign, man, exp, _ = v._mpf_
    return (-man if sign else man), exp


def test_proven_text_and_bound_as_before():
    checked = ties = 0
    for x, rad, digits in _cases(14, 6000):
        text = proven_text(x, rad, digits)
        assert text == reference_text(x, rad, digits), (x._mpf_, rad._mpf_, digits)
        ref = reference_error(text, x, rad)
        assert printed_error(text, x, rad) == ref
        assert bound_text(ref) == reference_bound(ref)
        assert printed_bound([(text, x, rad)]) == reference_bound(ref)
        checked += 1
        ties += text.rstrip("0").endswith("5")
    assert checked == 6000 and ties > 100


@pytest.mark.parametrize("digits", [1, 2, 3])
def test_bound_text_as_before(digits):
    rng = random.Random(digits)
    for _ in range(3000):
        num = rng.choice([rng.getrandbits(rng.randint(1, 300)), 10 ** rng.randint(0, 60)])
        num += rng.choice([-1, 0, 0, 1]) if num > 1 else 0
        den = rng.choice(
            [10 ** rng.randint(0, 80), 2 ** rng.randint(0, 300), rng.randint(1, 10**9)]
        )
        b = Fraction(num, den)
        assert bound_text(b, digits) == reference_bound(b, digits), (num, den)


def test_largest_of_several_as_before():
    cases = list(_cases(5, 800))
    for i in range(0, len(cases), 4):
        items = [(proven_text(x, r, d), x, r) for x, r, d in cases[i : i + 4]]
        assert printed_bound(items) == reference_bound(max(reference_error(*it) for it in items))
    assert printed_bound([(None, None, None)]) is None


@pytest.mark.parametrize("m", ["1/20", "3/10", "3/5", "9/10"])
@pytest.mark.parametrize("digits", [15, 50])
def test_boundary_rows_as_before(m, digits):
    """A table row: the four decimals and the bound of the print, as the reference writes them."""
    b = boundary(3, m, digits=digits)
    j = dataclasses.replace(b).as_json()
    values = (b.lower, b.upper, b.delta_lower, b.delta_upper)
    keys = ("lower", "upper", "delta_lower", "delta_upper")
    texts = [reference_text(x, b.radii[k], digits) for k, x in enumerate(values)]
    assert [j[k] for k in keys] == texts
    assert j["error_bound"] == reference_bound(
        max(
            reference_error(t, x, b.radii[k])
            for k, (t, x) in enumerate(zip(texts, values, strict=True))
        )
    )
    assert j["radius"] == mpmath.nstr(b.radius, 3)


def test_radius_text_as_before():
    from verify.result import _radius_text

    for x, rad, _ in _cases(21, 2000):
        assert _radius_text(rad) == mpmath.nstr(rad, 3)
        assert _radius_text(x) == mpmath.nstr(x, 3)
    assert _radius_text(mpmath.mpf(0)) == mpmath.nstr(mpmath.mpf(0), 3)
    assert _radius_text(mpmath.mpf("0.5")) == "0.5"
