"""Russian versions of the report's prose (see :mod:`reports.i18n`), in the paper's own terms:
интервал параметрической неустойчивости, глубина модуляции, добротность, период модуляции.

``PHRASES`` maps an English string, exactly as the report or the engine writes it, to its Russian
version; ``PATTERNS`` are ``(regular expression, replacement)`` pairs for strings that carry numbers
or formulas.  A string with no entry is left in English.
"""

from __future__ import annotations

import re

__all__ = ["PHRASES", "PATTERNS", "EDGE_SHAPES", "edge_shape"]

#: the engine's names of the four symmetric edge shapes (``analytic.stitching.EdgeKind``) as the
#: Russian text calls them: the functions on the bob-down and the bob-up half, and the orders
EDGE_SHAPES: dict[str, tuple[str, str]] = {
    "odd-cos-sin": ("cos--sin", "нечётные порядки"),
    "odd-sin-cos": ("sin--cos", "нечётные порядки"),
    "even-cos-cos": ("cos--cos", "чётные порядки"),
    "even-sin-sin": ("sin--sin", "чётные порядки"),
}


def edge_shape(name: str) -> str:
    """The Russian name of the edge shape ``name``: ``"odd-cos-sin"`` -> ``"cos--sin"``."""
    return EDGE_SHAPES[name][0] if name in EDGE_SHAPES else name


