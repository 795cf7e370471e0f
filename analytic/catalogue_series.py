"""Catalogue rows for the paper's small-``m`` results, thresholds with friction and closings.

Each provider transcribes the printed formula (the thing being checked, in the paper's symbols
``T_av, T_0, m, Q, m_min``), takes the engine's version from :mod:`analytic.expansions`,
:mod:`analytic.thresholds` or :mod:`analytic.closings`, and compares the two **coefficient by
coefficient** in the small quantity through the order the paper claims (each coefficient is proven
equal or different by :func:`analytic.identity.prove_zero`).  Where they differ, ``how`` gives the
correct form and the size of the difference; where they agree, ``how`` says through which order and
gives the engine's next term, which the paper does not have.
"""

from __future__ import annotations

from functools import lru_cache

import sympy as sp

from .catalogue import Row, latex, row, written
from .closings import closings
from .expansions import edge_series, small_m_parameters
from .identity import prove_zero
from .model import S, derived_quantities, physical
from .thresholds import (
    model_gap,
    scaled_edges,
    scaling_power,
    solve_for_lambda,
    threshold_lambda,
    threshold_series,
    tuning_threshold,
)

__all__ = ["compare_through", "next_term"]

m, Q, pi = S.m, S.Q, sp.pi
Tav, T0 = S.T_av, S.T0
MP = sp.Symbol(r"\mp")
m_min = sp.Symbol(r"m_{\min}", positive=True)
Q_min = sp.Symbol(r"Q_{\min}", positive=True)
s_ = sp.Symbol("s", positive=True)  # sqrt(1 - nu^2) of the distinguished scaling
T_lo, T_hi = sp.Symbol("T_-", positive=True), sp.Symbol("T_+", positive=True)


def compare_through(printed: sp.Expr, derived: sp.Expr, var: sp.Symbol, order: int):
    """Compare two expressions as polynomials in ``var`` through ``var**order``.

    Returns ``(holds, first, printed_coeff, derived_coeff, verdicts)``: ``first`` is the lowest
    power at which they differ (``None`` if they agree through ``order``).
    """
    a = _coefficient(printed, var)
    b = _coefficient(derived, var)
    verdicts = []
    for k in range(order + 1):
        ca, cb = a(k), b(k)
        v = prove_zero(sp.expand(ca - cb))
        verdicts.append(v)
        if not v.holds:
            return False, k, ca, cb, verdicts
    return True, None, None, None, verdicts


def _coefficients(e: sp.Expr, var: sp.Symbol) -> dict[int, sp.Expr] | None:
    """``{k: e.coeff(var, k)}`` over the powers ``k`` that occur in the expanded ``e``, its terms
    sorted by their power of ``var`` in one pass (each term a product of factors free of ``var``
    and ``var**k``; the coefficient is the sum of the cofactors, as ``coeff`` gives it); ``None``
    where a term is not of that form."""
    parts: dict[int, list] = {}
    for term in sp.Add.make_args(e):
        k, rest = 0, []
        for f in sp.Mul.make_args(term):
            if f == var:
                k += 1
            elif f.is_Pow and f.base == var and f.exp.is_Integer:
                k += int(f.exp)
            elif f.has(var):
                return None
            else:
                rest.append(f)
        parts.setdefault(k, []).append(sp.Mul(*rest))
    return {k: sp.Add(*v) for k, v in parts.items()}


@lru_cache(maxsize=256)
def _coefficient(e: sp.Expr, var: sp.Symbol):
    """``k -> expand(e).coeff(var, k)`` (through :func:`_coefficients`), once per expression
    (rows compare the same derived series with several printed ones)."""
    e = sp.expand(e)
    found = _coefficients(e, var)
    if found is None:
        return lambda k: e.coeff(var, k)
    return lambda k: found.get(k, sp.Integer(0))


#: while :mod:`analytic.generate_simplified` rebuilds the stored forms: the expressions asked for
RECORDING: list | None = None


@lru_cache(maxsize=256)
def _simplified(c: sp.Expr) -> sp.Expr:
    """``simplify(c)``, once per expression (rows ask for the same next terms), for a printed
    form: taken from :mod:`analytic.simplified_generated` where ``c`` is one of the stored
    inputs (``tests/test_simplified_generated.py`` simplifies every one again and compares)."""
    if RECORDING is not None:
        RECORDING.append(c)
        return sp.simplify(c)
    from .simplified_generated import FORMS

    stored = FORMS.get(sp.srepr(c))
    return stored if stored is not None else sp.simplify(c)


def next_term(expr: sp.Expr, var: sp.Symbol, after: int) -> sp.Expr:
    """The lowest non-zero term of ``expr`` beyond ``var**after``."""
    e = sp.expand(expr)
    found = _coefficients(e, var)
    if found is None or min(found) < 0:  # pragma: no cover - every series here is a polynomial
        deg = sp.Poly(e, var).degree()
        found = {k: e.coeff(var, k) for k in range(deg + 1)}
    for k in sorted(found):
        if k > after:
            c = _simplified(found[k])
            if c != 0:
                return c * var**k
    return sp.Integer(0)


