"""The double grid with friction against the certified boundary, point by point.

Reference: the certified :func:`verify.solve.boundary` at the exact depth of each point (its digits
are proven by ball arithmetic; it never uses the grid's values), at 20 digits, or more where it asks
for more.  The claim checked is the one stated in :func:`verify.grid.boundary_grid`: every finite
entry within a relative :data:`verify.grid.ERROR_BOUND` of the exact edge, NaN exactly where the
interval does not exist.  Depths: random (fixed seed) over the whole range, next to the thresholds
where an interval appears or closes (where the two edges are a near-double root of the indicator),
and next to critical damping of either half in the exact model (where the grid changes from the
normal form to the trace form).  Each set of depths is checked in a grid of its own and embedded
among :data:`FILLER` depths, where the grid takes the path of large grids (the brackets from start
tables per ``Q`` and damping model).
"""

from __future__ import annotations

from fractions import Fraction

import numpy as np
import pytest

import verify.grid as grid_module
from verify.certify import CertificationError
from verify.grid import ERROR_BOUND, boundary_grid
from verify.solve import boundary

ORDERS = [1, 2, 3, 4, 5, 6]

#: evenly spread depths among which the checked ones are embedded (a large grid)
FILLER = (np.arange(600) + 0.5) / 600

#: the thresholds of orders 1-6 with Q = 7 (depths where an interval appears or closes), from
#: ``verify.existence.existence(n, 7, damping=..., digits=15)`` (proven enclosures; here they only
#: choose depths next to them -- the reference at each depth is the certified boundary)
THRESHOLDS = {
    "exact": [
        0.07442366215504008,
        0.296290949907762,
        0.2600664686827162,
        0.4826539711306615,
        0.6520353346861848,
        0.3191726978904458,
        0.7789682720051991,
        0.8133908237386502,
        0.5081551097314514,
        0.8750605899326807,
        0.8867408607788055,
        0.6547139014937136,
        0.9197659551875935,
        0.9247372611288041,
    ],
    "paper": [
        0.07444395814033679,
        0.29695044545435956,
        0.2593586091943339,
        0.4859976240146599,
        0.6536435572591718,
        0.31971495877639283,
        0.7807238824815731,
        0.8146848054712842,
        0.5094974027461772,
        0.876169940546023,
        0.8876624913076495,
        0.6562814093132477,
        0.9205154608156897,
        0.9253996912664038,
    ],
}


def _certified(n, m, Q, damping):
    for digits in (20, 40, 80):
        try:
            return boundary(n, m, Q=Q, damping=damping, digits=digits)
        except CertificationError:
            continue
    raise AssertionError(f"no certified reference for order {n}, m = {m}, Q = {Q}, {damping}")


def _grid(orders, ms, Q, damping, large):
    """``boundary_grid`` at ``ms``; ``large``: in a grid with :data:`FILLER` after them."""
    if not large:
        return boundary_grid(orders, ms, Q=Q, damping=damping)
    assert FILLER.size >= grid_module._TABLE_MIN
    exact = any(isinstance(m, Fraction) for m in ms)
    filler = [Fraction(2 * k + 1, 2 * FILLER.size) for k in range(FILLER.size)] if exact else FILLER
    both = list(ms) + list(filler) if exact else np.concatenate([ms, filler])
    return boundary_grid(orders, both, Q=Q, damping=damping)[..., : len(ms)]


def _bad_points(orders, ms, Q, damping, large=False):
    """Every disagreement of the grid with the certified edges at the depths ``ms``."""
    grid = _grid(orders, ms, Q, damping, large)
    assert grid.shape == (len(orders), 2, len(ms))
    bad = []
    for i, n in enumerate(orders):
        for j, m in enumerate(ms):
            b = _certified(n, m, Q, damping)
            where = f"order {n}, m = {m!r}, Q = {Q} {damping}"
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


@pytest.mark.parametrize("large", [False, True], ids=["small", "large"])
@pytest.mark.parametrize("damping", ["exact", "paper"])
def test_random_depths(damping, large):
    """150 depths uniform in (0, 1) (seeded), orders 1-6, Q = 7."""
    rng = np.random.default_rng(20261123 + (damping == "paper"))
    ms = np.sort(rng.uniform(0.0, 1.0, 150))
    bad = _bad_points(ORDERS, ms, 7, damping, large)
    assert not bad, f"{len(bad)} bad points:\n" + "\n".join(bad)


