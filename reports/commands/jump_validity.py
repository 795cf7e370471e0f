"""``paramres jump-validity``: up to which switching time is the instantaneous jump a good model?

    paramres jump-validity --order N --m M --tol TOL [--duty D] [--digits D] [--json] [-q]

Replaces each jump of the pendulum's length by a linear ramp lasting ``S`` (units ``T0``) and
gives the largest ``S`` for which both certified edges of the ``N``-th interval stay within the
relative tolerance ``TOL`` of the jump model's edges, with the derived slope ``dT/dS`` at ``S = 0``
and a table of certified shifts (:func:`verify.ramp.jump_validity`).
"""

from __future__ import annotations

import argparse

from reports.output import dump_json, working

from ._arguments import add_depth, add_json, add_order, add_quiet

__all__ = ["register", "run"]


def register(subparsers) -> None:
    p = subparsers.add_parser(
        "jump-validity",
        help="the largest switching time S for which the jump model's edges hold to a tolerance",
        description=(
            "The paper's model lets the pendulum's length jump instantly. With a linear ramp of "
            "the length lasting S (units of T0) at each switch, the edges of the N-th interval "
            "move; this command gives the largest S for which both edges stay within the "
            "relative tolerance TOL of the jump model's edges (proven by certified edges just "
            "below and just above), the derived leading shift dT/dS at S = 0, and the certified "
            "shifts at a few S. Pendulum without friction. The time grows in proportion to "
            "the order (the lower edge is followed in S, in steps of a fixed fraction of the "
            "spacing of the orders, up to the longest ramp that fits a phase, which grows with "
            "the order): seconds for the low orders, about half a minute at order 1000 and "
            "minutes near 10000; the elapsed time is shown on stderr (on a terminal; -q turns "
            "it off)."
        ),
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    add_order(p)
    add_depth(p)
    p.add_argument(
        "--tol",
        required=True,
        metavar="TOL",
        help="relative tolerance of the edges T/T0, 1e-12 to 0.1 (e.g. 1e-3)",
    )
    p.add_argument(
        "--duty",
        default="1/2",
        metavar="D",
        help="fraction of the period spent in phase 1 (the long pendulum), 0 < D < 1; default 1/2",
    )
    p.add_argument(
        "--digits",
        default="15",
        metavar="D",
        help="digits of the certified edges, 5 to 10000 (default 15)",
    )
    add_json(p)
    add_quiet(p)
    p.set_defaults(func=run)


def run(args) -> int:
    from verify.ramp import jump_validity

    with working("jump-validity", quiet=args.quiet):
        result = jump_validity(args.order, args.m, args.tol, duty=args.duty, digits=args.digits)
    if args.json:
        dump_json(result.as_json())
    else:
        print(result)
    return 0
