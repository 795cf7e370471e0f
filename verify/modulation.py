"""The modulation axis: the square wave (the paper's jump), linear ramps of the length, or a sine.

:func:`boundary` and :func:`multipliers` take ``modulation=`` (``"square"``, the default,
``"ramp"`` or ``"sine"``) and ``switch_time=`` (``S`` in units of ``T0``, only with ``"ramp"``)
on top of the arguments of :func:`verify.solve.boundary` and
:func:`verify.multipliers.multipliers`.  The options are checked once, by
:func:`paramres.inputs.as_modulation`; the square wave goes to those functions unchanged, the
ramp to :mod:`verify.ramp` (the Bessel route; with friction the validated integrator of
:mod:`verify.smooth`), the sine to :mod:`verify.smooth`.  What is implemented:

=========  ==========================================  ==========================================
           edges (``boundary``)                        multipliers
=========  ==========================================  ==========================================
square     every system, duty, friction model          every system, duty, friction model
ramp       pendulum, any duty, no friction              pendulum, any duty, with or without ``Q``
sine       pendulum, ``D = 1/2``, no friction           pendulum, ``D = 1/2``, with or without ``Q``
=========  ==========================================  ==========================================

Friction with a varying length is the exact model (the governing equation itself); the paper's
approximation is defined for the square wave only.  Anything else is refused with an
:class:`~verify.inputs.InputError` that names the value and what is allowed.
"""

from __future__ import annotations

from fractions import Fraction

from .inputs import InputError, as_damping, as_modulation, as_quality, as_system

__all__ = ["boundary", "multipliers"]


def _friction(kind: str, Q, damping, *, edges: bool) -> None:
    if kind == "square" or as_quality(Q) is None:
        return
    if edges:
        raise InputError(
            f"the {kind} modulation's edges are implemented without friction only (got Q = {Q}); "
            "leave Q out (its multipliers take Q)"
        )
    if as_damping(damping) != "exact":
        raise InputError(
            f"the {kind} modulation has the exact friction model only (got damping "
            f"{damping!r}); the paper's model is defined for the square wave"
        )


_SQUARE: list = []


def _square_boundary():
    """:func:`verify.solve.boundary`, imported on first use (kept: an import statement costs more
    than a certified edge at 15 digits)."""
    if not _SQUARE:
        from .solve import boundary

        _SQUARE.append(boundary)
    return _SQUARE[0]


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
    :func:`verify.ramp.ramp_boundary`, for ``"sine"`` those of
    :func:`verify.smooth.sine_boundary`, as a :class:`verify.solve.Boundary` (pendulum, no
    friction, the certified method)."""
    sysv = as_system(system, getattr(system, "duty", duty)) if modulation != "square" else None
    kind, S = as_modulation(modulation, switch_time, sysv or system)
    if kind == "square":
        return _square_boundary()(
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
    _friction(kind, Q, damping, edges=True)
    if method != "certified" or tol is not None:
        raise InputError(
            f"the {kind} modulation has the certified method only (got method {method!r}"
            + (f", tol {tol}" if tol is not None else "")
            + ")"
        )
    if kind == "sine":
        from .smooth import sine_boundary

        return sine_boundary(order, m, digits=digits)
    from .ramp import ramp_boundary

    return ramp_boundary(order, m, S, duty=sysv.duty, digits=digits).boundary


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
    """:func:`verify.multipliers.multipliers` (the same arguments), with the monodromy of the
    ramp (``switch_time`` in units of ``T0``) or of the sine modulation."""
    from .multipliers import multipliers as mult

    kind, S = as_modulation(modulation, switch_time, system)
    if kind == "square":
        return mult(T, m, Q=Q, damping=damping, digits=digits, system=system, duty=duty)
    sysv = as_system(system, getattr(system, "duty", duty))
    as_modulation(kind, switch_time, sysv)  # the duty, now that it is known
    _friction(kind, Q, damping, edges=False)
    QQ = as_quality(Q)
    QQ = None if QQ is None else Fraction(QQ) if not hasattr(QQ, "_mpf_") else QQ
    if kind == "ramp":
        from .ramp import check_fits, ramp_monodromy_arb

        def monodromy(mm, TT):
            check_fits(S, TT, sysv.duty)
            if QQ is None:
                return ramp_monodromy_arb(mm, TT, S, sysv.duty)
            from .smooth import ramp_monodromy_damped_arb

            return _velocity(ramp_monodromy_damped_arb(mm, TT, S, QQ, sysv.duty), 1 + mm)

        how = "Bessel route" if QQ is None else "validated Taylor integration"
        note = (
            f"ramp modulation: the length changes linearly during S = {_text(S)} T0 at each "
            f"switch ({how})"
        )
    else:
        from .smooth import sine_monodromy_arb

        def monodromy(mm, TT):
            return _velocity(sine_monodromy_arb(mm, TT, QQ), 1)

        note = (
            "sine modulation l = 1 + m sin(2 pi t/T) (validated Taylor integration in ball "
            "arithmetic)"
        )
    return mult(T, m, Q=Q, digits=digits, system=sysv, _monodromy=monodromy, _notes=(note,))


def _velocity(M, l):
    """The period map of ``(phi, p = l^2 phi')`` turned into one of ``(phi, phi')`` at a point
    where the length is ``l`` (exact): the multipliers are the same, the entries the usual."""
    from flint import arb, fmpq

    lf = Fraction(l)
    L = arb(fmpq(lf.numerator, lf.denominator)) ** 2
    a, b, c, d = M
    return a, b * L, c / L, d


def _text(x: Fraction) -> str:
    return str(x.numerator) if x.denominator == 1 else f"{x.numerator}/{x.denominator}"
