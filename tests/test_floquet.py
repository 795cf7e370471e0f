"""The Floquet route (verify.floquet) against facts that do not come from it.

References used here, none of them the module's own formulas:

* Liouville: the flow of ``phi'' + 2 gamma phi' + w**2 phi = 0`` shrinks areas by
  ``exp(-2 gamma t)`` and the jumps ``diag(1, k)``, ``diag(1, 1/k)`` preserve area, so
  ``det M = exp(-2 gamma T)``; the paper model's half map is ``exp(-gamma t)`` times a map of
  determinant 1, the same;
* an independent brute-force integration of the equations of motion (``mpmath.odefun``, Taylor
  series at 30 digits) with the jumps applied by hand;
* the closing theorem (docs/theory.md): at ``m = (b**2-a**2)/(b**2+a**2)`` and
  ``omega1 T/2 = a pi``, ``omega2 T/2 = b pi`` every solution is (anti)periodic,
  ``M = (-1)**(a+b) I``;
* the critically damped free oscillation ``(A t + B) exp(-gamma t)``, written out in the test.
"""

from __future__ import annotations

import math
import random
from fractions import Fraction
from fractions import Fraction as F

import mpmath
import numpy as np
import pytest

from verify.floquet import floquet_multipliers, floquet_vector, growth_factor, monodromy_matrix
from verify.inputs import InputError


def mp(x) -> mpmath.mpf:
    if isinstance(x, F):
        return mpmath.mpf(x.numerator) / x.denominator
    return mpmath.mpf(x)


def relnorm(A, B):
    """``||A - B|| / ||B||`` (Frobenius) for mpmath matrices."""
    return mpmath.mnorm(A - B, "F") / mpmath.mnorm(B, "F")


def as_mp_matrix(a) -> mpmath.matrix:
    return mpmath.matrix([[mpmath.mpf(float(x)) for x in row] for row in np.asarray(a)])


# ---------------------------------------------------------------------------------------------
# brute force: integrate the ODE of each half with mpmath.odefun, apply the jumps by hand


def brute_force(m: F, tau: F, Q, model: str, dps: int = 30) -> mpmath.matrix:
    with mpmath.workdps(dps):
        mm, T = mp(m), mp(tau)
        g = mpmath.pi / mp(Q) if Q is not None else mpmath.mpf(0)
        w1, w2 = 4 * mpmath.pi**2 / (1 + mm), 4 * mpmath.pi**2 / (1 - mm)
        k = ((1 + mm) / (1 - mm)) ** 2

        def half(w, y0):
            if model == "paper":  # d/dt of exp(-g t) (rotation): the paper's velocity (eqs. 28-30)
                rhs = lambda t, y: [-g * y[0] + y[1], -w * y[0] - g * y[1]]  # noqa: E731
            else:
                rhs = lambda t, y: [y[1], -2 * g * y[1] - w * y[0]]  # noqa: E731
            return mpmath.odefun(rhs, 0, y0)(T / 2)

        cols = []
        for y0 in ([mpmath.mpf(1), mpmath.mpf(0)], [mpmath.mpf(0), mpmath.mpf(1)]):
            y = half(w1, y0)
            y = half(w2, [y[0], k * y[1]])  # bob up: J phi' conserved
            cols.append([y[0], y[1] / k])  # bob down again
        return mpmath.matrix([[cols[0][0], cols[1][0]], [cols[0][1], cols[1][1]]])


BRUTE_POINTS = [
    # (m, tau, Q, model): no friction; under-damped; paper model; one half over-damped (4Q^2 < 1+m);
    # strongly over-damped half (the separated-exponential branch); both halves over-damped
    (F(3, 10), F(13, 25), None, "exact"),
    (F(3, 10), F(13, 25), F(3), "exact"),
    (F(3, 10), F(13, 25), F(3), "paper"),
    (F(1, 2), F(3, 2), F(2, 5), "exact"),
    (F(9, 10), F(7, 4), F(1, 5), "exact"),
    (F(1, 2), F(1, 1), F(1, 10), "exact"),
    (F(2, 3), F(23, 10), F(7), "exact"),
]


