"""Certified Floquet multipliers at one point ``(T, m)`` of any member of the family.

The monodromy comes from the independent route (:func:`verify.floquet.monodromy_arb`: segment maps
and switches in ball arithmetic, nothing from :mod:`analytic`'s determinants).  Its eigenvalues

    mu = (tr M +- sqrt((M11 - M22)^2 + 4 M12 M21)) / 2,     mu1 mu2 = det M = exp(-2 gamma T)

are enclosed in balls (complex balls where the discriminant may be negative); the working precision
is doubled until every ball is as narrow as the digits asked for, *relative* to the number (the
growth rate ``ln |mu|max`` tends to 0 at an edge: next to one it needs far more bits than the
multipliers themselves), or the discriminant's ball holds zero (a double multiplier, e.g. at a
closing, where the square root halves the digits).  Where a proven complex pair is found,
``|mu1| = |mu2| = sqrt(det M) = exp(-gamma T)`` exactly (Liouville: the trace of every phase's
matrix is ``-2 gamma``, every jump has determinant 1 over a period), so ``ln |mu|max = -gamma T =
-pi T/Q`` -- exactly 0 without friction -- is printed to every digit asked for.  A number that
still has fewer digits than asked (a double multiplier, or a point so close to an edge that the
largest working precision tried cannot separate ``|mu|max`` from 1) prints only the digits its
ball proves, and a note says how many and why (``growth_rate_digits`` in the JSON).  Reported: both
multipliers, the largest modulus ``|mu|max`` and the growth rate per period ``ln |mu|max``
(positive inside an interval of instability).
"""

from __future__ import annotations

from dataclasses import dataclass, field, replace
from fractions import Fraction

import mpmath
from flint import acb, arb, ctx, fmpq

from analytic.system import System

from .certify import bits_for_digits, to_mpf, upper_mpf
from .floquet import monodromy_arb
from .inputs import (
    InputError,
    as_damping,
    as_depth,
    as_digits,
    as_period,
    as_quality,
    as_system,
)
from .params import exact_fraction
from .result import proven_text
from .rounding import bound_text, printed_error

__all__ = ["Multipliers", "multipliers"]

#: the largest working precision tried, in bits per asked digit
_MAX_BITS_PER_DIGIT = 16


