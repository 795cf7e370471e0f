"""The boundary equations that :mod:`analytic` derived, compiled once for every number type.

Nothing here is typed in by hand: each form is taken from :mod:`analytic` (the per-edge factor
:func:`analytic.normal_form.edge_factor`, the order form :func:`analytic.normal_form.order_form`,
the half-period maps :func:`analytic.stitching.propagator`), rewritten by sympy into the variables
the solvers use, differentiated by sympy, and compiled with :func:`sympy.lambdify` for four back
ends:

* ``"math"``: Python floats (starting values for the certified solver),
* ``"numpy"``: float64 arrays (the vectorised grid),
* ``"mpmath"``: mpmath numbers at the caller's ``mp.workdps`` precision,
* ``"arb"``: python-flint ``arb`` balls at the caller's ``flint.ctx.workprec`` precision
  (the certified route: every operation rounds outward).

Rational constants are printed as calls to the back end's exact rational constructor, never as
Python floats, and ``pi`` never occurs in a compiled form (the phase ``c = n pi/2`` is an argument),
so the arb and mpmath functions are exact to the working precision.  Compiling is done once per
process and form (:func:`functools.cache`); sympy is imported only when a form is first needed.

The forms, in the variables of :mod:`verify.solve`:

:func:`edge_equation` (no friction)
    ``F(theta) = sin(theta) + k r f(beta (c + theta))`` up to the sign that makes ``dF/dtheta > 0``
    at the root, from the factor ``f(x) - eps r f(y)`` with ``x = c + theta``, ``y = beta x``,
    ``c = n pi/2``; ``f = cos`` for odd ``n``, ``sin`` for even ``n``.  Arguments
    ``(theta, c, sgn, eps, r, beta)`` with ``sgn = sin(n pi/2)`` (odd) or ``cos(n pi/2)`` (even),
    an exact integer ``+-1``.
:func:`indicator` (normal form with friction)
    ``D(theta) = R(theta) - sin(theta)**2`` (``= -N``, positive inside the interval) with
    ``R = r^2 f(beta x)^2 - u sinh(g x)^2``; arguments ``(theta, c, r2, u, beta, g)`` where
    ``u = 1 - r^2`` is passed separately (computed without cancellation by :mod:`verify.params`).
:func:`trace_indicator` (exact model, a half critically or over-damped)
    ``D(zeta) = sigma (2 C1 C2 - kappa S1 S2) - 2 cosh(2 zeta)`` with ``zeta = gamma T/2`` and the
    half-period functions ``C = e^(gamma t) (U11 + U22)/2``, ``S = gamma e^(gamma t) U12`` of the
    derived propagators (``cos``/``sin``, ``1``/``zeta`` or ``cosh``/``sinh``); arguments
    ``(zeta, sigma, kappa, nu1, nu2)`` with ``nu_i = sqrt(|omega_i^2 - gamma^2|)/gamma`` and
    ``kappa = (k omega1^2 + omega2^2/k - 2 gamma^2)/gamma^2``, ``k = ((1+m)/(1-m))^2``.

Rearrangements of these for the vectorised grid and the ends of the depth range --
:func:`edge_equation_any` / :func:`edge_equation_linear` (both parities in one array),
:func:`order1_forms` (order 1 in ``x`` itself, ``T -> 0`` as ``m -> 1``), :func:`near_one_forms`
(``r, beta -> 1``) -- and the paper's iteration maps (:func:`fixed_point_map`) are derived from the
forms above by sympy, each rewrite checked by :func:`analytic.identity.prove_zero` or by the
structure sympy returns.
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass, field
from fractions import Fraction
from functools import cache
from operator import methodcaller

import mpmath
import numpy as np
from flint import arb

__all__ = [
    "Backend",
    "backend",
    "Form",
    "edge_equation",
    "edge_equation_any",
    "edge_equation_linear",
    "edge_equation_trig",
    "regime_roots",
    "indicator",
    "indicator_bend",
    "indicator_slope",
    "order1_forms",
    "near_one_forms",
    "trace_indicator",
    "trace_indicator_scaled",
    "trace_indicator_halves",
    "HALF_SQUARE",
    "half_period_forms",
    "fixed_point_map",
    "term_sizes",
    "with_term_sizes",
]


# --------------------------------------------------------------------------------------------
# number back ends


@dataclass(frozen=True)
class Backend:
    """A number type the forms are compiled for: its function namespace and constructors."""

    name: str
    namespace: dict = field(repr=False)

    def num(self, value):
        """An exact integer or :class:`fractions.Fraction` as a number of this back end."""
        p, q = _as_pq(value)
        return self.namespace["_q"](p, q)

    def pi(self):
        return self.namespace["_pi"]()

    def sqrt(self, x):
        return self.namespace["sqrt"](x)

    def fn(self, name):
        return self.namespace[name]


def _as_pq(value) -> tuple[int, int]:
    if isinstance(value, int):
        return value, 1
    return value.numerator, value.denominator


def _arb_q(p: int, q: int):
    return arb(p) / q if q != 1 else arb(p)  # arb(p) is exact: one rounding, by the division


def _mp_q(p: int, q: int):
    return mpmath.mpf(p) / q if q != 1 else mpmath.mpf(p)


_BACKENDS = {
    "math": {
        "sin": math.sin,
        "cos": math.cos,
        "sinh": math.sinh,
        "cosh": math.cosh,
        "exp": math.exp,
        "sqrt": math.sqrt,
        "atan2": math.atan2,
        "asin": math.asin,
        "_q": lambda p, q: p / q,
        "_pi": lambda: math.pi,
    },
    "numpy": {
        "sin": np.sin,
        "cos": np.cos,
        "sinh": np.sinh,
        "cosh": np.cosh,
        "exp": np.exp,
        "sqrt": np.sqrt,
        "atan2": np.arctan2,
        "asin": np.arcsin,
        "_q": lambda p, q: p / q,
        "_pi": lambda: np.pi,
    },
    "mpmath": {
        "sin": mpmath.sin,
        "cos": mpmath.cos,
        "sinh": mpmath.sinh,
        "cosh": mpmath.cosh,
        "exp": mpmath.exp,
        "sqrt": mpmath.sqrt,
        "atan2": mpmath.atan2,
        "asin": mpmath.asin,
        "_q": _mp_q,
        "_pi": lambda: +mpmath.pi,
    },
    "exact": {  # Fractions: rational functions only (no transcendental function is defined)
        "_q": Fraction,
    },
    "arb": {  # z.sin() etc. (balls or jets, verify.certify.Jet), called without a Python frame
        "sin": methodcaller("sin"),
        "cos": methodcaller("cos"),
        "sinh": methodcaller("sinh"),
        "cosh": methodcaller("cosh"),
        "exp": methodcaller("exp"),
        "sqrt": methodcaller("sqrt"),
        "atan2": lambda a, b: arb.atan2(a, b),
        "asin": methodcaller("asin"),
        "sin_cos": methodcaller("sin_cos"),
        "sinh_cosh": methodcaller("sinh_cosh"),
        "_q": _arb_q,
        "_dyadic": lambda man, exp: arb((man, exp)),  # man 2**exp, exactly (dyadic_constants)
        "_pi": arb.pi,
    },
}


@cache
def backend(name: str) -> Backend:
    """The back end called ``name`` (``"math"``, ``"numpy"``, ``"mpmath"``, ``"arb"``, or
    ``"exact"``: :class:`fractions.Fraction` arithmetic, for rational functions)."""
    return Backend(name, _BACKENDS[name])


# --------------------------------------------------------------------------------------------
# compiling


def _printer(products: bool = False):
    """The printer of the compiled texts.  ``products``: integer powers ``x**n`` with ``3 <= |n|
    <= 8`` or ``n = -2`` written as products of squares (numpy's ``power`` calls the C library's
    ``pow`` for each element, about 100 ns where the base is negative, against about 1 ns a
    product)."""
    from sympy.printing.lambdarepr import LambdaPrinter
    from sympy.printing.precedence import PRECEDENCE

    class _Printer(LambdaPrinter):
        """Plain function names; rationals as exact ``_q(p, q)`` calls of the back end."""

        def _print_Pow(self, expr, **kw):
            n = expr.exp
            if not (products and n.is_Integer and (3 <= abs(int(n)) <= 8 or n == -2)):
                return super()._print_Pow(expr, **kw)
            base = self.parenthesize(expr.base, PRECEDENCE["Pow"], strict=False)

            def power(k: int) -> str:  # base**k by squaring, one atom (in parentheses)
                if k == 1:
                    return base
                if k % 2:
                    return f"({power(k - 1)}*{base})"
                return f"({power(k // 2)})**2"

            text = power(abs(int(n)))
            return text if n > 0 else f"1/({text})"

        def _print_Rational(self, expr):
            return f"_q({expr.p}, {expr.q})"

        _print_Half = _print_Rational

        def _print_Pi(self, expr):  # pragma: no cover - the forms are built without pi
            raise ValueError("a compiled form must not contain pi (pass c = n pi/2 instead)")

        def _print_Float(self, expr):  # pragma: no cover - the forms are exact
            raise ValueError(f"a compiled form must be exact, found the float {expr}")

    return _Printer(
        {"fully_qualified_modules": False, "inline": True, "allow_unknown_functions": True}
    )


@dataclass
class Form:
    """A derived expression, its derivatives in the first argument, and their compilations.

    ``exprs[k]`` is the ``k``-th derivative; ``compiled(name, k)`` returns a function of ``args``
    evaluating ``exprs[k]`` with back end ``name``; ``compiled(name, (0, 1))`` returns one
    function giving both (common subexpressions shared).
    """

    title: str
    args: tuple
    exprs: tuple
    _cache: dict = field(default_factory=dict, repr=False)

    def compiled(self, name: str, orders=0):
        key = (name, orders)
        fn = self._cache.get(key)
        if fn is None:
            fn = load_source(self.source(name, orders), name, orders)
            self._cache[key] = fn
        return fn

    def source(self, name: str, orders=0) -> str:
        """The Python text of ``compiled(name, orders)`` as :func:`sympy.lambdify` writes it
        (sympy's dummy names renumbered in order of appearance, so that the text is the same in
        every process)."""
        import inspect

        import sympy as sp

        many = isinstance(orders, tuple)
        exprs = [self.exprs[k] for k in orders] if many else self.exprs[orders]
        fn = sp.lambdify(
            self.args,
            exprs,
            modules=[backend(name).namespace],
            printer=_printer(),
            cse=many or name == "arb",  # arb: every evaluation counts (and pairs are shared)
            docstring_limit=0,
        )
        text = inspect.getsource(fn)
        names = {}
        text = re.sub(
            r"_?Dummy_\d+", lambda mt: names.setdefault(mt.group(0), f"_d{len(names)}"), text
        )
        if name == "math":  # x**2 of a float is the C library's pow: x*x is the rounded square
            return squares_as_products(text)
        return arb_text(text) if name == "arb" else text


def arb_text(text: str) -> str:
    """A compiled text for the arb back end, as :func:`sympy.lambdify` wrote it, with the work
    of each evaluation cut and its balls unchanged: pairs shared (:func:`share_pairs`), squares
    as products (:func:`squares_as_products`) and the functions as method calls
    (:func:`method_calls`), and the rationals with a power of two below as constants made once
    (:func:`dyadic_constants`)."""
    return dyadic_constants(method_calls(squares_as_products(share_pairs(text))))


_PAIRS = (("sin", "cos", "sin_cos"), ("sinh", "cosh", "sinh_cosh"))


def share_pairs(text: str) -> str:
    """A compiled form's text with each ``sin(v)``, ``cos(v)`` of one name ``v`` (an argument or
    a common subexpression) computed by one ``sin_cos(v)`` call (likewise ``sinh``/``cosh`` by
    ``sinh_cosh``): one evaluation of the pair costs about what one of them does (arb).  The
    values are the same functions of ``v``; only the work is shared."""
    lines = text.split("\n")
    head = lines[0]  # def _lambdifygenerated(args):
    params = [a.strip() for a in head[head.index("(") + 1 : head.rindex(")")].split(",")]
    for f, g, both in _PAIRS:
        pat_f = re.compile(rf"(?<![\w.]){f}\((\w+)\)")
        pat_g = re.compile(rf"(?<![\w.]){g}\((\w+)\)")
        body = "\n".join(lines[1:])
        shared = sorted(set(pat_f.findall(body)) & set(pat_g.findall(body)))
        for v in shared:
            fv, gv = f"_{f}_{v}", f"_{g}_{v}"
            call = f"{fv}, {gv} = {both}({v})"
            out = [head] if v in params else []
            for line in lines[1:] if v in params else lines:
                line = re.sub(rf"(?<![\w.]){f}\({v}\)", fv, line)
                line = re.sub(rf"(?<![\w.]){g}\({v}\)", gv, line)
                out.append(line)
                if v not in params and line.startswith(f"    {v} = "):
                    out.append(f"    {call}")
            if v in params:
                out.insert(1, f"    {call}")
            lines = out
    return "\n".join(lines)


def squares_as_products(text: str) -> str:
    """A compiled text (arb or math) with each square ``v**2`` written ``(v*v)``.  A ball's
    ``**`` goes through ``arb_pow`` (with the exponent converted to a ball first), about 140 ns,
    where the product costs about 60; the product of a ball with itself is the ball ``v**2``
    gives, bit for bit, except where ``v``'s midpoint is 0: there ``**`` gives NaN and the product
    an enclosure (``tests/test_forms_generated.py`` checks both).  A float's ``**`` is the C
    library's ``pow`` (about 25 ns more, and not always correctly rounded: it differs from the
    product in the last bit for about one float in a thousand); the product is the correctly
    rounded square.  ``v`` is a name (an argument or a common
    subexpression) or a call of one function on an argument without parentheses, ``cos(beta*x0)``;
    such a call is made once, into a new name ``_sq<k>`` assigned just before the first line that
    squares it, so that the product does not evaluate it twice."""
    lines = text.split("\n")
    # (not a base of a power in the exponent: x**2**k is x**(2**k))
    name_sq = re.compile(r"(?<![\w.])([A-Za-z_]\w*)\*\*2(?![\w.]|\*\*)")
    call_sq = re.compile(r"(?<![\w.])([A-Za-z_]\w*\([^()]*\))\*\*2(?![\w.]|\*\*)")
    calls: dict[str, str] = {}
    out = lines[:1]

    def hoist(mt):
        call = mt.group(1)
        v = calls.get(call)
        if v is None:
            v = calls[call] = f"_sq{len(calls)}"
            out.append(f"    {v} = {call}")  # before the line being rewritten
        return f"({v}*{v})"

    for line in lines[1:]:
        line = call_sq.sub(hoist, line)
        out.append(name_sq.sub(lambda mt: f"({mt.group(1)}*{mt.group(1)})", line))
    return "\n".join(out)


#: the functions of the arb back end that are methods of a ball (or a jet), by name
_METHODS = ("sin", "cos", "sinh", "cosh", "sqrt", "asin", "sin_cos", "sinh_cosh")


def method_calls(text: str) -> str:
    """An arb form's text with each call ``f(v)`` of a function in :data:`_METHODS` written as
    the method call ``(v).f()``: the back end's ``operator.methodcaller`` makes that very call,
    at about 140 ns more a call (a third of ``sin`` at 64 bits).  ``v`` holds at most one level of
    parentheses; a deeper argument keeps the call through the back end (the same method)."""
    arg = r"(?:[^()]|\([^()]*\))*"
    pat = re.compile(rf"(?<![\w.])({'|'.join(_METHODS)})\(({arg})\)")
    lines = text.split("\n")

    def repl(mt):
        v = mt.group(2)
        return f"{v}.{mt.group(1)}()" if re.fullmatch(r"\w+", v) else f"({v}).{mt.group(1)}()"

    return "\n".join(lines[:1] + [pat.sub(repl, line) for line in lines[1:]])


def dyadic_constants(text: str) -> str:
    """An arb form's text with each rational ``_q(p, q)`` whose denominator is a power of two
    (and ``|p| < 2**24``) read from a name made once, above the function, by ``_dyadic(p, -k)``
    (``q = 2**k``): the ball ``p 2**-k`` exactly, which is the ball ``_q(p, q)`` gives at any
    working precision of 24 bits or more (the quotient is exact), where each evaluation made it
    again (a conversion and a division, about 190 ns).  ``_q(1, 2)`` is the mean of two phases'
    values in the parameters of the family (equal halves), the most frequent of them."""
    pat = re.compile(r"(?<![\w.])_q\((-?\d+), (\d+)\)")
    made: dict[str, str] = {}

    def repl(mt):
        p, q = int(mt.group(1)), int(mt.group(2))
        if q & (q - 1) or abs(p) >= 2**24:
            return mt.group(0)
        name = f"_q{'m' if p < 0 else ''}{abs(p)}_{q}"
        made[name] = f"{name} = _dyadic({p}, {1 - q.bit_length()})"
        return name

    body = pat.sub(repl, text)
    return "".join(f"{line}\n" for line in made.values()) + body


def int_constants(text: str) -> str:
    """An arb form's text with each integer constant that is an operand of ``+``, ``-``, ``*``
    or ``/`` beside a ball (``2*c``, ``1 - v``, ``-2*_d0``) read from a name made once, above
    the function, by ``_dyadic(k, 0)``: the exact ball ``k``, which is what python-flint
    converts the int to at each evaluation (about 40 ns), so every result is the same ball.
    Only for arguments that are balls: with an int or a float argument (``eps = 1``) or a jet,
    ``2*eps`` would become a ball, or a jet's arithmetic another's.  Exponents, function
    arguments and operations between two constants stay as they are."""
    import ast

    tree = ast.parse(text)
    made: dict[str, str] = {}

    def constant(node) -> int | None:
        if isinstance(node, ast.Constant) and type(node.value) is int:
            return node.value
        if (
            isinstance(node, ast.UnaryOp)
            and isinstance(node.op, ast.USub)
            and isinstance(node.operand, ast.Constant)
            and type(node.operand.value) is int
        ):
            return -node.operand.value
        return None

    def named(k: int):
        name = f"_i{'m' if k < 0 else ''}{abs(k)}"
        made[name] = f"{name} = _dyadic({k}, 0)"
        return ast.Name(name, ast.Load())

    class Constants(ast.NodeTransformer):
        def visit_BinOp(self, node):
            self.generic_visit(node)
            if isinstance(node.op, ast.Add | ast.Sub | ast.Mult | ast.Div):
                kl, kr = constant(node.left), constant(node.right)
                if kl is not None and kr is None:
                    node.left = named(kl)
                elif kr is not None and kl is None:
                    node.right = named(kr)
            return node

    body = ast.unparse(ast.fix_missing_locations(Constants().visit(tree)))
    return "".join(f"{line}\n" for line in sorted(made.values())) + body + "\n"


def hoist_powers(text: str, names, least: int = 3) -> tuple[str, tuple]:
    """A compiled form's text with each power ``v**k`` (``k >= least``) of an argument ``v`` in
    ``names`` read from a new argument ``_pow_v_k`` (appended to the signature, in order of
    first appearance), and the ``(v, k)`` of those arguments.  A caller whose ``v`` repeats over
    many evaluations (a parameter per depth, gathered per point) computes ``v**k`` once per value
    and passes it gathered: the same numbers where they are used (``v**k`` is an elementwise
    function of ``v``), without a general power per point."""
    lines = text.split("\n")
    head = lines[0]
    params = [a.strip() for a in head[head.index("(") + 1 : head.rindex(")")].split(",")]
    found = []
    pat = re.compile(r"(?<![\w.])(\w+)\*\*(\d+)(?![\w.])")

    def repl(mt):
        v, k = mt.group(1), int(mt.group(2))
        if v not in names or v not in params or k < least:
            return mt.group(0)
        if (v, k) not in found:
            found.append((v, k))
        return f"_pow_{v}_{k}"

    body = pat.sub(repl, "\n".join(lines[1:]))
    extra = "".join(f", _pow_{v}_{k}" for v, k in found)
    head = f"{head[: head.rindex(')')]}{extra}{head[head.rindex(')') :]}"
    return f"{head}\n{body}", tuple(found)


def load_source(text: str, name: str, orders=0):
    """The function a form's text (:meth:`Form.source`) defines, in back end ``name``'s
    namespace; one giving a tuple for several ``orders``."""
    ns = dict(backend(name).namespace)
    many = isinstance(orders, tuple)
    if many:  # the list returned as a tuple by the function itself (no wrapper's frame per call)
        head, sep, last = text.rstrip("\n").rpartition("\n")
        if sep and last.startswith("    return [") and last.endswith("]"):
            text = f"{head}\n    return ({last[len('    return [') : -1]},)\n"
            many = False
    exec(compile(text, f"<form {name} {orders}>", "exec"), ns)  # noqa: S102 - derived text
    inner = ns["_lambdifygenerated"]
    if many:
        return lambda *a: tuple(inner(*a))
    return inner


def hoisted(text: str, name: str, dynamic: str = "theta"):
    """``(prepare, evaluate)`` of :func:`hoisted_source`, in back end ``name``'s namespace."""
    ns = dict(backend(name).namespace)
    source = hoisted_source(text, dynamic)
    exec(compile(source, f"<hoisted form {name}>", "exec"), ns)  # noqa: S102 - derived text
    return ns["_prepare"], ns["_evaluate"]


