"""The double-precision grid in its hard regions: ``1 - m`` down to the last double below 1, ``m``
down to 1e-300, and exact depths closer to 1 than a double can say.

Reference: the certified :func:`verify.solve.boundary` at the exact depth of each point (its digits
are proven by ball arithmetic; it never uses the grid's values), at 20 digits, or more where it asks
for more.  The claim checked is the one stated in :func:`verify.grid.boundary_grid`: every finite
entry within a relative :data:`verify.grid.ERROR_BOUND` of the exact edge, NaN exactly where the
interval does not exist.  Depths are log-spaced with a fixed seed towards both ends (``1 - m``
from 1e-1 to 1e-16, ``m`` from 1e-1 to 1e-300), in the style of SciPy's hard-region tests; a
failure lists every bad point with both values and their relative difference.
"""

from __future__ import annotations

from fractions import Fraction

import numpy as np
import pytest

from reports.cli import main
from verify.certify import CertificationError
from verify.grid import ERROR_BOUND, boundary_grid
from verify.solve import boundary

#: orders 1-6 and a few high ones
ORDERS = [1, 2, 3, 4, 5, 6, 17, 100]
#: no friction; Q = 7 in both models; Q = 0.4 (both halves over-damped for m < 0.36, half 1 always)
MODELS = [(None, "exact"), (7, "paper"), (7, "exact"), (Fraction(2, 5), "exact")]
#: the last double below 1
LAST = float(np.nextafter(1.0, 0.0))


def _certified(n, m, Q, damping):
    for digits in (20, 40, 80):
        try:
            return boundary(n, m, Q=Q, damping=damping, digits=digits)
        except CertificationError:
            continue
    raise AssertionError(f"no certified reference for order {n}, m = {m}, Q = {Q}, {damping}")


def _compare(orders, ms, grid, Q, damping):
    """Every disagreement of ``grid`` (shape ``(len(orders), 2, len(ms))``) with the certified
    edges at the exact depths ``ms``, as text lines."""
    bad = []
    for i, n in enumerate(orders):
        for j, m in enumerate(ms):
            b = _certified(n, m, Q, damping)
            om = float(1 - Fraction(m))
            where = f"order {n}, m = {m!r} (1 - m = {om:.3e}), Q = {Q} {damping}"
            if not b.exists:
                if not np.isnan(grid[i, :, j]).all():
                    bad.append(f"{where}: grid {grid[i, :, j]}, certified: no interval")
                continue
            for k, want in ((0, b.lower), (1, b.upper)):
                got, want = grid[i, k, j], float(want)
                rel = abs(got - want) / abs(want) if np.isfinite(got) else np.inf
                if not rel <= ERROR_BOUND:
                    edge = "lower" if k == 0 else "upper"
                    bad.append(f"{where}, {edge}: grid {got!r}, certified {want!r}, rel {rel:.2e}")
    return bad


def _assert_grid(orders, ms, Q, damping):
    grid = boundary_grid(orders, ms, Q=Q, damping=damping)
    assert grid.shape == (len(orders), 2, len(ms))
    bad = _compare(orders, ms, grid, Q, damping)
    assert not bad, f"{len(bad)} bad points:\n" + "\n".join(bad)


def _near_one(seed, count):
    """Doubles ``m`` with ``1 - m`` log-uniform in (1e-16, 1e-1), and the last double below 1."""
    rng = np.random.default_rng(seed)
    ms = 1 - 10.0 ** rng.uniform(-16, -1, count)
    ms = np.where(ms < 1, ms, LAST)
    return np.sort(np.concatenate([ms, [LAST]]))


def _near_zero(seed, count):
    rng = np.random.default_rng(seed)
    return np.sort(10.0 ** rng.uniform(-300, -1, count))


# ---------------------------------------------------------------------------------------------
# the findings, verbatim


