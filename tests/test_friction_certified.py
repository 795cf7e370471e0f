"""Certified edges with friction (normal and trace forms): the shape of the indicator ``D``.

The fast path encloses both edges and proves the shape -- ``D < 0``, then ``> 0`` between the
edges, then ``< 0`` on the bracket -- by unimodality (:func:`verify.hump._unimodal_shape`); where
that fails the former proof runs (a point with ``D > 0``, signs on sub-intervals,
:func:`verify.hump._prove_shape`).

References, independent of the indicator:

* the Floquet route (:func:`verify.floquet.monodromy_matrix`, built from the segment solutions and
  the jump rule): on an edge of order ``n`` one multiplier is ``(-1)^n``, so ``det(M - (-1)^n I)``
  changes sign within ``1e-25`` (relative) of each certified edge;
* the former proof of the shape (the fast path switched off): the same edges, every enclosure
  overlapping.
"""

from __future__ import annotations

import math
from fractions import Fraction

import mpmath
import pytest
from flint import arb, ctx

import verify.hump as hump
from analytic.system import system
from verify.certify import Root
from verify.existence import existence
from verify.floquet import monodromy_matrix
from verify.params import NEAR_CRITICAL, form_for
from verify.solve import boundary


def _floquet_sign(T, m, Q, damping, sysv, sigma):
    with mpmath.workdps(60):
        M = monodromy_matrix(m, T, Q, damping, system=sysv, dps=60)
        return (M[0, 0] - sigma) * (M[1, 1] - sigma) - M[0, 1] * M[1, 0]


def _assert_floquet_edges(b, m, Q, damping, sysv, n):
    sigma = (-1) ** n
    with mpmath.workdps(60):
        for T in (b.lower, b.upper):
            delta = abs(mpmath.mpf(T)) * mpmath.mpf(10) ** -25
            lo = _floquet_sign(mpmath.mpf(T) - delta, m, Q, damping, sysv, sigma)
            hi = _floquet_sign(mpmath.mpf(T) + delta, m, Q, damping, sysv, sigma)
            assert lo * hi < 0, (n, m, Q, damping, T, lo, hi)


def _root(x: float, rad: float = 1e-12) -> Root:
    return Root(arb(x, rad), arb(x, 10 * rad), 64)


def _hump_of(D, dD, d2D, a, b):
    return hump._Hump(
        D=D, dD=dD, d2D=d2D, a=a, b=b, top=0.0, dtop=1.0, lo=math.nan, hi=math.nan, floor=0.0
    )


def test_unimodal_shape_proves_a_cap():
    """``D = 1 - x^2`` on ``[-2, 2]``: concave, zeros at -+1 -- proven."""
    h = _hump_of(lambda x: 1 - x * x, lambda x: -2 * x, lambda x: x * 0 - 2, -2.0, 2.0)
    assert hump._unimodal_shape(h, _root(-1.0), _root(1.0))


def test_unimodal_shape_refuses_a_second_hump():
    """``D = cos(x)`` on ``[-7, 7]`` has zeros at -+pi/2 and -+3pi/2: D rises again after falling,
    so the two inner zeros are not all of them -- not proven (never a wrong shape)."""
    h = _hump_of(lambda x: x.cos(), lambda x: -x.sin(), lambda x: -x.cos(), -7.0, 7.0)
    assert not hump._unimodal_shape(h, _root(-math.pi / 2), _root(math.pi / 2))


def test_unimodal_shape_tests_no_slope_on_a_piece_with_both_zeros():
    """``D = cos(x) - 1/2`` on ``[-2, 2]`` (zeros at -+pi/3; convex beyond -+pi/2): proven in the
    pieces ``[-2, -1]`` up, ``[-1, 0]``, ``[0, 1]`` cap, ``[1, 2]`` down.  ``D'`` is evaluated
    (once, at the midpoint) on each half and on the two monotone pieces, not on the whole
    bracket: it holds both zeros, so a zero of ``D'`` (Rolle)."""
    calls = []

    def dD(x):
        calls.append(x)
        return -x.sin()

    h = hump._Hump(
        D=lambda x: x.cos() - 0.5, dD=dD, d2D=lambda x: -x.cos(), a=-2.0, b=2.0, top=0.0,
        dtop=0.5, lo=math.nan, hi=math.nan, floor=0.0, bend=lambda x: x.cos() / 2,
    )  # fmt: skip
    assert hump._unimodal_shape(h, _root(-math.pi / 3), _root(math.pi / 3))
    assert [float(x) for x in calls] == [-1.0, -1.5, 1.0, 1.5]