@pytest.mark.parametrize("large", [False, True], ids=["small", "large"])
@pytest.mark.parametrize("damping", ["exact", "paper"])
def test_next_to_the_thresholds(damping, large):
    """Depths a relative 1e-4 ... 1e-12 either side of every threshold of orders 1-6 (Q = 7):
    the edges merge into a double root of the indicator there, and the grid must either bound its
    error or hand the point to ball arithmetic (and be NaN exactly where nothing exists)."""
    ms = []
    for t in THRESHOLDS[damping]:
        for k in (4, 6, 8, 10, 12):
            ms += [t * (1 - 10.0**-k), t * (1 + 10.0**-k)]
    ms = np.sort(np.array(ms))
    bad = _bad_points(ORDERS, ms, 7, damping, large)
    assert not bad, f"{len(bad)} bad points:\n" + "\n".join(bad)


@pytest.mark.parametrize(
    "Q, critical",
    [
        # half 1 critically damped where 4 Q^2 - 1 - m = 0: m = 11/25 for Q = 3/5
        (Fraction(3, 5), Fraction(11, 25)),
        # half 2 critically damped where 4 Q^2 - 1 + m = 0: m = 9/25 for Q = 2/5
        (Fraction(2, 5), Fraction(9, 25)),
    ],
)
@pytest.mark.parametrize("large", [False, True], ids=["small", "large"])
def test_next_to_critical_damping(Q, critical, large):
    """Exact model: depths at critical damping of one half (exactly, as a rational) and a relative
    1e-3 ... 1e-15 either side, where the grid changes between the normal form and the trace
    form, and the normal form's parameters lose digits to cancellation."""
    ms = [critical]
    for k in (3, 6, 9, 12, 15):
        d = Fraction(1, 10**k) * critical
        ms += [critical - d, critical + d]
    bad = _bad_points([1, 2, 3], ms, Q, "exact", large)
    assert not bad, f"{len(bad)} bad points:\n" + "\n".join(bad)


@pytest.mark.parametrize("damping", ["exact", "paper"])
def test_small_grid_next_to_one(damping):
    """Orders 1-3 at 40 depths log-spaced in ``1 - m`` from 1e-12 to 0.1, as a grid of their own
    (the path of small grids); ``tests/test_grid.py`` checks the same depths in a large grid.
    Order 1 at ``m = 1 - 9.4e-11`` was NaN here (the standard form read ``D < 0`` at the
    maximiser where the certified route proves the interval exists)."""
    near = 1 - np.logspace(-12, -1, 40)
    bad = _bad_points([1, 2, 3], near, 7, damping)
    assert not bad, f"{len(bad)} bad points:\n" + "\n".join(bad)


@pytest.mark.parametrize("damping", ["exact", "paper"])
def test_a_depth_does_not_depend_on_the_rest_of_the_grid(damping):
    """The start tables of the brackets depend on the system, the order, ``Q`` and the damping
    model alone: a depth's edges are the same bits in any large grid, with the tables computed
    afresh or taken from the cache, and in any position among other depths."""
    rng = np.random.default_rng(7)
    ms = np.concatenate([rng.uniform(0.0, 1.0, 20), [1e-12, 0.999999, 0.9999999999]])
    a = _grid([1, 2, 3, 6], ms, 7, damping, True)
    grid_module._TABLES.clear()
    grid_module._plan.cache_clear()
    shifted = np.concatenate([FILLER[:377], ms, FILLER[377:]])
    b = boundary_grid([6, 3, 2, 1], shifted, Q=7, damping=damping)
    assert np.array_equal(a, b[::-1, :, 377 : 377 + ms.size], equal_nan=True)


