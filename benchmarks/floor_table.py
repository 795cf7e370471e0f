"""``table --digits 50``: formatting a table against solving it.

Ours is everything ``paramres table --digits 50`` does beyond solving, for a table of order 3
at 18 depths: its rows (:func:`reports.commands.table.rows`: the engine's loop in this process,
the progress stream, each row's four proven decimals and the bound of the printed digits,
:meth:`verify.result.Boundary.printed`, in C where the package was built with a compiler,
:mod:`verify._digits`) and its CSV text (:func:`reports.commands.table.csv_text`, what the
command prints).  Only the solver is replaced: it hands out its results, each in exactly the
state :func:`verify.result.from_balls` (the constructor the solver itself calls) leaves it in,
from the solver's four balls -- nothing formatted and nothing converted from the balls yet, so
formatting pays every conversion the printed text needs.  Building the result is the solver's
own last step, paid by the floor: here each result is built once, before the timing, and handed
out again after what printing kept in it (the texts and the bound, the keys it added) is taken
out, so that it is back in from_balls's state.  The floor is solving those rows
(:func:`verify.solve.boundary`).  The target is that formatting costs at most 15 % of solving.
"""

from __future__ import annotations

from fractions import Fraction

DEPTHS = [Fraction(k, 20) for k in range(1, 19)]
HEADER = ["order", "m", "lower", "upper", "delta_lower", "delta_upper", "error_bound"]


def _added_by_printing(result) -> tuple:
    """The keys printing adds to a result as the solver returns it (its texts and its bound,
    kept), printed from a copy; printing changes none of the keys it was built with."""
    attributes = dict(vars(result))
    copy = object.__new__(type(result))
    object.__setattr__(copy, "__dict__", dict(attributes))
    copy.printed()
    assert all(vars(copy)[k] is v for k, v in attributes.items())
    return tuple(k for k in vars(copy) if k not in attributes)


def scenes(quick: bool) -> list[dict]:
    from analytic.system import PAPER
    from reports.commands import table
    from verify.result import from_balls
    from verify.solve import boundary

    ms = DEPTHS[::3] if quick else DEPTHS
    # what the solver returns: from_balls of its balls and the row's fields, as built (nothing
    # printed from it yet); handed out again, each time back in that state: what printing kept
    # in it (the keys it added, found once here) is taken out first
    pool = []
    keys = ("order", "m", "Q", "damping", "digits", "method", "regime", "system", "notes")
    for m in ms:
        b = boundary(3, m, digits=50)
        built = from_balls(b._balls, certified=b.certified, **{k: getattr(b, k) for k in keys})
        pool.append((m, built.__dict__, built))
    added = _added_by_printing(pool[0][2])

    def fmt():
        solved = iter(pool)

        def fresh(order, m, *, Q, damping, digits, system, modulation, switch_time):
            depth, d, result = next(solved)
            assert depth is m
            for key in added:
                d.pop(key, None)
            return result

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
                "the table's rows and CSV text with the solver handing out fresh results "
                "(from_balls's state of its balls, nothing converted) against solving them"
            ),
        }
    ]
