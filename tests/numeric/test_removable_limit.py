"""The removable-singularity patch of the float64 export (numeric/exports.py):
a limit SymPy cannot find is tried once, not at every export."""
import math

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
