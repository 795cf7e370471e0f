"""Every input gets an answer: the inputs that used to end in a traceback or a hang now end with
exit status 2 and one line ``paramres: error: ...`` naming the value and the allowed range, and
unwritable outputs are refused before any work, with nothing written."""

from __future__ import annotations

import time

import pytest

from paramres.inputs import InputError, as_depth, as_number, as_quality, as_tolerance
from reports.cli import main


def run(capsys, argv):
    code = main(argv)
    out, err = capsys.readouterr()
    return code, out, err


def refused(capsys, argv, *words):
    code, out, err = run(capsys, argv)
    assert code == 2, (argv, out, err)
    lines = err.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("paramres: error: "), err
    for w in words:
        assert w in lines[0], (w, lines[0])
    return lines[0]


@pytest.mark.parametrize(
    "argv, words",
    [
        (["boundary", "--order", "1", "--m", "1e-5000"], ("1e-5000", "0 < m < 1")),
        (["boundary", "--order", "1", "--m", "1e999999999"], ("1e999999999", "0 < m < 1")),
        (["boundary", "--order", "1", "--m", "0.3", "--Q", "1e400"], ("1e400", "Q <=")),
        (["table", "--orders", "1", "--m", "0.1:0.2:0.1", "--Q", "1e400"], ("1e400", "Q <=")),
        (["existence", "--order", "1", "--Q", "1e400"], ("1e400", "Q <=")),
        (["existence", "--order", "1", "--Q", "1e-400"], ("1e-400", "<= Q")),
        (["boundary", "--order", "1", "--m", "0.3", "--tol", "1/0"], ("1/0", "0.1")),
        (["table", "--orders", "1", "--m", "1e999999999:1:1"], ("1e999999999",)),
        (["table", "--orders", "1", "--m", "1e-5000:0.1:0.1"], ("0 < m < 1",)),
        (["simulate", "--order", "1", "--m", "0.3", "--T", "1e999999999"], ("1e999999999",)),
        (
            ["simulate", "--order", "1", "--m", "0.3", "--edge", "lower", "--amplitude", "1e99999"],
            ("1e99999",),
        ),
        (["boundary", "--order", "9" * 5000, "--m", "0.3"], ("order", "1 to")),
        (["boundary", "--order", "1", "--m", "0.3", "--digits", "9" * 5000], ("digits",)),
        (["existence", "--order", "1", "--Q", "3", "--digits", "5000"], ("5000", "5 to 3000")),
        (
            [
                "atlas",
                "--orders",
                "1",
                "--m",
                "0.1:0.2:0.1",
                "--workers",
                "1000",
                "--output",
                "a.nc",
            ],
            ("1000", "1 to 64"),
        ),
        (
            ["boundary", "--order", "3", "--m", "0.3", "--system", "torsion", "--tol", "1e-8"],
            ("tolerance", "--digits for torsion"),
        ),
    ],
)
def test_refused_at_once(capsys, argv, words):
    start = time.monotonic()
    refused(capsys, argv, *words)
    # a hang would show here (the exponent used to be expanded); generous bound, not a benchmark
    assert time.monotonic() - start < 30


def test_unwritable_outputs_refused_before_any_work(capsys, tmp_path):
    afile = tmp_path / "afile"
    afile.write_text("x")
    refused(
        capsys,
        ["table", "--orders", "1", "--m", "0.1:0.2:0.1", "--output", "/proc/x.csv"],
        "/proc/x.csv",
    )
    refused(
        capsys,
        ["simulate", "--order", "1", "--m", "0.3", "--edge", "lower", "--plot", "/proc/x.png"],
        "/proc/x.png",
    )
    refused(
        capsys,
        ["report", "--out", str(afile / "sub"), "--no-pdf", "-q", "--no-cache"],
        "not a directory",
    )
    refused(
        capsys,
        ["table", "--orders", "1", "--m", "0.1:0.2:0.1", "--output", str(tmp_path)],
        "directory",
    )
    # the JSON is not written when the plot cannot be (it used to be written, then a crash)
    target = tmp_path / "a.json"
    start = time.monotonic()
    refused(
        capsys,
        ["bench", "--quick", "--output", str(target), "--plot", "/proc/x.png"],
        "/proc/x.png",
    )
    assert time.monotonic() - start < 30  # refused before the benchmark runs
    assert not target.exists()
    assert sorted(p.name for p in tmp_path.iterdir()) == ["afile"]


def test_api_refuses_the_same_values():
    for bad in ("1e-5000", "1e999999999", "1/0", "0", "1", "x", "1e" + "9" * 50, "9" * 3000):
        with pytest.raises(InputError):
            as_depth(bad)
    for bad in ("1e400", "1e-400", "0", "-1", "1/0"):
        with pytest.raises(InputError):
            as_quality(bad)
    for bad in ("1/0", "1", "0", "1e-20000"):
        with pytest.raises(InputError):
            as_tolerance(bad)
    # exact values at the ends of the ranges are accepted
    assert as_depth("1e-1000") == as_number("1/1" + "0" * 1000, name="m", allowed="")
    assert as_quality("1e30") == 10**30 and as_quality("1e-6") * 10**6 == 1


def test_floats_mean_their_shortest_decimal():
    from fractions import Fraction

    assert as_depth(0.3) == Fraction(3, 10)  # as --m 0.3 on the command line
    assert as_quality(7.1) == Fraction(71, 10)


