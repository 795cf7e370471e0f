"""The ramp modulation: the Bessel solution (analytic.ramp), its certified monodromy and edges
(verify.ramp), checked against the jump model (S = 0) and an independent ODE integration."""

from __future__ import annotations

import math
import random
from fractions import Fraction as F

import mpmath
import pytest
import sympy as sp
from cli_run import run_cli as _cli
from flint import arb, ctx

from analytic import ramp as ar
from verify.floquet import monodromy_arb
from verify.inputs import InputError, as_system
from verify.ramp import leading_shift, ramp_boundary, ramp_half_map, ramp_monodromy_arb
from verify.solve import boundary

# ---------------------------------------------------------------------------------------------
# analytic


def test_dsolve_gives_order_one_bessel():
    sol = ar.ramp_solution()
    assert sol.has(sp.besselj) and sol.has(sp.bessely)
    orders = {f.args[0] for f in sol.atoms(sp.besselj, sp.bessely)}
    assert orders == {1}


def test_bessel_solution_solves_the_equation():
    assert ar.check_ramp_solution()


def test_wronskian_constant():
    s = ar.symbols()
    assert sp.simplify(ar.fundamental_determinant() - s["c"] ** 3 / (4 * sp.pi * s["g"])) == 0


def test_reversal_and_factorisation():
    assert ar.check_reversal()
    assert ar.half_period_factorisation() == (0, 0)


def test_defect_is_the_mean_of_inverse_square_length():
    s = ar.symbols()
    E = ar.first_order_defect()
    la, lb = s["la"], s["lb"]
    # reference: (1/S) int 1/l^2 dt over a linear ramp = 1/(la lb), minus the jump's mean
    assert E[0, 0] == 0 and E[1, 0] == 0 and E[1, 1] == 0
    assert sp.simplify(E[0, 1] - (1 / (la * lb) - (1 / la**2 + 1 / lb**2) / 2)) == 0


def _ode_map(la, lb, S, dps=30):
    """Reference: the map of (phi, p) across a ramp by mpmath's Taylor integrator (odefun)."""
    with mpmath.workdps(dps):
        g = 4 * mpmath.pi**2
        c = (lb - la) / S
        cols = []
        for y0 in ([1, 0], [0, 1]):
            f = mpmath.odefun(
                lambda t, y: [y[1] / (la + c * t) ** 2, -g * (la + c * t) * y[0]], 0, y0
            )
            cols.append(f(S))
        return [cols[0][0], cols[1][0], cols[0][1], cols[1][1]]


@pytest.mark.parametrize("la,lb,S", [("1.3", "0.7", "0.05"), ("0.4", "1.6", "0.3")])
def test_ramp_map_matches_ode(la, lb, S):
    s = ar.symbols()
    R = ar.ramp_map()
    with mpmath.workdps(30):
        la_, lb_, S_ = mpmath.mpf(la), mpmath.mpf(lb), mpmath.mpf(S)
        f = sp.lambdify((s["la"], s["lb"], s["S"], s["g"]), list(R), "mpmath")
        got = f(la_, lb_, S_, 4 * mpmath.pi**2)
        ref = _ode_map(la_, lb_, S_)
        for a, b in zip(got, ref, strict=True):
            assert abs(a - b) < mpmath.mpf("1e-20")


# ---------------------------------------------------------------------------------------------
# verify: monodromy


@pytest.mark.parametrize(
    "m,tau,D",
    [(F(3, 10), F(1, 2), F(1, 2)), (F(3, 5), F(8, 5), F(1, 3)), (F(1, 10**6), 1, F(1, 2))],
)
def test_S_zero_is_the_jump_model(m, tau, D):
    with ctx.workprec(200):
        R = ramp_monodromy_arb(m, tau, 0, D)
        J = monodromy_arb(m, tau, None, "exact", as_system("pendulum", D))
        for a, b in zip(R, J, strict=True):
            assert a.overlaps(b)
            assert a.rad() < 1e-50 * (1 + abs(a).mid())