@pytest.mark.parametrize("parity", [1, -1])
def test_one_call_gives_the_forms_and_their_term_sizes(parity):
    """:func:`verify.derived.with_term_sizes` (the grid's one call per evaluation) gives the same
    values as the indicator's own compilations and :func:`verify.derived.term_sizes` (two
    independent lambdifications of the same sympy expressions; they differ only by rounding)."""
    from verify.derived import indicator, term_sizes, with_term_sizes

    rng = np.random.default_rng(7)
    k = 200
    theta = rng.uniform(-1.5, 1.5, k)
    c = rng.integers(1, 7, k) * (np.pi / 2)
    r2 = rng.uniform(0.0, 0.9, k)
    args = (theta, c, r2, 1 - r2, rng.uniform(0.0, 1.0, k), rng.uniform(0.0, 0.2, k))
    form = indicator(parity).real
    both = with_term_sizes(form).compiled("numpy", (0, 1, 2, 3, 4, 5))(*args)
    want = [form.compiled("numpy", j)(*args) for j in range(4)]
    want += list(term_sizes(form).compiled("numpy", (0, 1))(*args))
    sizes = np.abs(want[4]) + np.abs(want[5])  # every value is a sum of terms of these sizes
    for got, ref in zip(both, want, strict=True):
        assert np.all(np.abs(got - ref) <= 1e-14 * (sizes + np.abs(ref)))


@pytest.mark.parametrize("parity", [1, -1])
def test_one_call_gives_the_fourth_derivative(parity):
    """``with_term_sizes(form, 4)`` (the grid's stopping test of order 4 needs ``D''''``) gives the
    same first values and sizes as ``with_term_sizes(form)``, and as its fifth value the
    derivative of ``D'''`` differentiated by sympy and lambdified on its own."""
    import sympy as sp

    from verify.derived import indicator, with_term_sizes

    rng = np.random.default_rng(11)
    k = 200
    theta = rng.uniform(-1.5, 1.5, k)
    c = rng.integers(1, 7, k) * (np.pi / 2)
    r2 = rng.uniform(0.0, 0.9, k)
    args = (theta, c, r2, 1 - r2, rng.uniform(0.0, 1.0, k), rng.uniform(0.0, 0.2, k))
    form = indicator(parity).real
    three = with_term_sizes(form).compiled("numpy", (0, 1, 2, 3, 4, 5))(*args)
    four = with_term_sizes(form, 4).compiled("numpy", (0, 1, 2, 3, 4, 5, 6))(*args)
    d4 = sp.lambdify(form.args, sp.diff(form.exprs[3], form.args[0]), "numpy")(*args)
    sizes = np.abs(three[4]) + np.abs(three[5])
    for got, ref in zip(four[:4] + four[5:], three, strict=True):
        assert np.all(np.abs(got - ref) <= 1e-14 * (sizes + np.abs(ref)))
    assert np.all(np.abs(four[4] - d4) <= 1e-13 * (16 * sizes + np.abs(d4)))


@pytest.mark.parametrize("parity", [1, -1])
def test_hoisted_powers_give_the_same_bits(parity):
    """The indicator with the powers of its parameters taken as arguments
    (:func:`verify.grid._indicator_powers`, the table path's evaluations; the powers computed once
    per depth and gathered) gives the same bits as the compiled form it rewrites
    (:func:`verify.grid._indicator_all`), on random arguments with repeated parameters."""
    from verify.grid import _indicator_all, _indicator_powers

    rng = np.random.default_rng(3)
    fn, powers = _indicator_powers(parity)
    assert {v for v, _ in powers} == {"beta", "g"} and all(k >= 3 for _, k in powers)
    depth = rng.integers(0, 50, 4001)  # 50 depths, each used many times
    beta, g = rng.uniform(0.0, 1.0, 50), rng.uniform(0.0, 0.2, 50)
    args = (rng.uniform(-1.5, 1.5, depth.size), rng.integers(1, 7, depth.size) * (np.pi / 2))
    args += (rng.uniform(0.0, 0.9, depth.size), rng.uniform(0.0, 0.3, depth.size))
    args += (beta[depth], g[depth])
    named = {"beta": beta, "g": g}
    got = fn(*args, *(((named[v]) ** k)[depth] for v, k in powers))
    want = _indicator_all(parity)(*args)
    assert len(got) == len(want) == 7
    for a, b in zip(got, want, strict=True):
        assert np.array_equal(a, b)


@pytest.mark.parametrize("damping", ["exact", "paper"])
def test_table_path_next_to_one_matches_certified(damping):
    """The table path of a large grid takes entries next to ``m = 1`` too (``1 - beta`` down to
    :data:`verify.grid.TABLE_NEAR_MIN`, an interval only where its edges lie a relative
    ``_NEAR_GAP`` apart); there the edges are polished on the forms for ``m -> 1``.  Reference:
    the certified route at 20 digits (every interval of orders 1-6) on depths log-spaced in ``1 -
    m`` from 1e-7 to 0.05, in a grid of 600 more depths."""
    near = 1 - np.logspace(-7, np.log10(0.05), 12)
    bad = _bad_points(ORDERS, near, 7, damping, large=True)
    assert not bad, f"{len(bad)} bad points:\n" + "\n".join(bad)


