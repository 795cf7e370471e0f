"""The certified edges without friction: one simple root per edge equation.

The two per-edge equations ``sin(theta) + k r f(beta (n pi/2 + theta)) = 0``
(:func:`verify.derived.edge_equation`; ``k = +-1`` picks the edge) each have exactly one root in
``(-pi/2, pi/2)``, and it is simple (the window theorem, ``docs/theory.md``), also where the
interval closes.  Each root is found by Halley's method in floats (:func:`float_edge`), refined by
Newton on ball midpoints with the precision doubled every step and proven by interval Newton
(:func:`verify.certify.quick_root`, with :func:`verify.certify.certified_root` behind it where the
fast path does not succeed).  The lower edge is the smaller root.  No solver can reach another
interval's edge: the window holds one root of each equation and the iteration is kept inside it.
Near ``m = 1`` (``1 - beta <`` :data:`verify.params.NEAR_ONE`) the unknown is ``y = theta + pi/2``
on the forms whose terms are of the size of the result (:func:`near_one_edge`).
"""

from __future__ import annotations

import math
from functools import cache

from flint import arb, ctx

from analytic.system import PAPER

from .certify import QUICK_GUARD, Root, ball, bits_for_digits, certified_root, pow2, quick_root
from .derived import backend, edge_equation, near_one_forms, order1_forms
from .enclosure import GUARD, AtPrecision, edges_result, sgn_of, theta_floor, theta_scale
from .float_stage import float_edge
from .inputs import as_depth, as_order
from .params import NEAR_ONE, exact_fraction, normal_params, undamped_params
from .request import Request
from .result import Boundary, from_balls
from .system_params import undamped_values

__all__ = ["undamped", "float_edges", "near_one_edge"]

_ARB = backend("arb")
#: the accuracy (bits) of the float start (:func:`verify.certify.quick_root`'s ``start_bits``)
_START_BITS = 50
_MATH = backend("math")


@cache
def _forms(odd: bool):
    """The edge equation of one parity compiled: floats with two derivatives (the start), and
    arb ``F``, ``F'`` and both at once (shared subexpressions)."""
    form = edge_equation(-1 if odd else 1)  # the parity's multiplier (analytic.stitching.Parity)
    return (
        form.compiled("math", (0, 1, 2)),
        form.compiled("arb", 0),
        form.compiled("arb", 1),
        form.compiled("arb", (0, 1)),
    )


