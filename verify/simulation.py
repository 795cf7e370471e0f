"""The result of a time-domain run (:func:`verify.timedomain.simulate`): the sampled segments and
the figures measured on the trajectory."""

from __future__ import annotations

import functools
import math
from dataclasses import dataclass, field
from fractions import Fraction

import mpmath
import numpy as np

from analytic.system import PAPER

__all__ = ["Segment", "Simulation"]


@dataclass(frozen=True)
class Segment:
    """One half period of a trajectory, sampled for plotting (double precision).

    ``half`` is 1 (bob down) or 2 (bob up); ``t`` runs over ``[t0, t0 + T/2]``; ``phi`` and ``dphi``
    are the angle and the angular velocity (for the paper damping model: the model's velocity).
    """

    half: int
    t: np.ndarray
    phi: np.ndarray
    dphi: np.ndarray


@dataclass(frozen=True)
class Simulation:
    """A run and what was measured on it.

    ``strobe``: the states ``(phi, phi')`` at ``t = kT`` (just after the jump into the bob-down
    half), ``k = 0..max(periods, 2)`` (mpf for the linear model at ``digits``, float for the
    nonlinear one).  ``closure_error``: on an edge, ``|s_P - s_0| / |s_0|`` with ``P = 2`` (odd
    order) or ``1`` (even) in the amplitude norm; ``None`` elsewhere.  ``measured_multipliers``:
    from the stroboscopic sequence (one value when the start was an eigenvector).
    ``multipliers``: from :mod:`verify.floquet`.  ``envelope``: the largest ``|phi|`` in each
    period (linear model: from the samples; nonlinear: the largest ``|phi|`` of the cubic Hermite
    interpolant between the integrator's steps, the same curve the samples come from).
    """

    order: int
    m: Fraction | mpmath.mpf
    tau: mpmath.mpf
    Q: Fraction | mpmath.mpf | None
    damping: str
    edge: str | None
    edge_kind: str | None
    nonlinear: bool
    periods: int
    amplitude: Fraction
    digits: int
    initial: tuple
    strobe: tuple
    closure_periods: int
    closure_error: mpmath.mpf | float | None
    max_return_error: mpmath.mpf | float | None
    measured_multipliers: tuple
    multipliers: tuple
    interval: tuple | None
    envelope: tuple[float, ...] = field(repr=False)
    method: str = ""
    rtol: float | None = None
    atol: float | None = None
    saturation_estimate: float | None = None
    #: the member of the family (:mod:`analytic.system`)
    system: object = PAPER
    #: the plotted segments, or a function computing them when first asked for (:attr:`segments`)
    dense: object = field(default=(), repr=False, compare=False)

    @functools.cached_property
    def segments(self) -> tuple[Segment, ...]:
        """The trajectory sampled for plotting, one :class:`Segment` per half period of the first
        ``periods`` periods (computed on first use for the nonlinear model)."""
        return tuple(self.dense() if callable(self.dense) else self.dense)

    # -- derived figures ---------------------------------------------------------------------

    @property
    def growth_per_period(self):
        """The measured growth per period: the largest modulus of the measured multipliers."""
        with mpmath.workdps(self.digits):
            return +max(abs(mpmath.mpmathify(x)) for x in self.measured_multipliers)

    @property
    def floquet_multiplier(self):
        """The Floquet multiplier of the largest modulus (:mod:`verify.floquet`)."""
        return self.multipliers[0]

    @property
    def floquet_growth(self):
        with mpmath.workdps(self.digits):
            return +abs(mpmath.mpmathify(self.multipliers[0]))

    @property
    def growth_agreement(self):
        """``|measured growth - max |mu|| / max |mu|``."""
        with mpmath.workdps(self.digits):
            g = self.floquet_growth
            return abs(self.growth_per_period - g) / g

    @property
    def jump_times(self) -> np.ndarray:
        return np.array([s.t[0] for s in self.segments[1:]])

    @property
    def peak_amplitude(self) -> float:
        return max(self.envelope) if self.envelope else float("nan")

    @property
    def rotates(self) -> bool | None:
        """Nonlinear runs: whether the pendulum went over the top (``|phi|`` passed ``pi``), after
        which it rotates instead of swinging and the growth is no longer limited by the
        amplitude-dependent period; ``None`` for the linear model."""
        if not self.nonlinear:
            return None
        return bool(self.envelope) and max(self.envelope) > math.pi

    def __str__(self) -> str:
        def show(x, digits):
            if x is None:
                return "-"
            with mpmath.workdps(max(digits, 15)):
                return mpmath.nstr(mpmath.mpmathify(x), digits)

        fr = "no friction" if self.Q is None else f"Q = {self.Q} ({self.damping} model)"
        where = f"on the {self.edge} edge" if self.edge else "at a given period"
        model = "nonlinear pendulum" if self.nonlinear else f"linear model, {self.digits} digits"
        lines = [
            f"Simulation: order {self.order}, m = {self.m}, {fr}, {self.periods} periods ({model})",
            f"  T/T0 = {show(self.tau, min(self.digits, 20))} ({where})",
        ]
        if self.closure_error is not None:
            lines.append(
                f"  closure error after {self.closure_periods} T: {show(self.closure_error, 3)}"
            )
        lines.append(
            f"  growth per period: measured {show(self.growth_per_period, 12)}, Floquet "
            f"{show(self.floquet_growth, 12)}"
        )
        if self.nonlinear:
            lines.append(f"  peak |phi| = {self.peak_amplitude:.6g} rad")
            if self.rotates:
                lines.append("  the pendulum went over the top (|phi| > pi): it rotates")
        return "\n".join(lines)

    @property
    def inside(self) -> bool | None:
        """Whether ``T`` lies strictly inside the interval of the order (``None``: none exists)."""
        if self.interval is None:
            return None
        lo, hi = self.interval
        return bool(lo < self.tau < hi)

    def as_json(self) -> dict:
        d = self.digits

        def num(x):
            if x is None:
                return None
            x = mpmath.mpmathify(x)
            if isinstance(x, mpmath.mpc):
                return {"re": float(x.real), "im": float(x.imag)}
            return float(x)

        def text(x):
            if x is None:
                return None
            with mpmath.workdps(d):
                return mpmath.nstr(mpmath.mpmathify(x), d, min_fixed=-5, max_fixed=5)

        out = {
            **self.system.as_json(),
            "closure_error": num(self.closure_error),
            "growth_per_period": num(self.growth_per_period),
            "floquet_multiplier": num(self.floquet_multiplier),
            "method": self.method,
            "order": self.order,
            "m": str(self.m),
            "T": text(self.tau),
            "Q": None if self.Q is None else str(self.Q),
            "damping": self.damping,
            "edge": self.edge,
            "edge_kind": self.edge_kind,
            "nonlinear": self.nonlinear,
            "periods": self.periods,
            "amplitude": float(self.amplitude),
            "digits": None if self.nonlinear else d,
            "initial": [text(x) for x in self.initial],
            "closure_periods": self.closure_periods,
            "max_return_error": num(self.max_return_error),
            "measured_multipliers": [num(x) for x in self.measured_multipliers],
            "floquet_multipliers": [num(x) for x in self.multipliers],
            "growth_agreement": num(self.growth_agreement),
            "interval": None if self.interval is None else [text(x) for x in self.interval],
            "inside_interval": self.inside,
        }
        if self.nonlinear:
            out["rtol"], out["atol"] = self.rtol, self.atol
            out["peak_amplitude"] = self.peak_amplitude
            out["rotates"] = self.rotates
            out["saturation_estimate"] = self.saturation_estimate
            out["envelope"] = list(self.envelope)
        return out
