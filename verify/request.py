"""A checked request for the edges of one interval: what every solver of :mod:`verify.methods`
takes.  :func:`make_request` checks the user's arguments (through :mod:`verify.inputs`) and turns
them into exact values."""

from __future__ import annotations

from dataclasses import dataclass, fields
from fractions import Fraction

from analytic.system import PAPER, System

from .inputs import (
    BOUNDARY_DIGITS_RANGE,
    InputError,
    as_damping,
    as_depth,
    as_digits,
    as_order,
    as_quality,
    as_system,
    as_tolerance,
)
from .params import exact_fraction

__all__ = ["Request", "make_request"]


@dataclass(frozen=True)
class Request:
    """A checked request: order, exact depth and quality factor, model, digits."""

    order: int
    m: Fraction
    Q: Fraction | None
    damping: str
    digits: int
    m_input: object = None
    #: relative tolerance of ``T/T0`` for ``method="auto"`` (:mod:`verify.auto`)
    tol: object = None
    #: the member of the family (:mod:`analytic.system`); the paper's pendulum by default
    system: System = PAPER

    @property
    def parity_sign(self) -> int:
        return -1 if self.order % 2 else 1


def make_request(order, m, Q, damping, digits, method, tol, system, duty) -> tuple[Request, str]:
    """Check the arguments of :func:`verify.solve.boundary`; returns the request and the method
    (``"auto"`` when a tolerance is given).  Raises :class:`~verify.inputs.InputError` on bad
    input, naming the value and what is allowed."""
    n = as_order(order)
    sysv = as_system(system, duty)
    mm = as_depth(m) if sysv.uses_depth or m is not None else None
    if not sysv.uses_depth and m is not None:
        raise InputError(f"a custom system has no depth: leave m out (got m = {m!r})")
    QQ = as_quality(Q)
    model = as_damping(damping)
    d = as_digits(digits, BOUNDARY_DIGITS_RANGE)
    tt = None
    if tol is not None or method == "auto":
        if method not in ("certified", "auto"):
            raise InputError(f"tol chooses the method itself; it cannot go with {method!r}")
        if tol is None:
            raise InputError("method 'auto' needs a tolerance (--tol)")
        tt, method = as_tolerance(tol), "auto"
    QF = None if QQ is None else exact_fraction(QQ)
    if sysv is PAPER or sysv.is_paper:
        return _request(n, exact_fraction(mm), QF, model, d, mm, tt, PAPER), method
    if tt is not None:  # (method is 'auto' here)
        raise InputError(
            f"a tolerance (--tol) chooses among methods built for the paper's system; use "
            f"--digits for {sysv.label}"
        )
    if method != "certified":
        raise InputError(
            f"method {method!r} is for the paper's system only; {sysv.label} uses 'certified'"
        )
    return Request(
        n, None if mm is None else exact_fraction(mm), QF, model, d, mm, tt, sysv
    ), method


def _request(*values) -> Request:
    """``Request(*values)`` (every field) without the frozen dataclass's ``__init__`` (one
    ``object.__setattr__`` per field: a sizeable part of a certified edge at 15 digits)."""
    obj = object.__new__(Request)
    obj.__dict__.update(zip(_FIELDS, values, strict=True))
    return obj


_FIELDS = tuple(f.name for f in fields(Request))
