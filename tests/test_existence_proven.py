"""Existence is proven on the whole depth axis, so that it never contradicts the certified
boundary, also for narrow islands, over-damped halves (Q < 1/2) and next to closings.

References: the certified :func:`verify.solve.boundary` (an independent decision at one exact
depth: it proves the interval's edges or proves ``D < 0`` on the window); the former scan
(:func:`verify.existence.existence_scan`), whose thresholds are proven at points, for the value of
the order-3 threshold at Q = 0.3 (the issue's ``m ~ 0.938``).
"""

from __future__ import annotations

from fractions import Fraction
from functools import cache

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from analytic.system import PAPER
from verify.existence import absence_reason, existence, existence_scan
from verify.inputs import InputError
from verify.solve import boundary
from verify.timedomain import simulate


@cache
def _ex(order, Q, damping):
    return existence(order, Q, damping=damping)


def _sign_at(ex, m: Fraction):
    """+1 / -1 from the proof at m, None where undecided or inside a threshold's enclosure."""
    for lo, hi, sign in ex.segments:
        if lo <= m <= hi:
            return sign if sign != 0 else None
    return None


def test_narrow_island_is_found_and_agrees_with_boundary():
    """Was: only 0.891268... < m < 1 at Q = 2.008906, while boundary certifies an interval at
    m = 0.78366 (the island spans about 0.78349 < m < 0.78384)."""
    ex = _ex(5, "2.008906", "exact")
    assert not ex.undecided
    (a1, b1), (a2, b2) = ex.intervals
    assert 0.7834 < a1 < 0.78366 < b1 < 0.7839 and abs(float(a2) - 0.891268) < 1e-6 and b2 == 1
    assert boundary(5, "0.78366", Q="2.008906").exists
    for t in ex.thresholds:  # both sides of every end, by the certified boundary
        lo, hi = t.enclosure
        d = Fraction(1, 10**9)
        inside, outside = (hi + d, lo - d) if t.appears else (lo - d, hi + d)
        assert boundary(5, inside, Q="2.008906").exists
        assert not boundary(5, outside, Q="2.008906").exists


@pytest.mark.parametrize("order,Q,damping", [(3, "7", "exact"), (1, "10", "paper")])
def test_json_enclosure_contains_the_threshold(order, Q, damping):
    """Was: the JSON enclosure was both ends rounded to nearest at 18 digits, e.g.
    ["0.260066468682716239", "0.260066468682716239"] for order 3, Q = 7, whose threshold is
    0.2600664686827162388625... (mpmath, the Floquet tangency): a point beside it."""
    ex = _ex(order, Q, damping)
    for t, row in zip(ex.thresholds, ex.as_json()["thresholds"], strict=True):
        lo, hi = (Fraction(x) for x in row["enclosure"])
        assert lo <= t.enclosure[0] and t.enclosure[1] <= hi and lo < hi
        assert hi - lo <= Fraction(2, 10**18) * max(1, 10 * abs(lo))  # still 18 digits


@pytest.mark.parametrize(
    "order,damping", [(1, "exact"), (3, "exact"), (4, "exact"), (5, "exact"), (3, "paper")]
)
def test_overdamped_halves_q_below_half(order, damping):
    """Was: 'math domain error' for every order >= 3 with Q < 1/2 in the exact model.  Towards
    critical damping of a half and towards m -> 1 the exact model's trace form may leave narrow
    ranges undecided; they are reported, and every decided depth agrees with the certified
    boundary."""
    ex = _ex(order, "0.3", damping)
    assert ex.intervals
    checked = 0
    for k in range(1, 40):
        m = Fraction(k, 40)
        sign = _sign_at(ex, m)
        if sign is None:
            continue
        assert boundary(order, m, Q="0.3", damping=damping, digits=10).exists == (sign == 1)
        checked += 1
    assert checked >= 30
    a = ex.intervals[0][0]
    assert 0.5 < a < 1  # the interval needs a deep modulation against such friction


def test_order3_q03_threshold_value():
    """The issue: order 3 at Q = 0.3 has its threshold near m ~ 0.938 (the scan's value, proven at
    points, agrees to all 15 digits)."""
    ex = _ex(3, "0.3", "exact")
    scan = existence_scan(3, "0.3")
    assert ex.thresholds[-1].text() == scan.thresholds[-1].text()
    assert ex.thresholds[-1].text().startswith("0.93816")


def test_undecided_is_reported_not_guessed():
    """With a budget too small to decide the axis, the rest is printed as undecided."""
    ex = existence(3, 7, budget=30)
    assert ex.undecided and "undecided" in str(ex) and ex.as_json()["undecided"]


