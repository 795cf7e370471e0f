"""Speed against error: every way of computing an edge, side by side, on the same scenes.

:func:`run` measures, in one process and one run, every method the engine offers (and one it does
not) on a set of :class:`Scene` s, and compares each result with a certified reference:

**Scenes** (:func:`scenes`): orders 1-6 on a grid of depths (``"standard"``), and the hard cases --
``"tiny m"`` (``m = 1e-12``), ``"m near 1"`` (``0.999``), ``"closing"`` (order 3 at ``m = 3/5``,
order 5 at ``5/13``, where the two edges meet), ``"threshold"`` (friction, paper model, ``Q = 10``,
just above the depth where the interval appears) and ``"high order"`` (order 100).

**Methods** (:func:`methods`):

* ``series K=k`` (k = 1..8): the edges as power series in ``m`` through ``m**k``
  (:func:`analytic.expansions.edge_series`; with friction the series in the distinguished scaling
  of :mod:`analytic.thresholds`), evaluated in floats;
* ``fixed point (paper)``: the paper's iteration (eqs. 15, 26, 39, 44;
  :func:`verify.fixedpoint.iterate`) in double precision from ``Delta T = 0``, at most
  :data:`FIXED_POINT_STEPS` steps, with the paper's labels (its "lower" edge compared with the true
  lower edge);
* ``double, per point``: the float stage of the certified solver for one point
  (:func:`verify.solve.float_edges`; with friction the grid for one point);
* ``numpy grid``: :func:`verify.grid.boundary_grid` for all scenes of one friction setting in one
  call (the time is that call over the number of edges it computed);
* ``mpmath D, uncertified`` (D = 15, 30, 50, 100, 1000): Newton's method on the derived equations
  (:mod:`verify.derived`, compiled for mpmath) from the double start, the precision doubled each
  step, no proof;
* ``certified D``: :func:`verify.solve.boundary` at ``D`` digits (ball arithmetic, proven);
* ``findroot D (printed eq.)``: the peer, plain ``mpmath.findroot`` (secant) on the equation as the
  paper prints it (eq. 13 or 25; eq. 36 or 41 with friction, whose model is the paper's), in
  ``T``, from the double start, the way a user would do it by hand (:mod:`analytic.printed`);
* ``auto, tol=t``: :func:`verify.solve.boundary` with a tolerance (:mod:`verify.auto`): the method
  it chose is recorded per scene, and its error must be below ``t``.

**Timing** (:func:`median_time`): the first call computes the value and warms every cache
(derivations, compilation); then the median over several calls of the wall time and of the CPU
time of this process (the machine may be shared: the CPU time is what the call costs), each call
timed in a batch long enough for the clock when it is short.  Times are per edge (a call gives
two edges).

**Errors**: the largest relative error of the two edges ``T/T0`` against
:func:`verify.solve.boundary` at :data:`REFERENCE_DIGITS` digits; errors below
:data:`ERROR_FLOOR` are below what the reference resolves and are reported as that floor.

:func:`BenchResult.summary` gives one row per method (median time per edge over the scenes,
largest error), :func:`pareto` the time-against-error points and which of them are on the Pareto
front (no other method both faster and more accurate); :func:`BenchResult.targets` checks the
targets of the solver (grid of 6 orders x 1000 depths within 10 ms, certified 50 digits within
1 ms, certified no slower than plain findroot at 1000 digits) from measurements of the same run;
:func:`auto_ratios` measures the automatic choice against the certified route at the digits the
same tolerance needs, for one point and for whole tables, interleaved (:func:`interleaved`:
alternating calls, so that the drifts of a shared machine cancel in the ratio).

At tiny depths the relative error of ``T/T0`` is small for every method (``T`` is within ``O(m)``
of ``n T_av/2``, ``O(m^2)`` for even orders); the offsets ``T - n T_av/2`` are what only the
certified route keeps to full relative accuracy there.
"""

from __future__ import annotations

import datetime
import math
import os
import platform
import statistics
import time
from collections.abc import Callable, Iterable
from dataclasses import asdict, dataclass, field
from fractions import Fraction
from functools import cache

import mpmath
import numpy as np

from verify.derived import backend
from verify.params import normal_params

__all__ = [
    "Scene",
    "Method",
    "Measurement",
    "BenchResult",
    "REFERENCE_DIGITS",
    "DIGITS",
    "SERIES_K",
    "TOLERANCES",
    "ERROR_FLOOR",
    "FIXED_POINT_STEPS",
    "scenes",
    "methods",
    "median_time",
    "machine",
    "run",
    "pareto",
    "interleaved",
    "auto_ratios",
]

