"""Rendering the engine's proof objects: verdicts, proven links and chains of reductions."""

from __future__ import annotations

import re

import sympy as sp

from ..latex import (
    Config,
    Latex,
    equation,
    equation_lines,
    fit,
    inline,
    math,
    math_lines,
    paragraph,
    prose,
    raw,
    section,
    slashed,
    text,
    visible_width,
)

__all__ = ["verdict", "check", "link", "chain", "tag_of", "note", "CHECKS_STATED_ONCE"]

#: said once at the head of a section of derivations, instead of after every step
CHECKS_STATED_ONCE = (
    "Every step below is checked by the engine. Unless its note says otherwise, the check is "
    "symbolic: the difference of the two sides reduces to zero exactly (after the trigonometric "
    "functions are written as exponentials, an identity of rational functions). Where sympy "
    "cannot reduce it, the note says so and gives the numeric check used instead: random points "
    "at 40 digits and the largest relative residual."
)


#: a factor wider than this (characters, see :func:`reports.latex.visible_width`) is displayed
INLINE_FACTOR_WIDTH = 24


def verdict(v, config: Config) -> Latex:
    """How an identity was decided, for a reader: symbolic, up to which factor, or numeric."""
    if not v.holds:
        return paragraph(raw(r"\textbf{does not hold}:"), prose(v.describe()))
    if v.route == "symbolic":
        factor = getattr(v, "factor", None)
        if factor is not None and factor != 1:
            shown = slashed(factor, config)
            if visible_width(shown) > INLINE_FACTOR_WIDTH:  # too long for the line: displayed
                shown = Latex(r"\[" + fit(math(factor, config), config).raw + r"\]")
            else:
                shown = inline(shown)
            return paragraph(
                "holds up to the non-vanishing factor",
                shown,
                "(proved symbolically)",
            )
        return Latex("")
    return paragraph(
        f"numeric, at {v.points} random points with {v.dps} digits, largest relative "
        f"residual {v.worst:.1e} (sympy did not reduce it to zero)"
    )


def check(v, config: Config) -> Latex:
    """``Check: ...`` for a step whose check is not the plain symbolic one (stated once, see
    :data:`CHECKS_STATED_ONCE`); nothing for the plain one."""
    said = verdict(v, config)
    if said.empty:
        return Latex("")
    return paragraph(raw(r"\emph{Check:}"), said, ".")


def note(*parts) -> Latex:
    """A small-print remark under a displayed formula."""
    return Latex(r"{\small " + paragraph(*parts).raw + r"\par}")


def tag_of(label: str) -> str | None:
    """The equation tag for a step labelled with the paper's number: ``"13"`` -> ``13``,
    ``"15-upper"`` -> ``15\\textsuperscript{+}``... ``""`` -> ``None`` (numbered by the report)."""
    if not label:
        return None
    m = re.fullmatch(r"(\d+)-upper", label)
    if m:
        return m.group(1) + "'"
    m = re.fullmatch(r"IC-(\d+)", label)
    if m:  # the stationary initial condition the paper states after its equation
        return m.group(1) + r"\text{, i.c.}"
    return sp.latex(sp.Symbol(label)) if re.fullmatch(r"\d+", label) else label.replace("_", r"\_")


def link(
    lnk, config: Config, *, lhs=None, rhs=None, tag: str | None = None, title: str | None = None
) -> Latex:
    """A proven step ``lhs = rhs`` with its reason and verdict; ``lhs``/``rhs`` replace the sides
    that were actually compared for display, e.g. the symbol ``tr M`` for the expanded trace, or
    the symbol ``K`` for the coupling constant written out."""
    left = lnk.lhs if lhs is None else lhs
    right = lnk.rhs if rhs is None else rhs
    eq = sp.Eq(left, right, evaluate=False)
    return Latex(
        equation(eq, tag=tag, config=config).raw
        + "\n"
        + note(
            raw(r"\emph{" + text(title or lnk.name).raw + ".}"),
            prose(lnk.why + "."),
            check(lnk.verdict, config),
        ).raw
    )


def _group(steps):
    """Consecutive steps with the same non-empty label form one display."""
    groups: list[list] = []
    for s in steps:
        if groups and s.label and groups[-1][0].label == s.label:
            groups[-1].append(s)
        else:
            groups.append([s])
    return groups


def chain(
    ch, config: Config, level: int = 1, used_tags: set | None = None, heading: bool = True
) -> Latex:
    """A chain of reductions: its title as a heading, then each step's equation (tagged with the
    paper's number when it has one), why it follows from the previous step and how that was
    checked.  ``used_tags`` collects tags across chains: a paper number printed a second time is
    marked with a prime in the same way the paper's upper edges are."""
    used_tags = set() if used_tags is None else used_tags
    out = [section(ch.title, None, level=level)] if heading else []
    for grp in _group(ch.steps):
        tag = tag_of(grp[0].label)
        while tag is not None and tag in used_tags:
            tag = tag + "'"
        if tag is not None:
            used_tags.add(tag)
        lines: list[Latex] = []
        for s in grp:
            lines.extend(math_lines(s.expr, config))
        if len(grp) == 1:
            out.append(equation_lines(lines, tag=tag))
        else:
            body = Latex(
                r"\begin{gathered}" + " \\\\\n".join(x.raw for x in lines) + r"\end{gathered}"
            )
            out.append(equation_lines([body], tag=tag))
        reasons: list[Latex] = []
        for s in grp:
            reason = paragraph(prose(s.why + "."), check(s.verdict, config))
            if reason not in reasons:  # two lines with the same reason: said once
                reasons.append(reason)
        out.append(note(*reasons))
    return Latex("\n\n".join(x.raw for x in out))


def display(expr, config: Config, **kw) -> Latex:
    """Shorthand: a displayed, numbered formula."""
    return equation(expr, config=config, **kw)


def lines_of(expr, config: Config) -> list[Latex]:
    return math_lines(expr, config)
