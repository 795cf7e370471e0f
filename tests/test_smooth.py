"""A length that varies in time: the Liouville/Hill form and the sine modulation
(analytic.smooth), the validated Taylor integrator (verify.taylor) and what it gives
(verify.smooth: sine edges and multipliers, ramps with friction), each checked against an
independent computation (mpmath's Taylor integrator ``odefun``, the Bessel route of the ramp,
the jump model's monodromy)."""

from __future__ import annotations

import random
from fractions import Fraction as F

import mpmath
import pytest
import sympy as sp
from cli_run import run_cli as _cli
from flint import arb, ctx

from analytic import smooth as asm
from analytic.ramp import half_period_factorisation
from verify.certify import to_mpf
from verify.floquet import monodromy_arb
from verify.inputs import as_system
from verify.ramp import ramp_monodromy_arb
from verify.smooth import (
    ramp_monodromy_damped_arb,
    sine_boundary,
    sine_half_map,
    sine_monodromy_arb,
)

# ---------------------------------------------------------------------------------------------
# analytic


def test_hill_form_of_the_sine_length():
    l = asm.sine_length()
    assert asm.check_hill_form(l)
    assert asm.check_sine_symmetry()
    # the premise of the per-edge factorisation (proven for any G with det G = 1)
    assert half_period_factorisation() == (0, 0)


def test_hill_coefficient_is_constant_at_T0():
    """At T = T0 (Omega^2 = g) the sine's Hill coefficient is g for every m: all solutions
    have period T0, so the second interval has zero width at every depth."""
    s = asm.symbols()
    q = asm.hill_form(asm.sine_length()).subs({s["gamma"]: 0, s["T"]: 1, s["g"]: 4 * sp.pi**2})
    assert sp.simplify(q - 4 * sp.pi**2) == 0


def test_first_width_by_harmonic_balance():
    assert asm.sine_first_width() == (sp.Rational(-3, 8), sp.Rational(3, 8))


# ---------------------------------------------------------------------------------------------
# the integrator against mpmath.odefun


def _ode_sine(m, T, Q, t0, t1, dps=25):
    """Reference: the map of (phi, p) from t0 to t1 for l = 1 + m sin(2 pi t/T), by mpmath's
    Taylor integrator (odefun), independent of the sympy forms."""
    with mpmath.workdps(dps + 5):
        g = 4 * mpmath.pi**2
        gam = 0 if Q is None else mpmath.pi * F(Q).denominator / F(Q).numerator
        m, T = (mpmath.mpf(x.numerator) / x.denominator if isinstance(x, F) else x for x in (m, T))

        def rhs(t, y):
            l = 1 + m * mpmath.sin(2 * mpmath.pi * t / T)
            return [y[1] / l**2, -g * l * y[0] - 2 * gam * y[1]]

        cols = [mpmath.odefun(rhs, t0 * T, y0)(t1 * T) for y0 in ([1, 0], [0, 1])]
        return [cols[0][0], cols[1][0], cols[0][1], cols[1][1]]


def test_sine_monodromy_matches_ode_at_random_points():
    rng = random.Random(2013)
    for _ in range(2):
        m = F(rng.randint(1, 85), 100)
        T = F(rng.randint(30, 160), 100)
        Q = rng.choice([None, 3, F(17, 2)])
        ref = _ode_sine(m, T, Q, 0, 1, dps=20)
        with ctx.workprec(110):
            got = sine_monodromy_arb(m, T, Q)
        for a, b in zip(got, ref, strict=True):
            assert a.rad() < 1e-25 * (1 + abs(a).mid())
            with mpmath.workdps(40):
                assert abs(to_mpf(a) - b) < mpmath.mpf("1e-18") * (1 + abs(b)), (m, T, Q)


@pytest.mark.parametrize("m,T,Q", [(F(3, 10), F(9, 20), None), (F(4, 5), F(13, 10), 5)])
def test_determinant_is_the_damping(m, T, Q):
    """det M = exp(-2 gamma T) (the trace of A is -2 gamma): a property of the exact map that
    the enclosure must contain."""
    with ctx.workprec(150):
        a, b, c, d = sine_monodromy_arb(m, T, Q)
        det = a * d - b * c
        gam = arb(0) if Q is None else arb.pi() / Q
        want = (-2 * gam * arb(T.numerator) / T.denominator).exp()
        assert det.overlaps(want) and det.rad() < 1e-35


