"""``table --digits 50``: formatting a table against solving it.

Ours is everything ``paramres table --digits 50`` does beyond solving, for a table of order 3
at 18 depths: its rows (:func:`reports.commands.table.rows`: the engine's loop in this process,
the progress stream, each row's four proven decimals and the bound of the printed digits,
:meth:`verify.result.Boundary.printed`) and its CSV text (:func:`reports.commands.table.csv_text`,
what the command prints).  Only the solver is replaced: it hands out fresh results, each in
exactly the state :func:`verify.result.from_balls` (the constructor the solver itself calls)
leaves it in, from the solver's four balls -- nothing formatted and nothing converted from the
balls yet, so formatting pays every conversion the printed text needs.  Building the result is
the solver's own last step, paid by the floor: a fresh result here is a new object holding a
copy of the attributes of a :func:`~verify.result.from_balls` result taken before anything was
printed from it (the same values, the same class, no cache filled), not a second call of the
constructor.  The floor is solving those rows (:func:`verify.solve.boundary`).  The target is
that formatting costs at most 15 % of solving.
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
    # what the solver returns: from_balls of its balls and the row's fields, kept as built
    # (its class and its attributes, before anything is printed from it)
    made = []
    for m in ms:
        b = boundary(3, m, digits=50)
        keys = ("order", "m", "Q", "damping", "digits", "method", "regime", "system", "notes")
        built = from_balls(b._balls, certified=b.certified, **{k: getattr(b, k) for k in keys})
        made.append((m, type(built), dict(vars(built))))

    new = object.__new__
    set_attributes = object.__setattr__  # the results are frozen dataclasses

    def fmt():
        solved = iter(made)

        def fresh(order, m, *, Q, damping, digits, system, modulation, switch_time):
            # the solver's result, fresh: a new object with from_balls's attributes (a copy:
            # what printing keeps in it stays in it), nothing converted
            depth, cls, attributes = next(solved)
            assert depth is m
            result = new(cls)
            set_attributes(result, "__dict__", attributes.copy())
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
