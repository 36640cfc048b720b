"""Reports of a paper check: a text table for the terminal, Markdown, LaTeX
(booktabs), the power-law table (Table 1 of Popov 2017) and the JSON record.

Everything here is a *view* of :class:`~linecontact_sym.claims.PaperResult`
objects and of derived SymPy expressions.
"""
from __future__ import annotations

import json
from pathlib import Path

import sympy as sp

from ..core import symbols as S
from .results import FAILS, HOLDS, HOLDS_IF, SHORT, UNDECIDED, digits_text, markdown_summary, md_escape
from ..core.conversion import exact_number, nsimplify_basic
from ..core.errors import DomainError
from ..method.profile import MAX_EXPONENT
from ..core.printing import ELLIPTIC_CONVENTION, ELLIPTIC_CONVENTION_TEX
from ..parsing import to_sympy
from ..views.latex import (booktabs_table, fit_math, latex_escape, longtable, standalone, text_to_latex, to_latex,
                           wrapped_latex)

#: printed characters per line of a formula in the reports (verdicts; the claims table's column)
FORMULA_WIDTH, TABLE_FORMULA_WIDTH = 90, 48



# ------------------------------------------------------------------ power-law table
def power_law_rows(ns, budget: float = 20.0):
    """Rows (n, Z_n exact, Z_n numeric, force law) for the exponents ``ns``,
    from the engine's force law of f = c x**n (derived once with symbolic n,
    then evaluated at each exponent)."""
    from .derive import power_law_force
    d = power_law_force(budget)
    Zsym = sp.simplify(sp.gammasimp(d.expr / (S.E_star * S.c * S.a**S.n)))
    rows = []
    for nv in ns:
        nv = exact_number(nv) if isinstance(nv, float) else to_sympy(nv, where="exponent n")
        if not (nv.is_number and nv.is_real and nv > 0):
            raise DomainError(f"the exponent of the power law must be a positive number, got {nv}")
        if not sp.Rational(1, MAX_EXPONENT) <= nv <= MAX_EXPONENT:
            raise DomainError(f"the exponent n = {sp.N(nv, 6)} lies outside 1/{MAX_EXPONENT} .. {MAX_EXPONENT}, the "
                              f"exponents of profiles the package accepts (no physical power law needs more)")
        Z = nsimplify_basic(sp.gammasimp(sp.expand_func(Zsym.subs(S.n, nv))))
        rows.append({"n": nv, "Z": Z, "Z_float": float(sp.N(Z, 20)),
                     "force": S.E_star * S.c * Z * S.a**nv})
    return rows, Zsym, d


def power_law_text(rows) -> str:
    head = f"{'n':>6}  {'Z_n':<18} {'Z_n (numeric)':>20}  force law P(a)"
    lines = [head, "-" * len(head)]
    for r in rows:
        lines.append(f"{str(r['n']):>6}  {str(r['Z']):<18} {r['Z_float']:>20.15f}  {r['force']}")
    return "\n".join(lines)


def power_law_latex(rows, caption=None, label="tab:Zn") -> str:
    """Table 1 of Popov (2017) as a booktabs table: n, Z_n exact and
    numeric, and the force law, with a caption that is a sentence."""
    caption = caption or (r"The coefficient $Z_n$ of the power-law profile $f(x) = c\,|x|^n$ (the paper's "
                          r"$c_n$), defined by the force law $P(a) = E^{*} c\, Z_n a^n$ (Popov 2017, "
                          r"Eqs.~(16)--(17) and Table~1), as derived by \texttt{linecontact\_sym}.")
    body = [[f"${to_latex(r['n'])}$", f"${to_latex(r['Z'])}$", f"${r['Z_float']:.10f}$",
             f"${to_latex(r['force'])}$"] for r in rows]
    return booktabs_table([r"$n$", r"$Z_n$", r"$Z_n$ (numeric)", r"$P(a)$"], body, align="rlll",
                          caption=caption, label=label, escape_header=False)


