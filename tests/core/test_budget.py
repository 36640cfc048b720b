"""Budgets are CPU seconds of the process doing the work (core/budget.py),
never wall time: a busy child is stopped when its CPU time is spent, a child
that waits is not (only the wall-clock guard against a hang stops it, and
says so), a Deadline counts the CPU time of the children it ran, and a
derivation gives the same closed forms on a quiet machine and under load."""
import json
import multiprocessing as mp
import os
import subprocess
import sys
import time
from pathlib import Path

import pytest

import linecontact_sym.core.budget as B
from linecontact_sym.core.budget import Deadline, run_with_budget
from linecontact_sym.core.errors import BudgetExceeded

pytestmark = pytest.mark.skipif("fork" not in mp.get_all_start_methods(), reason="no fork on this platform")


def _spin(cpu_seconds):
    """Busy for ``cpu_seconds`` of this process's CPU time; returns it."""
    t0 = time.process_time()
    while time.process_time() - t0 < cpu_seconds:
        pass
    return cpu_seconds


def test_a_busy_child_is_stopped_when_its_cpu_seconds_are_spent():
    d = Deadline(None)
    with pytest.raises(BudgetExceeded, match=r"budget of 0\.15 CPU s") as info:
        run_with_budget(_spin, 30, seconds=0.15)
    assert not info.value.wall_guard
    assert 0.12 < d.used() < 1.5           # the child's CPU time is counted by the Deadline


def test_a_child_within_its_cpu_budget_returns_and_is_charged():
    d = Deadline(10)
    assert run_with_budget(_spin, 0.1, seconds=5) == 0.1
    assert 0.09 < d.used() < 1.4 and 8.6 < d.left() < 9.92
    assert not d.expired()


def test_waiting_costs_no_cpu_and_only_the_wall_clock_guard_stops_a_hang(monkeypatch):
    """time.sleep uses no CPU: 0.3 s of it passes a CPU budget of 0.1 s; a
    child that sleeps for ever is stopped by the wall-clock guard, which says so."""
    assert run_with_budget(time.sleep, 0.3, seconds=0.1) is None
    monkeypatch.setattr(B, "WALL_GUARD_FACTOR", 1.0)
    monkeypatch.setattr(B, "WALL_GUARD_EXTRA", 0.2)
    t0 = time.monotonic()
    with pytest.raises(BudgetExceeded, match="wall-clock guard") as info:
        run_with_budget(time.sleep, 60, seconds=0.1)
    assert info.value.wall_guard and time.monotonic() - t0 < 5
    assert B.wall_guard(20) == 20 + 0.2


def test_default_guard_is_generous():
    monkey = B.WALL_GUARD_FACTOR, B.WALL_GUARD_EXTRA
    assert monkey == (10.0, 60.0) and B.wall_guard(20) == 260.0


def _double(v):
    return 2 * v


def _fail(v):
    raise ValueError("second stage fails")


def _forever(v):
    return _spin(30)


@pytest.mark.slow
def test_stages_run_in_one_child_under_one_budget():
    """run_stages: each stage's result as soon as it is there; a stage that the
    CPU budget ends (begun, no result) or that raises leaves the later ones to the
    caller, who learns how many were begun; the first stage's budget and errors
    behave as run_with_budget's; a Deadline counts the child's CPU time."""
    d = Deadline(None)
    assert B.run_stages([_spin, _double, _double], 0.01, seconds=5) == ([0.01, 0.02, 0.04], 3)
    out, started = B.run_stages([_spin, _forever, _double], 0.01, seconds=0.2)
    assert out == [0.01] and started == 2           # the second stage was stopped by the budget
    assert d.used() > 0.18
    assert B.run_stages([_spin, _fail, _double], 0.01, seconds=5) == ([0.01], 2)
    with pytest.raises(BudgetExceeded, match="budget of 0.15 CPU s"):
        B.run_stages([_spin, _double], 30, seconds=0.15)
    with pytest.raises(ValueError, match="second stage"):
        B.run_stages([_fail, _double], 1, seconds=5)


def _nested():
    """Inside a budgeted child: a nested budget larger than what remains is cut to it."""
    _spin(0.15)
    try:
        run_with_budget(_spin, 30, seconds=100)
    except BudgetExceeded as exc:
        return str(exc)
    return "not stopped"


