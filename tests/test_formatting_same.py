"""The fast formatting of proven decimals (:func:`verify.result.proven_text`, the error bound of a
:class:`verify.result.Boundary`, :func:`verify.rounding.printed_bound`) writes exactly the text
of the general formulation kept here as the reference: ``mpmath.nstr`` on the estimate of usable
digits, and the bound of the print in :class:`fractions.Fraction` arithmetic, rounded up.  Random
cases at many precisions and exponents, with ties (a digit 5 after the last printed), runs of
nines (the rounding carries into a new power of ten) and ratios value/radius next to powers of
ten (where the digit count is decided exactly)."""

from __future__ import annotations

import dataclasses
import math
import random
import sys
from fractions import Fraction

import mpmath
import pytest
from mpmath.libmp import from_man_exp

from verify.result import proven_text
from verify.rounding import bound_text, printed_bound, printed_error
from verify.solve import boundary

_LOG10_2 = math.log10(2)


def _log10_abs(v) -> float:
    _, man, exp, bc = v._mpf_
    top = man >> (bc - 53) if bc > 53 else man
    return (exp + bc - min(bc, 53) + math.log2(top)) * _LOG10_2


def _no_bare_point(text: str) -> str:
    """``text`` without a point that no digit follows (mpmath's ``"2."``, ``"2.e-30"``)."""
    mant, e, exp = text.partition("e")
    return mant.removesuffix(".") + e + exp


def reference_text(x, rad, digits: int) -> str:
    """The formatting as first written (mpmath's comparisons and ``nstr``), without a point that
    no digit follows."""
    return _no_bare_point(_reference_nstr(x, rad, digits))


def _reference_nstr(x, rad, digits: int) -> str:
    if rad is None or rad == 0 or x == 0:
        return mpmath.nstr(x, digits, strip_zeros=False) if x != 0 or rad is None else "0"
    est = _log10_abs(x) - _log10_abs(rad) - _LOG10_2
    usable = math.floor(est)
    if abs(est - round(est)) < 1e-6:
        with mpmath.workdps(20):
            ratio = abs(x) / (2 * rad)
            usable = int(mpmath.floor(mpmath.log10(ratio))) if ratio >= 1 else 0
    if usable < 1:
        return "0"
    return mpmath.nstr(x, min(digits, usable), strip_zeros=False)


