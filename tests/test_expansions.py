"""Series of the interval edges in m: the paper's expansions, closed forms in n, and the error
against high-precision roots computed independently (monodromy trace, built in the tests)."""

from __future__ import annotations

import mpmath
import pytest
import sympy as sp
from pendulum_monodromy import monodromy_mp

from analytic.expansions import (
    MAX_TERMS,
    closed_forms,
    edge_equation,
    edge_series,
    factor_for,
    order_sign,
    small_m_parameters,
    theta_series,
)
from analytic.identity import prove_zero
from analytic.model import S
from analytic.powerseries import LaurentRing, Series, evaluate
from verify.inputs import InputError

m, pi, n = S.m, sp.pi, S.n


# ------------------------------------------------------------------------------------- references


def trace_condition(T, mm, sigma):
    """``tr M - 2 sigma`` from the period map built from the free oscillations and the jumps
    (``tests/pendulum_monodromy.py``: omega_i = 2 pi/sqrt(1 -+ m), J ~ (1 -+ m)^2): independent
    of analytic/."""
    M = monodromy_mp(T, mm)
    return M[0, 0] + M[1, 1] - 2 * sigma


def reference_edge(order: int, mm, guess, dps: int):
    """The root of ``tr M = 2 sigma`` next to ``guess`` (secant from the series value)."""
    sigma = -1 if order % 2 else 1
    with mpmath.workdps(dps):
        mm = mpmath.mpf(mm)
        return mpmath.findroot(
            lambda T: trace_condition(T, mm, sigma),
            mpmath.mpf(guess),
            tol=mpmath.mpf(10) ** (-dps + 8),
        )


def coeffs(expr, k):
    return sp.expand(expr).coeff(m, k)


# ------------------------------------------------------------------------- the paper's expansions


def test_eq7_average_frequency_and_period():
    # eq. (7): omega_av ~ omega_0 (1 + 3 m^2/8), T_av ~ T_0 (1 - 3 m^2/8)
    par = small_m_parameters(4)
    w, invw = par["w"].to_sympy(m), par["1/w"].to_sympy(m)
    assert [coeffs(w, k) for k in range(3)] == [1, 0, sp.Rational(3, 8)]
    assert [coeffs(invw, k) for k in range(3)] == [1, 0, -sp.Rational(3, 8)]
    # next terms, from sympy's own series of the definition (an independent expansion)
    ref = sp.series((1 / sp.sqrt(1 + m) + 1 / sp.sqrt(1 - m)) / 2, m, 0, 5).removeO()
    assert sp.expand(w - ref) == 0


def test_eq18_first_interval():
    es = edge_series(1, 4)
    # eq. (18): T-+ = (1/2)(1 -+ 3m/pi) T_av = (1/2)(1 -+ 3m/pi - 3m^2/8) T_0, through m^2
    for name, sign in (("lower", -1), ("upper", 1)):
        tav, t0 = es.in_Tav[name], es.in_T0[name]
        assert [coeffs(tav, k) for k in range(3)] == [sp.Rational(1, 2), sign * 3 / (2 * pi), 0]
        assert [coeffs(t0, k) for k in range(3)] == [
            sp.Rational(1, 2),
            sign * 3 / (2 * pi),
            -sp.Rational(3, 16),
        ]


def test_eq19_third_interval_and_its_shift():
    es = edge_series(3, 4)
    for name, sign in (("lower", -1), ("upper", 1)):
        # eq. (19): (3/2)(1 -+ m/pi) T_av = (3/2)(1 -+ m/pi - 3m^2/8) T_0
        assert [coeffs(es.in_Tav[name], k) for k in range(3)] == [
            sp.Rational(3, 2),
            sign * 3 / (2 * pi),
            0,
        ]
        assert [coeffs(es.in_T0[name], k) for k in range(3)] == [
            sp.Rational(3, 2),
            sign * 3 / (2 * pi),
            -sp.Rational(9, 16),
        ]
    # text after (19): centre (9/16) m^2 T_0 left of (3/2) T_0, width (3m/pi) T_0 as for n = 1
    centre = sp.expand((es.in_T0["lower"] + es.in_T0["upper"]) / 2)
    assert coeffs(centre, 2) == -sp.Rational(9, 16)
    width3 = sp.expand(es.in_T0["upper"] - es.in_T0["lower"])
    width1 = sp.expand(edge_series(1, 4).in_T0["upper"] - edge_series(1, 4).in_T0["lower"])
    assert coeffs(width3, 1) == coeffs(width1, 1) == 3 / pi


