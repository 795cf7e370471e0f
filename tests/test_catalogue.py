"""The catalogue: statuses are decided by derivation.

Expected statuses below are what the derivation established (each differing row's ``how`` names
the derived correct form); independently, the comparison machinery is shown to catch a planted
misprint, so an 'agrees' cannot come from a checker that always agrees.
"""

import json

import pytest
import sympy as sp

from analytic.catalogue import catalogue
from analytic.catalogue_rows import _how_differs, compare_equations, difference
from analytic.printed import printed
from analytic.reductions import chain

#: rows the derivation finds to differ from the print (see each row's `how`)
EXPECTED_DIFFERS = {"23", "39-ref", "40-ref", "15-n3"}


@pytest.fixture(scope="module")
def rows():
    return {r.equation: r for r in catalogue()}


def test_required_rows_present(rows):
    for eq in (
        "4",
        "5",
        "10",
        "11",
        "12",
        "13",
        "14",
        "15",
        "IC-15",
        "22",
        "23",
        "24",
        "25",
        "26",
        "IC-26",
        "32",
        "34",
        "36",
        "39",
        "41",
        "44",
    ):
        assert eq in rows, eq


def test_rows_well_formed(rows):
    for r in rows.values():
        assert r.status in ("agrees", "differs")
        assert r.printed and r.derived and r.how and r.title
        json.dumps(r.as_json())


def test_statuses_of_the_exact_results(rows):
    mine = {
        k: v
        for k, v in rows.items()
        if k in EXPECTED_DIFFERS or k in printed() or k.endswith("-ref")
    }
    for label, r in mine.items():
        expected = "differs" if label in EXPECTED_DIFFERS else "agrees"
        assert r.status == expected, (label, r.how)


def test_eq23_misprint_is_located(rows):
    how = rows["23"].how
    assert (
        r"\cos{\left(\frac{T \omega_{2}}{4} \right)}" in how
        and r"\sin{\left(\frac{T \omega_{2}}{4} \right)}" in how
    )
    assert "does not follow from the printed (22)-(23)" in how


def test_cross_reference_after_39_points_to_15(rows):
    assert "should be (15)" in rows["39-ref"].how
    assert "reference is right" in rows["44-ref"].how


def test_planted_misprint_is_caught():
    """Change one coefficient of the printed (13) and the comparison must fail and locate it."""
    q = sp.Symbol("q", positive=True)
    derived = chain("edge-odd-cos-sin").step("13").expr
    good = printed()["13"][0]
    bad = sp.Eq(good.lhs, good.rhs.subs(q - 1, q - 2), evaluate=False)
    assert compare_equations(good, derived).holds
    assert not compare_equations(bad, derived).holds
    assert "printed" in _how_differs(bad, derived)


def test_difference_locates_smallest_subexpressions():
    a, b, c = sp.symbols("a b c")
    assert difference(a * sp.cos(b) + c, a * sp.sin(b) + c) == [(sp.cos(b), sp.sin(b))]
    assert difference(a + b, a + b) == []


def test_a_row_says_decided_symbolically_only_when_every_check_was():
    # a check that fell back to random points must be described as numeric, not as symbolic
    from analytic.catalogue_rows import _decided
    from analytic.identity import Verdict

    assert _decided([Verdict(True, "symbolic"), Verdict(True, "symbolic")]) == (
        "decided symbolically."
    )
    mixed = _decided([Verdict(True, "symbolic"), Verdict(True, "numeric", 24, 40, 1e-41)])
    assert "symbolically" not in mixed.replace("sympy did not", "") and "24 random points" in mixed


def test_equations_of_motion_row_is_an_exact_identity(rows):
    # eqs. (2)-(3): the frequencies are compared through their squares (both positive), which
    # sympy reduces to zero exactly; the row says so only because every check was symbolic
    row = rows["2-3"]
    assert row.status == "agrees" and row.how.endswith("decided symbolically.")


def test_exact_average_frequency_is_decided_symbolically(rows):
    # eq. (7): omega_av/omega_0 = (1/sqrt(1+m) + 1/sqrt(1-m))/2 is an exact identity of the model;
    # the check reduces it to zero without falling back to random points
    assert "(simplifies symbolically to zero)" in rows["7"].how


def test_the_papers_sections_are_named_as_the_papers(rows):
    """'(section 3.2)' would read as a section of the report: it is the paper's, in both
    languages."""
    from reports.i18n import language, tr

    r = rows["15-n3"]
    assert "the paper's section 3.2" in r.title
    assert r.how.startswith("The paper's section 3.2:")
    with language("ru"):
        assert "разд. 3.2 статьи" in tr(r.title)
        assert tr(r.how).startswith("Раздел 3.2 статьи:")
