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

import math
from fractions import Fraction
from functools import cache

import mpmath

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
from .pendulum_ode import amplitude_factor, run_nonlinear, saturation_estimate
from .propagation import as_mp as _mp
from .propagation import envelope as _envelope
from .propagation import run_linear as _run_linear
from .simulation import Segment, Simulation

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


#: the edge shapes (:class:`analytic.stitching.EdgeKind`) by value and parity, without sympy
_KINDS = {-1: ("odd-cos-sin", "odd-sin-cos"), 1: ("even-cos-cos", "even-sin-sin")}


def _initial_ratio_exprs(kind_value: str) -> tuple:
    """``phi'(0)/phi(0)`` on an undamped edge of the given shape as ``(num, den)`` in ``(m, tau)``:
    the derived ratio split into numerator and denominator so a vanishing ``phi(0)`` is fine."""
    import sympy as sp

    from analytic.model import physical
    from analytic.reductions import stationary_initial_condition
    from analytic.stitching import EdgeKind

    ratio = physical(stationary_initial_condition(EdgeKind(kind_value)), damping=False)
    ratio = ratio.replace(sp.tan, lambda u: sp.sin(u) / sp.cos(u))
    ratio = ratio.replace(sp.cot, lambda u: sp.cos(u) / sp.sin(u))
    return sp.fraction(sp.together(ratio))


def _edge_factor_expr(kind_value: str):
    """The undamped per-edge factor of the shape in ``(m, tau)``, in the physical units, from
    :func:`analytic.normal_form.edge_factor`."""
    from analytic.model import S, inertia, physical
    from analytic.normal_form import edge_factor
    from analytic.stitching import EdgeKind

    kind = EdgeKind(kind_value)
    a1, a2 = S.omega1 * S.T / 2, S.omega2 * S.T / 2
    q = inertia(1) * S.omega1 / (inertia(2) * S.omega2)
    r = (q - 1) / (q + 1)
    f = edge_factor(kind.parity, kind.epsilon, symbols=((a1 + a2) / 2, (a2 - a1) / 2, r))
    return physical(f, damping=False)


def _text(expr) -> str:
    """The Python text :func:`sympy.lambdify` writes for ``expr`` in ``(m, tau)`` (mpmath)."""
    import inspect

    import sympy as sp

    from analytic.model import S

    return inspect.getsource(sp.lambdify((S.m, S.tau), expr, modules="mpmath", docstring_limit=0))


def _key(name: str, kind_value: str) -> str:
    return f"timedomain {name}({kind_value}) | mpmath"


def derived_sources() -> dict[str, str]:
    """The text of every building block, derived now (imports sympy), keyed as in
    :data:`verify.forms_generated.SOURCES` (written there by :mod:`verify.generate_forms`)."""
    out = {}
    for kinds in _KINDS.values():
        for kv in kinds:
            num, den = _initial_ratio_exprs(kv)
            out[_key("initial_ratio_num", kv)] = _text(num)
            out[_key("initial_ratio_den", kv)] = _text(den)
            out[_key("edge_factor", kv)] = _text(_edge_factor_expr(kv))
    return out


def _load(key: str):
    """The function of ``(m, tau)`` whose text is stored under ``key`` (derived if it is not)."""
    from .forms_generated import SOURCES

    text = SOURCES.get(key)
    if text is None:
        text = derived_sources()[key]
    ns = dict(vars(mpmath))
    exec(compile(text, f"<form {key}>", "exec"), ns)  # noqa: S102 - derived text
    return ns["_lambdifygenerated"]


@cache
def _initial_ratio(kind_value: str):
    """``phi'(0)/phi(0)`` on an undamped edge of the given shape, as ``(m, tau) -> (num, den)``
    (:func:`_initial_ratio_exprs`, compiled from the stored text)."""
    return _load(_key("initial_ratio_num", kind_value)), _load(
        _key("initial_ratio_den", kind_value)
    )


@cache
def _edge_factors(parity_value: int):
    """The two undamped per-edge factors of the parity, ``{kind value: f(m, tau)}`` (mpmath,
    :func:`_edge_factor_expr`, compiled from the stored text)."""
    return {kv: _load(_key("edge_factor", kv)) for kv in _KINDS[parity_value]}


# ---------------------------------------------------------------------------------------------
# what is measured on the trajectory


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
        strobe, segments, env = run_nonlinear(m, Q, tau, s0, loop, K, samples, rtol, atol, sysv)
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

    sat = saturation_estimate(tau_out, interval_out) if nonlinear else None
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
    return min(vals, key=vals.get)
