"""Certified boundaries of one interval of instability, to any number of digits.

:func:`boundary` returns the lower and upper edge ``T/T0`` of the ``n``-th interval at depth ``m``
(with friction ``Q`` in either damping model), each as an mpmath number whose digits are proven:
the value comes from a ball (python-flint ``arb``) that contains the exact edge, and the ball's
radius is below the accuracy asked for.  How each edge is found and proven:

**The unknown.**  ``theta = x - n pi/2`` with ``x = omega_av T/2`` (the paper's ``omega_av Delta
T/2``, eqs. 15, 26), so ``T/T0 = (n/2 + theta/pi)/w``; ``delta = theta/(pi w)`` is the offset from
the exact tuning ``n T_av/2`` and keeps its digits even where it is ``1e-24`` (even orders at ``m =
1e-12``).

**No friction** (any model): the two per-edge equations ``sin(theta) + k r f(beta (n pi/2 + theta))
= 0`` (:func:`verify.derived.edge_equation`; ``k = +-1`` picks the edge) each have exactly one root
in ``(-pi/2, pi/2)``, and it is simple (the window theorem, ``docs/theory.md``), also where the
interval closes.  Each root is found by Halley's method in floats, refined by Newton in ``arb`` with
the precision doubled every step, and proven by interval Newton
(:func:`verify.certify.certified_root`). The lower edge is the smaller root.  No solver can reach
another interval's edge: the window holds one root of each equation and the iteration is kept inside
the bracket it has seen.

**Friction, normal form** (paper model; exact model with both halves under-damped): ``D(theta) =
R(theta) - sin^2(theta)`` (:func:`verify.derived.indicator`) is positive exactly inside the
interval.  ``D`` is at most its friction-free value ``D0`` (same ``r``, ``beta``), which is negative
outside the two undamped roots ``[a, b]``; so the interval lies in ``[a, b]``.  There ``D`` is
maximised (root of ``D'``); no interval if the maximum is ``<= 0``, else the edges are the zeros of
``D`` left and right of the maximiser, each proven by interval Newton.  The *shape* -- ``D < 0`` on
``[a, lower)``, ``D > 0`` between the edges, ``D < 0`` on ``(upper, b]`` -- is proven too
(:func:`verify.certify.prove_sign` on sub-intervals, with monotone neighbourhoods of the edges), so
the two zeros are the edges and nothing in between is missed.  Non-existence is proven the same way
(``D < 0`` on all of ``[a, b]``).

**Friction, trace form** (exact model, a half critically or over-damped, ``4 Q^2 <= 1 + m``, or half
1 within :data:`verify.params.NEAR_CRITICAL` of it, where the normal form degenerates): ``D(zeta) =
sigma (2 C1 C2 - kappa S1 S2) - 2 cosh(2 zeta)`` in ``zeta = gamma T/2``
(:func:`verify.derived.trace_indicator`).  With half 2 under-damped, ``2 C1 C2 - kappa S1 S2 = rho
cos(Phi)`` with the phase ``Phi = nu2 zeta + atan2(kappa S1, 2 nu2 C1)``, which increases strictly
with ``T``; ``D > 0`` needs ``sigma cos(Phi) > 0``, so the ``n``-th interval lies where ``|Phi - n
pi| < pi/2`` (this numbers the orders continuously with the normal form).  With both halves
over-damped there is no rotation: only ``n = 1`` can exist, where ``P < 0``.  Inside the window the
same maximise-and-bracket scheme as above is proven.

The float stage shares its code with the vectorised grid (:mod:`verify.grid`).  ``method=`` selects
a solver from :data:`METHODS` (``"certified"``, the default; ``"fixedpoint"``, the paper's own
iteration, uncertified, see :mod:`verify.fixedpoint`); new methods register there.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass, field, fields
from fractions import Fraction
from functools import partial

import mpmath
import numpy as np
from flint import arb, ctx

from analytic.system import PAPER, System

from .certify import (
    CertificationError,
    Jet,
    Root,
    ball,
    bits_for_digits,
    certified_root,
    prove_sign,
    to_mpf,
    upper_mpf,
)
from .derived import (
    backend,
    edge_equation,
    indicator,
    near_one_forms,
    order1_forms,
    trace_indicator,
    trace_window,
)
from .inputs import (
    InputError,
    as_damping,
    as_depth,
    as_digits,
    as_order,
    as_quality,
    as_system,
    as_tolerance,
)
from .params import NormalParams, exact_fraction, form_for, normal_params, trace_params

__all__ = [
    "Boundary",
    "Request",
    "boundary",
    "METHODS",
    "register_method",
    "CertificationError",
    "proven_text",
    "hump_normal",
    "hump_trace",
    "float_edges",
    "hump_box",
    "depth_ball",
    "trace_phase",
    "prove_no_window",
]

_ARB = backend("arb")
_MATH = backend("math")


# ---------------------------------------------------------------------------------------------
# the result


@dataclass(frozen=True)
class Request:
    """A checked request: order, exact depth and quality factor, model, digits."""

    order: int
    m: Fraction
    Q: Fraction | None
    damping: str
    digits: int
    m_input: object = None
    #: relative tolerance of ``T/T0`` for ``method="auto"`` (:mod:`verify.auto`)
    tol: object = None
    #: the member of the family (:mod:`analytic.system`); the paper's pendulum by default
    system: System = PAPER

    @property
    def parity_sign(self) -> int:
        return -1 if self.order % 2 else 1


@dataclass(frozen=True)
class Boundary:
    """The ``order``-th interval of instability at depth ``m``: edges ``lower < upper`` in ``T/T0``.

    ``lower``/``upper`` are mpmath numbers (``None`` if the interval does not exist);
    ``delta_lower``/``delta_upper`` are ``T - n T_av/2`` in units of ``T0`` (``T_av`` of eq. 5, the
    undamped average period); ``radius`` bounds ``|returned - exact|`` for all four numbers
    (``T/T0`` units; ``None`` if not certified); ``lower_enclosure``/``upper_enclosure`` are proven
    ``(low, high)`` bounds of each edge.  ``method`` names the solver, ``regime`` the
    equations used.
    """

    order: int
    m: Fraction
    Q: Fraction | None
    damping: str
    digits: int
    method: str
    exists: bool
    lower: mpmath.mpf | None = None
    upper: mpmath.mpf | None = None
    delta_lower: mpmath.mpf | None = None
    delta_upper: mpmath.mpf | None = None
    radius: mpmath.mpf | None = None
    lower_enclosure: tuple | None = None
    upper_enclosure: tuple | None = None
    certified: bool = False
    regime: str = ""
    notes: tuple = field(default=())
    #: proven radii of ``lower, upper, delta_lower, delta_upper`` (for printing only proven digits)
    radii: tuple | None = field(default=None, repr=False)
    #: the member of the family (:mod:`analytic.system`)
    system: System = PAPER

    @property
    def width(self) -> mpmath.mpf | None:
        """``upper - lower`` (``T/T0``), from the deltas so that tiny widths keep their digits."""
        if not self.exists:
            return None
        with mpmath.workdps(self.digits + 10):
            return self.delta_upper - self.delta_lower

    def _fmt(self, x, k: int | None = None) -> str:
        if x is None:
            return "-"
        rad = None if self.radii is None or k is None else self.radii[k]
        return proven_text(x, rad, self.digits)

    def error_bound(self) -> str | None:
        """A bound of ``|printed - exact|`` over the four printed numbers (rounding of the print
        included; see :mod:`verify.rounding`), or ``None`` if not certified."""
        from .rounding import bound_text, printed_error

        if not (self.certified and self.exists and self.radius is not None):
            return None
        values = (self.lower, self.upper, self.delta_lower, self.delta_upper)
        bounds = [
            printed_error(self._fmt(x, k), x, self.radius if self.radii is None else self.radii[k])
            for k, x in enumerate(values)
        ]
        return bound_text(max(b for b in bounds if b is not None))

    def as_json(self) -> dict:
        """A JSON-ready dict; numbers as decimal strings with ``digits`` significant digits;
        ``error_bound`` bounds ``|printed - exact|`` for each of them (rounding included),
        ``radius`` is the internal enclosure's (smaller: before rounding)."""
        fmt = lambda x, k: None if x is None else self._fmt(x, k)  # noqa: E731
        return {
            "order": self.order,
            **self.system.as_json(),
            "m": None if self.m is None else _fraction_text(self.m),
            "Q": None if self.Q is None else _fraction_text(self.Q),
            "damping": self.damping if self.Q is not None else "none",
            "digits": self.digits,
            "method": self.method,
            "regime": self.regime,
            "exists": self.exists,
            "lower": fmt(self.lower, 0),
            "upper": fmt(self.upper, 1),
            "delta_lower": fmt(self.delta_lower, 2),
            "delta_upper": fmt(self.delta_upper, 3),
            "radius": None if self.radius is None else mpmath.nstr(self.radius, 3),
            "error_bound": self.error_bound(),
            "certified": self.certified,
            "notes": list(self.notes),
        }

    def __repr__(self) -> str:
        """Every certified digit (the dataclass repr showed mpmath's 15-17)."""
        j = self.as_json()
        return (
            f"Boundary(order={self.order}, m={j['m']}, Q={j['Q']}, damping={j['damping']!r}, "
            f"lower={j['lower']}, upper={j['upper']}, error_bound={j['error_bound']}, "
            f"method={self.method!r})"
        )

    def _repr_html_(self) -> str:
        import html

        return f"<pre>{html.escape(str(self))}</pre>"

    def __str__(self) -> str:
        fr = (
            "no friction"
            if self.Q is None
            else f"Q = {_fraction_text(self.Q)} ({self.damping} model)"
        )
        where = f"m = {_fraction_text(self.m)}, " if self.m is not None else ""
        head = f"order {self.order}, {where}{fr}"
        if not self.system.is_paper:
            head = f"{self.system.label}: {head}"
        off = "T - n T_av/2" if self.system.is_paper else "T - T_n"
        if not self.exists:
            body = "  no interval of instability"
        else:
            body = (
                f"  lower T/T0 = {self._fmt(self.lower, 0)}   "
                f"({off} = {self._fmt(self.delta_lower, 2)})\n"
                f"  upper T/T0 = {self._fmt(self.upper, 1)}   "
                f"({off} = {self._fmt(self.delta_upper, 3)})"
            )
        bound = self.error_bound()
        proof = (
            f"certified: |printed - exact| < {bound}"
            if bound is not None
            else ("certified" if self.certified else "not certified")
        )
        tail = f"  [{self.method}; {self.regime}; {proof}]"
        notes = "".join(f"\n  note: {n}" for n in self.notes)
        return f"{head}\n{body}\n{tail}{notes}"


