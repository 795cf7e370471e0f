"""Model only what a scene needs: the cheapest method whose error provably meets a tolerance.

``boundary(order, m, tol=1e-8)`` (and ``paramres boundary --tol``, ``paramres table --tol``) asks
for both edges ``T/T0`` with **relative error at most** ``tol``: ``|returned - exact| <= tol
|exact|`` for each edge.  The engine picks the cheapest method that can meet it at that order,
depth and friction, says which one it used (``Boundary.method``), and proves the result against the
tolerance whatever the method.  The candidates, cheapest first (``paramres bench`` measures them;
the figures are in the README):

``series K=k``
    The edges as power series in ``m`` through ``m**k`` (:func:`analytic.expansions.edge_series`,
    no friction).  Their coefficients (polynomials in ``pi`` and ``1/pi``) are evaluated once per
    order to 45 digits, or more when needed (:func:`series_coefficients`), the series by Horner's
    rule in floats, or in mpmath when the tolerance is below about ``1e-12`` (then tried after
    the double path, :func:`choose`).  **Predicted error** (the "checked bound"): the next-term
    estimate

        e_k(m) = SAFETY (|c_{k+1}| m^{k+1} + |c_{k+2}| m^{k+2}) / T,

    the moduli of the next *two* coefficients (every edge of an even order is an even function of
    ``m``, so one of them may vanish; moduli, so that the two cannot cancel), times
    :data:`SAFETY`.  It is used only for ``m <= m_max(order, k)``, a range **established at first
    use from certified comparisons** (:func:`series_validity`): on log-spaced depths from
    ``1e-8`` to ``0.95``, the true error of the series (against :func:`verify.solve.boundary` at 50
    digits) must stay below ``SAFETY/2`` times the estimate at every depth up to ``m_max``; below
    the depths the references resolve, the estimate is the leading term of the error itself
    (asymptotic regime).  Nothing about the ranges is typed in: they are recomputed in every
    process, from the series and the certified solver.  The estimate only *chooses*; the proof
    below decides.
``double``
    For one point the double-precision float stage of the certified solver
    (:func:`verify.solve.float_edges`, safeguarded Halley per edge equation; up to
    :data:`NEAR_ONE_DEPTH`, above which it loses digits for order 1 and the polished grid costs
    more for a single point than the certified route); for a table the vectorised grid
    :func:`verify.grid.boundary_grid` for all points at once.  Predicted error
    :data:`DOUBLE_ERROR` (the grid's documented bound, checked by ``tests/test_grid.py``).
``certified (D digits)``
    :func:`verify.solve.boundary` with just enough digits, ``D = ceil(-log10(tol)) + 2``
    (:func:`certified_digits`), that its proven radius and the rounding of its printed digits
    stay below the tolerance.

**The proof** (:func:`prove_within`, no friction): for each returned value ``v`` the interval
``[v (1 - t), v (1 + t)]``, ``t = tol/(1 + tol)``, is mapped to ``theta`` (``theta = pi w T - n
pi/2``) and one edge equation ``F_eps`` (:func:`verify.derived.edge_equation`) is evaluated in
ball arithmetic (python-flint ``arb``, 64 bits or what the tolerance needs, more only if undecided)
at both ends: ``F_eps < 0`` at the left and ``> 0`` at the right end proves a root inside; by the
window theorem (``docs/theory.md``) ``F_eps`` has exactly one root in ``(-pi/2, pi/2)``, and it
is an edge.  The lower value must hold the root of one equation and the upper value the root of
the other; then the lower edge, the smaller root, lies within ``t v`` of the lower value and the
upper edge within ``t v`` of the upper one (also where the two intervals overlap, at a closing),
so the relative error is below ``t/(1 - t) = tol``.  A series or double value is proven to
:func:`fine_tolerance` (about ``tol/25``), so that the digits *printed* (only proven ones,
:func:`verify.solve.proven_text`, rounded) meet ``tol`` too; if the proof fails the next method
is tried (and a note says so).  Nothing unproven is returned.

**Cost** (``paramres bench``, interleaved measurements in one run; README): a series value costs
about a microsecond, the double stage ten; the proof costs tens of microseconds -- about what the
interval-Newton stage of the certified solver costs, which is itself "float start plus a
low-precision proof".  So for **one point** the automatic choice costs the same as the certified
route at the digits the tolerance needs (ratio 0.96-1.05 at tolerances 1e-8 and 1e-13), and some
20-45 % more where it ends on the certified route (the bookkeeping of the choice); it returns the
accuracy asked for and says how.  For **tables**, where the grid gives all double values in one
call, it costs 0.65-0.75 times the certified entries.  The choice is kept for one point because it
is not slower where it picks a series or the double path; a caller who wants the most digits for
the time asks for digits instead.

**With friction** the edges are zeros of the indicator, not of one equation each, and proving that
a double value is within ``tol`` needs the shape of the indicator on the whole window, which is
what the certified solve itself does: its float stage and proven bracket alone
(:func:`verify.solve.hump_normal`) cost 0.7 times the certified 15-digit result (measured
interleaved: 1.1-1.2 ms against 1.5-1.8 ms), and the shape proof a double value would need is the
rest.  So with ``Q`` the choice is always the certified route at just enough digits.  The series
near the threshold (:func:`analytic.thresholds.near_threshold_edges`) are benchmarked, not chosen:
they are not uniform as the depth approaches the threshold.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace
from fractions import Fraction
from functools import cache, lru_cache

import mpmath
import numpy as np
from flint import arb, ctx

from .certify import ball
from .derived import backend, edge_equation
from .inputs import DIGITS_RANGE, as_damping, as_depth, as_orders, as_quality, as_tolerance
from .methods import register_method
from .params import exact_fraction, normal_params

__all__ = [
    "Choice",
    "SERIES_TERMS",
    "SAFETY",
    "DOUBLE_ERROR",
    "NEAR_ONE_DEPTH",
    "series_coefficients",
    "series_value",
    "series_estimate",
    "series_validity",
    "fine_tolerance",
    "certified_digits",
    "choose",
    "prove_within",
    "boundary_auto",
    "boundaries_tol",
]

#: the series orders ``K`` (powers of ``m``) the choice may use
SERIES_TERMS = tuple(range(1, 9))
#: predicted error of a series = SAFETY x the next-term estimate; validated with SAFETY/2
SAFETY = 4.0
#: relative error of the double-precision paths (the grid's documented bound)
DOUBLE_ERROR = 1e-14
#: above this depth a single point skips the double path (the scalar float stage loses digits for
#: order 1 as m -> 1, and the polished grid costs more than the certified route for one point)
NEAR_ONE_DEPTH = 0.95
#: below this (fine) tolerance a series is evaluated in mpmath instead of floats
FLOAT_SERIES_TOL = 1e-13
#: rounding of a series evaluated in floats (relative; a few units in the last place)
FLOAT_ROUNDING = 1e-15
#: depths of the validation of the series ranges: 1, 2, 3, 5 times 10**-8 ... 10**-1, then
#: 0.7, 0.9, 0.95 (ascending, neighbours at most a factor 2 apart)
VALIDATION_DEPTHS = tuple(
    Fraction(mult, 10**k) for k in range(8, 0, -1) for mult in (1, 2, 3, 5)
) + (Fraction(7, 10), Fraction(9, 10), Fraction(95, 100))
#: digits of the references (and the mpmath evaluation of the series) in the validation
VALIDATION_DIGITS = 50

_ARB = backend("arb")


# ---------------------------------------------------------------------------------------------
# the series


def series_coefficients(order: int, digits: int = 45) -> dict[str, tuple]:
    """``{"lower": (c_0, ..., c_Kmax+2), "upper": ...}``: the coefficients of the frictionless edge
    series ``T/T0 = sum c_k m^k`` (:func:`analytic.expansions.edge_series` through
    ``m**(max(SERIES_TERMS) + 2)``) as mpmath numbers with ``digits`` correct digits (at least
    45; computed once per order and multiple of 50 digits).  ``"lower"`` is the edge that is lower
    at small ``m`` (the two swap past a closing)."""
    return _coefficients(order, max(45, -(-digits // 50) * 50))


@cache
def _coefficients(order: int, digits: int) -> dict[str, tuple]:
    import sympy as sp

    from analytic.expansions import edge_series
    from analytic.model import S

    top = max(SERIES_TERMS) + 2
    es = edge_series(order, top)
    out = {}
    with mpmath.workdps(digits + 5):
        for edge in ("lower", "upper"):
            poly = sp.Poly(sp.expand(es.in_T0[edge]), S.m)
            coeffs = [sp.Integer(0)] * (top + 1)
            for (k,), c in poly.terms():
                coeffs[k] = c
            out[edge] = tuple(mpmath.mpf(str(sp.N(c, digits + 5))) for c in coeffs)
    return out


@cache
def _float_coefficients(order: int) -> dict[str, tuple[float, ...]]:
    return {k: tuple(float(c) for c in v) for k, v in series_coefficients(order).items()}


def series_value(order: int, K: int, m, *, exact: bool = False):
    """The two series edges ``(lower, upper)`` through ``m**K``, sorted.

    ``m`` a float (or a float64 array: the result is then two arrays) with ``exact=False``; with
    ``exact=True`` ``m`` is exact (Fraction, str, mpf) and the series is evaluated in mpmath at
    the caller's precision, with coefficients to as many digits."""
    if exact:
        coeffs = series_coefficients(order, mpmath.mp.dps)
        mm = mpmath.mpf(m.numerator) / m.denominator if isinstance(m, Fraction) else mpmath.mpf(m)
        zero = mpmath.mpf(0)
    else:
        coeffs = _float_coefficients(order)
        mm, zero = m, 0.0 * m
    vals = []
    for edge in ("lower", "upper"):
        acc = zero
        for c in reversed(coeffs[edge][: K + 1]):
            acc = acc * mm + c
        vals.append(acc)
    if isinstance(mm, np.ndarray):
        return np.minimum(*vals), np.maximum(*vals)
    return min(vals), max(vals)


