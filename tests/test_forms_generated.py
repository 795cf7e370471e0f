"""The stored compilations of the derived forms, and what they buy: numeric commands without
sympy.

Reference for the stored texts: the derivation itself (:func:`verify.generate_forms.build`
derives every entry again with sympy from :mod:`analytic`); the texts must be identical, and the
function loaded from a text must give the same numbers as the one compiled from the derivation.
"""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import pytest
from flint import arb, ctx

from verify import derived, generate_forms
from verify.forms_generated import SOURCES

ROOT = Path(__file__).resolve().parent.parent


def test_stored_texts_are_what_the_derivation_gives():
    fresh = generate_forms.build()
    assert sorted(fresh) == sorted(SOURCES)
    changed = [k for k in fresh if fresh[k] != SOURCES[k]]
    assert changed == [], "run python -m verify.generate_forms"


def test_a_stored_function_computes_what_the_derived_one_does():
    lazy = derived.edge_equation(-1)
    stored = lazy.compiled("arb", (0, 1))
    fresh = lazy.real.compiled("arb", (0, 1))
    with ctx.workprec(200):
        args = (arb("0.3"), 3 * arb.pi() / 2, -1, 1, arb("0.41"), arb("0.15"))
        for a, b in zip(stored(*args), fresh(*args), strict=True):
            assert a.overlaps(b) and abs(a - b) < arb(2) ** -190


NUMERIC = [
    ["boundary", "--order", "3", "--m", "0.3"],
    ["boundary", "--order", "3", "--m", "0.3", "--Q", "7"],
    ["boundary", "--order", "1", "--m", "0.999999", "--digits", "700"],  # the near-one forms
    ["boundary", "--order", "1", "--m", "0.9995", "--Q", "0.001"],  # the scaled trace form
    ["table", "--orders", "1-2", "--m", "0.1:0.2:0.1", "--digits", "20"],
    ["multipliers", "--T", "1.45", "--m", "0.3"],
]


@pytest.mark.parametrize("argv", NUMERIC, ids=lambda a: " ".join(a[:3]))
def test_numeric_commands_do_not_import_sympy(argv, tmp_path):
    code = (
        "import sys\n"
        "from reports.cli import main\n"
        "status = main(sys.argv[1:])\n"
        "print('sympy' in sys.modules, status)\n"
    )
    env = dict(os.environ, PARAMRES_CACHE_DIR=str(tmp_path / "cache"))
    env.pop("PARAMRES_NO_CACHE", None)
    for _ in range(2):  # the first run fills whatever cache it uses; the second is warm
        proc = subprocess.run(
            [sys.executable, "-c", code, *argv],
            cwd=ROOT,
            env=env,
            capture_output=True,
            text=True,
            timeout=600,
        )
        assert proc.returncode == 0, proc.stderr
    assert proc.stdout.strip().splitlines()[-1] == "False 0"


def test_linear_runs_load_their_maps_without_sympy():
    """The half-period maps and the jump factors of the linear runs (no friction, the paper's
    damping model, the exact one under-damped) are loaded from their stored texts: a run on an
    edge imports no sympy."""
    code = (
        "import sys\n"
        "from fractions import Fraction\n"
        "from verify.timedomain import simulate\n"
        "m = Fraction(3, 10)\n"
        "simulate(order=1, m=m, edge='lower', periods=2)\n"
        "simulate(order=2, m=Fraction(1, 2), edge='upper', periods=2, Q=5, damping='paper')\n"
        "simulate(order=1, m=m, edge='lower', periods=2, Q=3)\n"
        "print('sympy' in sys.modules)\n"
    )
    assert _output_of(code) == "False"


def test_time_domain_edge_shapes_are_the_derivations():
    """The edge shapes the time domain names without sympy are those of
    :class:`analytic.stitching.EdgeKind`, by parity."""
    from analytic.stitching import EdgeKind, Parity
    from verify.timedomain import _KINDS

    want = {int(p): tuple(k.value for k in EdgeKind if k.parity is p) for p in Parity}
    assert want == _KINDS