def proven_text(x: mpmath.mpf, rad, digits: int) -> str:
    """``x`` with at most ``digits`` significant digits, and only as many as the proven radius
    ``rad`` supports (the exact value lies within half a unit of the last digit printed, plus the
    rounding of the print itself).  A value whose enclosure contains zero and is too wide for one
    digit prints as ``"0"`` (e.g. the offset at a closing, which is exactly zero by the closing
    theorem)."""
    if rad is None or rad == 0 or x == 0:
        return mpmath.nstr(x, digits, strip_zeros=False) if x != 0 or rad is None else "0"
    with mpmath.workdps(20):
        ratio = abs(x) / (2 * rad)
        usable = int(mpmath.floor(mpmath.log10(ratio))) if ratio >= 1 else 0
    if usable < 1:
        return "0"
    return mpmath.nstr(x, min(digits, usable), strip_zeros=False)


def _fraction_text(x) -> str:
    if isinstance(x, Fraction):
        return str(x.numerator) if x.denominator == 1 else f"{x.numerator}/{x.denominator}"
    return str(x)


# ---------------------------------------------------------------------------------------------
# dispatch

#: solver name -> function(Request) -> Boundary
METHODS: dict[str, Callable[[Request], Boundary]] = {}


def register_method(name: str):
    """Decorator: make ``fn(request) -> Boundary`` available as ``boundary(..., method=name)``."""

    def deco(fn):
        METHODS[name] = fn
        return fn

    return deco


