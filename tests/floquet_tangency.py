"""The threshold of an interval by the Floquet route alone (:mod:`verify.floquet`, no sympy): the
depth ``m*`` and period ``T*`` where the interval is born, i.e. where ``det(M - sigma I) = 1 -
sigma tr M + det M`` (``sigma = (-1)^n``) has a double root in ``T`` -- the growth factor
``max |mu|`` touches 1 at the interval's centre.  Solved with mpmath at high precision (Newton in
two unknowns, ``d/dT`` by mpmath's numerical differentiation).  A reference for the tests of
:mod:`verify.existence` and :mod:`analytic.thresholds`."""

from __future__ import annotations

import mpmath

from verify.floquet import growth_factor, monodromy_matrix


def edge_function(n, Q, system, duty, damping, dps):
    sigma = -1 if n % 2 else 1

    def F(m, T):
        M = monodromy_matrix(m, T, Q, damping, system=system, duty=duty)
        tr = M[0, 0] + M[1, 1]
        det = M[0, 0] * M[1, 1] - M[0, 1] * M[1, 0]
        return 1 - sigma * tr + det

    return F


def tangency(n, Q, m0, T0, *, system="pendulum", duty="1/2", damping="exact", dps=40):
    """``(m*, T*)`` near the starting guess ``(m0, T0)``, to about ``dps - 10`` digits."""
    F = edge_function(n, Q, system, duty, damping, dps)
    with mpmath.workdps(dps):

        def eqs(m, T):
            return F(m, T), mpmath.diff(lambda t: F(m, t), T)

        start = (mpmath.mpf(m0), mpmath.mpf(T0))
        m, T = mpmath.findroot(eqs, start, tol=mpmath.mpf(10) ** (10 - 2 * dps))
        return +m, +T


def peak_growth(n, Q, m, T0, *, system="pendulum", duty="1/2", damping="exact", dps=30):
    """``max_T max|mu|`` near ``T0`` at depth ``m`` (the maximiser of ``sigma tr M`` found by
    Newton on its derivative): above 1 where the interval exists."""
    sigma = -1 if n % 2 else 1
    with mpmath.workdps(dps):

        def s_tr(T):
            M = monodromy_matrix(m, T, Q, damping, system=system, duty=duty)
            return sigma * (M[0, 0] + M[1, 1])

        T = mpmath.findroot(lambda t: mpmath.diff(s_tr, t), mpmath.mpf(T0))
        return growth_factor(m, T, Q, damping, system=system, duty=duty, dps=dps), T
