"""Conditional results: the cases of a Piecewise profile in a parameter are
each derived, verified at points of their own case and seen by every path
(evaluate_at, evalf, the exports, the inverse) and by every kind of contact;
where a result's condition fails no number is given.  Moved from
tests/test_trust.py (issue 9, item 5) and tests/test_trust_round3.py (issue
19, item 3).

References: mpmath quadrature of Eq. (10*) and Eq. (12) (tests/independent_refs.py)
and closed forms worked out by hand."""
from __future__ import annotations

import time

import mpmath
import numpy as np
import pytest
import sympy as sp

import linecontact_sym as lcs
from independent_refs import close, force_ref, pressure_ref
from linecontact_sym.core import symbols as S
from linecontact_sym.core.errors import DomainError
from linecontact_sym.method import transforms as T

x, a, E, R = S.x, S.a, S.E_star, S.R


def test_parameter_case_of_a_piecewise_is_a_condition():
    """before: P = 2 E* a^3 for every R, verified to 45 digits; round 2: the
    closed form carried R >= 1 and R < 1 was refused; after (issue 19, item
    3): every case is derived, P = 2 E* a^3 where R >= 1 and pi E* a^2/2
    where R < 1, each verified at points of its own case, and the reference
    (which reads the profile at the point) agrees with both."""
    c = lcs.LineContact(sp.Piecewise((x**2, R < 1), (x**3, True)))
    d = c.derivation("force")
    assert isinstance(d.expr, sp.Piecewise) and d.closed_form
    assert sp.simplify(d.expr.subs(R, 2) - 2 * E * a**3) == 0
    assert sp.simplify(d.expr.subs(R, sp.Rational(1, 2)) - sp.pi * E * a**2 / 2) == 0
    assert d.verification.passed
    with mpmath.workdps(40):
        for Rv, want in ((sp.Rational(1, 2), mpmath.pi / 8), (2, mpmath.mpf(1) / 4)):   # pi a^2/2, 2 a^3 at a = 1/2
            ref = T.force_quad(c.profile, {a: sp.Rational(1, 2), R: Rv, E: 1}, 30)
            assert abs(ref - want) < mpmath.mpf(10)**-28
            assert abs(c.evaluate_at("force", a=sp.Rational(1, 2), R=Rv, E_star=1) - want) < mpmath.mpf(10)**-28


CASED = sp.Piecewise((x**2 / (2 * lcs.R), lcs.R < 1), (x**2, True))


@pytest.fixture(scope="module")
def cased():
    return lcs.LineContact(CASED, points=2)


def test_every_case_is_derived_and_every_path_agrees(cased):
    """before: the force was pi*E_star*a**2/2 'holding for R >= 1'; R = 1/4
    was refused by evaluate_at and given pi/2 by Derivation.evalf and
    to_numeric(check=False).  At R = 1/4 the profile is 2 x^2: P(1) = pi."""
    ref = force_ref(lambda t: 4 * t, 1)                 # f' = 4 t where R = 1/4
    ref_hi = force_ref(lambda t: 2 * t, 1)              # f' = 2 t where R >= 1
    with mpmath.workdps(50):
        assert abs(ref - mpmath.pi) < 1e-25 and abs(ref_hi - mpmath.pi / 2) < 1e-25
    d = cased.derivation("force")
    assert d.closed_form and isinstance(d.expr, sp.Piecewise)
    q = sp.Rational(1, 4)
    near = force_ref(lambda t: t / mpmath.mpf("0.999"), 1)   # R = 0.999 < 1: f' = t/R
    for R, want in ((q, ref), (2, ref_hi), (1, ref_hi), (sp.Rational(999, 1000), near)):
        assert close(cased.evaluate_at("force", a=1, R=R, E_star=1), want, 1e-25)
        assert close(d.evalf(a=1, R=R, E_star=1), want, 1e-25)
        for check in (True, False):
            assert close(cased.to_numeric("force", check=check)(a=1.0, R=float(R), E_star=1.0), float(want), 1e-13)
            assert close(cased.to_numeric("force", "mpmath", check=check)(a=1, R=R, E_star=1), want, 1e-25)
        assert close(float(cased.evaluate("force", a=1, R=float(R), E_star=1).value), float(want), 1e-13)
    # the inverse at R = 1/4: P = pi -> a = 1
    assert close(cased.half_width(sp.pi, R=q, E_star=1), 1, 1e-25)
    # the pressure at R = 1/4 against Eq. (12) of the 2 x^2 profile
    p_ref = pressure_ref(lambda t: 4 * t, lambda t: 4, 1, sp.Rational(1, 2))
    assert close(cased.evaluate_at("pressure", a=1, x=sp.Rational(1, 2), R=q, E_star=1), p_ref, 1e-15)


