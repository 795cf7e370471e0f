"""The double grid against a plain-numpy floor, timed side by side.

The floor is the least a vectorised double grid of the undamped edges can cost, written here in
plain numpy (no engine code): the parameters of the paper's pendulum (``s = sqrt((1-m)(1+m))``,
``beta = m/(1+s)``, ``r = beta (3 + beta^2)/(1 + 3 beta^2)``, ``w = sqrt((1+s)/2)/s``), the per-edge
equation ``f(c + theta) = eps r f(beta (c + theta))`` (eq. 13 and 25 with their signs, ``f = cos``
for odd ``n``, ``sin`` for even, ``c = n pi/2``) written as ``sin(theta) - k f(beta (c + theta)) =
0``; a blended start (the fixed-point iterate ``asin(k f(beta c))`` corrected by one Newton step on
the equation linearised in ``theta``), two Halley steps on every point with the sines and cosines
from half-angle tangents (two ``tan`` per step instead of four ``sin``/``cos``), then Halley steps
on the compacted few that still move; ``T/T0 = (n/2 + theta/pi)/w``.  No input checks, no
safeguards, no special forms near ``m = 1`` or for the order-1 edge that goes to 0 (so it is less
accurate there than ours).

Ours is the public ``paramres.boundary_grid`` (input checks, the exact ``1 - m`` of each depth,
the forms for ``m -> 1``, the order-1 edge in ``x``, the error bound).

Scenes:

* ``grid 6x1000``: orders 1-6 at 1000 depths spread over (0, 1) (target 1.3x); its ``extra`` gives
  the largest relative error against the certified edges (:func:`paramres.boundary` at 25 digits)
  on depths including 1e-12 and 0.999999, for the pendulum, the torsion pendulum, the Meissner
  equation and a duty of 1/3;
* ``grid 6x1000 torsion`` / ``meissner`` / ``duty 1/3``: the other members against the same floor
  (their parameters differ, the work does not; target 1.3x);
* ``grid friction / frictionless``: the grid with friction (``Q = 7``, exact model) against the
  frictionless grid (ours both; target 4x);
* ``grid memory``: (full runs only) 10^7 edges, the peak of traced allocations (``extra``;
  target under 1 GB), timed against the floor on the same depths.

Run ``python benchmarks/floor_grid.py [--quick]`` for the ratios alone.
"""

from __future__ import annotations

import math

import numpy as np

ORDERS = (1, 2, 3, 4, 5, 6)
DEPTHS = (np.arange(1000) + 0.5) / 1000
#: depths where the error is checked (both ends of the range)
CHECK = np.array([1e-12, 1e-9, 1e-6, 1e-3, 0.05, 0.3, 0.55, 0.8, 0.95, 0.99, 0.9999, 0.999999])


