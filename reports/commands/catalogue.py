"""``paramres catalogue``: every numbered formula of the paper, printed against derived."""

from __future__ import annotations

import argparse
import textwrap

from reports.output import dump_json, working

from ._arguments import add_quiet

__all__ = ["register", "run"]


def register(sub) -> None:
    p = sub.add_parser(
        "catalogue",
        help="the paper's numbered formulas: printed vs derived, agrees/differs and why",
        description=(
            "One row per numbered formula of the paper: its printed form, the form the engine "
            "derives from the model, whether they agree (decided by symbolic simplification, or at "
            "many random points at 40 digits where sympy cannot) and, where the print differs, "
            "what the correct form is."
        ),
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    p.add_argument(
        "--json",
        action="store_true",
        help="one JSON object (its rows under 'results') instead of text",
    )
    p.add_argument(
        "--only",
        choices=("agrees", "differs"),
        help="show only the rows with this status",
    )
    add_quiet(p)
    p.set_defaults(func=run)


def run(args) -> int:
    from analytic.catalogue import catalogue

    with working("catalogue", quiet=args.quiet):  # a cold derivation takes seconds
        every = catalogue()
    rows = [r for r in every if args.only is None or r.status == args.only]
    if args.json:
        dump_json(
            {
                "only": args.only,
                "checked": len(rows),
                "agree": sum(r.status == "agrees" for r in rows),
                "differ": sum(r.status == "differs" for r in rows),
                "results": [r.as_json() for r in rows],
            }
        )
        return 0
    n_diff = sum(r.status == "differs" for r in rows)
    print(f"{len(rows)} results checked: {len(rows) - n_diff} agree, {n_diff} differ\n")
    for r in rows:
        mark = "ok " if r.status == "agrees" else "XX "
        print(f"{mark}({r.equation}) {r.title} -- {r.status}")
        for line in textwrap.wrap(r.how, width=96):
            print(f"      {line}")
    return 0
