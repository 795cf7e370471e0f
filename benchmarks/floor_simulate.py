"""The nonlinear simulation against a compiled DOP853 loop, timed side by side.

The floor is the plain loop with the same integrator and tolerances, written here without engine
code: the pendulum ``phi'' = -omega_i^2 sin(phi)`` (``omega_i^2 = (2 pi)^2/(1 +- m)`` in units of
``T0``) integrated half period by half period by Hairer's DOP853 through
``scipy.integrate.ode(f).set_integrator("dop853", rtol, atol)``, ``phi'`` multiplied by
``((1+m)/(1-m))^2`` at the switch to the short length and divided by it at the switch back (eq. 4);
nothing recorded but the state at each period.  Each half period starts from DOP853's own guess of
the first step.

Ours is the public ``paramres.simulate(..., nonlinear=True)`` through its whole path: the certified
edge and the Floquet multipliers at 30 digits, the run (the integrator's steps recorded, the plotted
segments interpolated from them afterwards), the multipliers measured from the stroboscopic states
and the envelope.  Its run does less than the floor's: each half period starts with the step the
integrator took at the same place of the previous half period of the same kind (DOP853's error
control accepts or shrinks it as any step), which saves DOP853's smaller first steps and its two
evaluations for the guess (about 14 % of the evaluations), and its right-hand side reads the state
as two floats and writes into one kept array instead of returning a new list (which the integrator
converts into an array at every evaluation).  The extra figures: the largest difference of the
stroboscopic angles, ours against the floor's, and each against the same loop at
``rtol = 1e-13``: the error of a run over 2000 periods is its global error (the beats are
sensitive to the phase), of the same size in both.

Scene: order 1 at ``m = 1/20``, ``T`` a third of the way into the first interval, amplitude 1/100
(the beats of the nonlinear pendulum), 2000 periods (200 with ``--quick``); five alternated single
calls each (a single pair varies by 20-40 % on a loaded machine); target 1.2x.

Run ``python benchmarks/floor_simulate.py [--quick] [--extra]`` for the ratio alone.
"""

from __future__ import annotations

import math
from fractions import Fraction

M = Fraction(1, 20)
#: a third of the way into the first interval at m = 1/20 (the lower and upper edges from
#: ``paramres boundary --order 1 --m 1/20``, rounded to 12 digits; any T inside serves)
T = Fraction(2 * 475_699_199_170 + 523_358_950_673, 3 * 10**12)
AMPLITUDE = Fraction(1, 100)
RTOL, ATOL = 1e-10, 1e-13


def floor_run(periods: int, rtol: float = RTOL, atol: float = ATOL):
    """The states at ``t = k T`` for ``k = 0 .. periods`` (the floor)."""
    from scipy.integrate import ode

    m = float(M)
    w2 = ((2 * math.pi) ** 2 / (1 + m), (2 * math.pi) ** 2 / (1 - m))
    k12 = ((1 + m) / (1 - m)) ** 2
    half = float(T) / 2
    cur = [w2[0]]
    sin = math.sin

    def f(t, y):
        return [y[1], -cur[0] * sin(y[0])]

    solver = ode(f).set_integrator("dop853", rtol=rtol, atol=atol, nsteps=10**7)
    s = [float(AMPLITUDE), 0.0]
    out = [tuple(s)]
    for _ in range(periods):
        for h, jump in ((0, k12), (1, 1 / k12)):
            cur[0] = w2[h]
            solver.set_initial_value(s, 0.0)
            solver.integrate(half)
            s = [float(solver.y[0]), float(solver.y[1]) * jump]
        out.append(tuple(s))
    return out


def _ours(periods: int):
    import paramres

    return paramres.simulate(
        1, M, T=T, periods=periods, amplitude=AMPLITUDE, nonlinear=True, rtol=RTOL, atol=ATOL
    )


def _agreement(periods: int) -> dict:
    """The largest differences of the stroboscopic angles: ours against the floor's (both DOP853
    at the same tolerances, started differently each half period), and each against the floor's
    loop at ``rtol = 1e-13``, ``atol = 1e-16`` (their global errors)."""
    a = [float(x[0]) for x in _ours(periods).strobe]
    b = [y[0] for y in floor_run(periods)]
    c = [y[0] for y in floor_run(periods, rtol=1e-13, atol=1e-16)]

    def gap(u, v):
        return max(abs(x - y) for x, y in zip(u, v, strict=True))

    return {
        "max |phi_ours - phi_floor| over the strobe": gap(a, b),
        "max |phi_ours - phi_tight| (rtol 1e-13)": gap(a, c),
        "max |phi_floor - phi_tight| (rtol 1e-13)": gap(b, c),
    }


def scenes(quick: bool) -> list[dict]:
    periods = 200 if quick else 2000
    return [
        {
            "name": f"simulate nonlinear {periods} periods",
            "target": 1.2,
            "ours": lambda: _ours(periods),
            "floor": lambda: floor_run(periods),
            "note": (
                "scipy.integrate.ode dop853 per half period, same rtol/atol, DOP853's own first "
                "step, no recording"
            ),
            "extra": lambda: _agreement(periods),
            "repeat": 5,
        }
    ]


def _main(argv=None) -> int:  # pragma: no cover - a measurement
    import sys

    from floors import measure  # run as a script: this directory is on sys.path

    argv = argv if argv is not None else sys.argv[1:]
    for sc in scenes("--quick" in argv):
        n = 5
        a, b = measure(sc["ours"], sc["floor"], samples=n, min_time=0)
        print(
            f"{sc['name']:<40} ours {a * 1e3:9.1f} ms  floor {b * 1e3:9.1f} ms  "
            f"ratio {a / b:5.2f}  target {sc['target']}",
            flush=True,
        )
        if "--extra" in argv:
            print("   ", sc["extra"](), flush=True)
    return 0


if __name__ == "__main__":  # pragma: no cover
    raise SystemExit(_main())