@pytest.mark.parametrize("m, tau, Q, model", BRUTE_POINTS)
def test_agrees_with_brute_force_integration(m, tau, Q, model):
    ref = brute_force(m, tau, Q, model, dps=30)
    M = monodromy_matrix(m, tau, Q, model, dps=30)
    with mpmath.workdps(30):
        err = relnorm(M, ref)
    assert err < mpmath.mpf("1e-27"), f"{m}, {tau}, {Q}, {model}: relative difference {err}"


# ---------------------------------------------------------------------------------------------
# Liouville


LIOUVILLE = [
    (F(3, 10), F(1, 2), None),
    (F(3, 10), F(1, 2), F(3)),
    (F(1, 10**12), F(3, 2), F(40)),
    (F(999, 1000), F(1, 3), F(5)),
    (F(3, 5), F(7, 3), F(1, 2)),  # half 2 over-damped
    (F(1, 2), F(1), F(1, 10)),  # both halves over-damped, one strongly
    (F(11, 25), F(6, 5), F(3, 5)),  # half 1 exactly critical: 4 Q^2 = 1 + m
]


@pytest.mark.parametrize("model", ["exact", "paper"])
@pytest.mark.parametrize("m, tau, Q", LIOUVILLE)
def test_liouville_determinant(m, tau, Q, model):
    dps = 40
    M = monodromy_matrix(m, tau, Q, model, dps=dps)
    with mpmath.workdps(dps):
        p2 = mpmath.exp(-2 * mpmath.pi / mp(Q) * mp(tau)) if Q is not None else mpmath.mpf(1)
        det = mpmath.det(M)
        # det from rounded entries: absolute error ~ 10**-dps ||M||^2 (relative when det ~ ||M||^2)
        scale = max(mpmath.mnorm(M, "F") ** 2, p2)
        assert abs(det - p2) <= mpmath.mpf(10) ** (5 - dps) * scale, (m, tau, Q, model, det, p2)
    Mn = monodromy_matrix(
        float(m), float(tau), None if Q is None else float(Q), model, backend="numpy"
    )
    detn = np.linalg.det(Mn)
    assert abs(detn - float(p2)) <= 1e-13 * max(np.sum(Mn**2), float(p2))


def test_liouville_relative_where_determinant_is_not_small():
    # moderate friction: det M is O(||M||^2), so the relative error is at the working precision
    for m, tau, Q in [
        (F(1, 5), F(1, 2), F(2)),
        (F(7, 10), F(3, 2), F(5)),
        (F(1, 3), F(5, 2), F(1)),
    ]:
        for model in ("exact", "paper"):
            M = monodromy_matrix(m, tau, Q, model, dps=50)
            with mpmath.workdps(50):
                p2 = mpmath.exp(-2 * mpmath.pi / mp(Q) * mp(tau))
                assert abs(mpmath.det(M) / p2 - 1) < mpmath.mpf("1e-44")


# ---------------------------------------------------------------------------------------------
# the two backends


def random_points(n: int, seed: int):
    """Log-spaced hard regions: m from 1e-12 to 0.99, tau from 0.1 to 6, Q None or 0.05 to 100."""
    rng = random.Random(seed)
    pts = []
    for _ in range(n):
        m = (
            10 ** rng.uniform(-12, math.log10(0.99))
            if rng.random() < 0.5
            else rng.uniform(0.01, 0.99)
        )
        tau = rng.uniform(0.1, 6.0)
        Q = None if rng.random() < 0.25 else 10 ** rng.uniform(math.log10(0.05), 2)
        pts.append((m, tau, Q, rng.choice(["exact", "paper"])))
    return pts