def test_eq27_second_interval():
    es = edge_series(2, 4)
    # eq. (27): (1 -+ 3m^2/4) T_av; T- = T0 (1 - 9m^2/8), T+ = T0 (1 + 3m^2/8); width (3/2) m^2 T0
    assert [coeffs(es.in_Tav["lower"], k) for k in range(4)] == [1, 0, -sp.Rational(3, 4), 0]
    assert [coeffs(es.in_Tav["upper"], k) for k in range(4)] == [1, 0, sp.Rational(3, 4), 0]
    assert [coeffs(es.in_T0["lower"], k) for k in range(4)] == [1, 0, -sp.Rational(9, 8), 0]
    assert [coeffs(es.in_T0["upper"], k) for k in range(4)] == [1, 0, sp.Rational(3, 8), 0]


def test_next_orders_first_interval():
    """m^3, m^4 of the first interval (beyond the paper).  Reference: the fixed-point form of
    eq. (15), sin(theta) = -(q-1)/(q+1) cos(beta (pi/2 + theta)), iterated with sympy polynomial
    algebra and Taylor polynomials of cos and asin, from sympy's series of q and beta (a route
    that shares nothing with analytic.powerseries)."""

    def trunc(e, k=4):
        e = sp.expand(e)
        return sum(e.coeff(m, j) * m**j for j in range(k + 1))

    q = ((1 + m) / (1 - m)) ** sp.Rational(3, 2)
    rq = sp.series((q - 1) / (q + 1), m, 0, 6).removeO()
    bq = sp.series(m / (1 + sp.sqrt(1 - m**2)), m, 0, 6).removeO()
    th = sp.Integer(0)
    for _ in range(5):
        u = trunc(bq * (pi / 2 + th))
        v = trunc(-rq * trunc(1 - u**2 / 2 + u**4 / 24))
        th = trunc(v + v**3 / 6)
    ref = sp.Rational(1, 2) + th / pi
    es = edge_series(1, 4)
    assert sp.expand(ref - es.in_Tav["lower"]) == 0
    assert coeffs(es.in_Tav["lower"], 3) == 1 / (16 * pi) + 3 * pi / 64
    assert coeffs(es.in_Tav["lower"], 4) == -sp.Rational(9, 32)


# -------------------------------------------------------------------------------------- structure


@pytest.mark.parametrize("order", [2, 4, 6, 10])
def test_even_orders_are_even_in_m(order):
    # m -> -m swaps the halves (a shift of time by T/2): even-order edges are even functions of m
    es = edge_series(order, 9)
    for name in ("lower", "upper"):
        for k in range(1, 10, 2):
            assert coeffs(es.in_T0[name], k) == 0


@pytest.mark.parametrize("order", [1, 3, 5, 7])
def test_odd_orders_centre_even_halfwidth_odd(order):
    es = edge_series(order, 9)
    lo, hi = es.in_T0["lower"], es.in_T0["upper"]
    centre, half = sp.expand((lo + hi) / 2), sp.expand((hi - lo) / 2)
    assert all(coeffs(centre, k) == 0 for k in range(1, 10, 2))
    assert all(coeffs(half, k) == 0 for k in range(0, 10, 2))


def test_closed_forms_in_n():
    cf = closed_forms(4)
    # leading width: 3m/pi T_av for every odd order, (3n/4) m^2 T_av for every even order;
    # centre shift -(3n/16) m^2 T_0 for both parities (the shift of n T_av/2, eq. 7)
    assert cf["odd"]["width_leading_Tav"] == 3 * m / pi
    assert sp.simplify(cf["even"]["width_leading_Tav"] - sp.Rational(3, 4) * n * m**2) == 0
    for word in ("odd", "even"):
        assert sp.simplify(cf[word]["centre_leading_T0"] + sp.Rational(3, 16) * n * m**2) == 0
    # the symbolic-n series is the integer-n series for every order of that parity
    o, e = edge_series("odd", 6), edge_series("even", 6)
    for k, es in ((1, o), (3, o), (5, o), (9, o), (2, e), (4, e), (8, e)):
        ref = edge_series(k, 6)
        for units in ("in_T0", "in_Tav"):
            for name in ("lower", "upper"):
                assert (
                    sp.expand(getattr(es, units)[name].subs(n, k) - getattr(ref, units)[name]) == 0
                )


