"""The one writer of the project's generated source modules.

Every stored text the project loads instead of deriving again (compiled forms, ``srepr`` texts,
simplified forms) is a Python module holding one dictionary, written here: a docstring naming its
generator, an optional import line, and the entries sorted by key.  The file is written to a
temporary name and renamed, so an interrupted run leaves the old module whole.  Each generator's
test derives its entries again and compares, so a module cannot drift from the derivation.
"""

from __future__ import annotations

import os
from pathlib import Path

__all__ = ["write_module"]


def write_module(
    path: Path,
    doc: str,
    entries: dict[str, str],
    *,
    name: str = "SOURCES",
    imports: str | None = None,
    comment: str | None = None,
    as_code: bool = False,
) -> Path:
    """Write ``entries`` as the module ``name = {...}`` with the docstring ``doc`` at ``path``.

    Values are written as string literals, or as Python code when ``as_code`` (each value then
    is an expression the module evaluates on import, with the names ``imports`` brings in).
    """
    lines = [f'"""{doc}"""', "", "# ruff: noqa: E501", ""]
    if imports:
        lines += [imports, ""]
    if comment:
        lines.append(f"#: {comment}")
    lines.append(f"{name} = {{")
    for key, value in sorted(entries.items()):
        lines.append(f"    {key!r}: {value if as_code else repr(value)},")
    lines.append("}")
    tmp = path.with_suffix(".tmp")
    tmp.write_text("\n".join(lines) + "\n", encoding="utf-8")
    os.replace(tmp, path)
    return path
