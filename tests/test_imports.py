"""The import graph of the engine's packages: no cycles, and ``analytic`` never imports ``verify``.

The graph is built from the source with :mod:`ast` (every ``import`` statement, also those inside
functions, since a lazy import is still a dependency): a node per module of ``paramres``,
``analytic``, ``verify`` and ``reports``, an edge for every import of another of them.
"""

from __future__ import annotations

import ast
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
PACKAGES = ("paramres", "analytic", "verify", "reports")

#: edges not yet removed, each with the change that removes it (none left: the double grid's
#: fallback imports ``verify.certified``, the certified method alone, not the dispatcher)
KNOWN: set[tuple[str, str]] = set()


def _module_name(path: Path) -> str:
    parts = list(path.relative_to(ROOT).with_suffix("").parts)
    if parts[-1] == "__init__":
        parts = parts[:-1]
    return ".".join(parts)


def import_graph() -> dict[str, set[str]]:
    mods = {}
    for pkg in PACKAGES:
        for path in (ROOT / pkg).rglob("*.py"):
            mods[_module_name(path)] = path
    graph = {m: set() for m in mods}
    for name, path in mods.items():
        package = name if path.name == "__init__.py" else name.rpartition(".")[0]
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            if isinstance(node, ast.Import):
                targets = [a.name for a in node.names]
            elif isinstance(node, ast.ImportFrom):
                if node.level:
                    base = package.split(".")[: len(package.split(".")) - node.level + 1]
                    mod = ".".join(base + ([node.module] if node.module else []))
                else:
                    mod = node.module
                targets = [mod] + [f"{mod}.{a.name}" for a in node.names]
            else:
                continue
            for t in targets:
                if t in mods and t != name:
                    graph[name].add(t)
    return graph


def cycles(graph: dict[str, set[str]]) -> list[list[str]]:
    """The strongly connected components with more than one module (Tarjan)."""
    index, low, stack, on, out = {}, {}, [], set(), []
    counter = [0]

    def visit(v):
        index[v] = low[v] = counter[0]
        counter[0] += 1
        stack.append(v)
        on.add(v)
        for w in sorted(graph[v]):
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in on:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            comp = []
            while True:
                w = stack.pop()
                on.discard(w)
                comp.append(w)
                if w == v:
                    break
            if len(comp) > 1:
                out.append(sorted(comp))

    for v in sorted(graph):
        if v not in index:
            visit(v)
    return out


def test_the_cycle_finder_finds_a_cycle():
    assert cycles({"a": {"b"}, "b": {"c"}, "c": {"a"}, "d": {"a"}}) == [["a", "b", "c"]]
    assert cycles({"a": {"b"}, "b": set()}) == []


def test_the_graph_sees_lazy_and_relative_imports():
    g = import_graph()
    assert "verify.certified" in g["verify.solve"]  # relative, at module level
    assert "verify.certified" in g["verify.auto"]  # inside a function


def test_no_import_cycles():
    g = import_graph()
    for a, b in KNOWN:
        assert b in g[a], f"{a} no longer imports {b}: drop it from KNOWN"
        g[a].discard(b)
    assert cycles(g) == []


def test_analytic_never_imports_verify_or_reports():
    g = import_graph()
    bad = sorted(
        (a, b)
        for a, targets in g.items()
        if a.split(".")[0] == "analytic"
        for b in targets
        if b.split(".")[0] in ("verify", "reports")
    )
    assert bad == []