def test_reason_in_a_gap_around_a_closing():
    """Was: 'below the threshold' for m = 0.7988, which lies in the gap around the 4/5 (3:1)
    closing of order 4 at Q = 3."""
    why = absence_reason(4, Fraction("0.7988"), 3)
    assert "gap" in why and "3:1" in why and "4/5" in why and "threshold" not in why
    assert absence_reason(4, Fraction("0.3"), 3).startswith("below the threshold m = 0.559")
    with pytest.raises(InputError, match="gap"):
        simulate(4, "0.7988", Q=3, edge="lower")


def test_critical_damping_is_decided_across_the_axis():
    """Was, at Q = 1/2 (phase 2 critically damped at m -> 0): undecided for 2.4e-7 < m < 0.289
    (the tail bound's ``zeta a > 2`` held at the middle of a range with a margin of 1e-6, and
    ``a`` varies more over the range), around the threshold (0.6338 < m < 0.6348) and above
    m = 0.948 (the phases at the window's ends wider than its margin over a range).  Every depth
    away from m = 0 is now decided and agrees with the certified boundary, and the threshold
    lies between two depths 1e-13 apart that the boundary decides apart."""
    ex = _ex(1, "1/2", "exact")
    assert all(hi < Fraction(1, 10**100) for _, hi in ex.undecided)
    for m in ["1e-6", "0.1", "0.289", "0.6", "0.7", "0.95", "0.999", "0.9999999"]:
        sign = _sign_at(ex, Fraction(m))
        assert sign is not None, m
        assert boundary(1, m, Q="1/2", digits=10).exists == (sign == 1), m
    (t,) = ex.thresholds
    assert t.appears and t.text().startswith("0.6345193500009")
    assert not boundary(1, "0.6345193500009", Q="1/2", digits=20).exists
    assert boundary(1, "0.6345193500010", Q="1/2", digits=20).exists


@pytest.mark.parametrize("order,Q", [(1, "0.7"), (1, "0.3"), (2, "0.3")])
def test_the_tail_towards_one_is_decided_in_the_trace_form(order, Q):
    """Was: undecided from m = 0.99901 (order 1) or in alternate pieces from m = 0.99936 (order
    2) up to 1, where a half is over-damped (the trace form): over a range a tenth as wide as
    ``1 - m`` the phase at the window's ends is a ball a hundredth of pi wide, more than the
    window's margin.  The interval now exists up to m -> 1, as the certified boundary finds at
    depths 1e-4 to 1e-12 from 1."""
    ex = _ex(order, Q, "exact")
    assert not [r for r in ex.undecided if r[1] > Fraction(99, 100)]
    assert ex.open_to_one
    for k in (4, 7, 12):
        m = 1 - Fraction(1, 10**k)
        assert _sign_at(ex, m) == 1
        assert boundary(order, m, Q=Q, digits=10).exists


@pytest.mark.parametrize("order,Q", [(1, "3/5"), (2, "3/5"), (3, "13/20")])
def test_the_switch_to_the_trace_form_is_decided(order, Q):
    """Was: an undecided sliver ``0.436408977556109 < m < 0.43640897755611`` (order 1 and 2 at Q =
    3/5) where phase 1 comes within NEAR_CRITICAL of critical damping and the equations switch
    from the normal to the trace form: a range ending there had another form at its end than
    inside, and was split down to the resolution.  Both forms hold at that depth; the depths on
    both sides agree with the certified boundary."""
    from verify.existence import _regime_changes
    from verify.params import form_for

    Qx = Fraction(Q)
    ex = _ex(order, Q, "exact")
    d = Fraction(1, 10**9)
    switches = [
        c
        for c in _regime_changes(Qx, PAPER)
        if form_for(c - d, Qx, "exact")[0] != form_for(c + d, Qx, "exact")[0]
    ]
    assert switches
    for c in switches:
        assert not [r for r in ex.undecided if r[0] <= c <= r[1]], c
        for m in (c - d, c, c + d):
            sign = _sign_at(ex, m)
            assert sign is not None, m
            assert boundary(order, m, Q=Q, digits=10).exists == (sign == 1), m


