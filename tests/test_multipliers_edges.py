"""Multipliers and growth rates next to the edges of the intervals: every digit asked for is
printed and proven, or a note says how many are and why.

``ln |mu|max`` tends to 0 at an edge (like the square root of the distance without friction,
linearly with friction), so a bound absolute to ``|mu|max`` leaves it fewer digits than asked
for.  The reference is independent of the package: the pendulum's period map built with mpmath
at 250 digits from the free (or damped) oscillations and the jumps
(``tests/pendulum_monodromy.py``), its eigenvalues from the quadratic formula.
"""

from __future__ import annotations

import json
from fractions import Fraction

import mpmath
import pytest
from pendulum_monodromy import damped_monodromy_mp, monodromy_mp, multipliers_mp

from paramres.cli import main
from verify.multipliers import multipliers

M = Fraction(3, 10)
DIGITS = 30

#: the edges at m = 3/10 to 40 digits (``paramres boundary --order N --m 0.3 [--Q 30] --digits
#: 40``); they only place the points below: nothing is compared with them
EDGES = {
    (None, 1): (
        "0.3470067191935299473885839533689521589087",
        "0.6134674138449552755459528295409129791645",
    ),
    (None, 2): (
        "0.9064633538136918983284982509545165870712",
        "1.031278399945216271387234128444114911645",
    ),
    (None, 3): (
        "1.341180048051514201408749491942108473121",
        "1.544715914139092245486817843827005834058",
    ),
    ("30", 1): (
        "0.3471437876759457070829502592968978997987",
        "0.6132274271166392546984861636605622322779",
    ),
    ("30", 2): (
        "0.9080054686408187609887373657593510326038",
        "1.029567782864707978180155287695135802831",
    ),
    ("30", 3): (
        "1.343400541168320932107700574868351392138",
        "1.542251040665796159039525262991699737403",
    ),
}


def significant_digits(text: str) -> int:
    """The significant digits of a printed decimal (``"0.00120"``: 3, ``"-1.5e-7"``: 2)."""
    return len(text.lstrip("+-").split("e")[0].replace(".", "").lstrip("0"))


def _near(edge: str, exponent: int, side: int) -> str:
    return str(Fraction(edge) + side * Fraction(1, 10**exponent))


def _decimal_text(x: Fraction) -> str:
    """``x`` (a decimal fraction) as a decimal string, exactly."""
    places = 0
    while (x * 10**places).denominator != 1:
        places += 1
    n = int(x * 10**places)
    sign, n = ("-" if n < 0 else ""), abs(n)
    digits = str(n).rjust(places + 1, "0")
    return f"{sign}{digits[:-places]}.{digits[-places:]}" if places else f"{sign}{digits}"


def _reference(T: str, Q, model="exact", dps=250):
    with mpmath.workdps(dps):
        Tm = mpmath.mpf(Fraction(T).numerator) / Fraction(T).denominator
        mm = mpmath.mpf(3) / 10
        Qm = None if Q is None else mpmath.mpf(Fraction(Q).numerator) / Fraction(Q).denominator
        mu = multipliers_mp(damped_monodromy_mp(Tm, mm, Qm, model))
        return mu, abs(mu[0]), mpmath.log(abs(mu[0]))


def _within(text: str, exact, bound: str) -> bool:
    """``|text - exact| <= bound``, ``exact`` an mpf at the reference's precision (whose own
    error, below 1e-200 here, is far below every bound checked)."""
    with mpmath.workdps(300):
        return abs(mpmath.mpf(text) - exact) <= mpmath.mpf(bound) + mpmath.mpf(10) ** -200


def _check(doc: dict, ref) -> None:
    mu, modulus, growth = ref
    if doc["growth_rate"] == "0" and doc["Q"] is None and doc["real"] is False:
        # a proven complex pair without friction: |mu| = 1, ln|mu|max = 0 exactly
        assert doc["growth_rate_exact"] and doc["growth_rate_error_bound"] == "0"
        assert doc["Q"] is None and abs(growth) < mpmath.mpf(10) ** -200
        assert any("exactly" in n for n in doc["notes"])
    else:
        assert _within(doc["growth_rate"], growth, doc["growth_rate_error_bound"])
        assert significant_digits(doc["growth_rate"]) == DIGITS, doc["growth_rate"]
        assert doc["growth_rate_digits"] == DIGITS and not doc["growth_rate_exact"]
    assert significant_digits(doc["max_modulus"]) == DIGITS
    assert _within(doc["max_modulus"], modulus, doc["max_modulus_error_bound"])
    for got, z in zip(doc["multipliers"], mu, strict=True):
        parts = [("re", mpmath.re(z))] + ([] if doc["real"] else [("im", mpmath.im(z))])
        for key, value in parts:
            assert significant_digits(got[key]) == DIGITS, (key, got[key])
            # the sign of the imaginary part: the certified pair is ordered by modulus only
            exact = value if key == "re" or got[key].startswith("-") == (value < 0) else -value
            assert _within(got[key], exact, got["error_bound"])
    assert not any("fewer digits" in n for n in doc["notes"])


