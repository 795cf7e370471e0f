"""Certified boundaries: against the paper's printed equations solved independently, the closing
theorem, and the hard cases (tiny and near-1 depths, high orders, closings, thresholds, critical
damping, 5 to 1000 digits).

Independent references used below (each solved here with ``mpmath.findroot`` in the plain period
``T``, no ``theta`` variable, no parameter rearrangements, at 2-3x the digits compared):

* eqs. 13 and 25 (no friction): ``(q+1) f(omega_av T/2) = +-(q-1) f(Delta omega T/4)`` with ``f =
  cos`` (odd orders; the paper uses eq. 13 for every odd order) or ``sin`` (even orders, eq. 25),
  ``q = ((1+m)/(1-m))^(3/2)`` (eq. 14);
* eqs. 36 and 41 squared (paper model with friction): ``(q+1)^2 f(omega_av T/2)^2 =
  (q-1)^2 f(Delta omega T/4)^2 - q (p + 1/p - 2)``, ``p = exp(-gamma T)``;
* the closing theorem (docs/theory.md): at ``m = (b^2-a^2)/(b^2+a^2)``, ``a + b = n``, both edges of
  order ``n`` equal ``a T1 = a sqrt(1+m) T0``.
"""

from __future__ import annotations

from fractions import Fraction

import mpmath
import numpy as np
import pytest

from verify.existence import existence
from verify.floquet import floquet_multipliers
from verify.grid import boundary_grid
from verify.inputs import InputError
from verify.solve import Boundary, boundary


def _mp(x):
    return mpmath.mpf(x.numerator) / x.denominator if isinstance(x, Fraction) else mpmath.mpf(x)


def printed_edge_equation(n: int, m, sign: int, Q=None):
    """Eqs. 13/25 (Q None) or eqs. 36/41 squared (paper model) as a function of T (units T0)."""
    m = _mp(m)
    w1 = 2 * mpmath.pi / mpmath.sqrt(1 + m)
    w2 = 2 * mpmath.pi / mpmath.sqrt(1 - m)
    wav, dw = (w1 + w2) / 2, w2 - w1
    q = ((1 + m) / (1 - m)) ** mpmath.mpf(1.5)
    f = mpmath.cos if n % 2 else mpmath.sin
    if Q is None:
        return lambda T: (q + 1) * f(wav * T / 2) - sign * (q - 1) * f(dw * T / 4)
    gam = mpmath.pi / _mp(Fraction(Q))

    def F(T):
        p = mpmath.exp(-gam * T)
        return (
            (q + 1) ** 2 * f(wav * T / 2) ** 2
            - (q - 1) ** 2 * f(dw * T / 4) ** 2
            + q * (p + 1 / p - 2)
        )

    return F


def reference_edges(n, m, Q=None, dps=60, damping="paper"):
    """Both edges from the printed equations, started at the double-precision grid values."""
    g = boundary_grid([n], [float(m)], Q=Q, damping=damping)[0, :, 0]
    out = []
    with mpmath.workdps(dps):
        for T0 in g:
            if Q is None:
                cands = []
                for s in (1, -1):
                    try:
                        cands.append(
                            mpmath.findroot(printed_edge_equation(n, m, s), mpmath.mpf(T0))
                        )
                    except ValueError:  # this sign's root is not near T0
                        pass
                out.append(min(cands, key=lambda T: abs(T - T0)))
            else:
                out.append(mpmath.findroot(printed_edge_equation(n, m, 0, Q), mpmath.mpf(T0)))
    return out


def assert_within(b: Boundary, ref, what=""):
    """``ref`` lies within the proven radius (plus the reference's own 1e-(dps-5))."""
    for got, want, name in ((b.lower, ref[0], "lower"), (b.upper, ref[1], "upper")):
        with mpmath.workdps(80):
            err = abs(got - want)
            tol = b.radius + mpmath.mpf(10) ** (-55) * abs(want)
            assert err <= tol, (
                f"{what} {name}: got {got}, reference {want}, |diff| {err}, radius {b.radius}"
            )


@pytest.mark.parametrize("n", [1, 2, 3, 4, 5, 6])
@pytest.mark.parametrize("m", ["0.05", "0.3", "3/7", "0.8", "0.95"])
def test_undamped_against_eqs_13_25(n, m):
    b = boundary(n, m, digits=50)
    assert b.exists and b.certified and b.lower <= b.upper
    assert b.radius < mpmath.mpf(10) ** -50
    assert_within(b, reference_edges(n, Fraction(m)), f"n={n} m={m}")


