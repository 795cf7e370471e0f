"""The report, cold: ``paramres report`` (PDF included when TeX is installed) in a fresh process
with an empty cache directory, against the issue's target of 15 s wall time.

No plain code does the same job, so the scene has **no floor** (``floor`` is ``None``, the target
is in seconds).  One sample, no warm-up call (each call is cold by construction: a new output and
cache directory).  The row's ``extra`` holds the CPU time of the build's processes (the
command, its second process and LaTeX) and whether a PDF was made.
"""

from __future__ import annotations

import resource
import subprocess
import sys
import tempfile
from pathlib import Path

#: the issue's target for a cold build, seconds of wall time
TARGET_SECONDS = 15.0

_last: dict = {}


def _children_cpu() -> float:
    r = resource.getrusage(resource.RUSAGE_CHILDREN)
    return r.ru_utime + r.ru_stime


def _cold_report() -> None:
    with tempfile.TemporaryDirectory(prefix="paramres-bench-report-") as tmp:
        out, cache = Path(tmp) / "report", Path(tmp) / "cache"
        cmd = [
            sys.executable,
            "-m",
            "paramres",
            "report",
            "--out",
            str(out),
            "--cache",
            str(cache),
            "-q",
        ]
        before = _children_cpu()
        subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        _last["cpu_seconds"] = round(_children_cpu() - before, 1)
        _last["pdf"] = (out / "paramres-report.pdf").exists()


def scenes(quick: bool) -> list[dict]:
    return [
        {
            "name": "report, cold (fresh process, empty cache)",
            "target": TARGET_SECONDS,
            "ours": _cold_report,
            "floor": None,
            "repeat": 1,
            "warm": False,
            "kind": "wall",
            "extra": lambda: dict(_last),
            "note": "wall time of paramres report with an empty cache; extra: CPU seconds of its "
            "processes and whether a PDF was made",
        }
    ]