def _ode_monodromy(m, tau, S, D, dps=25):
    """Reference: the period map of (phi, phi') from t = S/2 by mpmath.odefun through every
    piece of l(t) (plateaus and ramps integrated alike)."""
    with mpmath.workdps(dps + 10):
        g = 4 * mpmath.pi**2
        m, tau, S, D = (mpmath.mpf(x.numerator) / x.denominator for x in map(F, (m, tau, S, D)))
        l1, l2 = 1 + m, 1 - m
        pieces = [  # (duration, l at start, l at end)
            (D * tau - S, l1, l1),
            (S, l1, l2),
            ((1 - D) * tau - S, l2, l2),
            (S, l2, l1),
        ]
        cols = []
        for y0 in ([1, 0], [0, l1**2]):  # (phi, p) of the unit states of (phi, phi')
            y = [mpmath.mpf(y0[0]), mpmath.mpf(y0[1])]
            for dur, la, lb in pieces:
                if dur == 0:
                    continue
                c = (lb - la) / dur
                f = mpmath.odefun(
                    lambda t, u, la=la, c=c: [u[1] / (la + c * t) ** 2, -g * (la + c * t) * u[0]],
                    0,
                    y,
                )
                y = list(f(dur))
            cols.append((y[0], y[1] / l1**2))
        return [cols[0][0], cols[1][0], cols[0][1], cols[1][1]]


def _random_points(count=2, seed=13):
    rng = random.Random(seed)
    for _ in range(count):
        m = F(rng.randint(1, 90), 100)
        tau = F(rng.randint(40, 160), 100)
        D = F(rng.choice([1, 2, 3]), 4)
        S = min(D, 1 - D) * tau * F(rng.randint(1, 100), 100)
        yield m, tau, S, D


@pytest.mark.parametrize(
    "m,tau,S,D",
    [
        *_random_points(),
        # S equal to the shorter phase (no plateau in it): D = 1/3, T = 1, S = 1/3
        (F(2, 5), F(1), F(1, 3), F(1, 3)),
    ],
)
def test_monodromy_matches_ode(m, tau, S, D):
    ref = _ode_monodromy(m, tau, S, D)
    with ctx.workprec(120):
        got = ramp_monodromy_arb(m, tau, S, D)
    for a, b in zip(got, ref, strict=True):
        assert abs(float(a.mid()) - float(b)) < 1e-18 * (1 + abs(float(b))), (m, tau, S, D)


def test_ramp_too_long_is_refused():
    with pytest.raises(InputError, match="longer than a phase"):
        ramp_monodromy_arb(F(3, 10), F(1, 2), F(26, 100))


# ---------------------------------------------------------------------------------------------
# verify: edges


def test_edges_at_S_zero_are_the_jump_edges():
    r = ramp_boundary(3, "0.3", 0, digits=30)
    b = boundary(3, "0.3", digits=30)
    assert str(r.boundary).splitlines()[1] == str(b).splitlines()[1]
    assert str(r.boundary).splitlines()[2] == str(b).splitlines()[2]


def test_edge_is_a_zero_of_the_half_map():
    r = ramp_boundary(2, "0.4", "1/50", digits=30)
    with ctx.workprec(200):
        for T, name in zip((r.lower, r.upper), r.factors, strict=True):
            G = ramp_half_map(F(2, 5), T, F(1, 50))
            e = {"G11": 0, "G12": 1, "G21": 2, "G22": 3}[name]
            assert G[e].contains(0)
            assert T.rad() < 1e-30 * T.mid()


@pytest.mark.parametrize("n", [1, 2, 3, 4, 5, 6])
def test_S_zero_reproduces_the_jump_edges_all_orders(n):
    # reference: the jump model's certified per-edge solver (verify.solve.boundary)
    r = ramp_boundary(n, "0.45", 0, digits=40)
    b = boundary(n, "0.45", digits=40)
    assert r.boundary.as_json()["lower"] == b.as_json()["lower"]
    assert r.boundary.as_json()["upper"] == b.as_json()["upper"]


