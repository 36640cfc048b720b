"""Numbers next to a profile's kinks: hidden kinks (Abs, Min) are break
points, the digits asked for hold next to a switch and inside a flat, the
float64 error estimate covers the error there.  Moved from tests/test_trust.py
(issue 9, items 6, 7, 10, 11).  References: closed forms and integrals worked
out by hand, mpmath quadrature."""
from __future__ import annotations

import mpmath
import pytest
import sympy as sp

import linecontact_sym as lcs
from linecontact_sym.core import symbols as S

x, R, th = S.x, S.R, S.theta


@pytest.mark.parametrize("profile, a_value, exact", [
    (sp.Abs(x - 1) - 1 + 2 * x, 2, 2 + 2 * sp.sqrt(3)),     # f' = 1 | 3: P = a + 2 sqrt(a^2 - 1)
    (sp.Min(x**2, x), 2, 2 * sp.pi / 3),                     # f' = 2t | 1, integrated by hand
])
def test_hidden_kinks_are_breakpoints(profile, a_value, exact):
    """before: 5.46404536... and 2.09442284... printed to 30 digits (4-5
    right), a NameError for the pressure; after: 30 correct digits."""
    c = lcs.LineContact(profile, verify=False)
    assert c.profile.is_piecewise
    got = c.evaluate_at("force", dps=30, a=a_value, E_star=1)
    with mpmath.workdps(40):
        assert abs(got - mpmath.mpf(sp.N(exact, 40))) < mpmath.mpf(10)**-29


def test_pressure_behind_abs_and_oscillation_refused():
    c = lcs.LineContact(sp.Abs(x - 1) - 1 + 2 * x, verify=False)
    with mpmath.workdps(40):
        # P'(s) = 1 (s < 1), 1 + 2 s/sqrt(s^2 - 1) (s > 1); Eq. (12) by hand at a = 2, x = 1/2
        exact = (mpmath.acosh(4) + 2 * mpmath.log((mpmath.sqrt(3) + mpmath.sqrt(mpmath.mpf(15) / 4))
                                                   / mpmath.sqrt(mpmath.mpf(3) / 4))) / mpmath.pi
        got = c.evaluate_at("pressure", dps=30, a=2, x=sp.Rational(1, 2), E_star=1)
        assert abs(got - exact) < mpmath.mpf(10)**-28
    with pytest.raises(lcs.InadmissibleProfileError, match="decreases arbitrarily close"):
        lcs.LineContact(x * sp.sin(1 / x))


def test_error_estimate_covers_the_error_next_to_a_kink():
    """before: float64 with estimated error 1.2e-13, actual 2.1e-11; after:
    the float64 quadrature is not trusted next to the integrand's switch."""
    c = lcs.worn_cylinder(verify=False)
    b = 0.5
    X = b * (1 - 1e-9)
    ref = c.evaluate_at("pressure", dps=40, a=1.0, x=X, R=5.0, b=b, E_star=1.0)
    r = c.evaluate("pressure", a=1.0, x=X, R=5.0, b=b, E_star=1.0, rtol=1e-10)
    assert abs(r.value - ref) <= r.error <= 1e-10 * abs(ref)


def test_inside_the_flat_is_zero_not_overflow():
    """before: OverflowError (kappa = inf where the pressure is 0)."""
    c = lcs.worn_cylinder(verify=False)
    r = c.evaluate("pressure", a=0.4, x=0.1, R=5.0, b=0.5, E_star=1.0, rtol=1e-10)
    assert r.value == 0 and r.error == 0


def test_pressure_of_a_piecewise_profile_to_30_digits():
    """Rounded wedge f = x^2/(2R) (x < R tan th), x tan th - R tan^2 th / 2:
    before: 28.6 correct digits of 30 at x = 3/10 (the quadrature lost
    digits next to the breakpoint); after: 30."""
    f = sp.Piecewise((x**2 / (2 * R), x < R * sp.tan(th)), (x * sp.tan(th) - R * sp.tan(th)**2 / 2, True))
    c = lcs.LineContact(f, params={R: (0.5, 2), th: (0.1, 0.6)}, verify=False)
    got = c.evaluate_at("pressure", dps=30, a=1, x=sp.Rational(3, 10), R=1, theta=sp.Rational(1, 2), E_star=1)
    with mpmath.workdps(60):
        # by hand: P'(s) = E* int_0^{pi/2} sin(p) h'(s sin p) dp, h = t f'(t): h' = 2t/R (t < b), tan th
        # (f' is continuous: no slope-jump term); Eq. (12) after s = sqrt(x^2 + w^2).  With R = 1,
        # b = tan th: P'(s) = pi s/2 for s <= b, else (sin p0 = b/s, the integral split at p0)
        # 2s int_0^p0 sin^2 + b int_p0^{pi/2} sin = s (p0 - sin p0 cos p0) + b cos p0
        # (this equals the Gauss-Legendre quadrature of the integral over p to 40 digits, at 1/40 of its CPU)
        b, X = mpmath.tan(mpmath.mpf(1) / 2), mpmath.mpf(3) / 10

        def dP(sv):
            if sv <= b:
                return mpmath.pi * sv / 2
            p0 = mpmath.asin(b / sv)
            return sv * (p0 - mpmath.sin(p0) * mpmath.cos(p0)) + b * mpmath.cos(p0)
        wb, W = mpmath.sqrt(b**2 - X**2), mpmath.sqrt(1 - X**2)
        g = lambda w: dP(mpmath.sqrt(X**2 + w**2)) / mpmath.sqrt(X**2 + w**2)  # noqa: E731
        ref = (mpmath.quad(g, [0, wb]) + mpmath.quad(lambda t: 2 * t * g(wb + t * t), [0, mpmath.sqrt(W - wb)])) \
            / mpmath.pi
        assert abs(got - ref) < mpmath.mpf(10)**-30 * abs(ref)