# --------------------------------------------------------------------- which factor is which edge


def test_order_sign_and_lower_factor():
    # f(n pi/2 + theta) = c_n sin(theta); eq. (13)'s factor (eps = +1) is the lower edge iff
    # c_n = -1
    assert [order_sign(k) for k in range(1, 9)] == [-1, -1, 1, 1, -1, -1, 1, 1]
    assert [edge_series(k, 2).lower_factor for k in range(1, 9)] == [1, 1, -1, -1, 1, 1, -1, -1]


@pytest.mark.parametrize("order", [1, 2, 3, 4, 7, 12])
def test_edge_equation_is_the_normal_form_factor(order):
    for delta in (-1, 1):
        eps, factor = factor_for(order, delta)
        c = order_sign(order)
        assert prove_zero(sp.expand(factor - c * edge_equation(order, delta))).holds


def test_lower_edge_is_the_smaller_root():
    for order in range(1, 9):
        es = edge_series(order, 4)
        d = sp.expand(es.in_T0["upper"] - es.in_T0["lower"])
        assert sp.N(d.subs(m, sp.Rational(1, 100))) > 0


# ---------------------------------------------------------------------------- parameter relations


def test_beta_relations_hold_as_series():
    # theory: beta = m/(1 + sqrt(1-m^2)), m = 2 beta/(1+beta^2), r = beta(3+beta^2)/(1+3beta^2),
    # w = sqrt(1+beta^2)/(1-beta^2): each checked through m^12 against the series expanded from the
    # definitions (omega_i, q) in analytic.normal_form.parameters
    P = 12
    par = small_m_parameters(P)
    ring = par["beta"].ring
    b = sp.Symbol("b")
    env = {b: par["beta"]}
    checks = {
        "beta": (m / (1 + sp.sqrt(1 - m**2)), False),
        "m": (2 * b / (1 + b**2), True),
        "r": (b * (3 + b**2) / (1 + 3 * b**2), True),
        "w": (sp.sqrt(1 + b**2) / (1 - b**2), True),
    }
    for name, (expr, in_beta) in checks.items():
        got = evaluate(expr, env if in_beta else {}, ring, P, var=m)
        want = Series.variable(ring, P) if name == "m" else par[name]
        assert got.equals(want), name


def test_powerseries_against_sympy_series():
    ring = LaurentRing(["pi"])
    expr = (
        sp.sin(pi * m / 2 + m**2) * sp.sqrt(1 + m) / (1 - m) ** sp.Rational(3, 2) + sp.cosh(m) ** 3
    )
    got = evaluate(expr, {}, ring, 8, var=m).to_sympy(m)
    ref = sp.series(expr, m, 0, 9).removeO()
    assert sp.simplify(sp.expand(got - ref)) == 0


# -------------------------------------------------------------------------- numbers against roots


def _error_profile(order, K, name, ms, dps=90):
    es = edge_series(order, K)
    longer = edge_series(order, min(K + 4, MAX_TERMS))
    f = sp.lambdify(m, es.in_T0[name], "mpmath")
    rest = sp.expand(longer.in_T0[name] - es.in_T0[name])
    p = min(k for k in range(K + 1, min(K + 4, MAX_TERMS) + 1) if coeffs(rest, k) != 0)
    cp = sp.N(coeffs(rest, p), 30)
    errs = []
    with mpmath.workdps(dps):
        for mm in ms:
            mm = mpmath.mpf(mm)
            guess = f(mm)
            root = reference_edge(order, mm, guess, dps)
            errs.append(abs(root - guess))
    return p, mpmath.mpf(str(abs(cp))), errs


def _fit(xs, ys):
    n_ = len(xs)
    mx, my = sum(xs) / n_, sum(ys) / n_
    num = sum((x - mx) * (y - my) for x, y in zip(xs, ys, strict=True))
    return num / sum((x - mx) ** 2 for x in xs)


