"""The derivation report: every section built from the engine's objects, assembled into one LaTeX
document with its figures, written atomically and compiled when a TeX engine is installed.

>>> from reports.report import build_report
>>> result = build_report("report")            # doctest: +SKIP
>>> result.pdf, result.pages                   # doctest: +SKIP
(PosixPath('report/paramres-report.pdf'), 31)

The expensive parts of each section (symbolic derivations, certified tables, boundary grids) go
through a :class:`~analytic.cache.Cache` keyed by the source of the engine, so a second build with
unchanged code only assembles and compiles.
"""

from __future__ import annotations

import os
import sys
import time
from collections.abc import Callable
from dataclasses import dataclass

from analytic.cache import Cache, cache_dir_override

from . import frontmatter
from .bibliography import bibliography
from .build import BuildResult, find_engine, supports, write_output
from .frontmatter import provenance
from .i18n import language
from .latex import DEFAULT, Config, Latex, document, section
from .output import BANNER
from .sections import SECTIONS, Context, Part, load

__all__ = ["TEX_NAME", "FIGURE_DIR", "Assembled", "assemble", "build_report", "tex_name"]

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
) -> Assembled:
    """Build every section and the document around them (no files written), in ``lang``;
    ``command`` is the command line that produced the report, printed under the title."""
    ctx = ctx or Context()
    with language(lang):
        return _assemble(ctx, sections, lang, command)


def _assemble(ctx: Context, sections, lang: str, command: str | None) -> Assembled:
    body: list[Latex] = []
    files: dict[str, str | bytes] = {}
    timings = []
    for k, name in enumerate(sections, start=1):
        module = load(name)
        ctx.log(f"report: [{k}/{len(sections)}] {module.TITLE} ...")
        start = time.perf_counter()
        if getattr(module, "CACHED", True):
            key = f"section-{name}" if lang == "en" else f"section-{name}-{lang}"
            part: Part = ctx.cache.get(key, lambda m=module: m.build(ctx))
        else:
            part = module.build(ctx)
        seconds = time.perf_counter() - start
        timings.append((name, seconds))
        ctx.log(f"report: [{k}/{len(sections)}] {module.TITLE}: {seconds:.1f} s")
        if getattr(module, "NEW_PAGE", False):  # the floats of the sections before end here
            body.append(Latex(r"\clearpage"))
        body.append(section(module.TITLE, module.LABEL))
        body.append(part.body)
        for fname, data in part.figures:
            path = f"{FIGURE_DIR}/{fname}"
            if path in files:
                raise ValueError(f"two sections draw {path}")
            files[path] = data
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
        preamble=(frontmatter.pdf_metadata(prov),),
        contents=(
            Latex(r"\tableofcontents"),
            Latex(r"\listoffigures"),
            Latex(r"\listoftables"),
            Latex(r"\clearpage"),
        ),
        back=(bibliography(),),
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
) -> BuildResult:
    """Assemble the report and write it to ``out_dir`` (source, figures and, if a TeX engine is
    found or ``compile=True``, the PDF), in ``lang`` (``"en"`` or ``"ru"``; the Russian report is
    ``paramres-report-ru.tex``/``.pdf``, compiled only where TeX has Cyrillic fonts); ``command``
    is printed under the title.  ``compile=None`` compiles when an engine is installed;
    ``compile=True`` fails if none is.  ``cache_dir`` is the cache directory of the engine and the
    report (see :mod:`analytic.cache`); ``None`` computes everything afresh (a cold build)."""
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
        assembled = assemble(ctx, sections, lang=lang, command=command)
    if engine is not None:
        log(f"report: compiling with {engine.name} ...")
    start = time.perf_counter()
    result = write_output(out_dir, tex_name(lang), assembled.files, engine=engine)
    if engine is not None:
        log(f"report: compiled in {time.perf_counter() - start:.1f} s, {result.pages} pages")
    return result
