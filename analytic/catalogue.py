"""The catalogue: every numbered formula of the paper, printed form against derived form.

A row is produced by a *provider*: a function registered with :func:`row` that builds the printed
formula (transcribed from the paper: the thing being checked), derives the same result with the
engine, decides agreement through :mod:`analytic.identity` and explains a difference.  Providers
live
in the modules listed in :data:`PROVIDERS`; :func:`catalogue` runs them all and returns the rows in
the order of the paper's equation numbers.
"""

from __future__ import annotations

import importlib
import re
from collections.abc import Callable
from dataclasses import asdict, dataclass
from functools import lru_cache

from .cache import disk_cached

__all__ = ["Row", "row", "catalogue", "PROVIDERS", "equation_key", "written", "latex"]

#: modules whose import registers providers
PROVIDERS = ("analytic.catalogue_rows", "analytic.catalogue_series")


@dataclass(frozen=True)
class Row:
    """One numbered result.

    ``status`` is ``"agrees"`` or ``"differs"``; ``printed`` and ``derived`` are LaTeX; ``how`` says
    how agreement was established (symbolic simplification to zero, or the numeric identity check
    and its size) or what the correct form is and how the printed one differs.
    """

    equation: str
    status: str
    printed: str
    derived: str
    how: str
    title: str = ""

    def _repr_html_(self) -> str:
        """The row as a small table; the formulas (LaTeX between ``$``) are left to MathJax."""
        from paramres.display import html_table

        return html_table(
            ("eq.", "status", "printed", "derived", "how"),
            [(self.equation, self.status, f"${self.printed}$", f"${self.derived}$", self.how)],
        )

    def as_json(self) -> dict:
        d = asdict(self)
        return {k: d[k] for k in ("equation", "status", "printed", "derived", "how", "title")}


_REGISTRY: dict[str, Callable[[], Row | list[Row]]] = {}


def row(equation: str):
    """Register the provider of the row(s) for ``equation`` (``"18"``, ``"10-11"``, ``"IC-15"``)."""

    def deco(fn: Callable[[], Row | list[Row]]):
        if equation in _REGISTRY:
            raise ValueError(f"two providers for equation {equation}")
        _REGISTRY[equation] = fn
        return fn

    return deco


def written(lhs, rhs):
    """The equation ``lhs = rhs`` as written, for printing or comparing (sympy's ``Eq`` without
    its attempt to decide the equation, a symbolic test that costs more than the rest of building
    it; a row's verdict comes from :mod:`analytic.identity`, never from ``Eq``)."""
    import sympy as sp

    return sp.Eq(lhs, rhs, evaluate=False)


@lru_cache(maxsize=1024, typed=True)
def latex(expr) -> str:
    """``sympy.latex(expr)``, printed once per expression (rows show the same equations more
    than once: a printed form in its own row and as the target of a cross-reference)."""
    import sympy as sp

    return sp.latex(expr)


def equation_key(label: str) -> tuple:
    """Sort key: the first number in the label, then the label (``"IC-15"`` sorts after
    ``"15"``)."""
    nums = re.findall(r"\d+", label)
    return (int(nums[0]) if nums else 10**6, 0 if label[0].isdigit() else 1, label)


@lru_cache(maxsize=1)
@disk_cached("catalogue")
def catalogue() -> tuple[Row, ...]:
    """All rows, in the order of the paper's equation numbers (cached on disk, see
    :mod:`analytic.cache`)."""
    for name in PROVIDERS:
        importlib.import_module(name)
    rows: list[Row] = []
    for label in sorted(_REGISTRY, key=equation_key):
        out = _REGISTRY[label]()
        rows.extend(out if isinstance(out, list) else [out])
    return tuple(rows)
