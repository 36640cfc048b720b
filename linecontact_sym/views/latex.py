"""LaTeX views: booktabs tables, standalone documents and a well-formedness
check.  Expressions are printed by the package's one printer,
:func:`linecontact_sym.core.printing.to_latex` (re-exported here).

Tables are booktabs tables (``\\toprule``, ``\\midrule``, ``\\bottomrule``)
that compile with a standard LaTeX installation (packages ``booktabs`` and
``amsmath``); :func:`standalone` wraps any body into a complete document.
"""
from __future__ import annotations

import re

from ..core.printing import PaperLatexPrinter, latex_escape, to_latex


_IDENT = r"[A-Za-z_][A-Za-z0-9_]*"
_NUMBER = r"\d+(?:\.\d+)?(?:[eE][-+]?\d+)?"
_IDENT_RE = re.compile(_IDENT)
_OPS = ("**", "!=", "<=", ">=", "*", "/", "+", "-", "<", ">", "=", "^")
_RELATIONS = {"!=": r"\neq", "<=": r"\le", ">=": r"\ge", "<": "<", ">": ">", "=": "="}
_SPECIAL = {"E*\u00b7a\u00b7f'(0+)": "E^{*} a f'(0^{+})", "f'(0+)": "f'(0^{+})", "E*": "E^{*}"}


def _group(text, i):
    """End of the balanced parenthesis group starting at ``text[i] == '('`` (or -1)."""
    depth = 0
    for j in range(i, len(text)):
        if text[j] == "(":
            depth += 1
        elif text[j] == ")":
            depth -= 1
            if depth == 0:
                return j + 1
    return -1


def _atom(text, i):
    """End of an operand starting at i: [-]name[(...)] | [-]number | [-](...) ; -1 if none."""
    j = i
    if j < len(text) and text[j] == "-":
        j += 1
    for sp_, tex in _SPECIAL.items():
        if text.startswith(sp_, j):
            return j + len(sp_)
    m = re.compile(_NUMBER).match(text, j) or re.compile(_IDENT).match(text, j)
    if m:
        j = m.end()
        if j < len(text) and text[j] == "'":
            j += 1
        if j < len(text) and text[j] == "(" and m.group(0)[0].isalpha():
            k = _group(text, j)
            if k < 0:
                return -1
            j = k
        return j
    if j < len(text) and text[j] == "(":
        return _group(text, j)
    return -1


def _math_span(text, i):
    """(end, n_operators) of the formula starting at i, or (-1, 0)."""
    end = _atom(text, i)
    if end < 0:
        return -1, 0
    nops = 1 if text[i] == "-" else 0
    while True:
        k = end
        while k < len(text) and text[k] == " ":
            k += 1
        op = next((o for o in _OPS if text.startswith(o, k)), None)
        if op is None:
            return end, nops
        k += len(op)
        while k < len(text) and text[k] == " ":
            k += 1
        nxt = _atom(text, k)
        if nxt < 0:
            return end, nops
        end, nops = nxt, nops + 1


def _formula_tex(span):
    """LaTeX of a formula typed in SymPy syntax (relations split at =, !=, <, ...)."""
    import re
    from ..parsing import parse_expr
    parts = re.split(r"\s*(!=|<=|>=|<|>|=)\s*", span)
    out = []
    for k, part in enumerate(parts):
        if k % 2:
            out.append(_RELATIONS[part])
            continue
        if part in _SPECIAL:
            out.append(_SPECIAL[part])
            continue
        if re.fullmatch(r"-?" + _NUMBER, part):      # a number stays as written (0.3141, not 3141/10000)
            out.append(part)
            continue
        try:
            expr = parse_expr(part, where="report")
        except Exception:  # noqa: BLE001 -- short undeclared names (k, w1) are symbols; words are not
            names = sorted(set(re.findall(_IDENT, part)))
            try:
                expr = parse_expr(part, symbols=[n for n in names if len(n) <= 2 or ("_" in n and len(n) <= 6)], where="report")
            except Exception:  # noqa: BLE001 -- not a formula after all
                return None
        out.append(to_latex(expr))
    return " ".join(out)


