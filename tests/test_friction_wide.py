"""Certified edges with friction on wide brackets (deep modulation, ``m >= 1/2``), checked against
the monodromy matrix of :mod:`tests.pendulum_monodromy` (pure mpmath, built from the damped halves
and the jumps, not from :mod:`verify.hump` or :mod:`analytic`).

On each printed edge ``E`` with its bound ``b`` (``|printed - exact| <= b``) the largest multiplier
``|mu|max`` crosses 1: ``|mu|max - 1`` is negative at ``E -+ b`` outside the interval and positive
at ``E +- b`` inside it (and at ``E +- 3b``).  Where the engine finds no interval, ``|mu|max < 1``
over the order's bracket.  The cases are the hardest met in a check over ``m`` from 1/2 to
``1 - 1e-6``, orders 1-6 and ``Q`` from just above each threshold to ``1e6``: ``Q`` within
``1e-4`` of the threshold, both halves over-damped (the trace form, ``m = 0.99``, ``Q ~ 0.01``),
and the largest ``Q`` at 40 digits.
"""

from __future__ import annotations

import math

import mpmath
import pytest

from tests.cli_run import run_cli
from tests.pendulum_monodromy import damped_monodromy_mp, multipliers_mp
from verify.solve import boundary


def _excess(T, m, Q, damping, dps):
    """``|mu|max - 1`` of the reference monodromy at ``T`` (all arguments decimal strings)."""
    with mpmath.workdps(dps):
        M = damped_monodromy_mp(mpmath.mpf(T), mpmath.mpf(m), mpmath.mpf(Q), damping)
        return abs(multipliers_mp(M)[0]) - 1


# (order, m, Q, damping, digits): Q just above the threshold unless large
CASES = [
    (3, "0.5", "7.6", "exact", 15),
    (4, "0.75", "3.925", "exact", 40),
    (5, "0.6", "3.557", "paper", 15),
    (3, "0.9", "0.4451", "exact", 40),
    (6, "0.9", "1.635", "paper", 15),
    (5, "0.95", "0.4283", "exact", 15),
    (1, "0.99", "0.01014", "exact", 15),  # both halves over-damped: the trace form
    (1, "0.99", "0.02", "exact", 40),
    (2, "0.99", "1e6", "paper", 40),
    (6, "0.999", "1e6", "exact", 40),
]


@pytest.mark.parametrize("n, m, Q, damping, digits", CASES)
def test_edges_against_the_monodromy(n, m, Q, damping, digits):
    b = boundary(n, m, Q=Q, damping=damping, digits=digits)
    assert b.exists and b.certified
    j = b.as_json()
    dps = digits + 30
    with mpmath.workdps(dps):
        lo, hi, err = (mpmath.mpf(j[k]) for k in ("lower", "upper", "error_bound"))
        assert hi - lo > 8 * err
        for edge, inward in ((lo, 1), (hi, -1)):
            for k in (1, 3):
                assert _excess(edge + inward * k * err, m, Q, damping, dps) > 0
                assert _excess(edge - inward * k * err, m, Q, damping, dps) < 0
        assert _excess((lo + hi) / 2, m, Q, damping, dps) > 0


def test_no_interval_just_below_a_threshold():
    # order 3 at m = 0.9, exact model: the threshold is Q = 0.44505...; 0.445 is below it
    # (its bracket 0.635 < T < 0.945 borders order 2's, whose multiplier is positive: the scan
    # keeps the negative multipliers of the odd orders)
    b = boundary(3, "0.9", Q="0.445", damping="exact", digits=15)
    assert not b.exists
    worst = -1
    with mpmath.workdps(30):
        for k in range(201):
            T = mpmath.mpf("0.635") + k * mpmath.mpf("0.00155")
            mu = multipliers_mp(damped_monodromy_mp(T, mpmath.mpf("0.9"), mpmath.mpf("0.445")))[0]
            if mpmath.re(mu) < 0:
                worst = max(worst, abs(mu) - 1)
    assert -0.01 < worst < 0  # close to the threshold, yet below it


