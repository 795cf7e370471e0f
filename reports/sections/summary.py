"""Section 2: the findings up front -- the paper's errata with the corrected formulas, the closing
theorem, the thresholds with friction and the third-order island at ``Q = 7``, every formula and
number taken from the engine's objects (:func:`analytic.catalogue.catalogue`,
:func:`analytic.closings.closings`, :func:`analytic.thresholds.threshold_series`,
:func:`verify.existence.existence` through the diagrams' data)."""

from __future__ import annotations

import re

import sympy as sp

from analytic.model import S

from ..i18n import say
from ..latex import (
    Latex,
    break_source,
    inline,
    math,
    notation,
    paragraph,
    prose,
    raw,
    slashed,
    table,
)
from . import Context, Part, shared
from .catalogue import anchor, eq_text
from .catalogue import rows as catalogue_rows

TITLE = "Summary of results"
LABEL = "sec:summary"

#: orders whose closings are listed in the summary (the paper's Fig. 2 shows orders 1 to 6)
LISTED_ORDERS = 6
#: the width (in characters, see :func:`reports.latex.visible_width`) of a formula line in the
#: errata table before it is broken: the widest line the formula column holds at the table's type
CELL_WIDTH = 50
#: the most lines one formula may take in the errata table (a longer one, a series, is left to the
#: full entry)
CELL_LINES = 1
#: closings are counted up to this order (as in the closings section)
MAX_ORDER = 12


def _closings():
    from analytic.closings import closings

    return closings(MAX_ORDER)


def _thresholds():
    from analytic.thresholds import threshold_series

    out = {}
    for order in ("odd", "even", 1, 2, 3):
        t = threshold_series(order, terms=1, damping="paper")
        out[order] = (t.m_min_leading, t.Q_min)
    return out


def prepare(ctx: Context) -> None:
    """Compute the results :func:`findings` shares with the catalogue, the closings and the
    expansions (the closings and the threshold series), in the process that built those
    sections, where they are cheap (:func:`reports.report.assemble` with ``jobs=2``)."""
    shared(ctx, "closings-theorem", _closings)
    shared(ctx, "threshold-leading", _thresholds)


def findings(ctx: Context) -> dict:
    """What the summary and the abstract state, computed once per build."""
    from .diagrams import ISLAND_ORDER, ISLAND_Q, PAPER_ISLAND_CLAIM, _compute

    rows = catalogue_rows(ctx)
    cl = shared(ctx, "closings-theorem", _closings)
    th = shared(ctx, "threshold-leading", _thresholds)
    island = shared(ctx, "diagram-data", _compute)["ex"]
    return {
        "rows": rows,
        "differs": [r for r in rows if r.status != "agrees"],
        "closings": cl,
        "thresholds": th,
        "island": island,
        "island_order": ISLAND_ORDER,
        "island_Q": ISLAND_Q,
        "island_claim": PAPER_ISLAND_CLAIM,
    }


def _items(src: str) -> list[str]:
    return [notation(x.strip()) for x in re.split(r",\\quad\s*", src) if x.strip()]


def _lines(src: str) -> list[str]:
    """The formulas of one side of an erratum, one per line (a long one broken before ``+`` and
    ``=``); a formula that would take more than :data:`CELL_LINES` lines is left to the full
    entry (``\\dots``)."""
    items = _items(src)
    shown = [len(break_source(x, CELL_WIDTH)) <= CELL_LINES for x in items]
    # a definition (``s = ...``) of a symbol that only the elided formulas use is left to the
    # full entry with them
    for k, x in enumerate(items):
        if shown[k] and (mt := _DEFINITION.match(x)):
            used = re.compile(rf"(?<![\\a-zA-Z]){re.escape(mt.group(1))}(?![a-zA-Z_])")
            users = [j for j in range(len(items)) if j != k and used.search(items[j])]
            shown[k] = not users or any(shown[j] for j in users)
    lines: list[str] = []
    for x, keep in zip(items, shown, strict=True):
        if not keep:
            if not lines or lines[-1] != r"\dots":
                lines.append(r"\dots")
            continue
        lines.extend(r"\fitcell{" + line.raw + "}" for line in break_source(x, CELL_WIDTH))
    return lines


#: a formula that defines a one-letter symbol: ``s = \sqrt{...}``
_DEFINITION = re.compile(r"([a-zA-Z]) = ")


