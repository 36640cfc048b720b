"""Values where a result does not hold, and foreign exceptions at the edges
(issue 42, classes 4 and 5): a symbol declared positive given a negative,
zero (where refused) or complex value is refused where values enter (the one
binding, values_by_name), for every path; a force law no contact has is
refused by the inverse map; sampling ranges, deep nesting and complex loads
give the package's errors naming the problem."""
import pytest
import sympy as sp

import linecontact_sym as lcs
from linecontact_sym import a, x, R, E_star
from linecontact_sym.core.errors import DomainError, InadmissibleProfileError, ProfileError


@pytest.mark.parametrize("values, match", [
    (dict(R=-1, E_star=1, gamma=1), "R is declared positive"),
    (dict(R=1, E_star=0, gamma=1), "E_star is declared positive"),
    (dict(R=1, E_star=1, gamma=-1), "gamma is declared positive"),
    (dict(R=1, E_star=1, gamma=sp.I), "complex"),
    (dict(R=1, E_star=1, gamma="1+2*I"), "complex"),
])
def test_the_pull_off_refuses_values_outside_the_symbols_domain(values, match):
    """The exact cylinder upside down (R = -1, f(0) = -2) returned a pull-off of -1.616."""
    with pytest.raises(DomainError, match=match):
        lcs.exact_cylinder(verify=False).adhesive().pull_off_at(15, **values)


def test_every_path_that_binds_values_refuses_a_negative_radius():
    c = lcs.parabola(verify=False)
    with pytest.raises(DomainError, match="R is declared positive"):
        c.force_law(R=-1, E_star=1)
    with pytest.raises(DomainError, match="R is declared positive"):
        c.derivation("force").evalf(15, a=1, R=-1, E_star=1)
    with pytest.raises(DomainError, match="R is declared positive"):
        c.tangential().state(0.1, E_star=1, R=-1, mu=0.4, a=0.8)
    # gamma = 0 stays the non-adhesive limit, x any sign (the profile is mirrored)
    with pytest.raises(lcs.NoPullOffError, match="no adhesion"):
        c.adhesive().pull_off_at(15, R=1, E_star=1, gamma=0)
    assert c.derivation("pressure").evalf(15, a=1, x=-sp.Rational(1, 2), R=1, E_star=1) > 0


def test_the_inverse_map_refuses_a_force_law_no_contact_has():
    """Before: -a**2 gave the decreasing profile -2 x**2/(pi E*)."""
    with pytest.raises(InadmissibleProfileError, match="negative"):
        lcs.profile_from_force(-a**2)
    with pytest.raises(InadmissibleProfileError, match="negative|decreasing"):
        lcs.profile_from_force(a**3 - a**2)
    with pytest.raises(InadmissibleProfileError, match="not real"):
        lcs.profile_from_force(sp.I * a**2)
    Rp = sp.Symbol("R", positive=True)
    assert lcs.profile_from_force(sp.pi * E_star * a**2 / (4 * Rp), verify_points=1).expr == x**2 / (2 * Rp)


@pytest.mark.parametrize("rng", [("a", "b"), (float("nan"), 1), (0.5, float("inf")), (2, 1), (1,), 5, (-1, 1)])
def test_sampling_ranges_are_pairs_of_finite_numbers(rng):
    """Before: ValueError (could not convert string to float; NaN to integer)."""
    with pytest.raises(ProfileError, match="sampling range of R"):
        lcs.LineContact(x**2 / (2 * R), params={R: rng})


def test_a_profile_nested_300_deep_is_refused_not_a_recursion_error():
    e, law = x, a
    for _ in range(300):
        e, law = sp.sin(e, evaluate=False), sp.sinh(law, evaluate=False)
    with pytest.raises(ProfileError, match="nested more than"):
        lcs.LineContact(e)
    with pytest.raises(ProfileError, match="nested more than"):
        lcs.profile_from_force(law)


@pytest.mark.parametrize("load", [1 + 2j, sp.I, "1+2*I", float("nan"), sp.oo])
def test_a_complex_or_infinite_load_is_refused_by_name(load):
    """Before: TypeError (Invalid comparison of non-real 1 + 2*I)."""
    with pytest.raises(DomainError, match="the load P must be a"):
        lcs.parabola(verify=False).half_width(load, R=1, E_star=1)
