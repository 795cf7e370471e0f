"""Certified numbers for a length that varies smoothly: the ``sine`` modulation, and the ramps
with friction.

The equation is (V2) of :mod:`analytic.smooth`, ``y' = A(t) y`` in the state ``(phi, p = l^2
phi')``, with ``A`` compiled from the sympy forms there and integrated by the one validated
integrator :func:`verify.taylor.flow` (ball arithmetic, proven remainder).  Units: time in
``T0``, ``g = 4 pi^2``, ``gamma = pi/Q``.

* :func:`sine_monodromy_arb`: the period map of ``l = 1 + m sin(2 pi t/T)`` from ``t = 0``.
* :func:`ramp_monodromy_damped_arb`: the period map of the ramp modulation with friction (the
  length constant on the plateaus, linear on the ramps; every piece through the integrator).
* :func:`sine_boundary`: the certified edges of the sine modulation without friction.  ``l`` is
  even about ``T/4`` and ``3T/4`` (:func:`analytic.smooth.check_sine_symmetry`), so each edge is
  a zero of one entry of ``G``, the map from ``T/4`` to ``3T/4`` (odd orders ``G11``/``G22``,
  even ``G12``/``G21``), as for the ramp.  *Which* zero: in the time ``s = t/T`` the Prüfer
  angle of the column of ``G`` grows strictly with ``T`` (Sturm comparison: ``T^2 g l`` is the
  only place ``T`` enters), and on the edge of order ``n`` it has turned by exactly ``n pi/2``
  over the half period; that angle is found by a double-precision integration of the Prüfer
  equation (*not proven*), the zero then refined by the secant method on ball midpoints (at 64
  bits first, then usually two evaluations at full precision), and enclosed by a **proven sign
  change** of the entry on a small bracket (a zero of the edge equation lies in the printed
  enclosure).  ``G`` is integrated in the Liouville form (V3) (one varying entry: half the work
  per Taylor step) and carried back to ``(phi, p)`` by the derived ``C`` at both ends
  (:func:`sine_half_map`; :func:`sine_half_map_direct` integrates (V2) itself).
* :func:`sine_edges_fourier`: the edges by Hill's method from the Fourier recurrence of the
  sine's Ince form (:func:`analytic.smooth.fourier_recurrence`), an independent route without
  integration (not proven: truncated).
"""

from __future__ import annotations

import math
from fractions import Fraction
from functools import cache

import mpmath
from flint import arb, arb_series, ctx, fmpq

from .certify import CertificationError, bits_for_digits
from .inputs import InputError, as_depth, as_digits, as_order
from .params import exact_fraction
from .taylor import flow

__all__ = [
    "sine_monodromy_arb",
    "sine_half_map",
    "sine_half_map_direct",
    "ramp_monodromy_damped_arb",
    "sine_rotation",
    "sine_boundary",
    "sine_edges_fourier",
]


def _sin(z):
    return z.sin()


def _cos(z):
    return z.cos()


_NAMESPACE = {
    "sin": _sin,
    "cos": _cos,
    "_q": lambda p, q: arb(fmpq(p, q)) if q != 1 else arb(p),
}


@cache
def _compiled():
    """``A(t)`` of the sine modulation (in ``t, T, m, g, gamma, PI``), of a linear length
    ``l = la + c (t - ta)`` (in ``t, la, c, ta, g, gamma``), and the sine's ``B`` and ``C`` of
    (V3), compiled for ``arb_series``/``acb`` arguments from :mod:`analytic.smooth`; loaded from
    their stored texts (:mod:`verify.switch_forms`)."""
    from .switch_forms import load

    f = load("smooth", _NAMESPACE, _derived)
    return f["sine"], f["lin"], f["hill"], f["state"]