def _forms(printed: str, derived: str | None) -> Latex:
    """The printed and the derived forms of one erratum, one above the other, each labelled, so
    that every formula has the width of the whole column (side by side they would have to be
    set in small type)."""
    blocks = [(say("printed", "в статье"), _lines(printed))]
    if derived:
        blocks.append((say("derived", "выведено"), _lines(derived)))
    rows = []
    for label, lines in blocks:
        for k, line in enumerate(lines):
            rows.append((r"\emph{" + label + "}" if k == 0 else "") + " & " + line)
            rows.append(r" \\[3pt] " if k < len(lines) - 1 else r" \\[6pt] ")
    return raw(
        rf"\begin{{tabular}}[t]{{@{{}}p{{{FORM_LABEL}\linewidth}}@{{}}"
        rf"p{{{1 - FORM_LABEL:.2f}\linewidth}}@{{}}}}" + "".join(rows) + r"\end{tabular}"
    )


#: the share of the forms column taken by the labels ``printed`` and ``derived``
FORM_LABEL = 0.17


def errata_table(f: dict) -> Latex:
    rows = []
    for r in f["differs"]:
        rows.append(
            [
                raw(r"\hyperref[cat:" + anchor(r.equation) + "]{" + eq_text(r.equation).raw + "}"),
                prose(r.title or ""),
                _forms(r.printed, r.derived),
            ]
        )
    return table(
        [
            say("eq.", "ур."),
            say("result", "результат"),
            say("printed and derived (correct) forms", "в статье и выведено (верно)"),
        ],
        rows,
        columns=r"@{}>{\raggedright}p{0.08\linewidth}>{\raggedright}p{0.17\linewidth}"
        r"p{\dimexpr0.75\linewidth-4\tabcolsep\relax}@{}",
        caption=raw(
            say(
                "Errata: the paper's results whose printed form differs from the derivation, "
                "with the derived (correct) form. Each equation number links to its entry in "
                "Section~",
                "Опечатки: результаты статьи, напечатанная форма которых расходится с выводом, "
                "и выведенная (верная) форма. Номер уравнения --- ссылка на подробный разбор "
                "в разделе~",
            )
            + r"\ref{sec:catalogue}."
        ),
        label="tab:errata",
        long=True,
        size="small",
    )


def notation_paragraph() -> Latex:
    """The symbols of the table and the findings below it, said before they are used (Section 3
    gives their definitions as the engine states them)."""
    return t(
        r"The symbols are the paper's (Section~\ref{sec:model} defines them as the engine does): "
        r"$\omega_1$, $\omega_2$ and $T_1$, $T_2$ are the natural frequencies and periods of the "
        r"two halves of a period (bob down, length $l_0(1+m)$; bob up, $l_0(1-m)$), $T_0$ that of "
        r"the unmodulated pendulum; $\omega_{av} = (\omega_1 + \omega_2)/2$, "
        r"$\Delta\omega = \omega_2 - \omega_1$, $T_{av} = 2\pi/\omega_{av}$, and "
        r"$\Delta T = T - nT_{av}/2$ is the detuning from the resonance of order $n$; "
        r"$q = \omega_1(1+m)^2/(\omega_2(1-m)^2)$ is the coupling of the jumps, "
        r"$p = e^{-\gamma T}$ the decay per period ($\gamma = \omega_0/(2Q)$), "
        r"$C_i = \cos(\omega_i T/2)$ and $S_i = \sin(\omega_i T/2)$; $A$, $B$, $A_1$, $A_2$ "
        r"are amplitudes of the free oscillation in the halves; $N$ is the normal form of the "
        r"Floquet condition (the rest state is unstable where $N < 0$, "
        r"Section~\ref{sec:normal-form}) and $\theta = \omega_{av}\Delta T/2$; "
        r"$m_{\min}$ is the threshold depth with friction, $M$ the monodromy matrix over one "
        r"period and $I$ the identity matrix.",
        r"Обозначения --- те же, что в статье (раздел~\ref{sec:model} определяет их так же, как "
        r"программа): $\omega_1$, $\omega_2$ и $T_1$, $T_2$ --- собственные частоты и периоды "
        r"двух половин периода (груз опущен, длина $l_0(1+m)$; груз поднят, $l_0(1-m)$), "
        r"$T_0$ --- период маятника без модуляции; "
        r"$\omega_{av} = (\omega_1 + \omega_2)/2$, $\Delta\omega = \omega_2 - \omega_1$, "
        r"$T_{av} = 2\pi/\omega_{av}$, а $\Delta T = T - nT_{av}/2$ --- расстройка относительно "
        r"резонанса порядка $n$; $q = \omega_1(1+m)^2/(\omega_2(1-m)^2)$ --- связь при скачках, "
        r"$p = e^{-\gamma T}$ --- затухание за период ($\gamma = \omega_0/(2Q)$), "
        r"$C_i = \cos(\omega_i T/2)$ и $S_i = \sin(\omega_i T/2)$; $A$, $B$, $A_1$, $A_2$ --- "
        r"амплитуды свободных колебаний на половинах периода; $N$ --- нормальная форма условия "
        r"Флоке (положение покоя неустойчиво там, где $N < 0$, раздел~\ref{sec:normal-form}), "
        r"$\theta = \omega_{av}\Delta T/2$; $m_{\min}$ --- пороговая глубина модуляции при "
        r"трении, $M$ --- матрица монодромии за период, $I$ --- единичная матрица.",
    )


