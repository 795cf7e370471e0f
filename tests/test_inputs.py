"""Input checks: every bad value refused with a message naming it and the allowed range."""

from fractions import Fraction

import mpmath
import pytest

from verify.inputs import (
    InputError,
    as_damping,
    as_depth,
    as_digits,
    as_order,
    as_orders,
    as_quality,
    as_range,
)


@pytest.mark.parametrize(
    "m,expected",
    [
        ("3/5", Fraction(3, 5)),
        ("0.3", Fraction(3, 10)),
        (Fraction(1, 7), Fraction(1, 7)),
        ("1e-12", Fraction(1, 10**12)),
        (0.5, Fraction(1, 2)),
    ],
)
def test_depth_exact(m, expected):
    assert as_depth(m) == expected


def test_depth_mpf_kept():
    v = mpmath.mpf("0.25")
    assert as_depth(v) is v


@pytest.mark.parametrize(
    "bad",
    [0, 1, "1", "-0.1", "1.5", "nan", float("nan"), float("inf"), "abc", "", "3/0", True, None],
)
def test_depth_refused(bad):
    with pytest.raises(InputError) as e:
        as_depth(bad)
    assert "0 < m < 1" in str(e.value) or "not a number" in str(e.value)


@pytest.mark.parametrize("bad", [0, -1, "0", "1.5", 2.5, "x", True, 10**9])
def test_order_refused(bad):
    with pytest.raises(InputError):
        as_order(bad)


def test_orders_parsing():
    assert as_orders("1-6") == [1, 2, 3, 4, 5, 6]
    assert as_orders("5,1,3") == [1, 3, 5]
    assert as_orders(range(1, 4)) == [1, 2, 3]
    for bad in ("", "6-1", "0-3", "a-b", "1,,2"):
        with pytest.raises(InputError):
            as_orders(bad)


def test_quality():
    assert as_quality(None) is None and as_quality("none") is None
    assert as_quality("7") == 7
    for bad in (0, -3, "0", "nan", float("nan"), float("inf"), "x"):
        with pytest.raises(InputError):
            as_quality(bad)


def test_quality_range_ends_are_exact():
    # Q_RANGE = [1e-6, 1e30], both ends allowed; the check is exact at either end (a value one
    # part in 10**40 outside is refused), for text, int and Fraction alike
    from fractions import Fraction

    lo, hi = Fraction(1, 10**6), Fraction(10**30)
    assert as_quality("1e-6") == lo and as_quality(10**30) == hi and as_quality(hi) == hi
    for bad in (lo * (1 - Fraction(1, 10**40)), hi * (1 + Fraction(1, 10**40)), "1e31", 10**31):
        with pytest.raises(InputError, match="outside the allowed range"):
            as_quality(bad)


def test_digits_and_damping():
    assert as_digits("50") == 50
    for bad in (4, 10**5, "x", 3.5, -1):
        with pytest.raises(InputError):
            as_digits(bad)
    assert as_damping("PAPER") == "paper"
    with pytest.raises(InputError):
        as_damping("viscous")


def test_range():
    assert len(as_range("0.1:0.9:0.1")) == 9
    assert as_range("0.05:0.05:0.1") == [Fraction(1, 20)]
    for bad in (
        "0.1:0.9",
        "0:0.5:0.1",
        "0.1:1:0.1",
        "0.5:0.1:0.1",
        "0.1:0.9:0",
        "a:b:c",
        "0.1:0.9:-0.1",
    ):
        with pytest.raises(InputError):
            as_range(bad)


def test_as_system_passes_a_system_through_as_analytic_system_does():
    """A ``System`` with the default duty comes back as it is (the fast path), and with another
    duty as :func:`analytic.system.system` makes it; both as that function gives them."""
    from analytic.system import PAPER, custom, system
    from verify.inputs import as_system

    members = [PAPER, system("torsion", duty="1/3"), custom(("4/5", "6/5"), jump="3/2")]
    for s in members:
        assert as_system(s) is s is system(s)
        assert as_system(s, "2/5") == system(s, duty="2/5")
    assert as_system("pendulum") is PAPER


def test_a_system_hashes_again_in_another_process():
    """A system's kept hash is not pickled: a string hashes differently in another process (a
    worker of :mod:`verify.engine`), where the system must equal and hash as that process's own."""
    import os
    import pickle
    import subprocess
    import sys

    from analytic.system import PAPER, system

    torsion = system("torsion", duty="1/3")
    hash(PAPER), hash(torsion)  # the hash kept
    data = pickle.dumps((PAPER, torsion))
    code = (
        "import pickle, sys\n"
        "from analytic.system import PAPER, system\n"
        "p, t = pickle.loads(sys.stdin.buffer.read())\n"
        "own = system('torsion', duty='1/3')\n"
        "print(p == PAPER and hash(p) == hash(PAPER) and t == own and hash(t) == hash(own))\n"
    )
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    path = os.pathsep.join(filter(None, (root, os.environ.get("PYTHONPATH"))))
    for seed in ("1", "2"):
        env = dict(os.environ, PYTHONHASHSEED=seed, PYTHONPATH=path)
        out = subprocess.run(
            [sys.executable, "-c", code], input=data, capture_output=True, env=env, check=True
        )
        assert out.stdout.strip() == b"True"
    assert pickle.loads(data) == (PAPER, torsion)


def test_integer_quality_factors_are_kept():
    """An integer ``Q`` gives its exact Fraction, the same object again on the next call (made
    once); out of range it is refused every time (never kept)."""
    from paramres.inputs import as_quality

    q = as_quality(7)
    assert q == Fraction(7) and type(q) is Fraction
    assert as_quality(7) is q
    for bad in (0, 10**31):
        for _ in range(2):
            with pytest.raises(InputError):
                as_quality(bad)
