"""``paramres existence``: the depths at which an interval of instability exists with friction.

    paramres existence --order N --Q Q [--damping exact|paper] [--digits D] [--json]
                       [--system pendulum|torsion|meissner] [--duty D]

Prints the ranges ``a < m < b`` (``b = 1``: open towards ``m -> 1``) with proven ends: the threshold
and the gaps where friction swallows the interval near a closing.  The whole depth axis is proven
(see :func:`verify.existence.existence`): inside a range the interval exists at every depth, in a
gap at none; what could not be decided is printed as ``undecided``.
"""

from __future__ import annotations

import argparse

from reports.output import dump_json, working
from verify.existence import existence

from ._arguments import add_friction, add_json, add_order, add_quiet, add_system, system_of

__all__ = ["register", "run"]


def register(subparsers) -> None:
    p = subparsers.add_parser(
        "existence",
        help="depth ranges where the interval of order N exists with friction Q",
        description=(
            "With friction an interval of instability exists only above a threshold depth, and "
            "an interval of order N >= 3 also vanishes near every depth where it would close. "
            "Prints the ranges of m in (0, 1) where it exists, each end proven to D digits; "
            "every range and every gap is proven (interval arithmetic over depth ranges), and a "
            "range that could not be decided is printed as undecided."
        ),
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    add_order(p)
    add_friction(p, required=True)
    p.add_argument(
        "--digits", default="15", metavar="D", help="digits of each end, 5 to 3000 (default 15)"
    )
    add_system(p)
    add_json(p)
    add_quiet(p)
    p.set_defaults(func=run)


def run(args) -> int:
    sysv = system_of(args)
    with working("existence", quiet=args.quiet):
        result = existence(
            args.order, args.Q, system=sysv, damping=args.damping, digits=args.digits
        )
    if args.json:
        data = result.as_json()
        dump_json(
            {
                "system": data["system"],
                "duty": data["duty"],
                "order": data["order"],
                "Q": data["Q"],
                "damping": data["damping"],
                "intervals": data["intervals"],
                "digits": data["digits"],
                "thresholds": data["thresholds"],
                "undecided": data["undecided"],
            }
        )
    else:
        print(result)
    return 0
