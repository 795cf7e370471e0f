"""The automatic choice of method with a tolerance: ``boundary(..., tol=...)``, ``--tol``.

Every returned value is compared with an independent certified reference: the edges of
:func:`verify.solve.boundary` at ``D`` digits (interval Newton on the per-edge equations, see
``verify/certify.py``), ``D`` at least ten more than the tolerance asks for; a value passes when
``|returned - reference| <= tol |reference|`` for both edges (the reference's own radius is below
``10**-(D+2)`` relative, far below the tolerance).  The choices themselves (series at small depth
and loose tolerance, double precision at 1e-13, the certified route beyond) are checked at and
next to the switch points.
"""

from __future__ import annotations

import csv
import io
import json
import math
import random
from fractions import Fraction

import mpmath
import pytest
from cli_run import run_cli as run

from verify import auto
from verify.inputs import InputError
from verify.solve import boundary


def reference(order, m, tol, Q=None, damping="exact"):
    """The certified edges with ten digits more than the tolerance needs (source: verify.solve
    .boundary, certified)."""
    digits = max(20, auto.certified_digits(mpmath.mpf(tol)) + 10)
    return boundary(order, m, Q=Q, damping=damping, digits=digits)


def assert_within(result, ref, tol, label=""):
    """Both edges within the relative tolerance of the reference; the failure message lists both
    values and the relative difference."""
    assert result.exists and ref.exists, label
    with mpmath.workdps(ref.digits + 10):
        t = mpmath.mpf(tol)
        for name in ("lower", "upper"):
            got, want = getattr(result, name), getattr(ref, name)
            rel = abs(got - want) / abs(want)
            assert rel <= t, (
                f"{label} {name}: returned {mpmath.nstr(got, 25)} vs reference "
                f"{mpmath.nstr(want, 25)}, relative difference {mpmath.nstr(rel, 3)} > tol {tol} "
                f"({result.method})"
            )


# ---------------------------------------------------------------------------------------------
# the choice


def test_series_at_small_depth_and_loose_tolerance():
    b = boundary(3, "0.01", tol=1e-8)
    assert b.method.startswith("series K=") and b.certified
    assert_within(b, reference(3, "0.01", 1e-8), 1e-8)


def test_double_at_1e13_and_certified_beyond():
    b13 = boundary(3, "0.3", tol=1e-13)
    assert b13.method == "double" and b13.certified
    assert_within(b13, reference(3, "0.3", 1e-13), 1e-13)
    b20 = boundary(3, "0.3", tol=1e-20)
    assert b20.method == "certified (22 digits)"  # two digits more: the printed ones meet tol too
    assert_within(b20, reference(3, "0.3", 1e-20), 1e-20)


def test_friction_always_takes_the_certified_route():
    b = boundary(1, "0.3", Q=10, tol=1e-6)
    assert b.method.startswith("certified") and b.exists
    assert_within(b, reference(1, "0.3", 1e-6, Q=10), 1e-6)
    below = boundary(1, "0.05", Q=10, damping="paper", tol=1e-6)  # threshold 0.0522 (eq. 38 ~)
    assert not below.exists and below.method.startswith("certified")


def test_switch_points_of_the_double_path():
    edge = 4 * auto.DOUBLE_ERROR
    on = boundary(3, "0.3", tol=edge)
    below = boundary(3, "0.3", tol=edge * (1 - 1e-9))
    assert on.method == "double" and below.method.startswith("certified")
    for b, t in ((on, edge), (below, edge * (1 - 1e-9))):
        assert_within(b, reference(3, "0.3", t), t)
    # a single point above NEAR_ONE_DEPTH skips the double path (order 1 loses digits there)
    near = boundary(1, "0.999", tol=1e-13)
    assert near.method.startswith("certified")
    assert_within(near, reference(1, "0.999", 1e-13), 1e-13)


def test_switch_points_between_series_orders():
    """The series order is the smallest whose predicted error (SAFETY x next-term estimate / |T|,
    recomputed here) is below half the fine tolerance, which steps at each power of ten: on both
    sides of each step the choice follows, and the result meets its tolerance."""
    m, mf = Fraction(1, 100), 0.01
    ks = set()
    for D in range(4, 12):  # fine tolerance >= FLOAT_SERIES_TOL: series in floats
        for tol in (mpmath.mpf(10) ** -D, mpmath.mpf(10) ** -D * (1 - mpmath.mpf("1e-9"))):
            goal = float(auto.fine_tolerance(tol)) / 2
            want = None
            floats = 2 * goal >= auto.FLOAT_SERIES_TOL  # else the double path comes first
            for K in auto.SERIES_TERMS if floats else ():
                lo = abs(auto.series_value(3, K, mf)[0])
                pred = auto.SAFETY * auto.series_estimate(3, K, mf) / lo + auto.FLOAT_ROUNDING
                if mf <= auto.series_validity(3)[K] and pred <= goal:
                    want = K
                    break
            c = auto.choose(3, m, None, tol)
            assert (c.K if c.kind == "series" else None) == want, (D, tol, c)
            ks.add(want)
            b = boundary(3, m, tol=tol)
            assert_within(b, reference(3, m, tol), tol, f"tol={tol}")
    assert len(ks) >= 3  # the steps do change the order
    # one step further a series would need mpmath: the double path is cheaper and is taken
    assert auto.choose(3, m, None, mpmath.mpf("9.99e-12")).kind == "double"