def _route(verdicts) -> str:
    return (
        "symbolically"
        if all(v.route == "symbolic" for v in verdicts)
        else "numerically at random points"
    )


def _edges(n: int, terms: int = 4) -> dict[str, dict[str, sp.Expr]]:
    es = edge_series(n, terms)
    return {"T0": es.in_T0, "Tav": es.in_Tav}


def _with_sign(expr_mp: sp.Expr, sign: int) -> sp.Expr:
    return expr_mp.subs(MP, sign)


def _edge_rows_compare(printed_pairs, derived, order: int):
    """``printed_pairs``: list of (units, printed expression with MP in units of that T).  Returns
    (all_ok, list of texts)."""
    ok_all, texts, verdicts = True, [], []
    for units, pr in printed_pairs:
        for name, sign in (("lower", -1), ("upper", 1)):
            ok, k, ca, cb, vs = compare_through(
                _with_sign(pr, sign), derived[units][name], m, order
            )
            verdicts += vs
            if not ok:
                ok_all = False
                texts.append(
                    f"{name} edge in units of {units}: the coefficient of $m^{k}$ is printed "
                    f"${latex(ca)}$ where the derivation gives ${latex(cb)}$"
                )
    return ok_all, texts, verdicts


def _signed_pair(expr_mp: sp.Expr, unit: sp.Expr, lhs=(T_lo, T_hi)) -> tuple:
    r"""``T_- = ...``, ``T_+ = ...`` from a printed formula written with the ``\mp`` symbol."""
    return tuple(
        sp.Eq(side, _with_sign(expr_mp, sign) * unit, evaluate=False)
        for side, sign in zip(lhs, (-1, 1), strict=False)
    )


# ---------------------------------------------------------------------------------------- eq. (7)


@row("7")
def _eq7() -> Row:
    wav_over_w0 = sp.Rational(1, 2) * (1 / sp.sqrt(1 + m) + 1 / sp.sqrt(1 - m))
    printed_w = 1 + sp.Rational(3, 8) * m**2
    printed_T = 1 - sp.Rational(3, 8) * m**2
    par = small_m_parameters(6)
    w = par["w"].to_sympy(m)
    invw = par["1/w"].to_sympy(m)
    # the exact first equality of (7): omega_av/omega_0 from omega_i = omega_0/sqrt(1 -+ m)
    exact = physical((S.omega1 + S.omega2) / 2 / S.omega0)
    v0 = prove_zero(exact - wav_over_w0)
    ok1, _, _, _, vs1 = compare_through(printed_w, w, m, 3)
    ok2, _, _, _, vs2 = compare_through(printed_T, invw, m, 3)
    ok = v0.holds and ok1 and ok2
    printed = (
        sp.Eq(S.omega_av, S.omega0 * (1 + sp.Rational(3, 8) * m**2), evaluate=False),
        sp.Eq(Tav, T0 * printed_T, evaluate=False),
    )
    derived = (
        sp.Eq(S.omega_av / S.omega0, _plus_order(w, sp.Order(m**7)), evaluate=False),
        sp.Eq(Tav / T0, _plus_order(invw, sp.Order(m**7)), evaluate=False),
    )
    how = (
        "The exact form $\\omega_{av} = (\\omega_0/2)(1/\\sqrt{1+m} + 1/\\sqrt{1-m})$ follows from "
        f"the model ({v0.describe()}); its series (and that of $T_{{av}}/T_0 = 1/w$, where "
        "$w = \\omega_{av}/\\omega_0$) agree with the "
        f"printed ones through $m^3$ ({_route(vs1 + vs2)}), the printed order being $m^2$. Next "
        f"terms: $\\omega_{{av}}/\\omega_0$: ${latex(next_term(w, m, 3))}$, $T_{{av}}/T_0$: "
        f"${latex(next_term(invw, m, 3))}$."
    )
    return Row(
        "7",
        "agrees" if ok else "differs",
        _latex_tuple(printed),
        _latex_tuple(derived),
        how,
        "Average frequency and period at small depth",
    )


def _plus_order(series: sp.Expr, order: sp.Expr) -> sp.Expr:
    """``series + order`` as printed, for a truncated series and the order term just beyond its
    last power (built as written: no term of the series is of that order, and sympy's test of
    every term against the order term costs more than the rest of the sum)."""
    return sp.Add(*sp.Add.make_args(series), order, evaluate=False)


def _latex_tuple(items) -> str:
    return r",\quad ".join(latex(e) for e in items)


# ------------------------------------------------------------------------------- (18), (19), (27)


