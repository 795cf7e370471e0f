"""Time-domain simulation (verify.timedomain): closure on every kind of edge, measured growth
against
the Floquet multipliers, the nonlinear pendulum's saturation, and bad input.

References: the edges come from ``verify.boundary`` (their own tests check them); the closure test
is that the state returns after ``2T`` (odd orders) or ``T`` (even), a property of a boundary, not
of the code under test.  The Floquet multipliers come from ``verify.floquet`` (checked against a
brute-force integration in tests/test_floquet.py), the stroboscopic states from the propagators of
``analytic.stitching`` -- two separate constructions.
"""

from __future__ import annotations

import math
from fractions import Fraction as F

import mpmath
import numpy as np
import pytest

from verify.floquet import monodromy_matrix
from verify.inputs import InputError
from verify.timedomain import Simulation, amplitude_factor, simulate


def boundary(*args, **kwargs):
    from verify import boundary as b

    return b(*args, **kwargs)


def tiny(digits: int, slack: int = 3) -> mpmath.mpf:
    return mpmath.mpf(10) ** (slack - digits)


# ---------------------------------------------------------------------------------------------
# closure on the edges


EDGE_CASES = [
    # (order, m, edge, Q, damping)
    (1, F(3, 10), "lower", None, "exact"),
    (1, F(3, 10), "upper", None, "exact"),
    (2, F(1, 2), "lower", None, "exact"),
    (2, F(1, 2), "upper", None, "exact"),
    (3, F(3, 10), "lower", None, "exact"),
    (3, F(3, 10), "upper", None, "exact"),
    (4, F(7, 10), "lower", None, "exact"),
    (4, F(7, 10), "upper", None, "exact"),
    (1, F(3, 10), "lower", F(5), "exact"),
    (1, F(3, 10), "upper", F(5), "exact"),
    (1, F(3, 10), "lower", F(5), "paper"),
    (1, F(3, 10), "upper", F(5), "paper"),
    (2, F(7, 10), "lower", F(9), "exact"),
    (2, F(7, 10), "upper", F(9), "exact"),
    (2, F(7, 10), "lower", F(9), "paper"),
    (2, F(7, 10), "upper", F(9), "paper"),
    (3, F(4, 5), "lower", F(7), "exact"),  # past the closing at 3/5, with friction
    (1, F(1, 10**6), "lower", None, "exact"),  # tiny depth: interval width ~ 1e-6
    (1, F(1, 10**12), "upper", None, "exact"),  # interval width ~ 1e-12
    (2, F(1, 10**6), "lower", None, "exact"),  # even order: width ~ m^2 ~ 1e-12
    (1, F(999, 1000), "upper", None, "exact"),  # depth near one
    (20, F(1, 2), "lower", None, "exact"),  # a high order
    (21, F(1, 2), "upper", None, "exact"),
]


@pytest.mark.parametrize("order, m, edge, Q, damping", EDGE_CASES)
def test_closure_on_edges_at_working_precision(order, m, edge, Q, damping):
    sim = simulate(order, m, edge=edge, Q=Q, damping=damping, digits=30, periods=4)
    assert sim.closure_periods == (2 if order % 2 else 1)
    assert sim.closure_error < tiny(30), (order, m, edge, Q, damping, sim.closure_error)
    # on an edge the run is stationary: the measured multiplier is (-1)^n
    assert len(sim.measured_multipliers) == 1
    with mpmath.workdps(30):
        assert abs(sim.measured_multipliers[0] - (-1) ** order) < tiny(30)


def test_closure_follows_the_precision():
    for digits in (20, 50):
        sim = simulate(2, F(1, 2), edge="upper", digits=digits, periods=2)
        assert sim.closure_error < tiny(digits)
    sim = simulate(1, F(3, 10), edge="lower", Q=F(4), digits=60, periods=2)
    assert sim.closure_error < tiny(60)


@pytest.mark.parametrize(
    "order, m, edge, kind",
    [
        (1, F(3, 10), "lower", "odd-cos-sin"),  # eqs. 8-9
        (1, F(3, 10), "upper", "odd-sin-cos"),  # eqs. 16-17
        (2, F(1, 2), "lower", "even-cos-cos"),  # eqs. 20-21
        (2, F(1, 2), "upper", "even-sin-sin"),
        # order 3 below its closing at m = 3/5: the shapes are the other way round
        (3, F(3, 10), "lower", "odd-sin-cos"),
        (3, F(3, 10), "upper", "odd-cos-sin"),
        # past the closing they swap back (docs/theory.md, closings)
        (3, F(4, 5), "lower", "odd-cos-sin"),
        (3, F(4, 5), "upper", "odd-sin-cos"),
    ],
)
def test_edge_shapes(order, m, edge, kind):
    assert simulate(order, m, edge=edge, periods=2).edge_kind == kind


