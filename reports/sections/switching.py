"""The jump against a finite switching time and a smooth modulation: the first three intervals'
edges against the ramp's duration ``S``, the sine modulation's edges beside them, and the
jump-validity table (:mod:`analytic.ramp`, :mod:`analytic.smooth`,
:func:`verify.ramp.ramp_boundary`, :func:`verify.ramp.jump_validity`,
:func:`verify.smooth.sine_boundary`).  Few points, and the section is cached like every other."""

from __future__ import annotations

from fractions import Fraction

import numpy as np
import sympy as sp

from .. import figures
from ..i18n import say
from ..latex import Latex, figure, inline, math, paragraph, raw, table
from . import Context, Part

TITLE = "When is the jump a good model?"
LABEL = "sec:switching"

#: the depth of the figure, the ramp durations (units T0), the orders
FIG_M = Fraction(3, 10)
FIG_S = tuple(Fraction(k, 200) for k in (0, 1, 2, 4, 6, 8, 10, 12, 14, 16, 18, 20))
ORDERS = (1, 2, 3)
#: the jump-validity table: depths and one relative tolerance
VALIDITY_M = ("0.1", "0.3", "0.6")
VALIDITY_TOL = "1e-3"
DIGITS = 15
#: the sine's edges: the narrowest width shown (order 5 at m = 3/10, 2.8e-7 at T = 2.46) keeps
#: its 6 printed digits when each edge is proven to 11 digits (balls of radius ~1e-15)
SINE_DIGITS = 11
#: the closings: the sine's orders and depths of the width table; the ramp closing searched
#: (order, S, a depth bracket around the jump model's closing at m = 3/5, the bracket wanted)
CLOSE_ORDERS = (1, 2, 3, 4, 5, 6)
CLOSE_M = (Fraction(3, 10), Fraction(4, 5))
RAMP_CLOSING = (3, Fraction(1, 100), "0.6", "0.62", "1e-10")
#: the names the sine's paragraphs print for the engine's symbols (:mod:`analytic.smooth`), so
#: that no symbol of the report has two meanings: the engine's ``q`` (Hill coefficient), ``theta``
#: (2 pi t/T), ``c`` ((T/T0)^2), ``d`` (c - k^2), ``k`` (Fourier index) and ``u_+``/``u_-``
#: (couplings) are elsewhere the paper's q, the angle theta = omega_av Delta T/2, the damping
#: coefficient c, the integers of the closings proof
SINE_NAMES = {
    "q": "V",
    "theta": r"\psi",
    "c": r"\eta",
    "d": r"\delta",
    "k": r"\nu",
    "u_+": r"\kappa_{+}",
    "u_-": r"\kappa_{-}",
}


def sine_names(expr) -> dict:
    """``symbol_names`` for sympy's ``latex``: :data:`SINE_NAMES` for the symbols of ``expr``."""
    return {
        x: SINE_NAMES[x.name] for x in sp.sympify(expr).atoms(sp.Symbol) if x.name in SINE_NAMES
    }


def _compute():
    from verify.ramp import jump_validity, ramp_chart
    from verify.smooth import sine_boundary

    edges = np.full((len(ORDERS), 2, len(FIG_S)), np.nan)
    for k, n in enumerate(ORDERS):
        for j, r in enumerate(ramp_chart(n, FIG_M, FIG_S, digits=DIGITS)):
            edges[k, 0, j], edges[k, 1, j] = float(r.lower.mid()), float(r.upper.mid())
    sine = [sine_boundary(n, FIG_M, digits=SINE_DIGITS) for n in ORDERS]
    validity = [[jump_validity(n, m, VALIDITY_TOL, fit=False) for m in VALIDITY_M] for n in ORDERS]
    return edges, sine, validity


def _closings(sine_at_fig_m):
    """The certified widths of the sine's intervals (text with proven digits only) and the
    ramp closing of :data:`RAMP_CLOSING`."""
    from verify.certify import ball
    from verify.ramp import _ball_text, ramp_closing
    from verify.smooth import sine_boundary

    known = {(b.order, FIG_M): b for b in sine_at_fig_m}
    widths = {}
    for n in CLOSE_ORDERS:
        for m in CLOSE_M:
            b = known.get((n, m)) or sine_boundary(n, m, digits=SINE_DIGITS)
            disjoint = b.lower_enclosure[1] < b.upper_enclosure[0]
            lo = ball(b.lower, b.radii[0])
            hi = ball(b.upper, b.radii[1])
            widths[n, m] = (disjoint, _ball_text(hi - lo, 6))
    n, S, a, c, tol = RAMP_CLOSING
    rc = ramp_closing(n, S, a, c, tol=tol)
    return widths, rc


