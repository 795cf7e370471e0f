"""The paper's chains of reductions, derived step by step, each step proven from the one before.

``(12) -> (13) -> (15)``, ``(24) -> (25) -> (26)``, ``(32) -> (34) -> (35) -> (36) -> (37) ->
(39)``,
``(41) -> (42) -> (44)``, and the single results (5), (6), (14) and the stationary initial
conditions.
A :class:`Step` holds the equation the engine arrives at (in the paper's symbols), why it follows
and
the :class:`~analytic.identity.Verdict` of the check that it does; a :class:`Chain` is a titled
list of
steps that a report can print.  Nothing here is copied from the paper: the first step of every chain
is built by :mod:`analytic.stitching` from the model.

Symbols: ``\\pm`` and ``\\mp`` stand for the two signs of a square root (one per edge); a step with
them is checked by squaring.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache

import sympy as sp

from .cache import disk_cached
from .identity import Verdict, prove_multiple, prove_zero, vanishes
from .model import Damping, S, derived_quantities, physical
from .normal_form import edge_factor_link
from .stitching import EdgeKind, Parity, edge_system, general_system, paper_system

__all__ = [
    "Step",
    "Chain",
    "chains",
    "chain",
    "PM",
    "MP",
    "stationary_initial_condition",
    "substitute_abbreviations",
    "odd_order_delta_form",
]

#: the sign of a square root that distinguishes the two edges (printed as \pm and \mp)
PM = sp.Symbol(r"\pm")
MP = sp.Symbol(r"\mp")

w1, w2, T, g, m = S.omega1, S.omega2, S.T, S.gamma, S.m
q, p, wav, dw, Tav, DT = S.q, S.p, S.omega_av, S.Domega, S.T_av, S.DT


@dataclass(frozen=True)
class Step:
    """One equation of a chain: its number in the paper (or ``""``), the equation, why it follows
    from the previous step, and the verdict of that check."""

    label: str
    expr: sp.Basic
    why: str
    verdict: Verdict

    def _repr_latex_(self) -> str:
        """The equation with its number, and why it follows (Jupyter)."""
        tag = rf" \qquad ({self.label})" if self.label else ""
        return (
            rf"$\displaystyle {sp.latex(self.expr)}{tag}$ "
            f"{self.why}; {self.verdict.describe()}"
        )


@dataclass(frozen=True)
class Chain:
    """A derivation: the paper's equation numbers it covers and its steps in order."""

    key: str
    title: str
    equations: tuple[str, ...]
    steps: tuple[Step, ...]

    @property
    def proven(self) -> bool:
        return all(s.verdict.holds for s in self.steps)

    def step(self, label: str) -> Step:
        for s in self.steps:
            if s.label == label:
                return s
        raise KeyError(label)


def substitute_abbreviations(expr: sp.Expr, keep: tuple = ()) -> sp.Expr:
    """Replace ``q, p, omega_av, Delta omega, T_av, C_i, S_i`` by what they abbreviate (eqs. 5, 14,
    33), leaving the primary symbols ``omega_i, gamma, T, m``; abbreviations in ``keep`` stay (an
    identity that holds with them as free symbols holds for their values too)."""
    dq = {k: v for k, v in derived_quantities().items() if k not in keep}
    # symbols replaced by expressions free of them: one simultaneous walk
    return sp.sympify(expr).xreplace(dq)


def _residual(eq) -> sp.Expr:
    return eq.lhs - eq.rhs if isinstance(eq, sp.Equality) else sp.sympify(eq)


def _squared_residual(eq: sp.Equality) -> sp.Expr:
    """For ``L = (\\pm) R``: ``L**2 - R**2`` (the sign symbol removed)."""
    lhs, rhs = eq.lhs, eq.rhs
    rhs = rhs.subs({PM: 1, MP: 1})
    return sp.expand(lhs**2 - rhs**2)