def test_order1_lower_edge_near_one_is_positive_and_right():
    """Was -8.4479e-06.  At the binary value of the float (``Fraction(0.9999999999821584)``) the
    true value is 8.0315494785835133163e-12; a float passed to the API means its shortest decimal,
    0.9999999999821584, where it is 8.03154179319819e-12 (both: certified route, 20 digits,
    `paramres boundary --order 1 --m ... --digits 20`)."""
    g = boundary_grid([1], [Fraction(0.9999999999821584)])
    assert abs(g[0, 0, 0] - 8.0315494785835133163e-12) <= ERROR_BOUND * 8.0315494785835133163e-12
    assert 0 < g[0, 0, 0] < g[0, 1, 0]
    g = boundary_grid([1], [0.9999999999821584])
    assert abs(g[0, 0, 0] - 8.03154179319819e-12) <= 1e-13 * 8.03154179319819e-12
    assert 0 < g[0, 0, 0] < g[0, 1, 0]


@pytest.mark.parametrize("Q, damping", MODELS[1:])
def test_order1_lower_edge_near_one_with_friction(Q, damping):
    """With friction the same edge gave lower > upper and negative periods."""
    ms = [0.9999999999821584, 0.99999999998885, 1 - 3.3204661242791644e-11, LAST]
    _assert_grid([1], np.array(ms), Q, damping)


def test_table_prints_the_certified_edge_near_one(capsys):
    """``paramres table`` printed -1.862688732479e-10 here; ``paramres boundary`` gives
    5.019263462585e-12 (certified route)."""
    code = main(["table", "--orders", "1", "--m", "0.99999999998885:0.99999999998885:0.1"])
    out = capsys.readouterr().out
    assert code == 0
    row = out.splitlines()[1].split(",")
    assert row[:3] == ["1", "0.99999999998885", "5.019263462585e-12"]
    assert row[3] == "3.339161571413e-6"


@pytest.mark.parametrize("m", ["0.99999", "0.999999999", "0.9999999999999", "0.99999999999999999"])
def test_table_computes_at_the_depth_it_prints(capsys, m):
    """A row labelled with the decimal depth is computed at that depth, not at ``float(m)``: near
    ``m = 1`` the rounding of ``float(m)`` is amplified by ``1/(1 - m)`` (was a relative 4.5e-12
    at 0.99999 and 2.8e-8 at 0.999999999).  Every printed digit (13) against the certified edges
    at the exact decimal depth."""
    code = main(["table", "--orders", "1-3", "--m", f"{m}:{m}:1"])
    out = capsys.readouterr().out
    assert code == 0
    rows = [line.split(",") for line in out.splitlines()[1:]]
    for order, label, lower, upper in rows:
        assert label == m
        b = _certified(int(order), m, None, "exact")
        for text, want in ((lower, b.lower), (upper, b.upper)):
            # 13 significant digits: off by at most half a unit of the last one, plus the grid's
            # error bound (a value within that bound of a rounding boundary may round either way)
            got, want = float(text), float(want)
            unit = 10.0 ** (np.floor(np.log10(abs(want))) - 12)
            assert abs(got - want) <= 0.5 * unit + ERROR_BOUND * abs(want), (order, text, want)


# ---------------------------------------------------------------------------------------------
# log-spaced sweeps


def _count(Q, damping):
    """Sample sizes: smaller with Q = 7, where each certified reference near ``m = 1`` costs
    about half a second."""
    return 12 if Q is None or Q < 1 else 5


@pytest.mark.slow
@pytest.mark.parametrize("Q, damping", MODELS)
def test_sweep_towards_m_one(Q, damping):
    _assert_grid(ORDERS, _near_one(17, _count(Q, damping)), Q, damping)


@pytest.mark.parametrize("Q, damping", MODELS)
def test_sweep_towards_m_zero(Q, damping):
    _assert_grid(ORDERS, _near_zero(18, 12), Q, damping)


@pytest.mark.slow
@pytest.mark.parametrize("Q, damping", MODELS)
def test_exact_depths_near_one(Q, damping):
    """Exact decimal depths: ``1 - m`` is computed from the exact depth, also where ``float(m)``
    rounds it off entirely (``1 - m < 2**-53`` is served by the certified route)."""
    rng = np.random.default_rng(19)
    ks = np.sort(rng.uniform(1, 16, _count(Q, damping)))
    ms = [1 - Fraction(f"{10.0**-k:.6e}") for k in ks]
    ms += [1 - Fraction(1, 10**17), 1 - Fraction(1, 10**20)]
    _assert_grid([1, 2, 3, 6], ms, Q, damping)


