"""Where the intervals exist with friction.

References: the paper's Fig. 8 text (Q = 7: the third-order region vanishes above about 48 % depth
and returns above about 66 %); the paper's small-m thresholds m_min = pi/(6Q) (eq. 38, order 1) and
m_min = sqrt(2/(3Q)) (eq. 43, order 2), leading terms for large Q; and the certified
:func:`verify.solve.boundary`, which must agree with every range on both sides of each end.
"""

from __future__ import annotations

import math
from fractions import Fraction

import mpmath
import pytest

from verify.existence import closing_depths, existence
from verify.inputs import InputError
from verify.solve import boundary


@pytest.mark.parametrize("damping", ["paper", "exact"])
def test_q7_third_order_island(damping):
    ex = existence(3, 7, damping=damping, digits=15)
    (a1, b1), (a2, b2) = ex.intervals
    assert b2 == 1 and ex.open_to_one
    assert abs(float(b1) - 0.48) < 0.01  # "disappears above about 48 %"
    assert abs(float(a2) - 0.66) < 0.01  # "returns above about 66 %"
    assert a1 < b1 < mpmath.mpf(3) / 5 < a2  # the gap holds the closing m = 3/5
    # both sides of every end, by the certified boundary
    for t in ex.thresholds:
        lo, hi = t.enclosure
        d = Fraction(1, 10**9)
        inside, outside = (hi + d, lo - d) if t.appears else (lo - d, hi + d)
        assert boundary(3, inside, Q=7, damping=damping, digits=15).exists
        assert not boundary(3, outside, Q=7, damping=damping, digits=15).exists
    data = ex.as_json()
    assert data["intervals"][-1][1] == "1" and data["order"] == 3 and data["damping"] == damping


def test_models_differ_and_both_reported():
    p = existence(3, 7, damping="paper").intervals
    e = existence(3, 7, damping="exact").intervals
    assert abs(float(p[0][1]) - float(e[0][1])) > 1e-3  # the two models give different ends


@pytest.mark.parametrize("Q", [50, 200])
def test_small_depth_thresholds_eqs_38_43(Q):
    """m_min -> pi/(6Q) (order 1) and sqrt(2/(3Q)) (order 2) as Q grows (relative 3/Q-ish)."""
    m1 = float(existence(1, Q, damping="paper").intervals[0][0])
    m2 = float(existence(2, Q, damping="paper").intervals[0][0])
    assert abs(m1 / (math.pi / (6 * Q)) - 1) < 5 / Q
    assert abs(m2 / math.sqrt(2 / (3 * Q)) - 1) < 0.2


def test_digits_and_enclosures():
    ex = existence(1, 5, damping="exact", digits=40)
    (t,) = ex.thresholds
    lo, hi = t.enclosure
    assert hi - lo <= Fraction(1, 10**40) * hi
    with mpmath.workdps(60):
        assert (
            mpmath.mpf(lo.numerator) / lo.denominator
            <= t.value
            <= mpmath.mpf(hi.numerator) / hi.denominator
        )
    assert len(t.text().replace("0.", "").lstrip("0")) == 40


def test_closing_depths():
    assert closing_depths(3, None, "paper") == [0.6]
    assert sorted(closing_depths(5, 7, "paper")) == pytest.approx([5 / 13, 15 / 17])
    # exact model: the damped frequencies close at a slightly different depth
    (mc,) = closing_depths(3, Fraction(7), "exact")
    assert 0.59 < mc < 0.61 and mc != 0.6


def test_bad_input():
    with pytest.raises(InputError):
        existence(3, None)
    with pytest.raises(InputError):
        existence(0, 7)
    with pytest.raises(InputError):
        existence(3, 7, damping="none")


def test_range_ends_rounded_inwards():
    """An end of a range that is not a threshold (it borders an undecided range) is an exact
    rational: printed, a range where the interval exists lies inside the proven one and an
    undecided range holds the undecided one (65471/65536 = 0.9990081787109375, 15 digits)."""
    from verify.existence import Existence

    lo, mid, hi = Fraction(3, 4), Fraction(65471, 65536), Fraction(2**20 - 1, 2**20)
    e = Existence(
        1,
        Fraction(1, 20),
        "exact",
        15,
        (),
        False,
        undecided=((Fraction(1, 2), lo), (mid, hi)),
        segments=(
            (Fraction(0), Fraction(1, 2), -1),
            (Fraction(1, 2), lo, 0),
            (lo, mid, 1),
            (mid, hi, 0),
            (hi, Fraction(1), -1),
        ),
    )
    assert e.interval_texts() == [["0.75", "0.999008178710937"]]
    assert e.undecided_texts() == [["0.5", "0.75"], ["0.999008178710937", "0.999999046325684"]]
    for a, b in e.interval_texts():
        assert lo <= Fraction(a) and Fraction(b) <= mid
    assert "0.999008178710937 < m < 0.999999046325684" in e.where(Fraction(999999, 10**6))


