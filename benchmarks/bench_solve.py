"""Speed of the numeric engine against its targets (a script, not a test).

    python -m benchmarks.bench_solve [--quick]

Measures, best of several runs after a warm-up (derivation and compilation are cached per process
and not counted):

* ``boundary_grid(range(1, 7), 1000 depths)`` -- target 10 ms;
* ``boundary(3, "0.3", digits=50)`` (both edges, certified) -- target 1 ms;
* ``boundary(3, "0.3", digits=1000)`` -- target 12 ms, and no slower than two plain uncertified
  ``mpmath.findroot`` calls on the printed edge equation (eq. 13) at the same precision.

The measuring functions are importable (:func:`best_time`, :func:`bench_grid`,
:func:`bench_boundary`, :func:`bench_findroot`, :func:`results`) for other benchmark commands.
"""

from __future__ import annotations

import argparse
import time
from collections.abc import Callable
from dataclasses import dataclass

import mpmath
import numpy as np

__all__ = [
    "Result",
    "best_time",
    "bench_grid",
    "bench_boundary",
    "bench_findroot",
    "results",
    "main",
]


@dataclass(frozen=True)
class Result:
    """One measurement: best wall time and best CPU time of this process (seconds, over ``runs``
    calls; the CPU time is what the call costs when the machine is shared), the target (seconds,
    or None) and a label."""

    name: str
    seconds: float
    target: float | None
    runs: int
    cpu_seconds: float = float("nan")

    @property
    def ratio(self) -> float | None:
        return None if self.target is None else self.seconds / self.target


def best_time(
    fn: Callable[[], object], *, runs: int = 20, warmup: int = 2, budget: float = 5.0
) -> tuple[float, int, float]:
    """Best wall time of ``fn()`` over up to ``runs`` calls (stops early after ``budget`` s), the
    number of calls, and the best CPU time of this process for one call."""
    for _ in range(warmup):
        fn()
    best, cpu, done, start = float("inf"), float("inf"), 0, time.perf_counter()
    while done < runs and (done < 3 or time.perf_counter() - start < budget):
        t, c = time.perf_counter(), time.process_time()
        fn()
        best = min(best, time.perf_counter() - t)
        cpu = min(cpu, time.process_time() - c)
        done += 1
    return best, done, cpu


def bench_grid(depths: int = 1000, orders=range(1, 7), runs: int = 30) -> Result:
    from verify.grid import boundary_grid

    ms = np.linspace(0.001, 0.999, depths)
    sec, n, cpu = best_time(lambda: boundary_grid(orders, ms), runs=runs)
    return Result(f"boundary_grid({len(orders)} orders x {depths} depths)", sec, 0.010, n, cpu)


def bench_boundary(digits: int, order: int = 3, m: str = "0.3", runs: int = 20) -> Result:
    from verify.solve import boundary

    target = {50: 0.001, 1000: 0.012}.get(digits)
    sec, n, cpu = best_time(lambda: boundary(order, m, digits=digits), runs=runs)
    return Result(f"boundary({order}, {m!r}, digits={digits}) certified", sec, target, n, cpu)


def bench_findroot(digits: int, order: int = 3, m: str = "0.3", runs: int = 10) -> Result:
    """Two plain ``mpmath.findroot`` calls (secant, uncertified) on eq. 13 for the two edges of
    ``order`` at ``digits`` digits, started from the double-precision edges."""
    from fractions import Fraction

    from verify.grid import boundary_grid

    starts = boundary_grid([order], [float(Fraction(m))])[0, :, 0]

    def run():
        with mpmath.workdps(digits):
            mm = mpmath.mpf(Fraction(m).numerator) / Fraction(m).denominator
            w1 = 2 * mpmath.pi / mpmath.sqrt(1 + mm)
            w2 = 2 * mpmath.pi / mpmath.sqrt(1 - mm)
            wav, dw = (w1 + w2) / 2, w2 - w1
            q = ((1 + mm) / (1 - mm)) ** mpmath.mpf(1.5)
            f = mpmath.cos if order % 2 else mpmath.sin
            for T0, s in zip(starts, (-1, 1), strict=True):
                mpmath.findroot(
                    lambda T, s=s: (q + 1) * f(wav * T / 2) + s * (q - 1) * f(dw * T / 4),
                    mpmath.mpf(T0),
                )

    sec, n, cpu = best_time(run, runs=runs)
    return Result(f"2 x mpmath.findroot(eq. 13), {digits} digits (uncertified)", sec, None, n, cpu)


def results(quick: bool = False) -> list[Result]:
    out = [
        bench_grid(runs=10 if quick else 30),
        bench_boundary(50),
        bench_boundary(1000, runs=5 if quick else 20),
        bench_findroot(50),
        bench_findroot(1000, runs=3 if quick else 10),
    ]
    return out


def _fmt(sec: float) -> str:
    return f"{sec * 1e3:9.3f} ms"


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="fewer repetitions")
    args = parser.parse_args(argv)
    res = results(args.quick)
    width = max(len(r.name) for r in res)
    cols = f"{'best wall':>12}  {'best cpu':>12}  {'target':>12}  {'ratio':>6}  runs"
    print(f"{'measurement':<{width}}  {cols}")
    for r in res:
        tgt = _fmt(r.target) if r.target else " " * 12
        ratio = f"{r.ratio:6.2f}" if r.ratio is not None else "      "
        print(
            f"{r.name:<{width}}  {_fmt(r.seconds):>12}  {_fmt(r.cpu_seconds):>12}  {tgt:>12}  "
            f"{ratio}  {r.runs}"
        )
    by = {r.name: r for r in res}
    cert = next(r for r in res if "digits=1000" in r.name)
    plain = next(r for n, r in by.items() if "1000 digits" in n)
    print(
        f"\ncertified (1000 digits) / two plain findroot calls: {cert.seconds / plain.seconds:.2f}"
    )
    cert50 = next(r for r in res if "digits=50" in r.name)
    plain50 = next(r for n, r in by.items() if "50 digits" in n)
    ratio50 = cert50.seconds / plain50.seconds
    print(f"certified (50 digits) / two plain findroot calls:   {ratio50:.2f}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
