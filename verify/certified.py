"""The certified method: every edge an enclosure proven by ball arithmetic.

:func:`certified` picks the equations for the request -- the per-edge equations without friction
(:mod:`verify.undamped`), the normal form or the trace form with friction (:mod:`verify.hump`) --
and is registered as ``method="certified"`` (:mod:`verify.methods`).  :func:`boundary` is the same
for callers that want the certified edges only (the arguments of :func:`verify.solve.boundary`
without ``method`` and ``tol``).
"""

from __future__ import annotations

from .certify import CertificationError
from .hump import normal_damped, trace_damped
from .methods import register_method
from .params import form_for
from .request import Request, make_request
from .result import Boundary
from .undamped import undamped

__all__ = ["certified", "boundary"]


@register_method("certified")
def certified(req: Request) -> Boundary:
    """The certified edges for a checked request."""
    if req.Q is None:
        return undamped(req)
    kind, regimes = form_for(req.m, req.Q, req.damping, req.system)
    try:
        if kind == "normal":
            return normal_damped(req)
        return trace_damped(req, regimes)
    except OverflowError:
        # the float stage that starts the proof met a value past the double range (the friction
        # factors grow like exp(pi T/Q): a tiny Q at a deep modulation); nothing was proven
        raise CertificationError(
            f"order {req.order}, m = {req.m}, Q = {req.Q} ({req.damping} model): the "
            "indicator's values reach beyond the range of double precision where the proof "
            "starts; not decided"
        ) from None


def boundary(
    order, m=None, *, Q=None, damping="exact", digits=30, system="pendulum", duty="1/2"
) -> Boundary:
    """The certified edges (:func:`verify.solve.boundary` with ``method="certified"``)."""
    req, _ = make_request(order, m, Q, damping, digits, "certified", None, system, duty)
    return certified(req)