#: digits of the certified reference every error is measured against
REFERENCE_DIGITS = 60
#: errors below this are below the reference's resolution
ERROR_FLOOR = 1e-58
#: precisions of the mpmath methods
DIGITS = (15, 30, 50, 100, 1000)
#: orders of the series
SERIES_K = tuple(range(1, 9))
#: tolerances of the automatic choice
TOLERANCES = ("1e-8", "1e-13", "1e-40")
#: the paper's iteration is stopped after this many steps (counted as not converging)
FIXED_POINT_STEPS = 2000


class NotApplicable(Exception):
    """The method does not apply to the scene (e.g. a printed equation without friction)."""


# ---------------------------------------------------------------------------------------------
# scenes


@dataclass(frozen=True)
class Scene:
    """One order and depth (and friction): ``group`` is ``"standard"`` or the hard case."""

    order: int
    m: Fraction
    Q: Fraction | None = None
    damping: str = "exact"
    group: str = "standard"

    @property
    def name(self) -> str:
        m = self.m
        mt = f"{m.numerator}/{m.denominator}" if m.denominator > 1000 else _decimal(m)
        if m.numerator == 1 and m.denominator >= 10**6:
            mt = f"1e-{len(str(m.denominator)) - 1}"
        fr = "" if self.Q is None else f", Q = {self.Q} ({self.damping})"
        return f"n = {self.order}, m = {mt}{fr}"

    def as_json(self) -> dict:
        return {
            "order": self.order,
            "m": str(self.m),
            "Q": None if self.Q is None else str(self.Q),
            "damping": self.damping,
            "group": self.group,
            "name": self.name,
        }


def _decimal(x: Fraction) -> str:
    text = f"{float(x):.6g}"
    return text if Fraction(text) == x else f"{x.numerator}/{x.denominator}"


#: depths of the standard scenes (full run, quick run)
STANDARD_DEPTHS = ("0.001", "0.01", "0.05", "0.1", "0.2", "0.3", "0.5", "0.7", "0.9")
QUICK_DEPTHS = ("0.01", "0.3")


def scenes(quick: bool = False) -> list[Scene]:
    """The standard scenes (orders 1-6 on :data:`STANDARD_DEPTHS`, or :data:`QUICK_DEPTHS` with
    ``quick``) and the hard cases."""
    depths = QUICK_DEPTHS if quick else STANDARD_DEPTHS
    out = [Scene(n, Fraction(m)) for n in range(1, 7) for m in depths]
    F = Fraction
    hard = [
        Scene(2, F(1, 10**12), group="tiny m"),
        Scene(1, F(999, 1000), group="m near 1"),
        Scene(3, F(3, 5), group="closing"),
        Scene(1, F(55, 1000), F(10), "paper", group="threshold"),
        Scene(100, F(1, 100), group="high order"),
    ]
    if not quick:
        hard += [
            Scene(1, F(1, 10**12), group="tiny m"),
            Scene(2, F(999, 1000), group="m near 1"),
            Scene(5, F(5, 13), group="closing"),
            Scene(2, F(27, 100), F(10), "paper", group="threshold"),
            Scene(100, F(3, 10), group="high order"),
        ]
    return out + hard


# ---------------------------------------------------------------------------------------------
# methods


@dataclass(frozen=True)
class Method:
    """A way of computing both edges: ``prepare(scene)`` returns a call without arguments giving
    ``(lower, upper)`` (or raises :class:`NotApplicable`).  ``labelled``: the values carry the
    method's own edge labels (not sorted before the comparison)."""

    name: str
    family: str
    prepare: Callable[[Scene], Callable[[], tuple]] = field(repr=False)
    digits: int | None = None
    labelled: bool = False


def methods(quick: bool = False) -> list[Method]:
    """Every method of the comparison (see the module text), cheapest families first."""
    out = [Method(f"series K={k}", "series", lambda s, k=k: _series(s, k, quick)) for k in SERIES_K]
    out.append(Method("fixed point (paper)", "fixed point", _fixed_point, labelled=True))
    out.append(Method("double, per point", "double", _double))
    out.append(Method("numpy grid", "grid", _grid_placeholder))
    for d in DIGITS:
        out.append(Method(f"mpmath {d}, uncertified", "mpmath", lambda s, d=d: _newton(s, d), d))
    for d in DIGITS:
        out.append(Method(f"certified {d}", "certified", lambda s, d=d: _certified(s, d), d))
    for d in DIGITS:
        out.append(
            Method(f"findroot {d} (printed eq.)", "findroot", lambda s, d=d: _findroot(s, d), d)
        )
    for t in TOLERANCES:
        out.append(Method(f"auto, tol={t}", "auto", lambda s, t=t: _auto(s, t)))
    return out


