"""What a series of the edges is: the result type shared by :mod:`analytic.expansions` (without
friction) and :mod:`analytic.thresholds` (above a threshold), and the checks of their arguments."""

from __future__ import annotations

from dataclasses import dataclass, field

import sympy as sp

from .stitching import Parity

__all__ = ["EdgeSeries", "MAX_TERMS", "TERM_LIMITS"]

#: the largest number of terms (powers of m) a series may be asked for (integer orders of the
#: paper's system without friction; the other routes have the lower limits of :data:`TERM_LIMITS`)
MAX_TERMS = 40

#: the largest number of terms per route, where a call still takes a few seconds: the cost grows
#: about like ``K^3`` (frictionless, order 6: K = 30 about 1 s, K = 40 about 2.5 s; the closed
#: forms in ``n``: K = 24 about 1.5 s, K = 40 about 10 s; with friction the edges through K = 12
#: take under 1 s, K = 16 about 2 s, but the threshold series the command adds K = 16 about 8 s)
TERM_LIMITS = {"frictionless": MAX_TERMS, "parity": 24, "friction": 12, "family": 12}
_ROUTE_WORDS = {
    "frictionless": "without friction",
    "parity": "for the closed forms in n (odd/even)",
    "friction": "with friction",
    "family": "for the other members of the family",
}

_PARITY_WORDS = {"odd": Parity.ODD, "even": Parity.EVEN}


@dataclass(frozen=True)
class EdgeSeries:
    """Both edges of order ``order`` as truncated power series (sympy expressions in ``m``).

    ``lower``/``upper`` are in the requested ``units`` (``"T0"``: ``T/T0``; ``"Tav"``: ``T/T_av``,
    with the paper's frictionless ``T_av = 2 pi/omega_av`` also in the exact damping model);
    ``in_T0`` and ``in_Tav`` hold both.  ``theta`` holds ``omega_av Delta T/2`` on each edge.
    ``scaled`` (with friction) holds the same series with the symbol ``s = sqrt(1 - nu^2)`` kept,
    ``nu = (m_min0/m)^p``.  ``lower_factor`` is the ``eps`` of the per-edge factor (``cos x - eps r
    cos y`` / ``sin x - eps r sin y``) whose root is the lower edge at small ``m`` (``None`` with
    friction, where the edges are the two roots of the normal form).  ``notes`` say how the series
    were obtained.
    """

    order: int | str
    terms: int
    units: str
    in_T0: dict[str, sp.Expr]
    in_Tav: dict[str, sp.Expr]
    theta: dict[str, sp.Expr]
    lower_factor: int | None = None
    Q: object = None
    damping: str | None = None
    threshold: dict | None = None
    notes: tuple[str, ...] = field(default=())
    scaled: dict | None = None
    #: the member of the family (:mod:`analytic.system`); ``None``: the paper's pendulum
    system: object = None

    def _repr_latex_(self) -> str:
        """Both edges as formulas (Jupyter renders them)."""
        from paramres.display import display_math

        unit = "T_0" if self.units == "T0" else "T_{av}"
        return display_math([(f"T_-/{unit}", self.lower), (f"T_+/{unit}", self.upper)])

    @property
    def lower(self) -> sp.Expr:
        return (self.in_T0 if self.units == "T0" else self.in_Tav)["lower"]

    @property
    def upper(self) -> sp.Expr:
        return (self.in_T0 if self.units == "T0" else self.in_Tav)["upper"]

    def as_json(self, edge_printer=str) -> dict:
        """The series as text; ``edge_printer`` prints the edges (``lower``, ``upper``,
        ``in_T0``, ``in_Tav``), ``str`` everything else."""
        # ``lower``/``upper`` are entries of ``in_T0`` or ``in_Tav``: each expression is printed
        # once (printing dominates for long series)
        printed: dict[int, tuple[object, str]] = {}  # id -> (the object, kept alive; its text)

        def text(v, printer=str) -> str:
            hit = printed.get(id(v))
            if hit is None:
                hit = printed[id(v)] = (v, printer(v))
            return hit[1]

        def edge(v) -> str:
            return text(v, edge_printer)

        out = {
            **({} if self.system is None else self.system.as_json()),
            "order": self.order,
            "terms": self.terms,
            "units": self.units,
            "lower": edge(self.lower),
            "upper": edge(self.upper),
            "in_T0": {k: edge(v) for k, v in self.in_T0.items()},
            "in_Tav": {k: edge(v) for k, v in self.in_Tav.items()},
        }
        if self.lower_factor is not None:
            out["lower_factor_epsilon"] = self.lower_factor
        if self.Q is not None:
            out["Q"] = text(self.Q)
            out["damping"] = self.damping
        if self.threshold is not None:
            out["threshold"] = {k: text(v) for k, v in self.threshold.items()}
        if self.scaled is not None:
            out["scaled"] = {
                "s": text(self.scaled["s"]),
                "in_T0": {k: text(v) for k, v in self.scaled["T0"].items()},
                "in_Tav": {k: text(v) for k, v in self.scaled["Tav"].items()},
            }
        return out


def _check_terms(terms, route: str = "frictionless") -> int:
    """``terms`` checked against the limit of ``route`` (a key of :data:`TERM_LIMITS`)."""
    from paramres.inputs import InputError

    limit = TERM_LIMITS[route]
    if isinstance(terms, bool) or not isinstance(terms, int) or not 1 <= terms <= limit:
        extra = (
            f" {_ROUTE_WORDS[route]} (the cost grows about like K^3; K = {limit} takes seconds)"
            if isinstance(terms, int) and not isinstance(terms, bool) and terms > limit
            else ""
        )
        raise InputError(f"terms {terms!r} is outside the allowed range 1 to {limit}{extra}")
    return terms


def _check_order(order):
    from paramres.inputs import as_order

    if isinstance(order, str) and order.strip().lower() in _PARITY_WORDS:
        return order.strip().lower()
    return as_order(order)
