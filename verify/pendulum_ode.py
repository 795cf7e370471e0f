"""The nonlinear pendulum (``phi'' + 2 gamma phi' + omega_i**2 sin phi = 0``) integrated between the
jumps, and what the amplitude-dependent period predicts for it.

The integrator is Hairer's DOP853 (the compiled code behind :class:`scipy.integrate.ode`), restarted
at each jump; its accepted steps are recorded as they come.  The envelope (largest ``|phi|`` per
period) and the plotted segments come from the cubic Hermite interpolant through those steps, after
the run and for all half periods at once; the segments only when asked for.
"""

from __future__ import annotations

import importlib.machinery
import importlib.util
import math
import os
import sys

import numpy as np

from analytic.system import PAPER
from paramres.inputs import InputError

from .simulation import Segment

__all__ = [
    "MAX_STEPS",
    "MAX_STEPS_PER_PERIOD",
    "too_fast",
    "amplitude_factor",
    "saturation_estimate",
    "run_nonlinear",
]

#: the most integration steps (DOP853's steps, rejected ones included) a run may take by the end
#: of its ``k``-th modulation period: ``MAX_STEPS_PER_PERIOD * k``, and never more than
#: :data:`MAX_STEPS` in all.  A pendulum swinging or rotating at a few times its natural frequency
#: takes 10 to 50 steps per period at the default tolerances (a few hundred at ``rtol = 1e-14``,
#: a few thousand when it rotates hundreds of times per ``T0`` through long periods); one whose
#: rotation the jumps keep speeding up (``phi'`` multiplied by ``((1+m)/(1-m))^2`` at every other
#: switch) takes ever more, and would run until the memory of its recorded steps ran out.
MAX_STEPS_PER_PERIOD = 10_000
#: the most integration steps of a whole run (their record takes about 150 bytes each)
MAX_STEPS = 4_000_000


def amplitude_factor(A: float) -> float:
    """The period of the free pendulum of amplitude ``A`` over that of small swings,
    ``2 K(sin^2(A/2)) / pi`` (``K`` the complete elliptic integral of the first kind, from
    mpmath with guard bits, rounded to a double: ``scipy.special`` would cost its import, about
    0.3 s, for this one function)."""
    import mpmath

    with mpmath.workprec(_ELLIPK_BITS):
        k = float(mpmath.ellipk(math.sin(A / 2) ** 2))
    return 2 * k / math.pi


#: working precision of the elliptic integral (a double's 53 bits and guard bits)
_ELLIPK_BITS = 80


def saturation_estimate(tau, interval) -> float | None:
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


def run_nonlinear(m, Q, tau, s0, loop, K, samples, rtol, atol, system=PAPER):
    """The nonlinear pendulum, half period by half period: Hairer's DOP853 (the compiled code
    behind :class:`scipy.integrate.ode`) from each jump to the next, the jump rule applied between
    them.  The integrator's accepted steps are recorded as they come (``(t, phi, phi')``); the
    samples of the plotted segments are interpolated from them afterwards, for all half periods at
    once (:func:`_hermite_segments`): no dense output inside the loop.

    Each half period starts with the step the integrator chose at the same place of the previous
    half period of the same kind (:class:`_Halves`) instead of DOP853's own guess, which is smaller
    and costs two evaluations: the step control (the same ``rtol``/``atol``) accepts it or shrinks
    it, as any step.

    A run that needs more than ``MAX_STEPS_PER_PERIOD * k`` integration steps by the end of its
    ``k``-th period (or more than :data:`MAX_STEPS` in all) stops there with an
    :class:`~paramres.inputs.InputError`: the runs within that budget are not changed by it."""
    W = system.values(m)
    w2 = [(2 * math.pi) ** 2 * float(W[0]), (2 * math.pi) ** 2 * float(W[1])]
    g = 0.0 if Q is None else math.pi / float(Q)
    k12 = float(W[2])
    lengths = (float(tau) * float(system.duty), float(tau) * (1 - float(system.duty)))
    cur = [w2[0]]
    sin = math.sin
    out = np.empty(2)  # the derivative, written in place (the integrator copies it)

    if g:
        g2 = 2 * g

        def rhs(t, y):
            p, v = y.tolist()
            out[0] = v
            out[1] = -g2 * v - cur[0] * sin(p)
            return out

    else:

        def rhs(t, y):
            p, v = y.tolist()
            out[0] = v
            out[1] = -cur[0] * sin(p)
            return out

    steps: list = []
    record = steps.append
    halves_run = _Halves(rhs, rtol, atol, lambda t, y: record((t, *y.tolist())))
    run = halves_run.run
    p, v = float(s0[0]), float(s0[1])
    strobe = [(p, v)]
    halves = []  # the index in ``steps`` of the first step of each recorded half period
    jumps = (k12, 1 / k12)
    first = [0.0, 0.0]  # the first step of the next half period of each kind (0: DOP853's guess)
    used = 0  # DOP853's steps so far
    for k in loop:
        budget = min(MAX_STEPS_PER_PERIOD * (k + 1), MAX_STEPS)
        for h in (0, 1):
            cur[0] = w2[h]
            mark = len(steps)
            if k < K:
                halves.append(mark)
            left = budget - used
            if left < 1:  # pragma: no cover - a half period takes at least one step
                raise _too_fast(budget, k, K, steps[mark:])
            done = run((p, v), lengths[h], first[h], left)
            if done is None:
                raise _too_fast(budget, k, K, steps[mark:])
            p, v, taken = done
            used += taken
            if len(steps) - mark >= 4:  # a second step that is not the last (cut to the jump)
                first[h] = steps[mark + 2][0] - steps[mark + 1][0]
            if k >= K:  # beyond the plotted periods: nothing kept
                del steps[mark:]
            v *= jumps[h]
        strobe.append((p, v))
    env = _hermite_envelope(steps, halves, w2, g, K)

    def dense():
        return _hermite_segments(steps, halves, lengths, tau, w2, g, samples)

    return strobe, dense, env


