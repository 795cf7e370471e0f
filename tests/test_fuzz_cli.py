"""Fuzzing the command line: hypothesis builds argument lists for every sub-command -- numbers of
every magnitude, fractions, garbage, unicode, odd paths, option combinations -- and every run must
end with exit status 0 and valid output (JSON that parses, CSV with its header, the files it
names), or exit status 2 and exactly one line ``paramres: error: ...`` on stderr.  Never a
traceback, never a hang: each call runs in-process under a time limit (SIGALRM).

The options that set how much work a valid call does (digits, periods, orders, terms, table
size) get their cheap valid values and every kind of invalid one, so that the examples stay
fast; ``bench``, ``report`` and ``atlas`` (seconds to minutes per valid run: a cluster starts,
tested elsewhere) always get an output path that must be refused before any work.
"""

from __future__ import annotations

import contextlib
import csv
import io
import json
import os
import signal
import sys
from pathlib import Path

import pytest
from hypothesis import HealthCheck, Phase, given, settings
from hypothesis import strategies as st

from reports.cli import build_parser, main

pytestmark = pytest.mark.skipif(
    not hasattr(signal, "setitimer"), reason="the time limit per call needs SIGALRM"
)

#: seconds one call may take before it counts as a hang (generous: the machine may be loaded)
CALL_LIMIT = 30.0
EXAMPLES = int(os.environ.get("PARAMRES_FUZZ_EXAMPLES", "500"))


class Hang(Exception):
    pass


def _alarm(signum, frame):
    raise Hang()


# ------------------------------------------------------------------------------------------------
# values

digits_text = st.text(alphabet="0123456789", min_size=1, max_size=6)
magnitude = st.builds(
    lambda mant, exp: f"{mant}e{exp}",
    st.sampled_from(["1", "3", "0.5", "-2", "9.99", "0"]),
    st.one_of(st.integers(-20, 20), st.integers(-(10**10), 10**10)),
)
fraction = st.builds(lambda p, q: f"{p}/{q}", st.integers(-(10**6), 10**6), st.integers(0, 10**6))
floats = st.floats(allow_nan=True, allow_infinity=True).map(repr)
integers = st.integers(-(10**40), 10**40).map(str)
odd_tokens = st.sampled_from(
    [
        "",
        " ",
        "-",
        "--",
        "nan",
        "inf",
        "-inf",
        "none",
        "1/0",
        "0",
        "-0",
        "1",
        "0x10",
        "1_000",
        "١٢",
        "½",
        "0.3.4",
        "3/5/7",
        "1e",
        "e5",
        ".",
        "1" * 5000,
        "0." + "0" * 1500 + "1",
        "--json",
        "-h",
        "\u202e1",
        "1\x00",
        "３",
        "∞",
        "1e-1000",
        "1e-1001",
        "1e30",
        "1e31",
    ]
)
garbage = st.text(max_size=12)
any_value = st.one_of(magnitude, fraction, floats, integers, odd_tokens, garbage, digits_text)


def _cheap_valid(dest: str):
    """Valid values of each option that keep a run short."""
    return {
        "order": st.sampled_from(["1", "2", "3", "4", "5", "6", "12", "odd", "even"]),
        "m": st.one_of(
            st.sampled_from(["0.3", "3/5", "5/13", "1e-12", "0.999", "1/2", "0.05", "1e-300"]),
            st.fractions(min_value=0, max_value=1, max_denominator=1000).map(str),
        ),
        "Q": st.sampled_from(["0.4", "1/2", "3", "7", "100", "1e6", "none", "1e-6", "1e30"]),
        "damping": st.sampled_from(["exact", "paper", "EXACT", " paper "]),
        "digits": st.sampled_from(["5", "15", "30", "60"]),
        "tol": st.sampled_from(["1e-8", "1e-13", "1e-30", "0.1", "1/1000"]),
        "method": st.sampled_from(["certified", "fixedpoint", "grid", "series", "auto"]),
        "orders": st.sampled_from(["1-6", "1,3", "2", "1-2"]),
        "table_m": st.sampled_from(["0.05:0.95:0.05", "0.1:0.3:0.1", "1/3:2/3:1/6", "0.5:0.5:1"]),
        "format": st.sampled_from(["csv", "json"]),
        "jobs": st.sampled_from(["1", "2"]),
        "edge": st.sampled_from(["lower", "upper"]),
        "T": st.sampled_from(["0.5", "1.3", "2", "1/3", "7"]),
        "periods": st.sampled_from(["1", "2", "8", "20"]),
        "amplitude": st.sampled_from(["0.1", "1", "3", "1/100"]),
        "terms": st.sampled_from(["1", "2", "4", "6"]),
        "max_order": st.sampled_from(["1", "3", "6", "12"]),
        "only": st.sampled_from(["agrees", "differs"]),
        # existence proves every threshold and closing on the whole depth axis (1-20 s a call):
        # its cheapest case; the hard ones (Q <= 1/2, orders 1-4) are tests of their own
        # (tests/test_existence.py, tests/test_cli_refusals.py)
        "existence_Q": st.sampled_from(["3"]),
        "existence_digits": st.sampled_from(["5", "15"]),
        "small_order": st.sampled_from(["3"]),
    }.get(dest)