def series_estimate(order: int, K: int, m) -> float:
    """The next-term estimate ``|c_{K+1}| m^{K+1} + |c_{K+2}| m^{K+2}`` (the larger of the two
    edges'), absolute, in ``T/T0``; ``m`` a float or a float64 array."""
    a1, a2 = _next_terms(order)[K]
    return a1 * m ** (K + 1) + a2 * m ** (K + 2)


@cache
def _next_terms(order: int) -> dict[int, tuple[float, float]]:
    """``K -> (max |c_{K+1}|, max |c_{K+2}|)`` over the two edges (at least each edge's own
    estimate)."""
    co = _float_coefficients(order)
    return {
        K: (max(abs(c[K + 1]) for c in co.values()), max(abs(c[K + 2]) for c in co.values()))
        for K in SERIES_TERMS
    }


@cache
def series_validity(order: int) -> dict[int, float]:
    """``{K: m_max}``: the depths ``m <= m_max`` where the predicted error of the series through
    ``m**K`` is validated (``0.0``: nowhere).

    Derivation: for each depth of :data:`VALIDATION_DEPTHS` (ascending) the certified edges at
    :data:`VALIDATION_DIGITS` digits are compared with the series evaluated in mpmath at the same
    precision.  A depth passes if the true relative error is at most ``SAFETY/2`` times the
    next-term estimate (so the predicted error, ``SAFETY`` times the estimate, has a margin of two
    between the depths, which are a factor of at most 2 apart), or if the estimate is below what
    the references resolve (``1e-40``: the asymptotic regime, where the estimate is the leading
    term of the error).  ``m_max`` is the largest depth up to which every depth passes.
    """
    from .certified import boundary

    refs = {}
    result = {}
    floor = mpmath.mpf("1e-40")
    with mpmath.workdps(VALIDATION_DIGITS + 10):
        for K in SERIES_TERMS:
            m_max = 0.0
            for m in VALIDATION_DEPTHS:
                mm = mpmath.mpf(m.numerator) / m.denominator
                coeffs = series_coefficients(order).values()
                a1 = max(abs(c[K + 1]) for c in coeffs)
                a2 = max(abs(c[K + 2]) for c in coeffs)
                est = a1 * mm ** (K + 1) + a2 * mm ** (K + 2)
                lo, hi = series_value(order, K, m, exact=True)
                if est / lo >= floor:
                    if m not in refs:
                        refs[m] = boundary(order, m, digits=VALIDATION_DIGITS)
                    ref = refs[m]
                    err = max(abs(lo - ref.lower) / ref.lower, abs(hi - ref.upper) / ref.upper)
                    if not err <= SAFETY / 2 * est / lo:
                        break
                m_max = float(m)
            result[K] = m_max
    return result