def _trace_target(n):
    return 2 if n % 2 == 0 else -2


@pytest.mark.parametrize("n", [1, 2, 3, 4, 5, 6])
def test_edges_orders_1_to_6_are_multiplier_edges(n):
    """30 proven digits; at each edge the period map (a different product of the derived maps:
    full plateaus and both ramps, from t = S/2) has trace (-1)^n 2 within its enclosure."""
    S = F(1, 200)
    r = ramp_boundary(n, "0.3", S, digits=30)
    assert r.lower < r.upper
    for T in (r.lower, r.upper):
        assert T.rad() < 1e-30 * T.mid()
    with ctx.workprec(200):
        for T in (r.lower, r.upper):
            # the exact rational nearest the midpoint, 1e-45 off at most: the trace moves by
            # |d tr/dT| 1e-45 there, far below the 1e-25 asked
            Tq = F(T.mid().str(60, radius=False))
            M = ramp_monodromy_arb(F(3, 10), Tq, S)
            assert abs(float((M[0] + M[3]).mid()) - _trace_target(n)) < 1e-25


@pytest.mark.parametrize("n,m,S", [(1, F(3, 10), F(3, 20)), (3, F(1, 2), F(1, 30))])
def test_edge_against_ode_integration(n, m, S):
    """The independent check of an edge: mpmath's Taylor integration of (l^2 phi')' + g l phi = 0
    over one period at the certified edge gives tr M = (-1)^n 2 (to the integrator's 1e-18)."""
    r = ramp_boundary(n, m, S, digits=25)
    for T in (r.lower, r.upper):
        Tq = F(T.mid().str(40, radius=False))
        M = _ode_monodromy(m, Tq, S, F(1, 2), dps=25)
        assert abs(float(M[0] + M[3]) - _trace_target(n)) < 1e-16


def test_tiny_switching_time():
    """S = 1e-8: the shift is the derived first-order one to within S^2 (reference: the slope
    from analytic.ramp.first_order_defect; the S^2 coefficient measured below 1 for order 1)."""
    S = F(1, 10**8)
    r = ramp_boundary(1, "0.3", S, digits=40)
    a = leading_shift(1, "0.3", digits=30)
    with ctx.workprec(200):
        Sb = arb(1) / 10**8
        for shift, slope in zip(r.shifts, a, strict=True):
            assert abs(float((shift - slope * Sb).mid())) < 2 * 1e-16
            assert abs(shift) > 0  # the edges do move: shift ~ 1.4e-9
            assert shift.rad() < 1e-30


@pytest.mark.parametrize("n,m", [(1, "0.3"), (2, "0.3"), (3, "0.6"), (4, "0.2"), (6, "0.3")])
def test_leading_shift_error_falls_like_S_squared(n, m):
    """(T(S) - T(0) - a S)/S^2 tends to a constant: between S = 1e-3 and 5e-4 it changes by less
    than 2 % (were a wrong, it would grow like 1/S).  Reference: a = leading_shift (derived)."""
    a = leading_shift(n, m, digits=25)
    q = {}
    for S in (F(1, 1000), F(1, 2000)):
        r = ramp_boundary(n, m, S, digits=30)
        with ctx.workprec(200):
            Sb = arb(S.numerator) / S.denominator
            q[S] = [
                float(((sh - ai * Sb) / (Sb * Sb)).mid())
                for sh, ai in zip(r.shifts, a, strict=True)
            ]
    for x, y in zip(q[F(1, 1000)], q[F(1, 2000)], strict=True):
        assert abs(x - y) < 0.02 * max(abs(x), abs(y)) + 1e-3


