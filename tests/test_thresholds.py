"""Friction: thresholds (tangency) and near-threshold edges in both damping models, checked against
the printed formulas (38), (40), (43), (45), section 6, and against high-precision numbers from a
period map of :mod:`tests.pendulum_monodromy` (pure mpmath, independent of analytic/)."""

from __future__ import annotations

from functools import cache

import mpmath
import pytest
import sympy as sp

import analytic.catalogue_series  # noqa: F401  (registers the rows)
from analytic.catalogue import _REGISTRY as ROWS
from analytic.expansions import edge_series
from analytic.model import S
from analytic.thresholds import (
    model_gap,
    near_threshold_edges,
    scaled_edges,
    threshold_lambda,
    threshold_series,
    tuning_threshold,
)
from tests.pendulum_monodromy import damped_monodromy_mp
from verify.inputs import InputError

m, Q, pi, n = S.m, S.Q, sp.pi, S.n
s = sp.Symbol("s", positive=True)


# -------------------------------------------------------------------------------------- reference


def det_condition(T, mm, QQ, sigma, model):
    """``det(M - sigma I)`` of the period map with friction: ``paper``: exp(-gamma t) times the
    undamped half-period map (eqs. 28-30); ``exact``: the damped oscillator (the pure-mpmath
    reference :func:`tests.pendulum_monodromy.damped_monodromy_mp`)."""
    M = damped_monodromy_mp(T, mm, QQ, model) - sigma * mpmath.eye(2)
    return M[0, 0] * M[1, 1] - M[0, 1] * M[1, 0]


@cache
def reference_threshold(order: int, QQ: int, model: str, dps: int = 50):
    """(m_min, T_min) where the interval of order ``order`` shrinks to a point at quality ``QQ``:
    det(M - sigma I) = 0 and its T-derivative = 0, solved from the leading-order guess."""
    sigma = -1 if order % 2 else 1
    with mpmath.workdps(dps):
        q = mpmath.mpf(QQ)
        m0 = order * mpmath.pi / (6 * q) if order % 2 else mpmath.sqrt(mpmath.mpf(2) / (3 * q))
        T0 = mpmath.mpf(order) / 2

        def F(T, mm):
            return det_condition(T, mm, q, sigma, model)

        sol = mpmath.findroot(
            [F, lambda T, mm: mpmath.diff(lambda tt: F(tt, mm), T)],
            (T0, m0),
            tol=mpmath.mpf(10) ** (-dps + 10),
        )
        return sol[1], sol[0]


def first_power(expr, var, after, upto):
    e = sp.expand(expr)
    for k in range(after + 1, upto + 1):
        if sp.expand(e.coeff(var, k)) != 0:
            return k
    raise AssertionError("no non-zero term")


# ---------------------------------------------------------------------------------- leading terms


@pytest.mark.parametrize("model", ["paper", "exact"])
def test_leading_thresholds_all_orders(model):
    # m_min = n pi/(6Q) for every odd n (eq. 38: n = 1; section 6: pi/(2Q) for n = 3);
    # m_min = sqrt(2/(3Q)) for every even n (eq. 43: n = 2)
    for order in (1, 3, 5, 7):
        assert (
            sp.simplify(
                threshold_series(order, 2, damping=model).m_min_leading - order * pi / (6 * Q)
            )
            == 0
        )
    for order in (2, 4, 6):
        assert (
            sp.simplify(
                threshold_series(order, 2, damping=model).m_min_leading - sp.sqrt(2 / (3 * Q))
            )
            == 0
        )
    assert (
        sp.simplify(threshold_series("odd", 2, damping=model).m_min_leading - n * pi / (6 * Q)) == 0
    )
    assert (
        sp.simplify(threshold_series("even", 2, damping=model).m_min_leading - sp.sqrt(2 / (3 * Q)))
        == 0
    )


