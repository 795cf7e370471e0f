"""Section 4: the edges as series in ``m`` (orders 1-6 and general ``n``), thresholds with friction
and the edges above them, in both damping models (:mod:`analytic.expansions`,
:mod:`analytic.thresholds`), each set against the paper's numbered formula."""

from __future__ import annotations

import sympy as sp

from ..i18n import say
from ..latex import (
    Latex,
    equation_lines,
    inline,
    math,
    mixed,
    pack,
    paragraph,
    raw,
    ref,
    section,
    series_terms,
)
from . import Context, Part
from ._render import note

TITLE = "Expansions in the depth"
LABEL = "sec:expansions"

ORDERS = (1, 2, 3, 4, 5, 6)
TERMS = 4
THRESHOLD_ORDERS = (1, 2, 3, 4)
NEAR_ORDERS = (1, 2)
#: the paper's formula for the edges of an order, and for its threshold
PAPER_EDGES = {1: ("18",), 2: ("27",), 3: ("19", "19-shift")}
PAPER_THRESHOLD = {1: ("37", "38"), 2: ("42", "43"), 3: ("§6-n3",)}
PAPER_NEAR = {1: ("40",), 2: ("45",)}


def _lines(lhs: Latex, terms: list[Latex], width: int) -> list[Latex]:
    first = Latex(lhs.raw + " = ") + terms[0]
    return pack([first, *terms[1:]], width)


def _series_display(lhs: Latex, expr, var, ctx: Context, big_o: int | None) -> Latex:
    return equation_lines(
        _lines(lhs, series_terms(expr, var, ctx.config, big_o=big_o), ctx.config.max_width)
    )


def _rows_by_label(ctx: Context) -> dict:
    from .catalogue import rows

    return {r.equation: r for r in rows(ctx)}


def _paper_note(labels, by_label) -> Latex:
    """``Paper (18): agrees, see ...`` for each label present in the catalogue."""
    from .catalogue import eq_text

    parts = []
    for lab in labels:
        r = by_label.get(lab)
        if r is None:
            continue
        word = (
            say("agrees", "совпадает")
            if r.status == "agrees"
            else r"\textbf{" + say("differs", "расходится") + "}"
        )
        ref = f"p.~\\pageref{{cat:{_key(lab)}}}"
        shown = eq_text(lab).raw  # as the catalogue prints it: (19), (19, centre), \S 6, n = 3
        parts.append(
            raw(
                say(
                    f"Paper {shown}: {word} (catalogue, {ref}).",
                    f"Статья {shown}: {word} (каталог, с.~{ref[3:]}).",
                )
            )
        )
    return note(*parts) if parts else Latex("")


#: the parity of the order as a subscript (``T_-/T_0|_{n odd}``)
_PARITY = {"odd": lambda: say("odd", "нечётное"), "even": lambda: say("even", "чётное")}
#: the engine's leading threshold ``m_min0`` as the report writes it
_MMIN0 = sp.Symbol(r"m_{\min,0}", positive=True)


def _shown_mmin0(expr):
    """``expr`` with the engine's symbol ``m_min0`` written as :data:`_MMIN0`."""
    return expr.subs({x: _MMIN0 for x in expr.free_symbols if x.name == "m_min0"})


#: the damping model named after a formula
_DAMPING = {
    "paper": lambda: say("paper", "модель статьи"),
    "exact": lambda: say("exact", "точная модель"),
}


def _key(label: str) -> str:
    from .catalogue import anchor

    return anchor(label)


def _frictionless(ctx: Context, by_label: dict) -> list[Latex]:
    from analytic.expansions import closed_forms, edge_series
    from analytic.model import S

    m = S.m
    out = [
        section("Edges without friction, orders 1 to 6", "sec:series-orders", level=1),
        paragraph(
            "Each edge is the root of one per-edge factor (",
            ref("Section", "sec:per-edge"),
            "), solved for",
            inline(raw(r"\theta(m)")),
            "by Newton steps on exact power series, then",
            inline(raw(r"T/T_{av} = n/2 + \theta/\pi")),
            "and",
            inline(raw(r"T/T_0 = (T/T_{av})/w")),
            "with the parameters expanded from their definitions; through",
            inline(raw(f"m^{TERMS}")),
            ":",
        ),
    ]
    for n in ORDERS:
        es = edge_series(n, TERMS)
        for side, sym in (("lower", "-"), ("upper", "+")):
            lhs = raw(f"T^{{({n})}}_{sym}/T_0")
            out.append(_series_display(lhs, es.in_T0[side], m, ctx, TERMS + 1))
        out.append(_paper_note(PAPER_EDGES.get(n, ()), by_label))
    cf = closed_forms(TERMS)
    out += [
        section("General order", "sec:series-general", level=1),
        paragraph(
            "The same computation with the order kept as a symbol",
            inline(raw("n")),
            "gives closed forms valid for every odd and every even order:",
        ),
    ]
    n = S.n
    for word in ("odd", "even"):
        d = cf[word]
        for side, sym in (("lower", "-"), ("upper", "+")):
            out.append(
                _series_display(
                    raw(f"T_{sym}/T_0\\big|_{{n\\ \\text{{{_PARITY[word]()}}}}}"),
                    d[f"{side}_T0"],
                    m,
                    ctx,
                    TERMS + 1,
                )
            )
        out.append(
            paragraph(
                f"Width and centre for {word} orders, leading terms:",
                inline(
                    math(
                        sp.Eq(sp.Symbol("T_+") - sp.Symbol("T_-"), d["width_leading_T0"]),
                        ctx.config,
                    )
                ),
                raw(r"$T_0$,"),
                inline(
                    math(
                        sp.Eq(
                            (sp.Symbol("T_+") + sp.Symbol("T_-")) / 2 - n * sp.Symbol("T_0") / 2,
                            d["centre_leading_T0"] * sp.Symbol("T_0"),
                        ),
                        ctx.config,
                    )
                ),
                "; in units of",
                inline(raw("T_{av}")),
                "the centre moves only at",
                inline(math(d["centre_leading_Tav"] * sp.Symbol("T_{av}"), ctx.config)),
                ".",
            )
        )
    return out


