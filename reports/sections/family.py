"""The model family: the paper's pendulum as one two-level oscillator among many -- the chart at
duty ``D = 1/3``, the pendulum, the torsion pendulum and the Meissner equation side by side, the
closing theorem for any duty with its table, and the widths at small depth
(:mod:`analytic.system`, :mod:`analytic.family`, :func:`analytic.closings.closings`,
:func:`verify.boundary`, :func:`verify.floquet.monodromy_matrix`)."""

from __future__ import annotations

import re
from fractions import Fraction

import mpmath
import numpy as np
import sympy as sp

from .. import figures
from ..i18n import say, tr
from ..latex import Latex, figure, inline, math, paragraph, raw, table
from . import Context, Part
from .closings import closings_table

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
                raw(re.split(r"[,(;:]", LAWS[name].picture)[0].strip()),
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
    fig = figures.family_figure(
        m_side, [(tr(name), side[name]) for name in SIDE_SYSTEMS], SIDE_ORDERS
    )
    figs.append(("family-systems.pdf", figures.pdf_bytes(fig)))

    from analytic.family import D as Dsym
    from analytic.family import coupling, phases
    from analytic.model import Damping, S

    def m_(x):
        return inline(math(x, cfg))

    a1, a2 = phases(Damping.NONE)
    a1x, a2x = phases(Damping.EXACT)
    out: list[Latex] = [
        paragraph(
            raw(
                say(
                    r"The paper's pendulum is one member of a family: two-level square-wave "
                    r"parametric oscillators. Phase~1 (the low-frequency phase) lasts $D\,T$ and "
                    r"phase~2 lasts $(1-D)\,T$; in each phase the linearised motion is a free "
                    r"oscillation with the same damping $\gamma$, and at the switch $1\to2$ the "
                    r"angular velocity is multiplied by $k$ (by $1/k$ at $2\to1$). The built-in "
                    r"members are listed in Table~\ref{tab:family}; a custom member is given by "
                    r"its two squared frequencies and $k$.",
                    r"Маятник статьи "
                    r"--- один из членов семейства: двухуровневые осцилляторы с параметрами, "
                    r"переключаемыми по закону меандра. Фаза~1 (с меньшей частотой) длится "
                    r"$D\,T$, фаза~2 --- $(1-D)\,T$; в каждой фазе линеаризованное движение "
                    r"--- свободные колебания с одним и тем же затуханием $\gamma$, а при "
                    r"переключении $1\to2$ угловая скорость умножается на $k$ (на $1/k$ при "
                    r"$2\to1$). Встроенные члены семейства перечислены в "
                    r"таблице~\ref{tab:family}; произвольный задаётся квадратами двух частот и "
                    r"множителем $k$.",
                )
            )
        ),
        table(
            [
                say("system", "система"),
                say("picture", "физическая картина"),
                raw(r"$\omega_1^2/\omega_0^2$"),
                raw(r"$\omega_2^2/\omega_0^2$"),
                raw(r"$k$"),
            ],
            _system_rows(cfg),
            columns="llccc",
            caption=say("The built-in members of the family.", "Встроенные члены семейства."),
            label="tab:family",
        ),
        paragraph(
            raw(
                say(
                    r"For every member and every duty the engine derives, with $D$ and $k$ kept "
                    r"as symbols, that $\det M = e^{-2\gamma T}$ and that the trace of the "
                    r"monodromy has the paper's form with the phases ",
                    r"Для любого члена семейства и любой скважности программа выводит, "
                    r"сохраняя $D$ и $k$ символами, что $\det M = e^{-2\gamma T}$ и что след "
                    r"матрицы монодромии имеет вид, как в статье, с фазами ",
                )
            ),
            m_(sp.Eq(sp.Symbol("a_1"), a1)),
            ",",
            m_(sp.Eq(sp.Symbol("a_2"), a2)),
            raw(say(r" and one coupling constant ", r" и одной постоянной связи ")),
            m_(sp.Eq(sp.Symbol("K"), coupling(Damping.NONE))),
            raw(
                say(
                    r" (with friction in the exact model the damped frequencies replace "
                    r"$\omega_i$ and ",
                    r" (с трением в точной модели вместо $\omega_i$ стоят затухающие частоты "
                    r"и ",
                )
            ),
            m_(sp.Eq(sp.Symbol("K"), coupling(Damping.EXACT))),
            raw(
                say(
                    r"). The normal form of the paper therefore holds for the whole family; only "
                    r"$r$, $\beta$ and the mean frequency $w = (D W_1 + (1-D) W_2)/\omega_0$ (in "
                    r"units of $\omega_0$) change, where "
                    r"$W_i$ is $\omega_i$ (with friction in the exact model $\Omega_i$), with "
                    r"$|r| < 1$ and $|\beta| < 1$ always. Without friction it factors into one "
                    r"equation per edge, each with one simple root per order, for every duty.",
                    r"). Поэтому нормальная форма статьи верна для всего семейства; меняются "
                    r"лишь $r$, $\beta$ и средняя частота $w = (D W_1 + (1-D) W_2)/\omega_0$ "
                    r"(в единицах $\omega_0$), где $W_i$ --- "
                    r"это $\omega_i$ (с трением в точной модели $\Omega_i$), причём всегда "
                    r"$|r| < 1$ и $|\beta| < 1$. Без трения она распадается на уравнения для "
                    r"каждой границы, у каждого по одному простому корню для каждого порядка, "
                    r"при любой скважности.",
                )
            ),
        ),
        figure(
            "figures/family-duty.pdf",
            raw(
                say(
                    r"Intervals of instability of the pendulum with unequal phases, $D = 1/3$ "
                    r"(certified edges at " + str(len(CHART_M)) + r" depths; the marks are the "
                    r"closings of Table~\ref{tab:family-closings}).",
                    r"Интервалы неустойчивости маятника с неравными фазами, $D = 1/3$ "
                    r"(гарантированные границы в " + str(len(CHART_M)) + r" точках по глубине; "
                    r"точки --- смыкания из таблицы~\ref{tab:family-closings}).",
                )
            ),
            label="fig:family-duty",
        ),
        paragraph(
            raw(
                say(
                    r"Unequal phases change the picture qualitatively. At small depth every "
                    r"interval is $O(m)$ wide unless $nD$ is an integer, where the $n$-th "
                    r"harmonic of the square wave vanishes and the width is $O(m^2)$: the even "
                    r"orders of equal halves are the case $D = 1/2$. The leading widths, from the "
                    r"series of the edges, are in Table~\ref{tab:family-widths}.",
                    r"Неравные фазы качественно меняют картину. При малой глубине ширина каждого "
                    r"интервала порядка $O(m)$, если только $nD$ не целое: тогда $n$-я гармоника "
                    r"меандра обращается в нуль и ширина порядка $O(m^2)$; чётные порядки при "
                    r"равных половинах --- это случай $D = 1/2$. Главные члены ширины из рядов "
                    r"для границ --- в таблице~\ref{tab:family-widths}.",
                )
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
                say(
                    r"Width $T_+ - T_-$ of the $n$-th interval of the pendulum through $m^2$ "
                    r"(units of $T_0$).",
                    r"Ширина $T_+ - T_-$ $n$-го интервала маятника до $m^2$ (в единицах $T_0$).",
                )
            ),
            label="tab:family-widths",
        ),
        figure(
            "figures/family-systems.pdf",
            raw(
                say(
                    r"The first four intervals of the three built-in systems with equal phases. "
                    r"The jump sets the strength of the excitation: $q = k\,\omega_1/\omega_2$ "
                    r"is $((1+m)/(1-m))^{3/2}$ for the pendulum, $((1+m)/(1-m))^{1/2}$ for the "
                    r"torsion pendulum and $((1-m)/(1+m))^{1/2}$ for the Meissner equation.",
                    r"Первые четыре интервала трёх встроенных систем при равных фазах. Скачок "
                    r"задаёт силу возбуждения: $q = k\,\omega_1/\omega_2$ равно "
                    r"$((1+m)/(1-m))^{3/2}$ для маятника, $((1+m)/(1-m))^{1/2}$ для крутильного "
                    r"маятника и $((1-m)/(1+m))^{1/2}$ для уравнения Мейсснера.",
                )
            ),
            label="fig:family-systems",
        ),
        paragraph(
            raw(
                r"\textbf{"
                + say(
                    "Theorem (closings, any member and duty).",
                    "Теорема (о смыканиях, любой член семейства и скважность).",
                )
                + "} "
                + say(
                    r"Without friction the $n$-th interval has zero width exactly where both "
                    r"phases turn through whole multiples of $\pi$: ",
                    r"Без трения $n$-й интервал имеет нулевую ширину в точности там, где обе "
                    r"фазы проходят целое число полупериодов $\pi$: ",
                )
            ),
            m_(sp.Eq(a1, sp.Symbol("a") * sp.pi)),
            ",",
            m_(sp.Eq(a2, sp.Symbol("b") * sp.pi)),
            raw(
                say(
                    r" with integers $a, b \ge 1$, $a + b = n$; there the monodromy is "
                    r"$M = (-1)^n I$, and there are no other closings ($r \ne 0$). For the "
                    r"built-in members this fixes ",
                    r" при целых $a, b \ge 1$, $a + b = n$; там матрица монодромии "
                    r"$M = (-1)^n I$, и других смыканий нет ($r \ne 0$). Для встроенных систем "
                    r"отсюда ",
                )
            ),
            m_(
                sp.Eq(
                    S.omega2**2 / S.omega1**2,
                    (sp.Symbol("b") * Dsym / (sp.Symbol("a") * (1 - Dsym))) ** 2,
                )
            ),
            raw(
                say(
                    r". Its derivation has "
                    + str(len(cl.steps))
                    + r" steps, each checked by the engine ("
                    + str(sum(s_.verdict.holds for s_ in cl.steps))
                    + r" hold).",
                    r". Вывод состоит из "
                    + str(len(cl.steps))
                    + r" шагов, каждый проверен программой (выполнены "
                    + str(sum(s_.verdict.holds for s_ in cl.steps))
                    + r").",
                )
            ),
        ),
    ]
    out.append(
        closings_table(
            cl,
            checks,
            raw(
                say(
                    r"Every closing of the pendulum with $D = 1/3$ up to order "
                    + str(CLOSING_ORDER)
                    + r": $\omega_1 D T = a\pi$, $\omega_2 (1-D) T = b\pi$; the last column is "
                    r"the independent Floquet check at the printed period.",
                    r"Все смыкания маятника с $D = 1/3$ до порядка "
                    + str(CLOSING_ORDER)
                    + r": $\omega_1 D T = a\pi$, $\omega_2 (1-D) T = b\pi$; последний столбец "
                    r"--- независимая проверка по Флоке при напечатанном периоде.",
                )
            ),
            "tab:family-closings",
        )
    )
    return Part(Latex("\n\n".join(b.raw for b in out)), tuple(figs))
