"""The explorer: the stability chart in the browser, certified answers on a click, the pendulum
moving.

``paramres explore`` (:mod:`reports.commands.explore`) and :func:`explore` start a local web server
(:mod:`.server`, the standard library's HTTP server) that serves one page of plain HTML, JavaScript
and CSS shipped in this package (``static/``) and JSON endpoints under ``/api/`` (:mod:`.api`)
that call the public API.  The JavaScript the page computes with is generated from the sympy
forms (:mod:`.jsgen`).  :mod:`.export` writes a static copy (precomputed charts, the motion
computed in the page, no certified clicks).
"""

from __future__ import annotations

import atexit
import subprocess
import sys
import tempfile

__all__ = ["explore", "RunningExplorer"]


class RunningExplorer:
    """An explorer serving from its own process: ``url``, ``stop()``."""

    def __init__(self, process: subprocess.Popen, url: str):
        self.process = process
        self.url = url

    def stop(self) -> None:
        if self.process.poll() is None:
            self.process.terminate()
            try:
                self.process.wait(10)
            except subprocess.TimeoutExpired:  # pragma: no cover
                self.process.kill()

    def __repr__(self) -> str:
        state = "running" if self.process.poll() is None else "stopped"
        return f"<paramres explorer at {self.url} ({state})>"


def explore(port: int = 0, host: str = "127.0.0.1", *, open_browser: bool = False, height=760):
    """Start the explorer and return what shows it.

    In IPython / Jupyter the return value is an :class:`IPython.display.IFrame` of the page (the
    notebook shows it inline; ``.explorer`` is the running server); elsewhere the address is
    printed and a :class:`RunningExplorer` is returned (``.url``, ``.stop()``).  ``port=0`` takes
    a free port; the server binds ``host`` (default ``127.0.0.1``: this machine only).

    The server runs in a process of its own (``paramres explore --no-browser``), not in a thread
    of the caller's: mpmath's and Arb's working precision are process-wide, so a server thread
    computing beside the notebook's own computations could disturb their digits.  It ends with
    ``.stop()`` or when the Python session ends.
    """
    from paramres.inputs import InputError, as_integer

    port = as_integer(port, name="port", low=0, high=65535)
    host = _host(host)
    err = tempfile.TemporaryFile(mode="w+")
    proc = subprocess.Popen(
        [sys.executable, "-m", "paramres", "explore", "--no-browser", "--port", str(port),
         "--host", host],
        stdin=subprocess.DEVNULL,
        stdout=subprocess.PIPE,
        stderr=err,
        text=True,
    )  # fmt: skip
    line = proc.stdout.readline()
    if not line.startswith("paramres explorer: "):
        proc.wait(30)
        err.seek(0)
        message = err.read().strip().splitlines()
        raise InputError(
            (message[-1] if message else "the explorer did not start").removeprefix(
                "paramres: error: "
            )
        )
    app = RunningExplorer(proc, line.split()[2])
    atexit.register(app.stop)
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

    text = host.strip() if isinstance(host, str) else ""
    if not text or len(text) > 253 or any(c.isspace() or c in "/?#@" for c in text):
        raise InputError(f"host {str(host)[:60]!r} is not a host name or address")
    return text
