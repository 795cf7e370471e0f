"""Atlases: certified edges, the growth-rate map and thresholds over a grid, as an
:class:`xarray.Dataset`, computed on a dask cluster and written chunk by chunk.

:func:`atlas` takes a grid of any of (order, depth ``m``, quality factor ``Q``, duty ``D``,
system) and computes on it

* **certified edges** (:func:`verify.modulation.boundary`, ball arithmetic): per point the lower
  and upper edge ``T/T0`` as the nearest double, their proven enclosures rounded outwards to
  doubles (``lower_min <= exact lower edge <= lower_max``), the offsets ``T - T_n``, the decimal
  text with ``digits`` proven digits and its bound ``|printed - exact|``;
* the **growth-rate map** ``log max|mu|`` over ``(T, m)`` for every ``(Q, D, system)``, in double
  precision (:func:`verify.growth.growth_map`), when periods ``T`` are given;
* **thresholds** with friction (:func:`verify.existence.existence`, proven by branch and bound):
  the depth where each order's interval first appears, with its enclosure, for every system and
  duty of the grid (a custom system has no depth, so it has no threshold and no place in an
  atlas; a threshold with an undecided depth range below it is left unset, NaN and empty text).

The work is cut into tasks (:data:`EDGE_CHUNK` depths of one order; blocks of rows of the growth
map; one threshold per ``(system, duty, Q, order)``) and run on :mod:`verify.engine` (a local
cluster sized to the machine by default, or an existing one).  Results are written as they
finish: to a Zarr store chunk by chunk, each task one Zarr chunk, its completion recorded in a
``*_done`` variable *after* its data, so an interrupted atlas resumes and skips what is done; to
netCDF (engine ``h5netcdf``) through a temporary file renamed at the end.  A store is reused only
for the very same request (grid, digits, damping, version, :data:`LAYOUT`), checked before any
work; anything else is refused, so a store can never change a result.  Before any work the cost
and the memory are estimated
(:func:`estimate`) and absurd sizes refused.
"""

from __future__ import annotations

import json
import math
import os
import shutil
import tempfile
import time
from dataclasses import asdict, dataclass
from fractions import Fraction
from pathlib import Path

import mpmath
import numpy as np

from .inputs import (
    InputError,
    as_damping,
    as_depth,
    as_digits,
    as_orders,
    as_period,
    as_quality,
    as_range,
    as_system,
)
from .params import exact_fraction

__all__ = [
    "Request",
    "Estimate",
    "request",
    "estimate",
    "edge_seconds",
    "atlas",
    "EDGE_CHUNK",
    "GROWTH_CHUNK_POINTS",
    "LIMITS",
]

#: depths per certified-edge task (one Zarr chunk)
EDGE_CHUNK = 16
#: growth-map points per task (one Zarr chunk, 8 MB)
GROWTH_CHUNK_POINTS = 1 << 20
#: Zarr format 2: every reader (zarr 2 and 3, other languages) reads it, and its variable-length
#: strings are part of the format (format 3 has no specification for them yet)
ZARR_FORMAT = 2
#: refused above these: estimated CPU seconds, and bytes (held in memory: netCDF or no output;
#: on disk: Zarr)
LIMITS = {"cpu_seconds": 1e7, "memory_bytes": 2 << 30, "store_bytes": 1 << 40}

#: CPU seconds per certified edge at ``d`` digits (measured by benchmarks/bench_atlas.py; friction
#: costs about 8 times as much), per growth point, per threshold proof
_EDGE_SECONDS = (5e-4, 4e-6)
_FRICTION_FACTOR = 8.0
_GROWTH_SECONDS = 1e-7
_THRESHOLD_SECONDS = 5.0

_EDGE_VARS = (
    "lower",
    "upper",
    "lower_min",
    "lower_max",
    "upper_min",
    "upper_max",
    "delta_lower",
    "delta_upper",
    "error_bound",
)
_EDGE_TEXT = ("lower_text", "upper_text")
_THRESHOLD_VARS = ("threshold", "threshold_min", "threshold_max")
_THRESHOLD_TEXT = ("threshold_text", "existence")
#: the layout of the variables, part of the request a stored atlas must match (2: thresholds
#: over (system, duty, Q, order))
LAYOUT = 2


