"""``paramres bench``: every method side by side, time per edge against error.

    paramres bench [--quick] [--json] [--plot FILE] [--output FILE]

Runs :func:`reports.benchmark.run`: the series of each order ``K``, the paper's fixed-point
iteration,
the double-precision paths, mpmath and the certified solver at 15 to 1000 digits, plain
``mpmath.findroot`` on the printed equation, and the automatic choice with a tolerance, on orders
1-6 over a grid of depths and the hard cases; each timed (median of warm runs, per edge) and
compared with a certified 60-digit reference.  Prints the table, the largest error per hard case,
and the solver's targets; ``--json`` prints everything as JSON instead, ``--output`` writes the
JSON to a file, ``--plot`` the time-against-error (Pareto) picture (.pdf, .png or .svg), both
atomically.  A progress bar goes to stderr on a terminal.
"""

from __future__ import annotations

import argparse
import json

from reports.output import BANNER, atomic_write, dump_json, progress

__all__ = ["register", "run", "render_text", "plot"]


def register(subparsers) -> None:
    p = subparsers.add_parser(
        "bench",
        help="speed against error: every method on the same scenes, with a Pareto plot",
        description=(
            "Measure every way of computing the edges -- series in m of order K = 1..8, the "
            "paper's fixed-point iteration, double precision per point and the vectorised grid, "
            "mpmath (uncertified) and the certified solver at 15, 30, 50, 100 and 1000 digits, "
            "plain mpmath.findroot on the printed equation, and the automatic choice with a "
            "tolerance -- on orders 1-6 over a grid of depths and the hard cases (tiny m, m near "
            "1, a closing, near a threshold, order 100). Time: median CPU time per edge over "
            "warm runs. Error: largest relative error of T/T0 against the certified 60-digit "
            "edges. A full run takes about a minute, --quick a few seconds."
        ),
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    p.add_argument("--quick", action="store_true", help="fewer scenes and runs (seconds)")
    p.add_argument(
        "--floors",
        action="store_true",
        help=(
            "instead: each hot path against a floor written in the benchmark, timed alternately "
            "(benchmarks/floor_*.py of a source checkout); prints the ratios against targets"
        ),
    )
    p.add_argument("--json", action="store_true", help="print all measurements as JSON")
    p.add_argument(
        "--plot", metavar="FILE", help="write the time-against-error plot (.pdf, .png or .svg)"
    )
    p.add_argument("--output", metavar="FILE", help="write the JSON to FILE (atomically)")
    p.add_argument("-q", "--quiet", action="store_true", help="no progress display on stderr")
    p.set_defaults(func=run)


def render_text(result) -> str:
    m = result.machine
    head = (
        f"paramres bench{' --quick' if result.quick else ''}: {result.date}, {m['cpu']}, "
        f"{m['cores']} cores, Python {m['python']}; {len(result.scenes)} scenes, "
        f"{result.seconds:.0f} s\n"
        "time: median CPU time per edge over warm runs (wall time beside it); error: largest "
        "relative error of T/T0 against the certified 60-digit edges\n"
    )
    return (
        head
        + "\n"
        + result.table()
        + "\n\nlargest error per hard case\n"
        + result.hard_table()
        + "\n\nsame run: ratios and targets\n"
        + result.targets_text()
        + "\n"
    )


def plot(result, path) -> None:
    """The Pareto picture of ``result`` written to ``path``."""
    from reports.output import atomic_write

    atomic_write(path, plot_bytes(result, path))


def plot_bytes(result, path) -> bytes:
    """The Pareto picture of ``result`` rendered in the format ``path``'s suffix names."""
    from pathlib import Path

    from reports.benchmark import pareto
    from reports.benchplots import pareto_figure
    from reports.figures import figure_bytes

    m = result.machine
    fig = pareto_figure(
        [
            ("all scenes", pareto(result, "all")),
            (r"depths $m \leq 0.01$", pareto(result, "small m")),
        ],
        subtitle=f"paramres bench, {result.date}, {m['cpu']} ({m['cores']} cores)",
    )
    return figure_bytes(fig, Path(path).suffix, what="bench")


def run_floors(args) -> int:
    """``paramres bench --floors``: the runner of ``benchmarks/floors.py`` (source checkout)."""
    import importlib.util
    from pathlib import Path

    from reports.output import check_writable
    from verify.inputs import InputError

    path = Path(__file__).resolve().parents[2] / "benchmarks" / "floors.py"
    if not path.is_file():
        raise InputError(
            "--floors runs benchmarks/floors.py of a source checkout, which this installation "
            "does not have"
        )
    if args.output is not None:
        check_writable(args.output, "--output")
    spec = importlib.util.spec_from_file_location("_paramres_floors", path)
    if spec is None or spec.loader is None:  # pragma: no cover - a file that is not Python
        raise InputError(f"{path.name} cannot be loaded as a Python module")
    floors = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(floors)

    def bar(items):
        return progress(items, total=len(items), label="floors")

    doc = floors.run(quick=args.quick, progress=bar)
    if args.output:
        atomic_write(args.output, json.dumps(doc, indent=2) + "\n")
    if args.json:
        dump_json(doc)
    else:
        print(floors.render(doc), end="")
    return 0


def run(args) -> int:
    from reports.output import check_writable

    if getattr(args, "floors", False):
        if args.plot is not None:
            from verify.inputs import InputError

            raise InputError("--plot draws the method comparison; it does not go with --floors")
        return run_floors(args)

    # refuse a bad file name before the work
    if args.plot is not None:
        from reports.figures import check_plot_path

        check_plot_path(args.plot)
    if args.output is not None:
        check_writable(args.output, "--output")

    from reports.benchmark import run as bench_run

    def bar(items):
        return progress(items, total=len(items), label="bench", quiet=args.quiet)

    result = bench_run(quick=args.quick, progress=bar)
    doc = result.as_json()
    # everything is rendered before anything is written
    picture = plot_bytes(result, args.plot) if args.plot else None
    if args.output:
        text = json.dumps({"generated_by": BANNER.format(what="bench"), **doc}, indent=2)
        atomic_write(args.output, text + "\n")
    if picture is not None:
        atomic_write(args.plot, picture)
    if args.json:
        dump_json(doc)
    else:
        print(render_text(result), end="")
    return 0
