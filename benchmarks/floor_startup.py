"""Startup: a numeric command against importing what it needs.

Ours is ``paramres boundary --order 3 --m 0.3`` in a fresh process (warm cache); the floor is
``python -c "import numpy, mpmath, flint"`` -- the libraries any such command must load.  Wall
time of the whole process (the process's own CPU time is not visible from outside).
"""

from __future__ import annotations

import subprocess
import sys


def _run(argv):
    subprocess.run(argv, check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)


def scenes(quick: bool) -> list[dict]:
    cmd = [sys.executable, "-m", "paramres", "boundary", "--order", "3", "--m", "0.3"]
    floor = [sys.executable, "-c", "import numpy, mpmath, flint"]
    return [
        {
            "name": "startup: boundary --order 3 --m 0.3",
            "target": 1.5,
            "ours": lambda: _run(cmd),
            "floor": lambda: _run(floor),
            "kind": "wall",
            "note": "wall time of the command against importing numpy, mpmath and flint",
        }
    ]
