"""Proven existence with friction for the other members of the family and other duties.

References: the Floquet route (:mod:`verify.floquet`, the period map multiplied from the segment
maps and switches, no sympy): the threshold is where ``det(M - sigma I)`` has a double root in ``T``
(``tests/floquet_tangency.py``, mpmath at 40 digits), and the growth factor ``max|mu|`` at the
interval's centre is above 1 inside a proven range and below 1 in a proven gap.  The closings are
those of :func:`analytic.closings.closings` (proven there), the regime changes ``omega_i^2 =
gamma^2`` the system's laws solved by hand in each test.
"""

from __future__ import annotations

import json
from fractions import Fraction

import mpmath
import pytest
from cli_run import run_cli as run
from floquet_tangency import peak_growth, tangency

from analytic.closings import closings
from analytic.system import system
from verify.existence import closing_depths, existence
from verify.floquet import growth_factor
from verify.inputs import InputError
from verify.params import NEAR_CRITICAL
from verify.solve import boundary


def _centre(n, m, Q, sysv, damping):
    """The middle of the interval at depth ``m`` (certified edges), a start for ``peak_growth``."""
    b = boundary(n, m, Q=Q, damping=damping, system=sysv, digits=15)
    assert b.exists
    return (b.lower + b.upper) / 2


def _above(t, rel=1e-4) -> Fraction:
    """A rational depth just inside the range that the threshold ``t`` opens or closes."""
    return Fraction(mpmath.nstr(t.value * (1 + rel if t.appears else 1 - rel), 20))


@pytest.mark.parametrize(
    "name, duty, n, Q, damping",
    [
        ("torsion", "1/2", 1, 7, "exact"),
        ("meissner", "1/3", 1, 7, "paper"),
        ("pendulum", "1/3", 1, 7, "exact"),
        ("pendulum", "98/100", 1, 7, "paper"),  # extreme duty
        ("torsion", "1/3", 2, 40, "paper"),
        # thresholds where a phase is over-damped (the trace form over depth ranges)
        ("pendulum", "1/3", 1, "3/5", "exact"),
        ("torsion", "1/2", 2, "3/5", "exact"),
        ("torsion", "1/3", 1, "3/5", "exact"),
    ],
)
def test_threshold_agrees_with_the_floquet_tangency(name, duty, n, Q, damping):
    sysv = system(name, duty=duty)
    ex = existence(n, Q, system=sysv, damping=damping, digits=15)
    assert not ex.undecided
    th = ex.thresholds[0]
    assert th.appears
    T_start = _centre(n, _above(th), Q, sysv, damping)
    m_ref, _T = tangency(n, Q, th.value, T_start, system=name, duty=duty, damping=damping)
    ref = Fraction(mpmath.nstr(m_ref, 30))
    lo, hi = th.enclosure
    # the proven enclosure holds the independent tangency (good to about 30 digits)
    assert lo - ref < Fraction(1, 10**25) and ref - hi < Fraction(1, 10**25)
    assert abs(th.value - m_ref) < 1e-14 * m_ref


def test_gap_around_a_closing_at_extreme_duty():
    """Torsion, D = 0.98, order 2: the interval closes at m = 1200/1201 (phase 1 turns through pi,
    phase 2 through pi); with Q = 20 friction swallows it there, and the proven gap holds that
    depth, the Floquet growth below 1 in the gap and above 1 on both sides."""
    sysv = system("torsion", duty="0.98")
    (closing,) = closings(2, sysv).of_order(2)
    assert (closing.a, closing.b, closing.m) == (1, 1, Fraction(1200, 1201))
    ex = existence(2, 20, system=sysv, damping="exact", digits=15)
    assert not ex.undecided
    (a1, b1), (a2, b2) = ex.intervals
    mc = mpmath.mpf(1200) / 1201
    assert a1 < b1 < mc < a2 < b2 == 1
    why = ex.where(Fraction(1200, 1201))
    assert "gap" in why and "closing" in why
    # the exact model closes a little off the friction-free depth: in the gap too
    (mq,) = closing_depths(2, Fraction(20), "exact", sysv)
    assert b1 < mq < a2
    for m, above in (((a1 + b1) / 2, True), (mc, False), ((a2 + 1) / 2, True)):
        mm = Fraction(mpmath.nstr(m, 20))
        T0 = 1 / (Fraction(49, 50) * 1 / (1 + mm) ** 0.5 + Fraction(1, 50) / (1 - mm) ** 0.5)
        start = _centre(2, mm, 20, sysv, "exact") if above else float(T0)
        growth, _ = peak_growth(2, 20, mm, start, system="torsion", duty="0.98")
        assert (growth > 1) == above, (m, growth)


def test_closing_gap_at_duty_one_third():
    """Pendulum, D = 1/3, order 4 (paper model, Q = 50): the closing a = 1, b = 3 at m = 5/13
    (omega_1 T/3 = pi, 2 omega_2 T/3 = 3 pi) opens a gap; its ends are proven thresholds."""
    sysv = system("pendulum", duty="1/3")
    assert [c.m for c in closings(4, sysv).of_order(4)] == [Fraction(5, 13)]
    ex = existence(4, 50, system=sysv, damping="paper", digits=15)
    assert not ex.undecided
    (a1, b1), (a2, b2) = ex.intervals
    assert b1 < mpmath.mpf(5) / 13 < a2 and b2 == 1
    assert len(ex.thresholds) == 3
    for t in ex.thresholds:  # every end at the Floquet tangency
        T = _centre(4, _above(t), 50, sysv, "paper")
        m_ref, _ = tangency(4, 50, t.value, T, system="pendulum", duty="1/3", damping="paper")
        assert abs(t.value - m_ref) < 1e-14 * m_ref


