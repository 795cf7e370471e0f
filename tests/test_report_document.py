"""The report as a document a reader is handed: front matter, findings first, conclusions and
references last, PDF metadata, and no machine notation in the text -- in English and in Russian.

The English report is built once (from the CLI, so that the producing command is recorded), the
Russian one once more from the same cache.  The LaTeX source is always checked; where ``pdflatex``,
``pdftotext`` and ``pdfinfo`` are installed (and, for Russian, Cyrillic TeX) the PDF is checked too.
"""

from __future__ import annotations

import re
import shutil
import subprocess
import unicodedata
from datetime import datetime, timezone

import pytest

from reports.bibliography import ENTRIES
from reports.build import find_engine, supports
from reports.cli import main
from reports.report import tex_name
from reports.sections import SECTIONS, load

pytestmark = pytest.mark.slow

HAVE_PDF_TOOLS = (
    find_engine() is not None
    and shutil.which("pdftotext") is not None
    and shutil.which("pdfinfo") is not None
)
HAVE = {"en": HAVE_PDF_TOOLS, "ru": HAVE_PDF_TOOLS and supports("ru")}

#: machine notation that must not reach a reader: Python/ASCII maths and Python values, an escaped
#: underscore, a command-line option whose double hyphen became a dash, and the check sentence
#: that used to follow every step
FORBIDDEN = {
    "Python power": r"\*\*",
    "ASCII power": r"[A-Za-z0-9)]\^[0-9(]",
    "sqrt( call": r"\bsqrt\(",
    "spelled Greek": r"\b(omega|gamma|theta|Delta|lambda|lam)(_?[a-z0-9]+)?\b",
    "Python bool": r"\b(True|False)\b",
    "dN/dtheta": r"dN/dtheta",
    "eps =": r"\beps\s*=",
    "escaped underscore": r"(?<!x86)\\_",  # a machine name such as x86_64 may have one
    "option with a dash": r"[\u2013\u2014](order|terms|m|Q|out|lang|digits|tol)\b",
    "repeated check": r"Check: proved symbolically",
    "ASCII minus-plus": r"(\+-|-\+) ",
}


@pytest.fixture(scope="module")
def reports(tmp_path_factory):
    """The English and the Russian report, built by the command a user types."""
    cache = tmp_path_factory.mktemp("cache")
    out = {}
    for lang in ("en", "ru"):
        directory = tmp_path_factory.mktemp(lang) / "report"
        args = ["report", "--out", str(directory), "--cache", str(cache), "-q"]
        if lang != "en":
            args += ["--lang", lang]
        assert main(args) == 0
        out[lang] = directory
    return out


def _tex(reports, lang) -> str:
    return (reports[lang] / tex_name(lang)).read_text(encoding="utf-8")


def _pdf(reports, lang):
    return reports[lang] / tex_name(lang).replace(".tex", ".pdf")


def _pdf_text(reports, lang) -> str:
    out = subprocess.run(
        ["pdftotext", str(_pdf(reports, lang)), "-"], capture_output=True, check=True
    )
    text = unicodedata.normalize("NFKC", out.stdout.decode("utf-8", "replace"))
    return re.sub(r"\s+", " ", text)


def _prose(tex: str) -> str:
    """The source without its mathematics, verbatim text and commands' arguments that are names
    (labels, references, citations, files): what is left is what a reader reads as words."""
    tex = tex.split(r"\begin{document}", 1)[1]
    tex = re.sub(
        r"\\begin\{(equation|multline|gather|align)\*?\}.*?\\end\{\1\*?\}", " ", tex, flags=re.S
    )
    tex = re.sub(r"\\\[.*?\\\]", " ", tex, flags=re.S)
    tex = _drop_command(tex, r"\fitcell")
    tex = re.sub(r"(?<!\\)\$.*?(?<!\\)\$", " ", tex, flags=re.S)
    tex = re.sub(
        r"\\(label|ref|cite|includegraphics|hyperref|url|bibitem)(\[[^\]]*\])?\{[^}]*\}", " ", tex
    )
    return tex


