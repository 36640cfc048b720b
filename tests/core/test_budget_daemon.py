"""Budgeted work inside a daemonic process (a multiprocessing pool's worker,
a Dask worker) runs as anywhere else: multiprocessing refuses children
there, and every rule used to fail, so an executor changed a result (the
parabola's force law came back as an unevaluated integral)."""
import multiprocessing as mp

import pytest
import sympy as sp

from linecontact_sym.core.budget import BudgetExceeded, run_with_budget


def _square(v):
    return v * v


def _spin_forever():
    while True:
        pass


def _in_worker(_):
    out = run_with_budget(_square, 7, seconds=10)
    try:
        run_with_budget(_spin_forever, seconds=0.5)   # 0.5 CPU s
        late = "no"
    except BudgetExceeded:
        late = "raised"
    return mp.current_process().daemon, out, late


def _force_in_worker(_):
    import linecontact_sym as lcs
    d = lcs.LineContact(lcs.x**2 / (2 * sp.Symbol("R", positive=True)), verify=False).derivation("force")
    return d.closed_form, str(d.expr)


@pytest.mark.skipif("fork" not in mp.get_all_start_methods(), reason="no fork on this platform")
def test_budget_inside_a_daemonic_pool_worker():
    with mp.get_context("fork").Pool(1) as pool:
        daemon, out, late = pool.map(_in_worker, [0])[0]
    assert daemon and out == 49 and late == "raised"


@pytest.mark.skipif("fork" not in mp.get_all_start_methods(), reason="no fork on this platform")
def test_a_rule_runs_inside_a_daemonic_worker(monkeypatch, tmp_path):
    monkeypatch.setenv("LINECONTACT_SYM_CACHE", "off")
    with mp.get_context("fork").Pool(1) as pool:
        closed, expr = pool.map(_force_in_worker, [0])[0]
    assert closed and expr == "pi*E_star*a**2/(4*R)"
