"""The text of ``paramres table`` (:func:`reports.commands.table.csv_text`,
:func:`reports.commands.table.decimal_text`) against the general formulations they replace: the
CSV as :mod:`csv`'s writer writes it, and a depth's decimal in :class:`fractions.Fraction`
arithmetic with its zeros stripped."""

from __future__ import annotations

import csv
import io
import random
from fractions import Fraction

from reports.commands.table import csv_text, decimal_text


def reference_decimal(x: Fraction) -> str:
    """The decimal of ``x`` as first written: strip the factors 10, 2 and 5 of the denominator,
    scale by the power of ten they need, strip trailing zeros (``p/q`` if it does not end)."""
    d = x.denominator
    k = 0
    while d % 10 == 0:
        d //= 10
        k += 1
    twos = fives = 0
    while d % 2 == 0:
        d //= 2
        twos += 1
    while d % 5 == 0:
        d //= 5
        fives += 1
    if d != 1:
        return f"{x.numerator}/{x.denominator}"
    places = k + max(twos, fives)
    scaled = x * 10**places
    sign = "-" if scaled < 0 else ""
    digits = str(abs(scaled.numerator // scaled.denominator)).rjust(places + 1, "0")
    text = digits[:-places] + "." + digits[-places:] if places else digits
    return sign + (text.rstrip("0").rstrip(".") if "." in text else text)


def reference_csv(header, data) -> str:
    buf = io.StringIO()
    w = csv.writer(buf, lineterminator="\n")
    w.writerow(header)
    for r in data:
        w.writerow([r[0], decimal_text(r[1])] + ["" if v is None else v for v in r[2:]])
    return buf.getvalue()


def test_depths_as_before():
    """Terminating and non-terminating depths, signs, zero, integers, tiny and huge
    denominators (powers of 2, 5, 10 and their products), each twice (the second time from the
    denominators kept)."""
    rng = random.Random(5)
    dens = [1, 2, 3, 4, 5, 6, 7, 8, 10, 12, 16, 20, 25, 40, 64, 100, 125, 1000, 1024]
    dens += [5**9, 2**20, 10**30, 2**70 * 5**3, 3 * 10**5]
    cases = [Fraction(k, 20) for k in range(-40, 41)]
    cases += [Fraction(rng.randint(-(10**9), 10**9), rng.choice(dens)) for _ in range(5000)]
    cases += [Fraction(0), Fraction(1, 10**40), Fraction(-3, 2**70), Fraction(10**50 + 1, 8)]
    for x in cases + cases:
        assert decimal_text(x) == reference_decimal(x), x
    assert decimal_text(Fraction(1, 20)) == "0.05" and decimal_text(Fraction(-7, 2)) == "-3.5"
    assert decimal_text(Fraction(2, 3)) == "2/3" and decimal_text(Fraction(-12)) == "-12"


def test_csv_as_the_writer_writes_it():
    """Certified rows, rows with missing numbers (no interval), a method column, and fields the
    writer quotes (a comma, a quote, line breaks): the same text as :mod:`csv`'s writer."""
    header = ["order", "m", "lower", "upper", "delta_lower", "delta_upper", "error_bound"]
    data = [
        (3, Fraction(1, 20), "1.36", "1.55", "-0.097", "0.092", "2.2e-50"),
        (3, Fraction(1, 3), "1.2e-7", "-3.0e+12", "0", "0.5", "4.4e-50"),
        (1, Fraction(1, 20), None, None, None, None, None),
        (2, Fraction(9, 10), "1,5", 'a "b"', "x\ny", "c\rd", ""),
        (2, Fraction(-1, 4), "", "1", "2", "3", "4"),
        (4, Fraction(7, 8), 1.5, 2, "3", "4", "5"),
    ]
    assert csv_text(header, data) == reference_csv(header, data)
    assert csv_text(header + ["method"], [(*data[0], "certified (22 digits)")]) == (
        reference_csv(header + ["method"], [(*data[0], "certified (22 digits)")])
    )
    assert csv_text(header, []) == reference_csv(header, [])
