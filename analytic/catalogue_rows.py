"""Catalogue rows for the paper's exact (non-series) results: printed form against derived form.

Agreement means: each printed equation is a non-vanishing multiple of the derived one once the
abbreviations (``q, p, omega_av, ...``) are expanded, decided by :mod:`analytic.identity` (the
factor
is found as the ratio of the two sides and must be free of the oscillating parts; otherwise random
points at 40 digits).  A difference is described by the smallest sub-expressions in which the
printed
and derived forms part (:func:`difference`), and the derived form is given as the correct one.
"""

from __future__ import annotations

from collections import Counter

import sympy as sp

from .catalogue import Row, latex, row, written
from .identity import Verdict, prove_multiple, prove_zero
from .model import Damping, S, inertia, segment
from .printed import CLAIMS, dphi, phi, printed
from .reductions import MP, PM, chain, odd_order_delta_form, substitute_abbreviations
from .stitching import EdgeKind, Parity, edge_system, general_system

__all__ = ["difference", "compare_equations"]


def _latex(e) -> str:
    if isinstance(e, (tuple, list)):
        return r",\quad ".join(_latex(x) for x in e)
    return latex(e)


def difference(a: sp.Basic, b: sp.Basic) -> list[tuple[sp.Basic, sp.Basic]]:
    """The smallest pairs of sub-expressions in which ``a`` and ``b`` part.

    Walks both trees together; for sums and products the arguments common to both are set aside and,
    if exactly one argument remains on each side, the walk continues into that pair.
    """
    if a == b:
        return []
    if type(a) is not type(b) or not a.args or not b.args:
        return [(a, b)]
    if a.is_Add or a.is_Mul:
        ca, cb = Counter(a.args), Counter(b.args)
        ra, rb = list((ca - cb).elements()), list((cb - ca).elements())
        if len(ra) == 1 and len(rb) == 1:
            return difference(ra[0], rb[0])
        return [(a.func(*ra) if ra else a.func.identity, b.func(*rb) if rb else b.func.identity)]
    if len(a.args) != len(b.args):
        return [(a, b)]
    out = []
    for x, y in zip(a.args, b.args, strict=True):
        out.extend(difference(x, y))
    return out


def _residual(eq) -> sp.Expr:
    e = eq.lhs - eq.rhs if isinstance(eq, sp.Equality) else eq
    if e.has(PM) or e.has(MP):
        lhs, rhs = eq.lhs, eq.rhs.subs({PM: 1, MP: 1})
        return sp.expand(lhs**2 - rhs**2)
    return e


def compare_equations(printed_eq: sp.Equality, derived_eq: sp.Equality) -> Verdict:
    """Is the printed equation a non-vanishing multiple of the derived one?

    First with the abbreviations ``q, p, omega_av, Delta omega`` kept as independent symbols (only
    ``T_av = 2 pi / omega_av`` used): agreement there is agreement.  Otherwise with everything
    expanded into the primary symbols.
    """
    a, b = _residual(printed_eq), _residual(derived_eq)
    tav = {S.T_av: 2 * sp.pi / S.omega_av}
    qa, qb = sp.expand(a.subs(tav)), sp.expand(b.subs(tav))
    if qb != 0:
        quick = prove_multiple(qa, qb)
        if quick.holds or qa.free_symbols == qb.free_symbols:
            return quick
    a, b = substitute_abbreviations(a), substitute_abbreviations(b)
    if b == 0:
        return prove_zero(a)
    return prove_multiple(a, b)


def _how_agrees(verdicts: list[Verdict], extra: str = "") -> str:
    routes = {v.route for v in verdicts}
    facs = [v.factor for v in verdicts if v.factor is not None and v.factor != 1]
    text = "Printed and derived forms are the same equation"
    if facs:
        text += " up to the non-vanishing factor" + ("s " if len(facs) > 1 else " ")
        text += ", ".join(f"${latex(f)}$" for f in facs)
    if routes == {"symbolic"}:
        text += (
            "; decided symbolically (exact rational identity after expanding the abbreviations)."
        )
    else:
        num = [v for v in verdicts if v.route == "numeric"]
        text += "; " + num[0].describe() + "."
    return text + (" " + extra if extra else "")