def _series(scene: Scene, K: int, quick: bool):
    if scene.Q is None:
        from verify.auto import series_value

        m, n = float(scene.m), scene.order
        series_value(n, K, m)  # coefficients derived and cached here, not in the timing
        return lambda: series_value(n, K, m)
    if quick and K > 3:
        raise NotApplicable("friction series above K = 3 are derived in full runs only")
    fn = _friction_series(scene.order, K, scene.Q, scene.damping)
    m = float(scene.m)

    def call():
        a, b = fn(m, math.pi)
        return (min(a, b), max(a, b))

    return call


@cache
def _friction_series(order: int, K: int, Q: Fraction, damping: str):
    """The edges near the threshold through ``m**K`` (:func:`analytic.expansions.edge_series`
    with ``Q``), compiled for floats with ``pi`` as an argument."""
    import sympy as sp

    from analytic.expansions import edge_series
    from analytic.model import S
    from verify.derived import Form

    es = edge_series(order, K, Q=Q, damping=damping)
    P = sp.Symbol("P", positive=True)
    exprs = tuple(e.subs(sp.pi, P) for e in (es.lower, es.upper))
    return Form(f"series K={K} with friction", (S.m, P), exprs).compiled("math", (0, 1))


def _fixed_point(scene: Scene):
    from verify.fixedpoint import iterate
    from verify.params import halves

    if scene.Q is not None and not halves(scene.m, scene.Q, scene.damping).normal:
        raise NotApplicable("the paper's iteration needs both halves under-damped")
    n, damped = scene.order, scene.Q is not None
    Qf = None if scene.Q is None else float(scene.Q)
    P = normal_params(float(scene.m), Qf, scene.damping, backend("numpy"))

    def call():
        out = []
        for s in (-1, 1):  # the paper's lower (s = -1) and upper edge
            th, conv, imag, _k = iterate(
                n, P, s, damped=damped, name="numpy", tol=1e-15, max_iter=FIXED_POINT_STEPS
            )
            if not bool(conv):
                raise ArithmeticError("imaginary" if bool(imag) else "no convergence")
            out.append(float((n / 2 + th / math.pi) / P.w))
        return tuple(out)

    return call


def _double(scene: Scene):
    if scene.Q is None:
        from verify.undamped import float_edges

        n, m = scene.order, scene.m
        return lambda: float_edges(n, m)
    from verify.grid import boundary_grid

    args = ([scene.order], [float(scene.m)])
    kw = {"Q": scene.Q, "damping": scene.damping}
    return lambda: tuple(float(v) for v in boundary_grid(*args, **kw)[0, :, 0])


def _grid_placeholder(scene: Scene):  # pragma: no cover - the grid is timed per friction setting
    raise NotApplicable("timed for all scenes at once")


def _certified(scene: Scene, digits: int):
    from verify.solve import boundary

    def call():
        b = boundary(scene.order, scene.m, Q=scene.Q, damping=scene.damping, digits=digits)
        if not b.exists:
            raise ArithmeticError("no interval")
        return (b.lower, b.upper)

    return call


def _auto(scene: Scene, tol: str):
    from verify.solve import boundary

    def call():
        b = boundary(scene.order, scene.m, Q=scene.Q, damping=scene.damping, tol=tol)
        if not b.exists:
            raise ArithmeticError("no interval")
        return (b.lower, b.upper, b.method)

    return call


def _start(scene: Scene) -> tuple[float, float]:
    from verify.grid import boundary_grid

    Q = scene.Q
    lo, hi = boundary_grid([scene.order], [float(scene.m)], Q=Q, damping=scene.damping)[0, :, 0]
    if not (math.isfinite(lo) and math.isfinite(hi)):
        raise ArithmeticError("no double start")
    return float(lo), float(hi)


