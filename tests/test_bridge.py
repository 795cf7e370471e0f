"""Existence next to a critical damping (:mod:`verify.bridge`): the ranges of depths that end where
a half is critically damped are decided, and agree with the certified boundary and with the
monodromy matrix of :mod:`tests.pendulum_monodromy` (pure mpmath, built from the damped halves and
the jumps, not from :mod:`verify.hump` or :mod:`analytic`), mpmath's ``cos``, ``sin``, ``cosh``,
``sinh`` at points of the balls (60 digits), and the certified :func:`verify.solve.boundary` at
single exact depths.

Was: ``undecided: 0.959999999999999 < m < 0.960000000000001`` at ``Q = 1/10`` (half 2 critically
damped at ``m = 1 - 4 Q^2``), ``0.439999999999999 < m < 0.440000000000001`` at ``Q = 3/5`` (half 1
at ``m = 4 Q^2 - 1``), for every order: over any range ending there the trace form's ``sin(nu
zeta)/nu`` is a ball without bounds (``nu = 0`` at the end).
"""

from __future__ import annotations

import random
from fractions import Fraction
from functools import cache

import mpmath
import pytest
from flint import arb, ctx

from analytic.system import PAPER
from tests.pendulum_monodromy import damped_monodromy_mp, multipliers_mp
from verify.bridge import half_values
from verify.derived import HALF_SQUARE, trace_indicator, trace_indicator_halves, trace_window
from verify.existence import _box_trace_params, _regime_changes, existence
from verify.params import form_for
from verify.solve import boundary

REGIMES = ("under", "critical", "over")


@cache
def _ex(order, Q):
    return existence(order, Q)


def _critical(Q: Fraction) -> Fraction:
    (c,) = [
        x for x in _regime_changes(Q, PAPER) if "critical" in (form_for(x, Q, "exact")[1] or ())
    ]
    return c


def _sign_at(ex, m: Fraction):
    for lo, hi, sign in ex.segments:
        if lo <= m <= hi:
            return sign
    return None


@pytest.mark.parametrize(
    "order,Q,value",
    [
        (1, "1/10", "24/25"),  # half 2 critical; the interval exists on both sides
        (2, "1/10", "24/25"),  # none on both sides
        (1, "3/10", "16/25"),
        (1, "3/5", "11/25"),  # half 1 critical; none on both sides
        (3, "13/20", "69/100"),
        (1, "13/20", "69/100"),  # half 1 critical; the interval exists on both sides
    ],
)
def test_a_critical_damping_is_decided(order, Q, value):
    """No undecided range is left, and the sign at the critical depth and 1e-13 and 1e-9 on
    either side is the certified boundary's (which decides each depth alone, in the critical
    form at the depth itself)."""
    Qx = Fraction(Q)
    c = _critical(Qx)
    assert c == Fraction(value)
    ex = _ex(order, Qx)
    assert not ex.undecided, ex.undecided
    for d in (
        Fraction(-1, 10**9),
        Fraction(-1, 10**13),
        0,
        Fraction(1, 10**13),
        Fraction(1, 10**9),
    ):
        m = c + d
        sign = _sign_at(ex, m)
        assert sign in (1, -1), m
        assert boundary(order, m, Q=Qx, digits=10).exists == (sign == 1), m


@pytest.mark.parametrize("order,Q", [(1, "1/10"), (1, "13/20")])
def test_the_interval_at_a_critical_damping_is_unstable(order, Q):
    """Where the interval exists next to the critical depth, the reference monodromy has
    ``|mu|max > 1`` in the middle of the certified interval, 1e-12 on either side of it."""
    Qx = Fraction(Q)
    c = _critical(Qx)
    for d in (Fraction(-1, 10**12), Fraction(1, 10**12)):
        m = c + d
        assert _sign_at(_ex(order, Qx), m) == 1
        b = boundary(order, m, Q=Qx, digits=20)
        with mpmath.workdps(40):
            T = (b.lower + b.upper) / 2
            M = damped_monodromy_mp(
                T,
                mpmath.mpf(m.numerator) / m.denominator,
                mpmath.mpf(Qx.numerator) / Qx.denominator,
                "exact",
            )
            assert abs(multipliers_mp(M)[0]) > 1


