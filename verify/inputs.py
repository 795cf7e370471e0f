"""The checks of user input, re-exported from :mod:`paramres.inputs` (the one implementation,
which :mod:`analytic` uses too, so that :mod:`analytic` never imports :mod:`verify`)."""

from paramres import inputs as _inputs
from paramres.inputs import *  # noqa: F401,F403
from paramres.inputs import __all__  # noqa: F401


def __getattr__(name: str):
    return getattr(_inputs, name)
