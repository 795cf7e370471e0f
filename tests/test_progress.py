"""Progress on long runs: drawn on stderr only when it is a terminal, never with ``--quiet``, and
the output of a run in a pipe (stdout and stderr) is the same as without any progress code."""

from __future__ import annotations

import io
import time

import pytest

from reports.cli import main
from reports.output import progress, working


class Terminal(io.StringIO):
    def isatty(self) -> bool:
        return True


@pytest.fixture(autouse=True)
def _no_forced_progress(monkeypatch):
    monkeypatch.delenv("PARAMRES_PROGRESS", raising=False)


def test_working_draws_on_a_terminal_and_clears_its_line():
    term = Terminal()
    with working("existence", stream=term, min_seconds=0.0):
        time.sleep(0.3)
    text = term.getvalue()
    assert "existence: working" in text
    assert text.endswith("\r")  # the line is cleared, the next output starts clean


@pytest.mark.parametrize("stream, quiet", [(io.StringIO(), False), (Terminal(), True)])
def test_working_is_silent_in_a_pipe_and_when_quiet(stream, quiet):
    with working("existence", stream=stream, quiet=quiet, min_seconds=0.0):
        time.sleep(0.3)
    assert stream.getvalue() == ""


def test_progress_bar_only_on_a_terminal_and_not_when_quiet():
    for stream, quiet, drawn in (
        (Terminal(), False, True),
        (Terminal(), True, False),
        (io.StringIO(), False, False),
    ):
        assert list(progress(range(3), stream=stream, min_seconds=0.0, quiet=quiet)) == [0, 1, 2]
        assert ("[" in stream.getvalue()) is drawn


def _slow_catalogue(monkeypatch):
    import analytic.catalogue as catalogue_module
    from analytic.catalogue import Row

    row = Row("18", "agrees", "T", "T", "symbolic", "a title")

    def slow():
        time.sleep(2.5)  # longer than the 2 s after which progress appears
        return (row,)

    monkeypatch.setattr(catalogue_module, "catalogue", slow)


def test_a_command_in_a_pipe_prints_exactly_its_result(monkeypatch, capsys):
    _slow_catalogue(monkeypatch)
    assert main(["catalogue", "--json"]) == 0
    piped = capsys.readouterr()
    assert piped.err == ""
    # the same command on a terminal draws progress on stderr and nothing else changes
    term = Terminal()
    monkeypatch.setattr("sys.stderr", term)
    assert main(["catalogue", "--json"]) == 0
    on_terminal = capsys.readouterr()
    assert on_terminal.out == piped.out
    assert "catalogue: working" in term.getvalue()
    term2 = Terminal()
    monkeypatch.setattr("sys.stderr", term2)
    assert main(["catalogue", "--json", "--quiet"]) == 0
    assert capsys.readouterr().out == piped.out and term2.getvalue() == ""


def test_jump_validity_shows_its_elapsed_time_and_takes_quiet(monkeypatch, capsys):
    """``jump-validity`` runs for minutes at high orders (the edges are followed in ``S`` in
    steps proportional to the spacing of the orders): a sign of life on a terminal, none with
    ``--quiet`` or in a pipe, and the same result."""
    import verify.ramp as ramp_module

    class Answer:
        def as_json(self):
            return {"S_within": "0.1"}

        def __str__(self):
            return "answer"

    def slow(*args, **kwargs):
        time.sleep(2.5)  # longer than the 2 s after which progress appears
        return Answer()

    monkeypatch.setattr(ramp_module, "jump_validity", slow)
    argv = ["jump-validity", "--order", "10000", "--m", "0.3", "--tol", "1e-3", "--json"]
    assert main(argv) == 0
    piped = capsys.readouterr()
    assert piped.err == ""
    term = Terminal()
    monkeypatch.setattr("sys.stderr", term)
    assert main(argv) == 0
    assert capsys.readouterr().out == piped.out
    assert "jump-validity: working" in term.getvalue()
    term2 = Terminal()
    monkeypatch.setattr("sys.stderr", term2)
    assert main([*argv, "-q"]) == 0
    assert capsys.readouterr().out == piped.out and term2.getvalue() == ""