def test_half_values_are_the_derived_functions():
    """:func:`verify.bridge.half_values` against the compiled half-period functions
    (:func:`verify.derived.trace_window`, from :func:`verify.derived.half_period_forms`) where
    ``nu > 0``: the balls overlap."""
    rng = random.Random(7)
    with ctx.workprec(80):
        for regime in REGIMES:
            C_S = trace_window(regime).compiled("arb", 0), trace_window(regime).compiled("arb", 1)
            for _ in range(40):
                nu, z = arb(rng.uniform(0.01, 2)), arb(rng.uniform(0.01, 20))
                C, S = half_values(regime, nu, z)
                assert C.overlaps(C_S[0](z, 1, 0, nu, 0)) and S.overlaps(C_S[1](z, 1, 0, nu, 0))


def test_half_values_enclose_where_nu_holds_zero():
    """A ball ``nu = [0, e]`` gives ``C``, ``S`` holding the functions' values at every ``nu`` in
    it (mpmath at 40 digits, ``nu`` from 0 to ``e``), and finite: the trace form's ``sin(nu
    zeta)/nu`` is a ball without bounds there."""
    funcs = {
        "under": (lambda v, z: mpmath.cos(v * z), lambda v, z: mpmath.sin(v * z) / v if v else z),
        "over": (lambda v, z: mpmath.cosh(v * z), lambda v, z: mpmath.sinh(v * z) / v if v else z),
    }
    with ctx.workprec(80), mpmath.workdps(40):
        for e in (1e-9, 1e-4, 0.3):
            nu = arb(e / 2, e / 2)  # [0, e]
            for zf in (0.5, 3.0, 11.0):
                z = arb(zf)
                for regime, (fC, fS) in funcs.items():
                    C, S = half_values(regime, nu, z)
                    assert C.is_finite() and S.is_finite()
                    for k in range(11):
                        v = mpmath.mpf(e) * k / 10
                        for ball, f in ((C, fC), (S, fS)):
                            assert ball.contains(arb(mpmath.nstr(f(v, zf), 35))), (regime, e, zf, k)
        # the trace form's S of the same ball: no bounds
        assert (
            not trace_window("under").compiled("arb", 1)(arb(1), 1, 0, arb(0.5, 0.5), 0).is_finite()
        )


def test_the_halves_form_is_the_trace_indicator():
    """:func:`verify.derived.trace_indicator_halves` with the halves' values of
    :func:`half_values` is :func:`verify.derived.trace_indicator` of every pair of regimes, ``D``
    and its first two derivatives (the balls overlap)."""
    rng = random.Random(3)
    halves = [trace_indicator_halves().compiled("arb", k) for k in (0, 1, 2)]
    with ctx.workprec(80):
        for r1 in REGIMES:
            for r2 in REGIMES:
                whole = [trace_indicator(r1, r2).compiled("arb", k) for k in (0, 1, 2)]
                for _ in range(10):
                    z = arb(rng.uniform(0.05, 8))
                    nu1, nu2 = arb(rng.uniform(0.05, 1.5)), arb(rng.uniform(0.05, 1.5))
                    kappa, sigma = arb(rng.uniform(-5, 50)), rng.choice((-1, 1))
                    C1, S1 = half_values(r1, nu1, z)
                    C2, S2 = half_values(r2, nu2, z)
                    u1, u2 = HALF_SQUARE[r1] * nu1**2, HALF_SQUARE[r2] * nu2**2
                    for F, G in zip(halves, whole, strict=True):
                        a = F(z, sigma, kappa, C1, S1, C2, S2, u1, u2)
                        b = G(z, sigma, kappa, nu1, nu2)
                        assert a.overlaps(b), (r1, r2)


@pytest.mark.parametrize("side", [-1, 1])
def test_nu_holds_every_value_next_to_a_critical_damping(side):
    """Over a range of depths ending at the critical depth, ``nu2`` holds ``sqrt|u2|`` of every
    depth of it, 0 at the end included (it was 0 exactly, a ball's ``!= 0`` being false where it
    holds 0)."""
    Q = Fraction(1, 10)
    c = _critical(Q)
    w = Fraction(1, 10**6)
    lo, hi = (c - w, c) if side < 0 else (c, c + w)
    P = _box_trace_params(lo, hi, Q)
    with ctx.workprec(96), mpmath.workdps(40):
        nu2 = P().nu2
        for k in range(11):
            m = lo + (hi - lo) * k / 10
            # half 2's (Omega2/gamma)^2 with its sign: omega2^2 = omega0^2/(1 - m) (length
            # l0 (1 - m)), gamma = omega0/(2 Q), so omega2^2/gamma^2 - 1
            u2 = 4 * Q * Q / (1 - m) - 1
            assert nu2.contains(
                arb(mpmath.nstr(mpmath.sqrt(abs(mpmath.mpf(u2.numerator) / u2.denominator)), 35))
            )


