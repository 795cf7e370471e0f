"""``paramres report``: the derivation report (LaTeX, figures, and the PDF when TeX is
installed)."""

from __future__ import annotations

import shlex
import sys
import time
from pathlib import Path, PurePath

from ..output import dump_json

__all__ = ["register", "run"]


def register(subparsers) -> None:
    p = subparsers.add_parser(
        "report",
        help="write the derivation report (LaTeX, figures, PDF)",
        description=(
            "Build the derivation report: the model, the stitching systems and their reductions, "
            "the paper's numbered results printed against derived, series, closings, the paper's "
            "Figs. 2 and 8 redrawn, accuracy, speed and the time domain. Writes "
            "DIR/paramres-report.tex and DIR/figures/, and DIR/paramres-report.pdf (with its LaTeX "
            "log) when latexmk or pdflatex is installed. Nothing in DIR changes unless the whole "
            "build succeeds."
        ),
    )
    p.add_argument(
        "--out", metavar="DIR", default="report", help="output directory (default: report/)"
    )
    p.add_argument(
        "--no-pdf",
        action="store_true",
        help="write the LaTeX source and figures only, do not compile",
    )
    p.add_argument(
        "--cache",
        metavar="DIR",
        default=None,
        help="cache directory for the symbolic and numeric work (default: $PARAMRES_CACHE_DIR or "
        "~/.cache/paramres)",
    )
    p.add_argument(
        "--no-cache", action="store_true", help="recompute everything, read and write no cache"
    )
    p.add_argument(
        "--lang",
        choices=("en", "ru"),
        default="en",
        help="language of the report: en (default) or ru (paramres-report-ru.pdf, in Russian)",
    )
    p.add_argument(
        "--jobs",
        type=int,
        choices=(1, 2),
        default=2,
        help="processes for a cold build: 2 (default) builds the catalogue, the stitching "
        "section and the expansions in a second process, 1 builds everything in this one; the "
        "report is the same",
    )
    p.add_argument("--json", action="store_true", help="print what was written as JSON on stdout")
    p.add_argument("-q", "--quiet", action="store_true", help="no progress messages on stderr")
    p.set_defaults(func=run)


def run(args) -> int:
    import gc

    # no cyclic garbage collection during the imports and the build either (they make few
    # cycles; see reports.report.collector_paused)
    collecting = gc.isenabled()
    gc.disable()
    try:
        return _run(args)
    finally:
        if collecting:
            gc.enable()


def _run(args) -> int:
    from analytic.cache import cache_dir

    from ..build import BuildError, how_to_get_pdf
    from ..output import check_writable
    from ..report import build_report, tex_name

    out = check_writable(args.out, "--out", directory=True)  # before any work
    cache = None if args.no_cache else (Path(args.cache) if args.cache else cache_dir())
    if cache is not None and cache.exists() and not cache.is_dir():
        from verify.inputs import InputError

        raise InputError(f"--cache {cache} exists and is not a directory")
    log = (
        (lambda msg: None) if args.quiet else (lambda msg: print(msg, file=sys.stderr, flush=True))
    )
    start = time.perf_counter()
    try:
        result = build_report(
            out,
            cache_dir=cache,
            compile=False if args.no_pdf else None,
            log=log,
            lang=args.lang,
            command=_command_line(args),
            jobs=args.jobs,
        )
    except BuildError as exc:
        print(f"paramres: LaTeX failed, {out} left as it was:\n{exc}", file=sys.stderr)
        return 1
    seconds = time.perf_counter() - start
    if args.json:
        dump_json(
            {
                "directory": str(result.directory),
                "files": list(result.files),
                "pdf": str(result.pdf) if result.pdf else None,
                "engine": result.engine,
                "pages": result.pages,
                "overfull_lines": result.overfull,
                "seconds": round(seconds, 2),
            }
        )
    elif result.pdf:
        print(
            f"wrote {result.pdf} ({result.pages} pages) and its source in {result.directory}/ "
            f"in {seconds:.1f} s"
        )
    else:
        print(
            f"wrote {result.directory / tex_name(args.lang)} and {len(result.files) - 1} figure "
            f"file(s) "
            f"in {seconds:.1f} s"
        )
        if not args.no_pdf:
            print(how_to_get_pdf(result.directory / tex_name(args.lang)), file=sys.stderr)
    return 0


def _command_line(args) -> str:
    """The command that produced the report, as a user would type it again (the options given,
    with their values; machine-specific cache paths are left out, and the output directory is
    named by its last component alone: where the report was written is no part of it)."""
    words = ["paramres", "report", "--out", PurePath(str(args.out)).name or "."]
    if args.lang != "en":
        words += ["--lang", args.lang]
    if args.no_pdf:
        words.append("--no-pdf")
    if args.no_cache:
        words.append("--no-cache")
    return " ".join(shlex.quote(w) for w in words)
