"""From the stitching determinant to one normal form and to one equation per edge.

The chain, each link proven by :mod:`analytic.identity`:

1. ``det(stitching system) = F * det(M - sigma I)`` (:func:`analytic.stitching.floquet_condition`):
   the determinant *is* the condition that ``sigma = (-1)**n`` is a Floquet multiplier.
2. ``det M = p**2`` with ``p = exp(-gamma T)`` (every model), so
   ``det(M - sigma I) = 1 + p**2 - sigma tr M``.
3. The trace form: ``tr M = p * (2 c1 c2 - K s1 s2)`` with ``c_i = cos(a_i)``, ``s_i = sin(a_i)``,
   ``a_i`` the phase of half ``i`` over ``T/2``, and one coupling constant ``K``:
   ``K = q + 1/q`` (no friction, paper model), ``K = (k w1^2 + w2^2/k - 2 gamma^2)/(W1 W2)`` with
   ``k = ((1+m)/(1-m))**2`` and ``W_i = sqrt(w_i^2 - gamma^2)`` (exact model, under-damped halves).
4. Product to sum (a lemma in ``K`` alone): with ``x = (a1+a2)/2`` and ``y = (a2-a1)/2``,
   ``2 cos a1 cos a2 - K sin a1 sin a2 = (K+2) cos^2 x - (K-2) cos^2 y - 2``.
5. Hence ``det(M - sigma I) = p (K+2) N_sigma`` with the **normal form**

       odd  (sigma = -1):  N = cos^2 x - r^2 cos^2 y + (1 - r^2) sinh^2(gamma T/2)
       even (sigma = +1):  N = sin^2 x - r^2 sin^2 y + (1 - r^2) sinh^2(gamma T/2)

   with ``r^2 = (K-2)/(K+2)`` (so ``r = (q-1)/(q+1)`` when ``K = q + 1/q``) and the instability
   inside the interval where ``N < 0``.  ``x = omega_av T/2`` is the paper's average phase
   (``psi``),
   ``y = beta x`` with ``beta = Delta omega / (2 omega_av)``, ``gamma T/2 = g x`` with
   ``g = gamma/omega_av``.  The exact model has the same normal form with the damped frequencies.
6. Without friction ``N`` is a difference of squares: one factor per edge,
   ``cos x -+ r cos y`` (odd), ``sin x -+ r sin y`` (even); each factor is, up to a non-vanishing
   factor, the determinant of one symmetric edge shape (:func:`analytic.stitching.edge_system`).
7. For order ``n`` put ``x = n pi/2 + theta`` (``theta = omega_av Delta T / 2``, the paper's unknown
   in eqs. 15, 26, 39, 44): ``cos^2 x = sin^2 theta`` for odd ``n`` and ``sin^2 x = sin^2 theta``
   for
   even ``n``, so for every order ``N = sin^2 theta - R(theta)`` with
   ``R = r^2 f(beta (n pi/2 + theta))^2 - (1 - r^2) sinh^2(g (n pi/2 + theta))``, ``f = cos`` (odd)
   or ``sin`` (even).
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cache

import sympy as sp
from sympy.matrices.utilities import dotprodsimp

from .identity import Verdict, factor_between, prove_zero
from .model import Damping, S, inertia
from .stitching import EdgeKind, Parity, edge_system, monodromy

__all__ = [
    "K",
    "Link",
    "normal_form",
    "normal_form_link",
    "trace_lemma",
    "trace_form",
    "det_monodromy",
    "edge_factor",
    "edge_factor_link",
    "order_form",
    "indicator_R",
    "parameters",
]

x, y, Kc = sp.symbols("x y K", real=True)
r2 = sp.Symbol("r^2", nonnegative=True)


@dataclass(frozen=True)
class Link:
    """One proven step: ``lhs == rhs`` (as expressions), why, and how it was decided."""

    name: str
    lhs: sp.Expr
    rhs: sp.Expr
    why: str
    verdict: Verdict


def _link(name: str, lhs, rhs, why: str, **kw) -> Link:
    return Link(name, lhs, rhs, why, prove_zero(sp.expand(lhs - rhs), **kw))


def K(damping: Damping) -> sp.Expr:
    """The coupling constant of the trace form (step 3), in the model's symbols."""
    damping = Damping(damping)
    if damping is Damping.EXACT:
        k = inertia(1) / inertia(2)
        g = S.gamma
        W1, W2 = S.Omega1, S.Omega2
        return (k * (W1**2 + g**2) + (W2**2 + g**2) / k - 2 * g**2) / (W1 * W2)
    q = inertia(1) * S.omega1 / (inertia(2) * S.omega2)
    return q + 1 / q


