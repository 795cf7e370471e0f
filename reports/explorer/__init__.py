"""The explorer: the stability chart in the browser, certified answers on a click, the pendulum
moving.

``paramres explore`` (:mod:`reports.commands.explore`) and :func:`explore` start a local web server
(:mod:`.server`, the standard library's HTTP server) that serves one page of plain HTML, JavaScript
and CSS shipped in this package (``static/``) and JSON endpoints under ``/api/`` (:mod:`.api`)
that call the public API.  The JavaScript the page computes with is generated from the sympy
forms (:mod:`.jsgen`).  :mod:`.export` writes a static copy (precomputed charts, the animation
run in the page, no certified clicks).
"""

from __future__ import annotations

__all__ = ["explore"]


def explore(port: int = 0, host: str = "127.0.0.1", *, open_browser: bool = False, height=760):
    """Start the explorer on a background thread and return what shows it.

    In IPython / Jupyter the return value is an :class:`IPython.display.IFrame` of the page (the
    notebook shows it inline); elsewhere the address is printed and the running
    :class:`~.server.Explorer` is returned (``.url``, ``.stop()``).  ``port=0`` takes a free port.
    The server binds ``host`` (default ``127.0.0.1``: this machine only).
    """
    from paramres.inputs import as_integer

    from .server import Explorer

    port = as_integer(port, name="port", low=0, high=65535)
    app = Explorer(_host(host), port).start()
    if open_browser:
        import webbrowser

        webbrowser.open(app.url)
    try:
        from IPython import get_ipython
        from IPython.display import IFrame
    except ImportError:
        get_ipython = None
    if get_ipython is not None and get_ipython() is not None:
        frame = IFrame(app.url, width="100%", height=height)
        frame.explorer = app
        return frame
    print(f"paramres explorer: {app.url}")
    return app


def _host(host) -> str:
    from paramres.inputs import InputError

    text = str(host).strip() if isinstance(host, str) else ""
    if not text or len(text) > 253 or any(c.isspace() or c in "/?#@" for c in text):
        raise InputError(f"host {str(host)[:60]!r} is not a host name or address")
    return text