def reference_bound(bound: Fraction, digits: int = 2) -> str:
    """The bound rounded up, in Fraction arithmetic, as first written."""
    if bound == 0:
        return "0"
    limit = sys.get_int_max_str_digits()
    sys.set_int_max_str_digits(0)  # tiny radii: integers of many thousand digits
    try:
        e = len(str(bound.numerator)) - len(str(bound.denominator))
    finally:
        sys.set_int_max_str_digits(limit)
    while Fraction(10) ** e > bound:
        e -= 1
    while Fraction(10) ** (e + 1) <= bound:
        e += 1
    scale = Fraction(10) ** (digits - 1 - e)
    mant = -((-bound * scale.numerator) // scale.denominator)
    if mant >= 10**digits:
        mant //= 10
        e += 1
    head = str(mant)
    return f"{head[0]}.{head[1:]}e{e}" if digits > 1 else f"{head}e{e}"


def reference_error(text: str, x, radius) -> Fraction:
    sign, man, exp, _ = x._mpf_
    xs = (-1 if sign else 1) * Fraction(man) * Fraction(2) ** exp
    _, rm, re, _ = radius._mpf_
    return abs(Fraction(text) - xs) + Fraction(rm) * Fraction(2) ** re


def _mpf(man: int, exp: int) -> mpmath.mpf:
    """The exact number ``man 2**exp`` (no rounding to the working precision)."""
    v = mpmath.mpf(0)
    v._mpf_ = from_man_exp(man, exp)
    return v


def _cases(seed: int, n: int):
    rng = random.Random(seed)
    for _ in range(n):
        bits = rng.choice([53, 120, 200, 400, 1200])
        kind = rng.random()
        if kind < 0.15:  # runs of nines, powers of ten and ties in decimal
            d = rng.randint(1, 70)
            man = rng.choice([10**d - 1, 10**d, 10**d + 1, 5 * 10**d, 5 * 10**d - 1, 25 * 10**d])
            exp = rng.randint(-300, 50)
        else:
            man = rng.getrandbits(bits) | 1
            exp = rng.randint(-bits - 300, 300) if kind < 0.97 else rng.randint(-12000, 12000)
        # (exponents beyond +-3500 bits take mpmath's own path; within the reference's reach)
        x = _mpf(-man if rng.random() < 0.5 else man, exp)
        if rng.random() < 0.15:  # |x| / (2 rad) next to a power of ten
            p = rng.randint(0, 60)
            with mpmath.workdps(80):
                r = abs(x) / (2 * mpmath.mpf(10) ** p)
                r = r * (1 + mpmath.mpf(rng.choice([-1, 0, 1])) * mpmath.mpf(2) ** -70)
            rad = _mpf(*_man_exp(r))
        else:
            rbits = rng.choice([10, 30, 53, 64])
            rad = _mpf(rng.getrandbits(rbits) | 1, exp + bc_of(man) - rbits - rng.randint(0, 260))
        yield x, rad, rng.choice([1, 2, 3, 5, 15, 20, 50, 100, rng.randint(1, 120)])


def bc_of(man: int) -> int:
    return man.bit_length()


def _man_exp(v):
    sign, man, exp, _ = v._mpf_
    return (-man if sign else man), exp


def test_proven_text_and_bound_as_before():
    checked = ties = 0
    for x, rad, digits in _cases(14, 6000):
        text = proven_text(x, rad, digits)
        assert text == reference_text(x, rad, digits), (x._mpf_, rad._mpf_, digits)
        ref = reference_error(text, x, rad)
        assert printed_error(text, x, rad) == ref
        assert bound_text(ref) == reference_bound(ref)
        assert printed_bound([(text, x, rad)]) == reference_bound(ref)
        checked += 1
        ties += text.rstrip("0").endswith("5")
    assert checked == 6000 and ties > 100


@pytest.mark.parametrize("digits", [1, 2, 3])
def test_bound_text_as_before(digits):
    rng = random.Random(digits)
    for _ in range(3000):
        num = rng.choice([rng.getrandbits(rng.randint(1, 300)), 10 ** rng.randint(0, 60)])
        num += rng.choice([-1, 0, 0, 1]) if num > 1 else 0
        den = rng.choice(
            [10 ** rng.randint(0, 80), 2 ** rng.randint(0, 300), rng.randint(1, 10**9)]
        )
        b = Fraction(num, den)
        assert bound_text(b, digits) == reference_bound(b, digits), (num, den)


def test_largest_of_several_as_before():
    cases = list(_cases(5, 800))
    for i in range(0, len(cases), 4):
        items = [(proven_text(x, r, d), x, r) for x, r, d in cases[i : i + 4]]
        assert printed_bound(items) == reference_bound(max(reference_error(*it) for it in items))
    assert printed_bound([(None, None, None)]) is None


@pytest.mark.parametrize("m", ["1/20", "3/10", "3/5", "9/10"])
@pytest.mark.parametrize("digits", [15, 50])
def test_boundary_rows_as_before(m, digits):
    """A table row: the four decimals and the bound of the print, as the reference writes them."""
    b = boundary(3, m, digits=digits)
    j = dataclasses.replace(b).as_json()
    values = (b.lower, b.upper, b.delta_lower, b.delta_upper)
    keys = ("lower", "upper", "delta_lower", "delta_upper")
    texts = [reference_text(x, b.radii[k], digits) for k, x in enumerate(values)]
    assert [j[k] for k in keys] == texts
    assert j["error_bound"] == reference_bound(
        max(
            reference_error(t, x, b.radii[k])
            for k, (t, x) in enumerate(zip(texts, values, strict=True))
        )
    )
    assert j["radius"] == mpmath.nstr(b.radius, 3)


def test_radius_text_as_before():
    from verify.result import _radius_text

    for x, rad, _ in _cases(21, 2000):
        assert _radius_text(rad) == mpmath.nstr(rad, 3)
        assert _radius_text(x) == mpmath.nstr(x, 3)
    assert _radius_text(mpmath.mpf(0)) == mpmath.nstr(mpmath.mpf(0), 3)
    assert _radius_text(mpmath.mpf("0.5")) == "0.5"


# -- whole rows: the table's cells and the text view, against the reference, cell by cell --------

KEYS = ("lower", "upper", "delta_lower", "delta_upper")


def assert_row_as_before(b, balls: bool = True) -> None:
    """``b`` formatted afresh (as ``paramres table`` writes a row, and as ``str``) against the
    reference: the four decimals, the bound of the print and the radius, byte for byte; with
    ``balls``, also the same row made from balls (:func:`assert_balls_as_numbers`)."""
    if balls:
        assert_balls_as_numbers(b)
    fresh = dataclasses.replace(b)  # nothing formatted yet
    j = fresh.as_json()
    assert dataclasses.replace(b).printed() == tuple(j[k] for k in (*KEYS, "error_bound"))
    values = (b.lower, b.upper, b.delta_lower, b.delta_upper)
    radii = (None,) * 4 if b.radii is None else b.radii
    texts = [
        None if x is None else reference_text(x, r, b.digits)
        for x, r in zip(values, radii, strict=True)
    ]
    assert [j[k] for k in KEYS] == texts, (b.lower, b.radii)
    if b.certified and b.exists and b.radius is not None:
        bradii = (b.radius,) * 4 if b.radii is None else b.radii
        errors = [
            reference_error(t, x, r)
            for t, x, r in zip(texts, values, bradii, strict=True)
            if x is not None and r is not None
        ]
        bound = reference_bound(max(errors))
    else:
        bound = None
    assert j["error_bound"] == bound
    assert j["radius"] == (None if b.radius is None else mpmath.nstr(b.radius, 3))
    text = str(dataclasses.replace(b))
    for t in texts:
        assert t is None or f"= {t}" in text
    assert bound is None or f"|printed - exact| < {bound}]" in text


def assert_balls_as_numbers(b) -> None:
    """The row made as the solver makes it (:func:`verify.result.from_balls`, formatted straight
    from the balls' raw numbers, nothing converted before) from balls with ``b``'s midpoints and
    radii, against a plain :class:`verify.result.Boundary` holding the balls' numbers exactly
    (formatted by the general route, itself checked against the reference): the same dict and
    the same text, byte for byte.  A zero radius or a zero midpoint takes the balls' general
    path; ``dataclasses.replace`` of a from-balls result (which drops the balls) formats alike."""
    from verify.certify import ball, exact_mpf, to_mpf
    from verify.result import Boundary, from_balls

    values = (b.lower, b.upper, b.delta_lower, b.delta_upper)
    if not b.exists or b.radii is None or any(v is None for v in values):
        return
    balls = [ball(v, r) for v, r in zip(values, b.radii, strict=True)]
    kw = {
        k: getattr(b, k)
        for k in ("order", "m", "Q", "damping", "digits", "method", "regime", "system", "notes")
    }
    radii = tuple(exact_mpf(x.rad()) for x in balls)
    ref = Boundary(
        exists=True,
        lower=to_mpf(balls[0]),
        upper=to_mpf(balls[1]),
        delta_lower=to_mpf(balls[2]),
        delta_upper=to_mpf(balls[3]),
        radius=max(radii),
        radii=radii,
        certified=b.certified,
        **kw,
    )
    assert_row_as_before(ref, balls=False)
    j = ref.as_json()
    assert from_balls(balls, certified=b.certified, **kw).as_json() == j
    assert from_balls(balls, certified=b.certified, **kw).printed() == tuple(
        j[k] for k in (*KEYS, "error_bound")
    )
    assert str(from_balls(balls, certified=b.certified, **kw)) == str(ref)
    assert dataclasses.replace(from_balls(balls, certified=b.certified, **kw)).as_json() == (
        ref.as_json()
    )


CONFIGS = [
    # (system, duty, Q): the paper's pendulum, the torsion pendulum, duty 1/3, with friction
    ("pendulum", "1/2", None),
    ("pendulum", "1/2", "7"),
    ("torsion", "1/2", None),
    ("torsion", "1/2", "12"),
    ("pendulum", "1/3", None),
    ("torsion", "1/3", "9"),
]


@pytest.mark.parametrize("digits", [15, 50, 100, 1000])
def test_table_rows_as_before(digits):
    """Random edges (order 1-4, random depth) of every configuration: each row written as the
    reference writes it."""
    rng = random.Random(digits)
    rows = 0
    for system, duty, Q in CONFIGS:
        for _ in range(3 if digits == 1000 else 5):
            order = rng.randint(1, 4)
            m = Fraction(rng.randint(20 if Q else 1, 90), 100)
            b = boundary(order, m, Q=Q, digits=digits, system=system, duty=duty)
            assert_row_as_before(b)
            rows += b.exists and b.certified
    assert rows >= 15  # most rows exist and are certified: the fast path is what is compared


def _rounded(q: Fraction, bits: int, up: bool) -> mpmath.mpf:
    """``q`` rounded to ``bits`` bits, up or down (an exact binary number beside ``q``)."""
    from mpmath.libmp import from_rational, round_ceiling, round_floor

    v = mpmath.mpf(0)
    v._mpf_ = from_rational(q.numerator, q.denominator, bits, round_ceiling if up else round_floor)
    return v


def _row(x, digits, rad_bits=40, deltas=None, radii=None):
    """A certified row whose lower edge is ``x`` (the rest beside it)."""
    from verify.result import Boundary

    bits = int(digits * 3.33)
    upper = mpmath.fadd(x, mpmath.ldexp(1, -(bits + 8)), exact=True)  # a tiny width
    one = mpmath.mpf(1)
    dl, du = (
        deltas
        if deltas is not None
        else (
            mpmath.fsub(x, one, exact=True),
            mpmath.fsub(upper, one, exact=True),
        )
    )
    if radii is None:
        r = _rounded(Fraction(1, 2 ** (bits + rad_bits)), 30, True)
        radii = (r, r, r, r)
    return Boundary(
        order=3,
        m=Fraction(1, 2),
        Q=None,
        damping="exact",
        digits=digits,
        method="certified",
        exists=True,
        lower=x,
        upper=upper,
        delta_lower=dl,
        delta_upper=du,
        radius=max(radii),
        certified=True,
        regime="test",
        radii=radii,
    )


@pytest.mark.parametrize("digits", [15, 50, 100, 1000])
def test_hard_rows_as_before(digits):
    """Hard cases, each formatted as the reference does: an edge beside a tie of the last digit
    (``...4999|5000...``: a hair below, a hair above, at several binary precisions), runs of nines
    (the rounding carries into the next power of ten), tiny widths and offsets, a radius whose
    value/radius ratio is next to the power of ten that decides the number of digits, a zero
    offset (an exact closing), and no radius at all."""
    rng = random.Random(1000 + digits)
    bits = int(digits * 3.33)
    cases = []
    for _ in range(12):
        N = rng.randrange(10 ** (digits - 1), 10**digits)
        tie = Fraction(10 * N + 5, 10**digits)  # 1.xxx...x5: a tie after the last digit
        for extra in (2, 12, 40, 400):
            for up in (False, True):
                cases.append(_rounded(tie / 10 ** rng.randint(0, 1), bits + extra, up))
        nines = 1 - Fraction(rng.randint(1, 9), 10 ** (digits + rng.randint(0, 2)))
        for extra in (3, 40):
            for up in (False, True):
                cases.append(_rounded(nines, bits + extra, up))
                cases.append(_rounded(10 * nines, bits + extra, up))
    for x in cases:
        assert_row_as_before(_row(x, digits))
        # negative offsets beside a tie, and tiny offsets (a narrow interval)
        tiny = mpmath.ldexp(x, -(bits // 2))
        assert_row_as_before(_row(x, digits, deltas=(mpmath.ldexp(-x, -6), tiny)))
    x = cases[0]
    # a radius next to the one that decides the number of digits: |x| / (2 r) = 10**p (1 +- eps)
    for p in (1, digits // 2, digits - 1, digits, digits + 1):
        for eps in (-(2**-40), -(2**-70), 0, 2**-70, 2**-40):
            with mpmath.workdps(digits + 40):
                r = abs(x) / (2 * mpmath.mpf(10) ** p) * (1 + eps)
            r = _mpf(*_man_exp(r))
            assert_row_as_before(_row(x, digits, radii=(r, r, r / 3, r / 3)))
    # an exact closing: a zero offset whose enclosure is wider than one digit
    r = _rounded(Fraction(1, 2**bits), 30, True)
    assert_row_as_before(_row(x, digits, deltas=(mpmath.mpf(0), mpmath.mpf(0)), radii=(r,) * 4))
    # no radii: every digit asked for, and the one radius for the bound
    b = dataclasses.replace(_row(x, digits), radii=None)
    assert_row_as_before(b)
    assert_row_as_before(dataclasses.replace(b, radius=None, certified=False))


def test_rows_of_random_balls_as_before():
    """Rows made from balls with random midpoints and radii -- the cases above, four to a row:
    ties, runs of nines, value/radius next to a power of ten, signs, precisions from 1 to 120
    digits, exponents far out -- written straight from the balls (the one pass of
    :func:`verify.result._row_of_balls`) and by the general route, against the reference
    (:func:`assert_balls_as_numbers`); most rows take the one pass."""
    from verify.certify import ball
    from verify.result import _row_of_balls

    # radii the one pass reads through doubles (between 2**-990 and 1: verify.result._TINY,
    # _HUGE); the rest take the general route, compared all the same
    cases = [c for c in _cases(31, 6000) if 2.0**-990 < float(c[1]) < 1.0][:2400]
    cases += list(_cases(32, 400))
    fast = 0
    for i in range(0, len(cases), 4):
        (x0, r0, digits), *rest = cases[i : i + 4]
        xs = [x0] + [x for x, _, _ in rest]
        rs = [r0] + [r for _, r, _ in rest]
        b = _row(xs[0], digits, radii=tuple(rs), deltas=(xs[2], xs[3]))
        b = dataclasses.replace(b, upper=xs[1])
        assert_balls_as_numbers(b)
        fast += _row_of_balls([ball(x, r) for x, r in zip(xs, rs, strict=True)], digits) is not None
    assert fast > 450  # of 700 rows: the one pass is what is compared


def _truncated_tie(N: int, E: int, dps: int, below: bool) -> mpmath.mpf:
    """A binary number whose digits as mpmath truncates them (``to_digits_exp`` at ``dps + 3``
    digits, the first step of ``nstr``) are exactly ``N`` (``dps`` digits), then ``5`` and zeros
    (``below``: the truncated digits one unit less, ``...4999``); the leading digit stands for
    ``10**E``."""
    value = (10 * N + 5) * Fraction(10) ** (E - dps)
    top = math.floor(math.log2(value)) + 1
    while Fraction(2) ** top <= value:
        top += 1
    while Fraction(2) ** (top - 1) > value:
        top -= 1
    bitprec = int((dps + 3) * math.log(10, 2)) + 10
    fixprec = bitprec - top
    fixdps = int(fixprec / math.log(10, 2) + 0.5)
    target = (10 * N + 5) * 10 ** (fixdps + E - dps) - below
    q = -((-target << fixprec) // 10**fixdps)  # the least q with q 10**fixdps >> fixprec = target
    return _mpf(q, -fixprec)


@pytest.mark.parametrize("dps", [1, 2, 3, 15, 50, 100])
def test_truncated_ties_from_balls_as_before(dps):
    """Midpoints whose truncated digits end exactly in ``5000...`` (a tie of the rounding that
    mpmath decides half up) and one unit below it (``4999...``), positive and negative, in fixed
    point and with an exponent, and runs of nines that carry into the next power of ten: rows
    from balls against the reference (:func:`assert_balls_as_numbers`)."""
    from mpmath.libmp import to_digits_exp

    rng = random.Random(dps)
    hits = 0
    for _ in range(6):
        row = []
        for E in (0, -1, rng.choice([-30, -7, 3])):
            N = rng.randrange(10 ** (dps - 1), 10**dps)
            for below in (False, True):
                x = _truncated_tie(N, E, dps, below)
                _, digits, exponent = to_digits_exp(x._mpf_, dps + 3)
                tail = digits[dps:]
                hits += tail == "5" + "0" * (len(tail) - 1) and exponent == E and not below
                row.append(x)
        nines = _truncated_tie(10**dps - 1, rng.choice([0, -2, 4]), dps, False)
        row += [nines, -row[0], -row[1]]
        for i in range(0, len(row) - 3, 2):
            xs = row[i : i + 4]
            r = _mpf(1, int(mpmath.floor(mpmath.log(abs(xs[0]), 2))) - int(dps * 3.33) - 60)
            b = _row(xs[0], dps, radii=(r, r, r, r), deltas=(xs[2], xs[3]))
            assert_balls_as_numbers(dataclasses.replace(b, upper=xs[1]))
    # exact powers of ten: the truncated digits a power of ten themselves
    tens = [mpmath.mpf(1), mpmath.mpf(10), mpmath.mpf(-100), mpmath.mpf(10) ** 5]
    r = _mpf(1, -int(dps * 3.33) - 60)
    b = _row(tens[0], dps, radii=(r, r, r, r), deltas=(tens[2], tens[3]))
    assert_balls_as_numbers(dataclasses.replace(b, upper=tens[1]))
    assert hits >= 12  # the exact ties were made


def test_largest_bound_as_before():
    """:func:`verify.rounding.largest_bound` (the rows' raw items, on one scale) against the
    largest error in Fraction arithmetic."""
    from verify.result import _proven
    from verify.rounding import largest_bound

    cases = list(_cases(8, 1200))
    for i in range(0, len(cases), 4):
        raw, ref = [], []
        for x, r, d in cases[i : i + 4]:
            text, dk = _proven(x, r, d)
            if dk is None:  # huge exponents: mpmath's own text, the general path
                continue
            raw.append((dk, x._mpf_, r._mpf_))
            ref.append(reference_error(text, x, r))
        assert largest_bound(raw) == (reference_bound(max(ref)) if ref else None)
    assert largest_bound([]) is None


def test_raw_numbers_of_balls_exact():
    """The raw numbers a from-balls result prints from (midpoints and radii read from the balls,
    radii through doubles where that is exact) are the balls' exact values
    (:func:`verify.certify.exact_mpf`, the reference conversion), at radii from 2**-3000 to
    2**40, around 1 and around the least radius taken through a double (2**-990)."""
    from flint import arb

    from verify.certify import exact_mpf
    from verify.result import from_balls

    rng = random.Random(77)
    exps = [-3000, -991, -990, -989, -200, -31, -30, -1, 0, 1, 40]
    for e in exps:
        for rman in (1, 2**29 + 1, 2**30 - 1, rng.randrange(1, 2**30)):
            rad = _mpf(rman, e)
            mid = _mpf(rng.choice([-1, 1]) * rng.randrange(1, 2**200), -199)
            balls = [arb(mid.man_exp[0] * (-1 if mid < 0 else 1)) * arb(2) ** -199] * 4
            balls = [arb(x.mid(), arb(rad)) for x in balls]
            b = from_balls(
                balls,
                order=1,
                m=Fraction(1, 2),
                Q=None,
                damping="none",
                digits=50,
                method="certified",
                regime="",
                system=boundary(1, Fraction(1, 2)).system,
            )
            mids, rads = b._raw
            assert mids == tuple(exact_mpf(x.mid())._mpf_ for x in balls)
            assert rads == tuple(exact_mpf(x.rad())._mpf_ for x in balls)


def test_many_thousand_digits_print():
    """5000 digits and more (the certified limit is 100000): the texts are those of the reference
    (``mpmath.nstr``, Python's limit on integer-to-text conversion lifted for it), and printing
    does not run into that limit itself."""
    b = boundary(3, "3/10", digits=5000)
    texts = b.printed()
    assert str(b).count("\n") == 3 and b.error_bound() == texts[4]
    limit = sys.get_int_max_str_digits()
    sys.set_int_max_str_digits(0)
    try:
        values = (b.lower, b.upper, b.delta_lower, b.delta_upper)
        for k, (x, r) in enumerate(zip(values, b.radii, strict=True)):
            assert texts[k] == reference_text(x, r, 5000)
    finally:
        sys.set_int_max_str_digits(limit)
    assert len(texts[0]) == 5001  # 5000 digits and the point


@pytest.mark.parametrize("digits", [3, 15, 50, 100])
def test_rows_with_wide_radii_and_zeros_as_before(digits):
    """Rows from balls whose radii lie between one unit of the truncated digits (``10**-F``,
    below which a radius is left out of the bound's bracket in doubles) and the least radius that
    leaves not every digit usable -- each counted in the bound exactly -- and rows with a number
    printed ``"0"`` (its radius wider than itself: its error ``|x| + r`` taken in doubles) beside
    numbers printed in full: rows from balls against the reference
    (:func:`assert_balls_as_numbers`), written in the one pass of
    :func:`verify.result._row_of_balls`."""
    from verify.certify import ball
    from verify.result import _row_of_balls

    def exact(v) -> Fraction:
        man, exp = v.man_exp
        return Fraction(man) * Fraction(2) ** exp

    rng = random.Random(digits)
    bits = int(digits * 3.33) + 60
    zeros = 0
    for _ in range(30):
        # the last below 1/8 (a radius three times it stays below 1, the one pass's reach)
        xs = [
            _mpf(rng.choice([-1, 1]) * rng.getrandbits(bits), rng.randint(-12, top) - bits)
            for top in (12, 12, 12, -3)
        ]
        # |x| 10**-(digits + j): every digit usable (j >= 1), and above one unit (j <= 3)
        radii = [
            _rounded(abs(exact(x)) / 10 ** (digits + rng.choice([1, 2, 3])), 30, True) for x in xs
        ]
        if rng.random() < 0.5:  # a number printed "0": its radius three times itself
            radii[3] = _rounded(3 * abs(exact(xs[3])), 30, True)
            zeros += 1
        b = _row(xs[0], digits, radii=tuple(radii), deltas=(xs[2], xs[3]))
        assert_balls_as_numbers(dataclasses.replace(b, upper=xs[1]))
        balls = [ball(x, r) for x, r in zip(xs, radii, strict=True)]
        row = _row_of_balls(balls, digits)
        assert row is not None and (row[0][3] == "0") == (radii[3] > abs(xs[3]))
    assert zeros > 5


def test_row_bound_on_a_two_digit_value_and_beside_one():
    """The bound of a row from its errors' bounds in doubles (:func:`verify.result._row_of_balls`,
    :func:`verify.result._bound_between`) where the largest error is exactly a two-digit value
    (``|1.00e+4 - 10000.5| + 0.25 = 7.5e-1``: the doubles cannot tell it from a hair above, the
    integers decide) and a hair away from one, on
    either side: rows from balls against the reference (:func:`assert_balls_as_numbers`)."""
    from verify.certify import ball
    from verify.result import _bound_between, _row_of_balls

    # on a two-digit value: the exact bound decides
    assert _bound_between(0.75, 0.75) is None and _bound_between(0.749, 0.7500001) is None
    assert _bound_between(0.7500001, 0.7500002) == "7.6e-1"
    assert _bound_between(0.7491, 0.7499) == "7.5e-1"
    assert _bound_between(0.995, 0.996) == "1.0e0" and _bound_between(1e-300, 1e-299) is None
    assert _bound_between(0.0999, 0.1001) is None  # either side of a power of ten
    x = mpmath.mpf("10000.5")
    quarter = mpmath.mpf("0.25")
    small = mpmath.mpf("0.125")  # the other numbers' errors are smaller
    # radii as the balls hold them (arb's radii have 30-bit mantissas, rounded up): exactly a
    # quarter (the largest error then exactly 0.75), a hair above, a hair below
    for r, expected in (
        (quarter - mpmath.ldexp(1, -40), "7.5e-1"),
        (quarter + mpmath.ldexp(1, -40), "7.6e-1"),
        (quarter - mpmath.ldexp(1, -20), "7.5e-1"),
    ):
        radii = (r, small / 64, small / 64, small / 64)
        b = dataclasses.replace(_row(x, 3, radii=radii, deltas=(small, -small)), upper=x - quarter)
        assert_balls_as_numbers(b)
        balls = [ball(v, rr) for v, rr in zip((x, x - quarter, small, -small), radii, strict=True)]
        texts, bound = _row_of_balls(balls, 3)
        assert texts[:2] == ("1.00e+4", "1.00e+4") and bound == expected
    assert ball(x, quarter - mpmath.ldexp(1, -40)).rad() == 0.25  # the exact case was made


@pytest.mark.parametrize(
    "x, rad, digits, text",
    [
        ("2.2", "0.04", 30, "2"),
        ("-2.2e-30", "4e-32", 30, "-2e-30"),
        ("22", "0.4", 30, "2e+1"),
        ("123.4", "0.004", 3, "123"),
        ("98765.4321", "1e-20", 5, "98765"),
        ("-7.7", None, 1, "-8"),
        ("0.0123", "1e-30", 1, "0.01"),
    ],
)
def test_no_point_without_a_digit_after_it(x, rad, digits, text):
    """A proven decimal whose digits all stand before the point is written without one (mpmath
    writes ``"2."`` and ``"2.e-30"``): one digit, or every digit of an integer part."""
    r = None if rad is None else mpmath.mpf(rad)
    assert proven_text(mpmath.mpf(x), r, digits) == text
