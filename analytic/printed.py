"""The paper's formulas exactly as printed: the things being checked, never used to derive anything.

Each entry transcribes one numbered formula of the text (symbols of :mod:`analytic.model`;
``PM``/``MP``
for the printed ``\\pm``/``\\mp``).  Misprints are transcribed as printed: finding them is the job
of
:mod:`analytic.catalogue_rows`, which compares these with what :mod:`analytic.reductions` derives.
The text around a formula is paraphrased in :data:`CLAIMS` where the paper makes a checkable
statement
(a cross-reference, or "the same equation serves ...").
"""

from __future__ import annotations

from functools import lru_cache

import sympy as sp

from .model import S
from .reductions import MP, PM

__all__ = ["printed", "CLAIMS", "phi", "dphi"]

t, T, m, g = S.t, S.T, S.m, S.gamma
w0, w1, w2 = S.omega0, S.omega1, S.omega2
q, p, wav, dw, Tav, DT = S.q, S.p, S.omega_av, S.Domega, S.T_av, S.DT
A1, A2, B1, B2, A, B = S.A1, S.A2, S.B1, S.B2, S.A, S.B
C1, C2, S1, S2 = S.C1, S.C2, S.S1, S.S2

#: function symbols for the angle and angular velocity of half i
phi = {1: sp.Function(r"\varphi_1"), 2: sp.Function(r"\varphi_2")}
dphi = {1: sp.Function(r"\dot{\varphi}_1"), 2: sp.Function(r"\dot{\varphi}_2")}


def _eq(a, b):
    return sp.Eq(a, b, evaluate=False)