PHRASES: dict[str, str] = {
    # section titles
    "Introduction": "Введение",
    "Summary of results": "Сводка результатов",
    "The model and conventions": "Модель и соглашения",
    "Stitching systems, determinants and the per-edge equations": (
        "Системы сшивания, определители и уравнения границ"
    ),
    "The paper's numbered results, printed against derived": (
        "Пронумерованные результаты статьи: напечатанное и выведенное"
    ),
    "Expansions in the depth": "Разложения по глубине модуляции",
    "Closings of the intervals": "Смыкания интервалов",
    "The family of two-level oscillators": "Семейство двухуровневых осцилляторов",
    "Diagrams: the paper's Figs. 2 and 8 redrawn": "Диаграммы: рис. 2 и 8 статьи",
    "Accuracy: series, certified values and the Floquet cross-check": (
        "Точность: ряды, гарантированные значения и проверка через матрицу монодромии"
    ),
    "Speed and the time domain": "Скорость и моделирование во времени",
    "How the numbers are certified": "Как гарантируются числа",
    "Conclusions": "Заключение",
    # subsection titles
    "Units and conventions": "Единицы и соглашения",
    "Equations of motion and the jump": "Уравнения движения и скачок",
    "Abbreviations and parameters": "Сокращения и параметры",
    "The general system": "Общая система",
    "From the determinant to the normal form": "От определителя к нормальной форме",
    "Parameters of the normal form": "Параметры нормальной формы",
    "The paper's remaining reductions": "Остальные преобразования статьи",
    "Single results": "Отдельные результаты",
    "Stationary initial conditions on the edges": "Стационарные начальные условия на границах",
    "Paper model with friction, odd orders": "Модель статьи с трением, нечётные порядки",
    "Paper model with friction, even orders": "Модель статьи с трением, чётные порядки",
    "The per-edge equations for every order": "Уравнения границ для любого порядка",
    "Edges without friction, orders 1 to 6": "Границы без трения, порядки 1--6",
    "Thresholds with friction": "Пороги с трением",
    "Edges above the threshold": "Границы выше порога",
    "General order": "Произвольный порядок",
    "Speed against error": "Скорость и погрешность",
    "Time-domain pictures": "Моделирование во времени",
    # table headers and short words
    "half": "полупериод",
    "bob down": "груз опущен",
    "bob up": "груз поднят",
    "length": "длина",
    "natural period": "собственный период",
    "model": "модель",
    "orders": "порядки",
    "symbol": "обозначение",
    "definition": "определение",
    "result": "результат",
    "status": "статус",
    "eq.": "ур.",
    "agrees": "совпадает",
    "no friction": "без трения",
    "paper model": "модель статьи",
    "exact model": "точная модель",
    "paper": "модель статьи",
    "exact": "точная модель",
    "residual in the equation": "невязка в уравнении",
    "coupling of the jumps (eq. 14)": "связь скачков (ур. 14)",
    "decay per period": "затухание за период",
    "mean frequency": "средняя частота",
    "frequency difference": "разность частот",
    "mean natural period (eq. 5)": "средний собственный период (ур. 5)",
    "eq. 33": "ур. 33",
    "The paper's abbreviations as the engine defines them.": (
        "Сокращения статьи в определении программы."
    ),
    # captions
    r"The two halves of a modulation period (time in units of $T_0$, so $\omega_0 = 2\pi$).": (
        r"Два полупериода модуляции (время в единицах $T_0$, так что $\omega_0 = 2\pi$)."
    ),
    r"Intervals of parametric instability without friction (the paper's Fig.~2), orders "
    r"$n = 1,\dots,6$. Shaded: the rest state is unstable. Dots: closings, labelled with "
    r"$T_1:T_2$.": (
        r"Интервалы параметрической неустойчивости без трения (рис.~2 статьи), порядки "
        r"$n = 1,\dots,6$. Закрашено: положение равновесия неустойчиво. Точки: смыкания с "
        r"отношением $T_1:T_2$."
    ),
    r"Intervals with friction (the paper's Fig.~8): orders 1--3 for no friction and "
    r"$Q = 7, 5, 3$ (darker: stronger friction). Left: the paper's model; right: the exact "
    r"damped oscillator.": (
        r"Интервалы с трением (рис.~8 статьи): порядки 1--3 без трения и при $Q = 7, 5, 3$ "
        r"(темнее --- сильнее трение). Слева: модель статьи; справа: точный затухающий "
        r"осциллятор."
    ),
    r"Relative error of the series for the lower edge against the certified value, on log--log "
    r"axes; below $10^{-16}$ no double-precision computation could tell.": (
        r"Относительная погрешность рядов для нижней границы по сравнению с гарантированным "
        r"значением, в логарифмическом масштабе; ниже $10^{-16}$ вычисление в двойной точности "
        r"её не различит."
    ),
    r"Median CPU time per edge against the largest relative error of $T/T_0$, per method, over "
    r"all scenes and over the small depths; the methods that no other beats in both are joined "
    r"(the Pareto front) and labelled.": (
        r"Медианное процессорное время на границу и наибольшая относительная погрешность "
        r"$T/T_0$ для каждого метода, по всем сценам и по малым глубинам модуляции; методы, "
        r"которые никто не превосходит по обоим показателям, соединены (фронт Парето) и "
        r"подписаны."
    ),
    "Speed against error of every method (from the benchmark).": (
        "Скорость и погрешность каждого метода (по замерам)."
    ),
    r"Growth inside the first interval: the linear model grows without bound, the real "
    r"pendulum's period lengthens with the amplitude, which detunes it (beats); with friction "
    r"the beats die out to a steady swing.": (
        r"Рост внутри первого интервала: в линейной модели колебания растут неограниченно, у "
        r"реального маятника период растёт с амплитудой, что выводит его из резонанса (биения); "
        r"с трением биения затухают и устанавливаются колебания постоянного размаха."
    ),
    # paragraphs of the model section
    "Two damping models are carried through everything: paper, the appendix's approximation "
    "(used by the paper's eqs. 32–45 and its Fig. 8), and exact, the true damped oscillator "
    "with frequency $\\Omega_i = \\sqrt{\\omega_i^2 - \\gamma^2}$ and its over- and critically "
    "damped "
    "forms. The gap between them is one of the results.": (
        r"Всюду рассматриваются две модели трения: модель статьи (приближение приложения, "
        r"использованное в ур. 32--45 и на рис. 8) и точная --- настоящий затухающий осциллятор "
        r"с частотой $\Omega_i = \sqrt{\omega_i^2 - \gamma^2}$, включая апериодический и "
        r"критический режимы. Различие между ними --- один из результатов."
    ),
    "Time is measured in units of the natural period": (
        "Время измеряется в единицах собственного периода"
    ),
    "(so": "(так что",
    "), the modulation period as": "), период модуляции --- как",
    ", the depth as": ", глубина модуляции --- как",
    ", friction by the quality factor": ", трение --- добротностью",
    "; no friction is": "; отсутствие трения --- это",
    "). The resonance of order": "). Резонанс порядка",
    "lies near": "лежит вблизи",
    "; on the edges of its interval the motion is anti-periodic over": (
        "; на границах его интервала движение антипериодично с периодом"
    ),
    "(Floquet multiplier": "(мультипликатор Флоке",
    ") for odd": ") для нечётных",
    "and periodic (": "и периодично (",
    ") for even": ") для чётных",
    ". The monodromy matrix is taken from": ". Матрица монодромии берётся от момента",
    ", the start of the bob-down half, over one period.": (
        ", начала полупериода с опущенным грузом, за один период."
    ),
    "Equation numbers without a section prefix, such as (13), are the paper's; numbers such as "
    "(2.3) are this report's.": (
        "Номера уравнений без номера раздела, например (13), --- номера статьи; номера вида "
        "(2.3) --- номера этого отчёта."
    ),
    "Between the jumps the linearised equation of motion of half": (
        "Между скачками линеаризованное уравнение движения на полупериоде"
    ),
    "is (eqs. 2--3 with": "имеет вид (ур. 2--3 при",
    "), as the engine's residual operator states it:": "), как его записывает программа:",
    "At each jump the angle is continuous and the angular momentum": (
        "При каждом скачке угол непрерывен, а момент импульса"
    ),
    "with": "при",
    "is conserved (eq. 4): the angular velocity is multiplied by": (
        "сохраняется (ур. 4): угловая скорость умножается на"
    ),
    "when the bob moves up and by the inverse when it moves down.": (
        "при подъёме груза и на обратную величину при его опускании."
    ),
    # stitching
    "Every step below is checked by the engine. Unless its note says otherwise, the check is "
    "symbolic: the difference of the two sides reduces to zero exactly (after the trigonometric "
    "functions are written as exponentials, an identity of rational functions). Where sympy "
    "cannot reduce it, the note says so and gives the numeric check used instead: random points "
    "at 40 digits and the largest relative residual.": (
        "Каждый шаг ниже проверен программой. Если в примечании не сказано иное, проверка "
        "символьная: разность двух частей в точности сводится к нулю (после записи "
        "тригонометрических функций через экспоненты --- тождество рациональных функций). Где "
        "sympy не справляется, это указано вместе с численной проверкой: случайные точки с 40 "
        "знаками и наибольшая относительная невязка."
    ),
    "Both halves symmetric about their midpoints: a cos on the bob-down half, a sin on the bob-up "
    "half (odd orders; the paper's lower edge of the first interval):": (
        "Оба полупериода симметричны относительно своих середин: cos на полупериоде с опущенным "
        "грузом, sin --- с поднятым (нечётные порядки; нижняя граница первого интервала в статье):"
    ),
    "Both halves symmetric about their midpoints: a sin on the bob-down half, a cos on the bob-up "
    "half (odd orders; the paper's upper edge of the first interval):": (
        "Оба полупериода симметричны относительно своих середин: sin на полупериоде с опущенным "
        "грузом, cos --- с поднятым (нечётные порядки; верхняя граница первого интервала в "
        "статье):"
    ),
    "Both halves symmetric about their midpoints: a cos on the bob-down half, a cos on the bob-up "
    "half (even orders; the paper's edge of the second interval):": (
        "Оба полупериода симметричны относительно своих середин: cos на обоих полупериодах "
        "(чётные порядки; граница второго интервала в статье):"
    ),
    "Both halves symmetric about their midpoints: a sin on the bob-down half, a sin on the bob-up "
    "half (even orders; the other edge of even intervals, which the paper does not write):": (
        "Оба полупериода симметричны относительно своих середин: sin на обоих полупериодах "
        "(чётные порядки; другая граница чётных интервалов, которую статья не выписывает):"
    ),
    "The single results, the stationary initial conditions on the edges, and the paper model with "
    "friction (the paper's appendix), each step derived from the previous one:": (
        "Отдельные результаты, стационарные начальные условия на границах и модель статьи с "
        "трением (приложение статьи); каждый шаг выведен из предыдущего:"
    ),
    "The monodromy matrix has determinant": "Определитель матрицы монодромии равен",
    "in every model:": "во всех моделях:",
    "and for even orders": "и для чётных порядков",
    "A stationary oscillation on an edge is made of two free segments, ": (
        "Стационарное колебание на границе состоит из двух отрезков свободных колебаний: "
    ),
    "on": "на",
    "and": "и",
    # catalogue
    "For each numbered result the engine transcribes the printed formula (the thing being "
    "checked), derives the same result from the model, and decides whether the two agree: "
    "symbolically where sympy can (an exact identity of rational functions after the "
    "abbreviations are expanded), otherwise at random points with 40 digits. An entry whose "
    "printed and derived forms are simply the same equation, decided symbolically, says nothing "
    "more; every other entry says how it was decided. Where they differ, the entry shows the "
    "smallest sub-expressions in which they part and the correct form.": (
        "Для каждого пронумерованного результата программа переписывает напечатанную формулу "
        "(предмет проверки), выводит тот же результат из модели и решает, совпадают ли они: "
        "символьно, где это удаётся sympy (точное тождество рациональных функций после "
        "раскрытия сокращений), иначе --- в случайных точках с 40 знаками. Если напечатанная и "
        "выведенная формы --- просто одно и то же уравнение и это доказано символьно, больше "
        "ничего не сказано; в остальных случаях указано, как принято решение. Где формы "
        "расходятся, показаны наименьшие различающиеся подвыражения и верная форма."
    ),
    "Printed:": "В статье:",
    "Derived:": "Выведено:",
    # model section
    r"Free-oscillation segments of each damping model, and what is left when the segment is put "
    r"into the equation of motion (computed by the engine). The paper's segment misses the "
    r"equation by $\gamma^2\varphi$: its frequency is the undamped one and its derivative is "
    r"taken as if $e^{-\gamma t}$ were constant. The critically damped segment solves the "
    r"equation exactly at $\gamma = \omega_1$, where its residual vanishes.": (
        r"Отрезки свободных колебаний в каждой модели трения и невязка при подстановке отрезка "
        r"в уравнение движения (вычислено программой). Отрезок статьи не удовлетворяет "
        r"уравнению на $\gamma^2\varphi$: его частота --- частота без трения, а производная "
        r"взята так, будто $e^{-\gamma t}$ постоянна. Отрезок критического затухания точно "
        r"удовлетворяет уравнению при $\gamma = \omega_1$, где его невязка обращается в нуль."
    ),
    r"The factor between the determinant of the four stitching conditions and "
    r"$\det(M-\sigma I)$, found as the ratio of the two (a symbolic identity: the ratio is free of "
    r"the oscillating terms). The boundary condition \emph{is} the statement that "
    r"$\sigma = (-1)^n$ is a Floquet multiplier.": (
        r"Множитель между определителем четырёх условий сшивания и $\det(M-\sigma I)$, найденный "
        r"как их отношение (символьное тождество: отношение не содержит осциллирующих членов). "
        r"Условие границы \emph{и есть} утверждение, что $\sigma = (-1)^n$ --- мультипликатор "
        r"Флоке."
    ),
    r"The per-edge equations in $\theta$ for $n = 1,\dots,6$, with "
    r"$\beta = (\omega_2-\omega_1)/(\omega_2+\omega_1)$ and $r = (q-1)/(q+1)$.": (
        r"Уравнения границ относительно $\theta$ для $n = 1,\dots,6$, где "
        r"$\beta = (\omega_2-\omega_1)/(\omega_2+\omega_1)$ и $r = (q-1)/(q+1)$."
    ),
    r"Every closing of the intervals of order $n\le 12$: $\omega_1T/2 = a\pi$, "
    r"$\omega_2T/2 = b\pi$, $m = (b^2-a^2)/(b^2+a^2)$, $T = ab\sqrt{2/(a^2+b^2)}\,T_0$.": (
        r"Все смыкания интервалов порядка $n\le 12$: $\omega_1T/2 = a\pi$, $\omega_2T/2 = b\pi$, "
        r"$m = (b^2-a^2)/(b^2+a^2)$, $T = ab\sqrt{2/(a^2+b^2)}\,T_0$."
    ),
    r"$|\det(M-\sigma I)|$, relative to the size of $M$, at the certified edges of "
    r"Table~\ref{tab:certified}.": (
        r"$|\det(M-\sigma I)|$ относительно величины $M$ на гарантированных границах "
        r"таблицы~\ref{tab:certified}."
    ),
    r"The third interval at $Q = 7$ in detail (dark), inside the frictionless interval (light). "
    r"Bars on the left: the proven existence ranges; dashed: the paper's 48\,\% and 66\,\%.": (
        r"Третий интервал при $Q = 7$ (тёмный) внутри интервала без трения (светлый). Полосы "
        r"слева: доказанные области существования; пунктир: 48\,\% и 66\,\% из статьи."
    ),
    "Certified edges, 35 significant digits.": "Гарантированные границы, 35 значащих цифр.",
    "Without friction": "Без трения",
    "Exact tuning": "Точная настройка",
    "Average period": "Средний период",
    "Naive resonance condition": "Простейшее условие резонанса",
    # expansions
    "Each edge is the root of one per-edge factor (": (
        "Каждая граница --- корень одного множителя ("
    ),
    "The same computation with the order kept as a symbol": (
        "То же вычисление с порядком в виде символа"
    ),
    "Width and centre for odd orders, leading terms:": (
        "Ширина и центр для нечётных порядков, главные члены:"
    ),
    "Width and centre for even orders, leading terms:": (
        "Ширина и центр для чётных порядков, главные члены:"
    ),
    r"With friction an interval exists only above a threshold depth $m_{\min}(Q)$. "
    r"At the threshold the instability indicator has a double zero in $\theta$ (a "
    r"tangency); in the distinguished scaling $1/Q = \lambda m^p$ ($p = 1$ for odd "
    r"orders, 2 for even) both conditions are solved as series and reverted. Both "
    r"damping models:": (
        r"С трением интервал существует лишь при глубине модуляции выше пороговой "
        r"$m_{\min}(Q)$. На пороге индикатор неустойчивости имеет двукратный нуль по $\theta$ "
        r"(касание); в выделенном масштабе $1/Q = \lambda m^p$ ($p = 1$ для нечётных порядков, 2 "
        r"для чётных) оба условия решаются в виде рядов, которые затем обращаются. Обе модели "
        r"трения:"
    ),
    r"Above the threshold the edges are series in $m$ at fixed "
    r"$s = \sqrt{1 - (m_{\min,0}/m)^{2}}$ (odd orders) or "
    r"$s = \sqrt{1 - (m_{\min,0}/m)^{4}}$ (even orders), with $m_{\min,0}$ the "
    r"leading threshold; "
    r"the paper's eqs. (40) and (45) are the first terms. Both damping models, in "
    r"units of $T_0$:": (
        r"Выше порога границы --- ряды по $m$ при фиксированном "
        r"$s = \sqrt{1 - (m_{\min,0}/m)^{2}}$ (нечётные порядки) или "
        r"$s = \sqrt{1 - (m_{\min,0}/m)^{4}}$ (чётные), где $m_{\min,0}$ --- главный член "
        r"порога; ур. (40) "
        r"и (45) статьи --- первые члены. Обе модели трения, в единицах $T_0$:"
    ),
    # closings
    "The paper shows closings of the third, fourth and fifth intervals in its Fig. 2 and links "
    "them to": "Статья показывает смыкания третьего, четвёртого и пятого интервалов на рис. 2 и "
    "связывает их с",
    "(its Section 5); the theorem says these are instances of one rule and that there are no "
    "others.": (
        "(разд. 5); теорема утверждает, что это частные случаи одного правила и других нет."
    ),
    r"Table~\ref{tab:closings} lists every closing of the orders $1,\dots,12$. The period is "
    r"printed with 40 correctly rounded significant digits from an interval enclosure; the last "
    r"column is the independent check: the monodromy matrix built from the free oscillations and "
    r"the jumps (\texttt{verify.floquet}, 50 digits) at that depth and period, against "
    r"$(-1)^n I$.": (
        r"В таблице~\ref{tab:closings} перечислены все смыкания порядков $1,\dots,12$. Период "
        r"напечатан с 40 правильно округлёнными значащими цифрами по интервальному включению; "
        r"последний столбец --- независимая проверка: матрица монодромии, построенная из "
        r"свободных колебаний и скачков (\texttt{verify.floquet}, 50 знаков) при этих глубине и "
        r"периоде, в сравнении с $(-1)^n I$."
    ),
    # diagrams
    "redraws the paper's Fig. 2: the first six intervals of instability in the plane of the "
    "modulation period and the depth, without friction, from the certified-equation solver in "
    "double precision (every edge is a root of one per-edge equation,": (
        "воспроизводит рис. 2 статьи: первые шесть интервалов неустойчивости на плоскости "
        "(период модуляции, глубина модуляции) без трения, по решениям уравнений границ в "
        "двойной точности (каждая граница --- корень одного уравнения границы,"
    ),
    "redraws the paper's Fig. 8: the first three intervals without friction and for": (
        "воспроизводит рис. 8 статьи: первые три интервала без трения и при"
    ),
    ", in the paper's damping model (left, which is what the paper computed) and in the exact "
    "model (right). Friction raises a threshold below which an interval does not exist and "
    "swallows the neighbourhood of every closing.": (
        ", в модели трения статьи (слева; её и рассчитывала статья) и в точной модели (справа). "
        "Трение создаёт порог, ниже которого интервала нет, и поглощает окрестность каждого "
        "смыкания."
    ),
    # performance
    "The paper's pictures of stationary oscillations, redrawn from simulations that follow the "
    "pendulum through the jumps half period by half period (exact piecewise propagation of the "
    "linear model, started on a certified edge from the stationary initial condition of ": (
        "Рисунки статьи со стационарными колебаниями, перестроенные по моделированию, которое "
        "ведёт маятник через скачки полупериод за полупериодом (точное кусочное решение "
        "линейной модели, начатое на гарантированной границе со стационарного начального "
        "условия из "
    ),
    "). The line above each run states its closure error after one (anti)period: the state "
    "returns to where it started to the working precision, which is the time-domain check that "
    "the edge and the initial condition are right.": (
        "). Строка над каждым прогоном указывает ошибку замыкания через один (анти)период: "
        "состояние возвращается к исходному с рабочей точностью, что и есть проверка во времени "
        "правильности границы и начального условия."
    ),
    # the catalogue's titles
    "Equations of motion in each half": "Уравнения движения на каждом полупериоде",
    "Angular-momentum jump": "Скачок момента импульса",
    "Closings of intervals": "Смыкания интервалов",
    "Third interval with friction": "Третий интервал с трением",
    "Average frequency and period at small depth": (
        "Средние частота и период при малой глубине модуляции"
    ),
    "Segments on the lower edge of the first interval": (
        "Отрезки на нижней границе первого интервала"
    ),
    "Product-to-sum form of (12)": "(12) с произведениями, записанными как суммы",
    "Left edge of the third interval (the paper's section 3.2)": (
        "Левая граница третьего интервала (разд. 3.2 статьи)"
    ),
    "Stationary initial condition on the lower edge (after eq. 15)": (
        "Стационарное начальное условие на нижней границе (после ур. 15)"
    ),
    "Segments on the upper edge of the first interval": (
        "Отрезки на верхней границе первого интервала"
    ),
    "First interval at small depth": "Первый интервал при малой глубине модуляции",
    "Third interval at small depth": "Третий интервал при малой глубине модуляции",
    "Asymmetry and width of the third interval": "Асимметрия и ширина третьего интервала",
    "Segments on the lower edge of the second interval": (
        "Отрезки на нижней границе второго интервала"
    ),
    "Product-to-sum form of (24)": "(24) с произведениями, записанными как суммы",
    "Stationary initial condition on the lower edge of the second interval": (
        "Стационарное начальное условие на нижней границе второго интервала"
    ),
    "Second interval at small depth": "Второй интервал при малой глубине модуляции",
    "Damped segments (paper model)": "Отрезки с затуханием (модель статьи)",
    "Periodicity conditions, odd orders with friction": (
        "Условия периодичности, нечётные порядки с трением"
    ),
    "Notation C_i, S_i": "Обозначения $C_i$, $S_i$",
    "Determinant of (32)": "Определитель (32)",
    "Product to sum": "Произведения как суммы",
    "Boundary equation, odd orders with friction": "Уравнение границы, нечётные порядки с трением",
    "Threshold condition of the first interval": "Условие порога первого интервала",
    "Threshold of the first interval": "Порог первого интервала",
    "Fixed-point form with friction (first interval)": (
        "Форма для итераций с трением (первый интервал)"
    ),
    "Cross-reference after eq. (39)": "Ссылка после ур. (39)",
    "First interval near the threshold": "Первый интервал вблизи порога",
    "Cross-reference before eq. (40)": "Ссылка перед ур. (40)",
    "Boundary equation, even orders with friction": "Уравнение границы, чётные порядки с трением",
    "Threshold condition of the second interval": "Условие порога второго интервала",
    "Threshold of the second interval": "Порог второго интервала",
    "Fixed-point form with friction (second interval)": (
        "Форма для итераций с трением (второй интервал)"
    ),
    "Cross-reference after eq. (44)": "Ссылка после ур. (44)",
    "Second interval near the threshold": "Второй интервал вблизи порога",
    # the paper's time-domain figures
    "Stationary oscillation on the lower edge of the first interval (near $T = T_{av}/2$)": (
        "Стационарные колебания на нижней границе первого интервала (вблизи $T = T_{av}/2$)"
    ),
    "Stationary oscillation on the upper edge of the first interval": (
        "Стационарные колебания на верхней границе первого интервала"
    ),
    "Stationary oscillations on the lower and upper edges of the third interval "
    "($T \\approx 3T_{av}/2$)": (
        "Стационарные колебания на нижней и верхней границах третьего интервала "
        "($T \\approx 3T_{av}/2$)"
    ),
    "Growth of the oscillation at the second-order resonance ($T \\approx T_{av}$)": (
        "Нарастание колебаний при резонансе второго порядка ($T \\approx T_{av}$)"
    ),
    "Stationary oscillation on the lower edge of the second interval (near $T = T_{av}$)": (
        "Стационарные колебания на нижней границе второго интервала (вблизи $T = T_{av}$)"
    ),
    "Closing of the third interval: $T_1 : T_2 = 2 : 1$ ($m = 3/5$), every solution is periodic": (
        "Смыкание третьего интервала: $T_1 : T_2 = 2 : 1$ ($m = 3/5$), любое решение периодично"
    ),
    "Stationary oscillation on the lower edge of the first interval with friction ($Q = 3$)": (
        "Стационарные колебания на нижней границе первого интервала с трением ($Q = 3$)"
    ),
    # checks
    r"\emph{Check:}": r"\emph{Проверка:}",
    "holds up to the non-vanishing factor": "выполняется с точностью до ненулевого множителя",
    "(proved symbolically)": "(доказано символьно)",
    r"\emph{Printed:}": r"\emph{В статье:}",
    r"\emph{Derived:}": r"\emph{Выведено:}",
    # diagrams, accuracy, performance
    "Section": "раздел",
    "Table": "таблица",
    "The intervals of order": "Интервалы порядка",
    "pinch to zero width at the closings of": "стягиваются в точку в смыканиях, см.",
    "(dots, labelled": "(точки с подписью",
    "); within the figure these are the ratios": "); на рисунке это отношения",
    ". The paper names 2:1, 3:1 and 3:2.": ". Статья называет 2:1, 3:1 и 3:2.",
    "compares the series of": "сравнивает ряды (см.",
    "truncated after the powers": "), оборванные после степеней",
    "with the certified lower edges (40 proven digits). The error falls off as the first "
    "neglected power: the fitted slopes at the smallest depths are": (
        "с гарантированными нижними границами (40 доказанных знаков). Погрешность убывает как "
        "первая отброшенная степень: наклоны, подобранные при наименьших глубинах модуляции,"
    ),
    ". The truncation through": ". Обрыв после",
    "is the form the paper prints for": "--- та форма, которую статья печатает для",
    "(eqs. 18, 27, 19; see the catalogue for where it agrees).": (
        "(ур. 18, 27, 19; где она совпадает --- см. разбор результатов статьи)."
    ),
    r"\textbf{Floquet cross-check.}": r"\textbf{Проверка через матрицу монодромии.}",
    "The monodromy matrix": "Матрица монодромии",
    "is built independently of the determinants, as the product of the half-period maps and the "
    "jumps, and evaluated at each certified edge with": (
        "строится независимо от определителей, как произведение отображений за полупериоды и "
        "скачков, и вычисляется на каждой гарантированной границе с"
    ),
    "digits. On an edge": "знаками. На границе",
    "must be a multiplier, i.e.": "должно быть мультипликатором, т.\u00a0е.",
    r"(Table~\ref{tab:floquet}):": r"(таблица~\ref{tab:floquet}):",
    "the residuals are at the level of the": "невязки --- на уровне",
    "digits the edges are given to.": "знаков, с которыми даны границы.",
    "Every way the engine offers to compute an edge -- the series, the paper's fixed-point "
    "iteration, double precision per point and on a grid, uncertified mpmath, the certified "
    "solver, plain root finding on the printed equations and the automatic choice -- timed on "
    "the same scenes (orders 1 to 6 on a grid of depths, and the hard cases: tiny depth, depth "
    "near 1, closings, thresholds with friction, order 100) and compared with a certified "
    "reference of 60 digits": (
        "Все способы, которыми программа вычисляет границу, --- ряды, итерации статьи, двойная "
        "точность в точке и на сетке, mpmath без гарантии, гарантированный решатель, обычный "
        "поиск корня напечатанных уравнений и автоматический выбор --- измерены на одних и тех "
        "же сценах (порядки 1--6 на сетке глубин модуляции и трудные случаи: очень малая "
        "глубина, глубина около 1, смыкания, пороги с трением, порядок 100) и сравнены с "
        "гарантированным эталоном в 60 знаков"
    ),
    r"(Figure~\ref{fig:pareto}, Table~\ref{tab:speed}).": (
        r"(рис.~\ref{fig:pareto}, таблица~\ref{tab:speed})."
    ),
    # the stitching section: the general system and the normal form
    ", with four amplitudes. Continuity of the angle and the angular-momentum jump at": (
        ", с четырьмя амплитудами. Непрерывность угла и скачок момента импульса при"
    ),
    "give four homogeneous linear conditions. Without friction, for odd orders": (
        "дают четыре однородных линейных условия. Без трения, для нечётных порядков"
    ),
    "The segments of the paper model and of the exact model (Table~\\ref{tab:segments}) give the "
    "same four conditions with their own segments. Their determinant is, in every model, a "
    "non-vanishing factor": (
        "Решения модели статьи и точной модели (таблица~\\ref{tab:segments}) дают те же четыре "
        "условия со своими решениями. Их определитель в любой модели равен необращающемуся в "
        "нуль множителю"
    ),
    "times the Floquet condition: with": "на условие Флоке: при",
    "the monodromy matrix (the period map of": "--- матрица монодромии (отображение за период для",
    ". Its trace has one form for all models, with the phases": (
        ". Её след имеет один вид для всех моделей, с фазами"
    ),
    "of the two halves over": "двух половин за",
    "and one coupling constant": "и одной константой связи",
    "where the coupling constant is": "где константа связи равна",
    "without friction and in the paper model, and": "без трения и в модели статьи и",
    "in the exact model. A product-to-sum lemma in": (
        "в точной модели. Лемма о переходе от произведения к сумме, записанная только через"
    ),
    "frequency ($T_0=1$)": "частота ($T_0=1$)",
    "paper (eqs. 28--30)": "статьи (ур. 28--30)",
    r"exact, $\gamma<\omega_1$": r"точная, $\gamma<\omega_1$",
    r"exact, $\gamma=\omega_1$": r"точная, $\gamma=\omega_1$",
    r"exact, $\gamma>\omega_1$": r"точная, $\gamma>\omega_1$",
    r"in units $T_0 = 1$, $\gamma = \pi/Q$": r"при $T_0 = 1$, $\gamma = \pi/Q$",
    "When is the jump a good model?": "Когда скачок длины --- хорошая модель?",
    "For": "При",
    "For order": "Для порядка",
    "put": "положим",
    "Write": "Положим",
    "). In units": "). В единицах",
    "interval closes (Section~\\ref{sec:closings}).": (
        "интервал смыкается (раздел~\\ref{sec:closings})."
    ),
    r"\textbf{Window theorem.}": r"\textbf{Теорема об окне.}",
    r"\textbf{differs}": r"\textbf{расходится}",
    "odd": "нечётные",
    "even": "чётные",
    "factor $F$": "множитель $F$",
    r"\textbf{not proportional}": r"\textbf{не пропорционален}",
    "from $m$": "от $m$",
    "to $m$": "до $m$",
    "lower edge $T_-/T_0$": "нижняя граница $T_-/T_0$",
    "upper edge $T_+/T_0$": "верхняя граница $T_+/T_0$",
    "per-edge equations": "уравнения границ",
    "method": "метод",
    "family": "семейство",
    "s per edge": "с/граница",
    "error (all)": "погр. (все)",
    r"error ($m\le 0.01$)": r"погр. ($m\le 0.01$)",
    "failures": "отказы",
    "torsion pendulum": "крутильный маятник",
    "stiffness switched": "переключается жёсткость",
    "alone, with": ", где",
    "(the paper's": "(в статье",
    ") and": ") и",
    "and (anti)periodicity across": "и (анти)периодичность при переходе через",
    "Trace form, no friction": "Вид следа: без трения",
    "Trace form, paper model": "Вид следа: модель статьи",
    "Trace form, exact model": "Вид следа: точная модель",
    "Odd orders; unstable where": ("Нечётные порядки: положение равновесия неустойчиво там, где"),
    "Even orders; unstable where": "Чётные порядки: положение равновесия неустойчиво там, где",
    "product to sum": "произведение в сумму",
    "\\emph{product to sum.}": "\\emph{произведение в сумму.}",
    "Together these give the normal form": "Вместе они дают нормальную форму",
    "(the rest state is unstable where": "(состояние покоя неустойчиво, где",
    "the engine defines the parameters as follows (exact model: the same with the damped "
    "frequencies": (
        "программа определяет параметры так (точная модель: то же с частотами затухающих колебаний"
    ),
    "The conditions across": "Условия при переходе через",
    "repeat those at": "повторяют условия при",
    "row by row up to sign": "построчно с точностью до знака",
    "(the engine compares the rows), so two conditions remain.": (
        "(программа сравнивает строки), так что остаются два условия."
    ),
    "Per-edge factor: the determinant is a non-vanishing multiple of": (
        "Множитель границы: определитель --- необращающееся в нуль кратное"
    ),
    "(the paper's unknown in eqs. 15, 26, 39, 44). For every order the normal form becomes": (
        "(неизвестная статьи в уравнениях 15, 26, 39, 44). Для любого порядка нормальная форма "
        "принимает вид"
    ),
    "is a difference of squares, one factor per edge (": (
        "--- разность квадратов, по одному множителю на границу ("
    ),
    "), and each edge of the": "), и каждая граница",
    "-th interval is the root in": "-го интервала --- корень на",
    "of one of the following equations, derived for each order:": (
        "одного из следующих уравнений, выведенных для каждого порядка:"
    ),
    "each per-edge equation has exactly one root, and it is simple: at": (
        "каждое уравнение границы имеет ровно один корень, и он простой: при"
    ),
    "term dominates because": "преобладает член, поскольку",
    ", and at any root its derivative exceeds that of the other term because": (
        ", а в любом корне его производная больше производной другого члена, поскольку"
    ),
    ", so all roots cross with the same sign. Each interval is therefore bounded by one root of "
    "each equation; the lower edge is the smaller one, and where both vanish at once the": (
        ", так что все корни пересекаются с одним знаком. Поэтому каждый интервал ограничен одним "
        "корнем каждого уравнения; нижняя граница --- меньший из них, а где оба обращаются в нуль "
        "одновременно,"
    ),
    # the expansions, thresholds and accuracy sections
    "by Newton steps on exact power series, then": (
        "находится шагами Ньютона над точными степенными рядами, затем"
    ),
    "with the parameters expanded from their definitions; through": (
        "с параметрами, разложенными из их определений; до"
    ),
    "gives closed forms valid for every odd and every even order:": (
        "даёт замкнутые формы, верные для любого нечётного и любого чётного порядка:"
    ),
    "the centre moves only at": "центр смещается лишь в порядке",
    "; the two models part at": "; две модели расходятся в порядке",
    "in the threshold series": "в ряду порога",
    "bob shifted along a light rod": "груз смещается вдоль лёгкого стержня",
    "gives certified edges to 35 significant digits at chosen depths, with and without friction. "
    "Every digit is proven: the number is the midpoint of a ball (interval) that contains the "
    "exact edge and is narrower than the last digit.": (
        "даёт гарантированные границы с 35 значащими цифрами при выбранных глубинах модуляции, с "
        "трением и без него. Каждая цифра доказана: число --- середина шара (интервала), который "
        "содержит точную границу и уже последней цифры."
    ),
    "normal form with friction": "нормальная форма с трением",
    # the catalogue's explanations that carry no computed numbers
    "The limit $m \\to 0$ of the exact tuning condition (6), $T = nT_{av}/2$ with "
    "$T_{av} \\to T_0$; decided symbolically.": (
        "Предел $m \\to 0$ точного условия настройки (6), $T = nT_{av}/2$ при $T_{av} \\to T_0$; "
        "решено символьно."
    ),
    "Derived from $J\\ddot\\varphi = $ torque for a point bob, with $J = J_0 (l/l_0)^2$ (so "
    "$J_0/l_0^2$ is the bob's mass), the torque of gravity $-(J_0/l_0^2)\\,gl\\sin\\varphi$ and "
    "that of the drag $-cl^2\\dot\\varphi$ on the bob: $2\\gamma = cl_0^2/J_0$ does "
    "not depend on $l$ (the same in both halves), $\\omega_i^2 = g/l_i$ with "
    "$l_{1,2} = l_0(1 \\pm m)$; decided symbolically.": (
        "Выведено из $J\\ddot\\varphi = $ момент сил для точечного груза при "
        "$J = J_0 (l/l_0)^2$ (так что $J_0/l_0^2$ --- масса груза), моменте силы тяжести "
        "$-(J_0/l_0^2)\\,gl\\sin\\varphi$ и моменте силы сопротивления $-cl^2\\dot\\varphi$, "
        "действующей на груз: $2\\gamma = cl_0^2/J_0$ не зависит от $l$ (одинаково в обеих "
        "половинах), $\\omega_i^2 = g/l_i$ при $l_{1,2} = l_0(1 \\pm m)$; решено символьно."
    ),
    "Printed and derived forms are the same equation; decided symbolically (exact rational "
    "identity after expanding the abbreviations). The angular momentum $J\\dot\\varphi$ with "
    "$J = J_0 (l/l_0)^2$ is conserved.": (
        "Напечатанная и выведенная формы --- одно и то же уравнение; решено символьно (точное "
        "рациональное тождество после раскрытия сокращений). Момент импульса $J\\dot\\varphi$ "
        "при $J = J_0 (l/l_0)^2$ сохраняется."
    ),
    "After eq. (39): 'at zero friction $p = 1$, and (39) coincides with (14)'. At $p = 1$ the "
    "(squared) equation (39) is a non-vanishing multiple of (15); the reference should be (15), "
    "not (14).": (
        "После уравнения (39): «при нулевом трении $p = 1$, и (39) совпадает с (14)». При $p = 1$ "
        "(возведённое в квадрат) уравнение (39) --- необращающееся в нуль кратное (15); ссылка "
        "должна быть на (15), а не на (14)."
    ),
    "After eq. (44): 'at zero friction $p = 1$, and (44) coincides with (26)'. At $p = 1$ the "
    "(squared) equation (44) is a non-vanishing multiple of (26); the reference is right.": (
        "После уравнения (44): «при нулевом трении $p = 1$, и (44) совпадает с (26)». При $p = 1$ "
        "(возведённое в квадрат) уравнение (44) --- необращающееся в нуль кратное (26); ссылка "
        "верна."
    ),
    # words set upright inside formulas (see reports.latex.notation)
    "at": "при",
    "centre": "центр",
    # the expansions section
    "; in units of": "; в единицах",
    "), solved for": "); корень",
    "no order computed": "порядок не вычислен",
    "so that": "так что",
    "from": "от",
    "in place of": "вместо",
    # the stitching section's proven links
    "det M, paper model": "det M, модель статьи",
    "det M, exact model": "det M, точная модель",
    "normal form": "нормальная форма",
    # the family's systems (the engine's names) as the figure titles them
    "pendulum": "маятник",
    "torsion": "крутильный маятник",
    "meissner": "уравнение Мейснера",
    # the tables of closings and of the Floquet cross-check
    "$T/T_0$ exact": "$T/T_0$ точно",
    "$T/T_0$ (certified digits)": "$T/T_0$ (гарантированные цифры)",
    "at $T_-$": "при $T_-$",
    "at $T_+$": "при $T_+$",
    "equations solved": "решаемые уравнения",
    # the benchmark: the panels, the families of methods and the methods without a number
    "all scenes": "все сцены",
    "series": "ряды",
    "fixed point": "итерации статьи",
    "double": "двойная точность",
    "grid": "сетка",
    "certified": "гарантированный",
    "auto": "авто",
    "fixed point (paper)": "итерации статьи",
    "double, per point": "двойная точность, в точке",
    "numpy grid": "сетка numpy",
}

