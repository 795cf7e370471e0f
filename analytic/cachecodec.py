"""The cache's encoding: finished results as JSON text, read back without running code.

:func:`encode` turns a value into JSON-compatible data and :func:`decode` builds the value back.
Loading never executes anything the file says: no ``pickle``, no ``eval``, no ``sympify`` of
text.  What can come back is a closed set of types:

- ``None``, ``bool``, ``int``, ``str`` (JSON's own), ``float`` (by its ``repr``, so ``nan`` and
  ``inf`` round-trip), ``list``, ``tuple``, ``dict`` (any encodable keys), ``bytes`` (base64);
- :class:`fractions.Fraction`, mpmath ``mpf``/``mpc`` (their exact binary words), numpy arrays and
  scalars of numeric dtypes (raw little-endian bytes);
- sympy expressions, written with :func:`sympy.srepr` and read back by :func:`parse_srepr`, a
  parser of that one grammar that only calls sympy classes from an allow-list, with sympy objects
  (never text) as the arguments of every class that would otherwise ``sympify`` a string (the
  classes evaluate as usual, so an expression held unevaluated may come back in another form:
  :mod:`analytic.cache` stores a value only if it reads back identical);
- dataclass instances and enum members of the engine's own classes (modules under
  :data:`TRUSTED_PACKAGES`), rebuilt field by field.

Anything else is refused by :func:`encode` (the value is then simply not cached), and anything
:func:`decode` does not recognise raises :class:`DecodeError`.
"""

from __future__ import annotations

import ast
import base64
import dataclasses
import enum
import importlib
import math
import re
from fractions import Fraction
from typing import Any

__all__ = ["DecodeError", "encode", "decode", "parse_srepr", "TRUSTED_PACKAGES"]

#: packages whose dataclasses and enums may be rebuilt from the cache
TRUSTED_PACKAGES = ("analytic", "verify", "reports", "paramres")


class DecodeError(ValueError):
    """Stored data that does not describe a value of the allowed kinds."""


# ----------------------------------------------------------------------------------------------
# encoding


def encode(value: Any) -> Any:
    """JSON-compatible data describing ``value``; ``TypeError`` for a value of another kind."""
    if value is None or type(value) in (bool, str, int):
        return value
    if type(value) is float:
        return {"$float": repr(value)}
    if type(value) is list:
        return [encode(v) for v in value]
    if type(value) is tuple:
        return {"$tuple": [encode(v) for v in value]}
    if type(value) is dict:
        return {"$dict": [[encode(k), encode(v)] for k, v in value.items()]}
    if type(value) is bytes:
        return {"$bytes": base64.b64encode(value).decode("ascii")}
    if type(value) is Fraction:
        return {"$fraction": [value.numerator, value.denominator]}
    mod = type(value).__module__.split(".")[0]
    if mod == "mpmath":
        return _encode_mpmath(value)
    if mod == "numpy":
        return _encode_numpy(value)
    if mod == "sympy":
        import sympy

        if isinstance(value, sympy.Basic):
            return {"$sympy": sympy.srepr(value)}
    if isinstance(value, enum.Enum):
        return {"$enum": _class_name(type(value)), "name": value.name}
    if dataclasses.is_dataclass(value) and not isinstance(value, type):
        return {
            "$dataclass": _class_name(type(value)),
            "fields": {f.name: encode(getattr(value, f.name)) for f in dataclasses.fields(value)},
        }
    raise TypeError(f"the cache cannot store a value of type {type(value).__qualname__}")


def _class_name(cls: type) -> str:
    if cls.__module__.split(".")[0] not in TRUSTED_PACKAGES:
        raise TypeError(f"the cache stores only the engine's own classes, not {cls!r}")
    return f"{cls.__module__}:{cls.__qualname__}"


def _encode_mpmath(value) -> dict:
    import mpmath

    if isinstance(value, mpmath.mpf):
        return {"$mpf": list(value._mpf_)}
    if isinstance(value, mpmath.mpc):
        re_, im_ = value._mpc_
        return {"$mpc": [list(re_), list(im_)]}
    raise TypeError(f"the cache cannot store a value of type {type(value).__qualname__}")


_NUMPY_KINDS = "biufc"