# ------------------------------------------------------------------ claims reports
def text_table(result, width: int = 110, notes: bool = True) -> str:
    """The terminal report: one row per claim, then (``notes``) the
    conditions and counterexamples."""
    res = result.results
    lab_w = max(8, max((len(r.label) for r in res), default=8))
    head = f"{'claim':<{lab_w}}  {'status':<24} {'digits':>6}  {'time':>7}  quantity"
    lines = [head, "-" * len(head)]
    for r in res:
        lines.append(f"{r.label:<{lab_w}}  {r.status:<24} {digits_text(r):>6}  {r.seconds:6.1f}s  "
                     f"{r.claim.title or r.claim.quantity}")
    counts = {s: sum(r.status == s for r in res) for s in (HOLDS, HOLDS_IF, FAILS, UNDECIDED)}
    lines.append("-" * len(head))
    lines.append(f"{len(res)} claim{'s' if len(res) != 1 else ''}: {counts[HOLDS]} hold, {counts[HOLDS_IF]} hold under a condition, "
                 f"{counts[FAILS]} do not hold, {counts[UNDECIDED]} undecided; {result.seconds:.0f} s")
    notes = [r for r in res if r.status != HOLDS] if notes else []
    if notes:
        lines.append("")
        lines.append("Conditions, counterexamples:")
        for r in notes:
            lines.append(f"  {r.label}: {_wrap(r.verdict, width - 4, '      ')}")
    return "\n".join(lines)


def claim_details_text(result, width: int = 110) -> str:
    """Per claim: the formula as claimed, the derived expression (for every
    claim, failing ones included), the condition, a counterexample for a
    form that does not hold, and the diagnosis of a common mistake."""
    lines = []
    for r in result.results:
        c = r.claim
        lines.append(f"{r.label}: {r.status}")
        for f in c.forms:
            lines.append(f"  claimed:        {f.text}")
        for t in r.targets:
            d = t.derived
            who = f" (for {t.profile_text})" if c.general and t.profile_text else ""
            if d is not None and d.expr is not None and not c.values:
                lines.append(f"  derived{who}:{' ' * max(1, 8 - len(who))}{d.expr}    [{d.method}]")
            if t.error:
                lines.append(f"  undecided{who}: {_wrap(t.error, width - 14, ' ' * 16)}")
            for f in t.forms:
                if f.status == HOLDS_IF and f.condition:
                    lines.append(f"  holds if:       {f.condition}")
                if f.status in (FAILS, HOLDS_IF) and f.counterexample is not None:
                    lines.append("  counterexample: " + _wrap(f.counterexample.describe(), width - 18, " " * 18))
                if f.diagnosis is not None:
                    lines.append("  diagnosis:      " + _wrap(f.diagnosis.message, width - 18, " " * 18))
                    if f.diagnosis.formula:
                        lines.append(f"  corrected:      {f.diagnosis.formula}")
        if r.status == UNDECIDED and not r.targets:
            lines.append("  " + _wrap(r.verdict, width - 2, "    "))
    return "\n".join(lines)


def _wrap(text, width, indent):
    import textwrap
    return textwrap.fill(text, width=width, subsequent_indent=indent, break_long_words=False,
                         break_on_hyphens=False)


