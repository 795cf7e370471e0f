"""The model axis: every member of the family and every duty, checked against independent routes.

References:
* the Floquet route (:mod:`verify.floquet`): the monodromy built from the segment maps and the
  switches of the system's description, at 60 digits, with nothing from :mod:`analytic`'s
  determinants; an edge is proven to hold an independent root by a sign change of
  ``det(M - sigma I)`` across ``[T - delta, T + delta]``;
* for the Meissner equation at ``D = 1/2``: the classical trace condition
  ``2 cos a cos b - (w1/w2 + w2/w1) sin a sin b = +-2`` (``a = w1 T/2``, ``b = w2 T/2``), written
  out in this file;
* the paper's system: the hand-checked fast path of :mod:`verify.params` (itself proven against
  the definitions in ``test_params.py``).
"""

from __future__ import annotations

import random
from fractions import Fraction

import mpmath
import pytest

from analytic.system import PAPER, custom, system
from verify.derived import backend
from verify.floquet import floquet_multipliers, monodromy_matrix
from verify.inputs import InputError
from verify.multipliers import multipliers
from verify.params import normal_params
from verify.solve import boundary

SYSTEMS = ("pendulum", "torsion", "meissner")


def _floquet_condition(T, m, Q, damping, sysv, sigma):
    with mpmath.workdps(60):
        M = monodromy_matrix(m, T, Q, damping, system=sysv, dps=60)
        return (M[0, 0] - sigma) * (M[1, 1] - sigma) - M[0, 1] * M[1, 0]


def _independent_root_near(T, m, Q, damping, sysv, n, delta):
    """A root of the Floquet condition lies in ``[T - delta, T + delta]`` (sign change)."""
    sigma = (-1) ** n
    with mpmath.workdps(60):
        T = mpmath.mpf(T)
        lo = _floquet_condition(T - delta, m, Q, damping, sysv, sigma)
        hi = _floquet_condition(T + delta, m, Q, damping, sysv, sigma)
    return lo * hi < 0, (lo, hi)


def _cases(seed: int, count: int):
    rng = random.Random(seed)
    out = []
    for _ in range(count):
        name = rng.choice(SYSTEMS)
        duty = Fraction(rng.randint(1, 19), 20)
        kind = rng.random()
        if kind < 0.2:
            m = Fraction(1, 10 ** rng.randint(3, 8))
        elif kind < 0.4:
            m = 1 - Fraction(1, 10 ** rng.randint(2, 5))
        else:
            m = Fraction(rng.randint(1, 99), 100)
        n = rng.choice([1, 2, 3, 4, 5, 7, 12, rng.randint(1, 50)])
        Q = rng.choice([None, None, Fraction(rng.randint(20, 400), 10)])
        damping = rng.choice(["exact", "paper"])
        out.append((name, duty, m, n, Q, damping))
    return out


@pytest.mark.parametrize("case", _cases(20261122, 40), ids=lambda c: "-".join(map(str, c)))
def test_certified_edges_agree_with_floquet_route(case):
    """Random (system, duty, depth, order, Q, model): each certified edge holds a root of the
    independent Floquet condition within 1e-25 relative."""
    name, duty, m, n, Q, damping = case
    sysv = system(name, duty=duty)
    b = boundary(n, m, Q=Q, damping=damping, system=sysv, digits=30)
    if not b.exists:
        # no interval: the growth factor stays <= 1 at the centre of the frictionless interval
        b0 = boundary(n, m, system=sysv, digits=20)
        with mpmath.workdps(40):
            mid = (b0.lower + b0.upper) / 2
            mu = floquet_multipliers(m, mid, Q, damping, system=sysv, dps=40)
            assert max(abs(x) for x in mu) <= 1 + mpmath.mpf(10) ** -30
        return
    for T in (b.lower, b.upper):
        delta = abs(T) * mpmath.mpf(10) ** -25
        ok, vals = _independent_root_near(T, m, Q, damping, sysv, n, delta)
        assert ok, f"{case}: no Floquet root within {delta} of {T} ({vals})"


