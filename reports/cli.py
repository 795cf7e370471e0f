"""The ``paramres`` command: one sub-command per module in :mod:`reports.commands`.

Each command module defines ``register(subparsers)``, which adds its parser and sets
``func(args) -> int`` as the parser's default.  Bad input of any kind -- an argparse error or an
:class:`verify.inputs.InputError` raised anywhere below -- ends as ``paramres: error: ...`` on
stderr
with exit status 2 and no traceback.
"""

from __future__ import annotations

import argparse
import importlib
import pkgutil
import sys

from paramres.inputs import InputError
from verify.certify import CertificationError

from . import commands

__all__ = ["main", "build_parser"]

PROG = "paramres"


class _Parser(argparse.ArgumentParser):
    def error(self, message: str):  # argparse calls this for malformed command lines
        # one line, like every other refusal; the usage is one --help away
        message = " ".join(message.split())
        self.exit(2, f"{PROG}: error: {message} (see '{self.prog} --help')\n")


def build_parser(only: str | None = None) -> argparse.ArgumentParser:
    """The parser of every command, or of the command ``only`` alone (imports only its module)."""
    parser = _Parser(
        prog=PROG,
        description=(
            "Regions of parametric excitation of a pendulum whose length is modulated by a square "
            "wave: symbolic derivations, certified high-precision boundaries, checks of the paper "
            "(Butikov, 'Pendulum with modulated length II'). Periods are in units of T0, depth is "
            "m "
            "(0 < m < 1), friction is the quality factor Q."
        ),
    )
    from paramres import __version__

    parser.add_argument("--version", action="version", version=f"{PROG} {__version__}")
    sub = parser.add_subparsers(dest="command", metavar="COMMAND", parser_class=_Parser)
    sub.required = True
    for info in sorted(pkgutil.iter_modules(commands.__path__), key=lambda i: i.name):
        if info.name.startswith("_") or (only is not None and info.name != only):
            continue
        module = importlib.import_module(f"{commands.__name__}.{info.name}")
        module.register(sub)
    return parser


#: commands whose parser is built alone when named first (a long-running server should start
#: without importing every other command's modules; the report should not import, before it
#: forks its second process, what only one of its processes needs)
_ALONE = ("explore", "report")


def main(argv: list[str] | None = None) -> int:
    first = (sys.argv[1:] if argv is None else argv)[:1]
    parser = build_parser(first[0] if first and first[0] in _ALONE else None)
    args = parser.parse_args(argv)
    try:
        return int(args.func(args) or 0)
    except InputError as exc:
        print(f"{PROG}: error: {exc}", file=sys.stderr)
        return 2
    except CertificationError as exc:
        # a proof the engine could not complete at this input and precision: say so, no traceback
        print(f"{PROG}: error: {_one_line(exc)}", file=sys.stderr)
        return 2
    except KeyboardInterrupt:  # pragma: no cover
        print(f"{PROG}: interrupted", file=sys.stderr)
        return 130
    except BrokenPipeError:  # pragma: no cover - e.g. `paramres table | head`
        return 0


def _one_line(exc: BaseException) -> str:
    return " ".join(str(exc).split()) or type(exc).__name__


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