def test_other_kinds_see_the_right_case(cased):
    q = sp.Rational(1, 4)
    # tangential: Q = mu (P(a) - P(c)), P of the 2 x^2 profile = pi a^2 E*
    t = cased.tangential()
    st_ = t.state(sp.Rational(1, 2), a=1, R=q, E_star=1, mu=sp.Rational(1, 2))
    with mpmath.workdps(30):
        c_ref = mpmath.findroot(lambda v: force_ref(lambda s: 4 * s, v) - (mpmath.pi - 1), mpmath.mpf("0.8"))
    assert close(st_.c, c_ref, 1e-20)
    # pull-off (JKR, Eq. 31 of the 2 x^2 profile at R = 1/4): P(a) = pi a^2 - sqrt(2 pi gamma a), gamma = 1/10
    po = cased.adhesive(sp.Rational(1, 10)).pull_off_at(R=q, E_star=1)
    with mpmath.workdps(40):
        P = lambda v: force_ref(lambda s: 4 * s, v, dps=40) - mpmath.sqrt(2 * mpmath.pi * v / 10)   # noqa: E731
        # by hand: P0 = pi a^2 (Eq. 10* of 2 x^2), dP/da = 0 at a^(3/2) = sqrt(2 pi gamma)/(4 pi)
        a_ref = (mpmath.sqrt(2 * mpmath.pi / 10) / (4 * mpmath.pi))**(mpmath.mpf(2) / 3)
        assert close(po.force, P(a_ref), 1e-25) and close(po.half_width, a_ref, 1e-20)
    # stresses: sigma_z on the surface is -p(x)
    sf = cased.stresses()
    p_ref = pressure_ref(lambda s: 4 * s, lambda s: 4, 1, sp.Rational(1, 2))
    assert close(sf.evaluate_at("sigma_z", dps=20, a=1, x=sp.Rational(1, 2), z=0, R=q, E_star=1), -p_ref, 1e-12)


def test_a_condition_that_fails_gives_no_number():
    """The exact cylinder holds for a < R: evalf refuses, the exports give NaN
    (check=False), and the contacts built on it refuse at once.  before:
    Derivation.evalf 'the quantity is complex', mpmath export a complex
    number, tangential state raised core.roots.Outside, the stress field a
    ValueError after 27 s."""
    c = lcs.exact_cylinder(verify=False)
    d = c.derivation("force")
    with pytest.raises(DomainError, match="a < R|a <= R"):
        d.evalf(a=2, R=1, E_star=1)
    assert np.isnan(c.to_numeric("force", check=False)(a=2.0, R=1.0, E_star=1.0))
    v = c.to_numeric("force", check=False)(a=np.array([0.5, 2.0]), R=1.0, E_star=1.0)
    assert np.isnan(v[1]) and np.isfinite(v[0])
    assert mpmath.isnan(c.to_numeric("force", "mpmath", check=False)(a=2, R=1, E_star=1))
    t0 = time.perf_counter()
    with pytest.raises(DomainError, match="a < R|a <= R"):
        c.tangential().state(sp.Rational(1, 10), a=2, R=1, E_star=1, mu=sp.Rational(3, 10))
    with pytest.raises(DomainError, match="a < R|a <= R"):
        c.stresses().evaluate_at("sigma_x", a=2, x=sp.Rational(1, 10), z=sp.Rational(1, 5), R=1, E_star=1)
    with pytest.raises(DomainError, match="a < R|a <= R"):
        c.stresses().maximum("von_mises", a=2, R=1, E_star=1, nu=0.3)
    assert time.perf_counter() - t0 < 10
