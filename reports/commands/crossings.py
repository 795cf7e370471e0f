"""``paramres crossings``: every depth at which an interval of order <= N closes.

    paramres crossings --max-order N [--json]

Both edges of the n-th interval meet exactly where omega_1 T/2 = a pi and omega_2 T/2 = b pi with
integers 1 <= a < b, a + b = n (the closing theorem of :mod:`analytic.closings`); the depth is the
rational m = (b^2 - a^2)/(b^2 + a^2), the period T = a T1 (printed with 40 certified digits).
"""

from __future__ import annotations

import argparse
from math import gcd

from reports.output import dump_json

from ._arguments import add_system, system_of

__all__ = ["register", "run", "render_text"]


def register(subparsers) -> None:
    p = subparsers.add_parser(
        "crossings",
        help="every closing of every interval up to order N (exact depths, certified periods)",
        description=(
            "List every depth m (exact rational) at which the interval of order n <= N closes, "
            "with the ratio T1:T2 = b:a of the natural periods there and the modulation period T "
            "in units of T0 (40 correctly rounded digits, from an interval enclosure). The list is "
            "complete: both edges meet only where omega_1 T/2 = a pi and omega_2 T/2 = b pi, "
            "1 <= a < b, a + b = n (the closing theorem; its derivation steps are checked on "
            "every run)."
        ),
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    p.add_argument("--max-order", required=True, metavar="N", help="largest order, 1 to 200")
    p.add_argument("--json", action="store_true", help="machine-readable output")
    add_system(p)
    p.set_defaults(func=run)


def run(args) -> int:
    from analytic.closings import closings

    result = closings(args.max_order, system_of(args))
    if not result.proven:  # pragma: no cover - a failed step would be a bug in the engine
        raise RuntimeError("a step of the closing theorem did not check out")
    if args.json:
        dump_json(json_document(result))
    else:
        print(render_text(result))
    return 0


def json_document(result) -> dict:
    """The ``--json`` document: one object, exact depths as fractions, each period ``T`` (correctly
    rounded) with ``T_error_bound``, half a unit of its last digit."""
    from decimal import Decimal
    from fractions import Fraction

    from verify.rounding import bound_text

    closings = []
    for item in result.as_json():
        exponent = Decimal(item["T"]).as_tuple().exponent
        assert isinstance(exponent, int)
        half_unit = Fraction(1, 2) * Fraction(10) ** exponent
        closings.append({**item, "T_error_bound": bound_text(half_unit)})
    return {
        **result.system.as_json(),
        "max_order": result.max_order,
        "statement": result.statement,
        "closings": closings,
    }


def render_text(result) -> str:
    where = "" if result.system.is_paper else f" of the {result.system.label}"
    lines = [
        f"Closings of the intervals of order n <= {result.max_order}{where} (no friction)",
        "",
        result.statement,
        f"Derivation: {len(result.steps)} steps, all checked "
        f"({sum(s.verdict.route == 'symbolic' for s in result.steps)} symbolically).",
        "",
    ]
    if not result.items:
        lines.append("No interval of these orders closes (closings need n >= 3).")
        return "\n".join(lines)
    head = f"{'n':>4}  {'T1:T2':>7}  {'m':>12}  {'m (decimal)':>14}  T/T0"
    lines.append(head)
    lines.append("-" * len(head) + "-" * 36)
    for c in result.items:
        m = "-" if c.m is None else f"{c.m.numerator}/{c.m.denominator}"
        mdec = "-" if c.m is None else f"{float(c.m):.10f}"
        g = gcd(c.a, c.b)
        note = (
            ""
            if g == 1 or not result.system.is_paper
            else f"   (= {c.reduced_ratio}: the depth of order {c.order // g})"
        )
        lines.append(f"{c.order:>4}  {c.ratio:>7}  {m:>12}  {mdec:>14}  {c.T}{note}")
    return "\n".join(lines)
