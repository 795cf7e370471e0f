"""The registry of boundary solvers: name -> ``fn(request) -> Boundary``.

Each solver module registers itself (:func:`register_method`); the dispatcher
:func:`verify.solve.boundary` imports the solvers and looks them up here, so no solver imports the
dispatcher.  ``"certified"`` (:mod:`verify.certified`), ``"fixedpoint"`` (:mod:`verify.fixedpoint`)
and ``"auto"`` (:mod:`verify.auto`) are the built-in ones.
"""

from __future__ import annotations

from collections.abc import Callable

from .request import Request
from .result import Boundary

__all__ = ["METHODS", "register_method"]

METHODS: dict[str, Callable[[Request], Boundary]] = {}


def register_method(name: str):
    """Decorator: make ``fn(request) -> Boundary`` available as ``boundary(..., method=name)``."""

    def deco(fn):
        METHODS[name] = fn
        return fn

    return deco