PHRASES.update(
    {
        f"Edge shape {name}": f"Форма границы {fn} ({orders})"
        for name, (fn, orders) in EDGE_SHAPES.items()
    }
)

PATTERNS: list[tuple[str, object]] = [
    (
        r"The third-order island at \$Q = (\d+)\$ \(Figure",
        r"Остров третьего порядка при $Q = \1$ (рис.",
    ),
    (
        r"The paper says the region vanishes above about (\d+)% depth and returns above about "
        r"(\d+)%\. The engine's existence ranges, each end proven by interval arithmetic "
        r"\((\d+) digits\), are in Table",
        r"Статья говорит, что область исчезает при глубине модуляции выше примерно \1% и "
        r"появляется снова выше примерно \2%. Области существования, найденные программой "
        r"(каждый конец доказан интервальной арифметикой, \3 знаков), приведены в таблице",
    ),
    (
        r"it vanishes at ([\d.]+)% in the paper model \((within|not within) one percentage point "
        r"of the paper's (\d+)%\); it returns at ([\d.]+)% in the paper model \((within|not "
        r"within) one percentage point of the paper's (\d+)%\); the exact model gives ([\d.]+)% "
        r"and ([\d.]+)%\.",
        lambda m: (
            f"в модели статьи она исчезает при {m[1]}% "
            f"({'в пределах' if m[2] == 'within' else 'вне'} одного процентного пункта от "
            f"{m[3]}% статьи) и появляется снова при {m[4]}% "
            f"({'в пределах' if m[5] == 'within' else 'вне'} одного процентного пункта от "
            f"{m[6]}% статьи); точная модель даёт {m[7]}% и {m[8]}%."
        ),
    ),
    (
        r"Against the paper: (.*)\. Among the first six intervals \(those of its Fig\. 2\) the "
        r"theorem also gives (.*), which lie at depths above those the paper discusses\.",
        lambda m: (
            "Сравнение со статьёй: "
            + m[1]
            .replace(" closes orders ", " смыкает порядки ")
            .replace(" closes order ", " смыкает порядок ")
            .replace(" at $m = ", " при $m = ")
            + ". Среди первых шести интервалов (рис. 2 статьи) теорема даёт ещё "
            + m[2]
            + "; они лежат при глубинах модуляции больших, чем обсуждаемые в статье."
        ),
    ),
    (
        r"Measured by paramres bench \((.*)\)\.",
        lambda m: (
            "Измерено командой paramres bench ("
            + re.sub(
                r"\b(cpu|cores|system) ",
                lambda k: {"cpu": "процессор ", "cores": "ядер ", "system": "система "}[k[1]],
                m[1],
            )
            + ")."
        ),
    ),
    # the benchmark's methods that carry a number (the others are phrases above)
    (r"series K=(\d+)", r"ряд, K=\1"),
    (r"mpmath (\d+), uncertified", r"mpmath \1, без гарантии"),
    (r"certified (\d+)", r"гарантированный \1"),
    (r"findroot (\d+) \(printed eq\.\)", r"findroot \1 (напечатанное ур.)"),
    (r"auto, (tol=\S+)", r"авто, \1"),
    # a friction entry of the certified tables: the quality factor and the damping model
    (r"(\$[^$]+\$) \(paper\)", r"\1 (модель статьи)"),
    (r"(\$[^$]+\$) \(exact\)", r"\1 (точная модель)"),
    (r"Figure~\\ref\{([^}]*)\}", r"Рис.~\\ref{\1}"),
    (r"Table~\\ref\{([^}]*)\}", r"Таблица~\\ref{\1}"),
    (r"Section~\\ref\{([^}]*)\}", r"Раздел~\\ref{\1}"),
    (
        r"The paper's numbered results: (\d+) checked, (\d+) agree with the derivation, (\d+) "
        r"differ \(misprints or wrong statements; the correct forms are given below\)\. Click an "
        r"equation number for the entry\.",
        r"Пронумерованные результаты статьи: проверено \1, с выводом совпадают \2, расходятся "
        r"\3 (опечатки или неверные утверждения; верные формы приведены ниже). Номер уравнения "
        r"--- ссылка на разбор.",
    ),
    (
        r"Depth ranges in which the third interval exists at \$Q = (\d+)\$ \(proven ends\)\.",
        r"Глубины модуляции, при которых третий интервал существует при $Q = \1$ (доказанные "
        r"концы).",
    ),
    (
        r"The paper's Fig\.~(\d+) redrawn: (.*)",
        r"Рис.~\1 статьи, перестроенный: \2",
    ),
    (
        r"numeric, at (\d+) random points with (\d+) digits, largest relative residual "
        r"([0-9.e+-]+) \(sympy did not reduce it to zero\)",
        r"численно, в \1 случайных точках с \2 знаками, наибольшая относительная невязка \3 "
        r"(sympy не свёл к нулю)",
    ),
]