def _encode_numpy(value) -> dict:
    import numpy as np

    if isinstance(value, (np.ndarray, np.generic)) and value.dtype.kind in _NUMPY_KINDS:
        arr = np.asarray(value)
        dtype = arr.dtype.newbyteorder("<")
        data = np.ascontiguousarray(arr, dtype=dtype).tobytes()
        return {
            "$numpy": "scalar" if isinstance(value, np.generic) else "array",
            "dtype": dtype.str,
            "shape": list(arr.shape),
            "data": base64.b64encode(data).decode("ascii"),
        }
    raise TypeError(f"the cache cannot store a value of type {type(value).__qualname__}")


# ----------------------------------------------------------------------------------------------
# decoding


def decode(data: Any) -> Any:
    """The value :func:`encode` described; :class:`DecodeError` for anything else."""
    if data is None or type(data) in (bool, str, int):
        return data
    if type(data) is list:
        return [decode(v) for v in data]
    if type(data) is not dict or not data:
        raise DecodeError(f"unexpected {type(data).__name__} in the stored data")
    tag = next(iter(data))
    body = data[tag]
    try:
        handler = _DECODERS[tag]
    except KeyError:
        raise DecodeError(f"unknown tag {tag!r}") from None
    if tag not in ("$numpy", "$enum", "$dataclass") and len(data) != 1:
        raise DecodeError(f"extra keys with {tag!r}")
    return handler(data, body)


def _float(data, body):
    if not isinstance(body, str) or not re.fullmatch(
        r"-?(inf|nan|\d+\.\d*(e[+-]?\d+)?|\d+e[+-]?\d+)", body
    ):
        raise DecodeError("malformed float")
    return float(body)


def _tuple(data, body):
    if type(body) is not list:
        raise DecodeError("malformed tuple")
    return tuple(decode(v) for v in body)


def _dict(data, body):
    if type(body) is not list:
        raise DecodeError("malformed dict")
    out = {}
    for item in body:
        if type(item) is not list or len(item) != 2:
            raise DecodeError("malformed dict item")
        key = decode(item[0])
        try:
            out[key] = decode(item[1])
        except TypeError:
            raise DecodeError("unhashable dict key") from None
    return out


def _bytes(data, body):
    if not isinstance(body, str):
        raise DecodeError("malformed bytes")
    try:
        return base64.b64decode(body.encode("ascii"), validate=True)
    except (ValueError, UnicodeEncodeError):
        raise DecodeError("malformed base64") from None


def _fraction(data, body):
    if not (type(body) is list and len(body) == 2 and all(type(x) is int for x in body)):
        raise DecodeError("malformed fraction")
    if body[1] <= 0:
        raise DecodeError("malformed fraction")
    return Fraction(body[0], body[1])


def _mpf_word(word) -> tuple:
    if not (type(word) is list and len(word) == 4 and all(type(x) is int for x in word)):
        raise DecodeError("malformed mpf")
    sign, man, exp, bc = word
    if sign not in (0, 1) or man < 0 or bc < 0 or bc != man.bit_length():
        raise DecodeError("malformed mpf")
    if man and not man & 1:
        raise DecodeError("malformed mpf (not normalised)")
    return (sign, man, exp, bc)


def _mpf(data, body):
    import mpmath

    return mpmath.mp.make_mpf(_mpf_word(body))


def _mpc(data, body):
    import mpmath

    if type(body) is not list or len(body) != 2:
        raise DecodeError("malformed mpc")
    return mpmath.mp.make_mpc((_mpf_word(body[0]), _mpf_word(body[1])))


def _numpy(data, body):
    import numpy as np

    if set(data) != {"$numpy", "dtype", "shape", "data"} or body not in ("array", "scalar"):
        raise DecodeError("malformed numpy value")
    dtype_text, shape = data["dtype"], data["shape"]
    if not (isinstance(dtype_text, str) and re.fullmatch(r"[<|][biufc]\d{1,2}", dtype_text)):
        raise DecodeError("numpy dtype not allowed")
    if not (type(shape) is list and all(type(s) is int and s >= 0 for s in shape)):
        raise DecodeError("malformed numpy shape")
    dtype = np.dtype(dtype_text)
    raw = _bytes(data, data["data"])
    if len(raw) != dtype.itemsize * math.prod(shape):
        raise DecodeError("numpy data of the wrong length")
    arr = np.frombuffer(raw, dtype=dtype).reshape(shape).astype(dtype.newbyteorder("="))
    if body == "scalar":
        if shape:
            raise DecodeError("numpy scalar with a shape")
        return arr[()]
    return arr


