"""The cancellation-free parameters of :mod:`verify.params` equal their definitions.

Reference: :func:`analytic.normal_form.parameters` (the definitions ``r^2 = (K-2)/(K+2)``,
``beta = (Omega2-Omega1)/(Omega2+Omega1)``, ``w = omega_av/omega0``, ``g = gamma/omega_av``),
evaluated by mpmath at 3x the working precision so that the cancellation in the definitions cannot
hide an error, and the trace-form constant ``K' = K Omega1 Omega2`` from
:func:`analytic.normal_form.K`.  Points are log-spaced towards both ends of ``0 < m < 1``.
"""

from __future__ import annotations

import random
from fractions import Fraction

import mpmath
import numpy as np
import pytest
import sympy as sp
from flint import ctx

from analytic.model import Damping, S
from analytic.normal_form import K, parameters
from verify.certify import to_mpf
from verify.derived import backend
from verify.params import exact_fraction, halves, normal_params, trace_params


def _definitions(damping):
    defs = parameters(damping)
    byname = {k.name: v for k, v in defs.items()}
    args = [S.m, S.Q]
    return {name: sp.lambdify(args, expr, modules="mpmath") for name, expr in byname.items()}


def _points(seed=7, count=12):
    rng = random.Random(seed)
    ms = [
        Fraction(1, 10**12),
        Fraction(1, 1000),
        Fraction(3, 5),
        Fraction(999, 1000),
        Fraction(1) - Fraction(1, 10**9),
    ]
    ms += [Fraction(rng.uniform(0.0, 1.0)).limit_denominator(10**9) for _ in range(count)]
    ms += [Fraction(10) ** -rng.randint(2, 14) for _ in range(4)]
    return [m for m in ms if 0 < m < 1]


DIGITS = 50


def _agree(got, ref, what, m, Q, rel=None):
    rel = mpmath.mpf(10) ** -(DIGITS - 3) if rel is None else rel
    err = abs(got - ref)
    assert err <= rel * abs(ref) + mpmath.mpf(10) ** -(3 * DIGITS), (
        f"{what} at m={m}, Q={Q}: got {got}, definition {ref}, rel diff {err / abs(ref)}"
    )


@pytest.mark.parametrize("damping", ["none", "paper", "exact"])
def test_normal_params_equal_definitions(damping):
    defs = _definitions(Damping.NONE if damping == "none" else Damping(damping))
    for m in _points():
        for Q in [None] if damping == "none" else [Fraction(3), Fraction(7, 2), Fraction(10**6)]:
            if damping == "exact" and not halves(m, Q, "exact").normal:
                continue
            prec = int(DIGITS * 3.33) + 20
            with ctx.workprec(prec):
                p = normal_params(m, Q, "exact" if damping == "none" else damping, backend("arb"))
            names = ("r2", "u", "beta", "w", "bm") + (("g",) if Q is not None else ())
            got = {k: to_mpf(getattr(p, k)) for k in names}
            for k in names:  # no cancellation: the ball is as tight as the working precision
                ball = getattr(p, k)
                assert ball.rad() <= ball.mid().abs_lower() * 2.0 ** -(prec - 24), (k, m, Q, ball)
            with mpmath.workdps(3 * DIGITS):
                mm = mpmath.mpf(m.numerator) / m.denominator
                QQ = mpmath.mpf(Q.numerator) / Q.denominator if Q is not None else mpmath.mpf(1)
                ref = {k: defs[k if k != "r2" else "r^2"](mm, QQ) for k in ("r2", "beta", "w", "g")}
                ref["u"] = 1 - ref["r2"]
                ref["bm"] = 1 - ref["beta"]
                for k in ("r2", "u", "beta", "w", "bm"):
                    _agree(got[k], ref[k], k, m, Q)
                if Q is not None:
                    _agree(got["g"], ref["g"], "g", m, Q)