@pytest.mark.parametrize(
    "m,tau,S,D", [(F(3, 10), F(1, 2), F(1, 20), F(1, 2)), (F(7, 10), F(3, 2), F(1, 5), F(1, 3))]
)
def test_integrator_agrees_with_the_bessel_route(m, tau, S, D):
    """Without friction the integrated ramp is the Bessel closed form (two independent routes:
    one sums Taylor series of the ODE, the other evaluates J1, J2, Y1, Y2)."""
    with ctx.workprec(120):
        A = ramp_monodromy_damped_arb(m, tau, S, None, D)
        B = ramp_monodromy_arb(m, tau, S, D)  # (phi, phi') from t = S/2, where l = 1 + m
        L = arb(1 + m.numerator / arb(m.denominator)) ** 2
        for x, y in zip(A, (B[0], B[1] / L, B[2] * L, B[3]), strict=True):
            assert x.overlaps(y)
            assert x.rad() < 1e-28 * (1 + abs(x).mid())


@pytest.mark.parametrize(
    "m,tau,Q,D", [(F(3, 10), F(1, 2), 3, F(1, 2)), (F(1, 2), F(6, 5), 7, F(2, 5))]
)
def test_damped_ramp_at_S_zero_is_the_jump_model(m, tau, Q, D):
    """The jump limit with friction: at S = 0 the integrated period map is the jump model's
    (exact damping, closed-form segments in verify.floquet)."""
    with ctx.workprec(150):
        A = ramp_monodromy_damped_arb(m, tau, 0, Q, D)
        J = monodromy_arb(m, tau, F(Q), "exact", as_system("pendulum", D))
        L = arb(1 + m.numerator / arb(m.denominator)) ** 2
        for x, y in zip((A[0], A[1] * L, A[2] / L, A[3]), J, strict=True):
            assert x.overlaps(y)
            assert x.rad() < 1e-35 * (1 + abs(x).mid())


# ---------------------------------------------------------------------------------------------
# sine edges


def _G_ode(m, T, entry, dps=22):
    """Reference: one entry of the half-period map (T/4 to 3T/4) by mpmath.odefun."""
    return _ode_sine(m, T, None, mpmath.mpf(1) / 4, mpmath.mpf(3) / 4, dps)[entry]


@pytest.mark.parametrize("n,m", [(1, "0.3"), (3, "0.5")])
def test_sine_edges_against_ode(n, m):
    """Each certified edge brackets the independent root: mpmath.odefun's entry of the
    half-period map (the one that vanishes there) changes sign across edge -+ 1e-13."""
    b = sine_boundary(n, m, digits=30)
    entries = (0, 3) if n % 2 else (1, 2)
    with mpmath.workdps(30):
        mm = F(m)
        for edge in (b.lower, b.upper):
            with ctx.workprec(100):
                G = sine_half_map(mm, arb(mpmath.nstr(edge, 30)))
            e = min(entries, key=lambda k: abs(G[k]).mid())
            lo = _G_ode(mm, edge - mpmath.mpf("1e-13"), e, dps=18)
            hi = _G_ode(mm, edge + mpmath.mpf("1e-13"), e, dps=18)
            assert lo * hi < 0, (n, m, edge)


def test_sine_edges_small_depth_first_order():
    """At m = 1e-6 the first interval is 1/2 -+ 3m/8 + O(m^2) (the derived harmonic-balance
    coefficients of analytic.smooth)."""
    m = F(1, 10**6)
    b = sine_boundary(1, m, digits=30)
    c_lo, c_hi = (float(c) for c in asm.sine_first_width())
    for T, c in ((b.lower, c_lo), (b.upper, c_hi)):
        assert abs((float(T) - 0.5) / float(m) - c) < 10 * float(m)


def test_sine_second_interval_is_closed_at_every_depth():
    for m in ("0.2", "0.7"):
        b = sine_boundary(2, m, digits=25)
        for lo, hi in (b.lower_enclosure, b.upper_enclosure):
            assert lo <= 1 <= hi
        assert b.radius < 1e-28


def test_sine_edge_is_a_zero_of_the_half_map():
    b = sine_boundary(1, "0.6", digits=30)
    with ctx.workprec(120):
        for T, e in ((b.lower, (0, 3)), (b.upper, (0, 3))):
            Tb = arb(mpmath.nstr(T, 40))
            G = sine_half_map(F(3, 5), Tb)
            assert min(abs(G[e[0]]).mid(), abs(G[e[1]]).mid()) < 1e-25


# ---------------------------------------------------------------------------------------------
# command line


