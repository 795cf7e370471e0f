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


def test_the_labels_of_the_front_cover_no_marker_and_no_other_label():
    """A front label goes where it covers no point (a slower method just right of a front point
    at its height, like findroot beside 'auto, tol=1e-13'), no other label, no step."""
    from reports.benchplots import pareto_figure

    points = [
        {"method": "series K=1", "family": "series", "seconds": 1e-6, "error": 1e-3, "front": 1},
        {
            "method": "auto, tol=1e-13",
            "family": "auto",
            "seconds": 1e-5,
            "error": 1e-14,
            "front": 1,
        },
        {"method": "findroot 15", "family": "findroot", "seconds": 2.5e-5, "error": 3e-14},
        {"method": "mpmath 15", "family": "mpmath", "seconds": 3e-5, "error": 1e-19},
        {
            "method": "certified 15",
            "family": "certified",
            "seconds": 1.2e-5,
            "error": 1e-22,
            "front": 1,
        },
        {"method": "mpmath 30", "family": "mpmath", "seconds": 1e-2, "error": 1e-35},
    ]
    fig = pareto_figure([("all scenes", points)])
    pdf_bytes(fig)
    renderer = fig._get_renderer()
    ax = fig.axes[0]
    labels = [
        t for t in ax.texts if t.get_text() in ("auto, tol=1e-13", "certified 15", "series K=1")
    ]
    assert len(labels) == 3
    boxes = [t.get_window_extent(renderer) for t in labels]
    centres = [ax.transData.transform((p["seconds"], p["error"])) for p in points]
    for t, box in zip(labels, boxes, strict=True):
        for x, y in centres:
            assert not (box.x0 - 2 < x < box.x1 + 2 and box.y0 - 2 < y < box.y1 + 2), t.get_text()
    for i, a in enumerate(boxes):
        for b in boxes[i + 1 :]:
            assert not a.overlaps(b)
