"""Time-domain simulation: the pendulum followed through the jumps, half period by half period.

Two models:

* **linear** (``sin phi -> phi``): exact piecewise propagation.  Each half period is a free
  oscillation whose map of ``(phi, phi')`` over a time ``t`` is the propagator that
  :mod:`analytic.stitching` derives from the model's segments (:func:`analytic.model.segment`, for
  the damping model and the regime of the half: under-, critically or over-damped), lambdified once
  to mpmath and numpy; the jump multiplies ``phi'`` by the derived ratio of the moments of inertia.
  Any precision (``digits``), everything inside ``mpmath.workdps``.
* **nonlinear** (``phi'' + 2 gamma phi' + omega_i**2 sin phi = 0``): integrated between the jumps by
  :class:`scipy.integrate.ode` (Hairer's DOP853, explicit ``rtol``/``atol``), the same jump rule.

Where the run starts:

* on an edge of the interval of order ``n`` (``edge="lower"``/``"upper"``, the period from
  :func:`verify.boundary`): without friction from the stationary initial condition derived from
  the symmetric boundary shapes (:func:`analytic.reductions.stationary_initial_condition`,
  ``phi'(0)/phi(0) = omega1 tan(omega1 T/4)`` or ``-omega1 cot(omega1 T/4)``; which shape belongs
  to the edge is decided by which per-edge factor (:func:`analytic.normal_form.edge_factor`)
  vanishes there); with friction from the eigenvector of the monodromy (:mod:`verify.floquet`)
  for the multiplier ``(-1)**n``.  The state after ``2T`` (odd ``n``) or ``T`` (even ``n``) must
  equal the start: the *closure error* measures that, and is at the level of the working precision
  when the edge is known to that precision.
* at a given period ``T``: from rest at the angle ``amplitude`` (released as the bob moves down).
* anywhere: from a given ``initial`` state ``(phi, phi')`` (on an edge this replaces the stationary
  start; the closure error then says whether that start returns -- at a closing every start does).

What is measured, from the trajectory alone: the states at ``t = kT`` (the stroboscopic sequence
``s_k``) obey ``s_{k+2} = tr(M) s_{k+1} - det(M) s_k`` (Cayley-Hamilton), two equations for the
two unknowns; their roots are the *measured multipliers* and the larger modulus is the measured
growth per period.  It is compared with :func:`verify.floquet.floquet_multipliers`.  When the start
is itself an eigenvector (a stationary start) the sequence determines only that multiplier,
``s_1 = mu s_0``.

The amplitude of a state is ``sqrt(phi**2 + (phi'/omega1)**2)``: the amplitude of the undamped free
oscillation of the bob-down half through that state.
"""

from __future__ import annotations

import functools
import math
from dataclasses import dataclass, field
from fractions import Fraction
from functools import cache

import mpmath
import numpy as np

from analytic.system import PAPER, phase_regimes

from .inputs import (
    InputError,
    as_damping,
    as_depth,
    as_digits,
    as_number,
    as_order,
    as_period,
    as_quality,
    as_system,
)
from .params import exact_fraction

__all__ = [
    "Simulation",
    "Segment",
    "simulate",
    "EDGES",
    "MAX_PERIODS",
    "as_amplitude",
    "as_periods",
    "amplitude_factor",
]

EDGES = ("lower", "upper")
#: the most modulation periods one run may follow
MAX_PERIODS = 10_000
#: guard digits for the linear propagation
_GUARD = 10
#: default integration tolerances of the nonlinear model
RTOL, ATOL = 1e-10, 1e-13


# ---------------------------------------------------------------------------------------------
# input checks specific to a run


def as_periods(K) -> int:
    """Number of modulation periods to follow: an integer ``1 <= K <= MAX_PERIODS``."""
    try:
        if isinstance(K, bool):
            raise TypeError
        val = int(K.strip()) if isinstance(K, str) else int(K)
        if val != K and not isinstance(K, str):
            raise TypeError
    except (TypeError, ValueError):
        raise InputError(
            f"periods {K!r} is not an integer; allowed range 1 to {MAX_PERIODS}"
        ) from None
    if not 1 <= val <= MAX_PERIODS:
        raise InputError(f"periods {val} is outside the allowed range 1 to {MAX_PERIODS}")
    return val


