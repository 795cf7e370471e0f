"""A finite switching time: the pendulum whose length changes linearly during each switch.

The ``ramp`` modulation replaces each jump of the length by a linear ramp of duration ``S``
(units ``T0``) centred on the nominal switch instant (``t = 0`` and ``t = D T``).  While the
length varies, the bob on a light rod obeys (no friction)

    (l^2 phi')' + g l phi = 0,                                               (R1)

with ``l^2 phi'`` the angular momentum per unit mass, ``p``.  In the state ``(phi, p)`` the
system is ``phi' = p/l^2``, ``p' = -g l phi``: the matrix ``A(l) = [[0, 1/l^2], [-g l, 0]]`` has
trace zero, so every period map has determinant 1, and across an instantaneous jump ``(phi, p)``
is continuous (the paper's momentum rule).

**The exact solution on a ramp** (derived here by sympy, :func:`ramp_solution`).  With
``l = l_a + c (t - t_a)`` and ``d/dt = c d/dl``, (R1) becomes ``c^2 (l^2 F')' + g l F = 0`` for
``phi(t) = F(l)``, which sympy's ``dsolve`` solves:

    F(l) = (C1 J1(x) + C2 Y1(x)) / sqrt(l),        x = 2 sqrt(g l) / |c|,

Bessel functions of order 1.  In the variable ``x`` (``l = x^2 c^2/(4 g)``) a fundamental system
of (R1) in the state ``(phi, p)`` is (:func:`fundamental_matrix`)

    phi_Z = Z1(x)/x,     p_Z = c l^2 dphi_Z/dl = -c^3 x^2 Z2(x) / (8 g),      Z = J, Y

(the derivative ``(Z1(x)/x)' = -Z2(x)/x`` is proven by sympy's recurrences).  Its determinant is
the constant ``c^3/(4 pi g)``: ``d/dx`` of it vanishes and its limit at ``x -> 0`` is taken by
sympy (:func:`fundamental_determinant`).  Hence the map of ``(phi, p)`` across a ramp from length
``l_a`` to ``l_b`` in time ``S`` (``c = (l_b - l_a)/S``) is, in closed form,

    R = Phi(x_b) adj(Phi(x_a)) * 4 pi g / c^3,     x_{a,b} = 2 sqrt(g l_{a,b}) S / |l_b - l_a|

(:func:`ramp_map`); e.g. ``R11 = (pi x_a^2 / (2 x_b)) (Y1(x_b) J2(x_a) - J1(x_b) Y2(x_a))``.  On a
constant length the map is ``exp(A(l) t)`` (:func:`plateau_map`), the free oscillation with
``omega^2 = g/l``.  As ``S -> 0`` the ramp map tends to the identity: the jump model is the limit
``S = 0``.

**Which symmetry survives.**  Reversing time, ``t -> -t``, maps (R1) with ``l(t)`` to (R1) with
``l(-t)`` and ``(phi, p)`` to ``(phi, -p)``.  The fundamental matrix with the slope ``-c`` is
``diag(1, -1)`` times the one with ``c`` (:func:`check_reversal`), so the ramp down is the
time-reverse of the ramp up: ``R_down = P R_up^{-1} P``, ``P = diag(1, -1)``.  With both ramps of
the same duration ``S`` centred on the switch instants, **each phase (from one switch instant to
the next) is still symmetric about its midpoint**, exactly as in the jump model.  Let ``G`` be
the map from the midpoint of phase 1 to the midpoint of phase 2 (half of plateau 1, the ramp
down, half of plateau 2); the other half period is its time reverse, so

    M = P G^{-1} P G,    tr M - 2 = 4 G12 G21,    tr M + 2 = 4 G11 G22       (det G = 1)

(:func:`half_period_factorisation`, proven for a generic ``G``).  **The per-edge factorisation
therefore survives the ramps**: each edge of an interval of odd order is a zero of ``G11`` or
``G22`` (a Floquet solution even or odd about the phase midpoints), of even order a zero of
``G12`` or ``G21``, one equation per edge, as in the jump model.

**The leading effect of a short ramp** (:func:`first_order_defect`).  Over ``[-S/2, S/2]`` the
ramp's map and the jump model's ``exp(A(l_b) S/2) exp(A(l_a) S/2)`` have the Magnus expansions
``exp(Omega1 + O(S^2))`` with ``Omega1 = integral A dt``; the two ``Omega1`` differ by
``S E`` with ``E = [[0, 1/(l_a l_b) - (1/l_a^2 + 1/l_b^2)/2], [0, 0]]`` (the mean of ``g l`` is
the same for both, the mean of ``1/l^2`` is not).  Hence ``G(S) = G0 + S U2 E U1 + O(S^2)``
(``U_i`` the jump model's half-phase maps) and each edge moves **linearly** in ``S``:

    T(S) = T(0) - S [U2 E U1]_e / (dG0_e/dT) + O(S^2),

``e`` the entry of ``G`` that vanishes on that edge.  ``E`` is proportional to ``(l_a - l_b)^2``,
i.e. to ``m^2`` for the pendulum (``l = 1 +- m``).
"""

