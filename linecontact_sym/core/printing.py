"""The package's one LaTeX printer, in the notation of Popov (2017).

* symbols: ``E_star`` -> E^{*}, ``gamma`` -> \\gamma_{12}, ``Z_n`` -> Z_{n};
* ONE elliptic convention, the paper's (and DLMF's): complete elliptic
  integrals K(k), E(k) of the *modulus* k, Popov (2017), Eqs. (26)-(28).
  SymPy's ``elliptic_k(m)`` takes the parameter m = k**2, so
  ``elliptic_k(a**2/R**2)`` prints as K(a/R); every report and table that
  shows one says so (:data:`ELLIPTIC_CONVENTION`);
* readable term order: terms with a minus sign last (``K - E``,
  ``\\sqrt{x^{2} - a^{2}}``), roots of non-negative factors under one root;
* inverse trigonometric functions as \\arcsin, \\arccos, ...

Everything the package shows goes through :func:`to_latex`: the
``_repr_latex_`` of derivations, contacts and claim results, the reports,
the tables and ``derive --format latex``.  ``sympy.latex(expr)`` is SymPy's
own printer (E_{star}, K of the parameter m); call :func:`init_printing` in a
notebook to display bare SymPy expressions with this printer too.

It lives in ``core`` because every layer shows expressions.
"""
from __future__ import annotations

import sympy as sp
from sympy.printing.latex import LatexPrinter

from . import symbols as S
from .conversion import to_basic


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

    def _print_Add(self, expr, order=None):
        """Terms with a leading minus after the others: ``K - E``,
        ``\\sqrt{x^{2} - a^{2}}`` (SymPy's own order would print ``-E + K``)."""
        terms = list(self._as_ordered_terms(expr, order=order))
        pos = [t for t in terms if not t.could_extract_minus_sign()]
        terms = (pos + [t for t in terms if t.could_extract_minus_sign()]) if pos else terms
        tex = ""
        for i, term in enumerate(terms):
            if i == 0:
                pass
            elif term.could_extract_minus_sign():
                tex += " - "
                term = -term
            else:
                tex += " + "
            term_tex = self._print(term)
            if self._needs_add_brackets(term):
                term_tex = r"\left(%s\right)" % term_tex
            tex += term_tex
        return tex

    def _print_Mul(self, expr):
        """Roots of non-negative factors under one root:
        ``\\sqrt{2 \\pi E^{*} a \\gamma_{12}}``, not five square roots in a row
        (likewise cube roots)."""
        groups = {}
        for f in expr.args:
            if isinstance(f, sp.Pow) and f.exp in (sp.S.Half, sp.Rational(1, 3)) and f.base.is_nonnegative:
                groups.setdefault(f.exp, []).append(f)
        groups = {e: fs for e, fs in groups.items() if len(fs) >= 2}
        if not groups:
            return super()._print_Mul(expr)
        names = dict(self._settings.get("symbol_names", {}))
        rest = list(expr.args)
        marks = []
        for e, fs in groups.items():
            inner = self._print(sp.Mul(*[f.base for f in fs]))
            mark = sp.Dummy("root", positive=True)
            names[mark] = (r"\sqrt{%s}" if e == sp.S.Half else r"\sqrt[3]{%s}") % inner
            marks.append(mark)
            rest = [f for f in rest if not any(f is g for g in fs)]
        old = self._settings["symbol_names"]
        self._settings["symbol_names"] = names
        try:
            return super()._print_Mul(sp.Mul(*rest, *marks, evaluate=False))
        finally:
            self._settings["symbol_names"] = old

    def _print_Symbol(self, expr, style="plain"):
        if expr.name == "Z_n":
            return "Z_{n}"
        if expr.name.count("_") > 1 and expr not in self._settings.get("symbol_names", {}):
            return _word(expr.name, r"\mathrm")       # pull_off_force: a name, not p_{ull off force}
        return super()._print_Symbol(expr, style)

    def _hprint_Function(self, func: str) -> str:
        """An undefined function (a placeholder of a quantity without closed
        form: ``maugis_lambda(E_star, R, ...)``, ``pull_off_force(...)``) by its
        name, underscores shown: SymPy's default reads ``maugis_lambda`` as
        maugis with the subscript lambda, ``pull_off_force`` as pull with the
        subscript "off force"."""
        if "_" in func:
            return _word(func, r"\operatorname")
        return super()._hprint_Function(func)


def _word(name: str, command: str) -> str:
    return command + "{" + name.replace("_", r"\_") + "}"


