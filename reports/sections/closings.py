"""Section 5: where intervals close -- the theorem, its derivation, every closing up to order 12
(:func:`analytic.closings`), and the monodromy there from the independent Floquet route."""

from __future__ import annotations

from fractions import Fraction

import mpmath
import sympy as sp

from ..i18n import say
from ..latex import Latex, inline, math, paragraph, prose, raw, table
from . import Context, Part
from ._render import check, note
from .summary import theorem

TITLE = "Closings of the intervals"
LABEL = "sec:closings"

MAX_ORDER = 12
#: digits of the independent Floquet check at each closing
FLOQUET_DIGITS = 50


def digit_groups(s: str, group: int = 5) -> str:
    """``"1.2649110640673"`` -> ``"1.26491\\,10640\\,673"``: decimals in groups for reading."""
    head, _, tail = s.partition(".")
    if not tail:
        return head
    parts = [tail[i : i + group] for i in range(0, len(tail), group)]
    return head + "." + r"\,".join(parts)


def _fraction(x: Fraction) -> Latex:
    return raw(f"${x.numerator}/{x.denominator}$")


def _floquet_check(c) -> str:
    """``max |M - sigma I|`` at the closing, from :func:`verify.monodromy_matrix` (mpmath, exact
    depth, the period to ``FLOQUET_DIGITS`` digits)."""
    from verify.floquet import monodromy_matrix

    with mpmath.workdps(FLOQUET_DIGITS + 10):
        tau = mpmath.mpf(c.a * c.b) * mpmath.sqrt(mpmath.mpf(2) / (c.a**2 + c.b**2))
        M = monodromy_matrix(c.m, tau, dps=FLOQUET_DIGITS)
        dev = max(
            abs(M[i, j] - (c.multiplier if i == j else 0)) for i in range(2) for j in range(2)
        )
        return mpmath.nstr(dev, 2) if dev else "0"


def _compute():
    from analytic.closings import closings

    cl = closings(MAX_ORDER)
    checks = {(c.order, c.a): _floquet_check(c) for c in cl}
    return cl, checks


