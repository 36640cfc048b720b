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


# ---------------------------------------------------------------- the frictional layers' keywords
def beta_by_hand(E1, nu1, E2, nu2):
    """Dundurs' beta (Johnson 1985, Eq. 5.4 labels: body 1 the indenter) in
    shear moduli and kappa = 3 - 4 nu (plane strain), floats; E = inf: rigid."""
    inv_G1 = 0.0 if E1 == float("inf") else 2 * (1 + nu1) / E1
    inv_G2 = 0.0 if E2 == float("inf") else 2 * (1 + nu2) / E2
    k1, k2 = 3 - 4 * nu1, 3 - 4 * nu2
    # (G2 (k1 - 1) - G1 (k2 - 1)) / (G2 (k1 + 1) + G1 (k2 + 1)), divided through by G1 G2
    return ((k1 - 1) * inv_G1 - (k2 - 1) * inv_G2) / ((k1 + 1) * inv_G1 + (k2 + 1) * inv_G2)


STEEL, ALUMINIUM = (210e9, 0.3), (70e9, 0.33)


@pytest.mark.parametrize("bodies,mu", [((STEEL, STEEL), 0.4), ((STEEL, ALUMINIUM), 0.4),
                                       (((float("inf"), 0.0), (5e6, 0.49)), 0.8),      # rigid on rubber
                                       (((float("inf"), 0.0), (5e6, 0.5)), 0.8)])      # on incompressible rubber
def test_coupling_note_size_is_beta_mu(bodies, mu):
    """The note's size |beta| mu with beta from the materials, against beta by
    hand; a DomainWarning exactly where beta != 0."""
    from linecontact_sym.core.materials import coupling
    (E1, nu1), (E2, nu2) = bodies
    hand = beta_by_hand(E1, nu1, E2, nu2)
    with warnings.catch_warnings(record=True) as seen:
        warnings.simplefilter("always")
        c = coupling(materials=bodies)
        note = c.note(mu, warn=True)
    assert float(c.beta) == pytest.approx(hand, rel=1e-14, abs=1e-300)
    assert float(note.size) == pytest.approx(abs(hand) * mu, rel=1e-14, abs=1e-300)
    assert len([w for w in seen if issubclass(w.category, DomainWarning)]) == (0 if hand == 0 else 1)
    if hand == 0:
        assert "uncouple" in note
    else:
        assert f"{abs(hand) * mu:.3g}"[:4] in note and "neglected" in note
    E_hand = 1 / sum((1 - nu**2) / E for E, nu in bodies if E != float("inf"))
    assert float(c.E_star) == pytest.approx(E_hand, rel=1e-14)


def test_steel_on_aluminium_and_rigid_on_rubber_numbers():
    """The sizes quoted in the README: steel on aluminium |beta| = 0.1167 (0.047
    at mu = 0.4); a rigid cylinder on rubber nu = 0.49: |beta| = 0.0196."""
    assert abs(beta_by_hand(*STEEL, *ALUMINIUM)) == pytest.approx(0.11674, abs=1e-5)
    assert abs(beta_by_hand(float("inf"), 0.0, 5e6, 0.49)) == pytest.approx(0.02 / 1.02, rel=1e-12)


def test_coupling_reader_refuses_what_it_cannot_mean():
    from linecontact_sym.core.materials import NOT_GIVEN, coupling
    assert coupling().note(sp.Rational(3, 10)).startswith(NOT_GIVEN) and coupling().note("0.3").assumed
    assert coupling(beta="-2/7").beta == sp.Rational(-2, 7)
    with pytest.raises(DomainError, match=r"\[-1/2, 1/2\]"):
        coupling(beta=0.7)
    with pytest.raises(DomainError, match="contradicts the materials"):
        coupling(beta=0.1, materials=(STEEL, ALUMINIUM))
    assert coupling(beta=0, materials=(STEEL, STEEL)).beta == 0                   # agreeing: accepted
    with pytest.raises(DomainError, match=r"\(\(E1, nu1\), \(E2, nu2\)\)"):
        coupling(materials=(210e9, 0.3, 70e9, 0.33))
    with pytest.raises(DomainError, match="numbers"):
        coupling(materials=((sp.Symbol("E1", positive=True), 0.3), STEEL))
    with pytest.raises(DomainError, match="Poisson"):
        coupling(materials=((1, 0.7), STEEL))
    c = coupling(materials=(STEEL, ALUMINIUM))
    assert c.values({"a": 1})["E_star"] == c.E_star                                 # filled where not given
    assert c.values({"E_star": float(c.E_star)}) == {"E_star": float(c.E_star)}      # the float of it: accepted
    with pytest.raises(DomainError, match="contradicts the materials"):
        c.values({"E_star": 58.6e9})                                                 # 0.01 % off: refused
