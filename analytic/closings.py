"""Where an interval closes: both edges meet, at exact rational depths, and nowhere else.

The theorem, derived step by step (each step is proven by :mod:`analytic.identity` or by sympy, and
the steps are returned with their verdicts by :func:`closings`):

1. Without friction the normal form is a difference of squares (:mod:`analytic.normal_form`,
   step 6): ``N = F_+ F_-`` with ``F_eps = f(x) - eps r f(y)``, ``f = cos`` (odd orders) or ``sin``
   (even), ``x = omega_av T/2``, ``y = beta x = Delta omega T/4``.
2. **Window theorem.** Write ``x = n pi/2 + theta``.  In the window ``|theta| < pi/2`` each factor
   has exactly one root, and it is simple (at ``theta = +-pi/2`` the ``sin theta`` term dominates,
   since ``r < 1``; at a root, ``|cos theta| >= sqrt(1 - r^2) > beta r``, so every root has the sign
   of the derivative of ``c_n sin theta``).  So the ``n``-th interval is bounded by the root of
   ``F_+`` and the root of ``F_-`` in window ``n``; it has zero width iff these roots coincide.
3. They coincide iff both factors vanish at one ``x``: ``F_+ + F_- = 2 f(x)`` and
   ``F_- - F_+ = 2 r f(y)`` with ``r > 0``, so iff ``f(x) = f(y) = 0``.
4. ``f(x) = f(y) = 0`` iff the half-period phases ``a_1 = x - y = omega_1 T/2`` and
   ``a_2 = x + y = omega_2 T/2`` are integer multiples of ``pi``: ``a_1 = a pi``, ``a_2 = b pi``
   (``cos``: ``x, y`` in ``pi/2 + pi Z``, so ``a + b`` is odd; ``sin``: ``x, y`` in ``pi Z``, ``a +
   b`` even).  Then ``x = (a + b) pi/2``: the closing belongs to order ``n = a + b``, at ``theta =
   0`` (exact tuning); ``1 <= a < b`` because ``0 < omega_1 < omega_2``.
5. ``omega_2/omega_1 = b/a = sqrt((1+m)/(1-m))`` gives ``m = (b^2 - a^2)/(b^2 + a^2)`` (rational),
   ``T1 : T2 = b : a`` and ``T = a T1 = b T2 = a sqrt(1+m) T0 = a b sqrt(2/(a^2 + b^2)) T0``.
6. There the monodromy is ``M = (-1)^n I`` (:func:`analytic.stitching.monodromy` with
   ``omega_1 T/2 = a pi``, ``omega_2 T/2 = b pi``): every solution is (anti)periodic, the
   "coexistence" that the paper describes for ``T1 : T2 = 2 : 1``.

Hence the closings of order ``n`` are exactly the pairs ``1 <= a < b``, ``a + b = n``:
``floor((n - 1)/2)`` of them, none for ``n = 1, 2``.  A ratio ``b : a`` not in lowest terms repeats
the depth of its reduced form: ``m = 3/5`` closes orders 3 (1:2), 6 (2:4), 9 (3:6), ...  Past a
closing the two factors exchange which edge they give (the crossing is transversal; checked
numerically in the tests for every closing up to order 12).
"""

from __future__ import annotations

import decimal
from dataclasses import dataclass
from fractions import Fraction
from functools import cache
from math import gcd

import sympy as sp

from paramres.inputs import InputError

from .identity import Verdict, prove_zero
from .model import Damping, S
from .normal_form import edge_factor, normal_form
from .stitching import Parity, monodromy
from .system import PAPER, System

__all__ = [
    "Closing",
    "Closings",
    "Step",
    "closings",
    "closings_of_order",
    "closing_pairs",
    "theorem_steps",
    "family_steps",
    "DIGITS",
]

#: decimal digits of the closing period that are printed (certified)
DIGITS = 40


@dataclass(frozen=True)
class Step:
    """One step of the derivation: what is claimed, the identity checked, and the verdict."""

    claim: str
    expr: sp.Expr
    verdict: Verdict

    def _repr_latex_(self) -> str:
        """The claim, the identity checked and the verdict (Jupyter)."""
        return (
            rf"{self.claim}: $\displaystyle {sp.latex(self.expr)}$ "
            f"({self.verdict.describe()})"
        )