def _phases(damping: Damping) -> tuple[sp.Expr, sp.Expr]:
    if Damping(damping) is Damping.EXACT:
        return S.Omega1 * S.T / 2, S.Omega2 * S.T / 2
    return S.omega1 * S.T / 2, S.omega2 * S.T / 2


@cache
def det_monodromy(damping: Damping = Damping.NONE) -> Link:
    """Step 2: ``det M = p**2`` (``= 1`` without friction)."""
    damping = Damping(damping)
    M = monodromy(damping)
    p2 = sp.Integer(1) if damping is Damping.NONE else sp.exp(-2 * S.gamma * S.T)
    # Berkowitz's division-free determinant without simplifying the products on the way: the
    # exact zero test of the difference (:func:`analytic.identity.prove_zero`) does the cancelling
    with dotprodsimp(False):
        det = sp.expand(M.det(method="berkowitz"))
    return _link("det M", det, p2, "product of the half-period maps and the jumps")


@cache
def trace_form(damping: Damping = Damping.NONE) -> Link:
    """Step 3: ``tr M = p (2 c1 c2 - K s1 s2)`` for under-damped (or undamped) halves."""
    damping = Damping(damping)
    M = monodromy(damping)
    a1, a2 = _phases(damping)
    p = sp.Integer(1) if damping is Damping.NONE else sp.exp(-S.gamma * S.T)
    form = p * (2 * sp.cos(a1) * sp.cos(a2) - K(damping) * sp.sin(a1) * sp.sin(a2))
    return _link("trace form", sp.expand(M.trace()), form, "entries of the half-period maps")


@cache
def trace_lemma(parity: Parity) -> Link:
    """Step 4, in ``K`` alone: the product-to-sum identity behind eqs. (13), (25), (35)-(36)."""
    a1, a2 = x - y, x + y
    lhs = 2 * sp.cos(a1) * sp.cos(a2) - Kc * sp.sin(a1) * sp.sin(a2)
    if Parity(parity) is Parity.ODD:
        rhs = (Kc + 2) * sp.cos(x) ** 2 - (Kc - 2) * sp.cos(y) ** 2 - 2
    else:
        rhs = 2 - (Kc + 2) * sp.sin(x) ** 2 + (Kc - 2) * sp.sin(y) ** 2
    return _link("product to sum", lhs, rhs, "cos a cos b and sin a sin b as half-sums")


def normal_form(parity: Parity, *, symbols: tuple = None) -> sp.Expr:
    """Step 5: the normal form ``N_sigma(x, y, r^2, h)`` with ``h = gamma T / 2``.

    ``symbols = (x, y, r2, h)`` to use other symbols (defaults: ``x, y, r^2, h``).
    """
    xs, ys, rs, hs = (
        symbols if symbols is not None else (x, y, r2, sp.Symbol("h", nonnegative=True))
    )
    f = sp.cos if Parity(parity) is Parity.ODD else sp.sin
    return f(xs) ** 2 - rs * f(ys) ** 2 + (1 - rs) * sp.sinh(hs) ** 2


@cache
def normal_form_link(parity: Parity) -> Link:
    """Step 5, for every model at once: with ``det M = p^2`` and the trace form (steps 2-3),
    ``1 + p^2 - sigma p (2 cos a1 cos a2 - K sin a1 sin a2) = p (K+2) N`` identically in ``K``,
    where ``p = exp(-2h)``, ``x = (a1+a2)/2``, ``y = (a2-a1)/2`` and ``r^2 = (K-2)/(K+2)``."""
    parity = Parity(parity)
    a1, a2 = sp.symbols("a_1 a_2", real=True)
    h = sp.Symbol("h", nonnegative=True)
    p = sp.exp(-2 * h)
    lhs = 1 + p**2 - parity.sigma * p * (2 * sp.cos(a1) * sp.cos(a2) - Kc * sp.sin(a1) * sp.sin(a2))
    N = normal_form(parity, symbols=((a1 + a2) / 2, (a2 - a1) / 2, (Kc - 2) / (Kc + 2), h))
    return _link(
        "normal form", lhs, p * (Kc + 2) * N, "steps 2-4; r^2 = (K-2)/(K+2), 1 - r^2 = 4/(K+2)"
    )


