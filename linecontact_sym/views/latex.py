"""LaTeX views: booktabs tables, standalone documents and a well-formedness
check.  Expressions are printed by the package's one printer,
:func:`linecontact_sym.core.printing.to_latex` (re-exported here).

Tables are booktabs tables (``\\toprule``, ``\\midrule``, ``\\bottomrule``)
that compile with a standard LaTeX installation (packages ``booktabs`` and
``amsmath``); :func:`standalone` wraps any body into a complete document.
"""
from __future__ import annotations

from ..core.printing import PaperLatexPrinter, latex_escape, to_latex


def booktabs_table(header, rows, *, align: str | None = None, caption: str | None = None,
                   label: str | None = None, float_env: bool = True, size: str | None = None,
                   escape_header: bool = True, notes: str | None = None) -> str:
    """A booktabs table.

    ``header`` is a list of column titles (plain text unless
    ``escape_header=False``); ``rows`` a list of lists of cells already in
    LaTeX (use :func:`to_latex` wrapped in ``$...$`` for formulas and
    :func:`latex_escape` for text)."""
    ncol = len(header)
    for r in rows:
        if len(r) != ncol:
            raise ValueError(f"row {r!r} has {len(r)} cells, the header {ncol}")
    align = align or ("l" * ncol)
    head = " & ".join(latex_escape(h) if escape_header else h for h in header) + r" \\"
    body = "\n".join("  " + " & ".join(str(c) for c in r) + r" \\" for r in rows)
    tab = (f"\\begin{{tabular}}{{{align}}}\n\\toprule\n  {head}\n\\midrule\n{body}\n\\bottomrule\n"
           f"\\end{{tabular}}")
    if notes:
        tab += f"\n\n\\smallskip\\footnotesize {notes}"
    if not float_env:
        return tab
    parts = ["\\begin{table}[htbp]", "\\centering"]
    if size:
        parts.append(f"\\{size}")
    if caption:
        parts.append(f"\\caption{{{caption}}}")
    if label:
        parts.append(f"\\label{{{label}}}")
    parts += [tab, "\\end{table}"]
    return "\n".join(parts)


def standalone(body: str, title: str | None = None) -> str:
    """A complete LaTeX document around ``body`` (article; booktabs, amsmath)."""
    head = ["\\documentclass[10pt]{article}", "\\usepackage[T1]{fontenc}",
            "\\usepackage{amsmath,amssymb}", "\\usepackage{booktabs}", "\\usepackage{longtable}",
            "\\usepackage[margin=2cm,landscape]{geometry}", "\\usepackage{array}", "\\begin{document}"]
    if title:
        head.append(f"\\section*{{{latex_escape(title)}}}")
    return "\n".join(head) + "\n" + body + "\n\\end{document}\n"


def check_latex(text: str) -> list[str]:
    """Well-formedness problems of a LaTeX text (empty list when fine):
    balanced braces (ignoring escaped ones), matched ``\\begin``/``\\end``,
    booktabs rules in every tabular, balanced ``\\left``/``\\right`` and
    ``$`` math delimiters."""
    import re
    problems = []
    depth = 0
    i = 0
    clean = re.sub(r"\\[\\{}$%&#_]", "", text)
    clean = re.sub(r"(?<!\\)%.*", "", clean)
    for ch in clean:
        if ch == "{":
            depth += 1
        elif ch == "}":
            depth -= 1
            if depth < 0:
                problems.append("closing brace without opening brace")
                depth = 0
        i += 1
    if depth:
        problems.append(f"{depth} unclosed brace(s)")
    stack = []
    for m in re.finditer(r"\\(begin|end)\{([^}]*)\}", clean):
        kind, env = m.groups()
        if kind == "begin":
            stack.append(env)
        elif not stack or stack.pop() != env:
            problems.append(f"\\end{{{env}}} does not match")
    if stack:
        problems.append(f"unclosed environment(s): {stack}")
    for m in re.finditer(r"\\begin\{tabular\}(.*?)\\end\{tabular\}", clean, re.S):
        body = m.group(1)
        for rule in ("\\toprule", "\\midrule", "\\bottomrule"):
            if rule not in body:
                problems.append(f"tabular without {rule}")
        if "\\hline" in body:
            problems.append("\\hline in a booktabs table")
    nleft = len(re.findall(r"\\left(?![a-zA-Z])", clean))
    nright = len(re.findall(r"\\right(?![a-zA-Z])", clean))
    if nleft != nright:
        problems.append(f"\\left/\\right unbalanced ({nleft} vs {nright})")
    if clean.count("$") % 2:
        problems.append("odd number of $ math delimiters")
    return problems


__all__ = ["to_latex", "latex_escape", "booktabs_table", "standalone", "check_latex", "PaperLatexPrinter"]
