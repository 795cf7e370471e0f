"""``paramres table``: edges of many intervals at many depths, as CSV or JSON.

    paramres table --orders 1-6 --m START:STOP:STEP [--Q Q] [--damping exact|paper]
                   [--digits D | --tol TOL] [--format csv|json] [--output FILE] [--jobs J]

Without ``--digits`` the vectorised double-precision grid is used (:func:`verify.boundary_grid`
at the exact depths of the rows, relative error below 1e-14; 13 significant digits are printed).
With ``--digits D`` every entry is certified to ``D`` digits (:func:`verify.boundary`), on
``--jobs`` worker processes of a local dask cluster (:mod:`verify.engine`, the engine of
``paramres atlas``; a table too small to pay for starting one runs in this process), with a
progress bar.
With ``--tol TOL`` every entry is proven within the relative tolerance by the cheapest method that
meets it at that order and depth (:func:`verify.auto.boundaries_tol`), named in a ``method`` column.
``--output`` is written atomically (nothing is written if anything fails).
"""

from __future__ import annotations

import argparse
import csv
import io
import json
import os
from fractions import Fraction

import numpy as np

from reports.output import BANNER, atomic_write, progress
from verify.inputs import (
    InputError,
    as_damping,
    as_digits,
    as_modulation,
    as_orders,
    as_quality,
    as_range,
    as_tolerance,
)

from ._arguments import add_friction, add_modulation, add_quiet, add_system, system_of

__all__ = ["register", "run", "rows", "decimal_text", "csv_text"]

GRID_DIGITS = 13


