"""LaTeX views: the paper's notation, booktabs tables that are well-formed
(and compile where a LaTeX installation exists)."""
import shutil
import subprocess

import pytest
import sympy as sp

import linecontact_sym as lcs
from linecontact_sym.claims import check as C
from linecontact_sym.claims.batch import check_paper
from linecontact_sym.claims.results import FAILS, HOLDS, HOLDS_IF
from linecontact_sym.claims.spec import paper_from_dict
from linecontact_sym.views.latex import booktabs_table, check_latex, latex_escape, standalone, to_latex
from linecontact_sym.claims.report import latex_report, markdown_report, power_law_latex, power_law_rows


def test_readable_term_order_and_joined_roots():
    a, x, R, E, g = lcs.a, lcs.x, lcs.R, lcs.E_star, lcs.gamma
    assert to_latex(sp.sqrt(x**2 - a**2)) == r"\sqrt{x^{2} - a^{2}}"
    assert to_latex(-sp.sqrt(2 * sp.pi * E * a * g) + sp.pi * E * a**2 / (4 * R)) == \
        r"\frac{\pi E^{*} a^{2}}{4 R} - \sqrt{2 \pi E^{*} a \gamma_{12}}"


def test_text_to_latex_turns_messages_into_latex():
    from linecontact_sym.views.latex import text_to_latex
    assert text_to_latex("n > 1/2 and n != 1") == r"$n > \frac{1}{2}$ and $n \neq 1$"
    assert text_to_latex("profile x**2/(2*R), E_star") == r"profile $\frac{x^{2}}{2 R}$, $E^{*}$"
    assert text_to_latex("1 -> n = 2 (a < b | c)") == r"1 $\to$ $n = 2$ ($a < b$ \textbar{} c)"
    assert text_to_latex("the adhesion_force holds") == r"the adhesion\_force holds"


def test_paper_notation():
    m = lcs.a**2 / lcs.R**2
    tex = to_latex(lcs.E_star * lcs.R * (sp.elliptic_k(m) - sp.elliptic_e(m)))
    assert "E^{*}" in tex
    assert r"K\!\left(\frac{a}{R}\right)" in tex and r"E\!\left(\frac{a}{R}\right)" in tex  # modulus k = a/R
    assert r"\gamma_{12}" in to_latex(sp.sqrt(2 * sp.pi * lcs.a * lcs.gamma * lcs.E_star))
    assert "Z_{n}" in to_latex(sp.Symbol("Z_n") * lcs.c)
    assert r"\arcsin" in to_latex(sp.asin(lcs.b / lcs.a))
    assert r"\Gamma" in to_latex(sp.gamma(lcs.n / 2))


def test_derived_objects_render_in_notebooks():
    d = lcs.parabola(budget=5).derivation("force")
    assert d._repr_latex_().startswith("$") and r"\pi" in d._repr_latex_()


def test_escape():
    assert latex_escape("a_b & 50% #1 {x}") == r"a\_b \& 50\% \#1 \{x\}"
    assert check_latex(latex_escape(r"\weird{ text")) == []


def test_booktabs_table_is_well_formed():
    tab = booktabs_table(["n", "value"], [["$1$", "$x_{1}$"], ["$2$", r"$\frac{1}{2}$"]],
                         caption="A caption with 50\\% text", label="tab:x")
    assert check_latex(tab) == []
    for rule in (r"\toprule", r"\midrule", r"\bottomrule"):
        assert tab.count(rule) == 1
    assert r"\hline" not in tab
    with pytest.raises(ValueError):
        booktabs_table(["a", "b"], [["1"]])


@pytest.mark.parametrize("bad, problem", [
    (r"\begin{tabular}{l}\toprule a \\ \bottomrule\end{tabular}", "midrule"),
    (r"\begin{tabular}{l}\hline a \\ \toprule\midrule\bottomrule\end{tabular}", "hline"),
    (r"{\frac{1}{2}", "unclosed brace"),
    (r"\frac{1}{2}}", "closing brace"),
    (r"\begin{table}x\end{tabular}", "does not match"),
    (r"$\left( x$", "unbalanced"),
    (r"$x", "odd number of $"),
])
def test_check_latex_finds_problems(bad, problem):
    assert any(problem in p for p in check_latex(bad))


def test_power_law_table():
    rows, Z, d = power_law_rows([1, 2, 3, 4, 5, 6, 10], budget=5)
    assert [r["Z"] for r in rows] == [1, sp.pi / 2, 2, 3 * sp.pi / 4, sp.Rational(8, 3), 15 * sp.pi / 16,
                                      315 * sp.pi / 256]
    tex = power_law_latex(rows)
    assert check_latex(tex) == []
    assert r"\frac{315 \pi}{256}" in tex and "E^{*}" in tex


