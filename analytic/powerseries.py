"""Truncated power series with exact coefficients, and the evaluation of sympy formulas as series.

The expansions of :mod:`analytic.expansions` and :mod:`analytic.thresholds` solve equations that
:mod:`analytic.normal_form` derives (sympy expressions in ``theta``, ``r``, ``beta``, ``g``, and the
parameters as functions of ``m`` and ``Q``) order by order in a small variable.  ``sympy.series`` on
such expressions is slow and its cost grows fast with the order; here the same expressions are
*evaluated* node by node in truncated power-series arithmetic instead:

* a coefficient is a Laurent polynomial over the rationals in a few named generators (``pi``, ``n``,
  the friction parameters ...), stored as ``{exponents: fmpq}``; one generator may be subject to a
  quadratic relation (``nu**2 = 1 - s**2``), which keeps the normal form of every coefficient
  unique, so that "is this coefficient zero" is decided exactly;
* a series is the list of its coefficients of ``var**0 .. var**P`` (everything beyond is dropped);
* sums, products, inverses, rational powers and ``sin, cos, sinh, cosh, exp`` of series are exact
  operations on the truncated series (the functions only of arguments without a constant term, or
  with a constant term for ``Pow``, whose leading coefficient must be a monomial with an exact
  root).

:func:`evaluate` maps a sympy expression to a :class:`Series` given what each free symbol stands
for; :meth:`Series.to_sympy` maps back.  Nothing here knows about pendulums.
"""

from __future__ import annotations

import functools
import math
from collections.abc import Iterable, Mapping, Sequence

import sympy as sp
from flint import fmpq

__all__ = [
    "LaurentRing",
    "Series",
    "evaluate",
    "fixed_parts",
    "newton",
    "newton_doubling",
    "reversion",
]


def _q(x) -> fmpq:
    if isinstance(x, fmpq):
        return x
    if isinstance(x, int):
        return fmpq(x)
    if isinstance(x, sp.Rational):
        return fmpq(int(x.p), int(x.q))
    raise TypeError(f"not an exact rational: {x!r}")