def undamped(req: Request) -> Boundary:
    """Both edges without friction (any member of the family), certified."""
    n, bits = req.order, bits_for_digits(req.digits + 2)
    forms = _forms(n % 2 == 1)
    if bits <= _LEAN_BITS:
        lean = _lean(req, n, bits, forms)
        if lean is not None:
            return lean
    f_math, f_arb, df_arb, fd_arb = forms
    P = AtPrecision(lambda: normal_params(req.m, None, "exact", _ARB, req.system))
    C = AtPrecision(lambda: arb.pi() * arb(n) * _HALF)  # n pi/2 (the halving is exact)
    # the parameters once, at the precision of the proof (quick_root's); the float start and
    # every lower precision of the Newton steps take them rounded from there
    top = bits + QUICK_GUARD
    old = ctx.prec
    ctx.prec = top
    try:
        pt, ct = P(), C()
    finally:
        ctx.prec = old
    if float(pt.bm) < NEAR_ONE:
        ys = sorted(
            (near_one_edge(n, eps, P, C, bits) for eps in (1, -1)),
            key=lambda r: float(r.ball.mid()),
        )
        return edges_result(
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
    r_f, beta_f = float(pt.r), float(pt.beta)
    sgn = _UNIT[sgn_of(n)]  # exact balls (an arb times an int converts the int first)
    rounded: dict[int, tuple] = {top: (ct, pt.r, pt.beta)}

    def args():
        """``(c, r, beta)`` at the working precision."""
        prec = ctx.prec
        a = rounded.get(prec)
        if a is None:
            if prec < top:
                ctx.prec = prec + 12
                a = (+ct, +pt.r, +pt.beta)
                ctx.prec = prec
            else:
                p = P()
                a = (C(), p.r, p.beta)
            rounded[prec] = a
        return a

    half = math.pi / 2
    floor = theta_floor(bits, n)
    window = _WINDOW
    roots = []

    def scale(t):
        return theta_scale(t, n, bits)

    for eps, k in _EDGES:
        start = float_edge(f_math, n, eps, r_f, beta_f)

        def F(t, k=k):
            c, r, beta = args()
            return f_arb(t, c, sgn, k, r, beta)

        def dF(t, k=k):
            c, r, beta = args()
            return df_arb(t, c, sgn, k, r, beta)

        def FD(t, k=k):
            c, r, beta = args()
            return fd_arb(t, c, sgn, k, r, beta)

        root = quick_root(FD, F, dF, start, bits=bits, floor=floor, bracket=window, scale=scale)
        if root is None:
            root = certified_root(
                F, dF, start, bits=bits, floor=floor, bracket=(-half, half), scale=scale
            )
        roots.append(root)
    lo_root, hi_root = roots
    if float(hi_root.ball.mid()) < float(lo_root.ball.mid()):
        lo_root, hi_root = hi_root, lo_root
    return edges_result(
        req,
        "certified",
        lo_root.ball,
        hi_root.ball,
        P,
        bits,
        "per-edge equations",
        max(lo_root.prec, hi_root.prec),
    )


#: up to this many bits the edges go through :func:`_lean` (above, Python's bookkeeping is a
#: negligible part of the work)
_LEAN_BITS = 4096


def _lean(req, n, bits, forms):
    """Both edges (``bits <= _LEAN_BITS``) in one function: the parameters as :func:`undamped`
    computes them (at the proof's precision and its guard, the precision at which its
    :class:`~verify.enclosure.AtPrecision` evaluates them), the float start, the steps of
    :func:`verify.certify.quick_root` -- Newton on midpoints doubling the accuracy at a precision
    just above it, then one interval Newton test at the full precision -- on the same balls
    (the parameters rounded from the proof's precision as :func:`undamped`'s ``args`` does it),
    without its general steps, and the result of :func:`verify.enclosure.edges_result` (the same
    arithmetic).  ``None`` near ``m = 1`` (:func:`near_one_edge`'s forms) and where a step does
    not succeed at once; the caller then runs the general path, which repeats these steps and
    goes on from there."""
    f_math, f_arb, df_arb, fd_arb = forms
    top = bits + QUICK_GUARD
    old = ctx.prec
    try:
        ctx.prec = top + GUARD
        if req.system is PAPER or req.system.is_paper:  # normal_params' route for these
            r, _, _, beta, w, bm = undamped_params(req.m, _ARB)
        else:
            r, beta, w, bm = undamped_values(req.system, req.m, _ARB)
        if float(bm) < NEAR_ONE:
            return None
        ct = arb.pi() * arb(n) * _HALF
        r_f, beta_f = float(r), float(beta)
        sgn = _UNIT[sgn_of(n)]
        floor = theta_floor(bits, n)
        tol = pow2(-bits)
        need = (bits + 4) // 2 + 1
        lo_w, hi_w = _WINDOW
        rounded = {}
        th = []
        for eps, k in _EDGES:
            x = arb(float_edge(f_math, n, eps, r_f, beta_f))
            acc = _START_BITS
            while acc < need:
                acc = min(2 * acc - 8, need + 8)
                prec = acc + 12
                a = rounded.get(prec)
                if a is None:
                    ctx.prec = prec + 12
                    a = rounded[prec] = (+ct, +r, +beta)
                ctx.prec = prec
                f, d = fd_arb(x, a[0], sgn, k, a[1], a[2])
                if not (d.is_finite() and f.is_finite()) or d.contains(0):
                    return None
                x = (x - f / d).mid()
                if not lo_w < x < hi_w:
                    return None
            ctx.prec = top
            size = abs(x)
            if floor > size:
                size = floor
            X = arb(x, (size * pow2(4 - acc)).abs_upper())
            dX = df_arb(X, ct, sgn, k, r, beta)
            if dX.contains(0) or not dX.is_finite():
                return None
            N = x - f_arb(x, ct, sgn, k, r, beta) / dX
            if not X.contains_interior(N):
                return None
            if not N.rad() <= (arb(theta_scale(float(x), n, bits)) * tol).abs_lower():
                return None
            th.append(N)
        if float(th[1].mid()) < float(th[0].mid()):
            th.reverse()
        # edges_result (theta given, no friction: no dinv), at the proof's precision
        pi = arb.pi()
        half = arb(n) * _HALF
        pw = pi * w
        Ts = [(half + t / pi) / w for t in th]
        ds = [t / pw for t in th]
        for T in Ts:
            if not T.rad() <= T.abs_lower() * tol:  # pragma: no cover - guard
                return None
    finally:
        ctx.prec = old
    return from_balls(
        Ts + ds,
        order=n,
        m=req.m,
        Q=req.Q,
        damping=req.damping,
        digits=req.digits,
        method="certified",
        regime="per-edge equations",
        system=req.system,
    )


_WINDOW = (ball(-math.pi / 2), ball(math.pi / 2))
_UNIT = {1: arb(1), -1: arb(-1)}
_HALF = arb(0.5)
_EDGES = ((1, _UNIT[1]), (-1, _UNIT[-1]))


def near_one_edge(n: int, eps: int, P, C, bits: int) -> Root:
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


def float_edges(order, m) -> tuple[float, float]:
    """Both undamped edges ``T/T0`` of order ``order`` at depth ``m`` in double precision, sorted:
    the float stage of :func:`boundary` (safeguarded Halley on each edge equation), not certified.
    Loses digits where ``1 - beta`` is small (``m`` near 1), where :func:`verify.grid.boundary_grid`
    polishes."""
    n = as_order(order)
    mq = exact_fraction(as_depth(m))
    f_math = _forms(n % 2 == 1)[0]
    pf = normal_params(mq, None, "exact", _MATH)
    Ts = sorted(
        (n / 2 + float_edge(f_math, n, eps, pf.r, pf.beta) / math.pi) / pf.w for eps in (1, -1)
    )
    return Ts[0], Ts[1]