def to_latex(expr, **settings) -> str:
    """LaTeX of a SymPy expression in the paper's notation.

    >>> import sympy as sp, linecontact_sym as lcs
    >>> m = lcs.a**2/lcs.R**2
    >>> print(to_latex(lcs.E_star*lcs.R*(sp.elliptic_k(m) - sp.elliptic_e(m))))
    E^{*} R \\left(K\\!\\left(\\frac{a}{R}\\right) - E\\!\\left(\\frac{a}{R}\\right)\\right)
    >>> print(to_latex(sp.sqrt(lcs.x**2 - lcs.a**2)))
    \\sqrt{x^{2} - a^{2}}
    """
    if isinstance(expr, str):
        return latex_escape(expr)
    return PaperLatexPrinter(settings).doprint(to_basic(expr))


#: the elliptic convention, stated wherever K or E are shown (plain text and LaTeX)
ELLIPTIC_CONVENTION = ("K(k), E(k): complete elliptic integrals of the first and second kind of modulus k "
                       "(SymPy's elliptic_k(m), elliptic_e(m) take the parameter m = k^2)")
ELLIPTIC_CONVENTION_TEX = (r"$K(k)$, $E(k)$: complete elliptic integrals of the first and second kind of "
                           r"modulus~$k$ (SymPy's \texttt{elliptic\_k(m)} and \texttt{elliptic\_e(m)} take the "
                           r"parameter $m = k^2$).")


def init_printing(**kw):
    """Display SymPy expressions in a notebook with this printer (E^{*},
    K(k) of the modulus, readable term order): ``sympy.init_printing`` with
    ``latex_printer=to_latex``; keywords go to it."""
    import sympy as _sp
    _sp.init_printing(latex_printer=to_latex, **kw)


_ESCAPES = {"\\": r"\textbackslash{}", "&": r"\&", "%": r"\%", "$": r"\$", "#": r"\#",
            "_": r"\_", "{": r"\{", "}": r"\}", "~": r"\textasciitilde{}", "^": r"\textasciicircum{}",
            # the default (OT1) font encoding has no < > | in text: they would print as other glyphs
            "<": r"\textless{}", ">": r"\textgreater{}", "|": r"\textbar{}"}


def latex_escape(text) -> str:
    """Escape plain text for LaTeX (``&``, ``%``, ``_``, braces, ...)."""
    text = str(text).replace("->", "\u2192")
    out = "".join(_ESCAPES.get(ch, ch) for ch in text)
    for u, tex in (("\u2264", r"$\le$"), ("\u2265", r"$\ge$"), ("\u2260", r"$\ne$"), ("\u03c0", r"$\pi$"),
                   ("\u2192", r"$\to$"), ("\u00b7", r"$\cdot$"), ("\u2248", r"$\approx$"), ("\u2212", "-"),
                   ("\u2014", "---"), ("\u2013", "--")):
        out = out.replace(u, tex)
    return out


def lambdify(args, expr, modules=None, **kw):
    """``sympy.lambdify`` with every argument renamed to a Dummy of the same
    assumptions first: the generated code names no user symbol, so a
    parameter called ``pi``, ``E``, ``I``, ``lambda``, ``numpy`` or ``sqrt``
    never shadows a constant, a keyword or a module (before: a profile
    parameter named pi made the export of pi*a**2/(4*pi) return a**2/4).
    Every code-generating call of the package with the user's symbols as
    arguments goes through here.

    >>> p, a = sp.Symbol("pi", positive=True), sp.Symbol("a")
    >>> round(lambdify([p, a], sp.pi * a / p, "math")(2.0, 1.0), 12)
    1.570796326795
    """
    single = not isinstance(args, (list, tuple))
    flat = [args] if single else list(args)
    ren = {s: sp.Dummy(s.name if s.name.isidentifier() else "v", **s.assumptions0)
           for s in flat if isinstance(s, sp.Symbol)}
    new = [ren.get(s, s) for s in flat]

    def renamed(e):
        if isinstance(e, sp.Basic):
            with sp.evaluate(False):      # a renaming, not a new expression: nothing re-evaluated
                return e.xreplace(ren)
        if isinstance(e, (list, tuple)):
            return type(e)(renamed(v) for v in e)
        return e
    return sp.lambdify(new[0] if single else new, renamed(expr), modules=modules, **kw)


__all__ = ["lambdify", "PaperLatexPrinter", "to_latex", "latex_escape", "init_printing", "ELLIPTIC_CONVENTION",
           "ELLIPTIC_CONVENTION_TEX"]
