"""Profiles a contact refuses, each with its reason (inadmissible, not real,
undefined, unbounded work), and the ones it takes as meant (x itself, a Float
exponent as its decimal).  Moved from tests/test_trust.py (issue 9, item 9),
tests/test_hardening.py and tests/test_state.py (issue 10)."""
from __future__ import annotations

import time

import pytest
import sympy as sp

import linecontact_sym as lcs
from linecontact_sym.core import symbols as S
from linecontact_sym.method.verification import VerificationRecord

x, a = S.x, S.a


def test_inadmissible_profiles_and_values_refused():
    """before: -x**2 and x**2 - x**4 'verified to 45 digits' for negative
    loads, I*x**2 'verified at 0 points', x**2 + I*x an unevaluated Integral."""
    with pytest.raises(lcs.InadmissibleProfileError, match="decreases"):
        lcs.LineContact(-x**2)
    for bad in (sp.I * x**2, x**2 + sp.I * x):
        with pytest.raises(lcs.ProfileError, match="not real"):
            lcs.LineContact(bad)
    c = lcs.LineContact(x**2 - x**4)
    rec = c.derivation("force").verification
    assert rec.passed and all(v[a] <= 1 / sp.sqrt(2) for v in rec.points)
    with pytest.raises(lcs.InadmissibleProfileError, match="decreases"):
        c.evaluate_at("force", a=1, E_star=1)
    with pytest.raises(lcs.DomainError, match="declared positive"):
        lcs.parabola().evaluate_at("force", a=1, R=-1, E_star=1)
    # 1 - cos(x) is rising up to pi, but dP0/da < 0 beyond j_{0,1}: tensile edge pressure
    with pytest.raises(lcs.InadmissibleProfileError, match="tensile"):
        lcs.LineContact(1 - sp.cos(x), verify=False).evaluate_at("force", a=sp.Rational(26, 10), E_star=1)
    empty = VerificationRecord((), (), 45, "a quadrature")
    assert not empty.passed and str(empty).startswith("NOT verified")


@pytest.mark.parametrize("make,err,match", [
    (lambda: lcs.x**2 / (2 * lcs.R) * 0 + lcs.x / 0, lcs.ProfileError, "undefined"),
    (lambda: lcs.x**2 / __import__("sympy").Symbol("R", negative=True), lcs.ProfileError, "non-positive"),
    (lambda: lcs.x**(10**10), lcs.ProfileError, "exponent"),
    (lambda: __import__("sympy").Derivative(__import__("sympy").sin(lcs.x), (lcs.x, 10**9)), lcs.ProfileError,
     "derivative of order"),
    (lambda: __import__("sympy").I * lcs.x**2, lcs.ProfileError, "not real"),
])
def test_profiles_refused_with_a_reason(make, err, match):
    t0 = time.perf_counter()
    with pytest.raises(err, match=match):
        lcs.LineContact(make())
    assert time.perf_counter() - t0 < 2


def test_the_profile_x_is_a_profile():
    assert lcs.LineContact(lcs.x).force == lcs.E_star * lcs.a


@pytest.mark.parametrize("make, match", [
    (lambda: lcs.LineContact(sp.floor(lcs.x)), "floor"),
    (lambda: lcs.LineContact(sp.Piecewise((lcs.x**2, lcs.x > 1))), "no value"),
    (lambda: lcs.parabola(R="1/0"), "undefined"),
    (lambda: lcs.parabola(R=-1), "positive"),
    (lambda: lcs.LineContact(lcs.x**2, params=5), "params"),
])
def test_profile_refusals(make, match):
    with pytest.raises(lcs.LineContactError, match=match):
        make()


def test_float_exponents_in_a_profile_mean_their_decimal():
    """power_law(n=1.5) is the power law with n = 3/2 (before: a pressure
    fallback holding zoo that neither export could print)."""
    c = lcs.power_law(n=1.5)
    assert c.profile.expr == lcs.c * lcs.x**sp.Rational(3, 2)
    exact = lcs.power_law(n=sp.Rational(3, 2))
    kw = dict(a=1.0, x=0.5, c=1.0, E_star=1.0)
    assert c.evaluate("pressure", **kw).value == exact.evaluate("pressure", **kw).value
    # p(0.5; 1) of c x^(3/2): (E* c n / pi) int_x^a ... checked against the quadrature of Eq. (12)
    assert c.derivation("pressure").closed_form and c.derivation("pressure").verification.passed
