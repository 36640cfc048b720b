"""Claims checked side by side (worker processes, any concurrent.futures
executor, a Dask cluster) give the results of a serial run, in the same
order; a second run reads the comparisons of the first from the store."""
import concurrent.futures as cf

import pytest

from linecontact_sym.claims import batch as B
from linecontact_sym.claims import check as C
from linecontact_sym.claims.batch import check_paper
from linecontact_sym.claims import derive as D
from linecontact_sym.claims import memo as M
from linecontact_sym.claims import spec as SPEC

BUDGET = 10.0

CLAIMS = [
    {"label": "Hertz", "quantity": "force", "profile": "x**2/(2*R)", "formula": "pi*E_star*a**2/(4*R)"},
    {"label": "wrong factor", "quantity": "force", "profile": "x**2/(2*R)", "formula": "pi*E_star*a**2/(2*R)"},
    {"label": "wedge", "quantity": "force", "profile": "x*tan(theta)", "formula": "E_star*a*tan(theta)"},
    {"label": "Hertz pressure", "quantity": "pressure", "profile": "x**2/(2*R)",
     "formula": "E_star*sqrt(a**2 - x**2)/(2*R)"},
]


def _paper():
    claims = [SPEC.claim_from_dict({"points": 2, **d}, "test.toml", index=i) for i, d in enumerate(CLAIMS)]
    return SPEC.Paper("test", "parallel test", "", claims, {}, "test.toml")


def _verdicts(result):
    """Everything of a result but the timings."""
    out = []
    for r in result.results:
        d = r.to_dict()
        d.pop("seconds")
        out.append(d)
    return out


@pytest.fixture
def fresh(monkeypatch):
    """Nothing remembered: every comparison is computed (in the workers too)."""
    monkeypatch.setattr(M, "remembered", lambda key, kind: None)


@pytest.mark.slow
def test_processes_give_the_serial_results_in_order(fresh):
    serial = check_paper(_paper(), budget=BUDGET, jobs=1)
    done = []
    parallel = check_paper(_paper(), budget=BUDGET, jobs=2, progress=lambda i, n, r: done.append(i))
    assert [r.label for r in parallel.results] == [c["label"] for c in CLAIMS]
    assert _verdicts(parallel) == _verdicts(serial)
    assert sorted(done) == [0, 1, 2, 3]
    assert [r.status for r in serial.results] == ["holds", "does not hold", "holds", "holds"]
    # the derived expressions come back (their evaluators stay in the workers)
    assert parallel.results[0].targets[0].derived.expr == serial.results[0].targets[0].derived.expr


def test_any_executor(fresh):
    serial = check_paper(_paper(), budget=BUDGET)
    with cf.ThreadPoolExecutor(2) as ex:
        threaded = check_paper(_paper(), budget=BUDGET, executor=ex)
    assert _verdicts(threaded) == _verdicts(serial)


def test_a_lost_worker_is_one_undecided_claim():
    class Broken(cf.Executor):
        def submit(self, fn, *a, **k):
            f = cf.Future()
            f.set_exception(RuntimeError("worker died"))
            return f
    res = check_paper(_paper(), budget=BUDGET, executor=Broken())
    assert [r.status for r in res.results] == ["undecided"] * 4
    assert "worker died" in res.results[0].verdict and res.exit_code() == 3


def test_second_run_reads_the_comparisons(monkeypatch):
    calls = []
    real = D._evaluate_point

    def counting(*a, **k):
        calls.append(1)
        return real(*a, **k)
    monkeypatch.setattr(D, "_evaluate_point", counting)
    claim = SPEC.claim_from_dict({**CLAIMS[1], "points": 2, "formula": "pi*E_star*a**2/(3*R)"}, "test.toml")
    paper = SPEC.Paper("test", "t", "", [claim], {}, "t")
    first = check_paper(paper, budget=BUDGET)
    n = len(calls)
    assert n > 0
    second = check_paper(paper, budget=BUDGET)
    assert len(calls) == n                      # nothing computed again
    assert _verdicts(second) == _verdicts(first)
    # a different point, form or derived record is a different key
    claim = paper.claims[0]
    d = C.derive(claim, claim.profiles[0][1], C.Context(BUDGET))
    vals = {s: v for s, v in first.results[0].targets[0].forms[0].points[0].values.items()}
    k1 = M.point_key(d, claim.formula.expr, vals, 45, False)
    assert k1 != M.point_key(d, claim.formula.expr * 2, vals, 45, False)
    assert k1 != M.point_key(d, claim.formula.expr, vals, 30, False)
    assert k1 != M.point_key(d, claim.formula.expr, {**vals, next(iter(vals)): 7}, 45, False)


@pytest.mark.slow
def test_dask_cluster(fresh):
    distributed = pytest.importorskip("distributed")
    serial = check_paper(_paper(), budget=BUDGET)
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None,
                                  silence_logs=40) as cluster, distributed.Client(cluster) as client:
        res = check_paper(_paper(), budget=BUDGET, executor=client.get_executor())
    assert _verdicts(res) == _verdicts(serial)


def test_worker_results_pickle():
    import pickle
    r = B.check_claim_portable(_paper().claims[0], BUDGET)
    back = pickle.loads(pickle.dumps(r))
    assert back.status == "holds" and back.targets[0].derived.expr == r.targets[0].derived.expr