def _decided(verdicts: list[Verdict]) -> str:
    """How a row's checks were decided: symbolically only if every one of them was."""
    num = [v for v in verdicts if v.route != "symbolic"]
    return "decided symbolically." if not num else num[0].describe() + "."


def _how_differs(pe: sp.Equality, de: sp.Equality) -> str:
    flipped = sp.Eq(-de.lhs, -de.rhs, evaluate=False)
    parts = min(difference(pe, de), difference(pe, flipped), key=len)
    de = de if parts == difference(pe, de) else flipped
    shown = "; ".join(
        f"printed ${latex(x)}$ where the derivation gives ${latex(y)}$" for x, y in parts[:3]
    )
    return f"Misprint: {shown}. The correct form is ${latex(de)}$."


def _compare_row(label: str, title: str, derived: tuple, extra: str = "") -> Row:
    pr = printed()[label]
    verdicts = [compare_equations(p_, d_) for p_, d_ in zip(pr, derived, strict=True)]
    if all(v.holds for v in verdicts):
        return Row(
            label, "agrees", _latex(pr), _latex(derived), _how_agrees(verdicts, extra), title
        )
    bad = [k for k, v in enumerate(verdicts) if not v.holds]
    how = " ".join(_how_differs(pr[k], derived[k]) for k in bad)
    return Row(
        label, "differs", _latex(pr), _latex(derived), how + (" " + extra if extra else ""), title
    )


def _steps(key: str, label: str) -> tuple:
    return tuple(s.expr for s in chain(key).steps if s.label == label)


# ------------------------------------------------------------------------------- the model


@row("1")
def _eq1() -> Row:
    # exact tuning (6) at m -> 0: T_av -> T0
    n = S.n
    Tav_m = 2 * sp.pi / ((S.omega0 / sp.sqrt(1 + S.m) + S.omega0 / sp.sqrt(1 - S.m)) / 2)
    T_lim = sp.limit(n * Tav_m / 2, S.m, 0)
    derived = (
        written(sp.Symbol(r"\omega"), 2 * sp.pi / T_lim),
        written(S.T, T_lim.subs(S.omega0, 2 * sp.pi / S.T0)),
    )
    pr = printed()["1"]
    v = [
        prove_zero(pr[0].rhs - derived[0].rhs),
        prove_zero(pr[1].rhs - derived[1].rhs),
    ]
    ok = all(x.holds for x in v)
    return Row(
        "1",
        "agrees" if ok else "differs",
        _latex(pr),
        _latex(derived),
        "The limit $m \\to 0$ of the exact tuning condition (6), $T = nT_{av}/2$ with "
        "$T_{av} \\to T_0$; " + (_decided(v) if ok else "the limits differ."),
        "Naive resonance condition",
    )


@row("2-3")
def _eq23() -> Row:
    # a rigid pendulum: a point bob at distance l, drag -c v on the bob (v = l phi'); the moment
    # of inertia is J0 at l0, so the bob's mass is J0/l0^2 (M is the monodromy matrix elsewhere)
    J0, c, gr, l0, l = sp.symbols("J_0 c g l_0 l", positive=True)
    mass = J0 / l0**2
    ph = sp.Function(r"\varphi")(S.t)
    J = mass * l**2
    torque = -mass * gr * l * sp.sin(ph) - c * l**2 * sp.Derivative(ph, S.t)
    eom = sp.expand((J * sp.Derivative(ph, S.t, 2) - torque) / J)
    gam = sp.Rational(1, 2) * eom.coeff(sp.Derivative(ph, S.t))
    om2 = eom.coeff(sp.sin(ph))
    om0 = sp.sqrt(gr / l0)
    w1 = sp.sqrt(om2.subs(l, l0 * (1 + S.m)))
    w2 = sp.sqrt(om2.subs(l, l0 * (1 - S.m)))
    # both frequencies are positive, so equal squares mean equal frequencies (the squares are
    # rational in the symbols: an exact identity, where the roots themselves are not reduced)
    checks = [
        prove_zero(gam.diff(l)),  # damping constant independent of the length
        prove_zero(w1**2 - om0**2 / (1 + S.m)),
        prove_zero(w2**2 - om0**2 / (1 - S.m)),
    ]
    ok = all(x.holds for x in checks)
    derived = (
        written(eom.subs(l, l0 * (1 + S.m)), 0),
        written(S.gamma, gam),
        written(S.omega1, om0 / sp.sqrt(1 + S.m)),
        written(S.omega2, om0 / sp.sqrt(1 - S.m)),
    )
    pr = printed()["2"] + printed()["3"]
    return Row(
        "2-3",
        "agrees" if ok else "differs",
        _latex(pr),
        _latex(derived),
        r"Derived from $J\ddot\varphi = $ torque for a point bob, with $J = J_0 (l/l_0)^2$ (so "
        r"$J_0/l_0^2$ is the bob's mass), the torque of gravity $-(J_0/l_0^2)\,gl\sin\varphi$ and "
        r"that of the drag $-cl^2\dot\varphi$ on the bob: $2\gamma = cl_0^2/J_0$ does "
        r"not depend on $l$ (the same in both halves), $\omega_i^2 = g/l_i$ with "
        r"$l_{1,2} = l_0(1 \pm m)$; " + _decided(checks),
        "Equations of motion in each half",
    )


