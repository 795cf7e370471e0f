"""The structure of a document as LaTeX: commands, environments, sections, paragraphs,
displayed equations, tables, figures and lists; each takes :class:`Latex` or ``str`` (escaped as
text)."""

from __future__ import annotations

from collections.abc import Iterable, Sequence

from .breaking import fit, math_lines
from .config import DEFAULT, Config
from .fragment import Latex, _source, raw

__all__ = [
    "command",
    "environment",
    "section",
    "paragraph",
    "equation",
    "equation_lines",
    "table",
    "short_caption",
    "figure",
    "itemize",
    "description",
]


def command(name: str, *args: Latex | str, optional: Latex | str | None = None) -> Latex:
    """``\\name[optional]{arg}...`` (``str`` arguments are escaped as text)."""
    opt = "" if optional is None else "[" + _source(optional) + "]"
    return Latex("\\" + name + opt + "".join("{" + _source(a) + "}" for a in args))


def environment(
    name: str, body: Latex | str, *args: Latex | str, optional: str | None = None
) -> Latex:
    """``\\begin{name}...body...\\end{name}`` on lines of their own."""
    head = "\\begin{" + name + "}" + (f"[{optional}]" if optional else "")
    head += "".join("{" + _source(a) + "}" for a in args)
    return Latex(f"{head}\n{_source(body).rstrip()}\n\\end{{{name}}}")


def section(title: Latex | str, label: str | None = None, level: int = 0) -> Latex:
    """``\\section`` (level 0), ``\\subsection`` (1) or ``\\subsubsection`` (2), with a label."""
    name = ("section", "subsection", "subsubsection")[level]
    out = command(name, title)
    if label:
        out = out + command("label", raw(label))
    return out


def paragraph(*parts: Latex | str) -> Latex:
    """Running text: the parts joined by single spaces (``str`` parts escaped as text), except
    before a part that starts with closing punctuation and after one that ends with ``(``.

    >>> from reports.latex import inline
    >>> str(paragraph("the period", inline(raw("T")), ", the depth (", inline(raw("m")), ")."))
    'the period $T$, the depth ($m$).'
    """
    out = ""
    for p in parts:
        src = _source(p)
        if not src:
            continue
        if (
            out
            and not out.endswith(("(", " ", "\n", "~"))
            and not src.startswith((".", ",", ";", ":", ")", "'", "!", "?", "-"))
        ):
            out += " "
        out += src
    return Latex(out)


def equation(
    body,
    *,
    tag: str | None = None,
    label: str | None = None,
    numbered: bool = True,
    config: Config = DEFAULT,
) -> Latex:
    """A displayed formula.  ``body`` is a sympy expression/equation or :class:`Latex`; a formula
    wider than ``config.max_width`` is broken over lines (``multline``).  ``tag`` prints the given
    number instead of the automatic one (used for the paper's equation numbers)."""
    lines = math_lines(body, config)
    return equation_lines(lines, tag=tag, label=label, numbered=numbered, config=config)


def equation_lines(
    lines: Sequence[Latex],
    *,
    tag: str | None = None,
    label: str | None = None,
    numbered: bool = True,
    config: Config = DEFAULT,
) -> Latex:
    """Displayed math from ready lines: ``equation`` for one line, ``multline`` for more; each
    line goes through :func:`fit`."""
    lines = [fit(line, config) for line in lines]
    marks = ""
    if tag is not None:
        # a tag is set as text: a prime typed as ' would come out as an apostrophe
        marks += command("tag", raw(tag if "$" in tag else tag.replace("'", "$'$"))).raw
    if label:
        marks += command("label", raw(label)).raw
    star = "" if (numbered or tag is not None) else "*"
    if len(lines) == 1:
        return environment("equation" + star, Latex(lines[0].raw + marks))
    body = " \\\\\n".join(line.raw for line in lines) + marks
    return environment("multline" + star, Latex(body))