@pytest.mark.parametrize(
    "sysv",
    [custom(("4/5", "6/5"), jump=1, duty="1/3"), custom(("3", "1/2"), jump="2", duty="1/4")],
    ids=["custom-a", "custom-b"],
)
@pytest.mark.parametrize("n", [1, 2, 3, 6])
def test_custom_edges_agree_with_floquet_route(sysv, n):
    b = boundary(n, system=sysv, digits=30)
    assert b.exists
    for T in (b.lower, b.upper):
        ok, vals = _independent_root_near(T, None, None, "exact", sysv, n, T * mpmath.mpf("1e-25"))
        assert ok, vals


@pytest.mark.parametrize("name", SYSTEMS)
@pytest.mark.parametrize("duty", ["1/2", "1/3", "9/10"])
@pytest.mark.parametrize("n", [1, 2, 3, 4])
def test_small_depth_limit(name, duty, n):
    """At m -> 0 the interval shrinks to the exact tuning T_n = n T0/2 (omega_i -> omega0) and the
    centre moves by O(m).  The width is O(m), except where the n-th harmonic of the square wave
    vanishes (``n D`` an integer: the even orders at D = 1/2, every third order at D = 1/3), where
    it is O(m^2)."""
    m = Fraction(1, 10**8)
    b = boundary(n, m, system=system(name, duty=duty), digits=20)
    width, mf = float(b.width), float(m)
    if (n * Fraction(duty)).denominator == 1:
        assert 0 < width < 10 * n * mf**2
    else:
        assert mf**1.5 < width < 10 * n * mf
    assert abs(float((b.upper + b.lower) / 2) - n / 2) < 10 * n * mf


def test_swapping_the_phases_gives_the_same_chart():
    """custom (W1, W2, k, D) and (W2, W1, 1/k, 1 - D) describe one oscillator started in the
    other phase: the Floquet route (which never reorders the phases) gives the same multipliers,
    and the certified edges of either description hold its roots."""
    a = custom(("4/5", "6/5"), jump="3/2", duty="1/3")
    b = a.swapped()
    assert b.omega_sq == (Fraction(6, 5), Fraction(4, 5)) and b.duty == Fraction(2, 3)
    for T in ("0.37", "1.3", "2.71"):
        with mpmath.workdps(40):
            mu_a = floquet_multipliers(None, T, system=a, dps=40)
            mu_b = floquet_multipliers(None, T, system=b, dps=40)
            for x, y in zip(mu_a, mu_b, strict=True):
                assert abs(x - y) < mpmath.mpf(10) ** -35
    for n in (1, 2, 5):
        ea, eb = boundary(n, system=a, digits=25), boundary(n, system=b, digits=25)
        for T in (ea.lower, ea.upper, eb.lower, eb.upper):
            ok, _ = _independent_root_near(T, None, None, "exact", b, n, T * mpmath.mpf("1e-22"))
            assert ok


@pytest.mark.parametrize("m", ["0.05", "0.3", "0.7", "0.99"])  # 0.8 is the 4/5 closing
@pytest.mark.parametrize("n", [1, 2, 3, 4, 9])
def test_meissner_classical_trace_condition(m, n):
    """Meissner equation, D = 1/2: the certified edges satisfy the classical condition
    2 cos a cos b - (w1/w2 + w2/w1) sin a sin b = 2 (-1)^n (a sign change across each edge)."""

    def classical(T):
        mm = mpmath.mpf(Fraction(m).numerator) / Fraction(m).denominator
        w1 = 2 * mpmath.pi * mpmath.sqrt(1 - mm)  # omega0 = 2 pi: stiffness (1 - m) in phase 1
        w2 = 2 * mpmath.pi * mpmath.sqrt(1 + mm)
        a, b = w1 * T / 2, w2 * T / 2
        tr = 2 * mpmath.cos(a) * mpmath.cos(b) - (w1 / w2 + w2 / w1) * mpmath.sin(a) * mpmath.sin(b)
        return tr - 2 * (-1) ** n

    res = boundary(n, m, system="meissner", digits=30)
    with mpmath.workdps(50):
        for T in (res.lower, res.upper):
            d = T * mpmath.mpf("1e-26")
            assert classical(T - d) * classical(T + d) < 0


