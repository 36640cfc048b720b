"""The Maugis-Dugdale law's parameters as expressions of one another (issue
42, class 6): sigma_0 = 2 gamma is a value of sigma_0 once gamma has one
(before: "the Dugdale pressure has symbols ['gamma'] without values")."""
import mpmath
import pytest
import sympy as sp

import linecontact_sym as lcs
from linecontact_sym.core import symbols as S
from linecontact_sym.contacts.adhesion.maugis import check as chk


@pytest.mark.slow        # two Dugdale sub-problems derived (SymPy's integrals): about 8 s on a loaded machine
def test_sigma0_as_an_expression_of_gamma_in_the_flamant_check():
    """The Dugdale sub-problem's displacement (the independent Flamant check of the
    cohesive gap) with sigma_0 = 2 gamma equals the one with sigma_0 given as the number."""
    vals = {S.a: sp.Rational(1, 2), S.c_D: sp.Rational(3, 4), S.E_star: 1, S.R: 1, S.gamma: sp.Rational(1, 10)}
    md = lcs.parabola(verify=False).maugis_dugdale(S.gamma, 2 * S.gamma)
    plain = lcs.parabola(verify=False).maugis_dugdale()
    with mpmath.workdps(15):
        u = chk._flamant_differences(md, vals, [vals[S.c_D]], 10)[0]
        u0 = chk._flamant_differences(plain, {**vals, S.sigma_0: sp.Rational(1, 5)}, [vals[S.c_D]], 10)[0]
    u, u0 = (getattr(v, "value", v) for v in (u, u0))
    assert abs(u - u0) <= 1e-9 * abs(u0) and abs(u0) > 0.01