def _follows(new: sp.Expr, old: sp.Expr, keep: tuple = ()) -> Verdict:
    """``new`` (a residual) is a non-vanishing multiple of ``old`` once abbreviations (other than
    those in ``keep``) are expanded."""
    return prove_multiple(substitute_abbreviations(new, keep), substitute_abbreviations(old, keep))


def _eq(lhs, rhs) -> sp.Equality:
    return sp.Eq(lhs, rhs, evaluate=False)


# ----------------------------------------------------------------------------- without friction


def _edge_chain(kind: EdgeKind, numbers: tuple[str, str, str, str, str], n0: int) -> Chain:
    """Conditions -> determinant -> product-to-sum form -> Delta T form, for one edge shape.

    ``numbers`` are the paper's labels of (first condition, second condition, determinant,
    reduced form, Delta T form) for this shape ("" where the paper prints none); ``n0`` the order
    whose neighbourhood the Delta T form is written for.
    """
    sysm = edge_system(kind)
    c0, c1 = sysm.conditions
    steps = [
        Step(numbers[0], c0.equation, c0.label, Verdict(True, "symbolic")),
        Step(numbers[1], c1.equation, c1.label, Verdict(True, "symbolic")),
    ]
    # the determinant, arranged as the paper does: terms with (1+m)^2 on the left
    det = sysm.determinant
    M = sysm.matrix
    lhs, rhs = M[0, 0] * M[1, 1], M[0, 1] * M[1, 0]
    if lhs.could_extract_minus_sign() and rhs.could_extract_minus_sign():
        lhs, rhs = -lhs, -rhs
    if w1 in sp.Mul.make_args(rhs):  # the bob-down factor (1+m)^2 omega_1 on the left, as printed
        lhs, rhs = rhs, lhs
    cross = sp.expand(lhs - rhs)
    steps.append(
        Step(
            numbers[2],
            _eq(lhs, rhs),
            "determinant of the two conditions = 0",
            _equal_up_to_sign(cross, det),
        )
    )
    # product to sum: the per-edge factor in q, omega_av, Delta omega
    f = sp.cos if kind.parity is Parity.ODD else sp.sin
    eps = kind.epsilon
    reduced = _eq((q + 1) * f(wav * T / 2), eps * (q - 1) * f(dw * T / 4))
    link = edge_factor_link(kind)
    steps.append(
        Step(
            numbers[3],
            reduced,
            "product to sum; divide by (1-m)^2 omega_2; q = (1+m)^2 omega_1 / ((1-m)^2 omega_2) "
            "(eq. 14)",
            _follows(_residual(reduced), det) if link.verdict.holds else link.verdict,
        )
    )
    # Delta T form around n0 T_av / 2
    th = wav * DT / 2
    arg = dw * (n0 * Tav / 2 + DT) / 4
    lhs_x = sp.expand_trig(f(n0 * sp.pi / 2 + th))  # f(omega_av T/2) at T = n0 T_av/2 + DT
    coeff = sp.simplify(lhs_x / sp.sin(th)) if lhs_x.has(sp.sin(th)) else None
    if coeff is None or coeff.has(th):  # pragma: no cover - f(n pi/2 + x) is always +-sin x here
        raise AssertionError("unexpected form of f(n pi/2 + x)")
    delta = _eq(sp.sin(th), _sign_ratio(eps / coeff) * f(arg))
    res_old = _residual(reduced).subs(T, n0 * Tav / 2 + DT)
    steps.append(
        Step(
            numbers[4],
            delta,
            f"T = {n0} T_av/2 + Delta T with omega_av T_av = 2 pi; divide by "
            f"{sp.sstr((q + 1) * coeff)}",
            _follows_delta(_residual(delta), res_old),
        )
    )
    word = "odd" if kind.parity is Parity.ODD else "even"
    return Chain(
        f"edge-{kind.value}",
        f"Edge shape {kind.value} ({word} orders), no friction",
        tuple(x for x in numbers if x),
        tuple(steps),
    )