@pytest.mark.parametrize("m", ["1/1000000000000", "3/10", "999/1000"])
@pytest.mark.parametrize("Q", [None, "7", "1/2"])
def test_general_parameters_match_the_paper_fast_path(m, Q):
    """The general route (generated from the description) and the paper's hand-checked
    rearrangements give the same normal-form parameters to 30 digits, also where m is tiny."""
    from verify.system_params import normal_values

    B = backend("mpmath")
    mq = Fraction(m)
    Qf = None if Q is None else Fraction(Q)
    with mpmath.workdps(30):
        for damping in ("exact", "paper"):
            if Qf is not None and damping == "exact" and 4 * Qf * Qf <= 1 + mq:
                continue
            fast = normal_params(mq, Qf, damping, B)
            general = normal_values(PAPER, mq, Qf, damping, B)
            for key in ("r", "r2", "u", "beta", "w", "g", "w0", "dinv", "bm"):
                a, b = getattr(fast, key), general[key]
                assert abs(a - b) <= mpmath.mpf(10) ** -28 * max(abs(a), abs(b), 10**-300), key


@pytest.mark.parametrize(
    "sysv",
    [
        system("torsion"),
        system("meissner", duty="1/3"),
        system("pendulum", duty="1/3"),
        custom(("3/2", "1/5"), jump="2", duty="2/5"),
    ],
    ids=lambda s: s.label,
)
def test_exact_atoms_from_integers_are_the_rational_ones(sysv):
    """The exact atoms of the parameter forms, computed from the integers of ``m = p/q`` and
    ``Q = P/R``, are the rational atoms rounded once: the same balls, bit for bit (reference:
    the atoms' text in rational arithmetic, ``atoms | fraction``), for depths of 1 to 40 digits,
    next to 0 and 1."""
    from verify.system_params import _atoms, _compiled, canonical

    rng = random.Random(7)
    sysv = canonical(sysv)
    B = backend("arb")
    depths = [Fraction(1, 10**40), Fraction(10**40 - 1, 10**40), Fraction(3, 10)]
    depths += [Fraction(rng.randrange(1, 10**k), 10**k) for k in range(1, 41, 3)]
    for damping in ("none", "paper", "exact"):
        _, rational, _ = _compiled(sysv, damping)
        for m in depths:
            Q = (
                None
                if damping == "none"
                else Fraction(rng.randrange(2, 10**6), rng.randrange(1, 99))
            )
            mm = m if sysv.uses_depth else None
            got = _atoms(sysv, damping, mm, Q, B)
            want = rational(Fraction(0) if mm is None else m, Fraction(1) if Q is None else Q)
            assert len(got) == len(want)
            for a, w in zip(got, want, strict=True):
                b = B.num(Fraction(w))
                assert a.mid() == b.mid() and a.rad() == b.rad(), (m, Q, a, w)


def test_paper_system_unchanged():
    """The paper's system through the new interface gives the same digits as before
    (reference: `paramres boundary --order 3 --m 3/5 --digits 40`, the closing of eq. 19's
    interval at T = T1 = sqrt(8/5), and --order 2 --m 1e-12 as printed in the README)."""
    b = boundary(3, "3/5", digits=40, system="pendulum", duty="1/2")
    assert mpmath.nstr(b.lower, 40) == "1.264911064067351732799557417773087413488"
    b2 = boundary(2, "1e-12", digits=30)
    assert mpmath.nstr(b2.delta_lower, 30) == "-7.49999999999999999999998722825e-25"


# ---------------------------------------------------------------------------------------------
# closings of any duty


@pytest.mark.parametrize(
    "sysv",
    [system("pendulum", duty="1/3"), system("meissner", duty="3/5"), system("torsion")],
    ids=lambda s: s.label,
)
def test_closings_are_multiples_of_identity(sysv):
    """At every listed closing M = (-1)^n I to 1e-35 (Floquet route at the listed 40-digit T)."""
    from analytic.closings import closings

    result = closings(9, sysv)
    assert result.proven and len(result) > 0
    for c in result:
        with mpmath.workdps(60):
            M = monodromy_matrix(c.m, mpmath.mpf(c.T), system=sysv, dps=60)
            target = (-1) ** c.order
            err = max(abs(M[0, 0] - target), abs(M[1, 1] - target), abs(M[0, 1]), abs(M[1, 0]))
            assert err < mpmath.mpf(10) ** -35, (c.order, c.m, err)


