"""The parameters of the boundary equations, in forms that do not cancel.

:func:`analytic.normal_form.parameters` gives the *definitions* (``r^2 = (K-2)/(K+2)``,
``beta = (Omega2 - Omega1)/(Omega2 + Omega1)``, ...).  Evaluated as written they lose digits: at
``m = 1e-12`` both ``K - 2`` and ``Omega2 - Omega1`` are differences of nearly equal numbers, and
near ``m = 1`` so is ``1 - r^2``.  This module evaluates the same quantities through rearrangements
in which every subtraction is either exact or of numbers of different size; ``tests/test_params.py``
proves each one equal to its definition.

Without friction, and in the ``paper`` model (whose ``K`` is the undamped one), with
``s = sqrt((1-m)(1+m))``::

    beta  = m / (1 + s)                      (= tanh a,  a = artanh(m)/2)
    1 - beta = (1 + s - m) / (1 + s)
    r     = beta (3 + beta^2) / (1 + 3 beta^2)   (= tanh 3a)
    1-r^2 = (1 - beta^2)^3 / (1 + 3 beta^2)^2,   1 - beta^2 = 2 s / (1 + s)
    w     = sqrt((1 + s)/2) / s              (= omega_av / omega0)
    g     = 1 / (2 Q w)                      (paper model; 0 without friction)

In the ``exact`` model with both halves under-damped, in units of ``gamma = pi/Q`` (``nu_i =
Omega_i/gamma = sqrt(u_i/(1 +- m))``, ``u_i = 4 Q^2 - (1 +- m)``)::

    w'     = (nu1 + nu2) / (4 Q)
    beta'  = 8 m Q^2 / ((1 - m^2) (nu1 + nu2)^2)          (Omega2^2 - Omega1^2 is exact)
    K' - 2 = (U^2 + d^2) / (nu1 nu2),  K' + 2 = (V^2 + d^2) / (nu1 nu2)
    r'^2   = (U^2 + d^2) / (V^2 + d^2),  1 - r'^2 = 4 nu1 nu2 / (V^2 + d^2)
    g'     = 2 / (nu1 + nu2),   1 - beta' = 2 nu1 / (nu1 + nu2)

with ``V = ((1+m)^2 nu1 + (1-m)^2 nu2)/(1-m^2)``, ``d = 4m/(1-m^2)`` and
``U = ((1+m)^2 nu1 - (1-m)^2 nu2)/(1-m^2) = 2m((4Q^2-1)(3+m^2) - (1+3m^2)) / ((1-m^2)(1-m^2) V)``
(the difference of the two square roots rewritten as a difference of squares, which is a
polynomial).  ``K' - 2`` is a sum of squares: ``r'^2 > 0`` always.

When a half is critically or over-damped (``u_i <= 0``) the normal form does not apply; the trace
form ``2 C1 C2 - kappa S1 S2`` does, with ``kappa = K' nu1 nu2`` and ``nu_i = Omega_i/gamma``, whose
parameters are not rearranged here: :func:`trace_params` evaluates the forms sympy derives for
every member of the family (:func:`analytic.family.trace_forms`; for the pendulum ``kappa =
4Q^2((1+m)/(1-m)^2 + (1-m)/(1+m)^2) - 2`` and ``nu_i^2 = |4Q^2/(1 +- m) - 1|``).

Every function takes the depth ``m`` and quality factor ``Q`` as numbers of one back end
(:func:`verify.derived.backend`) -- arb balls, mpmath numbers, floats or float64 arrays -- and
returns numbers of the same kind.
"""

from __future__ import annotations

from dataclasses import dataclass, fields
from fractions import Fraction
from functools import lru_cache

import mpmath
from flint import arb, fmpq

from analytic.system import PAPER, System, phase_regimes

from .derived import Backend
from .system_params import _evaluate, canonical, trace_atoms

__all__ = [
    "NormalParams",
    "TraceParams",
    "Halves",
    "exact_fraction",
    "halves",
    "form_for",
    "NEAR_CRITICAL",
    "NEAR_ONE",
    "normal_params",
    "normal_values",
    "exact_arb_values",
    "undamped_params",
    "trace_params",
    "omega_av",
]


