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
* :func:`ramp_closing`: a closing of an odd-order interval with ramps of a fixed ``S``: two
  depths at which the zeros of ``G11`` and ``G22`` are proven distinct and in opposite order, so
  that the two edges cross in between, where ``G11 = G22 = 0`` and hence ``M = -I`` exactly
  (:func:`analytic.ramp.half_period_factorisation`: with ``det G = 1`` and ``G11 = G22 = 0``,
  ``M = P G^-1 P G = -I``): the interval has zero width there.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from fractions import Fraction
from functools import cache, lru_cache

import mpmath
from flint import arb, ctx, fmpq

from .certify import CertificationError, bits_for_digits, certified_root, to_mpf, upper_mpf
from .inputs import InputError, as_depth, as_digits, as_order, as_switch_time, as_system
from .params import exact_fraction

__all__ = [
    "as_switch_time",
    "check_fits",
    "longest_ramp",
    "ramp_monodromy_arb",
    "ramp_half_map",
    "ramp_boundary",
    "ramp_chart",
    "leading_shift",
    "RampEdges",
    "jump_validity",
    "Validity",
    "RampClosing",
    "ramp_closing",
]

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
    function returning four entries (row-major), from their stored texts
    (:mod:`verify.switch_forms`)."""
    from .switch_forms import load

    return load("ramp", _NAMESPACE, _derived)


def _derived():
    """The functions of :func:`_compiled`, compiled now from the derivation (imports sympy)."""
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
            args,
            list(exprs),
            modules=[_NAMESPACE],
            printer=_printer(),
            cse=True,
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
            self.down = self._up = (one, nil, nil, one)
        else:
            self.down = tuple(f["ramp"](self.l1, self.l2, self.S, self.g, pi))
            self._up = None  # only the period map needs it (the edges need G alone)
        self.A1 = tuple(f["A"](self.l1, self.g))
        self.A2 = tuple(f["A"](self.l2, self.g))
        self._plateau = f["plateau"]

    @property
    def up(self):
        """The ramp up's map (computed on first use)."""
        if self._up is None:
            pi = arb.pi()
            self._up = tuple(_compiled()["ramp"](self.l2, self.l1, self.S, self.g, pi))
        return self._up

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


@lru_cache(maxsize=64)
def _pendulum_at(m: Fraction, S: Fraction, duty: Fraction, prec: int) -> _Pendulum:
    """:class:`_Pendulum` at the precision ``prec``, kept for the next caller: the two edges of
    an interval are followed to the same switching times (one ramp map, its Bessel functions
    evaluated once)."""
    with ctx.workprec(prec):
        return _Pendulum(m, S, duty)


def check_fits(S: Fraction, T: Fraction, duty: Fraction, where: str = "") -> None:
    """Refuse ``S > min(D, 1 - D) T``: a ramp longer than the shorter phase."""
    longest = min(duty, 1 - duty) * T
    if S > longest:
        at = where or f"at T/T0 = {float(T):.6g}"
        raise InputError(
            f"switching time S = {_text(S)} is longer than a phase: {at} and duty D = "
            f"{_text(duty)} the allowed range is 0 <= S <= min(D, 1-D) T = {float(longest):.6g}"
        )


def ramp_monodromy_arb(m, tau, S, duty=Fraction(1, 2)):
    """The period map of ``(phi, phi')`` over ``T = tau T0`` from ``t = S/2``, as four ``arb``
    balls at the working precision (``flint.ctx.prec``); ``m``, ``tau``, ``S``, ``duty`` exact
    Fractions with ``0 <= S <= min(D, 1 - D) tau``.  At ``S = 0`` it is the jump model's
    :func:`verify.floquet.monodromy_arb`."""
    m, tau, S, duty = (Fraction(v) for v in (m, tau, S, duty))
    check_fits(S, tau, duty)
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

    def _repr_html_(self) -> str:
        """The certified edges as the command line prints them (every certified digit)."""
        from paramres.display import pre_html

        return pre_html(self.boundary if self.boundary is not None else self)

    @property
    def shifts(self) -> tuple[arb, arb]:
        return self.lower - self.jump_lower, self.upper - self.jump_upper