def _edge_row(
    label: str, n: int, printed_Tav: sp.Expr, printed_T0: sp.Expr, title: str, extra: str = ""
) -> Row:
    derived = _edges(n, 4)
    pairs = [("Tav", printed_Tav), ("T0", printed_T0)]
    ok, texts, verdicts = _edge_rows_compare(pairs, derived, 2)
    printed = _signed_pair(printed_Tav, Tav) + _signed_pair(printed_T0, T0)
    d = derived
    shown = (
        sp.Eq(T_lo / Tav, _plus_order(d["Tav"]["lower"], sp.Order(m**5)), evaluate=False),
        sp.Eq(T_hi / Tav, _plus_order(d["Tav"]["upper"], sp.Order(m**5)), evaluate=False),
        sp.Eq(T_lo / T0, _plus_order(d["T0"]["lower"], sp.Order(m**5)), evaluate=False),
        sp.Eq(T_hi / T0, _plus_order(d["T0"]["upper"], sp.Order(m**5)), evaluate=False),
    )
    if ok:
        how = (
            "Both edges agree with the derived series through $m^2$, the printed order, in units "
            "of $T_{av}$ "
            f"and of $T_0$ ({_route(verdicts)}, coefficient by coefficient). The derived series go "
            "on: "
            f"$T_-/T_{{av}}$ next term ${latex(next_term(d['Tav']['lower'], m, 2))}$, "
            f"$T_-/T_0$ next term ${latex(next_term(d['T0']['lower'], m, 2))}$ "
            f"(any order: paramres series --order {n} --terms K)."
        )
    else:
        how = "Misprint: " + "; ".join(texts) + "."
    return Row(
        label,
        "agrees" if ok else "differs",
        _latex_tuple(printed),
        _latex_tuple(shown),
        how + (" " + extra if extra else ""),
        title,
    )


@row("18")
def _eq18() -> Row:
    return _edge_row(
        "18",
        1,
        sp.Rational(1, 2) * (1 + MP * 3 * m / pi),
        sp.Rational(1, 2) * (1 + MP * 3 * m / pi - sp.Rational(3, 8) * m**2),
        "First interval at small depth",
        "The lower edge is the root of the eq.-(13) factor ($\\varepsilon = +1$) for $n = 1$.",
    )


@row("19")
def _eq19() -> Row:
    return _edge_row(
        "19",
        3,
        sp.Rational(3, 2) * (1 + MP * m / pi),
        sp.Rational(3, 2) * (1 + MP * m / pi - sp.Rational(3, 8) * m**2),
        "Third interval at small depth",
        "For $n = 3$ the eq.-(13) factor ($\\varepsilon = +1$, the shape of eqs. 8-9) gives the "
        "upper edge and the factor of opposite sign (eqs. 16-17) the lower one: for odd $n$ the "
        "eq.-(13) factor is the lower edge when $n = 1, 5, 9, \\dots$ and the upper edge when "
        "$n = 3, 7, 11, \\dots$ ($c_n = -\\sin(n\\pi/2)$).",
    )


@row("19-shift")
def _eq19_shift() -> Row:
    d3 = _edges(3, 4)["T0"]
    d1 = _edges(1, 4)["T0"]
    centre = sp.expand((d3["lower"] + d3["upper"]) / 2 - sp.Rational(3, 2))
    width3 = sp.expand(d3["upper"] - d3["lower"])
    width1 = sp.expand(d1["upper"] - d1["lower"])
    printed_centre = -sp.Rational(9, 16) * m**2
    printed_width = 3 * m / pi
    ok1, k1, a1, b1, vs1 = compare_through(printed_centre, centre, m, 2)
    ok2, k2, a2, b2, vs2 = compare_through(printed_width, width3, m, 1)
    ok3, k3, a3, b3, vs3 = compare_through(printed_width, width1, m, 1)
    ok = ok1 and ok2 and ok3
    printed = (
        sp.Eq(
            sp.Symbol(r"\text{centre}") - sp.Rational(3, 2) * T0,
            printed_centre * T0,
            evaluate=False,
        ),
        sp.Eq(T_hi - T_lo, printed_width * T0, evaluate=False),
    )
    derived = (
        sp.Eq(
            sp.Symbol(r"\text{centre}") / T0 - sp.Rational(3, 2),
            _plus_order(centre, sp.Order(m**5)),
            evaluate=False,
        ),
        sp.Eq((T_hi - T_lo) / T0, _plus_order(width3, sp.Order(m**5)), evaluate=False),
    )
    how = (
        "The centre of the third interval lies $(9/16)\\,m^2 T_0$ below $(3/2)\\,T_0$ and its "
        "width is $(3m/\\pi)\\,T_0$, the same as the first interval's, both through the printed "
        f"order ({_route(vs1 + vs2 + vs3)}). In general the centre shift is "
        "$-(3n/16)\\,m^2 T_0$ for every order (it is the shift of $nT_{av}/2$) and the leading "
        "width $(3m/\\pi)\\,T_{av}$ for every odd order. "
        f"Next terms: centre ${latex(next_term(centre, m, 2))}$, width "
        f"${latex(next_term(width3, m, 1))}$ "
        f"(first interval: ${latex(next_term(width1, m, 1))}$)."
    )
    if not ok:
        how = "Differs: " + how
    return Row(
        "19-shift",
        "agrees" if ok else "differs",
        _latex_tuple(printed),
        _latex_tuple(derived),
        how,
        "Asymmetry and width of the third interval",
    )


