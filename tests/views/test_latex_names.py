"""Names in LaTeX (issue 42, class 6): a placeholder of a quantity without
closed form (an undefined function such as maugis_lambda(...)) and a symbol
with several underscores print as one name, underscores shown; SymPy's
default reads them as subscripts ("pull" with the subscript "off force")."""
import sympy as sp

import linecontact_sym as lcs
from linecontact_sym.core import symbols as S


def test_placeholder_functions_and_long_names_are_words():
    assert lcs.to_latex(sp.Function("pull_off_force")(S.E_star)) == \
        r"\operatorname{pull\_off\_force}{\left(E^{*} \right)}"
    assert lcs.to_latex(sp.Symbol("pull_off_force")) == r"\mathrm{pull\_off\_force}"
    # the Maugis parameter's placeholder, as the contact shows it
    md = lcs.parabola(verify=False).maugis_dugdale()
    assert md.latex("maugis_lambda").startswith(r"\operatorname{maugis\_lambda}")
    # the paper's subscripts stay subscripts
    assert lcs.to_latex(S.c_D) == r"c_{\mathrm{D}}" and lcs.to_latex(sp.Symbol("a_po")) == "a_{po}"
