"""The works the report cites, as one ``thebibliography`` list in the report's language.

Each entry is written once; only its descriptive words are translated (:func:`reports.i18n.say`).
Details that the sources themselves do not give (the journal of Part II, the pages of Part I) are
left out rather than guessed.  Checked against the publishers' records: Butikov, Eur. J. Phys. 25
(2004) 535-554 (the torsion pendulum; the journal's DOI record) and Am. J. Phys. 86 (2018) 257-267
(the Mathieu equation; the AIP record); Meissner's title, journal and year as the literature on
the Meissner equation cites them (its volume and pages were not confirmed, so they are left out).
Part I and the simulation program are cited as the paper's own reference list gives them.
"""

from __future__ import annotations

from .i18n import say
from .latex import Latex, raw

__all__ = ["ENTRIES", "bibliography", "cite"]

#: ``(key, English entry, Russian entry)``, LaTeX
ENTRIES: tuple[tuple[str, str, str], ...] = (
    (
        "butikov2",
        r"E.\,I.~Butikov, \emph{Pendulum with modulated length.~II. Regions of parametric "
        r"excitation} (in Russian), Saint Petersburg State University. The paper this report "
        r"derives and checks.",
        r"Е.\,И.~Бутиков, \emph{Маятник с модулируемой длиной.~II. Области параметрического "
        r"возбуждения}, Санкт-Петербургский государственный университет. Статья, которую этот "
        r"отчёт выводит и проверяет.",
    ),
    (
        "butikov1",
        r"E.\,I.~Butikov, \emph{Pendulum with modulated length.~I. Parametric resonance} (in "
        r"Russian), \emph{Computer Tools in Education} (2013); cited as [1] in the paper.",
        r"Е.\,И.~Бутиков, \emph{Маятник с модулируемой длиной.~I. Параметрический резонанс}, "
        r"\emph{Компьютерные инструменты в образовании} (2013); в статье --- ссылка [1].",
    ),
    (
        "butikov-applet",
        r"E.\,I.~Butikov, \emph{Pendulum with a square-wave modulated length} (simulation "
        r"program), \url{http://faculty.ifmo.ru/butikov/Applets/PendParSquare.html}; cited as "
        r"[7] in the paper.",
        r"E.\,I.~Butikov, \emph{Pendulum with a square-wave modulated length} (программа "
        r"моделирования), \url{http://faculty.ifmo.ru/butikov/Applets/PendParSquare.html}; "
        r"в статье --- ссылка [7].",
    ),
    (
        "butikov-square",
        r"E.\,I.~Butikov, \emph{Parametric excitation of a linear oscillator}, European "
        r"Journal of Physics \textbf{25} (2004) 535--554, doi:10.1088/0143-0807/25/4/009: the "
        r"torsion pendulum whose moment of inertia is switched as a square wave.",
        r"E.\,I.~Butikov, \emph{Parametric excitation of a linear oscillator}, European "
        r"Journal of Physics \textbf{25} (2004) 535--554, doi:10.1088/0143-0807/25/4/009: "
        r"крутильный маятник, момент инерции которого переключается прямоугольной волной.",
    ),
    (
        "butikov-mathieu",
        r"E.\,I.~Butikov, \emph{Analytical expressions for stability regions in the Ince--Strutt "
        r"diagram of Mathieu equation}, American Journal of Physics \textbf{86} (2018) 257--267, "
        r"doi:10.1119/1.5021895.",
        r"E.\,I.~Butikov, \emph{Analytical expressions for stability regions in the Ince--Strutt "
        r"diagram of Mathieu equation}, American Journal of Physics \textbf{86} (2018) 257--267, "
        r"doi:10.1119/1.5021895.",
    ),
    (
        "meissner",
        r"E.~Meissner, "
        r"\emph{Ueber Sch{\"u}ttelerscheinungen in Systemen mit periodisch ver{\"a}nderlicher "
        r"Elastizit{\"a}t}, Schweizerische Bauzeitung (1918): the square-wave "
        r"(Meissner) equation.",
        r"E.~Meissner, "
        r"\emph{Ueber Sch{\"u}ttelerscheinungen in Systemen mit periodisch ver{\"a}nderlicher "
        r"Elastizit{\"a}t}, Schweizerische Bauzeitung (1918): уравнение Мейснера "
        r"(прямоугольная модуляция жёсткости).",
    ),
    (
        "sympy",
        r"A.~Meurer et al., \emph{SymPy: symbolic computing in Python}, PeerJ Computer Science "
        r"\textbf{3} (2017) e103; \url{https://www.sympy.org}.",
        r"A.~Meurer et al., \emph{SymPy: symbolic computing in Python}, PeerJ Computer Science "
        r"\textbf{3} (2017) e103; \url{https://www.sympy.org}.",
    ),
    (
        "mpmath",
        r"The mpmath development team, \emph{mpmath: a Python library for arbitrary-precision "
        r"floating-point arithmetic}, \url{https://mpmath.org}.",
        r"The mpmath development team, \emph{mpmath: a Python library for arbitrary-precision "
        r"floating-point arithmetic}, \url{https://mpmath.org}.",
    ),
    (
        "arb",
        r"F.~Johansson, \emph{Arb: efficient arbitrary-precision midpoint-radius interval "
        r"arithmetic}, IEEE Transactions on Computers \textbf{66} (2017) 1281--1292; now part of "
        r"FLINT, \emph{Fast Library for Number Theory}, \url{https://flintlib.org}, used through "
        r"python-flint.",
        r"F.~Johansson, \emph{Arb: efficient arbitrary-precision midpoint-radius interval "
        r"arithmetic}, IEEE Transactions on Computers \textbf{66} (2017) 1281--1292; ныне часть "
        r"FLINT, \emph{Fast Library for Number Theory}, \url{https://flintlib.org}; используется "
        r"через python-flint.",
    ),
)


def cite(*keys: str) -> Latex:
    """``\\cite{a,b}``."""
    known = {k for k, _, _ in ENTRIES}
    for k in keys:
        if k not in known:
            raise KeyError(f"no bibliography entry {k!r}")
    return raw(r"\cite{" + ",".join(keys) + "}")


def bibliography() -> Latex:
    """The list of references (its heading is the document class's, in the report's language)."""
    items = "\n".join(r"\bibitem{" + key + "} " + say(en, ru) for key, en, ru in ENTRIES)
    return Latex(
        r"\begin{thebibliography}{9}"
        + "\n"
        + r"\addcontentsline{toc}{section}{\refname}"
        + "\n"
        + items
        + "\n"
        + r"\end{thebibliography}"
    )
