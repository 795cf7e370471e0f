"""The explorer's JSON endpoints: each a function of the query parameters, calling the public API.

The parameters are named like the command line's options (``order``, ``m``, ``T``, ``Q``,
``damping``, ``digits``, ``system``, ``duty``, ``omega_sq``, ``jump``, ``modulation``,
``switch_time``); every value goes through :mod:`paramres.inputs` (as on the command line), then
through the explorer's own caps (:data:`LIMITS`: digits, grid sizes, orders and periods are smaller
than the command line's, so that no request can keep the server busy for long).  A bad value raises
:class:`~paramres.inputs.InputError`, which the server answers with HTTP 400 and one line of JSON.

=================  ===========================================================================
``/api/boundary``  the certified edges of one interval (:func:`verify.modulation.boundary`)
``/api/multipliers``  the certified Floquet multipliers at ``(T, m)``
                   (:func:`verify.modulation.multipliers`)
``/api/point``     what a click shows: the order whose interval is nearest to ``(T, m)``, the
                   multipliers there and the edges of that interval (the two answers above)
``/api/chart``     ``log |mu|max`` on a grid (:func:`verify.growth.growth_map`) and the edges of
                   orders ``1..N`` (:func:`verify.grid.boundary_grid`)
``/api/simulate``  a trajectory ``phi(t), phi'(t)`` (:func:`verify.timedomain.simulate`), linear
                   or nonlinear, with what the page needs to animate it
``/api/presets``   the presets of the page
=================  ===========================================================================
"""

from __future__ import annotations

import hashlib
import json
import math
from fractions import Fraction
from functools import lru_cache

from paramres.inputs import (
    InputError,
    as_damping,
    as_depth,
    as_digits,
    as_integer,
    as_number,
    as_quality,
)
from verify.inputs import as_system

__all__ = ["ENDPOINTS", "LIMITS", "PRESETS", "handle", "warm_up", "warm_up_tasks"]

#: the explorer's caps (the command line allows more; a page needs no more than this)
LIMITS = {
    "digits": (5, 100),
    "max_order": (1, 12),
    "nt": (2, 600),
    "nm": (2, 400),
    "periods": (1, 60),
    "samples": (8, 200),
    "T": (Fraction(1, 100), Fraction(20)),
}

#: the parameters every endpoint that takes an oscillator accepts
_SYSTEM = ("system", "duty", "omega_sq", "jump", "Q", "damping")


def _one(query: dict, allowed: tuple[str, ...]) -> dict[str, str]:
    """The query as ``{name: value}``: every name allowed, none repeated."""
    out = {}
    for name, values in query.items():
        if name not in allowed:
            raise InputError(
                f"unknown parameter {_short(name)!r}; allowed: {', '.join(sorted(allowed))}"
            )
        if len(values) != 1:
            raise InputError(f"parameter {name!r} is given {len(values)} times; give it once")
        out[name] = values[0]
    return out


def _short(text: str) -> str:
    text = str(text)
    return text if len(text) <= 40 else text[:30] + "..."


def _system(p: dict):
    omega_sq = p.get("omega_sq")
    return as_system(p.get("system", "pendulum"), p.get("duty", "1/2"), omega_sq, p.get("jump"))


def _depth(p: dict, sysv):
    m = p.get("m")
    if sysv.uses_depth:
        if m is None:
            raise InputError(f"system {sysv.name} needs m (a depth 0 < m < 1)")
        return as_depth(m)
    if m is not None:
        raise InputError(f"m = {_short(m)} makes no sense with system custom (it has no depth)")
    return None


def _capped(value, name: str) -> int:
    low, high = LIMITS[name]
    return as_integer(value, name=name, low=low, high=high)


def _digits(p: dict) -> int:
    """The digits asked for, within the explorer's range (every message names that range, not
    the command line's)."""
    low, high = LIMITS["digits"]
    try:
        return as_digits(p.get("digits", "30"), allowed=(low, high))
    except InputError as exc:
        raise InputError(
            str(exc)
            .replace("the allowed range", "the explorer's range")
            .replace("; allowed range", "; the explorer's range is")
            + " (the command line goes further)"
        ) from None