def t(en: str, ru: str) -> Latex:
    """Prose with LaTeX in it, in the report's language."""
    return raw(say(en, ru))


def _step(cl, prefix: str):
    for s in cl.steps:
        if s.claim.startswith(prefix):
            return s.expr
    raise LookupError(prefix)


def closing_depth(cl) -> sp.Equality:
    """The depth of a closing, ``m = (b^2 - a^2)/(b^2 + a^2)``, as the theorem's step derives it."""
    return [
        e for e in _step(cl, "omega2/omega1").args if isinstance(e, sp.Equality) and e.lhs == S.m
    ][0]


def theorem(cl, ctx: Context) -> Latex:
    cfg = ctx.config
    a, b, n = sp.symbols("a b n", integer=True, positive=True)
    m_eq = closing_depth(cl)
    T_eq = _step(cl, "T = a T1")
    M_shown = sp.Eq(sp.Symbol("M"), (-1) ** n * sp.Symbol("I"), evaluate=False)
    c1 = sp.Eq(S.omega1 * S.T / 2, a * sp.pi)
    c2 = sp.Eq(S.omega2 * S.T / 2, b * sp.pi)
    ratio = sp.Eq(sp.Symbol("T_1") / sp.Symbol("T_2"), b / a)

    def m(x):
        return inline(math(x, cfg))

    m_eq = Latex(sp.latex(m_eq.lhs) + " = " + math(m_eq.rhs, cfg, order="rev-lex").raw)
    return paragraph(
        raw(r"\textbf{" + say("Theorem (closings).", "Теорема (о смыканиях).") + "}"),
        t(
            "Without friction the edges of the $n$-th interval of instability meet (the interval "
            "closes) exactly where",
            "Без трения границы $n$-го интервала неустойчивости смыкаются (интервал "
            "стягивается в точку) в точности там, где",
        ),
        m(c1),
        t("and", "и"),
        m(c2),
        t("with integers", "при целых"),
        inline(raw(r"1 \le a < b")),
        ",",
        inline(raw("a + b = n")),
        ";",
        t("there", "при этом"),
        raw(
            r"\["
            + math(m_eq, cfg).raw
            + r",\qquad "
            + math(ratio, cfg).raw
            + r",\qquad "
            + math(T_eq, cfg).raw
            + r"\,T_0,\qquad "
            + math(M_shown, cfg).raw
            + r"\]"
        ),
        t(
            "with $M$ the monodromy matrix over one period. There are no other closings.",
            "где $M$ --- матрица монодромии за период. Других смыканий нет.",
        ),
    )


