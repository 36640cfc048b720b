"""The asymmetric contact at the edges of its inputs (issue 42, trust round 5):
values read at the entry (complex, NaN, text, dps), a tensile one-interval
solution refused, profiles not real refused, the state solves bracketed by
the package's root finder; every refusal a package error."""
import mpmath
import pytest
import sympy as sp

import linecontact_sym as lcs
from linecontact_sym.core import symbols as S
from linecontact_sym.core.errors import (DomainError, InadmissibleProfileError, LineContactError,
                                         ProfileError)

X = S.x_real
FAST = dict(verify=False)
NAN = float("nan")


@pytest.fixture(scope="module")
def cubic():
    return lcs.LineContact(X**2 / 2 + X**3 / 10, symmetric=False, **FAST)


@pytest.fixture(scope="module")
def cubic_state(cubic):
    return cubic.contact_at(P=1, theta=sp.Rational(1, 5), E_star=2)


@pytest.fixture(scope="module")
def double_well():
    return lcs.LineContact(X**4 - X**2, symmetric=False, **FAST)


def test_double_well_small_load_tensile_refused(double_well):
    # one interval [-0.817, 0.817] balances P = 1e-3 only with p(0) < 0: the profile touches
    # near its two minima x = +-1/sqrt(2) first; without adhesion that is not the contact
    with pytest.raises(InadmissibleProfileError, match="tensile"):
        double_well.contact_at(P=sp.Rational(1, 1000), theta=0, E_star=1)


def test_double_well_large_load_answered_compressive(double_well):
    # at P = 4 the valley is filled: one interval, p >= 0, and int p dx = P by our own quadrature
    st = double_well.contact_at(P=4, theta=0, E_star=1)
    with mpmath.workdps(20):
        F = mpmath.quad(lambda v: st.pressure(v), [st.left, 0, st.right])
        pmin = min(st.pressure(v) for v in mpmath.linspace(st.left, st.right, 43)[1:-1])
    assert abs(F - 4) < 1e-10
    assert pmin > 0


@pytest.mark.parametrize("kw", [dict(P=1j), dict(P=NAN), dict(P="abc"), dict(P=1, theta=1j),
                                dict(P=1, theta=NAN), dict(P=1, moment=1j), dict(P=1, moment=float("inf")),
                                dict(P=1, dps=0), dict(P=1, dps=2.5), dict(P=0)])
def test_contact_at_values_read_at_entry(cubic, kw):
    with pytest.raises(DomainError):
        cubic.contact_at(E_star=1, **kw)


@pytest.mark.parametrize("x", [NAN, "abc", 1j, [0.0, NAN]])
def test_state_pressure_points_read(cubic_state, x):
    with pytest.raises(DomainError):
        cubic_state.pressure(x)


def test_state_pressure_still_takes_numbers(cubic_state):
    inside = (cubic_state.left + cubic_state.right) / 2
    assert cubic_state.pressure(float(inside)) > 0
    assert cubic_state.pressure([float(inside)])[0] == pytest.approx(float(cubic_state.pressure(inside)), rel=1e-9)


def test_ends_theta_nan_refused(cubic):
    with pytest.raises(DomainError):
        cubic.ends(theta=NAN)


def test_huge_load_package_error(cubic):
    # the cubic turns concave for x < -5/3: at P = 1e30 no bounded contact; a package error (was mpmath's ValueError)
    with pytest.raises(LineContactError):
        cubic.contact_at(P=sp.Float("1e30"), theta=0, E_star=1)


@pytest.mark.parametrize("f", [sp.sqrt(X), sp.log(X) + 1])
def test_profile_not_real_refused_at_construction(f):
    with pytest.raises(ProfileError, match="not real"):
        lcs.LineContact(f, symmetric=False, **FAST)


def test_flat_punch_viscoelastic_refused():
    with pytest.raises(DomainError, match="symmetric"):
        lcs.flat_punch(1).viscoelastic(lcs.maxwell(E0=1, tau=1))


def test_sign_check_pressure_of_a_bounded_state_without_closed_form():
    """The admissibility check of a bounded state whose pressure has no closed
    form takes p = (E*/2) sqrt(a^2 - s^2) J(x) in float64 (one Gauss-Legendre
    rule over the divided difference of f') instead of the engine's nested
    quadrature (the Gaussian bump's check: 100 s for 21 points).  Both routes
    share nothing but f: they agree to 1e-12 inside the contact."""
    import numpy as np
    import sympy as sp
    from linecontact_sym.contacts.asymmetric.contact import _bounded_pressure_float
    from linecontact_sym.core.precision import workdps
    xr = lcs.x_real
    st = lcs.LineContact(sp.exp(xr) - 1 - xr, symmetric=False).contact_at(
        P=sp.Rational(1, 2), theta=sp.Rational(1, 10), E_star=1)
    assert st.regime == "bounded" and st._fn("pressure") is None
    L, R = float(st.left), float(st.right)
    xs = np.array([0.97 * L + 0.03 * R, 0.7 * L + 0.3 * R, float(st.e), 0.1 * L + 0.9 * R])
    fast = _bounded_pressure_float(st)(xs)
    with workdps(20):
        ref = np.array([float(st.pressure(v)) for v in xs])
    assert np.all(ref > 0)
    assert np.max(np.abs(fast / ref - 1)) < 1e-12, (fast, ref)