def boundary(
    order,
    m=None,
    *,
    Q=None,
    damping="exact",
    digits=30,
    method="certified",
    tol=None,
    system="pendulum",
    duty="1/2",
) -> Boundary:
    """The lower and upper boundary ``T/T0`` of the ``order``-th interval of instability.

    ``m`` may be a str (``"3/5"``, ``"0.3"``, ``"1e-12"``: exact), int, Fraction, float (its exact
    binary value) or mpmath mpf.  ``Q`` is the quality factor (``None``: no friction); ``damping``
    ``"exact"`` (the damped oscillator) or ``"paper"`` (the paper's eqs. 28-30).  ``digits``
    significant digits are returned, each one proven (see the module text).  ``method`` picks a
    solver from :data:`METHODS`.  ``tol`` (a relative error of ``T/T0``) instead lets the engine
    pick the cheapest method that provably meets it (``method="auto"``, :mod:`verify.auto`; the
    digits then follow from ``tol``); ``Boundary.method`` says which one it used.

    ``system`` is a member of the family: ``"pendulum"`` (the paper's), ``"torsion"``,
    ``"meissner"``, or a value of :func:`analytic.system.custom` (which has no depth: leave ``m``
    out); ``duty`` is the fraction ``D`` of the period spent in phase 1 (default ``1/2``).
    """
    n = as_order(order)
    sysv = as_system(system, duty)
    mm = as_depth(m) if sysv.uses_depth or m is not None else None
    if not sysv.uses_depth and m is not None:
        raise InputError(f"a custom system has no depth: leave m out (got m = {m!r})")
    QQ = as_quality(Q)
    model = as_damping(damping)
    d = as_digits(digits)
    tt = None
    if tol is not None or method == "auto":
        if method not in ("certified", "auto"):
            raise InputError(f"tol chooses the method itself; it cannot go with {method!r}")
        if tol is None:
            raise InputError("method 'auto' needs a tolerance tol")
        tt, method = as_tolerance(tol), "auto"
    try:
        solver = METHODS[method]
    except KeyError:
        raise InputError(f"method {method!r} is not one of: {', '.join(sorted(METHODS))}") from None
    QF = None if QQ is None else exact_fraction(QQ)
    if sysv.is_paper:
        req = Request(n, exact_fraction(mm), QF, model, d, mm, tt)
    else:
        if method != "certified":
            raise InputError(
                f"method {method!r} is for the paper's system only; {sysv.label} uses 'certified'"
            )
        req = Request(n, None if mm is None else exact_fraction(mm), QF, model, d, mm, tt, sysv)
    return solver(req)


# ---------------------------------------------------------------------------------------------
# parameters at the working precision


class _AtPrecision:
    """Numbers recomputed for every working precision (``flint.ctx.prec``), cached."""

    def __init__(self, make, min_prec: int = 0):
        self._make = make
        self._cache: dict[int, object] = {}
        self._min = min_prec  # e.g. what a depth range needs to keep 1 - m

    def __call__(self):
        prec = ctx.prec
        val = self._cache.get(prec)
        if val is None:
            with ctx.workprec(max(prec, self._min) + 12):
                val = self._make()
            self._cache[prec] = val
        return val


def _sgn(n: int) -> int:
    """``sin(n pi/2)`` for odd ``n``, ``cos(n pi/2)`` for even ``n`` (exact)."""
    return (1 if n % 4 == 1 else -1) if n % 2 else (1 if n % 4 == 0 else -1)


def _theta_scale(theta: float, n: int, bits: int) -> float:
    """What ``theta`` must be accurate relative to: itself (for the offset ``delta``) and
    ``x = n pi/2 + theta`` (for ``T``; small for the lower edge of order 1 as ``m -> 1``)."""
    return max(min(abs(theta), abs(n * math.pi / 2 + theta)), _theta_floor(bits, n))


def _theta_floor(bits: int, n: int) -> float:
    """Absolute scale for a ``theta`` that may be exactly zero (closings):
    ``2**-max(2 bits, 200)`` of ``n pi/2``; above it ``theta`` (and the offset ``delta``) is given
    to full relative accuracy."""
    return math.ldexp(n * math.pi / 2, -max(2 * bits, 200))


# ---------------------------------------------------------------------------------------------
# no friction


def _float_edge(fn, n: int, eps: int, r: float, beta: float) -> float:
    """Scalar safeguarded Halley iteration for one undamped edge (the float stage)."""
    c = n * math.pi / 2
    sgn = _sgn(n)
    odd = n % 2 == 1
    f0 = math.cos(beta * c) if odd else math.sin(beta * c)
    th = math.asin(max(-1.0, min(1.0, -eps * sgn * r * f0 * (1 if odd else -1))))
    lo, hi = -math.pi / 2, math.pi / 2
    for _ in range(100):
        f, d1, d2 = fn(th, c, sgn, eps, r, beta)
        if f < 0:
            lo = th
        elif f > 0:
            hi = th
        else:
            return th
        step = f / d1
        step = step / (1.0 - 0.5 * step * d2 / d1)
        tn = th - step
        K = 1.0 / (3.0 * abs(d1)) + (0.5 * d2 / d1) ** 2
        if K * abs(step) ** 3 <= 2e-16 * abs(tn):
            return tn
        if not lo < tn < hi:
            tn = 0.5 * (lo + hi)
        if hi - lo <= 4e-16 * abs(tn):
            return tn
        th = tn
    return th


def _undamped(req: Request) -> Boundary:
    n, bits = req.order, bits_for_digits(req.digits + 2)
    from analytic.stitching import Parity

    form = edge_equation(Parity.of(n))
    f_math = form.compiled("math", (0, 1, 2))
    f_arb = form.compiled("arb", 0)
    df_arb = form.compiled("arb", 1)
    pf = normal_params(req.m, None, "exact", _MATH, req.system)
    P = _AtPrecision(lambda: normal_params(req.m, None, "exact", _ARB, req.system))
    C = _AtPrecision(lambda: arb.pi() * n / 2)
    sgn = _sgn(n)
    if pf.bm < NEAR_ONE:
        ys = sorted(
            (_near_one_edge(n, eps, P, C, bits) for eps in (1, -1)),
            key=lambda r: float(r.ball.mid()),
        )
        return _result(
            req,
            "certified",
            None,
            None,
            P,
            bits,
            "per-edge equations",
            max(r.prec for r in ys),
            ys=tuple(r.ball for r in ys),
        )
    roots = []
    for eps in (1, -1):
        start = _float_edge(f_math, n, eps, pf.r, pf.beta)

        def F(t, eps=eps):
            p = P()
            return f_arb(t, C(), sgn, eps, p.r, p.beta)

        def dF(t, eps=eps):
            p = P()
            return df_arb(t, C(), sgn, eps, p.r, p.beta)

        half = math.pi / 2
        root = certified_root(
            F,
            dF,
            start,
            bits=bits,
            floor=_theta_floor(bits, n),
            bracket=(-half, half),
            scale=lambda t: _theta_scale(t, n, bits),
        )
        roots.append(root)
    lo_root, hi_root = sorted(roots, key=lambda rt: float(rt.ball.mid()))
    return _result(
        req,
        "certified",
        lo_root.ball,
        hi_root.ball,
        P,
        bits,
        "per-edge equations",
        max(r.prec for r in roots),
    )


#: below this ``1 - beta`` (``m > 0.995``) the certified solver uses the forms for ``m -> 1``
#: (:func:`verify.derived.near_one_forms`, :func:`verify.derived.order1_forms`), whose terms are
#: of the size of the result; the standard forms cancel to ``1 - beta`` there
NEAR_ONE = 0.05


