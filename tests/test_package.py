"""The package as users get it: ``import paramres`` (public API, light import, no shadowing by a
user's module of the same name as an engine package), ``paramres --version``, and a wheel that holds
every package and the data the report reads (the wheel itself is built and installed by
``.ci/run``)."""

from __future__ import annotations

import re
import subprocess
import sys
from pathlib import Path

import pytest

import paramres
from reports.cli import main

ROOT = Path(__file__).resolve().parent.parent


def test_public_api_names_resolve():
    expected = {
        "boundary",
        "boundary_grid",
        "existence",
        "series",
        "crossings",
        "catalogue",
        "simulate",
        "report",
    }
    assert expected <= set(paramres.__all__)
    for name in paramres.__all__:
        assert getattr(paramres, name) is not None
    # the public boundary is the modulation-aware one (square: verify.solve.boundary unchanged)
    from verify.modulation import boundary

    assert paramres.boundary is boundary


def _run(code: str, cwd: Path) -> subprocess.CompletedProcess:
    return subprocess.run(
        [sys.executable, "-c", code], cwd=cwd, capture_output=True, text=True, timeout=120
    )


def test_import_is_light(tmp_path):
    # importing paramres must not import the heavy libraries; they load on first use
    proc = _run(
        "import sys, paramres; print(sorted(m for m in ('sympy', 'numpy', 'mpmath', 'scipy', "
        "'matplotlib', 'flint') if m in sys.modules))",
        tmp_path,
    )
    assert proc.returncode == 0, proc.stderr
    assert proc.stdout.strip() == "[]"


def test_a_users_module_named_like_an_engine_package_does_not_shadow_it(tmp_path):
    # python -c puts the working directory first on sys.path, so without the binding in
    # paramres/__init__ this verify.py would be imported as the engine's verify
    (tmp_path / "verify.py").write_text("raise SystemExit('the user module was imported')\n")
    (tmp_path / "analytic.py").write_text("raise SystemExit('the user module was imported')\n")
    code = "import paramres; print(paramres.boundary(1, '1/10', digits=20).as_json()['lower'])"
    proc = _run(code, tmp_path)
    assert proc.returncode == 0, proc.stderr
    # the reference: the same call in this process, where no user module is on the path
    assert proc.stdout.strip() == paramres.boundary(1, "1/10", digits=20).as_json()["lower"]


def test_a_foreign_module_imported_first_is_named(tmp_path):
    (tmp_path / "verify.py").write_text("X = 1\n")
    proc = _run("import verify, paramres", tmp_path)
    assert proc.returncode != 0
    assert "verify" in proc.stderr and "import paramres first" in proc.stderr


def test_version(capsys):
    with pytest.raises(SystemExit) as exc:
        main(["--version"])
    assert exc.value.code == 0
    out = capsys.readouterr().out
    assert out.strip() == f"paramres {paramres.__version__}"
    assert re.fullmatch(r"\d+\.\d+\.\d+", paramres.__version__)


def test_python_dash_m(tmp_path):
    proc = subprocess.run(
        [sys.executable, "-m", "paramres", "--version"],
        cwd=tmp_path,
        capture_output=True,
        text=True,
        timeout=60,
    )
    assert proc.returncode == 0 and proc.stdout.strip() == f"paramres {paramres.__version__}"


def test_wheel_includes_every_package():
    """Every directory with an ``__init__.py`` under the engine's packages is matched by the
    package discovery in pyproject.toml (the old explicit list missed ``reports.sections``)."""
    tomllib = pytest.importorskip("tomllib")  # Python >= 3.11
    config = tomllib.loads((ROOT / "pyproject.toml").read_text())["tool"]["setuptools"]
    include = config["packages"]["find"]["include"]
    from setuptools import find_packages

    found = set(find_packages(str(ROOT), include=include))
    expected = {
        ".".join(p.parent.relative_to(ROOT).parts)
        for top in ("paramres", "analytic", "verify", "reports")
        for p in (ROOT / top).rglob("__init__.py")
    }
    assert "reports.sections" in expected
    assert expected <= found
    assert not {p for p in found if p.split(".")[0] not in ("paramres", *paramres.ENGINE)}


def test_setup_ships_the_report_data():
    # the report reads the benchmark results; setup.py copies them into the wheel
    text = (ROOT / "setup.py").read_text()
    from reports.sections import performance

    assert "bench-results.json" in text and "results.json" in text
    assert performance._SOURCE_RESULTS.is_file()
    assert performance._PACKAGED_RESULTS.name == "bench-results.json"
