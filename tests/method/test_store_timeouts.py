"""Budgets are CPU seconds (core/budget.py), so a result cut short by its
budget does not depend on the machine's load and is carried across
processes like any other; only a step stopped by the wall-clock guard
against a hang (which may depend on the load: a loaded first run once fixed
Eq. (35)'s pull-off condition on disk) is derived again in a new process."""
from linecontact_sym.method.derivation import _usable


def _rec(attempts, source, budget=20.0, closed=False):
    return {"closed_form": closed, "attempts": attempts, "verification": None, "budget": budget,
            "source": source}


TIMED_OUT = (("hypergeometric_termwise", "no result within 20 CPU s"),)
GUARD = (("hypergeometric_termwise", "no result within 20 CPU s (run did not finish within the wall-clock "
                                     "guard of 260 s against a hang (its CPU budget was 20 s): the wall-clock "
                                     "guard fired)"),)
REFUSED = (("hypergeometric_termwise", "not applicable: the profile has a special function"),)


def test_result_cut_short_by_its_cpu_budget_is_carried_across_processes():
    assert _usable(_rec(TIMED_OUT, "disk"), 20.0)
    assert _usable(_rec(TIMED_OUT, "disk"), 5.0)
    assert not _usable(_rec(TIMED_OUT, "disk"), 40.0)        # a larger budget tries again
    assert not _usable(_rec(TIMED_OUT, "disk"), None)


def test_result_stopped_by_the_wall_clock_guard_is_not_taken_from_disk():
    assert not _usable(_rec(GUARD, "disk"), 20.0)
    assert not _usable(_rec(GUARD, "disk"), 5.0)
    assert _usable(_rec(GUARD, "memory"), 20.0)               # within one process nothing waits twice


def test_timed_out_result_in_this_process_is_not_waited_for_twice():
    assert _usable(_rec(TIMED_OUT, "memory"), 20.0)
    assert not _usable(_rec(TIMED_OUT, "memory"), 40.0)      # a larger budget tries again
    assert not _usable(_rec(TIMED_OUT, "memory"), None)


def test_results_that_did_not_depend_on_the_clock_are_kept():
    assert _usable(_rec(REFUSED, "disk"), 20.0)               # no closed form, for a reason
    assert _usable(_rec(TIMED_OUT, "disk", closed=True), 20.0)
