"""The speed-against-error picture of ``paramres bench``: time per edge against error, per method.

:func:`pareto_figure` takes the points of :func:`reports.benchmark.pareto` (one per method:
median CPU time per edge, largest relative error) for one or more panels -- typically all
scenes, and the small depths where the series shine -- and draws them on log-log axes, one
marker per family of methods, the Pareto front (the methods no other one beats in both speed
and error) joined by a step line and labelled.  Errors below the reference's resolution are
drawn at that floor (a dashed line).  :func:`save_figure` writes it as vector PDF, PNG or SVG
(by the file name's ending), atomically; :func:`reports.figures.pdf_bytes` gives the bytes the
report embeds.
"""

from __future__ import annotations

from collections.abc import Sequence
from pathlib import Path

import numpy as np
from matplotlib.figure import Figure

from . import figures
from .figures import FORMATS, new_figure, style, tight_layout
from .i18n import say, tr

__all__ = ["FAMILY_STYLE", "FORMATS", "pareto_figure", "save_figure"]

#: file name endings a figure can be written as

#: marker and colour per family of methods (Okabe-Ito colours)
FAMILY_STYLE = {
    "series": ("o", "#E69F00"),
    "fixed point": ("X", "#CC79A7"),
    "double": ("s", "#56B4E9"),
    "grid": ("D", "#0072B2"),
    "mpmath": ("^", "#999999"),
    "certified": ("*", "#009E73"),
    "findroot": ("v", "#D55E00"),
    "auto": ("P", "#000000"),
}

#: the height of one row of the legend under the panels, in inches
LEGEND_IN = 0.15

#: errors at or below this are drawn at it (the reference's resolution)
FLOOR = 1e-58