def _too_fast(budget: int, k: int, K: int, half: list) -> InputError:
    """The refusal of a run that went past its budget of steps in period ``k + 1`` (``half``:
    the steps recorded in the half period where it stopped)."""
    top = max((abs(s[2]) for s in half), default=0.0) / (2 * math.pi)  # in units of omega0
    return too_fast(budget, k, K, top)


def too_fast(budget: int, k: int, K: int, top: float | None = None) -> InputError:
    """The refusal of a run of ``K`` periods that went past its budget of ``budget`` integration
    steps in period ``k + 1`` (``top``: the largest ``|phi'|`` seen, in units of the natural
    frequency, where known)."""
    fewer = f"at most {k} periods, " if k >= 2 else ""
    seen = "" if top is None else f" (|phi'| reached {top:.3g} times the natural frequency)"
    return InputError(
        f"the motion grows too fast to follow: more than {budget} integration steps by period "
        f"{k + 1} of {max(K, 2)}{seen}; ask for {fewer}a smaller depth m or a shorter period T"
    )


def _dop853_module():
    """The compiled DOP853 behind :class:`scipy.integrate.ode` (``scipy.integrate._dop``).

    Loaded from its file without running ``scipy/integrate/__init__.py``, whose imports
    (``scipy.optimize``, ``scipy.sparse``, ``scipy.linalg``, ...) cost about 0.5 s and are not
    needed here; the usual import where ``scipy.integrate`` is already loaded or the file is not
    where scipy keeps it."""
    name = "scipy.integrate._dop"
    if name in sys.modules:
        return sys.modules[name]
    if "scipy.integrate" in sys.modules:
        from scipy.integrate import _dop

        return _dop
    spec = importlib.util.find_spec("scipy")
    where = spec.submodule_search_locations if spec is not None else None
    for suffix in importlib.machinery.EXTENSION_SUFFIXES if where else ():
        path = os.path.join(where[0], "integrate", "_dop" + suffix)
        if os.path.isfile(path):
            spec = importlib.util.spec_from_file_location(name, path)
            module = importlib.util.module_from_spec(spec)
            spec.loader.exec_module(module)
            sys.modules[name] = module  # what ``from scipy.integrate import _dop`` finds later
            return module
    from scipy.integrate import _dop  # pragma: no cover - another layout of scipy

    return _dop  # pragma: no cover


class _Halves:
    """DOP853 as :class:`scipy.integrate.ode` runs it (``set_integrator("dop853", rtol=rtol,
    atol=atol)``, the step callback ``solout``, scipy's defaults for the step control), run from
    ``t = 0`` over one half period at a time, the integrator's arrays made once, its first step
    and its largest number of steps given: :meth:`run`."""

    #: scipy's ``dop853`` defaults: WORK(2) safety factor, WORK(3) and WORK(4) the bounds of the
    #: step ratio, WORK(5) beta of the step control, WORK(6) the largest step (0: no limit)
    _SAFETY, _DFACTOR, _IFACTOR, _BETA, _MAX_STEP = 0.9, 0.3, 6.0, 0.0, 0.0

    def __init__(self, rhs, rtol, atol, solout):
        n = 2
        work = np.zeros(11 * n + 21)
        work[1:6] = (self._SAFETY, self._DFACTOR, self._IFACTOR, self._BETA, self._MAX_STEP)
        iwork = np.zeros(21, dtype=np.int32)
        self.rhs = rhs
        self.runner = _dop853_module().dopri853
        self.args = (rtol, atol, solout, 1, work, iwork)  # then nsteps, verbosity (-1: silent), ()
        self.work = work
        self.iwork = iwork

    def run(self, state, length: float, first: float, most: int) -> tuple[float, float, int] | None:
        """The state ``(phi, phi')`` after ``length`` from ``state``, the first step ``first``
        (``0``: DOP853's own initial guess), and the number of steps DOP853 took (rejected ones
        included); ``None`` when that would be more than ``most`` (``>= 1``)."""
        self.work[6] = first  # DOP853's WORK(7): the initial step
        _, y, istate = self.runner(self.rhs, 0.0, np.array(state), length, *self.args, most, -1, ())
        if istate == -2:  # DOP853's "larger nmax is needed"
            return None
        if istate < 0:  # pragma: no cover - DOP853 on a smooth right-hand side
            raise RuntimeError(f"the integration of a half period failed (DOP853 status {istate})")
        p, v = y.tolist()
        return p, v, int(self.iwork[17])  # IWORK(18): the number of steps


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
    h00, h10 = (1 + 2 * x) * (1 - x) ** 2, x * (1 - x) ** 2
    h01, h11 = x2 * (3 - 2 * x), x2 * (x - 1)
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