def _derived():
    """The functions of :func:`_compiled` by name, compiled now from the derivation (imports
    sympy)."""
    import sympy as sp

    from analytic.smooth import sine_forms, sine_hill_forms, symbols, system_matrix

    from .derived import _printer

    s = symbols()
    sine = sp.lambdify(
        (s["t"], s["T"], s["m"], s["g"], s["gamma"], s["PI"]),
        list(sine_forms()),
        modules=[_NAMESPACE],
        printer=_printer(),
        cse=True,
        docstring_limit=0,
    )
    la, c, ta = sp.symbols("l_a c t_a")
    lin = sp.lambdify(
        (s["t"], la, c, ta, s["g"], s["gamma"]),
        list(system_matrix(la + c * (s["t"] - ta), s["g"], s["gamma"])),
        modules=[_NAMESPACE],
        printer=_printer(),
        cse=True,
        docstring_limit=0,
    )
    B, C = sine_hill_forms()
    args = (s["t"], s["T"], s["m"], s["g"], s["gamma"], s["PI"])
    kw = {"modules": [_NAMESPACE], "printer": _printer(), "cse": True, "docstring_limit": 0}
    hill = sp.lambdify(args, list(B), **kw)
    state = sp.lambdify(args, list(C), **kw)
    return {"sine": sine, "lin": lin, "hill": hill, "state": state}


def _A(x: Fraction) -> arb:
    return arb(fmpq(x.numerator, x.denominator))


def _gamma(Q) -> arb:
    """``gamma = pi/Q`` in units ``1/T0`` (``0`` without friction)."""
    return arb(0) if Q is None else arb.pi() / _A(Fraction(Q))


def _series_safe(f):
    """Wrap ``A`` so that constant entries become series/boxes of the argument's type."""

    def coef(t):
        out = f(t)
        if isinstance(t, arb_series):
            return [e if isinstance(e, arb_series) else arb_series([e], prec=t.prec) for e in out]
        return out

    return coef


def _sine_coef(T: arb, m: arb, gamma: arb):
    sine = _compiled()[0]
    g = 4 * arb.pi() ** 2
    pi = arb.pi()
    return _series_safe(lambda t: sine(t, T, m, g, gamma, pi))


def sine_monodromy_arb(m, T, Q=None):
    """The period map of ``(phi, p)`` over ``T`` (units ``T0``) from ``t = 0`` for the sine
    modulation of depth ``m`` with friction ``Q`` (``None``: none), as four balls at the working
    precision; ``m``, ``T`` exact Fractions (or ``T`` an ``arb``)."""
    Tb = T if isinstance(T, arb) else _A(Fraction(T))
    coef = _sine_coef(Tb, _A(Fraction(m)), _gamma(Q))
    return flow(coef, arb(0), Tb, scale=2 * arb.pi())


def sine_half_map(m, T, *, goal_bits=None):
    """``G``: the map of ``(phi, p)`` from ``t = T/4`` to ``3T/4`` (no friction), four balls.

    Integrated in the Liouville form (V3) of :mod:`analytic.smooth` (one varying entry: half
    the work of (V2) per Taylor step) and carried back to ``(phi, p)`` by the derived ``C`` at
    both ends: ``G = C(3T/4)^-1 W C(T/4)``.  ``goal_bits``: the remainder goal of each Taylor
    step (:func:`verify.taylor.flow`; default the working precision plus 10 bits)."""
    _, _, hill, state = _compiled()
    Tb = T if isinstance(T, arb) else _A(Fraction(T))
    mb = m if isinstance(m, arb) else _A(Fraction(m))
    g = 4 * arb.pi() ** 2
    pi = arb.pi()
    zero = arb(0)
    coef = _series_safe(lambda t: hill(t, Tb, mb, g, zero, pi))
    a, b = Tb / 4, 3 * Tb / 4
    W = flow(coef, a, b, scale=2 * arb.pi(), goal_bits=goal_bits)
    Ca = state(a, Tb, mb, g, zero, pi)
    c11, c12, c21, c22 = state(b, Tb, mb, g, zero, pi)
    det = c11 * c22 - c12 * c21
    Cb_inv = (c22 / det, -c12 / det, -c21 / det, c11 / det)
    return _mul(Cb_inv, _mul(W, tuple(Ca)))


