"""The package's one LaTeX printer, in the notation of Popov (2017).

* symbols: ``E_star`` -> E^{*}, ``gamma`` -> \\gamma_{12}, ``Z_n`` -> Z_{n};
* complete elliptic integrals with the *modulus* k, as in Popov (2017),
  Eqs. (26)-(28): SymPy's ``elliptic_k(m)`` takes the parameter m = k**2, so
  ``elliptic_k(a**2/R**2)`` prints as K(a/R) and ``elliptic_e(m)`` as E(k);
* inverse trigonometric functions as \\arcsin, \\arccos, ...

It lives in ``core`` because every layer shows expressions (``_repr_latex_``
of derivations and contacts, reports, tables, the CLI).
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
    return PaperLatexPrinter(settings).doprint(to_basic(expr))


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


__all__ = ["PaperLatexPrinter", "to_latex", "latex_escape"]