#: (m, Q) with both halves over-damped where the order-1 window lies past the double range
#: (``cosh(2 zeta)`` overflows before its tail bound holds; ``zeta`` up to about 1000): refused
#: before as "not decided"; the float stage now takes ``D exp(-2 zeta)``
#: (:func:`verify.derived.trace_indicator_scaled`).  The last one is a narrow interval just above
#: the threshold in ``Q`` at ``m = 0.999``.
OVERDAMPED_PAST_DOUBLES = [
    ("0.9992", "0.001"),
    ("0.9993", "0.001"),
    ("0.9995", "0.001"),
    ("0.9997", "0.001"),
    ("0.9996", "0.0005"),
    ("0.9999", "0.0005"),
    ("0.999", "0.002"),
    ("0.9993", "0.002"),
    ("0.999", "0.0010018469107664705"),
]


@pytest.mark.parametrize("digits", [15, 40])
@pytest.mark.parametrize("m, Q", OVERDAMPED_PAST_DOUBLES)
def test_over_damped_window_past_double_range_against_the_monodromy(m, Q, digits):
    b = boundary(1, m, Q=Q, damping="exact", digits=digits)
    assert b.exists and b.certified and not b.notes
    j = b.as_json()
    assert "half 1 over, half 2 over" in j["regime"]
    dps = digits + 45  # (the reference's entries reach exp(+-1000): relative digits suffice)
    with mpmath.workdps(dps):
        lo, hi, err = (mpmath.mpf(j[k]) for k in ("lower", "upper", "error_bound"))
        assert hi - lo > 8 * err
        assert _excess((lo + hi) / 2, m, Q, "exact", dps) > 0
        for edge, inward in ((lo, 1), (hi, -1)):
            assert _excess(edge + inward * 3 * err, m, Q, "exact", dps) > 0
            assert _excess(edge - inward * 3 * err, m, Q, "exact", dps) < 0


def test_over_damped_window_past_double_range_no_interval():
    # just below the threshold in m at Q = 0.001 (between 0.99900175 and 0.999002), where the
    # bound by log-convexity does not decide: D exp(-2 zeta) < 0 on the whole window, proven on
    # balls (refused before); the reference monodromy agrees, |mu|max - 1 about -3.2e-4 at most
    b = boundary(1, "0.99900175", Q="0.001", digits=15)
    assert not b.exists and b.certified and not b.notes
    with mpmath.workdps(40):
        for i in range(121):  # over the interval of m = 0.999002 and beyond it
            T = mpmath.mpf("0.0022") + i * mpmath.mpf("0.00001")
            assert _excess(T, "0.99900175", "0.001", "exact", 40) < 0


def test_over_damped_window_past_double_range_answers(capsys):
    # m = 0.999 just above the threshold in Q: the window's tail bound lies where exp(2 zeta) has
    # no double; refused before, answered from the scaled form (as the table, below)
    code, out, err = run_cli(
        capsys, "boundary", "--order", "1", "--m", "0.999", "--Q", "0.0010018469107664705"
    )
    assert code == 0 and err == ""
    assert "lower T/T0 = 0.002558809698429" in out and "upper T/T0 = 0.002738561494758" in out
    assert "half 1 over, half 2 over" in out and "not certified" not in out