# ---------------------------------------------------------------------------------------------
# thresholds and closing gaps: the edges meet in a double root of the indicator


def _threshold(n, Q, damping, lo, hi):
    """The depth where the interval appears or vanishes between the doubles ``lo`` and ``hi``
    (the certified route's existence differs there), by bisection to adjacent doubles."""
    has_lo = _certified(n, lo, Q, damping).exists
    assert _certified(n, hi, Q, damping).exists != has_lo
    while np.nextafter(lo, hi) != hi:
        mid = 0.5 * (lo + hi)
        if _certified(n, mid, Q, damping).exists == has_lo:
            lo = mid
        else:
            hi = mid
    return lo


@pytest.mark.parametrize(
    "n, Q, damping, lo, hi",
    [
        (1, 7, "paper", 0.05, 0.1),  # threshold m_min ~ pi/(6Q)
        (2, 7, "exact", 0.2, 0.4),  # threshold ~ sqrt(2/(3Q))
        (3, 7, "exact", 0.4, 0.55),  # the island of Fig. 8 vanishes near 0.48
        (1, Fraction(2, 5), "exact", 0.6, 0.8),  # over-damped halves: the trace form
    ],
)
def test_next_to_a_threshold(n, Q, damping, lo, hi):
    """Within a relative 1e-14 .. 1e-2 of a threshold the edges are a near-double root of the
    indicator, and double precision cannot place them to 1e-14 (the double path lost up to 1e-10
    there); such entries are escalated to the certified route, and NaN is right on the other
    side."""
    m0 = _threshold(n, Q, damping, lo, hi)
    ks = np.arange(2, 15, 2.0)
    ms = np.concatenate([m0 * (1 + 10.0**-ks), m0 * (1 - 10.0**-ks), [m0, np.nextafter(m0, 1)]])
    _assert_grid([n], np.sort(ms), Q, damping)


def _assert_family_grid(orders, ms, Q, damping, sysv):
    """:func:`_assert_grid` for another member of the family (certified reference with the same
    ``system``)."""
    grid = boundary_grid(orders, ms, Q=Q, damping=damping, system=sysv)
    bad = []
    for i, n in enumerate(orders):
        for j, m in enumerate(ms):
            b = boundary(n, m, Q=Q, damping=damping, system=sysv, digits=20)
            if not b.exists:
                if not np.isnan(grid[i, :, j]).all():
                    bad.append((n, m, "grid has an interval, certified has none"))
                continue
            for k, want in ((0, b.lower), (1, b.upper)):
                rel = abs(grid[i, k, j] - float(want)) / float(want)
                if not rel <= ERROR_BOUND:
                    bad.append((n, m, k, grid[i, k, j], want, rel))
    assert not bad, bad


def test_next_to_a_threshold_torsion_duty_third():
    """Torsion, duty 1/3, paper model, Q = 7: the order-2 interval appears between m = 0.375 and
    0.385 (located on a coarse grid); within a relative 1e-12 .. 1e-2 of the threshold (found by
    bisection on the certified route) the grid meets the bound or is NaN where the certified
    route says no interval."""
    from analytic.system import system

    sysv = system("torsion", duty="1/3")
    lo, hi = 0.375, 0.385
    has_lo = boundary(2, lo, Q=7, damping="paper", system=sysv, digits=20).exists
    for _ in range(40):
        mid = 0.5 * (lo + hi)
        if boundary(2, mid, Q=7, damping="paper", system=sysv, digits=20).exists == has_lo:
            lo = mid
        else:
            hi = mid
    ks = np.arange(2, 13, 2.0)
    ms = np.sort(np.concatenate([lo * (1 + 10.0**-ks), lo * (1 - 10.0**-ks)]))
    _assert_family_grid([1, 2, 3], ms, 7, "paper", sysv)