@dataclass(frozen=True)
class Closing:
    """The ``order``-th interval closes at depth ``m`` and period ``T`` (units of ``T0``).

    ``a, b``: ``omega_1 T/2 = a pi``, ``omega_2 T/2 = b pi`` (half-oscillation counts of each
    half); ``ratio`` is ``T1 : T2 = b : a`` as printed (``"2:1"``); ``lowest_terms`` whether
    ``gcd(a, b) = 1``; ``T_exact`` the sympy value ``a b sqrt(2/(a^2+b^2))``; ``T`` its certified
    decimal expansion (``DIGITS`` significant digits, correctly rounded); ``multiplier`` the
    ``sigma`` with ``M = sigma I`` there.
    """

    order: int
    a: int
    b: int
    m: Fraction | None
    T: str
    multiplier: int
    system: System = PAPER

    @property
    def T_exact(self) -> sp.Expr:
        if self.system.is_paper:
            return self.a * self.b * sp.sqrt(sp.Rational(2, self.a**2 + self.b**2))
        return _family_period(self.system, self.a, self.m)

    @property
    def T_text(self) -> str:
        """The exact period as text that sympy parses: ``a*b*sqrt(2/(a^2+b^2))``."""
        if self.system.is_paper:
            return f"{self.a * self.b}*sqrt(2/{self.a**2 + self.b**2})"
        return sp.sstr(self.T_exact)

    @property
    def ratio(self) -> str:
        """``T1 : T2`` (for equal halves ``b : a``; for duty ``D`` it is ``b D : a (1 - D)``)."""
        if self.system.duty == Fraction(1, 2):
            return f"{self.b}:{self.a}"
        r = Fraction(self.b) * self.system.duty / (self.a * (1 - self.system.duty))
        return f"{r.numerator}:{r.denominator}"

    @property
    def lowest_terms(self) -> bool:
        return gcd(self.a, self.b) == 1

    @property
    def reduced_ratio(self) -> str:
        g = gcd(self.a, self.b)
        return f"{self.b // g}:{self.a // g}"

    def as_json(self) -> dict:
        return {
            "order": self.order,
            "ratio": self.ratio,
            "m": None if self.m is None else f"{self.m.numerator}/{self.m.denominator}",
            "T": self.T,
            "a": self.a,
            "b": self.b,
            "lowest_terms": self.lowest_terms,
            "T_exact": self.T_text,
            "multiplier": self.multiplier,
        }


@dataclass(frozen=True)
class Closings:
    """The closing theorem (its ``steps``) and every closing of the orders ``1 .. max_order``."""

    max_order: int
    items: tuple[Closing, ...]
    steps: tuple[Step, ...]
    statement: str
    system: System = PAPER

    def _repr_html_(self) -> str:
        """The closings as a table (order, ``T1 : T2``, exact depth, certified period)."""
        from paramres.display import html_table

        return html_table(
            ("order", "a", "b", "T1 : T2", "m", "T/T0"),
            ((c.order, c.a, c.b, c.ratio, c.m, c.T_text) for c in self.items),
        )

    def __iter__(self):
        return iter(self.items)

    def __len__(self) -> int:
        return len(self.items)

    def of_order(self, n: int) -> tuple[Closing, ...]:
        return tuple(c for c in self.items if c.order == n)

    def at_ratio(self, b: int, a: int) -> tuple[Closing, ...]:
        """All closings whose ``T1 : T2`` equals ``b : a`` (in any multiple)."""
        return tuple(c for c in self.items if c.b * a == c.a * b)

    @property
    def proven(self) -> bool:
        return all(s.verdict.holds for s in self.steps)

    def as_json(self) -> list[dict]:
        return [c.as_json() for c in self.items]


STATEMENT = (
    "Without friction the n-th interval has zero width exactly where omega_1 T/2 = a pi and "
    "omega_2 T/2 = b pi with integers 1 <= a < b, a + b = n; there m = (b^2 - a^2)/(b^2 + a^2), "
    "T1 : T2 = b : a, T = a T1 = a b sqrt(2/(a^2 + b^2)) T0 (exact tuning, T = n T_av/2), and the "
    "monodromy is M = (-1)^n I. There are no other closings."
)