def register(subparsers) -> None:
    p = subparsers.add_parser(
        "table",
        help="edges T/T0 of the intervals of several orders over a range of depths (CSV, JSON)",
        description=(
            "Lower and upper edges T/T0 of the intervals of instability of the given orders at "
            "depths START, START+STEP, ..., STOP. Without --digits: double precision from the "
            "vectorised grid (13 digits). With --digits D: every entry certified to D digits."
        ),
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    p.add_argument("--orders", required=True, metavar="LIST", help="orders, e.g. 1-6 or 1,3,5")
    p.add_argument(
        "--m",
        required=True,
        metavar="START:STOP:STEP",
        help="depths, e.g. 0.05:0.95:0.05 (exact decimal arithmetic)",
    )
    add_friction(p)
    add_system(p)
    add_modulation(p)
    p.add_argument(
        "--digits",
        default=None,
        metavar="D",
        help="certify every entry to D digits, 5 to 10000 (default: double-precision grid)",
    )
    p.add_argument(
        "--tol",
        default=None,
        metavar="TOL",
        help=(
            "instead of --digits: the relative error of T/T0 wanted (1e-10000 to 0.1); each entry "
            "is computed by the cheapest method that provably meets it (series in m, double "
            "precision, certified), named in a method column; the paper's system only "
            "(pendulum, D = 1/2, square modulation)"
        ),
    )
    p.add_argument(
        "--format", default="csv", choices=("csv", "json"), help="output format (default csv)"
    )
    p.add_argument(
        "--output",
        metavar="FILE",
        default=None,
        help="write to FILE (atomically) instead of standard output",
    )
    p.add_argument("--jobs", metavar="J", default="1", help="worker processes, 1 to 64 (default 1)")
    add_quiet(p)
    p.set_defaults(func=run)


def decimal_text(x: Fraction) -> str:
    """A depth as exact decimal text when it terminates, else ``p/q``."""
    num, d = x.as_integer_ratio()
    p = _PLACES.get(d)
    if p is None:
        p = _places(d)
        if len(_PLACES) < 4096:
            _PLACES[d] = p
    if not isinstance(p, tuple):  # no finite decimal
        return f"{num}/{d}"
    places, f = p
    if not places:
        return str(num)
    # no zero to strip: places is the least with d | 10**places, and num is prime to d
    if num < 0:
        digits = str(-num * f).rjust(places + 1, "0")
        return f"-{digits[:-places]}.{digits[-places:]}"
    digits = str(num * f).rjust(places + 1, "0")
    return f"{digits[:-places]}.{digits[-places:]}"


def _places(d: int) -> tuple[int, int] | bool:
    """``(places, 10**places // d)`` with ``places`` the least such that ``d`` divides
    ``10**places`` (``False`` if none: a fraction ``p/d`` in lowest terms has no finite decimal)."""
    twos = (d & -d).bit_length() - 1
    r = d >> twos
    fives = 0
    while not r % 5:
        r //= 5
        fives += 1
    if r != 1:
        return False
    places = max(twos, fives)
    return places, 10**places // d


#: :func:`_places` by denominator (the few a table meets)
_PLACES: dict[int, tuple[int, int] | bool] = {}


def _certified(task):
    """The row of one engine task ``(order, m, Q, damping, digits, system, modulation, S)``."""
    return _row(_solver or _load_solver(), *task)


def _row(solve, order, m, Q, damping, digits, system, modulation, S):
    """``(order, m, *texts)``: the edge of ``order`` at ``m`` solved by ``solve`` and printed."""
    b = solve(
        order,
        m,
        Q=Q,
        damping=damping,
        digits=digits,
        system=system,
        modulation=modulation,
        switch_time=S,
    )
    return (order, m, *b.printed())


#: the solver of a certified row (:func:`verify.modulation.boundary`), imported on first use
_solver = None


def _load_solver():
    global _solver
    from verify.modulation import boundary

    _solver = boundary
    return boundary


def _tol_rows(orders, ms, Q, damping, tol, label, quiet=False):
    from verify.auto import boundaries_tol

    def prog(items):
        return progress(items, total=len(items), label=label, quiet=quiet)

    out = []
    for b in boundaries_tol(orders, ms, Q=Q, damping=damping, tol=tol, progress=prog):
        out.append((b.order, b.m, *b.printed(), b.method))
    return out


def rows(
    orders,
    ms,
    Q,
    damping,
    digits,
    jobs=1,
    label="table",
    tol=None,
    system=None,
    modulation="square",
    switch_time=None,
    scheduler=None,
    quiet=False,
):
    """Table rows ``(order, m, lower, upper[, delta_lower, delta_upper, error_bound[, method]])``
    as text (``method`` with a tolerance ``tol``), for ``system`` (default: the paper's
    pendulum); a modulation other than ``square`` (:mod:`verify.modulation`) is certified
    only.  Certified rows run on :mod:`verify.engine`: ``jobs`` local worker processes, or the
    dask cluster ``scheduler`` (an address or a ``distributed.Client``); ``quiet``: no progress
    bar."""
    from analytic.system import PAPER

    system = PAPER if system is None else system
    if modulation != "square" and (digits is None or tol is not None):
        raise InputError(
            f"a table with the {modulation} modulation is certified only: give --digits D "
            "(not --tol)"
        )
    if tol is not None and not system.is_paper:
        raise InputError(
            f"--tol chooses among methods built for the paper's system; use --digits for "
            f"{system.label}"
        )
    if tol is not None:
        return _tol_rows(orders, ms, Q, damping, tol, label, quiet)
    if digits is None:
        import mpmath

        from verify.grid import boundary_grid

        def fmt(v):
            if not np.isfinite(v):
                return None
            return mpmath.nstr(mpmath.mpf(float(v)), GRID_DIGITS, strip_zeros=False)

        grid = boundary_grid(orders, list(ms), Q=Q, damping=damping, system=system)
        out = []
        for i, n in enumerate(orders):
            for j, m in enumerate(ms):
                out.append((n, m, fmt(grid[i, 0, j]), fmt(grid[i, 1, j])))
        return out
    if scheduler is None and jobs <= 1:  # in this process, one after the other (no engine)
        solve = _solver or _load_solver()
        pairs = [(n, m) for n in orders for m in ms]
        out = []
        add = out.append
        for n, m in progress(pairs, total=len(pairs), label=label, quiet=quiet):
            # :func:`_row`'s two steps, written out here (one call fewer per row)
            b = solve(
                n,
                m,
                Q=Q,
                damping=damping,
                digits=digits,
                system=system,
                modulation=modulation,
                switch_time=switch_time,
            )
            add((n, m, *b.printed()))
        return out
    from verify.atlas import edge_seconds
    from verify.engine import cluster, ordered

    tasks = [
        (n, m, Q, damping, digits, system, modulation, switch_time) for n in orders for m in ms
    ]
    # the engine of the atlas: a local dask cluster of ``jobs`` processes (or ``scheduler``);
    # work too small to pay for starting one runs here
    work = len(tasks) * edge_seconds(digits, Q is not None)
    with cluster(scheduler, jobs if jobs > 1 else 1, work_seconds=work, small_here=True) as client:
        if client is None:  # here, one after the other
            return [
                _certified(t) for t in progress(tasks, total=len(tasks), label=label, quiet=quiet)
            ]
        return ordered(
            client,
            _certified,
            tasks,
            progress=lambda it: progress(it, total=len(tasks), label=label, quiet=quiet),
        )


def run(args) -> int:
    orders = as_orders(args.orders)
    ms = as_range(args.m, name="m", max_points=100_000)
    Q = as_quality(args.Q)
    damping = as_damping(args.damping)
    digits = None if args.digits is None else as_digits(args.digits)
    if args.tol is not None and digits is not None:
        raise InputError("--tol and --digits exclude each other (the tolerance sets the digits)")
    tol = None if args.tol is None else as_tolerance(args.tol)
    try:
        jobs = int(args.jobs)
    except ValueError:
        raise InputError(f"--jobs {args.jobs!r} is not an integer; allowed range 1 to 64") from None
    if not 1 <= jobs <= 64:
        raise InputError(f"--jobs {jobs} is outside the allowed range 1 to 64")
    if args.output is not None:  # refuse an unwritable file before the work
        from reports.output import check_writable

        check_writable(args.output, "--output")
        if args.format == "csv":
            check_writable(sidecar(args.output), "--output's metadata file")
    if len(orders) * len(ms) > 2_000_000:
        raise InputError(f"{len(orders) * len(ms)} table entries; at most 2000000 allowed")
    Qtext = None if Q is None else decimal_text(Fraction(Q))
    sysv = system_of(args)
    if not sysv.uses_depth:
        raise InputError("a custom system has no depth: a table over m makes no sense for it")
    kind, S = as_modulation(args.modulation, args.switch_time, sysv)
    data = rows(
        orders,
        ms,
        Q,
        damping,
        digits,
        jobs,
        tol=tol,
        system=sysv,
        modulation=kind,
        switch_time=S,
        quiet=args.quiet,
    )
    certified = digits is not None or tol is not None
    header = ["order", "m", "lower", "upper"]
    # error_bound: |printed - exact| for each number of the row, the rounding of the print included
    header += ["delta_lower", "delta_upper", "error_bound"] if certified else []
    header += ["method"] if tol is not None else []
    # what the columns are and how they were computed: in the JSON, or beside a CSV file
    about = {
        "orders": orders,
        "Q": Qtext,
        "damping": damping if Q is not None else "none",
        "digits": digits if digits is not None else (None if tol is not None else GRID_DIGITS),
        "method": "auto" if tol is not None else ("certified" if certified else "grid"),
        "columns": header,
        # what a missing number means (an empty CSV field, null in JSON)
        "empty": "no interval of that order at that depth",
    }
    inputs: dict = {}
    if kind != "square":
        inputs["modulation"] = kind
        if S is not None:
            inputs["switch_time"] = decimal_text(S)
    if tol is not None:
        inputs["tolerance"] = args.tol.strip()
    if args.format == "json":
        doc = {
            **sysv.as_json(),
            **about,
            "rows": [[r[0], decimal_text(r[1])] + list(r[2:]) for r in data],
            **inputs,
        }
        text = json.dumps(doc, indent=2) + "\n"
    else:
        text = csv_text(header, data)
    if args.output:
        # the file holds exactly what standard output would show; a CSV's metadata (what the
        # columns mean, the inputs) goes to a JSON file beside it
        if args.format == "csv":
            meta = {
                "generated_by": BANNER.format(what="table"),
                "file": os.path.basename(args.output),
                **about,
                **inputs,
            }
            atomic_write(sidecar(args.output), json.dumps(meta, indent=2) + "\n")
        atomic_write(args.output, text)
    else:
        print(text, end="")
    return 0


def csv_text(header, data) -> str:
    """The CSV text of a table: the ``header`` line, then a line per row of :func:`rows` (the
    depth as :func:`decimal_text`, ``None`` as an empty field), as :mod:`csv`'s writer writes
    them (lines ending in ``\\n``).  The fields are joined as they are; if any field holds what
    the writer would quote (a comma, a quote or a line break: none of the numbers do), the lines
    are written by the writer itself."""
    lines = [",".join(header)]
    add = lines.append
    # the fields that could need quotes (the header's and the rows' texts; not the orders and the
    # depths, which are numbers), to be searched at once
    fields = list(header)
    more = fields.extend
    # the text of each depth, once a table (the orders repeat them), by the depth itself (data
    # holds every depth while this runs: no two at one id)
    depths: dict = {}
    for r in data:
        key = id(r[1])
        mt = depths.get(key)
        if mt is None:
            mt = depths[key] = decimal_text(r[1])
        texts = r[2:]
        try:
            add(f"{r[0]},{mt}," + ",".join(texts))
        except TypeError:  # a missing number (None) or a field that is not text
            texts = ["" if v is None else str(v) for v in texts]
            add(f"{r[0]},{mt}," + ",".join(texts))
        more(texts)
    add("")
    # one search per character over the fields alone (a search for one character is much
    # cheaper than a count of it over the whole text, commas and line ends included)
    probe = "".join(fields)
    if not ("," in probe or "\n" in probe or '"' in probe or "\r" in probe):
        return "\n".join(lines)
    buf = io.StringIO()  # a field to quote: the writer's own lines
    w = csv.writer(buf, lineterminator="\n")
    w.writerow(header)
    for r in data:
        w.writerow([r[0], decimal_text(r[1])] + ["" if v is None else v for v in r[2:]])
    return buf.getvalue()


def sidecar(path) -> str:
    """The metadata file written beside a CSV table: ``FILE.meta.json``."""
    return f"{path}.meta.json"