def hoisted_source(text: str, dynamic: str = "theta") -> str:
    """The text of two functions, ``_prepare`` and ``_evaluate``, from a compiled text
    (:meth:`Form.source`, a function of ``dynamic`` and parameters) for many evaluations with the
    same parameters: ``_evaluate(x, *_prepare(*params))`` is ``f(x, *params)``, value for value,
    with the work that does not depend on ``x`` done once in ``_prepare``.

    Every subexpression of the text (a node of Python's evaluation tree: ``-2*_d0*beta*x10*x7``
    is ``(((-2*_d0)*beta)*x10)*x7``) whose names are all parameters (or variables assigned from
    parameters alone) is computed in ``prepare`` instead: the same operations on the same
    operands, so the same numbers (floats: the same roundings; no reassociation), and ``evaluate``
    takes each as a name.  Equal subexpressions are computed once.  Constants (``2``, ``-2``)
    stay in place.  A list returned is returned as a tuple (as :func:`load_source` does)."""
    import ast

    tree = ast.parse(text)
    fn = tree.body[0]
    if not isinstance(fn, ast.FunctionDef):  # pragma: no cover - a lambdify text
        raise ValueError("not a function text")
    params = [a.arg for a in fn.args.args if a.arg != dynamic]
    static = set(params)
    hoist: dict[str, str] = {}  # the text of a hoisted subexpression -> its name
    prep: list[ast.stmt] = []

    def is_static(node) -> bool:
        return all(n.id in static for n in ast.walk(node) if isinstance(n, ast.Name))

    def trivial(node) -> bool:
        return isinstance(node, ast.Name | ast.Constant) or (
            isinstance(node, ast.UnaryOp) and isinstance(node.operand, ast.Constant)
        )

    class Hoist(ast.NodeTransformer):
        def visit(self, node):
            if isinstance(node, ast.expr) and not trivial(node) and is_static(node):
                key = ast.dump(node)
                var = hoist.get(key)
                if var is None:
                    var = hoist[key] = f"_h{len(hoist)}"
                    prep.append(ast.Assign([ast.Name(var, ast.Store())], node, lineno=0))
                return ast.Name(var, ast.Load())
            return self.generic_visit(node)

    body: list[ast.stmt] = []
    for stmt in fn.body:
        if (
            isinstance(stmt, ast.Assign)
            and len(stmt.targets) == 1
            and isinstance(stmt.targets[0], ast.Name)
            and is_static(stmt.value)
        ):
            prep.append(stmt)  # a variable of the parameters alone
            static.add(stmt.targets[0].id)
            continue
        if isinstance(stmt, ast.Return) and isinstance(stmt.value, ast.List):
            stmt = ast.Return(ast.Tuple(stmt.value.elts, ast.Load()))
        body.append(Hoist().visit(stmt))
    static.update(hoist.values())
    used = sorted({n.id for st in body for n in ast.walk(st) if isinstance(n, ast.Name)} & static)
    args = lambda names: ast.arguments(  # noqa: E731
        posonlyargs=[], args=[ast.arg(v) for v in names], kwonlyargs=[], kw_defaults=[],
        defaults=[],
    )  # fmt: skip
    ret = ast.Return(ast.Tuple([ast.Name(v, ast.Load()) for v in used], ast.Load()))
    module = ast.Module(
        [
            ast.FunctionDef("_prepare", args(params), [*prep, ret], [], lineno=0),
            ast.FunctionDef("_evaluate", args([dynamic, *used]), body, [], lineno=0),
        ],
        [],
    )
    return ast.unparse(ast.fix_missing_locations(module)) + "\n"