def closing_pairs(n: int) -> list[tuple[int, int]]:
    """``(a, b)`` with ``1 <= a < b`` and ``a + b = n``."""
    return [(a, n - a) for a in range(1, (n + 1) // 2) if a < n - a]


def _depth(a: int, b: int) -> Fraction:
    return Fraction(b * b - a * a, b * b + a * a)


def _certified_decimal(a: int, b: int, digits: int) -> str:
    """``a b sqrt(2/(a^2+b^2))`` correctly rounded to ``digits`` significant digits: an arb ball is
    computed and both its endpoints must round to the same decimal string."""
    from flint import arb, ctx

    for extra in (20, 60, 200):
        with ctx.workdps(digits + extra):
            ball = arb(a * b) * (arb(2) / arb(a * a + b * b)).sqrt()
            ends = (ball.lower(), ball.upper())
            texts = {_round_exact(e, digits) for e in ends}
        if len(texts) == 1:
            return texts.pop()
    raise ArithmeticError("could not certify the closing period")  # pragma: no cover


def _round_exact(x, digits: int) -> str:
    man, exp = x.man_exp()
    man, exp = int(man), int(exp)
    frac = Fraction(man) * (Fraction(2) ** exp)
    with decimal.localcontext() as dc:
        dc.prec = digits
        dc.rounding = decimal.ROUND_HALF_EVEN
        d = decimal.Decimal(frac.numerator) / decimal.Decimal(frac.denominator)
    return format(d, "f") if abs(d.adjusted()) < 6 else str(d)


@cache
def theorem_steps() -> tuple[Step, ...]:
    """The derivation of the closing theorem, each step checked."""
    x, y = sp.symbols("x y", real=True)
    r = sp.Symbol("r", positive=True)
    h = sp.Symbol("h", nonnegative=True)
    steps: list[Step] = []
    for parity, word in ((Parity.ODD, "odd"), (Parity.EVEN, "even")):
        Fp = edge_factor(parity, 1, symbols=(x, y, r))
        Fm = edge_factor(parity, -1, symbols=(x, y, r))
        N = normal_form(parity, symbols=(x, y, r**2, h)).subs(h, 0)
        steps.append(
            Step(
                f"{word} orders: the undamped normal form is the product of the two edge factors",
                sp.Eq(N, Fp * Fm),
                prove_zero(sp.expand(N - Fp * Fm)),
            )
        )
        f = sp.cos if parity is Parity.ODD else sp.sin
        steps.append(
            Step(
                f"{word} orders: F_+ + F_- = 2 f(x) and F_- - F_+ = 2 r f(y), so both vanish iff "
                "f(x) = f(y) = 0 (r > 0)",
                sp.Eq(
                    sp.Tuple(sp.Symbol("F_+"), sp.Symbol("F_-")), sp.Tuple(Fp, Fm), evaluate=False
                ),
                prove_zero(
                    sp.expand(Fp + Fm - 2 * f(x)) ** 2 + sp.expand(Fm - Fp - 2 * r * f(y)) ** 2
                ),
            )
        )
    # step 4: zeros of f(x), f(y) <=> integer multiples of pi for a1 = x - y, a2 = x + y
    a, b = sp.symbols("a b", integer=True, positive=True)
    j, k = sp.symbols("j k", integer=True)
    for parity, word, xv, yv in (
        (Parity.ODD, "odd", sp.pi / 2 + j * sp.pi, sp.pi / 2 + k * sp.pi),
        (Parity.EVEN, "even", j * sp.pi, k * sp.pi),
    ):
        f = sp.cos if parity is Parity.ODD else sp.sin
        zero = sp.simplify(f(xv)) == 0 and sp.simplify(f(yv)) == 0
        a1, a2 = sp.expand((xv - yv) / sp.pi), sp.expand((xv + yv) / sp.pi)
        total = sp.expand(a1 + a2)
        ok = zero and a1.is_integer and a2.is_integer
        if parity is Parity.ODD:
            ok = ok and sp.simplify((total - 1) / 2).is_integer  # a + b odd
        else:
            ok = ok and sp.simplify(total / 2).is_integer  # a + b even
        steps.append(
            Step(
                f"{word} orders: f(x) = f(y) = 0 makes a1 = x - y and a2 = x + y integer multiples "
                f"of pi with a + b {'odd' if parity is Parity.ODD else 'even'}, n = a + b",
                sp.Tuple(a1, a2, total),
                Verdict(bool(ok), "symbolic"),
            )
        )
    # step 5: the depth and the period
    m = S.m
    # omega2/omega1 = b/a, as written (sympy's attempt to decide it is the costly part)
    ratio_eq = sp.Eq(sp.sqrt((1 + m) / (1 - m)), b / a, evaluate=False)
    sol = sp.solve(sp.Eq((1 + m) / (1 - m), b**2 / a**2), m)
    m_ab = (b**2 - a**2) / (b**2 + a**2)
    ok = len(sol) == 1 and sp.simplify(sol[0] - m_ab) == 0
    steps.append(
        Step(
            "omega2/omega1 = sqrt((1+m)/(1-m)) = b/a gives m = (b^2 - a^2)/(b^2 + a^2)",
            sp.Tuple(ratio_eq, sp.Eq(m, m_ab)),
            Verdict(ok, "symbolic"),
        )
    )
    T_ab = a * sp.sqrt(1 + m_ab)  # omega1 T/2 = a pi with omega1 = 2 pi/sqrt(1+m)
    T_closed = a * b * sp.sqrt(sp.Rational(2) / (a**2 + b**2))
    ok = prove_zero(sp.simplify(T_ab**2 - T_closed**2))
    steps.append(
        Step(
            "T = a T1 = a sqrt(1+m) T0 = a b sqrt(2/(a^2+b^2)) T0 (and = b T2)",
            sp.Eq(sp.Symbol("T"), T_closed),
            ok,
        )
    )
    T_b = b * sp.sqrt(1 - m_ab)  # omega2 T/2 = b pi with omega2 = 2 pi/sqrt(1-m)
    steps.append(
        Step(
            "the same T is b T2 = b sqrt(1-m) T0",
            sp.Eq(T_b, T_closed, evaluate=False),
            prove_zero(sp.simplify(T_b**2 - T_closed**2)),
        )
    )
    # step 6: the monodromy at a closing
    M = monodromy(Damping.NONE)
    w1 = S.omega1
    sub = {S.T: 2 * a * sp.pi / w1, S.omega2: b * w1 / a}
    Mc = sp.simplify(M.subs(sub))
    target = (-1) ** (a + b) * sp.eye(2)
    diff = sp.simplify(Mc - target)
    ok = all(sp.simplify(e) == 0 for e in diff)
    steps.append(
        Step(
            "at omega1 T/2 = a pi, omega2 T/2 = b pi the monodromy is (-1)^(a+b) I = (-1)^n I",
            sp.Eq(sp.Symbol("M"), target, evaluate=False),
            Verdict(ok, "symbolic"),
        )
    )
    return tuple(steps)


@cache
def _closing(n: int, a: int, b: int) -> Closing:
    return Closing(n, a, b, _depth(a, b), _certified_decimal(a, b, DIGITS), (-1) ** n)


def closings(max_order: int = 12, system: System = PAPER) -> Closings:
    """The closing theorem with its derivation steps, and every closing of orders ``1..max_order``
    (sorted by order, then depth) of ``system`` (any member of the family, any duty)."""
    n_max = _max_order(max_order)
    if not system.is_paper:
        return _family_closings(n_max, system)
    items = tuple(
        sorted(
            (_closing(n, a, b) for n in range(1, n_max + 1) for a, b in closing_pairs(n)),
            key=lambda c: (c.order, c.m),
        )
    )
    return Closings(n_max, items, theorem_steps(), STATEMENT)


def _max_order(value) -> int:
    text = str(value).strip()
    if isinstance(value, bool) or not text.lstrip("+").isdigit():
        raise InputError(f"max-order {value!r} is not an integer; allowed range 1 to 200")
    n = int(text)
    if not 1 <= n <= 200:
        raise InputError(f"max-order {n} is outside the allowed range 1 to 200")
    return n


# ---------------------------------------------------------------------------------------------
# any member of the family, any duty

FAMILY_STATEMENT = (
    "Without friction the n-th interval of a two-level system with duty D has zero width exactly "
    "where both phases turn through whole multiples of pi: omega_1 D T = a pi and "
    "omega_2 (1 - D) T = b pi with integers a, b >= 1, a + b = n; there omega_2^2/omega_1^2 = "
    "(b D / (a (1 - D)))^2 fixes the depth, T = a / (2 D sqrt(omega_1^2/omega_0^2)) T0, and the "
    "monodromy is M = (-1)^n I. There are no other closings (r != 0)."
)


def _ratio_sq(system: System, a: int, b: int) -> Fraction:
    """``(omega2/omega1)^2`` needed for ``omega1 D T = a pi``, ``omega2 (1-D) T = b pi``."""
    D = system.duty
    return (Fraction(b) * D / (a * (1 - D))) ** 2


@cache
def _depth_solutions(system: System) -> tuple:
    """``m`` as a function of ``rho2 = (omega2/omega1)^2``: the roots in ``(0, 1)`` of
    ``omega2^2(m) = rho2 omega1^2(m)``, solved by sympy once per system (``rho2`` symbolic)."""
    rho2 = sp.Symbol("rho2", positive=True)
    W1, W2, _ = (sp.sympify(v) for v in system.values(S.m))
    num = sp.numer(sp.together(W2 - rho2 * W1))
    return rho2, tuple(sp.solve(num, S.m))


def _depths(system: System, a: int, b: int) -> list[Fraction]:
    rho2, sols = _depth_solutions(system)
    value = _ratio_sq(system, a, b)
    out = []
    for sol in sols:
        mv = sol.subs(rho2, sp.Rational(value.numerator, value.denominator))
        if not mv.is_Rational:  # nsimplify can turn a Rational into powers (-2303/2305)
            mv = sp.nsimplify(mv)
        if mv.is_Rational and 0 < mv < 1:
            out.append(Fraction(int(mv.p), int(mv.q)))
        elif mv.is_real and not mv.is_Rational:  # pragma: no cover - no built-in law needs it
            raise NotImplementedError(f"an irrational closing depth {mv} of {system.label}")
    return out


def _family_period(system: System, a: int, m) -> sp.Expr:
    """``T / T0 = a / (2 D sqrt(omega1^2))`` at the closing."""
    W1 = sp.sympify(system.omega1_sq(sp.Rational(m.numerator, m.denominator) if m else None))
    D = sp.Rational(system.duty.numerator, system.duty.denominator)
    return sp.nsimplify(a / (2 * D * sp.sqrt(W1)))


def _family_decimal(system: System, a: int, m, digits: int) -> str:
    from flint import arb, ctx, fmpq

    W1 = Fraction(system.omega1_sq(m if system.uses_depth else None))
    D = system.duty
    for extra in (20, 60, 200):
        with ctx.workdps(digits + extra):
            ball = (
                arb(fmpq(a * D.denominator, 2 * D.numerator))
                / arb(fmpq(W1.numerator, W1.denominator)).sqrt()
            )
            texts = {_round_exact(e, digits) for e in (ball.lower(), ball.upper())}
        if len(texts) == 1:
            return texts.pop()
    raise ArithmeticError("could not certify the closing period")  # pragma: no cover


@cache
def family_steps(system: System) -> tuple[Step, ...]:
    """The closing theorem for ``system``: the system-free steps 1-4 of :func:`theorem_steps`,
    then the depth equation solved for this system and the monodromy of the family at a
    closing (symbolic duty and jump)."""
    from .family import D as Dsym
    from .family import k as ksym
    from .family import monodromy as family_monodromy

    steps = list(theorem_steps()[:6])
    if system.uses_depth:
        rho2, sols = _depth_solutions(system)
        W1, W2, _ = (sp.sympify(v) for v in system.values(S.m))
        ok = bool(sols) and all(sp.simplify((W2 - rho2 * W1).subs(S.m, s)) == 0 for s in sols)
        steps.append(
            Step(
                f"{system.name}: omega2^2/omega1^2 = rho^2 solved for the depth",
                sp.Tuple(*(sp.Eq(S.m, s) for s in sols)),
                Verdict(ok, "symbolic"),
            )
        )
    j, l = sp.symbols("a b", integer=True, positive=True)
    M = family_monodromy(Damping.NONE)
    w1 = S.omega1
    sub = {S.T: j * sp.pi / (w1 * Dsym), S.omega2: l * w1 * Dsym / (j * (1 - Dsym))}
    Mc = sp.simplify(M.subs(sub))
    target = (-1) ** (j + l) * sp.eye(2)
    ok = all(sp.simplify(e) == 0 for e in sp.simplify(Mc - target))
    steps.append(
        Step(
            "at omega1 D T = a pi, omega2 (1-D) T = b pi the monodromy is (-1)^(a+b) I for every "
            "duty D and jump k",
            sp.Eq(sp.Symbol("M"), target),
            Verdict(ok, "symbolic"),
        )
    )
    _ = ksym
    return tuple(steps)


def _family_closings(n_max: int, system: System) -> Closings:
    items = [c for n in range(1, n_max + 1) for c in closings_of_order(n, system)]
    return Closings(n_max, tuple(items), family_steps(system), FAMILY_STATEMENT, system)


@cache
def closings_of_order(n: int, system: System = PAPER) -> tuple[Closing, ...]:
    """The closings of order ``n`` of ``system`` sorted by depth, without the derivation steps
    (those are :func:`closings`' ``steps``): the pairs ``a + b = n`` of the theorem, each at the
    depth its law gives (the paper's ``1 <= a < b``; any ``a, b >= 1`` for another duty)."""
    if system.is_paper:
        return tuple(sorted((_closing(n, a, b) for a, b in closing_pairs(n)), key=lambda c: c.m))
    items = []
    for a in range(1, n):
        b = n - a
        if system.uses_depth:
            depths = _depths(system, a, b)
        else:
            W1, W2 = system.omega_sq
            depths = [None] if W2 / W1 == _ratio_sq(system, a, b) else []
        for mv in depths:
            T = _family_decimal(system, a, mv, DIGITS)
            items.append(Closing(n, a, b, mv, T, (-1) ** n, system))
    items.sort(key=lambda c: c.m or 0)
    return tuple(items)
