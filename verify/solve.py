"""Certified boundaries of one interval of instability, to any number of digits.

:func:`boundary` returns the lower and upper edge ``T/T0`` of the ``n``-th interval at depth ``m``
(with friction ``Q`` in either damping model), each as an mpmath number whose digits are proven:
the value comes from a ball (python-flint ``arb``) that contains the exact edge, and the ball's
radius is below the accuracy asked for.  How each edge is found and proven:

**The unknown.**  ``theta = x - n pi/2`` with ``x = omega_av T/2`` (the paper's ``omega_av Delta
T/2``, eqs. 15, 26), so ``T/T0 = (n/2 + theta/pi)/w``; ``delta = theta/(pi w)`` is the offset from
the exact tuning ``n T_av/2`` and keeps its digits even where it is ``1e-24`` (even orders at ``m =
1e-12``).

**No friction** (any model): the two per-edge equations ``sin(theta) + k r f(beta (n pi/2 + theta))
= 0`` (:func:`verify.derived.edge_equation`; ``k = +-1`` picks the edge) each have exactly one root
in ``(-pi/2, pi/2)``, and it is simple (the window theorem, ``docs/theory.md``), also where the
interval closes.  Each root is found by Halley's method in floats, refined by Newton in ``arb`` with
the precision doubled every step, and proven by interval Newton
(:func:`verify.certify.certified_root`). The lower edge is the smaller root.  No solver can reach
another interval's edge: the window holds one root of each equation and the iteration is kept inside
the bracket it has seen.

**Friction, normal form** (paper model; exact model with both halves under-damped): ``D(theta) =
R(theta) - sin^2(theta)`` (:func:`verify.derived.indicator`) is positive exactly inside the
interval.  ``D`` is at most its friction-free value ``D0`` (same ``r``, ``beta``), which is negative
outside the two undamped roots ``[a, b]``; so the interval lies in ``[a, b]``.  There ``D`` is
maximised (root of ``D'``); no interval if the maximum is ``<= 0``, else the edges are the zeros of
``D`` left and right of the maximiser, each proven by interval Newton.  The *shape* -- ``D < 0`` on
``[a, lower)``, ``D > 0`` between the edges, ``D < 0`` on ``(upper, b]`` -- is proven too (by
unimodality, ``D'' < 0`` on the bracket or on pieces of it, else by
:func:`verify.certify.prove_sign` on sub-intervals; see :mod:`verify.hump`), so the two zeros are
the edges and nothing in between is missed.  Non-existence is proven by signs (``D < 0`` on all
of ``[a, b]``).

**Friction, trace form** (exact model, a half critically or over-damped, ``4 Q^2 <= 1 + m``, or half
1 within :data:`verify.params.NEAR_CRITICAL` of it, where the normal form degenerates): ``D(zeta) =
sigma (2 C1 C2 - kappa S1 S2) - 2 cosh(2 zeta)`` in ``zeta = gamma T/2``
(:func:`verify.derived.trace_indicator`).  With half 2 under-damped, ``2 C1 C2 - kappa S1 S2 = rho
cos(Phi)`` with the phase ``Phi = nu2 zeta + atan2(kappa S1, 2 nu2 C1)``, which increases strictly
with ``T`` wherever it exceeds ``pi/2`` (for ``zeta >= pi/(2 nu2)``, where the atan2 term's
derivative is below ``1/(2 zeta) < nu2``; before, ``Phi < pi/2``, with a dip of about ``1e-5``
below 0 near ``zeta = 0`` where ``kappa < -2 nu2^2``); ``D > 0`` needs ``sigma cos(Phi) > 0``, so
the ``n``-th interval lies where ``|Phi - n pi| < pi/2`` (this numbers the orders continuously
with the normal form).  With both halves over-damped there is no rotation: only ``n = 1`` can
exist, where ``P < 0``.  Inside the window the same maximise-and-bracket scheme as above is
proven.

``method=`` selects a solver from :data:`verify.methods.METHODS` (``"certified"``, the default,
:mod:`verify.certified`; ``"fixedpoint"``, the paper's own iteration, uncertified,
:mod:`verify.fixedpoint`; ``"auto"``, the cheapest method that provably meets a tolerance,
:mod:`verify.auto`); new methods register there.  This module is the dispatcher, above the
solvers: it imports them, none imports it.  The pieces live in modules of one concept each: the
request (:mod:`verify.request`), the result (:mod:`verify.result`), the registry
(:mod:`verify.methods`), the solvers without friction (:mod:`verify.undamped`) and with friction
(:mod:`verify.hump`), and the step from proven roots to the result (:mod:`verify.enclosure`); the
names below are re-exported from them.
"""

from __future__ import annotations

from . import auto as _auto  # noqa: F401  (registers "auto")
from . import certified as _certified  # noqa: F401  (registers "certified")
from . import fixedpoint as _fixedpoint  # noqa: F401  (registers "fixedpoint")
from .certify import CertificationError
from .hump import (
    depth_ball,
    hump_box,
    hump_normal,
    hump_trace,
    normal_damped,
    prove_no_window,
    trace_damped,
    trace_phase,
)
from .inputs import InputError
from .methods import METHODS, register_method
from .request import Request, make_request
from .result import Boundary, proven_text
from .undamped import float_edges

__all__ = [
    "Boundary",
    "Request",
    "boundary",
    "METHODS",
    "register_method",
    "CertificationError",
    "proven_text",
    "hump_normal",
    "hump_trace",
    "float_edges",
    "hump_box",
    "depth_ball",
    "trace_phase",
    "prove_no_window",
]

# the friction solvers under their former names (tests call them on a request)
_normal_damped = normal_damped
_trace_damped = trace_damped


def boundary(
    order,
    m=None,
    *,
    Q=None,
    damping="exact",
    digits=30,
    method="certified",
    tol=None,
    system="pendulum",
    duty="1/2",
) -> Boundary:
    """The lower and upper boundary ``T/T0`` of the ``order``-th interval of instability.

    ``m`` may be a str (``"3/5"``, ``"0.3"``, ``"1e-12"``: exact), int, Fraction, float (its exact
    binary value) or mpmath mpf.  ``Q`` is the quality factor (``None``: no friction); ``damping``
    ``"exact"`` (the damped oscillator) or ``"paper"`` (the paper's eqs. 28-30).  ``digits``
    significant digits are returned, each one proven (see the module text).  ``method`` picks a
    solver from :data:`METHODS`.  ``tol`` (a relative error of ``T/T0``) instead lets the engine
    pick the cheapest method that provably meets it (``method="auto"``, :mod:`verify.auto`; the
    digits then follow from ``tol``); ``Boundary.method`` says which one it used.

    ``system`` is a member of the family: ``"pendulum"`` (the paper's), ``"torsion"``,
    ``"meissner"``, or a value of :func:`analytic.system.custom` (which has no depth: leave ``m``
    out); ``duty`` is the fraction ``D`` of the period spent in phase 1 (default ``1/2``).
    """
    req, method = make_request(order, m, Q, damping, digits, method, tol, system, duty)
    try:
        solver = METHODS[method]
    except KeyError:
        raise InputError(f"method {method!r} is not one of: {', '.join(sorted(METHODS))}") from None
    return solver(req)
