"""paramres: regions of parametric excitation of an oscillator whose parameters switch as a
square wave (the pendulum of Butikov's "Pendulum with modulated length II" and its family).

The public API, loaded on first use so that ``import paramres`` is fast:

>>> import paramres
>>> b = paramres.boundary(1, "1/10", digits=20)
>>> b.as_json()["lower"], b.as_json()["upper"]
('0.45069268851530018344', '0.54548750191781203135')

``boundary`` (certified edges of one interval), ``boundary_grid`` (float64 edges on a grid),
``existence`` (depth ranges with friction), ``series`` (edges as power series in ``m``),
``crossings`` (every closing of every interval), ``catalogue`` (the paper's numbered results,
printed against derived), ``simulate`` (time-domain runs), ``report`` (the derivation report),
``multipliers`` (certified Floquet multipliers at a point), ``jump_validity`` (up to which
switching time the instantaneous jump is a good model), ``atlas`` (edges, growth map and
thresholds over a grid as an xarray dataset, computed on dask), ``explore`` (the explorer in
the browser; inline in a notebook); ``system``/``custom`` describe the
oscillator (a member of the two-level family, with its duty), taken by every function above as
``system=``.  ``boundary`` and ``multipliers`` take ``modulation="ramp", switch_time=S`` for
linear ramps of the length lasting ``S`` (units ``T0``) instead of jumps, and
``modulation="sine"`` for ``l = l0 (1 + m sin(2 pi t/T))``.

The engine lives in three packages installed beside this one, :mod:`analytic` (sympy
derivations), :mod:`verify` (numbers) and :mod:`reports` (command line and report).  Importing
:mod:`paramres` binds those names to the copies installed with it, so that a module of the same
name elsewhere on ``sys.path`` (a user's own ``verify.py``) cannot take their place; if a
different module of one of those names was imported first, the import fails and says which.
"""

from __future__ import annotations

import importlib
import importlib.machinery
import importlib.util
import sys
from pathlib import Path

__version__ = "0.1.0"

#: public name -> (module, attribute)
_API = {
    "boundary": ("verify.modulation", "boundary"),
    "boundary_grid": ("verify.grid", "boundary_grid"),
    "existence": ("verify.existence", "existence"),
    "series": ("analytic.expansions", "edge_series"),
    "crossings": ("analytic.closings", "closings"),
    "catalogue": ("analytic.catalogue", "catalogue"),
    "simulate": ("verify.timedomain", "simulate"),
    "report": ("reports.report", "build_report"),
    "multipliers": ("verify.modulation", "multipliers"),
    "jump_validity": ("verify.ramp", "jump_validity"),
    "atlas": ("verify.atlas", "atlas"),
    "explore": ("reports.explorer", "explore"),
    "system": ("analytic.system", "system"),
    "custom": ("analytic.system", "custom"),
    "System": ("analytic.system", "System"),
    "InputError": ("paramres.inputs", "InputError"),
}

__all__ = sorted(_API) + ["__version__"]

#: the engine's packages, installed beside this one
ENGINE = ("analytic", "verify", "reports")
_HOME = Path(__file__).resolve().parent.parent


def _bind_engine() -> None:
    """Import :data:`ENGINE` from :data:`_HOME` (their ``__init__`` modules are light)."""
    for name in ENGINE:
        mod = sys.modules.get(name)
        if mod is not None:
            where = getattr(mod, "__file__", None)
            if where is None or Path(where).resolve().parent.parent != _HOME:
                raise ImportError(
                    f"paramres: a module named {name!r} from {where or 'an unknown place'} was "
                    f"imported before paramres; paramres needs its own {name!r} package from "
                    f"{_HOME / name}. Rename the other module or import paramres first."
                )
            continue
        spec = importlib.machinery.PathFinder.find_spec(name, [str(_HOME)])
        if spec is None or spec.loader is None:  # pragma: no cover - a broken installation
            raise ImportError(f"paramres: its package {name!r} is missing from {_HOME}")
        module = importlib.util.module_from_spec(spec)
        sys.modules[name] = module
        try:
            spec.loader.exec_module(module)
        except BaseException:
            sys.modules.pop(name, None)
            raise


_bind_engine()


def __getattr__(name: str):
    try:
        module, attr = _API[name]
    except KeyError:
        raise AttributeError(f"module 'paramres' has no attribute {name!r}") from None
    value = getattr(importlib.import_module(module), attr)
    globals()[name] = value
    return value


def __dir__():
    return __all__
