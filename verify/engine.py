"""The parallel engine: tasks run on a ``dask.distributed`` cluster, results come back as they
finish.

:func:`cluster` opens the place to run: an existing cluster (a scheduler address such as
``tcp://host:8786``, or a :class:`distributed.Client`), or by default a
:class:`distributed.LocalCluster` of worker *processes* sized to the machine (one single-threaded
worker per core: the certified solver holds the GIL).  An address that does not answer within
:data:`CONNECT_TIMEOUT` seconds is refused with an :class:`~verify.inputs.InputError`.
:func:`as_finished` submits a function over a list of tasks and yields ``(index, result)`` as
each finishes; :func:`ordered` collects them in task order (``paramres table --jobs``).

The tasks are plain module-level functions of picklable arguments (exact ``Fraction`` s, numbers,
:class:`analytic.system.System` values): a worker of a remote cluster needs paramres installed,
nothing else.
"""

from __future__ import annotations

import os
from collections.abc import Callable, Iterator, Sequence
from contextlib import contextmanager

from .inputs import InputError

__all__ = [
    "cluster",
    "as_finished",
    "ordered",
    "CONNECT_TIMEOUT",
    "STARTUP_SECONDS",
    "MAX_WORKERS",
    "default_workers",
]

#: seconds to wait for an existing scheduler before refusing its address
CONNECT_TIMEOUT = 5
#: a local cluster takes seconds to start (worker processes import the engine): work estimated
#: below this many CPU seconds runs in this process instead, unless workers are asked for
STARTUP_SECONDS = 5.0
#: the most local worker processes (as ``--jobs`` of ``table`` and ``report``): each is a Python
#: process holding the engine, and a thousand on a small machine only contend and leak
MAX_WORKERS = 64


def default_workers() -> int:
    """One worker per core this process may use."""
    try:
        return max(1, len(os.sched_getaffinity(0)))
    except AttributeError:  # pragma: no cover - not Linux
        return max(1, os.cpu_count() or 1)


@contextmanager
def cluster(
    scheduler=None,
    workers: int | None = None,
    *,
    work_seconds=None,
    small_here: bool = False,
):
    """A :class:`distributed.Client`: to ``scheduler`` (an address or a ``Client``, used as is and
    left open), or to a new local cluster of ``workers`` processes (default: one per core), closed
    on exit.  ``None`` (run in this process) when no scheduler is given and either ``workers`` is
    1 or the work is estimated (``work_seconds``) below :data:`STARTUP_SECONDS` -- with
    ``workers`` left to the default, or with any ``workers`` if ``small_here``."""
    import logging

    small = work_seconds is not None and work_seconds < STARTUP_SECONDS
    if scheduler is None and (workers == 1 or (small and (workers is None or small_here))):
        yield None
        return
    from distributed import Client, LocalCluster

    if scheduler is not None and hasattr(scheduler, "submit"):
        yield scheduler
        return
    if scheduler is not None:
        address = str(scheduler).strip()
        if not address or "\0" in address:
            raise InputError(f"--scheduler {scheduler!r} is not a scheduler address")
        try:
            client = Client(address, timeout=CONNECT_TIMEOUT, set_as_default=False)
        except (OSError, TimeoutError, ValueError, TypeError) as exc:
            reason = " ".join(str(exc).split())[:200] or type(exc).__name__
            raise InputError(
                f"--scheduler {address!r}: no dask scheduler answers there within "
                f"{CONNECT_TIMEOUT} s ({reason})"
            ) from None
        try:
            yield client
        finally:
            client.close()
        return
    n = default_workers() if workers is None else int(workers)
    if not 1 <= n <= MAX_WORKERS:
        raise InputError(f"workers {workers} is outside the allowed range 1 to {MAX_WORKERS}")
    quiet = logging.getLogger("distributed")
    level = quiet.level
    quiet.setLevel(logging.ERROR)
    try:
        with (
            LocalCluster(
                n_workers=n,
                threads_per_worker=1,
                processes=True,  # never threads: mpmath's working precision is process-wide
                dashboard_address=None,
                silence_logs=logging.ERROR,
            ) as local,
            Client(local, set_as_default=False) as client,
        ):
            yield client
    finally:
        quiet.setLevel(level)


def as_finished(client, fn: Callable, tasks: Sequence) -> Iterator[tuple[int, object]]:
    """``(i, fn(tasks[i]))`` in the order the tasks finish (``client`` ``None``: one after the
    other in this process).  A task that raises re-raises here (the other tasks are
    cancelled)."""
    if client is None:
        for i, task in enumerate(tasks):
            yield i, fn(task)
        return
    from distributed import as_completed

    futures = client.map(fn, list(tasks), pure=False)
    index = {f.key: i for i, f in enumerate(futures)}
    try:
        for fut in as_completed(futures, loop=client.loop):
            yield index[fut.key], fut.result()
            fut.release()
    finally:
        client.cancel([f for f in futures if not f.done()])


def ordered(client, fn: Callable, tasks: Sequence, progress=None) -> list:
    """``[fn(t) for t in tasks]`` computed on ``client``; ``progress`` wraps the stream of
    finished tasks (e.g. :func:`reports.output.progress`)."""
    out: list = [None] * len(tasks)
    stream = as_finished(client, fn, tasks)
    if progress is not None:
        stream = progress(stream)
    for i, value in stream:
        out[i] = value
    return out
