"""Section 3: the catalogue -- every numbered result of the paper, printed against derived
(:func:`analytic.catalogue`), with the verdict and, where the paper is wrong, the correct form."""

from __future__ import annotations

import re

from ..i18n import say
from ..latex import (
    Config,
    Latex,
    break_source,
    fit,
    mixed,
    notation,
    paragraph,
    prose,
    raw,
    table,
    text,
)
from ..phrasebook import SAME_EQUATION
from . import Context, Part, shared

TITLE = "The paper's numbered results, printed against derived"
LABEL = "sec:catalogue"


def rows(ctx: Context) -> tuple:
    """The catalogue's rows, through the cache (the derivations behind them are the slow part)."""
    from analytic.catalogue import catalogue

    return shared(ctx, "catalogue-rows", lambda: tuple(catalogue()))


def anchor(label: str) -> str:
    """A LaTeX label for a catalogue entry: ``"§6-n3"`` -> ``"sec6-n3"``."""
    return re.sub(r"[^A-Za-z0-9-]", "", label.replace("§", "sec")) or "row"


def eq_text(label: str) -> Latex:
    """How an equation label is printed: ``(13)``, ``(2)--(3)``, ``\\S 6``, and for an entry that
    is about something next to an equation, what it is: ``(15, n = 3)`` (the same equation for
    another order), ``(15, i.c.)`` (the stationary initial condition stated after it),
    ``(39, reference)`` (a cross-reference in the text around it), ``(19, centre)``."""
    from ..i18n import say

    m = re.fullmatch(r"(§?)(\d+)(?:-(\d+))?(?:-(n\d+|ref|shift))?", label)
    ic = re.fullmatch(r"IC-(\d+)", label)
    if ic:
        return raw("(" + ic.group(1) + ", i.c.)")
    if not m:
        return raw("(" + text(label).raw + ")")
    sec, first, last, what = m.groups()
    extra = ""
    if what and what.startswith("n"):
        extra = f", $n = {what[1:]}$"
    elif what == "ref":
        extra = ", " + say("reference", "ссылка")
    elif what == "shift":
        extra = ", " + say("centre", "центр")
    if sec:
        return raw(r"\S" + first + extra)
    return raw("(" + first + extra + ")" + (f"--({last})" if last else ""))


def display(src: str, config: Config) -> Latex:
    """A LaTeX formula (string from the engine) as display math: a list ``a,\\quad b`` becomes one
    display per item; an item too wide for the line is broken before the ``+`` and ``-`` of its
    top-level sums (:func:`break_source`), and a line that still does not fit is scaled down to
    the line (:func:`fit`)."""
    items = [notation(x.strip()) for x in re.split(r",\\quad\s*", src) if x.strip()] or [""]
    out = []
    for item in items:
        lines = break_source(item, config.max_width)
        if len(lines) == 1:
            out.append(r"\[" + fit(lines[0], config).raw + r"\]")
        else:
            body = " \\\\\n".join(fit(x, config).raw for x in lines)
            out.append("\\begin{multline*}\n" + body + "\n\\end{multline*}")
    return Latex("\n".join(out))


def _entry(r, ctx: Context) -> Latex:
    status = (
        say("agrees", "совпадает")
        if r.status == "agrees"
        else r"\textbf{" + say("differs", "расходится") + "}"
    )
    head = raw(
        r"\paragraph{"
        + eq_text(r.equation).raw
        + " "
        + prose(r.title or "").raw
        + r" --- "
        + status
        + r".}\label{cat:"
        + anchor(r.equation)
        + "}"
    )
    cfg = ctx.config
    body = [head, raw(r"\emph{Printed:}"), display(r.printed, cfg)]
    if r.derived:
        body += [raw(r"\emph{Derived:}"), display(r.derived, cfg)]
    if r.how != SAME_EQUATION:  # the common verdict is stated once, in the introduction
        body.append(paragraph(raw(r"\emph{" + say("Verdict:", "Вывод:") + "}"), mixed(r.how, cfg)))
    return Latex("\n".join(b.raw for b in body))


def build(ctx: Context) -> Part:
    rs = rows(ctx)
    differs = [r for r in rs if r.status != "agrees"]
    summary = table(
        ["eq.", "result", "status"],
        [
            [
                raw(r"\hyperref[cat:" + anchor(r.equation) + "]{" + eq_text(r.equation).raw + "}"),
                prose(r.title or ""),
                raw("agrees") if r.status == "agrees" else raw(r"\textbf{differs}"),
            ]
            for r in rs
        ],
        columns="lp{0.62\\linewidth}l",
        caption=raw(
            f"The paper's numbered results: {len(rs)} checked, {len(rs) - len(differs)} agree "
            f"with the "
            f"derivation, {len(differs)} differ (misprints or wrong statements; the correct forms "
            f"are "
            r"given below). Click an equation number for the entry."
        ),
        label="tab:catalogue",
        long=True,
        size="small",
    )
    intro = paragraph(
        "For each numbered result the engine transcribes the printed formula (the thing being "
        "checked), derives the same result from the model, and decides whether the two agree: "
        "symbolically where sympy can (an exact identity of rational functions after the "
        "abbreviations are expanded), otherwise at random points with 40 digits. An entry whose "
        "printed and derived forms are simply the same equation, decided symbolically, says "
        "nothing more; every other entry says how it was decided. Where they differ, the entry "
        "shows the smallest sub-expressions in which they part and the correct form.",
        raw(
            say(
                r"In the entries on friction $m_{\min}$ is the threshold depth at a given quality "
                r"factor and $Q_{\min}$ the threshold quality factor at a given depth (below "
                r"either the interval does not exist).",
                r"В пунктах о трении $m_{\min}$ --- пороговая глубина модуляции при данной "
                r"добротности, а $Q_{\min}$ --- пороговая добротность при данной глубине (ниже "
                r"любого из них интервала нет).",
            )
        ),
    )
    entries = [_entry(r, ctx) for r in rs]
    blocks = [intro, summary, *entries]
    return Part(Latex("\n\n".join(b.raw for b in blocks)))