def _period(text, name="T") -> Fraction:
    low, high = LIMITS["T"]
    allowed = f"{float(low):g} <= T <= {float(high):g}"
    T = as_number(text, name=f"period {name}", allowed=allowed)
    if not low <= T <= high:
        raise InputError(
            f"period {name} = {_short(text)} is outside the explorer's range {allowed}"
        )
    return T


def _flag(p: dict, name: str) -> bool:
    text = str(p.get(name, "0")).strip().lower()
    if text in ("1", "true", "yes", "on"):
        return True
    if text in ("0", "false", "no", "off", ""):
        return False
    raise InputError(f"{name} {_short(text)!r} is not one of: 0, 1, true, false")


def _modulation(p: dict) -> tuple[str, str | None]:
    from paramres.inputs import MODULATIONS

    mod = p.get("modulation", "square").strip().lower()
    if mod not in MODULATIONS:
        raise InputError(f"modulation {_short(mod)!r} is not one of: {', '.join(MODULATIONS)}")
    return mod, p.get("switch_time")


def _friction(p: dict):
    Q = as_quality(p.get("Q"))
    damping = as_damping(p.get("damping", "exact"))
    return Q, damping


# ---------------------------------------------------------------------------------------------
# the endpoints


def boundary(query: dict) -> dict:
    """The certified edges of the interval ``order`` at ``m`` (as ``paramres boundary --json``)."""
    p = _one(query, ("order", "m", "digits", "modulation", "switch_time", *_SYSTEM))
    if "order" not in p:
        raise InputError("order is required (1, 2, ...)")
    return _boundary_doc(p)


def _boundary_doc(p: dict) -> dict:
    from verify.modulation import boundary as certified

    sysv = _system(p)
    n = as_integer(p["order"], name="order", low=1, high=LIMITS["max_order"][1] * 10)
    return _certified_doc(certified, n, p, sysv)


def _certified_doc(certified, first, p: dict, sysv) -> dict:
    """``certified(first, m, ...)`` (:func:`verify.modulation.boundary` or ``multipliers``) with
    the query's depth, friction, modulation and digits, as JSON (with the modulation)."""
    m = _depth(p, sysv)
    Q, damping = _friction(p)
    mod, S = _modulation(p)
    res = certified(
        first,
        m,
        Q=Q,
        damping=damping,
        digits=_digits(p),
        system=sysv,
        modulation=mod,
        switch_time=S,
    )
    doc = res.as_json()
    doc["modulation"] = mod
    if S is not None:
        doc["switch_time"] = str(S).strip()
    return doc


def multipliers(query: dict) -> dict:
    """The certified multipliers at ``(T, m)`` (as ``paramres multipliers --json``)."""
    p = _one(query, ("T", "m", "digits", "modulation", "switch_time", *_SYSTEM))
    return _multipliers_doc(p)


def _multipliers_doc(p: dict) -> dict:
    from verify.modulation import multipliers as certified

    sysv = _system(p)
    if "T" not in p:
        raise InputError("T is required (the modulation period T/T0 > 0)")
    return _certified_doc(certified, _period(p["T"]), p, sysv)


def nearest_order(T, m, Q, damping, sysv, max_order: int = 12) -> int:
    """The order whose interval (double-precision edges of :func:`verify.grid.boundary_grid` at
    ``m``) holds ``T``, else the one with the nearest edge."""
    import numpy as np

    from verify.grid import boundary_grid

    if not sysv.uses_depth:
        return 1
    orders = list(range(1, max_order + 1))
    g = boundary_grid(orders, [m], Q=_float(Q), damping=damping, system=sysv, duty=sysv.duty)
    t = float(T)
    best, dist = 1, math.inf
    for i, n in enumerate(orders):
        lo, hi = g[i, 0, 0], g[i, 1, 0]
        if np.isnan(lo) or np.isnan(hi):
            continue
        d = 0.0 if lo <= t <= hi else min(abs(t - lo), abs(t - hi))
        if d < dist:
            best, dist = n, d
    return best


