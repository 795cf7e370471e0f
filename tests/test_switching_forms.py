"""The stored derivations of the switching section (reports.sections._switching_forms).

Reference for the stored texts: the derivation itself (:func:`reports.sections._switching_forms.
build` derives every expression again with sympy from :mod:`analytic.ramp` and
:mod:`analytic.smooth`); the texts must be identical, and the expressions read back must equal
the derived ones (sympy's structural equality).
"""

from __future__ import annotations

import sympy as sp

from reports.sections import _switching_forms as forms
from reports.sections._switching_forms_generated import SOURCES


def test_stored_texts_are_what_the_derivation_gives():
    fresh = forms.build()
    assert sorted(fresh) == sorted(SOURCES) == sorted(forms.NAMES)
    changed = [k for k in fresh if fresh[k] != SOURCES[k]]
    assert changed == [], "run python -m reports.sections._switching_forms"


def test_the_stored_expressions_are_the_derived_ones():
    derived = forms.derive()
    loaded = forms.load()
    for name in forms.NAMES:
        assert loaded[name] == derived[name], name
    # the facts the section states from them: E12 = -(la - lb)^2/(2 la^2 lb^2), the first
    # interval's slopes -+3/8, the couplings vanish at k = +-1 only, the closings as stated
    la, lb = (sp.Symbol(n, positive=True) for n in ("l_a", "l_b"))
    assert sp.simplify(loaded["E12"] + (la - lb) ** 2 / (2 * la**2 * lb**2)) == 0
    assert (loaded["c_lo"], loaded["c_hi"]) == (sp.Rational(-3, 8), sp.Rational(3, 8))
    assert tuple(loaded["zeros"]) == (-1, 1)
    assert bool(loaded["even_closed"]) and bool(loaded["odd_open"])


def test_a_missing_text_is_derived(monkeypatch):
    import reports.sections._switching_forms_generated as gen

    monkeypatch.setattr(gen, "SOURCES", {k: v for k, v in SOURCES.items() if k != "q"})
    forms.load.cache_clear()
    try:
        assert forms.load()["q"] == forms.derive()["q"]
    finally:
        forms.load.cache_clear()
