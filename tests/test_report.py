"""The derivation report (``paramres report``): built once into a temporary directory, then checked.

The LaTeX source is always checked (sections, the paper's equation numbers, tables, figures, banner,
determinism, atomic writes).  Where ``pdflatex`` and ``pdftotext`` are installed -- CI installs them
-- the PDF is checked too: page count, and the extracted text contains every section, the paper's
equation numbers and the tables.
"""

from __future__ import annotations

import re
import shutil
import subprocess
import unicodedata

import pytest

from reports import build as build_mod
from reports.build import BuildError, find_engine, write_output
from reports.cli import main
from reports.output import BANNER
from reports.report import TEX_NAME, build_report
from reports.sections import SECTIONS, load

pytestmark = pytest.mark.slow

HAVE_TEX = find_engine() is not None and shutil.which("pdftotext") is not None

#: paper equation numbers that the report derives and prints as tags (see analytic/reductions.py)
PAPER_TAGS = (
    "8",
    "9",
    "10",
    "11",
    "12",
    "13",
    "14",
    "15",
    "16",
    "17",
    "24",
    "25",
    "26",
    "31",
    "32",
    "34",
    "35",
    "36",
    "37",
    "39",
    "41",
    "44",
)
FIGURES = ("fig2-intervals.pdf", "fig8-friction.pdf", "fig8-island-q7.pdf", "accuracy-series.pdf")
MIN_PAGES = 25


@pytest.fixture(scope="module")
def built(tmp_path_factory):
    """A cold build (empty cache) and a warm rebuild from the cache into a second directory."""
    cache = tmp_path_factory.mktemp("cache")
    cold_dir = tmp_path_factory.mktemp("cold") / "report"
    warm_dir = tmp_path_factory.mktemp("warm") / "report"
    messages: list[str] = []
    cold = build_report(cold_dir, cache_dir=cache, log=messages.append)
    warm = build_report(warm_dir, cache_dir=cache, log=lambda m: None)
    return cold, warm, messages, cache


def _tex(result) -> str:
    return (result.directory / TEX_NAME).read_text(encoding="utf-8")


def test_source_has_banner_and_is_ascii(built):
    cold, *_ = built
    tex = _tex(cold)
    assert tex.splitlines()[0] == "% " + BANNER.format(what="report")
    assert tex.isascii()
    assert "\\begin{document}" in tex and tex.rstrip().endswith("\\end{document}")


def test_every_section_is_present(built):
    tex = _tex(built[0])
    for name in SECTIONS:
        module = load(name)
        assert f"\\section{{{module.TITLE}}}\\label{{{module.LABEL}}}" in tex, module.TITLE


def test_paper_equation_numbers_are_tagged(built):
    tex = _tex(built[0])
    tags = set(re.findall(r"\\tag\{([^}]*)\}", tex))
    missing = [t for t in PAPER_TAGS if t not in tags]
    assert not missing, f"paper equations not tagged in the report: {missing}"


def test_tables_and_figures(built):
    cold, *_ = built
    tex = _tex(cold)
    for label in (
        "tab:catalogue",
        "tab:closings",
        "tab:certified",
        "tab:floquet",
        "tab:island",
        "tab:halves",
    ):
        assert f"\\label{{{label}}}" in tex, label
    for name in FIGURES:
        assert f"figures/{name}" in tex
        data = (cold.directory / "figures" / name).read_bytes()
        assert data.startswith(b"%PDF-"), name
        assert b"CreationDate" not in data  # reproducible: no time stamp


def test_catalogue_rows_all_present(built):
    from analytic.catalogue import catalogue
    from reports.sections.catalogue import anchor

    tex = _tex(built[0])
    for row in catalogue():
        assert f"\\label{{cat:{anchor(row.equation)}}}" in tex, row.equation


def test_same_inputs_give_the_same_bytes(built):
    cold, warm, *_ = built
    assert _tex(cold) == _tex(warm)
    for name in FIGURES:
        a = (cold.directory / "figures" / name).read_bytes()
        b = (warm.directory / "figures" / name).read_bytes()
        assert a == b, name


def test_progress_is_reported(built):
    _, _, messages, _ = built
    assert any(m.startswith(f"report: [1/{len(SECTIONS)}]") for m in messages)
    assert any(f"[{len(SECTIONS)}/{len(SECTIONS)}]" in m for m in messages)


