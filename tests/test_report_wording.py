"""Small things a reader of the report sees: primes in equation tags, punctuation after a
displayed formula, a reason said once under a group of lines, the right identity and reference in
the even-order friction chain, singular and plural, dashes in ranges, and the figures ending before
the references."""

from __future__ import annotations

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
