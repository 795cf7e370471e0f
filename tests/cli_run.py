"""The command line run inside a test: its exit status, standard output and standard error."""

from __future__ import annotations


def run_cli(capsys, *argv: str) -> tuple[int, str, str]:
    """``paramres ARGV...`` in this process (:func:`reports.cli.main`), with pytest's ``capsys``
    holding what it printed."""
    from reports.cli import main

    code = main(list(argv))
    out, err = capsys.readouterr()
    return code, out, err
