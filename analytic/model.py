"""The model: symbols, natural frequencies, the jump rule and free-oscillation segments.

Everything else in :mod:`analytic` is built from what this module defines, and from nothing typed in
from the paper.  Two layers of symbols are used:

* the paper's own, abstract symbols ``omega1, omega2, gamma, T, m`` in which the stitching systems
are
  written (so that the derived determinants look like the printed ones), and
* the project's units: time in units of ``T0 = 2*pi/omega0`` (so ``omega0 = 2*pi``), the period as
  ``tau = T/T0``, damping as the quality factor ``Q = omega0/(2*gamma)`` (so ``gamma*T0 = pi/Q``).

:func:`physical` maps the first onto the second.

The linearised equation in each half is ``phi'' + 2*gamma*phi' + omega_i**2*phi = 0`` (eqs. 2-3),
with
``omega1 = omega0/sqrt(1+m)`` while the bob is down (``0 < t < T/2``) and ``omega2 =
omega0/sqrt(1-m)``
while it is up (``-T/2 < t < 0``).  At a jump the angle is continuous and the angular momentum
``J*phi'`` with ``J ~ l**2`` is conserved (eq. 4): ``(1+m)**2 * phi1' = (1-m)**2 * phi2'``.
"""

from __future__ import annotations

from dataclasses import dataclass
from enum import Enum

import sympy as sp

__all__ = [
    "Damping",
    "Segment",
    "S",
    "physical",
    "segment",
    "jump_ratio",
    "inertia",
    "ode_residual",
    "derived_quantities",
]


class _Symbols:
    """The symbols of the model, with the assumptions the derivations rely on."""

    def __init__(self) -> None:
        self.m = sp.Symbol("m", positive=True)  # modulation depth, 0 < m < 1
        self.t = sp.Symbol("t", real=True)  # time
        self.T = sp.Symbol("T", positive=True)  # modulation period
        self.omega0 = sp.Symbol("omega_0", positive=True)
        self.omega1 = sp.Symbol("omega_1", positive=True)  # bob down, l1 = l0 (1+m)
        self.omega2 = sp.Symbol("omega_2", positive=True)  # bob up,   l2 = l0 (1-m)
        self.gamma = sp.Symbol("gamma", positive=True)  # viscous damping constant
        self.Omega1 = sp.Symbol("Omega_1", positive=True)  # sqrt(omega1**2 - gamma**2)
        self.Omega2 = sp.Symbol("Omega_2", positive=True)
        self.Lambda1 = sp.Symbol("Lambda_1", positive=True)  # sqrt(gamma**2 - omega1**2)
        self.Lambda2 = sp.Symbol("Lambda_2", positive=True)
        self.tau = sp.Symbol("tau", positive=True)  # T / T0
        self.Q = sp.Symbol("Q", positive=True)  # quality factor omega0 / (2 gamma)
        self.n = sp.Symbol("n", positive=True, integer=True)  # order of the resonance
        self.psi = sp.Symbol("psi", positive=True)  # omega_av T / 2 (average phase per half period)
        self.theta = sp.Symbol("theta", real=True)  # psi - n pi / 2 = omega_av Delta T / 2
        self.A1, self.B1, self.A2, self.B2 = sp.symbols("A_1 B_1 A_2 B_2")
        self.A, self.B = sp.symbols("A B")
        # the paper's abbreviations, as symbols, for printing and for the reduced forms
        self.q = sp.Symbol("q", positive=True)
        self.p = sp.Symbol("p", positive=True)
        self.r = sp.Symbol("r", positive=True)  # (q-1)/(q+1)
        self.beta = sp.Symbol("beta", positive=True)  # (omega2-omega1)/(omega2+omega1)
        self.g = sp.Symbol("g", nonnegative=True)  # gamma / omega_av
        self.omega_av = sp.Symbol(r"\omega_{av}", positive=True)
        self.Domega = sp.Symbol(r"\Delta\omega", positive=True)
        self.T_av = sp.Symbol(r"T_{av}", positive=True)
        self.T0 = sp.Symbol("T_0", positive=True)
        self.DT = sp.Symbol(r"\Delta T", real=True)
        self.C1, self.C2, self.S1, self.S2 = sp.symbols("C_1 C_2 S_1 S_2", real=True)