def _text(x: Fraction | None) -> str:
    if x is None:
        return "none"
    return str(x.numerator) if x.denominator == 1 else f"{x.numerator}/{x.denominator}"


# ---------------------------------------------------------------------------------------------
# the request


@dataclass(frozen=True)
class Request:
    """A checked atlas request: every axis exact, as given."""

    orders: tuple
    m: tuple
    Q: tuple
    duty: tuple
    system: tuple
    damping: str
    digits: int
    T: tuple
    thresholds: bool
    edge_chunk: int

    def as_json(self) -> dict:
        """The request as JSON (exact values as fraction text) and the version that computes it:
        what a stored atlas must match to be resumed."""
        from paramres import __version__

        doc = asdict(self)
        for key in ("m", "Q", "duty", "T"):
            doc[key] = [_text(v) for v in doc[key]]
        doc["orders"] = list(self.orders)
        doc["system"] = list(self.system)
        doc["version"] = __version__
        doc["layout"] = LAYOUT
        return doc

    @property
    def friction(self) -> list[int]:
        return [i for i, q in enumerate(self.Q) if q is not None]

    @property
    def growth_rows(self) -> int:
        """Rows of ``m`` per growth task."""
        return max(1, GROWTH_CHUNK_POINTS // max(1, len(self.T)))

    def edge_tasks(self) -> list[tuple]:
        """``(s, d, q, o, c)`` indices of every certified-edge task (``c``: block of depths)."""
        nc = math.ceil(len(self.m) / self.edge_chunk)
        return [
            (s, d, q, o, c)
            for s in range(len(self.system))
            for d in range(len(self.duty))
            for q in range(len(self.Q))
            for o in range(len(self.orders))
            for c in range(nc)
        ]

    def growth_tasks(self) -> list[tuple]:
        if not self.T:
            return []
        nc = math.ceil(len(self.m) / self.growth_rows)
        return [
            (s, d, q, c)
            for s in range(len(self.system))
            for d in range(len(self.duty))
            for q in range(len(self.Q))
            for c in range(nc)
        ]

    def threshold_tasks(self) -> list[tuple]:
        """``(s, d, q, o)`` indices of every threshold task: each system and duty (every system
        of an atlas has a depth), each finite ``Q``, each order."""
        if not self.thresholds:
            return []
        return [
            (s, d, q, o)
            for s in range(len(self.system))
            for d in range(len(self.duty))
            for q in self.friction
            for o in range(len(self.orders))
        ]


def _list(value, name: str, check) -> tuple:
    """A comma-separated text or a sequence, each item checked by ``check``; unique, in order."""
    items = value.split(",") if isinstance(value, str) else value
    if items is None or isinstance(items, (int, float, Fraction)):
        items = [items]
    out = dict.fromkeys(check(i.strip() if isinstance(i, str) else i) for i in items)
    if not out:
        raise InputError(f"{name}: empty list")
    return tuple(out)


def _quality(q):
    Q = as_quality(q)
    return None if Q is None else exact_fraction(Q)


def _system_name(name):
    sysv = as_system(name)
    if not sysv.uses_depth:
        raise InputError(
            f"system {name!r}: an atlas runs over depths m, and a custom system has none; "
            "allowed: pendulum, torsion, meissner"
        )
    return sysv.name


def _duty(d):
    return as_system("pendulum", d).duty


def _range(spec, name, **kw):
    """``START:STOP:STEP`` (exact decimals, as for ``table``) or a sequence of values."""
    if isinstance(spec, str):
        return tuple(as_range(spec, name=name, **kw))
    items = list(spec) if np.iterable(spec) else [spec]
    if len(items) > kw.get("max_points", 1_000_000):
        raise InputError(f"{name}: {len(items)} values; at most {kw['max_points']} allowed")
    one = as_depth if name == "m" else as_period
    return _list(items, name, lambda v: exact_fraction(one(v)))


def request(
    orders,
    m,
    *,
    Q=None,
    duty="1/2",
    system="pendulum",
    damping="exact",
    digits=30,
    T=None,
    thresholds=True,
    edge_chunk=EDGE_CHUNK,
) -> Request:
    """Check every argument of :func:`atlas` (refusals are :class:`InputError` s naming the value
    and the allowed range) and return the :class:`Request`."""
    if isinstance(edge_chunk, bool) or not isinstance(edge_chunk, int) or not 1 <= edge_chunk:
        raise InputError(f"edge_chunk {edge_chunk!r} must be a positive integer")
    return Request(
        orders=tuple(as_orders(orders)),
        m=_range(m, "m", max_points=1_000_000),
        Q=_list("none" if Q is None else Q, "Q", _quality),
        duty=_list(duty, "duty", _duty),
        system=_list(system, "system", _system_name),
        damping=as_damping(damping),
        digits=as_digits(digits),
        T=() if T is None else _range(T, "T", high=Fraction(10**6), max_points=1_000_000),
        thresholds=bool(thresholds),
        edge_chunk=edge_chunk,
    )


# ---------------------------------------------------------------------------------------------
# cost and memory, before any work


@dataclass(frozen=True)
class Estimate:
    """What a request costs: counts, CPU seconds (on one core) and bytes of the result."""

    edges: int
    growth_points: int
    thresholds: int
    cpu_seconds: float
    result_bytes: int
    chunk_bytes: int

    def text(self) -> str:
        return (
            f"{self.edges} certified edge pairs, {self.growth_points} growth-map points, "
            f"{self.thresholds} thresholds: about {_duration(self.cpu_seconds)} of CPU time and "
            f"{_size(self.result_bytes)} of results"
        )


def _duration(s: float) -> str:
    for unit, size in (("days", 86400), ("hours", 3600), ("minutes", 60)):
        if s >= size:
            return f"{s / size:.3g} {unit}"
    return f"{s:.3g} s"


def _size(b: float) -> str:
    for unit, size in (("TB", 1e12), ("GB", 1e9), ("MB", 1e6), ("kB", 1e3)):
        if b >= size:
            return f"{b / size:.3g} {unit}"
    return f"{int(b)} bytes"


def edge_seconds(digits: int, friction: bool) -> float:
    """Estimated CPU seconds of one certified edge pair at ``digits`` digits."""
    base = _EDGE_SECONDS[0] + _EDGE_SECONDS[1] * digits
    return base * (_FRICTION_FACTOR if friction else 1.0)


def estimate(req: Request) -> Estimate:
    """The cost of ``req`` from the measured cost per edge, per growth point and per threshold
    (``benchmarks/bench_atlas.py``), and the size of its result."""
    cells = len(req.system) * len(req.duty) * len(req.Q)
    edges = cells * len(req.orders) * len(req.m)
    growth = cells * len(req.m) * len(req.T)
    nthr = len(req.threshold_tasks())
    frac = len(req.friction) / len(req.Q)
    cpu = edges * (
        (1 - frac) * edge_seconds(req.digits, False) + frac * edge_seconds(req.digits, True)
    )
    cpu += growth * _GROWTH_SECONDS + nthr * _THRESHOLD_SECONDS * (1 + req.digits / 30)
    edge_bytes = 8 * (len(_EDGE_VARS) + 1) + 2 * (req.digits + 60)
    size = edges * edge_bytes + growth * 8 + nthr * 2000
    chunk = max(req.edge_chunk * edge_bytes, req.growth_rows * len(req.T) * 8 * 3)
    return Estimate(edges, growth, nthr, cpu, int(size), int(chunk))


def check_size(req: Request, store: str | None) -> Estimate:
    """Refuse (:class:`InputError`) a request whose estimated cost or size is absurd."""
    est = estimate(req)
    if est.cpu_seconds > LIMITS["cpu_seconds"]:
        raise InputError(
            f"atlas too large: {est.text()}; at most {_duration(LIMITS['cpu_seconds'])} of CPU "
            "time allowed per run (split the grid)"
        )
    key = "store_bytes" if store == "zarr" else "memory_bytes"
    if est.result_bytes > LIMITS[key]:
        where = "in a Zarr store" if store == "zarr" else "in memory (netCDF or no output)"
        raise InputError(
            f"atlas too large: {est.text()}; at most {_size(LIMITS[key])} allowed {where}"
            + ("" if store == "zarr" else "; write a .zarr store instead")
        )
    return est


# ---------------------------------------------------------------------------------------------
# the tasks (run on the workers)


def _down(x) -> float:
    """The largest double ``<= x`` (an exact mpf or a Fraction; the comparison is exact)."""
    f = float(x)
    return (
        float(np.nextafter(f, -np.inf))
        if (Fraction(f) if isinstance(x, Fraction) else mpmath.mpf(f)) > x
        else f
    )


def _up(x) -> float:
    """The smallest double ``>= x`` (an exact mpf or a Fraction; the comparison is exact)."""
    f = float(x)
    return (
        float(np.nextafter(f, np.inf))
        if (Fraction(f) if isinstance(x, Fraction) else mpmath.mpf(f)) < x
        else f
    )


def edge_task(args) -> dict:
    """Certified edges of one order at a block of depths (a worker's task)."""
    from .modulation import boundary

    system, duty, Q, damping, digits, order, ms = args
    nums = {k: np.full(len(ms), np.nan) for k in _EDGE_VARS}
    texts = {k: np.full(len(ms), "", dtype=object) for k in _EDGE_TEXT}
    exists = np.zeros(len(ms), dtype=np.int8)
    for j, m in enumerate(ms):
        b = boundary(order, m, Q=Q, damping=damping, digits=digits, system=system, duty=duty)
        if not b.exists:
            continue
        exists[j] = 1
        doc = b.as_json()
        nums["lower"][j], nums["upper"][j] = float(b.lower), float(b.upper)
        nums["delta_lower"][j], nums["delta_upper"][j] = float(b.delta_lower), float(b.delta_upper)
        nums["lower_min"][j], nums["lower_max"][j] = (
            _down(b.lower_enclosure[0]),
            _up(b.lower_enclosure[1]),
        )
        nums["upper_min"][j], nums["upper_max"][j] = (
            _down(b.upper_enclosure[0]),
            _up(b.upper_enclosure[1]),
        )
        bound = doc["error_bound"]
        nums["error_bound"][j] = _up(mpmath.mpf(bound)) if bound is not None else np.nan
        texts["lower_text"][j], texts["upper_text"][j] = doc["lower"], doc["upper"]
    return {**nums, **texts, "exists": exists}


def growth_task(args) -> np.ndarray:
    """A block of rows of the growth-rate map (a worker's task)."""
    from .growth import growth_map

    system, duty, Q, damping, tau, m = args
    return growth_map(tau, m, None if Q is None else float(Q), damping, system=system, duty=duty)


def threshold_task(args) -> dict:
    """The first depth where the interval of one order appears with friction ``Q``, proven
    (unset when no interval appears, or when a depth range below it is undecided, so that the
    value is never claimed as the lowest without a proof)."""
    from .existence import existence

    system, duty, order, Q, damping, digits = args
    ex = existence(order, Q, system=system, duty=duty, damping=damping, digits=min(digits, 30))
    out = dict.fromkeys(_THRESHOLD_VARS, np.nan)
    out["threshold_text"] = ""
    out["existence"] = json.dumps(ex.as_json())
    first = next((t for t in ex.thresholds if t.appears), None)
    if first is not None and any(
        Fraction(u[0]) < Fraction(first.enclosure[0]) for u in ex.undecided
    ):
        first = None
    if first is not None:
        lo, hi = first.enclosure
        out["threshold"] = float(first.value)
        out["threshold_min"], out["threshold_max"] = _down(Fraction(lo)), _up(Fraction(hi))
        out["threshold_text"] = first.text()
    return out


def _task_args(req: Request, kind: str, idx: tuple):
    if kind == "edges":
        s, d, q, o, c = idx
        ms = req.m[c * req.edge_chunk : (c + 1) * req.edge_chunk]
        return (req.system[s], req.duty[d], req.Q[q], req.damping, req.digits, req.orders[o], ms)
    if kind == "growth":
        s, d, q, c = idx
        rows = req.growth_rows
        m = np.array([float(x) for x in req.m[c * rows : (c + 1) * rows]])
        tau = np.array([float(t) for t in req.T])
        return (req.system[s], req.duty[d], req.Q[q], req.damping, tau, m)
    s, d, q, o = idx
    return (req.system[s], req.duty[d], req.orders[o], req.Q[q], req.damping, req.digits)


_TASKS = {"edges": edge_task, "growth": growth_task, "thresholds": threshold_task}


# ---------------------------------------------------------------------------------------------
# the dataset


def _attrs(long_name: str, units: str | None = "1", **extra) -> dict:
    out = {"long_name": long_name}
    if units is not None:
        out["units"] = units
    out.update(extra)
    return out


_VAR_ATTRS = {
    "lower": _attrs("lower edge T-/T0 of the interval of instability (nearest double)"),
    "upper": _attrs("upper edge T+/T0 of the interval of instability (nearest double)"),
    "lower_min": _attrs("proven lower bound of the lower edge T-/T0 (rounded down)"),
    "lower_max": _attrs("proven upper bound of the lower edge T-/T0 (rounded up)"),
    "upper_min": _attrs("proven lower bound of the upper edge T+/T0 (rounded down)"),
    "upper_max": _attrs("proven upper bound of the upper edge T+/T0 (rounded up)"),
    "delta_lower": _attrs("lower edge minus the order's tuning, (T- - T_n)/T0"),
    "delta_upper": _attrs("upper edge minus the order's tuning, (T+ - T_n)/T0"),
    "error_bound": _attrs("bound of |printed - exact| of the four certified texts (rounded up)"),
    "lower_text": _attrs("lower edge T-/T0, every printed digit proven", None),
    "upper_text": _attrs("upper edge T+/T0, every printed digit proven", None),
    "exists": _attrs(
        "whether the interval of instability exists",
        None,
        flag_values=np.array([0, 1], dtype=np.int8),
        flag_meanings="absent exists",
    ),
    "growth": _attrs(
        "growth rate per modulation period, log max|Floquet multiplier| (double precision)"
    ),
    "threshold": _attrs("lowest depth m where the interval appears with friction"),
    "threshold_min": _attrs("proven lower bound of the threshold depth (rounded down)"),
    "threshold_max": _attrs("proven upper bound of the threshold depth (rounded up)"),
    "threshold_text": _attrs("threshold depth, every printed digit proven", None),
    "existence": _attrs("the proven depth ranges where the interval exists (JSON)", None),
    "edges_done": _attrs("certified-edge chunk written (1) or not yet (0)", None),
    "growth_done": _attrs("growth-map chunk written (1) or not yet (0)", None),
    "thresholds_done": _attrs("threshold written (1) or not yet (0)", None),
}


def _coords(req: Request) -> dict:
    import xarray as xr

    def coord(dim, values, long_name, units="1", **extra):
        return xr.Variable(dim, np.asarray(values), _attrs(long_name, units, **extra))

    return {
        "system": coord("system", list(req.system), "member of the two-level family", None),
        "duty": coord(
            "duty",
            [float(d) for d in req.duty],
            "duty D: fraction of the period spent in phase 1",
            exact=",".join(_text(d) for d in req.duty),
        ),
        "Q": coord(
            "Q",
            [math.inf if q is None else float(q) for q in req.Q],
            "quality factor omega0/(2 gamma) (inf: no friction)",
            exact=",".join(_text(q) for q in req.Q),
        ),
        "order": coord("order", list(req.orders), "order n of the parametric resonance", None),
        "m": coord(
            "m",
            [float(x) for x in req.m],
            "modulation depth m (nearest double; the edges are computed at the exact decimal)",
        ),
        **(
            {"T": coord("T", [float(t) for t in req.T], "modulation period T/T0 (growth map)")}
            if req.T
            else {}
        ),
    }


def _shapes(req: Request) -> dict:
    """Variable -> (dims, shape, dtype, zarr chunks)."""
    S, D, Qn, O, M = len(req.system), len(req.duty), len(req.Q), len(req.orders), len(req.m)
    e = ("system", "duty", "Q", "order", "m")
    es, ec = (S, D, Qn, O, M), (1, 1, 1, 1, req.edge_chunk)
    out = dict.fromkeys(_EDGE_VARS, (e, es, np.float64, ec))
    out.update(dict.fromkeys(_EDGE_TEXT, (e, es, object, ec)))
    out["exists"] = (e, es, np.int8, ec)
    nce = math.ceil(M / req.edge_chunk)
    out["edges_done"] = (
        ("system", "duty", "Q", "order", "edge_chunk"),
        (S, D, Qn, O, nce),
        np.int8,
        (1, 1, 1, 1, 1),
    )
    if req.T:
        g = ("system", "duty", "Q", "m", "T")
        out["growth"] = (g, (S, D, Qn, M, len(req.T)), np.float64, (1, 1, 1, req.growth_rows, -1))
        ncg = math.ceil(M / req.growth_rows)
        out["growth_done"] = (
            ("system", "duty", "Q", "growth_chunk"),
            (S, D, Qn, ncg),
            np.int8,
            (1, 1, 1, 1),
        )
    if req.threshold_tasks():
        t, ts, tc = ("system", "duty", "Q", "order"), (S, D, Qn, O), (1, 1, 1, 1)
        out.update(dict.fromkeys(_THRESHOLD_VARS, (t, ts, np.float64, tc)))
        out.update(dict.fromkeys(_THRESHOLD_TEXT, (t, ts, object, tc)))
        out["thresholds_done"] = (t, ts, np.int8, tc)
    return out


def _fill(dtype):
    if dtype is object:
        return ""
    return 0 if dtype is np.int8 else np.nan


def _provenance(req: Request, command: str | None) -> dict:
    from paramres import __version__

    return {
        "title": "paramres atlas: regions of parametric excitation of two-level square-wave "
        "oscillators",
        "Conventions": "CF-1.10",
        "source": f"paramres {__version__}",
        "paramres_version": __version__,
        "command": command or "paramres.atlas(...)",
        "digits": req.digits,
        "damping": req.damping,
        "method": (
            "edges: verify.modulation.boundary, certified (ball arithmetic, python-flint arb); "
            "growth: verify.growth.growth_map, double precision (Floquet monodromy); "
            "thresholds: verify.existence.existence, proven by branch and bound "
            "(every system and duty; NaN where no interval appears or a lower range is undecided)"
        ),
        "date_created": time.strftime("%Y-%m-%dT%H:%M:%SZ", time.gmtime()),
        "units_note": "periods T in units of T0 = 2 pi/omega0; depth m and Q dimensionless",
        "paramres_request": json.dumps(req.as_json(), sort_keys=True),
    }


def _template(req: Request, command: str | None, lazy: bool):
    """The dataset with every value unset (NaN, 0, ""): numpy arrays, or dask arrays chunked as
    the tasks (``lazy``: for writing the metadata of a Zarr store only)."""
    import xarray as xr

    data = {}
    for name, (dims, shape, dtype, chunks) in _shapes(req).items():
        if name.endswith("_done") and not lazy:
            continue  # the completion marks belong to a Zarr store being filled
        if lazy:
            import dask.array as da

            ch = tuple(s if c == -1 else c for c, s in zip(chunks, shape, strict=True))
            from xarray.coding.strings import create_vlen_dtype

            dt = create_vlen_dtype(str) if dtype is object else dtype  # vlen strings
            arr = da.full(shape, _fill(dtype), dtype=dt, chunks=ch)
        else:
            arr = np.full(shape, _fill(dtype), dtype=dtype)
        data[name] = xr.Variable(dims, arr, _VAR_ATTRS[name])
    return xr.Dataset(data, coords=_coords(req), attrs=_provenance(req, command))


def _encoding(req: Request) -> dict:
    enc = {}
    for name, (_dims, shape, dtype, chunks) in _shapes(req).items():
        ch = tuple(s if c == -1 else c for c, s in zip(chunks, shape, strict=True))
        e = {"chunks": ch}
        if dtype is np.float64:
            e["_FillValue"] = np.nan
        enc[name] = e
    return enc


# ---------------------------------------------------------------------------------------------
# the stores


def store_kind(path) -> str:
    """``"nc"`` or ``"zarr"`` from the extension of ``path``; anything else refused."""
    suffix = Path(str(path)).suffix.lower()
    if suffix == ".nc":
        return "nc"
    if suffix == ".zarr":
        return "zarr"
    raise InputError(f"--output {str(path)!r}: the extension must be .nc (netCDF) or .zarr (Zarr)")


class _Zarr:
    """A Zarr atlas being filled: created from the template (metadata only) or reopened for the
    same request; ``write`` puts one task's values, then marks it done."""

    def __init__(self, path: Path, req: Request, command: str | None):
        import zarr

        self.path = path
        self.req = req
        if path.exists():
            self.check(path, req)
        else:
            tmp = Path(tempfile.mkdtemp(prefix=f".{path.name}.", dir=path.parent))
            try:
                _template(req, command, lazy=True).to_zarr(
                    tmp,
                    mode="w",
                    compute=False,
                    encoding=_encoding(req),
                    consolidated=True,
                    zarr_format=ZARR_FORMAT,
                )
                os.replace(tmp, path)  # the store appears whole, or not at all
            except BaseException:
                shutil.rmtree(tmp, ignore_errors=True)
                raise
        self.group = zarr.open_group(str(path), mode="r+")

    @staticmethod
    def check(path: Path, req: Request) -> None:
        """Refuse a store that is not an atlas of exactly ``req`` (grid, digits, damping,
        version)."""
        import zarr

        try:
            group = zarr.open_group(str(path), mode="r")
            stored = group.attrs.get("paramres_request")
        except Exception as exc:  # noqa: BLE001 - any unreadable store is refused the same way
            raise InputError(
                f"--output {str(path)!r} exists and is not a paramres atlas ({type(exc).__name__});"
                " remove it or choose another path"
            ) from None
        want = json.dumps(req.as_json(), sort_keys=True)
        if stored != want:
            raise InputError(
                f"--output {str(path)!r} holds an atlas of another request (grid, digits, damping "
                "or version differ); it can only be resumed with the same request: remove it or "
                "choose another path"
            )

    def done(self, kind: str) -> set:
        flags = np.asarray(self.group[f"{kind}_done"][...])
        return {tuple(int(i) for i in idx) for idx in np.argwhere(flags == 1)}

    def write(self, kind: str, idx: tuple, value) -> None:
        for name, sl, arr in _pieces(self.req, kind, idx, value):
            self.group[name][sl] = arr
        self.group[f"{kind}_done"][idx] = 1  # after the data: a chunk marked done is complete


def _pieces(req: Request, kind: str, idx: tuple, value):
    """``(variable, index, values)`` that one task's result fills."""
    if kind == "edges":
        s, d, q, o, c = idx
        sl = (s, d, q, o, slice(c * req.edge_chunk, (c + 1) * req.edge_chunk))
        for name, arr in value.items():
            yield name, sl, arr
    elif kind == "growth":
        s, d, q, c = idx
        yield "growth", (s, d, q, slice(c * req.growth_rows, (c + 1) * req.growth_rows)), value
    else:
        for name, v in value.items():
            yield name, idx, v


# ---------------------------------------------------------------------------------------------
# the driver


def atlas(
    orders,
    m,
    *,
    Q=None,
    duty="1/2",
    system="pendulum",
    damping="exact",
    digits=30,
    T=None,
    thresholds=True,
    output=None,
    scheduler=None,
    workers=None,
    edge_chunk=EDGE_CHUNK,
    progress=None,
    command=None,
    on_chunk=None,
):
    """An atlas of certified edges (and the growth map when periods ``T`` are given, and the
    thresholds where ``Q`` is finite) over the grid of ``orders`` x ``m`` x ``Q`` x ``duty`` x
    ``system``, as an :class:`xarray.Dataset`.

    Axes: ``orders`` as for ``table`` (``"1-6"``, ``"1,3"``, a list); ``m`` and ``T`` a range
    ``"START:STOP:STEP"`` (exact decimals) or a list; ``Q``, ``duty``, ``system`` a value, a list or
    comma-separated text (``Q`` ``None``/``"none"``: no friction).  ``digits`` proven digits per
    edge.  ``output`` a path ending in ``.nc`` (netCDF, written at the end through a temporary file)
    or ``.zarr`` (written chunk by chunk; an interrupted store of the same request is resumed);
    the Zarr atlas is returned lazily (:func:`xarray.open_zarr`).  ``scheduler`` an address of a
    running ``dask.distributed`` scheduler or a ``Client``; by default a local cluster of
    ``workers`` processes (one per core).  ``progress(iterable, total)`` wraps the stream of
    finished tasks; ``on_chunk(kind, index)`` is called after each task's result is stored.
    """
    from .engine import as_finished, cluster

    req = request(
        orders,
        m,
        Q=Q,
        duty=duty,
        system=system,
        damping=damping,
        digits=digits,
        T=T,
        thresholds=thresholds,
        edge_chunk=edge_chunk,
    )
    kind = None if output is None else store_kind(output)
    est = check_size(req, kind)
    path = None if output is None else Path(str(output))
    if kind == "zarr":
        _check_zarr_path(path)
        if path.exists():
            _Zarr.check(path, req)
    elif kind == "nc":
        _check_nc_path(path)
    pending = [
        ("edges", req.edge_tasks()),
        ("growth", req.growth_tasks()),
        ("thresholds", req.threshold_tasks()),
    ]
    with cluster(scheduler, workers, work_seconds=est.cpu_seconds) as client:
        # connected (or refused) before anything is written
        store = _Zarr(path, req, command) if kind == "zarr" else None
        dataset = None if store is not None else _template(req, command, lazy=False)
        jobs = []
        for k, tasks in pending:
            skip = store.done(k) if store is not None and tasks else set()
            jobs += [(k, idx) for idx in tasks if idx not in skip]
        stream = as_finished(client, _run_task, [(k, _task_args(req, k, i)) for k, i in jobs])
        if progress is not None:
            stream = progress(stream, len(jobs))
        for j, value in stream:
            k, idx = jobs[j]
            if store is not None:
                store.write(k, idx, value)
            else:
                for name, sl, arr in _pieces(req, k, idx, value):
                    dataset[name].values[sl] = arr
            if on_chunk is not None:
                on_chunk(k, idx)
    if kind == "zarr":
        import xarray as xr

        return xr.open_zarr(str(path), consolidated=True)
    if kind == "nc":
        _write_nc(dataset, path)
    return dataset


def _run_task(job):
    kind, args = job
    return _TASKS[kind](args)


def _check_zarr_path(path: Path) -> None:
    if path.exists() and not path.is_dir():
        raise InputError(f"--output {str(path)!r} exists and is not a Zarr store (a directory)")
    _probe(path)


def _check_nc_path(path: Path) -> None:
    if path.is_dir():
        raise InputError(f"--output {str(path)!r} is a directory")
    _probe(path)


def _probe(path: Path) -> None:
    """Refuse, before any work, a place where the output cannot be written: a temporary file is
    created next to it and removed at once."""
    try:
        path.parent.mkdir(parents=True, exist_ok=True)
        fd, tmp = tempfile.mkstemp(prefix=".paramres-probe.", dir=path.parent)
        os.close(fd)
        os.unlink(tmp)
    except OSError as exc:
        raise InputError(
            f"--output {str(path)!r} cannot be written: {exc.strerror or exc}"
        ) from None


def _write_nc(dataset, path: Path) -> None:
    """netCDF-4 through ``h5netcdf``, to a temporary file in the same directory renamed at the end
    (nothing half-written)."""
    path.parent.mkdir(parents=True, exist_ok=True)
    fd, tmp = tempfile.mkstemp(prefix=f".{path.name}.", suffix=".tmp", dir=path.parent)
    os.close(fd)
    try:
        enc = {}
        for name, var in dataset.data_vars.items():
            if var.dtype == np.float64:
                enc[name] = {"_FillValue": np.nan}
            elif var.dtype == object:
                enc[name] = {"dtype": str}
        dataset.to_netcdf(tmp, engine="h5netcdf", encoding=enc, invalid_netcdf=False)
        mask = os.umask(0)
        os.umask(mask)
        os.chmod(tmp, 0o666 & ~mask)
        os.replace(tmp, path)
    except BaseException:
        try:
            os.unlink(tmp)
        except FileNotFoundError:
            pass
        raise
