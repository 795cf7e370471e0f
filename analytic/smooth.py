"""A length that varies in time: the governing equation, its Liouville (Hill) form, and the
``sine`` modulation.

Units: time in ``T0``, length in ``l0``, so ``g = omega0^2 l0 = 4 pi^2`` and the friction
``gamma = pi/Q`` (``gamma T0 = pi/Q``).  The bob on a light rod obeys

    (l^2 phi')' + 2 gamma l^2 phi' + g l phi = 0                               (V1)

(the moment of inertia and the drag torque scale as ``l^2``, gravity's torque as ``l``).  In the
state ``(phi, p = l^2 phi')`` it is the first-order system ``y' = A(t) y`` with

    A = [[0, 1/l^2], [-g l, -2 gamma]]                                         (V2)

(:func:`system_matrix`), whose trace is the constant ``-2 gamma``: every period map has the
determinant ``exp(-2 gamma T)``.  Through a jump of ``l`` the state is continuous, which is the
paper's momentum rule.  (V2) serves every modulation; the certified integrator of
:mod:`verify.taylor` integrates it piece by piece.

**The Liouville form** (:func:`hill_form`).  With ``u = l phi`` (the bob's arc coordinate),
(V1) becomes

    u'' + 2 gamma u' + q(t) u = 0,      q = (g - l'' - 2 gamma l')/l,              (V3)

a Hill equation (with friction: a damped one) whose coefficient is periodic with ``l``.  The
substitution and its residual are checked by sympy.  In the state ``(u, u')`` it is ``w' = B w``
with ``B = [[0, 1], [-q, -2 gamma]]``, and ``(u, u') = C (phi, p)`` with ``C = [[l, 0], [l',
1/l]]`` (:func:`liouville_state`); for a smooth ``l`` the map of ``(phi, p)`` from ``a`` to ``b``
is ``C(b)^-1 W C(a)``, ``W`` the map of (V3).  One Taylor step of (V3) costs half one of (V2): a
single entry of ``B`` varies.

**The ``sine`` modulation** (:func:`sine_length`): ``l(t) = 1 + m sin(2 pi t/T)``, long in the
first half period as the square wave (only equal halves, ``D = 1/2``).  ``l`` is even about
``t = T/4`` and ``t = 3T/4`` (:func:`check_sine_symmetry`), so without friction the half-period
argument of :mod:`analytic.ramp` applies unchanged: with ``G`` the map from ``t = T/4`` to
``3T/4``, ``tr M - 2 = 4 G12 G21`` and ``tr M + 2 = 4 G11 G22``
(:func:`analytic.ramp.half_period_factorisation`): each edge is a zero of one entry of ``G``.

**Small depth** (:func:`sine_first_width`).  To first order in ``m``, (V3) without friction is
the Mathieu equation ``u'' + (g + m (Omega^2 - g) sin(Omega t)) u = 0`` (``Omega = 2 pi/T``).
Harmonic balance with ``u = a cos(Omega t/2) + b sin(Omega t/2)`` (the projections are taken by
sympy) gives the edges of the first interval ``T = 1/2 + c m + O(m^2)`` with ``c = -+3/8``: the
interval is ``3m/4`` wide, against ``3m/pi`` for the square wave (whose first harmonic is
``4/pi`` times larger).
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cache

import sympy as sp

__all__ = [
    "symbols",
    "system_matrix",
    "hill_form",
    "check_hill_form",
    "sine_length",
    "check_sine_symmetry",
    "sine_first_width",
    "sine_forms",
    "liouville_state",
    "sine_hill_forms",
    "ince_form",
    "fourier_recurrence",
    "sine_closings",
]

_t, _T, _g, _m = sp.symbols("t T g m", positive=True)
_gamma = sp.Symbol("gamma", nonnegative=True)
_PI = sp.Symbol("PI", positive=True)
#: the phase ``Omega t``, ``c = g/Omega^2`` and the Fourier index of the Ince form
_theta = sp.Symbol("theta", real=True)
_c = sp.Symbol("c", positive=True)
_k = sp.Symbol("k")


def symbols() -> dict:
    """The sympy symbols of this module by name (``PI`` stands for ``pi`` in compiled forms)."""
    return {
        "t": _t,
        "T": _T,
        "g": _g,
        "m": _m,
        "gamma": _gamma,
        "PI": _PI,
        "theta": _theta,
        "c": _c,
        "k": _k,
    }


def system_matrix(l, g=_g, gamma=_gamma) -> sp.Matrix:
    """``A`` of (V2) for a length ``l`` (any expression, e.g. in ``t``)."""
    return sp.Matrix([[0, 1 / l**2], [-g * l, -2 * gamma]])


@cache  # the sine's is asked for by the integrator's forms, the Ince form and the report
def hill_form(l) -> sp.Expr:
    """``q(t)`` of (V3) for the length ``l(t)``, derived: ``u = l phi`` substituted in (V1) and
    the result divided by ``l`` (see :func:`check_hill_form`), over one denominator with the
    common factors cancelled (``factor``: the same form as ``simplify`` gives for the lengths
    used here, in a tenth of the time)."""
    return sp.factor(_hill_coefficient(l))


def _hill_coefficient(l) -> sp.Expr:
    """``q(t)`` of (V3) as derived, before simplification."""
    u = sp.Function("u")(_t)
    phi = u / l
    lhs = sp.diff(l**2 * sp.diff(phi, _t), _t) + 2 * _gamma * l**2 * sp.diff(phi, _t)
    lhs = (lhs + _g * l * phi) / l
    # lhs = u'' + 2 gamma u' + q u, linear in u, u', u'': with these three as symbols, q is the
    # derivative in the symbol for u (no expansion needed); the other two coefficients are
    # checked to be 1 and 2 gamma
    u0, u1, u2 = sp.symbols("u0 u1 u2")
    lin = lhs.subs(sp.Derivative(u, (_t, 2)), u2).subs(sp.Derivative(u, _t), u1).subs(u, u0)
    if sp.cancel(sp.diff(lin, u2)) != 1 or sp.cancel(sp.diff(lin, u1)) != 2 * _gamma:
        raise AssertionError("(V1)/l is not u'' + 2 gamma u' + q u")  # pragma: no cover
    return sp.diff(lin, u0)


def _period_integral(expr, x) -> sp.Expr:
    """The integral of ``expr`` over ``0 <= x <= 2 pi`` for a trigonometric polynomial in ``x``:
    written with exponentials, every term but the constant one is ``c exp(i k x)`` with a nonzero
    integer ``k`` and integrates to zero, so the integral is ``2 pi`` times the constant term."""
    const = sp.S.Zero
    for term in sp.Add.make_args(sp.expand(expr.rewrite(sp.exp))):
        _, rest = term.as_independent(x, as_Add=False)
        if rest == 1:
            const += term
            continue
        k = rest.args[0] / (sp.I * x) if rest.func is sp.exp else None
        if k is None or not (k.is_integer and k.is_nonzero):  # pragma: no cover - a proof
            raise AssertionError(f"{term} is not a term of a trigonometric polynomial in {x}")
    return 2 * sp.pi * const


def check_hill_form(l) -> bool:
    """(V1) with ``phi = u/l`` equals ``l`` times (V3) identically (sympy)."""
    u = sp.Function("u")(_t)
    phi = u / l
    v1 = sp.diff(l**2 * sp.diff(phi, _t), _t) + 2 * _gamma * l**2 * sp.diff(phi, _t)
    v1 += _g * l * phi
    q = (_g - sp.diff(l, _t, 2) - 2 * _gamma * sp.diff(l, _t)) / l
    v3 = sp.diff(u, _t, 2) + 2 * _gamma * sp.diff(u, _t) + q * u
    return sp.simplify(v1 - l * v3) == 0 and sp.simplify(hill_form(l) - q) == 0


def sine_length(pi=sp.pi) -> sp.Expr:
    """``l(t) = 1 + m sin(2 pi t/T)`` (units ``l0``)."""
    return 1 + _m * sp.sin(2 * pi * _t / _T)


def check_sine_symmetry() -> bool:
    """``l(T/4 + s) = l(T/4 - s)`` and ``l(3T/4 + s) = l(3T/4 - s)`` (sympy): each half period
    is symmetric about its midpoint, the premise of the per-edge factorisation."""
    s = sp.Symbol("s", real=True)
    l = sine_length()
    ok = True
    for c in (_T / 4, 3 * _T / 4):
        d = sp.expand_trig(sp.expand(l.subs(_t, c + s) - l.subs(_t, c - s)))
        ok = ok and sp.simplify(d) == 0
    return ok


@cache
def sine_first_width() -> tuple[sp.Expr, sp.Expr]:
    """``(c_lower, c_upper)``: the first interval's edges ``T = 1/2 + c m + O(m^2)`` (units
    ``T0``) of the sine modulation without friction, by harmonic balance on the first-order
    Hill form (see the module's docstring)."""
    W = sp.Symbol("W", positive=True)  # Omega = 2 pi/T
    l = 1 + _m * sp.sin(W * _t)
    q = _hill_coefficient(l).subs(_gamma, 0)
    # Taylor to first order in m (the coefficients as derivatives at m = 0)
    q1 = sp.factor(q.subs(_m, 0)) + _m * sp.factor(sp.diff(q, _m).subs(_m, 0))
    a, b = sp.symbols("a b")
    u = a * sp.cos(W * _t / 2) + b * sp.sin(W * _t / 2)
    res = sp.diff(u, _t, 2) + q1 * u
    # the projections over the period 4 pi/W of u: with x = W t/2 the period is 2 pi in x and
    # dt = 2 dx/W
    x = sp.Symbol("x", real=True)
    eqs = []
    for basis in (sp.cos(W * _t / 2), sp.sin(W * _t / 2)):
        proj = _period_integral((res * basis).subs(_t, 2 * x / W), x) * 2 / W
        eqs.append(sp.expand(proj))
    mat = sp.Matrix([[e.coeff(a) for e in eqs], [e.coeff(b) for e in eqs]]).T
    det = sp.factor(mat.det())
    g0 = 4 * sp.pi**2
    c = sp.Symbol("c")
    # T = 1/2 + c m: Omega = 2 pi/T; the determinant vanishes to second order in m
    d = det.subs(_g, g0).subs(W, 2 * sp.pi / (sp.Rational(1, 2) + c * _m))
    lead = sp.factor(sp.diff(d, _m, 2).subs(_m, 0) / 2)  # the coefficient of m**2
    roots = sorted(sp.solve(sp.Eq(lead, 0), c), key=lambda r: float(r))
    if len(roots) != 2:  # pragma: no cover - a proof
        raise AssertionError(f"harmonic balance gave {roots}")
    return roots[0], roots[1]


def liouville_state(l) -> sp.Matrix:
    """``C``: ``(u, u') = C (phi, p)`` for ``u = l phi``, ``p = l^2 phi'`` (derived: ``u'`` is
    differentiated by sympy and read off in ``phi``, ``p``)."""
    phi, p = sp.symbols("phi p")
    ph = sp.Function("phi")(_t)
    du = sp.diff(l * ph, _t).subs(sp.Derivative(ph, _t), p / l**2).subs(ph, phi)
    du = sp.expand(du)
    return sp.Matrix([[l, 0], [du.coeff(phi), du.coeff(p)]])


@cache
def sine_hill_forms() -> tuple:
    """``(B, C)`` for the sine modulation: the entries of ``B`` of (V3) and of ``C`` of
    :func:`liouville_state`, row-major, in ``t, T, m, g, gamma, PI``."""
    l = sine_length(_PI)
    q = hill_form(l)
    B = sp.Matrix([[0, 1], [-q, -2 * _gamma]])
    return tuple(B), tuple(liouville_state(l))


@cache
def sine_forms() -> tuple:
    """The entries of ``A`` (V2) for the sine modulation, row-major, in ``t, T, m, g, gamma,
    PI`` (``pi`` replaced by the symbol ``PI``, so every back end supplies its own)."""
    A = system_matrix(sine_length(_PI))
    return tuple(A)


# ---------------------------------------------------------------------------------------------
# the closings of the sine modulation (coexistence)


@cache
def ince_form() -> sp.Expr:
    """The frictionless (V3) of the sine modulation times ``l/Omega^2`` in ``theta = Omega t``
    (``Omega = 2 pi/T``), with ``c = g/Omega^2`` (``= (T/T0)^2`` in these units): the operator
    ``L[u] = (1 + m sin theta) u'' + (c + m sin theta) u`` (an Ince equation), returned as
    ``L[u]`` for ``u = u(theta)``, derived from :func:`hill_form` (checked by sympy)."""
    W = sp.Symbol("Omega", positive=True)
    l = 1 + _m * sp.sin(W * _t)
    q = hill_form(l).subs(_gamma, 0)
    u = sp.Function("u")
    ut = u(W * _t)
    expr = l * (sp.diff(ut, _t, 2) + q * ut) / W**2
    expr = sp.expand(sp.cancel(expr.subs(_g, _c * W**2)))
    expr = expr.subs(_t, _theta / W).doit()
    out = (1 + _m * sp.sin(_theta)) * sp.diff(u(_theta), _theta, 2) + (
        _c + _m * sp.sin(_theta)
    ) * u(_theta)
    if sp.simplify(expr - out) != 0:  # pragma: no cover - a proof
        raise AssertionError("the Ince form did not follow from the Hill form")
    return out


@cache
def fourier_recurrence() -> tuple[sp.Expr, sp.Expr, sp.Expr]:
    """``(d, up, down)`` in ``k, c, m``: ``L[e^{i k theta}] = e^{i k theta} (d + up e^{i theta}
    + down e^{-i theta})`` (sympy applies :func:`ince_form` to the exponential).  With ``u =
    sum a_k e^{i k theta}`` the coefficient of ``e^{i k theta}`` in ``L[u]`` is ``d(k) a_k +
    up(k - 1) a_{k-1} + down(k + 1) a_{k+1}``."""
    u = sp.Function("u")
    L = ince_form()
    e = sp.exp(sp.I * _k * _theta)
    val = L.subs(u(_theta), e).doit()
    val = sp.expand(sp.expand(val.rewrite(sp.exp)) / e)
    z = sp.Symbol("z")  # z = e^{i theta}
    val = sp.expand(sp.powsimp(val.subs(sp.exp(sp.I * _theta), z)))
    d = val.coeff(z, 0)
    up = val.coeff(z, 1)
    down = val.coeff(z, -1)
    if sp.simplify(val - d - up * z - down / z) != 0:  # pragma: no cover - a proof
        raise AssertionError("L[e^{ik theta}] is not a three-term sum")
    return sp.factor(d), sp.factor(up), sp.factor(down)


@dataclass(frozen=True)
class SineClosings:
    """The closings of the sine modulation without friction (:func:`sine_closings`).

    ``coupling``: the factor of ``up(k)`` (and ``down(k)``) of :func:`fourier_recurrence` that
    depends on ``k``; ``zeros``: its zeros in ``k``.  ``even_closed``: every zero is an
    integer (the modes of period ``T``, even orders) and the recurrence decouples there;
    ``odd_open``: no zero is a half-integer (the modes of period ``2T``, odd orders)."""

    coupling: sp.Expr
    zeros: tuple
    even_closed: bool
    odd_open: bool


@cache
def sine_closings() -> SineClosings:
    """Which intervals of the sine modulation close, derived from the Fourier recurrence.

    The coupling of ``a_k`` to its neighbours is ``(m/2i)(1 - k^2)`` (up to sign): it
    vanishes exactly at ``k = +-1``.  *Even orders* (solutions of period ``T``: integer
    ``k``): the equations for ``k >= 2`` do not contain ``a_1``, those for ``k <= -2`` not
    ``a_-1``, and the one for ``k = 0`` reads ``c a_0 = 0``; so each solution ``(a_2, a_3,
    ...)`` of the upper chain (with ``a_1`` from the row ``k = 1``) and its mirror image in the
    lower chain are two independent periodic solutions at the same ``c = (T/T0)^2``: every
    periodic solution coexists with a second one, ``M = I``, and **every interval of even
    order has zero width at every depth** ``0 < m < 1`` (order 2: the chain ``k = +-1`` alone,
    ``c = 1``, ``T = T0``).  *Odd orders* (half-integer ``k``): no coupling vanishes.  The
    coefficients of an even and an odd solution (under ``theta -> pi - theta``, i.e. ``a_-k =
    +-i^.. a_k``) obey the same recurrence for ``k >= 3/2`` and decay (the solutions are
    analytic); by Perron's theorem the decaying solutions of that recurrence form one line
    (its characteristic roots ``(-1 +- sqrt(1 - m^2))/m`` have different moduli), so the two
    would be proportional, while their rows ``k = 1/2`` differ by ``3m/4 a_{1/2} != 0``: at
    no ``T`` are both periodic, ``M != -I``, and **no interval of odd order ever closes**."""
    d, up, down = fourier_recurrence()
    # the k-dependence of the couplings (the constant factor i m/2 aside)
    cu = sp.factor(sp.simplify(up / (sp.I * _m / 2)))
    zeros = tuple(sorted(sp.solve(sp.Eq(up, 0), _k), key=float))
    zeros_down = tuple(sorted(sp.solve(sp.Eq(down, 0), _k), key=float))
    # up(k) couples a_k into row k + 1, down(k) into row k - 1: a_{k} is cut off from its
    # upper neighbour when up(k) = 0 and from its lower one when down(k) = 0
    ints = all(z.is_integer for z in zeros + zeros_down)
    half = any((2 * z).is_integer and not z.is_integer for z in zeros + zeros_down)
    return SineClosings(cu, zeros + zeros_down, ints and len(zeros) > 0, not half)