def test_paper_shape_for_the_lower_edge_of_the_third_interval_does_not_close():
    # Section 3.2 of the paper says the left edge of every odd interval has the shapes of eqs. 8-9
    # (odd-cos-sin). At order 3, m = 3/10 that initial condition is not stationary at the lower
    # edge: after 2T it is far from its start (checked with the independent monodromy).
    from verify.timedomain import _initial_ratio

    m = F(3, 10)
    b = boundary(3, m, digits=40)
    with mpmath.workdps(40):
        M = monodromy_matrix(m, b.lower, dps=40)
        errs = {}
        for kind in ("odd-cos-sin", "odd-sin-cos"):
            num, den = _initial_ratio(kind)
            v = mpmath.matrix([den(mpmath.mpf(3) / 10, b.lower), num(mpmath.mpf(3) / 10, b.lower)])
            errs[kind] = mpmath.norm(M * M * v - v) / mpmath.norm(v)
    assert errs["odd-sin-cos"] < mpmath.mpf("1e-35")
    assert errs["odd-cos-sin"] > mpmath.mpf("0.1")


def test_closing_depth_every_start_returns():
    # closing of the third interval (docs/theory.md): m = 3/5, omega1 T/2 = pi, T = sqrt(1+m) T0;
    # M = -I, so a start from rest (not a stationary shape) returns after 2T as well
    m = F(3, 5)
    with mpmath.workdps(40):
        T = mpmath.sqrt(mpmath.mpf(8) / 5)
    sim = simulate(3, m, T=T, digits=30, periods=4, amplitude=F(1, 5))
    with mpmath.workdps(30):
        s0, s2 = sim.strobe[0], sim.strobe[2]
        assert abs(s2[0] - s0[0]) + abs(s2[1] - s0[1]) < tiny(30)
        s1 = sim.strobe[1]
        assert abs(s1[0] + s0[0]) + abs(s1[1] + s0[1]) < tiny(30)  # after T: the negative


def test_closing_edge_from_boundary():
    # at the closing the two edges coincide at T = sqrt(8/5) (the closing theorem, a = 1, b = 2)
    b = boundary(3, F(3, 5), digits=30)
    with mpmath.workdps(30):
        T = mpmath.sqrt(mpmath.mpf(8) / 5)
        for x in (b.lower, b.upper):
            assert abs(x - T) < tiny(30, 5)
    sim = simulate(3, F(3, 5), edge="lower", digits=30, periods=2)
    assert sim.closure_error < tiny(30)


# ---------------------------------------------------------------------------------------------
# measured growth against the Floquet multipliers


INSIDE = [
    (1, F(3, 10), None, "exact"),
    (2, F(1, 2), None, "exact"),
    (3, F(3, 10), None, "exact"),
    (5, F(1, 2), None, "exact"),
    (1, F(3, 10), F(3), "exact"),
    (1, F(3, 10), F(3), "paper"),
    (2, F(7, 10), F(9), "exact"),
    (2, F(7, 10), F(9), "paper"),
    (1, F(999, 1000), None, "exact"),
]


@pytest.mark.parametrize("order, m, Q, damping", INSIDE)
def test_measured_growth_equals_floquet_multiplier_inside(order, m, Q, damping):
    b = boundary(order, m, Q=Q, damping=damping, digits=40)
    with mpmath.workdps(40):
        T = (b.lower + b.upper) / 2
    sim = simulate(order, m, T=T, Q=Q, damping=damping, digits=30, periods=6)
    assert sim.inside
    g = sim.growth_per_period
    assert g > 1
    assert sim.growth_agreement < tiny(30), (order, m, Q, damping, sim.growth_agreement)
    # both multipliers, and the sign (-1)^n of the real pair
    with mpmath.workdps(30):
        for a, b_ in zip(sim.measured_multipliers, sim.multipliers, strict=True):
            assert abs(a - b_) < tiny(30) * max(1, abs(b_))
        assert mpmath.sign(sim.multipliers[0]) == (-1) ** order


