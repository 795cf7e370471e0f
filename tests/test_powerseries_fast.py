"""The fast series arithmetic gives exactly the coefficients of the definitions, and the long
series (K up to 40) are right.

References: the product term by term (the ring's own ``mul``/``add`` on each pair of coefficients)
against the FLINT ``fmpq_mpoly`` product; ``sin``, ``cos``, ``sinh``, ``cosh``, ``exp`` by their
Taylor sums ``sum c_k u^k`` (written out here with series products) against the recurrences; both
exact, so equality is tested, coefficient by coefficient.  The long frictionless series are checked
against the certified edge (:func:`verify.solve.boundary`, ball arithmetic, independent of the
series) at a small rational depth, and against the short series for their first coefficients.
"""

from __future__ import annotations

import math
import random
from fractions import Fraction

import mpmath
import pytest
import sympy as sp
from flint import fmpq

import analytic.powerseries as ps
from analytic.expansions import edge_series
from analytic.model import S
from analytic.powerseries import LaurentRing, Series
from verify.solve import boundary


def _random_series(ring: LaurentRing, prec: int, rng: random.Random, *, lo=-2, hi=3, c0=True):
    coeffs = []
    for k in range(prec + 1):
        if (k == 0 and not c0) or rng.random() < 0.2:
            coeffs.append({})
            continue
        el: dict = {}
        for _ in range(rng.randint(1, 4)):
            exps = {g: rng.randint(lo, hi) for g in ring.gens if g != "nu"}
            if "nu" in ring.gens:
                exps["nu"] = rng.randint(0, 1)
            el = ring.add(el, ring.monomial(fmpq(rng.randint(-9, 9), rng.randint(1, 7)), exps))
        coeffs.append(el)
    return Series(ring, coeffs)


def _rings():
    plain = LaurentRing(("pi", "n"))
    rel = LaurentRing(("s", "nu", "pi"))
    rel = LaurentRing(("s", "nu", "pi"), relation=("nu", rel.sub(rel.one, rel.gen("s", 2))))
    return [plain, rel]


def _term_by_term(a: Series, b: Series) -> Series:
    R, P = a.ring, min(a.prec, b.prec)
    out = [{} for _ in range(P + 1)]
    for i in range(P + 1):
        for j in range(P + 1 - i):
            out[i + j] = R.add(out[i + j], R.mul(a.c[i], b.c[j]))
    return Series(R, out)


@pytest.mark.parametrize("ring", _rings(), ids=["laurent", "relation"])
def test_flint_product_equals_the_term_by_term_product(ring):
    rng = random.Random(14)
    for _ in range(6):
        a = _random_series(ring, 9, rng)
        b = _random_series(ring, 7, rng)
        nz_a = [i for i in range(8) if a.c[i]]
        nz_b = [j for j in range(8) if b.c[j]]
        fast = ps._mul_flint(ring, a.c, b.c, nz_a, nz_b, 7)
        assert fast == _term_by_term(a, b).c


def _taylor(u: Series, coeff) -> Series:
    R, P = u.ring, u.prec
    total = Series.constant(R, R.const(coeff(0)), P)
    power = Series.constant(R, R.one, P)
    for k in range(1, P + 1):
        power = _term_by_term(power, u)
        c = coeff(k)
        if c != 0:
            total = total + power * c
    return total


_DEFS = {
    "sin": lambda k: 0 if k % 2 == 0 else fmpq((-1) ** (k // 2), math.factorial(k)),
    "cos": lambda k: 0 if k % 2 else fmpq((-1) ** (k // 2), math.factorial(k)),
    "sinh": lambda k: 0 if k % 2 == 0 else fmpq(1, math.factorial(k)),
    "cosh": lambda k: 0 if k % 2 else fmpq(1, math.factorial(k)),
    "exp": lambda k: fmpq(1, math.factorial(k)),
}


@pytest.mark.parametrize("ring", _rings(), ids=["laurent", "relation"])
@pytest.mark.parametrize("name", sorted(_DEFS))
def test_elementary_functions_equal_their_taylor_sums(ring, name):
    rng = random.Random(40)
    u = _random_series(ring, 8, rng, c0=False)
    assert getattr(u, name)().c == _taylor(u, _DEFS[name]).c


def test_forty_terms_agree_with_twelve_and_with_the_certified_edge():
    long = edge_series(6, 40)
    short = edge_series(6, 12)
    m = S.m
    for edge in ("lower", "upper"):
        a = sp.Poly(sp.expand(long.in_T0[edge]), m).all_coeffs()[::-1]
        b = sp.Poly(sp.expand(short.in_T0[edge]), m).all_coeffs()[::-1]
        assert a[:13] == b[:13]
    # at m = 1/50 the omitted terms of the 40-term series are ~1e-52 (its coefficients grow like
    # a power of the inverse radius of convergence), those of a 30-term series ~1e-40: the long
    # series must be right to 1e-48 and better than the short one by many orders
    depth = Fraction(1, 50)
    b = boundary(6, depth, digits=90)
    mid = edge_series(6, 30)
    with mpmath.workdps(100):
        for edge, want in (("lower", b.lower), ("upper", b.upper)):
            errs = []
            for es in (long, mid):
                got = mpmath.mpf(sp.N(es.in_T0[edge].subs(m, sp.Rational(1, 50)), 100))
                errs.append(abs(got - want) / abs(want))
            assert errs[0] <= mpmath.mpf(10) ** -48, (edge, errs)
            assert errs[0] * 10**6 <= errs[1], (edge, errs)


@pytest.mark.parametrize("ring", _rings(), ids=["laurent", "relation"])
def test_flint_coefficient_product_equals_the_plain_one(ring, monkeypatch):
    rng = random.Random(7)
    for _ in range(5):
        a = _random_series(ring, 12, rng)
        b = _random_series(ring, 12, rng)
        x = ring.add(ring.mul(a.c[1], a.c[2]), a.c[3])  # elements with many terms
        y = ring.add(ring.mul(b.c[4], b.c[5]), b.c[6])
        fast = ring.mul(x, y)
        monkeypatch.setattr(ps, "_FLINT_TERMS", 10**9)
        assert fast == ring.mul(x, y)
        monkeypatch.setattr(ps, "_FLINT_TERMS", 0)
        assert fast == ring.mul(x, y)
        monkeypatch.undo()