@pytest.mark.parametrize("damping", ["exact", "paper"])
def test_next_to_critical_damping(damping):
    """Q = 3/5: half 1 is critically damped at m = 4 Q^2 - 1 = 0.44 exactly (exact model; the
    regimes are decided in floats only away from it); depths within a relative 1e-15 .. 1e-2 of
    it, both sides, and 0.44 itself."""
    ks = np.arange(2, 16, 1.0)
    ms = np.sort(np.concatenate([0.44 * (1 + 10.0**-ks), 0.44 * (1 - 10.0**-ks), [0.44]]))
    _assert_grid([1, 2, 3], ms, Fraction(3, 5), damping)


def test_confirmation_rejects_a_wrong_edge():
    """The ball-arithmetic confirmation of an escalated entry proves a right edge and refuses one
    moved by 3e-14 (a relative error three times the bound), either edge, so that such an entry
    would go to the certified route.  Reference: the certified edges at 30 digits."""
    from verify.grid import _confirmed
    from verify.inputs import as_system

    sysv = as_system("pendulum", "1/2")
    m = Fraction("0.5095")  # order 5, Q = 7, paper: an entry the double estimate escalates
    b = boundary(5, m, Q=7, damping="paper", digits=30)
    lo, hi = float(b.lower), float(b.upper)
    assert _confirmed(5, m, 7, "paper", sysv, (lo, hi))
    for bad in ((lo * (1 + 3e-14), hi), (lo * (1 - 3e-14), hi), (lo, hi * (1 + 3e-14))):
        assert not _confirmed(5, m, 7, "paper", sysv, bad)


def test_confirmation_returns_the_secant_root():
    """An escalated entry that the ball-arithmetic proof confirms takes the secant root of the
    indicator between the two proved points: from edges moved by a relative 5e-15 (inside the
    bound, as the rounding of ``D`` next to a double root leaves them), the edges returned are
    within 1e-15 of the certified ones (Reference: the certified edges at 30 digits)."""
    from verify.grid import _confirm
    from verify.inputs import as_system

    sysv = as_system("pendulum", "1/2")
    for n, m, damping in ((5, "0.5095", "paper"), (3, "0.4825", "exact"), (6, "0.9205", "paper")):
        b = boundary(n, Fraction(m), Q=7, damping=damping, digits=30)
        lo, hi = float(b.lower), float(b.upper)
        for moved in ((lo * (1 + 5e-15), hi * (1 - 5e-15)), (lo * (1 - 5e-15), hi * (1 + 5e-15))):
            got = _confirm(n, Fraction(m), 7, damping, sysv, moved)
            assert got is not None
            for g, want in zip(got, (b.lower, b.upper), strict=True):
                assert abs(g - float(want)) <= 1e-15 * abs(float(want))


def test_confirmation_refines_an_edge_beyond_the_bound():
    """With ``refine=True`` (the grid's call) an escalated edge that misses the bound -- a double
    edge off by a relative 1e-14 .. 3e-14, as the rounding of ``D`` next to a double root can
    leave it (order 5 at m = 0.5095, paper model, left the lower edge 8.5e-15 off) -- is moved
    to the secant root through the two tested points and proved there: both edges returned are
    within 1e-15 of the certified ones; without ``refine`` the same edges are refused.
    Reference: the certified edges at 30 digits."""
    from verify.grid import _confirm
    from verify.inputs import as_system

    sysv = as_system("pendulum", "1/2")
    for n, m, damping in ((5, "0.5095", "paper"), (3, "0.4825", "exact")):
        b = boundary(n, Fraction(m), Q=7, damping=damping, digits=30)
        lo, hi = float(b.lower), float(b.upper)
        for moved in ((lo * (1 + 3e-14), hi), (lo, hi * (1 - 1e-14)), (lo * (1 - 2e-14), hi)):
            assert _confirm(n, Fraction(m), 7, damping, sysv, moved) is None
            got = _confirm(n, Fraction(m), 7, damping, sysv, moved, refine=True)
            assert got is not None
            for g, want in zip(got, (b.lower, b.upper), strict=True):
                assert abs(g - float(want)) <= 1e-15 * abs(float(want))