@pytest.mark.parametrize(
    "sysv", [system("pendulum", duty="1/3"), system("meissner", duty="3/5")], ids=lambda s: s.label
)
def test_no_unlisted_closings(sysv):
    """A scan of the width over 300 depths per order finds a near-zero width only next to a
    listed closing (the width is V-shaped there: the edges exchange)."""
    from analytic.closings import closings

    listed = {}
    for c in closings(6, sysv):
        listed.setdefault(c.order, []).append(float(c.m))
    for n in range(1, 7):
        ms = [Fraction(i, 301) for i in range(1, 301)]
        widths = [float(boundary(n, m, system=sysv, digits=8).width) for m in ms]
        for i in range(1, len(ms) - 1):
            w = widths[i]
            if w < widths[i - 1] and w < widths[i + 1] and w < 0.2 * max(widths):
                near = [x for x in listed.get(n, []) if abs(x - float(ms[i])) < 2 / 301]
                assert near, f"order {n}: unlisted minimum of the width at m = {float(ms[i])}"
        for x in listed.get(n, []):  # and each listed closing is a minimum of the scan
            j = min(range(len(ms)), key=lambda i: abs(float(ms[i]) - x))
            assert widths[j] < 0.2 * max(widths)


def test_custom_closings():
    """A custom system closes only where its ratio fits: omega2/omega1 = 2 at D = 1/2 closes
    orders 3, 6, 9, ... with T = a/(2 D sqrt(W1))."""
    from analytic.closings import closings

    result = closings(9, custom(("1", "4")))
    assert result.proven
    assert [(c.order, c.T) for c in result] == [(3, "1"), (6, "2"), (9, "3")]


# ---------------------------------------------------------------------------------------------
# certified multipliers


@pytest.mark.parametrize(
    "args",
    [
        ("1.45", "0.3", None, "exact", PAPER),
        ("1.2", "0.3", None, "exact", PAPER),
        ("1.2", "0.3", "0.3", "exact", system("meissner", duty="1/3")),
        ("0.9", "0.6", "5", "paper", system("torsion", duty="0.7")),
        ("2", None, None, "exact", custom(("4/5", "6/5"), jump=1, duty="1/3")),
        ("0.501", "0.999999", "3", "exact", PAPER),
    ],
)
def test_multipliers_digits_against_mpmath(args):
    """Every printed digit of the certified multipliers agrees with the Floquet route at 60
    digits (an independent evaluation of the same monodromy)."""
    T, m, Q, damping, sysv = args
    res = multipliers(T, m, Q=Q, damping=damping, digits=30, system=sysv)
    with mpmath.workdps(60):
        ref = floquet_multipliers(m, T, Q, damping, system=sysv, dps=60)
        ref = sorted(ref, key=lambda z: (-abs(z), -mpmath.im(z)))
        own = mpmath.mpf(10) ** -55  # the reference's own rounding at 60 digits
        for (re_, im_), rad, z in zip(res.mu, res.radii, ref, strict=True):
            assert abs(re_ - mpmath.re(z)) <= rad + own and abs(im_ - mpmath.im(z)) <= rad + own
            assert rad <= mpmath.mpf(10) ** -29 * max(abs(z), 1)
        big = max(abs(z) for z in ref)
        assert abs(res.modulus - big) <= res.modulus_radius + own
        assert abs(res.growth - mpmath.log(big)) <= res.growth_radius + own


def test_multipliers_text_shows_only_proven_digits():
    """Printed digits come from the proven balls: the imaginary part at T = 1.2, m = 0.3 is
    0.9994643431384090841571... (mpmath at 60 digits, the Floquet route)."""
    text = str(multipliers("1.2", "0.3", digits=30))
    assert "0.999464343138409084157138596696 i" in text
    assert "stable" in text


def test_multipliers_decide_growth_far_below_double_precision():
    """At m = 1e-10, T = 1 (inside the second interval, whose width is about 1e-20) the proven
    |mu|max = 1 + 4.08e-20 decides instability, whatever mpmath's working precision."""
    res = multipliers("1", "1e-10", digits=30)
    with mpmath.workdps(15):
        assert res.unstable is True
    assert "unstable" in str(res) and "undecided" not in str(res)
    assert res.as_json()["unstable"] is True
    # just outside the upper edge 1.00000000000000000000375...: the pair on the unit circle
    assert multipliers("1.00000000000000000001", "1e-10", digits=30).unstable is False


