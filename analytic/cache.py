"""A disk cache for finished work: derivations, and the report's sections and figures.

An entry is keyed by its name and by a *fingerprint* of everything that could change it: the
source of the packages it depends on and the versions of Python and of the libraries it computes
with.  Editing a source file, or upgrading sympy, invalidates every entry that depends on it, so a
cached result is always what the current code would compute.  Entries are pickles written
temp-then-rename; an unreadable entry is computed again; only the current fingerprint's entries are
kept.

The directory is ``$PARAMRES_CACHE_DIR``, else ``~/.cache/paramres``; ``PARAMRES_NO_CACHE=1``
turns the disk cache off (the in-process caches stay).  :func:`cache_dir_override` points it
elsewhere (or turns it off) for the duration of a block, so that one ``--cache DIR`` or
``--no-cache`` governs a whole run.
"""

from __future__ import annotations

import functools
import hashlib
import importlib.metadata
import os
import pickle
import re
import shutil
import sys
import tempfile
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from pathlib import Path
from typing import TypeVar

__all__ = ["Cache", "cache_dir", "cache_dir_override", "disk_cached", "fingerprint"]

T = TypeVar("T")

#: the libraries whose versions enter every fingerprint
LIBRARIES = ("sympy", "mpmath", "numpy", "scipy", "matplotlib", "python-flint")
_ROOT = Path(__file__).resolve().parent.parent


def cache_dir() -> Path | None:
    """``$PARAMRES_CACHE_DIR`` or ``~/.cache/paramres``; ``None`` when ``PARAMRES_NO_CACHE=1``."""
    if os.environ.get("PARAMRES_NO_CACHE") == "1":
        return None
    base = os.environ.get("PARAMRES_CACHE_DIR")
    return Path(base) if base else Path.home() / ".cache" / "paramres"


@contextmanager
def cache_dir_override(directory: str | os.PathLike | None) -> Iterator[Path | None]:
    """Within the block the disk cache lives in ``directory``, or is off when it is ``None``;
    the environment is restored afterwards.  Yields the directory."""
    keys = ("PARAMRES_CACHE_DIR", "PARAMRES_NO_CACHE")
    saved = {k: os.environ.get(k) for k in keys}
    try:
        if directory is None:
            os.environ["PARAMRES_NO_CACHE"] = "1"
        else:
            os.environ.pop("PARAMRES_NO_CACHE", None)
            os.environ["PARAMRES_CACHE_DIR"] = str(directory)
        yield None if directory is None else Path(directory)
    finally:
        for k, v in saved.items():
            if v is None:
                os.environ.pop(k, None)
            else:
                os.environ[k] = v


@functools.cache
def fingerprint(packages: tuple[str, ...] = ("analytic",)) -> str:
    """SHA-256 over the sources of ``packages`` (sorted paths and contents), Python's version and
    the versions of :data:`LIBRARIES`."""
    h = hashlib.sha256()
    h.update(sys.version.encode())
    for lib in LIBRARIES:
        try:
            version = importlib.metadata.version(lib)
        except importlib.metadata.PackageNotFoundError:
            version = "-"
        h.update(f"{lib}={version}\n".encode())
    for pkg in packages:
        for path in sorted((_ROOT / pkg).rglob("*.py")):
            h.update(str(path.relative_to(_ROOT)).encode() + b"\0")
            h.update(path.read_bytes() + b"\0")
    return h.hexdigest()


class Cache:
    """``get(name, make)``: the cached value of ``make()`` under ``name``, in
    ``directory/<fingerprint>/``; ``directory=None`` disables the cache (every call computes).
    ``packages`` are those whose sources the values depend on.  Values must be picklable."""

    def __init__(
        self, directory: str | os.PathLike | None, packages: tuple[str, ...] = ("analytic",)
    ):
        self.directory = None if directory is None else Path(directory)
        self.packages = tuple(packages)
        self.hits: list[str] = []
        self.misses: list[str] = []

    @property
    def enabled(self) -> bool:
        return self.directory is not None

    def _key(self) -> str:
        return fingerprint(self.packages)[:20]

    def get(self, name: str, make: Callable[[], T]) -> T:
        if self.directory is None:
            self.misses.append(name)
            return make()
        path = self.directory / self._key() / f"{re.sub(r'[^A-Za-z0-9_.-]', '_', name)}.pickle"
        try:
            with open(path, "rb") as fh:
                value = pickle.load(fh)
            self.hits.append(name)
            return value
        except (OSError, pickle.UnpicklingError, EOFError, AttributeError, ImportError, TypeError):
            pass  # absent, damaged or stale: compute again
        value = make()
        self.misses.append(name)
        try:
            self._prune()
            path.parent.mkdir(parents=True, exist_ok=True)
            fd, tmp = tempfile.mkstemp(prefix=f".{path.name}.", dir=path.parent)
            try:
                with os.fdopen(fd, "wb") as fh:
                    pickle.dump(value, fh, protocol=pickle.HIGHEST_PROTOCOL)
                os.replace(tmp, path)
            except BaseException:
                os.unlink(tmp)
                raise
        except (OSError, pickle.PicklingError, TypeError, AttributeError):
            pass  # an unwritable directory or an unpicklable value is not an error
        return value

    def _prune(self) -> None:
        """Remove the entries of other fingerprints."""
        assert self.directory is not None
        if not self.directory.is_dir():
            return
        keep = self._key()
        for child in self.directory.iterdir():
            if child.is_dir() and child.name != keep and re.fullmatch(r"[0-9a-f]{20}", child.name):
                shutil.rmtree(child, ignore_errors=True)


def disk_cached(name: str):
    """Cache a function of no arguments (a finished derivation) on disk under ``name``, keyed by
    the source of :mod:`analytic`; ``fn.uncached`` is the function itself."""

    def deco(fn):
        @functools.wraps(fn)
        def wrapper():
            base = cache_dir()
            return Cache(None if base is None else base / "analytic").get(name, fn)

        wrapper.uncached = fn
        return wrapper

    return deco
