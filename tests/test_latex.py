"""Golden strings for the LaTeX value type and its helpers (reports/latex.py).

Every expected string below is written out by hand from the LaTeX it must produce; a change in the
output format shows up here first.
"""

from fractions import Fraction

import pytest
import sympy as sp

from reports import latex as L
from reports.latex import Latex, raw


@pytest.mark.parametrize(
    "plain, expected",
    [
        ("plain words", "plain words"),
        ("50% & #1", r"50\% \& \#1"),
        ("a_1 {b}", r"a\_1 \{b\}"),
        ("x^2", r"x$^\wedge$2"),
        ("~ | < > \\", r"$\sim$ $|$ $<$ $>$ $\backslash$"),
        ("$5", r"\$5"),
        ("γ ≥ 0 – π", r"$\gamma$ $\geq$ 0 -- $\pi$"),
        ("snow \u2603", "snow [U+2603]"),
    ],
)
def test_text_escapes(plain, expected):
    assert str(L.text(plain)) == expected


def test_text_is_ascii_for_any_input():
    s = "".join(chr(c) for c in range(32, 0x3000, 7))
    assert str(L.text(s)).isascii()


@pytest.mark.parametrize(
    "plain, expected",
    [
        ("omega_av T/2 = n pi", r"$\omega_{av}$ T/2 = n $\pi$"),
        ("omega1 and T0", r"$\omega_{1}$ and $T_{0}$"),
        ("(1-m)^2 and x^(a+b)", r"(1-m)$^{2}$ and $x^{a+b}$"),
        ("3*m**2", r"3$\cdot$$m^{2}$"),
        ("sqrt(2/(a^2 + b^2))", r"$\sqrt{2/(a^{2} + b^{2})}$"),
        ("1 <= a < b, r > 0", r"1 $\le$ a $<$ b, r $>$ 0"),
        ("F_+ + F_- = 2 f(x)", r"$F_{+}$ + $F_{-}$ = 2 f(x)"),
        ("e^(-gamma t)", r"$e^{-\gamma  t}$"),
        ("no formulas here.", "no formulas here."),
        ("100% sure", r"100\% sure"),
    ],
)
def test_prose(plain, expected):
    assert str(L.prose(plain)) == expected


@pytest.mark.parametrize(
    "src, expected",
    [
        ("printed $q^2$ where omega_1 gives $q$", r"printed $q^2$ where $\omega_{1}$ gives $q$"),
        ("no math", "no math"),
        ("costs $5", r"costs \$5"),
        # a range of equations takes an en dash in the text, not inside a formula
        ("the printed (22)-(23) and $x-(1)$", r"the printed (22)--(23) and $x-(1)$"),
    ],
)
def test_mixed(src, expected):
    assert str(L.mixed(src)) == expected


def test_latex_value_type():
    a = Latex("a")
    assert a + "b & c" == Latex(r"ab \& c")
    assert "x_1" + a == Latex(r"x\_1a")
    assert a.wrap() == Latex("{a}")
    assert a.paren() == Latex(r"\left(a\right)")
    assert Latex(", ").join([raw("$x$"), "y_2"]) == Latex(r"$x$, y\_2")
    assert Latex("").empty and not a.empty
    with pytest.raises(TypeError):
        a + 3  # noqa: B018


def test_math_uses_config():
    x = sp.Symbol("omega_1")
    assert L.math(x / 2) == Latex(r"\frac{\omega_{1}}{2}")
    assert L.math(sp.log(x)) == Latex(r"\ln{\left(\omega_{1} \right)}")
    assert L.inline(L.math(x)) == Latex(r"$\omega_{1}$")
    assert L.math(raw("as is")) == Latex("as is")


@pytest.mark.parametrize(
    "value, expected",
    [
        (3, "$3$"),
        (Fraction(3, 5), "$3/5$"),
        (Fraction(4, 1), "$4$"),
        (0.5, "$0.5$"),
        (1.5e-30, r"$1.5\cdot 10^{-30}$"),
        (float("nan"), "--"),
        (float("inf"), r"$\infty$"),
    ],
)
def test_number(value, expected):
    assert str(L.number(value)) == expected


def test_number_refuses_bool():
    with pytest.raises(TypeError):
        L.number(True)


@pytest.mark.parametrize(
    "src, width",
    [
        ("x + y", 3),
        (r"\frac{a}{b}", 2),
        (r"\frac{abc}{d} + 1", 6),
        (r"\left(x\right)", 3),
        (r"\omega_{1}", 3),
        (r"\cos{\left(x \right)}", 4),
    ],
)
def test_visible_width(src, width):
    assert L.visible_width(src) == width


def test_commands_and_environments():
    assert L.command("section", "A_1") == Latex(r"\section{A\_1}")
    assert L.command("includegraphics", raw("f.pdf"), optional=raw("width=2cm")) == Latex(
        r"\includegraphics[width=2cm]{f.pdf}"
    )
    assert L.environment("center", "hi") == Latex("\\begin{center}\nhi\n\\end{center}")
    assert L.environment("tabular", raw("x"), raw("ll")) == Latex(
        "\\begin{tabular}{ll}\nx\n\\end{tabular}"
    )
    assert L.environment("table", raw("x"), optional="htbp") == Latex(
        "\\begin{table}[htbp]\nx\n\\end{table}"
    )
    assert L.section("Model", "sec:m") == Latex(r"\section{Model}\label{sec:m}")
    assert L.section("Sub", level=1) == Latex(r"\subsection{Sub}")
    assert L.ref("Section", "sec:m") == Latex(r"Section~\ref{sec:m}")


