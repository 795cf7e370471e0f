"""The catalogue: statuses are decided by derivation.

Expected statuses below are what the derivation established (each differing row's ``how`` names
the derived correct form); independently, the comparison machinery is shown to catch a planted
misprint, so an 'agrees' cannot come from a checker that always agrees.
"""

import json
import re

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


def _verdict_math(how: str) -> list[str]:
    return re.findall(r"\$(.*?)\$", how)


#: symbols of the normal form a verdict may use, and how a verdict defines each
_NORMAL_FORM_SYMBOLS = {
    "w": (r"(?<![\\A-Za-z])w(?![A-Za-z])", r"(?<![\\A-Za-z])w = "),
    "r": (r"(?<![\\A-Za-z])r(?![A-Za-z])", r"(?<![\\A-Za-z])r(\^2)? = "),
    "beta": (r"\\beta(?![A-Za-z])", r"\\beta = "),
}


@pytest.mark.parametrize("lang", ["en", "ru"])
def test_verdicts_define_the_normal_form_parameters_they_use(rows, lang):
    """A verdict is read on its own (``paramres catalogue``, or one entry of the report): the
    normal-form parameters ``r``, ``beta``, ``w`` it names are defined in it, in both languages
    (eq. (7) named ``T_av/T_0 = 1/w`` and the thresholds (38), (43) 'their r, beta, w' without
    saying what they are)."""
    from reports.i18n import language, tr

    used = set()
    for r in rows.values():
        with language(lang):
            how = tr(r.how)
        math = " ".join(_verdict_math(how))
        for name, (use, define) in _NORMAL_FORM_SYMBOLS.items():
            if re.search(use, math):
                used.add((r.equation, name))
                assert re.search(define, math), f"({r.equation}) uses {name} undefined: {how}"
    assert {("7", "w"), ("38", "w"), ("38", "beta"), ("43", "r")} <= used
    assert r"w = \omega_{av}/\omega_0" in rows["7"].how


def test_the_bobs_mass_is_not_the_monodromy_matrix(rows):
    """``M`` is the monodromy matrix throughout the report; the derivation of eqs. (2)-(4) writes
    the bob's mass through the moment of inertia ``J_0`` at the length ``l_0`` (as the report's
    table of the two halves does), not as a second ``M``."""
    mass = r"(?<![\\A-Za-z])M(?=\s*[gl])|/M(?![A-Za-z])"
    for r in rows.values():
        for piece in _verdict_math(r.how):
            assert not re.search(mass, piece), f"({r.equation}): ${piece}$"
    for eq in ("2-3", "4"):  # nor in the derived equations (gamma = c/(2M) before)
        assert not re.search(r"(?<![\\A-Za-z])M(?![A-Za-z])", rows[eq].derived), rows[eq].derived
        assert r"J = J_0 (l/l_0)^2" in rows[eq].how
    assert r"2\gamma = cl_0^2/J_0" in rows["2-3"].how
