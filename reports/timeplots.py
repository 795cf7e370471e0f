"""Time-domain pictures: the phase trajectory, ``phi'(t)`` and ``phi(t)`` of a simulated run.

The layout follows the paper's figures 1, 3-7 and 9: on the left the phase trajectory in the plane
``(phi, phi')`` -- arcs of two families of ellipses, one per length of the pendulum, joined by the
vertical jumps of the angular velocity at the moments the bob moves -- and on the right the angular
velocity and the angle against time, the moments of the jumps marked.  The points where a half
period starts and ends are numbered on the first periods, the same numbers in the phase plane and
on ``phi'(t)``, as the paper does.

:func:`paper_figure` re-draws the paper's scenes from runs of :func:`verify.timedomain.simulate`
(the
paper gives no depth for its pictures; the depths chosen here are in :data:`PAPER_SCENES`), and
:func:`envelope_figure` shows how the growth inside an interval is limited by the
amplitude-dependent period of the real (nonlinear) pendulum.  Figures are built without pyplot;
:func:`figure_bytes` renders one as PDF, PNG or SVG, :func:`save_figure` writes it atomically.
"""

from __future__ import annotations

from dataclasses import dataclass
from fractions import Fraction
from pathlib import Path

import numpy as np
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.figure import Figure

from verify.inputs import InputError

from . import figures
from .figures import FORMATS, TEXT_WIDTH_IN, check_plot_path, figure_bytes, pdf_text_extent, style
from .i18n import say

__all__ = [
    "PAPER_SCENES",
    "Scene",
    "time_figure",
    "envelope_figure",
    "saturation_figure",
    "paper_figure",
    "paper_simulations",
    "figure_bytes",
    "save_figure",
    "check_plot_path",
    "draw_run",
    "over_the_top",
    "FORMATS",
]

#: file name endings a figure can be written as

#: colours of the two halves: bob down (long pendulum), bob up (short pendulum)
HALF_COLOURS = {1: "#0072B2", 2: "#D55E00"}
JUMP_COLOUR = "0.45"
#: the level |phi| = pi and the moment a nonlinear run passes it (goes over the top)
ROTATION_COLOUR = "#CC79A7"
#: the height of one more line of a run's title (7.5 pt type), in inches
TITLE_LINE_IN = 0.13


@dataclass(frozen=True)
class Scene:
    """One of the paper's time-domain pictures, as a run: the arguments of ``simulate``."""

    figure: int
    caption: str
    runs: tuple[dict, ...]


#: the paper's time-domain figures.  Fig. 7 is the closing of the third interval (T1 : T2 = 2 : 1 at
#: m = 3/5, where both edges coincide); the others use moderate depths that show the shapes clearly.
PAPER_SCENES: dict[int, Scene] = {
    1: Scene(
        1,
        "Stationary oscillation on the lower edge of the first interval (near $T = T_{av}/2$)",
        ({"order": 1, "m": Fraction(3, 10), "edge": "lower", "periods": 3},),
    ),
    3: Scene(
        3,
        "Stationary oscillation on the upper edge of the first interval",
        ({"order": 1, "m": Fraction(3, 10), "edge": "upper", "periods": 3},),
    ),
    4: Scene(
        4,
        "Stationary oscillations on the lower and upper edges of the third interval "
        "($T \\approx 3T_{av}/2$)",
        (
            {"order": 3, "m": Fraction(3, 10), "edge": "lower", "periods": 2},
            {"order": 3, "m": Fraction(3, 10), "edge": "upper", "periods": 2},
        ),
    ),
    5: Scene(
        5,
        "Growth of the oscillation at the second-order resonance ($T \\approx T_{av}$)",
        ({"order": 2, "m": Fraction(1, 5), "T": "centre", "periods": 12, "amplitude": 0.02},),
    ),
    6: Scene(
        6,
        "Stationary oscillation on the lower edge of the second interval (near $T = T_{av}$)",
        ({"order": 2, "m": Fraction(1, 2), "edge": "lower", "periods": 3},),
    ),
    7: Scene(
        7,
        "Closing of the third interval: $T_1 : T_2 = 2 : 1$ ($m = 3/5$), "
        "every solution is periodic",
        # a start that is not one of the symmetric shapes: at the closing it returns all the same
        ({"order": 3, "m": Fraction(3, 5), "edge": "lower", "periods": 2, "phase": -0.7},),
    ),
    9: Scene(
        9,
        "Stationary oscillation on the lower edge of the first interval with friction ($Q = 3$)",
        ({"order": 1, "m": Fraction(3, 10), "edge": "lower", "Q": Fraction(3), "periods": 3},),
    ),
}


