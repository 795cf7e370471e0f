"""The explorer's HTTP layer: the standard library's :class:`http.server.ThreadingHTTPServer`.

``/`` and ``/static/...`` serve the page (package data in ``reports/explorer/static``);
``/static/generated.js`` is the JavaScript generated from the sympy forms (:mod:`.jsgen`);
``/api/<name>?...`` answers with JSON (:mod:`.api`).

**Safety.**  Every answer is JSON or a file of the package: a bad request gets HTTP 400 and
``{"error": "<one line>"}``, an unknown path 404, never a traceback (an unexpected failure is
logged on the server's side and answered with a 500 line that says so).  The engine's work runs on
**one worker thread**: mpmath's and Arb's working precision are process-wide, so two computations
at once could disturb each other's digits (the colour map alone, pure numpy, and the presets are
answered on the HTTP thread without waiting); the HTTP threads wait for the worker at most
:data:`REQUEST_SECONDS` and answer 503 (``{"error": "... took longer than ..."}``) past that.
The explorer's caps (:data:`.api.LIMITS`: digits <= 100, grids <= 600 x 400, orders <= 12, runs
<= 60 periods; the nonlinear run's budget of integration steps,
:data:`verify.pendulum_ode.MAX_STEPS_PER_PERIOD`) keep each computation to seconds, so a request
that timed out does not hold the worker for long.  The server binds ``127.0.0.1`` unless another
host is asked for.
"""

from __future__ import annotations

import itertools
import json
import mimetypes
import queue
import sys
import threading
from concurrent.futures import Future
from concurrent.futures import TimeoutError as FutureTimeout
from http.server import BaseHTTPRequestHandler, ThreadingHTTPServer
from importlib import resources
from urllib.parse import parse_qs, urlsplit

from paramres.inputs import InputError

from . import api

__all__ = ["Explorer", "REQUEST_SECONDS", "MAX_QUERY", "static_file"]

#: how long a request may wait for its answer (queue and computation), seconds
REQUEST_SECONDS = 20.0
#: the longest query string accepted
MAX_QUERY = 4000
#: requests waiting for the worker at once, beyond which the server answers 503 at once
MAX_PENDING = 16
#: seconds after the start when the rest of the warm-up begins if no chart was asked for
WARM_DELAY = 5.0

#: what a request that took too long may change, per endpoint (the parameters that set its cost)
_ADVICE = {
    "boundary": "ask for fewer digits",
    "multipliers": "ask for fewer digits",
    "point": "ask for fewer digits",
    "chart": "ask for a smaller grid (nt, nm) or fewer orders (max_order)",
    "simulate": "ask for fewer periods or fewer samples",
}


def static_file(name: str) -> bytes | None:
    """The bytes of ``static/<name>`` from the package (``None`` if there is no such file)."""
    if not name or "/" in name or "\\" in name or name.startswith("."):
        return None
    if name == "generated.js":
        from .jsgen import generated_js

        return generated_js().encode()
    try:
        return resources.files(__package__).joinpath("static", name).read_bytes()
    except (FileNotFoundError, IsADirectoryError, NotADirectoryError, OSError):
        return None


