"""One reader for each numeric setting (core/budget.py, core/parallel.py,
core/ranges.py): budgets, jobs, tolerances, digits, points and backends are
checked where they enter, and a bad one is a package error naming it.
Moved from tests/test_trust_round4.py (issue 29, item 4) and
tests/test_state.py (issue 10)."""
from __future__ import annotations

import numpy as np
import pytest

import linecontact_sym as lcs
from linecontact_sym.core.errors import DomainError, LineContactError


def test_one_reader_for_budgets_jobs_tolerances():
    from linecontact_sym.core.budget import checked_budget
    from linecontact_sym.core.errors import BudgetError
    from linecontact_sym.core.parallel import capped_jobs, jobs_count
    from linecontact_sym.core.ranges import check_tolerance
    assert checked_budget(" 2.5 ", text=True) == 2.5 and checked_budget(np.float32(4)) == 4.0
    assert checked_budget("inf", text=True) is None
    assert checked_budget(10**400) is None    # larger than any float: no limit
    for bad in ("abc", "nan", 0, -1, True, 1j, "1e-400x"):
        with pytest.raises(BudgetError):
            checked_budget(bad)
    assert jobs_count(" 3 ") == 3 and jobs_count(np.int64(2)) == 2 and jobs_count(2.0) == 2
    for bad in ("abc", 0, 2.5, "inf", None, True):
        with pytest.raises(DomainError):
            jobs_count(bad)
    assert capped_jobs(1000, 20) == 20 and capped_jobs(4, 0) == 1
    assert check_tolerance("0.05") == 0.05
    for bad in (-0.1, float("nan"), 0, "abc", 2):
        with pytest.raises(DomainError):
            check_tolerance(bad)


def test_an_executor_given_as_text_is_refused():
    from linecontact_sym.core.parallel import map_ordered
    with pytest.raises(DomainError, match="executor"):
        map_ordered(abs, [1, -2], executor="processes")


@pytest.mark.parametrize("kw", [dict(rtol=0), dict(rtol=-1e-3), dict(rtol=float("nan")), dict(rtol=2.0),
                                dict(rtol="1e-3"), dict(dps=0), dict(dps=5000), dict(dps=2.5)])
def test_bad_tolerances_are_package_errors(kw):
    c = lcs.parabola()
    with pytest.raises(DomainError, match="rtol|dps"):
        c.evaluate("force", a=0.5, R=1.0, E_star=1.0, **kw)


def test_unknown_backend_is_a_package_error():
    with pytest.raises(LineContactError, match="unknown backend"):
        lcs.parabola().to_numeric("force", backend="julia")


@pytest.mark.parametrize("dps", [0, -5, 1.5, True, 5000, "30", None, float("nan")])
def test_dps_checked_everywhere(dps):
    c = lcs.parabola()
    with pytest.raises(DomainError, match="dps must be an integer"):
        c.evaluate_at("force", dps=dps, a=0.5, R=1, E_star=1)
    with pytest.raises(DomainError, match="dps must be an integer"):
        c.to_numeric("force", backend="mpmath", dps=dps)


@pytest.mark.parametrize("points", [0, -1, "5", True, 10**9])
def test_points_checked(points):
    with pytest.raises(lcs.ProfileError, match="points must be an integer"):
        lcs.LineContact(lcs.x**2 / (2 * lcs.R), points=points)