def test_closing_reopens_into_an_interval():
    """Order 3 at m = 3/5, a closing of the jump model (M = -I at T = sqrt(8/5), width 0): with
    ramps of S = 1/100 the two certified edges are disjoint balls, so the interval reopens (its
    width ~ (18/17) S); inside, the certified multipliers show growth."""
    b = boundary(3, "3/5", digits=30)
    assert b.width == 0 or abs(b.width) < mpmath.mpf("1e-29")
    r = ramp_boundary(3, "3/5", F(1, 100), digits=30)
    assert r.lower.upper() < r.upper.lower()  # proven distinct
    assert 0.0105 < float((r.upper - r.lower).mid()) < 0.0107
    from verify.modulation import multipliers

    mid = F((r.lower + r.upper).mid().str(30, radius=False)) / 2
    mu = multipliers(mid, "3/5", modulation="ramp", switch_time="1/100", digits=20)
    assert mu.unstable is True
    # the leading shift: zero for one edge (it moves like S^5), 18/17 for the other
    a = leading_shift(3, "3/5", digits=25)
    assert a[0].contains(0) or a[1].contains(0)
    other = a[1] if a[0].contains(0) else a[0]
    assert abs(float(other.mid()) - 18 / 17) < 1e-12


def test_S_at_its_maximum_and_beyond():
    from verify.ramp import longest_ramp

    S_fit = longest_ramp(1, "0.3")
    ok = F(S_fit) * (1 - F(1, 10**6))
    r = ramp_boundary(1, "0.3", ok, digits=20)
    assert r.lower < r.upper
    with pytest.raises(InputError, match="longer than a phase"):
        ramp_boundary(1, "0.3", F(S_fit) * (1 + F(1, 10**4)), digits=20)


def test_jump_validity_answer():
    """Order 1, m = 0.3, tol 1e-3: the proven bracket S_ok < S_bad lies within 3 % of the
    first-order prediction tol T-(0)/a- (the lower edge moves fastest relative to its size)."""
    from verify.ramp import jump_validity

    v = jump_validity(1, "0.3", "1e-3")
    assert v.S_bad is not None and v.S_ok < v.S_bad
    pred = 1e-3 * float(v.jump_lower.mid()) / float(v.slopes[0].mid())
    assert abs(float(v.S_ok) - pred) < 0.03 * pred
    rows = {S: (a, b) for S, a, b in v.table}
    a, b = rows[v.S_ok]
    assert float((abs(a) / v.jump_lower).mid()) <= 1e-3
    a, b = rows[v.S_bad]
    assert max(float((abs(a) / v.jump_lower).mid()), float((abs(b) / v.jump_upper).mid())) > 1e-3


def test_jump_validity_proves_the_tolerance_asked_exactly():
    """The bound proven (and given in the JSON) is the tolerance asked, not its 64-bit rounding
    (``0.05`` rounds up, so "within" would have been proven against a larger tolerance)."""
    from verify.ramp import jump_validity

    v = jump_validity(2, "0.1", "0.05")
    assert v.tol == F(1, 20)
    assert v.as_json()["tolerance"] == "1/20"
    from verify.params import exact_fraction

    binary = mpmath.mpf("0.001")  # an mpmath number is taken as the value it has
    assert jump_validity(1, "0.3", binary).tol == exact_fraction(binary)


@pytest.mark.parametrize("n, m, tol", [(1, "0.3", "1e-3"), (3, "0.6", "1e-3"), (1, "0.1", "0.1")])
def test_jump_validity_without_the_longest_ramp_is_the_same(n, m, tol):
    """``fit=False`` computes the longest ramp only where the search comes near it; the answer
    (the bracket, the certified shifts) is the one ``fit=True`` gives (the reference).  At tol
    0.1 and m = 0.1 every ramp that fits stays within (S_bad is None): the search reaches the
    cap, so S_fit is computed."""
    from verify.ramp import jump_validity

    full = jump_validity(n, m, tol)
    lazy = jump_validity(n, m, tol, fit=False)
    assert (lazy.S_ok, lazy.S_bad) == (full.S_ok, full.S_bad)
    assert [S for S, _, _ in lazy.table] == [S for S, _, _ in full.table]
    for (_, a, b), (_, a2, b2) in zip(lazy.table, full.table, strict=True):
        assert a.overlaps(a2) and b.overlaps(b2)
    if full.S_bad is None:
        assert lazy.S_fit == full.S_fit
    else:
        assert lazy.S_fit is None