@pytest.mark.parametrize("Q", [None, "30"])
@pytest.mark.parametrize("order", [1, 2, 3])
@pytest.mark.parametrize("exponent", [6, 12, 20])
def test_every_digit_next_to_an_edge(Q, order, exponent):
    """At ``1e-6``, ``1e-12`` and ``1e-20`` from both edges of the first three intervals, on both
    sides, with and without friction: 30 proven digits of every number (with friction the growth
    rate printed 5 to 26 of them before, without a note), or an exact 0."""
    for edge in EDGES[Q, order]:
        for side in (-1, 1):
            T = _near(edge, exponent, side)
            doc = multipliers(T, M, Q=Q, digits=DIGITS).as_json()
            _check(doc, _reference(T, Q))


@pytest.mark.parametrize("model", ["exact", "paper"])
def test_growth_with_friction_cli_json_and_text(model, capsys):
    """The command line, JSON and text: order 2, m = 0.3, Q = 30, 1e-20 above the lower edge (the
    growth rate is about 3.2e-19; before, 12 of the 30 digits were printed)."""
    T = _decimal_text(Fraction(_near(EDGES["30", 2][0], 20, 1)))
    args = ["multipliers", "--T", T, "--m", "0.3", "--Q", "30", "--damping", model]
    assert main([*args, "--digits", "30", "--json"]) == 0
    doc = json.loads(capsys.readouterr().out)
    ref = _reference(T, "30", model)
    if model == "exact":
        _check(doc, ref)
    assert significant_digits(doc["growth_rate"]) == 30 and doc["growth_rate_digits"] == 30
    assert _within(doc["growth_rate"], ref[2], doc["growth_rate_error_bound"])
    assert main([*args, "--digits", "30"]) == 0
    text = capsys.readouterr().out
    line = next(x for x in text.splitlines() if "ln|mu|max =" in x)
    assert line.split("= ")[-1] == doc["growth_rate"]
    assert "note" not in text


def test_stable_without_friction_growth_is_exactly_zero(capsys):
    """Just outside an interval without friction the pair lies on the unit circle: ``0`` with the
    bound 0, said in the JSON and in a text note."""
    T = _near(EDGES[None, 1][0], 12, -1)
    assert main(["multipliers", "--T", _decimal_text(Fraction(T)), "--m", "0.3", "--json"]) == 0
    doc = json.loads(capsys.readouterr().out)
    _check(doc, _reference(T, None))
    assert doc["growth_rate_exact"] is True and doc["growth_rate_digits"] == 0
    text = str(multipliers(T, M, digits=DIGITS))
    assert "ln|mu|max = 0 exactly" in text and "growth per period ln|mu|max = 0\n" in text


def _edge_mp(dps: int) -> mpmath.mpf:
    """The lower edge of the first interval at m = 3/10 from the reference alone: ``tr M = -2``
    (a multiplier -1), by mpmath's root finder at ``dps`` digits."""
    with mpmath.workdps(dps):
        mm = mpmath.mpf(3) / 10

        def f(T):
            M_ = monodromy_mp(T, mm)
            return M_[0, 0] + M_[1, 1] + 2

        return mpmath.findroot(f, mpmath.mpf("0.34700671919352994738858395336895"))


def test_every_digit_within_1e_200_of_an_edge():
    """1e-200 inside the first interval: the discriminant is about 1e-200, so the working precision
    must pass 200 digits (before: the multipliers were called a possible double multiplier at 452
    bits and the growth rate, 3.5e-100, printed as 0)."""
    with mpmath.workdps(400):
        edge = _edge_mp(400)
        T = mpmath.nstr(edge + mpmath.mpf(10) ** -200, 260)
    doc = multipliers(T, M, digits=DIGITS).as_json()
    mu, modulus, growth = _reference(T, None, dps=400)
    assert mpmath.mpf("3e-100") < growth < mpmath.mpf("4e-100")
    _check(doc, (mu, modulus, growth))
    assert doc["unstable"] is True