@pytest.mark.parametrize(
    "kwargs, word",
    [
        ({"system": "custom"}, "omega_sq"),
        ({"system": "pendulum", "duty": "1"}, "0 < D < 1"),
        ({"system": "pendulum", "duty": "0"}, "0 < D < 1"),
        ({"system": "swing"}, "not one of"),
        ({"system": custom(("1", "2")), "m": "0.3"}, "no depth"),
    ],
)
def test_bad_system_input(kwargs, word):
    kw = dict(kwargs)
    m = kw.pop("m", "0.3" if kw.get("system") != "custom" else None)
    if isinstance(kw.get("system"), str) and kw["system"] == "custom":
        m = None
    with pytest.raises(InputError, match=word):
        boundary(1, m, **kw)


def test_bad_custom_values():
    for bad in [("0", "1"), ("1",), ("-1", "2"), ("a", "2")]:
        with pytest.raises(InputError):
            custom(bad)
    with pytest.raises(InputError, match="k > 0"):
        custom(("1", "2"), jump="-1")


# ---------------------------------------------------------------------------------------------
# series in m for any duty


@pytest.mark.parametrize("n", [1, 2, 3])
def test_family_series_reproduce_the_paper_series(n):
    """The family's series solver (fixed-point steps on truncated series, parameters from the
    family's definitions), applied to the paper's system, gives the paper's series
    (:func:`analytic.expansions.edge_series`, a different derivation: the ring of Laurent
    polynomials and Newton steps)."""
    import sympy as sp

    from analytic.expansions import edge_series
    from analytic.family_series import family_edge_series

    K = 5
    ours = family_edge_series(n, K, "T0", PAPER)
    ref = edge_series(n, K)
    for edge in ("lower", "upper"):
        assert sp.simplify(sp.expand(ours.in_T0[edge] - ref.in_T0[edge])) == 0


@pytest.mark.parametrize("name", ["pendulum", "torsion", "meissner"])
@pytest.mark.parametrize("duty", ["1/2", "1/3", "3/4"])
def test_family_series_parameters_equal_sympy_series(name, duty):
    """The coefficients of ``r, beta, w`` in powers of ``m`` that the family's series solver takes
    (the definitions evaluated in truncated power-series arithmetic) are exactly those of
    ``sympy.series`` of the same definitions (compared with ``==``)."""
    import sympy as sp

    from analytic.family import parameter_forms
    from analytic.family_series import _parameters
    from analytic.model import Damping, S

    K = 3
    sysv = system(name, duty=duty)
    ours = _parameters(sysv, K)
    defs = parameter_forms(sysv, Damping.NONE).definitions
    for key in ("r", "beta", "w"):
        ref = sp.expand(sp.series(defs[key], S.m, 0, K + 1).removeO())
        assert ours[key] == [sp.expand(ref.coeff(S.m, k)) for k in range(K + 1)], key


@pytest.mark.parametrize(
    "name, duty, n", [("meissner", "1/3", 2), ("torsion", "1/2", 1), ("pendulum", "3/4", 3)]
)
@pytest.mark.parametrize("K", [2, 4])
def test_family_series_error_falls_like_m_to_the_K_plus_1(name, duty, n, K):
    """The truncation error against the certified edges falls like m^(K+1) (log-log slope between
    m = 1e-3 and 1e-4 at least K + 1 - 0.15)."""
    import sympy as sp

    from analytic.expansions import edge_series
    from analytic.model import S

    sysv = system(name, duty=duty)
    es = edge_series(n, K, system=sysv)
    errs = []
    for m in (Fraction(1, 1000), Fraction(1, 10000)):
        b = boundary(n, m, system=sysv, digits=40)
        with mpmath.workdps(40):
            val = sp.N(es.lower.subs(S.m, sp.Rational(m.numerator, m.denominator)), 40)
            errs.append(abs(mpmath.mpf(str(val)) - b.lower))
    slope = mpmath.log10(errs[0] / errs[1])
    assert slope > K + 1 - 0.15, (errs, slope)


# ---------------------------------------------------------------------------------------------
# the double grid for every member