def _figure(edges, sine):
    with figures.style():
        fig, ax = figures.new_figure(height=3.0)
        S = np.array([float(s) for s in FIG_S])
        for k, n in enumerate(ORDERS):
            col = figures.ORDER_COLOURS[k % len(figures.ORDER_COLOURS)]
            ax.fill_betweenx(S, edges[k, 0], edges[k, 1], color=col, alpha=0.3, lw=0)
            ax.plot(edges[k, 0], S, color=col, lw=1)
            ax.plot(edges[k, 1], S, color=col, lw=1)
            for T in (float(sine[k].lower), float(sine[k].upper)):
                ax.plot([T], [S[-1] * 1.04], marker="v", color=col, ms=4, clip_on=False)
            ax.annotate(
                f"$n={n}$",
                (float(np.mean(edges[k, :, -1])), S[-1] / 2),
                ha="center",
                va="center",
                fontsize=7,
            )
        ax.set_ylim(0, S[-1] * 1.08)
        ax.set_xlabel(r"$T/T_0$")
        ax.set_ylabel(say(r"switching time $S/T_0$", r"время переключения $S/T_0$"))
        fig.tight_layout(pad=0.4)
    return fig


def _validity_rows(validity) -> list:
    from verify.ramp import _ball_text, _decimal

    rows = []
    for n, row in zip(ORDERS, validity, strict=True):
        for m, v in zip(VALIDITY_M, row, strict=True):
            bad = "---" if v.S_bad is None else _decimal(v.S_bad)
            rows.append(
                [
                    raw(f"${n}$"),
                    raw(f"${m}$"),
                    raw(f"${_decimal(v.S_ok)}$"),
                    raw(f"${bad}$" if v.S_bad is not None else bad),
                    # only the digits the enclosures prove (0 where the ball holds 0)
                    raw(f"${_ball_text(v.slopes[0], 6)}$"),
                    raw(f"${_ball_text(v.slopes[1], 6)}$"),
                ]
            )
    return rows