def _counting(f, calls, name):
    def g(x):
        calls.append((name, float(x.mid())))
        return f(x)

    return g


def test_unimodal_direct_end_pieces():
    """``D = cos(x) - 1/2`` on ``[-2.4, 2.4]`` from three pieces, ``D`` convex at both ends: with
    ``direct=3`` each end piece (``[-2.4, -0.8]`` holding the zero ``-pi/3``, and its mirror) is
    decided by ``D'`` on the piece itself, one enclosure each (``-sin`` keeps its sign there:
    ``D'`` of the ball ``[-2.4, -0.8]`` is positive), and the middle piece is a cap: three
    enclosures in all, against five without (``-D''/2`` and ``D'`` at the midpoint on each end
    piece)."""
    one = arb(1)

    def run(direct):
        calls = []
        ok = hump._unimodal(
            arb(-2.4), arb(2.4), _root(-math.pi / 3).ball, _root(math.pi / 3).ball,
            _counting(lambda x: x.cos() / 2, calls, "bend"), None,
            _counting(lambda x: -x.sin(), calls, "dD"),
            _counting(lambda x: x.cos() - one / 2, calls, "D"),
            pieces=3, direct=direct,
        )  # fmt: skip
        return ok, calls

    ok, calls = run(3)
    assert ok
    assert [c[0] for c in calls] == ["dD", "bend", "dD"]
    assert calls[0][1] == pytest.approx(-1.6) and calls[2][1] == pytest.approx(1.6)
    ok0, calls0 = run(0)
    assert ok0 and len(calls0) == 5
    ok1, calls1 = run(1)  # the left end alone
    assert ok1 and [c[0] for c in calls1] == ["dD", "bend", "bend", "dD"]


def test_unimodal_direct_test_that_fails_falls_back():
    """Where ``D'`` on an end piece does not keep its sign, the piece is tested as any other: the
    shape is still proven (``D = cos(x) - 1/2`` on ``[-2.4, 2.4]`` cut in three, the end pieces'
    ``D'`` replaced by a ball holding 0 on whole pieces) -- and a false shape is never accepted
    (``cos`` on ``[-7, 7]``, direct tests at both ends)."""
    one = arb(1)

    def loose_dD(x):  # D' on a wide ball: widened to hold 0 (the test cannot decide)
        d = -x.sin()
        return d.union(arb(0)) if x.rad() > 0.1 else d

    assert hump._unimodal(
        arb(-2.4), arb(2.4), _root(-math.pi / 3).ball, _root(math.pi / 3).ball,
        lambda x: x.cos() / 2, None, loose_dD, lambda x: x.cos() - one / 2,
        pieces=3, direct=3,
    )  # fmt: skip
    assert not hump._unimodal(
        arb(-7.0), arb(7.0), _root(-math.pi / 2).ball, _root(math.pi / 2).ball,
        lambda x: x.cos() / 2, None, lambda x: -x.sin(), lambda x: x.cos(),
        pieces=3, direct=3,
    )  # fmt: skip


def test_unimodal_stops_at_the_first_label_that_fails():
    """The labels are checked as they come, left to right: a piece rising after a falling one
    ends the test (``False``) before the pieces right of it are evaluated -- no later label could
    make the shape acceptable.  Here ``[-3, -1]`` falls (``D'`` on it), ``[-1, 1]`` is not a cap
    and rises (the mean-value form), and ``[1, 3]`` is never evaluated."""
    calls = []

    def dD(x):
        calls.append(("dD", float(x.mid())))
        return x * 0 + (-1 if x.upper() < -0.5 else 1)

    def bend(x):
        calls.append(("bend", float(x.mid())))
        return x * 0 - arb(1) / 100

    def D(x):  # pragma: no cover - not reached (no neg test here)
        calls.append(("D", float(x.mid())))
        return x * 0 - 1

    ok = hump._unimodal(
        arb(-3.0), arb(3.0), _root(-2.5).ball, _root(2.5).ball, bend, None, dD, D,
        pieces=3, direct=3,
    )  # fmt: skip
    assert not ok
    assert calls == [("dD", -2.0), ("bend", 0.0), ("dD", 0.0)]