# ---------------------------------------------------------------------------------------------
# drawing


#: the vertical margins of the phase plane and of the velocity plot, as shares of the data range
#: (matplotlib's default is 0.05): a number is drawn 3 points above its point and is 7 points high
NUMBERED_MARGIN = (0.1, 0.2)


def _new(width: float, height: float) -> Figure:
    fig = Figure(figsize=(width, height))
    FigureCanvasAgg(fig)
    return fig


def _label(sim) -> str:
    return ", ".join(_label_parts(sim))


def _label_parts(sim) -> list[str]:
    """The run's parameters (in one formula), its edge, its friction, as separate phrases."""
    import mpmath

    with mpmath.workdps(sim.digits):
        T = mpmath.nstr(sim.tau, 10)
    parts = [f"$n = {sim.order}$, $m = {sim.m}$, $T/T_0 = {T}$"]
    if sim.edge:
        parts.append(
            say(
                f"{sim.edge} edge",
                {"lower": "нижняя граница", "upper": "верхняя граница"}[sim.edge],
            )
        )
    if sim.Q is None:
        parts.append(say("no friction", "без трения"))
    else:
        model = say(sim.damping, {"exact": "точная модель", "paper": "модель статьи"}[sim.damping])
        parts.append(f"$Q = {sim.Q}$ ({model})")
    if sim.nonlinear:
        parts.append(say("nonlinear", "нелинейный"))
    return parts


def _sci(x: float) -> str:
    """``1.6e-40`` as mathematics, ``$1.6\\cdot 10^{-40}$``."""
    mant, _, exp = f"{x:.1e}".partition("e")
    return "$0$" if x == 0 else f"${mant}\\cdot 10^{{{int(exp)}}}$"


def _fitting_title(ax, candidates: list[list[str]], **kw) -> int:
    """Title ``ax`` with the first candidate (a list of lines) that ends inside the figure, or the
    last one if none does (the lines of the candidates are shorter and shorter); the number of
    lines used."""
    fig = ax.figure
    # measured as the figure's PDF lays the title out (the formulas in it are laid out once,
    # for this and for the drawing); the margin is two pixels at the figure's resolution
    limit = 72 * fig.get_figwidth() - 2 * 72 / fig.dpi
    for lines in candidates:
        lines = [x for x in lines if x]
        title = ax.set_title("\n".join(lines), **kw)
        if pdf_text_extent(fig, title)[1] <= limit:
            break
    return len(lines)


def _check_finite(sim) -> None:
    for s in sim.segments:
        if not (np.all(np.isfinite(s.phi)) and np.all(np.isfinite(s.dphi))):
            raise InputError(
                "the trajectory leaves the range of double precision; plot fewer periods"
            )


def over_the_top(sim) -> tuple[float, float] | None:
    """``(t, phi)`` where a nonlinear run first passes ``|phi| = pi`` (the pendulum goes over the
    top and rotates from then on), or ``None``."""
    if not getattr(sim, "rotates", None):
        return None
    for s in sim.segments:
        phi = np.asarray(s.phi, dtype=float)
        hit = np.nonzero(np.abs(phi) > np.pi)[0]
        if hit.size:
            k = int(hit[0])
            return float(np.asarray(s.t, dtype=float)[k]), float(phi[k])
    return None  # pragma: no cover - rotates means some sample passed pi


def _mark_rotation(ax_phase, ax_angle, sim) -> None:
    """The level ``|phi| = pi`` and the moment the pendulum first passes it, with a legend."""
    top = over_the_top(sim)
    if top is None:
        return
    t, phi = top
    for level in (np.pi, -np.pi):
        ax_angle.axhline(level, color=ROTATION_COLOUR, lw=0.6, ls=":", zorder=0)
        ax_phase.axvline(level, color=ROTATION_COLOUR, lw=0.6, ls=":", zorder=0)
    ax_angle.plot(
        [t],
        [phi],
        marker="v",
        ms=5,
        color=ROTATION_COLOUR,
        ls="none",
        label=say(
            rf"over the top ($|\varphi| = \pi$) at $t/T_0 = {t:.3g}$: it rotates",
            rf"переход через верх ($|\varphi| = \pi$) при $t/T_0 = {t:.3g}$: вращение",
        ),
    )
    ax_angle.legend(fontsize=6.5, loc="upper left")


