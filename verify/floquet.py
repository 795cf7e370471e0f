"""The Floquet route: the period map built directly from the free oscillations and the jumps.

This module is the independent cross-check of what :mod:`analytic` derives.  It uses nothing from
there: the monodromy matrix is the product of the four maps one modulation period is made of,

    M = J21 . U2(T/2) . J12 . U1(T/2),

acting on the state ``(phi, phi')`` just after ``t = 0`` (the start of the bob-down half).
``U_i(t)`` is the map of a free oscillation of half ``i`` over a time ``t``; the jumps are
``J12 = diag(1, k)`` and ``J21 = diag(1, 1/k)`` with ``k = ((1+m)/(1-m))**2`` (the angle is
continuous, the angular momentum ``J phi'`` with ``J ~ (1 -+ m)**2`` is conserved).  The
boundaries of the intervals of instability are where ``(-1)**n`` is an eigenvalue of ``M`` (a
*Floquet multiplier*); inside an interval the larger multiplier exceeds 1 in modulus and is the
growth of the amplitude per period.

Units: ``T0 = 1`` (``omega0 = 2 pi``), ``omega1 = 2 pi/sqrt(1+m)``, ``omega2 = 2 pi/sqrt(1-m)``,
the period ``tau = T/T0``, friction ``gamma = pi/Q`` (``Q = None``: none).

Three models of a half period:

* no friction: ``U(t) = [[cos wt, sin(wt)/w], [-w sin wt, cos wt]]``;
* ``"paper"``: the paper's approximation (eqs. 28-30), ``exp(-gamma t)`` times the undamped map;
* ``"exact"``: the damped oscillator ``phi'' + 2 gamma phi' + w**2 phi = 0``,

      U(t) = exp(-gamma t) [[C + gamma S, S], [-w**2 S, C - gamma S]],

  with ``C = cos(sqrt(z) t)``, ``S = sin(sqrt(z) t)/sqrt(z)``, ``z = w**2 - gamma**2``.  ``C`` and
  ``S`` are entire functions of ``z`` (``cosh`` and ``sinh(x)/x`` for ``z < 0``, ``1`` and ``t`` at
  ``z = 0``), so one formula covers under-, critically and over-damped halves and is continuous
  through critical damping; for strongly over-damped halves the two exponentials
  ``exp(-(gamma -+ sqrt(-z)) t)`` are used separately, so nothing overflows or cancels.

Two backends: ``"mpmath"`` (any precision, scalars, an ``mpmath.matrix``) and ``"numpy"``
(double precision, vectorised over arrays of ``m``, ``tau`` and ``Q``, shape ``(..., 2, 2)``).

Example (the closing of the third interval at ``m = 3/5``: there ``T = T1 = sqrt(8/5) T0`` and every
solution is anti-periodic, ``M = -I``)::

    >>> import mpmath
    >>> from fractions import Fraction
    >>> with mpmath.workdps(30):
    ...     M = monodromy_matrix(Fraction(3, 5), mpmath.sqrt(mpmath.mpf(8) / 5))
    ...     print(mpmath.mnorm(M + mpmath.eye(2), 1) < mpmath.mpf("1e-29"))
    True
"""

from __future__ import annotations

import math
from fractions import Fraction

import mpmath
import numpy as np

from analytic.system import PAPER

from .inputs import InputError, as_damping, as_depth, as_digits, as_period, as_quality, as_system

__all__ = [
    "monodromy_matrix",
    "monodromy_arb",
    "floquet_multipliers",
    "growth_factor",
    "floquet_vector",
    "BACKENDS",
    "MODELS",
]

BACKENDS = ("mpmath", "numpy")
#: the damping models; without friction (``Q = None``) the model does not matter
MODELS = ("exact", "paper")

#: extra decimal digits carried inside the mpmath backend
_GUARD = 12
#: in the over-damped case, ``sqrt(-z) t`` above which the two exponentials are kept apart
_SPLIT = 0.5


# ---------------------------------------------------------------------------------------------
# arguments


def _check_common(damping, backend):
    model = as_damping(damping)
    if backend not in BACKENDS:
        raise InputError(f"backend {backend!r} is not one of: {', '.join(BACKENDS)}")
    return model


def _mp(x) -> mpmath.mpf:
    """An exact rational or an mpf as an mpf at the working precision."""
    if isinstance(x, Fraction):
        return mpmath.mpf(x.numerator) / x.denominator
    return mpmath.mpf(x)


