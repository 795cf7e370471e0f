"""A complete LaTeX document from its parts: preamble, title block, abstract, contents, body and
back matter."""

from __future__ import annotations

from collections.abc import Sequence

from .config import DEFAULT, Config
from .fragment import Latex, _source, raw
from .structure import command, environment

__all__ = ["document"]


def document(
    body: Sequence[Latex],
    *,
    title: Latex | str,
    author: Latex | str = "",
    date: Latex | str = "",
    banner: str | None = None,
    abstract: Latex | str | None = None,
    config: Config = DEFAULT,
    packages: Sequence[tuple[str, str]] = (),
    preamble: Sequence[Latex | str] = (),
    contents: Sequence[Latex] = (Latex(r"\tableofcontents"),),
    back: Sequence[Latex] = (),
) -> Latex:
    """A complete document: optional ``% banner`` line, ``packages`` (loaded first, e.g. the font
    encoding and language), the packages and preamble of ``config``, then ``preamble`` (LaTeX
    source), the title block, the abstract, ``contents`` (table of contents, lists), the body
    blocks separated by blank lines, and the ``back`` matter (bibliography)."""
    head = []
    if banner:
        head.append("% " + banner)
    head.append(
        command(
            "documentclass", raw(config.documentclass), optional=raw(",".join(config.class_options))
        ).raw
    )
    for name, opts in (*packages, *config.packages):
        head.append(Latex("\\usepackage" + (f"[{opts}]" if opts else "") + "{" + name + "}").raw)
    head.extend(config.preamble)
    head.extend(_source(x) if isinstance(x, Latex) else x for x in preamble)
    head.append(command("title", title).raw)
    head.append(command("author", author).raw)
    head.append(command("date", date).raw)
    blocks = [r"\maketitle"]
    if abstract is not None:
        blocks.append(environment("abstract", abstract).raw)
    blocks.extend(b.raw for b in contents)
    blocks.extend(b.raw for b in body)
    blocks.extend(b.raw for b in back)
    content = "\n\n".join(blocks)
    return Latex("\n".join(head) + "\n\n" + environment("document", Latex(content)).raw + "\n")