from __future__ import annotations

from functools import cache

import sympy as sp

from .cache import disk_cached

__all__ = [
    "symbols",
    "system_matrix",
    "ramp_solution",
    "fundamental_matrix",
    "fundamental_determinant",
    "ramp_map",
    "plateau_map",
    "check_ramp_solution",
    "check_reversal",
    "half_period_factorisation",
    "crossing_is_a_closing",
    "first_order_defect",
    "defect_series",
    "next_power",
    "ramp_forms",
]

#: ``l, g`` (positive), ``c`` (the slope dl/dt), ``x`` (the Bessel argument), ``t`` (time),
#: ``la, lb`` (the lengths at the start and end of a ramp), ``S`` (its duration)
_l, _g, _x, _t, _S = sp.symbols("l g x t S", positive=True)
_c = sp.Symbol("c", real=True, nonzero=True)
_la, _lb = sp.symbols("l_a l_b", positive=True)


def symbols() -> dict:
    """The sympy symbols of this module by name."""
    return {"l": _l, "g": _g, "x": _x, "t": _t, "S": _S, "c": _c, "la": _la, "lb": _lb}


def system_matrix(l=_l, g=_g) -> sp.Matrix:
    """``A(l)`` of ``(phi, p)' = A (phi, p)`` for (R1): ``phi' = p/l^2``, ``p' = -g l phi``."""
    return sp.Matrix([[0, 1 / l**2], [-g * l, 0]])


@cache
def ramp_solution() -> sp.Expr:
    """The general solution ``F(l)`` of (R1) on a linear ramp, as sympy's ``dsolve`` returns it
    for ``c^2 (l^2 F')' + g l F = 0`` (constants ``C1``, ``C2``)."""
    F = sp.Function("F")
    eq = _c**2 * sp.diff(_l**2 * F(_l).diff(_l), _l) + _g * _l * F(_l)
    sol = sp.dsolve(eq, F(_l))
    return sol.rhs


@cache
def fundamental_matrix() -> sp.Matrix:
    """``Phi(x) = [[J1/x, Y1/x], [p_J, p_Y]]`` in ``x`` (and ``c``, ``g``): columns the states
    ``(phi, p)`` of two independent solutions of (R1) on a ramp of slope ``c``.

    ``p = c l^2 dphi/dl`` is formed by the chain rule from ``phi(l) = Z1(x(l))/x(l)`` and
    rewritten with sympy's recurrences to a single Bessel function of order 2 (the rewrite is
    proven: the difference simplifies to zero)."""
    cols = []
    for Z in (sp.besselj, sp.bessely):
        xl = 2 * sp.sqrt(_g * _l) / sp.Abs(_c)
        phi_l = Z(1, xl) / xl
        p_l = _c * _l**2 * sp.diff(phi_l, _l)
        p_x = p_l.subs(_l, _x**2 * _c**2 / (4 * _g))
        p_x = sp.simplify(p_x.subs(sp.Abs(_c), sp.sqrt(_c**2)))
        closed = -(_c**3) * _x**2 * Z(2, _x) / (8 * _g)
        if sp.simplify(sp.expand_func(p_x - closed)) != 0:  # pragma: no cover - a proof
            raise AssertionError("the momentum of the Bessel solution did not reduce")
        cols.append((Z(1, _x) / _x, closed))
    return sp.Matrix([[cols[0][0], cols[1][0]], [cols[0][1], cols[1][1]]])


