"""Cold timing of the symbolic derivations: stitching systems, normal form, the paper's chains and
the catalogue rows of the exact results, each in a fresh process with the disk cache off.

    python benchmarks/bench_derive.py [--repeat 3]

Prints one line per stage (seconds, median of the fresh-process runs) and the total.
"""

from __future__ import annotations

import argparse
import json
import os
import statistics
import subprocess
import sys

STAGES = {
    "import sympy + analytic": "import analytic.model, analytic.stitching, analytic.normal_form",
    "stitching systems (4x4, 2x2, paper 2x2)": (
        "from analytic.stitching import *\n"
        "from analytic.model import Damping\n"
        "[general_system(p, d) for p in Parity for d in Damping]\n"
        "[edge_system(k) for k in EdgeKind]; [paper_system(p) for p in Parity]"
    ),
    "Floquet condition (det = F det(M - sigma I))": (
        "from analytic.stitching import *\nfrom analytic.model import Damping\n"
        "[floquet_condition(p, d) for p in Parity for d in Damping]"
    ),
    "normal-form links": (
        "from analytic.normal_form import *\nfrom analytic.stitching import Parity, EdgeKind\n"
        "from analytic.model import Damping\n"
        "[det_monodromy(d) for d in Damping]; [trace_form(d) for d in Damping]\n"
        "[trace_lemma(p) for p in Parity]; [normal_form_link(p) for p in Parity]\n"
        "[edge_factor_link(k) for k in EdgeKind]"
    ),
    "the paper's chains": "from analytic.reductions import chains; chains()",
    "catalogue rows (exact results)": (
        "import analytic.catalogue_rows\nfrom analytic.catalogue import _REGISTRY\n"
        "import analytic.catalogue_rows as R\n"
        "[f() for k, f in list(_REGISTRY.items()) if f.__module__ == 'analytic.catalogue_rows']"
    ),
}

PRELUDE = "import time\nt0 = time.perf_counter()\n"
CODA = "\nprint(time.perf_counter() - t0)\n"


def run_stage(code: str) -> float:
    env = dict(os.environ, PARAMRES_NO_CACHE="1")
    out = subprocess.run(
        [sys.executable, "-c", PRELUDE + code + CODA],
        capture_output=True,
        text=True,
        env=env,
        check=True,
    )
    return float(out.stdout.strip().splitlines()[-1])


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--json", action="store_true")
    args = ap.parse_args()
    # everything in one fresh process (what a cold `paramres catalogue` pays, minus the series rows)
    total_code = "\n".join(STAGES.values())
    results = {}
    for name, code in STAGES.items():
        results[name] = statistics.median(run_stage(code) for _ in range(args.repeat))
    results["all of the above, one fresh process"] = statistics.median(
        run_stage(total_code) for _ in range(args.repeat)
    )
    if args.json:
        print(json.dumps(results, indent=2))
    else:
        for name, sec in results.items():
            print(f"{sec:8.2f} s  {name}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
