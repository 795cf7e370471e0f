"""The command-line arguments several commands share, defined once (values are checked later by
:mod:`verify.inputs`, so every command refuses bad values in the same words)."""

from __future__ import annotations

__all__ = ["add_order", "add_depth", "add_friction", "add_json"]


def add_order(p, help: str = "order of the resonance (1, 2, ...)") -> None:
    p.add_argument("--order", required=True, metavar="N", help=help)


def add_depth(p) -> None:
    p.add_argument(
        "--m",
        required=True,
        metavar="M",
        help="modulation depth, 0 < m < 1 (exact: 0.3, 3/5, 1e-12)",
    )


def add_friction(p, *, required: bool = False) -> None:
    """``--Q`` (the quality factor; optional unless ``required``) and ``--damping``."""
    if required:
        p.add_argument("--Q", required=True, metavar="Q", help="quality factor, Q > 0")
    else:
        p.add_argument(
            "--Q", metavar="Q", default=None, help="quality factor (omit for no friction)"
        )
    p.add_argument(
        "--damping",
        default="exact",
        metavar="MODEL",
        help="friction model: exact (default; the true damped oscillator) or paper (eqs. 28-30)",
    )


def add_json(p, help: str = "machine-readable output") -> None:
    p.add_argument("--json", action="store_true", help=help)
