"""Shared test setup: precision is never global state."""

import os

import mpmath
import pytest


@pytest.fixture(autouse=True)
def _reset_mpmath_precision():
    """Fail a test that leaves ``mp.dps`` changed, and restore it either way."""
    before = mpmath.mp.prec
    yield
    changed = mpmath.mp.prec != before
    mpmath.mp.prec = before
    assert not changed, "a test or the code under test left mpmath.mp.prec changed"


# derivations are computed afresh in every test run: never read (or write) the user's disk cache
os.environ["PARAMRES_NO_CACHE"] = "1"