@row("4")
def _eq4() -> Row:
    # J = J0 (l/l0)^2: J0 is the moment of inertia at the length l0
    J0, l0 = sp.symbols("J_0 l_0", positive=True)
    J1, J2 = J0 * (l0 * (1 + S.m) / l0) ** 2, J0 * (l0 * (1 - S.m) / l0) ** 2
    d = sp.Function(r"\dot{\varphi}")
    derived = (written(sp.factor(J1 / J0) * d(1), sp.factor(J2 / J0) * d(2)),)
    v = prove_zero(sp.expand(J1 / J0 - inertia(1)) + sp.expand(J2 / J0 - inertia(2)))
    r = _compare_row(
        "4",
        "Angular-momentum jump",
        derived,
        r"The angular momentum $J\dot\varphi$ with $J = J_0 (l/l_0)^2$ is conserved.",
    )
    return (
        r
        if v.holds
        else Row(r.equation, "differs", r.printed, r.derived, "inertia mismatch", r.title)
    )


@row("5")
def _eq5() -> Row:
    d = printed()["5"]
    derived = (d[0], chain("single").step("5").expr)
    return _compare_row("5", "Average period", derived)


@row("6")
def _eq6() -> Row:
    return _compare_row("6", "Exact tuning", (printed()["6"][0], chain("single").step("6").expr))


def _shape_row(labels: tuple[str, str], kind: EdgeKind, title: str, amp: dict) -> list[Row]:
    """Printed segments against the engine's edge shape (amplitude names mapped by ``amp``)."""
    seg1, seg2 = edge_system(kind).segments
    rows = []
    for label, half, seg in ((labels[0], 1, seg1), (labels[1], 2, seg2)):
        pr = printed()[label]
        ph_p = pr[0].rhs.subs(amp)
        dph_p = pr[1].rhs.subs(amp)
        same = prove_zero(ph_p - seg.phi)
        consistent = prove_zero(dph_p - sp.diff(pr[0].rhs, S.t).subs(amp))
        derived = (written(phi[half](S.t), seg.phi), written(dphi[half](S.t), seg.dphi))
        ok = same.holds and consistent.holds
        how = (
            f"The printed segment is the engine's edge shape {kind.value} and its printed "
            "velocity is the "
            "time derivative of the printed angle; " + _decided([same, consistent])
            if ok
            else f"shape: {same.describe()}; velocity: {consistent.describe()}"
        )
        rows.append(
            Row(label, "agrees" if ok else "differs", _latex(pr), _latex(derived), how, title)
        )
    return rows


@row("8-9")
def _eq89() -> list[Row]:
    return _shape_row(
        ("8", "9"), EdgeKind.ODD_COS_SIN, "Segments on the lower edge of the first interval", {}
    )


@row("16-17")
def _eq1617() -> list[Row]:
    return _shape_row(
        ("16", "17"),
        EdgeKind.ODD_SIN_COS,
        "Segments on the upper edge of the first interval",
        {S.B1: S.A1, S.B2: S.A2},
    )


