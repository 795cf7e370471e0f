"""What a series of the edges is: the result type shared by :mod:`analytic.expansions` (without
friction) and :mod:`analytic.thresholds` (above a threshold), and the checks of their arguments."""

from __future__ import annotations

from dataclasses import dataclass, field

import sympy as sp

from .stitching import Parity

__all__ = ["EdgeSeries", "MAX_TERMS"]

#: the largest number of terms (powers of m) a series may be asked for
MAX_TERMS = 12

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

    def as_json(self) -> dict:
        out = {
            **({} if self.system is None else self.system.as_json()),
            "order": self.order,
            "terms": self.terms,
            "units": self.units,
            "lower": str(self.lower),
            "upper": str(self.upper),
            "in_T0": {k: str(v) for k, v in self.in_T0.items()},
            "in_Tav": {k: str(v) for k, v in self.in_Tav.items()},
        }
        if self.lower_factor is not None:
            out["lower_factor_epsilon"] = self.lower_factor
        if self.Q is not None:
            out["Q"] = str(self.Q)
            out["damping"] = self.damping
        if self.threshold is not None:
            out["threshold"] = {k: str(v) for k, v in self.threshold.items()}
        if self.scaled is not None:
            out["scaled"] = {
                "s": str(self.scaled["s"]),
                "in_T0": {k: str(v) for k, v in self.scaled["T0"].items()},
                "in_Tav": {k: str(v) for k, v in self.scaled["Tav"].items()},
            }
        return out


def _check_terms(terms) -> int:
    from paramres.inputs import InputError

    if isinstance(terms, bool) or not isinstance(terms, int) or not 1 <= terms <= MAX_TERMS:
        raise InputError(f"terms {terms!r} is outside the allowed range 1 to {MAX_TERMS}")
    return terms


def _check_order(order):
    from paramres.inputs import as_order

    if isinstance(order, str) and order.strip().lower() in _PARITY_WORDS:
        return order.strip().lower()
    return as_order(order)