def markdown_report(result, figures=(), table_path=None, captions=None) -> str:
    """The full report in Markdown: counts, the claims table, each verdict
    with the derived expressions, Table 1 and the figures (``captions``:
    {file stem: caption sentence})."""
    captions = captions or {}
    paper = result.paper
    res = result.results
    counts = {s: sum(r.status == s for r in res) for s in (HOLDS, HOLDS_IF, FAILS, UNDECIDED)}
    out = [f"# Claims check: {paper.title or paper.key}", ""]
    if paper.reference:
        out += [f"Source: {paper.reference}", ""]
    out += [f"Claims file: `{Path(paper.source).name}`. Each printed formula was compared with the "
            f"quantity derived by `linecontact_sym` at random points with mpmath (45 working digits; "
            f">= 30 agreeing digits required), and symbolically where SymPy can decide.", "",
            f"**{len(res)} claims: {counts[HOLDS]} hold, {counts[HOLDS_IF]} hold under a condition, "
            f"{counts[FAILS]} do not hold, {counts[UNDECIDED]} undecided** ({result.seconds:.0f} s).", "",
            "| claim | result | status | digits | time |", "|---|---|---|---:|---:|"]
    for r in res:
        out.append(f"| {r.label} | {md_escape(r.claim.title)} | {SHORT[r.status]} | {digits_text(r)} | "
                   f"{r.seconds:.1f} s |")
    out += ["", "## Verdicts", ""]
    for r in res:
        c = r.claim
        out.append(f"### {c.label}: {c.title}")
        out.append("")
        if c.forms:
            for f in c.forms:
                out.append(f"- printed: `{f.text}`")
                out += ["", f"  $${wrapped_latex(f.shown, FORMULA_WIDTH)}$$", ""]
        if c.profiles:
            out.append("- profile(s): " + ", ".join(f"`{p}`" for p, _ in c.profiles))
        if c.assumptions:
            out.append("- assumptions: " + ", ".join(f"`{a}`" for a in c.assumptions))
        out.append(f"- **{r.verdict}**")
        for t in r.targets:
            d = t.derived
            if d is not None and d.expr is not None and not c.values:
                who = f" for `{t.profile_text}`" if c.general else ""
                out.append(f"- derived{who}: `{d.expr}` ({d.method})")
                out += ["", f"  $${wrapped_latex(d.expr, FORMULA_WIDTH)}$$", ""]
            for f in t.forms:
                if f.symbolic:
                    out.append(f"  - `{f.form.text}`: symbolic: {f.symbolic}")
                if f.note:
                    out.append(f"  - {md_escape(f.note)}")
        for line in r.details:
            out.append(f"- {line}")
        if c.reading:
            out.append(f"- reading of the transcription: {c.reading}")
        if c.note:
            out.append(f"- note: {c.note}")
        out.append("")
    if table_path:
        out += ["## Table 1", "", f"LaTeX (booktabs): `{Path(table_path).name}`", ""]
    if figures:
        out += ["## Figures", ""]
        for p in figures:
            if str(p).endswith(".png"):
                cap = captions.get(Path(p).stem)
                out.append(f"![{md_escape(cap or Path(p).stem)}]({Path(p).name})")
                if cap:
                    out += ["", f"*{md_escape(cap)}*", ""]
        out.append("")
    return "\n".join(out)


_STATUS_TEX = {HOLDS: "holds", HOLDS_IF: "holds under a condition", FAILS: "\\textbf{does not hold}",
               UNDECIDED: "\\textbf{undecided}"}

#: the conventions every report states (plain text; LaTeX below)
CONVENTIONS = ("E* is the reduced (plane-strain) modulus, E* = E/(1 - nu^2) for a rigid indenter and "
               "1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2 for two elastic bodies; P is the load per unit length "
               "(compressive positive); pull_off_force = P_min < 0, adhesion_force = P_adh = -P_min > 0. "
               + ELLIPTIC_CONVENTION + ".")
CONVENTIONS_TEX = (r"$E^{*}$ is the reduced (plane-strain) modulus, $E^{*} = E/(1-\nu^2)$ for a rigid indenter "
                   r"and $1/E^{*} = (1-\nu_1^2)/E_1 + (1-\nu_2^2)/E_2$ for two elastic bodies; $P$ is the load per "
                   r"unit length (compressive positive); the pull-off load is $P_{\min} < 0$ and the adhesion "
                   r"force $P_{\mathrm{adh}} = -P_{\min} > 0$; $\gamma_{12}$ is the work of adhesion. "
                   + ELLIPTIC_CONVENTION_TEX)