def text_to_latex(text: str) -> str:
    r"""A message with formulas in SymPy syntax (a verdict, a condition, a
    note) as LaTeX text: every formula is parsed (whitelisted parser) and
    printed by :func:`to_latex` in ``$...$``, the rest is escaped.  A formula
    is a chain of operands joined by operators (``n != 1``,
    ``x**2/(2*R)``, ``a = 0.25``); a lone word stays text, except names with
    an underscore (``E_star``) and calls (``gamma(n/2)``).

    >>> print(text_to_latex("holds under a condition: n != 1 and E_star*a > 0; 3*pi/4"))
    holds under a condition: $n \neq 1$ and $E^{*} a > 0$; $\frac{3 \pi}{4}$
    >>> print(text_to_latex("only where f'(0+) = 0 (50% of cases)"))
    only where $f'(0^{+}) = 0$ (50\% of cases)
    """
    out, i, plain = [], 0, []
    text = str(text)
    while i < len(text):
        start_ok = i == 0 or not (text[i - 1].isalnum() or text[i - 1] in "_.")
        end, nops = _math_span(text, i) if start_ok else (-1, 0)
        if end > i:
            span = text[i:end]
            word = span.lstrip("-")
            is_math = nops > 0 or "_" in word or word.endswith(")") or word in _SPECIAL
            if span.startswith("-") and nops == 1 and not ("_" in word or word.endswith(")")):
                is_math = i == 0 or text[i - 1] in " (=,"
            tex = _formula_tex(span) if is_math else None
            if tex is not None:
                out.append(latex_escape("".join(plain)))
                plain = []
                out.append(f"${tex}$")
                i = end
                continue
            w = _IDENT_RE.match(text, i)
            if w:                           # a word that is not a formula: skip it whole
                plain.append(w.group(0))
                i = w.end()
                continue
        plain.append(text[i])
        i += 1
    out.append(latex_escape("".join(plain)))
    return "".join(out)


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


#: the preamble of every document written (standard packages of any LaTeX installation)
PREAMBLE = [r"\documentclass[10pt,a4paper]{article}",
            r"\usepackage{amsmath,amssymb}", r"\usepackage{booktabs}", r"\usepackage{longtable}",
            r"\usepackage{array}", r"\usepackage{graphicx}", r"\usepackage[margin=2.2cm]{geometry}",
            # a display formula shrinks to the line width where it would not fit, never grows
            r"\newsavebox{\fitbox}",
            r"\newcommand{\fitmath}[1]{\sbox{\fitbox}{$\displaystyle #1$}\ifdim\wd\fitbox>\linewidth"
            r"\resizebox{\linewidth}{!}{\usebox{\fitbox}}\else\usebox{\fitbox}\fi}",
            r"\renewcommand{\arraystretch}{1.3}", r"\AtBeginDocument{\setlength{\LTcapwidth}{\textwidth}}"]


def fit_math(tex: str) -> str:
    """A formula (LaTeX, no ``$``) set in display style, shrunk to the line
    width if it is wider (``\\fitmath`` of :data:`PREAMBLE`)."""
    return r"\fitmath{%s}" % tex


def visible_length(tex: str) -> int:
    """A rough printed width of a LaTeX formula: its characters without the
    command names and braces (``\\frac{a}{b}`` counts 2)."""
    return len(re.sub(r"\\[a-zA-Z]+|[{}\s]", "", tex))