_ENTRY = {"G11": 0, "G12": 1, "G21": 2, "G22": 3}


def _jump(order: int, m: Fraction, duty: Fraction, digits: int):
    from .certified import boundary

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


#: the largest step of the continuation in S, and the largest Newton correction accepted after
#: the predictor, as fractions of the order's spacing T_upper/n
_STEP, _CORRECTION = 40, 100


def _follow(
    m, S, duty, e, T0: float, spacing: float, bits: int = 96, start=None, trail=None
) -> float:
    """Continue the zero of entry ``e`` of ``G`` from ``S = 0`` (at ``T0``) to ``S``: secant
    predictor, Newton corrector; steps of at most ``spacing/40`` in ``S``, halved whenever the
    corrector moves the root by more than ``spacing/100`` or does not converge (so the path
    cannot jump to another zero of the same entry).  ``start = (s, T, slope)``: continue from a
    point of the same path already followed (``s <= S``) instead of from ``S = 0``; the end
    point is appended to the list ``trail`` in that form."""
    with ctx.workprec(bits):
        s_now, T_now, slope = (Fraction(0), T0, 0.0) if start is None else start
        cap = Fraction(spacing / _STEP)
        step = min(S, cap)
        while s_now < S:
            s_next = min(S, s_now + step)
            guess = T_now + slope * float(s_next - s_now)
            p = _pendulum_at(m, s_next, duty, ctx.prec)
            root = _newton_mid(p, e, guess)
            if root is None or abs(root - guess) > spacing / _CORRECTION:
                step = step / 2
                if step < S * Fraction(1, 2**40):
                    raise CertificationError(
                        f"the edge could not be followed to S = {_text(S)} (it may turn back "
                        "or leave the window)"
                    )
                continue
            ds = float(s_next - s_now)
            if ds > 0:  # a step below the smallest double (S = 1e-400) keeps the slope it had
                slope = (root - T_now) / ds
            s_now, T_now = s_next, root
            step = min(step * 2, cap, S)
        if trail is not None:
            trail.append((s_now, T_now, slope))
        return T_now


class _Paths:
    """Both followed edges of one ``(n, m, D)`` at many ``S``: each call continues from the
    largest ``S`` already reached below it (the same continuation, in pieces)."""

    def __init__(self, n, mm, D, jump, names):
        self.args = (mm, D)
        self.names = tuple(names)
        self.spacing = float(jump.upper) / n
        self.starts = ((_ENTRY[names[0]], float(jump.lower)), (_ENTRY[names[1]], float(jump.upper)))
        self.known = ([], [])  # per edge: (s, T, slope), s ascending

    def edges(self, S: Fraction) -> tuple[float, float]:
        """The two followed zeros at ``S``, ascending."""
        out = self.each(S)
        return min(out), max(out)

    def each(self, S: Fraction) -> list[float]:
        """The followed zeros of the entries :attr:`names` at ``S``, in that order."""
        mm, D = self.args
        out = []
        for (e, T0), known in zip(self.starts, self.known, strict=True):
            if S == 0:
                out.append(T0)
                continue
            below = [k for k in known if k[0] <= S]
            start = max(below, key=lambda k: k[0]) if below else None
            out.append(_follow(mm, S, D, e, T0, self.spacing, start=start, trail=known))
            known.sort(key=lambda k: k[0])
        return out


def ramp_chart(order, m, S_values, *, duty="1/2", digits=30) -> list[RampEdges]:
    """:func:`ramp_boundary` at each switching time of ``S_values``, the jump model's edges
    computed once and each edge followed in ``S`` once (each ``S`` continues from the largest
    one already reached below it)."""
    n = as_order(order)
    D = as_system("pendulum", duty).duty
    mm = exact_fraction(as_depth(m))
    d = as_digits(digits)
    jump = _jump(n, mm, D, max(d, 20) + 5)
    paths = _paths(n, mm, D, jump)
    return [
        ramp_boundary(n, mm, S, duty=D, digits=d, _jump_result=jump, _followed=paths)
        for S in S_values
    ]