def _iroot(a: int, k: int) -> int | None:
    """The exact ``k``-th root of the integer ``a >= 0``, or ``None``."""
    if a < 0:
        return None
    if k == 2:
        r = math.isqrt(a)
        return r if r * r == a else None
    r = round(a ** (1.0 / k)) if a < 2**1000 else int(math.exp(math.log(a) / k))
    for c in (r - 1, r, r + 1):
        if c >= 0 and c**k == a:
            return c
    lo, hi = 0, 1 << (a.bit_length() // k + 1)
    while lo < hi:
        mid = (lo + hi) // 2
        if mid**k < a:
            lo = mid + 1
        else:
            hi = mid
    return lo if lo**k == a else None


#: products of ring elements with more pairs of terms than this go through FLINT
_FLINT_TERMS = 48


def _mul_coeff_flint(nv: int, a: dict, b: dict) -> dict:
    """The product of two Laurent polynomials (dicts) as one ``fmpq_mpoly`` product, exponents
    shifted to be nonnegative and back (exact; no zero terms)."""
    lo_a = [min(k[g] for k in a) for g in range(nv)]
    lo_b = [min(k[g] for k in b) for g in range(nv)]
    ctx = _mpoly_ctx(nv - 1) if nv else None
    if ctx is None:
        return {(): next(iter(a.values())) * next(iter(b.values()))}
    pa = ctx.from_dict(
        {tuple(x - y for x, y in zip(k, lo_a, strict=True)): v for k, v in a.items()}
    )
    pb = ctx.from_dict(
        {tuple(x - y for x, y in zip(k, lo_b, strict=True)): v for k, v in b.items()}
    )
    lo = [x + y for x, y in zip(lo_a, lo_b, strict=True)]
    prod = pa * pb
    return {
        tuple(x + y for x, y in zip(k, lo, strict=True)): v
        for k, v in zip(prod.monoms(), prod.coeffs(), strict=True)
    }


def _plain_base(b: sp.Expr) -> bool:
    return b is sp.pi or b.is_Symbol or not b.is_number


def _times_rational(c: sp.Rational, mono: sp.Expr) -> sp.Expr:
    """``c * mono``, the same expression as sympy's product, without its general flattening
    where the product is plain: ``mono`` a symbol, ``pi``, a power of a base that is not a
    number (or is ``pi``), or a product of these with a rational coefficient ``a``; then
    sympy's canonical product is ``c a`` (dropped if 1) followed by the factors (the tests
    compare the two)."""
    factors = mono.args if mono.is_Mul else (mono,)
    coeff = c
    if factors[0].is_Rational:  # the rational coefficient of mono
        coeff, factors = c * factors[0], factors[1:]
    plain = (
        c != 0
        and coeff != 0
        and bool(factors)
        and all(f.is_Symbol or f is sp.pi or (f.is_Pow and _plain_base(f.base)) for f in factors)
    )
    if not plain:
        return c * mono
    if coeff == 1:
        return factors[0] if len(factors) == 1 else sp.Mul._from_args(factors)
    return sp.Mul._from_args((coeff, *factors))


class LaurentRing:
    """Laurent polynomials over ``Q`` in the generators ``gens``.

    ``relation = (name, square)`` declares ``name**2 = square`` (``square`` a dict element of this
    ring, free of ``name``); every product is reduced so that ``name`` appears at most to the first
    power.  Elements are plain dicts ``{exponent tuple: fmpq}`` without zero entries.
    """

    def __init__(self, gens: Sequence[str], relation: tuple[str, Mapping] | None = None):
        self.gens = tuple(gens)
        self.index = {g: i for i, g in enumerate(self.gens)}
        self.nvars = len(self.gens)
        self.zero: dict = {}
        self.one = {(0,) * self.nvars: fmpq(1)}
        self._rel_index = None
        self._rel_powers: list[dict] = []
        if relation is not None:
            name, square = relation
            self._rel_index = self.index[name]
            if any(e[self._rel_index] for e in square):
                raise ValueError("the relation's right-hand side must be free of its generator")
            self._rel_powers = [self.one, dict(square)]

    # -- construction -------------------------------------------------------------------------
    def const(self, c) -> dict:
        c = _q(c)
        return {(0,) * self.nvars: c} if c != 0 else {}

    def gen(self, name: str, power: int = 1) -> dict:
        e = [0] * self.nvars
        e[self.index[name]] = power
        out = {tuple(e): fmpq(1)}
        return self._reduce(out) if self._rel_index is not None else out

    def monomial(self, coeff, exps: Mapping[str, int]) -> dict:
        e = [0] * self.nvars
        for k, v in exps.items():
            e[self.index[k]] = v
        return self.mul(self.const(coeff), self._reduce({tuple(e): fmpq(1)}))

    # -- arithmetic ---------------------------------------------------------------------------
    @staticmethod
    def add(a: dict, b: dict) -> dict:
        if not a:
            return b
        if not b:
            return a
        out = dict(a)
        for k, v in b.items():
            w = out.get(k)
            if w is None:
                out[k] = v
            else:
                w = w + v
                if w == 0:
                    del out[k]
                else:
                    out[k] = w
        return out

    @staticmethod
    def neg(a: dict) -> dict:
        return {k: -v for k, v in a.items()}

    def sub(self, a: dict, b: dict) -> dict:
        return self.add(a, self.neg(b))

    @staticmethod
    def scale(a: dict, c) -> dict:
        c = _q(c)
        if c == 0:
            return {}
        return {k: v * c for k, v in a.items()}

    def mul(self, a: dict, b: dict) -> dict:
        if not a or not b:
            return {}
        r = self._rel_index
        # the constrained generator's square occurs only if both factors hold it
        rel = r is not None and any(k[r] for k in a) and any(k[r] for k in b)
        if len(a) * len(b) > _FLINT_TERMS:
            out = _mul_coeff_flint(self.nvars, a, b)
            return self._reduce(out) if rel else out
        out: dict = {}
        for ka, va in a.items():
            for kb, vb in b.items():
                k = tuple(x + y for x, y in zip(ka, kb, strict=False))
                w = out.get(k)
                out[k] = va * vb if w is None else w + va * vb
        out = {k: v for k, v in out.items() if v != 0}
        if rel:
            out = self._reduce(out)
        return out

    def _rel_power(self, j: int) -> dict:
        while len(self._rel_powers) <= j:
            self._rel_powers.append(self._mul_plain(self._rel_powers[-1], self._rel_powers[1]))
        return self._rel_powers[j]

    def _mul_plain(self, a: dict, b: dict) -> dict:
        out: dict = {}
        for ka, va in a.items():
            for kb, vb in b.items():
                k = tuple(x + y for x, y in zip(ka, kb, strict=False))
                out[k] = out.get(k, fmpq(0)) + va * vb
        return {k: v for k, v in out.items() if v != 0}

    def _reduce(self, a: dict) -> dict:
        i = self._rel_index
        if i is None or all(0 <= k[i] < 2 for k in a):
            return a
        out: dict = {}
        for k, v in a.items():
            e = k[i]
            if 0 <= e < 2:
                out[k] = out.get(k, fmpq(0)) + v
                continue
            if e < 0:
                raise ValueError(f"negative power of the constrained generator {self.gens[i]}")
            base = list(k)
            base[i] = e % 2
            for kr, vr in self._rel_power(e // 2).items():
                kk = tuple(x + y for x, y in zip(base, kr, strict=False))
                out[kk] = out.get(kk, fmpq(0)) + v * vr
        return {k: v for k, v in out.items() if v != 0}

    # -- division by monomials, roots -------------------------------------------------------
    def is_monomial(self, a: dict) -> bool:
        return len(a) == 1 and (self._rel_index is None or next(iter(a))[self._rel_index] == 0)

    def inverse(self, a: dict) -> dict:
        """``1/a`` for a monomial ``a`` (the only units of the ring)."""
        if not self.is_monomial(a):
            raise ZeroDivisionError(
                f"cannot invert the non-monomial coefficient {self.to_sympy(a)}"
            )
        ((k, v),) = a.items()
        return {tuple(-x for x in k): 1 / v}

    def root(self, a: dict, num: int, den: int) -> dict:
        """``a**(num/den)`` for a monomial with an exact root (positive rational coefficient)."""
        if not self.is_monomial(a):
            raise ValueError(f"no exact root of the non-monomial coefficient {self.to_sympy(a)}")
        ((k, v),) = a.items()
        if any(x % den for x in k):
            raise ValueError(f"no exact root of {self.to_sympy(a)}")
        p, q = int(v.p), int(v.q)
        if den > 1:
            if p < 0:
                raise ValueError(f"no real root of {self.to_sympy(a)}")
            rp, rq = _iroot(p, den), _iroot(q, den)
            if rp is None or rq is None:
                raise ValueError(f"no rational root of {self.to_sympy(a)}")
        else:
            rp, rq = p, q
        c = fmpq(rp, rq) ** num if num >= 0 else fmpq(rq, rp) ** (-num)
        return {tuple(x // den * num for x in k): c}

    # -- conversion ---------------------------------------------------------------------------
    def to_sympy(
        self, a: dict, symbols: Mapping[str, sp.Expr] | None = None, monomials: dict | None = None
    ) -> sp.Expr:
        """``a`` as a sympy expression, generators replaced by ``symbols`` (default: their names;
        ``pi`` is sympy's).  ``monomials``: a cache of the products of powers of the generators,
        shared by the calls with the same ``symbols`` (as by :meth:`Series.to_sympy`)."""
        symbols = symbols or {}
        monomials = {} if monomials is None else monomials
        syms = None
        terms = []
        for k, v in a.items():
            mono = monomials.get(k)
            if mono is None:
                if syms is None:
                    syms = [symbols.get(g, sp.pi if g == "pi" else sp.Symbol(g)) for g in self.gens]
                mono = sp.Mul(*(s_**e for s_, e in zip(syms, k, strict=False) if e))
                monomials[k] = mono
            terms.append(_times_rational(sp.Rational(int(v.p), int(v.q)), mono))
        return sp.Add(*terms)


#: products of series with more pairs of nonzero coefficients than this go through FLINT
_FLINT_PAIRS = 8


@functools.cache
def _mpoly_ctx(nvars: int):
    from flint import fmpq_mpoly_ctx

    return fmpq_mpoly_ctx.get(tuple(f"x{i}" for i in range(nvars + 1)), "lex")


def _mul_flint(R: LaurentRing, a, b, nz_a, nz_b, P: int) -> list:
    """The coefficients ``0 .. P`` of the product of the series with coefficients ``a`` and
    ``b`` (nonzero at ``nz_a``, ``nz_b``), as one product of multivariate polynomials over ``Q``
    in FLINT (``fmpq_mpoly``): the series variable is one more generator, and the Laurent
    exponents are shifted to be nonnegative (by the smallest exponent of each generator) and
    back.  Exact: the same coefficients as the term-by-term product, reduced by the ring's
    relation afterwards."""
    nv = R.nvars
    lo_a = [min(k[g] for i in nz_a for k in a[i]) for g in range(nv)]
    lo_b = [min(k[g] for j in nz_b for k in b[j]) for g in range(nv)]
    da = {}
    for i in nz_a:
        for k, v in a[i].items():
            da[(i,) + tuple(x - y for x, y in zip(k, lo_a, strict=True))] = v
    db = {}
    for j in nz_b:
        if j > P:
            break
        for k, v in b[j].items():
            db[(j,) + tuple(x - y for x, y in zip(k, lo_b, strict=True))] = v
    ctx = _mpoly_ctx(nv)
    prod = ctx.from_dict(da) * ctx.from_dict(db)
    lo = [x + y for x, y in zip(lo_a, lo_b, strict=True)]
    out: list = [{} for _ in range(P + 1)]
    shift = any(lo)
    for k, v in zip(prod.monoms(), prod.coeffs(), strict=True):
        i = k[0]
        if i <= P:
            out[i][tuple(x + y for x, y in zip(k[1:], lo, strict=True)) if shift else k[1:]] = v
    r = R._rel_index
    if (
        r is not None
        and any(k[r] for i in nz_a for k in a[i])
        and any(k[r] for j in nz_b for k in b[j])
    ):  # the constrained generator in both factors: its square may occur
        out = [R._reduce(c) for c in out]
    return out


class Series:
    """``sum(c[k] * var**k for k in range(P + 1))``, coefficients in ``ring``; ``P`` = ``prec``."""

    __slots__ = ("ring", "c")

    def __init__(self, ring: LaurentRing, coeffs: Iterable[dict]):
        self.ring = ring
        self.c = list(coeffs)

    # -- construction -------------------------------------------------------------------------
    @classmethod
    def constant(cls, ring: LaurentRing, value: dict, prec: int) -> Series:
        return cls(ring, [value] + [{} for _ in range(prec)])

    @classmethod
    def variable(cls, ring: LaurentRing, prec: int) -> Series:
        c = [{} for _ in range(prec + 1)]
        if prec >= 1:
            c[1] = ring.one
        return cls(ring, c)

    @property
    def prec(self) -> int:
        return len(self.c) - 1

    def valuation(self) -> int | None:
        for k, a in enumerate(self.c):
            if a:
                return k
        return None

    def truncate(self, prec: int) -> Series:
        """Drop the terms beyond ``var**prec`` (never extends: unknown terms are not zeros)."""
        return Series(self.ring, self.c[: prec + 1])

    def padded(self, prec: int) -> Series:
        """Extend with zero coefficients up to ``var**prec``: only for series known to be exact
        (polynomials), e.g. a truncated series that is then treated as a polynomial."""
        return Series(self.ring, self.c + [{} for _ in range(prec + 1 - len(self.c))])

    def shift(self, k: int) -> Series:
        """Multiply by ``var**k``; the precision moves with it (``k < 0`` requires the lowest ``-k``
        coefficients to vanish)."""
        if k >= 0:
            return Series(self.ring, [{} for _ in range(k)] + self.c)
        if any(self.c[:-k]):
            raise ValueError(f"cannot divide by var**{-k}: a lower coefficient does not vanish")
        return Series(self.ring, self.c[-k:])

    def map(self, f) -> Series:
        return Series(self.ring, [f(a) for a in self.c])

    # -- arithmetic ---------------------------------------------------------------------------
    def _coerce(self, other) -> Series:
        if isinstance(other, Series):
            return other
        return Series.constant(self.ring, self.ring.const(other), self.prec)

    def __add__(self, other) -> Series:
        o = self._coerce(other)
        P = min(self.prec, o.prec)
        return Series(self.ring, [self.ring.add(self.c[k], o.c[k]) for k in range(P + 1)])

    __radd__ = __add__

    def __neg__(self) -> Series:
        return self.map(self.ring.neg)

    def __sub__(self, other) -> Series:
        return self + (-self._coerce(other))

    def __rsub__(self, other) -> Series:
        return self._coerce(other) - self

    def __mul__(self, other) -> Series:
        if not isinstance(other, Series):
            c = _q(other)
            return self.map(lambda a: self.ring.scale(a, c))
        P = min(self.prec, other.prec)
        R = self.ring
        a, b = self.c, other.c
        nz_a = [i for i in range(P + 1) if a[i]]
        nz_b = [j for j in range(P + 1) if b[j]]
        if len(nz_a) * len(nz_b) > _FLINT_PAIRS:
            return Series(R, _mul_flint(R, a, b, nz_a, nz_b, P))
        out = [{} for _ in range(P + 1)]
        for i in nz_a:
            for j in nz_b:
                if i + j > P:
                    break
                out[i + j] = R.add(out[i + j], R.mul(a[i], b[j]))
        return Series(R, out)

    __rmul__ = __mul__

    def scale_coeff(self, a: dict) -> Series:
        """Multiply every coefficient by the ring element ``a``."""
        return self.map(lambda x: self.ring.mul(x, a))

    def inverse(self) -> Series:
        R = self.ring
        if not self.c[0]:
            raise ZeroDivisionError("series without a constant term has no inverse")
        inv0 = R.inverse(self.c[0])
        out = [inv0]
        for k in range(1, self.prec + 1):
            acc: dict = {}
            for j in range(1, k + 1):
                if self.c[j] and out[k - j]:
                    acc = R.add(acc, R.mul(self.c[j], out[k - j]))
            out.append(R.neg(R.mul(acc, inv0)))
        return Series(R, out)

    def __truediv__(self, other) -> Series:
        if not isinstance(other, Series):
            return self * (1 / _q(other))
        return self * other.inverse()

    def __rtruediv__(self, other) -> Series:
        return self._coerce(other) * self.inverse()

    def __pow__(self, e) -> Series:
        if isinstance(e, int) or (isinstance(e, sp.Integer)):
            e = int(e)
            if e < 0:
                return self.inverse() ** (-e)
            result = Series.constant(self.ring, self.ring.one, self.prec)
            base = self
            while e:
                if e & 1:
                    result = result * base
                e >>= 1
                if e:
                    base = base * base
            return result
        return self.rational_power(sp.Rational(e))

    def rational_power(self, e: sp.Rational) -> Series:
        """``self**e`` for rational ``e``: ``c var**v (1 + t)**e``, ``c`` the leading
        coefficient."""
        e = sp.Rational(e)
        if e.q == 1:
            return self ** int(e)
        v = self.valuation()
        if v is None:
            raise ValueError("power of the zero series")
        if (v * e.p) % e.q:
            raise ValueError(f"var**{v} has no power {e} in integer exponents")
        R = self.ring
        lead = self.c[v]
        inv_lead = R.inverse(lead)
        unit = self.shift(-v).scale_coeff(inv_lead)  # 1 + t, with precision prec - v
        t = unit - 1
        out = _binomial_series(t, e)
        out = out.scale_coeff(R.root(lead, int(e.p), int(e.q)))
        shift = v * e.p // e.q
        if shift >= 0:
            return out.shift(shift).truncate(self.prec - v + shift)
        raise ValueError("negative power of a series without constant term")

    # -- elementary functions of a series without constant term ---------------------------------
    def _taylor(self, coeffs) -> Series:
        if self.c[0]:
            raise ValueError("elementary function of a series with a constant term")
        R = self.ring
        P = self.prec
        total = Series.constant(R, R.const(coeffs(0)), P)
        power = Series.constant(R, R.one, P)
        for k in range(1, P + 1):
            power = power * self
            c = coeffs(k)
            if c != 0:
                total = total + power * c
        return total

    def _pair(self, sign: int) -> tuple[Series, Series]:
        """``(sin u, cos u)`` (``sign = -1``) or ``(sinh u, cosh u)`` (``sign = +1``) of ``u`` =
        ``self`` without constant term, from ``s' = c u'``, ``c' = sign s u'``: ``k s_k = sum_j
        j u_j c_(k-j)``, ``k c_k = sign sum_j j u_j s_(k-j)`` -- as many coefficient products as
        one series product (the Taylor sum needs one per power)."""
        if self.c[0]:
            raise ValueError("elementary function of a series with a constant term")
        R = self.ring
        P = self.prec
        du = [(j, R.scale(self.c[j], j)) for j in range(1, P + 1) if self.c[j]]
        s_, c_ = [{}], [R.one]
        for k in range(1, P + 1):
            acc_s: dict = {}
            acc_c: dict = {}
            for j, uj in du:
                if j > k:
                    break
                if c_[k - j]:
                    acc_s = R.add(acc_s, R.mul(uj, c_[k - j]))
                if s_[k - j]:
                    acc_c = R.add(acc_c, R.mul(uj, s_[k - j]))
            s_.append(R.scale(acc_s, fmpq(1, k)))
            c_.append(R.scale(acc_c, fmpq(sign, k)))
        return Series(R, s_), Series(R, c_)

    def sin(self) -> Series:
        return self._pair(-1)[0]

    def cos(self) -> Series:
        return self._pair(-1)[1]

    def sinh(self) -> Series:
        return self._pair(1)[0]

    def cosh(self) -> Series:
        return self._pair(1)[1]

    def exp(self) -> Series:
        """``e = exp(u)`` from ``e' = e u'``: ``k e_k = sum_j j u_j e_(k-j)``."""
        if self.c[0]:
            raise ValueError("elementary function of a series with a constant term")
        R = self.ring
        P = self.prec
        du = [(j, R.scale(self.c[j], j)) for j in range(1, P + 1) if self.c[j]]
        e = [R.one]
        for k in range(1, P + 1):
            acc: dict = {}
            for j, uj in du:
                if j > k:
                    break
                if e[k - j]:
                    acc = R.add(acc, R.mul(uj, e[k - j]))
            e.append(R.scale(acc, fmpq(1, k)))
        return Series(R, e)

    def compose(self, inner: Series) -> Series:
        """``self(inner)`` for ``inner`` without constant term (Horner)."""
        if inner.c[0]:
            raise ValueError("composition with a series that has a constant term")
        P = min(self.prec, inner.prec)
        R = self.ring
        out = Series.constant(R, self.c[P] if P < len(self.c) else {}, P)
        for k in range(P - 1, -1, -1):
            out = out * inner + Series.constant(R, self.c[k], P)
        return out

    # -- conversion ---------------------------------------------------------------------------
    def to_sympy(self, var: sp.Expr, symbols: Mapping[str, sp.Expr] | None = None) -> sp.Expr:
        mono: dict = {}
        return sp.Add(
            *(self.ring.to_sympy(a, symbols, mono) * var**k for k, a in enumerate(self.c) if a)
        )

    def coefficients_sympy(self, symbols: Mapping[str, sp.Expr] | None = None) -> list[sp.Expr]:
        return [self.ring.to_sympy(a, symbols) for a in self.c]

    def equals(self, other: Series) -> bool:
        P = min(self.prec, other.prec)
        return all(not self.ring.sub(self.c[k], other.c[k]) for k in range(P + 1))

    def __repr__(self) -> str:
        return f"Series({self.to_sympy(sp.Symbol('x'))} + O(x**{self.prec + 1}))"


def _binomial_series(t: Series, e: sp.Rational) -> Series:
    """``y = (1 + t)**e`` for ``t`` without constant term, from ``(1 + t) y' = e t' y``: ``k y_k =
    sum_(i=1..k) ((e + 1) i - k) t_i y_(k-i)``, ``y_0 = 1`` (as many coefficient products as one
    series product; the series is unique, so these are the coefficients of the binomial sum)."""
    R = t.ring
    P = t.prec
    if t.c[0]:
        raise ValueError("binomial series of a series with a constant term")
    e1 = fmpq(int(e.p), int(e.q)) + 1
    nz = [i for i in range(1, P + 1) if t.c[i]]
    y = [R.one]
    for k in range(1, P + 1):
        acc: dict = {}
        for i in nz:
            if i > k:
                break
            w = e1 * i - k
            if w != 0 and y[k - i]:
                acc = R.add(acc, R.scale(R.mul(t.c[i], y[k - i]), w))
        y.append(R.scale(acc, fmpq(1, k)))
    return Series(R, y)


#: ``function: ((first, second) of the pair, sign of Series._pair, index in the pair)``
_PAIRS = {
    sp.sin: ((sp.sin, sp.cos), -1, 0),
    sp.cos: ((sp.sin, sp.cos), -1, 1),
    sp.sinh: ((sp.sinh, sp.cosh), 1, 0),
    sp.cosh: ((sp.sinh, sp.cosh), 1, 1),
}

#: memo key tag of the fixed part of a sum or product (:func:`fixed_parts`)
_FIXED = "fixed part"


def fixed_parts(
    exprs: Iterable[sp.Expr],
    env: Mapping[sp.Symbol, Series | str],
    ring: LaurentRing,
    prec: int,
    *,
    var: sp.Symbol | None = None,
    vary: Iterable[sp.Symbol],
) -> dict:
    """A memo for :func:`evaluate` holding every part of ``exprs`` free of the symbols ``vary``,
    evaluated once through ``var**prec``: each maximal sub-expression free of them, and for a sum
    or product that contains them, the sum or product of its arguments free of them.

    Evaluating ``exprs`` again with ``memo=dict(fixed)`` for new values of the ``vary`` symbols
    (at any precision up to ``prec``) then computes only the parts that depend on them; the result
    is the same series (exact arithmetic in a commutative ring: the order of the operations does
    not change it).
    """
    vary = frozenset(vary)
    memo: dict = {}
    known: dict = {}

    def varies(e) -> bool:
        """Whether ``e`` has a free symbol in ``vary`` (its ``free_symbols``, found once per
        sub-expression: sums, products, powers and functions have the free symbols of their
        arguments)."""
        hit = known.get(e)
        if hit is None:
            if e.is_Symbol:
                hit = e in vary
            elif e.is_Atom:
                hit = False
            elif e.is_Add or e.is_Mul or e.is_Pow or e.is_Function:
                hit = any(varies(a) for a in e.args)
            else:  # e.g. a derivative, whose variables are bound
                hit = bool(e.free_symbols & vary)
            known[e] = hit
        return hit

    def walk(e) -> None:
        if e in memo or (_FIXED, e) in memo:
            return
        if not varies(e):
            evaluate(e, env, ring, prec, var=var, memo=memo)
            return
        if e.is_Add or e.is_Mul:
            free = [a for a in e.args if not varies(a)]
            if len(free) > 1:
                vals = [evaluate(a, env, ring, prec, var=var, memo=memo) for a in free]
                out = vals[0]
                for a in vals[1:]:
                    out = out + a if e.is_Add else out * a
                memo[(_FIXED, e)] = (out, tuple(a for a in e.args if varies(a)))
        for a in e.args:
            walk(a)

    for e in exprs:
        walk(sp.sympify(e))
    return memo


def evaluate(
    expr: sp.Expr,
    env: Mapping[sp.Symbol, Series | str],
    ring: LaurentRing,
    prec: int,
    *,
    var: sp.Symbol | None = None,
    memo: dict | None = None,
) -> Series:
    """The truncated series of ``expr``.

    ``env`` says what each free symbol stands for: a :class:`Series` (same ring) or the name of a
    ring generator.  ``var`` (if given) is the series variable itself; ``pi`` is the ring generator
    ``"pi"``.  Shared sub-expressions are evaluated once (``memo``).
    """
    memo = {} if memo is None else memo
    R = ring

    def ev(e) -> Series:
        hit = memo.get(e)
        if hit is not None:  # possibly from an evaluation at a higher precision
            return hit if hit.prec <= prec else hit.truncate(prec)
        out = _ev(e)
        memo[e] = out
        return out

    def _ev(e) -> Series:
        if var is not None and e == var:
            return Series.variable(R, prec)
        if e.is_Rational:
            return Series.constant(R, R.const(e), prec)
        if e is sp.pi:
            return Series.constant(R, R.gen("pi"), prec)
        if e.is_Symbol:
            val = env.get(e)
            if val is None:
                raise KeyError(f"no value for the symbol {e}")
            if isinstance(val, str):
                return Series.constant(R, R.gen(val), prec)
            return val.truncate(prec)
        if e.is_Add or e.is_Mul:
            # a part of the arguments may be fixed (see :func:`fixed_parts`): evaluated once
            part = memo.get((_FIXED, e))
            args = [ev(a) for a in (e.args if part is None else part[1])]
            if part is not None:
                args.insert(0, part[0].truncate(prec))
            out = args[0]
            for a in args[1:]:
                out = out + a if e.is_Add else out * a
            return out
        if e.is_Pow:
            base, ex = e.args
            if not ex.is_Rational:
                raise ValueError(f"non-rational exponent in {e}")
            return ev(base) ** (int(ex) if ex.is_Integer else sp.Rational(ex))
        for f, (pair, sign, first) in _PAIRS.items():
            if isinstance(e, f):
                # both functions of the pair from one recurrence; the other one is kept
                arg = e.args[0]
                one, two = ev(arg)._pair(sign)
                other = pair[1 - first]
                memo.setdefault(other(arg, evaluate=False), two if first == 0 else one)
                return one if first == 0 else two
        if isinstance(e, sp.exp):
            return ev(e.args[0]).exp()
        raise ValueError(f"cannot evaluate {type(e).__name__} as a series: {e}")

    return ev(sp.sympify(expr))


def newton(residual, derivative, start: Series, *, max_iter: int = 40) -> Series:
    """Solve ``residual(u) = 0`` for the series ``u`` by Newton steps ``u -= residual/derivative``.

    The derivative's leading coefficient must be a monomial (so that it is a unit); then each step
    at least doubles the number of correct coefficients, and the loop stops when a step changes
    nothing and the residual vanishes to the working precision.
    """
    u = start
    for _ in range(max_iter):
        res = residual(u)
        if all(not a for a in res.c):
            return u
        step = res / derivative(u)
        u = u - step
    raise ArithmeticError("Newton iteration on series did not converge")


def newton_doubling(system, start: Series, prec: int) -> Series:
    """Solve ``F(u) = 0`` for the series ``u`` through ``var**prec`` by Newton steps that double
    the precision: ``start`` is right through ``var**0`` (``F(start) = O(var)``) and ``system(u,
    L, Ld)`` returns ``(F(u), F'(u))``, ``F`` through ``var**L`` and ``F'`` through ``var**Ld``,
    for the polynomial ``u`` of degree ``L``.

    If ``u`` is right through ``var**j``, then ``F(u) = var**(j+1) G`` and, the constant term of
    ``F'`` being a unit, ``u - F/F'`` is right through ``var**(2j+1)`` (the quadratic convergence
    of Newton's method on formal power series); ``F/F'`` through ``var**(2j+1)`` needs ``F'`` only
    through ``var**j``.  So each step evaluates ``F`` only to the precision it can gain, and ``F'``
    to half of it: the last step costs about as much as all the earlier ones together.
    """
    targets = [prec]  # each step from j reaches 2j + 1: the schedule read backwards
    while targets[-1] > 1:
        targets.append(targets[-1] // 2)
    u = start.truncate(0)
    known = 0
    for L in reversed(targets):
        if L <= known:
            continue
        Ld = L - known - 1
        u = u.padded(L)
        F, D = system(u, L, Ld)
        # F vanishes through var**known (a nonzero low coefficient raises: no Newton step then)
        step = (F.truncate(L).shift(-(known + 1)) / D.truncate(Ld)).shift(known + 1)
        u = (u - step).truncate(L)
        known = L
    return u


def reversion(f: Series) -> Series:
    """The compositional inverse ``g`` of ``f = c1 x + c2 x**2 + ...`` (``c1`` a monomial)."""
    R = f.ring
    if f.c[0] or not f.c[1]:
        raise ValueError("reversion needs f(0) = 0 and f'(0) a unit")
    P = f.prec
    c1inv = R.inverse(f.c[1])
    g = Series(R, [{}, c1inv] + [{} for _ in range(P - 1)])
    x = Series.variable(R, P)
    # Newton on f(g) - x = 0 with f'(g) computed from the derivative series of f
    df = Series(R, [R.scale(f.c[k], k) for k in range(1, P + 1)] + [{}])
    for _ in range(2 * P + 4):
        res = f.compose(g) - x
        if all(not a for a in res.c):
            return g
        g = g - res / df.compose(g)
    raise ArithmeticError("series reversion did not converge")
