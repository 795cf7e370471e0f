"""The one-function paths for certified edges give the very balls of the general path.

:func:`verify.undamped._lean` (no friction) and :func:`verify.hump._lean_normal` (the normal form
with friction) fold the float start, the one interval Newton test and the result into one
function where the general path (:func:`verify.certify.quick_root`, :func:`verify.hump._solve_hump`,
:func:`verify.enclosure.edges_result`) takes the same steps through more calls.  The reference is
the general path itself, with the short path switched off: every ball (midpoint and radius, bit
for bit), every printed text and the error bound must be the same.  Where a step of the short path
does not succeed at once it hands over to the general path, so the cases include depths next to
``m = 1`` and ``m -> 0``, closings, and friction near a threshold.
"""

from __future__ import annotations

import pytest

import verify.hump as hump
import verify.undamped as undamped
from analytic.system import custom
from verify.inputs import as_system
from verify.solve import boundary

DEPTHS = ("1e-12", "1e-6", "0.05", "3/10", "3/5", "0.77", "0.9", "0.999", "0.999999")


def _balls(b):
    """Midpoints and radii of the four balls as exact integer pairs."""
    out = []
    for x in b._balls:
        out.append(tuple(int(v) for v in x.mid().man_exp()))
        out.append(tuple(int(v) for v in x.rad().man_exp()) if x.rad() != 0 else (0, 0))
    return tuple(out)


def _same(fast, slow):
    assert fast.as_json() == slow.as_json()
    assert str(fast) == str(slow)
    if "_balls" in fast.__dict__ and "_balls" in slow.__dict__:
        assert _balls(fast) == _balls(slow)


def _outcome(*args, **kw):
    """The boundary, or the refusal's text (too close to a threshold: both paths refuse alike)."""
    try:
        return boundary(*args, **kw)
    except ArithmeticError as exc:
        return repr(exc)


def _compare(monkeypatch, modules, *args, **kw):
    """The short paths of ``modules`` against the general path, switched on and off."""
    fast = _outcome(*args, **kw)
    with monkeypatch.context() as mp:
        for mod in modules:
            mp.setattr(mod, "_LEAN_BITS", 0)
        slow = _outcome(*args, **kw)
    if isinstance(fast, str) or isinstance(slow, str):
        assert fast == slow
    else:
        _same(fast, slow)


@pytest.mark.parametrize("digits", [5, 12, 15, 20, 26, 50, 120, 400])
@pytest.mark.parametrize("order", [1, 2, 3, 6])
def test_undamped_lean_is_general(monkeypatch, order, digits):
    for m in DEPTHS:
        fast = boundary(order, m, digits=digits)
        with monkeypatch.context() as mp:
            mp.setattr(undamped, "_LEAN_BITS", 0)
            slow = boundary(order, m, digits=digits)
        _same(fast, slow)


@pytest.mark.parametrize("damping", ["exact", "paper"])
@pytest.mark.parametrize("digits", [5, 15, 26, 50, 120])
@pytest.mark.parametrize("order", [1, 2, 3, 4])
def test_friction_lean_is_general(monkeypatch, order, digits, damping):
    for m in ("0.05", "3/10", "0.6", "0.9", "0.999"):
        for Q in ("3/5", "2", "7", "30", "1000"):
            _compare(monkeypatch, (hump,), order, m, Q=Q, damping=damping, digits=digits)


SYSTEMS = (
    {"system": "torsion"},
    {"system": "meissner"},
    {"duty": "1/3"},
    {"system": "meissner", "duty": "1/3"},
    {"system": custom(("4/5", "6/5"), jump="3/2", duty="2/5")},
)


@pytest.mark.parametrize("kw", SYSTEMS, ids=lambda kw: "-".join(str(v)[:8] for v in kw.values()))
@pytest.mark.parametrize("digits", [15, 50])
def test_lean_paths_are_general_for_every_system(monkeypatch, kw, digits):
    """The other members of the family take the same short paths, with and without friction:
    the same balls as their general path."""
    for order in (1, 2, 3):
        depthless = getattr(kw.get("system"), "uses_depth", True) is False
        for m in (None,) if depthless else ("0.05", "3/10", "0.9"):
            for Q in (None, "2", "7", "1000", "100000"):
                for damping in ("exact", "paper") if Q else ("exact",):
                    _compare(
                        monkeypatch,
                        (hump, undamped),
                        order,
                        m,
                        Q=Q,
                        damping=damping,
                        digits=digits,
                        **kw,
                    )


