"""Symbolic derivations (sympy): from the model to the boundary equations, their series and
closings.

The public names are loaded on first use, so importing one part does not import the rest.  Three
concepts are public as modules, because each module is named after its main function:
``analytic.normal_form`` (``normal_form.normal_form``), ``analytic.catalogue``
(``catalogue.catalogue``) and ``analytic.closings`` (``closings.closings``).
"""

from __future__ import annotations

import importlib

_API = {
    # the model
    "S": "model",
    "Damping": "model",
    "segment": "model",
    "physical": "model",
    # stitching systems and the monodromy
    "Parity": "stitching",
    "EdgeKind": "stitching",
    "general_system": "stitching",
    "edge_system": "stitching",
    "paper_system": "stitching",
    "monodromy": "stitching",
    "floquet_condition": "stitching",
    # normal form and per-edge equations
    "edge_factor": "normal_form",
    "order_form": "normal_form",
    "parameters": "normal_form",
    # the paper's chains of reductions, and the catalogue of numbered results
    "chains": "reductions",
    "stationary_initial_condition": "reductions",
    # identities
    "prove_zero": "identity",
    "prove_proportional": "identity",
    # expansions in m, thresholds with friction, closings of intervals
    "edge_series": "expansions",
    "threshold_series": "thresholds",
    "closed_forms": "expansions",
}

#: public modules (see the docstring)
_MODULES = ("normal_form", "catalogue", "closings")

__all__ = sorted(_API) + list(_MODULES)


def __getattr__(name: str):
    if name in _MODULES:
        return importlib.import_module(f"{__name__}.{name}")
    try:
        module = _API[name]
    except KeyError:
        raise AttributeError(f"module 'analytic' has no attribute {name!r}") from None
    value = getattr(importlib.import_module(f"{__name__}.{module}"), name)
    globals()[name] = value
    return value


def __dir__():
    return __all__