@pytest.mark.parametrize("order", [1, 2, 3, 4, 5, 6])
@pytest.mark.parametrize("K", [2, 4, 8])
def test_error_falls_like_the_first_omitted_power(order, K):
    """|series - root| ~ |c_p| m^p with p >= K+1 the first omitted non-zero power (the error
    must be the omitted term itself: ratio to it -> 1, and the log-log slope is p)."""
    ms = ["1e-4", "3e-4", "1e-3", "3e-3", "1e-2"]
    for name in ("lower", "upper"):
        p, cp, errs = _error_profile(order, K, name, ms)
        assert p >= K + 1
        with mpmath.workdps(30):
            xs = [mpmath.log(mpmath.mpf(x)) for x in ms]
            ys = [mpmath.log(e) for e in errs]
            # least-squares slope over m in [1e-4, 1e-3]; tolerance 0.1 (the next term is O(m))
            slope = _fit(xs[:3], ys[:3])
            assert abs(slope - p) < 0.1, (order, K, name, slope, p)
            # the error is the omitted term: relative tolerance 5 % at m = 1e-4
            ratio = errs[0] / (cp * mpmath.mpf(ms[0]) ** p)
            assert abs(ratio - 1) < 0.05, (order, K, name, ratio)
            # and err / m^p stays bounded (within a factor 10 of |c_p|) up to m = 1e-2
            scaled = [e / mpmath.mpf(x) ** p for e, x in zip(errs, ms, strict=False)]
            assert max(scaled) < 10 * cp and min(scaled) > cp / 10, (order, K, name)


def test_tiny_depth():
    # m = 1e-12: the series through m^4 must agree with the root to ~60 digits (error ~ m^5)
    for order in (1, 2, 3):
        es = edge_series(order, 4)
        for name in ("lower", "upper"):
            with mpmath.workdps(120):
                mm = mpmath.mpf("1e-12")
                val = sp.lambdify(m, es.in_T0[name], "mpmath")(mm)
                root = reference_edge(order, mm, val, 120)
                assert abs(root - val) < mpmath.mpf("1e-58")
                # and the edges are resolved: width ~ 3m/pi (odd) or (3/2) m^2 (even)
        w = sp.lambdify(m, sp.expand(es.in_T0["upper"] - es.in_T0["lower"]), "mpmath")
        with mpmath.workdps(60):
            assert w(mpmath.mpf("1e-12")) > 0


def test_high_order_100():
    es = edge_series(100, 6)
    for name in ("lower", "upper"):
        with mpmath.workdps(80):
            mm = mpmath.mpf("1e-5")
            val = sp.lambdify(m, es.in_T0[name], "mpmath")(mm)
            root = reference_edge(100, mm, val, 80)
            # first omitted term ~ (n pi m)^8 m^0 / ... : bounded by 1e-20 here
            assert abs(root - val) < mpmath.mpf("1e-20")


def test_twelve_terms_any_order():
    for order in (1, 2, 7):
        es = edge_series(order, 12)
        assert sp.Poly(es.in_T0["lower"], m).degree() <= 12
        assert coeffs(es.in_T0["lower"], 12) != 0 or order % 2 == 0


# -------------------------------------------------------------------------------------- bad input


@pytest.mark.parametrize(
    "kwargs",
    [
        {"order": 0},
        {"order": -3},
        {"order": 1.5},
        {"order": "x"},
        {"order": 1, "terms": 0},
        {"order": 1, "terms": 41},
        {"order": "odd", "terms": 25},
        {"order": 1, "terms": 13, "Q": 7},
        {"order": 1, "terms": True},
        {"order": 1, "units": "s"},
        {"order": 1, "Q": 0},
        {"order": 1, "Q": -2},
        {"order": 1, "Q": float("nan")},
        {"order": 1, "Q": 2, "damping": "x"},
    ],
)
def test_bad_input(kwargs):
    with pytest.raises(InputError):
        edge_series(**kwargs)


def test_theta_series_is_cached_and_exact():
    a = theta_series(3, -1, 6)
    b = theta_series(3, -1, 6)
    assert a is b
    assert a.c[0] == {}