def test_lean_paths_are_taken(monkeypatch):
    """The short paths run where they are meant to (else the tests above compare nothing)."""
    used = []
    for mod, name in ((undamped, "_lean"), (hump, "_lean_normal")):
        real = getattr(mod, name)

        def spy(*a, real=real, name=name):
            out = real(*a)
            used.append((name, out is not None))
            return out

        monkeypatch.setattr(mod, name, spy)
    for digits in (15, 120):
        boundary(3, "3/10", digits=digits)
        boundary(3, "3/10", Q=7, digits=digits)
    assert used == [("_lean", True), ("_lean_normal", True)] * 2
    used.clear()
    for kw in SYSTEMS:
        m = "3/10" if getattr(kw.get("system"), "uses_depth", True) else None
        boundary(3, m, digits=15, **kw)
        boundary(3, m, Q=1000, digits=15, **kw)  # an interval for each (at Q = 7 not all)
    assert used == [("_lean", True), ("_lean_normal", True)] * len(SYSTEMS)
    # no interval: the short path proves D < 0 on the bracket itself
    used.clear()
    for kw, m, Q in (({}, "3/10", 3), (SYSTEMS[0], "3/10", 7), (SYSTEMS[-1], None, 30)):
        for digits in (15, 120):
            assert not boundary(3, m, Q=Q, digits=digits, **kw).exists
    assert used == [("_lean_normal", True)] * 6


@pytest.mark.parametrize("backend_name", ["arb", "math", "mpmath"])
def test_normal_tuple_reads_the_named_values(backend_name):
    """:func:`verify.system_params.normal_tuple` (the values read by position) against the
    compiled values read by name (:func:`verify.system_params._evaluate`) and combined as the
    normal form defines them, number for number: the built-in members and custom systems in
    either order of the phases, with ``beta`` of either sign (the swapped custom system has
    ``beta < 0``), without friction and with it in both models; and
    :func:`verify.system_params.undamped_values` is its frictionless part."""
    from fractions import Fraction

    import mpmath
    from flint import arb

    from verify.derived import backend
    from verify.params import _NORMAL_FIELDS
    from verify.system_params import (
        NORMAL_FIELDS,
        _evaluate,
        canonical,
        normal_tuple,
        undamped_values,
    )

    assert NORMAL_FIELDS == _NORMAL_FIELDS
    B = backend(backend_name)

    def by_name(system, m, Q, damping):
        v = _evaluate(system, m, Q, damping, B)
        r2 = v["r2"] if "r2" in v else v["r"] * v["r"]
        r = B.sqrt(r2) if "r2" in v else abs(v["r"])
        beta = v["beta"]
        bm = v["bm_pos"] if beta > 0 else v["bm_neg"]
        exact = Q is not None and damping == "exact"
        dinv = v["dw"] / (v["w"] * v["w0"]) if exact else 0
        return (r, r2, v["u"], abs(beta), v["w"], v.get("g", 0), v["w0"], dinv, bm)

    def same(a, b):
        if isinstance(a, arb):
            return a.mid() == b.mid() and a.rad() == b.rad() if isinstance(b, arb) else a == b
        return a == b

    systems = [
        as_system("torsion"),
        as_system("meissner"),
        as_system(duty="1/3"),
        as_system("meissner", duty="1/3"),
        custom(("4/5", "6/5"), jump="3/2", duty="2/5"),
        custom(("6/5", "4/5"), jump="3/2", duty="2/5"),  # the phases swapped: beta < 0
        custom(("4/5", "6/5"), jump="1/2"),
        custom(("1/3", "3"), jump="5"),
    ]
    depths = [Fraction(1, 20), Fraction(3, 10), Fraction(9, 10)]
    if backend_name != "arb":
        depths.append(0.3)
    signs = set()
    with mpmath.workdps(30):
        for system in systems:
            for m in depths if system.uses_depth else depths[1:2]:
                signs.add(
                    _evaluate(canonical(system), m, None, "none", backend("math"))["beta"] > 0
                )
                for Q, damping in ((None, "exact"), (Fraction(7), "exact"), (Fraction(7), "paper")):
                    got = normal_tuple(system, m, Q, damping, B)
                    want = by_name(canonical(system), m, Q, damping)
                    assert all(same(a, b) for a, b in zip(got, want, strict=True)), (system, m, Q)
                r, _, _, beta, w, _, _, _, bm = normal_tuple(system, m, None, "exact", B)
                lean = undamped_values(system, m, B)
                assert all(same(a, b) for a, b in zip(lean, (r, beta, w, bm), strict=True))
    assert signs == {True, False}


