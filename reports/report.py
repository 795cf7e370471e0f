"""The derivation report: every section built from the engine's objects, assembled into one LaTeX
document with its figures, written atomically and compiled when a TeX engine is installed.

>>> from reports.report import build_report
>>> result = build_report("report")            # doctest: +SKIP
>>> result.pdf, result.pages                   # doctest: +SKIP
(PosixPath('report/paramres-report.pdf'), 31)

The expensive parts of each section (symbolic derivations, certified tables, boundary grids) go
through a :class:`~analytic.cache.Cache` keyed by the source of the engine, so a second build with
unchanged code only assembles and compiles.  A cold build runs the catalogue, the stitching
section and the expansions in a second process (:data:`~reports.sections.SECOND_PROCESS`) while
this one builds the other sections, the longest first
(:data:`~reports.sections.LONGEST_FIRST`); the second process takes the next of those when its
own are done.  Each section is computed the same way in either process, so the document does not
depend on it.
"""

from __future__ import annotations

import gc
import os
import sys
import time
from collections.abc import Callable
from contextlib import contextmanager
from dataclasses import dataclass

from analytic.cache import Cache, cache_dir_override

from . import frontmatter
from .bibliography import bibliography
from .build import BuildResult, find_engine, supports, write_output
from .frontmatter import provenance
from .i18n import language
from .latex import DEFAULT, Config, Latex, document, section
from .output import BANNER
from .sections import (
    AFTER_SECOND,
    LONGEST_FIRST,
    SECOND_PROCESS,
    SECTIONS,
    Context,
    Part,
    load,
)

__all__ = [
    "TEX_NAME",
    "FIGURE_DIR",
    "Assembled",
    "assemble",
    "build_report",
    "collector_paused",
    "tex_name",
]

TEX_NAME = "paramres-report.tex"
FIGURE_DIR = "figures"

#: packages loaded before all others for a language: font encoding, input encoding, hyphenation
LANGUAGE_PACKAGES = {
    "en": (),
    "ru": (("fontenc", "T2A"), ("inputenc", "utf8"), ("babel", "russian")),
}


def tex_name(lang: str = "en") -> str:
    """The name of the report's source for ``lang``: ``paramres-report.tex``,
    ``paramres-report-ru.tex``."""
    return TEX_NAME if lang == "en" else TEX_NAME.replace(".tex", f"-{lang}.tex")


@dataclass(frozen=True)
class Assembled:
    """The report's source and files: ``files`` maps names relative to the output directory to
    contents (the ``.tex`` source and the figures); ``timings`` the seconds each section took."""

    tex: str
    files: dict[str, str | bytes]
    timings: tuple[tuple[str, float], ...]


def assemble(
    ctx: Context | None = None,
    sections: tuple[str, ...] = SECTIONS,
    *,
    lang: str = "en",
    command: str | None = None,
    jobs: int = 1,
) -> Assembled:
    """Build every section and the document around them (no files written), in ``lang``;
    ``command`` is the command line that produced the report, printed under the title.
    ``jobs=2`` builds the sections of :data:`~reports.sections.SECOND_PROCESS` in a second
    process while this one builds the others (when they are not all in the cache), and that
    process then shares the others' work; the document is the same either way."""
    ctx = ctx or Context()
    with language(lang):
        return _assemble(ctx, sections, lang, command, jobs)


def _key(name: str, lang: str) -> str:
    return f"section-{name}" if lang == "en" else f"section-{name}-{lang}"


def _build(ctx: Context, name: str, lang: str) -> Part:
    """Section ``name``, through the cache unless it is cheap."""
    module = load(name)
    if getattr(module, "CACHED", True):
        return ctx.cache.get(_key(name, lang), lambda: module.build(ctx))
    return module.build(ctx)