def as_amplitude(A) -> Fraction:
    """The initial amplitude in radians, ``0 < A < pi`` (an angle beyond ``pi`` is not a swing),
    kept exact (``"0.1"`` is ``1/10``; a float means its shortest decimal)."""
    val = as_number(A, name="amplitude", allowed="0 < A < pi")
    if not 0 < val < math.pi:
        raise InputError(f"amplitude {A!r} is outside the allowed range 0 < A < pi (radians)")
    return val


# ---------------------------------------------------------------------------------------------
# the derived building blocks, lambdified once


def _regime(m, Q, half: int, model: str, system=PAPER) -> str:
    """``"under"``, ``"critical"`` or ``"over"``: the sign of ``omega_i**2 - gamma**2``
    (:func:`analytic.system.phase_regimes`, exact for rational ``m`` and ``Q``)."""
    if Q is None or model == "paper":
        return "under"
    mq = m if isinstance(m, Fraction) else exact_fraction(m)
    Qq = Q if isinstance(Q, Fraction) else exact_fraction(Q)
    return phase_regimes(system, mq, Qq, model)[half - 1]


@cache
def _propagator(model: str, regime: str, half: int, module: str):
    """``(t, omega, gamma, Omega, Lambda) -> [[a, b], [c, d]]`` from
    :func:`analytic.stitching.propagator` of the model's segment (the entries as four functions)."""
    import sympy as sp

    from analytic.model import Damping, Regime, S, segment
    from analytic.stitching import propagator

    damping = {"none": Damping.NONE, "paper": Damping.PAPER, "exact": Damping.EXACT}[model]
    omega = S.omega1 if half == 1 else S.omega2
    Omega = S.Omega1 if half == 1 else S.Omega2
    Lam = S.Lambda1 if half == 1 else S.Lambda2
    seg = segment(omega, S.A1, S.B1, damping, Regime(regime))
    U = propagator(seg, S.t)
    args = (S.t, omega, S.gamma, Omega, Lam)
    return tuple(sp.lambdify(args, U[i, j], modules=module) for i in (0, 1) for j in (0, 1))


@cache
def _jump(module: str):
    """The factor on ``phi'`` at the jumps 1 -> 2 and 2 -> 1 (:func:`analytic.model.jump_ratio`)."""
    import sympy as sp

    from analytic.model import S, jump_ratio

    return (
        sp.lambdify((S.m,), jump_ratio(1, 2), modules=module),
        sp.lambdify((S.m,), jump_ratio(2, 1), modules=module),
    )


@cache
def _initial_ratio(kind_value: str):
    """``phi'(0)/phi(0)`` on an undamped edge of the given shape, as ``(m, tau) -> (num, den)``:
    the derived ratio is split into numerator and denominator so a vanishing ``phi(0)`` is fine."""
    import sympy as sp

    from analytic.model import S, physical
    from analytic.reductions import stationary_initial_condition
    from analytic.stitching import EdgeKind

    ratio = physical(stationary_initial_condition(EdgeKind(kind_value)), damping=False)
    ratio = ratio.replace(sp.tan, lambda u: sp.sin(u) / sp.cos(u))
    ratio = ratio.replace(sp.cot, lambda u: sp.cos(u) / sp.sin(u))
    num, den = sp.fraction(sp.together(ratio))
    return (
        sp.lambdify((S.m, S.tau), num, modules="mpmath"),
        sp.lambdify((S.m, S.tau), den, modules="mpmath"),
    )


