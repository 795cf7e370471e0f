"""The edges of every interval of instability as power series in the depth ``m``, for any order.

Without friction each edge is the root of one per-edge factor of the normal form
(:func:`analytic.normal_form.edge_factor`, step 6): ``f(x) - eps r f(beta x)`` with ``f = cos`` for
odd orders, ``sin`` for even ones, ``x = n pi/2 + theta`` and ``theta = omega_av Delta T / 2``.  For
every order ``f(n pi/2 + theta) = c_n sin(theta)`` with ``c_n = -sin(n pi/2)`` (odd) or ``cos(n
pi/2)`` (even), ``c_n = +-1``, so each factor is ``c_n`` times

    sin(theta) - delta r f(beta (n pi/2 + theta)),        delta = eps c_n.

At small ``m`` the right-hand side has the sign of ``delta`` (``r > 0``, ``f(beta n pi/2) > 0``), so
``delta = -1`` is the **lower** edge and ``delta = +1`` the upper one, for every order; the factor
of the paper's eq. (13)/(25) (``eps = +1``) is the lower edge when ``c_n = -1`` (``n = 1, 2, 5, 6,
9, 10, ...``) and the upper edge when ``c_n = +1`` (``n = 3, 4, 7, 8, ...``).

The parameters ``r, beta, w`` are those of :func:`analytic.normal_form.parameters` (their
definitions through ``omega_1, omega_2`` and ``q``), expanded in ``m`` by evaluating the sympy
definitions in exact series arithmetic (:mod:`analytic.powerseries`); the equation is then solved
for the series ``theta(m)`` by Newton steps on series (each step doubles the number of correct
coefficients), and converted:

    T/T_av = n/2 + theta/pi,        T/T0 = (T/T_av) / w,        w = omega_av/omega_0.

Coefficients are polynomials in ``pi`` and ``1/pi`` with rational coefficients; with ``order="odd"``
or ``"even"`` they are polynomials in the symbol ``n`` as well (the closed forms for all odd / all
even orders).  The symmetry ``m -> -m`` (it swaps the two halves, a shift of time by ``T/2``) makes
every edge of an even order, and the centre of an odd one, an even function of ``m``, and the half
width of an odd order an odd function: the tests check this on the output.

With friction (``Q`` given) the edges exist only above a threshold; their expansion in the
distinguished scaling is :mod:`analytic.thresholds`, and :func:`edge_series` hands over to it.
"""

from __future__ import annotations

from functools import cache

import sympy as sp

from .model import Damping, S
from .normal_form import edge_factor, parameters
from .powerseries import LaurentRing, Series, evaluate, newton
from .series_result import _PARITY_WORDS, MAX_TERMS, EdgeSeries, _check_order, _check_terms
from .stitching import Parity

__all__ = [
    "EdgeSeries",
    "edge_series",
    "edge_equation",
    "small_m_parameters",
    "closed_forms",
    "order_sign",
    "theta_series",
    "MAX_TERMS",
]


def _ring(symbolic_n: bool) -> LaurentRing:
    return LaurentRing(["pi", "n"] if symbolic_n else ["pi"])


def _param_symbol(name: str) -> sp.Symbol:
    return {"r": S.r, "beta": S.beta}[name]


@cache
def small_m_parameters(prec: int, symbolic_n: bool = False) -> dict[str, Series]:
    """``r, r^2, beta, w, 1/w`` (no friction) as series in ``m`` through ``m**prec``, expanded from
    the definitions in :func:`analytic.normal_form.parameters` (not from the closed relations in
    ``beta``; those are checked against these in the tests)."""
    ring = _ring(symbolic_n)
    defs = {k.name: v for k, v in parameters(Damping.NONE).items()}
    out = {}
    out["r^2"] = evaluate(defs["r^2"], {}, ring, prec + 1, var=S.m)
    out["r"] = out["r^2"].rational_power(sp.Rational(1, 2)).truncate(prec)
    out["beta"] = evaluate(defs["beta"], {}, ring, prec, var=S.m)
    out["w"] = evaluate(defs["w"], {}, ring, prec, var=S.m)
    out["1/w"] = out["w"].inverse()
    out["r^2"] = out["r^2"].truncate(prec)
    return out