def test_built_in_parameter_forms_load_without_sympy():
    """The parameter forms of every built-in system at a stored duty (those of the family
    section among them) are loaded from their stored texts: no sympy in the process."""
    code = (
        "import sys\n"
        "from fractions import Fraction\n"
        "from analytic.system import LAWS, system\n"
        "from verify.derived import backend\n"
        "from flint import arb\n"
        "from verify.params import trace_params\n"
        "from verify.system_params import STORED_DUTIES, normal_values\n"
        "for name in LAWS:\n"
        "    for D in STORED_DUTIES:\n"
        "        s = system(name, duty=D)\n"
        "        for B in ('math', 'numpy', 'mpmath', 'arb'):\n"
        "            normal_values(s, Fraction(1, 5), None, 'none', backend(B))\n"
        "            normal_values(s, Fraction(1, 5), Fraction(7), 'exact', backend(B))\n"
        "        normal_values(s, 0.2, 7.0, 'paper', backend('math'))\n"
        "        for B in ('math', 'arb'):\n"
        "            trace_params(Fraction(1, 5), Fraction(7), backend(B), s)\n"
        "        trace_params(arb('0.2', '1e-3'), Fraction(7), backend('arb'), s)\n"
        "print('sympy' in sys.modules)\n"
    )
    assert _output_of(code) == "False"


@pytest.mark.parametrize("name", ["pendulum", "torsion", "meissner"])
@pytest.mark.parametrize("Q", ["1/2", "2/3", "7/10", "3", "7"])
def test_regime_changes_from_the_stored_roots(name, Q):
    """The depths where the exact model's equations change, from the stored compiled roots
    (:func:`verify.derived.regime_roots`), against sympy solving ``omega_i^2(m) = g2`` (and
    ``omega_1^2 = g2 (1 + NEAR_CRITICAL^2)``) at the rational ``g2 = 1/(4 Q^2)`` itself."""
    from fractions import Fraction

    import sympy as sp

    from analytic.model import S
    from analytic.system import system
    from verify.existence import _regime_changes
    from verify.params import NEAR_CRITICAL

    sysm = system(name)
    g2 = sp.Rational(1, 4) / sp.Rational(Q) ** 2
    w1, w2, _ = (sp.sympify(v) for v in sysm.values(S.m))
    eps2 = sp.Rational(Fraction(NEAR_CRITICAL) ** 2)
    want = set()
    for eq in (w1 - g2, w2 - g2, w1 - g2 * (1 + eps2)):
        for root in sp.solveset(eq, S.m, sp.Interval.open(0, 1)):
            want.add(Fraction(int(root.p), int(root.q)))
    assert _regime_changes(Fraction(Q), sysm) == want
    assert _regime_changes(Fraction(Q), system("custom", omega_sq=("1/2", "3/2"))) == set()


def _output_of(code: str) -> str:
    """What ``code`` prints, run in a fresh interpreter from the repository (which must end it
    with status 0)."""
    proc = subprocess.run(
        [sys.executable, "-c", code], cwd=ROOT, capture_output=True, text=True, timeout=600
    )
    assert proc.returncode == 0, proc.stderr
    return proc.stdout.strip()


def test_numpy_texts_write_integer_powers_as_products():
    """The numpy texts of the parameters write ``x**n`` (``3 <= |n| <= 8``, ``n = -2``) as
    products of squares (numpy's ``power`` takes about 100 ns an element on a negative base): the
    printed text has no such power left and gives the power to a few units in the last place,
    on negative and positive bases, alone and inside a quotient."""
    import re

    import numpy as np
    import sympy as sp

    from verify.derived import _printer, backend

    x, y = sp.symbols("x y")
    base = np.linspace(-3, 3, 601)
    base = base[base != 0]
    ns = dict(backend("numpy").namespace)
    for n in [-8, -5, -3, -2, -1, 2, 3, 4, 5, 6, 7, 8]:
        for expr in ((x - 1) ** n, 2 * y * (y**2 + 3) / (x - 1) ** n):
            text = _printer(True).doprint(expr)
            assert not re.search(r"\*\*\(?-?[3-8]\b|\*\*\(-2\)", text), text
            fn = eval(f"lambda x, y: {text}", ns)  # noqa: S307 - the printer's own text
            want = sp.lambdify((x, y), expr, "mpmath")
            got = fn(base + 1, base)
            for a, xv in zip(got[::37], (base + 1)[::37], strict=False):
                yv = xv - 1
                ref = float(want(xv, yv))
                assert abs(a - ref) <= 8 * n * n * np.finfo(float).eps * abs(ref), (n, xv)
    stored = [k for k in SOURCES if k.startswith("system_params") and k.endswith("| numpy")]
    assert stored and not any(re.search(r"\*\*\(?-?[3-8]\b", SOURCES[k]) for k in stored)