def _small_result():
    paper = paper_from_dict({
        "key": "demo", "title": "Demo & test_paper",
        "definitions": {"Z_n": "(n - 1)*sqrt(pi)*gamma(n/2 - 1/2)/(2*gamma(n/2))"},
        "claims": [
            {"label": "Eq. (13)", "title": "parabola", "quantity": "force", "profile": "x**2/(2*R)",
             "formula": "pi*E_star*a**2/(4*R)", "points": 2},
            {"label": "Eq. (17)", "title": "Z_n", "quantity": "Z_n", "profile": "c*x**n",
             "formula": "Z_n", "special": {"n": ["1"]}, "points": 2},
            {"label": "wrong", "title": "a wrong wedge law", "quantity": "force", "profile": "x*tan(theta)",
             "formula": "E_star*a", "points": 2},
            {"label": "Table 1", "title": "table", "quantity": "Z_n", "profile": "c*x**n", "values": ["1", "pi/2"]},
        ]}, "demo.toml")
    return check_paper(paper, budget=5)


def test_reports_are_well_formed():
    result = _small_result()
    assert [r.status for r in result.results] == [HOLDS, HOLDS_IF, FAILS, HOLDS]
    tex = latex_report(result, power_law_latex(power_law_rows([1, 2], budget=5)[0]))
    assert check_latex(tex) == []
    assert r"\documentclass" in tex and r"\usepackage{booktabs}" in tex
    assert "Z_{n}" in tex                               # printed forms keep the paper's names
    # no Python syntax: verdicts, conditions and formulas are LaTeX
    body = tex[tex.index(r"\begin{document}"):]
    for py in ("**", "!=", "E_star", "sqrt(", "3*pi", "x**2", "->"):
        assert py not in body, py
    assert r"n \neq 1" in body and "modulus~$k$" in body        # the condition, the elliptic convention
    assert r"\caption{The claims of Demo" in body
    md = markdown_report(result)
    assert "| Eq. (13) |" in md and "does not hold" in md
    assert result._repr_markdown_().startswith("| claim |")


@pytest.mark.skipif(shutil.which("pdflatex") is None, reason="pdflatex not installed")
def test_tables_compile(tmp_path):
    result = _small_result()
    rows = power_law_rows([1, 2, 4, 5, 6, 10], budget=5)[0]
    for name, doc in (("table", standalone(power_law_latex(rows))),
                      ("report", latex_report(result, power_law_latex(rows)))):
        src = tmp_path / f"{name}.tex"
        src.write_text(doc)
        proc = subprocess.run(["pdflatex", "-interaction=nonstopmode", "-halt-on-error", src.name],
                              cwd=tmp_path, capture_output=True, text=True, timeout=120)
        assert proc.returncode == 0, proc.stdout[-2000:]
        assert (tmp_path / f"{name}.pdf").exists()


def test_derivation_repr_is_a_few_lines_with_formula_status_and_time():
    """Issue 23: a tangential derivation printed a multi-thousand-character
    dataclass dump; now the formula, the status and the timing."""
    t = lcs.TangentialLineContact(lcs.parabola(budget=5))
    d = t.derivation("tangential_force")
    text = repr(d)
    assert len(text.splitlines()) <= 4 and len(text) < 400, text
    assert str(d.expr) in text and "verified at 5 points" in text and "derived in" in text
    tex = d._repr_latex_()
    assert tex.startswith("$") and tex.endswith("$") and r"\mathrm{tangential\_force}" in tex
    assert r"\mu" in tex and "verified at 5 points" in tex


def test_long_formulas_are_wrapped_whole():
    """Issue 23: reports never cut a formula: a long sum breaks at its terms into
    lines of about the width; the lines hold every term; Piecewise keeps its cases."""
    from linecontact_sym.views.latex import visible_length, wrapped_latex
    t = sp.symbols("t0:16")
    expr = lcs.E_star * (sum(ti**3 / (ti + 1) for ti in t) - lcs.a)
    tex = wrapped_latex(expr, width=40)
    assert check_latex(f"${tex}$") == []
    body = tex[tex.index(r"\Bigl(") + 6:tex.index(r"\Bigr)")]
    lines = body.split(r" \\ &\quad ")
    assert len(lines) >= 4 and all(visible_length(ln) <= 40 + 12 for ln in lines)
    for ti in t:                                             # every term is there, once
        assert tex.count(to_latex(ti**3 / (ti + 1))) == 1
    short = lcs.pi * lcs.a if hasattr(lcs, "pi") else sp.pi * lcs.a
    assert wrapped_latex(short) == to_latex(short)
    pw = sp.Piecewise((0, lcs.a <= lcs.b), (expr, True))
    assert wrapped_latex(pw, 40).startswith(r"\begin{cases}") and r"\Bigl(" in wrapped_latex(pw, 40)


def test_markdown_report_keeps_the_whole_printed_formula():
    paper = paper_from_dict({
        "key": "demo", "title": "long",
        "claims": [{"label": "long", "title": "a long wrong law", "quantity": "force", "profile": "x**2/(2*R)",
                    "formula": " + ".join(f"E_star*a**{k}/(R**{k - 1}*{k + 1})" for k in range(2, 12)),
                    "points": 1}]}, "demo.toml")
    result = check_paper(paper, budget=5)
    md = markdown_report(result)
    printed = paper.claims[0].forms[0].text
    assert f"`{printed}`" in md and len(printed) > 150
    assert r"\begin{aligned}" in md
