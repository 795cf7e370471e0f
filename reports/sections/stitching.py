"""Section 2: stitching systems and determinants for every boundary kind, each reduction step,
ending in the per-edge equations (from :mod:`analytic.stitching`, :mod:`analytic.normal_form` and
:mod:`analytic.reductions`)."""

from __future__ import annotations

import sympy as sp

from analytic.identity import vanishes
from analytic.model import Damping, S
from analytic.normal_form import (
    K,
    det_monodromy,
    edge_factor,
    edge_factor_link,
    normal_form_link,
    order_form,
    parameters,
    r2,
    trace_form,
    trace_lemma,
)
from analytic.stitching import (
    EdgeKind,
    Parity,
    edge_system,
    floquet_condition,
    general_system,
    implied_rows,
)

from ..i18n import say
from ..latex import Latex, equation, inline, math, paragraph, raw, section, table, text
from . import Context, Part
from ._render import CHECKS_STATED_ONCE, chain, check, link, note

TITLE = "Stitching systems, determinants and the per-edge equations"
LABEL = "sec:stitching"

#: the paper's numbers of the segments of each edge shape (none for the fourth shape)
SEGMENT_TAGS = {
    EdgeKind.ODD_COS_SIN: ("8", "9"),
    EdgeKind.ODD_SIN_COS: ("16", "17"),
    EdgeKind.EVEN_COS_COS: ("20", "21"),
    EdgeKind.EVEN_SIN_SIN: (None, None),
}

_WORD = {Parity.ODD: "odd", Parity.EVEN: "even"}
_MODEL = {Damping.NONE: "no friction", Damping.PAPER: "paper model", Damping.EXACT: "exact model"}


def _m(expr, ctx: Context) -> Latex:
    return inline(math(expr, ctx.config))


def _join(blocks) -> Latex:
    return Latex("\n\n".join(b.raw for b in blocks))


def _general(ctx: Context) -> list[Latex]:
    out = [
        section("The general system", "sec:general", level=1),
        paragraph(
            "A stationary oscillation on an edge is made of two free segments, ",
            _m(sp.Symbol("varphi_1"), ctx),
            "on",
            inline(raw("0<t<T/2")),
            "and",
            _m(sp.Symbol("varphi_2"), ctx),
            "on",
            inline(raw("-T/2<t<0")),
            ", with four amplitudes. Continuity of the angle and the angular-momentum jump at",
            inline(raw("t=0")),
            "and (anti)periodicity across",
            inline(raw("t=T/2")),
            "give four homogeneous linear conditions. Without friction, for odd orders",
            inline(raw(r"(\sigma=-1)")),
            ":",
        ),
    ]
    for parity in (Parity.ODD, Parity.EVEN):
        sysm = general_system(parity, Damping.NONE)
        if parity is Parity.EVEN:
            out.append(paragraph("and for even orders", inline(raw(r"(\sigma=+1)")), ":"))
        for c in sysm.conditions:
            out.append(equation(c.equation, config=ctx.config))
    out.append(
        paragraph(
            raw(
                "The segments of the paper model and of the exact model "
                "(Table~\\ref{tab:segments}) give the "
                "same four conditions with their own segments. Their determinant is, in every "
                "model, a "
                "non-vanishing factor"
            ),
            inline(raw("F")),
            "times the Floquet condition: with",
            inline(raw("M")),
            "the monodromy matrix (the period map of",
            inline(raw(r"(\varphi,\dot\varphi)")),
            "from",
            inline(raw("t=0+")),
            "),",
        )
    )
    out.append(
        equation(
            raw(
                r"\det(\text{"
                + say("stitching system", "система сшивания")
                + r"}) = F\,\det(M - \sigma I)"
            ),
            numbered=False,
        )
    )
    rows = []
    for damping in Damping:
        for parity in Parity:
            _, factor = floquet_condition(parity, damping)
            rows.append(
                [
                    text(_MODEL[damping]),
                    text(_WORD[parity]),
                    _m(sp.factor(factor), ctx)
                    if factor is not None
                    else raw(r"\textbf{not proportional}"),
                ]
            )
    out.append(
        table(
            ["model", "orders", raw("factor $F$")],
            rows,
            columns="llc",
            caption=raw(
                "The factor between the determinant of the four stitching conditions and "
                r"$\det(M-\sigma I)$, found as the ratio of the two (a symbolic identity: the "
                r"ratio "
                "is free of the oscillating terms). The boundary condition \\emph{is} the "
                "statement that "
                r"$\sigma = (-1)^n$ is a Floquet multiplier."
            ),
            label="tab:floquet-factor",
        )
    )
    return out


