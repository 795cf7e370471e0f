"""The stored simplified forms the catalogue prints (:mod:`analytic.simplified_generated`).

Reference for every stored form: ``sympy.simplify`` of its input, computed again here; the set of
inputs is what the catalogue's rows ask for (:func:`analytic.generate_simplified.asked`, every row
built afresh), so the file cannot drift from the derivation.
"""

from __future__ import annotations

import sympy as sp

from analytic import catalogue_series, generate_simplified
from analytic.simplified_generated import FORMS


def _parse(code: str) -> sp.Expr:
    return eval(code, {n: getattr(sp, n) for n in generate_simplified.NAMES})


def test_every_stored_form_is_what_simplify_gives():
    assert FORMS
    for key, form in FORMS.items():
        assert sp.srepr(sp.simplify(_parse(key))) == sp.srepr(form), key


def test_the_stored_inputs_are_the_ones_the_rows_ask_for():
    fresh = generate_simplified.build()
    assert sorted(fresh) == sorted(FORMS), "run python -m analytic.generate_simplified"
    assert all(_parse(fresh[k]) == FORMS[k] for k in fresh)


def test_an_expression_not_stored_is_simplified():
    x = sp.Symbol("x", positive=True)
    e = x / (x**2 + x)
    assert sp.srepr(e) not in FORMS
    assert catalogue_series._simplified(e) == 1 / (x + 1)
