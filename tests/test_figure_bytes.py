"""A laid-out figure is drawn once by :func:`reports.figures.pdf_bytes`; the reference is
matplotlib's own ``savefig``, which draws it twice (the layout in a first drawing with the output
switched off): the bytes must be the same, and the figure is left as it was."""

from __future__ import annotations

import io

import numpy as np

from reports.benchplots import pareto_figure
from reports.figures import error_figure, pdf_bytes, style
from reports.output import BANNER


def _savefig(fig) -> bytes:
    buf = io.BytesIO()
    with style():
        fig.savefig(
            buf,
            format="pdf",
            metadata={
                "Creator": BANNER.format(what="report"),
                "Producer": "paramres (matplotlib)",
                "CreationDate": None,
            },
        )
    return buf.getvalue()


def _errors():
    m = np.geomspace(1e-5, 0.5, 40)
    curves = {f"through $m^{{{k}}}$": (m, m**k) for k in (2, 4, 6)}
    return error_figure([("$n = 1$", curves), ("$n = 2$", curves)])


def _pareto():
    points = [
        {"method": "series K=1", "family": "series", "seconds": 1e-5, "error": 1e-3, "front": 1},
        {"method": "double", "family": "double", "seconds": 1e-4, "error": 1e-15, "front": 1},
        {"method": "certified", "family": "certified", "seconds": 1e-2, "error": 0.0, "front": 1},
        {"method": "mpmath", "family": "mpmath", "seconds": 3e-2, "error": 1e-30},
    ]
    return pareto_figure([("all scenes", points), ("small m", points)], subtitle="test")


def test_one_drawing_gives_the_bytes_of_savefig():
    for make in (_errors, _pareto):  # the tight layout alone, and with a rectangle
        fig, ref = make(), make()
        dpi = fig.dpi
        assert pdf_bytes(fig) == _savefig(ref)
        assert fig.dpi == dpi  # the PDF canvas draws at 72 dpi; the figure keeps its own
        # drawn a second time (matplotlib's second drawing differs from its first): the same
        assert pdf_bytes(fig) == _savefig(ref)
