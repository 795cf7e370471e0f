"""``paramres boundary``: the certified edges of one interval of instability.

    paramres boundary --order N --m M [--Q Q] [--damping exact|paper] [--digits D | --tol TOL]
                      [--method certified|fixedpoint] [--system S] [--duty D]
                      [--modulation square|ramp|sine] [--switch-time S] [--json]

Prints the lower and upper edge ``T/T0`` and their offsets ``T - n T_av/2`` with ``D`` proven
digits (ball arithmetic; see :mod:`verify.solve`), or says that the interval does not exist.
With ``--tol`` the engine picks the cheapest method that provably meets the relative tolerance
(:mod:`verify.auto`) and names it.
"""

from __future__ import annotations

import argparse

from reports.output import dump_json
from verify.fixedpoint import FixedPointError
from verify.inputs import InputError
from verify.modulation import boundary
from verify.solve import METHODS

from ._arguments import (
    add_depth,
    add_friction,
    add_json,
    add_modulation,
    add_order,
    add_system,
    system_of,
)

__all__ = ["register", "run"]


def register(subparsers) -> None:
    p = subparsers.add_parser(
        "boundary",
        help="certified lower and upper edge T/T0 of the interval of order N at depth m",
        description=(
            "The edges of the N-th interval of parametric instability at modulation depth m, "
            "in units of T0, each digit proven by interval (ball) arithmetic. With --Q the "
            "friction is included in the exact (damped oscillator) or the paper's model; the "
            "interval may then not exist (below the threshold, or where friction swallows it "
            "near a closing). --method fixedpoint runs the paper's own iteration instead "
            "(eqs. 15, 26, 39, 44; not certified)."
        ),
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    add_order(p)
    add_depth(p, required=False)
    add_friction(p)
    add_system(p)
    add_modulation(p)
    p.add_argument(
        "--digits", default=None, metavar="D", help="significant digits, 5 to 100000 (default 30)"
    )
    p.add_argument(
        "--tol",
        default=None,
        metavar="TOL",
        help=(
            "instead of --digits: the relative error of T/T0 wanted (1e-10000 to 0.1); the "
            "cheapest method that provably meets it is used (a series in m, double precision or "
            "the certified solver at just enough digits) and named in the output; the paper's "
            "system only (pendulum, D = 1/2, square modulation)"
        ),
    )
    p.add_argument(
        "--method",
        default="certified",
        metavar="METHOD",
        help=f"solver: {', '.join(sorted(METHODS))} (default certified; auto and fixedpoint: "
        "the paper's system only)",
    )
    add_json(p)
    p.set_defaults(func=run)


def run(args) -> int:
    if args.tol is not None and args.digits is not None:
        raise InputError("--tol and --digits exclude each other (the tolerance sets the digits)")
    sysv = system_of(args)
    try:
        result = boundary(
            args.order,
            args.m,
            system=sysv,
            Q=args.Q,
            damping=args.damping,
            digits=30 if args.digits is None else args.digits,
            method=args.method,
            tol=args.tol,
            modulation=args.modulation,
            switch_time=args.switch_time,
        )
    except FixedPointError as exc:
        raise InputError(f"the fixed-point iteration failed ({exc.kind}): {exc}") from None
    if args.json:
        doc = result.as_json()
        if args.tol is not None:
            doc["tolerance"] = str(args.tol).strip()
        doc["modulation"] = args.modulation.strip().lower()
        if args.switch_time is not None:
            doc["switch_time"] = str(args.switch_time).strip()
        dump_json(doc)
    else:
        print(result)
    return 0
