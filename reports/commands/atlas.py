"""``paramres atlas``: certified edges, the growth-rate map and thresholds over a grid, as an
xarray dataset in netCDF or Zarr, computed on dask.

    paramres atlas --orders 1-6 --m 0.01:0.99:0.01 [--Q none,3,7] [--damping exact|paper]
                   [--system pendulum,torsion] [--duty 1/2,1/3] [--digits 30]
                   [--T START:STOP:STEP] [--no-thresholds] --output FILE.nc|FILE.zarr
                   [--scheduler ADDRESS | --workers N] [--chunk C]

Every axis takes a list (``--Q``, ``--system``, ``--duty``: comma-separated) or a range
(``--m``, ``--T``: exact decimal ``START:STOP:STEP``, as for ``table``).  The work runs on a local
dask cluster sized to the machine, or on the cluster at ``--scheduler``.  A ``.zarr`` store is
written chunk by chunk and resumed if interrupted; a ``.nc`` file appears whole at the end.  See
:mod:`verify.atlas`.
"""

from __future__ import annotations

import argparse
import shlex

from reports.output import check_writable, progress
from verify.inputs import InputError

__all__ = ["register", "run"]


def register(subparsers) -> None:
    p = subparsers.add_parser(
        "atlas",
        help="certified edges, growth map and thresholds over a grid, as netCDF or Zarr (dask)",
        description=(
            "An atlas over a grid of orders, depths m, quality factors Q, duties and systems: the "
            "certified edges of every interval with their proven enclosures, the growth rate "
            "log max|mu| over (T, m) when --T is given, and the threshold depths where Q is "
            "finite (every system and duty). Written as an xarray dataset to FILE.nc (netCDF-4) or "
            "FILE.zarr (Zarr, written chunk by chunk and resumed when run again), with units, "
            "long names and provenance. Computed on a local dask cluster, or on --scheduler."
        ),
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    p.add_argument("--orders", required=True, metavar="LIST", help="orders, e.g. 1-6 or 1,3,5")
    p.add_argument(
        "--m", required=True, metavar="START:STOP:STEP", help="depths, e.g. 0.01:0.99:0.01"
    )
    p.add_argument(
        "--Q",
        default="none",
        metavar="LIST",
        help="quality factors, comma-separated, 'none' for no friction (default none)",
    )
    p.add_argument(
        "--damping",
        default="exact",
        metavar="MODEL",
        help="friction model: exact (default) or paper (eqs. 28-30)",
    )
    p.add_argument(
        "--system",
        default="pendulum",
        metavar="LIST",
        help="systems, comma-separated: pendulum (default), torsion, meissner",
    )
    p.add_argument(
        "--duty", default="1/2", metavar="LIST", help="duties 0 < D < 1, comma-separated"
    )
    p.add_argument("--digits", default="30", metavar="D", help="proven digits per edge (30)")
    p.add_argument(
        "--T",
        default=None,
        metavar="START:STOP:STEP",
        help="periods T/T0 of the growth-rate map (no map without it)",
    )
    p.add_argument(
        "--no-thresholds",
        action="store_true",
        help="skip the threshold proofs (made where Q is finite, for every system and duty)",
    )
    p.add_argument(
        "--output", required=True, metavar="FILE", help="FILE.nc (netCDF) or FILE.zarr (Zarr)"
    )
    p.add_argument(
        "--scheduler",
        default=None,
        metavar="ADDRESS",
        help="address of a running dask.distributed scheduler (default: a local cluster)",
    )
    p.add_argument(
        "--workers",
        default=None,
        metavar="N",
        help="local worker processes, 1 to 64 (default: one per core)",
    )
    p.add_argument(
        "--chunk", default=None, metavar="C", help="depths per certified-edge task (default 16)"
    )
    p.set_defaults(func=run)


def _int(text, name, low, high):
    if text is None:
        return None
    try:
        v = int(str(text).strip())
    except ValueError:
        raise InputError(
            f"--{name} {text!r} is not an integer; allowed range {low} to {high}"
        ) from None
    if not low <= v <= high:
        raise InputError(f"--{name} {v} is outside the allowed range {low} to {high}")
    return v


def run(args) -> int:
    from verify.atlas import EDGE_CHUNK, atlas, check_size, request, store_kind
    from verify.engine import MAX_WORKERS

    workers = _int(args.workers, "workers", 1, MAX_WORKERS)
    chunk = _int(args.chunk, "chunk", 1, 100_000) or EDGE_CHUNK
    if args.scheduler is not None and workers is not None:
        raise InputError("--scheduler and --workers exclude each other (the cluster has its own)")
    kind = store_kind(args.output)
    grid = {
        "Q": args.Q,
        "duty": args.duty,
        "system": args.system,
        "damping": args.damping,
        "digits": args.digits,
        "T": args.T,
        "thresholds": not args.no_thresholds,
        "edge_chunk": chunk,
    }
    req = request(args.orders, args.m, **grid)
    est = check_size(req, kind)  # before any work, and before touching the output
    check_writable(args.output, "--output", directory=kind == "zarr")

    def bar(items, total):
        return progress(items, total=total, label="atlas")

    ds = atlas(
        args.orders,
        args.m,
        **grid,
        output=args.output,
        scheduler=args.scheduler,
        workers=workers,
        progress=bar,
        command=_command(args),
    )
    sizes = ", ".join(f"{k} {v}" for k, v in ds.sizes.items() if not k.endswith("_chunk"))
    print(f"atlas written to {args.output} ({'Zarr' if kind == 'zarr' else 'netCDF-4'})")
    print(f"  dimensions: {sizes}")
    print(f"  {est.text()} (estimated before the run)")
    print(f"  variables: {', '.join(sorted(v for v in ds.data_vars if not v.endswith('_done')))}")
    return 0


def _command(args) -> str:
    """The command line, as the options were given (for the provenance attribute)."""
    words = ["paramres", "atlas"]
    for flag in ("orders", "m", "Q", "damping", "system", "duty", "digits", "T", "output"):
        value = getattr(args, flag)
        if value is not None:
            words += [f"--{flag}", str(value)]
    if args.no_thresholds:
        words.append("--no-thresholds")
    for flag in ("scheduler", "workers", "chunk"):
        if getattr(args, flag) is not None:
            words += [f"--{flag}", str(getattr(args, flag))]
    return shlex.join(words)