class _Handler(BaseHTTPRequestHandler):
    server_version = "paramres-explorer"
    explorer: Explorer  # set on the subclass made per server

    def log_message(self, format, *args):  # noqa: A002 - the signature of the base class
        if self.explorer.verbose:
            super().log_message(format, *args)

    def _send(self, status: int, body: bytes, ctype: str) -> None:
        self.send_response(status)
        self.send_header("Content-Type", ctype)
        self.send_header("Content-Length", str(len(body)))
        self.send_header("Cache-Control", "no-store")
        self.send_header("X-Content-Type-Options", "nosniff")
        self.end_headers()
        if self.command != "HEAD":
            self.wfile.write(body)

    def _json(self, status: int, doc: dict) -> None:
        body = json.dumps(doc, allow_nan=False, separators=(",", ":")).encode()
        self._send(status, body, "application/json; charset=utf-8")

    def _error(self, status: int, message: str) -> None:
        self._json(status, {"error": " ".join(str(message).split())})

    def do_HEAD(self):  # noqa: N802 - http.server's naming
        self.do_GET()

    def do_GET(self):  # noqa: N802
        try:
            parts = urlsplit(self.path)
        except ValueError:
            return self._error(400, "the request's address cannot be read")
        path = parts.path
        if path in ("/", "/index.html"):
            return self._static("index.html")
        if path.startswith("/static/"):
            return self._static(path[len("/static/") :])
        if path.startswith("/api/"):
            return self._api(path[len("/api/") :], parts.query)
        return self._error(404, f"no such page: {path[:80]}")

    def do_POST(self):  # noqa: N802
        self._error(405, "the explorer answers GET requests only")

    def _static(self, name: str) -> None:
        if name == "generated.js":  # sympy at work the first time: on the engine's worker
            from .jsgen import generated_js

            try:
                if generated_js.cache_info().currsize:  # built already: no sympy, no waiting
                    body = generated_js()
                else:
                    future = self.explorer._worker.submit(generated_js)
                    body = future.result(max(self.explorer.timeout, 120.0))
            except FutureTimeout:
                return self._error(503, "the generated script is not ready yet; reload")
            return self._send(200, body.encode(), "text/javascript; charset=utf-8")
        body = static_file(name)
        if body is None:
            return self._error(404, f"no such file: {name[:80]}")
        ctype = mimetypes.guess_type(name)[0] or "application/octet-stream"
        if ctype.startswith("text/") or ctype.endswith("javascript"):
            ctype += "; charset=utf-8"
        self._send(200, body, ctype)

    def _api(self, name: str, query: str) -> None:
        if name not in api.ENDPOINTS:
            return self._error(
                404, f"no endpoint {name[:40]!r}; there are: {', '.join(sorted(api.ENDPOINTS))}"
            )
        if len(query) > MAX_QUERY:
            return self._error(400, f"the query is longer than {MAX_QUERY} characters")
        try:
            params = parse_qs(query, keep_blank_values=True, strict_parsing=bool(query))
        except ValueError:
            return self._error(400, "the query string cannot be read (name=value&name=value)")
        status, doc = self.explorer.run(name, params)
        self._json(status, doc)
        if name == "chart" and params.get("parts") != ["growth"] and self.explorer._warm:
            self.explorer._warm_rest()