def test_numpy_and_mpmath_agree_at_random_points():
    bad = []
    for m, tau, Q, model in random_points(300, seed=20240601):
        # both back ends at the same exact point: the binary value of each double (a float given
        # to the API means its shortest decimal, which the double only approximates)
        m, tau = Fraction(m), Fraction(tau)
        Q = None if Q is None else Fraction(Q)
        Mn = monodromy_matrix(m, tau, Q, model, backend="numpy")
        # the same binary inputs for mpmath (a float given to the API means its shortest decimal)
        exact = [None if v is None else F(v) for v in (m, tau, Q)]
        Mm = monodromy_matrix(*exact, model, dps=30)
        with mpmath.workdps(30):
            err = relnorm(as_mp_matrix(Mn), Mm)
        if err > 1e-13:
            bad.append((m, tau, Q, model, float(err)))
    assert not bad, "numpy and mpmath differ (m, tau, Q, model, rel. diff):\n" + "\n".join(
        map(str, bad)
    )


def test_numpy_broadcasts_over_arrays():
    m = np.array([0.1, 0.3, 0.6])[:, None]
    tau = np.array([0.4, 0.5, 1.0, 1.5])
    M = monodromy_matrix(m, tau, 4.0, "exact", backend="numpy")
    assert M.shape == (3, 4, 2, 2)
    for i in range(3):
        for j in range(4):
            one = monodromy_matrix(float(m[i, 0]), float(tau[j]), 4.0, "exact", backend="numpy")
            np.testing.assert_array_equal(M[i, j], one)
    mu = floquet_multipliers(m, tau, None, backend="numpy")
    assert mu.shape == (3, 4, 2)
    # per-point Q as an array, crossing critical damping for half 1 (Q_c = sqrt(1+m)/2)
    Qs = np.array([0.3, 0.5, 0.7, 2.0])
    M2 = monodromy_matrix(0.4, 1.0, Qs, "exact", backend="numpy")
    for j, Q in enumerate(Qs):
        ref = monodromy_matrix(F(2, 5), F(1), F(Q), "exact", dps=30)
        with mpmath.workdps(30):
            assert relnorm(as_mp_matrix(M2[j]), ref) < 1e-14


# ---------------------------------------------------------------------------------------------
# damping models and regimes


@pytest.mark.parametrize(
    "m, tau, Q",
    [(F(3, 10), F(1, 2), F(3)), (F(4, 5), F(9, 4), F(1, 3)), (F(1, 10**6), F(1), F(50))],
)
def test_paper_model_is_exp_times_undamped(m, tau, Q):
    with mpmath.workdps(40):
        p = mpmath.exp(-mpmath.pi / mp(Q) * mp(tau))
    Mp = monodromy_matrix(m, tau, Q, "paper", dps=40)
    M0 = monodromy_matrix(m, tau, None, dps=40)
    with mpmath.workdps(40):
        assert relnorm(Mp, p * M0) < mpmath.mpf("1e-38")


def test_without_friction_the_model_does_not_matter():
    a = monodromy_matrix(F(1, 3), F(2, 3), None, "exact", dps=30)
    b = monodromy_matrix(F(1, 3), F(2, 3), None, "paper", dps=30)
    assert a == b


def critical_map(g, t):
    """The critically damped half map, from ``phi = (A t + B) exp(-g t)``
    (``A = v0 + g phi0``, ``B = phi0``)."""
    e = mpmath.exp(-g * t)
    return mpmath.matrix([[e * (1 + g * t), e * t], [-(g**2) * t * e, e * (1 - g * t)]])


@pytest.mark.parametrize("half, m, Q", [(1, F(11, 25), F(3, 5)), (2, F(9, 25), F(2, 5))])
def test_exactly_critical_half_matches_the_critical_solution(half, m, Q):
    # 4 Q^2 = 1 + m (half 1) or 1 - m (half 2): that half is critically damped
    assert 4 * Q**2 == (1 + m if half == 1 else 1 - m)
    tau = F(9, 10)
    with mpmath.workdps(40):
        mm, g, t = mp(m), mpmath.pi / mp(Q), mp(tau) / 2
        k = ((1 + mm) / (1 - mm)) ** 2
        w = [4 * mpmath.pi**2 / (1 + mm), 4 * mpmath.pi**2 / (1 - mm)]
        W = mpmath.sqrt(w[2 - half] - g**2)  # the other half is under-damped
        e = mpmath.exp(-g * t)
        c, s = mpmath.cos(W * t), mpmath.sin(W * t) / W
        under = mpmath.matrix([[e * (c + g * s), e * s], [-e * w[2 - half] * s, e * (c - g * s)]])
        U1, U2 = (critical_map(g, t), under) if half == 1 else (under, critical_map(g, t))
        ref = mpmath.diag([1, 1 / k]) * U2 * mpmath.diag([1, k]) * U1
    M = monodromy_matrix(m, tau, Q, "exact", dps=40)
    with mpmath.workdps(40):
        assert relnorm(M, ref) < mpmath.mpf("1e-37")


