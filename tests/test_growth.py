"""The growth-rate map (verify.growth.growth_map) against the Floquet route it is built from,
``log verify.floquet.growth_factor`` (the monodromy matrix multiplied out and its eigenvalues),
on grids of every system, duty and damping model, at the edges of the intervals and with over-
damped phases."""

from __future__ import annotations

import numpy as np
import pytest

from verify.floquet import growth_factor
from verify.grid import boundary_grid
from verify.growth import TOLERANCE, growth_map
from verify.inputs import InputError

TAU = np.linspace(0.15, 4.2, 211)
M = np.linspace(0.01, 0.97, 97)


def _reference(tau, m, Q, damping, system="pendulum", duty="1/2"):
    with np.errstate(divide="ignore"):
        return np.log(
            growth_factor(
                m[:, None], tau[None, :], Q, damping, backend="numpy", system=system, duty=duty
            )
        )


@pytest.mark.parametrize("system", ["pendulum", "torsion", "meissner"])
@pytest.mark.parametrize("duty", ["1/2", "1/3"])
@pytest.mark.parametrize("Q, damping", [(None, "exact"), (7.0, "exact"), (7.0, "paper")])
def test_equals_floquet(system, duty, Q, damping):
    got = growth_map(TAU, M, Q, damping, system=system, duty=duty)
    ref = _reference(TAU, M, Q, damping, system, duty)
    # the same quantity, rounded differently: TOLERANCE relative to max(1, |g|) away from the
    # edges; within a rounding-level distance of an edge both are sqrt(rounding), so sqrt(TOL)
    diff = np.abs(got - ref)
    near_edge = np.abs(ref + (0 if Q is None else np.pi / Q * TAU[None, :])) < 1e-6
    far = ~near_edge
    assert np.all(diff[far] <= TOLERANCE * np.maximum(1, np.abs(ref[far]))), diff[far].max()
    assert np.all(diff <= np.sqrt(TOLERANCE)), diff.max()


def test_at_the_edges():
    # the edges of orders 1-4 from the double-precision grid (verify.grid): there the growth is
    # zero to sqrt(rounding) in both routes
    m = np.array([0.1, 0.3, 0.5, 0.8])
    edges = boundary_grid([1, 2, 3, 4], list(m))
    for j, mj in enumerate(m):
        tau = edges[:, :, j].ravel()
        tau = tau[np.isfinite(tau)]
        got = growth_map(tau, np.array([mj]))[0]
        ref = _reference(tau, np.array([mj]), None, "exact")[0]
        assert np.all(np.abs(got - ref) <= np.sqrt(TOLERANCE))
        assert np.all(np.abs(got) <= 1e-6)


@pytest.mark.parametrize("system, Q", [("pendulum", 0.3), ("meissner", 1.0)])
def test_over_damped_rows_take_the_general_route(system, Q):
    # omega_i^2 < gamma^2 iff W_i < 1/(4 Q^2): pendulum, Q = 0.3: phase 1 (W1 = 1/(1+m) < 1) at
    # every depth; meissner, Q = 1: phase 1 (W1 = 1 - m) for m > 3/4 only -- rows of both kinds
    got = growth_map(TAU, M, Q, system=system)
    ref = _reference(TAU, M, Q, "exact", system)
    assert np.allclose(got, ref, rtol=TOLERANCE, atol=TOLERANCE)


def test_chunking_does_not_change_the_map():
    a = growth_map(TAU, M, 7.0, chunk=1)
    b = growth_map(TAU, M, 7.0, chunk=1 << 20)
    assert np.array_equal(a, b)


@pytest.mark.parametrize(
    "tau, m, Q",
    [([0.0, 1.0], [0.3], None), ([1.0], [1.0], None), ([1.0], [0.3], -1.0), ([[1.0]], [0.3], None)],
)
def test_bad_input(tau, m, Q):
    with pytest.raises(InputError):
        growth_map(tau, m, Q)
