"""Proofs by ball arithmetic: enclosures of simple roots, and signs of a function on an interval.

Every high-precision number the engine returns comes out of this module as an ``arb`` ball
(python-flint; midpoint and radius, every operation rounded outward) that provably contains the
exact value.  Two tools:

:func:`certified_root`
    Newton's method on ball midpoints, starting from a float and doubling the precision each step
    (the cost is dominated by the last step), then **interval Newton**: for a ball ``X`` around the
    approximate root ``x``, ``N(X) = x - F(x)/F'(X)``.  If ``N(X)`` lies in the interior of ``X``,
    ``F`` has exactly one zero in ``X`` and it lies in ``N(X)`` (Moore; the interval form of
    Krawczyk's test for one unknown).  ``F(x)`` is evaluated on the exact point ``x`` and ``F'``
    on all of ``X``, so the test covers rounding and the truncation of the transcendental functions
    alike.  The ball returned is ``N(X)`` and its radius is checked against the requested accuracy.

:func:`prove_sign`
    ``F`` has a strict sign on ``[a, b]``: ``F`` is evaluated on sub-balls (bisection), each
    through the centred form ``F(mid) + F'(ball) (ball - mid)`` when that is tighter than the
    direct evaluation.  Used to prove that a function with friction is positive between the two
    edges and negative outside, i.e. that the two certified zeros *are* the edges.

Precision is always a parameter (``flint.ctx.workprec`` contexts, restored on exit).
"""

from __future__ import annotations

import math
from collections.abc import Callable
from typing import NamedTuple

import mpmath
from flint import arb, ctx
from mpmath.libmp import from_man_exp

__all__ = [
    "CertificationError",
    "Root",
    "certified_root",
    "quick_root",
    "prove_sign",
    "to_mpf",
    "upper_mpf",
    "exact_mpf",
    "ball",
    "bits_for_digits",
    "Jet",
    "QUICK_GUARD",
]

#: bits above the accuracy asked for at which :func:`quick_root` runs its proof
QUICK_GUARD = 30


class CertificationError(ArithmeticError):
    """A result could not be proven at the precision allowed (e.g. a double root at a threshold)."""


class Root(NamedTuple):
    """A proven simple root: ``ball`` contains exactly one zero of the function (in the ball
    ``search`` the test was run on), computed at ``prec`` bits."""

    ball: arb
    search: arb
    prec: int


def bits_for_digits(digits: int) -> int:
    """Bits that represent ``digits`` significant decimal digits."""
    return int(math.ceil(digits * math.log2(10)))


def exact_mpf(x: arb) -> mpmath.mpf:
    """The exact ball ``x`` (radius zero) as an mpmath number."""
    fman, fexp = x.man_exp()
    man, exp = int(fman), int(fexp)
    if man & 1:  # arb gives the odd mantissa: already mpmath's normal form
        raw = (0, man, exp, man.bit_length()) if man > 0 else (1, -man, exp, (-man).bit_length())
        return _make_mpf(raw)
    return _make_mpf(from_man_exp(man, exp))


_make_mpf = mpmath.mp.make_mpf


def to_mpf(x: arb) -> mpmath.mpf:
    """The midpoint of ``x`` as an mpmath number, exactly (no rounding to the mpmath context)."""
    return exact_mpf(x.mid())


def upper_mpf(x: arb) -> mpmath.mpf:
    """An mpmath number ``>= |x|`` for every point of the ball (its upper magnitude bound)."""
    return exact_mpf(x.abs_upper())


def ball(mid, rad=0) -> arb:
    """A ball from a float, an mpf or an arb midpoint and a radius (exact conversions)."""
    if isinstance(mid, mpmath.mpf):
        negative = mid < 0
        man, exp = mid.man_exp  # the magnitude only: man_exp drops the sign
        # exact at any working precision: the product with a power of two is formed with
        # enough bits for the whole mantissa (else it would round and the midpoint taken
        # below would silently drop the rounding error)
        with ctx.workprec(max(ctx.prec, int(man).bit_length() + 8)):
            mid = arb(man) * arb(2) ** int(exp) if man else arb(0)
            if negative:
                mid = -mid
    elif isinstance(mid, arb):
        mid = mid.mid()
    else:
        mid = arb(mid)
    if rad:
        return arb(mid.mid(), arb(rad).abs_upper())
    return mid


