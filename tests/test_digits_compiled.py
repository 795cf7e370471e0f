"""The digits of a table's rows in C (:mod:`verify._digits`) against the Python loop they stand
for (:func:`verify.result._row_of_balls` with the compiled row turned off): the same texts and
the same bound, row for row, over the cases the formatting tests build (ties, runs of nines,
radii next to a power of ten, signs, 1 to 1400 digits, exponents far out, numbers printed
``"0"``, zero midpoints and radii, rows that fall back to mpmath).  The reference for the texts
themselves is the Python loop, which ``tests/test_formatting_same.py`` holds to mpmath's.

Where the package was built without a C compiler the module is missing and these tests skip;
with ``PARAMRES_REQUIRE_COMPILED=1`` (CI) they fail instead."""

from __future__ import annotations

import os
import random
from fractions import Fraction

import mpmath
import pytest

from tests.test_formatting_same import _cases, _mpf, _rounded, _truncated_tie
from verify import result
from verify.certify import ball


@pytest.fixture
def compiled():
    if result._compiled_row is None:
        if os.environ.get("PARAMRES_REQUIRE_COMPILED") == "1":
            pytest.fail("verify._digits was not built (PARAMRES_REQUIRE_COMPILED=1)")
        pytest.skip("verify._digits was not built (no C compiler at install)")
    return result._compiled_row


def _both(balls, digits, monkeypatch) -> tuple:
    """The row written with the compiled loop, and by the Python loop alone."""
    fast = result._row_of_balls(balls, digits)
    with monkeypatch.context() as m:
        m.setattr(result, "_compiled_row", None)
        slow = result._row_of_balls(balls, digits)
    return fast, slow


def _taken(compiled, balls, digits) -> bool:
    """Whether the compiled loop writes the row itself (its scales kept by a first call)."""
    result._row_of_balls(balls, digits)
    scales = result._ROW_SCALES[digits]
    return compiled(balls, scales, result._TEN_TUPLE, result._ball_raw, digits) is not None


def test_random_rows_as_the_python_loop(compiled, monkeypatch):
    """Rows of one to six balls from the formatting tests' random cases (their radii from far
    below one unit to wider than the number), each row at one of the cases' digits."""
    # most with radii the compiled loop reads (between 2**-990 and 1), the rest as they come
    cases = [c for c in _cases(41, 6000) if 2.0**-990 < float(c[1]) < 1.0][:3000]
    cases += list(_cases(42, 800))
    rng = random.Random(41)
    i = taken = 0
    rows = 0
    while i < len(cases):
        size = rng.randint(1, 6)
        chunk = cases[i : i + size]
        i += size
        digits = chunk[0][2]
        balls = [ball(x, r) for x, r, _ in chunk]
        fast, slow = _both(balls, digits, monkeypatch)
        assert fast == slow, ([(x._mpf_, r._mpf_) for x, r, _ in chunk], digits)
        taken += _taken(compiled, balls, digits)
        rows += 1
    assert taken > rows // 2  # the compiled loop writes most rows itself


@pytest.mark.parametrize("dps", [1, 2, 3, 15, 50, 100])
def test_ties_and_runs_of_nines_as_the_python_loop(compiled, monkeypatch, dps):
    """Midpoints whose truncated digits end exactly in ``5000...`` (rounded half up) and one unit
    below, and runs of nines that carry into the next power of ten, in fixed point and with an
    exponent, positive and negative (the cases of ``test_truncated_ties_from_balls_as_before``)."""
    rng = random.Random(dps)
    taken = 0
    for _ in range(6):
        row = []
        for E in (0, -1, rng.choice([-30, -7, 3])):
            N = rng.randrange(10 ** (dps - 1), 10**dps)
            row += [_truncated_tie(N, E, dps, below) for below in (False, True)]
        nines = _truncated_tie(10**dps - 1, rng.choice([0, -2, 4]), dps, False)
        row += [nines, -row[0], -row[1], -nines]
        for i in range(0, len(row) - 3, 2):
            xs = row[i : i + 4]
            r = _mpf(1, int(mpmath.floor(mpmath.log(abs(xs[0]), 2))) - int(dps * 3.33) - 60)
            balls = [ball(x, r) for x in xs]
            fast, slow = _both(balls, dps, monkeypatch)
            assert fast == slow, ([x._mpf_ for x in xs], dps)
            taken += _taken(compiled, balls, dps)
    assert taken > 20  # of 30 rows


