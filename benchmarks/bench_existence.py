"""What proven existence costs against the former scan.

    python benchmarks/bench_existence.py

Times ``verify.existence`` (branch and bound over depth ranges, every range and gap proven) and
``verify.existence.existence_scan`` (the former float scan with proven thresholds) on the same
cases, warm (the compiled forms are built once, before timing); CPU time of the process
(``time.process_time``), which a loaded machine inflates less than wall time.
"""

from __future__ import annotations

import statistics
import time

from verify.existence import existence, existence_scan

CASES = [
    (3, 7, "exact"),
    (3, 7, "paper"),
    (1, 5, "exact"),
    (5, "2.008906", "exact"),
    (3, "0.3", "exact"),
]


def _time(fn, *args, repeat=1, **kw):
    out = []
    for _ in range(repeat):
        t = time.process_time()
        fn(*args, **kw)
        out.append(time.process_time() - t)
    return statistics.median(out)


#: other members of the family (proven existence only: the scan is the paper's)
FAMILY_CASES = [
    (1, 7, "exact", "torsion", "1/2"),
    (1, 7, "paper", "meissner", "1/3"),
    (4, 50, "paper", "pendulum", "1/3"),
]


def main() -> None:
    existence(3, 7)  # warm: compile the forms once
    existence_scan(3, 7)
    print(f"{'case':28s} {'proven (s)':>11s} {'scan (s)':>9s}")
    for n, Q, damping in CASES:
        tp = _time(existence, n, Q, damping=damping)
        ts = _time(existence_scan, n, Q, damping=damping)
        print(f"order {n}, Q = {Q}, {damping:6s}      {tp:11.2f} {ts:9.2f}")
    for n, Q, damping, name, duty in FAMILY_CASES:
        existence(n, Q, damping=damping, system=name, duty=duty)  # warm: the system's forms
        tp = _time(existence, n, Q, damping=damping, system=name, duty=duty)
        label = f"{name} D={duty} n={n} Q={Q} {damping}"
        print(f"{label:28s} {tp:11.2f} {'-':>9s}")


if __name__ == "__main__":
    main()