class LazyForm:
    """A :class:`Form` derived only when something needs more than its compiled functions.

    ``key`` names the form (the builder and its argument); a compilation whose text is in
    :data:`verify.forms_generated.SOURCES` is loaded from there without sympy, any other request
    derives the form (``build()``) and delegates to it.  ``tests/test_forms_generated.py``
    checks that the stored texts are what the derivation gives today."""

    def __init__(self, key: str, build):
        self.key = key
        self._build = build
        self._real = None
        self._fns = {}

    @property
    def real(self) -> Form:
        if self._real is None:
            self._real = self._build()
        return self._real

    def compiled(self, name: str, orders=0):
        k = (name, orders)
        fn = self._fns.get(k)
        if fn is None:
            from .forms_generated import SOURCES

            text = SOURCES.get(generated_key(self.key, name, orders))
            fn = load_source(text, name, orders) if text else self.real.compiled(name, orders)
            self._fns[k] = fn
        return fn

    def text(self, name: str, orders=0) -> str:
        """The text of ``compiled(name, orders)``: the stored one, else the derived form's."""
        from .forms_generated import SOURCES

        return SOURCES.get(generated_key(self.key, name, orders)) or self.real.source(name, orders)

    def __getattr__(self, attr):
        if attr.startswith("__") or attr in ("_build", "_real", "_fns", "key"):
            raise AttributeError(attr)
        return getattr(self.real, attr)


