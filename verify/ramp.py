"""Certified numbers for the ``ramp`` modulation: each switch a linear ramp of the length.

The pendulum's length ramps linearly from ``l2 = 1 - m`` to ``l1 = 1 + m`` (units ``l0``) during
``[-S/2, S/2]`` and back during ``[D T - S/2, D T + S/2]`` (``S``, ``T`` in units of ``T0``), so
the constant phases last ``D T - S`` and ``(1 - D) T - S``; ``0 <= S <= min(D T, (1 - D) T)``.
``S = 0`` is the jump model.  No friction; the paper's pendulum (bob on a light rod) with any
duty ``D``.

Every map is compiled from :mod:`analytic.ramp` (the Bessel solution on a ramp, the free
oscillation on a plateau, in the state ``(phi, p = l^2 phi')``) and evaluated in python-flint
``arb`` ball arithmetic (``arb.bessel_j``/``bessel_y``), so every entry encloses the exact one.

* :func:`ramp_monodromy_arb`: the period map of ``(phi, phi')`` from ``t = S/2`` (the end of the
  ramp into phase 1; at ``S = 0`` exactly the jump model's ``t = 0+``), the four entries as balls.
* :func:`ramp_boundary`: the certified edges.  By the symmetry :mod:`analytic.ramp` proves, each
  edge is a zero of one entry of ``G`` (the map from the middle of phase 1 to the middle of phase
  2): ``G11`` or ``G22`` for odd orders, ``G12`` or ``G21`` for even ones.  Each factor's zero is
  followed from the jump model's certified edge (``S = 0``) to the ``S`` asked by continuation in
  ``S`` (Newton on ball midpoints, small steps), then enclosed by interval Newton
  (:func:`verify.certify.certified_root`: the ball returned holds exactly one zero of that factor,
  proven).  *What is proven*: the enclosure of a zero of the edge equation; *what rests on the
  continuation*: that this zero is the one connected to the jump model's edge (steps are small
  against the distance to the next zero of the same factor, and a step that changes the root by
  more than a fraction of the order's spacing is refused and halved).
* :func:`leading_shift`: the derived first-order coefficient ``dT/dS`` at ``S = 0`` of each edge
  (:func:`analytic.ramp.first_order_defect`), evaluated in ball arithmetic.
* :func:`jump_validity`: the largest ``S`` for which both ramp edges stay within a relative
  tolerance of the jump model's edges.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from fractions import Fraction
from functools import cache

import mpmath
from flint import arb, ctx, fmpq

from .certify import CertificationError, bits_for_digits, certified_root, to_mpf, upper_mpf
from .inputs import InputError, as_depth, as_digits, as_order, as_system
from .params import exact_fraction

__all__ = [
    "MODULATIONS",
    "as_switch_time",
    "check_modulation",
    "ramp_monodromy_arb",
    "ramp_half_map",
    "ramp_boundary",
    "leading_shift",
    "RampEdges",
    "jump_validity",
    "Validity",
]

#: the modulations the engine knows (``sine`` is not implemented yet)
MODULATIONS = ("square", "ramp")


# ---------------------------------------------------------------------------------------------
# input


def as_switch_time(S) -> Fraction:
    """A switching time ``S >= 0`` (units ``T0``) as an exact Fraction."""
    if isinstance(S, bool) or S is None:
        raise InputError(f"switching time S = {S!r} must be a number >= 0 (units of T0)")
    try:
        if isinstance(S, str):
            v = Fraction(S.strip())
        elif isinstance(S, (int, Fraction)):
            v = Fraction(S)
        elif isinstance(S, float):
            if not math.isfinite(S):
                raise ValueError
            v = Fraction(S)
        else:
            v = exact_fraction(S)
    except (ValueError, ZeroDivisionError, TypeError):
        raise InputError(f"switching time S = {S!r} is not a number (units of T0, S >= 0)") from None
    if v < 0:
        raise InputError(f"switching time S = {S} must be >= 0 (units of T0)")
    return v


def check_modulation(modulation, switch_time, system) -> Fraction | None:
    """Check the modulation options; returns ``S`` (a Fraction) for ``ramp``, ``None`` for
    ``square``.  Refuses: an unknown modulation, ``switch_time`` without ``ramp``, ``ramp``
    without ``switch_time``, and ``ramp`` for a system other than the pendulum."""
    if modulation not in MODULATIONS:
        extra = " (sine modulation is not implemented)" if modulation == "sine" else ""
        raise InputError(
            f"modulation {modulation!r} is not one of: {', '.join(MODULATIONS)}{extra}"
        )
    if modulation == "square":
        if switch_time is not None:
            raise InputError(
                f"a switching time S = {switch_time} needs the ramp modulation "
                "(--modulation ramp); the square wave switches instantly"
            )
        return None
    if switch_time is None:
        raise InputError("the ramp modulation needs a switching time S >= 0 (--switch-time S)")
    S = as_switch_time(switch_time)
    name = getattr(system, "name", system)
    if name != "pendulum":
        raise InputError(
            f"the ramp modulation is implemented for the pendulum only (got system {name!r})"
        )
    return S


# ---------------------------------------------------------------------------------------------
# the compiled forms


_NAMESPACE = {
    "sin": lambda z: z.sin(),
    "cos": lambda z: z.cos(),
    "sqrt": lambda z: z.sqrt(),
    "besselj": lambda n, z: z.bessel_j(n),
    "bessely": lambda n, z: z.bessel_y(n),
    "Abs": abs,
    "_q": lambda p, q: arb(fmpq(p, q)) if q != 1 else arb(p),
}


@cache
def _compiled():
    """The arb functions of :func:`analytic.ramp.ramp_forms`: ``(ramp, plateau, A, E)``, each a
    function returning four entries (row-major)."""
    import sympy as sp

    from analytic.ramp import ramp_forms, symbols

    from .derived import _printer

    s = symbols()
    forms = ramp_forms()
    PI = sp.Symbol("PI", positive=True)
    pieces = {
        "ramp": ((s["la"], s["lb"], s["S"], s["g"], PI), forms[0:4]),
        "plateau": ((s["t"], s["l"], s["g"]), forms[4:8]),
        "A": ((s["l"], s["g"]), forms[8:12]),
        "E": ((s["la"], s["lb"], s["g"]), forms[12:16]),
    }
    out = {}
    for name, (args, exprs) in pieces.items():
        fn = sp.lambdify(
            args, list(exprs), modules=[_NAMESPACE], printer=_printer(), cse=True,
            docstring_limit=0,
        )
        out[name] = fn
    return out


def _A(x: Fraction) -> arb:
    return arb(fmpq(x.numerator, x.denominator))


def _mul(P, Q):
    a, b, c, d = P
    e, f, g, h = Q
    return (a * e + b * g, a * f + b * h, c * e + d * g, c * f + d * h)


class _Pendulum:
    """The numbers of one ``(m, S, D)`` at the working precision: lengths, ``g = 4 pi^2``, the
    ramp maps (they do not depend on ``T``)."""

    def __init__(self, m: Fraction, S: Fraction, duty: Fraction):
        f = _compiled()
        pi = arb.pi()
        self.g = 4 * pi * pi
        self.l1, self.l2 = _A(1 + m), _A(1 - m)
        self.S, self.D = _A(S), _A(duty)
        self.zero = S == 0
        if self.zero:
            one, nil = arb(1), arb(0)
            self.down = self.up = (one, nil, nil, one)
        else:
            self.down = tuple(f["ramp"](self.l1, self.l2, self.S, self.g, pi))
            self.up = tuple(f["ramp"](self.l2, self.l1, self.S, self.g, pi))
        self.A1 = tuple(f["A"](self.l1, self.g))
        self.A2 = tuple(f["A"](self.l2, self.g))
        self._plateau = f["plateau"]

    def U1(self, t):
        return tuple(self._plateau(t, self.l1, self.g))

    def U2(self, t):
        return tuple(self._plateau(t, self.l2, self.g))

    def half(self, T):
        """``G``: from the middle of phase 1 to the middle of phase 2."""
        t1 = (self.D * T - self.S) / 2
        t2 = ((1 - self.D) * T - self.S) / 2
        return _mul(self.U2(t2), _mul(self.down, self.U1(t1)))

    def half_dT(self, T):
        """``G`` and ``dG/dT = (1-D)/2 A2 G + D/2 G A1``."""
        G = self.half(T)
        a = _mul(self.A2, G)
        b = _mul(G, self.A1)
        w2, w1 = (1 - self.D) / 2, self.D / 2
        return G, tuple(w2 * x + w1 * y for x, y in zip(a, b, strict=True))

    def period(self, T):
        """The period map of ``(phi, p)`` from ``t = S/2``."""
        t1 = self.D * T - self.S
        t2 = (1 - self.D) * T - self.S
        P = _mul(self.U1(t1), (arb(1), arb(0), arb(0), arb(1)))
        P = _mul(self.down, P)
        P = _mul(self.U2(t2), P)
        return _mul(self.up, P)


def _check_fits(S: Fraction, T: Fraction, duty: Fraction) -> None:
    longest = min(duty, 1 - duty) * T
    if S > longest:
        raise InputError(
            f"switching time S = {S} is longer than a phase: at T/T0 = {float(T):.6g} and duty "
            f"D = {duty} the allowed range is 0 <= S <= min(D, 1-D) T = {float(longest):.6g}"
        )


def ramp_monodromy_arb(m, tau, S, duty=Fraction(1, 2)):
    """The period map of ``(phi, phi')`` over ``T = tau T0`` from ``t = S/2``, as four ``arb``
    balls at the working precision (``flint.ctx.prec``); ``m``, ``tau``, ``S``, ``duty`` exact
    Fractions with ``0 <= S <= min(D, 1 - D) tau``.  At ``S = 0`` it is the jump model's
    :func:`verify.floquet.monodromy_arb`."""
    m, tau, S, duty = (Fraction(v) for v in (m, tau, S, duty))
    _check_fits(S, tau, duty)
    p = _Pendulum(m, S, duty)
    a, b, c, d = p.period(_A(tau))
    L = p.l1 * p.l1  # p = l1^2 phi' at t = S/2
    return a, b * L, c / L, d


def ramp_half_map(m, T, S, duty=Fraction(1, 2)):
    """``G`` (four balls): the map of ``(phi, p)`` from the middle of phase 1 to the middle of
    phase 2 at period ``T`` (an exact Fraction or an ``arb``)."""
    p = _Pendulum(Fraction(m), Fraction(S), Fraction(duty))
    return p.half(T if isinstance(T, arb) else _A(Fraction(T)))


# ---------------------------------------------------------------------------------------------
# edges


@dataclass(frozen=True)
class RampEdges:
    """The certified edges of one interval with ramps of duration ``S``: ``lower``, ``upper``
    (``T/T0``) as balls, the jump model's edges ``jump_lower``, ``jump_upper`` (balls), which
    entry of ``G`` vanishes on each, and the result for the command line (``boundary``: a
    :class:`verify.solve.Boundary`)."""

    order: int
    m: Fraction
    S: Fraction
    duty: Fraction
    lower: arb
    upper: arb
    jump_lower: arb
    jump_upper: arb
    factors: tuple
    boundary: object = field(repr=False, default=None)

    @property
    def shifts(self) -> tuple[arb, arb]:
        return self.lower - self.jump_lower, self.upper - self.jump_upper


_ENTRY = {"G11": 0, "G12": 1, "G21": 2, "G22": 3}


def _jump(order: int, m: Fraction, duty: Fraction, digits: int):
    from .solve import boundary

    return boundary(order, m, digits=digits, system="pendulum", duty=duty)


def _ball(x: mpmath.mpf, rad) -> arb:
    from .certify import ball

    return ball(x, rad if rad else 0)


def _factors(p: _Pendulum, n: int, T_lo: arb, T_hi: arb) -> tuple[str, str]:
    """Which entry of ``G`` vanishes on the lower and which on the upper jump edge."""
    pair = ("G11", "G22") if n % 2 else ("G12", "G21")
    g_lo = p.half(T_lo)
    a, b = (abs(g_lo[_ENTRY[e]]) for e in pair)
    return pair if a.mid() <= b.mid() else (pair[1], pair[0])


def _newton_mid(p: _Pendulum, e: int, T: float, iters: int = 40) -> float | None:
    """Newton on midpoints at the working precision; the root as a float, or ``None``."""
    x = arb(T)
    for _ in range(iters):
        G, dG = p.half_dT(x)
        f, df = G[e].mid(), dG[e].mid()
        if df == 0 or not df.is_finite():
            return None
        step = (f / df).mid()
        x = (x - step).mid()
        if abs(float(step)) <= 1e-15 * max(1.0, abs(float(x))):
            return float(x)
    return None


def _follow(m, S, duty, e, T0: float, spacing: float, bits: int = 96) -> float:
    """Continue the zero of entry ``e`` of ``G`` from ``S = 0`` (at ``T0``) to ``S``."""
    with ctx.workprec(bits):
        s_now, T_now, slope = Fraction(0), T0, 0.0
        step = S
        while s_now < S:
            s_next = min(S, s_now + step)
            guess = T_now + slope * float(s_next - s_now)
            p = _Pendulum(m, s_next, duty)
            root = _newton_mid(p, e, guess)
            if root is None or abs(root - guess) > 0.05 * spacing:
                step = step / 2
                if step < S * Fraction(1, 2**40):
                    raise CertificationError(
                        f"the edge could not be followed to S = {S} (it may leave the window)"
                    )
                continue
            if s_next > s_now:
                slope = (root - T_now) / float(s_next - s_now)
            s_now, T_now = s_next, root
            step = min(step * 2, S)
        return T_now


def ramp_boundary(order, m, S, *, duty="1/2", digits=30) -> RampEdges:
    """The certified edges of the ``order``-th interval with linear ramps of duration ``S``."""
    from .solve import Boundary

    n = as_order(order)
    sysv = as_system("pendulum", duty)
    D = sysv.duty
    mm = exact_fraction(as_depth(m))
    SS = as_switch_time(S)
    d = as_digits(digits)
    jump = _jump(n, mm, D, max(d, 20) + 5)
    rad = jump.radii or (jump.radius,) * 4
    bits = bits_for_digits(d + 5)
    T_scale = float(jump.upper)
    # a first check before any work: the ramp must fit a phase near this order
    if SS > min(D, 1 - D) * Fraction(float(jump.upper)) * 2:
        _check_fits(SS, Fraction(float(jump.lower)), D)
    with ctx.workprec(bits + 20):
        T_lo0 = _ball(jump.lower, rad[0])
        T_hi0 = _ball(jump.upper, rad[1])
        p0 = _Pendulum(mm, Fraction(0), D)
        names = _factors(p0, n, T_lo0, T_hi0)
    spacing = float(T_scale) / n
    approx = [
        _follow(mm, SS, D, _ENTRY[names[0]], float(jump.lower), spacing) if SS else float(jump.lower),
        _follow(mm, SS, D, _ENTRY[names[1]], float(jump.upper), spacing) if SS else float(jump.upper),
    ]
    roots = []
    p_cache = {}

    def maker(e):
        def F(T):
            key = ctx.prec
            if key not in p_cache:
                p_cache[key] = _Pendulum(mm, SS, D)
            return p_cache[key].half(T)[e]

        def dF(T):
            key = ctx.prec
            if key not in p_cache:
                p_cache[key] = _Pendulum(mm, SS, D)
            return p_cache[key].half_dT(T)[1][e]

        return F, dF

    for name, x0 in zip(names, approx, strict=True):
        F, dF = maker(_ENTRY[name])
        root = certified_root(F, dF, x0, bits=bits)
        roots.append(root.ball)
    swap = roots[1] < roots[0]
    if swap:
        roots = roots[::-1]
        names = names[::-1]
    lo, hi = roots
    if not (lo < hi) and not (lo.overlaps(hi)):  # pragma: no cover - ordered above
        raise CertificationError("the edges could not be ordered")
    with ctx.workprec(bits + 20):
        # the ramps must fit the phases at the edge (the shorter period is the stricter)
        if not (_A(SS) <= _A(min(D, 1 - D)) * lo):
            _check_fits(SS, Fraction(float(lo.mid())), D)
        jl, ju = _ball(jump.lower, rad[0]), _ball(jump.upper, rad[1])
        dl = (lo - jl) + _ball(jump.delta_lower, rad[2])
        du = (hi - ju) + _ball(jump.delta_upper, rad[3])
    with mpmath.workdps(d + 10):
        vals = [to_mpf(x) for x in (lo, hi, dl, du)]
        radii = tuple(upper_mpf(arb(x.rad())) for x in (lo, hi, dl, du))
    notes = [
        f"linear ramps of the length lasting S = {_text(SS)} T0 at each switch "
        f"(S = 0: the jump model); edges are the zeros of {names[0]} and {names[1]} "
        "of the half-period map, followed from the jump model's edges",
    ]
    if lo.overlaps(hi):
        notes.append("the two edges could not be separated at this precision")
    b = Boundary(
        order=n,
        m=mm,
        Q=None,
        damping="exact",
        digits=d,
        method="certified",
        exists=True,
        lower=vals[0],
        upper=vals[1],
        delta_lower=vals[2],
        delta_upper=vals[3],
        radius=max(radii),
        lower_enclosure=(to_mpf(lo) - radii[0], to_mpf(lo) + radii[0]),
        upper_enclosure=(to_mpf(hi) - radii[1], to_mpf(hi) + radii[1]),
        certified=True,
        regime=f"ramp modulation, S = {_text(SS)}, Bessel route",
        notes=tuple(notes),
        radii=radii,
        system=sysv,
    )
    jl_b, ju_b = _ball(jump.lower, rad[0]), _ball(jump.upper, rad[1])
    if swap:
        jl_b, ju_b = ju_b, jl_b
    return RampEdges(n, mm, SS, D, lo, hi, jl_b, ju_b, tuple(names), b)


def _text(x: Fraction) -> str:
    return str(x.numerator) if x.denominator == 1 else f"{x.numerator}/{x.denominator}"


def leading_shift(order, m, *, duty="1/2", digits=20) -> tuple[arb, arb]:
    """``dT/dS`` at ``S = 0`` of the lower and upper edge (balls), from the derived first-order
    defect ``E`` (:func:`analytic.ramp.first_order_defect`): ``-[U2 E U1]_e / (dG0_e/dT)`` at
    the jump model's certified edge, ``U1``, ``U2`` the jump model's half-phase maps."""
    n = as_order(order)
    D = as_system("pendulum", duty).duty
    mm = exact_fraction(as_depth(m))
    d = as_digits(digits)
    jump = _jump(n, mm, D, d + 10)
    rad = jump.radii or (jump.radius,) * 4
    out = []
    with ctx.workprec(bits_for_digits(d + 10)):
        p = _Pendulum(mm, Fraction(0), D)
        E = tuple(_compiled()["E"](p.l1, p.l2, p.g))
        edges = (_ball(jump.lower, rad[0]), _ball(jump.upper, rad[1]))
        names = _factors(p, n, *edges)
        for name, T in zip(names, edges, strict=True):
            e = _ENTRY[name]
            U1 = p.U1(p.D * T / 2)
            U2 = p.U2((1 - p.D) * T / 2)
            num = _mul(U2, _mul(E, U1))[e]
            _, dG = p.half_dT(T)
            out.append(-num / dG[e])
    return tuple(out)


# ---------------------------------------------------------------------------------------------
# validity of the jump model


@dataclass(frozen=True)
class Validity:
    """The answer of :func:`jump_validity`."""

    order: int
    m: Fraction
    duty: Fraction
    tol: Fraction
    S_ok: Fraction | None
    S_bad: Fraction | None
    S_fit: float
    slopes: tuple
    table: tuple
    notes: tuple = ()
