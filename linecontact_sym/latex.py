"""LaTeX views of derived results, in the paper's notation.

* symbols: ``E_star`` -> E^{*}, ``gamma`` -> \\gamma_{12}, ``Z_n`` -> Z_{n};
* complete elliptic integrals with the *modulus* k, as in Popov (2017),
  Eqs. (26)-(28): SymPy's ``elliptic_k(m)`` takes the parameter m = k**2, so
  ``elliptic_k(a**2/R**2)`` prints as K(a/R) and ``elliptic_e(m)`` as E(k);
* inverse trigonometric functions as \\arcsin, \\arccos, ...

Tables are booktabs tables (``\\toprule``, ``\\midrule``, ``\\bottomrule``)
that compile with a standard LaTeX installation (packages ``booktabs`` and
``amsmath``); :func:`standalone` wraps any body into a complete document.
"""
from __future__ import annotations

import sympy as sp
from sympy.printing.latex import LatexPrinter

from .parsing import to_sympy
from . import symbols as S


class PaperLatexPrinter(LatexPrinter):
    """SymPy's LaTeX printer with the notation of Popov (2017)."""

    def __init__(self, settings=None):
        settings = dict(settings or {})
        names = {**S.LATEX_NAMES, **settings.pop("symbol_names", {})}
        settings.setdefault("inv_trig_style", "full")
        super().__init__({"symbol_names": names, **settings})

    @staticmethod
    def _modulus(m):
        k = sp.sqrt(m)
        if isinstance(k, sp.Pow) and k.exp == sp.S.Half and not k.base.is_Symbol:
            k2 = sp.powdenest(sp.sqrt(sp.factor(m)), force=False)
            k = k2 if sp.count_ops(k2) <= sp.count_ops(k) else k
        return k

    def _print_elliptic_k(self, expr, exp=None):
        tex = r"K\!\left(%s\right)" % self._print(self._modulus(expr.args[0]))
        return tex if exp is None else r"K^{%s}\!\left(%s\right)" % (exp, self._print(self._modulus(expr.args[0])))

    def _print_elliptic_e(self, expr, exp=None):
        if len(expr.args) != 1:
            return super()._print_elliptic_e(expr, exp)
        k = self._print(self._modulus(expr.args[0]))
        return r"E\!\left(%s\right)" % k if exp is None else r"E^{%s}\!\left(%s\right)" % (exp, k)

    def _print_Symbol(self, expr, style="plain"):
        if expr.name == "Z_n":
            return "Z_{n}"
        return super()._print_Symbol(expr, style)


def to_latex(expr, **settings) -> str:
    """LaTeX of a SymPy expression in the paper's notation.

    >>> import sympy as sp, linecontact_sym as lcs
    >>> m = lcs.a**2/lcs.R**2
    >>> print(to_latex(lcs.E_star*lcs.R*(sp.elliptic_k(m) - sp.elliptic_e(m))))
    E^{*} R \\left(- E\\!\\left(\\frac{a}{R}\\right) + K\\!\\left(\\frac{a}{R}\\right)\\right)
    """
    if isinstance(expr, str):
        return latex_escape(expr)
    return PaperLatexPrinter(settings).doprint(to_sympy(expr))


_ESCAPES = {"\\": r"\textbackslash{}", "&": r"\&", "%": r"\%", "$": r"\$", "#": r"\#",
            "_": r"\_", "{": r"\{", "}": r"\}", "~": r"\textasciitilde{}", "^": r"\textasciicircum{}"}


def latex_escape(text) -> str:
    """Escape plain text for LaTeX (``&``, ``%``, ``_``, braces, ...)."""
    text = str(text)
    out = "".join(_ESCAPES.get(ch, ch) for ch in text)
    for u, tex in (("\u2264", r"$\le$"), ("\u2265", r"$\ge$"), ("\u2260", r"$\ne$"), ("\u03c0", r"$\pi$"),
                   ("\u2192", r"$\to$"), ("\u00b7", r"$\cdot$"), ("\u2248", r"$\approx$"), ("\u2212", "-"),
                   ("\u2014", "---"), ("\u2013", "--")):
        out = out.replace(u, tex)
    return out


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
