"""The time budget of a derivation: refused unless a number of seconds > 0,
None and inf mean no limit, one budget covers the rules, the tidying and the
verification, and a derivation cut short says what it did.  Moved from
tests/test_state.py (issue 10) and tests/test_trust.py (issue 9, item 8).
The closed forms they check were worked out by hand (Eq. (10) of
x^2/(2R) + x^4/R^3)."""
from __future__ import annotations

import math

import pytest
import sympy as sp

import linecontact_sym as lcs
from linecontact_sym.core import symbols as S
from linecontact_sym.core.budget import Deadline, checked_budget
from linecontact_sym.core.errors import BudgetError, NumericValuesRequired

x = S.x


@pytest.mark.parametrize("bad", [0, -1, float("nan"), "5", True, [3]])
def test_budget_refused(bad):
    with pytest.raises(BudgetError, match="budget must be a number of seconds > 0"):
        lcs.LineContact(lcs.x**2 / (2 * lcs.R), budget=bad)


def test_budget_none_and_inf_mean_no_limit():
    assert checked_budget(None) is None and checked_budget(math.inf) is None
    assert checked_budget(2) == 2.0
    c = lcs.LineContact(lcs.x**2 / (2 * lcs.R), budget=None)
    assert c.budget is None
    assert sp.simplify(c.force - sp.pi * lcs.E_star * lcs.a**2 / (4 * lcs.R)) == 0
    assert Deadline(None).left() is None and not Deadline(None).expired()


def test_budget_covers_the_whole_derivation(monkeypatch):
    """A budget too small for the rules and the verification together: the
    derivation returns within about the budget (rules, tidying and
    verification share one deadline) and does not call an unverified closed
    form verified."""
    from linecontact_sym.method import store
    monkeypatch.setattr(store, "get", lambda key: None)      # neither the disk nor the memory
    monkeypatch.setattr(store, "put", lambda key, rec: None)
    c = lcs.LineContact(lcs.x**2 / (2 * lcs.R) + lcs.x**4 / lcs.R**3, budget=0.3)
    d = c.derivation("force")
    assert d.seconds < 0.3 + 8          # the fork and one quadrature step of slack, not 120 s
    if d.closed_form:
        assert d.verification is not None and d.verification.passed and d.verification.points
    else:
        why = " ".join(d.notes + tuple(w for _, w in d.attempts))
        assert "budget" in why or "within" in why, why
    # with time enough the same force closes and is verified (Eq. 10 of x^2/(2R) + x^4/R^3)
    full = lcs.LineContact(lcs.x**2 / (2 * lcs.R) + lcs.x**4 / lcs.R**3).derivation("force")
    assert full.closed_form and full.verification.passed
    # E* a int_0^{pi/2} sin(phi) f'(a sin(phi)) dphi with int sin^4 = 3 pi / 16
    expected = sp.pi * lcs.E_star * (lcs.a**2 / (4 * lcs.R) + 3 * lcs.a**4 / (4 * lcs.R**3))
    assert sp.simplify(full.expr - expected) == 0


def test_message_says_what_happened():
    """before: '(dP/da = 0 is transcendental here)'; after: what sympy.solve did.
    (Two power terms: one, c x**4, is now solved without sympy.solve, issue 22.)"""
    c = lcs.LineContact(S.c * x**4 + x**2 / 2)
    c.derivation("force")
    c.budget = 1e-3
    with pytest.raises(NumericValuesRequired) as exc:
        c.adhesive().pull_off_force
    assert "transcendental" not in str(exc.value) and "within 0.001 s" in str(exc.value)