def _trusted_class(name) -> type:
    if not isinstance(name, str) or not re.fullmatch(r"[A-Za-z_][\w.]*:[A-Za-z_][\w.]*", name):
        raise DecodeError("malformed class name")
    module_name, qualname = name.split(":")
    if module_name.split(".")[0] not in TRUSTED_PACKAGES or "<" in qualname:
        raise DecodeError(f"class {name} is not the engine's own")
    try:
        obj: Any = importlib.import_module(module_name)
    except ImportError:
        raise DecodeError(f"no module {module_name}") from None
    for part in qualname.split("."):
        obj = getattr(obj, part, None)
    if not isinstance(obj, type):
        raise DecodeError(f"{name} is not a class")
    return obj


def _enum(data, body):
    cls = _trusted_class(body)
    if set(data) != {"$enum", "name"} or not issubclass(cls, enum.Enum):
        raise DecodeError("malformed enum")
    try:
        return cls[data["name"]]
    except (KeyError, TypeError):
        raise DecodeError(f"{body} has no member {data['name']!r}") from None


def _dataclass(data, body):
    cls = _trusted_class(body)
    fields = data.get("fields")
    if set(data) != {"$dataclass", "fields"} or not dataclasses.is_dataclass(cls):
        raise DecodeError("malformed dataclass")
    names = [f.name for f in dataclasses.fields(cls)]
    if type(fields) is not dict or sorted(fields) != sorted(names):
        raise DecodeError(f"the fields of {body} do not match")
    obj = object.__new__(cls)
    for key in names:
        object.__setattr__(obj, key, decode(fields[key]))
    return obj


def _sympy(data, body):
    if not isinstance(body, str):
        raise DecodeError("malformed sympy expression")
    return parse_srepr(body)


_DECODERS = {
    "$float": _float,
    "$tuple": _tuple,
    "$dict": _dict,
    "$bytes": _bytes,
    "$fraction": _fraction,
    "$mpf": _mpf,
    "$mpc": _mpc,
    "$numpy": _numpy,
    "$enum": _enum,
    "$dataclass": _dataclass,
    "$sympy": _sympy,
}


# ----------------------------------------------------------------------------------------------
# sympy's srepr, read back by a parser of that grammar alone

#: classes whose positional arguments are plain data (names, digits), checked one by one
_LEAF_CLASSES = ("Symbol", "Dummy", "Function", "Integer", "Rational", "Float")
_FLOAT_TEXT = re.compile(r"-?(\d+\.?\d*|\.\d+)(e[+-]?\d+)?|[+-]?inf|nan", re.IGNORECASE)
_NAME_TEXT = re.compile(r"[^\x00]{1,200}")


def _sympy_namespace() -> tuple[dict, dict]:
    import sympy

    classes = {}
    for name in dir(sympy):
        obj = getattr(sympy, name)
        if isinstance(obj, type) and issubclass(obj, sympy.Basic):
            classes[name] = obj
    from sympy.core.function import AppliedUndef  # noqa: F401  (the class of f(t))

    constants = {
        "pi": sympy.pi,
        "E": sympy.E,
        "oo": sympy.oo,
        "zoo": sympy.zoo,
        "nan": sympy.nan,
        "true": sympy.true,
        "false": sympy.false,
        "EulerGamma": sympy.EulerGamma,
        "Catalan": sympy.Catalan,
        "GoldenRatio": sympy.GoldenRatio,
    }
    return classes, constants


_NAMESPACE: tuple[dict, dict] | None = None


def parse_srepr(text: str):
    """The sympy object ``text`` (the output of :func:`sympy.srepr`) describes, built without
    ``eval``: only calls of allow-listed sympy classes, with sympy objects as arguments (names,
    digits and assumption flags for the few classes that take them)."""
    global _NAMESPACE
    import sympy

    if _NAMESPACE is None:
        _NAMESPACE = _sympy_namespace()
    if len(text) > 10_000_000:
        raise DecodeError("sympy expression too long")
    try:
        tree = ast.parse(text, mode="eval")
    except (SyntaxError, ValueError, MemoryError, RecursionError):
        raise DecodeError("malformed sympy expression") from None
    try:
        out = _build(tree.body, *_NAMESPACE)
    except DecodeError:
        raise
    except RecursionError:
        raise DecodeError("sympy expression nested too deeply") from None
    except Exception as exc:  # a sympy constructor refusing its arguments
        raise DecodeError(f"sympy refused the stored expression: {type(exc).__name__}") from None
    if not isinstance(out, sympy.Basic):
        raise DecodeError("the stored expression is not a sympy object")
    return out


