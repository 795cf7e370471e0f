"""Russian versions of the report's prose (see :mod:`reports.i18n`), in the paper's own terms:
интервал параметрической неустойчивости, глубина модуляции, добротность, период модуляции.

``PHRASES`` maps an English string, exactly as the report or the engine writes it, to its Russian
version; ``PATTERNS`` are ``(regular expression, replacement)`` pairs for strings that carry numbers
or formulas.  A string with no entry is left in English.
"""

from __future__ import annotations

__all__ = ["PHRASES", "PATTERNS"]

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
    "Edge shape odd-cos-sin": "Форма границы odd-cos-sin",
    "Edge shape odd-sin-cos": "Форма границы odd-sin-cos",
    "Edge shape even-cos-cos": "Форма границы even-cos-cos",
    "Edge shape even-sin-sin": "Форма границы even-sin-sin",
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
    "paper": "статья",
    "exact": "точная",
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
    "(used by the paper's eqs. 32-45 and its Fig. 8), and exact, the true damped oscillator "
    "with frequency Omega_i = sqrt(omega_i^2 - gamma^2) and its over- and critically damped "
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
}

PATTERNS: list[tuple[str, object]] = [
    (
        r"The paper's Fig\.~(\d+) redrawn: (.*)",
        r"Рис.~\1 статьи, перестроенный: \2",
    ),
]