def generated_key(key: str, name: str, orders) -> str:
    """The key of one compilation in :data:`verify.forms_generated.SOURCES`."""
    return f"{key} | {name} | {orders}"


def term_sizes(form: Form | LazyForm) -> Form | LazyForm:
    """The sizes of the terms of ``form``, for bounding its rounding error: ``(sum |t_i|, sum
    |dt_i/dv|)`` over the additive terms ``t_i`` of its expanded expression, ``v`` its first
    argument, as a form of the same arguments (kept on ``form``; built once).

    Evaluating ``sum t_i`` in floating point with arguments correct to a few ulp errs by at most
    a few ulp of the first sum, plus what the errors of the angles cost: an angle ``a v + b`` with
    a relative error ``e`` moves by about ``e |a v + b|``, which changes ``t_i`` by about ``e |v +
    b/a| |dt_i/dv|`` -- bounded through the second sum by the caller's scale of the angles.

    For a :class:`LazyForm` the sizes are a :class:`LazyForm` too (key ``term_sizes(key)``), so
    that their pregenerated compilations need no derivation."""
    if isinstance(form, LazyForm):
        sizes = form._fns.get("term_sizes")
        if sizes is None:
            sizes = LazyForm(f"term_sizes({form.key})", lambda: term_sizes(form.real))
            form._fns["term_sizes"] = sizes
        return sizes
    sizes = form._cache.get("term_sizes")
    if sizes is None:
        import sympy as sp

        var = form.args[0]
        terms = sp.Add.make_args(sp.expand(form.exprs[0]))
        total = sp.Add(*(sp.Abs(t) for t in terms))
        slope = sp.Add(*(sp.Abs(sp.diff(t, var)) for t in terms))
        sizes = Form(f"term sizes of {form.title}", form.args, (total, slope))
        form._cache["term_sizes"] = sizes
    return sizes


def with_term_sizes(form: Form | LazyForm, count: int = 3) -> Form | LazyForm:
    """``form`` and its first ``count`` derivatives followed by its :func:`term_sizes` ``(sum
    |t_i|, sum |dt_i/dv|)``, as one form of the same arguments (kept on ``form``; built once):
    compiled for all ``count + 3`` orders it shares every sine, cosine and hyperbolic function
    among the values, the derivatives and the sizes (a root finder gets its step and the rounding
    bound of its root from one call).  The terms are those of :func:`term_sizes`, taken without
    expanding the arguments of the functions (so that they are the form's own), which is the same
    sum (``tests/test_grid_friction.py`` compares the two).

    For a :class:`LazyForm` the result is a :class:`LazyForm` too (key
    ``with_term_sizes(key, count)``), so that its pregenerated compilations need no derivation."""
    key = ("with_term_sizes", count)
    if isinstance(form, LazyForm):
        out = form._fns.get(key)
        if out is None:
            out = LazyForm(
                f"with_term_sizes({form.key}, {count})", lambda: with_term_sizes(form.real, count)
            )
            form._fns[key] = out
        return out
    out = form._cache.get(key)
    if out is None:
        import sympy as sp

        var = form.args[0]
        terms = sp.Add.make_args(sp.expand(form.exprs[0], deep=False))
        total = sp.Add(*(sp.Abs(t) for t in terms))
        slope = sp.Add(*(sp.Abs(sp.diff(t, var)) for t in terms))
        derivs = tuple(form.exprs[: count + 1])
        if len(derivs) < count + 1:  # more derivatives than the form keeps
            derivs = derivs + _derivatives(derivs[-1], var, count + 1 - len(derivs))[1:]
        exprs = derivs + (total, slope)
        out = Form(f"{form.title} with term sizes", form.args, exprs)
        form._cache[key] = out
    return out


def _derivatives(expr, var, count: int) -> tuple:
    import sympy as sp

    out = [expr]
    for _ in range(count):
        out.append(sp.diff(out[-1], var))
    return tuple(out)


# --------------------------------------------------------------------------------------------
# the forms


def _symbols():
    import sympy as sp

    from analytic.model import S

    return {
        "theta": S.theta,
        "c": sp.Symbol("c", real=True),
        "sgn": sp.Symbol("sgn", real=True),
        "eps": sp.Symbol("eps", real=True),
        "r": sp.Symbol("r", positive=True),
        "r2": sp.Symbol("r^2", nonnegative=True),
        "u": sp.Symbol("u", positive=True),
        "beta": S.beta,
        "g": S.g,
        "zeta": sp.Symbol("zeta", positive=True),
        "sigma": sp.Symbol("sigma", real=True),
        "kappa": sp.Symbol("kappa", real=True),
        "nu1": sp.Symbol("nu_1", positive=True),
        "nu2": sp.Symbol("nu_2", positive=True),
    }


@cache
def edge_equation(parity) -> LazyForm:
    """The undamped per-edge equation of ``parity`` (see :func:`_edge_equation`), derived when
    first needed beyond its pregenerated compilations."""
    p = int(parity)
    return LazyForm(f"edge_equation({p})", lambda: _edge_equation(_parity(p)))


def _parity(p: int):
    from analytic.stitching import Parity

    return Parity(p)


@cache
def _edge_equation(parity) -> Form:
    """The undamped per-edge equation in ``theta`` (:func:`analytic.normal_form.edge_factor`).

    ``x = c + theta``: ``f(x)`` is expanded by sympy and ``cos(c)``, ``sin(c)`` replaced by their
    exact values for the parity (``cos(n pi/2) = 0`` for odd ``n``, ``sin(n pi/2) = 0`` for even
    ``n``; the other is ``sgn = +-1``); the factor is then multiplied by the coefficient of
    ``sin(theta)`` (which is ``+-1``) so that the result starts with ``+sin(theta)``.  Returns the
    form and its first two ``theta``-derivatives.
    """
    import sympy as sp

    from analytic.normal_form import edge_factor
    from analytic.stitching import Parity

    s = _symbols()
    th, c, sgn, eps, r, beta = (s[k] for k in ("theta", "c", "sgn", "eps", "r", "beta"))
    parity = Parity(parity)
    X = sp.Symbol("X")
    factor = edge_factor(parity, 1, symbols=(X, beta * (c + th), r))
    factor = factor.subs(r, eps * r)  # the factor with epsilon = +-1 as an argument
    f = sp.cos if parity is Parity.ODD else sp.sin
    fx = sp.expand_trig(f(c + th))
    if parity is Parity.ODD:
        fx = fx.subs({sp.cos(c): 0, sp.sin(c): sgn})
    else:
        fx = fx.subs({sp.sin(c): 0, sp.cos(c): sgn})
    expr = sp.expand(factor.subs(f(X), fx))
    lead = expr.coeff(sp.sin(th))
    expr = sp.expand(lead * expr).subs(sgn**2, 1)
    if sp.expand(expr.coeff(sp.sin(th)) - 1) != 0:  # pragma: no cover - derivation guard
        raise AssertionError(f"edge equation does not start with sin(theta): {expr}")
    title = f"edge equation, {'odd' if parity is Parity.ODD else 'even'} orders"
    return Form(title, (th, c, sgn, eps, r, beta), _derivatives(expr, th, 2))


@cache
def edge_equation_any() -> Form:
    """Both parities' edge equations in one form, for arrays mixing odd and even orders:
    ``odd * F_odd + (1 - odd) * F_even`` with ``odd`` = 1 or 0 (the two forms of
    :func:`edge_equation`, each starting with ``sin(theta)``); arguments
    ``(theta, c, sgn, eps, odd, r, beta)``.  Evaluating it costs the same four sines and cosines
    as either form alone (each form's derivative needs both ``sin`` and ``cos`` of ``beta x``)."""
    import sympy as sp

    from analytic.stitching import Parity

    odd_form, even_form = edge_equation(Parity.ODD), edge_equation(Parity.EVEN)
    odd = sp.Symbol("odd", real=True)
    pairs = zip(odd_form.exprs, even_form.exprs, strict=True)
    exprs = tuple(odd * a + (1 - odd) * b for a, b in pairs)
    args = odd_form.args[:4] + (odd,) + odd_form.args[4:]
    return Form("edge equation, any order", args, tuple(sp.expand(e) for e in exprs))