# The catalogue's verdicts that carry computed formulas, orders and equation numbers.  Each entry is
# the English sentence with its computed parts as ``<name>`` and the Russian one with the same
# names; the computed parts (the engine's formulas) pass into the Russian text unchanged, except
# the short verdict words listed in ``_WORDS``.
_WORDS = {"agrees": "совпадает", "differs": "расходится", "disagrees": "расходится"}


def _slot_re(en: str) -> str:
    """The regular expression of a template: the text literal, each ``<name>`` a lazy group
    (``<v...>`` a verdict word of ``_WORDS``)."""
    out, pos = [], 0
    for m in re.finditer(r"<([a-z][a-z0-9]*)>", en):
        body = "[a-z ]+?" if m[1].startswith("v") else ".+?"  # <v...>: a verdict word
        out.append(re.escape(en[pos : m.start()]) + f"(?P<{m[1]}>{body})")
        pos = m.end()
    return "".join(out) + re.escape(en[pos:])


def _slot_fill(ru: str, fix: dict | None = None):
    """The replacement of a template: ``<name>`` in ``ru`` filled with the matched part."""

    def fill(m: re.Match) -> str:
        def part(k: re.Match) -> str:
            v = m[k[1]]
            v = _WORDS.get(v, v)
            return fix[k[1]](v) if fix and k[1] in fix else v

        return re.sub(r"<([a-z][a-z0-9]*)>", part, ru)

    return fill