@cache
def _edge_factors(parity_value: int):
    """The two undamped per-edge factors of the parity, ``{kind: f(m, tau)}`` (mpmath), in the
    physical units, from :func:`analytic.normal_form.edge_factor`."""
    import sympy as sp

    from analytic.model import S, inertia, physical
    from analytic.normal_form import edge_factor
    from analytic.stitching import EdgeKind, Parity

    parity = Parity(parity_value)
    a1, a2 = S.omega1 * S.T / 2, S.omega2 * S.T / 2
    q = inertia(1) * S.omega1 / (inertia(2) * S.omega2)
    r = (q - 1) / (q + 1)
    out = {}
    for kind in EdgeKind:
        if kind.parity is not parity:
            continue
        f = edge_factor(parity, kind.epsilon, symbols=((a1 + a2) / 2, (a2 - a1) / 2, r))
        f = physical(f, damping=False)
        out[kind] = sp.lambdify((S.m, S.tau), f, modules="mpmath")
    return out


def _mp(x) -> mpmath.mpf:
    if isinstance(x, Fraction):
        return mpmath.mpf(x.numerator) / x.denominator
    return mpmath.mpf(x)


# ---------------------------------------------------------------------------------------------
# the result


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


# ---------------------------------------------------------------------------------------------
# the run


def amplitude_factor(A: float) -> float:
    """The period of the free pendulum of amplitude ``A`` over that of small swings,
    ``2 K(sin^2(A/2)) / pi`` (``K`` the complete elliptic integral of the first kind)."""
    from scipy.special import ellipk

    return float(2 * ellipk(math.sin(A / 2) ** 2) / math.pi)


def _saturation_estimate(tau, interval) -> float | None:
    """The amplitude at which the lengthening of the free periods carries the lower edge of the
    interval past ``T``: ``amplitude_factor(A) = T / T_-`` (adiabatic estimate; ``None`` when
    ``T`` is not inside the interval)."""
    if interval is None:
        return None
    lo, hi = (float(x) for x in interval)
    t = float(tau)
    if not lo < t < hi:
        return None
    target = t / lo
    a, b = 1e-9, math.pi - 1e-12
    for _ in range(60):  # the bracket, pi wide, below an ulp of the result
        c = (a + b) / 2
        if amplitude_factor(c) < target:
            a = c
        else:
            b = c
    return (a + b) / 2


class _LazyStates:
    """The stroboscopic states as mpmath numbers, converted when first used (a long nonlinear run
    needs only the first few and the last two)."""

    def __init__(self, strobe):
        self._raw = strobe
        self._done: dict = {}

    def __len__(self) -> int:
        return len(self._raw)

    def __getitem__(self, k):
        k = k % len(self._raw)
        out = self._done.get(k)
        if out is None:
            a, b = self._raw[k]
            out = self._done[k] = (mpmath.mpmathify(a), mpmath.mpmathify(b))
        return out