def test_eq38_and_eq43_as_printed():
    eps = sp.Symbol("epsilon", positive=True)
    th1 = threshold_series(1, 4, damping="paper")
    e1 = sp.expand(th1.m_min.subs(Q, 1 / eps))
    assert e1.coeff(eps, 1) == pi / 6 and e1.coeff(eps, 2) == 0  # eq. (38): m_min ~ pi/(6Q)
    assert sp.limit(th1.Q_min * m, m, 0) == pi / 6  # Q_min ~ pi/(6m)
    th2 = threshold_series(2, 4, damping="paper")
    e2 = sp.expand(th2.m_min2.subs(Q, 1 / eps))
    assert e2.coeff(eps, 1) == sp.Rational(2, 3)  # eq. (43): m_min^2 ~ 2/(3Q)
    assert sp.limit(th2.Q_min * m**2, m, 0) == sp.Rational(2, 3)  # Q_min ~ 2/(3 m^2)
    th3 = threshold_series(3, 4, damping="paper")
    assert sp.expand(th3.m_min.subs(Q, 1 / eps)).coeff(eps, 1) == pi / 2  # section 6: pi/(2Q)


def test_models_part_at_relative_order_one_over_Q_squared():
    # gamma^2 ~ 1/Q^2 enters the exact model's damped frequencies: lambda(m) and the edges
    # differ from the paper model's first at m^2 (odd orders, 1/Q ~ m) and m^4 (even, 1/Q ~ m^2)
    for order in (1, 3):
        assert model_gap(order, 4) == {"threshold": 2, "edges_T0": 2, "edges_Tav": 2, "p": 1}
    for order in (2, 4):
        assert model_gap(order, 5) == {"threshold": 4, "edges_T0": 4, "edges_Tav": 4, "p": 2}


def test_centre_shift_with_friction_closed_form():
    # odd n: (T+ + T-)/(2 T_av) = n/2 - (9/(2 pi^2 n)) nu^2 m^2 + ... (paper) and half that
    # (exact); with nu m = n pi/(6Q): -n/(8Q^2) and -n/(16Q^2)
    for model, c in (("paper", sp.Rational(9, 2)), ("exact", sp.Rational(9, 4))):
        e = scaled_edges("odd", 3, model)
        centre = sp.expand((e["lower"]["Tav"] + e["upper"]["Tav"]) / 2)
        assert sp.simplify(centre.coeff(m, 2) - c * (s**2 - 1) / (pi**2 * n)) == 0


# --------------------------------------------------------------------------- near-threshold edges


@pytest.mark.parametrize("model", ["paper", "exact"])
def test_edges_reduce_to_the_frictionless_series(model):
    # s = 1 is nu = 0 (Q -> infinity): the near-threshold series become the frictionless ones
    for order in (1, 2, 3):
        e = scaled_edges(order, 4, model)
        ref = edge_series(order, 4)
        for name in ("lower", "upper"):
            assert sp.expand(e[name]["T0"].subs(s, 1) - ref.in_T0[name]) == 0
            assert sp.expand(e[name]["Tav"].subs(s, 1) - ref.in_Tav[name]) == 0


def test_eq40_lost_factor_three_and_eq45():
    e1 = scaled_edges(1, 3, "paper")
    # derived: T/T_av = 1/2 -+ (3/(2 pi)) m s; printed eq. (40): 1/2 -+ (1/(2 pi)) m s
    assert sp.expand(e1["lower"]["Tav"]).coeff(m, 1) == -3 * s / (2 * pi)
    assert sp.expand(e1["upper"]["Tav"]).coeff(m, 1) == 3 * s / (2 * pi)
    # eq. (45): 1 -+ (3/4) sqrt(m^4 - m_min^4) = 1 -+ (3/4) m^2 s
    e2 = scaled_edges(2, 3, "paper")
    assert sp.expand(e2["lower"]["Tav"]).coeff(m, 2) == -sp.Rational(3, 4) * s
    assert sp.expand(e2["upper"]["Tav"]).coeff(m, 2) == sp.Rational(3, 4) * s
    assert sp.expand(e2["lower"]["Tav"]).coeff(m, 3) == 0
    # section 6, third interval: 3/2 -+ (3/(2 pi)) m s with m_min = pi/(2Q)
    e3 = scaled_edges(3, 3, "paper")
    assert sp.expand(e3["upper"]["Tav"]).coeff(m, 1) == 3 * s / (2 * pi)
    # every even order: n/2 -+ (3n/8) m^2 s
    ee = scaled_edges("even", 3, "exact")
    assert sp.simplify(sp.expand(ee["upper"]["Tav"]).coeff(m, 2) - sp.Rational(3, 8) * n * s) == 0