def test_a_paper_system_object_takes_the_papers_parameters():
    """A pendulum of duty 1/2 built anew (equal to the paper's system, not the same object)
    takes the paper's parameters in the frictionless short path, as :func:`verify.params
    .normal_params` gives them to the general path: the same balls as the paper's own object."""
    from fractions import Fraction

    from analytic.system import PAPER
    from analytic.system import system as make
    from verify.request import Request

    twin = make("pendulum", duty="1/2")
    assert twin is not PAPER and twin.is_paper
    m = Fraction(3, 10)
    for digits in (15, 40, 100):
        a = undamped.undamped(Request(3, m, None, "exact", digits, m, None, PAPER))
        b = undamped.undamped(Request(3, m, None, "exact", digits, m, None, twin))
        assert _balls(a) == _balls(b)


@pytest.mark.parametrize("Q, exists", [(7, True), (3, False), (4, False)])
def test_concave_bound_decides_only_where_there_is_no_interval(Q, exists):
    """Taylor's bound of the short path (:func:`verify.hump._concave_negative`) proves ``D < 0``
    on the bracket where there is no interval, and never where there is one (``D > 0`` at the
    float maximiser)."""
    from fractions import Fraction

    from flint import arb, ctx

    from verify.float_stage import float_edges
    from verify.params import normal_values

    n = 3
    _, _, D2, D01, _, Bend, _ = hump._normal_forms(-1)
    old = ctx.prec
    ctx.prec = 76
    try:
        r, r2, u, beta, _, g, _, _, _ = normal_values(
            Fraction(3, 10), Fraction(Q), "exact", hump._ARB
        )
        args = (arb.pi() * n / 2, r2, u, beta, g)
        a, b, top, dtop, _, _ = float_edges(n, *(float(v) for v in (r, r2, u, beta, g)))
        assert (dtop > 0) is exists
        got = hump._concave_negative(arb(a).union(arb(b)), arb(top), args, D01, D2, Bend)
    finally:
        ctx.prec = old
    assert got is (not exists)
    assert boundary(n, "3/10", Q=Q, digits=15).exists is exists


@pytest.mark.parametrize("m, Q", [("9/10", "7"), ("19/20", "30"), ("4/5", "7")])
def test_wide_bracket_starts_from_pieces(monkeypatch, m, Q):
    """At a deep modulation the bracket is wide and ``D`` convex at its ends: the float stage says
    so (:func:`verify.float_stage.wide_float_edges`), the short path's unimodality test starts
    from three pieces, proves the shape there, and with fewer evaluations than bisection from the
    whole bracket on the same balls."""
    calls = []
    real = hump._unimodal

    def spy(*a, **kw):
        calls.append((a, kw))
        return real(*a, **kw)

    monkeypatch.setattr(hump, "_unimodal", spy)
    b = boundary(3, m, Q=Q, digits=15)
    assert b.exists and b.certified and b.regime == hump._FRICTION_REGIME
    assert len(calls) == 1
    a, kw = calls[0]
    assert kw["pieces"] == 3
    assert kw["direct"] in (1, 2, 3)  # the ends where D is convex: D' tested there first

    def counted(pieces):
        n = [0]

        def count(f):
            def g(*x):
                n[0] += 1
                return f(*x)

            return g

        A, B, lo, hi, bend, d2D, dD, D = a
        ok = real(
            A,
            B,
            lo,
            hi,
            count(bend),
            count(d2D),
            count(dD),
            count(D),
            args=kw["args"],
            pieces=pieces,
        )
        return ok, n[0]

    from flint import ctx

    old = ctx.prec
    ctx.prec = 64
    try:
        (ok3, n3), (ok1, n1) = counted(3), counted(1)
    finally:
        ctx.prec = old
    assert ok3 and ok1
    assert n3 < n1


