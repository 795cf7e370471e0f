"""``table --digits 50``: formatting a table against solving it.

Ours is everything ``paramres table --digits 50`` does beyond solving, for a table of order 3
at 18 depths: its rows (:func:`reports.commands.table.rows`: the engine's loop in this process,
the progress stream, each row's four proven decimals and the bound of the printed digits,
:meth:`verify.result.Boundary.printed`) and its CSV text (:func:`reports.commands.table.csv_text`,
what the command prints).  Only the solver is replaced: it hands out fresh results, built by
:func:`verify.result.from_balls` (the constructor the solver itself calls) from the solver's four
balls -- nothing formatted and nothing converted from the balls yet, so formatting pays every
conversion the printed text needs, and the building of the result (the solver's own last step)
as well.  The floor is solving those rows (:func:`verify.solve.boundary`).  The target is that
formatting costs at most 15 % of solving.
"""

from __future__ import annotations

from fractions import Fraction

DEPTHS = [Fraction(k, 20) for k in range(1, 19)]
HEADER = ["order", "m", "lower", "upper", "delta_lower", "delta_upper", "error_bound"]


def scenes(quick: bool) -> list[dict]:
    from analytic.system import PAPER
    from reports.commands import table
    from verify.result import from_balls
    from verify.solve import boundary

    ms = DEPTHS[::3] if quick else DEPTHS
    # what the solver hands to from_balls: its balls and the row's fields
    made = []
    for m in ms:
        b = boundary(3, m, digits=50)
        keys = ("order", "m", "Q", "damping", "digits", "method", "regime", "system", "notes")
        made.append((m, b._balls, {k: getattr(b, k) for k in keys}, b.certified))

    def fmt():
        solved = iter(made)

        def fresh(order, m, *, Q, damping, digits, system, modulation, switch_time):
            # the solver's results, fresh: nothing converted
            depth, balls, kw, certified = next(solved)
            assert depth is m
            return from_balls(balls, certified=certified, **kw)

        table._solver = fresh
        try:
            data = table.rows([3], ms, None, "exact", 50, 1, system=PAPER)
        finally:
            table._solver = None
        table.csv_text(HEADER, data)

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
                "the table's rows and CSV text with the solver handing out fresh from_balls "
                "results (its constructor, its balls, nothing converted) against solving them"
            ),
        }
    ]
