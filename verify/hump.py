"""The certified edges with friction: the instability indicator as a hump on a proven bracket.

**Normal form** (paper model; exact model with both halves under-damped): ``D(theta) = R(theta) -
sin^2(theta)`` (:func:`verify.derived.indicator`) is positive exactly inside the interval.  ``D`` is
at most its friction-free value ``D0`` (same ``r``, ``beta``), which is negative outside the two
undamped roots ``[a, b]``; so the interval lies in ``[a, b]``.  There ``D`` is maximised (root of
``D'``); no interval if the maximum is ``<= 0``, else the edges are the zeros of ``D`` left and
right of the maximiser, each proven by interval Newton.  The *shape* -- ``D < 0`` on ``[a,
lower)``, ``D > 0`` between the edges, ``D < 0`` on ``(upper, b]`` -- is proven too, so the two
zeros are the edges and nothing in between is missed: by unimodality where it holds (``D'' < 0``
on the bracket, or on pieces of it with ``D'`` of one sign on the others, in an order that lets
``D`` rise and then fall: at most two zeros; :func:`_unimodal_shape`, usually one evaluation),
else by :func:`verify.certify.prove_sign` on sub-intervals, with monotone neighbourhoods of the
edges.  Non-existence is proven by signs (``D < 0`` on all of ``[a, b]``).

**Trace form** (exact model, a half critically or over-damped, or half 1 within
:data:`verify.params.NEAR_CRITICAL` of it): ``D(zeta) = sigma (2 C1 C2 - kappa S1 S2) - 2 cosh(2
zeta)`` in ``zeta = gamma T/2`` (:func:`verify.derived.trace_indicator`), on the window of the
order found from the phase ``Phi`` (see :func:`trace_phase`); inside it the same
maximise-and-bracket scheme.

The float stage of one point is scalar (:func:`verify.float_stage.normal_float_stage`); the
range versions (:func:`hump_box`, ``m_box=``) serve :mod:`verify.existence`.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass
from fractions import Fraction
from functools import cache, partial

from flint import arb, ctx

from analytic.system import PAPER

from .certify import (
    QUICK_GUARD,
    CertificationError,
    Jet,
    ball,
    bits_for_digits,
    certified_root,
    pow2,
    prove_sign,
    quick_root,
)
from .derived import (
    backend,
    edge_equation,
    indicator,
    indicator_bend,
    indicator_slope,
    int_constants,
    load_source,
    near_one_forms,
    order1_forms,
    trace_indicator,
    trace_indicator_scaled,
    trace_window,
)
from .enclosure import AtPrecision, edges_result, no_interval, sgn_of, theta_floor
from .float_stage import normal_float_edges, normal_float_stage, wide_float_edges
from .params import (
    NEAR_ONE,
    NormalParams,
    exact_arb_values,
    normal_params,
    normal_values,
    trace_params,
)
from .request import Request
from .result import Boundary, from_balls
from .system_params import normal_jets

__all__ = [
    "hump_normal",
    "hump_box",
    "hump_trace",
    "trace_phase",
    "prove_no_window",
    "prove_negative",
    "taylor_negative",
    "depth_ball",
    "box_prec",
    "normal_damped",
    "trace_damped",
]

_ARB = backend("arb")
_MATH = backend("math")
_EPS_BOTH = arb(0, 1)  # the ball [-1, 1]: both signs eps = +-1 at once (exact)


@dataclass
class _Hump:
    """Arb functions ``D``, ``D'``, ``D''`` of one variable, a bracket ``[a, b]`` on which the
    interval must lie (``D < 0`` proven at both ends and outside by the caller), and the float
    stage: ``top`` (``dtop = D(top)``), the maximiser or, where ``D > 0`` there, a point between
    the edges (:func:`verify.float_stage.normal_float_edges`), and edges ``lo``, ``hi`` (NaN if
    none)."""

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
    #: ``(D, D')`` in one evaluation (shared subexpressions), where there is one
    DdD: Callable | None = None
    #: ``-D''/2`` in a form whose enclosure of a wide ball is tighter and cheaper than ``D''``'s
    #: (:func:`verify.derived.indicator_bend`), where there is one: the concavity test
    bend: Callable | None = None
    #: ``D'`` in a cheaper form (:func:`verify.derived.indicator_slope`), where there is one (else
    #: ``dD`` itself): the interval Newton test's slope, and ``D'`` in the shape's tests
    slope: Callable | None = None
    #: a proof that ``D < 0`` at every point right of its argument (a float), where there is one
    #: (:func:`overdamped_beyond`): the bracket's right part without a bisection
    beyond: Callable | None = None

    def __post_init__(self):
        if self.slope is None:
            self.slope = self.dD


def _unimodal_shape(h: _Hump, lo_root, hi_root, budget: int = 16) -> bool:
    """The shape from unimodality (:func:`_unimodal`) on the bracket ``[a, b]`` of ``h`` at 64
    bits, with the root balls of ``lo_root`` and ``hi_root``."""
    old = ctx.prec  # set and restored here (a workprec context costs a sizeable part of this)
    ctx.prec = 64
    try:
        return _unimodal(
            arb(h.a), arb(h.b), lo_root.ball, hi_root.ball, h.bend, h.d2D, h.slope, h.D, budget
        )  # (h.a, h.b floats: exact)
    finally:
        ctx.prec = old


def _unimodal(
    a: arb,
    b: arb,
    lo: arb,
    hi: arb,
    bend,
    d2D,
    dD,
    D,
    budget: int = 16,
    args: tuple = (),
    pieces: int = 1,
    direct: int = 0,
) -> bool:
    """The shape from unimodality, at the working precision: the two root balls ``lo``, ``hi``
    disjoint and inside ``(a, b)`` (exact ends), and ``[a, b]`` cut (first into ``pieces`` equal
    parts at exact floats -- where the float stage sees ``D`` convex at an end of a wide bracket,
    :func:`verify.float_stage.wide_float_edges`, the tests of the whole and of its halves would
    fail -- then by bisection, at most ``budget`` sub-balls in all; often the whole bracket at
    once) into pieces each ``cap`` (``D'' <
    0``: ``-D''/2 > 0`` by ``bend`` where there is one, else ``D'' < 0`` by ``d2D``), ``up``
    (``D' > 0``), ``down`` (``D' < 0``) -- ``D'`` by the mean-value form around the piece's
    midpoint with the ``D''`` of the first test -- or ``neg`` (``D < 0``; tested only left of
    ``lo`` or right of ``hi``, where the ``neg`` pieces must lie), where the ``neg`` pieces are at
    the two ends only (the others make one interval, the run) and no ``up`` piece lies right of
    a ``down`` one.  A piece that holds both root balls holds a zero of ``D'`` (Rolle) and is not
    tested for ``up`` or ``down``.  An end piece of the first cut (``pieces > 1``) named by
    ``direct`` (``1`` the left, ``2`` the right, ``3`` both: where the float stage sees ``D``
    convex at that end, so that no ``cap`` test can pass there) is tested for ``up`` or
    ``down`` first by ``D'`` on the piece itself (``dD(X)``: one enclosure), then as the others
    where that does not decide the sign.  The functions are called as ``f(X, *args)``.

    On the run, ``D' > 0`` up to the last ``up`` piece (a run of ``cap`` pieces before an ``up``
    one has ``D'`` decreasing to a positive value), ``D' < 0`` from the first ``down`` piece on, and
    ``D'`` strictly decreasing between them: ``D`` rises strictly, then falls strictly, so it has at
    most two zeros there, and none on the ``neg`` pieces.  The two enclosed zeros are therefore all
    of them, ``D > 0`` between them and ``D < 0`` on either side: the shape of
    :func:`_prove_shape`, and existence with it.  ``False`` where this is not proven."""
    if not (a < lo and lo < hi and hi < b):
        return False
    if pieces > 1:  # the cuts at floats strictly inside (a, b), as the stack takes them
        fa, fb = float(a), float(b)  # (exact: the ends are floats)
        stack, v, fv = [], b, fb
        for i in range(1, pieces):  # the cuts, descending: the leftmost piece is pushed last
            c = fb - (fb - fa) * i / pieces
            if not fa < c < fv:
                return False  # pragma: no cover - guard (a bracket of a few floats)
            u = arb(c)
            stack.append((u, v, v is b and direct & 2))
            v, fv = u, c
        stack.append((a, v, direct & 1))
    else:
        stack = [(a, b, 0)]
    # The labels are checked as they come (left to right), not collected: ``state`` is 0 while
    # only neg pieces came (none yet: the leading ones), 1 in the run before any down piece (cap
    # or up pieces), 2 in the run once a down piece came, 3 in the neg pieces after the run.  A
    # label that no later labels can make acceptable -- a cap, up or down piece after the
    # trailing neg pieces (a neg piece inside the run), an up piece after a down one -- ends the
    # test at once: False, as the whole list would give.
    state = 0
    count = 0
    zero = _ZERO  # (a ball: comparing with the int 0 converts it each time)
    pop, push = stack.pop, stack.append
    while stack:  # left to right: the left half is pushed last
        u, v, end = pop()
        count += 1
        if count > budget:
            return False
        X = u.union(v)  # u, v exact: a ball holding [u, v]
        both = None  # whether the piece holds both root balls (compared once, where needed)
        label = 0  # 1 cap, 2 up, 3 down, 4 neg; 0 not decided
        if end:  # an end piece named by direct: D' on X itself
            both = u < lo and hi < v
            if not both:
                d1 = dD(X, *args)
                label = 2 if d1 > zero else 3 if d1 < zero else 0
        if not label:
            if bend is not None:
                d2 = bend(X, *args)
                if d2 > zero:
                    label = 1
                else:
                    d2 = -2 * d2  # D'' on X (bend is -D''/2, in a tighter form than d2D's)
            else:
                d2 = d2D(X, *args)
                if d2 < zero:
                    label = 1
            if not label:
                mid = X.mid()
                if both is None:
                    both = u < lo and hi < v
                if not both:
                    # D' on X by the mean-value form around the midpoint (D'' on X is d2)
                    d1 = dD(mid, *args) + d2 * (X - mid)
                    label = 2 if d1 > zero else 3 if d1 < zero else 0
                if not label:
                    if (v < lo or hi < u) and D(X, *args) < zero:  # (elsewhere a neg piece
                        label = 4  # fails the shape)
                    else:
                        push((mid, v, 0))
                        push((u, mid, 0))
                        continue
        if label == 4:
            if state:
                state = 3
        elif state == 3:
            return False  # a neg piece inside the run
        elif label == 3:
            state = 2
        elif label == 2:
            if state == 2:
                return False  # up after down
            state = 1
        elif not state:
            state = 1
    return True


def _prove_shape(h: _Hump, lo_root, hi_root, unimodal: bool = True) -> bool:
    """``D < 0`` on ``[a, lower)``, ``> 0`` on ``(lower, upper)``, ``< 0`` on ``(upper, b]``:
    by unimodality where that is proven cheaply (:func:`_unimodal_shape`; not tried again with
    ``unimodal=False``), else by signs on sub-intervals around monotone neighbourhoods of the two
    zeros."""
    if unimodal and _unimodal_shape(h, lo_root, hi_root):
        return True
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


#: evaluations of the bisection that proves ``D < 0`` on the bracket (:func:`prove_negative`)
_NEGATIVE_BUDGET = 400


def prove_negative(
    h: _Hump, bits: int = 64, max_bits: int | None = None, budget: int = _NEGATIVE_BUDGET
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
            if Dt < 0 and taylor_negative(h, float(t), Dt, D1t, 60, 64, 10 * budget, at=t):
                return True
        prec *= 2
    return False


def taylor_negative(
    h: _Hump,
    t: float,
    Dt,
    D1t,
    tries: int,
    prec: int,
    budget: int,
    monotone: bool = False,
    at: arb | None = None,
) -> bool | None:
    """``D < 0`` on all of ``[a, b]`` from ``D(t) = Dt < 0`` and ``D'(t) = D1t`` near the
    maximiser ``t``: on a ball ``X`` around ``t`` where ``D'' < 0``, ``D <= D(t) + D'(t)^2 / (2
    |sup D''(X)|)``, and bisection (:func:`verify.certify.prove_sign` at ``prec``, ``budget``)
    outside ``X``.  ``X`` shrinks by 4 up to ``tries`` times.  ``True``: proven; ``False``: the
    bound holds on ``X`` but a side was not proven; ``None``: no such ``X``.  ``monotone``: each
    side is first tried by the sign of ``D'`` (:func:`_negative_side`).  ``at``: the ball where
    ``Dt`` and ``D1t`` were taken, where it is not the float ``t`` itself.  ``X`` is the hull of
    the sides' inner ends ``[lo, hi]`` and of that point (Taylor's bound needs the segment from it
    to each point in ``X``, and the sides end at ``lo`` and ``hi``): a ball around the float
    middle of ``[lo, hi]`` with its half width misses an end by a rounding where ``hi - lo`` is a
    few units in the last place."""
    rho = (h.b - h.a) / 4
    for _ in range(tries):
        lo, hi = max(t - rho, h.a), min(t + rho, h.b)
        X = arb(lo).union(arb(hi)).union(arb(t))  # (floats: exact; the union rounds outward)
        if at is not None:
            X = X.union(at)
        d2 = h.d2D(X)
        if d2 < 0:
            bound = Dt + D1t * D1t / (2 * abs(d2.upper()))
            if bound < 0:
                return _negative_side(h, h.a, lo, True, prec, budget, monotone) and _negative_right(
                    h, hi, prec, budget, monotone
                )
        rho /= 4
    return None


def _negative_side(
    h: _Hump, x: float, y: float, rising: bool, prec: int, budget: int, monotone: bool
) -> bool:
    """``D < 0`` on ``[x, y]``, a side of :func:`taylor_negative`'s ball ``X``: ``y`` its left end
    (``rising``) or ``x`` its right end, where the bound gives ``D < 0``.  By bisection of ``D``;
    with ``monotone`` first of ``D'`` (``> 0`` if ``rising``, else ``< 0``): ``D`` is then below
    its value at that end of ``X``.  Where ``D`` is flat next to ``X`` and its enclosures are wide
    (over a range of depths), ``D'``'s margin is the larger one."""
    if x >= y:
        return True
    if monotone and prove_sign(h.dD, h.d2D, x, y, 1 if rising else -1, prec=prec, budget=budget):
        return True
    return prove_sign(h.D, h.dD, x, y, -1, prec=prec, budget=budget)


def _negative_right(h: _Hump, x: float, prec: int, budget: int, monotone: bool = False) -> bool:
    """``D < 0`` on ``[x, b]``, right of :func:`taylor_negative`'s ball (:func:`_negative_side`);
    where the hump has a proof for all of a right part (:attr:`_Hump.beyond`), by that proof from
    ``x`` or from a point a little right of it (the rest only up to there)."""
    if h.beyond is not None:
        if h.beyond(x):
            return True
        for f in (1 / 64, 1 / 16, 1 / 4):
            c = x + (h.b - x) * f
            if h.beyond(c):
                return _negative_side(h, x, c, False, prec, budget, monotone)
    return _negative_side(h, x, h.b, False, prec, budget, monotone)


def _solve_hump(req: Request, h: _Hump, bits: int):
    """Decide existence and enclose the two zeros.

    Where the float stage found both edges, each is enclosed by the fast path
    (:func:`verify.certify.quick_root`) and the concavity of ``D`` on the bracket proves the
    shape, existence included (:func:`_unimodal_shape`).  Otherwise, or where that fails: a point
    with ``D > 0`` (or ``D < 0`` proven on all of ``[a, b]``: no interval), the two zeros either
    side of it, and the shape by :func:`_prove_shape`.

    Returns ``(exists, lo_root, hi_root, shape_ok)``."""

    def scale(t):
        return max(min(abs(t + sh) for sh in h.shifts), h.floor, 1e-300)

    neg = lambda t: -h.D(t)  # noqa: E731
    dneg = lambda t: -h.dD(t)  # noqa: E731
    slope = h.slope  # the interval Newton test's D' on its narrow ball
    slope_neg = lambda t: -slope(t)  # noqa: E731
    if h.DdD is not None:
        both = h.DdD

        def both_neg(t):
            v, d = h.DdD(t)
            return -v, -d

    else:
        both = lambda t: (h.D(t), h.dD(t))  # noqa: E731
        both_neg = lambda t: (neg(t), dneg(t))  # noqa: E731

    def quick(lower: bool, top):
        """The fast path for the float edge on one side of ``top`` (``None`` where it fails)."""
        if lower:
            return quick_root(
                both, h.D, slope, h.lo, bits=bits, floor=h.floor,
                bracket=(ball(h.a), ball(top)), scale=scale,
            )  # fmt: skip
        return quick_root(
            both_neg, neg, slope_neg, h.hi, bits=bits, floor=h.floor,
            bracket=(ball(top), ball(h.b)), scale=scale,
        )  # fmt: skip

    fine = math.isfinite(h.lo) and math.isfinite(h.hi) and h.dtop > 0
    quick_roots, tried = (None, None), None
    if fine and h.a < h.lo < h.top < h.hi < h.b:
        quick_roots = (quick(True, h.top), quick(False, h.top))
        if None not in quick_roots:
            if _unimodal_shape(h, *quick_roots):
                return True, quick_roots[0], quick_roots[1], True
            tried = quick_roots  # unimodality not proven with these roots: not tried again
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
        if prove_negative(h, bits):
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
        quick_roots = (None, None)  # found around another top: not known to be on its sides
    else:
        lo0 = h.lo if math.isfinite(h.lo) else 0.5 * (h.a + top)
        hi0 = h.hi if math.isfinite(h.hi) else 0.5 * (top + h.b)
    roots = []
    for k, (F, dF, x0, (a, b)) in enumerate(
        ((h.D, h.dD, lo0, (h.a, top)), (neg, dneg, hi0, (top, h.b)))
    ):
        root = quick_roots[k]
        if root is None and (math.isfinite(h.lo) if k == 0 else math.isfinite(h.hi)):
            # a float edge from the float stage: the fast path (None where it fails)
            root = quick(k == 0, top)
        if root is None:
            root = certified_root(F, dF, x0, bits=bits, floor=h.floor, bracket=(a, b), scale=scale)
        roots.append(root)
    lo_root, hi_root = roots
    again = tried is None or tried[0] is not lo_root or tried[1] is not hi_root
    return True, lo_root, hi_root, _prove_shape(h, lo_root, hi_root, unimodal=again)


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


@cache
def _normal_forms(parity: int) -> tuple:
    """``D``, ``D'``, ``D''``, ``(D, D')``, the undamped edge equation, ``-D''/2`` in the sines
    (:func:`verify.derived.indicator_bend`) and ``D'`` in double angles
    (:func:`verify.derived.indicator_slope`), compiled for arb."""
    form = indicator(parity)
    return (
        *(form.compiled("arb", k) for k in (0, 1, 2)),
        form.compiled("arb", (0, 1)),
        edge_equation(parity).compiled("arb", 0),
        indicator_bend(parity).compiled("arb", 0),
        indicator_slope(parity).compiled("arb", 0),
    )


@cache
def _lean_forms(parity: int) -> tuple:
    """:func:`_normal_forms` for :func:`_lean_normal`, whose arguments are always balls: ``D``,
    ``D'`` and the undamped edge equation as they are, and ``D''``, ``(D, D')``, ``-D''/2`` and
    ``D'`` in double angles with their integer constants as exact balls made once
    (:func:`verify.derived.int_constants`): the same balls, without an int converted at each
    operation."""
    D0, D1, _, _, E0, _, _ = _normal_forms(parity)
    form = indicator(parity)

    def balls(f, k):
        return load_source(int_constants(f.text("arb", k)), "arb", k)

    return (
        D0,
        D1,
        balls(form, 2),
        balls(form, (0, 1)),
        E0,
        balls(indicator_bend(parity), 0),
        balls(indicator_slope(parity), 0),
    )


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
    :func:`verify.float_stage.normal_float_stage` returns, plus ``"bm"``)."""
    parity = -1 if n % 2 else 1  # the multiplier (analytic.stitching.Parity)
    D0, D1, D2, D01, E0, Bend, Slope = _normal_forms(parity)
    if jet:  # parameters as jets in m over the range (for the mean-value form, hump_box)

        def jets():
            M, Qb = Jet(depth_ball(m_box), 1), Jet(arb(Q.numerator) / Q.denominator)
            if system.is_paper:
                return normal_params(M, Qb, damping, _ARB)
            return NormalParams(**normal_jets(system, M, Qb, damping))

        P = AtPrecision(jets, box_prec(m_box))
    else:
        if m_box is None and system is PAPER:
            make = lambda: normal_params(m, Q, damping, _ARB)  # noqa: E731
        else:
            make = partial(_params_at, m, Q, damping, m_box, partial(normal_params, system=system))
        P = AtPrecision(make, box_prec(m_box) if m_box else 0, rounded=True)
    C = AtPrecision(lambda: arb.pi() * n / 2, rounded=True)
    near = None  # the parameters at the proof's precision (one point): used as they are below
    if float_stage is not None:
        fl, bm = float_stage, float_stage["bm"]
    elif jet or m_box is not None:  # pragma: no cover - ranges come with their float stage
        pm = normal_params(m, Q, damping, _MATH, system)
        fl, bm = normal_float_stage(n, pm), pm.bm
    else:
        # the parameters once, at the precision of the proof (quick_root's); the float stage
        # takes their midpoints (right to the last bit, also next to critical damping)
        top = max(80, bits + QUICK_GUARD)
        old = ctx.prec  # set and restored (cheaper than a workprec context)
        ctx.prec = top
        try:
            pt = P()
            near = (top, pt, C())
        finally:
            ctx.prec = old
        fl, bm = normal_float_edges(n, pt), float(pt.bm)

    def params():
        """``(p, c)`` for the working precision: those of the proof's precision as they are
        (balls that hold the exact values, at a precision not far above the working one: no
        rounding needed), else the parameters at the working precision."""
        if near is not None and near[0] <= 2 * ctx.prec + 64:
            return near[1], near[2]
        return P(), C()

    cache: dict = {}

    def args():
        prec = ctx.prec
        got = cache.get(prec)
        if got is None:
            p, c = params()
            got = cache[prec] = (c, p.r2, p.u, p.beta, p.g)
        return got

    # the bracket: a little outside the undamped-form roots, proven outside both
    sgn = sgn_of(n)
    span = max(fl["b"] - fl["a"], 1e-300)
    a = max(fl["a"] - max(span * 1e-6, abs(fl["a"]) * 1e-12, 1e-300), -math.pi / 2)
    b = min(fl["b"] + max(span * 1e-6, abs(fl["b"]) * 1e-12, 1e-300), math.pi / 2)
    if not jet:
        A, B = arb(a), arb(b)  # floats: exact
        old = ctx.prec
        try:
            # the edge equation is affine in eps (one term): with eps the ball [-1, 1] one
            # evaluation encloses both signs' values, so two evaluations nearly always decide it
            ctx.prec = 64
            p, c = params()
            r, beta = p.r, p.beta
            outside = (
                E0(A, c, sgn, _EPS_BOTH, r, beta) < 0 and E0(B, c, sgn, _EPS_BOTH, r, beta) > 0
            )
            for prec in () if outside else (64, 128):  # each sign apart
                ctx.prec = prec
                p, c = params()
                r, beta = p.r, p.beta
                outside = (
                    E0(A, c, sgn, 1, r, beta) < 0
                    and E0(A, c, sgn, -1, r, beta) < 0
                    and E0(B, c, sgn, 1, r, beta) > 0
                    and E0(B, c, sgn, -1, r, beta) > 0
                )
                if outside:
                    break
        finally:
            ctx.prec = old
        if not outside:  # pragma: no cover - the float bracket is always this good
            a, b = -math.pi / 2, math.pi / 2
    if bm < NEAR_ONE:
        return _hump_near_one(n, P, fl, b, C, E0, check=not jet), P
    h = _Hump(
        D=lambda t: D0(t, *args()),
        dD=lambda t: D1(t, *args()),
        d2D=lambda t: D2(t, *args()),
        DdD=lambda t: D01(t, *args()),
        bend=lambda t: Bend(t, *args()),
        slope=lambda t: Slope(t, *args()),
        a=a,
        b=b,
        top=fl["top"],
        dtop=fl["dtop"],
        lo=fl["lo"],
        hi=fl["hi"],
        floor=theta_floor(bits, n),
        shifts=(0.0, n * math.pi / 2),
    )
    return h, P