def build(ctx: Context) -> Part:
    from ._switching_forms import load

    cfg = ctx.config
    ctx.log("switching: ramp edges, sine edges, jump validity")
    edges, sine, validity = _compute()
    widths, rc = _closings(sine)
    figs = [("switching-edges.pdf", figures.pdf_bytes(_figure(edges, sine)))]

    def m_(x):
        return inline(math(x, cfg, symbol_names=sine_names(x)))

    # the derived forms, stored by reports.sections._switching_forms (checked by its test)
    forms = load()
    E12, q = forms["E12"], forms["q"]
    c_lo, c_hi = forms["c_lo"], forms["c_hi"]
    m = sp.Symbol("m")
    out: list[Latex] = [
        paragraph(
            raw(
                say(
                    r"The paper lets the length jump. With a \emph{ramp} each switch is a linear "
                    r"change of the length lasting $S$ (units of $T_0$), centred on the nominal "
                    r"switch; with the \emph{sine} modulation $l = l_0(1 + m\sin(2\pi t/T))$. "
                    r"While the length varies the bob obeys "
                    r"$(l^2\varphi')' + 2\gamma l^2\varphi' + g l\varphi = 0$. On a ramp it is "
                    r"solved by Bessel functions of order one (derived by sympy), which gives the "
                    r"ramp's map in closed form; every other case (the sine, ramps with friction) "
                    r"goes through one validated Taylor integrator in ball arithmetic with a "
                    r"proven remainder. Time reversal maps the ramp up onto the ramp down, so "
                    r"each phase stays symmetric about its midpoint and each edge is still a zero "
                    r"of one entry of the half-period map $G$, from the midpoint of phase 1 to "
                    r"that of phase 2 (the other half is its time reverse: $M = P G^{-1} P G$ "
                    r"with $P = \operatorname{diag}(1, -1)$). The first Magnus term of a ramp "
                    r"differs from the jump's by $S\,E$, where $E$ is the $2\times 2$ matrix "
                    r"whose only non-zero entry is ",
                    r"В статье длина меняется скачком. При \emph{линейном переходе} каждое "
                    r"переключение --- линейное изменение длины за время $S$ (в единицах "
                    r"$T_0$) с центром в момент переключения; при \emph{синусоидальной} "
                    r"модуляции $l = l_0(1 + m\sin(2\pi t/T))$. Пока длина меняется, груз "
                    r"подчиняется уравнению "
                    r"$(l^2\varphi')' + 2\gamma l^2\varphi' + g l\varphi = 0$. На линейном "
                    r"участке оно решается функциями Бесселя первого порядка (вывод в sympy), "
                    r"что даёт отображение через участок в замкнутом виде; все остальные случаи "
                    r"(синус, переходы с трением) считаются одним интегратором Тейлора в "
                    r"шаровой арифметике с доказанной оценкой остатка. Обращение времени "
                    r"переводит подъём груза в спуск, поэтому каждая фаза остаётся симметричной "
                    r"относительно середины и каждая граница --- по-прежнему нуль одного "
                    r"элемента отображения за полпериода $G$ от середины фазы 1 до середины "
                    r"фазы 2 (вторая половина --- его обращение во времени: $M = P G^{-1} P G$, "
                    r"$P = \operatorname{diag}(1, -1)$). Первый член Магнуса для перехода "
                    r"отличается от скачка на $S\,E$, где $E$ --- матрица $2\times 2$ "
                    r"с единственным ненулевым элементом ",
                )
            ),
            m_(sp.Eq(sp.Symbol("E_{12}"), E12)),
            raw(
                say(
                    r" ($l_a$ and $l_b$ the lengths before and after the switch), so every edge "
                    r"moves linearly in $S$ (Fig.~\ref{fig:switching}).",
                    r" ($l_a$ и $l_b$ --- длины до и после переключения), поэтому каждая "
                    r"граница смещается линейно по $S$ "
                    r"(рис.~\ref{fig:switching}).",
                )
            ),
        ),
        figure(
            "figures/switching-edges.pdf",
            raw(
                say(
                    r"The first three intervals at $m = "
                    + str(FIG_M)
                    + r"$ against the ramp's duration $S$ (certified edges at "
                    + str(len(FIG_S))
                    + r" durations; $S = 0$ is the jump). The triangles mark the edges of the "
                    r"sine modulation at the same depth (its second interval has zero width).",
                    r"Первые три интервала при $m = "
                    + str(FIG_M)
                    + r"$ в зависимости от длительности перехода $S$ (гарантированные границы "
                    r"при " + str(len(FIG_S)) + r" значениях; $S = 0$ --- скачок). Треугольники "
                    r"--- границы при синусоидальной модуляции той же глубины (её второй "
                    r"интервал имеет нулевую ширину).",
                )
            ),
            label="fig:switching",
        ),
        paragraph(
            raw(
                say(
                    r"\textbf{The sine modulation.} With $u = l\varphi$ the equation becomes "
                    r"the Hill equation $u'' + 2\gamma u' + V(t)\,u = 0$, without friction ",
                    r"\textbf{Синусоидальная модуляция.} Подстановка $u = l\varphi$ даёт "
                    r"уравнение Хилла $u'' + 2\gamma u' + V(t)\,u = 0$, без трения ",
                )
            ),
            m_(sp.Eq(sp.Symbol("q"), q)),
            raw(
                say(
                    r". At $T = T_0$ ($g = (2\pi/T)^2$ in these units) $V$ is the constant $g$ "
                    r"for every depth: all solutions have the period $T_0$, and the second "
                    r"interval has \emph{zero width at every depth} (the certified edges enclose "
                    r"$T = T_0$). Harmonic balance on the first-order Hill equation gives the "
                    r"first interval ",
                    r". При $T = T_0$ ($g = (2\pi/T)^2$ в этих единицах) $V$ равно постоянной "
                    r"$g$ при любой глубине: все решения имеют период $T_0$, и второй интервал "
                    r"имеет \emph{нулевую ширину при любой глубине} (гарантированные границы "
                    r"содержат $T = T_0$). Гармонический баланс для уравнения Хилла первого "
                    r"порядка по $m$ даёт первый интервал ",
                )
            ),
            m_(sp.Eq(sp.Symbol("T_-"), sp.Rational(1, 2) + c_lo * m)),
            ",",
            m_(sp.Eq(sp.Symbol("T_+"), sp.Rational(1, 2) + c_hi * m)),
            raw(
                say(
                    r" $+\,O(m^2)$: $3m/4$ wide against $3m/\pi$ for the "
                    r"square wave, whose first harmonic is $4/\pi$ times larger; the certified "
                    r"edges at $m = 10^{-6}$ agree.",
                    r" $+\,O(m^2)$: ширина $3m/4$ против $3m/\pi$ "
                    r"для меандра, у которого первая гармоника в $4/\pi$ раз больше; "
                    r"гарантированные границы при $m = 10^{-6}$ согласуются.",
                )
            ),
        ),
        paragraph(
            raw(
                say(
                    r"\textbf{Up to which $S$ is the jump good?} Table~\ref{tab:jump-validity} "
                    r"gives, for a relative tolerance of $"
                    + VALIDITY_TOL.replace("e-", r"\cdot 10^{-")
                    + r"}$ on both edges, "
                    r"two switching times: at the first both ramp edges are proven within the "
                    r"tolerance of the jump model's, at the second one edge is proven beyond it; "
                    r"and the slopes $dT_\mp/dS$ at $S = 0$.",
                    r"\textbf{До какого $S$ скачок --- хорошая модель?} "
                    r"Таблица~\ref{tab:jump-validity} даёт для относительного допуска $"
                    + VALIDITY_TOL.replace("e-", r"\cdot 10^{-")
                    + r"}$ на обе границы два времени переключения: при первом обе границы с "
                    r"переходом доказанно в пределах допуска от границ скачка, при втором одна "
                    r"граница доказанно вне его; и наклоны $dT_\mp/dS$ при $S = 0$.",
                )
            )
        ),
        table(
            [
                raw("$n$"),
                raw("$m$"),
                say("within", "в допуске"),
                say("beyond", "вне допуска"),
                raw(r"$dT_-/dS$"),
                raw(r"$dT_+/dS$"),
            ],
            _validity_rows(validity),
            columns="rrrrrr",
            caption=raw(
                say(
                    r"Switching times $S/T_0$ up to which the jump model's edges hold to a "
                    r"relative $" + VALIDITY_TOL.replace("e-", r"\cdot 10^{-") + r"}$.",
                    r"Времена переключения $S/T_0$, до которых границы модели скачка верны с "
                    r"относительной точностью $"
                    + VALIDITY_TOL.replace("e-", r"\cdot 10^{-")
                    + r"}$.",
                )
            ),
            label="tab:jump-validity",
        ),
        *_closings_text(widths, rc, m_),
        paragraph(
            raw(
                say(
                    r"\textbf{What is proven.} Every edge printed or drawn is an enclosure of a "
                    r"zero of its edge equation (interval Newton for ramps, a proven sign change "
                    r"for the sine), and every ``within''/``beyond'' is a comparison of such "
                    r"enclosures. Not proven: that the zero enclosed is the one connected to the "
                    r"jump model's edge (ramps: continuation in $S$ with bounded steps; sine: the "
                    r"order identified by the Pr\"ufer angle in double precision), and that no "
                    r"$S$ below the ``within'' value leaves the tolerance (the shift is checked at "
                    r"three smaller $S$ and grows in every case seen).",
                    r"\textbf{Что доказано.} Каждая напечатанная или нарисованная граница --- "
                    r"оболочка нуля своего уравнения (интервальный метод Ньютона для переходов, "
                    r"доказанная смена знака для синуса), и каждое <<в допуске>>/<<вне допуска>> "
                    r"--- сравнение таких оболочек. Не доказано: что найден именно нуль, "
                    r"связанный с границей модели скачка (переходы: продолжение по $S$ "
                    r"ограниченными шагами; синус: порядок определяется углом Прюфера в "
                    r"двойной точности), и что ни одно $S$ меньше значения <<в допуске>> не "
                    r"выходит из допуска (сдвиг проверен при трёх меньших $S$ и растёт во всех "
                    r"просмотренных случаях).",
                )
            )
        ),
    ]
    return Part(Latex("\n\n".join(b.raw for b in out)), tuple(figs))


