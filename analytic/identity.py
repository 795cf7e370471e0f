"""Deciding whether two formulas agree: symbolically when sympy can, else at many random points.

Every "agrees" in the engine goes through :func:`prove_zero` (an expression vanishes identically) or
:func:`prove_proportional` (two residuals differ by a factor that is a non-zero constant).  The
symbolic route rewrites trigonometric and hyperbolic functions as exponentials and expands; that
decides sums of products of exponentials of linear forms, which is what stitching produces.  Where
it
does not reach zero the expression is evaluated at random points of the physical domain at high
precision, and the result says which route decided it.
"""

from __future__ import annotations

import functools
import random
from dataclasses import dataclass

import mpmath
import sympy as sp
from sympy.polys.fields import sfield

__all__ = [
    "Verdict",
    "prove_zero",
    "prove_proportional",
    "exponential_polynomial",
    "factor_between",
    "prove_multiple",
    "vanishes",
    "expanded_polynomial",
    "random_points",
    "DOMAIN",
]

#: The physical domain of each primary symbol, for random sampling: (low, high).
DOMAIN: dict[str, tuple[float, float]] = {
    "m": (0.01, 0.95),
    "tau": (0.2, 6.0),
    "T": (0.2, 6.0),
    "Q": (1.5, 40.0),
    "t": (-3.0, 3.0),
    "theta": (-1.2, 1.2),
    "psi": (0.3, 9.0),
    "omega_1": (0.5, 8.0),
    "omega_2": (0.5, 8.0),
    "omega_0": (0.5, 8.0),
    "gamma": (0.01, 0.4),
    "A_1": (-2.0, 2.0),
    "B_1": (-2.0, 2.0),
    "A_2": (-2.0, 2.0),
    "B_2": (-2.0, 2.0),
    "A": (-2.0, 2.0),
    "B": (-2.0, 2.0),
}


@dataclass(frozen=True)
class Verdict:
    """Outcome of an identity check.

    ``holds``: whether the identity holds; ``route``: ``"symbolic"`` (simplified to zero / to a
    constant) or ``"numeric"`` (``points`` random points at ``dps`` digits, worst value ``worst``).
    """

    holds: bool
    route: str
    points: int = 0
    dps: int = 0
    worst: float = 0.0
    factor: sp.Expr | None = None

    def describe(self) -> str:
        if self.route == "symbolic":
            what = "simplifies symbolically to zero"
            if self.factor is not None and self.factor != 1:
                what = f"equal up to the constant factor {sp.sstr(self.factor)} (symbolic)"
            return what
        return (
            f"checked numerically at {self.points} random points with {self.dps} digits "
            f"(largest relative residual {self.worst:.1e}); sympy did not reduce it to zero"
        )


_TRIG = (sp.sin, sp.cos, sp.tan, sp.sinh, sp.cosh, sp.tanh)


@functools.lru_cache(maxsize=4096)
def _trig_as_exponentials(f: sp.Expr) -> sp.Expr:
    """One trigonometric or hyperbolic function value rewritten as exponentials."""
    return f.rewrite(_TRIG, sp.exp)


def _as_exponentials(e: sp.Expr) -> sp.Expr:
    """``e.rewrite(_TRIG, exp)``: each function value of ``_TRIG`` rewritten once (remembered
    across expressions) and put in place by one ``xreplace`` -- the same expression."""
    found = e.atoms(*_TRIG)
    if not found:
        return e
    return e.xreplace({f: _trig_as_exponentials(f) for f in found})


def _z_mapping(exprs):
    """The expressions as polynomials in fresh symbols for the exponentials, and the map back
    (see :func:`exponential_polynomial`)."""
    return _z_mapping_of(tuple(sp.sympify(e) for e in exprs))