@pytest.mark.parametrize("m", [F(11, 25), F(9, 10)])
def test_continuous_through_critical_damping(m):
    # half 1 is critical at Q_c = sqrt(1+m)/2; approach it from both sides by 1e-20 relative
    tau = F(6, 5)
    with mpmath.workdps(60):
        Qc = mpmath.sqrt(1 + mp(m)) / 2
        below, above = Qc * (1 - mpmath.mpf("1e-20")), Qc * (1 + mpmath.mpf("1e-20"))
    Ms = [monodromy_matrix(m, tau, Q, "exact", dps=50) for Q in (below, Qc, above)]
    with mpmath.workdps(50):
        assert relnorm(Ms[0], Ms[1]) < mpmath.mpf("1e-18")
        assert relnorm(Ms[2], Ms[1]) < mpmath.mpf("1e-18")
        assert relnorm(Ms[0], Ms[2]) > mpmath.mpf("1e-24")  # the change is real, not frozen
    # numpy at and around the critical value
    Qf = float(Qc)
    Mn = monodromy_matrix(
        float(m), float(tau), np.array([Qf * (1 - 1e-9), Qf, Qf * (1 + 1e-9)]), backend="numpy"
    )
    assert np.all(np.isfinite(Mn))
    np.testing.assert_allclose(Mn[0], Mn[1], rtol=0, atol=1e-7 * np.abs(Mn[1]).max())
    np.testing.assert_allclose(Mn[2], Mn[1], rtol=0, atol=1e-7 * np.abs(Mn[1]).max())


def test_continuous_where_overdamped_formula_switches():
    # half 1 over-damped with sqrt(gamma^2 - omega1^2) T/2 = 1/2 exactly: the two closed forms meet
    m, Q = F(1, 2), F(1, 4)
    with mpmath.workdps(60):
        g, w = mpmath.pi / mp(Q), 4 * mpmath.pi**2 / (1 + mp(m))
        tau0 = 1 / mpmath.sqrt(g**2 - w)
        taus = [tau0 * (1 - mpmath.mpf("1e-30")), tau0, tau0 * (1 + mpmath.mpf("1e-30"))]
    a, c, b = (monodromy_matrix(m, t, Q, dps=40) for t in taus)
    with mpmath.workdps(40):
        # M is smooth in tau: the midpoint of the two sides equals the centre to O(1e-60); a jump
        # between the two closed forms would show here
        assert relnorm((a + b) / 2, c) < mpmath.mpf("1e-37")
        assert relnorm(a, b) > mpmath.mpf("1e-32")


def test_strong_overdamping_does_not_overflow():
    # Q = 1e-3: gamma T/2 ~ 1.6e3, cosh would overflow double precision; det = exp(-2 gamma T)
    M = monodromy_matrix(0.3, 0.5, 1e-3, backend="numpy")
    assert np.all(np.isfinite(M))
    Mm = monodromy_matrix(F(3, 10), F(1, 2), F(1, 1000), dps=30)
    with mpmath.workdps(30):
        assert relnorm(as_mp_matrix(M), Mm) < 1e-13
    # the dominant solution decays slowly (rate ~ omega^2/(2 gamma)), the other one fast
    mu = floquet_multipliers(F(3, 10), F(1, 2), F(1, 1000), dps=30)
    assert 0 < mu[0] < 1


# ---------------------------------------------------------------------------------------------
# closings, multipliers, eigenvectors


