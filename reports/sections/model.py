"""Section 1: the model and the conventions, printed from :mod:`analytic.model`."""

from __future__ import annotations

import sympy as sp

from analytic.model import (
    Damping,
    Regime,
    S,
    Segment,
    damped_frequency_relations,
    derived_quantities,
    inertia,
    jump_ratio,
    ode_residual,
    physical,
    segment,
)

from ..i18n import say
from ..latex import Latex, equation, inline, math, paragraph, prose, raw, section, table, text
from . import Context, Part

TITLE = "The model and conventions"
LABEL = "sec:model"


def _m(expr, ctx: Context) -> Latex:
    return inline(math(expr, ctx.config))


def _halves(ctx: Context) -> Latex:
    rows = []
    for half, (span, where) in enumerate(
        ((r"$0<t<T/2$", "bob down"), (r"$T/2<t<T$", "bob up")), start=1
    ):
        omega = S.omega1 if half == 1 else S.omega2
        length = sp.refine(sp.sqrt(inertia(half)), sp.Q.lt(S.m, 1))  # J ~ l^2
        freq = physical(omega)
        period = sp.simplify(2 * sp.pi / freq)
        rows.append(
            [
                raw(span),
                text(where),
                _m(sp.Symbol("l_0") * sp.factor(length), ctx),
                _m(inertia(half), ctx),
                _m(sp.Eq(omega, freq), ctx),
                _m(sp.Eq(sp.Symbol(f"T_{half}"), period), ctx),
            ]
        )
    return table(
        ["half", "", "length", raw(r"$J/J_0$"), raw(r"frequency ($T_0=1$)"), "natural period"],
        rows,
        columns="llcccc",
        caption=Latex(
            raw(
                r"The two halves of a modulation period (time in units of $T_0$, so "
                r"$\omega_0 = 2\pi$)."
            ).raw
            + say(
                r" $J$ is the moment of inertia of the pendulum, $J_0$ its value at the length "
                r"$l_0$.",
                r" $J$ --- момент инерции маятника, $J_0$ --- его значение при длине $l_0$.",
            )
        ),
        label="tab:halves",
    )


def _segments(ctx: Context) -> list[Latex]:
    phi = sp.Function("varphi")(S.t)
    out = []
    generic = ode_residual(Segment(phi, sp.diff(phi, S.t), S.omega1, Damping.EXACT))
    out.append(
        paragraph(
            "Between the jumps the linearised equation of motion of half",
            inline(raw("i")),
            "is (eqs. 2--3 with",
            inline(raw(r"\sin\varphi\to\varphi")),
            "), as the engine's residual operator states it:",
        )
    )
    plain = {
        sp.Derivative(phi, (S.t, 2)): sp.Symbol("varphiddot"),
        sp.Derivative(phi, S.t): sp.Symbol("varphidot"),
        phi: sp.Symbol("varphi"),
        S.omega1: sp.Symbol("omega_i"),
    }
    out.append(
        equation(math(sp.Eq(generic.subs(plain), 0), ctx.config, order="lex"), config=ctx.config)
    )
    damped = damped_frequency_relations()
    rows = []
    for damping, regime, note in (
        (Damping.NONE, Regime.UNDER, "no friction"),
        (Damping.PAPER, Regime.UNDER, "paper (eqs. 28--30)"),
        (Damping.EXACT, Regime.UNDER, r"exact, $\gamma<\omega_1$"),
        (Damping.EXACT, Regime.CRITICAL, r"exact, $\gamma=\omega_1$"),
        (Damping.EXACT, Regime.OVER, r"exact, $\gamma>\omega_1$"),
    ):
        seg = segment(S.omega1, S.A1, S.B1, damping, regime)
        res = ode_residual(seg)
        if res != 0:
            ratio = sp.factor(sp.simplify(res / seg.phi))
            res_tex = _m(ratio * sp.Symbol("varphi_1"), ctx)
        else:
            res_tex = raw("$0$")
        rows.append(
            [raw(note) if "$" in note or "--" in note else text(note), _m(seg.phi, ctx), res_tex]
        )
    out.append(
        table(
            [
                "model",
                raw(
                    say(
                        r"segment $\varphi_1(t)$ on the bob-down half",
                        r"отрезок $\varphi_1(t)$ на полупериоде с опущенным грузом",
                    )
                ),
                "residual in the equation",
            ],
            rows,
            columns="lll",
            caption=Latex(
                raw(
                    "Free-oscillation segments of each damping model, and what is left when the "
                    "segment "
                    "is put into the equation of motion (computed by the engine). The paper's "
                    "segment "
                    "misses the equation by $\\gamma^2\\varphi$: its frequency is the undamped one "
                    "and its "
                    "derivative is taken as if $e^{-\\gamma t}$ were constant. The critically "
                    "damped "
                    "segment solves the equation exactly at $\\gamma = \\omega_1$, where its "
                    "residual "
                    "vanishes."
                ).raw
                + say(" In the exact model ", " В точной модели ")
                + inline(math(sp.Eq(S.Omega1, damped[S.Omega1]), ctx.config, order="rev-lex")).raw
                + say(" (under-damped) and ", " (слабое затухание) и ")
                + inline(math(sp.Eq(S.Lambda1, damped[S.Lambda1]), ctx.config, order="lex")).raw
                + say(" (over-damped).", " (сильное затухание).")
            ),
            label="tab:segments",
            size="small",
        )
    )
    return out