@row("27")
def _eq27() -> Row:
    base = _edge_row(
        "27",
        2,
        1 + MP * sp.Rational(3, 4) * m**2,
        1 + (MP * sp.Rational(3, 4) - sp.Rational(3, 8)) * m**2,
        "Second interval at small depth",
    )
    d = _edges(2, 4)["T0"]
    width = sp.expand(d["upper"] - d["lower"])
    ok_w = compare_through(sp.Rational(3, 2) * m**2, width, m, 3)[0]
    ok_lo = compare_through(1 - sp.Rational(9, 8) * m**2, d["lower"], m, 3)[0]
    ok_hi = compare_through(1 + sp.Rational(3, 8) * m**2, d["upper"], m, 3)[0]
    ok = base.status == "agrees" and ok_w and ok_lo and ok_hi
    how = base.how + (
        " The explicit forms $T_- = T_0(1 - 9m^2/8)$, $T_+ = T_0(1 + 3m^2/8)$ and the width "
        "$(3/2)\\,m^2 T_0$ agree through $m^3$ (there is no $m^3$ term: even orders are even "
        "in $m$)."
    )
    return Row("27", "agrees" if ok else "differs", base.printed, base.derived, how, base.title)


# ------------------------------------------------------------------------------------- thresholds


def _printed_threshold_condition(label: str):
    """The printed (37) at T = T_av/2, or (42) at T = T_av (sympy, paper's symbols)."""
    q, p, dw, T = S.q, S.p, S.Domega, S.T
    if label == "37":
        eq = sp.Eq((q - 1) ** 2 / q * sp.cos(dw * T / 4) ** 2, p + 1 / p - 2, evaluate=False)
        tuning = Tav / 2
    else:
        eq = sp.Eq((q - 1) ** 2 / q * sp.sin(dw * Tav / 4) ** 2, (p - 1) ** 2 / p, evaluate=False)
        tuning = Tav
    return eq, tuning


def _threshold_row(label: str, n: int, title: str) -> Row:
    eq, tuning = _printed_threshold_condition(label)
    # expand the abbreviations (p = exp(-gamma T), ...) first, then put T at exact tuning
    # (symbols replaced by expressions free of them: ``xreplace``, one walk each)
    residual = physical((eq.lhs - eq.rhs).xreplace(derived_quantities()).xreplace({S.T: tuning}))
    terms = 6 if n % 2 else 10
    lam_printed = solve_for_lambda(residual, n, terms)
    lam_tuning = tuning_threshold(n, terms, "paper")
    lam_tangent = threshold_lambda(n, terms, "paper")
    same_as_radicand = compare_through(lam_printed, lam_tuning, m, terms)[0]
    ok, k, a, b, vs = compare_through(lam_printed, lam_tangent, m, terms)
    p_ = 1 if n % 2 else 2
    derived = (
        sp.Eq(sp.Symbol("N"), 0, evaluate=False),
        sp.Eq(sp.Derivative(sp.Symbol("N"), S.theta), 0, evaluate=False),
        sp.Eq(
            1 / (Q_min * m**p_),
            _plus_order(lam_tangent, sp.Order(m ** (terms + 1))),
            evaluate=False,
        ),
    )
    where = "$T = T_{av}/2$" if label == "37" else "$T = T_{av}$"
    text = (
        f"Read at exact tuning ({where}), as the text does, the printed condition is exactly the "
        "engine's radicand $R(\\theta = 0) = 0$ (its threshold series "
        f"{'agrees' if same_as_radicand else 'does not agree'} with that of $R(0) = 0$ through "
        f"$m^{{{terms}}}$). But the threshold is where the interval shrinks to a point: a "
        "double root, $N = 0$ and $dN/d\\theta = 0$ together (the radicand and "
        "$(q+1)^2 f(x)^2$ touch), "
        "and "
        f"the double root does not sit at exact tuning: $\\theta_* = "
        f"{latex(threshold_series(n, 4 if n % 2 else 6, damping='paper').theta)} + \\dots$."
    )
    if ok:
        how = text + f" The two thresholds nevertheless agree through $m^{{{terms}}}$."
        status = "agrees"
    else:
        rel = _simplified((b - a) / lam_tangent.coeff(m, 0))
        how = text + (
            f" So the threshold read off the printed condition is right through relative order "
            f"$m^{{{k - 1}}}$ and wrong at $m^{{{k}}}$ ($1/Q^{{{k // p_}}}$): with "
            f"$1/Q_{{\\min}} = \\lambda(m)\\, m^{{{p_}}}$, the $m^{{{k}}}$ coefficient "
            f"of $\\lambda$ is ${latex(a)}$ from the printed condition but ${latex(b)}$ at "
            f"the tangency "
            f"(relative difference ${latex(rel)}\\, m^{{{k}}}$); the leading term, eq. "
            f"({'38' if label == '37' else '43'}), is right. The correct condition is the tangency "
            f"(paper model)."
        )
        status = "differs"
    return Row(
        label,
        status,
        latex(eq) + rf"\quad\text{{at }}{latex(written(S.T, tuning))}",
        _latex_tuple(derived),
        how,
        title,
    )