def _newton(F, dF, x: arb, lo, hi, signs: list | None = None):
    """One safeguarded Newton step on midpoints; returns ``(x, |step|, lo, hi)``.  ``signs``
    (a list) collects whether ``F(x)`` had a proven sign."""
    fx = F(x)
    if signs is not None:
        signs.append(not fx.contains(0))
    dfx = dF(x)
    if lo is not None:
        if fx > 0:
            hi = x
        elif fx < 0:
            lo = x
    if not dfx.contains(0) and dfx.is_finite() and fx.is_finite():
        xn = (x - fx / dfx).mid()
        # the closed bracket: at the root to the working precision the step rounds to nothing
        # (``xn == x``) while ``F(x)`` still has a proven sign, which has just made ``x`` an end
        # of the bracket; that iterate is converged, not outside (a bisection from there would
        # throw the digits away and crawl back one bit a step)
        if lo is None or lo <= xn <= hi:
            return xn, abs(xn - x), lo, hi
    if lo is None:
        raise CertificationError(f"Newton's method broke down near {float(x)}")
    xn = ((lo + hi) / 2).mid()  # bisection on the bracket
    return xn, abs(hi - lo), lo, hi


def certified_root(
    F: Callable[[arb], arb],
    dF: Callable[[arb], arb],
    x0: float | arb,
    *,
    bits: int,
    floor: float = 0.0,
    bracket: tuple | None = None,
    max_bits: int | None = None,
    scale: float | Callable[[float], float] | None = None,
) -> Root:
    """Enclose the simple zero of ``F`` near ``x0`` to relative accuracy ``2**-bits``.

    ``F`` and ``dF`` take and return ``arb`` at the current precision.  The radius of the result is
    at most ``2**-bits * max(|root|, floor)`` (``floor`` is an absolute scale for roots that may be
    exactly zero), or ``2**-bits * scale`` if ``scale`` is given (when what matters is the accuracy
    of a quantity derived from the root, e.g. ``root + shift`` near zero); ``scale`` may be a
    function of the root (a float), evaluated at the enclosed root, not at the start.
    ``bracket = (a, b)`` (numbers with ``F(a) < 0 < F(b)``) keeps Newton inside: a step that would
    leave it is replaced by a bisection step.

    Where ``F`` is the small difference of large terms (an ill-conditioned variable), the working
    precision is raised until ``F`` has a sign at the Newton iterate and the interval-Newton test
    succeeds; :class:`CertificationError` is raised only past ``max_bits`` bits of working
    precision (default: enough for a cancellation of ``16 * bits + 4096`` bits).
    """
    target = bits + 20
    max_bits = max_bits or 16 * target + 4096
    x = ball(x0)
    lo = ball(bracket[0]) if bracket else None
    hi = ball(bracket[1]) if bracket else None
    floor_b = arb(floor)

    def size_of(x):
        return max(abs(x), floor_b)

    def want_of(x):
        if scale is None:
            return size_of(x)
        s = scale(float(x.mid())) if callable(scale) else scale
        return arb(s)

    def polish(x, lo, hi, prec, count):
        """Newton on midpoints at ``prec`` bits until the step is at the precision's noise (or
        ``F`` has no sign there: then more precision is needed)."""
        step, signs = None, []
        with ctx.workprec(prec):
            for _ in range(count):
                x, step, lo, hi = _newton(F, dF, x, lo, hi, signs)
                if not signs[-1] or step <= size_of(x) * arb(2) ** (-prec + 8):
                    break  # converged, or at the noise floor of this precision
        return x, step, lo, hi

    # Newton on midpoints, doubling the precision each step (one step per precision while the
    # iteration converges quadratically; more where it does not yet)
    prec, step = 53, None
    while prec < target:
        prec = min(2 * prec, target)
        with ctx.workprec(prec + 10):
            x, step, lo, hi = _newton(F, dF, x, lo, hi)
    x, step, lo, hi = polish(x, lo, hi, target + 10, 200)
    # interval Newton, enlarging the search ball (or the precision) until it succeeds
    work = target + 10
    while work <= max_bits:
        with ctx.workprec(work):
            size = size_of(x)
            want = (want_of(x) * arb(2) ** (-bits)).abs_lower()
            delta = max(
                arb(step) * 4 if step is not None else arb(0), size * arb(2) ** (-work + 12)
            )
            if abs(x) < floor_b:
                # the iterate is below the absolute scale: it is the noise around a zero that
                # may be exactly 0 (a closing), and the search ball must reach it
                delta = max(delta, 4 * abs(x))
            for _ in range(10):
                X = arb(x, delta.abs_upper())
                dX = dF(X)
                if dX.contains(0) or not dX.is_finite():
                    delta = delta / 16
                    continue
                N = x - F(x) / dX
                if X.contains_interior(N):
                    if N.rad() <= want:
                        return Root(N, X, work)
                    break  # proven, but too wide at this precision
                delta = delta * 16
        work *= 2
        x, step, lo, hi = polish(x, lo, hi, work, 200)
    raise CertificationError(
        f"could not enclose a simple root near {float(x.mid())} below {max_bits} bits"
    )


