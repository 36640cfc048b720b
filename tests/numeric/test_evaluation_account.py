"""What an Evaluation states about itself is one account (issue 42, class 7).

* Its enclosure is the ball of the error it states, at the precision asked:
  a quantity left as an integral (the pressure of cosh(x) - 1) at rtol = 1e-25
  printed "error <= 1.22e-36" beside an interval 1e-16 wide (the Arb ball's
  end points were rounded to 53 bits).
* What ``evaluate(rtol)`` certifies, ``evaluate(certified=True)`` does not
  refuse ("has no closed form; certified evaluation needs one").
* No silent underflow: the exact cylinder's force at a = 1e-300 (7.85e-601,
  which mpmath holds) was 0.0 "error <= 0"; pi a^2/(4 R) at a = 1e-160,
  R = 1e-20 (a^2 a subnormal) was off by 2e-4 with "rel. error <= 7e-15".

References shared with nothing in the package: mpmath quadratures of
Popov's Eq. (10) and Eq. (12) written out here.
"""
from __future__ import annotations

import mpmath
import numpy as np
import pytest
import sympy as sp

import linecontact_sym as lcs
from linecontact_sym.numeric.certified import CertificationError


def _cosh_pressure(A, X_num, X_den, dps=40):
    """p(x) = (1/pi) int_x^a P'(s)/sqrt(s^2 - x^2) ds (Eq. 12, tanh-sinh in s = x cosh(u)),
    with P(s) = E* int_0^s t f'(t)/sqrt(s^2 - t^2) dt (Eq. 10, E* = 1, f' = sinh) as the series
    of sinh termwise: P(s) = sum_j s^(2j+2) W(2j+2)/(2j+1)!, W(n) = int_0^(pi/2) sin^n (Wallis)."""
    with mpmath.workdps(dps + 10):
        A, X = mpmath.mpf(A), mpmath.mpf(X_num) / X_den     # x exact to dps digits (not 53 bits)
        W = [mpmath.sqrt(mpmath.pi) * mpmath.gamma((n + 1) / mpmath.mpf(2)) / (2 * mpmath.gamma(n / mpmath.mpf(2) + 1))
             for n in range(2 * 40 + 3)]
        coef = [(2 * j + 2) * W[2 * j + 2] / mpmath.factorial(2 * j + 1) for j in range(40)]

        def dP(s):
            return mpmath.fsum(c * s**(2 * j + 1) for j, c in enumerate(coef))
        return mpmath.quad(lambda u: dP(X * mpmath.cosh(u)), [0, mpmath.acosh(A / X)]) / mpmath.pi


@pytest.fixture(scope="module")
def cosh_contact():
    return lcs.LineContact(sp.cosh(lcs.x) - 1)


@pytest.fixture(scope="module")
def reference():
    return _cosh_pressure(1, 1, 3)


def test_enclosure_is_the_ball_of_the_stated_error(cosh_contact, reference):
    r = cosh_contact.evaluate("pressure", a=1, x=sp.Rational(1, 3), E_star=1, rtol=1e-25)
    assert r.path == "arb" and r.certified
    lo, hi = r.enclosure
    with mpmath.workdps(60):
        assert lo <= reference <= hi
        # the interval is the error it states: width 2 * error (was 1e-16 wide beside error 1e-36)
        assert hi - lo <= 2 * r.error * (1 + mpmath.mpf(10)**-10)
        assert abs(r.value - reference) <= r.error
    assert r.error <= 1e-25 * abs(r.value)
    # the printed interval shows the digits the value holds, not 53-bit end points
    text = str(r)
    shown = text.split(" in [")[1].split("]")[0].split(", ")
    with mpmath.workdps(60):
        assert abs(mpmath.mpf(shown[1]) - mpmath.mpf(shown[0])) < 1e-30


def test_certified_evaluation_of_a_quantity_left_as_an_integral(cosh_contact, reference):
    r = cosh_contact.evaluate("pressure", a=1, x=sp.Rational(1, 3), E_star=1, certified=True, dps=20)
    assert r.certified and r.path == "arb"
    lo, hi = r.enclosure
    with mpmath.workdps(60):
        assert lo <= reference <= hi
        assert hi - lo <= 2 * r.error * (1 + mpmath.mpf(10)**-10)
    assert r.digits() >= 20


def test_certified_refusal_names_the_reason():
    # a closed form that Arb has no translation for is still refused, with a package error
    from linecontact_sym.numeric.certified import arb_evaluate
    with pytest.raises(CertificationError):
        arb_evaluate(sp.Function("g")(lcs.x), [lcs.x], [1.0])


def _cylinder_force(A, R, dps=30):
    """Eq. (10) of R - sqrt(R^2 - x^2) (E* = 1): (a^2/R) int_0^(pi/2) sin^2/sqrt(1 - (a/R)^2 sin^2) dphi."""
    with mpmath.workdps(dps):
        A, R = mpmath.mpf(A), mpmath.mpf(R)
        # (scaled to O(1): quad's tolerance is absolute)
        return A**2 / R * mpmath.quad(lambda ph: mpmath.sin(ph)**2 / mpmath.sqrt(1 - (A / R)**2 * mpmath.sin(ph)**2),
                                      [0, mpmath.pi / 2])


@pytest.mark.slow
def test_no_silent_underflow_in_the_series_model():
    """The cylinder's force by its series model (path model:...) at a = 1e-300."""
    r = lcs.exact_cylinder().evaluate("force", a=1e-300, R=1.0, E_star=1.0, rtol=1e-12)
    ref = _cylinder_force(1e-300, 1.0)
    assert r.value != 0 and r.error > 0
    with mpmath.workdps(30):
        err = abs(mpmath.mpf(r.value) - ref)
        assert err <= r.error and err <= 1e-12 * ref
    assert "e-601" in str(r) and "error <= 0" not in str(r)


@pytest.mark.parametrize("A, R", [(1e-300, 1.0), (1e-160, 1e-20), (1e-100, 1e100)])
def test_no_silent_underflow_in_float64(A, R):
    """pi E* a^2/(4 R) (the parabola's closed form, float64 path) where a^2 or the value underflows."""
    r = lcs.parabola().evaluate("force", a=A, R=R, E_star=1.0, rtol=1e-12)
    with mpmath.workdps(30):
        ref = mpmath.pi * mpmath.mpf(A)**2 / (4 * mpmath.mpf(R))
        err = abs(mpmath.mpf(r.value) - ref)
        assert r.value != 0 and err <= r.error and err <= 1e-12 * ref, r


def test_arrays_evaluate_an_underflow_point_by_point():
    c = lcs.parabola()
    r = c.evaluate("force", a=np.array([1e-300, 0.5]), R=1.0, E_star=1.0, rtol=1e-12)
    with mpmath.workdps(30):
        ref = mpmath.pi * mpmath.mpf(1e-300)**2 / 4
        assert abs(mpmath.mpf(r.value[0]) / ref - 1) < 1e-12
    assert abs(float(r.value[1]) - np.pi / 16) < 1e-15