@pytest.mark.parametrize("order", [1, 2, 3, 4, 5, 6])
def test_against_certified_boundaries(order):
    """Cross-check with verify.boundary (certified per-edge roots, 40 digits, another route): at
    m = 1e-3 the series through m^12 agrees with the certified edges to 1e-32 absolute (its first
    omitted term is ~ m^13 = 1e-39 times a coefficient below 1e4 for these orders)."""
    from verify import boundary

    b = boundary(order, "0.001", digits=40)
    es = edge_series(order, 12)
    for name in ("lower", "upper"):
        with mpmath.workdps(60):
            val = sp.lambdify(m, es.in_T0[name], "mpmath")(mpmath.mpf("0.001"))
            assert abs(val - mpmath.mpf(str(getattr(b, name)))) < mpmath.mpf("1e-32"), (order, name)


@pytest.mark.parametrize("order", [1, 2])
def test_series_with_friction_for_torsion_is_one_route_and_meets_certified_edges(order):
    """``paramres.series(order, K, Q=..., system="torsion")`` goes through
    :func:`analytic.thresholds.near_threshold_edges` (equal expressions), and agrees with the
    certified edges of ``paramres.boundary(..., Q=..., system="torsion")`` (ball arithmetic, another
    route) to the order of its truncation.

    The series is in powers of ``m`` at fixed ``nu = (m_min0/m)^p`` (``m_min0 = pi/(2Q)`` for
    order 1, ``p = 1``; ``sqrt(2/Q)`` for order 2, ``p = 2``, from ``threshold_series``): at a
    fixed ``Q`` it is not a Taylor series in ``m``, so the bound tested is the one along fixed
    ``nu = 0.6``: halving ``m`` (and scaling ``Q`` like ``m^-p``) divides the error by
    ``2^(K+1)`` (slope in ``log m`` above ``K + 0.9``), and the error is the first omitted terms
    (series through ``m^(K+2)`` minus through ``m^K``) to 15 %.  The certified edges are exact to
    ``1e-25``, far below the errors (measured 1e-12 and above)."""
    from fractions import Fraction

    import paramres
    from analytic.system import system
    from analytic.thresholds import near_threshold_edges, threshold_series

    K = 2
    torsion = system("torsion")
    es = paramres.series(order, K, Q=7, system="torsion")
    direct = near_threshold_edges(order, K, Q=7, system=torsion)
    for name in ("lower", "upper"):
        assert sp.simplify(es.in_T0[name] - direct.in_T0[name]) == 0
        assert sp.simplify(es.in_Tav[name] - direct.in_Tav[name]) == 0
    th = threshold_series(order, 1, system="torsion")
    (Q,) = th.m_min_leading.free_symbols
    c = th.m_min_leading * Q ** sp.Rational(1, th.p)  # m_min0 = c Q^(-1/p)
    assert sp.simplify(sp.diff(c, Q)) == 0
    ms = ["0.002", "0.004"]
    errs, preds = {"lower": [], "upper": []}, {"lower": [], "upper": []}
    for x in ms:
        mm = mpmath.mpf(x)
        with mpmath.workdps(40):
            q = Fraction(mpmath.nstr(mpmath.mpf(str(sp.N(c**th.p, 45))) / (0.6 * mm**th.p), 30))
        short = paramres.series(order, K, Q=q, system="torsion")
        longer = paramres.series(order, K + 2, Q=q, system="torsion")
        b = paramres.boundary(order, x, Q=q, system="torsion", digits=25)
        assert b.exists
        for name in ("lower", "upper"):
            with mpmath.workdps(40):
                f = sp.lambdify(m, short.in_T0[name], "mpmath")(mm)
                g = sp.lambdify(m, longer.in_T0[name] - short.in_T0[name], "mpmath")(mm)
                errs[name].append(abs(mpmath.mpf(str(getattr(b, name))) - f))
                preds[name].append(abs(g))
    for name in ("lower", "upper"):
        slope = mpmath.log(errs[name][1] / errs[name][0]) / mpmath.log(2)
        assert slope > K + 0.9, (order, name, slope, errs[name])
        assert errs[name][0] > mpmath.mpf("1e-15")
        for e, p in zip(errs[name], preds[name], strict=True):
            assert abs(e / p - 1) < 0.15, (order, name, e, p)
