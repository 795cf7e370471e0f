"""``paramres multipliers``: both Floquet multipliers at one point, certified.

    paramres multipliers --T T [--m M] [--Q Q] [--damping exact|paper] [--digits D]
                         [--system S] [--duty D] [--omega-sq W1,W2 --jump K]
                         [--modulation square|ramp|sine] [--switch-time S] [--json]

The monodromy over one modulation period is built from the segment maps and the switches in ball
arithmetic (the independent Floquet route, :mod:`verify.multipliers`); both eigenvalues, the
largest modulus and the growth rate per period are printed with every digit proven.
"""

from __future__ import annotations

import argparse

from reports.output import dump_json
from verify.inputs import InputError

from ._arguments import add_depth, add_friction, add_json, add_modulation, add_system, system_of

__all__ = ["register", "run"]


def register(subparsers) -> None:
    p = subparsers.add_parser(
        "multipliers",
        help="certified Floquet multipliers, |mu|max and the growth per period at one (T, m)",
        description=(
            "Both Floquet multipliers of the oscillator at modulation period T (units of T0) and "
            "depth m, from the monodromy matrix built in ball arithmetic, with every printed digit "
            "proven; the largest modulus |mu|max (> 1 inside an interval of instability) and the "
            "growth of the amplitude per period ln|mu|max."
        ),
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    p.add_argument(
        "--T", required=True, metavar="T", help="modulation period T/T0, 0 < T <= 1e6 (exact)"
    )
    add_depth(p, required=False)
    add_friction(p)
    p.add_argument(
        "--digits", default="30", metavar="D", help="significant digits, 5 to 10000 (default 30)"
    )
    add_system(p)
    add_modulation(p)
    add_json(p)
    p.set_defaults(func=run)


def run(args) -> int:
    from verify.modulation import multipliers

    sysv = system_of(args)
    if args.T is None:  # pragma: no cover - argparse requires it
        raise InputError("--T is required")
    result = multipliers(
        args.T,
        args.m,
        Q=args.Q,
        damping=args.damping,
        digits=args.digits,
        system=sysv,
        modulation=args.modulation,
        switch_time=args.switch_time,
    )
    if args.json:
        dump_json(result.as_json())
    else:
        print(result)
    return 0