@pytest.mark.parametrize(
    "a, b",
    [(1, 2), (1, 3), (2, 3), (1, 4), (3, 4)],
)
def test_closing_depth_gives_plus_or_minus_identity(a, b):
    # docs/theory.md, closings: m = (b^2-a^2)/(b^2+a^2), omega1 T/2 = a pi, i.e. T = a sqrt(1+m) T0
    m = F(b * b - a * a, b * b + a * a)
    with mpmath.workdps(60):
        tau = a * mpmath.sqrt(1 + mp(m))
    M = monodromy_matrix(m, tau, dps=50)
    sign = (-1) ** (a + b)
    with mpmath.workdps(50):
        assert mpmath.mnorm(M - sign * mpmath.eye(2), "F") < mpmath.mpf("1e-45")


def test_multipliers_inside_on_and_outside_the_first_interval():
    m = F(3, 10)
    # inside (T near T_av/2 ~ 0.48): real, negative (odd order), reciprocal
    mu = floquet_multipliers(m, F(1, 2), dps=30)
    assert all(isinstance(x, mpmath.mpf) for x in mu)
    assert mu[0] < -1 < mu[1] < 0
    with mpmath.workdps(30):
        assert abs(mu[0] * mu[1] - 1) < mpmath.mpf("1e-28")
    with mpmath.workdps(30):
        assert growth_factor(m, F(1, 2), dps=30) == abs(mu[0])
    # outside (T = 0.8, between the first and second intervals): a unit-modulus complex pair
    mu = floquet_multipliers(m, F(4, 5), dps=30)
    assert isinstance(mu[0], mpmath.mpc) and mu[0].imag > 0
    assert mu[1].real == mu[0].real and mu[1].imag + mu[0].imag == 0
    with mpmath.workdps(30):
        assert abs(abs(mu[0]) - 1) < mpmath.mpf("1e-28")
    # outside with friction: |mu| = exp(-gamma T)
    with mpmath.workdps(30):
        p = mpmath.exp(-mpmath.pi / 5 * mpmath.mpf("0.8"))
        assert abs(growth_factor(m, F(4, 5), 5, dps=30) - p) < mpmath.mpf("1e-28")
    # the second interval (T near T_av): positive multipliers
    mu = floquet_multipliers(F(7, 10), F(19, 20), dps=30)
    assert mu[0] > 1 > mu[1] > 0


def test_multipliers_numpy_match_mpmath():
    ms = np.array([0.05, 0.3, 0.6, 0.9])
    taus = np.array([0.49, 0.8, 1.0, 1.45])
    for Q in (None, 3.0):
        for model in ("exact", "paper"):
            mun = floquet_multipliers(ms[:, None], taus, Q, model, backend="numpy")
            gn = growth_factor(ms[:, None], taus, Q, model, backend="numpy")
            for i, m in enumerate(ms):
                for j, t in enumerate(taus):
                    mum = floquet_multipliers(float(m), float(t), Q, model, dps=30)
                    for x, y in zip(mun[i, j], mum, strict=True):
                        assert abs(complex(y) - x) <= 1e-12 * max(1.0, abs(complex(y))), (
                            m,
                            t,
                            Q,
                            model,
                        )
                    assert abs(gn[i, j] - float(max(abs(z) for z in mum))) <= 1e-12 * max(
                        1.0, gn[i, j]
                    )


def test_floquet_vector_is_an_eigenvector():
    for m, tau, Q in [
        (F(3, 10), F(1, 2), None),
        (F(3, 10), F(1, 2), F(4)),
        (F(7, 10), F(19, 20), F(9)),
    ]:
        M = monodromy_matrix(m, tau, Q, dps=30)
        for mu in floquet_multipliers(m, tau, Q, dps=30):
            with mpmath.workdps(30):
                v = floquet_vector(M, mu)
                Mv = M * mpmath.matrix(v)
                assert mpmath.norm(Mv - mu * mpmath.matrix(v)) < mpmath.mpf("1e-25") * abs(
                    mu
                ) + mpmath.mpf("1e-27")
                assert abs(mpmath.norm(mpmath.matrix(v)) - 1) < mpmath.mpf("1e-28")
        Mn = monodromy_matrix(
            float(m), float(tau), None if Q is None else float(Q), backend="numpy"
        )
        for mu in floquet_multipliers(
            float(m), float(tau), None if Q is None else float(Q), backend="numpy"
        ):
            v = floquet_vector(Mn, mu)
            assert np.linalg.norm(Mn @ v - mu * v) < 1e-12 * max(1, abs(mu))
    # M = -I (closing): any vector, a unit one is returned
    with mpmath.workdps(30):
        v = floquet_vector(-mpmath.eye(2), mpmath.mpf(-1))
        assert v == (1, 0)