def table(
    header: Sequence[Latex | str],
    rows: Sequence[Sequence[Latex | str]],
    *,
    columns: str | None = None,
    caption: Latex | str | None = None,
    label: str | None = None,
    long: bool = False,
    size: str | None = None,
    colsep: str | None = None,
) -> Latex:
    """A booktabs table.  ``columns`` is the column spec (default: left, then right-aligned);
    ``long=True`` makes a ``longtable`` that may break across pages (caption on top, the header
    repeated on every page); ``size`` a font size (``"small"``) and ``colsep`` the space between
    columns (``"3pt"``), both local to the table."""
    ncol = len(header)
    for r in rows:
        if len(r) != ncol:
            raise ValueError(f"row has {len(r)} cells, header has {ncol}")
    columns = columns or ("l" + "r" * (ncol - 1))
    head = " & ".join(_source(h) for h in header) + r" \\"
    body = "\n".join(" & ".join(_source(c) for c in r) + r" \\" for r in rows)
    cap = _caption(caption) if caption is not None else ""
    lab = command("label", raw(label)).raw if label else ""
    switches = [f"\\{size}"] if size else []
    if colsep:
        switches.append(f"\\setlength{{\\tabcolsep}}{{{colsep}}}")
    if long:
        top = (cap + lab + r" \\" + "\n") if cap else ""
        content = (
            f"{top}\\toprule\n{head}\n\\midrule\n\\endfirsthead\n"
            f"\\toprule\n{head}\n\\midrule\n\\endhead\n"
            f"\\bottomrule\n\\endlastfoot\n{body}"
        )
        inner = environment("longtable", Latex(content), raw(columns))
        if not switches:
            return inner
        return Latex("{" + "\n".join(switches) + "\n" + inner.raw + "\n}")
    tab = environment(
        "tabular", Latex(f"\\toprule\n{head}\n\\midrule\n{body}\n\\bottomrule"), raw(columns)
    )
    floated = (
        "\n".join(["\\centering", *switches]) + "\n" + (cap + lab + "\n" if cap else "") + tab.raw
    )
    return environment("table", Latex(floated), optional="htbp")


def short_caption(src: str, limit: int = 90) -> str | None:
    """The first sentence of a caption (LaTeX source) for the lists of figures and tables, or
    ``None`` when the caption is short enough to be listed whole."""
    if len(src) <= limit:
        return None
    depth = 0
    in_math = False
    for i, ch in enumerate(src):
        if ch == "$" and (i == 0 or src[i - 1] != "\\"):
            in_math = not in_math
        elif ch == "{":
            depth += 1
        elif ch == "}":
            depth -= 1
        elif (
            ch == "."
            and not in_math
            and depth == 0
            and src[i + 1 : i + 2] == " "
            and not src[max(0, i - 4) : i].endswith(("Fig", "eq", "eqs", "Eq", "e.g", "i.e"))
        ):
            return src[: i + 1]
    return None


def _caption(caption: Latex | str) -> str:
    src = _source(caption)
    short = short_caption(src)
    return r"\caption" + ("" if short is None else "[{" + short + "}]") + "{" + src + "}"


def figure(
    path: str, caption: Latex | str, *, label: str | None = None, width: str = r"\textwidth"
) -> Latex:
    """A floating figure with one graphic (``path`` relative to the .tex file)."""
    body = (
        "\\centering\n" + command("includegraphics", raw(path), optional=raw(f"width={width}")).raw
    )
    body += "\n" + _caption(caption)
    if label:
        body += command("label", raw(label)).raw
    return environment("figure", Latex(body), optional="htbp")


def itemize(items: Iterable[Latex | str]) -> Latex:
    """A bulleted list."""
    return environment("itemize", Latex("\n".join("\\item " + _source(i) for i in items)))


def description(items: Iterable[tuple[Latex | str, Latex | str]]) -> Latex:
    """A list of (term, explanation) pairs."""
    return environment(
        "description", Latex("\n".join(f"\\item[{_source(k)}] {_source(v)}" for k, v in items))
    )