def test_a_tiny_q_near_one_is_decided_over_ranges():
    """Was, at Q = 1/1000: undecided from m = 0.9990005 to 0.99996948 and in pieces up to the
    critical damping at m = 0.999996.  Over a range of depths the ball of half 2's ``u2 = (4 Q^2
    - 1 + m)/(1 - m)`` counted ``m`` twice and lost ``4 Q^2`` against 1, and with it ``2 - nu1 -
    nu2`` (``trace_params``); written ``4 Q^2/(1 - m) - 1`` it keeps it.  Then ``0.9990015 < m <
    0.9990692`` was left, at the threshold, where the window reaches past the double range
    (``zeta`` of some 500): the ranges there take ``D exp(-2 zeta)`` in the float stage, as a
    single depth does.  Now the threshold is proven, and the certified boundary decides the
    depths 1e-9 outside its enclosure apart; above it the interval exists up to m -> 1."""
    ex = _ex(1, "1/1000", "exact")
    assert not ex.undecided, ex.undecided
    assert ex.open_to_one
    (t,) = ex.thresholds
    lo, hi = t.enclosure
    d = Fraction(1, 10**9)
    assert Fraction(9990015, 10**7) < lo < hi < Fraction(9990692, 10**7)
    assert not boundary(1, lo - d, Q="1/1000", digits=20).exists
    assert boundary(1, hi + d, Q="1/1000", digits=20).exists
    for m in ("0.9991", "0.9995", "0.999996", "0.99999"):
        assert _sign_at(ex, Fraction(m)) == 1
        assert boundary(1, m, Q="1/1000", digits=10).exists


@pytest.mark.parametrize("order,Q", [(1, "0.501"), (2, "0.5075")])
def test_q_just_above_half_is_decided(order, Q):
    """Was, for Q just above 1/2: undecided near m -> 0 (``0 < m < 0.0015`` at Q = 0.501) or just
    below the switch to the trace form (``0.0253 < m < 0.0277`` at Q = 0.5075), where phase 1
    nears critical damping and the normal form degenerates; those ranges took the budget, and the
    threshold was left undecided too.  Such a range is now tried in the trace form as well (both
    halves under-damped), and the threshold lies between two depths 2e-9 apart that the
    certified boundary decides apart."""
    ex = _ex(order, Q, "exact")
    assert not ex.undecided, ex.undecided
    (t,) = ex.thresholds
    lo, hi = t.enclosure
    d = Fraction(1, 10**9)
    assert not boundary(order, lo - d, Q=Q, digits=20).exists
    assert boundary(order, hi + d, Q=Q, digits=20).exists
    for m in ("0.00001", "0.0014", "0.026"):
        assert _sign_at(ex, Fraction(m)) == -1
        assert not boundary(order, m, Q=Q, digits=10).exists


def test_no_threshold_is_named_next_to_an_undecided_range():
    """Was, at Q = 1/1000, m = 1/2 (then undecided at its threshold): "below the threshold m =
    0.999069213867188", a number that is only where the proven interval begins.  The reason names
    the range proven without the interval and the undecided one (torsion, D = 1/50, Q = 7, order
    1, whose interval is so thin near its threshold that the budget runs out there); where the
    threshold is proven it is named as before, also with an undecided range on the other side."""
    ex = existence(1, 7, system="torsion", duty="1/50")
    assert not ex.thresholds and ex.undecided
    why = ex.where(Fraction(1, 2))
    assert "threshold" not in why and "proven absent for 0 < m < 0.9805" in why
    assert "could not be decided (0.9805" in why
    assert (
        _ex(1, "0.3", "exact").where(Fraction(1, 2)) == "below the threshold m = 0.755565920740151"
    )
    # an undecided range below (m -> 0 at Q = 1/2) leaves the proven threshold above as it is
    assert (
        _ex(1, "1/2", "exact").where(Fraction(1, 2)) == "below the threshold m = 0.634519350000923"
    )


CASES = [
    (3, "7", "exact"),
    (3, "7", "paper"),
    (4, "3", "exact"),
    (5, "2.008906", "exact"),
    (5, "2.0089", "exact"),  # near the birth of the island (it exists above Q ~ 2.0088)
    (3, "0.3", "exact"),
    (1, "5", "paper"),
    (1, "1/2", "exact"),  # critical damping of phase 2 at m -> 0
    (2, "0.7", "exact"),
]


@settings(
    max_examples=40,
    derandomize=True,
    deadline=None,
    suppress_health_check=[HealthCheck.too_slow],
)
@given(
    case=st.sampled_from(CASES),
    m=st.fractions(min_value=Fraction(1, 100), max_value=Fraction(99, 100), max_denominator=10**6),
)
def test_existence_and_boundary_never_disagree(case, m):
    order, Q, damping = case
    ex = _ex(order, Q, damping)
    sign = _sign_at(ex, m)
    if sign is None:  # an undecided sliver or a threshold's enclosure: nothing is claimed
        return
    assert boundary(order, m, Q=Q, damping=damping, digits=10).exists == (sign == 1)


@pytest.mark.parametrize("m", ["0.78350", "0.78360", "0.78370", "0.78380", "0.78345", "0.78390"])
def test_island_points_agree(m):
    """Depths across the narrow island of order 5 at Q = 2.008906."""
    ex = _ex(5, "2.008906", "exact")
    sign = _sign_at(ex, Fraction(m))
    assert sign is not None
    assert boundary(5, m, Q="2.008906").exists == (sign == 1)