# ---------------------------------------------------------------------------------------------
# hard cases


def test_tiny_depth():
    # m = 1e-12.  At the centre of the first interval (x = pi/2) the odd normal form of
    # docs/theory.md is N = -r^2 cos^2 y ~ -r^2, and det(M + I) = (K+2) N = -4 r^2, so
    # tr M = -2 - 4 r^2 and the larger multiplier is -(1 + 2r + O(r^2)) with r = (q-1)/(q+1) ~ 3m/2:
    # the growth per period exceeds 1 by 3m.
    m = F(1, 10**12)
    excess = growth_factor(m, F(1, 2), dps=40) - 1
    assert mpmath.mpf("2.99e-12") < excess < mpmath.mpf("3.01e-12")
    # outside the interval the multipliers are on the unit circle
    with mpmath.workdps(40):
        assert abs(growth_factor(m, F(6, 10), dps=40) - 1) < mpmath.mpf("1e-38")


def test_depth_near_one_and_high_order():
    # m = 0.999: omega2 ~ 199 omega0; order 100: T ~ 50 T_av, phases ~ 1e4 rad
    for m, tau in [(F(999, 1000), F(3, 10)), (F(1, 3), F(103, 2)), (F(999, 1000), F(11, 2))]:
        Mm = monodromy_matrix(m, tau, None, dps=40)
        with mpmath.workdps(40):
            assert abs(mpmath.det(Mm) - 1) < mpmath.mpf("1e-30") * mpmath.mnorm(Mm, "F") ** 2
        Mn = monodromy_matrix(float(m), float(tau), backend="numpy")
        with mpmath.workdps(40):
            # double precision loses ~ phase * 1e-16 (the phases are up to 2e3 here)
            assert relnorm(as_mp_matrix(Mn), Mm) < 1e-11


def test_precision_is_a_parameter():
    before = mpmath.mp.prec
    M20 = monodromy_matrix(F(1, 3), F(1, 2), dps=20)
    M60 = monodromy_matrix(F(1, 3), F(1, 2), dps=60)
    assert mpmath.mp.prec == before
    assert M20[0, 0].context.prec == before  # plain mpf values, nothing global changed
    with mpmath.workdps(60):
        assert mpmath.mpf("1e-22") < abs(M60[0, 0] - M20[0, 0]) < mpmath.mpf("1e-18")
    # default: the current working precision
    with mpmath.workdps(45):
        M45 = monodromy_matrix(F(1, 3), F(1, 2))
        assert abs(M45[0, 0] - M60[0, 0]) < mpmath.mpf("1e-43")


@pytest.mark.parametrize(
    "kwargs",
    [
        {"m": 0, "tau": 0.5},
        {"m": 1, "tau": 0.5},
        {"m": float("nan"), "tau": 0.5},
        {"m": 0.3, "tau": 0},
        {"m": 0.3, "tau": -1},
        {"m": 0.3, "tau": 0.5, "Q": 0},
        {"m": 0.3, "tau": 0.5, "Q": -2},
        {"m": 0.3, "tau": 0.5, "damping": "approx"},
        {"m": 0.3, "tau": 0.5, "backend": "flint"},
        {"m": 0.3, "tau": 0.5, "dps": 3},
    ],
)
def test_bad_input(kwargs):
    with pytest.raises(InputError):
        monodromy_matrix(**kwargs)


@pytest.mark.parametrize(
    "m, tau, Q",
    [([0.3, 1.2], 0.5, None), (0.3, [0.5, np.nan], None), (0.3, 0.5, [1.0, 0.0]), ("x", 0.5, None)],
)
def test_bad_input_numpy(m, tau, Q):
    with pytest.raises(InputError):
        monodromy_matrix(m, tau, Q, backend="numpy")