def test_existence_with_both_halves_overdamped_at_small_depth(capsys):
    # `existence --order 3 --Q 0.4` (exact model, 4Q^2 < 1: half 2 is over-damped below
    # m = 1 - 4Q^2) used to end in "math domain error"; the reference is the certified boundary
    # on either side of the first end it reports
    from verify.existence import existence
    from verify.solve import boundary

    code, out, err = run(capsys, ["existence", "--order", "3", "--Q", "0.4"])
    assert code == 0 and err == "" and "exists for" in out
    ex = existence(3, "0.4")
    (a, b), *_ = ex.intervals
    # the proven range starts at a; an undecided sliver may separate it from the proven gap below
    below = min([lo for lo, hi in ex.undecided if hi == a] or [a])
    assert not boundary(3, below * (1 - mpmath_eps()), Q="0.4", digits=15).exists
    assert boundary(3, a * (1 + mpmath_eps()), Q="0.4", digits=15).exists


def mpmath_eps():
    import mpmath

    return mpmath.mpf("1e-6")


def test_every_help_states_the_ranges_and_an_example():
    """Each command's --help ends with a typical command line, which its own parser accepts, and
    the shared options state their ranges (the ones the checks in paramres.inputs enforce)."""
    import shlex

    from reports.cli import EXAMPLES, build_parser

    parser = build_parser()
    sub = next(a for a in parser._actions if a.__class__.__name__ == "_SubParsersAction")
    assert set(sub.choices) == set(EXAMPLES)
    for name, sp in sub.choices.items():
        text = " ".join(sp.format_help().split())
        assert f"example: {EXAMPLES[name]}" in text, name
        argv = shlex.split(EXAMPLES[name])
        assert argv[:2] == ["paramres", name]
        parser.parse_args(argv[1:])  # a malformed example would exit here
        if any(a.dest == "order" for a in sp._actions) and name != "series":
            assert "order of the resonance, 1 to 10000" in text, name
        if any(a.dest == "Q" for a in sp._actions) and name != "atlas":
            assert "1e-6 <= Q <= 1e30" in text, name
    boundary = " ".join(sub.choices["boundary"].format_help().split())
    assert "5 to 100000" in boundary  # verify.inputs.BOUNDARY_DIGITS_RANGE
    # --tol (and --method auto/fixedpoint) refuse every other system: the help says so
    assert boundary.count("the paper's system only") == 2
    assert "the paper's system only" in " ".join(sub.choices["table"].format_help().split())
    assert "0 < T <= 1e6" in " ".join(sub.choices["multipliers"].format_help().split())


@pytest.mark.parametrize(
    "argv, words",
    [
        # an empty file name is refused as typed: it used to mean "no plot" (simulate ran and
        # drew nothing) or the current directory (named '.' in the refusal)
        (["simulate", "--order", "1", "--m", "0.3", "--edge", "lower", "--plot", ""], "''"),
        (["table", "--orders", "1", "--m", "0.1:0.2:0.1", "--output", ""], "--output ''"),
    ],
)
def test_an_empty_file_name_is_refused(capsys, argv, words):
    line = refused(capsys, argv, words)
    assert "'.'" not in line


def test_a_decimal_over_an_integer_is_read(capsys):
    """``0.3/2`` and ``1e-1/3`` match the number syntax but are no literal ``Fraction`` reads:
    they used to end in a ValueError traceback."""
    from fractions import Fraction

    assert as_number("0.3/2", name="x", allowed="") == Fraction(3, 20)
    assert as_depth("1e-1/3") == Fraction(1, 30)
    code, out, err = run(capsys, ["boundary", "--order", "1", "--m", "0.3/2", "--digits", "10"])
    assert code == 0, err
    assert out == run(capsys, ["boundary", "--order", "1", "--m", "3/20", "--digits", "10"])[1]
    refused(capsys, ["boundary", "--order", "1", "--m", "1e-1/0"], "1e-1/0", "divides by zero")


@pytest.fixture
def int_text_limit():
    """Python's default guard on long integer text (4300 digits) in force, restored after."""
    import sys

    old = sys.get_int_max_str_digits()
    sys.set_int_max_str_digits(4300)
    yield
    sys.set_int_max_str_digits(old)


@pytest.mark.parametrize(
    "argv",
    [
        ["multipliers", "--T", "1e-4999", "--m", "0.3"],
        ["boundary", "--order", "1", "--m", "0.3", "--duty", "1e-4999", "--digits", "10"],
        [
            "boundary",
            "--order",
            "1",
            "--m",
            "0.3",
            "--modulation",
            "ramp",
            "--switch-time",
            "1e4999",
        ],
        ["multipliers", "--T", "1", "--m", "0.3", "--digits", "5000"],
    ],
)
def test_values_of_thousands_of_digits_end_in_an_answer(capsys, int_text_limit, argv):
    # a value of 5000 digits, echoed in a result or a message, or a result of 5000 digits, used
    # to hit Python's limit on integer text and end in a traceback
    code, out, err = run(capsys, argv)
    assert code in (0, 2) and "Traceback" not in err, err
    if code == 2:
        assert len(err.splitlines()) == 1 and err.startswith("paramres: error: ")


def test_a_bound_of_a_print_of_thousands_of_digits(int_text_limit):
    """The bound of a 5000-digit print is computed in the API too (no CLI to lift the limit)."""
    from verify.multipliers import multipliers

    text = str(multipliers("1", "0.3", digits=5000))
    assert "certified: |printed - exact| < " in text


def test_the_smallest_tolerance_can_be_typed(capsys):
    """The range of a tolerance starts at 1e-10000: that text is read (it used to be refused by
    the limit on exponents, 5000, with the message 'tolerance = 1e-10000 is outside the allowed
    range 1e-10000 to 0.1')."""
    import mpmath

    tol = as_tolerance("1e-10000")
    assert abs(int(mpmath.floor(mpmath.log10(tol))) + 10000) <= 1
    refused(capsys, ["boundary", "--order", "1", "--m", "0.3", "--tol", "1e-10001"], "1e-10000")