def test_r_is_tanh_3a_and_beta_tanh_a():
    """docs/theory.md item 5: with a = artanh(m)/2, beta = tanh a and r = tanh 3a."""
    for m in _points(seed=11):
        with ctx.workprec(300):
            p = normal_params(m, None, "exact", backend("arb"))
            with mpmath.workprec(300):
                a = mpmath.atanh(mpmath.mpf(m.numerator) / m.denominator) / 2
                _agree(to_mpf(p.beta), mpmath.tanh(a), "beta", m, None)
                _agree(to_mpf(p.r), mpmath.tanh(3 * a), "r", m, None)


def test_dinv_and_kappa():
    """``1/w - 1/w0`` (exact model) against the difference evaluated at triple precision, and
    ``kappa`` against ``K(exact) * Omega1 * Omega2 / gamma^2`` of :func:`analytic.normal_form.K`."""
    Kexpr = K(Damping.EXACT) * S.Omega1 * S.Omega2 / S.gamma**2
    om1, om2, gam = 2 * sp.pi / sp.sqrt(1 + S.m), 2 * sp.pi / sp.sqrt(1 - S.m), sp.pi / S.Q
    Kexpr = Kexpr.subs(
        {S.Omega1: sp.sqrt(om1**2 - gam**2), S.Omega2: sp.sqrt(om2**2 - gam**2), S.gamma: gam}
    )
    kap = sp.lambdify([S.m, S.Q], Kexpr, modules="mpmath")
    defs = _definitions(Damping.EXACT)
    undamped = _definitions(Damping.NONE)
    for m in _points(seed=3):
        for Q in (Fraction(3), Fraction(1000)):
            with ctx.workprec(200):
                p = normal_params(m, Q, "exact", backend("arb"))
                t = trace_params(m, Q, backend("arb"))
            with mpmath.workdps(150):
                mm, QQ = (
                    mpmath.mpf(m.numerator) / m.denominator,
                    mpmath.mpf(Q.numerator) / Q.denominator,
                )
                ref = 1 / defs["w"](mm, QQ) - 1 / undamped["w"](mm, QQ)
                _agree(to_mpf(p.dinv), ref, "dinv", m, Q, rel=mpmath.mpf(10) ** -50)
                _agree(to_mpf(t.kappa), kap(mm, QQ), "kappa", m, Q, rel=mpmath.mpf(10) ** -50)


def test_halves_exact_regimes():
    assert halves(Fraction(44, 100), Fraction(3, 5), "exact").half1 == "critical"  # 4Q^2 = 1 + m
    assert halves(Fraction(44, 100), Fraction(3, 5), "exact").half2 == "under"
    assert halves(Fraction(96, 100), Fraction(1, 10), "exact").half2 == "critical"  # 4Q^2 = 1 - m
    assert halves(Fraction(96, 100), Fraction(1, 10), "exact").half1 == "over"
    assert halves(Fraction(1, 2), Fraction(1, 10), "paper").normal
    assert halves(Fraction(1, 2), None, "exact").half1 == "undamped"


def test_exact_fraction():
    assert exact_fraction(0.1) == Fraction(0.1)
    assert exact_fraction(mpmath.mpf("0.375")) == Fraction(3, 8)
    with mpmath.workprec(200):
        x = mpmath.mpf(1) / 3
    assert abs(exact_fraction(x) - Fraction(1, 3)) < Fraction(1, 2**199)


def test_numpy_backend_matches_arb():
    """The float64 arrays of the grid are the same formulas: relative agreement to 4e-16 * 8."""
    ms = np.array([float(m) for m in _points(seed=5)])
    for damping, Q in (("exact", None), ("paper", 5.0), ("exact", 5.0)):
        p = normal_params(ms, Q, damping, backend("numpy"))
        for i, m in enumerate(ms):
            with ctx.workprec(120):
                ref = normal_params(
                    Fraction(m), None if Q is None else Fraction(Q), damping, backend("arb")
                )
            for k in ("r2", "u", "beta", "w", "g"):
                want = float(getattr(ref, k).mid())
                assert abs(getattr(p, k)[i] - want) <= 8 * 2.0**-52 * abs(want), (k, m, damping)


