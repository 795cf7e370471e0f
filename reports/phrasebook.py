"""The engine's short explanations (the reasons of derivation steps, the verdicts of the
catalogue), written in the engine's plain-text notation, as typeset prose in each language.

The engine states each step in plain text so that its command-line output stays readable; the
report sets the same statement with real mathematics.  ``TEXTS`` maps the engine's exact string to
``(English, Russian)`` in the report's mixed format (prose with formulas between ``$`` signs);
``PATTERNS`` does the same for statements that carry an order or a name.  A statement without an
entry goes through :func:`reports.latex.prose` unchanged.
"""

from __future__ import annotations

import re

from .i18n_ru import edge_shape

__all__ = ["TEXTS", "PATTERNS", "lookup", "SAME_EQUATION"]

#: the catalogue's verdict for a printed result that is the derived one (stated once in the report)
SAME_EQUATION = (
    "Printed and derived forms are the same equation; decided symbolically (exact rational "
    "identity after expanding the abbreviations)."
)

TEXTS: dict[str, tuple[str, str]] = {
    # the catalogue's titles that name a formula
    "Angle continuity at t = 0": (
        "Angle continuity at $t = 0$",
        "Непрерывность угла при $t = 0$",
    ),
    "Momentum jump at t = 0": (
        "Momentum jump at $t = 0$",
        "Скачок момента импульса при $t = 0$",
    ),
    "Determinant of (10)-(11)": (
        "Determinant of (10)--(11)",
        "Определитель (10)--(11)",
    ),
    "q as a function of m": (
        "$q$ as a function of $m$",
        "$q$ как функция $m$",
    ),
    "Fixed-point form for Delta T (first interval)": (
        "Fixed-point form for $\\Delta T$ (first interval)",
        "Форма для итераций по $\\Delta T$ (первый интервал)",
    ),
    "Angle continuity at t = 0 (second interval)": (
        "Angle continuity at $t = 0$ (second interval)",
        "Непрерывность угла при $t = 0$ (второй интервал)",
    ),
    "Momentum jump at t = 0 (second interval)": (
        "Momentum jump at $t = 0$ (second interval)",
        "Скачок момента импульса при $t = 0$ (второй интервал)",
    ),
    "Determinant of (22)-(23)": (
        "Determinant of (22)--(23)",
        "Определитель (22)--(23)",
    ),
    "Fixed-point form for Delta T (second interval)": (
        "Fixed-point form for $\\Delta T$ (second interval)",
        "Форма для итераций по $\\Delta T$ (второй интервал)",
    ),
    "Homogeneous system for A, B": (
        "Homogeneous system for $A$, $B$",
        "Однородная система для $A$, $B$",
    ),
    "product of the half-period maps and the jumps.": (
        "The product of the half-period maps and the jumps.",
        "Произведение отображений за полупериоды и скачков.",
    ),
    "entries of the half-period maps.": (
        "From the entries of the half-period maps.",
        "Из элементов отображений за полупериоды.",
    ),
    "cos a cos b and sin a sin b as half-sums.": (
        r"Products $\cos a\cos b$ and $\sin a\sin b$ written as half-sums.",
        r"Произведения $\cos a\cos b$ и $\sin a\sin b$ записаны как полусуммы.",
    ),
    "steps 2-4; r^2 = (K-2)/(K+2), 1 - r^2 = 4/(K+2).": (
        r"Steps 2--4, with $r^2 = \frac{K-2}{K+2}$ and $1 - r^2 = \frac{4}{K+2}$.",
        r"Шаги 2--4, где $r^2 = \frac{K-2}{K+2}$ и $1 - r^2 = \frac{4}{K+2}$.",
    ),
    "continuity of the angle at t = 0.": (
        "Continuity of the angle at $t = 0$.",
        "Непрерывность угла при $t = 0$.",
    ),
    "angular-momentum jump at t = 0 (eq. 4).": (
        "The jump of the angular velocity at $t = 0$ that conserves the angular momentum (eq. 4).",
        "Скачок угловой скорости при $t = 0$, сохраняющий момент импульса (ур. 4).",
    ),
    "determinant of the two conditions = 0.": (
        "The determinant of the two conditions vanishes.",
        "Определитель двух условий равен нулю.",
    ),
    "product to sum; divide by (1-m)^2 omega_2; "
    "q = (1+m)^2 omega_1 / ((1-m)^2 omega_2) (eq. 14).": (
        r"Products written as sums, divided by $(1-m)^2\omega_2$, with "
        r"$q = \frac{(1+m)^2\omega_1}{(1-m)^2\omega_2}$ (eq. 14).",
        r"Произведения записаны как суммы, деление на $(1-m)^2\omega_2$, где "
        r"$q = \frac{(1+m)^2\omega_1}{(1-m)^2\omega_2}$ (ур. 14).",
    ),
    "omega_av = (omega_1 + omega_2)/2, T_i = 2 pi / omega_i.": (
        r"With $\omega_{av} = (\omega_1 + \omega_2)/2$ and $T_i = 2\pi/\omega_i$.",
        r"Где $\omega_{av} = (\omega_1 + \omega_2)/2$ и $T_i = 2\pi/\omega_i$.",
    ),
    "omega_1 T/2 + omega_2 T/2 = n pi.": (
        r"Exact tuning: $\omega_1 T/2 + \omega_2 T/2 = n\pi$.",
        r"Точная настройка: $\omega_1 T/2 + \omega_2 T/2 = n\pi$.",
    ),
    "q = (1+m)^2 omega_1 / ((1-m)^2 omega_2) with omega_i = omega_0/sqrt(1 -+ m).": (
        r"$q = \frac{(1+m)^2\omega_1}{(1-m)^2\omega_2}$ with $\omega_{1,2} = "
        r"\omega_0/\sqrt{1 \pm m}$.",
        r"$q = \frac{(1+m)^2\omega_1}{(1-m)^2\omega_2}$, где $\omega_{1,2} = "
        r"\omega_0/\sqrt{1 \pm m}$.",
    ),
    "anti-periodicity of the angle across t = T/2.": (
        "Anti-periodicity of the angle across $t = T/2$.",
        "Антипериодичность угла при переходе через $t = T/2$.",
    ),
    "anti-periodicity of the angular momentum across t = T/2.": (
        "Anti-periodicity of the angular momentum across $t = T/2$.",
        "Антипериодичность момента импульса при переходе через $t = T/2$.",
    ),
    "conditions at t = 0 solved (B_2 = B_1 = B, A_2 = q A); multiplied by exp(-gamma T/2).": (
        r"The conditions at $t = 0$ solved ($B_2 = B_1 = B$, $A_2 = qA$), multiplied by "
        r"$e^{-\gamma T/2}$.",
        r"Условия при $t = 0$ решены ($B_2 = B_1 = B$, $A_2 = qA$) и умножены на "
        r"$e^{-\gamma T/2}$.",
    ),
    "conditions at t = 0 solved (B_2 = B_1 = B, A_2 = q A); multiplied by exp(-gamma T/2); "
    "divided by (1-m)^2 omega_2.": (
        r"The conditions at $t = 0$ solved ($B_2 = B_1 = B$, $A_2 = qA$), multiplied by "
        r"$e^{-\gamma T/2}$ and divided by $(1-m)^2\omega_2$.",
        r"Условия при $t = 0$ решены ($B_2 = B_1 = B$, $A_2 = qA$), умножены на "
        r"$e^{-\gamma T/2}$ и разделены на $(1-m)^2\omega_2$.",
    ),
    "determinant of the 2 x 2 system divided by -p, using C_i^2 + S_i^2 = 1.": (
        r"The determinant of the $2\times 2$ system divided by $-p$, using $C_i^2 + S_i^2 = 1$.",
        r"Определитель системы $2\times 2$, делённый на $-p$, с учётом $C_i^2 + S_i^2 = 1$.",
    ),
    "product to sum.": ("Products written as sums.", "Произведения записаны как суммы."),
    "cos(a) = 2 cos^2(a/2) - 1 in (34); one sign per edge (checked squared).": (
        r"$\cos a = 2\cos^2(a/2) - 1$ in (34); one sign per edge (checked squared).",
        r"$\cos a = 2\cos^2(a/2) - 1$ в (34); по знаку на каждую границу (проверено в квадрате).",
    ),
    "cos(a) = 1 - 2 sin^2(a/2) in the determinant above; one sign per edge (checked squared).": (
        r"$\cos a = 1 - 2\sin^2(a/2)$ in the determinant above; one sign per edge (checked "
        r"squared).",
        r"$\cos a = 1 - 2\sin^2(a/2)$ в определителе выше; по знаку на каждую границу "
        r"(проверено в квадрате).",
    ),
    "radicand of the previous step = 0 (the two signs give the same T).": (
        "The radicand of the previous step vanishes (the two signs give the same $T$).",
        "Подкоренное выражение предыдущего шага равно нулю (оба знака дают одно $T$).",
    ),
    "product of the half-period maps and the jumps": (
        "The product of the half-period maps and the jumps",
        "Произведение отображений за полупериоды и скачков",
    ),
    SAME_EQUATION: (
        "The printed and the derived forms are the same equation.",
        "Напечатанная и выведенная формы --- одно и то же уравнение.",
    ),
    "Printed and derived forms are the same equation; decided symbolically (exact rational "
    "identity after expanding the abbreviations). Checked squared (one sign per edge).": (
        "The printed and the derived forms are the same equation, compared squared (one sign "
        "per edge).",
        "Напечатанная и выведенная формы --- одно и то же уравнение (сравнение в квадрате, по "
        "знаку на каждую границу).",
    ),
    "Printed and derived forms are the same equation up to the non-vanishing factor $-1$; decided "
    "symbolically (exact rational identity after expanding the abbreviations).": (
        "The printed and the derived forms are the same equation up to the factor $-1$.",
        "Напечатанная и выведенная формы совпадают с точностью до множителя $-1$.",
    ),
    "Notation, the same as the engine's abbreviations (half-period phases).": (
        "Notation: the same as the engine's abbreviations (phases over a half-period).",
        "Обозначения: те же, что сокращения программы (фазы за полупериод).",
    ),
    "The anti-periodicity conditions the engine builds for odd orders (angle, and angular "
    "momentum across t = T/2); decided symbolically.": (
        "The anti-periodicity conditions the engine builds for odd orders (the angle, and the "
        "angular momentum across $t = T/2$).",
        "Условия антипериодичности, которые программа строит для нечётных порядков (угол и "
        "момент импульса при переходе через $t = T/2$).",
    ),
    "Odd orders: the undamped normal form is the product of the two edge factors.": (
        "Odd orders: without friction the normal form is the product of the two edge factors.",
        "Нечётные порядки: без трения нормальная форма --- произведение двух множителей границ.",
    ),
    "Even orders: the undamped normal form is the product of the two edge factors.": (
        "Even orders: without friction the normal form is the product of the two edge factors.",
        "Чётные порядки: без трения нормальная форма --- произведение двух множителей границ.",
    ),
    "Odd orders: F_+ + F_- = 2 f(x) and F_- - F_+ = 2 r f(y), so both vanish iff f(x) = f(y) = 0 "
    "(r > 0).": (
        r"Odd orders: $F_+ + F_- = 2f(x)$ and $F_- - F_+ = 2rf(y)$, so both vanish if and only "
        r"if $f(x) = f(y) = 0$ (as $r > 0$).",
        r"Нечётные порядки: $F_+ + F_- = 2f(x)$ и $F_- - F_+ = 2rf(y)$, поэтому оба обращаются в "
        r"нуль тогда и только тогда, когда $f(x) = f(y) = 0$ (так как $r > 0$).",
    ),
    "Even orders: F_+ + F_- = 2 f(x) and F_- - F_+ = 2 r f(y), so both vanish iff f(x) = f(y) = 0 "
    "(r > 0).": (
        r"Even orders: $F_+ + F_- = 2f(x)$ and $F_- - F_+ = 2rf(y)$, so both vanish if and only "
        r"if $f(x) = f(y) = 0$ (as $r > 0$).",
        r"Чётные порядки: $F_+ + F_- = 2f(x)$ и $F_- - F_+ = 2rf(y)$, поэтому оба обращаются в "
        r"нуль тогда и только тогда, когда $f(x) = f(y) = 0$ (так как $r > 0$).",
    ),
    "Odd orders: f(x) = f(y) = 0 makes a1 = x - y and a2 = x + y integer multiples of pi with "
    "a + b odd, n = a + b.": (
        r"Odd orders: $f(x) = f(y) = 0$ makes $x - y$ and $x + y$ integer multiples $a\pi$, "
        r"$b\pi$ of $\pi$ with $a + b = n$ odd.",
        r"Нечётные порядки: при $f(x) = f(y) = 0$ величины $x - y$ и $x + y$ --- целые кратные "
        r"$a\pi$, $b\pi$ числа $\pi$, причём $a + b = n$ нечётно.",
    ),
    "Even orders: f(x) = f(y) = 0 makes a1 = x - y and a2 = x + y integer multiples of pi with "
    "a + b even, n = a + b.": (
        r"Even orders: $f(x) = f(y) = 0$ makes $x - y$ and $x + y$ integer multiples $a\pi$, "
        r"$b\pi$ of $\pi$ with $a + b = n$ even.",
        r"Чётные порядки: при $f(x) = f(y) = 0$ величины $x - y$ и $x + y$ --- целые кратные "
        r"$a\pi$, $b\pi$ числа $\pi$, причём $a + b = n$ чётно.",
    ),
    "Omega2/omega1 = sqrt((1+m)/(1-m)) = b/a gives m = (b^2 - a^2)/(b^2 + a^2).": (
        r"$\omega_2/\omega_1 = \sqrt{(1+m)/(1-m)} = b/a$ gives $m = (b^2 - a^2)/(b^2 + a^2)$.",
        r"Из $\omega_2/\omega_1 = \sqrt{(1+m)/(1-m)} = b/a$ следует "
        r"$m = (b^2 - a^2)/(b^2 + a^2)$.",
    ),
    "T = a T1 = a sqrt(1+m) T0 = a b sqrt(2/(a^2+b^2)) T0 (and = b T2).": (
        r"$T = aT_1 = a\sqrt{1+m}\,T_0 = ab\sqrt{2/(a^2+b^2)}\,T_0$ (and $= bT_2$).",
        r"$T = aT_1 = a\sqrt{1+m}\,T_0 = ab\sqrt{2/(a^2+b^2)}\,T_0$ (и $= bT_2$).",
    ),
    "The same T is b T2 = b sqrt(1-m) T0.": (
        r"The same $T$ is $bT_2 = b\sqrt{1-m}\,T_0$.",
        r"То же $T$ равно $bT_2 = b\sqrt{1-m}\,T_0$.",
    ),
    "At omega1 T/2 = a pi, omega2 T/2 = b pi the monodromy is (-1)^(a+b) I = (-1)^n I.": (
        r"At $\omega_1 T/2 = a\pi$, $\omega_2 T/2 = b\pi$ the monodromy matrix is "
        r"$(-1)^{a+b} I = (-1)^n I$.",
        r"При $\omega_1 T/2 = a\pi$, $\omega_2 T/2 = b\pi$ матрица монодромии равна "
        r"$(-1)^{a+b} I = (-1)^n I$.",
    ),
}

