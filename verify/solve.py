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

import mpmath
import numpy as np
from flint import arb, ctx

from .certify import (
    CertificationError,
    ball,
    bits_for_digits,
    certified_root,
    prove_sign,
    to_mpf,
    upper_mpf,
)
from .derived import backend, edge_equation, indicator, trace_indicator, trace_window
from .inputs import (
    InputError,
    as_damping,
    as_depth,
    as_digits,
    as_order,
    as_quality,
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
            "m": _fraction_text(self.m),
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
        head = f"order {self.order}, m = {_fraction_text(self.m)}, {fr}"
        if not self.exists:
            body = "  no interval of instability"
        else:
            body = (
                f"  lower T/T0 = {self._fmt(self.lower, 0)}   "
                f"(T - n T_av/2 = {self._fmt(self.delta_lower, 2)})\n"
                f"  upper T/T0 = {self._fmt(self.upper, 1)}   "
                f"(T - n T_av/2 = {self._fmt(self.delta_upper, 3)})"
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
    order, m, *, Q=None, damping="exact", digits=30, method="certified", tol=None
) -> Boundary:
    """The lower and upper boundary ``T/T0`` of the ``order``-th interval of instability.

    ``m`` may be a str (``"3/5"``, ``"0.3"``, ``"1e-12"``: exact), int, Fraction, float (its exact
    binary value) or mpmath mpf.  ``Q`` is the quality factor (``None``: no friction); ``damping``
    ``"exact"`` (the damped oscillator) or ``"paper"`` (the paper's eqs. 28-30).  ``digits``
    significant digits are returned, each one proven (see the module text).  ``method`` picks a
    solver from :data:`METHODS`.  ``tol`` (a relative error of ``T/T0``) instead lets the engine
    pick the cheapest method that provably meets it (``method="auto"``, :mod:`verify.auto`; the
    digits then follow from ``tol``); ``Boundary.method`` says which one it used.
    """
    n = as_order(order)
    mm = as_depth(m)
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
    req = Request(n, exact_fraction(mm), QF, model, d, mm, tt)
    return solver(req)


# ---------------------------------------------------------------------------------------------
# parameters at the working precision


class _AtPrecision:
    """Numbers recomputed for every working precision (``flint.ctx.prec``), cached."""

    def __init__(self, make):
        self._make = make
        self._cache: dict[int, object] = {}

    def __call__(self):
        prec = ctx.prec
        val = self._cache.get(prec)
        if val is None:
            with ctx.workprec(prec + 12):
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
    pf = normal_params(req.m, None, "exact", _MATH)
    P = _AtPrecision(lambda: normal_params(req.m, None, "exact", _ARB))
    C = _AtPrecision(lambda: arb.pi() * n / 2)
    sgn = _sgn(n)
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
            scale=_theta_scale(start, n, bits),
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


def _result(
    req, method, th_lo, th_hi, P, bits, regime, prec, notes=(), theta=True, certified=True
) -> Boundary:
    """Turn two ``theta`` (or ``zeta``) balls into the result: ``T/T0`` and offsets as balls,
    midpoints returned, radius the largest proven error."""
    n = req.order
    with ctx.workprec(prec + 20):
        p = P()
        if theta:
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
    shift: float = 0.0  # T is proportional to (variable + shift): accuracy relative to both


def _prove_shape(h: _Hump, lo_root, hi_root) -> bool:
    """``D < 0`` on ``[a, lower)``, ``> 0`` on ``(lower, upper)``, ``< 0`` on ``(upper, b]``."""
    e1, e2 = float(lo_root.ball.mid()), float(hi_root.ball.mid())
    for prec in (64, 128, 256):
        ok = True
        with ctx.workprec(prec):
            # monotone neighbourhoods Y1, Y2 of the two zeros
            ys = []
            for e, root, sign in ((e1, lo_root, 1), (e2, hi_root, -1)):
                rho = max(min(e2 - e1, e1 - h.a, h.b - e2) / 4, abs(e) * 2.0**-40, 1e-300)
                found = None
                for _ in range(40):
                    Y = arb(ball(e), arb(rho).abs_upper())
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


def _prove_negative(h: _Hump, bits: int = 64) -> bool:
    """``D < 0`` on all of ``[a, b]`` (no interval).

    First by bisection at low precision; near a threshold, where the maximum of ``D`` is a tiny
    negative number, by Taylor's bound around the maximiser ``t``: on a ball ``X`` where
    ``D'' < 0``, ``D <= D(t) + D'(t)^2 / (2 |sup D''(X)|)``, and by bisection outside ``X``.
    """
    if prove_sign(h.D, h.dD, h.a, h.b, -1, prec=64, budget=400):
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
                            if (lo <= h.a or prove_sign(h.D, h.dD, h.a, lo, -1, prec=64)) and (
                                hi >= h.b or prove_sign(h.D, h.dD, hi, h.b, -1, prec=64)
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
        return max(min(abs(t), abs(t + h.shift)) if h.shift else abs(t), h.floor, 1e-300)

    lo_root = certified_root(
        h.D, h.dD, lo0, bits=bits, floor=h.floor, bracket=(h.a, top), scale=scale(lo0)
    )
    neg = lambda t: -h.D(t)  # noqa: E731
    dneg = lambda t: -h.dD(t)  # noqa: E731
    hi_root = certified_root(
        neg, dneg, hi0, bits=bits, floor=h.floor, bracket=(top, h.b), scale=scale(hi0)
    )
    return True, lo_root, hi_root, _prove_shape(h, lo_root, hi_root)


def hump_normal(n: int, m: Fraction, Q: Fraction, damping: str, bits: int):
    """The friction problem in the normal form, for order ``n`` at exact ``m``, ``Q``: the
    :class:`_Hump` (arb functions, proven bracket, float stage) and the parameters at precision."""
    from analytic.stitching import Parity

    from .grid import damped_normal

    parity = Parity.of(n)
    # float parameters from the exact rationals (right also next to critical damping)
    pm = normal_params(m, Q, damping, _MATH)
    Pn = NormalParams(*(np.array([float(getattr(pm, f.name))]) for f in fields(NormalParams)))
    fl = damped_normal(np.array([[n]]), Pn)
    fl = {k: float(np.asarray(v).ravel()[0]) for k, v in fl.items()}
    form = indicator(parity)
    D0, D1, D2 = (form.compiled("arb", k) for k in (0, 1, 2))
    P = _AtPrecision(lambda: normal_params(m, Q, damping, _ARB))
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
    with ctx.workprec(128):
        p = P()
        outside = all(E0(ball(a), C(), sgn, e, p.r, p.beta) < 0 for e in (1, -1)) and all(
            E0(ball(b), C(), sgn, e, p.r, p.beta) > 0 for e in (1, -1)
        )
    if not outside:  # pragma: no cover - the float bracket is always this good
        a, b = -math.pi / 2, math.pi / 2
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
        shift=n * math.pi / 2,
    )
    return h, P


def _normal_damped(req: Request) -> Boundary:
    bits = bits_for_digits(req.digits + 2)
    h, P = hump_normal(req.order, req.m, req.Q, req.damping, bits)
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
        certified=shape,
    )