def _system_values(system, m):
    """``(omega1^2, omega2^2, k)`` in units of ``omega0^2`` from the system's description, exact
    when ``m`` is (custom systems have no depth)."""
    return system.values(m if system.uses_depth else None)


def _mp_parameters(m, tau, Q, system):
    """``(omega1**2, omega2**2, z1, z2, gamma, k, t1, t2)`` at the working precision (units
    ``omega0 = 2 pi``; ``t1 = D tau``, ``t2 = (1 - D) tau`` the phase lengths).

    ``z_i = omega_i**2 - gamma**2 = 4 pi**2 (W_i - 1/(4 Q**2))`` is formed from the exact bracket
    when ``m`` and ``Q`` are rational, so its sign (the regime of the phase) is right.
    """
    tau, Q = as_period(tau), as_quality(Q)
    if system.uses_depth:
        m = as_depth(m)
    exact = (not system.uses_depth or isinstance(m, Fraction)) and (
        Q is None or isinstance(Q, Fraction)
    )
    four_pi2 = 4 * mpmath.pi**2
    W1, W2, k = _system_values(system, m if exact or not system.uses_depth else _mp(m))
    if exact:
        g2 = None if Q is None else 1 / (4 * Q * Q)
        w1, w2, k = _mp(W1) * four_pi2, _mp(W2) * four_pi2, _mp(k)
        if Q is None:
            z1, z2, g = w1, w2, mpmath.mpf(0)
        else:
            z1, z2 = _mp(W1 - g2) * four_pi2, _mp(W2 - g2) * four_pi2
            g = mpmath.pi / _mp(Q)
    else:
        w1, w2, k = _mp(W1) * four_pi2, _mp(W2) * four_pi2, _mp(k)
        if Q is None:
            z1, z2, g = w1, w2, mpmath.mpf(0)
        else:
            g = mpmath.pi / _mp(Q)
            z1, z2 = w1 - g * g, w2 - g * g
    tau = _mp(tau)
    t1 = tau * _mp(system.duty)
    return w1, w2, z1, z2, g, k, t1, tau - t1, Q is not None


# ---------------------------------------------------------------------------------------------
# one half period, mpmath


def _sinhc(x):
    return mpmath.sinh(x) / x if x else mpmath.mpf(1)


def _half_mp(w, z, g, t, model: str, friction: bool):
    """Entries ``(a, b, c, d)`` of the map of ``(phi, phi')`` over ``t`` for ``w = omega**2``."""
    if not friction or model == "paper":
        W = mpmath.sqrt(w)
        c, s = mpmath.cos(W * t), t * mpmath.sinc(W * t)
        e = mpmath.exp(-g * t) if friction else mpmath.mpf(1)
        return e * c, e * s, -e * w * s, e * c
    if z >= 0:
        W = mpmath.sqrt(z)
        c, s = mpmath.cos(W * t), t * mpmath.sinc(W * t)
    else:
        L = mpmath.sqrt(-z)
        if L * t > _SPLIT:
            # exp(-gamma t) cosh and sinh through E = exp(-(gamma - L) t), F = exp(-(gamma + L) t),
            # with gamma - L = w / (gamma + L) (no cancellation)
            slow = w / (g + L)
            E, F = mpmath.exp(-slow * t), mpmath.exp(-(g + L) * t)
            h = (E - F) / (2 * L)
            return ((L + g) * E - slow * F) / (2 * L), h, -w * h, ((L + g) * F - slow * E) / (2 * L)
        c, s = mpmath.cosh(L * t), t * _sinhc(L * t)
    e = mpmath.exp(-g * t)
    return e * (c + g * s), e * s, -e * w * s, e * (c - g * s)


def _monodromy_mp(m, tau, Q, model, system):
    """The monodromy at the working precision (no rounding, no guard digits added)."""
    w1, w2, z1, z2, g, k, t1, t2, friction = _mp_parameters(m, tau, Q, system)
    a1, b1, c1, d1 = _half_mp(w1, z1, g, t1, model, friction)
    a2, b2, c2, d2 = _half_mp(w2, z2, g, t2, model, friction)
    # J12 U1: the velocity row scaled by k; then U2; then J21: the velocity row divided by k
    c1, d1 = k * c1, k * d1
    M11, M12 = a2 * a1 + b2 * c1, a2 * b1 + b2 * d1
    M21, M22 = (c2 * a1 + d2 * c1) / k, (c2 * b1 + d2 * d1) / k
    return mpmath.matrix([[M11, M12], [M21, M22]])