def _status_sentence(r) -> str:
    """The verdict as a LaTeX sentence: status, then condition or counterexample."""
    v = r.verdict
    rest = v.split(": ", 1)[1] if ": " in v and v.split(": ", 1)[0] == r.status else ""
    if r.status == HOLDS:
        rest = v[len(HOLDS):].lstrip(": ").strip().strip("()")
    head = {HOLDS: "Holds", HOLDS_IF: "Holds under a condition", FAILS: "Does not hold",
            UNDECIDED: "Undecided"}[r.status]
    return head + (": " + text_to_latex(rest) if rest else "") + "."


def _centred(tex):
    return "\\begin{center}\n" + tex + "\n\\end{center}"


def latex_report(result, table1: str | None = None, figures=(), captions=None) -> str:
    """The report as a standalone LaTeX document: the conventions, the
    claims (a booktabs longtable), the verdicts with the printed and derived
    formulas in the paper's notation, Table 1 and the figures (PDF) with
    their ``captions`` ({file stem: caption sentence}).  No Python syntax is
    left: formulas go through :func:`to_latex`, messages through
    :func:`~linecontact_sym.views.latex.text_to_latex`."""
    captions = captions or {}
    paper = result.paper
    res = result.results
    counts = {st: sum(r.status == st for r in res) for st in (HOLDS, HOLDS_IF, FAILS, UNDECIDED)}
    intro = [f"{latex_escape(paper.reference)}." if paper.reference else "",
             r"Each formula \emph{as printed} in the paper (transcribed in the claims file "
             f"\\texttt{{{latex_escape(Path(paper.source).name)}}}) was compared with the quantity derived by "
             r"\texttt{linecontact\_sym}: at random points with mpmath (45 working digits, at least 30 agreeing "
             r"digits required) and symbolically where SymPy can decide. "
             f"{len(res)} claims: {counts[HOLDS]} hold, {counts[HOLDS_IF]} hold under a condition, "
             f"{counts[FAILS]} do not hold, {counts[UNDECIDED]} undecided (run time {result.seconds:.0f}~s).",
             r"\paragraph{Notation.} " + CONVENTIONS_TEX]
    rows = []
    for r in res:
        c = r.claim
        formula = (fit_math(wrapped_latex(c.formula.shown, TABLE_FORMULA_WIDTH)) if c.forms
                   else ", ".join(f"${to_latex(v)}$" for _, v in c.values))
        rows.append([latex_escape(c.label), formula, _STATUS_TEX[r.status], digits_text(r), f"{r.seconds:.1f}"])
    table = longtable(["Claim", "Formula as printed", "Status", "Digits", "Time (s)"], rows,
                      align=r"l>{\raggedright\arraybackslash}p{0.50\linewidth}>{\raggedright\arraybackslash}p{0.15\linewidth}rr",
                      caption=latex_escape(f"The claims of {paper.title or paper.key}, checked against the "
                                           f"quantities derived by linecontact_sym: the verdict, the agreeing "
                                           f"digits (at least 30 required) and the time taken."),
                      label="tab:claims", size="small")
    verdicts = [r"\section*{Verdicts}", r"\begin{description}\small"]
    for r in res:
        c = r.claim
        item = [f"\\item[{latex_escape(c.label)}] \\emph{{{text_to_latex(c.title or c.quantity)}.}} "
                + _status_sentence(r)]
        if len(c.forms) > 1:
            for f in c.forms:
                item.append("Printed form:\n" + _centred(fit_math(wrapped_latex(f.shown, FORMULA_WIDTH))))
        if c.profiles and c.general:
            item.append("Test profiles: " + ", ".join(f"${to_latex(p)}$" for _, p in c.profiles) + ".")
        if c.assumptions:
            item.append("Assumptions: " + ", ".join(f"${to_latex(a_)}$" for a_ in c.assumptions) + ".")
        for t in r.targets:
            d = t.derived
            if d is not None and d.expr is not None and not c.values:
                who = f" for $f(x) = {to_latex(d.profile)}$" if c.general and d.profile is not None else ""
                item.append(f"Derived{who}:\n" + _centred(fit_math(wrapped_latex(d.expr, FORMULA_WIDTH))))
            for f in t.forms:
                if f.diagnosis is not None:
                    item.append(r"\emph{Diagnosis:} " + text_to_latex(f.diagnosis.message) + ".")
                if f.note and r.status != HOLDS:
                    item.append(text_to_latex(f.note) + ".")
        for line in r.details:
            item.append(text_to_latex(line) + ".")
        if c.reading:
            item.append(r"\emph{Reading of the transcription:} " + text_to_latex(c.reading))
        if c.note:
            item.append(r"\emph{Note:} " + text_to_latex(c.note))
        verdicts.append("\n".join(item))
    verdicts.append(r"\end{description}")
    figs = []
    for p in figures:
        if str(p).endswith(".pdf"):
            cap = captions.get(Path(p).stem) or f"Figure {Path(p).stem} of the claims file, redrawn."
            figs.append("\\begin{figure}[htbp]\\centering\\includegraphics[width=0.6\\linewidth]{%s}"
                        "\\caption{%s}\\end{figure}" % (Path(p).name, text_to_latex(cap)))
    body = "\n\n".join(["\n\n".join(x for x in intro if x), table] + ([table1] if table1 else [])
                        + ["\n\n".join(verdicts)] + figs)
    return standalone(body, title=f"Claims check: {paper.title or paper.key}")


