"""A disk cache for finished derivations, so that a second run does not redo the symbolic work.

The key of every entry includes a hash of the source of the whole :mod:`analytic` package and the
versions of Python and sympy, so an edit to any derivation invalidates everything derived before it.
Entries are pickles written temp-then-rename; an unreadable entry is recomputed.  The directory is
``$PARAMRES_CACHE_DIR`` or ``~/.cache/paramres``; ``PARAMRES_NO_CACHE=1`` turns the disk cache off
(the in-process cache of each function stays).
"""

from __future__ import annotations

import functools
import hashlib
import os
import pickle
import sys
import tempfile
from pathlib import Path

import sympy

__all__ = ["disk_cached", "cache_dir", "source_hash"]


@functools.lru_cache(maxsize=1)
def source_hash() -> str:
    """Hash of every ``.py`` file of :mod:`analytic`, Python's and sympy's versions."""
    h = hashlib.sha256()
    here = Path(__file__).resolve().parent
    for path in sorted(here.glob("*.py")):
        h.update(path.name.encode())
        h.update(path.read_bytes())
    h.update(sys.version.encode())
    h.update(sympy.__version__.encode())
    return h.hexdigest()[:20]


def cache_dir() -> Path | None:
    if os.environ.get("PARAMRES_NO_CACHE") == "1":
        return None
    base = os.environ.get("PARAMRES_CACHE_DIR")
    return Path(base) if base else Path.home() / ".cache" / "paramres"


def disk_cached(name: str):
    """Cache a function of no arguments (a finished derivation) on disk under ``name``."""

    def deco(fn):
        @functools.wraps(fn)
        def wrapper():
            folder = cache_dir()
            if folder is None:
                return fn()
            path = folder / f"{name}-{source_hash()}.pickle"
            try:
                with open(path, "rb") as fh:
                    return pickle.load(fh)
            except (
                OSError,
                pickle.UnpicklingError,
                EOFError,
                AttributeError,
                ImportError,
                TypeError,
            ):
                pass
            value = fn()
            try:
                folder.mkdir(parents=True, exist_ok=True)
                fd, tmp = tempfile.mkstemp(prefix=f".{name}.", dir=folder)
                with os.fdopen(fd, "wb") as fh:
                    pickle.dump(value, fh, protocol=pickle.HIGHEST_PROTOCOL)
                os.replace(tmp, path)
            except (OSError, pickle.PicklingError, TypeError, AttributeError):
                try:
                    os.unlink(tmp)  # type: ignore[possibly-undefined]
                except (OSError, UnboundLocalError):
                    pass
            return value

        wrapper.uncached = fn
        return wrapper

    return deco
