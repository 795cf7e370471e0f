"""Each hot path against a floor written beside it, timed side by side in one run.

    python benchmarks/floors.py [--quick] [--only NAME] [--output FILE]
    paramres bench --floors [--quick] [--output FILE]

Every module ``benchmarks/floor_*.py`` defines ``scenes(quick: bool) -> list[dict]``; a scene has

``name``
    what is timed (unique over all modules);
``target``
    the largest ratio ``ours / floor`` that passes (with ``floor=None``: the largest time, in
    seconds, that passes);
``ours``, ``floor``
    zero-argument callables: the engine's path, and the best plain code written for the same job
    in the benchmark module itself (no engine code in it); ``floor=None`` for a scene whose target
    is absolute (a time the issue sets, where no plain code does the same job);
``note``
    one line: what the floor is;

and optionally ``repeat`` (a costly scene: that many single calls per sample set), ``warm``
(``False``: no warm-up call, for a scene that is cold by construction),
``extra`` (a callable whose JSON-ready result joins the row: errors, memory), ``kind``
(``"cpu"``, the default: CPU time of this process, or ``"wall"``: wall time, for scenes that run
a subprocess) and ``baseline`` (seconds per call of the same job in the
previous release, from ``benchmarks/results.json``: the table shows ``ours / baseline`` beside
the ratio, so that nothing gets slower unnoticed -- measured on another day, so the load of the
machine differs; the load of this run is printed).

The two callables are timed **alternately** (ours, floor, ours, floor, ...), each sample a batch
long enough for the clock, so that the drifts of a shared machine fall on both; the ratio is that
of the medians.  Each callable is called once before timing (warm caches: compiled forms,
imports).  The table printed has one row per scene with both medians, the ratio, the target and
``pass``/``FAIL``; :func:`run` returns the same as a JSON-ready dict (``--output`` writes it).
"""

from __future__ import annotations

import argparse
import datetime
import importlib.util
import json
import os
import statistics
import sys
import time
from pathlib import Path

__all__ = ["discover", "measure", "run", "render", "markdown", "main"]

HERE = Path(__file__).resolve().parent


def discover(only: str | None = None) -> list:
    """The ``floor_*`` modules of this directory (loaded from their files), sorted by name."""
    mods = []
    root = str(HERE.parent)
    if root not in sys.path:  # the engine's packages, when run as a script from a checkout
        sys.path.insert(0, root)
    for path in sorted(HERE.glob("floor_*.py")):
        if only and only not in path.stem:
            continue
        spec = importlib.util.spec_from_file_location(f"_paramres_{path.stem}", path)
        mod = importlib.util.module_from_spec(spec)
        spec.loader.exec_module(mod)
        mods.append(mod)
    return mods


def _clock(kind: str):
    return time.perf_counter if kind == "wall" else time.process_time


def _call_time(fn, clock) -> float:
    """The time of one call of ``fn``."""
    t = clock()
    fn()
    dt = clock() - t
    return dt if dt > 0 else 1e-7


def _batch(dt: float, min_time: float) -> int:
    """Calls per sample so that one sample of calls taking ``dt`` lasts about ``min_time``."""
    return max(1, min(10_000, int(min_time / dt)))


#: a sample of calls shorter than ``min_time / SPLIT`` each is split: ``SPLIT`` times as many
#: samples, each a ``SPLIT``-th as long (the same time in all)
SPLIT = 5