@functools.lru_cache(maxsize=32)
def _z_mapping_of(exprs: tuple):
    """:func:`_z_mapping` of a tuple of sympy expressions, remembered: a check looks at the same
    pair first for a structural screen, then for the exact factor."""
    rewritten = [_as_exponentials(e) for e in exprs]
    exps = set().union(*(e.atoms(sp.exp) for e in rewritten))
    terms = {ex: sp.Add.make_args(sp.expand(ex.args[0])) for ex in exps}
    monos: dict[sp.Expr, list[sp.Rational]] = {}
    for ex in exps:
        for term in terms[ex]:
            c, rest = term.as_coeff_Mul()
            monos.setdefault(rest, []).append(sp.Rational(c))
    zs = {}
    for k, (mono, cs) in enumerate(
        sorted(monos.items(), key=lambda kv: sp.default_sort_key(kv[0]))
    ):
        lcm = 1
        for c in cs:
            lcm = sp.ilcm(lcm, c.q)
        zs[mono] = (sp.Symbol(f"_z{k}"), lcm)
    rep = {}
    for ex in exps:
        val = sp.Integer(1)
        for term in terms[ex]:
            c, rest = term.as_coeff_Mul()
            z, lcm = zs[rest]
            val *= z ** (c * lcm)
        rep[ex] = val
    back = {z: sp.exp(mono / lcm) for mono, (z, lcm) in zs.items()}
    return tuple(e.xreplace(rep) for e in rewritten), back


def exponential_polynomial(*exprs: sp.Expr) -> list[sp.Expr]:
    """Rewrite trigonometric and hyperbolic functions as exponentials, then each exponential as a
    monomial in fresh symbols ``_z0, _z1, ...`` (one per linear form in the exponents), with one
    mapping shared by all ``exprs``.

    An expression built from sums and products of such functions with rational coefficients becomes
    a rational function; it vanishes identically iff that rational function is zero.  Only the
    functions in ``_TRIG`` are rewritten (``x**2`` must not become ``exp(2 log x)``).
    """
    return list(_z_mapping(exprs)[0])


class _Unfit(Exception):
    """An expression that :func:`_ring_field_elements` does not take (sympy's ``sfield`` does)."""


def _scan(expr, gens: set, seen: dict) -> bool:
    """Collect the generators of ``expr`` into ``gens`` (symbols only); whether ``I`` occurs."""
    if expr in seen:
        return seen[expr]
    has_i = False
    if expr.is_Add or expr.is_Mul:
        for a in expr.args:
            has_i |= _scan(a, gens, seen)
    elif expr is sp.I:
        has_i = True
    elif expr.is_Rational:
        pass
    elif expr.is_Pow and expr.exp.is_Integer:
        has_i = _scan(expr.base, gens, seen)
    elif expr.is_Symbol:
        gens.add(expr)
    else:  # a float, a root, a function: left to sfield
        raise _Unfit
    seen[expr] = has_i
    return has_i


