"""The edges of any member of the family, any duty, as power series in the depth ``m``.

The per-edge factor of the normal form is the same for every member (:mod:`analytic.family`):
``sin(theta) - delta r f(beta (n pi/2 + theta))`` with ``f = cos`` (odd ``n``) or ``sin`` (even
``n``), only ``r(m), beta(m), w(m)`` change.  For a duty ``D != 1/2`` the mean-frequency offset
``beta`` does not vanish at ``m = 0`` (``beta(0) = 1 - 2 D``), so the coefficients hold
``cos``/``sin`` of rational multiples of ``pi``, which sympy keeps exact.  The series ``theta(m)``
comes from the fixed-point step ``theta <- theta - F(theta)`` on truncated series (``F' = 1 +
O(m)``: each step fixes one more power of ``m``), then ``T/T0 = (n/2 + theta/pi)/w``.

At ``m -> 0`` the term ``r f(beta n pi/2)`` sets the width: it is ``O(m)`` unless
``f((1 - 2D) n pi/2) = 0``, i.e. unless ``n D`` is an integer (the n-th harmonic of the square
wave vanishes), where the width is ``O(m^2)`` -- the even orders of the paper's equal halves.
"""

from __future__ import annotations

from functools import cache

import sympy as sp

from .model import Damping, S
from .powerseries import LaurentRing, evaluate
from .series_result import EdgeSeries
from .system import System

__all__ = ["family_edge_series"]


def _mul(a: list, b: list, K: int) -> list:
    """The product of two truncated series (coefficient lists), truncated at ``m**K``."""
    return [
        sp.expand(sum((a[i] * b[k - i] for i in range(k + 1)), sp.Integer(0))) for k in range(K + 1)
    ]


def _sin_cos(u: list, K: int) -> tuple[list, list]:
    """``sin(u)`` and ``cos(u)`` of a series with ``u(0) = 0``, truncated at ``m**K``."""
    zero = [sp.Integer(0)] * (K + 1)
    s, c = list(zero), list(zero)
    c[0] = sp.Integer(1)
    power = list(zero)
    power[0] = sp.Integer(1)
    for j in range(1, K + 1):
        power = _mul(power, u, K)
        term = [sp.expand(x / sp.factorial(j)) for x in power]
        sign = (-1) ** (j // 2)
        target = s if j % 2 else c
        for k in range(K + 1):
            target[k] = sp.expand(target[k] + sign * term[k])
    return s, c


@cache
def _parameters(system: System, K: int) -> dict:
    from .family import parameter_forms

    """The coefficients ``[c_0, ..., c_K]`` of ``r, beta, w`` in powers of ``m``: the definitions
    evaluated in exact truncated power-series arithmetic (:func:`analytic.powerseries.evaluate`,
    the same coefficients as ``sympy.series``, much faster)."""
    defs = parameter_forms(system, Damping.NONE).definitions
    ring = LaurentRing(["pi"])
    memo: dict = {}
    out = {}
    for name in ("r", "beta", "w"):
        ser = evaluate(defs[name], {}, ring, K, var=S.m, memo=memo)
        out[name] = [sp.expand(c) for c in ser.coefficients_sympy({"pi": sp.pi})]
    return out


def _solve_theta(n: int, delta: int, par: dict, K: int) -> list:
    """``theta(m)`` on the edge ``delta``: the fixed point of ``theta <- theta - F(theta)``,
    ``F = sin(theta) - delta r f(beta (n pi/2 + theta))``, in truncated series arithmetic.

    ``f(beta x) = f(A + u)`` with the exact constant angle ``A = beta(0) n pi/2`` and the small
    ``u = (beta - beta(0)) n pi/2 + beta theta``, expanded by the angle-addition rule."""
    beta, r = par["beta"], par["r"]
    A = beta[0] * n * sp.pi / 2
    cA, sA = sp.cos(A), sp.sin(A)
    if n % 2:  # f = cos: cos(A + u) = cos A cos u - sin A sin u
        fA, gA = cA, -sA
    else:  # f = sin: sin(A + u) = sin A cos u + cos A sin u
        fA, gA = sA, cA
    th = [sp.Integer(0)] * (K + 1)
    half = n * sp.pi / 2
    for _ in range(K + 1):
        u = [sp.Integer(0)] + [sp.expand(beta[k] * half) for k in range(1, K + 1)]
        bt = _mul(beta, th, K)
        u = [sp.expand(u[k] + bt[k]) for k in range(K + 1)]
        su, cu = _sin_cos(u, K)
        fval = [sp.expand(fA * cu[k] + gA * su[k]) for k in range(K + 1)]
        rf = _mul(r, fval, K)
        sth, _ = _sin_cos(th, K)
        th = [sp.expand(th[k] - (sth[k] - delta * rf[k])) for k in range(K + 1)]
    return th


def _leading_sign(expr) -> int:
    """The sign of a series at small positive ``m`` (its first non-zero coefficient)."""
    poly = sp.Poly(sp.expand(expr), S.m)
    for k in range(poly.degree() + 1):
        c = poly.coeff_monomial(S.m**k)
        if c != 0:
            return 1 if sp.N(c, 30) > 0 else -1
    return 0


@cache
def family_edge_series(order: int, terms: int, units: str, system: System) -> EdgeSeries:
    """Both frictionless edges of order ``order`` of ``system`` through ``m**terms``."""
    n, K = order, terms
    par = _parameters(system, K)
    m = S.m
    found = []
    w_inv = [sp.Integer(0)] * (K + 1)  # 1/w by the Newton-free recursion for a series inverse
    w = par["w"]
    w_inv[0] = 1 / w[0]
    for k in range(1, K + 1):
        w_inv[k] = sp.expand(-sum(w[i] * w_inv[k - i] for i in range(1, k + 1)) / w[0])
    for delta in (-1, 1):
        coeffs = _solve_theta(n, delta, par, K)
        th = sum((c * m**k for k, c in enumerate(coeffs)), sp.Integer(0))
        tn = [sp.Rational(n, 2) + coeffs[0] / sp.pi] + [c / sp.pi for c in coeffs[1:]]
        t0 = _mul(tn, w_inv, K)
        in_tn = sum((sp.expand(c) * m**k for k, c in enumerate(tn)), sp.Integer(0))
        in_t0 = sum((sp.expand(c) * m**k for k, c in enumerate(t0)), sp.Integer(0))
        found.append((th, in_tn, in_t0))
    a, b = found
    if _leading_sign(b[2] - a[2]) < 0:
        a, b = b, a
    theta = {"lower": a[0], "upper": b[0]}
    in_Tav = {"lower": a[1], "upper": b[1]}
    in_T0 = {"lower": a[2], "upper": b[2]}
    _ = m
    notes = (
        "per-edge factor of the family's normal form, solved by fixed-point steps on power series",
        "T/T0 = (n/2 + theta/pi)/w with the system's parameters expanded from their definitions",
    )
    return EdgeSeries(n, K, units, in_T0, in_Tav, theta, notes=notes, system=system)