@dataclass(frozen=True)
class NormalParams:
    """Parameters of the normal form ``N = f(x)^2 - r^2 f(beta x)^2 + (1-r^2) sinh(g x)^2``.

    ``w`` is ``omega_av/omega0`` of the model (``T/T0 = x/(pi w)``); ``w0`` that of the undamped
    pendulum (eq. 5: ``T_av/T0 = 1/w0``); ``dinv = 1/w - 1/w0`` (zero unless the exact model with
    friction), computed without cancellation.
    """

    r: object
    r2: object
    u: object  # 1 - r^2
    beta: object
    w: object
    g: object
    w0: object
    dinv: object
    bm: object = None  # 1 - beta


_NORMAL_FIELDS = tuple(f.name for f in fields(NormalParams))


@dataclass(frozen=True)
class TraceParams:
    """Parameters of the trace form (exact model): ``kappa``, ``nu1``, ``nu2`` in units of
    ``gamma``, ``Q`` (``zeta = gamma T/2 = pi tau/(2 Q)``) and ``w0`` (undamped ``omega_av /
    omega0``)."""

    kappa: object
    nu1: object
    nu2: object
    Q: object
    w0: object


@dataclass(frozen=True)
class Halves:
    """How each half behaves: ``"undamped"``, ``"under"``, ``"critical"`` or ``"over"``, decided
    exactly (rational arithmetic on ``4 Q^2 - (1 +- m)``)."""

    half1: str
    half2: str

    @property
    def normal(self) -> bool:
        """Whether the normal form applies (no half critically or over-damped)."""
        return self.half1 in ("undamped", "under") and self.half2 in ("undamped", "under")


#: below this ``1 - beta`` (``m > 0.995``) the certified solvers use the forms for ``m -> 1``
#: (:func:`verify.derived.near_one_forms`, :func:`verify.derived.order1_forms`), whose terms are
#: of the size of the result; the standard forms cancel to ``1 - beta`` there
NEAR_ONE = 0.05

#: below this ``nu1 = Omega1/gamma`` (half 1 close to critical damping) the normal form
#: degenerates (``r, beta -> 1``: every term of ``D`` is O(1) while ``D`` is O(nu1)); the trace form
#: is used instead, whose terms stay of the size of ``D``
NEAR_CRITICAL = 0.05


def form_for(
    m: Fraction, Q: Fraction | None, damping: str, system: System = PAPER
) -> tuple[str, tuple[str, str] | None]:
    """Which equations solve the problem: ``("normal", None)`` or ``("trace", (half1, half2))``.

    The normal form without friction, in the paper model, and in the exact model with both halves
    under-damped and half 1 (the low-frequency phase) not within :data:`NEAR_CRITICAL` of critical
    damping (``Omega1^2 / gamma^2 < NEAR_CRITICAL^2``); the trace form otherwise."""
    if type(m) is Fraction and type(Q) is Fraction:
        # cached by the integers (hashing a Fraction costs more than the lookup; a System's hash
        # about a quarter of one)
        if system is PAPER:
            return _form_for_paper(m.numerator, m.denominator, Q.numerator, Q.denominator, damping)
        return _form_for_system(
            m.numerator, m.denominator, Q.numerator, Q.denominator, damping, system
        )
    return _form_for(m, Q, damping, system)


@lru_cache(maxsize=256)
def _form_for_paper(mp: int, mq: int, qp: int, qq: int, damping: str):
    return _form_for(Fraction(mp, mq), Fraction(qp, qq), damping, PAPER)


@lru_cache(maxsize=256)
def _form_for_system(mp: int, mq: int, qp: int, qq: int, damping: str, system: System):
    return _form_for(Fraction(mp, mq), Fraction(qp, qq), damping, system)


@lru_cache(maxsize=256)
def _form_for(m, Q, damping: str, system: System) -> tuple[str, tuple[str, str] | None]:
    """:func:`form_for` (exact rational decisions: the same answer for the same arguments)."""
    if system is not PAPER and not system.is_paper:
        from .system_params import canonical

        system = canonical(system)
    hv = halves(m, Q, damping, system)
    if not hv.normal:
        return "trace", (hv.half1, hv.half2)
    if Q is not None and damping == "exact":
        w1 = system.omega1_sq(m if system.uses_depth else None)
        g2 = 1 / (4 * Q * Q)
        if (w1 - g2) / g2 < Fraction(NEAR_CRITICAL) ** 2:
            return "trace", ("under", "under")
    return "normal", None