def _ring_field_elements(exprs):
    """What ``sfield(exprs)`` gives for sums, products and integer powers of symbols with
    rational (or Gaussian-rational) coefficients: the same field (generators sorted as sympy
    sorts them, integer coefficients) and the same elements, computed by ring arithmetic on
    the expression tree instead of sympy's ``expand``.  Each sub-expression is a numerator and a
    product of denominator factors, so a sum is taken over the least common multiple of its
    terms' factors; one cancellation per element at the end.  Raises :class:`_Unfit` for
    anything else, and where a Gaussian coefficient is left after the arithmetic (whose
    cancellation sympy does over ``ZZ_I``)."""
    from sympy.polys.domains import ZZ, ZZ_I
    from sympy.polys.fields import FracField
    from sympy.polys.orderings import lex
    from sympy.polys.polyoptions import build_options
    from sympy.polys.polyutils import _sort_gens

    gens: set = set()
    seen: dict = {}
    has_i = False
    for e in exprs:
        has_i |= _scan(e, gens, seen)
    gens = _sort_gens(gens, opt=build_options((), {}))
    domain = ZZ_I if has_i else ZZ
    ring = FracField(gens, domain, lex).ring
    index = dict(zip(gens, ring.gens, strict=True))
    one = ring.one
    memo: dict = {}

    def product(den: dict):
        out = one
        for f, p in den.items():
            out = out * f**p
        return out

    def power(num, den: dict, e: int):
        if e >= 0:
            return num**e, {f: p * e for f, p in den.items()}
        if not num:
            raise ZeroDivisionError("a power of zero with a negative exponent")
        return product(den) ** -e, {num: -e}

    def conv(expr):
        """``(numerator, {denominator factor: power})`` of ``expr``."""
        if expr in memo:
            return memo[expr]
        if expr.is_Add:
            parts = [conv(a) for a in expr.args]
            lcm: dict = {}
            for _, d in parts:
                for f, p in d.items():
                    if lcm.get(f, 0) < p:
                        lcm[f] = p
            num = ring.zero
            for n, d in parts:
                num = num + n * product({f: p - d.get(f, 0) for f, p in lcm.items()})
            out = (num, lcm)
        elif expr.is_Mul:
            num, den = one, {}
            for a in expr.args:
                n, d = conv(a)
                num = num * n
                for f, p in d.items():
                    den[f] = den.get(f, 0) + p
            out = (num, den)
        elif expr is sp.I:
            out = (ring(domain.from_sympy(sp.I)), {})
        elif expr.is_Integer:
            out = (ring(int(expr)), {})
        elif expr.is_Rational:
            out = (ring(expr.p), {ring(expr.q): 1})
        elif expr.is_Pow:
            out = power(*conv(expr.base), int(expr.exp))
        else:
            out = (index[expr], {})
        memo[expr] = out
        return out

    pairs = [(n, product(d)) for n, d in map(conv, exprs)]
    return FracField(gens, ZZ, lex), has_i, pairs


def _flint_parts(field, has_i: bool, poly):
    """A polynomial of :func:`_ring_field_elements` as ``(real part, imaginary part)`` in
    FLINT's ``fmpz_mpoly`` (the same generators, in the same lexicographic order)."""
    from flint import fmpz_mpoly_ctx

    ctx = fmpz_mpoly_ctx.get(tuple(f"x{i}" for i in range(field.ring.ngens)), "lex")
    if not has_i:
        return ctx.from_dict(dict(poly)), ctx.from_dict({})
    re = {k: int(c.x) for k, c in poly.items() if c.x}
    im = {k: int(c.y) for k, c in poly.items() if c.y}
    return ctx.from_dict(re), ctx.from_dict(im)


def _cancel(field, num, den):
    """``num/den`` (``fmpz_mpoly``, ``den`` not zero) as the element of ``field`` that sympy's
    cancellation gives: numerator and denominator coprime (their greatest common divisor,
    content included, taken by FLINT), the denominator's leading coefficient positive."""
    ring = field.ring
    if num == 0:
        return field.raw_new(ring.zero, ring.one)
    g = num.gcd(den)
    if g != 1:
        num, den = num / g, den / g
    p = ring.from_dict(num.to_dict())
    q = ring.from_dict(den.to_dict())
    if q.LC < 0:
        p, q = -p, -q
    return field.raw_new(p, q)


def _fast_parts(exprs):
    """The field of :func:`_ring_field_elements` for ``exprs`` and each expression's numerator
    and denominator as FLINT parts (:func:`_flint_parts`)."""
    field, has_i, pairs = _ring_field_elements(exprs)
    return field, [tuple(_flint_parts(field, has_i, x) for x in pair) for pair in pairs]


def _element(field, num, den):
    """``num/den`` (FLINT parts) cancelled in ``field``; ``None`` where it keeps an imaginary
    part."""
    (nr, ni), (dr, di) = num, den
    if dr == 0 and di == 0:
        raise ZeroDivisionError("the divisor is zero as a rational function")
    if di != 0:  # multiply by the conjugate of the denominator: dr^2 + di^2 is real
        nr, ni, dr = nr * dr + ni * di, ni * dr - nr * di, dr * dr + di * di
    if ni != 0:
        return None
    return _cancel(field, nr, dr)