def draw_run(ax_phase, ax_vel, ax_angle, sim, *, numbered: int = 8) -> None:
    """Draw one run on three axes; number the first ``numbered`` segment end points.  A
    nonlinear run that goes over the top is marked where it first passes ``|phi| = pi``."""
    _check_finite(sim)
    segs = sim.segments
    for i, s in enumerate(segs):
        c = HALF_COLOURS[s.half]
        ax_phase.plot(s.phi, s.dphi, color=c, lw=1.0)
        ax_vel.plot(s.t, s.dphi, color=c, lw=1.0)
        ax_angle.plot(s.t, s.phi, color=c, lw=1.0)
        if i + 1 < len(segs):
            nxt = segs[i + 1]
            # the jump: angle continuous, angular velocity changes (J phi' conserved)
            ax_phase.plot(
                [s.phi[-1], nxt.phi[0]],
                [s.dphi[-1], nxt.dphi[0]],
                color=JUMP_COLOUR,
                lw=0.8,
                ls="--",
            )
            ax_vel.plot(
                [s.t[-1], nxt.t[0]], [s.dphi[-1], nxt.dphi[0]], color=JUMP_COLOUR, lw=0.8, ls="--"
            )
    for ax in (ax_vel, ax_angle):
        if len(segs) <= 40:  # mark the moments of the jumps while they can be told apart
            for tj in sim.jump_times:
                ax.axvline(tj, color="0.85", lw=0.5, zorder=0)
        ax.axhline(0, color="0.6", lw=0.5, zorder=0)
    ax_phase.axhline(0, color="0.6", lw=0.5, zorder=0)
    ax_phase.axvline(0, color="0.6", lw=0.5, zorder=0)
    # numbered points: start and end of each of the first segments; in the phase plane points that
    # coincide (a closed trajectory passes them twice) share one label, "2,5"
    points = []
    for s in segs:
        for j in (0, -1):
            if len(points) < numbered:
                points.append((len(points) + 1, s.t[j], s.phi[j], s.dphi[j]))
    span = max((max(np.ptp(s.phi), np.ptp(s.dphi) / 10) for s in segs), default=1.0) or 1.0
    groups: list[list] = []
    for p in points:
        for g in groups:
            if abs(g[0][2] - p[2]) < 1e-3 * span and abs(g[0][3] - p[3]) < 1e-2 * span:
                g.append(p)
                break
        else:
            groups.append([p])
    for g in groups:
        x, y = g[0][2], g[0][3]
        ax_phase.plot([x], [y], "o", ms=2.2, color="k")
        ax_phase.annotate(
            ",".join(str(p[0]) for p in g),
            (x, y),
            textcoords="offset points",
            xytext=(3, 3),
            fontsize=7,
        )
    for k, t, _, dphi in points:
        ax_vel.plot([t], [dphi], "o", ms=2.2, color="k")
        ax_vel.annotate(str(k), (t, dphi), textcoords="offset points", xytext=(3, 3), fontsize=7)
    # room above and below the curves, so that the numbered points at their extremes and the
    # numbers above them stay off the frame
    ax_phase.margins(y=NUMBERED_MARGIN[0])
    ax_vel.margins(y=NUMBERED_MARGIN[1])
    rad = say("rad", "рад")
    ax_phase.set_xlabel(rf"$\varphi$ ({rad})")
    ax_phase.set_ylabel(rf"$\dot\varphi$ ({rad}$/T_0$)")
    ax_vel.set_ylabel(rf"$\dot\varphi$ ({rad}$/T_0$)")
    ax_angle.set_ylabel(rf"$\varphi$ ({rad})")
    ax_angle.set_xlabel(r"$t/T_0$")
    _mark_rotation(ax_phase, ax_angle, sim)