def sine_half_map_direct(m, T):
    """``G`` as :func:`sine_half_map`, integrated in ``(phi, p)`` (V2) directly: the slower
    route, kept to check the Liouville route."""
    Tb = T if isinstance(T, arb) else _A(Fraction(T))
    coef = _sine_coef(Tb, m if isinstance(m, arb) else _A(Fraction(m)), arb(0))
    return flow(coef, Tb / 4, 3 * Tb / 4, scale=2 * arb.pi())


def ramp_monodromy_damped_arb(m, tau, S, Q, duty=Fraction(1, 2)):
    """The period map of ``(phi, p)`` from ``t = S/2`` for the ramp modulation (linear ramps of
    the length lasting ``S`` centred on ``t = 0`` and ``t = D T``) with friction ``Q``, every
    piece through the validated integrator (four balls)."""
    lin = _compiled()[1]
    m, S, duty = Fraction(m), Fraction(S), Fraction(duty)
    T = _A(Fraction(tau))
    g = 4 * arb.pi() ** 2
    gam = _gamma(Q)
    l1, l2 = _A(1 + m), _A(1 - m)
    Sb, D = _A(S), _A(duty)
    t_a = Sb / 2
    t_b = D * T - Sb / 2
    t_c = D * T + Sb / 2
    t_d = T - Sb / 2
    pieces = [
        (t_a, t_b, l1, arb(0), t_a),  # plateau 1
        (t_b, t_c, l1, (l2 - l1) / Sb if S else arb(0), t_b),  # ramp down
        (t_c, t_d, l2, arb(0), t_c),  # plateau 2
        (t_d, T + Sb / 2, l2, (l1 - l2) / Sb if S else arb(0), t_d),  # ramp up
    ]
    if S == 0:  # the jump: only the plateaus (the state is continuous through a jump)
        pieces = pieces[0::2]
    M = (arb(1), arb(0), arb(0), arb(1))
    for a, b, la, c, ta in pieces:
        coef = _series_safe(lambda t, la=la, c=c, ta=ta: lin(t, la, c, ta, g, gam))
        M = _mul(flow(coef, a, b, scale=2 * arb.pi()), M)
    return M


def _mul(P, Q):
    a, b, c, d = P
    e, f, g, k = Q
    return (a * e + b * g, a * f + b * k, c * e + d * g, c * f + d * k)


# ---------------------------------------------------------------------------------------------
# the Prüfer angle (double precision; locates the edge of each order)

_COLUMN = {"G11": 0, "G21": 0, "G12": 1, "G22": 1}
_ENTRY = {"G11": 0, "G12": 1, "G21": 2, "G22": 3}


def sine_rotation(m: float, T: float, column: int, steps: int = 400) -> float:
    """The angle (radians) by which the state ``(phi, l^2 dphi/ds)`` (``s = t/T``) of the
    ``column``-th solution of ``G`` (0: starting at ``(1, 0)``, 1: at ``(0, 1)``) turns from
    ``s = 1/4`` to ``3/4``, by RK4 on the Prüfer equation ``theta' = cos^2/l^2 + T^2 g l sin^2``
    (double precision; strictly increasing in ``T``)."""
    g = 4 * math.pi**2
    k = T * T * g
    cos, sin = math.cos, math.sin
    th0 = math.pi / 2 if column == 0 else 0.0
    th = th0
    h = 0.5 / steps
    h2, h6 = h / 2, h / 6
    for a0, b0, a1, b1, a2, b2 in _rotation_nodes(m, steps):
        # the right side at a node with 1/l^2 = a, l = b
        c, sn = cos(th), sin(th)
        k1 = c * c * a0 + k * b0 * sn * sn
        t = th + h2 * k1
        c, sn = cos(t), sin(t)
        k2 = c * c * a1 + k * b1 * sn * sn
        t = th + h2 * k2
        c, sn = cos(t), sin(t)
        k3 = c * c * a1 + k * b1 * sn * sn
        t = th + h * k3
        c, sn = cos(t), sin(t)
        k4 = c * c * a2 + k * b2 * sn * sn
        th += h6 * (k1 + 2 * k2 + 2 * k3 + k4)
    return th - th0