@pytest.mark.parametrize(
    "name, duty", [("meissner", "1/3"), ("torsion", "0.7"), ("pendulum", "0.25")]
)
@pytest.mark.parametrize("Q, damping", [(None, "exact"), (7, "paper"), (7, "exact")])
def test_family_grid_accuracy(name, duty, Q, damping):
    """boundary_grid for other members meets the same 1e-14 relative bound against the
    certified edges (log-spaced depths toward both ends; fixed seed)."""
    import numpy as np

    from verify.grid import boundary_grid

    rng = np.random.default_rng(20261122)
    ms = np.concatenate([10 ** rng.uniform(-12, -0.05, 12), 1 - 10 ** rng.uniform(-7, -1, 6)])
    orders = [1, 2, 3, 12]
    sysv = system(name, duty=duty)
    g = boundary_grid(orders, ms, Q=Q, damping=damping, system=sysv)
    bad = []
    for i, n in enumerate(orders):
        for j, m in enumerate(ms):
            b = boundary(n, float(m), Q=Q, damping=damping, system=sysv, digits=20)
            if not b.exists:
                if not np.isnan(g[i, 0, j]):
                    bad.append((n, m, "grid has an interval, certified has none"))
                continue
            for k, T in enumerate((b.lower, b.upper)):
                rel = abs(g[i, k, j] - float(T)) / float(T)
                if not rel <= 1e-14:
                    bad.append((n, m, k, g[i, k, j], T, rel))
    assert not bad, bad


def test_cli_family_options(capsys):
    """Every command with a model takes --system/--duty; JSON echoes them."""
    import json

    from reports.cli import main

    assert (
        main(
            [
                "table",
                "--orders",
                "1-2",
                "--m",
                "0.1:0.2:0.1",
                "--system",
                "torsion",
                "--duty",
                "1/3",
                "--format",
                "json",
            ]
        )
        == 0
    )
    doc = json.loads(capsys.readouterr().out)
    assert doc["system"] == "torsion" and doc["duty"] == "1/3" and len(doc["rows"]) == 4
    assert (
        main(
            [
                "boundary",
                "--order",
                "2",
                "--system",
                "custom",
                "--omega-sq",
                "4/5,6/5",
                "--duty",
                "1/3",
                "--json",
            ]
        )
        == 0
    )
    doc = json.loads(capsys.readouterr().out)
    assert doc["omega_sq"] == ["4/5", "6/5"] and doc["m"] is None and doc["exists"]
    assert main(["multipliers", "--T", "1.45", "--m", "0.3", "--json"]) == 0
    doc = json.loads(capsys.readouterr().out)
    assert doc["unstable"] is True and doc["system"] == "pendulum"
    assert main(["crossings", "--max-order", "5", "--duty", "1/3", "--json"]) == 0
    doc = json.loads(capsys.readouterr().out)
    assert doc["duty"] == "1/3" and [c["order"] for c in doc["closings"]] == [4, 5]
    assert (
        main(["series", "--order", "2", "--terms", "2", "--system", "meissner", "--duty", "1/3"])
        == 0
    )
    assert "meissner, D = 1/3" in capsys.readouterr().out


@pytest.mark.parametrize(
    "argv, word",
    [
        (["boundary", "--order", "1", "--m", "0.3", "--duty", "1"], "0 < D < 1"),
        (["boundary", "--order", "1", "--m", "0.3", "--duty=-1/2"], "0 < D < 1"),
        (["boundary", "--order", "1", "--m", "0.3", "--omega-sq", "1,2"], "only for system"),
        (
            ["boundary", "--order", "1", "--system", "custom", "--omega-sq", "1,2", "--m", "0.3"],
            "no depth",
        ),
        (["boundary", "--order", "1", "--system", "custom", "--omega-sq", "0,2"], "not positive"),
        (["boundary", "--order", "1", "--system", "custom", "--omega-sq", "1"], "two numbers"),
        (
            ["boundary", "--order", "1", "--system", "custom", "--omega-sq", "1,2", "--jump", "0"],
            "k > 0",
        ),
        (["boundary", "--order", "1", "--system", "torsion"], "needs --m"),
        (["multipliers", "--T", "1", "--m", "0.3", "--system", "swing"], "not one of"),
        (
            [
                "table",
                "--orders",
                "1",
                "--m",
                "0.1:0.2:0.1",
                "--system",
                "meissner",
                "--tol",
                "1e-8",
            ],
            "--digits",
        ),
        (["series", "--order", "odd", "--system", "torsion"], "integer order"),
        (["crossings", "--max-order", "5", "--duty", "2"], "0 < D < 1"),
    ],
)
def test_cli_family_bad_input(argv, word, capsys):
    from reports.cli import main

    assert main(argv) == 2
    err = capsys.readouterr().err
    assert err.startswith("paramres: error:") and word in err and "Traceback" not in err