def time_figure(
    sims, *, title: str | None = None, numbered: int = 8, envelope: bool = False
) -> Figure:
    """Phase trajectory, ``phi'(t)`` and ``phi(t)`` for one run or a row per run; with
    ``envelope`` a last row shows the largest ``|phi|`` per period (see :func:`envelope_figure`)."""
    sims = list(sims) if isinstance(sims, list | tuple) else [sims]
    rows = len(sims)
    with style():
        extra = 2.2 if envelope else 0.0
        height = 3.0 * rows + extra + (0.3 if title else 0)
        fig = _new(TEXT_WIDTH_IN, height)
        top = 1 - (0.45 + (0.3 if title else 0)) / height  # room for the titles, in inches
        ratios = [3.0] * rows + ([extra] if envelope else [])
        first_row_moved = False
        outer = fig.add_gridspec(
            len(ratios), 1, hspace=0.42, top=top, bottom=0.45 / height, height_ratios=ratios
        )
        for r, sim in enumerate(sims):
            inner = outer[r].subgridspec(2, 2, width_ratios=(1, 1.6), wspace=0.3, hspace=0.15)
            ax_phase = fig.add_subplot(inner[:, 0])
            ax_vel = fig.add_subplot(inner[0, 1])
            ax_angle = fig.add_subplot(inner[1, 1], sharex=ax_vel)
            ax_vel.tick_params(labelbottom=False)
            draw_run(ax_phase, ax_vel, ax_angle, sim, numbered=numbered)
            note = []
            if sim.closure_error is not None:
                after = "2T" if sim.closure_periods == 2 else "T"
                closure = _sci(float(sim.closure_error))
                note.append(
                    say(f"closure after ${after}$: ", f"невязка через ${after}$: ") + closure
                )
            growth = f"{float(sim.growth_per_period):.6g}"
            note.append(say("growth per period ", "рост за период ") + growth)
            if sim.nonlinear and sim.rotates:
                note.append(say("over the top: it rotates", "переход через верх: вращение"))
            elif sim.nonlinear:
                peak = f"{sim.peak_amplitude:.3g}"
                note.append(say(f"peak amplitude {peak} rad", f"наибольший размах {peak} рад"))
            head = _label_parts(sim)
            lines = _fitting_title(
                ax_vel,
                [
                    [", ".join(head), "; ".join(note)],
                    [head[0], ", ".join(head[1:]), "; ".join(note)],
                    [head[0], ", ".join(head[1:]), *note],
                ],
                fontsize=7.5,
                loc="left",
            )
            if r == 0 and lines > 2:  # room above the first row for the longer title
                outer.update(top=top - TITLE_LINE_IN * (lines - 2) / height)
                first_row_moved = True
        if envelope:
            _draw_envelope(fig.add_subplot(outer[rows]), sims, [_label(s) for s in sims])
        if first_row_moved:
            for ax in fig.axes:
                ax.set_position(ax.get_subplotspec().get_position(fig))
        if title:
            fig.suptitle(title, fontsize=9)
    return fig


def _draw_envelope(ax, runs, labels) -> None:
    marked = False
    for sim, lab in zip(runs, labels, strict=True):
        env = np.asarray(sim.envelope, dtype=float)
        ax.semilogy(np.arange(1, len(env) + 1), env, lw=1.0, label=lab)
        if sim.saturation_estimate is not None:
            label = (
                None
                if marked
                else say(
                    "amplitude that detunes the lower edge past $T$ (estimate)",
                    "амплитуда, при которой нижняя граница уходит за $T$ (оценка)",
                )
            )
            ax.axhline(sim.saturation_estimate, color="0.5", lw=0.6, ls=":", label=label)
            marked = True
    rotating = any(getattr(s, "rotates", None) for s in runs)
    if rotating:
        ax.axhline(
            np.pi, color=ROTATION_COLOUR, lw=0.6, ls=":", label=r"$|\varphi| = \pi$: over the top"
        )
    ax.set_xlabel(say("period $k$", "период $k$"))
    ax.set_ylabel(say(r"$\max|\varphi|$ in period $k$", r"$\max|\varphi|$ за период $k$"))
    if len(labels) > 1 or rotating or any(s.saturation_estimate is not None for s in runs):
        ax.legend(fontsize=7)