@row("20-21")
def _eq2021() -> list[Row]:
    return _shape_row(
        ("20", "21"), EdgeKind.EVEN_COS_COS, "Segments on the lower edge of the second interval", {}
    )


# ---------------------------------------------------------------- odd orders, no friction


@row("10")
def _eq10() -> Row:
    return _compare_row("10", "Angle continuity at t = 0", _steps("edge-odd-cos-sin", "10"))


@row("11")
def _eq11() -> Row:
    return _compare_row("11", "Momentum jump at t = 0", _steps("edge-odd-cos-sin", "11"))


@row("12")
def _eq12() -> Row:
    return _compare_row("12", "Determinant of (10)-(11)", _steps("edge-odd-cos-sin", "12"))


@row("13")
def _eq13() -> Row:
    return _compare_row("13", "Product-to-sum form of (12)", _steps("edge-odd-cos-sin", "13"))


@row("14")
def _eq14() -> Row:
    return _compare_row("14", "q as a function of m", (chain("single").step("14").expr,))


@row("15")
def _eq15() -> Row:
    return _compare_row(
        "15", "Fixed-point form for Delta T (first interval)", _steps("edge-odd-cos-sin", "15")
    )


@row("IC-15")
def _ic15() -> Row:
    return _compare_row(
        "IC-15",
        "Stationary initial condition on the lower edge (after eq. 15)",
        _steps("initial", "IC-15"),
    )


# ---------------------------------------------------------------- even orders, no friction


@row("22")
def _eq22() -> Row:
    return _compare_row(
        "22", "Angle continuity at t = 0 (second interval)", _steps("edge-even-cos-cos", "22")
    )


@row("23")
def _eq23() -> Row:
    r = _compare_row(
        "23", "Momentum jump at t = 0 (second interval)", _steps("edge-even-cos-cos", "23")
    )
    if r.status == "differs":
        # does the printed (24) follow from the printed (22)-(23)?  (it follows from the derived
        # ones)
        p22, p23, p24 = printed()["22"][0], printed()["23"][0], printed()["24"][0]
        rows = [sp.expand(e.lhs - e.rhs) for e in (p22, p23)]
        Mp = sp.Matrix([[sp.diff(x, u) for u in (S.A1, S.A2)] for x in rows])
        follows = compare_equations(written(Mp.det(), 0), p24).holds
        note = (
            " The printed (24) does not follow from the printed (22)-(23) (their determinant is "
            f"${latex(sp.factor(Mp.det()))}$), but does follow from the corrected (23)."
            if not follows
            else ""
        )
        r = Row(r.equation, r.status, r.printed, r.derived, r.how + note, r.title)
    return r


@row("24")
def _eq24() -> Row:
    return _compare_row("24", "Determinant of (22)-(23)", _steps("edge-even-cos-cos", "24"))


@row("25")
def _eq25() -> Row:
    return _compare_row("25", "Product-to-sum form of (24)", _steps("edge-even-cos-cos", "25"))


@row("26")
def _eq26() -> Row:
    return _compare_row(
        "26", "Fixed-point form for Delta T (second interval)", _steps("edge-even-cos-cos", "26")
    )


@row("IC-26")
def _ic26() -> Row:
    return _compare_row(
        "IC-26",
        "Stationary initial condition on the lower edge of the second interval",
        _steps("initial", "IC-26"),
    )


# ----------------------------------------------------------------------- with friction


