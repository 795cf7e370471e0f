"""The disk cache cannot run code and cannot lie: entries are JSON read by a restricted decoder
(no pickle, no eval/sympify of stored text), authenticated by an HMAC with a private key, and an
entry that is damaged, truncated, garbage, forged or stale is dropped with one warning line and
computed again.  The commands that read the cache give exactly the output they give without it.

References: the value each ``make`` computes (the no-cache result), and the no-cache output of the
same command.
"""

from __future__ import annotations

import json
import os
import stat
from fractions import Fraction

import mpmath
import numpy as np
import pytest
import sympy as sp

from analytic import cachecodec
from analytic.cache import KEY_FILE, Cache, cache_dir_override
from analytic.cachecodec import DecodeError, decode, encode, parse_srepr
from analytic.identity import Verdict
from analytic.model import Damping
from analytic.reductions import Step

# ------------------------------------------------------------------------------------------------
# the codec


def _sample():
    t, m = sp.symbols("t m", positive=True)
    f = sp.Function("phi")
    rhs = -m * sp.cos(sp.pi * t / 3) * f(t) + sp.Rational(3, 7) + sp.Float(0.1)
    expr = sp.Eq(f(t).diff(t), rhs)
    return {
        "none": None,
        "flags": [True, False],
        "int": -(10**40),
        "float": (0.1, float("inf"), -0.0),
        "text": "unicode: ω₀ — ∓",
        "bytes": bytes(range(256)),
        "fraction": Fraction(-3, 5),
        "mpf": mpmath.mpf("0.1") * mpmath.pi,
        "mpc": mpmath.mpc(1, -2) / 3,
        "array": np.linspace(0, 1, 7).reshape(7, 1),
        "ints": np.arange(5, dtype=np.int32),
        "scalar": np.float64(2.5),
        "sympy": expr,
        (1, "a"): "tuple key",
        "enum": Damping.PAPER,
        "dataclass": Step("13", expr, "why", Verdict(True, "symbolic", 0, 0, 0.0, sp.Integer(2))),
    }


def _same(a, b) -> bool:
    if isinstance(a, np.ndarray):
        return type(b) is np.ndarray and a.dtype == b.dtype and np.array_equal(a, b)
    if isinstance(a, float) and a != a:
        return b != b
    if isinstance(a, dict):
        return type(b) is dict and a.keys() == b.keys() and all(_same(a[k], b[k]) for k in a)
    if isinstance(a, (list, tuple)):
        return type(a) is type(b) and len(a) == len(b) and all(map(_same, a, b))
    if isinstance(a, sp.Basic):
        return sp.srepr(a) == sp.srepr(b)
    return type(a) is type(b) and a == b and repr(a) == repr(b)


def test_codec_round_trip_is_exact():
    value = _sample()
    text = json.dumps(encode(value))
    back = decode(json.loads(text))
    assert _same(value, back)
    assert back["mpf"] == value["mpf"]  # the exact binary word, not a decimal rendering