def _equal_up_to_sign(a: sp.Expr, b: sp.Expr) -> Verdict:
    """The verdict that ``a = b``, else that of ``a = -b``: exact identities are looked for on
    both signs first (:func:`~analytic.identity.vanishes`), so that the numeric route of
    :func:`~analytic.identity.prove_zero` is taken only where neither sign is one."""
    for c in (b, -b):
        if vanishes(a - c):
            return Verdict(True, "symbolic")
    check = prove_zero(a - b)
    return check if check.holds else prove_zero(a + b)


def _follows_delta(new: sp.Expr, old: sp.Expr) -> Verdict:
    """Like :func:`_follows` for forms written with ``T_av`` and ``Delta T``: ``T_av`` is replaced
    by
    ``2 pi / omega_av`` with ``omega_av`` kept as a symbol (it cancels in ``omega_av T_av``)."""
    sub = {Tav: 2 * sp.pi / wav}
    return prove_multiple(sp.expand(new.subs(sub)), sp.expand(old.subs(sub)))


def odd_order_delta_form(kind: EdgeKind, n: int | sp.Expr) -> sp.Equality:
    """The Delta T form of an edge shape's equation around ``n T_av/2`` for any order ``n`` (of the
    shape's parity): ``sin(omega_av Delta T/2) = s_n (q-1)/(q+1) f(Delta omega (n T_av/2 + Delta
    T)/4)``.

    For the paper's eq.-13 shape the sign is ``s_n = -(-1)**((n-1)/2)``: negative (lower edge at
    small m) for n = 1, 5, 9, ..., positive (upper edge) for n = 3, 7, ...
    """
    f = sp.cos if kind.parity is Parity.ODD else sp.sin
    th = wav * DT / 2
    lhs_x = sp.expand_trig(f(n * sp.pi / 2 + th))
    coeff = sp.simplify(lhs_x / sp.sin(th))
    return _eq(sp.sin(th), _sign_ratio(kind.epsilon / coeff) * f(dw * (n * Tav / 2 + DT) / 4))


def _sign_ratio(sign: sp.Expr) -> sp.Expr:
    """``sign (q - 1)/(q + 1)`` simplified: for ``sign = +-1`` it is already in its simplest form
    (``(q - 1)/(q + 1)`` or ``(1 - q)/(q + 1)``, which ``simplify`` returns unchanged)."""
    ratio = sign * (q - 1) / (q + 1)
    return ratio if sign in (1, -1) else sp.simplify(ratio)


# ------------------------------------------------------------------------------- with friction


