"""Sweeps and grids on any concurrent.futures.Executor (linecontact_sym.core.parallel):
the same numbers as one call in this process; exports, contacts and stress-field
functions pickle; scalar calls of an export take the fast path and agree with
the array path."""
import concurrent.futures as cf
import math
import pickle

import numpy as np
import pytest

import linecontact_sym as lcs
from linecontact_sym.core.errors import DomainError
from linecontact_sym.core.parallel import default_jobs, map_chunks, map_ordered, process_pool


def test_map_ordered_keeps_the_order_and_reports_errors():
    with cf.ThreadPoolExecutor(3) as ex:
        assert map_ordered(lambda v: v * v, range(10), ex) == [v * v for v in range(10)]

        def bad(v):
            if v == 2:
                raise ValueError("two")
            return v
        assert map_ordered(bad, range(4), ex, on_error=lambda i, e: str(e)) == [0, 1, "two", 3]
        with pytest.raises(ValueError):
            map_ordered(bad, range(4), ex)
    assert default_jobs() >= 1


def test_export_on_blocks_equals_one_call():
    c = lcs.exact_cylinder()
    p = c.to_numeric("pressure", R=1.0, E_star=2.0)
    x = np.linspace(-0.49, 0.49, 301)
    one = p(x=x, a=0.5)
    with cf.ThreadPoolExecutor(2) as ex:
        blocks = map_chunks(p, ex, x=x, a=0.5, chunks=7)
    assert np.array_equal(blocks, one)


@pytest.mark.slow
def test_processes_for_an_export_and_a_stress_grid():
    c = lcs.parabola()
    f = c.to_numeric("force")
    a = np.linspace(0.1, 2.0, 1000)
    sf = c.stresses().to_numeric("von_mises", a=1.0, E_star=1.0, R=1.0)
    X, Z = np.meshgrid(np.linspace(-2, 2, 60), np.linspace(0.01, 2, 50))
    with process_pool(2) as ex:
        assert np.array_equal(map_chunks(f, ex, a=a, R=1.0, E_star=1.5), f(a=a, R=1.0, E_star=1.5))
        assert np.array_equal(map_chunks(sf, ex, x=X, z=Z), sf(x=X, z=Z), equal_nan=True)


def test_exports_and_contacts_pickle():
    c = lcs.exact_cylinder()
    f = c.to_numeric("force")
    v = f(a=0.3, E_star=1.7, R=1.0)                        # scalar fast path compiled
    g = pickle.loads(pickle.dumps(f))
    assert g(a=0.3, E_star=1.7, R=1.0) == v
    c2 = pickle.loads(pickle.dumps(c))
    assert c2.to_numeric("force")(a=0.3, E_star=1.7, R=1.0) == v
    with pytest.raises(DomainError):
        g(a=1.5, E_star=1.7, R=1.0)                        # a < R, checked after unpickling too


@pytest.mark.parametrize("law, point", [
    ("parabola", dict(a=0.3, E_star=1.7, R=1.0)),
    ("exact_cylinder", dict(a=0.3, E_star=1.7, R=1.0)),
    ("worn_cylinder", dict(a=0.7, E_star=1.7, R=1.0, b=0.2)),
    ("power_law", dict(a=0.7, E_star=1.7, c=1.3, n=1.5)),
])
def test_scalar_calls_agree_with_the_array_path(law, point):
    """Python floats take the scalar path (math / scalar SciPy, same stable
    form); a 1-element array takes the NumPy path: both within 4 ulp."""
    c = getattr(lcs, law)()
    for q in ("force", "pressure"):
        f = c.to_numeric(q)
        pt = dict(point, x=0.1) if q == "pressure" else point
        s = f(**pt)
        arr = f(**{k: np.array([v]) for k, v in pt.items()})[0]
        assert np.ndim(s) == 0 and math.isclose(float(s), arr, rel_tol=4 * 2.2e-16), (q, s, arr)


def test_scalar_domain_check_is_the_full_check():
    c = lcs.exact_cylinder()
    p = c.to_numeric("pressure")
    ok = dict(a=0.5, x=0.2, E_star=1.0, R=1.0)
    assert p(**ok) == p(**{**ok, "x": -0.2})                # mirrored
    for bad in (dict(ok, x=0.7), dict(ok, a=-0.5), dict(ok, a=2.0), dict(ok, R=float("nan")),
                dict(ok, E_star=0.0)):
        with pytest.raises(DomainError) as scalar:
            p(**bad)
        with pytest.raises(DomainError) as full:
            c.check_domain("pressure", bad)
        assert str(scalar.value) == str(full.value)
    assert c.check_domain_scalar("pressure", dict(ok, x=-0.2)) == c.check_domain("pressure", dict(ok, x=-0.2))


@pytest.mark.slow
def test_dask_executor_for_a_sweep():
    distributed = pytest.importorskip("distributed")
    f = lcs.parabola().to_numeric("force")
    a = np.linspace(0.1, 1.0, 400)
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None,
                                  silence_logs=40) as cluster, distributed.Client(cluster) as client:
        out = map_chunks(f, client.get_executor(), a=a, R=2.0, E_star=1.0, chunks=4)
    assert np.array_equal(out, f(a=a, R=2.0, E_star=1.0))