@cache
def edge_equation_linear() -> tuple[LazyForm, LazyForm]:
    """:func:`_edge_equation_linear`, each form derived when first needed beyond its
    pregenerated compilations (:data:`verify.forms_generated.SOURCES`)."""
    return (
        LazyForm("edge_equation_linear[0]", _pick(_edge_equation_linear, 0)),
        LazyForm("edge_equation_linear[1]", _pick(_edge_equation_linear, 1)),
    )


@cache
def _edge_equation_linear() -> tuple[Form, Form]:
    """:func:`edge_equation_any` collected in ``cos(beta x)`` and ``sin(beta x)``:
    ``sin(theta) + A cos(beta (c + theta)) + B sin(beta (c + theta))``, the coefficients ``A``,
    ``B`` (functions of ``sgn, eps, odd, r``) computed once per point instead of once per
    iteration.  Returns ``(form, coefficients)``: the form in ``(theta, c, beta, A, B)`` with two
    ``theta``-derivatives, and ``(A, B)`` as a form of ``(sgn, eps, odd, r)``."""
    import sympy as sp

    any_form = edge_equation_any()
    th, c, sgn, eps, odd, r, beta = any_form.args
    y = beta * (c + th)
    expr = sp.expand(any_form.exprs[0], trig=False)
    Y = sp.Symbol("Y")
    expr = expr.subs(
        {sp.cos(beta * c + beta * th): sp.cos(Y), sp.sin(beta * c + beta * th): sp.sin(Y)}
    )
    A = sp.expand(expr.coeff(sp.cos(Y)))
    B = sp.expand(expr.coeff(sp.sin(Y)))
    rest = sp.expand(expr - A * sp.cos(Y) - B * sp.sin(Y))
    if rest != sp.sin(th) or A.has(th) or B.has(th):  # pragma: no cover - derivation guard
        raise AssertionError(f"edge equation is not linear in cos, sin of beta x: {expr}")
    Asym, Bsym = sp.symbols("A B", real=True)
    form = sp.sin(th) + Asym * sp.cos(y) + Bsym * sp.sin(y)
    return (
        Form(
            "edge equation, linear in f(beta x)",
            (th, c, beta, Asym, Bsym),
            _derivatives(form, th, 2),
        ),
        Form("edge equation coefficients", (sgn, eps, odd, r), (A, B)),
    )


@cache
def edge_equation_trig() -> LazyForm:
    """:func:`_edge_equation_trig`, derived when first needed beyond its pregenerated
    compilations (:data:`verify.forms_generated.SOURCES`)."""
    return LazyForm("edge_equation_trig", _edge_equation_trig)


@cache
def _edge_equation_trig() -> Form:
    """:func:`edge_equation_linear` and its two ``theta``-derivatives as polynomials in the sines
    and cosines they contain: ``sin(theta), cos(theta), sin(y), cos(y)`` (``y = beta (c + theta)``)
    replaced by the arguments ``(st, ct, sy, cy)``; the form in ``(st, ct, sy, cy, beta, A, B)``.
    The vectorised grid evaluates the sines once and moves them along with each Newton-type step
    by the addition theorems (:func:`verify.grid.undamped_roots`), so each step costs no new
    transcendental function."""
    import sympy as sp

    lin, _coef = _edge_equation_linear()
    th, c, beta, A, B = lin.args
    st, ct, sy, cy = sp.symbols("s_t c_t s_y c_y", real=True)
    y = beta * (c + th)
    rep = {sp.sin(th): st, sp.cos(th): ct, sp.sin(y): sy, sp.cos(y): cy}
    exprs = tuple(sp.expand(e.subs(rep)) for e in lin.exprs)
    for e in exprs:
        if e.has(th) or e.has(c):  # pragma: no cover - derivation guard
            raise AssertionError(f"edge equation not polynomial in its sines: {e}")
    return Form("edge equation in its sines", (st, ct, sy, cy, beta, A, B), exprs)


@cache
def order1_forms() -> tuple[LazyForm, LazyForm]:
    """:func:`_order1_forms`, each derived when first needed beyond its pregenerated
    compilations (:data:`verify.forms_generated.SOURCES`)."""
    return (
        LazyForm("order1_forms[0]", _pick(_order1_forms, 0)),
        LazyForm("order1_forms[1]", _pick(_order1_forms, 1)),
    )


@cache
def near_one_forms() -> tuple[LazyForm, LazyForm, LazyForm]:
    """:func:`_near_one_forms`, each derived when first needed beyond its pregenerated
    compilations (:data:`verify.forms_generated.SOURCES`)."""
    return (
        LazyForm("near_one_forms[0]", _pick(_near_one_forms, 0)),
        LazyForm("near_one_forms[1]", _pick(_near_one_forms, 1)),
        LazyForm("near_one_forms[2]", _pick(_near_one_forms, 2)),
    )


def _pick(build, k: int):
    return lambda: build()[k]


@cache
def _order1_forms() -> tuple[Form, Form]:
    """Order 1 in the phase ``x = pi/2 + theta`` itself, for the lower edge at ``m -> 1`` where
    ``x -> 0`` (``T -> 0``) and ``theta -> -pi/2`` would lose the digits of ``x``.

    Derived from :func:`analytic.normal_form.edge_factor` (with ``eps = +1``, the equation of
    that edge) and the order form with ``theta = x - pi/2``, rewritten so that no two large terms
    cancel: ``cos z = 1 - 2 sin^2(z/2)`` (edge) or ``cos^2 z = 1 - sin^2 z`` (indicator), then
    ``sin^2 a - sin^2 b = sin(a - b) sin(a + b)`` (checked by :func:`analytic.identity.prove_zero`),
    ``r = 1 - v`` and ``r^2 = 1 - u``, ``1 - beta = bm``: every term is then small with ``x``,
    ``v = 1 - r``, ``u = 1 - r^2`` or ``bm``, all computed without cancellation.  Returns
    ``(edge, indicator)``: the edge form in ``(x, v, beta, bm)`` and ``D`` in
    ``(x, r2, u, beta, bm, g)``, each with two ``x``-derivatives.
    """
    import sympy as sp

    from analytic.identity import prove_zero
    from analytic.normal_form import edge_factor, order_form, r2
    from analytic.stitching import Parity

    s = _symbols()
    beta, u, g = s["beta"], s["u"], s["g"]
    x = sp.Symbol("x", positive=True)
    v = sp.Symbol("v", positive=True)
    bm = sp.Symbol("b_m", positive=True)
    rr = sp.Symbol("r", positive=True)

    def split(a, b, diff):  # sin(a)^2 -> sin(b)^2 + sin(a - b) sin(a + b), a - b = diff
        rep = sp.sin(b) ** 2 + sp.sin(diff) * sp.sin(a + b)
        check = prove_zero((sp.sin(a) ** 2 - rep).subs(bm, 1 - beta))
        if not check.holds:  # pragma: no cover - derivation guard
            raise AssertionError(f"identity sin^2 a - sin^2 b failed for {a}, {b}")
        return {sp.sin(a) ** 2: rep}

    edge = edge_factor(Parity.ODD, 1, symbols=(x, beta * x, rr))
    half = {
        sp.cos(x): 1 - 2 * sp.sin(x / 2) ** 2,
        sp.cos(beta * x): 1 - 2 * sp.sin(beta * x / 2) ** 2,
    }
    edge = sp.expand(edge.subs(half).subs(rr, 1 - v))
    edge = sp.expand(edge.subs(split(x / 2, beta * x / 2, bm * x / 2)))
    N, _R = order_form(1)
    D = sp.expand((-N).subs(s["theta"], x - sp.pi / 2))
    D = sp.expand(sp.expand_trig(D)) if D.has(sp.pi) else D
    D = D.subs(sp.cos(x) ** 2, 1 - sp.sin(x) ** 2).subs(
        sp.cos(beta * x) ** 2, 1 - sp.sin(beta * x) ** 2
    )
    D = sp.expand(D.subs(r2, 1 - u))
    D = sp.expand(D.subs(split(x, beta * x, bm * x)))
    for e in (edge, D):
        if e.has(sp.pi) or e.has(sp.sin(x / 2) ** 2) or e.has(sp.sin(x) ** 2):  # pragma: no cover
            raise AssertionError(f"order-1 form not rewritten: {e}")
    return (
        Form("order 1 edge equation in x", (x, v, beta, bm), _derivatives(edge, x, 2)),
        Form("order 1 indicator in x", (x, r2, u, beta, bm, g), _derivatives(D, x, 2)),
    )