def _tex_number(text: str) -> str:
    """``2.75936e-7`` as ``2.75936 \\cdot 10^{-7}`` (the digits unchanged)."""
    if "e" not in text:
        return text
    mant, exp = text.split("e")
    return rf"{mant} \cdot 10^{{{int(exp)}}}"


def _closings_text(widths, rc, m_) -> list:
    """The closings question, answered from :func:`analytic.smooth.sine_closings` (the Fourier
    recurrence of the sine's Ince form) and the certified widths; the ramp's closing from
    :func:`verify.ramp.ramp_closing`."""
    from analytic.ramp import crossing_is_a_closing
    from analytic.smooth import symbols
    from verify.ramp import _decimal

    from ._switching_forms import load

    forms = load()  # analytic.smooth.sine_closings, fourier_recurrence, ince_form, stored
    if not (forms["even_closed"] and forms["odd_open"]):  # pragma: no cover - a proof
        raise AssertionError("the sine's closings are not as stated")
    if crossing_is_a_closing() != sp.zeros(2, 2):  # pragma: no cover - a proof
        raise AssertionError("G11 = G22 = 0 does not give M = -I")
    sym = symbols()
    d, up = forms["d"], forms["up"]
    u = sp.Function("u")
    zeros = list(forms["zeros"])
    a_, c_ = _decimal(rc.m_lo), _decimal(rc.m_hi)
    jump_closing = sp.Rational(3, 5)
    rows = []
    for n in CLOSE_ORDERS:
        cells = [raw(f"${n}$")]
        for m in CLOSE_M:
            disjoint, text = widths[n, m]
            if n % 2 == 0:
                cells.append(raw("$0$" if not disjoint else f"${_tex_number(text)}$"))
            else:
                cells.append(raw(f"${_tex_number(text)}$"))
        cells.append(
            raw(say("closed ($M = I$)", "закрыт ($M = I$)"))
            if n % 2 == 0
            else raw(say("open (proven)", "открыт (доказано)"))
        )
        rows.append(cells)
    return [
        paragraph(
            raw(
                say(
                    r"\textbf{Do the intervals still close?} For the sine modulation, "
                    r"multiplying the Hill equation by $l$ and writing $\psi = 2\pi t/T$, "
                    r"$\eta = (T/T_0)^2$ gives the Ince equation ",
                    r"\textbf{Закрываются ли интервалы?} Для синусоидальной модуляции "
                    r"умножение уравнения Хилла на $l$ и замена $\psi = 2\pi t/T$, "
                    r"$\eta = (T/T_0)^2$ дают уравнение Айнса ",
                )
            ),
            m_(sp.Eq(sp.Function("L")(u(sym["theta"])), forms["ince"])),
            raw(
                say(
                    r". On $e^{i\nu\psi}$ it gives $e^{i\nu\psi}$ times ",
                    r". На $e^{i\nu\psi}$ оно даёт $e^{i\nu\psi}$, умноженное на ",
                )
            ),
            m_(
                sp.Symbol("d")
                + sp.Symbol("u_+") * sp.Symbol("z")
                + sp.Symbol("u_-") / sp.Symbol("z")
            ),
            raw(say(r" ($z = e^{i\psi}$) with ", r" ($z = e^{i\psi}$), где ")),
            m_(sp.Eq(sp.Symbol("d"), d)),
            ",",
            m_(sp.Eq(sp.Symbol("u_+"), up)),
            raw(
                say(
                    r" $= -\kappa_-$: a Fourier mode is coupled to its neighbours by a factor ",
                    r" $= -\kappa_-$: гармоника связана с соседними множителем ",
                )
            ),
            m_(forms["coupling"]),
            raw(
                say(
                    r", which vanishes only at $\nu = "
                    + ", ".join(str(z) for z in zeros)
                    + r"$ (derived by sympy). \emph{Every interval of even order has zero width "
                    r"at every depth}: for solutions of period $T$ ($\nu$ integer) the recurrence "
                    r"splits at $\nu = \pm 1$ into the chain $\nu \ge 2$ and its mirror image "
                    r"$\nu \le -2$, which have the same eigenvalues $\eta$; so two independent "
                    r"periodic solutions coexist and $M = I$ (order 2: the modes $\nu = \pm 1$ "
                    r"alone, $\eta = 1$, $T = T_0$). \emph{No interval of odd order ever closes}: "
                    r"for half-integer $\nu$ no coupling vanishes; the coefficients of the "
                    r"solutions even and odd about $t = T/4$ obey the same recurrence for "
                    r"$\nu \ge 3/2$, whose decaying solutions form a line (Perron's theorem: the "
                    r"characteristic roots $(-1 \pm \sqrt{1 - m^2})/m$ have different moduli), "
                    r"while their rows $\nu = 1/2$ differ by $\tfrac{3m}{4}\,\hat u_{1/2} \ne 0$ "
                    r"($\hat u_\nu$ the coefficient of $e^{i\nu\psi}$); "
                    r"so both are never periodic at once and $M \ne -I$. "
                    r"Table~\ref{tab:sine-widths} shows the certified widths: the odd ones "
                    r"are proven positive, the even edges are enclosed together, as the theorem "
                    r"requires.",
                    r", который обращается в нуль только при $\nu = "
                    + ", ".join(str(z) for z in zeros)
                    + r"$ (вывод в sympy). \emph{Каждый интервал чётного порядка имеет "
                    r"нулевую ширину при любой глубине}: для решений периода $T$ ($\nu$ целое) "
                    r"рекуррентное соотношение распадается при $\nu = \pm 1$ на цепочку "
                    r"$\nu \ge 2$ и её зеркальное отражение $\nu \le -2$ с одинаковыми "
                    r"собственными значениями $\eta$; поэтому сосуществуют два независимых "
                    r"периодических решения и $M = I$ (порядок 2: гармоники $\nu = \pm 1$, "
                    r"$\eta = 1$, $T = T_0$). \emph{Ни один интервал нечётного порядка не "
                    r"закрывается}: при полуцелых $\nu$ связи не обращаются в нуль; коэффициенты "
                    r"чётного и нечётного относительно $t = T/4$ решений подчиняются одному "
                    r"соотношению при $\nu \ge 3/2$, убывающие решения которого образуют прямую "
                    r"(теорема Перрона: характеристические корни $(-1 \pm \sqrt{1 - m^2})/m$ "
                    r"различны по модулю), а их строки $\nu = 1/2$ отличаются на "
                    r"$\tfrac{3m}{4}\,\hat u_{1/2} \ne 0$ "
                    r"($\hat u_\nu$ --- коэффициент при $e^{i\nu\psi}$); поэтому оба решения "
                    r"никогда не периодичны одновременно и $M \ne -I$. "
                    r"Таблица~\ref{tab:sine-widths} даёт гарантированные ширины: нечётные "
                    r"доказанно положительны, границы чётных заключены в одну оболочку.",
                )
            ),
        ),
        table(
            [raw("$n$")] + [raw(f"$m = {m}$") for m in CLOSE_M] + [say("interval", "интервал")],
            rows,
            columns="rrrl",
            caption=raw(
                say(
                    r"Widths $(T_+ - T_-)/T_0$ of the sine modulation's intervals (certified "
                    r"digits only).",
                    r"Ширины $(T_+ - T_-)/T_0$ интервалов при синусоидальной модуляции "
                    r"(только гарантированные цифры).",
                )
            ),
            label="tab:sine-widths",
        ),
        paragraph(
            raw(
                say(
                    r"\textbf{With ramps the closings survive and move.} The per-edge "
                    r"factorisation holds for ramps (above), and where the zeros of $G_{11}$ "
                    r"and $G_{22}$ meet, $M = -I$ exactly (sympy: $P G^{-1} P G + I = 0$ when "
                    r"$G_{11} = G_{22} = 0$, $\det G = 1$). The third interval, closed at "
                    + f"$m = {jump_closing}$"
                    + r" for the jump, has with ramps of $S = "
                    + str(rc.S)
                    + r"\,T_0$ certified edges, proven disjoint, in opposite orders at $m = "
                    + a_
                    + r"$ and at $m = "
                    + c_
                    + r"$: it closes at a depth between them (near $T = "
                    + f"{rc.T_approx:.6f}"
                    + r"\,T_0$). Not proven: that the zeros compared lie on the same two "
                    r"continuous branches (each is followed from the jump by continuation).",
                    r"\textbf{С линейными переходами закрытия сохраняются и смещаются.} "
                    r"Разложение на уравнения отдельных границ сохраняется (см. выше), и там, "
                    r"где встречаются нули $G_{11}$ и $G_{22}$, точно $M = -I$ (sympy: "
                    r"$P G^{-1} P G + I = 0$ при $G_{11} = G_{22} = 0$, $\det G = 1$). Третий "
                    r"интервал, закрытый при "
                    + f"$m = {jump_closing}$"
                    + r" для скачка, при переходах длительности $S = "
                    + str(rc.S)
                    + r"\,T_0$ имеет гарантированные, доказанно непересекающиеся границы в "
                    r"противоположном порядке при $m = "
                    + a_
                    + r"$ и при $m = "
                    + c_
                    + r"$: он закрывается на глубине между ними (около $T = "
                    + f"{rc.T_approx:.6f}"
                    + r"\,T_0$). Не доказано: что сравниваемые нули лежат на одних и тех же "
                    r"непрерывных ветвях (каждая прослежена от скачка продолжением по $S$).",
                )
            )
        ),
    ]
