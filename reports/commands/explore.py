"""``paramres explore``: the explorer in the browser (:mod:`reports.explorer`).

    paramres explore [--port N] [--host H] [--no-browser] [--export DIR]

Starts a local web server (``127.0.0.1`` unless ``--host`` says otherwise) serving the page and
its JSON endpoints, prints the address and opens the browser; Ctrl-C ends it.  ``--export DIR``
writes a static copy instead (precomputed charts, the motion computed in the page, no certified
clicks) that any web server can serve.
"""

from __future__ import annotations

import argparse

__all__ = ["register", "run"]


def register(subparsers) -> None:
    p = subparsers.add_parser(
        "explore",
        help="the stability chart in the browser: click for certified values and the motion",
        description=(
            "Start the explorer: a local web page with the chart of T/T0 against m coloured by "
            "the growth per period, the edges of orders 1..N over it, and on a click the "
            "certified multipliers, the certified edges and the pendulum moving. The page and "
            "all its scripts are served from the installed package (works offline)."
        ),
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    p.add_argument(
        "--port",
        default="8765",
        metavar="N",
        help="port, 0 to 65535 (0: any free port; default 8765)",
    )
    p.add_argument(
        "--host",
        default="127.0.0.1",
        metavar="H",
        help="address to bind (default 127.0.0.1: this machine only)",
    )
    p.add_argument("--no-browser", action="store_true", help="do not open a browser")
    p.add_argument(
        "--export",
        default=None,
        metavar="DIR",
        help="write a static copy of the explorer to DIR instead of serving",
    )
    p.set_defaults(func=run)


def run(args) -> int:
    import sys

    from paramres.inputs import InputError, as_integer
    from reports.explorer import _host

    if args.export is not None:
        from reports.explorer.export import export

        where = export(args.export)
        print(f"paramres explore: static copy written to {where}")
        return 0
    port = as_integer(args.port, name="port", low=0, high=65535)
    host = _host(args.host)
    from reports.explorer.server import Explorer

    try:
        app = Explorer(host, port)
    except OSError as exc:
        raise InputError(f"cannot serve on {host}:{port}: {exc.strerror or exc}") from None
    print(f"paramres explorer: {app.url}  (Ctrl-C ends it)", flush=True)
    if not args.no_browser:
        import webbrowser

        webbrowser.open(app.url)
    try:
        app.serve_forever()
    except KeyboardInterrupt:
        print("paramres explore: stopped", file=sys.stderr)
    return 0