def _newton(scene: Scene, digits: int):
    """Newton on the derived equation in ``theta`` from the double start, the precision doubled
    each step (parameters computed once, at the final precision); uncertified.  Without friction
    each edge equation is solved for its own root (the start decides which equation belongs to
    which double edge); with friction the indicator from each double edge."""
    from analytic.stitching import Parity
    from verify.derived import edge_equation, indicator
    from verify.params import form_for

    n = scene.order
    if scene.Q is not None and form_for(scene.m, scene.Q, scene.damping)[0] != "normal":
        raise NotApplicable("trace-form regimes are not in the comparison")
    parity = Parity.of(n)
    mp = backend("mpmath")
    bits = int(digits * math.log2(10)) + 20
    if scene.Q is None:
        fn = edge_equation(parity).compiled("mpmath", (0, 1))
        sgn = -1 if (n // 2) % 2 else 1
    else:
        fn = indicator(parity).compiled("mpmath", (0, 1))

    def call():
        starts = _float_start(scene) if scene.Q is None else _start(scene)  # part of the method
        with mpmath.workprec(bits + 10):
            P = normal_params(scene.m, scene.Q, scene.damping, mp)
            c = mpmath.pi * n / 2
        if scene.Q is None:
            args = [(sgn, e, P.r, P.beta) for e in (1, -1)]
            with mpmath.workprec(53):
                th = [mpmath.pi * P.w * mpmath.mpf(T) - c for T in starts]
                res = [[abs(fn(t, c, *a)[0]) for a in args] for t in th]
            keep = res[0][0] + res[1][1] <= res[0][1] + res[1][0]
            jobs = (
                [(th[0], args[0]), (th[1], args[1])]
                if keep
                else [(th[0], args[1]), (th[1], args[0])]
            )
        else:
            with mpmath.workprec(53):
                jobs = [
                    (mpmath.pi * P.w * mpmath.mpf(T) - c, (P.r2, P.u, P.beta, P.g)) for T in starts
                ]
        out = []
        for theta, a in jobs:
            prec = 53
            while True:
                prec = min(2 * prec, bits)
                with mpmath.workprec(prec + 10):
                    f, d = fn(theta, c, *a)
                    theta = theta - f / d
                if prec >= bits:
                    break
            with mpmath.workprec(bits + 10):
                f, d = fn(theta, c, *a)  # one more step at the full precision
                theta = theta - f / d
                out.append((mpmath.mpf(n) / 2 + theta / mpmath.pi) / P.w)
        return (min(out), max(out))

    return call


def _float_start(scene: Scene):
    from verify.undamped import float_edges

    if float(scene.m) > 0.95:
        return _start(scene)
    return float_edges(scene.order, scene.m)


@cache
def _printed_residual(odd: bool, damped: bool):
    """``lhs - rhs`` of the printed eq. 13 / 25 (36 / 41 with friction) as an mpmath function of
    ``(T, m, Q, s)``, ``s = +-1`` the printed ``\\pm`` (the other edge), units ``T0 = 1``."""
    import sympy as sp

    from analytic.model import S
    from analytic.printed import printed
    from analytic.reductions import PM

    label = {(True, False): "13", (False, False): "25", (True, True): "36", (False, True): "41"}
    eq = printed()[label[odd, damped]][0]
    s = sp.Symbol("s")
    expr = eq.lhs - eq.rhs
    if not damped:
        expr = (eq.lhs - s * eq.rhs).subs(PM, 1)
    else:
        expr = expr.subs(PM, s)
    w1 = S.omega0 / sp.sqrt(1 + S.m)
    w2 = S.omega0 / sp.sqrt(1 - S.m)
    expr = expr.subs(
        {
            S.q: ((1 + S.m) / (1 - S.m)) ** sp.Rational(3, 2),
            S.omega_av: (S.omega1 + S.omega2) / 2,
            S.Domega: S.omega2 - S.omega1,
            S.p: sp.exp(-S.gamma * S.T),
        }
    )
    expr = expr.subs({S.omega1: w1, S.omega2: w2, S.gamma: S.omega0 / (2 * S.Q)})
    expr = expr.subs(S.omega0, 2 * sp.pi)
    return sp.lambdify((S.T, S.m, S.Q, s), expr, modules="mpmath")


def _findroot(scene: Scene, digits: int):
    if scene.Q is not None and scene.damping != "paper":
        raise NotApplicable("the paper prints the friction equations for its own model only")
    f = _printed_residual(scene.order % 2 == 1, scene.Q is not None)
    starts = _start(scene)

    def call():
        out = []
        with mpmath.workdps(digits):
            m = mpmath.mpf(scene.m.numerator) / scene.m.denominator
            Q = None if scene.Q is None else mpmath.mpf(scene.Q.numerator) / scene.Q.denominator
            x0 = [mpmath.mpf(T) for T in starts]
            # the printed equation and its other sign, one for each double edge
            res = [[abs(f(x, m, Q, s)) for s in (1, -1)] for x in x0]
            signs = (1, -1) if res[0][0] + res[1][1] <= res[0][1] + res[1][0] else (-1, 1)
            for x, s in zip(x0, signs, strict=True):
                root = mpmath.findroot(lambda T, s=s: f(T, m, Q, s), x)
                if isinstance(root, mpmath.mpc):  # the square root of eq. 36/41 went negative
                    if abs(root.imag) > abs(root.real) * mpmath.eps * 2**10:
                        raise ArithmeticError(f"complex root {mpmath.nstr(root, 5)}")
                    root = root.real
                out.append(root)
        return (min(out), max(out))

    return call


# ---------------------------------------------------------------------------------------------
# timing


def median_time(
    fn: Callable[[], object], *, runs: int, budget: float, first: float
) -> tuple[float, float, int]:
    """Median wall and CPU time (seconds) of one call of ``fn`` over up to ``runs`` timed runs
    after the caller's warm-up call (which took ``first`` seconds), stopping early when ``budget``
    seconds are spent (at least one run; three if they fit in the budget).  A call shorter than
    0.2 ms is timed in batches of many calls.  Returns ``(wall, cpu, calls)``."""
    batch = 1 if first >= 2e-4 else min(2000, max(1, int(2e-4 / max(first, 1e-7))))
    walls, cpus = [], []
    start = time.perf_counter()
    while len(walls) < runs:
        w, c = time.perf_counter(), time.process_time()
        for _ in range(batch):
            fn()
        walls.append((time.perf_counter() - w) / batch)
        cpus.append((time.process_time() - c) / batch)
        spent = time.perf_counter() - start
        if spent > budget and (len(walls) >= 3 or spent + walls[-1] * batch > 2 * budget):
            break
    return statistics.median(walls), statistics.median(cpus), len(walls) * batch


def machine() -> dict:
    """What the measurements were taken on (no host names)."""
    cpu = platform.processor() or platform.machine()
    try:
        with open("/proc/cpuinfo", encoding="utf-8") as fh:
            for line in fh:
                if line.startswith("model name"):
                    cpu = line.split(":", 1)[1].strip()
                    break
    except OSError:
        pass
    import flint

    from verify.result import _compiled_row

    return {
        "cpu": cpu,
        "cores": os.cpu_count(),
        "system": f"{platform.system()} {platform.machine()}",
        "python": platform.python_version(),
        "numpy": np.__version__,
        "mpmath": mpmath.__version__,
        "python-flint": getattr(flint, "__version__", "?"),
        # the digits of a table's rows in C (verify._digits), or the Python loop alone
        "compiled digits": _compiled_row is not None,
    }


# ---------------------------------------------------------------------------------------------
# measurements


@dataclass
class Measurement:
    """One method on one scene: median seconds per edge (wall, CPU), the largest relative error of
    the two edges (``None`` if it gave no value), why it failed, and the method the automatic
    choice used."""

    method: str
    family: str
    digits: int | None
    scene: Scene
    wall: float | None = None
    cpu: float | None = None
    calls: int = 0
    error: float | None = None
    failure: str | None = None
    chosen: str | None = None
    spent: float = 0.0  # seconds this measurement took, warm-up included

    def as_json(self) -> dict:
        d = asdict(self)
        d["scene"] = self.scene.as_json()
        return d


def _error(values, ref, labelled: bool) -> float:
    with mpmath.workdps(REFERENCE_DIGITS + 10):
        vals = [mpmath.mpf(v) for v in values]
        if not labelled:
            vals = sorted(vals)
        if not all(mpmath.isfinite(v) for v in vals):
            return math.inf
        err = max(abs(v - r) / abs(r) for v, r in zip(vals, ref, strict=True))
        return max(float(err), ERROR_FLOOR)


@dataclass
class BenchResult:
    """All measurements of one run, with when and where they were taken."""

    date: str
    machine: dict
    quick: bool
    seconds: float
    measurements: list[Measurement]
    grid_target: dict
    scenes: list[Scene]
    ratios: list = field(default_factory=list)

    def summary(self) -> list[dict]:
        """One row per method: median over the scenes of the median time per edge (CPU and wall),
        the largest error over all scenes and over the depths ``m <= 0.01``, and the failures."""
        rows = []
        for name in dict.fromkeys(x.method for x in self.measurements):
            ms = [x for x in self.measurements if x.method == name]
            timed = [x for x in ms if x.cpu is not None]
            errs = [x.error for x in ms if x.error is not None]
            small = [x.error for x in ms if x.error is not None and x.scene.m <= Fraction(1, 100)]
            groups = {}
            for x in ms:
                if x.error is not None:
                    groups[x.scene.group] = max(groups.get(x.scene.group, 0.0), x.error)
            rows.append(
                {
                    "method": name,
                    "family": ms[0].family,
                    "digits": ms[0].digits,
                    "seconds": statistics.median(x.cpu for x in timed) if timed else None,
                    "wall_seconds": statistics.median(x.wall for x in timed) if timed else None,
                    "error": max(errs) if errs else None,
                    "error_small_m": max(small) if small else None,
                    "error_by_group": groups,
                    "failures": sum(1 for x in ms if x.failure is not None),
                    "scenes": len(ms),
                }
            )
        return rows

    def find(self, method: str, scene: Scene) -> Measurement | None:
        for x in self.measurements:
            if x.method == method and x.scene == scene:
                return x
        return None

    def targets(self) -> list[dict]:
        """The solver's targets from this run's measurements."""
        ref = Scene(3, Fraction(3, 10))
        out = [
            {
                "name": f"numpy grid, 6 orders x {self.grid_target['depths']} depths",
                "seconds": self.grid_target["cpu"],
                "wall_seconds": self.grid_target["wall"],
                "target": 0.010,
                "unit": "s per call",
            }
        ]
        c50 = self.find("certified 50", ref)
        if c50 is not None and c50.cpu is not None:
            out.append(
                {
                    "name": "certified 50 digits, n = 3, m = 0.3 (both edges)",
                    "seconds": 2 * c50.cpu,
                    "wall_seconds": 2 * c50.wall,
                    "target": 0.001,
                    "unit": "s per call",
                }
            )
        c1000 = self.find("certified 1000", ref)
        f1000 = self.find("findroot 1000 (printed eq.)", ref)
        if c1000 and f1000 and c1000.cpu and f1000.cpu:
            out.append(
                {
                    "name": "certified / plain findroot at 1000 digits, n = 3, m = 0.3",
                    "seconds": c1000.cpu / f1000.cpu,
                    "wall_seconds": c1000.wall / f1000.wall,
                    "target": 1.0,
                    "unit": "ratio",
                }
            )
        for x in out:
            x["met"] = x["seconds"] <= x["target"]
        return out

    def comparisons(self) -> list[dict]:
        """The automatic choice against the certified route at the digits the tolerance needs,
        measured interleaved (alternating calls, median of the per-round ratios) in this run:
        single points and whole tables (:func:`auto_ratios`)."""
        return list(self.ratios)

    def as_json(self) -> dict:
        return {
            "date": self.date,
            "machine": self.machine,
            "quick": self.quick,
            "seconds": self.seconds,
            "reference_digits": REFERENCE_DIGITS,
            "time_unit": "seconds per edge, median of warm runs (CPU time of the process)",
            "error_unit": "largest relative error of T/T0 against the certified reference",
            "methods": self.summary(),
            "targets": self.targets(),
            "comparisons": self.comparisons(),
            "pareto": {key: pareto(self, key) for key in ("all", "small m")},
            "measurements": [x.as_json() for x in self.measurements],
        }

    def table(self) -> str:
        """The summary as aligned text."""
        head = (
            f"{'method':<28} {'CPU/edge':>10} {'wall/edge':>10} {'max error':>10} "
            f"{'m<=0.01':>10} {'failed':>7}"
        )
        lines = [head, "-" * len(head)]
        for r in self.summary():
            lines.append(
                f"{r['method']:<28} {_t(r['seconds']):>10} {_t(r['wall_seconds']):>10} "
                f"{_e(r['error']):>10} {_e(r['error_small_m']):>10} "
                f"{r['failures']:>3}/{r['scenes']:<3}"
            )
        return "\n".join(lines)

    def hard_table(self) -> str:
        """Largest error per hard-case group and method."""
        groups = [g for g in dict.fromkeys(s.group for s in self.scenes) if g != "standard"]
        head = f"{'method':<28} " + " ".join(f"{g:>11}" for g in groups)
        lines = [head, "-" * len(head)]
        for r in self.summary():
            cells = []
            for g in groups:
                ms = [
                    x for x in self.measurements if x.method == r["method"] and x.scene.group == g
                ]
                if all(x.failure == "n/a" for x in ms):
                    cells.append("n/a")
                elif any(x.failure not in (None, "n/a") for x in ms):
                    cells.append("fails")
                else:
                    cells.append(_e(r["error_by_group"].get(g)))
            lines.append(f"{r['method']:<28} " + " ".join(f"{c:>11}" for c in cells))
        return "\n".join(lines)

    def targets_text(self) -> str:
        lines = []
        for c in self.comparisons():
            lines.append(f"{c['name']:<60} {c['ratio']:>10.2f}")
        for t in self.targets():
            if t["unit"] == "ratio":
                val, tgt = f"{t['seconds']:.3f}", f"<= {t['target']:g}"
            else:
                val, tgt = _t(t["seconds"]), f"<= {_t(t['target']).strip()}"
            flag = "met" if t["met"] else "NOT met"
            lines.append(f"{t['name']:<60} {val:>10}  (target {tgt}) {flag}")
        return "\n".join(lines)


def _t(sec) -> str:
    if sec is None:
        return "-"
    if sec >= 1:
        return f"{sec:.2f} s"
    if sec >= 1e-3:
        return f"{sec * 1e3:.2f} ms"
    return f"{sec * 1e6:.1f} us"


def _e(err) -> str:
    if err is None:
        return "-"
    if err <= ERROR_FLOOR:
        return f"<{ERROR_FLOOR:.0e}"
    if math.isinf(err):
        return "inf"
    return f"{err:.1e}"


def pareto(result: BenchResult, key: str = "all") -> list[dict]:
    """Time-against-error points, one per method: median CPU time per edge and largest error
    over all scenes (``key="all"``) or over the depths ``m <= 0.01`` (``"small m"``); ``front`` is
    true for the methods no other method beats in both."""
    pts = []
    for r in result.summary():
        err = r["error"] if key == "all" else r["error_small_m"]
        if r["seconds"] is None or err is None or not math.isfinite(err):
            continue
        pts.append(
            {
                "method": r["method"],
                "family": r["family"],
                "seconds": r["seconds"],
                "error": err,
                "failures": r["failures"],
            }
        )
    pts.sort(key=lambda p: (p["seconds"], p["error"]))
    best = math.inf
    for p in pts:
        p["front"] = p["error"] < best
        best = min(best, p["error"])
    return pts


# ---------------------------------------------------------------------------------------------
# the run


def run(
    *,
    quick: bool = False,
    scene_list: Iterable[Scene] | None = None,
    method_list: Iterable[Method] | None = None,
    progress: Callable | None = None,
    runs: int | None = None,
    grid_depths: int = 1000,
    table: bool = True,
) -> BenchResult:
    """Measure every method on every scene (defaults: :func:`scenes`, :func:`methods`).

    ``progress`` wraps the iteration over the (method, scene) pairs (e.g.
    :func:`reports.output.progress`); ``runs`` timed runs per pair (default 7, quick 3);
    ``grid_depths``: depths of the grid target (6 orders); ``table``: also measure the automatic
    choice against the certified route, interleaved (:func:`auto_ratios`)."""
    from verify.solve import boundary

    began = time.perf_counter()
    sc = list(scene_list) if scene_list is not None else scenes(quick)
    ms = list(method_list) if method_list is not None else methods(quick)
    runs = runs or (3 if quick else 7)
    budget = 0.05 if quick else 0.15
    refs = {}
    for s in sc:
        b = boundary(s.order, s.m, Q=s.Q, damping=s.damping, digits=REFERENCE_DIGITS)
        if not b.exists:
            raise ValueError(f"scene {s.name}: the interval does not exist")
        refs[s] = (b.lower, b.upper)
    pairs = [(m, s) for m in ms for s in sc]
    out: list[Measurement] = []
    grid_done = set()
    it = progress(pairs) if progress is not None else pairs
    for meth, s in it:
        began_pair = time.perf_counter()
        rec = Measurement(meth.name, meth.family, meth.digits, s)
        if meth.family == "grid":
            key = (s.Q, s.damping)
            if key not in grid_done:
                grid_done.add(key)
                out.extend(
                    _grid_group(
                        meth, [x for x in sc if (x.Q, x.damping) == key], refs, runs, budget
                    )
                )
            continue
        try:
            call = meth.prepare(s)
            t0 = time.perf_counter()
            values = call()  # the warm-up run, which gives the value
            first = time.perf_counter() - t0
        except NotApplicable:
            rec.failure = "n/a"
            out.append(rec)
            continue
        except (ArithmeticError, ValueError, TypeError) as exc:
            rec.failure = f"{type(exc).__name__}: {exc}"[:200]
            out.append(rec)
            continue
        if len(values) == 3:
            rec.chosen = values[2]
            values = values[:2]
        wall, cpu, calls = median_time(call, runs=runs, budget=budget, first=first)
        rec.wall, rec.cpu, rec.calls = wall / 2, cpu / 2, calls
        rec.error = _error(values, refs[s], meth.labelled)
        rec.spent = time.perf_counter() - began_pair
        out.append(rec)
    out.sort(key=lambda x: [m.name for m in ms].index(x.method))
    gt = _grid_target(grid_depths, runs)
    rt = auto_ratios(quick=quick) if table else []
    return BenchResult(
        date=datetime.date.today().isoformat(),
        machine=machine(),
        quick=quick,
        seconds=time.perf_counter() - began,
        measurements=out,
        grid_target=gt,
        scenes=sc,
        ratios=rt,
    )


def _grid_group(meth: Method, group: list[Scene], refs, runs: int, budget: float):
    """The grid for all scenes of one friction setting in one call: orders x depths."""
    from verify.grid import boundary_grid

    s0 = group[0]
    orders = sorted({s.order for s in group})
    depths = sorted({float(s.m) for s in group})
    ms = np.array(depths)

    def call():
        return boundary_grid(orders, ms, Q=s0.Q, damping=s0.damping)

    t0 = time.perf_counter()
    grid = call()
    wall, cpu, calls = median_time(call, runs=runs, budget=budget, first=time.perf_counter() - t0)
    edges = 2 * len(orders) * len(depths)
    out = []
    for s in group:
        rec = Measurement(meth.name, meth.family, meth.digits, s)
        vals = grid[orders.index(s.order), :, depths.index(float(s.m))]
        rec.wall, rec.cpu, rec.calls = wall / edges, cpu / edges, calls
        if np.all(np.isfinite(vals)):
            rec.error = _error([float(v) for v in vals], refs[s], False)
        else:
            rec.failure = "no value"
        out.append(rec)
    return out


def _grid_target(depths: int, runs: int) -> dict:
    from verify.grid import boundary_grid

    ms = np.linspace(0.001, 0.999, depths)
    orders = list(range(1, 7))
    t0 = time.perf_counter()
    boundary_grid(orders, ms)
    first = time.perf_counter() - t0
    wall, cpu, calls = median_time(
        lambda: boundary_grid(orders, ms), runs=max(runs, 5), budget=1.0, first=first
    )
    return {"orders": 6, "depths": depths, "wall": wall, "cpu": cpu, "calls": calls}


#: single points of the comparison of the automatic choice with the certified route
RATIO_POINTS = (
    (1, Fraction(1, 100)),
    (3, Fraction(3, 10)),
    (2, Fraction(1, 10**6)),
    (5, Fraction(1, 2)),
)
#: tables of that comparison: orders 1-6 at depths 0.05, 0.10, ..., 0.95 and 0.001, ..., 0.019
TABLE_ORDERS = tuple(range(1, 7))
TABLE_DEPTHS = {
    "0.05-0.95": tuple(Fraction(k, 20) for k in range(1, 20)),
    "0.001-0.019": tuple(Fraction(k, 1000) for k in range(1, 20)),
}


def interleaved(fa: Callable[[], object], fb: Callable[[], object], rounds: int, batch: int = 1):
    """``(median of a/b, median a, median b)`` over ``rounds`` rounds, each timing ``batch``
    calls of ``fa`` then of ``fb`` (CPU time): drifts of a shared machine cancel in the ratio."""
    fa(), fb()
    ra, ta, tb = [], [], []
    for _ in range(rounds):
        t = time.process_time()
        for _ in range(batch):
            fa()
        a = (time.process_time() - t) / batch
        t = time.process_time()
        for _ in range(batch):
            fb()
        b = (time.process_time() - t) / batch
        if a > 0 and b > 0:
            ra.append(a / b)
            ta.append(a)
            tb.append(b)
    return statistics.median(ra), statistics.median(ta), statistics.median(tb)


def auto_ratios(quick: bool = False) -> list[dict]:
    """The automatic choice (:mod:`verify.auto`) against :func:`verify.solve.boundary` at the
    digits the same tolerance needs (:func:`verify.auto.certified_digits`), interleaved: for one
    point (:data:`RATIO_POINTS`, tolerances :data:`TOLERANCES`) and for whole tables (orders 1-6,
    :data:`TABLE_DEPTHS`, tolerance 1e-8: the grid gives all double values at once)."""
    from collections import Counter

    from verify.auto import boundaries_tol, certified_digits
    from verify.inputs import as_tolerance
    from verify.solve import boundary

    rounds = 15 if quick else 40
    out = []
    for tol in TOLERANCES:
        d = certified_digits(as_tolerance(tol))
        rs, chosen = [], Counter()
        for n, m in RATIO_POINTS:
            chosen[boundary(n, m, tol=tol).method] += 1
            r = interleaved(
                lambda n=n, m=m, tol=tol: boundary(n, m, tol=tol),
                lambda n=n, m=m, d=d: boundary(n, m, digits=d),
                rounds,
                batch=3,
            )
            rs.append(r)
        out.append(
            {
                "name": f"one point: auto (tol {tol}) / certified {d} digits",
                "ratio": statistics.median(r[0] for r in rs),
                "auto_seconds_per_edge": statistics.median(r[1] for r in rs) / 2,
                "certified_seconds_per_edge": statistics.median(r[2] for r in rs) / 2,
                "methods": dict(chosen),
            }
        )
    tol = "1e-8"
    d = certified_digits(as_tolerance(tol))
    for label, depths in TABLE_DEPTHS.items():
        entries = len(TABLE_ORDERS) * len(depths)
        chosen = Counter(b.method for b in boundaries_tol(TABLE_ORDERS, depths, tol=tol))
        r = interleaved(
            lambda depths=depths: boundaries_tol(TABLE_ORDERS, depths, tol=tol),
            lambda depths=depths: [boundary(n, m, digits=d) for n in TABLE_ORDERS for m in depths],
            3 if quick else 7,
        )
        out.append(
            {
                "name": f"table, orders 1-6, m = {label}: auto (tol {tol}) / certified {d} digits",
                "ratio": r[0],
                "auto_seconds_per_edge": r[1] / (2 * entries),
                "certified_seconds_per_edge": r[2] / (2 * entries),
                "methods": dict(chosen),
            }
        )
    return out