def _half_arb(w, z_sign, z, g, t, model: str, friction: bool):
    """:func:`_half_mp` in ball arithmetic (python-flint ``arb``): every entry encloses the exact
    one.  ``z_sign`` is the exact sign of ``z`` (the regime), so no branch depends on a ball."""
    from flint import arb

    if not friction or model == "paper":
        W = w.sqrt()
        c, s = (W * t).cos(), t * (W * t).sinc()
        e = (-g * t).exp() if friction else arb(1)
        return e * c, e * s, -e * w * s, e * c
    if z_sign > 0:
        W = z.sqrt()
        c, s = (W * t).cos(), t * (W * t).sinc()
    elif z_sign == 0:
        c, s = arb(1), t
    else:
        L = (-z).sqrt()
        c, s = (L * t).cosh(), (L * t).sinh() / L
    e = (-g * t).exp()
    return e * (c + g * s), e * s, -e * w * s, e * (c - g * s)


def monodromy_arb(m, tau, Q, damping: str, system):
    """The monodromy as four ``arb`` balls ``(M11, M12, M21, M22)`` at the working precision
    (``flint.ctx.prec``), for exact ``m``, ``tau`` and ``Q`` (Fractions; ``Q = None``: no
    friction): the certified version of :func:`monodromy_matrix`."""
    from flint import arb, fmpq

    def A(x: Fraction):
        return arb(fmpq(x.numerator, x.denominator))

    W1, W2, k = _system_values(system, m)
    pi = arb.pi()
    four_pi2 = 4 * pi * pi
    w1, w2 = A(Fraction(W1)) * four_pi2, A(Fraction(W2)) * four_pi2
    friction = Q is not None
    if friction:
        g2 = 1 / (4 * Fraction(Q) ** 2)
        zf = (Fraction(W1) - g2, Fraction(W2) - g2)
        z1, z2 = A(zf[0]) * four_pi2, A(zf[1]) * four_pi2
        g = pi / A(Fraction(Q))
    else:
        zf = (Fraction(W1), Fraction(W2))
        z1, z2, g = w1, w2, arb(0)
    t1 = A(Fraction(tau) * system.duty)
    t2 = A(Fraction(tau) * (1 - system.duty))
    a1, b1, c1, d1 = _half_arb(w1, zf[0], z1, g, t1, damping, friction)
    a2, b2, c2, d2 = _half_arb(w2, zf[1], z2, g, t2, damping, friction)
    kk = A(Fraction(k))
    c1, d1 = kk * c1, kk * d1
    return (
        a2 * a1 + b2 * c1,
        a2 * b1 + b2 * d1,
        (c2 * a1 + d2 * c1) / kk,
        (c2 * b1 + d2 * d1) / kk,
    )


def _system(system, duty):
    return as_system(system, "1/2" if duty is None else duty)


def _digits(dps) -> int:
    return mpmath.mp.dps if dps is None else as_digits(dps)


# ---------------------------------------------------------------------------------------------
# one half period, numpy


def _np_sinc(x):
    safe = np.where(x == 0, 1.0, x)
    return np.where(x == 0, 1.0, np.sin(safe) / safe)


def _np_sinhc(x):
    safe = np.where(x == 0, 1.0, x)
    return np.where(x == 0, 1.0, np.sinh(safe) / safe)


def _half_np(w, z, g, t, model: str, friction):
    if model == "paper" or not np.any(friction):
        W = np.sqrt(w)
        c, s = np.cos(W * t), t * _np_sinc(W * t)
        e = np.exp(-g * t)
        return e * c, e * s, -e * w * s, e * c
    under = z >= 0
    W = np.sqrt(np.where(under, z, 0.0))
    L = np.sqrt(np.where(under, 0.0, -z))
    split = (~under) & (L * t > _SPLIT)
    # under-damped, critical and mildly over-damped: C and S as entire functions of z
    Lm = np.where(split, 0.0, L)
    c = np.where(under, np.cos(W * t), np.cosh(Lm * t))
    s = t * np.where(under, _np_sinc(W * t), _np_sinhc(Lm * t))
    e = np.exp(-g * t)
    out = [e * (c + g * s), e * s, -e * w * s, e * (c - g * s)]
    if np.any(split):
        Ls = np.where(split, L, 1.0)
        slow = w / (g + Ls)
        E, F = np.exp(-slow * t), np.exp(-(g + Ls) * t)
        h = (E - F) / (2 * Ls)
        d = 2 * Ls
        alt = [((Ls + g) * E - slow * F) / d, h, -w * h, ((Ls + g) * F - slow * E) / d]
        out = [np.where(split, b, a) for a, b in zip(out, alt, strict=True)]
    return tuple(out)


