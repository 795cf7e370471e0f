"""The Russian report's figures have every letter: Computer Modern has no Cyrillic, so a figure
built in Russian is set in DejaVu Serif (text and formulas), and nothing is drawn as a dummy box."""

from __future__ import annotations

import logging
import warnings

from reports.figures import new_figure, pdf_bytes, style
from reports.i18n import language


def _draw() -> bytes:
    with style():
        fig, ax = new_figure()
        ax.set_xlabel("период модуляции $T/T_0$")
        ax.set_ylabel("глубина модуляции $m$")
        ax.set_title("нижняя граница, без трения")
        return pdf_bytes(fig)


def test_cyrillic_labels_have_their_glyphs(caplog):
    with caplog.at_level(logging.WARNING), warnings.catch_warnings():
        warnings.simplefilter("error")  # "Glyph ... missing from font(s)" is a UserWarning
        with language("ru"):
            _draw()
    assert not [r for r in caplog.records if "glyph" in r.getMessage().lower()]


def test_the_same_labels_in_the_english_fonts_would_lose_them(caplog):
    # the check above can fail: outside the Russian build the fonts are Computer Modern
    with caplog.at_level(logging.WARNING), warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        _draw()
    missing = [w for w in caught if "missing from font" in str(w.message)]
    missing += [r for r in caplog.records if "glyph" in r.getMessage().lower()]
    assert missing