def test_over_damped_window_past_double_range_from_the_float_stage():
    from fractions import Fraction

    from verify.derived import backend, trace_indicator_scaled
    from verify.float_roots import NOISE_ULPS, damped_trace, trace_window_ends
    from verify.params import trace_params

    # the plain float stage overflows; the scaled one gives the window and the edges in zeta
    # (T = 2 Q zeta/pi), with the same signs and no overflow; its rounding bound (zeta ~ 500
    # times the rounding of the exponents) is above DOUBT, which sends the double grid to the
    # certified route, and holds the edges' actual errors (1.7e-14 at the upper edge)
    T = trace_params(Fraction(1999, 2000), Fraction(1, 1000), backend("math"))
    with pytest.raises(OverflowError):
        trace_window_ends(1, ("over", "over"), T)
    window = trace_window_ends(1, ("over", "over"), T, scaled=True)
    assert window is not None and window[1] > 400
    got = damped_trace(1, ("over", "over"), T, window, scaled=True)
    assert got["dtop"] > 0 and got["doubt"]
    b = boundary(1, "0.9995", Q="0.001", digits=20)
    scale = 2 * 0.001 / math.pi  # T/T0 = 2 Q zeta/pi
    form = trace_indicator_scaled("over", "over")
    sizes, d01 = form.compiled("math", (4, 5)), form.compiled("math", (0, 1))
    args = (-1.0, float(T.kappa), float(T.nu1), float(T.nu2))
    for z, edge in ((got["lo"], b.as_json()["lower"]), (got["hi"], b.as_json()["upper"])):
        total, slope = sizes(z, *args)
        noise = NOISE_ULPS * 2.0**-53 * (total + z * slope)
        estimate = noise / abs(d01(z, *args)[1]) / z  # the relative error damped_trace bounds
        assert abs(z * scale / float(edge) - 1) < min(estimate, 1e-12)


def test_paper_model_past_double_range_is_refused(capsys):
    # the paper's model at m = 1 - 1e-6 and Q near 1e-6: the float stage's values of the normal
    # form overflow; the engine says it cannot decide instead of failing
    code, out, err = run_cli(
        capsys,
        "boundary",
        "--order",
        "1",
        "--m",
        "0.999999",
        "--Q",
        "1.0669502220605025e-06",
        "--damping",
        "paper",
    )
    assert code == 2 and out == ""
    assert err.startswith("paramres: error: ") and "not decided" in err


def test_table_past_double_range_is_refused(capsys):
    # the double grid at the paper model's point above: the certified route is asked, and refuses
    code, out, err = run_cli(
        capsys,
        "table",
        "--orders",
        "1",
        "--m",
        "0.999999:0.999999:0.1",
        "--Q",
        "1.0669502220605025e-06",
        "--damping",
        "paper",
    )
    assert code == 2
    assert err.startswith("paramres: error: ") and "not decided" in err
    # m = 0.999999 lies inside the double grid's range: the refusal does not say it lies outside
    assert "outside the double grid" not in err
    assert "the double grid cannot bound its error there" in err


def test_table_past_double_range_over_damped(capsys):
    # the double grid's trace form at m = 0.999 past the double range: the certified route is
    # asked, and answers (refused before)
    code, out, err = run_cli(
        capsys, "table", "--orders", "1", "--m", "0.999:0.999:0.1", "--Q", "0.0010018469107664705"
    )
    assert code == 0
    assert out.splitlines()[-1] == "1,0.999,0.002558809698429,0.002738561494758"


@pytest.mark.parametrize("kappa", ["-1000", "-3", "-0.1", "0.1", "3", "1000"])
@pytest.mark.parametrize("nu1, nu2", [("0.05", "0.9"), ("0.5", "0.5"), ("0.99", "0.005")])
def test_the_tail_bound_of_the_overdamped_window_holds(kappa, nu1, nu2):
    """Beyond the end the window's proof accepts (both halves over-damped, either sign sigma of
    the multiplier, either sign of kappa), ``D < 0``: checked in mpmath at 40 digits from the
    bound's own end ``zeta*`` (where ``max(2, 1 + k) exp(-a zeta*) = 1``) to ``zeta* + 40/a``,
    on ``D = sigma (2 C1 C2 - kappa S1 S2) - 2 cosh(2 zeta)`` with ``C = cosh(nu zeta)``, ``S =
    sinh(nu zeta)/nu`` (the over-damped half, :func:`verify.derived.half_period_forms`)."""
    with mpmath.workdps(40):
        k_, n1, n2 = mpmath.mpf(kappa), mpmath.mpf(nu1), mpmath.mpf(nu2)
        a = 2 - n1 - n2
        k = abs(k_) / (2 * n1 * n2)
        start = mpmath.log(max(2, 1 + k)) / a  # the proof's condition holds just beyond
        for i in range(1, 401):
            z = start * (1 + mpmath.mpf(i) / 10**6) + i * (40 / a) / 400
            C1, C2 = mpmath.cosh(n1 * z), mpmath.cosh(n2 * z)
            S1, S2 = mpmath.sinh(n1 * z) / n1, mpmath.sinh(n2 * z) / n2
            for sigma in (1, -1):
                assert sigma * (2 * C1 * C2 - k_ * S1 * S2) - 2 * mpmath.cosh(2 * z) < 0


