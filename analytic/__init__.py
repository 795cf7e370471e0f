"""Symbolic derivations (sympy): from the model to the boundary equations, their series and closings.

The public names are loaded on first use, so importing one part does not import the rest.
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
    "normal_form": "normal_form",
    "edge_factor": "normal_form",
    "order_form": "normal_form",
    "parameters": "normal_form",
    # the paper's chains of reductions, and the catalogue of numbered results
    "chains": "reductions",
    "stationary_initial_condition": "reductions",
    "catalogue": "catalogue",
    # identities
    "prove_zero": "identity",
    "prove_proportional": "identity",
    # expansions in m, thresholds with friction, closings of intervals
    "edge_series": "expansions",
    "threshold_series": "thresholds",
    "closings": "closings",
    "closed_forms": "expansions",
}

__all__ = sorted(_API)


def __getattr__(name: str):
    try:
        module = _API[name]
    except KeyError:
        raise AttributeError(f"module 'analytic' has no attribute {name!r}") from None
    value = getattr(importlib.import_module(f"{__name__}.{module}"), name)
    globals()[name] = value
    return value


def __dir__():
    return __all__