def _near_one_edge(n: int, eps: int, P, C, bits: int) -> Root:
    """One undamped edge for ``1 - beta < NEAR_ONE``, in ``y = theta + pi/2`` (the distance from
    the window's left end, where an edge goes as ``m -> 1``) on the forms whose terms are of the
    size of the result: :func:`verify.derived.order1_forms` in ``x = y`` for order 1, ``eps = +1``
    (``T`` proportional to ``x -> 0``); :func:`verify.derived.near_one_forms` at ``theta = y -
    pi/2`` otherwise.  Each has one simple root in ``(0, pi)`` (the window theorem)."""
    half = math.pi / 2
    if n == 1 and eps == 1:
        f = order1_forms()[0]
        f0, f1 = f.compiled("arb", 0), f.compiled("arb", 1)

        def F(y):  # the form is positive at x = 0: negate for F(0) < 0 < F(pi)
            p = P()
            return -f0(y, p.u / (1 + p.r), p.beta, p.bm)

        def dF(y):
            p = P()
            return -f1(y, p.u / (1 + p.r), p.beta, p.bm)

    else:
        f = near_one_forms()[0 if eps == 1 else 1]
        f0, f1 = f.compiled("arb", 0), f.compiled("arb", 1)

        def F(y):
            p = P()
            return f0(y - arb.pi() / 2, C(), p.r, p.u / (1 + p.r), p.bm)

        def dF(y):
            p = P()
            return f1(y - arb.pi() / 2, C(), p.r, p.u / (1 + p.r), p.bm)

    # start: bisection in floats on the sign (the forms are well scaled in y)
    lo, hi = 0.0, math.pi
    with ctx.workprec(64):
        for _ in range(60):
            mid = 0.5 * (lo + hi) if hi > 1e-3 or lo > 0 else hi / 16
            v = F(ball(mid))
            if v > 0:
                hi = mid
            elif v < 0:
                lo = mid
            else:
                break
            if hi - lo < 1e-6 * hi:
                break
    start = 0.5 * (lo + hi)
    return certified_root(
        F,
        dF,
        start,
        bits=bits,
        floor=1e-300,
        bracket=(0.0, math.pi),
        scale=lambda y: max(min(abs(y - half), abs(y + (n - 1) * half)), 1e-300),
    )


def _result(
    req,
    method,
    th_lo,
    th_hi,
    P,
    bits,
    regime,
    prec,
    notes=(),
    theta=True,
    certified=True,
    ys=None,
) -> Boundary:
    """Turn two ``theta`` (or ``zeta``) balls into the result: ``T/T0`` and offsets as balls,
    midpoints returned, radius the largest proven error.  ``ys`` (balls of ``y = theta + pi/2``
    for the two edges, near ``m = 1``; ``None`` to use ``theta``) give ``T`` from ``x = y + (n -
    1) pi/2`` and the offset from ``theta = y - pi/2``, each without cancellation."""
    n = req.order
    with ctx.workprec(prec + 20):
        p = P()
        if theta and ys is not None:
            pi = arb.pi()
            half = arb(n) / 2
            Ts = [(y + (n - 1) * pi / 2) / (pi * p.w) for y in ys]
            ds = [(y - pi / 2) / (pi * p.w) + half * p.dinv for y in ys]
        elif theta:
            pi = arb.pi()
            half = arb(n) / 2
            Ts = [(half + th / pi) / p.w for th in (th_lo, th_hi)]
            ds = [th / (pi * p.w) + half * p.dinv for th in (th_lo, th_hi)]
        else:
            pi = arb.pi()
            Ts = [2 * p.Q * z / pi for z in (th_lo, th_hi)]
            ds = [T - arb(n) / (2 * p.w0) for T in Ts]
        rad = max(x.rad() for x in Ts + ds)
        radii = tuple(upper_mpf(arb(x.rad())) for x in Ts + ds)
        for T in Ts:
            if not T.rad() <= T.abs_lower() * arb(2) ** (-bits):  # pragma: no cover - guard
                raise CertificationError(f"enclosure of T too wide: {T}")
        vals = [to_mpf(x) for x in Ts + ds]
        encl = [(to_mpf(arb(x.lower())), to_mpf(arb(x.upper()))) for x in Ts]
        radius = upper_mpf(arb(rad))
    return Boundary(
        order=n,
        m=req.m,
        Q=req.Q,
        damping=req.damping,
        digits=req.digits,
        method=method,
        exists=True,
        lower=vals[0],
        upper=vals[1],
        delta_lower=vals[2],
        delta_upper=vals[3],
        radius=radius,
        lower_enclosure=encl[0],
        upper_enclosure=encl[1],
        certified=certified,
        regime=regime,
        notes=tuple(notes),
        radii=radii,
        system=req.system,
    )


def _none(req, method, regime, notes=(), certified=True) -> Boundary:
    return Boundary(
        order=req.order,
        m=req.m,
        Q=req.Q,
        damping=req.damping,
        digits=req.digits,
        method=method,
        exists=False,
        certified=certified,
        regime=regime,
        notes=tuple(notes),
        system=req.system,
    )


# ---------------------------------------------------------------------------------------------
# friction: a hump of the indicator on a bracket


@dataclass
class _Hump:
    """Arb functions ``D``, ``D'``, ``D''`` of one variable, a bracket ``[a, b]`` on which the
    interval must lie (``D < 0`` proven at both ends and outside by the caller), and the float
    stage: maximiser ``top`` (``dtop = D(top)``) and edges ``lo``, ``hi`` (NaN if none)."""

    D: Callable
    dD: Callable
    d2D: Callable
    a: float
    b: float
    top: float
    dtop: float
    lo: float
    hi: float
    floor: float
    #: T and the offset are proportional to (variable + shift) for these shifts: the accuracy of
    #: the variable is measured relative to the smallest of them
    shifts: tuple = (0.0,)
    variable: str = "theta"  # or "y" = theta + pi/2 (near m = 1)
    #: for a range of depths (:func:`hump_box`): the hump at its middle depth
    point: object = None