def _drop_command(tex: str, name: str) -> str:
    """``tex`` without every ``name{...}`` (balanced braces)."""
    out, pos = [], 0
    while (k := tex.find(name + "{", pos)) >= 0:
        out.append(tex[pos:k])
        depth, j = 0, k + len(name)
        while j < len(tex):
            depth += {"{": 1, "}": -1}.get(tex[j], 0) if tex[j - 1] != "\\" else 0
            j += 1
            if depth == 0:
                break
        pos = j
    out.append(tex[pos:])
    return " ".join(out)


@pytest.mark.parametrize("lang", ["en", "ru"])
def test_front_matter(reports, lang):
    import reports.frontmatter as fm

    tex = _tex(reports, lang)
    head, body = tex.split(r"\begin{document}", 1)
    assert r"\hypersetup{" in head and "pdftitle={" in head and "pdfauthor={paramres " in head
    prov = fm.provenance()
    assert prov.version in head
    if prov.commit:  # a git checkout: the commit is printed; a wheel install has none
        assert prov.commit in head
    today = datetime.now(timezone.utc)
    assert str(today.year) in head
    # the producing command, its output directory by name alone (no path of this machine)
    expected = f"paramres report -{{}}-out {reports[lang].name}"
    assert expected in head.replace("-{}-{}", "-{}-"), "the producing command is printed"
    assert str(reports[lang].parent) not in head
    if lang == "ru":
        assert "-{}-lang ru" in head.replace("-{}-{}", "-{}-")
    for piece in (
        r"\maketitle",
        r"\begin{abstract}",
        r"\tableofcontents",
        r"\listoffigures",
        r"\listoftables",
        r"\begin{thebibliography}",
    ):
        assert piece in body, piece


@pytest.mark.parametrize("lang", ["en", "ru"])
def test_findings_first_conclusions_and_references_last(reports, lang):
    tex = _tex(reports, lang)
    labels = re.findall(r"\\section\{[^}]*\}\\label\{([^}]+)\}", tex)
    assert labels[:2] == ["sec:introduction", "sec:summary"]
    assert labels[-1] == "sec:conclusions"
    assert labels == [load(name).LABEL for name in SECTIONS]
    assert tex.index(r"\begin{thebibliography}") > tex.index(r"\label{sec:conclusions}")
    # every entry is cited and every citation has an entry
    keys = {k for k, _, _ in ENTRIES}
    cited = {k for group in re.findall(r"\\cite\{([^}]*)\}", tex) for k in group.split(",")}
    assert cited == keys
    for key in keys:
        assert r"\bibitem{" + key + "}" in tex
    assert r"\label{tab:errata}" in tex


def test_summary_numbers_come_from_the_engine(reports):
    """The summary states the catalogue's counts, the closings' count and the island's ends."""
    from analytic.catalogue import catalogue
    from analytic.closings import closings
    from reports.sections.summary import MAX_ORDER

    tex = _tex(reports, "en")
    summary = tex.split(r"\label{sec:summary}", 1)[1].split(r"\section{", 1)[0]
    rows = catalogue()
    differs = [r for r in rows if r.status != "agrees"]
    assert f"checks {len(rows)} numbered results" in summary
    assert f"{len(differs)} do not" in summary
    assert f"there are {len(closings(MAX_ORDER))} closings" in summary
    # m_min = n pi/(6Q) (odd) and sqrt(2/(3Q)) (even), as sympy prints them
    assert r"m_{\min} = \frac{\pi n}{6 Q}" in summary
    assert r"m_{\min} = \frac{\sqrt{6}}{3 \sqrt{Q}}" in summary
    # the island at Q = 7 (paper model): the proven ends, as the existence section prints them
    assert re.search(r"0\.48\d+ < m < 0\.65\d+", summary)


@pytest.mark.parametrize("lang", ["en", "ru"])
def test_no_machine_notation_in_the_prose(reports, lang):
    prose = _prose(_tex(reports, lang))
    for what, pattern in FORBIDDEN.items():
        hit = re.search(pattern, prose)
        assert hit is None, f"{what}: ...{prose[max(0, hit.start() - 80) : hit.end() + 40]}..."