def measure(
    ours, floor, *, samples: int = 9, kind: str = "cpu", min_time: float = 0.02, warm: bool = True
):
    """Medians (seconds per call) of ``ours`` and ``floor``, timed alternately.  ``floor=None``
    (a scene whose target is absolute, in seconds): ``ours`` alone, and ``None`` for the floor.
    ``warm=False``: no call before the samples (a scene that is cold by construction, e.g. a
    fresh process with an empty cache, gains nothing from one).

    Where every call is shorter than ``min_time / SPLIT``, the same time is spent in ``SPLIT``
    times as many samples, each ``SPLIT`` times shorter: ours and the floor then alternate five
    times as often, so that a change of the shared machine's load falls on both more evenly.  In
    six measurements each, alternately, of three friction scenes: 1.89-1.92 against 1.89-1.97
    (``m = 0.9``), 1.85-1.93 against 1.49-1.93 (torsion), 1.69-1.94 against 1.84-2.08 (the custom
    system), with medians 0.02-0.08 apart."""
    clock = _clock(kind)
    pairs = [(ours, [])] + ([] if floor is None else [(floor, [])])
    for fn, _ in pairs if warm else ():
        fn()  # warm
    if min_time > 0:
        dts = [_call_time(fn, clock) for fn, _ in pairs]
        if max(dts) * SPLIT < min_time:
            samples, min_time = samples * SPLIT, min_time / SPLIT
        ks = [_batch(dt, min_time) for dt in dts]
    else:
        ks = [1] * len(pairs)
    for _ in range(samples):
        for (fn, out), k in zip(pairs, ks, strict=True):
            t = clock()
            for _ in range(k):
                fn()
            out.append((clock() - t) / k)
    meds = [statistics.median(out) for _, out in pairs]
    return meds[0], (meds[1] if floor is not None else None)


def _machine() -> dict:
    """:func:`reports.benchmark.machine` and the load of this run."""
    from reports.benchmark import machine

    load = round(os.getloadavg()[0], 1) if hasattr(os, "getloadavg") else None
    return {**machine(), "load": load}


def run(quick: bool = False, only: str | None = None, progress=None) -> dict:
    """Every scene of every ``floor_*`` module, measured; a JSON-ready dict."""
    t0 = time.perf_counter()
    scenes = []
    mods = discover(only)
    for mod in mods:
        for sc in mod.scenes(quick):
            scenes.append((mod.__name__.removeprefix("_paramres_"), sc))
    rows = []
    items = progress(scenes) if progress else scenes
    for module, sc in items:
        kind = sc.get("kind", "cpu")
        repeat = sc.get("repeat")  # a costly scene: that many single calls
        ours_s, floor_s = measure(
            sc["ours"],
            sc["floor"],
            samples=repeat or (5 if quick else 9),
            kind=kind,
            min_time=0 if repeat else (0.01 if quick else 0.03),
            warm=sc.get("warm", True),
        )
        # no floor: the target is a time in seconds, and the "ratio" is ours against it
        ratio = ours_s / (floor_s if floor_s is not None else sc["target"])
        absolute = floor_s is None
        rows.append(
            {
                "module": module,
                "name": sc["name"],
                "ours_seconds": ours_s,
                "floor_seconds": floor_s,
                "ratio": ratio,
                "target": sc["target"],
                "passed": ratio <= 1 if absolute else ratio <= sc["target"],
                "target_is_seconds": absolute,
                "clock": kind,
                "note": sc.get("note", ""),
                "baseline_seconds": sc.get("baseline"),
                "vs_previous": None if not sc.get("baseline") else ours_s / sc["baseline"],
                **({"extra": sc["extra"]()} if callable(sc.get("extra")) else {}),
            }
        )
    notes = []
    for mod in mods:  # a module may sum up its own rows (e.g. how time grows with digits)
        if hasattr(mod, "summary"):
            name = mod.__name__.removeprefix("_paramres_")
            notes += mod.summary([r for r in rows if r["module"] == name])
    return {
        "generated_by": "generated by paramres bench --floors -- do not edit",
        "notes": notes,
        "date": datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%d %H:%M UTC"),
        "machine": _machine(),
        "quick": quick,
        "seconds": time.perf_counter() - t0,
        "time_unit": "seconds per call, median of alternate samples",
        "scenes": rows,
    }


def _fmt_time(s: float) -> str:
    for unit, f in (("s", 1), ("ms", 1e-3), ("us", 1e-6)):
        if s >= f:
            return f"{s / f:.3g} {unit}"
    return f"{s / 1e-9:.3g} ns"


def _digits_note(m: dict) -> str:
    """How the tables' digits were written in the run: ``verify._digits`` compiled, or the Python
    loop alone (nothing for a run recorded before this was noted)."""
    if "compiled digits" not in m:
        return ""
    return ", compiled digits" if m["compiled digits"] else ", digits in Python (not compiled)"