@pytest.mark.parametrize("damping, Q", [("exact", None), ("paper", 7.0), ("exact", 7.0)])
def test_one_minus_m_given_separately(damping, Q):
    """``om = 1 - m`` passed on its own (the grid near ``m = 1``, where ``1 - float(m)`` has lost
    the digits of ``1 - m``): the numpy arrays at ``float(m)`` with ``om = float(1 - m)`` equal
    the definitions at the exact depth (:func:`analytic.normal_form.parameters` by mpmath at 150
    digits) to a relative 8 ulp, down to ``1 - m = 1e-30``; and in ball arithmetic the separate
    ``om`` gives the same balls as the exact rational depth."""
    defs = _definitions(Damping.NONE if Q is None else Damping(damping))
    exact = [1 - Fraction(1, 10**k) for k in (1, 3, 5, 8, 11, 13, 15, 16, 17, 20, 30)]
    exact += [1 - Fraction(3, 7) * Fraction(1, 10**k) for k in (9, 14)]
    ms = np.array([float(m) for m in exact])
    om = np.array([float(1 - m) for m in exact])
    p = normal_params(ms, Q, damping, backend("numpy"), om=om)
    for i, m in enumerate(exact):
        with mpmath.workdps(150):
            mm = mpmath.mpf(m.numerator) / m.denominator
            QQ = mpmath.mpf(1) if Q is None else mpmath.mpf(Q)
            ref = {k: defs[k if k != "r2" else "r^2"](mm, QQ) for k in ("r2", "beta", "w", "g")}
            ref["u"] = 1 - ref["r2"]
            ref["bm"] = 1 - ref["beta"]
        for k in ("r2", "u", "beta", "w", "bm") + (("g",) if Q is not None else ()):
            want = float(ref[k])
            got = getattr(p, k)[i]
            assert abs(got - want) <= 8 * 2.0**-52 * abs(want), (k, m, damping, got, want)
        QF = None if Q is None else Fraction(Q)
        with ctx.workprec(200):
            a = normal_params(m, QF, damping, backend("arb"))
            B = backend("arb")
            Qb = None if QF is None else B.num(QF)
            b = normal_params(B.num(m), Qb, damping, B, om=B.num(1 - m))
            for k in ("r2", "u", "beta", "w", "bm", "g"):
                x, y = getattr(a, k), getattr(b, k)
                assert x.overlaps(y) and y.rad() <= abs(y.mid()) * 2.0**-190 + 2.0**-400, (k, m)


def test_form_for_every_system_by_its_integers():
    """The choice of equations for exact ``m``, ``Q`` is cached by their integers for every member
    of the family (not only the paper's pendulum): the same answers as the exact decision itself,
    and a second call is a lookup."""
    from verify.inputs import as_system
    from verify.params import _form_for, _form_for_system, form_for

    for name in ("torsion", "meissner"):
        sysv = as_system(name, "1/2")
        for m in (Fraction(3, 10), Fraction(9, 10), Fraction(99, 100)):
            for Q in (Fraction(1, 2), Fraction(7), Fraction(30)):
                for damping in ("exact", "paper"):
                    want = _form_for.__wrapped__(m, Q, damping, sysv)
                    assert form_for(m, Q, damping, sysv) == want
                    hits = _form_for_system.cache_info().hits
                    assert form_for(m, Q, damping, sysv) == want
                    assert _form_for_system.cache_info().hits == hits + 1