@cache
def _rotation_nodes(m: float, steps: int) -> tuple:
    """``(1/l^2, l)`` at the start, middle and end of each RK4 step of :func:`sine_rotation`
    (they do not depend on ``T``)."""

    def node(s: float) -> tuple[float, float]:
        l = 1 + m * math.sin(2 * math.pi * s)
        return 1 / (l * l), l

    out = []
    h = 0.5 / steps
    s = 0.25
    for _ in range(steps):
        out.append((*node(s), *node(s + h / 2), *node(s + h)))
        s += h
    return tuple(out)


def _guess(m: float, n: int, column: int) -> float:
    """The ``T`` at which the rotation is ``n pi/2``: bracketed on the monotone rotation, then
    the Illinois (regula falsi) iteration on it (double precision); then the same zero with
    twice the RK4 steps (secant steps from the first), and Richardson's extrapolation of the
    two (RK4's error is ``O(h^4)``): a start that the secant refinement needs fewer evaluations
    from."""
    steps = 200 + 120 * n
    x1 = _rotation_zero(m, n, column, steps)
    target = n * math.pi / 2

    def f(T: float) -> float:
        return sine_rotation(m, T, column, 2 * steps) - target

    a, b = x1, x1 * (1 + 1e-7)
    fa, fb = f(a), f(b)
    for _ in range(6):
        if fb == fa:
            break
        a, b, fa = b, b - fb * (b - a) / (fb - fa), fb
        if abs(b - a) < 1e-14 * abs(b):
            break
        fb = f(b)
    x2 = b
    extrapolated = x2 + (x2 - x1) / 15
    # keep the extrapolation only where it is a small correction (else the RK4 zero itself)
    return extrapolated if abs(x2 - x1) < 1e-4 * abs(x2) else x2


def _rotation_zero(m: float, n: int, column: int, steps: int) -> float:
    """The ``T`` at which the rotation with ``steps`` RK4 steps is ``n pi/2``: bracketed on the
    monotone rotation, then the Illinois (regula falsi) iteration on it."""
    target = n * math.pi / 2

    def f(T: float) -> float:
        return sine_rotation(m, T, column, steps) - target

    lo, hi, flo, fhi = _rotation_bracket(f, n)
    while flo > 0:
        lo /= 2
        flo = f(lo)
    while fhi < 0:
        hi *= 2
        fhi = f(hi)
    side = 0
    for _ in range(100):
        x = (lo * fhi - hi * flo) / (fhi - flo)
        fx = f(x)
        if fx == 0 or hi - lo < 1e-14 * hi:
            return x
        if fx < 0:
            lo, flo = x, fx
            if side == -1:
                fhi /= 2
            side = -1
        else:
            hi, fhi = x, fx
            if side == 1:
                flo /= 2
            side = 1
        if abs(fx) < 1e-13:
            return x
    return (lo + hi) / 2


def _rotation_bracket(f, n: int) -> tuple[float, float, float, float]:
    """``(lo, hi, f(lo), f(hi))`` with ``f(lo) < 0 < f(hi)`` for ``f`` the rotation minus its
    target, increasing in ``T``: from ``T = n/2`` (the order's tuning without modulation) and
    the rotation taken proportional to ``T``, then secant steps (a few evaluations for a tight
    bracket); the wide bracket ``[0.02 n, 0.8 n + 0.5]`` where that does not close in six."""
    target = n * math.pi / 2
    a = n / 2
    fa = f(a)
    b = a * target / (fa + target) if fa + target > 0 else a / 2
    fb = f(b)
    for _ in range(6):
        if fa < 0 < fb:
            return a, b, fa, fb
        if fb < 0 < fa:
            return b, a, fb, fa
        if fb == fa or not (math.isfinite(fa) and math.isfinite(fb)):
            break
        # past the secant's zero by a tenth of the step: the next point brackets it
        c = b - fb * (b - a) / (fb - fa)
        c = c + 0.1 * (c - b)
        if not c > 0:
            break
        a, fa, b, fb = b, fb, c, f(c)
    lo, hi = 0.02 * n, 0.8 * n + 0.5
    return lo, hi, f(lo), f(hi)