@pytest.mark.parametrize("order", [1, 2, 3])
@pytest.mark.parametrize("model", ["paper", "exact"])
@pytest.mark.parametrize("K", [2, 4])
def test_near_threshold_edges_against_roots(order, model, K):
    """At fixed nu = (m_min0/m)^p = 0.6 the error against the root of det(M - sigma I) falls like
    the first omitted power of m (slope within 0.1; the error is that term to 10 %)."""
    sigma = -1 if order % 2 else 1
    es = near_threshold_edges(order, K, damping=model)
    longer = near_threshold_edges(order, K + 3, damping=model)
    ms = ["0.001", "0.002", "0.004"]
    nu = mpmath.mpf("0.6")
    for name in ("lower", "upper"):
        f = sp.lambdify((m, Q), es.in_T0[name], "mpmath")
        g = sp.lambdify((m, Q), longer.in_T0[name] - es.in_T0[name], "mpmath")
        errs, preds = [], []
        with mpmath.workdps(50):
            for x in ms:
                mm = mpmath.mpf(x)
                QQ = order * mpmath.pi / (6 * nu * mm) if order % 2 else 2 / (3 * nu * mm**2)
                guess = f(mm, QQ)
                root = mpmath.findroot(
                    lambda T, mm=mm, QQ=QQ: det_condition(T, mm, QQ, sigma, model),
                    guess,
                    tol=mpmath.mpf(10) ** -44,
                )
                errs.append(abs(root - guess))
                preds.append(abs(g(mm, QQ)))
            slope = mpmath.log(errs[-1] / errs[0]) / mpmath.log(
                mpmath.mpf(ms[-1]) / mpmath.mpf(ms[0])
            )
            pslope = mpmath.log(preds[-1] / preds[0]) / mpmath.log(
                mpmath.mpf(ms[-1]) / mpmath.mpf(ms[0])
            )
            assert slope > K + 0.9, (order, model, K, name, slope)
            assert abs(slope - pslope) < 0.1, (order, model, K, name, slope, pslope)
            assert abs(errs[0] / preds[0] - 1) < 0.1, (order, model, K, name)


# --------------------------------------------------------------------- thresholds against numbers


CASES = [(1, (20, 40, 80)), (3, (60, 120, 240)), (2, (300, 1000, 3000))]


@pytest.mark.parametrize("order,Qs", CASES)
@pytest.mark.parametrize("model", ["paper", "exact"])
@pytest.mark.parametrize("K", [2, 4])
def test_threshold_against_numerical_tangency(order, Qs, model, K):
    """m_min(Q) through 1/Q^K (m_min^2 for even orders) against the numerically solved tangency:
    the relative error falls like the first omitted power of 1/Q."""
    th = threshold_series(order, K, damping=model)
    longer = threshold_series(order, K + 2, damping=model)
    eps = sp.Symbol("epsilon", positive=True)
    series = th.m_min2 if order % 2 == 0 else th.m_min
    more = longer.m_min2 if order % 2 == 0 else longer.m_min
    p = first_power(sp.expand((more - series).subs(Q, 1 / eps)), eps, K, K + 2)
    f = sp.lambdify(Q, th.m_min, "mpmath")
    fT = sp.lambdify(m, th.T_T0, "mpmath")
    errs = []
    with mpmath.workdps(50):
        for QQ in Qs:
            ref_m, ref_T = reference_threshold(order, QQ, model)
            errs.append(abs(f(mpmath.mpf(QQ)) - ref_m) / ref_m)
            # the period at the threshold, from the series along the threshold curve
            assert abs(fT(ref_m) - ref_T) < mpmath.mpf(ref_m) ** (K + 1) * 100
        slope = mpmath.log(errs[-1] / errs[0]) / mpmath.log(mpmath.mpf(Qs[0]) / Qs[-1])
    expected = p - 1  # relative to the leading 1/Q (m_min, odd) or 1/Q (m_min^2, even)
    assert abs(slope - expected) < 0.1, (order, model, K, slope, expected)