@cache
def _near_one_forms() -> tuple[Form, Form, Form]:
    """The equations for ``m -> 1``, where ``r -> 1`` and ``beta -> 1`` and the terms of
    :func:`edge_equation` and :func:`indicator` cancel each other.

    With ``beta = 1 - bm`` and ``x = c + theta``, ``f(beta x) = f(c + w)``, ``w = theta - bm x``;
    expanding in ``c`` with the exact ``cos(c)``, ``sin(c)`` makes both parities ``F = sin(theta) -
    eps r sin(w)`` and ``D = r^2 sin(w)^2 - u sinh(g x)^2 - sin(theta)^2`` (checked for each parity
    by :func:`analytic.identity.prove_zero`).  Then ``r = 1 - v``, ``r^2 = 1 - u`` and ``sin a - sin
    b = 2 cos((a+b)/2) sin((a-b)/2)``, ``sin^2 a - sin^2 b = sin(a-b) sin(a+b)`` remove the
    cancellation (``theta - w = bm x`` is small with ``bm``).  Returns the edge forms for ``eps =
    +1`` and ``eps = -1`` in ``(theta, c, r, v, bm)`` and ``D`` in ``(theta, c, u, bm, g)``, each
    with two ``theta``-derivatives.  Used where ``bm`` is small (:data:`verify.grid.NEAR_ONE`).
    """
    import sympy as sp

    from analytic.identity import prove_zero
    from analytic.normal_form import r2
    from analytic.stitching import Parity

    s = _symbols()
    th, c, r, u, g, beta, eps, sgn = (
        s[k] for k in ("theta", "c", "r", "u", "g", "beta", "eps", "sgn")
    )
    v = sp.Symbol("v", positive=True)
    bm = sp.Symbol("b_m", positive=True)
    X = c + th
    w = th - bm * X
    target_F = sp.sin(th) - eps * r * sp.sin(w)
    target_D = r2 * sp.sin(w) ** 2 - u * sp.sinh(g * X) ** 2 - sp.sin(th) ** 2
    for parity in Parity:
        F = edge_equation(parity).exprs[0].subs(beta, 1 - bm)
        D = indicator(parity).exprs[0].subs(beta, 1 - bm)
        for expr, target in ((F, target_F), (D, target_D)):
            for sg in (1, -1):  # sgn = sin or cos of c, the other one zero
                cs = (
                    {sp.cos(c): 0, sp.sin(c): sg}
                    if parity is Parity.ODD
                    else {sp.sin(c): 0, sp.cos(c): sg}
                )
                diff = sp.expand_trig(
                    sp.expand(expr.subs(sgn, sg) - target)
                    .subs(sp.cos(c * (1 - bm) - bm * th + th), sp.cos(c + w))
                    .subs(sp.sin(c * (1 - bm) - bm * th + th), sp.sin(c + w))
                )
                diff = sp.expand(diff).subs(cs)
                if not prove_zero(diff).holds:  # pragma: no cover - derivation guard
                    raise AssertionError(f"near-one form differs for {parity}: {diff}")
    plus = 2 * sp.cos((th + w) / 2) * sp.sin(bm * X / 2) + v * sp.sin(w)  # eps = +1, r = 1 - v
    minus = sp.sin(th) + r * sp.sin(w)  # eps = -1: no cancellation
    Dn = -sp.sin(bm * X) * sp.sin(th + w) - u * (sp.sin(w) ** 2 + sp.sinh(g * X) ** 2)
    for got, want in (
        (plus, target_F.subs(eps, 1).subs(r, 1 - v)),
        (minus, target_F.subs(eps, -1)),
        (Dn, target_D.subs(r2, 1 - u)),
    ):
        if not prove_zero(sp.expand(got - want)).holds:  # pragma: no cover - derivation guard
            raise AssertionError(f"near-one rewrite failed: {got} vs {want}")
    return (
        Form("edge equation near m = 1, eps = +1", (th, c, r, v, bm), _derivatives(plus, th, 2)),
        Form("edge equation near m = 1, eps = -1", (th, c, r, v, bm), _derivatives(minus, th, 2)),
        Form("indicator near m = 1", (th, c, u, bm, g), _derivatives(Dn, th, 2)),
    )


@cache
def indicator(parity) -> LazyForm:
    """``D`` of the normal form for ``parity`` (see :func:`_indicator`), derived when first
    needed beyond its pregenerated compilations."""
    p = int(parity)
    return LazyForm(f"indicator({p})", lambda: _indicator(_parity(p)))


@cache
def _indicator(parity) -> Form:
    """``D = R - sin^2(theta)`` of the normal form (:func:`analytic.normal_form.order_form`),
    positive inside the interval, with ``n pi/2 -> c`` and ``1 - r^2 -> u``; and its first three
    ``theta``-derivatives."""
    import sympy as sp

    from analytic.normal_form import order_form, r2
    from analytic.stitching import Parity

    s = _symbols()
    th, c, u, beta, g = (s[k] for k in ("theta", "c", "u", "beta", "g"))
    nsym = sp.Symbol("n", positive=True, integer=True)
    N, _R = order_form(nsym, parity=Parity(parity))
    D = (-N).subs(nsym, 2 * c / sp.pi)
    D = D.subs(1 - r2, u)
    if D.has(sp.pi) or D.has(1 - r2):  # pragma: no cover - derivation guard
        raise AssertionError(f"indicator still contains pi or 1 - r^2: {D}")
    title = f"instability indicator, {'odd' if Parity(parity) is Parity.ODD else 'even'} orders"
    return Form(title, (th, c, r2, u, beta, g), _derivatives(D, th, 3))


@cache
def indicator_bend(parity) -> LazyForm:
    """``-D''/2`` of the normal form for ``parity`` (see :func:`_indicator_bend`), derived when
    first needed beyond its pregenerated compilations."""
    p = int(parity)
    return LazyForm(f"indicator_bend({p})", lambda: _indicator_bend(_parity(p)))


@cache
def _indicator_bend(parity) -> Form:
    """``-D''/2`` of :func:`indicator` in the sines alone: ``D''`` (squares of the sines and
    cosines of ``theta``, ``beta (c + theta)`` and of the sinh and cosh of ``g (c + theta)``) with
    ``cos^2 v = 1 - sin^2 v`` and ``cosh^2 v = 1 + sinh^2 v``.  The same function; over a wide ball
    its enclosure has each angle once where ``D''`` has it in two squares that nearly cancel
    (``sin^2 v - cos^2 v``), and it costs three functions instead of three pairs: ``D'' < 0`` on a
    bracket (the indicator concave there) as ``-D''/2 > 0``.  (The double angles ``cos 2v`` would
    have each angle once too, but over twice the width: arb encloses ``cos`` of a ball wider than
    about 0.45 by ``[-1, 1]``.)"""
    import sympy as sp

    form = _indicator(parity)
    to_sines = {sp.cos: lambda v: 1 - sp.sin(v) ** 2, sp.cosh: lambda v: 1 + sp.sinh(v) ** 2}

    def is_square(e):
        return e.is_Pow and e.exp == 2 and type(e.base) in to_sines

    bend = sp.expand(
        -form.exprs[2].replace(is_square, lambda e: to_sines[type(e.base)](e.base.args[0])) / 2
    )
    # the angles as products (beta (c + theta), not beta c + beta theta), and each square with
    # its coefficient once: r^2 beta^2 (1 - 2 sin^2 ...) + g^2 u (1 + 2 sinh^2 ...) + ...
    r2, u, beta, g = form.args[2:]
    bend = bend.replace(
        lambda e: type(e) in (sp.sin, sp.sinh), lambda e: e.func(sp.factor(e.args[0]))
    )
    bend = sp.collect(bend, [r2 * beta**2, g**2 * u])
    if bend.has(sp.cos, sp.cosh) or sp.simplify(
        (bend + form.exprs[2] / 2).rewrite(sp.exp)
    ):  # pragma: no cover - derivation guard
        raise AssertionError(f"-D''/2 in the sines is not -D''/2: {bend}")
    return Form(f"{form.title}: -D''/2 in the sines", form.args, (bend,))


@cache
def indicator_slope(parity) -> LazyForm:
    """``D'`` of the normal form for ``parity`` in double angles (see :func:`_indicator_slope`),
    derived when first needed beyond its pregenerated compilations."""
    p = int(parity)
    return LazyForm(f"indicator_slope({p})", lambda: _indicator_slope(_parity(p)))