# ---------------------------------------------------------------------------------------------
# the choice


@dataclass(frozen=True)
class Choice:
    """What :func:`choose` picked: ``kind`` (``"series"``, ``"double"``, ``"certified"``), the
    series order ``K`` or the ``digits``, and the predicted relative error (``None`` for the
    certified route, whose radius is proven directly)."""

    kind: str
    K: int | None = None
    digits: int | None = None
    predicted: float | None = None

    @property
    def label(self) -> str:
        if self.kind == "series":
            return f"series K={self.K}"
        if self.kind == "certified":
            return f"certified ({self.digits} digits)"
        return self.kind


def _neg_log(tol, base: float) -> float:
    """``-log(tol)`` in ``base`` (floats where ``tol`` is one, mpmath below ``1e-300``)."""
    f = float(tol)
    if f > 1e-300:
        return -math.log(f, base)
    with mpmath.workdps(20):
        return float(-mpmath.log(tol, base))


def _decades(tol) -> int:
    """``D = ceil(-log10(tol))``: ``10**-D <= tol < 10**(1-D)``."""
    return math.ceil(_neg_log(tol, 10) - 1e-12)


@lru_cache(maxsize=256)
def certified_digits(tol) -> int:
    """Digits for the certified route: ``D + 2`` (:func:`_decades`), so that its proven radius
    (below ``10**-(D+4)`` relative) and the rounding of the printed digits (half a unit of the
    ``(D+2)``-th) together stay below ``tol``."""
    lo, hi = DIGITS_RANGE
    return max(lo, min(hi, _decades(tol) + 2))


