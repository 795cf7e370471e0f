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
        "from verify.system_params import STORED_DUTIES, normal_values, trace_values\n"
        "for name in LAWS:\n"
        "    for D in STORED_DUTIES:\n"
        "        s = system(name, duty=D)\n"
        "        for B in ('math', 'numpy', 'mpmath', 'arb'):\n"
        "            normal_values(s, Fraction(1, 5), None, 'none', backend(B))\n"
        "            normal_values(s, Fraction(1, 5), Fraction(7), 'exact', backend(B))\n"
        "        normal_values(s, 0.2, 7.0, 'paper', backend('math'))\n"
        "        trace_values(s, Fraction(1, 5), Fraction(7), backend('arb'))\n"
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