@pytest.mark.parametrize(
    "n,m,Q",
    [(1, "0.3", 5), (2, "0.6", 3), (3, "0.7", 7), (1, "0.2", "7/2"), (4, "0.9", 5), (3, "0.3", 7)],
)
def test_paper_model_against_eqs_36_41(n, m, Q):
    b = boundary(n, m, Q=Q, damping="paper", digits=40)
    assert b.exists and b.certified
    assert_within(b, reference_edges(n, Fraction(m), Q=Q), f"n={n} m={m} Q={Q}")


def test_result_object():
    b = boundary(3, "3/5", digits=20)
    assert b.m == Fraction(3, 5) and b.order == 3 and b.Q is None and b.method == "certified"
    j = b.as_json()
    assert j["lower"] == j["upper"] and j["exists"] is True and j["damping"] == "none"
    assert "order 3" in str(b) and "certified" in str(b)
    assert b.width is not None and abs(b.width) <= b.radius * 4
    none = boundary(3, "0.6", Q=7, digits=15)
    assert not none.exists and none.lower is None and none.width is None
    assert none.as_json()["lower"] is None and "no interval" in str(none)


@pytest.mark.parametrize("m", ["0.3", 0.3, Fraction(3, 10), mpmath.mpf("0.3")])
def test_depth_types(m):
    b = boundary(1, m, digits=20)
    # a float means its shortest decimal (0.3 is 3/10, as on the command line); an mpf its binary
    # value
    ref = boundary(1, Fraction(0.3) if isinstance(m, mpmath.mpf) else "3/10", digits=20)
    assert b.lower == ref.lower
    if isinstance(m, str):
        assert b.m == Fraction(3, 10)  # "0.3" is exact


def test_bad_input():
    for kw in (
        {"order": 0, "m": "0.3"},
        {"order": 1, "m": "1"},
        {"order": 1, "m": "nan"},
        {"order": 1, "m": "0.3", "Q": 0},
        {"order": 1, "m": "0.3", "digits": 3},
        {"order": 1, "m": "0.3", "damping": "none"},
        {"order": 1, "m": "0.3", "method": "x"},
    ):
        with pytest.raises(InputError):
            boundary(kw.pop("order"), kw.pop("m"), **kw)


# --------------------------------------------------------------------------------------------
# hard cases


def test_tiny_depth_keeps_the_digits_of_the_offset():
    """m = 1e-12: widths ~ m (odd) and ~ m^2 (even orders, ~1e-24); the offsets T - n T_av/2 keep
    full relative accuracy.  Reference: eqs. 13/25 solved for Delta T = T - n T_av/2 at 120
    digits."""
    m = Fraction(1, 10**12)
    for n in range(1, 7):
        b = boundary(n, m, digits=30)
        with mpmath.workdps(120):
            mm = _mp(m)
            w1 = 2 * mpmath.pi / mpmath.sqrt(1 + mm)
            w2 = 2 * mpmath.pi / mpmath.sqrt(1 - mm)
            Tav = 4 * mpmath.pi / (w1 + w2)
            for got in (b.delta_lower, b.delta_upper):
                cands = []
                for s in (1, -1):
                    F = printed_edge_equation(n, m, s)
                    try:
                        cands.append(
                            mpmath.findroot(
                                lambda d, F=F, n=n, Tav=Tav: F(n * Tav / 2 + d),
                                mpmath.mpf(float(got)),
                            )
                        )
                    except ValueError:
                        pass
                ref = min(cands, key=lambda d: abs(d - got))
                assert abs(got - ref) <= mpmath.mpf(10) ** -29 * abs(ref), (n, got, ref)
        if n % 2 == 0:
            assert 1e-25 < abs(float(b.delta_lower)) < 1e-23  # ~ m^2
        assert b.lower < b.upper


def test_depth_near_one():
    for n in range(1, 7):
        b = boundary(n, "0.999", digits=40)
        assert_within(b, reference_edges(n, Fraction(999, 1000), dps=60), f"n={n} m=0.999")


@pytest.mark.parametrize("n", [20, 57, 99, 100])
def test_high_orders(n):
    """Orders up to 100: against eqs. 13/25 at 60 digits; the edges bracket n T_av/2 and the
    solver stays in its own window (edges strictly between those of orders n-1 and n+1's
    centres)."""
    m = Fraction(3, 10)
    b = boundary(n, m, digits=40)
    assert_within(b, reference_edges(n, m), f"n={n}")
    with mpmath.workdps(40):
        wav = (1 / mpmath.sqrt(1 + _mp(m)) + 1 / mpmath.sqrt(1 - _mp(m))) / 2
        centre = lambda k: mpmath.mpf(k) / (2 * wav)  # noqa: E731
        assert centre(n - 1) < b.lower <= b.upper < centre(n + 1)