def _pair(n: int) -> tuple[str, str]:
    return ("G11", "G22") if n % 2 else ("G12", "G21")


#: the working precision of the first refinement (cheap; to about 1e-17), and the remainder
#: its Taylor steps are bounded to (``2^-_LOW_GOAL``; its zero is not proven but only placed
#: within the enclosure :func:`_enclose` proves, so it needs no more than the secant's goal)
_LOW_BITS = 64
_LOW_GOAL = 64


def _secant(F, x1: arb, x2: arb, f1: arb, goal: arb, iters: int):
    """Secant steps on ball midpoints from ``x1`` (where ``F`` is ``f1``) and ``x2``; returns
    ``(x, slope)``: the last iterate, computed but not evaluated, and the slope of the secant
    through the last two points evaluated.  Stops when a step is below ``goal`` (relative), or
    when the new iterate's error, about the product of its distances to the last two points
    over ``|x|`` (the secant's error), is below ``goal/256``."""
    f2 = F(x2).mid()
    for _ in range(iters):
        if f2 == f1:
            break
        slope = (f2 - f1) / (x2 - x1)
        x3 = (x2 - f2 / slope).mid()
        d = abs(x3 - x2)
        if d < goal * abs(x3) or d * abs(x3 - x1) < goal * abs(x3) * abs(x3) * arb(2) ** -8:
            return x3, slope
        x1, f1 = x2, f2
        x2 = x3
        f2 = F(x2).mid()
    return x2, ((f2 - f1) / (x2 - x1) if x2 != x1 and f2 != f1 else None)


def _refine(m: Fraction, e: int, x0: float, bits: int) -> tuple[arb, arb | None]:
    """The zero of entry ``e`` of ``G`` near ``x0`` to about ``2^-(bits - 8)`` (relative), and
    the slope of the entry there (a secant's): the secant method on ball midpoints at
    :data:`_LOW_BITS` bits first, then (above ``_LOW_BITS + 12`` bits) Newton and secant steps
    at ``bits``, started from the low-precision zero and slope (usually two evaluations).
    Returns midpoints (not proven: :func:`_enclose` proves the zero, and moves a zero that is
    not yet accurate enough)."""
    with ctx.workprec(_LOW_BITS):

        def F_low(T: arb) -> arb:
            return sine_half_map(m, T, goal_bits=_LOW_GOAL)[e]

        x1 = arb(x0)
        f1 = F_low(x1).mid()
        x, slope = _secant(F_low, x1, arb(x0 * (1 + 1e-9)), f1, arb(2) ** -50, 12)
    if bits <= _LOW_BITS + 12:
        return x, slope
    with ctx.workprec(bits):

        def F(T: arb) -> arb:
            return sine_half_map(m, T)[e]

        goal = arb(2) ** (-(bits - 8))
        x1 = arb(x.mid())
        f1 = F(x1).mid()
        if slope is None or slope == 0:
            x2 = arb((x1 * (1 + arb(2) ** -40)).mid())
            return _secant(F, x1, x2, f1, goal, 40)
        d_prev = None
        for _ in range(20):
            # a Newton step with the low-precision slope, then secant steps: from 1e-17 off,
            # the second point is ~1e-25 off and the third ~1e-42
            x2 = (x1 - f1 / slope).mid()
            d = abs(x2 - x1)
            if d < goal * abs(x2):
                return x2, slope
            # a secant step's error is about (the last two steps' product)/|x|
            if d_prev is not None and d * d_prev < goal * abs(x2) * abs(x2) * arb(2) ** -8:
                return x2, slope
            f2 = F(x2).mid()
            if f2 == f1:
                return x2, slope
            slope = (f2 - f1) / (x2 - x1)
            x1, f1, d_prev = x2, f2, d
        return x1, slope


def _opposite(fa: arb, fb: arb) -> bool:
    return (fa < 0 and fb > 0) or (fa > 0 and fb < 0)


def _same(fa: arb, fb: arb) -> bool:
    return (fa < 0 and fb < 0) or (fa > 0 and fb > 0)