class Explorer:
    """A running explorer: ``Explorer(port=0).start()`` serves on a background thread;
    ``url`` is its address, ``stop()`` ends it."""

    def __init__(
        self,
        host: str = "127.0.0.1",
        port: int = 0,
        *,
        timeout: float = REQUEST_SECONDS,
        verbose: bool = False,
        warm: bool = True,
    ):
        handler = type("Handler", (_Handler,), {"explorer": self})
        self.httpd = ThreadingHTTPServer((host, port), handler)
        self.httpd.daemon_threads = True
        self.timeout = timeout
        self.verbose = verbose
        self._worker = _Worker()
        self._pending = threading.BoundedSemaphore(MAX_PENDING)
        self._thread: threading.Thread | None = None
        self._warm = warm

    @property
    def url(self) -> str:
        host, port = self.httpd.server_address[:2]
        shown = f"[{host}]" if ":" in str(host) else host
        return f"http://{shown}:{port}/"

    def run(self, name: str, params: dict) -> tuple[int, dict]:
        """The status and JSON document answering ``/api/<name>`` with ``params``."""
        if _double_only(name, params):
            try:
                doc = api.handle(name, params)
                if name == "presets":
                    doc = {**doc, "warming": self._worker.warming}
                return 200, doc
            except InputError as exc:
                return 400, {"error": " ".join(str(exc).split())}
        if not self._pending.acquire(blocking=False):
            return 503, {"error": "the explorer is busy; try again in a moment"}
        try:
            future = self._worker.submit(api.handle, name, params)
            try:
                return 200, future.result(timeout=self.timeout)
            except FutureTimeout:
                future.cancel()
                return 503, {
                    "error": f"the computation took longer than {self.timeout:g} s; "
                    + _ADVICE.get(name, "try again in a moment")
                }
            except InputError as exc:
                return 400, {"error": " ".join(str(exc).split())}
            except Exception as exc:  # a proof that could not be completed, or a bug
                from verify.certify import CertificationError

                if isinstance(exc, CertificationError):
                    return 400, {"error": " ".join(str(exc).split())}
                print(f"paramres explore: internal error in /api/{name}: {exc!r}", file=sys.stderr)
                return 500, {"error": f"internal error ({type(exc).__name__}); see the server log"}
        finally:
            self._pending.release()

    def _begin_warm_up(self) -> None:
        """What the page asks for first (the generated script, the default chart's edges) is
        built at once; the rest of the warm-up waits until the page has its first chart (or
        :data:`WARM_DELAY` seconds), so that it does not hold up the first paint."""
        if not self._warm:
            return
        tasks = api.warm_up_tasks()
        self._worker.warm(tasks[:2])
        self._rest = tasks[2:]
        self._rest_lock = threading.Lock()
        self._timer = threading.Timer(WARM_DELAY, self._warm_rest)
        self._timer.daemon = True
        self._timer.start()

    def _warm_rest(self) -> None:
        with self._rest_lock:
            rest, self._rest = self._rest, []
        if rest:
            self._worker.warm(rest)

    def start(self) -> Explorer:
        """Serve on a background (daemon) thread; the engine warms up on the worker meanwhile."""
        self._begin_warm_up()
        self._thread = threading.Thread(
            target=self.httpd.serve_forever, name="paramres-explorer", daemon=True
        )
        self._thread.start()
        return self

    def serve_forever(self) -> None:
        """Serve in this thread until interrupted."""
        self._begin_warm_up()
        try:
            self.httpd.serve_forever()
        finally:
            self.stop(wait=0)

    def stop(self, wait: float = 60.0) -> None:
        """Stop serving; the engine's worker ends after the task it is running (waited for at
        most ``wait`` s, so that no computation goes on beside the caller's)."""
        if getattr(self, "_timer", None) is not None:
            self._timer.cancel()
        self.httpd.shutdown() if self._thread is not None else None
        self.httpd.server_close()
        self._worker.stop(wait)

    def __enter__(self) -> Explorer:
        return self.start()

    def __exit__(self, *exc) -> None:
        self.stop()


def _double_only(name: str, params: dict) -> bool:
    """Requests that need no working precision: the presets, and the colour map alone (numpy,
    :func:`verify.growth.growth_map` on the double-precision Floquet route); they are answered on
    the HTTP thread at once, without waiting for the worker."""
    return name == "presets" or (name == "chart" and params.get("parts") == ["growth"])


class _Worker:
    """The one thread that runs the engine: requests first, warm-up tasks when it is idle."""

    def __init__(self):
        self._queue: queue.PriorityQueue = queue.PriorityQueue()
        self._count = itertools.count()
        #: warm-up tasks not yet run
        self.warming = 0
        self._thread = threading.Thread(target=self._loop, name="paramres-engine", daemon=True)
        self._thread.start()

    def submit(self, fn, *args, priority: int = 0) -> Future:
        future: Future = Future()
        self._queue.put((priority, next(self._count), fn, args, future))
        return future

    def warm(self, tasks) -> None:
        for task in tasks:
            self.warming += 1
            self.submit(self._warm_one, task, priority=1)

    def _warm_one(self, task) -> None:
        try:
            _quietly(task)
        finally:
            self.warming -= 1

    def stop(self, wait: float = 60.0) -> None:
        """End the thread after the task it is running (waiting for it at most ``wait`` s)."""
        self._queue.put((-1, next(self._count), None, (), None))
        if threading.current_thread() is not self._thread:
            self._thread.join(wait)

    def _loop(self) -> None:
        while True:
            _, _, fn, args, future = self._queue.get()
            if fn is None:
                return
            if not future.set_running_or_notify_cancel():
                continue
            try:
                future.set_result(fn(*args))
            except BaseException as exc:  # handed to the waiting request
                future.set_exception(exc)


def _quietly(task) -> None:
    try:
        task()
    except Exception as exc:  # pragma: no cover - warming is an optimisation only
        print(f"paramres explore: warm-up failed: {exc!r}", file=sys.stderr)