@pytest.mark.parametrize("k", ["-50", "-1.5", "-1", "-0.3", "0", "1", "2.5", "3"])
@pytest.mark.parametrize(
    "nu1, nu2", [("0.05", "0.9"), ("0.5", "0.5"), ("0.9999", "0.98"), ("0.99", "0.005")]
)
def test_overdamped_order_one_has_no_interval_where_kappa_is_small(k, nu1, nu2):
    """:func:`verify.hump.overdamped_no_interval`: with both halves over-damped and ``kappa <= 6
    nu1 nu2`` (``k = kappa/(2 nu1 nu2) <= 3``), ``D < 0`` for order 1 (``sigma = -1``) at every
    ``zeta``: checked in mpmath at 40 digits on ``D = -(2 C1 C2 - kappa S1 S2) - 2 cosh(2 zeta)``
    over ``zeta`` from 1e-6 to 200 (a geometric grid), and the function says so for these
    parameters (as balls)."""
    from flint import arb

    from verify.hump import overdamped_no_interval
    from verify.params import TraceParams

    with mpmath.workdps(40):
        n1, n2 = mpmath.mpf(nu1), mpmath.mpf(nu2)
        kap = mpmath.mpf(k) * 2 * n1 * n2
        for i in range(600):
            z = mpmath.mpf(10) ** (-6 + 8.3 * i / 599)
            C1, C2 = mpmath.cosh(n1 * z), mpmath.cosh(n2 * z)
            S1, S2 = mpmath.sinh(n1 * z) / n1, mpmath.sinh(n2 * z) / n2
            assert -(2 * C1 * C2 - kap * S1 * S2) - 2 * mpmath.cosh(2 * z) < 0
    if k != "3":  # (at k = 3 exactly the balls' comparison is not decided)
        p = TraceParams(arb(mpmath.nstr(kap, 30)), arb(nu1), arb(nu2), None, None)
        assert overdamped_no_interval(p)


def _scaled_max_of_D(k: str, nu1: str, nu2: str) -> mpmath.mpf:
    """The largest ``D / cosh(2 zeta)`` of order 1 (both halves over-damped) over ``zeta`` from
    1e-4 to 1e5 (a geometric grid of 800), in mpmath at 40 digits; ``kappa = 2 k nu1 nu2``."""
    with mpmath.workdps(40):
        n1, n2 = mpmath.mpf(nu1), mpmath.mpf(nu2)
        kap = mpmath.mpf(k) * 2 * n1 * n2
        best = -mpmath.inf
        for i in range(800):
            z = mpmath.mpf(10) ** (-4 + 9 * i / 799)
            C1, C2 = mpmath.cosh(n1 * z), mpmath.cosh(n2 * z)
            S1, S2 = mpmath.sinh(n1 * z) / n1, mpmath.sinh(n2 * z) / n2
            D = -(2 * C1 * C2 - kap * S1 * S2) - 2 * mpmath.cosh(2 * z)
            best = max(best, D / mpmath.cosh(2 * z))
        return best