def _friction_chain(parity: Parity) -> Chain:
    """Paper model: (31) -> (32) -> (34) -> (36) -> (37) -> (39) (odd), (41) -> (42) -> (44)
    (even)."""
    odd = parity is Parity.ODD
    gen = general_system(parity, Damping.PAPER)
    psys = paper_system(parity)
    steps: list[Step] = []
    if odd:
        for c in gen.conditions[2:]:
            steps.append(Step("31", c.equation, c.label, Verdict(True, "symbolic")))
    rows = psys.matrix * sp.Matrix([S.A, S.B])
    for k in range(2):
        steps.append(
            Step(
                "32" if odd else "",
                _eq(sp.collect(sp.expand(rows[k]), [S.A, S.B]), 0),
                "conditions at t = 0 solved (B_2 = B_1 = B, A_2 = q A); multiplied by exp(-gamma "
                "T/2)" + ("; divided by (1-m)^2 omega_2" if k == 1 else ""),
                Verdict(True, "symbolic"),
            )
        )
    # (34): determinant / (-p), with C^2 + S^2 = 1
    sig = parity.sigma
    d34 = 2 * q * S.C1 * S.C2 - (1 + q**2) * S.S1 * S.S2 - sig * q * (p + 1 / p)
    steps.append(
        Step(
            "34" if odd else "",
            _eq(d34, 0),
            "determinant of the 2 x 2 system divided by -p, using C_i^2 + S_i^2 = 1",
            _follows(d34, psys.determinant, keep=(q, p)),
        )
    )
    if odd:
        half = sp.Rational(1, 2)
        c1c2 = _eq(S.C1 * S.C2, half * (sp.cos(dw * T / 2) + sp.cos(wav * T)))
        s1s2 = _eq(S.S1 * S.S2, half * (sp.cos(dw * T / 2) - sp.cos(wav * T)))
        for e in (c1c2, s1s2):
            steps.append(
                Step(
                    "35",
                    e,
                    "product to sum",
                    prove_zero(substitute_abbreviations(_residual(e), keep=(q, p))),
                )
            )
    f = sp.cos if odd else sp.sin
    rad = (q - 1) ** 2 * f(dw * T / 4) ** 2 - q * (p + 1 / p - 2)
    e36 = _eq((q + 1) * f(wav * T / 2), PM * sp.sqrt(rad))
    steps.append(
        Step(
            "36" if odd else "41",
            e36,
            (
                "cos(a) = 2 cos^2(a/2) - 1 in (34)"
                if odd
                else "cos(a) = 1 - 2 sin^2(a/2) in the determinant above"
            )
            + "; one sign per edge (checked squared)",
            _follows(_squared_residual(e36), d34, keep=(q, p)),
        )
    )
    e37 = _eq((q - 1) ** 2 / q * f(dw * T / 4) ** 2, p + 1 / p - 2)
    steps.append(
        Step(
            "37" if odd else "",
            e37,
            "radicand of the previous step = 0 (the two signs give the same T)",
            _follows(_residual(e37), rad, keep=(q, p)),
        )
    )
    n0 = 1 if odd else 2
    th = wav * DT / 2
    arg = dw * (n0 * Tav / 2 + DT) / 4
    lhs_x = sp.expand_trig(f(n0 * sp.pi / 2 + th))
    coeff = sp.simplify(lhs_x / sp.sin(th))
    radD = (q - 1) ** 2 * f(arg) ** 2 - q * (p - 1) ** 2 / p
    e39 = _eq(sp.sin(th), MP * sp.sqrt(radD) / (q + 1))
    old = _squared_residual(e36).subs(T, n0 * Tav / 2 + DT)
    steps.append(
        Step(
            "39" if odd else "44",
            e39,
            f"T = {n0} T_av/2 + Delta T; f(omega_av T/2) = {sp.sstr(coeff)} sin(omega_av Delta "
            "T/2); "
            "p + 1/p - 2 = (p-1)^2/p (checked squared)",
            _follows_delta(_squared_residual(e39), old),
        )
    )
    title = "Paper model with friction, " + ("odd orders" if odd else "even orders")
    eqs = ("31", "32", "34", "35", "36", "37", "39") if odd else ("41", "44")
    return Chain("friction-odd" if odd else "friction-even", title, eqs, tuple(steps))


# ----------------------------------------------------------------------------- single results


def _single_results() -> Chain:
    T1, T2 = sp.symbols("T_1 T_2", positive=True)
    steps = []
    # (5): T_av = 2 pi / omega_av = 2 T1 T2 / (T1 + T2)
    e5 = _eq(Tav, 2 * T1 * T2 / (T1 + T2))
    v5 = prove_zero(
        substitute_abbreviations(_residual(e5)).subs({T1: 2 * sp.pi / w1, T2: 2 * sp.pi / w2})
    )
    steps.append(Step("5", e5, "omega_av = (omega_1 + omega_2)/2, T_i = 2 pi / omega_i", v5))
    # (6): phase gained per modulation period
    n = S.n
    e6 = _eq(T, n * Tav / 2)
    v6 = prove_zero(
        sp.expand(
            (w1 * T / 2 + w2 * T / 2 - n * sp.pi).subs(T, n * sp.pi / wav).subs(wav, (w1 + w2) / 2)
        )
    )
    steps.append(Step("6", e6, "omega_1 T/2 + omega_2 T/2 = n pi", v6))
    # (14): q in terms of m
    e14 = _eq(q, ((1 + m) / (1 - m)) ** sp.Rational(3, 2))
    v14 = prove_zero(physical(substitute_abbreviations(_residual(e14))))
    steps.append(
        Step(
            "14",
            e14,
            "q = (1+m)^2 omega_1 / ((1-m)^2 omega_2) with omega_i = omega_0/sqrt(1 -+ m)",
            v14,
        )
    )
    return Chain("single", "Single results", ("5", "6", "14"), tuple(steps))