def edge_factor(parity: Parity, epsilon: int, *, symbols: tuple = None) -> sp.Expr:
    """Step 6: the undamped per-edge factor ``cos x - eps r cos y`` (odd) / ``sin x - eps r sin
    y``."""
    xs, ys, rs = symbols if symbols is not None else (x, y, sp.Symbol("r", positive=True))
    f = sp.cos if Parity(parity) is Parity.ODD else sp.sin
    return f(xs) - epsilon * rs * f(ys)


@cache
def edge_factor_link(kind: EdgeKind) -> Link:
    """Step 6 proven: the edge shape's determinant is a non-vanishing multiple of its factor.

    The multiple is found (not assumed) as the ratio of the two and must be free of the phases;
    it comes out as ``-+ (1-m)^2 omega2 (q+1)/2``, so the edge equation is the factor.
    """
    kind = EdgeKind(kind)
    det = edge_system(kind).determinant
    a1, a2 = S.omega1 * S.T / 2, S.omega2 * S.T / 2
    q = inertia(1) * S.omega1 / (inertia(2) * S.omega2)
    r = (q - 1) / (q + 1)
    fac = edge_factor(kind.parity, kind.epsilon, symbols=((a1 + a2) / 2, (a2 - a1) / 2, r))
    multiple = factor_between(det, fac)
    if multiple is None:  # pragma: no cover - would mean the shape is not an edge of this factor
        return Link(
            f"edge factor of {kind.value}", det, fac, "not proportional", Verdict(False, "symbolic")
        )
    return Link(
        f"edge factor of {kind.value}",
        det,
        multiple * fac,
        "product to sum in the quarter-period phases; q = (1+m)^2 omega1 / ((1-m)^2 omega2)",
        Verdict(True, "symbolic", factor=multiple),
    )


def order_form(n, parity: Parity | None = None) -> tuple[sp.Expr, sp.Expr]:
    """Step 7: ``(sin^2 theta - R(theta), R(theta))`` for order ``n`` (an int, or symbolic with
    ``parity`` given), in the symbols ``theta, r^2, beta, g`` (``h = g x``, ``y = beta x``)."""
    th, beta, g = S.theta, S.beta, S.g
    if isinstance(n, int):
        parity = Parity.of(n)
    parity = Parity(parity)
    xx = n * sp.pi / 2 + th
    f = sp.cos if parity is Parity.ODD else sp.sin
    R = r2 * f(beta * xx) ** 2 - (1 - r2) * sp.sinh(g * xx) ** 2
    return sp.sin(th) ** 2 - R, R


def indicator_R(parity: Parity) -> sp.Expr:
    """``R`` of step 7 as a function of ``x`` (not ``theta``): instability where ``f(x)^2 < R``."""
    f = sp.cos if Parity(parity) is Parity.ODD else sp.sin
    return r2 * f(S.beta * x) ** 2 - (1 - r2) * sp.sinh(S.g * x) ** 2


def parameters(damping: Damping = Damping.PAPER) -> dict[sp.Symbol, sp.Expr]:
    """The normal-form parameters in the project's units (``T0 = 1``, ``Q``), from their
    definitions.

    Keys: ``r^2``, ``beta``, ``g`` and ``w = omega_av/omega0`` (so that ``T/T0 = x / (pi w)``);
    for the exact model they are built from the damped frequencies.  These are the definitions;
    numerically stable rearrangements are the business of :mod:`verify` (and are tested against
    these).
    """
    damping = Damping(damping)
    w = sp.Symbol("w", positive=True)
    m, Q = S.m, S.Q
    om1, om2 = 2 * sp.pi / sp.sqrt(1 + m), 2 * sp.pi / sp.sqrt(1 - m)
    gam = sp.pi / Q
    if damping is Damping.EXACT:
        a1, a2 = sp.sqrt(om1**2 - gam**2), sp.sqrt(om2**2 - gam**2)
        k_ = K(damping).subs({S.Omega1: a1, S.Omega2: a2, S.gamma: gam})
    else:
        a1, a2 = om1, om2
        k_ = K(Damping.NONE).subs({S.omega1: om1, S.omega2: om2})
    wav = (a1 + a2) / 2
    out = {
        r2: (k_ - 2) / (k_ + 2),
        S.beta: (a2 - a1) / (a2 + a1),
        w: wav / (2 * sp.pi),
    }
    out[S.g] = sp.Integer(0) if damping is Damping.NONE else gam / wav
    return out