S = _Symbols()


class Damping(str, Enum):
    """How friction enters the segments.

    ``NONE``: no friction.  ``PAPER``: the paper's appendix (eqs. 28-30): ``e**(-gamma t)`` times an
    oscillation of the *undamped* frequency, differentiated as if the exponential were constant.
    ``EXACT``: the true damped linear oscillator (frequency ``sqrt(omega**2 - gamma**2)``, full
    derivative; critically and over-damped forms where ``gamma >= omega``).
    """

    NONE = "none"
    PAPER = "paper"
    EXACT = "exact"


class Regime(str, Enum):
    UNDER = "under"
    CRITICAL = "critical"
    OVER = "over"


@dataclass(frozen=True)
class Segment:
    """A free oscillation on one half period: ``phi(t)`` and the velocity the model assigns to it.

    For the ``paper`` model ``dphi`` is *not* ``d(phi)/dt`` (the paper's approximation, eqs. 28-30);
    for every other model it is, and :func:`ode_residual` of it vanishes identically.
    """

    phi: sp.Expr
    dphi: sp.Expr
    omega: sp.Symbol
    damping: Damping
    regime: Regime = Regime.UNDER

    @property
    def is_exact_derivative(self) -> bool:
        return self.damping is not Damping.PAPER


def segment(
    omega: sp.Symbol,
    A: sp.Expr,
    B: sp.Expr,
    damping: Damping = Damping.NONE,
    regime: Regime = Regime.UNDER,
    t: sp.Symbol | None = None,
) -> Segment:
    """The general free oscillation ``A * sin-like + B * cos-like`` of frequency ``omega``.

    The amplitudes are those of the paper's eqs. (28)-(30): ``B`` is the angle at ``t = 0`` in every
    model.  In the exact model ``Omega = sqrt(omega**2 - gamma**2)`` (under-damped), ``Lambda =
    sqrt(gamma**2 - omega**2)`` (over-damped), and ``(A t + B) e**(-gamma t)`` at critical damping.
    """
    t = S.t if t is None else t
    g = S.gamma
    damping = Damping(damping)
    if damping is Damping.NONE:
        phi = A * sp.sin(omega * t) + B * sp.cos(omega * t)
        return Segment(phi, sp.diff(phi, t), omega, damping)
    decay = sp.exp(-g * t)
    if damping is Damping.PAPER:
        phi = decay * (A * sp.sin(omega * t) + B * sp.cos(omega * t))
        dphi = decay * (A * omega * sp.cos(omega * t) - B * omega * sp.sin(omega * t))
        return Segment(phi, dphi, omega, damping)
    regime = Regime(regime)
    if regime is Regime.UNDER:
        W = _Omega(omega)
        phi = decay * (A * sp.sin(W * t) + B * sp.cos(W * t))
    elif regime is Regime.OVER:
        L = _Lambda(omega)
        phi = decay * (A * sp.sinh(L * t) + B * sp.cosh(L * t))
    else:
        phi = decay * (A * t + B)
    return Segment(phi, sp.diff(phi, t), omega, damping, regime)


def _Omega(omega: sp.Symbol) -> sp.Symbol:
    return {S.omega1: S.Omega1, S.omega2: S.Omega2}[omega]


def _Lambda(omega: sp.Symbol) -> sp.Symbol:
    return {S.omega1: S.Lambda1, S.omega2: S.Lambda2}[omega]