@row("37")
def _eq37() -> Row:
    return _threshold_row("37", 1, "Threshold condition of the first interval")


@row("42")
def _eq42() -> Row:
    return _threshold_row("42", 2, "Threshold condition of the second interval")


def _limit_at_zero(expr: sp.Expr, var: sp.Symbol) -> sp.Expr:
    """``lim expr`` as ``var -> 0``: for a quotient of polynomials in ``var`` whose denominator
    does not vanish at 0 (a threshold series ``Q_min m^p = 1/lam(m)``, ``lam(0) > 0``) its value
    there, the definition of continuity; otherwise sympy's ``limit``."""
    num, den = sp.fraction(sp.together(expr))
    if num.is_polynomial(var) and den.is_polynomial(var):
        d0 = den.xreplace({var: sp.Integer(0)})
        if d0.is_zero is False:
            return num.xreplace({var: sp.Integer(0)}) / d0
    return sp.limit(expr, var, 0)  # pragma: no cover - every threshold series is of that form


#: what the two damping models' thresholds differ in: the normal-form parameters, each defined
#: (the verdict is read on its own, away from the section that derives them)
_MODELS_DIFFER_IN = (
    "frequencies of the halves: $W_i$ is the undamped $\\omega_i$ in the paper model and the "
    "damped $\\Omega_i = \\sqrt{\\omega_i^2 - \\gamma^2}$ in the exact model, and the normal-form "
    "parameters are built from them: $r^2 = (K-2)/(K+2)$ (with $K = q + 1/q$ in the paper model "
    "and the exact model's own coupling $K$), $\\beta = (W_2 - W_1)/(W_2 + W_1)$ and "
    "$w = (W_1 + W_2)/(2\\omega_0)$."
)


def _mmin_row(label: str, n: int, printed_Qmin: sp.Expr, printed_mmin: sp.Expr, title: str) -> Row:
    texts, ok_all = [], True
    derived_show = []
    for model in ("paper", "exact"):
        th = threshold_series(n, 4, damping=model)
        inv = sp.Symbol("epsilon", positive=True)
        if n % 2:
            d_series = sp.expand(th.m_min.subs(Q, 1 / inv))
            p_series = sp.expand(printed_mmin.subs(Q, 1 / inv))
            ok, k, a, b, vs = compare_through(p_series, d_series, inv, 1)
            nxt = next_term(d_series, inv, 1).subs(inv, 1 / Q)
        else:
            d_series = sp.expand(th.m_min2.subs(Q, 1 / inv))
            p_series = sp.expand((printed_mmin**2).subs(Q, 1 / inv))
            ok, k, a, b, vs = compare_through(p_series, d_series, inv, 1)
            nxt = next_term(d_series, inv, 1).subs(inv, 1 / Q)
        # the leading term against the printed one, decided exactly by the identity check
        lead_Q = _limit_at_zero(th.Q_min * m ** (1 if n % 2 else 2), m)
        okQ = prove_zero(lead_Q - printed_Qmin * m ** (1 if n % 2 else 2)).holds
        ok_all = ok_all and ok and okQ
        what = "$m_{\\min}$" if n % 2 else "$m_{\\min}^2$"
        texts.append(
            f"{model.capitalize() if not texts else model} model: leading term "
            f"{'agrees' if ok and okQ else 'differs'}; next term of {what}: ${latex(nxt)}$"
        )
        if model == "paper":
            derived_show = [
                sp.Eq(Q_min, th.Q_min, evaluate=False),
                sp.Eq(
                    m_min if n % 2 else m_min**2, th.m_min if n % 2 else th.m_min2, evaluate=False
                ),
            ]
    printed = (
        sp.Eq(Q_min, printed_Qmin, evaluate=False),
        sp.Eq(m_min, printed_mmin, evaluate=False),
    )
    p_ = scaling_power(n)
    gap = model_gap(n, 4)["threshold"]
    how = (
        "The threshold is the tangency of the normal form ($N = 0$, $dN/d\\theta = 0$), solved "
        f"in the distinguished scaling $1/Q \\sim m^{{{1 if n % 2 else 2}}}$ and compared with the "
        "printed leading term, coefficient by coefficient in $1/Q$. "
        + "; ".join(texts)
        + f". The two damping models part at relative order $m^{{{gap}}} = 1/Q^{{{gap // p_}}}$ "
        f"in the threshold ($1/Q_{{\\min}} = \\lambda(m)\\, m^{{{p_}}}$). They differ in the "
        + _MODELS_DIFFER_IN
    )
    return Row(
        label,
        "agrees" if ok_all else "differs",
        _latex_tuple(printed),
        _latex_tuple(derived_show),
        how,
        title,
    )