@pytest.mark.parametrize("lang", ["en", "ru"])
def test_pdf_metadata_and_text(reports, lang):
    if not HAVE[lang]:
        pytest.skip(f"no TeX/poppler for {lang}")
    info = subprocess.run(
        ["pdfinfo", str(_pdf(reports, lang))], capture_output=True, text=True, check=True
    ).stdout
    title = re.search(r"^Title:\s+(.*)$", info, re.M).group(1)
    author = re.search(r"^Author:\s+(.*)$", info, re.M).group(1)
    assert author.startswith("paramres ")
    if lang == "en":
        assert title.startswith("Regions of parametric excitation")
    else:
        assert title.startswith("Области параметрического возбуждения")
    text = _pdf_text(reports, lang)
    words = {
        "en": (
            "Abstract",
            "Contents",
            "List of Figures",
            "List of Tables",
            "References",
            "Summary of results",
            "Conclusions",
            "Butikov",
        ),
        "ru": (
            "Аннотация",
            "Содержание",
            "Список иллюстраций",
            "Список таблиц",
            "Список литературы",
            "Сводка результатов",
            "Заключение",
            "Бутиков",
            "интервал",
            "глубина модуляции",
            "добротность",
        ),
    }[lang]
    for w in words:
        assert w in text, w
    for what, pattern in FORBIDDEN.items():
        if what in ("ASCII power",):  # superscripts extract as plain digits from a PDF
            continue
        hit = re.search(pattern, text)
        assert hit is None, f"{what}: ...{text[max(0, hit.start() - 80) : hit.end() + 40]}..."
    # the command is printed with its double hyphen
    assert "paramres report --out" in text


#: English sentences the Russian report once showed (figure captions, the general system, the
#: normal form, the window theorem, the threshold sections); each now has its Russian version
KNOWN_ENGLISH = (
    "Growth inside the first interval",
    "row by row up to sign",
    "so two conditions remain",
    "with four amplitudes",
    "where the coupling constant is",
    "Together these give the normal form",
    "so all roots cross with the same sign",
    "the two models part at",
    "in the threshold series",
    "the number is the midpoint of a ball",
    "the reference should be (15), not (14)",
    "The angular momentum",
    # the speed table's methods, the Floquet table's header, the edge shapes' names, the
    # expansions' units and the notes of the stitching section
    "series K=",
    "fixed point (paper)",
    "per point",
    "uncertified",
    "printed eq.",
    "equations solved",
    "certified digits",
    "odd-cos-sin",
    "odd-sin-cos",
    "even-cos-cos",
    "even-sin-sin",
    "in units of",
    "solved for",
    "det M, paper model",
    "normal form",
)

#: English words set upright inside formulas that the English report has (so the check below
#: looks at words that do occur)
ENGLISH_IN_FORMULAS = ("at", "paper", "exact", "odd", "even", "centre", "stitching system")


def _upright_words(tex: str) -> list[str]:
    """The contents of ``\\text{...}`` and ``\\mathrm{...}`` in the document's formulas."""
    body = tex.split(r"\begin{document}", 1)[1]
    return re.findall(r"\\(?:text|mathrm)\{([^{}]*)\}", body)


#: four English words in a row (separated by spaces or punctuation, not by mathematics)
ENGLISH_RUN = re.compile(r"[A-Za-z]{2,}(?:[ ,;:()'.]+[A-Za-z]{2,}){3,}")


def test_the_russian_report_has_no_english_sentence(reports):
    # every English entry of the phrasebook (whole sentences and phrases of four words or more)
    # and the sentences above must not appear in the Russian prose: each has a translation
    from reports.i18n_ru import PHRASES

    prose = re.sub(r"\s+", " ", _prose(_tex(reports, "ru")))
    english = [en for en in PHRASES if len(en.split()) >= 4 and "$" not in en]
    english += list(KNOWN_ENGLISH)
    found = [en for en in english if re.sub(r"\s+", " ", en) in prose]
    assert not found, found
    # the catalogue's verdicts built with computed formulas (translated through templates): no
    # verdict keeps four English words in a row outside its mathematics
    tex = _tex(reports, "ru")
    verdicts = re.findall(r"\\emph\{Вывод:\}(.*?)(?:\n\s*\n|\\paragraph)", tex, flags=re.S)
    assert len(verdicts) >= 17, len(verdicts)  # 37 in today's report; 17 carry formulas
    left = [m[0] for v in verdicts if (m := ENGLISH_RUN.search(_prose(r"\begin{document}" + v)))]
    assert not left, left
    # and the English report does say them (so the check looks at the right text)
    en_prose = re.sub(r"\s+", " ", _prose(_tex(reports, "en")))
    assert all(k in en_prose for k in ("row by row up to sign", "so two conditions remain"))
    assert all(k in en_prose for k in ("series K=", "equations solved", "in units of"))


