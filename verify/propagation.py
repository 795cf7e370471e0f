"""Exact piecewise propagation of the linear model: each half period is a free oscillation whose
map of ``(phi, phi')`` is the propagator :mod:`analytic.stitching` derives (lambdified to mpmath and
numpy), the jump multiplies ``phi'`` by the derived ratio of the moments of inertia."""

from __future__ import annotations

from fractions import Fraction
from functools import cache

import mpmath
import numpy as np

from analytic.system import PAPER, phase_regimes

from .params import exact_fraction
from .simulation import Segment

__all__ = ["run_linear", "envelope", "regime", "jump_factors", "as_mp"]


def as_mp(x) -> mpmath.mpf:
    """An exact rational (or any number mpmath takes) as an mpf at the working precision."""
    if isinstance(x, Fraction):
        return mpmath.mpf(x.numerator) / x.denominator
    return mpmath.mpf(x)


def _regime(m, Q, half: int, model: str, system=PAPER) -> str:
    """``"under"``, ``"critical"`` or ``"over"``: the sign of ``omega_i**2 - gamma**2``
    (:func:`analytic.system.phase_regimes`, exact for rational ``m`` and ``Q``)."""
    if Q is None or model == "paper":
        return "under"
    mq = m if isinstance(m, Fraction) else exact_fraction(m)
    Qq = Q if isinstance(Q, Fraction) else exact_fraction(Q)
    return phase_regimes(system, mq, Qq, model)[half - 1]


@cache
def _propagator_matrix(model: str, regime: str, half: int):
    """The arguments ``(t, omega, gamma, Omega, Lambda)`` and the matrix of
    :func:`analytic.stitching.propagator` of the model's segment (derived once for every back
    end)."""
    from analytic.model import Damping, Regime, S, segment
    from analytic.stitching import propagator

    damping = {"none": Damping.NONE, "paper": Damping.PAPER, "exact": Damping.EXACT}[model]
    omega = S.omega1 if half == 1 else S.omega2
    Omega = S.Omega1 if half == 1 else S.Omega2
    Lam = S.Lambda1 if half == 1 else S.Lambda2
    seg = segment(omega, S.A1, S.B1, damping, Regime(regime))
    return (S.t, omega, S.gamma, Omega, Lam), propagator(seg, S.t)


@cache
def _propagator(model: str, regime: str, half: int, module: str):
    """``(t, omega, gamma, Omega, Lambda) -> [[a, b], [c, d]]`` from
    :func:`analytic.stitching.propagator` of the model's segment (the entries as four functions)."""
    import sympy as sp

    args, U = _propagator_matrix(model, regime, half)
    return tuple(sp.lambdify(args, U[i, j], modules=module) for i in (0, 1) for j in (0, 1))


#: the propagators whose compiled text is stored (:data:`verify.forms_generated.SOURCES`): the
#: models and the regimes a half can be in
STORED = (
    ("none", "under"),
    ("paper", "under"),
    ("exact", "under"),
    ("exact", "critical"),
    ("exact", "over"),
)
#: the back ends of the stored texts
MODULES = ("mpmath", "numpy")


def _key(what: str, module: str) -> str:
    return f"{what} | {module}"


def _propagator_text(model: str, regime: str, module: str) -> str:
    """The text :func:`sympy.lambdify` writes for the four entries of half 1's propagator."""
    import inspect

    import sympy as sp

    args, U = _propagator_matrix(model, regime, 1)
    entries = [U[i, j] for i in (0, 1) for j in (0, 1)]
    return inspect.getsource(sp.lambdify(args, entries, modules=module, docstring_limit=0))


def _jump_text(module: str) -> str:
    """The text :func:`sympy.lambdify` writes for the two jump factors
    (:func:`analytic.model.jump_ratio` 1 -> 2 and 2 -> 1) as functions of ``m``."""
    import inspect

    import sympy as sp

    from analytic.model import S, jump_ratio

    exprs = [jump_ratio(1, 2), jump_ratio(2, 1)]
    return inspect.getsource(sp.lambdify((S.m,), exprs, modules=module, docstring_limit=0))


def derived_sources() -> dict[str, str]:
    """The text of every stored propagator and of the jump factors, derived now (imports
    sympy), keyed as in :data:`verify.forms_generated.SOURCES` (written there by
    :mod:`verify.generate_forms`)."""
    out = {}
    for module in MODULES:
        for model, regime in STORED:
            out[_key(f"propagator({model}, {regime})", module)] = _propagator_text(
                model, regime, module
            )
        out[_key("jump_factors", module)] = _jump_text(module)
    return out


