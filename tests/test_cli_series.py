"""``paramres series`` and ``paramres crossings``: output, JSON that sympy parses, bad input."""

from __future__ import annotations

import json
import subprocess
import sys

import pytest
import sympy as sp
from cli_run import run_cli as run

from analytic.expansions import edge_series
from reports.cli import main

m = sp.Symbol("m")


def test_series_json_format_and_values(capsys):
    code, out, err = run(capsys, "series", "--order", "3", "--terms", "4", "--json")
    assert code == 0 and not err
    d = json.loads(out)
    assert d["order"] == 3 and d["terms"] == 4
    assert set(d["in_Tav"]) == {"lower", "upper"}
    ref = edge_series(3, 4)
    for name in ("lower", "upper"):
        got = sp.sympify(d[name], locals={"m": m})
        want = ref.in_T0[name].subs(ref.in_T0[name].free_symbols.pop(), m)
        assert sp.expand(got - want) == 0
        got_av = sp.sympify(d["in_Tav"][name], locals={"m": m})
        assert (
            sp.expand(got_av - ref.in_Tav[name].subs(list(ref.in_Tav[name].free_symbols)[0], m))
            == 0
        )
    # eq. (19) in units of T_av: 3/2 -+ 3m/(2 pi)
    low = sp.sympify(d["in_Tav"]["lower"], locals={"m": m})
    assert sp.expand(low).coeff(m, 1) == -3 / (2 * sp.pi)


def test_series_eight_terms_and_text(capsys):
    code, out, _ = run(capsys, "series", "--order", "5", "--terms", "8")
    assert code == 0
    assert "T-/T0" in out and "T+/T_av" in out and "O(m^9)" in out
    assert "lower edge: root of cos(x) - r cos(beta x)" in out  # n = 5: eq. (13)'s factor


def test_series_symbolic_order(capsys):
    code, out, _ = run(capsys, "series", "--order", "even", "--terms", "2", "--json")
    d = json.loads(out)
    n = sp.Symbol("n")
    up = sp.sympify(d["in_Tav"]["upper"], locals={"m": m, "n": n})
    assert sp.expand(up - (n / 2 + sp.Rational(3, 8) * n * m**2)) == 0


def test_series_with_friction(capsys):
    code, out, _ = run(
        capsys, "series", "--order", "1", "--Q", "20", "--damping", "paper", "--json"
    )
    assert code == 0
    d = json.loads(out)
    assert d["Q"] == "20" and d["damping"] == "paper"
    # leading threshold pi/(6Q) and edges that parse as functions of m alone
    assert sp.sympify(d["threshold"]["m_min_leading"]) == sp.pi / 120
    low = sp.sympify(d["in_Tav"]["lower"], locals={"m": m})
    assert low.free_symbols == {m}
    val = float(low.subs(m, sp.Rational(1, 10)))
    # eq. (18) with m -> sqrt(m^2 - m_min^2) at m = 0.1 (leading order), within the next term
    lead = 0.5 - 3 / (2 * float(sp.pi)) * float(sp.sqrt(sp.Rational(1, 100) - (sp.pi / 120) ** 2))
    assert abs(val - lead) < 0.01
    code, out, _ = run(capsys, "series", "--order", "2", "--Q", "1000")
    assert code == 0 and "m_min0" in out and "threshold" in out


def test_crossings_json(capsys):
    code, out, _ = run(capsys, "crossings", "--max-order", "6", "--json")
    assert code == 0
    doc = json.loads(out)  # one object, like every command's --json (it used to be a bare list)
    assert doc["max_order"] == 6
    d = doc["closings"]
    # correctly rounded: the bound is half a unit of the last printed digit
    assert d[0]["T_error_bound"] == "5.0e-" + str(len(d[0]["T"].split(".")[1]) + 1)
    assert [(x["order"], x["ratio"], x["m"]) for x in d] == [
        (3, "2:1", "3/5"),
        (4, "3:1", "4/5"),
        (5, "3:2", "5/13"),
        (5, "4:1", "15/17"),
        (6, "4:2", "3/5"),
        (6, "5:1", "12/13"),
    ]
    assert d[0]["T"].startswith("1.2649110640673517327995574177730874134")  # sqrt(8/5)
    assert all(len(x["T"].replace(".", "")) >= 30 for x in d)


def test_crossings_text(capsys):
    code, out, _ = run(capsys, "crossings", "--max-order", "12")
    assert code == 0
    assert "no other closings" in out.lower()
    assert out.count("\n") > 30 and "(= 2:1: the depth of order 3)" in out
    code, out, _ = run(capsys, "crossings", "--max-order", "2")
    assert "closings need n >= 3" in out


@pytest.mark.parametrize(
    "argv",
    [
        ["series", "--order", "0"],
        ["series", "--order", "x"],
        ["series", "--order", "2", "--terms", "0"],
        ["series", "--order", "2", "--terms", "41"],
        ["series", "--order", "2", "--terms", "13", "--Q", "7"],
        ["series", "--order", "2", "--terms", "2.5"],
        ["series", "--order", "2", "--Q", "0"],
        ["series", "--order", "2", "--Q", "nan"],
        ["series", "--order", "2", "--Q", "5", "--damping", "viscous"],
        ["crossings", "--max-order", "0"],
        ["crossings", "--max-order", "201"],
        ["crossings", "--max-order", "many"],
        ["crossings"],
    ],
)
def test_bad_input_exit_2(capsys, argv):
    with pytest.raises(SystemExit) as exc:
        code = main(argv)
        raise SystemExit(code)
    assert exc.value.code == 2
    _, err = capsys.readouterr()
    assert "paramres: error:" in err and "Traceback" not in err


def test_bad_input_in_a_real_process():
    proc = subprocess.run(
        [sys.executable, "-m", "reports.cli", "series", "--order", "-2"],
        capture_output=True,
        text=True,
    )
    assert proc.returncode == 2
    assert proc.stderr.startswith("paramres: error:") and "Traceback" not in proc.stderr
    assert proc.stdout == ""
