"""Section 1: the physics, the model, what the paper did and what this report adds."""

from __future__ import annotations

from ..i18n import say
from ..latex import Latex, raw
from . import Context, Part

TITLE = "Introduction"
LABEL = "sec:introduction"
#: nothing expensive here: built afresh every time
CACHED = False


def t(en: str, ru: str) -> Latex:
    return raw(say(en, ru))


def build(ctx: Context) -> Part:
    paras = [
        t(
            r"A child on a swing pumps it by standing up as the swing passes through the lowest "
            r"point and squatting at the extreme positions: the effective length of the pendulum "
            r"is modulated at twice its natural frequency, and the oscillation grows. This is "
            r"\emph{parametric resonance}. E.\,I.~Butikov's paper~\cite{butikov2}, the second "
            r"part of a study that begins in~\cite{butikov1}, treats the simplest model in which "
            r"everything can be solved exactly: a rigid pendulum whose length jumps between "
            r"$l_0(1+m)$ and $l_0(1-m)$ as a square wave of period $T$, with $m$ the depth of "
            r"modulation and, optionally, viscous friction measured by the quality factor $Q$.",
            r"Ребёнок раскачивает качели, выпрямляясь, когда они проходят нижнюю точку, и "
            r"приседая в крайних положениях: приведённая длина маятника модулируется с "
            r"удвоенной собственной частотой, и колебания нарастают. Это \emph{параметрический "
            r"резонанс}. Статья Е.\,И.~Бутикова~\cite{butikov2} --- вторая часть работы, "
            r"начатой в~\cite{butikov1}, --- рассматривает простейшую модель, допускающую "
            r"точное решение: жёсткий маятник, длина которого скачком меняется между $l_0(1+m)$ "
            r"и $l_0(1-m)$ по прямоугольному закону с периодом $T$; $m$ --- глубина модуляции, "
            r"трение (если есть) задаётся добротностью $Q$.",
        ),
        t(
            r"Between the jumps the pendulum oscillates freely; at each jump the angle is "
            r"continuous and the angular momentum is conserved. Near $T = nT_{av}/2$ "
            r"($n = 1, 2, 3, \dots$; $T_{av} = 2\pi/\omega_{av}$ is the period of the mean "
            r"$\omega_{av}$ of the natural frequencies $\omega_1$, $\omega_2$ at the two "
            r"lengths) lies the $n$-th \emph{interval of parametric instability}, "
            r"a range $T_-(m) < T < T_+(m)$ of modulation periods in which the lower equilibrium "
            r"is unstable. On its edges the motion is a stationary oscillation. The paper "
            r"stitches free-oscillation segments across the jumps, asks when the resulting "
            r"homogeneous system has a non-trivial solution, and so finds the edges of the first "
            r"three intervals as series in $m$ (its eqs.~18, 19, 27), their closings at some "
            r"depths (its Section~5), and the thresholds of excitation with friction (its "
            r"Section~6 and appendix, eqs.~28--45), illustrated by its Figs.~2 and~8 and by "
            r"the author's simulation program~\cite{butikov-applet}.",
            r"Между скачками маятник совершает свободные колебания; при скачке угол непрерывен, "
            r"а момент импульса сохраняется. Вблизи $T = nT_{av}/2$ ($n = 1, 2, 3, \dots$; "
            r"$T_{av} = 2\pi/\omega_{av}$ --- период средней $\omega_{av}$ собственных частот "
            r"$\omega_1$, $\omega_2$ при двух длинах) "
            r"лежит $n$-й \emph{интервал параметрической неустойчивости} $T_-(m) < T < T_+(m)$, "
            r"в котором нижнее положение равновесия неустойчиво; на его границах происходят "
            r"стационарные колебания. Статья сшивает отрезки свободных колебаний через скачки, "
            r"ищет условие нетривиального решения получающейся однородной системы и так находит "
            r"границы первых трёх интервалов в виде рядов по $m$ (ур.~18, 19, 27), их смыкания "
            r"при некоторых глубинах модуляции (разд.~5) и пороги возбуждения с трением "
            r"(разд.~6 и приложение, ур.~28--45), иллюстрируя их рис.~2 и~8 и "
            r"программой моделирования автора~\cite{butikov-applet}.",
        ),
        t(
            r"This report is produced by \texttt{paramres}, a program that derives every one of "
            r"those results from the model alone with the computer algebra system "
            r"SymPy~\cite{sympy}, compares each with the formula printed in the paper, and solves "
            r"the exact equations numerically with proven error bounds (ball arithmetic, "
            r"Arb/FLINT~\cite{arb}, and mpmath~\cite{mpmath}). It adds what the paper could not: "
            r"the edges of every interval to any order in $m$, every closing of every interval "
            r"with a proof that there are no others, the thresholds for every order in two "
            r"models of friction, certified high-precision tables, independent checks by the "
            r"Floquet (monodromy) route and by simulation in the time domain, and a comparison of "
            r"the speed and accuracy of the methods. Related problems --- the linear oscillator "
            r"with square-wave modulation~\cite{butikov-square}, the Meissner "
            r"equation~\cite{meissner} and the Mathieu equation~\cite{butikov-mathieu} --- share "
            r"the structure of the derivation.",
            r"Этот отчёт создан программой \texttt{paramres}, которая выводит каждый из этих "
            r"результатов только из модели с помощью системы компьютерной алгебры "
            r"SymPy~\cite{sympy}, сравнивает его с напечатанной в статье формулой и решает "
            r"точные уравнения численно с доказанными оценками погрешности (шаровая арифметика "
            r"Arb/FLINT~\cite{arb} и mpmath~\cite{mpmath}). Она добавляет то, чего нет в "
            r"статье: границы любого интервала в любом порядке по $m$, все смыкания всех "
            r"интервалов с доказательством, что других нет, пороги для любого порядка в двух "
            r"моделях трения, гарантированные таблицы высокой точности, независимые проверки "
            r"через матрицу монодромии (теория Флоке) и прямым моделированием, а также сравнение "
            r"скорости и точности методов. Родственные задачи --- линейный осциллятор с "
            r"прямоугольной модуляцией~\cite{butikov-square}, уравнение Мейснера~\cite{meissner} "
            r"и уравнение Матье~\cite{butikov-mathieu} --- имеют ту же структуру вывода.",
        ),
        t(
            r"Section~\ref{sec:summary} states the findings. Section~\ref{sec:model} fixes the "
            r"model and the notation; the sections after it give the derivations, the paper's "
            r"results one by one, the series, the closings, the diagrams, the accuracy of the "
            r"methods and the time domain; Section~\ref{sec:certification} explains what "
            r"``proven'' means here. Equation numbers without a section prefix, such as (13), "
            r"are the paper's; a prime, as in (15$'$), marks the paper's equation for the other "
            r"edge or a second appearance of the same number, and ``i.c.'', as in (15, i.c.), the "
            r"stationary initial condition the paper states after that equation; numbers such as "
            r"(2.3) are this report's. Figure numbers of the paper are always written ``the "
            r"paper's Fig.~2''.",
            r"В разделе~\ref{sec:summary} собраны результаты. Раздел~\ref{sec:model} задаёт "
            r"модель и обозначения; следующие разделы содержат вывод, разбор результатов статьи "
            r"по одному, ряды, смыкания, диаграммы, точность методов и моделирование; "
            r"в разделе~\ref{sec:certification} объяснено, что здесь значит <<доказано>>. "
            r"Номера уравнений без номера раздела, например (13), --- номера статьи; штрих, "
            r"как в (15$'$), отмечает уравнение статьи для другой границы или повторное "
            r"появление того же номера, а <<i.c.>>, как в (15, i.c.), --- стационарное начальное "
            r"условие, которое статья приводит после этого уравнения; номера вида (2.3) --- номера "
            r"этого отчёта. Номера "
            r"рисунков статьи всегда указаны как <<рис.~2 статьи>>.",
        ),
    ]
    return Part(Latex("\n\n".join(p.raw for p in paras)))