@pytest.mark.parametrize(
    "data",
    [
        {"$dataclass": "os:system", "fields": {}},
        {"$dataclass": "subprocess:Popen", "fields": {}},
        {"$enum": "builtins:object", "name": "x"},
        {"$sympy": "__import__('os').system('echo hacked')"},
        {"$sympy": "Add(\"__import__('os').system('echo hacked')\")"},
        {"$sympy": "Symbol('x').__class__"},
        {"$sympy": "Integer('7')"},
        {"$sympy": "Function(Symbol('x'))(Symbol('y'))"},
        {"$sympy": "Lambda(x, x)"},
        {"$sympy": "Symbol('x', **{'a': 1})"},
        {"$sympy": "'just text'"},
        {"$sympy": "Add(Symbol('x'), Integer(1)" + ")" * 3},
        {"$numpy": "array", "dtype": "|O8", "shape": [1], "data": "AAAAAAAAAAA="},
        {"$numpy": "array", "dtype": "<f8", "shape": [2], "data": "AAAAAAAAAAA="},
        {"$float": "1e5; import os"},
        {"$mpf": [0, 2, 0, 2]},
        {"$fraction": [1, 0]},
        {"$bytes": "not base64!"},
        {"$unknown": 1},
        {"$tuple": [1], "extra": 2},
        3.5,
    ],
)
def test_decoder_refuses_what_it_does_not_know(data, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    with pytest.raises(DecodeError):
        decode(data)
    assert list(tmp_path.iterdir()) == []


def test_srepr_parser_builds_no_code_objects():
    # a string argument of a class that would sympify it is refused, not parsed
    with pytest.raises(DecodeError):
        parse_srepr("Mul(Integer(2), 'x')")
    x = sp.Symbol("x", positive=True)
    assert parse_srepr(sp.srepr(sp.sin(x) ** 2)) == sp.sin(x) ** 2


def test_encode_refuses_foreign_objects():
    with pytest.raises(TypeError):
        encode(object())
    with pytest.raises(TypeError):
        encode({"f": len})


# ------------------------------------------------------------------------------------------------
# the cache


def _flip(raw: bytes, where: float) -> bytes:
    i = min(len(raw) - 1, int(len(raw) * where))
    return raw[:i] + bytes([raw[i] ^ 0x04]) + raw[i + 1 :]


def _forged(raw: bytes, cache: Cache, name: str) -> bytes:
    """A well-formed entry with other content: a correct header whose tag is computed the way
    the cache does, but with a key other than the cache's own."""
    header, _, _ = raw.partition(b"\n")
    forged = json.dumps(encode(("forged", 42))).encode()
    head = json.loads(header)
    head["hmac"] = cache._tag(b"\0" * 32, name, forged)
    return json.dumps(head).encode() + b"\n" + forged


CORRUPTIONS = {
    "bit flip in the header": lambda raw, c, n: _flip(raw, 0.05),
    "bit flip in the middle": lambda raw, c, n: _flip(raw, 0.5),
    "bit flip at the end": lambda raw, c, n: _flip(raw, 0.999),
    "truncated": lambda raw, c, n: raw[: len(raw) // 2],
    "empty": lambda raw, c, n: b"",
    "garbage": lambda raw, c, n: os.urandom(len(raw)),
    "invalid utf-8": lambda raw, c, n: b"\xff\xfe" + raw,
    "a pickle": lambda raw, c, n: b"\x80\x04\x95\x05\x00\x00\x00\x00\x00\x00\x00K\x2a.",
    "forged": _forged,
    "directory": None,
}


@pytest.mark.parametrize("kind", sorted(CORRUPTIONS))
def test_a_damaged_entry_is_dropped_recomputed_and_rewritten(kind, tmp_path, capsys):
    value = _sample()
    calls = []

    def make():
        calls.append(1)
        return value

    Cache(tmp_path).get("entry", make)
    cache = Cache(tmp_path)
    path = cache.path("entry")
    if CORRUPTIONS[kind] is None:  # something that cannot be opened as a file
        path.unlink()
        path.mkdir()
    else:
        path.write_bytes(CORRUPTIONS[kind](path.read_bytes(), cache, "entry"))
    capsys.readouterr()
    got = cache.get("entry", make)
    err = capsys.readouterr().err
    assert _same(got, value) and len(calls) == 2
    assert len(err.splitlines()) == 1 and err.startswith("paramres: warning: cache entry")
    if kind != "directory":
        # rewritten: the next reader finds it intact and says nothing
        again = Cache(tmp_path)
        assert _same(again.get("entry", make), value) and len(calls) == 2
        assert capsys.readouterr().err == "" and again.hits == ["entry"]


def test_entries_are_authenticated_by_a_private_key(tmp_path, capsys):
    Cache(tmp_path).get("entry", lambda: [1, 2, 3])
    key = tmp_path / KEY_FILE
    assert stat.S_IMODE(key.stat().st_mode) == 0o600
    # a key readable by others is not trusted: replaced, the entry computed again
    key.chmod(0o644)
    old = key.read_bytes()
    assert Cache(tmp_path).get("entry", lambda: [4]) == [4]
    assert "not private" in capsys.readouterr().err
    assert key.read_bytes() != old and stat.S_IMODE(key.stat().st_mode) == 0o600
    # an entry copied from another cache (another key) is refused
    other = tmp_path / "other"
    Cache(other).get("entry", lambda: ["other"])
    src = Cache(other).path("entry")
    Cache(tmp_path).path("entry").write_bytes(src.read_bytes())
    assert Cache(tmp_path).get("entry", lambda: [5]) == [5]
    assert "authentication tag" in capsys.readouterr().err


def test_values_that_do_not_read_back_identical_are_not_stored(tmp_path):
    x = sp.Symbol("x")
    held = sp.Add(x, x, evaluate=False)  # would come back as 2*x
    cache = Cache(tmp_path)
    assert cache.get("held", lambda: held) is held
    assert not cache.path("held").exists()
    assert Cache(tmp_path).get("fn", lambda: len) is len  # not encodable: computed, not stored


def test_unwritable_cache_directory_is_not_an_error(tmp_path):
    blocker = tmp_path / "file"
    blocker.write_text("x")
    assert Cache(blocker / "sub").get("entry", lambda: 7) == 7


def test_cache_modules_import_no_pickle_and_call_no_eval():
    import ast
    import inspect

    import analytic.cache as cache_module

    for module in (cachecodec, cache_module):
        tree = ast.parse(inspect.getsource(module))
        imported = set()
        for node in ast.walk(tree):
            if isinstance(node, ast.Import):
                imported |= {alias.name.split(".")[0] for alias in node.names}
            elif isinstance(node, ast.ImportFrom):
                imported |= {(node.module or "").split(".")[0]}
                imported |= {alias.name for alias in node.names}
        assert not imported & {"pickle", "marshal", "shelve", "dill", "cloudpickle"}
        calls = [node.func for node in ast.walk(tree) if isinstance(node, ast.Call)]
        names = {f.id for f in calls if isinstance(f, ast.Name)}
        attributes = {f.attr for f in calls if isinstance(f, ast.Attribute)}
        assert not names & {"eval", "exec", "compile", "__import__", "sympify", "S"}
        assert not attributes & {"sympify", "parse_expr", "eval", "literal_eval"}


# ------------------------------------------------------------------------------------------------
# the commands that read the cache give exactly their no-cache output


def _cli(capsys, argv):
    from reports.cli import main

    code = main(argv)
    out, err = capsys.readouterr()
    return code, out, err


@pytest.mark.slow
def test_catalogue_command_with_each_cache_file_damaged(tmp_path, capsys):
    from analytic import catalogue as catalogue_module
    from analytic import reductions

    def clear():
        catalogue_module.catalogue.cache_clear()
        reductions.chains.cache_clear()

    clear()
    with cache_dir_override(None):
        code, reference, _ = _cli(capsys, ["catalogue", "--json"])
    assert code == 0
    # seed the cache with the values just computed (the same as a cold run would write)
    base = tmp_path / "analytic"
    Cache(base).get("chains", reductions.chains)
    Cache(base).get("catalogue", catalogue_module.catalogue)
    files = sorted(p.name for p in Cache(base).path("x").parent.glob("*.json"))
    assert files == ["catalogue.json", "chains.json"]
    kinds = {"catalogue.json": "forged", "chains.json": "bit flip in the middle"}
    for name, kind in kinds.items():
        path = Cache(base).path(name[: -len(".json")])
        good = path.read_bytes()
        path.write_bytes(CORRUPTIONS[kind](good, Cache(base), name[: -len(".json")]))
        if name == "chains.json":  # the command reads the chains only to build the catalogue
            Cache(base).path("catalogue").unlink()
        clear()
        with cache_dir_override(tmp_path):
            code, out, err = _cli(capsys, ["catalogue", "--json"])
        assert code == 0 and out == reference, name
        assert len(err.splitlines()) == 1 and name in err, err
        # and once more from the rewritten entry, silently
        clear()
        with cache_dir_override(tmp_path):
            code, out, err = _cli(capsys, ["catalogue", "--json"])
        assert code == 0 and out == reference and err == ""
    clear()


@pytest.mark.slow
def test_report_sections_with_each_cache_file_damaged(tmp_path, capsys):
    from reports.report import assemble
    from reports.sections import Context

    sections = ("closings", "expansions")
    cold = assemble(Context(log=lambda m: None), sections)
    cache_dir = tmp_path / "report"
    packages = ("analytic", "verify", "reports", "paramres")

    def build():
        ctx = Context(cache=Cache(cache_dir, packages), log=lambda m: None)
        return assemble(ctx, sections), ctx.cache

    assert build()[0].files == cold.files
    entries = sorted(Cache(cache_dir, packages).path("x").parent.glob("*.json"))
    names = [p.stem for p in entries]
    assert {"section-closings", "section-expansions"} <= set(names)
    kinds = ("bit flip in the middle", "garbage", "forged", "truncated")
    for k, path in enumerate(entries):
        capsys.readouterr()
        good = path.read_bytes()
        path.write_bytes(CORRUPTIONS[kinds[k % len(kinds)]](good, Cache(cache_dir), path.stem))
        if not path.stem.startswith("section-"):  # read only when the sections are rebuilt
            for other in entries:
                if other.stem.startswith("section-"):
                    other.unlink()
        warm, cache = build()
        assert warm.files == cold.files, path.stem
        assert path.stem in cache.misses
        err = capsys.readouterr().err
        assert len(err.splitlines()) == 1 and path.name in err, err