def write_paper_outputs(result, out_dir, *, figures: bool = True, budget: float = 20.0, drawn=None) -> dict:
    """Write report.md, report.tex, table1.tex, results.json and the paper's
    figures (its ``[[figures]]``, PNG and PDF) into ``out_dir``; returns
    {kind: path or [paths]}.  ``drawn``: the figures' paths where they were
    already drawn into ``out_dir`` (by a worker, while the claims were checked)."""
    out = Path(out_dir)
    out.mkdir(parents=True, exist_ok=True)
    written = {}
    ns = _table1_ns(result)
    t1 = None
    if ns:
        rows, _, _ = power_law_rows(ns, budget=budget)
        t1 = power_law_latex(rows)
        (out / "table1.tex").write_text(t1 + "\n", encoding="utf-8")
        written["table1"] = out / "table1.tex"
    figs = []
    caps = {}
    if figures and result.paper.figures:
        from .figures import captions, draw_figures
        figs = list(drawn) if drawn is not None else draw_figures(result.paper, out, budget=budget)
        caps = captions(result.paper)
        written["figures"] = figs
    (out / "report.md").write_text(markdown_report(result, figs, written.get("table1"), caps), encoding="utf-8")
    written["markdown"] = out / "report.md"
    (out / "report.tex").write_text(latex_report(result, t1, figs, caps), encoding="utf-8")
    written["latex"] = out / "report.tex"
    (out / "results.json").write_text(json.dumps(result.to_dict(), indent=2, default=str), encoding="utf-8")
    written["json"] = out / "results.json"
    return written


def _table1_ns(result):
    """The exponents of the paper's Table 1 as identified by the checker."""
    for r in result.results:
        if r.claim.values and r.claim.quantity == "Z_n":
            ns = []
            for line in r.details:
                if ": n = " in line:
                    try:
                        ns.append(sp.Rational(line.split(": n = ")[1].split()[0].rstrip(",")))
                    except (TypeError, ValueError):
                        pass
            if ns:
                return sorted(set(ns))
    return []


__all__ = ["power_law_rows", "power_law_text", "power_law_latex", "text_table", "claim_details_text", "markdown_report",
           "markdown_summary",
           "latex_report", "write_paper_outputs"]