def _normal_form(ctx: Context) -> list[Latex]:
    cfg = ctx.config
    trM, detM = sp.Symbol(r"\operatorname{tr} M"), sp.Symbol(r"\det M")
    out = [
        section("From the determinant to the normal form", "sec:normal-form", level=1),
        paragraph("The monodromy matrix has determinant", inline(raw("p^2")), "in every model:"),
    ]
    for damping in (Damping.PAPER, Damping.EXACT):
        out.append(link(det_monodromy(damping), cfg, lhs=detM, title=f"det M, {_MODEL[damping]}"))
    out.append(
        paragraph(
            "so that",
            inline(raw(r"\det(M-\sigma I) = 1 + p^2 - \sigma\operatorname{tr} M")),
            ". Its trace has one form for all models, with the phases",
            inline(raw(r"a_i = \omega_i T/2")),
            "of the two halves over",
            inline(raw("T/2")),
            raw(
                say(
                    r"($a_i = \Omega_i T/2$ in the exact model)",
                    r"($a_i = \Omega_i T/2$ в точной модели)",
                )
            ),
            "and one coupling constant",
            inline(raw("K")),
            ":",
        )
    )
    Ksym = sp.Symbol("K")
    for damping in Damping:
        lnk = trace_form(damping)
        shown = lnk.rhs.subs(K(damping), Ksym)
        out.append(link(lnk, cfg, lhs=trM, rhs=shown, title=f"Trace form, {_MODEL[damping]}"))
    out.append(paragraph("where the coupling constant is"))
    out.append(equation(sp.Eq(Ksym, K(Damping.PAPER)), config=cfg))
    out.append(paragraph("without friction and in the paper model, and"))
    out.append(equation(sp.Eq(Ksym, K(Damping.EXACT)), config=cfg))
    out.append(
        paragraph(
            "in the exact model. A product-to-sum lemma in",
            inline(raw("K")),
            "alone, with",
            inline(raw(r"x = (a_1+a_2)/2")),
            "(the paper's",
            inline(raw(r"\omega_{av}T/2")),
            ") and",
            inline(raw(r"y = (a_2-a_1)/2")),
            "(the paper's",
            inline(raw(r"\Delta\omega T/4")),
            "):",
        )
    )
    for parity in Parity:
        out.append(link(trace_lemma(parity), cfg))
    out.append(
        paragraph(
            "Together these give the normal form",
            inline(raw(r"\det(M-\sigma I) = p\,(K+2)\,N")),
            "with",
            inline(raw(r"r^2 = (K-2)/(K+2)")),
            "and",
            inline(raw(r"h = \gamma T/2")),
            "(the rest state is unstable where",
            inline(raw("N<0")),
            "):",
        )
    )
    for parity in Parity:
        lnk = normal_form_link(parity)
        out.append(link(lnk, cfg))
    out.append(section("Parameters of the normal form", "sec:nf-parameters", level=1))
    out.append(
        paragraph(
            "Write",
            inline(raw(r"y = \beta x")),
            ",",
            inline(raw(r"\gamma T/2 = g x")),
            "and",
            inline(raw(r"T/T_0 = x/(\pi w)")),
            "(so",
            inline(raw(r"w = \omega_{av}/\omega_0")),
            "). In units",
            inline(raw(r"T_0 = 1")),
            "the engine defines the parameters as follows (exact model: the same with the damped "
            "frequencies",
            inline(raw(r"\Omega_i = \sqrt{\omega_i^2-\gamma^2}")),
            "in place of",
            inline(raw(r"\omega_i")),
            "):",
        )
    )
    for sym, expr in parameters(Damping.PAPER).items():
        if sym == r2:
            continue  # shown through K above
        expr = sp.simplify(expr)
        out.append(equation(sp.Eq(sym, expr), config=cfg))
    return out