def damped_frequency_relations() -> dict[sp.Symbol, sp.Expr]:
    """``Omega_i = sqrt(omega_i**2 - gamma**2)`` and ``Lambda_i = sqrt(gamma**2 - omega_i**2)``."""
    g = S.gamma
    return {
        S.Omega1: sp.sqrt(S.omega1**2 - g**2),
        S.Omega2: sp.sqrt(S.omega2**2 - g**2),
        S.Lambda1: sp.sqrt(g**2 - S.omega1**2),
        S.Lambda2: sp.sqrt(g**2 - S.omega2**2),
    }


def ode_residual(seg: Segment, t: sp.Symbol | None = None) -> sp.Expr:
    """``phi'' + 2 gamma phi' + omega**2 phi`` for the segment (0 for an exact solution).

    Uses the true derivative of ``phi`` and the frequency relations, whatever the model's ``dphi``.
    """
    t = S.t if t is None else t
    g = S.gamma if seg.damping is not Damping.NONE else 0
    phi = seg.phi
    res = sp.diff(phi, t, 2) + 2 * g * sp.diff(phi, t) + seg.omega**2 * phi
    res = res.subs(damped_frequency_relations())
    return sp.simplify(sp.expand(res))


def inertia(half: int) -> sp.Expr:
    """Moment of inertia of half ``1`` (bob down) or ``2`` (bob up), in units of ``J0``."""
    return (1 + S.m) ** 2 if half == 1 else (1 - S.m) ** 2


def jump_ratio(from_half: int, to_half: int) -> sp.Expr:
    """Factor on the angular velocity at a jump (eq. 4: angular momentum ``J phi'`` conserved)."""
    return inertia(from_half) / inertia(to_half)


def physical(expr: sp.Expr, *, damping: bool = True) -> sp.Expr:
    """Express a formula of the paper's symbols in the project's units (``T0 = 1``).

    ``omega0 = 2 pi``, ``omega_i = 2 pi / sqrt(1 -+ m)``, ``T = tau``, ``gamma = pi / Q``; the
    damped frequencies ``Omega_i, Lambda_i`` and the paper's abbreviations ``q, p, r, beta, g,
    omega_av, Delta omega, T_av, T_0, C_i, S_i`` are replaced by what they stand for.
    """
    dq = derived_quantities()
    subs = dict(dq)
    subs.update(damped_frequency_relations())
    # symbols replaced by expressions free of the replaced symbols: one simultaneous walk each
    # (the same as ``subs``, without its pattern matching)
    expr = sp.sympify(expr).xreplace(subs)
    base = {
        S.omega0: 2 * sp.pi,
        S.omega1: 2 * sp.pi / sp.sqrt(1 + S.m),
        S.omega2: 2 * sp.pi / sp.sqrt(1 - S.m),
        S.T: S.tau,
        S.T0: sp.Integer(1),
    }
    if damping:
        base[S.gamma] = sp.pi / S.Q
    return expr.xreplace(base)


def derived_quantities() -> dict[sp.Symbol, sp.Expr]:
    """The paper's abbreviations in terms of the primary symbols (eqs. 5, 14, 33, appendix).

    ``q`` is *defined* here from the stitching (the ratio of ``(1+m)**2 omega1`` to ``(1-m)**2
    omega2`` that multiplies the jump); that it equals ``((1+m)/(1-m))**(3/2)`` (eq. 14) is derived
    in :mod:`analytic.reductions`, not assumed.
    """
    w1, w2, T = S.omega1, S.omega2, S.T
    omega_av = (w1 + w2) / 2
    return {
        S.q: inertia(1) * w1 / (inertia(2) * w2),
        S.p: sp.exp(-S.gamma * T),
        S.omega_av: omega_av,
        S.Domega: w2 - w1,
        S.T_av: 2 * sp.pi / omega_av,
        S.C1: sp.cos(w1 * T / 2),
        S.C2: sp.cos(w2 * T / 2),
        S.S1: sp.sin(w1 * T / 2),
        S.S2: sp.sin(w2 * T / 2),
        S.T0: 2 * sp.pi / S.omega0,
    }