def test_sections_are_deterministic_without_cache():
    from reports.report import assemble
    from reports.sections import Context

    a = assemble(Context(log=lambda m: None), ("model", "closings"))
    b = assemble(Context(log=lambda m: None), ("model", "closings"))
    assert a.tex == b.tex


def test_failed_build_leaves_the_old_report(built, tmp_path, monkeypatch):
    out = tmp_path / "report"
    out.mkdir()
    (out / TEX_NAME).write_text("old", encoding="utf-8")
    from reports.sections import model

    def broken(ctx):
        raise RuntimeError("boom")

    monkeypatch.setattr(model, "build", broken)
    with pytest.raises(RuntimeError, match="boom"):
        build_report(out, cache_dir=None, compile=False, log=lambda m: None, sections=("model",))
    assert [p.name for p in out.iterdir()] == [TEX_NAME]
    assert (out / TEX_NAME).read_text(encoding="utf-8") == "old"


@pytest.mark.skipif(find_engine() is None, reason="no TeX engine installed")
def test_latex_error_leaves_the_old_report(tmp_path):
    out = tmp_path / "report"
    out.mkdir()
    (out / "keep.txt").write_text("old", encoding="utf-8")
    bad = "\\documentclass{article}\\begin{document}\\undefinedcommand\\end{document}\n"
    with pytest.raises(BuildError, match="undefinedcommand|Undefined control sequence"):
        write_output(out, "bad.tex", {"bad.tex": bad}, engine=find_engine())
    assert sorted(p.name for p in out.iterdir()) == ["keep.txt"]


def test_without_tex_the_source_is_written_and_the_way_to_the_pdf_is_told(
    built, tmp_path, monkeypatch, capsys
):
    real_which = shutil.which
    monkeypatch.setattr(
        build_mod.shutil, "which", lambda name: None if "latex" in name else real_which(name)
    )
    out = tmp_path / "report"
    assert main(["report", "--out", str(out), "--cache", str(built[3]), "-q"]) == 0
    captured = capsys.readouterr()
    assert (out / TEX_NAME).exists()
    assert (out / "figures" / FIGURES[0]).exists()
    assert not (out / "paramres-report.pdf").exists()
    assert "apt-get install" in captured.err and "latexmk -pdf" in captured.err
    assert "wrote" in captured.out


def test_cli_refuses_an_output_path_that_is_a_file(tmp_path, capsys):
    target = tmp_path / "file"
    target.write_text("x", encoding="utf-8")
    assert main(["report", "--out", str(target), "--no-cache", "-q"]) == 2
    err = capsys.readouterr().err
    assert err.startswith("paramres: error:") and "not a directory" in err
    assert "Traceback" not in err
    assert target.read_text(encoding="utf-8") == "x"


# ----------------------------------------------------------------------------------------- PDF


def _pdf_text(result) -> str:
    out = subprocess.run(
        ["pdftotext", "-layout", str(result.pdf), "-"], capture_output=True, check=True
    )
    text = unicodedata.normalize("NFKC", out.stdout.decode("utf-8", "replace"))
    text = text.replace("\u2019", "'").replace("\u2018", "`").replace("\u2212", "-")
    return re.sub(r"\s+", " ", text)


@pytest.mark.skipif(not HAVE_TEX, reason="pdflatex/pdftotext not installed")
def test_pdf_pages_and_overfull_lines(built):
    cold, *_ = built
    assert cold.pdf is not None and cold.pdf.exists()
    assert cold.pages >= MIN_PAGES
    assert cold.overfull == 0, "LaTeX reported lines sticking out into the margin"


@pytest.mark.skipif(not HAVE_TEX, reason="pdflatex/pdftotext not installed")
def test_pdf_text_has_sections_equation_numbers_and_tables(built):
    text = _pdf_text(built[0])
    for name in SECTIONS:
        title = re.sub(r"\s+", " ", load(name).TITLE)
        assert title in text, title
    for tag in PAPER_TAGS:
        assert f"({tag})" in text, tag
    for caption in (
        "Table 1:",
        "Figure 1:",
        "The paper's numbered results:",
        "Every closing of the intervals",
        "Certified edges",
    ):
        assert caption in text, caption
    assert "agrees" in text and "differs" in text
    # a certified number from the closings table: T/T0 = 2 sqrt(10)/5 at m = 3/5 (closings theorem)
    assert "1.26491 10640 67351 73279" in text