def order_sign(n) -> int | sp.Expr:
    """``c_n`` with ``f(n pi/2 + theta) = c_n sin(theta)`` (derived by sympy's trigonometric
    reduction; for ``"odd"``/``"even"`` in terms of ``k`` with ``n = 2k+1`` / ``n = 2k``)."""
    th = S.theta
    if isinstance(n, str):
        k = sp.Symbol("k", integer=True)
        parity = _PARITY_WORDS[n]
        nn = 2 * k + 1 if parity is Parity.ODD else 2 * k
    else:
        parity, nn = Parity.of(n), n
    f = sp.cos if parity is Parity.ODD else sp.sin
    reduced = sp.expand_trig(f(nn * sp.pi / 2 + th))
    c = sp.simplify(reduced / sp.sin(th))
    if c.has(th):  # pragma: no cover - the reduction is an identity of sympy's trigonometry
        raise AssertionError(f"f(n pi/2 + theta) is not a multiple of sin(theta): {reduced}")
    return int(c) if c.is_Integer else c


def edge_equation(n, delta: int) -> sp.Expr:
    """``sin(theta) - delta r f(beta (n pi/2 + theta))`` for order ``n`` (int, or
    ``"odd"``/``"even"`` with the symbol ``n``); ``delta = -1`` is the lower edge at small ``m``,
    ``+1`` the upper.

    For an integer order the expression is the per-edge factor of
    :func:`analytic.normal_form.edge_factor` with ``eps = delta c_n``, divided by ``c_n``; the test
    suite checks that identity for the orders it uses.
    """
    th = S.theta
    if isinstance(n, str):
        parity, nn = _PARITY_WORDS[n], S.n
    else:
        parity, nn = Parity.of(n), n
    x = nn * sp.pi / 2 + th
    f = sp.cos if parity is Parity.ODD else sp.sin
    return sp.sin(th) - delta * S.r * f(S.beta * x)


def factor_for(n: int, delta: int) -> tuple[int, sp.Expr]:
    """``(eps, factor)``: the per-edge factor (step 6) whose root is edge ``delta`` of order
    ``n``."""
    c = order_sign(n)
    eps = delta * c
    th = S.theta
    x = n * sp.pi / 2 + th
    return eps, edge_factor(Parity.of(n), eps, symbols=(x, S.beta * x, S.r))


@cache
def theta_series(n, delta: int, prec: int) -> Series:
    """``theta(m)`` through ``m**prec`` on the edge ``delta`` of order ``n`` (no friction)."""
    symbolic = isinstance(n, str)
    ring = _ring(symbolic)
    par = small_m_parameters(prec, symbolic)
    eq = edge_equation(n, delta)
    deq = sp.diff(eq, S.theta)
    env = {S.r: par["r"], S.beta: par["beta"], S.n: "n"}

    def at(expr, th: Series) -> Series:
        e = dict(env)
        e[S.theta] = th
        return evaluate(expr, e, ring, prec, var=S.m)

    start = Series.constant(ring, ring.zero, prec)
    return newton(lambda th: at(eq, th), lambda th: at(deq, th), start)


def _to_period(n, theta: Series, inv_w: Series | None) -> Series:
    ring = theta.ring
    half_n = (
        ring.scale(ring.gen("n"), sp.Rational(1, 2))
        if isinstance(n, str)
        else ring.const(sp.Rational(n, 2))
    )
    tav = theta.scale_coeff(ring.gen("pi", -1)) + Series.constant(ring, half_n, theta.prec)
    return tav if inv_w is None else tav * inv_w


