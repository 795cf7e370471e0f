"""What a finite switching time and the sine modulation cost, side by side with their floors.

    python benchmarks/bench_ramp.py [--quick]

Scenes (each a dict: ``name``, ``target`` (seconds), ``ours`` (seconds), ``floor`` (seconds),
``note``), CPU time (``time.process_time``; a child's from ``resource``), which a loaded machine
inflates less than wall time:

* ``ramp chart``: certified edges of orders 1-3 with ramps of ``S = 1/100`` at 200 depths
  (``m = 0.0045 ... 0.9``, 15 digits), warm; the floor is the same chart of the jump model
  (:func:`verify.solve.boundary`, the certified per-edge solver) -- the ramp's extra cost is the
  continuation in ``S`` and the Bessel maps.  Target: 2 minutes.
* ``jump-validity cold``: ``paramres jump-validity --order 1 --m 0.3 --tol 1e-3`` in a fresh
  process (imports, compiling the forms, the jump model's edges, the search and the proofs);
  the floor is the same process printing ``paramres boundary --order 1 --m 0.3`` (the jump
  model's edges alone).  Target: 2 s.
* ``sine edges``: certified sine edges of orders 1-3 at three depths (30 digits, the validated
  Taylor integrator); the floor is the jump model's edges at the same points.  No target (the
  integrator is the general route; it is reported to be known).

``--quick`` uses 20 depths instead of 200 (the target scales with the count).
"""

from __future__ import annotations

import resource
import subprocess
import sys
import time
from fractions import Fraction

ORDERS = (1, 2, 3)
S_CHART = Fraction(1, 100)


def _depths(count: int) -> list[Fraction]:
    return [Fraction(9, 10) * k / count for k in range(1, count + 1)]


def _cpu(fn) -> float:
    t = time.process_time()
    fn()
    return time.process_time() - t


def _child_cpu(argv: list[str]) -> float:
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    subprocess.run(argv, check=True, capture_output=True)
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    return (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)


def _chart(depths, ramp: bool) -> None:
    from verify.ramp import ramp_boundary
    from verify.solve import boundary

    for m in depths:
        for n in ORDERS:
            if ramp:
                ramp_boundary(n, m, S_CHART, digits=15)
            else:
                boundary(n, m, digits=15)


def scenes(quick: bool = False) -> list[dict]:
    """The measured scenes (see the module's docstring)."""
    from verify.ramp import ramp_boundary
    from verify.smooth import sine_boundary
    from verify.solve import boundary

    out = []
    count = 20 if quick else 200
    depths = _depths(count)
    ramp_boundary(1, "0.3", S_CHART, digits=15)  # warm: compile the forms once
    floor = _cpu(lambda: _chart(depths, ramp=False))
    ours = _cpu(lambda: _chart(depths, ramp=True))
    out.append(
        {
            "name": f"ramp chart, orders 1-3, {count} depths, S = 1/100",
            "target": 120.0 * count / 200,
            "ours": ours,
            "floor": floor,
            "note": "certified (15 digits); floor: the jump model's certified chart",
        }
    )
    exe = [sys.executable, "-m", "paramres"]
    floor = _child_cpu([*exe, "boundary", "--order", "1", "--m", "0.3"])
    ours = _child_cpu([*exe, "jump-validity", "--order", "1", "--m", "0.3", "--tol", "1e-3"])
    out.append(
        {
            "name": "jump-validity cold (order 1, m = 0.3, tol 1e-3)",
            "target": 2.0,
            "ours": ours,
            "floor": floor,
            "note": "a fresh process; floor: the same process for the jump model's boundary",
        }
    )
    points = [(n, m) for n in ORDERS for m in (("0.3",) if quick else ("0.1", "0.5", "0.8"))]
    sine_boundary(1, "0.3", digits=30)  # warm
    floor = _cpu(lambda: [boundary(n, m, digits=30) for n, m in points])
    ours = _cpu(lambda: [sine_boundary(n, m, digits=30) for n, m in points])
    out.append(
        {
            "name": f"sine edges, orders 1-3, {len(points) // 3} depths, 30 digits",
            "target": None,
            "ours": ours,
            "floor": floor,
            "note": "validated Taylor integration; floor: the jump model's edges",
        }
    )
    return out


def main() -> None:
    quick = "--quick" in sys.argv[1:]
    print(f"{'scene':52s} {'ours (s)':>9s} {'floor (s)':>10s} {'ratio':>7s} {'target':>7s}")
    for s in scenes(quick):
        ratio = s["ours"] / s["floor"] if s["floor"] > 0 else float("inf")
        target = "-" if s["target"] is None else f"{s['target']:.0f}"
        mark = "" if s["target"] is None or s["ours"] <= s["target"] else "  OVER"
        print(
            f"{s['name']:52s} {s['ours']:9.2f} {s['floor']:10.2f} {ratio:7.1f} {target:>7s}{mark}"
        )


if __name__ == "__main__":
    main()
