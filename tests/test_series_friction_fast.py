"""The fast route of the friction series gives exactly the coefficients of the plain one.

References, all exact (equality is tested, coefficient by coefficient): the binomial series by its
sum ``sum binom(e, k) t^k`` (written out here with series products) against the recurrence; the
evaluation with the parts free of ``theta`` evaluated once
(:func:`analytic.powerseries.fixed_parts`) against the plain evaluation; Newton steps that double
the precision against the plain Newton loop of :func:`analytic.powerseries.newton` (which stops
when the residual vanishes); the lower edge as the image of the upper one under ``s -> -s``
against the lower edge solved directly; products in the ring with the relation ``nu^2 = 1 - s^2``
against the product reduced term by term; the shortcut for ``c * monomial`` against sympy's own
product.
"""

from __future__ import annotations

import random

import pytest
import sympy as sp
from flint import fmpq

import analytic.powerseries as ps
from analytic import thresholds
from analytic.model import S
from analytic.powerseries import LaurentRing, Series, evaluate, fixed_parts, newton, newton_doubling


def _rel_ring():
    tmp = LaurentRing(("pi", "s", "nu"))
    return LaurentRing(("pi", "s", "nu"), relation=("nu", tmp.sub(tmp.one, tmp.gen("s", 2))))


def _random_element(ring, rng, *, nu=True):
    el: dict = {}
    for _ in range(rng.randint(1, 5)):
        exps = {"pi": rng.randint(-2, 2), "s": rng.randint(-2, 2), "nu": rng.randint(0, int(nu))}
        el = ring.add(el, ring.monomial(fmpq(rng.randint(-9, 9), rng.randint(1, 7)), exps))
    return el


def _random_series(ring, prec, rng, *, c0=True):
    c = [
        _random_element(ring, rng) if (k or c0) and rng.random() > 0.2 else {}
        for k in range(prec + 1)
    ]
    return Series(ring, c)


@pytest.mark.parametrize("e", ["1/2", "-1/2", "3/2", "-3/2", "1/3", "-5/4"])
def test_binomial_recurrence_equals_the_binomial_sum(e):
    rng = random.Random(3)
    R = _rel_ring()
    t = _random_series(R, 9, rng, c0=False)
    ee = fmpq(*map(int, e.split("/")))
    total = Series.constant(R, R.one, t.prec)
    power = Series.constant(R, R.one, t.prec)
    coeff = fmpq(1)
    for k in range(1, t.prec + 1):
        coeff = coeff * (ee - (k - 1)) / k
        power = power * t
        total = total + power * coeff
    assert ps._binomial_series(t, sp.Rational(e)).c == total.c


def test_relation_products_equal_the_products_reduced_term_by_term():
    rng = random.Random(5)
    R = _rel_ring()
    for _ in range(20):
        a = _random_element(R, rng)
        b = _random_element(R, rng, nu=rng.random() < 0.5)
        assert R.mul(a, b) == R._reduce(R._mul_plain(a, b))
        big_a = R.mul(R.add(a, _random_element(R, rng)), _random_element(R, rng))
        big_b = R.mul(R.add(b, _random_element(R, rng)), _random_element(R, rng, nu=False))
        assert R.mul(big_a, big_b) == R._reduce(R._mul_plain(big_a, big_b))


def test_times_rational_equals_sympys_product():
    nu, Qs, x = sp.Symbol("nu"), sp.Symbol("Q"), sp.Symbol("x")
    bases = [sp.pi, sp.sqrt(1 - nu**2), nu, sp.pi / (14 * S.m), 1 / (Qs * S.m), sp.sqrt(2), x + 1]
    rng = random.Random(11)
    for _ in range(300):
        mono = sp.Mul(*(b ** rng.randint(-3, 3) for b in rng.sample(bases, rng.randint(1, 4))))
        c = sp.Rational(rng.randint(-20, 20), rng.randint(1, 9))
        got = ps._times_rational(c, mono)
        assert got == c * mono and sp.srepr(got) == sp.srepr(c * mono), (c, mono)


@pytest.mark.parametrize("order,model", [(1, "exact"), (2, "paper")])
def test_evaluation_with_fixed_parts_equals_the_plain_one(order, model):
    rng = random.Random(order)
    R = _rel_ring()
    lam = Series.constant(R, R.gen("nu"), 8)
    model_ = thresholds._scaled_model(order, model)
    env = {thresholds.LAM: lam}
    fixed = fixed_parts([model_["N"], model_["dN"]], env, R, 8, var=S.m, vary={S.theta})
    for prec in (8, 5):
        th = _random_series(R, prec, rng, c0=False)
        e = {**env, S.theta: th}
        for key in ("N", "dN"):
            plain = evaluate(model_[key], e, R, prec, var=S.m)
            fast = evaluate(model_[key], e, R, prec, var=S.m, memo=dict(fixed))
            assert fast.c == plain.c, (key, prec)


def test_newton_doubling_equals_the_plain_newton():
    # u^2 = (1 + m)^3 (1 + pi m)^2 (1/2 + s m^2)^2: the root with u(0) = 1/2
    R = LaurentRing(("pi", "s"))
    P = 13
    m = Series.variable(R, P)
    pi = Series.constant(R, R.gen("pi"), P)
    s = Series.constant(R, R.gen("s"), P)
    rhs = (
        (1 + m) ** 3
        * (1 + pi * m) ** 2
        * (Series.constant(R, R.const(fmpq(1, 2)), P) + s * m * m) ** 2
    )

    def F(u):
        return u * u - rhs.truncate(u.prec)

    start = Series.constant(R, R.const(fmpq(1, 2)), P)
    plain = newton(F, lambda u: u * 2, start)
    fast = newton_doubling(lambda u, L, Ld: (F(u), (u * 2).truncate(Ld)), start, P)
    assert fast.c == plain.c


@pytest.mark.parametrize(
    "order,model,K,system",
    [
        (1, "exact", 5, None),
        (2, "paper", 4, None),
        (3, "paper", 3, None),
        (1, "exact", 3, "torsion"),
    ],
)
def test_lower_edge_is_the_image_of_the_upper_one(order, model, K, system):
    from analytic.system import system as as_system

    sysv = None if system is None else as_system(system)
    p = thresholds._power(order, sysv)
    assert p in (1, 2)
    both = thresholds._near_edges(order, model, K, sysv, ("upper", "lower"))
    fast = thresholds._near_raw(order, model, K, sysv)
    for name in ("lower", "upper"):
        for key in ("theta", "T0", "Tav"):
            assert fast[name][key].c == both[name][key].c, (name, key)
    # and the images are not trivially equal: the edges differ
    assert fast["lower"]["T0"].c != fast["upper"]["T0"].c
