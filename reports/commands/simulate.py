"""``paramres simulate``: follow the pendulum in time, on an edge or at a given period.

    paramres simulate --order N --m M (--edge lower|upper | --T T) [--Q Q]
                      [--damping exact|paper] [--periods K] [--amplitude A] [--nonlinear]
                      [--digits D] [--plot FILE] [--json]
                      [--modulation square|ramp|sine] [--switch-time S]

On an edge the run starts from the stationary initial condition and reports how well the state
returns after ``2T`` (odd orders) or ``T`` (even); at any period it reports the growth per period
measured on the trajectory and the Floquet multiplier of :mod:`verify.floquet`.  ``--nonlinear``
integrates the real pendulum (``sin phi``) and reports how the growth saturates.
"""

from __future__ import annotations

import argparse

import mpmath

from reports.output import dump_json, progress
from verify.timedomain import EDGES, MAX_PERIODS

from ._arguments import (
    add_depth,
    add_friction,
    add_json,
    add_modulation,
    add_order,
    add_quiet,
    add_system,
    system_of,
)

__all__ = ["register", "run", "render_text"]


def register(subparsers) -> None:
    p = subparsers.add_parser(
        "simulate",
        help="time-domain simulation: closure on an edge, growth per period, phase portraits",
        description=(
            "Follow the pendulum through the jumps of its length. On an edge of the interval of "
            "order N (--edge) the run starts from the stationary initial condition and the closure "
            "error after 2T (odd N) or T (even N) is reported; at a period T (--T, in units of T0) "
            "the growth per period measured on the trajectory is compared with the Floquet "
            "multiplier. The linear model is propagated exactly (closed-form segments) at "
            "--digits digits; --nonlinear integrates phi'' + 2 gamma phi' + omega^2 sin(phi) = 0 "
            "between the jumps: the amplitude-dependent period limits the growth, unless the "
            "pendulum goes over the top, which the run detects and reports (it then rotates); a "
            "rotation that the jumps keep speeding up is stopped at a budget of integration steps "
            "and refused."
        ),
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    add_order(p)
    add_depth(p, required=False)
    where = p.add_mutually_exclusive_group(required=True)
    where.add_argument(
        "--edge", choices=EDGES, help="start on this edge of the interval of order N"
    )
    where.add_argument(
        "--T",
        metavar="T",
        help="modulation period in units of T0, 0 < T <= 1e6 (start from rest at angle A)",
    )
    add_friction(p)
    add_system(p)
    add_modulation(p)
    p.add_argument(
        "--periods",
        metavar="K",
        default=None,
        help=f"modulation periods to follow, 1 to {MAX_PERIODS} (default 8; 200 with --nonlinear)",
    )
    p.add_argument(
        "--amplitude",
        metavar="A",
        default="0.1",
        help="initial amplitude in radians, 0 < A < pi (default 0.1)",
    )
    p.add_argument("--nonlinear", action="store_true", help="integrate the real pendulum (sin phi)")
    p.add_argument(
        "--digits",
        metavar="D",
        default="30",
        help="working precision of the linear model, 5 to 10000 digits (default 30)",
    )
    p.add_argument(
        "--plot",
        metavar="FILE",
        help="write phase trajectory, phi'(t), phi(t) (.pdf, .png or .svg)",
    )
    add_json(p)
    add_quiet(p)
    p.set_defaults(func=run)


def run(args) -> int:
    from reports.timeplots import check_plot_path, save_figure, time_figure
    from verify.timedomain import simulate

    plot = (
        check_plot_path(args.plot) if args.plot is not None else None
    )  # refuse a bad name before any work
    sysv = system_of(args)
    if args.modulation.strip().lower() != "square" or args.switch_time is not None:
        return _run_modulated(args, sysv, plot)
    sim = simulate(
        args.order,
        args.m,
        edge=args.edge,
        T=args.T,
        Q=args.Q,
        damping=args.damping,
        periods=args.periods,
        amplitude=args.amplitude,
        nonlinear=args.nonlinear,
        digits=args.digits,
        progress=lambda it, total: progress(it, total=total, label="simulate", quiet=args.quiet),
        system=sysv,
    )
    if plot is not None:
        fig = time_figure(sim, numbered=0 if sim.periods > 4 else 8, envelope=sim.nonlinear)
        save_figure(fig, plot)
    if args.json:
        out = sim.as_json()
        if plot is not None:
            out["plot"] = str(plot)
        dump_json(out)
    else:
        print(render_text(sim, plot))
    return 0


def _run_modulated(args, sysv, plot) -> int:
    """The ramp or sine modulation: :func:`verify.modulated_run.simulate_modulated`."""
    from verify.inputs import InputError, as_modulation
    from verify.modulated_run import simulate_modulated

    kind, S = as_modulation(args.modulation, args.switch_time, sysv)
    if plot is not None:
        raise InputError(f"--plot is not available with the {kind} modulation")
    if args.damping.strip().lower() != "exact" and args.Q is not None:
        raise InputError(f"the {kind} modulation has the exact friction model only")
    run_ = simulate_modulated(
        args.order,
        args.m,
        modulation=kind,
        switch_time=S,
        edge=args.edge,
        T=args.T,
        Q=args.Q,
        periods=args.periods or (200 if args.nonlinear else 8),
        amplitude=args.amplitude,
        nonlinear=args.nonlinear,
    )
    if args.json:
        dump_json(run_.as_json())
    else:
        print(run_)
    return 0


def _fmt(x, digits: int) -> str:
    x = mpmath.mpmathify(x)
    with mpmath.workdps(digits):
        if isinstance(x, mpmath.mpc):
            sign = "+" if x.imag >= 0 else "-"
            return f"{mpmath.nstr(x.real, digits)} {sign} {mpmath.nstr(abs(x.imag), digits)}i"
        return mpmath.nstr(x, digits)


def render_text(sim, plot=None) -> str:
    """The readable report of a run."""
    d = sim.digits if not sim.nonlinear else 12
    lines = []
    where = f"{sim.edge} edge" if sim.edge else "given period"
    fr = "no friction" if sim.Q is None else f"Q = {sim.Q}, {sim.damping} friction model"
    head = f"order {sim.order}, " + ("" if sim.m is None else f"m = {sim.m}, ") + fr
    lines.append(head if sim.system.is_paper else f"{sim.system.label}: {head}")
    lines.append(f"  T/T0 = {_fmt(sim.tau, sim.digits)} ({where})")
    if sim.interval is not None:
        lo, hi = (_fmt(x, 12) for x in sim.interval)
        state = f"its {sim.edge} edge" if sim.edge else ("inside" if sim.inside else "outside")
        lines.append(f"  interval of order {sim.order}: {lo} < T/T0 < {hi}; T is {state}")
    else:
        lines.append(f"  no interval of order {sim.order} at this depth and friction")
    lines.append(f"  method: {sim.method}")
    if sim.edge_kind:
        lines.append(f"  start: stationary initial condition of the edge shape {sim.edge_kind}")
    elif sim.edge:
        lines.append(
            f"  start: eigenvector of the monodromy for the multiplier {(-1) ** sim.order}"
        )
    else:
        lines.append(
            f"  start: at rest at the angle {float(sim.amplitude):g} rad as the bob moves down"
        )
    lines.append(f"  initial (phi, phi'): ({_fmt(sim.initial[0], 12)}, {_fmt(sim.initial[1], 12)})")
    if sim.closure_error is not None:
        after = "2T" if sim.closure_periods == 2 else "T"
        lines.append(f"  closure error after {after}: {_fmt(sim.closure_error, 3)} (relative)")
        lines.append(f"  largest return error over the run: {_fmt(sim.max_return_error, 3)}")
    lines.append(f"  growth per period, measured: {_fmt(sim.growth_per_period, d)}")
    lines.append(f"  Floquet multipliers:         {', '.join(_fmt(x, d) for x in sim.multipliers)}")
    lines.append(f"  largest |multiplier|:        {_fmt(sim.floquet_growth, d)}")
    lines.append(f"  relative difference:         {_fmt(sim.growth_agreement, 3)}")
    if sim.nonlinear:
        lines.append(f"  peak amplitude over {sim.periods} periods: {sim.peak_amplitude:.6g} rad")
        if sim.rotates:
            lines.append(
                "  the pendulum went over the top (|phi| passed pi): it rotates instead of "
                "swinging, and the peak angle counts whole turns"
            )
        if sim.saturation_estimate is not None and not sim.rotates:
            lines.append(
                f"  amplitude at which the lengthened free period carries the lower edge past T "
                f"(estimate): {sim.saturation_estimate:.4g} rad"
            )
        step = max(1, sim.periods // 20)
        env = ", ".join(f"{sim.envelope[k]:.3g}" for k in range(0, sim.periods, step))
        lines.append(f"  max |phi| every {step} period(s): {env}")
    if plot is not None:
        lines.append(f"  plot written to {plot}")
    return "\n".join(lines)
