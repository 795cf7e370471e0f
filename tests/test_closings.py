"""The closing theorem: its derivation, the list of closings, and numbers computed here.

References are built in this file from the printed per-edge equations (13) and (25), ``(q+1)
f(omega_av T/2) = eps (q-1) f(Delta omega T/4)`` with ``q`` from eq. (14), and from the period map
of the free oscillations and the jumps (``tests/pendulum_monodromy.py``) -- not from analytic/.
"""

from __future__ import annotations

from fractions import Fraction
from math import gcd

import mpmath
import numpy as np
import pytest
import sympy as sp
from pendulum_monodromy import monodromy_mp

import analytic.catalogue_series  # noqa: F401  (registers the rows)
from analytic.catalogue import _REGISTRY as ROWS
from analytic.closings import closing_pairs, closings, theorem_steps
from verify.inputs import InputError


def factor_mp(T, mm, order, eps):
    """Printed eq. (13) (odd) / (25) (even) as a residual:
    (q+1) f(omega_av T/2) - eps (q-1) f(dw T/4)."""
    w1 = 2 * mpmath.pi / mpmath.sqrt(1 + mm)
    w2 = 2 * mpmath.pi / mpmath.sqrt(1 - mm)
    q = ((1 + mm) / (1 - mm)) ** mpmath.mpf(1.5)
    f = mpmath.cos if order % 2 else mpmath.sin
    return (q + 1) * f((w1 + w2) * T / 4) - eps * (q - 1) * f((w2 - w1) * T / 4)


# ------------------------------------------------------------------------------------ the theorem


def test_every_step_of_the_derivation_checks_out():
    steps = theorem_steps()
    assert len(steps) == 10
    assert all(s.verdict.holds for s in steps), [s.claim for s in steps if not s.verdict.holds]
    assert closings(3).proven
    # every step states what it checks: none is an equation sympy evaluated to True or False,
    # which the report could not print
    for s in steps:
        assert not isinstance(s.expr, (bool, sp.logic.boolalg.BooleanAtom)), s.claim
        for eq in s.expr.atoms(sp.Eq) if isinstance(s.expr, sp.Basic) else ():
            assert not isinstance(eq, sp.logic.boolalg.BooleanAtom)
    # the sums of the two edge factors the steps show are the ones they prove
    for s in steps:
        if s.claim.startswith(("odd orders: F_+ + F_-", "even orders: F_+ + F_-")):
            (_, (fp, fm)) = s.expr.args
            f = sp.cos if s.claim.startswith("odd") else sp.sin
            x, y = sorted(fp.atoms(sp.Symbol) - {sp.Symbol("r", positive=True)}, key=str)
            r = sp.Symbol("r", positive=True)
            assert sp.expand(fp + fm - 2 * f(x)) == 0
            assert sp.expand(fm - fp - 2 * r * f(y)) == 0