def _no_interval_samples(seed, count):
    """Random ``(order, depth, Q, damping)`` with the normal form's parameters (both halves
    underdamped), Q from 0.8 to 100 (log-uniform), depths uniform and next to the thresholds."""
    rng = np.random.default_rng(seed)
    out = []
    while len(out) < count:
        n = int(rng.integers(1, 9))
        Q = float(np.exp(rng.uniform(np.log(0.8), np.log(100.0))))
        damping = ["exact", "paper"][int(rng.integers(0, 2))]
        m = float(rng.uniform(1e-3, 0.97))
        if damping == "exact" and 4 * Q * Q - 1 - m <= 1e-6:
            continue
        out.append((n, round(m, 6), round(Q, 4), damping))
    return out


def test_no_interval_bound_agrees_with_certified():
    """:func:`verify.grid._no_interval` (the bound that proves ``D < 0`` on the whole window, which
    takes an entry as "no interval" without solving anything) against the certified route: every
    entry it takes has no interval there (``boundary(...).exists`` is False), on 300 random
    entries (orders 1-8, Q from 0.8 to 100, both damping models) and on the depths next to every
    threshold of orders 1-6 with Q = 7 (a relative 1e-3 ... 1e-9 either side, where the maximum of
    ``D`` is a near-zero).  It must take some of each (the test is not vacuous)."""
    from verify.derived import backend
    from verify.grid import _no_interval, _parity
    from verify.params import normal_params

    samples = _no_interval_samples(99, 300)
    for damping in ("exact", "paper"):
        for t in THRESHOLDS[damping]:
            for k in (3, 5, 7, 9):
                for sign in (-1, 1):
                    for order in ORDERS:
                        samples.append((order, t * (1 + sign * 10.0**-k), 7.0, damping))
    taken = 0
    for n, m, Q, damping in samples:
        P = normal_params(np.array([m]), Q, damping, backend("numpy"), om=np.array([1 - m]))
        args = [np.atleast_1d(np.asarray(getattr(P, k), float)) for k in ("r2", "u", "beta", "g")]
        c = np.array([n * np.pi / 2])
        if not _no_interval(int(_parity(n)), c, *args)[0]:
            continue
        taken += 1
        b = boundary(n, Fraction(repr(m)), Q=Fraction(repr(Q)), damping=damping, digits=20)
        assert not b.exists, f"order {n}, m = {m!r}, Q = {Q}, {damping}: the interval exists"
    assert taken >= 50


@pytest.mark.parametrize("damping", ["exact", "paper"])
def test_split_at_the_maximiser_next_to_thresholds(damping, monkeypatch):
    """Entries whose four nearest table nodes do not all have the interval (next to a threshold)
    are split at the maximiser of ``D`` (:func:`verify.grid._table_split`): the grid's edges there
    against the certified route, on depths spaced 2e-4 within 3e-3 of every threshold of orders
    1-6 (Q = 7) in a large grid; the split must have taken some of them."""
    took = []
    split = grid_module._table_split

    def spy(*args, **kw):
        got = split(*args, **kw)
        took.append(int(got[4].sum()))
        return got

    monkeypatch.setattr(grid_module, "_table_split", spy)
    ms = np.unique(np.concatenate([t + np.arange(-15, 16) * 2e-4 for t in THRESHOLDS[damping]]))
    grid = _grid(ORDERS, ms, 7, damping, True)
    assert sum(took) >= 20
    bad = []
    for i, n in enumerate(ORDERS):
        for j, m in enumerate(ms):
            if not np.isfinite(grid[i, 0, j]):
                continue
            b = _certified(n, float(m), 7, damping)
            for k, want in ((0, b.lower), (1, b.upper)):
                rel = abs(grid[i, k, j] - float(want)) / abs(float(want))
                if not rel <= ERROR_BOUND:
                    bad.append(f"order {n}, m = {m!r}, edge {k}: rel {rel:.2e}")
    assert not bad, "\n".join(bad)