def hump_box(
    n: int,
    lo: Fraction,
    hi: Fraction,
    Q: Fraction,
    damping: str,
    float_stage=None,
    system=PAPER,
):
    """The normal-form friction problem for every depth of ``[lo, hi]`` at once: ``D``, ``D'``,
    ``D''`` (in ``theta``, or ``y`` near ``m = 1``) enclosed by the mean-value form in ``m``,
    ``f(M) in f(mid) + f_m(M) (M - mid)``, with ``f_m`` from jets (:class:`verify.certify.Jet`)
    over the ball ``M`` of the range -- far tighter than evaluating with ``M`` itself, where the
    parameters' dependence on ``m`` is counted many times.  Any member of the family (``system``;
    its jets from :func:`verify.system_params.normal_jets`).  The bracket is the whole window
    (rounded outward).  The float stage is that of the middle."""
    mid = (lo + hi) / 2
    if float_stage is None:
        pm = normal_params(mid, Q, damping, _MATH, system)
        float_stage = normal_float_stage(n, pm)
        float_stage["bm"] = float(pm.bm)
    # the middle as an exact ball: arb arithmetic instead of long rationals
    fl = float_stage
    hm, _ = hump_normal(n, mid, Q, damping, 64, m_box=(mid, mid), float_stage=fl, system=system)
    hj, _ = hump_normal(
        n, mid, Q, damping, 64, m_box=(lo, hi), float_stage=fl, jet=True, system=system
    )
    if hj.variable != hm.variable:  # pragma: no cover - both follow the float stage's bm
        raise CertificationError("the middle and the jets use different variables")

    def dm():
        return depth_ball((lo, hi)) - (arb(mid.numerator) / mid.denominator)

    dM = AtPrecision(dm, box_prec((lo, hi)))

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
            sgn = sgn_of(n)
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