def ramp_boundary(
    order, m, S, *, duty="1/2", digits=30, _jump_result=None, _followed=None
) -> RampEdges:
    """The certified edges of the ``order``-th interval with linear ramps of duration ``S``
    (``0 <= S <= min(D, 1 - D) T`` at the lower edge; a longer ramp is refused).  ``_followed``:
    the followed edges of the same jump result (:class:`_Paths`), continued to ``S`` instead of
    following each edge from ``S = 0``."""
    from .result import from_balls

    n = as_order(order)
    sysv = as_system("pendulum", duty)
    D = sysv.duty
    mm = exact_fraction(as_depth(m))
    SS = as_switch_time(S)
    d = as_digits(digits)
    jump = _jump(n, mm, D, max(d, 20) + 5) if _jump_result is None else _jump_result
    rad = jump.radii or (jump.radius,) * 4
    bits = bits_for_digits(d + 5)
    T_scale = float(jump.upper)
    c = min(D, 1 - D)
    if SS > c * Fraction(float(jump.lower)) / 2:
        # a long ramp: first make sure it fits a phase at the lower edge (where T is least)
        S_fit = longest_ramp(n, mm, duty=D, _jump_result=jump, _followed=_followed)
        if SS > Fraction(S_fit) * (1 + Fraction(1, 10**9)):
            raise InputError(
                f"switching time S = {_text(SS)} is longer than a phase: at the lower edge of "
                f"order {n} (m = {_text(mm)}, duty D = {_text(D)}) the allowed range is "
                f"0 <= S <= min(D, 1-D) T = {S_fit:.6g}"
            )
    with ctx.workprec(bits + 20):
        T_lo0 = _ball(jump.lower, rad[0])
        T_hi0 = _ball(jump.upper, rad[1])
        p0 = _Pendulum(mm, Fraction(0), D)
        names = _factors(p0, n, T_lo0, T_hi0)
    spacing = float(T_scale) / n
    if _followed is not None and _followed.names == tuple(names) and SS:
        approx = _followed.each(SS)
    else:
        approx = [
            _follow(mm, SS, D, _ENTRY[names[0]], float(jump.lower), spacing)
            if SS
            else float(jump.lower),
            _follow(mm, SS, D, _ENTRY[names[1]], float(jump.upper), spacing)
            if SS
            else float(jump.upper),
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
        if not (_A(SS) <= _A(c) * lo):
            check_fits(SS, Fraction(float(lo.mid())), D, f"at the lower edge T/T0 = {lo.mid()}")
        jl, ju = _ball(jump.lower, rad[0]), _ball(jump.upper, rad[1])
        dl = (lo - jl) + _ball(jump.delta_lower, rad[2])
        du = (hi - ju) + _ball(jump.delta_upper, rad[3])
    notes = [
        f"linear ramps of the length lasting S = {_text(SS)} T0 at each switch "
        f"(S = 0: the jump model); edges are the zeros of {names[0]} and {names[1]} "
        "of the half-period map, followed from the jump model's edges",
    ]
    if lo.overlaps(hi):
        notes.append("the two edges could not be separated at this precision")
    b = from_balls(
        (lo, hi, dl, du),
        order=n,
        m=mm,
        Q=None,
        damping="exact",
        digits=d,
        method="certified",
        regime=f"ramp modulation, S = {_text(SS)}, Bessel route",
        system=sysv,
        notes=notes,
    )
    jl_b, ju_b = _ball(jump.lower, rad[0]), _ball(jump.upper, rad[1])
    if swap:
        jl_b, ju_b = ju_b, jl_b
    return RampEdges(n, mm, SS, D, lo, hi, jl_b, ju_b, tuple(names), b)


def _text(x: Fraction) -> str:
    return str(x.numerator) if x.denominator == 1 else f"{x.numerator}/{x.denominator}"


def _paths(n, mm, D, jump, names=None) -> _Paths:
    """The followed edges of the jump model's ``jump`` (a :class:`verify.solve.Boundary`)."""
    if names is None:
        with ctx.workprec(96):
            rad = jump.radii or (jump.radius,) * 4
            names = _factors(
                _Pendulum(mm, Fraction(0), D),
                n,
                _ball(jump.lower, rad[0]),
                _ball(jump.upper, rad[1]),
            )
    return _Paths(n, mm, D, jump, names)


def longest_ramp(order, m, *, duty="1/2", _jump_result=None, _followed=None) -> float:
    """The longest switching time that fits a phase at the lower edge of the ``order``-th
    interval: the ``S`` with ``S = min(D, 1 - D) T_lower(S)`` (a float, by a fixed-point
    iteration on the followed edge; not certified -- the certified edges are checked against
    the condition exactly)."""
    n = as_order(order)
    D = as_system("pendulum", duty).duty
    mm = exact_fraction(as_depth(m))
    jump = _jump(n, mm, D, 20) if _jump_result is None else _jump_result
    paths = _paths(n, mm, D, jump) if _followed is None else _followed
    c = float(min(D, 1 - D))
    S = c * float(jump.lower)
    prev = None  # (S, c T_lower(S) - S) of the last iterate: secant steps on that difference
    for _ in range(60):
        try:
            lo = paths.edges(Fraction(S))[0]
        except CertificationError:
            S *= 0.9
            prev = None
            continue
        new = c * lo
        if abs(new - S) <= 1e-13 * S:
            return min(new, S)
        step = new - S  # the fixed-point step, replaced by the secant's where that is sound
        if prev is not None and prev[1] != step:
            sec = -step * (S - prev[0]) / (step - prev[1])
            if math.isfinite(sec) and abs(sec) <= 4 * abs(step):
                step = sec
        prev = (S, new - S)
        S = S + step
    return S


def leading_shift(order, m, *, duty="1/2", digits=20, _jump_result=None) -> tuple[arb, arb]:
    """``dT/dS`` at ``S = 0`` of the lower and upper edge (balls), from the derived first-order
    defect ``E`` (:func:`analytic.ramp.first_order_defect`): ``-[U2 E U1]_e / (dG0_e/dT)`` at
    the jump model's certified edge, ``U1``, ``U2`` the jump model's half-phase maps."""
    n = as_order(order)
    D = as_system("pendulum", duty).duty
    mm = exact_fraction(as_depth(m))
    d = as_digits(digits)
    jump = _jump(n, mm, D, d + 10) if _jump_result is None else _jump_result
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
    """The answer of :func:`jump_validity`.

    ``S_ok``: a switching time at which both certified ramp edges are proven within ``tol``
    (relative) of the jump model's edges; ``S_bad``: one (the next decimal up) at which an edge
    is proven to have moved by more than ``tol`` (``None``: every ramp that fits a phase keeps
    the edges within ``tol``; then ``S_ok`` is that longest ramp, rounded down).  ``S_fit`` the
    longest ramp that fits a phase at the lower edge.  ``slopes``: the derived ``dT/dS`` at
    ``S = 0`` of the lower and upper edge (balls).  ``table``: rows ``(S, shift_lower,
    shift_upper)`` of certified shifts ``T(S) - T(0)`` (balls), including ``S_ok`` and
    ``S_bad``."""

    order: int
    m: Fraction
    duty: Fraction
    tol: Fraction
    jump_lower: arb
    jump_upper: arb
    S_ok: Fraction
    S_bad: Fraction | None
    S_fit: float | None
    slopes: tuple
    table: tuple
    notes: tuple = ()

    def _rel(self, shift: arb, T: arb) -> float:
        return float((abs(shift) / T).mid())

    def as_json(self) -> dict:
        def num(x: arb, k=10):
            return mpmath.nstr(to_mpf(x), k) if not x.contains(0) or x.rad() == 0 else "0"

        return {
            "order": self.order,
            "m": _text(self.m),
            "duty": _text(self.duty),
            "tolerance": str(self.tol),
            "jump_lower": num(self.jump_lower, 15),
            "jump_upper": num(self.jump_upper, 15),
            "S_within": _decimal(self.S_ok),
            "S_exceeded": None if self.S_bad is None else _decimal(self.S_bad),
            "S_longest_fitting": f"{self.S_fit:.6g}",
            "slope_lower": _ball_text(self.slopes[0]),
            "slope_upper": _ball_text(self.slopes[1]),
            "shifts": [
                {
                    "S": _decimal(S),
                    "lower": _ball_text(a),
                    "upper": _ball_text(b),
                    "rel_lower": f"{self._rel(a, self.jump_lower):.3e}",
                    "rel_upper": f"{self._rel(b, self.jump_upper):.3e}",
                }
                for S, a, b in self.table
            ],
            "certified": True,
            "notes": list(self.notes),
        }

    def __str__(self) -> str:
        head = (
            f"order {self.order}, m = {_text(self.m)}, duty D = {_text(self.duty)}, "
            f"no friction: jump-model edges T-/T0 = {_ball_text(self.jump_lower, 15)}, "
            f"T+/T0 = {_ball_text(self.jump_upper, 15)}"
        )
        tol = mpmath.nstr(mpmath.mpf(self.tol.numerator) / self.tol.denominator, 6)
        if self.S_bad is None:
            answer = (
                f"  every ramp that fits a phase (S <= {self.S_fit:.6g} T0) keeps both edges "
                f"within {tol} (relative) of the jump model's; proven at S = "
                f"{_decimal(self.S_ok)}"
            )
        else:
            answer = (
                f"  the jump model's edges hold to {tol} (relative) for switching times up to "
                f"S = {_decimal(self.S_ok)} T0 (proven there); at S = {_decimal(self.S_bad)} "
                "an edge has moved by more (proven)"
            )
        lead = "  leading behaviour: " + ", ".join(
            f"T{sign}(S) = T{sign}(0) {_slope_text(a)}"
            for sign, a in zip("-+", self.slopes, strict=True)
        )
        rows = ["      S/T0        T-(S) - T-(0)   rel.        T+(S) - T+(0)   rel."]
        for S, a, b in self.table:
            rows.append(
                f"  {_decimal(S):>10}  {_ball_text(a, 6):>14}  "
                f"{self._rel(a, self.jump_lower):9.2e}  {_ball_text(b, 6):>14}  "
                f"{self._rel(b, self.jump_upper):9.2e}"
            )
        tail = "  [certified: the shifts are differences of proven enclosures (ball arithmetic)]"
        notes = [f"  note: {x}" for x in self.notes]
        return "\n".join([head, answer, lead, *rows, tail, *notes])

    def _repr_html_(self) -> str:
        """The printed text in a notebook (every certified digit)."""
        from paramres.display import pre_html

        return pre_html(self)


def _ball_text(x: arb, k: int = 10) -> str:
    """``x`` with at most ``k`` digits, only those its radius proves (``0`` if it holds 0)."""
    from .result import proven_text

    with mpmath.workdps(k + 20):
        return proven_text(to_mpf(x), upper_mpf(arb(x.rad())), k)


def _slope_text(a: arb) -> str:
    if a.contains(0):
        return f"+ 0*S + (higher powers of S)   [dT/dS = 0 within {float(a.rad()):.1e}]"
    t = _ball_text(a, 8)
    sign = "-" if t.startswith("-") else "+"
    return f"{sign} {t.lstrip('-')} S + O(S^2)"


def _decimal(x: Fraction) -> str:
    for places in range(40):
        scaled = x * 10**places
        if scaled.denominator == 1:
            digits = str(abs(scaled.numerator)).rjust(places + 1, "0")
            body = digits if places == 0 else f"{digits[:-places]}.{digits[-places:]}"
            return ("-" if x < 0 else "") + body
    return _text(x)


def _round_decimal(x: float, sig: int, up: bool) -> Fraction:
    """``x > 0`` rounded to ``sig`` significant decimal digits, down or up, exactly."""
    e = math.floor(math.log10(x)) - sig + 1
    unit = Fraction(10) ** e
    q = Fraction(x) / unit
    k = math.ceil(q) if up else math.floor(q)
    return max(k, 1) * unit


#: the smallest tolerance of :func:`jump_validity`: the crossing is located on the followed edges,
#: which are doubles (a relative shift below about 1e-15 is not resolved)
JUMP_TOL_LOW = Fraction(1, 10**12)
#: the duty of :func:`jump_validity` keeps ``min(D, 1 - D)`` at least this: the longest ramp
#: ``S <= min(D, 1 - D) T`` is a double in the search
JUMP_DUTY_LOW = Fraction(1, 10**300)


def jump_validity(order, m, tol, *, duty="1/2", digits=15, fit=True) -> Validity:
    """The largest switching time ``S`` for which both edges of the ``order``-th interval with
    ramps stay within the relative tolerance ``tol`` of the jump model's edges.

    The crossing ``|T(S) - T(0)| = tol T(0)`` is located on the followed (float) edges, then
    bracketed by two 3-digit decimals ``S_ok < S_bad`` at which certified edges prove ``within``
    and ``beyond``; the shifts at ``S_ok/8, S_ok/4, S_ok/2`` are certified too.  That no larger
    ``S`` below ``S_bad`` comes back within ``tol`` rests on the shift growing with ``S``
    (observed, not proven).  ``fit=False``: :attr:`Validity.S_fit` is computed only where the
    search comes near the longest ramp (else ``None``); the answer is the same."""
    from .inputs import as_number, as_tolerance

    n = as_order(order)
    D = as_system("pendulum", duty).duty
    mm = exact_fraction(as_depth(m))
    checked = as_tolerance(tol)  # the range check; the bound proven is the exact tolerance asked
    if isinstance(tol, mpmath.mpf):
        tt = exact_fraction(checked)
    else:
        tt = as_number(tol, name="tolerance", allowed="1e-12 to 0.1")
    if tt < JUMP_TOL_LOW:
        raise InputError(
            f"tolerance {tol} is outside the allowed range 1e-12 to 0.1 of the jump-model "
            "validity (the crossing is located on double-precision edges)"
        )
    if min(D, 1 - D) < JUMP_DUTY_LOW:
        raise InputError(
            f"duty D = {duty} is outside the allowed range 1e-300 <= D <= 1 - 1e-300 of the "
            "jump-model validity (the ramp's length is searched in double precision)"
        )
    d = as_digits(digits)
    jump = _jump(n, mm, D, d + 10)
    with ctx.workprec(96):
        rad = jump.radii or (jump.radius,) * 4
        names = _factors(
            _Pendulum(mm, Fraction(0), D), n, _ball(jump.lower, rad[0]), _ball(jump.upper, rad[1])
        )
    T0s = (float(jump.lower), float(jump.upper))
    paths = _paths(n, mm, D, jump, names)
    S_fit = longest_ramp(n, mm, duty=D, _jump_result=jump) if fit else None
    tolf = float(tt)
    c_fit = float(min(D, 1 - D))

    def below_cap(x: float) -> bool:
        """``x <= S_fit (1 - 1e-9)`` (the search's cap).  Without ``S_fit``: a ramp of ``y = x/(1
        - 1e-9)`` that fits a phase at the followed lower edge with room to spare (``c T_lo(y) >=
        y (1 + 1e-6)``) is below the longest one, ``S = c T_lo(S)`` (the same premise as
        :func:`longest_ramp`: ``c T_lo(S) - S`` decreases, ``|dT/dS| < 1/c``); where that is not
        clear, ``S_fit`` is computed."""
        nonlocal S_fit
        if S_fit is None:
            y = x / (1 - 1e-9)
            try:
                if c_fit * paths.edges(Fraction(y))[0] >= y * (1 + 1e-6):
                    return True
            except CertificationError:
                pass
            S_fit = longest_ramp(n, mm, duty=D, _jump_result=jump)
        return x <= S_fit * (1 - 1e-9)

    def cap() -> float:
        nonlocal S_fit
        if S_fit is None:
            S_fit = longest_ramp(n, mm, duty=D, _jump_result=jump)
        return S_fit * (1 - 1e-9)

    def excess(S: float) -> float:
        lo, hi = paths.edges(Fraction(S))
        return max(abs(lo - T0s[0]) / T0s[0], abs(hi - T0s[1]) / T0s[1]) - tolf

    slopes = leading_shift(n, mm, duty=D, digits=d, _jump_result=jump)
    rate = max(abs(float(a.mid())) / T for a, T in zip(slopes, T0s, strict=True))
    notes = []
    # S = min(tol/rate, S_cap/2), the cap S_cap = S_fit (1 - 1e-9) computed only if needed
    if rate > 0 and below_cap(2 * (tolf / rate)):
        S = tolf / rate
    else:
        S = min(tolf / rate, cap() / 2) if rate > 0 else cap() / 2
    lo_S, hi_S = 0.0, None
    f_lo, f_hi = -tolf, None  # the excess at lo_S (at S = 0 the edges are the jump's)
    while hi_S is None:
        f = excess(S)
        if f > 0:
            hi_S, f_hi = S, f
        else:
            lo_S, f_lo = S, f
            if below_cap(2 * S):  # then S < S_cap: the doubling as below
                S = 2 * S
                continue
            if S >= cap():
                break
            S = min(2 * S, cap())
    if hi_S is not None:
        # the Illinois (regula falsi) iteration on the excess, nearly linear in S (the shift
        # grows like S dT/dS), down to a bracket of 1e-6 relative
        side = 0
        for _ in range(60):
            mid = hi_S - f_hi * (hi_S - lo_S) / (f_hi - f_lo)
            if not lo_S < mid < hi_S:
                mid = (lo_S + hi_S) / 2
            f = excess(mid)
            if f > 0:
                hi_S, f_hi = mid, f
                if side == 1:
                    f_lo /= 2
                side = 1
            else:
                lo_S, f_lo = mid, f
                if side == -1:
                    f_hi /= 2
                side = -1
            if hi_S - lo_S <= 1e-6 * hi_S:
                break
    crossing = lo_S if hi_S is None else hi_S

    def certified(S: Fraction):
        r = ramp_boundary(n, mm, S, duty=D, digits=d, _jump_result=jump, _followed=paths)
        a, b = r.shifts
        by_name = dict(zip(r.factors, (a, b), strict=True))
        jl, ju = r.jump_lower, r.jump_upper
        if r.factors != names:  # the edges swapped order: report by the jump model's edges
            a, b = by_name[names[0]], by_name[names[1]]
            jl, ju = ju, jl
        return (
            a,
            b,
            (abs(a) <= _A(tt) * jl and abs(b) <= _A(tt) * ju),
            (abs(a) > _A(tt) * jl or abs(b) > _A(tt) * ju),
        )

    table = []
    S_ok = S_bad = None
    with ctx.workprec(bits_for_digits(d + 10)):
        jl_b, ju_b = _ball(jump.lower, rad[0]), _ball(jump.upper, rad[1])
        for sig in (3, 4, 6, 8):
            if hi_S is None:
                ok = _round_decimal(crossing, sig, up=False)
                a, b, within, _ = certified(ok)
                if within:
                    S_ok, S_bad = ok, None
                    table.append((ok, a, b))
                    break
                continue
            ok = _round_decimal(crossing, sig, up=False)
            bad = _round_decimal(crossing, sig, up=True)
            if bad == ok:
                bad = ok + Fraction(10) ** (math.floor(math.log10(crossing)) - sig + 1)
            a, b, within, _ = certified(ok)
            a2, b2, _, beyond = certified(bad)
            if within and beyond:
                S_ok, S_bad = ok, bad
                table.extend([(ok, a, b), (bad, a2, b2)])
                break
        if S_ok is None:
            raise CertificationError(
                f"the crossing of the tolerance near S = {crossing:.6g} could not be proven"
            )
        for k in (8, 4, 2):
            S = S_ok / k
            a, b, within, _ = certified(S)
            if not within:  # pragma: no cover - the shift grows with S in every case seen
                notes.append(f"at S = {_decimal(S)} an edge is already beyond the tolerance")
            table.insert(len(table) - (1 if S_bad is None else 2), (S, a, b))
    return Validity(
        n, mm, D, tt, jl_b, ju_b, S_ok, S_bad, S_fit, slopes, tuple(table), tuple(notes)
    )


# ---------------------------------------------------------------------------------------------
# closings with ramps


@dataclass(frozen=True)
class RampClosing:
    """A closing of the ``order``-th interval with ramps of duration ``S``: the depth ``m*`` at
    which the two edges meet lies in ``[m_lo, m_hi]`` (``factors_lo``/``factors_hi``: the
    entries of ``G`` whose zeros are the lower and upper edge at ``m_lo``, ``m_hi``: opposite
    orders, each pair of edges proven disjoint); ``T_approx``: the mean of the four edges at the
    two depths (a float, not an enclosure of the closing's period)."""

    order: int
    S: Fraction
    m_lo: Fraction
    m_hi: Fraction
    factors_lo: tuple
    factors_hi: tuple
    T_approx: float
    proven: str = (
        "the edges at m_lo and at m_hi are certified and proven disjoint, in opposite orders; "
        "at the crossing in between G11 = G22 = 0, so M = -I exactly (zero width). Not proven: "
        "that the zeros compared at the two depths lie on the same two continuous branches "
        "(each is followed from the jump model's edge by continuation in S)"
    )


def ramp_closing(order, S, m_lo, m_hi, *, tol="1e-10", digits=25) -> RampClosing:
    """Bisect the depth between ``m_lo`` and ``m_hi`` (at which the edges of the odd
    ``order``-th interval with ramps of duration ``S`` come in opposite orders) down to a
    bracket of width ``tol``; every comparison is one of proven-disjoint certified edges."""
    n = as_order(order)
    if n % 2 == 0:
        raise InputError(f"order n = {n}: closings with ramps are searched for odd orders only")
    SS = as_switch_time(S)
    a, b = (exact_fraction(as_depth(x)) for x in (m_lo, m_hi))
    width = exact_fraction(as_depth(tol)) if not isinstance(tol, Fraction) else tol

    def side(m: Fraction):
        r = ramp_boundary(n, m, SS, digits=digits)
        if not r.lower.upper() < r.upper.lower():
            return None, r
        return r.factors, r

    fa, ra = side(a)
    fb, rb = side(b)
    if fa is None or fb is None or fa == fb:
        raise CertificationError(
            f"the edges at m = {_text(a)} and m = {_text(b)} are not proven to come in opposite "
            "orders"
        )
    while b - a > width:
        mid = (a + b) / 2
        # a short decimal-like point near the middle keeps the fractions small
        mid = Fraction(round(mid * 10**14), 10**14) if (b - a) > Fraction(1, 10**12) else mid
        fm, rm = side(mid)
        if fm is None:
            break
        if fm == fa:
            a, ra = mid, rm
        else:
            b, rb, fb = mid, rm, fm
    T = float((ra.lower + ra.upper + rb.lower + rb.upper).mid()) / 4
    return RampClosing(n, SS, a, b, fa, fb, T)
