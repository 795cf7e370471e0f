"""Packaging beyond what pyproject.toml declares: the wheel carries the benchmark results the
report reads (``benchmarks/results.json``, written by ``paramres bench``) as
``paramres/data/bench-results.json``."""

import shutil
from pathlib import Path

from setuptools import setup
from setuptools.command.build_py import build_py

SOURCE = Path(__file__).resolve().parent / "benchmarks" / "results.json"


class BuildWithData(build_py):
    def run(self):
        super().run()
        if SOURCE.is_file() and not getattr(self, "editable_mode", False):
            target = Path(self.build_lib) / "paramres" / "data" / "bench-results.json"
            target.parent.mkdir(parents=True, exist_ok=True)
            shutil.copyfile(SOURCE, target)


setup(cmdclass={"build_py": BuildWithData})
