"""The ``paramres`` command's entry point: binds the engine's packages (see :mod:`paramres`),
then runs :func:`reports.cli.main`."""

from __future__ import annotations

import paramres  # noqa: F401  (binds the engine's packages first)

__all__ = ["main"]


def main(argv: list[str] | None = None) -> int:
    from reports.cli import main as run

    return run(argv)