PATTERNS: list[tuple[re.Pattern, object]] = [
    (
        re.compile(r"T = (\d+) T_av/2 \+ Delta T with omega_av T_av = 2 pi; divide by -q - 1\."),
        lambda m: (
            rf"With $T = {_n_half(m.group(1))} T_{{av}} + \Delta T$ and $\omega_{{av}} T_{{av}} "
            rf"= 2\pi$, divided by $-(q + 1)$.",
            rf"При $T = {_n_half(m.group(1))} T_{{av}} + \Delta T$ и $\omega_{{av}} T_{{av}} "
            rf"= 2\pi$, деление на $-(q + 1)$.",
        ),
    ),
    (
        re.compile(
            r"T = (\d+) T_av/2 \+ Delta T; f\(omega_av T/2\) = (-?\d+) sin\(omega_av Delta T/2\); "
            r"p \+ 1/p - 2 = \(p-1\)\^2/p \(checked squared\)\."
        ),
        lambda m: (
            rf"With $T = {_n_half(m.group(1))} T_{{av}} + \Delta T$, "
            rf"$f(\omega_{{av}} T/2) = {_sign(m.group(2))}\sin(\omega_{{av}}\Delta T/2)$ and "
            r"$p + 1/p - 2 = (p-1)^2/p$ (checked squared).",
            rf"При $T = {_n_half(m.group(1))} T_{{av}} + \Delta T$ "
            rf"$f(\omega_{{av}} T/2) = {_sign(m.group(2))}\sin(\omega_{{av}}\Delta T/2)$ и "
            r"$p + 1/p - 2 = (p-1)^2/p$ (проверено в квадрате).",
        ),
    ),
    (
        re.compile(r"edge shape ([a-z]+-[a-z]+-[a-z]+): its first segment at t = 0\."),
        lambda m: (
            rf"Edge shape {m.group(1)}: its first segment at $t = 0$.",
            rf"Форма границы {edge_shape(m.group(1))}: её первый отрезок при $t = 0$.",
        ),
    ),
    (
        re.compile(
            r"The printed segment is the engine's edge shape ([a-z-]+) and its printed velocity "
            r"is the time derivative of the printed angle; decided symbolically\."
        ),
        lambda m: (
            rf"The printed segment is the engine's edge shape {m.group(1)}, and its "
            r"printed velocity is the time derivative of the printed angle.",
            rf"Напечатанный отрезок совпадает с формой границы {edge_shape(m.group(1))} в "
            r"программе, а напечатанная скорость --- производная напечатанного угла по времени.",
        ),
    ),
]


def _n_half(n: str) -> str:
    k = int(n)
    return "\\tfrac{1}{2}" if k == 1 else ("" if k == 2 else f"\\tfrac{{{k}}}{{2}}")


def _sign(s: str) -> str:
    return {"1": "", "-1": "-"}.get(s, s + r"\,")


def lookup(s: str, lang: str) -> str | None:
    """The typeset version of the engine's statement ``s`` in ``lang``, or ``None``."""
    k = 0 if lang == "en" else 1
    hit = TEXTS.get(s)
    if hit is not None:
        return hit[k]
    for pattern, make in PATTERNS:
        m = pattern.fullmatch(s)
        if m:
            return make(m)[k]
    return None