#: up to this many bits the friction edges go through :func:`_lean_normal` (above, Python's
#: bookkeeping is a negligible part of the work)
_LEAN_BITS = 4096
_START_BITS = 50  # quick_root's start_bits
_START_RAD = 2.0 ** (4 - _START_BITS)  # the relative radius of the interval Newton test's ball


def _lean_normal(req: Request, bits: int) -> Boundary | None:
    """The normal form with friction (``bits <= _LEAN_BITS``, any system) in one
    function: the steps of :func:`hump_normal` and :func:`_solve_hump` where everything succeeds
    at once -- the bracket proven by the two evaluations with both signs, both float edges
    refined and proven by the steps of :func:`verify.certify.quick_root` (the same balls: the
    parameters at each precision as ``hump_normal``'s ``args`` gives them), the shape by
    unimodality (:func:`_unimodal_shape`'s test) -- and the arithmetic of
    :func:`verify.enclosure.edges_result`.
    Where the float stage finds no interval, ``D < 0`` on the bracket proven by the first step of
    :func:`prove_negative` (no interval).
    ``None`` where a step does not succeed at once; the caller then runs the general path, which
    repeats these steps and goes on from there."""
    n = req.order
    D0, D1, D2, D01, E0, Bend, Slope = _lean_forms(-1 if n % 2 else 1)
    work = bits + QUICK_GUARD
    top = work if work > 80 else 80
    old = ctx.prec
    try:
        # the parameters and c = n pi/2 at the proof's precision, as hump_normal's AtPrecision
        # objects compute them (12 bits above it), without the NormalParams object (the same
        # balls): the paper's exact model, and the other members of the family
        ctx.prec = top + 12
        if req.system is PAPER and req.damping == "exact":  # normal_values' route for these
            r, r2, u, beta, w, g, _, dinv, bm = exact_arb_values(req.m, req.Q)
        else:
            r, r2, u, beta, w, g, _, dinv, bm = normal_values(
                req.m, req.Q, req.damping, _ARB, req.system
            )
        c = arb.pi() * n / 2
        if float(bm) < NEAR_ONE:
            return None
        beta_f = float(beta)
        fa, fb, tp, dtop, lo, hi, convex = wide_float_edges(
            n, float(r), float(r2), float(u), beta_f, float(g)
        )
        # the bracket (hump_normal's, its max and min written out: the same floats where none
        # is NaN; with a NaN the bracket's test fails there, and here)
        if not (fa == fa and fb == fb):
            return None
        span = fb - fa
        if span < 1e-300:
            span = 1e-300
        span *= 1e-6
        pad, pad2 = abs(fa) * 1e-12, abs(fb) * 1e-12
        a = fa - (span if span >= pad and span >= 1e-300 else pad if pad >= 1e-300 else 1e-300)
        b = fb + (span if span >= pad2 and span >= 1e-300 else pad2 if pad2 >= 1e-300 else 1e-300)
        if a < -_HALF_PI:
            a = -_HALF_PI
        if b > _HALF_PI:
            b = _HALF_PI
        A, B = arb(a), arb(b)  # floats: exact
        near = (c, r2, u, beta, g)
        if top <= 192:  # 2 * 64 + 64: args(64) takes the parameters as they are
            low, cache = near, None
        else:
            cache = {}
            low = _lean_args(cache, 64, top, near)
            ctx.prec = 76  # 64 + 12, as args(64)
            r = +r
        c64, _, _, beta64, _ = low
        sgn = _SGN[n & 3]  # exact: the same balls as with the int
        # the precision changes as few times as it can (setting it costs about as much as an
        # arb product): the bracket's test (64 bits) comes after the edges and the result's
        # arithmetic (at the proof's precision), next to the shape (64 bits) -- each test's
        # balls are those of the order where the bracket came first; a failed test returns
        # None either way
        if not dtop > 0:
            ctx.prec = 64
            if not (
                E0(A, c64, sgn, _EPS_BOTH, r, beta64) < _ZERO
                and E0(B, c64, sgn, _EPS_BOTH, r, beta64) > _ZERO
            ):
                return None
            # the float stage finds no interval: D < 0 on all of [a, b], on the balls args(64)
            # -- by Taylor's bound at the float maximiser where D'' < 0 on the whole bracket
            # (taylor_negative's, on all of [a, b]), else by the first step of prove_negative;
            # else the general path goes on
            if a <= tp <= b and _concave_negative(A.union(B), arb(tp), low, D01, D2, Bend):
                return no_interval(req, "certified", _FRICTION_REGIME)
            if prove_sign(
                lambda t: D0(t, *low),
                lambda t: D1(t, *low),
                a,
                b,
                -1,
                prec=64,
                budget=_NEGATIVE_BUDGET,
            ):
                return no_interval(req, "certified", _FRICTION_REGIME)
            return None
        if not (a < lo < tp < hi < b):  # (NaN compares false)
            return None
        tol = pow2(-bits)
        shift = n * math.pi / 2
        need = (bits + 4) // 2 + 1
        big = n * 1e-59
        Tp = arb(tp) if need > _START_BITS else None  # (the steps' bracket: none at few digits)
        # the lower edge: a zero of D; the upper one: of -D (quick_root's F and F')
        N1 = N2 = None
        ctx.prec = work
        for x0, left, right in ((lo, A, Tp), (hi, Tp, B)):
            x = arb(x0)  # (exact at any precision)
            acc = _START_BITS
            if acc < need:
                while acc < need:
                    acc = min(2 * acc - 8, need + 8)
                    prec = acc + 12
                    if cache is None:
                        cache = {}
                    at = _lean_args(cache, prec, top, near)
                    ctx.prec = prec
                    # -D for the upper edge: the step f/d is the same ball (both negated
                    # exactly, the quotient rounded towards zero), and so are the tests
                    f, d = D01(x, *at)
                    if not (d.is_finite() and f.is_finite()) or d.contains(0):
                        return None
                    x = (x - f / d).mid()
                    if not left < x < right:
                        return None
                ctx.prec = work
            if acc == _START_BITS and abs(x0) > big:
                # x is the float start (no step taken) and |x| is above the floor: the radius
                # |x| 2**(4 - acc) is an exact float, and the ball the one below
                X = arb(x0, abs(x0) * _START_RAD)
            else:
                size = abs(x)
                floor = theta_floor(bits, n)
                if floor > size:
                    size = floor
                X = arb(x, (size * pow2(4 - acc)).abs_upper())
            dX = Slope(X, c, r2, u, beta, g)  # of -D for the upper edge: the same quotient
            if _ZERO in dX or not dX.is_finite():  # (dX.contains(0), without converting 0)
                return None
            N = x - D0(x, c, r2, u, beta, g) / dX
            if not X.contains_interior(N):
                return None
            t = float(x) if acc != _START_BITS else x0  # (x = arb(x0) where no step was taken)
            s, s2 = abs(t), abs(t + shift)
            if s2 < s:
                s = s2
            # above n 1e-59 the floor (<= 3n 2**-201) and 1e-300 are below s (theta_scale); the
            # product of two exact balls, s and 2**-bits, is exact
            want = arb(s) if s > big else arb(max(s, theta_floor(bits, n), 1e-300))
            if not N.rad() <= want * tol:
                return None
            if N1 is None:
                N1 = N
            else:
                N2 = N
        # edges_result at the roots' precision: the parameters as they are at the proof's
        # precision, else rounded from there (AtPrecision with rounded=True)
        if work != top:  # the two fields used, as _rounded_params(pt, work) rounds them
            ctx.prec = work + 12
            w, dinv = +w, +dinv
            ctx.prec = work
        pi = arb.pi()
        half = _HALVES[n] if n < 8 else arb(n) * _HALF
        pw = pi * w
        T1, T2 = (half + N1 / pi) / w, (half + N2 / pi) / w
        if dinv.is_zero():
            d1, d2 = N1 / pw, N2 / pw
        else:
            hd = half * dinv
            d1, d2 = N1 / pw + hd, N2 / pw + hd
        if not (T1.rad() <= T1.abs_lower() * tol and T2.rad() <= T2.abs_lower() * tol):
            return None  # pragma: no cover - guard
        ctx.prec = 64
        # the bracket: D < 0 outside it (the edge equation's signs at its ends, both eps)
        if not (
            E0(A, c64, sgn, _EPS_BOTH, r, beta64) < _ZERO
            and E0(B, c64, sgn, _EPS_BOTH, r, beta64) > _ZERO
        ):
            return None
        # the shape: unimodality on [a, b] at 64 bits (_unimodal_shape's test, on args(64))
        if not _unimodal(
            A, B, N1, N2, Bend, D2, Slope, D0, args=low, pieces=3 if convex else 1, direct=convex
        ):
            return None
    finally:
        ctx.prec = old
    return from_balls(
        (T1, T2, d1, d2),
        order=n,
        m=req.m,
        Q=req.Q,
        damping=req.damping,
        digits=req.digits,
        method="certified",
        regime=_FRICTION_REGIME,
        system=req.system,
    )


