"""The checks of user input, re-exported from :mod:`paramres.inputs` (the one implementation,
which :mod:`analytic` uses too, so that :mod:`analytic` never imports :mod:`verify`), and
:func:`as_system`, the check of the oscillator (a member of :mod:`analytic.system`)."""

from fractions import Fraction
from functools import lru_cache

from paramres import inputs as _inputs
from paramres.inputs import *  # noqa: F401,F403
from paramres.inputs import __all__ as _all

__all__ = [*_all, "as_system"]


def as_system(system="pendulum", duty="1/2", omega_sq=None, jump=None):
    """A member of the family (:class:`analytic.system.System`): a name (``pendulum``,
    ``torsion``, ``meissner``, ``custom`` with ``omega_sq`` and ``jump``) or a ``System``, with the
    duty ``0 < D < 1``."""
    if type(system) is str:
        if system == "pendulum" and duty == "1/2" and omega_sq is None and jump is None:
            return _paper()  # the default, without parsing it again
    elif duty == "1/2" and omega_sq is None and jump is None and type(system) is type(_paper()):
        return system  # a System with the default duty passes through (analytic.system.system)
    if omega_sq is None and jump is None and type(system) is str and type(duty) in _PLAIN:
        return _named(system, duty)
    from analytic.system import system as make

    return make(system, duty=duty, omega_sq=omega_sq, jump=jump)


#: the types of a duty whose parse :func:`_named` keeps (hashable, compared by value and type)
_PLAIN = (str, int, Fraction)


@lru_cache(maxsize=256)
def _named(name: str, duty):
    """A built-in system by name (or the error it raises, every time), parsed once per input."""
    from analytic.system import system as make

    return make(name, duty=duty)


_PAPER: list = []


def _paper():
    """:data:`analytic.system.PAPER`, imported on first use (kept)."""
    if not _PAPER:
        from analytic.system import PAPER

        _PAPER.append(PAPER)
    return _PAPER[0]


def __getattr__(name: str):
    return getattr(_inputs, name)