def _load(key: str, module: str, derive):
    """The function whose text is stored under ``key`` (``derive()`` gives it where it is
    not), in the namespace of ``module``."""
    from .forms_generated import SOURCES

    text = SOURCES.get(key)
    if text is None:
        text = derive()
    ns = dict(vars(mpmath) if module == "mpmath" else vars(np))
    exec(compile(text, f"<form {key}>", "exec"), ns)  # noqa: S102 - derived text
    return ns["_lambdifygenerated"]


@cache
def _propagator_entries(model: str, regime: str, module: str):
    """The four entries ``(a, b, c, d)`` of :func:`_propagator` from one function of ``(t,
    omega, gamma, Omega, Lambda)`` (the same text as each entry's own function), for either
    half: the two halves' maps are one derivation in the half's own symbols, so half 1's serves
    both.  Loaded from the stored text where there is one (no sympy)."""
    key = _key(f"propagator({model}, {regime})", module)
    return _load(key, module, lambda: _propagator_text(model, regime, module))


@cache
def _jumps(module: str):
    """The factors on ``phi'`` at the jumps 1 -> 2 and 2 -> 1 (:func:`analytic.model.jump_ratio`),
    one function of ``m`` giving both (from the stored text where there is one)."""
    return _load(_key("jump_factors", module), module, lambda: _jump_text(module))


@cache
def _jump(module: str):
    """The factor on ``phi'`` at the jumps 1 -> 2 and 2 -> 1, as two functions of ``m``."""
    both = _jumps(module)
    return (lambda m: both(m)[0]), (lambda m: both(m)[1])


def _frequencies(m, Q, eff, work, system=PAPER):
    """``omega_i``, ``gamma``, ``Omega_i``, ``Lambda_i`` (the latter zero where not applicable),
    from the system's description (``omega0 = 2 pi``)."""
    with mpmath.workdps(work):
        g = mpmath.mpf(0) if Q is None else mpmath.pi / as_mp(Q)
        out = []
        W = system.values(m if system.uses_depth else None)[:2]
        for half, Wi in ((1, W[0]), (2, W[1])):
            w = 2 * mpmath.pi * mpmath.sqrt(as_mp(Wi))
            z = w * w - g * g
            reg = _regime(m, Q, half, eff, system)
            Om = mpmath.sqrt(z) if reg == "under" and eff == "exact" else mpmath.mpf(0)
            La = mpmath.sqrt(-z) if reg == "over" else mpmath.mpf(0)
            out.append((w, g, Om, La, reg))
        return out


def run_linear(m, Q, eff, tau, s0, loop, K, samples, work, system=PAPER):
    freqs = _frequencies(m, Q, eff, work, system)
    U_mp = [_propagator_entries(eff, freqs[h][4], "mpmath") for h in (0, 1)]
    U_np = [_propagator_entries(eff, freqs[h][4], "numpy") for h in (0, 1)]
    with mpmath.workdps(work):
        if system.is_paper:
            k12, k21 = _jumps("mpmath")(as_mp(m))
        else:
            k12 = as_mp(Fraction(system.jump(m if system.uses_depth else None)))
            k21 = 1 / k12
        lengths = (tau * as_mp(system.duty), tau - tau * as_mp(system.duty))
        maps = []
        for h in (0, 1):
            w, g, Om, La, _ = freqs[h]
            maps.append(list(U_mp[h](lengths[h], w, g, Om, La)))
        tgrids = [np.linspace(0.0, float(lengths[h]), samples) for h in (0, 1)]
        fl = [tuple(float(x) for x in freqs[h][:4]) for h in (0, 1)]
        with np.errstate(all="ignore"):
            dense = [
                [
                    np.broadcast_to(np.asarray(v, dtype=float), tgrids[h].shape)
                    for v in U_np[h](tgrids[h], *fl[h])
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


def envelope(segments, K) -> tuple[float, ...]:
    env = []
    for k in range(K):
        parts = segments[2 * k : 2 * k + 2]
        env.append(float(max(np.max(np.abs(p.phi)) for p in parts)) if parts else float("nan"))
    return tuple(env)


#: public names of the building blocks (the simulation's start needs the regimes and the jump)
regime = _regime
jump_factors = _jump