@lru_cache(maxsize=1)
def printed() -> dict[str, tuple[sp.Equality, ...]]:
    """Label -> the printed equation(s) under that number."""
    ph, dph = sp.Function(r"\varphi"), sp.Function(r"\dot{\varphi}")
    T1, T2 = sp.symbols("T_1 T_2", positive=True)
    n = S.n
    half = sp.Rational(1, 2)
    return {
        "1": (_eq(sp.Symbol(r"\omega"), 2 * w0 / n), _eq(T, n * S.T0 / 2)),
        "2": (
            _eq(
                sp.Derivative(ph(t), t, 2)
                + 2 * g * sp.Derivative(ph(t), t)
                + w1**2 * sp.sin(ph(t)),
                0,
            ),
            _eq(w1, w0 / sp.sqrt(1 + m)),
        ),
        "3": (
            _eq(
                sp.Derivative(ph(t), t, 2)
                + 2 * g * sp.Derivative(ph(t), t)
                + w2**2 * sp.sin(ph(t)),
                0,
            ),
            _eq(w2, w0 / sp.sqrt(1 - m)),
        ),
        "4": (_eq((1 + m) ** 2 * dph(1), (1 - m) ** 2 * dph(2)),),
        "5": (_eq(Tav, 2 * sp.pi / wav), _eq(Tav, 2 * T1 * T2 / (T1 + T2))),
        "6": (_eq((w1 + w2) / 2 * T, n * sp.pi), _eq(T, n * Tav / 2)),
        "8": (
            _eq(phi[1](t), -A1 * sp.cos(w1 * (t - T / 4))),
            _eq(dphi[1](t), A1 * w1 * sp.sin(w1 * (t - T / 4))),
        ),
        "9": (
            _eq(phi[2](t), -A2 * sp.sin(w2 * (t + T / 4))),
            _eq(dphi[2](t), -A2 * w2 * sp.cos(w2 * (t + T / 4))),
        ),
        "10": (_eq(A1 * sp.cos(w1 * T / 4), A2 * sp.sin(w2 * T / 4)),),
        "11": (
            _eq(
                A1 * (1 + m) ** 2 * w1 * sp.sin(w1 * T / 4),
                A2 * (1 - m) ** 2 * w2 * sp.cos(w2 * T / 4),
            ),
        ),
        "12": (
            _eq(
                (1 + m) ** 2 * w1 * sp.sin(w1 * T / 4) * sp.sin(w2 * T / 4),
                (1 - m) ** 2 * w2 * sp.cos(w1 * T / 4) * sp.cos(w2 * T / 4),
            ),
        ),
        "13": (_eq((q + 1) * sp.cos(wav * T / 2), (q - 1) * sp.cos(dw * T / 4)),),
        "14": (_eq(q, ((1 + m) / (1 - m)) ** sp.Rational(3, 2)),),
        "15": (_eq(sp.sin(wav * DT / 2), -(q - 1) / (q + 1) * sp.cos(dw * (Tav / 2 + DT) / 4)),),
        "IC-15": (_eq(dphi[1](0), w1 * sp.tan(w1 * T / 4) * phi[1](0)),),
        "16": (
            _eq(phi[1](t), B1 * sp.sin(w1 * (t - T / 4))),
            _eq(dphi[1](t), B1 * w1 * sp.cos(w1 * (t - T / 4))),
        ),
        "17": (
            _eq(phi[2](t), -B2 * sp.cos(w2 * (t + T / 4))),
            _eq(dphi[2](t), B2 * w2 * sp.sin(w2 * (t + T / 4))),
        ),
        "20": (
            _eq(phi[1](t), -A1 * sp.cos(w1 * (t - T / 4))),
            _eq(dphi[1](t), A1 * w1 * sp.sin(w1 * (t - T / 4))),
        ),
        "21": (
            _eq(phi[2](t), A2 * sp.cos(w2 * (t + T / 4))),
            _eq(dphi[2](t), -A2 * w2 * sp.sin(w2 * (t + T / 4))),
        ),
        "22": (_eq(A1 * sp.cos(w1 * T / 4), -A2 * sp.cos(w2 * T / 4)),),
        "23": (
            _eq(
                A1 * (1 + m) ** 2 * w1 * sp.sin(w1 * T / 4),
                A2 * (1 - m) ** 2 * w2 * sp.cos(w2 * T / 4),
            ),
        ),
        "24": (
            _eq(
                (1 + m) ** 2 * w1 * sp.sin(w1 * T / 4) * sp.cos(w2 * T / 4),
                -((1 - m) ** 2) * w2 * sp.sin(w2 * T / 4) * sp.cos(w1 * T / 4),
            ),
        ),
        "25": (_eq((q + 1) * sp.sin(wav * T / 2), (q - 1) * sp.sin(dw * T / 4)),),
        "26": (_eq(sp.sin(wav * DT / 2), -(q - 1) / (q + 1) * sp.sin(dw * (Tav + DT) / 4)),),
        "IC-26": (_eq(dphi[1](0), w1 * sp.tan(w1 * T / 4) * phi[1](0)),),
        "28": (
            _eq(phi[1](t), (A1 * sp.sin(w1 * t) + B1 * sp.cos(w1 * t)) * sp.exp(-g * t)),
            _eq(dphi[1](t), (A1 * w1 * sp.cos(w1 * t) - B1 * w1 * sp.sin(w1 * t)) * sp.exp(-g * t)),
        ),
        "29": (_eq(phi[2](t), (A2 * sp.sin(w2 * t) + B2 * sp.cos(w2 * t)) * sp.exp(-g * t)),),
        "30": (
            _eq(dphi[2](t), (A2 * w2 * sp.cos(w2 * t) - B2 * w2 * sp.sin(w2 * t)) * sp.exp(-g * t)),
        ),
        "31": (
            _eq(phi[1](T / 2), -phi[2](-T / 2)),
            _eq((1 + m) ** 2 * dphi[1](T / 2), -((1 - m) ** 2) * dphi[2](-T / 2)),
        ),
        "32": (
            _eq((p * S1 - q * S2) * A + (p * C1 + C2) * B, 0),
            _eq(q * (p * C1 + C2) * A - (p * q * S1 - S2) * B, 0),
        ),
        "33": (
            _eq(C1, sp.cos(w1 * T / 2)),
            _eq(C2, sp.cos(w2 * T / 2)),
            _eq(S1, sp.sin(w1 * T / 2)),
            _eq(S2, sp.sin(w2 * T / 2)),
        ),
        "34": (_eq(2 * q * C1 * C2 - (1 + q**2) * S1 * S2 + q * (p + 1 / p), 0),),
        "35": (
            _eq(C1 * C2, half * (sp.cos(dw * T / 2) + sp.cos(wav * T))),
            _eq(S1 * S2, half * (sp.cos(dw * T / 2) - sp.cos(wav * T))),
        ),
        "36": (
            _eq(
                (q + 1) * sp.cos(wav * T / 2),
                PM * sp.sqrt((q - 1) ** 2 * sp.cos(dw * T / 4) ** 2 - q * (p + 1 / p - 2)),
            ),
        ),
        "39": (
            _eq(
                sp.sin(wav * DT / 2),
                MP
                / (q + 1)
                * sp.sqrt(
                    (q - 1) ** 2 * sp.cos(dw * (Tav / 2 + DT) / 4) ** 2 - q * (p - 1) ** 2 / p
                ),
            ),
        ),
        "41": (
            _eq(
                (q + 1) * sp.sin(wav * T / 2),
                PM * sp.sqrt((q - 1) ** 2 * sp.sin(dw * T / 4) ** 2 - q * (p + 1 / p - 2)),
            ),
        ),
        "44": (
            _eq(
                sp.sin(wav * DT / 2),
                MP
                / (q + 1)
                * sp.sqrt((q - 1) ** 2 * sp.sin(dw * (Tav + DT) / 4) ** 2 - q * (p - 1) ** 2 / p),
            ),
        ),
    }


#: Checkable statements of the text, paraphrased: label -> (what the text says, the equation it
#: refers to as printed, what it is said to be the same as).
CLAIMS: dict[str, tuple[str, str, str]] = {
    "39-ref": (
        "After eq. (39): 'at zero friction $p = 1$, and (39) coincides with (14)'.",
        "39",
        "14",
    ),
    "44-ref": (
        "After eq. (44): 'at zero friction $p = 1$, and (44) coincides with (26)'.",
        "44",
        "26",
    ),
    "40-ref": (
        "Before eq. (40): 'simplify the radicand in the right-hand side of (32)'.",
        "32",
        "radicand",
    ),
    "15-n3": (
        "The paper's section 3.2: for the left edge of the third interval "
        "'we get the same equations (10)-(11) "
        "and the same equation (15) ... this holds for all odd-order intervals', solved near "
        "$T = nT_{av}/2$.",
        "15",
        "lower edge, odd n",
    ),
}