def test_meissner_past_critical_damping_of_phase_one():
    """Meissner, exact model, Q = 7: phase 1 (omega_1^2 = 1 - m) is critically damped at
    1 - m = 1/(4 Q^2), i.e. m = 195/196, and the trace form takes over where omega_1^2 <
    gamma^2 (1 + NEAR_CRITICAL^2).  The trace form's parameters over a range of depths are
    derived for every member: the whole axis is decided, the interval exists from its threshold
    up to m -> 1, and the Floquet growth is above 1 on both sides of the critical depth and
    past it (phase 1 over-damped)."""
    ex = existence(1, 7, system="meissner", damping="exact", digits=15)
    eps2 = Fraction(NEAR_CRITICAL) ** 2
    cut = 1 - Fraction(1, 196) * (1 + eps2)  # omega_1^2 = gamma^2 (1 + eps^2)
    assert cut < Fraction(195, 196)
    assert not ex.undecided
    ((a, b),) = ex.intervals
    assert 0.2 < a < 0.25 and b == 1
    assert [seg[2] for seg in ex.segments] == [-1, 0, 1]  # the threshold between
    assert len(ex.thresholds) == 1
    sysv = system("meissner")
    for mm in (cut + Fraction(1, 10**6), Fraction(195, 196), Fraction(998, 1000)):
        assert ex.where(mm) == "exists", ex.where(mm)
        growth, _ = peak_growth(1, 7, mm, _centre(1, mm, 7, sysv, "exact"), system="meissner")
        assert growth > 1, (mm, growth)


def test_critical_damping_of_phase_one_at_duty_one_third():
    """Pendulum, D = 1/3, Q = 0.6, exact model: phase 1 (omega_1^2 = 1/(1+m)) is critically damped
    at m = 4 Q^2 - 1 = 0.44, and over-damped above it.  The whole axis is decided: no interval
    below the threshold (which lies in the over-damped range, at the Floquet tangency:
    :func:`test_threshold_agrees_with_the_floquet_tangency`), the interval above it up to
    m -> 1; the Floquet growth agrees on both sides of the critical depth."""
    ex = existence(1, "0.6", system=system("pendulum", duty="1/3"), damping="exact")
    assert not ex.undecided
    ((a, b),) = ex.intervals
    assert 0.44 < a < 0.7 and b == 1
    assert [s[2] for s in ex.segments] == [-1, 0, 1]  # the threshold between
    assert len(ex.thresholds) == 1
    sysv = system("pendulum", duty="1/3")
    Q = Fraction(3, 5)
    mm = Fraction(9, 10)
    T = _centre(1, mm, Q, sysv, "exact")
    assert growth_factor(mm, T, Q, "exact", system="pendulum", duty="1/3", dps=30) > 1
    for mm in (Fraction(11, 25), Fraction(1, 2)):  # at the critical depth and past it: no interval
        assert ex.where(mm) != "exists"
        # T_1 = T_av/2 (T/T0 units): the growth below 1 over the whole neighbourhood of T_1
        T1 = 1 / (2 * (Fraction(1, 3) / (1 + mm) ** 0.5 + Fraction(2, 3) / (1 - mm) ** 0.5))
        for j in range(1, 60):
            T = T1 * j / 30
            g = growth_factor(mm, T, Q, "exact", system="pendulum", duty="1/3", dps=20)
            assert g < 1, (mm, T, g)


def test_the_paper_system_is_unchanged_by_the_family_route():
    """The paper's closings come from the same theorem: the depths the scan cuts at are those of
    eq. ``m = (b^2 - a^2)/(b^2 + a^2)``; ``system="pendulum"`` at ``D = 1/2`` is the default."""
    assert sorted(closing_depths(5, None, "paper")) == [5 / 13, 15 / 17]
    a = existence(1, 5, damping="paper")
    b = existence(1, 5, system="pendulum", duty="1/2", damping="paper")
    assert a.as_json() == b.as_json()
    assert a.as_json()["system"] == "pendulum" and a.as_json()["duty"] == "1/2"


def test_custom_system_is_refused():
    with pytest.raises(InputError, match="has none"):
        existence(1, 7, system=system("custom", omega_sq=("4/5", "6/5")))
    with pytest.raises(InputError, match="duty"):
        existence(1, 7, system="torsion", duty="1")


def test_cli_existence_takes_the_system(capsys):
    code, out, err = run(
        capsys,
        "existence",
        "--order",
        "1",
        "--Q",
        "7",
        "--system",
        "meissner",
        "--duty",
        "1/3",
        "--damping",
        "paper",
        "--json",
    )
    assert code == 0 and err == ""
    data = json.loads(out)
    assert data["system"] == "meissner" and data["duty"] == "1/3" and not data["undecided"]
    ref = existence(1, 7, system="meissner", duty="1/3", damping="paper")
    assert data["intervals"] == ref.interval_texts()
    code, out, _ = run(capsys, "existence", "--order", "1", "--Q", "7", "--system", "torsion")
    assert code == 0 and out.startswith("torsion: order 1, Q = 7 (exact model)")


@pytest.mark.parametrize(
    "argv, words",
    [
        (["--system", "custom", "--omega-sq", "4/5,6/5"], "has none"),
        (["--duty", "0"], "duty"),
        (["--system", "spring"], "system"),
        (["--omega-sq", "1,2"], "custom"),
    ],
)
def test_cli_existence_refusals(capsys, argv, words):
    code, out, err = run(capsys, "existence", "--order", "1", "--Q", "7", *argv)
    assert code == 2 and out == ""
    assert err.startswith("paramres: error:") and words in err and "Traceback" not in err
