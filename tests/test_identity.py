"""The identity checks that every 'agrees' of the engine rests on: they must prove true identities
and refuse false ones (a checker that always says yes would make every other test meaningless)."""

import sympy as sp

from analytic.identity import factor_between, prove_multiple, prove_proportional, prove_zero

x, y, b = sp.symbols("x y beta", positive=True)
K = sp.Symbol("K")


def test_true_trig_identity_is_symbolic():
    v = prove_zero(sp.cos(x) ** 2 + sp.sin(x) ** 2 - 1)
    assert v.holds and v.route == "symbolic"


def test_product_to_sum_with_free_coefficient():
    lhs = 2 * sp.cos(x - y) * sp.cos(x + y) - K * sp.sin(x - y) * sp.sin(x + y)
    rhs = (K + 2) * sp.cos(x) ** 2 - (K - 2) * sp.cos(y) ** 2 - 2
    assert prove_zero(lhs - rhs).holds
    assert not prove_zero(lhs - rhs - sp.cos(y) ** 2 / 1000).holds


def test_powers_are_not_rewritten_as_exponentials():
    # x**2 must stay algebraic: (1+b)^3/(1-b)^3 style identities
    q = ((1 + b) / (1 - b)) ** 3
    r = b * (3 + b**2) / (1 + 3 * b**2)
    assert prove_zero((q - 1) / (q + 1) - r).holds
    assert not prove_zero((q - 1) / (q + 1) - r * (1 + b / 10**6)).holds


def test_false_identity_is_refused_numerically():
    v = prove_zero(sp.sin(2 * x) - 2 * sp.sin(x))
    assert not v.holds and v.route == "numeric" and v.worst > 1e-3


def test_numeric_route_with_names_that_are_not_identifiers_or_clash():
    # the numeric route compiles expressions whose symbols are named like LaTeX or like the names
    # it renames them to; each compiled function must take its arguments in the order given
    # (reference: the same expression evaluated by mpmath directly)
    import mpmath

    from analytic.identity import _mpmath_function

    w = sp.Symbol(r"\omega_{0}", positive=True)
    a0, aa0 = sp.Symbol("_a0"), sp.Symbol("__a0")
    expr = sp.sin(w) * 3 + a0**2 - aa0 / 7
    for order in ((w, a0, aa0), (aa0, w, a0)):
        f = _mpmath_function(order, expr)
        vals = {w: mpmath.mpf("0.3"), a0: mpmath.mpf("1.7"), aa0: mpmath.mpf("-2.5")}
        with mpmath.workdps(30):
            want = mpmath.sin(vals[w]) * 3 + vals[a0] ** 2 - vals[aa0] / 7
            got = f(*(vals[s] for s in order))
            assert abs(got - want) < mpmath.mpf(10) ** -28
    v = prove_zero(sp.sin(w + a0) - sp.sin(w) * sp.cos(a0) - sp.cos(w) * sp.sin(a0) + aa0 / 10**6)
    assert not v.holds and 1e-7 < v.worst < 1e-5


def test_factor_between_finds_non_oscillating_factor():
    fac = factor_between((1 + b) * sp.sin(2 * x), sp.sin(x) * sp.cos(x))
    assert sp.simplify(fac - 2 * (1 + b)) == 0
    # a ratio that oscillates is not a factor we accept
    assert factor_between(sp.sin(2 * x), sp.sin(x)) is None


def test_prove_multiple_and_proportional():
    assert prove_multiple(sp.exp(-x) * (sp.cos(x) + 1), 2 * sp.cos(x / 2) ** 2).holds
    assert not prove_multiple(sp.cos(x) + 1, sp.cos(x) - 1).holds
    v = prove_proportional(sp.sin(2 * x), 4 * sp.sin(x) * sp.cos(x))
    assert v.holds and v.factor == sp.Rational(1, 2)
    assert not prove_proportional(sp.sin(x), sp.cos(x)).holds


def test_ring_route_gives_sfields_elements_and_quotients():
    """The exact quotient of two rational functions by ring arithmetic and FLINT's gcd is, term
    for term, what sympy's own field (``sfield``, the independent route) gives: rational and
    Gaussian coefficients, negative powers, a quotient that is real although both sides carry
    ``I``, one that stays complex, and a root (which goes to sympy)."""
    from sympy.polys.fields import sfield

    from analytic.identity import _field_elements, _field_ratio

    x, y, z = sp.symbols("x y z")
    cases = [
        ((x**2 - y**2) / 3 + x / (y + 1), (x - y) * (x + 1) / (2 * (y + 1))),
        ((x + sp.I * y) * (x - sp.I * y) / (z - 1) ** 2, (x**2 + y**2) * (z + 1) / (z - 1)),
        (sp.I * (z - 1 / z) * (x + 1), (z - 1 / z) / 2),
        ((x + sp.I * y) ** 2, x * (y - 2)),
        (-(x**3) + 2 * x * y - y / z, -(x**2) * z + 2 * y * z - y / x),
        (sp.sqrt(x + 1) * y + x, y - x),
    ]
    for a, b in cases:
        _, (ea, eb) = sfield([a, b])
        expected = (ea / eb).as_expr()
        got = _field_ratio(a, b)
        assert sp.srepr(got) == sp.srepr(expected), (a, b)
        # asked to give up on a ratio that depends on a symbol: None exactly where the ratio
        # (sympy's own cancellation) keeps an imaginary part and that symbol
        for s in (x, y, z):
            screened = _field_ratio(a, b, unless=frozenset({s}))
            complex_ratio = expected.has(sp.I)
            assert (screened is None) == (complex_ratio and s in expected.free_symbols), (a, b, s)
            if screened is not None:
                assert sp.srepr(screened) == sp.srepr(expected), (a, b, s)
        for e, f in zip((ea, eb), _field_elements([a, b]), strict=True):
            assert sp.srepr(f.as_expr()) == sp.srepr(e.as_expr())