@pytest.mark.slow
def test_nested_budget_is_cut_to_what_remains_of_the_childs():
    t0 = time.monotonic()
    msg = run_with_budget(_nested, seconds=0.4)
    assert "exceeded its budget" in msg and time.monotonic() - t0 < 20
    budget = float(msg.split("budget of ")[1].split(" CPU")[0])
    assert 0.1 < budget < 0.27                 # 0.4 CPU s less the 0.15 spent (and the fork's own)


def test_deadline_counts_in_process_cpu_too():
    d = Deadline(0.1)
    _spin(0.12)
    assert d.expired() and d.left() == 0.0


def test_environment_budget_is_cpu_seconds(monkeypatch):
    monkeypatch.setenv("LINECONTACT_SYM_BUDGET", "7.5")
    assert B._budget_from_environment(20.0) == 7.5
    monkeypatch.setitem(B._ENV, "problem", None)
    monkeypatch.setenv("LINECONTACT_SYM_BUDGET", "soon")
    assert B._budget_from_environment(20.0) == 20.0       # remembered, raised where it can be reported
    with pytest.raises(B.BudgetError, match="LINECONTACT_SYM_BUDGET.*CPU seconds"):
        B.check_environment()


# ------------------------------------------------------- quiet and loaded
_DERIVE = """
import json, resource, sys, time
import sympy as sp
import linecontact_sym as lcs

def cpu():
    return sum(resource.getrusage(w).ru_utime + resource.getrusage(w).ru_stime
               for w in (resource.RUSAGE_SELF, resource.RUSAGE_CHILDREN))

out = {}
for spec in sys.argv[1:]:
    name, q = spec.split(":")
    t0, c0 = time.monotonic(), cpu()
    d = getattr(lcs, name)().derivation(q)
    out[spec] = {"closed": d.closed_form, "expr": sp.srepr(d.expr), "wall": time.monotonic() - t0,
                 "cpu": cpu() - c0, "verified": bool(d.verification is not None and d.verification.passed)}
print(json.dumps(out))
"""

#: the rounded punch's pressure (its force law included): a wall-clock budget once
#: turned it into an unevaluated integral under load
QUANTITIES = ("rounded_punch:pressure",)


def _pinned(code, cpu):
    """``code`` run on the one core ``cpu`` (the affinity is set by the child itself; any core if None)."""
    return code if cpu is None else f"import os\nos.sched_setaffinity(0, {{{cpu}}})\n" + code


def _start_cold(budget, cpu=None):
    """A fresh process deriving QUANTITIES cold with ``budget`` CPU seconds (on the one core ``cpu`` if given)."""
    env = dict(os.environ, LINECONTACT_SYM_CACHE="off", LINECONTACT_SYM_BUDGET=str(budget),
               PYTHONPATH=str(Path(__file__).resolve().parents[2]) + os.pathsep + os.environ.get("PYTHONPATH", ""))
    env.pop("LINECONTACT_SYM_NO_FORK", None)
    return subprocess.Popen([sys.executable, "-c", _pinned(_DERIVE, cpu), *QUANTITIES], env=env,
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)


def _result(proc):
    out, err = proc.communicate(timeout=900)
    assert proc.returncode == 0, err[-2000:]
    return json.loads(out.strip().splitlines()[-1])


_LOOP = "import time\nt = time.monotonic() + {limit}\nwhile time.monotonic() < t:\n    pass\n"