@pytest.mark.parametrize(
    "k, nu1, nu2, proven",
    [
        ("3.004", "0.999999", "0.998", True),  # m = 0.999, Q = 0.001: s = 1.998
        ("3.0009", "0.9999", "0.9999", True),  # s = 1.9998: up to about 1 + 4/s = 3.0002, and on
        ("3.3", "0.95", "0.9", True),
        ("5", "0.5", "0.5", True),  # a <= 1: (k - 1) s/4 = 1
        ("3.01", "0.9999", "0.9999", False),  # D > 0 at large zeta: an interval
        ("4.2", "0.9", "0.88", False),  # D < 0, but beyond what the bound proves
    ],
)
def test_overdamped_bound_by_log_convexity(k, nu1, nu2, proven):
    """Above ``k = 3`` (``kappa > 6 nu1 nu2``) :func:`verify.hump.overdamped_no_interval` proves
    ``D < 0`` by ``cosh(s zeta) <= cosh(2 zeta)**(s/2)`` where that bound reaches: it says so
    only where the scaled ``D / cosh(2 zeta)`` is negative at every ``zeta`` of a grid from 1e-4
    to 1e5 (mpmath, 40 digits), and not where it is positive somewhere."""
    from flint import arb

    from verify.hump import overdamped_no_interval
    from verify.params import TraceParams

    top = _scaled_max_of_D(k, nu1, nu2)
    kap = mpmath.mpf(k) * 2 * mpmath.mpf(nu1) * mpmath.mpf(nu2)
    p = TraceParams(arb(mpmath.nstr(kap, 30)), arb(nu1), arb(nu2), None, None)
    got = overdamped_no_interval(p)
    assert bool(got) == proven
    if got:
        assert top < 0 and "log-convexity" in got
    if k == "3.01":
        assert top > 0


def test_overdamped_near_one_at_a_tiny_quality_factor():
    """``m = 0.999``, ``Q = 0.001`` (``k = 3.004``, ``s = 1.998``): refused before (the trace
    form's window reached beyond the doubles); now no interval, certified by the bound by
    log-convexity, and the reference monodromy agrees: ``|mu|max < 1`` at 120 periods from
    ``T/T0 = 1e-3`` to 30 (a geometric grid)."""
    b = boundary(1, "0.999", Q="0.001", digits=15)
    assert not b.exists and b.certified
    assert any("log-convexity" in note for note in b.notes)
    for i in range(120):
        T = mpmath.nstr(mpmath.mpf(10) ** (-3 + 4.5 * i / 119), 15)
        assert _excess(T, "0.999", "0.001", "exact", 30) < 0


def test_overdamped_criterion_is_not_met_where_an_interval_exists():
    """At ``m = 0.99``, ``Q = 0.0102`` the order-1 interval exists (``|mu|max > 1`` inside it, by
    the reference monodromy) and ``k = kappa/(2 nu1 nu2)`` is about 3.2: the criterion does not
    hold there; a ``k`` just above 3 with ``D > 0`` somewhere exists, so the bound 3 is not far
    from the truth."""
    from fractions import Fraction

    from flint import ctx

    from verify.derived import backend
    from verify.hump import overdamped_no_interval
    from verify.params import trace_params

    b = boundary(1, "0.99", Q="0.0102", digits=15)
    assert b.exists
    j = b.as_json()
    mid = (mpmath.mpf(j["lower"]) + mpmath.mpf(j["upper"])) / 2
    assert _excess(mpmath.nstr(mid, 20), "0.99", "0.0102", "exact", 40) > 0
    old = ctx.prec
    ctx.prec = 64
    try:
        assert not overdamped_no_interval(
            trace_params(Fraction(99, 100), Fraction(51, 5000), backend("arb"))
        )
    finally:
        ctx.prec = old


#: depths where both halves are over-damped at Q = 0.0102 (order 1): up to m = 0.9897 the
#: criterion holds (the trace form's maximum is below 0); m = 0.985 to 0.9897 were refused before
#: as "too close to a threshold" (the threshold lies between 0.9897 and 0.99)
OVERDAMPED_NONE = ["0.01", "0.5", "0.985", "0.989", "0.9897"]


