"""Diagnosis of failing claims (claims/diagnosis.py): each common mistake,
made on purpose in a formula that is otherwise right, is recognised and named;
a formula that is simply wrong gets no diagnosis."""
import mpmath
import pytest
import sympy as sp

from linecontact_sym.claims.check import _force_law, check_form
from linecontact_sym.claims.derive import Context, derive
from linecontact_sym.claims.diagnosis import identify_constant
from linecontact_sym.claims.results import FAILS
from linecontact_sym.claims.spec import claim_from_cli

CTX = Context(10.0)


def form_result(quantity, formula, profile, **kw):
    claim = claim_from_cli(quantity, formula, profile, **kw)
    prof = claim.profiles[0][1]
    derived = derive(claim, prof, CTX)
    printed = claim.forms[0].expr
    return check_form(claim, claim.forms[0], derived, printed, physics_points=0, symbolic=False,
                      force_law=lambda: _force_law(claim, prof, CTX, printed))


@pytest.mark.parametrize("formula, rule, words", [
    # exact cylinder, Eq. (26) with the paper's K(k): k = a/R passed to SymPy's elliptic_k(m)
    ("E_star*R*(elliptic_k(a/R) - elliptic_e(a/R))", "modulus", ["m = k^2", "modulus", "parameter"]),
    # K and E exchanged (not read as a sign: the K <-> E rule comes first)
    ("E_star*R*(elliptic_e(a**2/R**2) - elliptic_k(a**2/R**2))", "swap K E", ["K and E swapped"]),
    # both mistakes at once
    ("E_star*R*(elliptic_e(a/R) - elliptic_k(a/R))", "swap K E", ["K and E swapped", "m = k^2"]),
])
def test_elliptic_mistakes(formula, rule, words):
    fr = form_result("force", formula, "R - sqrt(R**2 - x**2)", assumptions=["a < R"])
    assert fr.status == FAILS
    assert fr.diagnosis is not None and fr.diagnosis.rule == rule
    for w in words:
        assert w in fr.diagnosis.message
    assert "elliptic_k(a**2/R**2)" in fr.diagnosis.formula


def test_pressure_written_in_the_load():
    # Hertz, Eq. (14) with E*/(2R) eliminated through P = pi E* a^2/(4R): right, but in P
    fr = form_result("pressure", "2*P/(pi*a**2)*sqrt(a**2 - x**2)", "x**2/(2*R)")
    assert fr.status == FAILS and fr.diagnosis.rule == "load"
    assert "P = pi*E_star*a**2/(4*R)" in fr.diagnosis.message and "load P" in fr.diagnosis.message


@pytest.mark.parametrize("formula, factor", [
    ("pi*E_star*a**2/(2*R)", "2"),          # Eq. (13) twice over
    ("E_star*a**2/(4*R)", "1/pi"),          # pi dropped
])
def test_constant_factor(formula, factor):
    fr = form_result("force", formula, "x**2/(2*R)")
    assert fr.status == FAILS and fr.diagnosis.rule == "factor"
    assert f"the formula is {factor} times the derived value" in fr.diagnosis.message
    assert fr.diagnosis.formula == "pi*E_star*a**2/(4*R)"          # the corrected formula


def test_contact_width_for_half_width():
    # Hertz force law written in the contact width w = 2a but called a
    fr = form_result("force", "pi*E_star*a**2/(16*R)", "x**2/(2*R)")
    assert fr.status == FAILS and fr.diagnosis.rule == "width" and "a -> 2a" in fr.diagnosis.message


def test_a_wrong_formula_gets_no_diagnosis():
    fr = form_result("force", "pi*E_star*a**3/(4*R)", "x**2/(2*R)")
    assert fr.status == FAILS and fr.diagnosis is None
    assert fr.to_dict()["diagnosis"] is None


def test_identify_constant():
    with mpmath.workdps(50):
        assert identify_constant(2 * mpmath.pi / 3) == 2 * sp.pi / 3
        assert identify_constant(mpmath.sqrt(2) / mpmath.pi) == sp.sqrt(2) / sp.pi
    assert identify_constant(mpmath.mpf(3) / 4) == sp.Rational(3, 4)
    assert identify_constant(mpmath.e) is None
