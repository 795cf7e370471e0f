"""How the numbers are certified: ball arithmetic, interval Newton, and what "proven" covers."""

from __future__ import annotations

from ..i18n import say
from ..latex import Latex, itemize, raw
from . import Context, Part

TITLE = "How the numbers are certified"
LABEL = "sec:certification"
CACHED = False
#: no page break before it: the last figure of the time domain may share its page (a break
#: here left that figure alone on a float page, mostly blank)
NEW_PAGE = False


def t(en: str, ru: str) -> Latex:
    return raw(say(en, ru))


def build(ctx: Context) -> Part:
    blocks = [
        t(
            r"\emph{Ball arithmetic.} A real number is carried as a ball: a midpoint and a "
            r"radius, with the guarantee that the exact value lies inside. Every operation of "
            r"Arb~\cite{arb} (through python-flint) returns a ball that contains every possible "
            r"result of the operation on the points of its argument balls, rounding included; "
            r"so a ball computed for $\cos(\omega_1 T/2)$ at an exact rational depth $m$ "
            r"contains the true value, whatever the working precision.",
            r"\emph{Шаровая арифметика.} Вещественное число представляется шаром: центр и "
            r"радиус с гарантией, что точное значение лежит внутри. Каждая операция "
            r"Arb~\cite{arb} (через python-flint) возвращает шар, содержащий все возможные "
            r"результаты операции над точками шаров-аргументов, с учётом округлений; поэтому "
            r"шар, вычисленный для $\cos(\omega_1 T/2)$ при точной рациональной глубине "
            r"модуляции $m$, содержит истинное значение при любой рабочей точности.",
        ),
        t(
            r"\emph{Interval Newton.} Each edge is the root of one equation $f(\theta)=0$ in "
            r"$\theta = \omega_{av}\Delta T/2$, the offset from exact tuning. If $X$ is an "
            r"interval, $x\in X$, and the interval Newton image $x - f(x)/f'(X)$ (with $f'(X)$ a "
            r"ball enclosing the derivative on all of $X$, not containing $0$) lies inside $X$, "
            r"then $X$ contains exactly one root, and that image is a narrower enclosure of it. "
            r"The engine starts from a floating-point root in a window where the theorem of "
            r"Section~\ref{sec:stitching} guarantees a single simple root, refines it by "
            r"Newton's method on ball midpoints, doubling the precision at each step, and then "
            r"applies the interval Newton test once; the radius of the ball it returns is "
            r"checked against the accuracy asked for. With friction, the zeros of the "
            r"instability indicator are proven the same way, and its sign between and around "
            r"them by bisection into sub-balls.",
            r"\emph{Интервальный метод Ньютона.} Каждая граница --- корень одного уравнения "
            r"$f(\theta)=0$ относительно $\theta = \omega_{av}\Delta T/2$, отклонения от точной "
            r"настройки. Если $X$ --- интервал, $x\in X$, и образ Ньютона $x - f(x)/f'(X)$ (где "
            r"$f'(X)$ --- шар, содержащий производную на всём $X$ и не содержащий $0$) лежит "
            r"внутри $X$, то в $X$ ровно один корень, а образ --- более узкое его включение. "
            r"Программа начинает с корня в плавающей точке в окне, где теорема "
            r"раздела~\ref{sec:stitching} гарантирует единственный простой корень, уточняет его "
            r"методом Ньютона по центрам шаров, удваивая точность на каждом шаге, и затем один "
            r"раз применяет интервальный тест Ньютона; радиус полученного шара сравнивается с "
            r"требуемой точностью. С трением так же доказываются нули индикатора "
            r"неустойчивости, а его знак между ними и вне их --- делением на подшары.",
        ),
        t(
            r"\emph{What ``proven'' means here.} A number printed as certified carries only "
            r"digits that its enclosure supports: the exact root of the equation the engine "
            r"derived, for the exact rational inputs ($m$, $Q$) given, lies within half a unit "
            r"of the last printed digit (plus the rounding of the print itself). This rests on: "
            r"the symbolic derivation of "
            r"that equation from the model (SymPy~\cite{sympy}, each step checked as described "
            r"with the derivations, and cross-checked at random points against the independent "
            r"Floquet route); the correctness of Arb's ball arithmetic; and the correctness of "
            r"the engine's own code, which the tests exercise but which is not formally "
            r"verified.",
            r"\emph{Что здесь значит <<доказано>>.} Число, напечатанное как гарантированное, "
            r"содержит лишь разряды, подтверждённые его включением: точный корень уравнения, "
            r"выведенного программой, при заданных точных рациональных входных данных ($m$, $Q$) "
            r"отличается от него не более чем на половину единицы последнего разряда (плюс "
            r"округление при печати). Это опирается на: "
            r"символьный вывод уравнения из модели (SymPy~\cite{sympy}; каждый шаг проверен так, "
            r"как сказано при выводе, и сверен в случайных точках с независимым путём через "
            r"матрицу монодромии); корректность шаровой арифметики Arb; корректность кода самой "
            r"программы, которую проверяют тесты, но которая формально не верифицирована.",
        ),
        t(r"\emph{What it does not cover:}", r"\emph{Что не покрывается:}"),
        itemize(
            [
                t(
                    r"the model itself: a square-wave jump of the length, a rigid light rod, "
                    r"linear viscous friction, and the linearisation $\sin\varphi\to\varphi$ "
                    r"(the nonlinear pendulum is only simulated);",
                    r"сама модель: скачкообразное изменение длины, жёсткий невесомый стержень, "
                    r"линейное вязкое трение и линеаризация $\sin\varphi\to\varphi$ (нелинейный "
                    r"маятник только моделируется численно);",
                ),
                t(
                    r"identities that SymPy could not reduce to zero, which are checked at random "
                    r"points with 40 digits and say so where they appear;",
                    r"тождества, которые SymPy не свёл к нулю: они проверены в случайных точках с "
                    r"40 знаками, и это указано на месте;",
                ),
                t(
                    r"floating-point columns, series and the paper's own iteration: their errors "
                    r"are measured against the certified values (Section~\ref{sec:accuracy}), "
                    r"not proven;",
                    r"столбцы в плавающей точке, ряды и итерации самой статьи: их погрешности "
                    r"измерены по гарантированным значениям (раздел~\ref{sec:accuracy}), а не "
                    r"доказаны;",
                ),
                t(
                    r"figures, which are drawn from double-precision grids.",
                    r"рисунки, построенные по сеткам в двойной точности.",
                ),
            ]
        ),
    ]
    return Part(Latex("\n\n".join(b.raw for b in blocks)))
