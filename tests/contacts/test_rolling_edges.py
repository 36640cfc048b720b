"""Steady rolling at the edges of its inputs (issue 42, trust round 5): the
creepage at free rolling (tiny Q) against Carter's closed form recomputed
here without cancellation, values read at the entry, adhesion refused."""
import math

import mpmath
import pytest
import sympy as sp

import linecontact_sym as lcs
from linecontact_sym.contacts.rolling import state as st
from linecontact_sym.core.errors import DomainError, InadmissibleProfileError

ES, RV, MU = 113888.9, 500, 0.3
P1 = math.pi * ES / (4 * RV)      # Hertz: the load at a = 1


@pytest.fixture(scope="module")
def carter():
    return lcs.parabola(verify=False).rolling(MU)


@pytest.mark.parametrize("q", [1e-300, 1e-30, 1e-12])
def test_free_rolling_creepage_carter(carter, q):
    # Carter: xi = mu (a - c_s)/R, c_s = a sqrt(1 - q), so a - c_s = a q/(1 + sqrt(1 - q)) (no cancellation)
    s = carter.state_at(Q=q * MU * P1, a=1, E_star=ES, R=RV)
    with mpmath.workdps(40):
        mu, P = mpmath.mpf(str(MU)), mpmath.pi * mpmath.mpf(str(ES)) / (4 * RV)    # the decimals as given
        qq = s.Q / (mu * P)                      # the force as the state read it (its shortest decimal)
        assert abs(qq / q - 1) < 1e-14
        ref = mu * qq / (1 + mpmath.sqrt(1 - qq)) / RV
        assert abs(s.creepage - ref) <= mpmath.mpf("1e-20") * ref


def test_deficit_without_root_is_an_error():
    # g > 0 all the way down: an error, not the bracket's lower end as the root
    with mpmath.workdps(30):
        with pytest.raises(InadmissibleProfileError):
            st.solve_deficit(lambda u: mpmath.mpf(1), mpmath.mpf(1), mpmath.mpf("1e-10"))


@pytest.mark.parametrize("Q", [1j, float("nan"), float("inf"), "abc", None])
def test_Q_read_at_entry(carter, Q):
    with pytest.raises(DomainError):
        carter.state_at(Q=Q, a=1, E_star=ES, R=RV)


def test_symbolic_friction_negative_value_refused():
    r = lcs.parabola(verify=False).rolling(sp.Symbol("mu_f", positive=True))
    with pytest.raises(DomainError, match="mu_f"):
        r.state_at(Q=1, a=1, E_star=ES, R=RV, mu_f=-0.3)


def test_traction_points_read(carter):
    s = carter.state_at(Q=0.5 * MU * P1, a=1, E_star=ES, R=RV)
    with pytest.raises(DomainError):
        s.traction(float("nan"))
    with pytest.raises(DomainError):
        s.traction([0.0, float("inf")])
    # at the trailing edge side (slip) q = mu p: the Hertz pressure at x = -0.9
    assert float(s.traction(-0.9)) == pytest.approx(MU * 2 * P1 / math.pi * math.sqrt(1 - 0.81), rel=1e-9)


@pytest.mark.parametrize("points", [0, 1, -3, 2.5, "5"])
def test_creepage_curve_points(carter, points):
    with pytest.raises(DomainError):
        carter.creepage_curve(points=points, a=1, E_star=ES, R=RV)


def test_rolling_with_adhesion_refused():
    with pytest.raises(DomainError, match="adhesion"):
        lcs.parabola(verify=False).adhesive(sp.Rational(1, 10)).rolling(MU)