@cache
def fundamental_determinant() -> sp.Expr:
    """``det Phi = c^3/(4 pi g)``: constant (its ``x``-derivative is proven zero) and equal to its
    limit at ``x -> 0`` (taken by sympy)."""
    Phi = fundamental_matrix()
    det = sp.expand(Phi.det())
    if sp.simplify(sp.expand_func(sp.diff(det, _x))) != 0:  # pragma: no cover - a proof
        raise AssertionError("the Wronskian is not constant")
    core = sp.expand_func(sp.simplify(det * 8 * _g / _c**3))
    value = sp.limit(core, _x, 0) * _c**3 / (8 * _g)
    return sp.simplify(value)


@cache
def ramp_map() -> sp.Matrix:
    """The map of ``(phi, p)`` across a ramp from length ``l_a`` to ``l_b`` lasting ``S``, in the
    symbols ``la, lb, S, g`` (closed form in ``J1, J2, Y1, Y2``)."""
    Phi = fundamental_matrix()
    c = (_lb - _la) / _S
    xa = 2 * sp.sqrt(_g * _la) * _S / sp.Abs(_lb - _la)
    xb = 2 * sp.sqrt(_g * _lb) * _S / sp.Abs(_lb - _la)
    det = fundamental_determinant()
    A = Phi.subs(_x, xa)
    B = Phi.subs(_x, xb)
    R = B * A.adjugate() / det
    return R.subs(_c, c)


@cache
def plateau_map() -> sp.Matrix:
    """``exp(A(l) t)``: the map of ``(phi, p)`` over a time ``t`` at constant length ``l``."""
    M = (system_matrix() * _t).exp()
    return M.applyfunc(lambda e: sp.simplify(e.rewrite(sp.cos)))


def check_ramp_solution() -> bool:
    """Both columns of :func:`fundamental_matrix` solve (R1) as a first-order system in ``x``:
    with ``dx/dt = c x/(2 l)`` (``l = x^2 c^2/(4 g)``), ``d phi/dt = p/l^2`` and ``d p/dt = -g l
    phi`` hold identically (sympy, after the Bessel recurrences)."""
    Phi = fundamental_matrix()
    lx = _x**2 * _c**2 / (4 * _g)
    dxdt = _c * _x / (2 * lx)
    for j in range(2):
        phi, p = Phi[0, j], Phi[1, j]
        r1 = sp.diff(phi, _x) * dxdt - p / lx**2
        r2 = sp.diff(p, _x) * dxdt + _g * lx * phi
        for r in (r1, r2):
            if sp.simplify(sp.expand_func(r)) != 0:
                return False
    return True


def check_reversal() -> bool:
    """The fundamental matrix with slope ``-c`` is ``diag(1, -1)`` times the one with ``c``: the
    ramp down is the time reverse of the ramp up (``p -> -p``)."""
    Phi = fundamental_matrix()
    P = sp.diag(1, -1)
    return sp.simplify(Phi.subs(_c, -_c) - P * Phi) == sp.zeros(2, 2)


def half_period_factorisation() -> tuple[sp.Expr, sp.Expr]:
    """For ``G`` with ``det G = 1`` and ``M = P G^{-1} P G`` (``P = diag(1, -1)``): returns
    ``(tr M - 2 - 4 G12 G21, tr M + 2 - 4 G11 G22)``, both simplified (zero when proven)."""
    a, b, c, d = sp.symbols("G11 G12 G21 G22")
    G = sp.Matrix([[a, b], [c, d]])
    P = sp.diag(1, -1)
    Ginv = sp.Matrix([[d, -b], [-c, a]])  # the inverse when det G = 1
    M = P * Ginv * P * G
    tr = sp.expand(M.trace())
    on_det = {a * d: 1 + b * c}
    e1 = sp.expand(sp.expand(tr - 2 - 4 * b * c).subs(a * d, 1 + b * c))
    e2 = sp.expand(sp.expand(tr + 2 - 4 * a * d).subs(on_det))
    return sp.simplify(e1), sp.simplify(e2)


def crossing_is_a_closing() -> sp.Matrix:
    """``M + I`` for ``M = P G^-1 P G`` with ``G11 = G22 = 0`` and ``det G = 1`` (so ``G21 =
    -1/G12``), simplified: the zero matrix, i.e. where the zeros of ``G11`` and ``G22`` meet the
    period map is ``-I`` and the interval of odd order has zero width (likewise ``G12 = G21 =
    0`` gives ``M = I`` for even orders)."""
    b = sp.Symbol("G12", nonzero=True)
    G = sp.Matrix([[0, b], [-1 / b, 0]])
    P = sp.diag(1, -1)
    M = P * G.inv() * P * G
    return sp.simplify(M + sp.eye(2))