@pytest.mark.parametrize("m", ["3/5", "4/5", "9/10", "19/20", "99/100", "999/1000"])
@pytest.mark.parametrize("Q", ["7", "30", "1000"])
def test_wide_float_edges_are_the_float_stages(m, Q):
    """The edges of the float stage started at the bracket's ends (a wide bracket) are those of
    :func:`verify.float_stage.float_stage` (started around the maximiser), to what doubles can
    tell near ``m = 1``: a relative ``1e-13`` (against the edges Newton's method gives at 300 bits,
    both are off by up to ``7e-14`` at ``m = 0.999``, from the rounding of ``D`` in doubles)."""
    from fractions import Fraction

    from verify.float_stage import WIDE, float_stage, wide_float_edges
    from verify.params import normal_values

    for n in (1, 2, 3, 4):
        r, r2, u, beta, _, g, _, _, _ = normal_values(Fraction(m), Fraction(Q), "exact", hump._MATH)
        a, b, _, dtop, lo, hi, convex = wide_float_edges(n, r, r2, u, beta, g)
        a0, b0, _, dtop0, lo0, hi0 = float_stage(n, r, r2, u, beta, g)
        assert (a, b) == (a0, b0)
        if convex:
            assert b - a > WIDE
        if dtop0 > 0 and dtop > 0:
            assert abs(lo - lo0) <= 1e-13 * abs(lo0) + 1e-300
            assert abs(hi - hi0) <= 1e-13 * abs(hi0) + 1e-300


def _plain_d012(monkeypatch):
    """Make :mod:`verify.float_stage` evaluate ``(D, D', D'')`` by the stored text itself (no
    parameter products computed ahead): the reference of the hoisted evaluation."""
    import verify.float_stage as fs

    def plain(odd):
        d012 = fs._forms(odd)[1]
        return (lambda *params: params), d012

    monkeypatch.setattr(fs, "_hoisted", plain)


@pytest.mark.parametrize("m", ["1e-6", "3/10", "3/5", "9/10", "999/1000"])
@pytest.mark.parametrize("Q", ["1/2", "3", "7", "1000"])
def test_float_stage_hoisted_is_the_stored_text(monkeypatch, m, Q):
    """The float stage evaluates ``(D, D', D'')`` with the products of the parameters alone
    computed once (:func:`verify.derived.hoisted`): every float it returns is the one of the
    stored text evaluated as it is (the same operations on the same operands), with an interval
    and without (the maximiser's search), on wide brackets and narrow ones."""
    from fractions import Fraction

    from verify.float_stage import float_stage, wide_float_edges
    from verify.params import form_for, normal_values

    for damping in ("exact", "paper"):
        if form_for(Fraction(m), Fraction(Q), damping)[0] != "normal":
            continue
        p = normal_values(Fraction(m), Fraction(Q), damping, hump._MATH)
        r, r2, u, beta, _, g, _, _, _ = p
        got = [
            (f(n, r, r2, u, beta, g)) for n in (1, 2, 3, 6) for f in (float_stage, wide_float_edges)
        ]
        with monkeypatch.context() as mp:
            _plain_d012(mp)
            ref = [
                (f(n, r, r2, u, beta, g))
                for n in (1, 2, 3, 6)
                for f in (float_stage, wide_float_edges)
            ]
        assert repr(got) == repr(ref)