def wrapped_latex(expr, width: int = 80) -> str:
    r"""LaTeX of ``expr`` (the package's printer) whole, broken into lines of
    about ``width`` printed characters where it is longer: a sum at its top
    level terms (an ``aligned`` block, the continued lines indented), a
    product around its longest sum factor (``\Bigl( ... \Bigr)``), each
    case of a Piecewise.  A
    formula is never cut: the lines together are the whole expression.

    >>> import sympy as sp
    >>> t = sp.symbols("t0:12")
    >>> tex = wrapped_latex(sum(ti**2 for ti in t), width=30)
    >>> tex.count(r"\\"), tex.startswith(r"\begin{aligned}")
    (2, True)
    """
    import sympy as sp
    from ..core.conversion import to_basic
    expr = to_basic(expr)
    whole = to_latex(expr)
    if visible_length(whole) <= width or not isinstance(expr, sp.Expr):
        return whole
    if isinstance(expr, sp.Piecewise):
        rows = [wrapped_latex(e, width - 20) + r" & " + (r"\text{otherwise}" if c == sp.true
                                                         else r"\text{for}\: " + to_latex(c))
                for e, c in expr.args]
        return r"\begin{cases} " + r" \\ ".join(rows) + r" \end{cases}"
    if isinstance(expr, sp.Add):
        return r"\begin{aligned}&" + r" \\ &\quad ".join(_lines(expr, width)) + r"\end{aligned}"
    if isinstance(expr, sp.Mul):
        sums = [f for f in expr.args if isinstance(f, sp.Add)]
        if sums:
            big = max(sums, key=lambda f: len(to_latex(f)))
            rest = expr / big
            sign = "-" if rest.could_extract_minus_sign() else ""
            rest = -rest if sign else rest
            head = "" if rest == 1 else to_latex(rest)
            lines = _lines(big, width)
            return (r"\begin{aligned}&" + sign + head + r"\Bigl(" + r" \\ &\quad ".join(lines) + r"\Bigr)"
                    + r"\end{aligned}")
    return whole


def _lines(add, width: int = 80) -> list:
    """The terms of a sum, signed, gathered into lines of about ``width``."""
    lines, cur = [], ""
    for i, t in enumerate(add.as_ordered_terms()):
        neg = t.could_extract_minus_sign()
        tex = to_latex(-t if neg else t)
        if t.is_Add or (neg and (-t).is_Add):
            tex = rf"\left({tex}\right)"
        piece = ("- " if neg else ("" if i == 0 else "+ ")) + tex
        if cur and visible_length(cur + piece) > width:
            lines.append(cur.rstrip())
            cur = ""
        cur += piece + " "
    lines.append(cur.rstrip())
    return lines


def standalone(body: str, title: str | None = None, landscape: bool = False) -> str:
    """A complete LaTeX document around ``body`` (article, A4, booktabs,
    longtable, amsmath, graphicx; :data:`PREAMBLE`)."""
    head = list(PREAMBLE)
    if landscape:
        head = [h.replace("]{geometry}", ",landscape]{geometry}") for h in head]
    head.append(r"\begin{document}")
    if title:
        head.append(f"\\section*{{{latex_escape(title)}}}")
    return "\n".join(head) + "\n" + body + "\n\\end{document}\n"


def longtable(header, rows, *, align: str, caption: str | None = None, label: str | None = None,
              size: str | None = None) -> str:
    """A booktabs ``longtable`` (breaks across pages; the header repeats);
    cells are LaTeX already; rows are separated by a little space."""
    ncol = len(header)
    head = " & ".join(header) + r" \\"
    parts = []
    if size:
        parts.append("{\\" + size)
    parts.append(f"\\begin{{longtable}}{{{align}}}")
    if caption:
        parts.append(f"\\caption{{{caption}}}" + (f"\\label{{{label}}}" if label else "") + r" \\")
    parts += [r"\toprule", head, r"\midrule", r"\endfirsthead",
              r"\toprule", head, r"\midrule", r"\endhead",
              r"\bottomrule", r"\endfoot"]
    for r in rows:
        if len(r) != ncol:
            raise ValueError(f"row {r!r} has {len(r)} cells, the header {ncol}")
        parts.append(" & ".join(str(c) for c in r) + r" \\ \addlinespace[2pt]")
    parts.append(r"\end{longtable}")
    if size:
        parts.append("}")
    return "\n".join(parts)


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
    for m in re.finditer(r"\\begin\{(?:tabular|longtable)\}(.*?)\\end\{(?:tabular|longtable)\}", clean, re.S):
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


__all__ = ["to_latex", "latex_escape", "text_to_latex", "wrapped_latex", "visible_length", "booktabs_table", "longtable", "standalone",
           "fit_math", "check_latex", "PaperLatexPrinter", "PREAMBLE"]