def _prove_shape(h: _Hump, lo_root, hi_root) -> bool:
    """``D < 0`` on ``[a, lower)``, ``> 0`` on ``(lower, upper)``, ``< 0`` on ``(upper, b]``."""
    e1, e2 = float(lo_root.ball.mid()), float(hi_root.ball.mid())
    top_prec = max(256, 2 * max(lo_root.prec, hi_root.prec))
    precs = [64]
    while precs[-1] < top_prec:
        precs.append(2 * precs[-1])
    for prec in precs:
        ok = True
        with ctx.workprec(prec):
            # monotone neighbourhoods Y1, Y2 of the two zeros
            ys = []
            for e, root, sign in ((e1, lo_root, 1), (e2, hi_root, -1)):
                size = min(abs(e + sh) for sh in h.shifts)
                gap = min(e2 - e1, e1 - h.a, h.b - e2)
                rho = max(gap / 4, min(size * 2.0**-40, gap / 2), 1e-300)
                found = None
                for _ in range(80):
                    Y = arb(root.ball.mid(), arb(rho).abs_upper())
                    Y = arb(Y.mid(), max(Y.rad(), (root.ball.rad() * 2)))
                    lo_end, hi_end = ball(Y.lower()), ball(Y.upper())
                    if (
                        sign * h.dD(Y) > 0
                        and sign * h.D(lo_end) < 0
                        and sign * h.D(hi_end) > 0
                        and Y.contains(root.ball)
                    ):
                        found = (lo_end, hi_end)
                        break
                    rho /= 4
                if found is None:
                    ok = False
                    break
                ys.append(found)
            if not ok:
                continue
            (y1a, y1b), (y2a, y2b) = ys
            if not (y1b < y2a):
                ok = False
                continue
            ok = (
                prove_sign(h.D, h.dD, h.a, y1a, -1, prec=prec)
                and prove_sign(h.D, h.dD, y1b, y2a, 1, prec=prec)
                and prove_sign(h.D, h.dD, y2b, h.b, -1, prec=prec)
            )
        if ok:
            return True
    return False


def _prove_negative(
    h: _Hump, bits: int = 64, max_bits: int | None = None, budget: int = 400
) -> bool:
    """``D < 0`` on all of ``[a, b]`` (no interval).

    First by bisection at low precision; near a threshold, where the maximum of ``D`` is a tiny
    negative number, by Taylor's bound around the maximiser ``t``: on a ball ``X`` where
    ``D'' < 0``, ``D <= D(t) + D'(t)^2 / (2 |sup D''(X)|)``, and by bisection outside ``X``.
    """
    if prove_sign(h.D, h.dD, h.a, h.b, -1, prec=64, budget=budget):
        return True
    start = h.top if math.isfinite(h.top) else 0.5 * (h.a + h.b)
    try:
        t = certified_root(
            lambda x: -h.dD(x),
            lambda x: -h.d2D(x),
            start,
            bits=max(bits, 64),
            floor=h.floor or 1e-300,
            bracket=(h.a, h.b),
            max_bits=max_bits or 4 * max(bits, 64) + 336,
        ).ball.mid()
    except CertificationError:
        return False
    prec = 64
    while prec <= 8 * max(bits, 64) + 256:
        with ctx.workprec(prec):
            Dt, D1t = h.D(t), h.dD(t)
            if Dt > 0:
                return False
            if Dt < 0:
                rho = (h.b - h.a) / 4
                for _ in range(60):
                    lo, hi = max(float(t) - rho, h.a), min(float(t) + rho, h.b)
                    X = arb(ball(0.5 * (lo + hi)), 0.5 * (hi - lo) * (1 + 2.0**-40))
                    d2 = h.d2D(X)
                    if d2 < 0:
                        bound = Dt + D1t * D1t / (2 * abs(d2.upper()))
                        if bound < 0:
                            if (
                                lo <= h.a
                                or prove_sign(h.D, h.dD, h.a, lo, -1, prec=64, budget=10 * budget)
                            ) and (
                                hi >= h.b
                                or prove_sign(h.D, h.dD, hi, h.b, -1, prec=64, budget=10 * budget)
                            ):
                                return True
                            break
                    rho /= 4
        prec *= 2
    return False


def _solve_hump(req: Request, h: _Hump, bits: int):
    """Decide existence and enclose the two zeros.

    Returns ``(exists, lo_root, hi_root, shape_ok)``."""
    # existence: a point with D > 0, or D < 0 everywhere on [a, b]
    top = h.top
    if math.isfinite(top) and h.dtop > 0:
        for prec in (64, 128, 256, 512, 1024):
            with ctx.workprec(prec):
                if h.D(ball(top)) > 0:
                    break
        else:
            top = None
    else:
        top = None
    if top is None:
        if _prove_negative(h, bits):
            return False, None, None, True
        # very close to a threshold: refine the maximiser and look again
        try:
            t_root = certified_root(
                lambda x: -h.dD(x),
                lambda x: -h.d2D(x),
                h.top if math.isfinite(h.top) else 0.5 * (h.a + h.b),
                bits=bits,
                floor=h.floor or 1e-300,
                bracket=(h.a, h.b),
            )
        except CertificationError as exc:
            raise CertificationError(
                "cannot decide whether the interval exists: the depth is too close to a threshold"
            ) from exc
        with ctx.workprec(t_root.prec):
            val = h.D(t_root.ball.mid())
        if not val > 0:
            raise CertificationError(
                "cannot decide whether the interval exists: the depth is too close to a threshold "
                f"(max D = {val})"
            )
        top = float(t_root.ball.mid())
        lo0, hi0 = 0.5 * (h.a + top), 0.5 * (top + h.b)
    else:
        lo0 = h.lo if math.isfinite(h.lo) else 0.5 * (h.a + top)
        hi0 = h.hi if math.isfinite(h.hi) else 0.5 * (top + h.b)

    def scale(t):
        return max(min(abs(t + sh) for sh in h.shifts), h.floor, 1e-300)

    lo_root = certified_root(
        h.D, h.dD, lo0, bits=bits, floor=h.floor, bracket=(h.a, top), scale=scale
    )
    neg = lambda t: -h.D(t)  # noqa: E731
    dneg = lambda t: -h.dD(t)  # noqa: E731
    hi_root = certified_root(
        neg, dneg, hi0, bits=bits, floor=h.floor, bracket=(top, h.b), scale=scale
    )
    return True, lo_root, hi_root, _prove_shape(h, lo_root, hi_root)


def depth_ball(m_box: tuple[Fraction, Fraction]) -> arb:
    """The ball (rounded outward; at the working precision, or more where ``1 - m`` needs it)
    that holds every depth of the closed range ``m_box = (lo, hi)`` of exact rationals."""
    lo, hi = m_box
    with ctx.workprec(max(ctx.prec, box_prec(m_box))):
        a = arb(lo.numerator) / lo.denominator
        b = arb(hi.numerator) / hi.denominator
        return a.union(b)


def box_prec(m_box) -> int:
    """Bits that keep ``1 - m`` and the width of a depth range (dyadic ends)."""
    lo, hi = m_box
    return 32 + max(lo.denominator.bit_length(), hi.denominator.bit_length(), 32)


