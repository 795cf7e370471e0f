"""The command-line arguments several commands share, defined once (values are checked later by
:mod:`verify.inputs`, so every command refuses bad values in the same words)."""

from __future__ import annotations

__all__ = [
    "add_order",
    "add_depth",
    "add_friction",
    "add_json",
    "add_system",
    "system_of",
    "add_modulation",
]


def add_order(p, help: str = "order of the resonance, 1 to 10000") -> None:
    p.add_argument("--order", required=True, metavar="N", help=help)


def add_depth(p, *, required: bool = True) -> None:
    p.add_argument(
        "--m",
        required=required,
        default=None,
        metavar="M",
        help="modulation depth, 0 < m < 1 (exact: 0.3, 3/5, 1e-12)"
        + ("" if required else "; not for --system custom"),
    )


def add_system(p) -> None:
    """``--system``, ``--duty`` and, for ``custom``, ``--omega-sq`` and ``--jump``."""
    g = p.add_argument_group("the oscillator (a member of the two-level family)")
    g.add_argument(
        "--system",
        default="pendulum",
        metavar="NAME",
        help=(
            "pendulum (default: the paper's, bob sliding on a light rod), torsion (moment of "
            "inertia switched), meissner (stiffness switched, no jump), or custom"
        ),
    )
    g.add_argument(
        "--duty",
        default="1/2",
        metavar="D",
        help="fraction of the period spent in phase 1 (the low-frequency phase), 0 < D < 1; "
        "default 1/2",
    )
    g.add_argument(
        "--omega-sq",
        default=None,
        metavar="W1,W2",
        help="custom only: omega1^2,omega2^2 in units of omega0^2, e.g. 4/5,6/5",
    )
    g.add_argument(
        "--jump",
        default=None,
        metavar="K",
        help="custom only: the factor k > 0 on the angular velocity at the switch 1 -> 2 "
        "(default 1)",
    )


def system_of(args):
    """The :class:`analytic.system.System` the options describe, checked; also checks that
    ``--m`` is given exactly when the system has a depth."""
    from verify.inputs import InputError, as_system

    sysv = as_system(args.system, args.duty, args.omega_sq, args.jump)
    m = getattr(args, "m", None)
    if sysv.uses_depth and hasattr(args, "m") and m is None:
        raise InputError(f"system {sysv.name} needs --m (a depth 0 < m < 1)")
    if not sysv.uses_depth and m is not None:
        raise InputError(f"--m {m} makes no sense with --system custom (it has no depth)")
    return sysv


def add_friction(p, *, required: bool = False) -> None:
    """``--Q`` (the quality factor; optional unless ``required``) and ``--damping``."""
    if required:
        p.add_argument("--Q", required=True, metavar="Q", help="quality factor, 1e-6 <= Q <= 1e30")
    else:
        p.add_argument(
            "--Q",
            metavar="Q",
            default=None,
            help="quality factor, 1e-6 <= Q <= 1e30 (omit for no friction)",
        )
    p.add_argument(
        "--damping",
        default="exact",
        metavar="MODEL",
        help="friction model: exact (default; the true damped oscillator) or paper (eqs. 28-30)",
    )


def add_json(p, help: str = "machine-readable output") -> None:
    p.add_argument("--json", action="store_true", help=help)


def add_quiet(p) -> None:
    """``-q/--quiet``: no progress on stderr (progress is drawn only on a terminal anyway)."""
    p.add_argument("-q", "--quiet", action="store_true", help="no progress display on stderr")


def add_modulation(p) -> None:
    """``--modulation square|ramp|sine`` and ``--switch-time S`` (the ramp's duration)."""
    g = p.add_argument_group("the modulation (how the length switches)")
    g.add_argument(
        "--modulation",
        default="square",
        metavar="KIND",
        help="square (default: the paper's instantaneous jump), ramp (the length changes "
        "linearly during --switch-time S around each switch) or sine (l = l0(1 + m sin(2 pi "
        "t/T)), equal halves); ramp and sine: the pendulum, edges without friction, "
        "multipliers also with --Q",
    )
    g.add_argument(
        "--switch-time",
        default=None,
        metavar="S",
        help="ramp only: the duration of each switch in units of T0, 0 <= S <= the shorter "
        "phase (S = 0 is the jump)",
    )