def test_series_in_floats_then_double_then_series_in_mpmath():
    """Down to the tolerance whose fine tolerance floats resolve the series is evaluated in
    floats (53-bit values); below it the double path is cheaper; below what doubles can give, the
    series in mpmath (values with more bits) is, still before the certified route."""
    for tol, kind, wide in (
        ("1e-11", "series", False),
        ("9.99e-12", "double", False),
        ("1e-20", "series", True),
        ("1e-45", "series", True),
    ):
        b = boundary(2, "1e-6", tol=tol)
        assert b.method.split(" ")[0] == kind, (tol, b.method)
        assert (b.lower.man.bit_length() > 53) == wide, (tol, b.lower)
        assert_within(b, reference(2, "1e-6", tol), tol)


@pytest.mark.parametrize(
    "order, m, tol",
    [
        (1, "1e-12", "1e-30"),  # tiny m
        (2, "1e-12", "1e-8"),
        (2, "1e-12", "1e-60"),
        (3, "3/5", "1e-10"),  # a closing: both edges equal
        (3, "0.600000001", "1e-12"),  # next to it
        (5, "5/13", "1e-20"),
        (1, "0.999", "1e-6"),  # m near 1
        (2, "0.999", "1e-30"),
        (100, "0.01", "1e-10"),  # high order
        (100, "0.3", "1e-14"),
    ],
)
def test_hard_cases(order, m, tol):
    b = boundary(order, m, tol=tol)
    assert b.certified and b.radius is not None
    assert_within(b, reference(order, m, tol), tol, f"n={order} m={m}")


def test_random_orders_depths_and_tolerances():
    """Random (order, m, tol), fixed seed: depths log-spaced from 1e-12 to 0.999, tolerances from
    1e-40 to 0.05; every method must be used somewhere and every value meet its tolerance."""
    rng = random.Random(20261121)
    used = set()
    for _ in range(45):
        order = rng.choice([1, 2, 3, 4, 5, 6, 7, 12, 100])
        m = f"{10 ** rng.uniform(-12, math.log10(0.999)):.3g}"
        tol = f"{10 ** rng.uniform(-40, math.log10(0.05)):.2g}"
        b = boundary(order, m, tol=tol)
        used.add(b.method.split(" ")[0])
        assert_within(b, reference(order, m, tol), tol, f"n={order} m={m} tol={tol}")
    assert {"series", "double", "certified"} <= used


def test_printed_digits_meet_the_tolerance_too():
    """Values are proven to about tol/25 where the method allows, so that the proven digits that
    are printed (rounded: half a unit of the last) are within tol as well."""
    for order, m, tol in ((1, "0.3", 0.1), (3, "0.01", 1e-8), (3, "0.3", 3e-11), (2, "0.2", 1e-25)):
        b = boundary(order, m, tol=tol)
        ref = reference(order, m, tol)
        text = b.as_json()
        for name in ("lower", "upper"):
            with mpmath.workdps(60):
                printed = mpmath.mpf(text[name])
                want = getattr(ref, name)
                assert abs(printed - want) <= mpmath.mpf(tol) * want, (order, m, tol, b.method)
        assert len(text["lower"].replace("0.", "", 1).lstrip("0")) >= 2


# ---------------------------------------------------------------------------------------------
# the pieces


def test_series_coefficients_are_those_of_edge_series():
    import sympy as sp

    from analytic.expansions import edge_series
    from analytic.model import S

    for order, K in ((1, 3), (4, 6)):
        es = edge_series(order, K)
        coeffs = auto.series_coefficients(order)
        for edge in ("lower", "upper"):
            poly = sp.Poly(sp.expand(es.in_T0[edge]), S.m)
            for (k,), c in poly.terms():
                with mpmath.workdps(45):
                    want = mpmath.mpf(str(sp.N(c, 40)))
                    assert mpmath.almosteq(coeffs[edge][k], want, rel_eps=1e-35, abs_eps=1e-38)