def test_threshold_is_below_exact_tuning_for_odd_orders():
    # the double root sits at theta* = -9 m^2/(2 pi n) + ..., below exact tuning (friction costs
    # less on a shorter period); for even orders the shift starts only at m^6
    th = threshold_series(1, 4, damping="paper")
    assert sp.expand(th.theta).coeff(m, 2) == -9 / (2 * pi)
    assert sp.expand(threshold_series("odd", 4, damping="exact").theta).coeff(m, 2) == -9 / (
        2 * pi * n
    )
    assert sp.expand(threshold_series(2, 6, damping="paper").theta).coeff(m, 4) == 0
    ref_m, ref_T = reference_threshold(1, 40, "paper")
    with mpmath.workdps(50):
        Tav = 2 / (1 / mpmath.sqrt(1 + ref_m) + 1 / mpmath.sqrt(1 - ref_m))
        assert ref_T < Tav / 2


def test_exact_tuning_threshold_is_right_only_at_leading_order():
    # eqs. (37), (42) read at exact tuning = R(theta = 0) = 0: right at leading order, wrong at
    # relative m^2 (odd; 1/Q^2) and m^8 (n = 2; 1/Q^4)
    d1 = sp.expand(tuning_threshold(1, 4, "paper") - threshold_lambda(1, 4, "paper"))
    assert (
        d1.coeff(m, 0) == 0
        and d1.coeff(m, 1) == 0
        and sp.simplify(d1.coeff(m, 2) + 27 / pi**3) == 0
    )
    d2 = sp.expand(tuning_threshold(2, 8, "paper") - threshold_lambda(2, 8, "paper"))
    assert all(d2.coeff(m, k) == 0 for k in range(8)) and d2.coeff(m, 8) != 0


# --------------------------------------------------------------------------------- catalogue rows


@pytest.mark.parametrize(
    "label,status",
    [
        ("37", "differs"),
        ("38", "agrees"),
        ("40", "differs"),
        ("42", "differs"),
        ("43", "agrees"),
        ("45", "agrees"),
        ("§6-n3", "agrees"),
    ],
)
def test_catalogue_rows_friction(label, status):
    row = ROWS[label]()
    assert row.status == status, row.how
    assert row.printed and row.derived and row.how
    if label == "40":
        assert "factor 3" in row.how


@pytest.mark.parametrize("label,power", [("§6-n3", 2), ("40", 2), ("45", 4)])
def test_catalogue_rows_define_s_before_the_series_use_it(label, power):
    """The near-threshold series are in ``s``: the derived forms state ``s`` before the first
    one that uses it (a reader meets the derived forms before the verdict)."""
    import re

    items = [x.strip() for x in re.split(r",\\quad\s*", ROWS[label]().derived)]
    uses = [i for i, x in enumerate(items) if re.search(r"(?<![\\a-zA-Z])s(?![a-zA-Z])", x)]
    assert uses, items
    first = items[uses[0]]
    assert first == (rf"s = \sqrt{{1 - \frac{{m_{{\min}}^{{{power}}}}}{{m^{{{power}}}}}}}"), first