@pytest.mark.parametrize(
    "name, duty",
    [("pendulum", "1/2"), ("pendulum", "1/3"), ("torsion", "1/2"), ("meissner", "2/3")],
)
def test_trace_params_over_a_range_of_depths(name, duty):
    """``kappa``, ``nu1``, ``nu2`` of :func:`verify.params.trace_params` for every member: over a
    ball of depths (and of its jets, the slope in ``m``) they hold the values and the slopes at
    every depth in it, ranges touching a critical damping (``nu = 0`` at an end) included.
    Reference: the definitions ``kappa = (k omega1^2 + omega2^2/k - 2 gamma^2)/gamma^2`` and
    ``nu_i^2 = |omega_i^2 - gamma^2|/gamma^2`` (in units of ``omega0``) from the system's own
    description (:meth:`analytic.system.System.values`), scaled by the duty (``4 D (1 - D)``,
    ``2 D``, ``2 (1 - D)``), evaluated in exact rationals; the slopes by central differences at
    60 digits."""
    from flint import arb

    from analytic.system import system as make
    from verify.certify import Jet
    from verify.hump import depth_ball

    sysv = make(name, duty=duty)
    D = sysv.duty
    A = backend("arb")

    def exact(m, Q):
        W1, W2, k = (sp.Rational(v) for v in sysv.values(sp.Rational(m.numerator, m.denominator)))
        g2 = sp.Rational(1, 4) / sp.Rational(Q.numerator, Q.denominator) ** 2
        kappa = (k * W1 + W2 / k - 2 * g2) / g2 * 4 * D * (1 - D)
        return kappa, abs(W1 - g2) / g2 * (2 * D) ** 2, abs(W2 - g2) / g2 * (4 * (1 - D) ** 2)

    def value(m, Q, i):
        with mpmath.workdps(60):
            v = exact(m, Q)[i]
            return (
                mpmath.mpf(sp.Rational(v).p) / sp.Rational(v).q
                if i == 0
                else mpmath.sqrt(mpmath.mpf(sp.Rational(v).p) / sp.Rational(v).q)
            )

    rng = random.Random(5)
    Q = Fraction(3, 5)
    g2 = Fraction(1, 4) / Q**2
    # the depths where a phase is critically damped at this Q (W_i(m) = g2), from the laws
    crit = [c for c in (1 / g2 - 1, 1 - 1 / g2, 1 - g2) if 0 < c < 1]
    ranges = [(c - Fraction(1, 10**4), c) for c in crit] + [
        (c, c + Fraction(1, 10**4)) for c in crit
    ]
    ranges += [
        (lo, lo + Fraction(1, 10 ** rng.randint(3, 8)))
        for lo in (Fraction(rng.randint(1, 9900), 10**4) for _ in range(6))
    ]
    ranges += [(Fraction(998, 1000), Fraction(999, 1000))]
    for lo, hi in ranges:
        with ctx.workprec(80):
            Qb = arb(Q.numerator) / Q.denominator
            P = trace_params(depth_ball((lo, hi)), Qb, A, sysv)
            touching = any(lo <= c <= hi for c in crit)
            # (a jet's nu over a range holding nu = 0 has no slope: |x| of it raises)
            J = None if touching else trace_params(Jet(depth_ball((lo, hi)), 1), Jet(Qb), A, sysv)
        got = (P.kappa, P.nu1, P.nu2)
        jets = None if J is None else (J.kappa, J.nu1, J.nu2)
        for j in range(7):
            m = lo + (hi - lo) * Fraction(j, 6)
            for i in range(3):
                with ctx.workprec(200):
                    ref = arb(mpmath.nstr(value(m, Q, i), 55))
                    assert got[i].contains(ref), (name, duty, lo, hi, m, i, got[i], ref)
                if 0 < j < 6 and jets is not None:
                    h = Fraction(1, 10**20)
                    with mpmath.workdps(60):
                        slope = (value(m + h, Q, i) - value(m - h, Q, i)) * 10**20 / 2
                    d = jets[i].d if isinstance(jets[i], Jet) else arb(0)
                    with ctx.workprec(200):  # the difference quotient: good to ~1e-30
                        ref = arb(mpmath.nstr(slope, 40))
                        assert (d + arb(0, 1e-20)).contains(ref), (name, duty, lo, hi, m, i, d, ref)