def _params_at(m, Q, damping, m_box, make):
    """Parameters as balls: at the exact depth ``m``, or for every depth of ``m_box``."""
    if m_box is None:
        return make(m, Q, damping, _ARB) if damping is not None else make(m, Q, _ARB)
    M = depth_ball(m_box)
    Qb = arb(Q.numerator) / Q.denominator
    return make(M, Qb, damping, _ARB) if damping is not None else make(M, Qb, _ARB)


def hump_normal(
    n: int,
    m: Fraction,
    Q: Fraction,
    damping: str,
    bits: int,
    m_box=None,
    float_stage=None,
    jet: bool = False,
    system=PAPER,
):
    """The friction problem in the normal form, for order ``n`` at exact ``m``, ``Q``: the
    :class:`_Hump` (arb functions, proven bracket, float stage) and the parameters at precision.

    With ``m_box = (lo, hi)`` (exact rationals around ``m``) the arb functions and the bracket hold
    for every depth of that range at once (the parameters are balls that contain them all); the
    float stage is that of ``m`` (``float_stage``: computed already, a dict as
    :func:`verify.grid.damped_normal` returns for one depth, plus ``"bm"``)."""
    from analytic.stitching import Parity

    from .grid import damped_normal

    parity = Parity.of(n)
    if float_stage is None:
        # float parameters from the exact rationals (right also next to critical damping)
        pm = normal_params(m, Q, damping, _MATH, system)
        Pn = NormalParams(*(np.array([float(getattr(pm, f.name))]) for f in fields(NormalParams)))
        fl = damped_normal(np.array([[n]]), Pn)
        fl = {k: float(np.asarray(v).ravel()[0]) for k, v in fl.items()}
        bm = pm.bm
    else:
        fl, bm = float_stage, float_stage["bm"]
    form = indicator(parity)
    D0, D1, D2 = (form.compiled("arb", k) for k in (0, 1, 2))
    if jet and not system.is_paper:  # pragma: no cover - existence is the paper's for now
        raise InputError(f"proven existence is derived for the paper's system, not {system.label}")
    if jet:  # parameters as jets in m over the range (for the mean-value form, hump_box)

        def jets():
            Qb = arb(Q.numerator) / Q.denominator
            return normal_params(Jet(depth_ball(m_box), 1), Jet(Qb), damping, _ARB)

        P = _AtPrecision(jets, box_prec(m_box))
    else:
        P = _AtPrecision(
            lambda: _params_at(m, Q, damping, m_box, partial(normal_params, system=system)),
            box_prec(m_box) if m_box else 0,
        )
    C = _AtPrecision(lambda: arb.pi() * n / 2)

    def args():
        p = P()
        return (C(), p.r2, p.u, p.beta, p.g)

    # the bracket: a little outside the undamped-form roots, proven outside both
    E0 = edge_equation(parity).compiled("arb", 0)
    sgn = _sgn(n)
    span = max(fl["b"] - fl["a"], 1e-300)
    a = max(fl["a"] - max(span * 1e-6, abs(fl["a"]) * 1e-12, 1e-300), -math.pi / 2)
    b = min(fl["b"] + max(span * 1e-6, abs(fl["b"]) * 1e-12, 1e-300), math.pi / 2)
    if not jet:
        with ctx.workprec(128):
            p = P()
            outside = all(E0(ball(a), C(), sgn, e, p.r, p.beta) < 0 for e in (1, -1)) and all(
                E0(ball(b), C(), sgn, e, p.r, p.beta) > 0 for e in (1, -1)
            )
        if not outside:  # pragma: no cover - the float bracket is always this good
            a, b = -math.pi / 2, math.pi / 2
    if bm < NEAR_ONE:
        return _hump_near_one(n, P, fl, b, C, E0, check=not jet), P
    h = _Hump(
        D=lambda t: D0(t, *args()),
        dD=lambda t: D1(t, *args()),
        d2D=lambda t: D2(t, *args()),
        a=a,
        b=b,
        top=fl["top"],
        dtop=fl["dtop"],
        lo=fl["lo"],
        hi=fl["hi"],
        floor=_theta_floor(bits, n),
        shifts=(0.0, n * math.pi / 2),
    )
    return h, P


def hump_box(n: int, lo: Fraction, hi: Fraction, Q: Fraction, damping: str, float_stage=None):
    """The normal-form friction problem for every depth of ``[lo, hi]`` at once: ``D``, ``D'``,
    ``D''`` (in ``theta``, or ``y`` near ``m = 1``) enclosed by the mean-value form in ``m``,
    ``f(M) in f(mid) + f_m(M) (M - mid)``, with ``f_m`` from jets (:class:`verify.certify.Jet`)
    over the ball ``M`` of the range -- far tighter than evaluating with ``M`` itself, where the
    parameters' dependence on ``m`` is counted many times.  The bracket is the whole window
    (rounded outward).  The float stage is that of the middle."""
    mid = (lo + hi) / 2
    if float_stage is None:
        from .grid import damped_normal

        pm = normal_params(mid, Q, damping, _MATH)
        Pn = NormalParams(*(np.array([float(getattr(pm, f.name))]) for f in fields(NormalParams)))
        fl = damped_normal(np.array([[n]]), Pn)
        float_stage = {k: float(np.asarray(v).ravel()[0]) for k, v in fl.items()}
        float_stage["bm"] = float(pm.bm)
    # the middle as an exact ball: arb arithmetic instead of long rationals
    hm, _ = hump_normal(n, mid, Q, damping, 64, m_box=(mid, mid), float_stage=float_stage)
    hj, _ = hump_normal(n, mid, Q, damping, 64, m_box=(lo, hi), float_stage=float_stage, jet=True)

    def dm():
        return depth_ball((lo, hi)) - (arb(mid.numerator) / mid.denominator)

    dM = _AtPrecision(dm, box_prec((lo, hi)))

    def mv(f0, f1):
        def g(t):
            v = f1(t)
            slope = v.d if isinstance(v, Jet) else 0
            return f0(t) + slope * dM()

        return g

    if hm.variable == "y":
        a, b = 0.0, math.nextafter(math.pi, 4.0)
    else:
        a, b = math.nextafter(-math.pi / 2, -2.0), math.nextafter(math.pi / 2, 2.0)
    return _Hump(
        D=mv(hm.D, hj.D),
        dD=mv(hm.dD, hj.dD),
        d2D=mv(hm.d2D, hj.d2D),
        a=a,
        b=b,
        top=hm.top,
        dtop=hm.dtop,
        lo=hm.lo,
        hi=hm.hi,
        floor=hm.floor,
        shifts=hm.shifts,
        variable=hm.variable,
        point=hm,
    )