def test_measured_growth_outside_intervals():
    # between the first and second intervals: |mu| = 1 without friction, exp(-gamma T) with it
    sim = simulate(1, F(3, 10), T=F(4, 5), digits=30, periods=5)
    assert not sim.inside
    with mpmath.workdps(30):
        assert abs(sim.growth_per_period - 1) < tiny(30)
    sim = simulate(1, F(3, 10), T=F(4, 5), Q=F(5), digits=30, periods=5)
    with mpmath.workdps(30):
        p = mpmath.exp(-mpmath.pi / 5 * mpmath.mpf(4) / 5)
        assert abs(sim.growth_per_period - p) < tiny(30)


def test_one_period_of_propagation_is_the_monodromy():
    # the stroboscopic map of the simulation (analytic's propagators) against verify.floquet, in
    # every regime: under-damped, exactly critical (4 Q^2 = 1 + m), over-damped halves
    for m, T, Q, damping in [
        (F(3, 10), F(1, 2), None, "exact"),
        (F(3, 10), F(1, 2), F(3), "paper"),
        (F(11, 25), F(6, 5), F(3, 5), "exact"),
        (F(1, 2), F(3, 2), F(2, 5), "exact"),
        (F(1, 2), F(1), F(1, 10), "exact"),
    ]:
        sim = simulate(1, m, T=T, Q=Q, damping=damping, digits=30, periods=3)
        M = monodromy_matrix(m, T, Q, damping, dps=40)
        with mpmath.workdps(40):
            for k in range(3):
                s, s1 = mpmath.matrix(sim.strobe[k]), mpmath.matrix(sim.strobe[k + 1])
                err = mpmath.norm(M * s - s1) / mpmath.norm(s1)
                assert err < tiny(30), (m, T, Q, damping, k, err)


def test_stationary_start_with_friction_is_the_floquet_eigenvector():
    sim = simulate(1, F(3, 10), edge="upper", Q=F(5), digits=30, periods=3)
    assert sim.edge_kind is None  # with friction the start comes from the monodromy
    with mpmath.workdps(30):
        s0, s1 = sim.strobe[0], sim.strobe[1]
        assert abs(s1[0] + s0[0]) + abs(s1[1] + s0[1]) < tiny(30) * abs(s0[0])


def test_amplitude_of_the_start():
    sim = simulate(1, F(3, 10), edge="lower", amplitude=F(1, 4), periods=2)
    with mpmath.workdps(30):
        w1 = 2 * mpmath.pi / mpmath.sqrt(mpmath.mpf(13) / 10)
        a = mpmath.sqrt(sim.initial[0] ** 2 + (sim.initial[1] / w1) ** 2)
        assert abs(a - mpmath.mpf(1) / 4) < tiny(30)


def test_segments_match_the_strobe_and_the_jump_rule():
    sim = simulate(2, F(1, 2), T=F(19, 20), periods=3)
    assert isinstance(sim, Simulation)
    segs = sim.segments
    assert len(segs) == 6 and [s.half for s in segs] == [1, 2, 1, 2, 1, 2]
    k = (1.5 / 0.5) ** 2  # ((1+m)/(1-m))^2 at m = 1/2: the jump of phi' (eq. 4)
    for a, b in zip(segs[:-1], segs[1:], strict=True):
        assert abs(a.t[-1] - b.t[0]) < 1e-12
        assert abs(a.phi[-1] - b.phi[0]) < 1e-12 * max(1, abs(b.phi[0]))
        ratio = k if a.half == 1 else 1 / k
        assert abs(a.dphi[-1] * ratio - b.dphi[0]) < 1e-11 * max(1, abs(b.dphi[0]))
    for j in range(3):
        assert abs(segs[2 * j].phi[0] - float(sim.strobe[j][0])) < 1e-12
    # the envelope is the largest |phi| per period
    assert sim.envelope[0] == pytest.approx(
        max(np.abs(segs[0].phi).max(), np.abs(segs[1].phi).max())
    )


def test_json_fields():
    sim = simulate(1, F(3, 10), edge="lower", periods=2)
    d = sim.as_json()
    for key in ("closure_error", "growth_per_period", "floquet_multiplier", "method"):
        assert key in d
    assert isinstance(d["closure_error"], float) and d["closure_error"] < 1e-27
    assert d["edge_kind"] == "odd-cos-sin"
    assert d["T"].startswith("0.3470067")
    d = simulate(1, F(3, 10), T=F(4, 5), periods=2).as_json()
    assert d["closure_error"] is None
    assert set(d["floquet_multiplier"]) == {"re", "im"}


# ---------------------------------------------------------------------------------------------
# the nonlinear pendulum