@dataclass(frozen=True)
class Multipliers:
    """Both Floquet multipliers at one point, each digit proven.

    ``mu`` holds two pairs ``(re, im)`` of mpmath numbers (``im = 0`` for real multipliers), larger
    modulus first; ``radii`` their proven radii (per pair, a bound on both parts); ``modulus`` and
    ``growth`` are ``|mu|max`` and ``ln |mu|max`` with radii ``modulus_radius``,
    ``growth_radius``.  ``real`` says whether both are proven real, ``double`` whether the two
    could not be separated (a double multiplier); ``growth_exact`` whether ``growth`` is the exact
    value (``0``: a proven complex pair on the unit circle, no friction).
    """

    T: Fraction
    m: Fraction | None
    Q: Fraction | None
    damping: str
    digits: int
    system: System
    mu: tuple
    radii: tuple
    modulus: mpmath.mpf
    modulus_radius: mpmath.mpf
    growth: mpmath.mpf
    growth_radius: mpmath.mpf
    real: bool
    double: bool
    notes: tuple = field(default=())
    growth_exact: bool = False

    @property
    def unstable(self) -> bool | None:
        """``True`` if ``|mu|max > 1`` is proven, ``False`` if ``<= 1`` is, else ``None``.

        A proven complex pair is stable: ``|mu|^2 = det M = exp(-2 gamma T) <= 1``."""
        if not self.real and not self.double:
            return False
        # exact rational comparisons: mpf arithmetic would round to the caller's precision
        # (|mu|max - 1 can be far below 10^-15)
        mod, rad = _exact(self.modulus), _exact(self.modulus_radius)
        if mod - rad > 1:
            return True
        if mod + rad < 1 or (mod == 1 and rad == 0):
            return False
        return None

    def _num(self, x, rad) -> str:
        return proven_text(x, rad, self.digits)

    @property
    def growth_digits(self) -> int:
        """The significant digits printed for ``ln |mu|max``, every one certified (``0`` where
        it prints as ``0``; see :attr:`growth_exact`)."""
        return significant_digits(self._num(self.growth, self.growth_radius))

    def _mu_text(self, i: int) -> str:
        re_, im_ = self.mu[i]
        rad = self.radii[i]
        if self.real:
            return self._num(re_, rad)
        sign = "-" if im_ < 0 else "+"
        with mpmath.workdps(self.digits + 20):  # abs() rounds to the working precision
            mag = abs(im_)
        return f"{self._num(re_, rad)} {sign} {self._num(mag, rad)} i"

    def _bound(self, texts_values, rad) -> str | None:
        """The bound of the printed decimals (rounding included): the largest over the parts."""
        bounds = [printed_error(t, x, rad) for t, x in texts_values]
        return bound_text(max(b for b in bounds if b is not None)) if bounds else None

    def _overall_bound(self) -> str:
        """One bound for every number the text prints (rounding included)."""
        items = []
        with mpmath.workdps(self.digits + 20):
            for (re_, im_), rad in zip(self.mu, self.radii, strict=True):
                items.append((self._num(re_, rad), re_, rad))
                if not self.real:
                    mag = abs(im_)
                    items.append((self._num(mag, rad), mag, rad))
        items.append(
            (self._num(self.modulus, self.modulus_radius), self.modulus, self.modulus_radius)
        )
        items.append((self._num(self.growth, self.growth_radius), self.growth, self.growth_radius))
        bounds = [printed_error(t, x, r) for t, x, r in items]
        return bound_text(max(b for b in bounds if b is not None))

    def as_json(self) -> dict:
        def one(i):
            re_, im_ = self.mu[i]
            rt, it = self._num(re_, self.radii[i]), self._num(im_, self.radii[i])
            return {
                "re": rt,
                "im": it,
                "error_bound": self._bound([(rt, re_), (it, im_)], self.radii[i]),
            }

        mod_t = self._num(self.modulus, self.modulus_radius)
        gr_t = self._num(self.growth, self.growth_radius)

        return {
            **self.system.as_json(),
            "T": _decimal(self.T),
            "m": None if self.m is None else _text(self.m),
            "Q": None if self.Q is None else _text(self.Q),
            "damping": self.damping if self.Q is not None else "none",
            "digits": self.digits,
            "multipliers": [one(0), one(1)],
            "real": self.real,
            "max_modulus": mod_t,
            "max_modulus_error_bound": self._bound([(mod_t, self.modulus)], self.modulus_radius),
            "growth_rate": gr_t,
            "growth_rate_error_bound": self._bound([(gr_t, self.growth)], self.growth_radius),
            "growth_rate_digits": significant_digits(gr_t),
            "growth_rate_exact": self.growth_exact,
            "unstable": self.unstable,
            "certified": True,
            "notes": list(self.notes),
        }

    def __str__(self) -> str:
        fr = "no friction" if self.Q is None else f"Q = {_text(self.Q)} ({self.damping} model)"
        where = f"m = {_text(self.m)}, " if self.m is not None else ""
        head = f"{self.system.label}: T/T0 = {_decimal(self.T)}, {where}{fr}"
        state = {True: "unstable (inside an interval)", False: "stable", None: "undecided"}[
            self.unstable
        ]
        lines = [
            head,
            f"  mu1 = {self._mu_text(0)}",
            f"  mu2 = {self._mu_text(1)}",
            f"  |mu|max = {self._num(self.modulus, self.modulus_radius)}",
            f"  growth per period ln|mu|max = {self._num(self.growth, self.growth_radius)}",
            f"  [{state}; certified: |printed - exact| < {self._overall_bound()}]",
        ]
        lines += [f"  note: {n}" for n in self.notes]
        return "\n".join(lines)

    def _repr_html_(self) -> str:
        """The printed text in a notebook (every certified digit)."""
        from paramres.display import pre_html

        return pre_html(self)


def _exact(x: mpmath.mpf) -> Fraction:
    """The binary value of a finite ``mpf``, exactly."""
    man, exp = x.man_exp
    return Fraction(man) * Fraction(2) ** exp


def _text(x: Fraction) -> str:
    return str(x.numerator) if x.denominator == 1 else f"{x.numerator}/{x.denominator}"


def _decimal(x: Fraction) -> str:
    """An exact decimal when ``x`` has one of at most 60 places (as typed), else ``p/q``."""
    for places in range(61):
        scaled = x * 10**places
        if scaled.denominator == 1:
            if places == 0:
                return str(scaled.numerator)
            sign = "-" if scaled < 0 else ""
            digits = str(abs(scaled.numerator)).rjust(places + 1, "0")
            return f"{sign}{digits[:-places]}.{digits[-places:]}"
    return _text(x)