def _thresholds(ctx: Context, by_label: dict) -> list[Latex]:
    from analytic.thresholds import Q_SYM, model_gap, threshold_series

    out = [
        section("Thresholds with friction", "sec:thresholds", level=1),
        paragraph(
            mixed(
                r"With friction an interval exists only above a threshold depth $m_{\min}(Q)$. "
                r"At the threshold the instability indicator has a double zero in $\theta$ (a "
                r"tangency); in the distinguished scaling $1/Q = \lambda m^p$ ($p = 1$ for odd "
                r"orders, 2 for even) both conditions are solved as series and reverted. Both "
                r"damping models:"
            )
        ),
    ]
    mmin = sp.Symbol(r"m_{\min}")
    for n in THRESHOLD_ORDERS:
        for damping in ("paper", "exact"):
            ts = threshold_series(n, TERMS, damping=damping)
            lhs = raw(f"m^{{({n})}}_{{\\min}}\\ \\text{{({_DAMPING[damping]()})}}")
            eps = sp.Symbol("epsilon")
            Qs = sp.Symbol("Q", positive=True)
            if ts.p == 1:
                expr, shown = ts.m_min, lhs
            else:
                expr, shown = ts.m_min2, Latex(f"\\left({lhs.raw}\\right)^2")
            expr = sp.expand(sp.expand(expr).subs(Q_SYM, 1 / eps))
            terms = series_terms(expr, eps, ctx.config, big_o=TERMS + 1, shown_as=1 / Qs)
            out.append(equation_lines(_lines(shown, terms, ctx.config.max_width)))
        gap = model_gap(n, TERMS)
        where = gap.get("threshold")
        out.append(
            note(
                say(f"Order {n}: leading term", f"Порядок {n}: главный член"),
                inline(math(sp.Eq(mmin, ts.m_min_leading), ctx.config)),
                "; the two models part at",
                inline(raw(f"m^{{{where}}}")) if where is not None else "no order computed",
                "in the threshold series",
                inline(raw(r"\lambda(m) = 1/(Q_{\min} m^p)")),
                ".",
                _paper_note(PAPER_THRESHOLD.get(n, ()), by_label),
            )
        )
    return out


def _near(ctx: Context, by_label: dict) -> list[Latex]:
    from analytic.model import S
    from analytic.thresholds import near_threshold_edges

    m = S.m
    out = [
        section("Edges above the threshold", "sec:near-threshold", level=1),
        paragraph(
            mixed(
                r"Above the threshold the edges are series in $m$ at fixed "
                r"$s = \sqrt{1 - (m_{\min,0}/m)^{2}}$ (odd orders) or "
                r"$s = \sqrt{1 - (m_{\min,0}/m)^{4}}$ (even orders), with $m_{\min,0}$ the "
                r"leading threshold; "
                r"the paper's eqs. (40) and (45) are the first terms. Both damping models, in "
                r"units of $T_0$:"
            )
        ),
    ]
    for n in NEAR_ORDERS:
        for damping in ("paper", "exact"):
            es = near_threshold_edges(n, 3, damping=damping)  # Q kept as a symbol
            sc = es.scaled
            for side, sym in (("lower", "-"), ("upper", "+")):
                lhs = raw(f"T^{{({n})}}_{sym}/T_0\\ \\text{{({_DAMPING[damping]()})}}")
                out.append(_series_display(lhs, sc["T0"][side], m, ctx, 4))
        out.append(
            note(
                say("Here", "Здесь"),
                inline(math(_shown_mmin0(sc["s"]), ctx.config)),
                "with",
                inline(math(sp.Eq(_MMIN0, es.threshold["m_min_leading"]), ctx.config)),
                ".",
                _paper_note(PAPER_NEAR.get(n, ()), by_label),
            )
        )
    return out


def build(ctx: Context) -> Part:
    by_label = _rows_by_label(ctx)
    blocks = _frictionless(ctx, by_label) + _thresholds(ctx, by_label) + _near(ctx, by_label)
    return Part(Latex("\n\n".join(b.raw for b in blocks if not b.empty)))