@cache
def _indicator_slope(parity) -> Form:
    """``D'`` of :func:`indicator` in double angles: ``D`` with ``cos^2 v = (1 + cos 2v)/2``,
    ``sin^2 v = (1 - cos 2v)/2`` and ``sinh^2 v = (cosh 2v - 1)/2``, then differentiated, so that
    each product ``sin v cos v`` of ``D'`` is ``sin(2v)/2`` (likewise ``sinh v cosh v``).  The same
    function at three functions instead of three pairs and fewer products: the slope of the
    interval Newton test.  Its enclosure of a wide ball is also the tighter one (each angle once,
    where the products count the width of one ball twice): on the end pieces of the shape's test
    (:func:`verify.hump._unimodal`) at depths 0.6-0.99, orders 1-6, three systems, it decided the
    sign of ``D'`` on 174 of 210 pieces, :func:`indicator`'s ``D'`` on 134 (all of them among the
    174)."""
    import sympy as sp

    form = _indicator(parity)
    th = form.args[0]
    halves = {
        sp.cos: lambda v: (1 + sp.cos(2 * v)) / 2,
        sp.sin: lambda v: (1 - sp.cos(2 * v)) / 2,
        sp.sinh: lambda v: (sp.cosh(2 * v) - 1) / 2,
    }

    def is_square(e):
        return e.is_Pow and e.exp == 2 and type(e.base) in halves

    D = form.exprs[0].replace(is_square, lambda e: halves[type(e.base)](e.base.args[0]))
    slope = sp.expand(sp.diff(D, th))
    # the angles as products (2 beta (c + theta), not 2 beta c + 2 beta theta)
    slope = slope.replace(
        lambda e: type(e) in (sp.sin, sp.sinh), lambda e: e.func(sp.factor(e.args[0]))
    )
    if slope.has(sp.cos, sp.cosh) or sp.simplify(
        (slope - form.exprs[1]).rewrite(sp.exp)
    ):  # pragma: no cover - derivation guard
        raise AssertionError(f"D' in double angles is not D': {slope}")
    return Form(f"{form.title}: D' in double angles", form.args, (slope,))


@cache
def half_period_forms(regime) -> tuple:
    """``(C, S)`` of one half in the exact model for ``regime`` (under, critical, over), in units
    of ``gamma`` (``zeta = gamma t``, ``nu = |Omega|/gamma``), from the derived propagator:
    ``C = e^(gamma t) (U11 + U22)/2`` and ``S = gamma e^(gamma t) U12``."""
    import sympy as sp

    from analytic.model import Damping, Regime, S, segment
    from analytic.stitching import propagator

    regime = Regime(regime)
    s = _symbols()
    seg = segment(S.omega1, S.A1, S.B1, Damping.EXACT, regime)
    U = propagator(seg, S.t)
    C = sp.simplify(sp.exp(S.gamma * S.t) * (U[0, 0] + U[1, 1]) / 2)
    Sv = sp.simplify(S.gamma * sp.exp(S.gamma * S.t) * U[0, 1])
    units = {S.gamma: 1, S.t: s["zeta"], S.Omega1: s["nu1"], S.Lambda1: s["nu1"]}
    return sp.simplify(C.subs(units)), sp.simplify(Sv.subs(units))


@cache
def trace_indicator(regime1, regime2) -> LazyForm:
    """The trace-form indicator for the halves' regimes (see :func:`_trace_indicator`), derived
    when first needed beyond its pregenerated compilations."""
    return LazyForm(
        f"trace_indicator({regime1}, {regime2})", lambda: _trace_indicator(regime1, regime2)
    )


@cache
def _trace_indicator(regime1, regime2) -> Form:
    """``sigma tr(M) e^(gamma T) - 2 cosh(gamma T)`` in ``zeta = gamma T/2`` for the exact model
    with the halves in the given regimes (``2 C1 C2 - kappa S1 S2`` with the half-period functions
    of :func:`half_period_forms`); positive inside an interval."""

    s = _symbols()
    zeta, sigma, kappa, nu1, nu2 = (s[k] for k in ("zeta", "sigma", "kappa", "nu1", "nu2"))
    C1, S1 = half_period_forms(regime1)
    C2, S2 = (e.subs(nu1, nu2) for e in half_period_forms(regime2))
    D = _trace_sum(zeta, sigma, kappa, C1, S1, C2, S2)
    title = f"trace indicator, half 1 {regime1}, half 2 {regime2}"
    return Form(title, (zeta, sigma, kappa, nu1, nu2), _derivatives(D, zeta, 2))


def _trace_sum(zeta, sigma, kappa, C1, S1, C2, S2):
    """The trace-form indicator ``sigma (2 C1 C2 - kappa S1 S2) - 2 cosh(2 zeta)`` of the halves'
    functions ``C_i``, ``S_i`` (:func:`half_period_forms`)."""
    import sympy as sp

    return sigma * (2 * C1 * C2 - kappa * S1 * S2) - 2 * sp.cosh(2 * zeta)


#: ``u = HALF_SQUARE[regime] nu**2`` of a half (``nu = |Omega|/gamma``): its functions of
#: :func:`half_period_forms` obey ``C' = -u S`` and ``S' = C`` in ``zeta`` in every regime
#: (checked by :func:`_trace_indicator_halves`), so ``u`` is ``(Omega/gamma)^2`` with its sign
HALF_SQUARE = {"under": 1, "critical": 0, "over": -1}


@cache
def trace_indicator_halves() -> LazyForm:
    """The trace-form indicator in the halves' functions themselves (see
    :func:`_trace_indicator_halves`), derived when first needed beyond its pregenerated
    compilations."""
    return LazyForm("trace_indicator_halves()", _trace_indicator_halves)


@cache
def _trace_indicator_halves() -> Form:
    """``D`` of :func:`_trace_indicator` and its first two derivatives in ``zeta`` as functions of
    ``(zeta, sigma, kappa, C1, S1, C2, S2, u1, u2)``: the values of the halves' functions at
    ``zeta`` are arguments, and their derivatives are ``C_i' = -u_i S_i``, ``S_i' = C_i`` (``u_i``
    of :data:`HALF_SQUARE`).  Both rules are proven on :func:`half_period_forms` of every regime
    (:func:`analytic.identity.prove_zero`), so this one form holds in each of them and across a
    critical damping (where ``nu = 0``), with ``C``, ``S`` evaluated by the caller in whatever
    way stays finite there (``S = zeta sinc(nu zeta)``, not ``sin(nu zeta)/nu``)."""
    import sympy as sp

    from analytic.identity import prove_zero

    s = _symbols()
    zeta, sigma, kappa, nu1 = (s[k] for k in ("zeta", "sigma", "kappa", "nu1"))
    for regime, sign in HALF_SQUARE.items():
        C, S = half_period_forms(regime)
        u = sign * nu1**2
        for rule in (sp.diff(C, zeta) + u * S, sp.diff(S, zeta) - C):
            if not prove_zero(rule):  # pragma: no cover - derivation guard
                raise AssertionError(f"the rules C' = -u S, S' = C fail for {regime}: {rule}")
    C1, S1, C2, S2 = sp.symbols("C_1 S_1 C_2 S_2", real=True)
    u1, u2 = sp.symbols("u_1 u_2", real=True)
    funcs = {v: sp.Function(f"f_{v}")(zeta) for v in (C1, S1, C2, S2)}
    rules = {
        sp.Derivative(funcs[C1], zeta): -u1 * funcs[S1],
        sp.Derivative(funcs[S1], zeta): funcs[C1],
        sp.Derivative(funcs[C2], zeta): -u2 * funcs[S2],
        sp.Derivative(funcs[S2], zeta): funcs[C2],
    }
    back = {f: v for v, f in funcs.items()}
    exprs = [_trace_sum(zeta, sigma, kappa, *(funcs[v] for v in (C1, S1, C2, S2)))]
    for _ in range(2):
        exprs.append(sp.expand(sp.diff(exprs[-1], zeta).subs(rules)))
    args = (zeta, sigma, kappa, C1, S1, C2, S2, u1, u2)
    return Form(
        "trace indicator in the halves' functions", args, tuple(e.subs(back) for e in exprs)
    )


@cache
def trace_indicator_scaled(regime1, regime2) -> LazyForm:
    """The trace-form indicator times ``exp(-2 zeta)`` (see :func:`_trace_indicator_scaled`),
    derived when first needed beyond its pregenerated compilations."""
    return LazyForm(
        f"trace_indicator_scaled({regime1}, {regime2})",
        lambda: _trace_indicator_scaled(regime1, regime2),
    )


