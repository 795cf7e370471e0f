"""How the LaTeX looks: the frozen :class:`Config` and its default."""

from __future__ import annotations

from dataclasses import dataclass, field

__all__ = ["Config", "DEFAULT"]


@dataclass(frozen=True)
class Config:
    """Everything that decides how the LaTeX looks; frozen, so a run cannot change it midway.

    ``max_width`` is the visible width (in characters, see :func:`visible_width`) of a displayed
    formula line before :func:`math_lines` breaks it; a line wider than ``fit_width`` is wrapped
    in ``\\fitmath``, which lets TeX measure it and scale it to the line if it is too wide;
    ``digits`` the significant digits of a float printed by :func:`number`; ``printer`` the sympy
    ``latex()`` settings.
    """

    documentclass: str = "article"
    class_options: tuple[str, ...] = ("11pt", "a4paper")
    packages: tuple[tuple[str, str], ...] = (
        ("geometry", "margin=2.3cm"),
        ("amsmath", ""),
        ("amssymb", ""),
        ("graphicx", ""),
        ("booktabs", ""),
        ("longtable", ""),
        ("array", ""),
        ("xcolor", ""),
        ("microtype", "expansion=false"),
        ("caption", "font=small,labelfont=bf"),
        ("hyperref", "hidelinks,hypertexnames=false,pdfcreator={paramres},pdfproducer={paramres}"),
    )
    preamble: tuple[str, ...] = (
        # \fitmath{...}: display math scaled down to the line only if TeX finds it too wide
        r"\newsavebox\prfitbox",
        r"\newcommand{\fitmath}[1]{\sbox\prfitbox{$\displaystyle #1$}%",
        r"\ifdim\wd\prfitbox>\dimexpr\linewidth-4em\relax"
        r"\resizebox{\dimexpr\linewidth-4em\relax}{!}{\usebox\prfitbox}%",
        r"\else\usebox\prfitbox\fi}",
        # \fitcell{...}: a formula in a table cell, scaled to the column if it is a little too
        # wide, but never below 90 % of the table's type (a wider one sticks out, and the build
        # counts it as an overfull line): the columns are made wide enough for their formulas
        r"\newcommand{\fitcell}[1]{\sbox\prfitbox{$\displaystyle #1$}%",
        r"\ifdim\wd\prfitbox>1.1111\linewidth\scalebox{0.9}{\usebox\prfitbox}%",
        r"\else\ifdim\wd\prfitbox>\linewidth\resizebox{\linewidth}{!}{\usebox\prfitbox}%",
        r"\else\usebox\prfitbox\fi\fi}",
        r"\numberwithin{equation}{section}",
        r"\setlength{\LTcapwidth}{\textwidth}",
        r"\allowdisplaybreaks",
        r"\renewcommand{\topfraction}{0.9}",
        r"\renewcommand{\bottomfraction}{0.8}",
        r"\renewcommand{\textfraction}{0.07}",
        r"\renewcommand{\floatpagefraction}{0.75}",
        r"\emergencystretch=2em",
    )
    max_width: int = 70
    fit_width: int = 60
    digits: int = 6
    printer: tuple[tuple[str, object], ...] = field(
        default=(("mul_symbol", None), ("ln_notation", True), ("fold_short_frac", False))
    )


DEFAULT = Config()
