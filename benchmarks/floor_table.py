"""``table --digits 50``: formatting a row against solving it.

Ours is the text of one row as ``paramres table`` writes it (the four proven decimals and the
bound of the printed digits, :meth:`verify.result.Boundary.as_json`) for a fresh result; the floor
is solving that row (:func:`verify.solve.boundary`).  The target is that formatting costs at most
15 % of solving.
"""

from __future__ import annotations

import dataclasses
from fractions import Fraction

DEPTHS = [Fraction(k, 20) for k in range(1, 19)]


def scenes(quick: bool) -> list[dict]:
    from verify.solve import boundary

    ms = DEPTHS[::3] if quick else DEPTHS
    results = [boundary(3, m, digits=50) for m in ms]

    def fmt():
        for b in results:
            dataclasses.replace(b).as_json()  # a fresh result: nothing formatted yet

    def solve():
        for m in ms:
            boundary(3, m, digits=50)

    return [
        {
            "name": "table --digits 50: formatting / solving",
            "target": 0.15,
            "ours": fmt,
            "floor": solve,
            "note": "formatting a row (proven decimals, bound of the print) against solving it",
        }
    ]
