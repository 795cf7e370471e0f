"""The labels of the report's figures stay inside their axes and off the curves' tips and the
frame: the order of the last interval, the orders of the diagram with friction, the numbered
points of a time-domain figure."""

from __future__ import annotations

import numpy as np

from reports.figures import friction_figure, intervals_figure, pdf_bytes


def _bounds(orders, m):
    """Intervals of instability shaped like the real ones: a tip at ``n/2`` on ``m = 0``, a width
    growing with ``m``."""
    return np.array([[[n / 2 - 0.3 * m, n / 2 + 0.1 * m]] for n in orders]).reshape(
        len(orders), 2, len(m)
    )


def _labels(ax):
    return [t for t in ax.texts if t.get_text().startswith("$n=")]


def test_the_last_orders_label_is_inside_the_axes():
    orders = (1, 2, 3, 4, 5, 6)
    m = np.linspace(0, 0.98, 30)
    fig = intervals_figure(m, _bounds(orders, m), orders)
    pdf_bytes(fig)
    ax = fig.axes[0]
    renderer = fig._get_renderer()
    right = ax.get_window_extent(renderer).x1
    for label in _labels(ax):
        assert label.get_window_extent(renderer).x1 < right, label.get_text()


def test_the_orders_of_the_friction_diagram_stand_beside_the_tips():
    orders = (1, 2, 3)
    m = np.linspace(0, 0.98, 30)
    b = _bounds(orders, m)
    fig = friction_figure(m, [("a", {"none": b}), ("b", {"none": b})], orders, t_max=2.0)
    pdf_bytes(fig)
    renderer = fig._get_renderer()
    for ax in fig.axes:
        for label, n in zip(_labels(ax), orders, strict=True):
            tip = ax.transData.transform((n / 2, 0.0))[0]
            assert label.get_window_extent(renderer).x0 > tip, label.get_text()


def test_the_numbered_points_keep_off_the_frame():
    from reports.timeplots import paper_figure

    fig = paper_figure(7, digits=20)
    pdf_bytes(fig)
    renderer = fig._get_renderer()
    for ax in fig.axes:
        numbers = [t for t in ax.texts if t.get_text()[:1].isdigit()]
        frame = ax.get_window_extent(renderer)
        for t in numbers:
            box = t.get_window_extent(renderer)
            assert frame.y0 < box.y0 and box.y1 < frame.y1, t.get_text()
        for line in ax.lines:  # the numbered points: not on the frame
            if line.get_marker() == "o":
                x, y = ax.transData.transform(np.column_stack(line.get_data())).T
                assert np.all(y > frame.y0 + 2) and np.all(y < frame.y1 - 2)


def test_a_closings_label_lies_on_a_light_ground():
    """Where closings crowd (4:1 beside 5:1) an edge passes under a label: the label is drawn
    over it, on a light ground, so that it stays legible."""
    orders = (1, 2)
    m = np.linspace(0, 0.98, 30)
    fig = intervals_figure(m, _bounds(orders, m), orders, closings=[(2, 0.5, 0.9, "4:1")])
    (label,) = [t for t in fig.axes[0].texts if t.get_text() == "4:1"]
    ground = label.get_bbox_patch()
    assert ground is not None and ground.get_facecolor()[:3] == (1.0, 1.0, 1.0)
    assert label.get_zorder() > max(line.get_zorder() for line in fig.axes[0].lines)
