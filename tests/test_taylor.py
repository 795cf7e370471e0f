"""The validated Taylor integrator (verify.taylor) on a flow known in closed form: the harmonic
oscillator ``y' = [[0, 1], [-w^2, 0]] y``, whose map over ``t`` is ``[[cos wt, sin(wt)/w],
[-w sin wt, cos wt]]`` (reference: mpmath at 60 digits).  Long spans and a large ``w`` (integrated
in the balanced variables ``(y1, y2/w)``) make the integrator take many steps of both kinds (the
majorant's and the defect bound's)."""

from __future__ import annotations

import mpmath
import pytest
from flint import arb, arb_series, ctx

from verify.taylor import flow


def _oscillator(w: arb):
    def coef(t):
        if isinstance(t, arb_series):
            zero = arb_series([0], prec=t.prec)
            return [zero, arb_series([1], prec=t.prec), arb_series([-w * w], prec=t.prec), zero]
        return [0 * t, 0 * t + 1, 0 * t - w * w, 0 * t]

    return coef


@pytest.mark.parametrize("prec", [64, 120, 250])
@pytest.mark.parametrize("w, span", [(1, 3), (7, 5), (40, 2)])
def test_flow_encloses_the_oscillator(prec, w, span):
    with ctx.workprec(prec):
        M = flow(_oscillator(arb(w)), arb(0), arb(span), scale=arb(w))
    with mpmath.workdps(60):
        c, s = mpmath.cos(w * span), mpmath.sin(w * span)
        exact = (c, s / w, -w * s, c)
    for ball, ref in zip(M, exact, strict=True):
        assert ball.contains(arb(mpmath.nstr(ref, 55))) or ball.overlaps(
            arb(mpmath.nstr(ref, 55), mpmath.mpf(10) ** -50)
        ), (ball, ref)
        # and the ball is narrow: about the precision asked for
        assert ball.rad() < (1 + abs(arb(mpmath.nstr(ref, 20)))) * arb(2) ** (-(prec - 24))