def stationary_initial_condition(kind: EdgeKind) -> sp.Expr:
    """``phi'(0+)/phi(0+)`` of the undamped boundary oscillation of shape ``kind``.

    Read off the shape's bob-down segment at ``t = 0``: ``omega_1 tan(omega_1 T/4)`` for the
    cos-shaped first half (the paper's remark after eq. 15 and after eq. 26), and
    ``-omega_1 cot(omega_1 T/4)`` for the sin-shaped one (the paper's upper edges, not printed).
    """
    seg1 = edge_system(EdgeKind(kind)).segments[0]
    ratio = seg1.dphi.subs(S.t, 0) / seg1.phi.subs(S.t, 0)
    # the amplitude cancels; sin/cos of one argument becomes tan (or 1/tan)
    return _tan_form(sp.cancel(ratio))


def _tan_form(e: sp.Expr) -> sp.Expr:
    """``e`` with ``sin(x)**k cos(x)**-k`` written ``tan(x)**k`` (what ``trigsimp`` makes of a
    product with one such pair, by the definition of ``tan``); ``trigsimp`` for anything else."""
    powers: dict = {}
    rest = []
    for f in sp.Mul.make_args(e):
        b, k = f.as_base_exp()
        if isinstance(b, (sp.sin, sp.cos)) and k.is_Integer:
            powers[b] = k
        else:
            rest.append(f)
    args = {b.args[0] for b in powers}
    if len(powers) == 2 and len(args) == 1:
        (x,) = args
        k = powers.get(sp.sin(x))
        if k is not None and powers.get(sp.cos(x)) == -k:
            return sp.Mul(*rest, sp.tan(x) ** k)
    return sp.trigsimp(e)  # pragma: no cover - the stationary ratios are all of that form


def _initial_conditions() -> Chain:
    steps = []
    labels = {
        EdgeKind.ODD_COS_SIN: "IC-15",
        EdgeKind.EVEN_COS_COS: "IC-26",
        EdgeKind.ODD_SIN_COS: "",
        EdgeKind.EVEN_SIN_SIN: "",
    }
    phi0, dphi0 = sp.Function(r"\varphi_1")(0), sp.Function(r"\dot{\varphi}_1")(0)
    for kind, label in labels.items():
        ratio = stationary_initial_condition(kind)
        seg1 = edge_system(kind).segments[0]
        check = prove_zero(sp.expand(seg1.dphi.subs(S.t, 0) - ratio * seg1.phi.subs(S.t, 0)))
        steps.append(
            Step(
                label,
                _eq(dphi0, ratio * phi0),
                f"edge shape {kind.value}: its first segment at t = 0",
                check,
            )
        )
    return Chain(
        "initial", "Stationary initial conditions on the edges", ("IC-15", "IC-26"), tuple(steps)
    )


@lru_cache(maxsize=1)
@disk_cached("chains")
def chains() -> tuple[Chain, ...]:
    """Every chain, in the order of the paper."""
    return (
        _single_results(),
        _edge_chain(EdgeKind.ODD_COS_SIN, ("10", "11", "12", "13", "15"), 1),
        _edge_chain(EdgeKind.ODD_SIN_COS, ("", "", "", "", "15-upper"), 1),
        _edge_chain(EdgeKind.EVEN_COS_COS, ("22", "23", "24", "25", "26"), 2),
        _edge_chain(EdgeKind.EVEN_SIN_SIN, ("", "", "", "", "26-upper"), 2),
        _initial_conditions(),
        _friction_chain(Parity.ODD),
        _friction_chain(Parity.EVEN),
    )


def chain(key: str) -> Chain:
    for c in chains():
        if c.key == key:
            return c
    raise KeyError(key)
