"""Two elastic bodies: E* and Dundurs' beta against Dundurs' own form in
kappa = 3 - 4 nu and the shear moduli (not the compliance form of the code)."""
import warnings

import pytest
import sympy as sp

import linecontact_sym as lcs
from linecontact_sym.core.errors import DomainError, DomainWarning


def dundurs_kappa(E1, nu1, E2, nu2):
    G1, G2 = E1 / (2 * (1 + nu1)), E2 / (2 * (1 + nu2))
    k1, k2 = 3 - 4 * nu1, 3 - 4 * nu2
    return (G1 * (k2 - 1) - G2 * (k1 - 1)) / (G1 * (k2 + 1) + G2 * (k1 + 1))


@pytest.mark.parametrize("m", [(210, "0.3", 70, "0.33"), (1, "0.5", 3, "-0.2"), (5, "0.1", 5, "0.1")])
def test_beta_against_dundurs_kappa_form(m):
    E1, nu1, E2, nu2 = (sp.Rational(v) for v in m)
    # Dundurs' kappa form has beta of the opposite labels: beta(1, 2) = -kappa-form(1, 2)
    assert sp.simplify(lcs.dundurs_beta(E1, nu1, E2, nu2) + dundurs_kappa(E1, nu1, E2, nu2)) == 0
    assert lcs.dundurs_beta(E1, nu1, E2, nu2) == -lcs.dundurs_beta(E2, nu2, E1, nu1)
    assert abs(lcs.dundurs_beta(E1, nu1, E2, nu2)) <= sp.Rational(1, 2)


def test_reduced_modulus_and_rigid_limits():
    assert lcs.reduced_modulus(2, sp.Rational(3, 10)) == 2 / (1 - sp.Rational(9, 100))        # Popov Eq. (4)
    assert lcs.reduced_modulus(2, 0, 2, 0) == 1
    nu = sp.Rational(3, 10)
    assert lcs.dundurs_beta(sp.oo, 0, 1, nu) == -(1 - 2 * nu) / (2 * (1 - nu))
    assert lcs.dundurs_beta(3, "1/2", 7, "1/2") == 0                                        # incompressible pair
    with pytest.raises(DomainError, match="Poisson"):
        lcs.reduced_modulus(1, "0.7")
    with pytest.raises(DomainError, match="rigid"):
        lcs.reduced_modulus(sp.oo, 0, sp.oo, 0)


def test_neglected_coupling_warns_only_where_beta_is_not_zero():
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        note = lcs.neglected_coupling(0, "0.3")
        assert note.size == 0 and "uncouple" in note
    beta = lcs.dundurs_beta(210, "0.3", 70, "0.33")
    with pytest.warns(DomainWarning, match="neglected"):
        note = lcs.neglected_coupling(beta, "0.3")
    assert abs(float(note.size) - abs(float(beta)) * 0.3) < 1e-15