def quick_root(
    FD: Callable[[arb], tuple],
    F: Callable[[arb], arb],
    dF: Callable[[arb], arb],
    x0: float,
    *,
    bits: int,
    start_bits: int = 50,
    floor: float = 0.0,
    bracket: tuple | None = None,
    scale: float | Callable[[float], float] | None = None,
) -> Root | None:
    """The fast path of :func:`certified_root` for a well-conditioned simple zero: ``None`` where
    it does not succeed (the caller then runs :func:`certified_root`), never a wrong enclosure.

    ``x0`` is accurate to about ``start_bits`` bits.  Newton steps on midpoints (``FD(x)`` gives
    ``F(x), F'(x)`` in one evaluation, common subexpressions shared) double the accuracy at a
    precision just above it, until the iterate holds half of the ``bits`` asked for; then one
    interval Newton test at the full precision, ``N = x - F(x)/F'(X)`` inside ``X``, which proves
    the zero and, being itself a Newton step, doubles the accuracy once more -- so the last full
    precision evaluation is that of the proof, not a further midpoint step.  The enclosure must
    meet the radius that :func:`certified_root` promises (``2**-bits`` relative to ``scale`` or
    ``max(|root|, floor)``); a proven enclosure that is still too wide is the start of one more
    test (its midpoint holds twice the accuracy)."""
    work = bits + QUICK_GUARD
    need = (bits + 4) // 2 + 1
    x = arb(x0)
    acc = start_bits
    lo = hi = None
    if bracket is not None:
        lo, hi = bracket
    old = ctx.prec  # set and restored here (a workprec context costs more than this proof at
    try:  # 15 digits)
        while acc < need:
            acc = min(2 * acc - 8, need + 8)
            ctx.prec = acc + 12
            f, d = FD(x)
            if not (d.is_finite() and f.is_finite()) or d.contains(0):
                return None
            x = (x - f / d).mid()
            if lo is not None and not lo < x < hi:
                return None
        ctx.prec = work
        fl = floor if type(floor) is arb else arb(floor)
        for _ in range(2):
            size = abs(x)
            if fl > size:
                size = fl
            X = arb(x, (size * pow2(4 - acc)).abs_upper())
            dX = dF(X)
            if dX.contains(0) or not dX.is_finite():
                return None
            N = x - F(x) / dX
            if not X.contains_interior(N):
                return None
            if scale is None:
                want = size
            else:
                want = arb(scale(float(x)) if callable(scale) else scale)
            if N.rad() <= (want * pow2(-bits)).abs_lower():
                return Root(N, X, work)
            x, acc = N.mid(), 2 * acc - 8  # proven, too wide: once more from its midpoint
        return None
    finally:
        ctx.prec = old


_POW2: dict[int, arb] = {}


def pow2(k: int) -> arb:
    """The exact ball ``2**k`` (the same few powers recur: kept)."""
    p = _POW2.get(k)
    if p is None:
        p = arb((1, k))
        if len(_POW2) < 4096:
            _POW2[k] = p
    return p