def build(ctx: Context) -> Part:
    f = findings(ctx)
    cfg = ctx.config
    rows, differs, cl = f["rows"], f["differs"], f["closings"]
    out: list[Latex] = []
    out.append(
        paragraph(
            t(
                f"The engine checks {len(rows)} numbered results of the paper. "
                f"{len(rows) - len(differs)} agree with the derivation; {len(differs)} do not "
                "(Table~",
                f"Программа проверяет {len(rows)} пронумерованных результатов статьи: "
                f"{len(rows) - len(differs)} совпадают с выводом, {len(differs)} --- нет "
                "(таблица~",
            ),
            raw(r"\ref{tab:errata}):"),
            t(
                "misprinted formulas, a lost factor, wrong cross-references, and threshold "
                "conditions read at exact tuning where the threshold is a tangency.",
                "опечатки в формулах, потерянный множитель, неверные ссылки и условия порога, "
                "записанные при точной настройке, тогда как порог --- это касание.",
            ),
        )
    )
    out.append(notation_paragraph())
    out.append(errata_table(f))
    out.append(theorem(cl, ctx))
    pairs = {}
    for c in cl:
        if c.order <= LISTED_ORDERS:
            pairs.setdefault((c.reduced_ratio, c.m), []).append(c.order)
    listed = []
    for (ratio, mval), orders in sorted(pairs.items(), key=lambda kv: kv[0][1]):
        listed.append(
            inline(raw(ratio.replace(":", "\\!:\\!")))
            + " ("
            + inline(raw(f"m = {mval.numerator}/{mval.denominator}"))
            + ", "
            + (t("order", "порядок") if len(orders) == 1 else t("orders", "порядки"))
            + " "
            + inline(raw(", ".join(str(o) for o in orders)))
            + ")"
        )
    out.append(
        paragraph(
            t(
                f"Up to order {MAX_ORDER} there are {len(cl)} closings (Section~",
                f"До порядка {MAX_ORDER} имеется {len(cl)} смыканий (раздел~",
            ),
            raw(r"\ref{sec:closings});"),
            t(
                f"within the first {LISTED_ORDERS} intervals, those of the paper's Fig.~2, they "
                "are at",
                f"в первых {LISTED_ORDERS} интервалах, показанных на рис.~2 статьи, это",
            ),
            raw("; ".join(x.raw for x in listed) + "."),
            t(
                "The paper names the first three ratios and explains $2:1$.",
                "Статья называет первые три отношения и объясняет $2:1$.",
            ),
        )
    )
    th = f["thresholds"]
    mmin = sp.Symbol(r"m_{\min}")
    odd, even = th["odd"][0], th["even"][0]
    out.append(
        paragraph(
            t(
                "With friction (quality factor $Q$) an interval exists only above a threshold "
                "depth; to leading order in $1/Q$, in both damping models,",
                "С трением (добротность $Q$) интервал существует лишь при глубине модуляции выше "
                "пороговой; в главном порядке по $1/Q$, в обеих моделях трения,",
            ),
            raw(
                r"\["
                + math(sp.Eq(mmin, odd), cfg).raw
                + r"\quad\text{"
                + say("(odd } n\\text{)", "(нечётные } n\\text{)")
                + r"},\qquad "
                + math(sp.Eq(mmin, even), cfg).raw
                + r"\quad\text{"
                + say("(even } n\\text{)", "(чётные } n\\text{)")
                + r"}.\]"
            ),
            t(
                "For $n = 1, 2, 3$ these are the paper's",
                "При $n = 1, 2, 3$ это пороги статьи",
            ),
            inline(slashed(sp.Eq(mmin, th[1][0]), cfg)),
            ",",
            inline(slashed(sp.Eq(mmin, th[2][0]), cfg)),
            t("and", "и"),
            inline(slashed(sp.Eq(mmin, th[3][0]), cfg)),
            t(
                "(eqs. 38, 43 and Section 6); for every other order they are new (Section~",
                "(ур. 38, 43 и разд. 6); для остальных порядков они новые (раздел~",
            ),
            raw(r"\ref{sec:expansions})."),
        )
    )
    ex = f["island"]
    lo, hi = (round(100 * x) for x in f["island_claim"])

    def rng(model):
        ranges = ex[model][1]
        if len(ranges) < 2:
            return raw(say("no gap", "разрыва нет"))
        return inline(raw(f"{ranges[0][1]} < m < {ranges[1][0]}"))

    out.append(
        paragraph(
            t(
                f"At $Q = {f['island_Q']}$ the interval of order {f['island_order']} vanishes for",
                f"При $Q = {f['island_Q']}$ интервал порядка {f['island_order']} исчезает при",
            ),
            rng("paper"),
            t("in the paper's model and for", "в модели статьи и при"),
            rng("exact"),
            raw(
                say(
                    r"in the exact one (ends proven in interval arithmetic); the paper reads "
                    rf"``about {lo}\,\%'' and ``about {hi}\,\%'' off its Fig.~8 (Section~",
                    r"в точной модели (концы доказаны интервальной арифметикой); статья "
                    rf"оценивает по рис.~8: <<около {lo}\,\%>> и <<около {hi}\,\%>> (раздел~",
                )
            ),
            raw(r"\ref{sec:diagrams})."),
        )
    )
    return Part(Latex("\n\n".join(b.raw for b in out)))