@row("28-30")
def _eq2830() -> Row:
    s1 = segment(S.omega1, S.A1, S.B1, Damping.PAPER)
    s2 = segment(S.omega2, S.A2, S.B2, Damping.PAPER)
    pr = printed()["28"] + printed()["29"] + printed()["30"]
    derived = (
        written(phi[1](S.t), s1.phi),
        written(dphi[1](S.t), s1.dphi),
        written(phi[2](S.t), s2.phi),
        written(dphi[2](S.t), s2.dphi),
    )
    vs = [prove_zero(a.rhs - b.rhs) for a, b in zip(pr, derived, strict=True)]
    true_d = sp.diff(s1.phi, S.t)
    # the common factors taken out of the sum (``simplify`` finds no shorter form of it)
    dropped = sp.factor_terms(true_d - s1.dphi)
    ok = all(v.holds for v in vs)
    return Row(
        "28-30",
        "agrees" if ok else "differs",
        _latex(pr),
        _latex(derived),
        "The printed segments are the engine's 'paper' damping model; "
        + _decided(vs)
        + " As the text "
        "says, the printed velocity is not the derivative of the angle: it drops "
        f"${latex(dropped)}$ "
        "(valid for $\\gamma \\ll \\omega$). The 'exact' model keeps it.",
        "Damped segments (paper model)",
    )


@row("31")
def _eq31() -> Row:
    gen = general_system(Parity.ODD, Damping.PAPER)
    c3, c4 = gen.conditions[2:]
    pr = printed()["31"]
    s1, s2 = gen.segments
    sub = {
        phi[1](S.T / 2): s1.phi.subs(S.t, S.T / 2),
        phi[2](-S.T / 2): s2.phi.subs(S.t, -S.T / 2),
        dphi[1](S.T / 2): s1.dphi.subs(S.t, S.T / 2),
        dphi[2](-S.T / 2): s2.dphi.subs(S.t, -S.T / 2),
    }
    vs = [
        prove_zero(sp.expand((a.lhs - a.rhs).subs(sub) - (b.lhs - b.rhs)))
        for a, b in zip(pr, (c3, c4), strict=True)
    ]
    ok = all(v.holds for v in vs)
    return Row(
        "31",
        "agrees" if ok else "differs",
        _latex(pr),
        _latex((c3.equation, c4.equation)),
        "The anti-periodicity conditions the engine builds for odd orders (angle, and angular "
        "momentum across "
        "t = T/2); " + _decided(vs),
        "Periodicity conditions, odd orders with friction",
    )


@row("32")
def _eq32() -> Row:
    return _compare_row("32", "Homogeneous system for A, B", _steps("friction-odd", "32"))


@row("33")
def _eq33() -> Row:
    pr = printed()["33"]
    vs = [prove_zero(substitute_abbreviations(e.lhs - e.rhs)) for e in pr]
    ok = all(v.holds for v in vs)
    return Row(
        "33",
        "agrees" if ok else "differs",
        _latex(pr),
        _latex(pr),
        "Notation, the same as the engine's abbreviations (half-period phases).",
        "Notation C_i, S_i",
    )


@row("34")
def _eq34() -> Row:
    return _compare_row("34", "Determinant of (32)", _steps("friction-odd", "34"))


@row("35")
def _eq35() -> Row:
    return _compare_row("35", "Product to sum", _steps("friction-odd", "35"))


@row("36")
def _eq36() -> Row:
    return _compare_row(
        "36",
        "Boundary equation, odd orders with friction",
        _steps("friction-odd", "36"),
        "Checked squared (one sign per edge).",
    )


@row("39")
def _eq39() -> Row:
    return _compare_row(
        "39",
        "Fixed-point form with friction (first interval)",
        _steps("friction-odd", "39"),
        "Checked squared (one sign per edge).",
    )


@row("41")
def _eq41() -> Row:
    return _compare_row(
        "41",
        "Boundary equation, even orders with friction",
        _steps("friction-even", "41"),
        "Checked squared (one sign per edge).",
    )


@row("44")
def _eq44() -> Row:
    return _compare_row(
        "44",
        "Fixed-point form with friction (second interval)",
        _steps("friction-even", "44"),
        "Checked squared (one sign per edge).",
    )


# ------------------------------------------------------------------ statements of the text


