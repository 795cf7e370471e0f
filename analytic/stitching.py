"""Stitching: the homogeneous systems for the segment amplitudes, built from the conditions.

A stationary oscillation on a boundary of an interval of instability is a solution that repeats
after
one modulation period (even orders, ``sigma = +1``) or changes sign after it (odd orders,
``sigma = -1``).  It is made of two free-oscillation segments, ``phi1`` on ``0 < t < T/2`` (bob
down)
and ``phi2`` on ``-T/2 < t < 0`` (bob up), joined by

* continuity of the angle at ``t = 0``,
* the angular-momentum jump at ``t = 0``: ``(1+m)**2 phi1'(0) = (1-m)**2 phi2'(0)`` (eq. 4),
* (anti)periodicity across ``t = T/2``: ``phi1(T/2) = sigma phi2(-T/2)`` and
  ``(1+m)**2 phi1'(T/2) = sigma (1-m)**2 phi2'(-T/2)`` (eq. 31 for odd orders).

:func:`general_system` builds all four conditions for the general segments of any damping model
(four
unknowns); :func:`edge_system` uses the symmetric shapes of the undamped boundary oscillations (the
paper's eqs. 8-9, 16-17, 20-21 and a fourth kind the paper does not write), for which the conditions
at ``T/2`` repeat those at ``t = 0`` and two unknowns remain; :func:`paper_system` eliminates two
amplitudes from the general paper-model system the way the appendix does (eq. 32).
:func:`monodromy` is the period map, whose trace the determinants are shown to be functions of.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from enum import Enum
from functools import cache

import sympy as sp
from sympy.polys.rings import sring

from .identity import expanded_polynomial, factor_between
from .model import Damping, Regime, S, Segment, inertia, segment

__all__ = [
    "Parity",
    "EdgeKind",
    "Condition",
    "StitchingSystem",
    "general_system",
    "edge_system",
    "paper_system",
    "implied_rows",
    "monodromy",
    "propagator",
    "floquet_condition",
]


class Parity(int, Enum):
    """Odd orders: anti-periodic over ``T`` (multiplier ``-1``); even orders: periodic (``+1``)."""

    ODD = -1
    EVEN = 1

    @property
    def sigma(self) -> int:
        return int(self.value)

    @classmethod
    def of(cls, n: int) -> Parity:
        return cls.ODD if n % 2 else cls.EVEN


class EdgeKind(str, Enum):
    """The four symmetric shapes of an undamped boundary oscillation.

    Each half is a segment centred on its own midpoint (``t = T/4`` for the bob-down half,
    ``t = -T/4`` for the bob-up half), either even (``cos``) or odd (``sin``) about it.  Mixed
    parities are anti-periodic (odd orders), equal parities periodic (even orders).  The paper
    writes
    ``ODD_COS_SIN`` (eqs. 8-9, lower edge of the first interval), ``ODD_SIN_COS`` (eqs. 16-17, upper
    edge) and ``EVEN_COS_COS`` (eqs. 20-21, lower edge of the second); ``EVEN_SIN_SIN`` is the
    remaining one (the other edge of even intervals).
    """

    ODD_COS_SIN = "odd-cos-sin"
    ODD_SIN_COS = "odd-sin-cos"
    EVEN_COS_COS = "even-cos-cos"
    EVEN_SIN_SIN = "even-sin-sin"

    @property
    def parity(self) -> Parity:
        return Parity.ODD if self.value.startswith("odd") else Parity.EVEN

    @property
    def shapes(self) -> tuple[str, str]:
        a, b = self.value.split("-")[1:]
        return a, b

    @property
    def epsilon(self) -> int:
        """``+1`` for the kinds whose reduced equation has ``+(q-1)`` (eqs. 13, 25), else ``-1``."""
        return 1 if self in (EdgeKind.ODD_COS_SIN, EdgeKind.EVEN_COS_COS) else -1


@dataclass(frozen=True)
class Condition:
    """One stitching condition ``lhs = rhs``, with where it comes from."""

    label: str
    lhs: sp.Expr
    rhs: sp.Expr

    @property
    def residual(self) -> sp.Expr:
        return self.lhs - self.rhs

    @property
    def equation(self) -> sp.Eq:
        return sp.Eq(self.lhs, self.rhs, evaluate=False)


@dataclass(frozen=True)
class StitchingSystem:
    """A homogeneous linear system ``matrix * unknowns = 0`` and its determinant."""

    title: str
    parity: Parity
    damping: Damping
    segments: tuple[Segment, Segment]
    unknowns: tuple[sp.Symbol, ...]
    conditions: tuple[Condition, ...]
    matrix: sp.Matrix
    determinant: sp.Expr
    notes: tuple[str, ...] = field(default=())


def _linear_matrix(residuals, unknowns) -> sp.Matrix:
    """Coefficients of the unknowns in each residual, kept in the factored form the conditions
    produce (``(1+m)**2`` stays ``(1+m)**2``); linearity and homogeneity are checked."""
    rows = []
    for res in residuals:
        row = [sp.diff(res, u) for u in unknowns]
        rest = sp.expand(res - sum(c * u for c, u in zip(row, unknowns, strict=True)))
        if rest != 0 or any(sp.diff(c, u) != 0 for c in row for u in unknowns):  # pragma: no cover
            raise ValueError(f"condition is not linear homogeneous in {unknowns}: {res}")
        rows.append(row)
    return sp.Matrix(rows)


def _expanded_det(M: sp.Matrix) -> sp.Expr:
    """``expand(det M)``, computed by cofactor expansion in a polynomial ring whose generators are
    the entries' symbols and function values (sympy's ``sring``): the same expanded sum of
    monomials, without expanding the nested products of a determinant formula afterwards."""
    ring, elems = sring(list(M), expand=True)
    if not (ring.domain.is_ZZ or ring.domain.is_QQ):  # coefficients with symbols: the plain way
        return sp.expand(M.det(method="berkowitz"))
    n = M.rows
    rows = [elems[n * i : n * (i + 1)] for i in range(n)]

    def det(k: int, cols: tuple[int, ...]):
        if len(cols) == 1:
            return rows[k][cols[0]]
        out = ring.zero
        for j, c in enumerate(cols):
            if rows[k][c]:
                minor = det(k + 1, cols[:j] + cols[j + 1 :])
                out = out + rows[k][c] * minor if j % 2 == 0 else out - rows[k][c] * minor
        return out

    return det(0, tuple(range(n))).as_expr()


def _conditions(seg1: Segment, seg2: Segment, sigma: int, with_period: bool) -> list[Condition]:
    t, T = S.t, S.T
    J1, J2 = inertia(1), inertia(2)
    at = lambda e, v: e.subs(t, v)  # noqa: E731
    conds = [
        Condition("continuity of the angle at t = 0", at(seg1.phi, 0), at(seg2.phi, 0)),
        Condition(
            "angular-momentum jump at t = 0 (eq. 4)", J1 * at(seg1.dphi, 0), J2 * at(seg2.dphi, 0)
        ),
    ]
    if with_period:
        word = "anti-periodicity" if sigma < 0 else "periodicity"
        conds += [
            Condition(
                f"{word} of the angle across t = T/2",
                at(seg1.phi, T / 2),
                sigma * at(seg2.phi, -T / 2),
            ),
            Condition(
                f"{word} of the angular momentum across t = T/2",
                J1 * at(seg1.dphi, T / 2),
                sigma * J2 * at(seg2.dphi, -T / 2),
            ),
        ]
    return conds


def general_system(
    parity: Parity,
    damping: Damping = Damping.NONE,
    regimes: tuple[Regime, Regime] = (Regime.UNDER, Regime.UNDER),
) -> StitchingSystem:
    """All four stitching conditions for the general segments; unknowns ``A1, B1, A2, B2``."""
    return _general_system(Parity(parity), Damping(damping), tuple(Regime(r) for r in regimes))


@cache
def _general_system(
    parity: Parity, damping: Damping, regimes: tuple[Regime, Regime]
) -> StitchingSystem:
    seg1 = segment(S.omega1, S.A1, S.B1, damping, regimes[0])
    seg2 = segment(S.omega2, S.A2, S.B2, damping, regimes[1])
    conds = _conditions(seg1, seg2, parity.sigma, True)
    unknowns = (S.A1, S.B1, S.A2, S.B2)
    M = _linear_matrix([c.residual for c in conds], unknowns)
    det = _expanded_det(M)
    title = f"{'odd' if parity is Parity.ODD else 'even'} orders, damping={damping.value}"
    return StitchingSystem(title, parity, damping, (seg1, seg2), unknowns, tuple(conds), M, det)


def _shape(kind: str, omega, center, amp) -> tuple[sp.Expr, sp.Expr]:
    t = S.t
    f = sp.cos if kind == "cos" else sp.sin
    phi = amp * f(omega * (t - center))
    return phi, sp.diff(phi, t)


#: the signs of the paper's amplitudes (eqs. 8-9, 16-17, 20-21), so that (10)-(11), (22)-(23) come
#: out letter for letter; they do not change any determinant up to sign.
_PAPER_SIGNS = {
    EdgeKind.ODD_COS_SIN: (-1, -1),
    EdgeKind.ODD_SIN_COS: (1, -1),
    EdgeKind.EVEN_COS_COS: (-1, 1),
    EdgeKind.EVEN_SIN_SIN: (1, 1),
}


@cache
def edge_system(kind: EdgeKind) -> StitchingSystem:
    """The undamped boundary oscillation of a given symmetric shape; unknowns ``A1, A2``.

    Returns the two conditions at ``t = 0`` (eqs. 10-11, 22-23 for the paper's kinds) and their
    determinant (eqs. 12, 24).  The conditions across ``T/2`` are checked by :func:`implied_rows` to
    repeat those at ``t = 0``, which is why two conditions suffice.
    """
    kind = EdgeKind(kind)
    s1, s2 = _PAPER_SIGNS[kind]
    k1, k2 = kind.shapes
    T = S.T
    phi1, dphi1 = _shape(k1, S.omega1, T / 4, s1 * S.A1)
    phi2, dphi2 = _shape(k2, S.omega2, -T / 4, s2 * S.A2)
    seg1 = Segment(phi1, dphi1, S.omega1, Damping.NONE)
    seg2 = Segment(phi2, dphi2, S.omega2, Damping.NONE)
    conds = _conditions(seg1, seg2, kind.parity.sigma, False)
    unknowns = (S.A1, S.A2)
    M = _linear_matrix([c.residual for c in conds], unknowns)
    det = _expanded_det(M)
    return StitchingSystem(
        f"edge kind {kind.value}",
        kind.parity,
        Damping.NONE,
        (seg1, seg2),
        unknowns,
        tuple(conds),
        M,
        det,
    )


def implied_rows(kind: EdgeKind) -> tuple[sp.Matrix, sp.Matrix]:
    """Rows of the conditions across ``T/2`` for the symmetric shape, and those at ``t = 0``.

    For every kind the first equals the second up to the sign of each row, so the (anti)periodicity
    adds nothing and the system is 2 x 2.
    """
    sysm = edge_system(kind)
    full = _conditions(*sysm.segments, kind.parity.sigma, True)
    rows = _linear_matrix([c.residual for c in full], sysm.unknowns)
    return rows[2:, :], rows[:2, :]


@cache
def paper_system(parity: Parity) -> StitchingSystem:
    """The appendix's route (eqs. 31-32): general paper-model segments, with the conditions at
    ``t = 0`` solved first, which gives ``B2 = B1 = B`` and ``A2 = q A1 = q A``; the
    (anti)periodicity
    conditions, multiplied by ``exp(-gamma T/2)`` (the momentum one also divided by
    ``(1-m)**2 omega2``), are a 2 x 2 system for ``A, B`` in the abbreviations ``C_i, S_i, p, q``.
    """
    parity = Parity(parity)
    gen = general_system(parity, Damping.PAPER)
    cont, jump = gen.conditions[0], gen.conditions[1]
    solved = sp.solve([cont.residual, jump.residual], [S.B2, S.A2], dict=True)[0]
    q_def = inertia(1) * S.omega1 / (inertia(2) * S.omega2)
    # at t = 0 the conditions are rational in the symbols: cancellation decides the identity
    if sp.cancel(solved[S.A2] - q_def * S.A1) != 0 or solved[S.B2] != S.B1:  # pragma: no cover
        raise AssertionError("the conditions at t = 0 do not give B2 = B1, A2 = q A1")
    sub = {S.B2: S.B, S.B1: S.B, S.A1: S.A, S.A2: S.q * S.A}
    abbreviations = {
        sp.cos(S.omega1 * S.T / 2): S.C1,
        sp.sin(S.omega1 * S.T / 2): S.S1,
        sp.cos(S.omega2 * S.T / 2): S.C2,
        sp.sin(S.omega2 * S.T / 2): S.S2,
    }
    rows = []
    for k, c in enumerate(gen.conditions[2:]):
        res = sp.expand(c.residual.subs(sub) * sp.exp(-S.gamma * S.T / 2))
        res = sp.powsimp(res).subs(sp.exp(-S.gamma * S.T), S.p).subs(abbreviations)
        if k == 1:  # the momentum condition: (1+m)^2 omega1 = q (1-m)^2 omega2
            res = sp.expand(
                res.subs(S.omega1, S.q * inertia(2) * S.omega2 / inertia(1))
                / (inertia(2) * S.omega2)
            )
        # a polynomial in A, B, C_i, S_i, p, q once the inertia factors cancel
        poly = expanded_polynomial(res)
        rows.append(poly if poly is not None else sp.expand(sp.cancel(res)))
    M = _linear_matrix(rows, (S.A, S.B))
    conds = tuple(
        Condition(c.label, r, sp.Integer(0)) for c, r in zip(gen.conditions[2:], rows, strict=True)
    )
    return StitchingSystem(
        "paper model, amplitudes A and B (eq. 32)",
        parity,
        Damping.PAPER,
        gen.segments,
        (S.A, S.B),
        conds,
        M,
        _expanded_det(M),
    )


def propagator(seg: Segment, duration: sp.Expr) -> sp.Matrix:
    """The 2 x 2 map of ``(phi, phi')`` over ``duration`` along the free oscillation ``seg``.

    Built from the segment itself: its columns are the solutions started from ``(1, 0)`` and
    ``(0, 1)``, using the velocity the model assigns (so for the paper model, its approximation).
    """
    t = S.t
    A, B = sp.Dummy("A"), sp.Dummy("B")
    gen = segment(seg.omega, A, B, seg.damping, seg.regime)
    cols = []
    for x0, v0 in ((1, 0), (0, 1)):
        sol = sp.solve([gen.phi.subs(t, 0) - x0, gen.dphi.subs(t, 0) - v0], [A, B], dict=True)[0]
        cols.append(
            [
                sp.expand(gen.phi.subs(sol).subs(t, duration)),
                sp.expand(gen.dphi.subs(sol).subs(t, duration)),
            ]
        )
    return sp.Matrix([[cols[0][0], cols[1][0]], [cols[0][1], cols[1][1]]])


def monodromy(
    damping: Damping = Damping.NONE, regimes: tuple[Regime, Regime] = (Regime.UNDER, Regime.UNDER)
) -> sp.Matrix:
    """The period map of ``(phi, phi')`` from ``t = 0+`` (start of the bob-down half) to ``t = T+``.

    ``M = J_21 U_2(T/2) J_12 U_1(T/2)`` with ``J`` the angular-momentum jumps (eq. 4).
    """
    return _monodromy(Damping(damping), tuple(Regime(r) for r in regimes))


@cache
def _monodromy(damping: Damping, regimes: tuple[Regime, Regime]) -> sp.Matrix:
    seg1 = segment(S.omega1, S.A1, S.B1, damping, regimes[0])
    seg2 = segment(S.omega2, S.A2, S.B2, damping, regimes[1])
    U1 = propagator(seg1, S.T / 2)
    U2 = propagator(seg2, S.T / 2)
    J12 = sp.diag(1, inertia(1) / inertia(2))
    J21 = sp.diag(1, inertia(2) / inertia(1))
    return J21 * U2 * J12 * U1


def floquet_condition(
    parity: Parity, damping: Damping = Damping.NONE, regimes=(Regime.UNDER, Regime.UNDER)
):
    """``det(M - sigma I)``: zero iff ``sigma = (-1)**n`` is a Floquet multiplier.

    Returns ``(expression, factor)`` where ``factor`` is the derived ratio
    ``det(general_system) / det(M - sigma I)`` (``None`` if the two are not proportional), so that
    the determinant of the stitching system *is* the multiplier condition.
    """
    return _floquet_condition(Parity(parity), Damping(damping), tuple(Regime(r) for r in regimes))


@cache
def _floquet_condition(parity: Parity, damping: Damping, regimes: tuple[Regime, Regime]):
    M = monodromy(damping, regimes)
    s = parity.sigma
    cond = (M[0, 0] - s) * (M[1, 1] - s) - M[0, 1] * M[1, 0]
    det = general_system(parity, damping, regimes).determinant
    return cond, factor_between(det, cond)