def _path(tmp: Path, suffixes):
    names = st.one_of(
        st.sampled_from(["out", "a b", "ünï", "x" * 300, ".hidden", "sub/dir/deep", "-", ""]),
        st.text(alphabet=st.characters(blacklist_categories=("Cs",)), min_size=1, max_size=8),
    )
    return st.builds(
        lambda name, suffix, where: where(tmp, name + suffix),
        names,
        st.sampled_from(suffixes),
        st.sampled_from(
            [
                lambda t, n: str(t / n),
                lambda t, n: "/proc/" + n,
                lambda t, n: str(t / "afile" / n),
                lambda t, n: str(t),
            ]
        ),
    )


def _bad_path(tmp: Path, suffix: str):
    return st.sampled_from([f"/proc/x{suffix}", str(tmp / "afile" / f"x{suffix}"), "/proc/sub/x"])


_SUBCOMMANDS = None
#: commands whose valid runs are long: their output is always one that must be refused
_SLOW = ("bench", "report", "atlas")


def _subcommands():
    global _SUBCOMMANDS
    if _SUBCOMMANDS is None:
        parser = build_parser()
        sub = next(a for a in parser._actions if a.__class__.__name__ == "_SubParsersAction")
        _SUBCOMMANDS = {
            name: [a for a in sp._actions if a.option_strings and a.dest != "help"]
            for name, sp in sub.choices.items()
        }
    return _SUBCOMMANDS


@st.composite
def argv_for(draw, tmp: Path):
    commands = _subcommands()
    # `explore` serves until interrupted: its refusals and its endpoints are fuzzed in
    # tests/test_explorer_api.py
    name = draw(st.sampled_from(sorted(c for c in commands if c != "explore")))
    argv = [name]
    for action in commands[name]:
        required = action.required
        if not required and not draw(st.booleans()):
            continue
        if required and draw(st.integers(0, 30)) == 0:
            continue  # a required option left out
        flag = draw(st.sampled_from(action.option_strings))
        if action.nargs == 0:
            argv.append(flag)
            continue
        dest = action.dest
        if dest in ("output", "plot", "out", "cache"):
            suffixes = [".csv", ".json", ".png", ".pdf", ".svg", ".txt", ""]
            if name in _SLOW and dest in ("output", "plot", "out"):
                suffix = {"plot": ".png"}.get(dest, ".json")
                if name == "atlas":
                    suffix = draw(st.sampled_from([".nc", ".zarr", ".json"]))
                value = draw(_bad_path(tmp, suffix))
            else:
                value = draw(_path(tmp, suffixes))
        else:
            key = {
                ("table", "m"): "table_m",
                ("atlas", "m"): "table_m",
                ("existence", "Q"): "existence_Q",
                ("existence", "digits"): "existence_digits",
            }.get((name, dest))
            key = key or {("existence", "order"): "small_order"}.get((name, dest), dest)
            valid = _cheap_valid(key)
            if action.choices:
                valid = st.sampled_from([str(c) for c in action.choices])
            use_valid = valid is not None and draw(st.integers(0, 3)) > 0
            value = draw(valid if use_valid else any_value)
        if draw(st.integers(0, 10)) == 0:
            argv.append(f"{flag}={value}")
        else:
            argv += [flag, value]
    if name in _SLOW and not any(a.startswith(("--out", "--plot")) for a in argv):
        flag = {"report": "--out", "atlas": "--output"}.get(name, "--plot")
        argv += [flag, "/proc/x.png" if name != "atlas" else "/proc/x.nc"]
    if draw(st.integers(0, 15)) == 0:
        argv.insert(draw(st.integers(1, len(argv))), draw(any_value))  # a stray token
    return argv


# ------------------------------------------------------------------------------------------------
# one call, checked


def call(argv: list[str]) -> tuple[int, str, str]:
    out, err = io.StringIO(), io.StringIO()
    old = signal.signal(signal.SIGALRM, _alarm)
    signal.setitimer(signal.ITIMER_REAL, CALL_LIMIT)
    try:
        with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
            try:
                code = main(argv)
            except SystemExit as exc:  # argparse: --help, or a malformed command line
                code = exc.code if isinstance(exc.code, int) else (0 if exc.code is None else 2)
    except Hang:
        pytest.fail(f"no answer within {CALL_LIMIT} s: paramres {argv!r}")
    finally:
        signal.setitimer(signal.ITIMER_REAL, 0)
        signal.signal(signal.SIGALRM, old)
    return code, out.getvalue(), err.getvalue()


