"""``paramres simulate``: output, plots written atomically, bad input refused, nothing written."""

from __future__ import annotations

import json
import math
import subprocess
import sys
from pathlib import Path

import pytest

from reports.cli import main


def run(capsys, *argv):
    code = main(["simulate", *argv])
    out, err = capsys.readouterr()
    return code, out, err


def test_text_output_on_an_edge(capsys):
    code, out, err = run(capsys, "--order", "3", "--m", "0.3", "--edge", "upper")
    assert code == 0, err
    assert "closure error after 2T" in out
    assert "odd-cos-sin" in out  # the upper edge of the third interval below the closing at 3/5
    closure = float(out.split("closure error after 2T:")[1].split()[0])
    assert closure < 1e-27


def test_json_output_inside_an_interval(capsys):
    code, out, _ = run(capsys, "--order", "1", "--m", "0.3", "--T", "0.5", "--Q", "3", "--json")
    assert code == 0
    d = json.loads(out)
    assert {"closure_error", "growth_per_period", "floquet_multiplier", "method"} <= set(d)
    assert d["closure_error"] is None
    assert d["inside_interval"] is True
    assert d["growth_per_period"] == pytest.approx(abs(d["floquet_multiplier"]), rel=1e-14)
    assert d["floquet_multiplier"] < -1  # odd order: negative multiplier


def test_json_even_edge_with_friction(capsys):
    code, out, _ = run(
        capsys,
        "--order",
        "2",
        "--m",
        "0.7",
        "--edge",
        "lower",
        "--Q",
        "9",
        "--damping",
        "paper",
        "--json",
        "--digits",
        "40",
    )
    assert code == 0
    d = json.loads(out)
    assert d["closure_periods"] == 1 and d["closure_error"] < 1e-37
    assert d["damping"] == "paper" and d["digits"] == 40


@pytest.mark.parametrize(
    "suffix, magic", [(".pdf", b"%PDF"), (".png", b"\x89PNG"), (".svg", b"<?xml")]
)
def test_plot_files(capsys, tmp_path, suffix, magic):
    path = tmp_path / "sub" / f"scene{suffix}"
    code, out, _ = run(
        capsys,
        "--order",
        "1",
        "--m",
        "0.3",
        "--edge",
        "lower",
        "--periods",
        "3",
        "--plot",
        str(path),
    )
    assert code == 0
    assert path.read_bytes().startswith(magic)
    assert str(path) in out
    assert [p.name for p in path.parent.iterdir()] == [path.name]  # no temporary left behind


def test_nonlinear_run(capsys, tmp_path):
    path = tmp_path / "beats.png"
    code, out, _ = run(
        capsys,
        "--order",
        "1",
        "--m",
        "0.05",
        "--T",
        "0.4916",
        "--nonlinear",
        "--amplitude",
        "0.01",
        "--periods",
        "120",
        "--plot",
        str(path),
        "--json",
    )
    assert code == 0
    d = json.loads(out)
    assert d["nonlinear"] is True and d["rtol"] == 1e-10
    assert len(d["envelope"]) == 120
    assert 0.3 < d["peak_amplitude"] < 1.5
    assert path.read_bytes().startswith(b"\x89PNG")


BAD = [
    ["--order", "1", "--m", "0.3", "--edge", "lower", "--T", "0.5"],
    ["--order", "1", "--m", "0.3"],
    ["--order", "1", "--m", "0.3", "--edge", "middle"],
    ["--order", "1", "--m", "0.3", "--T", "0.5", "--periods", "0"],
    ["--order", "1", "--m", "0.3", "--T", "0.5", "--periods", "-2"],
    ["--order", "1", "--m", "0.3", "--T", "0.5", "--periods", "many"],
    ["--order", "1", "--m", "0.3", "--T", "0.5", "--amplitude", "0"],
    ["--order", "1", "--m", "0.3", "--T", "0.5", "--amplitude", "-1"],
    ["--order", "1", "--m", "0.3", "--T", "0.5", "--amplitude", "1e6"],
    ["--order", "1", "--m", "0.3", "--T", "0.5", "--amplitude", "nan"],
    ["--order", "1", "--m", "0.3", "--T", "0"],
    ["--order", "1", "--m", "0.3", "--T", "-0.5"],
    ["--order", "1", "--m", "0.3", "--T", "nan"],
    ["--order", "0", "--m", "0.3", "--T", "0.5"],
    ["--order", "1", "--m", "1.5", "--T", "0.5"],
    ["--order", "1", "--m", "0.3", "--T", "0.5", "--Q", "0"],
    ["--order", "1", "--m", "0.3", "--T", "0.5", "--Q", "-1"],
    ["--order", "1", "--m", "0.3", "--T", "0.5", "--damping", "viscous"],
    ["--order", "1", "--m", "0.3", "--T", "0.5", "--digits", "100000"],
    ["--order", "1", "--m", "0.3", "--T", "0.5", "--Q", "3", "--damping", "paper", "--nonlinear"],
    ["--order", "2", "--m", "0.1", "--edge", "lower", "--Q", "3"],  # no interval below threshold
]


