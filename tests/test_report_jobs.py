"""The report built with a second process (``jobs=2``) is the same document as the one built in
one process, and a cold build in two processes leaves a cache the next build reads without a
warning (both processes sign with the directory's one key)."""

from __future__ import annotations

import pytest

import reports.report as report
from analytic.cache import Cache
from reports.report import assemble
from reports.sections import Context

SECTIONS = ("introduction", "model", "closings")
PACKAGES = ("analytic", "verify", "reports", "paramres")


@pytest.fixture
def second_builds_closings(monkeypatch):
    """A cheap section in the second process, and one that waits for it (the real split sends
    the catalogue and the stitching section, which take minutes)."""
    monkeypatch.setattr(report, "SECOND_PROCESS", ("closings",))
    monkeypatch.setattr(report, "AFTER_SECOND", ("model",))


def test_two_processes_give_the_same_document(second_builds_closings):
    one = assemble(Context(log=lambda m: None), SECTIONS, jobs=1)
    messages: list[str] = []
    two = assemble(Context(log=messages.append), SECTIONS, jobs=2)
    assert two.files == one.files
    assert [name for name, _ in two.timings] == list(SECTIONS)
    assert any("(second process)" in m and "Closings" in m for m in messages)
    # the section waiting for the second process is built after it is done
    done = next(k for k, m in enumerate(messages) if m.endswith("(second process)"))
    model = next(k for k, m in enumerate(messages) if "The model" in m)
    assert model > done


def test_cold_build_in_two_processes_leaves_a_cache_read_without_warnings(
    second_builds_closings, tmp_path, capsys
):
    def build(jobs):
        ctx = Context(cache=Cache(tmp_path / "report", PACKAGES), log=lambda m: None)
        return assemble(ctx, SECTIONS, jobs=jobs), ctx.cache

    cold, _ = build(2)
    capsys.readouterr()
    warm, cache = build(1)
    assert warm.files == cold.files
    assert {"section-model", "section-closings"} <= set(cache.hits)
    assert capsys.readouterr().err == ""


def test_one_process_when_everything_is_cached(second_builds_closings, tmp_path):
    ctx = Context(cache=Cache(tmp_path / "report", PACKAGES), log=lambda m: None)
    assemble(ctx, SECTIONS, jobs=2)
    messages: list[str] = []
    ctx = Context(cache=Cache(tmp_path / "report", PACKAGES), log=messages.append)
    assemble(ctx, SECTIONS, jobs=2)
    assert not any("second process" in m for m in messages)


def test_second_process_takes_the_shared_sections_left():
    """After its own sections the second process builds the sections of the shared list not yet
    taken (here: none of its own, the first of two already taken by the first process), and
    hands back what it built, the same as the first process builds it."""
    import multiprocessing

    from reports.i18n import language
    from reports.latex import DEFAULT

    mp = multiprocessing.get_context("spawn")
    counter = mp.Value("i", 1)
    receive, send = mp.Pipe(duplex=False)
    queue = ("model", "closings")
    report._second_process(send, counter, DEFAULT, None, PACKAGES, (), queue, "en")
    kind, parts, _, _ = receive.recv()
    assert kind == "ok"
    assert set(parts) == {"closings"}
    assert counter.value == len(queue)
    with language("en"):
        alone = report._build(Context(log=lambda m: None), "closings", "en")
    assert parts["closings"][0] == alone