def _check_ru(s: str) -> str:
    """How an identity was checked, in Russian."""
    m = re.fullmatch(
        r"checked numerically at (\d+) random points with (\d+) digits \(largest relative "
        r"residual ([^()]*)\); sympy did not reduce it to zero",
        s,
    )
    if m:
        return (
            f"проверено численно в {m[1]} случайных точках с {m[2]} знаками (наибольшая "
            f"относительная невязка {m[3]}); sympy не свёл разность к нулю"
        )
    return {
        "proved symbolically": "доказано символьно",
        "simplifies symbolically to zero": "символьно сводится к нулю",
    }.get(s, s)


_EDGE_TAILS = [
    (
        " The lower edge is the root of the eq.-(13) factor ($\\varepsilon = +1$) for $n = 1$.",
        " Нижняя граница при $n = 1$ --- корень множителя уравнения (13) ($\\varepsilon = +1$).",
    ),
    (
        " For $n = 3$ the eq.-(13) factor ($\\varepsilon = +1$, the shape of eqs. 8-9) gives the "
        "upper edge and the factor of opposite sign (eqs. 16-17) the lower one: for odd $n$ the "
        "eq.-(13) factor is the lower edge when $n = 1, 5, 9, \\dots$ and the upper edge when "
        "$n = 3, 7, 11, \\dots$ (<cn>).",
        " При $n = 3$ множитель уравнения (13) ($\\varepsilon = +1$, форма уравнений 8-9) даёт "
        "верхнюю границу, а множитель противоположного знака (уравнения 16-17) --- нижнюю: при "
        "нечётном $n$ множитель уравнения (13) даёт нижнюю границу при $n = 1, 5, 9, \\dots$ и "
        "верхнюю при $n = 3, 7, 11, \\dots$ (<cn>).",
    ),
    (
        " The explicit forms <f1>, <f2> and the width <w> agree through <o> (there is no <o2> "
        "term: even orders are even in $m$).",
        " Явные формулы <f1>, <f2> и ширина <w> верны до <o> включительно (члена <o2> нет: "
        "ряды чётных порядков чётны по $m$).",
    ),
]