@pytest.mark.parametrize("lang", ["en", "ru"])
def test_words_inside_formulas(reports, lang):
    # the words set upright inside formulas (``at T = T_av/2``, ``(paper)``, ``n odd``,
    # ``centre``) are translated like the prose
    words = _upright_words(_tex(reports, lang))
    english = [w for w in words if re.search(r"[A-Za-z]{2,}", w)]
    if lang == "en":  # the check looks at words that do occur
        found = {w.strip(" ()") for w in english}
        assert set(ENGLISH_IN_FORMULAS) <= found, set(ENGLISH_IN_FORMULAS) - found
    else:
        assert not english, english


def test_bad_language_is_refused(tmp_path, capsys):
    with pytest.raises(SystemExit) as exc:
        main(["report", "--out", str(tmp_path / "r"), "--lang", "de"])
    assert exc.value.code == 2
    assert "invalid choice" in capsys.readouterr().err
    assert not (tmp_path / "r").exists()


#: mathematics set as plain text in a verdict: an operator typeset on its own between text tokens
#: (``m $\to$ 0``), a formula cut at a slash, a power or another formula (``$T_{av}$/2``,
#: ``$m_{min}$$^{2}$``), and outside the formulas a relation (``T = n``, ``1/Q ~``) or a one-letter
#: variable (``in m at``)
PLAIN_MATHS_AROUND = {
    "operator set alone": r"\$\s*(\\to|\\mp|\\pm|\\sim|\\le|\\ge|\\ll|<|>|=)\s*\$",
    "formula cut at a slash, a power or another formula": r"\$/|/\$|\$\$|\$\^",
}
PLAIN_MATHS_OUTSIDE = {
    "relation in the text": r"(?<![<>])(=|~|<|>)(?![<>])",
    # a one-letter word other than ``a`` and ``I``; ``--terms K`` is a command's placeholder
    "one-letter variable in the text": r"(?<![\w\\{}.'-])(?<!terms )[B-HJ-Zb-z](?![\w'}]|\.\w)",
}
_MATH = re.compile(r"\\\[.*?\\\]|\$[^$]*\$", re.S)


def plain_text_maths(verdict: str) -> list[str]:
    """The places where ``verdict`` (LaTeX source) sets mathematics as text."""
    hits = [what for what, p in PLAIN_MATHS_AROUND.items() if re.search(p, verdict)]
    text = _MATH.sub(" ", verdict)
    for what, p in PLAIN_MATHS_OUTSIDE.items():
        if m := re.search(p, text):
            hits.append(f"{what}: ...{text[max(0, m.start() - 40) : m.end() + 40]}...")
    return hits


def test_plain_text_maths_is_recognised():
    # verdicts as an earlier report set them (every formula of the prose must be real
    # mathematics), and the same verdicts typeset
    old = [
        r"The limit m $\to$ 0 of the exact tuning condition (6), T = n $T_{av}$/2 with $T_{av}$ "
        r"$\to$ $T_{0}$; decided symbolically.",
        r"Threshold = tangency of the normal form (N = 0, $dN/d\theta$ = 0), solved in the "
        r"distinguished scaling 1/Q $\sim$ $m^{1}$",
        r"(with $m_{min}$ = $\pi$/(6Q), s = $\sqrt{1 - m_{min}^{2}/m^{2}}$, compared coefficient "
        r"by coefficient in m at fixed $m_{min}$/m)",
        r"a friction shift of the centre ($s^{2}$ - 1 = -$m_{min}$$^{2}$/$m^{2}$)",
        r"(there is no $m^{3}$ term: even orders are even in m).",
    ]
    new = [
        r"The limit $m \to 0$ of the exact tuning condition (6), $T = nT_{av}/2$ with "
        r"$T_{av} \to T_0$; decided symbolically.",
        r"The threshold is the tangency of the normal form ($N = 0$, $dN/d\theta = 0$), solved in "
        r"the distinguished scaling $1/Q \sim m^{1}$",
        r"(with $m_{\min} = \pi/(6Q)$, $s = \sqrt{1 - m_{\min}^2/m^2}$, compared coefficient by "
        r"coefficient in $m$ at fixed $m_{\min}/m$), i.e. \[x = 1\] (any order: paramres series "
        r"-{}-{}order 1 -{}-{}terms K); a case",
    ]
    assert all(plain_text_maths(v) for v in old)
    assert not [h for v in new for h in plain_text_maths(v)]


