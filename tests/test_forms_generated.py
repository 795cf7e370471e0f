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
