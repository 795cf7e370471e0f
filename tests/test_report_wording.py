"""Small things a reader of the report sees: primes in equation tags, punctuation after a
displayed formula, a reason said once under a group of lines, the right identity and reference in
the even-order friction chain, singular and plural, dashes in ranges, and the figures ending before
the references."""

from __future__ import annotations

import re
import shutil
import subprocess

import pytest
import sympy as sp

from reports import latex as L


def test_a_prime_in_a_tag_is_a_prime_not_an_apostrophe():
    x = sp.Symbol("x")
    assert r"\tag{15$'$}" in L.equation(x, tag="15'").raw
    assert r"\tag{13}" in L.equation(x, tag="13").raw


def test_punctuation_after_a_displayed_formula_ends_the_display():
    wide = " + ".join(rf"\frac{{\Delta T \omega_{{{k}}}}}{{q + {k}}}" for k in range(8))
    out = L.mixed(f"it gives ${wide}$, whose root is small").raw
    assert out.endswith(r",\]whose root is small"), out
    out = L.mixed(f"the correct form is ${wide}$. The printed one").raw
    assert r".\]The printed one" in out, out
    # a formula in the line keeps its punctuation after it
    assert L.mixed("with $q$, and").raw == "with $q$, and"


def test_a_reason_shared_by_the_lines_of_one_display_is_said_once():
    from analytic.reductions import chains
    from reports.latex.config import DEFAULT
    from reports.sections._render import chain

    odd = next(c for c in chains() if c.key == "friction-odd")
    assert [s.why for s in odd.steps if s.label == "35"] == ["product to sum"] * 2
    assert chain(odd, DEFAULT).raw.count("Products written as sums.") == 1


def test_the_even_order_friction_chain_names_its_own_identity():
    from analytic.reductions import chains

    even = next(c for c in chains() if c.key == "friction-even")
    (step,) = [s for s in even.steps if s.label == "41"]
    assert "(34)" not in step.why and "1 - 2 sin^2(a/2)" in step.why
    odd = next(c for c in chains() if c.key == "friction-odd")
    (step,) = [s for s in odd.steps if s.label == "36"]
    assert "2 cos^2(a/2) - 1 in (34)" in step.why


def test_closings_model_text_and_the_references():
    from reports.report import assemble
    from reports.sections import Context

    tex = assemble(Context(log=lambda m: None), ("model", "closings")).tex
    assert "3:1 closes order 4 at" in tex and "2:1 closes orders 3, 6 at" in tex
    assert "eqs. 32--45" in tex
    assert tex.index("\\clearpage\n\n\\begin{thebibliography}") > tex.index(r"\label{sec:closings}")


def test_a_sentence_of_the_threshold_verdict_starts_with_a_capital():
    from analytic.catalogue import catalogue
    from reports.i18n import language, tr

    (row,) = [r for r in catalogue() if r.equation == "38"]
    assert "$1/Q$. Paper model: leading term" in row.how
    with language("ru"):
        assert "Модель статьи: главный член" in tr(row.how)


def test_the_printed_command_names_no_directory_of_the_machine():
    """The command under the title names the output directory by its last component: an absolute
    ``--out`` is no part of the report."""
    from argparse import Namespace

    from reports.commands.report import _command_line

    def line(out, **kw):
        args = {"lang": "en", "no_pdf": False, "no_cache": False, **kw}
        return _command_line(Namespace(out=out, **args))

    assert line("/home/someone/work/report") == "paramres report --out report"
    assert line("report") == "paramres report --out report"
    assert line("out dir/", lang="ru") == "paramres report --out 'out dir' --lang ru"
    assert line(".") == "paramres report --out ."


#: the smallest share of the table's type a formula in the errata table may be set at
ERRATA_MIN_SCALE = 0.9