@pytest.mark.parametrize("lang", ["en", "ru"])
def test_verdicts_set_their_formulas_as_mathematics(reports, lang):
    head = {"en": "Verdict:", "ru": "Вывод:"}[lang]
    tex = _tex(reports, lang)
    verdicts = re.findall(r"\\emph\{" + head + r"\}(.*?)(?:\n\s*\n|\\paragraph)", tex, flags=re.S)
    assert len(verdicts) >= 30, len(verdicts)  # 37 in today's report
    bad = {v[:60]: h for v in verdicts if (h := plain_text_maths(v))}
    assert not bad, bad


@pytest.mark.skipif(not HAVE["en"], reason="pdflatex or poppler-utils not installed")
def test_the_report_settles_in_two_passes(reports, monkeypatch):
    """The front matter is numbered apart from the body, so the contents' length does not move the
    body's pages: a fresh compilation of the report settles after two pdflatex passes (a third
    would read back the same auxiliary files), and the body starts on page 1 after the lists."""
    import reports.build as build

    directory = reports["en"]
    files = {tex_name("en"): _tex(reports, "en")}
    for figure in sorted((directory / "figures").iterdir()):
        files[f"figures/{figure.name}"] = figure.read_bytes()
    passes = []
    real_run = build._run
    monkeypatch.setattr(build, "_run", lambda cmd, cwd: passes.append(cmd) or real_run(cmd, cwd))
    pdf, _ = build.compile_pdf(tex_name("en"), files, find_engine())
    assert len(passes) == 2
    assert pdf.startswith(b"%PDF")
    text = _pdf_text(reports, "en")
    contents = text.split("List of Figures", 1)[0]
    assert re.search(r"1 Introduction \.?[ .]*1 ", contents), contents[:400]


def test_the_settled_test_ignores_only_the_last_page_record(tmp_path):
    """The comparison of auxiliary files between passes drops the kernel's last-page record (read
    by no pass) and nothing else."""
    from reports.build import _auxiliary

    aux = tmp_path / "doc.aux"
    aux.write_bytes(b"\\relax\n\\newlabel{a}{{1}{2}}\n\\gdef \\@abspage@last{49}\n")
    first = _auxiliary(tmp_path, "doc")
    aux.write_bytes(b"\\relax\n\\newlabel{a}{{1}{2}}\n\\gdef \\@abspage@last{51}\n")
    assert _auxiliary(tmp_path, "doc") == first
    aux.write_bytes(b"\\relax\n\\newlabel{a}{{1}{3}}\n\\gdef \\@abspage@last{51}\n")
    assert _auxiliary(tmp_path, "doc") != first