def _gauss_mul(a, b):
    (ar, ai), (br, bi) = a, b
    if ai == 0 and bi == 0:
        return ar * br, ai
    return ar * br - ai * bi, ar * bi + ai * br


def _field_elements(exprs):
    """The expressions as elements of one field of rational functions (sympy's sparse ``sfield``,
    much faster than ``cancel`` on large sums; by ring arithmetic and FLINT where that fits, see
    :func:`_ring_field_elements`), or ``None`` if they do not fit one."""
    exprs = [sp.sympify(e) for e in exprs]
    try:
        field, parts = _fast_parts(exprs)
        out = [_element(field, n, d) for n, d in parts]
        if all(x is not None for x in out):
            return out
    except _Unfit:
        pass
    try:
        _, elems = sfield(exprs)
        return elems
    except (
        sp.PolynomialError,
        sp.CoercionFailed,
        ValueError,
        TypeError,
        NotImplementedError,
    ):  # pragma: no cover
        return None


def _depends_on(field, num, den, symbols) -> bool:
    """Whether ``num/den`` (Gaussian FLINT parts, ``den`` not zero) depends on one of
    ``symbols``: its real and imaginary parts (over the real denominator ``|den|^2``) are
    cancelled by their greatest common divisors, and a rational function in lowest terms is free
    of a generator exactly when its numerator and denominator are."""
    (nr, ni), (dr, di) = num, den
    if di != 0:
        nr, ni, dr = nr * dr + ni * di, ni * dr - nr * di, dr * dr + di * di
    index = [k for k, g in enumerate(field.symbols) if g in symbols]
    for part in (nr, ni):
        if part == 0:
            continue
        g = part.gcd(dr)
        for x in (part / g, dr / g):
            degrees = x.degrees()
            if any(degrees[k] > 0 for k in index):
                return True
    return False


def _field_ratio(a: sp.Expr, b: sp.Expr, unless: frozenset = frozenset()) -> sp.Expr | None:
    """``a/b`` cancelled exactly as a rational function (``b`` not zero); ``None`` where that
    ratio keeps an imaginary part and depends on one of the symbols ``unless`` (decided without
    sympy's cancellation over the Gaussian integers; the ratio itself is then not needed)."""

    try:
        field, ((na, da), (nb, db)) = _fast_parts([a, b])
        num, den = _gauss_mul(na, db), _gauss_mul(da, nb)
        r = _element(field, num, den)
        if r is not None:
            return r.as_expr()
        if unless and _depends_on(field, num, den, unless):
            return None
    except _Unfit:
        pass
    elems = _field_elements([a, b])
    return (elems[0] / elems[1]).as_expr() if elems is not None else sp.cancel(a / b)


def factor_between(a: sp.Expr, b: sp.Expr) -> sp.Expr | None:
    """The factor ``F`` with ``a = F * b`` if it is free of the oscillating parts, else ``None``.

    Both sides become rational functions of the exponential monomials
    (:func:`exponential_polynomial`)
    and of the other symbols; their quotient is computed exactly in a field of rational functions,
    so a returned ``F`` is a proof of ``a = F b``.  ``F`` may keep real exponentials
    (``p = exp(-gamma T)``) but no oscillating one.
    """
    (za, zb), back = _z_mapping([a, b])
    if zb == 0:
        return None
    osc = {z for z, e in back.items() if e.args[0].has(sp.I)}
    ratio = _field_ratio(za, zb, unless=frozenset(osc))
    if ratio is None or ratio == 0 or ratio.free_symbols & osc:
        return None
    return sp.factor(ratio).xreplace(back)