def test_list_up_to_order_12():
    c = closings(12)
    assert len(c) == sum((k - 1) // 2 for k in range(1, 13)) == 30
    assert not c.of_order(1) and not c.of_order(2)  # the paper: closings only for n > 2
    for k in range(3, 13):
        got = sorted((x.a, x.b) for x in c.of_order(k))
        assert got == [(a, k - a) for a in range(1, (k + 1) // 2)]
        for x in c.of_order(k):
            assert x.m == Fraction(x.b**2 - x.a**2, x.b**2 + x.a**2)
            assert x.multiplier == (-1) ** k
            assert x.lowest_terms == (gcd(x.a, x.b) == 1)


def test_the_papers_three_ratios_are_special_cases():
    c = closings(6)
    # section 5: T1:T2 = 2:1 (third interval, and again the sixth as 4:2), 3:1, 3:2
    assert [(x.order, x.m) for x in c.at_ratio(2, 1)] == [(3, Fraction(3, 5)), (6, Fraction(3, 5))]
    assert [(x.order, x.m) for x in c.at_ratio(3, 1)] == [(4, Fraction(4, 5))]
    assert [(x.order, x.m) for x in c.at_ratio(3, 2)] == [(5, Fraction(5, 13))]
    # 2:1: half an oscillation of T1 and a full one of T2 per cycle, T = T1, M = -I
    x = c.at_ratio(2, 1)[0]
    assert (x.a, x.b, x.multiplier) == (1, 2, -1)
    # the two the text does not name
    assert {(x.order, x.ratio) for x in c.items} - {
        (3, "2:1"),
        (6, "4:2"),
        (4, "3:1"),
        (5, "3:2"),
    } == {
        (5, "4:1"),
        (6, "5:1"),
    }
    row = ROWS["§5"]()
    assert row.status == "agrees" and "15/17" in row.how and "12/13" in row.how


def test_same_depth_closes_several_orders():
    c = closings(12)
    assert [x.order for x in c if x.m == Fraction(3, 5)] == [3, 6, 9, 12]
    assert [x.lowest_terms for x in c if x.m == Fraction(3, 5)] == [True, False, False, False]


def test_periods_are_certified_and_correct():
    # T = a T1 = a sqrt(1+m) = b sqrt(1-m) in units of T0, recomputed here at 60 digits
    for x in closings(12):
        with mpmath.workdps(60):
            mm = mpmath.mpf(x.m.numerator) / x.m.denominator
            t1 = x.a * mpmath.sqrt(1 + mm)
            t2 = x.b * mpmath.sqrt(1 - mm)
            assert abs(t1 - t2) < mpmath.mpf(10) ** -55
            assert len(x.T.replace(".", "").lstrip("0")) >= 40
            assert abs(mpmath.mpf(x.T) - t1) <= mpmath.mpf(10) ** (-39) * t1
            assert mpmath.nstr(t1, 40, strip_zeros=False) == x.T
        assert sp.simplify(x.T_exact - sp.sympify(x.T_text)) == 0


def test_order_200_is_fast_and_complete():
    c = closings(200)
    assert len(c) == sum((k - 1) // 2 for k in range(1, 201))
    assert all(0 < x.m < 1 for x in c)


@pytest.mark.parametrize("bad", [0, -1, 201, "x", 2.5])
def test_bad_max_order(bad):
    with pytest.raises(InputError):
        closings(bad)


# ------------------------------------------------------------------------ numbers at each closing


@pytest.mark.parametrize("x", closings(12).items, ids=lambda x: f"n{x.order}-{x.ratio}")
def test_both_edges_meet_at_the_closing(x):
    """Both per-edge equations (printed 13/25) have their root at T = a T1, to 45 digits, and the
    period map there is (-1)^n I."""
    with mpmath.workdps(60):
        mm = mpmath.mpf(x.m.numerator) / x.m.denominator
        T = mpmath.mpf(x.a) * mpmath.sqrt(1 + mm)
        for eps in (1, -1):
            root = mpmath.findroot(
                lambda t, eps=eps: factor_mp(t, mm, x.order, eps), T * (1 + mpmath.mpf("1e-6"))
            )
            assert abs(root - T) < mpmath.mpf(10) ** -45, (x.order, x.ratio, eps)
        M = monodromy_mp(T, mm)
        assert mpmath.mnorm(M - x.multiplier * mpmath.eye(2), 1) < mpmath.mpf(10) ** -45
        # exact tuning: T = n T_av/2
        Tav = 2 / (1 / mpmath.sqrt(1 + mm) + 1 / mpmath.sqrt(1 - mm))
        assert abs(T - x.order * Tav / 2) < mpmath.mpf(10) ** -45


def _window_roots(order, ms, eps):
    """Root theta of (q+1) f(n pi/2 + theta) - eps (q-1) f(beta (n pi/2 + theta)) in the window
    |theta| < pi/2 for every m in ``ms`` (vectorised bisection, double precision)."""
    w1 = 2 * np.pi / np.sqrt(1 + ms)
    w2 = 2 * np.pi / np.sqrt(1 - ms)
    beta = (w2 - w1) / (w2 + w1)
    q = ((1 + ms) / (1 - ms)) ** 1.5
    f = np.cos if order % 2 else np.sin

    def F(th):
        x = order * np.pi / 2 + th
        return (q + 1) * f(x) - eps * (q - 1) * f(beta * x)

    lo = np.full_like(ms, -np.pi / 2)
    hi = np.full_like(ms, np.pi / 2)
    flo = F(lo)
    assert np.all(flo * F(hi) < 0)  # the window brackets exactly one root (window theorem)
    for _ in range(60):
        mid = (lo + hi) / 2
        fm = F(mid)
        left = np.sign(fm) == np.sign(flo)
        lo = np.where(left, mid, lo)
        flo = np.where(left, fm, flo)
        hi = np.where(left, hi, mid)
    return (lo + hi) / 2


def test_no_other_closings_up_to_order_12():
    """Scan T1:T2 = rho from 1.01 to 30 (m up to 0.9978): the gap between the two edge roots
    changes sign exactly once near each predicted closing and nowhere else (the two factors swap
    which edge they give), for every order up to 12."""
    rho = np.exp(np.linspace(np.log(1.01), np.log(30.0), 6001))
    ms = (rho**2 - 1) / (rho**2 + 1)
    for order in range(1, 13):
        gap = _window_roots(order, ms, 1) - _window_roots(order, ms, -1)
        changes = np.nonzero(np.sign(gap[1:]) != np.sign(gap[:-1]))[0]
        predicted = sorted(b / a for a, b in closing_pairs(order))
        assert len(changes) == len(predicted), (order, rho[changes], predicted)
        for idx, r in zip(changes, predicted, strict=False):
            assert rho[idx] <= r <= rho[idx + 1], (order, r)
        # away from the closings the edges are well apart (no touching without crossing)
        far = np.ones_like(rho, dtype=bool)
        for r in predicted:
            far &= np.abs(np.log(rho / r)) > 0.02
        assert np.min(np.abs(gap[far])) > 1e-4, order


def test_factors_swap_across_a_closing():
    # order 3 at m = 3/5: below, eq. (13)'s factor (eps = +1) gives the upper edge; above, the lower
    for mm, sign in ((0.55, 1), (0.65, -1)):
        arr = np.array([mm])
        d = _window_roots(3, arr, 1) - _window_roots(3, arr, -1)
        assert np.sign(d[0]) == sign


def test_family_closings_where_sympy_would_rewrite_a_negative_depth():
    """Was: NotImplementedError (a traceback from ``paramres crossings --max-order 10 --duty
    1/7``): for a = 8, b = 1 the depth -2303/2305 (no closing) went through nsimplify, which
    returned a product of fractional powers.  Every closing listed is the rational
    m = (rho^2 - 1)/(rho^2 + 1), rho = b D / (a (1 - D))."""
    from analytic.system import system

    for name, duty, n_max in (("pendulum", "1/7", 10), ("meissner", "0.98", 8)):
        sysv = system(name, duty=duty)
        D = sysv.duty
        items = closings(n_max, sysv).items
        assert items
        for c in items:
            rho = Fraction(c.b) * D / (c.a * (1 - D))
            assert c.m == (rho**2 - 1) / (rho**2 + 1) and 0 < c.m < 1
