"""The certified solver near m = 1, at every number of digits: it never gives up on a valid input
and every printed digit is right.

As ``m -> 1`` every edge ``T/T0`` goes to zero (``omega_av`` grows like ``(1 - m)^(-1/2)``), the
lower edge of order 1 like ``1 - m`` itself, and the standard forms cancel to ``1 - beta``.
References: (a) the same solver at 90 digits (a different working precision, so a different
enclosure); (b) independently, the Floquet route (:mod:`verify.floquet`, no sympy): on an edge of
order ``n`` a multiplier is ``(-1)^n``, so ``det(M - (-1)^n I)`` changes sign between one unit of
the last printed digit below and above the printed value.
"""

from __future__ import annotations

from fractions import Fraction

import mpmath
import pytest

from verify.floquet import monodromy_matrix
from verify.solve import boundary

FRICTION = [(None, "exact"), (10, "paper"), (10, "exact"), (Fraction(3, 5), "exact")]
EXPONENTS = [2, 5, 8, 13, 17, 22, 30]  # 1 - m = 10^-k, log-spaced to 1e-30


def _ulp(text: str) -> mpmath.mpf:
    """One unit of the last digit of a printed decimal."""
    mant = text.lstrip("-").split("e")[0]
    nd = len(mant.replace(".", "").lstrip("0"))
    with mpmath.workdps(100):
        v = mpmath.mpf(text)
        return mpmath.mpf(10) ** (mpmath.floor(mpmath.log10(abs(v))) - nd + 1)


def _right(text: str, ref) -> bool:
    """The printed decimal is within one unit of its last digit of the reference."""
    with mpmath.workdps(100):
        return abs(mpmath.mpf(text) - ref) <= _ulp(text)


def test_reported_order1_low_digits():
    """Was: CertificationError 'could not enclose a simple root ... below 432 bits'."""
    b = boundary(1, "0.9999999999999", digits=5)
    ref = boundary(1, "0.9999999999999", digits=40)
    assert b.certified and _right(b.as_json()["lower"], ref.lower)
    assert _right(b.as_json()["upper"], ref.upper)


def test_reported_paper_model_16_digits():
    """Was: CertificationError 'enclosure of T too wide'."""
    m = "0.9999999999999997"
    b = boundary(1, m, Q=10, damping="paper", digits=16)
    ref = boundary(1, m, Q=10, damping="paper", digits=60)
    assert b.certified and b.exists
    for key, val in (("lower", ref.lower), ("upper", ref.upper), ("delta_lower", ref.delta_lower)):
        assert _right(b.as_json()[key], val)


@pytest.mark.parametrize("Q,damping", FRICTION)
@pytest.mark.parametrize("order", [1, 2, 3, 4])
def test_log_sweep_towards_one(order, Q, damping):
    for k in EXPONENTS:
        m = 1 - Fraction(1, 10**k)
        ref = boundary(order, m, Q=Q, damping=damping, digits=90)
        assert ref.certified
        for digits in (5, 16, 50):
            b = boundary(order, m, Q=Q, damping=damping, digits=digits)
            assert b.certified and b.exists == ref.exists, (k, digits)
            if not b.exists:
                continue
            data = b.as_json()
            for key in ("lower", "upper", "delta_lower", "delta_upper"):
                assert _right(data[key], getattr(ref, key)), (k, digits, key, data[key])


@pytest.mark.parametrize("Q,damping", [(None, "exact"), (10, "paper"), (10, "exact")])
@pytest.mark.parametrize("order", [1, 2, 3, 4])
@pytest.mark.parametrize("k", [8, 20, 30])
def test_edges_bracket_a_floquet_multiplier(order, Q, damping, k):
    """Independent: det(M - (-1)^n I) changes sign across each printed edge +- one last unit."""
    m = 1 - Fraction(1, 10**k)
    b = boundary(order, m, Q=Q, damping=damping, digits=12)
    assert b.exists
    sigma = (-1) ** order
    for key in ("lower", "upper"):
        text = b.as_json()[key]
        with mpmath.workdps(150):
            t = mpmath.mpf(text)
            u = _ulp(text)
            vals = []
            for tau in (t - u, t + u):
                M = monodromy_matrix(m, tau, None if Q is None else Fraction(Q), damping, dps=150)
                vals.append((M[0, 0] - sigma) * (M[1, 1] - sigma) - M[0, 1] * M[1, 0])
            assert vals[0] * vals[1] < 0, (key, text, vals)


def _mpmath_edges(order: int, m: Fraction, dps: int):
    """Reference: both undamped edges ``T/T0`` by mpmath ``findroot`` at ``dps`` digits on the
    derived per-edge equation ``F(theta) = sin(theta) + eps r f(beta (n pi/2 + theta))``
    (:func:`verify.derived.edge_equation`, compiled for mpmath from the sympy form of
    :mod:`analytic`; the standard form, not the near-one rewrite the solver uses there), with
    ``T/T0 = (n/2 + theta/pi)/w``.  Each equation has one root in ``(-pi/2, pi/2)`` where
    ``F(-pi/2) < 0 < F(pi/2)``: a bisection at 40 digits starts a secant iteration at ``dps``."""
    from verify.derived import backend, edge_equation
    from verify.enclosure import sgn_of
    from verify.params import normal_params

    f = edge_equation(-1 if order % 2 else 1).compiled("mpmath", 0)
    sgn = sgn_of(order)
    out = []
    for eps in (1, -1):
        with mpmath.workdps(40):
            p = normal_params(m, None, "exact", backend("mpmath"))
            c = mpmath.pi * order / 2
            lo, hi = -mpmath.pi / 2, mpmath.pi / 2
            for _ in range(120):
                mid = (lo + hi) / 2
                if f(mid, c, sgn, eps, p.r, p.beta) < 0:
                    lo = mid
                else:
                    hi = mid
            start = (lo + hi) / 2
        with mpmath.workdps(dps):
            p = normal_params(m, None, "exact", backend("mpmath"))
            c = mpmath.pi * order / 2
            theta = mpmath.findroot(
                lambda t, c=c, e=eps, r=p.r, b=p.beta: f(t, c, sgn, e, r, b), mpmath.mpf(start)
            )
            out.append((mpmath.mpf(order) / 2 + theta / mpmath.pi) / p.w)
    return sorted(out)


@pytest.mark.parametrize("order", [1, 2, 3])
@pytest.mark.parametrize("m", [Fraction(999999, 1000000), 1 - Fraction(1, 10**9)])
def test_thousand_digits_near_one_against_mpmath(order, m):
    """Was (0.999999 at 700 and 1000 digits, orders 1, 2, 3, 5): CertificationError 'could not
    enclose a simple root near 1.5719070478067234 below 41728 bits' -- a midpoint Newton step
    that rounded to no step at all was taken for one leaving the bracket, and the bisection that
    replaced it threw the digits away.  Every printed digit against mpmath at 1200 digits
    (:func:`_mpmath_edges`), within the printed bound."""
    b = boundary(order, m, digits=1000)
    assert b.certified and b.exists
    data = b.as_json()
    ref = _mpmath_edges(order, m, 1200)
    with mpmath.workdps(1200):
        bound = mpmath.mpf(data["error_bound"])
        assert bound < mpmath.mpf(10) ** -990 * ref[1]
        for key, val in zip(("lower", "upper"), ref, strict=True):
            text = data[key]
            assert len(text.lstrip("-0.").replace(".", "")) >= 990, key
            assert abs(mpmath.mpf(text) - val) <= bound, (key, order)