def pareto_figure(panels: Sequence[tuple[str, Sequence[dict]]], *, subtitle: str = "") -> Figure:
    """One panel per ``(title, points)``; each point a dict with ``method``, ``family``,
    ``seconds`` (per edge), ``error`` and ``front`` (as :func:`reports.benchmark.pareto`
    returns)."""
    with style():
        fig, axes = new_figure(height=3.9, ncols=len(panels), sharey=True)
        axes = axes if isinstance(axes, tuple) else (axes,)
        top = max([1.0] + [float(p["error"]) for _, pts in panels for p in pts])
        for ax, (title, points) in zip(axes, panels, strict=True):
            seen = set()
            for p in points:
                marker, colour = FAMILY_STYLE.get(p["family"], ("o", "0.3"))
                err = max(float(p["error"]), FLOOR)
                label = tr(p["family"]) if p["family"] not in seen else None
                seen.add(p["family"])
                ax.loglog(
                    [p["seconds"]],
                    [err],
                    linestyle="none",
                    marker=marker,
                    color=colour,
                    markersize=6 if p.get("front") else 4,
                    markeredgecolor="black" if p.get("front") else colour,
                    markeredgewidth=0.5,
                    label=label,
                    zorder=3,
                )
            ax.set_ylim(FLOOR / 1e4, 10 ** (np.ceil(np.log10(top)) + 2))
            front = sorted((p for p in points if p.get("front")), key=lambda p: p["seconds"])
            if front:
                xs = np.array([p["seconds"] for p in front])
                ys = np.array([max(float(p["error"]), FLOOR) for p in front])
                ax.step(xs, ys, where="post", color="0.4", lw=0.6, zorder=2)
                scale = _Points(fig, ax, len(panels))
                taken: list[tuple[float, float, float, float]] = []
                for text, x, y in _front_labels(front, xs, ys, points):
                    label = ax.annotate(
                        text,
                        (x, y),
                        textcoords="offset points",
                        xytext=(4, 3),
                        fontsize=6,
                        color="0.2",
                    )
                    taken.append(_place(fig, label, scale, points, xs, ys, taken))
            ax.axhline(FLOOR, color="0.6", lw=0.5, ls="--", zorder=1)
            ax.annotate(
                say("resolution of the reference", "разрешение эталона"),
                (0.02, FLOOR),
                xycoords=("axes fraction", "data"),
                textcoords="offset points",
                xytext=(0, 3),
                fontsize=6,
                color="0.4",
            )
            ax.set_title(title)
            ax.set_xlabel(say("median CPU time per edge (s)", "медиана времени ЦП на границу (с)"))
            ax.grid(True, which="major", lw=0.3, color="0.85")
        axes[0].set_ylabel(
            say(
                r"largest relative error of $T/T_0$",
                r"наибольшая относительная погрешность $T/T_0$",
            )
        )
        handles = {}
        for ax in axes:
            for h, lab in zip(*ax.get_legend_handles_labels(), strict=True):
                handles.setdefault(lab, h)
        bottom = 0.0
        if handles:  # under the panels, where it covers no point and no label
            fig.legend(
                handles.values(),
                handles.keys(),
                loc="lower center",
                bbox_to_anchor=(0.5, 0.0),
                fontsize=6,
                ncol=min(len(handles), 4),
                frameon=False,
            )
            bottom = LEGEND_IN * ((len(handles) + 3) // 4) / fig.get_figheight()
        if subtitle:
            fig.suptitle(subtitle, fontsize=7)
        tight_layout(fig, pad=0.4, rect=(0, bottom, 1, 1))
    return fig


#: a label moves right of the points of its family within this many decades of its height
#: (about the height of a label on the panel's axis), so that it touches none of them
CLUSTER_DECADES = 2.0


def _front_labels(front, xs, ys, points=()):
    """One label per run of consecutive front points of the same family (``series K=1 ... 8``),
    at the run's first point, so that labels of close points do not overlap; a label starts
    right of the points of its family (in ``points``) at about its height, so that it does not
    touch a cluster of them."""
    out = []
    k = 0
    while k < len(front):
        j = k
        while j + 1 < len(front) and front[j + 1]["family"] == front[k]["family"]:
            j += 1
        first, last = tr(front[k]["method"]), front[j]["method"]
        if j == k:
            text = first
        else:
            tail = last.split()[-1]
            tail = tail.split("=")[-1]
            text = f"{first} ... {tail}"
        x, y = xs[k], ys[k]
        for p in points:
            err = max(float(p["error"]), FLOOR)
            if (
                p["family"] == front[k]["family"]
                and abs(np.log10(err) - np.log10(y)) <= CLUSTER_DECADES
                and p["seconds"] > x
            ):
                x = p["seconds"]
        out.append((text, x, y))
        k = j + 1
    return out


#: where a front label may go, tried in turn: (offset in points, horizontal alignment, vertical
#: alignment) -- above right of its point, a little higher, below right, above left, below left
LABEL_PLACES = (
    ((4, 3), "left", "baseline"),
    ((4, 6), "left", "baseline"),
    ((4, -3), "left", "top"),
    ((-4, 3), "right", "baseline"),
    ((-4, -3), "right", "top"),
)

#: a marker's half width and a little air, points: the markers of the front are 6 points across,
#: the others 4
MARKER_PT = {True: 3.5, False: 2.5}

#: room the axes of one row of panels leave for the tick labels, the axis label and the padding:
#: across, per panel, and up, as a share of the figure's height, points
AXES_MARGIN_PT = 26.0
AXES_HEIGHT_SHARE = 0.75


class _Points:
    """Data to points from the axes' lower left corner, the axes' size estimated from the
    figure's (the layout comes when the figure is drawn)."""

    def __init__(self, fig, ax, panels: int):
        self.w = (72 * fig.get_figwidth() - AXES_MARGIN_PT * panels) / panels
        self.h = 72 * fig.get_figheight() * AXES_HEIGHT_SHARE
        self.x = np.log10(ax.get_xlim())
        self.y = np.log10(ax.get_ylim())

    def __call__(self, x: float, y: float) -> tuple[float, float]:
        u = (np.log10(x) - self.x[0]) / (self.x[1] - self.x[0]) * self.w
        v = (np.log10(max(y, FLOOR)) - self.y[0]) / (self.y[1] - self.y[0]) * self.h
        return float(u), float(v)


def _place(fig, label, scale, points, xs, ys, taken):
    """Put ``label`` at the first place of :data:`LABEL_PLACES` where it covers no marker, no
    label placed before (``taken``, boxes in points) and no part of the front's step line
    (``xs``, ``ys``); where none is clear, above right.  Its box, in points."""
    from .figures import pdf_text_extent

    x0, x1 = pdf_text_extent(fig, label)
    width = x1 - x0
    px, py = scale(*label.xy)
    marks = [
        (*scale(p["seconds"], float(p["error"])), MARKER_PT[bool(p.get("front"))]) for p in points
    ]
    line = [scale(x, y) for x, y in zip(xs, ys, strict=True)]
    steps = []  # the step line: a horizontal then a vertical piece from each point to the next
    for (u0, v0), (u1, v1) in zip(line, line[1:], strict=False):
        steps += [(u0, v0, u1, v0), (u1, min(v0, v1), u1, max(v0, v1))]
    boxes = []
    for (dx, dy), ha, va in LABEL_PLACES:
        left = px + (dx if ha == "left" else dx - width)
        bottom = py + (dy - 1.5 if va == "baseline" else dy - 6.0)
        box = (left, bottom, left + width, bottom + 6.5)
        boxes.append(box)
        clear = not any(
            box[0] - r < u < box[2] + r and box[1] - r < v < box[3] + r for u, v, r in marks
        )
        clear = clear and not any(
            a[0] < box[2] and box[0] < a[2] and a[1] < box[3] and box[1] < a[3] for a in taken
        )
        clear = clear and not any(
            min(a, c) < box[2] and box[0] < max(a, c) and min(b, d) < box[3] and box[1] < max(b, d)
            for a, b, c, d in steps
        )
        if clear:
            label.set_position((dx, dy))
            label.set_horizontalalignment(ha)
            label.set_verticalalignment(va)
            return box
    return boxes[0]


def save_figure(fig: Figure, path) -> Path:
    """Write the Pareto figure (PDF, PNG or SVG by the file ending), atomically."""
    return figures.save_figure(fig, path, what="bench")