def test_hoisted_forms_are_the_stored_forms():
    """``evaluate(x, *prepare(*params))`` gives the very floats of the stored text on random
    points, for both parities; the parameters' products are computed in ``prepare`` (none is
    left in ``evaluate``)."""
    import math
    import random

    from verify.derived import hoisted, hoisted_source, indicator
    from verify.float_stage import _forms

    rnd = random.Random(7)
    for odd in (True, False):
        text = indicator(-1 if odd else 1).text("math", (0, 1, 2))
        prepare, evaluate = hoisted(text, "math")
        d012 = _forms(odd)[1]
        for _ in range(20000):
            params = (
                rnd.randint(1, 12) * math.pi / 2,
                rnd.random(),
                rnd.random() * rnd.choice([1.0, 1e-3]),
                rnd.uniform(0.01, 2),
                rnd.random() * rnd.choice([1.0, 10.0, 1e-3]),
            )
            x = rnd.uniform(-1.6, 1.6)
            assert repr(evaluate(x, *prepare(*params))) == repr(d012(x, *params))
        source = hoisted_source(text)
        body = source[source.index("def _evaluate") :]
        assert "_d0 * beta" not in body and "g * u" not in body and "beta * beta" not in body
        assert "_d0 * beta" in source  # computed once, in _prepare


def test_hoisted_source_keeps_the_evaluation_order():
    """Only whole nodes of the evaluation tree move: ``a*b*x`` is ``(a*b)*x`` (``a*b`` computed
    ahead), ``x*a*b`` is ``(x*a)*b`` (nothing moves), a node of the parameters alone moves whole
    (``2*(a*b)``, its own operations in its own order)."""
    from verify.derived import hoisted, hoisted_source

    text = "def _lambdifygenerated(theta, a, b):\n    return [a*b*theta + theta*a*b, 2*(a*b)]\n"
    source = hoisted_source(text)
    assert "_h0 = a * b" in source and "_h1 = 2 * (a * b)" in source
    assert "return (_h0 * theta + theta * a * b, _h1)" in source
    prepare, evaluate = hoisted(text, "math")
    assert evaluate(0.3, *prepare(0.1, 0.7)) == (0.1 * 0.7 * 0.3 + 0.3 * 0.1 * 0.7, 2 * (0.1 * 0.7))


def test_lean_forms_give_the_balls_of_the_stored_forms():
    """The short path's forms with their integer constants as exact balls
    (:func:`verify.hump._lean_forms`, :func:`verify.derived.int_constants`) give the very balls of
    the stored forms (:func:`verify.hump._normal_forms`) on random balls -- points and wide ones,
    parameters from several precisions -- at the precisions the short path works at; and no
    integer is left beside a ball in their texts."""
    import random
    import re

    from flint import arb, ctx

    from verify.derived import indicator, indicator_slope, int_constants

    rnd = random.Random(11)
    old = ctx.prec
    try:
        for parity in (-1, 1):
            lean, stored = hump._lean_forms(parity), hump._normal_forms(parity)
            for _ in range(3000):
                ctx.prec = rnd.choice([64, 76, 92, 128, 300])
                c = arb.pi() * rnd.randint(1, 6) / 2
                params = [arb(rnd.uniform(0.01, 1.5)) / 3 for _ in range(4)]
                ctx.prec = rnd.choice([64, 87, 100, 200])
                x = arb(rnd.uniform(-1.5, 1.5), rnd.choice([0.0, 1e-15, 0.1, 0.6]))
                for f, g in zip(lean, stored, strict=True):
                    a, b = f(x, c, *params), g(x, c, *params)
                    for u, v in zip(a, b, strict=True) if isinstance(a, tuple) else ((a, b),):
                        assert u.mid() == v.mid() and u.rad() == v.rad()
    finally:
        ctx.prec = old
    for text in (indicator(-1).text("arb", (0, 1)), indicator_slope(1).text("arb", 0)):
        new = int_constants(text)
        body = new[new.index("def ") :]
        assert re.search(r"(?<![\w.])\d+ \*|[-+] \d+(?![\w.])", body) is None
        assert "_i2 = _dyadic(2, 0)" in new