def _jump(ctx: Context) -> Latex:
    d1, d2 = sp.symbols(r"\dot{\varphi}_1 \dot{\varphi}_2")
    return paragraph(
        "At each jump the angle is continuous and the angular momentum",
        inline(raw(r"J\dot\varphi")),
        "with",
        inline(raw(r"J\propto l^2")),
        "is conserved (eq. 4): the angular velocity is multiplied by",
        _m(sp.Eq(d2 / d1, jump_ratio(1, 2)), ctx),
        "when the bob moves up and by the inverse when it moves down.",
    )


def _abbreviations(ctx: Context) -> Latex:
    names = {
        S.q: "coupling of the jumps (eq. 14)",
        S.p: "decay per period",
        S.omega_av: "mean frequency",
        S.Domega: "frequency difference",
        S.T_av: "mean natural period (eq. 5)",
        S.C1: "eq. 33",
        S.C2: "",
        S.S1: "",
        S.S2: "",
    }
    dq = derived_quantities()
    rows = []
    for sym, note in names.items():
        rows.append(
            [_m(sym, ctx), _m(dq[sym], ctx), _m(sp.simplify(physical(dq[sym])), ctx), text(note)]
        )
    return table(
        ["symbol", "definition", raw(r"in units $T_0 = 1$, $\gamma = \pi/Q$"), ""],
        rows,
        columns="clll",
        caption=Latex(
            raw("The paper's abbreviations as the engine defines them.").raw
            + say(
                r" In the third column $\tau = T/T_0$ is the modulation period in units of $T_0$.",
                r" В третьем столбце $\tau = T/T_0$ --- период модуляции в единицах $T_0$.",
            )
        ),
        label="tab:abbreviations",
    )


def build(ctx: Context) -> Part:
    body = [
        raw(
            say(
                r"A rigid pendulum whose length jumps between $l_0(1+m)$ and $l_0(1-m)$ as a "
                r"square wave of period $T$~\cite{butikov2}. Everything below is derived by the "
                r"engine from this model: two free-oscillation segments per period, the jump rule, "
                r"and (anti)periodicity. A formula printed in the paper is only ever the thing "
                r"being checked.",
                r"Жёсткий маятник, длина которого скачком меняется между $l_0(1+m)$ и $l_0(1-m)$ "
                r"по прямоугольному закону с периодом $T$~\cite{butikov2}. Всё дальнейшее "
                r"программа выводит из этой модели: два отрезка свободных колебаний за период, "
                r"правило скачка и (анти)периодичность. Формула, напечатанная в статье, --- "
                r"всегда лишь предмет проверки.",
            )
        ),
        section("Units and conventions", "sec:conventions", level=1),
        paragraph(
            "Time is measured in units of the natural period",
            inline(raw(r"T_0 = 2\pi/\omega_0")),
            "(so",
            inline(raw(r"\omega_0 = 2\pi")),
            "), the modulation period as",
            inline(raw(r"T/T_0")),
            ", the depth as",
            inline(raw(r"0<m<1")),
            ", friction by the quality factor",
            inline(raw(r"Q = \omega_0/(2\gamma)")),
            "(so",
            inline(raw(r"\gamma T_0 = \pi/Q")),
            "; no friction is",
            inline(raw(r"Q=\infty")),
            "). The resonance of order",
            inline(raw("n")),
            "lies near",
            inline(raw(r"T = nT_{av}/2")),
            raw(
                say(
                    r"($T_{av}$ is the mean natural period of the two halves, "
                    r"Table~\ref{tab:abbreviations}); $\Delta T = T - nT_{av}/2$ is the detuning "
                    r"from it",
                    r"($T_{av}$ --- средний собственный период двух половин, "
                    r"таблица~\ref{tab:abbreviations}); $\Delta T = T - nT_{av}/2$ --- расстройка "
                    r"относительно него",
                )
            ),
            "; on the edges of its interval the motion is anti-periodic over",
            inline(raw("T")),
            "(Floquet multiplier",
            inline(raw(r"\sigma = -1")),
            ") for odd",
            inline(raw("n")),
            "and periodic (",
            inline(raw(r"\sigma = +1")),
            ") for even",
            inline(raw("n")),
            ". The monodromy matrix is taken from",
            inline(raw("t = 0+")),
            ", the start of the bob-down half, over one period.",
        ),
        paragraph(
            "Equation numbers without a section prefix, such as (13), are the paper's; numbers "
            "such "
            "as (2.3) are this report's.",
        ),
        _halves(ctx),
        section("Equations of motion and the jump", "sec:motion", level=1),
        *_segments(ctx),
        _jump(ctx),
        section("Abbreviations and parameters", "sec:abbrev", level=1),
        _abbreviations(ctx),
        paragraph(
            prose(
                "Two damping models are carried through everything: paper, the appendix's "
                "approximation (used by the paper's eqs. 32–45 and its Fig. 8), and exact, the "
                "true damped oscillator with frequency "
                "$\\Omega_i = \\sqrt{\\omega_i^2 - \\gamma^2}$ and its over- and critically "
                "damped forms. The gap between them is one of the results."
            )
        ),
    ]
    return Part(Latex("\n\n".join(b.raw for b in body)))