def _errata_table_widths(tmp_path, lang: str) -> tuple[str, list[tuple[float, float]], str]:
    """The errata table of the report in ``lang`` typeset alone with the report's preamble: its
    source, the natural width of every formula in it against the width it is given (points,
    measured by TeX), and the LaTeX log."""
    from reports.i18n import language
    from reports.latex import Latex, document
    from reports.report import LANGUAGE_PACKAGES
    from reports.sections import Context
    from reports.sections.catalogue import rows
    from reports.sections.summary import errata_table

    with language(lang):
        differs = [r for r in rows(Context(log=lambda m: None)) if r.status != "agrees"]
        table = errata_table({"differs": differs}).raw
    measure = (
        r"\newsavebox\measurebox\let\fitcellset\fitcell"
        r"\renewcommand{\fitcell}[1]{\sbox\measurebox{$\displaystyle #1$}"
        r"\typeout{FORMULA \the\wd\measurebox\space\the\linewidth}\fitcellset{#1}}"
    )
    tex = document(
        [Latex(r"\section{S}\label{sec:catalogue}"), Latex(table)],
        title="errata",
        packages=LANGUAGE_PACKAGES.get(lang, ()),
        preamble=[measure],
        contents=(),
    ).raw
    (tmp_path / "errata.tex").write_text(tex, encoding="utf-8")
    subprocess.run(
        ["pdflatex", "-interaction=nonstopmode", "-halt-on-error", "errata.tex"],
        cwd=tmp_path,
        capture_output=True,
        check=True,
    )
    log = (tmp_path / "errata.log").read_text(encoding="latin-1")
    widths = [
        (float(w), float(lw)) for w, lw in re.findall(r"^FORMULA ([\d.]+)pt ([\d.]+)pt$", log, re.M)
    ]
    return table, widths, log


@pytest.mark.skipif(shutil.which("pdflatex") is None, reason="pdflatex not installed")
@pytest.mark.parametrize("lang", ["en", "ru"])
def test_the_errata_table_sets_its_formulas_in_readable_type(tmp_path, lang):
    """Every formula of the errata table fits its column at 90 % of the table's type or more (it
    used to be scaled to a third of the page, down to 5 or 6 pt), the table shrinks nothing
    otherwise and sticks out nowhere."""
    from reports.build import supports

    if not supports(lang):
        pytest.skip(f"the installed TeX cannot typeset {lang}")
    table, widths, log = _errata_table_widths(tmp_path, lang)
    for shrink in (r"\scalebox", r"\resizebox", r"\tiny", r"\scriptsize", r"\footnotesize"):
        assert shrink not in table, shrink
    assert len(widths) >= 10
    scales = [min(1.0, lw / w) for w, lw in widths if w > 0]
    assert min(scales) >= ERRATA_MIN_SCALE, sorted(scales)[:5]
    assert "Overfull" not in log


def _math_symbols(src: str) -> set[str]:
    """The letters (Greek or Latin, with their subscripts) in the mathematics of ``src``, without
    the operators' names, the differential ``d``, Euler's ``e`` and words set as text."""
    src = re.sub(r"\\(text|operatorname|mathrm)\{[^{}]*\}", " ", src)
    src = re.sub(r"\\(frac|left|right|sqrt|sin|cos|tan|min|quad|qquad|dots|cdot|mp|pm)\b", " ", src)
    src = src.replace(r"\fitcell", " ")
    found = set()
    for mt in re.finditer(
        r"(\\[A-Za-z]+|(?<![\\A-Za-z])[A-Za-z](?![A-Za-z]))(_\{[^{}]*\}|_[A-Za-z0-9])?", src
    ):
        name = mt.group(1) + re.sub(r"[{}]", "", mt.group(2) or "")
        if name not in ("d", "e") and not name.startswith(("\\begin", "\\end", "\\emph")):
            found.add(name)
    return found


def test_every_symbol_of_the_errata_table_is_said_before_it():
    """The summary comes before the model section: the symbols of its errata table are said in
    the paragraph before the table (they used to appear there undefined)."""
    from reports.sections import Context
    from reports.sections.catalogue import rows
    from reports.sections.summary import _lines, notation_paragraph

    differs = [r for r in rows(Context(log=lambda m: None)) if r.status != "agrees"]
    used = set()
    for r in differs:
        for side in (r.printed, r.derived or ""):
            for line in _lines(side):
                used |= _math_symbols(line)
    said = _math_symbols(" ".join(re.findall(r"\$([^$]*)\$", notation_paragraph().raw)))
    said |= {x[:-1] + k for x in said if x.endswith("_i") for k in "12"}  # C_i: C_1 and C_2
    said |= {"T", "m", "n", "T_-", "T_+"}  # said in the introduction
    assert {"q", "p", r"\Delta", r"\omega_av", "T_av", "N", r"\theta"} <= used
    assert used <= said, sorted(used - said)