def _np_arrays(m, tau, Q):
    try:
        m = np.asarray(m, dtype=float)
        tau = np.asarray(tau, dtype=float)
        Qa = None if Q is None else np.asarray(Q, dtype=float)
    except (TypeError, ValueError):
        raise InputError("m, tau and Q must be numbers or arrays of numbers") from None
    if not np.all(np.isfinite(m)) or not np.all((m > 0) & (m < 1)):
        raise InputError("depth m must be finite and in the allowed range 0 < m < 1")
    if not np.all(np.isfinite(tau)) or not np.all(tau > 0):
        raise InputError("period T/T0 must be finite and > 0")
    if Qa is not None and (not np.all(np.isfinite(Qa)) or not np.all(Qa > 0)):
        raise InputError("quality factor Q must be finite and > 0 (None for no friction)")
    return m, tau, Qa


def _monodromy_np(m, tau, Q, model, system):
    if not system.uses_depth:
        m = 0.5  # unused: a custom system has no depth
    m, tau, Q = _np_arrays(m, tau, Q)
    two_pi2 = (2 * math.pi) ** 2
    W1, W2, k = _system_values(system, m)
    W1, W2, k = (np.asarray(float(v) if isinstance(v, Fraction) else v, float) for v in (W1, W2, k))
    w1, w2 = two_pi2 * W1, two_pi2 * W2
    if Q is None:
        g = np.zeros(())
        z1, z2 = w1, w2
        friction = np.zeros((), dtype=bool)
    else:
        g = math.pi / Q
        z1, z2 = w1 - g * g, w2 - g * g
        friction = np.ones((), dtype=bool)
    t1 = tau * float(system.duty)
    t2 = tau - t1
    with np.errstate(over="ignore", under="ignore", invalid="ignore", divide="ignore"):
        a1, b1, c1, d1 = _half_np(w1, z1, g, t1, model, friction)
        a2, b2, c2, d2 = _half_np(w2, z2, g, t2, model, friction)
    c1, d1 = k * c1, k * d1
    M11, M12 = a2 * a1 + b2 * c1, a2 * b1 + b2 * d1
    M21, M22 = (c2 * a1 + d2 * c1) / k, (c2 * b1 + d2 * d1) / k
    M11, M12, M21, M22 = np.broadcast_arrays(M11, M12, M21, M22)
    return np.stack([np.stack([M11, M12], -1), np.stack([M21, M22], -1)], -2)


# ---------------------------------------------------------------------------------------------
# public API


def monodromy_matrix(
    m, tau, Q=None, damping="exact", *, backend="mpmath", dps=None, system=PAPER, duty=None
):
    """The period map of ``(phi, phi')`` from ``t = 0+`` over one modulation period ``T = tau T0``.

    ``backend="mpmath"``: ``m, tau, Q`` scalars (exact rationals, strings, floats or mpf), the
    result an ``mpmath.matrix`` rounded to ``dps`` digits (default: the current mpmath precision;
    the computation runs inside ``mpmath.workdps`` with guard digits and leaves the global precision
    alone).  ``backend="numpy"``: floats or arrays (broadcast together), the result a float64 array
    of shape ``(..., 2, 2)``.  ``damping`` is ``"exact"`` or ``"paper"`` (ignored when ``Q`` is
    ``None``).  ``system`` (and ``duty``) pick a member of the family (:mod:`analytic.system`);
    ``m`` is ignored for a custom system.
    """
    model = _check_common(damping, backend)
    system = _system(system, duty)
    if backend == "numpy":
        return _monodromy_np(m, tau, Q, model, system)
    d = _digits(dps)
    with mpmath.workdps(d + _GUARD):
        M = _monodromy_mp(m, tau, Q, model, system)
    with mpmath.workdps(d):
        return M.apply(lambda x: +x)


def _roots_mp(M):
    """Eigenvalues of a 2 x 2 mpmath matrix, the larger in modulus first."""
    tr = M[0, 0] + M[1, 1]
    det = M[0, 0] * M[1, 1] - M[0, 1] * M[1, 0]
    disc = (M[0, 0] - M[1, 1]) ** 2 + 4 * M[0, 1] * M[1, 0]
    if disc >= 0:
        root = mpmath.sqrt(disc)
        big = (tr + root) / 2 if tr >= 0 else (tr - root) / 2
        small = det / big if big else mpmath.mpf(0)
        return big, small
    root = mpmath.sqrt(-disc) / 2
    return mpmath.mpc(tr / 2, root), mpmath.mpc(tr / 2, -root)


