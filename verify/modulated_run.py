"""Time-domain runs with a length that varies in time: the ramp (finite switching time) and the
sine modulation.

The pendulum obeys ``(l^2 phi')' + 2 gamma l^2 phi' + g l f(phi) = 0`` (``f = phi`` linear,
``sin phi`` with ``nonlinear=True``), integrated in the state ``(phi, p = l^2 phi')`` by
:func:`scipy.integrate.solve_ivp` (DOP853, ``rtol = 1e-12``), piece by piece where ``l(t)`` has a
kink (the ends of the ramps).  This is an ordinary double-precision integration of the equation
itself, independent of the Bessel maps and of the validated integrator, so its agreement with
the certified multipliers is a check.  Units: time in ``T0``, ``g = 4 pi^2``, ``gamma = pi/Q``.

On an edge (``edge="lower"|"upper"``, no friction) the period is the certified edge of the
modulation (:func:`verify.modulation.boundary`) and the run starts from the Floquet vector of the
multiplier ``(-1)^n`` (of the double-precision period map); the closure error after ``2T`` (odd
orders) or ``T`` (even) is reported.  At a period ``T`` the run starts at rest at the angle
``amplitude``; the growth per period measured on the run is compared with the certified
multipliers (:func:`verify.modulation.multipliers`).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from fractions import Fraction

import numpy as np

from .inputs import InputError, as_depth, as_modulation, as_order, as_period, as_quality
from .params import exact_fraction
from .pendulum_ode import MAX_STEPS, MAX_STEPS_PER_PERIOD, too_fast

__all__ = ["ModulatedRun", "simulate_modulated"]

_G = 4 * math.pi**2


@dataclass(frozen=True)
class ModulatedRun:
    order: int
    m: Fraction
    modulation: str
    switch_time: Fraction | None
    Q: Fraction | None
    T: float
    edge: str | None
    nonlinear: bool
    periods: int
    initial: tuple[float, float]
    closure_error: float | None
    growth_per_period: float
    floquet_growth: float
    peak_amplitude: float
    floquet_text: str = ""
    #: what the certified ``ln|mu|max`` is where it is exactly 0 or prints fewer than its 10 digits
    notes: tuple = ()

    @property
    def growth_agreement(self) -> float:
        return abs(self.growth_per_period - self.floquet_growth) / max(
            abs(self.floquet_growth), 1e-300
        )

    def _difference(self) -> str:
        d = abs(self.growth_per_period - self.floquet_growth)
        if abs(self.floquet_growth) > 1e-8:
            return f"{self.growth_agreement:.3g} (relative)"
        return f"{d:.3g} (absolute; the multipliers lie on the unit circle to 1e-8)"

    def as_json(self) -> dict:
        return {
            "order": self.order,
            "m": str(self.m),
            "modulation": self.modulation,
            "switch_time": None if self.switch_time is None else str(self.switch_time),
            "Q": None if self.Q is None else str(self.Q),
            "T": f"{self.T:.15g}",
            "edge": self.edge,
            "nonlinear": self.nonlinear,
            "periods": self.periods,
            "initial": [f"{x:.12g}" for x in self.initial],
            "closure_error": None if self.closure_error is None else f"{self.closure_error:.3g}",
            "growth_per_period": f"{self.growth_per_period:.10g}",
            "floquet_growth": self.floquet_text,
            "difference": self._difference(),
            "peak_amplitude": f"{self.peak_amplitude:.6g}",
            "method": "scipy solve_ivp DOP853 (rtol 1e-12), double precision, not certified",
            "notes": list(self.notes),
        }

    def __str__(self) -> str:
        mod = self.modulation + (
            f", S = {self.switch_time} T0" if self.switch_time is not None else ""
        )
        fr = "no friction" if self.Q is None else f"Q = {self.Q}"
        where = f"{self.edge} edge" if self.edge else "given period"
        lines = [
            f"order {self.order}, m = {self.m}, {mod}, {fr}",
            f"  T/T0 = {self.T:.15g} ({where})",
            "  method: (l^2 phi')' + 2 gamma l^2 phi' + g l "
            + ("sin(phi)" if self.nonlinear else "phi")
            + " = 0 by scipy solve_ivp DOP853 (rtol 1e-12), double precision, not certified",
            f"  initial (phi, phi'): ({self.initial[0]:.12g}, {self.initial[1]:.12g})",
        ]
        if self.closure_error is not None:
            after = "2T" if self.order % 2 else "T"
            lines.append(f"  closure error after {after}: {self.closure_error:.3g} (relative)")
        lines += [
            f"  growth per period, measured: {self.growth_per_period:.10g}",
            f"  ln|mu|max (certified):       {self.floquet_text}",
            f"  difference:                  {self._difference()}",
            f"  peak amplitude over {self.periods} periods: {self.peak_amplitude:.6g} rad",
        ]
        lines += [f"  note: {note}" for note in self.notes]
        return "\n".join(lines)


def _pieces(m: float, T: float, S: float | None, kind: str):
    """``[(t_a, t_b, l(t), dl/dt)]`` over one period from the start ``t0`` (``S/2`` or 0)."""
    if kind == "sine":
        w = 2 * math.pi / T
        return [(0.0, T, lambda t: 1 + m * math.sin(w * t))]
    l1, l2 = 1 + m, 1 - m
    D = 0.5
    a, b, c, d = S / 2, D * T - S / 2, D * T + S / 2, T - S / 2
    out = [(a, b, lambda t: l1)]
    if S > 0:
        out.append((b, c, lambda t: l1 + (l2 - l1) * (t - b) / S))
    out.append((c, d, lambda t: l2))
    if S > 0:
        out.append((d, T + S / 2, lambda t: l2 + (l1 - l2) * (t - d) / S))
    return out


def _strobe_growth(states) -> float:
    """``ln max |mu|`` measured on the states once per period: ``y_{k+2} = a y_{k+1} - b y_k``
    (Cayley-Hamilton for the period map) fitted by least squares over the run (both
    components), ``mu`` the roots of ``x^2 - a x + b``; with fewer than three states the mean
    growth of the norm."""
    Y = np.array(states)
    if len(Y) < 3:
        return math.log(np.linalg.norm(Y[-1]) / np.linalg.norm(Y[0])) / (len(Y) - 1)
    scale = np.linalg.norm(Y, axis=1)[:-2, None]  # keep late, grown states from dominating
    A = np.concatenate([(Y[1:-1] / scale).ravel()[:, None], (-Y[:-2] / scale).ravel()[:, None]], 1)
    rhs = (Y[2:] / scale).ravel()
    (a, b), *_ = np.linalg.lstsq(A, rhs, rcond=None)
    mu = np.roots([1.0, -a, b])
    return float(math.log(max(abs(mu))))


class _OverBudget(Exception):
    """Raised by the right-hand side of a run past its budget of evaluations."""


#: evaluations of the right-hand side per step of DOP853 (its stages)
_STAGES = 12


def _propagate(y, pieces, T, periods, gamma, nonlinear, peak):
    """The states once per period over ``periods`` periods; a run that needs more than
    :data:`verify.pendulum_ode.MAX_STEPS_PER_PERIOD` steps per period so far (counted as
    evaluations of the right-hand side over DOP853's 12 stages), or more than
    :data:`~verify.pendulum_ode.MAX_STEPS`, stops with :func:`~verify.pendulum_ode.too_fast`'s
    refusal."""
    from scipy.integrate import solve_ivp

    f = math.sin if nonlinear else (lambda x: x)
    states = [np.array(y, dtype=float)]
    calls = [0, 0]  # evaluations so far, and the most allowed by the end of this period
    for k in range(periods):
        budget = min(MAX_STEPS_PER_PERIOD * (k + 1), MAX_STEPS)
        calls[1] = _STAGES * budget
        for ta, tb, l in pieces:

            def rhs(t, u, l=l):
                calls[0] += 1
                if calls[0] > calls[1]:
                    raise _OverBudget
                L = l(t)
                return [u[1] / (L * L), -2 * gamma * u[1] - _G * L * f(u[0])]

            try:
                sol = solve_ivp(rhs, (ta, tb), y, method="DOP853", rtol=1e-12, atol=1e-14)
            except _OverBudget:
                raise too_fast(budget, k, periods) from None
            y = sol.y[:, -1]
            peak[0] = max(peak[0], float(np.max(np.abs(sol.y[0]))))
        states.append(np.array(y))
    return states


def simulate_modulated(
    order,
    m,
    *,
    modulation,
    switch_time=None,
    edge=None,
    T=None,
    Q=None,
    periods=8,
    amplitude="0.1",
    nonlinear=False,
) -> ModulatedRun:
    """A run of the ramp or sine modulation (see the module's docstring)."""
    from .modulation import boundary, multipliers
    from .solve import proven_text

    n = as_order(order)
    mm = exact_fraction(as_depth(m))
    kind, S = as_modulation(modulation, switch_time, "pendulum")
    if kind == "square":
        raise InputError("the square wave is run by verify.timedomain.simulate")
    QQ = as_quality(Q)
    QQ = None if QQ is None else exact_fraction(QQ)
    if (edge is None) == (T is None):
        raise InputError("give either an edge (lower|upper) or a period T")
    if edge is not None:
        if edge not in ("lower", "upper"):
            raise InputError(f"edge {edge!r} is not one of: lower, upper")
        if QQ is not None:
            raise InputError(f"the {kind} modulation's edges are implemented without friction only")
        b = boundary(n, mm, digits=20, modulation=kind, switch_time=S)
        TT = exact_fraction(b.lower if edge == "lower" else b.upper)
    else:
        TT = exact_fraction(as_period(T))
    K = int(periods)
    if not 1 <= K <= 2000:
        raise InputError(f"periods {periods} outside the allowed range 1 to 2000")
    A = float(Fraction(str(amplitude)))
    if not 0 < A < math.pi:
        raise InputError(f"amplitude {amplitude} outside the allowed range 0 < A < pi")
    mf, Tf = float(mm), float(TT)
    Sf = None if S is None else float(S)
    gamma = 0.0 if QQ is None else math.pi / float(QQ)
    pieces = _pieces(mf, Tf, Sf, kind)
    l0 = pieces[0][2](pieces[0][0])
    mu = multipliers(TT, mm, Q=QQ, digits=15, modulation=kind, switch_time=S)
    if edge is not None:
        # the Floquet vector of the multiplier (-1)^n of the period map (double precision)
        cols = [
            _propagate(list(e), pieces, Tf, 1, gamma, False, [0.0])[1] for e in ([1, 0], [0, 1])
        ]
        M = np.array([[cols[0][0], cols[1][0]], [cols[0][1], cols[1][1]]])
        sigma = (-1) ** n
        w, V = np.linalg.eig(M)
        v = np.real(V[:, int(np.argmin(np.abs(w - sigma)))])
        y0 = list(A * v / np.max(np.abs(v)))
    else:
        y0 = [A, 0.0]
    peak = [abs(y0[0])]
    states = _propagate(y0, pieces, Tf, K, gamma, nonlinear, peak)

    def vel(y):  # (phi, phi') at the start time, where the length is l0
        return np.array([y[0], y[1] / (l0 * l0)])

    closure = None
    if edge is not None:
        k = 2 if n % 2 else 1
        if K >= k:
            closure = float(
                np.linalg.norm(vel(states[k]) - vel(states[0])) / np.linalg.norm(vel(states[0]))
            )
    if edge is not None:  # the run stays on the Floquet vector: the mean growth of the norm
        growth = math.log(np.linalg.norm(vel(states[-1])) / np.linalg.norm(vel(states[0]))) / K
    else:
        growth = _strobe_growth([vel(y) for y in states])
    text = proven_text(mu.growth, mu.growth_radius, _FLOQUET_DIGITS)
    return ModulatedRun(
        order=n,
        m=mm,
        modulation=kind,
        switch_time=S,
        Q=QQ,
        T=Tf,
        edge=edge,
        nonlinear=bool(nonlinear),
        periods=K,
        initial=tuple(float(x) for x in vel(np.array(y0))),
        closure_error=closure,
        growth_per_period=growth,
        floquet_growth=float(mu.growth),
        peak_amplitude=peak[0],
        floquet_text=text,
        notes=_growth_notes(mu, text, _FLOQUET_DIGITS),
    )


#: the digits of the certified ``ln|mu|max`` a run prints
_FLOQUET_DIGITS = 10


def _growth_notes(mu, text: str, digits: int) -> tuple:
    """What the printed certified ``ln|mu|max`` (``text``, ``digits`` asked) is, where a bare
    number would not say it: exactly 0, or fewer digits than asked and why."""
    from .multipliers import significant_digits

    if mu.growth_exact:
        return (
            "ln|mu|max (certified) is 0 exactly: the multipliers are a proven complex pair on the "
            "unit circle",
        )
    shown = significant_digits(text)
    if shown >= digits:
        return ()
    why = (
        "the two multipliers are not separated at the working precision (a double multiplier, "
        "as on an edge, or one within the error bound)"
        if mu.double
        else "its ball is still too wide at the largest working precision tried"
    )
    return (
        f"ln|mu|max (certified) prints {shown} of {digits} digits: {why}; every digit printed "
        "is proven",
    )