def test_bad_input():
    with pytest.raises(InputError):
        threshold_series(0)
    with pytest.raises(InputError):
        threshold_series(1, 13)
    with pytest.raises(InputError):
        threshold_series(1, damping="viscous")
    with pytest.raises(InputError):
        edge_series(1, 2, Q="-3")


# ------------------------------------------------------------------ the other members of the family


FAMILY_CASES = [
    # (system, duty, order, model, Q): p = 1 unless n D is an integer
    ("torsion", "1/2", 1, "exact", 200),
    ("meissner", "1/3", 2, "paper", 200),
    ("pendulum", "1/3", 3, "exact", 20000),  # n D = 1: p = 2, m_min a series in Q^(-1/2)
    ("torsion", "1/50", 1, "paper", 5000),  # extreme duty: f(A) = cos(12 pi/25) is small
]


@pytest.mark.parametrize("name, duty, n, model, QQ", FAMILY_CASES)
def test_family_threshold_series_against_the_floquet_tangency(name, duty, n, model, QQ):
    """``m_min(Q)`` through ``K`` terms against the depth where the Floquet route's ``det(M - sigma
    I)`` has a double root in ``T`` (``tests/floquet_tangency.py``, mpmath at 40 digits): the error
    falls like ``m*^(K+1)`` (constant below 20 in every case; measured 0.003 to 8.6)."""
    from fractions import Fraction

    from floquet_tangency import tangency

    from analytic.system import system
    from verify.solve import boundary

    sysv = system(name, duty=duty)
    values = []
    for K in (1, 2, 3):
        th = threshold_series(n, K, damping=model, system=sysv)
        assert th.system == sysv and th.as_json()["system"] == name
        values.append(mpmath.mpf(str(sp.N(th.m_min.subs(Q, QQ), 30))))
    # a start for the tangency: the centre of the interval just above the series' threshold
    mm = Fraction(mpmath.nstr(values[-1] * (1 + mpmath.mpf(10) ** -3), 20))
    b = boundary(n, mm, Q=QQ, damping=model, system=sysv, digits=15)
    m_ref, _T = tangency(n, QQ, values[-1], (b.lower + b.upper) / 2, **_sys(name, duty, model))
    for K, v in zip((1, 2, 3), values, strict=True):
        assert abs(v - m_ref) < 20 * m_ref ** (K + 1), (K, v, m_ref)
    assert abs(values[-1] - m_ref) < abs(values[0] - m_ref)


def _sys(name, duty, model):
    return {"system": name, "duty": duty, "damping": model}


def test_family_scaling_power_follows_the_vanishing_harmonic():
    """``p = 2`` exactly where the frictionless width is ``O(m^2)``, read off the family's edge
    series (:mod:`analytic.family_series`, the per-edge factor): the m^1 coefficient of the width
    vanishes iff ``n D`` is an integer."""
    from analytic.family_series import family_edge_series
    from analytic.system import system
    from analytic.thresholds import family_scaling_power

    for name, duty in (("pendulum", "1/3"), ("torsion", "1/2"), ("meissner", "1/4")):
        sysv = system(name, duty=duty)
        for n in (1, 2, 3, 4):
            es = family_edge_series(n, 2, "T0", sysv)
            width1 = sp.simplify(sp.expand(es.in_T0["upper"] - es.in_T0["lower"]).coeff(m, 1))
            p = family_scaling_power(n, sysv)
            assert p == (2 if width1 == 0 else 1), (name, duty, n)
            assert (p == 2) == ((n * sysv.duty).denominator == 1)


def test_family_leading_threshold_duty_one_third():
    """Pendulum at D = 1/3, order 1: ``r ~ 3m/2`` and ``f(A) = cos(pi/6)``, so the leading balance
    gives ``m_min0 = pi/(4 (3/2) cos(pi/6) Q) = sqrt(3) pi/(9 Q)``; at D = 1/2 the paper's
    ``pi/(6Q)`` (eq. 38) is kept."""
    th = threshold_series(1, 2, damping="paper", system="pendulum", duty="1/3")
    assert sp.simplify(th.m_min_leading - sp.sqrt(3) * pi / (9 * Q)) == 0
    assert sp.simplify(threshold_series(1, 2, damping="paper").m_min_leading - pi / (6 * Q)) == 0


