"""The ramp modulation: the Bessel solution (analytic.ramp), its certified monodromy and edges
(verify.ramp), checked against the jump model (S = 0) and an independent ODE integration."""

from __future__ import annotations

import random
from fractions import Fraction as F

import mpmath
import pytest
import sympy as sp
from flint import arb, ctx

from analytic import ramp as ar
from verify.floquet import monodromy_arb
from verify.inputs import InputError, as_system
from verify.ramp import ramp_boundary, ramp_half_map, ramp_monodromy_arb
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
    "m,tau,D", [(F(3, 10), F(1, 2), F(1, 2)), (F(3, 5), F(8, 5), F(1, 3)), (F(1, 10**6), 1, F(1, 2))]
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


def test_monodromy_matches_ode_at_random_points():
    rng = random.Random(13)
    for _ in range(2):
        m = F(rng.randint(1, 90), 100)
        tau = F(rng.randint(40, 160), 100)
        D = F(rng.choice([1, 2, 3]), 4)
        S = min(D, 1 - D) * tau * F(rng.randint(1, 100), 100)
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
