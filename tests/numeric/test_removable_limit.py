"""The removable-singularity patch of the float64 export (numeric/exports.py):
a limit SymPy cannot find is tried once, not at every export."""
import math
from types import SimpleNamespace

import pytest
import sympy as sp

from linecontact_sym.core import symbols as S
from linecontact_sym.numeric import exports


def test_failed_limit_is_not_tried_twice(monkeypatch):
    # E* R (K(a^2/R^2) - E(a^2/R^2)) at R = 0 is nan, and R -> 0+ has no finite limit
    expr = S.E_star * S.R * (sp.elliptic_k(S.a**2 / S.R**2) - sp.elliptic_e(S.a**2 / S.R**2)) * sp.Rational(7, 3)
    calls = []
    import linecontact_sym.core.budget as budget

    def out_of_time(*args, **kw):   # what SymPy's gruntz does here: spend the budget (10 CPU s)
        calls.append(args[1])
        raise budget.BudgetExceeded("limit", 10.0)
    monkeypatch.setattr(budget, "run_with_budget", out_of_time)
    assert exports._removable_limit(expr, S.R) is None
    assert exports._removable_limit(expr, S.R) is None
    assert len(calls) == 1


def test_found_limit_still_patches():
    # x^2 atanh(1/x)/x^2 ... a removable point: sin(x)/x at x = 0 is 1
    f = exports.lambdify_numpy(sp.sin(S.x) / S.x * S.a, [S.x, S.a])
    assert f(0.0, 2.0) == 2.0
    assert math.isclose(f(1e-3, 2.0), 2 * math.sin(1e-3) / 1e-3, rel_tol=1e-15)
    f = exports.lambdify_numpy(sp.sin(S.x) / S.x * S.a, [S.x, S.a])   # again: the found limit is not withheld
    assert f(0.0, 3.0) == 3.0


def test_found_limit_is_sought_once_per_process(monkeypatch):
    # each new contact of a profile compiles the same exports: the exact cylinder's
    # dP/da at a -> 0+ (a found limit, 1 CPU s) was sought again for every one
    expr = sp.sin(S.x) / S.x * S.a * sp.Rational(11, 13)
    calls = []
    import linecontact_sym.core.budget as budget
    real = budget.run_with_budget

    def counted(*args, **kw):
        calls.append(args[1])
        return real(*args, **kw)
    monkeypatch.setattr(budget, "run_with_budget", counted)
    assert exports._removable_limit(expr, S.x) == S.a * sp.Rational(11, 13)
    assert exports._removable_limit(expr, S.x) == S.a * sp.Rational(11, 13)
    assert len(calls) == 1


def test_no_limit_is_sought_where_every_contact_refuses_zero():
    """core.ranges.NEVER_ZERO: symbols declared positive whose value 0 no
    contact takes, so an export's patch at 0 could never be used (the exact
    cylinder's failing limit at R -> 0+ cost 1-3 CPU s per export).  Checked
    against the contacts' own rules: no kind lets them be 0."""
    import linecontact_sym as lcs
    from linecontact_sym.contacts.base import CONTACT_KINDS, checked_value, may_be_zero
    from linecontact_sym.core.errors import DomainError
    from linecontact_sym.core.ranges import NEVER_ZERO
    names = {s.name for s in NEVER_ZERO}
    assert not any(may_be_zero(n) for n in names)
    c = lcs.parabola()
    for kind, cls in CONTACT_KINDS.items():
        obj = cls.from_frictionless(c)
        assert not names & set(obj._zero_ok), kind
        for q in type(obj).quantities().values():
            assert not names & set(q.nonnegative), (kind, q)
    assert not names & set(lcs.SlidingStressField.from_frictionless(c)._zero_ok)
    # the entry check's generic rule refuses 0 for each (end to end: the parabola's R, and
    # the stick half-width of its tangential contact's slip)
    for sym in NEVER_ZERO:
        with pytest.raises(DomainError, match="positive"):
            checked_value(sym.name, 0.0, sym)
    with pytest.raises(DomainError, match="positive"):
        c.check_domain("force", dict(a=0.5, R=0.0, E_star=1.0))
    with pytest.raises(DomainError, match="positive"):
        c.tangential().check_domain("slip", dict(a=1.0, R=1.0, E_star=1.0, mu=0.3, x=0.9, c_s=0.0))
    d = SimpleNamespace(quantity="force", variables_all=(S.a, S.E_star, S.R, S.x, S.z, S.gamma, S.mu, S.c_s))
    assert exports._zero_in_domain(d) == (S.x, S.z, S.gamma, S.mu)