def _second_names(ctx: Context, sections: tuple[str, ...], lang: str, jobs: int) -> tuple:
    """The sections to build in a second process: none for ``jobs=1``, when they would be all
    there is to build, or when they and the sections waiting for them are all in the cache."""
    names = tuple(n for n in SECOND_PROCESS if n in sections) if jobs > 1 else ()
    if not names or len(names) == len(sections):
        return ()
    waiting = names + tuple(n for n in AFTER_SECOND if n in sections)
    if ctx.cache.enabled and all(ctx.cache.path(_key(n, lang)).exists() for n in waiting):
        return ()
    return names


def _claim(counter, count: int) -> int | None:
    """The index of the next section of the shared list for the caller (the counter is shared by
    both processes), or ``None`` when all ``count`` are taken."""
    with counter.get_lock():
        k = counter.value
        if k >= count:
            return None
        counter.value = k + 1
    return k


def _picklable(value) -> bool:
    """Whether ``value`` can go through the pipe (a result the first process cannot receive it
    computes again)."""
    import pickle

    try:
        pickle.dumps(value)
    except Exception:
        return False
    return True


def _second_process(
    conn, counter, config: Config, directory, packages, names, queue, lang, prepare=()
):
    """The second process: build ``names``, compute what the sections ``prepare`` (built by the
    first process once this one is done) share with them (their ``prepare(ctx)``), then build
    the sections of ``queue`` the first process has not taken yet, and send back ``("ok", parts,
    shares, messages)``, or ``("error", exception)``."""
    try:
        gc.disable()  # as in the first process (see :func:`collector_paused`); this one ends
        messages: list[str] = []
        ctx = Context(config=config, cache=Cache(directory, packages), log=messages.append)
        parts = {}
        with language(lang):

            def build(name: str) -> None:
                start = time.perf_counter()
                parts[name] = (_build(ctx, name, lang), time.perf_counter() - start)

            for name in names:
                build(name)
            for name in prepare:
                load(name).prepare(ctx)
            while (k := _claim(counter, len(queue))) is not None:
                build(queue[k])
        shares = {k: v for k, v in ctx.memo.items() if _picklable(v)}  # shared with others
        conn.send(("ok", parts, shares, messages))
    except BaseException as exc:  # handed to the first process, which raises it
        try:
            conn.send(("error", exc))
        except Exception:
            conn.send(("error", RuntimeError(f"{type(exc).__name__}: {exc}")))
    finally:
        conn.close()


@contextmanager
def collector_paused():
    """Python's cyclic garbage collector off for the block, on again after it if it was on.

    A build makes few reference cycles (matplotlib's figures; sympy's expressions and the
    numbers are freed by their reference counts), while the collector's full collections walk
    every object alive -- the libraries, sympy's caches -- again and again: 0.5 to 1 s of CPU
    time per process of a cold build, for 30 to 60 MB of memory held until the block ends
    (measured: a process of a cold build peaks at 200-230 MB instead of 165-185 MB)."""
    collecting = gc.isenabled()
    gc.disable()
    try:
        yield
    finally:
        if collecting:
            gc.enable()


def _start_method() -> str:
    """How the second process starts: a fork of this one where the system has it and this process
    runs no other thread (the child then finds the libraries imported, about 2 s of CPU time
    saved), else a fresh interpreter."""
    import multiprocessing
    import threading

    if "fork" in multiprocessing.get_all_start_methods() and threading.active_count() == 1:
        return "fork"
    return "spawn"


def _preload(names) -> None:
    """Import before the fork what both processes need, so that it is imported once: the modules
    of the second process's own sections ``names``, the numeric namespaces of sympy's
    ``lambdify`` and the units package ``sympy.simplify`` imports on its first call.  Not
    matplotlib (about 1 s): the second process's own sections draw no figures, so it starts on
    them while the first imports matplotlib with its first section (the second imports it too if
    it takes a section with figures from the shared list later)."""
    import sympy

    for name in names:
        load(name)
    for module in ("numpy", "mpmath"):
        sympy.lambdify((), 0, modules=module)
    import sympy.physics.units  # noqa: F401