def _eigen(M) -> tuple:
    """Both eigenvalues as ``acb`` balls (larger modulus first) and whether the discriminant is
    proven positive, proven negative, or holds zero."""
    a, b, c, d = M
    tr = a + d
    disc = (a - d) * (a - d) + 4 * b * c
    if disc > 0:
        root = disc.sqrt()
        big = (tr + root) / 2 if tr >= 0 else (tr - root) / 2
        if not (tr >= 0 or tr < 0):  # tr straddles 0: take both and order by modulus
            p, q = (tr + root) / 2, (tr - root) / 2
            big = p if abs(p) >= abs(q) else q
        small = (a * d - b * c) / big
        return acb(big), acb(small), "positive"
    if disc < 0:
        im = (-disc).sqrt() / 2
        return acb(tr / 2, im), acb(tr / 2, -im), "negative"
    root = acb(disc).sqrt()
    return (acb(tr) + root) / 2, (acb(tr) - root) / 2, "zero"


def multipliers(
    T,
    m=None,
    *,
    Q=None,
    damping="exact",
    digits=30,
    system="pendulum",
    duty="1/2",
    _monodromy=None,
    _notes=(),
) -> Multipliers:
    """Both Floquet multipliers at period ``T`` (units of ``T0``) and depth ``m`` (left out for a
    custom system), with friction ``Q`` in the ``exact`` or ``paper`` model, to ``digits``
    proven digits; ``system``/``duty`` as in :func:`verify.boundary`.  Other modulations of the
    length (:func:`verify.modulation.multipliers`) pass their period map as ``_monodromy(m, T)``
    (four balls at the working precision, exact ``m``, ``T``) and a line for the notes."""
    sysv = as_system(system, duty)
    if sysv.uses_depth:
        if m is None:
            raise InputError(f"system {sysv.name} needs a depth m (0 < m < 1)")
        mm = exact_fraction(as_depth(m))
    else:
        if m is not None:
            raise InputError(f"a custom system has no depth: leave m out (got m = {m!r})")
        mm = None
    TT = exact_fraction(as_period(T))
    QQ = as_quality(Q)
    QQ = None if QQ is None else exact_fraction(QQ)
    model = as_damping(damping)
    d = as_digits(digits)
    monodromy = lambda: monodromy_arb(mm, TT, QQ, model, sysv)  # noqa: E731
    notes = list(_notes)
    if _monodromy is not None:
        monodromy = lambda: _monodromy(mm, TT)  # noqa: E731
    goal = arb(10) ** (-(d + 1))
    bits = bits_for_digits(d + 4)
    cap = max(bits * _MAX_BITS_PER_DIGIT, 4096)
    # a discriminant whose ball holds zero: a double multiplier (a closing; no precision separates
    # it) or a point within a hair of an edge (more precision does).  The closed-form period map
    # is cheap at any precision: up to the cap; an integrated one stops at four times the start
    double_cap = cap if _monodromy is None else 4 * bits
    while True:
        with ctx.workprec(bits):
            M = monodromy()
            mu1, mu2, kind = _eigen(M)
            exact = None
            if kind == "negative":  # a proven complex pair: |mu|^2 = det M = exp(-2 gamma T)
                exact = _on_circle(M, mu1, TT, QQ)
            if exact is not None:
                big, growth = exact
            else:
                mods = [abs(mu1), abs(mu2)]
                big = mods[0] if mods[0] >= mods[1] else mods[1]
                if not (mods[0] >= mods[1] or mods[0] < mods[1]):  # overlapping: the union
                    big = arb.union(mods[0], mods[1]) if hasattr(arb, "union") else mods[0]
                growth = big.log() if big > 0 else None
            narrow = (
                _pair_ok(mu1, goal)
                and _pair_ok(mu2, goal)
                and _rel_ok(big, goal)
                and growth is not None
                and (growth.is_zero() or _rel_ok(growth, goal))
            )
            if narrow or bits >= cap or kind == "zero" and bits >= double_cap:
                break
            bits *= 2
    if growth is None:  # pragma: no cover - |mu|max = sqrt(det M) > 0 always
        raise InputError("the multipliers could not be separated from zero")
    if kind == "zero":
        notes.append(
            "the two multipliers may coincide here (a double multiplier, e.g. on a closing): "
            "their enclosures overlap and only the digits their balls prove are printed"
        )
    growth_exact = exact is not None and QQ is None
    if growth_exact:
        notes.append(
            "ln|mu|max = 0 exactly: the multipliers are a proven complex pair on the unit "
            "circle (|mu1| = |mu2| = sqrt(det M) = 1 without friction)"
        )
    with ctx.workprec(bits), mpmath.workdps(d + 10):
        pairs = [(to_mpf(z.real), to_mpf(z.imag)) for z in (mu1, mu2)]
        radii = [upper_mpf(arb(max(z.real.rad(), z.imag.rad()))) for z in (mu1, mu2)]
        real = kind == "positive"
        if real:
            pairs = [(re_, mpmath.mpf(0)) for re_, _ in pairs]
        result = Multipliers(
            T=TT,
            m=mm,
            Q=QQ,
            damping=model,
            digits=d,
            system=sysv,
            mu=tuple(pairs),
            radii=tuple(radii),
            modulus=to_mpf(big),
            modulus_radius=upper_mpf(arb(big.rad())),
            growth=to_mpf(growth),
            growth_radius=upper_mpf(arb(growth.rad())),
            real=real,
            double=kind == "zero",
            notes=tuple(notes),
            growth_exact=growth_exact,
        )
    # every ball narrow enough: each number prints with every digit asked for, except a part whose
    # ball holds zero (a multiplier's real part at tr M = 0, or an imaginary part at a closing)
    held = any(x.contains(0) and not x.is_zero() for x in (mu1.real, mu1.imag, mu2.real, mu2.imag))
    short = _short(result) if not narrow or held else []
    if short:
        if kind == "zero":
            why = (
                f"the two multipliers are not separated at {bits} bits of working precision "
                "(a double multiplier, or one within the error bound)"
            )
        elif bits >= cap:
            why = (
                f"the balls are still too wide at {bits} bits of working precision, the most "
                f"tried for {d} digits (|mu|max is that close to 1)"
            )
        else:
            why = "a part whose ball holds 0 is printed as 0, within its error bound"
        notes.append(
            f"fewer digits than the {d} asked for are certified here: "
            + ", ".join(f"{name} {n}" for name, n in short)
            + f"; {why}. Every digit printed is proven"
        )
        result = replace(result, notes=tuple(notes))
    return result


