"""Section 7: accuracy -- the series against certified edges (error against ``m``, log-log), a table
of certified edges to 35 digits, and the Floquet cross-check of every edge in it
(:func:`verify.boundary`, :func:`analytic.edge_series`, :func:`verify.monodromy_matrix`)."""

from __future__ import annotations

from fractions import Fraction

import mpmath
import numpy as np
import sympy as sp

from .. import figures
from ..i18n import say
from ..latex import Latex, figure, inline, mixed, paragraph, raw, ref, table, text
from . import Context, Part
from .closings import digit_groups

TITLE = "Accuracy: series, certified values and the Floquet cross-check"
LABEL = "sec:accuracy"

ERROR_ORDERS = (1, 2, 3)
SERIES_TERMS = (2, 4, 6)
ERROR_DEPTHS = tuple(Fraction(1, 2**k) for k in range(1, 16)) + tuple(
    Fraction(1, 10**k) for k in (4, 5)
)
REFERENCE_DIGITS = 40
TABLE_DIGITS = 35
#: (order, depth, Q, damping) of the certified table: small, middle and deep modulation, a closing
#: depth, and friction in both models
TABLE_CASES = (
    *((n, Fraction(1, 10**6), None, "exact") for n in (1, 2)),
    *((n, Fraction(1, 10), None, "exact") for n in (1, 2, 3, 4, 5, 6)),
    *((n, Fraction(1, 2), None, "exact") for n in (1, 2, 3, 4, 5, 6)),
    (3, Fraction(3, 5), None, "exact"),
    *((n, Fraction(9, 10), None, "exact") for n in (1, 2, 3)),
    (1, Fraction(1, 2), Fraction(5), "paper"),
    (1, Fraction(1, 2), Fraction(5), "exact"),
    (2, Fraction(1, 2), Fraction(5), "paper"),
    (2, Fraction(1, 2), Fraction(5), "exact"),
    (3, Fraction(9, 10), Fraction(7), "exact"),
)
FLOQUET_DIGITS = 60


def _errors():
    """Relative error of the series through ``m**k`` against the certified edge, per order."""
    from analytic.expansions import edge_series
    from analytic.model import S
    from verify.solve import boundary

    out = {}
    for n in ERROR_ORDERS:
        refs = [boundary(n, m, digits=REFERENCE_DIGITS) for m in ERROR_DEPTHS]
        curves = {}
        for k in SERIES_TERMS:
            es = edge_series(n, k)
            f = sp.lambdify(S.m, es.in_T0["lower"], modules="mpmath")
            with mpmath.workdps(REFERENCE_DIGITS + 10):
                err = [
                    abs(f(mpmath.mpf(m.numerator) / m.denominator) / b.lower - 1)
                    for m, b in zip(ERROR_DEPTHS, refs, strict=True)
                ]
            curves[k] = [float(e) for e in err]
        out[n] = curves
    return [float(m) for m in ERROR_DEPTHS], out


def _table():
    """The certified edges (proven digits as text) and the Floquet check at each."""
    from verify.floquet import monodromy_matrix
    from verify.solve import boundary

    rows = []
    for n, m, Q, damping in TABLE_CASES:
        b = boundary(n, m, Q=Q, damping=damping, digits=TABLE_DIGITS)
        js = b.as_json()
        checks = []
        for edge in (b.lower, b.upper):
            if edge is None:
                checks.append(None)
                continue
            sigma = -1 if n % 2 else 1
            with mpmath.workdps(FLOQUET_DIGITS):
                printed_edge = mpmath.mpf(js["lower" if edge is b.lower else "upper"])
                M = monodromy_matrix(m, printed_edge, Q=Q, damping=damping, dps=FLOQUET_DIGITS)
                det = (M[0, 0] - sigma) * (M[1, 1] - sigma) - M[0, 1] * M[1, 0]
                scale = 1 + abs(M[0, 0]) + abs(M[1, 1]) + abs(M[0, 1] * M[1, 0])
                checks.append(mpmath.nstr(abs(det) / scale, 2))
        rows.append(
            (n, m, Q, damping, js["lower"], js["upper"], b.exists, checks, b.method, b.regime)
        )
    return rows


def _fraction(x: Fraction) -> str:
    if x.denominator == 1:
        return f"{x.numerator}"
    if x.numerator == 1 and str(x.denominator).strip("0") == "1" and x.denominator >= 1000:
        return f"10^{{-{len(str(x.denominator)) - 1}}}"
    return f"{x.numerator}/{x.denominator}"


def _sci(s: str | None) -> Latex:
    if s is None:
        return raw("--")
    mant, _, exp = s.partition("e")
    return raw(f"${mant}\\cdot 10^{{{int(exp)}}}$" if exp else f"${mant}$")