@cache
def _trace_indicator_scaled(regime1, regime2) -> Form:
    """:func:`_trace_indicator` scaled by ``w = exp(-2 zeta)``, for where ``cosh(2 zeta)`` is
    past the double range (both halves over-damped near ``m = 1`` at a tiny ``Q``: the window of
    order 1 reaches ``zeta`` of several hundred), and where the balls of ``D``'s large, nearly
    cancelling terms, which grow like ``exp(2 zeta)``, would need a fine bisection of the window.
    ``D w`` has the zeros and the signs of ``D``.  The same arguments; the expressions are

    - ``0, 1, 2``: ``D w`` and its first two derivatives in ``zeta``,
    - ``3``: ``P w`` with ``P = dD/dsigma = 2 C1 C2 - kappa S1 S2`` (the window's start),
    - ``4, 5``: the sizes of the terms of ``D w`` for its rounding bound, as
      :func:`term_sizes`: ``sum |t_i|`` and a bound on ``sum |dt_i/dzeta|`` in which each
      exponent's slope ``a_1 nu_1 + a_2 nu_2 + a_0`` counts as ``|a_1| nu_1 + |a_2| nu_2 + |a_0|``
      (the rounding of ``nu_1 + nu_2 - 2`` is relative to its terms, not to the small
      difference).

    Each hyperbolic function is written as exponentials and each product of exponentials as one
    ``exp(zeta (a_1 nu_1 + a_2 nu_2 + a_0))`` with ``a_0 <= -2 + |a_1| + |a_2|`` (``nu_i < 1``
    over-damped): no term overflows.  ``D w`` and ``P w`` are checked against ``w`` times their
    unscaled forms by :func:`analytic.identity.prove_zero`."""
    import sympy as sp

    from analytic.identity import prove_zero

    form = _trace_indicator(regime1, regime2)
    zeta, sigma = form.args[:2]
    w = sp.exp(-2 * zeta)

    def exponentials(e):
        e = e.replace(sp.cosh, lambda x: (sp.exp(x) + sp.exp(-x)) / 2)
        return e.replace(sp.sinh, lambda x: (sp.exp(x) - sp.exp(-x)) / 2)

    def scaled(e):
        e = sp.powsimp(sp.expand(exponentials(e), power_exp=False), combine="exp")
        return e.replace(sp.exp, lambda x: sp.exp(sp.factor_terms(x)))

    plain = (form.exprs[0] * w, sp.diff(form.exprs[0], sigma) * w)
    Dw, Pw = (scaled(e) for e in plain)
    for e, sc in zip(plain, (Dw, Pw), strict=True):
        same = prove_zero(exponentials(e) - sc).holds
        if sc.has(sp.cosh, sp.sinh) or not same:  # pragma: no cover - derivation guard
            raise AssertionError(f"scaled trace form is not {e}: {sc}")
    total, slope = [], []
    for t in sp.Add.make_args(Dw):
        exps = [f for f in sp.Mul.make_args(t) if isinstance(f, sp.exp)]
        coef = sp.Mul(*(f for f in sp.Mul.make_args(t) if not isinstance(f, sp.exp)))
        rates = [sp.expand(sp.diff(f.args[0], zeta)) for f in exps]
        grow = sp.Add(*(sp.Abs(a) for r in rates for a in sp.Add.make_args(r)))
        size = sp.Mul(*exps)
        total.append(sp.Abs(coef) * size)
        slope.append((sp.Abs(sp.diff(coef, zeta)) + sp.Abs(coef) * grow) * size)
    exprs = _derivatives(Dw, zeta, 2) + (Pw, sp.Add(*total), sp.Add(*slope))
    title = f"trace indicator times exp(-2 zeta), half 1 {regime1}, half 2 {regime2}"
    return Form(title, form.args, exprs)


@cache
def trace_window(regime1) -> LazyForm:
    """``(C1, S1)`` of half 1 (see :func:`_trace_window`), derived when first needed beyond its
    pregenerated compilations."""
    return LazyForm(f"trace_window({regime1})", lambda: _trace_window(regime1))


@cache
def _trace_window(regime1) -> Form:
    """``(C1, S1)`` of half 1 as a form of ``(zeta, sigma, kappa, nu1, nu2)`` (for the phase
    ``Phi = nu2 zeta + atan2(kappa S1, 2 nu2 C1)`` that numbers the orders)."""
    s = _symbols()
    C1, S1 = half_period_forms(regime1)
    args = tuple(s[k] for k in ("zeta", "sigma", "kappa", "nu1", "nu2"))
    return Form(f"half 1 functions, {regime1}", args, (C1, S1))


@cache
def fixed_point_map(parity, damped: bool) -> Form:
    """The paper's iteration map (eqs. 15, 26 without friction; 39, 44 with it), derived here from
    the same equations the solvers use, solved for ``sin(theta)`` by sympy:

    * no friction: the edge equation solved for ``sin(theta)``, written with the paper's sign
      convention ``sin(theta) = s r f(beta (c + theta))`` (``s = -1`` is what the paper calls the
      lower edge, eqs. 15, 26; ``s = +1`` the upper); map ``theta -> asin(s r f(...))``;
      arguments ``(theta, c, r, beta, s)``;
    * friction: ``sin(theta)^2 = R(theta)`` solved for ``sin(theta) = s sqrt(R)`` (eqs. 39, 44, with
      ``s = -+1``); map ``theta -> asin(s sqrt(R(theta)))``; arguments
      ``(theta, c, r2, u, beta, g, s)``.

    The iteration starts from ``theta = 0`` (the paper's ``Delta T = 0``).
    """
    import sympy as sp

    s = _symbols()
    th, c, r, beta = (s[k] for k in ("theta", "c", "r", "beta"))
    branch = sp.Symbol("s", real=True)
    Z = sp.Symbol("Z", real=True)
    if not damped:
        F = edge_equation(parity).exprs[0]
        (rhs,) = sp.solve(F.subs(sp.sin(th), Z), Z)  # (+-) eps sgn r f(beta (c + theta))
        unit = sp.expand(rhs / (s["eps"] * s["sgn"]))
        if unit.could_extract_minus_sign():
            unit = -unit
        rhs = branch * unit  # the edge-picking sign eps sgn becomes the paper's sign s
        args = (th, c, r, beta, branch)
    else:
        form = indicator(parity)
        D = form.exprs[0]
        sols = sp.solve((D + sp.sin(th) ** 2 - Z**2).subs(sp.sin(th), 0), Z)
        root = [e for e in sols if not sp.Mul.make_args(e)[0].could_extract_minus_sign()]
        if len(root) != 1:  # pragma: no cover - derivation guard
            raise AssertionError(f"unexpected solutions {sols}")
        rhs = branch * root[0]
        args = (th, c, s["r2"], s["u"], beta, s["g"], branch)
    title = f"fixed-point map, {'with' if damped else 'without'} friction"
    return Form(title, args, (sp.asin(rhs),))


@cache
def regime_roots(name: str) -> LazyForm:
    """:func:`_regime_roots` of the built-in law ``name`` (:data:`analytic.system.LAWS`), derived
    when first needed beyond its pregenerated compilation (:data:`verify.forms_generated.SOURCES`):
    ``compiled("exact")(g2, e2)`` gives the roots as exact fractions of ``g2 = gamma^2/omega0^2``
    and the squared margin ``e2``."""
    return LazyForm(f"regime_roots({name})", lambda: _regime_roots(name))


@cache
def _regime_roots(name: str) -> Form:
    """The depths ``m`` where ``omega_1^2``, ``omega_2^2`` or ``omega_1^2 / (1 + e2)`` equal ``g2
    = gamma^2/omega0^2``, solved by sympy for the law ``name``: a form of ``(g2, e2)`` whose one
    expression is the list of the roots (the paper's ``4 Q^2 - 1 = +-m``, ...; ``e2`` is the
    square of the caller's margin to critical damping, :data:`verify.params.NEAR_CRITICAL`).
    Each root must be a rational function of ``g2`` and ``e2``, so that it is exact at rational
    arguments (derivation guard)."""
    import sympy as sp

    from analytic.model import S
    from analytic.system import system

    g2, e2 = sp.symbols("g2 e2", positive=True)
    w1, w2, _ = (sp.sympify(v) for v in system(name).values(S.m))
    roots = []
    for eq in (w1 - g2, w2 - g2, w1 - g2 * (1 + e2)):
        roots.extend(sp.solve(sp.numer(sp.together(eq)), S.m))
    for root in roots:
        if not root.is_rational_function(g2, e2):  # pragma: no cover - derivation guard
            raise AssertionError(f"a critical depth of {name} is not rational in g2: {root}")
    return Form(f"critical depths of {name}", (g2, e2), (roots,))