@pytest.mark.parametrize("m", OVERDAMPED_NONE)
def test_overdamped_no_interval_against_the_monodromy(m):
    """``boundary`` finds no interval of order 1, certified, and the reference monodromy agrees:
    ``|mu|max < 1`` at 300 periods from ``T/T0 = 1e-3`` to 30 (a geometric grid)."""
    b = boundary(1, m, Q="0.0102", digits=15)
    assert not b.exists and b.certified
    assert any("kappa <= 6 nu1 nu2" in note for note in b.notes)
    for i in range(300):
        T = mpmath.nstr(mpmath.mpf(10) ** (-3 + 4.5 * i / 299), 15)
        assert _excess(T, m, "0.0102", "exact", 30) < 0


def test_existence_decides_the_overdamped_depths():
    """``existence --order 1 --Q 0.0102`` left every depth undecided; now no depth below ``m =
    0.98`` is undecided, and what it finds lies where the reference has ``|mu|max > 1``."""
    from fractions import Fraction

    from verify.existence import existence

    ex = existence(1, "0.0102", digits=15)
    assert all(lo >= Fraction(98, 100) for lo, _ in ex.undecided)
    assert all(sign == -1 for _, hi, sign in ex.segments if hi <= Fraction(98, 100))
    found = [lo for lo, _, sign in ex.segments if sign == 1]
    assert found
    for lo in found:
        assert lo > Fraction(98, 100)
        m = mpmath.nstr(mpmath.mpf(lo.numerator) / lo.denominator, 20)
        b = boundary(1, m, Q="0.0102", digits=15)
        assert b.exists
        j = b.as_json()
        mid = (mpmath.mpf(j["lower"]) + mpmath.mpf(j["upper"])) / 2
        assert _excess(mpmath.nstr(mid, 20), m, "0.0102", "exact", 40) > 0


def test_a_system_built_directly_keeps_the_model_ranges():
    """The bound ``kappa <= 6 nu1 nu2`` needs ``nu1 + nu2 < 2``, true because an over-damped
    phase with ``omega_i^2 > 0`` has ``nu_i < 1``.  A ``System`` built directly (not by
    ``custom``) with ``omega1^2 = -75``, ``omega2^2 = 25/2``, ``k = 1/16`` at ``Q = 0.1`` has
    both phases "over-damped" with ``nu1 = 2`` and ``kappa/(2 nu1 nu2)`` about 2, and its
    monodromy a multiplier near ``-1.6e14`` at ``T = 3``: no longer a member of the family, it is
    refused when built (else ``boundary`` would call its order 1 empty), as are a duty outside
    ``(0, 1)`` and a jump ``k <= 0``."""
    from fractions import Fraction

    from analytic.system import System
    from paramres.inputs import InputError

    half = Fraction(1, 2)
    with pytest.raises(InputError, match="omega\\^2 = -75 is not positive"):
        System("custom", half, (Fraction(-75), Fraction(25, 2)), Fraction(1, 16))
    with pytest.raises(InputError, match="omega\\^2 = 0 is not positive"):
        System("custom", half, (Fraction(1), Fraction(0)), Fraction(1))
    with pytest.raises(InputError, match="jump k = -1 is not positive"):
        System("custom", half, (Fraction(1), Fraction(2)), Fraction(-1))
    with pytest.raises(InputError, match="outside the allowed range 0 < D < 1"):
        System("pendulum", Fraction(3, 2))
    with pytest.raises(InputError, match="needs omega_sq"):
        System("custom", half)
    with pytest.raises(InputError, match="is not one of"):
        System("pendulm", half)
    with mpmath.workdps(30):  # the multiplier of that system, from the ODE (pure mpmath)
        g, T = mpmath.pi / mpmath.mpf("0.1"), mpmath.mpf(3)

        def U(w2, t):
            W = mpmath.sqrt(g * g - w2)
            c, s = mpmath.cosh(W * t), mpmath.sinh(W * t) / W
            e = mpmath.exp(-g * t)
            return mpmath.matrix([[e * (c + g * s), e * s], [-w2 * e * s, e * (c - g * s)]])

        four_pi2, k = 4 * mpmath.pi**2, mpmath.mpf(1) / 16
        M = (
            mpmath.matrix([[1, 0], [0, 1 / k]])
            * U(four_pi2 * mpmath.mpf("12.5"), T / 2)
            * mpmath.matrix([[1, 0], [0, k]])
            * U(-four_pi2 * 75, T / 2)
        )
        assert mpmath.re(multipliers_mp(M)[0]) < -1e13