def test_family_threshold_refusals():
    from analytic.system import custom

    with pytest.raises(InputError, match="no depth"):
        threshold_series(1, 2, system=custom(("4/5", "6/5")))
    with pytest.raises(InputError, match="integer order"):
        threshold_series("odd", 2, system="torsion")
    with pytest.raises(InputError, match="duty"):
        threshold_series(1, 2, system="torsion", duty="3/2")


def test_cli_series_threshold_for_the_family(capsys):
    import json

    from reports.cli import main

    code = main(
        ["series", "--order", "1", "--terms", "2", "--Q", "50", "--system", "torsion",
         "--duty", "1/3", "--damping", "paper", "--json"]
    )  # fmt: skip
    out, err = capsys.readouterr()
    assert code == 0 and err == ""
    data = json.loads(out)
    assert data["system"] == "torsion" and data["duty"] == "1/3"
    ref = threshold_series(1, 2, damping="paper", system="torsion", duty="1/3")
    assert (
        sp.simplify(sp.sympify(data["threshold"]["m_min_series"], locals={"Q": Q}) - ref.m_min) == 0
    )
    assert data["threshold"]["scaling_power"] == 1
    code = main(["series", "--order", "1", "--Q", "5", "--system", "custom", "--omega-sq", "1,2"])
    out, err = capsys.readouterr()
    assert code == 2 and out == "" and err.startswith("paramres: error:")


@pytest.mark.parametrize("order,model", [(1, "exact"), (2, "paper")])
def test_twelve_term_edges_against_roots(order, model):
    """The longest friction series (K = 12, the limit) against the root of det(M - sigma I) of the
    period map built in this file, at fixed nu = 0.6 and small depths: the error is the first
    omitted term (the first nonzero term beyond m^12, from the solver run two orders further) to
    10 %, and falls like its power of m (slope within 0.2)."""
    from analytic.thresholds import _near_raw

    K = 12
    sigma = -1 if order % 2 else 1
    es = near_threshold_edges(order, K, damping=model)
    raw = _near_raw(order, model, K + 2)  # beyond the limit: the omitted terms
    ms = ["0.001", "0.002"] if order % 2 else ["0.01", "0.02"]
    nu = mpmath.mpf("0.6")
    lam0 = 6 / (order * pi) if order % 2 else sp.Rational(3, 2)
    nus = sp.Symbol("nu")
    for name in ("lower", "upper"):
        f = sp.lambdify((m, Q), es.in_T0[name], "mpmath")
        T0 = raw[name]["T0"]
        q = next(k for k in (K + 1, K + 2) if T0.c[k])  # the first omitted power
        tsym = T0.ring.to_sympy(T0.c[q], {"s": sp.sqrt(1 - nus**2), "nu": nus})
        g = sp.lambdify((nus,), tsym, "mpmath")
        errs, preds = [], []
        with mpmath.workdps(80):
            for x in ms:
                mm = mpmath.mpf(x)
                QQ = 1 / (nu * mpmath.mpf(sp.N(lam0, 90)) * mm ** (1 if order % 2 else 2))
                guess = f(mm, QQ)
                root = mpmath.findroot(
                    lambda T, mm=mm, QQ=QQ: det_condition(T, mm, QQ, sigma, model),
                    guess,
                    tol=mpmath.mpf(10) ** -150,
                )
                errs.append(abs(root - guess))
                preds.append(abs(g(nu) * mm**q))
            assert abs(errs[0] / preds[0] - 1) < 0.1, (order, model, name, errs, preds)
            slope = mpmath.log(errs[1] / errs[0]) / mpmath.log(2)
            assert abs(slope - q) < 0.2, (order, model, name, slope, q)