def test_unimodal_shape_refuses_bad_roots():
    """The same zero twice, or a zero outside the bracket: not proven."""
    h = _hump_of(lambda x: 1 - x * x, lambda x: -2 * x, lambda x: x * 0 - 2, -2.0, 2.0)
    assert not hump._unimodal_shape(h, _root(1.0), _root(1.0))
    assert not hump._unimodal_shape(h, _root(-1.0), _root(2.5))


def _sqrt_fraction(x: Fraction) -> Fraction:
    with mpmath.workdps(60):
        return Fraction(mpmath.nstr(mpmath.sqrt(mpmath.mpf(x.numerator) / x.denominator), 60))


def _near_threshold_cases():
    """Depths ``1e-9`` inside the proven thresholds (the interval is a sliver there)."""
    out = []
    eps = Fraction(1, 10**9)
    for n, Q, damping in ((3, Fraction(7), "exact"), (1, Fraction(5), "paper")):
        ex = existence(n, Q, damping=damping, digits=15)
        for th in ex.thresholds:
            lo, hi = th.enclosure
            for m in (lo - eps, hi + eps):
                b = boundary(n, m, Q=Q, damping=damping, digits=20)
                if b.exists:
                    out.append((n, m, Q, damping))
    return out


#: just on the normal form's side of the switch to the trace form at m = 9/10 (half 1 within
#: NEAR_CRITICAL of critical damping: 4 Q^2 = (1 + m)(1 + NEAR_CRITICAL^2), times 1 + 1e-20)
Q_NEAR_CRITICAL = _sqrt_fraction(
    Fraction(19, 40) * (1 + Fraction(NEAR_CRITICAL) ** 2) * (1 + Fraction(1, 10**20))
)

CASES = [
    (3, Fraction(3, 10), Fraction(7), "exact", "pendulum", "1/2"),  # the benchmark's
    (3, Fraction(3, 10), Fraction(7), "paper", "pendulum", "1/2"),
    (1, Fraction(1, 5), Fraction(5), "paper", "pendulum", "1/2"),
    (2, Fraction(1, 2), Fraction(20), "exact", "pendulum", "1/2"),
    (5, Fraction(7, 10), Fraction(30), "exact", "pendulum", "1/2"),
    (1, Fraction(99, 100), Fraction(7), "exact", "pendulum", "1/2"),  # edge next to the bracket
    (3, Fraction(9, 10), Fraction(7), "exact", "pendulum", "1/2"),  # wide, not concave
    (1, Fraction(3, 10), Fraction(7), "exact", "torsion", "1/2"),
    (2, Fraction(1, 2), Fraction(20), "paper", "torsion", "1/2"),
    (2, Fraction(1, 2), Fraction(20), "exact", "meissner", "1/3"),
    (1, Fraction(3, 10), Fraction(7), "paper", "pendulum", "1/3"),
    (1, Fraction(96, 100), Fraction(7, 10), "exact", "pendulum", "1/2"),  # half 1 critical
    (1, Fraction(9, 10), Q_NEAR_CRITICAL, "exact", "pendulum", "1/2"),
]


@pytest.mark.parametrize("case", CASES, ids=lambda c: "-".join(map(str, c)))
def test_edges_agree_with_floquet_and_with_the_former_proof(case, monkeypatch):
    n, m, Q, damping, name, duty = case
    sysv = system(name, duty=duty)
    b = boundary(n, m, Q=Q, damping=damping, system=sysv, digits=30)
    assert b.exists and b.certified, str(b)
    _assert_floquet_edges(b, m, Q, damping, sysv, n)
    monkeypatch.setattr(hump, "_unimodal_shape", lambda *a, **k: False)
    old = boundary(n, m, Q=Q, damping=damping, system=sysv, digits=30)
    assert old.exists and old.certified
    for (a0, a1), (b0, b1) in zip(
        (b.lower_enclosure, b.upper_enclosure),
        (old.lower_enclosure, old.upper_enclosure),
        strict=True,
    ):
        assert a0 <= b1 and b0 <= a1  # the enclosures overlap


