"""The modulation axis: the square wave (the paper's jump) or linear ramps of the length.

:func:`boundary` and :func:`multipliers` take ``modulation=`` (``"square"``, the default, or
``"ramp"``) and ``switch_time=`` (``S`` in units of ``T0``, only with ``"ramp"``) on top of the
arguments of :func:`verify.solve.boundary` and :func:`verify.multipliers.multipliers`.  The
square wave goes to those unchanged; the ramp to :mod:`verify.ramp` (the paper's pendulum, any
duty, no friction, the certified method).  Anything else is refused with an
:class:`~verify.inputs.InputError` that names the value and what is allowed.
"""

from __future__ import annotations

from fractions import Fraction

from .inputs import InputError, as_quality

__all__ = ["MODULATIONS", "check_modulation", "boundary", "multipliers"]

#: the modulations the engine knows
MODULATIONS = ("square", "ramp")


def check_modulation(modulation, switch_time, system="pendulum", Q=None) -> Fraction | None:
    """Check the modulation options; returns ``S`` (a Fraction) for ``ramp``, ``None`` for
    ``square``.  Refused: an unknown modulation (``sine`` is not implemented), a switching time
    without ``ramp``, ``ramp`` without a switching time, ``ramp`` for a system other than the
    pendulum, and ``ramp`` with friction."""
    if not isinstance(modulation, str) or modulation.strip().lower() not in MODULATIONS:
        extra = "; sine is not implemented" if str(modulation).strip().lower() == "sine" else ""
        raise InputError(
            f"modulation {modulation!r} is not one of: {', '.join(MODULATIONS)}{extra}"
        )
    modulation = modulation.strip().lower()
    if modulation == "square":
        if switch_time is not None:
            raise InputError(
                f"a switching time S = {switch_time} needs the ramp modulation "
                "(--modulation ramp); the square wave switches instantly"
            )
        return None
    if switch_time is None:
        raise InputError("the ramp modulation needs a switching time S >= 0 (--switch-time S)")
    from .ramp import as_switch_time

    S = as_switch_time(switch_time)
    name = getattr(system, "name", system)
    if name != "pendulum":
        raise InputError(
            f"the ramp modulation is implemented for the pendulum only, not for system {name!r}"
        )
    if as_quality(Q) is not None:
        raise InputError(
            f"the ramp modulation is implemented without friction only (got Q = {Q}); leave Q out"
        )
    return S


def boundary(
    order,
    m=None,
    *,
    Q=None,
    damping="exact",
    digits=30,
    method="certified",
    tol=None,
    system="pendulum",
    duty="1/2",
    modulation="square",
    switch_time=None,
):
    """:func:`verify.solve.boundary` for ``modulation="square"`` (the same arguments); for
    ``"ramp"`` the certified edges with linear ramps lasting ``switch_time`` (units ``T0``) of
    :func:`verify.ramp.ramp_boundary`, as a :class:`verify.solve.Boundary` (pendulum, no
    friction, the certified method)."""
    from .solve import boundary as square_boundary

    S = check_modulation(modulation, switch_time, system, Q)
    if S is None:
        return square_boundary(
            order,
            m,
            Q=Q,
            damping=damping,
            digits=digits,
            method=method,
            tol=tol,
            system=system,
            duty=duty,
        )
    if method != "certified" or tol is not None:
        raise InputError(
            f"the ramp modulation has the certified method only (got method {method!r}"
            + (f", tol {tol}" if tol is not None else "")
            + ")"
        )
    from .ramp import ramp_boundary

    if hasattr(system, "duty"):
        duty = system.duty
    return ramp_boundary(order, m, S, duty=duty, digits=digits).boundary


def multipliers(
    T,
    m=None,
    *,
    Q=None,
    damping="exact",
    digits=30,
    system="pendulum",
    duty="1/2",
    modulation="square",
    switch_time=None,
):
    """:func:`verify.multipliers.multipliers` (the same arguments), with the ramp's monodromy
    for ``modulation="ramp"`` (``switch_time`` in units of ``T0``)."""
    from .multipliers import multipliers as mult

    S = check_modulation(modulation, switch_time, system, Q)
    return mult(T, m, Q=Q, damping=damping, digits=digits, system=system, duty=duty, switch_time=S)