def _enclose(m: Fraction, entries: tuple, x: arb, bits: int) -> arb:
    """A ball around ``x`` at whose ends each entry in ``entries`` of ``G`` has proven opposite
    signs (so it holds a zero of each), as narrow as the precision allows: half-width
    ``|x| 2^-(bits - 24)`` first.  Where one entry has the same proven sign at both ends, its
    zero lies outside: ``x`` moves to the secant's zero through the two ends (twice at most)
    before the ball is widened."""
    with ctx.workprec(bits):
        for k in range(bits - 24, 8, -8):
            d = abs(x) * arb(2) ** (-k)
            for _ in range(3):
                a, b = (x - d).mid(), (x + d).mid()
                # only the signs at a and b are used: |G_e| there is about |G_e'| d, far above
                # the radius of Taylor steps bounded to 2^-bits (the default asks 2^-(bits+10))
                Ga = sine_half_map(m, a, goal_bits=bits)
                Gb = sine_half_map(m, b, goal_bits=bits)
                if all(_opposite(Ga[e], Gb[e]) for e in entries):
                    return arb.union(a, b)
                moved = next((e for e in entries if _same(Ga[e], Gb[e])), None)
                if moved is None:
                    break  # a sign not proven at this precision: a wider ball
                fa, fb = Ga[moved].mid(), Gb[moved].mid()
                if fa == fb:
                    break
                x = (a - fa * (b - a) / (fb - fa)).mid()
    raise CertificationError("no sign change of the edge equation could be proven")


def _edges(m: Fraction, n: int, names: tuple, bits: int) -> list:
    """The enclosures of the zeros of the two entries ``names`` of ``G`` on the edges of order
    ``n`` at ``bits`` bits.  For an even order the two zeros are tried in one ball first (the
    even intervals of the sine modulation are closed: :func:`analytic.smooth.sine_closings`),
    so that the same two evaluations prove both sign changes; where that fails, and for odd
    orders, each zero is located and enclosed on its own."""
    if n % 2 == 0:
        e0, e1 = (_ENTRY[name] for name in names)
        x, _ = _refine(m, e0, _guess(float(m), n, _COLUMN[names[0]]), bits)
        try:
            ball = _enclose(m, (e0, e1), x, bits)
            return [ball, ball]
        except CertificationError:
            pass
    out = []
    for name in names:
        x, _ = _refine(m, _ENTRY[name], _guess(float(m), n, _COLUMN[name]), bits)
        out.append(_enclose(m, (_ENTRY[name],), x, bits))
    return out


def sine_boundary(order, m, *, digits=30):
    """The certified edges of the ``order``-th interval of the sine modulation (no friction) as
    a :class:`verify.solve.Boundary` (``delta_*``: ``T - n T_av/2``, the offset from the square
    wave's tuning at the same depth, as for every modulation)."""
    from analytic.system import system as make_system

    from .result import from_balls

    n = as_order(order)
    mm = exact_fraction(as_depth(m))
    d = as_digits(digits)
    bits = bits_for_digits(d + 6)
    names = _pair(n)
    balls = _edges(mm, n, names, bits + 16)
    if balls[1] < balls[0]:
        balls, names = balls[::-1], names[::-1]
    lo, hi = balls
    sysv = make_system("pendulum")
    notes = [
        "sine modulation l = 1 + m sin(2 pi t/T); edges are zeros of "
        f"{names[0]} and {names[1]} of the half-period map, each enclosed by a proven sign "
        "change (validated Taylor integration in ball arithmetic); the order of each zero is "
        "identified by the Prüfer angle in double precision (not proven)",
    ]
    if lo.overlaps(hi):
        notes.append("the two edges could not be separated at this precision")
    with ctx.workprec(bits + 16):
        # the square wave's tuning n T_av/2 = n pi/omega_av (the offsets' reference)
        w1, w2 = (arb(fmpq(w.numerator, w.denominator)).sqrt() for w in sysv.values(mm)[:2])
        half = n / (w1 + w2)
        return from_balls(
            (lo, hi, lo - half, hi - half),
            order=n,
            m=mm,
            Q=None,
            damping="exact",
            digits=d,
            method="certified",
            regime="sine modulation, validated Taylor route",
            system=sysv,
            notes=notes,
        )