def build(ctx: Context) -> Part:
    ms, errs = ctx.cache.get("accuracy-errors", _errors)
    rows = ctx.cache.get("accuracy-table", _table)
    panels = []
    for n in ERROR_ORDERS:
        curves = {
            say(f"through $m^{{{k}}}$", f"до $m^{{{k}}}$"): (np.array(ms), np.array(errs[n][k]))
            for k in SERIES_TERMS
        }
        panels.append((say(f"$n = {n}$, lower edge", f"$n = {n}$, нижняя граница"), curves))
    fig = figures.error_figure(
        panels,
        ylabel=say(r"relative error of $T_-/T_0$", r"относительная погрешность $T_-/T_0$"),
    )
    figs = [("accuracy-series.pdf", figures.pdf_bytes(fig))]
    slopes = {}
    for n in ERROR_ORDERS:
        for k in SERIES_TERMS:
            e = np.array(errs[n][k])
            ok = e > 0
            x, y = np.log(np.array(ms)[ok][-5:]), np.log(e[ok][-5:])
            slopes[(n, k)] = float(np.polyfit(x, y, 1)[0]) if len(x) >= 2 else float("nan")
    blocks = [
        paragraph(
            raw(r"Figure~\ref{fig:accuracy}"),
            "compares the series of",
            ref("Section", "sec:series-orders"),
            "truncated after the powers",
            raw(", ".join(f"$m^{k}$" for k in SERIES_TERMS)),
            f"with the certified lower edges ({REFERENCE_DIGITS} proven digits). The error falls "
            f"off "
            "as the first neglected power: the fitted slopes at the smallest depths are",
            mixed(
                "; ".join(
                    f"$n = {n}$: " + ", ".join(f"{slopes[(n, k)]:.2f}" for k in SERIES_TERMS)
                    for n in ERROR_ORDERS
                )
            ),
            ". The truncation through",
            inline(raw("m^2")),
            "is the form the paper prints for",
            inline(raw("n = 1, 2, 3")),
            "(eqs. 18, 27, 19; see the catalogue for where it agrees).",
        ),
        figure(
            "figures/accuracy-series.pdf",
            raw(
                r"Relative error of the series for the lower edge against the certified value, "
                r"on log--log axes; below $10^{-16}$ no double-precision computation could tell."
            ),
            label="fig:accuracy",
        ),
    ]
    trows = []
    for n, m, Q, damping, lo, hi, exists, _checks, _method, _regime in rows:
        fr = "--" if Q is None else f"${_fraction(Q)}$ ({damping})"
        trows.append(
            [
                raw(f"${n}$"),
                raw(f"${_fraction(m)}$"),
                raw(fr),
                raw(r"\texttt{" + digit_groups(lo) + "}") if exists else text("no interval"),
                raw(r"\texttt{" + digit_groups(hi) + "}") if exists else raw(""),
            ]
        )
    blocks.append(
        paragraph(
            raw(r"Table~\ref{tab:certified}"),
            f"gives certified edges to {TABLE_DIGITS} significant digits at chosen depths, with "
            f"and "
            "without friction. Every digit is proven: the number is the midpoint of a ball "
            "(interval) that contains the exact edge and is narrower than the last digit.",
        )
    )
    blocks.append(
        table(
            [
                raw("$n$"),
                raw("$m$"),
                raw("$Q$"),
                raw("lower edge $T_-/T_0$"),
                raw("upper edge $T_+/T_0$"),
            ],
            trows,
            columns="rllll",
            caption=raw(f"Certified edges, {TABLE_DIGITS} significant digits."),
            label="tab:certified",
            long=True,
            size="scriptsize",
            # two 40-character digit columns: with the default 6pt between columns the Russian
            # damping labels (``5 (модель статьи)``) push the table 24.5pt into the margin
            colsep="3pt",
        )
    )
    crow = []
    for n, m, Q, damping, _lo, _hi, exists, checks, _method, regime in rows:
        if not exists:
            continue
        fr = "--" if Q is None else f"${_fraction(Q)}$ ({damping})"
        crow.append(
            [
                raw(f"${n}$"),
                raw(f"${_fraction(m)}$"),
                raw(fr),
                _sci(checks[0]),
                _sci(checks[1]),
                text(regime),
            ]
        )
    blocks.append(
        paragraph(
            raw(r"\textbf{Floquet cross-check.}"),
            "The monodromy matrix",
            inline(raw("M")),
            "is built independently of the determinants, as the product of the half-period maps "
            "and the jumps, and evaluated at each certified edge with",
            text(str(FLOQUET_DIGITS)),
            "digits. On an edge",
            inline(raw(r"\sigma = (-1)^n")),
            "must be a multiplier, i.e.",
            inline(raw(r"\det(M - \sigma I) = 0")),
            raw(r"(Table~\ref{tab:floquet}):"),
            "the residuals are at the level of the",
            text(str(TABLE_DIGITS)),
            "digits the edges are given to.",
        )
    )
    blocks.append(
        table(
            [
                raw("$n$"),
                raw("$m$"),
                raw("$Q$"),
                raw(r"at $T_-$"),
                raw(r"at $T_+$"),
                "equations solved",
            ],
            crow,
            columns="rlllll",
            caption=raw(
                r"$|\det(M-\sigma I)|$, relative to the size of $M$, at the certified edges of "
                r"Table~\ref{tab:certified}."
            ),
            label="tab:floquet",
            long=True,
            size="footnotesize",
        )
    )
    return Part(Latex("\n\n".join(b.raw for b in blocks)), figures=tuple(figs))