def test_paragraph_spacing():
    p = L.paragraph(
        "the period", L.inline(raw("T")), ", the depth (", L.inline(raw("m")), ").", "-th"
    )
    assert p == Latex("the period $T$, the depth ($m$).-th")
    assert L.paragraph("a", "", "b") == Latex("a b")


def test_equation_single_and_tagged():
    x = sp.Symbol("x")
    assert L.equation(sp.Eq(x, 1)) == Latex("\\begin{equation}\nx = 1\n\\end{equation}")
    assert L.equation(x, tag="13") == Latex("\\begin{equation}\nx\\tag{13}\n\\end{equation}")
    assert L.equation(x, numbered=False) == Latex("\\begin{equation*}\nx\n\\end{equation*}")
    assert L.equation(x, label="eq:x") == Latex(
        "\\begin{equation}\nx\\label{eq:x}\n\\end{equation}"
    )


def test_long_formula_is_broken_before_plus_and_equals():
    xs = sp.symbols("a0:30")
    expr = sp.Add(*xs)
    lines = L.math_lines(expr, width=20)
    assert len(lines) > 1
    assert all(L.visible_width(line) <= 20 for line in lines)
    assert all(line.raw.startswith("+ ") for line in lines[1:])
    # the lines together are the sum as printed on one line
    assert " ".join(line.raw for line in lines) == sp.latex(expr)
    eq = sp.Eq(sp.Symbol("y"), expr)
    out = L.equation(eq, config=L.Config(max_width=20))
    assert out.raw.startswith("\\begin{multline}\ny = a_{0} + a_{1}")
    # a side that fits stays whole, and the line breaks before "="
    lhs = sp.Mul(*sp.symbols("b0:6"))
    lines = L.math_lines(sp.Eq(lhs, sp.Mul(*sp.symbols("c0:6"))), width=20)
    assert [line.raw for line in lines] == [
        sp.latex(lhs),
        "= " + sp.latex(sp.Mul(*sp.symbols("c0:6"))),
    ]


def test_series_terms():
    m = sp.Symbol("m")
    expr = sp.Rational(1, 2) - 3 * m / (2 * sp.pi) + m**3 * (sp.pi + 1 / sp.pi)
    terms = [str(t) for t in L.series_terms(expr, m, big_o=4)]
    assert terms == [
        r"\frac{1}{2}",
        r"- \frac{3 m}{2 \pi}",
        r"+ \left(\frac{1}{\pi} + \pi\right) m^{3}",
        r"+ O\left(m^{4}\right)",
    ]


def test_pack():
    pieces = [Latex("aaaa"), Latex("+ bb"), Latex("+ cc"), Latex("+ dddddd")]
    # visible width counts no spaces: "aaaa + bb + cc" is 10 wide
    assert L.pack(pieces, 10) == [Latex("aaaa + bb + cc"), Latex("+ dddddd")]
    assert L.pack(pieces, 9) == [Latex("aaaa + bb"), Latex("+ cc"), Latex("+ dddddd")]


def test_table_golden():
    out = L.table(["a", raw("$b$")], [["1", raw("$2$")]], caption="Cap", label="tab:x")
    assert out == Latex(
        "\\begin{table}[htbp]\n"
        "\\centering\n"
        "\\caption{Cap}\\label{tab:x}\n"
        "\\begin{tabular}{lr}\n"
        "\\toprule\n"
        "a & $b$ \\\\\n"
        "\\midrule\n"
        "1 & $2$ \\\\\n"
        "\\bottomrule\n"
        "\\end{tabular}\n"
        "\\end{table}"
    )


def test_long_table_repeats_header():
    out = L.table(["a", "b"], [["1", "2"]], long=True, caption="C", size="small").raw
    assert out.startswith("{\\small\n\\begin{longtable}{lr}\n\\caption{C}")
    assert out.count("a & b \\\\") == 2 and "\\endhead" in out and "\\endlastfoot" in out


def test_table_rejects_ragged_rows():
    with pytest.raises(ValueError):
        L.table(["a", "b"], [["1"]])


def test_figure_and_lists():
    assert L.figure("f.pdf", "Cap", label="fig:f", width="0.5\\textwidth") == Latex(
        "\\begin{figure}[htbp]\n\\centering\n\\includegraphics[width=0.5\\textwidth]{f.pdf}\n"
        "\\caption{Cap}\\label{fig:f}\n\\end{figure}"
    )
    assert L.itemize(["a", "b_1"]) == Latex(
        "\\begin{itemize}\n\\item a\n\\item b\\_1\n\\end{itemize}"
    )
    assert L.description([("k", "v")]) == Latex(
        "\\begin{description}\n\\item[k] v\n\\end{description}"
    )


def test_document_is_deterministic_and_has_banner():
    cfg = L.Config(packages=(("amsmath", ""),), preamble=())
    doc = L.document([raw("Body.")], title="T", banner="generated -- do not edit", config=cfg)
    assert doc == Latex(
        "% generated -- do not edit\n"
        "\\documentclass[11pt,a4paper]{article}\n"
        "\\usepackage{amsmath}\n"
        "\\title{T}\n\\author{}\n\\date{}\n\n"
        "\\begin{document}\n\\maketitle\n\n\\tableofcontents\n\nBody.\n\\end{document}\n"
    )
    assert doc == L.document(
        [raw("Body.")], title="T", banner="generated -- do not edit", config=cfg
    )


def test_config_is_frozen():
    with pytest.raises(AttributeError):
        L.DEFAULT.max_width = 3  # type: ignore[misc]
