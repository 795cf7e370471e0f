"""``sympy.factor`` with the multivariate factoring over the integers done by FLINT.

sympy factors a multivariate polynomial over ``Z`` by Wang's algorithm, which starts from a prime
above the Mignotte bound of the coefficients.  For a duty with many digits (``D = 1e-300``) the
parameter forms of :mod:`analytic.family` have coefficients of thousands of bits, and the search
for that prime (probable-prime tests of numbers of that size) takes minutes, while the
factorisation itself is trivial.  :func:`factor` is :func:`sympy.factor` with that one step, the
factorisation of a primitive square-free polynomial into irreducibles, done by FLINT
(``fmpz_mpoly.factor`` of python-flint) and checked: the factors multiply back to the polynomial
exactly and each is normalised as sympy normalises its own (primitive, positive leading
coefficient in sympy's order of the variables).  The factorisation into irreducibles over ``Z`` is
unique up to those signs, so the result is the expression sympy itself returns; everything around
that step (contents, square-free parts, multiplicities, the order of the factors, the expression
built) is sympy's own.  Where python-flint has no multivariate polynomials, sympy's algorithm runs.
"""

from __future__ import annotations

import threading
from collections.abc import Iterator
from contextlib import contextmanager

import sympy as sp

__all__ = ["factor", "flint_factoring"]

_LOCK = threading.RLock()


def _flint_wang(f, u, K, mod=None, seed=None):
    """The irreducible factors of the primitive, square-free ``f`` in ``Z[x_0, ..., x_u]`` (sympy's
    dense recursive form over ``K = ZZ``), as :func:`sympy.polys.factortools.dmp_zz_wang` returns
    them: each primitive, with a positive leading coefficient."""
    from flint import fmpz_mpoly_ctx
    from sympy.polys.densearith import dmp_neg
    from sympy.polys.densebasic import dmp_from_dict, dmp_ground_LC, dmp_to_dict
    from sympy.polys.densetools import dmp_ground_primitive

    names = tuple(f"x{i}" for i in range(u + 1))
    ctx = fmpz_mpoly_ctx.get(names, "lex")
    poly = ctx.from_dict({mon: int(c) for mon, c in dmp_to_dict(f, u, K).items()})
    content, pairs = poly.factor()
    out = []
    product = ctx.from_dict({}) + int(content)
    for g, e in pairs:
        product *= g**e
        h = dmp_from_dict({mon: K(int(c)) for mon, c in g.to_dict().items()}, u, K)
        _, h = dmp_ground_primitive(h, u, K)
        if K.is_negative(dmp_ground_LC(h, u, K)):
            h = dmp_neg(h, u, K)
        out.append(h)
    if product != poly or any(e != 1 for _, e in pairs) or abs(int(content)) != 1:
        raise ArithmeticError("FLINT's factors do not multiply back to the polynomial")
    return out


def _available() -> bool:
    try:
        from flint import fmpz_mpoly_ctx

        fmpz_mpoly_ctx.get(("x0",), "lex")
    except (ImportError, AttributeError, TypeError):  # pragma: no cover - older python-flint
        return False
    return True


@contextmanager
def flint_factoring() -> Iterator[None]:
    """Within the block, sympy factors multivariate polynomials over ``Z`` with FLINT (see the
    module's text); the results are the same.  One thread at a time (sympy is patched)."""
    from sympy.polys import factortools

    if not (_available() and hasattr(factortools, "dmp_zz_wang")):  # pragma: no cover
        yield  # an older python-flint, or a sympy without this step: sympy's own algorithm
        return
    with _LOCK:
        original = factortools.dmp_zz_wang
        factortools.dmp_zz_wang = _flint_wang
        try:
            yield
        finally:
            factortools.dmp_zz_wang = original


def factor(expr) -> sp.Expr:
    """:func:`sympy.factor` of ``expr`` (the same expression), fast for huge coefficients."""
    with flint_factoring():
        return sp.factor(expr)