def test_next_term_estimate_bounds_the_error_where_validated():
    """The predicted error (SAFETY x estimate) exceeds the true error at random depths inside
    the validated range (reference: certified edges at 60 digits: the estimates go down to
    1e-52, below what a 40-digit reference promises)."""
    rng = random.Random(7)
    for order in (1, 2, 5):
        valid = auto.series_validity(order)
        for K in (2, 5, 8):
            assert valid[K] >= 0.1  # the validation is not vacuous
            for _ in range(3):
                m = Fraction(f"{10 ** rng.uniform(-6, math.log10(valid[K])):.3g}")
                ref = boundary(order, m, digits=60)
                with mpmath.workdps(70):
                    lo, hi = auto.series_value(order, K, m, exact=True)
                    err = max(abs(lo - ref.lower) / ref.lower, abs(hi - ref.upper) / ref.upper)
                    mm = mpmath.mpf(m.numerator) / m.denominator
                    bound = auto.SAFETY * auto.series_estimate(order, K, mm) / lo
                    assert err <= bound, (order, K, float(m), float(err), float(bound))


def test_proof_refuses_values_outside_the_tolerance():
    ref = boundary(3, "0.3", digits=30)
    good = (float(ref.lower), float(ref.upper))
    assert auto.prove_within(3, Fraction(3, 10), good, mpmath.mpf("1e-14")) is not None
    bad = (float(ref.lower) * (1 + 3e-10), float(ref.upper))
    assert auto.prove_within(3, Fraction(3, 10), bad, mpmath.mpf("1e-10")) is None
    # both values on the same edge: one equation's root is not near either value
    same = (float(ref.lower), float(ref.lower))
    assert auto.prove_within(3, Fraction(3, 10), same, mpmath.mpf("1e-10")) is None


def test_table_with_a_tolerance_uses_the_grid_and_proves_every_entry():
    ms = [Fraction(1, 100), Fraction(3, 10), Fraction(999, 1000)]
    rows = auto.boundaries_tol([1, 2], ms, tol="1e-13")
    assert [b.order for b in rows] == [1, 1, 1, 2, 2, 2]
    # in a table the polished grid serves m near 1 as well
    assert rows[2].method == "double" and rows[5].method == "double"
    for b in rows:
        assert_within(b, reference(b.order, b.m, 1e-13), 1e-13, f"n={b.order} m={b.m}")


def test_bad_requests():
    with pytest.raises(InputError):
        boundary(3, "0.3", tol=1e-8, method="fixedpoint")
    with pytest.raises(InputError):
        boundary(3, "0.3", method="auto")
    for bad in (0, 1, "nan", -1e-8, "1e-20000", "x"):
        with pytest.raises(InputError):
            boundary(3, "0.3", tol=bad)


# ---------------------------------------------------------------------------------------------
# command line


def test_cli_boundary_tol(capsys):
    code, out, err = run(capsys, "boundary", "--order", "3", "--m", "0.01", "--tol", "1e-8")
    assert code == 0 and err == "" and "series K=" in out
    code, out, _ = run(capsys, "boundary", "--order", "3", "--m", "0.3", "--tol", "1e-13", "--json")
    data = json.loads(out)
    assert code == 0 and data["method"] == "double" and data["tolerance"] == "1e-13"
    assert data["certified"]
    ref = reference(3, "0.3", 1e-13)
    assert abs(mpmath.mpf(data["lower"]) - ref.lower) <= mpmath.mpf("1e-13") * ref.lower


def test_cli_table_tol(capsys):
    code, out, err = run(
        capsys, "table", "--orders", "1-2", "--m", "0.01:0.03:0.01", "--tol", "1e-9"
    )
    assert code == 0 and err == ""
    rows = list(csv.reader(io.StringIO(out)))
    assert rows[0] == [
        "order",
        "m",
        "lower",
        "upper",
        "delta_lower",
        "delta_upper",
        "error_bound",  # was "radius", the internal ball's, smaller than the printed digits' error
        "method",
    ]
    assert len(rows) == 7
    for row in rows[1:]:
        ref = reference(int(row[0]), row[1], 1e-9)
        for k, name in ((2, "lower"), (3, "upper")):
            # the printed numbers themselves meet the tolerance
            assert abs(mpmath.mpf(row[k]) - getattr(ref, name)) <= 1e-9 * getattr(ref, name)
    code, out, _ = run(
        capsys, "table", "--orders", "1", "--m", "0.1:0.2:0.1", "--tol", "1e-6", "--format", "json"
    )
    data = json.loads(out)
    assert data["method"] == "auto" and data["tolerance"] == "1e-6"
    assert data["columns"][-1] == "method" and len(data["rows"]) == 2


@pytest.mark.parametrize(
    "argv",
    [
        ["boundary", "--order", "3", "--m", "0.3", "--tol", "1e-8", "--digits", "20"],
        ["boundary", "--order", "3", "--m", "0.3", "--tol", "1"],
        ["boundary", "--order", "3", "--m", "0.3", "--tol", "1e-8", "--method", "fixedpoint"],
        ["table", "--orders", "1", "--m", "0.1:0.2:0.1", "--tol", "1e-8", "--digits", "20"],
        ["table", "--orders", "1", "--m", "0.1:0.2:0.1", "--tol", "abc"],
    ],
)
def test_cli_bad_tolerances(capsys, argv):
    code, out, err = run(capsys, *argv)
    assert code == 2 and err.startswith("paramres: error:") and "Traceback" not in err