def test_radii_counted_zeros_and_general_rows_as_the_python_loop(compiled, monkeypatch):
    """Radii at and above one unit of the digits (counted in the bound), numbers printed ``"0"``
    beside numbers printed in full (their error in doubles), a zero midpoint and a zero radius
    (the row to mpmath's path), 1000 and 1400 digits (the integers' bound), and a scale not kept
    yet (the Python loop keeps it, then the compiled loop uses it)."""
    rng = random.Random(7)
    for digits in (3, 15, 50, 100, 1000, 1400):
        bits = int(digits * 3.33) + 60
        for k in range(12):
            xs = [
                _mpf(rng.choice([-1, 1]) * rng.getrandbits(bits), rng.randint(-12, top) - bits)
                for top in (12, 12, 12, -3)
            ]
            radii = []
            for x in xs:
                man, exp = x.man_exp
                q = Fraction(abs(int(man))) * Fraction(2) ** int(exp)
                radii.append(_rounded(q / 10 ** (digits + rng.choice([0, 1, 2, 3])), 30, True))
            if k % 3 == 0:  # printed "0": a radius three times the number
                man, exp = xs[3].man_exp
                radii[3] = _rounded(3 * abs(Fraction(int(man)) * Fraction(2) ** int(exp)), 30, True)
            if k == 5:  # a zero midpoint: the row to mpmath's path
                xs[2] = mpmath.mpf(0)
            if k == 7:  # an exact ball: no radius
                radii[1] = mpmath.mpf(0)
            balls = [ball(x, r) for x, r in zip(xs, radii, strict=True)]
            if k == 0:  # no scale kept for these digits yet
                result._ROW_SCALES.pop(digits, None)
            fast, slow = _both(balls, digits, monkeypatch)
            assert fast == slow, (digits, k)


def test_the_compiled_row_refuses_what_it_is_not_given(compiled):
    """Wrong arguments raise ``TypeError`` (not a crash); balls that are not balls raise what
    their methods raise."""
    scales = result._ROW_SCALES.setdefault(50, {})
    tens = result._TEN_TUPLE
    with pytest.raises(TypeError):
        compiled([], scales)
    with pytest.raises(TypeError):
        compiled([], [], tens, result._ball_raw, 50)
    with pytest.raises(TypeError):
        compiled([], scales, tens[:-1], result._ball_raw, 50)
    with pytest.raises(TypeError):
        compiled(3, scales, tens, result._ball_raw, 50)
    with pytest.raises(AttributeError):
        compiled([1.5], scales, tens, result._ball_raw, 50)
    assert compiled([], scales, tens, result._ball_raw, 50) == ((), None)


def test_binary_exponents_far_out_go_to_the_python_loop(compiled, monkeypatch):
    """A ball whose binary exponent is beyond 2**60 either way (where the exponent plus the
    mantissa's bits could overflow C's integers) is left to the Python loop, which prints the
    row as it would without the compiled loop."""
    import flint

    near = flint.arb("0.5 +/- 1e-20")
    result._row_of_balls([near], 15)
    scales = dict(result._ROW_SCALES[15])
    some_scale = next(iter(scales.values()))
    for shift in (2**60 + 1, 2**62, 2**63 + 5, -(2**62), -(2**63) - 5):
        far = flint.arb("3 +/- 1e-19") * flint.arb(2) ** shift
        man, exp = (int(v) for v in far.mid().man_exp())
        assert abs(exp) > 2**60
        # a scale planted where the far ball's would be: only the limit keeps C from using it
        scales[exp + man.bit_length()] = some_scale
        assert compiled([near, far], scales, result._TEN_TUPLE, result._ball_raw, 15) is None
        fast, slow = _both([near, far], 15, monkeypatch)
        assert fast == slow, shift