def prove_sign(
    F: Callable[[arb], arb],
    dF: Callable[[arb], arb],
    a,
    b,
    sign: int,
    *,
    prec: int = 64,
    budget: int = 4000,
) -> bool:
    """Whether ``sign * F > 0`` on all of ``[a, b]`` is proven by ball arithmetic.

    Bisection with the centred form; at most ``budget`` evaluations, then ``False`` (not proven,
    not disproven).  ``a``, ``b`` are floats, mpf or arb (their midpoints are used as the exact
    ends; callers choose them so that this is what they need).
    """
    with ctx.workprec(prec):
        a = ball(a)
        b = ball(b)
        if not a < b:
            return a == b and bool(sign * F(a) > 0)
        stack = [(a, b)]
        count = 0
        while stack:
            lo, hi = stack.pop()
            count += 1
            if count > budget:
                return False
            mid = ((lo + hi) / 2).mid()
            X = arb(mid, max(hi - mid, mid - lo).abs_upper())
            val = F(X)
            if not (sign * val > 0):
                fm = F(mid)
                if not (sign * fm > 0):
                    return False  # a point where the sign fails (or cannot be decided)
                cf = fm + dF(X) * (X - mid)
                val = cf
            if sign * val > 0:
                continue
            stack.append((lo, mid))
            stack.append((mid, hi))
        return True


class Jet:
    """A first-order jet ``value + slope * dm`` over ``arb`` balls: evaluating a function on jets
    gives, with the value, an enclosure of its derivative with respect to one parameter (the
    derivative over a whole ball when the parameter's jet is ``Jet(ball, 1)``).  Supports what the
    compiled forms use: ``+ - * /``, powers with integer exponents, ``sqrt``, ``exp``, ``sin``,
    ``cos``, ``sinh``, ``cosh`` and the pairs ``sin_cos``, ``sinh_cosh``.  Used for the mean-value
    form ``f(M) in f(mid) + f'(M) (M - mid)``."""

    __slots__ = ("v", "d")

    def __init__(self, v, d=0):
        self.v = v
        self.d = d

    @staticmethod
    def _of(x):
        return x if isinstance(x, Jet) else Jet(x, 0)

    def __add__(self, o):
        if type(o) is Jet:
            return Jet(self.v + o.v, self.d + o.d)
        return Jet(self.v + o, self.d)

    __radd__ = __add__

    def __neg__(self):
        return Jet(-self.v, -self.d)

    def __pos__(self):
        return self

    def __sub__(self, o):
        if type(o) is Jet:
            return Jet(self.v - o.v, self.d - o.d)
        return Jet(self.v - o, self.d)

    def __rsub__(self, o):
        return Jet(o - self.v, -self.d)

    def __mul__(self, o):
        if type(o) is Jet:
            return Jet(self.v * o.v, self.d * o.v + self.v * o.d)
        return Jet(self.v * o, self.d * o)

    __rmul__ = __mul__

    def __truediv__(self, o):
        if type(o) is Jet:
            q = self.v / o.v
            return Jet(q, (self.d - q * o.d) / o.v)
        return Jet(self.v / o, self.d / o)

    def __rtruediv__(self, o):
        q = o / self.v
        return Jet(q, -q * self.d / self.v)

    def __pow__(self, k):
        if not isinstance(k, int):
            raise TypeError("Jet powers take integer exponents")
        if k == 0:
            return Jet(self.v * 0 + 1, 0)
        if k < 0:
            return 1 / (self ** (-k))
        if k == 1:
            return self
        if k == 2:
            return Jet(self.v * self.v, 2 * self.v * self.d)
        return Jet(self.v**k, k * self.v ** (k - 1) * self.d)

    def __abs__(self):
        if self.v > 0:
            return self
        if self.v < 0:
            return -self
        raise ArithmeticError("|x| of a jet whose value may be zero")

    def sqrt(self):
        s = self.v.sqrt()
        return Jet(s, self.d / (2 * s))

    def sin(self):
        return Jet(self.v.sin(), self.v.cos() * self.d)

    def cos(self):
        return Jet(self.v.cos(), -self.v.sin() * self.d)

    def sin_cos(self):
        s, c = self.v.sin_cos()
        return Jet(s, c * self.d), Jet(c, -s * self.d)

    def sinh_cosh(self):
        s, c = self.v.sinh_cosh()
        return Jet(s, c * self.d), Jet(c, s * self.d)

    def sinh(self):
        return Jet(self.v.sinh(), self.v.cosh() * self.d)

    def exp(self):
        e = self.v.exp()
        return Jet(e, e * self.d)

    def cosh(self):
        return Jet(self.v.cosh(), self.v.sinh() * self.d)
