"""Ball-arithmetic proofs: enclosures of simple roots and signs on intervals.

References: roots with closed forms computed by mpmath at twice the precision (``asin(1/3)``,
``pi/4``, the root ``1e-30`` of ``sin(x) - 1e-30`` to first order); functions whose sign is known
in closed form.
"""

from __future__ import annotations

import mpmath
import pytest
from flint import arb, ctx

from verify.certify import (
    CertificationError,
    ball,
    bits_for_digits,
    certified_root,
    prove_sign,
    to_mpf,
    upper_mpf,
)


def _contains(root, value) -> bool:
    with mpmath.workprec(4 * root.prec + 64):
        lo = to_mpf(arb(root.ball.lower()))
        hi = to_mpf(arb(root.ball.upper()))
        return lo <= value <= hi


@pytest.mark.parametrize("bits", [20, 53, 166, 1000, 3400])
def test_root_enclosure_contains_exact_root(bits):
    third = lambda: arb(1) / 3  # noqa: E731
    F = lambda x: x.sin() - third()  # noqa: E731
    dF = lambda x: x.cos()  # noqa: E731
    root = certified_root(F, dF, 0.34, bits=bits)
    with mpmath.workprec(2 * bits + 100):
        exact = mpmath.asin(mpmath.mpf(1) / 3)
    assert _contains(root, exact)
    assert root.ball.rad() <= abs(root.ball.mid()) * arb(2) ** (-bits)
    assert ctx.prec == 53  # precision restored


def test_root_from_a_poor_start_stays_in_bracket():
    """tan(x) = 1 has roots pi/4 + k pi; from a start near 3 pi/4 the bracket keeps the solver on
    the root in (0, 1.2)."""
    F = lambda x: x.sin() - x.cos()  # noqa: E731
    dF = lambda x: x.cos() + x.sin()  # noqa: E731
    root = certified_root(F, dF, 1.1, bits=200, bracket=(0.0, 1.2))
    with mpmath.workprec(500):
        assert _contains(root, mpmath.pi / 4)


def test_tiny_and_zero_roots():
    root = certified_root(
        lambda x: x.sin() - arb("1e-30"), lambda x: x.cos(), 0.0, bits=100, floor=1e-60
    )
    with mpmath.workprec(400):
        exact = mpmath.asin(mpmath.mpf("1e-30"))
    assert _contains(root, exact)
    assert root.ball.rad() <= arb("1e-30") * arb(2) ** -100
    zero = certified_root(lambda x: x.sin(), lambda x: x.cos(), 1e-9, bits=100, floor=1e-40)
    assert zero.ball.contains(0)


def test_double_root_is_refused():
    """x^2 has a double root: interval Newton cannot prove it (F' vanishes there)."""
    with pytest.raises(CertificationError):
        certified_root(lambda x: x * x, lambda x: 2 * x, 0.1, bits=60, max_bits=400)


def test_prove_sign():
    F = lambda x: x.cos()  # noqa: E731
    dF = lambda x: -x.sin()  # noqa: E731
    assert prove_sign(F, dF, -1.5, 1.5, 1)
    assert not prove_sign(F, dF, -1.5, 1.6, 1)  # cos(pi/2) = 0 inside
    assert prove_sign(F, dF, 1.6, 4.6, -1)
    # a near-zero positive minimum: (x - 1/3)^2 + 1e-12 on [0, 1]
    G = lambda x: (x - arb(1) / 3) ** 2 + arb("1e-12")  # noqa: E731
    dG = lambda x: 2 * (x - arb(1) / 3)  # noqa: E731
    assert prove_sign(G, dG, 0.0, 1.0, 1, prec=64)


def test_conversions():
    with ctx.workprec(300):
        x = arb(1) / 3
        m = to_mpf(x)
    assert m.man_exp == tuple(int(v) for v in x.mid().man_exp())  # exact, not rounded to 53 bits
    assert upper_mpf(arb(2, 1)) >= 3
    assert ball(mpmath.mpf("0.375")).mid() == arb("0.375")
    assert bits_for_digits(30) == 100


def test_jet_functions_enclose_the_derivative_over_a_ball():
    """``Jet(f(x), f'(x) dx)`` over a ball ``x``: the value holds ``f`` and the slope holds ``f'``
    at every point of the ball (checked at its ends and middle, against mpmath at 50 digits), for
    each function the compiled forms call on jets (``exp`` for the forms in ``D exp(-2 zeta)``)."""
    import mpmath
    from flint import arb

    from verify.certify import Jet

    x = arb("0.7", "0.01")
    cases = {
        "exp": (mpmath.exp, mpmath.exp),
        "sqrt": (mpmath.sqrt, lambda t: 1 / (2 * mpmath.sqrt(t))),
        "sin": (mpmath.sin, mpmath.cos),
        "cos": (mpmath.cos, lambda t: -mpmath.sin(t)),
        "sinh": (mpmath.sinh, mpmath.cosh),
        "cosh": (mpmath.cosh, mpmath.sinh),
    }
    for name, (f, df) in cases.items():
        j = getattr(Jet(x, 3), name)()
        for t in ("0.69", "0.7", "0.71"):
            with mpmath.workdps(50):
                tv = mpmath.mpf(t)
                assert j.v.contains(arb(mpmath.nstr(f(tv), 15))), name
                assert j.d.contains(arb(mpmath.nstr(3 * df(tv), 15))), name