def _exact(v) -> arb:
    """The mpf ``v`` as an exact ball."""
    sign, man, exp, _ = v._mpf_
    return (-1 if sign else 1) * arb(int(man)) * arb(2) ** int(exp)


def _reference(regime, nu, z):
    x = nu * z
    if regime == "under":
        return mpmath.cos(x), (mpmath.sin(x) / nu if nu else z)
    if regime == "over":
        return mpmath.cosh(x), (mpmath.sinh(x) / nu if nu else z)
    return mpmath.mpf(1), z


def test_half_values_hold_the_functions_at_every_point_of_the_balls():
    """``C``, ``S`` of each regime contain the values at the ends and the middle of the balls
    ``nu`` (many holding 0) and ``zeta``, at several precisions."""
    rng = random.Random(5)
    with mpmath.workdps(60):
        for _ in range(400):
            prec = rng.choice([53, 64, 128])
            with ctx.workprec(prec):
                r = 10 ** rng.uniform(-16, -1)
                nu = rng.choice([arb(0, r), arb(0).union(arb(r)), arb(rng.uniform(0, 2), r)])
                z = arb(10 ** rng.uniform(-3, 1.5), rng.choice([0, 1e-12]))
                balls = {g: half_values(g, nu, z) for g in ("under", "over", "critical")}
            with ctx.workprec(300):
                for g, (C, S) in balls.items():
                    for nb in (nu.lower(), nu.mid(), nu.upper()):
                        for zb in (z.lower(), z.mid(), z.upper()):
                            n_ = max(mpmath.mpf(nb.mid().str(90, radius=False)), 0)
                            z_ = mpmath.mpf(zb.mid().str(90, radius=False))
                            c, s = _reference(g, n_, z_)
                            assert C.contains(_exact(c)) and S.contains(_exact(s)), (g, nu, z)


def test_over_damped_values_are_tight_where_nu_holds_zero():
    """Over-damped, ``cosh`` and ``sinh(x)/x`` of a ball ``x`` of radius ``r`` about 0 were balls
    of radius about ``r`` (2e-7 here); they are even and rise with ``|x|``, so their values at
    the ends of ``|x|`` give them to ``r^2``, as ``cos`` and ``sinc`` do under-damped."""
    with ctx.workprec(96):
        for nu in (arb(0, 1e-7), arb(0).union(arb(1e-7))):
            for g in ("over", "under"):
                C, S = half_values(g, nu, arb(2))
                assert C.rad() < 1e-12 and S.rad() < 1e-12, (g, nu, C, S)


def test_a_threshold_next_to_the_critical_damping_of_phase_two():
    """Q = 0.21401: the threshold of order 1 lies 2.7e-6 below m* = 1 - 4 Q^2, where phase 2 is
    critically damped, and the interval exists at m* with |mu| - 1 = 4.5e-5.  The range from
    m* - 4.9e-8 to m* was left undecided (its balls of C, S as wide as the square root of its
    width), and one next to the threshold; every depth is now decided, as the boundary decides
    it."""
    Q = Fraction("0.21401")
    ms = 1 - 4 * Q * Q
    ex = existence(1, Q)
    assert not ex.undecided
    for d in (-(10**10), -(10**13), 0, 10**13, 10**10):
        m = ms + (Fraction(1, d) if d else 0)
        (sign,) = {s for lo, hi, s in ex.segments if lo <= m <= hi}
        assert sign == 1 and boundary(1, m, Q=Q, digits=10).exists, d