@lru_cache(maxsize=256)
def fine_tolerance(tol) -> mpmath.mpf:
    """The tolerance a series or double value is proven to where it can be: ``0.4 10**-(D+1)``
    (``D`` of :func:`_decades`, at most ``tol/25``).  Proven to it, the value prints with ``D+1``
    proven digits (:func:`verify.solve.proven_text`), whose rounding, half a unit of the last,
    stays below ``tol/2``: the printed numbers meet the tolerance too, not only the returned
    ones."""
    with mpmath.workprec(64):
        return mpmath.mpf("0.4") * mpmath.mpf(10) ** (-(_decades(tol) + 1))


def choose(order: int, m: Fraction, Q, tol, *, grid: bool = False) -> Choice:
    """The cheapest candidate predicted to meet the relative tolerance ``tol`` (see the module
    text), in the order of their measured cost:

    1. a series evaluated in floats: the lowest order ``K`` whose range holds ``m`` and whose
       predicted error is below half of :func:`fine_tolerance` (one or two more terms than
       ``tol`` itself needs, at no cost, so that the printed digits meet ``tol`` as well);
    2. the double path, if :data:`DOUBLE_ERROR` is below ``tol/4`` (for a single point only up
       to :data:`NEAR_ONE_DEPTH`; ``grid=True``: the polished grid's values, at every depth);
    3. a series evaluated in mpmath (where the fine tolerance is below what floats resolve);
    4. the certified route at :func:`certified_digits`.
    """
    tolf = float(tol)
    if Q is None:
        mf = float(m)
        goal = float(fine_tolerance(tol))
        in_floats = goal >= FLOAT_SERIES_TOL
        K = _series_order(order, mf, goal, FLOAT_ROUNDING if in_floats else 0.0)
        if K is not None and in_floats:
            return Choice("series", K=K[0], predicted=K[1])
        if DOUBLE_ERROR <= tolf / 4 and (grid or mf <= NEAR_ONE_DEPTH):
            return Choice("double", predicted=DOUBLE_ERROR)
        if K is not None:
            return Choice("series", K=K[0], predicted=K[1])
    return Choice("certified", digits=certified_digits(tol))