class _Second:
    """The second process, the counter of the shared list of sections and the pipe its results
    come back through."""

    def __init__(
        self,
        ctx: Context,
        names: tuple[str, ...],
        queue: tuple[str, ...],
        lang: str,
        prepare: tuple[str, ...] = (),
    ):
        import multiprocessing

        from analytic.cache import cache_dir

        # one key per cache directory, made before two processes write entries into it
        ctx.cache.ensure_key()
        base = cache_dir()
        if base is not None:
            Cache(base / "analytic").ensure_key()
        method = _start_method()
        if method == "fork":
            _preload(names)
        mp = multiprocessing.get_context(method)
        self.queue = queue
        self.counter = mp.Value("i", 0)
        self.conn, child = mp.Pipe(duplex=False)
        self.process = mp.Process(
            target=_second_process,
            args=(
                child,
                self.counter,
                ctx.config,
                ctx.cache.directory,
                ctx.cache.packages,
                names,
                queue,
                lang,
                prepare,
            ),
            daemon=True,
        )
        self.process.start()
        child.close()

    def claim(self) -> str | None:
        """The next section of the shared list for this process, ``None`` when none is left."""
        k = _claim(self.counter, len(self.queue))
        return None if k is None else self.queue[k]

    def result(self):
        try:
            reply = self.conn.recv()
        except EOFError:
            raise RuntimeError("the report's second process ended without a result") from None
        finally:
            self.process.join()
        if reply[0] == "error":
            raise reply[1]
        return reply[1:]

    def stop(self) -> None:
        if self.process.is_alive():
            self.process.terminate()
        self.process.join()
        self.conn.close()


def _assemble(ctx: Context, sections, lang: str, command: str | None, jobs: int) -> Assembled:
    total = len(sections)
    number = {name: k for k, name in enumerate(sections, start=1)}
    parts: dict[str, Part] = {}
    seconds: dict[str, float] = {}

    def title(name: str) -> str:
        return f"report: [{number[name]}/{total}] {load(name).TITLE}"

    def build(name: str) -> None:
        ctx.log(f"{title(name)} ...")
        start = time.perf_counter()
        parts[name] = _build(ctx, name, lang)
        seconds[name] = time.perf_counter() - start
        ctx.log(f"{title(name)}: {seconds[name]:.1f} s")

    second_names = _second_names(ctx, sections, lang, jobs)
    mine = [n for n in sections if n not in second_names]
    later = [n for n in mine if second_names and n in AFTER_SECOND]
    second = None
    try:
        if second_names:
            # the rest is shared: each process takes the next section when it is free
            rest = [n for n in mine if n not in later]
            queue = tuple(n for n in LONGEST_FIRST if n in rest) + tuple(
                n for n in rest if n not in LONGEST_FIRST
            )
            # what the sections waiting for the second process share with it, computed there
            # (where the sections they share it with were built) before the shared list
            prepare = tuple(n for n in later if hasattr(load(n), "prepare"))
            second = _Second(ctx, second_names, queue, lang, prepare)
            for name in second_names:
                ctx.log(f"{title(name)} ... (in a second process)")
            while (name := second.claim()) is not None:
                build(name)
        else:
            for name in mine:
                build(name)
        if second is not None:
            done, shares, messages = second.result()
            for msg in messages:
                ctx.log(msg)
            for name in sections:
                if name in done:
                    parts[name], seconds[name] = done[name]
                    ctx.log(f"{title(name)}: {seconds[name]:.1f} s (second process)")
            for k, v in shares.items():
                ctx.memo.setdefault(k, v)
        for name in later:
            build(name)
    finally:
        if second is not None:
            second.stop()
    body: list[Latex] = []
    files: dict[str, str | bytes] = {}
    for name in sections:
        module = load(name)
        if getattr(module, "NEW_PAGE", False):  # the floats of the sections before end here
            body.append(Latex(r"\clearpage"))
        body.append(section(module.TITLE, module.LABEL))
        body.append(parts[name].body)
        for fname, data in parts[name].figures:
            path = f"{FIGURE_DIR}/{fname}"
            if path in files:
                raise ValueError(f"two sections draw {path}")
            files[path] = data
    timings = tuple((name, seconds[name]) for name in sections)
    prov = provenance(command)
    abstract = None
    if "summary" in sections:
        from .sections.summary import findings

        abstract = frontmatter.abstract(findings(ctx), ctx.config)
    name = tex_name(lang)
    tex = document(
        body,
        title=frontmatter.title(),
        author=frontmatter.author(prov),
        date=Latex(
            frontmatter.date(prov).raw + r"\\[1ex]\small " + frontmatter.provenance_block(prov).raw
        ),
        banner=BANNER.format(what="report"),
        abstract=abstract,
        config=ctx.config,
        packages=LANGUAGE_PACKAGES[lang],
        # the front matter is numbered i, ii, ... and the body from 1, so that the body's pages
        # do not depend on the length of the contents (two pdflatex passes settle the document)
        preamble=(frontmatter.pdf_metadata(prov), r"\pagenumbering{roman}"),
        contents=(
            Latex(r"\tableofcontents"),
            Latex(r"\listoffigures"),
            Latex(r"\listoftables"),
            Latex(r"\clearpage"),
            Latex(r"\pagenumbering{arabic}"),
        ),
        # the figures still floating end before the references, not between them
        back=(Latex(r"\clearpage"), bibliography()),
    ).raw
    files[name] = tex
    return Assembled(tex, files, tuple(timings))