def _closings(n):
    for a in range(1, n):
        b_ = n - a
        if a < b_:
            yield a, b_, Fraction(b_ * b_ - a * a, b_ * b_ + a * a)


@pytest.mark.parametrize("n", [3, 4, 5, 6, 7, 8])
def test_every_closing_depth(n):
    """Closing theorem: at m = (b^2-a^2)/(b^2+a^2) both edges equal a T1; both enclosures
    contain it."""
    for a, b_, m in _closings(n):
        res = boundary(n, m, digits=40)
        with mpmath.workdps(400):  # above the enclosures' own precision
            T1a = a * mpmath.sqrt(1 + _mp(m))
            for lo, hi in (res.lower_enclosure, res.upper_enclosure):
                assert lo <= T1a <= hi, (n, a, b_, lo, T1a, hi)
            assert abs(res.lower - T1a) <= res.radius and abs(res.upper - T1a) <= res.radius
        assert res.as_json()["lower"] == res.as_json()["upper"]


def test_closing_m_3_5_order_3_edges_equal_T1():
    res = boundary(3, "3/5", digits=100)
    with mpmath.workdps(120):
        T1 = mpmath.sqrt(mpmath.mpf(8) / 5)
        assert abs(res.lower - T1) < mpmath.mpf(10) ** -100
        assert abs(res.upper - T1) < mpmath.mpf(10) ** -100
    # just off the closing the interval reopens with the two equations swapped
    below, above = boundary(3, "0.59", digits=20), boundary(3, "0.61", digits=20)
    assert below.lower < below.upper and above.lower < above.upper


@pytest.mark.parametrize("damping", ["paper", "exact"])
def test_just_above_and_below_a_threshold(damping):
    """Order 1, Q = 5: the certified threshold from :func:`verify.existence.existence`; just
    below it
    no interval (proven), just above a tiny one (both edges on the same side of the tuning is
    possible there)."""
    th = existence(1, 5, damping=damping, digits=20).thresholds[0]
    lo, hi = th.enclosure
    eps = Fraction(1, 10**12)
    below = boundary(1, lo - eps, Q=5, damping=damping, digits=20)
    above = boundary(1, hi + eps, Q=5, damping=damping, digits=20)
    assert not below.exists and below.certified
    assert above.exists and above.certified
    assert 0 < float(above.upper - above.lower) < 1e-4


def test_threshold_of_a_closing_gap_order_3():
    """Q = 7, order 3, exact model: the gap around the closing; no interval at m = 0.6, one on
    either side of the gap ends found by existence()."""
    ex = existence(3, 7, damping="exact", digits=15)
    (_, b1), (a2, _) = ex.intervals
    assert boundary(3, "0.6", Q=7).exists is False
    inside1 = Fraction(str(mpmath.nstr(b1, 15))) - Fraction(1, 10**6)
    inside2 = Fraction(str(mpmath.nstr(a2, 15))) + Fraction(1, 10**6)
    assert boundary(3, inside1, Q=7).exists and boundary(3, inside2, Q=7).exists


def _multiplier_residual(m, T, Q, damping, sigma):
    mu = floquet_multipliers(m, T, Q, damping, dps=60)
    return min(abs(x - sigma) for x in mu)


@pytest.mark.parametrize(
    "m,Q,half",
    [
        (Fraction(96, 100), Fraction(7, 10), 1),
        (Fraction(69, 100), Fraction(13, 20), 1),
        (Fraction(96, 100), Fraction(1, 10), 2),
        (Fraction(91, 100), Fraction(3, 20), 2),
    ],
)
def test_critical_damping(m, Q, half):
    """gamma = omega_i: 4 Q^2 = 1 + m (half 1) or 1 - m (half 2), exactly.  The result is continuous
    through it (Q -+ 1e-25 relative), and on its edges the Floquet route has multiplier -1."""
    assert 4 * Q * Q == (1 + m if half == 1 else 1 - m)
    at = boundary(1, m, Q=Q, digits=30)
    assert f"half {half} critical" in at.regime and at.exists and at.certified
    for s in (-1, 1):
        b = boundary(1, m, Q=Q * (1 + s * Fraction(1, 10**25)), digits=30)
        assert b.exists and "critical" not in b.regime
        assert abs(b.lower - at.lower) < 1e-20 and abs(b.upper - at.upper) < 1e-20
    with mpmath.workdps(60):
        for T in (at.lower, at.upper):
            assert _multiplier_residual(m, T, Q, "exact", -1) < mpmath.mpf(10) ** -25


