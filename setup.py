"""Packaging beyond what pyproject.toml declares:

- the wheel carries the benchmark results the report reads (``benchmarks/results.json``, written
  by ``paramres bench``) as ``paramres/data/bench-results.json``;
- ``verify._digits``, the digits of a table's rows in C (``verify/_digits.c``), is built where a C
  compiler and Python's headers are at hand.  It is optional: without them the package installs
  all the same and prints the same digits from Python, only slower."""

import shutil
from pathlib import Path

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext
from setuptools.command.build_py import build_py

SOURCE = Path(__file__).resolve().parent / "benchmarks" / "results.json"


class BuildWithData(build_py):
    def run(self):
        super().run()
        if SOURCE.is_file() and not getattr(self, "editable_mode", False):
            target = Path(self.build_lib) / "paramres" / "data" / "bench-results.json"
            target.parent.mkdir(parents=True, exist_ok=True)
            shutil.copyfile(SOURCE, target)


class BuildExtension(build_ext):
    """The compiled digits' doubles are those of the Python loop, operation for operation: no
    multiply-add contracted into one rounding (gcc and clang contract by default on some
    machines, such as aarch64)."""

    def build_extensions(self):
        if self.compiler.compiler_type == "unix":
            for extension in self.extensions:
                extension.extra_compile_args.append("-ffp-contract=off")
        super().build_extensions()


setup(
    cmdclass={"build_py": BuildWithData, "build_ext": BuildExtension},
    ext_modules=[Extension("verify._digits", ["verify/_digits.c"], optional=True)],
)