def _series_order(order: int, mf: float, goal: float, rounding: float):
    """``(K, predicted)`` for the lowest series order predicted within ``goal/2``, or ``None``."""
    valid = series_validity(order)
    scale = None
    for K in SERIES_TERMS:
        if mf > valid[K]:
            continue
        est = SAFETY * series_estimate(order, K, mf)
        if scale is None:  # |T| from the series itself (T -> 0 for order 1 as m -> 1)
            scale = abs(series_value(order, max(SERIES_TERMS), mf)[0])
        if est > goal * scale:  # cannot pass even with the most favourable |T|
            continue
        lo = abs(series_value(order, K, mf)[0])
        pred = est / lo + rounding if lo > 0 else math.inf
        if pred <= goal / 2:
            return K, pred
    return None


# ---------------------------------------------------------------------------------------------
# the proof


def _sgn(n: int) -> int:
    """``sin(n pi/2)`` (odd ``n``) or ``cos(n pi/2)`` (even ``n``): ``(-1)**(n // 2)`` for both."""
    return -1 if (n // 2) % 2 else 1


def prove_within(order: int, m: Fraction, values, tol, *, max_bits: int | None = None):
    """Prove (no friction) that the two values ``(lower, upper)`` (floats or mpf, ``lower <=
    upper``) are each within relative ``tol`` of the corresponding exact edge ``T/T0`` of order
    ``order`` at the exact depth ``m``.  Returns the working precision (bits) of the proof, or
    ``None`` if it did not succeed (not disproven: the value may be right but not provably so at
    ``max_bits``).  See the module text for the argument."""
    proof = _prove(order, m, values, tol, max_bits)
    return None if proof is None else proof[0]


def _prove(order: int, m: Fraction, values, tol, max_bits=None):
    """:func:`prove_within`, returning ``(bits, w, t, balls)`` (``w = omega_av/omega0``, ``t =
    tol/(1 + tol)`` and the values as balls at ``bits``, for the result) or ``None``."""
    bits = max(64, math.ceil(_neg_log(tol, 2)) + 32)
    max_bits = max_bits or 4 * bits
    while bits <= max_bits:
        outcome, data = _prove_at(order, m, values, tol, bits)
        if outcome == 1:
            return (bits, *data)
        if outcome == -1:
            return None
        bits *= 2
    return None


def _prove_at(n: int, m: Fraction, values, tol, bits: int) -> tuple[int, tuple]:
    """One attempt of :func:`prove_within` at ``bits``: 1 proven, -1 disproven, 0 undecided;
    and ``(w, t, balls)``."""
    F = edge_equation(-1 if n % 2 else 1).compiled("arb", 0)
    sgn = _sgn(n)
    with ctx.workprec(bits):
        p = normal_params(m, None, "exact", _ARB)
        half_pi = arb.pi() / 2
        c = half_pi * n
        tb = ball(tol)
        t = tb / (1 + tb)
        scale = 2 * half_pi * p.w
        vb = [arb(v) if isinstance(v, float) else ball(v) for v in values]
        ends = [(scale * v * (1 - t) - c, scale * v * (1 + t) - c) for v in vb]
        known: dict[tuple[int, int], int] = {}

        def status(i, k):
            if (i, k) not in known:
                left, right = ends[i]
                known[i, k] = _bracket_status(F, left, right, c, sgn, (1, -1)[k], p, half_pi)
            return known[i, k]

        # the lower value holds the root of one equation, the upper value that of the other
        undecided = False
        for k in (0, 1):
            first = status(0, k)
            if first == 1 and status(1, 1 - k) == 1:
                return 1, (p.w, t, vb)
            undecided = undecided or first == 0 or known.get((1, 1 - k)) == 0
    return (0 if undecided else -1), (p.w, t, vb)


def _bracket_status(F, left, right, c, sgn, eps, p, half_pi) -> int:
    """``1``: the root of ``F_eps`` in the window is proven inside ``[left, right]``; ``-1``:
    proven outside; ``0``: undecided at this precision."""
    # left end: root > left if left < -pi/2 (window) or F(left) < 0 with left < pi/2
    if left < -half_pi:
        lo_state = 1
    else:
        fl = F(left, c, sgn, eps, p.r, p.beta)
        if left < half_pi and fl < 0:
            lo_state = 1
        elif left > -half_pi and left < half_pi and fl > 0:
            lo_state = -1
        else:
            lo_state = 0
    if lo_state == -1:
        return -1
    if right > half_pi:
        hi_state = 1
    else:
        fr = F(right, c, sgn, eps, p.r, p.beta)
        if right > -half_pi and fr > 0:
            hi_state = 1
        elif right > -half_pi and right < half_pi and fr < 0:
            hi_state = -1
        else:
            hi_state = 0
    if hi_state == -1:
        return -1
    return 1 if lo_state == 1 and hi_state == 1 else 0


# ---------------------------------------------------------------------------------------------
# the results


def _double_values(order: int, m: Fraction) -> tuple[float, float]:
    from .undamped import float_edges

    return float_edges(order, m)


def _tol_text(x) -> str:
    f = float(x)
    return f"{f:.2g}" if f > 1e-300 else mpmath.nstr(x, 2)


def _from_values(req, choice: Choice, values, tol, proof, notes) -> object:
    """A :class:`verify.solve.Boundary` for values proven within ``tol``: radii ``t |v|``, the
    offsets from ``n T_av/2`` computed in ball arithmetic (their radius adds that of ``T_av``),
    and as many digits as the tolerance supports."""
    from .certify import to_mpf, upper_mpf
    from .result import Boundary

    n = req.order
    bits, w, t, vb = proof
    with ctx.workprec(bits):
        half_tav = arb(n) / (2 * w)  # w = w0 without friction: n T_av/2 in units of T0
        rads = [t * abs(v) for v in vb]
        offsets = [v - half_tav for v in vb]
        encl = [
            (to_mpf((v - r).lower()), to_mpf((v + r).upper()))
            for v, r in zip(vb, rads, strict=True)
        ]
        rad_T = [upper_mpf(r) for r in rads]
        rad_d = [upper_mpf(r + d.rad()) for r, d in zip(rads, offsets, strict=True)]
        deltas = [to_mpf(d) for d in offsets]
    vals = [v if isinstance(v, mpmath.mpf) else mpmath.mpf(v) for v in values]  # exact
    digits = max(1, math.floor(_neg_log(tol, 10) - math.log10(2) + 1e-9))
    why = (
        f"|error| <= {_tol_text(tol)} relative, proven: each edge equation changes sign on "
        f"[v(1 - t), v(1 + t)] (ball arithmetic, {bits} bits) and has one root in the window"
    )
    pred = f"predicted error {choice.predicted:.1e} ({choice.label})"
    return Boundary(
        order=n,
        m=req.m,
        Q=req.Q,
        damping=req.damping,
        digits=digits,
        method=choice.label,
        exists=True,
        lower=vals[0],
        upper=vals[1],
        delta_lower=deltas[0],
        delta_upper=deltas[1],
        radius=max(rad_T),
        lower_enclosure=encl[0],
        upper_enclosure=encl[1],
        certified=True,
        regime="per-edge equations",
        notes=tuple(notes) + (pred, why),
        radii=(rad_T[0], rad_T[1], rad_d[0], rad_d[1]),
    )


def _certified(req, tol, notes=()):
    """The certified route at just enough digits, its radius checked against ``tol``."""
    from . import certified as _registers  # noqa: F401  (registers "certified": the table's

    # tolerance path reaches here without the dispatcher verify.solve, which imports it)
    from .methods import METHODS
    from .request import Request

    digits = certified_digits(tol)
    while True:
        sub = Request(req.order, req.m, req.Q, req.damping, digits, req.m_input)
        res = METHODS["certified"](sub)
        choice = Choice("certified", digits=digits)
        if not res.exists:
            return replace(res, method=choice.label, notes=tuple(notes) + res.notes)
        t = _safe_t(tol)
        ok = all(
            rad <= t * abs(v) for rad, v in zip(res.radii[:2], (res.lower, res.upper), strict=True)
        )
        if ok or digits >= DIGITS_RANGE[1]:
            break
        digits = min(DIGITS_RANGE[1], digits + 5)  # pragma: no cover - the radius is 100x smaller
    note = f"|error| <= {_tol_text(tol)} relative: proven radius {_tol_text(res.radius)}"
    return replace(res, method=choice.label, notes=tuple(notes) + res.notes + (note,))


@lru_cache(maxsize=256)
def _safe_t(tol) -> mpmath.mpf:
    """``tol/(1 + tol)`` rounded down by a margin that covers the rounding of the comparison
    ``radius <= t |v|`` at the default precision."""
    with mpmath.workprec(80):
        return +(tol / (1 + tol) * (1 - mpmath.mpf(2) ** -40))


def _attempt(req, choice: Choice, tol, double=None):
    """Values for a series or double choice, or ``None``."""
    n, m = req.order, req.m
    if choice.kind == "series":
        if float(fine_tolerance(tol)) >= FLOAT_SERIES_TOL:
            return series_value(n, choice.K, float(m))
        with mpmath.workdps(certified_digits(tol) + 5):
            return series_value(n, choice.K, m, exact=True)
    return double if double is not None else _double_values(n, m)


def boundary_auto(req, *, double=None):
    """``boundary(..., tol=...)``: the request's ``tol`` met by the cheapest method that proves it
    (see the module text).  ``double``: precomputed double values of the polished grid (tables),
    else the scalar float stage is used."""
    tol = req.tol
    choice = choose(req.order, req.m, req.Q, tol, grid=double is not None)
    notes = []
    fine = fine_tolerance(tol)
    while choice.kind != "certified":
        values = _attempt(req, choice, tol, double)
        if all(_finite(v) for v in values):
            proof = _prove(req.order, req.m, values, fine)
            if proof is not None:
                return _from_values(req, choice, values, fine, proof, notes)
        notes.append(f"{choice.label} was not proven within tol/25; next method tried")
        floats = choice.kind == "series" and float(fine) >= FLOAT_SERIES_TOL
        if floats and DOUBLE_ERROR <= float(tol) / 4 and (double or req.m <= NEAR_ONE_DEPTH):
            choice = Choice("double", predicted=DOUBLE_ERROR)
        else:
            break
    return _certified(req, tol, notes)


def _finite(v) -> bool:
    return mpmath.isfinite(v) if isinstance(v, mpmath.mpf) else math.isfinite(v)


def boundaries_tol(orders, ms, *, Q=None, damping="exact", tol, progress=None) -> list:
    """:func:`boundary_auto` for every order and depth (a table: rows ordered by order, then
    depth); the double values of all points come from one call of the vectorised grid.
    ``progress`` wraps the iteration (e.g. :func:`reports.output.progress`)."""
    from .request import Request

    orders = as_orders(orders)
    QQ = as_quality(Q)
    model = as_damping(damping)
    tol = as_tolerance(tol)
    ms = [exact_fraction(as_depth(m)) for m in ms]
    QF = None if QQ is None else exact_fraction(QQ)
    grid = None
    if QQ is None and DOUBLE_ERROR <= float(tol) / 4:
        from .grid import boundary_grid

        grid = boundary_grid(orders, ms)  # the exact depths
    tasks = [(i, j) for i in range(len(orders)) for j in range(len(ms))]
    it = progress(tasks) if progress is not None else tasks
    out = []
    for i, j in it:
        req = Request(orders[i], ms[j], QF, model, certified_digits(tol), ms[j], tol=tol)
        double = None if grid is None else (float(grid[i, 0, j]), float(grid[i, 1, j]))
        out.append(boundary_auto(req, double=double))
    return out


register_method("auto")(lambda req: boundary_auto(req))