def test_numpy_parameter_texts_agree_with_the_math_texts():
    """Every stored numpy text of the parameters (integer powers as products) gives, element by
    element, what the math text of the same part gives (powers by ``pow``), to a relative
    ``1e-13``, at depths over ``(0, 1)`` and quality factors from 1.5 to 100 (the values at the
    atoms the math text gives)."""
    import numpy as np

    m = np.array([0.013, 0.2, 0.37, 0.5, 0.61, 0.88, 0.97])
    Q = np.array([1.5, 2.0, 7.0, 30.0, 100.0, 3.0, 11.0])
    checked = 0
    for key, text in SOURCES.items():
        if not (key.startswith("system_params") and key.endswith("| numpy")):
            continue
        head, part, _ = key.split(" | ")
        mine = derived.load_source(text, "numpy", 0)
        plain = derived.load_source(SOURCES[f"{head} | {part} | math"], "math", 0)
        if part == "values":
            atoms = derived.load_source(SOURCES[f"{head} | atoms | math"], "math", 0)
            args = [atoms(float(m[i]), float(Q[i])) for i in range(m.size)]
        else:
            x = (1 - m) if part == "atoms_om" else m
            args = [(float(x[i]), float(Q[i])) for i in range(m.size)]
        columns = np.array(args).T
        got = mine(*columns)
        for i in range(m.size):
            want = plain(*args[i])
            for a, b in zip(got, want, strict=True):
                a = np.broadcast_to(a, m.shape)[i]
                assert abs(a - b) <= 1e-13 * abs(b), (key, i, a, b)
        checked += 1
    assert checked >= 30


def _random_balls(rng, count: int, zero_share: float = 0.05) -> list:
    """``count`` balls: midpoints in ``(-2, 2)`` (a share of them exactly 0), radii from 0 to
    about the midpoint's size."""
    out = []
    for _ in range(count):
        mid = 0.0 if rng.random() < zero_share else rng.uniform(-2, 2)
        rad = abs(mid) * 10 ** rng.uniform(-18, 0.3) if rng.random() < 0.7 else 0.0
        out.append(arb(mid, rad))
    return out


def _same_ball(a, b) -> bool:
    return a.mid() == b.mid() and a.rad() == b.rad()


ARB_FORMS = [
    ("indicator", (-1,), 0),
    ("indicator", (1,), 1),
    ("indicator", (-1,), 2),
    ("indicator", (1,), (0, 1)),
    ("indicator_bend", (-1,), 0),
    ("indicator_slope", (1,), 0),
    ("edge_equation", (-1,), (0, 1)),
    ("trace_indicator", ("under", "over"), 2),
    ("near_one_forms[2]", (), 2),
    ("near_one_forms[0]", (), 2),  # (a dyadic rational: _q(1, 2))
]


@pytest.mark.parametrize("builder, args, orders", ARB_FORMS, ids=str)
def test_arb_texts_give_the_balls_of_the_plain_text(monkeypatch, builder, args, orders):
    """The arb texts (:func:`verify.derived.arb_text`: pairs shared, squares as products,
    method calls) give bit for bit the balls of the text :func:`sympy.lambdify` writes with the
    pairs shared alone, at 64 and 200 bits, on random balls -- except where a squared value's
    midpoint is exactly 0: there ``**`` gave NaN and the product gives an enclosure, which must
    hold the plain text's value at the midpoints of the arguments."""
    import random

    form = generate_forms._lazy(builder, args).real
    new_text = form.source("arb", orders)
    new = derived.load_source(new_text, "arb", orders)
    monkeypatch.setattr(derived, "arb_text", derived.share_pairs)
    plain_text = form.source("arb", orders)
    plain = derived.load_source(plain_text, "arb", orders)
    assert new_text != plain_text  # (something rewritten)
    rng = random.Random(7)
    nargs = len(form.args)
    for prec in (64, 200):
        with ctx.workprec(prec):
            for _ in range(1500):
                xs = _random_balls(rng, nargs)
                got, want = new(*xs), plain(*xs)
                many = isinstance(orders, tuple)
                for g, w in zip(got if many else (got,), want if many else (want,), strict=True):
                    if w.is_nan() and not g.is_nan():
                        at_mid = plain(*(x.mid() + arb(0, 0) for x in xs))
                        point = at_mid[0] if many else at_mid
                        assert point.is_nan() or g.overlaps(point)
                    else:
                        assert (g.is_nan() and w.is_nan()) or _same_ball(g, w), (xs, g, w)