def floor_grid(orders, m):
    """Both undamped edges ``T/T0`` for ``orders`` x ``m``: shape ``(len(orders), 2, len(m))``."""
    m = np.asarray(m, float)
    s = np.sqrt((1 - m) * (1 + m))
    beta = m / (1 + s)
    b2 = beta * beta
    r = beta * (3 + b2) / (1 + 3 * b2)
    w = np.sqrt((1 + s) / 2) / s
    n = np.asarray(orders, float).reshape(1, -1, 1)
    eps = np.array([1.0, -1.0]).reshape(2, 1, 1)
    odd = (n % 2) == 1
    c = n * (math.pi / 2)
    sgn = 1.0 - 2.0 * ((n // 2) % 2)  # sin(c) for odd n, cos(c) for even n
    # f(c + theta) = -sgn sin(theta) (odd), sgn sin(theta) (even): sin(theta) = k f(beta x)
    k = eps * r / np.where(odd, -sgn, sgn)
    shape = np.broadcast(k, c, beta).shape
    k, c, beta_, odd = (np.broadcast_to(a, shape).ravel() for a in (k, c, beta, odd))
    # blended start: asin(k f(beta c)), then one Newton step with f(beta x) linearised
    sb, cb = np.sin(beta_ * c), np.cos(beta_ * c)
    f0 = np.where(odd, cb, sb)
    f1 = np.where(odd, -sb, cb)
    s0 = np.clip(k * f0, -1.0, 1.0)
    th = np.arcsin(s0)
    kb = k * f1 * beta_
    th = th - (-kb * th) / (np.sqrt((1 - s0) * (1 + s0)) - kb)
    th = np.clip(th, -1.5, 1.5)
    idx = np.arange(th.size)
    t, kk, cc, bb, oo = th, k, c, beta_, odd
    for it in range(8):
        ht = np.tan(0.5 * t)
        hy = np.tan(0.5 * bb * (cc + t))
        it2, iy2 = 1 / (1 + ht * ht), 1 / (1 + hy * hy)
        st, ct = 2 * ht * it2, (1 - ht * ht) * it2
        sy, cy = 2 * hy * iy2, (1 - hy * hy) * iy2
        fy = np.where(oo, cy, sy)
        dfy = np.where(oo, -sy, cy)
        F = st - kk * fy
        F1 = ct - kk * bb * dfy
        F2 = -st + kk * bb * bb * fy
        step = F / F1
        step = step / (1 - 0.5 * step * F2 / F1)
        t = t - step
        th[idx] = t
        if it >= 1:  # after two steps on all: compact to the points still moving
            keep = np.abs(step) > 1e-9 * np.abs(cc + t)
            if not keep.any():
                break
            idx, t, kk, cc, bb, oo = idx[keep], t[keep], kk[keep], cc[keep], bb[keep], oo[keep]
    T = (n / 2 + th.reshape(shape) / math.pi) / w
    return np.stack([T.min(axis=0), T.max(axis=0)], axis=1)


def _ours(orders, m, **kw):
    import paramres

    return paramres.boundary_grid(list(orders), m, **kw)


def max_error(**kw) -> float:
    """The largest relative error of ours against the certified edges at :data:`CHECK`, taken
    from a grid of :data:`DEPTHS` and :data:`CHECK` together (the path the scenes time)."""
    import mpmath

    import paramres

    grid = _ours(ORDERS, np.concatenate([DEPTHS, CHECK]), **kw)[..., DEPTHS.size :]
    worst = 0.0
    with mpmath.workdps(40):
        for i, n in enumerate(ORDERS):
            for j, m in enumerate(CHECK):
                b = paramres.boundary(n, float(m), digits=25, **kw)
                if not b.exists:
                    if not np.isnan(grid[i, :, j]).all():
                        return math.inf
                    continue
                for k, want in ((0, b.lower), (1, b.upper)):
                    rel = abs(mpmath.mpf(float(grid[i, k, j])) - want) / abs(want)
                    worst = max(worst, float(rel))
    return worst


def _errors() -> dict:
    out = {}
    for label, kw in (
        ("pendulum", {}),
        ("torsion", {"system": "torsion"}),
        ("meissner", {"system": "meissner"}),
        ("pendulum D=1/3", {"duty": "1/3"}),
    ):
        out[f"max relative error, {label}"] = max_error(**kw)
    floor = floor_grid(ORDERS, DEPTHS)
    ours = _ours(ORDERS, DEPTHS)
    mid = (DEPTHS > 1e-3) & (DEPTHS < 0.97)  # the floor has no special forms near m = 1
    out["floor agrees with ours (max rel. difference, 1e-3 < m < 0.97)"] = float(
        np.nanmax(np.abs(floor[..., mid] / ours[..., mid] - 1))
    )
    return out


def _memory(edges: int) -> dict:
    """Peak traced memory and CPU time of ``edges`` edges (orders 1-6, depths to match)."""
    import time
    import tracemalloc

    depths = (np.arange(edges // 12) + 0.5) / (edges // 12)
    tracemalloc.start()
    t = time.process_time()
    _ours(ORDERS, depths)
    cpu = time.process_time() - t
    peak = tracemalloc.get_traced_memory()[1]
    tracemalloc.stop()
    return {
        "edges": 12 * depths.size,
        "peak_bytes": peak,
        "bytes_per_edge": peak / edges,
        "cpu_seconds": cpu,
        "ns_per_edge": 1e9 * cpu / edges,
    }


def scenes(quick: bool) -> list[dict]:
    out = [
        {
            "name": "grid 6x1000",
            "target": 1.3,
            "ours": lambda: _ours(ORDERS, DEPTHS),
            "floor": lambda: floor_grid(ORDERS, DEPTHS),
            "note": "plain numpy: half-angle tan trig, blended start, 2 Halley steps, compaction",
            "extra": _errors,
        }
    ]
    for label, kw in (
        ("torsion", {"system": "torsion"}),
        ("meissner", {"system": "meissner"}),
        ("duty 1/3", {"duty": "1/3"}),
    ):
        out.append(
            {
                "name": f"grid 6x1000 {label}",
                "target": 1.3,
                "ours": lambda kw=kw: _ours(ORDERS, DEPTHS, **kw),
                "floor": lambda: floor_grid(ORDERS, DEPTHS),
                "note": "the same floor (the pendulum's parameters; the same work)",
            }
        )
    for label, kw in (("exact", {}), ("paper", {"damping": "paper"})):
        out.append(
            {
                "name": f"grid friction Q=7 {label} / frictionless",
                "target": 4.0,
                "ours": lambda kw=kw: _ours(ORDERS, DEPTHS, Q=7, **kw),
                "floor": lambda: _ours(ORDERS, DEPTHS),
                "note": "ours with friction against ours without (same depths and orders)",
            }
        )
    if not quick:
        big = (np.arange(10**7 // 12) + 0.5) / (10**7 // 12)
        out.append(
            {
                "name": "grid 10^7 edges",
                "target": 1.3,
                "ours": lambda: _ours(ORDERS, big),
                "floor": lambda: floor_grid(ORDERS, big),
                "note": "memory: peak traced allocations of ours in extra (target < 1 GB)",
                "extra": lambda: _memory(10**7),
                "repeat": 1,
            }
        )
    return out


def _main(argv=None) -> int:  # pragma: no cover - a measurement
    import sys

    from floors import measure  # run as a script: this directory is on sys.path

    argv = argv if argv is not None else sys.argv[1:]
    quick = "--quick" in argv
    only = [a for a in argv if not a.startswith("--")]
    for sc in scenes(quick):
        if only and not any(o in sc["name"] for o in only):
            continue
        n = 3 if "10^7" in sc["name"] else (5 if quick else 9)
        a, b = measure(sc["ours"], sc["floor"], samples=n, min_time=0)
        print(
            f"{sc['name']:<40} ours {a * 1e3:9.2f} ms  floor {b * 1e3:9.2f} ms  "
            f"ratio {a / b:5.2f}  target {sc['target']}",
            flush=True,
        )
        if callable(sc.get("extra")) and "--extra" in argv:
            print("   ", sc["extra"](), flush=True)
    return 0


if __name__ == "__main__":  # pragma: no cover
    raise SystemExit(_main())