def _roots_np(M):
    a, b, c, d = M[..., 0, 0], M[..., 0, 1], M[..., 1, 0], M[..., 1, 1]
    tr, det = a + d, a * d - b * c
    disc = (a - d) ** 2 + 4 * b * c
    real = disc >= 0
    root = np.sqrt(np.abs(disc))
    with np.errstate(divide="ignore", invalid="ignore"):
        big = np.where(tr >= 0, tr + root, tr - root) / 2
        small = np.where(big != 0, det / np.where(big != 0, big, 1.0), 0.0)
    mu1 = np.where(real, big + 0j, tr / 2 + 0.5j * root)
    mu2 = np.where(real, small + 0j, tr / 2 - 0.5j * root)
    return np.stack([mu1, mu2], -1)


def floquet_multipliers(
    m, tau, Q=None, damping="exact", *, backend="mpmath", dps=None, system=PAPER, duty=None
):
    """The two Floquet multipliers (eigenvalues of :func:`monodromy_matrix`), larger modulus first.

    mpmath: a pair of mpf (real multipliers) or of conjugate mpc (complex ones, the one with
    positive imaginary part first).  numpy: a complex array of shape ``(..., 2)``.  Their product is
    ``exp(-2 gamma T)``; inside an interval of instability they are real with the sign ``(-1)**n``.
    """
    model = _check_common(damping, backend)
    system = _system(system, duty)
    if backend == "numpy":
        return _roots_np(_monodromy_np(m, tau, Q, model, system))
    d = _digits(dps)
    with mpmath.workdps(d + _GUARD):
        mu = _roots_mp(_monodromy_mp(m, tau, Q, model, system))
    with mpmath.workdps(d):
        return tuple(+x for x in mu)


def growth_factor(
    m, tau, Q=None, damping="exact", *, backend="mpmath", dps=None, system=PAPER, duty=None
):
    """The growth of the amplitude per modulation period, ``max |mu|`` over the two multipliers.

    Above 1 inside an interval of instability; 1 on its edges and outside it without friction;
    ``exp(-gamma T)`` outside it with friction.
    """
    mu = floquet_multipliers(
        m, tau, Q, damping, backend=backend, dps=dps, system=system, duty=duty
    )
    if backend == "numpy":
        return np.abs(mu).max(axis=-1)
    with mpmath.workdps(_digits(dps)):
        return +max(abs(x) for x in mu)


def floquet_vector(M, mu):
    """A unit eigenvector of the 2 x 2 matrix ``M`` for the eigenvalue ``mu``: the initial state
    ``(phi, phi')`` that is multiplied by ``mu`` every period.

    Of the two null vectors of ``M - mu I`` read off its rows, ``(M12, mu - M11)`` and
    ``(mu - M22, M21)``, the longer one is taken (they are parallel when ``mu`` is an eigenvalue).
    ``M`` an ``mpmath.matrix`` gives an mpmath pair, a numpy array of shape ``(..., 2, 2)`` an
    array of shape ``(..., 2)``.  The sign makes the larger component positive.
    """
    if isinstance(M, mpmath.matrix):
        v1 = (M[0, 1], mu - M[0, 0])
        v2 = (mu - M[1, 1], M[1, 0])
        n1 = mpmath.sqrt(abs(v1[0]) ** 2 + abs(v1[1]) ** 2)
        n2 = mpmath.sqrt(abs(v2[0]) ** 2 + abs(v2[1]) ** 2)
        v, n = (v1, n1) if n1 >= n2 else (v2, n2)
        if not n:  # M = mu I: every vector is an eigenvector
            return mpmath.mpf(1), mpmath.mpf(0)
        big = v[0] if abs(v[0]) >= abs(v[1]) else v[1]
        sign = -1 if mpmath.re(big) < 0 else 1
        return tuple(sign * x / n for x in v)
    M = np.asarray(M)
    v1 = np.stack([M[..., 0, 1], mu - M[..., 0, 0]], -1)
    v2 = np.stack([mu - M[..., 1, 1], M[..., 1, 0]], -1)
    n1, n2 = np.linalg.norm(v1, axis=-1), np.linalg.norm(v2, axis=-1)
    v = np.where((n1 >= n2)[..., None], v1, v2)
    n = np.maximum(n1, n2)
    v = np.where((n > 0)[..., None], v / np.where(n > 0, n, 1.0)[..., None], np.array([1.0, 0.0]))
    big = np.where(np.abs(v[..., 0]) >= np.abs(v[..., 1]), v[..., 0], v[..., 1])
    return v * np.where(np.real(big) < 0, -1.0, 1.0)[..., None]