def check_sine(system, duty, Q=None) -> None:
    """Refuse the sine modulation outside the pendulum with equal halves."""
    name = getattr(system, "name", system)
    if name != "pendulum":
        raise InputError(
            f"the sine modulation is implemented for the pendulum only, not for system {name!r}"
        )
    D = getattr(system, "duty", None)
    D = Fraction(D) if D is not None else exact_fraction(as_depth(duty))
    if D != Fraction(1, 2):
        raise InputError(
            f"the sine modulation has equal halves only: duty D = {D} is not allowed (D = 1/2)"
        )


# ---------------------------------------------------------------------------------------------
# Hill's method: an independent route to the sine's edges (not proven)


@cache
def _fourier_compiled():
    import sympy as sp

    from analytic.smooth import fourier_recurrence, symbols

    d, up, down = fourier_recurrence()
    s = symbols()
    k, c, m = s["k"], s["c"], s["m"]
    f = sp.lambdify((k, c, m), [d, up, down], modules="mpmath")
    return f


def sine_edges_fourier(order, m, *, dps=40, start=None):
    """The edges ``T/T0`` of the ``order``-th interval of the sine modulation (no friction) by
    Hill's method: the Fourier recurrence of :func:`analytic.smooth.fourier_recurrence`
    (``u = sum a_k e^{i k theta}``), truncated where its decaying solution has fallen below
    ``10^-(dps + 5)``, and the zero in ``c = (T/T0)^2`` of the truncated determinant near
    ``start`` (two guesses ``T``; default the square wave's tuning ``n/2``).  Even orders: the
    upper chain ``k = 2, 3, ...`` (one value, twice: the interval is closed; order 2 is ``T =
    1``); odd orders: ``k = 1/2, 3/2, ...`` with ``a_-k = +-e^{i k pi} a_k`` (the solutions even
    and odd about ``t = T/4``).  A cross-check of the certified route, not itself proven."""
    n = as_order(order)
    mm = exact_fraction(as_depth(m))
    f = _fourier_compiled()
    with mpmath.workdps(dps + 10):
        mq = mpmath.mpf(mm.numerator) / mm.denominator
        lam = (1 - mpmath.sqrt(1 - mq * mq)) / mq
        K = int((dps + 5) * mpmath.log(10) / -mpmath.log(lam)) + n + 20
        guesses = start if start is not None else (mpmath.mpf(n) / 2,) * 2

        def det(c, first, k0):
            # P_j = d_j P_{j-1} - up(k_j - 1) down(k_j) P_{j-2}, normalised by k^2 each row
            p_prev, p = mpmath.mpf(1), first(c)
            kk = k0
            for _ in range(K):
                kk += 1
                dk, _, dn = f(kk, c, mq)
                _, upk, _ = f(kk - 1, c, mq)
                p_prev, p = p, (dk * p - upk * dn * p_prev)
                s = kk * kk
                p_prev, p = p_prev / s, p / s
            return mpmath.re(p)

        if n == 2:
            return mpmath.mpf(1), mpmath.mpf(1)
        if n % 2 == 0:
            k0 = mpmath.mpf(2)

            def first(c):
                return f(k0, c, mq)[0]

            roots = [
                mpmath.findroot(lambda c: det(c, first, k0), mpmath.mpf(g) ** 2, verify=False)
                for g in guesses[:1]
            ]
            T = mpmath.sqrt(roots[0])
            return T, T
        out = []
        k0 = mpmath.mpf(1) / 2
        for sign, g in zip((1, -1), guesses, strict=True):

            def first(c, sign=sign):
                dk = f(k0, c, mq)[0]
                upm = f(-k0, c, mq)[1]  # a_{-1/2} into row 1/2
                return dk + upm * sign * mpmath.exp(1j * mpmath.pi * k0)

            c = mpmath.findroot(
                lambda c, first=first: det(c, first, k0), mpmath.mpf(g) ** 2, verify=False
            )
            out.append(mpmath.sqrt(c))
        out.sort()
        return out[0], out[1]