def point(query: dict) -> dict:
    """What a click at ``(T, m)`` shows: the multipliers, and the edges of the nearest interval
    (``order`` chooses another)."""
    p = _one(query, ("T", "m", "order", "digits", "modulation", "switch_time", *_SYSTEM))
    mu = _multipliers_doc(p)
    sysv = _system(p)
    Q, damping = _friction(p)
    if "order" not in p:
        T = _period(p["T"])
        p["order"] = str(nearest_order(T, _depth(p, sysv), Q, damping, sysv))
    bnd = _boundary_doc({k: v for k, v in p.items() if k != "T"})
    return {"order": int(p["order"]), "multipliers": mu, "boundary": bnd}


def _float(Q):
    return None if Q is None else float(Q)


def chart(query: dict) -> dict:
    """``log |mu|max`` on ``nt`` periods x ``nm`` depths and the edges of orders ``1..max_order``;
    ``parts`` is ``growth``, ``edges`` or both (default)."""
    p = _one(
        query,
        ("tmin", "tmax", "mmin", "mmax", "nt", "nm", "max_order", "parts", *_SYSTEM),
    )
    sysv = _system(p)
    if not sysv.uses_depth:
        raise InputError("the chart needs a depth axis; system custom has none")
    Q, damping = _friction(p)
    tmin = _period(p.get("tmin", "0.2"), "tmin")
    tmax = _period(p.get("tmax", "3.2"), "tmax")
    if not tmin < tmax:
        raise InputError(f"tmin = {tmin} must be smaller than tmax = {tmax}")
    allowed_m = "0.001 <= mmin < mmax <= 0.99"
    mmin = as_number(p.get("mmin", "0.005"), name="mmin", allowed=allowed_m)
    mmax = as_number(p.get("mmax", "0.95"), name="mmax", allowed=allowed_m)
    if not (Fraction(1, 1000) <= mmin < mmax <= Fraction(99, 100)):
        raise InputError(f"mmin = {mmin}, mmax = {mmax}: the allowed range is {allowed_m}")
    nt = _capped(p.get("nt", "240"), "nt")
    nm = _capped(p.get("nm", "160"), "nm")
    max_order = _capped(p.get("max_order", "6"), "max_order")
    parts = {s.strip() for s in p.get("parts", "growth,edges").split(",")}
    if not parts or not parts <= {"growth", "edges"}:
        raise InputError(f"parts {_short(p.get('parts'))!r} is not growth, edges or both")
    Qf = _float(Q)
    return _chart(
        sysv, Qf, damping, float(tmin), float(tmax), float(mmin), float(mmax), nt, nm,
        max_order, tuple(sorted(parts)),
    )  # fmt: skip


@lru_cache(maxsize=32)
def _chart(sysv, Q, damping, tmin, tmax, mmin, mmax, nt, nm, max_order, parts) -> dict:
    import numpy as np

    tau = np.linspace(tmin, tmax, nt)
    ms = np.linspace(mmin, mmax, nm)
    doc = {
        **sysv.as_json(),
        "Q": None if Q is None else _num(Q),
        "damping": "none" if Q is None else damping,
        "T": [_num(x) for x in tau],
        "m": [_num(x) for x in ms],
        "method": "double precision (numpy), verify.growth.growth_map; edges verify.grid."
        "boundary_grid (relative error < 1e-14)",
    }
    if "growth" in parts:
        from verify.growth import growth_map

        g = growth_map(tau, ms, Q, damping, system=sysv, duty=sysv.duty)
        doc["growth"] = [[_num(x, 4) for x in row] for row in g]
    if "edges" in parts:
        key = (sysv.as_json(), Q, damping, mmin, mmax, nm, max_order)
        doc.update(_edges_cached(json.dumps(key, sort_keys=True), sysv, Q, damping, ms, max_order))
    return doc