@pytest.mark.parametrize("Q, lo, hi", [("0.05", "0.953", "0.989"), ("0.2", "0.828", "0.839")])
def test_existence_proves_the_overdamped_interval_over_depth_ranges(Q, lo, hi):
    """Both halves over-damped, order 1, where the interval exists: ``existence`` proves it over
    ranges of depths (the window's start taken inside ``P > 0`` for the whole range; at ``Q =
    0.05`` it left ``0.9485 < m < 0.990`` undecided before, at ``Q = 0.2`` ``0.79 < m < 0.84``),
    and the reference monodromy has ``|mu|max > 1`` inside the edges ``boundary`` gives at the
    ends and the middle of the range asked for."""
    from fractions import Fraction

    from verify.existence import existence

    ex = existence(1, Q, digits=15)
    a, b = Fraction(lo), Fraction(hi)
    # every segment meeting [lo, hi] says the interval exists there
    meeting = [sign for x, y, sign in ex.segments if x < b and y > a]
    assert meeting and all(sign == 1 for sign in meeting)
    for m in (lo, hi, mpmath.nstr((mpmath.mpf(lo) + mpmath.mpf(hi)) / 2, 15)):
        bd = boundary(1, m, Q=Q, digits=15)
        assert bd.exists
        j = bd.as_json()
        mid = (mpmath.mpf(j["lower"]) + mpmath.mpf(j["upper"])) / 2
        assert _excess(mpmath.nstr(mid, 20), m, Q, "exact", 40) > 0


def _D_trace_order_one(k, nu1, nu2, z):
    """The trace form's ``D`` of order 1 with both halves over-damped, in mpmath from its
    definition (``C_i = cosh(nu_i z)``, ``S_i = sinh(nu_i z)/nu_i``, ``kappa = 2 k nu1 nu2``)."""
    C1, C2 = mpmath.cosh(nu1 * z), mpmath.cosh(nu2 * z)
    S1, S2 = mpmath.sinh(nu1 * z) / nu1, mpmath.sinh(nu2 * z) / nu2
    return -(2 * C1 * C2 - 2 * k * nu1 * nu2 * S1 * S2) - 2 * mpmath.cosh(2 * z)


def test_overdamped_beyond_holds_past_the_last_zero_and_only_there():
    """:func:`verify.hump.overdamped_beyond` (``D < 0`` from ``z`` on, both halves over-damped,
    order 1) against ``D`` in mpmath (40 digits): where ``D`` has a last zero ``z0`` (an interval
    exists; below ``zeta = 90``), it does not claim at ``0.999 z0`` and does claim at ``1.001
    z0``; wherever it claims, ``D < 0`` on a grid from ``z`` to ``z + 400``."""
    import random
    from types import SimpleNamespace

    from flint import arb, ctx

    from verify.hump import overdamped_beyond

    rng = random.Random(11)
    claims = 0
    with mpmath.workdps(40):
        for _ in range(60):
            nu1 = mpmath.mpf(rng.uniform(0.3, 0.999))
            nu2 = mpmath.mpf(rng.uniform(0.3, min(0.999, 1.999 - float(nu1))))
            k = mpmath.mpf(10 ** rng.uniform(0.3, 4))
            p = SimpleNamespace(
                nu1=arb(mpmath.nstr(nu1, 40)),
                nu2=arb(mpmath.nstr(nu2, 40)),
                kappa=arb(mpmath.nstr(2 * k * nu1 * nu2, 40)),
            )
            grid = [mpmath.mpf(j) / 20 for j in range(1, 2000)]
            positive = [z for z in grid if _D_trace_order_one(k, nu1, nu2, z) >= 0]
            if positive and positive[-1] > 90:  # D > 0 up to the grid's end: no last zero seen
                continue
            old, ctx.prec = ctx.prec, 64
            try:
                if positive:  # the last zero, by bisection
                    a, b = positive[-1], positive[-1] + mpmath.mpf(1) / 20
                    for _ in range(120):
                        c = (a + b) / 2
                        a, b = (c, b) if _D_trace_order_one(k, nu1, nu2, c) >= 0 else (a, c)
                    assert not overdamped_beyond(p, float(b * mpmath.mpf("0.999")))
                    assert overdamped_beyond(p, float(b * mpmath.mpf("1.001")))
                z = rng.uniform(0.05, 20)
                if overdamped_beyond(p, z):
                    claims += 1
                    for j in range(400):
                        assert _D_trace_order_one(k, nu1, nu2, z + mpmath.mpf(j)) < 0
            finally:
                ctx.prec = old
    assert claims > 10