def exact_fraction(x) -> Fraction:
    """``x`` (int, Fraction, float, mpmath mpf) as the exact Fraction of its value."""
    if isinstance(x, Fraction):
        return x
    if isinstance(x, int | float):
        return Fraction(x)
    if isinstance(x, mpmath.mpf):
        man, exp = x.man_exp
        return Fraction(man) * Fraction(2) ** exp
    return Fraction(x)


def halves(m: Fraction, Q: Fraction | None, damping: str, system: System = PAPER) -> Halves:
    """Regime of each half (phase) for the exact depth ``m`` and quality factor ``Q``
    (:func:`analytic.system.phase_regimes`, the one definition of the rule)."""
    return Halves(*phase_regimes(system, m, Q, damping))


def _lift(x, B: Backend):
    """Exact rationals become numbers of the back end; back-end numbers pass through."""
    return B.num(x) if isinstance(x, Fraction | int) else x


def _root(x, B: Backend):
    return B.sqrt(_lift(x, B))


def omega_av(m, B: Backend, om=None):
    """``w0 = omega_av/omega0 = sqrt((1 + s)/2)/s`` with ``s = sqrt(1 - m^2)`` (undamped);
    ``om`` is ``1 - m`` (see :func:`normal_params`)."""
    s = _root(_one_minus(m, om) * (1 + m), B)
    return B.sqrt((1 + s) / 2) / s


def _one_minus(m, om):
    """``1 - m``: the caller's ``om`` when given (a double depth near 1 passes ``1 - m`` computed
    from the exact depth), else ``1 - m`` itself (exact for rationals, and for doubles ``m >=
    1/2``)."""
    return 1 - m if om is None else om


def _small(B: Backend) -> tuple:
    """``0, 1, 2, 3`` as numbers of the back end where that is cheaper: exact ``arb`` balls (an
    ``arb`` with an ``arb`` costs a fraction of an ``arb`` with a Python int, and gives the same
    ball: the int is converted exactly first); plain ints elsewhere."""
    return _ARB_SMALL if B.name == "arb" else (0, 1, 2, 3)


_ARB_SMALL = tuple(arb(k) for k in range(4))
_ARB_FOUR = arb(4)


def undamped_params(m, B: Backend, om=None) -> tuple:
    """``(r, r^2, u = 1 - r^2, beta, w, bm = 1 - beta)`` of the paper's system without friction,
    as numbers of back end ``B`` (``m`` and ``om`` as for :func:`normal_params`, which takes its
    frictionless values from here)."""
    _, one, two, three = _small(B)
    if om is None and type(m) is Fraction:
        # the exact rationals from the integers of m = p/q (in lowest terms, and so are
        # 1 - m = (q - p)/q and (1 - m)(1 + m) = (q - p)(q + p)/q^2): rounded once each
        p, q = m.numerator, m.denominator
        rat = B.namespace["_q"]
        s = B.sqrt(rat((q - p) * (q + p), q * q))
        mb, omb = rat(p, q), rat(q - p, q)
    else:
        om = _one_minus(m, om)
        s = _root(om * (1 + m), B)
        mb, omb = _lift(m, B), _lift(om, B)
    ps = one + s
    beta = mb / ps
    b2 = beta * beta
    q = one + three * b2
    r = beta * (three + b2) / q
    omb2 = two * s / ps
    u = omb2 * omb2 * omb2 / (q * q)
    w = B.sqrt(ps / two) / s
    bm = (omb + s) / ps  # 1 - m is exact or given: no cancellation
    return r, r * r, u, beta, w, bm


def _normal(*values) -> NormalParams:
    """``NormalParams(*values)`` without the frozen dataclass's ``__init__`` (one
    ``object.__setattr__`` per field: more than the arithmetic of the parameters at 15 digits)."""
    obj = object.__new__(NormalParams)
    obj.__dict__.update(zip(_NORMAL_FIELDS, values, strict=True))
    return obj


def normal_params(
    m, Q, damping: str, B: Backend, system: System = PAPER, *, om=None
) -> NormalParams:
    """The normal-form parameters of :func:`normal_values` as a :class:`NormalParams`."""
    return _normal(*normal_values(m, Q, damping, B, system, om=om))


