"""Benchmark of the atlas (``python benchmarks/bench_atlas.py [--quick]``): not a test.

Measured side by side in one run, each against a floor written here:

* the growth-rate map, 2000 x 2000 points of the paper's system (``T/T0`` in 0.2 .. 4, ``m`` in
  0.0005 .. 0.9995), without friction and with ``Q = 7``: :func:`verify.growth.growth_map`
  against the former route (``log`` of :func:`verify.floquet.growth_factor` in blocks of rows,
  the 2 x 2 matrices stacked) and against a plain-numpy floor (four sines and cosines of the
  outer products and one ``arccosh``: what any evaluation of the map must at least do);
* the CPU cost of one certified edge pair (:func:`verify.modulation.boundary`, both edges) at
  30 digits, without friction and with ``Q = 7``, in this process;
* the memory of one task (peak of ``tracemalloc``) for a certified-edge chunk and a growth chunk;
* the atlas on a local cluster of 1 and of 2 worker processes (started and warmed first): wall
  time, the CPU time of the workers, and the speed-up.

CPU times (``time.process_time``) are what count on a shared machine: wall times depend on the
load of other processes, and both are printed.  Prints one JSON document.
"""

from __future__ import annotations

import argparse
import json
import platform
import time
import tracemalloc
from fractions import Fraction

import numpy as np


def _best(fn, repeat=3):
    """Best (CPU seconds, wall seconds) of ``repeat`` runs."""
    cpu, wall = [], []
    for _ in range(repeat):
        c, w = time.process_time(), time.perf_counter()
        fn()
        cpu.append(time.process_time() - c)
        wall.append(time.perf_counter() - w)
    return min(cpu), min(wall)


