"""The catalogue command, and the CLI's handling of bad command lines."""

import json
import subprocess
import sys

import pytest

from reports.cli import main


def _run(*args):
    return subprocess.run(
        [sys.executable, "-m", "reports.cli", *args], capture_output=True, text=True
    )


def test_catalogue_json(capsys):
    assert main(["catalogue", "--json"]) == 0
    # one object, like every command's --json (it used to be a bare list)
    doc = json.loads(capsys.readouterr().out)
    rows = doc["results"]
    assert doc["checked"] == len(rows) == doc["agree"] + doc["differ"]
    assert {"equation", "status", "printed", "derived", "how"} <= set(rows[0])
    assert any(r["status"] == "differs" for r in rows)


def test_catalogue_help_says_what_json_gives():
    from reports.cli import build_parser

    text = " ".join(
        build_parser("catalogue")
        ._subparsers._group_actions[0]
        .choices["catalogue"]
        .format_help()
        .split()
    )
    assert "one JSON object" in text and "JSON list" not in text


def test_catalogue_text_only_differs(capsys):
    assert main(["catalogue", "--only", "differs"]) == 0
    out = capsys.readouterr().out
    assert "(23)" in out and "ok " not in out


@pytest.mark.parametrize(
    "args", [["catalogue", "--bogus"], ["nonsense"], [], ["catalogue", "--only", "maybe"]]
)
def test_bad_command_lines(args):
    r = _run(*args)
    assert r.returncode == 2
    assert "paramres: error:" in r.stderr
    assert "Traceback" not in r.stderr