def _hump_near_one(n, P, fl, b, C, E0, check: bool = True) -> _Hump:
    """Friction near ``m = 1`` (``1 - beta < NEAR_ONE``): the hump in ``y = theta + pi/2``, the
    distance from the window's left end, where the lower edge goes as ``m -> 1``.  ``D`` is the
    form whose terms are of the size of ``D``: :func:`verify.derived.order1_forms` in ``x = y``
    (order 1; ``T`` is proportional to ``x``), :func:`verify.derived.near_one_forms` at ``theta = y
    - pi/2`` otherwise.  The bracket is ``[0, b + pi/2]``: the interval lies in the window, and
    ``D < 0`` at its left end."""
    half = math.pi / 2
    if n == 1:
        form = order1_forms()[1]

        def yargs():
            p = P()
            return (p.r2, p.u, p.beta, p.bm, p.g)

        def at(y):
            return y

    else:
        form = near_one_forms()[2]

        def yargs():
            p = P()
            return (C(), p.u, p.bm, p.g)

        def at(y):
            return y - arb.pi() / 2

    Y0, Y1, Y2 = (form.compiled("arb", k) for k in (0, 1, 2))
    by = b + half
    if check:
        with ctx.workprec(128):
            p = P()
            thb = ball(by) - arb.pi() / 2
            sgn = _sgn(n)
            if not all(E0(thb, C(), sgn, e, p.r, p.beta) > 0 for e in (1, -1)):  # pragma: no cover
                by = math.pi

    def shifted(v):
        return v + half if math.isfinite(v) and v + half > 0 else math.nan

    return _Hump(
        D=lambda y: Y0(at(y), *yargs()),
        dD=lambda y: Y1(at(y), *yargs()),
        d2D=lambda y: Y2(at(y), *yargs()),
        a=0.0,
        b=by,
        top=shifted(fl["top"]),
        dtop=fl["dtop"],
        lo=shifted(fl["lo"]),
        hi=shifted(fl["hi"]),
        floor=1e-300,
        shifts=(-half, (n - 1) * half),  # theta = y - pi/2, x = y + (n - 1) pi/2
        variable="y",
    )


def _normal_damped(req: Request) -> Boundary:
    bits = bits_for_digits(req.digits + 2)
    h, P = hump_normal(req.order, req.m, req.Q, req.damping, bits, system=req.system)
    regime = "normal form with friction"
    exists, lo_root, hi_root, shape = _solve_hump(req, h, bits)
    notes = (
        []
        if shape
        else [
            "the two edges are proven zeros of the indicator; that the indicator has no other sign "
            "change in the window was not proven"
        ]
    )
    if not exists:
        return _none(req, "certified", regime, notes)
    lo_ball, hi_ball, ys = lo_root.ball, hi_root.ball, None
    if h.variable == "y":
        ys = (lo_ball, hi_ball)
    return _result(
        req,
        "certified",
        lo_ball,
        hi_ball,
        P,
        bits,
        regime,
        max(lo_root.prec, hi_root.prec),
        notes,
        certified=shape,
        ys=ys,
    )


def hump_trace(
    n: int,
    m: Fraction,
    Q: Fraction,
    regimes: tuple[str, str],
    m_box=None,
    window=None,
    system=PAPER,
):
    """The friction problem in the trace form (exact model, a half critically or over-damped):
    the :class:`_Hump` in ``zeta`` on the proven window of order ``n``, and the parameters; or
    ``(None, reason)`` if the order has no window.  ``m_box`` as for :func:`hump_normal` (the
    regimes must be those of every depth in it)."""
    from .grid import damped_trace, trace_window_ends

    Tf = trace_params(m, Q, _MATH, system)
    window = window or trace_window_ends(n, regimes, Tf)
    if window is None:
        why = (
            "both halves are critically or over-damped: only order 1 can exist"
            if regimes[1] != "under"
            else "no window"
        )
        return None, why
    form = trace_indicator(*regimes)
    D0, D1, D2 = (form.compiled("arb", k) for k in (0, 1, 2))
    P = _AtPrecision(
        lambda: _params_at(m, Q, None, m_box, partial(trace_params, system=system)),
        box_prec(m_box) if m_box else 0,
    )
    sigma = -1 if n % 2 else 1

    def args():
        p = P()
        return (sigma, p.kappa, p.nu1, p.nu2)

    funcs = [lambda z, F=F: F(z, *args()) for F in (D0, D1, D2)]
    if m_box is not None:  # the mean-value form in m (see hump_box), jets from the middle
        Pm = _AtPrecision(lambda: _params_at(m, Q, None, (m, m), trace_params), box_prec((m, m)))

        def jets():
            Qb = arb(Q.numerator) / Q.denominator
            return trace_params(Jet(depth_ball(m_box), 1), Jet(Qb), _ARB)

        Pj = _AtPrecision(jets, box_prec(m_box))
        dM = _AtPrecision(
            lambda: depth_ball(m_box) - arb(m.numerator) / m.denominator, box_prec(m_box)
        )

        def mv(F):
            def g(z):
                pm, pj = Pm(), Pj()
                v = F(z, sigma, pj.kappa, pj.nu1, pj.nu2)
                slope = v.d if isinstance(v, Jet) else 0
                return F(z, sigma, pm.kappa, pm.nu1, pm.nu2) + slope * dM()

            return g

        funcs = [mv(F) for F in (D0, D1, D2)]

    za, zb = window
    if m_box is not None:  # the union of the windows at the two ends of the range
        for x in m_box:
            Tx = trace_params(x, Q, _MATH)
            wx = trace_window_ends(n, regimes, Tx)
            if wx is None and regimes[1] != "under":
                continue  # the given window covers it
            if wx is None:  # the window ends at the tail bound there: reach past it
                ax = 2 - float(Tx.nu1)
                if not ax > 0:
                    return None, "no window at an end of the range"
                zt = max(2 / ax, 1.0)
                while (2 + abs(float(Tx.kappa)) * zt * zt) * math.exp(-ax * zt) >= 0.5:
                    zt *= 1.25
                wx = (za, zt)
            za, zb = min(za, wx[0]), max(zb, wx[1])
    widen = 1e-9 if m_box is None else 1e-3
    za = za * (1 - widen)
    zb = zb * (1 + widen)
    if not _prove_window(n, regimes, P, za, zb, m_box, m, Q):  # pragma: no cover - guard
        raise CertificationError(f"could not prove the window of order {n}: {za}, {zb}")
    fl = damped_trace(n, regimes, Tf, (za, zb))
    h = _Hump(
        D=funcs[0],
        dD=funcs[1],
        d2D=funcs[2],
        a=za,
        b=zb,
        top=fl["top"],
        dtop=fl["dtop"],
        lo=fl["lo"],
        hi=fl["hi"],
        floor=0.0,
        # T = 2 Q zeta/pi and the offset T - n/(2 w0): accuracy relative to both
        shifts=(0.0, -math.pi * n / (4 * float(Q) * Tf.w0)),
    )
    return h, P