def _edge_kind(kind: EdgeKind, ctx: Context, chains_by_key: dict | None, used: set) -> list[Latex]:
    cfg = ctx.config
    sysm = edge_system(kind)
    shape1, shape2 = kind.shapes
    word = _WORD[kind.parity]
    tags = SEGMENT_TAGS[kind]
    out = [
        section(f"Edge shape {kind.value}", f"sec:edge-{kind.value}", level=1),
        paragraph(
            f"Both halves symmetric about their midpoints: a {shape1} on the bob-down half, a "
            f"{shape2} on "
            f"the bob-up half ({word} orders"
            + (
                "; the paper's"
                + (
                    " lower edge of the first interval"
                    if kind is EdgeKind.ODD_COS_SIN
                    else " upper edge of the first interval"
                    if kind is EdgeKind.ODD_SIN_COS
                    else " edge of the second interval"
                )
                + ")"
                if tags[0]
                else "; the other edge of even intervals, which the paper does not write)"
            )
            + ":"
        ),
    ]
    for seg, tag, idx in zip(sysm.segments, tags, (1, 2), strict=True):
        out.append(equation(sp.Eq(sp.Symbol(f"varphi_{idx}"), seg.phi), tag=tag, config=cfg))
    late, early = implied_rows(kind)
    same = all(
        any(all(vanishes(late[i, j] - s * early[i, j]) for j in range(late.cols)) for s in (1, -1))
        for i in range(late.rows)
    )
    out.append(
        paragraph(
            "The conditions across",
            inline(raw("t=T/2")),
            "repeat those at",
            inline(raw("t=0")),
            "row by row up to sign" if same else "(\\textbf{check failed})",
            "(the engine compares the rows), so two conditions remain.",
        )
    )
    ch = chains_by_key.get(f"edge-{kind.value}") if chains_by_key else None
    if ch is not None:
        out.append(chain(ch, cfg, used_tags=used, heading=False))
    else:
        for c in sysm.conditions:
            out.append(equation(c.equation, config=cfg))
        out.append(paragraph("Their determinant:"))
        out.append(equation(sp.Eq(sysm.determinant, 0), config=cfg))
    lnk = edge_factor_link(kind)
    out.append(
        paragraph(
            "Per-edge factor: the determinant is a non-vanishing multiple of",
            _m(
                edge_factor(
                    kind.parity,
                    kind.epsilon,
                    symbols=(sp.Symbol("x"), sp.Symbol("y"), sp.Symbol("r")),
                ),
                ctx,
            ),
            "with",
            inline(raw(r"r = (q-1)/(q+1)")),
            ".",
            check(lnk.verdict, cfg),
        )
    )
    return out