@pytest.mark.parametrize("damping", ["exact", "paper"])
def test_table_path_agrees_with_the_bracketed_path(damping):
    """The entries the grid with friction takes from the start tables of its edges
    (:func:`verify.grid._table_friction`: most of a grid of 1000 depths) against the bracketed
    path (:func:`verify.grid._damped_normal`, the float stage of the proofs: the maximiser to
    1e-12, the edges safeguarded by bisection) at the same parameters: the same existence, and
    edges within 1e-15 of ``max(c + theta, 1)`` (except the order-1 lower edge where ``x = pi/2 +
    theta`` is below ``ORDER1_X_DAMPED``: the grid solves it again in ``x``, and in ``theta`` both
    paths leave a few ulp of ``pi/2`` there)."""
    from dataclasses import fields

    from verify.derived import backend
    from verify.grid import (
        NEAR_ONE,
        ORDER1_X_DAMPED,
        NormalParams,
        _damped_normal,
        _table_friction,
    )
    from verify.params import normal_params

    ms = (np.arange(1000) + 0.5) / 1000
    om = 1 - ms
    P = normal_params(ms, 7.0, damping, backend("numpy"), om=om)
    P = NormalParams(*(np.asarray(getattr(P, f.name), float) * np.ones(ms.size) for f in fields(P)))
    orders = np.array(ORDERS)
    far = np.nonzero(P.bm >= NEAR_ONE)[0]
    from analytic.system import PAPER

    fast = _table_friction(orders, P, np.sqrt(om), PAPER, (7.0, damping), far)
    done = fast["done"]
    assert done.sum() >= 0.85 * done.size  # the tables carry the grid
    for parity in (1, 0):
        rows = np.nonzero(orders % 2 == parity)[0]
        ref = _damped_normal(orders[rows][:, None], P)
        for key in ("lo", "hi"):
            got, want = fast[key][rows], ref[key]
            sel = done[rows]
            assert np.array_equal(np.isfinite(got[sel]), np.isfinite(want[sel]))
            both = sel & np.isfinite(got)
            if key == "lo" and parity == 1:  # (order 1 is the first odd row)
                both[0] &= np.pi / 2 + want[0] >= ORDER1_X_DAMPED
            scale = np.maximum(np.abs(orders[rows][:, None] * np.pi / 2 + want), 1.0)
            # an edge the table path flags (its rounding over its slope above DOUBT: next to a
            # threshold, a near-double root) is escalated by the grid (proved or certified);
            # there both paths are only within that rounding of the root
            flagged = fast[f"{key}_doubt"][rows]
            clear = both & ~flagged
            assert np.all(np.abs(got - want)[clear] <= 1e-15 * scale[clear])
            near = both & flagged
            assert np.all(np.abs(got - want)[near] <= ERROR_BOUND * scale[near])


@pytest.mark.parametrize("Q", [1.2, 2.5, 20])
def test_large_grid_where_existence_changes(Q):
    """A grid of 1200 depths, orders 1-6, at quality factors where the intervals of the orders
    close at other depths (Q = 1.2: most orders close over most of the range; 2.5; 20), both
    damping models: at every pair of neighbouring depths where the grid says an interval appears
    or closes, both entries against the certified route (existence, and the edges within the
    bound).  These are the entries the table path takes next to a threshold (the split at the
    maximiser, the bound that proves no interval)."""
    ms = (np.arange(1200) + 0.5) / 1200
    for damping in ("exact", "paper"):
        if damping == "exact" and 4 * Q * Q - 1 <= 1:
            continue
        grid = boundary_grid(ORDERS, ms, Q=Q, damping=damping)
        bad = []
        for i, n in enumerate(ORDERS):
            has = np.isfinite(grid[i, 0])
            for j in np.nonzero(has[1:] != has[:-1])[0]:
                for jj in (j, j + 1):
                    b = _certified(n, float(ms[jj]), Q, damping)
                    where = f"order {n}, m = {ms[jj]!r}, Q = {Q}, {damping}"
                    if b.exists != bool(has[jj]):
                        bad.append(f"{where}: grid exists {bool(has[jj])}, certified {b.exists}")
                        continue
                    for k, want in ((0, b.lower), (1, b.upper)) if b.exists else ():
                        rel = abs(grid[i, k, jj] - float(want)) / abs(float(want))
                        if not rel <= ERROR_BOUND:
                            bad.append(f"{where}, edge {k}: rel {rel:.2e}")
        assert not bad, "\n".join(bad)
