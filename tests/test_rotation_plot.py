"""A nonlinear run that goes over the top is marked in the plots: the level |phi| = pi, the moment
it is first passed, and a legend that says so (the issue's case: m = 0.3, T = 0.5)."""

from __future__ import annotations

import numpy as np

from reports.timeplots import envelope_figure, over_the_top, time_figure
from verify.timedomain import simulate


def _texts(fig) -> str:
    out = []
    for ax in fig.axes:
        legend = ax.get_legend()
        if legend is not None:
            out += [t.get_text() for t in legend.get_texts()]
        out.append(ax.get_title(loc="left"))
    return "\n".join(out)


def test_going_over_the_top_is_marked():
    sim = simulate(1, "0.3", T="0.5", periods=20, nonlinear=True)
    assert sim.rotates
    t, phi = over_the_top(sim)
    # the first sample past pi, and no earlier sample of the run is past it
    assert abs(phi) > np.pi
    earlier = np.concatenate(
        [np.asarray(s.phi, float)[np.asarray(s.t, float) < t] for s in sim.segments]
    )
    assert np.all(np.abs(earlier) <= np.pi)
    texts = _texts(time_figure(sim))
    assert "over the top" in texts and "peak amplitude" not in texts
    assert "over the top" in _texts(envelope_figure([sim], ["pendulum"]))


def test_a_swinging_run_has_no_mark():
    sim = simulate(1, "0.3", edge="lower", periods=2, nonlinear=True)
    assert sim.rotates is False and over_the_top(sim) is None
    assert "over the top" not in _texts(time_figure(sim))
    linear = simulate(1, "0.3", edge="lower", periods=2)
    assert over_the_top(linear) is None