def test_nonlinear_small_amplitude_agrees_with_the_linear_model():
    m, T = F(3, 10), F(1, 2)
    lin = simulate(1, m, T=T, periods=4, amplitude=F(1, 10**4))
    non = simulate(1, m, T=T, periods=4, amplitude=F(1, 10**4), nonlinear=True)
    # sin(phi) - phi ~ phi^3/6: relative effects ~ phi^2/6, phi up to 4e-3 after 4 periods
    # (growth 2.44 per period); integration tolerance 1e-10
    assert float(non.growth_agreement) < 1e-6
    for a, b in zip(lin.strobe, non.strobe, strict=True):
        scale = math.hypot(float(a[0]), float(a[1]) / 5)
        assert math.hypot(float(a[0]) - b[0], (float(a[1]) - b[1]) / 5) < 1e-5 * scale
    # a larger amplitude visibly detunes: the growth differs at the level A^2/16
    big = simulate(1, m, T=T, periods=4, amplitude=F(1, 10), nonlinear=True)
    assert 1e-5 < float(big.growth_agreement) < 1e-1


def test_nonlinear_growth_is_limited_by_the_amplitude_dependent_period():
    # centre-ish of the first interval at m = 1/20: the linear growth is ~1.15 per period, so
    # 300 periods would multiply the amplitude by ~1e18; the real pendulum beats instead
    m = F(1, 20)
    b = boundary(1, m)
    T = (2 * b.lower + b.upper) / 3
    sim = simulate(1, m, T=T, periods=300, amplitude=F(1, 100), nonlinear=True)
    assert float(sim.floquet_growth) > 1.1
    env = np.array(sim.envelope)
    peak = env.max()
    assert 0.3 < peak < 1.5  # limited well below a rotation (and far below 0.01 * 1.15^300)
    first = int(env.argmax())
    assert env[first:].min() < 0.1 * peak  # the amplitude comes back down: beats
    assert sim.saturation_estimate is not None and 0.3 < sim.saturation_estimate < 1.5


def test_nonlinear_with_friction_settles_near_the_estimate():
    # with friction the beats die out (the paper's closing remarks) and a constant swing remains;
    # the adiabatic estimate (free period lengthened by 2K(sin^2(A/2))/pi carries the lower edge
    # past T) is close to it
    m, Q = F(1, 20), F(30)
    b = boundary(1, m, Q=Q)
    T = (2 * b.lower + b.upper) / 3
    sim = simulate(1, m, T=T, Q=Q, periods=250, amplitude=F(1, 100), nonlinear=True)
    tail = np.array(sim.envelope[-50:])
    assert tail.max() - tail.min() < 0.01 * tail.mean()
    assert abs(sim.saturation_estimate / tail.mean() - 1) < 0.1


def test_nonlinear_runaway_stops_at_its_budget_of_steps():
    # at m = 0.9, T = 20 the jumps speed the rotation up until a period needs tens of thousands
    # of steps: the run stops in period 4 (more than 4 * MAX_STEPS_PER_PERIOD steps by then)
    # and says so; the 3 periods it offers are run in full, the same as at the start of the
    # refused run
    from verify.pendulum_ode import MAX_STEPS_PER_PERIOD

    with pytest.raises(InputError) as exc:
        simulate(1, "0.9", T="20", periods=60, nonlinear=True)
    msg = str(exc.value)
    assert msg.startswith("the motion grows too fast to follow: ")
    assert f"more than {4 * MAX_STEPS_PER_PERIOD} integration steps by period 4 of 60" in msg
    assert "times the natural frequency" in msg and "ask for at most 3 periods" in msg
    sim = simulate(1, "0.9", T="20", periods=3, nonlinear=True, samples=8)
    assert len(sim.strobe) == 4 and len(sim.envelope) == 3


def test_nonlinear_budget_of_a_whole_run(monkeypatch):
    # the budget of the whole run caps the per-period one: 300 periods of small swings (about
    # 20 steps each) refused under a budget of 2000 where the steps run out, run in full below
    import verify.pendulum_ode as ode

    monkeypatch.setattr(ode, "MAX_STEPS", 2000)
    with pytest.raises(InputError) as exc:
        simulate(1, F(1, 20), T="0.98", periods=300, amplitude=F(1, 100), nonlinear=True)
    msg = str(exc.value)
    assert "more than 2000 integration steps by period " in msg
    k = int(msg.split("by period ")[1].split()[0])
    assert 50 < k < 300 and f"ask for at most {k - 1} periods" in msg
    sim = simulate(1, F(1, 20), T="0.98", periods=k - 1, amplitude=F(1, 100), nonlinear=True)
    assert len(sim.envelope) == k - 1


