"""The model family: the paper's pendulum as one two-level oscillator among many -- the chart at
duty ``D = 1/3``, the pendulum, the torsion pendulum and the Meissner equation side by side, the
closing theorem for any duty with its table, and the widths at small depth
(:mod:`analytic.system`, :mod:`analytic.family`, :func:`analytic.closings.closings`,
:func:`verify.boundary`, :func:`verify.floquet.monodromy_matrix`)."""

from __future__ import annotations

from fractions import Fraction

import mpmath
import numpy as np
import sympy as sp

from .. import figures
from ..latex import Latex, figure, inline, math, paragraph, prose, raw, ref, table
from . import Context, Part
from .closings import _sci, digit_groups

TITLE = "The family of two-level oscillators"
LABEL = "sec:family"

CHART_DUTY = Fraction(1, 3)
CHART_ORDERS = (1, 2, 3, 4, 5, 6)
SIDE_ORDERS = (1, 2, 3, 4)
SIDE_SYSTEMS = ("pendulum", "torsion", "meissner")
#: depths of the charts: exact rationals (certified edges at each)
CHART_M = tuple(Fraction(i, 100) for i in range(1, 99))
SIDE_M = tuple(Fraction(i, 50) for i in range(1, 50))
CHART_DIGITS = 8
CLOSING_ORDER = 8
FLOQUET_DIGITS = 40
WIDTH_DUTIES = (Fraction(1, 2), Fraction(1, 3))
WIDTH_ORDERS = (1, 2, 3, 4, 5, 6)


def _edges(sysv, orders, depths) -> np.ndarray:
    from verify.solve import boundary

    out = np.full((len(orders), 2, len(depths)), np.nan)
    for k, n in enumerate(orders):
        for j, m in enumerate(depths):
            b = boundary(n, m, system=sysv, digits=CHART_DIGITS)
            out[k, 0, j], out[k, 1, j] = float(b.lower), float(b.upper)
    return out


def _floquet_check(c, sysv) -> str:
    from verify.floquet import monodromy_matrix

    with mpmath.workdps(FLOQUET_DIGITS + 10):
        M = monodromy_matrix(c.m, mpmath.mpf(c.T), system=sysv, dps=FLOQUET_DIGITS)
        dev = max(
            abs(M[i, j] - (c.multiplier if i == j else 0)) for i in range(2) for j in range(2)
        )
    return mpmath.nstr(dev, 2) if dev else "0"


def _widths():
    """Leading term of the width ``T_+ - T_-`` (units ``T0``) for each duty and order."""
    from analytic.family_series import family_edge_series
    from analytic.system import system

    out = {}
    for D in WIDTH_DUTIES:
        for n in WIDTH_ORDERS:
            es = family_edge_series(n, 2, "T0", system("pendulum", duty=D))
            w = sp.expand(es.in_T0["upper"] - es.in_T0["lower"])
            out[(D, n)] = w
    return out


def _compute():
    from analytic.closings import closings
    from analytic.system import system

    chart_sys = system("pendulum", duty=CHART_DUTY)
    chart = _edges(chart_sys, CHART_ORDERS, CHART_M)
    side = {name: _edges(system(name), SIDE_ORDERS, SIDE_M) for name in SIDE_SYSTEMS}
    cl = closings(CLOSING_ORDER, chart_sys)
    checks = {(c.order, c.a): _floquet_check(c, chart_sys) for c in cl}
    return chart, side, cl, checks, _widths()


def _system_rows(cfg) -> list:
    from analytic.model import S
    from analytic.system import LAWS, system

    rows = []
    for name in LAWS:
        w1, w2, k = (sp.sympify(v) for v in system(name).values(S.m))
        rows.append(
            [
                raw(r"\texttt{" + name + "}"),
                prose(LAWS[name].picture.split(";")[0].split("(")[0].strip()),
                inline(math(w1, cfg)),
                inline(math(w2, cfg)),
                inline(math(sp.factor(k), cfg)),
            ]
        )
    return rows


