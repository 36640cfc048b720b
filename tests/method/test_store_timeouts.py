"""A result cut short by the wall clock is not carried across processes: how
far a rule gets in a budget depends on the machine's load, and a verdict must
not (a loaded first run once fixed Eq. (35)'s pull-off condition on disk)."""
from linecontact_sym.method.derivation import _usable


def _rec(attempts, source, budget=20.0, closed=False):
    return {"closed_form": closed, "attempts": attempts, "verification": None, "budget": budget,
            "source": source}


TIMED_OUT = (("hypergeometric_termwise", "no result within 20 s"),)
REFUSED = (("hypergeometric_termwise", "not applicable: the profile has a special function"),)


def test_timed_out_result_from_disk_is_derived_again():
    assert not _usable(_rec(TIMED_OUT, "disk"), 20.0)
    assert not _usable(_rec(TIMED_OUT, "disk"), 5.0)


def test_timed_out_result_in_this_process_is_not_waited_for_twice():
    assert _usable(_rec(TIMED_OUT, "memory"), 20.0)
    assert not _usable(_rec(TIMED_OUT, "memory"), 40.0)      # a larger budget tries again
    assert not _usable(_rec(TIMED_OUT, "memory"), None)


def test_results_that_did_not_depend_on_the_clock_are_kept():
    assert _usable(_rec(REFUSED, "disk"), 20.0)               # no closed form, for a reason
    assert _usable(_rec(TIMED_OUT, "disk", closed=True), 20.0)
