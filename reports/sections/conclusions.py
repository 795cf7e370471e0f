"""The conclusions: what the derivation established, with the numbers of the summary."""

from __future__ import annotations

from ..i18n import say
from ..latex import Latex, raw
from . import Context, Part
from .summary import findings

TITLE = "Conclusions"
LABEL = "sec:conclusions"


def t(en: str, ru: str) -> Latex:
    return raw(say(en, ru))


def build(ctx: Context) -> Part:
    f = findings(ctx)
    n_rows, n_diff = len(f["rows"]), len(f["differs"])
    cl = f["closings"]
    paras = [
        t(
            rf"Every numbered result of Butikov's paper~\cite{{butikov2}} has been derived from "
            rf"the model --- free oscillations between the jumps, the jump rule, and "
            rf"(anti)periodicity --- and compared with its printed form: {n_rows - n_diff} of "
            rf"{n_rows} agree, {n_diff} do not (Table~\ref{{tab:errata}}). The paper's physics "
            rf"stands: its approximate edges, thresholds and figures are right to the order it "
            rf"claims, once the misprints are corrected.",
            rf"Каждый пронумерованный результат статьи Бутикова~\cite{{butikov2}} выведен из "
            rf"модели --- свободные колебания между скачками, правило скачка и "
            rf"(анти)периодичность --- и сопоставлен с напечатанной формой: {n_rows - n_diff} из "
            rf"{n_rows} совпадают, {n_diff} --- нет (таблица~\ref{{tab:errata}}). Физика статьи "
            rf"верна: её приближённые границы, пороги и рисунки правильны в заявленном порядке, "
            rf"если исправить опечатки.",
        ),
        t(
            rf"Beyond the paper, the closings of the intervals follow one rule with no "
            rf"exceptions ({len(cl)} closings up to order {cl.max_order}); the thresholds with "
            rf"friction have closed forms for every odd and every even order; the two models of "
            rf"friction agree at leading order and part beyond it "
            rf"(Section~\ref{{sec:expansions}}); and the "
            rf"third-order island at $Q = {f['island_Q']}$ is confirmed, with proven ends, close "
            rf"to the depths the paper reads off its figure.",
            rf"Помимо статьи: смыкания интервалов подчиняются одному правилу без исключений "
            rf"({len(cl)} смыканий до порядка {cl.max_order}); пороги с трением имеют замкнутый "
            rf"вид для всех нечётных и всех чётных порядков; две модели трения совпадают в главном "
            rf"порядке и расходятся в следующих (раздел~\ref{{sec:expansions}}); <<остров>> "
            rf"третьего порядка "
            rf"при $Q = {f['island_Q']}$ подтверждён, с доказанными концами, вблизи глубин, "
            rf"которые статья снимает с рисунка.",
        ),
        t(
            r"Numerically, the certified solver is the method of choice past double precision: "
            r"it is faster than plain multiple-precision root finding even with its proof "
            r"(Section~\ref{sec:performance}), while the series in $m$ and the paper's own "
            r"iteration are good only at small depth and, for the iteration, before the first "
            r"closing. The report regenerates itself from the engine with one command; every "
            r"number in it can be re-derived and checked the same way.",
            r"Численно гарантированный решатель --- лучший выбор за пределами двойной точности: "
            r"даже с доказательством он быстрее обычного поиска корня в многократной точности "
            r"(раздел~\ref{sec:performance}), а ряды по $m$ и итерации самой статьи хороши лишь "
            r"при малой глубине модуляции и, для итераций, до первого смыкания. Отчёт "
            r"воспроизводится одной командой; каждое число в нём можно заново вывести и "
            r"проверить тем же путём.",
        ),
    ]
    return Part(Latex("\n\n".join(p.raw for p in paras)))