def test_squares_as_products_hoists_a_call_and_keeps_precedence():
    """A squared call is made once (into a new name, before the first line that squares it);
    a squared name becomes a parenthesised product, so ``-x**2`` and ``a*x**2/y`` keep their
    order of operations; a power other than 2 and a parenthesised base are left alone."""
    text = (
        "def _lambdifygenerated(x, y, a):\n"
        "    x0 = cos(a*x)**2 + y**2\n"
        "    return -x**2 + a*x**2/y - x0*cos(a*x)**2 + x**3 + (x + y)**2 + x**20\n"
    )
    out = derived.squares_as_products(text)
    assert out.split("\n")[1] == "    _sq0 = cos(a*x)"
    assert "-(x*x) + a*(x*x)/y - x0*(_sq0*_sq0) + x**3 + (x + y)**2 + x**20" in out
    assert out.count("_sq0 = ") == 1
    with ctx.workprec(80):
        xs = (arb("0.3", "1e-10"), arb("-1.7"), arb("0.61", "1e-3"))
        got = derived.load_source(derived.method_calls(out), "arb")(*xs)
        want = derived.load_source(text, "arb")(*xs)
    assert _same_ball(got, want)


def test_squares_as_products_leaves_a_square_whose_exponent_is_raised():
    """``x**2**k`` is ``x**(2**k)`` (``**`` groups from the right): the ``2`` is no square's
    exponent, and the text (a name or a call as the base) stays as it was, with its value."""
    import math

    text = "def _lambdifygenerated(x, y):\n    return x**2**y + cos(x)**2**3 - y**2\n"
    out = derived.squares_as_products(text)
    assert out.split("\n")[1] == "    return x**2**y + cos(x)**2**3 - (y*y)"
    fn = derived.load_source(out, "math")
    assert fn(1.25, 3.0) == 1.25**8 + math.cos(1.25) ** 8 - 9


def test_method_calls_rewrite_only_the_back_ends_methods():
    """``sin(v)`` becomes ``(v).sin()`` (a plain name without the parentheses), with one level
    of parentheses inside the argument; a deeper argument keeps the call (the same method, through
    the back end), as does a call inside a rewritten argument; names that merely end in a
    function's name are left alone."""
    text = (
        "def _lambdifygenerated(theta, c, beta):\n"
        "    _sin_theta, _cos_theta = sin_cos(theta)\n"
        "    return sin(beta*(c + theta)) + asin(theta) + my_sin(theta) + cos(sin(cos(theta)))\n"
    )
    out = derived.method_calls(text)
    assert "    _sin_theta, _cos_theta = theta.sin_cos()" in out
    assert "(beta*(c + theta)).sin() + theta.asin() + my_sin(theta)" in out
    assert "cos((cos(theta)).sin())" in out  # (the inner call, matched inside, stays a call)


def test_the_slope_is_the_indicators_derivative():
    """:func:`verify.derived.indicator_slope` (``D'`` in double angles) encloses what the
    indicator's ``D'`` encloses on narrow balls, to the precision's width, for both parities."""
    import random

    rng = random.Random(11)
    for parity in (-1, 1):
        slope = derived.indicator_slope(parity).compiled("arb", 0)
        d1 = derived.indicator(parity).compiled("arb", 1)
        with ctx.workprec(120):
            for _ in range(300):
                args = [arb(rng.uniform(-1.5, 1.5), 1e-20), 3 * arb.pi() / 2]
                args += [arb(rng.uniform(0.05, 1)) for _ in range(4)]
                a, b = slope(*args), d1(*args)
                assert a.overlaps(b) and abs(a - b) < arb(2) ** -60 * (1 + abs(b))


def test_dyadic_constants_are_the_rationals_they_replace():
    """A rational with a power of two below becomes a constant made once above the function
    (``_q(1, 2)`` -> ``_q1_2``, ``_q(-3, 4)`` -> ``_qm3_4``), each use reads it, another rational
    stays a call, and the function gives the very balls of the text with the calls at 24 to
    300 bits."""
    text = (
        "def _lambdifygenerated(x0, x1):\n"
        "    return (_q(1, 2))*x0 + (_q(1, 2))*x1 - _q(-3, 4)*x0 + _q(2, 3)*x1 + _q(5, 1)\n"
    )
    out = derived.dyadic_constants(text)
    lines = out.split("\n")
    assert lines[:2] == ["_q1_2 = _dyadic(1, -1)", "_qm3_4 = _dyadic(-3, -2)"]
    assert "(_q1_2)*x0 + (_q1_2)*x1 - _qm3_4*x0 + _q(2, 3)*x1 + _q5_1" in out
    before, after = derived.load_source(text, "arb"), derived.load_source(out, "arb")
    for prec in (24, 64, 300):
        with ctx.workprec(prec):
            xs = (arb("0.3", "1e-9"), arb(-1.7))
            assert _same_ball(after(*xs), before(*xs))