def normal_values(m, Q, damping: str, B: Backend, system: System = PAPER, *, om=None) -> tuple:
    """The fields of :class:`NormalParams`, in their order (no object built): the normal-form
    parameters for depth ``m`` and quality factor ``Q`` (``None``: no friction) in the damping
    model ``damping`` (``"exact"`` or ``"paper"``), as numbers of back end ``B``.

    ``m`` and ``Q`` are exact :class:`~fractions.Fraction` s (the rational parts are then computed
    exactly and rounded once) or numbers of the back end.  For the exact model both halves must be
    under-damped (``4 Q^2 > 1 + m``).  Any other member of the family (``system``) takes the
    general route of :mod:`verify.system_params`, which the tests check against this one.

    ``om`` is ``1 - m``, for a depth that is not exactly a number of the back end: the formulas
    above need ``1 - m`` to the relative accuracy of the result (near ``m = 1`` it sets ``s``,
    ``1 - beta`` and ``1 - r^2``), and ``1 - float(m)`` can be wrong in every digit, while ``m``
    itself enters only through ``1 + m`` and ``m`` (rounding it changes the result by a relative
    2^-53).  Omitted, it is ``1 - m``.
    """
    if system is not PAPER and not system.is_paper:
        from .system_params import normal_tuple

        return normal_tuple(system, m, Q, damping, B, om)
    if (
        Q is not None
        and damping != "paper"
        and isinstance(m, Fraction)
        and isinstance(Q, Fraction)
        and (om is None or om == 1 - m)
    ):
        return _exact_rational(m, Q, B)
    r, r2, u, beta, w0, bm = undamped_params(m, B, om)
    zero = r * _small(B)[0]
    if Q is None:
        return r, r2, u, beta, w0, zero, w0, zero, bm
    if damping == "paper":
        return r, r2, u, beta, w0, 1 / (2 * _lift(Q, B) * w0), w0, zero, bm
    om = _one_minus(m, om)
    q2 = 4 * Q * Q
    u1, u2, om2 = (q2 - 1 - m) / (1 + m), (q2 - 1 + m) / om, om * (1 + m)
    a, b = (1 + m) * (1 + m), om * om
    Un, d4, b8 = 2 * m * ((q2 - 1) * (3 + m * m) - (1 + 3 * m * m)), 4 * m, 8 * m * Q * Q
    op = 1 + m
    nu1 = _root(u1, B)
    nu2 = _root(u2, B)
    om2 = _lift(om2, B)
    a, b = _lift(a, B), _lift(b, B)
    V = (a * nu1 + b * nu2) / om2
    U = _lift(Un, B) / (om2 * om2 * V)
    d = _lift(d4, B) / om2
    den = V * V + d * d
    r2 = (U * U + d * d) / den
    u = 4 * nu1 * nu2 / den
    nsum = nu1 + nu2
    Qb = _lift(Q, B)
    w = nsum / (4 * Qb)
    beta = _lift(b8, B) / (om2 * nsum * nsum)
    g = 2 / nsum
    # w0 - w = (omega1 - Omega1 + omega2 - Omega2)/(4 pi), omega - Omega = gamma^2/(omega + Omega)
    diff = (1 / (2 * Qb / _root(op, B) + nu1) + 1 / (2 * Qb / _root(om, B) + nu2)) / (4 * Qb)
    return B.sqrt(r2), r2, u, beta, w, g, w0, diff / (w * w0), 2 * nu1 / nsum


def indicator_params(m, Q, damping: str, B: Backend, system: System = PAPER) -> tuple:
    """``(r2, u, beta, g, w)`` of :func:`normal_params` (the parameters of the indicator ``D``
    and ``omega_av/omega0``), the same numbers; for exact ``m``, ``Q`` in ``arb`` in the exact
    model of the paper's system without the other fields (:func:`exact_arb_values`)."""
    if (
        B.name == "arb"
        and damping != "paper"
        and type(m) is Fraction
        and type(Q) is Fraction
        and (system is PAPER or system.is_paper)
    ):
        return exact_arb_values(m, Q, False)
    _, r2, u, beta, w, g, _, _, _ = normal_values(m, Q, damping, B, system)
    return r2, u, beta, g, w