# ---------------------------------------------------------------------------------------------
# time domain for every member


@pytest.mark.parametrize(
    "sysv, n, Q",
    [
        (system("meissner", duty="1/3"), 1, None),
        (system("meissner", duty="1/3"), 2, None),
        (system("torsion", duty="0.7"), 1, "9"),
        (system("pendulum", duty="1/3"), 3, None),
        (custom(("4/5", "6/5"), duty="1/3"), 2, None),
    ],
    ids=lambda v: getattr(v, "label", str(v)),
)
@pytest.mark.parametrize("edge", ["lower", "upper"])
def test_simulation_closes_on_every_members_edges(sysv, n, Q, edge):
    """Started on a certified edge (from the Floquet eigenvector), the piecewise-exact propagation
    of the system's segments and switches returns to its start after one period (even n) or two
    (odd n) to the working precision (30 digits)."""
    from verify.timedomain import simulate

    m = None if not sysv.uses_depth else "0.3"
    sim = simulate(n, m, edge=edge, Q=Q, system=sysv, digits=30)
    assert sim.closure_error < 1e-35


def test_simulated_growth_matches_the_multiplier_for_a_member():
    """Inside an interval the growth measured on the trajectory equals the Floquet multiplier
    (Meissner, D = 1/3, T = 0.5 T0, m = 0.3) to 20 digits."""
    from verify.timedomain import simulate

    sim = simulate(1, "0.3", T="0.5", system="meissner", duty="1/3", periods=12)
    assert sim.growth_per_period > 1 and sim.growth_agreement < 1e-20


# ---------------------------------------------------------------------------------------------
# the derivation for the family


@pytest.mark.parametrize("damping", ["none", "paper", "exact"])
def test_family_chain_is_proven(damping):
    """det M = p^2, the trace form and the stitching determinant = F det(M - sigma I) (F > 0)
    hold with symbolic duty D and jump k, for both parities."""
    from analytic.family import det_link, stitching_link, trace_link
    from analytic.stitching import Parity

    assert det_link(damping).verdict.holds
    assert trace_link(damping).verdict.holds
    for parity in (Parity.ODD, Parity.EVEN):
        assert stitching_link(parity, damping).verdict.holds


@pytest.mark.parametrize(
    "name, duty, n", [("meissner", "1/3", 1), ("torsion", "0.7", 2), ("pendulum", "1/4", 3)]
)
def test_stationary_start_of_the_family(name, duty, n):
    """On each frictionless edge the Floquet eigenvector for (-1)^n (the independent route) has
    phi'(0)/phi(0) equal to one of the derived ratios omega1 tan(omega1 D T/2) or
    -omega1 cot(omega1 D T/2), evaluated at the certified edge (30 digits)."""
    import sympy as sp

    from analytic.family import D as Dsym
    from analytic.family import stationary_ratio
    from analytic.model import S
    from verify.floquet import floquet_vector

    sysv = system(name, duty=duty)
    b = boundary(n, "0.4", system=sysv, digits=35)
    W1 = sysv.omega1_sq(Fraction(4, 10))
    for T in (b.lower, b.upper):
        with mpmath.workdps(40):
            M = monodromy_matrix("0.4", T, system=sysv, dps=40)
            v = floquet_vector(M, mpmath.mpf((-1) ** n))
            got = v[1] / v[0]
            cands = []
            for shape in ("cos", "sin"):
                expr = stationary_ratio(shape).subs(
                    {
                        Dsym: sp.Rational(sysv.duty.numerator, sysv.duty.denominator),
                        S.omega1: 2 * sp.pi * sp.sqrt(sp.Rational(W1.numerator, W1.denominator)),
                        S.T: sp.Float(mpmath.nstr(T, 40), 40),
                    }
                )
                cands.append(mpmath.mpf(str(sp.N(expr, 40))))
            assert min(abs(got - c) / abs(c) for c in cands) < mpmath.mpf(10) ** -25