def check(argv: list[str], code: int, out: str, err: str) -> None:
    assert "Traceback" not in err, (argv, err)
    if code == 2:
        lines = err.splitlines()
        assert len(lines) == 1 and lines[0].startswith("paramres: error: "), (argv, err)
        return
    assert code == 0, (argv, code, out, err)
    if "-h" in argv or "--help" in argv:
        return
    writes = [argv[i + 1] for i, a in enumerate(argv[:-1]) if a in ("--output", "--plot")]
    writes += [a.split("=", 1)[1] for a in argv if a.startswith(("--output=", "--plot="))]
    for path in writes:
        assert Path(path).is_file(), (argv, path)
    if "--json" in argv:
        json.loads(out)
    elif argv[0] == "table" and not any(a.startswith("--output") for a in argv):
        fmt = "json" if ("--format", "json") in zip(argv, argv[1:], strict=False) else None
        if fmt == "json" or "--format=json" in argv:
            json.loads(out)
        else:
            rows = list(csv.reader(io.StringIO(out)))
            assert rows[0][:4] == ["order", "m", "lower", "upper"], (argv, out[:200])
    elif not writes:
        assert out.strip(), (argv, err)


_TMP = None


def _tmp() -> Path:
    global _TMP
    if _TMP is None:
        import tempfile

        _TMP = Path(tempfile.mkdtemp(prefix="paramres-fuzz-"))
        (_TMP / "afile").write_text("a file, not a directory\n")
    return _TMP


@pytest.fixture(scope="module", autouse=True)
def _warm():
    """The catalogue is derived once per process (8-16 s cold, then a lookup): derive it here,
    outside the time limit of a call."""
    from analytic.catalogue import catalogue

    catalogue()


@pytest.fixture(scope="module", autouse=True)
def _existence_once():
    """``existence`` computed once per distinct argument list: the command still parses, checks
    and prints on every call, but a repeated valid input (hypothesis draws the cheap valid values
    often) does not prove the same ranges again."""
    import reports.commands.existence as command

    inner = command.existence
    memo: dict = {}

    def once(*args, **kwargs):
        key = repr((args, sorted(kwargs.items())))
        if key not in memo:
            memo[key] = inner(*args, **kwargs)
        return memo[key]

    mp = pytest.MonkeyPatch()
    mp.setattr(command, "existence", once)
    yield
    mp.undo()


@settings(
    max_examples=EXAMPLES,
    deadline=None,
    suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large],
    derandomize=True,
    phases=[Phase.explicit, Phase.reuse, Phase.generate, Phase.shrink],
)
@given(data=st.data())
def test_every_command_line_gets_an_answer(data):
    argv = data.draw(argv_for(_tmp()), label="argv")
    code, out, err = call(argv)
    check(argv, code, out, err)


@pytest.mark.parametrize(
    "argv",
    [
        ["boundary", "--order", "3", "--m", "0.3", "--json"],
        ["table", "--orders", "1-2", "--m", "0.1:0.3:0.1"],
        ["boundary", "--order", "1", "--m", "1e999999999"],
        ["simulate", "--order", "1", "--m", "0.3", "--edge", "lower", "--plot", "/proc/x.png"],
        ["--version"],
    ],
)
def test_the_checker_itself(argv):
    # the harness accepts a good run and a refusal, so the fuzz test can fail only on real faults
    code, out, err = call(argv)
    check(argv, code, out, err)
    assert code in (0, 2)


def test_the_checker_catches_a_traceback_and_a_hang(monkeypatch):
    import reports.commands.boundary as boundary_command

    def broken(args):
        raise ZeroDivisionError("boom")

    monkeypatch.setattr(boundary_command, "run", broken)
    with pytest.raises(ZeroDivisionError):
        call(["boundary", "--order", "1", "--m", "0.3"])
    monkeypatch.setattr(sys.modules[__name__], "CALL_LIMIT", 0.2)

    def slow(args):
        import time

        time.sleep(5)

    monkeypatch.setattr(boundary_command, "run", slow)
    with pytest.raises(pytest.fail.Exception):
        call(["boundary", "--order", "1", "--m", "0.3"])