def _reference_row(label: str, title: str, candidates: tuple[str, ...]) -> Row:
    """A cross-reference 'X at p = 1 coincides with (Y)': find which candidate it coincides with."""
    text, eq_from, eq_to = CLAIMS[label]
    src = printed()[eq_from][0]
    at_p1 = written(src.lhs, src.rhs.subs(S.p, 1))
    matches = []
    for cand in candidates:
        tgt = printed()[cand][0]
        # a +- form coincides with an equation if it does so for one of its signs: compare squares
        squared = written(tgt.lhs**2 - tgt.rhs**2, 0)
        if compare_equations(at_p1, squared).holds:
            matches.append(cand)
    ok = eq_to in matches
    how = (
        f"{text} At $p = 1$ the (squared) equation ({eq_from}) is a non-vanishing multiple of "
        + (", ".join(f"({c})" for c in matches) if matches else "none of " + ", ".join(candidates))
        + (
            "; the reference is right."
            if ok
            else f"; the reference should be ({matches[0]}), not ({eq_to})."
        )
    )
    return Row(
        label,
        "agrees" if ok else "differs",
        _latex(at_p1),
        _latex(printed()[matches[0]][0]) if matches else "",
        how,
        title,
    )


@row("39-ref")
def _ref39() -> Row:
    return _reference_row("39-ref", "Cross-reference after eq. (39)", ("13", "14", "15"))


@row("44-ref")
def _ref44() -> Row:
    return _reference_row("44-ref", "Cross-reference after eq. (44)", ("25", "26"))


@row("40-ref")
def _ref40() -> Row:
    text, eq_from, _ = CLAIMS["40-ref"]

    def has_radicand(e) -> bool:
        return any(
            isinstance(a, sp.Pow) and a.exp == sp.S.Half and a.base.has(S.p)
            for a in sp.preorder_traversal(e)
        )

    holders = [k for k, eqs in printed().items() if any(has_radicand(e) for e in eqs)]
    ok = eq_from in holders
    return Row(
        "40-ref",
        "agrees" if ok else "differs",
        _latex(printed()[eq_from]),
        _latex(printed()["39"]),
        f"{text} Equation ({eq_from}) has no radicand; the printed equations with one are "
        + ", ".join(f"({h})" for h in holders)
        + ". The simplification described ($q \\approx 1 + 3m$, cosine $\\approx 1$) is of the "
        "radicand of (39), "
        "whose small-$m$ solution is (40).",
        "Cross-reference before eq. (40)",
    )


@row("15-n3")
def _claim15() -> Row:
    text = CLAIMS["15-n3"][0]
    f13 = odd_order_delta_form(EdgeKind.ODD_COS_SIN, 3)  # shape (8)-(9), i.e. eqs. (10)-(11)
    f17 = odd_order_delta_form(EdgeKind.ODD_SIN_COS, 3)  # shape (16)-(17)
    p15 = printed()["15"][0]
    generalised = written(p15.lhs, p15.rhs.subs(S.T_av / 2, 3 * S.T_av / 2))
    same_as_13 = compare_equations(generalised, f13).holds
    same_as_17 = compare_equations(generalised, f17).holds
    # sign of Delta T at small m for the eq.-(13) shape: sin(...) = s * (q-1)/(q+1) * cos(small)
    sign13 = sp.sign(f13.rhs.subs({S.Domega: 0, S.q: 2}))
    side = "upper (right)" if sign13 > 0 else "lower (left)"
    status = "agrees" if same_as_13 and sign13 < 0 else "differs"
    how = (
        f"{text} Derived: for $n = 3$ the shape (8)-(9) of eqs. (10)-(11) gives "
        f"${latex(f13)}$, whose small-$m$ root has "
        f"$\\Delta T {'>' if sign13 > 0 else '<'} 0$: the {side} edge. Eq. (15) with "
        "$T_{av}/2 \\to 3T_{av}/2$ "
        f"{'is' if same_as_17 else 'is not'} the equation of the other shape (16)-(17), and it is "
        "that one that gives the left edge. In general the shape of (8)-(9) gives the lower edge "
        "for $n = 1, 5, 9, \\dots$ and the upper edge for $n = 3, 7, 11, \\dots$ at small $m$, and "
        "the two shapes swap edges at every closing of the interval. The printed (15) with "
        "$nT_{av}/2$ does give the left edge of every odd interval at small $m$; the statement "
        "that it comes from (10)-(11) holds only for $n = 1, 5, 9, \\dots$"
    )
    return Row(
        "15-n3",
        status,
        _latex(generalised),
        _latex((f13, f17)),
        how,
        "Left edge of the third interval (the paper's section 3.2)",
    )