def _exact_rational(m: Fraction, Q: Fraction, B: Backend) -> tuple:
    """The exact model's parameters for exact ``m``, ``Q``: the formulas of the general branch of
    :func:`normal_params`, with their rational parts combined exactly first (once per ``(m, Q)``,
    :func:`_exact_parts`), so that fewer numbers are converted and rounded::

        V = k nu1 + nu2 / k,  k = (1+m)/(1-m);   U = (Un/(1-m^2)^2) / V;   d = 4m/(1-m^2)
        beta = (8 m Q^2/(1-m^2)) / (nu1 + nu2)^2;   2Q/sqrt(1 +- m) = sqrt(nu_i^2 + 1)
    """
    if B.name == "arb":
        return exact_arb_values(m, Q)
    u1, u2, k, Uq, dq, bq, q4, s2 = _exact_parts(m, Q)
    lift = B.num
    U1, U2, K = lift(u1), lift(u2), lift(k)
    nu1, nu2 = B.sqrt(U1), B.sqrt(U2)
    V = K * nu1 + nu2 / K
    U = lift(Uq) / V
    d = lift(dq)
    dd = d * d
    den = V * V + dd
    r2 = (U * U + dd) / den
    nsum = nu1 + nu2
    iq = lift(q4)
    w = nsum * iq
    s = B.sqrt(lift(s2))
    w0 = B.sqrt((1 + s) / 2) / s  # omega_av/omega0 without friction (see omega_av)
    # w0 - w = (omega1 - Omega1 + omega2 - Omega2)/(4 pi), omega - Omega = gamma^2/(omega + Omega)
    diff = (1 / (B.sqrt(U1 + 1) + nu1) + 1 / (B.sqrt(U2 + 1) + nu2)) * iq
    return (
        B.sqrt(r2),
        r2,
        4 * nu1 * nu2 / den,
        lift(bq) / (nsum * nsum),
        w,
        2 / nsum,
        w0,
        diff / (w * w0),
        2 * nu1 / nsum,
    )


def exact_arb_values(m: Fraction, Q: Fraction, full: bool = True) -> tuple:
    """The fields of :class:`NormalParams` (in their order) of the exact model at exact ``m``,
    ``Q``, as ``arb`` balls at the working precision: the operations of :func:`_exact_rational` on
    the same roundings, without the back end's indirections: the rational parts cached by the
    integers of ``m`` and ``Q`` (a Fraction's hash costs more than the lookup), each lifted by one
    rounded division (:func:`_exact_lifts`), the small integers as exact balls (an ``arb`` with a
    Python int converts the int first: the same ball, at a cost), and the square roots as ``arb``
    methods.  ``full=False``: ``(r2, u, beta, g, w)`` alone."""
    small, lifts = _exact_lifts(m.numerator, m.denominator, Q.numerator, Q.denominator)
    U1, U2, K, Uq, d, bq, iq, s2 = (
        map(arb, lifts)
        if small
        else (
            arb(x) if type(x) is fmpq else arb(x[0]) / x[1] if x[1] != 1 else arb(x[0])
            for x in lifts
        )
    )
    _, one, two, _ = _ARB_SMALL
    nu1, nu2 = U1.sqrt(), U2.sqrt()
    V = K * nu1 + nu2 / K
    U = Uq / V
    dd = d * d
    den = V * V + dd
    r2 = (U * U + dd) / den
    nsum = nu1 + nu2
    w = nsum * iq
    if not full:
        return r2, _ARB_FOUR * nu1 * nu2 / den, bq / (nsum * nsum), two / nsum, w
    s = s2.sqrt()
    w0 = ((one + s) / two).sqrt() / s  # omega_av/omega0 without friction (see omega_av)
    diff = (one / ((U1 + one).sqrt() + nu1) + one / ((U2 + one).sqrt() + nu2)) * iq
    return (
        r2.sqrt(),
        r2,
        _ARB_FOUR * nu1 * nu2 / den,
        bq / (nsum * nsum),
        w,
        two / nsum,
        w0,
        diff / (w * w0),
        two * nu1 / nsum,
    )