@pytest.mark.parametrize(
    "argv, expected",
    [
        (["boundary", "--order", "1", "--m", "1e999999999"], 2),
        (["existence", "--order", "3", "--Q", "1e400"], 2),
        (["table", "--orders", "1", "--m", "0.3", "--output", "/proc/x.csv"], 2),
        (["boundary", "--order", "1", "--m", "0.3", "--json"], 0),
        # the tolerance path with friction reaches the certified solver without the dispatcher
        # that registers it: in a fresh process it used to end in KeyError: 'certified'
        (["table", "--orders", "1", "--m", "0.3:0.3:1", "--tol", "1e-5", "--Q", "3"], 0),
    ],
)
def test_a_real_process_exits_as_the_in_process_call_says(argv, expected):
    # the fuzz test calls main() in-process; a few command lines run as a real process too, so
    # that the exit status the shell sees and the absence of a traceback are checked end to end
    import subprocess

    proc = subprocess.run(
        [sys.executable, "-m", "paramres", *argv],
        capture_output=True,
        text=True,
        timeout=120,
    )
    assert proc.returncode == expected, (argv, proc.returncode, proc.stderr)
    check(argv, proc.returncode, proc.stdout, proc.stderr)


def test_a_command_named_first_gets_its_own_parser_alone(capsys):
    """``main`` builds the parser of the command named first alone (no other command's modules
    imported); it is the very parser of the full build: every command, typed as the full parser
    names it, finds itself and only itself, with the same options and help.  Anything that is
    not a command's name gets the full parser (whose refusal lists every command)."""
    from reports.cli import _named

    def subparsers(parser):
        sub = next(a for a in parser._actions if a.__class__.__name__ == "_SubParsersAction")
        return sub.choices

    full = subparsers(build_parser())
    assert len(full) > 5
    for name, sp in full.items():
        alone = subparsers(build_parser(_named([name])))
        assert list(alone) == [name]
        assert alone[name].format_help() == sp.format_help()
    others = ([], ["--help"], ["-h"], ["nonsense"], ["jump_validity"], ["_arguments"], [""])
    others += (["--init--"], ["-arguments"], ["--pycache--"], ["-table"], ["--table"])
    for other in others:
        assert _named(other) is None, other
    for argv in (["--init--", "table", "-h"], ["-arguments", "boundary", "-h"]):
        with pytest.raises(SystemExit) as stop:  # the full parser: the command's help, as before
            main(argv)
        assert stop.value.code == 0
        assert f"usage: paramres {argv[1]}" in capsys.readouterr().out


_THREES = "0." + "3" * 400  # a duty near 1/3 whose exact fraction has 400 digits


@pytest.mark.parametrize(
    "argv, words",
    [
        # the search for the longest valid ramp runs in doubles: a tolerance or a duty that
        # underflows there used to loop for ever
        (["jump-validity", "--order", "1", "--m", "0.3", "--tol", "1e-400"], ("1e-400", "1e-12")),
        (["jump-validity", "--order", "1", "--m", "0.3", "--tol", "1e-13"], ("1e-13", "1e-12")),
        (
            ["jump-validity", "--order", "1", "--m", "0.3", "--tol", "1e-3", "--duty", "1e-400"],
            ("1e-400", "1e-300 <= D"),
        ),
        # the double-precision grid of a duty whose exact coefficients overflow a double used to
        # end in an OverflowError traceback
        (
            ["table", "--orders", "1-2", "--m", "0.1:0.2:0.1", "--duty", _THREES],
            ("33333", "double"),
        ),
        (["table", "--orders", "1", "--m", "0.1:0.2:0.1", "--duty", "1e-400"], ("D = 1/1000",)),
    ],
)
def test_inputs_that_used_to_hang_or_fail_are_refused(argv, words):
    code, out, err = call(argv)
    check(argv, code, out, err)
    assert code == 2 and out == "", (argv, code, out, err)
    for word in words:
        assert word in err, (word, err)


def test_a_switching_time_below_the_smallest_double(capsys):
    """A ramp of S = 1e-400 (a step of the continuation below the smallest double used to divide
    by zero) gives the jump model's edges (reference: the square modulation, same digits)."""
    argv = ["boundary", "--order", "1", "--m", "0.3", "--digits", "20", "--json"]
    code, out, err = call([*argv, "--modulation", "ramp", "--switch-time", "1e-400"])
    check(argv, code, out, err)
    assert code == 0, err
    ramp = json.loads(out)
    code, out, err = call(argv)
    square = json.loads(out)
    assert (ramp["lower"], ramp["upper"]) == (square["lower"], square["upper"])


def test_an_exact_edge_is_not_said_to_be_within_zero():
    """Equal custom frequencies: the edges are exact rationals, the bound 0; the text says they
    are exact (``|printed - exact| < 0`` would be false)."""
    code, out, err = call(["boundary", "--order", "2", "--system", "custom", "--omega-sq", "1,1"])
    assert code == 0, err
    assert "printed = exact" in out and "< 0]" not in out