def prove_multiple(a: sp.Expr, b: sp.Expr) -> Verdict:
    """Decide whether ``a = F * b`` for a factor ``F`` free of the oscillating parts.

    When :func:`factor_between` finds ``F`` the identity holds by construction (the ratio of the two
    rational functions *is* ``F``), so this is a symbolic proof and ``F`` is recorded in the
    verdict.
    Otherwise falls back to :func:`prove_proportional` (a constant factor, numerically if need be).
    """
    screen = _ratio_screen(a, b)
    if screen is not None:
        return screen
    fac = factor_between(a, b)
    if fac is not None:
        return Verdict(True, "symbolic", factor=fac)
    # the exact ratio depends on an oscillation: not a multiple (the numeric look guards against a
    # relation between the symbols that the rational-function view cannot see)
    return prove_proportional(a, b, points=12, dps=30, numeric_only=True)


def _ratio_screen(a: sp.Expr, b: sp.Expr) -> Verdict | None:
    """A cheap structural look first: if one side oscillates in an argument the other does not
    have, no factor free of oscillations can join them; decide that case numerically (constant
    ratio or not) instead of attempting an expensive cancellation.  ``None``: go on."""
    (za, zb), back = _z_mapping([a, b])
    osc = {z for z, e in back.items() if e.args[0].has(sp.I)}
    if (za.free_symbols & osc) != (zb.free_symbols & osc):
        return prove_proportional(a, b, points=12, dps=30, numeric_only=True)
    return None


def _symbolic_zero(expr: sp.Expr) -> bool:
    if expr == 0:
        return True
    try:
        z = exponential_polynomial(expr)[0]
        elems = _field_elements([z])
        return (elems[0] == 0) if elems is not None else sp.cancel(z) == 0
    except (TypeError, ValueError, NotImplementedError, sp.PolynomialError):  # pragma: no cover
        return False


def vanishes(expr: sp.Expr) -> bool:
    """Whether ``expr`` vanishes identically, decided exactly by the symbolic route of
    :func:`prove_zero` alone (``False`` where that route does not reach zero; no numeric look)."""
    return _symbolic_zero(sp.sympify(expr))


def expanded_polynomial(expr: sp.Expr) -> sp.Expr | None:
    """``expand(cancel(expr))`` where the cancelled ``expr`` is a polynomial (a sum of products of
    symbols with rational coefficients), by the exact field arithmetic of the identity checks
    (:func:`_field_elements`) instead of sympy's ``cancel``; ``None`` where it is not one (or
    ``expr`` is not a rational function of its symbols)."""
    try:
        field, parts = _fast_parts([sp.sympify(expr)])
        elem = _element(field, *parts[0])
    except _Unfit:
        return None
    if elem is None or not elem.denom.is_ground:
        return None
    return sp.expand(elem.as_expr())


def random_points(symbols, count: int, seed: int = 20130101):
    """``count`` dicts of random values for ``symbols`` inside :data:`DOMAIN` (fixed seed)."""
    rng = random.Random(seed)
    out = []
    for _ in range(count):
        point = {}
        for s in symbols:
            lo, hi = DOMAIN.get(s.name, (0.1, 2.0))
            point[s] = sp.Float(rng.uniform(lo, hi), 30)
        out.append(point)
    return out


@functools.lru_cache(maxsize=256)
def _mpmath_function(symbols: tuple, expr: sp.Expr):
    """``lambdify(symbols, expr)`` on mpmath, compiled once per expression (checks meet the same
    side twice); without the docstring, which would print the expression only to document it.
    The symbols (whose names need not be Python identifiers) are renamed to ``_a0``, ``_a1``, ...
    in one walk of the expression, prefixed with underscores until no name of the expression is
    taken."""
    taken = {str(a) for a in expr.atoms(sp.Symbol, sp.Function, sp.core.function.AppliedUndef)}
    taken |= {type(f).__name__ for f in expr.atoms(sp.core.function.AppliedUndef)}
    prefix = "_a"
    while any(t.startswith(prefix) for t in taken):
        prefix = "_" + prefix
    new = {s: sp.Symbol(f"{prefix}{i}") for i, s in enumerate(symbols)}
    return sp.lambdify(
        tuple(new[s] for s in symbols),
        expr.xreplace(new),
        modules="mpmath",
        dummify=False,
        docstring_limit=0,
    )