def exit_code(argv) -> int:
    """The status ``paramres`` exits with (argparse errors raise SystemExit, others return)."""
    try:
        return main(argv)
    except SystemExit as exc:
        return exc.code


@pytest.mark.parametrize("argv", BAD)
def test_bad_input_exit_2_nothing_written(capsys, tmp_path, argv):
    path = tmp_path / "out.png"
    assert exit_code(["simulate", *argv, "--plot", str(path)]) == 2
    _, err = capsys.readouterr()
    assert err.strip().splitlines()[-1].startswith("paramres: error:")
    assert "Traceback" not in err
    assert not list(tmp_path.iterdir())


def test_nonlinear_runaway_refused_nothing_written(capsys, tmp_path):
    # the jumps at m = 0.99 speed the pendulum up without bound: the run stops at its budget of
    # integration steps at once (it used to run for minutes, its memory growing by GBs)
    path = tmp_path / "out.png"
    argv = ["--order", "1", "--m", "0.99", "--T", "20", "--periods", "60", "--nonlinear"]
    assert exit_code(["simulate", *argv, "--plot", str(path)]) == 2
    _, err = capsys.readouterr()
    assert err.startswith("paramres: error: the motion grows too fast to follow: more than ")
    assert "integration steps by period 1 of 60" in err and "a smaller depth m" in err
    assert "Traceback" not in err and len(err.strip().splitlines()) == 1
    assert not list(tmp_path.iterdir())


def test_bad_plot_name_refused_before_any_work(capsys, tmp_path):
    path = tmp_path / "scene.txt"
    code = main(["simulate", "--order", "1", "--m", "0.3", "--edge", "lower", "--plot", str(path)])
    _, err = capsys.readouterr()
    assert code == 2 and err.startswith("paramres: error:") and ".pdf" in err
    assert not list(tmp_path.iterdir())


def test_entry_point(tmp_path):
    exe = Path(sys.executable).with_name("paramres")
    res = subprocess.run(
        [str(exe), "simulate", "--order", "2", "--m", "1/2", "--edge", "upper", "--json"],
        capture_output=True,
        text=True,
        timeout=120,
    )
    assert res.returncode == 0, res.stderr
    assert json.loads(res.stdout)["closure_error"] < 1e-27


# ---------------------------------------------------------------------------------------------
# the report's pictures


def test_paper_scenes_are_stationary_where_they_should_be():
    from reports.timeplots import PAPER_SCENES, paper_simulations

    for number, scene in PAPER_SCENES.items():
        for run_, sim in zip(scene.runs, paper_simulations(number), strict=True):
            if "edge" in run_:
                assert sim.closure_error < 1e-27, (number, sim.closure_error)
            else:  # Fig. 5: growth inside the second interval
                assert sim.inside and sim.growth_per_period > 1
    # Fig. 7 starts away from the symmetric shapes and still returns: the closing (M = -I)
    (sim7,) = paper_simulations(7)
    assert sim7.edge_kind is None and sim7.initial[0] != 0 and sim7.initial[1] != 0


def test_figures_render(tmp_path):
    from reports.timeplots import figure_bytes, paper_figure, save_figure
    from verify.inputs import InputError

    fig = paper_figure(7)
    assert figure_bytes(fig, ".pdf").startswith(b"%PDF")
    path = save_figure(fig, tmp_path / "fig7.svg")
    assert path.read_bytes().startswith(b"<?xml")
    with pytest.raises(InputError):
        save_figure(fig, tmp_path / "fig7.jpeg")
    with pytest.raises(InputError):
        paper_figure(2)  # Fig. 2 is a diagram of intervals, not a time-domain scene
    assert sorted(p.name for p in tmp_path.iterdir()) == ["fig7.svg"]


def test_nonlinear_run_detects_going_over_the_top(capsys):
    # at m = 0.3, T = 0.5 (inside the first interval, far from its edges) the growth carries the
    # pendulum past phi = pi; the run used to report a "peak amplitude" of hundreds of radians as
    # if it were a swing
    from reports.cli import main
    from verify.timedomain import simulate

    sim = simulate(1, "0.3", T="0.5", nonlinear=True, periods=60)
    assert sim.rotates is True and sim.peak_amplitude > math.pi
    assert "over the top" in str(sim) and sim.as_json()["rotates"] is True
    small = simulate(1, "0.3", T="0.5", nonlinear=True, periods=2)
    assert small.rotates is False and small.peak_amplitude < math.pi
    assert simulate(1, "0.3", edge="lower").rotates is None  # linear model: no such notion
    assert (
        main(
            [
                "simulate",
                "--order",
                "1",
                "--m",
                "0.3",
                "--T",
                "0.5",
                "--nonlinear",
                "--periods",
                "60",
            ]
        )
        == 0
    )
    assert "went over the top" in capsys.readouterr().out


def test_str_of_a_simulation_is_short_and_readable():
    from verify.timedomain import simulate

    text = str(simulate(1, "0.3", edge="lower"))
    assert text.startswith("Simulation: order 1, m = 3/10") and len(text) < 400
    assert "closure error after 2 T" in text