#: narrow ranges next to m = 1, each narrower than 15 digits resolve
_A1, _B1 = 1 - Fraction(1, 2**51), 1 - Fraction(1, 2**52)  # 1 - 4.4e-16 .. 1 - 2.2e-16
_A2, _B2 = 1 - Fraction(3, 2**50), 1 - Fraction(5, 2**51)  # both print 0.999999999999997


def _narrow_ranges_next_to_one():
    """Order 1 at ``Q = 7`` proven to exist in the two narrow ranges (``_A2, _B2``) and (``_A1,
    _B1``) next to m = 1, proven not to exist below 1/2, and undecided between and beside them
    (as torsion at D = 1/50 leaves them, whose closings crowd towards m = 1)."""
    from verify.existence import Existence

    return Existence(
        1,
        Fraction(7),
        "exact",
        15,
        (),
        False,
        undecided=((Fraction(1, 2), _A2), (_B2, _A1), (_B1, Fraction(1))),
        segments=(
            (Fraction(0), Fraction(1, 2), -1),
            (Fraction(1, 2), _A2, 0),
            (_A2, _B2, 1),
            (_B2, _A1, 0),
            (_A1, _B1, 1),
            (_B1, Fraction(1), 0),
        ),
    )


def test_a_range_narrower_than_the_digits_prints_in_order():
    """Ranges next to m = 1 between gaps (e.g. torsion at D = 1/50, whose closings crowd towards
    m = 1) can be narrower than 15 digits resolve: rounded inwards at 15 digits the first would
    print as ``1 < m < 0.999999999999999`` and the second as ``0.999999999999997 < m <
    0.999999999999997``.  Each prints with as many more digits as it takes for its start to lie
    below its end, still inside the proven range."""
    e = _narrow_ranges_next_to_one()
    texts = e.interval_texts()
    assert len(texts) == 2
    for (a, b), (lo, hi) in zip(texts, ((_A2, _B2), (_A1, _B1)), strict=True):
        assert lo <= Fraction(a) < Fraction(b) <= hi, (a, b)
    assert texts[0] == ["0.9999999999999974", "0.9999999999999977"]
    assert all(len(t.replace("0.", "", 1)) <= 17 for pair in texts for t in pair)
    for a, b in e.interval_texts():
        assert f"{a} < m < {b}" in str(e)


def test_a_narrow_range_from_a_threshold_prints_in_order():
    """A range from a proven threshold to an undecided range (or the other way) narrower than
    15 digits resolve: the threshold prints its proven digits and the rational end takes more
    digits until the start prints below the end (was ``0.999999999999999 < m <
    0.999999999999999`` and ``0.500000000000000 < m < 0.5``), still rounded inwards."""
    import mpmath

    from verify.existence import Existence, Threshold, _mpf

    u, half = Fraction(1, 2**53), Fraction(1, 2)
    cases = (
        (1 - 6 * u - Fraction(1, 2**60), 1 - 6 * u, 1 - 5 * u),
        (half - Fraction(1, 10**18), half, half + Fraction(3, 10**17)),
    )
    with mpmath.workprec(200):
        for tlo, thi, b in cases:
            t = Threshold(_mpf((tlo + thi) / 2), (tlo, thi), True, 15)
            e = Existence(
                1,
                Fraction(7),
                "exact",
                15,
                (t,),
                False,
                undecided=((b, Fraction(1)),),
                segments=((Fraction(0), tlo, -1), (tlo, thi, 0), (thi, b, 1), (b, Fraction(1), 0)),
            )
            ((ta, tb),) = e.interval_texts()
            assert ta == t.text()
            assert Fraction(ta) < Fraction(tb) <= b, (ta, tb)
            assert f"{ta} < m < {tb}" in str(e)
            assert e.as_json()["intervals"] == [[ta, tb]]


def test_an_undecided_range_prints_within_the_ranges_beside_it():
    """Undecided ranges between the narrow proven ranges next to m = 1 (the case above): rounded
    outwards at 15 digits, the one between them would print as ``0.999999999999997 < m < 1``, over
    both proven ranges beside it.  Each undecided range prints with as many more digits as keep its
    rounding within the ranges beside it, still holding the undecided range; a wide one keeps 15."""
    e = _narrow_ranges_next_to_one()
    texts = e.undecided_texts()
    assert texts == [
        ["0.5", "0.9999999999999974"],
        ["0.9999999999999977", "0.9999999999999996"],
        ["0.9999999999999997", "1"],
    ]
    for (a, b), (lo, hi) in zip(texts, e.undecided, strict=True):
        assert Fraction(a) <= lo and hi <= Fraction(b)  # the undecided range held
    # none covers a proven range printed beside it
    for (a, b), (pa, pb) in zip(texts[1:], e.interval_texts(), strict=False):
        assert not (Fraction(a) <= Fraction(pa) and Fraction(pb) <= Fraction(b))
    assert "0.9999999999999977 < m < 0.9999999999999996" in str(e)
    where = e.where(1 - Fraction(1, 2**50))
    assert "0.9999999999999977 < m < 0.9999999999999996" in where