def hump_trace(n: int, m: Fraction, Q: Fraction, regimes: tuple[str, str]):
    """The friction problem in the trace form (exact model, a half critically or over-damped):
    the :class:`_Hump` in ``zeta`` on the proven window of order ``n``, and the parameters; or
    ``(None, reason)`` if the order has no window."""
    from .grid import damped_trace, trace_window_ends

    Tf = trace_params(m, Q, _MATH)
    window = trace_window_ends(n, regimes, Tf)
    if window is None:
        why = (
            "both halves are critically or over-damped: only order 1 can exist"
            if regimes[1] != "under"
            else "no window"
        )
        return None, why
    form = trace_indicator(*regimes)
    D0, D1, D2 = (form.compiled("arb", k) for k in (0, 1, 2))
    P = _AtPrecision(lambda: trace_params(m, Q, _ARB))
    sigma = -1 if n % 2 else 1

    def args():
        p = P()
        return (sigma, p.kappa, p.nu1, p.nu2)

    za, zb = window
    za = za * (1 - 1e-9)
    zb = zb * (1 + 1e-9)
    if not _prove_window(n, regimes, P, za, zb):  # pragma: no cover - guard
        raise CertificationError(f"could not prove the window of order {n}: {za}, {zb}")
    fl = damped_trace(n, regimes, Tf, (za, zb))
    h = _Hump(
        D=lambda z: D0(z, *args()),
        dD=lambda z: D1(z, *args()),
        d2D=lambda z: D2(z, *args()),
        a=za,
        b=zb,
        top=fl["top"],
        dtop=fl["dtop"],
        lo=fl["lo"],
        hi=fl["hi"],
        floor=0.0,
    )
    return h, P


def _trace_damped(req: Request, regimes) -> Boundary:
    bits = bits_for_digits(req.digits + 2)
    regime = f"trace form (half 1 {regimes[0]}, half 2 {regimes[1]})"
    h, P = hump_trace(req.order, req.m, req.Q, regimes)
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


def _prove_window(n, regimes, P, za, zb) -> bool:
    """The window ends enclose the order's window (and nothing of the same parity beyond it)."""
    r1, r2 = regimes
    with ctx.workprec(96):
        p = P()
        if r2 == "under":
            win = trace_window(r1).compiled("arb", 0), trace_window(r1).compiled("arb", 1)

            def phi(z):
                z = ball(z)
                C1 = win[0](z, 1, p.kappa, p.nu1, p.nu2)
                S1 = win[1](z, 1, p.kappa, p.nu1, p.nu2)
                return p.nu2 * z + arb.atan2(p.kappa * S1, 2 * p.nu2 * C1)

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
    kind, regimes = form_for(req.m, req.Q, req.damping)
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
