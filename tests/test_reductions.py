"""The paper's chains, derived step by step: every step proven from the previous one, and the
derived forms checked numerically against the Floquet route where they make a prediction."""

import mpmath
import pytest
import sympy as sp

from analytic.model import S
from analytic.reductions import chain, chains, odd_order_delta_form, stationary_initial_condition
from analytic.stitching import EdgeKind
from verify.floquet import floquet_vector, monodromy_matrix


def test_every_step_of_every_chain_is_proven():
    for c in chains():
        for s in c.steps:
            assert s.verdict.holds, (c.key, s.label, s.verdict)


def test_chains_cover_the_issue_numbers():
    labels = {s.label for c in chains() for s in c.steps}
    for eq in (
        "5",
        "6",
        "10",
        "11",
        "12",
        "13",
        "14",
        "15",
        "22",
        "23",
        "24",
        "25",
        "26",
        "31",
        "32",
        "34",
        "35",
        "36",
        "37",
        "39",
        "41",
        "44",
        "IC-15",
        "IC-26",
    ):
        assert eq in labels, eq


def test_upper_edge_form_has_the_opposite_sign():
    lower = chain("edge-odd-cos-sin").step("15").expr
    upper = chain("edge-odd-sin-cos").step("15-upper").expr
    assert sp.simplify(lower.rhs + upper.rhs) == 0


@pytest.mark.parametrize("n,sign", [(1, -1), (3, 1), (5, -1), (7, 1)])
def test_eq13_shape_delta_form_sign_alternates(n, sign):
    """sin(omega_av dT/2) = s_n (q-1)/(q+1) cos(...): s_n = -(-1)^((n-1)/2)."""
    e = odd_order_delta_form(EdgeKind.ODD_COS_SIN, n)
    coeff = e.rhs.subs({S.Domega: 0, S.q: 3}) / sp.Rational(1, 2)
    assert coeff == sign


@pytest.mark.parametrize("kind", list(EdgeKind))
def test_stationary_initial_condition_is_a_floquet_vector(kind):
    """On a boundary the derived phi'(0)/phi(0) makes (phi, phi') an eigenvector of the numeric
    monodromy with multiplier (-1)^n.  The boundary T is found here by bisection on the factor of
    the shape (independent of the engine's solver); order 1 for odd kinds, 2 for even ones."""
    n = 1 if kind.parity.sigma < 0 else 2
    m = mpmath.mpf("0.3")
    with mpmath.workdps(40):
        w1 = 2 * mpmath.pi / mpmath.sqrt(1 + m)
        w2 = 2 * mpmath.pi / mpmath.sqrt(1 - m)
        q = ((1 + m) / (1 - m)) ** mpmath.mpf(1.5)
        f = mpmath.cos if n % 2 else mpmath.sin
        eps = kind.epsilon

        def factor(T):
            return (q + 1) * f((w1 + w2) * T / 4) - eps * (q - 1) * f((w2 - w1) * T / 4)

        Tav = 4 * mpmath.pi / (w1 + w2)
        T = mpmath.findroot(
            factor, (n * Tav / 2 - Tav / 4, n * Tav / 2 + Tav / 4), solver="anderson"
        )
        ratio = sp.lambdify((S.omega1, S.T), stationary_initial_condition(kind), modules="mpmath")(
            w1, T
        )
        M = monodromy_matrix(m, T, None, dps=40)
        v = mpmath.matrix([1, ratio])
        Mv = M * v
        sigma = kind.parity.sigma
        assert abs(Mv[0] - sigma * v[0]) < mpmath.mpf(10) ** -25
        assert abs(Mv[1] - sigma * v[1]) < mpmath.mpf(10) ** -25 * abs(ratio)
        # and the eigenvector from the matrix agrees
        u = floquet_vector(M, sigma)
        assert abs(u[1] / u[0] - ratio) < mpmath.mpf(10) ** -20 * max(1, abs(ratio))