# ---------------------------------------------------------------------------------------------
# command line


def test_cli_boundary_ramp(capsys):
    rc, out, err = _cli(
        capsys,
        "boundary",
        "--order",
        "1",
        "--m",
        "0.3",
        "--modulation",
        "ramp",
        "--switch-time",
        "0.01",
    )
    assert rc == 0 and "ramp modulation, S = 1/100" in out
    # reference: ramp_boundary (the API the command calls), 30 digits
    r = ramp_boundary(1, "0.3", "0.01", digits=30).boundary
    assert f"lower T/T0 = {r.as_json()['lower']}" in out


def test_cli_default_is_square(capsys):
    rc, out, _ = _cli(capsys, "boundary", "--order", "2", "--m", "0.3", "--digits", "20")
    assert rc == 0
    assert str(boundary(2, "0.3", digits=20)).splitlines()[1] in out


def test_cli_multipliers_ramp(capsys):
    rc, out, _ = _cli(
        capsys,
        "multipliers",
        "--T",
        "0.5",
        "--m",
        "0.3",
        "--modulation",
        "ramp",
        "--switch-time",
        "1/4",
        "--digits",
        "15",
    )
    assert rc == 0 and "ramp modulation" in out and "unstable" in out


def test_cli_jump_validity(capsys):
    rc, out, _ = _cli(capsys, "jump-validity", "--order", "2", "--m", "0.4", "--tol", "1e-3")
    assert rc == 0 and "proven" in out and "leading behaviour" in out
    rc, out, _ = _cli(
        capsys, "jump-validity", "--order", "2", "--m", "0.4", "--tol", "1e-3", "--json"
    )
    import json

    doc = json.loads(out)
    assert F(doc["S_within"]) < F(doc["S_exceeded"])


_B = ["boundary", "--order", "1", "--m", "0.3"]
_RAMP = ["--modulation", "ramp", "--switch-time"]
_MU = ["multipliers", "--T", "0.5", "--m", "0.3"]


@pytest.mark.parametrize(
    "argv,words",
    [
        (_B + _RAMP + ["-0.1"], "negative"),
        (_B + _RAMP + ["0.3"], "longer than a phase"),
        (_B + ["--switch-time", "0.01"], "needs the ramp modulation"),
        (_B + ["--modulation", "ramp"], "needs a switching time"),
        (_B + ["--modulation", "sine", "--duty", "1/3"], "equal halves"),
        (_B + _RAMP + ["0.01", "--system", "meissner"], "pendulum only"),
        (_B + _RAMP + ["0.01", "--Q", "5"], "without friction"),
        (_B + _RAMP + ["abc"], "not a number"),
        (_MU + _RAMP + ["0.26"], "longer than a phase"),
        (_MU + ["--switch-time", "0.1"], "needs the ramp modulation"),
        (["jump-validity", "--order", "1", "--m", "0.3", "--tol", "0"], "tolerance"),
    ],
)
def test_cli_refusals(capsys, argv, words):
    rc, out, err = _cli(capsys, *argv)
    assert rc == 2 and out == ""
    assert err.startswith("paramres: error:") and words in err
    assert "Traceback" not in err