def _edges_cached(key: str, sysv, Q, damping, ms, max_order) -> dict:
    """The edges of orders ``1..max_order`` at the depths ``ms`` (:func:`verify.grid.boundary_grid`)
    kept in the disk cache (:class:`analytic.cache.Cache`, keyed by the sources of the engine):
    the first grid of a process derives its forms with sympy for seconds, a cached one is read
    in milliseconds."""
    from analytic.cache import Cache, cache_dir

    def make() -> dict:
        from verify.grid import boundary_grid

        orders = list(range(1, max_order + 1))
        ms_edges = [float(f"{x:.12g}") for x in ms]
        e = boundary_grid(orders, ms_edges, Q=Q, damping=damping, system=sysv, duty=sysv.duty)
        return {
            "orders": orders,
            "lower": [[_num(x) for x in e[i, 0]] for i in range(len(orders))],
            "upper": [[_num(x) for x in e[i, 1]] for i in range(len(orders))],
        }

    base = cache_dir()
    name = "edges_" + hashlib.sha256(key.encode()).hexdigest()[:24]
    store = Cache(None if base is None else base / "explorer", ("analytic", "verify", "paramres"))
    return store.get(name, make)


def _num(x, digits: int = 12):
    x = float(x)
    if not math.isfinite(x):
        return None
    return float(f"{x:.{digits}g}")


def simulate(query: dict) -> dict:
    """A run at ``(T, m)`` for the animation: the sampled segments, the measured growth, and the
    parameters the page's generated propagator needs to move smoothly between samples."""
    from analytic.system import phase_regimes
    from verify.timedomain import simulate as run

    p = _one(
        query,
        ("T", "m", "order", "periods", "samples", "nonlinear", "amplitude", *_SYSTEM),
    )
    sysv = _system(p)
    if "T" not in p:
        raise InputError("T is required (the modulation period T/T0 > 0)")
    T = _period(p["T"])
    m = _depth(p, sysv)
    Q, damping = _friction(p)
    nonlinear = _flag(p, "nonlinear")
    periods = _capped(p.get("periods", "8"), "periods")
    samples = _capped(p.get("samples", "48"), "samples")
    order = p.get("order")
    if order is None:
        order = nearest_order(T, m, Q, damping, sysv)
    s = run(
        order,
        m,
        T=T,
        Q=Q,
        damping=damping,
        periods=periods,
        amplitude=p.get("amplitude", "0.1"),
        nonlinear=nonlinear,
        digits=15,
        samples=samples,
        system=sysv,
    )
    W1, W2, k = (float(x) for x in sysv.values(m))
    eff = "none" if Q is None else damping
    regimes = phase_regimes(sysv, m if m is None else Fraction(m), Q if Q is None else Fraction(Q),
                            damping)  # fmt: skip
    regimes = ["under" if r == "undamped" else r for r in regimes]
    doc = s.as_json()
    doc.update(
        {
            "model": eff,
            "omega_sq": [W1, W2],
            "jump": k,
            "duty_value": float(sysv.duty),
            "regimes": regimes,
            "Q_value": None if Q is None else float(Q),
            "segments": [
                {
                    "half": seg.half,
                    "t": [_num(x, 15) for x in seg.t],
                    "phi": [_num(x, 15) for x in seg.phi],
                    "dphi": [_num(x, 15) for x in seg.dphi],
                }
                for seg in s.segments
            ],
        }
    )
    return doc


def presets(query: dict) -> dict:
    _one(query, ())
    return {"presets": PRESETS}