@cache
def first_order_defect() -> sp.Matrix:
    """``E``: the first Magnus term of the ramp's map over ``[-S/2, S/2]`` minus that of the jump
    model's two half-steps, divided by ``S`` (integrals taken by sympy), in ``la, lb, g``."""
    s = sp.Symbol("s", real=True)
    lt = _la + (_lb - _la) * (s + _S / 2) / _S
    A = system_matrix(lt, _g)
    # rational integrands: sympy's rational integration, without the Risch algorithm's setup
    ramp = A.applyfunc(lambda e: sp.integrate(e, (s, -_S / 2, _S / 2), risch=False))
    jump = (system_matrix(_la, _g) + system_matrix(_lb, _g)) * _S / 2
    return (ramp - jump).applyfunc(lambda e: sp.factor(e / _S))


@cache
def defect_series(order: int = 2) -> dict:
    """The power series in ``S`` of ``R(S) - J(S)``, the ramp's map over ``[-S/2, S/2]`` minus
    the jump model's two half-steps ``exp(A(l_b) S/2) exp(A(l_a) S/2)``, to ``S^order``:
    ``{power: matrix}`` for the powers whose coefficient is not zero (sympy).  In ``sigma =
    s/S`` the ramp's ``A`` does not depend on ``S``, so ``R(S) = sum_k S^k I_k`` with ``I_k``
    the ``k``-fold ordered integral of ``A`` over ``sigma`` in ``[-1/2, 1/2]`` (Peano-Baker),
    a series in integer powers of ``S``; the coefficients are taken at ``l_a = 1 + m``,
    ``l_b = 1 - m`` (the pendulum's ramp down) with ``g`` symbolic."""
    m = sp.Symbol("m", positive=True)
    sig, tau = sp.symbols("sigma tau", real=True)
    la, lb = 1 + m, 1 - m

    def A(x):
        return system_matrix(la + (lb - la) * (x + sp.Rational(1, 2)), _g)

    half = sp.Rational(1, 2)
    out = {}
    inner = sp.eye(2)  # the (k-1)-fold integral as a function of its upper end tau
    Aa, Ab = system_matrix(la, _g), system_matrix(lb, _g)
    for k in range(1, order + 1):
        integrand = (A(sig) * inner.subs(tau, sig)).applyfunc(sp.expand)
        inner = integrand.applyfunc(lambda e: sp.integrate(e, (sig, -half, tau)))
        Ik = inner.subs(tau, half).applyfunc(sp.simplify)
        # J's S^k coefficient: sum over i + j = k of (Ab/2)^i/i! (Aa/2)^j/j!
        Jk = sp.zeros(2, 2)
        for i in range(k + 1):
            j = k - i
            Jk += (Ab / 2) ** i / sp.factorial(i) * (Aa / 2) ** j / sp.factorial(j)
        Dk = (Ik - Jk).applyfunc(sp.simplify)
        if Dk != sp.zeros(2, 2):
            out[k] = Dk
    return out


def next_power() -> int:
    """The power of ``S`` of the first term that the leading-order shift leaves out: the edge
    ``T(S)`` is analytic in ``S`` (a simple zero of an entry of ``G``, a power series in ``S``
    by :func:`defect_series`), its first-order term comes from the lowest power ``p`` of the
    defect, and the next term is of power ``min(p2, 2 p)``, ``p2`` the defect's next power
    (its own term, or the square of the first)."""
    powers = sorted(defect_series(2))
    p = powers[0]
    p2 = powers[1] if len(powers) > 1 else 2 * p
    return min(p2, 2 * p)


@disk_cached("ramp_forms")
def ramp_forms() -> tuple:
    """Everything the numeric route compiles, as one tuple (cached on disk):
    ``(ramp map entries R11, R12, R21, R22 in la, lb, S, g, pi; plateau map entries in t, l, g;
    A(l) entries in l, g; E entries in la, lb, g)``, with ``pi`` replaced by the symbol ``PI``
    (so that every back end supplies its own ``pi`` at its own precision)."""
    PI = sp.Symbol("PI", positive=True)
    R = ramp_map().subs(sp.pi, PI)
    U = plateau_map()
    A = system_matrix()
    E = first_order_defect()
    return tuple(R) + tuple(U) + tuple(A) + tuple(E)
