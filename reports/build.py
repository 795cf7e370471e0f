"""Building the report's output directory: the LaTeX source, its figures and, when a TeX engine is
installed, the compiled PDF.

Compilation happens in a private temporary directory; only when it succeeds are the source, the
figures and the PDF moved into the output directory (:func:`reports.output.atomic_directory`), so
a failed run -- a LaTeX error, an interrupted build -- leaves the previous report untouched.
Without a TeX engine the source and figures are still written, and :func:`how_to_get_pdf` says
what to install.  ``pdflatex`` is run until its auxiliary files (:data:`AUXILIARY`: labels, the
contents, the lists of figures and tables, the bookmarks) come out of a pass as they went in --
the fixed point ``latexmk`` also waits for, without its start-up and bookkeeping (about 1 s of
CPU time a build) -- and as long as the log asks for a rerun.  The report numbers its front
matter (title, contents, lists) apart from its body, so that the length of the contents does not
move the body's pages: a fresh document settles in two passes instead of three.  ``latexmk``
is used where asked for (``find_engine("latexmk")``).
"""

from __future__ import annotations

import os
import re
import shutil
import subprocess
import tempfile
from collections.abc import Mapping
from dataclasses import dataclass
from pathlib import Path

from .output import atomic_directory

__all__ = [
    "BuildError",
    "BuildResult",
    "Engine",
    "find_engine",
    "supports",
    "compile_pdf",
    "write_output",
    "how_to_get_pdf",
    "page_count",
    "APT_PACKAGES",
    "APT_PACKAGES_RU",
]

#: Debian/Ubuntu packages that compile the report (and let the tests read the PDF back)
APT_PACKAGES = (
    "latexmk",
    "texlive-latex-base",
    "texlive-latex-recommended",
    "poppler-utils",
)
#: what the Russian report needs in addition: Cyrillic fonts (T2A) and Russian hyphenation
APT_PACKAGES_RU = ("texlive-lang-cyrillic", "cm-super")

_MAX_PDFLATEX_RUNS = 5
_TIMEOUT = 600
#: the files a pdflatex pass writes and the next one reads: when none of them changes in a pass,
#: the next pass would typeset the same document
AUXILIARY = (".aux", ".toc", ".lof", ".lot", ".out")
#: what a pass writes into the ``.aux`` that no pass reads back into the typeset document: the
#: kernel's record of the number of the last page (``\@abspage@last``, for packages that ask
#: for the page count; the report uses none), which the first pass, typesetting empty contents,
#: gets wrong
_NOT_READ = re.compile(rb"^\\gdef ?\\@abspage@last\{\d+\}\r?\n", re.MULTILINE)
#: what the log says when a pass is not the last one
_RERUN = re.compile(r"Rerun to get|Label\(s\) may have changed|Rerun LaTeX")


class BuildError(RuntimeError):
    """LaTeX failed; the message carries the error lines of the log."""


@dataclass(frozen=True)
class Engine:
    """A TeX engine found on ``PATH``: ``name`` is ``"latexmk"`` or ``"pdflatex"``."""

    name: str
    path: str


@dataclass(frozen=True)
class BuildResult:
    """What a build wrote: the output directory, the file names (relative), the PDF if compiled,
    the engine used (or ``None``), the PDF's page count (0 without a PDF) and the number of
    overfull lines LaTeX reported (text sticking out into the margin)."""

    directory: Path
    files: tuple[str, ...]
    pdf: Path | None
    engine: str | None
    pages: int
    overfull: int = 0


def find_engine(prefer: str | None = None) -> Engine | None:
    """The TeX engine to use: ``pdflatex``, rerun by :func:`compile_pdf` until the document is
    settled; ``prefer="latexmk"`` asks for ``latexmk`` (with ``pdflatex`` under it) instead.
    ``None`` when none is found."""
    names = ("pdflatex",) if prefer is None else (prefer,)
    if shutil.which("pdflatex") is None:
        return None
    for name in names:
        path = shutil.which(name)
        if path:
            return Engine(name, path)
    return None


#: TeX files each language needs beyond the base installation
LANGUAGE_FILES = {"en": (), "ru": ("t2aenc.def", "russianb.ldf")}


def supports(lang: str) -> bool:
    """Whether the installed TeX can typeset ``lang`` (for Russian: the T2A font encoding and
    babel's Russian), asked of ``kpsewhich``."""
    files = LANGUAGE_FILES.get(lang, ())
    if not files:
        return True
    kpsewhich = shutil.which("kpsewhich")
    if kpsewhich is None:
        return False
    proc = subprocess.run([kpsewhich, *files], capture_output=True, text=True, check=False)
    return len([x for x in proc.stdout.splitlines() if x.strip()]) == len(files)


def how_to_get_pdf(tex: Path) -> str:
    """The advice printed when no TeX engine is installed."""
    return (
        f"no TeX engine (latexmk or pdflatex) found: wrote {tex} and its figures but not the PDF.\n"
        "To get the PDF, install TeX, e.g. on Debian/Ubuntu\n"
        f"    sudo apt-get install -y --no-install-recommends {' '.join(APT_PACKAGES)}\n"
        f"(and for `--lang ru` also {' '.join(APT_PACKAGES_RU)}),\n"
        f"then run `paramres report` again, or compile by hand:\n"
        f"    cd {tex.parent} && latexmk -pdf {tex.name}"
    )