@pytest.mark.parametrize(
    "Q, below, above",
    [("0.1", "0.9080637255058", "0.9080637255059"), ("0.05", "0.9523483356125", "0.9523483356126")],
)
def test_existence_pins_the_overdamped_threshold(Q, below, above):
    """Both halves over-damped, order 1: was undecided over ``0.9051 < m < 0.9081`` (``Q =
    0.1``) and ``0.95179 < m < 0.95235`` (``Q = 0.05``), where ``boundary`` decides every depth:
    over a range of depths the proof that ``D < 0`` right of the maximiser bisected up to the
    window's tail bound (``D`` there a difference of cosh terms a hundred million times larger),
    and left of it ran out of pieces.  Now the threshold is pinned to 15 digits, between two
    depths 1e-13 apart that the certified boundary decides apart, and it is the only undecided
    thing below the regime change at ``m = 1 - 4 Q^2``."""
    from fractions import Fraction

    from verify.existence import existence

    ex = existence(1, Q, digits=15)
    (t,) = ex.thresholds
    lo, hi = t.enclosure
    assert Fraction(below) < lo and hi < Fraction(above) and t.appears
    assert not boundary(1, below, Q=Q, digits=20).exists
    assert boundary(1, above, Q=Q, digits=20).exists
    change = 1 - 4 * Fraction(Q) ** 2
    assert all(abs(x - change) < Fraction(1, 10**14) for x, _ in ex.undecided)


def test_taylor_ball_holds_the_sides_ends_and_the_point_of_expansion():
    """:func:`verify.hump.taylor_negative` bounds ``D`` on a ball ``X`` and proves the sides
    ``[a, lo]`` and ``[hi, b]`` apart: ``X`` must hold ``[lo, hi]`` and the point where ``D(t)``,
    ``D'(t)`` were taken.  Was: a ball around the float middle of ``[lo, hi]`` with its half
    width, which misses ``lo`` (here ``a`` itself, whose side is empty) by half a unit in the last
    place where ``hi - lo`` is three units, and the point of expansion where it is not the
    float ``t``."""
    import math

    from flint import arb

    from verify.hump import _Hump, taylor_negative

    u = 2.0**-52
    seen = []

    def d2D(X):
        seen.append(X)
        return arb(-1)

    a = 1.5
    h = _Hump(
        D=lambda x: arb(-1),
        dD=lambda x: arb(0),
        d2D=d2D,
        a=a,
        b=a + 8 * u,
        top=a + u,
        dtop=-1.0,
        lo=math.nan,
        hi=math.nan,
        floor=0.0,
    )
    assert taylor_negative(h, a + u, arb(-1), arb(0), 1, 64, 10)
    (X,) = seen
    for x in (arb(a), arb(a + 3 * u), arb(a + u)):  # lo = a, hi = t + rho = a + 3 u
        assert X.contains(x)
    at = arb(a + u) + arb(2) ** -60  # (not a float)
    assert taylor_negative(h, a + u, arb(-1), arb(0), 1, 64, 10, at=at)
    assert seen[-1].contains(at)