@pytest.mark.slow
def test_same_closed_forms_quiet_and_under_cpu_load():
    """Cold, in fresh processes: the rounded punch's pressure (a wall-clock
    budget of 25 s once turned it into an unevaluated integral with three
    busy loops per core) quiet, then with three busy loops on its core and a
    budget of twice the CPU seconds the quiet derivation took: the loaded
    derivation's wall time is past that budget (checked: else the load did
    not bite and the test would prove nothing), its CPU time is not, and it
    derives the same closed form.  Where this process may run on two cores or
    more, the loaded derivation and its loops share one core (each loop ends
    by itself after 10 minutes at most, and is killed when the test ends), so
    the rest of the machine (the other xdist worker) is not slowed down by
    loops of its own."""
    cpus = sorted(os.sched_getaffinity(0)) if hasattr(os, "sched_getaffinity") else []
    pinned = len(cpus) >= 2
    loaded_cpu = cpus[-1] if pinned else None
    quiet = _result(_start_cold(60, loaded_cpu))
    budget = round(max(1.0, 2 * max(quiet[q]["cpu"] for q in QUANTITIES)), 2)
    loops = [subprocess.Popen([sys.executable, "-c", _pinned(_LOOP.format(limit=600), loaded_cpu)])
             for _ in range(3 if pinned else 3 * (os.cpu_count() or 1))]
    try:
        time.sleep(0.5)
        loaded = _result(_start_cold(budget, loaded_cpu))
    finally:
        for p in loops:
            p.kill()
        for p in loops:
            p.wait()
    for q in QUANTITIES:
        assert quiet[q]["closed"] and quiet[q]["verified"], q
        assert loaded[q]["closed"] and loaded[q]["verified"], (q, budget, loaded[q])
        assert loaded[q]["expr"] == quiet[q]["expr"], q
    assert max(loaded[q]["wall"] for q in QUANTITIES) > budget, (budget, loaded)
    print({q: (round(quiet[q]["cpu"], 1), budget, round(loaded[q]["wall"], 1)) for q in QUANTITIES})


def _squares(n, cost):
    def produce():
        for k in range(n):
            _spin(cost)
            yield k * k
    return produce


def test_work_done_ahead_comes_in_order_with_its_cpu_seconds():
    a = B.Ahead(_squares(3, 0.05), 10)
    try:
        got = [a.take() for _ in range(4)]
    finally:
        a.close()
    assert [g[0] for g in got[:3]] == [0, 1, 4] and got[3] is None
    assert all(0.04 < g[1] < 1.0 for g in got[:3])
    short = B.Ahead(_squares(3, 0.3), 0.1)      # its own budget spent before the first item: nothing
    try:
        assert short.take() is None
    finally:
        short.close()


def test_a_child_taking_work_done_ahead_is_charged_for_it():
    """The CPU seconds of the values taken count against the taker's budget
    (core.budget's rule for Ahead): 3 x 0.1 s charged to a child that itself
    only waits; with a budget of 0.15 s the second charge ends it as its own
    CPU timer would (BudgetExceeded, not the wall-clock guard)."""
    def take_all(ahead):
        out = []
        while (item := ahead.take()) is not None:
            B.charge_child(item[1])
            out.append(item[0])
        return out, B._IN_CHILD["deadline"].used()
    a = B.Ahead(_squares(3, 0.1), 10)
    try:
        out, used = run_with_budget(take_all, a, seconds=5)
    finally:
        a.close()
    assert out == [0, 1, 4] and 0.28 < used < 2
    a = B.Ahead(_squares(3, 0.1), 10)
    try:
        with pytest.raises(BudgetExceeded) as info:
            run_with_budget(take_all, a, seconds=0.15)
    finally:
        a.close()
    assert not info.value.wall_guard


def test_a_second_child_only_where_a_core_is_idle(monkeypatch):
    """forks(): the references are done ahead only with an idle core (two or
    more cores, fewer processes running now than cores), never
    without a budget or fork; either way the records are the same
    (tests/numeric/test_reference.py::test_references_done_ahead_give_the_same_record)."""
    import builtins
    import io
    real_open = builtins.open
    running = {"n": 1}

    def fake_open(path, *args, **kw):       # /proc/loadavg with ``running`` processes running now
        if path == "/proc/loadavg":
            return io.StringIO(f"0.50 0.40 0.30 {running['n']}/300 12345\n")
        return real_open(path, *args, **kw)
    monkeypatch.setattr(builtins, "open", fake_open)
    monkeypatch.setattr(B, "_cores", lambda: 2)
    assert B.forks(5) and not B.forks(None) and not B.forks(float("inf"))
    running["n"] = 2                        # this process and another: no idle core
    assert not B.forks(5)
    monkeypatch.setattr(B, "_cores", lambda: 1)
    running["n"] = 1
    assert not B.forks(5)