def _per_edge(ctx: Context) -> list[Latex]:
    cfg = ctx.config
    th, beta = S.theta, S.beta
    r = sp.Symbol("r", positive=True)
    out = [
        section("The per-edge equations for every order", "sec:per-edge", level=1),
        paragraph(
            "For order",
            inline(raw("n")),
            "put",
            inline(raw(r"x = n\pi/2 + \theta")),
            "with",
            inline(raw(r"\theta = \omega_{av}\Delta T/2")),
            "(the paper's unknown in eqs. 15, 26, 39, 44). For every order the normal form becomes",
            inline(raw(r"N = \sin^2\theta - R(\theta)")),
            ":",
        ),
    ]
    n = S.n
    for parity in Parity:
        N, R = order_form(n, parity)
        out.append(equation(sp.Eq(sp.Symbol("R"), R), config=cfg))
        out.append(
            note(
                f"{_WORD[parity].capitalize()} orders; unstable where",
                inline(raw(r"\sin^2\theta < R(\theta)")),
                ".",
            )
        )
    out.append(
        paragraph(
            "Without friction",
            inline(raw("N")),
            "is a difference of squares, one factor per edge (",
            inline(raw(r"\varepsilon = \pm 1")),
            "), and each edge of the",
            inline(raw("n")),
            "-th interval is the root in",
            inline(raw(r"-\pi/2 < \theta < \pi/2")),
            "of one of the following equations, derived for each order:",
        )
    )
    rows = []
    for order in range(1, 7):
        parity = Parity.of(order)
        x = order * sp.pi / 2 + th
        eqs = []
        for eps in (1, -1):
            factor = edge_factor(parity, eps, symbols=(x, beta * x, r))
            lhs = edge_factor(
                parity, 0, symbols=(x, beta * x, r)
            )  # f(x), evaluated at n pi/2 + theta
            eqs.append(_m(sp.Eq(lhs, sp.expand(lhs - factor)), ctx))
        rows.append([raw(f"${order}$"), eqs[0], eqs[1]])
    out.append(
        table(
            [raw("$n$"), raw(r"$\varepsilon = +1$"), raw(r"$\varepsilon = -1$")],
            rows,
            columns="rll",
            caption=raw(
                r"The per-edge equations in $\theta$ for $n = 1,\dots,6$, with $\beta = "
                r"(\omega_2-\omega_1)/(\omega_2+\omega_1)$ and $r = (q-1)/(q+1)$."
            ),
            label="tab:per-edge",
            size="small",
        )
    )
    out.append(
        paragraph(
            raw(r"\textbf{Window theorem.}"),
            "For",
            inline(raw(r"\theta\in(-\pi/2,\pi/2)")),
            "each per-edge equation has exactly one root, and it is simple: at",
            inline(raw(r"\theta=\pm\pi/2")),
            "the",
            inline(raw(r"\sin\theta")),
            "term dominates because",
            inline(raw("r<1")),
            ", and at any root its derivative exceeds that of the other term because",
            inline(raw(r"\beta<1")),
            "and",
            inline(raw(r"|\cos\theta|\ge\sqrt{1-r^2}")),
            ", so all roots cross with the same sign. Each interval is therefore bounded by one "
            "root of "
            "each equation; the lower edge is the smaller one, and where both vanish at once the",
            raw("interval closes (Section~\\ref{sec:closings})."),
        )
    )
    return out


def build(ctx: Context) -> Part:
    cfg = ctx.config
    from analytic.reductions import chains

    chains_by_key = {c.key: c for c in chains()}
    used: set = set()
    blocks: list[Latex] = [paragraph(CHECKS_STATED_ONCE)]
    blocks += _general(ctx)
    blocks += _normal_form(ctx)
    for kind in EdgeKind:
        blocks += _edge_kind(kind, ctx, chains_by_key, used)
    blocks.append(section("The paper's remaining reductions", "sec:chains", level=1))
    edge_keys = {f"edge-{k.value}" for k in EdgeKind}
    blocks.append(
        paragraph(
            "The single results, the stationary initial conditions on the edges, and the paper "
            "model with friction (the paper's appendix), each step derived from the previous "
            "one:"
        )
    )
    for key, ch in chains_by_key.items():
        if key not in edge_keys:
            blocks.append(chain(ch, cfg, level=2, used_tags=used))
    blocks += _per_edge(ctx)
    return Part(_join(blocks))