def _edge_tail(s: str) -> str:
    """The last sentence of an edge-series verdict, in Russian."""
    for en, ru in _EDGE_TAILS:
        m = re.fullmatch(_slot_re(en), s, flags=re.S)
        if m:
            return _slot_fill(ru)(m)
    return s


_CATALOGUE = [
    (
        "Closing theorem (derived: both edge factors vanish together if and only if "
        "$\\omega_1 T/2 = a\\pi$ and $\\omega_2 T/2 = b\\pi$ with $1 \\le a < b$, "
        "$a + b = n$; then $T_1:T_2 = b:a$, $m = (b^2-a^2)/(b^2+a^2)$, $T = aT_1$, $M = (-1)^n I$; "
        "no other closings, by the window theorem). The three ratios the text names are special "
        "cases: <named>. The "
        "2:1 closing is the one the text explains ($a = 1$, $b = 2$: half an oscillation of $T_1$ "
        "and a full one of $T_2$ per cycle, $M = -I$, so every motion repeats after two cycles). "
        "For $n \\le <nmax>$ the theorem gives <k> closings: <list>. Not named in the text: "
        "<unnamed>; they lie at depths near 0.9, where Fig. 2 may not reach. No closings for "
        "$n = 1, 2$ (the text's '$n > 2$' agrees).",
        "Теорема о смыканиях (выведена: оба множителя границ обращаются в нуль одновременно тогда "
        "и только тогда, когда $\\omega_1 T/2 = a\\pi$ и $\\omega_2 T/2 = b\\pi$, где "
        "$1 \\le a < b$, $a + b = n$; тогда $T_1:T_2 = b:a$, $m = (b^2-a^2)/(b^2+a^2)$, "
        "$T = aT_1$, $M = (-1)^n I$; других смыканий нет по теореме об окне). Три отношения, "
        "названные в тексте, --- её частные случаи: <named>. Смыкание 2:1 --- то, которое "
        "объясняется в тексте ($a = 1$, $b = 2$: за цикл укладываются половина колебания с "
        "периодом $T_1$ и полное колебание с периодом $T_2$, $M = -I$, так что любое движение "
        "повторяется через два цикла). При $n \\le <nmax>$ теорема даёт смыкания (всего <k>): "
        "<list>. Не названы в тексте: <unnamed>; они лежат при глубинах модуляции около 0,9, "
        "куда рис. 2 может не доходить. При $n = 1, 2$ смыканий нет (это согласуется с условием "
        "«$n > 2$» в тексте).",
        {"named": lambda v: v.replace(" at ", " при ")},
    ),
    (
        "Threshold of the third interval (tangency, paper model): <lead> at leading order "
        "(<v1>); in general <gen> for every odd $n$. Edges: with "
        "$s = \\sqrt{1 - m_{\\min}^2/m^2}$ (so $ms = \\sqrt{m^2 - m_{\\min}^2}$), the derived "
        "<edges>, which is (19) with $m \\to \\sqrt{m^2 - m_{\\min}^2}$ (<v2>) through order $m$, "
        "coefficient by coefficient in $m$ at fixed $m_{\\min}/m$. The next order is a friction "
        "shift of the centre, <shift> ($s^2 - 1 = -m_{\\min}^2/m^2$), which (19) does not have.",
        "Порог третьего интервала (касание, модель статьи): <lead> в главном порядке "
        "(<v1>); в общем случае <gen> для любого нечётного $n$. Границы: при "
        "$s = \\sqrt{1 - m_{\\min}^2/m^2}$ (так что $ms = \\sqrt{m^2 - m_{\\min}^2}$) выведенное "
        "<edges>, т. е. (19) с заменой $m \\to \\sqrt{m^2 - m_{\\min}^2}$ (<v2>), до порядка $m$ "
        "включительно, коэффициент за коэффициентом по $m$ при фиксированном $m_{\\min}/m$. "
        "Следующий порядок --- сдвиг центра из-за трения, <shift> "
        "($s^2 - 1 = -m_{\\min}^2/m^2$), которого в (19) нет.",
    ),
    (
        "The exact form $\\omega_{av} = (\\omega_0/2)(1/\\sqrt{1+m} + 1/\\sqrt{1-m})$ follows from "
        "the model (<check>); its series (and that of $T_{av}/T_0 = 1/w$, where "
        "$w = \\omega_{av}/\\omega_0$) agree with the printed "
        "ones through <o> (symbolically), the printed order being <po>. Next terms: "
        "$\\omega_{av}/\\omega_0$: <a>, $T_{av}/T_0$: <b>.",
        "Точная формула $\\omega_{av} = (\\omega_0/2)(1/\\sqrt{1+m} + 1/\\sqrt{1-m})$ следует из "
        "модели (<check>); её ряд (и ряд $T_{av}/T_0 = 1/w$, где $w = \\omega_{av}/\\omega_0$) "
        "совпадает с напечатанным до <o> "
        "включительно (символьно), тогда как напечатан порядок <po>. Следующие члены: "
        "$\\omega_{av}/\\omega_0$: <a>, $T_{av}/T_0$: <b>.",
        {"check": _check_ru},
    ),
    (
        "The paper's section 3.2: for the left edge of the third interval "
        "'we get the same equations (10)-(11) "
        "and the same equation (15) ... this holds for all odd-order intervals', solved near "
        "$T = nT_{av}/2$. Derived: for $n = 3$ the shape (8)-(9) of eqs. (10)-(11) gives <eq>, "
        "whose small-$m$ root has $\\Delta T > 0$: the upper (right) edge. Eq. (15) with "
        "$T_{av}/2 \\to 3T_{av}/2$ is the equation of the other shape (16)-(17), and it is that "
        "one that gives the left edge. In general the shape of (8)-(9) gives the lower edge for "
        "$n = 1, 5, 9, \\dots$ and the upper edge for $n = 3, 7, 11, \\dots$ at small $m$, and the "
        "two shapes swap edges at every closing of the interval. The printed (15) with "
        "$nT_{av}/2$ does give the left edge of every odd interval at small $m$; the statement "
        "that it comes from (10)-(11) holds only for $n = 1, 5, 9, \\dots$",
        "Раздел 3.2 статьи: для левой границы третьего интервала "
        "«получаются те же уравнения (10)-(11) и "
        "то же уравнение (15) ... это справедливо для всех интервалов нечётного порядка», "
        "решаемое вблизи $T = nT_{av}/2$. Вывод: при $n = 3$ форма (8)-(9) уравнений (10)-(11) "
        "даёт <eq>; корень этого уравнения при малых $m$ имеет $\\Delta T > 0$, т. е. это верхняя "
        "(правая) граница. Уравнение (15) с заменой $T_{av}/2 \\to 3T_{av}/2$ --- уравнение "
        "другой формы, (16)-(17), и левую границу даёт именно оно. В общем случае при малых $m$ "
        "форма (8)-(9) даёт нижнюю границу при $n = 1, 5, 9, \\dots$ и верхнюю при "
        "$n = 3, 7, 11, \\dots$, а при каждом смыкании интервала две формы меняются границами. "
        "Напечатанное (15) с $nT_{av}/2$ действительно даёт левую границу любого нечётного "
        "интервала при малых $m$; утверждение же, что оно получается из (10)-(11), верно лишь при "
        "$n = 1, 5, 9, \\dots$",
    ),
    (
        "Both edges agree with the derived series through <o>, the printed order, in units of "
        "$T_{av}$ and of $T_0$ (symbolically, coefficient by coefficient). The derived series go "
        "on: $T_-/T_{av}$ next term <a>, $T_-/T_0$ next term <b> (any order: paramres series "
        "--order <n> --terms K).<tail>",
        "Обе границы совпадают с выведенными рядами до <o> включительно (это напечатанный порядок) "
        "в единицах $T_{av}$ и $T_0$ (символьно, коэффициент за коэффициентом). Выведенные ряды "
        "продолжаются: следующий член $T_-/T_{av}$ равен <a>, $T_-/T_0$ --- <b> (любой порядок: "
        "paramres series --order <n> --terms K).<tail>",
        {"tail": _edge_tail},
    ),
    (
        "The centre of the third interval lies <s> below <c> and its width is <w>, the same as the "
        "first interval's, both through the printed order (symbolically). In general the centre "
        "shift is <g> for every order (it is the shift of $nT_{av}/2$) and the leading width <gw> "
        "for "
        "every odd order. Next terms: centre <a>, width <b> (first interval: <c1>).",
        "Центр третьего интервала лежит на <s> ниже <c>, а его ширина равна <w>, как и у первого "
        "интервала; то и другое --- до напечатанного порядка включительно (символьно). В общем "
        "случае сдвиг центра равен <g> для любого порядка (это сдвиг $nT_{av}/2$), а главный член "
        "ширины --- <gw> для любого нечётного порядка. Следующие члены: центр <a>, ширина <b> "
        "(первый интервал: <c1>).",
    ),
    (
        "Misprint: printed <p> where the derivation gives <d>. The correct form is <c>. The "
        "printed <e1> does not follow from the printed <e2> (their determinant is <det>), but "
        "does follow from the corrected <e3>.",
        "Опечатка: напечатано <p>, а вывод даёт <d>. Верная форма: <c>. Напечатанное <e1> не "
        "следует из напечатанных <e2> (их определитель равен <det>), но следует из "
        "исправленного <e3>.",
    ),
    (
        "The printed segments are the engine's 'paper' damping model; decided symbolically. As "
        "the text says, the printed velocity is not the derivative of the angle: it drops <t> "
        "(valid for $\\gamma \\ll \\omega$). The 'exact' model keeps it.",
        "Напечатанные отрезки совпадают с моделью трения статьи (модель «paper» программы); "
        "установлено символьно. Как и сказано в тексте, напечатанная скорость не есть производная "
        "угла: в ней опущен член <t> (что допустимо при $\\gamma \\ll \\omega$). Точная модель "
        "(«exact») "
        "этот член сохраняет.",
    ),
    (
        "Read at exact tuning (<t>), as the text does, the printed condition is exactly the "
        "engine's radicand $R(\\theta = 0) = 0$ (its threshold series agrees with that of "
        "$R(0) = 0$ through <o1>). But the threshold is where the interval shrinks to a point: a "
        "double root, $N = 0$ and $dN/d\\theta = 0$ together (the radicand and $(q+1)^2 f(x)^2$ "
        "touch), and the double root does not sit at exact tuning: <th>. So the threshold read "
        "off the printed condition is right through relative order <o2> and wrong at <o3> (<q>): "
        "with $1/Q_{\\min} = \\lambda(m)\\, <mp>$, the <o4> coefficient of $\\lambda$ is <c1> from "
        "the printed condition but <c2> at the tangency (relative difference <rd>); the leading "
        "term, eq. <e>, is right. The correct condition is the tangency (paper model).",
        "Если, как в тексте, взять напечатанное условие при точной настройке (<t>), оно в "
        "точности совпадает с условием $R(\\theta = 0) = 0$ для подкоренного выражения программы "
        "(его ряд для порога совпадает с рядом для $R(0) = 0$ до <o1> включительно). Но порог --- "
        "это точка, в которую стягивается интервал: двукратный корень, $N = 0$ и "
        "$dN/d\\theta = 0$ одновременно (подкоренное выражение и $(q+1)^2 f(x)^2$ касаются), и "
        "этот двукратный корень лежит не при точной настройке: <th>. Поэтому порог, найденный из "
        "напечатанного условия, верен до относительного порядка <o2> включительно и неверен в "
        "порядке <o3> (<q>): при $1/Q_{\\min} = \\lambda(m)\\, <mp>$ коэффициент при <o4> "
        "в $\\lambda$ "
        "равен <c1> по напечатанному условию, но <c2> по условию касания (относительная разность "
        "<rd>); главный член, ур. <e>, верен. Верное условие --- касание (модель статьи).",
    ),
    (
        "The threshold is the tangency of the normal form ($N = 0$, $dN/d\\theta = 0$), solved "
        "in the distinguished scaling <p> and compared with the printed leading term, "
        "coefficient by coefficient in $1/Q$. Paper model: leading term <v1>; next term of <x1>: "
        "<a>; exact model: leading term <v2>; next term of <x2>: <b>. The two damping models "
        "part at relative order <o> in the threshold (<mp>). They differ in the frequencies of the "
        "halves: $W_i$ is the undamped $\\omega_i$ in the paper model and the damped "
        "$\\Omega_i = \\sqrt{\\omega_i^2 - \\gamma^2}$ in the exact model, and the normal-form "
        "parameters are built from them: $r^2 = (K-2)/(K+2)$ (with $K = q + 1/q$ in the paper "
        "model and the exact model's own coupling $K$), $\\beta = (W_2 - W_1)/(W_2 + W_1)$ and "
        "$w = (W_1 + W_2)/(2\\omega_0)$.",
        "Порог --- касание нормальной формы ($N = 0$, $dN/d\\theta = 0$); он найден в выделенном "
        "масштабе <p> и сравнён с напечатанным главным членом, коэффициент за коэффициентом "
        "по $1/Q$. Модель статьи: главный член <v1>; следующий член <x1>: <a>; точная модель: "
        "главный член <v2>; следующий член <x2>: <b>. Две модели трения дают разные пороги "
        "начиная с относительного порядка <o> (<mp>). Они различаются частотами половин периода: "
        "$W_i$ --- частота без затухания $\\omega_i$ в модели статьи и частота затухающих "
        "колебаний $\\Omega_i = \\sqrt{\\omega_i^2 - \\gamma^2}$ в точной модели, и из них "
        "строятся параметры нормальной формы: $r^2 = (K-2)/(K+2)$ (с $K = q + 1/q$ в модели "
        "статьи и собственной константой связи $K$ точной модели), "
        "$\\beta = (W_2 - W_1)/(W_2 + W_1)$ и $w = (W_1 + W_2)/(2\\omega_0)$.",
    ),
    (
        "Misprint (a lost factor 3): lower edge: coefficient of <k1> printed <a>, derived <b>; "
        "upper edge: coefficient of <k2> printed <c>, derived <d> (with $m_{\\min} = \\pi/(6Q)$, "
        "$s = \\sqrt{1 - m_{\\min}^2/m^2}$, compared coefficient by coefficient in $m$ at fixed "
        "$m_{\\min}/m$). The correct form is <cf>, i.e. <ie> (<v>), which is what Section 6 "
        "states ((18) with $m \\to \\sqrt{m^2 - m_{\\min}^2}$). The printed form fails the text's "
        "own check: at $m_{\\min} = 0$ it gives <g>, not (18) (it differs from (18); coefficient "
        "of $m$ printed <p1>, (18) <p2>). In the derivation before (40) the last radicand term "
        "$q(p-1)^2/p \\approx (\\pi/(2Q))^2$ equals $9m_{\\min}^2$, not $m_{\\min}^2$, so the "
        "radicand is $9(m^2 - m_{\\min}^2)$. The text also sends the reader to the radicand of "
        "(32) where (39) is meant. Beyond the printed order the friction shifts the centre: "
        "$(T_+ + T_-)/(2T_{av}) - 1/2 = <s1>$ (paper model) <l1> at leading order, <s2> (exact "
        "model) <l2>.",
        "Опечатка (потерян множитель 3): нижняя граница: коэффициент при <k1> напечатан <a>, "
        "выведен <b>; верхняя граница: коэффициент при <k2> напечатан <c>, выведен <d> (при "
        "$m_{\\min} = \\pi/(6Q)$, $s = \\sqrt{1 - m_{\\min}^2/m^2}$; сравнение коэффициент за "
        "коэффициентом по $m$ при фиксированном $m_{\\min}/m$). Верная форма: <cf>, т. е. <ie> "
        "(<v>); это и утверждается в разделе 6 ((18) с заменой "
        "$m \\to \\sqrt{m^2 - m_{\\min}^2}$). Напечатанная форма не проходит проверку, "
        "предложенную самим текстом: при $m_{\\min} = 0$ она даёт <g>, а не (18) (отличается "
        "от (18); коэффициент при $m$ напечатан <p1>, в (18) --- <p2>). В выводе перед (40) "
        "последний член подкоренного выражения $q(p-1)^2/p \\approx (\\pi/(2Q))^2$ равен "
        "$9m_{\\min}^2$, а не $m_{\\min}^2$, так что подкоренное выражение равно "
        "$9(m^2 - m_{\\min}^2)$. Кроме того, текст отсылает читателя к подкоренному выражению "
        "в (32), тогда как имеется в виду (39). За пределами напечатанного порядка трение "
        "сдвигает центр: $(T_+ + T_-)/(2T_{av}) - 1/2 = <s1>$ (модель статьи) <l1> в главном "
        "порядке, <s2> (точная модель) <l2>.",
    ),
    (
        "Before eq. (40): 'simplify the radicand in the right-hand side of (32)'. Equation (32) "
        "has no radicand; the printed equations with one are <l>. The simplification described "
        "($q \\approx 1 + 3m$, cosine $\\approx 1$) is of the radicand of (39), whose small-$m$ "
        "solution is (40).",
        "Перед уравнением (40): «можно упростить подкоренное выражение в правой части (32)». В "
        "уравнении (32) подкоренного выражения нет; из напечатанных уравнений оно есть в <l>. "
        "Описанное упрощение ($q \\approx 1 + 3m$, косинус $\\approx 1$) относится "
        "к подкоренному выражению "
        "в (39), решение которого при малых $m$ и есть (40).",
    ),
    (
        "Near-threshold edges of the second interval in the distinguished scaling "
        "$1/Q \\sim m^2$ ($m_{\\min} = \\sqrt{2/(3Q)}$, $s = \\sqrt{1 - m_{\\min}^4/m^4}$, "
        "$m^2 s = \\sqrt{m^4 - m_{\\min}^4}$): the derived <e> agrees with the printed form "
        "through <o>, coefficient by coefficient in $m$ at fixed $m_{\\min}/m$ (symbolically). In "
        "general <g> with the same $m_{\\min}$ for every even $n$. Next order (paper model): "
        "lower <a>; exact model: lower <b>.",
        "Границы второго интервала вблизи порога в выделенном масштабе $1/Q \\sim m^2$ "
        "($m_{\\min} = \\sqrt{2/(3Q)}$, $s = \\sqrt{1 - m_{\\min}^4/m^4}$, "
        "$m^2 s = \\sqrt{m^4 - m_{\\min}^4}$): выведенное <e> совпадает с напечатанной формой до "
        "<o> включительно, коэффициент за коэффициентом по $m$ при фиксированном $m_{\\min}/m$ "
        "(символьно). В общем случае <g> с тем же $m_{\\min}$ для любого чётного $n$. Следующий "
        "порядок (модель статьи): нижняя граница <a>; точная модель: нижняя граница <b>.",
    ),
]

PATTERNS += [(_slot_re(en), _slot_fill(ru, *fix)) for en, ru, *fix in _CATALOGUE]