def envelope_figure(runs, labels, *, title: str | None = None, ylim=None) -> Figure:
    """The largest ``|phi|`` in each period for several runs (e.g. linear against nonlinear), on a
    logarithmic scale: exponential growth is a straight line, beats and saturation bend it.  A
    dotted line marks a run's estimate of the amplitude at which the lengthened free period carries
    the interval past ``T``."""
    with style():
        fig = _new(TEXT_WIDTH_IN, 3.0)
        ax = fig.add_subplot(1, 1, 1)
        _draw_envelope(ax, runs, labels)
        if ylim is not None:
            ax.set_ylim(*ylim)
        # the legend above the axes, in two columns: inside, the growing curve crosses it
        ax.legend(fontsize=7, loc="lower left", bbox_to_anchor=(0, 1.02), ncol=2, borderaxespad=0)
        fig.subplots_adjust(top=0.8 if not title else 0.72)
        if title:
            fig.suptitle(title, fontsize=9)
    return fig


# ---------------------------------------------------------------------------------------------
# the paper's scenes


def _centre(order, m):
    import mpmath

    from verify import boundary

    b = boundary(order, m)
    if not b.exists:  # pragma: no cover - the scenes are chosen where the interval exists
        raise InputError(f"no interval of order {order} at m = {m}")
    with mpmath.workdps(30):
        return (b.lower + b.upper) / 2


def paper_simulations(number: int, *, digits: int = 30):
    """The runs behind the paper's figure ``number`` (one of :data:`PAPER_SCENES`)."""
    from verify.timedomain import simulate

    if number not in PAPER_SCENES:
        raise InputError(
            f"figure {number} is not a time-domain scene; choose from {sorted(PAPER_SCENES)}"
        )
    sims = []
    for run in PAPER_SCENES[number].runs:
        kw = dict(run)
        if kw.get("T") == "centre":
            kw["T"] = _centre(kw["order"], kw["m"])
        if "phase" in kw:  # the state of amplitude A at this phase of the bob-down free oscillation
            import mpmath

            alpha, A = kw.pop("phase"), kw.pop("amplitude", 0.1)
            with mpmath.workdps(digits + 10):
                w1 = (
                    2
                    * mpmath.pi
                    / mpmath.sqrt(1 + mpmath.mpf(kw["m"].numerator) / kw["m"].denominator)
                )
                kw["initial"] = (A * mpmath.cos(alpha), -A * w1 * mpmath.sin(alpha))
        sims.append(simulate(digits=digits, **kw))
    return sims


def paper_figure(number: int, *, digits: int = 30, titled: bool = False) -> Figure:
    """The paper's figure ``number`` re-drawn from simulated runs; ``titled`` puts the paper's
    number and caption above it (a figure in a document is titled by its caption instead)."""
    sims = paper_simulations(number, digits=digits)
    numbered = 0 if any(r.get("T") for r in PAPER_SCENES[number].runs) else 8
    title = f"Fig. {number}: {PAPER_SCENES[number].caption}" if titled else None
    return time_figure(sims, title=title, numbered=numbered)


def saturation_figure(
    *,
    m=Fraction(1, 20),
    Q=Fraction(30),
    periods: int = 300,
    amplitude=Fraction(1, 100),
    titled: bool = False,
) -> Figure:
    """Growth inside the first interval limited by the amplitude-dependent period: the envelope of
    the linear model (exponential growth) against the real pendulum without friction (beats) and
    with friction ``Q`` (beats that die out to a steady swing), all at one period ``T`` a third of
    the way into the interval with friction."""
    import mpmath

    from verify import boundary
    from verify.timedomain import simulate

    b = boundary(1, m, Q=Q)
    with mpmath.workdps(30):
        T = (2 * b.lower + b.upper) / 3
    common = {"T": T, "periods": periods, "amplitude": amplitude}
    runs = [
        simulate(1, m, **common),
        simulate(1, m, nonlinear=True, **common),
        simulate(1, m, Q=Q, nonlinear=True, **common),
    ]
    labels = [
        say("linear model", "линейная модель"),
        say("pendulum, no friction", "маятник без трения"),
        say(f"pendulum, $Q = {Q}$", f"маятник, $Q = {Q}$"),
    ]
    with mpmath.workdps(10):
        Tt = mpmath.nstr(T, 8)
    return envelope_figure(
        runs,
        labels,
        title=(
            f"First interval, $m = {m}$, $T/T_0 = {Tt}$: growth limited by the amplitude"
            if titled
            else None
        ),
        ylim=(float(amplitude) / 3, 30.0),
    )


# ---------------------------------------------------------------------------------------------
# output


def save_figure(fig: Figure, path) -> Path:
    """Write a time-domain figure (PDF, PNG or SVG by the file ending), atomically."""
    return figures.save_figure(fig, path, what="simulate")