def test_order_3_closes_at_a_finite_switching_time():
    """At m = 9/10 (past the jump model's closing at 3/5) the edges of order 3 are zeros of G11
    (lower) and G22 (upper) at S = 0.3, and the other way round at S = 0.35: both pairs proven
    distinct, so the two followed edges cross in between, where M = -I (the interval closes at a
    finite S; located near S = 0.31228, T = 1.18410).  The period map there, from the derived maps,
    is -I to the accuracy of the located point."""
    r1 = ramp_boundary(3, "9/10", F(3, 10), digits=20)
    r2 = ramp_boundary(3, "9/10", F(7, 20), digits=20)
    assert r1.factors == ("G11", "G22") and r1.lower.upper() < r1.upper.lower()
    assert r2.factors == ("G22", "G11") and r2.lower.upper() < r2.upper.lower()
    with ctx.workprec(100):
        M = ramp_monodromy_arb(F(9, 10), F("1.1841011666965775"), F("0.3122835850405863"))
    for x, ref in zip(M, (-1, 0, 0, -1), strict=True):
        assert abs(float(x.mid()) - ref) < 1e-9


@pytest.mark.parametrize("n", [1, 2, 3, 4])
def test_leading_shift_at_small_depth(n):
    """The slope dT/dS at S = 0 for small m, measured: odd n, 2 m^2 (1 -+ n pi m/4); even n,
    4 m^2 (lower) and n^2 pi^2 m^4/16 (upper).  Reference: leading_shift at m = 1e-4, where the
    terms left out are O(m^2) relative (1e-8), except for the even upper edge, whose relative
    correction is O(m) (1e-4): tolerances 1e-6 (still 1e3 below the m-term tested) and 1e-3."""
    m = 1e-4
    a = [float(x.mid()) for x in leading_shift(n, "1e-4", digits=20)]
    if n % 2:
        assert abs(a[0] / (2 * m**2) - (1 - n * math.pi * m / 4)) < 1e-6
        assert abs(a[1] / (2 * m**2) - (1 + n * math.pi * m / 4)) < 1e-6
    else:
        assert abs(a[0] / (4 * m**2) - 1) < 1e-6
        assert abs(a[1] / (n**2 * math.pi**2 * m**4 / 16) - 1) < 1e-3


def test_tiny_depth_edges_keep_their_digits():
    """m = 1e-12, order 2, S = 1e-4: the lower edge moves by 4 m^2 S = 4e-28 (the measured slope
    at small m, test above) within 1 % (the S^2 term is of relative size ~S), an offset 1e-16
    below the edges themselves: the certified shift must resolve it."""
    r = ramp_boundary(2, "1e-12", F(1, 10**4), digits=30)
    shift = float(r.shifts[0].mid())
    assert abs(shift / 4e-28 - 1) < 1e-2
    assert r.shifts[0].rad() < 1e-40


def test_ball_is_exact_at_low_working_precision():
    """verify.certify.ball keeps every bit of an mpf midpoint whatever flint's precision (the
    ramp's shifts are differences of such balls; a rounded midpoint once gave 1.1e-16)."""
    from verify.certify import ball

    with mpmath.workdps(40):
        x = mpmath.mpf(1) - mpmath.mpf(2) ** -100
        y = -x
    with ctx.workprec(53):
        bx, by = ball(x, 1e-45), ball(y)
    with ctx.workprec(300):
        assert (bx - 1).contains(-(arb(2) ** -100))
        assert (by + 1).mid() == arb(2) ** -100