def test_ranges_next_to_the_critical_damping_are_decided_in_the_halves_functions():
    """Q = 0.2140127 (threshold of order 1 just below m* = 1 - 4 Q^2) and Q = 0.6267345 (just
    above m* = 4 Q^2 - 1): ranges a few of their widths from m* were left undecided (4.5e-7 and
    1e-6 wide; 2.1e-6 above m*), their sin(nu zeta)/nu balls wide for nu's size; they are
    decided as the ranges ending at m* are, and agree with the boundary."""
    for Q, ds in (("0.2140127", (-(10**10), 10**6)), ("0.6267345", (10**10, 10**6))):
        Qx = Fraction(Q)
        ms = abs(1 - 4 * Qx * Qx)
        ex = existence(1, Qx)
        assert not ex.undecided, Q
        for d in ds:
            m = ms + Fraction(1, d)
            signs = {s for lo, hi, s in ex.segments if lo <= m <= hi}
            assert signs == {1 if boundary(1, m, Q=Qx, digits=10).exists else -1}, (Q, d)


def _continuous_phase(system, m, Q, z):
    """The trace form's phase at one depth with half 1 under-damped, lifted continuously from
    ``zeta = 0`` in mpmath (60 digits): ``atan2`` plus ``2 pi`` for each time ``nu1 zeta`` has
    passed an odd multiple of ``pi``, where ``(2 nu2 cos(nu1 zeta), kappa sin(nu1 zeta)/nu1)``
    crosses the negative real axis (``kappa > 0``)."""
    from verify.derived import backend
    from verify.params import trace_params

    with mpmath.workdps(60):
        p = trace_params(m, Q, backend("mpmath"), system)
        x = p.nu1 * z
        turns = mpmath.floor((x / mpmath.pi + 1) / 2)
        theta = mpmath.atan2(p.kappa * mpmath.sin(x) / p.nu1, 2 * p.nu2 * mpmath.cos(x))
        return p.nu2 * z + theta + 2 * mpmath.pi * turns


def _wrapping_case():
    """Meissner, D = 99/100, Q = 100, m = 0.999974: phase 1 under-damped near critical damping
    (``nu1 = 0.396`` after the duty's scaling; a normal-form range is tried in the trace form
    there), and a range of depths around it."""
    from analytic.system import System

    system = System("meissner", Fraction(99, 100))
    Q = Fraction(100)
    m = Fraction(999974, 10**6)
    assert form_for(m, Q, "exact", system) == ("normal", None)  # both halves under-damped
    return system, Q, m, (m - Fraction(1, 10**12), m + Fraction(1, 10**12))


def _right_or_not_given(calls, system, m, Q):
    """Each call's phase at ``zeta = 3`` and ``9`` holds the continuous phase, or the call raises
    ``ValueError`` (not decided), which it may only past ``nu1 zeta = pi`` (``zeta = 9``)."""
    for zeta in (3, 9):
        with ctx.workprec(96):
            true = arb(mpmath.nstr(_continuous_phase(system, m, Q, mpmath.mpf(zeta)), 40))
            for name, call in calls.items():
                try:
                    ph = call(arb(zeta))
                except ValueError:
                    assert zeta == 9, name
                    continue
                assert ph.overlaps(true), (name, zeta, ph, true)


def test_the_phase_is_not_counted_past_half_one_turning_back():
    """At ``zeta = 9`` (``nu1 zeta = 3.56``, inside the tail bound's reach) atan2's point has
    crossed the negative real axis and atan2 is ``2 pi`` below the phase that numbers the orders
    (49.337 for 55.620): an order's window would be taken for that of the order two below, and
    a phase below an order's window at the tail point would not prove that the window is never
    reached.  The trace form's phase at a depth and over a range is right or not given."""
    from verify.hump import trace_phase

    system, Q, m, (lo, hi) = _wrapping_case()
    regimes = ("under", "under")
    P = _box_trace_params(lo, hi, Q, system)
    P1 = _box_trace_params(m, m, Q, system)
    calls = {
        "at a depth": lambda z: trace_phase(regimes, P1, z),
        "over a range": lambda z: trace_phase(regimes, P, z, (lo, hi), m, Q, system),
    }
    _right_or_not_given(calls, system, m, Q)


def test_the_halves_phase_is_not_counted_past_half_one_turning_back():
    """The same over the balls of the halves' functions (:mod:`verify.bridge`, whose phase decides
    the windows of ranges next to a critical damping)."""
    from verify.bridge import _phase

    system, Q, m, (lo, hi) = _wrapping_case()
    P = _box_trace_params(lo, hi, Q, system)
    _right_or_not_given({"halves' functions": lambda z: _phase("under", P(), z)}, system, m, Q)