#: symbols that used to appear before (or without) their definition: (what, the symbol as it is
#: set, its definition in English or Russian)
DEFINED_SYMBOLS = (
    ("the phases a_i", r"(?<![\\A-Za-z])a_\{?[i12]\}?", r"a_i = \\omega_i T/2"),
    ("W_1, W_2", r"W_\{?[i12]\}?", r"\$W_i\$ (is|---)"),
    ("the matrix E", r"\$S\\,E\$|E_\{12\}", r"\$E\$ (is the|---)"),
    ("the lengths l_a, l_b", r"l_\{?[ab]\}?", r"\$l_a\$ (and|и) \$l_b\$ (the|---)"),
    ("the half-period map G", r"G_\{11\}|\$G\$", r"(map|полпериода) \$G\$"),
    ("the reflection P", r"P G\^\{-1\}", r"P = \\operatorname\{diag\}"),
    ("Delta T", r"\\Delta T(?![a-z])", r"\\Delta T = T - nT_\{av\}/2"),
    ("theta", r"\\theta(?![a-z])", r"\\theta = \\omega_\{av\}\\Delta T/2"),
    ("T_av", r"T_\{av\}", r"T_\{av\} = 2\\pi/\\omega_\{av\}"),
    ("tau", r"\\tau(?![a-z])", r"\\tau = T/T_0"),
    ("q", r"(?<![\\A-Za-z])q(?![A-Za-z{])", r"\$q = \\omega_1\(1\+m\)\^2"),
    ("p", r"(?<![\\A-Za-z\[])p(?![A-Za-z{\]])", r"\$p = e\^\{-\\gamma T\}"),
    ("C_i, S_i", r"[CS]_\{?[i12]\}?", r"C_i = \\cos\(\\omega_i T/2\)"),
    ("N", r"(?<![\\A-Za-z])N(?= [=<])", r"\$N\$ (is the normal form|--- нормальная форма)"),
    ("J_0", r"J_0", r"\$J_0\$ (its|---)"),
    ("Omega_1", r"\\Omega_", r"\\Omega_\{1\} = \\sqrt"),
    ("Lambda_1", r"\\Lambda_", r"\\Lambda_\{1\} = \\sqrt"),
    ("Q_min", r"Q_\{\\min\}", r"\$Q_\{\\min\}\$ (the|---)"),
    ("T_0", r"T_0|T_\{0\}", r"\$T_0\$ (that of|--- период)"),
    ("omega_1, omega_2", r"\\omega_\{?[12]\}?", r"\(\$\\omega_1\$, \$\\omega_2\$ (the|---)"),
    ("the edge factors F_+, F_-", r"F_\{?[+-]|F_\\pm", r"\$F_\\pm\$ (its|---)"),
)


@pytest.mark.parametrize("lang", ["en", "ru"])
def test_symbols_are_defined_where_they_are_first_used(reports, lang):
    """Each symbol of :data:`DEFINED_SYMBOLS` is defined before its first use in the report or
    in the sentence of its first use (a teacher reads the report from the front)."""
    body = _tex(reports, lang).split(r"\begin{document}", 1)[1]
    for what, symbol, definition in DEFINED_SYMBOLS:
        first = re.search(symbol, body)
        assert first is not None, what
        said = re.search(definition, body)
        assert said is not None, f"{what} is never defined"
        end = re.search(r"[.:](\s|\}|$)|\n\n", body[first.end() :])
        sentence_end = first.end() + (end.start() if end else len(body))
        assert said.start() <= sentence_end, (
            f"{what} is used before it is defined: "
            f"...{body[max(0, first.start() - 120) : first.end() + 60]}..."
        )


@pytest.mark.parametrize("lang", ["en", "ru"])
def test_no_overfull_lines(reports, lang):
    """No line sticks out into the margin, in either language (the Russian words are longer:
    the damping labels of the certified table, the method names of the speed table)."""
    if not HAVE[lang]:
        pytest.skip(f"no TeX for {lang}")
    log = _pdf(reports, lang).with_suffix(".log").read_text(encoding="utf-8", errors="replace")
    overfull = re.findall(r"^Overfull \\hbox \(([\d.]+pt) too wide\) (.*)$", log, re.M)
    assert overfull == [], f"LaTeX reported lines sticking out into the margin: {overfull}"


#: (what, a use of a symbol with a second meaning): the sine's paragraphs name their own symbols
#: (V, psi, eta, delta, nu, kappa) where the engine's are the paper's q, the angle theta =
#: omega_av Delta T/2, the damping coefficient c, the integers j, k of the closings proof
SECOND_MEANINGS = (
    ("q as the Hill coefficient", r"q\(t\)|\$q\$ (is the constant|равно постоянной)"),
    ("theta = 2 pi t/T", r"\\theta = 2\\pi t/T|u\{\\left\(\\theta"),
    ("c = (T/T_0)^2", r"(?<![\\A-Za-z])c = \(T/T_0\)\^2|eigenvalues \$c\$|значениями \$c\$"),
    ("d = c - k^2", r"(?<![\\A-Za-z])d = c - k"),
    ("k as a Fourier index", r"e\^\{ik|\(k - 1\\right\)|\$k \\ge 3/2\$"),
    ("a_k as a Fourier coefficient", r"a_\{1/2\}|\$a_k\$"),
    ("u_+ beside u", r"u_\{?[+-]"),
    # M is the monodromy matrix: the bob's mass is not a second M (eqs. 2-4 write J = J_0 (l/l_0)^2)
    ("M as the bob's mass", r"J = Ml\^2|(?<![\\A-Za-z])Mgl|c/M(?![A-Za-z])|\{2 M\}|\}\{M\}"),
    # w is omega_av/omega_0 (sec. 'Parameters of the normal form'), not the mean frequency itself
    ("w as a frequency", r"(?<![\\A-Za-z])w = D W_1"),
)


