"""A disk cache for finished work: derivations, and the report's sections and figures.

An entry is keyed by its name and by a *fingerprint* of everything that could change it: the
source of the packages it depends on and the versions of Python and of the libraries it computes
with.  Editing a source file, or upgrading sympy, invalidates every entry that depends on it, so a
cached result is always what the current code would compute.  Entries are JSON read without
running code (:mod:`analytic.cachecodec`), authenticated with an HMAC whose key lives in the cache
directory (readable by its owner only), and written temp-then-rename; an entry that is damaged,
forged or unreadable is dropped with one warning line and computed again; only the current
fingerprint's entries are kept.

The directory is ``$PARAMRES_CACHE_DIR``, else ``~/.cache/paramres``; ``PARAMRES_NO_CACHE=1``
turns the disk cache off (the in-process caches stay).  :func:`cache_dir_override` points it
elsewhere (or turns it off) for the duration of a block, so that one ``--cache DIR`` or
``--no-cache`` governs a whole run.
"""

from __future__ import annotations

import functools
import hashlib
import hmac
import importlib.metadata
import json
import os
import re
import secrets
import shutil
import stat
import sys
import tempfile
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from pathlib import Path
from typing import TypeVar

from . import cachecodec

__all__ = ["Cache", "EntryError", "cache_dir", "cache_dir_override", "disk_cached", "fingerprint"]

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


#: the format of an entry file (changes invalidate every entry)
FORMAT = "paramres-cache/2"
#: the file in each cache directory that holds its key
KEY_FILE = "key"


def warn(message: str) -> None:
    """One line on stderr."""
    print(f"paramres: warning: {message}", file=sys.stderr, flush=True)


class EntryError(ValueError):
    """A cache entry that cannot be trusted: unreadable, malformed, or failing its check."""


def _atomic_write(path: Path, data: bytes, mode: int = 0o600) -> None:
    """Write ``data`` to ``path`` through a temporary file in the same directory and a rename, so
    that a reader sees either the old file or the whole new one."""
    path.parent.mkdir(parents=True, exist_ok=True)
    fd, tmp = tempfile.mkstemp(prefix=f".{path.name}.", dir=path.parent)
    try:
        os.fchmod(fd, mode)
        with os.fdopen(fd, "wb") as fh:
            fh.write(data)
            fh.flush()
            os.fsync(fh.fileno())
        os.replace(tmp, path)
    except BaseException:
        try:
            os.unlink(tmp)
        except OSError:
            pass
        raise


