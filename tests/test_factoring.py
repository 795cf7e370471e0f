"""The factorisation of the parameter forms (:mod:`analytic.factoring`): sympy's own results, and
no minutes-long prime search for a duty with many digits (``--duty 1e-300``)."""

from __future__ import annotations

import time

import pytest
import sympy as sp
from sympy.polys import factortools

from analytic.factoring import factor
from analytic.model import S
from analytic.system import system

x, y, z = sp.symbols("x y z")

POLYS = [
    x**2 - y**2,
    6 * x**2 * y - 6 * y**3,
    -((x + y) ** 3) * (x - 2 * y) ** 2 * 15,
    (3 * x * y - 2) * (x**2 + y * z + 1) * (z - x) ** 2,
    x**4 * y**2 + 2 * x**2 * y + 1 - z**2,
    (x - y) / (4 * x**2 - 9 * y**2),
    sp.Rational(3, 7) * x**2 * y - sp.Rational(2, 5) * y**3,
]


def _atoms(duty: str) -> list:
    """The atoms of the exact model at ``duty`` as the derivation builds them, and their forms
    near ``m = 1`` (the polynomials :func:`analytic.family.parameter_forms` factors)."""
    m, Q = S.m, S.Q
    Dv = sp.Rational(duty)
    W1, W2, k = (sp.sympify(v) for v in system("pendulum", duty=duty).values(m))
    G2 = 1 / (4 * Q**2)
    N = k * W1 + W2 / k - 2 * G2
    out = [
        W1 - G2,
        N,
        N**2 - 4 * (W1 - G2) * (W2 - G2),
        (1 - Dv) ** 2 * (W2 - G2) - Dv**2 * (W1 - G2),
        (1 - Dv) ** 2 * W2 - Dv**2 * W1,
    ]
    nums = [sp.fraction(sp.cancel(sp.together(e)))[0] for e in out]
    om = sp.Symbol("om", positive=True)
    return nums + [sp.expand(e.subs(m, 1 - om)) for e in out]


@pytest.mark.parametrize("expr", POLYS, ids=range(len(POLYS)))
def test_the_same_expression_as_sympy(expr):
    assert factor(expr) == sp.factor(expr)


@pytest.mark.parametrize("duty", ["1/2", "1/3", "2/7", "1/100000000000000000000"])
def test_the_parameter_forms_factor_as_sympy_factors_them(duty):
    for e in _atoms(duty):
        assert factor(e) == sp.factor(e)


def test_a_duty_of_300_digits_factors_without_sympys_prime_search(monkeypatch):
    """sympy's Wang algorithm searches a prime above the Mignotte bound (thousands of bits at
    ``D = 1e-300``): minutes.  The forms of such a duty never run it."""

    def refuse(*args, **kwargs):
        raise AssertionError("sympy's multivariate factoring ran")

    monkeypatch.setattr(factortools, "dmp_zz_wang", refuse)
    from analytic.family import _factored

    start = time.perf_counter()
    for e in _atoms("1/" + "1" + "0" * 300):
        _factored(e)
    assert time.perf_counter() - start < 10