@pytest.mark.parametrize("lang", ["en", "ru"])
def test_no_symbol_has_two_meanings(reports, lang):
    body = _tex(reports, lang).split(r"\begin{document}", 1)[1]
    for what, pattern in SECOND_MEANINGS:
        hit = re.search(pattern, body)
        assert hit is None, f"{what}: ...{body[max(0, hit.start() - 80) : hit.end() + 40]}..."
    for definition in (
        r"\psi = 2\pi t/T",
        r"\eta = (T/T_0)^2",
        r"\delta = \eta - \nu^{2}",
        r"J = J_0 (l/l_0)^2",
        r"w = (D W_1 + (1-D) W_2)/\omega_0",
    ):
        assert definition in body, definition


@pytest.mark.parametrize("lang", ["en", "ru"])
def test_w_is_defined_where_first_used(reports, lang):
    """``w`` (``omega_av/omega_0``, the normal-form parameter with ``T/T_0 = x/(pi w)``) is said in
    words where it first appears, and each catalogue entry that names ``w``, ``r`` or ``beta`` in
    its verdict defines them there (eq. (7) had ``T_av/T_0 = 1/w`` with no ``w`` in it; (38), (43)
    'their r, beta, w')."""
    body = _tex(reports, lang).split(r"\begin{document}", 1)[1]
    first = re.search(r"\$[^$]*(?<![\\A-Za-z])w(?![A-Za-z])[^$]*\$", body)
    assert first is not None
    near = body[first.start() : first.end() + 80]
    assert r"w = \omega_{av}/\omega_0" in near, near
    uses = {
        "w": (r"(?<![\\A-Za-z])w(?![A-Za-z])", r"(?<![\\A-Za-z])w = "),
        "r": (r"(?<![\\A-Za-z])r(?![A-Za-z])", r"(?<![\\A-Za-z])r(\^2)? = "),
        "beta": (r"\\beta(?![A-Za-z])", r"\\beta = "),
    }
    verdict = r"\\emph\{(?:Verdict|Вывод):\}(.*?)(?=\n\n|\\paragraph|$)"
    entries = re.findall(r"\\paragraph\{.*?(?=\\paragraph\{|\\section\{|$)", body, re.S)
    checked = 0
    for entry in entries:
        for text in re.findall(verdict, entry, re.S):
            math = " ".join(re.findall(r"\$(.*?)\$", text))
            for name, (use, define) in uses.items():
                if re.search(use, math):
                    checked += 1
                    assert re.search(define, math), f"{name} undefined in: {entry[:120]}"
    assert checked >= 7  # (7): w; (38), (43): r, beta, w


@pytest.mark.parametrize("lang", ["en", "ru"])
def test_catalogue_entries_define_s_before_their_series(reports, lang):
    """A catalogue entry whose derived series are in ``s`` states ``s`` before the first of them
    (the verdict, which restates it, comes after the formulas)."""
    body = _tex(reports, lang).split(r"\begin{document}", 1)[1]
    entries = re.findall(r"\\paragraph\{.*?(?=\\paragraph\{|\\section\{|$)", body, re.S)
    with_s = 0
    for entry in entries:
        displays = re.findall(
            r"\\\[(.*?)\\\]|\\begin\{multline\*\}(.*?)\\end\{multline\*\}", entry, re.S
        )
        for k, (one, many) in enumerate(displays):
            formula = one or many
            if re.search(r"(?<![\\A-Za-z])s(?![A-Za-z])", formula):
                with_s += 1
                earlier = [a or b for a, b in displays[: k + 1]]
                assert any(x.strip().startswith(r"s = \sqrt") for x in earlier), entry[:200]
                break
    assert with_s >= 3  # sec. 6 n = 3, (40), (45)
