"""Stitching systems: built from the conditions, their determinants are the Floquet condition.

Independent route: the determinants and traces derived symbolically are evaluated at random points
and compared with the monodromy that :mod:`verify.floquet` builds numerically from the segment
solutions and jump matrices (no sympy), at 40 digits.
"""

import random

import mpmath
import pytest
import sympy as sp

from analytic.model import Damping, Regime, S, ode_residual, physical, segment
from analytic.stitching import (
    EdgeKind,
    Parity,
    edge_system,
    floquet_condition,
    general_system,
    implied_rows,
    monodromy,
    paper_system,
)
from verify.floquet import monodromy_matrix

DPS = 40
TOL = mpmath.mpf(10) ** -30  # relative, and absolute below magnitude 1


def _points(n, seed, damped):
    rng = random.Random(seed)
    out = []
    for _ in range(n):
        m = mpmath.mpf(rng.uniform(0.02, 0.95))
        tau = mpmath.mpf(rng.uniform(0.2, 5.0))
        Q = mpmath.mpf(rng.uniform(2.0, 30.0)) if damped else None
        out.append((m, tau, Q))
    return out


def _close(a, b):
    return abs(a - b) <= TOL * max(1, abs(a), abs(b))


@pytest.mark.parametrize("damping", [Damping.NONE, Damping.PAPER, Damping.EXACT])
def test_segments_solve_the_equation_of_motion(damping):
    for regime in (
        (Regime.UNDER, Regime.CRITICAL, Regime.OVER)
        if damping is Damping.EXACT
        else (Regime.UNDER,)
    ):
        seg = segment(S.omega1, S.A1, S.B1, damping, regime)
        if regime is Regime.CRITICAL:
            res = ode_residual(seg).subs(S.gamma, S.omega1)
            assert sp.simplify(res) == 0
        elif damping is not Damping.PAPER:
            assert ode_residual(seg) == 0
    # the paper's velocity is not the derivative of its angle (eqs. 28-30)
    p = segment(S.omega1, S.A1, S.B1, Damping.PAPER)
    assert sp.simplify(sp.diff(p.phi, S.t) - p.dphi) != 0


@pytest.mark.parametrize("parity", list(Parity))
@pytest.mark.parametrize("damping", [Damping.NONE, Damping.PAPER, Damping.EXACT])
def test_determinant_is_the_multiplier_condition(parity, damping):
    """det(stitching) = F * det(M - sigma I), F free of oscillations (step 1 of the chain)."""
    cond, factor = floquet_condition(parity, damping)
    assert factor is not None
    # F vanishes nowhere in the physical domain: (1-m^2)^2 omega1 omega2 e^{gamma T}-like
    assert not factor.has(sp.sin, sp.cos)


@pytest.mark.parametrize(
    "damping,model", [(Damping.NONE, "exact"), (Damping.PAPER, "paper"), (Damping.EXACT, "exact")]
)
def test_symbolic_monodromy_equals_numeric_monodromy(damping, model):
    M = monodromy(damping)
    f = sp.lambdify((S.m, S.tau, S.Q), physical(M), modules="mpmath")
    for m, tau, Q in _points(6, 11, damping is not Damping.NONE):
        with mpmath.workdps(DPS):
            sym = f(m, tau, Q if Q is not None else mpmath.inf)
            num = monodromy_matrix(m, tau, Q, model, dps=DPS)
            for i in range(2):
                for j in range(2):
                    assert _close(sym[i, j], num[i, j]), (m, tau, Q, i, j, sym[i, j], num[i, j])


@pytest.mark.parametrize("parity", list(Parity))
@pytest.mark.parametrize(
    "damping,model", [(Damping.NONE, "exact"), (Damping.PAPER, "paper"), (Damping.EXACT, "exact")]
)
def test_stitching_determinant_against_numeric_floquet(parity, damping, model):
    """The 4x4 determinant, divided by its derived factor, is det(M - sigma I) of the numeric
    monodromy at random points (40 digits)."""
    cond, factor = floquet_condition(parity, damping)
    det = general_system(parity, damping).determinant
    f = sp.lambdify((S.m, S.tau, S.Q), physical(det / factor), modules="mpmath")
    sigma = parity.sigma
    for m, tau, Q in _points(6, 12, damping is not Damping.NONE):
        with mpmath.workdps(DPS):
            val = f(m, tau, Q if Q is not None else mpmath.inf)
            M = monodromy_matrix(m, tau, Q, model, dps=DPS)
            ref = (M[0, 0] - sigma) * (M[1, 1] - sigma) - M[0, 1] * M[1, 0]
            assert _close(val, ref), (m, tau, Q, val, ref)


@pytest.mark.parametrize("kind", list(EdgeKind))
def test_symmetric_shapes_need_only_the_conditions_at_zero(kind):
    at_half, at_zero = implied_rows(kind)
    for i in range(2):
        same = sp.simplify(at_half.row(i) - at_zero.row(i)) == sp.zeros(1, 2)
        opposite = sp.simplify(at_half.row(i) + at_zero.row(i)) == sp.zeros(1, 2)
        assert same or opposite


def test_edge_system_two_conditions_and_unknowns():
    s = edge_system(EdgeKind.ODD_COS_SIN)
    assert s.unknowns == (S.A1, S.A2) and len(s.conditions) == 2 and s.matrix.shape == (2, 2)


def test_paper_system_amplitude_relations():
    s = paper_system(Parity.ODD)
    assert s.unknowns == (S.A, S.B)
    assert s.matrix.shape == (2, 2)
    # rows are free of the unknowns and of the primary frequencies' jump factors
    assert not s.matrix.has(S.m)