def test_near_critical_case_is_the_normal_form():
    """The last case of CASES is just on the normal form's side of the switch to the trace form
    (half 1 within NEAR_CRITICAL of critical damping), the one before it critical itself."""
    assert form_for(CASES[-1][1], CASES[-1][2], "exact")[0] == "normal"
    assert form_for(CASES[-2][1], CASES[-2][2], "exact")[0] == "trace"


def test_near_thresholds():
    """Slivers of intervals ``1e-9`` inside the proven thresholds (order 3 with Q = 7, exact;
    order 1 with Q = 5, paper): certified, and each edge a Floquet root."""
    cases = _near_threshold_cases()
    assert len(cases) >= 3
    for n, m, Q, damping in cases:
        b = boundary(n, m, Q=Q, damping=damping, digits=30)
        assert b.exists and b.certified, str(b)
        assert 0 < b.upper - b.lower < 1e-3
        _assert_floquet_edges(b, m, Q, damping, system("pendulum"), n)


def test_the_benchmark_case_takes_the_fast_path(monkeypatch):
    """Order 3, m = 0.3, Q = 7: the shape is proven by unimodality (one call, no sign proof on
    sub-intervals): by the short path's first test of it (``D'' < 0`` on the whole bracket,
    :func:`verify.hump._lean_normal`), and with the short path off by
    :func:`verify.hump._unimodal_shape`."""
    calls = {"unimodal": [], "signs": 0, "lean": []}
    real = hump._unimodal_shape
    real_lean = hump._lean_normal

    def unimodal(*a, **k):
        calls["unimodal"].append(real(*a, **k))
        return calls["unimodal"][-1]

    def lean(*a, **k):
        out = real_lean(*a, **k)
        calls["lean"].append(out is not None)
        return out

    def signs(*a, **k):  # pragma: no cover - must not be reached
        calls["signs"] += 1
        return False

    monkeypatch.setattr(hump, "_unimodal_shape", unimodal)
    monkeypatch.setattr(hump, "prove_sign", signs)
    monkeypatch.setattr(hump, "_lean_normal", lean)
    for digits in (15, 50):
        b = boundary(3, "3/10", Q=7, digits=digits)
        assert b.exists and b.certified
    assert calls["lean"] == [True, True] and calls["unimodal"] == [] and calls["signs"] == 0
    monkeypatch.setattr(hump, "_LEAN_BITS", 0)
    for digits in (15, 50):
        b = boundary(3, "3/10", Q=7, digits=digits)
        assert b.exists and b.certified
    assert calls["unimodal"] == [True, True] and calls["signs"] == 0


@pytest.mark.parametrize("parity", [-1, 1])
def test_bend_is_minus_half_the_curvature(parity):
    """:func:`verify.derived.indicator_bend` is ``-D''/2`` (points: the two forms agree to the
    working precision), and over the benchmark's whole bracket its enclosure proves the concavity
    that the short path tests first (and meets ``D''``'s own, halved)."""
    D2, bend = hump._normal_forms(parity)[2], hump._normal_forms(parity)[5]
    with ctx.workprec(200):
        c = arb.pi() * (3 if parity == -1 else 2) / 2
        args = (c, arb("0.19"), arb("0.81"), arb("0.154"), arb("0.069"))
        for t in ("-0.4", "-0.1", "0", "0.2", "0.35"):
            x = arb(t)
            diff = bend(x, *args) + D2(x, *args) / 2
            assert diff.contains(0) and abs(diff) < arb(2) ** -190
    with ctx.workprec(64):
        X = arb(-0.3466).union(arb(0.3155))
        got, ref = bend(X, *args), -D2(X, *args) / 2
        assert got > 0 and got.overlaps(ref)
