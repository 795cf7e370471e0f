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


def _exact_step(w: int, h: str):
    """The oscillator's map over the decimal ``h`` (mpmath at 60 digits, as strings for arb)."""
    with mpmath.workdps(60):
        c, s = mpmath.cos(w * mpmath.mpf(h)), mpmath.sin(w * mpmath.mpf(h))
        return [mpmath.nstr(v, 55) for v in (c, s / w, -w * s, c)]


def _encloses(step, w, h):
    P, used = step
    for ball, ref in zip(P, _exact_step(w, h), strict=True):
        assert ball.overlaps(arb(ref, mpmath.mpf(10) ** -50)), (ball, ref)
    return used


@pytest.mark.parametrize("prec", [64, 200])
def test_one_step_by_each_bound(prec, monkeypatch):
    """One step of the oscillator (w = 3, rho = 4 h) closed by each of the two remainder
    bounds: the defect bound (short step: fewer terms than the ``bits/2 + 8`` coefficients of
    ``A`` computed first), the majorant where the defect bound is switched off (the step then
    uses the majorant's count of terms, beyond the coefficients computed first), and a step too
    long for either within the most terms allowed (refused)."""
    import verify.taylor as taylor

    w = 3
    with ctx.workprec(prec):
        bits = prec + 10
        coef = _oscillator(arb(w))
        for h in ("0.05", "0.4"):
            hb, rho = arb(h), 4 * arb(h)
            K = taylor._bound(coef, arb(0), rho)
            used = _encloses(taylor._step(coef, arb(0), hb, K, rho, bits), w, h)
            assert 4 <= used <= bits // 2 + 8
        # the defect bound off: the majorant's count and tail close the step (asked for once
        # the bits/2 + 8 coefficients computed first are used up: at least that many terms)
        monkeypatch.setattr(taylor, "_defect_tail", lambda *a: arb(1))
        counts = set()
        for h in ("0.05", "0.4"):
            hb, rho = arb(h), 4 * arb(h)
            K = taylor._bound(coef, arb(0), rho)
            N, _ = taylor._terms(K, rho, hb, bits)
            used = _encloses(taylor._step(coef, arb(0), hb, K, rho, bits), w, h)
            assert used == max(N, bits // 2 + 9)
            counts.add(N > bits // 2 + 9)
        assert counts == {False, True}  # the majorant's count below and beyond them
        # too long for the majorant within bits/2 + MAX_TERMS terms: refused
        hb, rho = arb(2), arb(8)
        K = taylor._bound(coef, arb(0), rho)
        assert taylor._terms(K, rho, hb, bits) is None
        assert taylor._step(coef, arb(0), hb, K, rho, bits) is None


@pytest.mark.parametrize("goal", [40, 56])
def test_a_lower_goal_still_encloses(goal):
    """``goal_bits`` below the default (the working precision plus 10): fewer terms, balls still
    enclosing the oscillator's map (reference: mpmath at 60 digits), their radii near
    ``2^-goal`` (at most a few steps' tails, times the map's growth)."""
    w, span = 7, 5
    with ctx.workprec(64):
        M = flow(_oscillator(arb(w)), arb(0), arb(span), scale=arb(w), goal_bits=goal)
    with mpmath.workdps(60):
        c, s = mpmath.cos(w * span), mpmath.sin(w * span)
        exact = (c, s / w, -w * s, c)
    for ball, ref in zip(M, exact, strict=True):
        assert ball.overlaps(arb(mpmath.nstr(ref, 55), mpmath.mpf(10) ** -50)), (ball, ref)
        assert ball.rad() < arb(2) ** (-(goal - 16))