@pytest.mark.parametrize("n,m", [(1, "0.3"), (2, "0.3"), (3, "0.5"), (4, "0.2"), (5, "0.4")])
def test_leading_shift_error_has_the_derived_exponent(n, m):
    """The error of the leading-order prediction T(0) + a S falls like S^p, p the power that the
    expansion says comes next (analytic.ramp.next_power, from the sympy series of the ramp's map
    in S: here 2).  The slope of log|error| against log S, fitted over S = 1e-3, 5e-4, 2.5e-4
    (certified shifts, 30 digits), must equal p within 0.05 (the S^(p+1) term moves it by
    O(S) ~ 1e-3).  Reference: a = leading_shift (derived first-order coefficient).  Not at a
    closing of the jump model (order 3, m = 3/5), where one edge's coefficients vanish up to
    S^5 (test_closing_reopens_into_an_interval)."""
    p = ar.next_power()
    assert p == 2  # the series has an S^2 term (analytic.ramp.defect_series)
    a = leading_shift(n, m, digits=25)
    Ss = (F(1, 1000), F(1, 2000), F(1, 4000))
    errs = [[], []]
    for S in Ss:
        r = ramp_boundary(n, m, S, digits=30)
        with ctx.workprec(200):
            Sb = arb(S.numerator) / S.denominator
            for k, (sh, ai) in enumerate(zip(r.shifts, a, strict=True)):
                e = sh - ai * Sb
                assert not e.contains(0)  # the error itself is resolved
                errs[k].append(abs(float(e.mid())))
    x = [math.log(float(S)) for S in Ss]
    xm = sum(x) / len(x)
    for ek in errs:
        y = [math.log(e) for e in ek]
        ym = sum(y) / len(y)
        slope = sum((xi - xm) * (yi - ym) for xi, yi in zip(x, y, strict=True)) / sum(
            (xi - xm) ** 2 for xi in x
        )
        assert abs(slope - p) < 0.05, (n, m, slope, p)


def test_defect_series_first_term_is_the_magnus_defect():
    """The S^1 coefficient of the derived series is first_order_defect at l = 1 -+ m (two
    derivations: the ordered integrals and the first Magnus term)."""
    s = ar.symbols()
    m = sp.Symbol("m", positive=True)
    D1 = ar.defect_series(2)[1]
    E = ar.first_order_defect().subs({s["la"]: 1 + m, s["lb"]: 1 - m})
    assert (D1 - E).applyfunc(sp.simplify) == sp.zeros(2, 2)
    assert 2 in ar.defect_series(2)


def test_ramp_closing_moves_off_the_jump_closing():
    """Order 3, S = 1/100: the jump model's closing at m = 3/5 moves to a depth in a certified
    bracket of width <= 1e-10 above 3/5 (the edges at the two ends are proven disjoint and come
    in opposite orders).  Independent check: the full period map from the Bessel route (a
    different product than the half map) at the bracket's middle and the closing's period is
    -I to 1e-7 (the located point is ~1e-10 off)."""
    from verify.ramp import ramp_closing

    rc = ramp_closing(3, "1/100", "0.6", "0.62", tol="1e-10")
    assert F(3, 5) < rc.m_lo < rc.m_hi and rc.m_hi - rc.m_lo <= F(1, 10**10)
    assert set(rc.factors_lo) == {"G11", "G22"} and rc.factors_lo == rc.factors_hi[::-1]
    mid = (rc.m_lo + rc.m_hi) / 2
    with ctx.workprec(120):
        M = ramp_monodromy_arb(mid, F(rc.T_approx), F(1, 100))
    for x, ref in zip(M, (-1, 0, 0, -1), strict=True):
        assert abs(float(x.mid()) - ref) < 1e-7
    assert ar.crossing_is_a_closing() == sp.zeros(2, 2)


def test_ramp_chart_gives_the_edges_of_ramp_boundary():
    """Reference: ramp_boundary at each S (every edge followed from S = 0 on its own); the chart
    continues one path per edge through the S values, and encloses the same zeros."""
    from verify.ramp import ramp_chart

    S_values = [F(0), F(1, 200), F(3, 100), F(1, 10)]
    chart = ramp_chart(2, "3/10", S_values, digits=15)
    assert [r.S for r in chart] == S_values
    for r, S in zip(chart, S_values, strict=True):
        ref = ramp_boundary(2, "3/10", S, digits=15)
        assert r.factors == ref.factors
        for a, b in ((r.lower, ref.lower), (r.upper, ref.upper)):
            assert a.overlaps(b)
            assert float(a.rad()) < 1e-15 and float(b.rad()) < 1e-15