@lru_cache(maxsize=64)
def _exact_lifts(mp: int, mq: int, qp: int, qq: int) -> tuple[bool, tuple]:
    """:func:`_exact_parts` as what :func:`exact_arb_values` lifts, cached by the integers: an
    ``fmpq`` where numerator and denominator have at most 53 bits (``arb`` of it is the quotient
    rounded once, the ball of ``arb(p) / q``: both integers convert exactly), else the pair
    ``(p, q)`` (a longer integer is rounded to the working precision by ``arb(p)``, and the
    quotient follows it); and whether every one is an ``fmpq``."""
    out = []
    for x in _exact_parts(Fraction(mp, mq), Fraction(qp, qq)):
        p, q = x.numerator, x.denominator
        small = abs(p).bit_length() <= 53 and q.bit_length() <= 53
        out.append(fmpq(p, q) if small else (p, q))
    return all(type(x) is fmpq for x in out), tuple(out)


@lru_cache(maxsize=64)
def _exact_parts(m: Fraction, Q: Fraction) -> tuple:
    """The rational parts of the exact model's normal-form parameters (see the module text and
    :func:`_exact_rational`): ``u1 = nu1^2``, ``u2 = nu2^2``, ``(1+m)/(1-m)``, ``Un/(1-m^2)^2``,
    ``4m/(1-m^2)``, ``8 m Q^2/(1-m^2)``, ``1/(4Q)`` and ``1 - m^2``."""
    q2 = 4 * Q * Q
    om, op = 1 - m, 1 + m
    om2 = om * op
    Un = 2 * m * ((q2 - 1) * (3 + m * m) - (1 + 3 * m * m))
    return (
        (q2 - 1 - m) / op,
        (q2 - 1 + m) / om,
        op / om,
        Un / (om2 * om2),
        4 * m / om2,
        8 * m * Q * Q / om2,
        1 / (4 * Q),
        om2,
    )


def trace_params(m, Q, B: Backend, system: System = PAPER) -> TraceParams:
    """``kappa``, ``nu1``, ``nu2`` of the exact model's trace form (any regime), for every member
    of the family: ``kappa = N/gamma^2`` and ``u_i = Omega_i^2/gamma^2`` as derived by sympy
    (:func:`analytic.family.trace_forms`, compiled: :func:`verify.system_params.trace_atoms`),
    ``nu_i = sqrt|u_i|``, and for a duty ``D`` other than 1/2 the phases' lengths folded in
    (``nu1 -> 2 D nu1``, ``nu2 -> 2 (1 - D) nu2``, ``kappa -> 4 D (1 - D) kappa``, so that the form
    of :func:`verify.derived.trace_indicator`, written for two half periods, holds).

    ``m``, ``Q``: exact (the signs of ``u_i`` are then exact, and a critically damped half gets
    ``nu_i = 0`` exactly: its forms do not use it), numbers of ``B``, or jets over balls with
    ``arb`` (:class:`verify.certify.Jet`).  ``w0``: the undamped ``omega_av/omega0``.
    """
    if system is not PAPER:
        system = canonical(system)
    kappa, u1, u2 = trace_atoms(system, m, Q, B)
    nu1, nu2 = _nu(u1, B), _nu(u2, B)
    D = system.duty
    if system is not PAPER and D != _HALF:
        if isinstance(kappa, Fraction):
            kappa *= 4 * D * (1 - D)
        else:
            kappa = kappa * _lift(4 * D * (1 - D), B)
        nu1, nu2 = nu1 * _lift(2 * D, B), nu2 * _lift(2 * (1 - D), B)
    w0 = omega_av(m, B) if system.is_paper else _evaluate(system, m, None, "none", B)["w0"]
    return TraceParams(_lift(kappa, B), nu1, nu2, _lift(Q, B), w0)


_HALF = Fraction(1, 2)


def _nu(u, B: Backend):
    """``nu = sqrt|u|``, and exactly 0 where ``u`` is.  A ball that holds 0 (a range of depths
    ending at a critical damping) gives ``nu`` from 0 up to the root of its largest magnitude,
    every value it holds (a ball's ``!= 0`` is true only where it excludes 0, and ``abs`` of it
    still reaches below 0)."""
    if isinstance(u, arb):
        if u.is_zero():
            return _lift(Fraction(0), B)
        if u.contains(0):
            return abs(u).nonnegative_part().sqrt()
    elif u == 0:
        return _lift(Fraction(0), B)
    return _root(abs(u), B)
