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