class Cache:
    """``get(name, make)``: the cached value of ``make()`` under ``name``, in
    ``directory/<fingerprint>/<name>.json``; ``directory=None`` disables the cache (every call
    computes).  ``packages`` are those whose sources the values depend on.

    An entry is JSON (see :mod:`analytic.cachecodec`: reading it runs no code) with an
    HMAC-SHA256 over its name, fingerprint and content, keyed by a random secret in
    ``directory/key`` (created with permissions 0600).  On load the tag is checked first; an entry
    that fails the check, or cannot be read or parsed, is dropped, computed again and rewritten,
    with one warning line on stderr.  A key file that is not a regular file owned by this user and
    readable by no one else is not trusted: it is replaced (which invalidates every entry signed
    with it).  Values that cannot be stored faithfully (a type outside the codec, or a sympy
    expression that does not read back identical) are simply not cached.
    """

    def __init__(
        self,
        directory: str | os.PathLike | None,
        packages: tuple[str, ...] = ("analytic", "paramres"),
    ):
        self.directory = None if directory is None else Path(directory)
        self.packages = tuple(packages)
        self.hits: list[str] = []
        self.misses: list[str] = []
        self._secret: bytes | None = None
        self._secret_loaded = False

    @property
    def enabled(self) -> bool:
        return self.directory is not None

    def _key(self) -> str:
        return fingerprint(self.packages)[:20]

    def path(self, name: str) -> Path:
        """The file of the entry ``name``."""
        assert self.directory is not None
        return self.directory / self._key() / f"{re.sub(r'[^A-Za-z0-9_.-]', '_', name)}.json"

    # -- the key ----------------------------------------------------------------------------

    def _load_secret(self) -> bytes | None:
        """The key of this directory, or ``None`` if there is none or it is not trustworthy."""
        assert self.directory is not None
        path = self.directory / KEY_FILE
        try:
            fd = os.open(path, os.O_RDONLY | getattr(os, "O_NOFOLLOW", 0))
        except OSError:
            return None
        try:
            st = os.fstat(fd)
            trusted = (
                stat.S_ISREG(st.st_mode)
                and st.st_mode & 0o077 == 0
                and (not hasattr(os, "getuid") or st.st_uid == os.getuid())
            )
            data = os.read(fd, 4096)
        finally:
            os.close(fd)
        if not trusted:
            warn(f"cache key {path} is not private to this user; replacing it")
            return None
        if not re.fullmatch(rb"[0-9a-f]{64}\n?", data):
            warn(f"cache key {path} is malformed; replacing it")
            return None
        return bytes.fromhex(data[:64].decode("ascii"))

    def _secret_key(self, *, create: bool) -> bytes | None:
        if not self._secret_loaded:
            self._secret = self._load_secret()
            self._secret_loaded = True
        if self._secret is None and create:
            assert self.directory is not None
            secret = secrets.token_bytes(32)
            _atomic_write(self.directory / KEY_FILE, secret.hex().encode() + b"\n", 0o600)
            self._secret = secret
        return self._secret

    def ensure_key(self) -> None:
        """Create the directory's key now if it has none (before several processes write entries
        into one directory, so that they all sign with the same key)."""
        if self.directory is not None:
            self._secret_key(create=True)

    def _tag(self, secret: bytes, name: str, body: bytes) -> str:
        msg = b"\0".join((FORMAT.encode(), name.encode(), self._key().encode(), body))
        return hmac.new(secret, msg, hashlib.sha256).hexdigest()

    # -- reading and writing ----------------------------------------------------------------

    def _read(self, name: str, path: Path):
        """The value stored in ``path``; ``FileNotFoundError`` if there is none, :class:`EntryError`
        if it cannot be trusted."""
        with open(path, "rb") as fh:
            raw = fh.read()
        header, sep, body = raw.partition(b"\n")
        try:
            head = json.loads(header.decode("ascii"))
        except (UnicodeDecodeError, ValueError):
            raise EntryError("unreadable header") from None
        if (
            not sep
            or type(head) is not dict
            or set(head) != {"format", "name", "fingerprint", "hmac"}
            or head["format"] != FORMAT
            or head["name"] != name
            or head["fingerprint"] != self._key()
            or not isinstance(head["hmac"], str)
        ):
            raise EntryError("malformed header")
        secret = self._secret_key(create=False)
        if secret is None:
            raise EntryError("no trusted key to check it with")
        if not hmac.compare_digest(head["hmac"], self._tag(secret, name, body)):
            raise EntryError("its authentication tag does not match its content")
        try:
            return cachecodec.decode(json.loads(body.decode("utf-8")))
        except (UnicodeDecodeError, ValueError, RecursionError):
            raise EntryError("its content cannot be parsed") from None

    def _encode(self, value) -> bytes | None:
        """The stored form of ``value``, or ``None`` if it cannot be stored faithfully."""
        try:
            data = cachecodec.encode(value)
            if cachecodec.encode(cachecodec.decode(data)) != data:
                return None
            return json.dumps(data, separators=(",", ":"), ensure_ascii=True).encode("ascii")
        except (TypeError, ValueError, RecursionError):
            return None

    def get(self, name: str, make: Callable[[], T]) -> T:
        if self.directory is None:
            self.misses.append(name)
            return make()
        path = self.path(name)
        try:
            value = self._read(name, path)
            self.hits.append(name)
            return value
        except FileNotFoundError:
            pass
        except EntryError as exc:
            warn(f"cache entry {path} dropped ({exc}); computing it again")
        except OSError as exc:
            warn(f"cache entry {path} unreadable ({exc.strerror or exc}); computing it again")
        value = make()
        self.misses.append(name)
        body = self._encode(value)
        if body is None:
            return value
        try:
            self._prune()
            secret = self._secret_key(create=True)
            assert secret is not None
            header = json.dumps(
                {
                    "format": FORMAT,
                    "name": name,
                    "fingerprint": self._key(),
                    "hmac": self._tag(secret, name, body),
                },
                separators=(",", ":"),
            )
            _atomic_write(path, header.encode("ascii") + b"\n" + body)
        except OSError:
            pass  # an unwritable directory is not an error
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
    the source of :mod:`analytic` (and :mod:`paramres`, whose input checks it uses);
    ``fn.uncached`` is the function itself."""

    def deco(fn):
        @functools.wraps(fn)
        def wrapper():
            base = cache_dir()
            return Cache(None if base is None else base / "analytic").get(name, fn)

        wrapper.uncached = fn
        return wrapper

    return deco