@row("38")
def _eq38() -> Row:
    return _mmin_row("38", 1, pi / (6 * m), pi / (6 * Q), "Threshold of the first interval")


@row("43")
def _eq43() -> Row:
    return _mmin_row(
        "43",
        2,
        sp.Rational(2, 3) / m**2,
        sp.sqrt(sp.Rational(2, 3) / Q),
        "Threshold of the second interval",
    )


@row("§6-n3")
def _sec6_n3() -> Row:
    th = threshold_series(3, 4, damping="paper")
    inv = sp.Symbol("epsilon", positive=True)
    ok1, k, a, b, vs = compare_through(pi / 2 * inv, sp.expand(th.m_min.subs(Q, 1 / inv)), inv, 1)
    # edges: (19) with m -> sqrt(m^2 - m_min^2), in units of T_av
    printed_Tav = sp.Rational(3, 2) * (1 + MP * sp.sqrt(m**2 - m_min**2) / pi)
    ok2, texts, verdicts = _near_compare(3, printed_Tav, 1)
    ok = ok1 and ok2
    printed = (
        sp.Eq(m_min, pi / (2 * Q), evaluate=False),
        *_signed_pair(printed_Tav, Tav),
    )
    d = scaled_edges(3, 3, "paper")
    derived = (
        sp.Eq(m_min, th.m_min, evaluate=False),
        _s_definition(3),
        sp.Eq(T_lo / Tav, _plus_order(d["lower"]["Tav"], sp.Order(m**4)), evaluate=False),
    )
    how = (
        "Threshold of the third interval (tangency, paper model): $m_{\\min} = \\pi/(2Q)$ at "
        f"leading order ({'agrees' if ok1 else 'differs'}); in general "
        "$m_{\\min} = n\\pi/(6Q) + O(1/Q^3)$ for every odd $n$. Edges: with "
        "$s = \\sqrt{1 - m_{\\min}^2/m^2}$ (so $ms = \\sqrt{m^2 - m_{\\min}^2}$), the derived "
        "$T/T_{av} = 3/2 \\mp (3/(2\\pi))\\, ms + O(m^2)$, which is (19) with "
        "$m \\to \\sqrt{m^2 - m_{\\min}^2}$ "
        f"({'agrees' if ok2 else 'differs: ' + '; '.join(texts)}) through order $m$, coefficient "
        "by coefficient in $m$ at fixed $m_{\\min}/m$. The next order is a friction shift of the "
        "centre, "
        f"${latex(next_term(sp.expand((d['lower']['Tav'] + d['upper']['Tav']) / 2), m, 1))}$ "
        "($s^2 - 1 = -m_{\\min}^2/m^2$), which (19) does not have."
    )
    return Row(
        "§6-n3",
        "agrees" if ok else "differs",
        _latex_tuple(printed),
        _latex_tuple(derived),
        how,
        "Third interval with friction",
    )


def _s_definition(n: int) -> sp.Eq:
    """``s = sqrt(1 - (m_min/m)^(2p))``, the variable of the near-threshold series of order ``n``
    (``p`` of :func:`scaling_power`), stated among the derived forms before the first that uses
    it."""
    p2 = 2 * scaling_power(n)
    return sp.Eq(s_, sp.sqrt(1 - m_min**p2 / m**p2), evaluate=False)


def _near_compare(n: int, printed_Tav: sp.Expr, order: int):
    """Compare a printed near-threshold edge formula (in T_av, with ``m_min``, ``MP``) with the
    derived series at fixed ``nu`` (``m_min^p = nu m^p``, ``s = sqrt(1 - nu^2)``) through
    ``m**order``."""
    d = scaled_edges(n, max(order + 2, 3), "paper")
    p_ = scaling_power(n)
    nu = sp.sqrt(1 - s_**2)
    sub = {m_min: m * nu ** sp.Rational(1, p_)}
    texts, verdicts, ok_all = [], [], True
    for name, sign in (("lower", -1), ("upper", 1)):
        # expanded, the radicand is m^(2p) s^2 and its root m^p s (m, s positive)
        pr = sp.expand(_with_sign(printed_Tav, sign).subs(sub))
        pr = sp.expand(sp.powdenest(pr, force=True))
        ok, k, a, b, vs = compare_through(pr, d[name]["Tav"], m, order)
        verdicts += vs
        if not ok:
            ok_all = False
            texts.append(
                f"{name} edge: coefficient of $m^{{{k}}}$ printed ${latex(a)}$, derived "
                f"${latex(b)}$"
            )
    return ok_all, texts, verdicts