def test_nonlinear_runaway_in_the_first_period():
    # m = 0.99: the angular velocity is multiplied by ((1+m)/(1-m))^2 ~ 4e4 at the first switch
    with pytest.raises(InputError, match="by period 1 of 60 .*; ask for a smaller depth m"):
        simulate(1, "0.99", T="20", periods=60, nonlinear=True, samples=200)


def test_amplitude_factor():
    # K(0) = pi/2: small swings keep their period; at 90 degrees the period grows by 18.0%
    assert amplitude_factor(1e-8) == pytest.approx(1.0, abs=1e-12)
    assert amplitude_factor(math.pi / 2) == pytest.approx(1.18034059901609, rel=1e-12)


# ---------------------------------------------------------------------------------------------
# bad input


@pytest.mark.parametrize(
    "kwargs",
    [
        {"edge": "lower", "T": F(1, 2)},
        {},
        {"edge": "middle"},
        {"T": 0},
        {"T": -1},
        {"T": float("nan")},
        {"T": F(1, 2), "periods": 0},
        {"T": F(1, 2), "periods": -3},
        {"T": F(1, 2), "periods": 10**6},
        {"T": F(1, 2), "periods": 2.5},
        {"T": F(1, 2), "amplitude": 0},
        {"T": F(1, 2), "amplitude": -0.1},
        {"T": F(1, 2), "amplitude": 4},
        {"T": F(1, 2), "amplitude": float("inf")},
        {"T": F(1, 2), "amplitude": "x"},
        {"T": F(1, 2), "Q": 0},
        {"T": F(1, 2), "damping": "viscous"},
        {"T": F(1, 2), "digits": 2},
        {"T": F(1, 2), "Q": 3, "damping": "paper", "nonlinear": True},
        {"T": F(1, 2), "nonlinear": True, "rtol": 1.0},
    ],
)
def test_bad_input(kwargs):
    with pytest.raises(InputError):
        simulate(1, F(3, 10), **kwargs)


def test_bad_order_and_depth():
    with pytest.raises(InputError):
        simulate(0, F(3, 10), T=F(1, 2))
    with pytest.raises(InputError):
        simulate(1, 1, T=F(1, 2))


def test_edge_without_an_interval():
    # order 2 at m = 0.1 needs Q above ~2/(3 m^2) ~ 67 (eq. 43); at Q = 3 there is no interval
    with pytest.raises(InputError, match="no interval"):
        simulate(2, F(1, 10), edge="lower", Q=F(3))


def test_a_ramp_run_past_its_budget_is_refused():
    """The ramp modulation's nonlinear run at ``m = 0.99`` over ``T = 20`` spins ever faster (the
    run of the square wave is refused alike): refused in its first period with the advice, not
    run for minutes."""
    from verify.inputs import InputError
    from verify.modulated_run import simulate_modulated

    with pytest.raises(InputError, match="grows too fast to follow") as info:
        simulate_modulated(
            1, "0.99", modulation="ramp", switch_time="0.01", T="20", periods=60, nonlinear=True
        )
    assert "by period 1 of 60" in str(info.value)


@pytest.mark.parametrize(
    "kw, exact",
    [
        ({"modulation": "sine", "T": "1.1"}, True),  # stable, no friction: a complex pair
        ({"modulation": "sine", "edge": "lower"}, False),  # on an edge: not separated
        ({"modulation": "ramp", "switch_time": "0.1", "edge": "upper"}, True),
    ],
)
def test_a_modulated_run_says_what_its_certified_growth_is(kw, exact):
    """The certified ``ln|mu|max`` of a run with the ramp or the sine prints ``0`` both where it
    is exactly 0 (a proven complex pair: the ramp's upper edge, as the double-precision edge
    falls) and where its ball holds 0 (the sine's lower edge, where the multipliers are not
    separated): a note says which, in the text and the JSON."""
    from verify.modulated_run import simulate_modulated
    from verify.multipliers import significant_digits

    run = simulate_modulated(2, "0.3", periods=2, **kw)
    assert run.floquet_text == "0"
    assert len(run.notes) == 1
    if exact:
        assert "0 exactly" in run.notes[0]
    else:
        shown = significant_digits(run.floquet_text)
        assert f"prints {shown} of 10 digits" in run.notes[0]
    assert run.as_json()["notes"] == list(run.notes)
    assert f"  note: {run.notes[0]}" in str(run).splitlines()