@pytest.mark.parametrize(
    "n,m",
    [(1, Fraction(9, 10)), (2, Fraction(95, 100)), (3, Fraction(97, 100)), (1, Fraction(6, 10))],
)
def test_normal_and_trace_forms_agree(n, m):
    """The exact model with both halves under-damped is solved by the normal form; the trace form
    (derived separately, from the half-period propagators) must give the same edges.  Q is chosen
    with nu1 = Omega1/gamma = 0.08, where both apply."""
    from verify.solve import Request, _normal_damped, _trace_damped

    Q = mpmath_sqrt_fraction((1 + m) * (1 + Fraction(8, 100) ** 2) / 4)
    req = Request(n, m, Q, "exact", 30)
    a, b = _normal_damped(req), _trace_damped(req, ("under", "under"))
    assert a.exists and b.exists and a.certified and b.certified
    assert abs(a.lower - b.lower) <= a.radius + b.radius
    assert abs(a.upper - b.upper) <= a.radius + b.radius


def test_switch_to_trace_form_near_critical_is_seamless():
    """Across 4Q^2 - 1 - m = NEAR_CRITICAL^2 (1 + m), where the solver changes equations."""
    from verify.params import NEAR_CRITICAL, form_for

    m = Fraction(9, 10)
    Q2 = (1 + m) * (1 + Fraction(NEAR_CRITICAL) ** 2) / 4
    Qs = [mpmath_sqrt_fraction(Q2 * (1 + s * Fraction(1, 10**22))) for s in (-1, 1)]
    kinds = [form_for(m, q, "exact")[0] for q in Qs]
    assert kinds == ["trace", "normal"]
    a, b = (boundary(1, m, Q=q, digits=25) for q in Qs)
    assert abs(a.lower - b.lower) < 1e-18 and abs(a.upper - b.upper) < 1e-18


def mpmath_sqrt_fraction(x: Fraction) -> Fraction:
    """A rational close to sqrt(x) (60 digits)."""
    with mpmath.workdps(60):
        return Fraction(mpmath.nstr(mpmath.sqrt(_mp(x)), 60))


@pytest.mark.parametrize("digits", [5, 6, 15, 50, 200, 1000])
def test_digits_5_to_1000(digits):
    """Every printed digit is right: against the 1100-digit result of the same call."""
    ref = boundary(3, "0.3", digits=1100)
    b = boundary(3, "0.3", digits=digits)
    for got, want in ((b.lower, ref.lower), (b.upper, ref.upper)):
        text = mpmath.nstr(got, digits, strip_zeros=False)
        with mpmath.workdps(digits + 20):
            err = abs(mpmath.mpf(text) - want)
            assert err <= mpmath.mpf(10) ** (-digits + 1) * abs(want) * 0.51 + 0 * err, (
                digits,
                text,
            )
        assert b.radius < mpmath.mpf(10) ** (-digits) * abs(want)


def test_damped_trace_regimes_agree_with_floquet():
    """Half 1 over-damped (Q = 0.6, m = 0.9) and both halves over-damped (Q = 0.2, m = 0.83):
    the certified edges are where the Floquet multiplier is -1."""
    for m, Q in ((Fraction(9, 10), Fraction(3, 5)), (Fraction(83, 100), Fraction(1, 5))):
        b = boundary(1, m, Q=Q, digits=30)
        assert b.exists and b.certified, str(b)
        with mpmath.workdps(60):
            for T in (b.lower, b.upper):
                assert _multiplier_residual(m, T, Q, "exact", -1) < mpmath.mpf(10) ** -25
    b2 = boundary(2, Fraction(83, 100), Q=Fraction(1, 5))
    assert not b2.exists and "only order 1" in " ".join(b2.notes)


def test_grid_values_within_radius_of_float():
    ms = np.array([0.1, 0.5, 0.9])
    g = boundary_grid([2, 5], ms)
    for i, n in enumerate([2, 5]):
        for j, m in enumerate(ms):
            b = boundary(n, float(m), digits=20)
            assert abs(float(b.lower) - g[i, 0, j]) <= 1e-14 * g[i, 0, j]