def growth_bench(n: int) -> dict:
    from verify.floquet import growth_factor
    from verify.growth import growth_map

    tau = np.linspace(0.2, 4.0, n)
    m = np.linspace(0.0005, 0.9995, n)

    def former(Q):
        out = np.empty((m.size, tau.size))
        rows = max(1, (1 << 18) // tau.size)
        for s in range(0, m.size, rows):
            g = growth_factor(m[s : s + rows, None], tau[None, :], Q, backend="numpy")
            out[s : s + rows] = np.log(g)
        return out

    def floor():
        for w in (np.sqrt(1 / (1 + m)), np.sqrt(1 / (1 - m))):
            x = np.multiply.outer(w * 2 * np.pi, tau / 2)
            np.cos(x)
            np.sin(x)
        np.arccosh(np.full((m.size, tau.size), 1.5))

    out = {"points": n * n}
    for label, Q in (("no_friction", None), ("Q7", 7.0)):
        new = _best(lambda Q=Q: growth_map(tau, m, Q))
        old = _best(lambda Q=Q: former(Q), repeat=1)
        out[label] = {
            "growth_map_cpu_s": new[0],
            "growth_map_wall_s": new[1],
            "former_cpu_s": old[0],
            "former_wall_s": old[1],
            "speedup_cpu": old[0] / new[0],
        }
    fl = _best(floor)
    out["floor_cpu_s"], out["floor_wall_s"] = fl
    out["ratio_to_floor_cpu"] = out["no_friction"]["growth_map_cpu_s"] / fl[0]
    return out


def edge_cost(count: int) -> dict:
    from verify.modulation import boundary

    ms = [Fraction(k, 100) for k in range(3, 98, max(1, 95 // count))][:count]
    out = {}
    for label, Q in (("no_friction", None), ("Q7", Fraction(7))):
        for n in (1, 3, 6):
            boundary(n, ms[0], Q=Q, digits=30)  # warm: the derivations
        c = time.process_time()
        k = 0
        for n in (1, 2, 3, 4, 5, 6):
            for m in ms:
                boundary(n, m, Q=Q, digits=30)
                k += 1
        out[label] = {"edges": k, "cpu_ms_per_edge_pair": (time.process_time() - c) / k * 1e3}
    return out


def task_memory() -> dict:
    from verify.atlas import EDGE_CHUNK, GROWTH_CHUNK_POINTS, edge_task, growth_task

    ms = tuple(Fraction(k, 100) for k in range(1, 1 + EDGE_CHUNK))
    edge_task(("pendulum", Fraction(1, 2), None, "exact", 30, 3, ms[:1]))  # warm
    tracemalloc.start()
    edge_task(("pendulum", Fraction(1, 2), None, "exact", 30, 3, ms))
    _, peak_edge = tracemalloc.get_traced_memory()
    tracemalloc.stop()
    tau = np.linspace(0.2, 4, 2000)
    m = np.linspace(0.001, 0.999, GROWTH_CHUNK_POINTS // 2000)
    tracemalloc.start()
    growth_task(("pendulum", Fraction(1, 2), None, "exact", tau, m))
    _, peak_growth = tracemalloc.get_traced_memory()
    tracemalloc.stop()
    return {
        "edge_chunk_depths": EDGE_CHUNK,
        "edge_chunk_peak_bytes": peak_edge,
        "growth_chunk_points": int(m.size * tau.size),
        "growth_chunk_peak_bytes": peak_growth,
    }


def _warm(orders):
    """Derive what the certified solver needs for every order, in this process."""
    from verify.inputs import as_orders
    from verify.modulation import boundary

    for n in as_orders(orders):
        boundary(n, "0.5", digits=30)


def cluster_bench(orders: str, m: str) -> dict:
    import distributed

    from verify.atlas import atlas, request

    req = request(orders, m)
    edges = len(req.orders) * len(req.m)
    out = {"grid": f"orders {orders}, m {m}, 30 digits, no friction", "edge_pairs": edges}
    _warm(orders)
    c, w = time.process_time(), time.perf_counter()
    atlas(orders, m, digits=30, workers=1)  # in this process: no cluster
    out["serial"] = {
        "wall_s": time.perf_counter() - w,
        "cpu_s": time.process_time() - c,
        "cpu_ms_per_edge_pair": (time.process_time() - c) / edges * 1e3,
    }
    for workers in (1, 2):
        with (
            distributed.LocalCluster(
                n_workers=workers,
                threads_per_worker=1,
                processes=True,
                dashboard_address=None,
                silence_logs=50,
            ) as cl,
            distributed.Client(cl, set_as_default=False) as client,
        ):
            client.run(_warm, orders)  # every worker derives its forms for every order once
            cpu0 = sum(client.run(time.process_time).values())
            w = time.perf_counter()
            atlas(orders, m, digits=30, scheduler=client)
            wall = time.perf_counter() - w
            cpu = sum(client.run(time.process_time).values()) - cpu0
        out[f"workers_{workers}"] = {
            "wall_s": wall,
            "worker_cpu_s": cpu,
            "cpu_ms_per_edge_pair": cpu / edges * 1e3,
        }
    out["speedup_wall_2_over_1"] = out["workers_1"]["wall_s"] / out["workers_2"]["wall_s"]
    # the workers' CPU includes their communication threads (heartbeats, the event loop)
    out["cpu_overhead_1_worker"] = out["workers_1"]["worker_cpu_s"] / out["serial"]["cpu_s"]
    return out


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--quick", action="store_true", help="smaller grids")
    ap.add_argument(
        "--only", choices=("growth", "edges", "memory", "cluster"), help="one part only"
    )
    args = ap.parse_args()
    import mpmath

    import paramres  # noqa: F401 - binds the engine's packages

    doc = {
        "date": time.strftime("%Y-%m-%d %H:%M UTC", time.gmtime()),
        "python": platform.python_version(),
        "numpy": np.__version__,
        "mpmath": mpmath.__version__,
        "machine": platform.machine(),
    }
    want = lambda part: args.only in (None, part)  # noqa: E731
    if want("growth"):
        doc["growth_map"] = growth_bench(500 if args.quick else 2000)
    if want("edges"):
        doc["edge_cost"] = edge_cost(8 if args.quick else 24)
    if want("memory"):
        doc["task_memory"] = task_memory()
    if want("cluster"):
        doc["cluster"] = cluster_bench(
            *(("1-6", "0.01:0.99:0.04") if args.quick else ("1-20", "0.005:0.995:0.005"))
        )
    print(json.dumps(doc, indent=2))


if __name__ == "__main__":
    main()
