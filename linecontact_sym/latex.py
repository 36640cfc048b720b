"""LaTeX views of derived results, in the paper's notation (E^*, gamma_12,
K and E with the modulus k)."""
from __future__ import annotations

import sympy as sp

from . import symbols as S


def to_latex(expr) -> str:
    """LaTeX of a SymPy expression with the paper's symbol names."""
    return sp.latex(expr, symbol_names=S.LATEX_NAMES)