#: the page's presets: the chart's options and a point to click
PRESETS = [
    {
        "id": "fig2",
        "en": "Paper, Fig. 2: orders 1-6, no friction",
        "ru": "Статья, рис. 2: порядки 1-6, без трения",
        "chart": {"system": "pendulum", "max_order": 6},
        "point": {"T": "1.45", "m": "0.3"},
    },
    {
        "id": "fig8",
        "en": "Paper, Fig. 8: friction Q = 7 (paper model)",
        "ru": "Статья, рис. 8: трение Q = 7 (модель статьи)",
        "chart": {"system": "pendulum", "Q": "7", "damping": "paper", "max_order": 4},
        "point": {"T": "0.5", "m": "0.3"},
    },
    {
        "id": "closing",
        "en": "A closing: order 3 at m = 3/5 (T1:T2 = 2:1)",
        "ru": "Смыкание: порядок 3 при m = 3/5 (T1:T2 = 2:1)",
        "chart": {"system": "pendulum", "max_order": 6},
        "point": {"T": "1.264911064067352", "m": "3/5"},
    },
    {
        "id": "threshold",
        "en": "A threshold: order 1 with Q = 5, m just above pi/(6Q)",
        "ru": "Порог: порядок 1 при Q = 5, m чуть выше pi/(6Q)",
        "chart": {"system": "pendulum", "Q": "5", "damping": "exact", "max_order": 3},
        "point": {"T": "0.5", "m": "0.12"},
    },
    {
        "id": "island",
        "en": "Q = 7: order 3 gone for 0.483 < m < 0.652, back above (exact friction)",
        "ru": "Q = 7: третий порядок исчезает при 0.483 < m < 0.652 и возвращается выше",
        "chart": {"system": "pendulum", "Q": "7", "damping": "exact", "max_order": 4},
        "point": {"T": "1.2", "m": "0.7"},
    },
    {
        "id": "torsion",
        "en": "Torsion pendulum (moment of inertia switched)",
        "ru": "Крутильный маятник (переключается момент инерции)",
        "chart": {"system": "torsion", "max_order": 6},
        "point": {"T": "0.5", "m": "0.3"},
    },
    {
        "id": "meissner",
        "en": "Meissner equation, duty 1/3 (stiffness switched)",
        "ru": "Уравнение Мейснера, скважность 1/3 (переключается жёсткость)",
        "chart": {"system": "meissner", "duty": "1/3", "max_order": 6},
        "point": {"T": "0.5", "m": "0.4"},
    },
]

#: path under ``/api/`` -> the function answering it
ENDPOINTS = {
    "boundary": boundary,
    "multipliers": multipliers,
    "point": point,
    "chart": chart,
    "simulate": simulate,
    "presets": presets,
}


def handle(name: str, query: dict) -> dict:
    """The answer of ``/api/<name>`` to the parsed ``query`` (``{name: [values]}``); raises
    :class:`InputError` for a bad request, :class:`KeyError` for an unknown endpoint."""
    return ENDPOINTS[name](query)


def warm_up_tasks() -> list:
    """Small tasks that build the derived forms the endpoints need (sympy, lambdify) and fill the
    chart cache of the presets, so that a click costs what the next ones cost; the server runs
    them when no request is waiting."""
    from .jsgen import generated_js

    q = {"T": ["1.45"], "m": ["0.3"]}
    tasks = [
        generated_js,
        lambda: chart({"parts": ["edges"]}),
        lambda: point(q),
        lambda: simulate({**q, "periods": ["2"]}),
        lambda: point({**q, "modulation": ["ramp"], "switch_time": ["0.02"]}),
    ]
    for preset in PRESETS:
        c = {k: [v] for k, v in preset["chart"].items()}
        pt = {k: [v] for k, v in {**preset["chart"], **preset["point"]}.items() if k != "max_order"}
        tasks += [
            lambda c=c: chart({**c, "parts": ["growth"]}),
            lambda c=c: chart({**c, "parts": ["edges"]}),
            lambda pt=pt: point(pt),
        ]
    return tasks


def warm_up() -> None:
    """Run :func:`warm_up_tasks` now."""
    for task in warm_up_tasks():
        task()