def render(doc: dict) -> str:
    """The table of ratios, one line per scene."""
    m = doc["machine"]
    head = (
        f"paramres floors{' --quick' if doc['quick'] else ''}: {doc['date']}, {m['cpu']}, "
        f"{m['cores']} cores (load {m['load']}), Python {m['python']}{_digits_note(m)}; "
        f"{doc['seconds']:.0f} s\n"
        "ours and the floor timed alternately; medians per call (CPU time unless marked wall)\n"
    )
    w = max([len(r["name"]) for r in doc["scenes"]] + [5])
    lines = [
        f"{'scene':<{w}}  {'ours':>10}  {'floor':>10}  {'ratio':>6}  {'target':>6}  result"
        "   vs previous"
    ]
    for r in doc["scenes"]:
        mark = " (wall)" if r["clock"] == "wall" else ""
        absolute = r.get("target_is_seconds")
        floor = "-" if absolute else _fmt_time(r["floor_seconds"])
        target = f"{r['target']:g} s" if absolute else f"{r['target']:.2f}"
        lines.append(
            f"{r['name']:<{w}}  {_fmt_time(r['ours_seconds']):>10}  "
            f"{floor:>10}  {r['ratio']:>6.2f}  {target:>6}  "
            f"{'pass' if r['passed'] else 'FAIL'}{mark:7}"
            + ("" if r.get("vs_previous") is None else f"  {r['vs_previous']:.2f}")
        )
    failed = sum(not r["passed"] for r in doc["scenes"])
    tail = f"\n{len(doc['scenes']) - failed} of {len(doc['scenes'])} scenes within target\n"
    tail += "".join(f"{line}\n" for line in doc.get("notes", []))
    return head + "\n".join(lines) + tail


def markdown(doc: dict) -> str:
    """The README's table of a run (``--markdown FILE``: of a run written by ``--output``): its
    date and machine, then one row per scene, then the summary notes."""
    m = doc["machine"]
    versions = ", ".join(
        f"{k} {m[k]}" for k in ("python", "numpy", "mpmath", "python-flint") if m.get(k)
    ) + _digits_note(m)
    head = (
        f"Measured {doc['date']} (`paramres bench --floors{' --quick' if doc['quick'] else ''}`, "
        f"{doc['seconds']:.0f} s) on {m['cpu']}, {m['cores']} cores, load {m['load']}; "
        f"{versions}.\n\n"
        "| scene | ours | floor | ratio | target | result |\n|---|---:|---:|---:|---:|---|\n"
    )
    rows = []
    for r in doc["scenes"]:
        absolute = r.get("target_is_seconds")
        floor = "—" if absolute else _fmt_time(r["floor_seconds"]).replace("us", "µs")
        target = f"{r['target']:g} s" if absolute else f"{r['target']:g}"
        ratio = "—" if absolute else f"{r['ratio']:.2f}"
        result = ("pass" if r["passed"] else "**fails**") + (
            " (wall)" if r["clock"] == "wall" else ""
        )
        ours = _fmt_time(r["ours_seconds"]).replace("us", "µs")
        rows.append(f"| {r['name']} | {ours} | {floor} | {ratio} | {target} | {result} |")
    notes = "".join(f"\n- {line}" for line in doc.get("notes", []))
    return head + "\n".join(rows) + ("\n" + notes if notes else "") + "\n"


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--quick", action="store_true")
    ap.add_argument("--only", help="only the floor_* modules whose name contains this")
    ap.add_argument("--output", help="write the JSON here")
    ap.add_argument(
        "--markdown",
        metavar="FILE",
        help="print the README's table of a run written by --output (and measure nothing)",
    )
    a = ap.parse_args(argv)
    if a.markdown:
        print(markdown(json.loads(Path(a.markdown).read_text())), end="")
        return 0
    doc = run(a.quick, a.only)
    print(render(doc), end="")
    if a.output:
        tmp = Path(a.output).with_suffix(".tmp")
        tmp.write_text(json.dumps(doc, indent=2) + "\n")
        os.replace(tmp, a.output)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
