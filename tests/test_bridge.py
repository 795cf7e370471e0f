"""Ranges of depths that end at a critical damping (:mod:`verify.bridge`): the halves' functions
``C``, ``S`` as balls that stay finite and tight where ``nu`` holds 0.

References: mpmath's ``cos``, ``sin``, ``cosh``, ``sinh`` at points of the balls (60 digits), and
the certified :func:`verify.solve.boundary` at single exact depths."""

from __future__ import annotations

import random
from fractions import Fraction

import mpmath
from flint import arb, ctx

from verify.bridge import half_values
from verify.existence import existence
from verify.solve import boundary


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