def _log_errors(log: str, limit: int = 30) -> str:
    """The error lines of a LaTeX log (``! ...`` or ``file:line: ...``) with a little context."""
    lines = log.splitlines()
    keep: list[str] = []
    for k, line in enumerate(lines):
        if line.startswith("!") or re.match(r"^[^:\s]+\.tex:\d+:", line):
            keep.extend(lines[k : k + 3])
        if len(keep) >= limit:
            break
    return "\n".join(keep[:limit]) or "\n".join(lines[-limit:])


def _run(cmd: list[str], cwd: Path) -> subprocess.CompletedProcess:
    env = dict(os.environ)
    env.setdefault("max_print_line", "1000")
    return subprocess.run(
        cmd,
        cwd=cwd,
        env=env,
        stdout=subprocess.PIPE,
        stderr=subprocess.STDOUT,
        timeout=_TIMEOUT,
        check=False,
    )


def _auxiliary(work: Path, stem: str) -> dict[str, bytes]:
    """The contents of the auxiliary files of ``stem`` in ``work`` (:data:`AUXILIARY`), without
    what no pass reads back (:data:`_NOT_READ`)."""
    out = {}
    for suffix in AUXILIARY:
        path = work / f"{stem}{suffix}"
        if path.exists():
            data = path.read_bytes()
            out[suffix] = _NOT_READ.sub(b"", data) if suffix == ".aux" else data
    return out


def compile_pdf(
    tex_name: str, files: Mapping[str, str | bytes], engine: Engine
) -> tuple[bytes, str]:
    """Compile ``files[tex_name]`` together with the other ``files`` (figures) in a temporary
    directory and return the PDF's bytes and the last LaTeX log; :class:`BuildError` with the
    log's errors on failure."""
    stem = Path(tex_name).stem
    with tempfile.TemporaryDirectory(prefix="paramres-tex-") as tmp:
        work = Path(tmp)
        for name, data in files.items():
            dest = work / name
            dest.parent.mkdir(parents=True, exist_ok=True)
            if isinstance(data, bytes):
                dest.write_bytes(data)
            else:
                dest.write_text(data, encoding="utf-8")
        flags = ["-interaction=nonstopmode", "-halt-on-error", "-file-line-error"]
        if engine.name == "latexmk":
            cmds = [[engine.path, "-pdf", "-silent", *flags, tex_name]]
        else:
            cmds = [[engine.path, *flags, tex_name]] * _MAX_PDFLATEX_RUNS
        log_path = work / f"{stem}.log"
        for cmd in cmds:
            before = _auxiliary(work, stem)
            proc = _run(cmd, work)
            log = (
                log_path.read_text(encoding="latin-1")
                if log_path.exists()
                else proc.stdout.decode("latin-1")
            )
            if proc.returncode != 0:
                raise BuildError(f"{engine.name} failed on {tex_name}:\n{_log_errors(log)}")
            if (
                engine.name == "pdflatex"
                and _auxiliary(work, stem) == before
                and not _RERUN.search(log)
            ):
                break
        pdf = work / f"{stem}.pdf"
        if not pdf.exists():
            raise BuildError(f"{engine.name} produced no PDF for {tex_name}")
        log = log_path.read_text(encoding="latin-1") if log_path.exists() else ""
        return pdf.read_bytes(), log.replace(str(work), ".")


def write_output(
    out_dir: str | os.PathLike,
    tex_name: str,
    files: Mapping[str, str | bytes],
    *,
    engine: Engine | None,
) -> BuildResult:
    """Compile (when ``engine`` is given), then write ``files`` and the PDF into ``out_dir`` in one
    atomic step.  ``files`` maps names relative to ``out_dir`` to contents; ``tex_name`` is the
    main source among them."""
    if tex_name not in files:
        raise ValueError(f"{tex_name} is not among the files to write")
    pdf_bytes, log = compile_pdf(tex_name, files, engine) if engine is not None else (None, "")
    out = Path(out_dir)
    names = sorted(files)
    with atomic_directory(out) as tmp:
        for name in names:
            dest = tmp / name
            dest.parent.mkdir(parents=True, exist_ok=True)
            data = files[name]
            if isinstance(data, bytes):
                dest.write_bytes(data)
            else:
                dest.write_text(data, encoding="utf-8")
        pdf_name = None
        if pdf_bytes is not None:
            pdf_name = str(Path(tex_name).with_suffix(".pdf"))
            (tmp / pdf_name).write_bytes(pdf_bytes)
            log_name = str(Path(tex_name).with_suffix(".log"))
            (tmp / log_name).write_text(log, encoding="utf-8")
            names += [pdf_name, log_name]
    pdf_path = out / pdf_name if pdf_name else None
    return BuildResult(
        out,
        tuple(sorted(names)),
        pdf_path,
        engine.name if engine else None,
        page_count(pdf_path) if pdf_path else 0,
        len(re.findall(r"^Overfull \\hbox", log, re.M)),
    )


def page_count(pdf: str | os.PathLike) -> int:
    """Pages of a PDF: from ``pdfinfo`` when installed, else by counting page objects."""
    pdf = Path(pdf)
    if shutil.which("pdfinfo"):
        proc = subprocess.run(["pdfinfo", str(pdf)], capture_output=True, text=True, check=False)
        m = re.search(r"^Pages:\s+(\d+)", proc.stdout, re.M)
        if m:
            return int(m.group(1))
    return len(re.findall(rb"/Type\s*/Page(?![s\w])", pdf.read_bytes()))