def build_report(
    out_dir: str | os.PathLike = "report",
    *,
    cache_dir: str | os.PathLike | None = None,
    compile: bool | None = None,
    config: Config = DEFAULT,
    log: Callable[[str], None] | None = None,
    sections: tuple[str, ...] = SECTIONS,
    lang: str = "en",
    command: str | None = None,
    jobs: int = 2,
) -> BuildResult:
    """Assemble the report and write it to ``out_dir`` (source, figures and, if a TeX engine is
    found or ``compile=True``, the PDF), in ``lang`` (``"en"`` or ``"ru"``; the Russian report is
    ``paramres-report-ru.tex``/``.pdf``, compiled only where TeX has Cyrillic fonts); ``command``
    is printed under the title.  ``compile=None`` compiles when an engine is installed;
    ``compile=True`` fails if none is.  ``cache_dir`` is the cache directory of the engine and the
    report (see :mod:`analytic.cache`); ``None`` computes everything afresh (a cold build).
    ``jobs``: processes for a cold build (1 or 2, see :func:`assemble`)."""
    log = log or (lambda msg: print(msg, file=sys.stderr, flush=True))
    engine = find_engine() if compile is not False else None
    if engine is not None and not supports(lang):
        log(f"report: the installed TeX cannot typeset language {lang!r}; writing the source only")
        engine = None
    if compile is True and engine is None:
        raise RuntimeError(f"no TeX engine (latexmk or pdflatex) for language {lang!r} found")
    with cache_dir_override(cache_dir) as base:
        report_cache = None if base is None else base / "report"
        ctx = Context(
            config=config,
            cache=Cache(report_cache, ("analytic", "verify", "reports", "paramres")),
            log=log,
        )
        with collector_paused():
            assembled = assemble(ctx, sections, lang=lang, command=command, jobs=jobs)
    if engine is not None:
        log(f"report: compiling with {engine.name} ...")
    start = time.perf_counter()
    result = write_output(out_dir, tex_name(lang), assembled.files, engine=engine)
    if engine is not None:
        log(f"report: compiled in {time.perf_counter() - start:.1f} s, {result.pages} pages")
    return result