def test_double_multiplier_says_how_many_digits(capsys):
    """At a closing (a custom system whose phases are commensurate: ``M = -I`` at T = 1) the two
    multipliers are never separated: the growth rate prints as 0 within its bound, and a note (text
    and JSON) says how many digits are certified and why."""
    args = ["multipliers", "--T", "1", "--system", "custom", "--omega-sq", "1,4", "--digits", "20"]
    assert main([*args, "--json"]) == 0
    doc = json.loads(capsys.readouterr().out)
    assert doc["growth_rate"] == "0" and doc["growth_rate_digits"] == 0
    assert doc["growth_rate_exact"] is False
    assert mpmath.mpf(doc["growth_rate_error_bound"]) < mpmath.mpf(10) ** -100
    note = next(n for n in doc["notes"] if "fewer digits" in n)
    assert "the 20 asked for" in note and "ln|mu|max 0" in note and "not separated" in note
    assert main(args) == 0
    assert f"note: {note}" in capsys.readouterr().out


def _damped_edge_mp(dps: int) -> mpmath.mpf:
    """The lower edge of the first interval at m = 3/10 with Q = 30 (exact model) from the
    reference alone: a multiplier -1, ``tr M + 1 + det M = 0``, at ``dps`` digits."""
    with mpmath.workdps(dps):
        mm, Q = mpmath.mpf(3) / 10, mpmath.mpf(30)

        def f(T):
            M_ = damped_monodromy_mp(T, mm, Q)
            return M_[0, 0] + M_[1, 1] + 1 + mpmath.det(M_)

        return mpmath.findroot(f, mpmath.mpf("0.34714378767594570708295025929689789979871823"))


def test_beyond_the_largest_precision_a_note_says_so():
    """With friction, 1e-2400 inside the first interval and 5 digits: ``ln|mu|max`` is about
    1.7e-2398 and the largest working precision tried (7680 bits) does not separate it from 0.
    It prints as 0 with a bound that holds (checked against the reference at 2600 digits), the
    verdict is 'undecided', and the note (JSON and text) says 0 of the 5 digits and why.  (The
    command line takes at most 2000 characters of T: the Python API, the same result.)"""
    with mpmath.workdps(2600):
        edge = _damped_edge_mp(2600)
        T = mpmath.nstr(edge + mpmath.mpf(10) ** -2400, 2560)
    mu, modulus, growth = _reference(T, "30", dps=2600)
    assert mpmath.mpf("1e-2399") < growth < mpmath.mpf("1e-2397")
    res = multipliers(Fraction(T), M, Q="30", digits=5)
    doc = res.as_json()
    assert doc["growth_rate"] == "0" and doc["growth_rate_digits"] == 0
    assert not doc["growth_rate_exact"] and doc["unstable"] is None
    with mpmath.workdps(2600):
        assert abs(growth) <= mpmath.mpf(doc["growth_rate_error_bound"])
        bound = mpmath.mpf(doc["max_modulus_error_bound"])
        assert abs(mpmath.mpf(doc["max_modulus"]) - modulus) <= bound
    note = next(n for n in doc["notes"] if "fewer digits" in n)
    assert "the 5 asked for" in note and "ln|mu|max 0" in note and "bits" in note
    text = str(res)
    assert "growth per period ln|mu|max = 0\n" in text and f"note: {note}" in text


def test_tiny_friction_stable_growth_to_every_digit():
    """Q = 1e30 at a stable point: ``ln|mu|max = -pi T/Q`` is about -2.2e-30 (before: printed as
    ``-2.e-30``, one digit, no note); now 30 digits, within the bound of the reference."""
    T = "0.7"
    doc = multipliers(T, M, Q="1e30", digits=DIGITS).as_json()
    ref = _reference(T, "1e30")
    _check(doc, ref)
    assert significant_digits(doc["growth_rate"]) == DIGITS
    with mpmath.workdps(300):
        exact = -mpmath.pi * mpmath.mpf("0.7") / 10**30
    assert _within(doc["growth_rate"], exact, doc["growth_rate_error_bound"])
