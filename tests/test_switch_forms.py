"""The stored compilations of the ramp's and the sine modulation's forms (verify.switch_forms).

Reference for the stored texts: the derivation itself (:func:`verify.switch_forms.build`
compiles every form again with sympy from :mod:`analytic.ramp` and :mod:`analytic.smooth`); the
texts must be identical, and a function loaded from a text must give the numbers the function
compiled from the derivation gives.
"""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

from flint import arb, ctx

from verify import ramp, smooth, switch_forms
from verify.switch_forms_generated import SOURCES

ROOT = Path(__file__).resolve().parent.parent


def test_stored_texts_are_what_the_derivation_gives():
    fresh = switch_forms.build()
    assert sorted(fresh) == sorted(SOURCES)
    changed = [k for k in fresh if fresh[k] != SOURCES[k]]
    assert changed == [], "run python -m verify.switch_forms"


def _close(a: arb, b: arb) -> bool:
    return a.overlaps(b) and abs(a - b) <= arb(2) ** -180 * (1 + abs(a))


def test_a_stored_function_computes_what_the_derived_one_does():
    stored_r, fresh_r = ramp._compiled(), ramp._derived()
    stored_s = dict(zip(("sine", "lin", "hill", "state"), smooth._compiled(), strict=True))
    fresh_s = smooth._derived()
    with ctx.workprec(200):
        pi, g = arb.pi(), 4 * arb.pi() ** 2
        cases = [
            (stored_r["ramp"], fresh_r["ramp"], (arb("1.3"), arb("0.7"), arb("0.01"), g, pi)),
            (stored_r["plateau"], fresh_r["plateau"], (arb("0.37"), arb("1.3"), g)),
            (stored_s["hill"], fresh_s["hill"], (arb("0.4"), arb("1.7"), arb("0.6"), g, 0, pi)),
            (stored_s["state"], fresh_s["state"], (arb("0.4"), arb("1.7"), arb("0.6"), g, 0, pi)),
        ]
        for stored, fresh, args in cases:
            for a, b in zip(stored(*args), fresh(*args), strict=True):
                assert _close(arb(a), arb(b)), (stored, a, b)


def test_the_maps_are_computed_without_sympy():
    code = (
        "import sys\n"
        "from verify.ramp import ramp_half_map\n"
        "from verify.smooth import sine_half_map\n"
        "ramp_half_map('3/10', '13/10', '1/100')\n"
        "sine_half_map('3/10', '13/10')\n"
        "print('sympy' in sys.modules)\n"
    )
    out = subprocess.run(
        [sys.executable, "-c", code], cwd=ROOT, capture_output=True, text=True, check=True
    )
    assert out.stdout.strip() == "False"