def _centre_shift(centre: sp.Expr, damping: str) -> sp.Expr:
    """The first interval's centre shift beyond order ``m`` (``centre``: the mean of the scaled
    edges, in ``m`` and ``s = sqrt(1 - m_min^2/m^2)``) at the leading threshold ``m_min`` of the
    damping model (the ``1/Q`` term of its threshold series): a function of ``Q`` alone."""
    term = next_term(centre, m, 1)
    (s_,) = term.free_symbols - {m}
    inv = sp.Symbol("epsilon", positive=True)
    lead = sp.expand(threshold_series(1, 3, damping=damping).m_min.subs(Q, 1 / inv)).coeff(inv, 1)
    shift = term.subs(s_, sp.sqrt(1 - m_min**2 / m**2)).subs(m_min, lead / Q)
    return _simplified(shift)


@row("40")
def _eq40() -> Row:
    printed_Tav = sp.Rational(1, 2) * (1 + MP * sp.sqrt(m**2 - m_min**2) / pi)
    ok, texts, verdicts = _near_compare(1, printed_Tav, 1)
    correct = sp.Rational(1, 2) * (1 + MP * 3 * sp.sqrt(m**2 - m_min**2) / pi)
    ok_c, texts_c, _ = _near_compare(1, correct, 1)
    # the reduction to (18) at m_min = 0
    to18 = sp.expand(_with_sign(printed_Tav, -1).subs(m_min, 0))
    d18 = _edges(1, 2)["Tav"]["lower"]
    ok18, k18, a18, b18, _ = compare_through(to18, d18, m, 1)
    d = scaled_edges(1, 3, "paper")
    paper_c = sp.expand((d["lower"]["Tav"] + d["upper"]["Tav"]) / 2)
    exact = scaled_edges(1, 3, "exact")
    exact_c = sp.expand((exact["lower"]["Tav"] + exact["upper"]["Tav"]) / 2)
    printed = (
        *_signed_pair(MP * sp.sqrt(m**2 - m_min**2) / (2 * pi), 1, (S.DT / Tav, S.DT / Tav)),
        *_signed_pair(printed_Tav, Tav),
    )
    derived = (
        *_signed_pair(MP * 3 * sp.sqrt(m**2 - m_min**2) / (2 * pi), 1, (S.DT / Tav, S.DT / Tav)),
        *_signed_pair(correct, Tav),
        _s_definition(1),
        sp.Eq(T_lo / Tav, _plus_order(d["lower"]["Tav"], sp.Order(m**4)), evaluate=False),
    )
    if ok:
        how = "Agrees with the derived near-threshold edges through order $m$."
        status = "agrees"
    else:
        status = "differs"
        how = (
            "Misprint (a lost factor 3): " + "; ".join(texts) + " (with $m_{\\min} = \\pi/(6Q)$, "
            "$s = \\sqrt{1 - m_{\\min}^2/m^2}$, compared coefficient by coefficient in $m$ at "
            "fixed "
            "$m_{\\min}/m$). The correct form is "
            "$T_\\mp = (T_{av}/2)(1 \\mp (3/\\pi)\\sqrt{m^2 - m_{\\min}^2})$, i.e. "
            "$\\Delta T/T_{av} = \\mp (3/(2\\pi))\\sqrt{m^2 - m_{\\min}^2}$ "
            f"({'agrees' if ok_c else 'differs'}), which is what Section 6 states "
            "((18) with $m \\to \\sqrt{m^2 - m_{\\min}^2}$). The printed form fails the text's own "
            "check: at $m_{\\min} = 0$ it gives $(1/2)(1 \\mp m/\\pi)\\,T_{av}$, not (18) "
            f"({'it agrees with (18)' if ok18 else 'it differs from (18)'}; coefficient of $m$ "
            f"printed ${latex(a18)}$, (18) ${latex(b18)}$). In the derivation before (40) "
            "the last radicand term $q(p-1)^2/p \\approx (\\pi/(2Q))^2$ equals $9m_{\\min}^2$, not "
            "$m_{\\min}^2$, so the radicand is $9(m^2 - m_{\\min}^2)$. The text also sends the "
            "reader to the radicand of (32) where (39) is meant. Beyond the printed order the "
            "friction shifts the centre: $(T_+ + T_-)/(2T_{av}) - 1/2 = "
            f"{latex(next_term(paper_c, m, 1))}$ (paper model) "
            f"$= {latex(_centre_shift(paper_c, 'paper'))}$ at leading "
            f"order, ${latex(next_term(exact_c, m, 1))}$ (exact model) "
            f"$= {latex(_centre_shift(exact_c, 'exact'))}$."
        )
    return Row(
        "40",
        status,
        _latex_tuple(printed),
        _latex_tuple(derived),
        how,
        "First interval near the threshold",
    )