def _trace_damped(req: Request, regimes) -> Boundary:
    bits = bits_for_digits(req.digits + 2)
    regime = f"trace form (half 1 {regimes[0]}, half 2 {regimes[1]})"
    h, P = hump_trace(req.order, req.m, req.Q, regimes, system=req.system)
    if h is None:
        return _none(req, "certified", regime, (P,))
    exists, lo_root, hi_root, shape = _solve_hump(req, h, bits)
    notes = [] if shape else ["the shape of the indicator in the window was not proven"]
    if not exists:
        return _none(req, "certified", regime, notes)
    return _result(
        req,
        "certified",
        lo_root.ball,
        hi_root.ball,
        P,
        bits,
        regime,
        max(lo_root.prec, hi_root.prec),
        notes,
        theta=False,
        certified=shape,
    )


def _atan2(y, x):
    """``atan2`` of balls or of jets (:class:`verify.certify.Jet`)."""
    if isinstance(y, Jet) or isinstance(x, Jet):
        y, x = Jet._of(y), Jet._of(x)
        return Jet(arb.atan2(y.v, x.v), (x.v * y.d - y.v * x.d) / (x.v * x.v + y.v * y.v))
    return arb.atan2(y, x)


def trace_phase(regimes, P, z, m_box=None, m=None, Q=None) -> arb:
    """The phase ``Phi(zeta)`` of the trace form (half 2 under-damped), as a ball; with
    ``m_box`` (and its middle ``m``, and ``Q``) for every depth of the range, by the mean-value
    form in ``m`` (jets) instead of ``P``."""
    r1 = regimes[0]
    win = trace_window(r1).compiled("arb", 0), trace_window(r1).compiled("arb", 1)
    z = ball(z) if not isinstance(z, arb) else z

    def phase(p):
        C1 = win[0](z, 1, p.kappa, p.nu1, p.nu2)
        S1 = win[1](z, 1, p.kappa, p.nu1, p.nu2)
        return p.nu2 * z + _atan2(p.kappa * S1, 2 * p.nu2 * C1)

    if m_box is None:
        return phase(P())
    with ctx.workprec(max(ctx.prec, box_prec(m_box))):
        Qb = arb(Q.numerator) / Q.denominator
        mid = phase(trace_params(m, Q, _ARB))
        jet = phase(trace_params(Jet(depth_ball(m_box), 1), Jet(Qb), _ARB))
        slope = jet.d if isinstance(jet, Jet) else 0
        return mid + slope * (depth_ball(m_box) - arb(m.numerator) / m.denominator)


def prove_no_window(n: int, regimes, P, ztail: float, m_box=None, m=None, Q=None) -> bool:
    """Order ``n`` has no interval (half 2 under-damped): beyond ``ztail`` ``D < 0`` (the tail
    bound of :func:`verify.grid.trace_window_ends`), and below it the phase stays under ``n pi -
    pi/2`` (``Phi`` increases), so the order's window does not begin."""
    if regimes[1] != "under":
        return n > 1
    with ctx.workprec(96):
        p = P()
        z2 = ball(ztail)
        a = 2 - p.nu1
        tail = (2 + abs(p.kappa) * z2 * z2) * (-a * z2).exp()
        pi = arb.pi()
        ph = trace_phase(regimes, P, z2, m_box, m, Q)
        return bool(tail < 1 and z2 * a > 2 and ph < n * pi - pi / 2)


def _prove_window(n, regimes, P, za, zb, m_box=None, m=None, Q=None) -> bool:
    """The window ends enclose the order's window (and nothing of the same parity beyond it);
    with ``m_box`` for every depth of that range (the phase by the mean-value form)."""
    r1, r2 = regimes
    with ctx.workprec(96):
        p = P()
        if r2 == "under":

            def phi(z):
                return trace_phase(regimes, P, ball(z), m_box, m, Q)

            pi = arb.pi()
            z2 = ball(zb)
            a = 2 - p.nu1
            tail = (2 + abs(p.kappa) * z2 * z2) * (-a * z2).exp()
            beyond = bool(tail < 1 and z2 * a > 2) or bool(
                phi(zb) > n * pi + pi / 2 and phi(zb) < (n + 1) * pi + pi / 2
            )
            return bool(phi(za) < n * pi - pi / 2 and phi(za) > (n - 1) * pi - pi / 2) and beyond
        form = trace_indicator(*regimes).compiled("arb", 0)
        z1 = ball(za)
        P1 = form(z1, 1, p.kappa, p.nu1, p.nu2) + 2 * (2 * z1).cosh()
        a = 2 - p.nu1 - p.nu2
        z2 = ball(zb)
        tail = abs(p.kappa) * z2 * z2 * (-a * z2).exp()
        return bool(P1 > 0 and tail < 1 and z2 * a > 2)


@register_method("certified")
def _certified(req: Request) -> Boundary:
    if req.Q is None:
        return _undamped(req)
    kind, regimes = form_for(req.m, req.Q, req.damping, req.system)
    if kind == "normal":
        return _normal_damped(req)
    return _trace_damped(req, regimes)


def _fixedpoint(req: Request) -> Boundary:  # registered by verify.fixedpoint
    from .fixedpoint import boundary_fixedpoint

    return boundary_fixedpoint(req)


METHODS["fixedpoint"] = _fixedpoint


def _auto(req: Request) -> Boundary:  # registered here, implemented in verify.auto
    from .auto import boundary_auto

    return boundary_auto(req)


METHODS["auto"] = _auto


def float_edges(order, m) -> tuple[float, float]:
    """Both undamped edges ``T/T0`` of order ``order`` at depth ``m`` in double precision, sorted:
    the float stage of :func:`boundary` (safeguarded Halley on each edge equation), not certified.
    Loses digits where ``1 - beta`` is small (``m`` near 1), where :func:`verify.grid.boundary_grid`
    polishes."""
    from analytic.stitching import Parity

    n = as_order(order)
    mq = exact_fraction(as_depth(m))
    f_math = edge_equation(Parity.of(n)).compiled("math", (0, 1, 2))
    pf = normal_params(mq, None, "exact", _MATH)
    Ts = sorted(
        (n / 2 + _float_edge(f_math, n, eps, pf.r, pf.beta) / math.pi) / pf.w for eps in (1, -1)
    )
    return Ts[0], Ts[1]