def build(ctx: Context) -> Part:
    cfg = ctx.config
    cl, checks = _compute()
    out: list[Latex] = [
        theorem(cl, ctx),
        paragraph(
            "The paper shows closings of the third, fourth and fifth intervals in its Fig. 2 and "
            "links "
            "them to",
            inline(raw(r"T_1:T_2 = 2:1,\ 3:1,\ 3:2")),
            "(its Section 5); the theorem says these are instances of one rule and that there are "
            "no others.",
            raw(
                say(
                    r"Below $x$, $y$, $r$ are those of the normal form "
                    r"(Section~\ref{sec:normal-form}), $F_\pm$ its two edge factors, and $f$ is "
                    r"$\cos$ for odd orders and $\sin$ for even ones. The derivation, each step "
                    r"checked by the engine:",
                    r"Ниже $x$, $y$, $r$ --- величины из нормальной формы "
                    r"(раздел~\ref{sec:normal-form}), $F_\pm$ --- два её множителя для границ, "
                    r"а $f$ --- это $\cos$ для нечётных порядков и $\sin$ для чётных. Вывод, "
                    r"каждый шаг которого проверен программой:",
                )
            ),
        ),
    ]
    items = []
    for k, step in enumerate(cl.steps, start=1):
        expr = step.expr
        shown = None
        if not isinstance(expr, (bool, sp.logic.boolalg.BooleanAtom)) and expr not in (
            sp.true,
            sp.false,
        ):
            shown = inline(math(expr, cfg))
        if shown is not None and {"j", "k"} <= {str(x) for x in expr.free_symbols}:
            # the triple (a, b, n) at the zeros of f numbered by the integers j and k
            zeros = (
                r"x = \pi/2 + j\pi$, $y = \pi/2 + k\pi"
                if step.claim.startswith("odd")
                else r"x = j\pi$, $y = k\pi"
            )
            shown = Latex(
                say(r"$(a, b, n) = {}$ at ", r"$(a, b, n) = {}$ при ").format(shown.raw.strip("$"))
                + "$"
                + zeros
                + say(r"$, $j$ and $k$ integers", r"$, $j$ и $k$ целые")
            )
        items.append(
            paragraph(
                raw(f"\\item[{k}.]"),
                prose(step.claim[0].upper() + step.claim[1:] + "."),
                *((raw(r"\\"), shown) if shown is not None and len(shown.raw) < 260 else ()),
                *(
                    (raw(r"\\"), note(check(step.verdict, cfg)))
                    if not check(step.verdict, cfg).empty
                    else ()
                ),
            )
        )
    out.append(
        Latex("\\begin{description}\n" + "\n".join(i.raw for i in items) + "\n\\end{description}")
    )
    out.append(
        paragraph(
            raw(
                r"Table~\ref{tab:closings} lists every closing of the orders $1,\dots,"
                + str(MAX_ORDER)
                + r"$. The period is printed with "
                + str(len(cl.items[0].T.replace(".", "")) if cl.items else 0)
                + r" correctly rounded significant digits from an interval enclosure; the last "
                r"column is the independent check: the monodromy matrix built from the free "
                r"oscillations and the jumps (\texttt{verify.floquet}, "
                + str(FLOQUET_DIGITS)
                + r" digits) at that depth and period, against $(-1)^n I$."
            )
        )
    )
    out.append(
        closings_table(
            cl,
            checks,
            raw(
                r"Every closing of the intervals of order $n\le "
                + str(MAX_ORDER)
                + r"$: $\omega_1T/2 = a\pi$, $\omega_2T/2 = b\pi$, $m = (b^2-a^2)/(b^2+a^2)$, "
                r"$T = ab\sqrt{2/(a^2+b^2)}\,T_0$."
            ),
            "tab:closings",
            long=True,
        )
    )
    paper_ratios = [(2, 1), (3, 1), (3, 2)]
    found = []
    for b, a in paper_ratios:
        hits = [c for c in cl.at_ratio(b, a) if c.order <= 6]
        found.append(
            f"{b}:{a} closes order{'s' if len(hits) > 1 else ''} "
            f"{', '.join(str(c.order) for c in hits)} at $m = "
            f"{hits[0].m.numerator}/{hits[0].m.denominator}$"
            if hits
            else f"{b}:{a} not found"
        )
    extra = sorted(
        {c.reduced_ratio for c in cl if c.order <= 6} - {f"{b}:{a}" for b, a in paper_ratios}
    )
    out.append(
        paragraph(
            prose(
                "Against the paper: "
                + "; ".join(found)
                + ". Among the first six intervals (those of its Fig. 2) the theorem also gives "
                + (", ".join(extra) if extra else "no other ratio")
                + ", which lie at depths above those the paper discusses."
            )
        )
    )
    return Part(Latex("\n\n".join(b.raw for b in out)))


def closings_table(cl, checks, caption, label: str, *, long: bool = False) -> Latex:
    """The table of closings: order, phase counts, ``T1:T2``, exact depth, exact and certified
    period, and the independent Floquet check ``checks[(order, a)]`` (this section and the
    family chapter)."""
    rows = []
    for c in cl:
        reduced = c.system.is_paper and not c.lowest_terms
        rows.append(
            [
                raw(f"${c.order}$"),
                raw(f"${c.a}, {c.b}$"),
                raw(f"${c.ratio} = {c.reduced_ratio}$") if reduced else raw(f"${c.ratio}$"),
                _fraction(c.m),
                raw(f"${sp.latex(c.T_exact)}$"),
                raw(r"\texttt{" + digit_groups(c.T) + "}"),
                _sci(checks[(c.order, c.a)]),
            ]
        )
    return table(
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
        caption=caption,
        label=label,
        long=long,
        size="footnotesize",
        colsep="2.5pt",
    )


def _sci(s: str) -> Latex:
    """``"1.7e-51"`` -> ``$1.7\\cdot 10^{-51}$``."""
    mant, _, exp = s.partition("e")
    return raw(f"${mant}\\cdot 10^{{{int(exp)}}}$" if exp else f"${mant}$")