def _literal(node):
    """A constant (str, int, float, bool, None), or a negated number."""
    if isinstance(node, ast.Constant) and isinstance(
        node.value, (str, int, float, bool, type(None))
    ):
        return node.value
    if (
        isinstance(node, ast.UnaryOp)
        and isinstance(node.op, ast.USub)
        and isinstance(node.operand, ast.Constant)
        and type(node.operand.value) in (int, float)
    ):
        return -node.operand.value
    raise DecodeError("unexpected element in a sympy expression")


def _build(node, classes: dict, constants: dict):
    import sympy

    if isinstance(node, ast.Name):
        if node.id in constants:
            return constants[node.id]
        raise DecodeError(f"name {node.id!r} not allowed")
    if isinstance(node, (ast.Tuple, ast.List)):
        items = [_build(e, classes, constants) for e in node.elts]
        return tuple(items) if isinstance(node, ast.Tuple) else items
    if not isinstance(node, ast.Call):
        raise DecodeError("unexpected element in a sympy expression")
    if isinstance(node.func, ast.Call):
        # Function('f')(x): apply an undefined function built by the inner call
        fn = _build(node.func, classes, constants)
        if not isinstance(fn, sympy.core.function.UndefinedFunction) or node.keywords:
            raise DecodeError("only undefined functions may be applied")
        args = [_build(a, classes, constants) for a in node.args]
        _require_basic(args)
        return fn(*args)
    if not isinstance(node.func, ast.Name) or node.func.id not in classes:
        raise DecodeError("call of a name that is not an allowed sympy class")
    name = node.func.id
    cls = classes[name]
    kwargs = {}
    for kw in node.keywords:
        if kw.arg is None:
            raise DecodeError("** in a sympy expression")
        value = _literal(kw.value)
        if not isinstance(value, (bool, int)) or not re.fullmatch(r"[a-z_]+", kw.arg):
            raise DecodeError(f"keyword {kw.arg!r} not allowed")
        kwargs[kw.arg] = value
    if name in _LEAF_CLASSES:
        args = [_literal(a) for a in node.args]
        _check_leaf(name, args, kwargs)
        return cls(*args, **kwargs)
    if kwargs:
        raise DecodeError(f"keywords for {name} not allowed")
    args = [_build(a, classes, constants) for a in node.args]
    _require_basic(args)
    if issubclass(cls, sympy.core.relational.Relational):
        # a relation read back as written: sympy would otherwise try to decide it (for the
        # report's equations most of the time of reading them) and may return another object
        return cls(*args, evaluate=False)
    return cls(*args)


def _require_basic(args) -> None:
    import sympy

    for a in args:
        if not isinstance(a, sympy.Basic):
            raise DecodeError("a sympy class called with something that is not a sympy object")


def _check_leaf(name: str, args: list, kwargs: dict) -> None:
    if name in ("Symbol", "Dummy", "Function"):
        ok = len(args) == 1 and isinstance(args[0], str) and _NAME_TEXT.fullmatch(args[0])
        ok = ok and all(
            isinstance(v, bool) or (k == "dummy_index" and type(v) is int)
            for k, v in kwargs.items()
        )
    elif name == "Integer":
        ok = len(args) == 1 and type(args[0]) is int and not kwargs
    elif name == "Rational":
        ok = len(args) == 2 and all(type(a) is int for a in args) and args[1] != 0 and not kwargs
    else:  # Float
        ok = (
            len(args) == 1
            and isinstance(args[0], str)
            and _FLOAT_TEXT.fullmatch(args[0]) is not None
            and set(kwargs) <= {"precision"}
            and all(type(v) is int and 1 <= v <= 10**6 for v in kwargs.values())
        )
    if not ok:
        raise DecodeError(f"malformed arguments of {name}")