def test_cli_boundary_sine(capsys):
    rc, out, err = _cli(
        capsys, "boundary", "--order", "1", "--m", "0.3", "--modulation", "sine", "--json"
    )
    import json

    doc = json.loads(out)
    assert rc == 0 and doc["modulation"] == "sine" and doc["certified"]
    # edges by the independent sign-change check above, to 15 digits
    assert doc["lower"].startswith("0.38425572412651548")


def test_cli_multipliers_sine_with_friction(capsys):
    rc, out, err = _cli(
        capsys, "multipliers", "--T", "0.45", "--m", "0.3", "--Q", "10", "--modulation", "sine"
    )
    assert rc == 0 and "sine modulation" in out and "Q = 10" in out


@pytest.mark.parametrize(
    "extra,words",
    [
        (["--modulation", "sine", "--switch-time", "0.01"], "needs the ramp modulation"),
        (["--modulation", "sine", "--duty", "1/3"], "equal halves"),
        (["--modulation", "sine", "--Q", "5"], "without friction"),
        (["--modulation", "sine", "--system", "torsion"], "pendulum only"),
        (["--modulation", "saw"], "not one of"),
    ],
)
def test_cli_sine_refusals(capsys, extra, words):
    rc, out, err = _cli(capsys, "boundary", "--order", "1", "--m", "0.3", *extra)
    assert rc == 2 and out == ""
    assert err.startswith("paramres: error:") and words in err and "Traceback" not in err


def test_cli_ramp_multipliers_paper_damping_refused(capsys):
    rc, out, err = _cli(
        capsys,
        "multipliers",
        "--T",
        "0.5",
        "--m",
        "0.3",
        "--Q",
        "5",
        "--damping",
        "paper",
        "--modulation",
        "ramp",
        "--switch-time",
        "0.01",
    )
    assert rc == 2 and "exact friction model only" in err


# ---------------------------------------------------------------------------------------------
# table and simulate with a varying length


def test_cli_table_ramp_rows_are_the_boundaries(capsys):
    """Each certified row is verify.modulation.boundary's edge at that depth."""
    from verify.modulation import boundary

    rc, out, err = _cli(
        capsys,
        "table",
        "--orders",
        "2",
        "--m",
        "0.2:0.3:0.1",
        "--digits",
        "12",
        "--modulation",
        "ramp",
        "--switch-time",
        "0.01",
    )
    assert rc == 0
    lines = out.strip().splitlines()
    assert lines[0].startswith("order,m,lower,upper")
    for line, m in zip(lines[1:], ("0.2", "0.3"), strict=True):
        b = boundary(2, m, digits=12, modulation="ramp", switch_time="0.01").as_json()
        assert line.split(",")[2:4] == [b["lower"], b["upper"]]


def test_cli_table_sine_needs_digits(capsys):
    rc, out, err = _cli(
        capsys, "table", "--orders", "1", "--m", "0.1:0.2:0.1", "--modulation", "sine"
    )
    assert rc == 2 and out == "" and "certified only" in err


def test_simulate_sine_growth_matches_the_multiplier():
    """A double-precision time-domain run (scipy, independent of the validated integrator):
    the growth per period fitted on the strobes agrees with the certified ln|mu|max."""
    from verify.modulated_run import simulate_modulated

    r = simulate_modulated(3, "0.5", modulation="sine", T="1.452", periods=20)
    assert abs(r.growth_per_period - r.floquet_growth) < 1e-7 * r.floquet_growth
    assert r.floquet_growth > 0.007  # inside the third interval (edges 1.4510 .. 1.4532)


def test_simulate_ramp_edge_closes():
    """On the certified lower edge (S = 1/50) the state returns after 2T to 1e-9 (the
    integrator's rtol is 1e-12; the edge is placed to 20 digits)."""
    from verify.modulated_run import simulate_modulated

    r = simulate_modulated(1, "0.3", modulation="ramp", switch_time="1/50", edge="lower", periods=4)
    assert r.closure_error < 1e-9
    assert abs(r.growth_per_period) < 1e-9


def test_cli_simulate_sine(capsys):
    rc, out, err = _cli(
        capsys,
        "simulate",
        "--order",
        "1",
        "--m",
        "0.3",
        "--T",
        "0.45",
        "--modulation",
        "sine",
        "--Q",
        "10",
        "--periods",
        "6",
    )
    assert rc == 0 and "sine" in out and "growth per period" in out