def _on_circle(M, mu1, T: Fraction, Q: Fraction | None):
    """``(|mu|max, ln |mu|max)`` of a proven complex pair: ``exp(-gamma T)`` and ``-gamma T =
    -pi T/Q`` (``1`` and exactly ``0`` without friction), as balls at the working precision;
    ``None`` should the balls of ``sqrt(det M)`` or ``|mu1|`` not hold them (they always do:
    ``det M = exp(-2 gamma T)``, Liouville)."""
    if Q is None:
        big, growth = arb(1), arb(0)
    else:
        x = T / Q
        growth = -arb.pi() * arb(fmpq(x.numerator, x.denominator))
        big = growth.exp()
    a, b, c, d = M
    if not (abs(mu1).overlaps(big) and (a * d - b * c).overlaps(big * big)):
        return None  # pragma: no cover - a theorem; kept as a guard
    return big, growth


def _short(res: Multipliers) -> list:
    """``(name, digits)`` of every printed number with fewer significant digits than asked for
    (exact zeros aside: the imaginary parts of real multipliers, ``ln|mu|max = 0`` exactly)."""
    out = []
    for i, ((re_, im_), rad) in enumerate(zip(res.mu, res.radii, strict=True)):
        parts = [("", re_)] if res.real else [(" (real part)", re_), (" (imaginary part)", im_)]
        for what, x in parts:
            n = significant_digits(res._num(x, rad))
            if n < res.digits:
                out.append((f"mu{i + 1}{what}", n))
    n = significant_digits(res._num(res.modulus, res.modulus_radius))
    if n < res.digits:
        out.append(("|mu|max", n))
    if not res.growth_exact and res.growth_digits < res.digits:
        out.append(("ln|mu|max", res.growth_digits))
    return out


def significant_digits(text: str) -> int:
    """The significant digits of a printed decimal (``"0.00120"``: 3, ``"0"``: 0)."""
    mant = text.lstrip("+-").split("e")[0].replace(".", "").lstrip("0")
    return len(mant)


def _pair_ok(z: acb, goal: arb) -> bool:
    """Both parts of ``z`` printed to the digits asked for with the pair's one radius (a part
    whose ball holds zero: to ``goal**2``)."""
    rad = max(z.real.rad(), z.imag.rad())
    for x in (z.real, z.imag):
        if x.is_zero():  # exactly 0 (the imaginary part of a real multiplier)
            continue
        if not (rad <= goal * abs(x).upper() or (x.contains(0) and rad <= goal * goal)):
            return False
    return True


def _rel_ok(x: arb, goal: arb) -> bool:
    """``x`` to the digits asked for, relative to itself (never where its ball holds zero)."""
    return bool(x.rad() <= goal * abs(x).upper())
