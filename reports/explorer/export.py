"""``paramres explore --export DIR``: a static copy of the explorer for any web server.

``DIR/index.html`` and ``DIR/static/`` are the page (with the generated JavaScript written out),
``DIR/data/<preset>.json`` the chart of every preset (``/api/chart`` answers, computed now) and
``DIR/data/presets.json`` their list.  In the copy a click runs the linear model in the page
(the generated propagator, double precision) and says that its numbers are not certified.
The folder is written beside ``DIR`` and renamed into place, so nothing is half-written.
"""

from __future__ import annotations

import json
import os
import shutil
import tempfile
from pathlib import Path

from paramres.inputs import InputError

from . import api
from .server import static_file

__all__ = ["export", "STATIC_FILES"]

#: the page's files
STATIC_FILES = ("app.js", "style.css", "generated.js")


def export(target, *, presets=None) -> Path:
    """Write the static copy to ``target`` (a new or empty directory); returns its path."""
    target = Path(target)
    if target.exists() and (not target.is_dir() or any(target.iterdir())):
        raise InputError(f"--export {target}: exists and is not an empty directory")
    parent = target.resolve().parent
    if not parent.is_dir() or not os.access(parent, os.W_OK):
        raise InputError(f"--export {target}: cannot write in {parent}")
    chosen = api.PRESETS if presets is None else [p for p in api.PRESETS if p["id"] in presets]
    try:  # tried for real: os.access says yes to root even where nothing can be made (/proc)
        tmp = Path(tempfile.mkdtemp(prefix=".paramres-export-", dir=parent))
    except OSError as exc:
        raise InputError(
            f"--export {target}: cannot write in {parent}: {exc.strerror or exc}"
        ) from None
    try:
        (tmp / "static").mkdir()
        (tmp / "data").mkdir()
        page = static_file("index.html").decode()
        page = page.replace("<!--STATIC-->", "<script>window.PARAMRES_STATIC = true;</script>")
        (tmp / "index.html").write_text(page, encoding="utf-8")
        for name in STATIC_FILES:
            (tmp / "static" / name).write_bytes(static_file(name))
        for p in chosen:
            doc = api.chart({k: [str(v)] for k, v in p["chart"].items()})
            (tmp / "data" / f"{p['id']}.json").write_text(
                json.dumps(doc, allow_nan=False, separators=(",", ":")), encoding="utf-8"
            )
        (tmp / "data" / "presets.json").write_text(
            json.dumps({"presets": chosen}, ensure_ascii=False), encoding="utf-8"
        )
        if target.exists():
            target.rmdir()
        tmp.rename(target)
    except BaseException:
        shutil.rmtree(tmp, ignore_errors=True)
        raise
    return target
