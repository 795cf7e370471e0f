"""Numbers from what :mod:`analytic` derived: certified high-precision boundaries, a fast
double-precision grid, existence ranges with friction, the independent Floquet route, time-domain
simulation and benchmarks.

The public names are loaded on first use (no sympy import for the numeric paths that do not need
it).
"""

from __future__ import annotations

import importlib

_API = {
    "InputError": "inputs",
    "boundary": "modulation",
    "Boundary": "solve",
    "boundary_grid": "grid",
    "boundaries_tol": "auto",
    "existence": "existence",
    "monodromy_matrix": "floquet",
    "floquet_multipliers": "floquet",
    "simulate": "timedomain",
    "Simulation": "timedomain",
}

__all__ = sorted(_API)


def __getattr__(name: str):
    try:
        module = _API[name]
    except KeyError:
        raise AttributeError(f"module 'verify' has no attribute {name!r}") from None
    value = getattr(importlib.import_module(f"{__name__}.{module}"), name)
    globals()[name] = value
    return value


def __dir__():
    return __all__