# ---------------------------------------------------------------------------------------------
# the Liouville route of the half map, the Fourier recurrence, the closings in the report


@pytest.mark.parametrize("m,T", [(F(1, 2), F(29, 20)), (F(9, 10), F(3)), (F(1, 10**6), F(1, 2))])
def test_liouville_half_map_is_the_direct_one(m, T):
    """G integrated in (u, u') and carried back by C equals G integrated in (phi, p) (V2): both
    enclosures overlap and are 1e-35 narrow (reference: the direct route, a different ODE)."""
    from verify.smooth import sine_half_map_direct

    with ctx.workprec(150):
        for a, b in zip(sine_half_map(m, T), sine_half_map_direct(m, T), strict=True):
            assert a.overlaps(b)
            assert a.rad() < 1e-35 * (1 + abs(a).mid())


def test_liouville_state_is_the_substitution():
    """C of (u, u') = C (phi, p): u = l phi, u' = l' phi + p/l (differentiating u = l phi with
    phi' = p/l^2 by hand)."""
    s = asm.symbols()
    l = asm.sine_length()
    C = asm.liouville_state(l)
    want = sp.Matrix([[l, 0], [sp.diff(l, s["t"]), 1 / l]])
    assert (C - want).applyfunc(sp.simplify) == sp.zeros(2, 2)


def test_fourier_recurrence_of_the_ince_form():
    """L[e^{ik theta}] = e^{ik theta}((c - k^2) + (1 - k^2) m sin theta) by hand, and m sin theta
    = (m/2i)(z - 1/z): d = c - k^2, up = m (1 - k^2)/(2i), down = -up."""
    s = asm.symbols()
    k, c, m = s["k"], s["c"], s["m"]
    d, up, down = asm.fourier_recurrence()
    assert sp.simplify(d - (c - k**2)) == 0
    assert sp.simplify(up - m * (1 - k**2) / (2 * sp.I)) == 0
    assert sp.simplify(down + up) == 0
    th = asm.sine_closings()
    assert set(th.zeros) == {-1, 1} and th.even_closed and th.odd_open


def test_switching_chapter_states_the_closings():
    """The chapter's closings text is built from the derived recurrence and the ramp's certified
    bracket: it names the coupling's zeros, both sine statements, and the bracket's ends; the
    width table says closed for even orders and prints the odd widths."""
    from analytic.ramp import crossing_is_a_closing  # noqa: F401 - the text checks it
    from reports.latex import DEFAULT, inline, math
    from reports.sections import switching as sw
    from verify.ramp import RampClosing

    rc = RampClosing(
        3,
        F(1, 100),
        F(6072728525, 10**10),
        F(6072728527, 10**10),
        ("G22", "G11"),
        ("G11", "G22"),
        1.2649,
    )
    widths = {}
    for n in sw.CLOSE_ORDERS:
        for m in sw.CLOSE_M:
            widths[n, m] = (n % 2 == 1, "2.75936e-7" if n == 5 else "0.1")
    parts = sw._closings_text(widths, rc, lambda x: inline(math(x, DEFAULT)))
    text = "\n".join(p.raw for p in parts)
    assert r"\nu = -1, 1" in text  # the Fourier index is nu (k is an integer of the closings)
    assert "zero width at every depth" in text and "No interval of odd order ever closes" in text
    assert "0.6072728525" in text and "0.6072728527" in text
    assert r"2.75936 \cdot 10^{-7}" in text
    assert text.count("closed ($M = I$)") == 3 and text.count("open (proven)") == 3


def test_a_path_past_the_step_budget_is_refused(monkeypatch, capsys):
    """The sine modulation at ``m = 0.9`` over ``T = 20`` takes about 1700 Taylor steps; with a
    budget of 200 the integration is refused at once (its steps extrapolated over the period),
    as a proof that could not be completed: exit status 2 and the advice, no traceback."""
    import verify.taylor as taylor
    from verify.certify import CertificationError
    from verify.modulation import multipliers

    monkeypatch.setattr(taylor, "MAX_STEPS", 200)
    with pytest.raises(CertificationError, match="vary too fast") as info:
        multipliers(F(20), F(9, 10), modulation="sine", digits=15)
    assert "at most 200" in str(info.value)
    code, out, err = _cli(capsys, "multipliers", "--T", "20", "--m", "0.9", "--modulation", "sine")
    assert code == 2 and not out
    assert err.startswith("paramres: error: the coefficients vary too fast")
    assert "Traceback" not in err
    assert "a smaller depth m or a shorter period T" in err
