"""An independent reference for the tests: the paper pendulum's monodromy matrix over one period,
built from the free oscillations and the jumps with mpmath -- not from analytic/.

Units ``T0 = 1``: ``omega_i = 2 pi/sqrt(1 -+ m)`` (the bob-down half first), and the jump of the
velocity ``phi'`` by ``k = ((1 + m)/(1 - m))^2`` (the angular momentum ``l^2 phi'`` is kept)."""

from __future__ import annotations

import mpmath


def monodromy_mp(T, mm) -> mpmath.matrix:
    """The matrix taking ``(phi, phi')`` at ``t = 0+`` to ``t = T+`` (period ``T/T0``, depth
    ``mm``; at mpmath's working precision)."""
    w1 = 2 * mpmath.pi / mpmath.sqrt(1 + mm)
    w2 = 2 * mpmath.pi / mpmath.sqrt(1 - mm)

    def U(w, t):
        c, s = mpmath.cos(w * t), mpmath.sin(w * t)
        return mpmath.matrix([[c, s / w], [-w * s, c]])

    k = ((1 + mm) / (1 - mm)) ** 2
    return (
        mpmath.matrix([[1, 0], [0, 1 / k]])
        * U(w2, T / 2)
        * mpmath.matrix([[1, 0], [0, k]])
        * U(w1, T / 2)
    )


def damped_monodromy_mp(T, mm, Q=None, model="exact") -> mpmath.matrix:
    """:func:`monodromy_mp` with friction ``gamma = pi/Q`` (units ``T0 = 1``): in the exact model
    each half is the damped oscillator ``phi'' + 2 gamma phi' + w^2 phi = 0``, whose map over a
    time ``t`` is ``exp(-gamma t) [[C + gamma S, S], [-w^2 S, C - gamma S]]`` with ``C = cos(W t)``,
    ``S = sin(W t)/W``, ``W = sqrt(w^2 - gamma^2)`` (under-damped halves only); in the paper's
    model (its eqs. 28-30) the undamped map times ``exp(-gamma t)``.  ``Q = None``: no friction."""
    if Q is None:
        return monodromy_mp(T, mm)
    g = mpmath.pi / Q
    w1 = 2 * mpmath.pi / mpmath.sqrt(1 + mm)
    w2 = 2 * mpmath.pi / mpmath.sqrt(1 - mm)

    def U(w, t):
        if model == "paper":
            c, s = mpmath.cos(w * t), mpmath.sin(w * t)
            m_ = mpmath.matrix([[c, s / w], [-w * s, c]])
        else:
            W = mpmath.sqrt(w * w - g * g)
            c, s = mpmath.cos(W * t), mpmath.sin(W * t) / W
            m_ = mpmath.matrix([[c + g * s, s], [-w * w * s, c - g * s]])
        return mpmath.exp(-g * t) * m_

    k = ((1 + mm) / (1 - mm)) ** 2
    return (
        mpmath.matrix([[1, 0], [0, 1 / k]])
        * U(w2, T / 2)
        * mpmath.matrix([[1, 0], [0, k]])
        * U(w1, T / 2)
    )


def multipliers_mp(M) -> tuple:
    """Both eigenvalues of the 2x2 matrix ``M`` (larger modulus first) at the working precision."""
    tr, det = M[0, 0] + M[1, 1], mpmath.det(M)
    root = mpmath.sqrt(mpmath.mpc(tr * tr - 4 * det))
    a, b = (tr + root) / 2, (tr - root) / 2
    return (a, b) if abs(a) >= abs(b) else (b, a)
