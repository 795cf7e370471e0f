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
import importlib.util
import sys

from paramres.inputs import InputError
from verify.certify import CertificationError

from . import commands

__all__ = ["main", "build_parser", "EXAMPLES"]

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
    if only is not None:
        names = [only]
    else:
        import pkgutil

        names = sorted(i.name for i in pkgutil.iter_modules(commands.__path__))
    for name in names:
        if not name.startswith("_"):
            importlib.import_module(f"{commands.__name__}.{name}").register(sub)
    for name, sp in sub.choices.items():
        if name in EXAMPLES and sp.epilog is None:
            sp.epilog = f"example: {EXAMPLES[name]}"
    return parser


#: one typical command line of each command, shown at the end of its --help
EXAMPLES = {
    "atlas": "paramres atlas --orders 1-3 --m 0.1:0.9:0.1 --Q none,7 --output atlas.nc",
    "bench": "paramres bench --quick --plot bench.pdf",
    "boundary": "paramres boundary --order 3 --m 3/5 --digits 40",
    "catalogue": "paramres catalogue --only differs",
    "crossings": "paramres crossings --max-order 6",
    "existence": "paramres existence --order 3 --Q 7",
    "explore": "paramres explore --port 8765",
    "jump-validity": "paramres jump-validity --order 1 --m 0.3 --tol 1e-3",
    "multipliers": "paramres multipliers --T 1.45 --m 0.3 --digits 20",
    "report": "paramres report --out report --lang en",
    "series": "paramres series --order 2 --terms 6",
    "simulate": "paramres simulate --order 1 --m 0.3 --edge lower --plot run.pdf",
    "table": "paramres table --orders 1-6 --m 0.05:0.95:0.05 --output edges.csv",
}


def _named(first: list[str]) -> str | None:
    """The command named first on the command line, if it is one: its parser is then built
    alone, importing no other command's modules (a numeric command starts sooner, a
    long-running server starts without them, and the report does not import, before it forks
    its second process, what only one of its processes needs).  Anything else -- no command,
    an option, a name that is no command -- gets the parser of every command, whose message
    lists them."""
    typed = first[0] if first else ""
    name = typed.replace("-", "_")  # a command is typed with hyphens where its module has _
    if "_" in typed or typed.startswith("-") or not name.isidentifier():
        return None
    return name if importlib.util.find_spec(f"{commands.__name__}.{name}") is not None else None


def main(argv: list[str] | None = None) -> int:
    if hasattr(sys, "set_int_max_str_digits"):
        # every number typed is bounded (2000 characters, exponents within +-10000) and results
        # run to 100000 digits: Python's guard on converting long integers to text (4300 digits)
        # would turn such a value, echoed in a message or a result, into a traceback
        sys.set_int_max_str_digits(0)
    parser = build_parser(_named((sys.argv[1:] if argv is None else argv)[:1]))
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