@row("45")
def _eq45() -> Row:
    printed_Tav = 1 + MP * sp.Rational(3, 4) * sp.sqrt(m**4 - m_min**4)
    ok, texts, verdicts = _near_compare(2, printed_Tav, 3)
    d = scaled_edges(2, 4, "paper")
    e = scaled_edges(2, 4, "exact")
    printed = (
        *_signed_pair(
            MP * sp.Rational(3, 4) * sp.sqrt(m**4 - m_min**4), 1, (S.DT / Tav, S.DT / Tav)
        ),
        *_signed_pair(printed_Tav, Tav),
    )
    derived = (
        _s_definition(2),
        sp.Eq(T_lo / Tav, _plus_order(d["lower"]["Tav"], sp.Order(m**5)), evaluate=False),
        sp.Eq(T_hi / Tav, _plus_order(d["upper"]["Tav"], sp.Order(m**5)), evaluate=False),
    )
    how = (
        "Near-threshold edges of the second interval in the distinguished scaling "
        "$1/Q \\sim m^2$ ($m_{\\min} = \\sqrt{2/(3Q)}$, $s = \\sqrt{1 - m_{\\min}^4/m^4}$, "
        "$m^2 s = \\sqrt{m^4 - m_{\\min}^4}$): the derived "
        "$T/T_{av} = 1 \\mp (3/4)\\, m^2 s + O(m^4)$ "
        + ("agrees with the printed form" if ok else "differs: " + "; ".join(texts))
        + " through $m^3$, coefficient by coefficient in $m$ at fixed $m_{\\min}/m$ "
        f"({_route(verdicts)}). In general "
        "$T/T_{av} = n/2 \\mp (3n/8)\\sqrt{m^4 - m_{\\min}^4}$ "
        "with the same $m_{\\min}$ for every even $n$. "
        f"Next order (paper model): lower ${latex(next_term(d['lower']['Tav'], m, 3))}$; "
        f"exact model: lower ${latex(next_term(e['lower']['Tav'], m, 3))}$."
    )
    return Row(
        "45",
        "agrees" if ok else "differs",
        _latex_tuple(printed),
        _latex_tuple(derived),
        how,
        "Second interval near the threshold",
    )


# -------------------------------------------------------------------------------------- section 5


@row("§5")
def _sec5() -> Row:
    c = closings(6)
    named = ((2, 1), (3, 1), (3, 2))
    found = {f"{b}:{a}": list(c.at_ratio(b, a)) for b, a in named}
    ok = c.proven and all(found.values())
    listing = "; ".join(f"$n = {x.order}$: $T_1:T_2 = {x.ratio}$, $m = {x.m}$" for x in c.items)
    others = [x for x in c.items if not any(x.b * a == x.a * b for b, a in named)]
    printed = latex(sp.Symbol(r"T_1 : T_2 \in \{2:1,\ 3:1,\ 3:2\}"))
    derived = latex(
        sp.Tuple(
            written(S.omega1 * S.T / 2, sp.Symbol("a") * pi),
            written(S.omega2 * S.T / 2, sp.Symbol("b") * pi),
            written(
                m,
                (sp.Symbol("b") ** 2 - sp.Symbol("a") ** 2)
                / (sp.Symbol("b") ** 2 + sp.Symbol("a") ** 2),
            ),
        )
    )
    how = (
        r"Closing theorem (derived: both edge factors vanish together if and only if "
        r"$\omega_1 T/2 = a\pi$ and $\omega_2 T/2 = b\pi$ with $1 \le a < b$, $a + b = n$; then "
        r"$T_1:T_2 = b:a$, $m = (b^2-a^2)/(b^2+a^2)$, $T = aT_1$, $M = (-1)^n I$; no other "
        r"closings, by the window theorem). The three ratios the text names are special cases: "
        + ", ".join(
            f"{k} at $n = {', '.join(str(x.order) for x in v)}$ ($m = {v[0].m}$)"
            for k, v in found.items()
        )
        + r". The 2:1 closing is the one the text explains ($a = 1$, $b = 2$: half an oscillation "
        r"of $T_1$ and a full one of $T_2$ per cycle, $M = -I$, so every motion repeats after two "
        f"cycles). For $n \\le 6$ the theorem gives {len(c)} closings: {listing}. Not named in the "
        "text: "
        + ", ".join(f"{x.ratio} ($n = {x.order}$, $m = {x.m} = {float(x.m):.3f}$)" for x in others)
        + "; they lie at depths near 0.9, where Fig. 2 may not reach. No closings for "
        "$n = 1, 2$ (the text's '$n > 2$' agrees)."
    )
    return Row("§5", "agrees" if ok else "differs", printed, derived, how, "Closings of intervals")
