"""Every member of the family, derived once: monodromy, trace form and normal-form parameters.

For a system of :mod:`analytic.system` (phases of length ``D T`` and ``(1 - D) T``, frequencies
``omega_i``, velocity factor ``k`` at the switches) the period map is

    M = J21 . U2((1 - D) T) . J12 . U1(D T),    J12 = diag(1, k),  J21 = diag(1, 1/k),

and the chain of :mod:`analytic.normal_form` goes through with symbolic ``D`` and ``k``, each link
proven here by :func:`analytic.identity.prove_zero`:

1. ``det M = p^2`` with ``p = exp(-gamma T)`` (:func:`det_link`);
2. the trace form ``tr M = p (2 cos a1 cos a2 - K sin a1 sin a2)`` with the phases
   ``a1 = W1 D T``, ``a2 = W2 (1 - D) T`` (``W_i = omega_i`` without friction and in the paper
   model, ``sqrt(omega_i^2 - gamma^2)`` in the exact model) and the coupling (:func:`coupling`)

       K = q + 1/q,  q = k omega1/omega2                         (no friction; paper model)
       K = (k omega1^2 + omega2^2/k - 2 gamma^2) / (W1 W2)        (exact model)

   (:func:`trace_link`);
3. the product-to-sum lemma and the normal form (:func:`analytic.normal_form.normal_form_link`,
   which holds for any phases ``a1, a2``): ``det(M - sigma I) = p (K + 2) N`` with
   ``x = (a1 + a2)/2 = w T/2``, ``w = D W1 + (1 - D) W2`` (the mean frequency), ``y = (a2 - a1)/2
   = beta x``, ``beta = ((1 - D) W2 - D W1)/w``, ``r^2 = (K - 2)/(K + 2)`` and ``gamma T/2 = g x``,
   ``g = gamma / w``.

So **every member, every duty** has the paper's normal form; only ``r, beta, g, w`` change.  Without
friction ``N`` is a difference of squares and factors into one equation per edge (the per-edge
factorisation holds for every duty: each phase is symmetric about its own midpoint); with friction
``N`` has the extra ``(1 - r^2) sinh^2(g x)`` and does not factor.  ``|r| < 1`` and ``|beta| < 1``
for every member (``q > 0``; ``D, W_i > 0``), which is all the window theorem of
``docs/theory.md`` uses, so it carries over: each edge equation has one simple root per order.
``K >= 2`` also in the exact model, since ``k A + B/k >= 2 sqrt(A B)`` for ``A, B >= 0``.

:func:`parameter_forms` gives ``r, 1 - r^2, beta, w, g`` and the offset of the exact model's
mean frequency in forms that do not cancel: every difference of nearly equal numbers is turned into
a rational function (``q - 1 = (q^2 - 1)/(q + 1)``, ``K - 2`` as a difference of squares), which
sympy factors, so that its zero at ``m = 0`` is an explicit factor.  Each form is proven equal to
its definition when it is built.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from functools import cache

import sympy as sp

from .factoring import factor
from .identity import Verdict, prove_zero
from .model import Damping, Regime, S
from .normal_form import Link
from .stitching import propagator
from .system import System

__all__ = [
    "D",
    "k",
    "monodromy",
    "coupling",
    "phases",
    "det_link",
    "trace_link",
    "ParameterForms",
    "parameter_forms",
    "TraceForms",
    "trace_forms",
    "stitching_system",
    "stitching_link",
    "stationary_ratio",
]

#: the duty and the velocity factor at the switch 1 -> 2, as symbols
D = sp.Symbol("D", positive=True)
k = sp.Symbol("k", positive=True)


def _damped(damping: Damping) -> bool:
    return Damping(damping) is not Damping.NONE


@cache
def monodromy(
    damping: Damping = Damping.NONE, regimes: tuple[Regime, Regime] = (Regime.UNDER, Regime.UNDER)
) -> sp.Matrix:
    """``M = J21 U2((1-D) T) J12 U1(D T)`` in the symbols ``omega_i, gamma, T, D, k``."""
    from .model import segment

    damping = Damping(damping)
    seg1 = segment(S.omega1, S.A1, S.B1, damping, Regime(regimes[0]))
    seg2 = segment(S.omega2, S.A2, S.B2, damping, Regime(regimes[1]))
    U1 = propagator(seg1, D * S.T)
    U2 = propagator(seg2, (1 - D) * S.T)
    return sp.diag(1, 1 / k) * U2 * sp.diag(1, k) * U1


def coupling(damping: Damping = Damping.NONE) -> sp.Expr:
    """``K`` of the trace form (step 2), in ``omega_i, Omega_i, gamma, k``."""
    if Damping(damping) is Damping.EXACT:
        g = S.gamma
        return (k * S.omega1**2 + S.omega2**2 / k - 2 * g**2) / (S.Omega1 * S.Omega2)
    q = k * S.omega1 / S.omega2
    return q + 1 / q


def phases(damping: Damping = Damping.NONE) -> tuple[sp.Expr, sp.Expr]:
    """``(a1, a2)``: the phase each segment turns through, ``W1 D T`` and ``W2 (1 - D) T``."""
    if Damping(damping) is Damping.EXACT:
        return S.Omega1 * D * S.T, S.Omega2 * (1 - D) * S.T
    return S.omega1 * D * S.T, S.omega2 * (1 - D) * S.T


def _link(name, lhs, rhs, why) -> Link:
    return Link(name, lhs, rhs, why, prove_zero(sp.expand(lhs - rhs)))


@cache
def det_link(damping: Damping = Damping.NONE) -> Link:
    """Step 1: ``det M = p^2`` for every member and duty."""
    damping = Damping(damping)
    p2 = sp.exp(-2 * S.gamma * S.T) if _damped(damping) else sp.Integer(1)
    return _link("det M", sp.expand(monodromy(damping).det()), p2, "det J12 J21 = 1")


@cache
def trace_link(damping: Damping = Damping.NONE) -> Link:
    """Step 2: ``tr M = p (2 cos a1 cos a2 - K sin a1 sin a2)`` for every member and duty
    (under-damped or undamped phases)."""
    damping = Damping(damping)
    a1, a2 = phases(damping)
    p = sp.exp(-S.gamma * S.T) if _damped(damping) else sp.Integer(1)
    form = p * (2 * sp.cos(a1) * sp.cos(a2) - coupling(damping) * sp.sin(a1) * sp.sin(a2))
    lhs = sp.expand(monodromy(damping).trace())
    if damping is Damping.EXACT:
        lhs = lhs.subs({S.omega1: sp.sqrt(S.Omega1**2 + S.gamma**2)})
        lhs = lhs.subs({S.omega2: sp.sqrt(S.Omega2**2 + S.gamma**2)})
        form = form.subs({S.omega1: sp.sqrt(S.Omega1**2 + S.gamma**2)})
        form = form.subs({S.omega2: sp.sqrt(S.Omega2**2 + S.gamma**2)})
    return _link("trace form", lhs, form, "entries of the phase maps and the switches")


# ---------------------------------------------------------------------------------------------
# the normal-form parameters of one system, in forms that do not cancel


@dataclass(frozen=True)
class ParameterForms:
    """The normal-form parameters of one system and damping model, ready to compile.

    ``atoms``: name -> rational function of ``m`` (and ``Q``), each difference of nearly equal
    numbers already factored by sympy; computed exactly when ``m, Q`` are exact.
    ``values``: name -> expression in the atom symbols (square roots, sums of positive terms,
    products), evaluated in the caller's number type.  The names are ``r`` (signed ``(q-1)/(q+1)``,
    or ``r^2`` in the exact model as ``r2``), ``u = 1 - r^2``, ``w``, ``beta`` (signed), ``bm_pos``
    and ``bm_neg`` (``1 - |beta|`` for ``beta >= 0`` and ``beta < 0``), ``g``, ``w0`` (the
    undamped ``w``) and ``dw`` (``w0 - w``).  ``definitions``: the same from their definitions
    (for the proof, :meth:`check`).
    """

    system: System
    damping: Damping
    atoms: dict = field(hash=False)
    values: dict = field(hash=False)
    definitions: dict = field(hash=False)

    @property
    def atom_symbols(self) -> tuple:
        return tuple(sp.Symbol(name) for name in self.atoms)

    def check(self) -> dict[str, Verdict]:
        """Each value, with the atoms put in, proven equal to its definition."""
        subs = {sp.Symbol(n): e for n, e in self.atoms.items()}
        out = {}
        for name, expr in self.values.items():
            diff = sp.together(expr.subs(subs) - self.definitions[name])
            out[name] = prove_zero(diff)
        return out


def _factored(expr) -> sp.Expr:
    """A rational function of ``m`` (and ``Q``) with its numerator and denominator factored."""
    num, den = sp.fraction(sp.cancel(sp.together(expr)))
    return factor(num) / factor(den)


@cache
def parameter_forms(system: System, damping: Damping = Damping.NONE) -> ParameterForms:
    """The parameter forms of ``system`` in the model ``damping`` (``NONE``, ``PAPER`` or
    ``EXACT``), proven equal to their definitions (a failed proof raises)."""
    damping = Damping(damping)
    m, Q = S.m, S.Q
    Dv = sp.Rational(system.duty.numerator, system.duty.denominator)
    W1e, W2e, ke = (sp.sympify(v) for v in system.values(m))
    G = 1 / (2 * Q)  # gamma / omega0
    sym = sp.Symbol
    W1, W2, kk = sym("W1"), sym("W2"), sym("k")
    s1, s2 = sp.sqrt(W1), sp.sqrt(W2)
    atoms = {"W1": W1e, "W2": W2e, "k": ke}
    w0 = Dv * s1 + (1 - Dv) * s2
    w0_def = Dv * sp.sqrt(W1e) + (1 - Dv) * sp.sqrt(W2e)
    if damping is not Damping.EXACT:
        atoms["E"] = _factored(ke**2 * W1e - W2e)  # (q^2 - 1) omega2^2
        atoms["B"] = _factored((1 - Dv) ** 2 * W2e - Dv**2 * W1e)  # beta w^2
        q = kk * s1 / s2
        values = {
            "r": sym("E") / (W2 * (q + 1) ** 2),
            "u": 4 * q / (q + 1) ** 2,
            "w": w0,
            "beta": sym("B") / w0**2,
            "bm_pos": 2 * Dv * s1 / w0,
            "bm_neg": 2 * (1 - Dv) * s2 / w0,
            "w0": w0,
            "dw": sp.Integer(0),
        }
        qd = ke * sp.sqrt(W1e) / sp.sqrt(W2e)
        bd = ((1 - Dv) * sp.sqrt(W2e) - Dv * sp.sqrt(W1e)) / w0_def
        defs = {
            "r": (qd - 1) / (qd + 1),
            "u": 1 - ((qd - 1) / (qd + 1)) ** 2,
            "w": w0_def,
            "beta": bd,
            "bm_pos": 1 - bd,
            "bm_neg": 1 + bd,
            "w0": w0_def,
            "dw": sp.Integer(0),
        }
        if damping is Damping.PAPER:
            atoms["G"] = G
            values["g"] = sym("G") / w0
            defs["g"] = G / w0_def
    else:
        G2 = G**2
        atoms["G"] = G
        atoms["O1"] = _factored(W1e - G2)  # Omega1^2 / omega0^2: its sign is the regime
        atoms["O2"] = _factored(W2e - G2)
        Ne = ke * W1e + W2e / ke - 2 * G2
        atoms["N"] = _factored(Ne)
        atoms["E"] = _factored(Ne**2 - 4 * (W1e - G2) * (W2e - G2))  # (K^2 - 4) (W1 W2)^2
        atoms["B"] = _factored((1 - Dv) ** 2 * (W2e - G2) - Dv**2 * (W1e - G2))
        o1, o2 = sp.sqrt(sym("O1")), sp.sqrt(sym("O2"))
        w = Dv * o1 + (1 - Dv) * o2
        Gs = sym("G")
        values = {
            "r2": sym("E") / (sym("N") + 2 * o1 * o2) ** 2,
            "u": 4 * o1 * o2 / (sym("N") + 2 * o1 * o2),
            "w": w,
            "beta": sym("B") / w**2,
            "bm_pos": 2 * Dv * o1 / w,
            "bm_neg": 2 * (1 - Dv) * o2 / w,
            "g": Gs / w,
            "w0": w0,
            # omega - Omega = gamma^2 / (omega + Omega): no cancellation
            "dw": Dv * Gs**2 / (s1 + o1) + (1 - Dv) * Gs**2 / (s2 + o2),
        }
        O1d, O2d = sp.sqrt(W1e - G2), sp.sqrt(W2e - G2)
        Kd = Ne / (O1d * O2d)
        wd = Dv * O1d + (1 - Dv) * O2d
        bd = ((1 - Dv) * O2d - Dv * O1d) / wd
        defs = {
            "r2": (Kd - 2) / (Kd + 2),
            "u": 4 / (Kd + 2),
            "w": wd,
            "beta": bd,
            "bm_pos": 1 - bd,
            "bm_neg": 1 + bd,
            "g": G / wd,
            "w0": w0_def,
            "dw": w0_def - wd,
        }
    forms = ParameterForms(system, damping, atoms, values, defs)
    return forms


@dataclass(frozen=True)
class TraceForms:
    """The exact model's trace-form parameters of one system, in units of ``gamma`` and for two
    half periods (the caller scales them to the phases' lengths): ``kappa = N / gamma^2 = K
    Omega1 Omega2 / gamma^2`` and ``u_i = Omega_i^2 / gamma^2``, whose sign is phase ``i``'s regime
    (``nu_i = sqrt|u_i|``), as rational functions of ``m`` and ``Q``.

    Each is written as ``4 Q^2`` times a sum of the law's own functions of ``m``, each factored by
    itself, less a constant (``u_i = (omega_i/gamma)^2 - 1``, ``kappa = (k omega1^2 + omega2^2/k)
    / gamma^2 - 2``): a ball of depths enters every term once, so that over a range of depths no
    term loses ``4 Q^2`` against the constant (the pendulum's ``u1 = 4 Q^2/(1 + m) - 1``, not
    ``(4 Q^2 - 1 - m)/(1 + m)``, whose ball loses ``4 Q^2`` against 1 for a small ``Q`` near ``m =
    1``).  ``definitions``: the same from the atoms of :func:`parameter_forms` (``N/G^2``,
    ``O_i/G^2``), for the proof (:meth:`check`)."""

    system: System
    values: dict = field(hash=False)
    definitions: dict = field(hash=False)

    def check(self) -> dict[str, Verdict]:
        """Each form proven equal to its definition."""
        return {
            name: prove_zero(sp.together(expr - self.definitions[name]))
            for name, expr in self.values.items()
        }


@cache
def trace_forms(system: System) -> TraceForms:
    """The trace-form parameters ``kappa``, ``u1``, ``u2`` of ``system`` (:class:`TraceForms`),
    proven equal to their definitions (a failed proof raises)."""
    atoms = parameter_forms(system, Damping.EXACT).atoms
    W1e, W2e, ke = (sp.sympify(v) for v in system.values(S.m))
    G = atoms["G"]
    scale = sp.cancel(1 / G**2)  # (omega0/gamma)^2 = 4 Q^2
    values = {
        "kappa": scale * (_factored(ke * W1e) + _factored(W2e / ke)) - 2,
        "u1": scale * _factored(W1e) - 1,
        "u2": scale * _factored(W2e) - 1,
    }
    definitions = {
        "kappa": atoms["N"] / G**2,
        "u1": atoms["O1"] / G**2,
        "u2": atoms["O2"] / G**2,
    }
    forms = TraceForms(system, values, definitions)
    bad = [name for name, v in forms.check().items() if not v.holds]
    if bad:  # pragma: no cover - derivation guard
        raise AssertionError(f"trace forms of {system.label} not proven: {bad}")
    return forms


# ---------------------------------------------------------------------------------------------
# the stitching system of the family, and its link to the monodromy


@cache
def stitching_system(parity, damping: Damping = Damping.NONE) -> tuple[sp.Matrix, sp.Expr]:
    """The paper's stitching for any duty and jump: segments ``phi1`` on ``0 < t < D T`` and
    ``phi2`` on ``-(1 - D) T < t < 0``, joined by continuity of the angle and ``k phi1'(0) =
    phi2'(0)`` at ``t = 0`` (the switch 2 -> 1 divides the velocity by ``k``), and by
    (anti)periodicity across ``t = D T``: ``phi1(D T) = sigma phi2(-(1-D) T)``, ``k phi1'(D T) =
    sigma phi2'(-(1-D) T)``.  Returns the 4 x 4 matrix in ``A1, B1, A2, B2`` and its determinant."""
    from .model import segment
    from .stitching import Parity

    sigma = Parity(parity).sigma
    damping = Damping(damping)
    t, T = S.t, S.T
    seg1 = segment(S.omega1, S.A1, S.B1, damping)
    seg2 = segment(S.omega2, S.A2, S.B2, damping)
    at = lambda e, v: e.subs(t, v)  # noqa: E731
    residuals = [
        at(seg1.phi, 0) - at(seg2.phi, 0),
        k * at(seg1.dphi, 0) - at(seg2.dphi, 0),
        at(seg1.phi, D * T) - sigma * at(seg2.phi, -(1 - D) * T),
        k * at(seg1.dphi, D * T) - sigma * at(seg2.dphi, -(1 - D) * T),
    ]
    unknowns = (S.A1, S.B1, S.A2, S.B2)
    M = sp.Matrix([[sp.diff(r, u) for u in unknowns] for r in residuals])
    return M, sp.expand(M.det(method="berkowitz"))


@cache
def stitching_link(parity, damping: Damping = Damping.NONE) -> Link:
    """``det(stitching system) = F det(M - sigma I)`` for every duty and jump, with ``F > 0`` (a
    product of positive symbols and exponentials): the determinant the paper builds *is* the
    Floquet condition of the family."""
    from .identity import factor_between
    from .stitching import Parity

    parity = Parity(parity)
    _, det = stitching_system(parity, damping)
    Mm = monodromy(Damping(damping))
    s = parity.sigma
    cond = sp.expand((Mm[0, 0] - s) * (Mm[1, 1] - s) - Mm[0, 1] * Mm[1, 0])
    F = factor_between(det, cond)
    ok = F is not None and bool(sp.sympify(F).is_positive)  # never zero: the same roots
    return Link(
        f"stitching = F det(M - sigma I), {parity.name.lower()} orders",
        det,
        cond if F is None else F * cond,
        "the conditions at t = 0 and t = D T are the monodromy's, up to the factor F",
        Verdict(ok, "symbolic", factor=F),
    )


def stationary_ratio(edge_shape: str) -> sp.Expr:
    """``phi'(0)/phi(0)`` of a frictionless edge oscillation for any member and duty: the edge
    solutions are symmetric (``"cos"``) or antisymmetric (``"sin"``) about the middle of phase 1,
    ``phi1 = A cos(omega1 (t - D T/2))`` or ``A sin(omega1 (t - D T/2))``, which gives
    ``omega1 tan(omega1 D T/2)`` or ``-omega1 cot(omega1 D T/2)`` (the paper's condition after
    eq. 15 is ``D = 1/2``)."""
    t = S.t
    f = sp.cos if edge_shape == "cos" else sp.sin
    phi = f(S.omega1 * (t - D * S.T / 2))
    return sp.simplify(sp.diff(phi, t).subs(t, 0) / phi.subs(t, 0))