_FRICTION_REGIME = "normal form with friction"


def _concave_negative(X: arb, t: arb, args: tuple, D01, D2, Bend) -> bool:
    """``D < 0`` on all of the ball ``X`` is proven by Taylor's bound at the point ``t`` of ``X``:
    where ``D'' <= -k < 0`` on ``X`` (``-D''/2 > 0`` in the sines, else ``D'' < 0``), ``D(x) <=
    D(t) + D'(t) (x - t) - k (x - t)^2 / 2 <= D(t) + D'(t)^2 / (2 k)`` (:func:`taylor_negative`'s
    bound, on one ball).  ``D01``, ``D2``, ``Bend``: the normal form's arb functions, evaluated
    with ``args``."""
    bend = Bend(X, *args)
    if bend > _ZERO:
        k = 2 * bend.lower()
    else:
        d2 = D2(X, *args)
        if not d2 < _ZERO:
            return False
        k = -d2.upper()
    Dt, D1t = D01(t, *args)
    return bool(Dt + D1t * D1t / (2 * k) < _ZERO)


def _lean_args(cache: dict, prec: int, top: int, near: tuple) -> tuple:
    """``(c, r2, u, beta, g)`` at ``prec`` bits for :func:`_lean_normal`, as hump_normal's
    ``args`` gives them: those of the proof's precision ``top`` as they are (``near``), or
    rounded from there (AtPrecision, rounded=True); kept in ``cache`` by precision.  Leaves
    ``flint.ctx.prec`` changed where it rounds (the caller sets it next)."""
    got = cache.get(prec)
    if got is None:
        if top <= 2 * prec + 64:
            got = near
        else:  # the fields used, each rounded as _rounded_params rounds it
            ctx.prec = prec + 12
            got = (+near[0], +near[1], +near[2], +near[3], +near[4])
        cache[prec] = got
    return got


