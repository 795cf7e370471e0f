"""The example notebook (docs/example.ipynb) runs from top to bottom, and what it shows is what
the API gives: executed with nbclient in a fresh kernel of this interpreter."""

from __future__ import annotations

from pathlib import Path

import pytest

nbformat = pytest.importorskip("nbformat", reason="the test extra installs nbformat")
nbclient = pytest.importorskip("nbclient", reason="the test extra installs nbclient")
pytest.importorskip("ipykernel", reason="the test extra installs ipykernel")

NOTEBOOK = Path(__file__).resolve().parents[1] / "docs" / "example.ipynb"


def test_the_example_notebook_runs_and_shows_certified_digits(tmp_path, monkeypatch):
    nb = nbformat.read(NOTEBOOK, as_version=4)
    monkeypatch.setenv("PARAMRES_NO_CACHE", "1")  # the kernel inherits it: no disk cache in tests
    client = nbclient.NotebookClient(
        nb, timeout=600, kernel_name="python3", resources={"metadata": {"path": str(tmp_path)}}
    )
    client.execute()
    outputs = [o for cell in nb.cells if cell.cell_type == "code" for o in cell.get("outputs", [])]
    assert not [o for o in outputs if o.get("output_type") == "error"]
    html = "".join(o.get("data", {}).get("text/html", "") for o in outputs)
    latex = "".join(o.get("data", {}).get("text/latex", "") for o in outputs)
    import paramres

    # the boundary's display carries all 40 certified digits (the same text the API prints)
    assert str(paramres.boundary(3, "3/10", digits=40)).splitlines()[1].split()[3] in html
    assert "mu1 = -2.0249540173479945877" in html  # as README's multipliers example prints
    assert "meissner" in html and "T_-/T_0" in latex
    assert any(o.get("data", {}).get("text/plain") == "(4, 2, 200)" for o in outputs)