def _cayley_hamilton(strobe, digits):
    """Measured multipliers from the stroboscopic states (see the module docstring)."""
    with mpmath.workdps(digits + _GUARD):
        S = _LazyStates(strobe)
        tol = mpmath.mpf(10) ** (-(digits // 2))
        best, best_k = mpmath.mpf(-1), 0
        for k in range(len(S) - 2):
            (a0, b0), (a1, b1) = S[k], S[k + 1]
            n0, n1 = mpmath.hypot(a0, b0), mpmath.hypot(a1, b1)
            if not (n0 and n1):
                continue
            sine = abs(a1 * b0 - a0 * b1) / (n0 * n1)
            if sine > mpmath.mpf("1e-3"):  # the earliest well-conditioned triple
                best, best_k = sine, k
                break
            if sine > best:
                best, best_k = sine, k
        if best <= tol:
            # an eigen-sequence: s_{k+1} = mu s_k
            (a0, b0), (a1, b1) = S[-2], S[-1]
            mu = (a1 * a0 + b1 * b0) / (a0 * a0 + b0 * b0)
            with mpmath.workdps(digits):
                return (+mu,)
        k = best_k
        (a0, b0), (a1, b1), (a2, b2) = S[k], S[k + 1], S[k + 2]
        # [a1, -a0; b1, -b0] (tr, det) = (a2, b2)
        D = -a1 * b0 + a0 * b1
        tr = (-a2 * b0 + a0 * b2) / D
        det = (a1 * b2 - a2 * b1) / D
        disc = tr * tr - 4 * det
        if disc >= 0:
            root = mpmath.sqrt(disc)
            big = (tr + root) / 2 if tr >= 0 else (tr - root) / 2
            mus = (big, det / big)
        else:
            root = mpmath.sqrt(-disc) / 2
            mus = (mpmath.mpc(tr / 2, root), mpmath.mpc(tr / 2, -root))
        with mpmath.workdps(digits):
            return tuple(+x for x in mus)


def _norm(s, w1):
    return mpmath.sqrt(s[0] ** 2 + (s[1] / w1) ** 2)


def simulate(
    order,
    m,
    *,
    edge: str | None = None,
    T=None,
    Q=None,
    damping: str = "exact",
    periods=None,
    amplitude=0.1,
    initial=None,
    nonlinear: bool = False,
    digits=30,
    samples: int | None = None,
    rtol: float = RTOL,
    atol: float = ATOL,
    progress=None,
    system="pendulum",
    duty="1/2",
) -> Simulation:
    """Follow the pendulum for ``periods`` modulation periods; see the module docstring.

    Exactly one of ``edge`` (``"lower"`` / ``"upper"``: the edge of the interval of ``order`` at
    ``m``, ``Q``) and ``T`` (the period, in units of ``T0``) is given.  ``periods`` defaults to 8
    (linear) or 200 (nonlinear).  ``digits`` is the working precision of the linear model (and of
    the edge period).  ``samples`` per half period for the plotted segments (default: fewer when
    the run is long).  ``initial``: a start ``(phi, phi')`` in rad and rad/T0 (then ``amplitude`` is
    not used).  ``progress``: an optional wrapper for the loop over periods (e.g.
    :func:`reports.output.progress`).  ``system``, ``duty``: a member of the family
    (:mod:`analytic.system`; ``m`` is ``None`` for a custom system); the nonlinear model is the
    pendulum's (``sin phi``) and is offered for ``system="pendulum"`` only.
    """
    from . import boundary
    from .existence import absence_reason
    from .floquet import floquet_multipliers, floquet_vector, monodromy_matrix

    sysv = as_system(system, duty)
    n = as_order(order)
    if sysv.uses_depth:
        m = as_depth(m)
    elif m is not None:
        raise InputError(f"a custom system has no depth: leave m out (got m = {m!r})")
    if nonlinear and sysv.name != "pendulum":
        raise InputError(
            f"the nonlinear model (sin phi) is the pendulum's; {sysv.name} is simulated linearly"
        )
    Q = as_quality(Q)
    model = as_damping(damping)
    digits = as_digits(digits)
    if (edge is None) == (T is None):
        raise InputError("give exactly one of an edge (lower or upper) and a period T")
    if edge is not None and edge not in EDGES:
        raise InputError(f"edge {edge!r} is not one of: {', '.join(EDGES)}")
    T = None if T is None else as_period(T, name="period T")
    K = as_periods(periods if periods is not None else (200 if nonlinear else 8))
    A = as_amplitude(amplitude)
    with mpmath.workdps(digits + _GUARD):
        start = None if initial is None else _as_initial(initial)
    if nonlinear and Q is not None and model == "paper":
        raise InputError(
            "the paper damping model approximates the linear solution only; "
            "the nonlinear pendulum is integrated with the exact friction term (--damping exact)"
        )
    if not (isinstance(rtol, float | int) and 1e-14 <= rtol <= 1e-3):
        raise InputError(f"rtol {rtol!r} is outside the allowed range 1e-14 to 1e-3")
    if not (isinstance(atol, float | int) and 0 < atol <= 1e-3):
        raise InputError(f"atol {atol!r} is outside the allowed range 0 < atol <= 1e-3")
    eff = "none" if Q is None else model
    sigma = -1 if n % 2 else 1
    P = 2 if n % 2 else 1
    work = digits + _GUARD

    bnd = boundary(n, m, Q=Q, damping=model, digits=work, system=sysv)
    interval = (bnd.lower, bnd.upper) if bnd.exists else None

    with mpmath.workdps(work):
        if edge is not None:
            if interval is None:
                raise InputError(
                    f"there is no interval of order {n} at m = {m}"
                    + ("" if Q is None else f", Q = {Q}: {absence_reason(n, m, Q, damping=model)}")
                )
            tau = bnd.lower if edge == "lower" else bnd.upper
        else:
            tau = _mp(T)
        tau = mpmath.mpf(tau)
        w1 = 2 * mpmath.pi * mpmath.sqrt(_mp(sysv.omega1_sq(m if sysv.uses_depth else None)))

        # the start
        kind = None
        if start is not None:
            v = start
        elif edge is not None and Q is None and sysv.is_paper:
            kind = _edge_kind(n, m, tau)
            num, den = _initial_ratio(kind)
            v = (den(_mp(m), tau), num(_mp(m), tau))  # (phi, phi') up to a factor
        elif edge is not None:
            M = monodromy_matrix(m, tau, Q, model, dps=work, system=sysv)
            v = floquet_vector(M, mpmath.mpf(sigma))
        else:
            v = (mpmath.mpf(1), mpmath.mpf(0))
        if start is not None:
            s0 = start
            A = Fraction(float(_norm(s0, w1)))
            if not 0 < A < math.pi:
                raise InputError("the initial state's amplitude must be in the range 0 < A < pi")
        else:
            if v[0] < 0 or (v[0] == 0 and v[1] < 0):
                v = (-v[0], -v[1])
            scale = _mp(A) / _norm(v, w1)
            s0 = (v[0] * scale, v[1] * scale)
        mus = floquet_multipliers(m, tau, Q, model, dps=digits, system=sysv)

    if samples is None:
        samples = int(max(16, min(256, 400_000 // (2 * K))))
    steps = max(K, 2)
    loop = range(steps) if progress is None else progress(range(steps), total=steps)
    if nonlinear:
        strobe, segments, env = _run_nonlinear(m, Q, tau, s0, loop, K, samples, rtol, atol, sysv)
        strobe_mp = _LazyStates(strobe)  # float states, read as mpf where used
        method = (
            f"nonlinear pendulum (sin phi), DOP853 (Hairer's code, scipy.integrate.ode) between "
            f"the jumps, "
            f"rtol={rtol:g}, atol={atol:g}; "
            + ("exact friction" if Q is not None else "no friction")
        )
    else:
        strobe_mp, segments = _run_linear(m, Q, eff, tau, s0, loop, K, samples, work, sysv)
        strobe = strobe_mp
        env = _envelope(segments, K)
        segments = tuple(segments)
        method = (
            f"linear model, exact piecewise propagation (closed-form segments of "
            f"analytic.stitching.propagator and the jump rule) at {digits} digits; "
            + {"none": "no friction", "exact": "exact friction", "paper": "paper friction model"}[
                eff
            ]
        )

    with mpmath.workdps(work):
        n0 = _norm(strobe_mp[0], w1)
        closure = maxret = None
        if edge is not None:
            rets = [
                _norm((strobe_mp[j][0] - strobe_mp[0][0], strobe_mp[j][1] - strobe_mp[0][1]), w1)
                / n0
                for j in range(P, len(strobe_mp), P)
            ]
            closure, maxret = rets[0], max(rets)
    measured = _cayley_hamilton(strobe_mp, digits if not nonlinear else 15)
    with mpmath.workdps(digits):
        if closure is not None:
            closure, maxret = +closure, +maxret
        if nonlinear:
            closure = None if closure is None else float(closure)
            maxret = None if maxret is None else float(maxret)
        initial = tuple(+x for x in s0)
        tau_out = +tau
        interval_out = None if interval is None else tuple(+x for x in interval)

    sat = _saturation_estimate(tau_out, interval_out) if nonlinear else None
    return Simulation(
        order=n,
        m=m,
        tau=tau_out,
        Q=Q,
        damping=eff,
        edge=edge,
        edge_kind=None if kind is None else kind,
        nonlinear=nonlinear,
        periods=K,
        amplitude=A,
        digits=digits,
        initial=initial,
        strobe=tuple(strobe),
        closure_periods=P,
        closure_error=closure,
        max_return_error=maxret,
        measured_multipliers=measured,
        multipliers=tuple(mus),
        interval=interval_out,
        dense=segments,
        envelope=env,
        method=method,
        rtol=rtol if nonlinear else None,
        atol=atol if nonlinear else None,
        saturation_estimate=sat,
        system=sysv,
    )


def _as_initial(initial) -> tuple:
    """A start ``(phi, phi')``: two finite numbers (exact rationals, strings, floats or mpf)."""
    try:
        phi, dphi = initial
        out = []
        for x in (phi, dphi):
            if isinstance(x, bool):
                raise TypeError
            if isinstance(x, str):
                x = Fraction(x.strip())
            x = _mp(x) if isinstance(x, Fraction | int) else mpmath.mpf(x)
            if not mpmath.isfinite(x):
                raise ValueError
            out.append(x)
    except (TypeError, ValueError, ZeroDivisionError):
        raise InputError(f"initial state {initial!r} is not a pair of finite numbers") from None
    if not (out[0] or out[1]):
        raise InputError("initial state (0, 0) is the rest state: nothing to simulate")
    return tuple(out)


def _edge_kind(n: int, m, tau) -> str:
    """The edge shape whose per-edge factor vanishes at ``tau`` (the smaller one in modulus)."""
    factors = _edge_factors(-1 if n % 2 else 1)
    vals = {kind: abs(f(_mp(m), tau)) for kind, f in factors.items()}
    return min(vals, key=vals.get).value


def _frequencies(m, Q, eff, work, system=PAPER):
    """``omega_i``, ``gamma``, ``Omega_i``, ``Lambda_i`` (the latter zero where not applicable),
    from the system's description (``omega0 = 2 pi``)."""
    with mpmath.workdps(work):
        g = mpmath.mpf(0) if Q is None else mpmath.pi / _mp(Q)
        out = []
        W = system.values(m if system.uses_depth else None)[:2]
        for half, Wi in ((1, W[0]), (2, W[1])):
            w = 2 * mpmath.pi * mpmath.sqrt(_mp(Wi))
            z = w * w - g * g
            reg = _regime(m, Q, half, eff, system)
            Om = mpmath.sqrt(z) if reg == "under" and eff == "exact" else mpmath.mpf(0)
            La = mpmath.sqrt(-z) if reg == "over" else mpmath.mpf(0)
            out.append((w, g, Om, La, reg))
        return out


def _run_linear(m, Q, eff, tau, s0, loop, K, samples, work, system=PAPER):
    freqs = _frequencies(m, Q, eff, work, system)
    U_mp = [_propagator(eff, freqs[h][4], h + 1, "mpmath") for h in (0, 1)]
    U_np = [_propagator(eff, freqs[h][4], h + 1, "numpy") for h in (0, 1)]
    with mpmath.workdps(work):
        if system.is_paper:
            j12, j21 = _jump("mpmath")
            mm = _mp(m)
            k12, k21 = j12(mm), j21(mm)
        else:
            k12 = _mp(Fraction(system.jump(m if system.uses_depth else None)))
            k21 = 1 / k12
        lengths = (tau * _mp(system.duty), tau - tau * _mp(system.duty))
        maps = []
        for h in (0, 1):
            w, g, Om, La, _ = freqs[h]
            maps.append([f(lengths[h], w, g, Om, La) for f in U_mp[h]])
        tgrids = [np.linspace(0.0, float(lengths[h]), samples) for h in (0, 1)]
        fl = [tuple(float(x) for x in freqs[h][:4]) for h in (0, 1)]
        with np.errstate(all="ignore"):
            dense = [
                [
                    np.broadcast_to(np.asarray(f(tgrids[h], *fl[h]), dtype=float), tgrids[h].shape)
                    for f in U_np[h]
                ]
                for h in (0, 1)
            ]
        strobe = [s0]
        segments = []
        s = s0
        for k in loop:
            for h in (0, 1):
                a, b, c, d = maps[h]
                if k < K:  # the samples for plotting (beyond double range they become inf)
                    p0, v0 = float(s[0]), float(s[1])
                    A_, B_, C_, D_ = dense[h]
                    with np.errstate(all="ignore"):
                        phi, dphi = A_ * p0 + B_ * v0, C_ * p0 + D_ * v0
                    t0 = float(k * tau + h * lengths[0])
                    segments.append(Segment(h + 1, t0 + tgrids[h], phi, dphi))
                s = (a * s[0] + b * s[1], c * s[0] + d * s[1])
                s = (s[0], s[1] * (k12 if h == 0 else k21))
            strobe.append(s)
    return strobe, segments


def _run_nonlinear(m, Q, tau, s0, loop, K, samples, rtol, atol, system=PAPER):
    """The nonlinear pendulum, half period by half period: Hairer's DOP853 (the compiled code
    behind :class:`scipy.integrate.ode`) from each jump to the next, the jump rule applied between
    them.  The integrator's accepted steps are recorded as they come (``(t, phi, phi')``); the
    samples of the plotted segments are interpolated from them afterwards, for all half periods at
    once (:func:`_hermite_segments`): no dense output inside the loop."""
    from scipy.integrate import ode

    W = system.values(m)
    w2 = [(2 * math.pi) ** 2 * float(W[0]), (2 * math.pi) ** 2 * float(W[1])]
    g = 0.0 if Q is None else math.pi / float(Q)
    k12 = float(W[2])
    lengths = (float(tau) * float(system.duty), float(tau) * (1 - float(system.duty)))
    cur = [w2[0]]
    sin = math.sin

    if g:

        def rhs(t, y):
            return [y[1], -2 * g * y[1] - cur[0] * sin(y[0])]

    else:

        def rhs(t, y):
            return [y[1], -cur[0] * sin(y[0])]

    steps: list = []
    solver = ode(rhs).set_integrator("dop853", rtol=rtol, atol=atol, nsteps=10**7)
    solver.set_solout(lambda t, y: steps.append((t, y[0], y[1])))
    s = [float(s0[0]), float(s0[1])]
    strobe = [tuple(s)]
    halves = []  # (index of the first step of the half period, w^2) per recorded half period
    jumps = (k12, 1 / k12)
    for k in loop:
        for h in (0, 1):
            cur[0] = w2[h]
            mark = len(steps)
            if k < K:
                halves.append(mark)
            solver.set_initial_value(s, 0.0)
            solver.integrate(lengths[h])
            if not solver.successful():  # pragma: no cover - DOP853 on a smooth right-hand side
                raise RuntimeError(f"integration failed in period {k} (half {h + 1})")
            if k >= K:  # beyond the plotted periods: nothing kept
                del steps[mark:]
            y = solver.y
            s = [float(y[0]), float(y[1]) * jumps[h]]
        strobe.append(tuple(s))
    env = _hermite_envelope(steps, halves, w2, g, K)

    def dense():
        return _hermite_segments(steps, halves, lengths, tau, w2, g, samples)

    return strobe, dense, env


def _hermite_envelope(steps, halves, w2, g, K) -> tuple[float, ...]:
    """The largest ``|phi|`` in each of the first ``K`` periods: on each interval between two
    accepted steps the cubic Hermite interpolant of ``phi`` (values and slopes ``phi'`` at both
    ends) takes its extreme values at the ends or where its derivative (a quadratic) vanishes."""
    if not halves:
        return tuple(float("nan") for _ in range(K))
    arr = np.asarray(steps, float)
    t, p, v = arr[:, 0], arr[:, 1], arr[:, 2]
    starts = np.asarray(halves + [len(steps)])
    inner = np.ones(len(steps), bool)
    inner[starts[1:] - 1] = False  # the last step of a half period starts no interval
    i = np.nonzero(inner)[0]
    h = t[i + 1] - t[i]
    p0, p1, m0, m1 = p[i], p[i + 1], h * v[i], h * v[i + 1]
    b = -3 * p0 - 2 * m0 + 3 * p1 - m1
    a = 2 * p0 + m0 - 2 * p1 + m1
    best = np.maximum(np.abs(p0), np.abs(p1))
    with np.errstate(invalid="ignore", divide="ignore"):
        disc = np.sqrt(b * b - 3 * a * m0)
        for x in ((-b + disc) / (3 * a), (-b - disc) / (3 * a), -m0 / (2 * b)):
            ok = (x > 0) & (x < 1)
            val = np.abs(((a * x + b) * x + m0) * x + p0)
            best = np.where(ok & (val > best), val, best)
    period = (np.searchsorted(starts[:-1], i, side="right") - 1) // 2  # period of each interval
    env = np.zeros(K)
    np.maximum.at(env, period, best)
    return tuple(float(x) for x in env)


def _hermite_segments(steps, halves, lengths, tau, w2, g, samples):
    """The plotted segments from the accepted steps: cubic Hermite interpolation of ``phi`` (with
    ``phi'``) and of ``phi'`` (with ``phi''`` from the equation of motion) between consecutive
    steps, at ``samples`` equally spaced times of each half period; all half periods at once."""
    if not halves:
        return []
    arr = np.asarray(steps, float)
    t, phi, dphi = arr[:, 0], arr[:, 1], arr[:, 2]
    starts = np.asarray(halves + [len(steps)])
    nh = len(halves)
    which = np.repeat(np.arange(nh), np.diff(starts))  # the half period of every step
    w = np.where(which % 2 == 0, w2[0], w2[1])
    acc = -2 * g * dphi - w * np.sin(phi)
    L = 2.0 * max(lengths) + 1.0
    keys = which * L + t
    halflen = np.where(np.arange(nh) % 2 == 0, lengths[0], lengths[1])
    u = np.linspace(0.0, 1.0, samples)
    ts = halflen[:, None] * u[None, :]  # (nh, samples) local times
    skeys = (np.arange(nh)[:, None] * L + ts).ravel()
    i = np.searchsorted(keys, skeys, side="right") - 1
    lo = np.repeat(starts[:-1], samples)
    hi = np.repeat(starts[1:] - 2, samples)
    i = np.minimum(np.maximum(i, lo), hi)
    h = t[i + 1] - t[i]
    with np.errstate(invalid="ignore", divide="ignore"):
        x = np.where(h > 0, (ts.ravel() - t[i]) / h, 0.0)
    x2 = x * x
    h00, h10, h01, h11 = (1 + 2 * x) * (1 - x) ** 2, x * (1 - x) ** 2, x2 * (3 - 2 * x), x2 * (x - 1)
    P = h00 * phi[i] + h10 * h * dphi[i] + h01 * phi[i + 1] + h11 * h * dphi[i + 1]
    V = h00 * dphi[i] + h10 * h * acc[i] + h01 * dphi[i + 1] + h11 * h * acc[i + 1]
    P, V = P.reshape(nh, samples), V.reshape(nh, samples)
    tau = float(tau)
    out = []
    for j in range(nh):
        k, half = divmod(j, 2)
        t0 = k * tau + half * lengths[0]
        out.append(Segment(half + 1, t0 + ts[j], P[j], V[j]))
    return out


def _envelope(segments, K) -> tuple[float, ...]:
    env = []
    for k in range(K):
        parts = segments[2 * k : 2 * k + 2]
        env.append(float(max(np.max(np.abs(p.phi)) for p in parts)) if parts else float("nan"))
    return tuple(env)