def edge_series(
    order,
    terms: int = 4,
    *,
    units: str = "T0",
    Q=None,
    damping: str = "exact",
    system=None,
    duty="1/2",
) -> EdgeSeries:
    """The two edges of the interval of order ``order`` through ``m**terms``.

    ``order``: an integer ``>= 1``, or ``"odd"``/``"even"`` for the closed forms in the symbol ``n``
    (valid for every order of that parity).  ``units``: ``"T0"`` or ``"Tav"``.  Without ``Q``: the
    frictionless edges.  With ``Q`` (and ``damping`` ``"paper"`` or ``"exact"``): the edges in the
    distinguished scaling of :mod:`analytic.thresholds` (``1/Q`` of order ``m`` for odd orders,
    ``m**2`` for even ones), as expressions in ``m`` valid above the threshold.

    ``system``, ``duty``: another member of the family (:mod:`analytic.system`; a name or a
    :class:`~analytic.system.System`, which passes through), integer orders only: frictionless
    series from :mod:`analytic.family_series`, with ``Q`` the edges above the threshold from
    :func:`analytic.thresholds.near_threshold_edges` (scaling ``1/Q ~ m^p``).  A custom system
    has no depth and is refused.
    """
    from paramres.inputs import InputError, as_damping, as_quality

    from .system import system as as_system

    order = _check_order(order)
    terms = _check_terms(terms)  # the widest range first: a bad value names the general limit
    if units not in ("T0", "Tav"):
        raise InputError(f"units {units!r} is not one of: T0, Tav")
    Qv = as_quality(Q)
    model = as_damping(damping)
    sysv = as_system("pendulum" if system is None else system, duty=duty)
    if not sysv.is_paper:
        if not sysv.uses_depth:
            raise InputError("a custom system has no depth: there is no series in m")
        if isinstance(order, str):
            raise InputError(
                f"closed forms in n (--order odd/even) are for the paper's system; give an integer "
                f"order for {sysv.label}"
            )
        if Qv is not None:
            from .thresholds import near_threshold_edges

            _check_terms(terms, "friction")
            return near_threshold_edges(order, terms, Q=Qv, damping=model, units=units, system=sysv)
        from .family_series import family_edge_series

        _check_terms(terms, "family")
        return family_edge_series(order, terms, units, sysv)
    if Qv is not None:
        from .thresholds import near_threshold_edges

        _check_terms(terms, "friction")
        return near_threshold_edges(order, terms, Q=Qv, damping=model, units=units)
    _check_terms(terms, "parity" if isinstance(order, str) else "frictionless")
    return _frictionless(order, terms, units)


@cache
def _frictionless(order, terms: int, units: str) -> EdgeSeries:
    symbolic = isinstance(order, str)
    par = small_m_parameters(terms, symbolic)
    syms = {"n": S.n}
    m = S.m
    in_T0, in_Tav, theta = {}, {}, {}
    for name, delta in (("lower", -1), ("upper", 1)):
        th = theta_series(order, delta, terms)
        theta[name] = th.to_sympy(m, syms)
        in_Tav[name] = _to_period(order, th, None).to_sympy(m, syms)
        in_T0[name] = _to_period(order, th, par["1/w"]).to_sympy(m, syms)
    lower_factor = None if symbolic else -order_sign(order)
    notes = (
        "per-edge factor of the normal form, solved by Newton steps on exact power series in m",
        "T/T_av = n/2 + theta/pi, T/T0 = (T/T_av)/w, parameters expanded from their definitions",
    )
    return EdgeSeries(order, terms, units, in_T0, in_Tav, theta, lower_factor, notes=notes)


def closed_forms(terms: int = 4) -> dict[str, dict[str, sp.Expr]]:
    """Leading half-width and centre shift for all odd and all even orders (symbol ``n``).

    For each parity: ``lower``/``upper`` (in ``T0`` and ``T_av``), ``width`` (``T_+ - T_-``),
    ``centre`` (``(T_+ + T_-)/2 - n T0/2`` in ``T0``, ``- n T_av/2`` in ``T_av``), each a series
    through ``m**terms``; and the leading terms ``width_leading``, ``centre_leading``.
    """
    out = {}
    m = S.m
    for word in ("odd", "even"):
        es = _frictionless(word, terms, "T0")
        d = {}
        for units, src in (("T0", es.in_T0), ("Tav", es.in_Tav)):
            width = sp.expand(src["upper"] - src["lower"])
            centre = sp.expand((src["upper"] + src["lower"]) / 2 - S.n / 2)
            d[f"lower_{units}"] = src["lower"]
            d[f"upper_{units}"] = src["upper"]
            d[f"width_{units}"] = width
            d[f"centre_{units}"] = centre
            d[f"width_leading_{units}"] = _leading(width, m)
            d[f"centre_leading_{units}"] = _leading(centre, m)
        out[word] = d
    return out


def _leading(expr: sp.Expr, var: sp.Symbol) -> sp.Expr:
    poly = sp.Poly(sp.expand(expr), var)
    if poly.is_zero:
        return sp.Integer(0)
    for k in range(poly.degree() + 1):
        c = poly.coeff_monomial(var**k)
        if c != 0:
            return sp.factor(c) * var**k
    return sp.Integer(0)  # pragma: no cover
