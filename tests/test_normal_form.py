"""The chain from the determinant to the normal form and to one equation per edge.

Each link is a proven identity (:mod:`analytic.identity`); independently, the normal form with the
model's parameters is evaluated numerically and compared with det(M - sigma I) of the monodromy
built by :mod:`verify.floquet` (no sympy) at random points, 40 digits.
"""

import random

import mpmath
import pytest
import sympy as sp

from analytic.model import Damping, S
from analytic.normal_form import (
    det_monodromy,
    edge_factor_link,
    normal_form,
    normal_form_link,
    order_form,
    parameters,
    r2,
    trace_form,
    trace_lemma,
    x,
    y,
)
from analytic.stitching import EdgeKind, Parity
from verify.floquet import monodromy_matrix

DPS = 40


@pytest.mark.parametrize("damping", list(Damping))
def test_det_and_trace_links(damping):
    assert det_monodromy(damping).verdict.holds
    assert trace_form(damping).verdict.holds


@pytest.mark.parametrize("parity", list(Parity))
def test_lemma_and_normal_form_links(parity):
    assert trace_lemma(parity).verdict.holds
    assert normal_form_link(parity).verdict.holds


@pytest.mark.parametrize("kind", list(EdgeKind))
def test_each_edge_shape_is_one_factor(kind):
    link = edge_factor_link(kind)
    assert link.verdict.holds and link.verdict.factor is not None
    assert not link.verdict.factor.has(sp.sin, sp.cos)


def test_normal_form_is_the_product_of_the_edge_factors():
    r = sp.Symbol("r", positive=True)
    for parity in Parity:
        from analytic.normal_form import edge_factor

        prod = edge_factor(parity, 1, symbols=(x, y, r)) * edge_factor(
            parity, -1, symbols=(x, y, r)
        )
        nf = normal_form(parity, symbols=(x, y, r**2, 0))
        assert sp.expand(prod - nf) == 0


@pytest.mark.parametrize("parity", list(Parity))
@pytest.mark.parametrize("model,damped", [("paper", False), ("paper", True), ("exact", True)])
def test_normal_form_matches_numeric_monodromy(parity, model, damped):
    """det(M - sigma I) = p (K+2) N with the model's parameters (docs/theory.md, step 5)."""
    params = parameters(
        Damping.EXACT if model == "exact" else (Damping.PAPER if damped else Damping.NONE)
    )
    w = [k for k in params if k.name == "w"][0]
    fr2 = sp.lambdify((S.m, S.Q), params[r2], modules="mpmath")
    fb = sp.lambdify((S.m, S.Q), params[S.beta], modules="mpmath")
    fw = sp.lambdify((S.m, S.Q), params[w], modules="mpmath")
    fg = sp.lambdify((S.m, S.Q), params[S.g], modules="mpmath")
    N = sp.lambdify(
        (x, S.beta, r2, S.g),
        normal_form(parity, symbols=(x, S.beta * x, r2, S.g * x)),
        modules="mpmath",
    )
    rng = random.Random(5)
    for _ in range(6):
        with mpmath.workdps(DPS):
            m = mpmath.mpf(rng.uniform(0.02, 0.95))
            tau = mpmath.mpf(rng.uniform(0.2, 5.0))
            Q = mpmath.mpf(rng.uniform(2.0, 30.0)) if damped else None
            Qv = Q if Q is not None else mpmath.inf
            rr, bb, ww, gg = fr2(m, Qv), fb(m, Qv), fw(m, Qv), fg(m, Qv)
            xx = mpmath.pi * ww * tau
            K = 2 * (1 + rr) / (1 - rr)
            p = mpmath.exp(-mpmath.pi * tau / Q) if damped else 1
            val = p * (K + 2) * N(xx, bb, rr, gg)
            M = monodromy_matrix(m, tau, Q, model, dps=DPS)
            s = parity.sigma
            ref = (M[0, 0] - s) * (M[1, 1] - s) - M[0, 1] * M[1, 0]
            assert abs(val - ref) <= mpmath.mpf(10) ** -30 * max(1, abs(ref)), (m, tau, Q, val, ref)


def test_order_form_reduces_cos_of_shifted_phase():
    # odd n: cos^2(n pi/2 + theta) = sin^2 theta; even n: sin^2(...) = sin^2 theta
    for n in (1, 2, 3, 4, 7, 10):
        N, R = order_form(n)
        assert sp.simplify(N + R - sp.sin(S.theta) ** 2) == 0


@pytest.mark.parametrize("n", [1, 2, 3, 4, 5, 6, 9, 12])
def test_window_theorem_one_root_per_factor(n):
    """Each undamped per-edge factor changes sign exactly once for theta in (-pi/2, pi/2), at
    random depths (docs/theory.md: the window theorem)."""
    rng = random.Random(n)
    fpar = parameters(Damping.NONE)
    fr = sp.lambdify(S.m, sp.sqrt(fpar[r2]), modules="mpmath")
    fb = sp.lambdify(S.m, fpar[S.beta], modules="mpmath")
    f = mpmath.cos if n % 2 else mpmath.sin
    for _ in range(5):
        m = mpmath.mpf(rng.uniform(0.01, 0.98))
        r, b = fr(m), fb(m)
        x0 = n * mpmath.pi / 2
        for eps in (1, -1):
            g = [
                (mpmath.cos if n % 2 else mpmath.sin)(x0 + th) - eps * r * f(b * (x0 + th))
                for th in mpmath.linspace(-mpmath.pi / 2 + 1e-9, mpmath.pi / 2 - 1e-9, 801)
            ]
            changes = sum(1 for a, c in zip(g, g[1:], strict=False) if a * c < 0)
            assert changes == 1, (n, m, eps, changes)