_ZERO = arb(0)


def _rounded_params(pt, prec: int):
    """``pt`` rounded to ``prec`` bits as :class:`verify.enclosure.AtPrecision` does it for a
    lower precision (12 bits above it)."""
    old = ctx.prec
    ctx.prec = prec + 12
    try:
        return type(pt)(**{k: (+x if type(x) is arb else x) for k, x in vars(pt).items()})
    finally:
        ctx.prec = old


_HALF_PI = math.pi / 2
_UNIT = {1: arb(1), -1: arb(-1)}
_SGN = tuple(_UNIT[sgn_of(k)] for k in range(4))  # by n mod 4
_HALF = arb(0.5)
_HALVES = tuple(arb(k) * _HALF for k in range(8))  # n/2 as edges_result computes it (exact)


def normal_damped(req: Request) -> Boundary:
    bits = bits_for_digits(req.digits + 2)
    if bits <= _LEAN_BITS:
        lean = _lean_normal(req, bits)
        if lean is not None:
            return lean
    h, P = hump_normal(req.order, req.m, req.Q, req.damping, bits, system=req.system)
    regime = _FRICTION_REGIME
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
        return no_interval(req, "certified", regime, notes)
    lo_ball, hi_ball, ys = lo_root.ball, hi_root.ball, None
    if h.variable == "y":
        ys = (lo_ball, hi_ball)
    return edges_result(
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
    from .float_roots import damped_trace, trace_window_ends

    if m_box is None and n == 1 and tuple(regimes) == ("over", "over"):
        old = ctx.prec
        ctx.prec = 64
        try:
            none = overdamped_no_interval(trace_params(m, Q, _ARB, system))
        finally:
            ctx.prec = old
        if none:
            return None, none
    Tf = trace_params(m, Q, _MATH, system)
    scaled = False  # the float stage in D exp(-2 zeta) (past the double range)
    try:
        window = window or trace_window_ends(n, regimes, Tf)
    except OverflowError:  # D ~ exp(2 zeta) past the double range before the tail bound holds
        # the float stage takes D exp(-2 zeta) instead (the same signs and zeros, no overflow);
        # the window is proven on D itself, in balls
        window = trace_window_ends(n, regimes, Tf, scaled=True)
        scaled = True
    if window is None:
        why = (
            "both halves are critically or over-damped: only order 1 can exist"
            if regimes[1] != "under"
            else "no window"
        )
        return None, why
    # past the double range (at one depth) the proofs too take D exp(-2 zeta), the same signs
    # and zeros: the balls of D's terms, which grow like exp(2 zeta) and nearly cancel at the
    # upper edge, would need a fine bisection of a window hundreds of units wide
    form = trace_indicator_scaled(*regimes) if scaled else trace_indicator(*regimes)
    D0, D1, D2 = (form.compiled("arb", k) for k in (0, 1, 2))
    P = AtPrecision(
        lambda: _params_at(m, Q, None, m_box, partial(trace_params, system=system)),
        box_prec(m_box) if m_box else 0,
        rounded=True,
    )
    sigma = -1 if n % 2 else 1

    def args():
        p = P()
        return (sigma, p.kappa, p.nu1, p.nu2)

    funcs = [lambda z, F=F: F(z, *args()) for F in (D0, D1, D2)]
    if m_box is not None:  # the mean-value form in m (see hump_box), jets from the middle
        Pm = AtPrecision(
            lambda: _params_at(m, Q, None, (m, m), partial(trace_params, system=system)),
            box_prec((m, m)),
        )

        def jets():
            Qb = arb(Q.numerator) / Q.denominator
            return trace_params(Jet(depth_ball(m_box), 1), Jet(Qb), _ARB, system)

        Pj = AtPrecision(jets, box_prec(m_box))
        dM = AtPrecision(
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
            Tx = trace_params(x, Q, _MATH, system)
            try:
                wx = trace_window_ends(n, regimes, Tx, scaled=scaled)
            except OverflowError:
                wx = trace_window_ends(n, regimes, Tx, scaled=True)
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
    # the window's start: where P = 2 C1 C2 - kappa S1 S2 (> 0 before it) vanishes at one depth
    # (the float bisection leaves P(za) tiny); over a range of depths P's ball there is wide
    # (kappa grows like (1 - m)^-2), so the start is taken well inside P > 0: D < 0 there, the
    # window only grows.  Over a range of depths the ends' phases are balls as wide as the
    # phase's change over the range (near m = 1 a tenth of the range in 1 - m moves it by a
    # hundredth of pi): where the proof fails at a margin, wider ones are tried
    # (:data:`_RANGE_WIDEN`); any window the proof holds serves, holding the order's window
    for widen in (1e-9,) if m_box is None else _RANGE_WIDEN:
        wa = za * (1 - (widen if m_box is None or regimes[1] == "under" else _RANGE_START))
        wb = zb * (1 + widen)
        if _prove_window(n, regimes, P, wa, wb, m_box, m, Q, system):
            za, zb = wa, wb
            break
    else:  # (at a depth alone a guard: its window is proven at the first margin)
        raise CertificationError(f"could not prove the window of order {n}: {wa}, {wb}")
    fl = damped_trace(n, regimes, Tf, (za, zb), scaled=scaled)
    over = n == 1 and tuple(regimes) == ("over", "over")
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
        # order 1 with both halves over-damped: D < 0 right of a point by one test there
        # (:func:`overdamped_beyond`; P holds the depth, or every depth of the range)
        beyond=(lambda z: overdamped_beyond(P(), z)) if over else None,
    )
    return h, P


def trace_damped(req: Request, regimes) -> Boundary:
    bits = bits_for_digits(req.digits + 2)
    regime = f"trace form (half 1 {regimes[0]}, half 2 {regimes[1]})"
    h, P = hump_trace(req.order, req.m, req.Q, regimes, system=req.system)
    if h is None:
        return no_interval(req, "certified", regime, (P,))
    exists, lo_root, hi_root, shape = _solve_hump(req, h, bits)
    notes = [] if shape else ["the shape of the indicator in the window was not proven"]
    if not exists:
        return no_interval(req, "certified", regime, notes)
    return edges_result(
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


def newton_maximiser(dD, d2D, t, steps: int, rel, tiny=0):
    """The maximiser of ``D`` refined by Newton's method on ``D'`` from the ball ``t`` (ball
    midpoints, at the current precision): at most ``steps`` steps, stopping after one below
    ``|t| rel + tiny``, or where ``D''`` is 0 or a value is not finite.  Any point serves the
    proofs that use it; a better one makes them succeed."""
    for _ in range(steps):
        d1, d2 = dD(t).mid(), d2D(t).mid()
        if d2 == 0 or not d1.is_finite() or not d2.is_finite():
            break
        step = d1 / d2
        t = (t - step).mid()
        if abs(step) < abs(t) * rel + tiny:
            break
    return t


def phase_of(z, kappa, nu2, C1, S1, nu1=None):
    """The trace form's phase ``Phi = nu2 zeta + atan2(kappa S1, 2 nu2 C1)`` (half 2
    under-damped) from half 1's functions ``C1``, ``S1`` at ``zeta = z`` (balls or jets).

    ``atan2`` gives the continuous phase (``0`` at ``zeta = 0``, increasing wherever ``Phi``
    exceeds ``pi/2``, :mod:`verify.solve`) only while the point ``(2 nu2 C1, kappa S1)`` has not
    crossed the negative real axis.  With half 1 critically or over-damped ``C1 > 0``: never.
    With half 1 under-damped (``C1 = cos(nu1 zeta)``, ``S1 = sin(nu1 zeta)/nu1``, ``kappa > 0``)
    it crosses at ``nu1 zeta = pi``, where ``atan2`` falls by ``2 pi`` and the orders would be
    miscounted by two: ``nu1`` (a ball, given for an under-damped half 1) must then have ``nu1
    zeta < pi``, else :class:`ValueError` (not decided)."""
    if nu1 is not None and not bool(nu1 * z < arb.pi()):
        raise ValueError("half 1 under-damped past nu1 zeta = pi: the phase's atan2 has wrapped")
    return nu2 * z + _atan2(kappa * S1, 2 * nu2 * C1)


def tail_negative(kappa, a, z) -> bool:
    """``D < 0`` at every ``zeta >= z`` (balls ``kappa``, ``a``, ``z``): where ``|C_i| <= B_i`` and
    ``|S_i| <= zeta B_i`` with ``B_1 B_2 <= exp((2 - a) zeta)``, ``|sigma (2 C1 C2 - kappa S1 S2)|
    <= (2 + |kappa| zeta^2) exp((2 - a) zeta)`` and ``2 cosh(2 zeta) > exp(2 zeta)``, so ``D < 0``
    where ``(2 + |kappa| zeta^2) exp(-a zeta) < 1``; the bound decreases once ``a zeta > 2``."""
    tail = (2 + abs(kappa) * z * z) * (-a * z).exp()
    return bool(tail < 1 and z * a > 2)


def trace_phase(regimes, P, z, m_box=None, m=None, Q=None, system=PAPER) -> arb:
    """The phase ``Phi(zeta)`` of the trace form (half 2 under-damped), as a ball; with
    ``m_box`` (and its middle ``m``, and ``Q``) for every depth of the range, by the mean-value
    form in ``m`` (jets) instead of ``P``."""
    r1 = regimes[0]
    win = trace_window(r1).compiled("arb", 0), trace_window(r1).compiled("arb", 1)
    z = ball(z) if not isinstance(z, arb) else z

    def phase(p):
        C1 = win[0](z, 1, p.kappa, p.nu1, p.nu2)
        S1 = win[1](z, 1, p.kappa, p.nu1, p.nu2)
        # (over a range the jets give only the slope in m: the value is the middle's, checked)
        nu1 = p.nu1 if r1 == "under" and not isinstance(p.nu1, Jet) else None
        return phase_of(z, p.kappa, p.nu2, C1, S1, nu1)

    if m_box is None:
        return phase(P())
    with ctx.workprec(max(ctx.prec, box_prec(m_box))):
        Qb = arb(Q.numerator) / Q.denominator
        mid = phase(trace_params(m, Q, _ARB, system))
        jet = phase(trace_params(Jet(depth_ball(m_box), 1), Jet(Qb), _ARB, system))
        slope = jet.d if isinstance(jet, Jet) else 0
        return mid + slope * (depth_ball(m_box) - arb(m.numerator) / m.denominator)


#: how far inside ``P > 0`` the trace form's window starts over a range of depths (both halves
#: critically or over-damped: :func:`hump_trace`)
_RANGE_START = 0.05

#: the relative margins tried, in turn, around the trace form's window over a range of depths
#: (:func:`hump_trace`): the first is the one a range's proofs were built on; the wider ones
#: decide ranges next to ``m = 1`` and to critical damping, whose ends' phases are wide balls
_RANGE_WIDEN = (1e-3, 0.02, 0.1, 0.3, 0.6)


def overdamped_no_interval(p) -> str | None:
    """Order 1 has no interval at any period: both halves over-damped (``nu1, nu2 > 0``, the
    trace form's ``C_i = cosh(nu_i zeta)``, ``S_i = sinh(nu_i zeta)/nu_i``) and ``k = kappa/(2 nu1
    nu2)`` small enough; ``p`` holds the balls ``kappa``, ``nu1``, ``nu2`` (of one depth, or of
    every depth of a range).  The reason, as a result's note, where this is proven; else
    ``None``.  ``s = nu1 + nu2 < 2`` holds by the model: an over-damped half has ``nu_i =
    sqrt(gamma^2 - omega_i^2)/gamma < 1`` (``omega_i^2 > 0``), scaled by its share of the period
    (``2 D`` and ``2 (1 - D)``, :func:`verify.params.trace_params`), which sum to 2.  The
    first bound does not test it (over the balls of a range of depths it would often not be
    decided); the second one uses the ball of ``s`` and needs it below 2.

    With ``sigma = -1`` (order 1), ``s = nu1 + nu2``, ``d = nu1 - nu2`` and ``C1 C2 = (cosh(s
    zeta) + cosh(d zeta))/2``, ``nu1 nu2 S1 S2 = (cosh(s zeta) - cosh(d zeta))/2``::

        D = -(2 C1 C2 - kappa S1 S2) - 2 cosh(2 zeta)
          = (k - 1) cosh(s zeta) - (k + 1) cosh(d zeta) - 2 cosh(2 zeta).

    **k <= 3** (``kappa <= 6 nu1 nu2``).  For ``-1 <= k <= 3``: ``(k - 1) cosh(s zeta) <= 2
    cosh(s zeta) <= 2 cosh(2 zeta)`` (``k - 1 <= 2``; ``0 < s < 2``, ``zeta >= 0``), so ``D <=
    -(k + 1) cosh(d zeta)``, negative for ``k > -1``; and ``D = -2 cosh(s zeta) - 2 cosh(2
    zeta)`` for ``k = -1``.  For ``k < -1``: ``-(k + 1) cosh(d zeta) <= -(k + 1) cosh(s zeta)``
    (``|d| <= s``), so ``D <= -2 cosh(s zeta) - 2 cosh(2 zeta)``.

    **k > 1, by log-convexity** (sharper where ``s`` is below 2: it reaches past ``k = 3`` up to
    ``1 + 4/s`` and beyond).  ``log cosh`` is convex and 0 at 0, so ``cosh(l x) <= cosh(x)**l``
    for ``0 <= l <= 1``: with ``l = s/2`` and ``C = cosh(2 zeta) >= 1``, ``cosh(s zeta) <=
    C**l``; and ``cosh(d zeta) >= 1``.  So ``D <= h(C) = (k - 1) C**l - 2 C - (k + 1)`` (``k -
    1 > 0``, ``k + 1 > 0``), concave in ``C > 0`` with its maximum at ``C* = a**(1/(1 - l))``,
    ``a = (k - 1) l/2``, where ``(k - 1) C***l = 2 C*/l``: ``h <= h(C*) = 2 C* (1 - l)/l - (k +
    1)``, and ``h(1) = -4`` where ``C* <= 1`` (``a <= 1``).  Hence ``D < 0`` where ``a <= 1`` or
    ``log(2 (1 - l)/l) + log(a)/(1 - l) < log(k + 1)`` -- in logarithms, so that ``C*`` (huge as
    ``s -> 2``) is never formed.

    Either way ``D < 0`` for every ``zeta >= 0``: no interval of order 1."""
    nu1, nu2, kappa = p.nu1, p.nu2, p.kappa
    if not (nu1 > 0 and nu2 > 0):
        return None
    if kappa <= 6 * nu1 * nu2:
        return (
            "both halves are over-damped, with kappa <= 6 nu1 nu2 in the trace form: D < 0 "
            "at every period"
        )
    k = kappa / (2 * nu1 * nu2)
    lam = (nu1 + nu2) / 2
    if not (k > 1 and lam > 0 and lam < 1):
        return None
    a = (k - 1) * lam / 2
    if not a <= 1:
        bound = (2 * (1 - lam) / lam).log() + a.log() / (1 - lam)
        if not bound < (k + 1).log():
            return None
    return (
        "both halves are over-damped, with k = kappa/(2 nu1 nu2) below the bound by log-convexity "
        "(cosh(s zeta) <= cosh(2 zeta)**(s/2)) in the trace form: D < 0 at every period"
    )


def overdamped_beyond(p, z: float) -> bool:
    """Order 1, both halves over-damped: ``D < 0`` at every ``zeta >= z`` (``z > 0``), for every
    value in the balls ``kappa``, ``nu1``, ``nu2`` of ``p``.  With ``k``, ``s``, ``d`` as in
    :func:`overdamped_no_interval`, ``D = g(zeta) - (k + 1) cosh(d zeta)``, ``g(zeta) = (k - 1)
    cosh(s zeta) - 2 cosh(2 zeta)``, and ``0 < s < 2``, ``k > -1``.  Two tests at ``z``:

    - ``g(z) < 0``: ``cosh(2 zeta)/cosh(s zeta)`` increases (its logarithm's derivative is ``2
      tanh(2 zeta) - s tanh(s zeta) >= 0``), so ``g < 0`` from ``z`` on, and ``D <= g``.
    - ``g'(z) < 0`` and ``D(z) < 0``: ``sinh(2 zeta)/sinh(s zeta)`` increases too (``x coth x``
      increases, so ``2 coth(2 zeta) >= s coth(s zeta)``), so ``g' = (k - 1) s sinh(s zeta) - 4
      sinh(2 zeta) < 0`` from ``z`` on and ``g(zeta) <= g(z)``; with ``cosh(d zeta) >= cosh(d
      z)``, ``D(zeta) <= D(z) < 0``.  This one holds just past the maximiser of ``D``.

    Where the window's tail bound (:func:`_prove_window`) needs ``max(2, 1 + k) exp(-(2 - s)
    zeta) < 1``, far out as ``s -> 2``, these need no bisection of the range in between, whose
    balls of large, nearly cancelling terms take many pieces."""
    nu1, nu2, kappa = p.nu1, p.nu2, p.kappa
    if not (nu1 > 0 and nu2 > 0 and z > 0):
        return False
    s = nu1 + nu2
    k = kappa / (2 * nu1 * nu2)
    if not (s < 2 and k + 1 > 0):
        return False
    zb = arb(z)
    sz, tz = s * zb, 2 * zb
    g = (k - 1) * sz.cosh() - 2 * tz.cosh()
    if g < 0:
        return True
    falling = (k - 1) * s * sz.sinh() < 4 * tz.sinh()  # g' < 0 at z
    return bool(falling and g - (k + 1) * ((nu1 - nu2) * zb).cosh() < 0)


def prove_no_window(
    n: int, regimes, P, ztail: float, m_box=None, m=None, Q=None, system=PAPER
) -> bool:
    """Order ``n`` has no interval (half 2 under-damped): beyond ``ztail`` ``D < 0`` (the tail
    bound of :func:`verify.grid.trace_window_ends`), and below it the phase stays under ``n pi -
    pi/2`` (``Phi`` increases wherever it exceeds ``pi/2``: :mod:`verify.solve`), so the order's
    window does not begin."""
    if regimes[1] != "under":
        return n > 1
    with ctx.workprec(96):
        p = P()
        z2 = ball(ztail)
        pi = arb.pi()
        ph = trace_phase(regimes, P, z2, m_box, m, Q, system)
        return tail_negative(p.kappa, 2 - p.nu1, z2) and bool(ph < n * pi - pi / 2)


def _prove_window(n, regimes, P, za, zb, m_box=None, m=None, Q=None, system=PAPER) -> bool:
    """The window ends enclose the order's window (and nothing of the same parity beyond it);
    with ``m_box`` for every depth of that range (the phase by the mean-value form)."""
    r1, r2 = regimes
    with ctx.workprec(96):
        p = P()
        if r2 == "under":

            def phi(z):
                return trace_phase(regimes, P, ball(z), m_box, m, Q, system)

            pi = arb.pi()
            beyond = tail_negative(p.kappa, 2 - p.nu1, ball(zb)) or bool(
                phi(zb) > n * pi + pi / 2 and phi(zb) < (n + 1) * pi + pi / 2
            )
            return bool(phi(za) < n * pi - pi / 2 and phi(za) > (n - 1) * pi - pi / 2) and beyond
        form = trace_indicator(*regimes).compiled("arb", 0)
        z1 = ball(za)
        P1 = form(z1, 1, p.kappa, p.nu1, p.nu2) + 2 * (2 * z1).cosh()
        # D < 0 beyond zb: sigma (2 C1 C2 - kappa S1 S2) <= C1 C2 (2 + |kappa| zeta^2) (S_i <=
        # zeta C_i) with C1 C2 <= cosh(s zeta), s = nu1 + nu2, and 2 cosh(2 zeta) >= exp(a zeta)
        # cosh(s zeta): D < 0 where (2 + |kappa| zeta^2) exp(-a zeta) < 1, and for every larger
        # zeta once a zeta > 2 (the bound then decreases)
        a = 2 - p.nu1 - p.nu2
        z2 = ball(zb)
        beyond = tail_negative(p.kappa, a, z2)
        if not beyond and r1 == "over" and r2 == "over":
            # both over-damped: 2 C1 C2 + |kappa| S1 S2 = (1 + k) cosh(s zeta) + (1 - k)
            # cosh(d zeta) <= max(2, 1 + k) cosh(s zeta), k = |kappa|/(2 nu1 nu2): D < 0 where
            # max(2, 1 + k) exp(-a zeta) < 1, and beyond (a > 0)
            k = abs(p.kappa) / (2 * p.nu1 * p.nu2)
            top = k + 1 if k + 1 > 2 else arb(2) if k + 1 < 2 else (k + 1).union(arb(2))
            beyond = bool(p.nu1 > 0 and p.nu2 > 0 and a > 0) and bool(top * (-a * z2).exp() < 1)
        return bool(P1 > 0) and beyond
