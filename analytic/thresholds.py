"""Friction: the threshold depth of every interval and its edges near the threshold, in both models.

With friction the normal form (:func:`analytic.normal_form.order_form`) is

    N(theta) = sin^2(theta) - R(theta),
    R = r^2 f(beta x)^2 - (1 - r^2) sinh^2(g x),      x = n pi/2 + theta,

unstable where ``N < 0``.  At small ``m``, ``r ~ 3m/2``, ``f(beta n pi/2) ~ 1`` (odd) or
``~ n pi m/4`` (even), and ``g x ~ n pi/(4Q)``; the two terms of ``R`` balance when ``1/Q`` is of
order ``m`` (odd orders) or ``m^2`` (even orders).  These are the **distinguished scalings**: put
``1/Q = lam m^p`` (``p = 1`` odd, ``2`` even) and ``theta = m^p u``; then ``N / m^(2p)`` is a power
series in ``m`` whose leading term is ``u^2 - (A - B lam^2)``.

* **Threshold.** The interval exists where ``max_theta (R - sin^2 theta) > 0``; it closes where the
  maximum is zero: ``N = 0`` and ``dN/dtheta = 0`` together (a double root, the tangency).  Solving
  the two for ``lam(m)`` and ``u(m)`` as series (Newton steps with the leading-order Jacobian, one
  order gained per step) gives ``Q_min(m) = 1/(lam(m) m^p)``, and by series reversion ``m_min(Q)``.
  The leading term is ``lam_0 = sqrt(A/B)``: ``m_min = n pi/(6Q)`` for odd ``n`` (eq. 38 for
  ``n = 1``, the paper's ``pi/(2Q)`` for ``n = 3``), ``m_min = sqrt(2/(3Q))`` for every even ``n``
  (eq. 43 for ``n = 2``).  The double root is not at exact tuning: ``theta* = -9 m^2/(2 pi n)`` for
  odd orders (a shorter period loses less to friction), ``O(m^6)`` for even ones; so the printed
  conditions (37), (42), which set the radicand to zero at exact tuning, are exact only at leading
  order (:func:`tuning_threshold` gives what they imply).
* **Edges near the threshold.** With ``lam = lam_0 nu`` (``nu = (m_min0/m)^p`` the leading threshold
  over the depth) and ``s = sqrt(1 - nu^2)``, the leading equation is ``u^2 = A - B lam_0^2 nu^2 = A
  s^2``, so ``u = +- sqrt(A) s + O(m)`` (``sqrt(A) = 3/2`` odd, ``3 n pi/8`` even); Newton on series
  with coefficients Laurent polynomials in ``s`` (and ``nu`` reduced by ``nu^2 = 1 - s^2``) gives
  every further order.  ``m^p s`` is ``sqrt(m^2 - m_min0^2)`` (odd) or ``sqrt(m^4 - m_min0^4)``
  (even): the paper's eqs. (40), (45). The expansion holds at fixed ``nu < 1``; it is not uniform as
  ``nu -> 1`` (the true threshold differs from ``m_min0`` at higher order, which is what the
  threshold series gives).

The two damping models share the normal form and differ in the parameters
(:func:`analytic.normal_form.parameters`): the ``paper`` model keeps the undamped ``r, beta, w``
and ``g = 1/(2Qw)``; the ``exact`` model uses the damped frequencies ``Omega_i = sqrt(omega_i^2 -
gamma^2)``.  Since ``gamma^2 ~ 1/Q^2``, the models agree at leading order and part at relative order
``1/Q^2`` (:func:`model_gap` says at which power of ``m`` in each series).
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cache

import sympy as sp

from .model import Damping, S
from .normal_form import order_form, parameters, r2
from .powerseries import LaurentRing, Series, evaluate, fixed_parts, newton_doubling, reversion
from .stitching import Parity

__all__ = [
    "ThresholdSeries",
    "solve_for_lambda",
    "threshold_lambda",
    "scaled_edges",
    "threshold_series",
    "near_threshold_edges",
    "tuning_threshold",
    "model_gap",
    "scaling_power",
]

LAM = sp.Symbol("lambda", positive=True)  # 1/Q = lambda m^p
U = sp.Symbol("u", real=True)  # theta = m^p u
Q_SYM = S.Q
_WORDS = {"odd": Parity.ODD, "even": Parity.EVEN}


def _parity(n) -> Parity:
    return _WORDS[n] if isinstance(n, str) else Parity.of(n)


def scaling_power(n) -> int:
    """``p`` of the distinguished scaling ``1/Q ~ m^p``: 1 for odd orders, 2 for even ones."""
    return 1 if _parity(n) is Parity.ODD else 2


def _symbolic(n) -> bool:
    return isinstance(n, str)


def _nsym(n):
    return S.n if _symbolic(n) else n


@cache
def _scaled_model(n, damping: str, system=None) -> dict[str, sp.Expr]:
    """``N``, ``dN/dtheta`` and ``T/T0`` with ``1/Q = lambda m^p`` substituted (sympy)."""
    if system is not None:
        return _family_model(n, damping, system)
    damping = Damping(damping)
    p = scaling_power(n)
    par = {k.name: v for k, v in parameters(damping).items()}
    sub = {Q_SYM: 1 / (LAM * S.m**p)}
    N, _ = order_form(_nsym(n), _parity(n))
    # r^2, beta, g and Q do not depend on theta: differentiate the short normal form first and
    # substitute after (the same function as the derivative of the substituted N, far cheaper).
    # Symbols replaced by expressions: ``xreplace`` (one walk, no pattern matching), with ``Q``
    # replaced inside the parameters first -- the composition of the two substitutions
    env = {r2: par["r^2"], S.beta: par["beta"], S.g: par["g"]}
    env = {k: v.xreplace(sub) for k, v in env.items()}
    dN = sp.diff(N, S.theta).xreplace(env).xreplace(sub)
    N = N.xreplace(env).xreplace(sub)
    x = _nsym(n) * sp.pi / 2 + S.theta
    T0 = (x / (sp.pi * par["w"])).xreplace(sub)
    w_undamped = {k.name: v for k, v in parameters(Damping.NONE).items()}["w"]
    return {
        "N": N,
        "dN": dN,
        "T0": T0,
        "w0": w_undamped,
    }


#: generators for ``|f(A)|`` and ``f'(A)`` of another duty (see "any member of the family")
_ANGLE_GENS = ("cA", "sA")


def _gens(n, extra: tuple[str, ...] = (), system=None) -> list[str]:
    family = [] if system is None else list(_angle_parts(n, system)[1])
    return ["pi"] + (["n"] if _symbolic(n) else []) + family + list(extra)


def _eval(expr, env, ring, prec, memo=None):
    e = dict(env)
    e.setdefault(S.n, "n")
    for name in _ANGLE_GENS:  # the family's constant-angle generators (absent for the paper)
        e.setdefault(sp.Symbol(name), name)
    return evaluate(expr, e, ring, prec, var=S.m, memo=memo)


def _leading_balance(n, damping: str, ring: LaurentRing, system=None) -> tuple[dict, dict]:
    """``A`` and ``B`` of the leading term ``-(A - B lam^2)`` of ``N/m^(2p)`` at ``theta = 0``
    (found by evaluating at ``lam = 0, 1, 2``, the last as a check of the quadratic form)."""
    p = _power(n, system)
    model = _scaled_model(n, damping, system)
    vals = []
    for lam in (0, 1, 2):
        env = {
            LAM: Series.constant(ring, ring.const(lam), 2 * p),
            S.theta: Series.constant(ring, ring.zero, 2 * p),
        }
        N = _eval(model["N"], env, ring, 2 * p)
        vals.append(N.shift(-2 * p).c[0])
    A = ring.neg(vals[0])
    B = ring.add(vals[1], A)  # -(A - B) = vals[1]
    check = ring.sub(ring.neg(vals[2]), ring.sub(A, ring.scale(B, 4)))
    if (
        check
    ):  # pragma: no cover - would mean the damping term is not quadratic in 1/Q at leading order
        raise AssertionError("leading balance is not A - B lam^2")
    return A, B


@dataclass(frozen=True)
class ThresholdSeries:
    """The threshold of order ``order`` in one damping model.

    ``Q_min``: ``Q_min(m)`` (expression in ``m``: ``1/(m^p lam(m))`` with ``lam`` through
    ``m**terms``); ``m_min``: the threshold depth as an expression in ``Q`` (odd: a series in
    ``1/Q`` through ``Q**-terms``; even: the square root of the series ``m_min2`` in ``1/Q``);
    ``theta``: ``omega_av Delta T/2`` at the threshold along the threshold curve (series in ``m``),
    ``T_Tav``/``T_T0``: the period at the threshold in ``T_av`` / ``T0`` as series in ``m``.
    ``lam`` is the raw series ``1/(Q m^p)`` at the threshold.
    """

    order: int | str
    terms: int
    damping: str
    p: int
    lam: sp.Expr
    Q_min: sp.Expr
    m_min: sp.Expr
    m_min2: sp.Expr
    theta: sp.Expr
    T_Tav: sp.Expr
    T_T0: sp.Expr
    m_min_leading: sp.Expr
    #: the member of the family (:mod:`analytic.system`); ``None``: the paper's pendulum
    system: object = None

    def as_json(self) -> dict:
        return {
            **({} if self.system is None else self.system.as_json()),
            "order": self.order,
            "terms": self.terms,
            "damping": self.damping,
            "Q_min": str(self.Q_min),
            "m_min": str(self.m_min),
            "m_min_squared": str(self.m_min2),
            "m_min_leading": str(self.m_min_leading),
            "theta_at_threshold": str(self.theta),
            "T_at_threshold_Tav": str(self.T_Tav),
            "T_at_threshold_T0": str(self.T_T0),
        }


def _threshold_raw(n, damping: str, prec: int, system=None) -> tuple[Series, Series]:
    """``(lam(m), u(m))`` at the tangency through ``m**prec``.

    The solution is built one order at a time and each order depends only on the lower ones, so
    one solver per order and model is kept (:func:`_tangency`) and extended when a later call asks
    for more terms: the series through ``m**prec`` is the same whichever precision was asked
    first."""
    lam, u = _tangency(n, damping, system).solve(prec)
    return lam.truncate(prec), u.truncate(prec)


@cache
def _tangency(n, damping: str, system=None) -> _Tangency:
    return _Tangency(n, damping, system)


class _Tangency:
    """The tangency ``N = dN/dtheta = 0`` solved for ``(lam(m), u(m))``, order by order."""

    def __init__(self, n, damping: str, system):
        self.p = _power(n, system)
        self.ring = ring = LaurentRing(_gens(n, (), system))
        self.model = _scaled_model(n, damping, system)
        A, B = _leading_balance(n, damping, ring, system)
        lam0 = ring.root(ring.mul(A, ring.inverse(B)), 1, 2)
        # leading Jacobian of (N/m^2p, N_theta/m^p) in (lam, u): diag(2 B lam0, 2)
        self.j11_inv = ring.inverse(ring.scale(ring.mul(B, lam0), 2))
        self.lam = Series.constant(ring, lam0, 0)
        self.u = Series.constant(ring, ring.zero, 0)
        self.done = -1  # the highest order fixed so far
        self.pending = None  # the residuals of (lam, u), evaluated through the next order

    def _residuals(self, L: int, fixed: dict) -> tuple[Series, Series]:
        """``(N/m^2p, N_theta/m^p)`` at the current polynomials, through ``m**L``."""
        p, ring = self.p, self.ring
        hi = L + 2 * p
        lam, u = self.lam.padded(hi), self.u.shift(p).padded(hi)
        env = {LAM: lam, S.theta: u}
        F1 = _eval(self.model["N"], env, ring, hi, dict(fixed)).shift(-2 * p)
        F2 = _eval(self.model["dN"], env, ring, L + p, dict(fixed)).shift(-p)
        return F1, F2

    def solve(self, prec: int) -> tuple[Series, Series]:
        if prec <= self.done:
            return self.lam, self.u
        p, ring = self.p, self.ring
        # the parts of N and dN free of lam and theta, evaluated once for this extension
        fixed = fixed_parts(
            [self.model["N"], self.model["dN"]],
            {S.n: "n", **{sp.Symbol(g): g for g in _ANGLE_GENS}},
            ring,
            prec + 2 * p,
            var=S.m,
            vary={LAM, S.theta},
        )
        # one order at a time: each step with the leading Jacobian gains (at least) one order,
        # so the residuals are needed only through the order being fixed (through m^L at level
        # L).  The residuals that confirm level L are evaluated one order further and are the
        # first residuals of level L + 1 (the iterates are the same polynomials, padded).
        for L in range(self.done + 1, prec + 1):
            top = min(L + 1, prec)
            for _ in range(8):
                # the iterates are polynomials: padded, the residuals are exact through m^L
                self.lam, self.u = self.lam.padded(L), self.u.padded(L)
                if self.pending is None or self.pending[0].prec < L:
                    self.pending = self._residuals(top, fixed)
                F1, F2 = (x.truncate(L) for x in self.pending)
                if all(not a for a in F1.c) and all(not a for a in F2.c):
                    break
                self.lam = (self.lam - F1.scale_coeff(self.j11_inv)).truncate(L)
                self.u = (self.u - F2 * sp.Rational(1, 2)).truncate(L)
                self.pending = self._residuals(top, fixed)
            else:  # pragma: no cover
                raise ArithmeticError("threshold series did not converge")
            self.done = L
        return self.lam, self.u


def _check_terms(terms):
    from .series_result import _check_terms as check

    return check(terms, "friction")


def threshold_series(
    order, terms: int = 4, *, damping: str = "exact", system="pendulum", duty="1/2"
) -> ThresholdSeries:
    """The threshold (tangency) of the interval of order ``order`` as series.

    ``order``: an integer, or ``"odd"``/``"even"`` (symbol ``n``, the paper's system only).
    ``damping``: ``"paper"`` or ``"exact"``.  ``system``, ``duty``: the member of the family
    (:mod:`analytic.system`; a :class:`~analytic.system.System` passes through), whose
    threshold is derived from its parameter forms (:func:`analytic.family.parameter_forms`) in
    the scaling ``1/Q = lam m^p`` with ``p`` read off the forms (:func:`family_scaling_power`).
    A custom system has no depth and is refused.  See :class:`ThresholdSeries`.
    """
    from paramres.inputs import InputError, as_damping

    from .series_result import _check_order
    from .system import system as as_system

    order = _check_order(order)
    terms = _check_terms(terms)
    sysv = as_system(system, duty=duty)
    if not sysv.is_paper:
        if not sysv.uses_depth:
            raise InputError(
                f"{sysv.label} has no depth: there is no threshold depth m_min(Q) to expand"
            )
        if isinstance(order, str):
            raise InputError(
                "closed forms in n (order odd/even) are for the paper's system; give an integer "
                f"order for {sysv.label}"
            )
        return _threshold(order, terms, as_damping(damping), sysv)
    return _threshold(order, terms, as_damping(damping))


@cache
def _threshold(order, terms: int, damping: str, system=None) -> ThresholdSeries:
    n = order
    p = _power(n, system)
    # m_min (odd) through Q^-terms needs lam through m^(terms-1); m_min^2 (even) through Q^-terms
    # needs lam as a series in m^2 through (m^2)^(terms-1)
    prec = max(terms, terms - 1 if p == 1 else p * terms - p)
    lam, u = _threshold_raw(n, damping, prec, system)
    ring = lam.ring
    syms = {"n": S.n, **_constants(n, system)}
    m = S.m
    lam_expr = lam.to_sympy(m, syms)
    Q_min = 1 / (m**p * lam_expr)
    # m_min(Q): eps = 1/Q = lam(m) m^p, reverted
    eps = sp.Symbol("epsilon", positive=True)
    if p == 1:
        f = lam.shift(1)  # lam m
        g = reversion(f.truncate(terms))
        if g.prec != terms:  # pragma: no cover
            raise AssertionError("threshold series shorter than asked for")
        m_min = g.to_sympy(eps, syms).subs(eps, 1 / Q_SYM)
        m_min2 = (g * g).to_sympy(eps, syms).subs(eps, 1 / Q_SYM)
    elif system is None or not any(lam.c[k] for k in range(1, len(lam.c), 2)):
        if any(lam.c[k] for k in range(1, len(lam.c), 2)):  # pragma: no cover - m -> -m symmetry
            raise AssertionError("even-order threshold series is not even in m")
        half = Series(ring, lam.c[::2])  # lam as a series in M = m^2
        g = reversion(half.shift(1).truncate(terms))  # M(eps)
        if g.prec != terms:  # pragma: no cover
            raise AssertionError("threshold series shorter than asked for")
        m_min2 = g.to_sympy(eps, syms).subs(eps, 1 / Q_SYM)
        m_min = sp.sqrt(m_min2)
    else:
        # another member with p = 2: lam(m) has odd powers too, so m_min is a series in
        # Q^(-1/2): revert lam m^2 = eps = 1/Q
        g, lam0 = _revert_power(lam, p, terms)  # m as a series in delta = (eps/lam0)^(1/p)
        delta = sp.Symbol("delta", positive=True)
        dval = 1 / sp.sqrt(Q_SYM * ring.to_sympy(lam0, syms))
        m_min = g.to_sympy(delta, syms).subs(delta, dval)
        m_min2 = sp.expand((g * g).to_sympy(delta, syms).subs(delta, dval))
    theta = u.shift(p).truncate(terms)
    lam = lam.truncate(terms)
    model = _scaled_model(n, damping, system)
    w0 = evaluate(model["w0"], {}, ring, terms, var=m)
    T_env = {LAM: lam, S.theta: theta}
    T0 = _eval(model["T0"], T_env, ring, terms)
    Tav = T0 * w0
    return ThresholdSeries(
        n,
        terms,
        damping,
        p,
        lam_expr,
        Q_min,
        m_min,
        m_min2,
        theta.to_sympy(m, syms),
        Tav.to_sympy(m, syms),
        T0.to_sympy(m, syms),
        (1 / (Q_SYM * ring.to_sympy(lam.c[0], syms))) ** sp.Rational(1, p),
        system,
    )


# ------------------------------------------------------------------------ any member of the family
#
# For another member or duty (:mod:`analytic.family`) the normal form keeps its shape, with the
# system's ``r^2, u = 1 - r^2, beta, g, w`` from :func:`analytic.family.parameter_forms`.  For a
# duty ``D != 1/2``, ``beta(0) = 1 - 2D`` does not vanish, so ``f(beta x)`` has the constant angle
# ``A = beta(0) n pi/2``: ``f(A + t) = f(A) cos t + f'(A) sin t`` with the small ``t = (beta -
# beta(0)) n pi/2 + beta theta``.  Irrational constants ``|f(A)|``, ``f'(A)`` become generators
# ``c``, ``s`` of the coefficient ring (written out at the end); ``c`` is kept positive so that the
# leading ``lam_0 = sqrt(A/B)`` (a monomial in ``c``) is too.  The scaling power ``p`` is the
# order in ``m`` of ``r f(beta n pi/2)`` (1 unless ``n D`` is an integer, where ``f(A) = 0``).


def _power(n, system) -> int:
    return scaling_power(n) if system is None else family_scaling_power(n, system)


@cache
def _angle_parts(n: int, system) -> tuple[tuple, tuple]:
    """``((fA, gA, sign), gens)``: ``f(A) = sign * fA`` and ``f'(A) = gA`` as sympy numbers or
    generator names, and the generators used (``"cA"``, ``"sA"``)."""
    from .family import parameter_forms

    beta = parameter_forms(system, Damping.NONE).definitions["beta"]
    b0 = sp.nsimplify(sp.limit(beta, S.m, 0))
    A = b0 * n * sp.pi / 2
    if n % 2:
        fA, gA = sp.cos(A), -sp.sin(A)
    else:
        fA, gA = sp.sin(A), sp.cos(A)
    fA, gA = sp.nsimplify(fA), sp.nsimplify(gA)
    sign = -1 if fA.is_negative else 1
    gens = []
    f_part = abs(fA) if fA.is_Rational else "cA"
    g_part = gA if gA.is_Rational else "sA"
    gens += [x for x in (f_part, g_part) if isinstance(x, str)]
    return (f_part, g_part, sign, abs(fA), gA, b0), tuple(gens)


def _constants(n, system) -> dict:
    """The generators' values (sympy) for writing the series out."""
    if system is None:
        return {}
    (f_part, g_part, _sign, fval, gval, _b0), _ = _angle_parts(n, system)
    out = {}
    if f_part == "cA":
        out["cA"] = fval
    if g_part == "sA":
        out["sA"] = gval
    return out


def _family_parameters(system, damping: Damping) -> dict:
    from .family import parameter_forms

    defs = parameter_forms(system, damping).definitions
    r2e = defs["r2"] if "r2" in defs else defs["r"] ** 2
    return {
        "r2": r2e,
        "u": defs["u"],
        "beta": defs["beta"],
        "g": defs.get("g", sp.Integer(0)),
        "w": defs["w"],
        "w0": defs["w0"],
    }


def family_scaling_power(n: int, system) -> int:
    """``p`` of the distinguished scaling ``1/Q ~ m^p`` for order ``n`` of ``system``: the order
    in ``m`` of the frictionless ``r f(beta n pi/2)`` (the leading half-width), from the
    system's parameter forms.  1 unless ``n D`` is an integer (the n-th harmonic of the square
    wave vanishes), then 2 for the built-in laws."""
    return _family_power(int(n), system)


@cache
def _family_power(n: int, system) -> int:
    (f_part, g_part, sign, _fv, _gv, b0), gens = _angle_parts(n, system)
    ring = LaurentRing(["pi", *gens])
    par = _family_parameters(system, Damping.NONE)
    K = 8
    env = {}
    r2 = evaluate(par["r2"], env, ring, 2 * K, var=S.m)
    t = evaluate((par["beta"] - b0) * n * sp.pi / 2, env, ring, K, var=S.m)
    fA = ring.gen(f_part) if isinstance(f_part, str) else ring.const(f_part)
    gA = ring.gen(g_part) if isinstance(g_part, str) else ring.const(g_part)
    f = t.cos().scale_coeff(ring.scale(fA, sign)) + t.sin().scale_coeff(gA)
    prod = r2.truncate(K) * (f * f)  # r^2 f^2: of order m^(2p)
    v = prod.valuation()
    if v is None or v % 2:  # pragma: no cover - r^2 f^2 is a square: even order
        raise ArithmeticError(f"no leading half-width of order {n} within m^{K // 2}")
    return v // 2


@cache
def _family_model(n: int, damping: str, system) -> dict[str, sp.Expr]:
    """:func:`_scaled_model` for another member of the family: ``N``, ``dN/dtheta`` and ``T/T0``
    with ``1/Q = lambda m^p``, the angle ``A`` split off (generators ``cA``, ``sA``)."""
    damping = Damping(damping)
    p = family_scaling_power(n, system)
    (f_part, g_part, sign, _fv, _gv, b0), _ = _angle_parts(n, system)
    par = _family_parameters(system, damping)
    sub = {Q_SYM: 1 / (LAM * S.m**p)}
    c = sp.Symbol(f_part) if isinstance(f_part, str) else f_part
    s_ = sp.Symbol(g_part) if isinstance(g_part, str) else g_part
    th = S.theta
    x = n * sp.pi / 2 + th
    beta = par["beta"].subs(sub)
    t = (beta - b0) * n * sp.pi / 2 + beta * th
    fb = sign * c * sp.cos(t) + s_ * sp.sin(t)
    N = (
        sp.sin(th) ** 2
        - par["r2"].subs(sub) * fb**2
        + par["u"].subs(sub) * sp.sinh(par["g"].subs(sub) * x) ** 2
    )
    T0 = x / (sp.pi * par["w"].subs(sub))
    return {"N": N, "dN": sp.diff(N, th), "T0": T0, "w0": par["w0"]}


def _revert_power(lam: Series, p: int, terms: int) -> tuple[Series, dict]:
    """``m`` as a series in ``delta = (eps/lam_0)^(1/p)`` from ``eps = lam(m) m^p`` (``eps =
    1/Q``): ``delta = m (lam(m)/lam_0)^(1/p)`` (leading coefficient 1, so the root is exact),
    reverted.  Returns the series and ``lam_0``."""
    ring = lam.ring
    lam0 = lam.c[0]
    unit = lam.truncate(terms).scale_coeff(ring.inverse(lam0))
    root = unit.rational_power(sp.Rational(1, p))
    g = reversion(root.shift(1).truncate(terms))
    if g.prec != terms:  # pragma: no cover
        raise AssertionError("threshold series shorter than asked for")
    return g, lam0


# ------------------------------------------------------------------------------------------ edges


@cache
def _near_raw(n, damping: str, prec: int, system=None) -> dict[str, Series]:
    """``theta(m)`` on both edges at fixed ``nu``, coefficients in ``pi, (n,) s, nu``, and the
    conversion series to ``T/T0`` and ``T/T_av``.

    The parts of the model free of ``theta`` (the parameters as series in ``m`` at ``lam = lam_0
    nu``) are evaluated once (:func:`analytic.powerseries.fixed_parts`); Newton steps that double
    the precision (:func:`analytic.powerseries.newton_doubling`) then evaluate only the parts that
    depend on ``theta``.  The upper edge (``u(0) = +sqrt(A) s``) is solved; the lower one
    (``u(0) = -sqrt(A) s``) is its image under ``s -> -s``, an automorphism of the coefficient
    ring (it keeps ``nu^2 = 1 - s^2``) that fixes the equation, which involves ``nu`` but not
    ``s``: the same exact series as solving it anew (the tests check both ways)."""
    return _near_edges(n, damping, prec, system, ("upper",))


def _near_edges(n, damping: str, prec: int, system, solved: tuple[str, ...]) -> dict:
    """:func:`_near_raw` with the edges in ``solved`` solved directly, the others by ``s -> -s``."""
    p = _power(n, system)
    base = LaurentRing(_gens(n, (), system))
    A, B = _leading_balance(n, damping, base, system)
    lam0 = base.root(base.mul(A, base.inverse(B)), 1, 2)
    gens = _gens(n, ("s", "nu"), system)
    tmp = LaurentRing(gens)
    ring = LaurentRing(gens, relation=("nu", tmp.sub(tmp.one, tmp.gen("s", 2))))
    lift = _lift(base, ring)
    hi = prec + 2 * p
    lam = Series.constant(ring, ring.mul(lift(lam0), ring.gen("nu")), hi)
    model = _scaled_model(n, damping, system)
    sqrtA = lift(base.root(A, 1, 2))
    env = {S.n: "n", **{sp.Symbol(g): g for g in _ANGLE_GENS}, LAM: lam}
    fixed = fixed_parts(
        [model["N"], model["dN"], model["T0"]], env, ring, hi, var=S.m, vary={S.theta}
    )
    w0 = evaluate(model["w0"], {}, ring, prec, var=S.m)
    out = {}
    signs = {"upper": 1, "lower": -1}
    for name in sorted(signs, key=lambda k: k not in solved):  # the solved edges first
        sign = signs[name]
        if name not in solved:
            flip = _flip(ring, ring.index["s"])
            out[name] = {k: v.map(flip) for k, v in out["upper" if sign < 0 else "lower"].items()}
            continue
        u0 = ring.scale(ring.mul(sqrtA, ring.gen("s")), sign)

        def system_at(u, L, Ld):
            memo = dict(fixed)
            th = u.shift(p).padded(L + 2 * p)
            F = _eval(model["N"], {LAM: lam, S.theta: th}, ring, L + 2 * p, memo).shift(-2 * p)
            D = _eval(model["dN"], {LAM: lam, S.theta: th}, ring, Ld + p, memo).shift(-p)
            return F, D

        u = newton_doubling(system_at, Series.constant(ring, u0, 0), prec)
        theta = u.shift(p).truncate(prec)
        T0 = _eval(model["T0"], {LAM: lam, S.theta: theta}, ring, prec, dict(fixed))
        out[name] = {"theta": theta, "T0": T0, "Tav": T0 * w0}
    out["lam0"] = Series.constant(base, lam0, 0)
    return {k: out[k] for k in ("lower", "upper", "lam0")}


def _flip(ring: LaurentRing, i: int):
    """The map ``s -> -s`` on ring elements (``s`` the generator at index ``i``)."""

    def f(a: dict) -> dict:
        return {k: (-v if k[i] % 2 else v) for k, v in a.items()}

    return f


def _as_sympy_number(x) -> sp.Expr:
    if hasattr(x, "numerator") and hasattr(x, "denominator"):
        return sp.Rational(int(x.numerator), int(x.denominator))
    return sp.Float(str(x), 30)


def _lift(base: LaurentRing, ring: LaurentRing):
    idx = [ring.index[g] for g in base.gens]

    def f(a: dict) -> dict:
        out = {}
        for k, v in a.items():
            e = [0] * ring.nvars
            for i, x in zip(idx, k, strict=False):
                e[i] = x
            out[tuple(e)] = v
        return out

    return f


def near_threshold_edges(
    order, terms: int, *, Q=None, damping: str = "exact", units: str = "T0", system=None
):
    """Both edges above the threshold in the distinguished scaling, as an
    :class:`analytic.series_result.EdgeSeries`.

    The series are in powers of ``m`` at fixed ``nu = (m_min0/m)^p``, with ``m_min0`` the leading
    threshold (``n pi/(6Q)`` odd, ``sqrt(2/(3Q))`` even); the returned expressions have ``nu``
    written out, so they are functions of ``m`` and ``Q`` (``Q`` left symbolic if ``Q is None``).
    ``system``: another member of the family (:class:`analytic.system.System`, integer orders;
    ``p`` from :func:`family_scaling_power`); ``None`` or the paper's: the pendulum.
    """
    from .series_result import EdgeSeries, _check_order

    n = _check_order(order)
    terms = _check_terms(terms)
    if system is not None and system.is_paper:
        system = None
    p = _power(n, system)
    raw = _near_raw(n, damping, terms, system)
    consts = _constants(n, system)
    base = raw["lam0"].ring
    lam0 = base.to_sympy(raw["lam0"].c[0], {"n": S.n, **consts})
    Qs = Q_SYM if Q is None else _as_sympy_number(Q)
    nu = 1 / (Qs * lam0 * S.m**p)
    s = sp.sqrt(1 - nu**2)
    syms = {"n": S.n, "s": s, "nu": nu, **consts}
    m = S.m
    in_T0, in_Tav, theta = {}, {}, {}
    for name in ("lower", "upper"):
        theta[name] = raw[name]["theta"].to_sympy(m, syms)
        in_T0[name] = raw[name]["T0"].to_sympy(m, syms)
        in_Tav[name] = raw[name]["Tav"].to_sympy(m, syms)
    mmin0 = (1 / (Qs * lam0)) ** sp.Rational(1, p)
    s_sym = sp.Symbol("s", positive=True)
    ssyms = {"n": S.n, "s": s_sym, "nu": sp.sqrt(1 - s_sym**2), **consts}
    scaled = {
        "s": sp.Eq(s_sym, sp.sqrt(1 - (sp.Symbol("m_min0", positive=True) / m) ** (2 * p))),
        "m_min0": mmin0,
        "T0": {k: raw[k]["T0"].to_sympy(m, ssyms) for k in ("lower", "upper")},
        "Tav": {k: raw[k]["Tav"].to_sympy(m, ssyms) for k in ("lower", "upper")},
    }
    notes = (
        f"distinguished scaling 1/Q = lambda m^{p}, lambda = lambda_0 nu, s = sqrt(1 - nu^2)",
        f"leading threshold m_min0 = {sp.sstr(mmin0)}; the series hold at fixed nu < 1",
    )
    return EdgeSeries(
        n,
        terms,
        units,
        in_T0,
        in_Tav,
        theta,
        None,
        Q=Qs,
        damping=damping,
        threshold={"m_min_leading": mmin0},
        notes=notes,
        scaled=scaled,
        system=system,
    )


def scaled_edges(order, terms: int, damping: str) -> dict:
    """The raw near-threshold series: for ``"lower"``/``"upper"``, ``theta``, ``T0``, ``Tav`` as
    sympy expressions in ``m`` with coefficients in the symbols ``s`` (and ``pi``, ``n``)."""
    n = order
    raw = _near_raw(n, damping, terms)
    s = sp.Symbol("s", positive=True)
    syms = {"n": S.n, "s": s, "nu": sp.Symbol("nu", positive=True)}
    return {
        name: {k: v.to_sympy(S.m, syms) for k, v in raw[name].items()}
        for name in ("lower", "upper")
    }


# ------------------------------------------------------------------------------------ comparisons


def solve_for_lambda(expr: sp.Expr, order, terms: int) -> sp.Expr:
    """``lam(m)`` (``1/Q = lam m^p``) solving ``expr = 0`` order by order, where ``expr`` is a sympy
    expression in ``m`` and ``Q`` (or ``lambda``) whose leading term in the distinguished scaling is
    ``(a + b lam^2) m^(2p)`` (a threshold condition).  Used to read thresholds off the paper's
    printed conditions (37), (42) and off ``R(theta = 0) = 0``."""
    p = scaling_power(order)
    ring = LaurentRing(_gens(order))
    # a symbol replaced by an expression free of it: one walk (the same series as ``subs``)
    e = sp.sympify(expr).xreplace({Q_SYM: 1 / (LAM * S.m**p)})
    hi = terms + 2 * p
    # the parts of the condition free of lam, evaluated once for all the iterations below
    fixed = fixed_parts([e], {S.n: "n"}, ring, hi, var=S.m, vary={LAM})

    def F(lam: Series) -> Series:
        return _eval(e, {LAM: lam.padded(hi)}, ring, hi, dict(fixed)).shift(-2 * p)

    lead = [F(Series.constant(ring, ring.const(v), terms)).c[0] for v in (0, 1, 2)]
    a_, b_ = lead[0], ring.sub(lead[1], lead[0])
    if ring.sub(lead[2], ring.add(a_, ring.scale(b_, 4))):  # pragma: no cover
        raise AssertionError("the condition is not a + b lam^2 at leading order")
    lam0 = ring.root(ring.neg(ring.mul(a_, ring.inverse(b_))), 1, 2)
    j_inv = ring.inverse(ring.scale(ring.mul(b_, lam0), 2))
    lam = Series.constant(ring, lam0, terms)
    for _ in range(terms + 6):
        res = F(lam)
        if all(not c for c in res.c):
            return lam.to_sympy(S.m, {"n": S.n})
        lam = lam - res.scale_coeff(j_inv)
    raise ArithmeticError("threshold condition did not converge")  # pragma: no cover


def threshold_lambda(order, terms: int, damping: str) -> sp.Expr:
    """``lam(m) = 1/(Q_min m^p)`` at the tangency through ``m**terms`` (sympy)."""
    lam, _ = _threshold_raw(order, damping, terms)
    return lam.to_sympy(S.m, {"n": S.n})


def tuning_threshold(order, terms: int, damping: str = "paper") -> sp.Expr:
    """``lam(m)`` from the radicand set to zero at exact tuning (``R(theta = 0) = 0``, the way the
    paper's eqs. (37), (42) are used), to compare with the tangency of :func:`threshold_series`."""
    N = _scaled_model(order, damping)["N"].xreplace({S.theta: sp.Integer(0)})
    return solve_for_lambda(N, order, terms)


def model_gap(order, terms: int = 6) -> dict[str, int | None]:
    """The lowest power of ``m`` at which the ``paper`` and ``exact`` models differ: in the
    threshold series ``lam(m)`` and in the near-threshold edges (``T/T0`` and ``T/T_av``), compared
    coefficient by coefficient in exact arithmetic (``None``: none through ``m**terms``)."""
    out = {}
    p = scaling_power(order)
    a, _ = _threshold_raw(order, "paper", terms)
    b, _ = _threshold_raw(order, "exact", terms)
    out["threshold"] = _first_difference(a, b)
    ea, eb = _near_raw(order, "paper", terms), _near_raw(order, "exact", terms)
    for units in ("T0", "Tav"):
        found = [_first_difference(ea[k][units], eb[k][units]) for k in ("lower", "upper")]
        found = [d for d in found if d is not None]
        out[f"edges_{units}"] = min(found) if found else None
    out["p"] = p
    return out


def _first_difference(a: Series, b: Series) -> int | None:
    for k in range(min(a.prec, b.prec) + 1):
        if a.ring.sub(a.c[k], b.c[k]):
            return k
    return None
