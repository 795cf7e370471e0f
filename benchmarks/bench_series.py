"""Cold timing of the edge series: each case runs in a fresh Python process.

    python benchmarks/bench_series.py [--repeat R] [--json]

Reported per case: the wall-clock time of the whole process (interpreter start, imports of sympy
and the engine, the computation) and the time inside the process from before the first import of
the engine to the end (so sympy's import is included in both).  The requirement it checks: both
edges of orders 1-6 through m^4, cold, in under 20 s.
"""

from __future__ import annotations

import argparse
import json
import statistics
import subprocess
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]

CASES = {
    "orders 1-6, through m^4": "for n in range(1, 7): edge_series(n, 4)",
    "orders 1-6, through m^8": "for n in range(1, 7): edge_series(n, 8)",
    "orders 12 and 100, through m^12": "edge_series(12, 12); edge_series(100, 12)",
    "odd and even orders (symbol n), through m^8": "edge_series('odd', 8); edge_series('even', 8)",
    "order 1 with friction (exact model), through m^4": (
        "edge_series(1, 4, Q=50, damping='exact'); threshold_series(1, 4, damping='exact')"
    ),
}

SNIPPET = """
import time
t0 = time.perf_counter()
from analytic import edge_series, threshold_series
{body}
print(time.perf_counter() - t0)
"""


def run_case(body: str) -> tuple[float, float]:
    start = time.perf_counter()
    proc = subprocess.run(
        [sys.executable, "-c", SNIPPET.format(body=body)],
        cwd=ROOT,
        capture_output=True,
        text=True,
        check=True,
    )
    wall = time.perf_counter() - start
    return wall, float(proc.stdout.strip().splitlines()[-1])


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(
        description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter
    )
    ap.add_argument("--repeat", type=int, default=3, help="fresh processes per case (default 3)")
    ap.add_argument("--json", action="store_true", help="machine-readable output")
    args = ap.parse_args(argv)
    results = []
    for name, body in CASES.items():
        runs = [run_case(body) for _ in range(max(1, args.repeat))]
        walls, inner = zip(*runs, strict=True)
        results.append(
            {
                "case": name,
                "wall_median_s": statistics.median(walls),
                "wall_max_s": max(walls),
                "in_process_median_s": statistics.median(inner),
            }
        )
    if args.json:
        json.dump(results, sys.stdout, indent=2)
        sys.stdout.write("\n")
    else:
        print(f"{'case':<52} {'wall (median)':>14} {'wall (max)':>11} {'in-process':>11}")
        for r in results:
            print(
                f"{r['case']:<52} {r['wall_median_s']:>12.2f} s {r['wall_max_s']:>9.2f} s "
                f"{r['in_process_median_s']:>9.2f} s"
            )
    limit = 20.0
    worst = results[0]["wall_max_s"]
    print(
        f"requirement: orders 1-6 through m^4 cold < {limit:.0f} s: "
        f"{'met' if worst < limit else 'NOT met'} ({worst:.2f} s)",
        file=sys.stderr if args.json else sys.stdout,
    )
    return 0 if worst < limit else 1


if __name__ == "__main__":
    sys.exit(main())
