"""``table --digits 50``: formatting a row against solving it.

Ours is the text of one row as ``paramres table`` writes it (the four proven decimals and the
bound of the printed digits, :meth:`verify.result.Boundary.printed`) for a fresh result: one built
by :func:`verify.result.from_balls`, the constructor the solver calls, from the solver's four
balls -- nothing formatted and nothing converted from the balls yet, so formatting pays every
conversion the printed text needs.  The floor is solving that row (:func:`verify.solve.boundary`).
The target is that formatting costs at most 15 % of solving.
"""

from __future__ import annotations

from fractions import Fraction

DEPTHS = [Fraction(k, 20) for k in range(1, 19)]


def scenes(quick: bool) -> list[dict]:
    from verify.result import from_balls
    from verify.solve import boundary

    ms = DEPTHS[::3] if quick else DEPTHS
    # what the solver hands to from_balls: its balls and the row's fields
    made = []
    for m in ms:
        b = boundary(3, m, digits=50)
        keys = ("order", "m", "Q", "damping", "digits", "method", "regime", "system", "notes")
        made.append((b._balls, {k: getattr(b, k) for k in keys}, b.certified))

    def fmt():
        for balls, kw, certified in made:
            from_balls(balls, certified=certified, **kw).printed()  # fresh: nothing converted

    def solve():
        for m in ms:
            boundary(3, m, digits=50)

    return [
        {
            "name": "table --digits 50: formatting / solving",
            "target": 0.15,
            "ours": fmt,
            "floor": solve,
            "note": (
                "formatting a row (proven decimals, bound of the print) of a fresh from_balls "
                "result (the solver's constructor, its balls, nothing converted) against solving it"
            ),
        }
    ]
