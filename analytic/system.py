"""The model axis: one description of every two-level square-wave parametric oscillator.

A member of the family (``shared`` conventions, README "The model family") is fixed by

* the **duty** ``D`` (``0 < D < 1``, exact): phase 1 lasts ``D T``, phase 2 ``(1 - D) T``;
* the **frequencies** ``omega_i(m)^2`` of the two phases, in units of ``omega0^2`` (``omega0`` is
  the frequency at depth 0, so periods are in units of ``T0 = 2 pi/omega0``);
* the **jump** ``k(m)``: the angular velocity is multiplied by ``k`` at the switch 1 -> 2 and by
  ``1/k`` at 2 -> 1 (the angle is continuous; ``k = J1/J2`` conserves ``J phi'``);
* the **damping**: one viscous ``gamma`` in both phases, ``Q = omega0/(2 gamma)``, in the
  ``exact`` or the ``paper`` model (given with each question, not with the system).

A system's laws are plain rational arithmetic in ``m`` (``+ - * /`` and integer powers), written
once in :data:`LAWS`.  The same function serves every number type: sympy symbols (the derivations
in :mod:`analytic.family`), exact :class:`~fractions.Fraction` s, mpmath numbers, python-flint
balls and numpy arrays (the numeric routes in :mod:`verify`).  Adding a system means adding one
entry to :data:`LAWS` and nothing else.

A ``custom`` system is given directly by ``omega1^2, omega2^2`` (units of ``omega0^2``) and ``k``;
it has no depth.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from fractions import Fraction
from functools import lru_cache

from paramres.inputs import InputError, as_number

__all__ = [
    "System",
    "Law",
    "LAWS",
    "NAMES",
    "system",
    "custom",
    "PAPER",
    "phase_regimes",
    "is_normal",
]


@dataclass(frozen=True)
class Law:
    """How one built-in system depends on the depth ``m``: ``omega1^2``, ``omega2^2`` (units of
    ``omega0^2``) and the velocity factor ``k`` at the switch 1 -> 2, and a line of physics."""

    omega1_sq: Callable
    omega2_sq: Callable
    jump: Callable
    picture: str


def _pendulum_w1(m):
    return 1 / (1 + m)


def _pendulum_w2(m):
    return 1 / (1 - m)


def _pendulum_k(m):
    return ((1 + m) / (1 - m)) ** 2


def _torsion_k(m):
    return (1 + m) / (1 - m)


def _meissner_w1(m):
    return 1 - m


def _meissner_w2(m):
    return 1 + m


def _meissner_k(m):
    return m * 0 + 1


#: the built-in systems.  Phase 1 is always the low-frequency phase.
LAWS: dict[str, Law] = {
    "pendulum": Law(
        _pendulum_w1,
        _pendulum_w2,
        _pendulum_k,
        "bob shifted along a light rod, l = l0 (1 +- m); J ~ l^2 (the paper's system)",
    ),
    "torsion": Law(
        _pendulum_w1,
        _pendulum_w2,
        _torsion_k,
        "torsion pendulum, moment of inertia J0 (1 +- m), torque constant fixed",
    ),
    "meissner": Law(
        _meissner_w1,
        _meissner_w2,
        _meissner_k,
        "stiffness switched (spring, MEMS resonator): k0 (1 -+ m), no jump of the velocity",
    ),
}

#: every system name the engine accepts
NAMES = (*LAWS, "custom")


#: equal phases, the paper's duty
_HALF = Fraction(1, 2)


@dataclass(frozen=True)
class System:
    """One member of the family: a built-in ``name`` (laws in :data:`LAWS`) or ``"custom"``
    (constants ``omega_sq = (omega1^2, omega2^2)`` and ``jump``), and the duty ``D``.

    Values are exact :class:`~fractions.Fraction` s; a ``System`` is hashable and compares by
    value, so it can key caches.
    """

    name: str = "pendulum"
    duty: Fraction = Fraction(1, 2)
    omega_sq: tuple[Fraction, Fraction] | None = None
    jump_value: Fraction | None = None

    def __post_init__(self) -> None:
        """The model's ranges hold for every ``System``, also one built directly (not by
        :func:`custom` or :func:`system`): ``0 < D < 1``, a custom system's ``omega_i^2 > 0``
        and ``k > 0``.  The proofs rely on them (an over-damped phase has ``nu_i < 1`` only where
        ``omega_i^2 > 0``, :func:`verify.hump.overdamped_no_interval`)."""
        if self.name not in NAMES:
            raise InputError(f"system {self.name!r} is not one of: {', '.join(NAMES)}")
        if not 0 < self.duty < 1:
            raise InputError(f"duty D = {self.duty} is outside the allowed range 0 < D < 1")
        if self.name != "custom":
            return
        if self.omega_sq is None or len(self.omega_sq) != 2 or self.jump_value is None:
            raise InputError("a custom system needs omega_sq = (omega1^2, omega2^2) and jump k")
        for w in self.omega_sq:
            if not w > 0:
                raise InputError(
                    f"omega^2 = {w} is not positive; allowed range omega^2 > 0 (units of omega0^2)"
                )
        if not self.jump_value > 0:
            raise InputError(f"jump k = {self.jump_value} is not positive; allowed range k > 0")

    def __hash__(self) -> int:
        """The hash of the fields, computed once (a system keys the caches of every numeric
        call, and hashing its Fractions costs more than a 15-digit edge's parameters)."""
        h = self.__dict__.get("_hash")
        if h is None:
            h = hash((self.name, self.duty, self.omega_sq, self.jump_value))
            object.__setattr__(self, "_hash", h)
        return h

    def __getstate__(self) -> dict:
        """The fields without the kept hash: a string's hash differs from one process to the
        next, so a system sent to a worker process (:mod:`verify.engine`) hashes there again."""
        state = dict(self.__dict__)
        state.pop("_hash", None)
        return state

    # -- what the laws give ---------------------------------------------------------------

    @property
    def uses_depth(self) -> bool:
        """Whether the system depends on a modulation depth ``m`` (built-ins do; custom not)."""
        return self.name != "custom"

    @property
    def is_paper(self) -> bool:
        """The paper's own system: the pendulum with equal halves."""
        return self.name == "pendulum" and self.duty == _HALF

    @property
    def picture(self) -> str:
        if self.name == "custom":
            return "given directly: omega1^2, omega2^2 (units of omega0^2) and the jump k"
        return LAWS[self.name].picture

    def omega1_sq(self, m=None):
        """``omega1^2 / omega0^2`` at depth ``m`` (any number type, or a sympy symbol)."""
        if self.name == "custom":
            return _const(self.omega_sq[0], m)
        return LAWS[self.name].omega1_sq(m)

    def omega2_sq(self, m=None):
        """``omega2^2 / omega0^2`` at depth ``m``."""
        if self.name == "custom":
            return _const(self.omega_sq[1], m)
        return LAWS[self.name].omega2_sq(m)

    def jump(self, m=None):
        """The velocity factor ``k`` at the switch 1 -> 2 (``1/k`` at 2 -> 1)."""
        if self.name == "custom":
            return _const(self.jump_value, m)
        return LAWS[self.name].jump(m)

    def values(self, m=None) -> tuple:
        """``(omega1^2, omega2^2, k)`` at ``m``."""
        return self.omega1_sq(m), self.omega2_sq(m), self.jump(m)

    # -- variants and text ----------------------------------------------------------------

    def _constants(self) -> tuple[Fraction, Fraction, Fraction]:
        """``(omega1^2, omega2^2, k)`` of a custom system."""
        if self.omega_sq is None or self.jump_value is None:
            raise ValueError(f"the {self.name} system has no constant frequencies")
        return self.omega_sq[0], self.omega_sq[1], self.jump_value

    def with_duty(self, duty) -> System:
        return System(self.name, _as_duty(duty), self.omega_sq, self.jump_value)

    def swapped(self) -> System:
        """The same oscillator started in the other phase: phases exchanged, ``D -> 1 - D``,
        ``k -> 1/k`` (custom systems only; a built-in keeps phase 1 the low-frequency one)."""
        if self.name != "custom":
            raise InputError("only a custom system can swap its phases")
        w1, w2, k = self._constants()
        return System("custom", 1 - self.duty, (w2, w1), 1 / k)

    @property
    def label(self) -> str:
        """Short text: ``pendulum``, ``meissner, D = 1/3``, ``custom (4/5, 6/5; k = 1)``."""
        head = self.name
        if self.name == "custom":
            w1, w2, k = self._constants()
            head = f"custom (omega^2 = {_text(w1)}, {_text(w2)}; k = {_text(k)})"
        if self.duty != Fraction(1, 2):
            head += f", D = {_text(self.duty)}"
        return head

    def as_json(self) -> dict:
        """The description as JSON: exact values as fraction strings."""
        doc: dict[str, object] = {"system": self.name, "duty": _text(self.duty)}
        if self.name == "custom":
            w1, w2, k = self._constants()
            doc["omega_sq"] = [_text(w1), _text(w2)]
            doc["jump"] = _text(k)
        return doc


def _const(value: Fraction, m):
    """A custom constant: a sympy Rational when ``m`` is symbolic, else the exact Fraction (the
    numeric routes lift exact rationals into their own number type)."""
    return _sympy_rational(value) if m is not None and _is_sympy(m) else value


def _is_sympy(x) -> bool:
    return type(x).__module__.startswith("sympy")


def _sympy_rational(value: Fraction):
    import sympy as sp

    return sp.Rational(value.numerator, value.denominator)


def _text(x: Fraction) -> str:
    return str(x.numerator) if x.denominator == 1 else f"{x.numerator}/{x.denominator}"


def _rational(value, what: str, allowed: str) -> Fraction:
    """A user value as an exact rational (decimal strings are exact; a float means its shortest
    decimal)."""
    return as_number(value, name=what, allowed=allowed)


def _as_duty(duty) -> Fraction:
    D = _rational(duty, "duty", "0 < D < 1")
    if not 0 < D < 1:
        raise InputError(f"duty D = {duty} is outside the allowed range 0 < D < 1")
    return D


def custom(omega_sq, jump=1, duty="1/2") -> System:
    """A custom two-level system: ``omega_sq = (omega1^2, omega2^2)`` in units of ``omega0^2``
    (exact: ``("4/5", "6/5")``), the velocity factor ``jump = k`` at the switch 1 -> 2, the duty.

    >>> custom(("4/5", "6/5"), jump=1, duty="1/3").label
    'custom (omega^2 = 4/5, 6/5; k = 1), D = 1/3'
    """
    if isinstance(omega_sq, str):
        omega_sq = omega_sq.split(",")
    try:
        items = list(omega_sq)
    except TypeError:
        raise InputError(
            f"omega_sq = {omega_sq!r} must be two numbers omega1^2, omega2^2 > 0"
        ) from None
    if len(items) != 2:
        raise InputError(
            f"omega_sq = {omega_sq!r} must be two numbers omega1^2, omega2^2 > 0 (got {len(items)})"
        )
    w1, w2 = (_rational(w, "omega^2", "omega^2 > 0 (units of omega0^2)") for w in items)
    ws = (w1, w2)
    for given, w in zip(items, ws, strict=True):
        if not w > 0:
            raise InputError(
                f"omega^2 = {given} is not positive; allowed range omega^2 > 0 (units of omega0^2)"
            )
    k = _rational(jump, "jump k", "k > 0")
    if not k > 0:
        raise InputError(f"jump k = {jump} is not positive; allowed range k > 0")
    return System("custom", _as_duty(duty), ws, k)


def system(name="pendulum", *, duty="1/2", omega_sq=None, jump=None) -> System:
    """The system called ``name`` with duty ``duty``; ``custom`` takes ``omega_sq`` and ``jump``.

    A :class:`System` passes through (``duty`` then must be left at its default or agree).
    """
    if isinstance(name, System):
        if omega_sq is not None or jump is not None:
            raise InputError("omega_sq and jump describe a custom system; pass them to custom()")
        return name if _as_duty(duty) == Fraction(1, 2) else name.with_duty(duty)
    key = str(name).strip().lower()
    if key not in NAMES:
        raise InputError(f"system {name!r} is not one of: {', '.join(NAMES)}")
    if key == "custom":
        if omega_sq is None:
            raise InputError("system custom needs omega_sq = (omega1^2, omega2^2), e.g. 4/5,6/5")
        return custom(omega_sq, 1 if jump is None else jump, duty)
    if omega_sq is not None or jump is not None:
        raise InputError(
            f"omega_sq and jump are only for system custom (system {key} has its own laws)"
        )
    return _built_in(key, _as_duty(duty))


@lru_cache(maxsize=512)
def _built_in(name: str, duty: Fraction) -> System:
    """The built-in system ``name`` at ``duty``, one object per value (so that the caches it
    keys find it by identity)."""
    return System(name, duty)


#: the paper's system (pendulum, equal halves)
PAPER = System()


def phase_regimes(system: System, m, Q, damping: str) -> tuple[str, str]:
    """``"undamped"``, ``"under"``, ``"critical"`` or ``"over"`` for each phase, decided in exact
    rational arithmetic on ``omega_i^2 - gamma^2`` (units of ``omega0^2``, ``gamma = 1/(2Q)``).

    The paper model keeps the undamped frequencies, so its phases are ``"under"`` for any ``Q``.
    ``m`` and ``Q`` must be exact (``Fraction``); this is the one definition of the regime rule.
    """
    if Q is None:
        return "undamped", "undamped"
    if damping == "paper":
        return "under", "under"
    g2 = 1 / (4 * Fraction(Q) ** 2)

    def one(w) -> str:
        z = Fraction(w) - g2
        return "under" if z > 0 else ("critical" if z == 0 else "over")

    w1, w2, _ = system.values(Fraction(m) if system.uses_depth else None)
    return one(w1), one(w2)


def is_normal(regimes: tuple[str, str]) -> bool:
    """Whether the normal form applies: no phase critically or over-damped."""
    return all(r in ("undamped", "under") for r in regimes)
