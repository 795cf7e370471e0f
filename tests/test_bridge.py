"""Existence next to a critical damping (:mod:`verify.bridge`): the ranges of depths that end where
a half is critically damped are decided, and agree with the certified boundary and with the
monodromy matrix of :mod:`tests.pendulum_monodromy` (pure mpmath, built from the damped halves and
the jumps, not from :mod:`verify.hump` or :mod:`analytic`).

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