def _numeric_zero(expr: sp.Expr, scale: sp.Expr, points: int, dps: int) -> tuple[bool, float]:
    symbols = tuple(sorted(expr.free_symbols | scale.free_symbols, key=lambda s: s.name))
    f = _mpmath_function(symbols, expr)
    h = _mpmath_function(symbols, scale)
    worst = mpmath.mpf(0)
    tol = mpmath.mpf(10) ** (-(dps - 10))
    with mpmath.workdps(dps):
        for pt in random_points(symbols, points):
            args = [mpmath.mpf(str(pt[s])) for s in symbols]
            try:
                val = f(*args)
                ref = h(*args)
            except (ZeroDivisionError, ValueError):
                continue
            val = abs(mpmath.mpmathify(val))
            ref = abs(mpmath.mpmathify(ref))
            rel = val / ref if ref > tol else val
            worst = max(worst, rel)
    return worst < tol, float(worst)


def prove_zero(
    expr: sp.Expr, *, scale: sp.Expr | None = None, points: int = 24, dps: int = 40
) -> Verdict:
    """Decide whether ``expr`` vanishes identically on the physical domain.

    ``scale`` (default: 1) sets what a residual is measured against in the numeric route; pass the
    size of the terms that cancel so that the check is relative.
    """
    expr = sp.sympify(expr)
    if _symbolic_zero(expr):
        return Verdict(True, "symbolic")
    scale = sp.Integer(1) if scale is None else sp.sympify(scale)
    ok, worst = _numeric_zero(expr, scale, points, dps)
    return Verdict(ok, "numeric", points, dps, worst)


def prove_proportional(
    a: sp.Expr, b: sp.Expr, *, points: int = 24, dps: int = 40, numeric_only: bool = False
) -> Verdict:
    """Decide whether ``a = c * b`` for a non-zero constant ``c`` (two forms of one equation ``=
    0``).

    Tries ``a - b`` and ``a + b`` symbolically first (unless ``numeric_only``), then the ratio
    ``a / b`` at random points.
    """
    a, b = sp.sympify(a), sp.sympify(b)
    if not numeric_only:
        for c in (sp.Integer(1), sp.Integer(-1)):
            if _symbolic_zero(a - c * b):
                return Verdict(True, "symbolic", factor=c)
        za, zb = exponential_polynomial(a, b)
        ratio = sp.cancel(za / zb)
        if ratio.free_symbols == set() and ratio != 0:
            return Verdict(True, "symbolic", factor=ratio)
    symbols = tuple(sorted(a.free_symbols | b.free_symbols, key=lambda s: s.name))
    fa = _mpmath_function(symbols, a)
    fb = _mpmath_function(symbols, b)
    ratios = []
    with mpmath.workdps(dps):
        for pt in random_points(symbols, points):
            args = [mpmath.mpf(str(pt[s])) for s in symbols]
            try:
                va, vb = mpmath.mpmathify(fa(*args)), mpmath.mpmathify(fb(*args))
            except (ZeroDivisionError, ValueError):
                continue
            if abs(vb) < mpmath.mpf(10) ** (-dps // 2):
                continue
            ratios.append(va / vb)
        if not ratios:
            return Verdict(False, "numeric", points, dps, float("inf"))
        c0 = ratios[0]
        worst = max(abs(rt - c0) / max(abs(c0), mpmath.mpf(1)) for rt in ratios)
        ok = abs(c0) > mpmath.mpf(10) ** (-10) and worst < mpmath.mpf(10) ** (-(dps - 10))
        factor = sp.nsimplify(sp.Float(str(c0), 20), rational=True) if ok else None
    return Verdict(ok, "numeric", len(ratios), dps, float(worst), factor)