def build(ctx: Context) -> Part:
    cfg = ctx.config
    chart, side, cl, checks, widths = _compute()
    m_chart = np.array([float(m) for m in CHART_M])
    m_side = np.array([float(m) for m in SIDE_M])
    figs = []
    closing_marks = [(c.order, float(c.m), float(c.T), f"{c.ratio}") for c in cl if c.order <= 6]
    fig = figures.intervals_figure(m_chart, chart, CHART_ORDERS, closings=closing_marks)
    figs.append(("family-duty.pdf", figures.pdf_bytes(fig)))
    fig = figures.family_figure(m_side, [(name, side[name]) for name in SIDE_SYSTEMS], SIDE_ORDERS)
    figs.append(("family-systems.pdf", figures.pdf_bytes(fig)))

    out: list[Latex] = [
        paragraph(
            prose(
                "The paper's pendulum is one member of a family: two-level square-wave parametric "
                "oscillators. Phase 1 (the low-frequency phase) lasts D T and phase 2 lasts "
                "(1 - D) T; in each phase the linearised motion is a free damped oscillation "
                "with the same damping, and at the switch 1 -> 2 the angular velocity is "
                "multiplied by k (by 1/k at 2 -> 1). The built-in members are listed in"
            ),
            ref("Table", "tab:family"),
            prose("; a custom member is given by its two squared frequencies and k."),
        ),
        table(
            [
                "system",
                "picture",
                raw(r"$\omega_1^2/\omega_0^2$"),
                raw(r"$\omega_2^2/\omega_0^2$"),
                raw(r"$k$"),
            ],
            _system_rows(cfg),
            columns="llccc",
            caption="The built-in members of the family.",
            label="tab:family",
        ),
        paragraph(
            prose(
                "For every member and every duty the engine derives, with D and k kept as "
                "symbols, that det M = exp(-2 gamma T) and that the trace of the monodromy has the "
                "paper's form with the phases a_1 = W_1 D T and a_2 = W_2 (1 - D) T and one "
                "coupling constant K. The normal form of the paper therefore holds for the whole "
                "family; only r, beta and the mean frequency w = D W_1 + (1 - D) W_2 change, with "
                "|r| < 1 and |beta| < 1 always. Without friction it factors into one equation per "
                "edge, each with one simple root per order, for every duty."
            )
        ),
        figure(
            "figures/family-duty.pdf",
            raw(
                r"Intervals of instability of the pendulum with unequal phases, $D = 1/3$ "
                r"(certified edges at "
                + str(len(CHART_M))
                + r" depths; the marks are the closings of Table~\ref{tab:family-closings})."
            ),
            label="fig:family-duty",
        ),
        paragraph(
            prose(
                "Unequal phases change the picture qualitatively. At small depth every interval "
                "is O(m) wide unless n D is an integer, where the n-th harmonic of the square wave "
                "vanishes and the width is O(m^2): the even orders of equal halves are the case "
                "D = 1/2. The leading widths, from the series of the edges:"
            )
        ),
        table(
            [raw("$n$")] + [raw(f"$D = {D.numerator}/{D.denominator}$") for D in WIDTH_DUTIES],
            [
                [raw(f"${n}$")] + [inline(math(widths[(D, n)], cfg)) for D in WIDTH_DUTIES]
                for n in WIDTH_ORDERS
            ],
            columns="rcc",
            caption=raw(
                r"Width $T_+ - T_-$ of the $n$-th interval of the pendulum through $m^2$ "
                r"(units of $T_0$)."
            ),
            label="tab:family-widths",
        ),
        figure(
            "figures/family-systems.pdf",
            raw(
                r"The first four intervals of the three built-in systems with equal phases. The "
                r"jump sets the strength of the excitation: $q = k\,\omega_1/\omega_2$ is "
                r"$((1+m)/(1-m))^{3/2}$ for the pendulum, $((1+m)/(1-m))^{1/2}$ for the torsion "
                r"pendulum and $((1-m)/(1+m))^{1/2}$ for the Meissner equation."
            ),
            label="fig:family-systems",
        ),
        paragraph(
            raw(r"\textbf{Theorem (closings, any member and duty).}"),
            prose(cl.statement),
            prose(
                f"Its derivation has {len(cl.steps)} steps, each checked "
                f"({sum(s.verdict.holds for s in cl.steps)} hold)."
            ),
        ),
    ]
    rows = []
    for c in cl:
        rows.append(
            [
                raw(f"${c.order}$"),
                raw(f"${c.a}, {c.b}$"),
                raw(f"${c.ratio}$"),
                raw(f"${c.m.numerator}/{c.m.denominator}$"),
                raw(f"${sp.latex(c.T_exact)}$"),
                raw(r"\texttt{" + digit_groups(c.T) + "}"),
                _sci(checks[(c.order, c.a)]),
            ]
        )
    out.append(
        table(
            [
                raw("$n$"),
                raw("$a,b$"),
                raw("$T_1:T_2$"),
                raw("$m$"),
                raw("$T/T_0$ exact"),
                raw("$T/T_0$ (certified digits)"),
                raw(r"$|M-(-1)^nI|_{\max}$"),
            ],
            rows,
            columns="rcccclr",
            caption=raw(
                r"Every closing of the pendulum with $D = 1/3$ up to order "
                + str(CLOSING_ORDER)
                + r": $\omega_1 D T = a\pi$, $\omega_2 (1-D) T = b\pi$; the last column is the "
                r"independent Floquet check at the printed period."
            ),
            label="tab:family-closings",
            size="footnotesize",
            colsep="2.5pt",
        )
    )
    return Part(Latex("\n\n".join(b.raw for b in out)), tuple(figs))
